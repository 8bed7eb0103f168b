// The rigid motions of a works-like model's parts (thesis 4.1.2) as OpenCASCADE transformations: where a part
// is a fraction t of the way from its modelled pose to a configuration, for sweeping cavities and checking
// motion.
#pragma once

#include "Function/Model.h"
#include "Function/Pose.h"

#include <gp_Ax1.hxx>
#include <gp_Trsf.hxx>

#include <vector>

namespace fabguide::printable {

using function::jointMoving;
using function::poseOf;

/// Joint j's motion `t` (0..1) of the way to its pose in configuration k (identity when k does not pose it).
/// Everything that turns does so in the first half, everything that slides in the second: doors swing open
/// before drawers come out, a pocket door (sliding hinge) swings open, then slides in; a double pivot follows
/// its four-bar motion.
gp_Trsf jointMotion(const function::Model& model, int j, int configuration, double t);

/// Whether no joint moves part p (fixed joints out to the ground hold it still): it stands still in every
/// configuration, with every other such part.
bool standsStill(const function::Model& model, int part);

/// The parts printed as one body each: each part a joint moves on its own with the parts fixed to
/// it (fixed joints), and the parts that stand still grouped where they touch each other's material as
/// modelled (a carcass and its legs, a shelf against a cupboard's walls, an insert on a well's floor never
/// move apart: one body, no gap between them; a part loose in a cavity touches no wall and stays its own),
/// groups in the order of their first part.
std::vector<std::vector<int>> rigidBodies(const function::Model& model);

/// Part p's motion: its joint's, then its base's, out to the ground.
gp_Trsf partMotion(const function::Model& model, int part, int configuration, double t);

/// A double pivot's link: turned about the base pivot (and carried by whatever carries the base).
gp_Trsf linkMotion(const function::Model& model, int j, int configuration, double t);

/// A double pivot's pivots as modelled: on the part, on the base (on the coplanar faces).
std::pair<gp_Pnt, gp_Pnt> pivotPoints(const function::Model& model, const function::Joint& joint);

/// The coordinate axis (0: x, 1: y, 2: z) a hinge's (or sliding hinge's) edge runs along.
int hingeAlong(const function::Joint& joint);

/// A hinge's (or sliding hinge's) axis: its edge, directed along +x, +y or +z.
gp_Ax1 hingeAxis(const function::Model& model, const function::Joint& joint);

}  // namespace fabguide::printable
