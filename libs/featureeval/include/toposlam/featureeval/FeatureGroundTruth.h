#pragma once
// Exact ground truth of the features of a scan of a SyntheticScene, for benchmark B1 and the
// tests. Everything in the SENSOR frame of the scan.
//  - Corners: polygon vertices the scan sees with both incident walls observed: the vertex is
//    in the field of view and range, the ray to it is not blocked, and on each side of its
//    bearing at least minArmBeams consecutive beams hit the respective incident wall.
//    Vertices seen with both walls but fewer beams are "don't care": a detection there is
//    neither a hit nor a false alarm. A vertex seen with one wall only (an occluding edge)
//    is not a corner: a corner reported there is a false alarm.
//  - Wall runs: maximal blocks of consecutive beams hitting the same polygon edge as one
//    continuous surface (at least minRunBeams), with the exact hit points of their first and
//    last beams: the visible extent of that wall, what a segment should span.
// Beams are cast exactly (no noise) along the scan's own beam directions.
#include <mrpt/math/TPoint2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>
#include <toposlam/featureeval/SyntheticRooms.h>
#include <toposlam/features/ScanFeatures.h>

#include <cstdint>
#include <vector>

namespace toposlam::featureeval {

struct GroundTruthCorner {
    mrpt::math::TPoint2D position;  ///< m, sensor frame
    double angle = 0;               ///< rad in (0, pi), between the two walls
    features::EndpointType type = features::EndpointType::Convex;
    bool dontCare = false;
    double range = 0;  ///< m from the sensor
};

struct GroundTruthRun {
    std::uint32_t firstBeam = 0, lastBeam = 0;  ///< scan beam indices, first <= last
    mrpt::math::TPoint2D start, end;            ///< exact hit points of firstBeam and lastBeam (m)
};

struct ScanGroundTruth {
    std::vector<GroundTruthCorner> corners;
    std::vector<GroundTruthRun> runs;
};

struct GroundTruthOptions {
    unsigned minArmBeams = 5;
    unsigned minRunBeams = 5;
};

/// `scan` supplies the beam geometry (size, aperture, direction, maxRange); `sensorPose` is
/// the pose of the sensor in the world frame.
ScanGroundTruth computeGroundTruth(const SyntheticScene& scene,
                                   const mrpt::poses::CPose2D& sensorPose,
                                   const mrpt::obs::CObservation2DRangeScan& scan,
                                   const GroundTruthOptions& options = {});

}  // namespace toposlam::featureeval
