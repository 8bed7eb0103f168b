// Print-in-place geometry (thesis 4.5): the solved cuboid model turned into separate solids that can be
// printed assembled and move as designed: gaps around touching faces (4.5.3), cavities swept by inner parts
// along their motion (4.5.1), and joint geometry: hinge pins and yokes, slotted yokes for sliding hinges,
// pins and a link for double pivots (4.5.2).
#pragma once

#include "Function/Model.h"

#include <TopoDS_Shape.hxx>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace fabguide::printable {

/// What the printer needs: the clearance between parts that must not fuse (FDM 0.4 mm, resin 0.2 mm).
struct Printer {
    double gap = 0.4;
    /// What OpenCASCADE may take on one part (or joint) at each step before an error.
    double partSeconds = 60;
};

/// One printed body: a part (with the parts that stand still with it, `part` the first), or a double pivot's
/// link (part -1, joint set).
struct Body {
    std::string name;
    int part = -1, joint = -1;
    TopoDS_Shape shape;
};

struct Printable {
    std::vector<Body> bodies;
    std::vector<TopoDS_Shape> sweeps;  ///< the volumes the fit-inside cavities were cut with (for display)
    std::vector<std::string> notes;    ///< joints left without geometry, and why
};

/// The model solved (both stages) for printing at `scale` (a 1:5 prototype: 0.2), not yet scaled: the parts
/// that joints' round parts stand on kept as thick as those need at `gap` where drawn so (needingRoundParts);
/// std::runtime_error naming the relationships that cannot hold together when it does not solve.
function::Model solvedToPrint(const function::Model& model, double scale, double gap);

/// Which of its candidate places each joint's geometry takes, by joint (0, the first, where not given).
using Places = std::vector<int>;

/// How many places joint j's geometry can take: a hinge's round parts along its whole edge, its middle, first
/// or second half, then the same three quarters as thick; a slide's rails one per railPlaces; a double
/// pivot's one; 0 without geometry of its own (a slide a cavity guides, a fixed joint).
int placesOf(const function::Model& m, int j);

/// The printable bodies of a solved model. Throws std::invalid_argument naming a joint whose parts are too
/// thin for its geometry at this gap.
Printable makePrintable(const function::Model& solved, const Printer& printer, const Places& places = {});

/// The names of the bodies makePrintable makes, in its order: each rigid body's (rigidBodies: its parts'
/// names joined by " + "), then each double pivot's link.
std::vector<std::string> bodyNames(const function::Model& model);

/// Width, depth and height (x, y, z) in mm: of a print's bodies, or of a printer's build volume.
using Size = std::array<double, 3>;

/// The bounding box of the bodies.
Size sizeOf(const Printable& printable);

/// A model scaled to print on a printer, and its bodies (as modelled, where its motions are defined).
struct Fitted {
    double scale = 1;
    function::Model solved;  ///< as solved for the print (solvedToPrint), before scaling
    function::Model model;   ///< scaled
    Printable printable;
    bool turned = false;  ///< printed turned a quarter about z: the model's x along the bed's depth
};

/// The solved model at the largest scale, at most 1, whose bodies fit the build volume (the gap stays in mm),
/// 0.01 mm to spare, upright as modelled and turned a quarter about z if that lets it print larger;
/// std::runtime_error when none is found.
Fitted fitted(const function::Model& solved, const Size& volume, const Printer& printer);

/// The bodies as they go on the printer's bed: turned a quarter about z when the fit says so (`turned`).
Printable onTheBed(Printable printable, bool turned);

/// The model solved (solvedToPrint), then scaled by `scale`, or fitted to the build volume `fit` when given
/// (solved again at the scale its cuboids fit at, for what joints need there), and its bodies; noted, each
/// part the print's solve kept thicker than a plain solve would.
Fitted printed(const function::Model& model, const Printer& printer, double scale,
               const std::optional<Size>& fit = std::nullopt);

}  // namespace fabguide::printable
