#include <toposlam/io/AtomicFile.h>
#include <toposlam/simulation/GridGeometry.h>
#include <toposlam/simulation/TrajectoryImage.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace toposlam::simulation {

void saveTrajectoryImage(const mrpt::maps::COccupancyGridMap2D& map,
                         const io::Trajectory2D& trajectory,
                         const std::vector<mrpt::math::TPoint2D>& marks, const std::string& path,
                         int scale) {
    const GridGeometry g = GridGeometry::of(map);
    cv::Mat grey(g.sizeY, g.sizeX, CV_8UC1);
    for (int cy = 0; cy < g.sizeY; ++cy) {
        for (int cx = 0; cx < g.sizeX; ++cx) {
            grey.at<std::uint8_t>(g.sizeY - 1 - cy, cx) =
                static_cast<std::uint8_t>(255.0f * map.getCell(cx, cy) + 0.5f);
        }
    }
    cv::Mat image;
    cv::cvtColor(grey, image, cv::COLOR_GRAY2BGR);
    cv::resize(image, image, cv::Size(), scale, scale, cv::INTER_NEAREST);
    const auto pixel = [&](double x, double y) {
        return cv::Point(static_cast<int>((x - g.xMin) / g.resolution * scale),
                         static_cast<int>((g.sizeY - (y - g.yMin) / g.resolution) * scale));
    };
    for (std::size_t i = 1; i < trajectory.size(); ++i) {
        cv::line(image, pixel(trajectory[i - 1].pose.x, trajectory[i - 1].pose.y),
                 pixel(trajectory[i].pose.x, trajectory[i].pose.y), cv::Scalar(0, 0, 220),
                 std::max(1, scale / 2), cv::LINE_AA);
    }
    for (const auto& m : marks) {
        cv::circle(image, pixel(m.x, m.y), 4 * scale, cv::Scalar(220, 80, 0),
                   std::max(1, scale / 2), cv::LINE_AA);
    }
    if (!trajectory.empty()) {
        cv::circle(image, pixel(trajectory[0].pose.x, trajectory[0].pose.y), 3 * scale,
                   cv::Scalar(0, 170, 0), cv::FILLED, cv::LINE_AA);
    }
    io::writeFileAtomically(path, [&](const std::string& tmp) {
        if (!cv::imwrite(tmp, image))
            throw std::runtime_error(path + ": cannot write the image");
    });
}

}  // namespace toposlam::simulation
