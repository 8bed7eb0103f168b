// Gaps (thesis 4.5.3): the clearance between parts that touch, as modelled or in any configuration.
#pragma once

#include "Printable/Solids.h"

namespace fabguide::printable {

/// Gaps (4.5.3): where cuboids of two parts touch or face each other closer than the gap, as modelled or in
/// any configuration, the face of the one that moves (or the later one) steps back until they are the gap
/// apart, unless they print as one body (rigidBodies); so does a solid's face on or near its cavity's
/// wall (a drawer's 2 mm side play is 0.3 mm at 1:6.7). Between the poses, a cuboid that turns past another
/// within the gap steps back the one side that clears it least (an ironing board's legs folding under it).
std::vector<Coordinates> gapped(const Model& m, double gap);

}  // namespace fabguide::printable
