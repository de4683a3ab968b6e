#pragma once
// RANSAC over samples of observed segments (graph-matching paper, sec. 2.2: "randomly draw a
// few segments of S, match them, keep the transform with the smallest error"; sec. 3.1: 2-3
// segments suffice). Occluded walls and moving obstacles leave some observed segments without
// a true counterpart, so the transform must come from a subset that agrees.
// Samples. Each sample is two observed segments with their reference counterparts, taken
// from a pool of assignments: the greedy matching of SPGM and, for every observed segment, its
// next most probable reference segments in P (so a wrong greedy choice is not fatal, and the
// look-alike matchings of a symmetric scene are seen, so it can be reported). The two
// observed segments must not be parallel (two parallel lines fix no along-line translation)
// and their relative angle must equal that of their counterparts. Samples are tried in order
// of decreasing weight (probability x length, PROSAC style) rather than at random, so the
// result is reproducible and independent of the order of the segments; at most
// maxHypotheses samples are evaluated.
// Model. The transform through the two line pairs (RigidTransform2D fromLines: exact for
// two non-parallel lines). After the pairs, the most probable single matches are tried too,
// each anchored three ways along its line (midpoints, start points, end points): where all
// long segments are parallel (a corridor) they are the only hypotheses, and the point-level
// refinement and scoring decide whether the rest of the scan fixes the position.
// Consensus. Under a transform, observed segment i agrees with reference segment a when
// their directions differ by < consensusAngle (+ the short-segment slack), both transformed
// end points of i lie within
// consensusDistance of a's line and the two overlap along it (gaps < overlapMargin). The
// support of a transform is the summed length of the observed segments that agree with some
// reference segment; the third and further agreeing segments are what makes it the paper's
// "2-3 segment" estimate once the caller refits on the consensus.
// Output: the best-supported transforms, at most maxKept of them, pairwise distinct (they
// differ by more than distinctTranslation or distinctRotation), each with its consensus.
#include <mrpt/poses/CPose2D.h>
#include <toposlam/config/OptionsSchema.h>
#include <toposlam/matching/AttributedGraph.h>
#include <toposlam/matching/PointToLineIcp.h>
#include <toposlam/matching/RigidTransform2D.h>

#include <cstddef>
#include <optional>
#include <vector>

namespace toposlam::matching {

struct RansacOptions {
    std::size_t maxHypotheses = 120;
    /// Single-match hypotheses (after the pairs): the most probable matches, 3 each.
    std::size_t maxSingleHypotheses = 12;
    std::size_t alternativesPerSegment = 3;  ///< reference candidates per observed segment
    /// Added to every probability in the sample weights, so that alternatives SPGM drove to
    /// 0 (it converges to one vertex, i.e. one of several look-alike matchings) are still
    /// tried, after the likely ones, in order of length.
    double probabilityFloor = 0.02;
    double minSampleAngle = 0.35;        ///< rad; sampled segments at least this far from parallel
    double sampleAngleTolerance = 0.10;  ///< rad; relative angles of the pairs must agree
    double consensusAngle = 0.10;        ///< rad
    /// rad x m: both angle tolerances grow by this over the shorter segment's length, as the
    /// direction of a short segment is noisier (1 cm of noise on a 0.25 m wall is 2-5 deg).
    double shortSegmentAngleSlack = 0.03;
    double consensusDistance = 0.20;  ///< m
    double overlapMargin = 0.50;      ///< m
    std::size_t maxKept = 6;
    double distinctTranslation = 0.30;  ///< m
    double distinctRotation = 0.15;     ///< rad

    /// Its .ini keys (GraphScanMatcher.h gives them a prefix).
    void declare(config::OptionsSchema& s);
};

/// A candidate assignment observed (current) node -> reference node with its probability.
struct ScoredAssignment {
    std::uint32_t current = 0, reference = 0;
    double probability = 0;
};

struct Hypothesis {
    mrpt::poses::CPose2D pose;  ///< current sensor frame in the reference sensor frame
    double support = 0;         ///< m of agreeing observed segments
    std::vector<SegmentMatch> consensus;
    /// The pose came from all points (HoughPoseSearch), not from segment lines: where the
    /// agreeing lines are parallel, its position along them is kept as the start.
    bool positionFromPoints = false;
};

class RansacMatcher {
  public:
    /// `assignments`: the sample pool (greedy pairs and alternatives, duplicates allowed).
    /// `guess`: also evaluated as a hypothesis when given.
    const std::vector<Hypothesis>& run(const AttributedGraph& current,
                                       const AttributedGraph& reference,
                                       const std::vector<ScoredAssignment>& assignments,
                                       const RansacOptions& options,
                                       const std::optional<mrpt::poses::CPose2D>& guess = {});

    /// Support of `pose` (m); when `out` is given, the agreeing pairs (every agreeing
    /// reference segment of each observed segment).
    static double consensus(const AttributedGraph& current, const AttributedGraph& reference,
                            const mrpt::poses::CPose2D& pose, const RansacOptions& options,
                            std::vector<SegmentMatch>* out = nullptr);

    const std::vector<Hypothesis>& hypotheses() const { return kept_; }
    std::size_t evaluated() const { return evaluated_; }

  private:
    // The steps of run(): the candidate pool, hypotheses from pairs of matched segments, from
    // single matched segments.
    void buildPool(const std::vector<ScoredAssignment>& assignments);
    void offerPairs(const AttributedGraph& current, const AttributedGraph& reference,
                    const RansacOptions& options);
    void offerSingles(const AttributedGraph& current, const AttributedGraph& reference,
                      const RansacOptions& options);
    void offer(const AttributedGraph& current, const AttributedGraph& reference,
               const mrpt::poses::CPose2D& pose, const RansacOptions& options);

    struct Sample {
        std::uint32_t u, v;
        double weight;
    };
    std::vector<ScoredAssignment> pool_;
    std::vector<Sample> samples_, singles_;
    std::vector<LinePair> lines_;
    std::vector<Hypothesis> kept_;
    std::size_t evaluated_ = 0;
};

/// True when two poses differ by more than the given translation (m) or rotation (rad).
bool posesDistinct(const mrpt::poses::CPose2D& a, const mrpt::poses::CPose2D& b, double translation,
                   double rotation);

}  // namespace toposlam::matching
