// toposlam-sim: simulated laser + odometry logs over a grid map, with exact ground truth.
// Replaces MRPT 2.5.8's simul-gridmap (zero odometry, fixed 180 deg, wall-clock stamps).
// The work is libs/simulation's (SimulationJob.h, OfficeDataset.h); this parses options.
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/core/bits_math.h>
#include <toposlam/cli/CommandLine.h>
#include <toposlam/cli/MapReadingArgs.h>
#include <toposlam/cli/NumberArg.h>
#include <toposlam/config/IniFile.h>
#include <toposlam/io/GridMapIO.h>
#include <toposlam/io/ProgressDisplay.h>
#include <toposlam/simulation/OfficeDataset.h>
#include <toposlam/simulation/SimulationJob.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace {

using namespace toposlam;
using namespace toposlam::simulation;

const char* const kDescription =
    "Simulates a robot with a 2D laser and wheel odometry over an occupancy grid map and "
    "writes an MRPT rawlog plus the exact ground-truth trajectory (\"timestamp x y yaw\", "
    "s m m rad, map frame). The robot follows either a pose file or an automatic tour "
    "through every room-sized free area of the map. Defaults are those of "
    "config_ini/sim-office.ini; -c reads such a file, and options given on the command "
    "line override it.\n"
    "Examples:\n"
    "  toposlam-sim share/office/office.gridmap.gz --tour -o office.rawlog\n"
    "  toposlam-sim map.png --poses poses.txt -o run.rawlog.gz --format sf --people 3\n"
    "  toposlam-sim --make-office share/office -c config_ini/sim-office.ini";

