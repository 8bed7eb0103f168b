#include "IO/Report.h"

#include "IO/Json.h"
#include "IO/Output.h"
#include "IO/PackFormat.h"

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <memory>

namespace fabguide::io {

namespace {

constexpr double kPoint = 72 / 25.4;          // points per mm
constexpr double kPageW = 297, kPageH = 210;  // A4 landscape, mm
constexpr double kMargin = 12, kRow = 6.5;    // mm
constexpr int kRowsPerPage = 24;              // of the cut list

/// A number of millimetres as the shop reads it: to 0.1 mm, no trailing zeros.
std::string mm(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", value);
    std::string s = text;
    if (s.size() > 2 && s.compare(s.size() - 2, 2, ".0") == 0)
        s.resize(s.size() - 2);
    return s;
}

std::string metres(double millimetres)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.2f m", millimetres / 1000);
    return text;
}

std::string squareMetres(double squareMillimetres)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.2f m2", squareMillimetres / 1e6);
    return text;
}

void font(cairo_t* cr, double size, bool bold = false)
{
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                           bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, size);
}

double widthOf(cairo_t* cr, const std::string& text)
{
    cairo_text_extents_t extents;
    cairo_text_extents(cr, text.c_str(), &extents);
    return extents.x_advance;
}

/// Text with its baseline at y; `anchor` 0 puts its start at x, 0.5 its middle, 1 its end. In SVG as
/// outlines, which any SVG reader shows (TechDraw's does not read the glyph symbols of cairo's SVG text); in
/// PDF as text.
void text(cairo_t* cr, const std::string& s, double x, double y, double anchor = 0)
{
    cairo_move_to(cr, x - anchor * widthOf(cr, s), y);
    if (cairo_surface_get_type(cairo_get_target(cr)) == CAIRO_SURFACE_TYPE_SVG) {
        cairo_text_path(cr, s.c_str());
        cairo_fill(cr);
    } else {
        cairo_show_text(cr, s.c_str());
    }
}

void colour(cairo_t* cr, unsigned rgb, double alpha = 1)
{
    cairo_set_source_rgba(cr, (rgb >> 16 & 255) / 255.0, (rgb >> 8 & 255) / 255.0, (rgb & 255) / 255.0,
                          alpha);
}

void arrow(cairo_t* cr, double x0, double y0, double x1, double y1)
{
    const double angle = std::atan2(y1 - y0, x1 - x0), head = 2.5;
    cairo_move_to(cr, x0, y0);
    cairo_line_to(cr, x1, y1);
    for (const double turn : {2.6, -2.6}) {
        cairo_move_to(cr, x1, y1);
        cairo_line_to(cr, x1 + head * std::cos(angle + turn), y1 + head * std::sin(angle + turn));
    }
    cairo_stroke(cr);
}

/// Pages drawn one after another; `next()` gives the cairo context of a new page, in mm.
using NextPage = std::function<cairo_t*()>;

