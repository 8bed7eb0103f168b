#include "Api/Explore.h"

namespace fabguide::api {

nlohmann::json ExplorationReport::suggestionDocument(const material::Suggestion& s) const
{
    return io::suggestionDocument(document, flatpack.design, material, s);
}

ExplorationReport explore(const Exploring& job)
{
    nlohmann::json document = job.document;
    nlohmann::json keptEqual = nlohmann::json::array();
    if (job.keepDrawnEqual)
        for (const nlohmann::json& equal : io::drawnEqualConstraints(document)) {
            keptEqual.push_back(equal);
            document["constraints"].push_back(equal);
        }
    io::FlatpackDesign flatpack = io::readFlatpack(document);
    const material::ConstrainedDesign design(io::forSuggestions(flatpack));
    material::MaterialSpace material(flatpack.boards, flatpack.settings, design.parts());
    material::MinWastageOptions options = job.options;
    options.kept = flatpack.kept;
    material::Exploration exploration = material::minWastage(design, material, options);
    return {std::move(document), std::move(keptEqual), std::move(flatpack), std::move(material),
            std::move(exploration)};
}

}  // namespace fabguide::api
