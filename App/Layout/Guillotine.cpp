#include "Layout/Guillotine.h"

#include "Layout/GuillotineBeam.h"
#include "Layout/MaxRects.h"

#include <algorithm>
#include <deque>
#include <future>
#include <iterator>
#include <limits>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <tuple>

namespace fabguide::material {

namespace {

/// A piece of a sheet in the usable sheet's coordinates (trim removed), the clearance to the next piece
/// included at its far edges; axis 0 is x, 1 is y.
struct Piece {
    double at[2] = {0, 0}, size[2] = {0, 0};
};

double along(const Pose& pose, int axis)
{
    return axis == 0 ? pose.w : pose.h;
}

/// How one sheet is filled: the first stage's direction, the stages, and how the first stage's slabs are
/// led (their lead part lying tall, as thick as it may, or flat).
struct Fill {
    int firstAxis = 1;  ///< the first stage's slabs follow one another along this axis
    int stages = 3;
    bool tallLeads = true;
};

/// A run's rules: the parts in the order preferred, and the fills each sheet tries (the one that lays the
/// most part area is kept).
struct Rules {
    std::vector<int> order;
    std::vector<Fill> fills;
};

/// How far in from a board's edge its edge trim's cut runs (the kerf inside the trimmed margin); 0, the edge
/// itself, with no trim.
double edgeTrimAt(const PackSettings& s)
{
    return s.trim > 0 ? s.trim - s.kerf / 2 : 0;
}

/// A unit taken to lead a slab: its part, its pose, and the sizes of the slabs it leads along x and y when
/// longer than its own (a beam search's steps grow them).
struct Lead {
    int part = -1;
    Pose pose;
    double extent[2] = {0, 0};
};

/// One sheet filled by slabs, stage by stage (Guillotine.h), the units picked by the rules or taken from a
/// beam search's steps for the sheet (`script`, its first step leading the first slab).
class Filler {
public:
    Filler(const PackProblem& problem, const std::vector<int>& order, const Fill& rules,
           const std::vector<std::vector<Pose>>& poses, const Piece& sheet, std::vector<int>& remaining,
           Layout& layout, std::deque<SawStep>* script = nullptr)
        : problem_(problem),
          order_(order),
          rules_(rules),
          poses_(poses),
          sheet_(sheet),
          remaining_(remaining),
          layout_(layout),
          script_(script),
          clearance_(problem.settings.kerf + problem.settings.spacing)
    {
    }

    /// The last cut that made a piece: its stage and the axis it crosses (-1: none, the board itself).
    struct Made {
        int stage = 0, axis = -1;
    };

    /// Fills `piece` (made by `made`) with slabs following one another along axis `a`, the first led by
    /// `lead` when given (already taken), `depth` the stages down to here; its cuts, then those of its slabs,
    /// go to `cuts`. A piece left whole (one slab filling it) is not numbered again.
    void fill(const Piece& piece, int a, int depth, Made made, const std::string& number,
              std::optional<Lead> lead, std::vector<SawCut>& cuts)
    {
        const int b = 1 - a;
        const double end = piece.at[a] + piece.size[a];
        const Made here{made.axis == a ? made.stage : made.stage + 1, a};  // the stage of the cuts made here
        std::vector<SawCut> inner;
        double at = piece.at[a];
        for (int n = 1;; ++n, lead.reset()) {
            if (!lead) {
                lead = pick(piece, a, depth, end - at);
                if (!lead)
                    break;
                --remaining_[lead->part];
            }
            Piece slab = piece;
            slab.at[a] = at;
            slab.size[a] = std::max(along(lead->pose, a), lead->extent[a]);
            lead->extent[a] = 0;  // the deeper slabs it leads along `a` are its own size
            at += slab.size[a];
            const bool whole = n == 1 && at >= end - kHair;
            const std::string name = whole            ? number
                                     : number.empty() ? std::to_string(n)
                                                      : number + "." + std::to_string(n);
            if (at < end - kHair)
                cuts.push_back(cut(piece, a, at, here.stage, name));
            if (depth < rules_.stages)
                fill(slab, b, depth + 1, whole ? made : here, name, lead, inner);
            else
                place(*lead, slab, b, whole ? made : here, name, inner);
        }
        cuts.insert(cuts.end(), inner.begin(), inner.end());
    }

private:
    /// The unit to lead the next slab in `piece` along `a`, `room` left along it. In the first stage the
    /// first part of the order that fits, tall or flat by the rules; deeper, the one that fills the piece's
    /// depth across best (the order breaking ties).
    std::optional<Lead> pick(const Piece& piece, int a, int stage, double room) const
    {
        if (script_)
            return scripted(stage);
        const int b = 1 - a;
        std::optional<Lead> best;
        std::tuple<double, int, double> bestKey{std::numeric_limits<double>::max(), 0, 0};
        for (int rank = 0; rank < static_cast<int>(order_.size()); ++rank) {
            const int p = order_[rank];
            if (remaining_[p] == 0)
                continue;
            for (const Pose& pose : poses_[p]) {
                if (!leaves(room, along(pose, a)) || !leaves(piece.size[b], along(pose, b)))
                    continue;
                const double thick = rules_.tallLeads ? -along(pose, a) : along(pose, a);
                const auto key = stage == 1 ? std::tuple{0.0, rank, thick}
                                            : std::tuple{-along(pose, b), rank, -along(pose, a)};
                if (key < bestKey)
                    bestKey = key, best = Lead{p, pose};
            }
            if (stage == 1 && best)
                break;
        }
        return best;
    }

