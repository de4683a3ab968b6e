#pragma once
// Graph SLAM on TopoSLAM's own features and matchers (fed by GraphSlamInput; CGraphSlamBuilder
// wraps it as an MRPT map builder):
//   front end  every scan is registered against the local submap (ScanRegistration:
//              point-to-line ICP from the odometry prediction, the graph matcher where that
//              fails, odometry where both fail); keyframes (distance / angle / overlap rule)
//              carry their features, extracted once, and build the submaps (Submap);
//   loops      each keyframe is matched against older ones inside the gate of its propagated
//              uncertainty, and periodically guess-free (LoopCloser);
//   back end   the keyframe pose graph (PoseGraph), optimised by MRPT's sparse
//              Levenberg-Marquardt when a loop disagrees with it, and at the end.
// Every scan's pose is its keyframe's optimised pose composed with the scan's registered
// offset from it. World frame: the robot frame at the first scan (or the initial pose given);
// poses are ROBOT poses (m, rad).
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>
#include <toposlam/features/CObservationLaserFeatures.h>
#include <toposlam/features/FeatureExtractor.h>
#include <toposlam/mapping/GraphSlamOptions.h>
#include <toposlam/mapping/Keyframe.h>
#include <toposlam/mapping/LoopCloser.h>
#include <toposlam/mapping/OdometryCalibration.h>
#include <toposlam/mapping/OdometryLag.h>
#include <toposlam/mapping/PoseGraph.h>
#include <toposlam/mapping/ScanRegistration.h>
#include <toposlam/mapping/SlamStatistics.h>
#include <toposlam/mapping/Submap.h>

#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

namespace toposlam::mapping {

class GraphSlam {
  public:
    /// `extractor`: the keyframes' feature extractor (the graph matcher works on its
    /// segments).
    GraphSlam(const GraphSlamOptions& options, const matching::GraphMatcherOptions& matcherOptions,
              std::unique_ptr<features::FeatureExtractor> extractor,
              const mrpt::poses::CPose2D& initialPose = {});

    /// Processes one scan. `odometryIncrement`: the robot's motion since the previous scan by
    /// odometry (in the previous robot frame), nullopt when unknown. `storedFeatures`: the
    /// scan's features when the log already has them (used instead of extracting again).
    void processScan(const mrpt::obs::CObservation2DRangeScan::Ptr& scan,
                     const std::optional<mrpt::poses::CPose2D>& odometryIncrement,
                     const features::CObservationLaserFeatures::Ptr& storedFeatures = nullptr);
    /// Optimises the graph once more (loops still waiting for an optimisation). Call at the end.
    void finish();

    std::size_t scanCount() const { return scans_.size(); }
    /// Pose of scan i (0-based, in processing order) at the current graph estimate.
    mrpt::poses::CPose2D scanPose(std::size_t i) const;
    /// Every scan's pose: scanPose(), with the positions between keyframes re-estimated from
    /// registration and odometry together when `smooth_scans` is on (TrajectorySmoother.h).
    std::vector<mrpt::poses::CPose2D> scanPoses() const;
    /// Pose of the last scan.
    mrpt::poses::CPose2D currentPose() const { return current_; }
    /// Covariance of the last scan's pose relative to its keyframe (m^2, rad^2).
    const mrpt::math::CMatrixDouble33& currentCovariance() const { return currentCovariance_; }

    const std::vector<Keyframe>& keyframes() const { return keyframes_; }
    const PoseGraph& graph() const { return graph_; }
    const SlamStatistics& statistics() const { return stats_; }
    /// The odometry's distance scale as learnt so far (odometry_calibration).
    const OdometryCalibration& odometryCalibration() const { return odometryCalibration_; }
    const GraphSlamOptions& options() const { return options_; }

