#include "IO/PackFormat.h"

#include "IO/Json.h"
#include "Layout/CutSheet.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace fabguide::io {

namespace {

std::string at(const std::string& array, size_t i)
{
    return array + "[" + std::to_string(i) + "]";
}

std::vector<int> readOrientations(const Fields& part)
{
    const nlohmann::json& list = part.array("orientations", true);
    if (list.empty())
        return {0, 90, 180, 270};
    std::vector<int> orientations;
    for (size_t k = 0; k < list.size(); ++k) {
        if (!list[k].is_number_integer() || list[k].get<int>() % 90 != 0)
            throw FormatError(at(part.pathOf("orientations"), k),
                              "must be 0, 90, 180 or 270, got " + list[k].dump());
        orientations.push_back(((list[k].get<int>() % 360) + 360) % 360);
    }
    return orientations;
}

/// A point [x, y].
geometry::Point2 readPoint(const nlohmann::json& point, const std::string& path)
{
    if (!point.is_array() || point.size() != 2 || !point[0].is_number() || !point[1].is_number())
        throw FormatError(path, "must be a point [x, y], got " + point.dump());
    return {point[0].get<double>(), point[1].get<double>()};
}

/// A polygon as [[x, y], ...]: at least 3 points, not flat; returned counter-clockwise if `outer`.
geometry::Polygon readPolygon(const nlohmann::json& json, const std::string& path, bool outer)
{
    if (!json.is_array() || json.size() < 3)
        throw FormatError(path, "must be a list of at least 3 [x, y] points");
    geometry::Polygon polygon;
    for (size_t k = 0; k < json.size(); ++k) {
        const geometry::Point2 q = readPoint(json[k], at(path, k));
        if (polygon.empty() || q.x != polygon.back().x || q.y != polygon.back().y)  // a repeated point: once
            polygon.push_back(q);
    }
    while (polygon.size() > 1 && polygon.front().x == polygon.back().x &&
           polygon.front().y == polygon.back().y)
        polygon.pop_back();  // closed by repeating the first point
    if (polygon.size() < 3)
        throw FormatError(path, "must be a list of at least 3 different [x, y] points");
    if (const auto [i, j] = geometry::selfCrossing(polygon); i >= 0)
        throw FormatError(path, "crosses itself (its edges from point " + std::to_string(i) +
                                    " and from point " + std::to_string(j) +
                                    " meet); draw it as one closed loop that does not touch itself");
    const double area = geometry::signedArea(polygon);
    if (std::abs(area) < 1e-9)
        throw FormatError(path, "encloses no area");
    if ((area > 0) != outer)
        std::reverse(polygon.begin(), polygon.end());
    return polygon;
}

geometry::Outline readOutline(const Fields& part)
{
    geometry::Outline outline{readPolygon(part.array("outline"), part.pathOf("outline"), true), {}};
    const nlohmann::json& holes = part.array("holes", true);
    const geometry::Outline outer{outline.outer, {}};
    for (size_t k = 0; k < holes.size(); ++k) {
        const std::string path = at(part.pathOf("holes"), k);
        outline.holes.push_back(readPolygon(holes[k], path, false));
        double inside = 0;  // of the hole, within the outline
        for (const geometry::Polygon& piece : geometry::intersect(outline.holes.back(), outer))
            inside += std::abs(geometry::signedArea(piece));
        const double area = std::abs(geometry::signedArea(outline.holes.back()));
        if (inside < area * (1 - 1e-4))  // Clipper rounds to 0.1 µm
            throw FormatError(path,
                              std::string(inside > 0 ? "crosses the outline" : "lies outside the outline") +
                                  "; a hole must be inside the part");
    }
    if (const int touching = geometry::holeTouchingOuter(outline); touching >= 0)
        throw FormatError(
            at(part.pathOf("holes"), touching),
            "touches the outline; a hole must lie inside the part with material all round it (a "
            "notch is part of the outline)");
    return outline;
}

nlohmann::json points(const geometry::Polygon& polygon)
{
    nlohmann::json list = nlohmann::json::array();
    for (const geometry::Point2& p : polygon)
        list.push_back({p.x, p.y});
    return list;
}

/// The part's outline, drills and marks, moved together so the outline's box starts at the origin.
void readShape(const Fields& part, material::PartSpec& p)
{
    if (!part.has("outline")) {
        p.outline = geometry::rectangle(part.positive("width"), part.positive("height"));
        return;
    }
    p.outline = readOutline(part);
    const nlohmann::json& drills = part.array("drills", true);
    for (size_t k = 0; k < drills.size(); ++k) {
        const Fields drill(drills[k], at(part.pathOf("drills"), k));
        p.drills.push_back(
            {{drill.number("x"), drill.number("y")}, drill.positive("diameter"), drill.positive("depth")});
        drill.noOthers();
    }
    const nlohmann::json& marks = part.array("marks", true);
    for (size_t k = 0; k < marks.size(); ++k)
        p.marks.push_back(readPolygon(marks[k], at(part.pathOf("marks"), k), true));
    const geometry::Placement2 move = geometry::placement(p.outline, 0, 0, 0);
    p.outline = geometry::placed(p.outline, 0, 0, 0);
    for (material::Drill& drill : p.drills)
        drill.at = move(drill.at);
    for (geometry::Polygon& mark : p.marks)
        for (geometry::Point2& q : mark)
            q = move(q);
}

/// "edge_banding": {"L1": "oak 1 mm", ...}, the band on each named side.
std::array<std::string, 4> readEdgeBanding(const Fields& part)
{
    std::array<std::string, 4> banding;
    const std::string path = part.pathOf("edge_banding");
    if (!part.has("edge_banding"))
        return banding;
    const nlohmann::json& found = part.value("edge_banding");
    if (!found.is_object())
        throw FormatError(path, "must map sides (L1, L2, W1, W2) to band names, got " + found.dump());
    const Fields bands(found, path);
    for (const auto& [side, band] : found.items()) {
        const auto& names = sideNames();
        const auto at = std::find(names.begin(), names.end(), side);
        if (at == names.end())
            throw FormatError(
                bands.pathOf(side),
                "not a side of the part; use L1, L2 (along its length), W1 or W2 (along its width)");
        banding[at - names.begin()] = bands.text(side);
        if (banding[at - names.begin()].empty())
            throw FormatError(bands.pathOf(side), "the band's name is empty (leave the side out for none)");
    }
    return banding;
}

material::PartSpec readPart(const nlohmann::json& json, const std::string& path, size_t index)
{
    const Fields part(json, path);
    material::PartSpec p;
    p.id = part.text("id", "part " + std::to_string(index + 1));
    readShape(part, p);
    p.quantity = part.integer("quantity", 1);
    if (p.quantity < 1)
        throw FormatError(part.pathOf("quantity"), "must be at least 1, got " + std::to_string(p.quantity));
    p.orientations = readOrientations(part);
    p.followsGrain = part.flag("follow_grain", p.followsGrain);
    p.thickness = part.number("thickness", 0.0, 0.0);
    p.edgeBanding = readEdgeBanding(part);
    part.noOthers();
    return p;
}

/// The value `names` gives the text at `key` (the first of them when absent); FormatError listing them.
template <typename Value>
Value named(const Fields& fields, const std::string& key,
            const std::vector<std::pair<std::string, Value>>& names)
{
    const std::string text = fields.text(key, names.front().first);
    for (const auto& [name, value] : names)
        if (name == text)
            return value;
    std::string listed;
    for (size_t k = 0; k < names.size(); ++k)
        listed += (k == 0 ? "" : k + 1 == names.size() ? " or " : ", ") + ("\"" + names[k].first + "\"");
    throw FormatError(fields.pathOf(key), "must be " + listed + ", got \"" + text + "\"");
}

/// The name `names` gives `value`.
template <typename Value>
std::string nameOf(Value value, const std::vector<std::pair<std::string, Value>>& names)
{
    for (const auto& [name, named] : names)
        if (named == value)
            return name;
    return names.front().first;
}

}  // namespace

