// toposlam-convert: laser logs (CARMEN or MRPT rawlog) to MRPT rawlogs in either format, the
// odometry of a log as a trajectory, and grid maps between formats.
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <toposlam/cli/CommandLine.h>
#include <toposlam/cli/NumberArg.h>
#include <toposlam/io/GridMapIO.h>
#include <toposlam/io/LogConversion.h>
#include <toposlam/io/ProgressDisplay.h>

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace toposlam;

const char* const kDescription =
    "Converts laser logs and occupancy grid maps.\n"
    "Logs: the input is a CARMEN log (FLASER/RLASER/ROBOTLASER1/2 + PARAM lines; .clf, .log, "
    "optionally gzip) or an MRPT rawlog (either format, optionally gzip), detected from the "
    "content. -o writes an MRPT rawlog (gzip if it ends in .gz) in the format chosen by "
    "--format; --odometry-trajectory writes the odometry at each scan as 'fileStamp x y yaw' "
    "(s, m, m, rad), the stamps exactly as the log prints them, so ground-truth relation files "
    "match them. CARMEN import keeps exact per-scan timestamps (repairing the unpadded "
    "microseconds of old loggers), CARMEN's beam layout (180 readings: -90..+89 deg), the "
    "maximum range and invalid readings, and the laser's offset on the robot.\n"
    "Maps: when the input is a grid map (.gridmap, .gridmap.gz, .yaml/.yml, .png, .pgm, .bmp, "
    ".jpg, .tif), -o writes it in the format of its extension: .gridmap[.gz] (MRPT), .png (+ "
    "<stem>.yaml sidecar with resolution and origin), .yaml or .pgm (ROS map_server: YAML + "
    "trinary PGM). Bare images take --resolution and --origin.\n"
    "Examples:\n"
    "  toposlam-convert intel.clf -o intel.rawlog --odometry-trajectory intel.odometry.txt\n"
    "  toposlam-convert intel.clf -o intel_sf.rawlog.gz --format sf\n"
    "  toposlam-convert map.gridmap.gz -o map.yaml\n"
    "  toposlam-convert office.png --resolution 0.05 --origin -10,-5 -o office.gridmap.gz\n"
    "Exit status: 0 on success; 1 with 'error: ...' on stderr for bad input (the message "
    "names the file and, for logs, the line or object); 2 for bad options (an unknown option, "
    "a value out of range). No output file is written unless the whole input converts.";

