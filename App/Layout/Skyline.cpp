#include "Layout/Skyline.h"

#include "Layout/MaxRects.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <tuple>
#include <utility>

namespace fabguide::material {

namespace {

constexpr double kHair = 1e-6;  // mm: what counts as the same height or width

/// Units that lie alike: the same poses (sizes with the clearance added); the part of each unit.
struct Kind {
    std::vector<Pose> poses;
    std::vector<int> parts;
    int left = 0;
    double area = 0;
};

/// A stretch of the skyline: from x, w wide, at height y.
struct Segment {
    double x = 0, w = 0, y = 0;
};

/// A unit of `kind` put in `pose` with its lower-left corner at x, y.
struct Put {
    int kind = 0, pose = 0;
    double x = 0, y = 0;
};

/// The kinds of `problem`'s units; none when a part has no square pose on the strip.
std::vector<Kind> kindsOf(const PackProblem& problem, double clearance)
{
    std::map<std::vector<std::pair<double, double>>, size_t> index;  // sizes of the poses -> kind
    std::vector<Kind> kinds;
    for (size_t p = 0; p < problem.parts.size(); ++p) {
        const PartSpec& part = problem.parts[p];
        std::vector<Pose> poses = posesOn(part, problem.boards[0], clearance);
        if (poses.empty())
            return {};  // a part that lies no square way on the strip: Docking's to place
        std::vector<std::pair<double, double>> sizes;
        for (const Pose& pose : poses)
            sizes.emplace_back(std::round(pose.w / kHair) * kHair, std::round(pose.h / kHair) * kHair);
        std::sort(sizes.begin(), sizes.end());
        const auto [at, added] = index.emplace(sizes, kinds.size());
        if (added)
            kinds.push_back({poses, {}, 0, poses.front().w * poses.front().h});
        Kind& kind = kinds[at->second];
        kind.parts.insert(kind.parts.end(), part.quantity, static_cast<int>(p));
        kind.left += part.quantity;
    }
    return kinds;
}

/// The tree search at one target height, `nodes` at most.
class Search {
public:
    Search(std::vector<Kind> kinds, double width, double height, double waste, bool whole, long nodes,
           std::optional<std::uint64_t> shuffle, std::chrono::steady_clock::time_point deadline)
        : kinds_(std::move(kinds)),
          height_(height),
          wasteLeft_(waste),
          whole_(whole),
          nodesLeft_(nodes),
          random_(shuffle.value_or(0)),
          shuffled_(shuffle.has_value()),
          deadline_(deadline)
    {
        skyline_.push_back({0, width, 0});
        if (shuffled_)
            widthWeight_ = std::uniform_real_distribution<double>(1.0, 3.0)(random_);
        const auto lowest = [&](size_t k) {
            double h = HUGE_VAL;
            for (const Pose& pose : kinds_[k].poses)
                h = std::min(h, pose.h);
            return h;
        };
        for (size_t k = 0; k < kinds_.size(); ++k) {
            unitsLeft_ += kinds_[k].left;
            tallFirst_.push_back(k);
        }
        std::stable_sort(tallFirst_.begin(), tallFirst_.end(),
                         [&](size_t a, size_t b) { return lowest(a) > lowest(b); });
    }

    /// Whether every unit was put within the nodes; then puts() is the packing.
    bool run() { return fill(); }
    const std::vector<Put>& puts() const { return puts_; }
    double top() const
    {
        double top = 0;
        for (const Put& put : puts_)
            top = std::max(top, put.y + kinds_[put.kind].poses[put.pose].h);
        return top;
    }
    const std::vector<Kind>& kinds() const { return kinds_; }
    long nodesLeft() const { return nodesLeft_; }

private:
    struct Candidate {
        std::tuple<bool, bool, double> rank;  // lower first: top not level with a neighbour, not the gap's
        int kind = 0, pose = 0;               // width, larger w^k·h (jittered when shuffled)
    };

