#pragma once
// Where to cut a part that is no line (FeatureAssembly): the reading k that leaves the
// smallest total least-squares residual when readings begin..k-1 and k+1..end are each fitted
// by a line. k itself, which may belong to either wall, is left out of both. This is the
// least-squares breakpoint of two lines; unlike the reading farthest from the chord (split-
// and-merge), it stays at the corner when the corner is shallow or the part holds a third
// wall. One pass over prefix sums: O(N) per cut; the sums of a part serve every piece of it.
#include <toposlam/features/LineFit.h>
#include <toposlam/features/ScanPoints.h>

#include <cstddef>
#include <vector>

namespace toposlam::features {

class TwoLineSplit {
  public:
    /// Prefix sums of canonical readings begin..end (inclusive): the part to cut.
    void prepare(const ScanPoints& pts, std::size_t begin, std::size_t end);
    /// Best k for the readings begin..end (inclusive, inside the prepared part) with at least
    /// minPoints readings on each side; false when there are too few readings for that.
    bool find(std::size_t begin, std::size_t end, std::size_t minPoints, std::size_t& at) const;
    /// Least-squares residual sum of squares (m^2) of one line through readings begin..end
    /// (inclusive, inside the prepared part, at least 2).
    double residual(std::size_t begin, std::size_t end) const;

  private:
    std::size_t first_ = 0;          // the prepared part's first reading
    std::vector<PointSums> prefix_;  // prefix_[i]: sums of readings first_..first_+i-1
};

}  // namespace toposlam::features
