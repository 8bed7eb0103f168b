// Joint geometry (thesis 4.5.2): hinge pins, knuckles and yokes (slotted for sliding hinges), dovetail rails
// for slides no cavity guides, pins and links for double pivots.
#pragma once

#include "Printable/PrintInPlace.h"
#include "Printable/Solids.h"

#include <gp_Ax1.hxx>

#include <stdexcept>

namespace fabguide::printable {

/// A joint's geometry has no room at the place asked for (a half of the edge too short for the hinge's round
/// parts, round parts too thin to slim, its yokes beside another joint's, rails over too little material):
/// another place may have it. Checks tries the others; elsewhere it is said as any invalid_argument.
struct NoRoom : std::invalid_argument {
    using std::invalid_argument::invalid_argument;
};

/// A double pivot's link body: "<joint> link" (the joint's name alone when it already ends in "link").
std::string linkName(const Joint& joint);

/// The solid cuboid of another part that the hinge's edge lies on, along most of its length (the part the
/// yokes hang on), or -1. An edge standing off every other part (the sofa bunk's headrest, hinged 20 mm
/// behind the seat; a camera's flip screen, hinged on its outer edge) hangs on the nearest one within the
/// moving cuboid's thickness, else twice it; bridges join its yokes to it.
int cuboidAtEdge(const Model& m, const Joint& joint);

/// The model with the cuboids that joints' round parts stand on (a hinge's moving cuboid, a double pivot's
/// two) needing, along each axis, the least thickness that holds a pin at gap g, printed at `scale`
/// (Cuboid::least): the solve then moves a part drawn thick enough rather than thin it below that.
function::Model needingRoundParts(function::Model model, double g, double scale);

/// Hinge and sliding hinge (4.5.2): a pin along the edge and a knuckle around it in the middle third on the
/// moving part, two yokes at the ends on the part the edge lies on (slotted along a sliding hinge's travel),
/// each cleared of the other by the gap; at `place` 1, 2 or 3 along the edge's middle, first or second half
/// only; places 4-7 as 0-3 with round parts three quarters as thick. An error names the joint when no part is
/// near enough to hold the yokes, or a half is too short.
void addHinge(const Model& m, int j, const std::vector<Coordinates>& gapped, double g,
              std::vector<TopoDS_Shape>& shapes, Printable& out, int place = 0);

/// Where a slide's rails may run: a strip of the face of cuboid `base` that cuboid `mover` of the part rests
/// on, `across` [low, high] by `from` .. `to` along the slide axis, with the base's material under it; `dir`
/// the way from the base to the part along `normal`, `plane` the face.
struct RailPlace {
    int mover, base, normal, across;
    double dir, plane, from, to, low, high;
};

/// The places for slide j's rails: each contact of a cuboid of the part with one of
/// another part across the slide axis, less the cavities that open under it (a well), the largest strip
/// first.
std::vector<RailPlace> railPlaces(const Model& m, int j);

/// Slide (4.5.2) not guided by a cavity: mated rails. A dovetail tongue on the part it rests against, along
/// the slide axis where the two meet, and the matching groove, the gap all round, cut into the moving part
/// along its travel, so it can slide but not lift off; at railPlaces(m, j)[place]. An error names the joint
/// when the part rests on no other part, or on too little for rails.
void addRails(const Model& m, int j, const std::vector<Coordinates>& gapped, double g,
              std::vector<TopoDS_Shape>& shapes, int place = 0);

/// Double pivot (4.5.2): a headed pin at each pivot, standing out of the two coplanar faces, and a separate
/// rigid link between them, outside the faces, with a hole round each pin.
void addDoublePivot(const Model& m, int j, double g, std::vector<TopoDS_Shape>& shapes, Printable& out);

}  // namespace fabguide::printable
