// Bindings of print-in-place geometry (thesis 4.5): bodies cross as BREP text, which FreeCAD's Part module
// reads (Part.Shape().importBrepFromString).
#include "Api/PrintInPlace.h"
#include "Bindings.h"
#include "IO/Json.h"
#include "IO/PrintFiles.h"
#include "IO/WorkslikeFormat.h"
#include "Json.h"
#include "Printable/Checks.h"
#include "Printable/Motion.h"

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
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

std::string brep(const TopoDS_Shape& shape)
{
    std::ostringstream text;
    BRepTools::Write(shape, text);
    return text.str();
}

/// The print-in-place job (App/Api/PrintInPlace.h) without the GIL: {"bodies": [{"name", "part", "brep",
/// "volume"}], "sweeps": [brep], "notes", "scale", "turned", "size", "gap", and when checked "clearance",
/// "where", "invalid", "loose", "too_close", "ok"}.
py::dict printableBodies(const py::object& model, double gap, bool check, double scale, const Fit& fit,
                         double partSeconds)
{
    api::PrintJob job;
    job.model = toJson(model);
    job.gap = gap;
    job.check = check;
    job.scale = scale;
    job.fit = fit;
    job.partSeconds = partSeconds;
    const api::PrintReport made = geometry([&] { return api::printInPlace(job); });
    const printable::Printable& p = made.fitted.printable;
    py::list bodies, sweeps;
    for (size_t b = 0; b < p.bodies.size(); ++b) {
        py::dict body;
        body["name"] = p.bodies[b].name;
        body["part"] = p.bodies[b].part;
        body["brep"] = brep(p.bodies[b].shape);
        body["volume"] = made.volumes[b];
        bodies.append(body);
    }
    for (const TopoDS_Shape& s : p.sweeps)
        sweeps.append(brep(s));
    py::dict out;
    out["bodies"] = bodies;
    out["sweeps"] = sweeps;
    out["notes"] = p.notes;
    out["scale"] = made.fitted.scale;
    out["turned"] = made.fitted.turned;
    out["size"] = made.size;
    out["gap"] = made.gap;
    if (made.check) {
        out["clearance"] = made.check->clearance;
        out["where"] = made.check->where;
        out["invalid"] = made.check->invalid;
        out["loose"] = made.check->loose;
        out["too_close"] = made.tooClose();
        out["ok"] = made.ok();
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
          py::arg("part_seconds") = printable::Printer{}.partSeconds,
          "Print-in-place bodies of a works-like model (solved first) at `scale`, or at the largest\n"
          "scale that fits the build volume `fit` (x, y, z mm): {'bodies': [{'name', 'part', 'brep',\n"
          "'volume'}], 'sweeps', 'notes', 'scale', 'turned' (a quarter about z to fit), 'size' (x, y, z\n"
          "mm on the bed), 'gap', and with check 'clearance' (mm), 'where', 'invalid', 'loose',\n"
          "'too_close' (nearer than the gap), 'ok' (the print passes)}. part_seconds: what OpenCASCADE\n"
          "may take on one part or joint at each step before a RuntimeError naming it.");
    m.def(
        "printer_profiles",
        [] {
            py::list out;
            for (const api::PrinterProfile& p : api::printerProfiles())
                out.append(py::dict(py::arg("id") = p.id, py::arg("name") = p.name, py::arg("gap") = p.gap));
            return out;
        },
        "The printer profiles: [{'id', 'name', 'gap' (mm)}], FDM and resin.");
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
