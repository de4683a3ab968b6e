#include <mrpt/core/format.h>
#include <mrpt/core/initializer.h>
#include <mrpt/rtti/CObject.h>
#include <mrpt/serialization/CArchive.h>
#include <toposlam/features/CObservationLaserFeatures.h>

#include <cmath>
#include <ostream>

using namespace toposlam::features;
using mrpt::serialization::CArchive;

IMPLEMENTS_SERIALIZABLE(CObservationLaserFeatures, CObservation, toposlam::features)

// Registration: loading the library (directly, via the plugin or LD_PRELOAD) makes the class
// known to every MRPT reader.
MRPT_INITIALIZER(toposlam_features_register_classes) {
    mrpt::rtti::registerClass(CLASS_ID(CObservationLaserFeatures));
}

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
    if (v > static_cast<std::uint8_t>(EndpointType::Open)) {
        throw std::runtime_error("CObservationLaserFeatures: bad endpoint type " +
                                 std::to_string(v));
    }
    t = static_cast<EndpointType>(v);
}

}  // namespace

uint8_t CObservationLaserFeatures::serializeGetVersion() const {
    return 0;
}

void CObservationLaserFeatures::serializeTo(CArchive& out) const {
    // CObservation serializes nothing itself: timestamp and label are ours to write.
    out << timestamp << sensorLabel << sensorPose << extractor << scanLabel;
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

void CObservationLaserFeatures::serializeFrom(CArchive& in, uint8_t version) {
    switch (version) {
        case 0: {
            in >> timestamp >> sensorLabel >> sensorPose >> extractor >> scanLabel;
            std::uint32_t n = 0;
            in >> n;
            features.segments.resize(n);
            for (LineSegment& s : features.segments) {
                readPoint(in, s.start);
                readPoint(in, s.end);
                in >> s.line.theta >> s.line.rho >> s.firstBeam >> s.lastBeam;
                readType(in, s.startType);
                readType(in, s.endType);
                in >> s.residualRms;
            }
            in >> n;
            features.corners.resize(n);
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
                    throw std::runtime_error(
                        "CObservationLaserFeatures: corner refers to a missing segment");
                }
            }
            in >> n;
            features.endpoints.resize(n);
            for (Endpoint& e : features.endpoints) {
                readPoint(in, e.position);
                readType(in, e.type);
                in >> e.beam;
            }
        } break;
        default:
            MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
    }
}

ScanFeatures CObservationLaserFeatures::robotFrameFeatures() const {
    return features.transformed(
        mrpt::poses::CPose2D(sensorPose.x(), sensorPose.y(), sensorPose.yaw()));
}

void CObservationLaserFeatures::getDescriptionAsText(std::ostream& o) const {
    CObservation::getDescriptionAsText(o);
    constexpr double deg = 180.0 / M_PI;
    o << "TopoSLAM laser features, extracted by '" << extractor << "' from scan '" << scanLabel
      << "'\n"
      << "Sensor pose on the robot: " << sensorPose.asString() << "\n"
      << "Frame: sensor (x forward, y left; m, deg)\n\n";
    o << "Segments: " << features.segments.size() << "\n";
    for (std::size_t i = 0; i < features.segments.size(); ++i) {
        const LineSegment& s = features.segments[i];
        o << mrpt::format(
            "  [%3zu] beams %4u-%-4u (%7.3f,%7.3f) -> (%7.3f,%7.3f)  length %6.3f  "
            "theta %7.2f rho %6.3f  %s/%s  rms %.4f\n",
            i, s.firstBeam, s.lastBeam, s.start.x, s.start.y, s.end.x, s.end.y, s.length(),
            s.line.theta * deg, s.line.rho, toString(s.startType), toString(s.endType),
            s.residualRms);
    }
    o << "Corners: " << features.corners.size() << "\n";
    for (std::size_t i = 0; i < features.corners.size(); ++i) {
        const Corner& c = features.corners[i];
        o << mrpt::format(
            "  [%3zu] beam %4u (%7.3f,%7.3f)  angle %6.2f  %-7s  std (%.4f, %.4f)  segments "
            "%u-%u\n",
            i, c.beam, c.position.x, c.position.y, c.angle * deg, toString(c.type),
            std::sqrt(c.covariance(0, 0)), std::sqrt(c.covariance(1, 1)), c.segmentBefore,
            c.segmentAfter);
    }
    o << "Endpoints: " << features.endpoints.size() << "\n";
    for (std::size_t i = 0; i < features.endpoints.size(); ++i) {
        const Endpoint& e = features.endpoints[i];
        o << mrpt::format("  [%3zu] beam %4u (%7.3f,%7.3f)  %s\n", i, e.beam, e.position.x,
                          e.position.y, toString(e.type));
    }
}
