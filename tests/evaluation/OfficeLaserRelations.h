#pragma once
// Relations of the bundled office made in its laser's frame, as Kümmerle et al.'s are: the
// office's laser sits 0.2 m ahead of the robot's centre (config_ini/sim-office.ini), and its
// ground truth gives the robot's poses; moved to the laser with MRPT's pose algebra, they give
// the relations a hand-matched reference would.
#include <mrpt/poses/CPose2D.h>
#include <toposlam/evaluation/GroundTruthRelations.h>
#include <toposlam/evaluation/RelationFile.h>
#include <toposlam/io/Trajectory.h>

#include <TestSupport.h>

#include <string>

namespace toposlam::evaluation::test_paths {

/// Where the office's laser sits on the robot, m ahead of its centre.
inline constexpr double kOfficeLaserAhead = 0.2;

/// Writes the office's laser-frame relations to `path`.
inline void writeOfficeLaserRelations(const std::string& path) {
    io::Trajectory2D laser;
    for (const auto& p : io::loadTrajectory(test::shareDir() + "/office/office_gt.txt")) {
        laser.push_back(
            {p.stamp, (mrpt::poses::CPose2D(p.pose) + mrpt::poses::CPose2D(kOfficeLaserAhead, 0, 0))
                          .asTPose()});
    }
    saveRelations(relationsFromGroundTruth(laser, {}), path);
}

}  // namespace toposlam::evaluation::test_paths
