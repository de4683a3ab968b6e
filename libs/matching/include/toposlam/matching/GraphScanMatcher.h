#pragma once
// Scan matching by attributed-graph matching (graph-matching paper, sec. 2.2), the engine of
// tracking and loop closure. The pipeline, one file per step:
//   1. AttributedGraph   the graphs of both scans' segments (lengths; angles, length ratios,
//                        midpoint and closest-point distances);
//   2. candidates        which observed segment may be which reference segment: all pairs of
//                        compatible length, or, with a pose guess, those the guess places
//                        near each other with similar directions (fewer pairs, faster);
//   3. Similarity        X and y over the candidates (eqs. 2-3, alpha = 1);
//   4. SpgmSolver        the relaxed assignment P (eqs. 4-5);
//   5. GreedyAssignment  P -> one-to-one matches;
//   6. RansacMatcher     transforms from pairs of matched segments (lines, not midpoints),
//                        ranked by how many segments agree;
//   7. PointToLineIcp    refinement of the best few on the points of their agreeing segments
//                        (AlongLineSearch where those are all parallel, e.g. a corridor); the
//                        ones that screen well are then polished on all points against the
//                        reference scan's local lines;
//   8. AlignmentScorer   free-space consistency of each polished pose, both ways (current on
//                        reference and back), and the decision below;
//   9. AlongLineSearch   along the best pose's weakest direction when its covariance is
//                        elongated (a corridor with a few door frames: ICP stops in the
//                        nearest minimum); a pose found there competes with the others;
//  10. HoughPoseSearch   only when 1-9 found nothing reliable: rotations from segment pairs,
//                        translations voted by all points, refined and judged the same way
//                        (and step 9 again on the new best).
// With a guess that leads to no reliable match, the match is retried without it
// (guessFreeRetry).
// The result is the pose of the CURRENT scan's sensor in the REFERENCE scan's sensor frame
// (what MRPT calls the pose of m2 relative to m1), its covariance and the evidence for it.
// Decision: a pose is returned as reliable only when
//   - enough of the scans land on each other's surface (inliers >= minInliers, scaled to
//     the current scan's beam spacing, and >=
//     minInlierRatio of the scored points or >= minVisibleInlierRatio of those inside the
//     other sensor's field of view: where the robot turned round, the scans share a small
//     part, but the pose must explain most of that part) and little lands in space the other
//     scan saw as free (inlier fraction >= minInlierFraction);
//   - the matched lines fix the pose (ICP's worst translation std <= maxTranslationStd):
//     a single wall or a featureless corridor does not;
//   - no clearly different pose (distinct by the RANSAC distinctness thresholds) explains the
//     data almost as well (the best must lead by ambiguityMargin of the scan): symmetric rooms and
//     repetitive corridors are reported as ambiguous, with the alternative, instead of
//     returning one of the look-alikes with confidence.
// All workspaces live in the object: reuse one matcher for many pairs. Not thread-safe.
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/poses/CPose2D.h>
#include <toposlam/config/Options.h>
#include <toposlam/features/ScanFeatures.h>
#include <toposlam/matching/AlignmentScorer.h>
#include <toposlam/matching/AlongLineSearch.h>
#include <toposlam/matching/AttributedGraph.h>
#include <toposlam/matching/GreedyAssignment.h>
#include <toposlam/matching/HoughPoseSearch.h>
#include <toposlam/matching/PointToLineIcp.h>
#include <toposlam/matching/PolarScan.h>
#include <toposlam/matching/RansacMatcher.h>
#include <toposlam/matching/Similarity.h>
#include <toposlam/matching/SpgmSolver.h>

#include <optional>
#include <string>
#include <vector>

