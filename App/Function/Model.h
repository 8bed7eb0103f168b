// A works-like model (thesis 4.1): parts made of axis-aligned cuboids, joints and the configurations they
// take, the functional relationships the parts must satisfy, and the user's locked dimensions.
#pragma once

#include <algorithm>
#include <array>
#include <string>
#include <utility>
#include <vector>

namespace fabguide::function {

/// How far apart (mm) a rough drawing's faces may be and still be read as meant to meet (thesis 4.3): a
/// cover's faces correspond within it by default, a part's cuboids drawn this far apart are joined, parts
/// drawn this far into each other may be kept apart another way than the least overlap says.
constexpr double kInferenceDistance = 5;

/// The six coordinates of a cuboid (thesis 4.1.1): x left→right, y near→far, z bottom→top (FreeCAD's z up).
enum class Side { Left, Right, Near, Far, Bottom, Top };

/// "left", "right", "near", "far", "bottom" or "top".
inline const char* sideName(Side side)
{
    static const char* names[] = {"left", "right", "near", "far", "bottom", "top"};
    return names[static_cast<int>(side)];
}

/// The axis a side lies across: 0 for left and right (x), 1 near and far (y), 2 bottom and top (z).
inline int axisOf(Side side)
{
    return static_cast<int>(side) / 2;
}

/// A cuboid of a part, or a cavity cut out of one of its solid cuboids (thesis 4.1.1): a drawer's opening,
/// a compartment. A cavity's faces can be covered (an opening behind a door) and enclose parts.
struct Cuboid {
    std::string name;                     ///< unique in the model
    std::array<double, 6> coordinates{};  ///< indexed by Side
    int within = -1;                      ///< a cavity: the solid cuboid it is cut from; -1: solid
    std::array<double, 3> drawn{};        ///< sizes the user drew, before any solve (0: unknown)
    double least = 0;  ///< mm along each axis, what a joint's geometry on it needs: print in place sets it,
                       ///< so that the solve keeps it that thick where it is drawn so (Solve.cpp, collapsed)
    double at(Side side) const { return coordinates[static_cast<int>(side)]; }
    bool cavity() const { return within >= 0; }
    double thinnest() const  ///< its thinnest side
    {
        return std::min({at(Side::Right) - at(Side::Left), at(Side::Far) - at(Side::Near),
                         at(Side::Top) - at(Side::Bottom)});
    }
};

struct Part {
    std::string name;
    std::vector<int> cuboids;  ///< indices into Model::cuboids
};

/// A face of a cuboid, e.g. "lid.top".
struct Face {
    int cuboid = 0;
    Side side = Side::Top;
    bool operator==(const Face& other) const { return cuboid == other.cuboid && side == other.side; }
    bool operator<(const Face& other) const
    {
        return std::pair{cuboid, side} < std::pair{other.cuboid, other.side};
    }
};

/// Σ coefficient × quantity + constant, quantities being cuboid coordinates (a size is right − left).
struct Expression {
    std::vector<std::pair<double, Face>> terms;
    double constant = 0;
};

/// A joint that moves one part relative to its base (thesis 4.1.2). A hinge turns the part about the edge
/// where two faces of one of its cuboids meet (so the axis moves with the solved coordinates), by an angle in
/// degrees, right-handed about the +x, +y or +z direction of the edge. A slide moves it along an axis by an
/// offset in mm. A sliding hinge does both: the hinge's edge slides along the axis. A part is moved by at
/// most one joint; when its base moves, it is carried along (a chain of joints).
///
/// A double pivot (4.1.2, 4.3.6) links a pivot on a face of the part to a pivot on a coplanar face of its
/// base by a rigid link. Its configurations place the part by a turn about the faces' normal (through a pole,
/// any planar motion but a pure shift being such a turn); stage 2 of the solve moves the pivots along their
/// cuboids' longest in-plane axis so the link can take the part there.
///
/// A fixed joint holds the part rigidly to its base: it has no poses, the part is carried with its
/// base, and print-in-place fuses the two into one body (a toaster lever's knob on its lever).
struct Joint {
    std::string name;
    enum class Type { Hinge, Slide, SlidingHinge, DoublePivot, Fixed } type = Type::Hinge;
    int part = 0;
    int base = -1;      ///< the part it hangs on (-1: the ground)
    Face edgeA, edgeB;  ///< hinges: two faces of one cuboid of the part, on different axes
    int axis = 0;       ///< slides: 0 x, 1 y, 2 z
    /// Double pivots: the coplanar faces of the part and the base that carry the pivots, and each pivot's
    /// in-plane offsets from its cuboid's low corner (along the two axes after the normal, cyclically).
    Face pivotFace, basePivotFace;
    std::array<double, 2> pivot{}, basePivot{};
    bool turns() const;   ///< about an edge: hinges and sliding hinges (JointKind::turns)
    bool slides() const;  ///< along an axis: slides and sliding hinges (JointKind::slides)
};

/// Each joint kind, once: the name the formats, the bindings and the workbench give it, and how it moves. A
/// new kind is an entry here, its geometry (App/Printable/Joints.cpp) and its test.
struct JointKind {
    Joint::Type type;
    const char* name;
    bool turns, slides;
};

inline constexpr std::array<JointKind, 5> kJointKinds{
    {{Joint::Type::Hinge, "hinge", true, false},
     {Joint::Type::Slide, "slide", false, true},
     {Joint::Type::SlidingHinge, "sliding_hinge", true, true},
     {Joint::Type::DoublePivot, "double_pivot", false, false},
     {Joint::Type::Fixed, "fixed", false, false}}};

static_assert(
    [] {
        for (size_t k = 0; k < kJointKinds.size(); ++k)
            if (static_cast<size_t>(kJointKinds[k].type) != k)
                return false;
        return true;
    }(),
    "kJointKinds lists the kinds in Joint::Type's order");

inline const JointKind& kindOf(Joint::Type type)
{
    return kJointKinds[static_cast<size_t>(type)];  // in Type's order
}

inline bool Joint::turns() const
{
    return kindOf(type).turns;
}

inline bool Joint::slides() const
{
    return kindOf(type).slides;
}

/// How a configuration poses one joint: the angle (degrees) of a hinge, the offset (mm) of a slide, both for
/// a sliding hinge; a double pivot's turn (angle) about its pole.
struct JointPose {
    int joint = 0;
    double angle = 0, offset = 0;
    std::array<double, 3> pole{};
};

/// Along the motion from the base configuration (t = 0) to a pose (t = 1) turns come first, slides second:
/// the share of the pose's angle and of its offset reached at t (a pocket door swings open, then slides in).
inline double turnedAt(double t)
{
    return std::min(1.0, 2 * t);
}
inline double slidAt(double t)
{
    return std::max(0.0, 2 * t - 1);
}

/// A configuration (thesis 4.1.2): the joints' poses in which a relationship must hold. Joints not
/// mentioned stay as modelled (the base configuration).
struct Configuration {
    std::string name;
    std::vector<JointPose> poses;
    int along = -1;  ///< the solve's own: a pose on the way to configuration `along` (motionSampled)
    std::vector<int> poseOfJoint;  ///< joint → its index in poses, -1: not posed (filled by indexed)
};

/// Flush (thesis 4.2.4): two faces lie in one plane, in a configuration (-1: as modelled).
struct Flush {
    std::string name;
    Face a, b;
    int configuration = -1;
};

/// Geometric (thesis 4.3.5): left = right or left <= right, e.g. equal thickness, symmetry, a sum of widths.
struct Geometric {
    std::string name;
    enum class Relation { Equal, AtMost } relation = Relation::Equal;
    Expression left, right;
    int configuration = -1;  ///< where its quantities are measured (-1: as modelled)
};

/// What inference (4.3) had to stretch to link every part the user named in a relationship, one sentence
/// each ("right door: 7 mm from upper.near, beyond the 5 mm face distance; linked"); reported by the solve.
using InferenceNotes = std::vector<std::string>;

/// Support (thesis 4.2.3): each pair (a, b) of the corresponding-faces graph puts the bottom of cuboid b on
/// the top of cuboid a, overlapping in the supporting plane; parts that only support stand on one ground.
struct Support {
    std::string name;
    std::vector<int> supporting, supported;  ///< parts
    std::vector<std::pair<int, int>> pairs;  ///< (supporting cuboid, supported cuboid)
    int configuration = -1;
    InferenceNotes notes;
};

/// Fit inside (thesis 4.2.2, eq. 4.3–4.4): in the configuration, every solid cuboid of the inner parts lies
/// inside the enclosing part's box (or one of its cavities), the inner parts do not overlap (each `apart`
/// pair: a's high side at most b's low side along `axis`), and `just` pairs of faces coincide ("just fits"
/// along an axis).
struct FitInside {
    std::string name;
    std::vector<int> inner;    ///< parts
    int enclosing = 0;         ///< part
    int cavity = -1;           ///< a cavity of the enclosing part to fit in, else its box
    std::vector<int> portion;  ///< partial fit (4.2.2): the inner cuboids that must fit; empty: all
    struct Apart {
        int a = 0, b = 0, axis = 0;  ///< cuboids
    };
    std::vector<Apart> apart;
    std::vector<std::pair<Face, Face>> just;  ///< (inner face, enclosing face)
    int configuration = -1;
};

/// Cover (thesis 4.2.1, eq. 4.1): in the configuration, each connected component of the corresponding-faces
/// graph lies in one plane, its covering faces packed without gaps or overlaps (and likewise its covered
/// faces), the covering faces' box containing the covered faces' box; "just" makes the two boxes equal.
/// Faces are sides of the cuboids' boxes in the configuration.
struct Cover {
    std::string name;
    std::vector<int> covering, covered;        ///< parts
    std::vector<std::pair<Face, Face>> pairs;  ///< the graph M: (covering face, covered face)
    bool just = false;
    int configuration = -1;
    InferenceNotes notes;
    double distance =
        kInferenceDistance;  ///< mm: faces this far apart correspond, seams this far apart are one
};

/// A coordinate the user fixed (an edit): it keeps its value while the rest adapts.
struct Lock {
    Face face;
};

struct Model {
    std::vector<Part> parts;
    std::vector<Cuboid> cuboids;
    std::vector<Joint> joints;
    std::vector<Configuration> configurations;
    std::vector<Flush> flush;
    std::vector<Geometric> geometric;
    std::vector<Support> support;
    std::vector<FitInside> fitInside;
    std::vector<Cover> cover;
    std::vector<Lock> locks;
    std::vector<std::string> relationshipOrder;  ///< names as read: the writer keeps the file's order
    double minimumSize = 1;  ///< mm, every cuboid at least this big along each axis; also the least overlap
                             ///< of supporting faces
    double minimumWall = 1;  ///< mm, the least wall around a cavity on a side that is not an opening
    /// Derived for speed by indexed(): the part of each cuboid and the first joint of each part (-1: none).
    /// Left empty (a model built by hand), partOf and jointMoving search instead.
    std::vector<int> partOfCuboid, jointOfPart;
};

/// The model with partOfCuboid, jointOfPart and each configuration's poseOfJoint filled in (the reader
/// returns it so).
Model indexed(Model model);

/// "lid.top": how a face is named in files and messages.
std::string faceName(const Model& model, const Face& face);

/// A length in messages, to three significant digits (or `digits`): "7", "110", "0.5".
std::string millimetres(double mm, int digits = 3);

/// Whether side `side` of a cavity is an opening (4.1.1), which stays on its solid's face: it lies there as
/// modelled, within half the minimum wall (a rough drawing's mouth a hair short of the face), a cover names
/// it as a covered face (a door covers it), or a part that fits inside the cavity goes out through it (posed,
/// where its fit is not measured, half beyond it: a shelf pulled out of an oven). Other sides keep the
/// minimum wall.
bool isOpening(const Model& model, int cavity, int side);

}  // namespace fabguide::function
