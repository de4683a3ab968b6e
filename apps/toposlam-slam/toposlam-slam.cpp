// toposlam-slam: laser SLAM over a robot log, run like MRPT's icp-slam:
//   toposlam-slam <config.ini> <log.{rawlog,clf}> [-o outdir]
// Writes the trajectory (one pose per scan), the occupancy grid (.gridmap.gz; map.png to look
// at; map.yaml + map.pgm for ROS map_server) and prints a summary. The algorithm lives in
// libs/mapping.
#include <toposlam/classes/TopoSlamClasses.h>
#include <toposlam/cli/CommandLine.h>
#include <toposlam/config/IniFile.h>
#include <toposlam/io/GridMapIO.h>
#include <toposlam/io/Trajectory.h>
#include <toposlam/mapping/LogMapper.h>

#include <cstdio>
#include <filesystem>

namespace fs = std::filesystem;

namespace {

int run(int argc, char** argv) {
    TCLAP::CmdLine cmd(
        "Laser SLAM over a robot log (MRPT rawlog in either format, or CARMEN log), configured "
        "like MRPT's icp-slam: [MappingApplication] and [ICP] take icp-slam's keys, "
        "[OccupancyGrid] sets the output grid (see config_ini/toposlam-slam.ini). Writes "
        "<outdir>/trajectory.txt (timestamp x y yaw per scan, stamps as in the log), "
        "<outdir>/map.gridmap.gz, <outdir>/map.png (a picture of the grid) and the ROS "
        "map_server pair <outdir>/map.yaml + map.pgm (trinary, as map_saver writes it).",
        ' ', "0.1.0");
    TCLAP::UnlabeledValueArg<std::string> configArg("config", "configuration .ini file", true, "",
                                                    "config.ini", cmd);
    TCLAP::UnlabeledValueArg<std::string> logArg(
        "log", "laser + odometry log: .rawlog (plain or gz) or CARMEN .clf/.log", true, "", "log",
        cmd);
    TCLAP::ValueArg<std::string> outArg("o", "out", "output directory (created; default slam-out)",
                                        false, "slam-out", "dir", cmd);
    if (const auto exitCode = toposlam::cli::parseCommandLine(cmd, argc, argv))
        return *exitCode;
    toposlam::classes::registerTopoSlamClasses();  // logs may hold TopoSLAM's objects

    // A file that is no .ini file at all is an error here, not defaults (config/IniFile.h).
    const auto ini = toposlam::config::openIniFile(configArg.getValue());
    const toposlam::mapping::MappingResult result =
        toposlam::mapping::mapLog(logArg.getValue(), *ini);

    const fs::path out(outArg.getValue());
    fs::create_directories(out);
    toposlam::io::saveTrajectory(result.trajectory, (out / "trajectory.txt").string());
    toposlam::io::saveGridMap(result.grid, (out / "map.gridmap.gz").string());
    toposlam::io::saveGridMap(result.grid, (out / "map.png").string());

    std::printf("scans: %zu, log duration %.1f s, mapped in %.1f s (%.1fx real time)\n",
                result.scans, result.logDuration, result.wallSeconds,
                result.wallSeconds > 0 ? result.logDuration / result.wallSeconds : 0.0);
    std::printf("grid: %u x %u cells of %.2f m, x [%.2f, %.2f] y [%.2f, %.2f] m\n",
                result.grid.getSizeX(), result.grid.getSizeY(), result.grid.getResolution(),
                result.grid.getXMin(), result.grid.getXMax(), result.grid.getYMin(),
                result.grid.getYMax());
    if (result.wallAlignment != 0) {
        std::printf(
            "map turned by %.2f deg to line the walls up with the axes (wall "
            "direction strength %.2f)\n",
            result.wallAlignment * 180.0 / M_PI, result.wallDirectionStrength);
    }
    for (const char* f : {"trajectory.txt", "map.gridmap.gz", "map.png", "map.yaml", "map.pgm"}) {
        std::printf("wrote %s\n", (out / f).c_str());
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return toposlam::cli::runReportingErrors(run, argc, argv);
}
