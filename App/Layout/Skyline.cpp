#include "Layout/Skyline.h"

#include "Layout/MaxRects.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <tuple>
#include <utility>

namespace fabguide::material {

namespace {

constexpr double kSameSize = 1e-6;  // mm: what counts as the same height or width
// Candidates a node keeps for its backtracking: about one node in 4,000 tries more on the benchmark's largest
// strips, and a strip of thousands of units would otherwise hold thousands at each of its thousands of levels
// (3,000 rectangles: 259 MB, now 40 MB).
constexpr size_t kCandidates = 32;

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
            sizes.emplace_back(std::round(pose.w / kSameSize) * kSameSize,
                               std::round(pose.h / kSameSize) * kSameSize);
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

/// The tree search at one target height from a skyline, within `nodes` nodes and `work` (counted as
/// kSkylineWorkPerSecond tells).
class Search {
public:
    Search(std::vector<Kind> kinds, std::vector<Segment> skyline, double height, double waste, bool whole,
           long nodes, long work, std::optional<std::uint64_t> shuffle, Deadline deadline)
        : kinds_(std::move(kinds)),
          height_(height),
          wasteLeft_(waste),
          whole_(whole),
          nodesLeft_(nodes),
          mostWork_(work),
          random_(shuffle.value_or(0)),
          shuffled_(shuffle.has_value()),
          deadline_(deadline),
          skyline_(std::move(skyline))
    {
        const double width = skyline_.back().x + skyline_.back().w;
        const double widthWeight =
            shuffled_ ? std::uniform_real_distribution<double>(1.0, 3.0)(random_) : 2.0;
        const auto lowest = [&](size_t k) {
            double h = HUGE_VAL;
            for (const Pose& pose : kinds_[k].poses)
                h = std::min(h, pose.h);
            return h;
        };
        for (size_t k = 0; k < kinds_.size(); ++k) {
            tallFirst_.push_back(k);
            const std::vector<Pose>& poses = kinds_[k].poses;
            scores_.emplace_back();
            for (const Pose& pose : poses)
                scores_.back().push_back(std::pow(pose.w, widthWeight) * pose.h);
            wholeWidths_.emplace_back(std::lround(poses.front().w), std::lround(poses.back().w));
        }
        if (whole_)
            unitsOfWidth_.assign(static_cast<size_t>(std::lround(width)) + 1, 0);
        for (size_t k = 0; k < kinds_.size(); ++k)
            take(k, -std::exchange(kinds_[k].left, 0));
        std::stable_sort(tallFirst_.begin(), tallFirst_.end(),
                         [&](size_t a, size_t b) { return lowest(a) > lowest(b); });
    }

    /// Whether every unit was put within the nodes and work; then puts() is the packing on the skyline.
    bool run() { return fill(); }
    const std::vector<Put>& puts() const { return puts_; }
    long work() const { return work_; }

private:
    struct Candidate {
        std::tuple<bool, bool, double> rank;  // lower first: top not level with a neighbour, not the gap's
        int kind = 0, pose = 0;               // width, larger w^k·h (jittered when shuffled)
    };

    /// Whether candidate `a` comes after `b`: candidates() is a heap, the best on top.
    static bool later(const Candidate& a, const Candidate& b) { return a.rank > b.rank; }

    /// Whether the nodes, the work or the time have run out, a node charged.
    bool outOfWork()
    {
        work_ += 64 + static_cast<long>(kinds_.size() + skyline_.size());
        if (--nodesLeft_ >= 0 && nodesLeft_ % 256 == 0 && deadline_.passed())
            nodesLeft_ = -1;
        return spent();
    }

    /// Whether the nodes or the work have run out (the time too, once a node saw it).
    bool spent() const { return nodesLeft_ < 0 || work_ > mostWork_; }

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

    /// The best kCandidates units that fit at the chosen end of segment `at`, as a heap with the best on top.
    std::vector<Candidate> candidates(size_t at)
    {
        const Segment& s = skyline_[at];
        const auto [left, right] = neighbours(at);
        const double near = atRight(at) ? right : left, far = atRight(at) ? left : right;
        std::uniform_real_distribution<double> jitter(0.8, 1.2);
        std::vector<Candidate>& found = ranked_;
        found.clear();
        for (size_t k = 0; k < kinds_.size(); ++k) {
            if (kinds_[k].left == 0)
                continue;
            for (size_t p = 0; p < kinds_[k].poses.size(); ++p) {
                const Pose& pose = kinds_[k].poses[p];
                if (pose.w > s.w + kSameSize || s.y + pose.h > height_ + kSameSize)
                    continue;
                const bool exact = pose.w > s.w - kSameSize;
                const double top = s.y + pose.h;
                const bool level =
                    std::abs(top - near) < kSameSize || (exact && std::abs(top - far) < kSameSize);
                const double score = scores_[k][p] * (shuffled_ ? jitter(random_) : 1.0);
                found.push_back({{!level, !exact, -score}, static_cast<int>(k), static_cast<int>(p)});
            }
        }
        work_ += 11 * static_cast<long>(found.size());
        const auto kept = found.begin() + static_cast<long>(std::min(found.size(), kCandidates));
        std::nth_element(found.begin(), kept, found.end(),
                         [](const Candidate& a, const Candidate& b) { return later(b, a); });
        std::vector<Candidate> best(found.begin(), kept);
        std::make_heap(best.begin(), best.end(), later);
        return best;
    }

