#include "IO/CutSheetFiles.h"

#include "IO/Json.h"
#include "IO/Output.h"
#include "IO/PackFormat.h"
#include "IO/Xml.h"

#include <dxflib/dl_dxf.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

namespace fabguide::io {

namespace {

constexpr double kPi = 3.14159265358979323846;

/// Writes the text `write(out)` puts out into `path`, atomically (IO/Output.h).
template <typename Write>
void writeText(const std::string& path, Write&& write)
{
    writeAtomically(path, [&](const std::string& temporary) {
        std::ofstream out(temporary);
        write(out);
        if (!out.flush())
            throw FormatError(path + ": cannot write file");
    });
}

std::string quoteCsv(const std::string& text)
{
    const std::string plain = plainText(text);  // one row per part, whatever its name holds
    if (plain.find_first_of(",\"") == std::string::npos)
        return plain;
    std::string out = "\"";
    for (char c : plain)
        out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

/// An SVG path, closed unless `open`; y flipped for SVG's downward axis on a sheet `height` tall.
std::string svgPath(const geometry::Polygon& polygon, double height, bool open = false)
{
    std::ostringstream d;
    for (size_t i = 0; i < polygon.size(); ++i)
        d << (i ? " L" : "M") << polygon[i].x << "," << height - polygon[i].y;
    return "<path d=\"" + d.str() + (open ? "" : " Z") + "\"/>";
}

/// The OBJECTS section of an R2000 file: the root dictionary, groups and the three layouts dxflib's
/// block records stand for. dxflib's own writeObjects leaves out the owner handles (group 330), which
/// readers then have to repair; the handles are dxflib's fixed ones.
void writeObjects(DL_WriterA& dw)
{
    auto dictionary = [&](const char* handle, const char* owner,
                          std::initializer_list<std::pair<const char*, const char*>> entries) {
        dw.dxfString(0, "DICTIONARY");
        dw.dxfString(5, handle);
        dw.dxfString(330, owner);
        dw.dxfString(100, "AcDbDictionary");
        dw.dxfInt(281, 1);
        for (const auto& [name, entry] : entries) {
            dw.dxfString(3, name);
            dw.dxfString(350, entry);
        }
    };
    auto layout = [&](const char* handle, const char* name, int tab, const char* blockRecord) {
        dw.dxfString(0, "LAYOUT");
        dw.dxfString(5, handle);
        dw.dxfString(330, "1A");
        dw.dxfString(100, "AcDbPlotSettings");
        for (int code : {1, 2, 4, 6})
            dw.dxfString(code, code == 2 ? "none_device" : "");
        for (int code : {40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 140, 141})
            dw.dxfReal(code, 0.0);
        dw.dxfReal(142, 1.0);
        dw.dxfReal(143, 1.0);
        dw.dxfInt(70, 688);
        dw.dxfInt(72, 0);
        dw.dxfInt(73, 0);
        dw.dxfInt(74, 5);
        dw.dxfString(7, "");
        dw.dxfInt(75, 16);
        dw.dxfReal(147, 1.0);
        dw.dxfReal(148, 0.0);
        dw.dxfReal(149, 0.0);
        dw.dxfString(100, "AcDbLayout");
        dw.dxfString(1, name);
        dw.dxfInt(70, 1);
        dw.dxfInt(71, tab);
        const std::pair<int, double> limits[] = {{10, 0}, {20, 0},  {11, 420}, {21, 297}, {12, 0}, {22, 0},
                                                 {32, 0}, {14, 0},  {24, 0},   {34, 0},   {15, 0}, {25, 0},
                                                 {35, 0}, {146, 0}, {13, 0},   {23, 0},   {33, 0}, {16, 1},
                                                 {26, 0}, {36, 0},  {17, 0},   {27, 1},   {37, 0}};
        for (const auto& [code, value] : limits)
            dw.dxfReal(code, value);
        dw.dxfInt(76, 0);
        dw.dxfString(330, blockRecord);
    };
    dw.sectionObjects();
    dictionary("C", "0", {{"ACAD_GROUP", "D"}, {"ACAD_LAYOUT", "1A"}});
    dictionary("D", "C", {});
    dictionary("1A", "C", {{"Layout1", "1E"}, {"Layout2", "26"}, {"Model", "22"}});
    layout("1E", "Layout1", 1, "1B");  // *Paper_Space
    layout("22", "Model", 0, "1F");    // *Model_Space
    layout("26", "Layout2", 2, "23");  // *Paper_Space0
    dw.sectionEnd();
}

/// The DXF layer of a drill: DRILL_<depth>MM ("DRILL_12MM", "DRILL_7.5MM"), so a depth survives the file.
std::string drillLayer(const material::Drill& drill)
{
    char depth[32];
    std::snprintf(depth, sizeof depth, "%g", std::round(drill.depth * 1000) / 1000);
    return std::string("DRILL_") + depth + "MM";
}

}  // namespace

std::string svg(const material::CutSheet& sheet)
{
    const double stroke = 0.1;  // mm: a hairline
    const double w = sheet.board.width, h = sheet.board.height;
    std::ostringstream out;
    // An Inkscape layer per operation, in the order they are done; `style` holds its colour and such.
    const auto layer = [&](const std::string& id, const std::string& label, const std::string& style) {
        out << "  <g id=\"" << id << "\" inkscape:groupmode=\"layer\" inkscape:label=\"" << label << "\" "
            << style << ">\n";
    };
    const auto lines = [&](const std::string& colour) {
        return "fill=\"none\" stroke=\"" + colour + "\" stroke-width=\"" + show(stroke) + "\"";
    };
    out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        << "<svg xmlns=\"http://www.w3.org/2000/svg\" "
           "xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" width=\""
        << w << "mm\" height=\"" << h << "mm\" viewBox=\"0 0 " << w << " " << h << "\">\n"
        << "  <title>" << escapeXml(sheet.board.name) << " " << w << " x " << h << " mm</title>\n";
    layer("sheet", "Sheet (not cut)", lines("#999999"));
    out << "    <rect x=\"0\" y=\"0\" width=\"" << w << "\" height=\"" << h << "\"/>\n  </g>\n";
    std::vector<double> depths;
    for (const material::Drill& drill : sheet.drills)
        if (std::find(depths.begin(), depths.end(), drill.depth) == depths.end())
            depths.push_back(drill.depth);
    for (double depth : depths) {
        layer("drill-" + show(depth) + "mm", "Drill " + show(depth) + " mm deep", lines("#00a000"));
        for (const material::Drill& drill : sheet.drills)
            if (drill.depth == depth)
                out << "    <circle cx=\"" << drill.at.x << "\" cy=\"" << h - drill.at.y << "\" r=\""
                    << drill.diameter / 2 << "\" data-depth=\"" << drill.depth << "\"/>\n";
        out << "  </g>\n";
    }
    layer("engrave", "Engrave",
          "fill=\"#0000ff\" stroke=\"none\" font-family=\"sans-serif\" text-anchor=\"middle\" "
          "dominant-baseline=\"central\"");
    for (size_t k = 0; k < sheet.lettering.size(); ++k) {  // labels as strokes, their text kept as data
        out << "    <g data-label=\"" << escapeXml(sheet.labels[k].text) << "\" " << lines("#0000ff") << ">";
        for (const geometry::Polygon& stroke : sheet.lettering[k])
            out << svgPath(stroke, h, true);
        out << "</g>\n";
    }
    for (size_t k = sheet.lettering.empty() ? 0 : sheet.labels.size(); k < sheet.labels.size(); ++k) {
        const material::Label& label = sheet.labels[k];  // as text
        out << "    <text x=\"" << label.at.x << "\" y=\"" << h - label.at.y << "\" font-size=\""
            << label.height << "\""
            << (label.angle != 0
                    ? " transform=\"rotate(" + std::to_string(-label.angle) + " " +
                          std::to_string(label.at.x) + " " + std::to_string(h - label.at.y) + ")\""
                    : std::string())
            << ">" << escapeXml(label.text) << "</text>\n";
    }
    for (const geometry::Polygon& mark : sheet.engraved)
        out << "    " << svgPath(mark, h) << "\n";
    out << "  </g>\n";
    for (const bool inner : {true, false}) {
        layer(inner ? "inner-cut" : "outer-cut", inner ? "Inner cut (first)" : "Outer cut",
              lines(inner ? "#ff00ff" : "#ff0000"));
        for (const material::ToolPath& cut : sheet.cuts)
            if (cut.inner == inner)
                out << "    " << svgPath(cut.points, h, cut.open) << "\n";
        out << "  </g>\n";
    }
    if (!sheet.banding.empty()) {  // thick brown lines along the edges to band, the band's name as data
        layer("edge-banding", "Edge banding (not cut)",
              "fill=\"none\" stroke=\"#a0522d\" stroke-opacity=\"0.6\" stroke-width=\"" + show(10 * stroke) +
                  "\"");
        for (const material::Banding& b : sheet.banding)
            out << "    <line x1=\"" << b.from.x << "\" y1=\"" << h - b.from.y << "\" x2=\"" << b.to.x
                << "\" y2=\"" << h - b.to.y << "\" data-band=\"" << escapeXml(b.band) << "\"/>\n";
        out << "  </g>\n";
    }
    if (!sheet.tabs.empty()) {  // as designed: where the holding tabs go, for the CAM to leave them
        layer("tabs", "Holding tabs (not cut)", lines("#00c0c0"));
        for (const auto& [from, to] : sheet.tabs)
            out << "    <line x1=\"" << from.x << "\" y1=\"" << h - from.y << "\" x2=\"" << to.x << "\" y2=\""
                << h - to.y << "\"/>\n";
        out << "  </g>\n";
    }
    if (!sheet.sawCuts.empty()) {  // dashed orange lines numbered in their order, for the person at the saw
        const double size = std::max(8.0, std::min(w, h) / 80);
        layer("saw", "Saw cuts",
              "fill=\"#ff8000\" stroke=\"#ff8000\" stroke-width=\"" + show(std::max(stroke, size / 10)) +
                  "\" stroke-dasharray=\"" + show(2 * size) + " " + show(size) +
                  "\" font-family=\"sans-serif\" font-size=\"" + show(size) + "\" text-anchor=\"middle\"");
        for (const material::SawCut& c : sheet.sawCuts)
            out << "    <line x1=\"" << c.from.x << "\" y1=\"" << h - c.from.y << "\" x2=\"" << c.to.x
                << "\" y2=\"" << h - c.to.y << "\" data-number=\"" << c.number << "\" data-stage=\""
                << c.stage << "\"/>\n"
                << "    <text x=\"" << (c.from.x + c.to.x) / 2 << "\" y=\"" << h - (c.from.y + c.to.y) / 2
                << "\" stroke=\"none\">" << c.number << "</text>\n";
        out << "  </g>\n";
    }
    out << "</svg>\n";
    return out.str();
}

void writeSvg(const material::CutSheet& sheet, const std::string& path)
{
    writeText(path, [&](std::ostream& out) { out << svg(sheet); });
}

void writeDxf(const material::CutSheet& sheet, const std::string& path, const std::string& file)
{
    DL_Dxf dxf;
    std::unique_ptr<DL_WriterA> dw(dxf.out(file.c_str(), DL_Codes::AC1015));
    if (!dw)
        throw FormatError(path + ": cannot write file");
    dxf.writeHeader(*dw);
    dw->dxfString(9, "$INSUNITS");  // drawing units: millimetres
    dw->dxfInt(70, 4);
    dw->dxfString(9, "$MEASUREMENT");  // metric
    dw->dxfInt(70, 1);
    dw->sectionEnd();

    dw->sectionTables();
    dxf.writeVPort(*dw);
    dw->tableLinetypes(3);
    dxf.writeLinetype(*dw, DL_LinetypeData("BYBLOCK", "BYBLOCK", 0, 0, 0.0));
    dxf.writeLinetype(*dw, DL_LinetypeData("BYLAYER", "BYLAYER", 0, 0, 0.0));
    dxf.writeLinetype(*dw, DL_LinetypeData("CONTINUOUS", "Continuous", 0, 0, 0.0));
    dw->tableEnd();
    std::vector<std::pair<std::string, int>> layers = {{"0", 7},       {"INNER_CUT", 6}, {"OUTER_CUT", 1},
                                                       {"ENGRAVE", 5}, {"SHEET", 8},     {"SAW", 30}};
    if (!sheet.tabs.empty())
        layers.emplace_back("TABS", 4);
    if (!sheet.banding.empty())
        layers.emplace_back("EDGE_BANDING", 32);
    for (const material::Drill& drill : sheet.drills)  // a layer per depth, which CAM maps to a drilling pass
        if (std::none_of(layers.begin(), layers.end(),
                         [&](const auto& l) { return l.first == drillLayer(drill); }))
            layers.emplace_back(drillLayer(drill), 3);
    dw->tableLayers(static_cast<int>(layers.size()));
    for (const auto& [name, colour] : layers)
        dxf.writeLayer(*dw, DL_LayerData(name, 0), DL_Attributes("", colour, -1, "CONTINUOUS", 1.0));
    dw->tableEnd();
    dw->tableStyle(1);
    dxf.writeStyle(*dw, DL_StyleData("Standard", 0, 0.0, 1.0, 0.0, 0, 2.5, "txt", ""));
    dw->tableEnd();
    dxf.writeView(*dw);
    dxf.writeUcs(*dw);
    dw->tableAppid(1);
    dxf.writeAppid(*dw, "ACAD");
    dw->tableEnd();
    dxf.writeDimStyle(*dw, 1, 1, 1, 1, 1);
    dxf.writeBlockRecord(*dw);
    dw->tableEnd();
    dw->sectionEnd();

    dw->sectionBlocks();
    for (const char* block : {"*Model_Space", "*Paper_Space", "*Paper_Space0"}) {
        dxf.writeBlock(*dw, DL_BlockData(block, 0, 0.0, 0.0, 0.0));
        dxf.writeEndBlock(*dw, block);
    }
    dw->sectionEnd();

    dw->sectionEntities();
    auto polygon = [&](const geometry::Polygon& points, const char* layer, bool open = false) {
        const DL_Attributes attributes(layer, 256, -1, "BYLAYER", 1.0);  // colour and line type by layer
        dxf.writePolyline(*dw, DL_PolylineData(static_cast<int>(points.size()), 0, 0, open ? 0 : 1),
                          attributes);
        for (const geometry::Point2& p : points)
            dxf.writeVertex(*dw, DL_VertexData(p.x, p.y, 0.0, 0.0));
        dxf.writePolylineEnd(*dw);
    };
    polygon(
        {{0, 0}, {sheet.board.width, 0}, {sheet.board.width, sheet.board.height}, {0, sheet.board.height}},
        "SHEET");
    for (const material::ToolPath& cut : sheet.cuts)
        polygon(cut.points, cut.inner ? "INNER_CUT" : "OUTER_CUT", cut.open);
    for (const auto& [from, to] : sheet.tabs)
        dxf.writeLine(*dw, DL_LineData(from.x, from.y, 0, to.x, to.y, 0),
                      DL_Attributes("TABS", 256, -1, "BYLAYER", 1.0));
    for (const geometry::Polygon& mark : sheet.engraved)
        polygon(mark, "ENGRAVE");
    for (const material::Banding& b : sheet.banding)
        dxf.writeLine(*dw, DL_LineData(b.from.x, b.from.y, 0, b.to.x, b.to.y, 0),
                      DL_Attributes("EDGE_BANDING", 256, -1, "BYLAYER", 1.0));
    for (const material::Drill& drill : sheet.drills)
        dxf.writeCircle(*dw, DL_CircleData(drill.at.x, drill.at.y, 0.0, drill.diameter / 2),
                        DL_Attributes(drillLayer(drill), 256, -1, "BYLAYER", 1.0));
    for (const std::vector<geometry::Polygon>& lettering : sheet.lettering)
        for (const geometry::Polygon& stroke : lettering)
            polygon(stroke, "ENGRAVE", true);
    for (size_t k = sheet.lettering.empty() ? 0 : sheet.labels.size(); k < sheet.labels.size(); ++k) {
        const material::Label& label =
            sheet.labels[k];  // as text, centred horizontally (1) and vertically (2)
        dxf.writeText(
            *dw,
            DL_TextData(label.at.x, label.at.y, 0, label.at.x, label.at.y, 0, label.height, 1.0, 0, 1, 2,
                        plainText(label.text), "Standard", label.angle * kPi / 180),  // radians
            DL_Attributes("ENGRAVE", 256, -1, "BYLAYER", 1.0));
    }
    for (const material::SawCut& c : sheet.sawCuts) {  // the saw's lines, each with its number beside it
        dxf.writeLine(*dw, DL_LineData(c.from.x, c.from.y, 0, c.to.x, c.to.y, 0),
                      DL_Attributes("SAW", 256, -1, "BYLAYER", 1.0));
        const double x = (c.from.x + c.to.x) / 2, y = (c.from.y + c.to.y) / 2;
        dxf.writeText(*dw, DL_TextData(x, y, 0, x, y, 0, 8, 1.0, 0, 1, 0, plainText(c.number), "Standard", 0),
                      DL_Attributes("SAW", 256, -1, "BYLAYER", 1.0));
    }
    dw->sectionEnd();
    writeObjects(*dw);
    dw->dxfEOF();
    dw->close();
}

void writeCutList(const std::vector<material::CutListRow>& rows, const std::string& path)
{
    writeText(path, [&](std::ostream& out) {
        out << "part,quantity,width,height,thickness,material,board,grain";
        for (const std::string& side : sideNames())
            out << ",edge_" << side;
        out << ",label\n";
        for (const material::CutListRow& row : rows) {
            out << quoteCsv(row.part) << "," << row.quantity << "," << row.width << "," << row.height << ","
                << row.thickness << "," << quoteCsv(row.material) << "," << row.board + 1 << ","
                << (row.grain ? "width" : "");
            for (const std::string& band : row.edgeBanding)
                out << "," << quoteCsv(band);
            out << "," << quoteCsv(row.part) << "\n";
        }
    });
}

std::vector<std::string> writeSheets(const std::vector<material::CutSheet>& sheets, const std::string& folder,
                                     const std::string& extension, const std::string& name)
{
    if (name.find_first_of("/\\") != std::string::npos || name == "." || name == "..")
        throw FormatError("\"" + name + "\": a cut-sheet name must be a plain file name");
    std::error_code error;
    std::filesystem::create_directories(folder, error);
    if (error)
        throw FormatError(folder + ": cannot create folder (" + error.message() + ")");
    const auto pathOf = [&](size_t number) {
        return (std::filesystem::path(folder) /
                ((name.empty() ? "" : name + "-") + "sheet-" + std::to_string(number) + "." + extension))
            .string();
    };
    std::vector<std::string> paths;
    for (size_t s = 0; s < sheets.size(); ++s) {
        paths.push_back(pathOf(s + 1));
        if (extension == "svg")
            writeSvg(sheets[s], paths.back());
        else
            writeAtomically(paths.back(),
                            [&](const std::string& file) { writeDxf(sheets[s], paths.back(), file); });
    }
    for (size_t stale = sheets.size() + 1; std::filesystem::exists(pathOf(stale), error); ++stale)
        removeWhenCommitted(pathOf(stale));  // the previous layout's last sheets, once this one is in place
    return paths;
}

std::vector<std::string> writeOptiCutter(const material::PackProblem& problem, const std::string& path,
                                         const std::string& name)
{
    std::vector<double> thicknesses;  // of the parts' master boards
    for (const material::MasterBoard& board : problem.boards)
        if (std::find(thicknesses.begin(), thicknesses.end(), board.thickness) == thicknesses.end())
            thicknesses.push_back(board.thickness);
    std::vector<std::string> written;
    for (const double thickness : thicknesses) {
        const auto fits = [&](const material::PartSpec& part) {
            return part.thickness == 0 || part.thickness == thickness;
        };
        if (std::none_of(problem.parts.begin(), problem.parts.end(), fits))
            continue;
        std::string file = path;
        if (thicknesses.size() > 1) {
            const std::filesystem::path p(path);
            file = (p.parent_path() /
                    (p.stem().string() + "-" + show(thickness) + "mm" + p.extension().string()))
                       .string();
        }
        writeText(file, [&](std::ostream& out) {
            out << "N," << quoteCsv(name + (thicknesses.size() > 1 ? " " + show(thickness) + " mm" : ""))
                << "\n";
            for (const material::MasterBoard& board : problem.boards)
                if (board.thickness == thickness) {
                    out << "M," << quoteCsv(board.material.empty() ? board.name : board.material) << "\n";
                    break;
                }
            out << "K," << problem.settings.kerf << "\n";
            for (const material::MasterBoard& board : problem.boards)
                if (board.thickness == thickness)
                    out << "S," << board.width << "," << board.height << ","
                        << (board.count < 0 ? std::string() : std::to_string(board.count)) << "\n";
            for (const material::PartSpec& part : problem.parts)
                if (fits(part)) {
                    const bool turns = std::find(part.orientations.begin(), part.orientations.end(), 90) !=
                                       part.orientations.end();
                    out << "P," << part.width() << "," << part.height() << "," << part.quantity << ","
                        << quoteCsv(part.id) << "," << (turns && !part.followsGrain ? "y" : "") << "\n";
                }
        });
        written.push_back(file);
    }
    return written;
}

std::vector<std::string> writeCutSheets(const material::Layout& layout, const material::PackProblem& problem,
                                        const std::string& svgFolder, const std::string& dxfFolder,
                                        const std::string& csvFile, const std::string& name,
                                        material::CutSheetOptions options)
{
    std::vector<std::string> written;
    if (!svgFolder.empty() || !dxfFolder.empty()) {
        const std::vector<material::CutSheet> sheets = material::cutSheets(layout, problem, options);
        for (const auto& [folder, extension] : {std::pair{svgFolder, "svg"}, std::pair{dxfFolder, "dxf"}})
            if (!folder.empty())
                for (const std::string& path : writeSheets(sheets, folder, extension, name))
                    written.push_back(path);
    }
    if (!csvFile.empty()) {
        writeCutList(material::cutList(layout, problem), csvFile);
        written.push_back(csvFile);
    }
    return written;
}

}  // namespace fabguide::io
