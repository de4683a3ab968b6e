// toposlam-annotate-features: a laser log with the features of every scan stored beside it,
// as a rawlog MRPT's tools read with the TopoSLAM plugin.
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/config/CConfigFile.h>
#include <toposlam/cli/CommandLine.h>
#include <toposlam/cli/NumberArg.h>
#include <toposlam/config/IniFile.h>
#include <toposlam/features/FeatureExtractor.h>
#include <toposlam/features/LogAnnotation.h>
#include <toposlam/io/AtomicFile.h>
#include <toposlam/io/InputError.h>
#include <toposlam/io/ProgressDisplay.h>
#include <toposlam/io/Trajectory.h>
#include <toposlam/matching/CScanFeaturesMap.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace toposlam;

const char* const kDescription =
    "Extracts the features of every scan of a laser log and writes an MRPT rawlog where each "
    "scan comes with a toposlam::features::CObservationLaserFeatures holding its segments, "
    "corners and convex/concave/jump endpoints (sensor frame, label <scan label>_FEATURES) "
    "and, with --bearing-range, its corners as a CObservationBearingRange (label <scan "
    "label>_CORNERS; range, yaw and their covariance per corner, landmark id -1) for MRPT's "
    "landmark SLAM.\n"
    "--format obs (default): observations format, the log's odometry kept as "
    "CObservationOdometry. --format sf: actions + sensory frames, what MRPT's kf-slam and "
    "rbpf-slam read: per scan a CActionRobotMovement2D (the odometry increment, with the "
    "Gaussian noise of --odometry-noise) and a sensory frame {scan, features, corners}; the "
    "corners are always written in this format.\n"
    "The input is any log TopoSLAM reads: CARMEN (.clf/.log) or an MRPT rawlog of either format, "
    "gzip or not, detected from the content.\n"
    "MRPT's tools need the TopoSLAM plugin to read the output, e.g.\n"
    "  rawlog-edit -p /abs/path/libtoposlam-plugin.so -i out.rawlog --info\n"
    "  RawLogViewer -l /abs/path/libtoposlam-plugin.so out.rawlog\n"
    "Examples:\n"
    "  toposlam-annotate-features intel.clf -o intel_features.rawlog.gz\n"
    "  toposlam-annotate-features run.rawlog -o run_corners.rawlog -e corners --bearing-range\n"
    "  toposlam-annotate-features run.rawlog -o out.rawlog -c config_ini/features.ini\n"
    "  toposlam-annotate-features share/office/office.rawlog -o corners_sf.rawlog --format sf\n"
    "  kf-slam config_ini/kf-slam-corners.ini corners_sf.rawlog </dev/null\n"
    "Exit status: 0 on success; 1 with 'error: ...' on stderr for bad input; 2 for a bad option "
    "value; no output file is written unless the whole log is processed.";

io::RawlogFormat parseFormat(const std::string& text) {
    if (text == "obs")
        return io::RawlogFormat::Observations;
    if (text == "sf")
        return io::RawlogFormat::SensoryFrames;
    throw cli::UsageError("--format: '" + text + "' is not obs or sf");
}

features::MotionNoise parseMotionNoise(const std::string& text) {
    std::vector<double> v;
    try {
        v = cli::parseNumberList(text, 6, "--odometry-noise");
    } catch (const std::invalid_argument& e) {
        throw cli::UsageError(e.what());
    }
    features::MotionNoise n{v[0], v[1], v[2], v[3], v[4], v[5]};
    try {
        n.validate();
    } catch (const std::invalid_argument& e) {
        throw cli::UsageError(std::string("--odometry-noise: ") + e.what());
    }
    return n;
}

/// --feature-map: the map of the log's features at the poses of --poses, built on the way.
struct FeatureMapRequest {
    std::string prefix, posesFile;
    io::Trajectory2D poses;
    matching::CScanFeaturesMap map;
    std::size_t scans = 0;
    double cpuSeconds = 0;  ///< spent inserting

    void attachTo(features::LogAnnotationOptions& options) {
        options.onScan = [this](const io::LaserLogRecord& r, const features::ScanFeatures& f) {
            if (scans >= poses.size())
                throw io::InputError(posesFile, "fewer poses (" + std::to_string(poses.size()) +
                                                    ") than scans in the log");
            const io::TimedPose2D& p = poses[scans++];
            if (std::abs(p.stamp - r.fileStamp) > 1e-3) {
                throw io::InputError(posesFile, "pose " + std::to_string(scans - 1) +
                                                    " is stamped " + std::to_string(p.stamp) +
                                                    ", its scan " + std::to_string(r.fileStamp) +
                                                    ": not a trajectory of this log");
            }
            const std::clock_t start = std::clock();
            map.insertKeyframe(
                {mrpt::poses::CPose2D(p.pose), mrpt::poses::CPose2D(r.scan->sensorPose), f});
            cpuSeconds += static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
        };
    }

    /// What CScanFeaturesMap::saveMetricMapRepresentationToFile(prefix) writes.
    static std::vector<std::string> files(const std::string& prefix) {
        return {prefix + ".png", prefix + "_segments.txt", prefix + "_corners.txt",
                prefix + "_endpoints.txt"};
    }