/// Sheet k: the parts as placed, numbered, with their sizes; holes, drills, banding, saw cuts.
void drawSheet(cairo_t* cr, const material::Layout& layout, const material::PackProblem& problem,
               const material::CutSheet& sheet, size_t k, const std::string& title)
{
    const material::MasterBoard& board = sheet.board;
    font(cr, 5, true);
    colour(cr, 0x000000);
    text(cr, title + " - sheet " + std::to_string(k + 1) + " of " + std::to_string(layout.sheets.size()),
         kMargin, kMargin + 4);
    font(cr, 3.5);
    text(cr,
         (board.material.empty() ? board.name : board.material) + ", " + mm(board.width) + " x " +
             mm(board.height) + " x " + mm(board.thickness) + " mm",
         kMargin, kMargin + 10);
    const double top = kMargin + 16, areaW = kPageW - 2 * kMargin, areaH = kPageH - top - kMargin - 8;
    const double scale = std::min(areaW / board.width, areaH / board.height);
    const double left = kMargin, bottom = top + board.height * scale;
    const auto at = [&](const geometry::Point2& p) {
        return std::pair{left + p.x * scale, bottom - p.y * scale};
    };
    const auto path = [&](const geometry::Polygon& polygon) {
        for (size_t i = 0; i < polygon.size(); ++i) {
            const auto [x, y] = at(polygon[i]);
            i ? cairo_line_to(cr, x, y) : cairo_move_to(cr, x, y);
        }
        cairo_close_path(cr);
    };
    cairo_set_line_width(cr, 0.3);
    cairo_rectangle(cr, left, top, board.width * scale, board.height * scale);
    colour(cr, 0xf4ead5);
    cairo_fill_preserve(cr);
    colour(cr, 0x888888);
    cairo_stroke(cr);
    cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);
    for (size_t n = 0; n < layout.placements.size(); ++n) {
        if (layout.placements[n].sheet != static_cast<int>(k))
            continue;
        const geometry::Outline outline = material::placedOutline(layout, problem, n);
        path(outline.outer);
        for (const geometry::Polygon& hole : outline.holes)
            path(hole);
        colour(cr, 0xd9b77e);
        cairo_fill_preserve(cr);
        colour(cr, 0x000000);
        cairo_stroke(cr);
    }
    for (const material::Drill& drill : sheet.drills) {
        const auto [x, y] = at(drill.at);
        cairo_arc(cr, x, y, std::max(0.4, drill.diameter / 2 * scale), 0, 2 * M_PI);
        cairo_stroke(cr);
    }
    cairo_set_line_width(cr, 1.2);
    colour(cr, 0xa0522d, 0.8);
    for (const material::Banding& band : sheet.banding) {
        const auto [x0, y0] = at(band.from);
        const auto [x1, y1] = at(band.to);
        cairo_move_to(cr, x0, y0);
        cairo_line_to(cr, x1, y1);
        cairo_stroke(cr);
    }
    font(cr, 2.5, true);
    const double dash[] = {2, 1};
    for (const material::SawCut& c : sheet.sawCuts) {  // in their order, numbered
        const auto [x0, y0] = at(c.from);
        const auto [x1, y1] = at(c.to);
        colour(cr, 0xff8000);
        cairo_set_line_width(cr, 0.35);
        cairo_set_dash(cr, dash, 2, 0);
        cairo_move_to(cr, x0, y0);
        cairo_line_to(cr, x1, y1);
        cairo_stroke(cr);
        cairo_set_dash(cr, nullptr, 0, 0);
        text(cr, c.number, (x0 + x1) / 2 + 0.6, (y0 + y1) / 2 - 0.6);
    }
    for (const material::Label& label : sheet.labels) {  // number and size where the part's label goes
        const material::Placement& p = layout.placements[label.placement];
        const material::PartSpec& spec = problem.parts[p.part];
        const auto [x, y] = at(label.at);
        const double size = std::clamp(std::min(p.width, p.height) * scale / 4, 1.2, 4.0);
        colour(cr, 0x000000);
        font(cr, size, true);
        text(cr, std::to_string(p.part + 1), x, y, 0.5);
        font(cr, size * 0.7);
        text(cr, mm(spec.width()) + " x " + mm(spec.height()), x, y + size, 0.5);
    }
    colour(cr, 0x000000);
    font(cr, 3);
    const double footer = kPageH - kMargin + 2;
    std::string legend = "Parts numbered as in the cut list; sizes length x width in mm.";
    if (!sheet.banding.empty())
        legend += " Brown: edge banding.";
    if (!sheet.sawCuts.empty())
        legend += " Orange: saw cuts in their order (" + std::to_string(sheet.sawCuts.size()) + ").";
    text(cr, legend, kMargin, footer);
    if (board.grain != material::Grain::None) {  // the sheet's grain, beside the legend
        cairo_set_line_width(cr, 0.4);
        const double x = kPageW - kMargin - 30, y = footer - 1;
        text(cr, "grain", x - 10, footer);
        board.grain == material::Grain::AlongWidth ? arrow(cr, x, y, x + 20, y)
                                                   : arrow(cr, x + 10, y + 3, x + 10, y - 9);
    }
}

