#pragma once
// Graph-matching paper, sec. 2.1: turning angles. theta_i is the angle from vector
// l_{i-1} l_i to vector l_i l_{i+1}; the paper counts clockwise as positive = concave
// (a dent away from the sensor) for its clockwise scanner. Here scans run counter-clockwise
// (ScanPoints), so the same geometry is a counter-clockwise (left) turn: concave > 0,
// convex < 0, as in the paper. The sum of theta over a window (filter [1 1 1 1]) is the total
// turn of the scan around a point: convex if < -pi/3, concave if > pi/3 (EndpointDetector).
//
// A sum of turning angles telescopes: over readings a..b it is the direction change from
// chord l_{a-1} l_a to chord l_b l_{b+1}. The noise-robust form (a documented deviation)
// measures it that way over longer chords: the turn across readings i-1..i+1 between chord
// l_{i-1-s} l_{i-1} and chord l_{i+1} l_{i+1+s}, s chosen per reading so that each chord
// spans at least b metres. Range noise sigma turns a chord of length b by ~ sqrt(2) sigma / b,
// so b is chosen for z * 2 sigma / b <= threshold. A corner anywhere between readings i-1 and
// i+1 then lies inside the window and both chords run along its two walls.
#include <toposlam/features/JumpDetector.h>
#include <toposlam/features/ScanPoints.h>

#include <cstdint>
#include <vector>

namespace toposlam::features {

/// Signed turn (rad, counter-clockwise positive) from direction (ax, ay) to (bx, by).
double turnBetween(double ax, double ay, double bx, double by);

class TurningAngle {
  public:
    /// Windowed turn of each reading (rad); 0 where undefined. In the chord form only turns
    /// beyond the threshold are computed (atan2 is the costly part); smaller ones read 0.
    std::vector<double> windowTurn;
    /// Whether windowTurn[k] is defined (the window and its chords fit in k's run).
    std::vector<std::uint8_t> defined;

    /// paperForm: the sum of 4 single-step turning angles theta_{i-1} + ... + theta_{i+2}.
    /// Otherwise the chord form with minimum chord length for range noise sigma (m), margin z
    /// sigmas and turn threshold `threshold` (rad).
    void compute(const ScanPoints& pts, const std::vector<PointRun>& runs, bool paperForm,
                 double sigma, double z, double threshold);

  private:
    std::vector<double> single_;
};

}  // namespace toposlam::features
