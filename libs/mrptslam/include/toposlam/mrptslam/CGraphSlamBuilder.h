#pragma once
// TopoSLAM's graph SLAM (GraphSlam, fed by mapping::GraphSlamInput) as an MRPT map builder, so
// MRPT code drives it like CMetricMapBuilderICP: processActionObservation() for
// actions/sensory-frame rawlogs, processObservation() for observation-only ones
// (CObservationOdometry, then CObservation2DRangeScan; a CObservationLaserFeatures of the
// scan, when the log has one, is used instead of extracting the features again). The map
// handed out is the keyframes (getCurrentlyBuiltMap: a CSimpleMap of their poses and sensory
// frames, each with the scan and its features) and an occupancy grid of them at their
// optimised poses (getCurrentlyBuiltMetricMap, built when asked for). It maps one laser: the
// scans of the first sensor label it is given; those of other lasers are counted and left out.
//
// Configuration (loadFromConfigFile): [GraphSlam] (GraphSlamOptions), [GraphScanMatcher]
// (matching::GraphMatcherOptions), the feature extractor's own section (e.g.
// [CornerExtractor]) and [OccupancyGrid] (OccupancyGridOptions) of one .ini file; see
// config_ini/toposlam-slam.ini.
#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/slam/CMetricMapBuilder.h>
#include <toposlam/mapping/GraphSlamInput.h>

#include <map>
#include <optional>
#include <string>
#include <utility>

namespace toposlam::mrptslam {

class CGraphSlamBuilder : public mrpt::slam::CMetricMapBuilder {
  public:
    CGraphSlamBuilder();
    ~CGraphSlamBuilder() override;

    /// Reads the options (see above); call initialize() afterwards.
    void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg);

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
    const mapping::GraphSlam& slam() const { return input_.slam(); }
    /// The sensor label of the laser mapped (that of the first scan given), and the scans of
    /// other lasers left out, by label.
    const std::optional<std::string>& laserLabel() const { return input_.laserLabel(); }
    const std::map<std::string, std::size_t>& otherLaserScans() const {
        return input_.otherLaserScans();
    }

  private:
    mapping::GraphSlamInput input_;
    mutable mrpt::maps::CMultiMetricMap metricMap_;
    /// (keyframes, optimisations) of the graph the metric map was built from.
    mutable std::pair<std::size_t, std::size_t> metricMapVersion_{0, 0};
};

}  // namespace toposlam::mrptslam