const std::vector<std::pair<std::string, material::Cuts>>& cutsNames()
{
    static const std::vector<std::pair<std::string, material::Cuts>> names{
        {"free", material::Cuts::Free}, {"guillotine", material::Cuts::Guillotine}};
    return names;
}

const std::array<std::string, 4>& sideNames()
{
    static const std::array<std::string, 4> names{"L1", "L2", "W1", "W2"};
    return names;
}

const std::vector<std::pair<std::string, material::FirstCut>>& firstCutNames()
{
    static const std::vector<std::pair<std::string, material::FirstCut>> names{
        {"any", material::FirstCut::Any},
        {"along", material::FirstCut::Along},
        {"across", material::FirstCut::Across}};
    return names;
}

material::PackSettings readSettings(const nlohmann::json& document)
{
    material::PackSettings result;
    if (!document.contains("settings"))
        return result;
    const Fields settings(document["settings"], "settings");
    settings.only({"resolution", "kerf", "spacing", "trim", "dogbone", "tab_width", "tab_below",
                   "rotation_step", "cuts", "stages", "first_cut", "common_line", "min_length", "snap",
                   "max_growth"});  // the last three: a flat-pack design's
    result.resolution = settings.number("resolution", 0.5);
    if (!(result.resolution > 0))
        throw FormatError("settings.resolution", "must be greater than 0");
    result.kerf = settings.number("kerf", 0.0, 0.0);
    result.spacing = settings.number("spacing", 0.0, 0.0);
    result.trim = settings.number("trim", 0.0, 0.0);
    result.dogbone = settings.number("dogbone", 0.0, 0.0);
    result.tabWidth = settings.number("tab_width", 0.0, 0.0);
    result.tabBelow = settings.number("tab_below", 300.0, 0.0);
    result.rotationStep = settings.integer("rotation_step", 0);
    if (result.rotationStep < 0 || (result.rotationStep > 0 && 90 % result.rotationStep != 0))
        throw FormatError("settings.rotation_step", "must divide 90 (e.g. 15, 30, 45) or be 0, got " +
                                                        std::to_string(result.rotationStep));
    result.cuts = named(settings, "cuts", cutsNames());
    result.stages = settings.integer("stages", 0);
    if (result.stages < 0)
        throw FormatError("settings.stages", "must be 0 (unlimited) or a number of stages, got " +
                                                 std::to_string(result.stages));
    result.firstCut = named(settings, "first_cut", firstCutNames());
    result.commonLine = settings.flag("common_line", false);
    return result;
}

