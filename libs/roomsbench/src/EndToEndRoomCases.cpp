#include <toposlam/evaluation/RigidAlignment2D.h>
#include <toposlam/io/InputError.h>
#include <toposlam/io/Trajectory.h>
#include <toposlam/mapping/LogMapper.h>
#include <toposlam/roomsbench/EndToEndRoomCases.h>
#include <toposlam/roomsbench/GeneratedRoomCases.h>
#include <toposlam/simulation/ClearanceMap.h>
#include <toposlam/simulation/FloorPlanGenerator.h>
#include <toposlam/simulation/FloorPlanImages.h>
#include <toposlam/simulation/TourPlanner.h>

#include <mrpt/poses/CPose2D.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <cmath>
#include <filesystem>
#include <memory>

namespace toposlam::roomsbench {

namespace {

// RoomSegmenter's default free threshold: what the baselines get as free space of a SLAM grid.
constexpr float kFreeThreshold = 0.8f;

mrpt::maps::COccupancyGridMap2D gridOfMapImage(const cv::Mat& map, double resolution) {
    mrpt::maps::COccupancyGridMap2D grid;
    grid.setSize(0, static_cast<float>(map.cols * resolution), 0,
                 static_cast<float>(map.rows * resolution), static_cast<float>(resolution), 0.5f);
    for (int r = 0; r < map.rows; ++r) {
        const auto* row = map.ptr<std::uint8_t>(r);
        for (int c = 0; c < map.cols; ++c) {
            if (row[c] == 255 || row[c] == 0)
                grid.setCell(c, map.rows - 1 - r, row[c] == 255 ? 1.0f : 0.0f);
        }
    }
    return grid;
}

// CV_8U image of the free cells (p > kFreeThreshold) of `grid`, map-image layout.
cv::Mat freeImageOf(const mrpt::maps::COccupancyGridMap2D& grid) {
    const int cols = static_cast<int>(grid.getSizeX()), rows = static_cast<int>(grid.getSizeY());
    cv::Mat free(rows, cols, CV_8U, cv::Scalar(0));
    for (int r = 0; r < rows; ++r) {
        auto* row = free.ptr<std::uint8_t>(r);
        for (int c = 0; c < cols; ++c)
            row[c] = grid.getCell(c, rows - 1 - r) > kFreeThreshold ? 255 : 0;
    }
    return free;
}

// For every pixel of the plan image (`rows` x `cols`, origin at its lower-left corner), the
// index (row * cols + col) of the SLAM grid image pixel it falls in, -1 outside.
std::vector<int> planToSlamPixels(int rows, int cols, double resolution,
                                  const mrpt::maps::COccupancyGridMap2D& grid,
                                  const mrpt::math::TPose2D& slamToPlan) {
    const mrpt::poses::CPose2D planToSlam = -mrpt::poses::CPose2D(slamToPlan);
    const int sx = static_cast<int>(grid.getSizeX()), sy = static_cast<int>(grid.getSizeY());
    std::vector<int> index(static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols), -1);
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < cols; ++c) {
            double qx = 0, qy = 0;
            planToSlam.composePoint((c + 0.5) * resolution, (rows - 1 - r + 0.5) * resolution, qx,
                                    qy);
            const int cx = grid.x2idx(qx), cy = grid.y2idx(qy);
            if (cx >= 0 && cy >= 0 && cx < sx && cy < sy)
                index[static_cast<std::size_t>(r) * static_cast<std::size_t>(cols) +
                      static_cast<std::size_t>(c)] = (sy - 1 - cy) * sx + cx;
        }
    }
    return index;
}

template <class T>
cv::Mat resample(const cv::Mat& slamImage, const std::vector<int>& index, int rows, int cols) {
    cv::Mat out = cv::Mat::zeros(rows, cols, slamImage.type());
    const T* in = slamImage.ptr<T>(0);
    T* o = out.ptr<T>(0);
    for (std::size_t i = 0; i < index.size(); ++i) {
        if (index[i] >= 0)
            o[i] = in[index[i]];
    }
    return out;
}

