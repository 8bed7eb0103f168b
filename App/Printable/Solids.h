// OpenCASCADE solids for print-in-place geometry (thesis 4.5): boxes and rods, and Boolean operations that
// report failures by name instead of flags.
#pragma once

#include "Function/Model.h"

#include <TopoDS_Shape.hxx>
#include <gp_Pnt.hxx>
#include <gp_Trsf.hxx>

#include <array>
#include <chrono>
#include <string>
#include <vector>

namespace fabguide::printable {

using function::Cuboid;
using function::Joint;
using function::Model;
using function::Side;
/// A box: low and high x, y, z.
using Coordinates = std::array<double, 6>;

constexpr double kPi = 3.14159265358979323846;

/// What the Boolean operations are for while it lives: the part their errors name, and a time
/// budget for that part's operations, so that OpenCASCADE stuck on a shape ends in an error naming the part
/// and the operation rather than a hang. Nests, one stack per thread; a work without a budget (0) takes its
/// enclosing one's seconds, counted afresh.
class Work {
public:
    explicit Work(std::string part, double seconds = 0);
    ~Work();
    Work(const Work&) = delete;
    Work& operator=(const Work&) = delete;

private:
    friend struct Budget;
    std::string part_;
    double seconds_;
    std::chrono::steady_clock::time_point deadline_;
    const Work* enclosing_;
};

/// Coordinate `axis` (0: x, 1: y, 2: z) of a point, vector or direction. OpenCASCADE's Coord(index) and
/// SetCoord(index) reach y and z through a pointer to x, which clang's optimiser may take at its word (a y
/// written so was lost).
template <class Point>
double coord(const Point& p, int axis)
{
    return axis == 0 ? p.X() : axis == 1 ? p.Y() : p.Z();
}

/// Sets coordinate `axis` of a point or vector.
template <class Point>
void setCoord(Point& p, int axis, double value)
{
    if (axis == 0)
        p.SetX(value);
    else if (axis == 1)
        p.SetY(value);
    else
        p.SetZ(value);
}

/// The box with these corners.
TopoDS_Shape box(const Coordinates& c);

/// a united with b (b when a is null); std::runtime_error naming the failure, "try another --gap or --scale".
TopoDS_Shape fuse(const TopoDS_Shape& a, const TopoDS_Shape& b);

/// The union of shapes, in one operation (a wall of carcasses: much faster than one at a time).
TopoDS_Shape fuse(const std::vector<TopoDS_Shape>& shapes);

/// Whether a and b share material or touch.
bool touches(const TopoDS_Shape& a, const TopoDS_Shape& b);

/// In mm³.
double volumeOf(const TopoDS_Shape& s);

/// a less the tools, in one operation (tools that touch along faces are cut more reliably so than united
/// first). A cut takes at most its tools' volume; OpenCASCADE sometimes returns a fragment without an error,
/// which is refused here rather than printed.
TopoDS_Shape cut(const TopoDS_Shape& a, const std::vector<TopoDS_Shape>& tools);

TopoDS_Shape cut(const TopoDS_Shape& a, const TopoDS_Shape& b);

/// The shapes as one compound, not united (for display).
TopoDS_Shape compound(const std::vector<TopoDS_Shape>& shapes);

/// A copy of s moved by t.
TopoDS_Shape moved(const TopoDS_Shape& s, const gp_Trsf& t);

/// A cylinder of radius r around the axis `axis` through `at`, from `from` to `to` along it.
TopoDS_Shape rod(const gp_Pnt& at, int axis, double from, double to, double r);

/// What a rod of radius r round the axis `axis`, from `from` to `to` along it, fills moving from a to b
/// across it (a slot): two half rods joined by flat sides, one profile extruded, so that no Boolean leaves
/// tangent faces for OpenCASCADE to merge at a large tolerance (which made later cuts take away more than
/// their tools).
TopoDS_Shape slot(const gp_Pnt& a, const gp_Pnt& b, int axis, double from, double to, double r);

/// A rod of `radius` round p along normal axis n, from `from` to `to` measured from `face` in direction
/// `sign` (+1 or -1), whichever way round that puts its ends.
TopoDS_Shape rodFrom(const gp_Pnt& p, int n, double face, double sign, double from, double to, double radius);

/// A part's solid cuboids, grown by `grow` all round.
std::vector<Coordinates> boxesOf(const Model& m, int part, const std::vector<Coordinates>& at,
                                 double grow = 0);

/// The boxes united; a part's solid cuboids at `at` (gapped), grown by `grow`, united.
TopoDS_Shape solid(const std::vector<Coordinates>& boxes);
TopoDS_Shape solid(const Model& m, int part, const std::vector<Coordinates>& at, double grow = 0);

}  // namespace fabguide::printable
