#pragma once
// A map of a building's walls and corners: the line segments, corners and endpoints of many
// scans, moved into one frame (the MAP frame, x/y in metres) at the pose each scan was taken
// from, with repeated observations of the same wall or corner merged into one feature.
//  - Segments: an observed segment joins a map segment when both face the same way (the side
//    the sensor saw them from, within mergeAngle), its ends lie within mergeDistance of the
//    map segment's line and the two overlap or leave a gap of at most mergeGap along it. The
//    map segment's line is then the total-least-squares line of every segment merged into
//    it, each spread evenly along its length and weighted by its number of beams. Merging can
//    join two map segments (a wall seen in pieces); the two faces of a thin wall never merge
//    (they face opposite ways).
//  - Where the wall is: one wall LINE can hold several PIECES (collinear walls on both sides of
//    a door). A scan looking along a wall at a grazing angle may step over a door without a
//    single beam through it, so its segment bridges the door; a scan facing the wall shows
//    the opening. Each observation therefore counts its beams per metre along the line (5 cm
//    bins), and the pieces are the runs of bins with at least minCoverageRatio times the
//    line's median beam count (pieces shorter than minPieceLength are dropped): a door seen
//    only by grazing beams stays open, a wall seen only from afar stays whole.
//  - Corners (convex, concave) and endpoints (convex, concave, jump; open ends are not
//    physical points and are left out): an observation joins the nearest map point of the
//    same kind within the merge radius; corners are fused by their covariances (information
//    form, each covariance widened by poseStd for the pose's own error), endpoints averaged.
//  - A feature is confirmed once observed minObservations times; users (the likelihood,
//    pictures, exports) look at confirmed features only, so a single spurious observation
//    (a person, a reflection) never shows.
// Insertion costs O(features of the scan x features of the map); rebuilding from keyframes
// (CScanFeaturesMap) is just clear() and one insert() per keyframe.
#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/math/TPoint2D.h>
#include <mrpt/poses/CPose2D.h>
#include <toposlam/config/Options.h>
#include <toposlam/features/ScanFeatures.h>

#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

namespace toposlam::matching {

/// How observations merge into the map: keys of the scanFeaturesMap insertOpts section
/// (merge_angle_deg, merge_distance, ...; see declare()).
struct FeatureMapOptions : public config::Options {
    double mergeAngle = 5.0 * M_PI / 180;  ///< rad: facing directions this close may merge
    double mergeDistance = 0.08;           ///< m: ends this close to a map line may merge
    double mergeGap = 0.25;                ///< m: gap along the line bridged by a merge
    double minSegmentLength = 0.3;         ///< m: shorter observed segments are not inserted
    double cornerMergeRadius = 0.15;       ///< m
    double endpointMergeRadius = 0.15;     ///< m
    /// m: standard deviation of the insertion pose's position error, added to every corner's
    /// covariance before fusing (the extractor's covariance knows nothing of the pose).
    double poseStd = 0.02;
    std::uint32_t minObservations = 2;  ///< observations that make a feature confirmed
    double minCoverageRatio = 0.2;      ///< of the line's median beams per bin: a gap below it
    double minPieceLength = 0.1;        ///< m: shorter pieces of a line are dropped

    void declare(config::OptionsSchema& s) override;
};

/// Weighted first and second moments of a set of segments, each spread evenly along its
/// length (map frame): what the total-least-squares line through all of them needs.
struct SegmentMoments {
    double w = 0, x = 0, y = 0, xx = 0, xy = 0, yy = 0;
    void add(const mrpt::math::TPoint2D& a, const mrpt::math::TPoint2D& b, double weight);
    void add(const SegmentMoments& other);
    mrpt::math::TPoint2D centroid() const;
    /// Direction (rad, modulo pi) of the principal axis.
    double principalDirection() const;
};

/// A part of a map segment's line where there is wall (map frame, m; seen side on the left).
struct SegmentPiece {
    mrpt::math::TPoint2D start, end;
    double length() const;
};

/// How many beams fell on each 5 cm of a line: a histogram along a fixed axis (the direction
/// of the line's first observation, through its start). Adding an observation costs its own
/// length in bins, whatever the line already holds.
struct LineCoverage {
    static constexpr double kBin = 0.05;   ///< m
    mrpt::math::TPoint2D origin;           ///< map frame, m
    mrpt::math::TPoint2D direction{1, 0};  ///< unit
    long firstBin = 0;                     ///< index of beams[0] (bins before origin < 0)
    std::vector<double> beams;             ///< expected beam hits per bin

