#pragma once
// Real scan pairs for B2: the ground-truth relations of the Kuemmerle et al. 2009 benchmark
// (".relations", libs/evaluation RelationFile) with the two scans from the log (any format
// libs/io's LaserLogReader reads). A relation's stamps are matched to the scans' fileStamps
// within 1e-5 s; the truth is the relation (robot frames), the odometry guess the log's
// odometry difference odo(t1)^-1 + odo(t2). Throws io::InputError when a stamp has no scan.
#include <toposlam/matchingbench/ScanPair.h>

#include <string>

namespace toposlam::matchingbench {

/// `maxPairs` > 0 keeps that many relations, evenly spaced over the file (quick runs).
ScanPairs loadRelationPairs(const std::string& logPath, const std::string& relationsPath,
                            const std::string& setName, std::size_t maxPairs = 0);

}  // namespace toposlam::matchingbench
