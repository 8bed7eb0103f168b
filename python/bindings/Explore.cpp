// Bindings of zero-waste design exploration (thesis 5.3-5.4): designs are the `*.flatpack.json` dicts of
// docs/formats.md; the search runs without the GIL and reports progress on the calling thread.
#include "Api/Explore.h"
#include "Api/DesignEdit.h"
#include "Bindings.h"
#include "IO/ApiJson.h"
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

/// An exploration as a dict: its figures as summary.json gives them (io::explorationFigures), "before" and
/// "suggestions": [{usage, layout, problem, ...}], `describe` adding what a suggestion is in its design's own
/// terms.
template <typename Describe>
nlohmann::json explorationJson(const material::MaterialSpace& material, const material::Exploration& e,
                               Describe&& describe)
{
    nlohmann::json out = io::explorationFigures(e);
    out["before"] = io::designLayoutJson(material, e.start);
    out["suggestions"] = nlohmann::json::array();
    for (const material::Suggestion& s : e.suggestions) {
        nlohmann::json entry = io::designLayoutJson(material, s.result);
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

py::object layOutDesign(const py::object& document, std::uint64_t seed, double seconds)
{
    const io::FlatpackDesign f = io::readFlatpack(toJson(document));
    nlohmann::json laid;
    {
        py::gil_scoped_release release;
        laid = api::layOutDesign(f, seed, seconds, f.kept);
    }
    return fromJson(laid);
}

/// The exploration of a design dict (App/Api/Explore.h), run without the GIL.
py::object optimise(const py::object& document, std::uint64_t seed, int threads, double timeLimit, int rounds,
                    bool guided, const std::function<void(double, double)>& progress, CancelToken* cancel)
{
    const api::Exploring job{toJson(document),
                             options(seed, threads, timeLimit, rounds, guided, progress, cancel)};
    std::optional<api::ExplorationReport> report;
    {
        py::gil_scoped_release release;
        report.emplace(api::explore(job));
    }
    return fromJson(explorationJson(report->material, report->exploration,
                                    [&](const material::Suggestion& s, nlohmann::json& entry) {
                                        entry["design"] = report->suggestionDocument(s);
                                    }));
}

/// A flat-pack design's recompute (App/Api/DesignEdit.h), run without the GIL.
py::object editDesign(const py::object& design, const py::object& valid, bool keepEdits, double seconds,
                      std::uint64_t seed)
{
    api::DesignEdit edit{toJson(design), std::nullopt, keepEdits, seconds, seed};
    if (!valid.is_none())
        edit.valid = toJson(valid);
    api::DesignEditReport report;
    {
        py::gil_scoped_release release;
        report = api::editDesign(edit);
    }
    return fromJson(io::toJson(report));
}

py::object optimiseParametric(const py::list& parts,
                              const std::function<std::vector<double>(std::vector<double>)>& sides,
                              const std::vector<double>& start, const std::vector<double>& lower,
                              const std::vector<double>& upper, const py::object& sheets, std::uint64_t seed,
                              double timeLimit, int rounds,
                              const std::function<void(double, double)>& progress, CancelToken* cancel)
{
    const io::ParametricParts read = io::readParametricParts(toJson(parts));
    const auto toVector = [](const std::vector<double>& v) {
        return Eigen::Map<const Eigen::VectorXd>(v.data(), v.size());
    };
    const material::ParametricDesign design = material::parametricBoards(
        read.kinds, read.grainAxes,
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
    m.def(
        "edit_design", &editDesign, py::arg("design"), py::arg("valid") = py::none(),
        py::arg("keep_edits") = true, py::arg("seconds") = 2.0, py::arg("seed") = 1,
        "A flat-pack design dict's recompute (thesis 5.3.5, 5.3.2): the edit of the boards from `valid` (the "
        "last valid parts) kept as far as the constraints allow (keep_edits), boards moved until a "
        "constraint "
        "just added holds, the design laid out in a search of `seconds`, an edit that overflows the master "
        "boards absorbed or undone. Returns {design (as it ends), kept (share of the edit), limits, "
        "satisfied, "
        "absorbed, snapped, undone (why, or \"\"), warning, laid_out ({usage, layout, problem}, or None)}. "
        "Raises FormatError naming a bad field, ConstraintError naming constraints no move satisfies, "
        "PackingError when the design does not fit and there is no edit to undo.");
    m.def(
        "check_design",
        [](const py::object& design) { return fromJson(io::readFlatpack(toJson(design)).document); },
        py::arg("design"),
        "Reads a *.flatpack.json design dict as every command does, laying nothing out, and "
        "returns its normal form: as this version writes it (an older version's migrated), "
        "every default filled in (docs/formats.md). Raises FormatError naming a bad field, "
        "ConstraintError naming the constraints it breaks.");
    m.def(
        "drawn_equal",
        [](const py::object& design) { return fromJson(io::drawnEqualConstraints(toJson(design))); },
        py::arg("design"),
        "The equal constraints a design dict lacks that keep its boards drawn the same size so: "
        "[{kind, name, refs}], sizes along each in-plane axis.");
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
