#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3DPDFGaussian.h>
#include <mrpt/poses/CPosePDF.h>
#include <toposlam/io/UprightScan.h>
#include <toposlam/mapping/CGraphSlamBuilder.h>

#include <algorithm>
#include <stdexcept>

namespace toposlam::mapping {

using mrpt::poses::CPose2D;

CGraphSlamBuilder::CGraphSlamBuilder() {
    setLoggerName("CGraphSlamBuilder");
}

CGraphSlamBuilder::~CGraphSlamBuilder() = default;

void CGraphSlamBuilder::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg) {
    slamOptions.loadFromConfigFile(cfg, kSlamSection);
    matcherOptions.loadFromConfigFile(cfg, kMatcherSection);
    gridOptions.loadFromConfigFile(cfg, kGridSection);
    extractor_ = features::makeFeatureExtractor(slamOptions.extractor, &cfg);
}

std::vector<std::string> CGraphSlamBuilder::configSections() {
    std::vector<std::string> sections = {kSlamSection, kMatcherSection, kGridSection};
    for (const std::string& name : features::featureExtractorNames()) {
        const std::string section = features::defaultConfigSection(name);
        if (std::find(sections.begin(), sections.end(), section) == sections.end())
            sections.push_back(section);
    }
    return sections;
}

void CGraphSlamBuilder::initialize(const mrpt::maps::CSimpleMap& initialMap,
                                   const mrpt::poses::CPosePDF* x0) {
    if (!initialMap.empty())
        throw std::invalid_argument(
            "CGraphSlamBuilder: starting from an existing map is not supported");
    if (!extractor_)
        extractor_ = features::makeFeatureExtractor(slamOptions.extractor);
    CPose2D start;
    if (x0)
        x0->getMean(start);
    slam_ = std::make_unique<GraphSlam>(slamOptions, matcherOptions, std::move(extractor_), start);
    lastOdometry_.reset();
    pendingIncrement_.reset();
    pendingFeatures_.reset();
    laserLabel_.reset();
    otherLasers_.clear();
    metricMap_.maps.clear();
    metricMapVersion_ = {0, 0};
}

GraphSlam& CGraphSlamBuilder::engine() {
    if (!slam_)
        initialize();
    return *slam_;
}

const GraphSlam& CGraphSlamBuilder::slam() const {
    if (!slam_)
        throw std::logic_error("CGraphSlamBuilder: initialize() was not called");
    return *slam_;
}

mrpt::poses::CPose3DPDF::Ptr CGraphSlamBuilder::getCurrentPoseEstimation() const {
    auto pdf = mrpt::poses::CPose3DPDFGaussian::Create();
    if (!slam_)
        return pdf;
    pdf->mean = mrpt::poses::CPose3D(slam_->currentPose());
    pdf->cov.setZero();
    // (x, y, phi) -> (x, y, z, yaw, pitch, roll)
    const int map[3] = {0, 1, 3};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            pdf->cov(map[r], map[c]) = slam_->currentCovariance()(r, c);
    return pdf;
}

void CGraphSlamBuilder::processActionObservation(mrpt::obs::CActionCollection& action,
                                                 mrpt::obs::CSensoryFrame& observations) {
    if (const auto move = action.getBestMovementEstimation()) {
        const CPose2D increment = move->poseChange->getMeanVal();
        pendingIncrement_ = pendingIncrement_ ? *pendingIncrement_ + increment : increment;
    }
    // Features first, so the scan they belong to finds them.
    for (const auto& obs : observations)
        if (IS_CLASS(*obs, features::CObservationLaserFeatures))
            processObservation(obs);
    for (const auto& obs : observations)
        if (!IS_CLASS(*obs, features::CObservationLaserFeatures))
            processObservation(obs);
}

void CGraphSlamBuilder::processObservation(const mrpt::obs::CObservation::Ptr& obs) {
    if (!obs)
        return;
    if (IS_CLASS(*obs, mrpt::obs::CObservationOdometry)) {
        const CPose2D odometry =
            dynamic_cast<const mrpt::obs::CObservationOdometry&>(*obs).odometry;
        if (lastOdometry_) {
            const CPose2D increment = odometry - *lastOdometry_;
            pendingIncrement_ = pendingIncrement_ ? *pendingIncrement_ + increment : increment;
        }
        lastOdometry_ = odometry;
    } else if (IS_CLASS(*obs, features::CObservationLaserFeatures)) {
        pendingFeatures_ = std::dynamic_pointer_cast<features::CObservationLaserFeatures>(obs);
    } else if (IS_CLASS(*obs, mrpt::obs::CObservation2DRangeScan)) {
        processScan(std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(obs));
    }
}

void CGraphSlamBuilder::processScan(const mrpt::obs::CObservation2DRangeScan::Ptr& observed) {
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

void CGraphSlamBuilder::finish() {
    engine().finish();
}

void CGraphSlamBuilder::getCurrentlyBuiltMap(mrpt::maps::CSimpleMap& out) const {
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

unsigned int CGraphSlamBuilder::getCurrentlyBuiltMapSize() {
    return slam_ ? static_cast<unsigned int>(slam_->keyframes().size()) : 0u;
}

const mrpt::maps::CMultiMetricMap* CGraphSlamBuilder::getCurrentlyBuiltMetricMap() const {
    if (!slam_ || slam_->keyframes().empty())
        return &metricMap_;
    const std::pair<std::size_t, std::size_t> version{slam_->keyframes().size(),
                                                      slam_->statistics().optimizations};
    if (version != metricMapVersion_) {
        std::vector<PosedScan> scans;
        for (const Keyframe& kf : slam_->keyframes())
            scans.push_back({kf.scan, slam_->graph().pose(kf.id)});
        auto grid = mrpt::maps::COccupancyGridMap2D::Create(buildOccupancyGrid(scans, gridOptions));
        metricMap_.maps.clear();
        metricMap_.maps.push_back(grid);
        metricMapVersion_ = version;
    }
    return &metricMap_;
}

void CGraphSlamBuilder::saveCurrentEstimationToImage(const std::string& file, bool) {
    const auto* map = getCurrentlyBuiltMetricMap();
    if (const auto grid = map->mapByClass<mrpt::maps::COccupancyGridMap2D>())
        grid->saveAsBitmapFile(file);
}

}  // namespace toposlam::mapping
