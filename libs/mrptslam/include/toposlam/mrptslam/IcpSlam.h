#pragma once
// Incremental laser SLAM front end on MRPT's CMetricMapBuilderICP (the engine of MRPT's
// icp-slam): every scan is aligned by ICP against the map accumulated so far, starting from
// the odometry prediction, and inserted as a keyframe when the robot moved far enough.
// Configured with the same .ini keys as icp-slam ([MappingApplication] and [ICP]), so
// existing icp-slam configurations work unchanged. toposlam-slam's engine = icp, loaded at
// run time by mapping::loadIcpEngine() through toposlam_mrptslam_make_icp_engine (below).
#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/slam/CMetricMapBuilderICP.h>
#include <toposlam/mapping/IcpEngine.h>

#include <string>

namespace toposlam::mrptslam {

class IcpSlam : public mapping::IcpEngine {
  public:
    /// Reads CMetricMapBuilderICP::TConfigParams (incl. the map definitions) from
    /// `mappingSection` and CICP::TConfigParams from `icpSection` of `ini`. MRPT reads them
    /// unchecked: a value that is no number or out of range (maxIterations = -5) is a
    /// config::ConfigError naming the file, the section, the key and the value as written.
    explicit IcpSlam(const mrpt::config::CConfigFileBase& ini,
                     const std::string& mappingSection = kMappingSection,
                     const std::string& icpSection = kIcpSection);
    /// Feeds one scan with its odometry; returns the robot pose estimate at the scan
    /// (map frame = the odometry frame at the first scan; m, rad).
    mrpt::poses::CPose2D process(const io::LaserLogRecord& record) override;

    const mrpt::slam::CMetricMapBuilderICP& builder() const { return builder_; }

  private:
    mrpt::slam::CMetricMapBuilderICP builder_;
};

}  // namespace toposlam::mrptslam
