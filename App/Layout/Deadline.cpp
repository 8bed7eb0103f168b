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
    if (at == Clock::time_point::max())
        return *this;
    const Clock::time_point now = Clock::now();
    return Deadline(at <= now ? at : now + (at - now) / std::max(1, parts), cancel);
}

}  // namespace fabguide::material
