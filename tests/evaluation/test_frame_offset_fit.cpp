// The frame a relation file fits best (FrameOffsetFit.h): a trajectory of a point 0.12 m behind
// the one the relations were made for is found 0.12 m off, and scored there it is exact; one
// already in the right frame gains nothing, and the evaluation table names the frame only then.
#include "FigureOfEight.h"

#include <gtest/gtest.h>
#include <toposlam/evaluation/FrameOffsetFit.h>
#include <toposlam/evaluation/GroundTruthRelations.h>
#include <toposlam/evaluation/SlamEvaluation.h>

#include <cmath>

using namespace toposlam::evaluation;
using toposlam::evaluation::test_paths::figureOfEight;
using toposlam::io::Trajectory2D;

namespace {

// The same path, each pose moved `d` m along its heading.
Trajectory2D moved(Trajectory2D t, double d) {
    for (auto& p : t) {
        p.pose.x += d * std::cos(p.pose.phi);
        p.pose.y += d * std::sin(p.pose.phi);
    }
    return t;
}

}  // namespace

TEST(FrameOffsetFit, FindsTheFrameTheRelationsWereMadeIn) {
    const Trajectory2D truth = figureOfEight();
    const PoseRelations relations = relationsFromGroundTruth(truth, {});
    const Trajectory2D behind = moved(truth, -0.12);  // e.g. the robot's centre, not the laser
    const RelativePoseErrorResult scored = evaluateRelativePoseError(behind, relations);
    ASSERT_GT(scored.translation.mean, 0.01);
    const FrameOffsetFit fit = fitFrameOffset(behind, relations, scored);
    EXPECT_NEAR(fit.offset, 0.12, 1e-3);
    EXPECT_LT(fit.meanError, 1e-3);
    EXPECT_NEAR(fit.meanErrorAsIs, scored.translation.mean, 1e-12);
    EXPECT_NEAR(fit.gain(), scored.translation.mean - fit.meanError, 1e-12);

    // Already in the relations' frame: nothing to gain.
    const RelativePoseErrorResult exact = evaluateRelativePoseError(truth, relations);
    const FrameOffsetFit none = fitFrameOffset(truth, relations, exact);
    EXPECT_NEAR(none.offset, 0.0, 1e-3);
    EXPECT_NEAR(none.gain(), 0.0, 1e-9);
}

TEST(FrameOffsetFit, TheTableNamesTheFrameOnlyWhenItHelps) {
    const Trajectory2D truth = figureOfEight();
    SlamEvaluation ev;
    ev.referenceFile = "truth";
    const PoseRelations relations = relationsFromGroundTruth(truth, {});
    ev.relationCount = relations.size();
    ev.methods.push_back(
        evaluateMethod("centre", "", moved(truth, -0.12), relations, nullptr, 1e-5));
    ev.methods.push_back(evaluateMethod("laser", "", truth, relations, nullptr, 1e-5));
    EXPECT_NEAR(ev.methods[0].bestFrame.offset, 0.12, 1e-3);
    const std::string table = formatEvaluationTable(ev);
    EXPECT_NE(table.find("- centre: 0.120 m ahead of the poses scored"), std::string::npos)
        << table;
    EXPECT_EQ(table.find("- laser:"), std::string::npos) << table;
    // No relation matched: nothing fitted, nothing claimed.
    const FrameOffsetFit empty = fitFrameOffset(truth, relations, RelativePoseErrorResult{});
    EXPECT_EQ(empty.offset, 0.0);
    EXPECT_EQ(empty.gain(), 0.0);
}
