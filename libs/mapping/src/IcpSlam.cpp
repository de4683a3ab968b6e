#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/poses/CPose3DPDF.h>
#include <toposlam/mapping/IcpSlam.h>

namespace toposlam::mapping {

IcpSlam::IcpSlam(const mrpt::config::CConfigFileBase& ini, const std::string& mappingSection,
                 const std::string& icpSection) {
    // icp-slam's key; the default keeps MRPT's per-scan warnings ("low quality ICP") quiet.
    builder_.setVerbosityLevel(ini.read_enum<mrpt::system::VerbosityLevel>(
        mappingSection, "verbosity", mrpt::system::LVL_ERROR));
    builder_.ICP_options.loadFromConfigFile(ini, mappingSection);
    builder_.ICP_params.loadFromConfigFile(ini, icpSection);
    builder_.initialize();  // builds the maps listed in the ini; throws if there is none usable
}

mrpt::poses::CPose2D IcpSlam::process(const io::LaserLogRecord& record) {
    if (record.hasOdometry) {
        // The builder predicts each scan's pose from the odometry increment since the last one.
        auto odometry = mrpt::obs::CObservationOdometry::Create();
        odometry->odometry = record.odometry;
        odometry->timestamp = record.scan->timestamp;
        odometry->sensorLabel = "ODOMETRY";
        builder_.processObservation(odometry);
    }
    builder_.processObservation(record.scan);
    mrpt::poses::CPose3D pose;
    builder_.getCurrentPoseEstimation()->getMean(pose);
    return mrpt::poses::CPose2D(pose);
}

}  // namespace toposlam::mapping
