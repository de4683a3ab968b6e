#pragma once
// The features of one 2D laser scan, as every extractor in TopoSLAM returns them: line
// segments, the corners where two segments meet, and the convex / concave / jump endpoints.
// All geometry is in the SENSOR frame (x forward, y left, metres, radians) unless a function
// says otherwise; transformed() moves a whole set into another frame.
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/math/TPoint2D.h>
#include <mrpt/poses/CPose2D.h>

#include <cstdint>
#include <vector>

namespace toposlam::features {

/// Kind of a segment end or of a salient scan point (graph-matching paper, sec. 2.1).
enum class EndpointType : std::uint8_t {
    Convex,   ///< bulges towards the sensor (corner of an obstacle)
    Concave,  ///< recedes from the sensor (corner of a room)
    Jump,     ///< the nearer point of a range discontinuity: an occluding edge (convex)
    Open      ///< the segment just ends (scan border, invalid readings, far side of a jump)
};

/// Infinite line in normal form: x*cos(theta) + y*sin(theta) = rho, rho >= 0 (m),
/// theta in [-pi, pi] (mrpt::math::wrapToPi). Well defined for every direction, vertical lines
/// included.
struct Line2D {
    double theta = 0;
    double rho = 0;
    /// Signed distance (m) of a point to the line.
    double distance(const mrpt::math::TPoint2D& p) const;
    /// Orthogonal projection of a point onto the line.
    mrpt::math::TPoint2D project(const mrpt::math::TPoint2D& p) const;
    /// Line through two distinct points.
    static Line2D through(const mrpt::math::TPoint2D& a, const mrpt::math::TPoint2D& b);
};

struct LineSegment {
    mrpt::math::TPoint2D start,
        end;                      ///< end points projected onto `line` (m); start = firstBeam side
    Line2D line;                  ///< the fitted line
    std::uint32_t firstBeam = 0;  ///< index of the first supporting beam in the scan
    std::uint32_t lastBeam = 0;   ///< index of the last supporting beam (inclusive)
    EndpointType startType = EndpointType::Open;
    EndpointType endType = EndpointType::Open;
    double residualRms = 0;  ///< RMS distance (m) of the supporting points to `line`
    double length() const;
    mrpt::math::TPoint2D midpoint() const;
};

struct Corner {
    mrpt::math::TPoint2D position;    ///< intersection of the two incident lines (m)
    std::uint32_t beam = 0;           ///< index of the scan beam at the joint of the two segments
    std::uint32_t segmentBefore = 0;  ///< index in ScanFeatures::segments, lower beam indices
    std::uint32_t segmentAfter = 0;   ///< index in ScanFeatures::segments, higher beam indices
    double angle = 0;  ///< angle between the two segments at the corner, rad in (0, pi)
    /// Position covariance (m^2), from the two line fits.
    mrpt::math::CMatrixDouble22 covariance = mrpt::math::CMatrixDouble22::Zero();
    EndpointType type = EndpointType::Convex;  ///< Convex or Concave, seen from the sensor
};

struct Endpoint {
    mrpt::math::TPoint2D position;  ///< m
    EndpointType type = EndpointType::Convex;
    std::uint32_t beam = 0;  ///< index of the beam in the scan
};

struct ScanFeatures {
    std::vector<LineSegment> segments;  ///< ordered by firstBeam (scan order)
    std::vector<Corner> corners;        ///< ordered by beam
    std::vector<Endpoint> endpoints;    ///< ordered by beam

    void clear();  ///< empties the sets, keeping their capacity (no allocation in loops)
    /// The same features in another frame: every point p becomes pose (+) p. Use the
    /// sensor's pose in the world to get world-frame features.
    ScanFeatures transformed(const mrpt::poses::CPose2D& pose) const;
};

const char* toString(EndpointType t);

}  // namespace toposlam::features
