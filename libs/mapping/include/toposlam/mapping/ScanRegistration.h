#pragma once
// The front end's decision for one scan: where was the robot? In order:
//  1. point-to-line ICP of the scan against the local submap's line map, from the odometry
//     prediction (PointToLineIcp::refineOnMap); good when enough of the scan lands on the map
//     and the correction of the prediction is plausible. After an odometry jump the
//     prediction is the last scan's motion instead, and this step is skipped.
//     With confirm_large_corrections on (the default), when the odometry's step and the
//     robot's last registered motion are farther apart than ICP reaches (icp_max_distance),
//     ICP first runs from both, and the last motion replaces the odometry as the prediction
//     when both end at the same pose or it puts second_opinion_margin more of the scan on the
//     submap (odometry that counts reversing as driving forward: fr079 at a third of its scan
//     rate). Conversely, after an odometry jump (the prediction is then the last motion),
//     ICP also runs from the odometry's own step, and that step is the prediction when ICP
//     from it passes the tests below (its sideways bound grown with the step's length) and
//     ends where ICP from the last motion does, or puts jump_choice_margin more of the scan on
//     the submap, or ICP from the last motion fails them: at a low scan rate a real step
//     departs from the last motion by as much as a jump (mit-csail at a quarter of its rate;
//     simulated tours at a third of their scans, 0.9 m and 45 deg between scans).
//     With second_opinion on (the default), when ICP has not settled (no convergence, and a
//     residual over twice the recent median), it is run again from the graph matcher's answer
//     and from the prediction turned either way, and the start that explains clearly more of
//     the scan wins (an odometry heading off by 10-15 deg in one step of a fast turn); where
//     no such start settles, from the prediction turned farther (25-35 deg: a short reading
//     that missed a turn the other way than the last motion's); and where a start ends beyond
//     the jump bounds on clearly more of the scan than the answer, the answer is refused.
//     Before that, when ICP corrected the prediction by more than foreground_check along the
//     robot's heading, it is run again without the small objects close to the laser
//     (ForegroundObjects.h: a person walking just ahead, whom the submap holds where the next
//     scan sees it again); if that keeps less than half of the correction and passes the
//     same tests, it is the answer. So too where ICP corrects the odometry's step beyond its
//     noise (unsettled_max_chi2; a turn as well: people close by, whom the submap holds from
//     an earlier keyframe): where ICP without the objects stays within that noise and the
//     rest of the scan fits it no worse, it is the answer, or a failed ICP where it fits too
//     little of the scan (foreground_beyond_odometry). And a correction of more than
//     along_heading_check along the heading must be borne out by the scan (by its rest, without
//     such objects): where the odometry's position along the heading fits it nearly as well, along
//     a corridor whose walls do not fix that position, or where ICP's pose has the scan see through
//     walls the submap holds (along_heading_free_space), the pose is moved back there. Both
//     corrections are measured from the prediction, except in an odometry stall where ICP from the
//     standstill and from the last motion end at the same pose, nearer the last motion, on a step
//     straight on: the scan bore that step out, and they are measured from the last motion;
//  2. otherwise (poor overlap, a correction too large to trust, or an odometry jump) the graph
//     matcher against the last keyframe, from the prediction and, failing that, guess-free.
//     (Where the last keyframe was placed by odometry alone, first against the newest keyframe
//     a registration placed (matcher_from_registered_keyframe): a stall during a turn leaves
//     that keyframe tens of degrees off, and an answer relative to it keeps the error.)
//     (A jump whose reading ICP passes from, where ICP from the last motion passes as well and
//     fits no better, is taken as read before the matcher is asked when this log's earlier
//     jumps were mostly the odometry's own steps (undecided_jump_by_prior): along a corridor
//     ICP holds wherever it starts, and the matcher's answer, confirmed on the same submap,
//     is no better a guess.)
//     Without a jump, an answer that corrects the prediction by more than a jump is a
//     look-alike unless ICP on the submap, started there, confirms it (confirm_large_
//     corrections: odometry that counts reversing as driving forward); in an odometry
//     stall, only when it also does so from where the odometry stalled (a turn on the
//     spot). After a jump, an
//     answer that is a jump away from both the odometry's step and the last motion must fit
//     the submap better than ICP from the odometry's step (jumpMatchRefused);
//  3. after an odometry jump that neither placed, ICP from starts between the last motion and
//     the odometry's step (jump_search_step): a stalled odometry that caught up past the turn
//     or short of it (mit-csail at a quarter of its rate); then ICP from the scan before the
//     last followed by both readings, where the last scan's registered motion departed from
//     its reading (jump_over_two_readings): an odometry that stalled within a scan interval
//     read too little of a step and the rest with the next (generated plan 60, stalling
//     robot, a third of the scans); without a jump, where short readings before it missed
//     part of the turn that this one turned farther than, ICP from the reading less that turn
//     (missed_turn_start: a step of the robot's length that delivers the missed turn);
//  4. after a jump, ICP from the odometry's step where it fits the submap clearly better than
//     ICP from the last motion, though it failed step 1's tests (keepJumpedReading: a step
//     into new ground, little of the scan on the submap), or fits as well and the log's
//     earlier jumps were mostly the odometry's own steps; in a catch-up after a stall (the
//     last motion predicted), ICP from the odometry's step where it passes step 1's tests
//     (keepCaughtUpReading: a turn on the spot soon after a stall, read right);
//  5. if all fail, the odometry prediction, with the odometry model's covariance (after a
//     jump, the last motion; where the last motion was preferred to the odometry's step
//     without a jump, the odometry's step all the same: the scan bore out neither).
// Poses are ROBOT poses (the laser's mounting offset is applied here), in the frame of the
// reference keyframe the result names (m, rad).
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/poses/CPose2D.h>
#include <toposlam/features/FeatureExtractor.h>
#include <toposlam/mapping/ForegroundObjects.h>
#include <toposlam/mapping/GraphSlamOptions.h>
#include <toposlam/mapping/Keyframe.h>
#include <toposlam/mapping/SlamStatistics.h>
#include <toposlam/mapping/Submap.h>
#include <toposlam/matching/GraphScanMatcher.h>
#include <toposlam/matching/PointToLineIcp.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>

