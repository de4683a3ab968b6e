// The furnished floor-plan generator of B4-gen (offices), B4-flats and B4-rings and its drawings:
// the same seed gives the same plan; every plan is a closed building whose rooms are all reachable,
// doors join two rooms and stay clear of furniture; drawings at an angle keep every room's area and
// the doors.
#include <toposlam/simulation/FloorPlanGenerator.h>
#include <toposlam/simulation/FloorPlanImages.h>

#include "TestSupport.h"

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <cmath>
#include <filesystem>
#include <map>
#include <set>

using namespace toposlam::simulation;

namespace {

// Pixels per ground-truth room.
std::map<int, int> roomAreas(const cv::Mat& rooms) {
    std::map<int, int> areas;
    for (int r = 0; r < rooms.rows; ++r) {
        for (int c = 0; c < rooms.cols; ++c) {
            if (rooms.at<int>(r, c) > 0)
                ++areas[rooms.at<int>(r, c)];
        }
    }
    return areas;
}

// The labels of the 4-connected free region of `free` (CV_8U) that holds the most pixels.
cv::Mat largestRegion(const cv::Mat& free) {
    cv::Mat labels, stats, centroids;
    const int n = cv::connectedComponentsWithStats(free, labels, stats, centroids, 4, CV_32S);
    int best = 1;
    for (int i = 2; i < n; ++i) {
        if (stats.at<int>(i, cv::CC_STAT_AREA) > stats.at<int>(best, cv::CC_STAT_AREA))
            best = i;
    }
    return labels == best;
}

}  // namespace

TEST(FloorPlanGenerator, SameSeedSamePlan) {
    const auto a = generateFloorPlan(5), b = generateFloorPlan(5), c = generateFloorPlan(6);
    EXPECT_EQ(a.summary, b.summary);
    EXPECT_EQ(a.plan.furnitureBoxes().size(), b.plan.furnitureBoxes().size());
    EXPECT_EQ(a.plan.doors().size(), b.plan.doors().size());
    EXPECT_NE(a.summary, c.summary);
    EXPECT_TRUE(a.unfurnished.furnitureBoxes().empty());
}

namespace {

// Every room of `plan` is reached through doors only in the furnished building, every room is
// larger than the segmenters' smallest room, every door joins two rooms, is at least
// `narrowest` (m) wide and free of furniture, and nothing is free on the image's border.
void expectUsableBuilding(const GeneratedFloorPlan& plan, double narrowest) {
    const auto images = drawFloorPlan(plan);
    const auto areas = roomAreas(images.rooms);
    EXPECT_EQ(static_cast<int>(areas.size()), plan.roomCount);
    for (const auto& [room, pixels] : areas)
        EXPECT_GT(pixels * 0.05 * 0.05, 2.0) << "room " << room;
    const cv::Mat reached = largestRegion(images.furnished == 255);
    std::set<int> reachedRooms;
    for (int r = 0; r < reached.rows; ++r) {
        for (int c = 0; c < reached.cols; ++c) {
            if (reached.at<std::uint8_t>(r, c) != 0 && images.rooms.at<int>(r, c) > 0)
                reachedRooms.insert(images.rooms.at<int>(r, c));
        }
    }
    EXPECT_EQ(static_cast<int>(reachedRooms.size()), plan.roomCount);
    for (const auto& d : images.doors) {
        EXPECT_NE(d.roomA, d.roomB);
        EXPECT_GE(d.width, narrowest - 1e-9);
        const cv::Point middle(cvRound(0.5f * (d.jambA.x + d.jambB.x)),
                               cvRound(0.5f * (d.jambA.y + d.jambB.y)));
        EXPECT_EQ(images.furnished.at<std::uint8_t>(middle), 255);
    }
    EXPECT_EQ(cv::countNonZero(images.map.row(0) == 255), 0);
    EXPECT_EQ(cv::countNonZero(images.map.col(0) == 255), 0);
}

FloorPlanGeneratorOptions flats() {
    FloorPlanGeneratorOptions o;
    o.style = BuildingStyle::Flat;
    return o;
}

}  // namespace

TEST(FloorPlanGenerator, FlatsAreClosedAndEveryRoomIsReachable) {
    std::set<std::string> kinds;
    int lShaped = 0, wideOpenings = 0;
    for (unsigned seed = 1; seed <= 20; ++seed) {
        SCOPED_TRACE("flat seed " + std::to_string(seed));
        const auto plan = generateFloorPlan(seed, flats());
        EXPECT_GE(plan.roomCount, 3);
        EXPECT_EQ(plan.plan.rooms().size(), static_cast<std::size_t>(plan.roomCount));
        expectUsableBuilding(plan, 0.7);
        // A flat has a living room and a bathroom, and no corridor.
        int living = 0, bathrooms = 0;
        for (const auto& room : plan.plan.rooms()) {
            kinds.insert(room.kind);
            living += room.kind == "living";
            bathrooms += room.kind == "bathroom";
            EXPECT_NE(room.kind, "corridor");
        }
        EXPECT_EQ(living, 1);
        EXPECT_GE(bathrooms, 1);
        lShaped += plan.summary.find("L-shaped") != std::string::npos;
        for (const auto& d : plan.plan.doors())
            wideOpenings += d.width > 1.6;
    }
    // The set holds what it claims: L-shaped flats, open kitchens, halls, kitchens, bedrooms.
    EXPECT_GT(lShaped, 0);
    EXPECT_GT(wideOpenings, 0);
    for (const char* kind : {"hall", "kitchen", "bedroom", "bathroom"})
        EXPECT_TRUE(kinds.count(kind)) << kind;
    const auto a = generateFloorPlan(7, flats()), b = generateFloorPlan(7, flats());
    EXPECT_EQ(a.summary, b.summary);
    EXPECT_EQ(a.plan.furnitureBoxes().size(), b.plan.furnitureBoxes().size());
}

