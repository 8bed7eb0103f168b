// Bindings of the works-like solve (thesis ch. 4): models are *.workslike.json dicts.
#include "Bindings.h"
#include "IO/Json.h"
#include "IO/WorkslikeFormat.h"
#include "Json.h"

#include <pybind11/stl.h>

namespace py = pybind11;

namespace fabguide::bindings {

namespace {

/// The solved model (same format) with "report": {"solved", "conflict", "violation"}; raises FormatError
/// (a ValueError) naming a bad field.
py::object solve(const py::object& model)
{
    const function::Model read = io::readWorkslike(toJson(model));
    function::SolveResult result;
    {
        py::gil_scoped_release release;
        result = function::solve(read);
    }
    return fromJson(io::workslikeToJson(result.model, &result));
}

}  // namespace

void bindFunction(py::module_& m)
{
    m.def(
        "read_workslike",
        [](const py::object& model) { return fromJson(io::readWorkslikeDocument(toJson(model)).document); },
        py::arg("model"),
        "Reads a *.workslike.json dict as every command does and returns its normal form: as given, every "
        "default\n"
        "filled in (docs/formats.md). Raises FormatError (a ValueError) naming a bad field, e.g.\n"
        "\"relationships[0].faces[1]: no cuboid named 'bodyy'\".");
    m.def(
        "joint_kinds",
        [] {
            py::list kinds;
            for (const function::JointKind& k : function::kJointKinds)
                kinds.append(py::dict(py::arg("name") = k.name, py::arg("turns") = k.turns,
                                      py::arg("slides") = k.slides));
            return kinds;
        },
        "Every joint kind once, as the core knows it: [{'name', 'turns', 'slides'}].");
    m.def(
        "conflict_kinds",
        [] {
            py::list kinds;
            for (const function::ConflictKindName& k : function::kConflictKinds)
                kinds.append(py::dict(py::arg("name") = k.name, py::arg("relationship") = k.relationship));
            return kinds;
        },
        "Every kind a solve's conflicts give, once, as the core knows it: [{'name', 'relationship'}]; a "
        "relationship's kind is also its type in a model.");
    m.def(
        "solve", &solve, py::arg("model"),
        "Solve a works-like model (a *.workslike.json dict) for the least change that satisfies its "
        "relationships;\n"
        "returns the solved model with 'report': {'solved', 'conflict': [relationship names], 'violation'}.");
}

}  // namespace fabguide::bindings
