#include "Design/Design.h"

#include "Geometry/Interval.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fabguide::material {

std::array<int, 2> DesignBoard::inPlane() const
{
    const std::array<int, 2> axes = normal == 0   ? std::array<int, 2>{1, 2}
                                    : normal == 1 ? std::array<int, 2>{0, 2}
                                                  : std::array<int, 2>{0, 1};
    return grainAxis == axes[1] ? std::array<int, 2>{axes[1], axes[0]} : axes;
}

double Linear::value(const Eigen::VectorXd& X) const
{
    double sum = constant;
    for (const auto& [variable, coefficient] : terms)
        sum += coefficient * X[variable];
    return sum;
}

Linear Linear::operator+(const Linear& other) const
{
    Linear sum = *this;
    sum.terms.insert(sum.terms.end(), other.terms.begin(), other.terms.end());
    sum.constant += other.constant;
    return sum;
}

Linear Linear::operator*(double factor) const
{
    Linear scaled = *this;
    for (auto& term : scaled.terms)
        term.second *= factor;
    scaled.constant *= factor;
    return scaled;
}

Linear Linear::operator-(const Linear& other) const
{
    return *this + other * -1.0;
}

Linear centreOf(int board, int axis)
{
    return {{{centreVariable(board, axis), 1.0}}, 0};
}
Linear sizeOf(int board, int axis)
{
    return {{{sizeVariable(board, axis), 1.0}}, 0};
}
Linear lowerFace(int board, int axis)
{
    return centreOf(board, axis) - sizeOf(board, axis) * 0.5;
}
Linear upperFace(int board, int axis)
{
    return centreOf(board, axis) + sizeOf(board, axis) * 0.5;
}

namespace {

/// Board b's extent along an axis in design X.
Interval extent(int board, int axis, const Eigen::VectorXd& X)
{
    return {lowerFace(board, axis).value(X), upperFace(board, axis).value(X)};
}

}  // namespace

Linear constant(double value)
{
    return {{}, value};
}

Linear InnerVolume::lower(int axis) const
{
    return (anchor[axis] < 0 ? lowerFace(on, axis) : upperFace(on, axis)) + constant(offset[axis]);
}
Linear InnerVolume::upper(int axis) const
{
    return lower(axis) + constant(size[axis]);
}

Eigen::VectorXd Design::variables() const
{
    Eigen::VectorXd X(6 * boards.size());
    for (size_t b = 0; b < boards.size(); ++b)
        X.segment<6>(6 * b) << boards[b].centre, boards[b].size;
    return X;
}

std::vector<DesignBoard> Design::boardsAt(const Eigen::VectorXd& X) const
{
    std::vector<DesignBoard> at = boards;
    for (size_t b = 0; b < at.size(); ++b) {
        at[b].centre = X.segment<3>(6 * b);
        at[b].size = X.segment<3>(6 * b + 3);
    }
    return at;
}

std::vector<bool> Design::frozen() const
{
    std::vector<bool> frozen(6 * boards.size(), false);
    for (size_t b = 0; b < boards.size(); ++b)
        frozen[sizeVariable(static_cast<int>(b), boards[b].normal)] = true;
    return frozen;
}

Eigen::VectorXd Design::minimum() const
{
    // A bound -X[v] + m <= 0 on a size variable is a minimum length m.
    Eigen::VectorXd minimum =
        Eigen::VectorXd::Constant(6 * boards.size(), -std::numeric_limits<double>::infinity());
    for (const DesignConstraint& bound : bounds) {
        const auto& terms = bound.expression.terms;
        if (terms.size() == 1 && terms[0].second == -1.0 && terms[0].first % 6 >= 3)
            minimum[terms[0].first] = std::max(minimum[terms[0].first], bound.expression.constant);
    }
    return minimum;
}

bool intrudes(const InnerVolume& volume, int board, const Eigen::VectorXd& X, double tolerance)
{
    if (board == volume.on)
        return false;
    for (int axis = 0; axis < 3; ++axis) {
        if (overlapOf(extent(board, axis, X), {volume.lower(axis).value(X), volume.upper(axis).value(X)}) <=
            tolerance)
            return false;
    }
    return true;
}

namespace {

/// E(X) of thesis 5.3.5.1 term by term: calls broken(Ineffective) for each effectiveness constraint X
/// breaks, until it returns false.
template <typename Broken>
void visitBroken(const Design& design, const Eigen::VectorXd& X, Broken&& broken)
{
    for (const DesignConstraint& bound : design.bounds)
        if (bound.expression.value(X) > 1e-7 && !broken(Ineffective{bound.name, ""}))
            return;
    for (const InnerVolume& volume : design.innerVolumes)
        for (size_t b = 0; b < design.boards.size(); ++b)
            if (intrudes(volume, static_cast<int>(b), X) &&
                !broken(Ineffective{volume.name, design.boards[b].id}))
                return;
}

}  // namespace

bool effective(const Design& design, const Eigen::VectorXd& X)
{
    bool holds = true;
    visitBroken(design, X, [&](const Ineffective&) { return holds = false; });
    return holds;
}

std::string Ineffective::said() const
{
    return enteredBy.empty() ? name : name + " (entered by " + enteredBy + ")";
}

