// The least design (for saving a sheet): every part as small as the design's constraints allow.
#pragma once

#include "Design/Design.h"

#include <optional>

namespace fabguide::material {

/// The design with every part as small as the constraints allow: the least-change solve (thesis 4.4) towards
/// an aim far below every length in proportion to the area it carries (so it approaches the least total area)
/// subject to the design constraints, the bounds, minimum lengths, the thicknesses as they are, and every
/// board on the side of each inner volume it is on at X (so every design between X and the result keeps its
/// inner volumes free). nullopt when the solve fails.
std::optional<Eigen::VectorXd> leastDesign(const Design& design, const Eigen::VectorXd& X);

/// X with each board side at a length no design leastDesign chooses among undercuts (function::leastOf over
/// the same constraints, a design free to move whole held in place): the boards at these sides have no more
/// area than any such design's, wherever a sum or a chain of constraints ties the sides together. nullopt
/// when the constraints cannot hold together.
std::optional<Eigen::VectorXd> shortestSides(const Design& design, const Eigen::VectorXd& X);

}  // namespace fabguide::material
