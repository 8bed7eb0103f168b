#include "Layout/Connectors.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fabguide::material {

namespace {

using Eigen::Vector3d;
using geometry::Point2;
using geometry::Polygon;

Vector3d world(const Board3& b, Point2 p, double z = 0)
{
    return b.origin + p.x * b.u + p.y * b.v + z * b.n();
}

Point2 local(const Board3& b, const Vector3d& p)
{
    const Vector3d d = p - b.origin;
    return {d.dot(b.u), d.dot(b.v)};
}

double heightAbove(const Board3& b, const Vector3d& p)
{
    return (p - b.origin).dot(b.n());
}

Point2 operator+(Point2 a, Point2 b)
{
    return {a.x + b.x, a.y + b.y};
}
Point2 operator*(double s, Point2 a)
{
    return {s * a.x, s * a.y};
}
double dot(Point2 a, Point2 b)
{
    return a.x * b.x + a.y * b.y;
}

/// A straight edge of board `a` lying on a face of board `b` over [t0, t1] mm from `p0` along `dir`;
/// `out` is the edge's outward normal in a's plane (it points into b).
struct EdgeContact {
    int a = 0, b = 0;
    Point2 p0, dir, out;
    double t0 = 0, t1 = 0;
    Point2 at(double t) const { return p0 + t * dir; }
};

/// Where the edge faces of board a lie on the faces of board b (thesis 5.1: boards meeting edge to face).
std::vector<EdgeContact> edgeContacts(const std::vector<Board3>& boards, int a, int b, double tolerance)
{
    std::vector<EdgeContact> contacts;
    const Board3 &A = boards[a], &B = boards[b];
    const Polygon& outer = A.outline.outer;
    const double turn =
        geometry::signedArea(outer) > 0 ? 1 : -1;  // outward normal is on the right of a CCW edge
    for (size_t i = 0; i < outer.size(); ++i) {
        const Point2 p0 = outer[i], p1 = outer[(i + 1) % outer.size()];
        const double length = std::hypot(p1.x - p0.x, p1.y - p0.y);
        if (length < tolerance)
            continue;
        const Point2 dir{(p1.x - p0.x) / length, (p1.y - p0.y) / length};
        const Point2 out{turn * dir.y, -turn * dir.x};
        const Vector3d m = out.x * A.u + out.y * A.v;
        const double facing = m.dot(B.n());
        if (std::abs(std::abs(facing) - 1) > 1e-6)
            continue;  // the edge face is not parallel to b's faces
        const double face =
            facing < 0 ? B.thickness : 0;  // a comes down onto b's top face, or up to its bottom
        if (std::abs(heightAbove(B, world(A, p0)) - face) > tolerance)
            continue;
        const Polygon edgeFace{local(B, world(A, p0)), local(B, world(A, p1)),
                               local(B, world(A, p1, A.thickness)), local(B, world(A, p0, A.thickness))};
        const Point2 q0 = edgeFace[0];
        const Point2 along{(edgeFace[1].x - q0.x) / length, (edgeFace[1].y - q0.y) / length};
        for (const Polygon& piece : geometry::intersect(edgeFace, B.outline)) {
            double t0 = length, t1 = 0;
            for (const Point2& q : piece) {
                const double t = dot(Point2{q.x - q0.x, q.y - q0.y}, along);
                t0 = std::min(t0, t);
                t1 = std::max(t1, t);
            }
            if (t1 - t0 > tolerance)
                contacts.push_back({a, b, p0, dir, out, t0, t1});
        }
    }
    return contacts;
}

/// Footprint in b's frame of the part of a's edge between t0 and t1 (the whole thickness of a).
Polygon footprintOnB(const std::vector<Board3>& boards, const EdgeContact& c, double t0, double t1)
{
    const Board3 &A = boards[c.a], &B = boards[c.b];
    return {local(B, world(A, c.at(t0))), local(B, world(A, c.at(t1))),
            local(B, world(A, c.at(t1), A.thickness)), local(B, world(A, c.at(t0), A.thickness))};
}

/// Finger joint (thesis 5.1): an odd number of fingers of width factor × thickness of a centred on the
/// contact; every second one is a tab on a, as deep as b is thick, and the same footprint is cut from b.
bool fingers(const std::vector<Board3>& boards, const EdgeContact& c, const ConnectorSettings& s,
             Connector& joint)
{
    const double width = s.fingerFactor * boards[c.a].thickness;
    int count = static_cast<int>(std::floor((c.t1 - c.t0) / width + 1e-9));
    if (count % 2 == 0)
        --count;
    if (count < 3)
        return false;
    const double margin = (c.t1 - c.t0 - count * width) / 2;
    const double depth = boards[c.b].thickness;
    joint.kind = Connector::Kind::Fingers;
    for (int k = 1; k < count; k += 2) {
        const double t0 = c.t0 + margin + k * width, t1 = t0 + width;
        joint.tabs.push_back({c.at(t0), c.at(t1), c.at(t1) + depth * c.out, c.at(t0) + depth * c.out});
        joint.slots.push_back(footprintOnB(boards, c, t0, t1));
    }
    return true;
}

/// Dowels: at least two, at most `dowelPitch` apart, 32 mm in from the joint's ends, in the middle of a's
/// edge; holes drilled half-way into b's face, and a mark on a where its edge is bored.
bool dowels(const std::vector<Board3>& boards, const EdgeContact& c, const ConnectorSettings& s,
            Connector& joint)
{
    const double length = c.t1 - c.t0, inset = std::min(32.0, length / 4);
    if (length < 4 * s.dowelDiameter)
        return false;
    const int count =
        std::max(2, 1 + static_cast<int>(std::ceil((length - 2 * inset) / s.dowelPitch - 1e-9)));
    const Board3 &A = boards[c.a], &B = boards[c.b];
    joint.kind = Connector::Kind::Dowels;
    for (int k = 0; k < count; ++k) {
        const double t = c.t0 + inset + k * (length - 2 * inset) / (count - 1);
        joint.drills.push_back(
            {local(B, world(A, c.at(t), A.thickness / 2)), s.dowelDiameter, B.thickness / 2});
        const Point2 inward = -1.0 * c.out;
        joint.marks.push_back(
            {c.at(t - 0.25), c.at(t + 0.25), c.at(t + 0.25) + 10 * inward, c.at(t - 0.25) + 10 * inward});
    }
    return true;
}

/// Heights of a board's outline corners above another board's bottom face.
std::pair<double, double> heightRange(const Board3& of, const Board3& above)
{
    double low = 1e300, high = -1e300;
    for (const Point2& p : of.outline.outer) {
        const double h = heightAbove(above, world(of, p));
        low = std::min(low, h);
        high = std::max(high, h);
    }
    return {low, high};
}

/// The band of board `of` that board `through` passes through, between `from` and `to` mm along the
/// crossing direction d measured from `ref`. d, the normal of `through` and the normal of `of` are
/// mutually perpendicular, so the band is a rectangle in of's frame.
Polygon band(const Board3& of, const Board3& through, const Vector3d& d, const Vector3d& ref, double from,
             double to)
{
    const Vector3d n = through.n();
    const Vector3d base = ref + (through.origin - ref).dot(n) * n;
    auto point = [&](double along, double up) { return local(of, base + along * d + up * n); };
    return {point(from, 0), point(to, 0), point(to, through.thickness), point(from, through.thickness)};
}

/// Cross slots (thesis 5.1 cross connectors): two boards passing through each other are each slotted
/// half-way, from opposite edges, so they slide together.
bool crossSlots(const std::vector<Board3>& boards, int a, int b, const ConnectorSettings& s, Connector& joint,
                std::vector<std::string>& notes)
{
    const Board3 &A = boards[a], &B = boards[b];
    if (std::abs(A.n().dot(B.n())) > 1e-6)
        return false;
    const auto [aLow, aHigh] = heightRange(A, B);
    const auto [bLow, bHigh] = heightRange(B, A);
    if (!(aLow < -s.tolerance && aHigh > B.thickness + s.tolerance && bLow < -s.tolerance &&
          bHigh > A.thickness + s.tolerance))
        return false;  // not through each other on both sides
    const Vector3d d = A.n().cross(B.n()).normalized();
    auto extent = [&](const Board3& board) {
        double low = 1e300, high = -1e300;
        for (const Point2& p : board.outline.outer) {
            const double t = (world(board, p) - B.origin).dot(d);
            low = std::min(low, t);
            high = std::max(high, t);
        }
        return std::pair{low, high};
    };
    const auto [a0, a1] = extent(A);
    const auto [b0, b1] = extent(B);
    const double s0 = std::max(a0, b0), s1 = std::min(a1, b1), middle = (s0 + s1) / 2, clear = 1.0;
    if (s1 - s0 <= s.tolerance)
        return false;
    joint.kind = Connector::Kind::CrossSlots;
    joint.a = a;
    joint.b = b;
    if (std::abs(s0 - a0) < s.tolerance && std::abs(s1 - b1) < s.tolerance) {
        joint.tabs.push_back(band(A, B, d, B.origin, s0 - clear, middle));
        joint.slots.push_back(band(B, A, d, B.origin, middle, s1 + clear));
    } else if (std::abs(s1 - a1) < s.tolerance && std::abs(s0 - b0) < s.tolerance) {
        joint.tabs.push_back(band(A, B, d, B.origin, middle, s1 + clear));
        joint.slots.push_back(band(B, A, d, B.origin, s0 - clear, middle));
    } else {
        notes.push_back("'" + A.id + "' and '" + B.id +
                        "' cross, but neither reaches past the other to slide on: "
                        "not slotted");
        return false;
    }
    return true;
}

}  // namespace

