// SplitAndMergeExtractor (IEPF baseline): exact on noise-free scans, same output type and
// invariances as the corner extractor.
#include <gtest/gtest.h>
#include <toposlam/featureeval/FeatureGroundTruth.h>
#include <toposlam/features/SplitAndMergeExtractor.h>

#include <cmath>

#include "FeatureTestScenes.h"

using namespace toposlam;
using namespace toposlam::features;

TEST(SplitAndMergeExtractor, ExactCornersAndLinesWithoutNoise) {
    // Noise-free readings lie on the walls (float ranges: < 1e-6 m), and the split reading,
    // which may belong to either wall, is in neither fit: corners within 1e-4 m.
    const auto scene = test::roomWithBox();
    const mrpt::poses::CPose2D pose(0.5, -0.7, 0.6);
    const auto scan = test::scanOf(scene, pose, 1081, 1.5 * M_PI);
    SplitAndMergeExtractor ex;
    ScanFeatures f;
    ex.extract(scan, f);
    const auto gt = featureeval::computeGroundTruth(scene, pose, scan);
    std::vector<mrpt::math::TPoint2D> found;
    for (const Corner& c : f.corners)
        found.push_back(c.position);
    int counted = 0;
    for (const auto& g : gt.corners) {
        if (g.dontCare)
            continue;
        ++counted;
        EXPECT_LT(test::nearest(g.position, found), 1e-4) << g.position.x << ", " << g.position.y;
    }
    EXPECT_GE(counted, 3);
    for (const LineSegment& s : f.segments)
        EXPECT_LT(s.residualRms, 1e-4);
}

TEST(SplitAndMergeExtractor, BeamOrderAndDegenerateScans) {
    std::mt19937 rng(5);
    const auto scene = featureeval::makeSyntheticRoom(rng);
    const auto scan = test::scanOf(scene, scene.poses[0], 361, M_PI, 0.01);
    SplitAndMergeExtractor a, b;
    ScanFeatures fa, fb;
    a.extract(scan, fa);
    b.extract(test::reversed(scan), fb);
    ASSERT_EQ(fa.corners.size(), fb.corners.size());
    for (std::size_t i = 0; i < fa.corners.size(); ++i) {
        EXPECT_EQ(fa.corners[i].position.x, fb.corners[fa.corners.size() - 1 - i].position.x);
    }
    mrpt::obs::CObservation2DRangeScan empty;
    a.extract(empty, fa);
    EXPECT_TRUE(fa.segments.empty() && fa.corners.empty());
    empty.aperture = static_cast<float>(M_PI);
    empty.maxRange = 10;
    empty.resizeScanAndAssign(100, 3.0f, false);
    a.extract(empty, fa);
    EXPECT_TRUE(fa.segments.empty());
}
