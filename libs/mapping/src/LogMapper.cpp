#include <mrpt/system/datetime.h>
#include <toposlam/io/InputError.h>
#include <toposlam/io/LaserLogReader.h>
#include <toposlam/io/ProgressDisplay.h>
#include <toposlam/mapping/IcpSlam.h>
#include <toposlam/mapping/LogMapper.h>
#include <toposlam/mapping/ManhattanAlignment.h>
#include <toposlam/mapping/OccupancyGridBuilder.h>

#include <chrono>
#include <filesystem>

namespace toposlam::mapping {

MappingResult mapLog(const std::string& logPath, const mrpt::config::CConfigFileBase& ini) {
    const auto start = std::chrono::steady_clock::now();
    OccupancyGridOptions gridOptions;
    gridOptions.loadFromConfigFile(ini, "OccupancyGrid");
    IcpSlam slam(ini);

    io::LaserLogReader reader(logPath);
    io::ProgressDisplay progress("mapping " + std::filesystem::path(logPath).filename().string(),
                                 "scans");
    MappingResult result;
    std::vector<PosedScan> posedScans;
    io::LaserLogRecord record;
    while (reader.next(record)) {
        const mrpt::poses::CPose2D pose = slam.process(record);
        result.trajectory.push_back({record.fileStamp, pose.asTPose()});
        posedScans.push_back({record.scan, pose});
        progress.update(reader.fractionRead(), posedScans.size());
    }
    progress.finish();
    if (posedScans.empty())
        throw io::InputError(logPath, "the log contains no laser scans");

    if (gridOptions.alignWithWalls) {
        const auto walls = estimateWallDirection(posedScans);
        if (walls && walls->strength >= gridOptions.minWallDirectionStrength) {
            result.wallAlignment = -walls->angle;
            result.wallDirectionStrength = walls->strength;
            const mrpt::poses::CPose2D turn(0, 0, result.wallAlignment);
            for (std::size_t i = 0; i < posedScans.size(); ++i) {
                posedScans[i].robotPose = turn + posedScans[i].robotPose;
                result.trajectory[i].pose = posedScans[i].robotPose.asTPose();
            }
        } else if (walls) {
            result.wallDirectionStrength = walls->strength;
        }
    }

    result.scans = posedScans.size();
    result.logDuration = mrpt::system::timeDifference(posedScans.front().scan->timestamp,
                                                      posedScans.back().scan->timestamp);
    result.grid = buildOccupancyGrid(posedScans, gridOptions);
    result.wallSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace toposlam::mapping
