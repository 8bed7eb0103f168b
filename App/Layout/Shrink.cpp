#include "Layout/Shrink.h"

#include "Core/Parallel.h"

#include <algorithm>
#include <array>
#include <limits>
#include <numeric>
#include <random>
#include <tuple>
#include <utility>

namespace fabguide::material {

namespace {

/// Where a unit lies: which of its shapes, and its lower-left cell.
struct Pose {
    int shape = 0;
    int x = 0;
    int y = 0;
};

/// How many units lie on each of the strip's cells, summed along each column from the strip's start, so that
/// what lies under a part is a difference per run of its columns.
class Occupancy {
public:
    Occupancy(int width, int length) : length_(length), sums_(static_cast<size_t>(width) * (length + 1), 0) {}

    /// Adds `amount` to every cell of `shape` with its lower-left cell at (x, y).
    void add(const Footprint& shape, int x, int y, int amount)
    {
        for (int c = 0; c < shape.width(); ++c) {
            int* sum = column(x + c);
            for (const auto& [from, to] : shape.runs(c)) {
                int k = y + from + 1;
                for (int added = amount; k <= y + to; ++k, added += amount)
                    sum[k] += added;
                for (const int added = amount * (to - from); k <= length_; ++k)
                    sum[k] += added;
                work_ += (length_ - y - from) / 16;
            }
        }
    }

    /// What lies under `shape` at (x, y), summed; once the sum reaches `bound` it may stop there.
    long under(const Footprint& shape, int x, int y, long bound) const
    {
        long total = 0;
        int c = 0;
        for (; c < shape.width() && total < bound; ++c) {
            const int* sum = column(x + c) + y;
            for (const auto& [from, to] : shape.runs(c))
                total += sum[to] - sum[from];
        }
        work_ += c;
        return total;
    }

    void clear() { std::fill(sums_.begin(), sums_.end(), 0); }

    /// The work done so far, as a budget counts it: a column summed counts one, as do sixteen cells updated
    /// (about as long).
    long work() const { return work_; }

private:
    int* column(int x) { return &sums_[static_cast<size_t>(x) * (length_ + 1)]; }
    const int* column(int x) const { return &sums_[static_cast<size_t>(x) * (length_ + 1)]; }

    int length_;
    std::vector<int> sums_;
    mutable long work_ = 0;
};

/// Cells two footprints share, each with its lower-left cell where given.
long shared(const Footprint& a, int ax, int ay, const Footprint& b, int bx, int by)
{
    const int from = std::max(ax, bx), to = std::min(ax + a.width(), bx + b.width());
    if (from >= to || ay >= by + b.height() || by >= ay + a.height())
        return 0;
    long cells = 0;
    for (int x = from; x < to; ++x) {
        const Footprint::Runs runsA = a.runs(x - ax), runsB = b.runs(x - bx);
        for (auto p = runsA.begin(), q = runsB.begin(); p != runsA.end() && q != runsB.end();) {
            const int pTo = p->second + ay, qTo = q->second + by;
            cells += std::max(0, std::min(pTo, qTo) - std::max(p->first + ay, q->first + by));
            (pTo < qTo ? p : q)++;
        }
    }
    return cells;
}

/// Random places tried for a part in each of its shapes, anywhere on the strip and near where it is, before
/// the best of them is refined by steps.
constexpr int kAnywhere = 32, kNearby = 16;
/// A separation gives up after this many rounds without less overlap.
constexpr int kStaleRounds = 50;
/// Slices drawn at random each time the strip is cut shorter; the one with the least material is removed.
constexpr int kSlices = 8;
/// The shrinking runs in this many phases, every search starting each from the lowest strip of the last.
constexpr int kPhases = 4;

/// One shrinking search: the units' poses on the strip, the last feasible ones, and their height.
class Shrinker {
public:
    Shrinker(const std::vector<RasterPart>& parts, const BoardStock& strip, std::vector<Pose> start,
             int height, double cut, std::uint64_t seed)
        : parts_(parts),
          strip_(strip),
          pose_(start),
          feasible_(std::move(start)),
          height_(height),
          overlap_(parts.size()),
          weights_(parts.size()),
          count_(strip.width, height),
          random_(seed),
          cut_(cut)
    {
    }

    /// Cuts the strip shorter while the work budget and the time last, down to `least`: by the share `cut`
    /// of its height, halved (down to a cell) each time the overlap left cannot be separated.
    void shrink(int least, long work, Deadline deadline)
    {
        work_ = work;
        while (height_ > least && going(deadline)) {
            const int shorter = std::max(1, static_cast<int>(height_ * cut_));
            pose_ = feasible_;
            squeeze(shorter);
            if (separate(height_ - shorter, deadline)) {
                feasible_ = pose_;
                height_ = top(feasible_);
            } else {
                cut_ /= 2;
            }
        }
    }