material::MasterBoard readMasterBoard(const nlohmann::json& json, const std::string& path)
{
    const Fields board(json, path);
    board.only({"name", "material", "width", "height", "thickness", "count", "cost", "grain"});
    material::MasterBoard b;
    b.name = board.text("name", "board");
    b.material = board.text("material", "");
    b.width = board.positive("width");
    b.height = board.positive("height");
    b.thickness = board.number("thickness", 0.0, 0.0);
    b.count = board.integer("count", 1);
    b.cost = board.number("cost", 1.0, 0.0);
    const std::string grain = board.text("grain", "none");
    if (grain != "none" && grain != "width" && grain != "height")
        throw FormatError(board.pathOf("grain"),
                          "must be \"none\", \"width\" or \"height\", got \"" + grain + "\"");
    b.grain = grain == "width"    ? material::Grain::AlongWidth
              : grain == "height" ? material::Grain::AlongHeight
                                  : material::Grain::None;
    if (b.count == 0 || b.count < -1)
        throw FormatError(board.pathOf("count"), "must be a positive number of boards, or -1 for unlimited");
    return b;
}

std::vector<material::MasterBoard> readMasterBoards(const nlohmann::json& document)
{
    const nlohmann::json& boards = Fields(document, "").array("boards");
    std::vector<material::MasterBoard> result;
    for (size_t i = 0; i < boards.size(); ++i)
        result.push_back(readMasterBoard(boards[i], at("boards", i)));
    if (result.empty())
        throw FormatError("boards", "at least one master board is needed");
    return result;
}

