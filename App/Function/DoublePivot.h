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

/// The same for pivots at `pivot` (on the part) and `base` (on the base) and a turn by `degrees` about
/// `pole`, all in the pivot plane: turning the part about its pivot, then the link about the base pivot.
std::array<double, 2> fourBarAngles(const std::array<double, 2>& pivot, const std::array<double, 2>& base,
                                    const std::array<double, 2>& pole, double degrees);

/// A double pivot that cannot be placed, and why.
struct Unplaced {
    std::string joint, reason;
};

/// Moves every double pivot's pivots (stage 2). Returns the joints that cannot be placed: the position
/// constraint has no solution on the faces, or the parts would collide on the way (checked at 32 poses along
/// the motion); empty when all are placed.
std::vector<Unplaced> placePivots(Model& model);

}  // namespace fabguide::function
