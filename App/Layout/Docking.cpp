#include "Layout/Docking.h"

#include <algorithm>
#include <iterator>
#include <limits>
#include <tuple>

namespace fabguide::material {

namespace {

/// Adds `run` to the sorted, disjoint `runs`, merging it with those it touches.
void occupy(std::vector<std::pair<int, int>>& runs, std::pair<int, int> run)
{
    auto first = std::lower_bound(runs.begin(), runs.end(), run.first,
                                  [](const std::pair<int, int>& r, int y) { return r.second < y; });
    auto last = first;
    for (; last != runs.end() && last->first <= run.second; ++last)
        run = {std::min(run.first, last->first), std::max(run.second, last->second)};
    runs.insert(runs.erase(first, last), run);
}

}  // namespace

Sheet::Sheet(int width, int height, bool holes)
    : width_(width), height_(height), columns_(holes ? width : 0), right_(height, 0), top_(width, 0)
{
}

std::vector<Sheet::Run>::const_iterator Sheet::runAbove(int column, int y) const
{
    const std::vector<Run>& runs = columns_[column];
    return std::upper_bound(runs.begin(), runs.end(), y,
                            [](int v, const Run& run) { return v < run.second; });
}

int Sheet::lowestFit(const Footprint& part, int x) const
{
    // Raised past each run it meets until it meets none.
    int y = 0;
    for (bool raised = true; raised;) {
        raised = false;
        for (int c = 0; c < part.width(); ++c)
            for (const auto& [from, to] : part.runs(c)) {
                const auto run = runAbove(x + c, y + from);
                if (run != columns_[x + c].end() && run->first < y + to) {
                    y = run->second - from;
                    raised = true;
                }
            }
    }
    return y;
}

long Sheet::areaBelow(const Footprint& part, Position at) const
{
    long area = 0;
    for (int c = 0; c < part.width(); ++c)
        if (part.runs(c).begin() != part.runs(c).end()) {
            const int lowest = at.y + part.runs(c).begin()->first;
            const auto run = runAbove(at.x + c, lowest);
            area += lowest - (run == columns_[at.x + c].begin() ? 0 : std::prev(run)->second);
        }
    return area;
}

int Sheet::dropFromRight(const Footprint& part, int y) const
{
    int x = 0;
    for (int r = 0; r < part.height(); ++r)
        if (part.right()[r] > 0)
            x = std::max(x, right_[y + r] - part.left()[r]);
    return x;
}

int Sheet::dropFromTop(const Footprint& part, int x) const
{
    int y = 0;
    for (int c = 0; c < part.width(); ++c)
        if (part.top()[c] > 0)
            y = std::max(y, top_[x + c] - part.bottom()[c]);
    return y;
}

long Sheet::enclosedArea(const Footprint& part, Position at) const
{
    long grownRight = 0, grownTop = 0;
    for (int r = 0; r < part.height(); ++r)
        if (part.right()[r] > 0)
            grownRight += std::max(0, at.x + part.right()[r] - right_[at.y + r]);
    for (int c = 0; c < part.width(); ++c)
        if (part.top()[c] > 0)
            grownTop += std::max(0, at.y + part.top()[c] - top_[at.x + c]);
    return std::max(0L, grownRight - part.area()) + std::max(0L, grownTop - part.area());
}

void Sheet::place(const Footprint& part, Position at)
{
    for (int r = 0; r < part.height(); ++r)
        if (part.right()[r] > 0)
            right_[at.y + r] = std::max(right_[at.y + r], at.x + part.right()[r]);
    for (int c = 0; c < part.width(); ++c)
        if (part.top()[c] > 0 && at.y + part.top()[c] > top_[at.x + c]) {
            skylineArea_ += at.y + part.top()[c] - top_[at.x + c];
            top_[at.x + c] = at.y + part.top()[c];
        }
    if (!columns_.empty())
        for (int c = 0; c < part.width(); ++c)
            for (const auto& [from, to] : part.runs(c))
                occupy(columns_[at.x + c], {at.y + from, at.y + to});
    usedWidth_ = std::max(usedWidth_, at.x + part.width());
    usedHeight_ = std::max(usedHeight_, at.y + part.height());
}

namespace {

bool fitsOn(const RasterPart& part, const BoardStock& board)
{
    for (int s = 0; s < static_cast<int>(part.shapes.size()); ++s)
        if (allowedOn(part, s, board) && part.shapes[s].width() <= board.width &&
            part.shapes[s].height() <= board.height)
            return true;
    return false;
}

}  // namespace

bool allowedOn(const RasterPart& part, int shape, const BoardStock& board)
{
    return ofThickness(part.thickness, board.thickness) &&
           grainAllows(part.followsGrain, part.rotations[shape], board.grain);
}

Docker::Docker(const std::vector<BoardStock>& stock, Criterion criterion, Bounds bounds, Deadline deadline)
    : stock_(stock), criterion_(criterion), bounds_(bounds), deadline_(deadline), left_(stock.size())
{
    std::transform(stock.begin(), stock.end(), left_.begin(), [](const BoardStock& b) { return b.count; });
}

Placed Docker::bestOn(int sheetIndex, const RasterPart& part) const
{
    // Every candidate adds the same part area, so least wastage = least bounding-rectangle area.
    using Score = std::tuple<long, long, int, int>;  // (bounding area, enclosed area / area below, y, x)
    const Sheet& sheet = sheets_[sheetIndex];
    Score best{std::numeric_limits<long>::max(), 0, 0, 0};
    Placed choice{0, sheetIndex, 0, 0, -1};
    for (int s = 0; s < static_cast<int>(part.shapes.size()); ++s) {
        if (!allowedOn(part, s, stock_[layout_.stock[sheetIndex]]))
            continue;
        const Footprint& shape = part.shapes[s];
        const auto consider = [&](Sheet::Position at) {
            Score score;
            if (criterion_ == Criterion::BottomLeft) {
                score = {0, 0, at.y, at.x};
            } else {
                const long w = bounds_ == Bounds::Strip ? sheet.width()
                                                        : std::max(sheet.usedWidth(), at.x + shape.width());
                const long h = std::max(sheet.usedHeight(), at.y + shape.height());
                score = {w * h, 0, at.y, at.x};
                // The second term only breaks ties: computed for a candidate no worse than the best.
                if (criterion_ == Criterion::Docking && !(best < score))
                    std::get<1>(score) = sheet.enclosedArea(shape, at);
                else if (criterion_ == Criterion::SnugFill && !(best < score))
                    std::get<1>(score) = sheet.areaBelow(shape, at);
            }
            if (score < best) {
                best = score;
                choice = {0, sheetIndex, at.x, at.y, s};
            }
        };
        if (fills(criterion_))
            sheet.forEachFillPosition(shape, consider, deadline_);
        else
            sheet.forEachDockingPosition(shape, consider, deadline_);
    }
    return choice;
}

Placed Docker::bestPlace(const RasterPart& part) const
{
    for (int s = 0; s < static_cast<int>(sheets_.size()); ++s) {
        const Placed choice = bestOn(s, part);
        if (choice.shape >= 0)
            return choice;
    }
    const bool fits =
        std::any_of(stock_.begin(), stock_.end(), [&](const BoardStock& b) { return fitsOn(part, b); });
    return {0, -1, 0, 0, fits ? 0 : -1};
}

int Docker::openSheet(const RasterPart& part)
{
    bool fitsSomewhere = false;
    int cheapest = -1;  // of the boards left that it fits on, the first listed of the least cost
    for (size_t k = 0; k < stock_.size(); ++k) {
        if (!fitsOn(part, stock_[k]))
            continue;
        fitsSomewhere = true;
        if (left_[k] != 0 && (cheapest < 0 || stock_[k].cost < stock_[cheapest].cost))
            cheapest = static_cast<int>(k);
    }
    if (!fitsSomewhere)
        throw PackingError("part '" + part.name + "' is larger than every master board");
    if (cheapest < 0)
        return -1;
    open(cheapest);
    return static_cast<int>(sheets_.size()) - 1;
}

void Docker::open(int stock)
{
    --left_[stock];
    layout_.stock.push_back(stock);
    sheets_.emplace_back(stock_[stock].width, stock_[stock].height, fills(criterion_));
}

void Docker::place(const std::vector<RasterPart>& parts, int index)
{
    const RasterPart& part = parts[index];
    Placed choice = bestPlace(part);
    if (deadline_.passed()) {  // looked at in part only
        layout_.unplaced.push_back(index);
        layout_.finished = false;
        return;
    }
    if (choice.sheet < 0) {
        const int sheet = openSheet(part);
        if (sheet < 0) {
            layout_.unplaced.push_back(index);
            return;
        }
        choice = bestOn(sheet, part);
    }
    choice.part = index;
    commit(parts[index], choice);
}

void Docker::replay(const std::vector<RasterPart>& parts, const Placed& placed, int stock)
{
    if (placed.sheet == static_cast<int>(sheets_.size()))
        open(stock);
    commit(parts[placed.part], placed);
}

void Docker::commit(const RasterPart& part, const Placed& choice)
{
    sheets_[choice.sheet].place(part.shapes[choice.shape], {choice.x, choice.y});
    layout_.placed.push_back(choice);
    const Sheet& sheet = sheets_[choice.sheet];
    layout_.usedWidth.resize(sheets_.size());
    layout_.usedHeight.resize(sheets_.size());
    layout_.skylineArea.resize(sheets_.size());
    layout_.usedWidth[choice.sheet] = sheet.usedWidth();
    layout_.usedHeight[choice.sheet] = sheet.usedHeight();
    layout_.skylineArea[choice.sheet] = sheet.skylineArea();
}

GridLayout dock(const std::vector<RasterPart>& parts, const std::vector<int>& order,
                const std::vector<BoardStock>& stock, Criterion criterion, Bounds bounds,
                const GridLayout* before, size_t same, Deadline deadline)
{
    Docker docker(stock, criterion, bounds, deadline);
    size_t k = 0;
    if (before)
        for (; k < same && k < before->placed.size() && before->placed[k].part == order[k]; ++k)
            docker.replay(parts, before->placed[k], before->stock[before->placed[k].sheet]);
    for (; k < order.size() && !deadline.passed(); ++k)
        docker.place(parts, order[k]);
    GridLayout layout = docker.layout();
    layout.finished = layout.finished && k == order.size();
    layout.unplaced.insert(layout.unplaced.end(), order.begin() + static_cast<long>(k), order.end());
    return layout;
}

}  // namespace fabguide::material
