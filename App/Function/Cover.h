// Cover relationships (thesis 4.2.1, 4.3.1): inferring the corresponding-faces graph and ordering each set of
// coplanar faces by a plane sweep, so that packing constraints close the gaps between neighbours.
#pragma once

#include "Function/Model.h"

#include <array>
#include <utility>
#include <vector>

namespace fabguide::function {

/// The corresponding-faces graph M (4.3.1) and what it took to link every part named.
struct InferredCover {
    std::vector<std::pair<Face, Face>> pairs;  ///< (covering face, covered face)
    InferenceNotes notes;                      ///< parts linked beyond the distance
    std::vector<int> unlinked;                 ///< parts with no face facing the other side at all
};

/// Each covering face is linked to every covered face that faces it, parallel, at most `distance` away,
/// overlapping it by more than half the smaller face's area in their plane. Unlike the thesis' greedy pass a
/// covered face may take several covering faces (two doors, one opening). Of a cavity only an opening can be
/// covered, and a covering face linked to an opening is not linked to the wall around it. A part named but
/// left with no link within the distance (a door drawn 7 mm off at 5 mm) is linked by its nearest facing
/// faces and noted: every part the user named takes part.
InferredCover inferCover(const Model& model, const std::vector<int>& covering,
                         const std::vector<int>& covered, int configuration, double distance);

/// A connected component of M: the covering and the covered faces that must lie in one plane.
struct CoverComponent {
    std::vector<Face> covering, covered;
};
std::vector<CoverComponent> components(const std::vector<std::pair<Face, Face>>& pairs);

/// A plane sweep over coplanar faces (4.3.1, Fig. 4.11): along each in-plane axis, the neighbours (a's high
/// side meets b's low side: every two faces side by side, in order, with no face between them), their sides
/// across that lie within `align` mm of each other (lined up: one seam), and the faces at either end, which
/// share the end's coordinate.
struct Packing {
    struct Neighbours {
        Face a, b;
        int axis = 0;
    };
    std::vector<Neighbours> neighbours;
    std::vector<std::pair<Face, Face>> aligned;  ///< sides made equal
    std::array<std::vector<Face>, 6> ends;  ///< by Side: faces at the low / high end of each in-plane axis
};
Packing packing(const Model& model, const std::vector<Face>& faces, int configuration, double align);

}  // namespace fabguide::function
