#pragma once
// Refinement of a segment matching by point-to-line ICP (the graph-matching paper's last
// step, "ICP on the points of the corresponding segments", with the point-to-line metric
// the design asks for). The raw scan points of every matched current segment are pulled
// onto the LINE of the reference segment it was matched to: lines, not reference points,
// because partly occluded segments still lie on the right line, and point-to-line converges
// in a few iterations where point-to-point creeps.
// Each iteration re-associates every point with the nearest of its segment's candidate
// reference segments (a wall split in two in one scan is one segment in the other) and takes
// one Gauss-Newton step of the Cauchy-weighted least squares
//     min_{x,y,phi} sum_p rho( n_a . (R(phi) p + t) - offset_a ),   rho: Cauchy, scale c,
// dropping points farther than maxDistance from their line. It stops when a step moves the
// pose by less than the tolerances, or after maxIterations.
// Covariance: sigma^2 H^-1 with H = sum w J J' at the solution and sigma^2 the weighted
// residual variance (at least minNoiseStd^2). When the matched lines do not fix the pose
// (all parallel: a corridor), H is singular in that direction and the covariance says so.
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/poses/CPose2D.h>
#include <toposlam/matching/AttributedGraph.h>
#include <toposlam/matching/PolarScan.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace toposlam::matching {

/// Current node `current` is matched to reference node `reference` (graph node indices).
struct SegmentMatch {
    std::uint32_t current = 0;
    std::uint32_t reference = 0;
};

struct IcpOptions {
    int maxIterations = 15;
    double maxDistance = 0.30;           ///< m; points farther from their line are not used
    double robustScale = 0.05;           ///< m; Cauchy kernel scale c
    double translationTolerance = 1e-4;  ///< m
    double rotationTolerance = 1e-5;     ///< rad
    std::size_t stride = 1;              ///< use every stride-th beam of a segment
    double minNoiseStd = 0.01;           ///< m; floor of sigma in the covariance
};

struct IcpResult {
    mrpt::poses::CPose2D pose;
    /// Covariance of (x, y, phi) in m^2, rad^2; huge (1e6) along undetermined directions.
    mrpt::math::CMatrixDouble33 covariance;
    double residualRms = 0;  ///< m, weighted RMS point-to-line distance
    std::size_t pointsUsed = 0;
    int iterations = 0;
    bool converged = false;
    /// Square root of the largest eigenvalue of the translation covariance (m): the
    /// standard deviation along the worst-determined direction.
    double worstTranslationStd = 0;
};

class PointToLineIcp {
  public:
    /// `matches` may list several reference segments per current segment (any order).
    IcpResult refine(const PolarScan& current, const AttributedGraph& currentGraph,
                     const AttributedGraph& referenceGraph,
                     const std::vector<SegmentMatch>& matches, const mrpt::poses::CPose2D& initial,
                     const IcpOptions& options = {});

  private:
    std::vector<SegmentMatch> sorted_;
};

}  // namespace toposlam::matching
