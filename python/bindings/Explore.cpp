// Bindings of zero-waste design exploration (thesis 5.3-5.4): designs are the `*.flatpack.json` dicts of
// docs/formats.md; the search runs without the GIL and reports progress on the calling thread.
#include "Bindings.h"
#include "Design/Correction.h"
#include "Design/DynamicPacker.h"
#include "IO/FlatpackFormat.h"
#include "IO/Json.h"
#include "IO/PackFormat.h"
#include "Json.h"

#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <atomic>

namespace py = pybind11;

namespace fabguide::bindings {

namespace {

/// A design's layout: its measures (usage, sheets, waste_m2, largest_offcut), the layout dict and the pack
/// problem dict it refers to.
nlohmann::json layoutJson(const material::MaterialSpace& material, const material::DesignLayout& d)
{
    const material::PackProblem problem = material.problem(d.sizes);
    nlohmann::json out = io::measures(d);
    out["layout"] = io::layoutToJson(material.inMillimetres(d.layout, d.sizes), problem, io::PartNames::Ids);
    out["problem"] = io::problemToJson(problem);
    return out;
}

/// An exploration as a dict: its figures as summary.json gives them (io::explorationFigures), "before" and
/// "suggestions": [{usage, layout, problem, ...}], `describe` adding what a suggestion is in its design's own
/// terms.
template <typename Describe>
nlohmann::json explorationJson(const material::MaterialSpace& material, const material::Exploration& e,
                               Describe&& describe)
{
    nlohmann::json out = io::explorationFigures(e);
    out["before"] = layoutJson(material, e.start);
    out["suggestions"] = nlohmann::json::array();
    for (const material::Suggestion& s : e.suggestions) {
        nlohmann::json entry = layoutJson(material, s.result);
        describe(s, entry);
        out["suggestions"].push_back(entry);
    }
    return out;
}

material::MinWastageOptions options(std::uint64_t seed, int threads, double timeLimit, int rounds,
                                    bool guided, const std::function<void(double, double)>& progress,
                                    CancelToken* cancel)
{
    material::MinWastageOptions o;
    o.seed = seed;
    o.threads = threads;
    o.timeLimit = timeLimit;
    o.rounds = rounds;
    o.guided = guided;
    o.cancel = cancel ? &cancel->flag : nullptr;
    if (progress)
        o.progress = [progress](double done, double best) {
            py::gil_scoped_acquire gil;
            progress(done, best);
        };
    return o;
}

material::Exploration explore(const material::DesignSpace& design, const material::MaterialSpace& material,
                              const material::MinWastageOptions& o)
{
    py::gil_scoped_release release;
    return material::minWastage(design, material, o);
}

py::object layOutDesign(const py::object& document, std::uint64_t seed, double seconds)
{
    const io::FlatpackDesign f = io::readFlatpack(toJson(document));
    const material::ConstrainedDesign design(f.design);
    const material::MaterialSpace material(f.boards, f.settings, design.parts());
    material::DesignLayout laid;
    {
        py::gil_scoped_release release;
        laid = material::layOut(design, material, seed, seconds, nullptr, f.kept);
    }
    return fromJson(layoutJson(material, laid));
}

py::object optimise(const py::object& document, std::uint64_t seed, int threads, double timeLimit, int rounds,
                    bool guided, const std::function<void(double, double)>& progress, CancelToken* cancel)
{
    const nlohmann::json doc = toJson(document);
    const io::FlatpackDesign f = io::readFlatpack(doc);
    const material::ConstrainedDesign design(io::forSuggestions(f));
    const material::MaterialSpace material(f.boards, f.settings, design.parts());
    material::MinWastageOptions o = options(seed, threads, timeLimit, rounds, guided, progress, cancel);
    o.kept = f.kept;
    const material::Exploration e = explore(design, material, o);
    return fromJson(explorationJson(material, e, [&](const material::Suggestion& s, nlohmann::json& entry) {
        entry["design"] = io::suggestionDocument(doc, f.design, material, s);
    }));
}

/// X of `design` with the parts of the `edited` design dict (same parts, moved or resized).
Eigen::VectorXd editedVariables(const material::Design& design, const py::object& edited)
{
    const nlohmann::json parts = toJson(edited)["parts"];
    if (!parts.is_array() || parts.size() != design.boards.size())
        throw io::FormatError("parts: the edited design must have the same parts as the valid one");
    material::Design changed = design;
    for (size_t b = 0; b < parts.size(); ++b) {
        const io::Fields part(parts[b], "parts[" + std::to_string(b) + "]");
        changed.boards[b].size = part.vector3("size");
        changed.boards[b].centre = part.vector3("position") + changed.boards[b].size / 2;
    }
    return changed.variables();
}

/// Thesis 5.3.5: the edited design kept valid, the edits kept (Algorithms 5 and 6).
py::object correctDesign(const py::object& valid, const py::object& edited)
{
    const io::FlatpackDesign before = io::readFlatpack(toJson(valid));
    const Eigen::VectorXd X = before.design.variables(), edit = editedVariables(before.design, edited);
    material::CorrectedChange c;
    {
        py::gil_scoped_release release;
        c = material::correctChange(before.design, X, edit - X);
    }
    return fromJson({{"parts", io::partsAt(before.design, c.X)}, {"alpha", c.alpha}, {"limits", c.limits}});
}

/// A design that breaks some of its constraints (one just added) moved the least, sparsely (Algorithm 6, with
/// no change to keep), so that they all hold.
py::object satisfyDesign(const py::object& document)
{
    const io::FlatpackDesign f = io::readFlatpack(toJson(document), io::Satisfied::NotRequired);
    const Eigen::VectorXd X = f.design.variables();
    std::vector<std::string> broken;
    std::optional<Eigen::VectorXd> d;
    {
        py::gil_scoped_release release;
        d = material::correctForDesignConstraints(f.design, {}, X, Eigen::VectorXd::Zero(X.size()), &broken);
    }
    const Eigen::VectorXd Y = d ? Eigen::VectorXd(X + *d) : X;
    if (d)
        broken = material::said(material::ineffective(f.design, Y));
    return fromJson({{"solved", broken.empty()}, {"parts", io::partsAt(f.design, Y)}, {"broken", broken}});
}

/// Thesis 5.3.2: an edit after which the parts overflow the master boards, absorbed by the dynamic packer.
py::object absorbEdit(const py::object& valid, const py::object& edited)
{
    const io::FlatpackDesign before = io::readFlatpack(toJson(valid));
    const material::ConstrainedDesign design(before.design);
    const material::MaterialSpace material(before.boards, before.settings, design.parts());
    const Eigen::VectorXd X = before.design.variables(), edit = editedVariables(before.design, edited);
    material::Absorbed a;
    {
        py::gil_scoped_release release;
        const material::DesignLayout laid = material::layOut(design, material, 1);
        a = material::dynamicPacker(design, material, X, laid.layout, edit - X);
    }
    return fromJson(
        {{"fitted", a.fitted}, {"parts", io::partsAt(before.design, a.X)}, {"snapped", a.snapped}});
}

py::object optimiseParametric(const py::list& parts,
                              const std::function<std::vector<double>(std::vector<double>)>& sides,
                              const std::vector<double>& start, const std::vector<double>& lower,
                              const std::vector<double>& upper, const py::object& sheets, std::uint64_t seed,
                              double timeLimit, int rounds,
                              const std::function<void(double, double)>& progress, CancelToken* cancel)
{
    std::vector<material::PartKind> kinds;
    std::vector<int> grainAxes;
    for (const py::handle& p : parts) {
        kinds.push_back(
            {p["id"].cast<std::string>(), p.contains("quantity") ? p["quantity"].cast<int>() : 1});
        const std::string grain = p.contains("grain") ? p["grain"].cast<std::string>() : "free";
        const std::optional<int> axis = io::grainAxisNamed(grain);
        if (!axis)
            throw io::FormatError("parts[" + std::to_string(grainAxes.size()) +
                                  "].grain: must be \"free\", \"x\", \"y\" or \"z\", got \"" + grain + "\"");
        grainAxes.push_back(*axis);
    }
    const auto toVector = [](const std::vector<double>& v) {
        return Eigen::Map<const Eigen::VectorXd>(v.data(), v.size());
    };
    const material::ParametricDesign design = material::parametricBoards(
        kinds, grainAxes,
        [sides](const Eigen::VectorXd& X) {
            const std::vector<double> s = sides(std::vector<double>(X.data(), X.data() + X.size()));
            return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(s.data(), s.size()));
        },
        toVector(start), toVector(lower), toVector(upper));
    const nlohmann::json sheetsDoc = toJson(sheets);
    const material::MaterialSpace material(io::readMasterBoards(sheetsDoc), io::readSettings(sheetsDoc),
                                           design.parts());
    // D(X) is Python: one thread, on this one (FreeCAD documents recompute on the thread that owns them).
    material::MinWastageOptions o = options(seed, 1, timeLimit, rounds, true, progress, cancel);
    const material::Exploration e = material::minWastage(design, material, o);
    const auto list = [](const Eigen::VectorXd& X) {
        return std::vector<double>(X.data(), X.data() + X.size());
    };
    return fromJson(explorationJson(material, e, [&](const material::Suggestion& s, nlohmann::json& entry) {
        entry["parameters"] = list(s.result.X);
        entry["path"] = nlohmann::json::array();
        for (const material::DesignLayout& step : s.path)
            entry["path"].push_back({{"usage", 1 - step.wastage}, {"parameters", list(step.X)}});
    }));
}

}  // namespace