    void report() const {
        const matching::FeatureMap& m = map.featureMap();
        std::printf(
            "feature map: %zu keyframes; %zu wall segments (on %zu lines), %zu corners, %zu "
            "endpoints confirmed; "
            "insertion %.1f us CPU per keyframe\nwrote %s.png and %s_{segments,corners,"
            "endpoints}.txt\n",
            scans, m.confirmedPieces(), m.confirmedSegments(), m.confirmedCorners(),
            m.confirmedEndpoints(),
            1e6 * cpuSeconds / static_cast<double>(std::max<std::size_t>(1, scans)), prefix.c_str(),
            prefix.c_str());
    }
};

/// Runs the annotation with the parsed options and prints the summary.
int annotate(const std::string& input, const std::string& output, features::FeatureExtractor& ex,
             features::LogAnnotationOptions& options, FeatureMapRequest* featureMap, bool quiet) {
    io::ProgressDisplay progress("annotating " + std::filesystem::path(input).filename().string(),
                                 "scans", !quiet && ::isatty(2) == 1);
    options.progress = [&](double fraction, std::size_t scans) {
        progress.update(fraction, scans);
    };
    io::OutputGroup outputs;  // the rawlog and the feature map's files, or none of them
    const auto s = features::annotateLog(input, output, ex, options);
    progress.finish();
    if (featureMap)
        featureMap->map.saveMetricMapRepresentationToFile(featureMap->prefix);
    outputs.commit();
    if (!quiet) {
        const double n = static_cast<double>(s.scans);
        std::printf(
            "%s: %zu scans (%s); %s: %.1f segments, %.1f corners, %.1f endpoints per scan, "
            "%.1f us per scan\ncorner noise (RMS of the corners' own): range %.4f m, bearing "
            "%.3f deg\nwrote %s (%s format, %zu objects)\n",
            input.c_str(), s.scans, io::toString(s.inputFormat), ex.name().c_str(), s.segments / n,
            s.corners / n, s.endpoints / n, 1e6 * s.extractionSeconds / n, s.cornerRangeStd,
            s.cornerBearingStd * 180 / M_PI, output.c_str(), io::toString(options.format),
            s.objects);
    }
    if (featureMap && !quiet)
        featureMap->report();
    return EXIT_SUCCESS;
}

/// The command line: every option, registered with `cmd` in declaration order.
struct Arguments {
    TCLAP::CmdLine cmd{kDescription, ' ', "0.1"};
    std::vector<std::string> extractorNameList = features::featureExtractorNames();
    TCLAP::ValuesConstraint<std::string> extractorNames{extractorNameList};
    TCLAP::UnlabeledValueArg<std::string> input{
        "input", "Input log: CARMEN or MRPT rawlog (either format, optionally gzip)",
        true,    "",
        "log",   cmd};
    TCLAP::ValueArg<std::string> output{
        "o", "output", "Output rawlog (.rawlog, or .rawlog.gz for gzip)", true, "", "file", cmd};
    TCLAP::ValueArg<std::string> extractor{
        "e",
        "extractor",
        "Feature extractor: corners = corner paper, robust variant, two-point fit; corners-ls = "
        "the same with least squares; corners-paper = the paper's rules as printed; segments = "
        "convex/concave endpoints and segments of the graph-matching paper; segments-paper = "
        "the same with the paper's 4-tap turning sum; split-merge = classic IEPF. Default: "
        "corners",
        false,
        "corners",
        &extractorNames,
        cmd};
    TCLAP::ValueArg<std::string> config{
        "c",
        "config",
        "An .ini file with the extractor's options (see config_ini/features.ini); the presets "
        "corners-ls, corners-paper and segments-paper override its line_fit / paper_exact. "
        "Default: the papers' parameters",
        false,
        "",
        "file.ini",
        cmd};
    TCLAP::ValueArg<std::string> section{
        "",
        "section",
        "Section of the .ini file; it must be there. Default: the extractor's (CornerExtractor, "
        "SegmentExtractor, SplitAndMergeExtractor)",
        false,
        "",
        "name",
        cmd};
    TCLAP::SwitchArg bearingRange{"", "bearing-range",
                                  "Also write each scan's corners as a CObservationBearingRange "
                                  "(always done with --format sf)",
                                  cmd};
    TCLAP::ValueArg<std::string> format{
        "",
        "format",
        "Output rawlog format: obs = observations (odometry as CObservationOdometry); sf = "
        "actions + sensory frames (odometry increments as CActionRobotMovement2D), for kf-slam "
        "and rbpf-slam. Default: obs",
        false,
        "obs",
        "obs|sf",
        cmd};
    TCLAP::ValueArg<std::string> odometryNoise{
        "",
        "odometry-noise",
        "--format sf: noise of each odometry increment of length d (m) and turn a (deg), MRPT's "
        "Gaussian motion model: std(x), std(y) = minXY + a1*d + a2*a (m); std(yaw) = minPhi + "
        "a3*d + a4*a (deg). Given as a1,a2,a3,a4,minXY,minPhi in m/m, m/deg, deg/m, deg/deg, m, "
        "deg. Default: MRPT's, 0.01,0.001,1,0.05,0.01,0.2",
        false,
        "0.01,0.001,1,0.05,0.01,0.2",
        "a1,a2,a3,a4,minXY,minPhi",
        cmd};
    TCLAP::ValueArg<std::string> label{
        "",    "label", "Only scans with this sensor label. Default: all 2D laser scans",
        false, "",      "label",
        cmd};
    cli::NumberArg<double> maxRange{
        "",
        "carmen-max-range",
        "CARMEN: maximum range in m when no PARAM line gives one; readings at or beyond it are "
        "invalid. Default: 81",
        81.0,
        cli::NumberRange<double>::positive(1000),
        "m",
        cmd};
    cli::NumberArg<std::size_t> maxScans{"",
                                         "max-scans",
                                         "Process only the first N scans. Default: 0 = all",
                                         0,
                                         cli::NumberRange<std::size_t>::nonNegative(1000000000),
                                         "N",
                                         cmd};
    TCLAP::ValueArg<std::string> featureMap{
        "",
        "feature-map",
        "Also build the feature map of the log (libs/matching CScanFeaturesMap: every scan's "
        "segments, corners and endpoints at its pose of --poses, repeated observations merged) "
        "and write <prefix>.png and <prefix>_segments.txt, _corners.txt, _endpoints.txt",
        false,
        "",
        "prefix",
        cmd};
    TCLAP::ValueArg<std::string> poses{
        "",
        "poses",
        "With --feature-map: the robot pose of every scan, one 'timestamp x y yaw' line per scan "
        "in log order with the scan's own stamp (toposlam-slam's trajectory.txt, a simulated "
        "log's ground truth)",
        false,
        "",
        "trajectory.txt",
        cmd};
    TCLAP::SwitchArg printOptions{"", "print-options",
                                  "Print the extractor's options (as .ini lines) and exit", cmd};
    TCLAP::SwitchArg quiet{"q", "quiet", "No progress display and no summary", cmd};
};

