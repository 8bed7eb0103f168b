// The shop's paperwork for a layout: a printable report and labels for the parts, drawn with
// cairo.
#pragma once

#include "Layout/CutSheet.h"

#include <string>
#include <vector>

namespace fabguide::io {

/// The report, A4 landscape: a page per sheet (its parts numbered with their sizes, the grain, the edge
/// banding, the saw cuts numbered in their order), then the cut list and the totals (sheets, area, waste, cut
/// length, edge banding, cost). Parts are numbered by their place in the problem, from 1.
void writeReport(const material::Layout& layout, const material::PackProblem& problem,
                 const std::string& title, const std::string& path);

/// The report's pages as SVG texts (FreeCAD's TechDraw pages show them).
std::vector<std::string> reportSvgs(const material::Layout& layout, const material::PackProblem& problem,
                                    const std::string& title);

/// Labels for a label printer: one page of width x height mm for each part cut, with its number, name, size,
/// material, sheet, grain and banded edges. Throws FormatError for a label under 20 x 10 mm.
void writeLabels(const material::Layout& layout, const material::PackProblem& problem,
                 const std::string& path, double width = 62, double height = 29);

}  // namespace fabguide::io
