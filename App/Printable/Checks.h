// Checking printable bodies (thesis 4.5, issue 6): every solid valid, and the parts apart by at least the gap
// as printed and all along every configuration's motion.
#pragma once

#include "Printable/PrintInPlace.h"

#include <string>
#include <vector>

namespace fabguide::printable {

struct Check {
    std::vector<std::string> invalid;  ///< bodies BRepCheck_Analyzer finds invalid
    std::vector<std::string> loose;    ///< "lever: 2 pieces": bodies that print in pieces, not one
    double clearance = 1e300;          ///< the least distance between two bodies, as printed and moving
    std::string where;                 ///< "lid and body in 'open' at 50% near (120.0, 80.0, 50.0) mm"
};

/// Validity, each body in one piece, and the least clearance between any two bodies as printed and at
/// `samples` poses along the way to each configuration (0 when two bodies intersect). Pairs farther apart
/// than `enough` are not measured.
Check check(const function::Model& model, const Printable& printable, double enough, int samples = 32);

}  // namespace fabguide::printable
