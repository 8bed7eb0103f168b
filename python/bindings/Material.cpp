// Bindings of the flat-pack layout (thesis ch. 5): problems and layouts are the dicts of docs/formats.md.
#include "Api/Pack.h"
#include "Bindings.h"
#include "Core/Parallel.h"
#include "IO/CutSheetFiles.h"
#include "IO/FlatpackFormat.h"
#include "IO/Json.h"
#include "IO/LayoutFiles.h"
#include "IO/PackFormat.h"
#include "IO/Report.h"
#include "Json.h"

#include <pybind11/stl.h>

namespace py = pybind11;

namespace fabguide::bindings {

namespace {

py::object pack(const py::object& problemDict, long iterations, double timeLimit, std::uint64_t seed,
                bool bottomLeft, const CancelToken* cancel)
{
    api::PackJob job;
    job.document = toJson(problemDict);
    job.search.iterations = iterations;
    job.search.timeLimit = timeLimit;
    job.search.seed = seed;
    job.search.threads = cores();
    job.search.criterion = bottomLeft ? material::Criterion::BottomLeft : material::Criterion::Docking;
    job.search.cancel = cancel ? &cancel->flag : nullptr;
    api::PackReport report;
    {
        py::gil_scoped_release release;
        report = api::pack(job);
    }
    return fromJson(io::layoutToJson(report.layout, report.problem, io::PartNames::Ids));
}

/// A problem dict and a layout dict of it, read.
std::pair<material::PackProblem, material::Layout> readLayout(const py::object& problemDict,
                                                              const py::object& layoutDict)
{
    material::PackProblem problem = io::readPackProblem(toJson(problemDict));
    material::Layout layout = io::readLayout(toJson(layoutDict), problem, io::PartNames::Ids);
    return {std::move(problem), std::move(layout)};
}

/// Every file of a layout as one set (io::writeLayoutFiles); the paths written.
std::vector<std::string> writeLayoutFiles(const py::object& problemDict, const py::object& layoutDict,
                                          const io::LayoutFiles& files)
{
    const auto [problem, layout] = readLayout(problemDict, layoutDict);
    std::vector<std::string> paths;
    for (const io::WrittenFile& file : io::writeLayoutFiles(layout, problem, files))
        paths.push_back(file.path);
    return paths;
}

py::tuple point(const geometry::Point2& p)
{
    return py::make_tuple(p.x, p.y);
}

py::list points(const geometry::Polygon& polygon)
{
    py::list list;
    for (const geometry::Point2& p : polygon)
        list.append(point(p));
    return list;
}

py::list placedOutlines(const py::object& problemDict, const py::object& layoutDict)
{
    const auto [problem, layout] = readLayout(problemDict, layoutDict);
    py::list out;
    for (size_t k = 0; k < layout.placements.size(); ++k) {
        const geometry::Outline outline = material::placedOutline(layout, problem, k);
        py::list holes;
        for (const geometry::Polygon& hole : outline.holes)
            holes.append(points(hole));
        py::dict item;
        item["board"] = layout.placements[k].sheet;
        item["part"] = problem.parts[layout.placements[k].part].id;
        item["outline"] = points(outline.outer);
        item["holes"] = holes;
        out.append(item);
    }
    return out;
}

/// Boards in 3-D -> the parts to cut with their connectors (docs/formats.md "Boards in 3-D").
py::object joinBoards(const py::object& boards, const std::string& style, int fingerFactor, double dowelFrom)
{
    const std::vector<material::Board3> board3 = io::readBoards3(toJson(boards));
    material::ConnectorSettings settings;
    settings.style = io::jointStyle(style);
    settings.fingerFactor = fingerFactor;
    settings.dowelFrom = dowelFrom;
    const material::JoinedBoards joined = material::joinBoards(board3, settings);
    return fromJson(
        io::piecesToJson(material::coplanarPieces(board3, joined, settings.tolerance), joined, board3));
}

py::dict cutSheetDict(const material::CutSheet& sheet, const material::Layout& layout,
                      const material::PackProblem& problem)
{
    py::list cuts, tabs, drills, lettering, labels, engraved;
    for (const material::ToolPath& cut : sheet.cuts) {
        py::dict item;
        item["points"] = points(cut.points);
        item["inner"] = cut.inner;
        item["open"] = cut.open;
        item["tabbed"] = cut.tabbed;
        item["hole"] = cut.hole;
        item["placement"] = cut.placement;
        item["part"] = problem.parts[layout.placements[cut.placement].part].id;
        cuts.append(item);
    }
    for (const auto& [from, to] : sheet.tabs)
        tabs.append(py::make_tuple(point(from), point(to)));
    for (const material::Drill& drill : sheet.drills)
        drills.append(py::dict(py::arg("at") = point(drill.at), py::arg("diameter") = drill.diameter,
                               py::arg("depth") = drill.depth));
    for (const std::vector<geometry::Polygon>& strokes : sheet.lettering) {
        py::list label;
        for (const geometry::Polygon& stroke : strokes)
            label.append(points(stroke));
        lettering.append(label);
    }
    for (const material::Label& label : sheet.labels)
        labels.append(py::dict(py::arg("text") = label.text, py::arg("at") = point(label.at),
                               py::arg("height") = label.height, py::arg("angle") = label.angle));
    for (const geometry::Polygon& mark : sheet.engraved)
        engraved.append(points(mark));
    const material::MasterBoard& board = sheet.board;
    return py::dict(py::arg("name") = board.name, py::arg("material") = board.material,
                    py::arg("width") = board.width, py::arg("height") = board.height,
                    py::arg("thickness") = board.thickness, py::arg("cuts") = cuts, py::arg("tabs") = tabs,
                    py::arg("drills") = drills, py::arg("lettering") = lettering, py::arg("labels") = labels,
                    py::arg("engraved") = engraved);
}

py::list cutSheetsOf(const py::object& problemDict, const py::object& layoutDict, bool asDesigned,
                     bool textLabels)
{
    const auto [problem, layout] = readLayout(problemDict, layoutDict);
    py::list out;
    for (const material::CutSheet& sheet : material::cutSheets(layout, problem, {asDesigned, textLabels}))
        out.append(cutSheetDict(sheet, layout, problem));
    return out;
}

std::vector<std::string> reportSvgs(const py::object& problemDict, const py::object& layoutDict,
                                    const std::string& title)
{
    const auto [problem, layout] = readLayout(problemDict, layoutDict);
    return io::reportSvgs(layout, problem, title);
}

/// FormatError (a ValueError) and its ConstraintError, each carrying `field`, the path of the field it names,
/// and `names`, the constraints and inner volumes a ConstraintError is about (empty for any other).
void bindFormatErrors(py::module_& m)
{
    static const py::exception<io::FormatError> formatError(m, "FormatError", PyExc_ValueError);
    static const py::exception<io::ConstraintError> constraintError(m, "ConstraintError", formatError.ptr());
    py::register_exception_translator([](std::exception_ptr thrown) {
        const auto raise = [](const py::object& type, const io::FormatError& error,
                              const std::vector<std::string>& names) {
            py::object raised = type(error.what());
            raised.attr("field") = error.field();
            raised.attr("names") = py::cast(names);
            PyErr_SetObject(type.ptr(), raised.ptr());
        };
        try {
            if (thrown)
                std::rethrow_exception(thrown);
        } catch (const io::ConstraintError& error) {
            raise(constraintError, error, error.names);
        } catch (const io::FormatError& error) {
            raise(formatError, error, {});
        }
    });
}

}  // namespace

void bindMaterial(py::module_& m)
{
    bindFormatErrors(m);
    py::register_exception<material::PackingError>(m, "PackingError", PyExc_RuntimeError);
    py::class_<CancelToken>(m, "CancelToken", "Stops a running pack() or optimise() from another thread.")
        .def(py::init<>())
        .def("cancel", [](CancelToken& t) { t.flag = true; })
        .def_property_readonly("cancelled", [](const CancelToken& t) { return t.flag.load(); });
    m.def(
        "pack", &pack, py::arg("problem"), py::arg("iterations") = -1, py::arg("time_limit") = 60.0,
        py::arg("seed") = 1, py::arg("bottom_left") = false, py::arg("cancel") = nullptr,
        "Lay the parts of a pack problem (a *.pack.json dict) out on its master boards; returns the layout "
        "dict.\n"
        "iterations=-1 tries |parts|^2 ordering swaps (thesis 5.4.3); the same inputs give the same layout.\n"
        "cancel (a CancelToken) stops the search from another thread with the best layout found so far.\n"
        "Raises FormatError naming a bad field, PackingError naming a part that does not fit.");
    m.def(
        "join_boards", &joinBoards, py::arg("boards"), py::arg("style") = "Auto",
        py::arg("finger_factor") = 2, py::arg("dowel_from") = 18.0,
        "Connectors where 3-D boards meet (style None, Fingers or Auto = dowels for thick boards); returns\n"
        "{'parts': [pack parts with tabs, slots, drills, marks], 'connectors': [...], 'notes': [...]}.");
    m.def("placed_outlines", &placedOutlines, py::arg("problem"), py::arg("layout"),
          "Each placement's outline as placed on its board: [{'board', 'part', 'outline': [(x, y)...], "
          "'holes'}].");
    m.def(
        "cut_sheets", &cutSheetsOf, py::arg("problem"), py::arg("layout"), py::arg("as_designed") = true,
        py::arg("text_labels") = false,
        "Each master board's cutting plan: {'name', 'material', 'width', 'height', 'thickness', 'cuts': "
        "[{'points', 'inner', 'open', 'tabbed', 'hole', 'placement', 'part'}] in the order to cut them, "
        "'tabs': "
        "[(from, to)], 'drills': [{'at', 'diameter', 'depth'}], 'lettering': per label its strokes, "
        "'labels': "
        "[{'text', 'at', 'height', 'angle'}], 'engraved'}; as designed (default): nominal outlines, closed.");
    m.def("report_svgs", &reportSvgs, py::arg("problem"), py::arg("layout"), py::arg("title"),
          "The report's pages as SVG texts, 297 x 210 mm each.");
    m.def(
        "write_layout_files",
        [](const py::object& problem, const py::object& layout, const std::string& svgFolder,
           const std::string& dxfFolder, const std::string& csvFile, const std::string& reportFile,
           const std::string& labelsFile, const std::string& optiCutterFile, const std::string& name,
           const std::string& title, std::pair<double, double> labelSize, bool asDesigned, bool textLabels) {
            return writeLayoutFiles(problem, layout,
                                    {svgFolder,
                                     dxfFolder,
                                     csvFile,
                                     reportFile,
                                     labelsFile,
                                     optiCutterFile,
                                     name,
                                     title,
                                     labelSize,
                                     {asDesigned, textLabels}});
        },
        py::arg("problem"), py::arg("layout"), py::arg("svg_folder") = "", py::arg("dxf_folder") = "",
        py::arg("csv_file") = "", py::arg("report_file") = "", py::arg("labels_file") = "",
        py::arg("opticutter_file") = "", py::arg("name") = "", py::arg("title") = "",
        py::arg("label_size") = std::pair{62.0, 29.0}, py::arg("as_designed") = false,
        py::arg("text_labels") = false,
        "Write a layout's files as one set, renamed into place together (each skipped when its path is "
        "empty): SVG/DXF cut sheets per board (NAME-sheet-N.* when a name is given; sheets of an earlier, "
        "longer set removed), the CSV cut list, the shop's PDF report (sheets, cut list, totals) titled "
        "`title`, PDF labels of label_size (width, height) mm, optiCutter's CSV import (one file per "
        "thickness); returns the paths. as_designed: the parts' nominal outlines, closed, no dogbones, the "
        "holding tabs on their own layer (for CAM software that offsets by its tool itself). text_labels: "
        "labels as text in a font, not strokes.");
}

}  // namespace fabguide::bindings
