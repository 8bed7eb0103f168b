// libFuzzer harness: *.pack.json, OR-Datasets and ESICUP strip instances, read and, when small, laid out; a
// layout of a two-part job and 3-D boards (what FreeCAD hands the core), read.
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

/// The job a fuzzed layout is read against: two parts on one board.
const fabguide::material::PackProblem& twoParts()
{
    static const fabguide::material::PackProblem problem = fabguide::io::readPackProblem(nlohmann::json::parse(
        R"({"boards": [{"width": 1000, "height": 500}], "parts": [{"id": "a", "width": 300, "height": 200},
            {"id": "b", "width": 100, "height": 100, "quantity": 2}]})"));
    return problem;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const auto document = fabguide::fuzz::parsed(data, size);
    if (!document)
        return 0;
    fabguide::fuzz::runNamed([&] { layOutIfSmall(fabguide::io::readPackProblem(*document)); });
    fabguide::fuzz::runNamed([&] { layOutIfSmall(fabguide::io::readStripInstance(*document)); });
    fabguide::fuzz::runNamed(
        [&] { fabguide::io::readLayout(*document, twoParts(), fabguide::io::PartNames::Ids); });
    fabguide::fuzz::runNamed([&] { fabguide::io::readBoards3(*document); });
    return 0;
}
