#include <toposlam/io/InputError.h>
#include <toposlam/rooms/RoomBenchmarkCase.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <stdexcept>
#include <utility>
#include <vector>

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

namespace {

// `ratio` as a whole number from `least` to `most`; otherwise std::invalid_argument(`message`),
// formatted with the map's and the requested cell sizes.
int wholeFactor(double ratio, long least, long most, const char* message, double resolution,
                double cellSize) {
    const long factor = std::isfinite(ratio) ? std::lround(ratio) : 0;
    if (factor < least || factor > most ||
        std::abs(ratio - static_cast<double>(factor)) > 1e-6 * ratio) {
        char buf[160];
        std::snprintf(buf, sizeof buf, message, resolution, cellSize);
        throw std::invalid_argument(buf);
    }
    return static_cast<int>(factor);
}

// Throws std::invalid_argument unless `c` is a drawn case (gridOfFreeImage: no trajectory,
// origin (0, 0), in its ground truth's frame): only those can be `done` (pooled, split).
void requireDrawn(const RoomBenchmarkCase& c, const char* done) {
    if (c.toTruthFrame || !c.trajectory.empty() || c.grid.getXMin() != 0 || c.grid.getYMin() != 0)
        throw std::invalid_argument(std::string("only a drawn map can be ") + done + " ('" +
                                    c.name() + "')");
}

}  // namespace

int poolingFactor(double cellSize, double resolution) {
    return wholeFactor(cellSize / resolution, 1, 100,
                       "the cell size must be a whole multiple of the map's %g m cells (got %g m)",
                       resolution, cellSize);
}

cv::Mat poolFreeImage(const cv::Mat& free, int factor) {
    CV_Assert(free.type() == CV_8U && factor >= 1);
    const int k = factor;
    cv::Mat out((free.rows + k - 1) / k, (free.cols + k - 1) / k, CV_8U, cv::Scalar(0));
    const int above = out.rows * k - free.rows;  // rows of cells reaching past the image's top
    for (int r = 0; r < out.rows; ++r) {
        const int first = r * k - above;  // the cell's top pixel row
        if (first < 0)
            continue;
        auto* cell = out.ptr<std::uint8_t>(r);
        for (int c = 0; (c + 1) * k <= free.cols; ++c) {
            bool allFree = true;
            for (int dr = 0; dr < k && allFree; ++dr) {
                const auto* pixel = free.ptr<std::uint8_t>(first + dr) + c * k;
                allFree = std::find(pixel, pixel + k, 0) == pixel + k;
            }
            cell[c] = allFree ? 255 : 0;
        }
    }
    return out;
}

namespace {

// Labels of cells of `factor` x `factor` pixels (CV_32S) at the pixels of `free` (CV_8U, the
// drawn plan): each pixel takes its cell's label; then the free pixels whose cell was not free
// (along the walls) take the label of a 4-neighbour, layer by layer, as far as a cell reaches
// (4-neighbours: across a wall drawn as a diagonal staircase, free pixels touch only at corners).
cv::Mat labelsAtPixels(const cv::Mat& cellLabels, int factor, const cv::Mat& free) {
    CV_Assert(cellLabels.type() == CV_32S);
    cv::Mat out(free.size(), CV_32S, cv::Scalar(0));
    const int above = cellLabels.rows * factor - free.rows;  // as in poolFreeImage
    for (int r = 0; r < free.rows; ++r) {
        const int* cells = cellLabels.ptr<int>((r + above) / factor);
        int* row = out.ptr<int>(r);
        for (int c = 0; c < free.cols; ++c)
            row[c] = cells[c / factor];
    }
    std::vector<std::pair<cv::Point, int>> layer;
    for (int pass = 0; pass < 2 * (factor - 1); ++pass) {
        layer.clear();
        for (int r = 0; r < free.rows; ++r) {
            const auto* isFree = free.ptr<std::uint8_t>(r);
            const int* row = out.ptr<int>(r);
            for (int c = 0; c < free.cols; ++c) {
                if (row[c] != 0 || isFree[c] == 0)
                    continue;
                int label = 0;
                if (r > 0 && out.at<int>(r - 1, c) != 0)
                    label = out.at<int>(r - 1, c);
                else if (c > 0 && row[c - 1] != 0)
                    label = row[c - 1];
                else if (c + 1 < free.cols && row[c + 1] != 0)
                    label = row[c + 1];
                else if (r + 1 < free.rows && out.at<int>(r + 1, c) != 0)
                    label = out.at<int>(r + 1, c);
                if (label != 0)
                    layer.emplace_back(cv::Point(c, r), label);
            }
        }
        if (layer.empty())
            break;
        for (const auto& [p, label] : layer)
            out.at<int>(p) = label;
    }
    return out;
}

}  // namespace

