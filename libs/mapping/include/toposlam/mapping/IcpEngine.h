#pragma once
// engine = icp: MRPT's ICP map builder (CMetricMapBuilderICP, the engine of icp-slam), run scan
// by scan. Its implementation (mrptslam::IcpSlam) lives in libtoposlam-mrptslam.so, which
// links libmrpt-slam and with it mrpt-vision, OpenCV's video I/O, Qt and FFmpeg: 117 more
// shared libraries whose loading takes about 0.13 s at every start of a program that links
// them. So the graph engine's programs link none of it, and loadIcpEngine() loads that
// library when engine = icp asks for it.
#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/poses/CPose2D.h>
#include <toposlam/io/LaserLogReader.h>

#include <memory>

namespace toposlam::mapping {

class IcpEngine {
  public:
    virtual ~IcpEngine() = default;
    /// Feeds one scan with its odometry; returns the robot pose estimate at the scan
    /// (map frame = the odometry frame at the first scan; m, rad).
    virtual mrpt::poses::CPose2D process(const io::LaserLogRecord& record) = 0;

    /// icp-slam's section names: CMetricMapBuilderICP's options and the map definitions
    /// ([MappingApplication]), CICP's ([ICP]).
    static constexpr const char* kMappingSection = "MappingApplication";
    static constexpr const char* kIcpSection = "ICP";
};

/// Loads libtoposlam-mrptslam.so from the directory of this library (once per process) and
/// makes its IcpSlam from `ini`'s [MappingApplication] and [ICP]. Throws std::runtime_error
/// naming the library when it cannot be loaded, config::ConfigError for a bad key.
std::unique_ptr<IcpEngine> loadIcpEngine(const mrpt::config::CConfigFileBase& ini);

/// The name of the entry point loadIcpEngine() calls in libtoposlam-mrptslam.so: an
/// `IcpEngine* (const mrpt::config::CConfigFileBase&)` returning a new engine (or throwing).
constexpr const char* kIcpEngineFactorySymbol = "toposlam_mrptslam_make_icp_engine";

}  // namespace toposlam::mapping
