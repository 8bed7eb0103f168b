#include "Geometry/Polygon.h"

#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace fabguide::geometry {

namespace {

constexpr double kClipperScale = 1e4;  // Clipper works on integers: 0.1 µm steps

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
        default:
            return p;
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

Outline placed(const Outline& outline, int degrees, double x, double y)
{
    Outline out;
    double minX = std::numeric_limits<double>::max(), minY = minX;
    auto turn = [&](const Polygon& polygon) {
        Polygon result;
        for (const Point2& p : polygon) {
            result.push_back(turned(p, degrees));
            minX = std::min(minX, result.back().x);
            minY = std::min(minY, result.back().y);
        }
        return result;
    };
    out.outer = turn(outline.outer);
    for (const Polygon& hole : outline.holes)
        out.holes.push_back(turn(hole));
    auto move = [&](Polygon& polygon) {
        for (Point2& p : polygon)
            p = {p.x - minX + x, p.y - minY + y};
    };
    move(out.outer);
    for (Polygon& hole : out.holes)
        move(hole);
    return out;
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
