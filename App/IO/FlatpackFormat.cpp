#include "IO/FlatpackFormat.h"

#include "Design/DrawnEqual.h"
#include "IO/Json.h"
#include "IO/PackFormat.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>

namespace fabguide::io {

namespace {

using material::Design;
using material::DesignConstraint;
using material::Linear;

std::string at(const std::string& array, size_t i)
{
    return array + "[" + std::to_string(i) + "]";
}

int boardIndex(const Design& design, const std::string& id, const std::string& path)
{
    for (size_t b = 0; b < design.boards.size(); ++b)
        if (design.boards[b].id == id)
            return static_cast<int>(b);
    throw FormatError(path, "no part \"" + id + "\"");
}

int axisOf(const std::string& name, const std::string& path)
{
    if (name == "x" || name == "y" || name == "z")
        return name[0] - 'x';
    throw FormatError(path, "axis must be x, y or z, got \"" + name + "\"");
}

/// "part.size.x", "part.centre.y", "part.min.z" or "part.max.x" as a linear expression.
Linear reference(const Design& design, const nlohmann::json& json, const std::string& path)
{
    if (!json.is_string())
        throw FormatError(path, "must be a reference like \"top.size.x\", got " + json.dump());
    const std::string text = json.get<std::string>();
    const size_t last = text.rfind('.'),
                 middle = last == std::string::npos ? last : text.rfind('.', last - 1);
    if (middle == std::string::npos || middle == 0)
        throw FormatError(path, "\"" + text + "\" is not <part>.<size|centre|min|max>.<x|y|z>");
    const int board = boardIndex(design, text.substr(0, middle), path);
    const std::string what = text.substr(middle + 1, last - middle - 1);
    const int axis = axisOf(text.substr(last + 1), path);
    if (what == "size")
        return material::sizeOf(board, axis);
    if (what == "centre" || what == "center")
        return material::centreOf(board, axis);
    if (what == "min")
        return material::lowerFace(board, axis);
    if (what == "max")
        return material::upperFace(board, axis);
    throw FormatError(path, "\"" + what + "\" in \"" + text + "\" must be size, centre, min or max");
}

std::vector<Linear> references(const Design& design, const Fields& c, const std::string& key, size_t least)
{
    const nlohmann::json& list = c.array(key);
    if (list.size() < least)
        throw FormatError(c.pathOf(key), "needs at least " + std::to_string(least) + " references");
    const size_t distinct = 12 * design.boards.size();  // size, centre, min and max on three axes
    if (list.size() > distinct)
        throw FormatError(c.pathOf(key), std::to_string(list.size()) + " references, more than the " +
                                             std::to_string(distinct) + " different ones a design of " +
                                             std::to_string(design.boards.size()) + " boards has");
    std::vector<Linear> refs;
    for (size_t k = 0; k < list.size(); ++k)
        refs.push_back(reference(design, list[k], at(c.pathOf(key), k)));
    return refs;
}

std::vector<int> partsOf(const Design& design, const Fields& c, size_t least)
{
    const nlohmann::json& list = c.array("parts");
    if (list.size() < least)
        throw FormatError(c.pathOf("parts"), "needs at least " + std::to_string(least) + " parts");
    std::vector<int> parts;
    for (size_t k = 0; k < list.size(); ++k) {
        const std::string path = at(c.pathOf("parts"), k);
        if (!list[k].is_string())
            throw FormatError(path, "must be a part id");
        parts.push_back(boardIndex(design, list[k].get<std::string>(), path));
    }
    return parts;
}

/// The first few of `list` joined, "a = b = c = … (40 in all)": a name every equality of the constraint
/// carries (100,000 references joined in full, once per equality, took all the memory).
std::string firstFew(const nlohmann::json& list, const std::string& separator)
{
    constexpr size_t kNamed = 4;
    std::string text;
    for (size_t k = 0; k < list.size() && k < kNamed; ++k)
        text += (k ? separator : "") + (list[k].is_string() ? list[k].get<std::string>() : list[k].dump());
    if (list.size() > kNamed)
        text += separator + "… (" + std::to_string(list.size()) + " in all)";
    return text;
}

Linear sum(const std::vector<Linear>& terms)
{
    Linear total;
    for (const Linear& t : terms)
        total = total + t;
    return total;
}

/// Edge snapping (5.1) of boards a and b added to the design; false when they do not touch (nothing added).
bool addSnapping(Design& design, int a, int b)
{
    const material::Snapping snap = material::snapping(design, a, b);
    design.equalities.insert(design.equalities.end(), snap.equalities.begin(), snap.equalities.end());
    design.bounds.insert(design.bounds.end(), snap.bounds.begin(), snap.bounds.end());
    return !snap.equalities.empty();
}

/// One entry of "constraints" being read: the design it adds to, its fields, the design's values now, and
/// the entry's normal form, where each default it takes is written.
struct ConstraintReader {
    Design& design;
    const nlohmann::json& json;
    const Fields& c;
    nlohmann::json& normal;
    std::string kind;
    Eigen::VectorXd X;

