// libFuzzer harness: *.flatpack.json read, its constraints checked, and, when small, laid out once and each
// part size changed once.
#include "Design/DesignSpace.h"
#include "Design/MaterialSpace.h"
#include "FuzzSupport.h"
#include "IO/FlatpackFormat.h"

#include <numeric>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    return fabguide::fuzz::onDocument(data, size, [](const nlohmann::json& document) {
        namespace m = fabguide::material;
        const fabguide::io::FlatpackDesign flatpack =
            fabguide::io::readFlatpack(document, fabguide::io::Satisfied::NotRequired);
        const Eigen::VectorXd X = flatpack.design.variables();
        m::unsatisfied(flatpack.design, X);
        m::ineffective(flatpack.design, X);
        if (flatpack.design.boards.size() > 12)
            return;
        const m::ConstrainedDesign design(flatpack.design);
        const m::MaterialSpace material(flatpack.boards, flatpack.settings, design.parts());
        const Eigen::VectorXd sizes = design.sizes(design.start());
        std::vector<int> order(material.raster(sizes).parts.size());
        std::iota(order.begin(), order.end(), 0);
        material.dock(sizes, order);  // one docking pass: the search repeats it
        // CHANGEPARTSIZES one cell up on each size, the step of every exploration (thesis 5.4.2)
        for (Eigen::Index k = 0; k < sizes.size(); ++k)
            design.changePartSizes(design.start(), Eigen::VectorXd::Unit(sizes.size(), k) * 0.5);
    });
}
