// Checking printable bodies (thesis 4.5): every solid valid, and the parts apart by at least the gap
// as printed and all along every configuration's motion.
#pragma once

#include "Printable/PrintInPlace.h"

#include <array>
#include <string>
#include <vector>

namespace fabguide::printable {

struct Check {
    std::vector<std::string> invalid;  ///< bodies BRepCheck_Analyzer finds invalid
    std::vector<std::string> loose;    ///< "lever: 2 pieces": bodies that print in pieces, not one
    double clearance = 1e300;          ///< the least distance between two bodies, as printed and moving
    std::string where;                 ///< "lid and body in 'open' at 50% near (120.0, 80.0, 50.0) mm"
    int first = -1, second = -1;       ///< the nearest two bodies, -1 when none came near
    int configuration = -1;            ///< and where: in this configuration (-1: as printed)
    double t = 0;                      ///< this far along its motion
    std::array<double, 3> point{};     ///< near this point (on the first)
};

/// Validity, each body in one piece, and the least clearance between any two bodies as printed and at
/// `samples` poses along the way to each configuration (0 when two bodies intersect). Pairs farther apart
/// than `enough` are not measured.
Check check(const function::Model& model, const Printable& printable, double enough, int samples = 32);

/// A print that passes the check, where joint geometry can make it pass: while the nearest
/// two bodies come within the gap near joints' geometry (jointsInTheWay), the nearest joint not yet moved has
/// its other places made and checked, the nearest kept; when none clears, the check's `where` names the
/// joints tried and what they meet.
struct Checked {
    Printable printable;
    Check check;
};
Checked placedByCheck(const function::Model& model, Printable made, const Printer& printer, int samples = 32);

/// The joints whose geometry lies where the check found two bodies too near, within its reach, nearest
/// first: a hinge's round parts round its axis, a slide's rails, a double pivot's link.
std::vector<int> jointsInTheWay(const function::Model& model, const Printable& printable, const Check& check);

}  // namespace fabguide::printable
