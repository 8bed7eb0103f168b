// A works-like model (thesis 4.1): parts made of axis-aligned cuboids, the functional relationships they
// must satisfy, and the user's locked dimensions. Joints and configurations come with the next relationships.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace fabguide::function {

/// The six coordinates of a cuboid (thesis 4.1.1): x left→right, y near→far, z bottom→top (FreeCAD's z up).
enum class Side { Left, Right, Near, Far, Bottom, Top };

struct Cuboid {
    std::string name;                     ///< unique in the model
    std::array<double, 6> coordinates{};  ///< indexed by Side
    double at(Side side) const { return coordinates[static_cast<int>(side)]; }
};

struct Part {
    std::string name;
    std::vector<int> cuboids;  ///< indices into Model::cuboids
};

/// A face of a cuboid, e.g. "lid.top".
struct Face {
    int cuboid = 0;
    Side side = Side::Top;
};

/// Σ coefficient × quantity + constant, quantities being cuboid coordinates (a size is right − left).
struct Expression {
    std::vector<std::pair<double, Face>> terms;
    double constant = 0;
};

/// Flush (thesis 4.2.4): two faces lie in one plane.
struct Flush {
    std::string name;
    Face a, b;
};

/// Geometric (thesis 4.3.5): left = right or left <= right, e.g. equal thickness, symmetry, a sum of widths.
struct Geometric {
    std::string name;
    enum class Relation { Equal, AtMost } relation = Relation::Equal;
    Expression left, right;
};

/// A coordinate the user fixed (an edit): it keeps its value while the rest adapts.
struct Lock {
    Face face;
};

struct Model {
    std::vector<Part> parts;
    std::vector<Cuboid> cuboids;
    std::vector<Flush> flush;
    std::vector<Geometric> geometric;
    std::vector<Lock> locks;
    double minimumSize = 1;  ///< mm, every cuboid at least this big along each axis
};

}  // namespace fabguide::function
