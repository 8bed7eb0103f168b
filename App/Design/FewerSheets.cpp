#include "Design/FewerSheets.h"

#include "Layout/Deadline.h"

#include <algorithm>
#include <cmath>

namespace fabguide::material {

namespace {

using Clock = std::chrono::steady_clock;

}  // namespace

SavedSheets fewerSheets(const DesignSpace& design, const MaterialSpace& material, const DesignLayout& start,
                        std::uint64_t seed, Clock::time_point deadline, const std::atomic<bool>* cancel)
{
    const Deadline stop(deadline, cancel);
    constexpr int halvings = 6;  // the shrink found to 1/64 of its full length
    // The least design, the one most likely to save a sheet, gets half the time; the bisections share the
    // rest.
    const auto share = [&](int layoutsLeft) { return stop.secondsLeft() / std::max(1, layoutsLeft); };
    const auto laidOut = [&](const Eigen::VectorXd& X, double seconds) {
        Eigen::VectorXd sizes = design.sizes(X);
        GridLayout layout = material.packed(sizes, seed, seconds, cancel);
        return designLayout(material, X, std::move(sizes), std::move(layout));
    };
    const std::optional<Eigen::VectorXd> shrunk = design.least(start.X, deadline);
    if (!shrunk)
        return {};
    const Eigen::VectorXd& least = *shrunk;
    SavedSheets saved{laidOut(least, share(2)), {}};
    const DesignLayout& smallest = *saved.least;
    std::vector<DesignLayout>& found = saved.designs;
    if (!(smallest.score() < start.score()) || smallest.figures.sheets >= start.figures.sheets)
        return saved;
    // Fewer sheets need at least the shrink one sheet more needed: each bisection starts from the last.
    double lo = 0;
    for (int sheets = start.figures.sheets - 1; sheets >= smallest.figures.sheets; --sheets) {
        DesignLayout fits = smallest;
        double hi = 1;
        for (int k = 0; k < halvings && !stop.passed(); ++k) {
            const double t = (lo + hi) / 2;
            const auto X = design.between(start.X, least, t);
            if (!X) {
                lo = t;
                continue;
            }
            DesignLayout at = laidOut(*X, share(halvings - k));
            if (!std::isinf(at.score()) && at.figures.sheets <= sheets) {
                hi = t;
                fits = std::move(at);
            } else {
                lo = t;
            }
        }
        if (found.empty() || (found.back().X - fits.X).norm() > 1e-6)
            found.push_back(std::move(fits));
        lo = hi;
    }
    return saved;
}

}  // namespace fabguide::material
