// config_ini/graph-matcher.ini documents every option with its default: it must stay equal to
// the built-in defaults, and every key must be read (no typo silently ignored).
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/slam/CICP.h>
#include <toposlam/matching/CGraphMatcherAlignment.h>

#include <TestSupport.h>

#include <fstream>
#include <set>

using toposlam::matching::GraphMatcherOptions;

namespace {
std::string configFile(const std::string& name) {
    return toposlam::test::shareDir() + "/../config_ini/" + name;
}
}  // namespace

TEST(ConfigIni, GraphMatcherIniEqualsTheDefaults) {
    mrpt::config::CConfigFile ini(configFile("graph-matcher.ini"));
    GraphMatcherOptions fromFile, d;
    // Start from values that differ from every default, so each key has to be read.
    fromFile.minSegmentLength = fromFile.minLengthRatio = -1;
    fromFile.maxSegments = fromFile.refineTop = fromFile.minInliers = 999;
    fromFile.spgm.maxIterations = fromFile.icp.maxIterations = fromFile.scanIcp.maxIterations = -1;
    fromFile.ransac.maxHypotheses = fromFile.hough.maxRotations = 999;
    fromFile.minInlierFraction = fromFile.ambiguityMargin = fromFile.maxTranslationStd = -1;
    fromFile.minVisibleInlierRatio = -1;
    fromFile.weakDirectionRange = fromFile.weakDirectionElongation = -1;
    fromFile.scanRefinement = fromFile.houghFallback = fromFile.symmetricScore = false;
    fromFile.guessFreeRetry = false;
    fromFile.loadFromConfigFile(ini, "GraphScanMatcher");
#define SAME(field) EXPECT_DOUBLE_EQ(double(fromFile.field), double(d.field)) << #field
    SAME(minSegmentLength);
    SAME(maxSegments);
    SAME(minLengthRatio);
    SAME(guessTranslationWindow);
    SAME(guessRotationWindow);
    SAME(guessFreeRetry);
    SAME(similarity.alpha);
    SAME(similarity.maxAngleDifference);
    SAME(spgm.maxIterations);
    SAME(spgm.tolerance);
    SAME(spgm.projectionCycles);
    SAME(spgm.projectionTolerance);
    SAME(ransac.maxHypotheses);
    SAME(ransac.maxSingleHypotheses);
    SAME(ransac.alternativesPerSegment);
    SAME(ransac.probabilityFloor);
    SAME(ransac.minSampleAngle);
    SAME(ransac.sampleAngleTolerance);
    SAME(ransac.consensusAngle);
    SAME(ransac.shortSegmentAngleSlack);
    SAME(ransac.consensusDistance);
    SAME(ransac.overlapMargin);
    SAME(ransac.maxKept);
    SAME(ransac.distinctTranslation);
    SAME(ransac.distinctRotation);
    SAME(refineTop);
    SAME(screenStride);
    SAME(polishRatio);
    SAME(icp.maxIterations);
    SAME(icp.maxDistance);
    SAME(icp.robustScale);
    SAME(icp.translationTolerance);
    SAME(icp.rotationTolerance);
    SAME(icp.stride);
    SAME(icp.minNoiseStd);
    SAME(icp.minEigenRatio);
    SAME(alongLineConditioning);
    SAME(alongLine.range);
    SAME(alongLine.bin);
    SAME(alongLine.acrossTolerance);
    SAME(alongLine.fineStep);
    SAME(alongLine.peaks);
    SAME(alongLine.stride);
    SAME(scanRefinement);
    SAME(scanIcp.maxIterations);
    SAME(scanIcp.maxDistance);
    SAME(scanIcp.robustScale);
    SAME(scanIcp.stride);
    SAME(scanIcp.minNoiseStd);
    SAME(scanIcp.minEigenRatio);
    SAME(symmetricScore);
    SAME(score.inlierDistance);
    SAME(score.searchBeams);
    SAME(score.stride);
    SAME(score.maxJoinDistance);
    SAME(weakDirectionRange);
    SAME(weakDirectionElongation);
    SAME(houghFallback);
    SAME(houghRefineTop);
    SAME(hough.maxRotations);
    SAME(hough.rotationBin);
    SAME(hough.minRotationWeight);
    SAME(hough.window);
    SAME(hough.cell);
    SAME(hough.stride);
    SAME(hough.peaksPerRotation);
    SAME(hough.minPeakFraction);
    SAME(minInliers);
    SAME(minInlierRatio);
    SAME(minVisibleInlierRatio);
    SAME(minInlierFraction);
    SAME(maxTranslationStd);
    SAME(ambiguityMargin);
#undef SAME
    toposlam::matching::CGraphMatcherAlignment::Options alignment, alignmentDefaults;
    alignment.useGuess = false;
    alignment.unreliableVariance = -1;
    alignment.loadFromConfigFile(ini, "GraphScanMatcher");
    EXPECT_EQ(alignment.useGuess, alignmentDefaults.useGuess);
    EXPECT_DOUBLE_EQ(alignment.unreliableVariance, alignmentDefaults.unreliableVariance);

    // Every key in the file is one the loader knows (the list above, by name).
    std::ifstream in(configFile("graph-matcher.ini"));
    std::set<std::string> keys;
    for (std::string line; std::getline(in, line);) {
        const std::size_t eq = line.find('=');
        if (line.empty() || line[0] == '#' || line[0] == '[' || eq == std::string::npos)
            continue;
        std::string key = line.substr(0, eq);
        key.erase(key.find_last_not_of(" \t") + 1);
        keys.insert(key);
    }
    EXPECT_EQ(keys.size(), 75u) << "a key was added or removed: update this test and the file";
}

TEST(ConfigIni, BenchIcpIniLoads) {
    mrpt::config::CConfigFile ini(configFile("bench-matching-icp.ini"));
    mrpt::slam::CICP::TConfigParams p;
    p.onlyUniqueRobust = false;
    p.loadFromConfigFile(ini, "ICP");
    EXPECT_EQ(p.maxIterations, 80u);
    EXPECT_FLOAT_EQ(p.thresholdDist, 0.5f);
    EXPECT_FLOAT_EQ(p.ALFA, 0.8f);
    EXPECT_TRUE(p.onlyUniqueRobust);
}