  private:
    struct ScanRecord {
        std::size_t keyframe;               ///< the keyframe it hangs off
        mrpt::poses::CPose2D fromKeyframe;  ///< its robot pose in that keyframe's frame
        /// Odometry since the previous scan, calibrated (none: first scan, missing, or a jump).
        std::optional<mrpt::poses::CPose2D> odometry;
        double registrationVariance = 0;  ///< m², per coordinate of its position
    };
    void processScanTimed(const mrpt::obs::CObservation2DRangeScan::Ptr& scan,
                          const std::optional<mrpt::poses::CPose2D>& odometryIncrement,
                          const features::CObservationLaserFeatures::Ptr& storedFeatures);
    /// `scanInterval`: s since the scan before (0: not known).
    Prediction predict(const std::optional<mrpt::poses::CPose2D>& odometryIncrement,
                       double scanInterval);
    /// Whether the odometry `increment` is one of exactly zero, none having moved since the
    /// log began: then it is read as no odometry at all.
    bool odometryNeverMoved(const mrpt::poses::CPose2D& increment);
    bool isKeyframe(const Registration& r, const mrpt::poses::CPose2D& pose) const;
    /// The last `stallScans` scans before this one, a bridged stall's that registration left
    /// behind (Prediction::stallScansBehind), placed at even steps between the scan before the
    /// stall and this one (the robot at a steady speed), each keeping its heading unless
    /// `turnBetween` (nothing registered them: Prediction::stallUnplaced), when their
    /// headings are spread evenly over the turn too; their odometry, and this scan's, is the
    /// reading's share of each scan interval. `reading`: the odometry since the scan before the
    /// stall (its frame, m, rad). Keyframes stay.
    void placeStalledScans(std::size_t stallScans, const mrpt::poses::CPose2D& reading,
                           bool turnBetween);
    void addKeyframe(const mrpt::obs::CObservation2DRangeScan::Ptr& scan, const Registration& r,
                     const mrpt::poses::CPose2D& pose,
                     features::CObservationLaserFeatures::Ptr features);
    /// The edges that place a new keyframe (registration or fallback).
    void addKeyframeEdges(const Registration& r, Keyframe& kf);
    void updateSubmaps(const Keyframe& kf);
    std::size_t firstActiveKeyframe() const;
    /// Optimises after loops were accepted, over the window or the whole graph (see
    /// GraphSlamOptions::optimize*).
    void scheduleOptimization(const LoopClosureOutcome& loops);
    /// Optimises nodes from `firstFree` on; withdraws loops the result shows to be wrong.
    void optimize(std::size_t firstFree);
    void rebuildActiveSubmaps();

    GraphSlamOptions options_;
    std::unique_ptr<features::FeatureExtractor> extractor_;
    ScanRegistration registration_;
    OdometryCalibration odometryCalibration_;
    LoopCloser loopCloser_;
    PoseGraph graph_;
    std::vector<Keyframe> keyframes_;
    std::vector<Submap> submaps_;
    std::size_t firstActiveSubmap_ = 0;
    /// The line map of the submap finished last, for the next new submap to reuse.
    std::optional<matching::LineMap> spareLineMap_;
    std::vector<ScanRecord> scans_;
    SlamStatistics stats_;
    mrpt::poses::CPose2D initialPose_;
    mrpt::poses::CPose2D current_;  ///< last scan's robot pose, world frame
    mrpt::math::CMatrixDouble33 currentCovariance_;
    mrpt::poses::CPose2D lastMotion_;  ///< the last scan's registered motion
    /// The odometry's reading at the last scan (calibrated), when it had one.
    std::optional<mrpt::poses::CPose2D> lastReading_;
    /// The distances of the last ten scans' registered motions (m), oldest overwritten.
    std::array<double, 10> recentSteps_{};
    bool odometryMoved_ = false;              ///< some odometry increment was not zero
    OdometryLag odometryLag_;                 ///< the odometry stalling and catching up
    double travelled_ = 0;                    ///< m along the estimated trajectory
    double turned_ = 0;                       ///< rad turned along it (absolute)
    double odometrySinceKeyframe_ = 0;        ///< m by odometry since the last keyframe
    double turnSinceKeyframe_ = 0;            ///< rad by odometry since the last keyframe
    bool doubtSinceKeyframe_ = false;         ///< a scan since then placed without ICP
    std::size_t loopsWaiting_ = 0;            ///< accepted loops not yet optimised
    std::size_t lastGlobalOptimization_ = 0;  ///< newest keyframe at the last global one
    matching::PolarScan polar_;               ///< the current scan (workspace)
    matching::PolarScan previousPolar_;       ///< the scan before it
    mrpt::Clock::time_point previousStamp_;   ///< the stamp of the scan before it
    features::ScanFeatures features_;         ///< the current scan's features (workspace)
    /// The last keyframe's readings, for the graph matcher (Prediction::lastKeyframeReadings;
    /// keyframes do not keep theirs).
    matching::PolarScan lastKeyframeReadings_;
    /// Once a keyframe was placed by odometry alone: the newest keyframe a registration placed
    /// before it, and its readings (Prediction::registeredKeyframe).
    std::size_t registeredKeyframe_ = 0;
    matching::PolarScan registeredKeyframeReadings_;
};

}  // namespace toposlam::mapping
