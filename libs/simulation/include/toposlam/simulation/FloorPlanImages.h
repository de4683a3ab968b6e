#pragma once
// A generated floor plan drawn as the images of a room-segmentation benchmark, at any angle:
// the map (unfurnished and furnished), the ground-truth rooms and the doors, in the layout of
// Bormann et al.'s benchmark (ipa_room_segmentation: 8-bit map images, >= 250 free; a
// "_gt_segmentation" image with the rooms white). Every pixel is the plan at its centre
// (exact point sampling, as a scanned plan or a SLAM grid draws a building at that angle), so
// a turned plan is drawn afresh, not resampled from the upright one.
//
// Frames: the plan frame (FloorPlan, m) turned by rotationDeg counter-clockwise about its
// origin gives the image's world frame; pixel (c, r) has its centre at
// (xMin + (c + 0.5) res, yMax - (r + 0.5) res) there (row 0 at the top, as in a map image).
#include <toposlam/simulation/FloorPlanGenerator.h>

#include <mrpt/math/TPoint2D.h>

#include <opencv2/core/mat.hpp>

#include <string>
#include <vector>

namespace toposlam::simulation {

struct FloorPlanImages {
    double resolution = 0.05;   ///< m per pixel
    double rotationDeg = 0;     ///< counter-clockwise, plan frame -> image world frame
    double xMin = 0, yMax = 0;  ///< m, image world frame: left edge, top edge
    cv::Mat map;                ///< CV_8U: 255 free, 0 walls, 205 outside the building (unknown)
    cv::Mat furnished;          ///< the same with the furniture (0)
    /// CV_32S ground-truth room (GeneratedFloorPlan::groundTruthRoom) of every pixel whose
    /// centre is on a room's floor and not in a wall; 0 elsewhere (walls, doorways, outside).
    /// Furniture stands in rooms: its pixels carry the room.
    cv::Mat rooms;
    struct Door {
        cv::Point2f jambA,
            jambB;         ///< pixels (continuous), the opening's ends on the wall's centre line
        double width = 0;  ///< m
        int roomA = 0, roomB = 0;  ///< ground-truth rooms
    };
    std::vector<Door> doors;

    /// Pixel coordinates (continuous, centre of pixel (c, r) = (c, r)) of a plan point.
    cv::Point2f toPixel(const mrpt::math::TPoint2D& planPoint) const;
    /// The plan point at the centre of pixel coordinates (x, y).
    mrpt::math::TPoint2D toPlan(double x, double y) const;
};

/// Draws `plan` at `resolution` (m) turned by `rotationDeg`, with `margin` (m) of unknown space
/// around its walls.
FloorPlanImages drawFloorPlan(const GeneratedFloorPlan& plan, double resolution = 0.05,
                              double rotationDeg = 0, double margin = 0.5);

/// Writes the benchmark files of `images` into `dir` (created if needed), each atomically:
/// <name>.png, <name>_furnitures.png (grey maps), <name>_gt_segmentation.png (rooms 255, else
/// 0) and <name>_doors.json (per door: jambs in pixels, width in m, the two ground-truth rooms;
/// resolution, rotation). Returns the paths written.
std::vector<std::string> saveFloorPlanImages(const FloorPlanImages& images, const std::string& dir,
                                             const std::string& name);

}  // namespace toposlam::simulation