JoinedBoards joinBoards(const std::vector<Board3>& boards, const ConnectorSettings& settings)
{
    JoinedBoards joined;
    for (const Board3& board : boards)
        joined.outlines.push_back(board.outline);
    joined.drills.resize(boards.size());
    joined.marks.resize(boards.size());
    if (settings.style == JointStyle::None)
        return joined;

    const int count = static_cast<int>(boards.size());
    for (int a = 0; a < count; ++a)
        for (int b = 0; b < count; ++b) {
            if (a == b)
                continue;
            for (const EdgeContact& contact : edgeContacts(boards, a, b, settings.tolerance)) {
                Connector joint;
                joint.a = a;
                joint.b = b;
                const bool thick =
                    boards[a].thickness >= settings.dowelFrom && boards[b].thickness >= settings.dowelFrom;
                const bool made = settings.style == JointStyle::Auto && thick
                                      ? dowels(boards, contact, settings, joint)
                                      : fingers(boards, contact, settings, joint);
                if (made)
                    joined.connectors.push_back(joint);
                else
                    joined.notes.push_back("'" + boards[a].id + "' meets '" + boards[b].id + "' over only " +
                                           std::to_string(static_cast<int>(contact.t1 - contact.t0)) +
                                           " mm: too short for a joint, left butt-jointed");
            }
            Connector cross;
            if (a < b && crossSlots(boards, a, b, settings, cross, joined.notes))
                joined.connectors.push_back(cross);
        }

    // Tabs first, then slots, so a slot always wins where a tab of another joint would fill it.
    for (const Connector& c : joined.connectors)
        if (c.kind == Connector::Kind::Fingers)
            joined.outlines[c.a] = geometry::unite(joined.outlines[c.a], c.tabs);
    for (const Connector& c : joined.connectors) {
        try {
            if (c.kind == Connector::Kind::CrossSlots)
                joined.outlines[c.a] = geometry::subtract(joined.outlines[c.a], c.tabs);
            joined.outlines[c.b] = geometry::subtract(joined.outlines[c.b], c.slots);
        } catch (const std::runtime_error& e) {
            throw std::runtime_error("joining '" + boards[c.a].id + "' and '" + boards[c.b].id +
                                     "': " + e.what());
        }
        joined.drills[c.b].insert(joined.drills[c.b].end(), c.drills.begin(), c.drills.end());
        joined.marks[c.a].insert(joined.marks[c.a].end(), c.marks.begin(), c.marks.end());
    }
    return joined;
}

}  // namespace fabguide::material
