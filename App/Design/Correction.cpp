#include "Design/Correction.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>

namespace fabguide::material {

namespace {

constexpr double kResidual = 1e-9;  // mm, thesis 5.3.5.2

/// The equalities as C and s (C X = s), C also by columns for the variable choice, with what limits the
/// variables (frozen thicknesses, minimum lengths); made once for the many corrections a change tries.
struct System {
    Eigen::MatrixXd C;
    Eigen::VectorXd s;
    std::vector<std::string> names;
    std::vector<std::vector<std::pair<int, double>>> columns;  ///< per variable: (row, coefficient)
    std::vector<bool> frozen;
    Eigen::VectorXd minimum;
};

System systemOf(const Design& design, const std::vector<DesignConstraint>& extra, int variables)
{
    std::vector<const DesignConstraint*> rows;
    for (const auto& e : design.equalities)
        rows.push_back(&e);
    for (const auto& e : extra)
        rows.push_back(&e);
    System system{Eigen::MatrixXd::Zero(static_cast<int>(rows.size()), variables),
                  Eigen::VectorXd(static_cast<int>(rows.size())),
                  {},
                  std::vector<std::vector<std::pair<int, double>>>(variables),
                  design.frozen(),
                  design.minimum()};
    for (size_t i = 0; i < rows.size(); ++i) {
        for (const auto& [variable, coefficient] : rows[i]->expression.terms)
            system.C(static_cast<int>(i), variable) += coefficient;
        system.s[static_cast<int>(i)] = -rows[i]->expression.constant;
        system.names.push_back(rows[i]->name);
    }
    for (int v = 0; v < variables; ++v)
        for (int i = 0; i < system.C.rows(); ++i)
            if (system.C(i, v) != 0)
                system.columns[v].emplace_back(i, system.C(i, v));
    return system;
}

/// The next variable to free (Algorithm 6, lines 9-17), or -1 when none may move.
int chooseVariable(const System& system, const Eigen::VectorXd& r, const Eigen::VectorXd& at,
                   const std::vector<bool>& fixed, const Eigen::VectorXd& minimum)
{
    int best = -1;
    double bestScore = -std::numeric_limits<double>::infinity();
    for (int v = 0; v < static_cast<int>(system.columns.size()); ++v) {
        if (fixed[v])
            continue;
        bool inBrokenRow = false;
        double cr = 0, cc = 0;
        for (const auto& [row, c] : system.columns[v]) {
            inBrokenRow = inBrokenRow || std::abs(r[row]) > kResidual;
            cr += c * r[row];
            cc += c * c;
        }
        if (!inBrokenRow)
            continue;
        const double m = -cr / cc;  // how far it would move alone
        const bool length = v % 6 >= 3;
        if (length && at[v] + m < minimum[v] - 1e-9)
            continue;  // it would pass its minimum length
        double score = -std::abs(m);
        if (length)
            score -= 1e6;  // positions before lengths
        if (std::abs(cr) < 1e-12)
            score -= 1e12;  // alone it cannot help
        if (score > bestScore) {
            bestScore = score;
            best = v;
        }
    }
    return best;
}

/// Algorithm 6 on a prepared system.
std::optional<Eigen::VectorXd> correct(const System& system, const Eigen::VectorXd& X,
                                       const Eigen::VectorXd& u, std::vector<std::string>* broken,
                                       const Deadline& deadline = {})
{
    const int n = static_cast<int>(X.size());
    const Eigen::VectorXd changed = X + u;
    const Eigen::VectorXd& minimum = system.minimum;
    std::vector<bool> fixed = system.frozen;
    for (int v = 0; v < n; ++v)
        fixed[v] = fixed[v] || u[v] != 0;

    Eigen::VectorXd d = Eigen::VectorXd::Zero(n);
    const Eigen::VectorXd target = system.s - system.C * changed;
    Eigen::VectorXd r = -target;
    std::vector<int> freed;  // Λ
    while (r.norm() >= kResidual) {
        const int v = chooseVariable(system, r, changed + d, fixed, minimum);
        if (v >= 0 && deadline.passed())
            return std::nullopt;
        if (v < 0) {
            if (broken)
                for (int i = 0; i < r.size(); ++i)
                    if (std::abs(r[i]) >= kResidual)
                        broken->push_back(system.names[i]);
            return std::nullopt;
        }
        fixed[v] = true;
        freed.push_back(v);
        // SolvePartialCorrectionVector: least-norm d over the freed variables.
        Eigen::MatrixXd subset(system.C.rows(), static_cast<int>(freed.size()));
        for (size_t k = 0; k < freed.size(); ++k)
            subset.col(static_cast<int>(k)) = system.C.col(freed[k]);
        const Eigen::VectorXd dFreed = subset.completeOrthogonalDecomposition().solve(target);
        d.setZero();
        for (size_t k = 0; k < freed.size(); ++k)
            d[freed[k]] = dFreed[static_cast<int>(k)];
        r = subset * dFreed - target;
    }
    return d;
}

}  // namespace

std::optional<Eigen::VectorXd> correctForDesignConstraints(const Design& design,
                                                           const std::vector<DesignConstraint>& extra,
                                                           const Eigen::VectorXd& X, const Eigen::VectorXd& u,
                                                           std::vector<std::string>* broken)
{
    return correct(systemOf(design, extra, static_cast<int>(X.size())), X, u, broken);
}

namespace {

/// AddDynamicConstraints (Algorithm 5, line 14): the effectiveness constraints that hold at `before` and
/// break at `after`, as equalities that hold them where they are about to break.
std::vector<DesignConstraint> heldAtFirstBreak(const Design& design, const Eigen::VectorXd& before,
                                               const Eigen::VectorXd& after)
{
    std::vector<DesignConstraint> held;
    for (const DesignConstraint& bound : design.bounds)
        if (bound.expression.value(before) <= 1e-7 && bound.expression.value(after) > 1e-7)
            held.push_back({bound.name, bound.expression});
    for (const InnerVolume& volume : design.innerVolumes)
        for (int b = 0; b < static_cast<int>(design.boards.size()); ++b) {
            if (intrudes(volume, b, before) || !intrudes(volume, b, after))
                continue;
            // Keep the board on the side of the volume it was on before.
            for (int axis = 0; axis < 3; ++axis) {
                const Linear below = upperFace(b, axis) - volume.lower(axis);
                const Linear above = volume.upper(axis) - lowerFace(b, axis);
                const std::string name = volume.name + " (kept free of " + design.boards[b].id + ")";
                if (below.value(before) <= 1e-6) {
                    held.push_back({name, below});
                    break;
                }
                if (above.value(before) <= 1e-6) {
                    held.push_back({name, above});
                    break;
                }
            }
        }
    return held;
}

}  // namespace

CorrectedChange correctChange(const Design& design, const Eigen::VectorXd& X, const Eigen::VectorXd& u,
                              const Deadline& deadline)
{
    std::vector<DesignConstraint> held;
    std::vector<std::string> broken;  // the design constraints the last failed attempt could not keep
    System system = systemOf(design, held, static_cast<int>(X.size()));
    const auto attempt = [&](double alpha) -> std::optional<Eigen::VectorXd> {
        broken.clear();
        auto d = correct(system, X, alpha * u, &broken, deadline);
        if (!d)
            return std::nullopt;
        return X + alpha * u + *d;
    };
    const auto isHeld = [&](const std::string& name) {
        return std::any_of(held.begin(), held.end(),
                           [&](const DesignConstraint& c) { return c.name == name; });
    };
    CorrectedChange best{X, 0, {}};
    while (true) {
        if (auto full = attempt(1.0); full && effective(design, *full))
            return {*full, 1.0, {}};
        // Bisection on alpha for the first break (lines 4-12).
        double l = best.alpha, r = 1.0;
        Eigen::VectorXd atL = best.X, atR = X + u;
        const double step = std::max(1e-12, u.lpNorm<Eigen::Infinity>());
        while ((r - l) * step > 1e-4 && !deadline.passed()) {  // to a tenth of a micrometre along the change
            const double m = (l + r) / 2;
            const auto at = attempt(m);
            if (at && effective(design, *at)) {
                l = m;
                atL = *at;
            } else {
                r = m;
                atR = at ? *at : X + m * u;
            }
        }
        best.X = atL;
        best.alpha = l;
        // Hold what breaks there (lines 13-16); each round holds one more, so this ends.
        size_t added = 0;
        for (DesignConstraint& c : heldAtFirstBreak(design, atL, atR))
            if (!isHeld(c.name)) {
                held.push_back(std::move(c));
                ++added;
            }
        system = systemOf(design, held, static_cast<int>(X.size()));
        if (added == 0 || deadline.passed()) {
            for (const DesignConstraint& c : held)
                best.limits.push_back(c.name);
            for (const std::string& name : broken.empty() ? said(ineffective(design, atR)) : broken)
                if (!isHeld(name))
                    best.limits.push_back(name);
            return best;
        }
    }
}

}  // namespace fabguide::material
