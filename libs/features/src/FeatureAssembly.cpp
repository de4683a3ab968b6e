#include <mrpt/config/CConfigFileBase.h>
#include <toposlam/features/CornerIntersection.h>
#include <toposlam/features/FeatureAssembly.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <stdexcept>

namespace toposlam::features {

using mrpt::math::TPoint2D;

void FeatureAssemblyOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                                const std::string& section) {
    const std::string fit = cfg.read_string(
        section, "line_fit", lineFit == LineFitMethod::TwoPoint ? "two_point" : "least_squares");
    if (fit == "two_point") {
        lineFit = LineFitMethod::TwoPoint;
    } else if (fit == "least_squares") {
        lineFit = LineFitMethod::LeastSquares;
    } else {
        throw std::invalid_argument("[" + section + "] line_fit = '" + fit +
                                    "': expected two_point or least_squares");
    }
    minSegmentPoints = static_cast<unsigned>(
        cfg.read_int(section, "min_segment_points", static_cast<int>(minSegmentPoints)));
    minSegmentLength = cfg.read_double(section, "min_segment_length", minSegmentLength);
    maxCornerOffset = cfg.read_double(section, "max_corner_offset", maxCornerOffset);
    maxLineResidual = cfg.read_double(section, "max_line_residual", maxLineResidual);
    residualSigmas = cfg.read_double(section, "residual_sigmas", residualSigmas);
    rejectArcs = cfg.read_bool(section, "reject_arcs", rejectArcs);
    maxArcRadius = cfg.read_double(section, "max_arc_radius", maxArcRadius);
}

void FeatureAssemblyOptions::dumpToTextStream(std::ostream& out) const {
    out << "line_fit           = "
        << (lineFit == LineFitMethod::TwoPoint ? "two_point" : "least_squares") << "\n"
        << "min_segment_points = " << minSegmentPoints << "\n"
        << "min_segment_length = " << minSegmentLength << "  (m)\n"
        << "max_corner_offset  = " << maxCornerOffset << "  (m)\n"
        << "min_corner_turn    = " << minCornerTurn << "  (rad)\n"
        << "max_line_residual  = " << maxLineResidual << "  (m)\n"
        << "residual_sigmas    = " << residualSigmas << "\n"
        << "reject_arcs        = " << rejectArcs << "\n"
        << "max_arc_radius     = " << maxArcRadius << "  (m)\n";
}

void FeatureAssembly::assemble(ScanPoints& pts, std::vector<LinePart>& parts, double sigma,
                               ScanFeatures& out) {
    out.clear();

    // Jumps, before short parts vanish.
    for (const LinePart& p : parts) {
        if (p.beginType == EndpointType::Jump) {
            out.endpoints.push_back({pts.point(p.begin), EndpointType::Jump, p.begin});
        }
        if (p.endType == EndpointType::Jump) {
            out.endpoints.push_back({pts.point(p.end), EndpointType::Jump, p.end});
        }
    }

    // Drop very short parts; join the neighbours of one that sat between two corners.
    const auto tooShort = [&](const LinePart& p) {
        if (p.size() < std::max(2u, options.minSegmentPoints))
            return true;
        if (options.minSegmentLength <= 0)
            return false;
        return std::hypot(pts.x(p.end) - pts.x(p.begin), pts.y(p.end) - pts.y(p.begin)) <
               options.minSegmentLength;
    };
    std::size_t kept = 0;
    bool prevJoined = false;  // the last kept part is joined to the part being looked at
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const LinePart p = parts[i];
        if (!tooShort(p)) {
            parts[kept++] = p;
            prevJoined = p.cornerAfter;
            continue;
        }
        if (kept > 0 && prevJoined) {
            LinePart& prev = parts[kept - 1];
            if (p.cornerAfter) {
                prev.joint = (p.begin + p.end) / 2;  // the corner is around the short part
            } else {
                prev.cornerAfter = false;
                prev.endType = EndpointType::Open;
                prevJoined = false;
            }
        } else {
            prevJoined = false;
        }
    }
    parts.resize(kept);
    if (kept > 0 && parts[kept - 1].cornerAfter)
        parts[kept - 1].cornerAfter = false;

    // Step 4: fit each part.
    fits_.resize(kept);
    for (std::size_t i = 0; i < kept; ++i) {
        const LinePart& p = parts[i];
        fits_[i] = fitLine(options.lineFit, pts, p.begin, p.end);
        LineSegment s;
        s.line = fits_[i].line;
        s.start = s.line.project(pts.point(p.begin));
        s.end = s.line.project(pts.point(p.end));
        s.firstBeam = p.begin;
        s.lastBeam = p.end;
        s.startType = p.beginType;
        s.endType = p.endType;
        s.residualRms = fits_[i].residualRms;
        out.segments.push_back(s);
    }

    // Step 5: corners at the joints.
    const double lineTolerance = std::max(options.maxLineResidual, options.residualSigmas * sigma);
    ArcCornerTest arcTest;
    arcTest.maxRadius = options.maxArcRadius;
    for (std::size_t i = 0; i + 1 < kept; ++i) {
        if (!parts[i].cornerAfter)
            continue;
        LineSegment &a = out.segments[i], &b = out.segments[i + 1];
        Corner c;
        const bool ok = fits_[i].ok && fits_[i + 1].ok &&
                        intersectCorner(fits_[i], fits_[i + 1], a.start, b.end, sigma, c);
        const TPoint2D joint = pts.point(parts[i].joint);
        const auto isArc = [&] {
            const double na = fits_[i].count, nb = fits_[i + 1].count;
            const double ra = fits_[i].residualRms, rb = fits_[i + 1].residualRms;
            const double lineRms = std::sqrt((na * ra * ra + nb * rb * rb) / (na + nb));
            return arcTest.isArc(pts, parts[i].begin, parts[i].end, parts[i + 1].begin,
                                 parts[i + 1].end, lineRms);
        };
        if (!ok || M_PI - c.angle < options.minCornerTurn || c.angle < options.minCornerTurn ||
            fits_[i].residualRms > lineTolerance || fits_[i + 1].residualRms > lineTolerance ||
            std::hypot(c.position.x - joint.x, c.position.y - joint.y) > options.maxCornerOffset ||
            (options.rejectArcs && isArc())) {
            a.endType = EndpointType::Open;
            b.startType = EndpointType::Open;
            continue;
        }
        c.beam = parts[i].joint;
        c.segmentBefore = static_cast<std::uint32_t>(i);
        c.segmentAfter = static_cast<std::uint32_t>(i + 1);
        a.endType = c.type;
        b.startType = c.type;
        out.corners.push_back(c);
        out.endpoints.push_back({c.position, c.type, c.beam});
    }
    std::sort(out.endpoints.begin(), out.endpoints.end(),
              [](const Endpoint& x, const Endpoint& y) { return x.beam < y.beam; });
    pts.toScanOrder(out);
}

}  // namespace toposlam::features