/// The command line (TCLAP arguments register with cmd, which is declared first).
struct Arguments {
    TCLAP::CmdLine cmd{kDescription, ' ', "0.1.0"};
    TCLAP::UnlabeledValueArg<std::string> mapArg{
        "map",
        "Grid map: .gridmap/.gridmap.gz (MRPT), .yaml (ROS map_server), or an image (.png .pgm "
        "...; geometry from its <stem>.yaml sidecar, else 0.05 m at 0,0; --resolution and "
        "--origin replace either value).",
        false,
        "",
        "map",
        cmd};
    TCLAP::ValueArg<std::string> posesArg{
        "",
        "poses",
        "Follow these robot poses, one scan each: text lines \"timestamp x y yaw\" (s, m, m, "
        "rad; map frame; stamps strictly increasing; '#' comments), the format of "
        "simul-gridmap and of --gt.",
        false,
        "",
        "file",
        cmd};
    TCLAP::SwitchArg tourArg{"", "tour",
                             "Plan a tour that visits every room-sized free area of the map "
                             "(see [Tour] in config_ini/sim-office.ini) and follow it.",
                             cmd, false};
    TCLAP::ValueArg<std::string> makeOfficeArg{
        "",
        "make-office",
        "Instead of simulating over a given map, (re)generate the office data set into this "
        "directory: map (.gridmap.gz, .png + .yaml), room labels and doors, a toured log and its "
        "ground truth, a picture. This is how share/office is made.",
        false,
        "",
        "dir",
        cmd};
    TCLAP::ValueArg<std::string> outArg{
        "o",
        "out",
        "Output rawlog (.rawlog, or .rawlog.gz for gzip). Required unless --make-office.",
        false,
        "",
        "file",
        cmd};
    std::vector<std::string> formatNames{"obs", "sf"};
    TCLAP::ValuesConstraint<std::string> formatValues{formatNames};
    TCLAP::ValueArg<std::string> formatArg{
        "",
        "format",
        "Rawlog format: obs = CObservationOdometry + CObservation2DRangeScan (icp-slam, "
        "graphslam-engine); sf = actions + sensory frames (icp-slam, rbpf-slam). Default: obs.",
        false,
        "",
        &formatValues,
        cmd};
    TCLAP::ValueArg<std::string> gtArg{
        "",
        "gt",
        "Ground-truth output (timestamp x y yaw). Default: the rawlog name with "
        ".rawlog[.gz] replaced by _gt.txt.",
        false,
        "",
        "file",
        cmd};
    TCLAP::ValueArg<std::string> configArg{
        "c",
        "config",
        "Simulator configuration (.ini; sections [Laser] [Odometry] [People] "
        "[Tour] [Simulation]; see config_ini/sim-office.ini).",
        false,
        "",
        "file.ini",
        cmd};
    cli::NumberArg<unsigned> beamsArg{"",
                                      "beams",
                                      "Laser beams per scan. Default: 361.",
                                      361,
                                      cli::NumberRange<unsigned>::closed(2, 100000),
                                      "n",
                                      cmd};
    cli::NumberArg<double> fovArg{"",
                                  "fov-deg",
                                  "Laser field of view, first to last beam (deg). Default: 270.",
                                  270,
                                  cli::NumberRange<double>::positive(360),
                                  "deg",
                                  cmd};
    cli::NumberArg<double> maxRangeArg{
        "",
        "max-range",
        "Laser maximum range (m); farther returns are invalid. Default: 20.",
        20,
        cli::NumberRange<double>::positive(1000),
        "m",
        cmd};
    cli::NumberArg<double> rangeNoiseArg{"",
                                         "range-noise",
                                         "Laser range noise, Gaussian std (m). Default: 0.01.",
                                         0.01,
                                         cli::NumberRange<double>::nonNegative(10),
                                         "m",
                                         cmd};
    cli::NumberArg<double> bearingNoiseArg{
        "",
        "bearing-noise-deg",
        "Laser beam direction noise, Gaussian std (deg). Default: 0.05.",
        0.05,
        cli::NumberRange<double>::nonNegative(45),
        "deg",
        cmd};
    TCLAP::SwitchArg exactOdometryArg{
        "", "exact-odometry", "Odometry without any error (default: drift as in [Odometry]).", cmd,
        false};
    cli::NumberArg<unsigned> peopleArg{
        "",
        "people",
        "People (discs, radius 0.25 m) walking about at 0.8-1.3 m/s. Default: 0.",
        0,
        cli::NumberRange<unsigned>::nonNegative(1000),
        "n",
        cmd};
    cli::NumberArg<unsigned> seedArg{
        "",
        "seed",
        "Random seed; the same inputs and seed give the same log. Default: 1.",
        1,
        cli::NumberRange<unsigned>::nonNegative(2147483647),
        "n",
        cmd};
    TCLAP::ValueArg<std::string> startArg{
        "",
        "start",
        "Tour start pose x,y[,yaw_deg] (m, m, deg; map frame). Default: the centre "
        "of the largest room-sized area the tour visits (free space that runs on to the map's "
        "edge, such as the background of a drawn plan, is not toured).",
        false,
        "",
        "x,y[,yaw]",
        cmd};
    TCLAP::ValueArg<std::string> plotArg{
        "",
        "plot",
        "Also write a PNG of the map with the trajectory (and the tour's stops: its areas and, "
        "with [Tour] look_into_unseen, the places that look into what it would leave unseen).",
        false,
        "",
        "file.png",
        cmd};
    const cli::MapGeometryArgs geometry{cmd};
    const cli::MapReadingArgs mapReading{
        cmd,
        "Grey furniture stops the laser and a grey background around the building is no free "
        "space to tour ([Simulation] occupied_below = free_above = 0.98; as toposlam-rooms "
        "--drawn)."};
    TCLAP::SwitchArg quietArg{"q", "quiet", "No progress display and no summary.", cmd, false};
};

/// m: a tour shorter than this stays where it starts (worth a warning).
constexpr double kShortestTour = 1.0;

/// "x,y[,yaw_deg]" (m, m, deg) -> pose (m, m, rad).
mrpt::math::TPose2D parseStart(const std::string& text) {
    const bool withYaw = std::count(text.begin(), text.end(), ',') == 2;
    const auto v = cli::parseNumberList(text, withYaw ? 3 : 2, "--start");
    return {v[0], v[1], withYaw ? mrpt::DEG2RAD(v[2]) : 0.0};
}

