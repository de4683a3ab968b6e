// toposlam-eval-slam: scores SLAM trajectories with the relation metric of Kümmerle et al. 2009
// (benchmark B3), against a .relations file or a ground-truth trajectory, several methods side
// by side in one table, optionally as JSON and as a picture.
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <toposlam/cli/CommandLine.h>
#include <toposlam/cli/NumberArg.h>
#include <toposlam/evaluation/SlamEvaluationRun.h>
#include <toposlam/io/ProgressDisplay.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace {

using namespace toposlam;

const char* const kDescription =
    "Scores 2D SLAM trajectories with the relation-based metric of Kuemmerle et al. 2009 (\"On "
    "measuring the accuracy of SLAM algorithms\"; TopoSLAM benchmark B3). For every relation "
    "(t1, t2, delta_gt) the error is e = inv(delta_gt) (+) delta_est with delta_est = inv(x_t1) "
    "(+) x_t2, x_t the trajectory's pose at stamp t. Printed per method: relations matched / "
    "total, mean +- std (sample std) of |translation(e)| in m and |rotation(e)| in deg, the same "
    "for the squared errors (m^2, deg^2), and the maxima. Relations whose stamps are not in a "
    "trajectory (within --stamp-tolerance) are left out and counted as unmatched.\n"
    "With --ground-truth, relations are derived from the true trajectory (every consecutive "
    "pose pair + pairs separated by d, 2d, 4d ... metres of travelled path, d = "
    "--gt-separation, start poses d/2 apart) and the absolute trajectory error after the best "
    "rigid 2D alignment (ATE RMSE, max) is added.\n"
    "Methods (table rows, in this order): --odometry-of (a log's raw odometry at each scan), "
    "trajectory files (positional or --trajectory), --icp-slam-path. Trajectory files: one "
    "pose per line 'timestamp x y yaw' (s, m, m, rad; '#' comments), the timestamps being the "
    "scans' stamps as the log prints them. MRPT icp-slam's log_estimated_path.txt ('step x y "
    "yaw', one line per rawlog entry, no stamps) needs --rawlog: the scans of the rawlog "
    "icp-slam ran on give the lines their stamps, or, with --scan-stamps, the scans of the log "
    "that rawlog was converted from.\n"
    "Examples:\n"
    "  toposlam-eval-slam --odometry-of intel.clf --relations intel.relations\n"
    "  toposlam-eval-slam --odometry-of intel.clf --trajectory toposlam=slam.txt "
    "--icp-slam-path icp-out/log_estimated_path.txt --rawlog intel.rawlog --scan-stamps "
    "intel.clf --relations intel.relations --json intel-b3.json --plot intel-b3.png\n"
    "  toposlam-eval-slam slam.txt --ground-truth office_gt.txt --json office.json\n"
    "Exit status: 0 on success; 1 with 'error: ...' on stderr for bad input (missing or "
    "malformed files, non-finite poses, a trajectory that matches none of the relations); 2 "
    "for bad usage (unknown options, values out of range, options that do not go together). "
    "Output files are written atomically, and only on success.";

// Scores, prints the table, writes the outputs.
int evaluate(const evaluation::SlamEvaluationRequest& request,
             const evaluation::SlamEvaluationOutputs& outputs) {
    try {
        request.validate();
    } catch (const std::invalid_argument& e) {
        throw cli::UsageError(e.what());
    }
    io::ProgressDisplay progress("reading logs", "scans");
    const auto run = evaluation::runSlamEvaluation(
        request, [&](double fraction, std::size_t scans) { progress.update(fraction, scans); });
    progress.finish();
    std::cout << evaluation::formatEvaluationTable(run.evaluation);
    evaluation::saveSlamEvaluationOutputs(run, outputs);
    return EXIT_SUCCESS;
}

