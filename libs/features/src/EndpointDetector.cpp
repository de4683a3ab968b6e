#include <toposlam/features/EndpointDetector.h>

#include <cmath>

namespace toposlam::features {

void detectEndpoints(const ScanPoints& pts, const std::vector<PointRun>& runs,
                     const TurningAngle& turning, double threshold, std::vector<Endpoint>& out) {
    out.clear();
    const auto& turn = turning.windowTurn;
    const auto passes = [&](std::size_t k) {
        return turning.defined[k] && std::abs(turn[k]) > threshold;
    };
    for (const PointRun& run : runs) {
        if (run.beginType == EndpointType::Jump) {
            out.push_back({pts.point(run.begin), EndpointType::Jump, run.begin});
        }
        std::size_t k = run.begin;
        while (k <= run.end) {
            if (!passes(k)) {
                ++k;
                continue;
            }
            const bool concave = turn[k] > 0;
            std::size_t best = k;
            for (; k <= run.end && passes(k) && (turn[k] > 0) == concave; ++k) {
                if (std::abs(turn[k]) > std::abs(turn[best]))
                    best = k;
            }
            // A jump reading is already an endpoint; do not list it twice.
            const bool atJumpEnd = (best == run.begin && run.beginType == EndpointType::Jump) ||
                                   (best == run.end && run.endType == EndpointType::Jump);
            if (!atJumpEnd) {
                out.push_back({pts.point(best),
                               concave ? EndpointType::Concave : EndpointType::Convex,
                               static_cast<std::uint32_t>(best)});
            }
        }
        // (A one-reading run that is a jump on both sides is listed once.)
        const bool listedAsBegin = run.end == run.begin && run.beginType == EndpointType::Jump;
        if (run.endType == EndpointType::Jump && !listedAsBegin) {
            out.push_back({pts.point(run.end), EndpointType::Jump, run.end});
        }
    }
}

}  // namespace toposlam::features