void checkGrid(const material::PackSettings& settings, const std::vector<material::MasterBoard>& boards)
{
    for (size_t i = 0; i < boards.size(); ++i)
        if (settings.resolution > std::min(boards[i].width, boards[i].height))
            throw FormatError("settings.resolution",
                              "a cell of " + show(settings.resolution) + " mm is larger than master board '" +
                                  boards[i].name + "' (" + show(boards[i].width) + " x " +
                                  show(boards[i].height) + " mm, boards[" + std::to_string(i) + "])");
}

material::PackProblem readPackProblem(const nlohmann::json& document)
{
    checkNumbers(document);
    const Fields root(document, "");
    root.header("fabguide.pack", kPackFormatVersion);
    material::PackProblem problem;
    problem.settings = readSettings(document);
    problem.boards = readMasterBoards(document);
    checkGrid(problem.settings, problem.boards);
    const nlohmann::json& parts = root.array("parts");
    std::map<std::string, size_t> ids;
    for (size_t i = 0; i < parts.size(); ++i) {
        problem.parts.push_back(readPart(parts[i], at("parts", i), i));
        if (const auto [known, added] = ids.emplace(problem.parts[i].id, i); !added)
            throw FormatError(at("parts", i) + ".id", "\"" + problem.parts[i].id + "\" is used by parts[" +
                                                          std::to_string(known->second) +
                                                          "] too; give each part its own id");
    }
    if (problem.parts.empty())
        throw FormatError("parts", "at least one part is needed");
    root.noOthers({"settings", "boards"});  // read by readSettings and readMasterBoards
    return problem;
}

namespace {

/// An ESICUP irregular strip instance as the sparrow nester distributes it ({"items": [{"demand",
/// "allowed_orientations", "shape": {"type": "simple_polygon", "data"}}], "strip_height"}): its strip is
/// `strip_height` high and its length is minimised. Turned a quarter clockwise as a whole, so that the
/// strip's height is our strip's width and its length our height; the pieces keep their shapes and
/// orientations.
material::PackProblem readEsicupInstance(const nlohmann::json& document)
{
    // The grid as fine across any instance's strip: fine enough that the cells the parts' outlines touch lose
    // little (finer costs the shrinking more per move; 650 did best on swim at 60 s, docs/decisions.md).
    constexpr double kEsicupCells = 650;
    const Fields root(document, "");
    material::PackProblem problem;
    problem.strip = true;
    material::MasterBoard strip;
    strip.name = "strip";
    strip.width = root.positive("strip_height");
    problem.boards.push_back(strip);
    problem.settings.resolution = strip.width / kEsicupCells;
    const nlohmann::json& items = root.array("items");
    for (size_t i = 0; i < items.size(); ++i) {
        const Fields item(items[i], at("items", i));
        if (!item.has("shape") || !items[i]["shape"].is_object())
            throw FormatError(item.pathOf("shape"),
                              "must be {\"type\": \"simple_polygon\", \"data\": [[x, y], ...]}");
        const Fields shape(items[i]["shape"], item.pathOf("shape"));
        if (shape.text("type") != "simple_polygon")
            throw FormatError(shape.pathOf("type"), "only \"simple_polygon\" shapes are read");
        geometry::Polygon outline = readPolygon(shape.array("data"), shape.pathOf("data"), true);
        for (geometry::Point2& q : outline)
            q = {q.y, -q.x};  // a quarter clockwise: still counter-clockwise
        material::PartSpec p{std::to_string(i), geometry::placed({outline, {}}, 0, 0, 0), 1, {}, {}, {}};
        p.quantity = item.integer("demand", 1);
        if (p.quantity < 1)
            throw FormatError(item.pathOf("demand"), "must be at least 1");
        const nlohmann::json& turns = item.array("allowed_orientations", true);
        for (size_t k = 0; k < turns.size(); ++k) {
            const double degrees = turns[k].is_number() ? turns[k].get<double>() : -1;
            if (degrees < 0 || degrees >= 360 || std::fmod(degrees, 90) != 0)
                throw FormatError(at(item.pathOf("allowed_orientations"), k), "must be 0, 90, 180 or 270");
            p.orientations.push_back(static_cast<int>(degrees));
        }
        if (p.orientations.empty())
            p.orientations = {0};
        problem.parts.push_back(p);
    }
    if (problem.parts.empty())
        throw FormatError("items", "no items to pack");
    return problem;
}

}  // namespace

