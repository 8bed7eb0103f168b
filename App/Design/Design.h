// A flat-pack design in object space (thesis 5.1, 5.2.1, 5.3.5): boards as boxes, the design vector X,
// design constraints C X = s and effectiveness constraints (ranges, minimum lengths, inner and outer
// volumes).
#pragma once

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

namespace fabguide::material {

/// A board of the design: an axis-aligned box whose side along `normal` is the material thickness.
struct DesignBoard {
    std::string id;
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    Eigen::Vector3d size = Eigen::Vector3d::Zero();
    int normal = 2;  ///< axis of the thickness: 0 x, 1 y, 2 z
    int quantity = 1;
    bool followsGrain = false;
    int grainAxis =
        -1;  ///< the axis (0 x, 1 y, 2 z) the grain runs along in the model; -1: the first in-plane
    /// The in-plane axes: the board's width in material space runs along the first, its height along the
    /// second (thesis 5.2.2: w = l^x, h = l^y in the part's own frame); the grain axis first when it is set,
    /// so a board that follows the grain has it along its length whichever way it stands.
    std::array<int, 2> inPlane() const;
};

/// X holds six variables per board: its centre (x, y, z) then its size (x, y, z) (thesis 5.2: the box
/// centre and the lengths of its sides).
inline int centreVariable(int board, int axis)
{
    return 6 * board + axis;
}
inline int sizeVariable(int board, int axis)
{
    return 6 * board + 3 + axis;
}

/// Σ coefficient · X[variable] + constant.
struct Linear {
    std::vector<std::pair<int, double>> terms;
    double constant = 0;
    double value(const Eigen::VectorXd& X) const;
    Linear operator-(const Linear& other) const;
    Linear operator+(const Linear& other) const;
    Linear operator*(double factor) const;
};

/// A board's centre, size, or its lower / upper face along an axis, as a linear expression in X.
Linear centreOf(int board, int axis);
Linear sizeOf(int board, int axis);
Linear lowerFace(int board, int axis);
Linear upperFace(int board, int axis);
Linear constant(double value);

/// A named constraint on the design: `expression` = 0 for a design constraint, <= 0 for a bound.
struct DesignConstraint {
    std::string name;
    Linear expression;
};

/// Space that must stay free of boards (thesis 5.3.5.1): a box of `size` resting on board `on`, its lower
/// corner `offset` from the board's faces it is anchored to, so it moves with the board that holds it.
struct InnerVolume {
    std::string name;
    int on = 0;
    /// Per axis, the face of its board the volume keeps its distance from as the board changes (5.1: the
    /// space travels with its board): -1 the lower face, +1 the upper one, whichever it was drawn nearer
    /// (anchored at the centre, a board shrunk to the volume's length left an off-centre volume
    /// hanging over).
    std::array<int, 3> anchor{-1, -1, -1};
    Eigen::Vector3d offset = Eigen::Vector3d::Zero();  ///< the volume's lower corner from its anchors
    Eigen::Vector3d size = Eigen::Vector3d::Zero();
    Linear lower(int axis) const;  ///< the box's lower face
    Linear upper(int axis) const;
};

struct Design {
    std::vector<DesignBoard> boards;
    std::vector<DesignConstraint> equalities;  ///< C X = s (design constraints, 5.1)
    std::vector<DesignConstraint> bounds;      ///< effectiveness: ranges, minimum lengths, outer volume
    std::vector<InnerVolume> innerVolumes;

    Eigen::VectorXd variables() const;
    /// The boards at design vector X.
    std::vector<DesignBoard> boardsAt(const Eigen::VectorXd& X) const;
    /// Variables no change may touch: the thicknesses.
    std::vector<bool> frozen() const;
    /// Lower limits per variable (minimum lengths, -inf for positions).
    Eigen::VectorXd minimum() const;
};

/// Whether board `board` at X overlaps the inner volume's interior by more than `tolerance` on every axis.
bool intrudes(const InnerVolume& volume, int board, const Eigen::VectorXd& X, double tolerance = 1e-6);

/// E(X) of thesis 5.3.5.1: every bound holds and no board enters an inner volume.
bool effective(const Design& design, const Eigen::VectorXd& X);

/// An effectiveness constraint X breaks: a bound's name, or an inner volume's and the board entering it.
struct Ineffective {
    std::string name, enteredBy;
    std::string said() const;  ///< "name", or "name (entered by board)"
};

/// The effectiveness constraints X breaks (empty when E(X) is true).
std::vector<Ineffective> ineffective(const Design& design, const Eigen::VectorXd& X);

/// Each one's said().
std::vector<std::string> said(const std::vector<Ineffective>& broken);

/// The design constraints X breaks by more than `tolerance` mm, by name.
std::vector<std::string> unsatisfied(const Design& design, const Eigen::VectorXd& X, double tolerance = 1e-6);

/// Edge snapping (5.1) of two boards that touch: equalities that keep their facing faces together and every
/// pair of faces flush now flush, and bounds that keep them overlapping where they are not flush (by their
/// present overlap, at most the thinner board's thickness). Both empty when the boards do not touch.
struct Snapping {
    std::vector<DesignConstraint> equalities;
    std::vector<DesignConstraint> bounds;
};
Snapping snapping(const Design& design, int a, int b, double tolerance = 1e-6);

/// Physical validity as bounds of the exploration, not filters after it: boards that do not
/// overlap in the design never do ("apart: a/b", each pair kept on the side of the axis it is most apart
/// along, for pairs within `margin` mm: in furniture, every pair, since a rail may grow 300 mm towards a
/// shelf; a sweep beyond), and no board goes below the
/// design's lowest face ("above ground: a").
std::vector<DesignConstraint> keptApart(const Design& design, double margin = 3000);

}  // namespace fabguide::material
