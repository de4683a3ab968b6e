#include <toposlam/features/FeatureExtractor.h>
#include <toposlam/mapping/GraphSlamOptions.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace toposlam::mapping {

matching::LineMapOptions GraphSlamOptions::lineMapOptions() const {
    matching::LineMapOptions m;
    m.resolution = mapResolution;
    m.radius = icpMaxDistance;
    m.fuseDistance = mapFuseDistance;
    m.confirmDistance = mapConfirmDistance;
    m.maxRange = mapMaxRange;
    m.carveMargin = freeSpaceCarving ? kSeenThroughMargin : 0.0;
    return m;
}

matching::IcpOptions GraphSlamOptions::icpOptions() const {
    matching::IcpOptions icp;
    icp.maxIterations = icpMaxIterations;
    icp.maxDistance = icpMaxDistance;
    icp.robustScale = icpRobustScale;
    icp.stride = icpStride;
    icp.minMapViews = static_cast<std::uint32_t>(icpMinViews);
    icp.skipMovedMapPoints = freeSpaceCarving;
    icp.maxIncidence = icpMaxIncidence;
    icp.translationTolerance = 1e-4;
    icp.rotationTolerance = 1e-5;
    return icp;
}

void GraphSlamOptions::declare(config::OptionsSchema& s) {
    declareFrontEnd(s);
    declareLoopClosure(s);
    declareBackEnd(s);
}

