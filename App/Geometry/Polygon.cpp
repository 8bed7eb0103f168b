#include "Geometry/Polygon.h"

#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace fabguide::geometry {

namespace {

constexpr double kClipperScale = 1e4;  // Clipper works on integers: 0.1 µm steps
constexpr double kPi = 3.14159265358979323846;

ClipperLib::Path toClipper(const Polygon& polygon)
{
    ClipperLib::Path path;
    for (const Point2& p : polygon)
        path.emplace_back(std::llround(p.x * kClipperScale), std::llround(p.y * kClipperScale));
    return path;
}

Polygon fromClipper(const ClipperLib::Path& path)
{
    Polygon polygon;
    for (const ClipperLib::IntPoint& p : path)
        polygon.push_back({p.X / kClipperScale, p.Y / kClipperScale});
    return polygon;
}

Point2 turned(Point2 p, int degrees)
{
    switch (((degrees % 360) + 360) % 360) {
        case 90:
            return {-p.y, p.x};
        case 180:
            return {-p.x, -p.y};
        case 270:
            return {p.y, -p.x};
        case 0:
            return p;
        default: {  // free rotation: any whole degree
            const double a = degrees * kPi / 180, c = std::cos(a), s = std::sin(a);
            return {c * p.x - s * p.y, s * p.x + c * p.y};
        }
    }
}

}  // namespace

Outline rectangle(double width, double height)
{
    return {{{0, 0}, {width, 0}, {width, height}, {0, height}}, {}};
}

double signedArea(const Polygon& polygon)
{
    double twice = 0;
    for (size_t i = 0; i < polygon.size(); ++i) {
        const Point2& a = polygon[i];
        const Point2& b = polygon[(i + 1) % polygon.size()];
        twice += a.x * b.y - b.x * a.y;
    }
    return twice / 2;
}

double area(const Outline& outline)
{
    double total = std::abs(signedArea(outline.outer));
    for (const Polygon& hole : outline.holes)
        total -= std::abs(signedArea(hole));
    return total;
}

Box2 bounds(const Polygon& polygon)
{
    Box2 box{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
             std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest()};
    for (const Point2& p : polygon)
        box = {std::min(box.minX, p.x), std::min(box.minY, p.y), std::max(box.maxX, p.x),
               std::max(box.maxY, p.y)};
    return box;
}

bool isRectangle(const Outline& outline)
{
    const Box2 box = bounds(outline.outer);
    return outline.holes.empty() && outline.outer.size() == 4 &&
           std::abs(std::abs(signedArea(outline.outer)) - box.width() * box.height()) <
               1e-9 * (1 + box.width() * box.height());
}

Outline atOrigin(const Outline& outline)
{
    return placed(outline, 0, 0, 0);
}

std::vector<std::pair<double, double>> spansBetween(const Outline& outline, double y0, double y1)
{
    const Box2 box = bounds(outline.outer);
    ClipperLib::Clipper clipper;
    clipper.AddPath(toClipper(outline.outer), ClipperLib::ptSubject, true);
    for (const Polygon& hole : outline.holes)
        clipper.AddPath(toClipper(hole), ClipperLib::ptSubject, true);
    clipper.AddPath(
        toClipper({{box.minX - 1, y0}, {box.maxX + 1, y0}, {box.maxX + 1, y1}, {box.minX - 1, y1}}),
        ClipperLib::ptClip, true);
    ClipperLib::Paths pieces;
    clipper.Execute(ClipperLib::ctIntersection, pieces, ClipperLib::pftEvenOdd, ClipperLib::pftNonZero);
    std::vector<std::pair<double, double>> spans;
    for (const ClipperLib::Path& piece : pieces) {
        const Box2 b = bounds(fromClipper(piece));
        spans.emplace_back(b.minX, b.maxX);
    }
    return spans;
}

Point2 Placement2::operator()(Point2 p) const
{
    const Point2 t = turned(p, degrees);
    return {t.x + dx, t.y + dy};
}

Placement2 placement(const Outline& outline, int degrees, double x, double y)
{
    double minX = std::numeric_limits<double>::max(), minY = minX;
    for (const Point2& p : outline.outer) {
        const Point2 t = turned(p, degrees);
        minX = std::min(minX, t.x);
        minY = std::min(minY, t.y);
    }
    return {degrees, x - minX, y - minY};
}

Outline placed(const Outline& outline, int degrees, double x, double y)
{
    const Placement2 move = placement(outline, degrees, x, y);
    auto apply = [&](const Polygon& polygon) {
        Polygon result;
        for (const Point2& p : polygon)
            result.push_back(move(p));
        return result;
    };
    Outline out{apply(outline.outer), {}};
    for (const Polygon& hole : outline.holes)
        out.holes.push_back(apply(hole));
    return out;
}

