#pragma once
// One toposlam-eval-slam run: which trajectories to score (files, a log's odometry, icp-slam
// paths) against which reference (a relation file or a ground-truth trajectory), read and
// scored before anything is written; then the requested outputs. Libraries report progress
// through the callback only; the app draws it.
#include <toposlam/evaluation/SlamEvaluation.h>
#include <toposlam/io/ProgressCallback.h>

#include <optional>
#include <string>
#include <vector>

namespace toposlam::evaluation {

/// Where a trajectory to score comes from.
enum class TrajectorySource {
    LogOdometry,     ///< a laser log's raw odometry at each scan (LogOdometry.h)
    TrajectoryFile,  ///< 'timestamp x y yaw' lines (io::loadTrajectory)
    IcpSlamPath,     ///< MRPT icp-slam's log_estimated_path.txt, stamped by a rawlog
};

struct TrajectoryToScore {
    TrajectorySource source = TrajectorySource::TrajectoryFile;
    std::string name;  ///< the table row
    std::string file;
};

/// "label=path" -> {label, path}; a plain path is labelled `defaultName`, or when that is empty
/// by the file name without extension.
TrajectoryToScore trajectoryToScore(TrajectorySource source, const std::string& spec,
                                    const std::string& defaultName);

/// Rows that would share a name are told apart by their files: a name taken from the file
/// name becomes the shortest tail of the path that no other of those rows has ("run1/trajectory"
/// and "run2/trajectory" for two toposlam-slam outputs); a name given by the user keeps it,
/// followed by that tail in parentheses. The same file given twice is numbered.
void nameRowsApart(std::vector<TrajectoryToScore>& rows);

struct SlamEvaluationRequest {
    std::vector<TrajectoryToScore> trajectories;  ///< table rows, in order
    /// The reference: exactly one of a relation file and a ground-truth trajectory.
    std::string relationsFile;
    std::string groundTruthFile;
    /// Ground truth: path separation d (m) of the derived multi-scale relations; 0 = only
    /// consecutive pairs.
    double groundTruthSeparation = 1.0;
    double stampTolerance = StampedPoseLookup::kDefaultTolerance;  ///< s
    std::string rawlog;          ///< the rawlog icp-slam ran on (needed by IcpSlamPath)
    std::string scanStamps;      ///< optional: the log whose scan stamps replace the rawlog's
    bool keepEstimates = false;  ///< keep every trajectory in the run (for a plot)
    /// Scores the frame this far ahead of each estimated pose, along its heading (m; 0 = the
    /// poses as they are): for relations made in another frame on the robot than the one the
    /// trajectories give (a laser mounted off the robot's centre).
    double frameOffset = 0;
    /// A log (CARMEN, rawlog) whose scans say where the laser sits on the robot: each pose is
    /// moved there before it is scored (LaserFrame.h; the frame of Kümmerle et al.'s
    /// relations; a no-op where every scan's laser is at the robot's centre). "": the poses as
    /// given. Applied before frameOffset, after the mounting estimate.
    std::string laserFrameLog;
    /// A log (CARMEN, rawlog) whose odometry each trajectory is
    /// checked against: where on the robot its poses sit (SensorMounting.h; "": not asked).
    /// Estimated on the poses as given, before frameOffset.
    std::string mountingLog;
    /// List this many relations with the largest translational error per method (0: none).
    std::size_t worstRelations = 0;
    /// The trajectories are of the log's mirror image (toposlam-convert --mirror): they are
    /// scored against the mirror image of the reference (mirroredRelations,
    /// io::mirroredTrajectory).
    bool mirrorReference = false;

    /// Throws std::invalid_argument naming the option (e.g. "--icp-slam-path needs --rawlog")
    /// when the request cannot be run as given.
    void validate() const;
};

struct SlamEvaluationRun {
    SlamEvaluation evaluation;
    PoseRelations relations;  ///< those scored: read, or derived from the ground truth
    std::optional<io::Trajectory2D> groundTruth;
    std::vector<io::Trajectory2D> estimates;  ///< one per method when keepEstimates
};

/// Reads the reference and every trajectory and scores them. Throws io::InputError naming the
/// file for bad input, including a trajectory that matches none of the relations (its stamps
/// are not those of the reference within the stamp tolerance: nothing was measured).
/// `progress`: over all the logs read (odometry, scan stamps), scans so far.
SlamEvaluationRun runSlamEvaluation(const SlamEvaluationRequest& request,
                                    const io::ProgressCallback& progress = {});

/// Outputs of a run, each written atomically when its path is not empty: the relations used
/// (.relations), a PNG of the aligned trajectories (needs keepEstimates), the JSON document.
struct SlamEvaluationOutputs {
    std::string relations;
    std::string plot;
    std::string json;
};
void saveSlamEvaluationOutputs(const SlamEvaluationRun& run, const SlamEvaluationOutputs& out);

}  // namespace toposlam::evaluation
