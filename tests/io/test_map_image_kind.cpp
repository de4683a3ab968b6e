// How a bare map picture is read (io/MapImageKind.h): the guess from its greys, which pictures
// are bare at all, and a map_saver picture read without its .yaml as map_server reads it.
#include <gtest/gtest.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <toposlam/io/GridMapIO.h>
#include <toposlam/io/InputError.h>
#include <toposlam/io/MapImageKind.h>

#include <array>
#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "TestSupport.h"

namespace fs = std::filesystem;
using toposlam::io::guessMapImageKind;
using toposlam::io::MapImageKind;

namespace {

std::array<std::size_t, 256> histogram(std::initializer_list<std::pair<int, std::size_t>> counts) {
    std::array<std::size_t, 256> h{};
    for (const auto& [grey, n] : counts)
        h[static_cast<std::size_t>(grey)] += n;
    return h;
}

// A 60 x 40 picture: a white room with walls of `wall` grey, in a background of `outside`.
cv::Mat roomPicture(int wall, int outside) {
    cv::Mat image(40, 60, CV_8U, cv::Scalar(outside));
    cv::rectangle(image, cv::Rect(10, 10, 40, 20), cv::Scalar(wall), cv::FILLED);
    cv::rectangle(image, cv::Rect(12, 12, 36, 16), cv::Scalar(255), cv::FILLED);
    return image;
}

}  // namespace

TEST(MapImageKind, SlamGridsHaveUnknownSpaceAndOccupiedWalls) {
    // MRPT draws unknown 127/128, ROS map_saver 205; walls dark.
    EXPECT_EQ(guessMapImageKind(histogram({{255, 5000}, {128, 8000}, {10, 600}})).kind,
              MapImageKind::OccupancyGrid);
    EXPECT_EQ(guessMapImageKind(histogram({{254, 5000}, {205, 8000}, {0, 600}})).kind,
              MapImageKind::OccupancyGrid);
    // Lightly seen free cells (light greys) and a ramp of occupancy change nothing.
    EXPECT_EQ(
        guessMapImageKind(histogram({{255, 5000}, {230, 900}, {127, 8000}, {60, 100}, {0, 500}}))
            .kind,
        MapImageKind::OccupancyGrid);
}

TEST(MapImageKind, DrawingsHaveNoUnknownSpace) {
    // Bormann et al.'s plans: light-grey walls (211) in a grey background (180).
    EXPECT_EQ(guessMapImageKind(histogram({{255, 5000}, {211, 600}, {180, 3000}, {0, 200}})).kind,
              MapImageKind::DrawnPlan);
    // Mid-grey walls but no occupied cell at all: a grid like that would bound nothing.
    EXPECT_EQ(guessMapImageKind(histogram({{255, 5000}, {153, 4000}})).kind,
              MapImageKind::DrawnPlan);
    // A mid-grey minority (a few grey symbols in a light background) is no unknown space.
    const auto guess = guessMapImageKind(histogram({{255, 5000}, {230, 4000}, {127, 500}}));
    EXPECT_EQ(guess.kind, MapImageKind::DrawnPlan);
    EXPECT_NEAR(guess.midGreyShare(), 500.0 / 4500.0, 1e-12);
    EXPECT_NE(guess.reason().find("11 %"), std::string::npos) << guess.reason();
    // Black and white only.
    EXPECT_EQ(guessMapImageKind(histogram({{255, 5000}, {0, 4000}})).kind, MapImageKind::DrawnPlan);
}

TEST(MapImageKind, EdgesOfTheRule) {
    // All white: nothing to tell, read as a grid (as every picture was before the guess).
    EXPECT_EQ(guessMapImageKind(histogram({{255, 100}})).kind, MapImageKind::OccupancyGrid);
    // Exactly half mid grey, with walls: a grid; just under half: a plan.
    EXPECT_EQ(guessMapImageKind(histogram({{255, 10}, {128, 50}, {200, 49}, {0, 1}})).kind,
              MapImageKind::OccupancyGrid);
    EXPECT_EQ(guessMapImageKind(histogram({{255, 10}, {128, 49}, {200, 50}, {0, 1}})).kind,
              MapImageKind::DrawnPlan);
    // The band's ends: 90 and 165 are mid grey, 89 is dark, 166 is not mid grey.
    EXPECT_EQ(guessMapImageKind(histogram({{90, 50}, {165, 49}, {89, 1}})).midGreyPixels, 99u);
    EXPECT_EQ(guessMapImageKind(histogram({{166, 50}, {89, 1}})).midGreyPixels, 0u);
    // Dark pixels below kMinDarkShare of the non-white ones are specks, not walls.
    EXPECT_EQ(guessMapImageKind(histogram({{128, 100000}, {0, 99}})).kind, MapImageKind::DrawnPlan);
    EXPECT_EQ(guessMapImageKind(histogram({{128, 100000}, {0, 101}})).kind,
              MapImageKind::OccupancyGrid);
}

