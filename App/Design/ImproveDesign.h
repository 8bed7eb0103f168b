// Changing the design to waste less, for a fixed docking order (thesis 5.4.2): GROWPARTS (Algorithm 10),
// SHRINKPARTS with locking chains (Algorithms 11-12) and IMPROVEDESIGN (Algorithm 8).
#pragma once

#include "Design/MaterialSpace.h"

#include <atomic>
#include <chrono>
#include <limits>
#include <random>
#include <vector>

namespace fabguide::material {

/// A design X, its part sizes s(X), its layout, the layout's wastage W (5.2.3) and what a maker reads off it.
struct DesignLayout {
    Eigen::VectorXd X;
    Eigen::VectorXd sizes;
    GridLayout layout;
    double wastage = 1;
    MaterialSpace::Figures figures;
    /// What the search minimises: the boards' cost first (in sheets of the cheapest; the sheets
    /// bought when every board costs the same), then the thesis' wastage, which favours compact layouts;
    /// infinite when a part is left over.
    double score() const
    {
        return wastage >= 1 ? std::numeric_limits<double>::infinity() : figures.cost / figures.unit + wastage;
    }
};

/// X laid out as `layout`: its sizes, wastage and figures.
DesignLayout designLayout(const MaterialSpace& material, const Eigen::VectorXd& X, Eigen::VectorXd sizes,
                          GridLayout layout);

/// What the design search works with: D, the material space, the docking order O, its random source, the
/// designs that improved on the best so far (the path a suggestion's slider follows) and a stop flag and a
/// deadline.
struct Explorer {
    const DesignSpace& design;
    const MaterialSpace& material;
    std::vector<int> order;
    std::mt19937_64 random;
    const std::atomic<bool>* stop = nullptr;
    std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
    std::vector<DesignLayout> path;
    bool guided =
        true;  ///< false: shrink random part sizes instead of the locking chains (Fig. 5.20 baseline)

    bool stopped() const { return until().passed(); }
    /// The deadline and the stop together, for the steps that check them inside (a correction).
    Deadline until() const { return Deadline(deadline, stop); }
    /// DOCKING(D(X), O).
    DesignLayout docked(const Eigen::VectorXd& X) const;
    /// SLIDE(L, D(X)): `from`'s layout updated to the part sizes of X.
    DesignLayout slid(const DesignLayout& from, const Eigen::VectorXd& X) const;
    /// Records a new best design on the path.
    void improved(const DesignLayout& best) { path.push_back(best); }
};

/// GROWPARTS (Algorithm 10): each part size in random order (at most 24 per pass, a random subset of a large
/// design's) grows one grid cell at a time (sliding the layout, docking again when sliding loses) for as long
/// as the score drops; a growth that ends below the current score is kept. Repeats while some growth was
/// kept. `best` follows the least score seen.
void growParts(Explorer& explorer, DesignLayout& best, DesignLayout& current);

/// SELECTPARTSIZESTOSHRINK (Algorithm 12): the locking chains of the layout (units touching from the right
/// (top) border of its bounding rectangle to the left (bottom) one, as part sizes along that axis), broken by
/// drawing sizes by their occurrence in the chains, then by low coupling (how many sizes a shrink of it
/// changes). Sizes the design cannot shrink are never drawn.
std::vector<int> selectPartSizesToShrink(Explorer& explorer, const DesignLayout& best);

/// IMPROVEDESIGN (Algorithm 8): `iterations` rounds of grow, then shrink the locking chains by one cell
/// (SHRINKPARTS, Algorithm 11) and slide; returns the least-wastage design found. Unguided, it shrinks one
/// to three part sizes drawn at random instead.
DesignLayout improveDesign(Explorer& explorer, const DesignLayout& start, int iterations);

}  // namespace fabguide::material
