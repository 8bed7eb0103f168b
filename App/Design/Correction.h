// Keeping a changed design valid (thesis 5.3.5): a sparse correction for the design constraints
// (Algorithm 6) inside a bisection that turns effectiveness constraints into equalities where they are
// first broken (Algorithm 5).
#pragma once

#include "Design/Design.h"
#include "Layout/Deadline.h"

#include <optional>

namespace fabguide::material {

/// Algorithm 6, CORRECTFORDESIGNCONSTRAINT: a correction d with C (X + u + d) = s and d_i = 0 wherever
/// u_i != 0 or the variable is frozen. Variables join the solve one at a time, greedily: those that can
/// reduce the residual, positions before lengths, the smallest estimated move first, never a length whose
/// move would pass its minimum; the subset is solved by complete orthogonal decomposition (least norm).
/// `extra` equalities are added to the design's. Residual accepted below 1e-9 mm. nullopt on failure, with
/// the names of the equalities still broken in `broken`.
std::optional<Eigen::VectorXd> correctForDesignConstraints(const Design& design,
                                                           const std::vector<DesignConstraint>& extra,
                                                           const Eigen::VectorXd& X, const Eigen::VectorXd& u,
                                                           std::vector<std::string>* broken = nullptr);

/// What a change became after correction.
struct CorrectedChange {
    Eigen::VectorXd X;                ///< the valid design reached: X + alpha u + d
    double alpha = 0;                 ///< how much of the change it keeps, 1 when all
    std::vector<std::string> limits;  ///< the constraints that stopped it short of alpha = 1
};

/// Algorithm 5, DYNAMICEFFECTIVENESSCONSTRAINTS: applies change u to the valid design X. When the corrected
/// design breaks an effectiveness constraint, bisects on alpha for the first break, holds the constraints
/// that broke there as equalities and goes on; when nothing more can be held, returns the best partial
/// change (thesis 5.3.5.3: the solver's callers accept partial solutions). Past `deadline`, the partial
/// change reached so far (none at first): one correction of a large design takes seconds.
CorrectedChange correctChange(const Design& design, const Eigen::VectorXd& X, const Eigen::VectorXd& u,
                              const Deadline& deadline = {});

}  // namespace fabguide::material
