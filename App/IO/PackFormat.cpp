#include "IO/PackFormat.h"

#include "IO/Json.h"

#include <algorithm>
#include <cmath>

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
            throw FormatError(at(part.pathOf("orientations"), k) + ": must be 0, 90, 180 or 270, got " +
                              list[k].dump());
        orientations.push_back(((list[k].get<int>() % 360) + 360) % 360);
    }
    return orientations;
}

material::MasterBoard readBoard(const nlohmann::json& json, const std::string& path)
{
    const Fields board(json, path);
    material::MasterBoard b;
    b.name = board.text("name", "board");
    b.material = board.text("material", "");
    b.width = board.positive("width");
    b.height = board.positive("height");
    b.thickness = board.number("thickness", 0.0, 0.0);
    b.count = board.integer("count", 1);
    if (b.count == 0 || b.count < -1)
        throw FormatError(board.pathOf("count") +
                          ": must be a positive number of boards, or -1 for unlimited");
    return b;
}

/// A polygon as [[x, y], ...]: at least 3 points, not flat; returned counter-clockwise if `outer`.
geometry::Polygon readPolygon(const nlohmann::json& json, const std::string& path, bool outer)
{
    if (!json.is_array() || json.size() < 3)
        throw FormatError(path + ": must be a list of at least 3 [x, y] points");
    geometry::Polygon polygon;
    for (size_t k = 0; k < json.size(); ++k) {
        const nlohmann::json& point = json[k];
        if (!point.is_array() || point.size() != 2 || !point[0].is_number() || !point[1].is_number())
            throw FormatError(at(path, k) + ": must be a point [x, y], got " + point.dump());
        polygon.push_back({point[0].get<double>(), point[1].get<double>()});
    }
    const double area = geometry::signedArea(polygon);
    if (std::abs(area) < 1e-9)
        throw FormatError(path + ": encloses no area");
    if ((area > 0) != outer)
        std::reverse(polygon.begin(), polygon.end());
    return polygon;
}

geometry::Outline readOutline(const Fields& part)
{
    if (!part.has("outline"))
        return geometry::rectangle(part.positive("width"), part.positive("height"));
    geometry::Outline outline;
    outline.outer = readPolygon(part.array("outline"), part.pathOf("outline"), true);
    const nlohmann::json& holes = part.array("holes", true);
    for (size_t k = 0; k < holes.size(); ++k)
        outline.holes.push_back(readPolygon(holes[k], at(part.pathOf("holes"), k), false));
    return geometry::atOrigin(outline);
}

material::PartSpec readPart(const nlohmann::json& json, const std::string& path, size_t index)
{
    const Fields part(json, path);
    material::PartSpec p;
    p.id = part.text("id", "part " + std::to_string(index + 1));
    p.outline = readOutline(part);
    p.quantity = part.integer("quantity", 1);
    if (p.quantity < 1)
        throw FormatError(part.pathOf("quantity") + ": must be at least 1, got " +
                          std::to_string(p.quantity));
    p.orientations = readOrientations(part);
    return p;
}

}  // namespace

material::PackProblem readPackProblem(const nlohmann::json& document)
{
    const Fields root(document, "");
    if (root.text("format", "fabguide.pack") != "fabguide.pack")
        throw FormatError("format: expected \"fabguide.pack\", got \"" + root.text("format") + "\"");
    const int version = root.integer("version", kPackFormatVersion);
    if (version != kPackFormatVersion)
        throw FormatError("version: this FabGuide reads version " + std::to_string(kPackFormatVersion) +
                          ", the file is version " + std::to_string(version));
    material::PackProblem problem;
    if (root.has("settings")) {
        const Fields settings(document["settings"], "settings");
        problem.settings.resolution = settings.number("resolution", 0.5);
        if (!(problem.settings.resolution > 0))
            throw FormatError("settings.resolution: must be greater than 0");
        problem.settings.kerf = settings.number("kerf", 0.0, 0.0);
        problem.settings.spacing = settings.number("spacing", 0.0, 0.0);
        problem.settings.trim = settings.number("trim", 0.0, 0.0);
    }
    const nlohmann::json& boards = root.array("boards");
    for (size_t i = 0; i < boards.size(); ++i)
        problem.boards.push_back(readBoard(boards[i], at("boards", i)));
    const nlohmann::json& parts = root.array("parts");
    for (size_t i = 0; i < parts.size(); ++i)
        problem.parts.push_back(readPart(parts[i], at("parts", i), i));
    if (problem.boards.empty())
        throw FormatError("boards: at least one master board is needed");
    if (problem.parts.empty())
        throw FormatError("parts: at least one part is needed");
    return problem;
}

material::PackProblem readStripInstance(const nlohmann::json& document)
{
    const Fields root(document, "");
    const nlohmann::json& objects = root.array("Objects");
    if (objects.empty())
        throw FormatError("Objects: the strip (Objects[0]) is missing");
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
            throw FormatError(item.pathOf("Demand") + ": must be at least 1");
        problem.parts.push_back(p);
    }
    if (problem.parts.empty())
        throw FormatError("Items: no items to pack");
    return problem;
}

material::Layout readLayout(const nlohmann::json& document, const material::PackProblem& problem,
                            PartNames names)
{
    const Fields root(document, "");
    material::Layout layout;
    const nlohmann::json& boards = root.array("boards");
    for (size_t i = 0; i < boards.size(); ++i) {
        layout.sheets.push_back(readBoard(boards[i], at("boards", i)));
        layout.sheetArea += layout.sheets.back().width * layout.sheets.back().height;
    }
    const nlohmann::json& placements = root.array("placements");
    for (size_t i = 0; i < placements.size(); ++i) {
        const Fields p(placements[i], at("placements", i));
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
            throw FormatError(p.pathOf("part") + ": no such part in the problem");
        placement.sheet = p.integer("board");
        if (placement.sheet < 0 || placement.sheet >= static_cast<int>(layout.sheets.size()))
            throw FormatError(p.pathOf("board") + ": no such board in the layout");
        placement.x = p.number("x");
        placement.y = p.number("y");
        placement.rotation = p.integer("rotation");
        placement.width = p.positive("width");
        placement.height = p.positive("height");
        layout.placements.push_back(placement);
        layout.partArea += geometry::area(problem.parts[placement.part].outline);
    }
    layout.boundingArea = layout.partArea / root.number("usage", 1.0);
    layout.stripHeight = root.number("strip_height", 0.0);
    return layout;
}

nlohmann::json layoutToJson(const material::Layout& layout, const material::PackProblem& problem,
                            PartNames names)
{
    nlohmann::json boards = nlohmann::json::array();
    for (const material::MasterBoard& sheet : layout.sheets)
        boards.push_back({{"name", sheet.name},
                          {"material", sheet.material},
                          {"width", sheet.width},
                          {"height", sheet.height},
                          {"thickness", sheet.thickness}});
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
    return out;
}

}  // namespace fabguide::io