/// The cut list, kRowsPerPage rows a page, then the totals.
void drawCutList(const NextPage& next, const material::Layout& layout, const material::PackProblem& problem,
                 const std::string& title)
{
    const std::vector<material::CutListRow> rows = material::cutList(layout, problem);
    const std::vector<std::pair<std::string, double>> columns = {
        {"No.", 12},    {"Part", 52},     {"Qty", 12},   {"Length", 18}, {"Width", 18},
        {"Thick.", 14}, {"Material", 40}, {"Sheet", 13}, {"Grain", 13},  {"L1", 20},
        {"L2", 20},     {"W1", 20},       {"W2", 20}};
    const auto fit = [&](cairo_t* cr, std::string s, double width) {
        while (s.size() > 1 && widthOf(cr, s) > width - 1.5)
            s = s.substr(0, s.size() - 2) + "~";
        return s;
    };
    const size_t pages = std::max<size_t>(1, (rows.size() + kRowsPerPage - 1) / kRowsPerPage);
    cairo_t* cr = nullptr;
    double y = 0;
    for (size_t page = 0; page < pages; ++page) {
        cr = next();
        colour(cr, 0x000000);
        font(cr, 5, true);
        text(cr,
             title + " - cut list" +
                 (pages > 1 ? " (" + std::to_string(page + 1) + "/" + std::to_string(pages) + ")" : ""),
             kMargin, kMargin + 4);
        font(cr, 3, true);
        y = kMargin + 14;
        double x = kMargin;
        for (const auto& [name, width] : columns)
            text(cr, name, x, y), x += width;
        cairo_set_line_width(cr, 0.3);
        cairo_move_to(cr, kMargin, y + 1.5);
        cairo_line_to(cr, x, y + 1.5);
        cairo_stroke(cr);
        font(cr, 3);
        for (size_t r = page * kRowsPerPage; r < std::min(rows.size(), (page + 1) * kRowsPerPage); ++r) {
            const material::CutListRow& row = rows[r];
            y += kRow;
            std::vector<std::string> cells = {std::to_string(row.index + 1),
                                              row.part,
                                              std::to_string(row.quantity),
                                              mm(row.width),
                                              mm(row.height),
                                              mm(row.thickness),
                                              row.material,
                                              std::to_string(row.board + 1),
                                              row.grain ? "length" : ""};
            cells.insert(cells.end(), row.edgeBanding.begin(), row.edgeBanding.end());
            x = kMargin;
            for (size_t c = 0; c < columns.size(); ++c)
                text(cr, fit(cr, cells[c], columns[c].second), x, y), x += columns[c].second;
        }
    }
    const material::Totals t = material::totals(layout, problem);
    std::vector<std::pair<std::string, std::string>> lines = {
        {"Sheets", std::to_string(t.sheets) + " (" + std::to_string(t.parts) + " parts)"},
        {"Sheet area", squareMetres(t.sheetArea)},
        {"Part area", squareMetres(t.partArea)},
        {"Waste", squareMetres(t.sheetArea - t.partArea) + " (" +
                      mm(t.sheetArea > 0 ? 100 * (t.sheetArea - t.partArea) / t.sheetArea : 0) + " %)"},
        {layout.sawCuts.empty() ? "Cut length" : "Saw cut length",
         metres(t.cutLength) +
             (t.commonLine > 0 ? " (" + metres(t.commonLine) + " of it shared by two parts, cut once)" : "")},
        {"Cost", mm(t.cost) + " (master board costs)"}};
    for (const auto& [band, length] : t.banding)
        lines.push_back({"Edge banding " + band, metres(length)});
    if (y + (lines.size() + 2) * 5 > kPageH - kMargin)
        cr = next(), y = kMargin;
    y += 12;
    font(cr, 4, true);
    text(cr, "Totals", kMargin, y);
    for (const auto& [name, value] : lines) {
        y += 5;
        font(cr, 3.2, true);
        text(cr, name, kMargin, y);
        font(cr, 3.2);
        text(cr, value, kMargin + 75, y);
    }
}

void drawReport(const NextPage& next, const material::Layout& layout, const material::PackProblem& problem,
                const std::string& title)
{
    const std::vector<material::CutSheet> sheets = material::cutSheets(layout, problem, {true, true});
    for (size_t k = 0; k < sheets.size(); ++k)
        drawSheet(next(), layout, problem, sheets[k], k, title);
    drawCutList(next, layout, problem, title);
}

cairo_status_t append(void* closure, const unsigned char* data, unsigned int length)
{
    static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
    return CAIRO_STATUS_SUCCESS;
}

