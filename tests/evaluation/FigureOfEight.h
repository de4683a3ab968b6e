#pragma once
// A test trajectory for the evaluation's tests: a robot driving a figure of eight (turning both
// ways), a pose every 0.1 s, heading along the path.
#include <toposlam/io/Trajectory.h>

#include <cmath>

namespace toposlam::evaluation::test_paths {

inline io::Trajectory2D figureOfEight() {
    io::Trajectory2D t;
    for (int i = 0; i <= 1200; ++i) {
        const double s = 0.01 * i;  // rad along the curve
        const double x = 4 * std::sin(s), y = 2 * std::sin(2 * s);
        const double dx = 4 * std::cos(s), dy = 4 * std::cos(2 * s);
        t.push_back({0.1 * i, {x, y, std::atan2(dy, dx)}});
    }
    return t;
}

}  // namespace toposlam::evaluation::test_paths
