#include <toposlam/simulation/RoomSizedAreas.h>

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace toposlam::simulation {

namespace {
/// Cells of slack when comparing a clearance with the distance to the map's edge.
constexpr double kEdgeTolerance = 0.25;
}  // namespace

std::vector<RoomSizedArea> findRoomSizedAreas(const ClearanceMap& map,
                                              const RoomSizedAreaOptions& options) {
    const GridGeometry& g = map.geometry();
    // Strictly more than half the door width: an opening exactly doorWidthMax wide separates.
    const float separation = static_cast<float>(options.doorWidthMax / 2);
    cv::Mat wide(g.sizeY, g.sizeX, CV_8UC1, cv::Scalar(0));
    for (int cy = 0; cy < g.sizeY; ++cy) {
        for (int cx = 0; cx < g.sizeX; ++cx) {
            if (map.clearance(cx, cy) > separation)
                wide.at<std::uint8_t>(cy, cx) = 255;
        }
    }
    cv::Mat labels, stats, centroids;
    const int n = cv::connectedComponentsWithStats(wide, labels, stats, centroids, 8, CV_32S);

    // Largest clearance per region; among (nearly) tied cells, e.g. along a corridor, the one
    // nearest the region's centroid.
    std::vector<RoomSizedArea> areas(static_cast<std::size_t>(std::max(n - 1, 0)));
    std::vector<double> bestCentroidDist(areas.size(), 0.0);
    for (int pass = 0; pass < 2; ++pass) {
        for (int cy = 0; cy < g.sizeY; ++cy) {
            const int* row = labels.ptr<int>(cy);
            for (int cx = 0; cx < g.sizeX; ++cx) {
                if (row[cx] == 0)
                    continue;
                const auto k = static_cast<std::size_t>(row[cx] - 1);
                RoomSizedArea& a = areas[k];
                const float c = map.clearance(cx, cy);
                if (pass == 0) {
                    a.clearance = std::max(a.clearance, static_cast<double>(c));
                    // Nothing nearer than the map's edge: free space runs on beyond it.
                    const int edgeCells = std::min({cx, cy, g.sizeX - 1 - cx, g.sizeY - 1 - cy});
                    a.openToMapEdge =
                        a.openToMapEdge || c >= (edgeCells + 0.5 - kEdgeTolerance) * g.resolution;
                    continue;
                }
                if (c < a.clearance - 0.5 * g.resolution)
                    continue;
                const auto p = g.centre(cx, cy);
                const double d = std::hypot(
                    p.x - (g.xMin + (centroids.at<double>(row[cx], 0) + 0.5) * g.resolution),
                    p.y - (g.yMin + (centroids.at<double>(row[cx], 1) + 0.5) * g.resolution));
                if (bestCentroidDist[k] == 0.0 || d < bestCentroidDist[k]) {
                    bestCentroidDist[k] = std::max(d, 1e-12);
                    a.centre = p;
                }
            }
        }
    }
    const double cellArea = g.resolution * g.resolution;
    for (int i = 1; i < n; ++i) {
        areas[static_cast<std::size_t>(i - 1)].erodedAreaM2 =
            stats.at<int>(i, cv::CC_STAT_AREA) * cellArea;
    }
    areas.erase(
        std::remove_if(areas.begin(), areas.end(),
                       [&](const RoomSizedArea& a) { return a.erodedAreaM2 < options.minAreaM2; }),
        areas.end());
    std::stable_sort(areas.begin(), areas.end(),
                     [](const auto& a, const auto& b) { return a.erodedAreaM2 > b.erodedAreaM2; });
    return areas;
}

}  // namespace toposlam::simulation
