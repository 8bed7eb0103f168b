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

}  // namespace fabguide::material
