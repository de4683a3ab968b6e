#pragma once
// Shared pieces of the two ipa_room_segmentation baselines (Bormann et al., "Room segmentation:
// survey, implementation, and analysis", ICRA 2016), reimplemented from the package's
// description and sources for B4: MorphologicalSegmentation and DistanceSegmentation.
// Input maps are 8-bit, 255 = free, 0 = not free (the package's client thresholds grey >= 250);
// output label images are CV_32S with 0 = obstacle, segments 1..N and 65280 (kUnassignedLabel)
// for free pixels no segment reached, as the package's server returns them.
#include <opencv2/core/mat.hpp>

namespace toposlam::rooms {

/// The package's wavefrontRegionGrowing: unassigned pixels (> 65279) take, pass after pass, the
/// label of the first labelled 8-neighbour (scan order: rows -1..1, columns -1..1) the previous
/// pass had, until nothing changes. The outermost image rows and columns are never filled.
void wavefrontRegionGrowing(cv::Mat& labels);

}  // namespace toposlam::rooms
