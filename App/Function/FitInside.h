// Inferring how the inner parts of a fit-inside relationship stay apart and where they just fit
// (thesis 4.3.2).
#pragma once

#include "Function/Model.h"

#include <vector>

namespace fabguide::function {

/// The side of a part's bounding box in a configuration, as the face of the solid cuboid that is extreme
/// there now; of the cuboids in `portion` only, when the part has any there (a partial fit, 4.2.2).
Face extremeFace(const Model& model, int part, Side side, int configuration,
                 const std::vector<int>& portion = {});

/// For each pair of cuboids of different inner parts, the axis and order along which they are farthest
/// apart in the configuration (their least overlap when they overlap): keeping that order keeps them apart.
std::vector<FitInside::Apart> inferApart(const Model& model, const std::vector<int>& inner,
                                         int configuration);

/// The face inner parts fit against on a side: the cavity's (if >= 0), else the enclosing part's extreme
/// face.
Face wall(const Model& model, int enclosing, int cavity, Side side, int configuration);

/// "Just fits" along each axis in `axes` (0 x, 1 y, 2 z) of fit inside `f` (its portion, if any), for its
/// inner parts `inner`: on both sides, their extreme face on that side against the wall.
std::vector<std::pair<Face, Face>> inferJust(const Model& model, const FitInside& f,
                                             const std::vector<int>& inner, const std::vector<int>& axes);

}  // namespace fabguide::function
