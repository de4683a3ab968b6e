#pragma once
// What the two topological-map files (TopologicalMapJson.cpp, TopologicalMapGraphML.cpp) share:
// the bounds a file may declare, the error their readers throw before the file name is added,
// and the label image as runs. Internal to libs/rooms.
#include <toposlam/rooms/TopologicalMap.h>

#include <opencv2/core/mat.hpp>

#include <stdexcept>
#include <string>
#include <vector>

namespace toposlam::rooms::detail {

constexpr long long kMaxSide = 1 << 20;  ///< cells per grid row or column
constexpr long long kMaxId = 1 << 30;

/// What is wrong inside a file; the public readers add the file name (io::InputError).
class FormatError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// The label image as row-major runs "value, count, value, count, ..." over rows x cols
/// cells, row 0 at the top; {0, rows * cols} when the map has no label image.
std::vector<long long> labelRuns(const TopologicalMap& map);

/// The label image of `frame` from its runs; throws FormatError naming `what` unless the runs
/// cover exactly rows x cols cells with labels 0..roomCount. Empty for a 0-cell frame.
cv::Mat labelsFromRuns(const GridImageFrame& frame, const std::vector<long long>& runs,
                       int roomCount, const std::string& what);

/// Throws FormatError unless the resolution is > 0 and the corner finite.
void checkFrame(const GridImageFrame& frame);

}  // namespace toposlam::rooms::detail
