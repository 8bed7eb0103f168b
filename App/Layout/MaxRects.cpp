#include "Layout/MaxRects.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <tuple>

namespace fabguide::material {

namespace {

struct Rect {
    double x = 0, y = 0, w = 0, h = 0;
    bool contains(const Rect& o) const
    {
        return o.x >= x - kHair && o.y >= y - kHair && o.x + o.w <= x + w + kHair &&
               o.y + o.h <= y + h + kHair;
    }
    bool overlaps(const Rect& o) const
    {
        return o.x < x + w - kHair && x < o.x + o.w - kHair && o.y < y + h - kHair && y < o.y + o.h - kHair;
    }
};

/// An open sheet: its kind, the maximal free rectangles, how far its parts reach.
struct Bin {
    int kind = 0;
    std::vector<Rect> free;
    double usedWidth = 0, usedHeight = 0;
};

/// MaxRects' placement rules (Jylänki 2010): best short side fit, best long side fit, best area fit,
/// bottom-left.
enum class Rule { ShortSide, LongSide, Area, BottomLeft };

/// Where a unit goes and its score under the rule, lower first.
struct Choice {
    double first = std::numeric_limits<double>::max(), second = 0;
    int bin = -1, rotation = 0;
    Rect at;
    bool operator<(const Choice& o) const { return std::tie(first, second) < std::tie(o.first, o.second); }
};

Choice scored(Rule rule, const Rect& free, const Pose& pose)
{
    const double dw = free.w - pose.w, dh = free.h - pose.h;
    const Rect at{free.x, free.y, pose.w, pose.h};
    switch (rule) {
        case Rule::LongSide:
            return {std::max(dw, dh), std::min(dw, dh), 0, pose.rotation, at};
        case Rule::Area:
            return {free.w * free.h - pose.w * pose.h, std::min(dw, dh), 0, pose.rotation, at};
        case Rule::BottomLeft:
            return {free.y + pose.h, free.x, 0, pose.rotation, at};
        case Rule::ShortSide:
            break;
    }
    return {std::min(dw, dh), std::max(dw, dh), 0, pose.rotation, at};
}

void bestIn(Rule rule, const Bin& bin, int index, const std::vector<Pose>& poses, Choice& best)
{
    for (const Rect& free : bin.free)
        for (const Pose& pose : poses) {
            if (pose.w > free.w + kHair || pose.h > free.h + kHair)
                continue;
            Choice c = scored(rule, free, pose);
            c.bin = index;
            if (c < best)
                best = c;
        }
}

/// Splits every free rectangle the placed one overlaps into the maximal ones around it, then drops those
/// inside another (MaxRects' split and prune).
void occupy(Bin& bin, const Rect& placed)
{
    std::vector<Rect> next;
    for (const Rect& f : bin.free) {
        if (!f.overlaps(placed)) {
            next.push_back(f);
            continue;
        }
        if (placed.x > f.x + kHair)
            next.push_back({f.x, f.y, placed.x - f.x, f.h});
        if (placed.x + placed.w < f.x + f.w - kHair)
            next.push_back({placed.x + placed.w, f.y, f.x + f.w - placed.x - placed.w, f.h});
        if (placed.y > f.y + kHair)
            next.push_back({f.x, f.y, f.w, placed.y - f.y});
        if (placed.y + placed.h < f.y + f.h - kHair)
            next.push_back({f.x, placed.y + placed.h, f.w, f.y + f.h - placed.y - placed.h});
    }
    bin.free.clear();
    for (size_t i = 0; i < next.size(); ++i) {
        bool inside = false;
        for (size_t j = 0; j < next.size() && !inside; ++j)
            inside = j != i && next[j].contains(next[i]) && (!next[i].contains(next[j]) || j < i);
        if (!inside)
            bin.free.push_back(next[i]);
    }
    bin.usedWidth = std::max(bin.usedWidth, placed.x + placed.w);
    bin.usedHeight = std::max(bin.usedHeight, placed.y + placed.h);
}

/// The free rectangle of a fresh sheet (usableSize).
Rect usable(const MasterBoard& board, const PackSettings& s)
{
    const auto [w, h] = usableSize(board, s);
    return {0, 0, w, h};
}

/// A new sheet of `kind` in `layout` and `bins`.
void open(const PackProblem& problem, int kind, std::vector<int>& left, std::vector<Bin>& bins,
          Layout& layout)
{
    openSheet(problem, kind, left, layout);
    bins.push_back({kind, {usable(problem.boards[kind], problem.settings)}});
}

/// Unit `part` at `choice` in `layout`.
void put(const PackProblem& problem, int part, const Choice& choice, std::vector<Bin>& bins, Layout& layout)
{
    occupy(bins[choice.bin], choice.at);
    addPlacement(problem, part, choice.bin, choice.at.x, choice.at.y, choice.rotation, layout);
}

void finish(const PackProblem& problem, const std::vector<Bin>& bins, Layout& layout)
{
    const double clearance = problem.settings.kerf + problem.settings.spacing;
    for (const Bin& bin : bins)
        layout.boundingArea += (bin.usedWidth - clearance) * (bin.usedHeight - clearance);
}

/// The time limit ran out before a layout was complete.
struct PastDeadline {};

/// Sheets a unit may go on in the first run: the last ones opened.
constexpr size_t kWindow = 32;

/// One MaxRects run: the units in their order, each placed by `rule` on the last `window` sheets opened or a
/// new one.
Layout laidOut(const PackProblem& problem, const std::vector<int>& units, Rule rule, Deadline deadline,
               size_t window)
{
    const double clearance = problem.settings.kerf + problem.settings.spacing;
    std::vector<int> left;  // boards of each kind still in stock; -1: as many as needed
    for (const MasterBoard& b : problem.boards)
        left.push_back(b.count);
    std::vector<Bin> bins;
    Layout layout;
    for (size_t u = 0; u < units.size(); ++u) {
        const PartSpec& part = problem.parts[units[u]];
        if (deadline.passed())
            throw PastDeadline{};
        Choice best;
        for (size_t b = bins.size() > window ? bins.size() - window : 0; b < bins.size(); ++b)
            bestIn(rule, bins[b], static_cast<int>(b), posesOn(part, problem.boards[bins[b].kind], clearance),
                   best);
        if (best.bin < 0) {
            const int kind = sheetKindFor(problem, part, left);
            if (kind < 0)
                throw ranOut(part, units.size() - u - 1);
            open(problem, kind, left, bins, layout);
            bestIn(rule, bins.back(), static_cast<int>(bins.size()) - 1,
                   posesOn(part, problem.boards[kind], clearance), best);
        }
        put(problem, units[u], best, bins, layout);
    }
    finish(problem, bins, layout);
    return layout;
}

/// Sheet by sheet: each filled with the best fitting (by `rule`, the larger part on a tie) of all the parts
/// left until none fits; a new sheet for the largest part left (`units` in decreasing order).
Layout sheetBySheet(const PackProblem& problem, const std::vector<int>& units, Rule rule, Deadline deadline)
{
    const double clearance = problem.settings.kerf + problem.settings.spacing;
    std::vector<int> left, remaining(problem.parts.size(), 0), order;  // order: part indices, largest first
    for (const MasterBoard& b : problem.boards)
        left.push_back(b.count);
    for (int u : units)
        if (remaining[u]++ == 0)
            order.push_back(u);
    std::vector<Bin> bins;
    Layout layout;
    size_t done = 0;
    while (done < units.size()) {
        const auto largest =
            std::find_if(order.begin(), order.end(), [&](int p) { return remaining[p] > 0; });
        const int kind = sheetKindFor(problem, problem.parts[*largest], left);
        if (kind < 0)
            throw ranOut(problem.parts[*largest], units.size() - done - 1);
        open(problem, kind, left, bins, layout);
        for (;;) {
            if (deadline.passed())
                throw PastDeadline{};
            Choice best;
            int chosen = -1;
            for (int p : order) {
                if (remaining[p] == 0)
                    continue;
                Choice here;
                bestIn(rule, bins.back(), static_cast<int>(bins.size()) - 1,
                       posesOn(problem.parts[p], problem.boards[kind], clearance), here);
                if (here.bin >= 0 && (chosen < 0 || here < best))
                    best = here, chosen = p;
            }
            if (chosen < 0)
                break;
            put(problem, chosen, best, bins, layout);
            --remaining[chosen];
            ++done;
        }
    }
    finish(problem, bins, layout);
    return layout;
}

/// Every MaxRects run on `problem` while the time lasts, each layout handed to `keep` (which returns false to
/// stop); the first PackingError (boards ran out) of the runs that raised one, if any. The first run places
/// each unit among the last kWindow sheets opened only, so it takes a time linear in the parts whatever the
/// job; when a layout is `needed` it completes even past `deadline`.
std::optional<PackingError> eachRun(const PackProblem& problem, Deadline deadline, bool needed,
                                    const std::function<bool(Layout&&)>& keep)
{
    std::vector<int> units;  // a part index per unit of demand
    for (size_t i = 0; i < problem.parts.size(); ++i)
        units.insert(units.end(), problem.parts[i].quantity, static_cast<int>(i));
    const auto sortBy = [&](Order order) {
        std::vector<std::pair<double, double>> key;  // per part, computed once: sizes come from outlines
        for (const PartSpec& part : problem.parts)
            key.push_back(orderKey(order, part));
        std::stable_sort(units.begin(), units.end(), [&](int a, int b) { return key[a] > key[b]; });
    };
    std::optional<PackingError> ranOutFirst;
    const auto tried = [&](const std::function<Layout()>& run) {  // false: stop
        try {
            return keep(run());
        } catch (const PastDeadline&) {
            return false;
        } catch (const PackingError& e) {
            ranOutFirst = ranOutFirst.value_or(e);
        }
        return true;
    };
    sortBy(Order::LongestSide);
    if (!tried([&] {
            return laidOut(problem, units, Rule::ShortSide, needed ? Deadline() : deadline, kWindow);
        }))
        return ranOutFirst;
    for (Order order : {Order::LongestSide, Order::Area, Order::Perimeter, Order::ShortestSide}) {
        sortBy(order);
        for (Rule rule : {Rule::ShortSide, Rule::LongSide, Rule::Area, Rule::BottomLeft})
            if (!tried([&] { return laidOut(problem, units, rule, deadline, units.size()); }))
                return ranOutFirst;
    }
    sortBy(Order::Area);
    for (Rule rule : {Rule::ShortSide, Rule::Area})
        if (!tried([&] { return sheetBySheet(problem, units, rule, deadline); }))
            break;
    return ranOutFirst;
}

/// The height a one-sheet layout uses.
double usedHeight(const Layout& layout, const PackSettings& s)
{
    double top = s.trim;
    for (const Placement& p : layout.placements)
        top = std::max(top, p.y + p.height);
    return top + s.trim;
}

}  // namespace

std::pair<double, double> usableSize(const MasterBoard& board, const PackSettings& s)
{
    const double clearance = s.kerf + s.spacing;
    return {board.width - 2 * s.trim + clearance, board.height - 2 * s.trim + clearance};
}

int sheetKindFor(const PackProblem& problem, const PartSpec& part, const std::vector<int>& left)
{
    const PackSettings& s = problem.settings;
    int kind = -1;
    for (size_t k = 0; k < problem.boards.size(); ++k) {
        const MasterBoard& board = problem.boards[k];
        const Rect sheet = usable(board, s);
        const std::vector<Pose> poses = posesOn(part, board, s.kerf + s.spacing);
        const bool fits = std::any_of(poses.begin(), poses.end(), [&](const Pose& p) {
            return p.w <= sheet.w + kHair && p.h <= sheet.h + kHair;
        });
        if (left[k] != 0 && fits && (kind < 0 || board.cost < problem.boards[kind].cost))
            kind = static_cast<int>(k);
    }
    return kind;
}

void openSheet(const PackProblem& problem, int kind, std::vector<int>& left, Layout& layout)
{
    const MasterBoard& board = problem.boards[kind];
    if (left[kind] > 0)
        --left[kind];
    layout.sheets.push_back(board);
    layout.sheets.back().count = 1;
    layout.sheetArea += board.width * board.height;
}

void addPlacement(const PackProblem& problem, int part, int sheet, double x, double y, int rotation,
                  Layout& layout)
{
    const PartSpec& spec = problem.parts[part];
    const double trim = problem.settings.trim;
    const bool turned = rotation % 180 != 0;
    layout.placements.push_back({part, sheet, trim + x, trim + y, rotation,
                                 turned ? spec.height() : spec.width(),
                                 turned ? spec.width() : spec.height()});
    layout.partArea += geometry::area(spec.outline);
}

PackingError ranOut(const PartSpec& part, size_t more)
{
    return PackingError("not enough master boards: part '" + part.id + "'" +
                        (more ? " and " + std::to_string(more) + " more do not fit on the boards available"
                              : " does not fit on the boards available"));
}

std::vector<Pose> posesOn(const PartSpec& part, const MasterBoard& board, double clearance)
{
    std::vector<Pose> poses;
    if (!ofThickness(part.thickness, board.thickness))
        return poses;
    for (int rotation : part.orientations) {
        if (rotation % 90 != 0 || !grainAllows(part.followsGrain, rotation, board.grain))
            continue;  // free rotation is Docking's: rectangles lie square here
        if (std::any_of(poses.begin(), poses.end(),
                        [&](const Pose& p) { return p.rotation % 180 == rotation % 180; }))
            continue;
        const auto [width, height] = part.turnedSize(rotation);
        poses.push_back({rotation, width + clearance, height + clearance});
    }
    return poses;
}

std::pair<double, double> orderKey(Order order, const PartSpec& p)
{
    const double w = p.width(), h = p.height();
    switch (order) {
        case Order::Area:
            return {w * h, std::max(w, h)};
        case Order::Perimeter:
            return {w + h, w * h};
        case Order::ShortestSide:
            return {std::min(w, h), std::max(w, h)};
        case Order::LongestSide:
            break;
    }
    return {std::max(w, h), w * h};
}

bool rectangular(const PartSpec& part)
{
    return part.outline.holes.empty() && geometry::isRectangle(part.outline);
}

bool allRectangles(const PackProblem& problem)
{
    return std::all_of(problem.parts.begin(), problem.parts.end(), rectangular);
}

Layout maxRects(const PackProblem& problem, Deadline deadline)
{
    std::optional<Layout> best;
    const auto ranOutFirst = eachRun(problem, deadline, true, [&](Layout&& layout) {
        if (!best || better(layout, *best))
            best = std::move(layout);
        return true;
    });
    if (!best)
        throw *ranOutFirst;
    return *best;
}

std::optional<Layout> maxRectsStrip(const PackProblem& problem, Deadline deadline)
{
    const PackSettings& s = problem.settings;
    const double width = problem.boards[0].width, clearance = s.kerf + s.spacing;
    double area = 0, high = 2 * s.trim;  // every part stacked on its longer side: a height that fits
    for (const PartSpec& part : problem.parts) {
        area += (part.width() + clearance) * (part.height() + clearance) * part.quantity;
        high += (std::max(part.width(), part.height()) + clearance) * part.quantity;
    }
    double low = area / (width - 2 * s.trim + clearance) + 2 * s.trim - clearance;
    PackProblem on = problem;  // one board, of the height halfway at each step
    on.strip = false;
    on.boards = {problem.boards[0]};
    on.boards[0].count = 1;
    std::optional<Layout> best;
    while (high - low > 1e-3 * high && !deadline.passed()) {
        on.boards[0].height = (low + high) / 2;
        std::optional<Layout> found;
        eachRun(on, deadline, false, [&](Layout&& layout) {
            found = std::move(layout);
            return false;  // one layout at this height is enough
        });
        if (!found) {
            low = on.boards[0].height;
            continue;
        }
        high = usedHeight(*found, s);
        found->stripHeight = found->sheets[0].height = high;
        found->sheetArea = found->boundingArea = width * high;
        best = std::move(found);
    }
    return best;
}

}  // namespace fabguide::material
