#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3DPDFGaussian.h>
#include <toposlam/io/UprightScan.h>
#include <toposlam/mapping/GraphSlamInput.h>

#include <algorithm>
#include <stdexcept>

namespace toposlam::mapping {

using mrpt::poses::CPose2D;

GraphSlamInput::GraphSlamInput() = default;
GraphSlamInput::~GraphSlamInput() = default;

void GraphSlamInput::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg) {
    slamOptions.loadFromConfigFile(cfg, kSlamSection);
    matcherOptions.loadFromConfigFile(cfg, kMatcherSection);
    gridOptions.loadFromConfigFile(cfg, kGridSection);
    extractor_ = features::makeFeatureExtractor(slamOptions.extractor, &cfg);
}

std::vector<std::string> GraphSlamInput::configSections() {
    std::vector<std::string> sections = {kSlamSection, kMatcherSection, kGridSection};
    for (const std::string& name : features::featureExtractorNames()) {
        const std::string section = features::defaultConfigSection(name);
        if (std::find(sections.begin(), sections.end(), section) == sections.end())
            sections.push_back(section);
    }
    return sections;
}

void GraphSlamInput::start(const CPose2D& start) {
    if (!extractor_)
        extractor_ = features::makeFeatureExtractor(slamOptions.extractor);
    slam_ = std::make_unique<GraphSlam>(slamOptions, matcherOptions, std::move(extractor_), start);
    lastOdometry_.reset();
    pendingIncrement_.reset();
    pendingFeatures_.reset();
    laserLabel_.reset();
    otherLasers_.clear();
}

GraphSlam& GraphSlamInput::engine() {
    if (!slam_)
        start();
    return *slam_;
}

const GraphSlam& GraphSlamInput::slam() const {
    if (!slam_)
        throw std::logic_error("GraphSlamInput: start() was not called");
    return *slam_;
}

void GraphSlamInput::addOdometryIncrement(const CPose2D& increment) {
    pendingIncrement_ = pendingIncrement_ ? *pendingIncrement_ + increment : increment;
}

void GraphSlamInput::processObservation(const mrpt::obs::CObservation::Ptr& obs) {
    if (!obs)
        return;
    if (IS_CLASS(*obs, mrpt::obs::CObservationOdometry)) {
        const CPose2D odometry =
            dynamic_cast<const mrpt::obs::CObservationOdometry&>(*obs).odometry;
        if (lastOdometry_)
            addOdometryIncrement(odometry - *lastOdometry_);
        lastOdometry_ = odometry;
    } else if (IS_CLASS(*obs, features::CObservationLaserFeatures)) {
        pendingFeatures_ = std::dynamic_pointer_cast<features::CObservationLaserFeatures>(obs);
    } else if (IS_CLASS(*obs, mrpt::obs::CObservation2DRangeScan)) {
        processScan(std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(obs));
    }
}

void GraphSlamInput::processScan(const mrpt::obs::CObservation2DRangeScan::Ptr& observed) {
    // Scans from MRPT's tools come as logged: an upside-down laser's turned upright (as
    // LaserLogReader does); features stored for it were in the mirrored frame.
    const mrpt::obs::CObservation2DRangeScan::Ptr scan = io::uprightScan(observed);
    if (scan != observed)
        pendingFeatures_.reset();
    if (!laserLabel_)
        laserLabel_ = scan->sensorLabel;
    if (scan->sensorLabel != *laserLabel_) {  // another laser: its odometry stays pending
        ++otherLasers_[scan->sensorLabel];
        return;
    }
    // Stored features count only when they are this scan's.
    features::CObservationLaserFeatures::Ptr stored;
    if (pendingFeatures_ && pendingFeatures_->scanLabel == scan->sensorLabel &&
        pendingFeatures_->timestamp == scan->timestamp)
        stored = pendingFeatures_;
    pendingFeatures_.reset();
    engine().processScan(scan, pendingIncrement_, stored);
    // With odometry known, no new reading until the next scan means no motion.
    if (lastOdometry_ || pendingIncrement_)
        pendingIncrement_ = CPose2D();
}

void GraphSlamInput::finish() {
    engine().finish();
}

void GraphSlamInput::getKeyframes(mrpt::maps::CSimpleMap& out) const {
    out.clear();
    if (!slam_)
        return;
    for (const Keyframe& kf : slam_->keyframes()) {
        auto pose = mrpt::poses::CPose3DPDFGaussian::Create();
        pose->mean = mrpt::poses::CPose3D(slam_->graph().pose(kf.id));
        pose->cov.setZero();
        auto sf = mrpt::obs::CSensoryFrame::Create();
        sf->insert(kf.scan);
        sf->insert(kf.features);
        out.insert(mrpt::poses::CPose3DPDF::Ptr(pose), sf);
    }
}

}  // namespace toposlam::mapping