    /// The script's next step when it goes where a pick of `stage` puts its unit.
    std::optional<Lead> scripted(int stage) const
    {
        constexpr Where kPicked[] = {Where::Slab, Where::Column, Where::After};  // by stage
        if (script_->empty() || script_->front().where != kPicked[stage - 1])
            return std::nullopt;
        const SawStep& step = script_->front();
        const Lead lead{step.part, step.pose, {step.extent[0], step.extent[1]}};
        script_->pop_front();
        return lead;
    }

    bool leaves(double room, double size) const { return leavesSawable(room, size, clearance_); }

    /// The last stage's slab holds its lead alone, at its start; a trim cut across parts it from the waste
    /// beyond it along `b`.
    void place(const Lead& lead, const Piece& slab, int b, Made made, const std::string& number,
               std::vector<SawCut>& cuts)
    {
        addPlacement(problem_, lead.part, static_cast<int>(layout_.sheets.size()) - 1, slab.at[0], slab.at[1],
                     lead.pose.rotation, layout_);
        const double reach = slab.at[b] + along(lead.pose, b);
        const int stage = made.axis == b ? made.stage : made.stage + 1;
        if (reach < slab.at[b] + slab.size[b] - kHair)
            cuts.push_back(cut(slab, b, reach, stage, number.empty() ? "1" : number + ".1"));
    }

    /// Where a piece's edge at `at` along `axis` (usable coordinates) lies on the sheet: the middle of the
    /// cut there, or the board's edge (its edge trim's middle) at either end.
    double edge(double at, int axis) const
    {
        const PackSettings& s = problem_.settings;
        const double margin = edgeTrimAt(s);
        if (at <= kHair)
            return margin;
        if (at >= sheet_.size[axis] - kHair)
            return (axis == 0 ? layout_.sheets.back().width : layout_.sheets.back().height) - margin;
        return s.trim + at - clearance_ / 2;
    }

    /// The cut across `piece` that ends a slab at `at` along `a`, from edge to edge of the piece, in sheet
    /// coordinates.
    SawCut cut(const Piece& piece, int a, double at, int stage, const std::string& number) const
    {
        const bool trim = stage > rules_.stages;
        const int b = 1 - a;
        const double middle = edge(at, a), from = edge(piece.at[b], b),
                     to = edge(piece.at[b] + piece.size[b], b);
        SawCut c{number, stage, trim, {}, {}};
        c.from = a == 0 ? geometry::Point2{middle, from} : geometry::Point2{from, middle};
        c.to = a == 0 ? geometry::Point2{middle, to} : geometry::Point2{to, middle};
        return c;
    }

