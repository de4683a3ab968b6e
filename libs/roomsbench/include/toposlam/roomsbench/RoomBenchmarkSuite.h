#pragma once
// Everything toposlam-bench-rooms runs, as a library: B4 on Bormann's maps at any angle,
// B4-gen and B4-flats on generated furnished offices and flats at any angle, and rooms on grids
// built by our SLAM end to end, every method in one run; the report as Markdown and JSON.
#include <toposlam/io/ProgressCallback.h>
#include <toposlam/rooms/RoomBenchmark.h>
#include <toposlam/roomsbench/EndToEndRoomCases.h>

#include <string>
#include <vector>

namespace toposlam::roomsbench {

struct RoomBenchmarkSuiteOptions {
    /// Methods, repeats, pictures, angles, Bormann's folder and maps, segmenter options.
    rooms::RoomBenchmarkOptions bench;
    bool bormann = true;                   ///< B4 on Bormann's maps
    std::vector<unsigned> generatedSeeds;  ///< B4-gen plans (empty: none)
    std::vector<unsigned> flatSeeds;       ///< B4-flats plans (empty: none)
    std::vector<unsigned> ringSeeds;       ///< B4-rings plans (empty: none)
    /// End to end (empty lists: none): generated plans and Bormann maps toured, mapped by SLAM,
    /// segmented, scored; and the same plans as drawn (dataset "drawn") for comparison.
    std::vector<unsigned> endToEndSeeds;
    std::vector<std::string> endToEndBormannMaps;
    std::vector<unsigned> endToEndRingSeeds;  ///< generated ring plans
    EndToEndOptions endToEnd;
};

/// One end-to-end plan: what the tour and SLAM did.
struct EndToEndRecord {
    std::string map;
    EndToEndRun run;
};

struct RoomBenchmarkSuiteResult {
    std::vector<rooms::RoomBenchmarkScore> scores;
    std::vector<rooms::RoomBenchmarkSummary> summary;
    std::vector<EndToEndRecord> endToEnd;
};

/// Runs the selected sets in the order Bormann, B4-gen, B4-flats, B4-rings, end to end. Throws
/// io::InputError for a missing map, std::invalid_argument for bad options.
RoomBenchmarkSuiteResult runRoomBenchmarkSuite(const RoomBenchmarkSuiteOptions& options,
                                               const io::ProgressCallback& progress = {});

/// The per-map table, the summary, and (when run) the end-to-end runs (Markdown).
std::string suiteTable(const RoomBenchmarkSuiteResult& result);
/// rooms::RoomBenchmark::json plus "generated_seeds" and "end_to_end" (per plan: scans, tour
/// length, SLAM time, alignment).
std::string suiteJson(const RoomBenchmarkSuiteResult& result,
                      const RoomBenchmarkSuiteOptions& options);

}  // namespace toposlam::roomsbench