void GraphSlamOptions::declareFrontEnd(config::OptionsSchema& s) {
    // Keyframes and local submaps.
    s.real("keyframe_distance", keyframeDistance, "m", "a keyframe every this much travel ...")
        .above(0);
    s.angle("keyframe_angle", keyframeAngle, "... or this much turn").above(0).atMost(180);
    s.real("keyframe_min_overlap", keyframeMinOverlap, "",
           "... or as soon as less than this share of the scan lies on the local map")
        .within(0, 1);
    s.integer("submap_keyframes", submapKeyframes, "keyframes",
              "per submap; two overlapping submaps are active")
        .within(2, 10000);
    s.flag("submap_parts", submapParts,
           "a keyframe placed by odometry alone starts a part of each submap; a scan is tied to "
           "the part most of its readings lie on, not always to the anchor");
    s.real("map_resolution", mapResolution, "m", "lookup cells of the submaps' line maps")
        .within(0.005, 1);
    s.real("map_fuse_distance", mapFuseDistance, "m",
           "observations this close to a map point are fused into it")
        .above(0);
    s.real("map_confirm_distance", mapConfirmDistance, "m",
           "a map point counts one more view when another keyframe puts a reading this close")
        .atLeast(0);
    s.real("map_max_range", mapMaxRange, "m", "farther readings are not put into submaps...")
        .above(0);
    s.real("map_far_share", mapFarShare, "",
           "... unless more than this share of a scan's valid readings lie farther: then all "
           "of them (1 = never)")
        .within(0, 1);
    // Front end: registration.
    s.integer("icp_max_iterations", icpMaxIterations, "", "point-to-line ICP iterations at most")
        .within(1, 1000);
    s.real("icp_max_distance", icpMaxDistance, "m", "association gate of ICP's first stage")
        .above(0);
    s.real("icp_robust_scale", icpRobustScale, "m", "Cauchy kernel scale of ICP").above(0);
    s.integer("icp_stride", icpStride, "", "every stride-th point in ICP's first stage")
        .within(1, 100);
    s.integer("icp_min_views", icpMinViews, "keyframes",
              "ICP's first stage matches only submap points seen from this many keyframes")
        .within(1, 100);
    s.flag("free_space_carving", freeSpaceCarving,
           "ICP's first stage leaves out submap points that later keyframes saw through");
    s.angle("icp_max_incidence", icpMaxIncidence,
            "submap points whose surface faces the sensor at a larger incidence are not matched")
        .above(0)
        .atMost(180);
    s.flag("second_opinion", secondOpinion,
           "when ICP has not settled, also start it from the graph matcher and turned predictions");
    s.real("second_opinion_margin", secondOpinionMargin, "",
           "... a start that puts this share of the readings more on the map replaces it")
        .within(0, 1);
    s.angle("second_opinion_turn", secondOpinionTurn,
            "... the prediction turned by +-1 and +-2 times this (0: no turned starts)")
        .atLeast(0)
        .atMost(90);
    s.flag("short_turn_second_opinion", shortTurnSecondOpinion,
           "ICP that ended on little of the scan, settled or not, from a reading that turned "
           "less than the last motion, the same way, by more than the second opinion's turns "
           "reach, gets the second opinion with one more start, the last motion");
    s.flag("spot_turn_second_opinion", spotTurnSecondOpinion,
           "ICP that ended on little of the scan from a reading of a turn on the spot, in a log "
           "whose odometry has jumped, gets the second opinion");
    s.flag("second_opinion_wide_turns", secondOpinionWideTurns,
           "where none of the second opinion's starts settled, also start ICP from the "
           "prediction turned by +-3 and +-4 second_opinion_turn");
    s.flag("second_opinion_refuted_beyond_jump", secondOpinionRefutedBeyondJump,
           "the second opinion's answer is refused where ICP from one of its starts ended "
           "beyond the jump bounds on second_opinion_margin more of the scan");
    s.flag("matcher_second_opinion", matcherSecondOpinion,
           "where ICP from the prediction failed and the graph matcher answers, ICP from the "
           "prediction turned by +-1 and +-2 second_opinion_turn that fits second_opinion_margin "
           "more of the scan replaces the answer");
    s.flag("matcher_bounded_by_catch_up", matcherBoundedByCatchUp,
           "right after a stall, a graph-matcher answer within the jump bounds of the reading "
           "less the motion registered over the stall is no jump");
    s.flag("jump_sideways_by_turn", jumpSidewaysByTurn,
           "where ICP from a jumped reading turns back a turn the last reading missed, it may "
           "also correct the reading sideways by the step's length x sin(half that turn): the "
           "chord of a step whose heading lagged");
    s.real("unsettled_max_chi2", unsettledMaxChi2, "",
           "ICP that has not settled is taken only within this chi-square (3 dof) of the "
           "odometry model's step (0 = off)")
        .atLeast(0);
    s.real("foreground_check", foregroundCheck, "m",
           "ICP correcting the prediction by more than this along the heading runs again "
           "without small objects near the laser (people); 0 = off")
        .atLeast(0);
    s.flag("foreground_beyond_odometry", foregroundBeyondOdometry,
           "ICP correcting the odometry's step beyond unsettled_max_chi2 also runs again without "
           "small objects near the laser; kept where the rest of the scan fits it no worse");
    s.real("foreground_max_range", foregroundMaxRange, "m",
           "... objects whose nearest reading is at most this far ...")
        .above(0);
    s.real("foreground_max_width", foregroundMaxWidth, "m", "... and at most this wide").above(0);
    s.real("along_heading_check", alongHeadingCheck, "m",
           "ICP correcting the prediction by more than this along the heading keeps the "
           "odometry's position along it unless the scan fits better at ICP's; 0 = off")
        .atLeast(0);
    s.real("along_heading_margin", alongHeadingMargin, "",
           "... better: by more than this share of the readings")
        .within(0, 1);
    s.real("along_heading_free_space", alongHeadingFreeSpace, "",
           "... and keeps it where the scan at ICP's pose sees through this share of its "
           "readings more submap points than at the odometry's; 0 = off")
        .within(0, 1);
    s.real("min_inlier_ratio", minInlierRatio, "",
           "a registration is good when this share of the scan's points lies on the map ...")
        .within(0, 1);
    s.real("max_correction_distance", maxCorrectionDistance, "m",
           "... and it corrects the prediction by at most this ...")
        .above(0);
    s.angle("max_correction_angle", maxCorrectionAngle, "... and this").above(0).atMost(180);
    s.real("max_lateral_correction", maxLateralCorrection, "m",
           "... and moves the robot sideways by at most this (0 = no limit)")
        .atLeast(0);
    s.real("odometry_jump_distance", odometryJumpDistance, "m",
           "odometry steps longer than this between two scans, and as far from the last motion, "
           "are jumps, not motion ...")
        .above(0);
    s.angle("odometry_jump_angle", odometryJumpAngle, "... as are turns larger than this")
        .above(0)
        .atMost(180);
    s.flag("confirm_large_corrections", confirmLargeCorrections,
           "corrections of the odometry beyond these bounds (the graph matcher's, up to twice "
           "them; the last motion as the prediction) are used when ICP on the submap confirms "
           "them");
    s.real("jump_choice_margin", jumpChoiceMargin, "",
           "after an odometry jump, the odometry's step, the last motion or the graph matcher's "
           "answer is preferred over another when ICP from it puts this share more of the "
           "scan's readings on the submap")
        .atLeast(0)
        .atMost(1);
    s.flag("matcher_foreground_check", matcherForegroundCheck,
           "a graph-matcher answer where ICP was rejected must be borne out by the scan without "
           "its foreground objects (people close by)");
    s.angle("jump_search_step", jumpSearchStep,
            "after an odometry jump that neither ICP from its step nor the graph matcher places, "
            "ICP also starts between that step and the last motion, this far apart in heading "
            "(0 = off)")
        .atLeast(0)
        .atMost(90);
    s.flag("jump_over_two_readings", jumpOverTwoReadings,
           "after an odometry jump nothing else places, where the last scan's registration "
           "departed from its reading, ICP also starts from the scan before the last followed "
           "by both readings (a stall within a scan interval)");
    s.flag("missed_turn_start", missedTurnStart,
           "where nothing places a scan, and short readings before it missed part of the turn "
           "that its reading turned farther than, ICP also starts from the reading less that "
           "turn");
    s.flag("turned_start_search", turnedStartSearch,
           "where nothing places a scan whose reading is at least 0.6 times as long as the last "
           "motion, in a log whose odometry has jumped, ICP also starts from the reading turned "
           "by 1 to 4 x second_opinion_turn_deg either way, taken where every start that settles "
           "within the jump bounds ends at the same pose (a heading that stalled through the "
           "scan interval)");
    s.flag("undecided_jump_by_prior", undecidedJumpByPrior,
           "after an odometry jump the scan fits as well from the odometry's step as from the "
           "last motion (a corridor), the log's earlier clear jumps choose between them before "
           "the graph matcher is asked");
    s.flag("defer_keyframe_in_stall", deferKeyframeInStall,
           "a scan of an odometry stall that nothing placed (it kept the last motion) does not "
           "become a keyframe; the next scan that qualifies does");
    s.flag("matcher_from_registered_keyframe", matcherFromRegisteredKeyframe,
           "where the last keyframe was placed by odometry alone, the graph matcher matches the "
           "scan against the newest keyframe a registration placed (the last one only when that "
           "finds nothing)");
    s.flag("jump_only_out_of_step", jumpOnlyOutOfStep,
           "an odometry reading in step with the one before it (within 0.2 m and 10 deg) is "
           "never a jump, however far the registered motion departed from it");
    s.flag("bridge_odometry_stalls", bridgeOdometryStalls,
           "where registration saw less of an odometry stall than the reading after it holds "
           "(no translation, or 0.2 m less where the reading turned as far as registration saw, "
           "within 10 deg), that reading less the motion registered meanwhile is the step "
           "predicted, and the stall's scans registration left behind are placed between");
    s.flag("bridge_unplaced_stalls", bridgeUnplacedStalls,
           "a stall whose scans nothing placed (they kept the last motion) is bridged as one "
           "registration saw nothing of, whatever turn the last motion carried on; its scans are "
           "placed between, headings spread over the turn");
    s.flag("bridge_refuted_stalls", bridgeRefutedStalls,
           "a stall whose scans ICP placed none of (the graph matcher alone, or nothing) is "
           "bridged as one nothing placed where the reading after it turned otherwise than "
           "registered by more than odometry_jump_angle per scan interval it spans; its scans are "
           "placed between");
    s.flag("bridge_stall_and_step", bridgeStallAndStep,
           "a catch-up after a stall as long as the translation registered over the stall plus "
           "a step of the last motion's length (within 0.2 m) is bridged whatever it turned; "
           "after a last motion of 0.2 m or less the step left must also turn as it did");
    s.flag("catch_up_less_stall", catchUpLessStall,
           "in the first catch-up after a stall registration placed, where nothing from the last "
           "motion or the reading placed the scan, ICP also starts from the reading less the "
           "motion registered over the stall");
    s.flag("predict_stalls_by_last_motion", predictStallsByLastMotion,
           "in an odometry stall (a reading repeated exactly while the robot moved and the scan "
           "changed) ICP also starts from the last registered motion, and the standstill stays "
           "only where the scan bears it out (second_opinion_margin)");
    s.real("odometry_sigma_xy", odometrySigmaXY, "m",
           "odometry-only edges: position noise floor ...")
        .above(0);
    s.real("odometry_sigma_xy_per_metre", odometrySigmaXYPerMetre, "m/m",
           "... plus this share of the distance travelled")
        .atLeast(0);
    s.angle("odometry_sigma_phi", odometrySigmaPhi, "heading noise floor ...").above(0);
    s.real("odometry_sigma_phi_per_radian", odometrySigmaPhiPerRadian, "rad/rad",
           "... plus this share of the angle turned")
        .atLeast(0);
    s.real("edge_min_sigma_xy", edgeMinSigmaXY, "m",
           "registration edges: smallest position sigma (ICP's own is too confident)")
        .above(0);
    s.angle("edge_min_sigma_phi", edgeMinSigmaPhi, "... and heading sigma").above(0);
    s.real("foreground_edge_sigma_factor", foregroundEdgeSigmaFactor, "",
           "registration edges of keyframes whose scan sees foreground objects: this many times "
           "the edge floor's sigmas (1 = off)")
        .atLeast(1);
    s.flag("smooth_scans", smoothScans,
           "output: positions between keyframes from registration and odometry together");
    s.flag("odometry_calibration", odometryCalibration.enabled,
           "scale the odometry's distances by what the well-registered scans show");
    s.real("odometry_calibration_min_distance", odometryCalibration.minDistance, "m",
           "... once this much odometry distance counted ...")
        .atLeast(0);
    s.real("odometry_calibration_max_std", odometryCalibration.maxStd, "m",
           "... from scans ICP placed to this position sigma in every direction ...")
        .above(0);
    s.real("odometry_calibration_max_correction", odometryCalibration.maxCorrection, "",
           "... the scale within 1 +- this")
        .within(0, 0.5);
    std::vector<std::pair<std::string, std::string>> extractors;
    for (const std::string& name : features::featureExtractorNames())
        extractors.emplace_back(name, name);
    s.choice("extractor", extractor, extractors,
             "feature extractor of the keyframes; its options come from its own section");
}

