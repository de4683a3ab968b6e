#include <toposlam/io/AtomicFile.h>
#include <toposlam/io/FileExtension.h>
#include <toposlam/io/InputError.h>
#include <toposlam/simulation/ClearanceMap.h>
#include <toposlam/simulation/LogSimulator.h>
#include <toposlam/simulation/SimulationJob.h>
#include <toposlam/simulation/TrajectoryImage.h>

#include <stdexcept>
#include <string_view>

namespace toposlam::simulation {

std::string groundTruthPathFor(const std::string& rawlogPath) {
    std::string stem = rawlogPath;
    for (const std::string_view ext : {".gz", ".rawlog"}) {
        if (io::hasExtension(stem, ext))
            stem.erase(stem.size() - ext.size());
    }
    return stem + "_gt.txt";
}

namespace {

void planTourInto(SimulationPlan& plan, const ClearanceMap& clearance,
                  const SimulatorConfig& config, const std::string& mapPath) {
    try {
        plan.tour = planTour(clearance, plannedTour(config));
    } catch (const std::invalid_argument& e) {
        throw io::InputError(mapPath, std::string("cannot plan a tour: ") + e.what());
    }
    plan.poses = plan.tour->poses;
    for (std::size_t a : plan.tour->visitOrder)
        plan.marks.push_back(plan.tour->areas[a].centre);
    for (const UnseenArea& u : plan.tour->unseen)  // the stops that look into them
        plan.marks.insert(plan.marks.end(), u.viewpoints.begin(), u.viewpoints.end());
}

void loadPosesInto(SimulationPlan& plan, const ClearanceMap& clearance, const std::string& path) {
    plan.poses = io::loadTrajectory(path);
    if (plan.poses.empty())
        throw io::InputError(path, "no pose in the file");
    const GridGeometry& g = clearance.geometry();
    for (std::size_t i = 0; i < plan.poses.size(); ++i) {
        const auto& p = plan.poses[i].pose;
        if (!g.contains(g.cellX(p.x), g.cellY(p.y))) {
            throw io::InputError(path, "pose " + std::to_string(i + 1) + " (" +
                                           std::to_string(p.x) + ", " + std::to_string(p.y) +
                                           ") is outside the map");
        }
        plan.posesNotFree += clearance.isFree(g.cellX(p.x), g.cellY(p.y)) ? 0 : 1;
    }
}

}  // namespace

SimulationPlan planSimulation(const SimulatorConfig& config, const SimulationJob& job) {
    SimulationPlan plan;
    plan.map = io::loadGridMap(job.mapPath, job.imageGeometry);
    const ClearanceMap clearance(plan.map, config.log.world.thresholds);
    if (clearance.freeCellCount() == 0)
        throw io::InputError(job.mapPath, "the map has no free cell");
    if (job.posesPath.empty())
        planTourInto(plan, clearance, config, job.mapPath);
    else
        loadPosesInto(plan, clearance, job.posesPath);
    return plan;
}

std::size_t runSimulation(const SimulationPlan& plan, const SimulatorConfig& config,
                          const SimulationJob& job, const io::ProgressCallback& progress) {
    const std::string gtPath =
        job.groundTruthPath.empty() ? groundTruthPathFor(job.rawlogPath) : job.groundTruthPath;
    io::OutputGroup files;  // the log, its ground truth and the plot, or none of them
    std::size_t scans = 0;
    try {
        scans = simulateLogToFiles(plan.map, plan.poses, config.log, job.rawlogPath, config.format,
                                   gtPath, progress);
    } catch (const std::invalid_argument& e) {  // bad pose sequence (e.g. stamps)
        throw io::InputError(job.posesPath.empty() ? job.mapPath : job.posesPath, e.what());
    }
    if (!job.plotPath.empty())
        saveTrajectoryImage(plan.map, plan.poses, plan.marks, job.plotPath);
    files.commit();
    return scans;
}

}  // namespace toposlam::simulation
