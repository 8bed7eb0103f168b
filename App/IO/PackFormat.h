// The flat-pack layout formats (docs/formats.md): `*.pack.json` in, layout JSON out, and the
// OR-Datasets strip-packing instances used as benchmarks.
#pragma once

#include "Layout/Coplanar.h"
#include "Layout/Pack.h"

#include <nlohmann/json.hpp>

#include <string>
#include <utility>
#include <vector>

namespace fabguide::io {

constexpr int kPackFormatVersion = 1;

/// settings.cuts and settings.first_cut as the formats and the command line spell them, in the order told.
const std::vector<std::pair<std::string, material::Cuts>>& cutsNames();
const std::vector<std::pair<std::string, material::FirstCut>>& firstCutNames();
/// A part's sides as "edge_banding" and the cut list name them: L1, L2, W1, W2 (material::Side's order).
const std::array<std::string, 4>& sideNames();

/// The "settings" of a `*.pack.json` or `*.flatpack.json` document (defaults when absent).
material::PackSettings readSettings(const nlohmann::json& document);

/// The "boards" (master boards) of a `*.pack.json` or `*.flatpack.json` document; at least one.
std::vector<material::MasterBoard> readMasterBoards(const nlohmann::json& document);

/// Throws FormatError naming settings.resolution when a grid cell is larger than a master board's side: that
/// board would hold no cell, and nothing could be laid on it.
void checkGrid(const material::PackSettings& settings, const std::vector<material::MasterBoard>& boards);

/// Reads a `*.pack.json` document. Throws FormatError naming the offending field.
material::PackProblem readPackProblem(const nlohmann::json& document);

/// Reads a strip-packing instance, part ids = 0-based item indices: an OR-Datasets rectangle instance
/// ({"Objects": [{"Length", "Height"}], "Items": [{"Length", "Height", "Demand"}]}: width Objects[0].Length,
/// grid resolution 1), or an ESICUP irregular one as sparrow distributes it ({"items": [{"demand",
/// "allowed_orientations", "shape": {"type": "simple_polygon", "data"}}], "strip_height"}: turned a quarter
/// clockwise, so its strip height is the width, 250 grid cells across).
material::PackProblem readStripInstance(const nlohmann::json& document);

/// How placements name their part: by the part's id, or (OR-Datasets) by its index in the input.
enum class PartNames { Ids, Indices };

/// A master board as *.pack.json writes it.
nlohmann::json boardToJson(const material::MasterBoard& board);

/// Settings as *.pack.json writes them, every one.
nlohmann::json settingsToJson(const material::PackSettings& settings);

/// A problem as a *.pack.json document (rectangles as width and height, other parts as outlines).
nlohmann::json problemToJson(const material::PackProblem& problem);

/// The layout JSON contract: {"boards": [{"width", "height", ...}], "strip_height" (strip mode),
/// "placements": [{"part", "board", "x", "y", "rotation", "width", "height"}], metrics}.
nlohmann::json layoutToJson(const material::Layout& layout, const material::PackProblem& problem,
                            PartNames names);

/// Reads a layout JSON written by layoutToJson back, against the problem it was made for, so cut
/// sheets can be written for exactly the layout a user has seen. Throws FormatError naming the field, under
/// `where` when the layout is a value inside another document.
material::Layout readLayout(const nlohmann::json& document, const material::PackProblem& problem,
                            PartNames names, const std::string& where = "");

/// Reads boards in 3-D: [{"id", "outline", "holes", "origin": [x, y, z], "u": [...], "v": [...],
/// "thickness"}], outlines kept in their own frames. Throws FormatError naming the field.
std::vector<material::Board3> readBoards3(const nlohmann::json& document);

/// "None", "Fingers" or "Auto"; FormatError otherwise.
material::JointStyle jointStyle(const std::string& name);

/// The pieces to cut as *.pack.json parts (outline, holes, drills, marks, in the frame of each piece's
/// first board, plus "boards": the ids it is made of), with the connectors made and the notes:
/// {"parts": [...], "connectors": [...], "notes": [...]}.
nlohmann::json piecesToJson(const std::vector<material::Piece>& pieces, const material::JoinedBoards& joined,
                            const std::vector<material::Board3>& boards);

}  // namespace fabguide::io
