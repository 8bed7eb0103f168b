#include "Layout/Pack.h"

#include "Core/Memory.h"
#include "Core/Parallel.h"
#include "Layout/Compaction.h"
#include "Layout/Guillotine.h"
#include "Layout/HoleFill.h"
#include "Layout/MaxRects.h"
#include "Layout/Raster.h"
#include "Layout/Shrink.h"
#include "Layout/Skyline.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <map>
#include <optional>
#include <stdexcept>
#include <tuple>

namespace fabguide::material {

RasterPart rasterPart(const PartSpec& spec, const PackSettings& settings)
{
    RasterPart part{spec.id, {}, {}, spec.followsGrain, spec.thickness};
    for (int rotation : spec.orientations) {
        const Footprint shape = rasterise(geometry::placed(spec.outline, rotation, 0, 0), settings.resolution,
                                          settings.kerf + settings.spacing);
        // Identical shapes are one choice, unless the grain tells a turned one apart.
        bool known = false;
        for (size_t k = 0; k < part.shapes.size() && !known; ++k)
            known =
                part.shapes[k] == shape && (!spec.followsGrain || part.rotations[k] % 180 == rotation % 180);
        if (!known) {
            part.shapes.push_back(shape);
            part.rotations.push_back(rotation);
        }
    }
    return part;
}

namespace {

/// Whether `part` is cut from `board` (of its thickness) and fits on it (trim removed) in one of its
/// orientations the board's grain allows, by its bounding box.
bool fitsOn(const PartSpec& part, const MasterBoard& board, const PackSettings& s, bool strip)
{
    if (!ofThickness(part.thickness, board.thickness))
        return false;
    const double w = board.width - 2 * s.trim, h = strip ? HUGE_VAL : board.height - 2 * s.trim;
    for (int rotation : part.orientations) {
        const auto [width, height] = part.turnedSize(rotation);
        if (grainAllows(part.followsGrain, rotation, board.grain) && width <= w + 1e-9 && height <= h + 1e-9)
            return true;
    }
    return false;
}

std::string number(const char* format, double n)
{
    char text[32];
    std::snprintf(text, sizeof text, format, n);
    return text;
}
std::string mm(double n)
{
    return number("%.6g", n);
}
std::string cells(double n)
{
    return number("%.3g", n);
}

/// "not enough master boards: part 'a' and 3 more do not fit <where>"
PackingError notEnoughBoards(const std::string& part, long more, const std::string& where)
{
    return PackingError("not enough master boards: part '" + part + "' " +
                        (more ? "and " + std::to_string(more) + " more do not fit " : "does not fit ") +
                        where);
}

/// Whether `part`'s bitmaps are made cell by cell: an irregular part, or one turned off the quarters (a
/// rectangle on the quarters is its profiles).
bool byCells(const PartSpec& part)
{
    return !rectangular(part) ||
           std::any_of(part.orientations.begin(), part.orientations.end(), [](int r) { return r % 90 != 0; });
}

/// The cells of `part`'s bitmaps, one per orientation (a turn off the quarters takes its diagonal's square),
/// with its clearance.
double gridCells(const PartSpec& part, const PackSettings& s)
{
    const double clearance = s.kerf + s.spacing, w = part.width() + clearance, h = part.height() + clearance;
    double cells = 0;
    for (int rotation : part.orientations)
        cells += rotation % 90 == 0 ? w * h : w * w + h * h;
    return cells / (s.resolution * s.resolution);
}

/// The memory Docking's grid takes: the bitmaps of irregular parts, shared by a part's copies; every unit's
/// profiles, four per orientation, as long as its sides in cells; and a strip's height-fields, which grow
/// with its height in cells, on every thread.
double gridBytes(const PackProblem& problem)
{
    const PackSettings& s = problem.settings;
    double bitmaps = 0, profiles = 0, stripCells = 0;
    for (const PartSpec& part : problem.parts) {
        const double sides = (part.width() + part.height()) / s.resolution;
        stripCells += part.quantity * std::max(part.width(), part.height()) / s.resolution;
        profiles += part.quantity * part.orientations.size() * sides;
        if (byCells(part))
            bitmaps += gridCells(part, s);
    }
    return bitmaps * kBytesPerCell + profiles * kBytesPerProfileCell +
           (problem.strip ? stripCells * kBytesPerStripCell * cores() : 0);
}

/// Refuses an irregular job whose grid would pass the memory limit, before anything is rasterised;
/// a job of rectangles is laid out without the grid then.
void checkMemory(const PackProblem& problem)
{
    if (allRectangles(problem))
        return;
    if (problem.strip)  // an ESICUP instance: its grid follows from the strip, not from a setting
        needMemory(gridBytes(problem),
                   "items: the strip, gridded at " + mm(problem.settings.resolution) +
                       " mm a cell and as long as the pieces laid end to end, needs",
                   ": fewer or shorter pieces need less");
    else
        needMemory(gridBytes(problem),
                   "parts: the grid of their outlines at settings.resolution " +
                       mm(problem.settings.resolution) + " mm needs",
                   ": a resolution twice as coarse needs a quarter as much");
}

}  // namespace

void checkSettings(const PackProblem& problem)
{
    const PackSettings& s = problem.settings;
    if (!(s.resolution > 0))
        throw std::invalid_argument("settings.resolution must be positive");
    if (s.kerf < 0 || s.spacing < 0 || s.trim < 0)
        throw std::invalid_argument("settings.kerf, spacing and trim must not be negative");
    if (problem.boards.empty())
        throw std::invalid_argument("boards: at least one master board is needed");
    if (problem.parts.empty())
        throw std::invalid_argument("parts: nothing to lay out");
    if (s.rotationStep < 0 || (s.rotationStep > 0 && 90 % s.rotationStep != 0))
        throw std::invalid_argument("settings.rotation_step must divide 90 (e.g. 15, 30, 45), got " +
                                    std::to_string(s.rotationStep));
    if (s.stages < 0)
        throw std::invalid_argument("settings.stages must be 0 (unlimited) or a number of stages, got " +
                                    std::to_string(s.stages));
    if (s.cuts == Cuts::Guillotine && problem.strip)
        throw std::invalid_argument("settings.cuts: guillotine cuts are laid out on sheets, not on a strip");
    // Sizes are checked before anything is rasterised: the grid is what takes time and memory.
    for (size_t k = 0; k < problem.boards.size(); ++k) {
        const MasterBoard& b = problem.boards[k];
        const double grid = (b.width / s.resolution) * (problem.strip ? 1.0 : b.height / s.resolution);
        if (b.width > kLongest || (!problem.strip && b.height > kLongest) || grid > kMostCells)
            throw std::invalid_argument("boards[" + std::to_string(k) + "] ('" + b.name +
                                        "'): " + mm(b.width) + " x " + mm(b.height) + " mm is " +
                                        cells(grid) + " grid cells at settings.resolution " +
                                        mm(s.resolution) + " mm; FabGuide lays out boards of up to " +
                                        mm(kLongest) + " mm and " + cells(kMostCells) + " cells");
    }
    // The boards' area for parts of a thickness: those boards of it, summed once per thickness.
    std::map<double, double> boardAreas;
    const auto boardArea = [&](double thickness) {
        const auto [known, added] = boardAreas.try_emplace(thickness, 0.0);
        if (added)
            for (const MasterBoard& b : problem.boards)
                if (ofThickness(thickness, b.thickness))
                    known->second += b.count < 0 || problem.strip ? HUGE_VAL : b.count * b.width * b.height;
        return known->second;
    };
    long units = 0, over = 0;           // over: units past their boards' area, in the order given
    std::map<double, double> partArea;  // per thickness
    const PartSpec* first = nullptr;
    for (const PartSpec& part : problem.parts) {
        units += part.quantity;
        if (units > kMostUnits)
            throw std::invalid_argument("parts: more than " + std::to_string(kMostUnits) +
                                        " parts to lay out (quantities added up)");
        if (std::none_of(problem.boards.begin(), problem.boards.end(),
                         [&](const MasterBoard& b) { return ofThickness(part.thickness, b.thickness); }))
            throw PackingError("part '" + part.id + "' is " + mm(part.thickness) +
                               " mm thick: no master board is (add one that thick)");
        if (std::none_of(problem.boards.begin(), problem.boards.end(),
                         [&](const MasterBoard& b) { return fitsOn(part, b, s, problem.strip); }))
            throw PackingError("part '" + part.id + "' is larger than every master board" +
                               (part.thickness > 0 ? " of its thickness" : std::string()) + " (" +
                               mm(part.width()) + " x " + mm(part.height()) + " mm)");
        const double area = geometry::area(part.outline);
        for (int k = 0; k < part.quantity && !over; ++k)
            if ((partArea[part.thickness] += area) > boardArea(part.thickness))
                first = &part, over = part.quantity - k;
        if (over && first != &part)
            over += part.quantity;
    }
    if (over)
        throw notEnoughBoards(first->id, over - 1,
                              "in the boards' " + mm(boardArea(first->thickness) / 1e6) + " m²");
    checkMemory(problem);
}

GridLayout searchFromStarts(const std::vector<RasterPart>& parts, const std::vector<BoardStock>& stock,
                            OrderingSearchOptions options, Deadline firstPasses)
{
    // Each start wins on some instances: best-fit orders preferring large extents, wide parts and large
    // areas, and the thesis' decreasing extent (5.3.1); a fill starts from each with both its tie-breaks.
    // The starts run on the threads, each with an equal share of the time, of which building a best-fit
    // order may take a sixth.
    using Clock = std::chrono::steady_clock;
    const Deadline end(Clock::now() + seconds(options.timeLimit), options.cancel);
    const std::vector<Criterion> ways = options.criterion == Criterion::Fill
                                            ? std::vector<Criterion>{Criterion::Fill, Criterion::SnugFill}
                                            : std::vector<Criterion>{options.criterion};
    const std::vector<std::optional<Preference>> orders{Preference::LargestExtent, Preference::Widest,
                                                        Preference::LargestArea, std::nullopt};
    const int count = static_cast<int>(ways.size() * orders.size());
    const int threads = std::clamp(options.threads, 1, count);
    const double share = options.timeLimit * threads / count;
    std::vector<GridLayout> found(count);
    const auto start = [&](int k) {
        const Deadline until = end.sooner(Clock::now() + seconds(share));
        OrderingSearchOptions search = options;
        search.criterion = ways[k / orders.size()];
        const std::optional<Preference> preference = orders[k % orders.size()];
        const std::vector<int> order =
            preference ? bestFitOrder(parts, stock, search.criterion, options.bounds, *preference,
                                      until.sooner(Clock::now() + seconds(share / 6)))
                       : decreasingExtentOrder(parts);
        search.timeLimit = until.secondsLeft();
        found[k] = exploreOrderings(parts, order, stock, search, firstPasses);
    };
    runAll(count, threads, start, [](int) {});
    // The lowest cost of those finished, the first start on a tie: the same whichever thread finished first.
    const auto rank = [&](const GridLayout& g) {
        return std::pair{!g.finished, cost(g, stock, options.bounds)};
    };
    size_t best = 0;
    for (size_t k = 1; k < found.size(); ++k)
        if (rank(found[k]) < rank(found[best]))
            best = k;
    return std::move(found[best]);
}

std::pair<double, double> PartSpec::turnedSize(int rotation) const
{
    if (rotation % 90 == 0)
        return rotation % 180 ? std::pair{height(), width()} : std::pair{width(), height()};
    const geometry::Box2 box = geometry::bounds(geometry::placed(outline, rotation, 0, 0).outer);
    return {box.width(), box.height()};
}

PartSpec rectangularPart(std::string id, double width, double height, int quantity,
                         std::vector<int> orientations)
{
    return {std::move(id), geometry::rectangle(width, height), quantity, std::move(orientations), {}, {}};
}

RasterProblem rasterise(const PackProblem& problem)
{
    const PackSettings& settings = problem.settings;
    const double clearance = settings.kerf + settings.spacing;
    RasterProblem raster;
    long stripCells = 0;
    for (size_t i = 0; i < problem.parts.size(); ++i) {
        const RasterPart part = rasterPart(problem.parts[i], settings);  // its copies share its bitmaps
        raster.parts.insert(raster.parts.end(), problem.parts[i].quantity, part);
        raster.specOf.insert(raster.specOf.end(), problem.parts[i].quantity, static_cast<int>(i));
        stripCells += problem.parts[i].quantity * std::max(part.shapes[0].width(), part.shapes[0].height());
    }
    for (const MasterBoard& board : problem.boards)
        raster.stock.push_back(
            {cellsWithin(board.width - 2 * settings.trim + clearance, settings.resolution),
             problem.strip ? static_cast<int>(stripCells)
                           : cellsWithin(board.height - 2 * settings.trim + clearance, settings.resolution),
             problem.strip ? 1 : board.count, board.grain, board.thickness, board.cost});
    if (problem.strip)
        raster.stock.resize(1);
    return raster;
}

Layout inMillimetres(const GridLayout& grid, const PackProblem& problem, const RasterProblem& raster)
{
    if (!grid.unplaced.empty())
        throw notEnoughBoards(raster.parts[grid.unplaced.front()].name,
                              static_cast<long>(grid.unplaced.size()) - 1, "on the boards available");
    const PackSettings& settings = problem.settings;
    const double clearance = settings.kerf + settings.spacing;
    Layout layout;
    const double tau = settings.resolution;
    for (size_t s = 0; s < grid.stock.size(); ++s) {
        MasterBoard sheet = problem.boards[grid.stock[s]];
        if (problem.strip)
            sheet.height = layout.stripHeight = grid.usedHeight[s] * tau - clearance;
        sheet.count = 1;
        layout.sheets.push_back(sheet);
        layout.sheetArea += sheet.width * sheet.height;
        const double usedWidth = problem.strip ? sheet.width : grid.usedWidth[s] * tau - clearance;
        layout.boundingArea += usedWidth * (grid.usedHeight[s] * tau - clearance);
    }
    for (const Placed& p : grid.placed) {
        const PartSpec& spec = problem.parts[raster.specOf[p.part]];
        const int rotation = raster.parts[p.part].rotations[p.shape];
        const auto [width, height] = spec.turnedSize(rotation);
        layout.placements.push_back({raster.specOf[p.part], p.sheet, settings.trim + p.x * tau,
                                     settings.trim + p.y * tau, rotation, width, height});
        layout.partArea += geometry::area(spec.outline);
    }
    return layout;
}

bool better(const Layout& a, const Layout& b)
{
    const auto measure = [](const Layout& l) {
        double cost = 0;
        for (const MasterBoard& sheet : l.sheets)
            cost += sheet.cost;
        return std::make_tuple(cost, l.sheets.size(), l.boundingArea);
    };
    return measure(a) < measure(b);
}

namespace {

/// The problem with free rotation applied (settings.rotationStep): each part without grain that may take
/// every quarter turn may take every multiple of the step.
PackProblem freelyTurned(PackProblem problem)
{
    const int step = problem.settings.rotationStep;
    if (step <= 0)
        return problem;
    for (PartSpec& part : problem.parts) {
        const auto allows = [&](int r) {
            return std::count(part.orientations.begin(), part.orientations.end(), r) > 0;
        };
        if (part.followsGrain || !allows(0) || !allows(90) || !allows(180) || !allows(270))
            continue;
        part.orientations.clear();
        for (int r = 0; r < 360; r += step)
            part.orientations.push_back(r);
    }
    return problem;
}

/// Column steps of one fill pass: every unit's shapes tried at every column of the strip, across their width.
double fillPassSteps(const RasterProblem& raster)
{
    double steps = 0;
    for (const RasterPart& part : raster.parts)
        for (const Footprint& shape : part.shapes)
            steps += std::max(1.0, raster.stock[0].width - shape.width() + 1.0) * shape.width();
    return steps;
}

/// A search's size for a time limit: `perSecond` for each of its seconds, at most 10^18 (a limit of years is
/// none).
long forTimeLimit(double perSecond, double seconds)
{
    return static_cast<long>(std::min(perSecond * seconds, 1e18));
}

/// The skyline search of a strip of rectangles on each thread, their seeds 2^32 apart, each within the work
/// of the time limit; the lowest strip, the first thread's on a tie.
std::optional<Layout> skylineOnThreads(const PackProblem& problem, const OrderingSearchOptions& search,
                                       Deadline deadline)
{
    const int threads = std::max(1, search.threads);
    const long work = forTimeLimit(kSkylineWorkPerSecond, search.timeLimit);
    std::vector<std::optional<Layout>> found(threads);
    runAll(
        threads, threads,
        [&](int t) {
            found[t] =
                skylineStrip(problem, {work, search.seed + (static_cast<std::uint64_t>(t) << 32)}, deadline);
        },
        [](int) {});
    std::optional<Layout> lowest;
    for (std::optional<Layout>& strip : found)
        if (strip && (!lowest || strip->stripHeight < lowest->stripHeight))
            lowest = std::move(strip);
    return lowest;
}

/// About how long rasterising `problem` takes: a part whose bitmap is made cell by cell (an irregular one, or
/// one turned off the quarters) in every orientation at kOutlineCellsPerSecond, a rectangle by its profiles
/// in two turns and the boards at kRasterCellsPerSecond.
double rasterSeconds(const PackProblem& problem)
{
    const PackSettings& s = problem.settings;
    const double cell = s.resolution * s.resolution, clearance = s.kerf + s.spacing;
    double seconds = 0;
    for (const PartSpec& part : problem.parts)
        seconds += byCells(part) ? gridCells(part, s) / kOutlineCellsPerSecond
                                 : 2 * (part.width() + clearance) * (part.height() + clearance) / cell /
                                       kRasterCellsPerSecond;
    for (const MasterBoard& board : problem.boards)
        seconds += board.width * board.height / cell / kRasterCellsPerSecond;
    return seconds;
}

/// Whether Docking's grid is out of reach for a job of rectangles, whose MaxRects or skyline layout is in
/// hand: too many units, rasterising would outlast the time left at the `share` of a core this process gets,
/// or the grid would pass the memory limit.
bool gridOutOfReach(const PackProblem& problem, long units, const Deadline& deadline, double share = 1.0)
{
    return units > kDockedUnits || rasterSeconds(problem) / share > deadline.secondsLeft() ||
           gridBytes(problem) > memoryLimit();
}

/// The guillotine search's runs: the ordering search's iterations when given (a run bounded by work is so
/// bounded throughout), else kGuillotineRuns to the deadline.
long guillotineRuns(const OrderingSearchOptions& search)
{
    return search.iterations < 0 ? kGuillotineRuns : search.iterations;
}

/// The guillotine search's layout instead of `layout` when it is better: a layout for a saw is a free one
/// too, and on shop cut lists it often needs fewer sheets than MaxRects or Docking. Three stages:
/// in its share of the time, unlimited stages (four stage counts a sheet) made a quarter of the runs and
/// needed 2 sheets more on the 2BP classes (docs/benchmarks.md). Its saw cuts are dropped: the cuts are free.
Layout sawnIfBetter(const PackProblem& problem, Layout layout, const OrderingSearchOptions& search,
                    Deadline deadline)
{
    PackProblem saw = problem;
    saw.settings.cuts = Cuts::Guillotine;
    saw.settings.stages = 3;
    saw.settings.firstCut = FirstCut::Any;
    try {
        Layout sawn = guillotine(saw, guillotineRuns(search), search.seed, deadline, search.threads);
        sawn.sawCuts.clear();
        return better(sawn, layout) ? sawn : layout;
    } catch (const PackingError&) {  // a strip at a board's edge too narrow to saw: the free layout stands
        return layout;
    }
}

/// MaxRects on the parts' bounding boxes, a strip or on the boards; nothing when the boards run out first.
std::optional<Layout> boundingBoxes(const PackProblem& problem, Deadline deadline)
{
    if (problem.strip)
        return maxRectsStrip(problem, deadline);
    try {
        return maxRects(problem, deadline);
    } catch (const PackingError&) {
        return std::nullopt;
    }
}

Layout layOut(const PackProblem& problem, const OrderingSearchOptions& search)
{
    const auto started = std::chrono::steady_clock::now();
    const Deadline deadline(started + seconds(search.timeLimit), search.cancel);
    const bool rectangles = allRectangles(problem);
    long units = 0;
    for (const PartSpec& part : problem.parts)
        units += part.quantity;
    // Rectangles are laid out exactly by MaxRects first: at shop scale that is the layout, below it the
    // better of it and Docking's search.
    std::optional<Layout> exact;
    if (!problem.strip && rectangles) {
        const std::clock_t cpu = std::clock();
        try {
            exact = maxRects(problem, deadline);
        } catch (const PackingError&) {
            if (units > kDockedUnits)
                throw;
        }
        // Docking's grid alone would outlast the time limit (0.2 s took 0.5) at the speed this
        // process gets: on a loaded machine a share of a core, measured on MaxRects' run (1 s took 1.5).
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        const double share =
            wall < 0.005 ? 1.0 : std::clamp((std::clock() - cpu) / double(CLOCKS_PER_SEC) / wall, 0.05, 1.0);
        // The saw's search takes its share of the time, or all of it when Docking's grid would be out of
        // reach in the time it leaves.
        const Deadline afterSaw(std::chrono::steady_clock::now() +
                                seconds((1 - kSawShare) * search.timeLimit));
        if (exact && units <= kSawnUnits)
            exact = sawnIfBetter(problem, std::move(*exact), search,
                                 gridOutOfReach(problem, units, afterSaw, share)
                                     ? deadline
                                     : deadline.sooner(started + seconds(kSawShare * search.timeLimit)));
        if (exact && gridOutOfReach(problem, units, deadline, share))
            return *exact;
    }
    // A strip of rectangles: the skyline search on each thread within its work (by 85 % of the time), done
    // when it reaches the least height; else MaxRects bisects the height (until 95 %), Docking's search takes
    // the rest up to kDockedUnits units; the lowest strip wins.
    std::optional<Layout> lower;
    if (problem.strip && rectangles) {
        lower =
            skylineOnThreads(problem, search, deadline.sooner(started + seconds(0.85 * search.timeLimit)));
        if (lower && lower->stripHeight <= leastStripHeight(problem) + 1e-6)
            return *lower;
        std::optional<Layout> bisected =
            maxRectsStrip(problem, deadline.sooner(started + seconds(0.95 * search.timeLimit)));
        if (bisected && (!lower || bisected->stripHeight < lower->stripHeight))
            lower = std::move(bisected);
        if (lower && gridOutOfReach(problem, units, deadline))
            return *lower;
    }
    // Many irregular parts: MaxRects on their bounding boxes in a tenth of the time, a layout in hand should
    // Docking's first pass not end by the deadline (400 pieces took 22 s of a 5 s limit).
    const bool many = !rectangles && units > kBoxedUnits;
    const bool cut = rectangles || many;  // first passes cut at the deadline: a layout is in hand
    std::optional<Layout> boxed;
    if (many)
        boxed = boundingBoxes(problem, deadline.sooner(started + seconds(0.1 * search.timeLimit)));
    // Rasterising the outlines alone would outlast the time limit (100 parts of 10^8 cells took
    // minutes): the bounding boxes' layout is the one in hand.
    if (const double rasterising = rectangles ? 0 : rasterSeconds(problem);
        rasterising > deadline.secondsLeft()) {
        if (!boxed)
            boxed = boundingBoxes(problem, deadline);
        if (boxed)
            return *boxed;
        throw PackingError("rasterising the parts' outlines at settings.resolution " +
                           mm(problem.settings.resolution) + " mm takes ~" + mm(rasterising) +
                           " s, more than the time limit: give it more time or a coarser resolution");
    }
    const RasterProblem raster = rasterise(problem);
    OrderingSearchOptions options = search;
    options.bounds = problem.strip ? Bounds::Strip : Bounds::Layout;
    options.timeLimit = deadline.secondsLeft();
    // A strip of irregular parts: the search gives a first strip in a share of the time, shrinking shortens
    // it in the rest, and compaction on the outlines gives back what the grid lost. The search fills it
    // bottom-left, holes included, when it has time for kFillPasses passes; Docking's height-fields cannot
    // reach under the parts' overhangs.
    const bool shrinks = problem.strip && !rectangles;
    if (shrinks)
        options.timeLimit *= kFirstStripShare;
    if (shrinks && search.criterion == Criterion::Docking &&
        fillPassSteps(raster) * kFillPasses <= kFillStepsPerSecond * options.timeLimit)
        options.criterion = Criterion::Fill;
    try {
        GridLayout grid = searchFromStarts(raster.parts, raster.stock, options, cut ? deadline : Deadline());
        if (!grid.finished) {  // the deadline passed before any first layout: the one in hand
            if (const std::optional<Layout>& inHand = lower ? lower : exact ? exact : boxed)
                return *inHand;
            throw PackingError(deadline.cancelled()
                                   ? "stopped before a first layout"
                                   : "the time ran out before a first layout of " + std::to_string(units) +
                                         " parts: give it more time");
        }
        if (shrinks)
            grid = shrinkStrip(raster.parts, raster.stock[0], grid,
                               {forTimeLimit(kShrinkWorkPerSecond, search.timeLimit), search.seed,
                                std::max(1, search.threads)},
                               deadline);
        Layout docked = inMillimetres(grid, problem, raster);
        if (shrinks)
            docked = compacted(docked, problem);
        if (lower && lower->stripHeight < docked.stripHeight)
            return *lower;
        return exact && better(*exact, docked) ? *exact : docked;
    } catch (const PackingError&) {
        if (!exact)
            throw;
        return *exact;
    }
}

/// With common-line cutting, the parts slid together so that the grid's slack does not keep them from
/// sharing their lines.
Layout commonLined(const Layout& layout, const PackProblem& problem)
{
    return problem.settings.commonLine && !problem.strip ? slidTogether(layout, problem) : layout;
}

}  // namespace

Layout pack(const PackProblem& given, const OrderingSearchOptions& search)
{
    const Deadline deadline(std::chrono::steady_clock::now() + seconds(search.timeLimit), search.cancel);
    const PackProblem problem = freelyTurned(given);
    checkSettings(problem);
    if (problem.settings.cuts == Cuts::Guillotine)
        return guillotine(problem, guillotineRuns(search), search.seed, deadline, search.threads);
    std::vector<int> left;
    for (const PartSpec& part : problem.parts)
        left.push_back(part.quantity);
    const std::vector<int> quantities = left;
    const std::vector<std::vector<std::vector<Guest>>> guests = fillHoles(problem, left, deadline.share(4));
    if (left == quantities)
        return commonLined(layOut(problem, search), problem);
    PackProblem rest = problem;  // the parts less the units laid in holes
    rest.parts.clear();
    std::vector<int> original;
    for (size_t k = 0; k < problem.parts.size(); ++k)
        if (left[k] > 0) {
            rest.parts.push_back(problem.parts[k]);
            rest.parts.back().quantity = left[k];
            original.push_back(static_cast<int>(k));
        }
    OrderingSearchOptions options = search;
    options.timeLimit = deadline.secondsLeft();
    return commonLined(withGuests(layOut(rest, options), problem, original, guests), problem);
}

}  // namespace fabguide::material
