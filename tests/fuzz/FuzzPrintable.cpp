// libFuzzer harness: a small *.workslike.json made printable in place (cavities, joints, gaps in
// OpenCASCADE), its joint geometry placed by the clearance check, and its files written to a temporary
// folder.
#include "FuzzSupport.h"
#include "IO/PrintFiles.h"
#include "IO/WorkslikeFormat.h"
#include "Printable/Checks.h"
#include "Printable/PrintInPlace.h"

#include <filesystem>

#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    return fabguide::fuzz::onDocument(data, size, [](const nlohmann::json& document) {
        const fabguide::function::Model model = fabguide::io::readWorkslike(document);
        if (model.cuboids.size() > 8 || model.joints.size() > 3)
            return;
        const fabguide::printable::Printer printer{0.4, 5};
        const fabguide::printable::Fitted fitted = fabguide::printable::printed(model, printer, 1);
        const fabguide::printable::Checked placed =
            fabguide::printable::placedByCheck(fitted.model, fitted.printable, printer, 8);
        const std::filesystem::path folder =
            std::filesystem::temp_directory_path() / ("fabguide-fuzz-printable-" + std::to_string(getpid()));
        fabguide::io::writePrintFiles(fabguide::printable::onTheBed(placed.printable, fitted.turned),
                                      folder.string());
        std::filesystem::remove_all(folder);
    });
}