    /// Takes `units` of kind `k` (gives them back when negative).
    void take(size_t k, int units)
    {
        kinds_[k].left -= units;
        unitsLeft_ -= units;
        if (!whole_)
            return;
        const auto [along, across] = wholeWidths_[k];
        const auto count = [&](size_t w) {
            if (w < unitsOfWidth_.size())
                unitsOfWidth_[w] -= units;
        };
        count(along);
        if (across != along)
            count(across);
    }

    /// Merges segment `at` with its neighbours of the same height.
    void merge(size_t at)
    {
        if (at + 1 < skyline_.size() && std::abs(skyline_[at + 1].y - skyline_[at].y) < kSameSize) {
            skyline_[at].w += skyline_[at + 1].w;
            skyline_.erase(skyline_.begin() + static_cast<long>(at) + 1);
        }
        if (at > 0 && std::abs(skyline_[at - 1].y - skyline_[at].y) < kSameSize) {
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
        take(c.kind, 1);
        if (pose.w > s.w - kSameSize) {
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
                run = s.y + pose.h <= height_ + kSameSize ? run + s.w : 0;
                if (run >= pose.w - kSameSize)
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
        double shortest = HUGE_VAL;
        for (const Kind& kind : kinds_)
            if (kind.left > 0)
                for (const Pose& pose : kind.poses)
                    shortest = std::min(shortest, pose.h);
        valleys_.clear();
        double widest = 0;
        for (size_t at = 0; at < skyline_.size(); ++at) {
            const auto [left, right] = neighbours(at);
            const double rise = std::min({left - skyline_[at].y, right - skyline_[at].y, shortest});
            if (rise > 0 && rise < HUGE_VAL) {
                valleys_.push_back({skyline_[at].w, rise});
                widest = std::max(widest, skyline_[at].w);
            }
        }
        if (valleys_.empty() || !whole_)
            return 0;  // sizes not whole: any width is taken to fill
        double waste = 0;
        bool summed = false;  // subset sums only when some valley is as wide as no unit left
        for (const auto& [width, rise] : valleys_) {
            size_t filled = static_cast<size_t>(std::lround(width));
            if (unitsOfWidth_[filled] > 0)
                continue;
            if (!summed)
                fillableWidths(static_cast<size_t>(std::lround(widest)));
            summed = true;
            while (!(sums_[filled / 64] >> (filled % 64) & 1))
                --filled;
            waste += (width - static_cast<double>(filled)) * rise;
        }
        return waste;
    }

    /// Sets sums_ bit i (up to `most`) when the whole widths of some units left, side by side, each either
    /// way it lies, add up to i: a bounded subset sum by word shifts, in place from the top word down.
    void fillableWidths(size_t most)
    {
        sums_.assign(most / 64 + 1, 0);
        sums_[0] = 1;
        size_t words = 0;  // shifted in
        for (size_t k = 0; k < kinds_.size(); ++k) {
            const auto [along, across] = wholeWidths_[k];
            const size_t useful = most / std::min(along, across);
            for (int unit = 0; unit < kinds_[k].left && static_cast<size_t>(unit) < useful; ++unit) {
                std::uint64_t grown = 0;
                for (size_t i = sums_.size(); i-- > 0;) {
                    std::uint64_t word = sums_[i];
                    for (const size_t by : {along, across})
                        if (i >= by / 64) {
                            const size_t from = i - by / 64, bit = by % 64;
                            word |=
                                sums_[from] << bit | (bit && from > 0 ? sums_[from - 1] >> (64 - bit) : 0);
                        }
                    grown |= word ^ sums_[i];
                    sums_[i] = word;
                }
                words += sums_.size();
                if (!grown)
                    break;  // more of this kind add no sum
            }
        }
        work_ += static_cast<long>(words / 2);
    }

    /// Fills the lowest, leftmost gap of the skyline, then the rest; false when out of nodes or room.
    bool fill()
    {
        if (unitsLeft_ == 0)
            return true;
        if (outOfWork() || wasteInValleys() > wasteLeft_ + kSameSize || !roomForTallest())
            return false;
        const auto lowest =
            std::min_element(skyline_.begin(), skyline_.end(),
                             [](const Segment& a, const Segment& b) { return a.y < b.y - kSameSize; });
        const size_t at = static_cast<size_t>(lowest - skyline_.begin());
        const std::vector<Segment> before = skyline_;
        for (std::vector<Candidate> found = candidates(at); !found.empty(); found.pop_back()) {
            std::pop_heap(found.begin(), found.end(), later);
            const Candidate c = found.back();
            put(at, c);
            if (fill())
                return true;
            puts_.pop_back();
            take(c.kind, -1);
            skyline_ = before;
            if (spent())
                return false;
        }
        // Left as waste: the gap raised to its lower neighbour.
        const auto [left, right] = neighbours(at);
        const double level = std::min(left, right), waste = skyline_[at].w * (level - skyline_[at].y);
        if (level == HUGE_VAL || waste > wasteLeft_ + kSameSize)
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
    long nodesLeft_, mostWork_, work_ = 0, unitsLeft_ = 0;  // work_: done so far
    std::mt19937_64 random_;
    bool shuffled_;
    Deadline deadline_;
    std::vector<Segment> skyline_;
    std::vector<Put> puts_;
    std::vector<Candidate> ranked_;  // candidates() ranks every unit that fits here, then keeps the best
    std::vector<std::vector<double>> scores_;  // of each kind's poses: larger w^k·h first, k random in [1, 3]
    std::vector<size_t> tallFirst_;            // the kinds, tallest lying lowest first
    std::vector<std::pair<size_t, size_t>> wholeWidths_;  // of each kind's two poses (alike when it has one)
    std::vector<std::pair<double, double>> valleys_;      // width, rise
    std::vector<std::uint64_t> sums_;                     // bit i: the widths of some units left add up to i
    std::vector<int> unitsOfWidth_;                       // units left that lie as wide as the index
};

/// The top of unit `put` of `kinds`.
double topOf(const Put& put, const std::vector<Kind>& kinds)
{
    return put.y + kinds[put.kind].poses[put.pose].h;
}

/// The top of the highest of `puts`.
double topOf(const std::vector<Put>& puts, const std::vector<Kind>& kinds)
{
    double top = 0;
    for (const Put& put : puts)
        top = std::max(top, topOf(put, kinds));
    return top;
}

/// The skyline of `puts` on a strip `width` wide: the top of the highest unit above each point.
std::vector<Segment> skylineOf(const std::vector<Put>& puts, const std::vector<Kind>& kinds, double width)
{
    std::vector<Segment> skyline{{0, width, 0}};
    for (const Put& put : puts) {
        const double x0 = put.x, x1 = put.x + kinds[put.kind].poses[put.pose].w, top = topOf(put, kinds);
        std::vector<Segment> raised;
        for (const Segment& s : skyline) {
            const double a = std::max(s.x, x0), b = std::min(s.x + s.w, x1);
            if (b <= a + kSameSize || s.y >= top) {
                raised.push_back(s);
                continue;
            }
            if (a > s.x + kSameSize)
                raised.push_back({s.x, a - s.x, s.y});
            raised.push_back({a, b - a, top});
            if (s.x + s.w > b + kSameSize)
                raised.push_back({b, s.x + s.w - b, s.y});
        }
        skyline.clear();
        for (const Segment& s : raised)
            if (!skyline.empty() && std::abs(skyline.back().y - s.y) < kSameSize)
                skyline.back().w += s.w;
            else
                skyline.push_back(s);
    }
    return skyline;
}

/// The packing `puts` of `kinds` as a layout of `problem`'s strip.
Layout layoutOf(const PackProblem& problem, std::vector<Kind> kinds, const std::vector<Put>& puts)
{
    const PackSettings& s = problem.settings;
    const double clearance = s.kerf + s.spacing;
    for (Kind& kind : kinds)  // each unit takes the last part of its kind
        kind.left = static_cast<int>(kind.parts.size());
    Layout layout;
    for (const Put& put : puts) {
        Kind& kind = kinds[put.kind];
        const Pose& pose = kind.poses[put.pose];
        const int part = kind.parts[static_cast<size_t>(--kind.left)];
        int rotation = 0;  // parts of a kind lie alike, each turned its own way to do so
        for (const Pose& own : posesOn(problem.parts[part], problem.boards[0], clearance))
            if (std::abs(own.w - pose.w) < kSameSize && std::abs(own.h - pose.h) < kSameSize)
                rotation = own.rotation;
        layout.placements.push_back(
            {part, 0, s.trim + put.x, s.trim + put.y, rotation, pose.w - clearance, pose.h - clearance});
        layout.partArea += geometry::area(problem.parts[part].outline);
    }
    layout.stripHeight = topOf(puts, kinds) - clearance + 2 * s.trim;
    MasterBoard sheet = problem.boards[0];
    sheet.count = 1;
    sheet.height = layout.stripHeight;
    layout.sheets = {sheet};
    layout.sheetArea = layout.boundingArea = sheet.width * sheet.height;
    return layout;
}

/// Whether the strip's width and every size are whole numbers (of millimetres).
bool allWhole(const std::vector<Kind>& kinds, double width)
{
    const auto whole = [](double v) { return std::abs(v - std::round(v)) < kSameSize; };
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
            if (pose.w <= strip.width + kSameSize)
                lowest = std::min(lowest, pose.h);
        strip.area += kind.area * kind.left;
        strip.units += kind.left;
        tallest = std::max(tallest, lowest);
    }
    strip.whole = allWhole(strip.kinds, strip.width);
    strip.step = strip.whole ? 1.0 : s.resolution;
    strip.least =
        std::ceil(std::max(strip.area / strip.width, tallest) / strip.step - kSameSize) * strip.step;
    return strip;
}

}  // namespace

double leastStripHeight(const PackProblem& problem)
{
    const PackSettings& s = problem.settings;
    return stripOf(problem).least - s.kerf - s.spacing + 2 * s.trim;
}

std::optional<Layout> skylineStrip(const PackProblem& problem, const SkylineBudget& budget, Deadline deadline)
{
    const Strip strip = stripOf(problem);
    if (strip.kinds.empty() || strip.units > kSkylineUnits)
        return std::nullopt;
    const double step = strip.step, least = strip.least;
    const auto nodesFor = [](double units) { return std::max(200L, static_cast<long>(2 * units)); };
    long work = budget.work;
    std::mt19937_64 random(budget.seed);
    std::vector<Put> best;
    double ceiling = HUGE_VAL;  // the lowest strip found, with clearance: lower ones are sought
    // A search at `height` for the units after the first `kept` of the lowest strip found, on their skyline
    // and with the waste they leave; within `size` nodes and the work left.
    const auto tried = [&](double height, size_t kept, long size, std::optional<std::uint64_t> shuffle) {
        const bool greedy = height == HUGE_VAL;  // a first strip, whatever the work and time
        std::vector<Put> puts(best.begin(), best.begin() + static_cast<long>(kept));
        std::vector<Kind> kinds = strip.kinds;
        double keptArea = 0;
        for (const Put& put : puts) {
            --kinds[put.kind].left;
            keptArea += kinds[put.kind].area;
        }
        std::vector<Segment> skyline = skylineOf(puts, kinds, strip.width);
        double under = 0;  // the area under the skyline
        for (const Segment& s : skyline)
            under += s.w * s.y;
        Search search(std::move(kinds), std::move(skyline), height,
                      height * strip.width - strip.area - (under - keptArea), strip.whole, size,
                      greedy ? std::numeric_limits<long>::max() : work, shuffle,
                      greedy ? Deadline() : deadline);
        const bool found = search.run();
        work -= search.work();
        puts.insert(puts.end(), search.puts().begin(), search.puts().end());
        if (found && topOf(puts, strip.kinds) < ceiling) {
            best = std::move(puts);
            ceiling = topOf(best, strip.kinds);
        }
        return found;
    };
    const auto left = [&] { return work > 0 && !deadline.passed(); };
    // Greedily (no height, waste as it comes: one node a unit or a gap, past the budget and deadline); then a
    // short search at heights bisected between the lower bound and the lowest strip found.
    tried(HUGE_VAL, 0, static_cast<long>(2 * strip.units) + 1, std::nullopt);
    for (double low = least; ceiling - low > step + kSameSize && left();) {
        const double height = std::floor((low + ceiling) / 2 / step) * step;
        if (!tried(height, 0, nodesFor(strip.units), std::nullopt))
            low = height;
    }
    // Then rounds just below the lowest strip found. Five in six keep a random number of its first units,
    // up to all that lie below the target, and search the rest again: from its top to the whole strip. The
    // sixth starts afresh, every fourth of those at the lower bound.
    for (long round = 1; least < ceiling - kSameSize && left(); ++round) {
        const double target = std::max(least, ceiling - step);
        if (round % 6 == 0) {
            tried(round % 24 == 0 ? least : target, 0, nodesFor(strip.units), random());
            continue;
        }
        size_t below = 0;
        while (below < best.size() && topOf(best[below], strip.kinds) <= target + kSameSize)
            ++below;
        const size_t kept = std::uniform_int_distribution<size_t>(0, below)(random);
        tried(target, kept, nodesFor(static_cast<double>(best.size() - kept)), random());
    }
    if (best.empty())
        return std::nullopt;
    return layoutOf(problem, strip.kinds, best);
}

}  // namespace fabguide::material