/// A PDF of pages `width` x `height` mm drawn by `draw`, written whole to `path` or not at all.
void writePdf(const std::string& path, double width, double height,
              const std::function<void(const NextPage&)>& draw)
{
    std::string bytes;
    cairo_surface_t* surface =
        cairo_pdf_surface_create_for_stream(append, &bytes, width * kPoint, height * kPoint);
    cairo_t* cr = cairo_create(surface);
    bool started = false;
    draw([&] {
        if (started)
            cairo_show_page(cr);
        started = true;
        cairo_identity_matrix(cr);
        cairo_scale(cr, kPoint, kPoint);
        return cr;
    });
    cairo_destroy(cr);
    cairo_surface_finish(surface);
    const cairo_status_t status = cairo_surface_status(surface);
    cairo_surface_destroy(surface);
    if (status != CAIRO_STATUS_SUCCESS)
        throw FormatError(path + ": cannot draw the PDF (" + cairo_status_to_string(status) + ")");
    writeAtomically(path, [&](const std::string& temporary) {
        std::ofstream out(temporary, std::ios::binary);
        out << bytes;
        if (!out.flush())
            throw FormatError(path + ": cannot write file");
    });
}

/// Cairo gives the page's size in points; TechDraw reads it in millimetres (the viewBox stays).
std::string inMillimetres(std::string svg)
{
    for (const auto& [attribute, size] : {std::pair{"width=\"", kPageW}, std::pair{"height=\"", kPageH}}) {
        const size_t start = svg.find(attribute), end = svg.find('"', start + std::string(attribute).size());
        if (start != std::string::npos && end != std::string::npos)
            svg.replace(start, end + 1 - start, attribute + mm(size) + "mm\"");
    }
    return svg;
}

}  // namespace

void writeReport(const material::Layout& layout, const material::PackProblem& problem,
                 const std::string& title, const std::string& path)
{
    writePdf(path, kPageW, kPageH, [&](const NextPage& next) { drawReport(next, layout, problem, title); });
}

std::vector<std::string> reportSvgs(const material::Layout& layout, const material::PackProblem& problem,
                                    const std::string& title)
{
    std::vector<std::unique_ptr<std::string>> texts;
    std::vector<std::pair<cairo_surface_t*, cairo_t*>> pages;
    drawReport(
        [&] {
            texts.push_back(std::make_unique<std::string>());
            cairo_surface_t* surface = cairo_svg_surface_create_for_stream(append, texts.back().get(),
                                                                           kPageW * kPoint, kPageH * kPoint);
            pages.emplace_back(surface, cairo_create(surface));
            cairo_scale(pages.back().second, kPoint, kPoint);
            return pages.back().second;
        },
        layout, problem, title);
    std::vector<std::string> result;
    for (size_t k = 0; k < pages.size(); ++k) {
        cairo_destroy(pages[k].second);
        cairo_surface_finish(pages[k].first);
        cairo_surface_destroy(pages[k].first);
        result.push_back(inMillimetres(*texts[k]));
    }
    return result;
}

void writeLabels(const material::Layout& layout, const material::PackProblem& problem,
                 const std::string& path, double width, double height)
{
    if (!(width >= 20 && height >= 10 && width <= 300 && height <= 300))
        throw FormatError("label size " + mm(width) + " x " + mm(height) +
                          " mm: labels are 20 x 10 mm to 300 x 300 mm");
    writePdf(path, width, height, [&](const NextPage& next) {
        const double margin = std::min(2.0, height / 10), line = (height - 2 * margin) / 4.6;
        for (const material::Placement& p : layout.placements) {
            const material::PartSpec& spec = problem.parts[p.part];
            const material::MasterBoard& board = layout.sheets[p.sheet];
            std::string edges;
            for (size_t side = 0; side < 4; ++side)
                if (!spec.edgeBanding[side].empty())
                    edges += (edges.empty() ? "edges " : " ") + sideNames()[side];
            const std::vector<std::pair<std::string, bool>> lines = {
                {std::to_string(p.part + 1) + "  " + spec.id, true},
                {mm(spec.width()) + " x " + mm(spec.height()) + " x " + mm(board.thickness) + " mm", false},
                {(board.material.empty() ? board.name : board.material) + ", sheet " +
                     std::to_string(p.sheet + 1),
                 false},
                {edges + (spec.followsGrain && board.grain != material::Grain::None
                              ? std::string(edges.empty() ? "" : ", ") + "grain along the length"
                              : ""),
                 false}};
            cairo_t* cr = next();
            double y = margin;
            for (const auto& [s, bold] : lines) {
                const double size = bold ? line * 1.25 : line;
                font(cr, size, bold);
                const double shrink = std::min(1.0, (width - 2 * margin) / std::max(1e-9, widthOf(cr, s)));
                font(cr, size * shrink, bold);
                y += size;
                text(cr, s, margin, y);
                y += line * 0.15;
            }
        }
    });
}

}  // namespace fabguide::io
