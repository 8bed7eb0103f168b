#include "Api/PrintInPlace.h"

#include "IO/WorkslikeFormat.h"

#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>

#include <algorithm>

namespace fabguide::api {

const std::vector<PrinterProfile>& printerProfiles()
{
    static const std::vector<PrinterProfile> profiles{{"fdm", "FDM (0.4 mm gap)", 0.4},
                                                      {"resin", "Resin (0.2 mm gap)", 0.2}};
    return profiles;
}

bool PrintReport::tooClose() const
{
    return check && check->clearance < gap - 0.01;
}

bool PrintReport::ok() const
{
    return check && check->invalid.empty() && check->loose.empty() && !tooClose();
}

namespace {

double gapOf(const PrintJob& job)
{
    if (job.gap)
        return *job.gap;
    const auto& profiles = printerProfiles();
    const auto found = std::find_if(profiles.begin(), profiles.end(),
                                    [&](const PrinterProfile& p) { return p.id == job.printer; });
    if (found == profiles.end()) {
        std::string ids;
        for (const PrinterProfile& p : profiles)
            ids += (ids.empty() ? "" : ", ") + p.id;
        throw std::invalid_argument("no printer profile '" + job.printer + "' (" + ids + ")");
    }
    return found->gap;
}

}  // namespace

PrintReport printInPlace(const PrintJob& job)
{
    PrintReport report;
    report.gap = gapOf(job);
    const printable::Printer printer{report.gap, job.partSeconds};
    report.fitted = printable::printed(io::readWorkslike(job.model), printer, job.scale, job.fit);
    if (job.check) {
        printable::Checked placed =
            printable::placedByCheck(report.fitted.model, report.fitted.printable, printer);
        report.fitted.printable = std::move(placed.printable);
        report.check = std::move(placed.check);
    }
    report.size = printable::sizeOf(printable::onTheBed(report.fitted.printable, report.fitted.turned));
    for (const printable::Body& b : report.fitted.printable.bodies) {
        GProp_GProps volume;
        BRepGProp::VolumeProperties(b.shape, volume);
        report.volumes.push_back(volume.Mass());
    }
    return report;
}

}  // namespace fabguide::api