namespace toposlam::mapping {

enum class RegistrationMethod { Icp, GraphMatcher, Odometry };

struct Registration {
    RegistrationMethod method = RegistrationMethod::Odometry;
    std::size_t reference = 0;  ///< keyframe whose robot frame `pose` is in
    mrpt::poses::CPose2D pose;  ///< robot pose in the reference keyframe's frame
    /// Of pose (x, y, phi), m^2 and rad^2, made usable as a graph edge over the motion since
    /// the last keyframe (see edgeCovariance).
    mrpt::math::CMatrixDouble33 covariance;
    /// The matcher's own covariance, before that (ICP and graph matcher).
    mrpt::math::CMatrixDouble33 rawCovariance;
    double overlap = 0;  ///< share of the scan's valid points on the map (ICP), else 0
    /// ICP, from a second start (ScanRegistration's second opinion) that fits better.
    bool secondStart = false;
    /// ICP had not settled, so a second start was tried (second_opinion on).
    bool unsettled = false;
    /// ICP (settled or not) ended on little of the scan from a reading short of the last
    /// motion's turn, so second starts, one from the last motion, were tried
    /// (short_turn_second_opinion).
    bool shortOfTurn = false;
    /// ICP (settled or not) ended on little of the scan from a reading of a turn on the spot,
    /// so second starts were tried (spot_turn_second_opinion).
    bool shortOnTheSpot = false;
    /// The second start that replaced ICP's answer (secondStart) was one of the wider ring of
    /// turned starts, tried where none of the nearer starts settled (second_opinion_wide_turns).
    bool wideTurn = false;
    /// ... and no start settled where the odometry model allows (unsettled_max_chi2), or a start
    /// that ended beyond the jump bounds fitted clearly better (refutedBeyondJump): the scan
    /// went to the graph matcher instead.
    bool unsettledRefused = false;
    /// The second opinion's answer was refused because ICP from one of its starts ended beyond
    /// the jump bounds on second_opinion_margin more of the scan
    /// (second_opinion_refuted_beyond_jump).
    bool refutedBeyondJump = false;
    /// ICP without the scan's foreground objects (foreground_check), which took back the step,
    /// or turned or pushed it beyond the odometry's noise (foreground_beyond_odometry).
    bool withoutForeground = false;
    /// The graph matcher's answer beyond the jump bounds, confirmed by ICP on the submap
    /// (confirm_large_corrections).
    bool confirmedOnSubmap = false;
    /// The graph matcher's answer against the newest keyframe a registration placed, not the
    /// last keyframe, which odometry alone placed (matcher_from_registered_keyframe).
    bool fromRegisteredKeyframe = false;
    /// ICP from a turned start fitted clearly more of the scan than the graph matcher's answer
    /// after ICP from the prediction failed, and replaced it (matcher_second_opinion).
    bool outfitsMatcher = false;
    /// The graph matcher's answer, beyond the jump bounds of the reading right after a stall
    /// but within those of the catch-up it may hold (matcher_bounded_by_catch_up).
    bool withinStallCatchUp = false;
    /// The graph matcher answered, but only the scan's foreground objects bore its answer out
    /// against where ICP ended (matcher_foreground_check): the scan kept the prediction.
    bool matcherRefusedForeground = false;
    /// Predicted by the robot's last motion instead of the odometry's step
    /// (confirm_large_corrections).
    bool byLastMotion = false;
    /// Predicted by the odometry's step although it was judged a jump: the scan bore it out
    /// (a fast turn at a low scan rate; confirm_large_corrections), or, where nothing else
    /// registered the scan, ICP from that step fitted clearly better than from the last
    /// motion (ScanRegistration::keepJumpedReading).
    bool jumpBorneOut = false;
    /// In a catch-up after a stall that nothing registered from the last motion: ICP from the
    /// odometry's step placed it (ScanRegistration::keepCaughtUpReading).
    bool catchUpReadingKept = false;
    /// Of those, from the reading less the motion registered over the stall
    /// (Prediction::catchUpLessStall): the robot stopped and turned on the spot meanwhile.
    bool catchUpLessStall = false;
    /// After a jump that nothing registered: the scan kept the odometry's reading, not the last
    /// motion, because this log's earlier jumps were mostly the odometry's own steps.
    bool jumpReadingKept = false;
    /// After a jump that neither ICP from the odometry's step nor the graph matcher placed: ICP
    /// from a start between the odometry's step and the last motion (the odometry caught up
    /// past the turn or short of it; jump_search_step).
    bool jumpBetween = false;
    /// After a jump that neither those nor ICP between placed: ICP from the scan before the
    /// last followed by the last reading and this one (the last reading fell short of the
    /// step and this one holds the rest; jump_over_two_readings).
    bool jumpOverTwoReadings = false;
    /// Nothing above placed the scan: ICP from the odometry's step less the turn the short
    /// readings before it missed (Prediction::pastMissedTurn; missed_turn_start).
    bool pastMissedTurn = false;
    /// Placed by ICP from a turned start where nothing else placed it (tryTurnedStarts;
    /// turned_start_search).
    bool turnedStart = false;
    /// Of the jumps borne out (jumpBorneOut), those the scan fitted as well from the last
    /// motion: this log's earlier jumps chose the reading (undecided_jump_by_prior).
    bool jumpByPrior = false;
    /// Of the jumps borne out (by the scan or the prior), those whose ICP corrected the reading
    /// sideways beyond the step's own bound, within the allowance for the turn it took back
    /// (jump_sideways_by_turn; ScanRegistration::chordTurnAllowance).
    bool jumpSidewaysByTurn = false;
    /// The along-heading check's evidence when it ran (its `scan` is left 0: the caller knows
    /// which scan this is).
    std::optional<AlongHeadingCheck> alongHeading;
    /// At the odometry's position along the heading: the scan did not bear out ICP's
    /// correction along it (along_heading_check).
    bool heldAlongHeading() const { return alongHeading && alongHeading->held; }
};

/// True when `motion` goes farther than options.odometryJumpDistance or turns more than
/// options.odometryJumpAngle: more than the robot moves between two scans, whether it is an
/// odometry increment (a jump) or a registration's correction of the odometry (a look-alike).
/// `scans`: the motion covers that many scan intervals (the bounds grow with them; a step
/// bridged over an odometry stall).
bool beyondOdometryJump(const GraphSlamOptions& options, const mrpt::poses::CPose2D& motion,
                        double scans = 1);

/// Where the scan is expected from odometry, in the frames the registration works in.
struct Prediction {
    const Submap* submap = nullptr;  ///< matched against (nullptr: none yet)
    mrpt::poses::CPose2D inSubmap;   ///< robot pose in the submap's frame
    const Keyframe* lastKeyframe = nullptr;
    /// The last keyframe's readings (sensor frame), for the graph matcher.
    const matching::PolarScan* lastKeyframeReadings = nullptr;
    mrpt::poses::CPose2D fromLastKeyframe;  ///< robot pose in the last keyframe's frame
    double distanceFromLastKeyframe = 0;    ///< m travelled by odometry since then
    double turnFromLastKeyframe = 0;        ///< rad turned by odometry since then
    /// Where the last keyframe was placed by odometry alone: the newest keyframe a registration
    /// placed, its readings, the robot pose in its frame, and the odometry's distance (m) and
    /// turn (rad) since it; the graph matcher's first reference then
    /// (matcher_from_registered_keyframe). Unset (nullptr) otherwise.
    const Keyframe* registeredKeyframe = nullptr;
    const matching::PolarScan* registeredKeyframeReadings = nullptr;
    mrpt::poses::CPose2D fromRegisteredKeyframe;
    double distanceFromRegisteredKeyframe = 0;
    double turnFromRegisteredKeyframe = 0;
    bool odometryJumped = false;
    /// After a jump or in a catch-up (odometryLagging), the odometry's own step, set aside
    /// for the last motion (robot frame, m, rad).
    mrpt::poses::CPose2D readingStep;
    /// The odometry is catching up after a stall (OdometryLag): the last motion was predicted.
    bool odometryLagging = false;
    /// The odometry's reading repeated exactly while the robot moved at the last scan, and
    /// the scan changed (a stall, not a stop: OdometryLag::stalled(), scanChanged()): its
    /// step of zero says nothing about the motion. Only with predict_stalls_by_last_motion.
    bool odometryStalled = false;
    /// A catch-up after a stall registration saw too little of (OdometryLag::bridges): the
    /// step is the reading less the motion registered during the stall
    /// (OdometryLag::stepSinceStall; bridge_odometry_stalls).
    bool odometryBridged = false;
    /// When bridged: the stall's scans (its repeated readings) before this one, whether
    /// registration left them behind (OdometryLag::stallScansBehind), and whether it placed
    /// none of them (OdometryLag::stallUnplaced: their headings are the last motion's too).
    int stallScans = 0;
    bool stallScansBehind = false;
    bool stallUnplaced = false;
    /// Right after a stall of whole scans whose reading was neither bridged nor taken for a
    /// catch-up (it read no more than the robot's last motion: the robot slowed down or turned
    /// on the spot meanwhile): the step as a catch-up would be, the reading less the motion
    /// registered over the stall (robot frame of the last scan; OdometryLag::stepSinceStall).
    std::optional<mrpt::poses::CPose2D> stallCatchUpStep;
    /// In a catch-up right after a stall (odometryLagging) whose scans a registration placed:
    /// the reading less the motion registered over the stall (OdometryLag::stepSinceStall;
    /// robot frame of the last scan, m, rad; catch_up_less_stall).
    std::optional<mrpt::poses::CPose2D> catchUpLessStall;
    /// The prediction is the odometry's own step (not the last motion: no jump, no stall, a log
    /// with odometry), so the odometry model bounds its error.
    bool odometryPredicted = false;
    /// max_lateral_correction is for steps up to odometry_jump_distance; a jumped reading the
    /// scan bore out (ScanRegistration::jumpBorneOut) is longer, and its sideways error grows
    /// with it: the bound is this many times larger.
    double sidewaysScale = 1;
    /// The odometry's step since the last scan as predicted (the last motion after a jump),
    /// and the robot's motion registered at the last scan (robot frame, m, rad).
    mrpt::poses::CPose2D odometryStep, lastMotion;
    /// The longest of the robot's motions registered at the last ten scans (m).
    double longestRecentStep = 0;
    /// The odometry's reading at the last scan, when it had one (robot frame of the scan
    /// before it, m, rad; ScanRegistration::jumpOverTwoReadings).
    std::optional<mrpt::poses::CPose2D> lastReading;
    /// The odometry's step (the prediction) less the turn short readings before it missed,
    /// where this step turned farther the same way (OdometryLag::pastMissedTurn): where ICP
    /// from the step fails, a start that takes the missed turn out (missed_turn_start; robot
    /// frame of the last scan, m, rad).
    std::optional<mrpt::poses::CPose2D> pastMissedTurn;