namespace {

ClipperLib::Paths paths(const Outline& outline)
{
    ClipperLib::Paths all{toClipper(outline.outer)};
    for (const Polygon& hole : outline.holes)
        all.push_back(toClipper(hole));
    return all;
}

ClipperLib::Paths paths(const std::vector<Polygon>& polygons)
{
    ClipperLib::Paths all;
    for (const Polygon& polygon : polygons)
        all.push_back(toClipper(polygon));
    return all;
}

/// One outline from a Clipper result tree, or an error if it is several pieces.
Outline single(const ClipperLib::PolyTree& tree, const char* what)
{
    if (tree.ChildCount() != 1)
        throw std::runtime_error(std::string(what) + " leaves the board in " +
                                 std::to_string(tree.ChildCount()) + " pieces");
    const ClipperLib::PolyNode* outer = tree.Childs[0];
    Outline out{fromClipper(outer->Contour), {}};
    for (const ClipperLib::PolyNode* hole : outer->Childs) {
        out.holes.push_back(fromClipper(hole->Contour));
        if (hole->ChildCount())
            throw std::runtime_error(std::string(what) + " leaves an island inside a hole");
    }
    return out;
}

Outline combine(const Outline& outline, const std::vector<Polygon>& polygons, ClipperLib::ClipType type,
                const char* what)
{
    ClipperLib::Clipper clipper;
    clipper.AddPaths(paths(outline), ClipperLib::ptSubject, true);
    clipper.AddPaths(paths(polygons), ClipperLib::ptClip, true);
    ClipperLib::PolyTree tree;
    clipper.Execute(type, tree, ClipperLib::pftEvenOdd, ClipperLib::pftNonZero);
    return single(tree, what);
}

}  // namespace

Outline unite(const Outline& outline, const std::vector<Polygon>& polygons)
{
    return combine(outline, polygons, ClipperLib::ctUnion, "adding tabs");
}

Outline subtract(const Outline& outline, const std::vector<Polygon>& polygons)
{
    return combine(outline, polygons, ClipperLib::ctDifference, "cutting slots");
}

namespace {

/// The sign of the turn a -> b -> c: +1 left, -1 right, 0 straight on.
int turn(const Point2& a, const Point2& b, const Point2& c)
{
    const double cross = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    return (cross > 0) - (cross < 0);
}

/// Whether p, on the line through a and b, lies within their box.
bool within(const Point2& a, const Point2& b, const Point2& p)
{
    return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
           p.y <= std::max(a.y, b.y);
}

/// Whether segments ab and cd share a point.
bool meet(const Point2& a, const Point2& b, const Point2& c, const Point2& d)
{
    const int d1 = turn(c, d, a), d2 = turn(c, d, b), d3 = turn(a, b, c), d4 = turn(a, b, d);
    if (d1 * d2 < 0 && d3 * d4 < 0)
        return true;
    return (d1 == 0 && within(c, d, a)) || (d2 == 0 && within(c, d, b)) || (d3 == 0 && within(a, b, c)) ||
           (d4 == 0 && within(a, b, d));
}

}  // namespace

std::pair<int, int> selfCrossing(const Polygon& polygon)
{
    const int n = static_cast<int>(polygon.size());
    std::vector<int> byLeft(n);  // edges by their box's left side, for a sweep along x
    for (int i = 0; i < n; ++i)
        byLeft[i] = i;
    const auto left = [&](int i) { return std::min(polygon[i].x, polygon[(i + 1) % n].x); };
    const auto right = [&](int i) { return std::max(polygon[i].x, polygon[(i + 1) % n].x); };
    std::sort(byLeft.begin(), byLeft.end(), [&](int a, int b) { return left(a) < left(b); });
    for (int u = 0; u < n; ++u)
        for (int v = u + 1; v < n && left(byLeft[v]) <= right(byLeft[u]); ++v) {
            const int i = std::min(byLeft[u], byLeft[v]), j = std::max(byLeft[u], byLeft[v]);
            if (j == i + 1 || (i == 0 && j == n - 1)) {  // neighbours: only folding back onto each other
                const int shared = j == i + 1 ? j : 0;
                const Point2 &p = polygon[shared], &a = polygon[(shared + n - 1) % n],
                             &b = polygon[(shared + 1) % n];
                if (turn(a, p, b) == 0 && (b.x - p.x) * (a.x - p.x) + (b.y - p.y) * (a.y - p.y) > 0)
                    return {i, j};
                continue;
            }
            if (meet(polygon[i], polygon[(i + 1) % n], polygon[j], polygon[(j + 1) % n]))
                return {i, j};
        }
    return {-1, -1};
}