material::PackProblem readStripInstance(const nlohmann::json& document)
{
    checkNumbers(document);
    if (document.is_object() && document.contains("items"))
        return readEsicupInstance(document);
    const Fields root(document, "");
    const nlohmann::json& objects = root.array("Objects");
    if (objects.empty())
        throw FormatError("Objects", "the strip (Objects[0]) is missing");
    material::PackProblem problem;
    problem.strip = true;
    problem.settings.resolution = 1;
    material::MasterBoard strip;
    strip.name = "strip";
    strip.width = Fields(objects[0], "Objects[0]").positive("Length");
    problem.boards.push_back(strip);
    const nlohmann::json& items = root.array("Items");
    for (size_t i = 0; i < items.size(); ++i) {
        const Fields item(items[i], at("Items", i));
        material::PartSpec p =
            material::rectangularPart(std::to_string(i), item.positive("Length"), item.positive("Height"));
        p.quantity = item.integer("Demand", 1);
        if (p.quantity < 1)
            throw FormatError(item.pathOf("Demand"), "must be at least 1");
        problem.parts.push_back(p);
    }
    if (problem.parts.empty())
        throw FormatError("Items", "no items to pack");
    return problem;
}

material::Layout readLayout(const nlohmann::json& document, const material::PackProblem& problem,
                            PartNames names, const std::string& where)
{
    checkNumbers(document, kLargestArea);  // its metrics are areas
    const Fields root(document, where);
    root.header("fabguide.layout", kPackFormatVersion);
    material::Layout layout;
    const nlohmann::json& boards = root.array("boards");
    for (size_t i = 0; i < boards.size(); ++i) {
        layout.sheets.push_back(readMasterBoard(boards[i], at(root.pathOf("boards"), i)));
        layout.sheetArea += layout.sheets.back().width * layout.sheets.back().height;
    }
    const nlohmann::json& placements = root.array("placements");
    for (size_t i = 0; i < placements.size(); ++i) {
        const Fields p(placements[i], at(root.pathOf("placements"), i));
        material::Placement placement;
        if (names == PartNames::Indices) {
            placement.part = p.integer("part");
        } else {
            const std::string id = p.text("part");
            const auto found = std::find_if(problem.parts.begin(), problem.parts.end(),
                                            [&](const material::PartSpec& s) { return s.id == id; });
            placement.part = static_cast<int>(found - problem.parts.begin());
        }
        if (placement.part < 0 || placement.part >= static_cast<int>(problem.parts.size()))
            throw FormatError(p.pathOf("part"), "no such part in the problem");
        placement.sheet = p.integer("board");
        if (placement.sheet < 0 || placement.sheet >= static_cast<int>(layout.sheets.size()))
            throw FormatError(p.pathOf("board"), "no such board in the layout");
        placement.x = p.number("x");
        placement.y = p.number("y");
        placement.rotation = p.integer("rotation");
        placement.width = p.positive("width");
        placement.height = p.positive("height");
        p.noOthers();
        layout.placements.push_back(placement);
        layout.partArea += geometry::area(problem.parts[placement.part].outline);
    }
    const nlohmann::json& sawn = root.array("saw_cuts", true);
    for (size_t i = 0; i < sawn.size(); ++i) {
        if (!sawn[i].is_array())
            throw FormatError(at(root.pathOf("saw_cuts"), i), "must be the list of one board's saw cuts");
        layout.sawCuts.emplace_back();
        for (size_t k = 0; k < sawn[i].size(); ++k) {
            const Fields c(sawn[i][k], at(at(root.pathOf("saw_cuts"), i), k));
            layout.sawCuts.back().push_back({c.text("number"), c.integer("stage"), c.flag("trim", false),
                                             readPoint(c.value("from"), c.pathOf("from")),
                                             readPoint(c.value("to"), c.pathOf("to"))});
            c.noOthers({"length"});  // written for people
        }
    }
    if (!sawn.empty() && sawn.size() != layout.sheets.size())
        throw FormatError(root.pathOf("saw_cuts"), "one list per board, " +
                                                       std::to_string(layout.sheets.size()) + ", got " +
                                                       std::to_string(sawn.size()));
    layout.boundingArea = layout.partArea / root.number("usage", 1.0);
    layout.stripHeight = root.number("strip_height", 0.0);
    root.noOthers({"sheet_utilisation", "waste_area", "cut_length", "common_line"});  // written for people
    return layout;
}

