#include <toposlam/io/AtomicFile.h>
#include <toposlam/simulation/FloorPlanImages.h>

#include <toposlam/io/JsonFile.h>
#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace toposlam::simulation {

using mrpt::math::TPoint2D;

namespace {

// Sets `value` on every pixel of `image` whose centre, in the plan frame, satisfies `inside`;
// only the pixels of the turned bounding box of `box` (plan frame) are visited.
template <class T, class Inside>
void fill(cv::Mat& image, const FloorPlanImages& f, const Box& box, T value, Inside inside) {
    float x0 = 1e30f, y0 = 1e30f, x1 = -1e30f, y1 = -1e30f;
    for (const TPoint2D& p : {TPoint2D{box.xMin, box.yMin}, TPoint2D{box.xMax, box.yMin},
                              TPoint2D{box.xMin, box.yMax}, TPoint2D{box.xMax, box.yMax}}) {
        const cv::Point2f q = f.toPixel(p);
        x0 = std::min(x0, q.x);
        y0 = std::min(y0, q.y);
        x1 = std::max(x1, q.x);
        y1 = std::max(y1, q.y);
    }
    const int c0 = std::max(0, static_cast<int>(std::floor(x0)));
    const int c1 = std::min(image.cols - 1, static_cast<int>(std::ceil(x1)));
    const int r0 = std::max(0, static_cast<int>(std::floor(y0)));
    const int r1 = std::min(image.rows - 1, static_cast<int>(std::ceil(y1)));
    for (int r = r0; r <= r1; ++r) {
        T* row = image.ptr<T>(r);
        for (int c = c0; c <= c1; ++c) {
            if (inside(f.toPlan(c, r)))
                row[c] = value;
        }
    }
}

template <class T>
void fillBox(cv::Mat& image, const FloorPlanImages& f, const Box& b, T value) {
    fill(image, f, b, value, [&](const TPoint2D& p) { return b.contains(p); });
}

template <class T>
void fillDisc(cv::Mat& image, const FloorPlanImages& f, const Disc& d, T value) {
    const Box b{d.centre.x - d.radius, d.centre.y - d.radius, d.centre.x + d.radius,
                d.centre.y + d.radius};
    fill(image, f, b, value, [&](const TPoint2D& p) {
        return std::hypot(p.x - d.centre.x, p.y - d.centre.y) <= d.radius;
    });
}

// The image frame: the plan's walls plus the margin, turned, and its bounding box.
FloorPlanImages frameOf(const FloorPlan& plan, double resolution, double rotationDeg,
                        double margin) {
    FloorPlanImages f;
    f.resolution = resolution;
    f.rotationDeg = rotationDeg;
    const Box e = plan.extent();
    const double a = rotationDeg * M_PI / 180, c = std::cos(a), s = std::sin(a);
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (const TPoint2D& p :
         {TPoint2D{e.xMin - margin, e.yMin - margin}, TPoint2D{e.xMax + margin, e.yMin - margin},
          TPoint2D{e.xMin - margin, e.yMax + margin}, TPoint2D{e.xMax + margin, e.yMax + margin}}) {
        const double x = c * p.x - s * p.y, y = s * p.x + c * p.y;
        x0 = std::min(x0, x);
        y0 = std::min(y0, y);
        x1 = std::max(x1, x);
        y1 = std::max(y1, y);
    }
    f.xMin = x0;
    f.yMax = y1;
    const int cols = static_cast<int>(std::ceil((x1 - x0) / resolution));
    const int rows = static_cast<int>(std::ceil((y1 - y0) / resolution));
    f.map = cv::Mat(rows, cols, CV_8U, cv::Scalar(205));
    f.rooms = cv::Mat::zeros(rows, cols, CV_32S);
    return f;
}

}  // namespace

cv::Point2f FloorPlanImages::toPixel(const TPoint2D& p) const {
    const double a = rotationDeg * M_PI / 180, c = std::cos(a), s = std::sin(a);
    const double x = c * p.x - s * p.y, y = s * p.x + c * p.y;
    return {static_cast<float>((x - xMin) / resolution - 0.5),
            static_cast<float>((yMax - y) / resolution - 0.5)};
}

