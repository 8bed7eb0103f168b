// When a time-limited layout search must stop: a time on the steady clock, or at once when the one who asked
// for the layout cancels it (the FreeCAD Layout's Cancel). Every stage of `pack` checks it where it checks
// the time, so a cancelled search ends within one step and returns the best layout it has.
#pragma once

#include <atomic>
#include <chrono>

namespace fabguide::material {

struct Deadline {
    using Clock = std::chrono::steady_clock;

    Clock::time_point at = Clock::time_point::max();
    const std::atomic<bool>* cancel = nullptr;  ///< set by another thread to stop the search

    Deadline() = default;
    explicit Deadline(Clock::time_point at, const std::atomic<bool>* cancel = nullptr)
        : at(at), cancel(cancel)
    {
    }

    bool cancelled() const { return cancel && cancel->load(std::memory_order_relaxed); }
    /// The search must stop now.
    bool passed() const { return cancelled() || Clock::now() >= at; }
    /// Whether a step that takes `step` still ends before the deadline.
    bool allows(Clock::duration step) const { return !cancelled() && Clock::now() + step < at; }
    /// Seconds left (0 when passed): what a search may still take.
    double secondsLeft() const;
    /// The same cancel, with the time brought forward to `t` if that is sooner.
    Deadline sooner(Clock::time_point t) const { return Deadline(t < at ? t : at, cancel); }
    /// The same cancel, with a 1/`parts` share of the time left (none left: none; no time limit: none).
    Deadline share(int parts) const;
    /// The same cancel, with the fraction `f` (0-1) of the time left.
    Deadline fraction(double f) const;
};

}  // namespace fabguide::material
