#include <toposlam/io/LaserPosition.h>

#include <cmath>
#include <cstdio>

namespace toposlam::io {

bool laserOffCentre(const mrpt::math::TPoint2D& laser) {
    constexpr double kCentre = 1e-4;  // m
    return std::hypot(laser.x, laser.y) > kCentre;
}

std::string describeLaserPosition(const mrpt::math::TPoint2D& laser) {
    char text[128];
    std::snprintf(text, sizeof text, "%.3f m %s and %.3f m %s of the robot's centre",
                  std::abs(laser.x), laser.x < 0 ? "behind" : "ahead", std::abs(laser.y),
                  laser.y < 0 ? "right" : "left");
    return text;
}

}  // namespace toposlam::io
