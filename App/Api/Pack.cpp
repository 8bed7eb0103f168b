#include "Api/Pack.h"

#include "IO/PackFormat.h"

namespace fabguide::api {

PackReport pack(const PackJob& job)
{
    PackReport report;
    report.problem = job.strip ? io::readStripInstance(job.document) : io::readPackProblem(job.document);
    material::PackSettings& settings = report.problem.settings;
    settings.rotationStep = job.rotationStep.value_or(settings.rotationStep);
    settings.cuts = job.cuts.value_or(settings.cuts);
    settings.stages = job.stages.value_or(settings.stages);
    settings.firstCut = job.firstCut.value_or(settings.firstCut);
    settings.commonLine = settings.commonLine || job.commonLine;
    report.layout = material::pack(report.problem, job.search);
    return report;
}

}  // namespace fabguide::api
