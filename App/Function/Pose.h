// Cuboids in a configuration (thesis 4.1.2, 4.2): for fixed joint poses, every side of a moved cuboid's
// bounding box is a linear expression in the model's coordinates, the hinge axis included.
#pragma once

#include "Function/Model.h"

#include <array>
#include <utility>
#include <vector>

namespace fabguide::function {

/// The side `face.side` of the bounding box of cuboid `face.cuboid` in configuration `configuration`
/// (-1: as modelled), as Σ coefficient × coordinate + constant. A part moves by its joint and its base's.
/// After a turn by other than a multiple of 90°, a further turn bounds the first turn's box: conservative.
Expression posed(const Model& model, const Face& face, int configuration);

/// All six sides of that box (posed for each side, at once).
std::array<Expression, 6> posedBox(const Model& model, int cuboid, int configuration);

/// Their values for the model's current coordinates, indexed by Side.
std::array<double, 6> posedBounds(const Model& model, int cuboid, int configuration);

/// A direction in space (x, y, z).
using Direction = std::array<double, 3>;

/// The least (or, `high`, the greatest) of d · q over the points q of cuboid `cuboid` in the configuration,
/// as an expression in the coordinates: exact for any chain of turns and slides (each move's turn carried
/// back onto the direction, the extreme of the cuboid as modelled is a corner). The separating-axis test of
/// two posed cuboids is linear in the coordinates along a fixed direction.
Expression projected(const Model& model, int cuboid, int configuration, Direction d, bool high);

/// The directions of a cuboid's x, y and z axes in the configuration (turned with its part).
std::array<Direction, 3> posedAxes(const Model& model, int cuboid, int configuration);

/// The part a cuboid belongs to.
int partOf(const Model& model, int cuboid);

/// The part of each cuboid, by cuboid (partOf for all at once).
std::vector<int> owners(const Model& model);

/// The first joint that moves part p (its own, not its base's), or -1.
int jointMoving(const Model& model, int part);

/// How configuration k poses joint j, or nullptr (also for k = -1, as modelled).
const JointPose* poseOf(const Model& model, int joint, int configuration);

/// The first joint of part p's chain (its own, then its base's, out to the ground) that configuration k
/// poses, or -1: the part stands still there.
int jointMovingIn(const Model& model, int part, int configuration);

/// The part whose motion part p shares: its base's, through fixed joints (p itself when no fixed joint holds
/// it).
int carrierOf(const Model& model, int part);

/// The cuboid of the part hinge `joint` turns on (its base, else one no joint moves) that runs longest beside
/// its edge, of those within `reach` of the edge across its axis; -1 for none. The solve holds the edge
/// beside it, and the print hangs the yokes on it.
int cuboidNear(const Model& model, const Joint& joint, double reach);

/// cos and sin of an angle in degrees, exact at multiples of 90° (std::cos(π/2) is 6e-17, not 0).
std::pair<double, double> cosSin(double degrees);

/// The value of an expression for the model's current coordinates.
double evaluate(const Model& model, const Expression& expression);

}  // namespace fabguide::function
