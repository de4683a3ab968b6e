#include <mrpt/poses/CPose3D.h>
#include <toposlam/mapping/OccupancyGridBuilder.h>

#include <cmath>
#include <stdexcept>

namespace toposlam::mapping {

void OccupancyGridOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& ini,
                                              const std::string& section) {
    resolution = ini.read_double(section, "resolution", resolution);
    keyframeDistance = ini.read_double(section, "keyframeDistance", keyframeDistance);
    keyframeAngle =
        ini.read_double(section, "keyframeAngle_deg", keyframeAngle * 180.0 / M_PI) * M_PI / 180.0;
    insertion.loadFromConfigFile(ini, section);
}

mrpt::maps::COccupancyGridMap2D buildOccupancyGrid(const std::vector<PosedScan>& scans,
                                                   const OccupancyGridOptions& options) {
    if (scans.empty())
        throw std::invalid_argument("buildOccupancyGrid: no scans");
    const auto& first = scans.front().robotPose;
    const auto res = static_cast<float>(options.resolution);
    // Start small around the first pose; insertObservation() grows the grid as scans need.
    mrpt::maps::COccupancyGridMap2D grid(
        static_cast<float>(first.x() - 10), static_cast<float>(first.x() + 10),
        static_cast<float>(first.y() - 10), static_cast<float>(first.y() + 10), res);
    grid.insertionOptions = options.insertion;

    const mrpt::poses::CPose2D* lastInserted = nullptr;
    for (const PosedScan& s : scans) {
        if (lastInserted) {
            const mrpt::poses::CPose2D delta = s.robotPose - *lastInserted;
            if (delta.norm() < options.keyframeDistance &&
                std::abs(delta.phi()) < options.keyframeAngle) {
                continue;
            }
        }
        grid.insertObservation(*s.scan, mrpt::poses::CPose3D(s.robotPose));
        lastInserted = &s.robotPose;
    }
    return grid;
}

}  // namespace toposlam::mapping
