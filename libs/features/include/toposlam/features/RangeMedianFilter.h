#pragma once
// Graph-matching paper, sec. 2.1: "first denoise the ranges with a median (or mean) filter,
// then compute the angles". A median over a window of consecutive valid readings keeps range
// jumps and corners sharp, unlike a mean. The window never reaches across an invalid reading;
// near one (or the scan border) it shrinks to the valid readings it still holds.
#include <toposlam/features/ScanPoints.h>

#include <vector>

namespace toposlam::features {

class RangeMedianFilter {
  public:
    /// Readings in the window: 1 (no filtering), 3, 5, ... (an odd number, at most 15).
    unsigned window = 3;

    /// Replaces each valid reading of `pts` by the median of its window (in place).
    void apply(ScanPoints& pts);

  private:
    std::vector<double> original_;
};

}  // namespace toposlam::features
