#include <mrpt/config/CConfigFileBase.h>
#include <toposlam/mapping/GraphSlamOptions.h>

#include <cmath>
#include <functional>
#include <stdexcept>
#include <vector>

namespace toposlam::mapping {

namespace {
/// One key of the section: how to read and write it.
struct Key {
    const char* name;
    std::function<void(const mrpt::config::CConfigFileBase&, const std::string&)> read;
    std::function<void(mrpt::config::CConfigFileBase&, const std::string&)> write;
};

constexpr double kDeg = M_PI / 180;

Key number(const char* name, double& v) {
    return {name, [&v, name](const auto& c, const auto& s) { v = c.read_double(s, name, v); },
            [&v, name](auto& c, const auto& s) { c.write(s, name, v); }};
}
Key angle(const char* name, double& v) {  // radians in code, degrees in the file
    return {
        name,
        [&v, name](const auto& c, const auto& s) { v = c.read_double(s, name, v / kDeg) * kDeg; },
        [&v, name](auto& c, const auto& s) { c.write(s, name, v / kDeg); }};
}
Key count(const char* name, std::size_t& v) {
    return {
        name,
        [&v, name](const auto& c, const auto& s) { v = std::size_t(c.read_uint64_t(s, name, v)); },
        [&v, name](auto& c, const auto& s) { c.write(s, name, uint64_t(v)); }};
}
Key integer(const char* name, int& v) {
    return {name, [&v, name](const auto& c, const auto& s) { v = c.read_int(s, name, v); },
            [&v, name](auto& c, const auto& s) { c.write(s, name, v); }};
}
Key flag(const char* name, bool& v) {
    return {name, [&v, name](const auto& c, const auto& s) { v = c.read_bool(s, name, v); },
            [&v, name](auto& c, const auto& s) { c.write(s, name, v); }};
}
Key text(const char* name, std::string& v) {
    return {name, [&v, name](const auto& c, const auto& s) { v = c.read_string(s, name, v); },
            [&v, name](auto& c, const auto& s) { c.write(s, name, v); }};
}

std::vector<Key> keys(GraphSlamOptions& o) {
    return {number("keyframe_distance", o.keyframeDistance),
            angle("keyframe_angle_deg", o.keyframeAngle),
            number("keyframe_min_overlap", o.keyframeMinOverlap),
            count("submap_keyframes", o.submapKeyframes),
            number("map_resolution", o.mapResolution),
            number("map_fuse_distance", o.mapFuseDistance),
            number("map_max_range", o.mapMaxRange),
            integer("icp_max_iterations", o.icpMaxIterations),
            number("icp_max_distance", o.icpMaxDistance),
            number("icp_robust_scale", o.icpRobustScale),
            count("icp_stride", o.icpStride),
            number("min_inlier_ratio", o.minInlierRatio),
            number("max_correction_distance", o.maxCorrectionDistance),
            angle("max_correction_angle_deg", o.maxCorrectionAngle),
            number("odometry_jump_distance", o.odometryJumpDistance),
            angle("odometry_jump_angle_deg", o.odometryJumpAngle),
            number("odometry_sigma_xy", o.odometrySigmaXY),
            number("odometry_sigma_xy_per_metre", o.odometrySigmaXYPerMetre),
            angle("odometry_sigma_phi_deg", o.odometrySigmaPhi),
            number("odometry_sigma_phi_per_radian", o.odometrySigmaPhiPerRadian),
            number("edge_min_sigma_xy", o.edgeMinSigmaXY),
            angle("edge_min_sigma_phi_deg", o.edgeMinSigmaPhi),
            flag("loop_closure", o.loopClosure),
            number("loop_min_travel", o.loopMinTravel),
            number("loop_overlap_distance", o.loopOverlapDistance),
            number("loop_gate_sigmas", o.loopGateSigmas),
            count("loop_max_candidates", o.loopMaxCandidates),
            count("loop_search_every", o.loopSearchEvery),
            number("drift_sigma_xy", o.driftSigmaXY),
            angle("drift_sigma_phi_deg", o.driftSigmaPhi),
            angle("drift_sigma_phi_deg_per_turn", o.driftSigmaPhiPerTurn),
            count("global_search_every", o.globalSearchEvery),
            count("global_search_candidates", o.globalSearchCandidates),
            number("loop_min_sigma_xy", o.loopMinSigmaXY),
            angle("loop_min_sigma_phi_deg", o.loopMinSigmaPhi),
            number("loop_candidate_spacing", o.loopCandidateSpacing),
            number("loop_chi2", o.loopChi2),
            count("loop_confirm_window", o.loopConfirmWindow),
            number("loop_pair_tolerance", o.loopPairTolerance),
            angle("loop_pair_angle_tolerance_deg", o.loopPairAngleTolerance),
            number("loop_loss_scale", o.loopLossScale),
            integer("optimize_max_iterations", o.optimizeMaxIterations),
            number("optimize_trigger_distance", o.optimizeTriggerDistance),
            angle("optimize_trigger_angle_deg", o.optimizeTriggerAngle),
            number("optimize_global_distance", o.optimizeGlobalDistance),
            angle("optimize_global_angle_deg", o.optimizeGlobalAngle),
            count("optimize_every_loops", o.optimizeEveryLoops),
            count("optimize_window", o.optimizeWindow),
            count("optimize_global_every", o.optimizeGlobalEvery),
            text("extractor", o.extractor)};
}
}  // namespace

void GraphSlamOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                          const std::string& section) {
    for (const Key& k : keys(*this))
        k.read(cfg, section);
}

void GraphSlamOptions::saveToConfigFile(mrpt::config::CConfigFileBase& cfg,
                                        const std::string& section) const {
    for (const Key& k : keys(const_cast<GraphSlamOptions&>(*this)))
        k.write(cfg, section);
}

}  // namespace toposlam::mapping
