#include "Layout/HoleFill.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace fabguide::material {

namespace {

using geometry::Outline;
using geometry::Polygon;

/// The relative turns of a guest in a host that leave each orientation the host may take allowed for it; a
/// guest that follows the grain turns by a half turn at most, inside a host that follows it too.
std::vector<int> turnsIn(const PartSpec& guest, const PartSpec& host)
{
    std::vector<int> turns;
    for (int r : {0, 90, 180, 270}) {
        if (guest.followsGrain && (!host.followsGrain || r % 180 != 0))
            continue;
        const bool allowed = std::all_of(host.orientations.begin(), host.orientations.end(), [&](int h) {
            return std::count(guest.orientations.begin(), guest.orientations.end(), (h + r) % 360) > 0;
        });
        if (allowed)
            turns.push_back(r);
    }
    return turns;
}

/// Where in `room` (a hole less what it already holds, as an outline) `guest` fits turned by `turn`: the
/// lowest, then leftmost, of positions `step` apart; false when none does.
bool firstFit(const Outline& room, const PartSpec& guest, int turn, Guest& out)
{
    const geometry::Box2 within = geometry::bounds(room.outer);
    const Outline turned = geometry::placed(guest.outline, turn, 0, 0);
    const geometry::Box2 size = geometry::bounds(turned.outer);
    if (size.width() > within.width() || size.height() > within.height())
        return false;
    const double need = geometry::area(Outline{turned.outer, {}});
    const double spare = (within.width() - size.width()) * (within.height() - size.height());
    const double step = std::max(0.5, std::sqrt(spare / 4000));  // at most ~4000 positions a turn
    for (double y = within.minY; y <= within.maxY - size.height() + 1e-9; y += step)
        for (double x = within.minX; x <= within.maxX - size.width() + 1e-9; x += step) {
            Polygon moved = turned.outer;
            for (geometry::Point2& p : moved)
                p.x += x, p.y += y;
            // A quick test first: every corner in the room.
            if (!std::all_of(moved.begin(), moved.end(),
                             [&](geometry::Point2 p) { return geometry::inMaterial(room, p); }))
                continue;
            double inside = 0;
            for (const Polygon& piece : geometry::intersect(moved, room))
                inside += std::abs(geometry::signedArea(piece));
            if (inside >= need * (1 - 1e-9)) {
                out = {out.part, x, y, turn};
                return true;
            }
        }
    return false;
}

/// One unit's guests: its holes filled from the units `left`, the largest parts first (`bySize`).
std::vector<Guest> fill(const PackProblem& problem, int host, const std::vector<int>& bySize,
                        std::vector<int>& left, Deadline deadline)
{
    const PartSpec& spec = problem.parts[host];
    const double clear = problem.settings.kerf + problem.settings.spacing + 0.01;
    std::vector<Guest> guests;
    for (const Polygon& hole : spec.outline.holes) {
        Polygon inward(hole.rbegin(), hole.rend());  // the hole as a region (counter-clockwise)
        Outline room = geometry::offset(Outline{inward, {}}, -clear);
        for (int g : bySize) {
            const PartSpec& guest = problem.parts[g];
            if (g == host || left[g] == 0 || room.outer.empty() ||
                (guest.thickness != 0 && guest.thickness != spec.thickness))
                continue;
            for (int turn : turnsIn(guest, spec)) {
                Guest placed{g, 0, 0, 0};
                while (left[g] > 0 && !deadline.passed() && firstFit(room, guest, turn, placed)) {
                    guests.push_back(placed);
                    --left[g];
                    const Outline at = geometry::placed(guest.outline, turn, placed.x, placed.y);
                    room.holes.push_back(geometry::offset(Outline{at.outer, {}}, clear).outer);
                }
            }
        }
    }
    return guests;
}

}  // namespace

std::vector<std::vector<std::vector<Guest>>> fillHoles(const PackProblem& problem, std::vector<int>& left,
                                                       Deadline deadline)
{
    std::vector<double> area;
    for (const PartSpec& part : problem.parts)
        area.push_back(geometry::area(part.outline));
    std::vector<int> bySize(problem.parts.size());
    std::iota(bySize.begin(), bySize.end(), 0);
    std::stable_sort(bySize.begin(), bySize.end(), [&](int a, int b) { return area[a] > area[b]; });
    std::vector<std::vector<std::vector<Guest>>> guests(problem.parts.size());
    for (int host : bySize) {  // the largest hosts first: their holes take the largest guests
        if (problem.parts[host].outline.holes.empty())
            continue;
        std::vector<Guest> last;  // a unit like the one before takes the same guests while they last
        for (int unit = 0; unit < left[host]; ++unit) {  // its units left to lay out: none is a guest now
            std::vector<int> count(problem.parts.size());
            for (const Guest& g : last)
                ++count[g.part];
            bool again = !last.empty();
            for (size_t p = 0; p < count.size(); ++p)
                again = again && left[p] >= count[p];
            if (again) {
                for (const Guest& g : last)
                    --left[g.part];
            } else {
                last = fill(problem, host, bySize, left, deadline);
            }
            guests[host].push_back(last);
        }
    }
    return guests;
}

Layout withGuests(const Layout& layout, const PackProblem& problem, const std::vector<int>& original,
                  const std::vector<std::vector<std::vector<Guest>>>& guests)
{
    Layout out = layout;
    std::vector<size_t> placedUnits(problem.parts.size());
    for (Placement& p : out.placements)
        p.part = original[p.part];
    for (const Placement& p : layout.placements) {
        const int host = original[p.part];
        const size_t unit = placedUnits[host]++;
        if (unit >= guests[host].size())
            continue;
        const geometry::Placement2 move =
            geometry::placement(problem.parts[host].outline, p.rotation, p.x, p.y);
        for (const Guest& g : guests[host][unit]) {
            const PartSpec& spec = problem.parts[g.part];
            Polygon at = geometry::placed(spec.outline, g.rotation, g.x, g.y).outer;
            for (geometry::Point2& q : at)
                q = move(q);
            const geometry::Box2 box = geometry::bounds(at);
            out.placements.push_back({g.part, p.sheet, box.minX, box.minY, (g.rotation + p.rotation) % 360,
                                      box.width(), box.height()});
            out.partArea += geometry::area(spec.outline);
        }
    }
    return out;
}

}  // namespace fabguide::material
