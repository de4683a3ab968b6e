#pragma once
// Corner paper, step 3: fixing the corner position. A corner found at reading q is shared by
// the two lines, but the true corner lies between two readings: if
//     |dk(q) - dk(q-1)| < |dk(q) - dk(q+1)|
// it lies between q-1 and q, so the first line ends at q-1; otherwise between q and q+1, so the
// second line starts at q+1. Each line then holds only readings of its own wall.
// Where a neighbour's dk is undefined (end of a run) the other side decides.
#include <toposlam/features/LinePart.h>
#include <toposlam/features/SlopeDifference.h>

#include <vector>

namespace toposlam::features {

void fixCorners(const SlopeDifference& sd, std::vector<LinePart>& parts);

}  // namespace toposlam::features
