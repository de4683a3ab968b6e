#pragma once
// One map of a room-segmentation benchmark with its ground truth, as every method sees it:
// the grid to segment (and the robot's trajectory, when there is one) and, in the frame the
// ground truth is drawn in, the free space that was mapped, the rooms and the true doors.
// For drawn maps the two frames are the same; a map built by SLAM is scored after its labels
// have been carried into the plan's frame (toTruthFrame).
#include <toposlam/rooms/SegmentationMetrics.h>

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPose2D.h>

#include <opencv2/core/mat.hpp>

#include <functional>
#include <string>
#include <vector>

namespace toposlam::rooms {

struct RoomBenchmarkCase {
    std::string dataset;  ///< "bormann", "gen", "slam"
    std::string map;      ///< e.g. "office_a_furnitures"
    bool furnished = false;
    double rotationDeg = 0;  ///< how far the map was turned (counter-clockwise)
    /// What every method segments; the baselines segment its free cells (p(free) > 0.5 after
    /// RoomSegmenter's free threshold, see inputFree).
    mrpt::maps::COccupancyGridMap2D grid;
    cv::Mat inputFree;  ///< CV_8U, 255 = free cell of `grid`, map-image layout (GridImageFrame)
    /// The robot's poses while mapping (m, rad, world frame of `grid`); empty: none.
    std::vector<mrpt::math::TPose2D> trajectory;

    /// Scoring, in the ground truth's image: the free space of the segmented map there (`Min`
    /// of the door metric), the rooms and the true doors.
    cv::Mat scoredFree;
    GroundTruthRooms truth;
    std::vector<LabelBoundaryDoor> trueDoors;
    /// When not empty, also scored over the rooms' open floor only (openFloorOfRooms; the
    /// end-to-end cases: what a SLAM grid loses beyond the one-cell quantisation of its walls).
    GroundTruthRooms openFloor;
    /// Carries a label image of `grid` (CV_32S, map-image layout) into the ground truth's
    /// image (nearest cell). Empty: the two are the same image.
    std::function<cv::Mat(const cv::Mat&)> toTruthFrame;
    /// Metres per pixel of the ground truth's image (what door distances are measured in);
    /// 0: the grid's resolution.
    double truthResolution = 0;

    /// "office_a_furnitures" or "office_a_furnitures@17" when turned.
    std::string name() const;
};

/// `image` turned by `degrees` (counter-clockwise as displayed) about its centre, by nearest
/// neighbour (as a scanned plan or a SLAM grid would draw the same building at that angle);
/// the image grows to hold all of it and new pixels are `fill`. CV_8U or CV_32S. 0 degrees
/// returns a copy.
cv::Mat rotateNearest(const cv::Mat& image, double degrees, double fill);
/// The 2x3 affine map (pixel coordinates, pixel centres integer) rotateNearest() applies to an
/// image of `size`, and the size of its result.
cv::Mat rotationOfImage(const cv::Size& size, double degrees, cv::Size& rotatedSize);

/// A grid (origin (0, 0) at the lower-left corner, `resolution` m per cell) whose cells are
/// free (p = 1) where `free` (CV_8U, map-image layout) is non-zero and occupied (p = 0)
/// elsewhere: what a drawn map hands over.
mrpt::maps::COccupancyGridMap2D gridOfFreeImage(const cv::Mat& free, double resolution);

/// Metres per pixel of Bormann's maps and of the drawn B4-gen plans (SOURCES.md).
constexpr double kBenchmarkMapResolution = 0.05;

/// How many cells of `resolution` (m) span one of `cellSize` (m): a whole number from 1 to 100.
/// Throws std::invalid_argument, naming both sizes, for any other cell size.
int poolingFactor(double cellSize, double resolution);

/// `free` (CV_8U, map-image layout, non-zero = free) in cells of `factor` x `factor` pixels
/// aligned to its lower-left corner (a grid's origin): a cell is free (255) when every pixel in
/// it is free, and not free (0) when any is not or it reaches past the image, as a laser grid
/// marks a cell a beam ended in.
cv::Mat poolFreeImage(const cv::Mat& free, int factor);

/// A drawn case (gridOfFreeImage: no trajectory, origin (0, 0), the ground truth's frame)
/// mapped at a coarser cell size: its grid pooled (poolFreeImage) to `cellSize`, a whole
/// multiple of its resolution, with the same origin; the segmentation is scored in the drawn
/// ground truth, each cell's label carried to its pixels and on into the pixels along the
/// walls that only the drawn plan has free (the nearest label within a cell's reach).
/// cellSize equal to the resolution returns the case as it is. Throws std::invalid_argument
/// for a cell size poolingFactor() refuses, or for a case that is not drawn.
RoomBenchmarkCase pooledCase(const RoomBenchmarkCase& drawn, double cellSize);

/// How many cells of `cellSize` (m) split one of `resolution` (m) along each axis: a whole
/// number from 2 to 8. Throws std::invalid_argument, naming both sizes, for any other size.
int splittingFactor(double cellSize, double resolution);

/// A drawn case mapped at a finer cell size, `cellSize` = resolution / k (splittingFactor):
/// each pixel split into k x k cells of its own state, as a finer grid shows the same walls;
/// the segmentation is scored in the drawn ground truth, each pixel taking the label most of
/// its cells have. Throws std::invalid_argument for another cell size, or for a case that is
/// not drawn.
RoomBenchmarkCase splitCase(const RoomBenchmarkCase& drawn, double cellSize);

/// The drawn case at `cellSize`: pooledCase when it is coarser than the drawn pixels,
/// splitCase when it is finer. Throws std::invalid_argument when it is neither a whole
/// multiple nor a whole fraction of them.
RoomBenchmarkCase caseAtCellSize(const RoomBenchmarkCase& drawn, double cellSize);

/// Throws std::invalid_argument unless `cellSize` is a whole multiple of `resolution` (1 to
/// 100 times) or a whole fraction of it (1/2 to 1/8).
void checkCellSize(double cellSize, double resolution);

/// Bormann's map `base` in `dataDir` (<base>.png, <base>_furnitures.png,
/// <base>_gt_segmentation.png; grey >= 250 free), unfurnished then furnished, at each of
/// `rotationsDeg`: the maps, their ground-truth rooms and the free space of the unfurnished map
/// turned together. Throws io::InputError for a missing or unreadable image.
std::vector<RoomBenchmarkCase> bormannCases(const std::string& dataDir, const std::string& base,
                                            const std::vector<double>& rotationsDeg);

/// A case of a drawn map (grid = the free image, same frame as the truth) from a free image,
/// the unfurnished map's free image and its ground-truth room labels (CV_32S, 0 = no room),
/// all in the same (already turned) frame.
RoomBenchmarkCase drawnCase(std::string dataset, std::string map, bool furnished,
                            double rotationDeg, const cv::Mat& free, const cv::Mat& baseFree,
                            const cv::Mat& roomLabels, double resolution);

}  // namespace toposlam::rooms
