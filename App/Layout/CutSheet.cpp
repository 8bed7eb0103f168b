#include "Layout/CutSheet.h"

#include "Layout/CommonLine.h"
#include "Layout/Lettering.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace fabguide::material {

namespace {

/// The text a label can carry: an id of more than 60 bytes is cut (at a character, not inside one) and ends
/// in "..." (a 1 MB id drawn in strokes took 41 s and a DXF of hundreds of MB).
std::string labelText(const std::string& id)
{
    constexpr size_t kLongest = 60;
    if (id.size() <= kLongest)
        return id;
    size_t cut = kLongest - 3;
    while (cut > 0 && (static_cast<unsigned char>(id[cut]) & 0xC0) == 0x80)  // inside a UTF-8 character
        --cut;
    return id.substr(0, cut) + "...";
}

/// A part's label: at the point of its material farthest from its edges and holes, along its
/// longer side (a freely turned part's own, kept within a quarter turn of upright), as large as fits the
/// circle free there (a text n characters long is about 0.6 n of its height wide) between 2 and 12 mm.
Label labelOf(const PartSpec& spec, const geometry::Outline& placed, const Placement& p, size_t k)
{
    const auto [at, room] = geometry::deepestPoint(placed);
    const std::string text = labelText(spec.id);
    const double n = static_cast<double>(std::max<size_t>(text.size(), 1));
    const double fits = room / std::sqrt(0.09 * n * n + 0.25);  // half-diagonal of the text box = room
    double angle = p.height > p.width ? 90.0 : 0.0;
    if (p.rotation % 90 != 0) {
        angle = std::fmod(p.rotation + (spec.height() > spec.width() ? 90.0 : 0.0), 180.0);
        if (angle > 90)
            angle -= 180;
    }
    return {text, at, std::clamp(fits, 2.0, 12.0), angle, k};
}

}  // namespace

geometry::Outline placedOutline(const Layout& layout, const PackProblem& problem, size_t k)
{
    const Placement& p = layout.placements[k];
    return geometry::placed(problem.parts[p.part].outline, p.rotation, p.x, p.y);
}

std::pair<geometry::Point2, geometry::Point2> placedSide(const Layout& layout, const PackProblem& problem,
                                                         size_t k, Side side)
{
    const Placement& p = layout.placements[k];
    const PartSpec& spec = problem.parts[p.part];
    const double w = spec.width(), h = spec.height();
    const geometry::Placement2 move = geometry::placement(spec.outline, p.rotation, p.x, p.y);
    switch (side) {
        case Side::L1:
            return {move({0, 0}), move({w, 0})};
        case Side::L2:
            return {move({0, h}), move({w, h})};
        case Side::W1:
            return {move({0, 0}), move({0, h})};
        default:
            return {move({w, 0}), move({w, h})};
    }
}

double sideLength(const PartSpec& part, Side side)
{
    return side == Side::L1 || side == Side::L2 ? part.width() : part.height();
}

