#include "Material/DesignSpace.h"

#include "Material/Correction.h"

#include <Eigen/Dense>

#include <algorithm>
#include <stdexcept>

namespace fabguide::material {

ConstrainedDesign::ConstrainedDesign(Design design) : design_(std::move(design))
{
    for (const DesignBoard& board : design_.boards)
        parts_.push_back({board.id, board.quantity, board.followsGrain});
}

Eigen::VectorXd ConstrainedDesign::sizes(const Eigen::VectorXd& X) const
{
    Eigen::VectorXd s(2 * design_.boards.size());
    for (int i = 0; i < s.size(); ++i)
        s[i] = X[variableOfSize(i)];
    return s;
}

std::optional<Eigen::VectorXd> ConstrainedDesign::changePartSizes(const Eigen::VectorXd& X,
                                                                  const Eigen::VectorXd& change) const
{
    Eigen::VectorXd u = Eigen::VectorXd::Zero(X.size());
    for (int i = 0; i < change.size(); ++i)
        u[variableOfSize(i)] = change[i];
    const CorrectedChange corrected = correctChange(design_, X, u);
    if (corrected.alpha <= 0)
        return std::nullopt;
    return corrected.X;
}

ParametricDesign::ParametricDesign(std::vector<PartKind> parts, SizesOf sizesOf, Eigen::VectorXd start,
                                   Eigen::VectorXd lower, Eigen::VectorXd upper)
    : parts_(std::move(parts)),
      sizesOf_(std::move(sizesOf)),
      start_(std::move(start)),
      lower_(std::move(lower)),
      upper_(std::move(upper))
{
    if (lower_.size() != start_.size() || upper_.size() != start_.size())
        throw std::invalid_argument("parametric design: one lower and one upper bound per parameter");
    for (int j = 0; j < start_.size(); ++j)
        if (!(lower_[j] <= start_[j] && start_[j] <= upper_[j]))
            throw std::invalid_argument("parametric design: parameter " + std::to_string(j) +
                                        " starts outside its bounds");
    if (sizes(start_).size() != static_cast<Eigen::Index>(2 * parts_.size()))
        throw std::invalid_argument("parametric design: D(X) must give a width and a height per part");
}

Eigen::VectorXd ParametricDesign::sizes(const Eigen::VectorXd& X) const
{
    return sizesOf_(X);
}

std::optional<Eigen::VectorXd> ParametricDesign::changePartSizes(const Eigen::VectorXd& X,
                                                                 const Eigen::VectorXd& change) const
{
    // Gradients ds/dx_j by forward differences, stepping away from a bound when at the upper one.
    const Eigen::VectorXd s = sizes(X);
    Eigen::MatrixXd J(s.size(), X.size());
    for (int j = 0; j < X.size(); ++j) {
        const double h = (X[j] + 1e-3 <= upper_[j]) ? 1e-3 : -1e-3;
        Eigen::VectorXd stepped = X;
        stepped[j] += h;
        J.col(j) = (sizes(stepped) - s) / h;
    }
    const Eigen::VectorXd delta = J.completeOrthogonalDecomposition().solve(change);
    // Keep within the parameter bounds: as much of the change as they allow.
    double alpha = 1;
    for (int j = 0; j < X.size(); ++j) {
        if (delta[j] > 0)
            alpha = std::min(alpha, (upper_[j] - X[j]) / delta[j]);
        else if (delta[j] < 0)
            alpha = std::min(alpha, (lower_[j] - X[j]) / delta[j]);
    }
    if (!(alpha > 1e-9) || !((J * delta).norm() > 1e-9))
        return std::nullopt;
    return X + alpha * delta;
}

}  // namespace fabguide::material
