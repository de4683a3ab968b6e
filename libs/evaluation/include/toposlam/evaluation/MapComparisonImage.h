#pragma once
// Occupancy-grid pictures of several SLAM engines on one log side by side in one PNG, each
// under a title, all drawn at the same metric scale, so that doubled or bent corridors show at
// a glance (benchmark B3).
#include <string>
#include <vector>

namespace toposlam::evaluation {

struct MapPanel {
    std::string title;      ///< e.g. "graph: 0.0190 m, 31 s CPU"
    std::string imageFile;  ///< the engine's grid PNG; "" = no map (the panel says `missing`)
    double metresPerPixel = 0.05;
    /// Turn applied to the picture first (rad, counter-clockwise as seen), e.g. to bring maps
    /// built in different frames into one orientation.
    double rotation = 0;
    std::string missing;  ///< text drawn in place of a map, e.g. "failed: exit status 1"
};

/// Turns each picture by its `rotation`, crops it to its mapped part (pixels that differ from the
/// unknown-space colour of its corner), scales all by one factor (the same metres per output pixel
/// for every panel; the largest panel at most `maxPanelPixels` wide or high, never enlarged beyond
/// the finest resolution), and writes them left to right under `heading`, atomically, to `path`
/// (PNG). Throws std::runtime_error when a picture cannot be read or the file cannot be written,
/// std::invalid_argument for no panel.
void saveMapComparison(const std::vector<MapPanel>& panels, const std::string& heading,
                       const std::string& path, int maxPanelPixels = 1000);

}  // namespace toposlam::evaluation
