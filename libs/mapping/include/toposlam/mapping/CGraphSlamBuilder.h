#pragma once
// TopoSLAM's graph SLAM (GraphSlam) as an MRPT map builder, so MRPT code drives it like
// CMetricMapBuilderICP: processActionObservation() for actions/sensory-frame rawlogs,
// processObservation() for observation-only ones (CObservationOdometry, then
// CObservation2DRangeScan; a CObservationLaserFeatures of the scan, when the log has one, is
// used instead of extracting the features again). The map handed out is the keyframes
// (getCurrentlyBuiltMap: a CSimpleMap of their poses and sensory frames, each with the scan
// and its features) and an occupancy grid of them at their optimised poses
// (getCurrentlyBuiltMetricMap, built when asked for). It maps one laser: the scans of the
// first sensor label it is given; those of other lasers are counted and left out (their
// odometry still counts), since each scan is registered against the keyframes before it.
//
// Configuration (loadFromConfigFile): [GraphSlam] (GraphSlamOptions), [GraphScanMatcher]
// (matching::GraphMatcherOptions), the feature extractor's own section (e.g.
// [CornerExtractor]) and [OccupancyGrid] (OccupancyGridOptions) of one .ini file; see
// config_ini/toposlam-slam.ini.
#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/slam/CMetricMapBuilder.h>
#include <toposlam/mapping/GraphSlam.h>
#include <toposlam/mapping/OccupancyGridBuilder.h>
#include <toposlam/matching/GraphScanMatcher.h>

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace toposlam::mapping {

class CGraphSlamBuilder : public mrpt::slam::CMetricMapBuilder {
  public:
    CGraphSlamBuilder();
    ~CGraphSlamBuilder() override;

    GraphSlamOptions slamOptions;
    matching::GraphMatcherOptions matcherOptions;
    OccupancyGridOptions gridOptions;

    /// Reads the options (see above); call initialize() afterwards.
    void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg);
    /// The .ini sections loadFromConfigFile() may read: its own three and the default section
    /// of every feature extractor (the one read depends on [GraphSlam] extractor).
    static std::vector<std::string> configSections();
    static constexpr const char* kSlamSection = "GraphSlam";
    static constexpr const char* kMatcherSection = "GraphScanMatcher";
    static constexpr const char* kGridSection = "OccupancyGrid";

    /// Starts a new map at `x0` (its mean; default the origin). Building on an existing map
    /// is not supported: a non-empty `initialMap` throws std::invalid_argument.
    void initialize(const mrpt::maps::CSimpleMap& initialMap = {},
                    const mrpt::poses::CPosePDF* x0 = nullptr) override;
    mrpt::poses::CPose3DPDF::Ptr getCurrentPoseEstimation() const override;
    void processActionObservation(mrpt::obs::CActionCollection& action,
                                  mrpt::obs::CSensoryFrame& observations) override;
    /// Odometry, scans and scan features, one at a time (other classes are ignored).
    void processObservation(const mrpt::obs::CObservation::Ptr& obs);
    void getCurrentlyBuiltMap(mrpt::maps::CSimpleMap& out) const override;
    unsigned int getCurrentlyBuiltMapSize() override;
    const mrpt::maps::CMultiMetricMap* getCurrentlyBuiltMetricMap() const override;
    /// The occupancy grid as an image (the format follows the file name's extension).
    void saveCurrentEstimationToImage(const std::string& file, bool formatEMF_BMP = true) override;

    /// Optimises the pending loops; call when the log ends.
    void finish();
    /// The engine (trajectory of every scan, keyframes, graph, statistics).
    const GraphSlam& slam() const;
    /// The sensor label of the laser mapped (that of the first scan given), and the scans of
    /// other lasers left out, by label.
    const std::optional<std::string>& laserLabel() const { return laserLabel_; }
    const std::map<std::string, std::size_t>& otherLaserScans() const { return otherLasers_; }

  private:
    GraphSlam& engine();
    void processScan(const mrpt::obs::CObservation2DRangeScan::Ptr& scan);

    std::unique_ptr<GraphSlam> slam_;
    std::unique_ptr<features::FeatureExtractor> extractor_;  // configured, until initialize()
    std::optional<mrpt::poses::CPose2D> lastOdometry_;       // cumulative, observations format
    std::optional<mrpt::poses::CPose2D> pendingIncrement_;   // since the last scan
    features::CObservationLaserFeatures::Ptr pendingFeatures_;
    std::optional<std::string> laserLabel_;
    std::map<std::string, std::size_t> otherLasers_;
    mutable mrpt::maps::CMultiMetricMap metricMap_;
    /// (keyframes, optimisations) of the graph the metric map was built from.
    mutable std::pair<std::size_t, std::size_t> metricMapVersion_{0, 0};
};

}  // namespace toposlam::mapping
