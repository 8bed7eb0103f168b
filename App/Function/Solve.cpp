#include "Function/Solve.h"

#include <limits>
#include <stdexcept>

namespace fabguide::function {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
const char* kSideNames[] = {"left", "right", "near", "far", "bottom", "top"};

int axis(Side side)
{
    return static_cast<int>(side) / 2;
}

std::string faceName(const Model& model, const Face& face)
{
    return model.cuboids[face.cuboid].name + "." + kSideNames[static_cast<int>(face.side)];
}

/// left − right as constraint terms and the constant that moves to the bound.
std::pair<std::vector<std::pair<int, double>>, double> difference(const Expression& left,
                                                                  const Expression& right)
{
    std::vector<std::pair<int, double>> terms;
    for (const auto& [c, face] : left.terms)
        terms.push_back({variable(face), c});
    for (const auto& [c, face] : right.terms)
        terms.push_back({variable(face), -c});
    return {terms, right.constant - left.constant};
}

}  // namespace

std::vector<LinearConstraint> constraints(const Model& model)
{
    std::vector<LinearConstraint> rows;
    for (int c = 0; c < static_cast<int>(model.cuboids.size()); ++c)
        for (int a = 0; a < 3; ++a)  // right − left >= minimum size, along each axis
            rows.push_back(
                {{{6 * c + 2 * a + 1, 1.0}, {6 * c + 2 * a, -1.0}}, model.minimumSize, kInfinity, ""});
    for (const Flush& f : model.flush) {  // thesis 4.2.4: the two faces coplanar
        if (axis(f.a.side) != axis(f.b.side))
            throw std::invalid_argument("flush '" + f.name + "': " + faceName(model, f.a) + " and " +
                                        faceName(model, f.b) + " are not parallel");
        rows.push_back({{{variable(f.a), 1.0}, {variable(f.b), -1.0}}, 0, 0, f.name});
    }
    for (const Geometric& g : model.geometric) {  // thesis 4.3.5
        auto [terms, bound] = difference(g.left, g.right);
        rows.push_back({terms, g.relation == Geometric::Relation::Equal ? bound : -kInfinity, bound, g.name});
    }
    for (const Lock& lock : model.locks) {
        const double value = model.cuboids[lock.face.cuboid].at(lock.face.side);
        rows.push_back({{{variable(lock.face), 1.0}}, value, value, "lock: " + faceName(model, lock.face)});
    }
    return rows;
}

SolveResult solve(const Model& model)
{
    Eigen::VectorXd target(6 * model.cuboids.size());
    for (size_t c = 0; c < model.cuboids.size(); ++c)
        for (int k = 0; k < 6; ++k)
            target[6 * c + k] = model.cuboids[c].coordinates[k];
    const LeastChangeResult r = solveLeastChange(target, constraints(model));
    SolveResult result{r.solved, model, r.conflict, r.violation};
    for (size_t c = 0; c < model.cuboids.size() && r.solved; ++c)
        for (int k = 0; k < 6; ++k)
            result.model.cuboids[c].coordinates[k] = r.x[6 * c + k];
    return result;
}

}  // namespace fabguide::function
