// Bindings of print-in-place geometry (thesis 4.5): bodies cross as BREP text, which FreeCAD's Part module
// reads (Part.Shape().importBrepFromString).
#include "Bindings.h"
#include "Function/Solve.h"
#include "IO/Json.h"
#include "IO/PrintFiles.h"
#include "IO/WorkslikeFormat.h"
#include "Json.h"
#include "Printable/Checks.h"

#include <BRepGProp.hxx>
#include <BRepTools.hxx>
#include <GProp_GProps.hxx>
#include <Standard_Failure.hxx>

#include <pybind11/stl.h>

#include <sstream>

namespace py = pybind11;

namespace fabguide::bindings {

namespace {

/// The model solved (raises PrintableError naming what conflicts) and made printable.
printable::Printable made(const py::object& model, double gap, double scale)
{
    const function::Model read = io::readWorkslike(toJson(model));
    py::gil_scoped_release release;
    const function::SolveResult solved = function::solve(read);
    if (!solved.solved) {
        std::string names;
        for (const std::string& n : solved.conflict)
            names += (names.empty() ? "" : ", ") + n;
        throw std::runtime_error("the mechanism does not solve: " + names + " cannot hold together");
    }
    try {
        return printable::makePrintable(function::scaled(solved.model, scale), {gap});
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

/// {"bodies": [{"name", "part", "brep", "volume"}], "sweeps": [brep], "notes", "clearance", "where",
/// "invalid"}
py::dict printableBodies(const py::object& model, double gap, bool check, double scale)
{
    const printable::Printable p = made(model, gap, scale);
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
    if (check) {
        const function::Model solved =
            function::scaled(function::solve(io::readWorkslike(toJson(model))).model, scale);
        printable::Check c;
        {
            py::gil_scoped_release release;
            c = printable::check(solved, p, gap);
        }
        out["clearance"] = c.clearance;
        out["where"] = c.where;
        out["invalid"] = c.invalid;
    }
    return out;
}

std::vector<std::string> exportPrintable(const py::object& model, double gap, const std::string& folder,
                                         double scale)
{
    const printable::Printable p = made(model, gap, scale);
    py::gil_scoped_release release;
    return io::writePrintFiles(p, folder);
}

}  // namespace

void bindPrintable(py::module_& m)
{
    m.def("printable", &printableBodies, py::arg("model"), py::arg("gap") = 0.4, py::arg("check") = true,
          py::arg("scale") = 1.0,
          "Print-in-place bodies of a works-like model (solved first): {'bodies': [{'name', 'part', 'brep',\n"
          "'volume'}], 'sweeps', 'notes', and with check 'clearance' (mm), 'where', 'invalid'}.");
    m.def("export_printable", &exportPrintable, py::arg("model"), py::arg("gap"), py::arg("folder"),
          py::arg("scale") = 1.0,
          "Write assembly.stl/.3mf/.step and one of each per body into folder; returns the paths.");
}

}  // namespace fabguide::bindings