std::vector<Ineffective> ineffective(const Design& design, const Eigen::VectorXd& X)
{
    std::vector<Ineffective> broken;
    visitBroken(design, X, [&](Ineffective one) {
        broken.push_back(std::move(one));
        return true;
    });
    return broken;
}

std::vector<std::string> said(const std::vector<Ineffective>& broken)
{
    std::vector<std::string> out;
    for (const Ineffective& one : broken)
        out.push_back(one.said());
    return out;
}

std::vector<std::string> unsatisfied(const Design& design, const Eigen::VectorXd& X, double tolerance)
{
    std::vector<std::string> broken;
    for (const DesignConstraint& equality : design.equalities)
        if (std::abs(equality.expression.value(X)) > tolerance)
            broken.push_back(equality.name);
    return broken;
}

Snapping snapping(const Design& design, int a, int b, double tolerance)
{
    const Eigen::VectorXd X = design.variables();
    const std::string pair = design.boards[a].id + "/" + design.boards[b].id;
    const char* names = "xyz";
    const auto overlap = [&](int axis) { return overlapOf(extent(a, axis, X), extent(b, axis, X)); };
    const double thinner = std::min(design.boards[a].size[design.boards[a].normal],
                                    design.boards[b].size[design.boards[b].normal]);
    Snapping kept;
    for (int axis = 0; axis < 3; ++axis) {
        const int j = (axis + 1) % 3, k = (axis + 2) % 3;
        if (std::abs(overlap(axis)) > tolerance || overlap(j) <= tolerance || overlap(k) <= tolerance)
            continue;
        const bool aBelow = std::abs(upperFace(a, axis).value(X) - lowerFace(b, axis).value(X)) <= tolerance;
        kept.equalities.push_back(
            {"snap " + pair + " touch along " + names[axis],
             aBelow ? upperFace(a, axis) - lowerFace(b, axis) : upperFace(b, axis) - lowerFace(a, axis)});
        for (int other : {j, k}) {
            const std::string along = std::string(" along ") + names[other];
            const bool lowFlush =
                std::abs(lowerFace(a, other).value(X) - lowerFace(b, other).value(X)) <= tolerance;
            const bool highFlush =
                std::abs(upperFace(a, other).value(X) - upperFace(b, other).value(X)) <= tolerance;
            if (lowFlush)
                kept.equalities.push_back(
                    {"snap " + pair + " flush low" + along, lowerFace(a, other) - lowerFace(b, other)});
            if (highFlush)
                kept.equalities.push_back(
                    {"snap " + pair + " flush high" + along, upperFace(a, other) - upperFace(b, other)});
            if (lowFlush || highFlush)
                continue;
            const Linear keep = constant(std::min(overlap(other), thinner));
            kept.bounds.push_back(
                {"snap " + pair + " stay connected" + along + " (" + design.boards[b].id + " end)",
                 lowerFace(a, other) - upperFace(b, other) + keep});
            kept.bounds.push_back(
                {"snap " + pair + " stay connected" + along + " (" + design.boards[a].id + " end)",
                 lowerFace(b, other) - upperFace(a, other) + keep});
        }
        return kept;
    }
    return kept;
}

std::vector<DesignConstraint> keptApart(const Design& design, double margin)
{
    const Eigen::VectorXd X = design.variables();
    const int n = static_cast<int>(design.boards.size());
    std::vector<int> byLeft(n);
    for (int b = 0; b < n; ++b)
        byLeft[b] = b;
    std::sort(byLeft.begin(), byLeft.end(),
              [&](int a, int b) { return lowerFace(a, 0).value(X) < lowerFace(b, 0).value(X); });
    std::vector<DesignConstraint> bounds;
    const char* names = "xyz";
    for (int i = 0; i < n; ++i)
        for (int j = i + 1;
             j < n && lowerFace(byLeft[j], 0).value(X) < upperFace(byLeft[i], 0).value(X) + margin; ++j) {
            const int a = std::min(byLeft[i], byLeft[j]), b = std::max(byLeft[i], byLeft[j]);
            // Most apart: the axis and order with the widest gap (touching is a gap of 0).
            double widest = -std::numeric_limits<double>::infinity();
            Linear keep;
            int along = 0;
            for (int axis = 0; axis < 3; ++axis)
                for (const auto& [low, high] : {std::pair{a, b}, std::pair{b, a}})
                    if (const double gap = lowerFace(high, axis).value(X) - upperFace(low, axis).value(X);
                        gap > widest) {
                        widest = gap;
                        keep = upperFace(low, axis) - lowerFace(high, axis);  // <= 0, or a touch's hair
                        along = axis;
                    }
            if (widest < -1e-6 || widest > margin)
                continue;  // overlapping as designed (not ours to part), or far apart
            bounds.push_back({std::string("apart: ") + design.boards[a].id + "/" + design.boards[b].id +
                                  " along " + names[along],
                              keep + constant(std::min(0.0, widest))});
        }
    double ground = std::numeric_limits<double>::infinity();
    for (int b = 0; b < n; ++b)
        ground = std::min(ground, lowerFace(b, 2).value(X));
    for (int b = 0; b < n; ++b)
        bounds.push_back({"above ground: " + design.boards[b].id, constant(ground) - lowerFace(b, 2)});
    return bounds;
}

}  // namespace fabguide::material
