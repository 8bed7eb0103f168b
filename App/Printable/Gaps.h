// Gaps (thesis 4.5.3): the clearance between parts that touch, as modelled or in any configuration.
#pragma once

#include "Printable/Solids.h"

namespace fabguide::printable {

/// Gaps (4.5.3): where cuboids of two parts touch, as modelled or in any configuration, the face of the one
/// that moves (or the later one) steps back by the gap; so does a solid's face lying on its cavity's wall.
std::vector<Coordinates> gapped(const Model& m, double gap);

}  // namespace fabguide::printable
