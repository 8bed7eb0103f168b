#include "Layout/LowerBound.h"

#include "Layout/Docking.h"
#include "Layout/MaxRects.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace fabguide::material {

namespace {

long roundedUp(double sheets)
{
    return static_cast<long>(std::ceil(sheets - 1e-9));
}

/// A part's poses that fit the usable `size` of its one board kind, as (length along the lines' axis, depth
/// across), and how many of it.
struct Lines {
    int quantity = 0;
    std::vector<std::pair<double, double>> poses;
};

/// The sheets a set of parts needs by lines across one kind of sheet `length` long and `depth` deep (both
/// usable, with the clearance): a part longer than half the length takes its depth of the lines alone, and
/// for each threshold p (no more than half the length), a part longer than the length less p takes its depth,
/// one of at least p its area over the length, since it shares no line with the first kind. Each part counts
/// in the pose that counts least, so the bound holds whichever way the layout turns it.
long sheetsByLines(const std::vector<Lines>& parts, double length, double depth)
{
    const auto least = [&](const auto& taken) {
        double sum = 0;
        for (const Lines& part : parts) {
            double fewest = taken(part.poses.front());
            for (const auto& pose : part.poses)
                fewest = std::min(fewest, taken(pose));
            sum += fewest * part.quantity;
        }
        return roundedUp(sum / depth);
    };
    long sheets = least([&](const auto& pose) { return pose.first > length / 2 + kHair ? pose.second : 0; });
    for (const Lines& part : parts)
        for (const auto& [p, unused] : part.poses) {
            if (p > length / 2)
                continue;
            sheets = std::max(sheets, least([&, p = p](const auto& pose) {
                                  if (pose.first + p > length + kHair)
                                      return pose.second;
                                  return pose.first >= p ? pose.first * pose.second / length : 0;
                              }));
        }
    return sheets;
}

/// sheetsByLines along either side of `board`, for the plain rectangles of `parts` (the others count by
/// area).
long sheetsByLines(const std::vector<PartSpec>& parts, const MasterBoard& board, const PackSettings& s)
{
    const auto [width, height] = usableSize(board, s);
    std::vector<Lines> alongX, alongY;
    for (const PartSpec& part : parts) {
        if (!rectangular(part))
            continue;
        Lines x{part.quantity, {}}, y{part.quantity, {}};
        for (const Pose& pose : posesOn(part, board, s.kerf + s.spacing))
            if (pose.w <= width + kHair && pose.h <= height + kHair) {
                x.poses.emplace_back(pose.w, pose.h);
                y.poses.emplace_back(pose.h, pose.w);
            }
        if (!x.poses.empty()) {
            alongX.push_back(std::move(x));
            alongY.push_back(std::move(y));
        }
    }
    if (alongX.empty())
        return 0;
    return std::max(sheetsByLines(alongX, width, height), sheetsByLines(alongY, height, width));
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
