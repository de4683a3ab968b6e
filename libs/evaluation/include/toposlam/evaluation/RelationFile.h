#pragma once
// Ground-truth relations in the format of the Kümmerle et al. 2009 SLAM benchmark
// (".relations" files): one relation per line,
//     t1 t2 x y z roll pitch yaw
// = the motion of the robot from its pose at time t1 to its pose at time t2, expressed in the
// frame of the pose at t1 (t in seconds, x y z in metres, angles in radians). Lines are in no
// particular order and t1 > t2 is allowed (it still means "from the t1 pose to the t2 pose").
// Fields may be separated by any amount of blank space. TopoSLAM is 2D: z, roll and pitch must
// be 0.
#include <mrpt/math/TPose2D.h>

#include <cstddef>
#include <string>
#include <vector>

namespace toposlam::evaluation {

struct PoseRelation {
    double stamp1 = 0;           ///< s, stamp of the pose the motion starts from
    double stamp2 = 0;           ///< s, stamp of the pose the motion ends at
    mrpt::math::TPose2D motion;  ///< pose at stamp2 in the frame of the pose at stamp1 (m, rad)
};
using PoseRelations = std::vector<PoseRelation>;

/// Reads a .relations file, keeping the file's order. Blank lines and lines starting with '#'
/// are skipped. Throws io::InputError naming the file (and the line) when it is missing or
/// unreadable, has no relation, or a line does not have exactly 8 finite numbers, or has a
/// nonzero z, roll or pitch.
PoseRelations loadRelations(const std::string& path);

/// How many relations repeat an earlier one exactly (same stamps, same motion). Published files
/// have a few (fr079.relations 4, mit-csail.relations 1); they are scored as published, so each
/// counts twice in a mean, for every method alike. The evaluators report the count.
std::size_t countRepeatedRelations(const PoseRelations& relations);

/// The relations of the log's mirror image (io::MirrorImage.h, toposlam-convert --mirror):
/// each motion (x, y, yaw) becomes (x, -y, -yaw), the stamps stay.
PoseRelations mirroredRelations(const PoseRelations& relations);

/// Writes relations in the same format (stamps with microseconds, like the benchmark files,
/// motion with 9 decimals). Atomic: no partial file is left on failure.
void saveRelations(const PoseRelations& relations, const std::string& path);

}  // namespace toposlam::evaluation
