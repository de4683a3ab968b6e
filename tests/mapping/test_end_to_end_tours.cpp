// The graph SLAM on simulated tours of generated buildings (libs/roomsbench, the end-to-end
// rooms benchmark's chain), against the simulator's exact trajectory.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <toposlam/io/Trajectory.h>
#include <toposlam/roomsbench/EndToEndRoomCases.h>

#include "TestSupport.h"

#include <regex>
#include <string>

using namespace toposlam;

namespace {

// config_ini/toposlam-slam.ini with the contested-loop rule on (loop_contested_support = 4),
// whose guards against look-alike places these tours exercise.
std::string slamIniWithContestedLoops() {
    const std::string text = test::readFile(test::configIni("toposlam-slam.ini"));
    return std::regex_replace(text, std::regex("\nloop_contested_support = [0-9]+"),
                              "\nloop_contested_support = 4");
}

// Tours `plan` (with stops that look into what the room-sized tour leaves unseen, as the
// benchmark does, or without; or along recorded `poses`) and maps the log with the
// configuration `iniText`.
void tour(const roomsbench::PlanToTour& plan, const std::string& iniText,
          roomsbench::EndToEndRun& run, bool lookIntoUnseen = true,
          const io::Trajectory2D& poses = {}) {
    const mrpt::config::CConfigFileMemory ini(iniText);
    const test::TempDir dir;
    roomsbench::EndToEndOptions options;
    options.simulator.tour.coverage.lookIntoUnseen = lookIntoUnseen;
    options.poses = poses;
    options.slamConfig = &ini;
    options.workDir = dir.path();
    roomsbench::endToEndCase(plan, options, run);
}

void tourWithContestedLoops(const roomsbench::PlanToTour& plan, roomsbench::EndToEndRun& run,
                            const io::Trajectory2D& poses = {}) {
    const std::string ini = slamIniWithContestedLoops();
    ASSERT_NE(ini.find("\nloop_contested_support = 4"), std::string::npos);
    tour(plan, ini, run, true, poses);
}

}  // namespace

TEST(EndToEndTours, NoLoopIntoAParallelLookAlikeCorridor) {
    // Generated building 13 (B4-gen seed 13) has a corridor that looks like one 2 m beside it.
    // On the way along it, matches into the other agreed with each other, beyond the gate, all
    // from one pass: accepted together they bent the map (trajectory error 0.32 m). Agreeing
    // matches beyond the gate must come from two visits of the old place; with that the tour
    // is mapped to 24 mm. The tour is the one the benchmark drove when this was found
    // (data/gen13_lookalike_corridor_tour.txt): today's tours pass the corridor otherwise.
    const auto plans = roomsbench::plansToTour({13}, {}, "");
    ASSERT_EQ(plans.size(), 1u);
    const io::Trajectory2D poses = io::loadTrajectory(
        test::sourceDir() + "/tests/mapping/data/gen13_lookalike_corridor_tour.txt");
    ASSERT_GT(poses.size(), 1000u);
    roomsbench::EndToEndRun run;
    ASSERT_NO_FATAL_FAILURE(tourWithContestedLoops(plans.front(), run, poses));
    ASSERT_GT(run.scans, 1000u);
    // 1 cm range noise and simulated odometry errors; a closed map stays within a few cm.
    EXPECT_LT(run.alignmentRmse, 0.1);
}

TEST(EndToEndTours, NoLoopGroupFromOnePassAlongLookAlikeOffices) {
    // Bormann's Freiburg79 (furnished): offices of one shape in a row along a corridor. Coming
    // back along it, groups of four to six matches agreed with each other beyond the gate, all
    // into one stretch of the earlier path: one pass, so none is accepted; accepted (no
    // two-visits rule), they bent the map to 37 mm. Since the front end's later changes no
    // such group forms on this tour (8-9 mm with or without the rule, measured 2026-11-28):
    // this guards the mapping of a row of look-alike offices; the rule itself is tested above.
    TOPOSLAM_SHARED_DATA_OR_SKIP(plan, "rooms/Freiburg79_scan_furnitures.png");
    const auto plans =
        roomsbench::plansToTour({}, {"Freiburg79_scan"}, test::sharedDataDir() + "/rooms");
    ASSERT_EQ(plans.size(), 1u);
    roomsbench::EndToEndRun run;
    ASSERT_NO_FATAL_FAILURE(tourWithContestedLoops(plans.front(), run));
    ASSERT_GT(run.scans, 500u);
    // Twice the error of the closed map (15 mm), below the bent one (37 mm).
    EXPECT_LT(run.alignmentRmse, 0.03);
}

TEST(EndToEndTours, ICPDoesNotSlideAlongACorridorWithoutEvidence) {
    // Generated building 20 (B4-gen seed 20), the tour of its room-sized areas: along its
    // corridors ICP moved the robot by 0.1-0.4 m along the heading on a few stray matches,
    // where the odometry's position fitted all but one or two readings as well (trajectory
    // error 48 mm). A correction along the heading must be borne out by the scan
    // (along_heading_check): 23 mm.
    const auto plans = roomsbench::plansToTour({20}, {}, "");
    ASSERT_EQ(plans.size(), 1u);
    const std::string ini = test::readFile(test::configIni("toposlam-slam.ini"));
    ASSERT_NE(ini.find("\nalong_heading_check = 0.1"), std::string::npos);
    roomsbench::EndToEndRun run;
    ASSERT_NO_FATAL_FAILURE(tour(plans.front(), ini, run, false));
    ASSERT_GT(run.scans, 1000u);
    // 1 cm range noise: a map whose corridors did not slide stays within 3.5 cm (the creep
    // below the check's 0.1 m per scan that is left costs a centimetre or two).
    EXPECT_LT(run.alignmentRmse, 0.035);
}
