// libFuzzer harness: *.pack.json, OR-Datasets and ESICUP strip instances, read and, when small, laid out.
#include "FuzzSupport.h"
#include "IO/PackFormat.h"

namespace {

void layOutIfSmall(const fabguide::material::PackProblem& problem)
{
    long units = 0;
    for (const fabguide::material::PartSpec& part : problem.parts)
        units += part.quantity;
    if (units > 40)
        return;
    fabguide::material::OrderingSearchOptions search;
    search.iterations = 20;
    search.timeLimit = 0.2;
    const fabguide::material::Layout layout = fabguide::material::pack(problem, search);
    fabguide::io::layoutToJson(layout, problem, fabguide::io::PartNames::Ids);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const auto document = fabguide::fuzz::parsed(data, size);
    if (!document)
        return 0;
    fabguide::fuzz::runNamed([&] { layOutIfSmall(fabguide::io::readPackProblem(*document)); });
    fabguide::fuzz::runNamed([&] { layOutIfSmall(fabguide::io::readStripInstance(*document)); });
    return 0;
}
