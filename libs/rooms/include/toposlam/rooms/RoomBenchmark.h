#pragma once
// Benchmark B4 (shared/BENCHMARKS.md): room segmentation of the 20 maps of Bormann et al.'s
// evaluation, unfurnished and furnished (a furnished map is scored against its unfurnished
// ground truth), by the virtual-door segmenter (TopoSLAM's default and the paper-exact
// variant) and by the morphological and distance baselines, all in one run.
#include <toposlam/rooms/RoomSegmenter.h>
#include <toposlam/rooms/SegmentationMetrics.h>

#include <functional>
#include <string>
#include <vector>

namespace toposlam::rooms {

struct RoomBenchmarkOptions {
    std::string dataDir;   ///< the folder with the maps (shared/data/rooms)
    int repeats = 3;       ///< runs per map and method; the median time is reported
    std::string imageDir;  ///< when not empty, a PNG of every segmentation is written there
    /// Methods to run, of "vdoor", "vdoor-paper", "morph", "dist" (empty: all four).
    std::vector<std::string> methods;
    /// Maps to run, base names of benchmarkMaps() (empty: all 20).
    std::vector<std::string> maps;
    RoomSegmenter::Options virtualDoor = RoomSegmenter::Options::improved();
    RoomSegmenter::Options virtualDoorPaper = RoomSegmenter::Options::paperExact();
};

/// One method on one map.
struct RoomBenchmarkScore {
    std::string map;  ///< e.g. "office_a_furnitures"
    bool furnished = false;
    std::string method;
    PrecisionRecall pr;
    int segments = 0;          ///< labels returned (65280 excluded, tiny included)
    int groundTruthRooms = 0;  ///< GT rooms > 100 px
    DoorMatchCounts doors;     ///< at 0.5 m (10 px)
    DoorMatchCounts doors1m;   ///< at 1.0 m (20 px)
    double seconds = 0;        ///< median wall time over the repeats
    double minSeconds = 0;     ///< fastest repeat
};

/// Aggregate of one method over a group of maps.
struct RoomBenchmarkSummary {
    std::string method, group;  ///< group: "unfurnished", "furnished", "all"
    int maps = 0;
    double recallMean = 0, recallSd = 0, precisionMean = 0, precisionSd = 0;
    double recallPixels = 0, precisionPixels = 0;  ///< means over maps
    double secondsMean = 0, secondsMax = 0, minSecondsMean = 0;
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

    explicit RoomBenchmark(RoomBenchmarkOptions options);

    /// Runs every selected method on every selected map (unfurnished and furnished).
    /// `progress(done, total, what)` is called before each map. Throws toposlam::io::InputError
    /// for a missing or unreadable map file.
    std::vector<RoomBenchmarkScore> run(
        const std::function<void(std::size_t, std::size_t, const std::string&)>& progress = {})
        const;

    static std::vector<RoomBenchmarkSummary> summarize(
        const std::vector<RoomBenchmarkScore>& scores);
    /// Per-map table then the summary table (Markdown).
    static std::string table(const std::vector<RoomBenchmarkScore>& scores,
                             const std::vector<RoomBenchmarkSummary>& summary);
    static std::string json(const std::vector<RoomBenchmarkScore>& scores,
                            const std::vector<RoomBenchmarkSummary>& summary,
                            const RoomBenchmarkOptions& options);

    /// The label image B4 scores for a topological map: room ids, kUnassignedLabel on the free
    /// cells of `freeImage` (CV_8U, non-zero = free) that belong to no room, 0 elsewhere.
    static cv::Mat scoredLabels(const TopologicalMap& map, const cv::Mat& freeImage);

  private:
    RoomBenchmarkOptions options_;
};

}  // namespace toposlam::rooms
