#include "Printable/PrintInPlace.h"

#include "Core/Text.h"
#include "Function/Solve.h"
#include "Geometry/Interval.h"
#include "Printable/Gaps.h"
#include "Printable/Joints.h"
#include "Printable/Motion.h"
#include "Printable/Solids.h"
#include "Printable/Sweeps.h"

#include <BRepBndLib.hxx>
#include <Bnd_Box.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <TopExp_Explorer.hxx>
#include <gp.hxx>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>

namespace fabguide::printable {

namespace {

/// In configuration k, for two parts that lie within the gap of each other as printed and both turn, each is
/// cut by the other's path relative to it, grown by the gap (pathRelative): a door's edge turning towards its
/// neighbour bevels the neighbour's edge.
void clearNeighbours(const Model& m, int k, const std::vector<Coordinates>& at, double g,
                     std::vector<TopoDS_Shape>& shapes)
{
    const int parts = static_cast<int>(m.parts.size());
    auto turns = [&](int p) {  // its own joint turns in k (carried parts turn with their carrier)
        const int j = jointMoving(m, function::carrierOf(m, p));
        const function::JointPose* pose = j >= 0 ? poseOf(m, j, k) : nullptr;
        return pose && std::abs(pose->angle) > 1e-9 && m.joints[j].type != Joint::Type::Slide;
    };
    for (int a = 0; a < parts; ++a)
        for (int b = 0; b < parts; ++b) {
            if (function::carrierOf(m, a) == function::carrierOf(m, b) || !turns(a) || !turns(b))
                continue;  // one part, or held together by a fixed joint
            const gp_Trsf relative = partMotion(m, b, k, 1).Inverted() * partMotion(m, a, k, 1);
            if (relative.Form() == gp_Identity || relative.Form() == gp_Translation)
                continue;  // sliding past each other, the gap stays a gap
            const std::vector<Coordinates> grown = boxesOf(m, a, at, g);
            Bnd_Box near, other;
            for (const Coordinates& c : grown)
                near.Update(c[0], c[2], c[4], c[1], c[3], c[5]);
            BRepBndLib::Add(shapes[b], other);
            near.Enlarge(g);
            if (near.IsOut(other))
                continue;
            const Work on(m.parts[b].name);
            std::vector<TopoDS_Shape> path = pathRelative(m, k, a, b, grown);
            path.erase(std::remove_if(path.begin(), path.end(),
                                      [&](const TopoDS_Shape& s) { return !touches(s, shapes[b]); }),
                       path.end());
            if (!path.empty())  // only the poses that come within the gap: fewer tools, a quicker cut
                shapes[b] = cut(shapes[b], path);
        }
}

/// Each part's solid cuboids at their gapped coordinates, less its own cavities.
std::vector<TopoDS_Shape> partSolids(const Model& m, const std::vector<Coordinates>& at)
{
    std::vector<TopoDS_Shape> shapes;
    for (size_t p = 0; p < m.parts.size(); ++p) {
        const Work on(m.parts[p].name);
        TopoDS_Shape s = solid(m, static_cast<int>(p), at);
        for (int c : m.parts[p].cuboids)
            if (m.cuboids[c].cavity())
                s = cut(s, box(m.cuboids[c].coordinates));
        shapes.push_back(s);
    }
    return shapes;
}

/// Whether part p moves on its way to configuration k.
bool movesIn(const Model& m, int p, int k)
{
    return function::jointMovingIn(m, p, k) >= 0;
}

/// Cavities (4.5.1): what each inner part sweeps, with its clearance, on the way to its fit's configuration
/// leaves the enclosing part, swept in the enclosing part's frame when that moves too (a rack lifted in a
/// pull-out that slides out makes room in the pull-out, not a window along its path); a fit in the enclosing
/// part's box as modelled leaves the inner part's place (a battery drawn in a phone's solid body).
void cutCavities(const Model& m, const std::vector<Coordinates>& at, double g,
                 std::vector<TopoDS_Shape>& shapes, Printable& out)
{
    for (const function::FitInside& f : m.fitInside) {
        if (f.configuration < 0 && f.cavity >= 0)
            continue;  // its cavity is its room
        for (int p : f.inner) {
            const Work on(m.parts[f.enclosing].name);
            const std::vector<Coordinates> boxes = boxesOf(m, p, at, g);
            std::vector<TopoDS_Shape> swept;
            if (f.configuration < 0)
                std::transform(boxes.begin(), boxes.end(), std::back_inserter(swept),
                               [](const Coordinates& b) { return box(b); });
            else if (movesIn(m, f.enclosing, f.configuration))
                swept = pathRelative(m, f.configuration, p, f.enclosing, boxes);
            else
                swept = sweep(m, p, f.configuration, boxes);
            out.sweeps.push_back(compound(swept));
            shapes[f.enclosing] = cut(shapes[f.enclosing], swept);
        }
    }
}

/// Likewise a part turning on a hinge clears the part its yokes sit on: a thick lid's edge below the axis
/// sweeps a quarter round into the body.
void clearHingeBases(const Model& m, const std::vector<Coordinates>& at, double g,
                     std::vector<TopoDS_Shape>& shapes)
{
    for (size_t j = 0; j < m.joints.size(); ++j) {
        const Joint& joint = m.joints[j];
        const int edge = joint.turns() ? cuboidAtEdge(m, joint) : -1;
        for (size_t k = 0; k < m.configurations.size() && edge >= 0; ++k)
            if (const function::JointPose* pose = poseOf(m, static_cast<int>(j), static_cast<int>(k))) {
                const int base = function::partOf(m, edge);
                const Work on(m.parts[base].name);
                shapes[base] = cut(shapes[base], hingeSweep(m, joint, *pose, boxesOf(m, joint.part, at, g)));
            }
    }
}

/// Whether another part's cavity guides the part: it fits inside one (a phone's battery, slid in), or a
/// cuboid of it runs in one as modelled (a drawer in its bay, a lever's slider in its channel).
bool inCavity(const Model& m, int part)
{
    for (const function::FitInside& f : m.fitInside)
        if (f.cavity >= 0 && std::find(f.inner.begin(), f.inner.end(), part) != f.inner.end())
            return true;
    for (int c : m.parts[part].cuboids)
        for (const Cuboid& hollow : m.cuboids)
            if (hollow.cavity() && function::partOf(m, hollow.within) != part && !m.cuboids[c].cavity()) {
                bool overlap = true;
                for (int a = 0; a < 3; ++a)
                    overlap = overlap && overlapOf(along(hollow.coordinates, a),
                                                   along(m.cuboids[c].coordinates, a)) > 1e-9;
                if (overlap)
                    return true;
            }
    return false;
}

/// Joint geometry (4.5.2): hinges and sliding hinges, double pivots, and rails for slides no cavity guides
/// (a fixed joint's part is fused to its base as one body).
void addJoints(const Model& m, const std::vector<Coordinates>& at, double g, const Places& places,
               std::vector<TopoDS_Shape>& shapes, Printable& out)
{
    for (size_t j = 0; j < m.joints.size(); ++j) {
        const Joint& joint = m.joints[j];
        const Work on(joint.name);
        const int place = j < places.size() ? places[j] : 0;
        if (joint.turns())
            addHinge(m, static_cast<int>(j), at, g, shapes, out, place);
        else if (joint.type == Joint::Type::DoublePivot)
            addDoublePivot(m, static_cast<int>(j), g, shapes, out);
        else if (joint.slides() && !inCavity(m, joint.part))
            addRails(m, static_cast<int>(j), at, g, shapes, place);
    }
}

/// A body's name: its parts' names, joined by " + " (a carcass and its legs: "carcass + legs").
std::string bodyName(const Model& m, const std::vector<int>& parts)
{
    std::string name;
    for (int p : parts)
        name += (name.empty() ? "" : " + ") + m.parts[p].name;
    return name;
}

/// The parts' shapes as bodies (rigidBodies: parts that stand still together fused), before the links, faces
/// merged; a body OpenCASCADE lost is an error (one cut in pieces, check() reports).
void addBodies(const Model& m, const std::vector<TopoDS_Shape>& shapes, Printable& out)
{
    const std::vector<std::vector<int>> bodies = rigidBodies(m);
    for (size_t b = 0; b < bodies.size(); ++b) {
        const std::string name = bodyName(m, bodies[b]);
        const Work on(name);
        std::vector<TopoDS_Shape> parts;
        for (int p : bodies[b])
            parts.push_back(shapes[p]);
        ShapeUpgrade_UnifySameDomain unify(fuse(parts), true, true, false);
        unify.Build();
        int pieces = 0;
        for (TopExp_Explorer e(unify.Shape(), TopAbs_SOLID); e.More(); e.Next())
            ++pieces;
        if (pieces == 0 || volumeOf(unify.Shape()) < 1e-6)  // OpenCASCADE lost it without an error
            throw std::runtime_error(
                "geometry: nothing is left of part '" + name +
                "' after its cavities and joints were cut; try another --gap or --scale");
        out.bodies.insert(out.bodies.begin() + static_cast<long>(b),
                          {name, bodies[b].front(), -1, unify.Shape()});
    }
}

/// The model's cuboids' extent along x, y and z, as modelled.
Size extentOf(const Model& model)
{
    Size extent{0, 0, 0};
    for (int a = 0; a < 3; ++a) {
        double low = 1e300, high = -1e300;
        for (const Cuboid& c : model.cuboids) {
            low = std::min(low, c.at(static_cast<Side>(2 * a)));
            high = std::max(high, c.at(static_cast<Side>(2 * a + 1)));
        }
        extent[a] = high - low;
    }
    return extent;
}

/// The largest print FabGuide makes, mm along any side: beyond the largest printers (the thesis' bunk bed
/// is 2.1 m at 1:1), where meshing curved joints to a printer's precision takes ever longer (a
/// model at 1e6 mm, or --scale 100, did not finish).
constexpr double kLargestPrint = 5000;

/// std::invalid_argument when a scaled model is longer than kLargestPrint along an axis.
void checkPrintSize(const Model& scaled)
{
    const Size extent = extentOf(scaled);
    for (int a = 0; a < 3; ++a)
        if (extent[a] > kLargestPrint)
            throw std::invalid_argument("the print would be " + std::to_string(std::lround(extent[a])) +
                                        " mm long along " + std::string(1, "xyz"[a]) +
                                        "; FabGuide prints up to " +
                                        std::to_string(std::lround(kLargestPrint)) +
                                        " mm: print it at a smaller scale, or fitted to your printer");
}

/// The model with the coordinates along each axis that lie within a micrometre of the run's first moved onto
/// one plane: a locked face's where the run has one (the user's value stays exact; a carcass's locked front
/// moved 5e-4 mm onto a drawer front's, seed 7792), else the first's. Faces the solve leaves a hair apart,
/// but not in one plane (a sliding door's end 4e-5 mm past its opening's), become slivers in the Boolean
/// operations that no mesh closes. Their order along the axis is kept, so parts apart stay apart.
Model inPlanes(Model model)
{
    std::set<std::pair<int, int>> locked;  // (cuboid, side)
    for (const function::Lock& lock : model.locks)
        locked.insert({lock.face.cuboid, static_cast<int>(lock.face.side)});
    for (int axis = 0; axis < 3; ++axis) {
        std::vector<std::pair<double*, bool>> at;
        for (size_t c = 0; c < model.cuboids.size(); ++c)
            for (int side : {2 * axis, 2 * axis + 1})
                at.push_back(
                    {&model.cuboids[c].coordinates[side], locked.count({static_cast<int>(c), side}) > 0});
        std::sort(at.begin(), at.end(), [](const auto& a, const auto& b) { return *a.first < *b.first; });
        for (size_t first = 0, end = 0; first < at.size(); first = end) {
            end = first;
            while (end < at.size() && *at[end].first - *at[first].first <= 1e-3)
                ++end;
            const auto run = at.begin() + static_cast<long>(first),
                       past = at.begin() + static_cast<long>(end);
            const auto lockedFace = std::find_if(run, past, [](const auto& x) { return x.second; });
            const double plane = *(lockedFace != past ? lockedFace : run)->first;
            for (auto x = run; x != past; ++x)
                *x->first = plane;
        }
    }
    return model;
}

/// What the print's solve (`solved`, its cuboids marked with what joints need: solvedToPrint) kept thicker
/// than a plain solve of `model` would, one sentence per size ("lid: kept 2.4 mm thick, not thinned ...").
std::vector<std::string> keptForJoints(const Model& model, const Model& solved)
{
    const function::SolveResult plain = function::solve(model);
    std::vector<std::string> notes;
    for (size_t c = 0; c < solved.cuboids.size() && plain.solved; ++c)
        for (int a = 0; a < 3; ++a) {
            const auto size = [&](const Model& m) {
                return m.cuboids[c].coordinates[2 * a + 1] - m.cuboids[c].coordinates[2 * a];
            };
            const double least = solved.cuboids[c].least;
            if (size(plain.model) < least - 1e-9 && size(solved) > size(plain.model) + 1e-6)
                notes.push_back(solved.cuboids[c].name + ": kept " + function::millimetres(size(solved)) +
                                " mm thick, not thinned to " + function::millimetres(size(plain.model)) +
                                " mm, for a joint's round parts on it (" + function::millimetres(least) +
                                " mm at this scale and gap)");
        }
    return notes;
}

/// How much larger `size` could be in `bed`, 0.01 mm short of each side (meshes are written to a micrometre).
double room(const Size& size, const Size& bed)
{
    double r = 1e300;
    for (int a = 0; a < 3; ++a)
        r = std::min(r, (bed[a] - 0.01) / std::max(size[a], 1e-9));
    return r;
}

/// The bed as the model sees it turned a quarter about z.
Size turnedBed(const Size& volume)
{
    return {volume[1], volume[0], volume[2]};
}

/// Whether the model prints larger turned a quarter, and the largest scale (at most 1) its cuboids allow.
std::pair<bool, double> firstFit(const Model& solved, const Size& volume)
{
    const Size extent = extentOf(solved);
    const bool turned =
        std::min(1.0, room(extent, turnedBed(volume))) > std::min(1.0, room(extent, volume)) * (1 + 1e-9);
    return {turned, std::min(1.0, room(extent, turned ? turnedBed(volume) : volume))};
}

}  // namespace

Model solvedToPrint(const Model& model, double scale, double gap)
{
    const function::SolveResult solved = function::solve(needingRoundParts(model, gap, scale));
    if (!solved.solved) {
        const std::string names = joined(solved.conflict, quoted);
        std::string why;  // a double pivot's reason, where the names alone do not say
        for (const std::string& note : solved.notes)
            for (const std::string& name : solved.conflict)
                if (note.rfind(name + ": ", 0) == 0)
                    why += "; " + note;
        throw std::runtime_error("the model does not solve: " + names + " cannot hold together" + why);
    }
    return inPlanes(solved.model);
}

int placesOf(const Model& m, int j)
{
    const Joint& joint = m.joints[j];
    if (joint.turns())
        return 8;
    if (joint.type == Joint::Type::DoublePivot)
        return 1;
    return joint.slides() && !inCavity(m, joint.part) ? std::max(1, static_cast<int>(railPlaces(m, j).size()))
                                                      : 0;
}

Printable makePrintable(const Model& m, const Printer& printer, const Places& places)
{
    Printable out;
    const Work all("", printer.partSeconds);
    const double g = printer.gap;
    const std::vector<Coordinates> at = gapped(m, g);
    std::vector<TopoDS_Shape> shapes = partSolids(m, at);
    cutCavities(m, at, g, shapes, out);
    clearHingeBases(m, at, g, shapes);
    for (size_t k = 0; k < m.configurations.size(); ++k)
        clearNeighbours(m, static_cast<int>(k), at, g, shapes);
    addJoints(m, at, g, places, shapes, out);
    addBodies(m, shapes, out);
    return out;
}

std::vector<std::string> bodyNames(const Model& model)
{
    std::vector<std::string> names;
    for (const std::vector<int>& body : rigidBodies(model))
        names.push_back(bodyName(model, body));
    for (const Joint& j : model.joints)
        if (j.type == Joint::Type::DoublePivot)
            names.push_back(linkName(j));
    return names;
}

Size sizeOf(const Printable& printable)
{
    Bnd_Box bounds;
    for (const Body& b : printable.bodies)
        BRepBndLib::AddOptimal(b.shape, bounds, false, false);
    if (bounds.IsVoid())
        return {0, 0, 0};
    double x0, y0, z0, x1, y1, z1;
    bounds.Get(x0, y0, z0, x1, y1, z1);
    return {x1 - x0, y1 - y0, z1 - z0};
}

Fitted fitted(const Model& solved, const Size& volume, const Printer& printer)
{
    // First as large as the cuboids allow, then smaller by what joints and links add beyond them.
    Fitted f;
    f.solved = solved;
    std::tie(f.turned, f.scale) = firstFit(solved, volume);
    const Size bed = f.turned ? turnedBed(volume) : volume;
    // Joints do not scale with the part (least pins, the gap): rescale by the room left until the print
    // fits with less than 0.1 % to spare, keeping the largest that fits.
    std::optional<Fitted> fits;
    for (int attempt = 0; attempt < 5; ++attempt) {
        f.model = function::scaled(solved, f.scale);
        try {
            f.printable = makePrintable(f.model, printer);
        } catch (const std::invalid_argument& e) {
            std::ostringstream what;
            what << e.what() << "; printed at scale " << f.scale << ", which fits " << volume[0] << " x "
                 << volume[1] << " x " << volume[2] << " mm";
            throw std::invalid_argument(what.str());
        }
        const double r = room(sizeOf(f.printable), bed);
        if (r < 1 - 1e-9 && fits)
            return *fits;  // grown past the bed: the last that fitted
        if (r >= 1 - 1e-9) {
            fits = f;
            if (r < 1 + 1e-3 || f.scale >= 1)
                return f;
        }
        f.scale = std::min(1.0, f.scale * r * (1 - 1e-4));
    }
    if (fits)
        return *fits;
    std::ostringstream what;
    what << "the print does not fit the build volume " << volume[0] << " x " << volume[1] << " x "
         << volume[2] << " mm at any scale tried (down to " << f.scale << ")";
    throw std::runtime_error(what.str());
}

Printable onTheBed(Printable printable, bool turned)
{
    if (turned) {
        gp_Trsf quarter;
        quarter.SetRotation(gp::OZ(), kPi / 2);
        for (Body& b : printable.bodies)
            b.shape = moved(b.shape, quarter);
    }
    return printable;
}

Fitted printed(const Model& model, const Printer& printer, double scale, const std::optional<Size>& fit)
{
    Fitted f;
    if (fit) {  // what joints need taken at the scale the cuboids fit at (joints may make it a little less)
        const Model whole = solvedToPrint(model, 1, printer.gap);
        scale = firstFit(whole, *fit).second;
        f = fitted(scale < 1 ? solvedToPrint(model, scale, printer.gap) : whole, *fit, printer);
    } else {
        f.scale = scale;
        f.solved = solvedToPrint(model, scale, printer.gap);
        f.model = function::scaled(f.solved, scale);
        checkPrintSize(f.model);
        f.printable = makePrintable(f.model, printer);
    }
    const std::vector<std::string> kept = keptForJoints(model, f.solved);
    f.printable.notes.insert(f.printable.notes.begin(), kept.begin(), kept.end());
    return f;
}

}  // namespace fabguide::printable
