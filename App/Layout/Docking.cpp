#include "Layout/Docking.h"

#include <algorithm>
#include <limits>
#include <tuple>

namespace fabguide::material {

Sheet::Sheet(int width, int height) : width_(width), height_(height), right_(height, 0), top_(width, 0) {}

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

Docker::Docker(const std::vector<BoardStock>& stock, Criterion criterion, Bounds bounds)
    : stock_(stock), criterion_(criterion), bounds_(bounds), left_(stock.size())
{
    std::transform(stock.begin(), stock.end(), left_.begin(), [](const BoardStock& b) { return b.count; });
}

Placed Docker::bestOn(int sheetIndex, const RasterPart& part) const
{
    // Every candidate adds the same part area, so least wastage = least bounding-rectangle area.
    using Score = std::tuple<long, long, int, int>;  // (bounding area, enclosed area, y, x)
    const Sheet& sheet = sheets_[sheetIndex];
    Score best{std::numeric_limits<long>::max(), 0, 0, 0};
    Placed choice{0, sheetIndex, 0, 0, -1};
    for (int s = 0; s < static_cast<int>(part.shapes.size()); ++s) {
        if (!allowedOn(part, s, stock_[layout_.stock[sheetIndex]]))
            continue;
        const Footprint& shape = part.shapes[s];
        sheet.forEachDockingPosition(shape, [&](Sheet::Position at) {
            Score score;
            if (criterion_ == Criterion::BottomLeft) {
                score = {0, 0, at.y, at.x};
            } else {
                const long w = bounds_ == Bounds::Strip ? sheet.width()
                                                        : std::max(sheet.usedWidth(), at.x + shape.width());
                const long h = std::max(sheet.usedHeight(), at.y + shape.height());
                score = {w * h, 0, at.y, at.x};
                if (score > best)
                    return;  // the enclosed area only breaks ties: skip computing it
                std::get<1>(score) = sheet.enclosedArea(shape, at);
            }
            if (score < best) {
                best = score;
                choice = {0, sheetIndex, at.x, at.y, s};
            }
        });
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
    --left_[cheapest];
    layout_.stock.push_back(cheapest);
    sheets_.emplace_back(stock_[cheapest].width, stock_[cheapest].height);
    return static_cast<int>(sheets_.size()) - 1;
}

void Docker::place(const std::vector<RasterPart>& parts, int index)
{
    const RasterPart& part = parts[index];
    Placed choice = bestPlace(part);
    if (choice.sheet < 0) {
        const int sheet = openSheet(part);
        if (sheet < 0) {
            layout_.unplaced.push_back(index);
            return;
        }
        choice = bestOn(sheet, part);
    }
    choice.part = index;
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
                const std::vector<BoardStock>& stock, Criterion criterion, Bounds bounds)
{
    Docker docker(stock, criterion, bounds);
    for (int index : order)
        docker.place(parts, index);
    return docker.layout();
}

}  // namespace fabguide::material
