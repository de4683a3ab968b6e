#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3DPDFGaussian.h>
#include <mrpt/poses/CPosePDF.h>
#include <toposlam/mrptslam/CGraphSlamBuilder.h>

#include <stdexcept>
#include <vector>

namespace toposlam::mrptslam {

using mrpt::poses::CPose2D;

CGraphSlamBuilder::CGraphSlamBuilder() {
    setLoggerName("CGraphSlamBuilder");
}

CGraphSlamBuilder::~CGraphSlamBuilder() = default;

void CGraphSlamBuilder::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg) {
    input_.loadFromConfigFile(cfg);
}

void CGraphSlamBuilder::initialize(const mrpt::maps::CSimpleMap& initialMap,
                                   const mrpt::poses::CPosePDF* x0) {
    if (!initialMap.empty())
        throw std::invalid_argument(
            "CGraphSlamBuilder: starting from an existing map is not supported");
    CPose2D start;
    if (x0)
        x0->getMean(start);
    input_.start(start);
    metricMap_.maps.clear();
    metricMapVersion_ = {0, 0};
}

mrpt::poses::CPose3DPDF::Ptr CGraphSlamBuilder::getCurrentPoseEstimation() const {
    auto pdf = mrpt::poses::CPose3DPDFGaussian::Create();
    if (!input_.started())
        return pdf;
    const mapping::GraphSlam& slam = input_.slam();
    pdf->mean = mrpt::poses::CPose3D(slam.currentPose());
    pdf->cov.setZero();
    // (x, y, phi) -> (x, y, z, yaw, pitch, roll)
    const int map[3] = {0, 1, 3};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            pdf->cov(map[r], map[c]) = slam.currentCovariance()(r, c);
    return pdf;
}

void CGraphSlamBuilder::processActionObservation(mrpt::obs::CActionCollection& action,
                                                 mrpt::obs::CSensoryFrame& observations) {
    if (const auto move = action.getBestMovementEstimation())
        input_.addOdometryIncrement(move->poseChange->getMeanVal());
    // Features first, so the scan they belong to finds them.
    for (const auto& obs : observations)
        if (IS_CLASS(*obs, features::CObservationLaserFeatures))
            processObservation(obs);
    for (const auto& obs : observations)
        if (!IS_CLASS(*obs, features::CObservationLaserFeatures))
            processObservation(obs);
}

void CGraphSlamBuilder::processObservation(const mrpt::obs::CObservation::Ptr& obs) {
    input_.processObservation(obs);
}

void CGraphSlamBuilder::finish() {
    input_.finish();
}

void CGraphSlamBuilder::getCurrentlyBuiltMap(mrpt::maps::CSimpleMap& out) const {
    input_.getKeyframes(out);
}

unsigned int CGraphSlamBuilder::getCurrentlyBuiltMapSize() {
    return input_.started() ? static_cast<unsigned int>(input_.slam().keyframes().size()) : 0u;
}

const mrpt::maps::CMultiMetricMap* CGraphSlamBuilder::getCurrentlyBuiltMetricMap() const {
    if (!input_.started() || input_.slam().keyframes().empty())
        return &metricMap_;
    const mapping::GraphSlam& slam = input_.slam();
    const std::pair<std::size_t, std::size_t> version{slam.keyframes().size(),
                                                      slam.statistics().optimizations};
    if (version != metricMapVersion_) {
        std::vector<mapping::PosedScan> scans;
        for (const mapping::Keyframe& kf : slam.keyframes())
            scans.push_back({kf.scan, slam.graph().pose(kf.id)});
        auto grid = mrpt::maps::COccupancyGridMap2D::Create(
            mapping::buildOccupancyGrid(scans, input_.gridOptions));
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

}  // namespace toposlam::mrptslam
