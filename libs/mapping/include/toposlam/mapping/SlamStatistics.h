#pragma once
// What a graph SLAM run did, for its summary: how scans were registered, how many keyframes
// and loops, where the time went.
#include <cstddef>
#include <vector>

namespace toposlam::mapping {

/// One along-heading check (along_heading_check): ICP corrected the odometry's prediction by
/// more than that along the robot's heading, so the scan had to bear the correction out. With
/// foreground objects in view the check is made on ICP without them (foreground_check), whose
/// correction may be smaller, and on the rest of the scan.
struct AlongHeadingCheck {
    std::size_t scan = 0;      ///< index of the scan in the log's order (0 = the first)
    double correction = 0;     ///< m along the heading: the checked pose minus the prediction
    std::size_t readings = 0;  ///< valid readings of the scan checked
    /// Readings within 5 cm of the submap at ICP's pose and at the odometry's position along
    /// the heading (with ICP's sideways and turn correction).
    std::size_t onMapAtIcp = 0, onMapAtOdometry = 0;
    /// Submap points the scan sees through at those two poses (along_heading_free_space;
    /// LineMap::countSeenThrough): 0 when that test is off.
    std::size_t seenThroughAtIcp = 0, seenThroughAtOdometry = 0;
    bool held = false;  ///< the odometry's position along the heading was kept
    /// ... because ICP's pose sees through the submap, where the fit alone did not hold it.
    bool heldForFreeSpace = false;
};

struct SlamStatistics {
    std::size_t scans = 0;
    std::size_t keyframes = 0;
    std::size_t submaps = 0;
    /// Keyframes registered by ICP that are tied to a part of their submap started by a keyframe
    /// placed by odometry alone, not to its anchor (submap_parts; Submap.h).
    std::size_t tiedToLaterPart = 0;
    /// Scans that would have been keyframes but were in an odometry stall that nothing placed
    /// (defer_keyframe_in_stall).
    std::size_t keyframesDeferredInStall = 0;
    /// Keyframes registered by ICP whose scan saw foreground objects (people close by, mostly):
    /// their registration edges were made less certain (foreground_edge_sigma_factor).
    std::size_t keyframesSeeingForeground = 0;
    // Registration of each scan (the first scan is the origin and counts in none of them).
    std::size_t registeredByIcp = 0;  ///< point-to-line ICP against the local submap
    /// Of those, not settled (ScanRegistration.h; with second_opinion on), and how many of
    /// these a second start replaced.
    std::size_t icpUnsettled = 0, icpSecondStarts = 0;
    /// ICP (settled or not) that ended on little of the scan from a reading short of the last
    /// motion's turn (short_turn_second_opinion), and how many of these a second start
    /// replaced (where that ICP had not settled either, it counts in icpUnsettled and
    /// icpSecondStarts too).
    std::size_t icpShortOfTurn = 0, icpShortOfTurnReplaced = 0;
    /// The same from a reading of a turn on the spot (spot_turn_second_opinion).
    std::size_t icpShortOnTheSpot = 0, icpShortOnTheSpotReplaced = 0;
    /// Second starts (of either kind above) from the wider ring of turned starts, tried where
    /// none of the nearer starts settled (second_opinion_wide_turns).
    std::size_t icpWideTurnStarts = 0;
    /// Graph-matcher answers, after ICP from the prediction failed, that ICP from a turned start
    /// replaced: it fitted clearly more of the scan (matcher_second_opinion).
    std::size_t icpOutfittedMatcher = 0;
    /// Unsettled ICP refused: from no start did it settle within the odometry model's noise
    /// (unsettled_max_chi2); those scans count as registered by the graph matcher or failed.
    std::size_t icpUnsettledRefused = 0;
    /// Of those, refused because a start ended beyond the jump bounds on clearly more of the
    /// scan (second_opinion_refuted_beyond_jump).
    std::size_t icpRefutedBeyondJump = 0;
    /// Of those, registered without the scan's foreground objects (foreground_check).
    std::size_t icpWithoutForeground = 0;
    /// Of those, kept at the odometry's position along the heading (along_heading_check).
    std::size_t icpHeldAlongHeading = 0;
    /// Of those, held because ICP's pose saw through the submap (along_heading_free_space).
    std::size_t icpHeldForFreeSpace = 0;
    /// Every along-heading check, in scan order (for the summary: where ICP and the odometry
    /// disagreed along the way, and what the scan said).
    std::vector<AlongHeadingCheck> alongHeadingChecks;
    std::size_t registeredByGraphMatcher = 0;  ///< ICP was poor; the graph matcher succeeded
    /// Of those, answers beyond the odometry's jump bounds that ICP on the submap confirmed
    /// (confirm_large_corrections).
    std::size_t graphMatcherConfirmed = 0;
    /// Of those, matched against the newest keyframe a registration placed, the last keyframe
    /// having been placed by odometry alone (matcher_from_registered_keyframe).
    std::size_t graphMatcherFromRegisteredKeyframe = 0;
    /// Of those, beyond the jump bounds of the reading right after a stall but within those of
    /// the catch-up it may hold (matcher_bounded_by_catch_up).
    std::size_t graphMatcherWithinStallCatchUp = 0;
    /// Scans predicted by the robot's last motion instead of the odometry's step, whatever
    /// registered them (confirm_large_corrections).
    std::size_t lastMotionPredictions = 0;
    std::size_t registrationFailed = 0;  ///< both failed: odometry prediction kept
    /// Of those, scans whose graph-matcher answer only their foreground objects bore out
    /// (matcher_foreground_check).
    std::size_t matcherRefusedForeground = 0;
    std::size_t odometryJumps = 0;  ///< odometry increments rejected as jumps
    /// Of those, steps the scan bore out all the same, which predicted it (a fast turn at a low
    /// scan rate; confirm_large_corrections).
    std::size_t odometryJumpsBorneOut = 0;
    /// Of the jumps, steps the scan fitted as well as the last motion, taken as read because
    /// this log's earlier jumps were mostly the odometry's own steps (undecided_jump_by_prior;
    /// not counted in odometryJumpsBorneOut).
    std::size_t odometryJumpsByPrior = 0;
    /// Of the jumps borne out or taken by the prior, those whose ICP corrected the reading
    /// sideways beyond the step's own bound, within the allowance for a turn the last reading
    /// missed and this one held (jump_sideways_by_turn).
    std::size_t odometryJumpsSidewaysByTurn = 0;
    /// Of the others, placed by neither ICP from the odometry's step nor the graph matcher, those
    /// ICP placed from a start between the odometry's step and the last motion
    /// (jump_search_step): the odometry caught up past the turn or short of it.
    std::size_t odometryJumpsBetween = 0;
    /// Of the others, those ICP placed from the scan before the last followed by both readings
    /// (jump_over_two_readings): the last reading fell short of the step, this one holds the
    /// rest.
    std::size_t odometryJumpsOverTwoReadings = 0;
    /// Scans ICP placed from the odometry's step less the turn short readings before it
    /// missed, where nothing else placed them (missed_turn_start).
    std::size_t icpPastMissedTurn = 0;
    /// Scans ICP placed from the reading turned farther either way, where nothing else placed
    /// them (turned_start_search).
    std::size_t icpFromTurnedStarts = 0;
    /// Of the jumps nothing registered, those kept as the odometry read them, not as the last
    /// motion: the log's earlier jumps were mostly the odometry's own steps.
    std::size_t odometryJumpReadingsKept = 0;
    /// odometry increments taken for catching up after a stall (OdometryLag.h)
    std::size_t odometryCatchUps = 0;
    /// Of those, placed by ICP from the odometry's step where nothing from the last motion
    /// placed them (ScanRegistration::keepCaughtUpReading: a turn on the spot after a stall).
    std::size_t odometryCatchUpsKept = 0;
    /// Of those, from the reading less the motion registered over the stall before it
    /// (catch_up_less_stall: the robot stopped and turned on the spot meanwhile).
    std::size_t odometryCatchUpsLessStall = 0;
    /// catch-ups after an odometry stall registration saw too little of (OdometryLag::bridges),
    /// predicted as the reading (the motion since the last reading that changed) less the
    /// motion registered meanwhile (bridge_odometry_stalls)
    std::size_t odometryStallsBridged = 0;
    /// of those, stalls whose scans no registration had placed (bridge_unplaced_stalls)
    std::size_t odometryUnplacedStallsBridged = 0;
    /// of those, stalls whose turn the guess-free matcher registered and the reading after
    /// refuted (bridge_refuted_stalls)
    std::size_t odometryRefutedStallsBridged = 0;
    /// of those, readings as long as the stall's registered translation plus a step like the
    /// last, bridged only for that (OdometryLag::holdsStallAndStep; bridge_stall_and_step)
    std::size_t odometryStallsAndStepBridged = 0;
    /// catch-ups after readings that fell short of the registered motion (a stall within a
    /// scan interval: OdometryLag::catchesUpShortfall), predicted as the reading less the
    /// shortfall (bridge_odometry_stalls)
    std::size_t odometryShortfallsBridged = 0;
    /// readings of millimetres after one the robot could not have slowed from within the scan
    /// interval (the wheels' count stalled while the heading still read:
    /// OdometryLag::translationStalled), predicted as stalls (predict_stalls_by_last_motion)
    std::size_t odometryTranslationStalls = 0;
    /// the scans of those stalls registration had left behind, placed between the scan before
    /// the stall and the catch-up (GraphSlam::placeStalledScans)
    std::size_t stalledScansPlaced = 0;
    /// Scans that came without an odometry increment (a laser-only log), each predicted by
    /// the robot's last registered motion instead.
    std::size_t scansWithoutOdometry = 0;
    /// Of those, the scans whose odometry had read exactly the same since the log began (a
    /// log recorded without odometry states zeros; a robot standing still at the start too):
    /// read as none.
    std::size_t scansOfUnmovedOdometry = 0;
    /// Distance scale applied to the odometry at the end (odometry_calibration; 1 = none),
    /// the scale the well-registered scans show, applied or not (1 until they cover
    /// odometry_calibration_min_distance), and the odometry distance of those scans (m).
    double odometryScale = 1.0;
    double odometryScaleEstimate = 1.0;
    double odometryCalibrationDistance = 0;
    /// The well-registered scans covered odometry_calibration_min_distance: the estimate says
    /// something (and with odometry_calibration on, odometryScale is applied), even if it is 1.
    bool odometryScaleEstimated = false;
    // Loop closure
    std::size_t loopCandidates = 0;     ///< candidate pairs verified by the graph matcher
    std::size_t loopsUnmatched = 0;     ///< the matcher found no reliable match
    std::size_t loopsGateRejected = 0;  ///< reliable match, but disagrees with the graph (for good)
    std::size_t loopsUnconfirmed = 0;   ///< would correct the graph, but no support came
    std::size_t loopsContested = 0;     ///< of the gate-rejected, accepted together later
    std::size_t loopsAccepted = 0;      ///< added to the graph
    std::size_t loopsSwungIn = 0;       ///< of those, let in by the gate's lever arm only
    std::size_t loopsWithdrawn = 0;     ///< accepted, then removed as outliers after optimising
    std::size_t globalSearches = 0;     ///< guess-free searches run
    std::size_t globalHypotheses = 0;   ///< reliable guess-free matches awaiting confirmation
    std::size_t globalConfirmed = 0;    ///< of those, confirmed and accepted
    /// Of the unconfirmed, those still awaiting support when the log ended and off the graph by
    /// more than optimize_global_distance or optimize_global_angle: the map may be open there.
    std::size_t loopsOpenAtEnd = 0;
    /// The largest of them: the scans (indices in the log's order) of its older and current
    /// keyframes, and how far it is off the graph (m, rad).
    struct OpenLoop {
        std::size_t olderScan = 0, currentScan = 0;
        double distance = 0, angle = 0;
    } largestOpenLoop;
    // Back end
    std::size_t optimizations = 0;
    // CPU time (s) by stage, all threads
    double frontEndSeconds = 0;      ///< registration, keyframes, submaps
    double loopSeconds = 0;          ///< loop-closure search and verification
    double optimizationSeconds = 0;  ///< the optimiser
    double offloadedSeconds = 0;     ///< of the above, spent on worker threads (loop verification)

    std::size_t registered() const { return registeredByIcp + registeredByGraphMatcher; }
    /// Share of the scans after the first that were registered (ICP or graph matcher).
    double registeredShare() const {
        return scans > 1 ? double(registered()) / double(scans - 1) : 1.0;
    }
};

}  // namespace toposlam::mapping
