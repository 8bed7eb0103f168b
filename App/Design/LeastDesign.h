// The least design (issue 14, for saving a sheet): every part as small as the design's constraints allow.
#pragma once

#include "Design/Design.h"

#include <optional>

namespace fabguide::material {

/// The design nearest in kind to X with the least material: a linear programme minimising the part areas'
/// first-order change (each in-plane length weighted by the part's other length at X and its quantity)
/// subject to the design constraints, the bounds, minimum lengths, the thicknesses as they are, and every
/// board on the side of each inner volume it is on at X (so every design between X and the result keeps its
/// inner volumes free). nullopt when the programme fails (X itself breaking a constraint).
std::optional<Eigen::VectorXd> leastDesign(const Design& design, const Eigen::VectorXd& X);

}  // namespace fabguide::material
