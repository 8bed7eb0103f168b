// Solving a works-like model (thesis 4.4): its relationships as linear constraints on the cuboid
// coordinates, solved for the least change.
#pragma once

#include "Function/LeastChange.h"
#include "Function/Model.h"

#include <array>
#include <string>
#include <vector>

namespace fabguide::function {

/// Variable index of a cuboid coordinate: six per cuboid, in Side order.
inline int variable(const Face& face)
{
    return 6 * face.cuboid + static_cast<int>(face.side);
}

/// How a part's solid cuboids hold together: each pair that touches or overlaps as modelled, and where the
/// part is drawn in pieces, the nearest two cuboids of two pieces, joined when at most kInferenceDistance
/// apart (a tray drawn a hair off its front: a note says so); farther apart, an error naming the part.
struct Pieces {
    struct Glued {
        int a = 0, b = 0;
        double apart = 0;  ///< how far apart they were drawn (0: touching or overlapping)
    };
    std::vector<Glued> glued;
    std::vector<std::string> notes;
    std::string error;
};
Pieces piecesOf(const Model& model, const Part& part);

/// Every constraint of the model, each named after its relationship ("lock: lid.top" for locks; minimum
/// sizes unnamed). Throws std::invalid_argument naming a Flush whose faces are not parallel.
std::vector<LinearConstraint> constraints(const Model& model);

/// What a name in a conflict stands for: a relationship of the model (by its kind), a joint (a double pivot
/// that cannot be placed, a fixed joint's hold), a lock, a part kept in one piece, a cavity's wall, two parts
/// kept apart, or a part drawn inside another.
enum class ConflictKind {
    Cover,
    FitInside,
    Support,
    Flush,
    Geometric,
    Joint,
    Lock,
    OnePiece,
    Wall,
    NoOverlap,
    DrawnInside
};

/// Each kind as the formats name it: a relationship's type (the reader's, in a model) or a conflict's kind
/// (in a report). The one list of the relationships' kinds, which the reader, the writer and the bindings
/// read.
struct ConflictKindName {
    ConflictKind kind;
    const char* name;
    bool relationship;  ///< a relationship of the model (thesis 4.2)
};

inline constexpr std::array<ConflictKindName, 11> kConflictKinds{
    {{ConflictKind::Cover, "cover", true},
     {ConflictKind::FitInside, "fit_inside", true},
     {ConflictKind::Support, "support", true},
     {ConflictKind::Flush, "flush", true},
     {ConflictKind::Geometric, "geometric", true},
     {ConflictKind::Joint, "joint", false},
     {ConflictKind::Lock, "lock", false},
     {ConflictKind::OnePiece, "one_piece", false},
     {ConflictKind::Wall, "wall", false},
     {ConflictKind::NoOverlap, "no_overlap", false},
     {ConflictKind::DrawnInside, "drawn_inside", false}}};

static_assert(
    [] {
        for (size_t k = 0; k < kConflictKinds.size(); ++k)
            if (static_cast<size_t>(kConflictKinds[k].kind) != k)
                return false;
        return true;
    }(),
    "kConflictKinds lists the kinds in ConflictKind's order");

inline const char* nameOf(ConflictKind kind)
{
    return kConflictKinds[static_cast<size_t>(kind)].name;  // in ConflictKind's order
}

struct Conflict {
    ConflictKind kind = ConflictKind::Cover;
    std::string name;  ///< as SolveResult::conflict has it
    std::string
        subject;  ///< the relationship or joint, the locked face, the part, the cavity, "a, b", "a in b"
};

struct SolveResult {
    bool solved = false;
    Model model;                        ///< the solved model (unchanged when not solved)
    std::vector<std::string> conflict;  ///< relationships (or double pivots) that cannot hold together
    double violation = 0;
    std::vector<std::string> notes;   ///< why, where the names alone do not say
    std::vector<std::string> parts;   ///< parts a conflict blames beyond its relationships' (overlaps, walls)
    std::vector<Conflict> conflicts;  ///< `conflict` typed, in its order: callers read kinds, never wording
};

/// The model at `factor` times its size (a works-like prototype printed at 1:5): coordinates, slide offsets,
/// poles and pivots scale; angles do not.
Model scaled(Model model, double factor);

/// The model nearest to `model` that satisfies all its relationships, locks and minimum sizes.
SolveResult solve(const Model& model);

}  // namespace fabguide::function