TEST(FloorPlanGenerator, RoomsAreReachableAndDoorsClear) {
    for (unsigned seed = 1; seed <= 20; ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        const auto plan = generateFloorPlan(seed);
        EXPECT_GE(plan.roomCount, 5);
        expectUsableBuilding(plan, 0.8);
    }
}

TEST(FloorPlanGenerator, RingsAreCorridorLoopsAroundRowsOfRooms) {
    FloorPlanGeneratorOptions o;
    o.style = BuildingStyle::Ring;
    for (unsigned seed = 1; seed <= 10; ++seed) {
        SCOPED_TRACE("ring seed " + std::to_string(seed));
        const auto plan = generateFloorPlan(seed, o);
        EXPECT_GE(plan.roomCount, 20);
        expectUsableBuilding(plan, 0.8);
        // The corridor (the last ground-truth room, four boxes) is one region with a hole: the
        // middle block, which a flood from its centre over everything else cannot leave.
        const auto images = drawFloorPlan(plan);
        const cv::Mat corridor = images.rooms == plan.roomCount;
        cv::Mat labels;
        EXPECT_EQ(cv::connectedComponents(corridor, labels, 4), 2);  // background + corridor
        const cv::Rect box = cv::boundingRect(corridor);
        const cv::Point centre = (box.tl() + box.br()) / 2;
        ASSERT_EQ(corridor.at<std::uint8_t>(centre), 0);
        cv::Mat flooded = corridor.clone();
        cv::floodFill(flooded, centre, 255);
        EXPECT_EQ(flooded.at<std::uint8_t>(0, 0), 0)
            << "the flood from the middle block leaked past the corridor to the outside";
    }
    const auto a = generateFloorPlan(4, o), b = generateFloorPlan(4, o);
    EXPECT_EQ(a.summary, b.summary);
    EXPECT_NE(a.summary, generateFloorPlan(4).summary);  // not the office of the same seed
}

TEST(FloorPlanGenerator, DrawingAtAnAngleKeepsRoomsAndDoors) {
    const auto plan = generateFloorPlan(3);
    const auto upright = drawFloorPlan(plan);
    const auto turned = drawFloorPlan(plan, 0.05, 30);
    const auto a = roomAreas(upright.rooms), b = roomAreas(turned.rooms);
    ASSERT_EQ(a.size(), b.size());
    for (const auto& [room, pixels] : a)
        EXPECT_NEAR(b.at(room), pixels, 0.03 * pixels + 40) << "room " << room;
    ASSERT_EQ(upright.doors.size(), turned.doors.size());
    for (std::size_t i = 0; i < turned.doors.size(); ++i) {
        const auto& d = turned.doors[i];
        // Jambs 'width' apart, and the plan point of a jamb pixel is the jamb.
        EXPECT_NEAR(std::hypot(d.jambA.x - d.jambB.x, d.jambA.y - d.jambB.y) * 0.05, d.width,
                    1e-4);  // jambs are stored as float pixels
        const auto p = turned.toPlan(d.jambA.x, d.jambA.y);
        EXPECT_NEAR(p.x, plan.plan.doors()[i].jambA.x, 1e-4);
        EXPECT_NEAR(p.y, plan.plan.doors()[i].jambA.y, 1e-4);
    }
}

TEST(FloorPlanGenerator, SavesTheBenchmarkFiles) {
    const toposlam::test::TempDir dir;
    const auto images = drawFloorPlan(generateFloorPlan(2));
    const auto files = saveFloorPlanImages(images, dir.path(), "plan");
    ASSERT_EQ(files.size(), 4u);
    for (const auto& f : files)
        EXPECT_TRUE(std::filesystem::is_regular_file(f)) << f;
    // The ground-truth image's white 8-connected regions are the rooms (Bormann's reading).
    const cv::Mat truth = cv::imread(dir.file("plan_gt_segmentation.png"), cv::IMREAD_GRAYSCALE);
    cv::Mat labels;
    const int n = cv::connectedComponents(truth > 250, labels, 8, CV_32S) - 1;
    EXPECT_EQ(n, generateFloorPlan(2).roomCount);
    const cv::Mat map = cv::imread(dir.file("plan_furnitures.png"), cv::IMREAD_GRAYSCALE);
    EXPECT_EQ(cv::countNonZero(map != images.furnished), 0);
}
