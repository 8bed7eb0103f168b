// Keeping parts apart (issue 13, after the packing constraints of thesis 4.2.1–4.2.2): in every
// configuration, the material of two parts never overlaps. Each pair of solid cuboids of different parts
// that come near is kept apart by a linear constraint chosen from the model as drawn: one stays on its side
// of the other along an axis, or stays inside the other's cavity (leaving only through its openings).
#pragma once

#include "Function/Model.h"

#include <utility>
#include <vector>

namespace fabguide::function {

/// How two solid cuboids of different parts stay clear in a configuration (-1: as modelled): `a`'s high side
/// at most `b`'s low side along `axis`; or, when `cavity` >= 0, `a` inside that cavity of `b`'s part on every
/// side that is not an opening. `a` and `b` are as drawn, whichever comes first.
struct Separation {
    int a = 0, b = 0, axis = 0, cavity = -1, configuration = -1;
};

/// Whether every turn that places the part in the configuration is by a multiple of 90°: its posed box is
/// then exactly its cuboids' box, not a bound of it.
bool exactlyPosed(const Model& model, int part, int configuration);

/// Pairs of solid cuboids (a < b) of different parts whose boxes in the configuration overlap, or come within
/// `margin` (negative: overlap by more than -margin), found by a sweep over the boxes along x. Left out: the
/// inner and enclosing parts of a fit inside, whose room print-in-place sweeps out (thesis 4.5.1).
std::vector<std::pair<int, int>> nearPairs(const Model& model, int configuration, double margin);

/// The least change that keeps a and b clear, judged on `drawn` (the model as the user drew it): the
/// separating axis and order with the least overlap, or a cavity of one part that holds the other with less
/// to change. Returns false (nothing to keep) when a pose is not exact and the bounding boxes already overlap
/// as drawn: the bound says nothing then.
bool inferSeparation(const Model& drawn, int a, int b, int configuration, Separation& separation);

/// "no overlap: door, carcass": the name its constraints take, one per pair of parts.
std::string separationName(const Model& model, const Separation& separation);

}  // namespace fabguide::function
