#pragma once
// The progressive probabilistic Hough transform (Matas, Galambos and Kittler 2000) as OpenCV's
// cv::HoughLinesP runs it: the same segments, in the same order.
//
// The transform takes the set pixels in a random order (OpenCV's generator and seed); each
// votes for every line through it, one per angle step, and when a line gathers `threshold`
// votes, the pixels along it (gaps up to maxLineGap) are taken out of the image and out of the
// accumulator, and the run becomes a segment if it is minLineLength long. Nearly all the time
// is the votes: one accumulator cell per pixel and angle, in and out. Here the accumulator
// holds, per angle, only the distances a pixel of the image can reach there (a third of
// OpenCV's rows, which span twice width + height) and is kept from call to call; a pixel's
// cells are computed four angles at a time, and the strongest line is found after the votes
// rather than cell by cell. The integer and float arithmetic is OpenCV's, so the random order,
// the votes and the walks are the same.
#include <opencv2/core/mat.hpp>
#include <opencv2/core/matx.hpp>

#include <cstdint>
#include <vector>

namespace toposlam::rooms {

class ProbabilisticHough {
  public:
    struct Parameters {
        double rho = 1.0;          ///< distance step of the accumulator (pixels)
        double theta = 0.0;        ///< angle step of the accumulator (rad)
        int threshold = 1;         ///< votes a line needs
        double minLineLength = 0;  ///< shortest segment kept (pixels; rounded as OpenCV does)
        double maxLineGap = 0;     ///< longest gap inside one segment (pixels; rounded)
    };

    /// cv::HoughLinesP(image, lines, p.rho, p.theta, p.threshold, p.minLineLength,
    /// p.maxLineGap): segments (x1, y1, x2, y2) in pixels of `image` (CV_8U, non-zero = set,
    /// any stride).
    void find(const cv::Mat& image, const Parameters& p, std::vector<cv::Vec4i>& lines);

  private:
    // The mask's cell of pixel p (inside the image).
    std::uint8_t& maskAt(const cv::Point& p) {
        return mask_[static_cast<std::size_t>(p.y) * static_cast<std::size_t>(width_) +
                     static_cast<std::size_t>(p.x)];
    }
    // Writes the accumulator index of the cell (angle n, distance of pixel (x, y)) for every
    // angle into cells_.
    void cellsOf(int x, int y);
    // Walks from the pixel along the line of angle n both ways, as far as gaps allow; the two
    // ends found, then (taking the pixels out and, for a segment, their votes) returns whether
    // the run is a segment.
    bool takeLine(int x, int y, int n, int minLength, int maxGap, cv::Vec4i& segment);

    std::vector<float> cosines_, sines_;  // per angle, divided by rho (OpenCV's table)
    std::vector<int> rowOffset_;  // per angle: index of distance 0 in votes_ (may be outside)
    std::vector<int> cells_;      // per angle: the current pixel's cell, then its votes
    std::vector<std::int32_t> votes_;
    std::vector<cv::Point> pixels_;   // the set pixels not yet drawn
    std::vector<std::uint8_t> mask_;  // the set pixels still in the image, row-major
    int width_ = 0, height_ = 0, angles_ = 0;
};

}  // namespace toposlam::rooms
