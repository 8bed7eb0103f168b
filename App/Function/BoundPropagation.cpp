#include "Function/BoundPropagation.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fabguide::function {

namespace {

/// The least and greatest of a sum of terms, counting the infinite terms apart so that one term can be
/// taken out again: the range of the rest of a row.
struct SumRange {
    double finite[2] = {0, 0};  ///< sums of the finite least (0) and greatest (1) terms
    int infinite[2] = {0, 0};   ///< how many least terms are -inf, greatest terms +inf

    void add(double term, int end)
    {
        if (std::isinf(term))
            ++infinite[end];
        else
            finite[end] += term;
    }
    /// The sum's end without `term` (one of its terms at that end).
    double without(double term, int end) const
    {
        const double inf = (end == 0 ? -1 : 1) * std::numeric_limits<double>::infinity();
        if (std::isinf(term))
            return infinite[end] == 1 ? finite[end] : inf;
        return infinite[end] == 0 ? finite[end] - term : inf;
    }
};

/// a·x at the least (end 0) or greatest (end 1) x in `x`.
double termAt(double a, const Interval& x, int end)
{
    return a * ((a > 0) == (end == 0) ? x.lower : x.upper);
}

/// Narrows x to `to` where it moves an end by more than a hair; whether it did.
bool narrow(Interval& x, const Interval& to)
{
    const auto moves = [](double from, double next) {
        return std::isinf(from) ? !std::isinf(next)
                                : std::abs(next - from) > 1e-9 * std::max(1.0, std::abs(from));
    };
    bool moved = false;
    if (to.lower > x.lower && moves(x.lower, to.lower))
        x.lower = to.lower, moved = true;
    if (to.upper < x.upper && moves(x.upper, to.upper))
        x.upper = to.upper, moved = true;
    return moved;
}

/// One row carried to each of its variables; whether any interval narrowed.
bool propagate(const LinearConstraint& row, std::vector<Interval>& x)
{
    // Each term's ends as they are summed: a term is taken out of the sum as it went in, though its
    // variable narrows on the way.
    std::vector<Interval> terms;
    SumRange sum;
    for (const auto& [i, a] : row.terms) {
        terms.push_back({termAt(a, x[i], 0), termAt(a, x[i], 1)});
        sum.add(terms.back().lower, 0);
        sum.add(terms.back().upper, 1);
    }
    bool moved = false;
    for (size_t k = 0; k < terms.size(); ++k) {
        const auto [i, a] = row.terms[k];
        if (a == 0)
            continue;
        // a·x_i lies in [lower - rest's greatest, upper - rest's least].
        const double low = row.lower - sum.without(terms[k].upper, 1);
        const double high = row.upper - sum.without(terms[k].lower, 0);
        const Interval to = a > 0 ? Interval{low / a, high / a} : Interval{high / a, low / a};
        moved |= narrow(x[i], to);
    }
    return moved;
}

}  // namespace

Interval rangeOf(const LinearConstraint& row, const std::vector<Interval>& x)
{
    Interval range{0, 0};
    for (const auto& [i, a] : row.terms) {
        range.lower += termAt(a, x[i], 0);
        range.upper += termAt(a, x[i], 1);
    }
    return range;
}

std::vector<Interval> propagatedBounds(const std::vector<LinearConstraint>& rows, int n, int sweeps)
{
    std::vector<Interval> x(n);
    for (int sweep = 0; sweep < sweeps; ++sweep) {
        bool moved = false;
        for (const LinearConstraint& row : rows)
            moved |= propagate(row, x);
        if (!moved)
            break;
    }
    return x;
}

}  // namespace fabguide::function