std::vector<CutSheet> cutSheets(const Layout& layout, const PackProblem& problem, CutSheetOptions options)
{
    const PackSettings& s = problem.settings;
    const size_t n = layout.placements.size();
    std::vector<geometry::Outline> placed;
    for (size_t k = 0; k < n; ++k)
        placed.push_back(placedOutline(layout, problem, k));
    // Part-in-hole: a polygon on a sheet holds the parts whose outline starts inside it; a part's depth is
    // how many holes of other parts hold it.
    const auto holds = [&](int sheet, const geometry::Polygon& polygon, size_t k) {
        return layout.placements[k].sheet == sheet && geometry::contains(polygon, placed[k].outer.front());
    };
    std::vector<int> depth(n);
    for (size_t j = 0; j < n; ++j)
        for (const geometry::Polygon& hole : placed[j].holes)
            for (size_t k = 0; k < n; ++k)
                depth[k] += k != j && holds(layout.placements[j].sheet, hole, k);
    const int deepest = n ? *std::max_element(depth.begin(), depth.end()) : 0;
    std::vector<CutSheet> sheets;
    for (size_t k = 0; k < layout.sheets.size(); ++k)
        sheets.emplace_back().board = layout.sheets[k];
    for (size_t k = 0; k < layout.sawCuts.size() && k < sheets.size(); ++k)
        sheets[k].sawCuts = layout.sawCuts[k];
    std::vector<std::vector<ToolPath>> last(sheets.size());  // the tabbed paths, cut after the rest
    // Inner cuts first: a part never drops out before its holes are cut, and a part in another's hole is cut
    // before that hole (deepest first). With holding tabs, a hole that holds a part is tabbed too, so the
    // ring round the part stays in the sheet until the part is cut.
    const auto add = [&](size_t k, const geometry::Polygon& contour, bool hole, bool inner, bool tabbed,
                         std::vector<ToolPath>& closed) {
        const int sheet = layout.placements[k].sheet;
        if (!tabbed)
            closed.push_back({contour, inner, false, false, hole, k});
        else if (options.asDesigned) {
            closed.push_back({contour, inner, false, true, hole, k});
            const auto gaps = geometry::tabGaps(contour, 2, s.tabWidth);
            sheets[sheet].tabs.insert(sheets[sheet].tabs.end(), gaps.begin(), gaps.end());
        } else {
            for (const geometry::Polygon& piece : geometry::withTabs(contour, 2, s.tabWidth))
                last[sheet].push_back({piece, inner, true, true, hole, k});
        }
    };
    for (int level = deepest; level >= 0; --level) {
        std::vector<std::vector<ToolPath>> outers(sheets.size());
        for (size_t k = 0; k < n; ++k) {
            if (depth[k] != level)
                continue;
            const Placement& p = layout.placements[k];
            const PartSpec& spec = problem.parts[p.part];
            const geometry::Outline path =
                options.asDesigned
                    ? placed[k]
                    : geometry::offset(s.dogbone > 0 ? geometry::dogboned(placed[k], s.dogbone) : placed[k],
                                       s.kerf / 2);
            CutSheet& sheet = sheets[p.sheet];
            for (const geometry::Polygon& hole : path.holes) {
                bool holding = false;  // a hole holding a part (kerf + spacing inside the cut)
                for (size_t other = 0; other < n && !holding; ++other)
                    holding = other != k && holds(p.sheet, hole, other);
                add(k, hole, true, !holding, holding && s.tabWidth > 0, sheet.cuts);
            }
            add(k, path.outer, false, false, s.tabWidth > 0 && std::max(p.width, p.height) < s.tabBelow,
                outers[p.sheet]);
            sheet.labels.push_back(labelOf(spec, placed[k], p, k));
            if (!options.textLabels)
                sheet.lettering.push_back(strokes(sheet.labels.back()));
            const geometry::Placement2 move = geometry::placement(spec.outline, p.rotation, p.x, p.y);
            for (const Drill& drill : spec.drills)
                sheet.drills.push_back({move(drill.at), drill.diameter, drill.depth});
            for (const Side side : kSides)
                if (const std::string& band = spec.edgeBanding[static_cast<int>(side)]; !band.empty()) {
                    const auto [from, to] = placedSide(layout, problem, k, side);
                    sheet.banding.push_back({from, to, band});
                }
            for (const geometry::Polygon& mark : spec.marks) {
                sheet.engraved.emplace_back();
                for (const geometry::Point2& q : mark)
                    sheet.engraved.back().push_back(move(q));
            }
        }
        for (size_t i = 0; i < sheets.size(); ++i) {  // small parts first: they stay flat while the sheet
            std::stable_sort(outers[i].begin(), outers[i].end(),  // around them is still whole
                             [&](const ToolPath& a, const ToolPath& b) {
                                 return geometry::area(placed[a.placement]) <
                                        geometry::area(placed[b.placement]);
                             });
            sheets[i].cuts.insert(sheets[i].cuts.end(), outers[i].begin(), outers[i].end());
        }
    }
    for (size_t i = 0; i < sheets.size(); ++i) {
        if (s.commonLine && !options.asDesigned)
            sheets[i].commonLine = cutCommonLinesOnce(sheets[i].cuts);
        sheets[i].cuts.insert(sheets[i].cuts.end(), last[i].begin(), last[i].end());
    }
    return sheets;
}

Totals totals(const Layout& layout, const PackProblem& problem)
{
    Totals t;
    t.sheets = static_cast<int>(layout.sheets.size());
    t.parts = static_cast<int>(layout.placements.size());
    for (const MasterBoard& sheet : layout.sheets)
        t.sheetArea += sheet.width * sheet.height, t.cost += sheet.cost;
    std::map<std::string, double> banding;
    for (const Placement& p : layout.placements) {
        const PartSpec& spec = problem.parts[p.part];
        t.partArea += geometry::area(spec.outline);
        if (layout.sawCuts.empty()) {
            t.cutLength += geometry::perimeter(spec.outline.outer);
            for (const geometry::Polygon& hole : spec.outline.holes)
                t.cutLength += geometry::perimeter(hole);
        }
        for (const Side side : kSides)
            if (const std::string& band = spec.edgeBanding[static_cast<int>(side)]; !band.empty())
                banding[band] += sideLength(spec, side);
    }
    for (const std::vector<SawCut>& sheet : layout.sawCuts)
        for (const SawCut& c : sheet)
            t.cutLength += c.length();
    if (problem.settings.commonLine && layout.sawCuts.empty())
        for (const CutSheet& sheet : cutSheets(layout, problem, {false, true}))
            t.commonLine += sheet.commonLine;
    t.cutLength -= t.commonLine;
    t.banding.assign(banding.begin(), banding.end());
    return t;
}

std::vector<CutListRow> cutList(const Layout& layout, const PackProblem& problem)
{
    std::map<std::pair<int, int>, int> count;  // (part, sheet) -> quantity
    for (const Placement& p : layout.placements)
        ++count[{p.part, p.sheet}];
    std::vector<CutListRow> rows;
    for (const auto& [key, quantity] : count) {
        const PartSpec& spec = problem.parts[key.first];
        const MasterBoard& board = layout.sheets[key.second];
        rows.push_back({spec.id, quantity, spec.width(), spec.height(), board.thickness, board.material,
                        key.second, spec.followsGrain && board.grain != Grain::None, spec.edgeBanding,
                        key.first});
    }
    return rows;
}

}  // namespace fabguide::material
