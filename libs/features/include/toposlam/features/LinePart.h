#pragma once
// One element (Lb, Le, Lp) of the corner paper's segment set L: the readings begin..end
// (canonical indices, inclusive) believed to lie on one line, and whether it meets the next
// element at a corner (Lp = 1) or is broken from it (Lp = 0). The split (step 1), the merge
// (step 2) and the corner fix (step 3) edit a list of these; FeatureAssembly turns the list
// into segments and corners (steps 4 and 5). Split-and-merge produces the same list.
#include <toposlam/features/ScanFeatures.h>

#include <cstdint>

namespace toposlam::features {

struct LinePart {
    std::uint32_t begin = 0, end = 0;  ///< canonical reading indices, inclusive
    bool cornerAfter = false;          ///< Lp: joined to the next part by a corner
    /// The reading where the corner after this part was detected (valid when cornerAfter).
    std::uint32_t joint = 0;
    /// How each end came about when it is not a corner: Jump (the nearer side of a range
    /// discontinuity) or Open (far side of a jump, invalid reading, scan border).
    EndpointType beginType = EndpointType::Open, endType = EndpointType::Open;
    /// Fewest readings this part may have (0: no constraint of its own). The robust split sets
    /// it to the baseline its corners were measured over: a shorter part lies inside the
    /// corner's own dk bump and says nothing of its own about a line.
    std::uint32_t minSize = 0;
    std::uint32_t size() const { return end >= begin ? end - begin + 1 : 0; }
};

}  // namespace toposlam::features
