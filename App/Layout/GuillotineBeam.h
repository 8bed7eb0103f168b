// A beam search for guillotine layouts: which part comes next, in which pose and where, decided over many
// partial layouts at once (after packingsolver's tree search for guillotine bin packing: Fleszar, 2013;
// Libralesso & Fontan, 2020). Guillotine.cpp lays out and numbers the cuts of the steps it finds.
#pragma once

#include "Layout/Deadline.h"
#include "Layout/MaxRects.h"

#include <optional>
#include <vector>

namespace fabguide::material {

/// Where a step puts its unit, in the order a saw's layout is filled: on a new sheet, leading a new
/// first-stage slab, leading a new second-stage slab in it, or after the last unit of that slab (third
/// stage). A slab grows to hold what follows in it, as far as its sheet allows.
enum class Where { Sheet, Slab, Column, After };

/// One unit laid: its part, its pose on the sheet and where it goes; the axis along which its sheet's
/// first-stage slabs follow one another (0: x, 1: y); and the sizes of the slabs it leads along x and y
/// (0: the unit's own), as grown by the units after it.
struct SawStep {
    int part = -1;
    Pose pose;
    Where where = Where::Sheet;
    int axis = 1;
    double extent[2] = {0, 0};
};

/// Whether `size` fits in `room` leaving none of it or a strip a cut can take off: one wider than half the
/// clearance, so that the cut's middle stays on the board (no trim) or short of the piece's last cut.
bool leavesSawable(double room, double size, double clearance);

/// What the search is given: the units of each part (0: not on this kind of sheet), their poses on it, the
/// sheet's usable size along x and y (usableSize), the axes the first-stage slabs may follow one another
/// along (one search per axis), the stages (2 or 3), the clearance and the sheets of this kind in stock (-1:
/// unlimited).
struct BeamProblem {
    std::vector<int> quantities;
    std::vector<std::vector<Pose>> poses;
    double size[2] = {0, 0};
    std::vector<int> axes{1};
    int stages = 3;
    double clearance = 0;
    long sheets = -1;
};

/// The steps that lay every unit on the fewest sheets found (the last sheet emptiest on a tie), by beam
/// searches of widths 1, 2, 4, ... up to `widest` (and as wide as about 10^6 partial layouts grown at once
/// allow), partial layouts ranked by the area they can no longer
/// fill per area laid. Nothing when no search ends by `deadline` or the sheets run out.
std::optional<std::vector<SawStep>> beamSearch(const BeamProblem& problem, long widest, Deadline deadline);

}  // namespace fabguide::material