int holeTouchingOuter(const Outline& outline)
{
    struct Edge {
        Point2 a, b;
        int hole;  // -1: the outer contour
        double left() const { return std::min(a.x, b.x); }
        double right() const { return std::max(a.x, b.x); }
    };
    std::vector<Edge> edges;
    const auto add = [&](const Polygon& polygon, int hole) {
        for (size_t i = 0; i < polygon.size(); ++i)
            edges.push_back({polygon[i], polygon[(i + 1) % polygon.size()], hole});
    };
    add(outline.outer, -1);
    for (size_t h = 0; h < outline.holes.size(); ++h)
        add(outline.holes[h], static_cast<int>(h));
    std::sort(edges.begin(), edges.end(), [](const Edge& e, const Edge& f) { return e.left() < f.left(); });
    for (size_t u = 0; u < edges.size(); ++u)  // a sweep along x: only edges whose boxes overlap are met
        for (size_t v = u + 1; v < edges.size() && edges[v].left() <= edges[u].right(); ++v) {
            const Edge &e = edges[u], &f = edges[v];
            if ((e.hole < 0) != (f.hole < 0) && std::min(e.a.y, e.b.y) <= std::max(f.a.y, f.b.y) &&
                std::min(f.a.y, f.b.y) <= std::max(e.a.y, e.b.y) && meet(e.a, e.b, f.a, f.b))
                return std::max(e.hole, f.hole);
        }
    return -1;
}

bool contains(const Polygon& polygon, Point2 p)
{
    bool inside = false;  // a ray to the right crosses the boundary an odd number of times
    for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
        const Point2 &a = polygon[i], &b = polygon[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y))
            inside = !inside;
    }
    return inside;
}

bool inMaterial(const Outline& outline, Point2 p)
{
    return contains(outline.outer, p) && std::none_of(outline.holes.begin(), outline.holes.end(),
                                                      [&](const Polygon& hole) { return contains(hole, p); });
}

bool overlap(const Outline& a, const Outline& b)
{
    const auto rings = [](const Outline& o) {
        std::vector<const Polygon*> all{&o.outer};
        for (const Polygon& hole : o.holes)
            all.push_back(&hole);
        return all;
    };
    for (const Polygon* ringA : rings(a))
        for (const Polygon* ringB : rings(b))
            for (size_t i = 0; i < ringA->size(); ++i)
                for (size_t j = 0; j < ringB->size(); ++j) {
                    const Point2 &p = (*ringA)[i], &q = (*ringA)[(i + 1) % ringA->size()];
                    const Point2 &r = (*ringB)[j], &s = (*ringB)[(j + 1) % ringB->size()];
                    if (turn(p, q, r) * turn(p, q, s) < 0 && turn(r, s, p) * turn(r, s, q) < 0)
                        return true;
                }
    return inMaterial(b, a.outer.front()) || inMaterial(a, b.outer.front());
}

std::vector<Polygon> intersect(const Polygon& polygon, const Outline& outline)
{
    ClipperLib::Clipper clipper;
    clipper.AddPath(toClipper(polygon), ClipperLib::ptSubject, true);
    clipper.AddPaths(paths(outline), ClipperLib::ptClip, true);
    ClipperLib::Paths pieces;
    clipper.Execute(ClipperLib::ctIntersection, pieces, ClipperLib::pftNonZero, ClipperLib::pftEvenOdd);
    std::vector<Polygon> out;
    for (const ClipperLib::Path& piece : pieces)
        out.push_back(fromClipper(piece));
    return out;
}

