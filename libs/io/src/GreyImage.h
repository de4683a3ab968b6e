#pragma once
// Reading a map picture as 8-bit grey, shared by the grid-map reader and the guess of how a
// bare picture is meant (MapImageKind).
#include <opencv2/core/mat.hpp>

#include <string>

namespace toposlam::io::detail {

/// The image at `path` as 8-bit grey (colour and alpha images are converted). Throws
/// InputError naming the file when it is missing, unreadable, corrupt or larger than
/// kMaxGridMapCells pixels (checked before decoding).
cv::Mat readGreyImage(const std::string& path);

}  // namespace toposlam::io::detail
