#include "Printable/Solids.h"

#include <BOPAlgo_Alerts.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRep_Builder.hxx>
#include <GProp_GProps.hxx>
#include <Message_ProgressIndicator.hxx>
#include <Message_ProgressScope.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Ax2.hxx>
#include <gp_Circ.hxx>

#include <algorithm>
#include <cctype>
#include <sstream>
#include <stdexcept>
#include <string>

namespace fabguide::printable {

namespace {

thread_local const Work* current = nullptr;  // the innermost work of this thread

}  // namespace

/// Stops an operation past the current work's deadline (OpenCASCADE asks its progress indicator whether the
/// user broke off).
struct Budget : Message_ProgressIndicator {
    const Work* work = current;
    Standard_Boolean UserBreak() override
    {
        return work && std::chrono::steady_clock::now() > work->deadline_;
    }
    void Show(const Message_ProgressScope&, const Standard_Boolean) override {}
    /// What the errors say: the part worked on, and the seconds it was allowed.
    std::string part() const { return work && !work->part_.empty() ? " of '" + work->part_ + "'" : ""; }
    std::string allowed() const
    {
        std::ostringstream s;
        s << (work ? work->seconds_ : 0);
        return s.str();
    }
};

Work::Work(std::string part, double seconds)
    : part_(std::move(part)),
      seconds_(seconds > 0 || !current ? seconds : current->seconds_),
      deadline_(seconds_ > 0 ? std::chrono::steady_clock::now() +
                                   std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                       std::chrono::duration<double>(seconds_))
                             : std::chrono::steady_clock::time_point::max()),
      enclosing_(current)
{
    current = this;
}

Work::~Work()
{
    current = enclosing_;
}

namespace {

/// A Boolean operation of the first shape with the others, or an error naming it and the part worked on:
/// OpenCASCADE reports failures by flags, not exceptions. Many tools in one operation are much faster than
/// one at a time.
template <typename Operation>
TopoDS_Shape boolean(const std::vector<TopoDS_Shape>& shapes, const char* what)
{
    if (shapes.size() < 2)
        return shapes.empty() ? TopoDS_Shape() : shapes.front();
    TopTools_ListOfShape first, rest;
    first.Append(shapes.front());
    for (size_t i = 1; i < shapes.size(); ++i)
        rest.Append(shapes[i]);
    Operation operation;
    operation.SetArguments(first);
    operation.SetTools(rest);
    operation.SetRunParallel(true);
    Handle(Budget) budget = new Budget();
    operation.Build(budget->Start());
    if (operation.HasError(STANDARD_TYPE(BOPAlgo_AlertUserBreak)))
        throw std::runtime_error(std::string("geometry: the ") + what + budget->part() +
                                 " took longer than its " + budget->allowed() + " s (OpenCASCADE, " +
                                 std::to_string(shapes.size() - 1) +
                                 (shapes.size() == 2 ? " tool" : " tools") +
                                 "); fewer cuboids or configurations make fewer faces, or allow more with "
                                 "--part-seconds");
    if (operation.HasErrors()) {
        std::ostringstream report;
        operation.DumpErrors(report);
        std::string errors = report.str();
        while (!errors.empty() && std::isspace(static_cast<unsigned char>(errors.back())))
            errors.pop_back();
        throw std::runtime_error(std::string("geometry: the ") + what + budget->part() +
                                 " failed: " + errors + "; try another --gap or --scale");
    }
    return operation.Shape();
}

}  // namespace

TopoDS_Shape box(const Coordinates& c)
{
    return BRepPrimAPI_MakeBox(gp_Pnt(c[0], c[2], c[4]), gp_Pnt(c[1], c[3], c[5])).Shape();
}

TopoDS_Shape fuse(const TopoDS_Shape& a, const TopoDS_Shape& b)
{
    return a.IsNull() ? b : boolean<BRepAlgoAPI_Fuse>({a, b}, "union");
}

TopoDS_Shape fuse(const std::vector<TopoDS_Shape>& shapes)
{
    return boolean<BRepAlgoAPI_Fuse>(shapes, "union");
}

bool touches(const TopoDS_Shape& a, const TopoDS_Shape& b)
{
    BRepExtrema_DistShapeShape d(a, b, Extrema_ExtFlag_MIN);
    return d.IsDone() && d.NbSolution() > 0 && (d.InnerSolution() || d.Value() < 1e-9);
}

