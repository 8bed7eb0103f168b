#include "Design/LeastDesign.h"

#include <libalglib/optimization.h>

#include <cmath>
#include <limits>

namespace fabguide::material {

namespace {

constexpr double kHair = 1e-3;  // weight of |d|² against the area's mm² per mm

/// A row lower <= expression - constant <= upper of the programme.
struct Row {
    Linear expression;
    double lower, upper;
};

/// Board b kept out of inner volume v along the axis and side it is most clear of it at X.
Row outOf(const InnerVolume& v, int b, const Eigen::VectorXd& X)
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
    return {keep, -std::numeric_limits<double>::infinity(), std::max(0.0, -widest)};
}

}  // namespace

std::optional<Eigen::VectorXd> leastDesign(const Design& design, const Eigen::VectorXd& X)
{
    const int n = static_cast<int>(X.size());
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<Row> rows;
    for (const DesignConstraint& e : design.equalities)
        rows.push_back({e.expression, 0, 0});
    for (const DesignConstraint& bound : design.bounds)
        rows.push_back({bound.expression, -inf, 0});
    for (const InnerVolume& v : design.innerVolumes)
        for (int b = 0; b < static_cast<int>(design.boards.size()); ++b)
            if (b != v.on)
                rows.push_back(outOf(v, b, X));

    alglib::real_1d_array cost, lower, upper;
    cost.setlength(n);
    lower.setlength(n);
    upper.setlength(n);
    const std::vector<bool> frozen = design.frozen();
    const Eigen::VectorXd minimum = design.minimum();
    for (int i = 0; i < n; ++i) {
        cost[i] = 0;
        // The change d = X' - X, so that d = 0 is feasible even where X holds a constraint only to a hair.
        lower[i] = frozen[i] ? 0 : (i % 6 >= 3 ? std::min(0.0, std::max(0.0, minimum[i]) - X[i]) : -inf);
        upper[i] = frozen[i] ? 0 : inf;
    }
    for (int b = 0; b < static_cast<int>(design.boards.size()); ++b) {
        const auto [u, v] = design.boards[b].inPlane();
        const double q = design.boards[b].quantity;
        cost[sizeVariable(b, u)] = q * X[sizeVariable(b, v)];
        cost[sizeVariable(b, v)] = q * X[sizeVariable(b, u)];
    }
    alglib::real_1d_array d;
    alglib::minqpreport report;
    try {
        alglib::minqpstate state;
        alglib::minqpcreate(n, state);
        // A hair of |d|² makes the programme strictly convex: one answer, boards that may move anywhere
        // (positions cost nothing) staying where they are.
        alglib::sparsematrix hessian;
        alglib::sparsecreate(n, n, n, hessian);
        for (int i = 0; i < n; ++i)
            alglib::sparseset(hessian, i, i, 2 * kHair);
        alglib::sparseconverttocrs(hessian);
        alglib::minqpsetquadratictermsparse(state, hessian, true);
        alglib::minqpsetlinearterm(state, cost);
        alglib::minqpsetbc(state, lower, upper);
        const int k = static_cast<int>(rows.size());
        if (k > 0) {
            alglib::sparsematrix c;
            alglib::sparsecreate(k, n, c);
            alglib::real_1d_array al, au;
            al.setlength(k);
            au.setlength(k);
            for (int r = 0; r < k; ++r) {
                for (const auto& [variable, coefficient] : rows[r].expression.terms)
                    alglib::sparseadd(c, r, variable, coefficient);
                const double at = rows[r].expression.value(X);
                al[r] = std::min(0.0, rows[r].lower - at);
                au[r] = std::max(0.0, rows[r].upper - at);
            }
            alglib::sparseconverttocrs(c);
            alglib::minqpsetlc2(state, c, al, au, k);
        }
        alglib::minqpsetalgosparseipm(state, 1e-12);
        alglib::minqpoptimize(state);
        alglib::minqpresults(state, d, report);
    } catch (const alglib::ap_error&) {  // no third-party exception leaves the core
        return std::nullopt;
    }
    if (report.terminationtype <= 0)
        return std::nullopt;
    Eigen::VectorXd least(n);
    for (int i = 0; i < n; ++i)
        least[i] = X[i] + d[i];
    return least;
}

}  // namespace fabguide::material
