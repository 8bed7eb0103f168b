#include "Layout/CommonLine.h"

#include <algorithm>
#include <cmath>

namespace fabguide::material {

namespace {

using geometry::Point2;

struct Segment {
    Point2 a, b;
};

/// A stretch [from, to] (mm along it) of edge `edge` of a closed path.
struct Stretch {
    size_t edge;
    double from, to;
};

double length(Point2 a, Point2 b)
{
    return std::hypot(b.x - a.x, b.y - a.y);
}

/// The segments a path cuts: a closed path's last point joined to its first.
std::vector<Segment> segmentsOf(const ToolPath& path)
{
    std::vector<Segment> out;
    const geometry::Polygon& p = path.points;
    for (size_t i = 0; i + 1 < p.size(); ++i)
        out.push_back({p[i], p[i + 1]});
    if (!path.open && p.size() > 2)
        out.push_back({p.back(), p.front()});
    return out;
}

/// The intervals of edge a→b (mm from a) that the segments follow: on its line within `tolerance`, merged.
std::vector<std::pair<double, double>> followed(Point2 a, Point2 b, const std::vector<Segment>& cut,
                                                double tolerance)
{
    const double l = length(a, b);
    const Point2 u{(b.x - a.x) / l, (b.y - a.y) / l};
    const auto along = [&](Point2 q) { return (q.x - a.x) * u.x + (q.y - a.y) * u.y; };
    const auto off = [&](Point2 q) { return std::abs((q.y - a.y) * u.x - (q.x - a.x) * u.y); };
    std::vector<std::pair<double, double>> spans;
    for (const Segment& s : cut) {
        if (off(s.a) > tolerance || off(s.b) > tolerance)
            continue;
        const double from = std::max(0.0, std::min(along(s.a), along(s.b)));
        const double to = std::min(l, std::max(along(s.a), along(s.b)));
        if (to - from > tolerance)
            spans.push_back({from, to});
    }
    std::sort(spans.begin(), spans.end());
    std::vector<std::pair<double, double>> merged;
    for (const auto& span : spans)
        if (!merged.empty() && span.first <= merged.back().second + tolerance)
            merged.back().second = std::max(merged.back().second, span.second);
        else
            merged.push_back(span);
    return merged;
}

/// The stretches of a closed contour that no segment of `cut` follows, in order round it.
std::vector<Stretch> uncut(const geometry::Polygon& contour, const std::vector<Segment>& cut,
                           double tolerance)
{
    std::vector<Stretch> left;
    for (size_t i = 0; i < contour.size(); ++i) {
        const Point2 a = contour[i], b = contour[(i + 1) % contour.size()];
        const double l = length(a, b);
        if (l <= 0)
            continue;
        double from = 0;
        for (const auto& [start, end] : followed(a, b, cut, tolerance)) {
            if (start - from > tolerance)
                left.push_back({i, from, start});
            from = end;
        }
        if (l - from > tolerance || from == 0)
            left.push_back({i, from, l});
    }
    return left;
}

/// The open paths along the stretches, joined where one ends at the corner the next starts from.
std::vector<geometry::Polygon> joined(const geometry::Polygon& contour, const std::vector<Stretch>& left)
{
    const size_t n = contour.size();
    const auto point = [&](size_t edge, double at) {
        const Point2 a = contour[edge], b = contour[(edge + 1) % n];
        const double t = at / length(a, b);
        return Point2{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
    };
    const auto follows = [&](const Stretch& before, const Stretch& s) {  // no gap between them
        return s.from == 0 && (before.edge + 1) % n == s.edge &&
               before.to == length(contour[before.edge], contour[(before.edge + 1) % n]);
    };
    size_t first = 0;  // a stretch with a gap before it, so no path is cut at the contour's start point
    while (first < left.size() && follows(left[(first + left.size() - 1) % left.size()], left[first]))
        ++first;
    std::vector<geometry::Polygon> paths;
    for (size_t k = 0; k < left.size(); ++k) {
        const Stretch& s = left[(first + k) % left.size()];
        if (k == 0 || !follows(left[(first + k - 1) % left.size()], s))
            paths.push_back({point(s.edge, s.from)});
        paths.back().push_back(point(s.edge, s.to));
    }
    return paths;
}

}  // namespace

double cutCommonLinesOnce(std::vector<ToolPath>& cuts, double tolerance)
{
    std::vector<ToolPath> out;
    std::vector<Segment> cut;  // what the paths so far cut
    double saved = 0;
    for (ToolPath& path : cuts) {
        if (path.open || path.tabbed) {
            out.push_back(std::move(path));
            continue;
        }
        const std::vector<Stretch> left = uncut(path.points, cut, tolerance);
        const std::vector<Segment> own = segmentsOf(path);
        cut.insert(cut.end(), own.begin(), own.end());
        double kept = 0;
        for (const Stretch& s : left)
            kept += s.to - s.from;
        const double whole = geometry::perimeter(path.points);
        if (whole - kept <= tolerance) {  // nothing of it cut before
            out.push_back(std::move(path));
            continue;
        }
        saved += whole - kept;
        for (geometry::Polygon& piece : joined(path.points, left)) {
            ToolPath open = path;
            open.points = std::move(piece);
            open.open = true;
            out.push_back(std::move(open));
        }
    }
    cuts = std::move(out);
    return saved;
}

}  // namespace fabguide::material
