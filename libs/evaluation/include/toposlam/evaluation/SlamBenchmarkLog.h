#pragma once
// The logs of benchmark B3 and what each is scored against: the public logs of Kümmerle et
// al. 2009 with their relation files (../shared/data/slam), and simulated logs with their
// ground-truth trajectory (share/office).
#include <string>
#include <vector>

namespace toposlam::evaluation {

struct SlamBenchmarkLog {
    std::string name;     ///< table label, e.g. "intel", "office"
    std::string logFile;  ///< CARMEN log or MRPT rawlog
    /// Exactly one of the two references is set:
    std::string relationsFile;    ///< ground-truth relations (RelationFile.h)
    std::string groundTruthFile;  ///< true trajectory 'timestamp x y yaw' (Trajectory.h)
    /// Logs of one group are summarised together: a simulated log's robot (SimulatedSlamLogs.h);
    /// "" = none (the public logs, the office).
    std::string group;
};

/// Every log in `directory` that has a relation file beside it: `<name>.relations` with a log
/// `<name>.clf`, `.log`, `.rawlog` or one of those + `.gz` (the first found, in that order).
/// Sorted by name; empty when the directory is absent or holds none.
std::vector<SlamBenchmarkLog> findRelationLogs(const std::string& directory);

}  // namespace toposlam::evaluation
