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

template <class AnOutline, class Visit>  // Outline or const Outline
void forEachRing(AnOutline& outline, Visit&& visit)
{
    visit(outline.outer);
    for (auto& hole : outline.holes)
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

/// Each placed part's outline, and that outline grown by the clearance (mitred: never closer than a round
/// offset), which must stay off the others' outlines.
struct Outlines {
    std::vector<Outline> outline, grown;
};

Outlines outlinesOf(const Layout& layout, const PackProblem& problem)
{
    const double clearance = problem.settings.kerf + problem.settings.spacing;
    Outlines o;
    for (const Placement& p : layout.placements) {
        o.outline.push_back(geometry::placed(problem.parts[p.part].outline, p.rotation, p.x, p.y));
        o.grown.push_back(clearance > 0 ? geometry::offset(o.outline.back(), clearance + kGrowth)
                                        : o.outline.back());
    }
    return o;
}

void moveY(Outline& o, double dy)
{
    forEachRing(o, [&](Polygon& ring) {
        for (Point2& p : ring)
            p.y += dy;
    });
}

/// Each part, the lowest first, slid down as far as its outline stays clear of every other's on its sheet
/// and `trim` above the sheet's edge.
void slideDown(Layout& out, Outlines& o, double trim)
{
    const size_t n = out.placements.size();
    std::vector<geometry::Box2> box(n), grownBox(n);
    for (size_t i = 0; i < n; ++i)
        box[i] = geometry::bounds(o.outline[i].outer), grownBox[i] = geometry::bounds(o.grown[i].outer);
    std::vector<size_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&](size_t a, size_t b) { return out.placements[a].y < out.placements[b].y; });
    for (size_t i : order) {
        Placement& moving = out.placements[i];
        double gap = moving.y - trim;
        for (size_t j = 0; j < n && gap > 0; ++j)
            if (j != i && out.placements[j].sheet == moving.sheet && box[j].minY < grownBox[i].maxY &&
                box[j].maxX >= grownBox[i].minX && box[j].minX <= grownBox[i].maxX)
                gap = std::min(gap, geometry::overlap(o.grown[i], o.outline[j])
                                        ? 0.0
                                        : gapBelow(o.grown[i], o.outline[j]));
        if (gap > kMargin) {
            moveY(o.outline[i], -(gap - kMargin));
            moveY(o.grown[i], -(gap - kMargin));
            moving.y -= gap - kMargin;
            box[i] = geometry::bounds(o.outline[i].outer);
            grownBox[i] = geometry::bounds(o.grown[i].outer);
        }
    }
}

/// The layout mirrored in its diagonal (x and y swapped), so that sliding down slides left.
void transpose(Layout& layout, Outlines& o)
{
    for (Placement& p : layout.placements)
        std::swap(p.x, p.y), std::swap(p.width, p.height);
    for (std::vector<Outline>* outlines : {&o.outline, &o.grown})
        for (Outline& outline : *outlines)
            forEachRing(outline, [](Polygon& ring) {
                for (Point2& p : ring)
                    std::swap(p.x, p.y);
            });
}

}  // namespace

Layout compacted(const Layout& layout, const PackProblem& problem)
{
    if (!problem.strip || layout.sheets.size() != 1)
        return layout;
    Layout out = layout;
    Outlines o = outlinesOf(layout, problem);
    slideDown(out, o, problem.settings.trim);
    double before = 0, after = 0;
    for (size_t i = 0; i < out.placements.size(); ++i) {
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

Layout slidTogether(const Layout& layout, const PackProblem& problem)
{
    Layout out = layout;
    Outlines o = outlinesOf(layout, problem);
    for (int round = 0; round < 2; ++round) {
        slideDown(out, o, problem.settings.trim);
        transpose(out, o);
        slideDown(out, o, problem.settings.trim);
        transpose(out, o);
    }
    return out;
}

}  // namespace fabguide::material