// The SLAM frame -> plan frame transform from the poses both trajectories have (same stamps).
mrpt::math::TPose2D alignTrajectories(const io::Trajectory2D& slam, const io::Trajectory2D& truth,
                                      double& rmse) {
    std::vector<mrpt::math::TPoint2D> a, b;
    std::size_t j = 0;
    for (const auto& p : slam) {
        while (j < truth.size() && truth[j].stamp < p.stamp - 1e-4)
            ++j;
        if (j < truth.size() && std::abs(truth[j].stamp - p.stamp) <= 1e-4) {
            a.emplace_back(p.pose.x, p.pose.y);
            b.emplace_back(truth[j].pose.x, truth[j].pose.y);
        }
    }
    if (a.size() < 2)
        throw std::runtime_error(
            "the SLAM trajectory shares fewer than 2 stamps with the ground truth");
    const mrpt::math::TPose2D t = evaluation::alignRigid2D(a, b);
    const mrpt::poses::CPose2D tp(t);
    double sum = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        double qx = 0, qy = 0;
        tp.composePoint(a[i].x, a[i].y, qx, qy);
        sum += (qx - b[i].x) * (qx - b[i].x) + (qy - b[i].y) * (qy - b[i].y);
    }
    rmse = std::sqrt(sum / static_cast<double>(a.size()));
    return t;
}

}  // namespace

std::vector<PlanToTour> plansToTour(const std::vector<unsigned>& seeds,
                                    const std::vector<std::string>& bormannMaps,
                                    const std::string& bormannDir,
                                    const std::vector<unsigned>& ringSeeds) {
    std::vector<PlanToTour> plans;
    const auto generated = [&](unsigned seed, simulation::BuildingStyle style) {
        simulation::FloorPlanGeneratorOptions options;
        options.style = style;
        const auto images = simulation::drawFloorPlan(simulation::generateFloorPlan(seed, options));
        plans.push_back({generatedPlanName(seed, style) + "_furnitures", images.resolution,
                         images.furnished, images.map == 255, images.rooms});
    };
    for (const unsigned seed : seeds)
        generated(seed, simulation::BuildingStyle::Office);
    for (const std::string& base : bormannMaps) {
        // The turned-by-0 cases carry the maps and ground truth exactly as B4 reads them.
        auto cases = rooms::bormannCases(bormannDir, base, {0});
        const rooms::RoomBenchmarkCase& unfurnished = cases[0];
        const rooms::RoomBenchmarkCase& furnished = cases[1];
        plans.push_back({furnished.map, furnished.grid.getResolution(), furnished.inputFree,
                         unfurnished.inputFree, unfurnished.truth.labels});
    }
    for (const unsigned seed : ringSeeds)
        generated(seed, simulation::BuildingStyle::Ring);
    return plans;
}

// Ground-truth rooms of which less than kInViewShare of the pixels are in line of sight of the
// tour's poses. `map`: the plan's grid (image row r is grid row rows - 1 - r).
std::vector<int> roomsOutOfView(const rooms::GroundTruthRooms& truth,
                                const simulation::ClearanceMap& map, const io::Trajectory2D& poses,
                                double viewRange) {
    constexpr double kInViewShare = 0.1;
    const std::vector<std::uint8_t> seen = simulation::cellsInView(map, poses, viewRange);
    const simulation::GridGeometry& g = map.geometry();
    std::vector<std::size_t> pixels(static_cast<std::size_t>(truth.count) + 1, 0);
    std::vector<std::size_t> inView(pixels.size(), 0);
    for (int r = 0; r < truth.labels.rows; ++r) {
        const int* row = truth.labels.ptr<int>(r);
        for (int c = 0; c < truth.labels.cols; ++c) {
            const auto label = static_cast<std::size_t>(row[c]);
            ++pixels[label];
            inView[label] += seen[g.index(c, truth.labels.rows - 1 - r)];
        }
    }
    std::vector<int> out;
    for (int label = 1; label <= truth.count; ++label) {
        const auto l = static_cast<std::size_t>(label);
        if (static_cast<double>(inView[l]) < kInViewShare * static_cast<double>(pixels[l]))
            out.push_back(label);
    }
    return out;
}

