#pragma once
// Fallback search for scans whose segments do not lead to a reliable pose (short, cluttered or
// partly seen walls: the graph has too few shared segments, or only parallel ones). It keeps
// what segments are good at, the rotation, and finds the translation from all points:
//   1. rotation candidates: for every candidate segment pair (i -> a) the rotation
//      heading(a) - heading(i), voted with weight min(length) into 2-degree bins (circular,
//      each vote spread over its bin and the neighbours); the strongest bins are refined to the
//      weighted mean of their votes;
//   2. translation voting (a Hough transform): for each candidate rotation R, every pair of a
//      current point p and a reference point q votes for t = q - R p in a grid of cells over
//      +-window, each current point at most once per cell, so that a cell counts the current
//      points that translation t puts onto some reference point (an overlap in points; pair
//      counts would let the dense readings of near clutter outvote far walls); where the
//      scans overlap, all points on shared surfaces vote for the true t, while other pairs
//      spread their votes thinly;
//   3. the best few peaks of each grid (3x3 cell sums, with suppression around each peak) are
//      the pose hypotheses, refined and scored by the caller like the graph's own.
// Cost: (n/stride)^2 votes per rotation, a few hundred microseconds for ~10 rotations of
// 180-360-beam scans, which is why it runs only when the graph pipeline found nothing reliable.
#include <mrpt/poses/CPose2D.h>
#include <toposlam/config/OptionsSchema.h>
#include <toposlam/matching/AttributedGraph.h>
#include <toposlam/matching/PolarScan.h>
#include <toposlam/matching/RansacMatcher.h>

#include <cstdint>
#include <utility>
#include <vector>

namespace toposlam::matching {

struct HoughPoseSearchOptions {
    std::size_t maxRotations = 8;
    double rotationBin = 0.035;      ///< rad (2 deg)
    double minRotationWeight = 0.3;  ///< m of segment length behind a rotation candidate
    double window = 5.0;             ///< m, translations searched in [-window, window]^2
    double cell = 0.10;              ///< m
    std::size_t stride = 2;          ///< use every stride-th beam of both scans
    std::size_t peaksPerRotation = 3;
    double minPeakFraction = 0.1;  ///< of the voting current points, for a peak to count

    /// Its .ini keys (GraphScanMatcher.h gives them a prefix).
    void declare(config::OptionsSchema& s);
};

struct PoseCandidate {
    mrpt::poses::CPose2D pose;
    double votes = 0;
};

class HoughPoseSearch {
  public:
    /// Candidates for the pose of the current scan in the reference frame, strongest first.
    /// `pairs`: candidate segment assignments (current -> reference node).
    const std::vector<PoseCandidate>& search(const PolarScan& reference, const PolarScan& current,
                                             const AttributedGraph& currentGraph,
                                             const AttributedGraph& referenceGraph,
                                             const std::vector<ScoredAssignment>& pairs,
                                             const HoughPoseSearchOptions& options);
    const std::vector<PoseCandidate>& candidates() const { return out_; }
    const std::vector<double>& rotations() const { return rotations_; }

  private:
    void collectPoints(const PolarScan& reference, const PolarScan& current, std::size_t stride);
    /// Votes for translations around (cx, cy) +- window at rotation phi; appends the peaks.
    void vote(double phi, double cx, double cy, double window, double cell, std::size_t peaks,
              double minPeakFraction);
    void rotationCandidates(const AttributedGraph& currentGraph,
                            const AttributedGraph& referenceGraph,
                            const std::vector<ScoredAssignment>& pairs,
                            const HoughPoseSearchOptions& options);

    std::vector<double> binWeight_, binSin_, binCos_, rotations_;
    std::vector<std::pair<double, std::size_t>> peaks_;
    std::vector<mrpt::math::TPoint2D> ref_, cur_;
    std::vector<std::uint16_t> votes_;
    std::vector<std::uint32_t> sums_;
    std::vector<std::uint32_t> lastVoter_;  // per cell: the current point that voted last
    std::vector<PoseCandidate> out_;
};

}  // namespace toposlam::matching