Outline dogboned(const Outline& outline, double diameter)
{
    // Discs a hair (0.1 mm) larger than the bit, sampled to 0.05 mm: the bit's centre reaches its spot with
    // room to spare, so the tool path (the outline offset by the bit's radius) gets there.
    const double r = diameter / 2, disc = r + 0.1;
    const int sides = std::max(16, static_cast<int>(std::ceil(kPi / std::acos(1 - 0.05 / disc))));
    std::vector<Polygon> discs;
    const auto relieve = [&](const Polygon& contour) {  // material on the left of every contour
        const size_t n = contour.size();
        for (size_t k = 0; k < n; ++k) {
            const Point2 &a = contour[(k + n - 1) % n], &p = contour[k], &b = contour[(k + 1) % n];
            const double ax = a.x - p.x, ay = a.y - p.y, bx = b.x - p.x, by = b.y - p.y;
            const double la = std::hypot(ax, ay), lb = std::hypot(bx, by);
            if (la < 1e-9 || lb < 1e-9)
                continue;
            const double cross = (p.x - a.x) * by - (p.y - a.y) * bx;  // < 0: a right turn, an inside corner
            const double turn = std::acos(std::clamp(-(ax * bx + ay * by) / (la * lb), -1.0, 1.0));
            if (cross >= 0 || turn < kPi / 6)
                continue;
            const double wx = ax / la + bx / lb, wy = ay / la + by / lb, lw = std::hypot(wx, wy);
            const Point2 c{p.x + r * wx / lw, p.y + r * wy / lw};
            discs.emplace_back();
            for (int s = 0; s < sides; ++s)
                discs.back().push_back(
                    {c.x + disc * std::cos(2 * kPi * s / sides), c.y + disc * std::sin(2 * kPi * s / sides)});
        }
    };
    relieve(outline.outer);
    for (const Polygon& hole : outline.holes)
        relieve(hole);
    return discs.empty() ? outline : subtract(outline, discs);
}

namespace {

/// A closed contour measured along its length: its points (the first repeated at the end), the arc length
/// at each, and the point at any arc length.
struct Loop {
    explicit Loop(const Polygon& contour) : points(contour), at{0}
    {
        points.push_back(contour.front());
        for (size_t k = 1; k < points.size(); ++k)
            at.push_back(at.back() +
                         std::hypot(points[k].x - points[k - 1].x, points[k].y - points[k - 1].y));
    }
    double length() const { return at.back(); }
    Point2 pointAt(double s) const
    {
        s = std::fmod(s, length());
        const size_t k = static_cast<size_t>(std::upper_bound(at.begin(), at.end(), s) - at.begin());
        const size_t i = std::clamp<size_t>(k, 1, points.size() - 1);
        const double t = (s - at[i - 1]) / std::max(at[i] - at[i - 1], 1e-12);
        return {points[i - 1].x + t * (points[i].x - points[i - 1].x),
                points[i - 1].y + t * (points[i].y - points[i - 1].y)};
    }
    /// Where the gaps of withTabs lie along it: [from, to) in arc length, none when they do not fit.
    std::vector<std::pair<double, double>> gaps(int tabs, double width) const
    {
        const double spacing = length() / std::max(tabs, 1);
        std::vector<std::pair<double, double>> found;
        for (int k = 0; tabs >= 1 && width > 0 && width < spacing / 2 && k < tabs; ++k)
            found.emplace_back((k + 0.25) * spacing - width / 2, (k + 0.25) * spacing + width / 2);
        return found;
    }
    Polygon points;
    std::vector<double> at;
};

}  // namespace

double perimeter(const Polygon& contour)
{
    return contour.empty() ? 0 : Loop(contour).length();
}

std::vector<Polygon> withTabs(const Polygon& contour, int tabs, double width)
{
    const Loop loop(contour);
    const std::vector<std::pair<double, double>> gaps = loop.gaps(tabs, width);
    if (gaps.empty())
        return {loop.points};
    const double length = loop.length();
    std::vector<Polygon> pieces;
    for (size_t k = 0; k < gaps.size(); ++k) {
        // From the end of gap k to the start of the next, around the loop.
        const double from = gaps[k].second,
                     to = gaps[(k + 1) % gaps.size()].first + (k + 1 == gaps.size() ? length : 0);
        Polygon piece{loop.pointAt(from)};
        const size_t n = loop.points.size();
        for (size_t j = 0; j < 2 * n; ++j) {  // the loop's points strictly between, wrapping once
            const double s = loop.at[j % n] + (j >= n ? length : 0);
            if (s > from && s < to && j % n != n - 1)
                piece.push_back(loop.points[j % n]);
        }
        piece.push_back(loop.pointAt(to));
        pieces.push_back(std::move(piece));
    }
    return pieces;
}

std::vector<std::pair<Point2, Point2>> tabGaps(const Polygon& contour, int tabs, double width)
{
    const Loop loop(contour);
    std::vector<std::pair<Point2, Point2>> ends;
    for (const auto& [from, to] : loop.gaps(tabs, width))
        ends.emplace_back(loop.pointAt(from + loop.length()), loop.pointAt(to));
    return ends;
}