std::vector<material::Board3> readBoards3(const nlohmann::json& document)
{
    checkNumbers(document);
    if (!document.is_array())
        throw FormatError("boards", "must be a list of boards");
    std::vector<material::Board3> boards;
    for (size_t i = 0; i < document.size(); ++i) {
        const Fields board(document[i], at("boards", i));
        material::Board3 b{board.text("id"),   readOutline(board), board.vector3("origin"),
                           board.vector3("u"), board.vector3("v"), board.positive("thickness")};
        if (std::abs(b.u.norm() - 1) > 1e-6 || std::abs(b.v.norm() - 1) > 1e-6 ||
            std::abs(b.u.dot(b.v)) > 1e-6)
            throw FormatError(board.pathOf("u") + ", v", "must be perpendicular unit vectors");
        boards.push_back(b);
    }
    return boards;
}

material::JointStyle jointStyle(const std::string& name)
{
    if (name == "None")
        return material::JointStyle::None;
    if (name == "Fingers")
        return material::JointStyle::Fingers;
    if (name == "Auto")
        return material::JointStyle::Auto;
    throw FormatError("joint style: must be None, Fingers or Auto, got \"" + name + "\"");
}

nlohmann::json piecesToJson(const std::vector<material::Piece>& pieces, const material::JoinedBoards& joined,
                            const std::vector<material::Board3>& boards)
{
    nlohmann::json parts = nlohmann::json::array();
    for (const material::Piece& piece : pieces) {
        nlohmann::json holes = nlohmann::json::array(), drills = nlohmann::json::array(),
                       marks = nlohmann::json::array(), ids = nlohmann::json::array();
        for (const geometry::Polygon& hole : piece.outline.holes)
            holes.push_back(points(hole));
        for (const material::Drill& d : piece.drills)
            drills.push_back({{"x", d.at.x}, {"y", d.at.y}, {"diameter", d.diameter}, {"depth", d.depth}});
        for (const geometry::Polygon& mark : piece.marks)
            marks.push_back(points(mark));
        std::string id;
        for (int b : piece.boards) {
            ids.push_back(boards[b].id);
            id += (id.empty() ? "" : " + ") + boards[b].id;
        }
        parts.push_back({{"id", id},
                         {"boards", ids},
                         {"outline", points(piece.outline.outer)},
                         {"holes", holes},
                         {"drills", drills},
                         {"marks", marks}});
    }
    nlohmann::json connectors = nlohmann::json::array();
    for (const material::Connector& c : joined.connectors) {
        const char* kind = c.kind == material::Connector::Kind::Fingers  ? "fingers"
                           : c.kind == material::Connector::Kind::Dowels ? "dowels"
                                                                         : "cross slots";
        connectors.push_back({{"kind", kind},
                              {"a", boards[c.a].id},
                              {"b", boards[c.b].id},
                              {"count", std::max(c.tabs.size(), c.drills.size())}});
    }
    return {{"parts", parts}, {"connectors", connectors}, {"notes", joined.notes}};
}

nlohmann::json boardToJson(const material::MasterBoard& board)
{
    return {{"name", board.name},
            {"material", board.material},
            {"width", board.width},
            {"height", board.height},
            {"thickness", board.thickness},
            {"count", board.count},
            {"cost", board.cost},
            {"grain", board.grain == material::Grain::AlongWidth    ? "width"
                      : board.grain == material::Grain::AlongHeight ? "height"
                                                                    : "none"}};
}