    /// The last keyframe's robot pose in the submap's frame: the prediction less the motion
    /// predicted since that keyframe. A pose in that keyframe's frame (the graph matcher's
    /// answer) composed onto it is in the submap's frame.
    mrpt::poses::CPose2D lastKeyframeInSubmap() const { return inSubmap + (-fromLastKeyframe); }
    /// The same prediction with the registered keyframe (registeredKeyframe, set) as its last
    /// keyframe.
    Prediction fromRegistered() const;
    /// The last scan's robot pose in the last keyframe's frame: the prediction less the step
    /// predicted since that scan.
    mrpt::poses::CPose2D lastScanPose() const { return fromLastKeyframe + (-odometryStep); }
    /// After a jump or in a catch-up: from the predicted pose (the last motion's) to the
    /// odometry's reading, in the robot frame of the prediction (m, rad).
    mrpt::poses::CPose2D toReading() const { return (-odometryStep) + readingStep; }
    /// From the predicted pose to where the robot's last motion would have put it: the
    /// prediction less its step, plus that motion (robot frame of the prediction, m, rad).
    mrpt::poses::CPose2D toLastMotion() const { return (-odometryStep) + lastMotion; }
    /// Where `step` from the last scan (its robot frame, m, rad) puts the robot, in the
    /// submap's frame: the prediction less its own step, plus `step`.
    mrpt::poses::CPose2D inSubmapAfter(const mrpt::poses::CPose2D& step) const {
        return inSubmap + ((-odometryStep) + step);
    }
};

class ScanRegistration {
  public:
    ScanRegistration(const GraphSlamOptions& options,
                     const matching::GraphMatcherOptions& matcherOptions);

    /// Registers `scan` (its readings; the laser at `sensorOnRobot` on the robot).
    /// `extractFeatures` is called only if the graph matcher is needed, to fill `features`.
    template <typename ExtractFeatures>
    Registration registerScan(const matching::PolarScan& scan,
                              const mrpt::poses::CPose2D& sensorOnRobot,
                              const Prediction& prediction, ExtractFeatures&& extractFeatures,
                              features::ScanFeatures& features);

