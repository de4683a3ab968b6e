#pragma once
// The positions of the scans between keyframes, from both things that place them: each scan's
// registration against the local map, and the odometry between consecutive scans. The graph
// holds only keyframes; a scan between two of them was placed by its registration alone, and
// with a noisy laser (2-5 cm of range noise, MRPT's simul.rawlog) that jitters by 1-3 cm from
// scan to scan. Odometry between two consecutive scans has independent errors, so the
// weighted least-squares position from both (each weighted by its noise model) is better than
// either. Keyframes stay where the graph put them, and so do all headings (registration fixes
// them far better than odometry): only the positions between keyframes move.
#include <mrpt/poses/CPose2D.h>

#include <optional>
#include <vector>

namespace toposlam::mapping {

/// One scan, in processing order. Poses in the world frame (m, rad).
struct SmoothingInput {
    mrpt::poses::CPose2D pose;  ///< where the SLAM put the scan's robot
    bool fixed = false;         ///< a keyframe: kept as it is
    double poseVariance = 0;    ///< m², of each coordinate of that position (> 0 unless fixed)
    /// Odometry since the previous scan (robot frame of the previous scan), or nullopt when
    /// there is none (first scan, no odometry, or an increment taken for a jump).
    std::optional<mrpt::poses::CPose2D> odometry;
    double odometryVariance = 0;  ///< m², of each coordinate of that motion (> 0)
};

/// The robot poses of `scans` with the positions of the non-fixed ones re-estimated by
/// weighted least squares: each position near its own (weight 1 / poseVariance), and each
/// step from the previous scan near the odometry's, turned into the world by the previous
/// scan's heading (weight 1 / odometryVariance). Sparse Cholesky (Eigen) over all free scans.
std::vector<mrpt::poses::CPose2D> smoothScanPositions(const std::vector<SmoothingInput>& scans);

}  // namespace toposlam::mapping
