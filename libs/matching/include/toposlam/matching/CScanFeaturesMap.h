#pragma once
// The feature map as an MRPT metric map (mrpt::maps::CMetricMap): the line segments, corners
// and endpoints of every scan inserted, in one MAP frame (x/y in metres), repeated
// observations of the same wall or corner merged (FeatureMap). What MRPT's tools build from
// an .ini map definition once libtoposlam-plugin.so is loaded:
//     [MappingApplication]   scanFeaturesMap_count = 1
//     [MappingApplication_scanFeaturesMap_00_creationOpts]    extractor = split-merge
//     [MappingApplication_scanFeaturesMap_00_insertOpts]      (source, FeatureMapOptions' keys)
//     [MappingApplication_scanFeaturesMap_00_likelihoodOpts]  sigma_dist, max_corr_distance,
//                                                             decimation
// e.g. icp-slam (LD_PRELOAD), rbpf-slam, observations2map, RawLogViewer's "Raw map" dialog.
//
// Keyframes. Every insertion is kept as a keyframe: the robot pose, the sensor's pose on the
// robot and the scan's features in the SENSOR frame. The merged map is a function of the
// keyframes, so a SLAM back end that moves its poses (pose-graph optimisation) calls
// updateKeyframePoses() (or rebuild()) and gets the map of the corrected trajectory without
// extracting anything again.
//
// Insertion (insertObservation with the robot pose in the map frame; no pose = the origin):
//  - CObservation2DRangeScan: its features are extracted with the configured extractor
//    (libs/features: "split-merge" by default, see FeatureExtractor.h); used when insertion
//    option `source` is "scans" (default);
//  - features::CObservationLaserFeatures (toposlam-annotate-features output): its stored
//    features are used as they are; used when `source` is "features". One source only, so an
//    annotated log (a scan AND its features) is not counted twice.
// The last inserted SCAN is also kept whole (scan(), polar(), scanFeatures(), sensorPose()):
// it is what CGraphMatcherAlignment aligns, so a map with one scan inserted is the
// one-scan "scan + features" the matcher takes.
//
// Observation likelihood (computeObservationLikelihood, a LOG-likelihood as MRPT expects; the
// same form as MRPT's CPointsMap so particle filters weigh it alike):
//     log L = -(1/N) * sum_i min(d_i^2, max_corr_distance^2) / sigma_dist
// over every `decimation`-th valid point i of a scan (N points), d_i = distance (m) from the
// point, put in the map frame at the observation's pose, to the nearest confirmed map
// segment. For a CObservationLaserFeatures the points are its corners and the ends and
// middles of its segments. 0 (no information) when the map has no confirmed segment or the
// observation holds no point.
//
// Serialization: the extractor, the options, the keyframes and the last scan; the merged map
// is rebuilt on reading. Registered with mrpt-rtti and MAP_DEFINITION_REGISTER
// ("toposlam::matching::CScanFeaturesMap", short name "scanFeaturesMap") when
// libtoposlam-matching (or the plugin) is loaded.
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/maps/CMetricMap.h>
#include <mrpt/maps/TMetricMapInitializer.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>
#include <toposlam/features/FeatureExtractor.h>
#include <toposlam/features/ScanFeatures.h>
#include <toposlam/matching/FeatureMap.h>
#include <toposlam/matching/PolarScan.h>

#include <memory>
#include <string>
#include <vector>

namespace toposlam::matching {

/// The features of one scan and where they were seen from: what a CScanFeaturesMap is built of.
struct FeatureKeyframe {
    mrpt::poses::CPose2D robotPose;      ///< robot in the map frame (m, rad)
    mrpt::poses::CPose2D sensorOnRobot;  ///< laser on the robot (planar part)
    features::ScanFeatures features;     ///< SENSOR frame
    /// robotPose (+) sensorOnRobot.
    mrpt::poses::CPose2D sensorPose() const { return robotPose + sensorOnRobot; }
};

class CScanFeaturesMap : public mrpt::maps::CMetricMap {
    DEFINE_SERIALIZABLE(CScanFeaturesMap, toposlam::matching)

  public:
    /// Which observations insertObservation() takes.
    enum class Source { Scans, Features };

    /// Keys: source = scans | features, and FeatureMapOptions' (merge_angle_deg, ...).
    struct TInsertionOptions : public config::Options {
        FeatureMapOptions merge;
        Source source = Source::Scans;
        void declare(config::OptionsSchema& s) override;
    } insertionOptions;