bool isGridMapPath(const std::string& path) {
    std::string p = path;
    std::transform(p.begin(), p.end(), p.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (const char* ext : {".gridmap", ".gridmap.gz", ".yaml", ".yml", ".png", ".pgm", ".bmp",
                            ".jpg", ".jpeg", ".tif", ".tiff"}) {
        const std::string e = ext;
        if (p.size() >= e.size() && p.compare(p.size() - e.size(), e.size(), e) == 0)
            return true;
    }
    return false;
}

std::string fileName(const std::string& path) {
    return std::filesystem::path(path).filename().string();
}

int convertMap(const std::string& input, const std::string& output, bool hasResolution,
               double resolution, const std::string& origin, bool quiet) {
    if (output.empty())
        throw cli::UsageError("-o/--output is required for grid maps");
    std::optional<io::GridMapGeometry> geometry;
    if (hasResolution || !origin.empty()) {
        geometry.emplace();
        if (hasResolution)
            geometry->resolution = resolution;
        if (!origin.empty()) {
            const auto xy = cli::parseNumberList(origin, 2, "--origin");
            geometry->originX = xy[0];
            geometry->originY = xy[1];
        }
    }
    const auto map = io::loadGridMap(input, geometry);
    io::saveGridMap(map, output);
    if (!quiet) {
        std::printf("%s: %u x %u cells of %.4g m, origin (%.6g, %.6g) m, %zu free cells -> %s\n",
                    input.c_str(), map.getSizeX(), map.getSizeY(), map.getResolution(),
                    map.getXMin(), map.getYMin(), io::countFreeCells(map), output.c_str());
    }
    return EXIT_SUCCESS;
}

int run(int argc, char** argv) {
    TCLAP::CmdLine cmd(kDescription, ' ', "0.1");
    TCLAP::UnlabeledValueArg<std::string> input(
        "input", "Input: a CARMEN log, an MRPT rawlog, or a grid map", true, "", "input", cmd);
    TCLAP::ValueArg<std::string> output(
        "o", "output",
        "Output file. Logs: an MRPT rawlog (.rawlog, .rawlog.gz = gzip). Maps: .gridmap, "
        ".gridmap.gz, .png (+ .yaml sidecar), .yaml or .pgm (ROS map_server pair)",
        false, "", "file", cmd);
    std::vector<std::string> formats{"obs", "sf"};
    TCLAP::ValuesConstraint<std::string> formatValues(formats);
    TCLAP::ValueArg<std::string> format(
        "", "format",
        "Rawlog format: obs = observations only (CObservationOdometry + "
        "CObservation2DRangeScan; icp-slam, graphslam-engine), sf = actions/sensory frames "
        "(CActionRobotMovement2D + CSensoryFrame; rbpf-slam, icp-slam). Default: obs",
        false, "obs", &formatValues, cmd);
    TCLAP::ValueArg<std::string> odometryTrajectory(
        "", "odometry-trajectory",
        "Also write the log's odometry at each scan as 'fileStamp x y yaw' (s, m, m, rad)", false,
        "", "file", cmd);
    TCLAP::ValueArg<std::string> label(
        "", "label",
        "Only scans with this sensor label (CARMEN: FLASER, RLASER, ROBOTLASER1, ROBOTLASER2). "
        "Default: all 2D laser scans",
        false, "", "label", cmd);
    cli::NumberArg<double> maxRange(
        "", "carmen-max-range",
        "CARMEN: maximum range in m when no PARAM robot_front_laser_max line gives one; "
        "readings at or beyond it are invalid. Default: 81",
        81.0, cli::NumberRange<double>::positive(1000), "m", cmd);
    TCLAP::ValueArg<std::string> laserOffset(
        "", "laser-offset",
        "CARMEN: the laser's pose on the robot as x,y,yaw (m, m, rad), replacing what the log "
        "states. Default: from the log (laser vs robot pose in each line, else PARAM "
        "robot_frontlaser_offset)",
        false, "", "x,y,yaw", cmd);
    cli::NumberArg<std::size_t> maxScans(
        "", "max-scans", "Convert only the first N scans. Default: 0 = all", 0,
        cli::NumberRange<std::size_t>::nonNegative(1000000000), "N", cmd);
    cli::NumberArg<double> resolution(
        "", "resolution",
        "Maps: cell size in m for an input image (overrides its .yaml sidecar). Default: the "
        "sidecar's, else 0.05",
        0.05, cli::NumberRange<double>::positive(100), "m", cmd);
    TCLAP::ValueArg<std::string> origin(
        "", "origin",
        "Maps: world position x,y (m) of the lower-left corner of an input image (overrides "
        "its sidecar). Default: the sidecar's, else 0,0",
        false, "", "x,y", cmd);
    TCLAP::SwitchArg quiet("q", "quiet", "No progress display and no summary", cmd);
    if (const auto exitCode = cli::parseCommandLine(cmd, argc, argv)) {
        return *exitCode;
    }

    if (isGridMapPath(input.getValue())) {
        return convertMap(input.getValue(), output.getValue(), resolution.isSet(),
                          resolution.getValue(), origin.getValue(), quiet.getValue());
    }
    if (output.getValue().empty() && odometryTrajectory.getValue().empty()) {
        throw cli::UsageError("nothing to do: give -o and/or --odometry-trajectory");
    }
    io::LogConversionOptions options;
    options.read.scanLabel = label.getValue();
    options.read.carmenDefaultMaxRange = static_cast<float>(maxRange.getValue());
    if (laserOffset.isSet()) {
        const auto v = cli::parseNumberList(laserOffset.getValue(), 3, "--laser-offset");
        options.read.laserPoseOnRobot = mrpt::math::TPose2D(v[0], v[1], v[2]);
    }
    options.rawlogPath = output.getValue();
    options.rawlogFormat = format.getValue() == "sf" ? io::RawlogFormat::SensoryFrames
                                                     : io::RawlogFormat::Observations;
    options.odometryTrajectoryPath = odometryTrajectory.getValue();
    options.maxScans = maxScans.getValue();

    io::ProgressDisplay progress("reading " + fileName(input.getValue()), "scans",
                                 !quiet.getValue() && ::isatty(2) == 1);
    options.progress = [&](double fraction, std::size_t scans) {
        progress.update(fraction, scans);
    };
    const auto start = std::chrono::steady_clock::now();
    const io::LogConversionSummary s = io::convertLaserLog(input.getValue(), options);
    progress.finish();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!quiet.getValue()) {
        std::printf("%s: %s, %zu scans of %zu readings, %.3f .. %.3f s (%.1f s)",
                    input.getValue().c_str(), io::toString(s.inputFormat), s.scans, s.beamsPerScan,
                    s.firstStamp, s.lastStamp, s.lastStamp - s.firstStamp);
        if (s.adjustedTimestamps > 0) {
            std::printf(", %zu timestamps repaired", s.adjustedTimestamps);
        }
        if (s.scansWithoutOdometry > 0) {
            std::printf(", %zu scans without odometry", s.scansWithoutOdometry);
        }
        std::printf("\n");
        if (!options.rawlogPath.empty()) {
            std::printf("wrote %s (%s format, %zu objects)\n", options.rawlogPath.c_str(),
                        io::toString(options.rawlogFormat), s.rawlogObjects);
        }
        if (!options.odometryTrajectoryPath.empty()) {
            std::printf("wrote %s (%zu poses)\n", options.odometryTrajectoryPath.c_str(),
                        s.scans - s.scansWithoutOdometry);
        }
        std::printf("%.2f s, %.0f scans/s\n", seconds, seconds > 0 ? s.scans / seconds : 0.0);
    }
    return EXIT_SUCCESS;
}

}  // namespace

int main(int argc, char** argv) {
    return toposlam::cli::runReportingErrors(run, argc, argv);
}
