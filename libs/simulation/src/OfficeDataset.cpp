#include <toposlam/io/AtomicFile.h>
#include <toposlam/io/GridMapIO.h>
#include <toposlam/io/TextFile.h>
#include <toposlam/simulation/OfficeDataset.h>
#include <toposlam/simulation/OfficeFloorPlan.h>
#include <toposlam/simulation/TrajectoryImage.h>

#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <set>
#include <stdexcept>

namespace toposlam::simulation {

namespace fs = std::filesystem;

std::vector<std::string> officeDatasetFileNames() {
    return {"office.gridmap.gz", "office.png",       "office.yaml",
            "office.pgm",        "office_rooms.png", "office_rooms.json",
            "office.rawlog",     "office_gt.txt",    "office_tour.png"};
}

OfficeDataset writeOfficeDataset(const std::string& dir, const SimulatorConfig& config,
                                 const io::ProgressCallback& progress) {
    validate(config);
    fs::create_directories(dir);
    const auto file = [&](const std::string& name) { return (fs::path(dir) / name).string(); };
    OfficeDataset out;
    io::OutputGroup files;  // renamed together at the end: a failure leaves `dir` as it was

    const FloorPlan plan = makeOfficeFloorPlan();
    const auto grid = plan.rasterise(OfficeDataset::kResolution, OfficeDataset::kMargin);
    io::saveGridMap(grid, file("office.gridmap.gz"));
    io::saveGridMap(grid, file("office.png"));
    // office.png is the picture; office.yaml + office.pgm the ROS map_server pair.
    out.files = {file("office.gridmap.gz"), file("office.png"), file("office.yaml"),
                 file("office.pgm")};

    // Room labels as an image with the map's geometry (top row = highest y).
    const GridGeometry g = GridGeometry::of(grid);
    const std::vector<std::uint8_t> labels = plan.roomLabels(grid);
    cv::Mat labelImage(g.sizeY, g.sizeX, CV_8UC1);
    for (int cy = 0; cy < g.sizeY; ++cy) {
        for (int cx = 0; cx < g.sizeX; ++cx) {
            labelImage.at<std::uint8_t>(g.sizeY - 1 - cy, cx) = labels[g.index(cx, cy)];
        }
    }
    io::writeFileAtomically(file("office_rooms.png"), [&](const std::string& tmp) {
        if (!cv::imwrite(tmp, labelImage))
            throw std::runtime_error(file("office_rooms.png") + ": cannot write the PNG");
    });
    io::saveTextFile(plan.toJson(grid, "office.gridmap.gz", "office_rooms.png"),
                     file("office_rooms.json"));
    out.files.push_back(file("office_rooms.png"));
    out.files.push_back(file("office_rooms.json"));

    // The tour and its log.
    const ClearanceMap clearance(grid, config.log.world.thresholds);
    const Tour tour = planTour(clearance, plannedTour(config));
    simulateLogToFiles(grid, tour.poses, config.log, file("office.rawlog"), config.format,
                       file("office_gt.txt"), progress);
    std::vector<mrpt::math::TPoint2D> centres;
    for (std::size_t a : tour.visitOrder)
        centres.push_back(tour.areas[a].centre);
    saveTrajectoryImage(grid, tour.poses, centres, file("office_tour.png"));
    out.files.push_back(file("office.rawlog"));
    out.files.push_back(file("office_gt.txt"));
    out.files.push_back(file("office_tour.png"));
    files.commit();

    out.scans = tour.poses.size();
    out.tourLength = tour.length;
    out.duration = tour.poses.back().stamp - tour.poses.front().stamp;
    std::set<int> visited;
    for (const auto& p : tour.poses)
        visited.insert(plan.roomAt({p.pose.x, p.pose.y}));
    visited.erase(0);
    out.roomsVisited = visited.size();
    out.rooms = plan.rooms().size();
    return out;
}

}  // namespace toposlam::simulation
