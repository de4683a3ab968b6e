#pragma once
// How a bare map picture is meant: a picture without the .yaml that says what its greys mean
// (io::isBareMapImage) may be an occupancy grid, grey = p(free) (a SLAM map saved as a
// picture: white free, dark occupied, mid grey unknown), or a drawn floor plan, where only
// white is free and walls, furniture and the background around the building are drawn in
// whatever greys the drawing used, all of them obstacles. Read a plan as a grid and nothing
// fails, but the answer is wrong: light-grey walls (Bormann et al.'s Freiburg52_scan draws
// them in grey 211, p(free) 0.83) or a light-grey background read as free space, and the
// whole plan comes out as one room.
//
// The tell is unknown space. A SLAM grid is mostly unknown beyond what the laser saw, drawn in
// mid grey (p(free) 0.35-0.65; MRPT draws 127/128), and bounded by occupied cells in dark grey.
// A drawing has no unknown space: its non-white pixels are walls, furniture and background.
// So a picture is taken for a grid when at least half of its non-white pixels are mid grey and
// it has dark pixels (at least kMinDarkShare of the non-white ones); otherwise for a drawn
// plan. A picture of white and mid grey alone (every wall drawn in mid grey) is a plan: a grid
// without a single occupied cell bounds nothing. ROS map_saver draws unknown cells in grey 205
// (free 254, occupied 0), which counts as mid grey: its picture, read without its .yaml, is a
// grid, and p(free) = 205 / 255 = 0.804 reads as unknown, as map_server reads it.
#include <array>
#include <cstddef>
#include <string>

namespace toposlam::io {

enum class MapImageKind { OccupancyGrid, DrawnPlan };

/// Grey levels of the guess (8-bit grey; p(free) = grey / 255 in a grid).
constexpr int kWhiteGrey = 250;         ///< and above: white, free in either reading
constexpr int kMidGreyFirst = 90;       ///< p(free) 0.35 ...
constexpr int kMidGreyLast = 165;       ///< ... to 0.65: unknown space in a grid
constexpr double kMinDarkShare = 1e-3;  ///< of the non-white pixels, for a grid

/// What guessMapImageKind counted, and what it decided.
struct MapImageKindGuess {
    MapImageKind kind = MapImageKind::OccupancyGrid;
    std::size_t nonWhitePixels = 0;  ///< grey < kWhiteGrey
    /// grey kMidGreyFirst..kMidGreyLast, or map_saver's unknown (GridMapIO.h, 205)
    std::size_t midGreyPixels = 0;
    std::size_t darkPixels = 0;  ///< grey < kMidGreyFirst (occupied in a grid)

    /// Share of the non-white pixels that are mid grey (0 when all are white).
    double midGreyShare() const;
    /// Why, in a few words for the user: "41 % of its non-white pixels are mid grey ...".
    std::string reason() const;
};

/// The guess from a picture's histogram of 8-bit grey levels.
MapImageKindGuess guessMapImageKind(const std::array<std::size_t, 256>& greyHistogram);

/// The guess for the picture at `path`, read as loadGridMap reads it (8-bit grey; colour and
/// alpha images converted). Throws InputError naming the file as loadGridMap does.
MapImageKindGuess guessMapImageKind(const std::string& path);

}  // namespace toposlam::io