    const PackProblem& problem_;
    const std::vector<int>& order_;
    const Fill& rules_;
    const std::vector<std::vector<Pose>>& poses_;
    const Piece& sheet_;
    std::vector<int>& remaining_;
    Layout& layout_;
    std::deque<SawStep>* script_;
    double clearance_;
};

/// The cuts that take `trim` off the board's edges before the first stage, numbered 0.1 to 0.4: the kerf
/// inside the margin; the long edges' from end to end of the board, then the short edges'.
std::vector<SawCut> edgeTrims(const MasterBoard& board, const PackSettings& s)
{
    if (s.trim <= 0)
        return {};
    const double in = edgeTrimAt(s), w = board.width, h = board.height;
    return {{"0.1", 0, false, {0, in}, {w, in}},
            {"0.2", 0, false, {0, h - in}, {w, h - in}},
            {"0.3", 0, false, {in, in}, {in, h - in}},
            {"0.4", 0, false, {w - in, in}, {w - in, h - in}}};
}

/// The usable piece of a board of `kind`: the board less its trim, a clearance added at the far edges.
Piece sheetOf(const PackProblem& problem, int kind)
{
    Piece sheet;
    std::tie(sheet.size[0], sheet.size[1]) = usableSize(problem.boards[kind], problem.settings);
    return sheet;
}

/// The sheet of `kind` last opened in `layout` filled by `fill` (the rules' picks in `order`, or `script`'s
/// steps), with its cuts (the edge trims first) and its bounding area.
void sawSheet(const PackProblem& problem, int kind, const Fill& fill, const std::vector<int>& order,
              const std::vector<std::vector<Pose>>& poses, std::vector<int>& remaining, Layout& layout,
              std::deque<SawStep>* script = nullptr)
{
    const Piece sheet = sheetOf(problem, kind);
    const size_t placed = layout.placements.size();
    std::vector<SawCut> cuts = edgeTrims(problem.boards[kind], problem.settings);
    Filler(problem, order, fill, poses, sheet, remaining, layout, script)
        .fill(sheet, fill.firstAxis, 1, {}, "", {}, cuts);
    layout.sawCuts.push_back(std::move(cuts));
    double right = 0, top = 0;
    for (size_t k = placed; k < layout.placements.size(); ++k) {
        const Placement& p = layout.placements[k];
        right = std::max(right, p.x + p.width - problem.settings.trim);
        top = std::max(top, p.y + p.height - problem.settings.trim);
    }
    layout.boundingArea += right * top;
}

/// One run: sheet after sheet, each filled from its whole by the rules. Nothing when `deadline` passes
/// first.
std::optional<Layout> run(const PackProblem& problem, const Rules& rules,
                          const std::vector<std::vector<std::vector<Pose>>>& poses, Deadline deadline)
{
    std::vector<int> remaining, left;
    long units = 0;
    for (const PartSpec& part : problem.parts)
        remaining.push_back(part.quantity), units += part.quantity;
    for (const MasterBoard& board : problem.boards)
        left.push_back(board.count);
    Layout layout;
    for (long placed = 0; placed < units; placed = static_cast<long>(layout.placements.size())) {
        if (deadline.passed())
            return std::nullopt;
        const int first =
            *std::find_if(rules.order.begin(), rules.order.end(), [&](int p) { return remaining[p] > 0; });
        const int kind = sheetKindFor(problem, problem.parts[first], left);
        if (kind < 0)
            throw ranOut(problem.parts[first], units - placed - 1);
        openSheet(problem, kind, left, layout);
        const Piece sheet = sheetOf(problem, kind);
        const Fill* best = &rules.fills.front();
        double most = -1;
        for (const Fill& fill : rules.fills) {  // each tried, then undone
            const std::vector<int> before = remaining;
            const double area = layout.partArea;
            std::vector<SawCut> scratch;
            Filler(problem, rules.order, fill, poses[kind], sheet, remaining, layout)
                .fill(sheet, fill.firstAxis, 1, {}, "", {}, scratch);
            if (layout.partArea - area > most + kHair)
                most = layout.partArea - area, best = &fill;
            remaining = before, layout.partArea = area;
            layout.placements.resize(placed);
        }
        sawSheet(problem, kind, *best, rules.order, poses[kind], remaining, layout);
        if (static_cast<long>(layout.placements.size()) == placed)
            throw PackingError(
                "part '" + problem.parts[first].id + "' cannot be sawn from '" + problem.boards[kind].name +
                "': it would leave a strip narrower than half the kerf + spacing at the board's "
                "edge, which a saw cannot take off; set a trim, or a size that leaves none");
    }
    return layout;
}

/// Layouts compared for the search: cost and sheets (`better`), then how unevenly the parts fill the sheets
/// (the sum of each sheet's squared fill, larger first): a layout whose last sheets are emptier is nearer one
/// with a sheet fewer.
bool fuller(const Layout& a, const Layout& b)
{
    const auto measure = [](const Layout& l) {
        double cost = 0, spread = 0;
        std::vector<double> area(l.sheets.size());
        for (const Placement& p : l.placements)
            area[p.sheet] += p.width * p.height;
        for (size_t k = 0; k < l.sheets.size(); ++k) {
            cost += l.sheets[k].cost;
            const double fill = area[k] / (l.sheets[k].width * l.sheets[k].height);
            spread -= fill * fill;
        }
        return std::make_tuple(cost, l.sheets.size(), spread);
    };
    return measure(a) < measure(b);
}

/// The order with the parts of the layout's last sheet first: the parts that were left over are the ones to
/// place while the sheets are empty (sequential value correction's idea, in its simplest form).
std::vector<int> lastFirst(const std::vector<int>& order, const Layout& layout)
{
    std::vector<bool> last(order.size());
    for (const Placement& p : layout.placements)
        if (p.sheet + 1 == static_cast<int>(layout.sheets.size()))
            last[p.part] = true;
    std::vector<int> result = order;
    std::stable_partition(result.begin(), result.end(), [&](int p) { return last[p]; });
    return result;
}

/// `steps` (a beam search's, for parts cut from boards of `kind`) laid on new sheets of `kind` in `layout`,
/// in `stages`.
void replay(const PackProblem& problem, int kind, int stages, const std::vector<std::vector<Pose>>& poses,
            const std::vector<SawStep>& steps, std::vector<int>& remaining, std::vector<int>& left,
            Layout& layout)
{
    for (size_t k = 0; k < steps.size();) {
        const Fill fill{steps[k].axis, stages, true};
        std::deque<SawStep> script{steps[k]};
        script.front().where = Where::Slab;
        for (++k; k < steps.size() && steps[k].where != Where::Sheet; ++k)
            script.push_back(steps[k]);
        openSheet(problem, kind, left, layout);
        sawSheet(problem, kind, fill, {}, poses, remaining, layout, &script);
        if (!script.empty())
            throw std::logic_error("a beam search's step does not fit where the search laid it");
    }
}

/// The beam search's layout (GuillotineBeam.h): the parts of each board kind (the kind a sheet is opened for
/// them) on sheets of their own, in 3 stages (2 when the limit is 2), each sheet's first cuts along one of
/// `axes`; searches up to `widest` wide, each kind's with an equal share of the time. Nothing when a search
/// finds none or the limit is one stage.
std::optional<Layout> beamLayout(const PackProblem& problem, const std::vector<int>& axes,
                                 const std::vector<std::vector<std::vector<Pose>>>& poses, long widest,
                                 Deadline deadline)
{
    const PackSettings& s = problem.settings;
    if (s.stages == 1)
        return std::nullopt;
    std::vector<int> stock, kindOf, kinds;
    for (const MasterBoard& board : problem.boards)
        stock.push_back(board.count);
    for (const PartSpec& part : problem.parts) {
        kindOf.push_back(sheetKindFor(problem, part, stock));
        if (kindOf.back() < 0)
            return std::nullopt;
        if (std::find(kinds.begin(), kinds.end(), kindOf.back()) == kinds.end())
            kinds.push_back(kindOf.back());
    }
    const int stages = s.stages == 2 ? 2 : 3;
    Layout layout;
    std::vector<int> left = stock, remaining;
    for (const PartSpec& part : problem.parts)
        remaining.push_back(part.quantity);
    int searches = static_cast<int>(kinds.size());
    for (int kind : kinds) {
        BeamProblem beam{{}, poses[kind], {}, axes, stages, s.kerf + s.spacing, stock[kind]};
        std::tie(beam.size[0], beam.size[1]) = usableSize(problem.boards[kind], s);
        for (size_t p = 0; p < problem.parts.size(); ++p)
            beam.quantities.push_back(kindOf[p] == kind ? problem.parts[p].quantity : 0);
        const std::optional<std::vector<SawStep>> steps =
            beamSearch(beam, widest, deadline.share(searches--));
        if (!steps)
            return std::nullopt;
        replay(problem, kind, stages, poses[kind], *steps, remaining, left, layout);
    }
    return layout;
}

}  // namespace

Layout guillotine(const PackProblem& problem, long runs, std::uint64_t seed, Deadline deadline, int threads)
{
    const PackSettings& s = problem.settings;
    std::vector<std::vector<std::vector<Pose>>> poses;  // per board kind, per part
    for (const MasterBoard& board : problem.boards) {
        poses.emplace_back();
        for (const PartSpec& part : problem.parts)
            poses.back().push_back(posesOn(part, board, s.kerf + s.spacing));
    }
    std::vector<int> axes{1, 0}, stages{s.stages};
    if (s.firstCut != FirstCut::Any)
        axes = {s.firstCut == FirstCut::Along ? 1 : 0};
    if (s.stages == 0)
        stages = {2, 3, 4, 6};
    std::vector<Fill> fills;
    for (int axis : axes)
        for (int stage : stages)
            for (bool tall : {true, false})
                fills.push_back({axis, stage, tall});
    std::vector<Rules> tried;
    for (Order order : {Order::LongestSide, Order::Area, Order::Perimeter, Order::ShortestSide}) {
        std::vector<std::pair<double, double>> key;
        for (const PartSpec& part : problem.parts)
            key.push_back(orderKey(order, part));
        Rules rules{{}, fills};
        for (int p = 0; p < static_cast<int>(problem.parts.size()); ++p)
            rules.order.push_back(p);
        std::stable_sort(rules.order.begin(), rules.order.end(),
                         [&](int a, int b) { return key[a] > key[b]; });
        tried.push_back(rules);
        for (int stage : stages.size() > 1 ? stages : std::vector<int>{}) {  // each stage count alone too,
            Rules alone = rules;                                             // as a limit's own runs are
            alone.fills.clear();
            std::copy_if(fills.begin(), fills.end(), std::back_inserter(alone.fills),
                         [&](const Fill& f) { return f.stages == stage; });
            tried.push_back(alone);
        }
    }
    // The beam search: on sheets that must be filled nearly whole it finds layouts no order of the rules does
    // (docs/benchmarks.md). On a second thread it runs beside the rules' runs for the whole time; on one, in
    // the quarter of it they leave.
    const auto beamed = [&] { return beamLayout(problem, axes, poses, runs, deadline); };
    std::future<std::optional<Layout>> beside;
    if (threads > 1)
        beside = std::async(std::launch::async, beamed);
    const Deadline rulesEnd = threads > 1 ? deadline : deadline.fraction(0.75);
    std::optional<Layout> best;
    std::optional<PackingError> ranOutFirst;
    Rules bestRules = tried.front();
    std::mt19937_64 random(seed);
    for (long r = 0; r < std::max(runs, 1L); ++r) {
        Rules rules = r < static_cast<long>(tried.size()) ? tried[r] : bestRules;
        if (best && r >= static_cast<long>(tried.size()) && r % 4 == 0)  // the best's left-overs first
            rules.order = lastFirst(rules.order, *best);
        else if (r >= static_cast<long>(tried.size()) && rules.order.size() > 1) {  // a neighbour of the best
            std::uniform_int_distribution<size_t> any(0, rules.order.size() - 1);
            for (int swaps = 1 + static_cast<int>(random() % 3); swaps > 0; --swaps)
                std::swap(rules.order[any(random)], rules.order[any(random)]);
        }
        std::optional<Layout> layout;
        try {
            layout = run(problem, rules, poses, best ? rulesEnd : Deadline());
        } catch (const PackingError& e) {  // this order ran out of boards; another may not, in the time left
            ranOutFirst = ranOutFirst.value_or(e);
            if (rulesEnd.passed())
                break;
            continue;
        }
        if (!layout)
            break;
        if (!best || fuller(*layout, *best))
            best = std::move(layout), bestRules = rules;
    }
    const std::optional<Layout> beam = beside.valid() ? beside.get() : beamed();
    if (beam && (!best || fuller(*beam, *best)))
        return *beam;
    if (!best)
        throw *ranOutFirst;
    return *best;
}

}  // namespace fabguide::material
