// Keeping parts apart (after the packing constraints of thesis 4.2.1–4.2.2): in every
// configuration, the material of two parts never overlaps. Each pair of solid cuboids of different parts
// that come near is kept apart by a linear constraint chosen from the model as drawn: one stays on its side
// of the other along an axis, or stays inside the other's cavity (leaving only through its openings).
#pragma once

#include "Function/Model.h"
#include "Function/Pose.h"

#include <utility>
#include <vector>

namespace fabguide::function {

/// How two solid cuboids of different parts stay clear in a configuration (-1: as modelled): `a` wholly on
/// the low side of `b` along `direction` (an axis, or for parts turned by other than quarter turns any axis
/// of the separating-axis test); or, when `walls` is not empty, `a` inside a void of `b`'s part, within each
/// of those cavity faces: a cavity's sides that are neither openings nor passages into a neighbouring cavity
/// `a` reaches into (a lever's stem through the slot beside its channel).
struct Separation {
    int a = 0, b = 0, configuration = -1;
    Direction direction{1, 0, 0};
    std::vector<Face> walls;
};

/// Whether every turn that places the part in the configuration is by a multiple of 90°: its posed box is
/// then exactly its cuboids' box, not a bound of it.
bool exactlyPosed(const Model& model, int part, int configuration);

/// Pairs of solid cuboids (a < b) of different parts whose boxes in the configuration overlap, or come within
/// `margin` (negative: overlap by more than -margin), found by a sweep over the boxes along x. Left out:
/// parts a fixed joint holds together; an inner cuboid of a fit inside the enclosing part's box that lies
/// mostly inside an enclosing one, in the poses whose room print-in-place sweeps out (thesis 4.5.1): as
/// modelled, in the fit's configuration and on the way there.
std::vector<std::pair<int, int>> nearPairs(const Model& model, int configuration, double margin);

/// Solid cuboids (inner, outer) of different parts, the inner one drawn at least half inside the outer one's
/// material (its box less its cavities) as modelled, where nothing lets them overlap (no fixed joint, no fit
/// inside's room): a part made before the cavity it goes in. Keeping them apart would move or
/// shrink parts no relationship names, so the solve does not try.
std::vector<std::pair<int, int>> drawnInside(const Model& model);

/// The least change that keeps a and b clear, judged on `arranged` (the model as its relationships arrange
/// it): of the separating axes of the two posed cuboids (x, y, z; for turned parts also their own axes and
/// the cross products), the one and the order that overlap least; or a cavity of one part that holds the
/// other with less to change (its bounding box, for parts turned by other than quarter turns).
Separation inferSeparation(const Model& arranged, int a, int b, int configuration);

/// One way of keeping a pair apart along a motion: a separation in each of its poses, and what it changes
/// (the sum of what each pose changes; infinite for a way that has the pair change sides between poses, which
/// no motion does: no one move of one against the other keeps them on their sides in every pose).
struct Choice {
    std::vector<Separation> separations;
    double cost = 0;
    bool near = true;  ///< in every pose, each is at most half its size, or less than twice
                       ///< kInferenceDistance, from where this way keeps it
};

/// Whether two choices keep the pair apart the same way in each pose (whatever they cost).
bool sameWay(const Choice& x, const Choice& y);

/// The ways of keeping a and b apart in each of `poses` (poses of one motion: a configuration and poses on
/// the way to it, or the modelled pose alone), each chosen for all of them together, ranked by the change
/// they make in all the poses `judged` (those and the rest of the motion; Choice::cost): kept out pose by
/// pose as inferSeparation keeps them out, held by one cavity all the way, or kept apart along one axis all
/// the way. A pocket door turning into its bay stays within the bay's opening all the way, not out of the
/// carcass at the ends and in the bay between, nor in the neighbouring bay its hinge was drawn a hair into.
std::vector<Choice> choicesAlong(const Model& arranged, int a, int b, const std::vector<int>& poses,
                                 const std::vector<int>& judged);

/// "no overlap: carcass, door in 'open'": the name its constraints take, one per pair of parts and
/// configuration (none for the parts as modelled).
std::string separationName(const Model& model, const Separation& separation);

}  // namespace fabguide::function
