#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/poses/CPosePDF.h>
#include <toposlam/io/CpuTime.h>
#include <toposlam/matchingbench/PairMatcher.h>

namespace toposlam::matchingbench {

using io::threadCpuSeconds;

GraphPairMatcher::GraphPairMatcher(std::string name, const std::string& extractor,
                                   const matching::GraphMatcherOptions& options,
                                   const mrpt::config::CConfigFileBase* extractorConfig)
    : name_(std::move(name)),
      extractor_(features::makeFeatureExtractor(extractor)),
      matcher_(options) {
    if (extractorConfig)
        extractor_->loadOptions(*extractorConfig, features::defaultConfigSection(extractor));
}

PairOutcome GraphPairMatcher::match(const ScanPair& pair,
                                    const std::optional<mrpt::poses::CPose2D>& guess) {
    PairOutcome out;
    const double t0 = threadCpuSeconds();
    extractor_->extract(*pair.reference, refFeatures_);
    extractor_->extract(*pair.current, curFeatures_);
    refPolar_.assign(*pair.reference);
    curPolar_.assign(*pair.current);
    const double t1 = threadCpuSeconds();
    // Robot frames <-> sensor frames: T_sensor = S1^-1 + T_robot + S2.
    const mrpt::poses::CPose2D s1(pair.reference->sensorPose), s2(pair.current->sensorPose);
    std::optional<mrpt::poses::CPose2D> sensorGuess;
    if (guess)
        sensorGuess = (-s1) + *guess + s2;
    const matching::MatchResult& r =
        matcher_.match(refPolar_, refFeatures_, curPolar_, curFeatures_, sensorGuess);
    const double t2 = threadCpuSeconds();
    out.pose = s1 + r.pose + (-s2);
    out.answered = r.reliable();
    out.status = matching::toString(r.status);
    out.seconds = t2 - t0;
    out.matchSeconds = t2 - t1;
    return out;
}

CicpPairMatcher::CicpPairMatcher(std::string name, const mrpt::slam::CICP::TConfigParams& params)
    : name_(std::move(name)) {
    icp_.options = params;
}

PairOutcome CicpPairMatcher::match(const ScanPair& pair,
                                   const std::optional<mrpt::poses::CPose2D>& guess) {
    PairOutcome out;
    const double t0 = threadCpuSeconds();
    // Points in the robot frames (loadFromRangeScan applies the scan's sensorPose).
    mrpt::maps::CSimplePointsMap reference, current;
    reference.insertionOptions.minDistBetweenLaserPoints = 0;
    current.insertionOptions.minDistBetweenLaserPoints = 0;
    reference.loadFromRangeScan(*pair.reference);
    current.loadFromRangeScan(*pair.current);
    mrpt::slam::CICP::TReturnInfo info;
    const mrpt::poses::CPosePDF::Ptr pdf =
        icp_.Align(&reference, &current, guess ? *guess : mrpt::poses::CPose2D(), info);
    out.seconds = out.matchSeconds = threadCpuSeconds() - t0;
    out.pose = pdf->getMeanVal();
    out.answered = true;
    out.status = "goodness " + std::to_string(info.goodness);
    return out;
}

}  // namespace toposlam::matchingbench
