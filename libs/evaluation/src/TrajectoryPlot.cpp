#include <toposlam/evaluation/RigidAlignment2D.h>
#include <toposlam/evaluation/StampedPoseLookup.h>
#include <toposlam/evaluation/TrajectoryPlot.h>
#include <toposlam/io/AtomicFile.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace toposlam::evaluation {

mrpt::math::TPose2D alignmentTo(const io::Trajectory2D& reference,
                                const io::Trajectory2D& trajectory, double stampTolerance) {
    const StampedPoseLookup referenceAt(reference, stampTolerance);
    std::vector<mrpt::math::TPoint2D> from, to;
    for (const io::TimedPose2D& p : trajectory) {
        if (const auto r = referenceAt.find(p.stamp)) {
            from.push_back(p.pose.translation());
            to.push_back(reference[*r].pose.translation());
        }
    }
    return from.size() < 2 ? mrpt::math::TPose2D(0, 0, 0) : alignRigid2D(from, to);
}

std::vector<PlottedTrajectory> alignedTo(const io::Trajectory2D& reference,
                                         std::vector<PlottedTrajectory> trajectories,
                                         double stampTolerance) {
    for (PlottedTrajectory& t : trajectories) {
        const mrpt::math::TPose2D transform = alignmentTo(reference, t.poses, stampTolerance);
        for (io::TimedPose2D& p : t.poses)
            p.pose = transform + p.pose;
    }
    return trajectories;
}

namespace {

// Distinct colours (BGR), readable on white.
const cv::Scalar kColours[] = {{180, 119, 31},  {14, 127, 255}, {44, 160, 44},   {40, 39, 214},
                               {189, 103, 148}, {75, 86, 140},  {194, 119, 227}, {34, 189, 188}};

// 1, 2, 5, 10, 20, 50 ... m: the grid step that gives about `lines` lines over `span`.
double niceStep(double span, double lines) {
    const double raw = span / lines;
    const double decade = std::pow(10.0, std::floor(std::log10(raw)));
    for (const double m : {1.0, 2.0, 5.0}) {
        if (m * decade >= raw)
            return m * decade;
    }
    return 10 * decade;
}

}  // namespace

void saveTrajectoryPlot(const std::vector<PlottedTrajectory>& trajectories, const std::string& path,
                        int widthPixels) {
    double minX = std::numeric_limits<double>::max(), minY = minX;
    double maxX = std::numeric_limits<double>::lowest(), maxY = maxX;
    for (const auto& t : trajectories) {
        for (const auto& p : t.poses) {
            minX = std::min(minX, p.pose.x);
            maxX = std::max(maxX, p.pose.x);
            minY = std::min(minY, p.pose.y);
            maxY = std::max(maxY, p.pose.y);
        }
    }
    if (minX > maxX)
        throw std::invalid_argument("trajectory plot: no pose to draw");

    const int margin = 40;
    const double span = std::max({maxX - minX, maxY - minY, 1.0});  // m
    const double scale = (widthPixels - 2 * margin) / std::max(maxX - minX, span * 0.25);
    const int height =
        std::clamp(static_cast<int>((maxY - minY) * scale) + 2 * margin, 200, 4 * widthPixels);
    cv::Mat image(height, widthPixels, CV_8UC3, cv::Scalar(255, 255, 255));
    auto pixel = [&](double x, double y) {
        return cv::Point(static_cast<int>(std::lround(margin + (x - minX) * scale)),
                         static_cast<int>(std::lround(height - margin - (y - minY) * scale)));
    };

    // Metric grid, labelled in metres.
    const double step = niceStep(span, 10);
    for (double x = std::floor(minX / step) * step; x <= maxX + step; x += step) {
        const cv::Point p = pixel(x, 0);
        cv::line(image, {p.x, 0}, {p.x, height}, cv::Scalar(225, 225, 225), 1);
        cv::putText(image, cv::format("%g", x), {p.x + 2, height - 6}, cv::FONT_HERSHEY_SIMPLEX,
                    0.35, cv::Scalar(150, 150, 150), 1, cv::LINE_AA);
    }
    for (double y = std::floor(minY / step) * step; y <= maxY + step; y += step) {
        const cv::Point p = pixel(0, y);
        cv::line(image, {0, p.y}, {widthPixels, p.y}, cv::Scalar(225, 225, 225), 1);
        cv::putText(image, cv::format("%g", y), {4, p.y - 2}, cv::FONT_HERSHEY_SIMPLEX, 0.35,
                    cv::Scalar(150, 150, 150), 1, cv::LINE_AA);
    }

    for (std::size_t k = 0; k < trajectories.size(); ++k) {
        const cv::Scalar colour = kColours[k % std::size(kColours)];
        std::vector<cv::Point> line;
        line.reserve(trajectories[k].poses.size());
        for (const auto& p : trajectories[k].poses)
            line.push_back(pixel(p.pose.x, p.pose.y));
        cv::polylines(image, line, false, colour, 1, cv::LINE_AA);
        if (!line.empty())
            cv::circle(image, line.front(), 4, colour, cv::FILLED, cv::LINE_AA);
        // Legend, top left.
        const cv::Point at(margin, 24 + 20 * static_cast<int>(k));
        cv::rectangle(image, {at.x, at.y - 10}, {at.x + 20, at.y}, colour, cv::FILLED);
        cv::putText(image, trajectories[k].label, {at.x + 28, at.y}, cv::FONT_HERSHEY_SIMPLEX, 0.5,
                    cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
    }
    cv::putText(image, cv::format("grid %g m", step), {widthPixels - margin - 90, 20},
                cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar(120, 120, 120), 1, cv::LINE_AA);

    io::writeFileAtomically(path, [&](const std::string& tmp) {
        if (!cv::imwrite(tmp, image))
            throw std::runtime_error(path + ": cannot write the PNG");
    });
}

}  // namespace toposlam::evaluation