    /// Covariance the odometry model gives a motion of `distance` m and `turn` rad.
    mrpt::math::CMatrixDouble33 odometryCovariance(double distance, double turn) const;
    /// ICP's covariance made usable as a graph edge: at least the edge floor, and along
    /// directions the map did not determine at most the odometry model's.
    mrpt::math::CMatrixDouble33 edgeCovariance(const mrpt::math::CMatrixDouble33& icp,
                                               double distance, double turn) const;

    /// True when `scan` has objects close to the laser that stand in front of what lies behind
    /// them (people, mostly; ForegroundObjects.h with foreground_max_range and _width).
    bool seesForegroundObjects(const matching::PolarScan& scan) const;
    /// What a keyframe's registration edges add to their covariance (m^2, rad^2) when its scan
    /// sees foreground objects (seesForegroundObjects): (foreground_edge_sigma_factor^2 - 1)
    /// times the edge floor's variances, so that an edge at the floor is that factor less
    /// certain; zero otherwise, and with the factor at 1 (off, the default).
    mrpt::math::CMatrixDouble33 foregroundEdgeVariance(const matching::PolarScan& scan) const;

    /// The chi-square (3 dof) of the odometry model for the predicted step (odometryCovariance)
    /// by which `pose` (robot, in the prediction's submap frame) corrects that step.
    double odometryChi2(const Prediction& prediction, const mrpt::poses::CPose2D& pose) const;
    /// True when `pose` corrects the odometry's predicted step by more than unsettled_max_chi2
    /// (odometryChi2). False when the prediction is not the odometry's own step or the rule is
    /// off.
    bool outrunsOdometry(const Prediction& prediction, const mrpt::poses::CPose2D& pose) const;