    int height() const { return height_; }
    double cut() const { return cut_; }
    const std::vector<Pose>& feasible() const { return feasible_; }

    /// The height the poses reach.
    int top(const std::vector<Pose>& poses) const
    {
        int top = 0;
        for (size_t u = 0; u < poses.size(); ++u)
            top = std::max(top, poses[u].y + shape(u, poses[u]).height());
        return top;
    }

private:
    bool going(Deadline deadline) const { return count_.work() < work_ && !deadline.passed(); }

    const Footprint& shape(size_t unit, const Pose& pose) const { return parts_[unit].shapes[pose.shape]; }

    /// Removes a slice `cells` long across the strip, the one with the least material of kSlices drawn at
    /// random: what lies past it moves back by that much.
    void squeeze(int cells)
    {
        // Cells taken below each row: a sum of the rows' material, itself a sum of where the runs start and
        // end.
        std::vector<long> below(height_ + 1, 0);
        for (size_t u = 0; u < pose_.size(); ++u) {
            const Footprint& f = shape(u, pose_[u]);
            for (int c = 0; c < f.width(); ++c)
                for (const auto& [from, to] : f.runs(c)) {
                    ++below[pose_[u].y + from + 1];
                    if (pose_[u].y + to < height_)
                        --below[pose_[u].y + to + 1];
                }
        }
        std::partial_sum(below.begin(), below.end(), below.begin());
        std::partial_sum(below.begin(), below.end(), below.begin());
        std::uniform_int_distribution<int> row(0, height_ - 1);
        int at = row(random_);
        for (int k = 1; k < kSlices; ++k) {
            const int other = row(random_);
            const auto material = [&](int from) {
                return below[std::min(height_, from + cells)] - below[from];
            };
            if (material(other) < material(at))
                at = other;
        }
        for (Pose& pose : pose_)
            if (pose.y >= at)
                pose.y = std::max(0, pose.y - cells);
    }

    bool inside(size_t unit, const Pose& pose, int length) const
    {
        return pose.y + shape(unit, pose).height() <= length;
    }

    long sharedBy(size_t a, size_t b) const
    {
        return shared(shape(a, pose_[a]), pose_[a].x, pose_[a].y, shape(b, pose_[b]), pose_[b].x, pose_[b].y);
    }

    /// Moves the units that overlap or stick out past `length` until none does (true), or the overlap has not
    /// fallen for kStaleRounds rounds or the work budget or time ran out (false).
    bool separate(int length, Deadline deadline)
    {
        for (auto& weights : weights_)
            weights.clear();
        count_.clear();
        for (size_t u = 0; u < pose_.size(); ++u)
            count_.add(shape(u, pose_[u]), pose_[u].x, pose_[u].y, 1);
        long least = std::numeric_limits<long>::max();
        for (int stale = 0; stale < kStaleRounds && going(deadline);) {
            std::vector<size_t> overlapping;
            long total = 0;
            for (size_t u = 0; u < pose_.size(); ++u) {
                const Footprint& f = shape(u, pose_[u]);
                overlap_[u] =
                    count_.under(f, pose_[u].x, pose_[u].y, std::numeric_limits<long>::max()) - f.area();
                total += overlap_[u];
                if (overlap_[u] > 0 || !inside(u, pose_[u], length))
                    overlapping.push_back(u);
            }
            if (overlapping.empty())
                return true;
            if (total < least)
                least = total, stale = 0;
            else
                ++stale;
            reweigh();
            std::shuffle(overlapping.begin(), overlapping.end(), random_);
            for (size_t u : overlapping)
                move(u, length);
        }
        return false;
    }

    /// Guided local search's penalties, per pair: a pair that overlaps weighs 1.2 to 2 times more (the most
    /// for the largest overlap), one that does not 5 % less, down to 1.
    void reweigh()
    {
        std::vector<std::tuple<size_t, size_t, long>> pairs;
        long most = 0;
        for (size_t a = 0; a < pose_.size(); ++a)
            if (overlap_[a] > 0)
                for (size_t b = a + 1; b < pose_.size(); ++b)
                    if (overlap_[b] > 0)
                        if (const long cells = sharedBy(a, b); cells > 0)
                            pairs.emplace_back(a, b, cells), most = std::max(most, cells);
        for (size_t a = 0; a < weights_.size(); ++a)
            for (auto& [b, weight] : weights_[a])
                weight = std::max(1.0, 0.95 * weight);
        for (const auto& [a, b, cells] : pairs) {
            const double weight = this->weight(a, b) * (1.2 + 0.8 * static_cast<double>(cells) / most);
            setWeight(a, b, weight);
            setWeight(b, a, weight);
        }
    }

