#include "Printable/Checks.h"

#include "Printable/Motion.h"

#include <BRepBndLib.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <Bnd_Box.hxx>
#include <TopExp_Explorer.hxx>
#include <TopLoc_Location.hxx>

#include <string>

#include <cmath>
#include <cstdio>
#include <utility>

namespace fabguide::printable {

namespace {

gp_Trsf motion(const function::Model& m, const Body& b, int k, double t)
{
    return b.part >= 0 ? partMotion(m, b.part, k, t) : linkMotion(m, b.joint, k, t);
}

struct Placed {
    TopoDS_Shape shape;
    Bnd_Box bounds;
};

/// The body moved by t: located, not copied (a carcass that stands still is the same shape at every pose).
Placed place(const Body& b, const gp_Trsf& t)
{
    Placed p{t.Form() == gp_Identity ? b.shape : b.shape.Moved(TopLoc_Location(t)), {}};
    BRepBndLib::Add(p.shape, p.bounds);
    return p;
}

/// The distance between two solids, 0 when they intersect or one holds the other, and a point where it is
/// (on the first).
std::pair<double, gp_Pnt> distance(const Placed& a, const Placed& b)
{
    BRepExtrema_DistShapeShape d;
    d.SetFlag(Extrema_ExtFlag_MIN);  // the least distance only
    d.SetMultiThread(true);
    d.LoadS1(a.shape);
    d.LoadS2(b.shape);
    d.Perform();
    if (!d.IsDone() || d.NbSolution() == 0)
        return {0, gp_Pnt()};
    return {d.InnerSolution() ? 0 : d.Value(), d.PointOnShape1(1)};
}

/// Whether two bodies move alike (their distance is then as printed).
bool same(const gp_Trsf& a, const gp_Trsf& b)
{
    for (int r = 1; r <= 3; ++r)
        for (int c = 1; c <= 4; ++c)
            if (std::abs(a.Value(r, c) - b.Value(r, c)) > 1e-12)
                return false;
    return true;
}

}  // namespace

Check check(const function::Model& m, const Printable& printable, double enough, int samples)
{
    Check out;
    for (const Body& b : printable.bodies) {
        if (!BRepCheck_Analyzer(b.shape).IsValid())
            out.invalid.push_back(b.name);
        int pieces = 0;
        for (TopExp_Explorer e(b.shape, TopAbs_SOLID); e.More(); e.Next())
            ++pieces;
        if (pieces > 1)  // a cut through it: a joint turning the wrong way round, or a part in the way
            out.loose.push_back(b.name + ": " + std::to_string(pieces) + " pieces");
    }
    auto measure = [&](int k, double t, const std::string& when) {
        std::vector<Placed> placed;
        std::vector<gp_Trsf> motions;
        for (const Body& b : printable.bodies) {
            motions.push_back(motion(m, b, k, t));
            placed.push_back(place(b, motions.back()));
        }
        for (size_t a = 0; a < placed.size(); ++a)
            for (size_t b = a + 1; b < placed.size(); ++b) {
                if (k >= 0 && same(motions[a], motions[b]))
                    continue;  // no nearer than as printed
                Bnd_Box grown = placed[a].bounds;
                grown.Enlarge(enough);
                if (grown.IsOut(placed[b].bounds))
                    continue;
                const auto [d, at] = distance(placed[a], placed[b]);
                if (d < out.clearance) {
                    out.clearance = d;
                    char point[96];
                    std::snprintf(point, sizeof point, " near (%.1f, %.1f, %.1f) mm", at.X(), at.Y(), at.Z());
                    out.where =
                        printable.bodies[a].name + " and " + printable.bodies[b].name + " " + when + point;
                }
            }
    };
    measure(-1, 0, "as printed");
    for (size_t k = 0; k < m.configurations.size(); ++k)
        for (int s = 1; s <= samples; ++s)
            measure(static_cast<int>(k), static_cast<double>(s) / samples,
                    "in '" + m.configurations[k].name + "' at " + std::to_string(100 * s / samples) + "%");
    return out;
}

}  // namespace fabguide::printable
