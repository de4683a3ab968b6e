// toposlam-annotate-features: a laser log with the features of every scan stored beside it,
// as a rawlog MRPT's tools read with the TopoSLAM plugin.
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/config/CConfigFile.h>
#include <toposlam/cli/CommandLine.h>
#include <toposlam/config/IniFile.h>
#include <toposlam/features/FeatureExtractor.h>
#include <toposlam/features/LogAnnotation.h>
#include <toposlam/io/ProgressDisplay.h>

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

namespace {

using namespace toposlam;

const char* const kDescription =
    "Extracts the features of every scan of a laser log and writes an MRPT rawlog "
    "(observations format) where each scan is followed by a "
    "toposlam::features::CObservationLaserFeatures holding its segments, corners and "
    "convex/concave/jump endpoints (sensor frame, label <scan label>_FEATURES), and, with "
    "--bearing-range, its corners as a CObservationBearingRange (label <scan label>_CORNERS; "
    "range, yaw and their covariance per corner, landmark id -1) for MRPT's landmark SLAM. The "
    "odometry of the log is kept (CObservationOdometry).\n"
    "The input is any log TopoSLAM reads: CARMEN (.clf/.log) or an MRPT rawlog of either format, "
    "gzip or not, detected from the content.\n"
    "MRPT's tools need the TopoSLAM plugin to read the output, e.g.\n"
    "  rawlog-edit -p /abs/path/libtoposlam-plugin.so -i out.rawlog --info\n"
    "  RawLogViewer -l /abs/path/libtoposlam-plugin.so out.rawlog\n"
    "Examples:\n"
    "  toposlam-annotate-features intel.clf -o intel_features.rawlog.gz\n"
    "  toposlam-annotate-features run.rawlog -o run_corners.rawlog -e corners --bearing-range\n"
    "  toposlam-annotate-features run.rawlog -o out.rawlog -c config_ini/features.ini\n"
    "Exit status: 0 on success; 1 with 'error: ...' on stderr for bad input or options; no "
    "output file is written unless the whole log is processed.";

int run(int argc, char** argv) {
    TCLAP::CmdLine cmd(kDescription, ' ', "0.1");
    TCLAP::UnlabeledValueArg<std::string> input(
        "input", "Input log: CARMEN or MRPT rawlog (either format, optionally gzip)", true, "",
        "log", cmd);
    TCLAP::ValueArg<std::string> output(
        "o", "output", "Output rawlog (.rawlog, or .rawlog.gz for gzip)", true, "", "file", cmd);
    std::vector<std::string> names = features::featureExtractorNames();
    TCLAP::ValuesConstraint<std::string> nameValues(names);
    TCLAP::ValueArg<std::string> extractor(
        "e", "extractor",
        "Feature extractor: corners = corner paper, robust variant, two-point fit; corners-ls = "
        "the same with least squares; corners-paper = the paper's rules as printed; segments = "
        "convex/concave endpoints and segments of the graph-matching paper; segments-paper = "
        "the same with the paper's 4-tap turning sum; split-merge = classic IEPF. Default: "
        "corners",
        false, "corners", &nameValues, cmd);
    TCLAP::ValueArg<std::string> config(
        "c", "config",
        "An .ini file with the extractor's options (see config_ini/features.ini); the presets "
        "corners-ls, corners-paper and segments-paper override its line_fit / paper_exact. "
        "Default: the papers' parameters",
        false, "", "file.ini", cmd);
    TCLAP::ValueArg<std::string> section(
        "", "section",
        "Section of the .ini file; it must be there. Default: the extractor's (CornerExtractor, "
        "SegmentExtractor, SplitAndMergeExtractor)",
        false, "", "name", cmd);
    TCLAP::SwitchArg bearingRange(
        "", "bearing-range", "Also write each scan's corners as a CObservationBearingRange", cmd);
    TCLAP::ValueArg<std::string> label(
        "", "label", "Only scans with this sensor label. Default: all 2D laser scans", false, "",
        "label", cmd);
    TCLAP::ValueArg<double> maxRange(
        "", "carmen-max-range",
        "CARMEN: maximum range in m when no PARAM line gives one; readings at or beyond it are "
        "invalid. Default: 81",
        false, 81.0, "m", cmd);
    TCLAP::ValueArg<std::size_t> maxScans(
        "", "max-scans", "Process only the first N scans. Default: 0 = all", false, 0, "N", cmd);
    TCLAP::SwitchArg printOptions("", "print-options",
                                  "Print the extractor's options (as .ini lines) and exit", cmd);
    TCLAP::SwitchArg quiet("q", "quiet", "No progress display and no summary", cmd);
    if (const auto exitCode = cli::parseCommandLine(cmd, argc, argv))
        return *exitCode;

    std::unique_ptr<mrpt::config::CConfigFile> ini;
    if (config.isSet()) {
        ini = toposlam::config::openIniFile(config.getValue());
        toposlam::config::requireSection(
            *ini, section.isSet() ? section.getValue()
                                  : features::defaultConfigSection(extractor.getValue()));
    } else if (section.isSet()) {
        throw std::invalid_argument("--section: no -c file to read it from");
    }
    auto ex = features::makeFeatureExtractor(extractor.getValue(), ini.get(), section.getValue());
    if (printOptions.getValue()) {
        std::cout << "[" << features::defaultConfigSection(ex->name()) << "]\n";
        ex->dumpOptions(std::cout);
        return EXIT_SUCCESS;
    }

    features::LogAnnotationOptions options;
    options.read.scanLabel = label.getValue();
    options.read.carmenDefaultMaxRange = static_cast<float>(maxRange.getValue());
    options.bearingRange = bearingRange.getValue();
    options.maxScans = maxScans.getValue();
    io::ProgressDisplay progress(
        "annotating " + std::filesystem::path(input.getValue()).filename().string(), "scans",
        !quiet.getValue() && ::isatty(2) == 1);
    options.progress = [&](double fraction, std::size_t scans) {
        progress.update(fraction, scans);
    };
    const auto s = features::annotateLog(input.getValue(), output.getValue(), *ex, options);
    progress.finish();
    if (!quiet.getValue()) {
        const double n = static_cast<double>(s.scans);
        std::printf(
            "%s: %zu scans (%s); %s: %.1f segments, %.1f corners, %.1f endpoints per scan, "
            "%.1f us per scan\nwrote %s (%zu objects)\n",
            input.getValue().c_str(), s.scans, io::toString(s.inputFormat), ex->name().c_str(),
            s.segments / n, s.corners / n, s.endpoints / n, 1e6 * s.extractionSeconds / n,
            output.getValue().c_str(), s.objects);
    }
    return EXIT_SUCCESS;
}

}  // namespace

int main(int argc, char** argv) {
    return toposlam::cli::runReportingErrors(run, argc, argv);
}
