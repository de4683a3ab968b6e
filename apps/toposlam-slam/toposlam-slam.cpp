// toposlam-slam: laser SLAM over a robot log, run like MRPT's icp-slam:
//   toposlam-slam <config.ini> <log.{rawlog,clf}> [-o outdir]
// The algorithm lives in libs/mapping (mapLog, GraphSlamInput); this app parses the
// command line, shows progress and writes the outputs.
#include <toposlam/classes/TopoSlamClasses.h>
#include <toposlam/cli/CommandLine.h>
#include <toposlam/config/IniFile.h>
#include <toposlam/io/ProgressDisplay.h>
#include <toposlam/mapping/LogMapper.h>
#include <toposlam/mapping/MappingOutputs.h>

#include <cstdio>
#include <filesystem>

namespace fs = std::filesystem;

namespace {

int run(int argc, char** argv) {
    TCLAP::CmdLine cmd(
        "Laser SLAM over a robot log (MRPT rawlog in either format, or CARMEN log). The default "
        "engine is TopoSLAM's graph SLAM: scans registered against local submaps by "
        "point-to-line ICP, the graph matcher where that fails, keyframes with corner "
        "features, loop closure verified by the graph matcher, pose graph optimised by Ceres "
        "with a robust loss on loop edges. '[Slam] engine = icp' runs MRPT's icp-slam engine "
        "instead (configured by icp-slam's [MappingApplication] and [ICP] keys). One laser "
        "is mapped: '[Slam] scan_label' names it (default auto: the log's only laser, or its "
        "front one; the other lasers' scans are counted in the summary). See "
        "config_ini/toposlam-slam.ini for every key. Writes into <outdir>: trajectory.txt "
        "(timestamp x y yaw per scan, stamps as in the log), map.gridmap.gz, map.png + "
        "map.yaml, keyframes.graph (MRPT .graph), keyframes.simplemap (scans + features), "
        "summary.txt and summary.json.",
        ' ', "0.2.0");
    TCLAP::UnlabeledValueArg<std::string> configArg("config", "configuration .ini file", true, "",
                                                    "config.ini", cmd);
    TCLAP::UnlabeledValueArg<std::string> logArg(
        "log", "laser + odometry log: .rawlog (plain or gz) or CARMEN .clf/.log", true, "", "log",
        cmd);
    TCLAP::ValueArg<std::string> outArg("o", "out", "output directory (created; default slam-out)",
                                        false, "slam-out", "dir", cmd);
    if (const auto exitCode = toposlam::cli::parseCommandLine(cmd, argc, argv))
        return *exitCode;
    toposlam::cli::requireOutputsOfTheirOwn(
        {{"", configArg.getValue()}, {"", logArg.getValue()}},
        toposlam::cli::filesInFolder({"-o", outArg.getValue()},
                                     toposlam::mapping::mappingOutputFileNames()));
    toposlam::classes::registerTopoSlamClasses();  // logs may hold TopoSLAM's objects
    toposlam::cli::requireWritableOutputFolder(
        {"-o", outArg.getValue()});  // before the run, not after

    // A file that is no .ini file at all is an error here, not defaults (config/IniFile.h).
    const auto ini = toposlam::config::openIniFile(configArg.getValue());
    toposlam::io::ProgressDisplay progress(
        "mapping " + fs::path(logArg.getValue()).filename().string(), "scans");
    const toposlam::mapping::MappingResult result = toposlam::mapping::mapLog(
        logArg.getValue(), *ini,
        [&](double fraction, std::size_t scans) { progress.update(fraction, scans); });
    progress.finish();

    const auto files = toposlam::mapping::saveMappingOutputs(result, outArg.getValue());
    const std::string summary = toposlam::mapping::formatSummary(result);
    std::fputs(summary.c_str(), stdout);
    if (toposlam::mapping::mostlyUnregistered(result) || toposlam::mapping::weakFrontEnd(result) ||
        toposlam::mapping::openLoopAtEnd(result))
        std::fputs(("\n*** " + summary.substr(summary.find("WARNING")) + "\n").c_str(), stderr);
    for (const std::string& f : files)
        std::printf("wrote %s\n", f.c_str());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return toposlam::cli::runReportingErrors(run, argc, argv);
}
