#pragma once
// What every scan feature extractor in TopoSLAM offers, so apps, benchmarks and the SLAM loop
// can use any of them by name:
//   corners         CornerExtractor, robust defaults, two-point fit   (corner paper)
//   corners-ls      CornerExtractor, least-squares fit
//   corners-paper   CornerExtractor, the paper's rules exactly as printed
//   segments        SegmentExtractor: convex/concave endpoints and segments (graph paper 2.1)
//   segments-paper  SegmentExtractor with the paper's 4-tap turning sum, no noise model
//   split-merge     SplitAndMergeExtractor (IEPF), the classic baseline
// Extractors keep their workspaces between calls: after the first scans of a given size they
// allocate nothing. Output is in the SENSOR frame (ScanFeatures.h).
#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <toposlam/features/ScanFeatures.h>

#include <memory>
#include <string>
#include <vector>

namespace toposlam::features {

class FeatureExtractor {
  public:
    virtual ~FeatureExtractor() = default;
    /// Extracts the features of one scan into `out` (cleared first; capacity reused).
    virtual void extract(const mrpt::obs::CObservation2DRangeScan& scan, ScanFeatures& out) = 0;
    /// The method's name (one of featureExtractorNames()).
    virtual std::string name() const = 0;
    /// Reads the options from `section` of an .ini file (missing keys keep their values).
    virtual void loadOptions(const mrpt::config::CConfigFileBase& cfg,
                             const std::string& section) = 0;
    /// The options as commented "key = value" lines.
    virtual void dumpOptions(std::ostream& out) const = 0;
};

/// The names makeFeatureExtractor() accepts.
const std::vector<std::string>& featureExtractorNames();
/// The default .ini section of a method ("CornerExtractor", "SegmentExtractor", ...).
std::string defaultConfigSection(const std::string& name);
/// A new extractor; throws std::invalid_argument for an unknown name. With `config`, its
/// options are read from `section` (default: defaultConfigSection(name)) first; the preset the
/// name stands for (least squares, paper-exact) is applied after.
std::unique_ptr<FeatureExtractor> makeFeatureExtractor(
    const std::string& name, const mrpt::config::CConfigFileBase* config = nullptr,
    const std::string& section = "");

}  // namespace toposlam::features
