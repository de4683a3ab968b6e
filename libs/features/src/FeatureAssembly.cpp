#include <toposlam/features/CornerIntersection.h>
#include <toposlam/features/FeatureAssembly.h>
#include <toposlam/features/LeastSquaresLineFit.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <stdexcept>

namespace toposlam::features {

using mrpt::math::TPoint2D;

void FeatureAssemblyOptions::declare(config::OptionsSchema& s) {
    s.choice(
        "line_fit", lineFit,
        {{"two_point", LineFitMethod::TwoPoint}, {"least_squares", LineFitMethod::LeastSquares}},
        "fit of each segment: two_point (corner paper, step 4) or least_squares");
    s.integer("min_segment_points", minSegmentPoints, "readings",
              "shorter segments are dropped (their neighbours joined)")
        .within(2, 100000);
    s.real("min_segment_length", minSegmentLength, "m", "likewise, first to last reading")
        .atLeast(0);
    s.real("max_corner_offset", maxCornerOffset, "m",
           "reject corners this far from the reading where they were found")
        .above(0);
    s.real("max_line_residual", maxLineResidual, "m",
           "floor of the noise level in the line (chi-square) test")
        .above(0);
    s.real("line_noise_factor", lineNoiseFactor, "", "line test noise level, in range-noise sigmas")
        .atLeast(0);
    s.flag("split_non_lines", splitNonLines,
           "cut a part that is no line at its two-line breakpoint and test both halves");
    s.flag("merge_collinear", mergeCollinear,
           "merge joined neighbours that are one line within the noise");
    s.flag("reject_arcs", rejectArcs, "no corners on round objects (circle vs two lines)");
    s.real("max_arc_radius", maxArcRadius, "m", "larger arcs are treated as walls").above(0);
    s.real("corner_angle_sigmas", cornerAngleSigmas, "",
           "no corner whose angle std times this exceeds the smallest corner turn; 0 = off")
        .atLeast(0);
}

void FeatureAssembly::assemble(ScanPoints& pts, std::vector<LinePart>& parts, double sigma,
                               ScanFeatures& out) {
    out.clear();
    addJumps(pts, parts, out);
    dropShortParts(pts, parts);
    fitLines(pts, parts, sigma);        // step 4
    mergeCollinear(pts, parts, sigma);  // a split by noise
    addSegments(pts, parts, out);
    addCorners(pts, parts, sigma, out);  // step 5
    std::sort(out.endpoints.begin(), out.endpoints.end(),
              [](const Endpoint& x, const Endpoint& y) { return x.beam < y.beam; });
    pts.toScanOrder(out);
}

bool FeatureAssembly::tooShort(const ScanPoints& pts, const LinePart& p) const {
    if (p.size() < std::max(2u, options.minSegmentPoints))
        return true;
    if (options.minSegmentLength <= 0)
        return false;
    return std::hypot(pts.x(p.end) - pts.x(p.begin), pts.y(p.end) - pts.y(p.begin)) <
           options.minSegmentLength;
}

void FeatureAssembly::addJumps(const ScanPoints& pts, const std::vector<LinePart>& parts,
                               ScanFeatures& out) const {
    // Before short parts vanish.
    for (const LinePart& p : parts) {
        if (p.beginType == EndpointType::Jump) {
            out.endpoints.push_back({pts.point(p.begin), EndpointType::Jump, p.begin});
        }
        if (p.endType == EndpointType::Jump) {
            out.endpoints.push_back({pts.point(p.end), EndpointType::Jump, p.end});
        }
    }
}

void FeatureAssembly::dropShortParts(const ScanPoints& pts, std::vector<LinePart>& parts) const {
    // Join the neighbours of a short part that sat between two corners.
    std::size_t kept = 0;
    bool prevJoined = false;  // the last kept part is joined to the part being looked at
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const LinePart p = parts[i];
        if (!tooShort(pts, p)) {
            parts[kept++] = p;
            prevJoined = p.cornerAfter;
            continue;
        }
        if (kept > 0 && prevJoined) {
            LinePart& prev = parts[kept - 1];
            if (p.cornerAfter) {
                prev.joint = (p.begin + p.end) / 2;  // the corner is around the short part
            } else {
                prev.cornerAfter = false;
                prev.endType = EndpointType::Open;
                prevJoined = false;
            }
        } else {
            prevJoined = false;
        }
    }
    parts.resize(kept);
    if (kept > 0 && parts[kept - 1].cornerAfter)
        parts[kept - 1].cornerAfter = false;
}

