#include <toposlam/rooms/BormannBaselines.h>
#include <toposlam/rooms/MorphologicalSegmentation.h>

#include <opencv2/imgproc.hpp>

#include <vector>

namespace toposlam::rooms {

cv::Mat MorphologicalSegmentation::segment(const cv::Mat& map, double resolution) const {
    CV_Assert(map.type() == CV_8U);
    const double pixelArea = resolution * resolution;
    cv::Mat eroded = map.clone();
    std::vector<std::vector<cv::Point>> rooms;
    for (int step = 0; step < options_.maxErosions; ++step) {
        cv::erode(eroded, eroded, cv::Mat());
        std::vector<std::vector<cv::Point>> contours;
        std::vector<cv::Vec4i> hierarchy;
        cv::findContours(eroded, contours, hierarchy, cv::RETR_CCOMP, cv::CHAIN_APPROX_SIMPLE);
        for (int c = 0; c < static_cast<int>(contours.size()); ++c) {
            if (hierarchy[static_cast<std::size_t>(c)][3] != -1)
                continue;  // holes
            double area = pixelArea * cv::contourArea(contours[static_cast<std::size_t>(c)]);
            for (int h = 0; h < static_cast<int>(contours.size()); ++h) {
                if (hierarchy[static_cast<std::size_t>(h)][3] == c) {
                    area -= pixelArea * cv::contourArea(contours[static_cast<std::size_t>(h)]);
                }
            }
            if (options_.minArea < area && area < options_.maxArea) {
                rooms.push_back(contours[static_cast<std::size_t>(c)]);
                cv::drawContours(eroded, contours, c, cv::Scalar(0), cv::FILLED, cv::LINE_8,
                                 hierarchy, 2);
            }
        }
    }
    cv::Mat labels;
    map.convertTo(labels, CV_32S, 256, 0);  // free 255 -> 65280 (unassigned)
    for (int i = 0; i < static_cast<int>(rooms.size()); ++i) {
        cv::drawContours(labels, rooms, i, cv::Scalar(i + 1), cv::FILLED);
    }
    labels.setTo(0, map == 0);
    wavefrontRegionGrowing(labels);
    return labels;
}

}  // namespace toposlam::rooms
