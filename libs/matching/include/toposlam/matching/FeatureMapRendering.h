#pragma once
// How a FeatureMap looks: in 3D (MRPT opengl objects, what RawLogViewer's raw-map dialog and
// any CMetricMap::getVisualization() user shows) and as a picture (PNG). Both draw the
// CONFIRMED features only, with the same legend:
//   wall segments        dark blue lines
//   convex corners       red        (points that bulge towards the robot: obstacle corners)
//   concave corners      green      (room corners)
//   endpoints            orange: convex / concave segment ends; grey: jump (occluding) edges
#include <mrpt/img/CImage.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <toposlam/matching/FeatureMap.h>

namespace toposlam::matching {

/// Appends lines and point marks in the map frame (z = 0) to `out`.
void appendFeatureMapVisualization(const FeatureMap& map, mrpt::opengl::CSetOfObjects& out);

/// A top view of the map: white background, `metresPerPixel` (> 0) scale, a 0.5 m margin,
/// x to the right and y up; corners as marks (convex: red cross, concave: green square),
/// endpoints as small dots. At most 4000 x 4000 pixels: larger maps are drawn coarser.
mrpt::img::CImage drawFeatureMap(const FeatureMap& map, double metresPerPixel = 0.02);

}  // namespace toposlam::matching
