// The design function D(X) as the layout search sees it (thesis 5.2.1): part sizes from design parameters,
// and CHANGEPARTSIZES (5.4.2.2), for constrained designs (5.3.5) and parametric ones.
#pragma once

#include "Design/Design.h"
#include "Layout/Deadline.h"

#include <chrono>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace fabguide::material {

/// A part D produces, cut `quantity` times.
struct PartKind {
    std::string id;
    int quantity = 1;
    bool followsGrain = false;
    double thickness = 0;  ///< mm: cut from master boards this thick; 0: any
};

class DesignSpace {
public:
    virtual ~DesignSpace() = default;
    virtual const std::vector<PartKind>& parts() const = 0;
    /// X_s, the user's design.
    virtual Eigen::VectorXd start() const = 0;
    /// s(X): part i's width in material space at 2i, its height at 2i + 1, in mm.
    virtual Eigen::VectorXd sizes(const Eigen::VectorXd& X) const = 0;
    /// CHANGEPARTSIZES: parameters whose part sizes change by about `change` (one entry per size), the other
    /// sizes kept where the design allows; nullopt when the design cannot move that way at all, or not before
    /// `deadline`.
    virtual std::optional<Eigen::VectorXd> changePartSizes(const Eigen::VectorXd& X,
                                                           const Eigen::VectorXd& change,
                                                           const Deadline& deadline = {}) const = 0;
    /// The design a fraction t of the way from valid design `from` to valid design `to` (t in [0, 1]);
    /// nullopt when it breaks a constraint (the design space need not be convex).
    virtual std::optional<Eigen::VectorXd> between(const Eigen::VectorXd& from, const Eigen::VectorXd& to,
                                                   double t) const = 0;
    /// The least design from X (every part as small as the design allows, for saving a sheet): here each
    /// part size in turn shrunk by half through CHANGEPARTSIZES, in up to two passes, until `deadline`;
    /// nullopt when it could not be found.
    virtual std::optional<Eigen::VectorXd> least(const Eigen::VectorXd& X,
                                                 std::chrono::steady_clock::time_point deadline) const;
    /// Part sizes (as `sizes` orders them) that no design `least` chooses among undercuts along any side, so
    /// that their area bounds every such design's from below; nullopt when no bound is known.
    virtual std::optional<Eigen::VectorXd> shortestSides(const Eigen::VectorXd& X) const = 0;
};

/// A design of boards with design and effectiveness constraints: a size change is the change vector u of
/// thesis 5.3.5, kept valid by Algorithms 5 and 6.
class ConstrainedDesign : public DesignSpace {
public:
    explicit ConstrainedDesign(Design design);
    const std::vector<PartKind>& parts() const override { return parts_; }
    Eigen::VectorXd start() const override { return design_.variables(); }
    Eigen::VectorXd sizes(const Eigen::VectorXd& X) const override;
    std::optional<Eigen::VectorXd> changePartSizes(const Eigen::VectorXd& X, const Eigen::VectorXd& change,
                                                   const Deadline& deadline = {}) const override;
    /// Linear constraints hold on the way; an inner volume may not (a board passing by it).
    std::optional<Eigen::VectorXd> between(const Eigen::VectorXd& from, const Eigen::VectorXd& to,
                                           double t) const override;
    /// leastDesign.
    std::optional<Eigen::VectorXd> least(const Eigen::VectorXd& X,
                                         std::chrono::steady_clock::time_point deadline) const override;
    /// material::shortestSides.
    std::optional<Eigen::VectorXd> shortestSides(const Eigen::VectorXd& X) const override;
    const Design& design() const { return design_; }
    /// The design variable behind part size s_i (a board's length along one of its in-plane axes).
    int variableOfSize(int size) const
    {
        return sizeVariable(size / 2, design_.boards[size / 2].inPlane()[size % 2]);
    }

private:
    Design design_;
    std::vector<PartKind> parts_;
};

/// A parametric design (thesis 5.4.2.2): D given as a function from parameters to part sizes, each
/// parameter within [lower, upper]. Sizes change through finite-difference gradients ds/dX and a least
/// squares / least norm solve (complete orthogonal decomposition), cut short at the parameter bounds.
class ParametricDesign : public DesignSpace {
public:
    using SizesOf = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;
    ParametricDesign(std::vector<PartKind> parts, SizesOf sizesOf, Eigen::VectorXd start,
                     Eigen::VectorXd lower, Eigen::VectorXd upper);
    const std::vector<PartKind>& parts() const override { return parts_; }
    Eigen::VectorXd start() const override { return start_; }
    Eigen::VectorXd sizes(const Eigen::VectorXd& X) const override;
    std::optional<Eigen::VectorXd> changePartSizes(const Eigen::VectorXd& X, const Eigen::VectorXd& change,
                                                   const Deadline& deadline = {}) const override;
    /// Where every part side is an affine function of the parameters (as found at X, and confirmed at the
    /// corner of the parameter box where each side is least), each side's least over the box; else nullopt.
    std::optional<Eigen::VectorXd> shortestSides(const Eigen::VectorXd& X) const override;
    /// Parameter bounds are a box: every point on the way is within them.
    std::optional<Eigen::VectorXd> between(const Eigen::VectorXd& from, const Eigen::VectorXd& to,
                                           double t) const override
    {
        return from + t * (to - from);
    }

private:
    /// ds/dX by forward differences, stepping away from a bound when at the upper one.
    Eigen::MatrixXd jacobian(const Eigen::VectorXd& X) const;

    std::vector<PartKind> parts_;
    SizesOf sizesOf_;
    Eigen::VectorXd start_, lower_, upper_;
};

/// A parametric design of boards whose D(X), `boxesOf`, gives each part's three sides (x, y, z). Each part is
/// cut from master boards as thick as its thinnest side at the start, its material-space width along its
/// grain axis (`grainAxes`, -1: none) as DesignBoard::inPlane orders a board's sides: parametric designs
/// honour grain and thickness as constrained ones do.
ParametricDesign parametricBoards(std::vector<PartKind> parts, const std::vector<int>& grainAxes,
                                  const ParametricDesign::SizesOf& boxesOf, Eigen::VectorXd start,
                                  Eigen::VectorXd lower, Eigen::VectorXd upper);

}  // namespace fabguide::material
