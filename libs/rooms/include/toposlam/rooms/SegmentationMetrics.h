#pragma once
// The B4 room-segmentation metrics (shared/BENCHMARKS.md, "B4 metric definitions"), which
// reproduce ipa_room_segmentation's own evaluation (Bormann et al. 2016):
//  - Bormann recall / precision (EvaluationSegmentation::computePrecisionRecall): per ground-
//    truth room the best overlap with a segment over the room's area, per segment the best
//    overlap with a room over the segment's area, each averaged; rooms and segments of at most
//    100 pixels are ignored; the "unassigned free space" label 65280 is a segment like any other;
//  - door precision / recall: a door is a boundary between two labels, after the labels have
//    been grown 5 steps into unlabelled free space; a virtual door matches a true door when its
//    representative point is within the tolerance of one of the true door's pixels.
// Images are in map-image layout; a segmentation is a CV_32S label image, 0 = obstacle.
#include <opencv2/core/mat.hpp>

#include <cstddef>
#include <vector>

namespace toposlam::rooms {

/// Label of free pixels that no segment reached, as ipa_room_segmentation writes it.
constexpr int kUnassignedLabel = 65280;
/// Rooms and segments with at most this many pixels are ignored.
constexpr int kMaxIgnoredRegionPixels = 100;

/// Ground-truth rooms: 8-connected components of the pixels > 250 of the grey ground-truth
/// image, those of more than 100 pixels kept. CV_32S labels 1..count, 0 elsewhere.
struct GroundTruthRooms {
    cv::Mat labels;
    int count = 0;
};
GroundTruthRooms groundTruthRooms(const cv::Mat& groundTruthGrey);
/// Ground-truth rooms from a label image (CV_32S, 0 = no room, any other value a room, such as
/// a rotated GroundTruthRooms::labels or a generated plan's rooms): the labels with more than
/// 100 pixels, renumbered 1..count in order of their values; the others become 0.
GroundTruthRooms groundTruthFromLabels(const cv::Mat& roomLabels);

/// The open floor of the ground-truth rooms: the room pixels that are free in `free` (CV_8U,
/// non-zero = free; the map that was toured or segmented) and have no non-free pixel among
/// their 8 neighbours; every other pixel becomes 0. Labels and count are kept; a room whose
/// open floor would have at most 100 pixels stays whole. A grid built from a laser marks the cell a
/// wall face lies in as occupied, so its walls and furniture stand up to one cell into a drawn
/// plan's free pixels; scoring over the open floor leaves that quantisation out and keeps
/// everything else.
GroundTruthRooms openFloorOfRooms(const GroundTruthRooms& truth, const cv::Mat& free);

struct PrecisionRecall {
    double recall = 0;  ///< mean over GT rooms of best overlap / room area ("recall_micro")
    double precision =
        0;  ///< mean over segments of best overlap / segment area ("precision_micro")
    double recallPixels = 0;     ///< pixel-weighted recall ("recall_macro")
    double precisionPixels = 0;  ///< pixel-weighted precision ("precision_macro")
    int rooms = 0;               ///< GT rooms scored
    /// Per GT room (room g at [g - 1]): best overlap / room area, and the room's area (pixels).
    /// Says which rooms a mean lost (e.g. rooms a robot never saw).
    std::vector<double> roomRecall;
    std::vector<std::size_t> roomPixels;
    int segments = 0;  ///< segments scored (> 100 px, 65280 included)
    /// As `precision`, over the scored segments other than 65280: the rooms a method returned,
    /// without the free space it left unassigned (on a SLAM grid mostly specks of free cells
    /// next to and inside walls, outside every ground-truth room). 0 when 65280 is the only
    /// scored segment.
    double precisionOfRooms = 0;
    std::size_t unassignedPixels = 0;  ///< pixels of the 65280 segment (0: none or ignored)
};
/// `segmentation`: CV_32S, 0 = obstacle, any other value a segment (65280 included).
PrecisionRecall bormannPrecisionRecall(const GroundTruthRooms& truth, const cv::Mat& segmentation);

/// Segments a method returned: distinct labels other than 0 and 65280, tiny ones included.
int countSegments(const cv::Mat& segmentation);

/// A door of the door metric: the boundary pixels between two labels.
struct LabelBoundaryDoor {
    int labelA = 0, labelB = 0;     ///< labelA < labelB
    std::vector<cv::Point> pixels;  ///< raster order, each once
    cv::Point representative;       ///< the pixel nearest to the pixels' mean
};

/// Steps 1-5 of the door metric on a label image (CV_32S, 0 = unlabelled) and the free-space
/// mask `free` (CV_8U, non-zero = free): labels grown into unlabelled free pixels by a 4-connected
/// FIFO breadth-first search of at most `gapSteps` steps, seeded in raster order; then every
/// label pair with 4-adjacent pixels is one door. Doors sorted by (labelA, labelB).
std::vector<LabelBoundaryDoor> labelBoundaryDoors(const cv::Mat& labels, const cv::Mat& free,
                                                  int gapSteps = 5);

/// The segmentation side's labels for the door metric: 65280 and segments of at most 100 px
/// set to 0.
cv::Mat doorMetricSegmentLabels(const cv::Mat& segmentation);

struct DoorMatchCounts {
    std::size_t virtualDoors = 0;    ///< |V|
    std::size_t matchedVirtual = 0;  ///< virtual doors matching some true door
    std::size_t trueDoors = 0;       ///< |T|
    std::size_t matchedTrue = 0;     ///< true doors matched by some virtual door

    /// Share of the virtual doors that match a true door (0 when there is none).
    double precision() const { return share(matchedVirtual, virtualDoors); }
    /// Share of the true doors that some virtual door matches (0 when there is none).
    double recall() const { return share(matchedTrue, trueDoors); }

  private:
    static double share(std::size_t part, std::size_t whole) {
        return whole == 0 ? 0.0 : static_cast<double>(part) / static_cast<double>(whole);
    }
};
/// Step 6-7: v matches t when v's representative point is within `tolerancePixels` of a pixel
/// of t (no one-to-one constraint).
DoorMatchCounts matchDoors(const std::vector<LabelBoundaryDoor>& virtualDoors,
                           const std::vector<LabelBoundaryDoor>& trueDoors, double tolerancePixels);

}  // namespace toposlam::rooms