void GraphSlamOptions::declareLoopClosure(config::OptionsSchema& s) {
    s.flag("loop_closure", loopClosure, "search, verify and add loop edges");
    s.real("loop_min_travel", loopMinTravel, "m",
           "older keyframes are candidates beyond this travel along the trajectory")
        .atLeast(0);
    s.real("loop_overlap_distance", loopOverlapDistance, "m",
           "keyframes this close see enough of the same place to be matched")
        .above(0);
    s.real("loop_gate_sigmas", loopGateSigmas, "",
           "Mahalanobis gate of the pose uncertainty propagated through the graph")
        .above(0);
    s.integer("loop_max_candidates", loopMaxCandidates, "", "candidates verified per keyframe")
        .within(1, 100);
    s.integer("loop_search_every", loopSearchEvery, "keyframes",
              "the gated loop search runs on every this-many-th keyframe")
        .within(1, 1000);
    s.integer("loop_threads", loopThreads, "",
              "threads verifying loop candidates, the mapping thread included (same loops for any)")
        .within(1, 64);
    s.real("drift_sigma_xy", driftSigmaXY, "m/sqrt(m)",
           "drift model: position random walk per metre of path ...")
        .above(0);
    s.angle("drift_sigma_phi", driftSigmaPhi, "... heading random walk per metre ...",
            "deg/sqrt(m)")
        .atLeast(0);
    s.angle("drift_sigma_phi_per_turn", driftSigmaPhiPerTurn, "... and per radian turned",
            "deg/sqrt(rad)")
        .atLeast(0);
    s.integer("global_search_every", globalSearchEvery, "keyframes",
              "guess-free search against keyframes outside the gate every this many (0: off)")
        .within(0, 100000);
    s.integer("global_search_candidates", globalSearchCandidates, "",
              "keyframes of the most similar signatures matched by the guess-free search")
        .within(1, 100);
    s.real("loop_min_sigma_xy", loopMinSigmaXY, "m", "loop edges: smallest position sigma ...")
        .above(0);
    s.angle("loop_min_sigma_phi", loopMinSigmaPhi, "... and heading sigma").above(0);
    s.real("loop_candidate_spacing", loopCandidateSpacing, "m",
           "verified candidates are at least this far apart (look-alikes get tried)")
        .atLeast(0);
    s.real("loop_chi2", loopChi2, "",
           "chi-square bound (3 dof) on a new loop's disagreement with the graph (16.27 = 99.9 %)")
        .above(0);
    s.flag("loop_gate_lever_arm", loopGateLeverArm,
           "a loop outside the gate is let in where it is off by a turn and the shift that turn "
           "makes across the chain's reach, and the path's covariance, each edge's heading "
           "variance swung by its lever arm, explains it within loop_chi2");
    s.real("loop_withdraw_chi2", loopWithdrawChi2, "",
           "after optimisation, the worst loop whose chi-square is still above this is withdrawn")
        .above(0);
    s.integer("loop_confirm_window", loopConfirmWindow, "keyframes",
              "a guess-free or correcting loop needs an agreeing one within this many")
        .within(1, 100000);
    s.real("loop_pair_tolerance", loopPairTolerance, "m",
           "two loops agree when their cycle closes within this ...")
        .above(0);
    s.angle("loop_pair_angle_tolerance", loopPairAngleTolerance, "... and this").above(0);
    s.integer("loop_contested_support", loopContestedSupport, "",
              "gate-rejected matches accepted together when this many agree, from several "
              "searches, against two visits of the place (0 = never)")
        .within(0, 1000);
}

