#include "Layout/Coplanar.h"

#include <cmath>
#include <numeric>

namespace fabguide::material {

namespace {

using geometry::Point2;
using geometry::Polygon;

/// Board j's point p in board i's frame (exact when they share a plane).
Point2 into(const Board3& i, const Board3& j, Point2 p)
{
    const Eigen::Vector3d d = j.origin + p.x * j.u + p.y * j.v - i.origin;
    return {d.dot(i.u), d.dot(i.v)};
}

Polygon into(const Board3& i, const Board3& j, const Polygon& polygon)
{
    Polygon out;
    for (const Point2& p : polygon)
        out.push_back(into(i, j, p));
    return out;
}

/// Both slabs fill the same layer of space: parallel, same thickness, same faces.
bool samePlane(const Board3& i, const Board3& j, double tolerance)
{
    const double facing = i.n().dot(j.n());
    if (std::abs(std::abs(facing) - 1) > 1e-9 || std::abs(i.thickness - j.thickness) > tolerance)
        return false;
    const double low = (j.origin - i.origin).dot(i.n());
    const double high = low + facing * j.thickness;
    return std::abs(std::min(low, high)) < tolerance &&
           std::abs(std::max(low, high) - i.thickness) < tolerance;
}

/// Outlines sharing more than half of the smaller one's area: boards drawn on top of each other (each panel
/// modelled at the origin), two boards to cut rather than one piece. An L of two rectangles shares a corner.
bool stacked(const Polygon& a, const Polygon& b)
{
    double shared = 0;
    for (const Polygon& common : geometry::intersect(a, geometry::Outline{b, {}}))
        shared += std::abs(geometry::signedArea(common));
    return shared > 0.5 * std::min(std::abs(geometry::signedArea(a)), std::abs(geometry::signedArea(b)));
}

int root(std::vector<int>& parent, int i)
{
    return parent[i] == i ? i : parent[i] = root(parent, parent[i]);
}

}  // namespace

std::vector<Piece> coplanarPieces(const std::vector<Board3>& boards, const JoinedBoards& joined,
                                  double tolerance)
{
    const int count = static_cast<int>(boards.size());
    std::vector<int> parent(count);
    std::iota(parent.begin(), parent.end(), 0);
    for (int i = 0; i < count; ++i)
        for (int j = i + 1; j < count; ++j) {
            if (!samePlane(boards[i], boards[j], tolerance))
                continue;
            const Polygon other = into(boards[i], boards[j], joined.outlines[j].outer);
            if (stacked(joined.outlines[i].outer, other))
                continue;
            try {  // touching or overlapping outlines unite into one piece
                geometry::unite(geometry::Outline{joined.outlines[i].outer, {}}, {other});
            } catch (const std::runtime_error&) {
                continue;  // apart
            }
            parent[root(parent, j)] = root(parent, i);
        }

    std::vector<Piece> pieces;
    std::vector<int> pieceOf(count, -1);
    for (int j = 0; j < count; ++j) {
        const int r = root(parent, j);
        if (pieceOf[r] < 0) {
            pieceOf[r] = static_cast<int>(pieces.size());
            pieces.push_back({});
        }
        pieces[pieceOf[r]].boards.push_back(j);
    }
    for (Piece& piece : pieces) {
        const Board3& frame = boards[piece.boards.front()];
        std::vector<Polygon> outers, holes;
        for (int j : piece.boards) {
            outers.push_back(into(frame, boards[j], joined.outlines[j].outer));
            for (const Polygon& hole : joined.outlines[j].holes)
                holes.push_back(into(frame, boards[j], hole));
            for (const Drill& d : joined.drills[j])
                piece.drills.push_back({into(frame, boards[j], d.at), d.diameter, d.depth});
            for (const Polygon& mark : joined.marks[j])
                piece.marks.push_back(into(frame, boards[j], mark));
        }
        piece.outline = geometry::unite(geometry::Outline{outers.front(), {}}, outers);
        if (!holes.empty())
            piece.outline = geometry::subtract(piece.outline, holes);
    }
    return pieces;
}

}  // namespace fabguide::material