    bool outOfNodes()
    {
        if (--nodesLeft_ < 0)
            return true;
        if (nodesLeft_ % 1024 == 0 && std::chrono::steady_clock::now() > deadline_)
            nodesLeft_ = -1;
        return nodesLeft_ < 0;
    }

    /// The heights of segment `at`'s left and right neighbours; a wall is infinitely high.
    std::pair<double, double> neighbours(size_t at) const
    {
        return {at > 0 ? skyline_[at - 1].y : HUGE_VAL,
                at + 1 < skyline_.size() ? skyline_[at + 1].y : HUGE_VAL};
    }

    /// Whether units go at the right end of segment `at`: its right neighbour is the higher (Wei et al.
    /// 2011), so what the unit leaves of the gap lies by the lower. Either end of the lowest gap is some
    /// unit's corner in a packing without waste.
    bool atRight(size_t at) const
    {
        const auto [left, right] = neighbours(at);
        return right > left;
    }

    /// The units that fit at the chosen end of segment `at`, best first.
    std::vector<Candidate> candidates(size_t at)
    {
        const Segment& s = skyline_[at];
        const auto [left, right] = neighbours(at);
        const double near = atRight(at) ? right : left, far = atRight(at) ? left : right;
        std::uniform_real_distribution<double> jitter(0.8, 1.2);
        std::vector<Candidate> found;
        for (size_t k = 0; k < kinds_.size(); ++k) {
            if (kinds_[k].left == 0)
                continue;
            for (size_t p = 0; p < kinds_[k].poses.size(); ++p) {
                const Pose& pose = kinds_[k].poses[p];
                if (pose.w > s.w + kHair || s.y + pose.h > height_ + kHair)
                    continue;
                const bool exact = pose.w > s.w - kHair;
                const double top = s.y + pose.h;
                const bool level = std::abs(top - near) < kHair || (exact && std::abs(top - far) < kHair);
                const double score =
                    std::pow(pose.w, widthWeight_) * pose.h * (shuffled_ ? jitter(random_) : 1.0);
                found.push_back({{!level, !exact, -score}, static_cast<int>(k), static_cast<int>(p)});
            }
        }
        std::sort(found.begin(), found.end(),
                  [](const Candidate& a, const Candidate& b) { return a.rank < b.rank; });
        return found;
    }

    /// Merges segment `at` with its neighbours of the same height.
    void merge(size_t at)
    {
        if (at + 1 < skyline_.size() && std::abs(skyline_[at + 1].y - skyline_[at].y) < kHair) {
            skyline_[at].w += skyline_[at + 1].w;
            skyline_.erase(skyline_.begin() + static_cast<long>(at) + 1);
        }
        if (at > 0 && std::abs(skyline_[at - 1].y - skyline_[at].y) < kHair) {
            skyline_[at - 1].w += skyline_[at].w;
            skyline_.erase(skyline_.begin() + static_cast<long>(at));
        }
    }

    void put(size_t at, const Candidate& c)
    {
        const Pose& pose = kinds_[c.kind].poses[c.pose];
        const bool right = atRight(at);
        const Segment s = skyline_[at];
        const Segment unit{right ? s.x + s.w - pose.w : s.x, pose.w, s.y + pose.h};
        puts_.push_back({c.kind, c.pose, unit.x, s.y});
        --kinds_[c.kind].left;
        --unitsLeft_;
        if (pose.w > s.w - kHair) {
            skyline_[at] = {s.x, s.w, unit.y};
        } else if (right) {
            skyline_[at].w -= pose.w;
            skyline_.insert(skyline_.begin() + static_cast<long>(++at), unit);
        } else {
            skyline_[at] = unit;
            skyline_.insert(skyline_.begin() + static_cast<long>(at) + 1, {s.x + pose.w, s.w - pose.w, s.y});
        }
        merge(at);
    }