    std::string named(const std::string& fallback) const { return c.text("name", kind + " " + fallback); }
    void equal(const std::string& name, const Linear& e) { design.equalities.push_back({name, e}); }
    Linear ref() const { return reference(design, c.value("ref"), c.pathOf("ref")); }
    std::string refText() const { return json["ref"].get<std::string>(); }

    void equalKind()
    {
        const std::vector<Linear> refs = references(design, c, "refs", 2);
        const std::string name = named(firstFew(c.array("refs"), " = "));
        for (size_t k = 1; k < refs.size(); ++k)
            equal(name, refs[k] - refs[0]);
    }
    void sumKind()
    {
        const Linear lhs = sum(references(design, c, "lhs", 1)), rhs = sum(references(design, c, "rhs", 1));
        const double offset = c.number("offset", 0.0);
        normal["offset"] = offset;
        equal(named(firstFew(c.array("lhs"), " + ") + " = " + firstFew(c.array("rhs"), " + ") +
                    (offset != 0 ? " + " + show(offset) : "")),
              lhs - rhs - material::constant(offset));
    }
    void fixedKind()
    {
        const Linear r = ref();
        const double value = c.number("value", r.value(X));
        normal["value"] = value;
        equal(named(refText() + " = " + show(value)), r - material::constant(value));
    }
    void symmetricKind()
    {
        const std::vector<Linear> refs = references(design, c, "refs", 2);
        if (refs.size() != 2)
            throw FormatError(c.pathOf("refs"), "symmetric takes two references");
        const double midway = (refs[0] + refs[1]).value(X) / 2;
        if (!c.has("about"))
            normal["about"] = midway;
        const Linear about = !c.has("about") ? material::constant(midway)
                             : json["about"].is_number()
                                 ? material::constant(json["about"].get<double>())
                                 : reference(design, json["about"], c.pathOf("about"));
        equal(named(firstFew(c.array("refs"), ", ")), refs[0] + refs[1] - about * 2.0);
    }
    void groundKind()
    {
        const std::vector<int> parts = partsOf(design, c, 1);
        double lowest = std::numeric_limits<double>::infinity();
        for (size_t b = 0; b < design.boards.size(); ++b)
            lowest = std::min(lowest, material::lowerFace(static_cast<int>(b), 2).value(X));
        const double level = c.number("level", lowest);
        normal["level"] = level;
        for (int b : parts)
            equal(named(design.boards[b].id + " on z = " + show(level)),
                  material::lowerFace(b, 2) - material::constant(level));
    }
    void coplanarKind()
    {
        const std::vector<int> parts = partsOf(design, c, 2);
        const int normal = design.boards[parts[0]].normal;
        for (int b : parts)
            if (design.boards[b].normal != normal)
                throw FormatError(c.pathOf("parts"),
                                  design.boards[b].id + " is not parallel to " + design.boards[parts[0]].id);
        for (size_t k = 1; k < parts.size(); ++k)
            equal(named(firstFew(c.array("parts"), ", ")),
                  material::centreOf(parts[k], normal) - material::centreOf(parts[0], normal));
    }
    void snapKind(const std::string& path)
    {
        const std::vector<int> parts = partsOf(design, c, 2);
        if (parts.size() != 2)
            throw FormatError(c.pathOf("parts"), "snap takes two parts");
        if (!addSnapping(design, parts[0], parts[1]))
            throw FormatError(
                path, design.boards[parts[0]].id + " and " + design.boards[parts[1]].id + " do not touch");
    }
    void rangeKind(const std::string& path)
    {
        const Linear r = ref();
        const double value = r.value(X), fraction = c.number("fraction", 0.0, 0.0);
        const double low = c.number("min", fraction > 0 ? value * (1 - fraction) : -HUGE_VAL);
        const double high = c.number("max", fraction > 0 ? value * (1 + fraction) : HUGE_VAL);
        if (!c.has("min") && !c.has("max") && !(fraction > 0))
            throw FormatError(path, "a range needs min, max or fraction");
        normal.erase("fraction");  // its ends, taken from the values now
        for (const auto& [key, end] : {std::pair{"min", low}, std::pair{"max", high}})
            if (std::isfinite(end))
                normal[key] = end;
        // A named range names both its ends: "table height (min)", "table height (max)".
        const auto end = [&](const char* side, const std::string& fallback) {
            return c.has("name") ? c.text("name") + " (" + side + ")" : fallback;
        };
        if (std::isfinite(low))
            design.bounds.push_back(
                {end("min", refText() + " >= " + show(low)), material::constant(low) - r});
        if (std::isfinite(high))
            design.bounds.push_back(
                {end("max", refText() + " <= " + show(high)), r - material::constant(high)});
    }
};

/// One entry of "constraints": equalities into design.equalities, ranges into design.bounds; the defaults it
/// takes written into `normal`.
void readConstraint(Design& design, const nlohmann::json& json, const std::string& path,
                    nlohmann::json& normal)
{
    const Fields c(json, path);
    ConstraintReader r{design, json, c, normal, c.text("kind"), design.variables()};
    if (r.kind == "equal")
        r.equalKind();
    else if (r.kind == "sum")
        r.sumKind();
    else if (r.kind == "fixed")
        r.fixedKind();
    else if (r.kind == "symmetric")
        r.symmetricKind();
    else if (r.kind == "ground")
        r.groundKind();
    else if (r.kind == "coplanar")
        r.coplanarKind();
    else if (r.kind == "snap")
        r.snapKind(path);
    else if (r.kind == "range")
        r.rangeKind(path);
    else
        throw FormatError(c.pathOf("kind"),
                          "unknown constraint \"" + r.kind +
                              "\" (equal, sum, fixed, symmetric, ground, coplanar, snap, range)");
    c.noOthers();
}

/// A grain as the formats name it: -1 for "free", 0-2 for "x", "y", "z"; nullopt for anything else.
std::optional<int> grainAxisNamed(const std::string& grain)
{
    if (grain == "free")
        return -1;
    if (grain.size() == 1 && grain[0] >= 'x' && grain[0] <= 'z')
        return grain[0] - 'x';
    return std::nullopt;
}

/// Migration 1 to 2: a box by its lower corner and size ("position", "size") becomes one by its corners
/// ("min", "max"), as every box of the formats is written; the fields are named as the file has them.
void boxesByCorners(nlohmann::json& document)
{
    for (const char* list : {"parts", "inner_volumes"}) {
        if (!document.contains(list) || !document[list].is_array())
            continue;  // the reader says what is wrong
        nlohmann::json& boxes = document[list];
        for (size_t i = 0; i < boxes.size(); ++i) {
            const Fields box(boxes[i], at(list, i));
            const Eigen::Vector3d low = box.vector3("position"), size = box.vector3("size");
            if (size.minCoeff() <= 0)
                throw FormatError(box.pathOf("size"), "every side must be longer than 0");
            const Eigen::Vector3d high = low + size;
            boxes[i].erase("position");
            boxes[i].erase("size");
            boxes[i]["min"] = {low.x(), low.y(), low.z()};
            boxes[i]["max"] = {high.x(), high.y(), high.z()};
        }
    }
}

/// The version a document without "version" was written in, as its boxes say: version 1 wrote "position".
int versionWritten(const nlohmann::json& document)
{
    const nlohmann::json& parts = document.value("parts", nlohmann::json::array());
    const bool first =
        parts.is_array() && !parts.empty() && parts[0].is_object() && parts[0].contains("position");
    return first ? 1 : kFlatpackFormatVersion;
}

material::DesignBoard readPart(const nlohmann::json& json, const std::string& path,
                               const std::vector<double>& thicknesses)
{
    const Fields part(json, path);
    material::DesignBoard board;
    board.id = part.text("id");
    placeBoard(board, part);
    board.quantity = part.integer("quantity", 1);
    board.followsGrain = part.flag("follow_grain", false);
    if (board.quantity < 1)
        throw FormatError(part.pathOf("quantity"), "must be at least 1");
    board.size.minCoeff(&board.normal);
    if (part.has("grain")) {
        const std::string grain = part.text("grain");
        const std::optional<int> axis = grainAxisNamed(grain);
        const char* axes = "xyz";
        const std::string face = std::string(1, axes[board.normal == 0 ? 1 : 0]) + " or " +
                                 axes[board.normal == 2 ? 1 : 2];  // the axes in the board's plane
        if (axis == board.normal)
            throw FormatError(part.pathOf("grain"), "\"" + grain + "\" runs across the board, through its " +
                                                        show(board.size[board.normal]) +
                                                        " mm thickness; choose an axis of its face (" + face +
                                                        ") or \"free\"");
        if (!axis)
            throw FormatError(part.pathOf("grain"), "must be \"free\" or an axis of the board's face (" +
                                                        face + "), got \"" + grain + "\"");
        board.followsGrain = *axis >= 0;
        board.grainAxis = *axis;
    }
    if (std::none_of(thicknesses.begin(), thicknesses.end(),
                     [&](double t) { return material::ofThickness(board.size[board.normal], t); })) {
        std::string all;
        for (size_t k = 0; k < thicknesses.size(); ++k)
            if (std::find(thicknesses.begin(), thicknesses.begin() + k, thicknesses[k]) ==
                thicknesses.begin() + k)
                all += (all.empty() ? "" : ", ") + show(thicknesses[k]);
        throw FormatError(path, "its thinnest side " + show(board.size[board.normal]) +
                                    " must be the thickness of a master board (" + all + ")");
    }
    part.noOthers();
    return board;
}

/// Outer volume: every part within [min, max]; bounds named after the part side that would leave it.
void readOuterVolume(Design& design, const nlohmann::json& json)
{
    const Fields outer(json, "outer_volume");
    const Eigen::Vector3d low = outer.vector3("min"), high = outer.vector3("max");
    outer.noOthers();
    const char* axes = "xyz";
    for (int b = 0; b < static_cast<int>(design.boards.size()); ++b)
        for (int axis = 0; axis < 3; ++axis) {
            const std::string side = design.boards[b].id + "." + std::string("min.") + axes[axis];
            design.bounds.push_back({"outer volume (" + side + ")",
                                     material::constant(low[axis]) - material::lowerFace(b, axis)});
            design.bounds.push_back({"outer volume (" + design.boards[b].id + ".max." + axes[axis] + ")",
                                     material::upperFace(b, axis) - material::constant(high[axis])});
        }
}

/// The boards of "parts", every one as thick as a master board, each id once.
void readParts(const Fields& root, const std::vector<double>& thicknesses, Design& design)
{
    const nlohmann::json& parts = root.array("parts");
    long units = 0;
    for (size_t i = 0; i < parts.size(); ++i) {
        if (static_cast<long>(i) >= kMostDesignBoards)
            throw FormatError(
                "parts", "more than " + std::to_string(kMostDesignBoards) +
                             " boards; FabGuide explores designs of up to that (lay a larger job out with "
                             "`fabguide pack`)");
        design.boards.push_back(readPart(parts[i], at("parts", i), thicknesses));
        if ((units += design.boards.back().quantity) > kMostDesignBoards)
            throw FormatError(
                at("parts", i) + ".quantity",
                "more than " + std::to_string(kMostDesignBoards) +
                    " boards to cut in all; FabGuide explores designs of up to that (lay a larger job "
                    "out with `fabguide pack`)");
        for (size_t j = 0; j < i; ++j)
            if (design.boards[j].id == design.boards[i].id)
                throw FormatError(at("parts", i) + ".id", "\"" + design.boards[i].id + "\" is used twice");
    }
    if (design.boards.empty())
        throw FormatError("parts", "at least one part is needed");
}

/// What "settings" asks of every board: no in-plane side below min_length (or its present length if shorter),
/// and, with `snap`, every two boards that touch stay touching.
void addSettingConstraints(const Fields& settings, bool snap, Design& design)
{
    const Eigen::VectorXd X = design.variables();
    const char* axes = "xyz";
    for (int b = 0; b < static_cast<int>(design.boards.size()); ++b)
        for (int axis : design.boards[b].inPlane()) {
            const double thickness = design.boards[b].size[design.boards[b].normal];
            const double shortest = settings.number("min_length", 2 * thickness, 0.0);
            const double least = std::min(shortest, X[material::sizeVariable(b, axis)]);
            design.bounds.push_back({design.boards[b].id + ".size." + axes[axis] + " >= " + show(least),
                                     material::constant(least) - material::sizeOf(b, axis)});
        }
    if (!snap)
        return;
    for (int a = 0; a < static_cast<int>(design.boards.size()); ++a)
        for (int b = a + 1; b < static_cast<int>(design.boards.size()); ++b)
            addSnapping(design, a, b);
}

/// An inner volume stands on its board: along the board's plane the board stays under the volume's whole
/// footprint, or overhangs it no more than drawn (pantry shelves went from 542 to 60 mm deep under
/// 300 mm jar spaces).
void addStandsOn(Design& design, const material::InnerVolume& v)
{
    const Eigen::VectorXd X = design.variables();
    const std::string name = v.name + " (stands on " + design.boards[v.on].id + ")";
    for (int axis : design.boards[v.on].inPlane())
        for (const material::Linear& over : {material::lowerFace(v.on, axis) - v.lower(axis),
                                             v.upper(axis) - material::upperFace(v.on, axis)})
            design.bounds.push_back({name, over - material::constant(std::max(0.0, over.value(X)))});
}

/// The inner volumes into `design`, each one's name written into `normal`, their normal form.
void readInnerVolumes(const Fields& root, Design& design, nlohmann::json& normal)
{
    const nlohmann::json& inner = root.array("inner_volumes", true);
    for (size_t i = 0; i < inner.size(); ++i) {
        const Fields volume(inner[i], at("inner_volumes", i));
        material::InnerVolume v;
        v.name = volume.text("name", "inner volume " + std::to_string(i + 1));
        normal[i]["name"] = v.name;
        v.on = boardIndex(design, volume.text("on"), volume.pathOf("on"));
        const BoxSides box = volume.box();  // max beyond min: a space of no volume keeps no part out
        const Eigen::Vector3d position(box[0], box[2], box[4]);
        v.size = Eigen::Vector3d(box[1], box[3], box[5]) - position;
        const material::DesignBoard& on = design.boards[v.on];
        for (int axis = 0; axis < 3; ++axis) {  // its nearer face, the lower one on a tie
            const double low = on.centre[axis] - on.size[axis] / 2,
                         high = on.centre[axis] + on.size[axis] / 2;
            v.anchor[axis] = position[axis] - low <= high - position[axis] - v.size[axis] ? -1 : 1;
            v.offset[axis] = position[axis] - (v.anchor[axis] < 0 ? low : high);
        }
        volume.noOthers();
        design.innerVolumes.push_back(v);
        addStandsOn(design, v);
    }
}

/// A layout's order (a part index per unit) against the parts' quantities: none more times than its quantity,
/// and every one as many times unless the order is empty; `list` is its path in the file.
void checkQuantities(const Design& design, const std::vector<int>& order, const std::string& list)
{
    std::vector<int> left;
    for (const material::DesignBoard& b : design.boards)
        left.push_back(b.quantity);
    for (size_t i = 0; i < order.size(); ++i)
        if (left[order[i]]-- == 0)
            throw FormatError(at(list, i),
                              "part \"" + design.boards[order[i]].id + "\" more times than its quantity");
    if (!order.empty() && std::any_of(left.begin(), left.end(), [](int n) { return n > 0; }))
        throw FormatError(list, "must name every part as many times as its quantity");
}

/// "layout" (the boards and placements of a layout JSON: where each unit was laid, in the order laid) or the
/// older "layout_order" (a part id per unit, in the order laid): the layout the file keeps.
material::KeptLayout readKeptLayout(const nlohmann::json& document, const Fields& root, const Design& design)
{
    material::KeptLayout kept;
    if (root.has("layout")) {
        if (root.has("layout_order"))
            throw FormatError("layout_order",
                              "give layout or layout_order, not both: a layout keeps its order");
        material::PackProblem named;  // the boards by id, as the placements name them
        for (const material::DesignBoard& b : design.boards) {
            const auto [u, v] = b.inPlane();
            named.parts.push_back(material::rectangularPart(b.id, b.size[u], b.size[v], b.quantity));
        }
        kept.layout = readLayout(document["layout"], named, PartNames::Ids, "layout");
        for (const material::Placement& p : kept.layout->placements)
            kept.order.push_back(p.part);
        checkQuantities(design, kept.order, "layout.placements");
        return kept;
    }
    const nlohmann::json& ids = root.array("layout_order", true);
    for (size_t i = 0; i < ids.size(); ++i) {
        if (!ids[i].is_string())
            throw FormatError(at("layout_order", i), "must be a part id");
        kept.order.push_back(boardIndex(design, ids[i].get<std::string>(), at("layout_order", i)));
    }
    checkQuantities(design, kept.order, "layout_order");
    return kept;
}

/// How far from its constraints a design read may be, in mm. 0.1 µm: the search holds its constraints to 1e-6
/// mm and writes them with as many digits, so a reader as strict as the search could refuse a suggestion it
/// wrote.
constexpr double kSatisfied = 1e-4;

/// A design must satisfy its own constraints as given; the first five broken ones are named.
void checkSatisfied(const Design& design)
{
    const Eigen::VectorXd X = design.variables();
    std::vector<std::string> broken = material::unsatisfied(design, X, kSatisfied), names = broken;
    for (const material::Ineffective& one : material::ineffective(design, X)) {
        broken.push_back(one.said());
        if (std::find(names.begin(), names.end(), one.name) == names.end())
            names.push_back(one.name);
    }
    if (broken.empty())
        return;
    std::string listed;
    for (size_t k = 0; k < broken.size() && k < 5; ++k)
        listed += (k ? "; " : "") + broken[k];
    throw ConstraintError(
        "the design does not satisfy its own constraints: " + listed +
            (broken.size() > 5 ? "; and " + std::to_string(broken.size() - 5) + " more" : ""),
        std::move(names));
}

/// "" (Unknown), "bound" or "laid_out": summary.json's `no_sheet_saved`.
const char* nameOf(material::Exploration::NoSheetSaved why)
{
    switch (why) {
        case material::Exploration::NoSheetSaved::Bound:
            return "bound";
        case material::Exploration::NoSheetSaved::LaidOut:
            return "laid_out";
        default:
            return "";
    }
}

/// `normal` (the document read) with its master boards, settings and parts as `read` has them: every
/// default written, "follow_grain" as the grain axis it means (the board's first axis in its plane).
void normalBoards(nlohmann::json& normal, const FlatpackDesign& read, bool snap)
{
    normal["boards"] = nlohmann::json::array();
    for (const material::MasterBoard& b : read.boards)
        normal["boards"].push_back(boardToJson(b));
    const nlohmann::json given = normal.value("settings", nlohmann::json::object());
    normal["settings"] = settingsToJson(read.settings);
    normal["settings"]["snap"] = snap;
    normal["settings"]["max_growth"] = read.maxGrowth;
    if (given.contains("min_length"))  // else twice each board's thickness
        normal["settings"]["min_length"] = given["min_length"];
    for (size_t i = 0; i < read.design.boards.size(); ++i) {
        const material::DesignBoard& b = read.design.boards[i];
        nlohmann::json& part = normal["parts"][i];
        const int grain = b.grainAxis >= 0 ? b.grainAxis : b.followsGrain ? b.inPlane()[0] : -1;
        part.erase("follow_grain");
        part["quantity"] = b.quantity;
        part["grain"] = grain < 0 ? "free" : std::string(1, "xyz"[grain]);
    }
}

}  // namespace

void placeBoard(material::DesignBoard& board, const Fields& part)
{
    const BoxSides box = part.box();
    board.size = {box[1] - box[0], box[3] - box[2], box[5] - box[4]};
    board.centre = Eigen::Vector3d(box[0], box[2], box[4]) + board.size / 2;
}

nlohmann::json currentFlatpack(nlohmann::json document)
{
    using Migration = void (*)(nlohmann::json&);
    static const std::array<Migration, kFlatpackFormatVersion - 1> kMigrations = {boxesByCorners};
    if (!document.is_object())
        return document;
    const nlohmann::json given = document.value("version", nlohmann::json(versionWritten(document)));
    if (!given.is_number_integer())
        return document;  // the reader says what is wrong
    for (int version = given.get<int>(); version >= 1 && version < kFlatpackFormatVersion; ++version) {
        kMigrations[version - 1](document);
        document["version"] = version + 1;
    }
    return document;
}

FlatpackDesign readFlatpack(const nlohmann::json& given, Satisfied satisfied)
{
    checkNumbers(given);
    const nlohmann::json document = currentFlatpack(given);
    checkNumbers(document);  // a corner a migration added up, beyond what this version reads
    const Fields root(document, "");
    root.header("fabguide.flatpack", kFlatpackFormatVersion);
    FlatpackDesign result;
    result.boards = readMasterBoards(document);
    result.settings = readSettings(document);
    checkGrid(result.settings, result.boards);
    if (result.settings.cuts == material::Cuts::Guillotine)
        throw FormatError(
            "settings.cuts",
            "the zero-waste design search lays its parts out for free cuts (CNC, laser); lay a "
            "chosen design out for a saw with `fabguide pack --cuts guillotine` or a FreeCAD Layout");
    std::vector<double> thicknesses;
    for (size_t i = 0; i < result.boards.size(); ++i) {
        if (!(result.boards[i].thickness > 0))
            throw FormatError(at("boards", i) + ".thickness", "must be greater than 0");
        thicknesses.push_back(result.boards[i].thickness);
    }
    Design& design = result.design;
    readParts(root, thicknesses, design);
    const nlohmann::json noSettings = nlohmann::json::object();
    const Fields settings(document.contains("settings") ? document["settings"] : noSettings, "settings");
    result.maxGrowth = settings.number("max_growth", 1.5, 1.0);
    const bool snap = settings.flag("snap", true);
    addSettingConstraints(settings, snap, design);
    nlohmann::json& normal = result.document = document;
    normalBoards(normal, result, snap);
    const nlohmann::json& constraints = root.array("constraints", true);
    normal["constraints"] = constraints;
    for (size_t i = 0; i < constraints.size(); ++i)
        readConstraint(design, constraints[i], at("constraints", i), normal["constraints"][i]);
    normal["inner_volumes"] = root.array("inner_volumes", true);
    readInnerVolumes(root, design, normal["inner_volumes"]);
    if (root.has("outer_volume"))
        readOuterVolume(design, document["outer_volume"]);
    const std::vector<material::DesignConstraint> apart = material::keptApart(design);
    design.bounds.insert(design.bounds.end(), apart.begin(), apart.end());
    // The title names the design in FreeCAD; a suggestion's usage and path are written for people.
    normal["title"] = root.text("title", "");
    result.kept = readKeptLayout(document, root, design);
    root.noOthers({"settings", "boards", "usage", "path"});
    if (satisfied == Satisfied::Required)
        checkSatisfied(design);
    return result;
}

ParametricParts readParametricParts(const nlohmann::json& parts)
{
    if (!parts.is_array())
        throw FormatError("parts", "must be a list of parts");
    ParametricParts read;
    for (size_t i = 0; i < parts.size(); ++i) {
        const Fields part(parts[i], at("parts", i));
        read.kinds.push_back({part.text("id"), part.integer("quantity", 1)});
        if (read.kinds.back().quantity < 1)
            throw FormatError(part.pathOf("quantity"), "must be at least 1");
        const std::string grain = part.text("grain", "free");
        const std::optional<int> axis = grainAxisNamed(grain);
        if (!axis)
            throw FormatError(part.pathOf("grain"),
                              "must be \"free\", \"x\", \"y\" or \"z\", got \"" + grain + "\"");
        read.grainAxes.push_back(*axis);
        part.noOthers();
    }
    return read;
}

material::Design forSuggestions(const FlatpackDesign& f)
{
    material::Design design = f.design;
    const Eigen::VectorXd X = design.variables();
    const char* axes = "xyz";
    for (int b = 0; b < static_cast<int>(design.boards.size()); ++b)
        for (int axis : design.boards[b].inPlane()) {
            const double most = f.maxGrowth * X[material::sizeVariable(b, axis)];
            design.bounds.push_back({design.boards[b].id + ".size." + axes[axis] + " <= " + show(most) +
                                         " (max_growth " + show(f.maxGrowth) + ")",
                                     material::sizeOf(b, axis) - material::constant(most)});
        }
    return design;
}

nlohmann::json drawnEqualConstraints(const nlohmann::json& document)
{
    const Design design = readFlatpack(document, Satisfied::NotRequired).design;
    std::vector<std::set<std::string>> held;  // the refs of the equal constraints the document has already
    for (const nlohmann::json& c : document.value("constraints", nlohmann::json::array()))
        if (c.value("kind", "") == "equal")
            held.push_back(c["refs"].get<std::set<std::string>>());
    nlohmann::json constraints = nlohmann::json::array();
    // Drawn alike as the reader judges a design satisfied: an equal constraint on them holds as they are.
    for (const material::EqualSizes& equal : material::drawnEqual(design, kSatisfied)) {
        const std::string size = std::string("size.") + "xyz"[equal.axis];
        nlohmann::json refs = nlohmann::json::array(), ids = nlohmann::json::array();
        for (int b : equal.boards) {
            refs.push_back(design.boards[b].id + "." + size);
            ids.push_back(design.boards[b].id);
        }
        const auto wanted = refs.get<std::set<std::string>>();
        if (std::none_of(held.begin(), held.end(), [&](const std::set<std::string>& h) {
                return std::includes(h.begin(), h.end(), wanted.begin(), wanted.end());
            }))
            constraints.push_back({{"kind", "equal"},
                                   {"name", "drawn equal: " + size + " of " + firstFew(ids, ", ")},
                                   {"refs", refs}});
    }
    return constraints;
}

nlohmann::json partsAt(const Design& design, const Eigen::VectorXd& X)
{
    nlohmann::json parts = nlohmann::json::array();
    for (const material::DesignBoard& b : design.boardsAt(X)) {
        const Eigen::Vector3d low = b.centre - b.size / 2, high = low + b.size;
        parts.push_back(
            {{"id", b.id}, {"min", {low.x(), low.y(), low.z()}}, {"max", {high.x(), high.y(), high.z()}}});
    }
    return parts;
}

nlohmann::json withParts(nlohmann::json document, const Design& design, const Eigen::VectorXd& X)
{
    document = currentFlatpack(std::move(document));
    const nlohmann::json parts = partsAt(design, X);
    for (size_t i = 0; i < parts.size(); ++i)
        for (const char* corner : {"min", "max"})
            document["parts"][i][corner] = parts[i][corner];
    // Inner volumes move with their boards (5.1: the shelf space travels with the shelf).
    for (size_t i = 0; i < design.innerVolumes.size(); ++i) {
        const material::InnerVolume& v = design.innerVolumes[i];
        const Eigen::Vector3d low(v.lower(0).value(X), v.lower(1).value(X), v.lower(2).value(X)),
            high = low + v.size;
        document["inner_volumes"][i]["min"] = {low.x(), low.y(), low.z()};
        document["inner_volumes"][i]["max"] = {high.x(), high.y(), high.z()};
    }
    return document;
}

nlohmann::json designLayoutJson(const material::MaterialSpace& material, const material::DesignLayout& d)
{
    const material::PackProblem problem = material.problem(d.sizes);
    nlohmann::json out = measures(d);
    out["layout"] = layoutToJson(material.inMillimetres(d.layout, d.sizes), problem, PartNames::Ids);
    out["problem"] = problemToJson(problem);
    return out;
}

nlohmann::json explorationFigures(const material::Exploration& e)
{
    return {{"usage_before", e.usageBefore()},
            {"seconds", e.seconds},
            {"stopped", e.stopped},
            {"least_sheets", e.leastSheets},
            {"least_sheets_by_area", e.leastSheetsByArea},
            {"least_sheets_bound", e.leastSheetsBound},
            {"no_sheet_saved", nameOf(e.noSheetSaved())},
            {"not_reopened", e.notReopened}};
}

nlohmann::json measures(const material::DesignLayout& d)
{
    return {{"usage", 1 - d.wastage},
            {"sheets", d.figures.sheets},
            {"cost", d.figures.cost},
            {"waste_m2", d.figures.waste},
            {"largest_offcut", d.figures.offcut}};
}

nlohmann::json suggestionDocument(const nlohmann::json& document, const Design& design,
                                  const material::MaterialSpace& material,
                                  const material::Suggestion& suggestion, size_t steps)
{
    nlohmann::json out = withParts(document, design, suggestion.result.X);
    out["usage"] = suggestion.usage();
    nlohmann::json path = nlohmann::json::array();
    const size_t n = suggestion.path.size();
    for (size_t k = 0; k < std::min(n, steps); ++k) {
        const material::DesignLayout& step = suggestion.path[steps >= n ? k : k * (n - 1) / (steps - 1)];
        path.push_back({{"usage", 1 - step.wastage}, {"parts", partsAt(design, step.X)}});
    }
    out["path"] = path;
    // Where its layout laid each board, so that it reopens on those sheets (its metrics are the summary's).
    const nlohmann::json layout =
        layoutToJson(material.inMillimetres(suggestion.result.layout, suggestion.result.sizes),
                     material.problem(suggestion.result.sizes), PartNames::Ids);
    out["layout"] = {{"boards", layout["boards"]}, {"placements", layout["placements"]}};
    return out;
}

}  // namespace fabguide::io
