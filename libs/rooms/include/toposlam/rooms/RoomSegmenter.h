#pragma once
// Room segmentation of an occupancy grid by virtual-door detection (Qi, Wang et al., "Indoor
// topological map building with virtual door detection", J. Jilin Univ. 2020): the pipeline of
// steps 1-6 and its options. Each step lives in the file named after it:
//   1 FreeSpaceBinarizer       binarise, keep the largest free region
//   2 HoughLineExtractor,      wall segments (probabilistic Hough) and their merge (eqs. 3-7)
//     LineMerger
//   3 MainDirectionVoter       the two main directions (eqs. 8-9)
//   4 DoorSearchPaths,         door search from the trajectory cells (or the medial axis when
//     VirtualDoorDetector      there is no trajectory) along the main directions (eq. 10)
//   5 DoorFilters              distance, adjacency, minimum-area (+ TopoSLAM's two tests;
//     RegionBoundary           regions mostly open to the unobserved outside merge too)
//     WideOpeningDetector      TopoSLAM: openings wider than a door framed by wall ends
//   6 RegionPartition          connected components after cutting the doors -> rooms
// The result is a TopologicalMap (rooms = nodes, doors = edges).
#include <toposlam/config/Options.h>
#include <toposlam/rooms/DoorFilters.h>
#include <toposlam/rooms/FreeSpaceBinarizer.h>
#include <toposlam/rooms/HoughLineExtractor.h>
#include <toposlam/rooms/LineMerger.h>
#include <toposlam/rooms/MainDirectionVoter.h>
#include <toposlam/rooms/TopologicalMap.h>
#include <toposlam/rooms/VirtualDoorDetector.h>
#include <toposlam/rooms/WideOpeningDetector.h>

#include <mrpt/math/TPose2D.h>

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace mrpt::config {
class CConfigFileBase;
}
namespace mrpt::maps {
class COccupancyGridMap2D;
}

namespace toposlam::rooms {

class RoomSegmenter {
  public:
    /// Section [RoomSegmenter] of config_ini/rooms.ini (keys, units and defaults there).
    struct Options : public config::Options {
        FreeSpaceBinarizer::Options freeSpace;
        HoughLineExtractor::Options hough;
        /// maxAngleDeg is the paper's delta_phi, shared by the merge (eq. 5) and the voter's
        /// bin width (2 delta_phi).
        LineMerger::Options lineMerge;
        VirtualDoorDetector::Options door;
        DoorFilters::Options filters;
        /// Openings wider than a door that are room borders (deviation, WideOpeningDetector.h).
        WideOpeningDetector::Options wide;
        /// Free-standing things inside the free space (furniture, pillars, shadows behind them:
        /// non-free islands that do not reach the map's edge) belong to the room around them:
        /// their cells take the room's id in the label image, and its area includes them
        /// (deviation: the paper labels free cells only).
        bool labelIslands = true;
        /// m^2; free pockets up to this size cut off from the map's free space (no 4-connected
        /// way in: free cells between the steps of a wall drawn at an angle, a gap behind a
        /// desk) join the one room they touch (8-neighbours); a pocket touching no room (inside
        /// a wall: cells a few rays went through on a SLAM grid) joins the nearest room up to
        /// half of filters.maxWallThickness away, whatever its size if it is a line at most
        /// three cells across on average; 0 = off (deviation: the paper labels the largest
        /// free region only).
        double maxSliverArea = 0.25;
        /// m; furniture against a room's walls (non-free pockets inside the room's box along
        /// the main directions, touching no other room, up to this long both ways) takes the
        /// room's id, as islands do (deviation, FurniturePockets.h); 0 = off. 2.5: a wardrobe
        /// of up to 2.4 m, a bed of 2.1 m.
        double maxFurnitureSize = 2.5;
        /// With a trajectory, search from the medial axis too (deviation: the paper searches
        /// the trajectory only, assuming the robot went through every door; a tour that visits
        /// every room need not, e.g. through the second door of a room).
        bool medialAxisWithTrajectory = true;

