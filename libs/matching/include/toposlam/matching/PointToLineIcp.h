#pragma once
// Refinement of a segment matching by point-to-line ICP (the graph-matching paper's last
// step, "ICP on the points of the corresponding segments", with the point-to-line metric
// the design asks for). Two association modes:
//  - segment mode (refine): the raw points of every matched current segment are pulled onto
//    the LINE of the reference segment it was matched to: lines, not reference points,
//    because partly occluded segments still lie on the right line. Each iteration
//    re-associates every point with the nearest of its segment's candidate reference
//    segments (a wall split in two in one scan may be one segment in the other);
//  - scan mode (refineOnScan), the last polish once the segments agree on a pose: every
//    valid current point against the local line of its nearest reference point, searched
//    among the reference beams within `searchBeams` of its bearing (O(1) per point, no
//    search tree). Local lines are fitted to each reference point and its neighbours that
//    are not across a range jump (LocalLine.h: as far as the scan's noise asks), once per
//    reference scan. It uses the short
//    walls, corners and furniture the segment graph leaves out, which is what makes the pose
//    accurate on cluttered real scans; it never runs from a pose the segments did not give.
// In scan and map mode a point is associated only with a surface its own sensor faces, as the
// sensor that saw the surface did: a wall 10 cm thick, seen from the room on one side by the
// reference and from the corridor on the other by the current scan, has two faces 10 cm
// apart, and points on one face matched to the other pull the pose by the wall's thickness.
// Each iteration takes one Gauss-Newton step of the Cauchy-weighted least squares
//     min_{x,y,phi} sum_p rho( n . (R(phi) p + t) - offset ),   rho: Cauchy, scale c,
// dropping points farther than maxDistance from their line, and restricted to the directions
// the data determine (eigenvalues of H above minEigenRatio x the largest; "degeneracy-aware"
// solving), so a pose is never moved along a direction nothing constrains; it stops when a
// step moves the pose by less than the tolerances, or after maxIterations.
// Covariance: sigma^2 H^-1 with H = sum w J J' at the solution and sigma^2 the weighted
// residual variance (at least minNoiseStd^2). When the lines do not fix the pose (all
// parallel: a corridor), H is singular in that direction and the covariance says so.
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/poses/CPose2D.h>
#include <toposlam/config/OptionsSchema.h>
#include <toposlam/matching/AttributedGraph.h>
#include <toposlam/matching/LineMap.h>
#include <toposlam/matching/LocalLine.h>
#include <toposlam/matching/PolarScan.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
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
    std::size_t stride = 1;     ///< every stride-th beam (scan mode: in the wide-gate stage)
    double minNoiseStd = 0.01;  ///< m; floor of sigma in the covariance
    /// Steps are taken only along directions whose eigenvalue of H is at least this fraction
    /// of the largest: nearly parallel lines fix nothing along themselves, and a plain
    /// Gauss-Newton step there is noise amplified, sliding the pose down a corridor.
    double minEigenRatio = 1e-2;
    /// Map mode, wide-gate stage: only map points seen from at least this many scans
    /// (LineMapPoint::views; at most as many as the map holds) are associated; the tight stage
    /// takes them all. A person walking along with the robot stays a step ahead of it, and
    /// the places it stood in earlier scans pull a registration back by that step. 1 = all.
    std::uint32_t minMapViews = 1;
    /// Map mode, wide-gate stage: map points that later scans saw through
    /// (LineMapPoint::moved: a person who walked on) are not associated; the tight stage takes
    /// them all, so the share of readings that fit (the overlap) counts them as before.
    bool skipMovedMapPoints = false;
    /// Map mode: a map point is associated only when its surface faces the sensor at an
    /// incidence below this (rad; angle between its normal and the direction to the sensor;
    /// a surface facing away, beyond pi / 2, is never associated).
    /// A rough wall seen from down a corridor keeps the normals of the faces that looked back
    /// along it; passing beside them, a reading on the wall must not be held by them. pi = all.
    double maxIncidence = M_PI;

    /// Its .ini keys (GraphScanMatcher.h gives them a prefix).
    void declare(config::OptionsSchema& s);
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
    /// Segment mode. `matches` may list several reference segments per current segment.
    IcpResult refine(const PolarScan& current, const AttributedGraph& currentGraph,
                     const AttributedGraph& referenceGraph,
                     const std::vector<SegmentMatch>& matches, const mrpt::poses::CPose2D& initial,
                     const IcpOptions& options = {});

    /// Scan mode: fits the reference's local lines; call it whenever the reference changes ...
    void prepareReference(const PolarScan& reference, double maxJoinDistance = 0.3);
    /// ... then refines against them.
    IcpResult refineOnScan(const PolarScan& reference, const PolarScan& current,
                           const mrpt::poses::CPose2D& initial, const IcpOptions& options = {},
                           long searchBeams = 3);

    /// Map mode: every valid current point against the local line of the map point nearest
    /// to it (LineMap lookup, O(1)); `initial` and the result are the current SENSOR pose in
    /// the map frame. Two stages as in scan mode (every stride-th point with the wide gate,
    /// then all points with a gate of 3 sigma of the residuals); options.maxDistance must not
    /// exceed the map's radius. IcpResult::pointsUsed counts the points of the last
    /// iteration (the inliers of the tight gate).
    IcpResult refineOnMap(const LineMap& map, const PolarScan& current,
                          const mrpt::poses::CPose2D& initial, const IcpOptions& options = {});

    /// Map mode: how many valid points of `current`, at SENSOR pose `pose` in the map frame, lie
    /// within `distance` (m) of the local line of their nearest map point (any point within the
    /// map's radius): how much of the scan a pose explains, comparable between poses.
    static std::size_t countOnMap(const LineMap& map, const PolarScan& current,
                                  const mrpt::poses::CPose2D& pose, double distance);

  private:
    struct Accumulator;
    /// The two stages of scan and map mode around
    /// `correspond(qx, qy, sensorX, sensorY, gate2, tight, nx, ny, r)`, which finds the line for
    /// the current point moved to the world point q (the sensor at (sensorX, sensorY)) and its
    /// residual, false when there is none within the squared gate; `tight`: second stage.
    template <typename Correspond>
    IcpResult twoStageRefine(const PolarScan& current, const mrpt::poses::CPose2D& initial,
                             const IcpOptions& options, double gate, Correspond&& correspond) const;
    void finish(IcpResult& out, const Accumulator& acc, const IcpOptions& options) const;

    std::vector<SegmentMatch> sorted_;
    std::vector<std::optional<LocalLine>> lines_;  // per reference beam
};

}  // namespace toposlam::matching
