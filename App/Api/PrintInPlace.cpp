#include "Api/PrintInPlace.h"

#include "Core/Text.h"
#include "IO/WorkslikeFormat.h"

#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>

#include <algorithm>
#include <cstdio>

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

std::vector<std::string> PrintReport::failures() const
{
    std::vector<std::string> why;
    if (!check)
        return why;
    for (const std::string& name : check->invalid)
        why.push_back("'" + name + "' is no valid solid");
    for (const std::string& body : check->loose)
        why.push_back("'" + body + "' prints in pieces");
    if (tooClose()) {
        char line[96];
        std::snprintf(line, sizeof line, "parts come %.3f mm apart, under the %.2f mm gap, ",
                      check->clearance, gap);
        why.push_back(line + check->where);
    }
    return why;
}

bool PrintReport::ok() const
{
    return check && failures().empty();
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
        throw std::invalid_argument("no printer profile '" + job.printer + "' (" +
                                    joined(profiles, [](const PrinterProfile& p) { return p.id; }) + ")");
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