  private:
    struct IcpAttempt {
        matching::IcpResult icp;
        mrpt::poses::CPose2D robot;  ///< robot pose in the submap frame
        double overlap = 0;
    };
    IcpAttempt icpFrom(const matching::PolarScan& scan, const mrpt::poses::CPose2D& sensorOnRobot,
                       const Submap& submap, const mrpt::poses::CPose2D& start);
    /// ICP from the prediction turned by +-1 and +-2 second_opinion_turn that settles, passes
    /// min_inlier_ratio and the correction bounds from its start (not sideways), stays within
    /// the jump bounds of the prediction, does not end where the failed ICP did (`failedIcp`:
    /// refused for its correction), and puts second_opinion_margin more of `scan` on the
    /// submap than the graph matcher's answer (`matchedInSubmap`; robot poses in the submap's
    /// frame): the best such end, if any (matcher_second_opinion).
    std::optional<IcpAttempt> icpOutfitsMatcher(const matching::PolarScan& scan,
                                                const mrpt::poses::CPose2D& sensorOnRobot,
                                                const Prediction& prediction,
                                                const mrpt::poses::CPose2D& matchedInSubmap,
                                                const mrpt::poses::CPose2D& failedIcp);
    /// The correction passes max_correction_distance, _angle and, when `boundSideways`,
    /// max_lateral_correction times `sidewaysScale`.
    bool plausibleCorrection(const mrpt::poses::CPose2D& correction, bool boundSideways = true,
                             double sidewaysScale = 1) const;
    /// ICP that started at `start` passes as a registration: min_inlier_ratio of the scan on
    /// the map and a plausible correction of `start`. `boundSideways = false` for starts off
    /// the arc the robot moved on (interpolated between two steps), where a sideways
    /// correction is expected.
    bool acceptable(const IcpAttempt& attempt, const mrpt::poses::CPose2D& start,
                    bool boundSideways = true, double sidewaysScale = 1) const;
    /// Of two ICP runs on `map` (from `start` and `otherStart`), only `attempt` passes
    /// acceptable() and it puts more of `scan` on the map: where the other start lies beyond
    /// ICP's basin, its failure says nothing against the start that passed.
    bool passesAlone(const matching::LineMap& map, const matching::PolarScan& scan,
                     const mrpt::poses::CPose2D& sensorOnRobot, const IcpAttempt& attempt,
                     const mrpt::poses::CPose2D& start, const IcpAttempt& other,
                     const mrpt::poses::CPose2D& otherStart) const;
    /// The checks of a large correction along the heading (or beyond the odometry's noise), on
    /// `icp`, ICP from the prediction.
    /// The foreground check (foreground_check): replaced by ICP without the scan's foreground
    /// objects when that keeps less than half of the correction, or, where `icp` corrects the
    /// odometry's step beyond unsettled_max_chi2 (foreground_beyond_odometry), when that stays
    /// within it, keeps less than half of the correction and the rest of the scan fits it no
    /// worse (then without the along-heading check; tryIcp judges it as any ICP, and fails it
    /// on too little of the scan). Then the along-heading check (along_heading_check), on that ICP
    /// and the scan without the objects if there were any: held at the odometry's position along
    /// the heading when the readings do not fit better at ICP's. Sets out.withoutForeground and
    /// out.alongHeading. The correction is measured from `from`: the prediction's pose, or the last
    /// motion's start where a stall's step was borne out from it (stallStepBorneOut_).
    void checkAlongHeading(const matching::PolarScan& scan,
                           const mrpt::poses::CPose2D& sensorOnRobot, const Prediction& prediction,
                           const mrpt::poses::CPose2D& from, IcpAttempt& icp, Registration& out);
    /// True, and `attempt` moved there, when `scan`'s readings lie on the submap at `from`'s
    /// position along the heading (with the attempt's sideways and turn correction) nearly as
    /// often as at the attempt's pose (along_heading_margin), or the scan sees through clearly
    /// more submap points at the attempt's pose than there (along_heading_free_space); at the
    /// attempt's pose at least half of them must lie on the submap. `check` gets the evidence.
    bool holdAlongHeading(const matching::PolarScan& scan,
                          const mrpt::poses::CPose2D& sensorOnRobot, const Prediction& prediction,
                          const mrpt::poses::CPose2D& from, IcpAttempt& attempt,
                          AlongHeadingCheck& check) const;
    /// Step 1 at the top of this file: ICP from the prediction, judged (`started`: that ICP,
    /// already run; null: run it here).
    bool tryIcp(const matching::PolarScan& scan, const mrpt::poses::CPose2D& sensorOnRobot,
                const Prediction& prediction, Registration& out,
                const IcpAttempt* started = nullptr);
    /// The graph matcher against the last keyframe (first against the newest keyframe a
    /// registration placed, Prediction::registeredKeyframe, when set). An answer beyond the
    /// odometry's jump bounds is a look-alike unless the odometry jumped, or `failedIcp` (where ICP
    /// from the prediction ended, rejected; null when it was not tried or not rejected) is given
    /// and confirmOnSubmap() confirms it. An answer within them is refused when `failedIcp` stayed
    /// within the correction bounds (rejected for its overlap) and bornOutWithoutForeground() says
    /// only the scan's foreground objects bear the answer out.
    bool tryGraphMatcher(const matching::PolarScan& scan, const mrpt::poses::CPose2D& sensorOnRobot,
                         const Prediction& prediction, const features::ScanFeatures& features,
                         const mrpt::poses::CPose2D* failedIcp, Registration& out);
    /// The graph matcher against `prediction`'s last keyframe: tryGraphMatcher's work for
    /// one reference keyframe.
    bool matchKeyframe(const matching::PolarScan& scan, const mrpt::poses::CPose2D& sensorOnRobot,
                       const Prediction& prediction, const features::ScanFeatures& features,
                       const mrpt::poses::CPose2D* failedIcp, Registration& out);
    /// After an odometry jump: the graph matcher's robot pose `matched` (in the last keyframe's
    /// frame) is a look-alike when it is twice the jump bounds away from both the odometry's
    /// step and the last motion (a stall caught up is off by less), or, beyond the bounds
    /// themselves, when ICP on the submap started there does not fit jump_choice_margin
    /// more of the scan than ICP from the odometry's step (readingIcp_) where that corrected
    /// the step plausibly, or fits that much less where it did not.
    bool jumpMatchRefused(const matching::PolarScan& scan,
                          const mrpt::poses::CPose2D& sensorOnRobot, const Prediction& prediction,
                          const mrpt::poses::CPose2D& matched);
    /// In a catch-up after a stall (odometryLagging: the last motion predicted) that nothing
    /// placed: ICP from the odometry's own step is the answer when it passes as a
    /// registration (acceptable()); failing that, ICP from that step less the motion
    /// registered over the stall (Prediction::catchUpLessStall).
    bool keepCaughtUpReading(const matching::PolarScan& scan,
                             const mrpt::poses::CPose2D& sensorOnRobot,
                             const Prediction& prediction, Registration& out);
    /// After an odometry jump that nothing placed: ICP from the odometry's step (readingIcp_),
    /// when it corrected the step within max_correction_distance and _angle and puts
    /// jump_choice_margin more of the scan on the submap than ICP from the last motion, is
    /// the answer, however little of the scan is on the submap (a step into new ground).
    /// Where neither fits that much better, it is the answer when this log's jumps have
    /// mostly been the odometry's own steps (jumpsForOdometry_).
    bool keepJumpedReading(const matching::PolarScan& scan,
                           const mrpt::poses::CPose2D& sensorOnRobot, const Prediction& prediction,
                           Registration& out);
    /// Where ICP from a jumped odometry's step (`reading`) does not fit jump_choice_margin
    /// better than ICP from the last motion (`motion`): whether this log's earlier jumps
    /// decide for the reading (odometryUsuallyRight()), the last motion's end fitting no better
    /// either. The scan cannot tell the two apart; the log's history can.
    bool priorFavoursReading(const matching::LineMap& map, const matching::PolarScan& scan,
                             const mrpt::poses::CPose2D& sensorOnRobot, const IcpAttempt& reading,
                             const IcpAttempt& motion) const;
    /// The graph matcher's robot pose `matched` (in the last keyframe's frame) is farther from
    /// the prediction than a jump of `scans` scan intervals (beyondOdometryJump) and, in an
    /// odometry stall, also from the last scan's pose.
    bool answerBeyondJump(const Prediction& prediction, const mrpt::poses::CPose2D& matched,
                          double scans) const;
    /// confirm_large_corrections: the graph matcher's robot pose `matched` (in the last
    /// keyframe's frame), at most twice the jump bounds from the prediction, confirmed by ICP
    /// on the submap started there: enough overlap, within the correction bounds of
    /// `matched`, and ending where ICP from the prediction did (`failedIcp`) or with
    /// second_opinion_margin more readings on the submap than there. `out` gets ICP's pose on
    /// the submap.
    bool confirmOnSubmap(const matching::PolarScan& scan, const mrpt::poses::CPose2D& sensorOnRobot,
                         const Prediction& prediction, const mrpt::poses::CPose2D& matched,
                         const mrpt::poses::CPose2D& failedIcp, Registration& out);
    /// matcher_foreground_check: whether the graph matcher's robot pose `matched` (in the last
    /// keyframe's frame) stands against `failedIcp` (where ICP from the prediction ended,
    /// rejected, in the submap's frame) without the scan's foreground objects. True when the
    /// scan has none, or ICP on the submap started at `matched` ends where `failedIcp` is, or
    /// the rest of the scan puts along_heading_margin more of its readings on the submap
    /// there than at `failedIcp`. People walking along with the robot stand in the last
    /// keyframe one step back; fitted to them, the matcher takes back the robot's step.
    bool bornOutWithoutForeground(const matching::PolarScan& scan,
                                  const mrpt::poses::CPose2D& sensorOnRobot,
                                  const Prediction& prediction, const mrpt::poses::CPose2D& matched,
                                  const mrpt::poses::CPose2D& failedIcp);

    /// jump_sideways_by_turn: how much farther (in max_lateral_correction) ICP's `correction`
    /// of a jumped reading may go sideways than the step's own bound. Where the reading holds a
    /// turn the last reading missed (registration turned the last step further than it read)
    /// and ICP's heading correction takes it back, the step's length x sin(half the turn taken
    /// back, at most what was missed): a heading that lagged through the step turned its chord
    /// by about half the lag. 0 elsewhere.
    double chordTurnAllowance(const Prediction& prediction,
                              const mrpt::poses::CPose2D& correction) const;

    /// Where nothing else placed the scan and the odometry did not jump: ICP from the prediction
    /// turned by +-1 to +-4 x second_opinion_turn_deg (turned_start_search), for a heading that
    /// stalled through the scan interval by more than ICP's basin. The answer is the end every
    /// start that settled within the jump bounds reached (at least two of them), with
    /// min_inlier_ratio of the scan on the submap and sideways no farther than the turn swings
    /// the step's chord. Only in a log whose odometry has jumped (kJumpPriorCases clear jump
    /// choices) and for a reading at least kStepAsStepped of the last motion's length.
    bool tryTurnedStarts(const matching::PolarScan& scan, const mrpt::poses::CPose2D& sensorOnRobot,
                         const Prediction& prediction, Registration& out);
    /// ... only for a reading at least this share of the last motion's length.
    static constexpr double kStepAsStepped = 0.6;