bool FeatureAssembly::passesLineTest(double count, double rss) const {
    // Chi-square test on the residual: a true line of N readings leaves a sum of squares of
    // about (N - 2) s^2; allow mean + 3 std, with s the range noise made 50 % more generous
    // (sensors state their noise optimistically), at least maxLineResidual.
    const double dof = std::max(1.0, count - 2);
    return rss <= lineSigma_ * lineSigma_ * (dof + 3 * std::sqrt(2 * dof));
}

void FeatureAssembly::fitLines(const ScanPoints& pts, std::vector<LinePart>& parts, double sigma) {
    // A part whose readings are no line (residual beyond the noise) spans two walls whose
    // corner the slope difference missed, or is clutter. With splitNonLines it is cut at its
    // least-squares two-line breakpoint (TwoLineSplit.h), that reading left out as a joint, and
    // each half is tested again; otherwise, or once a piece is too short, it is dropped like a
    // short part, breaking its joints.
    lineSigma_ = std::max(options.maxLineResidual, options.lineNoiseFactor * sigma);
    lineParts_.clear();
    fits_.clear();
    bool brokenBefore = false;  // the part dropped before this one was joined to it
    for (std::size_t i = 0; i < parts.size(); ++i) {
        pending_.clear();
        pending_.push_back(parts[i]);
        bool prepared = false;  // split_ holds the sums of parts[i]
        while (!pending_.empty()) {
            LinePart p = pending_.back();
            pending_.pop_back();
            const bool canFit = !tooShort(pts, p);
            // A piece of a cut part whose least-squares residual (from the sums, no pass over
            // the readings) already fails the test fails it with any fit: no need to fit it.
            const bool hopeless =
                prepared && canFit &&
                !passesLineTest(static_cast<double>(p.size()), split_.residual(p.begin, p.end));
            const LineFit fit =
                canFit && !hopeless ? fitLine(options.lineFit, pts, p.begin, p.end) : LineFit{};
            if (fit.ok &&
                passesLineTest(fit.count, fit.count * fit.residualRms * fit.residualRms)) {
                if (brokenBefore && p.beginType != EndpointType::Jump)
                    p.beginType = EndpointType::Open;
                brokenBefore = false;
                fits_.push_back(fit);
                lineParts_.push_back(p);
                continue;
            }
            if (canFit && options.splitNonLines && !prepared) {
                split_.prepare(pts, parts[i].begin, parts[i].end);
                prepared = true;
            }
            std::size_t k = 0;
            if (canFit && options.splitNonLines &&
                split_.find(p.begin, p.end, options.minSegmentPoints, k)) {
                LinePart before = p, after = p;
                before.end = static_cast<std::uint32_t>(k - 1);
                before.cornerAfter = true;
                before.joint = static_cast<std::uint32_t>(k);
                before.endType = EndpointType::Open;
                after.begin = static_cast<std::uint32_t>(k + 1);
                after.beginType = EndpointType::Open;
                pending_.push_back(after);
                pending_.push_back(before);
                continue;
            }
            if (!lineParts_.empty() && lineParts_.back().cornerAfter) {
                lineParts_.back().cornerAfter = false;
                lineParts_.back().endType = EndpointType::Open;
            }
            brokenBefore = p.cornerAfter;
        }
    }
    parts.swap(lineParts_);
}

