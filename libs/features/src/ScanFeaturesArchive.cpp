#include <toposlam/features/ScanFeaturesArchive.h>

#include <cstdint>
#include <stdexcept>
#include <string>

namespace toposlam::features {

using mrpt::serialization::CArchive;

namespace {

void writePoint(CArchive& out, const mrpt::math::TPoint2D& p) {
    out << p.x << p.y;
}
void readPoint(CArchive& in, mrpt::math::TPoint2D& p) {
    in >> p.x >> p.y;
}
void writeType(CArchive& out, EndpointType t) {
    out << static_cast<std::uint8_t>(t);
}
void readType(CArchive& in, EndpointType& t) {
    std::uint8_t v = 0;
    in >> v;
    if (v > static_cast<std::uint8_t>(EndpointType::Open))
        throw std::runtime_error("scan features: bad endpoint type " + std::to_string(v));
    t = static_cast<EndpointType>(v);
}

/// A list size read from a file: a corrupt or hostile count must not allocate gigabytes. No
/// 2D scan has anywhere near this many features (one per beam at most).
std::uint32_t readCount(CArchive& in, const char* what) {
    constexpr std::uint32_t kMaxCount = 1u << 16;
    std::uint32_t n = 0;
    in >> n;
    if (n > kMaxCount)
        throw std::runtime_error(std::string("scan features: implausible number of ") + what +
                                 " (" + std::to_string(n) + ")");
    return n;
}

}  // namespace

void writeScanFeatures(CArchive& out, const ScanFeatures& features) {
    out << static_cast<std::uint32_t>(features.segments.size());
    for (const LineSegment& s : features.segments) {
        writePoint(out, s.start);
        writePoint(out, s.end);
        out << s.line.theta << s.line.rho << s.firstBeam << s.lastBeam;
        writeType(out, s.startType);
        writeType(out, s.endType);
        out << s.residualRms;
    }
    out << static_cast<std::uint32_t>(features.corners.size());
    for (const Corner& c : features.corners) {
        writePoint(out, c.position);
        out << c.beam << c.segmentBefore << c.segmentAfter << c.angle;
        out << c.covariance(0, 0) << c.covariance(0, 1) << c.covariance(1, 1);
        writeType(out, c.type);
    }
    out << static_cast<std::uint32_t>(features.endpoints.size());
    for (const Endpoint& e : features.endpoints) {
        writePoint(out, e.position);
        writeType(out, e.type);
        out << e.beam;
    }
}

void readScanFeatures(CArchive& in, ScanFeatures& features) {
    features.segments.resize(readCount(in, "segments"));
    for (LineSegment& s : features.segments) {
        readPoint(in, s.start);
        readPoint(in, s.end);
        in >> s.line.theta >> s.line.rho >> s.firstBeam >> s.lastBeam;
        readType(in, s.startType);
        readType(in, s.endType);
        in >> s.residualRms;
    }
    features.corners.resize(readCount(in, "corners"));
    for (Corner& c : features.corners) {
        readPoint(in, c.position);
        in >> c.beam >> c.segmentBefore >> c.segmentAfter >> c.angle;
        double xx = 0, xy = 0, yy = 0;
        in >> xx >> xy >> yy;
        c.covariance(0, 0) = xx;
        c.covariance(0, 1) = c.covariance(1, 0) = xy;
        c.covariance(1, 1) = yy;
        readType(in, c.type);
        if (c.segmentBefore >= features.segments.size() ||
            c.segmentAfter >= features.segments.size()) {
            throw std::runtime_error("scan features: a corner refers to a missing segment");
        }
    }
    features.endpoints.resize(readCount(in, "endpoints"));
    for (Endpoint& e : features.endpoints) {
        readPoint(in, e.position);
        readType(in, e.type);
        in >> e.beam;
    }
}

}  // namespace toposlam::features
