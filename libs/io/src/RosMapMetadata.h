#pragma once
// ROS map_server map metadata (http://wiki.ros.org/map_server#YAML_format), the sidecar of
// every image map TopoSLAM reads or writes:
//   image: map.pgm            # relative to the YAML file's directory
//   resolution: 0.05          # m per pixel
//   origin: [-10.0, -10.0, 0.0]   # world pose (x, y, yaw) of the lower-left pixel's corner
//   negate: 0                 # 1: white = occupied
//   occupied_thresh: 0.65     # p(occupied) above this: occupied
//   free_thresh: 0.196        # p(occupied) below this: free
//   mode: trinary             # or scale, raw (optional; default trinary)
// where p(occupied) = (255 - grey) / 255 (negate 0) or grey / 255 (negate 1).
#include <string>

namespace toposlam::io {

struct RosMapMetadata {
    enum class Mode { Trinary, Scale, Raw };
    std::string image;  ///< as written in the file (relative to the YAML's directory)
    double resolution = 0.05;
    double originX = 0, originY = 0, originYaw = 0;
    bool negate = false;
    double occupiedThresh = 0.65;
    double freeThresh = 0.196;
    Mode mode = Mode::Trinary;
};

/// Throws InputError naming `yamlPath` for a missing file, a missing or malformed key, a
/// non-positive resolution, thresholds outside [0,1] or free >= occupied, or an origin yaw
/// other than 0 (rotated maps are not supported).
RosMapMetadata readRosMapMetadata(const std::string& yamlPath);
/// The YAML text for `meta` (numbers in shortest round-trip form).
std::string formatRosMapMetadata(const RosMapMetadata& meta);
/// The image path of `meta`, resolved against the YAML file's directory.
std::string resolveRosMapImage(const std::string& yamlPath, const RosMapMetadata& meta);

}  // namespace toposlam::io
