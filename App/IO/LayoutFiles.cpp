#include "IO/LayoutFiles.h"

#include "IO/CutSheetFiles.h"
#include "IO/Output.h"
#include "IO/Report.h"

namespace fabguide::io {

std::vector<WrittenFile> writeLayoutFiles(const material::Layout& layout,
                                          const material::PackProblem& problem, const LayoutFiles& files)
{
    OutputBatch batch;  // within an open batch, its commit renames nothing yet
    std::vector<WrittenFile> written;
    for (const std::string& path : writeCutSheets(layout, problem, files.svgFolder, files.dxfFolder,
                                                  files.csvFile, files.name, files.options))
        written.push_back({path == files.csvFile ? "cut list" : "cut sheet", path});
    if (!files.reportFile.empty()) {
        writeReport(layout, problem, files.title, files.reportFile);
        written.push_back({"report", files.reportFile});
    }
    if (!files.labelsFile.empty()) {
        writeLabels(layout, problem, files.labelsFile, files.labelSize.first, files.labelSize.second);
        written.push_back({"labels", files.labelsFile});
    }
    if (!files.optiCutterFile.empty())
        for (const std::string& path : writeOptiCutter(problem, files.optiCutterFile, files.title))
            written.push_back({"optiCutter", path});
    batch.commit();
    return written;
}

}  // namespace fabguide::io
