#include <toposlam/evaluation/MapComparisonImage.h>
#include <toposlam/io/AtomicFile.h>

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace toposlam::evaluation {

namespace {

constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;
constexpr double kTitleScale = 0.6;
constexpr int kGap = 20;            // px between and around panels
constexpr int kTitleHeight = 32;    // px of a panel title line
constexpr int kHeadingHeight = 40;  // px of the heading line

// The picture turned by `rotation` (rad, counter-clockwise) on a canvas large enough for all
// of it, the new corners filled with the unknown-space grey.
cv::Mat rotated(const cv::Mat& image, double rotation) {
    if (rotation == 0)
        return image;
    const double degrees = rotation * 180.0 / M_PI;
    const cv::Point2f centre(0.5f * float(image.cols), 0.5f * float(image.rows));
    cv::Mat transform = cv::getRotationMatrix2D(centre, degrees, 1.0);
    const cv::Rect2f bounds =
        cv::RotatedRect(centre, image.size(), float(degrees)).boundingRect2f();
    transform.at<double>(0, 2) += 0.5 * bounds.width - centre.x;
    transform.at<double>(1, 2) += 0.5 * bounds.height - centre.y;
    cv::Mat turned;
    cv::warpAffine(image, turned, transform,
                   cv::Size(int(std::ceil(bounds.width)), int(std::ceil(bounds.height))),
                   cv::INTER_LINEAR, cv::BORDER_CONSTANT,
                   cv::Scalar(image.at<unsigned char>(0, 0)));
    return turned;
}

// The picture turned, then cut down to its mapped part: the pixels that differ from the
// unknown-space grey found in its corner, plus a small border.
cv::Mat croppedMap(const std::string& file, double rotation) {
    const cv::Mat original = cv::imread(file, cv::IMREAD_GRAYSCALE);
    if (original.empty())
        throw std::runtime_error(file + ": cannot read the map picture");
    const cv::Mat image = rotated(original, rotation);
    cv::Mat difference;
    cv::absdiff(image, cv::Scalar(image.at<unsigned char>(0, 0)), difference);
    const cv::Rect mapped = cv::boundingRect(difference > 8);
    if (mapped.empty())
        return image;
    const int border = 10;
    const cv::Rect padded = (mapped + cv::Size(2 * border, 2 * border)) - cv::Point(border, border);
    return image(padded & cv::Rect(0, 0, image.cols, image.rows)).clone();
}

int textWidth(const std::string& text, double scale) {
    int baseline = 0;
    return cv::getTextSize(text, kFont, scale, 1, &baseline).width;
}

// Every map scaled to one common metres-per-pixel; missing ones as grey boxes.
std::vector<cv::Mat> scaledPanels(const std::vector<MapPanel>& panels, int maxPanelPixels) {
    std::vector<cv::Mat> maps(panels.size());
    double finest = 0, largest = 0;  // m per pixel, m
    for (std::size_t i = 0; i < panels.size(); ++i) {
        if (panels[i].imageFile.empty())
            continue;
        maps[i] = croppedMap(panels[i].imageFile, panels[i].rotation);
        const double resolution = panels[i].metresPerPixel;
        finest = finest > 0 ? std::min(finest, resolution) : resolution;
        largest = std::max(largest, resolution * std::max(maps[i].cols, maps[i].rows));
    }
    const double output = std::max(finest, largest / std::max(1, maxPanelPixels));
    int tallest = 200;
    for (std::size_t i = 0; i < panels.size(); ++i) {
        if (maps[i].empty())
            continue;
        const double factor = panels[i].metresPerPixel / output;
        const cv::Size size(std::max(1, static_cast<int>(maps[i].cols * factor)),
                            std::max(1, static_cast<int>(maps[i].rows * factor)));
        cv::Mat resized;
        cv::resize(maps[i], resized, size, 0, 0, factor < 1 ? cv::INTER_AREA : cv::INTER_NEAREST);
        cv::cvtColor(resized, maps[i], cv::COLOR_GRAY2BGR);
        tallest = std::max(tallest, maps[i].rows);
    }
    for (std::size_t i = 0; i < panels.size(); ++i) {
        if (!maps[i].empty())
            continue;
        const int width = std::max(300, textWidth(panels[i].missing, 0.5) + 2 * kGap);
        maps[i] = cv::Mat(std::min(tallest, 400), width, CV_8UC3, cv::Scalar(225, 225, 225));
        cv::putText(maps[i], panels[i].missing, cv::Point(kGap, maps[i].rows / 2), kFont, 0.5,
                    cv::Scalar(40, 40, 160), 1, cv::LINE_AA);
    }
    return maps;
}

}  // namespace

void saveMapComparison(const std::vector<MapPanel>& panels, const std::string& heading,
                       const std::string& path, int maxPanelPixels) {
    if (panels.empty())
        throw std::invalid_argument("saveMapComparison: no panel");
    const std::vector<cv::Mat> maps = scaledPanels(panels, maxPanelPixels);
    std::vector<int> columns;
    int width = kGap, height = 0;
    for (std::size_t i = 0; i < panels.size(); ++i) {
        columns.push_back(std::max(maps[i].cols, textWidth(panels[i].title, kTitleScale)));
        width += columns.back() + kGap;
        height = std::max(height, maps[i].rows);
    }
    width = std::max(width, textWidth(heading, 0.8) + 2 * kGap);
    height += kHeadingHeight + kTitleHeight + 2 * kGap;
    cv::Mat canvas(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
    cv::putText(canvas, heading, cv::Point(kGap, kGap + 18), kFont, 0.8, cv::Scalar(0, 0, 0), 2,
                cv::LINE_AA);
    int x = kGap;
    const int top = kGap + kHeadingHeight;
    for (std::size_t i = 0; i < panels.size(); ++i) {
        cv::putText(canvas, panels[i].title, cv::Point(x, top + 20), kFont, kTitleScale,
                    cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
        maps[i].copyTo(canvas(cv::Rect(x, top + kTitleHeight, maps[i].cols, maps[i].rows)));
        x += columns[i] + kGap;
    }
    io::writeFileAtomically(path, [&](const std::string& tmp) {
        if (!cv::imwrite(tmp, canvas))
            throw std::runtime_error(path + ": cannot write the PNG");
    });
}

}  // namespace toposlam::evaluation
