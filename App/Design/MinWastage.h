// MINWASTAGE (thesis 5.4, Algorithm 7): rounds of ordering exploration and design improvement on several
// threads, and K = 3 diverse suggestions (5.3.3) with the path of designs that led to each.
#pragma once

#include "Design/ImproveDesign.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>

namespace fabguide::material {

/// The layout a design file keeps with it (its last, or the one a suggestion was found with), so that the
/// design reopens on the sheets it was laid out on: the order its units were laid in (a part kind per unit;
/// empty: none), and where, in millimetres, when the file says.
struct KeptLayout {
    std::vector<int> order;
    std::optional<Layout> layout;
};

struct MinWastageOptions {
    int rounds = 3;             ///< G
    int keep = 3;               ///< K designs carried from round to round
    int tasksPerRound = 8;      ///< orderings explored and improved per round (thesis: up to 8 threads)
    int improveIterations = 6;  ///< N of IMPROVEDESIGN
    int suggestions = 3;
    int threads = 2;         ///< 1 runs everything on the caller's thread
    std::uint64_t seed = 1;  ///< same seed, same suggestions (unless the time limit cuts the search)
    /// Seconds; the search ends with what it has found. Every stage also ends by its work (rounds, tasks,
    /// iterations): a limit well beyond that work makes the suggestions the seed's alone, at any load.
    double timeLimit = 8;
    bool guided = true;  ///< shrink the layout's locking chains; false: random sizes (baseline)
    const std::atomic<bool>* cancel = nullptr;
    /// The layout the design's file keeps: the user's design laid out by it besides the search.
    KeptLayout kept;
    /// Called on the caller's thread after each task: fraction done, usage of the best design so far.
    std::function<void(double, double)> progress;
};

/// A suggestion: the design reached, its layout, and the designs from the user's one to it, in order.
struct Suggestion {
    DesignLayout result;
    std::vector<DesignLayout> path;
    double usage() const { return 1 - result.wastage; }
};

struct Exploration {
    DesignLayout start;  ///< the user's design, laid out by the same docking and ordering search
    std::vector<Suggestion> suggestions;
    double seconds = 0;
    bool stopped = false;  ///< cancelled, or the time limit ended it
    int designsImproved = 0;
    int leastSheets = 0;  ///< sheets the design needs shrunk as far as it allows (0: not laid out in time)
    /// What the parts need with every side as short as any variation has it (DesignSpace::shortestSides): by
    /// their area alone (sheetsByArea), and by area and lines across the sheets (sheetsBound), bounds no
    /// layout of any variation beats, where leastSheets is one layout of one (0: no bound known).
    long leastSheetsByArea = 0;
    long leastSheetsBound = 0;
    int notReopened = 0;  ///< designs that waste less but a fresh layout put on boards that cost more
    double usageBefore() const { return 1 - start.wastage; }

    /// Why no variation saves a sheet, as far as it is known (never from one layout attempt alone): the bound
    /// over the variations needs as many sheets (Bound), or one layout of the least design took as many
    /// though that bound needs fewer (LaidOut: more time may save one). Unknown when the least design was
    /// not laid out or took fewer sheets, or no bound is known.
    enum class NoSheetSaved { Unknown, Bound, LaidOut };
    NoSheetSaved noSheetSaved() const;
};

/// The user's design laid out: the layout command's ordering search (MaterialSpace::searched, for at most
/// `seconds`, or 10 s when that leaves a part over), or the layout its file keeps (where it lies while the
/// parts fit there, else slid to their sizes), or docked in its order, whichever is best. Throws PackingError
/// naming a part left over when the design does not fit.
DesignLayout layOut(const DesignSpace& design, const MaterialSpace& material, std::uint64_t seed,
                    double seconds = 10, const std::atomic<bool>* cancel = nullptr,
                    const KeptLayout& kept = {});

/// Algorithm 7, on the maker's measure (DesignLayout::score: sheets first), after FEWERSHEETS (a fifth of the
/// time limit) whose designs the rounds improve on. Every suggestion keeps the design's constraints (it comes
/// from CHANGEPARTSIZES, or between the design and its least one); the suggestions are the best in the
/// maker's order, the least change on as many sheets, then the designs farthest (in part lengths) from those
/// chosen within 3 % of the bought area of its waste. None needs more sheets than the design as it is, none
/// is the design unchanged, each reopens; fewer when the search found no other distinct improving design.
Exploration minWastage(const DesignSpace& design, const MaterialSpace& material,
                       const MinWastageOptions& options);

}  // namespace fabguide::material
