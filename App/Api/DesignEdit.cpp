#include "Api/DesignEdit.h"

#include "Design/Correction.h"
#include "Design/DesignSpace.h"
#include "Design/DynamicPacker.h"

namespace fabguide::api {

namespace {

/// The format's parts of a design document (null when it has none).
nlohmann::json partsOf(const nlohmann::json& document)
{
    return document.is_object() && document.contains("parts") ? document["parts"] : nlohmann::json();
}

/// The ids of a format's parts, in order ("" for a part without one).
std::vector<std::string> idsOf(const nlohmann::json& parts)
{
    std::vector<std::string> ids;
    if (parts.is_array())
        for (const nlohmann::json& p : parts)
            ids.push_back(
                p.is_object() && p.contains("id") && p["id"].is_string() ? p["id"].get<std::string>() : "");
    return ids;
}

/// `drawn` with its boards where `parts` has them (same ids), every other field and the inner volumes as
/// drawn.
nlohmann::json withBoards(nlohmann::json drawn, const nlohmann::json& parts)
{
    for (size_t b = 0; b < parts.size(); ++b)
        for (const char* corner : {"min", "max"})
            drawn["parts"][b][corner] = parts[b][corner];
    return drawn;
}

/// The drawn parts as the variables X of `design` (the same boards, moved or resized).
Eigen::VectorXd variablesOf(const material::Design& design, const nlohmann::json& parts)
{
    material::Design drawn = design;
    for (size_t b = 0; b < design.boards.size(); ++b) {
        io::placeBoard(drawn.boards[b], io::Fields(parts[b], "parts[" + std::to_string(b) + "]"));
    }
    return drawn.variables();
}

/// Thesis 5.3.5 (Algorithms 5 and 6): the valid design `start` (the drawn one with the valid parts) changed
/// as far towards the drawn boards as its constraints allow; the drawn boards' other fields (grain) are kept.
void keepValid(const nlohmann::json& start, DesignEditReport& report)
{
    const io::FlatpackDesign before = io::readFlatpack(start);
    const Eigen::VectorXd X = before.design.variables();
    const material::CorrectedChange c =
        material::correctChange(before.design, X, variablesOf(before.design, report.design["parts"]) - X);
    report.design = io::withParts(report.design, before.design, c.X);
    report.kept = c.alpha;
    report.limits = c.limits;
}

/// The design read as every command reads it; when its boards break a constraint (one just added), first
/// moved the least, sparsely, so that every one holds (Algorithm 6 with no change to keep).
io::FlatpackDesign satisfied(DesignEditReport& report)
{
    try {
        return io::readFlatpack(report.design);
    } catch (const io::ConstraintError&) {
        const io::FlatpackDesign broken = io::readFlatpack(report.design, io::Satisfied::NotRequired);
        const Eigen::VectorXd X = broken.design.variables();
        const std::optional<Eigen::VectorXd> d =
            material::correctForDesignConstraints(broken.design, {}, X, Eigen::VectorXd::Zero(X.size()));
        if (!d || !material::ineffective(broken.design, X + *d).empty())
            throw;
        report.design = io::withParts(report.design, broken.design, X + *d);
        report.satisfied = true;
        return io::readFlatpack(report.design);
    }
}

/// Thesis 5.3.2: the drawn boards, which overflow the master boards, fitted from the valid design `start` by
/// the dynamic packer, slid from the layout `start` keeps (or a fresh one when it keeps none that fits), and
/// laid out. False when they cannot be fitted.
bool absorbed(const nlohmann::json& start, const DesignEdit& edit, DesignEditReport& report)
{
    try {
        const io::FlatpackDesign before = io::readFlatpack(start);
        const material::ConstrainedDesign design(before.design);
        const material::MaterialSpace material(before.boards, before.settings, design.parts());
        const Eigen::VectorXd X = before.design.variables();
        material::GridLayout previous;
        if (before.kept.layout)
            previous = material.onGrid(*before.kept.layout, design.sizes(X));
        if (!before.kept.layout || !previous.unplaced.empty())
            previous = material::layOut(design, material, edit.seed, edit.seconds).layout;
        const material::Absorbed a = material::dynamicPacker(
            design, material, X, previous, variablesOf(before.design, report.design["parts"]) - X);
        if (!a.fitted)
            return false;
        nlohmann::json fitted = io::withParts(report.design, before.design, a.X);
        const material::KeptLayout slid{{}, material.inMillimetres(a.layout, design.sizes(a.X))};
        report.laidOut = layOutDesign(io::readFlatpack(fitted), edit.seed, edit.seconds, slid);
        report.design = std::move(fitted);
        report.absorbed = true;
        report.snapped = a.snapped;
        return true;
    } catch (const material::PackingError&) {  // not even the valid design fits any more
        return false;
    }
}

}  // namespace

nlohmann::json layOutDesign(const io::FlatpackDesign& f, std::uint64_t seed, double seconds,
                            const material::KeptLayout& kept)
{
    const material::ConstrainedDesign design(f.design);
    const material::MaterialSpace material(f.boards, f.settings, design.parts());
    return io::designLayoutJson(material, material::layOut(design, material, seed, seconds, nullptr, kept));
}

DesignEditReport editDesign(const DesignEdit& edit)
{
    DesignEditReport report;
    const nlohmann::json drawn = io::currentFlatpack(edit.design);
    report.design = drawn;
    // The valid state as this version writes parts (a document saved by an older FabGuide kept them in its
    // own).
    const nlohmann::json valid =
        edit.valid ? io::currentFlatpack({{"parts", *edit.valid}})["parts"] : nlohmann::json();
    std::optional<nlohmann::json>
        start;  // the design with its valid boards, when the drawn ones are an edit of them
    if (edit.valid && idsOf(valid) == idsOf(partsOf(report.design)) && valid != partsOf(report.design)) {
        start = report.design;
        (*start)["parts"] = valid;
    }
    if (start && edit.keepEdits) {
        try {
            keepValid(*start, report);
        } catch (const io::FormatError& error) {  // the valid state no longer reads: the boards as drawn
            report.warning = error.what();
        }
    }
    try {
        const io::FlatpackDesign f = satisfied(report);
        report.laidOut = layOutDesign(f, edit.seed, edit.seconds, f.kept);
    } catch (const material::PackingError& error) {
        if (!start)
            throw;
        if (!absorbed(*start, edit, report)) {
            report.design = withBoards(drawn, valid);
            report.undone = error.what();
        }
    }
    return report;
}

}  // namespace fabguide::api
