// Swept volumes (thesis 4.5.1): what a part sweeps along its joints' motion, as solids to cut with, for
// cavities and for clearing the parts it moves past.
#pragma once

#include "Function/Pose.h"
#include "Printable/Solids.h"

#include <gp_Ax1.hxx>
#include <gp_Vec.hxx>

namespace fabguide::printable {

/// What a shape sweeps turning by `radians` about `axis`, then shifting by `by` (motions turn first, then
/// slide): a revolution, then a prism of the turned shape.
TopoDS_Shape turnedThenShifted(const TopoDS_Shape& shape, const gp_Ax1& axis, double radians,
                               const gp_Vec& by);

/// What boxes sweep turning about `axis` then shifting by `by`: the volume each piece (splitAtAxis) sweeps,
/// to cut with together; OpenCASCADE may drop a thin piece from their union.
std::vector<TopoDS_Shape> turnedThenShifted(const std::vector<Coordinates>& boxes, const gp_Ax1& axis,
                                            double radians, const gp_Vec& by);

/// The volume part p's boxes sweep as it moves from its modelled pose to configuration k (4.5.1), as solids
/// to cut with. Motions turn first, then slide (Motion.h), so with at most one hinge turning in p's chain the
/// sweep is exact: that hinge's revolution, then a prism along the slides' common displacement; otherwise
/// (double pivots, turns upon turns) the part at 48 poses along the motion.
std::vector<TopoDS_Shape> sweep(const Model& m, int part, int k, const std::vector<Coordinates>& boxes);

/// What a part sweeps by its own hinge (or sliding hinge) alone, in the frame of the part it turns on: the
/// revolution about the edge, then the prism along the slide. Direction -1: what the base's boxes sweep in
/// the turning part's frame (the motion undone).
std::vector<TopoDS_Shape> hingeSweep(const Model& m, const Joint& joint, const function::JointPose& pose,
                                     const std::vector<Coordinates>& boxes, int direction = 1);

/// The hinge or sliding hinge on which part `carried` turns on `base` in configuration k, or -1 (a hinge on
/// the ground turns on any part that stands still).
int hingeOn(const Model& m, int carried, int base, int k);

/// What part a's boxes sweep in part b's frame as both move to configuration k: when one turns on the other
/// by a hinge or sliding hinge, its revolution and slide (exact); otherwise a at 32 poses while they turn
/// (the first half) and 8 while they slide.
std::vector<TopoDS_Shape> pathRelative(const Model& m, int k, int a, int b,
                                       const std::vector<Coordinates>& boxes);

}  // namespace fabguide::printable
