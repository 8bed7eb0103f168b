#include "Design/MinWastage.h"

#include "Core/Parallel.h"
#include "Design/FewerSheets.h"
#include "Layout/Deadline.h"
#include "Layout/LowerBound.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <tuple>

namespace fabguide::material {

namespace {

using Clock = std::chrono::steady_clock;

/// A design carried between rounds: with its docking order and the path that led to it.
struct Entry {
    DesignLayout design;
    std::vector<int> order;
    std::vector<DesignLayout> path;
};

std::vector<int> orderOf(const GridLayout& layout)
{
    std::vector<int> order;
    for (const Placed& p : layout.placed)
        order.push_back(p.part);
    order.insert(order.end(), layout.unplaced.begin(), layout.unplaced.end());
    return order;
}

/// A seed per round and task (splitmix64), so results do not depend on which thread ran what.
std::uint64_t seedOf(std::uint64_t seed, int round, int task)
{
    std::uint64_t z = seed + 0x9e3779b97f4a7c15ULL * (1 + static_cast<std::uint64_t>(round) * 1000003 + task);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

/// Seconds a design's own layout may search on when a short share of the time limit left a part over.
constexpr double kSearchOn = 10;

GridLayout exploredOrder(const MaterialSpace& material, const Eigen::VectorXd& sizes, std::vector<int> order,
                         std::uint64_t seed, Clock::time_point deadline, const std::atomic<bool>* cancel)
{
    const RasterProblem units = material.raster(sizes);
    OrderingSearchOptions search = orderingSearch(units.parts.size(), seed, secondsUntil(deadline));
    search.cancel = cancel;
    return exploreOrderings(units.parts, std::move(order), material.stock(), search);
}

/// One task of a round: EXPLOREORDERINGS from the entry's order (shuffled unless `keepOrder`), then
/// IMPROVEDESIGN along the order found.
Entry improve(const DesignSpace& design, const MaterialSpace& material, const Entry& from, std::uint64_t seed,
              bool keepOrder, const MinWastageOptions& options, Clock::time_point deadline)
{
    Explorer explorer{design,         material, from.order, std::mt19937_64(seed),
                      options.cancel, deadline, {},         options.guided};
    std::vector<int> order = from.order;
    if (!keepOrder)
        std::shuffle(order.begin(), order.end(), explorer.random);
    // The ordering search takes at most half of a task's share of the time limit: the design change the rest.
    const double share = options.timeLimit * std::max(1, options.threads) /
                         std::max(1, options.rounds * options.tasksPerRound);
    explorer.order =
        orderOf(exploredOrder(material, from.design.sizes, order, seed,
                              std::min(deadline, Clock::now() + seconds(share / 2)), options.cancel));
    const DesignLayout start = explorer.docked(from.design.X);
    Entry out{improveDesign(explorer, start, options.improveIterations), explorer.order, from.path};
    out.path.insert(out.path.end(), explorer.path.begin(), explorer.path.end());
    return out;
}

/// The K least-wastage designs of `entries`, each design once.
std::vector<Entry> keepBest(std::vector<Entry> entries, int keep)
{
    std::stable_sort(entries.begin(), entries.end(),
                     [](const Entry& a, const Entry& b) { return a.design.score() < b.design.score(); });
    std::vector<Entry> kept;
    for (Entry& e : entries) {
        const bool known = std::any_of(kept.begin(), kept.end(), [&](const Entry& k) {
            return (k.design.X - e.design.X).norm() < 1e-6;
        });
        if (!known && static_cast<int>(kept.size()) < keep)
            kept.push_back(std::move(e));
    }
    return kept;
}

/// Whether a maker would take `d` over `start`: cheaper boards (fewer sheets when they cost the same), or
/// as cheap and less waste (parts that use more of what is bought), or the same waste and a larger offcut.
bool better(const DesignLayout& d, const DesignLayout& start)
{
    constexpr double hair = 1e-4;  // m²
    const auto& a = d.figures;
    const auto& b = start.figures;
    if (std::isinf(d.score()))
        return false;
    if (a.cost != b.cost || a.sheets != b.sheets)
        return std::tie(a.cost, a.sheets) < std::tie(b.cost, b.sheets);
    if (std::abs(a.waste - b.waste) > hair)
        return a.waste < b.waste;
    return a.offcut[0] * a.offcut[1] > b.offcut[0] * b.offcut[1] * (1 + 1e-6);
}

/// The maker's order: cost, sheets, then waste, then the largest offcut (larger first).
bool ranksBefore(const DesignLayout& a, const DesignLayout& b)
{
    const auto key = [](const MaterialSpace::Figures& f) {
        return std::tuple{f.cost, f.sheets, f.waste, -f.offcut[0] * f.offcut[1]};
    };
    return key(a.figures) < key(b.figures);
}

constexpr double kWindow = 0.03;    // of the bought area: suggestions after the first waste at most that more
constexpr double kUnchanged = 1.0;  // mm of part lengths (their norm) within which a design is the user's
constexpr double kDistinct = 10.0;  // mm one part length at least differs by between two suggestions

/// How far apart a maker sees two designs: the largest change of any one part length (suggestions
/// 1 and 2 within 2 mm of each other showed the same design twice).
double apart(const Eigen::VectorXd& a, const Eigen::VectorXd& b)
{
    return (a - b).lpNorm<Eigen::Infinity>();
}

/// The next suggestion (5.3.3's farthest-point choice, on the maker's terms) of `pool`, sorted in the maker's
/// order, not yet taken: the first; then the design nearest the user's on as many sheets as the first (the
/// least change that gets there); then the design farthest in part lengths from those chosen, among those on
/// as many sheets within kWindow of its waste. Each differs from every one chosen by kDistinct in some part
/// length. -1 when there is none.
int nextPick(const std::vector<Entry>& pool, const std::vector<bool>& taken,
             const std::vector<Suggestion>& chosen, const DesignLayout& start)
{
    int pick = -1;
    double value = 0;  // the pick's distance to the user's design (second), or to the nearest chosen (after)
    for (size_t i = 0; i < pool.size(); ++i) {
        if (taken[i])
            continue;
        if (chosen.empty())
            return static_cast<int>(i);
        const DesignLayout& d = pool[i].design;
        const MaterialSpace::Figures& best = chosen.front().result.figures;
        double nearest = std::numeric_limits<double>::infinity();
        for (const Suggestion& s : chosen)
            nearest = std::min(nearest, apart(s.result.sizes, d.sizes));
        if (d.figures.cost != best.cost || d.figures.sheets != best.sheets || nearest < kDistinct)
            continue;
        const double change = (d.sizes - start.sizes).norm();
        if (chosen.size() == 1 ? pick < 0 || change < value
                               : d.figures.waste <= best.waste + kWindow * best.bought && nearest > value) {
            pick = static_cast<int>(i);
            value = chosen.size() == 1 ? change : nearest;
        }
    }
    return pick;
}

/// The suggestions: of the designs a maker would take over the user's (never on more sheets, never the
/// design unchanged), `count` chosen by nextPick that reopen.
template <typename Reopens>
std::vector<Suggestion> diverse(std::vector<Entry> pool, const DesignLayout& start, int count,
                                Reopens&& reopens, int& notReopened)
{
    const int all = static_cast<int>(pool.size());  // read before the move: argument order is unspecified
    pool = keepBest(std::move(pool), all);
    pool.erase(std::remove_if(pool.begin(), pool.end(),
                              [&](const Entry& e) {
                                  return !better(e.design, start) ||
                                         (e.design.sizes - start.sizes).norm() < kUnchanged;
                              }),
               pool.end());
    std::stable_sort(pool.begin(), pool.end(),
                     [](const Entry& a, const Entry& b) { return ranksBefore(a.design, b.design); });
    std::vector<Suggestion> chosen;
    std::vector<bool> taken(pool.size(), false);
    for (int pick;
         static_cast<int>(chosen.size()) < count && (pick = nextPick(pool, taken, chosen, start)) >= 0;) {
        taken[pick] = true;
        if (reopens(pool[pick].design))
            chosen.push_back({pool[pick].design, pool[pick].path});
        else  // not one the user could go on with: the next
            ++notReopened;
    }
    return chosen;
}

}  // namespace

DesignLayout layOut(const DesignSpace& design, const MaterialSpace& material, std::uint64_t seed,
                    double seconds, const std::atomic<bool>* cancel, const KeptLayout& kept)
{
    const Eigen::VectorXd X = design.start();
    const Eigen::VectorXd sizes = design.sizes(X);
    const Deadline stop(Clock::time_point::max(), cancel);
    GridLayout layout = material.searched(sizes, seed, seconds, cancel);
    const auto keepBetter = [&](GridLayout other) {
        if (designLayout(material, X, sizes, other).score() <
            designLayout(material, X, sizes, layout).score())
            layout = std::move(other);
    };
    if (const std::vector<int> units = material.unitsInOrder(kept.order); !units.empty())
        keepBetter(material.dock(sizes, units));
    if (kept.layout)
        keepBetter(material.onGrid(*kept.layout, sizes));
    if (!layout.unplaced.empty() && seconds < kSearchOn && !stop.cancelled())  // a short share: search on
        layout = material.searched(sizes, seed, kSearchOn, cancel);
    if (!layout.unplaced.empty() && stop.cancelled())
        throw PackingError("stopped before the design as it is was laid out: nothing to compare with");
    if (!layout.unplaced.empty())
        throw PackingError("the design does not fit on the master boards: part '" +
                           material.parts()[material.kindOf()[layout.unplaced.front()]].id +
                           "' is left over; add a board or make the design smaller");
    return designLayout(material, X, sizes, std::move(layout));
}

Exploration minWastage(const DesignSpace& design, const MaterialSpace& material,
                       const MinWastageOptions& options)
{
    const auto started = Clock::now();
    const auto deadline = started + seconds(std::max(0.0, options.timeLimit));
    Exploration exploration;
    // The design as it is gets a quarter of the time: suggestions are measured against its best layout.
    exploration.start =
        layOut(design, material, options.seed, options.timeLimit / 4, options.cancel, options.kept);
    std::vector<Entry> entries{{exploration.start, orderOf(exploration.start.layout), {exploration.start}}};
    std::vector<Entry> pool;
    // Saving a sheet first, in a fifth of the time limit: the rounds then improve on the designs it found.
    SavedSheets saved =
        fewerSheets(design, material, exploration.start, options.seed,
                    std::min(deadline, Clock::now() + seconds(options.timeLimit / 5)), options.cancel);
    exploration.leastSheets =
        saved.least && saved.least->layout.unplaced.empty() ? saved.least->figures.sheets : 0;
    const auto shortest = design.shortestSides(exploration.start.X);
    if (shortest) {
        const PackProblem least = material.problem(*shortest);
        exploration.leastSheetsByArea = sheetsByArea(least);
        exploration.leastSheetsBound = sheetsBound(least);
    }
    for (DesignLayout& d : saved.designs) {
        pool.push_back({d, orderOf(d.layout), {exploration.start, d}});
        entries.push_back(pool.back());
    }
    entries = keepBest(std::move(entries), options.keep);
    const int total = options.rounds * options.tasksPerRound;
    DesignLayout best = entries.front().design;
    for (int round = 0; round < options.rounds; ++round) {
        std::vector<Entry> results(options.tasksPerRound);
        const auto task = [&](int t) {
            const int from = t % static_cast<int>(entries.size());
            results[t] = improve(design, material, entries[from], seedOf(options.seed, round, t),
                                 t < static_cast<int>(entries.size()), options, deadline);
        };
        const auto finished = [&](int t) {
            ++exploration.designsImproved;
            if (results[t].design.score() < best.score())
                best = results[t].design;
            if (options.progress)
                options.progress(static_cast<double>(exploration.designsImproved) / total, 1 - best.wastage);
        };
        runAll(options.tasksPerRound, options.threads, task, finished);
        pool.insert(pool.end(), results.begin(), results.end());
        results.insert(results.end(), entries.begin(), entries.end());
        entries = keepBest(std::move(results), options.keep);
        exploration.stopped = (options.cancel && options.cancel->load()) || Clock::now() > deadline;
        if (exploration.stopped)
            break;
    }
    // A suggestion is a design the user goes on with: its file keeps its layout, which reopened (in
    // millimetres, slid to the sizes read) must cut it from boards that cost no more.
    const auto reopens = [&](const DesignLayout& d) {
        const GridLayout reopened = material.onGrid(material.inMillimetres(d.layout, d.sizes), d.sizes);
        return reopened.unplaced.empty() && material.figures(reopened, d.sizes).cost <= d.figures.cost;
    };
    exploration.suggestions =
        diverse(std::move(pool), exploration.start, options.suggestions, reopens, exploration.notReopened);
    exploration.seconds = std::chrono::duration<double>(Clock::now() - started).count();
    return exploration;
}

Exploration::NoSheetSaved Exploration::noSheetSaved() const
{
    if (leastSheets == 0 || leastSheets < start.figures.sheets || leastSheetsBound == 0)
        return NoSheetSaved::Unknown;
    return leastSheetsBound >= start.figures.sheets ? NoSheetSaved::Bound : NoSheetSaved::LaidOut;
}

}  // namespace fabguide::material
