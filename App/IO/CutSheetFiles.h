// Cut-sheet files a laser cutter or CNC router accepts (docs/formats.md "Cut sheets"):
// SVG and DXF per master board, a CSV cut list.
#pragma once

#include "Layout/CutSheet.h"

#include <string>
#include <vector>

namespace fabguide::io {

/// SVG sized in millimetres, one Inkscape layer (group) per operation in the order they are done: "sheet"
/// (grey #999999 board outline, not to be cut), "drill-<depth>mm" (green #00a000 circles with data-depth),
/// "engrave" (blue #0000ff text and marks), "inner-cut" (magenta #ff00ff: holes with no part in them),
/// "outer-cut" (red #ff0000: outlines, holes holding parts), "tabs" (as designed: cyan #00c0c0 lines where
/// holding tabs go) and, with guillotine cuts, "saw": the saw's cuts as dashed orange (#ff8000) lines with
/// data-number and data-stage, each numbered in text at its middle.
/// "edge-banding" (brown lines, data-band, not cut). Lines are 0.1 mm hairlines.
/// y points up in FabGuide and down in SVG: flipped here.
std::string svg(const material::CutSheet& sheet);
void writeSvg(const material::CutSheet& sheet, const std::string& path);

/// DXF R2000 (AC1015) in millimetres with a layer per operation: INNER_CUT (magenta) and OUTER_CUT (red)
/// LWPOLYLINEs as in the SVG, ENGRAVE (blue TEXT and marks), DRILL_<depth>MM (green CIRCLEs), TABS (cyan
/// LINEs, as designed), SAW (orange LINEs and their numbers, guillotine cuts) and SHEET.
void writeDxf(const material::CutSheet& sheet, const std::string& path);

/// CSV cut list with header
/// part,quantity,width,height,thickness,material,board,grain,edge_L1,edge_L2,edge_W1, edge_W2,label (board
/// numbered from 1; grain "width" when the part's width runs along the board's grain, empty when it may lie
/// either way; the band on each side; the part's label).
void writeCutList(const std::vector<material::CutListRow>& rows, const std::string& path);

/// The parts and master boards of a problem in optiCutter's keyed CSV import format (N name, M material, S
/// stock length/width/quantity, K kerf, P part length/width/quantity/label/can-turn), one file per thickness:
/// `path` itself when all parts are one thickness, else PATH-<thickness>mm.csv each. Returns the paths.
std::vector<std::string> writeOptiCutter(const material::PackProblem& problem, const std::string& path,
                                         const std::string& name);

/// The cut sheets of a layout: SVG files into `svgFolder`, DXF files into `dxfFolder`, the cut list into
/// `csvFile`, each skipped when empty; sheet files named after `name` when given (writeSheets); returns the
/// paths written.
std::vector<std::string> writeCutSheets(const material::Layout& layout, const material::PackProblem& problem,
                                        const std::string& svgFolder, const std::string& dxfFolder,
                                        const std::string& csvFile, const std::string& name = "",
                                        material::CutSheetOptions options = {});

/// Writes sheet-1.svg / sheet-1.dxf ... (NAME-sheet-1.svg ... when `name` is given: two layouts share a
/// folder) into `folder` (created if missing), and removes the set's sheets numbered past these, left by an
/// earlier run with more sheets, so a set is replaced whole; returns the paths written. FormatError for a
/// name that is not a plain file name.
std::vector<std::string> writeSheets(const std::vector<material::CutSheet>& sheets, const std::string& folder,
                                     const std::string& extension, const std::string& name = "");

}  // namespace fabguide::io