int run(int argc, char** argv) {
    Arguments a;
    if (const auto exitCode = cli::parseCommandLine(a.cmd, argc, argv))
        return *exitCode;
    cli::requireExtension({"-o", a.output.getValue()}, {".rawlog", ".rawlog.gz"});
    std::vector<cli::FileArgument> outputs = {{"-o", a.output.getValue()}};
    if (a.featureMap.isSet() && !a.featureMap.getValue().empty()) {
        for (const std::string& file : FeatureMapRequest::files(a.featureMap.getValue()))
            outputs.push_back(
                {"", file, "written with --feature-map '" + a.featureMap.getValue() + "'"});
    }
    cli::requireOutputsOfTheirOwn({{"", a.input.getValue()},
                                   {"--config", a.config.getValue()},
                                   {"--poses", a.poses.getValue()}},
                                  outputs);

    std::unique_ptr<mrpt::config::CConfigFile> ini;
    if (a.config.isSet()) {
        ini = toposlam::config::openIniFile(a.config.getValue());
        toposlam::config::requireSection(
            *ini, a.section.isSet() ? a.section.getValue()
                                    : features::defaultConfigSection(a.extractor.getValue()));
    } else if (a.section.isSet()) {
        throw cli::UsageError("--section: no -c file to read it from");
    }
    auto ex =
        features::makeFeatureExtractor(a.extractor.getValue(), ini.get(), a.section.getValue());
    if (a.printOptions.getValue()) {
        std::cout << "[" << features::defaultConfigSection(ex->name()) << "]\n";
        ex->dumpOptions(std::cout);
        return EXIT_SUCCESS;
    }

    features::LogAnnotationOptions options;
    options.read.scanLabel = a.label.getValue();
    options.read.carmenDefaultMaxRange = static_cast<float>(a.maxRange.getValue());
    options.bearingRange = a.bearingRange.getValue();
    options.maxScans = a.maxScans.getValue();
    options.format = parseFormat(a.format.getValue());  // cli::UsageError: exit status 2
    options.motionNoise = parseMotionNoise(a.odometryNoise.getValue());
    if (a.featureMap.isSet() != a.poses.isSet() ||
        (a.featureMap.isSet() && a.featureMap.getValue().empty()))
        throw cli::UsageError(
            "--feature-map and --poses go together (a prefix and a trajectory file)");
    std::unique_ptr<FeatureMapRequest> map;
    if (a.featureMap.isSet()) {
        map = std::make_unique<FeatureMapRequest>();
        map->prefix = a.featureMap.getValue();
        map->posesFile = a.poses.getValue();
        map->poses = io::loadTrajectory(a.poses.getValue());
        map->attachTo(options);
    }
    cli::requireWritableOutputFiles(outputs);  // before the work, not after it
    return annotate(a.input.getValue(), a.output.getValue(), *ex, options, map.get(),
                    a.quiet.getValue());
}

}  // namespace

int main(int argc, char** argv) {
    return toposlam::cli::runReportingErrors(run, argc, argv);
}
