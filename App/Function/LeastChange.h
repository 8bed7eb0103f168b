// The least-change solve of thesis 4.4 (eq. 4.6, stage 1): the design nearest to the user's that satisfies
// every linear constraint of its functional relationships, and, when there is none, which relationships
// conflict.
#pragma once

#include <Eigen/Core>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace fabguide::function {

/// lower <= Σ coefficient·x[variable] <= upper (lower == upper: an equality; ±infinity for a one-sided
/// bound, never a large finite stand-in, which upsets the interior-point solver), from the relationship
/// named `source`. Constraints with an empty source (minimum sizes) are always kept and never blamed.
struct LinearConstraint {
    std::vector<std::pair<int, double>> terms;  ///< (variable, coefficient)
    double lower = 0;
    double upper = 0;
    std::string source;
};

struct LeastChangeResult {
    bool solved = false;
    Eigen::VectorXd x;                  ///< the solution (the target when not solved)
    double violation = 0;               ///< largest constraint violation at x, mm
    std::vector<std::string> conflict;  ///< not solved: a minimal set of sources that cannot hold together
};

/// Minimises Σ (x_i − target_i)² subject to the constraints with ALGLIB's sparse interior-point QP; the
/// result counts as solved only if every constraint holds within `tolerance` at it, checked here whatever
/// the solver reports. `start` (optional, e.g. the last solution) warm-starts the solver. When it cannot
/// be solved, a deletion filter over the sources finds a minimal conflicting set.
LeastChangeResult solveLeastChange(const Eigen::VectorXd& target,
                                   const std::vector<LinearConstraint>& constraints,
                                   const Eigen::VectorXd* start = nullptr, double tolerance = 1e-6);

/// Largest amount by which x breaks a constraint (0 when all hold).
double violation(const Eigen::VectorXd& x, const std::vector<LinearConstraint>& constraints);

/// A lower bound on each of `variables` (indices of n) over every x satisfying the constraints: bound
/// propagation's, and where that is finite, its least by one linear programme (ALGLIB's) per variable over
/// the variables the constraints tie to it, less a micrometre for the solver's rounding. nullopt when
/// propagation shows the constraints cannot hold together.
std::optional<std::vector<double>> leastOf(const std::vector<int>& variables,
                                           const std::vector<LinearConstraint>& rows, int n,
                                           double tolerance = 1e-6);

}  // namespace fabguide::function
