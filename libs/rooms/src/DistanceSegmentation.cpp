#include <toposlam/rooms/BormannBaselines.h>
#include <toposlam/rooms/DistanceSegmentation.h>

#include <opencv2/imgproc.hpp>

#include <vector>

namespace toposlam::rooms {

cv::Mat DistanceSegmentation::segment(const cv::Mat& map, double resolution) const {
    CV_Assert(map.type() == CV_8U);
    const double pixelArea = resolution * resolution;
    cv::Mat shrunk;
    cv::erode(map, shrunk, cv::Mat());
    cv::Mat distance;
    cv::distanceTransform(shrunk, distance, cv::DIST_L2, 5);
    cv::convertScaleAbs(distance, distance);  // 8 bit, as the package does
    double maxLevel = 0;
    cv::minMaxLoc(distance, nullptr, &maxLevel);

    std::vector<std::vector<cv::Point>> best, bestAll;
    std::vector<cv::Vec4i> bestHierarchy;
    // Levels at or above the maximum give no contour and cannot change the choice: skip them.
    for (int level = static_cast<int>(maxLevel) - 1; level > 0; --level) {
        cv::Mat binary;
        cv::threshold(distance, binary, level, 255, cv::THRESH_BINARY);
        std::vector<std::vector<cv::Point>> contours, rooms;
        std::vector<cv::Vec4i> hierarchy;
        cv::findContours(binary, contours, hierarchy, cv::RETR_CCOMP, cv::CHAIN_APPROX_NONE);
        for (int c = 0; c < static_cast<int>(contours.size()); ++c) {
            if (hierarchy[static_cast<std::size_t>(c)][3] != -1)
                continue;
            double area = pixelArea * cv::contourArea(contours[static_cast<std::size_t>(c)]);
            for (int h = 0; h < static_cast<int>(contours.size()); ++h) {
                if (hierarchy[static_cast<std::size_t>(h)][3] == c) {
                    area -= pixelArea * cv::contourArea(contours[static_cast<std::size_t>(h)]);
                }
            }
            if (area >= options_.minArea && area <= options_.maxArea) {
                rooms.push_back(contours[static_cast<std::size_t>(c)]);
            }
        }
        if (rooms.size() >= best.size()) {  // ">=": lower levels win ties
            best = std::move(rooms);
            bestAll = std::move(contours);
            bestHierarchy = std::move(hierarchy);
        }
    }
    cv::Mat labels;
    map.convertTo(labels, CV_32S, 256, 0);  // free 255 -> 65280 (unassigned)
    for (int i = 0; i < static_cast<int>(best.size()); ++i) {
        cv::drawContours(labels, best, i, cv::Scalar(i + 1), 7);  // outline, 7 px, as the package
    }
    // The package blacks out the holes whose parent is contour #1 (sic: index 1, not any room).
    for (int h = 0; h < static_cast<int>(bestAll.size()); ++h) {
        if (bestHierarchy[static_cast<std::size_t>(h)][3] == 1) {
            cv::drawContours(labels, bestAll, h, cv::Scalar(0), cv::FILLED);
        }
    }
    wavefrontRegionGrowing(labels);
    return labels;
}

}  // namespace toposlam::rooms
