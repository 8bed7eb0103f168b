#include "Layout/CutSheet.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace fabguide::material {

namespace {

/// A part's label (issue 16): at the point of its material farthest from its edges and holes, along its
/// longer side, as large as fits the circle free there (a text n characters long is about 0.6 n of its
/// height wide) between 2 and 12 mm.
Label labelOf(const std::string& text, const geometry::Outline& placed, const Placement& p)
{
    const auto [at, room] = geometry::deepestPoint(placed);
    const double n = static_cast<double>(std::max<size_t>(text.size(), 1));
    const double fits = room / std::sqrt(0.09 * n * n + 0.25);  // half-diagonal of the text box = room
    return {text, at, std::clamp(fits, 2.0, 12.0), p.height > p.width ? 90.0 : 0.0};
}

}  // namespace

geometry::Outline placedOutline(const Layout& layout, const PackProblem& problem, size_t k)
{
    const Placement& p = layout.placements[k];
    return geometry::placed(problem.parts[p.part].outline, p.rotation, p.x, p.y);
}

std::vector<CutSheet> cutSheets(const Layout& layout, const PackProblem& problem)
{
    const PackSettings& s = problem.settings;
    const size_t n = layout.placements.size();
    std::vector<geometry::Outline> placed;
    for (size_t k = 0; k < n; ++k)
        placed.push_back(placedOutline(layout, problem, k));
    // Part-in-hole: how many holes of other parts hold each part, and which holes hold one.
    std::vector<int> depth(n);
    std::vector<std::vector<bool>> holding(n);
    for (size_t j = 0; j < n; ++j) {
        holding[j].assign(placed[j].holes.size(), false);
        for (size_t h = 0; h < placed[j].holes.size(); ++h)
            for (size_t k = 0; k < n; ++k)
                if (k != j && layout.placements[k].sheet == layout.placements[j].sheet &&
                    geometry::contains(placed[j].holes[h], placed[k].outer.front())) {
                    holding[j][h] = true;
                    ++depth[k];
                }
    }
    const int deepest = n ? *std::max_element(depth.begin(), depth.end()) : 0;
    std::vector<CutSheet> sheets;
    for (const MasterBoard& board : layout.sheets)
        sheets.push_back({board, {}, {}, {}, {}, {}});
    // Inner cuts first: a part never drops out before its holes are cut, and a part in another's hole is cut
    // before that hole (deepest first). With holding tabs, a hole that holds a part is tabbed too, so the
    // ring round the part stays in the sheet until the part is cut.
    for (int level = deepest; level >= 0; --level) {
        std::vector<std::vector<geometry::Polygon>> outers(sheets.size());
        for (size_t k = 0; k < n; ++k) {
            if (depth[k] != level)
                continue;
            const Placement& p = layout.placements[k];
            const PartSpec& spec = problem.parts[p.part];
            const geometry::Outline path = geometry::offset(
                s.dogbone > 0 ? geometry::dogboned(placed[k], s.dogbone) : placed[k], s.kerf / 2);
            CutSheet& sheet = sheets[p.sheet];
            const bool tabs = s.tabWidth > 0 && std::max(p.width, p.height) < s.tabBelow;
            for (size_t h = 0; h < path.holes.size(); ++h) {
                if (s.tabWidth > 0 && h < holding[k].size() && holding[k][h]) {
                    const std::vector<geometry::Polygon> pieces =
                        geometry::withTabs(path.holes[h], 2, s.tabWidth);
                    sheet.tabbed.insert(sheet.tabbed.end(), pieces.begin(), pieces.end());
                } else {
                    sheet.cuts.push_back(path.holes[h]);
                }
            }
            if (tabs) {
                const std::vector<geometry::Polygon> pieces = geometry::withTabs(path.outer, 2, s.tabWidth);
                sheet.tabbed.insert(sheet.tabbed.end(), pieces.begin(), pieces.end());
            } else {
                outers[p.sheet].push_back(path.outer);
            }
            sheet.labels.push_back(labelOf(spec.id, placed[k], p));
            const geometry::Placement2 move = geometry::placement(spec.outline, p.rotation, p.x, p.y);
            for (const Drill& drill : spec.drills)
                sheet.drills.push_back({move(drill.at), drill.diameter, drill.depth});
            for (const geometry::Polygon& mark : spec.marks) {
                sheet.engraved.emplace_back();
                for (const geometry::Point2& q : mark)
                    sheet.engraved.back().push_back(move(q));
            }
        }
        for (size_t i = 0; i < sheets.size(); ++i)
            sheets[i].cuts.insert(sheets[i].cuts.end(), outers[i].begin(), outers[i].end());
    }
    return sheets;
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
        rows.push_back(
            {spec.id, quantity, spec.width(), spec.height(), board.thickness, board.material, key.second});
    }
    return rows;
}

}  // namespace fabguide::material
