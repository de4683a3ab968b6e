#pragma once
// One evaluation run: several trajectories (methods) scored against one reference (a relation
// file, or a ground-truth trajectory and the relations derived from it), with the result as a
// table for people and as JSON for scripts.
#include <toposlam/evaluation/AbsoluteTrajectoryError.h>
#include <toposlam/evaluation/GroundTruthRelations.h>
#include <toposlam/evaluation/RelationFile.h>
#include <toposlam/evaluation/RelativePoseError.h>
#include <toposlam/io/Trajectory.h>

#include <optional>
#include <string>
#include <vector>

namespace toposlam::evaluation {

struct MethodEvaluation {
    std::string name;    ///< label in the table, e.g. "odometry", "icp-slam"
    std::string source;  ///< where the trajectory came from (file names)
    std::size_t poses = 0;
    RelativePoseErrorResult relative;
    /// Only when the reference is a ground-truth trajectory.
    std::optional<AbsoluteTrajectoryErrorResult> absolute;
};

struct SlamEvaluation {
    /// The relation file, or the ground-truth trajectory file.
    std::string referenceFile;
    /// Ground-truth trajectory: relations derived with `groundTruthRelations`.
    bool referenceIsGroundTruth = false;
    std::size_t groundTruthPoses = 0;
    GroundTruthRelationOptions groundTruthRelations;
    std::size_t relationCount = 0;
    double stampTolerance = StampedPoseLookup::kDefaultTolerance;
    std::vector<MethodEvaluation> methods;
};

/// Scores one trajectory: the relation metric, and the ATE when `groundTruth` is given.
MethodEvaluation evaluateMethod(const std::string& name, const std::string& source,
                                const io::Trajectory2D& estimate, const PoseRelations& relations,
                                const io::Trajectory2D* groundTruth, double stampTolerance);

/// A Markdown table (readable in a terminal, pasteable into a README), one row per method,
/// preceded by a line that names the reference.
std::string formatEvaluationTable(const SlamEvaluation& evaluation);

/// The whole evaluation as a JSON document (keys documented in the README).
std::string formatEvaluationJson(const SlamEvaluation& evaluation);

/// Writes formatEvaluationJson() to `path` atomically (no partial file on failure).
void saveEvaluationJson(const SlamEvaluation& evaluation, const std::string& path);

/// A PNG of every method's trajectory (`estimates[i]` belongs to `evaluation.methods[i]`),
/// each rigidly aligned into one frame: the ground truth's, drawn too, when `groundTruth` is
/// given; otherwise the frame of the method with the lowest mean translational error. Legend:
/// name and mean translational error. Written atomically.
void saveEvaluationPlot(const SlamEvaluation& evaluation,
                        const std::vector<io::Trajectory2D>& estimates,
                        const io::Trajectory2D* groundTruth, const std::string& path);

}  // namespace toposlam::evaluation