double volumeOf(const TopoDS_Shape& s)
{
    GProp_GProps volume;
    BRepGProp::VolumeProperties(s, volume);
    return volume.Mass();
}

TopoDS_Shape cut(const TopoDS_Shape& a, const std::vector<TopoDS_Shape>& tools)
{
    std::vector<TopoDS_Shape> shapes{a};
    double held = 0;
    for (const TopoDS_Shape& tool : tools)
        if (!tool.IsNull()) {
            shapes.push_back(tool);
            held += volumeOf(tool);
        }
    const TopoDS_Shape result = boolean<BRepAlgoAPI_Cut>(shapes, "cut");
    const double before = volumeOf(a), lost = before - held - volumeOf(result);
    if (lost > 1e-6 * before + 1e-3)
        throw std::runtime_error("geometry: a cut" + Budget().part() + " lost " + std::to_string(lost) +
                                 " mm3 more than its tools hold (OpenCASCADE); try another --gap or --scale");
    return result;
}

TopoDS_Shape cut(const TopoDS_Shape& a, const TopoDS_Shape& b)
{
    return cut(a, std::vector<TopoDS_Shape>{b});
}

TopoDS_Shape compound(const std::vector<TopoDS_Shape>& shapes)
{
    TopoDS_Compound c;
    BRep_Builder builder;
    builder.MakeCompound(c);
    for (const TopoDS_Shape& s : shapes)
        builder.Add(c, s);
    return c;
}

TopoDS_Shape moved(const TopoDS_Shape& s, const gp_Trsf& t)
{
    return BRepBuilderAPI_Transform(s, t, true).Shape();
}

TopoDS_Shape rod(const gp_Pnt& at, int axis, double from, double to, double r)
{
    gp_Pnt start = at;
    setCoord(start, axis, from);
    return BRepPrimAPI_MakeCylinder(gp_Ax2(start, gp_Dir(axis == 0, axis == 1, axis == 2)), r, to - from)
        .Shape();
}

TopoDS_Shape slot(const gp_Pnt& a, const gp_Pnt& b, int axis, double from, double to, double r)
{
    gp_Pnt p = a, q = b;
    setCoord(p, axis, from);
    setCoord(q, axis, from);
    if (p.Distance(q) < 1e-9)
        return rod(p, axis, from, to, r);
    const gp_Dir n(axis == 0, axis == 1, axis == 2), d(gp_Vec(p, q));
    const gp_Vec side = gp_Vec(n.Crossed(d)) * r;
    // Each half circle runs anticlockwise about n: from +side round p's far end, from -side round q's.
    const auto half = [&](const gp_Pnt& centre, const gp_Vec& start) {
        return BRepBuilderAPI_MakeEdge(gp_Circ(gp_Ax2(centre, n), r), centre.Translated(start),
                                       centre.Translated(-start))
            .Edge();
    };
    const TopoDS_Wire profile =
        BRepBuilderAPI_MakeWire(
            half(p, side), BRepBuilderAPI_MakeEdge(p.Translated(-side), q.Translated(-side)), half(q, -side),
            BRepBuilderAPI_MakeEdge(q.Translated(side), p.Translated(side)))
            .Wire();
    return BRepPrimAPI_MakePrism(BRepBuilderAPI_MakeFace(profile).Face(), gp_Vec(n) * (to - from)).Shape();
}

TopoDS_Shape rodFrom(const gp_Pnt& p, int n, double face, double sign, double from, double to, double radius)
{
    const double a = face + sign * from, b = face + sign * to;
    return rod(p, n, std::min(a, b), std::max(a, b), radius);
}

std::vector<Coordinates> boxesOf(const Model& m, int part, const std::vector<Coordinates>& at, double grow)
{
    std::vector<Coordinates> boxes;
    for (int c : m.parts[part].cuboids)
        if (!m.cuboids[c].cavity()) {
            Coordinates k = at[c];
            for (int i = 0; i < 6; ++i)
                k[i] += i % 2 ? grow : -grow;
            boxes.push_back(k);
        }
    return boxes;
}

TopoDS_Shape solid(const std::vector<Coordinates>& boxes)
{
    TopoDS_Shape s;
    for (const Coordinates& b : boxes)
        s = fuse(s, box(b));
    return s;
}

TopoDS_Shape solid(const Model& m, int part, const std::vector<Coordinates>& at, double grow)
{
    return solid(boxesOf(m, part, at, grow));
}

}  // namespace fabguide::printable