TEST(MapImageKind, ReadsThePictureAsLoadGridMapDoes) {
    const toposlam::test::TempDir dir;
    ASSERT_TRUE(cv::imwrite(dir.file("plan.png"), roomPicture(211, 180)));
    EXPECT_EQ(guessMapImageKind(dir.file("plan.png")).kind, MapImageKind::DrawnPlan);
    ASSERT_TRUE(cv::imwrite(dir.file("grid.png"), roomPicture(0, 128)));
    const auto grid = guessMapImageKind(dir.file("grid.png"));
    EXPECT_EQ(grid.kind, MapImageKind::OccupancyGrid);
    EXPECT_EQ(grid.nonWhitePixels, 60u * 40u - 36u * 16u);
    EXPECT_EQ(grid.darkPixels, 40u * 20u - 36u * 16u);
    // A colour picture is read as grey.
    cv::Mat colour;
    cv::cvtColor(roomPicture(0, 128), colour, cv::COLOR_GRAY2BGR);
    ASSERT_TRUE(cv::imwrite(dir.file("colour.png"), colour));
    EXPECT_EQ(guessMapImageKind(dir.file("colour.png")).kind, MapImageKind::OccupancyGrid);
    EXPECT_THROW(guessMapImageKind(dir.file("missing.png")), toposlam::io::InputError);
}

TEST(MapImageKind, OnlyPicturesWithoutTheirYamlAreBare) {
    const toposlam::test::TempDir dir;
    mrpt::maps::COccupancyGridMap2D g;
    g.setSize(0, 2.0f, 0, 1.5f, 0.05f, 0.5f);
    toposlam::io::saveGridMap(g, dir.file("map.gridmap.gz"));
    toposlam::io::saveGridMap(g, dir.file("pair.png"));  // + pair.yaml + pair.pgm
    ASSERT_TRUE(cv::imwrite(dir.file("alone.png"), roomPicture(0, 128)));
    EXPECT_FALSE(toposlam::io::isBareMapImage(dir.file("map.gridmap.gz")));
    EXPECT_FALSE(toposlam::io::isBareMapImage(dir.file("pair.yaml")));
    EXPECT_FALSE(toposlam::io::isBareMapImage(dir.file("pair.pgm")));
    EXPECT_FALSE(toposlam::io::isBareMapImage(dir.file("pair.png")));
    EXPECT_TRUE(toposlam::io::isBareMapImage(dir.file("alone.png")));
    fs::remove(dir.file("pair.yaml"));
    EXPECT_TRUE(toposlam::io::isBareMapImage(dir.file("pair.pgm")));
}

TEST(MapImageKind, AMapSaverPictureWithoutItsYamlReadsAsMapServerReadsIt) {
    // The trinary picture saveGridMap writes as ROS map_saver does (occupied 0, unknown 205,
    // free 254), alone: guessed a grid, and read bare every cell is what its .yaml makes it
    // (grey 205 as p(free) = 205 / 255 would sit on the free threshold).
    const toposlam::test::TempDir dir;
    mrpt::maps::COccupancyGridMap2D g;
    g.setSize(0, 2.0f, 0, 1.5f, 0.05f, 0.5f);  // unknown
    for (int cy = 5; cy < 25; ++cy)
        for (int cx = 5; cx < 35; ++cx)
            g.setCell(cx, cy, cx == 5 || cy == 5 || cx == 34 || cy == 24 ? 0.02f : 0.98f);
    toposlam::io::saveGridMap(g, dir.file("map.pgm"));
    const auto withYaml = toposlam::io::loadGridMap(dir.file("map.yaml"));
    fs::copy_file(dir.file("map.pgm"), dir.file("bare.pgm"));
    ASSERT_TRUE(toposlam::io::isBareMapImage(dir.file("bare.pgm")));
    EXPECT_EQ(guessMapImageKind(dir.file("bare.pgm")).kind, MapImageKind::OccupancyGrid);
    const auto bare = toposlam::io::loadGridMap(dir.file("bare.pgm"));
    ASSERT_EQ(bare.getSizeX(), withYaml.getSizeX());
    ASSERT_EQ(bare.getSizeY(), withYaml.getSizeY());
    for (unsigned cy = 0; cy < bare.getSizeY(); ++cy)
        for (unsigned cx = 0; cx < bare.getSizeX(); ++cx)
            ASSERT_EQ(bare.getCell(cx, cy), withYaml.getCell(cx, cy)) << cx << ", " << cy;
    EXPECT_NEAR(bare.getCell(0, 0), 0.5f, 0.01f) << "unknown";
}
