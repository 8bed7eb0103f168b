#include "Design/DesignSpace.h"

#include "Design/Correction.h"
#include "Design/LeastDesign.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace fabguide::material {

std::optional<Eigen::VectorXd> DesignSpace::least(const Eigen::VectorXd& from,
                                                  std::chrono::steady_clock::time_point deadline) const
{
    constexpr int passes = 2;
    Eigen::VectorXd X = from;
    for (int pass = 0; pass < passes; ++pass) {
        const Eigen::VectorXd before = sizes(X);
        for (int size = 0; size < before.size() && std::chrono::steady_clock::now() < deadline; ++size) {
            Eigen::VectorXd change = Eigen::VectorXd::Zero(before.size());
            change[size] = -0.5 * sizes(X)[size];
            if (const auto next = changePartSizes(X, change))
                X = *next;
        }
        if ((sizes(X) - before).lpNorm<Eigen::Infinity>() < 1)
            break;
    }
    return X;
}

ConstrainedDesign::ConstrainedDesign(Design design) : design_(std::move(design))
{
    for (const DesignBoard& board : design_.boards)
        parts_.push_back({board.id, board.quantity, board.followsGrain, board.size[board.normal]});
}

Eigen::VectorXd ConstrainedDesign::sizes(const Eigen::VectorXd& X) const
{
    Eigen::VectorXd s(2 * design_.boards.size());
    for (int i = 0; i < s.size(); ++i)
        s[i] = X[variableOfSize(i)];
    return s;
}

std::optional<Eigen::VectorXd> ConstrainedDesign::changePartSizes(const Eigen::VectorXd& X,
                                                                  const Eigen::VectorXd& change,
                                                                  const Deadline& deadline) const
{
    Eigen::VectorXd u = Eigen::VectorXd::Zero(X.size());
    for (int i = 0; i < change.size(); ++i)
        u[variableOfSize(i)] = change[i];
    const CorrectedChange corrected = correctChange(design_, X, u, deadline);
    if (corrected.alpha <= 0)
        return std::nullopt;
    return corrected.X;
}

std::optional<Eigen::VectorXd> ConstrainedDesign::between(const Eigen::VectorXd& from,
                                                          const Eigen::VectorXd& to, double t) const
{
    Eigen::VectorXd X = from + t * (to - from);
    if (!effective(design_, X) || !unsatisfied(design_, X).empty())
        return std::nullopt;
    return X;
}

std::optional<Eigen::VectorXd> ConstrainedDesign::least(const Eigen::VectorXd& X,
                                                        std::chrono::steady_clock::time_point) const
{
    return leastDesign(design_, X);
}

std::optional<Eigen::VectorXd> ConstrainedDesign::shortestSides(const Eigen::VectorXd& X) const
{
    const auto shortest = material::shortestSides(design_, X);
    return shortest ? std::optional(sizes(*shortest)) : std::nullopt;
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

Eigen::MatrixXd ParametricDesign::jacobian(const Eigen::VectorXd& X) const
{
    // Forward differences, stepping away from a bound when at the upper one.
    const Eigen::VectorXd s = sizes(X);
    Eigen::MatrixXd J(s.size(), X.size());
    for (int j = 0; j < X.size(); ++j) {
        const double h = (X[j] + 1e-3 <= upper_[j]) ? 1e-3 : -1e-3;
        Eigen::VectorXd stepped = X;
        stepped[j] += h;
        J.col(j) = (sizes(stepped) - s) / h;
    }
    return J;
}

std::optional<Eigen::VectorXd> ParametricDesign::shortestSides(const Eigen::VectorXd& X) const
{
    const Eigen::VectorXd s = sizes(X);
    const Eigen::MatrixXd J = jacobian(X);
    Eigen::VectorXd shortest(s.size());
    std::map<std::vector<double>, Eigen::VectorXd> at;  // D at each corner, computed once (a recompute each)
    for (int i = 0; i < s.size(); ++i) {
        // Where side i is an affine function of the parameters, its least is at the corner of their box that
        // each parameter's slope points away from; the side computed there confirms it.
        std::vector<double> corner(X.data(), X.data() + X.size());
        for (int j = 0; j < X.size(); ++j)
            if (J(i, j) != 0)
                corner[j] = J(i, j) > 0 ? lower_[j] : upper_[j];
        const Eigen::Map<const Eigen::VectorXd> P(corner.data(), X.size());
        shortest[i] = s[i] + J.row(i).dot(P - X);
        if (!at.count(corner))
            at[corner] = sizes(P);
        if (std::abs(at[corner][i] - shortest[i]) > 1e-3 * std::max(1.0, std::abs(shortest[i])))
            return std::nullopt;
        shortest[i] = std::max(0.0, shortest[i] - 1e-3);
    }
    return shortest;
}

std::optional<Eigen::VectorXd> ParametricDesign::changePartSizes(const Eigen::VectorXd& X,
                                                                 const Eigen::VectorXd& change,
                                                                 const Deadline&) const
{
    const Eigen::MatrixXd J = jacobian(X);
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

ParametricDesign parametricBoards(std::vector<PartKind> parts, const std::vector<int>& grainAxes,
                                  const ParametricDesign::SizesOf& boxesOf, Eigen::VectorXd start,
                                  Eigen::VectorXd lower, Eigen::VectorXd upper)
{
    const Eigen::VectorXd sides = boxesOf(start);
    if (sides.size() != static_cast<Eigen::Index>(3 * parts.size()) || grainAxes.size() != parts.size())
        throw std::invalid_argument(
            "parametric design: D(X) must give three sides and a grain axis per part");
    std::vector<DesignBoard> boards(parts.size());
    for (size_t i = 0; i < parts.size(); ++i) {
        const Eigen::Vector3d size = sides.segment<3>(3 * static_cast<Eigen::Index>(i));
        size.minCoeff(&boards[i].normal);
        boards[i].grainAxis = grainAxes[i];
        if (grainAxes[i] == boards[i].normal || grainAxes[i] < -1 || grainAxes[i] > 2)
            throw std::invalid_argument("parametric design: part '" + parts[i].id +
                                        "': its grain must run along one of its two long sides");
        parts[i].followsGrain = grainAxes[i] >= 0;
        parts[i].thickness = size[boards[i].normal];
    }
    auto sizesOf = [boxesOf, boards](const Eigen::VectorXd& X) {
        const Eigen::VectorXd sides = boxesOf(X);
        Eigen::VectorXd s(2 * static_cast<Eigen::Index>(boards.size()));
        for (size_t i = 0; i < boards.size(); ++i)
            for (int k = 0; k < 2; ++k)
                s[2 * static_cast<Eigen::Index>(i) + k] =
                    sides[3 * static_cast<Eigen::Index>(i) + boards[i].inPlane()[k]];
        return s;
    };
    return ParametricDesign(std::move(parts), sizesOf, std::move(start), std::move(lower), std::move(upper));
}

}  // namespace fabguide::material
