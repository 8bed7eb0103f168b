// Connectors where the boards of a 3-D design meet (thesis 5.1 cutting plans): finger joints, cross
// slots and dowels, turned into the 2-D outlines (tabs, slots, notches) and drill holes that are cut.
#pragma once

#include "Geometry/Polygon.h"
#include "Layout/Drill.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string>
#include <vector>

namespace fabguide::material {

/// A board of the 3-D design: outline point (x, y) sits at origin + x·u + y·v; the slab spans
/// [0, thickness] along n = u × v (thesis 5.2: a part box of thickness τ).
struct Board3 {
    std::string id;
    geometry::Outline outline;
    Eigen::Vector3d origin{0, 0, 0}, u{1, 0, 0}, v{0, 1, 0};
    double thickness = 0;
    Eigen::Vector3d n() const { return u.cross(v); }
};

enum class JointStyle {
    None,     ///< boards are cut as modelled
    Fingers,  ///< tabs and slots everywhere
    Auto,     ///< dowels where both boards are at least `dowelFrom` thick, fingers elsewhere
};

struct ConnectorSettings {
    JointStyle style = JointStyle::Auto;
    int fingerFactor = 2;      ///< finger width = fingerFactor × thickness of the tabbed board
    double dowelFrom = 18;     ///< mm: boards this thick or thicker are doweled under Auto
    double dowelDiameter = 8;  ///< mm
    double dowelPitch = 128;   ///< mm: dowels at most this far apart along a joint (at least two per joint)
    double tolerance = 0.01;   ///< mm: how close faces must be to touch
};

/// How two boards are joined: `tabs` are added to board `a`, `slots` cut from board `b` (cross slots:
/// `slots` in b and `tabs` holds a's slots), pairwise the same size and place in 3-D.
struct Connector {
    enum class Kind { Fingers, Dowels, CrossSlots } kind = Kind::Fingers;
    int a = 0, b = 0;
    std::vector<geometry::Polygon> tabs;   ///< in a's frame
    std::vector<geometry::Polygon> slots;  ///< in b's frame
    std::vector<Drill> drills;             ///< dowels: holes in b's face
    std::vector<geometry::Polygon> marks;  ///< dowels: where to bore a's edge, engraved on a
};

/// The boards as they are cut: outlines with tabs and slots, holes to drill, marks to engrave.
struct JoinedBoards {
    std::vector<geometry::Outline> outlines;
    std::vector<std::vector<Drill>> drills;
    std::vector<std::vector<geometry::Polygon>> marks;
    std::vector<Connector> connectors;
    std::vector<std::string> notes;  ///< contacts left unjoined, and why
};

/// Finds every contact between boards, an edge of one lying on a face of another or two boards
/// crossing, and joins it in the chosen style. Throws std::runtime_error naming the boards when a
/// joint would cut a board into pieces.
JoinedBoards joinBoards(const std::vector<Board3>& boards, const ConnectorSettings& settings);

}  // namespace fabguide::material
