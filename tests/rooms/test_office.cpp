// The project's simulated office (share/office, made by toposlam-sim): its ground-truth rooms
// (office_rooms.png, one grey level per room id) and doors (office_rooms.json) are exact, so
// the room count, the door count and which rooms each door joins must come out exactly.
#include <toposlam/io/GridMapIO.h>
#include <toposlam/io/Trajectory.h>
#include <toposlam/rooms/RoomSegmenter.h>

#include "TestSupport.h"

#include <mrpt/containers/yaml.h>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <cmath>
#include <set>

using namespace toposlam::rooms;

namespace {

struct OfficeTruth {
    std::vector<mrpt::math::TPoint2D> roomPoints;  // one point inside each room, by id - 1
    struct TrueDoor {
        mrpt::math::TPoint2D middle;
        int roomA, roomB;
    };
    std::vector<TrueDoor> doors;
};

// A point inside each ground-truth room: its labelled, free cell nearest to the room's mean
// cell (the label image covers furniture too).
OfficeTruth loadTruth(const std::string& dir, const mrpt::maps::COccupancyGridMap2D& grid) {
    OfficeTruth truth;
    const auto doc = mrpt::containers::yaml::FromFile(dir + "/office_rooms.json");
    const auto& labels = doc["room_labels"];
    const double res = labels["resolution"].as<double>();
    const double ox = labels["origin"](0).as<double>(), oy = labels["origin"](1).as<double>();
    const cv::Mat img = cv::imread(dir + "/office_rooms.png", cv::IMREAD_GRAYSCALE);
    const int rooms = static_cast<int>(doc["rooms"].size());
    for (int id = 1; id <= rooms; ++id) {
        double mx = 0, my = 0;
        int n = 0;
        for (int r = 0; r < img.rows; ++r) {
            for (int c = 0; c < img.cols; ++c) {
                if (img.at<std::uint8_t>(r, c) != id)
                    continue;
                mx += c;
                my += r;
                ++n;
            }
        }
        mx /= n;
        my /= n;
        cv::Point best;
        double bestDistance = 1e18;
        for (int r = 0; r < img.rows; ++r) {
            for (int c = 0; c < img.cols; ++c) {
                const double d = (c - mx) * (c - mx) + (r - my) * (r - my);
                const double x = ox + (c + 0.5) * res, y = oy + (img.rows - 1 - r + 0.5) * res;
                if (img.at<std::uint8_t>(r, c) == id && d < bestDistance &&
                    grid.getPos(static_cast<float>(x), static_cast<float>(y)) > 0.9f) {
                    bestDistance = d;
                    best = {c, r};
                }
            }
        }
        truth.roomPoints.push_back(
            {ox + (best.x + 0.5) * res, oy + (img.rows - 1 - best.y + 0.5) * res});
    }
    for (const auto& d : doc["doors"].asSequence()) {
        const auto& j = d.asMap().at("jambs").asSequence();
        const auto& a = j[0].asSequence();
        const auto& b = j[1].asSequence();
        const auto& roomsOf = d.asMap().at("rooms").asSequence();
        truth.doors.push_back({{0.5 * (a[0].as<double>() + b[0].as<double>()),
                                0.5 * (a[1].as<double>() + b[1].as<double>())},
                               roomsOf[0].as<int>(),
                               roomsOf[1].as<int>()});
    }
    return truth;
}

void expectExact(const TopologicalMap& map, const OfficeTruth& truth) {
    std::vector<int> found;  // segment of each ground-truth room
    std::set<int> distinct;
    for (const auto& p : truth.roomPoints) {
        found.push_back(map.roomAt(p.x, p.y));
        EXPECT_GT(found.back(), 0);
        distinct.insert(found.back());
    }
    EXPECT_EQ(distinct.size(), truth.roomPoints.size()) << "ground-truth rooms share segments";
    EXPECT_EQ(map.rooms.size(), truth.roomPoints.size());
    ASSERT_EQ(map.doors.size(), truth.doors.size());
    for (const auto& t : truth.doors) {
        const Door* best = nullptr;
        double bestDistance = 1e9;
        for (const auto& d : map.doors) {
            const double dist = std::hypot(d.middle().x - t.middle.x, d.middle().y - t.middle.y);
            if (dist < bestDistance) {
                bestDistance = dist;
                best = &d;
            }
        }
        // The cut lies in the doorway: within the wall thickness (0.1 m) and a cell or two of
        // the drawn door line.
        EXPECT_LT(bestDistance, 0.2) << "door at (" << t.middle.x << ", " << t.middle.y << ")";
        const int a = found[static_cast<std::size_t>(t.roomA - 1)],
                  b = found[static_cast<std::size_t>(t.roomB - 1)];
        EXPECT_EQ(std::min(best->roomA, best->roomB), std::min(a, b));
        EXPECT_EQ(std::max(best->roomA, best->roomB), std::max(a, b));
    }
}

class OfficeRooms : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = toposlam::test::shareDir() + "/office";
        grid_ = toposlam::io::loadGridMap(dir_ + "/office.gridmap.gz");
        truth_ = loadTruth(dir_, grid_);
        for (const auto& p : toposlam::io::loadTrajectory(dir_ + "/office_gt.txt"))
            tour_.push_back(p.pose);
        ASSERT_EQ(truth_.roomPoints.size(), 11u);
        ASSERT_EQ(truth_.doors.size(), 12u);
    }
    std::string dir_;
    mrpt::maps::COccupancyGridMap2D grid_;
    OfficeTruth truth_;
    std::vector<mrpt::math::TPose2D> tour_;
};

TEST_F(OfficeRooms, FromTheTrajectory) {
    expectExact(RoomSegmenter().segment(grid_, tour_).map, truth_);
}

TEST_F(OfficeRooms, FromTheMedialAxis) {
    expectExact(RoomSegmenter().segment(grid_).map, truth_);
}

TEST_F(OfficeRooms, PaperExactFromTheTrajectory) {
    expectExact(RoomSegmenter(RoomSegmenter::Options::paperExact()).segment(grid_, tour_).map,
                truth_);
}

}  // namespace
