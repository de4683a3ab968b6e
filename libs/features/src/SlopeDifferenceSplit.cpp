#include <toposlam/features/SlopeDifferenceSplit.h>

#include <algorithm>
#include <cmath>

namespace toposlam::features {

namespace {

/// Paper rules within one run.
void splitRunPaper(const ScanPoints& pts, const PointRun& run, const SlopeDifference& sd,
                   double dkTh, std::vector<LinePart>& parts) {
    const auto& num = sd.numerator;                    // the paper's form: scale 1, numerator = dk
    const auto breakpointAfter = [&](std::size_t i) {  // between i and i+1
        return i + 1 <= run.end && sd.defined(i) && sd.defined(i + 1) && sd.exceeds(i, dkTh) &&
               sd.exceeds(i + 1, dkTh) && num[i] * num[i + 1] < 0;
    };
    LinePart cur;
    cur.begin = run.begin;
    cur.beginType = run.beginType;
    for (std::size_t i = run.begin + 1; i < run.end; ++i) {
        if (breakpointAfter(i)) {
            const bool thisNearer = pts.range(i) < pts.range(i + 1);
            cur.end = static_cast<std::uint32_t>(i);
            cur.endType = thisNearer ? EndpointType::Jump : EndpointType::Open;
            parts.push_back(cur);
            cur = LinePart();
            cur.begin = static_cast<std::uint32_t>(i + 1);
            cur.beginType = thisNearer ? EndpointType::Open : EndpointType::Jump;
            continue;
        }
        if (breakpointAfter(i - 1))
            continue;  // i starts a line after a breakpoint
        const bool peak = sd.exceeds(i, sd.threshold[i]) &&
                          (!sd.defined(i - 1) || sd.stronger(i, i - 1)) &&
                          (!sd.defined(i + 1) || sd.stronger(i, i + 1));
        if (peak) {
            cur.end = static_cast<std::uint32_t>(i);
            cur.cornerAfter = true;
            cur.joint = static_cast<std::uint32_t>(i);
            parts.push_back(cur);
            cur = LinePart();
            cur.begin = static_cast<std::uint32_t>(i);
        }
    }
    cur.end = run.end;
    cur.endType = run.endType;
    parts.push_back(cur);
}

/// Robust rules within one run: the largest |dk| of each same-sign stretch of consecutive
/// readings above threshold is a candidate; of candidates closer than their baselines (their dk
/// bumps overlap, so they cannot be told apart) only the strongest stays. Only the readings
/// above threshold (sd.above, ascending) are visited. `next`: position in sd.above.
void splitRunRobust(const PointRun& run, const SlopeDifference& sd, std::size_t& next,
                    std::vector<LinePart>& parts, std::vector<std::uint32_t>& peaks) {
    const auto& num = sd.numerator;  // scale > 0: its sign is dk's
    const auto& above = sd.above;
    peaks.clear();
    while (next < above.size() && above[next] <= run.begin)
        ++next;
    while (next < above.size() && above[next] < run.end) {
        const std::size_t first = above[next];
        const bool positive = num[first] > 0;
        std::size_t best = first, last = first;
        for (++next; next < above.size() && above[next] == last + 1 && above[next] < run.end &&
                     (num[above[next]] > 0) == positive;
             ++next) {
            last = above[next];
            if (sd.stronger(last, best))
                best = last;
        }
        // Non-maximum suppression against the peaks kept so far (a stack: a new strong peak
        // may knock out several weaker ones before it).
        bool keep = true;
        while (!peaks.empty()) {
            const std::uint32_t last = peaks.back();
            const std::size_t window = std::max(sd.baseline[last], sd.baseline[best]);
            if (best - last >= window)
                break;
            if (!sd.stronger(best, last)) {
                keep = false;
                break;
            }
            peaks.pop_back();
        }
        if (keep)
            peaks.push_back(static_cast<std::uint32_t>(best));
    }
    LinePart cur;
    cur.begin = run.begin;
    cur.beginType = run.beginType;
    for (const std::uint32_t q : peaks) {
        cur.end = q;
        cur.cornerAfter = true;
        cur.joint = q;
        cur.minSize = std::max(cur.minSize, sd.baseline[q]);
        parts.push_back(cur);
        cur = LinePart();
        cur.begin = q;
        cur.minSize = sd.baseline[q];
    }
    cur.end = run.end;
    cur.endType = run.endType;
    parts.push_back(cur);
}

}  // namespace

void splitBySlopeDifference(const ScanPoints& pts, const std::vector<PointRun>& runs,
                            const SlopeDifference& sd, double dkThreshold, bool paperRules,
                            std::vector<LinePart>& parts, std::vector<std::uint32_t>& workspace) {
    parts.clear();
    std::size_t next = 0;
    for (const PointRun& run : runs) {
        if (paperRules) {
            splitRunPaper(pts, run, sd, dkThreshold, parts);
        } else {
            splitRunRobust(run, sd, next, parts, workspace);
        }
    }
}

}  // namespace toposlam::features
