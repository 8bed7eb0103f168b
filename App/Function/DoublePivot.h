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

/// The other double pivot that makes a four-bar with `joint`: the same part and base, its pivot on a face of
/// the same side (wherever its pivots sit: two links with one pivot in common make a four-bar that cannot
/// move, or runs one link over the other), or of the opposite side with its pivots elsewhere in the plane (a
/// leaf carried by a link on each side), or nullptr. Links on both sides, one over the other (pivots within
/// the two links' widths), are one link doubled: placed alike (placePivots), each checked on its own.
const Joint* fourBarPartner(const Model& model, const Joint& joint);

/// A four-bar's state along its motion (degrees): its first and second links' turns about their base pivots,
/// and the part's whole turn.
struct FourBarTurns {
    double first = 0, second = 0, part = 0;
};

/// A four-bar moving a fraction t of the way to configuration k, at `steps` even steps: the
/// first link turns evenly, the shorter way, to its place; the second follows on the branch it starts on (the
/// meeting point of its two circles nearest its last place). Ends early where the links cannot stay joined.
std::vector<FourBarTurns> fourBarPath(const Model& model, const Joint& first, const Joint& second, int k,
                                      double t, int steps);

/// A double pivot that cannot be placed, and why.
struct Unplaced {
    std::string joint, reason;
};

/// Moves every double pivot's pivots (stage 2). Returns the joints that cannot be placed: the position
/// constraint has no solution on the faces, or the parts would collide on the way (checked at 32 poses along
/// the motion); empty when all are placed.
std::vector<Unplaced> placePivots(Model& model);

}  // namespace fabguide::function