    /// After an odometry jump, ICP from the jumped prediction's own pose (the last motion):
    /// run once per scan, kept in motionIcp_ for the jump's later steps.
    const IcpAttempt& icpFromLastMotion(const matching::PolarScan& scan,
                                        const mrpt::poses::CPose2D& sensorOnRobot,
                                        const Prediction& prediction);
    /// Counts a jump the scan decided clearly in jumpsForOdometry_ or jumpsForLastMotion_, once
    /// per scan:
    /// ICP from the odometry's step ended at `reading`, from the last motion at `motion`.
    void recordJumpChoice(const Submap& submap, const matching::PolarScan& scan,
                          const mrpt::poses::CPose2D& sensorOnRobot, const IcpAttempt& reading,
                          const IcpAttempt& motion);
    /// ICP on the submap from robot pose `start` (submap frame); where it passes step 1's
    /// overlap and correction tests, `out` is its answer (by ICP) and true.
    bool answerIcpFrom(const matching::PolarScan& scan, const mrpt::poses::CPose2D& sensorOnRobot,
                       const Prediction& prediction, const mrpt::poses::CPose2D& start,
                       Registration& out);
    /// `out` becomes `icp`'s answer on the prediction's submap, registered by `method`.
    void answerOnSubmap(const IcpAttempt& icp, const Prediction& prediction,
                        RegistrationMethod method, Registration& out) const;
    /// ICP from `prediction` ended in `icp` without settling, or short of a turn (see
    /// shortOfTurn): ICP again from the graph matcher's answer `matched` (when it has one),
    /// from the prediction turned by +-1 and +-2 second_opinion_turn and, with
    /// `fromLastMotion`, from the robot's last motion; where none of these settled, also by
    /// +-3 and +-4 second_opinion_turn (second_opinion_wide_turns); the end that puts at least
    /// second_opinion_margin more of the scan's readings on the submap than `icp` replaces it.
    /// Returns false when the answer outruns the odometry (outrunsOdometry) and none of those
    /// starts settled there, or when a start ended beyond the jump bounds on
    /// second_opinion_margin more of the scan than the answer (second_opinion_refuted_beyond_
    /// jump; both counted on the submap before its newest part, Submap::readingsBeforeNewestPart):
    /// no answer.
    bool secondOpinion(const matching::PolarScan& scan, const mrpt::poses::CPose2D& sensorOnRobot,
                       const Prediction& prediction, const Registration* matched, Registration& icp,
                       bool fromLastMotion);
    /// The prediction turned on the spot by `turns` times second_opinion_turn: the starts of
    /// the second opinion and of the turned-start search (tryTurnedStarts).
    mrpt::poses::CPose2D turnedStart(const Prediction& prediction, double turns) const {
        return prediction.inSubmap + mrpt::poses::CPose2D(0, 0, turns * options_.secondOpinionTurn);
    }
    /// ICP from the odometry's step (not a stalled reading) ended with less than
    /// keyframe_min_overlap of the scan on the submap, and the second opinion is on: what
    /// shortOfTurn and shortOnTheSpot both ask first.
    bool shortFromOdometry(const Prediction& prediction, const Registration& icp) const;
    /// ICP from the odometry's step ended with less than keyframe_min_overlap of the scan on
    /// the submap, and that step turned the way the robot's last motion did but less, by more
    /// than the second opinion's turned starts reach (2 second_opinion_turn): a reading
    /// mid-turn that fell short of the turn, and ICP that stayed near it on too little of the
    /// scan (short_turn_second_opinion).
    bool shortOfTurn(const Prediction& prediction, const Registration& icp) const;
    /// ICP from the odometry's step ended with less than keyframe_min_overlap of the scan on
    /// the submap, that step is a turn on the spot (at most OdometryLag::kMovedDistance, more
    /// than second_opinion_turn), and this log's odometry has jumped (kJumpPriorCases clear jump
    /// choices): a lagging heading may have read a fraction of the turn, and on the spot
    /// nothing in the step says how much (spot_turn_second_opinion).
    bool shortOnTheSpot(const Prediction& prediction, const Registration& icp) const;
    /// ICP that converged, or ended with a residual within kUnsettledResidualRatio of the
    /// recent registrations' (or before there are enough to judge); tryIcp's "unsettled" is
    /// its negation.
    bool settled(const IcpAttempt& attempt) const;
    /// `prediction`, or the same with the robot's last motion instead of the odometry's step
    /// (kept in motionPrediction_) when the two are farther apart than ICP reaches and ICP
    /// from the last motion ends where ICP from the odometry does, or puts
    /// second_opinion_margin more of `scan` on the submap, or passes tryIcp()'s overlap and
    /// correction tests and puts more of `scan` on it where ICP from the odometry fails them
    /// (confirm_large_corrections). After an odometry jump, jumpBorneOut() instead; in a stall,
    /// standstillBorneOut() (predict_stalls_by_last_motion). When it
    /// compared the two, `started` gets the ICP run from the prediction returned, so that it
    /// is not run again.
    const Prediction& preferredPrediction(const matching::PolarScan& scan,
                                          const mrpt::poses::CPose2D& sensorOnRobot,
                                          const Prediction& prediction,
                                          std::optional<IcpAttempt>& started);
    /// After an odometry jump (`prediction` is the last motion): the same with the odometry's
    /// own step (kept in motionPrediction_) when ICP from it passes tryIcp()'s overlap and
    /// correction tests (the sideways bound grown with the step beyond odometry_jump_distance:
    /// the odometry's sideways error grows with the distance) and ends where ICP from the last
    /// motion does, or puts jump_choice_margin more of `scan` on the submap, or ICP from the
    /// last motion fails those tests (but the sideways bound) (confirm_large_corrections);
    /// then `started` gets that ICP run. Otherwise `prediction`.
    const Prediction& jumpBorneOut(const matching::PolarScan& scan,
                                   const mrpt::poses::CPose2D& sensorOnRobot,
                                   const Prediction& prediction,
                                   std::optional<IcpAttempt>& started);
    /// In an odometry stall (`prediction` is a standstill): the same with the robot's last
    /// motion (kept in motionPrediction_) unless that motion translated at most
    /// OdometryLag::kMovedDistance (a turn the laser fixes anywhere), or ICP from both ends
    /// at the same pose, or ICP from the standstill puts second_opinion_margin more of `scan`
    /// on the submap, or only ICP from the standstill passes tryIcp()'s tests and it puts more
    /// of `scan` on the submap (the robot stopped turning during the stall).
    /// `started` gets the ICP run from the prediction returned.
    const Prediction& standstillBorneOut(const matching::PolarScan& scan,
                                         const mrpt::poses::CPose2D& sensorOnRobot,
                                         const Prediction& prediction,
                                         std::optional<IcpAttempt>& started);
    /// After an odometry jump that jumpBorneOut() did not bear out because ICP from the
    /// odometry's step failed tryIcp()'s tests, and the graph matcher did not answer
    /// either: ICP from starts between the last motion and the odometry's step
    /// (jump_search_step apart in heading, icp_max_distance in position). An end with the
    /// overlap and within the correction bounds (not the sideways one: the starts are off
    /// the arc the robot turned on) that another start, or ICP from the odometry's step,
    /// also reached, and that puts second_opinion_margin more of `scan` on the submap than
    /// ICP from the last motion (or more, where that ICP fails the tests), is the prediction
    /// (the best such end; `started` gets its ICP run). Otherwise `prediction`.
    const Prediction& jumpBetween(const matching::PolarScan& scan,
                                  const mrpt::poses::CPose2D& sensorOnRobot,
                                  const Prediction& prediction, std::optional<IcpAttempt>& started);
    /// ICP from Prediction::pastMissedTurn, taken where it passes step 1's tests.
    bool tryPastMissedTurn(const matching::PolarScan& scan,
                           const mrpt::poses::CPose2D& sensorOnRobot, const Prediction& prediction,
                           Registration& out);
    /// After an odometry jump that neither ICP from the odometry's step, the graph matcher nor
    /// jumpBetween() placed, where the last scan's registered motion departed from its reading
    /// by more than OdometryLag::kAgreeDistance or kAgreeAngle: ICP from the pose of the scan
    /// before the last followed by both readings (jump_over_two_readings). An odometry that
    /// stalls within a scan interval reads too little of a step and the rest with the next;
    /// applied where registration placed the scan in between (turned as the robot did, not as
    /// the odometry read), the second reading alone is off by the first one's error, while
    /// the two together are the robot's motion over both intervals. The end is the prediction
    /// (`started` gets its ICP run) when it passes tryIcp()'s overlap and correction tests,
    /// the sideways bound grown with the two steps' length, and ends where ICP from the last
    /// motion does, or puts jump_choice_margin more of `scan` on the submap, or ICP from the
    /// last motion fails those tests (but the sideways bound). Otherwise `prediction`.
    const Prediction& jumpOverTwoReadings(const matching::PolarScan& scan,
                                          const mrpt::poses::CPose2D& sensorOnRobot,
                                          const Prediction& prediction,
                                          std::optional<IcpAttempt>& started);
    /// `prediction` with the predicted step since the last scan followed by `shift` (robot
    /// frame), kept in motionPrediction_: the alternatives preferredPrediction() and
    /// jumpBorneOut() choose.
    const Prediction& shifted(const Prediction& prediction, const mrpt::poses::CPose2D& shift);
    /// Median residual RMS of the last accepted ICP registrations (m; 0 before there are
    /// enough): the scale of "a residual well above the recent ones" for this laser and place.
    double typicalResidual() const;

