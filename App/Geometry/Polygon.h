// Plain 2-D geometry shared by the domains: points, polygons, outlines with holes (millimetres).
#pragma once

#include <utility>
#include <vector>

namespace fabguide::geometry {

struct Point2 {
    double x = 0;
    double y = 0;
};

/// A closed polygon; the last point connects back to the first.
using Polygon = std::vector<Point2>;

/// A planar part's shape: one outer contour (counter-clockwise) and holes (clockwise).
struct Outline {
    Polygon outer;
    std::vector<Polygon> holes;
};

/// An axis-aligned box.
struct Box2 {
    double minX = 0, minY = 0, maxX = 0, maxY = 0;
    double width() const { return maxX - minX; }
    double height() const { return maxY - minY; }
};

/// An axis-aligned w × h rectangle with its lower-left corner at the origin.
Outline rectangle(double width, double height);

/// Signed area: positive for counter-clockwise polygons.
double signedArea(const Polygon& polygon);

/// Area of the outer contour less its holes.
double area(const Outline& outline);

/// Length of a closed contour, its last point joined to its first.
double perimeter(const Polygon& contour);

Box2 bounds(const Polygon& polygon);

/// Two edges of the polygon that cross or touch other than at their shared corner (edge i runs from point i
/// to point i + 1), or {-1, -1} when it is simple. Edges are compared by their boxes first: fast on a few
/// thousand points.
std::pair<int, int> selfCrossing(const Polygon& polygon);

/// The first hole whose contour touches or crosses the outer contour, or -1: a sweep along x over both.
int holeTouchingOuter(const Outline& outline);

/// True when the outline is a hole-free axis-aligned rectangle.
bool isRectangle(const Outline& outline);

/// The x intervals in which the outline has area between heights y0 and y1 (clipped with Clipper).
std::vector<std::pair<double, double>> spansBetween(const Outline& outline, double y0, double y1);

/// A turn by a multiple of 90° counter-clockwise about the origin followed by a move.
struct Placement2 {
    int degrees = 0;
    double dx = 0, dy = 0;
    Point2 operator()(Point2 p) const;
};

/// The placement that turns `outline` by `degrees` and moves its bounding box's lower-left corner to (x, y).
Placement2 placement(const Outline& outline, int degrees, double x, double y);

/// The outline turned by `degrees` (counter-clockwise; quarter turns exact) and moved so its bounding box's
/// lower-left corner is at (x, y).
Outline placed(const Outline& outline, int degrees, double x, double y);

/// The outline with `polygons` added (union); throws std::runtime_error if it falls into pieces.
Outline unite(const Outline& outline, const std::vector<Polygon>& polygons);

/// The outline with `polygons` cut away: cut inside it they become holes, cut across its edge notches.
/// Throws std::runtime_error if it falls into pieces.
Outline subtract(const Outline& outline, const std::vector<Polygon>& polygons);

/// Whether p lies inside the polygon (on its edge counts as either).
bool contains(const Polygon& polygon, Point2 p);

/// Whether p lies in the outline's material: inside its outer contour, in none of its holes (on an edge
/// counts as either).
bool inMaterial(const Outline& outline, Point2 p);

/// Whether two outlines' material overlaps: an edge of one crosses an edge of the other (touching is not
/// crossing), or one lies in the other's material.
bool overlap(const Outline& a, const Outline& b);

/// The parts of `polygon` inside `outline`.
std::vector<Polygon> intersect(const Polygon& polygon, const Outline& outline);

/// Dogbones (a router's relief at inside corners): the outline less a disc of the bit's radius at each
/// corner where the material turns in by at least 30° (a notch's or a slot's, a hole's), centred on the
/// corner's bisector a radius out into the waste, so a round bit of `diameter` cuts the corner square.
Outline dogboned(const Outline& outline, double diameter);

/// A closed contour cut open by `tabs` gaps of `width` mm, evenly spaced along it (the first a quarter of a
/// spacing from its start): the open pieces between them, each from one gap to the next. The contour whole
/// (one piece, closed by repeating its first point) when it is too short for the gaps.
std::vector<Polygon> withTabs(const Polygon& contour, int tabs, double width);

/// The gaps withTabs leaves, each as the points where it starts and ends on the contour; none when the
/// contour is too short for them.
std::vector<std::pair<Point2, Point2>> tabGaps(const Polygon& contour, int tabs, double width);

/// The point of the outline's material farthest from its edges and holes (its pole of inaccessibility, to
/// 0.01 mm) and that distance, the radius of the largest circle inside it: found by eroding the outline
/// (Clipper, round corners) by a bisected depth until nothing is left.
std::pair<Point2, double> deepestPoint(const Outline& outline);

/// The contour with only the vertices that keep it within `tolerance` of every vertex it had
/// (Douglas-Peucker, on both halves of the closed contour): a 100,000-point circle read from a file becomes a
/// few hundred.
Polygon simplified(const Polygon& polygon, double tolerance);

/// Grows outer contours and shrinks holes by `distance` (mitred corners), using Clipper:
/// the tool path of a cut of width 2·distance that leaves the outline at its nominal size.
Outline offset(const Outline& outline, double distance);

}  // namespace fabguide::geometry
