#include "Layout/GuillotineBeam.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_set>

namespace fabguide::material {

namespace {
constexpr long kMostCandidates = 1 << 20;  // partial layouts grown at one depth, 32 MB
}  // namespace

bool leavesSawable(double room, double size, double clearance)
{
    return size <= room + kHair && (size >= room - kHair || size < room - clearance / 2 - kHair);
}

namespace {

double along(const Pose& pose, int axis)
{
    return axis == 0 ? pose.w : pose.h;
}

/// Where a partial layout stands on its last sheet, along the first stage's axis a and across it (b): the
/// open first-stage slab, the open second-stage slab (column) in it and how far the column is filled along a.
struct Frontier {
    long sheets = 0;
    double slabAt = 0, slab = 0, columnAt = 0, column = 0, filled = 0;
};

/// A partial layout: its frontier, the part area laid (clearance included), the area it left that no later
/// unit can take, what it laid on its last sheet, its rank, its step and the partial layout it grew from.
struct Partial {
    Frontier at;
    double laid = 0, waste = 0, lastSheet = 0, squares = 0;  ///< squares: the units' areas squared, summed
    double guide = 0;                                        ///< lower is better (Guide)
    std::uint64_t units = 0;  ///< the multiset of units laid, hashed (order does not matter)
    int parent = -1;          ///< in the previous depth's partial layouts
    SawStep step;
    /// Partial layouts with the same units laid and the same frontier can grow the same ways.
    std::uint64_t key() const
    {
        std::uint64_t k = units ^ static_cast<std::uint64_t>(at.sheets) * 0x9e3779b97f4a7c15ULL;
        for (double v : {at.slabAt, at.slab, at.columnAt, at.column, at.filled})
            k = (k ^ static_cast<std::uint64_t>(std::llround(v * 1e3))) * 0x100000001b3ULL;
        return k;
    }
};

/// How a complete layout ranks, lower better: its sheets, then what its last sheet holds.
std::pair<long, double> rank(const Partial& n)
{
    return {n.at.sheets, n.lastSheet};
}

/// A partial layout yet to be chosen, as little as ranks it: its rank and how it grows from its parent.
struct Candidate {
    double guide = 0, laid = 0;
    int parent = -1, part = -1, pose = -1;
    Where where = Where::Sheet;
    /// Lower is better: by the guide, the more laid on a tie.
    bool operator<(const Candidate& o) const
    {
        return guide < o.guide || (guide == o.guide && laid > o.laid);
    }
};

/// A random 64-bit word per part (splitmix64), summed over the units laid.
std::uint64_t unitHash(int part)
{
    std::uint64_t z = static_cast<std::uint64_t>(part) + 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

/// How the partial layouts of one depth are ranked (packingsolver's guides 0, 2 and 3): by the share of the
/// area behind their frontier that is lost; by that share (plus 0.1) per area laid, which favours large units
/// first; or per the units' areas squared, more so.
enum class Guide { Lost, LostPerArea, LostPerSquare };
constexpr Guide kGuides[] = {Guide::Lost, Guide::LostPerArea, Guide::LostPerSquare};

/// How partial layouts grow, for one guide and one first-stage axis a of every sheet.
class Beam {
public:
    Beam(const BeamProblem& problem, Guide guide, int axis)
        : p_(problem), guide_(guide), a_(axis), b_(1 - axis)
    {
    }

    /// The candidates `from` (the `index`-th of its depth) grows into by one unit. After packingsolver's
    /// dominance rule: no new column when a unit fits after the last without growing its column or slab, no
    /// new slab when one fits in the slab without growing it, a new sheet only when nothing else fits.
    void grow(const Partial& from, int index, const std::vector<int>& remaining,
              std::vector<Candidate>& out) const
    {
        const size_t before = out.size();
        bool keptColumn = false, keptSlab = false;
        if (from.at.sheets > 0 && p_.stages >= 3)
            growAt(from, index, remaining, Where::After, out, keptColumn, keptSlab);
        if (from.at.sheets > 0 && !keptColumn)
            growAt(from, index, remaining, Where::Column, out, keptColumn, keptSlab);
        if (from.at.sheets > 0 && !keptSlab)
            growAt(from, index, remaining, Where::Slab, out, keptColumn, keptSlab);
        if (out.size() == before && (p_.sheets < 0 || from.at.sheets < p_.sheets))
            growAt(from, index, remaining, Where::Sheet, out, keptColumn, keptSlab);
    }

    /// `from` grown by a unit of `part` in its `pose`-th pose at `where`; nothing when it does not fit there.
    std::optional<Partial> child(const Partial& from, int index, int part, int pose, Where where) const
    {
        const Pose& unit = p_.poses[part][pose];
        Partial next = from;
        if (!placed(next, where, along(unit, a_), along(unit, b_)))
            return std::nullopt;
        const double area = unit.w * unit.h;
        next.laid += area;
        next.squares += area * area;
        next.lastSheet = (where == Where::Sheet ? 0 : from.lastSheet) + area;
        next.units += unitHash(part);
        next.parent = index;
        next.step = {part, unit, where, a_};
        next.guide = guided(next);
        return next;
    }

private:
    /// The candidates grown at `where`; `keptColumn` and `keptSlab` set when one leaves the open column and
    /// slab (or the slab) their sizes.
    void growAt(const Partial& from, int index, const std::vector<int>& remaining, Where where,
                std::vector<Candidate>& out, bool& keptColumn, bool& keptSlab) const
    {
        for (int part = 0; part < static_cast<int>(remaining.size()); ++part)
            for (int pose = 0; remaining[part] > 0 && pose < static_cast<int>(p_.poses[part].size()); ++pose)
                if (const std::optional<Partial> next = child(from, index, part, pose, where)) {
                    out.push_back({next->guide, next->laid, index, part, pose, where});
                    keptSlab = keptSlab || ((where == Where::After || where == Where::Column) &&
                                            next->at.slab == from.at.slab);
                    keptColumn = keptColumn || (where == Where::After && next->at.slab == from.at.slab &&
                                                next->at.column == from.at.column);
                }
    }

    bool leaves(double room, double size) const { return leavesSawable(room, size, p_.clearance); }

    double guided(const Partial& n) const
    {
        const double lost = n.waste / std::max(n.laid + n.waste, kHair);
        switch (guide_) {
            case Guide::Lost:
                return lost;
            case Guide::LostPerArea:
                return (0.1 + lost) / std::max(n.laid, kHair);
            case Guide::LostPerSquare:
                return (0.1 + lost) / std::max(n.squares, kHair);
        }
        return lost;
    }

    /// `extent` (a slab's or column's size, the units laid in it reaching `filled`) made to hold `size`
    /// within `room`: kept when the units leave a strip a cut can take off, grown to `size` when it fits and
    /// the strip it adds beside the units laid can be cut off; false when neither.
    bool holds(double& extent, double filled, double size, double room) const
    {
        if (size <= extent + kHair)
            return leaves(extent - filled, size - filled);
        if (!leaves(room, size) || !leaves(size, extent))
            return false;
        extent = size;
        return true;
    }

    /// Lays a unit of extents `pa` along a and `pb` across at `where` in `n`, growing the open slab and
    /// column to hold it, and adds the area it closes off to its waste; false when it does not fit there.
    bool placed(Partial& n, Where where, double pa, double pb) const
    {
        Frontier& f = n.at;
        const Frontier was = f;
        // What closing the open column, slab and sheet leaves unused.
        const double column = f.column * (f.slab - f.filled),
                     slab = (p_.size[b_] - f.columnAt - f.column) * f.slab,
                     sheet = (p_.size[a_] - f.slabAt - f.slab) * p_.size[b_];
        switch (where) {
            case Where::After:
                if (!holds(f.column, 0, pb, p_.size[b_] - f.columnAt) ||
                    !holds(f.slab, f.filled, f.filled + pa, p_.size[a_] - f.slabAt))
                    return false;
                n.waste += (f.column - pb) * pa + (f.column - was.column) * was.filled +
                           (f.slab - was.slab) * f.columnAt;
                f.filled += pa;
                return true;
            case Where::Column:
                if (!leaves(p_.size[b_] - f.columnAt - f.column, pb))
                    return false;
                f.columnAt += f.column;
                if (!holds(f.slab, 0, pa, p_.size[a_] - f.slabAt))
                    return false;
                n.waste += column + (f.slab - was.slab) * f.columnAt;
                break;
            case Where::Slab:
                if (!leaves(p_.size[a_] - f.slabAt - f.slab, pa) || !leaves(p_.size[b_], pb))
                    return false;
                n.waste += column + slab;
                f.slabAt += f.slab, f.columnAt = 0, f.slab = pa;
                break;
            case Where::Sheet:
                if (!leaves(p_.size[a_], pa) || !leaves(p_.size[b_], pb))
                    return false;
                if (f.sheets > 0)
                    n.waste += column + slab + sheet;
                ++f.sheets, f.slabAt = 0, f.columnAt = 0, f.slab = pa;
                break;
        }
        f.column = pb, f.filled = pa;
        return true;
    }

    const BeamProblem& p_;
    Guide guide_;
    int a_, b_;
};

/// The `width` best of `candidates` grown from `level` with distinct keys, sorted a few widths at a time:
/// most candidates are never looked at.
std::vector<Partial> bestDistinct(const Beam& beam, const std::vector<Partial>& level,
                                  std::vector<Candidate>& candidates, size_t width)
{
    std::vector<Partial> kept;
    std::unordered_set<std::uint64_t> seen;
    for (size_t from = 0; from < candidates.size() && kept.size() < width;) {
        const size_t to = std::min(candidates.size(), from + 4 * width);
        std::nth_element(candidates.begin() + from, candidates.begin() + to - 1, candidates.end());
        std::sort(candidates.begin() + from, candidates.begin() + to);
        for (; from < to && kept.size() < width; ++from) {
            const Candidate& c = candidates[from];
            Partial n = *beam.child(level[c.parent], c.parent, c.part, c.pose, c.where);
            if (seen.insert(n.key()).second)
                kept.push_back(std::move(n));
        }
    }
    return kept;
}

/// One beam search of `width`: the steps of its best complete layout, fewest sheets then least laid on the
/// last; nothing when the deadline passes or the sheets run out. `candidates`: memory kept between searches.
std::optional<std::pair<Partial, std::vector<SawStep>>> search(const BeamProblem& problem, size_t width,
                                                               Guide guide, int axis,
                                                               std::vector<Candidate>& candidates,
                                                               Deadline deadline)
{
    const Beam beam(problem, guide, axis);
    const long units = std::accumulate(problem.quantities.begin(), problem.quantities.end(), 0L);
    std::vector<Partial> level{Partial{}};
    std::vector<std::vector<int>> remaining{problem.quantities};
    std::vector<std::vector<std::pair<int, SawStep>>> history;  // per depth: parent and step of each kept
    for (long depth = 0; depth < units; ++depth) {
        if (deadline.passed())
            return std::nullopt;
        candidates.clear();
        for (size_t k = 0; k < level.size(); ++k)
            beam.grow(level[k], static_cast<int>(k), remaining[k], candidates);
        if (candidates.empty())
            return std::nullopt;
        level = bestDistinct(beam, level, candidates, width);
        std::vector<std::vector<int>> next;
        history.emplace_back();
        for (const Partial& n : level) {
            next.push_back(remaining[n.parent]);
            --next.back()[n.step.part];
            history.back().push_back({n.parent, n.step});
        }
        remaining = std::move(next);
    }
    size_t best = 0;
    for (size_t k = 1; k < level.size(); ++k)
        if (rank(level[k]) < rank(level[best]))
            best = k;
    std::vector<SawStep> steps(units);
    for (long depth = units - 1, k = static_cast<long>(best); depth >= 0; --depth) {
        steps[depth] = history[depth][k].second;
        k = history[depth][k].first;
    }
    return std::pair{level[best], std::move(steps)};
}

/// Sets each step's `extent`: the size of the slab it leads along its axis (its longest column) and of the
/// column it leads across (its widest unit), as the units after it grew them.
void measureLeads(std::vector<SawStep>& steps)
{
    SawStep *slab = nullptr, *column = nullptr;
    double filled = 0;
    for (SawStep& step : steps) {
        const int a = step.axis, b = 1 - a;
        filled = (step.where == Where::After ? filled : 0) + along(step.pose, a);
        if (step.where == Where::Sheet || step.where == Where::Slab)
            slab = &step;
        if (step.where != Where::After)
            column = &step;
        slab->extent[a] = std::max(slab->extent[a], filled);
        column->extent[b] = std::max(column->extent[b], along(step.pose, b));
    }
}

}  // namespace

std::optional<std::vector<SawStep>> beamSearch(const BeamProblem& problem, long widest, Deadline deadline)
{
    long branching = 0;  // the partial layouts one grows into at most
    for (size_t p = 0; p < problem.quantities.size(); ++p)
        branching += problem.quantities[p] > 0 ? 3 * static_cast<long>(problem.poses[p].size()) : 0;
    widest = std::min(widest, std::max(1L, kMostCandidates / std::max(1L, branching)));
    std::optional<std::pair<Partial, std::vector<SawStep>>> best;
    std::vector<Candidate> candidates;
    for (long width = 1; !deadline.passed(); width *= 2) {
        for (int axis : problem.axes)
            for (Guide guide : kGuides) {
                auto found = search(problem, static_cast<size_t>(width), guide, axis, candidates, deadline);
                if (found && (!best || rank(found->first) < rank(best->first)))
                    best = std::move(found);
            }
        if (width > widest / 2)
            break;
    }
    if (!best)
        return std::nullopt;
    measureLeads(best->second);
    return std::move(best->second);
}

}  // namespace fabguide::material
