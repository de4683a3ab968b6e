// The along-track scale (AlongTrackScale.h): a trajectory that reads 2 % short everywhere is
// scored at -2 %, the truth at 0; a place revisited long after, a turn on the spot and a long
// stretch are left out; the evaluation table and its JSON carry the figure.
#include "FigureOfEight.h"

#include <gtest/gtest.h>
#include <toposlam/evaluation/AlongTrackScale.h>
#include <toposlam/evaluation/GroundTruthRelations.h>
#include <toposlam/evaluation/SlamEvaluation.h>

#include <cmath>
#include <string>

using namespace toposlam::evaluation;
using toposlam::evaluation::test_paths::figureOfEight;
using toposlam::io::Trajectory2D;

namespace {

// Every position scaled about the origin, the headings kept: each motion reads `factor` times
// its length, in its own direction.
Trajectory2D scaled(Trajectory2D t, double factor) {
    for (auto& p : t) {
        p.pose.x *= factor;
        p.pose.y *= factor;
    }
    return t;
}

}  // namespace

TEST(AlongTrackScale, AMotionThatReadsShortScoresItsShortfall) {
    const Trajectory2D truth = figureOfEight();
    const PoseRelations relations = relationsFromGroundTruth(truth, {});
    const AlongTrackScale exact =
        alongTrackScale(relations, evaluateRelativePoseError(truth, relations));
    ASSERT_GT(exact.relations, 100u);
    EXPECT_NEAR(exact.percent(), 0.0, 1e-9);

    const AlongTrackScale shortBy2 =
        alongTrackScale(relations, evaluateRelativePoseError(scaled(truth, 0.98), relations));
    EXPECT_EQ(shortBy2.relations, exact.relations);
    EXPECT_NEAR(shortBy2.pathLength, exact.pathLength, 1e-9);
    EXPECT_NEAR(shortBy2.percent(), -2.0, 1e-9);
    EXPECT_NEAR(shortBy2.error, -0.02 * shortBy2.pathLength, 1e-9);
}

TEST(AlongTrackScale, OnlyTheRelationsOfOneStretchOfDrivingCount) {
    // From the pose at 0 s: 1 m ahead after 1 s (the estimate says 0.9 m), 0.5 m from it again
    // after 100 s (a revisit: the estimate has drifted to 3 m), a turn on the spot (0.01 m) and
    // 3 m ahead (longer than kAlongTrackMaxLength).
    const Trajectory2D estimate = {
        {0, {0, 0, 0}}, {1, {0.9, 0, 0}}, {2, {0.01, 0, 1.5}}, {3, {2.0, 0, 0}}, {100, {3, 0, 0}}};
    const PoseRelations relations = {
        {0, 1, {1, 0, 0}}, {0, 100, {0.5, 0, 0.1}}, {0, 2, {0.01, 0, 1.5}}, {0, 3, {3, 0, 0}}};
    const RelativePoseErrorResult scored = evaluateRelativePoseError(estimate, relations);
    ASSERT_EQ(scored.matchedRelations, 4u);
    const AlongTrackScale a = alongTrackScale(relations, scored);
    EXPECT_EQ(a.relations, 1u);
    EXPECT_NEAR(a.pathLength, 1.0, 1e-12);
    EXPECT_NEAR(a.error, -0.1, 1e-12);
    EXPECT_NEAR(a.percent(), -10.0, 1e-9);
    // A relation turning while it moves: the error is measured along its own travel.
    const PoseRelations turning = {{0, 1, {0, 1, M_PI / 2}}};
    const Trajectory2D left = {{0, {0, 0, 0}}, {1, {0, 1.05, M_PI / 2}}};
    EXPECT_NEAR(alongTrackScale(turning, evaluateRelativePoseError(left, turning)).percent(), 5.0,
                1e-9);
    // Nothing moved enough: no figure.
    EXPECT_EQ(alongTrackScale(relations, RelativePoseErrorResult{}).percent(), 0.0);
}

TEST(AlongTrackScale, TheTableAndTheJsonCarryIt) {
    const Trajectory2D truth = figureOfEight();
    SlamEvaluation ev;
    ev.referenceFile = "truth";
    const PoseRelations relations = relationsFromGroundTruth(truth, {});
    ev.relationCount = relations.size();
    ev.methods.push_back(
        evaluateMethod("short", "", scaled(truth, 0.98), relations, nullptr, 1e-5));
    EXPECT_NEAR(ev.methods[0].alongTrack.percent(), -2.0, 1e-9);
    const std::string table = formatEvaluationTable(ev);
    EXPECT_NE(table.find("| short | "), std::string::npos) << table;
    EXPECT_NE(table.find(" | -2.000 % |"), std::string::npos) << table;
    const std::string json = formatEvaluationJson(ev);
    EXPECT_NE(json.find("\"along_track\""), std::string::npos) << json;
    EXPECT_NE(json.find("\"percent\""), std::string::npos) << json;
}
