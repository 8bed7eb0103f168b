#include "Printable/Checks.h"

#include "Core/Parallel.h"
#include "Core/Text.h"
#include "Printable/Joints.h"
#include "Printable/Motion.h"

#include <cassert>  // FCL 0.7's headers use assert without including it: with GCC 15 (Debian 14) nothing else does

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/narrowphase/distance.h>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Poly_Triangulation.hxx>
#include <TopExp_Explorer.hxx>
#include <TopLoc_Location.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

namespace fabguide::printable {

namespace {

/// How far a body's mesh may lie from its surface (mm): distances found between meshes are within three times
/// this of the bodies' (two meshes, and the search's own tolerance).
constexpr double kDeflection = 0.002;

using Tree = fcl::BVHModel<fcl::OBBRSSd>;

/// A body to measure: its shape, its surface as triangles in FCL's bounding-volume tree (none when a face
/// would not mesh: then it is measured on its shape), and its bounds.
struct Measured {
    TopoDS_Shape shape;
    std::shared_ptr<Tree> surface;
    Bnd_Box bounds;
};

/// The body's surface meshed kDeflection close, on a copy (the body keeps the coarser mesh it is written
/// with).
std::shared_ptr<Tree> surfaceOf(const TopoDS_Shape& shape)
{
    const TopoDS_Shape copy = BRepBuilderAPI_Copy(shape).Shape();
    BRepMesh_IncrementalMesh(copy, kDeflection, false, 0.5, true);
    std::vector<fcl::Vector3d> points;
    std::vector<fcl::Triangle> triangles;
    for (TopExp_Explorer e(copy, TopAbs_FACE); e.More(); e.Next()) {
        TopLoc_Location at;
        const Handle(Poly_Triangulation) mesh = BRep_Tool::Triangulation(TopoDS::Face(e.Current()), at);
        if (mesh.IsNull())
            return nullptr;
        const size_t first = points.size();
        for (int i = 1; i <= mesh->NbNodes(); ++i) {
            const gp_Pnt p = mesh->Node(i).Transformed(at.Transformation());
            points.emplace_back(p.X(), p.Y(), p.Z());
        }
        for (int i = 1; i <= mesh->NbTriangles(); ++i) {
            int a, b, c;
            mesh->Triangle(i).Get(a, b, c);
            triangles.emplace_back(first + a - 1, first + b - 1, first + c - 1);
        }
    }
    auto tree = std::make_shared<Tree>();
    tree->beginModel();
    tree->addSubModel(points, triangles);
    tree->endModel();
    return tree;
}

gp_Trsf motion(const function::Model& m, const Body& b, int k, double t)
{
    return b.part >= 0 ? partMotion(m, b.part, k, t) : linkMotion(m, b.joint, k, t);
}

/// Bounds moved by t: the box round its moved corners.
Bnd_Box moved(const Bnd_Box& bounds, const gp_Trsf& t)
{
    return t.Form() == gp_Identity ? bounds : bounds.Transformed(t);
}

/// The body moved by t: located, not copied (a carcass that stands still is the same shape at every pose).
TopoDS_Shape placed(const TopoDS_Shape& shape, const gp_Trsf& t)
{
    return t.Form() == gp_Identity ? shape : shape.Moved(TopLoc_Location(t));
}

/// The distance between two solids, 0 when they intersect or one holds the other, and a point where it is
/// (on the first), on their shapes.
std::pair<double, gp_Pnt> exactDistance(const TopoDS_Shape& a, const TopoDS_Shape& b)
{
    BRepExtrema_DistShapeShape d;
    d.SetFlag(Extrema_ExtFlag_MIN);  // the least distance only
    d.LoadS1(a);
    d.LoadS2(b);
    d.Perform();
    if (!d.IsDone() || d.NbSolution() == 0)
        return {0, gp_Pnt()};
    return {d.InnerSolution() ? 0 : d.Value(), d.PointOnShape1(1)};
}

fcl::Transform3d toFcl(const gp_Trsf& t)
{
    fcl::Transform3d x = fcl::Transform3d::Identity();
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c)
            x.matrix()(r, c) = t.Value(r + 1, c + 1);
    return x;
}

/// A body at a pose: how it is moved there, and its bounds there.
struct Posed {
    gp_Trsf motion;
    Bnd_Box bounds;
};

/// Whether the one body lies wholly within the other (their surfaces apart): a point of it is inside.
bool holds(const Measured& outer, const Posed& to, const Measured& inner, const Posed& ti)
{
    double x0, y0, z0, x1, y1, z1;
    ti.bounds.Get(x0, y0, z0, x1, y1, z1);
    if (to.bounds.IsOut(gp_Pnt(x0, y0, z0)) || to.bounds.IsOut(gp_Pnt(x1, y1, z1)))
        return false;
    TopExp_Explorer vertex(inner.shape, TopAbs_VERTEX);
    if (!vertex.More())
        return false;
    const gp_Pnt p = BRep_Tool::Pnt(TopoDS::Vertex(vertex.Current())).Transformed(ti.motion);
    return BRepClass3d_SolidClassifier(placed(outer.shape, to.motion), p, 1e-7).State() == TopAbs_IN;
}

/// The distance between two posed bodies if less than `bound` (else `bound` or more), 0 when they meet or one
/// holds the other: on their meshes (within 3 kDeflection of theirs), on their shapes where a mesh is
/// missing.
double distance(const Measured& a, const Posed& pa, const Measured& b, const Posed& pb, double bound)
{
    if (holds(a, pa, b, pb) || holds(b, pb, a, pa))
        return 0;
    const gp_Trsf &ta = pa.motion, &tb = pb.motion;
    if (!a.surface || !b.surface)
        return exactDistance(placed(a.shape, ta), placed(b.shape, tb)).first;
    fcl::DistanceRequestd request;
    request.abs_err =
        kDeflection;  // boxes of triangles no more than this nearer than the nearest yet are passed
    request.rel_err = 0.02;
    fcl::DistanceResultd result(bound);  // and those no nearer than the bound: pairs farther are soon done
    fcl::distance(a.surface.get(), toFcl(ta), b.surface.get(), toFcl(tb), request, result);
    return std::max(0.0, result.min_distance);
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

/// A pose of the check: configuration k (-1: as printed) t of the way.
struct Pose {
    int k;
    double t;
    std::string when;
};

/// The nearest two bodies at a pose.
struct Nearest {
    double d = 1e300;
    size_t a = 0, b = 0;
};

/// The distance from p to the segment from a to b.
double toSegment(const gp_Pnt& p, const gp_Pnt& a, const gp_Pnt& b)
{
    const gp_Vec ab(a, b), ap(a, p);
    const double along =
        ab.SquareMagnitude() > 0 ? std::clamp(ap.Dot(ab) / ab.SquareMagnitude(), 0.0, 1.0) : 0;
    return p.Distance(a.Translated(ab * along));
}

/// The distance from p to box x.
double toBox(const gp_Pnt& p, const Coordinates& x)
{
    double d2 = 0;
    for (int a = 0; a < 3; ++a) {
        const double out = std::max({0.0, x[2 * a] - coord(p, a), coord(p, a) - x[2 * a + 1]});
        d2 += out * out;
    }
    return std::sqrt(d2);
}

/// How far the point lies beyond the reach of joint j's geometry, p given in the model's frame of the part
/// the geometry stands on (`frameOf`), and the parts that geometry belongs to.
double beyondReach(const function::Model& m, int j, const std::function<gp_Pnt(int)>& frameOf,
                   std::vector<int>& parts)
{
    const Joint& joint = m.joints[j];
    const double thin =
        m.cuboids[joint.type == Joint::Type::DoublePivot ? joint.pivotFace.cuboid : joint.edgeA.cuboid]
            .thinnest();
    parts = {joint.part};
    if (joint.turns()) {  // pin, knuckle and yokes round the axis along the edge, on the part and its base
        const gp_Ax1 axis = hingeAxis(m, joint);
        const int base = cuboidAtEdge(m, joint);
        if (base >= 0)
            parts.push_back(function::partOf(m, base));
        const Coordinates& edge = m.cuboids[joint.edgeA.cuboid].coordinates;
        const int along = hingeAlong(joint);
        gp_Pnt a = axis.Location(), b = axis.Location();
        setCoord(a, along, edge[2 * along]);
        setCoord(b, along, edge[2 * along + 1]);
        return toSegment(frameOf(joint.part), a, b) - std::max(thin, 4.0);
    }
    if (joint.type == Joint::Type::DoublePivot) {
        parts.push_back(joint.base);
        const auto [pivot, base] = pivotPoints(m, joint);
        return std::min(toSegment(frameOf(joint.part), pivot, base),
                        toSegment(frameOf(joint.base), pivot, base)) -
               std::max(thin, 4.0);
    }
    double beyond = 1e300;  // rails: the tongue on a base, the groove in the part
    for (const RailPlace& r : railPlaces(m, j)) {
        const int base = function::partOf(m, r.base);
        parts.push_back(base);
        Coordinates strip{};
        strip[2 * r.across] = r.low, strip[2 * r.across + 1] = r.high;
        strip[2 * r.normal] = r.plane - 1, strip[2 * r.normal + 1] = r.plane + 1;
        strip[2 * joint.axis] = r.from, strip[2 * joint.axis + 1] = r.to;
        beyond =
            std::min({beyond, toBox(frameOf(base), strip) - thin, toBox(frameOf(joint.part), strip) - thin});
    }
    return beyond;
}

}  // namespace

std::vector<int> jointsInTheWay(const function::Model& m, const Printable& printable, const Check& c)
{
    if (c.first < 0)
        return {};
    const std::vector<std::vector<int>> rigid = rigidBodies(m);
    auto holdsPart = [&](int body, int part) {
        const Body& b = printable.bodies[body];
        return b.part >= 0 && body < static_cast<int>(rigid.size()) &&
               std::find(rigid[body].begin(), rigid[body].end(), part) != rigid[body].end();
    };
    const gp_Pnt at(c.point[0], c.point[1], c.point[2]);
    const auto frameOf = [&](int part) {  // the point in the model's frame of the part
        return c.configuration < 0 ? at
                                   : at.Transformed(partMotion(m, part, c.configuration, c.t).Inverted());
    };
    std::vector<std::pair<double, int>> near;  // (how far beyond its reach, joint)
    for (size_t j = 0; j < m.joints.size(); ++j) {
        if (placesOf(m, static_cast<int>(j)) == 0)
            continue;  // no geometry of its own (a slide a cavity guides, a fixed joint)
        std::vector<int> parts;
        const double beyond = beyondReach(m, static_cast<int>(j), frameOf, parts);
        bool involved = false;
        for (int body : {c.first, c.second}) {
            involved = involved || printable.bodies[body].joint == static_cast<int>(j);
            for (int p : parts)
                involved = involved || (p >= 0 && holdsPart(body, p));
        }
        if (involved && beyond <= 0)
            near.push_back({beyond, static_cast<int>(j)});
    }
    std::sort(near.begin(), near.end());
    std::vector<int> joints;
    for (const auto& [beyond, j] : near)
        joints.push_back(j);
    return joints;
}

Checked placedByCheck(const function::Model& m, Printable made, const Printer& printer, int samples)
{
    const double g = printer.gap;
    Check c = check(m, made, g, samples);
    const auto fails = [&](const Check& k) { return k.clearance < g - 0.01; };
    // The nearest joint in the way not yet moved, or -1.
    std::vector<bool> moved(m.joints.size(), false);
    const auto next = [&] {
        for (int j : jointsInTheWay(m, made, c))
            if (!moved[j])
                return j;
        return -1;
    };
    Places places(m.joints.size(), 0);
    std::vector<std::string> tried;  // the joints moved in vain
    bool placed = false;             // one of them had other places
    for (int j = fails(c) ? next() : -1; j >= 0; j = fails(c) ? next() : -1) {
        moved[j] = true;
        const int kept = places[j], count = placesOf(m, j);
        placed = placed || count > 1;
        int best = kept;
        for (int place = 0; place < count && fails(c); ++place) {
            if (place == kept)
                continue;
            places[j] = place;
            Printable other;
            try {
                other = makePrintable(m, printer, places);
            } catch (const NoRoom&) {
                continue;  // another place may have room
            }
            const Check checked = check(m, other, g, samples);
            if (checked.clearance > c.clearance) {
                made = std::move(other);
                c = checked;
                best = place;
            }
        }
        places[j] = best;
        if (fails(c))
            tried.push_back(quoted(m.joints[j].name));
    }
    if (fails(c) && !tried.empty()) {
        const std::string names = joined(tried);
        const bool one = tried.size() == 1;
        c.where +=
            (one ? "; joint " : "; joints ") + names + (one ? " is" : " are") + " in the way" +
            (placed ? std::string(", and no other place of ") + (one ? "it" : "them") + " clears" : "");
    }
    return {std::move(made), c};
}

Check check(const function::Model& m, const Printable& printable, double enough, int samples)
{
    Check out;
    std::vector<Measured> bodies;
    for (const Body& b : printable.bodies) {
        if (!BRepCheck_Analyzer(b.shape).IsValid())
            out.invalid.push_back(b.name);
        int pieces = 0;
        for (TopExp_Explorer e(b.shape, TopAbs_SOLID); e.More(); e.Next())
            ++pieces;
        if (pieces > 1)  // a cut through it: a joint turning the wrong way round, or a part in the way
            out.loose.push_back(b.name + ": " + std::to_string(pieces) + " pieces");
        bodies.push_back({b.shape, surfaceOf(b.shape), {}});
        BRepBndLib::Add(b.shape, bodies.back().bounds);
    }
    std::vector<Pose> poses{{-1, 0, "as printed"}};
    for (size_t k = 0; k < m.configurations.size(); ++k)
        for (int s = 1; s <= samples; ++s)
            poses.push_back(
                {static_cast<int>(k), static_cast<double>(s) / samples,
                 "in '" + m.configurations[k].name + "' at " + std::to_string(100 * s / samples) + "%"});
    // Every pose on the meshes, on every core; then the nearest two exactly where they are nearest.
    std::vector<Nearest> nearest(poses.size());
    const auto measure = [&](int p) {
        std::vector<Posed> at;
        for (size_t b = 0; b < bodies.size(); ++b) {
            const gp_Trsf t = motion(m, printable.bodies[b], poses[p].k, poses[p].t);
            at.push_back({t, moved(bodies[b].bounds, t)});
        }
        for (size_t a = 0; a < bodies.size(); ++a)
            for (size_t b = a + 1; b < bodies.size(); ++b) {
                if (poses[p].k >= 0 && same(at[a].motion, at[b].motion))
                    continue;  // no nearer than as printed
                Bnd_Box grown = at[a].bounds;
                grown.Enlarge(enough);
                if (grown.IsOut(at[b].bounds))
                    continue;
                if (const double d = distance(bodies[a], at[a], bodies[b], at[b], nearest[p].d);
                    d < nearest[p].d)
                    nearest[p] = {d, a, b};
            }
    };
    runAll(static_cast<int>(poses.size()), cores(), measure, [](int) {});
    size_t worst = 0;
    for (size_t p = 1; p < poses.size(); ++p)
        if (nearest[p].d < nearest[worst].d)
            worst = p;
    if (nearest[worst].d >= 1e300)
        return out;
    const auto [a, b] = std::pair{nearest[worst].a, nearest[worst].b};
    const Pose& pose = poses[worst];
    const auto [d, point] =
        exactDistance(placed(bodies[a].shape, motion(m, printable.bodies[a], pose.k, pose.t)),
                      placed(bodies[b].shape, motion(m, printable.bodies[b], pose.k, pose.t)));
    out.clearance = nearest[worst].d <= 0 ? 0 : d;
    out.first = static_cast<int>(a), out.second = static_cast<int>(b);
    out.configuration = pose.k, out.t = pose.t;
    out.point = {point.X(), point.Y(), point.Z()};
    char near[96];
    std::snprintf(near, sizeof near, " near (%.1f, %.1f, %.1f) mm", point.X(), point.Y(), point.Z());
    out.where = printable.bodies[a].name + " and " + printable.bodies[b].name + " " + pose.when + near;
    return out;
}

}  // namespace fabguide::printable