TPoint2D FloorPlanImages::toPlan(double px, double py) const {
    const double x = xMin + (px + 0.5) * resolution, y = yMax - (py + 0.5) * resolution;
    const double a = rotationDeg * M_PI / 180, c = std::cos(a), s = std::sin(a);
    return {c * x + s * y, -s * x + c * y};
}

FloorPlanImages drawFloorPlan(const GeneratedFloorPlan& g, double resolution, double rotationDeg,
                              double margin) {
    const FloorPlan& plan = g.plan;
    FloorPlanImages f = frameOf(plan, resolution, rotationDeg, margin);
    for (const FloorRoom& r : plan.rooms()) {
        fillBox<std::uint8_t>(f.map, f, r.floor, 255);
        fillBox<int>(f.rooms, f, r.floor, g.groundTruthRoom.at(static_cast<std::size_t>(r.id)));
    }
    const double h = 0.5 * std::max(g.outerWallThickness, g.innerWallThickness) + 1e-6;
    for (const FloorDoor& d : plan.doors()) {
        const Box opening{std::min(d.jambA.x, d.jambB.x) - (d.jambA.x == d.jambB.x ? h : 0),
                          std::min(d.jambA.y, d.jambB.y) - (d.jambA.y == d.jambB.y ? h : 0),
                          std::max(d.jambA.x, d.jambB.x) + (d.jambA.x == d.jambB.x ? h : 0),
                          std::max(d.jambA.y, d.jambB.y) + (d.jambA.y == d.jambB.y ? h : 0)};
        fillBox<std::uint8_t>(f.map, f, opening, 255);
        f.doors.push_back({f.toPixel(d.jambA), f.toPixel(d.jambB), d.width,
                           g.groundTruthRoom.at(static_cast<std::size_t>(d.roomA)),
                           g.groundTruthRoom.at(static_cast<std::size_t>(d.roomB))});
    }
    for (const Box& w : plan.wallPieces()) {
        fillBox<std::uint8_t>(f.map, f, w, 0);
        fillBox<int>(f.rooms, f, w, 0);
    }
    f.furnished = f.map.clone();
    for (const Box& b : plan.furnitureBoxes())
        fillBox<std::uint8_t>(f.furnished, f, b, 0);
    for (const Disc& d : plan.furnitureDiscs())
        fillDisc<std::uint8_t>(f.furnished, f, d, 0);
    return f;
}

std::vector<std::string> saveFloorPlanImages(const FloorPlanImages& images, const std::string& dir,
                                             const std::string& name) {
    std::filesystem::create_directories(dir);
    const auto path = [&](const std::string& suffix) {
        return (std::filesystem::path(dir) / (name + suffix)).string();
    };
    auto png = [](const std::string& file, const cv::Mat& image) {
        io::writeFileAtomically(file, [&](const std::string& tmp) {
            if (!cv::imwrite(tmp, image))
                throw std::runtime_error(file + ": cannot write the PNG");
        });
    };
    const std::vector<std::string> files = {path(".png"), path("_furnitures.png"),
                                            path("_gt_segmentation.png"), path("_doors.json")};
    png(files[0], images.map);
    png(files[1], images.furnished);
    cv::Mat truth(images.rooms.size(), CV_8U, cv::Scalar(0));
    truth.setTo(255, images.rooms > 0);
    png(files[2], truth);
    io::Json j;
    j["resolution_m"] = images.resolution;
    j["rotation_deg"] = images.rotationDeg;
    j["doors"] = io::Json::array();
    for (const auto& d : images.doors) {
        j["doors"].push_back({{"jamb_a_px", {d.jambA.x, d.jambA.y}},
                              {"jamb_b_px", {d.jambB.x, d.jambB.y}},
                              {"width_m", d.width},
                              {"rooms", {d.roomA, d.roomB}}});
    }
    io::saveJsonFile(j, files[3]);
    return files;
}

}  // namespace toposlam::simulation
