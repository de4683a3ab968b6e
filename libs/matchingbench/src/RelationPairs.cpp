#include <toposlam/evaluation/RelationFile.h>
#include <toposlam/io/InputError.h>
#include <toposlam/io/LaserLogReader.h>
#include <toposlam/matchingbench/RelationPairs.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>

namespace toposlam::matchingbench {

ScanPairs loadRelationPairs(const std::string& logPath, const std::string& relationsPath,
                            const std::string& setName, std::size_t maxPairs) {
    evaluation::PoseRelations relations = evaluation::loadRelations(relationsPath);
    if (maxPairs > 0 && relations.size() > maxPairs) {
        evaluation::PoseRelations subset;
        for (std::size_t k = 0; k < maxPairs; ++k)
            subset.push_back(relations[k * relations.size() / maxPairs]);
        relations.swap(subset);
    }
    // The stamps needed, sorted; scans are kept only for them.
    std::vector<double> stamps;
    for (const auto& r : relations)
        stamps.push_back(r.stamp1), stamps.push_back(r.stamp2);
    std::sort(stamps.begin(), stamps.end());
    stamps.erase(std::unique(stamps.begin(), stamps.end()), stamps.end());
    constexpr double kTolerance = 1e-5;  // s: relation stamps have 5-6 decimals
    const auto nearest = [&](double t) -> long {
        const auto it = std::lower_bound(stamps.begin(), stamps.end(), t - kTolerance);
        return it != stamps.end() && std::abs(*it - t) <= kTolerance ? long(it - stamps.begin())
                                                                     : -1;
    };

    struct Kept {
        mrpt::obs::CObservation2DRangeScan::Ptr scan;
        mrpt::poses::CPose2D odometry;
    };
    std::vector<Kept> byStamp(stamps.size());
    io::LaserLogReader reader(logPath);
    io::LaserLogRecord record;
    while (reader.next(record)) {
        const long k = nearest(record.fileStamp);
        if (k >= 0 && !byStamp[std::size_t(k)].scan)
            byStamp[std::size_t(k)] = {record.scan, record.odometry};
    }

    ScanPairs pairs;
    for (const auto& r : relations) {
        const long a = nearest(r.stamp1), b = nearest(r.stamp2);
        for (const auto& [index, stamp] : {std::pair{a, r.stamp1}, std::pair{b, r.stamp2}}) {
            if (index < 0 || !byStamp[std::size_t(index)].scan) {
                std::ostringstream msg;
                msg << std::fixed << std::setprecision(6) << "relation stamp " << stamp
                    << " matches no scan of " << logPath << " (tolerance 1e-5 s)";
                throw io::InputError(relationsPath, msg.str());
            }
        }
        ScanPair pair;
        pair.set = setName;
        pair.reference = byStamp[std::size_t(a)].scan;
        pair.current = byStamp[std::size_t(b)].scan;
        pair.truth = mrpt::poses::CPose2D(r.motion);
        pair.odometry = byStamp[std::size_t(b)].odometry - byStamp[std::size_t(a)].odometry;
        pair.offset = std::hypot(pair.truth.x(), pair.truth.y());
        pair.rotation = std::abs(pair.truth.phi());
        pairs.push_back(std::move(pair));
    }
    return pairs;
}

}  // namespace toposlam::matchingbench
