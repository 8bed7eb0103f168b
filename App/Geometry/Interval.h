// A closed interval of the real line, ends possibly infinite.
#pragma once

#include <limits>

namespace fabguide {

struct Interval {
    double lower = -std::numeric_limits<double>::infinity();
    double upper = std::numeric_limits<double>::infinity();
};

}  // namespace fabguide
