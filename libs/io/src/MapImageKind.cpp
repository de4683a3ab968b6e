#include <toposlam/io/GridMapIO.h>
#include <toposlam/io/MapImageKind.h>

#include "GreyImage.h"

#include <cstdio>

namespace toposlam::io {

// White is what a drawn plan reads as free: grey >= kWhiteGrey <=> p(free) > kDrawnPlanFreeAbove.
static_assert(kWhiteGrey / 255.0 > kDrawnPlanFreeAbove &&
              (kWhiteGrey - 1) / 255.0 <= kDrawnPlanFreeAbove);

double MapImageKindGuess::midGreyShare() const {
    return nonWhitePixels == 0 ? 0.0 : double(midGreyPixels) / double(nonWhitePixels);
}

std::string MapImageKindGuess::reason() const {
    char text[200];
    std::snprintf(text, sizeof text,
                  "%.0f %% of its non-white pixels are mid grey (unknown space in a grid), "
                  "%.1f %% dark (occupied)",
                  100.0 * midGreyShare(),
                  nonWhitePixels == 0 ? 0.0 : 100.0 * double(darkPixels) / double(nonWhitePixels));
    return text;
}

MapImageKindGuess guessMapImageKind(const std::array<std::size_t, 256>& greyHistogram) {
    MapImageKindGuess guess;
    for (int grey = 0; grey < kWhiteGrey; ++grey) {
        const std::size_t n = greyHistogram[static_cast<std::size_t>(grey)];
        guess.nonWhitePixels += n;
        if (grey < kMidGreyFirst)
            guess.darkPixels += n;
        else if (grey <= kMidGreyLast || grey == kMapSaverUnknownGrey)
            guess.midGreyPixels += n;
    }
    const bool unknownSpace = 2 * guess.midGreyPixels >= guess.nonWhitePixels;
    const bool walls = double(guess.darkPixels) >= kMinDarkShare * double(guess.nonWhitePixels) &&
                       guess.darkPixels > 0;
    guess.kind = guess.nonWhitePixels == 0 || (unknownSpace && walls) ? MapImageKind::OccupancyGrid
                                                                      : MapImageKind::DrawnPlan;
    return guess;
}

MapImageKindGuess guessMapImageKind(const std::string& path) {
    const cv::Mat grey = detail::readGreyImage(path);
    std::array<std::size_t, 256> histogram{};
    for (int r = 0; r < grey.rows; ++r) {
        const auto* row = grey.ptr<unsigned char>(r);
        for (int c = 0; c < grey.cols; ++c)
            ++histogram[row[c]];
    }
    return guessMapImageKind(histogram);
}

}  // namespace toposlam::io
