#pragma once
// A keyframe of the graph SLAM: a scan kept for good, with what the back end and the loop
// closer need of it, computed once when it is made.
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>
#include <toposlam/features/CObservationLaserFeatures.h>
#include <toposlam/matching/LineMap.h>
#include <toposlam/matching/PolarScan.h>

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

namespace toposlam::mapping {

/// Rotation-tolerant summary of a scan for ranking guess-free loop candidates cheaply: the
/// share of valid readings per range band (0.5 m bands up to 8 m, the rest in the last).
using ScanSignature = std::array<float, 17>;

struct Keyframe {
    std::size_t id = 0;         ///< graph node id (= index in the keyframe list)
    std::size_t scanIndex = 0;  ///< index of its scan among all scans processed
    /// Its scan. The readings as the graph matcher takes them (matching::PolarScan) are not
    /// kept: PolarScan::assign rebuilds them from it, bit for bit, where a match needs them.
    /// Kept, they were 7.6 KiB per keyframe at 361 beams, a quarter of a long log's heap.
    mrpt::obs::CObservation2DRangeScan::Ptr scan;
    /// rad: the angle its readings span, |bearing step| x readings (for view overlap).
    double fieldOfView = 0;
    /// Its readings with their local lines (sensor frame), as every submap inserts them.
    std::vector<matching::SurfacePoint> surface;
    /// Its features (sensor frame), extracted once (or taken from the log when it has them).
    features::CObservationLaserFeatures::Ptr features;
    mrpt::poses::CPose2D sensorOnRobot;  ///< the laser's pose on the robot (2D part)
    double travelled = 0;                ///< m along the estimated trajectory at this keyframe
    double turned = 0;                   ///< rad turned (absolute) along it
    /// The front end doubts how it got here: this scan or one since the previous keyframe was
    /// placed without ICP (by the graph matcher, or by odometry alone). Only past such a
    /// keyframe may the graph be off by more than its covariances say (LoopCloser: contested
    /// matches).
    bool frontEndDoubt = false;
    /// Placed by odometry alone (neither ICP nor the graph matcher could place this scan): the
    /// odometry's covariance over the step from the previous keyframe, its edge's. Such a
    /// keyframe may be off by more than that (a fault of the odometry's), and it starts a part
    /// of each submap it goes into (Submap.h).
    std::optional<mrpt::math::CMatrixDouble33> placedByOdometry;
    /// The keyframe placed by odometry alone that starts the part of a submap this one is tied
    /// to (itself, when it is one); kNoPart when it is tied to a submap's anchor.
    std::size_t part = kNoPart;
    static constexpr std::size_t kNoPart = std::size_t(-1);
    ScanSignature signature{};
};

/// The signature of a scan (see ScanSignature).
ScanSignature scanSignature(const matching::PolarScan& scan);
/// L1 distance of two signatures, in [0, 2].
double signatureDistance(const ScanSignature& a, const ScanSignature& b);

}  // namespace toposlam::mapping
