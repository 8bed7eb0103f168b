#include "Function/LeastChange.h"

#include "Function/BoundPropagation.h"

#include <libalglib/optimization.h>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <stdexcept>

namespace fabguide::function {

namespace {

/// Which bound of a row x meets (within the tolerance), if any: the row is active there.
const double* activeBound(const LinearConstraint& row, const Eigen::VectorXd& x, double tolerance)
{
    double value = 0;
    for (const auto& [variable, coefficient] : row.terms)
        value += coefficient * x[variable];
    return std::abs(value - row.lower) <= tolerance   ? &row.lower
           : std::abs(value - row.upper) <= tolerance ? &row.upper
                                                      : nullptr;
}

/// The interior-point solution is optimal only to ~1e-5 mm. Polishing: project the target exactly onto the
/// constraints active at x (A x = b), x* = x + v − Aᵀλ with v = target − x and λ = argmin ‖Aᵀλ − v‖ by
/// conjugate gradients on the least-squares problem (indifferent to the redundant constraints that are
/// common; sparse QR took 2.6 s at 1000 cuboids), started from the solver's Lagrange multipliers (λ is half
/// of them at the optimum; ALGLIB's sign is found by trying both); kept only if no constraint gets worse.
Eigen::VectorXd polished(const Eigen::VectorXd& target, const std::vector<LinearConstraint>& rows,
                         const Eigen::VectorXd& x, const std::vector<double>& multipliers, double tolerance)
{
    std::vector<Eigen::Triplet<double>> entries;
    std::vector<double> guess;
    for (size_t r = 0; r < rows.size(); ++r) {
        if (!activeBound(rows[r], x, tolerance))
            continue;
        for (const auto& [variable, coefficient] : rows[r].terms)
            entries.emplace_back(variable, static_cast<int>(guess.size()),
                                 coefficient);  // Aᵀ: variables × rows
        guess.push_back(multipliers[r] / 2);
    }
    const int active = static_cast<int>(guess.size());
    if (active == 0)
        return target;
    Eigen::SparseMatrix<double> transposed(x.size(), active);
    transposed.setFromTriplets(entries.begin(), entries.end());
    transposed.makeCompressed();
    const Eigen::VectorXd v = target - x;
    Eigen::VectorXd start = Eigen::Map<const Eigen::VectorXd>(guess.data(), active);
    if ((transposed * start + v).norm() < (transposed * start - v).norm())
        start = -start;
    Eigen::LeastSquaresConjugateGradient<Eigen::SparseMatrix<double>> cgls(transposed);
    cgls.setTolerance(1e-14);
    const Eigen::VectorXd lambda = cgls.solveWithGuess(v, start);
    Eigen::VectorXd candidate = x + v - transposed * lambda;
    return violation(candidate, rows) <= violation(x, rows) + 1e-9 ? candidate : x;
}

/// Coordinates the solve makes equal come out equal to the last bit: a coordinate within the
/// tolerance of the user's value is the user's value; the coordinates that active constraints x_i − x_j = d
/// (and x_i = d) tie together are set from one value: a fixed one, else one the user's, else their mean;
/// then every coordinate is rounded to the nanometre.
/// Kept only if every constraint still holds within the tolerance.
Eigen::VectorXd snapped(const Eigen::VectorXd& target, const std::vector<LinearConstraint>& rows,
                        const Eigen::VectorXd& x, double tolerance)
{
    const int n = static_cast<int>(x.size());
    Eigen::VectorXd y = x;
    for (int i = 0; i < n; ++i)
        if (std::abs(y[i] - target[i]) <= tolerance)
            y[i] = target[i];
    // Union-find with offsets: y[i] = y[root] + offset[i], paths compressed.
    std::vector<int> parent(n);
    std::vector<double> offset(n, 0.0), fixed(n, std::numeric_limits<double>::quiet_NaN());
    for (int i = 0; i < n; ++i)
        parent[i] = i;
    auto find = [&](int i) {
        double total = 0;
        int root = i;
        for (; parent[root] != root; root = parent[root])
            total += offset[root];
        for (int next; i != root; i = next) {  // point the path at the root
            next = parent[i];
            const double rest = total - offset[i];
            parent[i] = root;
            offset[i] = total;
            total = rest;
        }
        return root;
    };
    for (const LinearConstraint& row : rows) {
        const double* bound = activeBound(row, y, tolerance);
        if (!bound)
            continue;
        if (row.terms.size() == 1)
            fixed[row.terms[0].first] = *bound / row.terms[0].second;  // a lock
        if (row.terms.size() != 2 || row.terms[0].second != -row.terms[1].second ||
            std::abs(row.terms[0].second) != 1)
            continue;
        const auto [i, j] = row.terms[0].second > 0 ? std::pair{row.terms[0].first, row.terms[1].first}
                                                    : std::pair{row.terms[1].first, row.terms[0].first};
        const int ri = find(i), rj = find(j);  // y[i] − y[j] = bound
        if (ri != rj) {
            parent[ri] = rj;
            offset[ri] = offset[j] + *bound - offset[i];
        }
    }
    std::vector<double> sum(n, 0.0), anchor(n, std::numeric_limits<double>::quiet_NaN());
    std::vector<int> count(n, 0);
    for (int i = 0; i < n; ++i) {
        const int root = find(i);
        sum[root] += y[i] - offset[i];
        ++count[root];
        if (!std::isnan(fixed[i]))
            anchor[root] = fixed[i] - offset[i];
        else if (std::isnan(anchor[root]) && y[i] == target[i])
            anchor[root] = y[i] - offset[i];
    }
    for (int i = 0; i < n; ++i) {
        const int root = find(i);
        y[i] = (std::isnan(anchor[root]) ? sum[root] / count[root] : anchor[root]) + offset[i];
        y[i] = std::round(y[i] * 1e9) / 1e9;  // and no 1e-15 residue of the arithmetic: a nanometre grid
    }
    return violation(y, rows) <= tolerance ? y : x;
}

/// `rows` over n variables as ALGLIB takes linear constraints: a sparse matrix and its lower and upper
/// bounds.
struct Rows {
    Rows(const std::vector<LinearConstraint>& rows, int n) : count(static_cast<int>(rows.size()))
    {
        alglib::sparsecreate(count, n, matrix);
        lower.setlength(count);
        upper.setlength(count);
        for (int r = 0; r < count; ++r) {
            for (const auto& [variable, coefficient] : rows[r].terms)
                alglib::sparseadd(matrix, r, variable, coefficient);
            lower[r] = rows[r].lower;
            upper[r] = rows[r].upper;
        }
        alglib::sparseconverttocrs(matrix);
    }
    int count;
    alglib::sparsematrix matrix;
    alglib::real_1d_array lower, upper;
};

/// One QP solve: whether it solved, x, and the solver's Lagrange multipliers of the rows.
struct QP {
    bool solved = false;
    Eigen::VectorXd x;
    std::vector<double> multipliers;
};

QP solveQP(const Eigen::VectorXd& target, const std::vector<LinearConstraint>& rows,
           const Eigen::VectorXd* start, double tolerance)
{
    const int n = static_cast<int>(target.size());
    if (n == 0)
        return {violation(target, rows) <= tolerance, target, std::vector<double>(rows.size(), 0.0)};
    alglib::real_1d_array result;
    alglib::minqpreport report;
    try {
        alglib::minqpstate state;
        alglib::minqpcreate(n, state);
        // Σ (x − t)² = xᵀx − 2tᵀx + const: Hessian 2I, linear term −2t (ALGLIB minimises ½xᵀAx + bᵀx).
        alglib::sparsematrix hessian;
        alglib::sparsecreate(n, n, n, hessian);
        alglib::real_1d_array linear, scale, x0;
        linear.setlength(n);
        scale.setlength(n);
        x0.setlength(n);
        for (int i = 0; i < n; ++i) {
            alglib::sparseset(hessian, i, i, 2.0);
            linear[i] = -2 * target[i];
            scale[i] = 1;
            x0[i] = start ? (*start)[i] : target[i];
        }
        alglib::sparseconverttocrs(hessian);
        alglib::minqpsetquadratictermsparse(state, hessian, true);
        alglib::minqpsetlinearterm(state, linear);
        alglib::minqpsetscale(state, scale);
        alglib::minqpsetstartingpoint(state, x0);
        if (!rows.empty()) {
            const Rows c(rows, n);
            alglib::minqpsetlc2(state, c.matrix, c.lower, c.upper, c.count);
        }
        // 1e-12: looser stopping tolerances can report success with errors up to 0.1 mm (DESIGN.md).
        alglib::minqpsetalgosparseipm(state, 1e-12);
        alglib::minqpoptimize(state);
        alglib::minqpresults(state, result, report);
    } catch (const alglib::ap_error& e) {  // no third-party exception leaves the core
        throw std::runtime_error("the least-change solve failed: " + e.msg);
    }
    Eigen::VectorXd x(n);
    for (int i = 0; i < n; ++i)
        x[i] = result[i];
    std::vector<double> multipliers(rows.size(), 0.0);
    for (size_t r = 0; r < rows.size() && static_cast<long>(r) < report.laglc.length(); ++r)
        multipliers[r] = report.laglc[r];
    if (report.terminationtype <= 0 || violation(x, rows) > tolerance)
        return {false, x, multipliers};
    return {true, snapped(target, rows, polished(target, rows, x, multipliers, tolerance), tolerance),
            multipliers};
}

std::vector<LinearConstraint> without(const std::vector<LinearConstraint>& rows,
                                      const std::vector<std::string>& sources)
{
    const std::set<std::string> gone(sources.begin(), sources.end());
    std::vector<LinearConstraint> kept;
    for (const LinearConstraint& row : rows)
        if (row.source.empty() || !gone.count(row.source))
            kept.push_back(row);
    return kept;
}

}  // namespace

double violation(const Eigen::VectorXd& x, const std::vector<LinearConstraint>& constraints)
{
    double worst = 0;
    for (const LinearConstraint& row : constraints) {
        double value = 0;
        for (const auto& [variable, coefficient] : row.terms)
            value += coefficient * x[variable];
        worst = std::max({worst, row.lower - value, value - row.upper});
    }
    return worst;
}

LeastChangeResult solveLeastChange(const Eigen::VectorXd& target,
                                   const std::vector<LinearConstraint>& constraints,
                                   const Eigen::VectorXd* start, double tolerance)
{
    LeastChangeResult result;
    if (result.violation = violation(target, constraints); result.violation <= tolerance) {
        result.solved = true;  // nothing to change: re-solving a solved design leaves it exactly as it is
        result.x = target;
        return result;
    }
    const QP qp = solveQP(target, constraints, start, tolerance);
    result.solved = qp.solved;
    result.x = qp.solved ? qp.x : target;
    result.violation = violation(result.x, constraints);
    if (qp.solved)
        return result;

    // Deletion filter: drop each source in turn; if the rest still conflicts it was not needed. The sources
    // whose rows the infeasible solve gave no multiplier are tried first all at once (one solve instead of
    // hundreds when a large model has one small conflict).
    std::vector<std::string> sources;
    std::map<std::string, double> weight;  // largest |multiplier| of a source's rows
    for (size_t r = 0; r < constraints.size(); ++r) {
        const std::string& source = constraints[r].source;
        if (source.empty())
            continue;
        if (!weight.count(source))
            sources.push_back(source);
        weight[source] = std::max(weight[source], std::abs(qp.multipliers[r]));
    }
    double largest = 0;
    for (const auto& [source, w] : weight)
        largest = std::max(largest, w);
    std::vector<std::string> dropped;
    for (const std::string& source : sources)
        if (weight[source] <= 1e-6 * largest)
            dropped.push_back(source);
    if (dropped.empty() || solveQP(target, without(constraints, dropped), nullptr, tolerance).solved)
        dropped.clear();  // the multipliers did not tell: one by one
    for (const std::string& source : sources) {
        if (std::find(dropped.begin(), dropped.end(), source) != dropped.end())
            continue;
        dropped.push_back(source);
        if (solveQP(target, without(constraints, dropped), nullptr, tolerance).solved) {
            dropped.pop_back();  // needed for the conflict
            result.conflict.push_back(source);
        }
    }
    return result;
}

namespace {

/// How far below a programme's least a variable's bound is put (mm): more than the solver's tolerance, so
/// that the bound holds however the solver rounds.
constexpr double kLeastHair = 1e-3;

/// Variables' boxes and the rows of more than one variable, as ALGLIB's linear programming takes them.
struct Programme {
    std::vector<Interval> boxes;
    std::vector<LinearConstraint> rows;
};

/// `rows` over n variables as a Programme: the boxes bound propagation finds, a variable its box fixes as a
/// constant of the rows it is in (so that it ties no programme together), and only the rows of more than one
/// variable its boxes do not already imply; nullopt when propagation shows the rows cannot hold.
std::optional<Programme> programmeOf(const std::vector<LinearConstraint>& rows, int n)
{
    Programme p{propagatedBounds(rows, n), {}};
    if (std::any_of(p.boxes.begin(), p.boxes.end(),
                    [](const Interval& box) { return box.lower > box.upper; }))
        return std::nullopt;
    for (const LinearConstraint& row : rows) {
        const Interval range = rangeOf(row, p.boxes);
        if (row.lower <= range.lower && range.upper <= row.upper)
            continue;  // implied
        LinearConstraint left{{}, row.lower, row.upper, row.source};
        for (const auto& [i, a] : row.terms) {
            const Interval& box = p.boxes[i];
            if (box.lower == box.upper)
                left.lower -= a * box.lower, left.upper -= a * box.lower;
            else
                left.terms.emplace_back(i, a);
        }
        if (left.terms.size() > 1)
            p.rows.push_back(std::move(left));
    }
    return p;
}

/// The least of each of `variables` over programme p, whose rows tie its variables together.
std::vector<std::optional<double>> leastInGroup(const std::vector<int>& variables, const Programme& p,
                                                double tolerance)
{
    const int n = static_cast<int>(p.boxes.size());
    std::vector<std::optional<double>> least(variables.size());
    try {
        alglib::minlpstate state;
        alglib::minlpcreate(n, state);
        alglib::real_1d_array low, high, cost, x;
        low.setlength(n);
        high.setlength(n);
        for (int i = 0; i < n; ++i)
            low[i] = p.boxes[i].lower, high[i] = p.boxes[i].upper;
        alglib::minlpsetbc(state, low, high);
        if (!p.rows.empty()) {
            const Rows c(p.rows, n);
            alglib::minlpsetlc2(state, c.matrix, c.lower, c.upper, c.count);
        }
        alglib::minlpsetalgoipm(state, 0);
        cost.setlength(n);
        for (size_t k = 0; k < variables.size(); ++k) {
            for (int i = 0; i < n; ++i)
                cost[i] = i == variables[k] ? 1 : 0;
            alglib::minlpsetcost(state, cost);
            alglib::minlpoptimize(state);
            alglib::minlpreport report;
            alglib::minlpresults(state, x, report);
            Eigen::VectorXd at(n);
            bool inBoxes = true;
            for (int i = 0; i < n; ++i) {
                at[i] = x[i];
                inBoxes &= p.boxes[i].lower - tolerance <= at[i] && at[i] <= p.boxes[i].upper + tolerance;
            }
            if (report.terminationtype > 0 && inBoxes && violation(at, p.rows) <= tolerance)
                least[k] = at[variables[k]];
        }
    } catch (const alglib::ap_error& e) {  // no third-party exception leaves the core
        throw std::runtime_error("a linear programme failed: " + e.msg);
    }
    return least;
}

/// Each variable's group: the variables rows tie to it, directly or through others (union-find).
std::vector<int> groupsOf(const std::vector<LinearConstraint>& rows, int n)
{
    std::vector<int> parent(n);
    std::iota(parent.begin(), parent.end(), 0);
    const std::function<int(int)> root = [&](int i) {
        return parent[i] == i ? i : parent[i] = root(parent[i]);
    };
    for (const LinearConstraint& row : rows)
        for (const auto& term : row.terms)
            parent[root(term.first)] = root(row.terms.front().first);
    for (int i = 0; i < n; ++i)
        parent[i] = root(i);
    return parent;
}

}  // namespace

std::optional<std::vector<double>> leastOf(const std::vector<int>& variables,
                                           const std::vector<LinearConstraint>& rows, int n, double tolerance)
{
    const std::optional<Programme> whole = programmeOf(rows, n);
    if (!whole)
        return std::nullopt;
    std::vector<double> least(variables.size());
    // One programme per group of the variables asked for, over that group alone: a design's axes and
    // parts apart make programmes a fraction of the whole's size. A variable its box fixes needs none, nor
    // one whose box has no lower end: its programme may be unbounded, which solvers do not all report.
    const std::vector<int> group = groupsOf(whole->rows, n);
    std::map<int, std::vector<size_t>> asked;
    for (size_t k = 0; k < variables.size(); ++k) {
        const Interval& box = whole->boxes[variables[k]];
        least[k] = box.lower;
        if (box.lower < box.upper && std::isfinite(box.lower))
            asked[group[variables[k]]].push_back(k);
    }
    for (const auto& [g, ks] : asked) {
        std::vector<int> local(n, -1);
        Programme p;
        for (int i = 0; i < n; ++i)
            if (group[i] == g) {
                local[i] = static_cast<int>(p.boxes.size());
                p.boxes.push_back(whole->boxes[i]);
            }
        for (const LinearConstraint& row : whole->rows)
            if (group[row.terms.front().first] == g) {
                p.rows.push_back(row);
                for (auto& term : p.rows.back().terms)
                    term.first = local[term.first];
            }
        std::vector<int> localAsked;
        for (size_t k : ks)
            localAsked.push_back(local[variables[k]]);
        const std::vector<std::optional<double>> found = leastInGroup(localAsked, p, tolerance);
        for (size_t j = 0; j < ks.size(); ++j)
            if (found[j])
                least[ks[j]] = std::max(least[ks[j]], *found[j] - kLeastHair);
    }
    return least;
}

}  // namespace fabguide::function
