// toposlam-convert: laser logs (CARMEN or MRPT rawlog) to MRPT rawlogs in either format, the
// odometry of a log as a trajectory, and grid maps between formats. The conversions live in
// libs/io (LogConversion.h, MapConversion.h); this app parses options and reports.
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <toposlam/classes/TopoSlamClasses.h>
#include <toposlam/cli/CommandLine.h>
#include <toposlam/cli/LogAlterationArgs.h>
#include <toposlam/cli/MapReadingArgs.h>
#include <toposlam/cli/NumberArg.h>
#include <toposlam/io/GridMapIO.h>
#include <toposlam/io/LogConversion.h>
#include <toposlam/io/MapConversion.h>
#include <toposlam/io/ProgressDisplay.h>

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace toposlam;

const char* const kDescription =
    "Converts laser logs and occupancy grid maps.\n"
    "Logs: the input is a CARMEN log (FLASER/RLASER/ROBOTLASER1/2 + PARAM lines; .clf, .log, "
    "optionally gzip) or an MRPT rawlog (either format, optionally gzip; objects other than "
    "scans and odometry, such as TopoSLAM's scan features, are skipped), detected from the "
    "content. -o writes an MRPT rawlog (gzip if it ends in .gz) in the format chosen by "
    "--format; --odometry-trajectory writes the odometry at each scan as 'fileStamp x y yaw' "
    "(s, m, m, rad), the stamps exactly as the log prints them, so ground-truth relation files "
    "match them. CARMEN import keeps exact per-scan timestamps (repairing the unpadded "
    "microseconds of old loggers), CARMEN's beam layout (180 readings: -90..+89 deg), the "
    "maximum range and invalid readings, and the laser's offset on the robot.\n"
    "Maps: when the input is a grid map (.gridmap, .gridmap.gz, .yaml/.yml, .png, .pgm, .bmp, "
    ".jpg, .tif), -o writes it in the format of its extension: .gridmap[.gz] (MRPT), .yaml or "
    ".pgm (the ROS map_server pair: YAML with mode trinary + trinary PGM, as map_saver writes "
    "it), .png (a grey picture of p(free), plus that ROS pair as <stem>.yaml + <stem>.pgm). Bare "
    "images take --resolution and --origin, and are read as a drawn floor plan (written with "
    "every non-white cell occupied) or as a grid as their greys show (a note on stderr; "
    "--drawn, --grid).\n"
    "Examples:\n"
    "  toposlam-convert intel.clf -o intel.rawlog --odometry-trajectory intel.odometry.txt\n"
    "  toposlam-convert intel.clf -o intel_sf.rawlog.gz --format sf\n"
    "  toposlam-convert map.gridmap.gz -o map.yaml\n"
    "  toposlam-convert office.png --resolution 0.05 --origin -10,-5 -o office.gridmap.gz\n"
    "Exit status: 0 on success; 1 with 'error: ...' on stderr for bad input (the message "
    "names the file and, for logs, the line or object); 2 for bad options (an unknown option, "
    "a value out of range). No output file is written unless the whole input converts.";

// The command line; every argument registers itself with `cmd` (constructed first).
struct Arguments {
    Arguments();
    TCLAP::CmdLine cmd;
    TCLAP::UnlabeledValueArg<std::string> input;
    TCLAP::ValueArg<std::string> output;
    std::vector<std::string> formats{"obs", "sf"};
    TCLAP::ValuesConstraint<std::string> formatValues;
    TCLAP::ValueArg<std::string> format;
    TCLAP::ValueArg<std::string> odometryTrajectory;
    TCLAP::ValueArg<std::string> label;
    cli::NumberArg<double> maxRange;
    TCLAP::ValueArg<std::string> laserOffset;
    cli::NumberArg<std::size_t> maxScans;
    cli::LogAlterationArgs alteration;
    cli::MapGeometryArgs geometry;
    cli::MapReadingArgs mapReading;
    TCLAP::SwitchArg quiet;
};

Arguments::Arguments()
    : cmd(kDescription, ' ', "0.1"),
      input("input", "Input: a CARMEN log, an MRPT rawlog, or a grid map", true, "", "input", cmd),
      output("o", "output",
             "Output file. Logs: an MRPT rawlog (.rawlog, .rawlog.gz = gzip). Maps: .gridmap, "
             ".gridmap.gz, .yaml or .pgm (ROS map_server pair), .png (picture + ROS pair)",
             false, "", "file", cmd),
      formatValues(formats),
      format("", "format",
             "Rawlog format: obs = observations only (CObservationOdometry + "
             "CObservation2DRangeScan; icp-slam, graphslam-engine), sf = actions/sensory frames "
             "(CActionRobotMovement2D + CSensoryFrame; rbpf-slam, icp-slam). Default: obs",
             false, "obs", &formatValues, cmd),
      odometryTrajectory(
          "", "odometry-trajectory",
          "Also write the log's odometry at each scan as 'fileStamp x y yaw' (s, m, m, rad)", false,
          "", "file", cmd),
      label("", "label",
            "Only scans with this sensor label (CARMEN: FLASER, RLASER, ROBOTLASER1, "
            "ROBOTLASER2). Default: all 2D laser scans",
            false, "", "label", cmd),
      maxRange("", "carmen-max-range",
               "CARMEN: maximum range in m when no PARAM robot_front_laser_max line gives one; "
               "readings at or beyond it are invalid. Default: 81",
               81.0, cli::NumberRange<double>::positive(1000), "m", cmd),
      laserOffset("", "laser-offset",
                  "CARMEN: the laser's pose on the robot as x,y,yaw (m, m, rad), replacing what "
                  "the log states. Default: from the log (laser vs robot pose in each line, else "
                  "PARAM robot_frontlaser_offset)",
                  false, "", "x,y,yaw", cmd),
      maxScans("", "max-scans", "Read only the first N scans of the log. Default: 0 = all", 0,
               cli::NumberRange<std::size_t>::nonNegative(1000000000), "N", cmd),
      alteration(cmd, {"A relation file still matches the kept scans' stamps.",
                       "Features stored with the scans are left out.", "",
                       "Observations format: no odometry observations; sensory frames: "
                       "empty action collections.",
                       "Features stored with the scans are left out. Score a trajectory of it "
                       "with toposlam-eval-slam --mirrored-reference."}),
      geometry(cmd),
      mapReading(cmd,
                 "Maps: the grid written has every non-white cell occupied (p(free) 0), walls, "
                 "furniture and background alike, and the white cells as they are."),
      quiet("q", "quiet", "No progress display and no summary", cmd) {}

