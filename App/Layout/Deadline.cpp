#include "Layout/Deadline.h"

#include <algorithm>

namespace fabguide::material {

double Deadline::secondsLeft() const
{
    if (cancelled())
        return 0;
    return std::max(0.0, std::chrono::duration<double>(at - Clock::now()).count());
}

Deadline Deadline::share(int parts) const
{
    return fraction(1.0 / std::max(1, parts));
}

Deadline Deadline::fraction(double f) const
{
    if (at == Clock::time_point::max())
        return *this;
    const Clock::time_point now = Clock::now();
    return Deadline(at <= now ? at : now + std::chrono::duration_cast<Clock::duration>((at - now) * f),
                    cancel);
}

}  // namespace fabguide::material
