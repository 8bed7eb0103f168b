// Every file a layout goes to the shop with, written as one set: what `fabguide pack` and FreeCAD's Export
// Cut Sheets both write (a set is replaced whole, whoever writes it).
#pragma once

#include "Layout/CutSheet.h"

#include <string>
#include <utility>
#include <vector>

namespace fabguide::io {

/// Where each file goes; an empty path or folder skips that file.
struct LayoutFiles {
    std::string svgFolder, dxfFolder, csvFile, reportFile, labelsFile, optiCutterFile;
    std::string name;   ///< sheet files NAME-sheet-N.* when given (two layouts share a folder)
    std::string title;  ///< the report's and optiCutter's job name
    std::pair<double, double> labelSize{62, 29};
    material::CutSheetOptions options;
};

/// A file written, and what it is ("cut sheet", "cut list", "report", "labels", "optiCutter").
struct WrittenFile {
    std::string what, path;
};

/// Writes the files of `files` for the layout, all renamed into place together: in the caller's open
/// OutputBatch, else in one of its own.
std::vector<WrittenFile> writeLayoutFiles(const material::Layout& layout,
                                          const material::PackProblem& problem, const LayoutFiles& files);

}  // namespace fabguide::io