void FeatureAssembly::mergeCollinear(const ScanPoints& pts, std::vector<LinePart>& parts,
                                     double sigma) {
    // Neighbours that are one line after all: a split by noise. The union's least-squares
    // residual is compared with the two fits': if both lie on one line, the union's sum of
    // squares exceeds theirs by about (gap + 2) sigma^2 (chi-square, gap = readings between
    // them); a real corner adds far more. Merge below that mean + 3 standard deviations.
    const std::size_t kept = parts.size();
    if (!options.mergeCollinear || kept <= 1)
        return;
    const double var = std::max(sigma, 1e-5) * std::max(sigma, 1e-5);
    const auto rss = [](const LineFit& f) { return f.count * f.residualRms * f.residualRms; };
    std::size_t m = 0;
    for (std::size_t i = 1; i < kept; ++i) {
        LinePart& last = parts[m];
        if (last.cornerAfter) {
            // The union's sums from the two fits' and the readings between: no new pass.
            PointSums sums = fits_[m].sums;
            sums.merge(fits_[i].sums);
            for (std::size_t k = last.end + 1; k < parts[i].begin; ++k) {
                sums.add(pts.x(k), pts.y(k));
            }
            const LineFit joint = fitLeastSquares(sums);
            const double gap = static_cast<double>(parts[i].begin - last.end - 1);
            const double excess = rss(joint) - rss(fits_[m]) - rss(fits_[i]);
            const double dof = gap + 2;
            if (joint.ok && excess <= var * (dof + 3 * std::sqrt(2 * dof))) {
                last.end = parts[i].end;
                last.cornerAfter = parts[i].cornerAfter;
                last.joint = parts[i].joint;
                last.endType = parts[i].endType;
                fits_[m] = options.lineFit == LineFitMethod::LeastSquares
                               ? joint
                               : fitLine(options.lineFit, pts, last.begin, last.end);
                continue;
            }
        }
        ++m;
        parts[m] = parts[i];
        fits_[m] = fits_[i];
    }
    parts.resize(m + 1);
}

void FeatureAssembly::addSegments(const ScanPoints& pts, const std::vector<LinePart>& parts,
                                  ScanFeatures& out) const {
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const LinePart& p = parts[i];
        LineSegment s;
        s.line = fits_[i].line;
        s.start = s.line.project(pts.point(p.begin));
        s.end = s.line.project(pts.point(p.end));
        s.firstBeam = p.begin;
        s.lastBeam = p.end;
        s.startType = p.beginType;
        s.endType = p.endType;
        s.residualRms = fits_[i].residualRms;
        out.segments.push_back(s);
    }
}

bool FeatureAssembly::isArcCorner(const ScanPoints& pts, const std::vector<LinePart>& parts,
                                  std::size_t i, double sigma) const {
    // A segment measurably straight (its sagitta on a circle of maxArcRadius, L^2 / 8R,
    // beyond 3 sigma of its own noise) cannot be a piece of such a circle: skip the test.
    const auto straight = [&](std::size_t k) {
        const LinePart& p = parts[k];
        const double l2 = sq2(pts.x(p.end) - pts.x(p.begin), pts.y(p.end) - pts.y(p.begin));
        return l2 / (8 * options.maxArcRadius) > 3 * std::sqrt(pointVariance(fits_[k], sigma));
    };
    if (straight(i) || straight(i + 1))
        return false;
    ArcCornerTest arcTest;
    arcTest.maxRadius = options.maxArcRadius;
    const double na = fits_[i].count, nb = fits_[i + 1].count;
    const double ra = fits_[i].residualRms, rb = fits_[i + 1].residualRms;
    return arcTest.isArc(pts, parts[i].begin, parts[i].end, parts[i + 1].begin, parts[i + 1].end,
                         na * ra * ra + nb * rb * rb, sigma);
}

void FeatureAssembly::addCorners(const ScanPoints& pts, const std::vector<LinePart>& parts,
                                 double sigma, ScanFeatures& out) const {
    for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
        if (!parts[i].cornerAfter)
            continue;
        LineSegment &a = out.segments[i], &b = out.segments[i + 1];
        Corner c;
        const bool ok = fits_[i].ok && fits_[i + 1].ok &&
                        intersectCorner(fits_[i], fits_[i + 1], a.start, b.end, sigma, c);
        const TPoint2D joint = pts.point(parts[i].joint);
        const bool vague =
            ok && options.cornerAngleSigmas * angleStd(fits_[i], fits_[i + 1], sigma) >
                      options.minCornerTurn;
        if (!ok || vague || M_PI - c.angle < options.minCornerTurn ||
            c.angle < options.minCornerTurn ||
            sq2(c.position.x - joint.x, c.position.y - joint.y) >
                options.maxCornerOffset * options.maxCornerOffset ||
            (options.rejectArcs && isArcCorner(pts, parts, i, sigma))) {
            a.endType = EndpointType::Open;
            b.startType = EndpointType::Open;
            continue;
        }
        c.beam = parts[i].joint;
        c.segmentBefore = static_cast<std::uint32_t>(i);
        c.segmentAfter = static_cast<std::uint32_t>(i + 1);
        a.endType = c.type;
        b.startType = c.type;
        out.corners.push_back(c);
        out.endpoints.push_back({c.position, c.type, c.beam});
    }
}

}  // namespace toposlam::features
