#pragma once
// A scan matcher under test in B2, behind one interface so that the benchmark runs all of
// them on the same pairs in the same process:
//   GraphPairMatcher  TopoSLAM's graph matcher: feature extraction of both scans (a
//                     libs/features extractor) + GraphScanMatcher;
//   CicpPairMatcher   MRPT's CICP (classic or Levenberg-Marquardt) on CSimplePointsMaps built
//                     with loadFromRangeScan, as icp-slam uses it.
// Each match is timed in CPU seconds of the calling thread (from the two raw scans to the
// pose, everything a caller would have to do), which other processes on a shared machine do
// not inflate. Poses are robot frames: the current robot in the reference robot frame.
#include <mrpt/poses/CPose2D.h>
#include <mrpt/slam/CICP.h>
#include <toposlam/features/FeatureExtractor.h>
#include <toposlam/matching/GraphScanMatcher.h>
#include <toposlam/matchingbench/ScanPair.h>

#include <memory>
#include <optional>
#include <string>

namespace toposlam::matchingbench {

struct PairOutcome {
    mrpt::poses::CPose2D pose;
    bool answered = true;     ///< false: the method declined (no reliable match)
    double seconds = 0;       ///< CPU time of the whole match
    double matchSeconds = 0;  ///< of which the matching proper (graph: without extraction)
    std::string status;       ///< method-specific outcome (graph: MatchStatus)
};

class PairMatcher {
  public:
    virtual ~PairMatcher() = default;
    virtual std::string name() const = 0;
    virtual PairOutcome match(const ScanPair& pair,
                              const std::optional<mrpt::poses::CPose2D>& guess) = 0;
};

class GraphPairMatcher : public PairMatcher {
  public:
    /// `extractorConfig`: when given, the extractor's options are read from its default
    /// section (features::defaultConfigSection, e.g. [SplitAndMergeExtractor]).
    GraphPairMatcher(std::string name, const std::string& extractor,
                     const matching::GraphMatcherOptions& options,
                     const mrpt::config::CConfigFileBase* extractorConfig = nullptr);
    std::string name() const override { return name_; }
    PairOutcome match(const ScanPair& pair,
                      const std::optional<mrpt::poses::CPose2D>& guess) override;

  private:
    std::string name_;
    std::unique_ptr<features::FeatureExtractor> extractor_;
    matching::GraphScanMatcher matcher_;
    matching::PolarScan refPolar_, curPolar_;
    features::ScanFeatures refFeatures_, curFeatures_;
};

class CicpPairMatcher : public PairMatcher {
  public:
    CicpPairMatcher(std::string name, const mrpt::slam::CICP::TConfigParams& params);
    std::string name() const override { return name_; }
    PairOutcome match(const ScanPair& pair,
                      const std::optional<mrpt::poses::CPose2D>& guess) override;

  private:
    std::string name_;
    mrpt::slam::CICP icp_;
};

}  // namespace toposlam::matchingbench