/// Defaults, then the .ini file, then explicit command-line options; validated.
SimulatorConfig configuration(Arguments& a) {
    SimulatorConfig config;
    if (a.configArg.isSet())
        loadSimulatorConfig(*toposlam::config::openIniFile(a.configArg.getValue()), config);
    LaserModel& laser = config.log.laser;
    if (a.beamsArg.isSet())
        laser.beams = a.beamsArg.getValue();
    if (a.fovArg.isSet())
        laser.aperture = mrpt::DEG2RAD(a.fovArg.getValue());
    if (a.maxRangeArg.isSet())
        laser.maxRange = a.maxRangeArg.getValue();
    if (a.rangeNoiseArg.isSet())
        laser.rangeNoiseStd = a.rangeNoiseArg.getValue();
    if (a.bearingNoiseArg.isSet())
        laser.bearingNoiseStd = mrpt::DEG2RAD(a.bearingNoiseArg.getValue());
    if (a.exactOdometryArg.isSet())
        config.log.odometry = OdometryErrorModel::exact();
    if (a.peopleArg.isSet())
        config.log.people.count = a.peopleArg.getValue();
    if (a.seedArg.isSet())
        config.log.seed = a.seedArg.getValue();
    if (a.formatArg.isSet())
        config.format = parseRawlogFormat(a.formatArg.getValue());
    if (a.startArg.isSet())
        config.tour.start = parseStart(a.startArg.getValue());
    if (a.mapArg.isSet() && a.mapReading.readAsDrawnPlan(a.mapArg.getValue()))
        config.log.world.thresholds = {io::kDrawnPlanFreeAbove, io::kDrawnPlanFreeAbove};
    validate(config);
    return config;
}

int makeOffice(Arguments& a, const SimulatorConfig& config, bool verbose) {
    if (a.mapArg.isSet() || a.posesArg.isSet() || a.tourArg.isSet() || a.outArg.isSet()) {
        throw cli::UsageError("--make-office takes no map, --poses, --tour or -o");
    }
    // Every file is checked before the work: none is written unless all can be.
    const cli::FileArgument folder{"--make-office", a.makeOfficeArg.getValue()};
    const auto files = cli::filesInFolder(folder, officeDatasetFileNames());
    cli::requireOutputsOfTheirOwn({{"-c", a.configArg.getValue()}}, files);
    cli::requireWritableOutputFolder(folder);
    if (std::filesystem::is_directory(folder.path))
        cli::requireWritableOutputFiles(files);
    io::ProgressDisplay progress("simulating office.rawlog", "scans", verbose && ::isatty(2) == 1);
    const OfficeDataset d = writeOfficeDataset(
        a.makeOfficeArg.getValue(), config,
        [&](double fraction, std::size_t scans) { progress.update(fraction, scans); });
    progress.finish();
    if (verbose) {
        std::printf("office: %zu scans, tour %.1f m in %.0f s, %zu of %zu rooms visited\n", d.scans,
                    d.tourLength, d.duration, d.roomsVisited, d.rooms);
        for (const auto& f : d.files)
            std::printf("  wrote %s\n", f.c_str());
    }
    return 0;
}

