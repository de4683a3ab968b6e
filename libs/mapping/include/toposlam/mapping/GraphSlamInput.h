#pragma once
// MRPT observations into TopoSLAM's graph SLAM (GraphSlam), one at a time, as a rawlog holds
// them: odometry (CObservationOdometry, cumulative; or increments from a rawlog's actions),
// a scan's features (CObservationLaserFeatures, used instead of extracting them again when
// they are that scan's) and the scans (CObservation2DRangeScan). It maps one laser: the scans
// of the first sensor label it is given; those of other lasers are counted and left out (their
// odometry still counts), since each scan is registered against the keyframes before it.
//
// What toposlam-slam runs (LogMapper), and what CGraphSlamBuilder (libs/mrptslam) wraps as
// an MRPT map builder; it links no libmrpt-slam, so programs that map with it start without
// the 117 libraries that one pulls in (mrpt-vision, OpenCV's video I/O, Qt, FFmpeg).
//
// Configuration (loadFromConfigFile): [GraphSlam] (GraphSlamOptions), [GraphScanMatcher]
// (matching::GraphMatcherOptions), the feature extractor's own section (e.g.
// [CornerExtractor]) and [OccupancyGrid] (OccupancyGridOptions) of one .ini file; see
// config_ini/toposlam-slam.ini.
#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>
#include <toposlam/features/CObservationLaserFeatures.h>
#include <toposlam/mapping/GraphSlam.h>
#include <toposlam/mapping/OccupancyGridBuilder.h>
#include <toposlam/matching/GraphScanMatcher.h>

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace toposlam::mapping {

class GraphSlamInput {
  public:
    GraphSlamInput();
    ~GraphSlamInput();

    GraphSlamOptions slamOptions;
    matching::GraphMatcherOptions matcherOptions;
    OccupancyGridOptions gridOptions;

    /// Reads the options (see above); call start() afterwards.
    void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg);
    /// The .ini sections loadFromConfigFile() may read: its own three and the default section
    /// of every feature extractor (the one read depends on [GraphSlam] extractor).
    static std::vector<std::string> configSections();
    static constexpr const char* kSlamSection = "GraphSlam";
    static constexpr const char* kMatcherSection = "GraphScanMatcher";
    static constexpr const char* kGridSection = "OccupancyGrid";

    /// Starts a new map with the robot at `start` (map frame; m, rad), forgetting any before.
    void start(const mrpt::poses::CPose2D& start = {});
    bool started() const { return slam_ != nullptr; }

    /// Robot motion since the last observation, in the robot's frame at its start (m, rad):
    /// a rawlog action's movement estimate.
    void addOdometryIncrement(const mrpt::poses::CPose2D& increment);
    /// Odometry, scans and scan features (see above); other classes are ignored. Starts the
    /// map at the origin if start() was not called.
    void processObservation(const mrpt::obs::CObservation::Ptr& obs);
    /// Optimises the pending loops; call when the log ends.
    void finish();

    /// The engine (trajectory of every scan, keyframes, graph, statistics); throws
    /// std::logic_error before start().
    const GraphSlam& slam() const;
    /// The keyframes at their optimised poses, each with its scan and its features.
    void getKeyframes(mrpt::maps::CSimpleMap& out) const;
    /// The sensor label of the laser mapped (that of the first scan given), and the scans of
    /// other lasers left out, by label.
    const std::optional<std::string>& laserLabel() const { return laserLabel_; }
    const std::map<std::string, std::size_t>& otherLaserScans() const { return otherLasers_; }

  private:
    GraphSlam& engine();
    void processScan(const mrpt::obs::CObservation2DRangeScan::Ptr& scan);

    std::unique_ptr<GraphSlam> slam_;
    std::unique_ptr<features::FeatureExtractor> extractor_;  // configured, until start()
    std::optional<mrpt::poses::CPose2D> lastOdometry_;       // cumulative, observations format
    std::optional<mrpt::poses::CPose2D> pendingIncrement_;   // since the last scan
    features::CObservationLaserFeatures::Ptr pendingFeatures_;
    std::optional<std::string> laserLabel_;
    std::map<std::string, std::size_t> otherLasers_;
};

}  // namespace toposlam::mapping
