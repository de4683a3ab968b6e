#include <toposlam/io/AtomicFile.h>
#include <toposlam/planning/PathRendering.h>
#include <toposlam/rooms/TopologicalMapRendering.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace toposlam::planning {

cv::Mat renderRoomPath(const rooms::TopologicalMap& map, const RoomPath& path, int scale) {
    rooms::RenderOptions options;
    options.scale = scale;
    cv::Mat image = rooms::renderTopologicalMap(map, options);
    const auto toImage = [&](const mrpt::math::TPoint2D& p) {
        const cv::Point2f px = map.frame.toPixel(p.x, p.y);
        return cv::Point(cvRound((px.x + 0.5f) * static_cast<float>(scale)),
                         cvRound((px.y + 0.5f) * static_cast<float>(scale)));
    };
    for (const int id : path.route.doors) {
        const rooms::Door& d = map.doors.at(static_cast<std::size_t>(id - 1));
        cv::line(image, toImage(d.jambA), toImage(d.jambB), cv::Scalar(0, 215, 255), 3 * scale,
                 cv::LINE_AA);
    }
    std::vector<cv::Point> polyline;
    for (const auto& p : path.points)
        polyline.push_back(toImage(p));
    if (polyline.size() >= 2) {
        cv::polylines(image, polyline, false, cv::Scalar(0, 0, 220), std::max(2, scale),
                      cv::LINE_AA);
    }
    if (!polyline.empty()) {
        cv::circle(image, polyline.front(), 4 * scale, cv::Scalar(0, 160, 0), cv::FILLED,
                   cv::LINE_AA);
        cv::circle(image, polyline.back(), 4 * scale, cv::Scalar(200, 60, 0), cv::FILLED,
                   cv::LINE_AA);
    }
    return image;
}

void saveRoomPathPng(const rooms::TopologicalMap& map, const RoomPath& path,
                     const std::string& file, int scale) {
    const cv::Mat image = renderRoomPath(map, path, scale);
    io::writeFileAtomically(file, [&](const std::string& tmp) {
        if (!cv::imwrite(tmp, image))
            throw std::runtime_error(file + ": cannot write the PNG");
    });
}

}  // namespace toposlam::planning
