#pragma once
// Benchmark B4 (shared/BENCHMARKS.md): room segmentation scored against ground-truth rooms and
// doors, by the virtual-door segmenter (TopoSLAM's default and the paper-exact variant) and by
// the morphological and distance baselines, all in one run. The maps come as
// RoomBenchmarkCase: Bormann et al.'s 20 maps, unfurnished and furnished (a furnished map is
// scored against its unfurnished ground truth), at any rotation (bormannCases), or any other
// set with ground truth (generated plans, grids built by SLAM: libs/roomsbench).
#include <toposlam/io/ProgressCallback.h>
#include <toposlam/rooms/RoomBenchmarkCase.h>
#include <toposlam/rooms/RoomSegmenter.h>
#include <toposlam/rooms/SegmentationMetrics.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace toposlam::rooms {

struct RoomBenchmarkOptions {
    std::string dataDir;   ///< the folder with Bormann's maps (shared/data/rooms)
    int repeats = 3;       ///< runs per map and method; the median time is reported
    std::string imageDir;  ///< when not empty, a PNG of every segmentation is written there
    /// Methods to run, of "vdoor", "vdoor-paper", "morph", "dist" (empty: all four).
    std::vector<std::string> methods;
    /// Maps to run, base names of benchmarkMaps() (empty: all 20).
    std::vector<std::string> maps;
    /// Angles (deg, counter-clockwise) each map is turned by (nearest neighbour); {0}: as drawn.
    std::vector<double> rotationsDeg = {0};
    /// m; > 0: every drawn map (Bormann's, B4-gen) is segmented in cells of this size (a whole
    /// multiple of its own), pooled as a laser grid would mark them (pooledCase), and scored in
    /// its drawn ground truth. 0: as drawn.
    double cellSize = 0;
    RoomSegmenter::Options virtualDoor = RoomSegmenter::Options::improved();
    RoomSegmenter::Options virtualDoorPaper = RoomSegmenter::Options::paperExact();
};

/// One method on one map.
struct RoomBenchmarkScore {
    std::string dataset;  ///< RoomBenchmarkCase::dataset
    std::string map;      ///< e.g. "office_a_furnitures"
    bool furnished = false;
    double rotationDeg = 0;
    std::string method;
    PrecisionRecall pr;
    /// Over the open floor of the rooms (RoomBenchmarkCase::openFloor; segment pixels on the
    /// rooms' other pixels left out): only for cases that have it.
    std::optional<PrecisionRecall> openFloor;
    int segments = 0;          ///< labels returned (65280 excluded, tiny included)
    int groundTruthRooms = 0;  ///< GT rooms > 100 px
    DoorMatchCounts doors;     ///< at 0.5 m (10 px)
    DoorMatchCounts doors1m;   ///< at 1.0 m (20 px)
    double seconds = 0;        ///< median wall time over the repeats
    double minSeconds = 0;     ///< fastest repeat
    double cpuSeconds = 0;     ///< median CPU time of the calling thread over the repeats
};

/// Aggregate of one method over a group of maps.
struct RoomBenchmarkSummary {
    std::string dataset, method, group;  ///< group: "unfurnished", "furnished", "all"
    std::optional<double> rotationDeg;   ///< nullopt: every angle of the run pooled
    int maps = 0;
    double recallMean = 0, recallSd = 0, precisionMean = 0, precisionSd = 0;
    double recallPixels = 0, precisionPixels = 0;  ///< means over maps
    double secondsMean = 0, secondsMax = 0, minSecondsMean = 0, cpuSecondsMean = 0;
    int segments = 0, groundTruthRooms = 0;
    DoorMatchCounts doors, doors1m;  ///< pooled counts
    double doorPrecisionMeanOfMaps = 0, doorRecallMeanOfMaps = 0;
};

class RoomBenchmark {
  public:
    /// The 20 base names the package's evaluation clients load.
    static const std::vector<std::string>& benchmarkMaps();
    /// All four method names, in table order.
    static const std::vector<std::string>& methodNames();

    /// Throws std::invalid_argument for an unknown method or map name.
    explicit RoomBenchmark(RoomBenchmarkOptions options);
    const RoomBenchmarkOptions& options() const { return options_; }

    /// Every selected method on every selected Bormann map (unfurnished and furnished) at every
    /// angle. Throws toposlam::io::InputError for a missing or unreadable map file.
    std::vector<RoomBenchmarkScore> run(const io::ProgressCallback& progress = {}) const;

    /// Every selected method on `count` cases made one at a time by `makeCase(i)` (so that only
    /// one is in memory). Single-threaded; `progress` after each case.
    std::vector<RoomBenchmarkScore> runCases(
        std::size_t count,
        const std::function<std::vector<RoomBenchmarkCase>(std::size_t)>& makeCases,
        const io::ProgressCallback& progress = {}) const;

    /// `cases` (drawn maps) at options().cellSize (caseAtCellSize: pooled when coarser, split
    /// when finer); as they are when it is 0.
    std::vector<RoomBenchmarkCase> atCellSize(std::vector<RoomBenchmarkCase> cases) const;

    /// Every selected method on one case (the images of options().imageDir included).
    std::vector<RoomBenchmarkScore> score(const RoomBenchmarkCase& c) const;

    /// Per dataset, method, group and angle (and, with more than one angle, all angles
    /// pooled).
    static std::vector<RoomBenchmarkSummary> summarize(
        const std::vector<RoomBenchmarkScore>& scores);
    /// Per-map table then the summary table (Markdown).
    static std::string table(const std::vector<RoomBenchmarkScore>& scores,
                             const std::vector<RoomBenchmarkSummary>& summary);
    /// The summary only, one row per method and group (and angle) (Markdown).
    static std::string summaryTable(const std::vector<RoomBenchmarkSummary>& summary);
    static std::string json(const std::vector<RoomBenchmarkScore>& scores,
                            const std::vector<RoomBenchmarkSummary>& summary,
                            const RoomBenchmarkOptions& options);

    /// The label image B4 scores for a topological map: room ids, kUnassignedLabel on the free
    /// cells of `freeImage` (CV_8U, non-zero = free) that belong to no room, 0 elsewhere.
    static cv::Mat scoredLabels(const TopologicalMap& map, const cv::Mat& freeImage);

  private:
    RoomBenchmarkOptions options_;
    // One segmenter per variant for the whole run: it keeps its scratch images between calls,
    // as an application that segments its maps again and again would.
    RoomSegmenter virtualDoor_, virtualDoorPaper_;
};

}  // namespace toposlam::rooms
