// libFuzzer harness: *.flatpack.json read, its constraints checked, and, when small, laid out.
#include "FuzzSupport.h"
#include "IO/FlatpackFormat.h"
#include "Material/MinWastage.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const auto document = fabguide::fuzz::parsed(data, size);
    if (!document)
        return 0;
    fabguide::fuzz::runNamed([&] {
        namespace m = fabguide::material;
        const fabguide::io::FlatpackDesign flatpack =
            fabguide::io::readFlatpack(*document, fabguide::io::Satisfied::NotRequired);
        const Eigen::VectorXd X = flatpack.design.variables();
        m::unsatisfied(flatpack.design, X);
        m::ineffective(flatpack.design, X);
        if (flatpack.design.boards.size() > 12)
            return;
        const m::ConstrainedDesign design(flatpack.design);
        const m::MaterialSpace material(flatpack.boards, flatpack.settings, design.parts());
        m::layOut(design, material, 1);
    });
    return 0;
}