    double weight(size_t a, size_t b) const
    {
        for (const auto& [other, weight] : weights_[a])
            if (other == b)
                return weight;
        return 1;
    }

    void setWeight(size_t a, size_t b, double weight)
    {
        for (auto& [other, w] : weights_[a])
            if (other == b) {
                w = weight;
                return;
            }
        weights_[a].emplace_back(b, weight);
    }

    /// What `unit` overlaps in `pose` (taken off the count): every cell it shares with another unit, times
    /// the pair's weight. Once past `bound` it may stop there.
    double cost(size_t unit, const Pose& pose, double bound) const
    {
        const Footprint& f = shape(unit, pose);
        const long cells = count_.under(f, pose.x, pose.y, static_cast<long>(std::min(bound, 1e18)));
        double total = static_cast<double>(cells);
        for (auto w = weights_[unit].begin(); w != weights_[unit].end() && total > 0 && total < bound; ++w)
            if (w->second > 1)
                total += (w->second - 1) *
                         static_cast<double>(shared(f, pose.x, pose.y, shape(w->first, pose_[w->first]),
                                                    pose_[w->first].x, pose_[w->first].y));
        return total;
    }

    /// Moves `unit` to where what it overlaps weighs least, inside `length`: the best of random places in
    /// each of its shapes (and where it is), refined by steps.
    void move(size_t unit, int length)
    {
        Pose& pose = pose_[unit];
        count_.add(shape(unit, pose), pose.x, pose.y, -1);
        Pose best = pose;
        double least = std::numeric_limits<double>::infinity();
        if (inside(unit, pose, length))
            least = refine(unit, best, length, cost(unit, pose, least));
        const RasterPart& part = parts_[unit];
        for (int s = 0; s < static_cast<int>(part.shapes.size()) && least > 0; ++s) {
            const Footprint& f = part.shapes[s];
            if (!allowedOn(part, s, strip_) || f.width() > strip_.width || f.height() > length)
                continue;
            std::uniform_int_distribution<int> anyX(0, strip_.width - f.width()),
                anyY(0, length - f.height());
            std::uniform_int_distribution<int> nearX(-f.width() / 2, f.width() / 2),
                nearY(-f.height() / 2, f.height() / 2);
            Pose tried{s, 0, 0};
            double lowest = std::numeric_limits<double>::infinity();
            for (int k = 0; k < kAnywhere + kNearby && lowest > 0; ++k) {
                const Pose at = k < kAnywhere ? Pose{s, anyX(random_), anyY(random_)}
                                              : Pose{s, std::clamp(pose.x + nearX(random_), 0, anyX.max()),
                                                     std::clamp(pose.y + nearY(random_), 0, anyY.max())};
                const double weight = cost(unit, at, lowest);
                if (weight < lowest)
                    tried = at, lowest = weight;
            }
            lowest = refine(unit, tried, length, lowest);
            if (lowest < least)
                best = tried, least = lowest;
        }
        pose = best;
        count_.add(shape(unit, pose), pose.x, pose.y, 1);
    }

    /// Steps `pose` (where what it overlaps weighs `weight`) to a neighbour that weighs less while one does,
    /// the steps halved from a quarter of the part's size to a cell; returns what it then weighs.
    double refine(size_t unit, Pose& pose, int length, double weight) const
    {
        const Footprint& f = shape(unit, pose);
        const int lastX = strip_.width - f.width(), lastY = length - f.height();
        constexpr std::array<std::pair<int, int>, 4> kWays{{{1, 0}, {-1, 0}, {0, 1}, {0, -1}}};
        for (int step = std::max(1, std::max(f.width(), f.height()) / 4); step >= 1 && weight > 0;) {
            bool moved = false;
            for (const auto& [dx, dy] : kWays) {
                const Pose next{pose.shape, std::clamp(pose.x + dx * step, 0, lastX),
                                std::clamp(pose.y + dy * step, 0, lastY)};
                const double less = cost(unit, next, weight);
                if (less < weight) {
                    pose = next, weight = less, moved = true;
                    break;
                }
            }
            if (!moved)
                step /= 2;
        }
        return weight;
    }