SimulationJob simulationJob(Arguments& a) {
    if (!a.mapArg.isSet())
        throw cli::UsageError("no map given");
    if (a.posesArg.isSet() == a.tourArg.isSet())
        throw cli::UsageError("give exactly one of --poses <file> and --tour");
    if (!a.outArg.isSet())
        throw cli::UsageError("no output rawlog given (-o <file>)");
    SimulationJob job;
    job.mapPath = a.mapArg.getValue();
    job.posesPath = a.posesArg.getValue();
    job.rawlogPath = a.outArg.getValue();
    job.groundTruthPath = a.gtArg.isSet() ? a.gtArg.getValue() : groundTruthPathFor(job.rawlogPath);
    job.plotPath = a.plotArg.getValue();
    cli::requireExtension({"-o", job.rawlogPath}, {".rawlog", ".rawlog.gz"});
    cli::requireExtension({"--plot", job.plotPath}, {".png"});
    std::vector<cli::FileArgument> inputs = cli::mapFilesRead({"", job.mapPath});
    inputs.push_back({"--poses", job.posesPath});
    inputs.push_back({"-c", a.configArg.getValue()});
    cli::requireOutputsOfTheirOwn(
        inputs, {{"-o", job.rawlogPath}, {"--gt", job.groundTruthPath}, {"--plot", job.plotPath}});
    job.imageGeometry = a.geometry.geometry();
    return job;
}

int simulate(Arguments& a, const SimulatorConfig& config, bool verbose) {
    const SimulationJob job = simulationJob(a);
    const SimulationPlan plan = planSimulation(config, job);
    if (plan.tour && verbose) {
        const Tour& t = *plan.tour;
        std::printf("tour: %zu room-sized areas (%zu unreachable), %.1f m, %.0f s, %zu scans\n",
                    t.areas.size() - t.outside.size(), t.unreachable.size(), t.length,
                    t.poses.back().stamp - t.poses.front().stamp, t.poses.size());
        if (!t.outside.empty()) {
            std::printf(
                "      %zu free areas open to the map's edge (around the building) left "
                "out\n",
                t.outside.size());
        }
        if (!t.unseen.empty()) {
            double area = 0;
            std::size_t viewpoints = 0;
            for (const UnseenArea& u : t.unseen) {
                area += u.areaM2;
                viewpoints += u.viewpoints.size();
            }
            std::printf(
                "      %zu areas (%.1f m^2) the room-sized tour left unseen; %zu stops "
                "added to look into them ([Tour] look_into_unseen), %zu more places to look "
                "from were already stops\n",
                t.unseen.size(), area, t.unseenStops, viewpoints - t.unseenStops);
        }
    }
    if (plan.tour && plan.tour->length < kShortestTour) {
        // Not an error (a one-room map), but rarely what was meant: say why and what helps.
        std::fflush(stdout);  // after the summary above
        std::fprintf(stderr,
                     "warning: the tour drives only %.1f m (%zu scans): the robot can reach no "
                     "room-sized area beyond its start%s\n",
                     plan.tour->length, plan.tour->poses.size(),
                     plan.tour->outside.empty()
                         ? ""
                         : "; the free space around it runs on to the map's edge and is left "
                           "out (a drawn plan whose grey background reads as free? try --drawn)");
    }
    if (plan.posesNotFree > 0) {
        std::fprintf(stderr, "warning: %zu of %zu poses are not in free cells of the map\n",
                     plan.posesNotFree, plan.poses.size());
    }
    io::ProgressDisplay progress(
        "simulating " + std::filesystem::path(job.rawlogPath).filename().string(), "scans",
        verbose && ::isatty(2) == 1);
    const std::size_t scans =
        runSimulation(plan, config, job,
                      [&](double fraction, std::size_t done) { progress.update(fraction, done); });
    progress.finish();
    if (verbose) {
        std::printf("wrote %s (%zu scans, format %s) and %s\n", job.rawlogPath.c_str(), scans,
                    config.format == io::RawlogFormat::Observations ? "obs" : "sf",
                    job.groundTruthPath.c_str());
    }
    return 0;
}

int run(int argc, char** argv) {
    Arguments a;
    if (const auto exitCode = cli::parseCommandLine(a.cmd, argc, argv))
        return *exitCode;
    const SimulatorConfig config = configuration(a);
    const bool verbose = !a.quietArg.getValue();
    return a.makeOfficeArg.isSet() ? makeOffice(a, config, verbose) : simulate(a, config, verbose);
}
}  // namespace

int main(int argc, char** argv) {
    return toposlam::cli::runReportingErrors(run, argc, argv);
}
