#include <toposlam/mapping/ManhattanAlignment.h>

#include <cmath>
#include <complex>

namespace toposlam::mapping {

namespace {

// Beams this far apart (in index) span one local wall piece; nearer points are too noisy to
// give a direction (1 cm noise over 4 cm spacing).
constexpr std::size_t kPieceBeams = 4;
constexpr double kMaxPieceLength = 0.4;   // m: longer = a range jump, not a wall
constexpr double kMinPieceLength = 0.05;  // m
// Every 10th scan is plenty: consecutive scans see the same walls.
constexpr std::size_t kScanStride = 10;

double wrapQuarter(double a) {  // to (-pi/4, pi/4]
    while (a <= -M_PI / 4)
        a += M_PI / 2;
    while (a > M_PI / 4)
        a -= M_PI / 2;
    return a;
}

template <typename Visitor>
void forEachWallPiece(const std::vector<PosedScan>& scans, Visitor&& visit) {
    for (std::size_t s = 0; s < scans.size(); s += kScanStride) {
        const auto& scan = *scans[s].scan;
        const mrpt::poses::CPose2D sensor =
            scans[s].robotPose + mrpt::poses::CPose2D(scan.sensorPose);
        const std::size_t n = scan.getScanSize();
        for (std::size_t i = 0; i + kPieceBeams < n; ++i) {
            const std::size_t j = i + kPieceBeams;
            if (!scan.getScanRangeValidity(i) || !scan.getScanRangeValidity(j))
                continue;
            const double ri = scan.getScanRange(i), rj = scan.getScanRange(j);
            const double ai = scan.getScanAngle(i), aj = scan.getScanAngle(j);
            const double dx = rj * std::cos(aj) - ri * std::cos(ai);
            const double dy = rj * std::sin(aj) - ri * std::sin(ai);
            const double len = std::hypot(dx, dy);
            if (len < kMinPieceLength || len > kMaxPieceLength)
                continue;
            visit(std::atan2(dy, dx) + sensor.phi());
        }
    }
}

}  // namespace

std::optional<WallDirection> estimateWallDirection(const std::vector<PosedScan>& scans) {
    // Directions modulo 90 deg: a unit vector at 4x the angle makes 0, 90, 180, 270 deg agree.
    std::complex<double> sum;
    std::size_t count = 0;
    forEachWallPiece(scans, [&](double a) {
        sum += std::polar(1.0, 4 * a);
        ++count;
    });
    if (count == 0)
        return std::nullopt;
    const double first = wrapQuarter(std::arg(sum) / 4);

    std::complex<double> inliers;
    forEachWallPiece(scans, [&](double a) {
        if (std::abs(wrapQuarter(a - first)) < 10 * M_PI / 180)
            inliers += std::polar(1.0, 4 * a);
    });
    WallDirection result;
    result.angle = std::abs(inliers) > 0 ? wrapQuarter(std::arg(inliers) / 4) : first;
    result.strength = std::abs(sum) / static_cast<double>(count);
    return result;
}

}  // namespace toposlam::mapping
