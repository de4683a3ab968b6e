#pragma once
// Furniture standing against a room's walls (a desk in a corner, a cabinet, a shelf) is not
// free space, so the room's label stops at its front and the room's area leaves it out, while
// the floor under it belongs to the room (deviation: the paper labels free cells only; Bormann's
// ground truth counts those cells to the room). Free-standing furniture is an island and
// already takes its room's id (RoomSegmenter::Options::labelIslands); this step gives the room
// the pockets furniture leaves along its walls.
//
// A pocket of room R: a connected (8-neighbour) set of non-free, unlabelled cells inside R's
// box that touches R and no other room, no longer than `maxSize` along either main direction,
// and filling at least half of its own box (furniture is rectangular).
//
// R's box is the rectangle, along the main directions (the frame the walls are drawn in), that
// spans the outermost lines across R holding at least `minSide` of R's cells and at least half
// as many as the line two cells further in, shrunk by one cell (a wall drawn at an angle ends
// in steps a cell deep, which are wall, not furniture). Cells near a door do not count: the
// room's half of a door opening reaches into the wall and would stretch the box over it.
//
// What it cannot tell apart from furniture: a notch of the room's outline of the same size and
// shape (a pillar or a duct shaft against a wall, the outside of an L-shaped building corner
// under maxSize); curved room ends leave corner pockets that fill less than half their box and
// stay unlabelled.
#include <toposlam/rooms/VirtualDoorDetector.h>

#include <opencv2/core/mat.hpp>

#include <cstddef>
#include <vector>

namespace toposlam::rooms {

class FurniturePockets {
  public:
    struct Options {
        double maxSize = 2.0;  ///< m, longest side of a pocket (0: off)
        /// m, the fewest of a room's cells a line across it holds to bound its box
        /// (RoomSegmenter: the narrowest door)
        double minSide = 0.6;
        /// m beyond half a door's width: the room's cells this near a door do not count for its
        /// box (RoomSegmenter: half the thickest wall)
        double doorReach = 0.35;
    };

    /// Labels the pockets of every room of `labels` (CV_32S room ids > 0, 0 = unlabelled, e.g.
    /// RoomSegmenter's labels before geometry) in place. `mainDirection`: rad, phi1 of the
    /// main-direction voter, in image coordinates (x right, y down); `doors`: the cuts, in
    /// `labels`' pixels; `resolution`: m per cell. Returns the number of cells labelled.
    std::size_t label(const Options& options, double mainDirection,
                      const std::vector<VirtualDoor>& doors, double resolution, cv::Mat& labels);

  private:
    /// Per room: its box along the main directions (u = along, v = across, cells; [u0, u1) x
    /// [v0, v1)), the
    /// histograms of its cells over u and v, and where its pockets may start.
    struct RoomBox {
        bool seen = false;      ///< the room is in this image
        bool measured = false;  ///< has cells away from doors
        double u0 = 0, u1 = -1, v0 = 0, v1 = -1;
        std::vector<int> alongU, alongV;
        std::vector<cv::Point> seeds;  ///< unlabelled 4-neighbours of the room's cells
    };
    void measureBoxes(double cosine, double sine, double minSideCells, const cv::Mat& labels);

    std::vector<RoomBox> boxes_;
    cv::Mat nearDoor_, visited_;
    std::vector<cv::Point> stack_, pocket_, filled_;
};

}  // namespace toposlam::rooms
