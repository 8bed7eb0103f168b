// Part-in-hole nesting (thesis 5.5.4 names it as a limit): small parts laid inside other parts'
// holes before the layout, so a coaster is cut from a stool seat's hand hole instead of from fresh board.
#pragma once

#include "Layout/Deadline.h"
#include "Layout/Pack.h"

#include <chrono>
#include <vector>

namespace fabguide::material {

/// A unit of a part laid in a hole of a unit of another (its host), in the host's frame as the problem gives
/// its outline (turned by 0°): turned by `rotation` with its bounding box's lower-left corner at (x, y).
struct Guest {
    int part = 0;
    double x = 0, y = 0;
    int rotation = 0;
};

/// The guests of each unit of each part, [part][unit]: units of smaller parts laid first-fit in the holes,
/// kerf + spacing clear of the hole's edge and of each other, the largest parts first, in a relative turn
/// that keeps every orientation the host may take allowed for the guest (and its grain with the host's), of
/// the host's thickness. `left` (units per part still to lay out) loses the units taken as guests. Stops
/// filling at `deadline`: what is not in a hole by then is laid out on the boards.
std::vector<std::vector<std::vector<Guest>>> fillHoles(const PackProblem& problem, std::vector<int>& left,
                                                       Deadline deadline);

/// `layout` of `rest` (the problem's parts less their guests; rest part k is problem part `original[k]`) with
/// the guests added, each turned and moved with its host: the j-th placed unit of a part carries the guests
/// of its j-th unit.
Layout withGuests(const Layout& layout, const PackProblem& problem, const std::vector<int>& original,
                  const std::vector<std::vector<std::vector<Guest>>>& guests);

}  // namespace fabguide::material
