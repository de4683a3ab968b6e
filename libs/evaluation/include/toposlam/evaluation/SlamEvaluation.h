#pragma once
// One evaluation run: several trajectories (methods) scored against one reference (a relation
// file, or a ground-truth trajectory and the relations derived from it), with the result as a
// table for people and as JSON for scripts.
#include <toposlam/evaluation/AbsoluteTrajectoryError.h>
#include <toposlam/evaluation/AlongTrackScale.h>
#include <toposlam/evaluation/FrameOffsetFit.h>
#include <toposlam/evaluation/GroundTruthRelations.h>
#include <toposlam/evaluation/RelationFile.h>
#include <toposlam/evaluation/RelativePoseError.h>
#include <toposlam/evaluation/SensorMounting.h>
#include <toposlam/evaluation/WorstRelations.h>
#include <toposlam/io/JsonFile.h>
#include <toposlam/io/Trajectory.h>

#include <mrpt/math/TPoint2D.h>

#include <optional>
#include <string>
#include <vector>

namespace toposlam::evaluation {

/// The errors of the relations of one scale of a ground-truth relation set
/// (GroundTruthRelations.h): how a method drifts over 0 (consecutive poses), d, 2d, ... metres.
struct SeparationErrors {
    double separation = 0;           ///< m of travelled path; 0 = consecutive poses
    std::size_t totalRelations = 0;  ///< relations of this scale
    ErrorStatistics translation;     ///< m, over the matched ones
    ErrorStatistics rotation;        ///< degrees
};

/// The errors of the relations whose reference motion turns by [minTurnDeg, maxTurnDeg)
/// (|yaw| of δ_gt; the last bin includes 180°). A trajectory given in another frame on the
/// robot than the reference's shows here: a frame d m off adds 2·d·sin(θ/2) to a relation
/// that turns by θ, so its error grows with the turn while a well-framed one stays flat.
struct TurnErrors {
    double minTurnDeg = 0, maxTurnDeg = 0;  ///< degrees
    std::size_t totalRelations = 0;         ///< relations of this bin
    ErrorStatistics translation;            ///< m, over the matched ones
    ErrorStatistics rotation;               ///< degrees
};

/// Share of its mean translational error that scoring another frame must save before the table
/// names that frame (a trajectory in the reference's frame gains next to nothing).
inline constexpr double kFrameOffsetNote = 0.1;

/// Bin edges of MethodEvaluation::byTurn, degrees.
inline constexpr double kTurnBinEdgesDeg[] = {0, 45, 90, 135, 180};

struct MethodEvaluation {
    std::string name;    ///< label in the table, e.g. "odometry", "icp-slam"
    std::string source;  ///< where the trajectory came from (file names)
    std::size_t poses = 0;
    RelativePoseErrorResult relative;
    /// Only when the reference is a ground-truth trajectory.
    std::optional<AbsoluteTrajectoryErrorResult> absolute;
    /// Only when the relations come with their separations (ground-truth reference).
    std::vector<SeparationErrors> bySeparation;
    /// Always: one entry per bin of kTurnBinEdgesDeg.
    std::vector<TurnErrors> byTurn;
    /// Always: the frame along the heading that fits the relations best (FrameOffsetFit.h),
    /// relative to the poses scored.
    FrameOffsetFit bestFrame;
    /// Always: how long or short its motion reads along the direction of travel
    /// (AlongTrackScale.h).
    AlongTrackScale alongTrack;
    /// Its worst relations, when asked for (SlamEvaluationRequest::worstRelations).
    std::vector<WorstRelation> worst;
    /// Where its poses sit on the robot as the odometry sees it, when asked for
    /// (SlamEvaluationRequest::mountingLog) and enough of its motion turns (SensorMounting.h).
    std::optional<SensorMounting> mounting;
};

struct SlamEvaluation {
    /// The relation file, or the ground-truth trajectory file.
    std::string referenceFile;
    /// Ground-truth trajectory: relations derived with `groundTruthRelations`.
    bool referenceIsGroundTruth = false;
    /// The reference's mirror image was scored (SlamEvaluationRequest::mirrorReference).
    bool referenceMirrored = false;
    std::size_t groundTruthPoses = 0;
    GroundTruthRelationOptions groundTruthRelations;
    std::size_t relationCount = 0;
    /// Relation file: how many lines repeat an earlier one (countRepeatedRelations); they are
    /// scored as published.
    std::size_t repeatedRelations = 0;
    /// Ground-truth reference: the separation of each relation (relationsFromGroundTruth).
    std::vector<double> relationSeparations;
    double stampTolerance = StampedPoseLookup::kDefaultTolerance;
    double frameOffset = 0;  ///< m ahead of each estimated pose: the frame scored
    /// The log whose scans placed each pose at its laser before scoring ("": the poses as
    /// given; SlamEvaluationRequest::laserFrameLog), and that laser's typical position on the
    /// robot (m, x forward, y left; typicalLaserPosition).
    std::string laserFrameLog;
    mrpt::math::TPoint2D laserPosition{0, 0};
    /// The log whose odometry each method's mounting was estimated against ("": not asked).
    std::string mountingLog;
    std::vector<MethodEvaluation> methods;
};

/// Scores one trajectory: the relation metric, and the ATE when `groundTruth` is given;
/// broken down by the reference motion's turn, and by scale when `separations` (one per
/// relation) is given.
MethodEvaluation evaluateMethod(const std::string& name, const std::string& source,
                                const io::Trajectory2D& estimate, const PoseRelations& relations,
                                const io::Trajectory2D* groundTruth, double stampTolerance,
                                const std::vector<double>* separations = nullptr);

/// A Markdown table (readable in a terminal, pasteable into a README), one row per method,
/// preceded by a line that names the reference; then the translational error by the
/// relations' turn, each method's along-track scale, and the frame that fits the relations
/// best for each method whose mean error it lowers by kFrameOffsetNote or more; with a
/// ground-truth reference, the error by relation separation; then the estimated sensor
/// mountings, if asked for; then each method's worst relations, if any (formatWorstRelations).
std::string formatEvaluationTable(const SlamEvaluation& evaluation);

/// One method's evaluation as JSON: relations, error statistics, ATE (with ground truth), by
/// turn and separation, along-track scale, best frame, mounting and worst relations (keys:
/// share/doc/apps.md). formatEvaluationJson lists one per method; toposlam-bench-slam puts
/// it under each run's "accuracy".
io::Json evaluationJson(const MethodEvaluation& method);

/// The whole evaluation as a JSON document (keys: share/doc/apps.md).
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
