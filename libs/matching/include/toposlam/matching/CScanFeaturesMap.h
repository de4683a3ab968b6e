#pragma once
// The "feature map" the graph matcher aligns (MRPT integration): one laser scan's points and
// its features, as an mrpt::maps::CMetricMap so that MRPT's alignment interface
// (CGraphMatcherAlignment, a CMetricMapsAlignmentAlgorithm) can take two of them, and so that
// .ini map definitions build it:
//     [map]  scanFeaturesMap_count = 1
//     [map_scanFeaturesMap_00_creationOpts]  extractor = split-merge
// Inserting a CObservation2DRangeScan REPLACES the content (the map holds one scan): its
// readings are kept in the sensor frame (PolarScan), its features are extracted with the
// configured extractor (libs/features: "split-merge" by default, the one the graph matcher
// does best with on real scans, see share/doc/benchmarks.md, B2; "corners", "segments", ...), and
// the sensor's pose in the map frame (robot pose given to insertObservation, default the origin,
// composed with the scan's sensorPose) is remembered. Serialization stores the scan and the
// extractor name; the features are extracted again on reading (extraction is deterministic).
// Registered with mrpt-rtti and MAP_DEFINITION_REGISTER ("toposlam::matching::CScanFeaturesMap",
// short name "scanFeaturesMap") when libtoposlam-matching (or the plugin) is loaded.
#include <mrpt/maps/CMetricMap.h>
#include <mrpt/maps/TMetricMapInitializer.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>
#include <toposlam/features/ScanFeatures.h>
#include <toposlam/matching/PolarScan.h>

#include <string>

namespace toposlam::matching {

class CScanFeaturesMap : public mrpt::maps::CMetricMap {
    DEFINE_SERIALIZABLE(CScanFeaturesMap, toposlam::matching)

  public:
    CScanFeaturesMap() = default;
    /// `extractor`: a name of features::featureExtractorNames().
    explicit CScanFeaturesMap(const std::string& extractor);

    /// Replaces the content with `scan`, taken with the robot at `robotPose` (map frame).
    void setScan(const mrpt::obs::CObservation2DRangeScan& scan,
                 const mrpt::poses::CPose2D& robotPose = {});

    const std::string& extractor() const { return extractor_; }
    /// Changes the extractor; re-extracts the features of the current scan.
    void setExtractor(const std::string& name);
    const PolarScan& polar() const { return polar_; }
    const features::ScanFeatures& features() const { return features_; }
    /// Sensor pose in the map frame (2D).
    const mrpt::poses::CPose2D& sensorPose() const { return sensorPose_; }
    const mrpt::obs::CObservation2DRangeScan& scan() const { return scan_; }

    bool isEmpty() const override;
    /// Writes <prefix>_points.txt (x y, map frame) and <prefix>_segments.txt (x0 y0 x1 y1).
    void saveMetricMapRepresentationToFile(const std::string& prefix) const override;
    void getVisualizationInto(mrpt::opengl::CSetOfObjects& outObj) const override;
    std::string asString() const override;

    MAP_DEFINITION_START(CScanFeaturesMap)
    std::string extractor = "split-merge";
    MAP_DEFINITION_END(CScanFeaturesMap)

  private:
    void internal_clear() override;
    bool internal_insertObservation(
        const mrpt::obs::CObservation& obs,
        const std::optional<const mrpt::poses::CPose3D>& robotPose = std::nullopt) override;
    /// Likelihood of a range scan taken from `takenFrom`: exp of the free-space-consistent
    /// inlier fraction minus one (1 when every verifiable point agrees), from AlignmentScorer.
    double internal_computeObservationLikelihood(
        const mrpt::obs::CObservation& obs, const mrpt::poses::CPose3D& takenFrom) const override;
    void extract();

    std::string extractor_ = "split-merge";
    mrpt::obs::CObservation2DRangeScan scan_;
    mrpt::poses::CPose2D robotPose_, sensorPose_;
    PolarScan polar_;
    features::ScanFeatures features_;
    bool hasScan_ = false;
};

}  // namespace toposlam::matching