void bindExplore(py::module_& m)
{
    m.def(
        "lay_out_design", &layOutDesign, py::arg("design"), py::arg("seed") = 1, py::arg("seconds") = 10.0,
        "A *.flatpack.json design dict laid out on its master boards by an ordering search of at most "
        "`seconds` (on to 10 s when a part is left over), or the layout it keeps (layout, layout_order) when "
        "that is better: {usage, layout, problem}. Raises FormatError naming a bad field or a broken "
        "constraint, PackingError naming a part that does not fit.");
    m.def("optimise", &optimise, py::arg("design"), py::arg("seed") = 1, py::arg("threads") = 2,
          py::arg("time_limit") = 8.0, py::arg("rounds") = 3, py::arg("guided") = true,
          py::arg("progress") = nullptr, py::arg("cancel") = nullptr,
          "MINWASTAGE on a *.flatpack.json design dict: the figures of summary.json (usage_before, seconds, "
          "stopped, least_sheets, least_sheets_by_area, least_sheets_bound, no_sheet_saved, not_reopened), "
          "before, and suggestions: [{usage, layout, problem, design (with path)}]. progress(fraction, "
          "best_usage) is called on this thread; cancel is a CancelToken.");
    m.def("correct_design", &correctDesign, py::arg("valid"), py::arg("edited"),
          "Keeps an edited design valid (thesis 5.3.5): valid is a design dict satisfying its constraints, "
          "edited "
          "has the same parts with some moved or resized. Returns {parts, alpha (share of the edit kept), "
          "limits "
          "(constraints that stopped it)}.");
    m.def(
        "satisfy_design", &satisfyDesign, py::arg("design"),
        "A design dict whose boards break some of its constraints (one just added), with the boards moved or "
        "resized the least, sparsely, so that they hold: {solved, parts, broken (names still broken)}.");
    m.def(
        "check_design", [](const py::object& design) { io::readFlatpack(toJson(design)); }, py::arg("design"),
        "Reads a *.flatpack.json design dict as every command does, laying nothing out: raises FormatError "
        "naming a bad field, ConstraintError naming the constraints it breaks.");
    m.def(
        "drawn_equal",
        [](const py::object& design) { return fromJson(io::drawnEqualConstraints(toJson(design))); },
        py::arg("design"),
        "The equal constraints a design dict lacks that keep its boards drawn the same size so: "
        "[{kind, name, refs}], sizes along each in-plane axis.");
    m.def(
        "absorb_edit", &absorbEdit, py::arg("valid"), py::arg("edited"),
        "The dynamic packer (thesis 5.3.2): when the edited design's parts no longer fit the master boards, "
        "shortens the parts that share a line across the board with the edited ones so they do, keeping the "
        "edit and every constraint. Returns {fitted, parts, snapped (the lines saturated)}.");
    m.def(
        "optimise_parametric", &optimiseParametric, py::arg("parts"), py::arg("sides"), py::arg("start"),
        py::arg("lower"), py::arg("upper"), py::arg("sheets"), py::arg("seed") = 1,
        py::arg("time_limit") = 8.0, py::arg("rounds") = 3, py::arg("progress") = nullptr,
        py::arg("cancel") = nullptr,
        "MINWASTAGE on a parametric design of boards (thesis 5.4.2.2): sides(parameters) -> [x0, y0, z0, x1, "
        "...], the three sides of each of parts [{id, quantity, grain: 'x', 'y', 'z' or 'free'}], parameters "
        "within [lower, upper]; each part is cut from master boards of its thinnest side, along their grain "
        "if it has one. sheets is {boards, settings} as in *.pack.json. Runs on this thread. Returns "
        "suggestions with their parameters and paths.");
}

}  // namespace fabguide::bindings