    const GraphSlamOptions& options_;
    /// Residual RMS of the last accepted ICP registrations (m), a ring.
    std::array<double, 101> recentResiduals_{};
    std::size_t residualCount_ = 0;
    bool icpUnsettled_ = false;  ///< the last ICP registration tryIcp accepted had not settled
    /// Robot pose (submap frame) where the last ICP that tryIcp rejected ended; empty when
    /// tryIcp accepted, or did not run ICP.
    std::optional<mrpt::poses::CPose2D> failedIcp_;
    /// Where ICP from a jumped odometry's step ended when it failed tryIcp()'s tests
    /// (jumpBorneOut(); reset for every scan).
    std::optional<mrpt::poses::CPose2D> jumpedIcpEnd_;
    /// After an odometry jump, ICP from the odometry's step when it did not become the
    /// prediction (jumpBorneOut(); reset for every scan).
    std::optional<IcpAttempt> readingIcp_;
    /// After an odometry jump, ICP from the last motion (icpFromLastMotion(); reset for every
    /// scan).
    std::optional<IcpAttempt> motionIcp_;
    /// This scan's jump went before the log's prior once (recordJumpChoice(); reset for every
    /// scan): a jump is one case, however many of the jump's steps ask.
    bool jumpChoiceRecorded_ = false;
    /// This scan's jump was taken as read by the log's prior (jumpBorneOut(); reset for every
    /// scan).
    bool jumpByPrior_ = false;
    /// This scan's jumped reading passed the sideways bound only with chordTurnAllowance()
    /// (jumpBorneOut(); reset for every scan).
    bool jumpSidewaysByTurn_ = false;
    /// In a stall, ICP from the standstill and from the last motion ended at the same pose,
    /// nearer the last motion's start: that start, in the submap frame (standstillBorneOut();
    /// reset for every scan). checkAlongHeading measures ICP's correction from it.
    std::optional<mrpt::poses::CPose2D> stallStepBorneOut_;
    /// ... where the step turned by less than this (rad, 5 deg): a step straight on.
    static constexpr double kStraightStepTurn = 5 * M_PI / 180;
    /// This log's jumps the scan decided clearly (recordJumpChoice): ICP from the odometry's
    /// step fitted jump_choice_margin better than ICP from the last motion, or the reverse.
    /// Whether a log's odometry is right at its jumps (long steps at a low scan rate) or off
    /// (a stall caught up) is a property of the log; keepJumpedReading asks it where the scan
    /// cannot tell, and registerScan where nothing registered the scan at all.
    int jumpsForOdometry_ = 0, jumpsForLastMotion_ = 0;
    /// ... once the odometry's step has won this many times, and more than twice as often.
    static constexpr int kJumpPriorCases = 3;
    /// This log's odometry has jumped: kJumpPriorCases clear jump choices either way (the
    /// rules for a lagging heading ask it: tryTurnedStarts, shortOnTheSpot).
    bool odometryHasJumped() const {
        return jumpsForOdometry_ + jumpsForLastMotion_ >= kJumpPriorCases;
    }
    /// A jumped reading nothing registered is kept by that prior only when no longer than this
    /// times the longest motion registered at the last ten scans: a catch-up after a stall
    /// adds the stalled motion and reads longer than the robot ever steps.
    static constexpr double kReadingWithinRecentSteps = 1.2;
    /// This log's jumps have mostly been the odometry's own steps (see above).
    bool odometryUsuallyRight() const {
        return jumpsForOdometry_ >= kJumpPriorCases && jumpsForOdometry_ > 2 * jumpsForLastMotion_;
    }
    Prediction motionPrediction_;  ///< shifted()'s prediction
    /// secondOpinion()'s starts at most: the last motion, the matcher's answer, eight turns.
    static constexpr std::size_t kMaxSecondStarts = 10;
    /// jumpBetween()'s starts: at most this many intervals (a 120 deg catch-up at 15 deg).
    static constexpr int kMaxJumpIntervals = 8;
    std::array<IcpAttempt, kMaxJumpIntervals - 1> betweenAttempts_;  ///< reused
    matching::PointToLineIcp icp_;
    matching::IcpOptions icpOptions_;
    matching::GraphScanMatcher matcher_;
    ForegroundObjectOptions foregroundOptions_;
    ForegroundObjects foreground_;
    matching::PolarScan background_;  ///< the scan without its foreground objects (reused)
};

template <typename ExtractFeatures>
Registration ScanRegistration::registerScan(const matching::PolarScan& scan,
                                            const mrpt::poses::CPose2D& sensorOnRobot,
                                            const Prediction& odometryPrediction,
                                            ExtractFeatures&& extractFeatures,
                                            features::ScanFeatures& features) {
    Registration out;
    std::optional<IcpAttempt> started;
    const Prediction& prediction =
        preferredPrediction(scan, sensorOnRobot, odometryPrediction, started);
    out.jumpBorneOut = odometryPrediction.odometryJumped && !prediction.odometryJumped;
    out.jumpByPrior = out.jumpBorneOut && jumpByPrior_;
    out.jumpSidewaysByTurn = out.jumpBorneOut && jumpSidewaysByTurn_;
    out.byLastMotion = !out.jumpBorneOut && &prediction != &odometryPrediction;
    if (!prediction.odometryJumped &&
        tryIcp(scan, sensorOnRobot, prediction, out, started ? &*started : nullptr)) {
        const bool shortTurn = shortOfTurn(prediction, out);
        const bool onTheSpot = shortOnTheSpot(prediction, out);
        if ((!icpUnsettled_ && !shortTurn && !onTheSpot) || !prediction.lastKeyframe)
            return out;  // icpUnsettled_ is set only with second_opinion on
        out.unsettled = icpUnsettled_;
        out.shortOfTurn = shortTurn;
        out.shortOnTheSpot = onTheSpot;
        extractFeatures(features);
        Registration matched;
        const bool found =
            tryGraphMatcher(scan, sensorOnRobot, prediction, features, nullptr, matched);
        if (secondOpinion(scan, sensorOnRobot, prediction, found ? &matched : nullptr, out,
                          shortTurn))
            return out;
        // Settled from no start, and ten sigmas or more off the odometry's step: no pose fits
        // the scan clearly (people close around the laser), and the odometry knows better.
        failedIcp_ = out.pose;
        out.unsettledRefused = true;
        out.secondStart = false;
        out.overlap = 0;
    }
    if (prediction.lastKeyframe) {
        extractFeatures(features);
        const mrpt::poses::CPose2D* failedIcp =
            prediction.odometryJumped || !failedIcp_ ? nullptr : &*failedIcp_;
        if (tryGraphMatcher(scan, sensorOnRobot, prediction, features, failedIcp, out))
            return out;
    }
    // Neither ICP from the jumped odometry's step nor the matcher placed the scan: the
    // odometry may have caught up past the turn or short of it.
    std::optional<IcpAttempt> between;
    const Prediction& searched = jumpBetween(scan, sensorOnRobot, prediction, between);
    if (between && tryIcp(scan, sensorOnRobot, searched, out, &*between)) {
        out.jumpBetween = true;
        return out;
    }
    // Or the reading before it fell short of the step, and this one holds the rest (a stall
    // within a scan interval): both readings together are the robot's motion.
    std::optional<IcpAttempt> both;
    const Prediction& overBoth = jumpOverTwoReadings(scan, sensorOnRobot, prediction, both);
    if (both && tryIcp(scan, sensorOnRobot, overBoth, out, &*both)) {
        out.jumpOverTwoReadings = true;
        return out;
    }
    // Or, no jump, short readings before it missed part of the turn and this reading holds
    // it on top of its own turn: ICP from the reading less that turn.
    if (tryPastMissedTurn(scan, sensorOnRobot, prediction, out))
        return out;
    // Or it did not jump at all, and the step went where the scan sees little of the submap.
    if (keepJumpedReading(scan, sensorOnRobot, prediction, out))
        return out;
    if (keepCaughtUpReading(scan, sensorOnRobot, prediction, out))
        return out;
    // Or the odometry missed part of a turn (its heading stalled within the interval) by more
    // than ICP's basin: ICP from the prediction turned further either way.
    if (tryTurnedStarts(scan, sensorOnRobot, prediction, out))
        return out;
    out.method = RegistrationMethod::Odometry;
    out.reference = prediction.lastKeyframe ? prediction.lastKeyframe->id : 0;
    // The last motion, preferred to the odometry's step before ICP failed from it, has lost
    // what made it preferable: the odometry's own step is the better guess (not in a stall or
    // after a jump, where the odometry's step is not the robot's).
    const bool odometryRather = out.byLastMotion && odometryPrediction.odometryPredicted &&
                                !odometryPrediction.odometryStalled;
    out.pose = (odometryRather ? odometryPrediction : prediction).fromLastKeyframe;
    // After a jump nothing placed, the log's earlier jumps decide between the last motion and
    // the odometry's reading, as where ICP could not (keepJumpedReading): a robot whose long,
    // sharp steps the scans have borne out again and again made this one too, unless the
    // reading is longer than the robot has stepped lately (a stall caught up, a glitch).
    if (prediction.odometryJumped && odometryUsuallyRight() &&
        prediction.readingStep.norm() <= kReadingWithinRecentSteps * prediction.longestRecentStep) {
        out.pose = prediction.fromLastKeyframe + prediction.toReading();
        out.jumpReadingKept = true;
    }
    out.covariance =
        odometryCovariance(prediction.distanceFromLastKeyframe, prediction.turnFromLastKeyframe);
    out.rawCovariance = out.covariance;
    return out;
}

}  // namespace toposlam::mapping
