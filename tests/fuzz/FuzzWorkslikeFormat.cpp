// libFuzzer harness: *.workslike.json read and, when small, solved and written back.
#include "FuzzSupport.h"
#include "IO/WorkslikeFormat.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    return fabguide::fuzz::onDocument(data, size, [](const nlohmann::json& document) {
        const fabguide::function::Model model = fabguide::io::readWorkslike(document);
        if (model.cuboids.size() > 24)
            return;
        const fabguide::function::SolveResult result = fabguide::function::solve(model);
        fabguide::io::workslikeToJson(result.model, &result);
    });
}