std::pair<Point2, double> deepestPoint(const Outline& outline)
{
    const auto eroded = [&](double depth) {  // the material at least `depth` from every edge
        ClipperLib::ClipperOffset clipper(2, 0.005 * kClipperScale);
        clipper.AddPath(toClipper(outline.outer), ClipperLib::jtRound, ClipperLib::etClosedPolygon);
        for (const Polygon& hole : outline.holes)
            clipper.AddPath(toClipper(hole), ClipperLib::jtRound, ClipperLib::etClosedPolygon);
        ClipperLib::Paths left;
        clipper.Execute(left, -depth * kClipperScale);
        return left;
    };
    const Box2 box = bounds(outline.outer);
    double lo = 0, hi = std::min(box.width(), box.height()) / 2;
    while (hi - lo > 0.01) {
        const double mid = (lo + hi) / 2;
        (eroded(mid).empty() ? hi : lo) = mid;
    }
    // What is left at that depth is a sliver around the pole: the middle of its largest piece.
    const ClipperLib::Paths left = eroded(lo);
    const ClipperLib::Path* largest = nullptr;
    for (const ClipperLib::Path& piece : left)
        if (ClipperLib::Orientation(piece) &&
            (!largest || std::abs(ClipperLib::Area(piece)) > std::abs(ClipperLib::Area(*largest))))
            largest = &piece;
    if (!largest)  // too thin to erode at all: the box's centre
        return {{(box.minX + box.maxX) / 2, (box.minY + box.maxY) / 2}, 0};
    const Box2 pole = bounds(fromClipper(*largest));
    return {{(pole.minX + pole.maxX) / 2, (pole.minY + pole.maxY) / 2}, lo};
}

namespace {

/// The distance from p to the segment from a to b.
double toSegment(Point2 p, Point2 a, Point2 b)
{
    const double dx = b.x - a.x, dy = b.y - a.y, length2 = dx * dx + dy * dy;
    const double t =
        length2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / length2, 0.0, 1.0) : 0.0;
    return std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy);
}

/// Marks in `kept` the vertices of polygon[first..last] (indices mod its size) that Douglas-Peucker keeps.
void keepFarthest(const Polygon& polygon, size_t first, size_t last, double tolerance,
                  std::vector<bool>& kept)
{
    std::vector<std::pair<size_t, size_t>> todo{{first, last}};
    const size_t n = polygon.size();
    while (!todo.empty()) {
        const auto [from, to] = todo.back();
        todo.pop_back();
        double farthest = tolerance;
        size_t at = from;
        for (size_t k = from + 1; k < to; ++k)
            if (const double d = toSegment(polygon[k % n], polygon[from % n], polygon[to % n]); d > farthest)
                farthest = d, at = k;
        if (at != from) {
            kept[at % n] = true;
            todo.emplace_back(from, at);
            todo.emplace_back(at, to);
        }
    }
}

}  // namespace

Polygon simplified(const Polygon& polygon, double tolerance)
{
    const size_t n = polygon.size();
    if (n < 5)
        return polygon;
    size_t opposite = 1;  // the vertex farthest from the first: the two halves' ends
    for (size_t k = 2; k < n; ++k)
        if (std::hypot(polygon[k].x - polygon[0].x, polygon[k].y - polygon[0].y) >
            std::hypot(polygon[opposite].x - polygon[0].x, polygon[opposite].y - polygon[0].y))
            opposite = k;
    std::vector<bool> kept(n, false);
    kept[0] = kept[opposite] = true;
    keepFarthest(polygon, 0, opposite, tolerance, kept);
    keepFarthest(polygon, opposite, n, tolerance, kept);
    Polygon out;
    for (size_t k = 0; k < n; ++k)
        if (kept[k])
            out.push_back(polygon[k]);
    return out.size() >= 3 ? out : polygon;
}

Outline offset(const Outline& outline, double distance)
{
    ClipperLib::ClipperOffset clipper(/*miterLimit=*/4);
    clipper.AddPath(toClipper(outline.outer), ClipperLib::jtMiter, ClipperLib::etClosedPolygon);
    for (const Polygon& hole : outline.holes)
        clipper.AddPath(toClipper(hole), ClipperLib::jtMiter, ClipperLib::etClosedPolygon);
    ClipperLib::PolyTree tree;
    clipper.Execute(tree, distance * kClipperScale);
    Outline out;
    for (const ClipperLib::PolyNode* node = tree.GetFirst(); node; node = node->GetNext()) {
        if (node->IsHole())
            out.holes.push_back(fromClipper(node->Contour));
        else if (out.outer.empty())
            out.outer = fromClipper(node->Contour);
    }
    return out;
}

}  // namespace fabguide::geometry
