#pragma once
// Step 1 of the virtual-door method (Qi et al. 2020, sec. 1.3): binarise the occupancy grid
// with free cells as foreground and occupied + unknown cells as background, then keep only the
// largest 4-connected free region. Smaller free regions are cells the robot cannot reach
// (sensor noise, pose errors, spaces seen through windows): they are reported separately so
// that callers can decide what to do with them.
//
// Deviation (Options::maxSpeckArea, on by default): the paper removes free noise only.
// TopoSLAM also treats tiny isolated specks of non-free cells inside the free space (sensor
// noise, people, chair legs) as free: they say nothing about rooms, but a speck inside a
// doorway would stop the door search short of the jambs. The non-free cells are labelled
// into 8-connected obstacles on the way; the door filters use that to tell walls from
// free-standing things.
//
// Deviation (Options::occupiedThreshold, SLAM grids): the paper's background holds occupied
// and unknown cells alike, so the shadow behind a table, joined to the unknown outside by thin
// unseen rays, looks like a wall. FreeSpace::noWall marks the unknown cells away from every
// occupied one: the door tests find no wall there (holes where the laser grazed a wall, next
// to its occupied cells, stay wall). Drawn maps without unknown cells are not affected.
//
// Deviation (Options::freeUnseenHoles, SLAM grids): an island of unknown cells with no
// occupied cell, inside the free space, is floor the laser did not reach (the middle of a hall
// wider than twice its range): free. Nothing the laser hit bounds it, so it cannot part rooms,
// and left as background it narrows the floor around it into false constrictions. Shadows
// behind furniture touch the furniture's occupied cells and stay.
#include <toposlam/rooms/ConnectedRuns.h>
#include <toposlam/rooms/GridImageFrame.h>

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <opencv2/core/mat.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace toposlam::rooms {

/// The binarised map, in the image layout of GridImageFrame.
struct FreeSpace {
    GridImageFrame frame;
    /// CV_8U, 255 = free cell of the largest 4-connected free region, 0 = everything else.
    cv::Mat free;
    /// CV_8U, 255 = free cell of any other (smaller) free region.
    cv::Mat otherFree;
    /// The cells of otherFree: runs along image rows, in raster order, each with the number of
    /// its free region.
    std::vector<ConnectedRuns::Run> otherFreeRuns;
    /// Bounding box of the cells of `free`.
    cv::Rect bounds;
    /// Number of cells of `free`.
    std::size_t freeCells = 0;
    /// CV_32S: the 8-connected obstacles (non-free cells, specks removed) numbered 1..n; 0 on
    /// free cells (of any region).
    cv::Mat obstacles;
    /// Per obstacle number: 1 when it reaches the border of the map (the outer walls and all
    /// that is joined to them); [0] unused.
    std::vector<std::uint8_t> obstacleOnBorder;
    /// The cells of the islands, the obstacles that do not reach the border (furniture, pillars):
    /// runs along image rows, in raster order, each with its obstacle number.
    std::vector<ConnectedRuns::Run> islandRuns;
    /// Specks made free (see maxSpeckArea).
    std::size_t specksRemoved = 0;
    /// Islands of unknown cells made free (see freeUnseenHoles), and their cells.
    std::size_t unseenHolesFreed = 0, unseenHoleCells = 0;
    /// CV_8U, 255 = where no wall can be: the cells of `free` and the unknown cells (p(free)
    /// from occupiedThreshold to freeThreshold) farther than wallHoleReach from every occupied
    /// cell (shadows behind furniture, unexplored space). Empty when the map has no such
    /// unknown cell: then `free` is where no wall can be.
    cv::Mat noWall;
    /// CV_8U, 255 = unknown cell (p(free) from occupiedThreshold to freeThreshold): never or
    /// hardly ever seen. The non-free cells that are not unknown are occupied. Empty when the
    /// map has no unknown cell (drawn maps: every non-free cell is occupied).
    cv::Mat unknown;
    /// m: the wallHoleReach `noWall` was made with (unknown cells this close to an occupied
    /// cell are part of its wall); 0 when the map has no unknown cell.
    double wallHoleReach = 0;
};

class FreeSpaceBinarizer {
  public:
    struct Options {
        /// A cell is free when its p(free) exceeds this (MRPT convention: 0 = occupied,
        /// 0.5 = unknown, 1 = free). 0.8 is ROS map_server's free threshold (occupancy below
        /// 0.196): cells seen free often enough. Lower values let the weakly observed cells of
        /// SLAM grids (seen free once or twice, through gaps in walls) join rooms to their
        /// neighbours; maps drawn with grey < 250 = not free (Bormann et al.) need 0.98.
        double freeThreshold = 0.8;
        /// Isolated non-free specks of at most this area (m^2) inside the free space count as
        /// free; 0 keeps every speck (the paper). 0.01 m^2 is four 5 cm cells.
        double maxSpeckArea = 0.01;
        /// Islands of unknown cells (p(free) from occupiedThreshold to freeThreshold) with no
        /// occupied cell, inside the free space, count as free: floor the laser did not reach.
        /// Off: they are background (the paper).
        bool freeUnseenHoles = true;
        /// A non-free cell is occupied (the laser hit something there) when its p(free) is
        /// below this, else unknown (never or hardly ever seen: MRPT's 0.5). At or above
        /// freeThreshold every non-free cell counts as occupied (the paper, FreeSpace::noWall
        /// empty).
        double occupiedThreshold = 0.45;
        /// m: unknown cells within this of an occupied cell are part of its wall (holes where
        /// the laser grazed the wall); farther ones are no wall (FreeSpace::noWall).
        double wallHoleReach = 0.15;
    };

    FreeSpaceBinarizer() = default;
    explicit FreeSpaceBinarizer(const Options& options) : options_(options) {}

    /// Throws toposlam::io::InputError(sourceName, ...) when the grid has no free cell at all
    /// (empty, unknown-only or fully occupied map).
    FreeSpace binarize(const mrpt::maps::COccupancyGridMap2D& grid,
                       const std::string& sourceName = "occupancy grid") const;
    /// Same, into `out`, whose images are reused when their size fits (no reallocation when the
    /// same binarizer and `out` are used again on a map of the same size).
    void binarize(const mrpt::maps::COccupancyGridMap2D& grid, FreeSpace& out,
                  const std::string& sourceName = "occupancy grid") const;

    /// Same, from an 8-bit image already in the layout of GridImageFrame where non-zero means
    /// free (frame.cols/rows are taken from the image).
    FreeSpace binarize(const cv::Mat& freeImage, GridImageFrame frame,
                       const std::string& sourceName = "free-space image") const;

    const Options& options() const { return options_; }

  private:
    void labelFreeSpace(cv::Mat& all, const std::string& sourceName, FreeSpace& out) const;
    void removeSpecksAndLabelObstacles(cv::Mat& all, const cv::Rect& freeBox, FreeSpace& out) const;
    void keepLargestComponent(const cv::Mat& all, const cv::Rect& box,
                              const std::string& sourceName, FreeSpace& out) const;
    void markNoWall(const cv::Mat& all, FreeSpace& out) const;

    Options options_;
    // Scratch, reused across calls (one binarizer per thread).
    mutable cv::Mat all_, nearOccupied_;
    mutable ConnectedRuns runs_;
};

}  // namespace toposlam::rooms