namespace toposlam::matching {

/// Section [GraphScanMatcher] of config_ini/graph-matcher.ini; each step's options are keys
/// with the step's prefix (ransac_max_hypotheses, icp_max_distance, ...).
struct GraphMatcherOptions : public config::Options {
    // Graph
    double minSegmentLength = 0.25;  ///< m; shorter segments are not graph nodes
    std::size_t maxSegments = 16;    ///< per scan, the longest ones
    // Candidates
    double minLengthRatio = 0.15;         ///< shorter/longer length of a candidate pair, no guess
    double guessTranslationWindow = 1.5;  ///< m; with a guess: predicted position error
    double guessRotationWindow = 0.6;     ///< rad; with a guess: predicted direction error
    /// With a guess and no reliable match inside its windows, match again without it.
    bool guessFreeRetry = true;
    // Steps
    SimilarityOptions similarity;
    SpgmOptions spgm;
    RansacOptions ransac;
    IcpOptions icp{15, 0.30, 0.05, 1e-4, 1e-5, 2, 0.01, 1e-2};  ///< segment-mode ICP
    bool scanRefinement = true;  ///< polish with scan-mode ICP on all points
    IcpOptions scanIcp{15, 0.20, 0.05, 1e-4, 1e-5, 2, 0.01, 1e-4};
    AlignmentScoreOptions score;
    bool symmetricScore = true;  ///< score both ways (current on reference and back)
    /// Consensus lines this close to parallel (smallest / largest eigenvalue of their normal
    /// matrix; 0.03 = all within ~10 deg) leave the position along them to AlongLineSearch.
    double alongLineConditioning = 0.03;
    AlongLineSearchOptions alongLine;
    std::size_t refineTop = 3;  ///< hypotheses refined by ICP and scored on points
    /// Refined hypotheses are first screened (segment ICP, every screenStride-th point, twice
    /// the inlier distance); only those within polishRatio of the best screened one get the
    /// scan-mode ICP and the full scoring.
    std::size_t screenStride = 3;
    double polishRatio = 0.8;
    /// The best pose's least-determined direction (largest translation std of its ICP
    /// covariance) is searched over +-weakDirectionRange (AlongLineSearch) when the std along
    /// it is at least weakDirectionElongation times the std across it: along a corridor with a
    /// few door frames, ICP stops in the nearest minimum. 0 = no search.
    double weakDirectionRange = 0.8;  ///< m
    double weakDirectionElongation = 2.5;
    /// When the graph gives nothing reliable, search with HoughPoseSearch (rotations from
    /// segment pairs, translations voted by all points) and refine its best houghRefineTop.
    bool houghFallback = true;
    std::size_t houghRefineTop = 12;
    HoughPoseSearchOptions hough;
    // Decision
    /// Current points on the reference surface, counted for a laser with
    /// minInliersBearingStep between beams: a laser with other spacing needs as many as cover
    /// the same bearing (a 1 deg laser half as many, a 0.25 deg one twice as many; at least
    /// one). 0 = minInliers whatever the laser.
    std::size_t minInliers = 30;
    double minInliersBearingStep = 0.5 * M_PI / 180;  ///< rad
    double minInlierRatio = 0.25;                     ///< of the current scan's valid points
    /// ... or of the points inside the other sensor's field of view (0: off).
    double minVisibleInlierRatio = 0;
    double minInlierFraction = 0.90;  ///< inliers / (inliers + free-space violations)
    double maxTranslationStd = 0.05;  ///< m
    /// The best pose must explain this fraction of the current scan's points more than any
    /// clearly different pose (score = inliers - violations), else the match is ambiguous.
    double ambiguityMargin = 0.05;

    void declare(config::OptionsSchema& s) override;

  private:
    void declareRefinement(config::OptionsSchema& s);
    void declareDecision(config::OptionsSchema& s);
};

enum class MatchStatus {
    Matched,         ///< reliable
    TooFewFeatures,  ///< a scan has fewer than two usable segments
    NoConsensus,     ///< no pair of segments gives a transform others agree with
    PoorFit,         ///< the best pose leaves too much of the scan unexplained
    Degenerate,      ///< the matched lines do not fix the pose (e.g. one wall, a corridor)
    Ambiguous        ///< a clearly different pose fits (almost) as well (symmetric scene)
};
const char* toString(MatchStatus s);

struct MatchResult {
    MatchStatus status = MatchStatus::TooFewFeatures;
    bool reliable() const { return status == MatchStatus::Matched; }

    /// Current sensor frame in the reference sensor frame (m, rad). Set whenever a
    /// hypothesis was found, reliable or not (then it is the best guess, to inspect only).
    mrpt::poses::CPose2D pose;
    /// Covariance of (x, y, phi) from the point-to-line refinement (m^2, rad^2).
    mrpt::math::CMatrixDouble33 covariance;
    /// inlierFraction x inliers / current valid points, in [0, 1]: the share of the current
    /// scan the pose explains, discounted by free-space violations. 0 without a hypothesis.
    double quality = 0;
    AlignmentScore score;         ///< point evidence of `pose`: current points on the reference
    AlignmentScore reverseScore;  ///< and reference points on the current scan (symmetricScore)
    double residualRms = 0;       ///< m, point-to-line RMS after refinement
    double ambiguity = 0;         ///< score of the best distinct alternative / best score
    std::optional<mrpt::poses::CPose2D> alternative;  ///< that alternative, if any
    /// Matched segments as indices into the two ScanFeatures::segments.
    std::vector<SegmentMatch> matches;
    // Diagnostics
    std::size_t currentNodes = 0, referenceNodes = 0, candidates = 0;
    int spgmIterations = 0;
    std::size_t hypotheses = 0;
    bool usedFallback = false;         ///< HoughPoseSearch ran (the graph alone was not reliable)
    bool retriedWithoutGuess = false;  ///< the guided match failed and was retried guess-free
    /// CPU seconds (this thread) of the stages: graphs + candidates + similarities + SPGM + greedy;
    /// RANSAC; refinement and scoring of its hypotheses; the fallback (search + refinement).
    double secondsGraph = 0, secondsRansac = 0, secondsRefine = 0, secondsFallback = 0;
};

class GraphScanMatcher {
  public:
    explicit GraphScanMatcher(const GraphMatcherOptions& options = {});