    /// Whether a stretch of the skyline is wide and low enough for some pose of each of the tallest kinds
    /// left, which run out of room first as the skyline rises.
    bool roomForTallest() const
    {
        const auto fits = [&](const Pose& pose) {
            double run = 0;
            for (const Segment& s : skyline_) {
                run = s.y + pose.h <= height_ + kHair ? run + s.w : 0;
                if (run >= pose.w - kHair)
                    return true;
            }
            return false;
        };
        int checked = 0;
        for (size_t k = 0; k < tallFirst_.size() && checked < 4; ++k) {
            const Kind& kind = kinds_[tallFirst_[k]];
            if (kind.left == 0)
                continue;
            ++checked;
            if (std::none_of(kind.poses.begin(), kind.poses.end(), fits))
                return false;
        }
        return true;
    }

    /// The least waste the skyline's valleys leave (segments lower than both neighbours, which only units
    /// as narrow fill): in each, what no units left fill of its width, up to the lower of its neighbours and
    /// the shortest unit left.
    double wasteInValleys()
    {
        double shortest = HUGE_VAL, waste = 0;
        widths_.clear();
        for (const Kind& kind : kinds_)
            if (kind.left > 0) {
                for (const Pose& pose : kind.poses)
                    shortest = std::min(shortest, pose.h);
                if (whole_)
                    widths_.push_back({static_cast<size_t>(std::lround(kind.poses.front().w)),
                                       static_cast<size_t>(std::lround(kind.poses.back().w)), kind.left});
            }
        for (size_t at = 0; at < skyline_.size(); ++at) {
            const Segment& s = skyline_[at];
            const auto [left, right] = neighbours(at);
            const double rise = std::min({left - s.y, right - s.y, shortest});
            if (rise > 0 && rise < HUGE_VAL)
                waste += (s.w - widestFill(s.w)) * rise;
        }
        return waste;
    }

    /// The widest the units left (widths_) can fill of a gap `gap` wide, side by side, each on either side: a
    /// subset sum of whole widths; `gap` itself when sizes are not whole.
    double widestFill(double gap)
    {
        const size_t g = static_cast<size_t>(std::lround(gap));
        if (!whole_ || std::any_of(widths_.begin(), widths_.end(),
                                   [&](const UnitWidths& u) { return u.along == g || u.across == g; }))
            return gap;
        sums_.assign(g / 64 + 1, 0);
        sums_[0] = 1;
        const auto shiftedIn = [&](size_t by) {
            for (size_t i = sums_.size(); i-- > by / 64;) {
                const size_t from = i - by / 64, bit = by % 64;
                next_[i] |= sums_[from] << bit | (bit && from > 0 ? sums_[from - 1] >> (64 - bit) : 0);
            }
        };
        const auto reached = [&](size_t i) { return sums_[i / 64] >> (i % 64) & 1; };
        for (const UnitWidths& u : widths_)
            for (int unit = 0; unit < u.units && !reached(g); ++unit) {
                next_ = sums_;
                for (const size_t w : {u.along, u.across})
                    if (w <= g)
                        shiftedIn(w);
                if (next_ == sums_)
                    break;  // more of this kind add no sum
                sums_.swap(next_);
            }
        sums_.back() &= g % 64 == 63 ? ~0ULL : (1ULL << (g % 64 + 1)) - 1;
        size_t widest = g;
        while (!reached(widest))
            --widest;
        return static_cast<double>(widest);
    }

