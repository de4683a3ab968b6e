#include <mrpt/core/format.h>
#include <mrpt/rtti/CObject.h>
#include <mrpt/serialization/CArchive.h>
#include <toposlam/features/CObservationLaserFeatures.h>
#include <toposlam/features/ScanFeaturesArchive.h>
#include <toposlam/io/ClassRegistration.h>

#include <cmath>
#include <ostream>

using namespace toposlam::features;
using mrpt::serialization::CArchive;

IMPLEMENTS_SERIALIZABLE(CObservationLaserFeatures, CObservation, toposlam::features)
TOPOSLAM_REGISTER_CLASS(CObservationLaserFeatures)

uint8_t CObservationLaserFeatures::serializeGetVersion() const {
    return 0;
}

void CObservationLaserFeatures::serializeTo(CArchive& out) const {
    // CObservation serializes nothing itself: timestamp and label are ours to write.
    out << timestamp << sensorLabel << sensorPose << extractor << scanLabel;
    writeScanFeatures(out, features);
}

void CObservationLaserFeatures::serializeFrom(CArchive& in, uint8_t version) {
    switch (version) {
        case 0: {
            in >> timestamp >> sensorLabel >> sensorPose >> extractor >> scanLabel;
            readScanFeatures(in, features);
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