void GraphSlamOptions::declareBackEnd(config::OptionsSchema& s) {
    s.real("loop_loss_scale", loopLossScale, "sigmas",
           "Cauchy loss on loop edges (0: plain least squares)")
        .atLeast(0);
    s.integer("optimize_max_iterations", optimizeMaxIterations, "",
              "Ceres iterations per optimisation")
        .within(1, 1000);
    s.real("optimize_trigger_distance", optimizeTriggerDistance, "m",
           "a loop disagreeing by more is optimised at once over the recent window ...")
        .atLeast(0);
    s.angle("optimize_trigger_angle", optimizeTriggerAngle, "... or by more than this").atLeast(0);
    s.real("optimize_global_distance", optimizeGlobalDistance, "m",
           "a loop disagreeing by more is optimised over the whole graph ...")
        .atLeast(0);
    s.angle("optimize_global_angle", optimizeGlobalAngle, "... or by more than this").atLeast(0);
    s.integer("optimize_every_loops", optimizeEveryLoops, "loops",
              "agreeing loops are optimised once this many have come")
        .within(1, 100000);
    s.integer("optimize_window", optimizeWindow, "keyframes",
              "the recent keyframes a windowed optimisation moves")
        .within(2, 1000000);
    s.integer("optimize_global_every", optimizeGlobalEvery, "keyframes",
              "the whole graph is optimised every this many keyframes with loops (and once it "
              "has grown by half since the last time), and at the end")
        .within(1, 1000000);
}

}  // namespace toposlam::mapping