    /// Keys sigma_dist, max_corr_distance, decimation (MRPT's CPointsMap names).
    struct TLikelihoodOptions : public config::Options {
        double sigma_dist = 0.0025;      ///< m^2 (MRPT's CPointsMap default)
        double max_corr_distance = 1.0;  ///< m
        unsigned decimation = 10;        ///< use every decimation-th scan point
        void declare(config::OptionsSchema& s) override;
    } likelihoodOptions;

    CScanFeaturesMap() = default;
    /// `extractor`: a name of features::featureExtractorNames() (throws for another).
    explicit CScanFeaturesMap(const std::string& extractor);

    // --- building --------------------------------------------------------------------------
    /// Adds a keyframe and merges its features into the map.
    void insertKeyframe(const FeatureKeyframe& keyframe);
    /// Extracts the features of `scan`, taken with the robot at `robotPose` (map frame),
    /// inserts them as a keyframe and keeps the scan as the last scan.
    void insertScan(const mrpt::obs::CObservation2DRangeScan& scan,
                    const mrpt::poses::CPose2D& robotPose = {});
    /// Empties the map, then insertScan(): a map holding exactly this scan (the matcher's input).
    void setScan(const mrpt::obs::CObservation2DRangeScan& scan,
                 const mrpt::poses::CPose2D& robotPose = {});
    /// Moves every keyframe to a new robot pose (one per keyframe, in insertion order) and
    /// rebuilds the merged map. Throws std::invalid_argument on a size mismatch.
    void updateKeyframePoses(const std::vector<mrpt::poses::CPose2D>& robotPoses);
    /// Replaces every keyframe and rebuilds the merged map (the last scan is kept).
    void rebuild(std::vector<FeatureKeyframe> keyframes);

    // --- reading ---------------------------------------------------------------------------
    const FeatureMap& featureMap() const { return map_; }
    const std::vector<FeatureKeyframe>& keyframes() const { return keyframes_; }
    const std::string& extractor() const { return extractor_; }
    /// Changes the extractor; re-extracts the features of the last scan (keyframes already
    /// inserted keep theirs).
    void setExtractor(const std::string& name);

    /// The last inserted scan, its features (sensor frame) and the sensor's pose (map frame).
    bool hasScan() const { return hasScan_; }
    const mrpt::obs::CObservation2DRangeScan& scan() const { return scan_; }
    const PolarScan& polar() const { return polar_; }
    const features::ScanFeatures& features() const { return scanFeatures_; }
    const mrpt::poses::CPose2D& sensorPose() const { return sensorPose_; }

    // --- CMetricMap ------------------------------------------------------------------------
    /// No keyframe and no scan.
    bool isEmpty() const override;
    /// Writes <prefix>_segments.txt, <prefix>_corners.txt, <prefix>_endpoints.txt (confirmed
    /// features, map frame, one per line with a '#' header) and <prefix>.png (drawFeatureMap).
    void saveMetricMapRepresentationToFile(const std::string& prefix) const override;
    /// Confirmed segments, corners and endpoints (FeatureMapRendering.h).
    void getVisualizationInto(mrpt::opengl::CSetOfObjects& outObj) const override;
    std::string asString() const override;

    MAP_DEFINITION_START(CScanFeaturesMap)
    std::string extractor = "split-merge";
    TInsertionOptions insertionOpts;
    TLikelihoodOptions likelihoodOpts;
    MAP_DEFINITION_END(CScanFeaturesMap)

  private:
    void internal_clear() override;
    bool internal_insertObservation(
        const mrpt::obs::CObservation& obs,
        const std::optional<const mrpt::poses::CPose3D>& robotPose = std::nullopt) override;
    bool internal_canComputeObservationLikelihood(
        const mrpt::obs::CObservation& obs) const override;
    double internal_computeObservationLikelihood(
        const mrpt::obs::CObservation& obs, const mrpt::poses::CPose3D& takenFrom) const override;
    void keepScan(const mrpt::obs::CObservation2DRangeScan& scan,
                  const mrpt::poses::CPose2D& robotPose);
    void rebuildMap();

    std::string extractor_ = "split-merge";
    /// Shared by copies (MRPT clones maps, e.g. per particle); used by one thread at a time.
    std::shared_ptr<features::FeatureExtractor> extractorObject_;
    FeatureMap map_;
    std::vector<FeatureKeyframe> keyframes_;
    // The last scan.
    bool hasScan_ = false;
    mrpt::obs::CObservation2DRangeScan scan_;
    mrpt::poses::CPose2D scanRobotPose_, sensorPose_;
    PolarScan polar_;
    features::ScanFeatures scanFeatures_;
};

}  // namespace toposlam::matching
