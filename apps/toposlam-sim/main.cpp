// toposlam-sim: simulated laser + odometry logs over a grid map, with exact ground truth.
// Replaces MRPT 2.5.8's simul-gridmap (zero odometry, fixed 180 deg, wall-clock stamps).
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/core/bits_math.h>
#include <toposlam/cli/CommandLine.h>
#include <toposlam/cli/NumberArg.h>
#include <toposlam/io/GridMapIO.h>
#include <toposlam/io/InputError.h>
#include <toposlam/io/Trajectory.h>
#include <toposlam/simulation/ClearanceMap.h>
#include <toposlam/simulation/LogSimulator.h>
#include <toposlam/simulation/OfficeDataset.h>
#include <toposlam/simulation/SimulatorConfig.h>
#include <toposlam/simulation/TourPlanner.h>
#include <toposlam/simulation/TrajectoryImage.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

namespace {

using namespace toposlam;
using namespace toposlam::simulation;

/// "out.rawlog[.gz]" -> "out_gt.txt".
std::string defaultGroundTruthPath(const std::string& rawlog) {
    std::string stem = rawlog;
    for (const std::string ext : {".gz", ".rawlog"}) {
        if (stem.size() > ext.size() &&
            stem.compare(stem.size() - ext.size(), ext.size(), ext) == 0) {
            stem.erase(stem.size() - ext.size());
        }
    }
    return stem + "_gt.txt";
}

/// "x,y[,yaw_deg]" (m, m, deg) -> pose (m, m, rad).
mrpt::math::TPose2D parseStart(const std::string& text) {
    const bool withYaw = std::count(text.begin(), text.end(), ',') == 2;
    const auto v = cli::parseNumberList(text, withYaw ? 3 : 2, "--start");
    return {v[0], v[1], withYaw ? mrpt::DEG2RAD(v[2]) : 0.0};
}

int run(int argc, char** argv) {
    TCLAP::CmdLine cmd(
        "Simulates a robot with a 2D laser and wheel odometry over an occupancy grid map and "
        "writes an MRPT rawlog plus the exact ground-truth trajectory (\"timestamp x y yaw\", "
        "s m m rad, map frame). The robot follows either a pose file or an automatic tour "
        "through every room-sized free area of the map. Defaults are those of "
        "config_ini/sim-office.ini; -c reads such a file, and options given on the command "
        "line override it.\n"
        "Examples:\n"
        "  toposlam-sim share/office/office.gridmap.gz --tour -o office.rawlog\n"
        "  toposlam-sim map.png --poses poses.txt -o run.rawlog.gz --format sf --people 3\n"
        "  toposlam-sim --make-office share/office -c config_ini/sim-office.ini",
        ' ', "0.1.0");

    TCLAP::UnlabeledValueArg<std::string> mapArg(
        "map",
        "Grid map: .gridmap/.gridmap.gz (MRPT), .yaml (ROS map_server), or an image (.png .pgm "
        "...; geometry from its <stem>.yaml sidecar, else --resolution/--origin).",
        false, "", "map", cmd);
    TCLAP::ValueArg<std::string> posesArg(
        "", "poses",
        "Follow these robot poses, one scan each: text lines \"timestamp x y yaw\" (s, m, m, "
        "rad; map frame; stamps strictly increasing; '#' comments), the format of "
        "simul-gridmap and of --gt.",
        false, "", "file", cmd);
    TCLAP::SwitchArg tourArg("", "tour",
                             "Plan a tour that visits every room-sized free area of the map "
                             "(see [Tour] in config_ini/sim-office.ini) and follow it.",
                             cmd, false);
    TCLAP::ValueArg<std::string> makeOfficeArg(
        "", "make-office",
        "Instead of simulating over a given map, (re)generate the office data set into this "
        "directory: map (.gridmap.gz, .png + .yaml), room labels and doors, a toured log and its "
        "ground truth, a picture. This is how share/office is made.",
        false, "", "dir", cmd);
    TCLAP::ValueArg<std::string> outArg(
        "o", "out",
        "Output rawlog (.rawlog, or .rawlog.gz for gzip). Required unless --make-office.", false,
        "", "file", cmd);
    TCLAP::ValueArg<std::string> formatArg(
        "", "format",
        "Rawlog format: obs = CObservationOdometry + CObservation2DRangeScan (icp-slam, "
        "graphslam-engine); sf = actions + sensory frames (icp-slam, rbpf-slam). Default: obs.",
        false, "", "sf|obs", cmd);
    TCLAP::ValueArg<std::string> gtArg(
        "", "gt",
        "Ground-truth output (timestamp x y yaw). Default: the rawlog name with "
        ".rawlog[.gz] replaced by _gt.txt.",
        false, "", "file", cmd);
    TCLAP::ValueArg<std::string> configArg(
        "c", "config",
        "Simulator configuration (.ini; sections [Laser] [Odometry] [People] "
        "[Tour] [Simulation]; see config_ini/sim-office.ini).",
        false, "", "file.ini", cmd);
    cli::NumberArg<unsigned> beamsArg("", "beams", "Laser beams per scan. Default: 361.", 361,
                                      cli::NumberRange<unsigned>::closed(2, 100000), "n", cmd);
    cli::NumberArg<double> fovArg("", "fov-deg",
                                  "Laser field of view, first to last beam (deg). Default: 270.",
                                  270, cli::NumberRange<double>::positive(360), "deg", cmd);
    cli::NumberArg<double> maxRangeArg(
        "", "max-range", "Laser maximum range (m); farther returns are invalid. Default: 20.", 20,
        cli::NumberRange<double>::positive(1000), "m", cmd);
    cli::NumberArg<double> rangeNoiseArg("", "range-noise",
                                         "Laser range noise, Gaussian std (m). Default: 0.01.",
                                         0.01, cli::NumberRange<double>::nonNegative(10), "m", cmd);
    cli::NumberArg<double> bearingNoiseArg(
        "", "bearing-noise-deg", "Laser beam direction noise, Gaussian std (deg). Default: 0.05.",
        0.05, cli::NumberRange<double>::nonNegative(45), "deg", cmd);
    TCLAP::SwitchArg exactOdometryArg(
        "", "exact-odometry", "Odometry without any error (default: drift as in [Odometry]).", cmd,
        false);
    cli::NumberArg<unsigned> peopleArg(
        "", "people", "People (discs, radius 0.25 m) walking about at 0.8-1.3 m/s. Default: 0.", 0,
        cli::NumberRange<unsigned>::nonNegative(1000), "n", cmd);
    cli::NumberArg<unsigned> seedArg(
        "", "seed", "Random seed; the same inputs and seed give the same log. Default: 1.", 1,
        cli::NumberRange<unsigned>::nonNegative(2147483647), "n", cmd);
    TCLAP::ValueArg<std::string> startArg(
        "", "start",
        "Tour start pose x,y[,yaw_deg] (m, m, deg; map frame). Default: the centre "
        "of the largest free area.",
        false, "", "x,y[,yaw]", cmd);
    TCLAP::ValueArg<std::string> plotArg(
        "", "plot", "Also write a PNG of the map with the trajectory (and the tour's areas).",
        false, "", "file.png", cmd);
    cli::NumberArg<double> resolutionArg(
        "", "resolution", "Image maps without metadata: metres per pixel. Default: 0.05.", 0.05,
        cli::NumberRange<double>::positive(100), "m", cmd);
    TCLAP::ValueArg<std::string> originArg(
        "", "origin",
        "Image maps without metadata: world x,y of the lower-left corner (m). "
        "Default: 0,0.",
        false, "", "x,y", cmd);
    TCLAP::SwitchArg quietArg("q", "quiet", "No progress display and no summary.", cmd, false);

    if (const auto exitCode = cli::parseCommandLine(cmd, argc, argv))
        return *exitCode;

    // Configuration: defaults, then the .ini, then explicit command-line options.
    SimulatorConfig config;
    if (configArg.isSet()) {
        if (!std::filesystem::is_regular_file(configArg.getValue())) {
            throw io::InputError(configArg.getValue(), "no such configuration file");
        }
        mrpt::config::CConfigFile ini(configArg.getValue());
        loadSimulatorConfig(ini, config);
    }
    LaserModel& laser = config.log.laser;
    if (beamsArg.isSet())
        laser.beams = beamsArg.getValue();
    if (fovArg.isSet())
        laser.aperture = mrpt::DEG2RAD(fovArg.getValue());
    if (maxRangeArg.isSet())
        laser.maxRange = maxRangeArg.getValue();
    if (rangeNoiseArg.isSet())
        laser.rangeNoiseStd = rangeNoiseArg.getValue();
    if (bearingNoiseArg.isSet())
        laser.bearingNoiseStd = mrpt::DEG2RAD(bearingNoiseArg.getValue());
    if (exactOdometryArg.isSet())
        config.log.odometry = OdometryErrorModel::exact();
    if (peopleArg.isSet())
        config.log.people.count = peopleArg.getValue();
    if (seedArg.isSet())
        config.log.seed = seedArg.getValue();
    if (formatArg.isSet())
        config.format = parseRawlogFormat(formatArg.getValue());
    if (startArg.isSet())
        config.tour.start = parseStart(startArg.getValue());
    validate(config);
    const bool verbose = !quietArg.getValue();

    if (makeOfficeArg.isSet()) {
        if (mapArg.isSet() || posesArg.isSet() || tourArg.isSet() || outArg.isSet()) {
            throw cli::UsageError("--make-office takes no map, --poses, --tour or -o");
        }
        const OfficeDataset d = writeOfficeDataset(makeOfficeArg.getValue(), config, verbose);
        if (verbose) {
            std::printf("office: %zu scans, tour %.1f m in %.0f s, %zu of %zu rooms visited\n",
                        d.scans, d.tourLength, d.duration, d.roomsVisited, d.rooms);
            for (const auto& f : d.files)
                std::printf("  wrote %s\n", f.c_str());
        }
        return 0;
    }

    if (!mapArg.isSet())
        throw cli::UsageError("no map given");
    if (posesArg.isSet() == tourArg.isSet()) {
        throw cli::UsageError("give exactly one of --poses <file> and --tour");
    }
    if (!outArg.isSet())
        throw cli::UsageError("no output rawlog given (-o <file>)");
    const std::string mapPath = mapArg.getValue();
    const std::string outPath = outArg.getValue();
    const std::string gtPath = gtArg.isSet() ? gtArg.getValue() : defaultGroundTruthPath(outPath);

    std::optional<io::GridMapGeometry> geometry;
    if (resolutionArg.isSet() || originArg.isSet()) {
        geometry = io::GridMapGeometry{};
        geometry->resolution = resolutionArg.getValue();
        if (originArg.isSet()) {
            const auto o = cli::parseNumberList(originArg.getValue(), 2, "--origin");
            geometry->originX = o[0];
            geometry->originY = o[1];
        }
    }
    const auto map = io::loadGridMap(mapPath, geometry);
    const ClearanceMap clearance(map, config.log.world.thresholds);
    if (clearance.freeCellCount() == 0)
        throw io::InputError(mapPath, "the map has no free cell");

    io::Trajectory2D poses;
    std::vector<mrpt::math::TPoint2D> marks;
    if (tourArg.isSet()) {
        Tour tour;
        try {
            tour = planTour(clearance, config.tour);
        } catch (const std::invalid_argument& e) {
            throw io::InputError(mapPath, std::string("cannot plan a tour: ") + e.what());
        }
        poses = tour.poses;
        for (std::size_t a : tour.visitOrder)
            marks.push_back(tour.areas[a].centre);
        if (verbose) {
            std::printf("tour: %zu room-sized areas (%zu unreachable), %.1f m, %.0f s, %zu scans\n",
                        tour.areas.size(), tour.unreachable.size(), tour.length,
                        poses.back().stamp - poses.front().stamp, poses.size());
        }
    } else {
        poses = io::loadTrajectory(posesArg.getValue());
        if (poses.empty())
            throw io::InputError(posesArg.getValue(), "no pose in the file");
        const GridGeometry& g = clearance.geometry();
        std::size_t notFree = 0;
        for (std::size_t i = 0; i < poses.size(); ++i) {
            const auto& p = poses[i].pose;
            if (!g.contains(g.cellX(p.x), g.cellY(p.y))) {
                throw io::InputError(posesArg.getValue(),
                                     "pose " + std::to_string(i + 1) + " (" + std::to_string(p.x) +
                                         ", " + std::to_string(p.y) + ") is outside the map");
            }
            notFree += clearance.isFree(g.cellX(p.x), g.cellY(p.y)) ? 0 : 1;
        }
        if (notFree > 0) {
            std::fprintf(stderr, "warning: %zu of %zu poses are not in free cells of the map\n",
                         notFree, poses.size());
        }
    }

    std::size_t scans = 0;
    try {
        scans = simulateLogToFiles(map, poses, config.log, outPath, config.format, gtPath, verbose);
    } catch (const std::invalid_argument& e) {  // bad pose sequence (e.g. stamps)
        throw io::InputError(posesArg.isSet() ? posesArg.getValue() : mapPath, e.what());
    }
    if (plotArg.isSet())
        saveTrajectoryImage(map, poses, marks, plotArg.getValue());
    if (verbose) {
        std::printf("wrote %s (%zu scans, format %s) and %s\n", outPath.c_str(), scans,
                    config.format == io::RawlogFormat::Observations ? "obs" : "sf", gtPath.c_str());
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return toposlam::cli::runReportingErrors(run, argc, argv);
}
