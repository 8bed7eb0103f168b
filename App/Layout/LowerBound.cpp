#include "Layout/LowerBound.h"

#include "Layout/Docking.h"
#include "Layout/MaxRects.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <utility>
#include <vector>

namespace fabguide::material {

namespace {

long roundedUp(double sheets)
{
    return static_cast<long>(std::ceil(sheets - 1e-9));
}

/// A part's poses that fit the usable sheet of its one board kind, and how many of it.
struct Fitting {
    int quantity = 0;
    std::vector<Pose> poses;
};

/// The sheets a set of parts needs by lines across one kind of sheet, the lines crossing `axis` (0: x), the
/// sheet `size` along x and y (usable, with the clearance): a part longer than half the sheet along the axis
/// takes its depth of the lines alone, and for each threshold p (no more than half that length), a part
/// longer than the length less p takes its depth, one of at least p its area over the length, since it shares
/// no line with the first kind. Each part counts in the pose that counts least, so the bound holds whichever
/// way the layout turns it.
long sheetsByLines(const std::vector<Fitting>& parts, int axis, const double size[2])
{
    const double length = size[axis], depth = size[1 - axis];
    const auto along = [&](const Pose& pose) { return axis == 0 ? pose.w : pose.h; };
    const auto across = [&](const Pose& pose) { return axis == 0 ? pose.h : pose.w; };
    const auto least = [&](const auto& taken) {
        double sum = 0;
        for (const Fitting& part : parts) {
            double fewest = taken(part.poses.front());
            for (const Pose& pose : part.poses)
                fewest = std::min(fewest, taken(pose));
            sum += fewest * part.quantity;
        }
        return roundedUp(sum / depth);
    };
    long sheets =
        least([&](const Pose& pose) { return along(pose) > length / 2 + kHair ? across(pose) : 0; });
    for (const Fitting& part : parts)
        for (const Pose& threshold : part.poses) {
            const double p = along(threshold);
            if (p > length / 2)
                continue;
            sheets = std::max(sheets, least([&](const Pose& pose) {
                                  if (along(pose) + p > length + kHair)
                                      return across(pose);
                                  return along(pose) >= p ? along(pose) * across(pose) / length : 0;
                              }));
        }
    return sheets;
}

/// sheetsByLines across either side of `board`, for the plain rectangles of `parts` (the others count by
/// area).
long sheetsByLines(const std::vector<PartSpec>& parts, const MasterBoard& board, const PackSettings& s)
{
    double size[2];
    std::tie(size[0], size[1]) = usableSize(board, s);
    std::vector<Fitting> fitting;
    for (const PartSpec& part : parts) {
        if (!rectangular(part))
            continue;
        Fitting f{part.quantity, {}};
        for (const Pose& pose : posesOn(part, board, s.kerf + s.spacing))
            if (pose.w <= size[0] + kHair && pose.h <= size[1] + kHair)
                f.poses.push_back(pose);
        if (!f.poses.empty())
            fitting.push_back(std::move(f));
    }
    if (fitting.empty())
        return 0;
    return std::max(sheetsByLines(fitting, 0, size), sheetsByLines(fitting, 1, size));
}

}  // namespace

long sheetsByArea(const PackProblem& problem)
{
    const double clearance = problem.settings.kerf + problem.settings.spacing;
    std::map<double, std::pair<double, double>> byThickness;  // thickness: (parts' area, largest board's)
    double anyArea = 0, largest = 0;
    for (const MasterBoard& board : problem.boards) {
        const auto [w, h] = usableSize(board, problem.settings);
        byThickness[board.thickness].second = std::max(byThickness[board.thickness].second, w * h);
        largest = std::max(largest, w * h);
    }
    for (const PartSpec& part : problem.parts) {
        const double area = (part.width() + clearance) * (part.height() + clearance) * part.quantity;
        if (part.thickness > 0 && byThickness.count(part.thickness))
            byThickness[part.thickness].first += area;
        else
            anyArea += area;
    }
    long sheets = 0;
    double all = anyArea;
    for (const auto& [thickness, areas] : byThickness) {
        sheets += roundedUp(areas.first / areas.second);
        all += areas.first;
    }
    return std::max(sheets, roundedUp(all / largest));
}

long sheetsBound(const PackProblem& problem)
{
    const long byArea = sheetsByArea(problem);
    std::map<double, std::vector<MasterBoard>> boards;  // by thickness
    for (const MasterBoard& board : problem.boards)
        boards[board.thickness].push_back(board);
    if (boards.count(0))  // a board of any thickness: a part may lie on it or on its own thickness's
        return byArea;
    long sheets = 0;
    for (const auto& stocked : boards) {
        const double thickness = stocked.first;
        const std::vector<MasterBoard>& kinds = stocked.second;
        PackProblem ofIt{kinds, {}, problem.settings, false};
        for (const PartSpec& part : problem.parts)  // of any thickness: on these when no others are stocked
            if (ofThickness(part.thickness, thickness) && (part.thickness > 0 || boards.size() == 1))
                ofIt.parts.push_back(part);
        const bool oneKind = std::all_of(kinds.begin(), kinds.end(), [&](const MasterBoard& b) {
            return b.width == kinds[0].width && b.height == kinds[0].height && b.grain == kinds[0].grain;
        });
        const long byLines = oneKind ? sheetsByLines(ofIt.parts, kinds[0], problem.settings) : 0;
        sheets += std::max(sheetsByArea(ofIt), byLines);
    }
    return std::max(byArea, sheets);
}

}  // namespace fabguide::material