int run(int argc, char** argv) {
    TCLAP::CmdLine cmd(kDescription, ' ', "0.1");
    TCLAP::UnlabeledMultiArg<std::string> positional(
        "trajectories",
        "Trajectory file(s) 'timestamp x y yaw' to score; labelled by --name or by the file "
        "name",
        false, "trajectory.txt", cmd);
    TCLAP::MultiArg<std::string> trajectories(
        "", "trajectory",
        "A trajectory file to score, labelled: [label=]file (repeatable; the label names the "
        "table row, default: the file name without extension)",
        false, "[label=]file", cmd);
    TCLAP::MultiArg<std::string> odometryOf(
        "", "odometry-of",
        "Score the raw wheel odometry of this laser log (CARMEN .clf/.log or rawlog) at each "
        "scan, stamped with the scans' file stamps: the odometry-only baseline. [label=]log, "
        "default label 'odometry' (repeatable)",
        false, "[label=]log", cmd);
    TCLAP::MultiArg<std::string> icpSlamPaths(
        "", "icp-slam-path",
        "MRPT icp-slam's log_estimated_path.txt to score (needs --rawlog): [label=]file, "
        "default label 'icp-slam' (repeatable, e.g. for several configurations on one rawlog)",
        false, "[label=]file", cmd);
    TCLAP::ValueArg<std::string> rawlog(
        "", "rawlog",
        "The rawlog icp-slam ran on: its scan entries give the --icp-slam-path lines their "
        "stamps (MRPT timestamps as Unix seconds)",
        false, "", "log.rawlog", cmd);
    TCLAP::ValueArg<std::string> scanStamps(
        "", "scan-stamps",
        "The log --rawlog was converted from (e.g. the CARMEN .clf): the file stamps of its "
        "scans, in order, replace the rawlog's scan stamps, one per scan. Needed where a "
        "converter made the stamps increasing (intel), since relation files use the stamps as "
        "printed",
        false, "", "log", cmd);
    TCLAP::ValueArg<std::string> name("", "name", "Label of the (single) positional trajectory",
                                      false, "", "label", cmd);
    TCLAP::ValueArg<std::string> relationsFile(
        "", "relations",
        "Ground-truth relations, Kuemmerle benchmark format 't1 t2 x y z roll pitch yaw'", true, "",
        "file.relations");
    TCLAP::ValueArg<std::string> groundTruthFile(
        "", "ground-truth",
        "Ground-truth trajectory 'timestamp x y yaw' (e.g. of a simulated log): relations are "
        "derived from it, and the ATE is reported",
        true, "", "gt.txt");
    cmd.xorAdd(relationsFile, groundTruthFile);
    cli::NumberArg<double> separation(
        "", "gt-separation",
        "With --ground-truth: shortest path separation d (m) of the multi-scale relations (d, "
        "2d, 4d, ... up to the path length); 0 keeps only consecutive pairs. Default 1 m",
        1.0, cli::NumberRange<double>::nonNegative(1e6), "metres", cmd);
    cli::NumberArg<double> tolerance(
        "", "stamp-tolerance",
        "Largest stamp difference (s) at which a relation or ground-truth stamp matches a "
        "trajectory pose (nearest one wins). Default 1e-5 s",
        evaluation::StampedPoseLookup::kDefaultTolerance,
        cli::NumberRange<double>::nonNegative(3600), "seconds", cmd);
    TCLAP::ValueArg<std::string> mountingFrom(
        "", "mounting-from",
        "Also estimate where each trajectory's poses sit on the robot (x, y, yaw of the mounting, "
        "and the odometry's scale) from this log's odometry: planar hand-eye calibration over "
        "pairs of poses 5 apart that turn by 3 deg or more. The odometry's own frame gives 0, "
        "0, 0; a SLAM trajectory of laser poses gives the laser's mounting, e.g. to check "
        "--frame-offset or toposlam-convert --laser-offset",
        false, "", "log", cmd);
    TCLAP::ValueArg<std::string> laserFrameOf(
        "", "laser-frame-of",
        "Score the laser's poses: move each pose to where this log's scan of the same stamp puts "
        "the laser on the robot (a CARMEN ROBOTLASER line's laser pose, a rawlog scan's "
        "sensorPose). Kuemmerle et al.'s relations are made in the laser's frame; trajectories "
        "of toposlam-slam and icp-slam give the robot's. Changes nothing where the laser sits at "
        "the robot's centre (FLASER logs)",
        false, "", "log", cmd);
    cli::NumberArg<double> frameOffset(
        "", "frame-offset",
        "Score the frame this many metres ahead of each estimated pose (along its heading; "
        "negative: behind), for relations made in another frame on the robot than the "
        "trajectories give, e.g. a laser mounted ahead of the robot's centre. Default 0",
        0.0, cli::NumberRange<double>::closed(-10, 10), "metres", cmd);
    TCLAP::SwitchArg mirroredReference(
        "", "mirrored-reference",
        "The trajectories are of a log's mirror image (toposlam-convert --mirror): score them "
        "against the mirror image of the relations or ground truth given",
        cmd);
    cli::NumberArg<int> worst(
        "", "worst",
        "After the tables, list each method's N relations with the largest translational error: "
        "stamps, the reference's and the method's motion, the error, and every other method's "
        "error on that relation (all methods off: a doubtful reference; only this one: its "
        "failure). Default 0 (none)",
        0, cli::NumberRange<int>::closed(0, 1000000), "N", cmd);
    TCLAP::ValueArg<std::string> writeRelations(
        "", "write-relations",
        "Also write the relations used (with --ground-truth: the derived ones) in .relations "
        "format, e.g. to score other tools against the same set",
        false, "", "out.relations", cmd);
    TCLAP::ValueArg<std::string> plot(
        "", "plot",
        "Also draw every trajectory into this PNG, rigidly aligned to the ground truth (drawn "
        "too) or else to the method with the lowest mean translational error",
        false, "", "out.png", cmd);
    TCLAP::ValueArg<std::string> json(
        "", "json", "Write the results as JSON to this file (keys: see share/doc/apps.md)", false,
        "", "out.json", cmd);
    if (const auto exitCode = cli::parseCommandLine(cmd, argc, argv))
        return *exitCode;

    using evaluation::TrajectorySource;
    evaluation::SlamEvaluationRequest request;
    const auto add = [&](TrajectorySource source, const std::vector<std::string>& specs,
                         const std::string& defaultName) {
        for (const auto& spec : specs) {
            request.trajectories.push_back(
                evaluation::trajectoryToScore(source, spec, defaultName));
        }
    };
    if (name.isSet() && positional.getValue().size() != 1)
        throw cli::UsageError("--name labels a single positional trajectory");
    add(TrajectorySource::LogOdometry, odometryOf.getValue(), "odometry");
    add(TrajectorySource::TrajectoryFile, positional.getValue(), name.getValue());
    add(TrajectorySource::TrajectoryFile, trajectories.getValue(), "");
    add(TrajectorySource::IcpSlamPath, icpSlamPaths.getValue(), "icp-slam");
    evaluation::nameRowsApart(request.trajectories);
    request.relationsFile = relationsFile.getValue();
    request.groundTruthFile = groundTruthFile.getValue();
    request.groundTruthSeparation = separation.getValue();
    request.stampTolerance = tolerance.getValue();
    request.frameOffset = frameOffset.getValue();
    request.mountingLog = mountingFrom.getValue();
    request.laserFrameLog = laserFrameOf.getValue();
    request.mirrorReference = mirroredReference.getValue();
    request.worstRelations = static_cast<std::size_t>(worst.getValue());
    request.rawlog = rawlog.getValue();
    request.scanStamps = scanStamps.getValue();
    request.keepEstimates = plot.isSet();
    cli::requireExtension({"--plot", plot.getValue()}, {".png"});
    std::vector<cli::FileArgument> inputs = {{"--relations", request.relationsFile},
                                             {"--ground-truth", request.groundTruthFile},
                                             {"--mounting-from", request.mountingLog},
                                             {"--laser-frame-of", request.laserFrameLog},
                                             {"--rawlog", request.rawlog},
                                             {"--scan-stamps", request.scanStamps}};
    for (const auto& t : request.trajectories)
        inputs.push_back({"", t.file});
    const std::vector<cli::FileArgument> outputs = {
        {"--write-relations", writeRelations.getValue()},
        {"--plot", plot.getValue()},
        {"--json", json.getValue()}};
    cli::requireOutputsOfTheirOwn(inputs, outputs);
    cli::requireWritableOutputFiles(outputs);  // before the scoring, not after its tables
    return evaluate(request, {writeRelations.getValue(), plot.getValue(), json.getValue()});
}

}  // namespace

int main(int argc, char** argv) {
    return toposlam::cli::runReportingErrors(run, argc, argv);
}
