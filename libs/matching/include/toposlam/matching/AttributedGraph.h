#pragma once
// The attributed graph of one scan's line segments (graph-matching paper, sec. 2.2):
// every segment is a node whose attribute A is its length; every ordered pair of segments is
// an edge with r = 4 attributes B_g:
//   g = 0  angle: signed angle (rad, [-pi, pi], mrpt::math::wrapToPi) from the direction of segment
//   i to that of j.
//          Segments are directed from their first to their last beam, i.e. counter-clockwise
//          around the sensor, so the same wall face keeps its direction in every scan that
//          sees it and the angle is rotation invariant;
//   g = 1  length-difference ratio: (L_i - L_j) / max(L_i, L_j), in (-1, 1);
//   g = 2  distance between the midpoints (m);
//   g = 3  closest-point distance between the two segments (m; 0 when they cross).
// All geometry is in the scan's SENSOR frame. Building reuses the object's storage.
#include <mrpt/math/TPoint2D.h>
#include <toposlam/features/ScanFeatures.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace toposlam::matching {

/// One node: a segment with the derived quantities the matcher uses again and again.
struct SegmentNode {
    mrpt::math::TPoint2D start, end, midpoint;  ///< m, sensor frame
    mrpt::math::TPoint2D direction;             ///< unit vector start -> end
    mrpt::math::TPoint2D normal;                ///< unit, direction rotated +90 deg
    double heading = 0;                         ///< angle of `direction`, rad in (-pi, pi]
    double length = 0;                          ///< node attribute A (m)
    double offset = 0;  ///< line: normal . p = offset for every point p on it (m)
    std::uint32_t firstBeam = 0, lastBeam = 0;  ///< supporting beams (inclusive)
    std::uint32_t segment = 0;  ///< index in the ScanFeatures::segments it came from
};

class AttributedGraph {
  public:
    static constexpr std::size_t kEdgeAttributes = 4;
    enum EdgeAttribute : std::size_t { Angle = 0, LengthRatio, MidpointDistance, ClosestDistance };
    using EdgeAttributes = std::array<double, kEdgeAttributes>;

    /// Builds the graph of the segments at least `minLength` (m) long; when there are more
    /// than `maxNodes` of them, of the `maxNodes` longest. Nodes keep the segments' order.
    void build(const std::vector<features::LineSegment>& segments, double minLength = 0,
               std::size_t maxNodes = std::size_t(-1));

    std::size_t size() const { return nodes_.size(); }
    bool empty() const { return nodes_.empty(); }
    const SegmentNode& node(std::size_t i) const { return nodes_[i]; }
    const std::vector<SegmentNode>& nodes() const { return nodes_; }
    /// The attributes B_g(i, j) of the edge from node i to node j (i != j).
    const EdgeAttributes& edge(std::size_t i, std::size_t j) const {
        return edges_[i * nodes_.size() + j];
    }

  private:
    std::vector<SegmentNode> nodes_;
    std::vector<EdgeAttributes> edges_;  // row-major n x n
    std::vector<double> lengths_;        // selection workspace
};

/// Closest distance (m) between the segments [a0, a1] and [b0, b1].
double segmentDistance(const mrpt::math::TPoint2D& a0, const mrpt::math::TPoint2D& a1,
                       const mrpt::math::TPoint2D& b0, const mrpt::math::TPoint2D& b1);

}  // namespace toposlam::matching
