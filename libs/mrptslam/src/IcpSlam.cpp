#include <mrpt/config/CConfigFile.h>
#include <mrpt/core/bits_math.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/poses/CPose3DPDF.h>
#include <toposlam/config/ConfigError.h>
#include <toposlam/config/IniFile.h>
#include <toposlam/config/Options.h>
#include <toposlam/mrptslam/IcpSlam.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>

namespace toposlam::mrptslam {

namespace {

// MRPT reads these sections unchecked: maxIterations = -5 becomes 4294967291 iterations (a run
// that never ends), a threshold of 0 or "abc" (read as 0) matches nothing. Checked here as
// written, naming the file, the section and the key.
class IcpKeyCheck {
  public:
    IcpKeyCheck(const mrpt::config::CConfigFileBase& ini, std::string section)
        : ini_(ini), section_(std::move(section)) {}
    /// `value`: as MRPT read it, in the unit of `min` and `max` (a key written in degrees is
    /// checked in degrees).
    void inRange(const char* key, double value, double min, double max, bool excludeMin) const {
        // Text that is no number is an error of its own (MRPT read it as 0).
        const std::optional<config::WrittenNumber> written =
            config::readWrittenNumber(ini_, section_, key);
        // A hair of slack at the top: 360 degrees read and converted back may exceed 360.
        const bool ok = std::isfinite(value) && (excludeMin ? value > min : value >= min) &&
                        value <= max + 1e-9 * std::max(1.0, std::abs(max));
        if (ok)
            return;
        std::ostringstream text, range;
        text.precision(12);
        range.precision(12);
        if (written)
            text << written->text;
        else
            text << value;
        range << "out of range: a number in " << (excludeMin ? "(" : "[") << min << ", " << max
              << "]";
        throw config::ConfigError(config::configFileName(ini_), section_, key, text.str(),
                                  range.str());
    }

  private:
    const mrpt::config::CConfigFileBase& ini_;
    std::string section_;
};

void checkIcpKeys(const mrpt::config::CConfigFileBase& ini, const std::string& mappingSection,
                  const std::string& icpSection, const mrpt::slam::CMetricMapBuilderICP& b) {
    const IcpKeyCheck icp(ini, icpSection), mapping(ini, mappingSection);
    const auto& p = b.ICP_params;
    icp.inRange("maxIterations", p.maxIterations, 1, 100000, false);
    icp.inRange("thresholdDist", p.thresholdDist, 0, 1000, true);
    // Keys MRPT reads in degrees are checked (and reported) in degrees.
    icp.inRange("thresholdAng_DEG", mrpt::RAD2DEG(p.thresholdAng), 0, 180, false);
    icp.inRange("ALFA", p.ALFA, 0, 1, true);
    icp.inRange("smallestThresholdDist", p.smallestThresholdDist, 0, 1000, true);
    icp.inRange("minAbsStep_trans", p.minAbsStep_trans, 0, 1000, false);
    icp.inRange("minAbsStep_rot", p.minAbsStep_rot, 0, M_PI, false);
    icp.inRange("corresponding_points_decimation", p.corresponding_points_decimation, 1, 100000,
                false);
    const auto& o = b.ICP_options;
    mapping.inRange("insertionLinDistance", o.insertionLinDistance, 0, 1000, false);
    mapping.inRange("insertionAngDistance", mrpt::RAD2DEG(o.insertionAngDistance), 0, 360, false);
    mapping.inRange("localizationLinDistance", o.localizationLinDistance, 0, 1000, false);
    mapping.inRange("localizationAngDistance", mrpt::RAD2DEG(o.localizationAngDistance), 0, 360,
                    false);
    mapping.inRange("minICPgoodnessToAccept", o.minICPgoodnessToAccept, 0, 1, false);
}

// Without the map it matches scans against, MRPT's builder fails on the first scan with an
// assertion and a backtrace: said here instead, naming the sections it reads.
void requireMatchingMap(const mrpt::config::CConfigFileBase& ini, const std::string& mappingSection,
                        const mrpt::slam::CMetricMapBuilderICP::TConfigParams& options) {
    bool points = false, grid = false;
    for (const auto& map : options.mapInitializers) {
        const std::string name = map->getMetricMapClassType()->className;
        points = points || name == "mrpt::maps::CSimplePointsMap";
        grid = grid || name == "mrpt::maps::COccupancyGridMap2D";
    }
    if (points || (grid && options.matchAgainstTheGrid))
        return;
    const std::string s = "[" + mappingSection;
    throw config::ConfigError(
        config::configFileName(ini), mappingSection, "", "",
        std::string("engine = icp has no map to match scans against") +
            (grid ? " (an occupancy grid, but matchAgainstTheGrid = 0)" : "") +
            ": MRPT's map definitions need pointsMap_count = 1 here and a " + s +
            "_pointsMap_00_insertOpts] section (or occupancyGrid_count = 1, " + s +
            "_occupancyGrid_00_creationOpts] and matchAgainstTheGrid = 1), as in "
            "config_ini/toposlam-slam.ini");
}

}  // namespace

IcpSlam::IcpSlam(const mrpt::config::CConfigFileBase& ini, const std::string& mappingSection,
                 const std::string& icpSection) {
    // icp-slam's key; the default keeps MRPT's per-scan warnings ("low quality ICP") quiet.
    builder_.setVerbosityLevel(ini.read_enum<mrpt::system::VerbosityLevel>(
        mappingSection, "verbosity", mrpt::system::LVL_ERROR));
    builder_.ICP_options.loadFromConfigFile(ini, mappingSection);
    builder_.ICP_params.loadFromConfigFile(ini, icpSection);
    checkIcpKeys(ini, mappingSection, icpSection, builder_);
    requireMatchingMap(ini, mappingSection, builder_.ICP_options);
    builder_.initialize();  // builds the maps listed in the ini; throws if there is none usable
}

mrpt::poses::CPose2D IcpSlam::process(const io::LaserLogRecord& record) {
    // The builder predicts each scan's pose from the odometry increment since the last one.
    if (record.hasOdometry)
        builder_.processObservation(record.odometryObservation());
    builder_.processObservation(record.scan);
    mrpt::poses::CPose3D pose;
    builder_.getCurrentPoseEstimation()->getMean(pose);
    return mrpt::poses::CPose2D(pose);
}

}  // namespace toposlam::mrptslam

/// mapping::loadIcpEngine()'s entry point (mapping::kIcpEngineFactorySymbol).
extern "C" toposlam::mapping::IcpEngine* toposlam_mrptslam_make_icp_engine(
    const mrpt::config::CConfigFileBase& ini) {
    return new toposlam::mrptslam::IcpSlam(ini);
}