    /// Adds the segment a-b covered by `beamsPerMetre` beams per metre.
    void add(const mrpt::math::TPoint2D& a, const mrpt::math::TPoint2D& b, double beamsPerMetre);
    /// Adds another line's coverage, bin by bin at its bins' centres.
    void add(const LineCoverage& other);
    /// Position (m) of the point along the axis.
    double along(const mrpt::math::TPoint2D& p) const;

  private:
    void reserveBins(long first, long last);
};

/// One wall face of the map: a line and the pieces of it where wall was seen.
struct MapSegment {
    /// Extent of everything merged (map frame, m). The side the wall was seen from is on the
    /// LEFT of start -> end.
    mrpt::math::TPoint2D start, end;
    /// The parts of start-end with wall (see the file comment), in order from start.
    std::vector<SegmentPiece> pieces;
    std::uint32_t observations = 0;  ///< scan segments merged into it
    SegmentMoments moments;          ///< of every merged observation
    LineCoverage coverage;           ///< of every merged observation

    double length() const;
    /// Direction (rad) of the normal pointing to the side the wall was seen from.
    double facing() const;
};

/// A corner or an endpoint of the map.
struct MapPoint {
    mrpt::math::TPoint2D position;  ///< map frame, m
    /// Position covariance (m^2): corners, from the fused observations; endpoints, the spread
    /// of the merged observations (poseStd^2 for a single one).
    mrpt::math::CMatrixDouble22 covariance = mrpt::math::CMatrixDouble22::Zero();
    features::EndpointType type = features::EndpointType::Convex;
    double angle = 0;  ///< corners: mean angle between the two walls (rad); endpoints: 0
    std::uint32_t observations = 0;
    // Fusion state: information matrix and vector (corners); sums of positions (endpoints).
    mrpt::math::CMatrixDouble22 information = mrpt::math::CMatrixDouble22::Zero();
    double infoX = 0, infoY = 0;
    double sumX = 0, sumY = 0, sumXX = 0, sumXY = 0, sumYY = 0, sumAngle = 0;
};

class FeatureMap {
  public:
    FeatureMapOptions options;

    void clear();
    /// Merges the features of one scan, given in its SENSOR frame, taken with the sensor at
    /// `sensorPose` (map frame).
    void insert(const features::ScanFeatures& sensorFrame, const mrpt::poses::CPose2D& sensorPose);

    /// Every feature, confirmed or not.
    const std::vector<MapSegment>& segments() const { return segments_; }
    const std::vector<MapPoint>& corners() const { return corners_; }
    const std::vector<MapPoint>& endpoints() const { return endpoints_; }
    bool confirmed(const MapSegment& s) const { return s.observations >= options.minObservations; }
    bool confirmed(const MapPoint& p) const { return p.observations >= options.minObservations; }
    std::size_t confirmedSegments() const;
    /// Pieces of the confirmed segments (what pictures and files show as wall segments).
    std::size_t confirmedPieces() const;
    std::size_t confirmedCorners() const;
    std::size_t confirmedEndpoints() const;
    /// No feature at all (confirmed or not).
    bool empty() const;

    /// Distance (m) from `p` (map frame) to the nearest piece of a confirmed segment, or
    /// `maxDistance` when none is nearer.
    double distanceToSegments(const mrpt::math::TPoint2D& p, double maxDistance) const;

  private:
    void insertSegment(mrpt::math::TPoint2D a, mrpt::math::TPoint2D b,
                       const mrpt::math::TPoint2D& sensor, double weight);
    /// Merges into segments_[i] every other segment that now qualifies; returns i's new index.
    std::size_t absorbSegments(std::size_t i);
    /// Recomputes the pieces of `s` from its observations.
    void updatePieces(MapSegment& s) const;
    void insertPoint(std::vector<MapPoint>& points, const MapPoint& observation, double radius,
                     bool fuseByCovariance);

    std::vector<MapSegment> segments_;
    std::vector<MapPoint> corners_, endpoints_;
};

/// Distance (m) from `p` to the segment a-b.
double pointToSegmentDistance(const mrpt::math::TPoint2D& p, const mrpt::math::TPoint2D& a,
                              const mrpt::math::TPoint2D& b);

}  // namespace toposlam::matching
