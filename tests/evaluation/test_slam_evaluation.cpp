// evaluateMethod's breakdown by the reference motion's turn: a trajectory given 0.1 m ahead of
// the reference's frame is exact on straight relations and off by 2·d·sin(θ/2) on turns.
// worstRelations: the largest errors first, each with the method's own motion, and the other
// methods' errors on the same relation in the table.
// runSlamEvaluation: a log named by two options is read once.
#include <gtest/gtest.h>
#include <toposlam/evaluation/LogOdometry.h>
#include <toposlam/evaluation/SlamEvaluation.h>
#include <toposlam/evaluation/SlamEvaluationRun.h>

#include <mrpt/poses/CPose2D.h>

#include <algorithm>
#include <cmath>

#include "TestSupport.h"

namespace toposlam::evaluation {
namespace {

TEST(SlamEvaluation, ErrorsByTurnShowAFrameOffset) {
    // Reference: 1 m ahead, then two quarter turns on the spot.
    const io::Trajectory2D truth = {
        {1, {0, 0, 0}}, {2, {1, 0, 0}}, {3, {1, 0, M_PI / 2}}, {4, {1, 0, M_PI}}};
    io::Trajectory2D ahead;
    for (const io::TimedPose2D& p : truth) {
        const mrpt::poses::CPose2D moved =
            mrpt::poses::CPose2D(p.pose) + mrpt::poses::CPose2D(0.1, 0, 0);
        ahead.push_back({p.stamp, moved.asTPose()});
    }
    PoseRelations relations;
    for (const auto& [a, b] : {std::pair{0, 1}, {1, 2}, {2, 3}, {1, 3}}) {
        const mrpt::poses::CPose2D motion =
            mrpt::poses::CPose2D(truth[b].pose) - mrpt::poses::CPose2D(truth[a].pose);
        relations.push_back({truth[a].stamp, truth[b].stamp, motion.asTPose()});
    }
    const MethodEvaluation m = evaluateMethod("ahead", "", ahead, relations, nullptr, 1e-5);
    ASSERT_EQ(m.byTurn.size(), 4u);
    EXPECT_EQ(m.byTurn[0].minTurnDeg, 0);
    EXPECT_EQ(m.byTurn[3].maxTurnDeg, 180);
    // 0 deg: exact; 90 deg (two relations): 2 * 0.1 * sin(45 deg); 180 deg (last bin, closed):
    // 0.2 m. No relation turns by 45-90 deg.
    EXPECT_EQ(m.byTurn[0].totalRelations, 1u);
    EXPECT_NEAR(m.byTurn[0].translation.mean, 0, 1e-12);
    EXPECT_EQ(m.byTurn[1].totalRelations, 0u);
    EXPECT_EQ(m.byTurn[1].translation.count, 0u);
    EXPECT_EQ(m.byTurn[2].totalRelations, 2u);
    EXPECT_NEAR(m.byTurn[2].translation.mean, 0.2 * std::sin(M_PI / 4), 1e-12);
    EXPECT_EQ(m.byTurn[3].totalRelations, 1u);
    EXPECT_NEAR(m.byTurn[3].translation.mean, 0.2, 1e-12);

    // The table: one column per bin, "–" where no relation falls.
    SlamEvaluation ev;
    ev.methods.push_back(m);
    const std::string table = formatEvaluationTable(ev);
    EXPECT_NE(table.find("| method | 0–45° (1) | 45–90° (0) | 90–135° (2) | 135–180° (1) |"),
              std::string::npos)
        << table;
    EXPECT_NE(table.find("| ahead | 0.0000 ± 0.0000 | – | 0.1414 ± 0.0000 | 0.2000 ± 0.0000 |"),
              std::string::npos)
        << table;
}

TEST(SlamEvaluation, WorstRelationsComeFirstWithEachMethodsMotion) {
    // Truth: 1 m steps along x. "slipped" places pose 3 0.3 m to the left; "exact" is the truth.
    io::Trajectory2D truth, slipped;
    for (int i = 0; i < 5; ++i) {
        truth.push_back({double(i), {double(i), 0, 0}});
        slipped.push_back({double(i), {double(i), i == 3 ? 0.3 : 0.0, 0}});
    }
    PoseRelations relations;
    for (const auto& [a, b] : {std::pair{0, 1}, {2, 3}, {3, 4}, {0, 3}, {1, 4}}) {
        relations.push_back({truth[a].stamp,
                             truth[b].stamp,
                             {double(b - a), 0, 0}});  // straight ahead, b - a metres
    }
    SlamEvaluation ev;
    ev.methods.push_back(evaluateMethod("slipped", "", slipped, relations, nullptr, 1e-5));
    ev.methods.push_back(evaluateMethod("exact", "", truth, relations, nullptr, 1e-5));

    // Three relations end or start at pose 3, each 0.3 m off; ties keep relation order.
    const std::vector<WorstRelation> worst = worstRelations(ev.methods[0].relative, relations, 4);
    ASSERT_EQ(worst.size(), 4u);
    EXPECT_EQ(worst[0].relation, 1u);
    EXPECT_EQ(worst[1].relation, 2u);
    EXPECT_EQ(worst[2].relation, 3u);
    EXPECT_NEAR(worst[0].translation, 0.3, 1e-12);
    EXPECT_NEAR(worst[3].translation, 0, 1e-12);
    // The method's own motion from 2 to 3 and from 3 to 4, recovered as δ_gt ⊕ e.
    EXPECT_NEAR(worst[0].estimate.x, 1, 1e-12);
    EXPECT_NEAR(worst[0].estimate.y, 0.3, 1e-12);
    EXPECT_NEAR(worst[1].estimate.y, -0.3, 1e-12);
    EXPECT_NEAR(worst[2].reference.x, 3, 1e-12);
    EXPECT_EQ(worst[2].stamp1, 0);
    EXPECT_EQ(worst[2].stamp2, 3);
    // More asked for than matched: all of them.
    EXPECT_EQ(worstRelations(ev.methods[0].relative, relations, 99).size(), relations.size());

    // The table names the other method's error on each of them: here, none.
    ev.methods[0].worst = worstRelations(ev.methods[0].relative, relations, 1);
    const std::string table = formatEvaluationTable(ev);
    EXPECT_NE(table.find("Worst relations of slipped"), std::string::npos) << table;
    EXPECT_NE(table.find("| 2.000 | 1.00 | 1.000, 0.000 m, 0.0° | 1.000, 0.300 m, 0.0° | "
                         "0.300 / 0.00 | 0.000 m |"),
              std::string::npos)
        << table;
    EXPECT_EQ(table.find("Worst relations of exact"), std::string::npos) << table;
}

TEST(SlamEvaluationRun, ALogNamedTwiceIsReadOnce) {
    // The bundled office log as --odometry-of, --mounting-from and --laser-frame-of: the
    // progress counts its scans once, and every use gets what it needs from it.
    const std::string office = test::shareDir() + "/office/";
    SlamEvaluationRequest request;
    request.groundTruthFile = office + "office_gt.txt";
    request.trajectories.push_back(
        {TrajectorySource::LogOdometry, "odometry", office + "office.rawlog"});
    request.mountingLog = office + "office.rawlog";
    request.laserFrameLog = office + "office.rawlog";
    std::size_t scansRead = 0;
    double fraction = 0;
    const SlamEvaluationRun run = runSlamEvaluation(request, [&](double f, std::size_t scans) {
        scansRead = std::max(scansRead, scans);
        fraction = std::max(fraction, f);
    });
    const std::size_t scans = odometryAtScans(office + "office.rawlog", {}).size();
    ASSERT_GT(scans, 300u);
    EXPECT_EQ(scansRead, scans);
    EXPECT_DOUBLE_EQ(fraction, 1.0);
    ASSERT_EQ(run.evaluation.methods.size(), 1u);
    EXPECT_EQ(run.evaluation.methods[0].relative.matchedRelations, run.evaluation.relationCount);
    // The odometry against itself sits at the origin.
    ASSERT_TRUE(run.evaluation.methods[0].mounting.has_value());
    EXPECT_NEAR(run.evaluation.methods[0].mounting->mounting.x, 0.0, 1e-6);
    // The office's laser sits 0.2 m ahead of the robot's centre.
    EXPECT_EQ(run.evaluation.laserFrameLog, office + "office.rawlog");
    EXPECT_NEAR(run.evaluation.laserPosition.x, 0.2, 1e-9);
}

}  // namespace
}  // namespace toposlam::evaluation
