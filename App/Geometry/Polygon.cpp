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
