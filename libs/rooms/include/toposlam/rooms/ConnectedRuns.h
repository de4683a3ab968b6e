#pragma once
// Connected components of a binary image, found run by run.
//
// A map is long runs of free cells and of wall: a 1000-cell row of a floor plan holds a few
// dozen runs. Joining each run to the runs it touches in the row above is then a few dozen
// steps per row instead of one per cell, and a component's area (or its box, or its cells)
// comes from its runs without another pass over the image.
// The labels are those of cv::connectedComponents with 4-connectivity (its SAUF algorithm):
// 1, 2, ... in the raster order of each component's first cell, 0 for the other cells. With
// 8-connectivity the components are the same as OpenCV's, numbered the same way (OpenCV's
// 8-connected labelling numbers them by 2x2 blocks instead).
#include <opencv2/core/mat.hpp>

#include <vector>

namespace toposlam::rooms {

class ConnectedRuns {
  public:
    /// Cells [begin, end) of image row `row` (cells), all in component `label`.
    struct Run {
        int row = 0;
        int begin = 0;
        int end = 0;
        int label = 0;
    };

    /// Which cells make up the components.
    enum class Cells { NonZero, Zero };

    /// Finds the 4- or 8-connected components of the `cells` of `image` (CV_8U, any stride).
    /// Returns their number plus one (label 0 is the other cells), as cv::connectedComponents.
    int find(const cv::Mat& image, int connectivity, Cells cells = Cells::NonZero);

    /// The runs of the last find(), in raster order, labelled.
    const std::vector<Run>& runs() const { return runs_; }
    /// Cells per label of the last find(); [0] = 0.
    const std::vector<int>& areas() const { return areas_; }
    /// Writes the label image of the last find() into `labels` (CV_32S, created with the
    /// image's size when it has another size or type; any stride): each run's label, 0
    /// elsewhere.
    void paint(cv::Mat& labels) const;

  private:
    template <bool NonZero>
    void collectRuns(const cv::Mat& image);
    int root(int run);

    std::vector<Run> runs_;
    std::vector<int> rowStart_;  // index of each row's first run; [rows] = runs_.size()
    std::vector<int> parent_;    // union-find over runs; a parent's index is below its child's
    std::vector<int> areas_;
    cv::Size size_;
};

}  // namespace toposlam::rooms
