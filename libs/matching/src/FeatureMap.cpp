#include <toposlam/matching/FeatureMap.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <stdexcept>

namespace toposlam::matching {

using features::EndpointType;
using mrpt::math::TPoint2D;

namespace {

double wrapToPi(double a) {
    return std::remainder(a, 2 * M_PI);
}

double dot(const TPoint2D& a, const TPoint2D& b) {
    return a.x * b.x + a.y * b.y;
}

TPoint2D unit(double angle) {
    return {std::cos(angle), std::sin(angle)};
}

/// Line of a map segment: a point on it, its unit direction (start -> end) and the left
/// normal (the side it was seen from).
struct SegmentLine {
    TPoint2D origin, direction, normal;
    explicit SegmentLine(const MapSegment& s) {
        origin = s.moments.centroid();
        const double len = s.length();
        direction = len > 0 ? TPoint2D((s.end.x - s.start.x) / len, (s.end.y - s.start.y) / len)
                            : TPoint2D(1, 0);
        normal = {-direction.y, direction.x};
    }
    double along(const TPoint2D& p) const { return dot(p - origin, direction); }
    double across(const TPoint2D& p) const { return dot(p - origin, normal); }
};

/// Whether the piece a-b (facing `facing`) may merge into map segment `s`.
bool mergeable(const MapSegment& s, const TPoint2D& a, const TPoint2D& b, double facing,
               const FeatureMapOptions& o) {
    // Bounding boxes first (cheap, and most map segments are far away).
    const double margin = o.mergeGap + o.mergeDistance;
    if (std::max(a.x, b.x) < std::min(s.start.x, s.end.x) - margin ||
        std::min(a.x, b.x) > std::max(s.start.x, s.end.x) + margin ||
        std::max(a.y, b.y) < std::min(s.start.y, s.end.y) - margin ||
        std::min(a.y, b.y) > std::max(s.start.y, s.end.y) + margin)
        return false;
    if (std::abs(wrapToPi(facing - s.facing())) > o.mergeAngle)
        return false;
    const SegmentLine line(s);
    if (std::abs(line.across(a)) > o.mergeDistance || std::abs(line.across(b)) > o.mergeDistance)
        return false;
    const double t0 = line.along(s.start), t1 = line.along(s.end);
    const double u0 = std::min(line.along(a), line.along(b));
    const double u1 = std::max(line.along(a), line.along(b));
    return std::max(u0 - t1, t0 - u1) <= o.mergeGap;
}

/// Refits `s` from its moments; its extent covers its old ends and `extra`.
void refit(MapSegment& s, const TPoint2D* extra, std::size_t extraCount) {
    const double oldFacing = s.facing();
    const TPoint2D c = s.moments.centroid();
    TPoint2D d = unit(s.moments.principalDirection());
    // Keep the seen side on the left: left normal (-d.y, d.x) must agree with the old facing.
    if (dot({-d.y, d.x}, unit(oldFacing)) < 0)
        d = {-d.x, -d.y};
    double tMin = dot(s.start - c, d), tMax = dot(s.end - c, d);
    if (tMin > tMax)
        std::swap(tMin, tMax);
    for (std::size_t k = 0; k < extraCount; ++k) {
        const double t = dot(extra[k] - c, d);
        tMin = std::min(tMin, t);
        tMax = std::max(tMax, t);
    }
    s.start = {c.x + tMin * d.x, c.y + tMin * d.y};
    s.end = {c.x + tMax * d.x, c.y + tMax * d.y};
}

void mergeSegmentInto(MapSegment& into, const MapSegment& from) {
    into.moments.add(from.moments);
    into.observations += from.observations;
    into.coverage.add(from.coverage);
    const TPoint2D ends[2] = {from.start, from.end};
    refit(into, ends, 2);
}

}  // namespace

// --- options -------------------------------------------------------------------------------

void FeatureMapOptions::declare(config::OptionsSchema& s) {
    s.angle("merge_angle", mergeAngle, "facing directions this close may merge")
        .above(0)
        .atMost(90);
    s.real("merge_distance", mergeDistance, "m", "ends this close to a map line may merge")
        .above(0);
    s.real("merge_gap", mergeGap, "m", "gap along the line bridged by a merge").atLeast(0);
    s.real("min_segment_length", minSegmentLength, "m",
           "shorter observed segments are not inserted")
        .atLeast(0);
    s.real("corner_merge_radius", cornerMergeRadius, "m", "corners this close merge").above(0);
    s.real("endpoint_merge_radius", endpointMergeRadius, "m", "endpoints this close merge")
        .above(0);
    s.real("pose_std", poseStd, "m",
           "std of the insertion pose's position error, added to every corner's covariance")
        .above(0);
    s.integer("min_observations", minObservations, "", "observations that make a feature confirmed")
        .within(1, 1000000);
    s.real("min_coverage_ratio", minCoverageRatio, "",
           "of the line's median beams per bin: a gap below it splits the line into pieces")
        .within(0, 1);
    s.real("min_piece_length", minPieceLength, "m", "shorter pieces of a line are dropped")
        .atLeast(0);
}

// --- moments -------------------------------------------------------------------------------

void SegmentMoments::add(const TPoint2D& a, const TPoint2D& b, double weight) {
    // Uniform on a-b: mean m, E[p p^T] = m m^T + (b-a)(b-a)^T / 12.
    const double mx = 0.5 * (a.x + b.x), my = 0.5 * (a.y + b.y);
    const double dx = b.x - a.x, dy = b.y - a.y;
    w += weight;
    x += weight * mx;
    y += weight * my;
    xx += weight * (mx * mx + dx * dx / 12);
    xy += weight * (mx * my + dx * dy / 12);
    yy += weight * (my * my + dy * dy / 12);
}

void SegmentMoments::add(const SegmentMoments& o) {
    w += o.w;
    x += o.x;
    y += o.y;
    xx += o.xx;
    xy += o.xy;
    yy += o.yy;
}

TPoint2D SegmentMoments::centroid() const {
    return w > 0 ? TPoint2D(x / w, y / w) : TPoint2D(0, 0);
}

double SegmentMoments::principalDirection() const {
    const TPoint2D c = centroid();
    const double cxx = xx / w - c.x * c.x, cxy = xy / w - c.x * c.y, cyy = yy / w - c.y * c.y;
    return 0.5 * std::atan2(2 * cxy, cxx - cyy);
}

// --- segments and points -------------------------------------------------------------------

double SegmentPiece::length() const {
    return std::hypot(end.x - start.x, end.y - start.y);
}

double MapSegment::length() const {
    return std::hypot(end.x - start.x, end.y - start.y);
}

double MapSegment::facing() const {
    // Left normal of start -> end.
    return std::atan2(end.x - start.x, -(end.y - start.y));
}

double pointToSegmentDistance(const TPoint2D& p, const TPoint2D& a, const TPoint2D& b) {
    const TPoint2D ab = b - a, ap = p - a;
    const double len2 = dot(ab, ab);
    const double t = len2 > 0 ? std::clamp(dot(ap, ab) / len2, 0.0, 1.0) : 0.0;
    return std::hypot(ap.x - t * ab.x, ap.y - t * ab.y);
}

// --- the map -------------------------------------------------------------------------------

void FeatureMap::clear() {
    segments_.clear();
    corners_.clear();
    endpoints_.clear();
}

bool FeatureMap::empty() const {
    return segments_.empty() && corners_.empty() && endpoints_.empty();
}

std::size_t FeatureMap::confirmedSegments() const {
    return static_cast<std::size_t>(std::count_if(
        segments_.begin(), segments_.end(), [&](const MapSegment& s) { return confirmed(s); }));
}

std::size_t FeatureMap::confirmedPieces() const {
    std::size_t n = 0;
    for (const MapSegment& s : segments_)
        n += confirmed(s) ? s.pieces.size() : 0;
    return n;
}

std::size_t FeatureMap::confirmedCorners() const {
    return static_cast<std::size_t>(std::count_if(corners_.begin(), corners_.end(),
                                                  [&](const MapPoint& p) { return confirmed(p); }));
}

std::size_t FeatureMap::confirmedEndpoints() const {
    return static_cast<std::size_t>(std::count_if(endpoints_.begin(), endpoints_.end(),
                                                  [&](const MapPoint& p) { return confirmed(p); }));
}

void FeatureMap::insert(const features::ScanFeatures& f, const mrpt::poses::CPose2D& sensorPose) {
    const TPoint2D sensor(sensorPose.x(), sensorPose.y());
    const double c = std::cos(sensorPose.phi()), s = std::sin(sensorPose.phi());
    const auto toMap = [&](const TPoint2D& p) {
        return TPoint2D(sensor.x + c * p.x - s * p.y, sensor.y + s * p.x + c * p.y);
    };
    for (const features::LineSegment& seg : f.segments) {
        const double beams = static_cast<double>(seg.lastBeam) - seg.firstBeam + 1;
        insertSegment(toMap(seg.start), toMap(seg.end), sensor, std::max(2.0, beams));
    }
    const double poseVar = options.poseStd * options.poseStd;
    for (const features::Corner& corner : f.corners) {
        MapPoint p;
        p.position = toMap(corner.position);
        p.type = corner.type;
        p.angle = corner.angle;
        // R C R^T, widened by the pose's error.
        const auto& C = corner.covariance;
        const double a = C(0, 0), b = C(0, 1), d = C(1, 1);
        p.covariance(0, 0) = c * c * a - 2 * c * s * b + s * s * d + poseVar;
        p.covariance(0, 1) = p.covariance(1, 0) = c * s * (a - d) + (c * c - s * s) * b;
        p.covariance(1, 1) = s * s * a + 2 * c * s * b + c * c * d + poseVar;
        insertPoint(corners_, p, options.cornerMergeRadius, true);
    }
    for (const features::Endpoint& e : f.endpoints) {
        if (e.type == EndpointType::Open)
            continue;
        MapPoint p;
        p.position = toMap(e.position);
        p.type = e.type;
        insertPoint(endpoints_, p, options.endpointMergeRadius, false);
    }
}

void FeatureMap::insertSegment(TPoint2D a, TPoint2D b, const TPoint2D& sensor, double weight) {
    const TPoint2D ab = b - a;
    const double length = std::hypot(ab.x, ab.y);
    if (length < std::max(options.minSegmentLength, 1e-9))
        return;
    // Orient a -> b so that the sensor is on the left.
    if (dot({-ab.y, ab.x}, sensor - a) < 0)
        std::swap(a, b);
    const double facing = std::atan2(b.x - a.x, -(b.y - a.y));

    std::size_t best = segments_.size();
    double bestDistance = 0;
    for (std::size_t i = 0; i < segments_.size(); ++i) {
        if (!mergeable(segments_[i], a, b, facing, options))
            continue;
        const SegmentLine line(segments_[i]);
        const double d = std::abs(line.across(a)) + std::abs(line.across(b));
        if (best == segments_.size() || d < bestDistance) {
            best = i;
            bestDistance = d;
        }
    }
    MapSegment observed;
    observed.start = a;
    observed.end = b;
    observed.observations = 1;
    observed.moments.add(a, b, weight);
    observed.coverage.origin = a;
    observed.coverage.direction = {ab.x / length, ab.y / length};
    observed.coverage.add(a, b, weight / length);
    if (best == segments_.size()) {
        updatePieces(observed);
        segments_.push_back(std::move(observed));
        return;
    }
    mergeSegmentInto(segments_[best], observed);
    const std::size_t i = absorbSegments(best);
    updatePieces(segments_[i]);
}

void FeatureMap::updatePieces(MapSegment& s) const {
    s.pieces.clear();
    const LineCoverage& c = s.coverage;
    std::vector<double> nonEmpty;
    for (double b : c.beams)
        if (b > 0)
            nonEmpty.push_back(b);
    if (nonEmpty.empty())
        return;
    std::nth_element(nonEmpty.begin(), nonEmpty.begin() + nonEmpty.size() / 2, nonEmpty.end());
    const double threshold =
        std::max(options.minCoverageRatio * nonEmpty[nonEmpty.size() / 2], 1e-12);
    // Pieces run along the fitted line: bin edges are projected onto it, within its extent.
    const SegmentLine line(s);
    const double tStart = line.along(s.start), tEnd = line.along(s.end);
    const auto onLine = [&](long bin) {
        const double t = static_cast<double>(bin) * LineCoverage::kBin;
        const TPoint2D axis(c.origin.x + t * c.direction.x, c.origin.y + t * c.direction.y);
        return std::clamp(line.along(axis), std::min(tStart, tEnd), std::max(tStart, tEnd));
    };
    const auto at = [&](double t) {
        return TPoint2D(line.origin.x + t * line.direction.x, line.origin.y + t * line.direction.y);
    };
    const long n = static_cast<long>(c.beams.size());
    for (long k = 0; k < n;) {
        if (c.beams[k] < threshold) {
            ++k;
            continue;
        }
        long e = k;
        while (e < n && c.beams[e] >= threshold)
            ++e;
        double t0 = onLine(c.firstBin + k), t1 = onLine(c.firstBin + e);
        if (t0 > t1)
            std::swap(t0, t1);
        if (t1 - t0 >= options.minPieceLength)
            s.pieces.push_back({at(t0), at(t1)});
        k = e;
    }
    // In start -> end order.
    if (tStart > tEnd)
        std::reverse(s.pieces.begin(), s.pieces.end());
    for (SegmentPiece& p : s.pieces)
        if (line.along(p.start) > line.along(p.end))
            std::swap(p.start, p.end);
}

// --- coverage ------------------------------------------------------------------------------

double LineCoverage::along(const TPoint2D& p) const {
    return dot(p - origin, direction);
}

void LineCoverage::reserveBins(long first, long last) {
    if (beams.empty()) {
        firstBin = first;
        beams.assign(static_cast<std::size_t>(last - first + 1), 0.0);
        return;
    }
    if (first < firstBin) {
        beams.insert(beams.begin(), static_cast<std::size_t>(firstBin - first), 0.0);
        firstBin = first;
    }
    const long end = firstBin + static_cast<long>(beams.size());
    if (last >= end)
        beams.resize(beams.size() + static_cast<std::size_t>(last - end + 1), 0.0);
}

void LineCoverage::add(const TPoint2D& a, const TPoint2D& b, double beamsPerMetre) {
    double t0 = along(a), t1 = along(b);
    if (t0 > t1)
        std::swap(t0, t1);
    const long k0 = static_cast<long>(std::floor(t0 / kBin));
    const long k1 = static_cast<long>(std::floor(t1 / kBin));
    reserveBins(k0, k1);
    for (long k = k0; k <= k1; ++k) {
        const double lo = std::max(t0, k * kBin), hi = std::min(t1, (k + 1) * kBin);
        beams[static_cast<std::size_t>(k - firstBin)] += beamsPerMetre * std::max(0.0, hi - lo);
    }
}

void LineCoverage::add(const LineCoverage& other) {
    for (std::size_t i = 0; i < other.beams.size(); ++i) {
        if (other.beams[i] <= 0)
            continue;
        const double t = (static_cast<double>(other.firstBin + static_cast<long>(i)) + 0.5) * kBin;
        const TPoint2D centre(other.origin.x + t * other.direction.x,
                              other.origin.y + t * other.direction.y);
        const long k = static_cast<long>(std::floor(along(centre) / kBin));
        reserveBins(k, k);
        beams[static_cast<std::size_t>(k - firstBin)] += other.beams[i];
    }
}

std::size_t FeatureMap::absorbSegments(std::size_t i) {
    for (bool merged = true; merged;) {
        merged = false;
        for (std::size_t j = 0; j < segments_.size(); ++j) {
            if (j == i)
                continue;
            // The shorter one is tested against the longer one's line.
            const MapSegment& a = segments_[i];
            const MapSegment& b = segments_[j];
            const bool ok = a.length() >= b.length()
                                ? mergeable(a, b.start, b.end, b.facing(), options)
                                : mergeable(b, a.start, a.end, a.facing(), options);
            if (!ok)
                continue;
            mergeSegmentInto(segments_[i], segments_[j]);
            // Remove j by moving the last segment into its place.
            if (j != segments_.size() - 1)
                segments_[j] = segments_.back();
            if (i == segments_.size() - 1)
                i = j;
            segments_.pop_back();
            merged = true;
            break;
        }
    }
    return i;
}

namespace {

/// Adds one observation (or another map point) to `into`.
void fusePoint(MapPoint& into, const MapPoint& obs, bool byCovariance) {
    into.observations += obs.observations;
    into.sumAngle += obs.sumAngle;
    into.angle = into.sumAngle / into.observations;
    if (byCovariance) {
        into.information += obs.information;
        into.infoX += obs.infoX;
        into.infoY += obs.infoY;
        into.covariance = into.information.inverse_LLt();
        into.position.x = into.covariance(0, 0) * into.infoX + into.covariance(0, 1) * into.infoY;
        into.position.y = into.covariance(1, 0) * into.infoX + into.covariance(1, 1) * into.infoY;
        return;
    }
    into.sumX += obs.sumX;
    into.sumY += obs.sumY;
    into.sumXX += obs.sumXX;
    into.sumXY += obs.sumXY;
    into.sumYY += obs.sumYY;
    const double n = into.observations;
    into.position = {into.sumX / n, into.sumY / n};
}

}  // namespace

void FeatureMap::insertPoint(std::vector<MapPoint>& points, const MapPoint& observation,
                             double radius, bool fuseByCovariance) {
    MapPoint obs = observation;
    obs.observations = 1;
    obs.sumAngle = obs.angle;
    if (fuseByCovariance) {
        obs.information = obs.covariance.inverse_LLt();
        obs.infoX = obs.information(0, 0) * obs.position.x + obs.information(0, 1) * obs.position.y;
        obs.infoY = obs.information(1, 0) * obs.position.x + obs.information(1, 1) * obs.position.y;
    } else {
        const double var = options.poseStd * options.poseStd;
        obs.covariance(0, 0) = obs.covariance(1, 1) = var;
        obs.sumX = obs.position.x;
        obs.sumY = obs.position.y;
        obs.sumXX = obs.position.x * obs.position.x;
        obs.sumXY = obs.position.x * obs.position.y;
        obs.sumYY = obs.position.y * obs.position.y;
    }
    const auto nearest = [&](const TPoint2D& p, std::size_t skip) {
        std::size_t best = points.size();
        double bestDistance = radius;
        for (std::size_t i = 0; i < points.size(); ++i) {
            if (i == skip || points[i].type != obs.type)
                continue;
            const double dx = points[i].position.x - p.x, dy = points[i].position.y - p.y;
            if (std::abs(dx) > bestDistance || std::abs(dy) > bestDistance)
                continue;
            const double d = std::hypot(dx, dy);
            if (d <= bestDistance) {
                best = i;
                bestDistance = d;
            }
        }
        return best;
    };
    std::size_t i = nearest(obs.position, points.size());
    if (i == points.size()) {
        points.push_back(obs);
        return;
    }
    fusePoint(points[i], obs, fuseByCovariance);
    // The moved point may now lie within reach of another one: join them.
    for (std::size_t j = nearest(points[i].position, i); j != points.size();
         j = nearest(points[i].position, i)) {
        fusePoint(points[i], points[j], fuseByCovariance);
        if (j != points.size() - 1)
            points[j] = points.back();
        if (i == points.size() - 1)
            i = j;
        points.pop_back();
    }
    if (!fuseByCovariance) {
        // Spread of the merged positions plus a single observation's variance.
        MapPoint& p = points[i];
        const double n = p.observations, var = options.poseStd * options.poseStd;
        p.covariance(0, 0) = std::max(0.0, p.sumXX / n - p.position.x * p.position.x) + var;
        p.covariance(1, 1) = std::max(0.0, p.sumYY / n - p.position.y * p.position.y) + var;
        p.covariance(0, 1) = p.covariance(1, 0) = p.sumXY / n - p.position.x * p.position.y;
    }
}

double FeatureMap::distanceToSegments(const TPoint2D& p, double maxDistance) const {
    double best = maxDistance;
    for (const MapSegment& s : segments_) {
        if (!confirmed(s))
            continue;
        // Bounding-box test first: most segments are far away.
        if (p.x < std::min(s.start.x, s.end.x) - best ||
            p.x > std::max(s.start.x, s.end.x) + best ||
            p.y < std::min(s.start.y, s.end.y) - best || p.y > std::max(s.start.y, s.end.y) + best)
            continue;
        for (const SegmentPiece& piece : s.pieces)
            best = std::min(best, pointToSegmentDistance(p, piece.start, piece.end));
    }
    return best;
}

}  // namespace toposlam::matching
