// Common-line cutting: a line two parts share is cut once.
#pragma once

#include "Layout/CutSheet.h"

#include <vector>

namespace fabguide::material {

/// Where two parts lie a kerf apart, the machine's paths round them (each outline grown by half the kerf)
/// coincide: that stretch is cut once, by the path cut first. Each later closed path loses the stretches
/// that earlier paths in `cuts` already follow (within `tolerance` mm) and is replaced, in its place in the
/// order, by the open paths left of it (none when an earlier path follows all of it). Paths cut open by
/// holding tabs are left alone: their gaps are not cut. Returns the length of path no longer cut twice.
double cutCommonLinesOnce(std::vector<ToolPath>& cuts, double tolerance = 0.01);

}  // namespace fabguide::material
