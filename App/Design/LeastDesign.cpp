#include "Design/LeastDesign.h"

#include "Function/LeastChange.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fabguide::material {

namespace {

/// How far (mm) below its length the solve aims the length that carries the most area: far enough that every
/// length stops at a constraint first, so that the valid design nearest the aim is the least one.
constexpr double kReach = 1e4;

/// lower <= expression <= upper as a constraint on the change d = X' - X, loosened where X itself holds it
/// only to a hair, so that d = 0 is feasible.
function::LinearConstraint onChange(const Linear& expression, double lower, double upper,
                                    const Eigen::VectorXd& X)
{
    const double at = expression.value(X);
    return {expression.terms, std::min(0.0, lower - at), std::max(0.0, upper - at), ""};
}

/// Board b kept out of inner volume v along the axis and side it is most clear of it at X.
function::LinearConstraint outOf(const InnerVolume& v, int b, const Eigen::VectorXd& X)
{
    double widest = -std::numeric_limits<double>::infinity();
    Linear keep;
    for (int axis = 0; axis < 3; ++axis)
        for (const auto& [low, high] :
             {std::pair{upperFace(b, axis), v.lower(axis)}, std::pair{v.upper(axis), lowerFace(b, axis)}})
            if (const double gap = high.value(X) - low.value(X); gap > widest) {
                widest = gap;
                keep = low - high;  // <= 0 when clear
            }
    return onChange(keep, -std::numeric_limits<double>::infinity(), 0, X);
}

/// The designs leastDesign chooses among, as constraints on the change d = X' - X.
std::vector<function::LinearConstraint> within(const Design& design, const Eigen::VectorXd& X)
{
    const int n = static_cast<int>(X.size());
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<function::LinearConstraint> rows;
    for (const DesignConstraint& e : design.equalities)
        rows.push_back(onChange(e.expression, 0, 0, X));
    for (const DesignConstraint& bound : design.bounds)
        rows.push_back(onChange(bound.expression, -inf, 0, X));
    for (const InnerVolume& v : design.innerVolumes)
        for (int b = 0; b < static_cast<int>(design.boards.size()); ++b)
            if (b != v.on)
                rows.push_back(outOf(v, b, X));
    const std::vector<bool> frozen = design.frozen();
    const Eigen::VectorXd minimum = design.minimum();
    for (int i = 0; i < n; ++i)
        if (frozen[i] || i % 6 >= 3)  // thicknesses stay; a length no shorter than its minimum, nor 0
            rows.push_back(onChange({{{i, 1.0}}, 0}, frozen[i] ? X[i] : std::max(0.0, minimum[i]),
                                    frozen[i] ? X[i] : inf, X));
    return rows;
}

}  // namespace

std::optional<Eigen::VectorXd> leastDesign(const Design& design, const Eigen::VectorXd& X)
{
    const int n = static_cast<int>(X.size());
    // The aim: every in-plane length shorter in proportion to the area a mm of it carries (the other length
    // times the quantity: the area's gradient), positions where they are; the least-change solve
    // (thesis 4.4's) finds the valid design nearest to it.
    Eigen::VectorXd gradient = Eigen::VectorXd::Zero(n);
    for (int b = 0; b < static_cast<int>(design.boards.size()); ++b) {
        const auto [u, v] = design.boards[b].inPlane();
        gradient[sizeVariable(b, u)] = design.boards[b].quantity * X[sizeVariable(b, v)];
        gradient[sizeVariable(b, v)] = design.boards[b].quantity * X[sizeVariable(b, u)];
    }
    const Eigen::VectorXd aim = -kReach * gradient / std::max(gradient.maxCoeff(), 1e-9);
    const function::LeastChangeResult d = function::solveLeastChange(aim, within(design, X), nullptr, 1e-8);
    if (!d.solved)
        return std::nullopt;
    return X + d.x;
}

std::optional<Eigen::VectorXd> shortestSides(const Design& design, const Eigen::VectorXd& X)
{
    std::vector<function::LinearConstraint> rows = within(design, X);
    // A design moved whole along an axis that no row pins keeps its sizes: there the first board stays.
    for (int axis = 0; axis < 3 && !design.boards.empty(); ++axis) {
        const bool pinned = std::any_of(rows.begin(), rows.end(), [&](const function::LinearConstraint& row) {
            double along = 0;
            for (const auto& [i, a] : row.terms)
                along += i % 6 == axis ? a : 0;
            return std::abs(along) > 1e-12;
        });
        if (!pinned)
            rows.push_back({{{centreVariable(0, axis), 1.0}}, 0, 0, ""});
    }
    std::vector<int> sides;
    for (int b = 0; b < static_cast<int>(design.boards.size()); ++b)
        for (int axis : design.boards[b].inPlane())
            sides.push_back(sizeVariable(b, axis));
    const auto least = function::leastOf(sides, rows, static_cast<int>(X.size()));
    if (!least)
        return std::nullopt;
    Eigen::VectorXd shortest = X;
    for (size_t k = 0; k < sides.size(); ++k)
        shortest[sides[k]] = std::max(0.0, X[sides[k]] + (*least)[k]);
    return shortest;
}

}  // namespace fabguide::material