simulation::SimulatorConfig endToEndSimulatorDefaults() {
    simulation::SimulatorConfig config;
    config.tour.coverage.lookIntoUnseen = true;
    return config;
}

rooms::RoomBenchmarkCase drawnPlanCase(const PlanToTour& plan) {
    rooms::RoomBenchmarkCase c =
        rooms::drawnCase("drawn", plan.name, true, 0, plan.map == 255, plan.unfurnishedFree,
                         plan.roomLabels, plan.resolution);
    c.openFloor = rooms::openFloorOfRooms(c.truth, plan.map == 255);
    return c;
}

rooms::RoomBenchmarkCase endToEndCase(const PlanToTour& plan, const EndToEndOptions& options,
                                      EndToEndRun& run) {
    namespace fs = std::filesystem;
    const auto grid = gridOfMapImage(plan.map, plan.resolution);
    const simulation::ClearanceMap clearance(grid, options.simulator.log.world.thresholds);
    const simulation::TourOptions tourOptions = simulation::plannedTour(options.simulator);
    io::Trajectory2D poses = options.poses;
    run.tourLength = 0;
    if (poses.empty()) {
        const simulation::Tour tour = simulation::planTour(clearance, tourOptions);
        poses = tour.poses;
        run.tourLength = tour.length;
    } else {
        for (std::size_t i = 1; i < poses.size(); ++i) {
            run.tourLength += std::hypot(poses[i].pose.x - poses[i - 1].pose.x,
                                         poses[i].pose.y - poses[i - 1].pose.y);
        }
    }
    fs::create_directories(options.workDir);
    const std::string rawlog = (fs::path(options.workDir) / (plan.name + ".rawlog")).string();
    const std::string truthPath = (fs::path(options.workDir) / (plan.name + "_gt.txt")).string();
    run.scans = simulation::simulateLogToFiles(grid, poses, options.simulator.log, rawlog,
                                               options.simulator.format, truthPath);
    const mapping::MappingResult slam = mapping::mapLog(rawlog, *options.slamConfig);
    run.slamSeconds = slam.wallSeconds;
    run.slamToPlan =
        alignTrajectories(slam.trajectory, io::loadTrajectory(truthPath), run.alignmentRmse);

    rooms::RoomBenchmarkCase c;
    c.dataset = "slam";
    c.map = plan.name;
    c.furnished = true;
    c.grid = slam.grid;
    c.inputFree = freeImageOf(slam.grid);
    for (const auto& p : slam.trajectory)
        c.trajectory.push_back(p.pose);
    const int rows = plan.map.rows, cols = plan.map.cols;
    const auto index = std::make_shared<std::vector<int>>(
        planToSlamPixels(rows, cols, plan.resolution, slam.grid, run.slamToPlan));
    c.scoredFree = resample<std::uint8_t>(c.inputFree, *index, rows, cols);
    c.toTruthFrame = [index, rows, cols](const cv::Mat& labels) {
        return resample<int>(labels, *index, rows, cols);
    };
    // Doors are matched in the plan's pixels, whatever the SLAM grid's cell size.
    c.truthResolution = plan.resolution;
    c.truth = rooms::groundTruthFromLabels(plan.roomLabels);
    c.trueDoors = rooms::labelBoundaryDoors(c.truth.labels, plan.unfurnishedFree);
    c.openFloor = rooms::openFloorOfRooms(c.truth, plan.map == 255);
    run.roomsOutOfView = roomsOutOfView(c.truth, clearance, poses, tourOptions.coverage.viewRange);
    return c;
}

}  // namespace toposlam::roomsbench
