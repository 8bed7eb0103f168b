// Boards drawn equal (functional growth only): the posts, legs, rails and cleats a maker drew the
// same size are meant to stay so. Kept by the equal constraints of thesis 5.1 on their sizes, inferred here
// for the user to see and delete, as edge snapping keeps boards that touch touching.
#pragma once

#include "Design/Design.h"

#include <vector>

namespace fabguide::material {

/// Boards whose sizes along `axis` stay equal.
struct EqualSizes {
    int axis = 0;
    std::vector<int> boards;
};

/// The boards drawn alike (the same thickness axis, sizes within `tolerance` mm on every axis) in groups of
/// two or more, each once per in-plane axis; groups in the order of their first board.
std::vector<EqualSizes> drawnEqual(const Design& design, double tolerance);

}  // namespace fabguide::material
