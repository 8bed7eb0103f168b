// Stage 2 of the works-like solve (thesis 4.3.6, 4.4): with the cuboids fixed, place each double pivot's two
// pivots, by the least change of their offsets, so that its rigid link can take the part to every
// configuration that poses it; then check the motion for interference.
#pragma once

#include "Function/Model.h"

#include <string>
#include <vector>

namespace fabguide::function {

/// A double pivot's geometry in its pivot plane: the plane's normal axis and in-plane axes (u, w), the
/// pivots' positions (u, w) as modelled.
struct PivotPlane {
    int normal = 0, u = 1, w = 2;
    std::array<double, 2> pivot{}, basePivot{};
};
PivotPlane pivotPlane(const Model& model, const Joint& joint);

/// The link's turn about the base pivot and the part's turn about its own pivot (degrees) that take the part
/// to a configuration's pose (for animating the four-bar motion).
std::array<double, 2> linkAngles(const Model& model, const Joint& joint, const JointPose& pose);

/// Moves every double pivot's pivots (stage 2). Returns the names of the joints that cannot be placed (the
/// position constraint has no solution on the faces) or whose parts would collide on the way (checked at 32
/// poses along the motion); empty when all are placed.
std::vector<std::string> placePivots(Model& model);

}  // namespace fabguide::function