nlohmann::json problemToJson(const material::PackProblem& problem)
{
    nlohmann::json boards = nlohmann::json::array(), parts = nlohmann::json::array();
    for (const material::MasterBoard& board : problem.boards)
        boards.push_back(boardToJson(board));
    for (const material::PartSpec& p : problem.parts) {
        nlohmann::json part = {{"id", p.id},
                               {"quantity", p.quantity},
                               {"orientations", p.orientations},
                               {"follow_grain", p.followsGrain}};
        if (p.thickness > 0)
            part["thickness"] = p.thickness;
        for (size_t side = 0; side < 4; ++side)
            if (!p.edgeBanding[side].empty())
                part["edge_banding"][sideNames()[side]] = p.edgeBanding[side];
        if (geometry::isRectangle(p.outline)) {
            part["width"] = p.width();
            part["height"] = p.height();
        } else {
            part["outline"] = points(p.outline.outer);
            part["holes"] = nlohmann::json::array();
            for (const geometry::Polygon& hole : p.outline.holes)
                part["holes"].push_back(points(hole));
        }
        parts.push_back(part);
    }
    return {{"format", "fabguide.pack"},
            {"version", kPackFormatVersion},
            {"settings", settingsToJson(problem.settings)},
            {"boards", boards},
            {"parts", parts}};
}

nlohmann::json settingsToJson(const material::PackSettings& s)
{
    return {{"resolution", s.resolution},
            {"kerf", s.kerf},
            {"spacing", s.spacing},
            {"trim", s.trim},
            {"dogbone", s.dogbone},
            {"tab_width", s.tabWidth},
            {"tab_below", s.tabBelow},
            {"rotation_step", s.rotationStep},
            {"cuts", nameOf(s.cuts, cutsNames())},
            {"stages", s.stages},
            {"first_cut", nameOf(s.firstCut, firstCutNames())},
            {"common_line", s.commonLine}};
}

nlohmann::json sawCutsToJson(const std::vector<std::vector<material::SawCut>>& sheets)
{
    nlohmann::json out = nlohmann::json::array();
    for (const std::vector<material::SawCut>& cuts : sheets) {
        nlohmann::json sheet = nlohmann::json::array();
        for (const material::SawCut& c : cuts)
            sheet.push_back({{"number", c.number},
                             {"stage", c.stage},
                             {"trim", c.trim},
                             {"from", {c.from.x, c.from.y}},
                             {"to", {c.to.x, c.to.y}},
                             {"length", c.length()}});
        out.push_back(sheet);
    }
    return out;
}

nlohmann::json layoutToJson(const material::Layout& layout, const material::PackProblem& problem,
                            PartNames names)
{
    nlohmann::json boards = nlohmann::json::array();
    for (const material::MasterBoard& sheet : layout.sheets)
        boards.push_back(boardToJson(sheet));
    nlohmann::json placements = nlohmann::json::array();
    for (const material::Placement& p : layout.placements) {
        nlohmann::json part =
            names == PartNames::Indices ? nlohmann::json(p.part) : nlohmann::json(problem.parts[p.part].id);
        placements.push_back({{"part", part},
                              {"board", p.sheet},
                              {"x", p.x},
                              {"y", p.y},
                              {"rotation", p.rotation},
                              {"width", p.width},
                              {"height", p.height}});
    }
    nlohmann::json out = {{"format", "fabguide.layout"},
                          {"version", kPackFormatVersion},
                          {"boards", boards},
                          {"placements", placements},
                          {"usage", layout.usage()},
                          {"sheet_utilisation", layout.sheetUtilisation()},
                          {"waste_area", layout.wasteArea()}};
    if (problem.strip)
        out["strip_height"] = layout.stripHeight;
    else {
        const material::Totals totals = material::totals(layout, problem);
        out["cut_length"] = totals.cutLength;
        if (problem.settings.commonLine)
            out["common_line"] = totals.commonLine;
    }
    if (!layout.sawCuts.empty())
        out["saw_cuts"] = sawCutsToJson(layout.sawCuts);
    return out;
}

}  // namespace fabguide::io
