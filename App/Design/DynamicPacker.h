// The dynamic packer (thesis 5.3.2, Algorithms 1-4): an edit after which the parts no longer fit the master
// boards is absorbed by saturating the lines of parts that overflow (snapping constraints), keeping the edit.
#pragma once

#include "Design/DesignSpace.h"
#include "Design/MaterialSpace.h"

namespace fabguide::material {

/// SWEEP and EXPAND (Algorithms 2-3) along material-space axis `axis` (0 x, 1 y): the units of `layout`, at
/// their positions there but with sizes s, that cross one line across `axis` on a sheet and together are
/// longer than the sheet (as unit indices, each set once).
std::vector<std::vector<int>> overflowingLines(const MaterialSpace& material, const GridLayout& layout,
                                               const Eigen::VectorXd& sizes, int axis);

struct Absorbed {
    bool fitted = false;
    Eigen::VectorXd X;                 ///< the design with the edit kept, fitted when `fitted`
    GridLayout layout;                 ///< its layout, slid from the previous one
    std::vector<std::string> snapped;  ///< the snapping constraints that made it fit
};

/// Algorithm 1, DYNAMIC PACKER: applies edit u to the valid design X laid out as `previous`. When the edited
/// design no longer slides (or docks, in the same order) into the master boards, alternately along x and y
/// (at most `iterations` times) each overflowing line of parts gets a snapping constraint (its lengths sum to
/// what the board holds) unless that contradicts the edit, the design is solved again with the edit kept
/// (Algorithms 5-6) and laid out again (SLIDE, Algorithm 4). The snapping constraints stay for later rounds
/// and none in the design. `fitted` is false when no round made it fit.
Absorbed dynamicPacker(const ConstrainedDesign& design, const MaterialSpace& material,
                       const Eigen::VectorXd& X, const GridLayout& previous, const Eigen::VectorXd& u,
                       int iterations = 4);

}  // namespace fabguide::material
