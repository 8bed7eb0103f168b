#include "Design/DrawnEqual.h"

#include <algorithm>

namespace fabguide::material {

namespace {

bool alike(const DesignBoard& a, const DesignBoard& b, double tolerance)
{
    return a.normal == b.normal && ((a.size - b.size).cwiseAbs().array() <= tolerance).all();
}

}  // namespace

std::vector<EqualSizes> drawnEqual(const Design& design, double tolerance)
{
    std::vector<std::vector<int>> groups;
    for (int b = 0; b < static_cast<int>(design.boards.size()); ++b) {
        auto group = std::find_if(groups.begin(), groups.end(), [&](const std::vector<int>& g) {
            return alike(design.boards[g.front()], design.boards[b], tolerance);
        });
        if (group == groups.end())
            groups.push_back({b});
        else
            group->push_back(b);
    }
    std::vector<EqualSizes> equal;
    for (const std::vector<int>& group : groups)
        if (group.size() > 1)
            for (int axis : design.boards[group.front()].inPlane())
                equal.push_back({axis, group});
    return equal;
}

}  // namespace fabguide::material
