#pragma once
// Split-and-merge (iterative end-point fit, IEPF), the classic line extractor and the
// baseline the corner paper compares itself with (Nguyen et al. 2005 found it the fastest of
// the classic ones). Per run of continuous readings (JumpDetector):
//  - split: the reading farthest from the chord between a part's first and last reading
//    splits the part when it is farther than the split distance, recursively (an explicit
//    stack here, no recursion);
//  - merge: neighbours whose union would not be split again are merged;
//  - the split reading, which may belong to either wall, is left out of both fits;
//  - fit (least squares by default), segments, corners and endpoints exactly as for the corner
//    extractor (FeatureAssembly), so the two differ only in how they split the scan.
// Split distance: max(splitDistance, noiseSigmas * sigma), sigma the range noise.
#include <toposlam/config/Options.h>
#include <toposlam/features/FeatureAssembly.h>
#include <toposlam/features/FeatureExtractor.h>
#include <toposlam/features/JumpDetector.h>
#include <toposlam/features/LinePart.h>
#include <toposlam/features/ScanPoints.h>

#include <utility>
#include <vector>

namespace toposlam::features {

/// Section [SplitAndMergeExtractor] of config_ini/features.ini.
struct SplitAndMergeOptions : public config::Options {
    double splitDistance = 0.04;  ///< m, floor of the split threshold
    double noiseSigmas = 3;       ///< split threshold in range-noise sigmas
    double rangeNoiseStd = 0.01;  ///< m, when the scan does not state one
    bool useScanStdError = true;  ///< take the range noise from the scan's stdError
    double minValidRange = 0;     ///< m
    JumpDetectorOptions jumps;
    FeatureAssemblyOptions assembly;  ///< lineFit defaults to least squares here

    SplitAndMergeOptions() { assembly.lineFit = LineFitMethod::LeastSquares; }
    void declare(config::OptionsSchema& s) override;
};

class SplitAndMergeExtractor : public FeatureExtractor {
  public:
    SplitAndMergeOptions options;

    SplitAndMergeExtractor() = default;
    explicit SplitAndMergeExtractor(const SplitAndMergeOptions& o) : options(o) {}

    void extract(const mrpt::obs::CObservation2DRangeScan& scan, ScanFeatures& out) override;
    std::string name() const override { return "split-merge"; }
    void loadOptions(const mrpt::config::CConfigFileBase& cfg,
                     const std::string& section) override {
        options.loadFromConfigFile(cfg, section);
    }
    void dumpOptions(std::ostream& out) const override { options.dumpToTextStream(out); }

    double rangeNoise(const mrpt::obs::CObservation2DRangeScan& scan) const;

  private:
    /// Farthest reading from the chord begin..end, if farther than the threshold.
    bool farthest(std::size_t begin, std::size_t end, double threshold, std::size_t& at) const;
    void splitRun(const PointRun& run, double threshold);

    ScanPoints points_;
    JumpDetector jumpDetector_;
    std::vector<PointRun> runs_;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> stack_;
    std::vector<LinePart> parts_;
    FeatureAssembly assembly_;
};

}  // namespace toposlam::features
