#include "Layout/Compaction.h"

#include <algorithm>
#include <limits>
#include <numeric>

namespace fabguide::material {

namespace {

using geometry::Outline;
using geometry::Point2;
using geometry::Polygon;

constexpr double kFar = std::numeric_limits<double>::infinity();
/// What a part keeps off the one it slides onto, mm: rounding never takes it into the other.
constexpr double kMargin = 1e-7;
/// What an outline is grown by beyond the clearance before it slides, mm: past Clipper's rounding.
constexpr double kGrowth = 1e-3;

template <class Visit>
void forEachRing(const Outline& outline, Visit&& visit)
{
    visit(outline.outer);
    for (const Polygon& hole : outline.holes)
        visit(hole);
}

/// How far `p` goes down (or up) before it meets an edge of `ring` that is not upright (sliding along an
/// upright edge meets nothing); 0 when it lies on one.
double rayGap(Point2 p, const Polygon& ring, bool up)
{
    double gap = kFar;
    for (size_t k = 0; k < ring.size(); ++k) {
        const Point2 a = ring[k], b = ring[(k + 1) % ring.size()];
        if (a.x == b.x || p.x < std::min(a.x, b.x) || p.x > std::max(a.x, b.x))
            continue;
        const double y = a.y + (p.x - a.x) / (b.x - a.x) * (b.y - a.y);
        const double ahead = up ? y - p.y : p.y - y;
        if (ahead >= -kMargin)
            gap = std::min(gap, std::max(0.0, ahead));
    }
    return gap;
}

/// How far `moving` goes down before it meets `fixed` (the two apart): two outlines first meet where a
/// vertex of one reaches an edge of the other.
double gapBelow(const Outline& moving, const Outline& fixed)
{
    double gap = kFar;
    const auto from = [&](const Outline& vertices, const Outline& edges, bool up) {
        forEachRing(vertices, [&](const Polygon& ring) {
            for (const Point2& p : ring)
                forEachRing(edges, [&](const Polygon& other) { gap = std::min(gap, rayGap(p, other, up)); });
        });
    };
    from(moving, fixed, false);
    from(fixed, moving, true);
    return gap;
}

}  // namespace

Layout compacted(const Layout& layout, const PackProblem& problem)
{
    if (!problem.strip || layout.sheets.size() != 1)
        return layout;
    const PackSettings& settings = problem.settings;
    const double clearance = settings.kerf + settings.spacing;
    const size_t n = layout.placements.size();
    // Each part's outline, and that outline grown by the clearance (mitred: never closer than a round
    // offset), which must stay off the others' outlines.
    std::vector<Outline> outline(n), grown(n);
    std::vector<geometry::Box2> box(n), grownBox(n);
    const auto place = [&](size_t i) {
        const Placement& p = layout.placements[i];
        outline[i] = geometry::placed(problem.parts[p.part].outline, p.rotation, p.x, p.y);
        grown[i] = clearance > 0 ? geometry::offset(outline[i], clearance + kGrowth) : outline[i];
        box[i] = geometry::bounds(outline[i].outer);
        grownBox[i] = geometry::bounds(grown[i].outer);
    };
    Layout out = layout;
    for (size_t i = 0; i < n; ++i)
        place(i);
    std::vector<size_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&](size_t a, size_t b) { return layout.placements[a].y < layout.placements[b].y; });
    for (size_t i : order) {
        Placement& moving = out.placements[i];
        double gap = moving.y - settings.trim;
        for (size_t j = 0; j < n && gap > 0; ++j)
            if (j != i && box[j].minY < grownBox[i].maxY && box[j].maxX >= grownBox[i].minX &&
                box[j].minX <= grownBox[i].maxX)
                gap = std::min(
                    gap, geometry::overlap(grown[i], outline[j]) ? 0.0 : gapBelow(grown[i], outline[j]));
        if (gap > kMargin) {
            for (Outline* o : {&outline[i], &grown[i]}) {
                for (Point2& p : o->outer)
                    p.y -= gap - kMargin;
                for (Polygon& hole : o->holes)
                    for (Point2& p : hole)
                        p.y -= gap - kMargin;
            }
            moving.y -= gap - kMargin;
            box[i] = geometry::bounds(outline[i].outer);
            grownBox[i] = geometry::bounds(grown[i].outer);
        }
    }
    double before = 0, after = 0;
    for (size_t i = 0; i < n; ++i) {
        before = std::max(before, layout.placements[i].y + layout.placements[i].height);
        after = std::max(after, out.placements[i].y + out.placements[i].height);
    }
    const double shorter = before - after, width = out.sheets.front().width;
    out.sheets.front().height -= shorter;
    out.stripHeight -= shorter;
    out.sheetArea -= width * shorter;
    out.boundingArea -= width * shorter;
    return out;
}

}  // namespace fabguide::material