RoomBenchmarkCase pooledCase(const RoomBenchmarkCase& drawn, double cellSize) {
    requireDrawn(drawn, "pooled");
    const double resolution = drawn.grid.getResolution();
    const int k = poolingFactor(cellSize, resolution);
    if (k == 1)
        return drawn;
    RoomBenchmarkCase c = drawn;
    c.inputFree = poolFreeImage(drawn.inputFree, k);
    c.grid = gridOfFreeImage(c.inputFree, cellSize);  // same origin: the same world frame
    c.truthResolution = resolution;
    c.toTruthFrame = [k, free = drawn.inputFree](const cv::Mat& labels) {
        return labelsAtPixels(labels, k, free);
    };
    return c;
}

int splittingFactor(double cellSize, double resolution) {
    return wholeFactor(resolution / cellSize, 2, 8,
                       "a finer cell size must split the map's %g m cells into 2 to 8 (got %g m)",
                       resolution, cellSize);
}

RoomBenchmarkCase splitCase(const RoomBenchmarkCase& drawn, double cellSize) {
    requireDrawn(drawn, "split");
    const double resolution = drawn.grid.getResolution();
    const int k = splittingFactor(cellSize, resolution);
    RoomBenchmarkCase c = drawn;
    cv::resize(drawn.inputFree, c.inputFree, {}, k, k, cv::INTER_NEAREST);
    c.grid = gridOfFreeImage(c.inputFree, cellSize);  // same origin: the same world frame
    c.truthResolution = resolution;
    c.toTruthFrame = [k](const cv::Mat& labels) {
        CV_Assert(labels.type() == CV_32S);
        cv::Mat out(labels.rows / k, labels.cols / k, CV_32S);
        std::vector<std::pair<int, int>> cells(static_cast<std::size_t>(k * k));  // label, index
        for (int r = 0; r < out.rows; ++r) {
            for (int c = 0; c < out.cols; ++c) {
                for (int dr = 0; dr < k; ++dr) {
                    const int* row = labels.ptr<int>(r * k + dr);
                    for (int dc = 0; dc < k; ++dc)
                        cells[static_cast<std::size_t>(dr * k + dc)] = {row[c * k + dc],
                                                                        dr * k + dc};
                }
                // The most frequent label of the pixel's cells (runs of the sorted labels); a
                // tie goes to the label found first in raster order.
                std::sort(cells.begin(), cells.end());
                std::pair<std::ptrdiff_t, int> best{0, 0};  // count, -first index
                int bestLabel = cells.front().first;
                for (auto run = cells.begin(); run != cells.end();) {
                    auto end = run;
                    while (end != cells.end() && end->first == run->first)
                        ++end;
                    const std::pair<std::ptrdiff_t, int> score{end - run, -run->second};
                    if (score > best) {
                        best = score;
                        bestLabel = run->first;
                    }
                    run = end;
                }
                out.at<int>(r, c) = bestLabel;
            }
        }
        return out;
    };
    return c;
}

RoomBenchmarkCase caseAtCellSize(const RoomBenchmarkCase& drawn, double cellSize) {
    return cellSize < drawn.grid.getResolution() ? splitCase(drawn, cellSize)
                                                 : pooledCase(drawn, cellSize);
}

void checkCellSize(double cellSize, double resolution) {
    if (cellSize < resolution)
        splittingFactor(cellSize, resolution);
    else
        poolingFactor(cellSize, resolution);
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
    const std::string dir = dataDir + "/";
    const GroundTruthRooms truth = groundTruthRooms(readGrey(dir + base + "_gt_segmentation.png"));
    const cv::Mat baseFree = freeOf(readGrey(dir + base + ".png"));
    const cv::Mat furnishedFree = freeOf(readGrey(dir + base + "_furnitures.png"));
    std::vector<RoomBenchmarkCase> cases;
    for (const double angle : rotationsDeg) {
        const cv::Mat labels = rotateNearest(truth.labels, angle, 0);
        const cv::Mat free = rotateNearest(baseFree, angle, 0);
        cases.push_back(
            drawnCase("bormann", base, false, angle, free, free, labels, kBenchmarkMapResolution));
        cases.push_back(drawnCase("bormann", base + "_furnitures", true, angle,
                                  rotateNearest(furnishedFree, angle, 0), free, labels,
                                  kBenchmarkMapResolution));
    }
    return cases;
}

}  // namespace toposlam::rooms