    /// Fills the lowest, leftmost gap of the skyline, then the rest; false when out of nodes or room.
    bool fill()
    {
        if (unitsLeft_ == 0)
            return true;
        if (outOfNodes() || wasteInValleys() > wasteLeft_ + kHair || !roomForTallest())
            return false;
        const auto lowest =
            std::min_element(skyline_.begin(), skyline_.end(),
                             [](const Segment& a, const Segment& b) { return a.y < b.y - kHair; });
        const size_t at = static_cast<size_t>(lowest - skyline_.begin());
        const std::vector<Segment> before = skyline_;
        for (const Candidate& c : candidates(at)) {
            put(at, c);
            if (fill())
                return true;
            puts_.pop_back();
            ++kinds_[c.kind].left;
            ++unitsLeft_;
            skyline_ = before;
            if (nodesLeft_ < 0)
                return false;
        }
        // Left as waste: the gap raised to its lower neighbour.
        const auto [left, right] = neighbours(at);
        const double level = std::min(left, right), waste = skyline_[at].w * (level - skyline_[at].y);
        if (level == HUGE_VAL || waste > wasteLeft_ + kHair)
            return false;
        wasteLeft_ -= waste;
        skyline_[at].y = level;
        merge(at);
        if (fill())
            return true;
        wasteLeft_ += waste;
        skyline_ = before;
        return false;
    }

