#pragma once
// From a segment set L (LinePart list, after split / merge / fix) to ScanFeatures: the corner
// paper's steps 4 and 5, plus what a usable feature set needs and the paper leaves open.
//  - Very short parts (fewer than minSegmentPoints readings, or shorter than
//    minSegmentLength) carry no reliable direction and are dropped. When such a part sits
//    between two corners, its neighbours are joined instead: a corner whose two lines are
//    split by a few noisy readings is still one corner.
//  - Each remaining part is fitted (two-point fit, step 4, or least squares) and becomes a
//    LineSegment; the ends are its first and last readings projected onto the line. A part
//    that is no line fails a chi-square test on its residual sum of squares (mean + 3 std for
//    N - 2 degrees of freedom) at the noise level max(maxLineResidual, lineNoiseFactor *
//    sigma): it holds readings of two walls, or clutter. With splitNonLines it is cut at its
//    least-squares two-line breakpoint (TwoLineSplit.h), which becomes a joint (only where
//    the slope difference missed a corner), and both halves are tested again; a piece too
//    short or still no line is dropped, and its joints broken.
//  - With mergeCollinear, joined neighbours whose readings are one line after all (the
//    union's least-squares residual exceeds the two fits' by no more than noise explains, a
//    chi-square test at mean + 3 std) are merged: a wall split by a noise peak stays one wall.
//  - Each joint becomes a Corner (step 5, CornerIntersection.h) unless the fitted lines turn
//    by less than minCornerTurn (they would have been merged; or, at the other extreme, they
//    fold back onto each other), the intersection lies farther than maxCornerOffset from the
//    reading where the corner was detected (nearly parallel lines or a bad fit: the
//    intersection means nothing there), when rejectArcs is set, the two segments are pieces
//    of one small circle (ArcCornerTest.h), or, when cornerAngleSigmas > 0, its angle is
//    too vague: cornerAngleSigmas standard deviations of the angle (propagated from both
//    fits, angleStd in CornerIntersection.h) exceed minCornerTurn. minCornerTurn is the
//    smallest turn the extractor calls a corner, its angular resolution; a corner whose
//    angle is not known to within it (a wall seen over a few centimetres: at 1 cm noise, five
//    readings over 5 cm leave its direction ~20 deg uncertain) is a place where two walls
//    meet, not a corner with an angle. Its segments stay, their ends Open.
//  - Segment ends get their types (corner type, Jump, Open); endpoints lists every corner
//    (convex / concave) and every jump (the nearer reading of a range discontinuity).
// The result is in the scan's own beam order (ScanPoints::toScanOrder).
#include <toposlam/config/Options.h>
#include <toposlam/features/ArcCornerTest.h>
#include <toposlam/features/LineFit.h>
#include <toposlam/features/LinePart.h>
#include <toposlam/features/ScanFeatures.h>
#include <toposlam/features/ScanPoints.h>
#include <toposlam/features/TwoLineSplit.h>

#include <cmath>
#include <vector>

namespace toposlam::features {

/// Keys line_fit, min_segment_points, ... (see declare()). minCornerTurn is no key: the corner
/// extractor derives it from theta_th.
struct FeatureAssemblyOptions : public config::Options {
    LineFitMethod lineFit = LineFitMethod::TwoPoint;
    unsigned minSegmentPoints = 4;          ///< readings
    double minSegmentLength = 0;            ///< m, first to last reading
    double maxCornerOffset = 0.2;           ///< m, corner to the reading where it was detected
    double minCornerTurn = std::atan(0.3);  ///< rad; the corner paper's merge angle
    double maxLineResidual = 0.01;          ///< m, floor of the noise level of the line test
    double lineNoiseFactor = 1.5;           ///< line test noise level in range-noise sigmas
    bool splitNonLines = false;             ///< cut parts that fail the line test (see above)
    bool mergeCollinear = true;  ///< merge joined neighbours that are one line (see above)
    bool rejectArcs = true;
    double maxArcRadius = 1.0;     ///< m, see ArcCornerTest
    double cornerAngleSigmas = 0;  ///< angle-precision test (see above); 0 = off

    void declare(config::OptionsSchema& s) override;
};

class FeatureAssembly {
  public:
    FeatureAssemblyOptions options;

    /// `parts` is consumed (edited in place). sigma: sensor range noise (m), the floor of the
    /// point noise in corner covariances. `out` is cleared first.
    void assemble(ScanPoints& pts, std::vector<LinePart>& parts, double sigma, ScanFeatures& out);

  private:
    // The steps of assemble(), in order (see the file comment).
    void addJumps(const ScanPoints& pts, const std::vector<LinePart>& parts,
                  ScanFeatures& out) const;
    void dropShortParts(const ScanPoints& pts, std::vector<LinePart>& parts) const;
    void fitLines(const ScanPoints& pts, std::vector<LinePart>& parts, double sigma);
    void mergeCollinear(const ScanPoints& pts, std::vector<LinePart>& parts, double sigma);
    void addSegments(const ScanPoints& pts, const std::vector<LinePart>& parts,
                     ScanFeatures& out) const;
    void addCorners(const ScanPoints& pts, const std::vector<LinePart>& parts, double sigma,
                    ScanFeatures& out) const;

    bool tooShort(const ScanPoints& pts, const LinePart& p) const;
    /// The chi-square line test of a part of `count` readings with residual sum of squares rss.
    bool passesLineTest(double count, double rss) const;
    /// Parts i and i + 1 are pieces of one small circle (ArcCornerTest), no corner.
    bool isArcCorner(const ScanPoints& pts, const std::vector<LinePart>& parts, std::size_t i,
                     double sigma) const;

    std::vector<LineFit> fits_;                  // one per part, from step 4 on
    std::vector<LinePart> lineParts_, pending_;  // step 4's output and the parts still to test
    TwoLineSplit split_;
    double lineSigma_ = 0;  // noise level of the line test for the current scan (m)
};

}  // namespace toposlam::features