    GraphMatcherOptions& options() { return options_; }
    const GraphMatcherOptions& options() const { return options_; }

    /// Matches the current scan against the reference scan. `guess`: pose of the current
    /// sensor in the reference sensor frame (e.g. from odometry), or none for guess-free
    /// matching (loop closure, relocalisation). Features must be in their scans' sensor
    /// frames with beam indices into the PolarScans. The returned reference stays valid
    /// until the next call.
    const MatchResult& match(const PolarScan& referenceScan,
                             const features::ScanFeatures& referenceFeatures,
                             const PolarScan& currentScan,
                             const features::ScanFeatures& currentFeatures,
                             const std::optional<mrpt::poses::CPose2D>& guess = {});

    const MatchResult& result() const { return result_; }
    /// The graphs of the last call (for visualisation and tests).
    const AttributedGraph& currentGraph() const { return current_; }
    const AttributedGraph& referenceGraph() const { return reference_; }
    /// The RANSAC hypotheses of the last call, best supported first (diagnostics).
    const std::vector<Hypothesis>& hypotheses() const { return ransac_.hypotheses(); }

  private:
    void buildCandidates(const std::optional<mrpt::poses::CPose2D>& guess);
    void buildPool();
    struct Refined {
        mrpt::poses::CPose2D pose;
        IcpResult icp;
        AlignmentScore score, reverseScore;
        double value = 0;        // inliers - violations (both ways when symmetric)
        double screenValue = 0;  // the same, sparse and forward only, before polishing
        bool polished = false;
        std::size_t hypothesis = 0;
        bool searchedAlongLine = false;
        mrpt::poses::CPose2D lineBase;       // pose the along-line search started from
        mrpt::math::TPoint2D lineDirection;  // and its direction
    };
    /// Polishes a coarse pose: scan-mode ICP and the full (symmetric) scoring.
    void polish(const PolarScan& referenceScan, const PolarScan& currentScan, Refined& out);
    /// Polishes the screened poses that can still win; drops the others and duplicates.
    void polishCandidates(const PolarScan& referenceScan, const PolarScan& currentScan);
    /// Coarse refinement of hypothesis `h` into `out` (line fit, segment ICP, along-line
    /// search) and its screening score; false when it duplicates an earlier one.
    bool refine(const PolarScan& referenceScan, const PolarScan& currentScan, const Hypothesis& h,
                Refined& out);
    /// Refines `h` and keeps it unless it ends on a pose already kept.
    void addRefined(const PolarScan& referenceScan, const PolarScan& currentScan,
                    const Hypothesis& h, std::size_t index);
    /// Searches the best pose's weakest direction (weakDirectionRange) and re-decides when
    /// that finds another pose.
    void searchWeakDirection(const PolarScan& referenceScan, const PolarScan& currentScan);
    /// Picks the best refined pose and sets the result's status.
    void decide();

    GraphMatcherOptions options_;
    AttributedGraph current_, reference_;
    bool swapped_ = false;  // SPGM rows are the reference graph
    std::vector<Assignment> candidates_;
    std::vector<ScoredAssignment> scored_, pool_;
    Similarity similarity_;
    SpgmSolver spgm_;
    GreedyAssignment greedy_;
    RansacMatcher ransac_;
    PointToLineIcp icp_;
    HoughPoseSearch hough_;
    AlongLineSearch alongLine_;
    Hypothesis fallback_;
    std::vector<LinePair> lines_;
    std::vector<SegmentMatch> consensus_, best_;
    std::vector<Refined> refined_;
    std::optional<mrpt::poses::CPose2D> weakDirectionSearched_;  // best pose searched last
    std::size_t minInliers_ = 0;  // options_.minInliers for the current scan's beam spacing
    MatchResult result_;
};

}  // namespace toposlam::matching
