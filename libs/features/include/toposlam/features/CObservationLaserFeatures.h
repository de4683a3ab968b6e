#pragma once
// The features of one laser scan as an MRPT observation, so they travel in rawlogs beside the
// scan they came from: rawlog-edit, RawLogViewer (text view) and every CRawlog reader handle
// it once libtoposlam-features.so (or the plugin, libtoposlam-plugin.so) is loaded.
//
// A separate class, not a subclass of CObservation2DRangeScan: MRPT matches classes exactly
// (IS_CLASS), so a derived scan would be ignored by grid maps, ICP and viewers. Registered
// with mrpt-rtti when the library is loaded (a static initialiser), under the name
// "toposlam::features::CObservationLaserFeatures".
//
// Geometry in `features` is in the SENSOR frame; sensorPose is the sensor on the robot.
#include <mrpt/obs/CObservation.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/serialization/CSerializable.h>
#include <toposlam/features/ScanFeatures.h>

#include <string>

namespace toposlam::features {

class CObservationLaserFeatures : public mrpt::obs::CObservation {
    DEFINE_SERIALIZABLE(CObservationLaserFeatures, toposlam::features)

  public:
    ScanFeatures features;            ///< sensor frame
    mrpt::poses::CPose3D sensorPose;  ///< the laser on the robot (m, rad)
    std::string extractor;            ///< method that made them ("corners", "segments", ...)
    std::string scanLabel;            ///< sensorLabel of the scan they were extracted from

    /// The features in the robot frame (sensorPose (+) features; planar part of the pose).
    ScanFeatures robotFrameFeatures() const;

    void getSensorPose(mrpt::poses::CPose3D& out) const override { out = sensorPose; }
    void setSensorPose(const mrpt::poses::CPose3D& p) override { sensorPose = p; }
    /// Counts and every feature, one per line (RawLogViewer, rawlog-edit --describe).
    void getDescriptionAsText(std::ostream& o) const override;
};

}  // namespace toposlam::features
