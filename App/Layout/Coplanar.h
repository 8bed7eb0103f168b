// Coplanar parts (thesis 5.3.4): boards in one plane that touch form one piece, cut as a whole, whose
// voids other parts may fill.
#pragma once

#include "Layout/Connectors.h"

#include <vector>

namespace fabguide::material {

/// One piece to cut: a board, or coplanar boards in contact, in the frame of its first board.
struct Piece {
    std::vector<int> boards;
    geometry::Outline outline;
    std::vector<Drill> drills;
    std::vector<geometry::Polygon> marks;
};

/// Groups the joined boards into pieces: boards whose slabs share a plane and whose outlines touch or
/// overlap (by at most half the smaller one: more is boards drawn on top of each other) become one piece (the
/// union of their outlines, less their holes); every other board is a piece of its own. Pieces are ordered by
/// their first board.
std::vector<Piece> coplanarPieces(const std::vector<Board3>& boards, const JoinedBoards& joined,
                                  double tolerance);

}  // namespace fabguide::material