// On a grid map these would be ignored without a word: bad usage instead.
void refuseLogOptions(const Arguments& a) {
    const std::pair<bool, const char*> logOptions[] = {
        {a.format.isSet(), "--format"},
        {a.odometryTrajectory.isSet(), "--odometry-trajectory"},
        {a.label.isSet(), "--label"},
        {a.maxRange.isSet(), "--carmen-max-range"},
        {a.laserOffset.isSet(), "--laser-offset"},
        {a.maxScans.isSet(), "--max-scans"}};
    for (const auto& [set, name] : logOptions) {
        if (set)
            throw cli::UsageError(std::string(name) + " is for laser logs, not grid maps");
    }
    for (const std::string& name : a.alteration.given())
        throw cli::UsageError(name + " is for laser logs, not grid maps");
}

int convertMap(Arguments& a) {
    refuseLogOptions(a);
    if (a.output.getValue().empty())
        throw cli::UsageError("-o/--output is required for grid maps");
    const auto geometry = a.geometry.geometry();
    const bool drawn = a.mapReading.readAsDrawnPlan(a.input.getValue());
    const auto summary =
        io::convertGridMap(a.input.getValue(), a.output.getValue(), geometry, drawn);
    if (!a.quiet.getValue())
        std::printf("%s\n", io::describe(summary, a.input.getValue(), a.output.getValue()).c_str());
    return EXIT_SUCCESS;
}

io::LogConversionOptions logOptions(Arguments& a) {
    if (a.mapReading.given() || a.geometry.given()) {
        throw cli::UsageError(
            "--drawn, --grid, --resolution and --origin are for grid maps, not laser logs");
    }
    if (a.output.getValue().empty() && a.odometryTrajectory.getValue().empty())
        throw cli::UsageError("nothing to do: give -o and/or --odometry-trajectory");
    if (a.alteration.alteration().dropOdometry && a.odometryTrajectory.isSet())
        throw cli::UsageError("--no-odometry leaves no odometry for --odometry-trajectory");
    io::LogConversionOptions options;
    options.read.scanLabel = a.label.getValue();
    options.read.carmenDefaultMaxRange = static_cast<float>(a.maxRange.getValue());
    if (a.laserOffset.isSet()) {
        const auto v = cli::parseNumberList(a.laserOffset.getValue(), 3, "--laser-offset");
        options.read.laserPoseOnRobot = mrpt::math::TPose2D(v[0], v[1], v[2]);
    }
    options.rawlogPath = a.output.getValue();
    options.rawlogFormat = a.format.getValue() == "sf" ? io::RawlogFormat::SensoryFrames
                                                       : io::RawlogFormat::Observations;
    options.odometryTrajectoryPath = a.odometryTrajectory.getValue();
    options.maxScans = a.maxScans.getValue();
    options.alteration = a.alteration.alteration();
    return options;
}

int convertLog(Arguments& a) {
    cli::requireExtension({"-o", a.output.getValue()}, {".rawlog", ".rawlog.gz"});
    io::LogConversionOptions options = logOptions(a);
    const std::string& input = a.input.getValue();
    io::ProgressDisplay progress("reading " + std::filesystem::path(input).filename().string(),
                                 "scans", !a.quiet.getValue() && ::isatty(2) == 1);
    options.progress = [&](double fraction, std::size_t scans) {
        progress.update(fraction, scans);
    };
    const auto start = std::chrono::steady_clock::now();
    const io::LogConversionSummary summary = io::convertLaserLog(input, options);
    progress.finish();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!a.quiet.getValue()) {
        std::printf("%s%.2f s, %.0f scans/s\n", io::describe(summary, input, options).c_str(),
                    seconds, seconds > 0 ? static_cast<double>(summary.scans) / seconds : 0.0);
    }
    return EXIT_SUCCESS;
}

int run(int argc, char** argv) {
    Arguments arguments;
    if (const auto exitCode = cli::parseCommandLine(arguments.cmd, argc, argv))
        return *exitCode;
    // A map's sidecar and ROS pair count too: office.png -o office.yaml rewrote its sidecar.
    std::vector<cli::FileArgument> outputs =
        cli::mapFilesWritten({"-o", arguments.output.getValue()});
    outputs.push_back({"--odometry-trajectory", arguments.odometryTrajectory.getValue()});
    cli::requireOutputsOfTheirOwn(cli::mapFilesRead({"", arguments.input.getValue()}), outputs);
    // Rawlogs may hold TopoSLAM's own objects (scan features, ...): make them readable.
    classes::registerTopoSlamClasses();
    if (io::isGridMapPath(arguments.input.getValue()))
        return convertMap(arguments);
    return convertLog(arguments);
}

}  // namespace

int main(int argc, char** argv) {
    return toposlam::cli::runReportingErrors(run, argc, argv);
}
