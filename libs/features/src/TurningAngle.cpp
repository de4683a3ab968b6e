#include <toposlam/features/TurningAngle.h>

#include <algorithm>
#include <cmath>

namespace toposlam::features {

double turnBetween(double ax, double ay, double bx, double by) {
    return std::atan2(ax * by - ay * bx, ax * bx + ay * by);
}

void TurningAngle::compute(const ScanPoints& pts, const std::vector<PointRun>& runs, bool paperForm,
                           double sigma, double z, double threshold) {
    const std::size_t n = pts.size();
    windowTurn.assign(n, 0.0);
    defined.assign(n, 0);
    if (paperForm) {
        // theta_i for every interior reading of a run, then the 4-tap box sum.
        single_.assign(n, 0.0);
        for (const PointRun& run : runs) {
            for (std::size_t i = run.begin + 1; i < run.end; ++i) {
                single_[i] = turnBetween(pts.x(i) - pts.x(i - 1), pts.y(i) - pts.y(i - 1),
                                         pts.x(i + 1) - pts.x(i), pts.y(i + 1) - pts.y(i));
            }
            for (std::size_t i = run.begin + 2; i + 3 <= run.end; ++i) {
                windowTurn[i] = single_[i - 1] + single_[i] + single_[i + 1] + single_[i + 2];
                defined[i] = 1;
            }
        }
        return;
    }
    // Chord form. Minimum chord for the noise budget (and at least one beam).
    const double step = pts.angularStep();
    if (!(step > 0))
        return;
    const double chord = z * 2.0 * sigma / threshold;
    // |turn| > threshold <=> |cross| cos(threshold) > dot sin(threshold): atan2 only then.
    const double cosT = std::cos(threshold), sinT = std::sin(threshold);
    for (const PointRun& run : runs) {
        for (std::size_t i = run.begin + 2; i + 2 <= run.end; ++i) {
            const double r = pts.range(i);
            const double wanted = std::max(1.0, std::ceil(chord / (r * step)));
            const std::size_t room = std::min(i - 1 - run.begin, run.end - i - 1);
            const std::size_t s =
                std::min<std::size_t>(room, static_cast<std::size_t>(std::min(wanted, 1e6)));
            if (s < 1 || static_cast<double>(s) < wanted)
                continue;  // chords too short here
            const std::size_t a = i - 1 - s, b = i - 1, c = i + 1, d = i + 1 + s;
            const double ax = pts.x(b) - pts.x(a), ay = pts.y(b) - pts.y(a);
            const double bx = pts.x(d) - pts.x(c), by = pts.y(d) - pts.y(c);
            const double cross = ax * by - ay * bx, dot = ax * bx + ay * by;
            windowTurn[i] = std::abs(cross) * cosT > dot * sinT ? std::atan2(cross, dot) : 0.0;
            defined[i] = 1;
        }
    }
}

}  // namespace toposlam::features
