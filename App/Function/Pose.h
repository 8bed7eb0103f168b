// Cuboids in a configuration (thesis 4.1.2, 4.2): for fixed joint poses, every side of a moved cuboid's
// bounding box is a linear expression in the model's coordinates, the hinge axis included.
#pragma once

#include "Function/Model.h"

namespace fabguide::function {

/// The side `face.side` of the bounding box of cuboid `face.cuboid` in configuration `configuration`
/// (-1: as modelled), as Σ coefficient × coordinate + constant. A part moves by its joint and its base's.
/// After a turn by other than a multiple of 90°, a further turn bounds the first turn's box: conservative.
Expression posed(const Model& model, const Face& face, int configuration);

/// The part a cuboid belongs to.
int partOf(const Model& model, int cuboid);

/// The value of an expression for the model's current coordinates.
double evaluate(const Model& model, const Expression& expression);

}  // namespace fabguide::function
