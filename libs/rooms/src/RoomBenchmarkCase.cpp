#include <toposlam/io/InputError.h>
#include <toposlam/rooms/RoomBenchmarkCase.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <cmath>
#include <cstdio>

namespace toposlam::rooms {

namespace {

cv::Mat readGrey(const std::string& path) {
    cv::Mat img = cv::imread(path, cv::IMREAD_GRAYSCALE);
    if (img.empty())
        throw io::InputError(path, "missing or not a readable image");
    return img;
}

// The package's client: grey >= 250 is free (255), the rest not (0).
cv::Mat freeOf(const cv::Mat& grey) {
    cv::Mat out;
    cv::threshold(grey, out, 249, 255, cv::THRESH_BINARY);
    return out;
}

}  // namespace

std::string RoomBenchmarkCase::name() const {
    if (rotationDeg == 0)
        return map;
    char buf[32];
    std::snprintf(buf, sizeof buf, "@%g", rotationDeg);
    return map + buf;
}

cv::Mat rotationOfImage(const cv::Size& imageSize, double degrees, cv::Size& size) {
    const cv::Point2f centre(0.5f * static_cast<float>(imageSize.width - 1),
                             0.5f * static_cast<float>(imageSize.height - 1));
    cv::Mat m = cv::getRotationMatrix2D(centre, degrees, 1.0);
    const double a = degrees * M_PI / 180, c = std::abs(std::cos(a)), s = std::abs(std::sin(a));
    // The turned image's bounding box (less a hair, so that 90 degrees does not grow it).
    size = cv::Size(static_cast<int>(std::ceil(c * imageSize.width + s * imageSize.height - 1e-6)),
                    static_cast<int>(std::ceil(s * imageSize.width + c * imageSize.height - 1e-6)));
    m.at<double>(0, 2) += 0.5 * (size.width - 1) - centre.x;
    m.at<double>(1, 2) += 0.5 * (size.height - 1) - centre.y;
    return m;
}

cv::Mat rotateNearest(const cv::Mat& image, double degrees, double fill) {
    CV_Assert(image.type() == CV_8U || image.type() == CV_32S);
    if (degrees == 0)
        return image.clone();
    cv::Size size;
    const cv::Mat m = rotationOfImage(image.size(), degrees, size);
    // warpAffine has no 32-bit integer images; labels up to 2^24 are exact as floats.
    cv::Mat in = image, out;
    if (image.type() == CV_32S)
        image.convertTo(in, CV_32F);
    cv::warpAffine(in, out, m, size, cv::INTER_NEAREST, cv::BORDER_CONSTANT, cv::Scalar(fill));
    if (image.type() == CV_32S)
        out.convertTo(out, CV_32S);
    return out;
}

mrpt::maps::COccupancyGridMap2D gridOfFreeImage(const cv::Mat& free, double resolution) {
    mrpt::maps::COccupancyGridMap2D grid;
    grid.setSize(0, static_cast<float>(free.cols * resolution), 0,
                 static_cast<float>(free.rows * resolution), static_cast<float>(resolution), 0.0f);
    for (int r = 0; r < free.rows; ++r) {
        const auto* row = free.ptr<std::uint8_t>(r);
        for (int c = 0; c < free.cols; ++c) {
            if (row[c] != 0)
                grid.setCell(c, free.rows - 1 - r, 1.0f);
        }
    }
    return grid;
}

RoomBenchmarkCase drawnCase(std::string dataset, std::string map, bool furnished,
                            double rotationDeg, const cv::Mat& free, const cv::Mat& baseFree,
                            const cv::Mat& roomLabels, double resolution) {
    RoomBenchmarkCase c;
    c.dataset = std::move(dataset);
    c.map = std::move(map);
    c.furnished = furnished;
    c.rotationDeg = rotationDeg;
    c.grid = gridOfFreeImage(free, resolution);
    c.inputFree = free;
    c.scoredFree = free;
    c.truth = groundTruthFromLabels(roomLabels);
    c.trueDoors = labelBoundaryDoors(c.truth.labels, baseFree);
    return c;
}

std::vector<RoomBenchmarkCase> bormannCases(const std::string& dataDir, const std::string& base,
                                            const std::vector<double>& rotationsDeg) {
    constexpr double kResolution = 0.05;  // m/pixel of every benchmark map (SOURCES.md)
    const std::string dir = dataDir + "/";
    const GroundTruthRooms truth = groundTruthRooms(readGrey(dir + base + "_gt_segmentation.png"));
    const cv::Mat baseFree = freeOf(readGrey(dir + base + ".png"));
    const cv::Mat furnishedFree = freeOf(readGrey(dir + base + "_furnitures.png"));
    std::vector<RoomBenchmarkCase> cases;
    for (const double angle : rotationsDeg) {
        const cv::Mat labels = rotateNearest(truth.labels, angle, 0);
        const cv::Mat free = rotateNearest(baseFree, angle, 0);
        cases.push_back(drawnCase("bormann", base, false, angle, free, free, labels, kResolution));
        cases.push_back(drawnCase("bormann", base + "_furnitures", true, angle,
                                  rotateNearest(furnishedFree, angle, 0), free, labels,
                                  kResolution));
    }
    return cases;
}

}  // namespace toposlam::rooms