    std::vector<Kind> kinds_;
    double height_, wasteLeft_;
    bool whole_;  // every size a whole number: gaps are filled by subset sums of widths
    long nodesLeft_, unitsLeft_ = 0;
    std::mt19937_64 random_;
    bool shuffled_;
    std::chrono::steady_clock::time_point deadline_;
    std::vector<Segment> skyline_;
    std::vector<Put> puts_;
    double widthWeight_ = 2;
    std::vector<size_t> tallFirst_;  // the kinds, tallest lying lowest first
    struct UnitWidths {
        size_t along = 0, across = 0;  // whole widths of a kind's two poses (the same when it has one)
        int units = 0;                 // of the kind left
    };
    std::vector<UnitWidths> widths_;
    std::vector<std::uint64_t> sums_, next_;  // bit i: the widths of some units left add up to i
};

/// The packing `search` found as a layout of `problem`'s strip.
Layout layoutOf(const PackProblem& problem, const Search& search)
{
    const PackSettings& s = problem.settings;
    const double clearance = s.kerf + s.spacing;
    std::vector<Kind> kinds = search.kinds();  // each unit takes the last part of its kind
    for (Kind& kind : kinds)
        kind.left = static_cast<int>(kind.parts.size());
    Layout layout;
    double top = 0;
    for (const Put& put : search.puts()) {
        Kind& kind = kinds[put.kind];
        const Pose& pose = kind.poses[put.pose];
        const int part = kind.parts[static_cast<size_t>(--kind.left)];
        int rotation = 0;  // parts of a kind lie alike, each turned its own way to do so
        for (const Pose& own : posesOn(problem.parts[part], problem.boards[0], clearance))
            if (std::abs(own.w - pose.w) < kHair && std::abs(own.h - pose.h) < kHair)
                rotation = own.rotation;
        layout.placements.push_back(
            {part, 0, s.trim + put.x, s.trim + put.y, rotation, pose.w - clearance, pose.h - clearance});
        layout.partArea += geometry::area(problem.parts[part].outline);
        top = std::max(top, put.y + pose.h);
    }
    layout.stripHeight = top - clearance + 2 * s.trim;
    MasterBoard sheet = problem.boards[0];
    sheet.count = 1;
    sheet.height = layout.stripHeight;
    layout.sheets = {sheet};
    layout.sheetArea = layout.boundingArea = sheet.width * sheet.height;
    return layout;
}

/// The Luby sequence 1 1 2 1 1 2 4 1 1 2 ... at `i` (from 1): restart lengths for searches whose length
/// to success is unknown (Luby, Sinclair, Zuckerman 1993).
long luby(long i)
{
    long size = 1;
    while (size < i + 1)
        size = 2 * size + 1;  // 2^k - 1, the first at least i
    while (size != i) {
        size /= 2;
        if (i > size)
            i -= size;
    }
    return (size + 1) / 2;
}

/// Whether the strip's width and every size are whole numbers (of millimetres).
bool allWhole(const std::vector<Kind>& kinds, double width)
{
    const auto whole = [](double v) { return std::abs(v - std::round(v)) < kHair; };
    bool all = whole(width);
    for (const Kind& kind : kinds)
        for (const Pose& pose : kind.poses)
            all = all && whole(pose.w) && whole(pose.h);
    return all;
}

/// A strip problem as the search sees it: sizes with the clearance added, trim taken off.
struct Strip {
    std::vector<Kind> kinds;
    double width = 0, area = 0, units = 0;
    bool whole = false;  ///< every size whole: gaps are filled by subset sums, heights tried a unit apart
    double step = 0;     ///< between target heights
    double least = 0;    ///< the least height, a whole number of steps
};

Strip stripOf(const PackProblem& problem)
{
    const PackSettings& s = problem.settings;
    const double clearance = s.kerf + s.spacing;
    Strip strip;
    strip.width = problem.boards[0].width - 2 * s.trim + clearance;
    strip.kinds = kindsOf(problem, clearance);
    double tallest = 0;  // the least height the most awkward unit needs
    for (const Kind& kind : strip.kinds) {
        double lowest = HUGE_VAL;
        for (const Pose& pose : kind.poses)
            if (pose.w <= strip.width + kHair)
                lowest = std::min(lowest, pose.h);
        strip.area += kind.area * kind.left;
        strip.units += kind.left;
        tallest = std::max(tallest, lowest);
    }
    strip.whole = allWhole(strip.kinds, strip.width);
    strip.step = strip.whole ? 1.0 : s.resolution;
    strip.least = std::ceil(std::max(strip.area / strip.width, tallest) / strip.step - kHair) * strip.step;
    return strip;
}

}  // namespace

double leastStripHeight(const PackProblem& problem)
{
    const PackSettings& s = problem.settings;
    return stripOf(problem).least - s.kerf - s.spacing + 2 * s.trim;
}

std::optional<Layout> skylineStrip(const PackProblem& problem, const SkylineBudget& budget,
                                   std::chrono::steady_clock::time_point deadline)
{
    const Strip strip = stripOf(problem);
    if (strip.kinds.empty())
        return std::nullopt;
    const double step = strip.step, least = strip.least;
    const long base = std::max(200L, static_cast<long>(2 * strip.units));
    long nodes = budget.nodes;
    std::uint64_t seed = budget.seed;
    std::optional<Layout> best;
    double ceiling = HUGE_VAL;  // the lowest strip found, with clearance: lower ones are sought
    const auto tried = [&](double height, long size, std::optional<std::uint64_t> shuffle) {
        Search search(strip.kinds, strip.width, height, height * strip.width - strip.area, strip.whole, size,
                      shuffle, deadline);
        const bool found = search.run();
        nodes -= size - std::max(0L, search.nodesLeft());
        if (found && search.top() < ceiling) {
            best = layoutOf(problem, search);
            ceiling = search.top();
        }
        return found;
    };
    const auto left = [&] { return nodes > 0 && std::chrono::steady_clock::now() < deadline; };
    // Greedily (no height, waste as it comes: one node a unit or a gap, past the budget if need be); then a
    // short search at heights bisected between the lower bound and the lowest strip found; then restarts,
    // shuffled and longer by the Luby sequence, at the lower bound and just below the lowest strip found, in
    // turn.
    tried(HUGE_VAL, static_cast<long>(2 * strip.units) + 1, std::nullopt);
    for (double low = least; ceiling - low > step + kHair && left();) {
        const double height = std::floor((low + ceiling) / 2 / step) * step;
        if (!tried(height, std::min(base, nodes), std::nullopt))
            low = height;
    }
    for (long round = 1; least < ceiling - kHair && left(); ++round)
        tried(round % 6 == 0 ? least : std::max(least, ceiling - step), std::min(base * luby(round), nodes),
              seed++);
    return best;
}

}  // namespace fabguide::material