        /// The defaults: the paper plus TopoSLAM's documented deviations (DoorFilters.h).
        static Options improved() { return {}; }
        /// The paper's method as published: every deviation switched off.
        static Options paperExact();
        /// Switches off every deviation of paperExact() (speck removal, local directions,
        /// narrowest-of-group, smallest-first merging, wall-jamb, wall-end and constriction
        /// tests, wide openings, unknown as no wall, the open-boundary merge, islands,
        /// slivers, furniture pockets, medial axis with trajectory) and keeps every other
        /// value (door width, areas, ...): `--paper` on top of an ini file. The one place that
        /// knows what "paper" means.
        void applyPaperPreset();
        /// The options of the apps' `-c file.ini [--paper]`: the built-in defaults, then the
        /// [RoomSegmenter] section of `iniPath` when not empty (config::ConfigError naming the
        /// file when it is missing, no .ini file, lacks the section or has a bad key or value),
        /// then applyPaperPreset() when `paper`.
        static Options load(const std::string& iniPath, bool paper);

        /// "variant = paper" in a file first applies applyPaperPreset(); the keys then
        /// override it (config::Options: strict, every key checked).
        enum class Variant { Improved, Paper };
        Variant variant = Variant::Improved;

        void declare(config::OptionsSchema& s) override;
        void loadFromConfigFile(const mrpt::config::CConfigFileBase& ini,
                                const std::string& section) override;
        using config::Options::validate;
        /// Throws config::ConfigError naming the first value out of range ([RoomSegmenter]).
        void validate() const;
    };

    /// Everything the pipeline found on the way, for inspection, rendering and tests.
    struct Result {
        TopologicalMap map;
        std::vector<LineSegment> lines;  ///< merged wall segments (pixels)
        MainDirections directions;
        bool fromTrajectory = false;             ///< search paths: trajectory or medial axis
        std::vector<cv::Point> searchCells;      ///< pixels: trajectory cells, then medial axis
        std::size_t trajectoryCells = 0;         ///< of searchCells, from the trajectory
        std::vector<VirtualDoor> candidates;     ///< step 4 output (pixels)
        std::vector<VirtualDoor> afterTests;     ///< after wall-jamb + constriction tests
        std::vector<VirtualDoor> wideOpenings;   ///< WideOpeningDetector's (also in afterTests)
        std::vector<VirtualDoor> afterDistance;  ///< after the distance filter
        std::size_t afterAdjacency = 0;          ///< doors left by the adjacency filter
        /// What the binarisation cleaned up (FreeSpace): specks made free, and islands of
        /// unknown cells made free with their area (m^2).
        std::size_t specksRemoved = 0, unseenHolesFreed = 0;
        double unseenHoleArea = 0;
        double milliseconds = 0;  ///< wall time of segment()
        /// Wall time per pipeline stage, in order (ms).
        std::vector<std::pair<std::string, double>> stageMilliseconds;
    };

    RoomSegmenter();
    explicit RoomSegmenter(const Options& options);
    ~RoomSegmenter();
    /// Copies share nothing: each gets its own scratch images.
    RoomSegmenter(const RoomSegmenter& other);
    RoomSegmenter& operator=(const RoomSegmenter& other);

    /// Segments `grid`. `trajectory`: the robot's poses while mapping (m, rad, world frame of
    /// the grid); empty = none, the medial axis is searched instead. `sourceName` names the map
    /// in error messages. Throws toposlam::io::InputError for a map without free cells.
    Result segment(const mrpt::maps::COccupancyGridMap2D& grid,
                   const std::vector<mrpt::math::TPose2D>& trajectory = {},
                   const std::string& sourceName = "occupancy grid") const;
    /// Same, on an already binarised map.
    Result segment(const FreeSpace& space,
                   const std::vector<mrpt::math::TPose2D>& trajectory = {}) const;

    const Options& options() const { return options_; }

  private:
    using Lap = std::function<void(const char*)>;  // records the time of a stage
    /// Steps 2-5 on the cropped `space`, leaving the partition in the workspace: the rooms
    /// (diagnostics into `result`).
    DoorFilters::Rooms findRooms(const FreeSpace& space,
                                 const std::vector<mrpt::math::TPose2D>& trajectory, Result& result,
                                 const Lap& lap) const;

    Options options_;
    // The steps with their scratch images, reused from call to call (no reallocation while the
    // map size stays the same). A segmenter is therefore not thread-safe: one per thread.
    struct Workspace;
    std::unique_ptr<Workspace> workspace_;
};

}  // namespace toposlam::rooms
