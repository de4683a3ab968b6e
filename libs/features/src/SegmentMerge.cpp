#include <toposlam/features/SegmentMerge.h>

#include <algorithm>
#include <cmath>

namespace toposlam::features {

bool chordsAlmostParallel(const ScanPoints& pts, const LinePart& a, const LinePart& b,
                          double thetaThreshold) {
    const double ax = pts.x(a.end) - pts.x(a.begin), ay = pts.y(a.end) - pts.y(a.begin);
    const double bx = pts.x(b.end) - pts.x(b.begin), by = pts.y(b.end) - pts.y(b.begin);
    const double dot = ax * bx + ay * by, cross = ax * by - ay * bx;
    return dot > 0 && std::abs(cross) < thetaThreshold * dot;
}

void mergeSegments(const ScanPoints& pts, double thetaThreshold, std::vector<LinePart>& parts) {
    if (parts.empty())
        return;
    std::size_t out = 0;  // parts[0..out] is the merged list so far
    for (std::size_t i = 1; i < parts.size(); ++i) {
        LinePart& last = parts[out];
        if (last.cornerAfter && chordsAlmostParallel(pts, last, parts[i], thetaThreshold)) {
            last.end = parts[i].end;
            last.cornerAfter = parts[i].cornerAfter;
            last.joint = parts[i].joint;
            last.endType = parts[i].endType;
            last.minSize = std::max(last.minSize, parts[i].minSize);
        } else {
            parts[++out] = parts[i];
        }
    }
    parts.resize(out + 1);
}

}  // namespace toposlam::features
