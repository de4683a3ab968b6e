#include <toposlam/io/AtomicFile.h>
#include <toposlam/rooms/TopologicalMapRendering.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace toposlam::rooms {

namespace {

const cv::Vec3b kObstacle(40, 40, 40);
const cv::Vec3b kUnassigned(200, 200, 200);

void putLabel(cv::Mat& img, const std::string& text, cv::Point at, double scale) {
    int baseline = 0;
    const cv::Size size = cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, scale, 1, &baseline);
    at -= cv::Point(size.width / 2, -size.height / 2);
    cv::putText(img, text, at, cv::FONT_HERSHEY_SIMPLEX, scale, cv::Scalar(255, 255, 255), 3,
                cv::LINE_AA);
    cv::putText(img, text, at, cv::FONT_HERSHEY_SIMPLEX, scale, cv::Scalar(0, 0, 0), 1,
                cv::LINE_AA);
}

}  // namespace

cv::Vec3b labelColour(int id) {
    // Golden-angle hues: neighbouring ids get very different colours.
    const double hue = std::fmod(static_cast<double>(id) * 0.6180339887, 1.0) * 180.0;
    const int value = 150 + (id * 37) % 90;
    cv::Mat hsv(1, 1, CV_8UC3, cv::Scalar(hue, 120 + (id * 53) % 100, value)), bgr;
    cv::cvtColor(hsv, bgr, cv::COLOR_HSV2BGR);
    return bgr.at<cv::Vec3b>(0, 0);
}

cv::Mat renderTopologicalMap(const TopologicalMap& map, const RenderOptions& options) {
    const int scale = std::clamp(options.scale, 1, 8);
    cv::Mat small(map.labels.size(), CV_8UC3, cv::Scalar(kObstacle));
    for (int r = 0; r < map.labels.rows; ++r) {
        for (int c = 0; c < map.labels.cols; ++c) {
            const int id = map.labels.at<int>(r, c);
            if (id > 0)
                small.at<cv::Vec3b>(r, c) = labelColour(id);
        }
    }
    cv::Mat img;
    cv::resize(small, img, cv::Size(), scale, scale, cv::INTER_NEAREST);
    auto toImage = [&](const mrpt::math::TPoint2D& p) {
        const cv::Point2f px = map.frame.toPixel(p.x, p.y);
        return cv::Point(cvRound((px.x + 0.5) * scale), cvRound((px.y + 0.5) * scale));
    };
    const double textScale = 0.35 + 0.1 * scale;
    for (const Door& d : map.doors) {
        cv::line(img, toImage(d.jambA), toImage(d.jambB), cv::Scalar(0, 0, 230), std::max(2, scale),
                 cv::LINE_AA);
        if (options.doorIds)
            putLabel(img, "d" + std::to_string(d.id), toImage(d.middle()), 0.8 * textScale);
    }
    if (options.roomIds) {
        for (const Room& room : map.rooms) {
            putLabel(img,
                     room.name.empty() ? std::to_string(room.id)
                                       : std::to_string(room.id) + " " + room.name,
                     toImage(room.anchor), textScale);
        }
    }
    return img;
}

void saveTopologicalMapPng(const TopologicalMap& map, const std::string& path,
                           const RenderOptions& options) {
    const cv::Mat img = renderTopologicalMap(map, options);
    io::writeFileAtomically(path, [&](const std::string& tmp) {
        if (!cv::imwrite(tmp, img))
            throw std::runtime_error(path + ": cannot write the PNG");
    });
}

cv::Mat renderLabelImage(const cv::Mat& labels, const cv::Mat& free,
                         const std::vector<LabelBoundaryDoor>& trueDoors,
                         const std::vector<LabelBoundaryDoor>& virtualDoors) {
    cv::Mat img(labels.size(), CV_8UC3, cv::Scalar(kObstacle));
    for (int r = 0; r < labels.rows; ++r) {
        for (int c = 0; c < labels.cols; ++c) {
            const int id = labels.at<int>(r, c);
            if (id == kUnassignedLabel || (id == 0 && free.at<std::uint8_t>(r, c) != 0)) {
                img.at<cv::Vec3b>(r, c) = kUnassigned;
            } else if (id > 0) {
                img.at<cv::Vec3b>(r, c) = labelColour(id);
            }
        }
    }
    for (const auto& t : trueDoors) {
        for (const cv::Point& p : t.pixels)
            img.at<cv::Vec3b>(p) = cv::Vec3b(255, 0, 0);
    }
    for (const auto& v : virtualDoors) {
        bool matched = false;
        for (const auto& t : trueDoors) {
            for (const cv::Point& p : t.pixels) {
                if (std::hypot(p.x - v.representative.x, p.y - v.representative.y) <= 10.0)
                    matched = true;
            }
        }
        cv::circle(img, v.representative, 10,
                   matched ? cv::Scalar(0, 170, 0) : cv::Scalar(0, 0, 255), 2);
    }
    return img;
}

cv::Mat renderDiagnostics(const RoomSegmenter::Result& result, const cv::Mat& free) {
    cv::Mat img(free.size(), CV_8UC3, cv::Scalar(kObstacle));
    img.setTo(cv::Scalar(255, 255, 255), free != 0);
    for (const cv::Point& p : result.searchCells)
        img.at<cv::Vec3b>(p) = cv::Vec3b(150, 150, 150);
    for (const LineSegment& l : result.lines) {
        cv::line(img, l.start, l.end, cv::Scalar(255, 120, 0), 1);
    }
    auto draw = [&](const std::vector<VirtualDoor>& doors, const cv::Scalar& colour) {
        for (const VirtualDoor& d : doors)
            cv::line(img, d.jambA, d.jambB, colour, 1);
    };
    draw(result.candidates, cv::Scalar(0, 220, 255));
    draw(result.afterTests, cv::Scalar(0, 140, 255));
    draw(result.afterDistance, cv::Scalar(255, 0, 255));
    for (const Door& d : result.map.doors) {
        const cv::Point2f a = result.map.frame.toPixel(d.jambA.x, d.jambA.y);
        const cv::Point2f b = result.map.frame.toPixel(d.jambB.x, d.jambB.y);
        cv::line(img, a, b, cv::Scalar(0, 0, 255), 2);
    }
    return img;
}

}  // namespace toposlam::rooms