    const std::vector<RasterPart>& parts_;
    const BoardStock& strip_;
    std::vector<Pose> pose_, feasible_;
    int height_;
    std::vector<long> overlap_;
    std::vector<std::vector<std::pair<size_t, double>>> weights_;  ///< per unit, the pairs weighing over 1
    Occupancy count_;                                              ///< how many units lie on each cell
    std::mt19937_64 random_;
    long work_ = 0;  ///< the budget
    double cut_;
};

/// Whether no two poses take a cell twice and each lies inside the strip `height` long.
bool feasible(const std::vector<RasterPart>& parts, const BoardStock& strip, const std::vector<Pose>& poses,
              int height)
{
    Occupancy count(strip.width, height);
    for (size_t u = 0; u < poses.size(); ++u) {
        const Footprint& f = parts[u].shapes[poses[u].shape];
        if (poses[u].x < 0 || poses[u].y < 0 || poses[u].x + f.width() > strip.width ||
            poses[u].y + f.height() > height || count.under(f, poses[u].x, poses[u].y, 1) > 0)
            return false;
        count.add(f, poses[u].x, poses[u].y, 1);
    }
    return true;
}

/// No strip is shorter than the parts' least area across its width, nor than a part at its lowest.
int leastHeight(const std::vector<RasterPart>& parts, const BoardStock& strip)
{
    long area = 0;
    int least = 0;
    for (const RasterPart& part : parts) {
        int lowest = std::numeric_limits<int>::max();
        long smallest = std::numeric_limits<long>::max();
        for (int s = 0; s < static_cast<int>(part.shapes.size()); ++s)
            if (allowedOn(part, s, strip) && part.shapes[s].width() <= strip.width) {
                lowest = std::min(lowest, part.shapes[s].height());
                smallest = std::min(smallest, part.shapes[s].area());
            }
        if (lowest < std::numeric_limits<int>::max())
            least = std::max(least, lowest), area += smallest;
    }
    return std::max(least, static_cast<int>((area + strip.width - 1) / strip.width));
}

/// `start` with each unit in its pose, its bounds and skyline as the docking's sheet measures them.
GridLayout posed(const GridLayout& start, const std::vector<RasterPart>& parts, const BoardStock& strip,
                 const std::vector<Pose>& poses)
{
    GridLayout shrunk = start;
    Sheet sheet(strip.width, strip.height);
    for (Placed& p : shrunk.placed) {
        const Pose& pose = poses[p.part];
        p.shape = pose.shape, p.x = pose.x, p.y = pose.y;
        sheet.place(parts[p.part].shapes[pose.shape], {p.x, p.y});
    }
    shrunk.usedWidth[0] = sheet.usedWidth();
    shrunk.usedHeight[0] = sheet.usedHeight();
    shrunk.skylineArea[0] = sheet.skylineArea();
    return shrunk;
}

}  // namespace

GridLayout shrinkStrip(const std::vector<RasterPart>& parts, const BoardStock& strip, const GridLayout& start,
                       const ShrinkBudget& budget, Deadline deadline)
{
    if (start.stock.size() != 1 || !start.unplaced.empty() || start.placed.size() != parts.size() ||
        static_cast<double>(strip.width) * start.usedHeight[0] > kShrinkCells)
        return start;
    std::vector<Pose> poses(parts.size());
    for (const Placed& p : start.placed)
        poses[p.part] = {p.shape, p.x, p.y};
    int height = start.usedHeight[0];
    double cut = 0.02;
    const int threads = std::max(1, budget.threads), least = leastHeight(parts, strip);
    // In phases, each search starting from the lowest strip the last phase found (the first search's on a
    // tie, whichever thread finished first), so a search that is stuck does not waste its core for long.
    for (int phase = 0; phase < kPhases && height > least; ++phase) {
        const Deadline end = deadline.share(kPhases - phase);
        std::vector<Shrinker> searches;
        for (int t = 0; t < threads; ++t)
            searches.emplace_back(parts, strip, poses, height, cut,
                                  budget.seed + phase + (static_cast<std::uint64_t>(t) << 32));
        runAll(
            threads, threads, [&](int t) { searches[t].shrink(least, budget.work / kPhases, end); },
            [](int) {});
        const Shrinker* lowest = &searches.front();
        for (const Shrinker& search : searches)
            if (search.height() < lowest->height())
                lowest = &search;
        poses = lowest->feasible(), height = lowest->height(), cut = lowest->cut();
    }
    if (height >= start.usedHeight[0] || !feasible(parts, strip, poses, height))
        return start;
    return posed(start, parts, strip, poses);
}

}  // namespace fabguide::material
