// Bindings of print-in-place geometry (thesis 4.5): bodies cross as BREP text, which FreeCAD's Part module
// reads (Part.Shape().importBrepFromString).
#include "Bindings.h"
#include "IO/Json.h"
#include "IO/PrintFiles.h"
#include "IO/WorkslikeFormat.h"
#include "Json.h"
#include "Printable/Checks.h"
#include "Printable/Motion.h"

#include <BRepGProp.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <GProp_GProps.hxx>
#include <Standard_Failure.hxx>

#include <pybind11/stl.h>

#include <algorithm>
#include <optional>
#include <sstream>

namespace py = pybind11;

namespace fabguide::bindings {

namespace {

using Fit = std::optional<printable::Size>;

/// OpenCASCADE's work, without the GIL, its failures as RuntimeError.
template <class Work>
auto geometry(Work&& work)
{
    py::gil_scoped_release release;
    try {
        return work();
    } catch (const Standard_Failure& e) {
        throw std::runtime_error(std::string("geometry: ") + e.GetMessageString());
    }
}

/// The model solved and scaled, or fitted to a build volume, and its printable bodies (RuntimeError naming
/// what conflicts).
printable::Fitted made(const py::object& model, double gap, double scale, const Fit& fit)
{
    const function::Model read = io::readWorkslike(toJson(model));
    return geometry([&] { return printable::printed(read, {gap}, scale, fit); });
}

std::string brep(const TopoDS_Shape& shape)
{
    std::ostringstream text;
    BRepTools::Write(shape, text);
    return text.str();
}

/// {"bodies": [{"name", "part", "brep", "volume"}], "sweeps": [brep], "notes", "scale", "size", "clearance",
/// "where", "invalid", "loose"}
py::dict printableBodies(const py::object& model, double gap, bool check, double scale, const Fit& fit)
{
    printable::Fitted m = made(model, gap, scale, fit);
    printable::Check c;
    if (check) {  // joint geometry placed where it clears, as checked
        const printable::Checked placed =
            geometry([&] { return printable::placedByCheck(m.model, m.printable, {gap}); });
        m.printable = placed.printable;
        c = placed.check;
    }
    const printable::Printable& p = m.printable;
    py::list bodies, sweeps;
    for (const printable::Body& b : p.bodies) {
        GProp_GProps volume;
        BRepGProp::VolumeProperties(b.shape, volume);
        py::dict body;
        body["name"] = b.name;
        body["part"] = b.part;
        body["brep"] = brep(b.shape);
        body["volume"] = volume.Mass();
        bodies.append(body);
    }
    for (const TopoDS_Shape& s : p.sweeps)
        sweeps.append(brep(s));
    py::dict out;
    out["bodies"] = bodies;
    out["sweeps"] = sweeps;
    out["notes"] = p.notes;
    out["scale"] = m.scale;
    out["turned"] = m.turned;
    out["size"] = printable::sizeOf(printable::onTheBed(p, m.turned));
    if (check) {
        out["clearance"] = c.clearance;
        out["where"] = c.where;
        out["invalid"] = c.invalid;
        out["loose"] = c.loose;
    }
    return out;
}

/// The bodies as made (FreeCAD's Printable shows them), written as they go on the bed.
std::vector<std::string> writePrintable(const std::vector<py::dict>& bodies, const std::string& folder,
                                        bool turned)
{
    printable::Printable p;
    for (const py::dict& body : bodies) {
        std::istringstream text(body["brep"].cast<std::string>());
        TopoDS_Shape shape;
        BRep_Builder builder;
        BRepTools::Read(shape, text, builder);
        if (shape.IsNull())
            throw io::FormatError("body '" + body["name"].cast<std::string>() +
                                  "': no shape in its BREP text");
        p.bodies.push_back({body["name"].cast<std::string>(), -1, -1, shape});
    }
    py::gil_scoped_release release;
    return io::writePrintFiles(printable::onTheBed(std::move(p), turned), folder);
}

/// Each part's motion `t` of the way to configuration `name` (thesis 4.1.2), as the sweeps and the clearance
/// check move it: {part name: 3 x 4 matrix rows (rotation | translation)}.
py::dict partMotions(const py::object& model, const std::string& name, double t)
{
    const function::Model read = io::readWorkslike(toJson(model));
    const auto& configurations = read.configurations;
    const auto found = std::find_if(configurations.begin(), configurations.end(),
                                    [&](const function::Configuration& c) { return c.name == name; });
    if (found == configurations.end())
        throw io::FormatError("no configuration named '" + name + "'");
    py::dict out;
    for (int p = 0; p < static_cast<int>(read.parts.size()); ++p) {
        const gp_Trsf motion =
            printable::partMotion(read, p, static_cast<int>(found - configurations.begin()), t);
        py::list rows;
        for (int r = 1; r <= 3; ++r)
            rows.append(py::make_tuple(motion.Value(r, 1), motion.Value(r, 2), motion.Value(r, 3),
                                       motion.Value(r, 4)));
        out[py::str(read.parts[p].name)] = rows;
    }
    return out;
}

}  // namespace

void bindPrintable(py::module_& m)
{
    m.def(
        "part_motions", &partMotions, py::arg("model"), py::arg("configuration"), py::arg("t") = 1.0,
        "Each part's rigid motion t (0..1) of the way from the model's pose to a configuration, the motion\n"
        "the print's sweeps and clearance check follow (turns in the first half, slides in the second):\n"
        "{part name: three rows (r0, r1, r2, translation)}.");
    m.def("printable", &printableBodies, py::arg("model"), py::arg("gap") = 0.4, py::arg("check") = true,
          py::arg("scale") = 1.0, py::arg("fit") = py::none(),
          "Print-in-place bodies of a works-like model (solved first) at `scale`, or at the largest\n"
          "scale that fits the build volume `fit` (x, y, z mm): {'bodies': [{'name', 'part', 'brep',\n"
          "'volume'}], 'sweeps', 'notes', 'scale', 'turned' (a quarter about z to fit), 'size' (x, y, z\n"
          "mm on the bed), and with check 'clearance' (mm), 'where', 'invalid', 'loose'}.");
    m.def(
        "printable_body_names",
        [](const py::object& model) { return printable::bodyNames(io::readWorkslike(toJson(model))); },
        py::arg("model"),
        "The names of the bodies printable() makes, in its order, without making them: each part's, then\n"
        "'<joint> link' per double pivot.");
    m.def(
        "write_printable", &writePrintable, py::arg("bodies"), py::arg("folder"), py::arg("turned") = false,
        "Write bodies ([{'name', 'brep'}], as printable() makes them) as assembly.stl/.3mf/.step and one of\n"
        "each per body into folder, turned a quarter about z when `turned`; returns the paths.");
}

}  // namespace fabguide::bindings
