#pragma once
// Settings of the graph SLAM (GraphSlamInput, CGraphSlamBuilder), one .ini section ([GraphSlam] in
// config_ini/toposlam-slam.ini, every key commented there). Units: m, and degrees in the file
// (keys ending in _deg), radians in code. Loading is strict (config/Options.h).
#include <toposlam/config/Options.h>
#include <toposlam/mapping/OdometryCalibration.h>
#include <toposlam/matching/LineMap.h>
#include <toposlam/matching/PointToLineIcp.h>

#include <cmath>
#include <cstddef>
#include <string>

namespace toposlam::mapping {

/// m: a beam must reach this far beyond a submap point to have seen through it
/// (free_space_carving, along_heading_free_space): a person is 0.3-0.5 m across, and a wall's
/// point seen again lies within the laser's noise and the keyframes' few centimetres of error of
/// where it was.
inline constexpr double kSeenThroughMargin = 0.2;

struct GraphSlamOptions : public config::Options {
    // --- Front end: keyframes and local submaps ---
    double keyframeDistance = 0.3;  ///< m travelled since the last keyframe
    double keyframeAngle = 0.2618;  ///< rad turned since the last keyframe (15 deg)
    /// A scan becomes a keyframe when less than this share of its points lies on the local
    /// map (new ground comes into view), even before the distance/angle rule.
    double keyframeMinOverlap = 0.6;
    /// Keyframes per submap. Two submaps are active and overlap by half: a scan is matched
    /// against the older (fuller) one, keyframes go into both.
    std::size_t submapKeyframes = 20;
    /// A keyframe placed by odometry alone starts a part of each submap it goes into, and a
    /// scan registered on a submap is tied to the start of the part most of its readings lie
    /// on (Submap.h), not always to the anchor (false: always to the anchor, and the previous
    /// keyframe's edge at ICP's covariance).
    bool submapParts = true;
    double mapResolution = 0.05;    ///< m, lookup cells of the submaps' line maps
    double mapFuseDistance = 0.05;  ///< m, observations this close to a map point are fused
    /// m: a map point counts one more view when another keyframe puts a reading this close.
    double mapConfirmDistance = 0.1;
    double mapMaxRange = 20;  ///< m, farther readings are not put into submaps...
    /// ... unless more than this share of a scan's valid readings lie farther: then all of
    /// them (an open hall, a long-range laser; MapRange.h).
    double mapFarShare = 0.1;

    // --- Front end: registration ---
    int icpMaxIterations = 30;
    double icpMaxDistance = 0.4;   ///< m, association gate of the first stage
    double icpRobustScale = 0.05;  ///< m, Cauchy kernel scale
    std::size_t icpStride = 2;     ///< every stride-th point in the first stage
    /// ICP's first stage matches only submap points seen from this many keyframes (1 = all):
    /// a person walking along with the robot is somewhere else in every keyframe, a wall is not.
    /// Opt-in: walls new to the last keyframe drop out of that stage too. This and the next
    /// rule are the "crowded places" settings of config_ini/toposlam-slam.ini.
    std::size_t icpMinViews = 1;
    /// Submap points that later keyframes saw through (Submap.h: a person who walked on) are
    /// left out of ICP's first stage, as icpMinViews leaves out points seen once. Opt-in: it
    /// helps people walking about, and costs a short, noisy laser (benchmarks.md, B3).
    bool freeSpaceCarving = false;
    /// rad: submap points whose surface faces the scan's sensor at a larger incidence are not
    /// matched (the faces of a rough wall that looked back along a corridor; 90 deg and more:
    /// surfaces seen from behind).
    double icpMaxIncidence = M_PI;  ///< 180 deg = off (80 deg for crowded places, see the ini)
    /// When ICP has not settled (no convergence, and a residual well above the recent ones),
    /// also start it from the graph matcher's answer and from the prediction turned by +-1 and
    /// +-2 second_opinion_turn; the start that puts at least secondOpinionMargin more of the
    /// scan's readings on the submap replaces it (an odometry heading off by 10-15 deg in one
    /// fast-turning step, seen on mit-csail).
    bool secondOpinion = true;
    double secondOpinionMargin = 0.25;
    double secondOpinionTurn = 0.15;  ///< rad (8.6 deg)
    /// ICP that ended on less than keyframeMinOverlap of the scan, settled or not, from a
    /// reading that turned the way the last motion did but less by more than 2
    /// secondOpinionTurn (a reading mid-turn that fell short of it), gets the second opinion,
    /// with one more start: the last motion (ScanRegistration::shortOfTurn).
    bool shortTurnSecondOpinion = true;
    /// ICP that ended on less than keyframeMinOverlap of the scan from a reading of a turn on
    /// the spot (at most 2 cm, more than secondOpinionTurn) gets the second opinion too, in a
    /// log whose odometry has jumped (ScanRegistration::kJumpPriorCases clear jump choices): a
    /// turn on the spot the odometry read short, where nothing along the heading tells ICP so
    /// (ScanRegistration::shortOnTheSpot).
    bool spotTurnSecondOpinion = true;
    /// Where none of the second opinion's starts settled, also start ICP from the prediction
    /// turned by +-3 and +-4 secondOpinionTurn, with the same margin and jump bounds: a short
    /// reading that missed 25-35 deg of a turn, which the nearer starts do not reach.
    bool secondOpinionWideTurns = true;
    /// The second opinion's answer is refused (the scan goes to the graph matcher) where ICP
    /// from one of its starts ended beyond the jump bounds (odometryJump*) on
    /// secondOpinionMargin more of the scan: the answer is one poor fit among others. Both fits
    /// are counted on the submap before its newest part: a keyframe placed by odometry alone
    /// starts one, and the copy of the place it adds is turned with its error.
    bool secondOpinionRefutedBeyondJump = true;
    /// Where ICP from the prediction failed the registration tests and the graph matcher
    /// answers, ICP also starts from the prediction turned by +-1 and +-2 secondOpinionTurn; an
    /// end that settles, passes min_inlier_ratio and the correction bounds from its start (not
    /// the sideways one), lies within the jump bounds of the prediction and is not where the
    /// failed ICP ended, and puts secondOpinionMargin more of the scan on the submap than the
    /// matcher's answer, replaces that answer (a fast turn the odometry over-read: the matcher
    /// answered 12 deg off, on a turned copy of the room).
    bool matcherSecondOpinion = true;
    /// Right after a stall of whole scans whose reading no rule took for a catch-up, a graph-
    /// matcher answer within the jump bounds of the reading less the motion registered over
    /// the stall is no jump (Prediction::stallCatchUpStep).
    bool matcherBoundedByCatchUp = true;
    /// Where ICP from a jumped reading (the odometry caught up in one step) turns back a turn
    /// the last reading missed (registration turned the last step further than it read), its
    /// sideways bound grows by the step's length x sin(half the turn taken back): the odometry
    /// integrated the step along a heading that lagged, which turns the step's chord by about
    /// half the lag (ScanRegistration::chordTurnAllowance).
    bool jumpSidewaysByTurn = true;
    /// The second opinion's answer (unsettled ICP from the prediction, or a second start) that
    /// corrects the odometry's step by more than this chi-square (3 dof) of the odometry model
    /// for that step (odometry_sigma_*) counts only where one of the second starts settled;
    /// otherwise the scan goes to the graph matcher, then keeps the odometry. Applies where
    /// the odometry's own step was predicted (not the last motion). 0 = off. 100 is ten
    /// sigmas: real odometries erred by up to 9 (mit-csail's 14-16 deg turns, fr079's reversing),
    /// and ICP among people crowding the laser ended 12 off (0.3 m ahead, 17 deg turned), with
    /// every other start unsettled too.
    double unsettledMaxChi2 = 100;
    /// When ICP corrects the prediction by more than this along the robot's heading (m; 0 =
    /// off), it is run again without the scan's small objects close to the laser
    /// (ForegroundObjects.h), and that answer is taken when it keeps less than half of the
    /// correction (ScanRegistration.h): a person walking just ahead stands in the submap where
    /// the next scan sees it again, and ICP fitted to it takes back the robot's step.
    double foregroundCheck = 0.1;
    /// Also when ICP corrects the odometry's step by more than unsettledMaxChi2 of the odometry
    /// model (a turn as well as a step): ICP without the foreground objects is then taken when
    /// it stays within that bound, keeps less than half of the correction (a quarter of its
    /// chi-square) and the rest of the scan fits it at least as well as ICP's answer; if it fits
    /// too little of the scan to pass the tests, the scan goes on as a failed ICP (graph matcher,
    /// then the odometry). People standing close by, whom the submap holds from an earlier
    /// keyframe, turned settled ICP 13.7 deg on a straight step (Bormann's office_d toured with 15
    /// people, seed 31: ATE 1.15 -> 0.08 m).
    bool foregroundBeyondOdometry = true;
    double foregroundMaxRange = 1.5;  ///< m: such an object's nearest reading, at most
    double foregroundMaxWidth = 0.8;  ///< m: its width (first to last reading), at most
    /// A correction along the robot's heading of more than this (m; 0 = off) must be borne
    /// out by the scan: when, at the odometry's position along the heading (with ICP's
    /// sideways and turn correction), no more than alongHeadingMargin of the readings fewer
    /// lie on the submap than at ICP's pose, that position is taken. Along a corridor whose
    /// walls fix nothing along it, ICP slides by tenths of a metre on a few stray matches
    /// (Bormann's offices, simulated tours: 1.5-2.7 m over one corridor). The margin is wide:
    /// such slides often fit a few percent more readings than the truth.
    double alongHeadingCheck = 0.1;
    double alongHeadingMargin = 0.1;  ///< share of the scan's readings
    /// ... or when, at ICP's pose, the scan sees through at least this share of its readings
    /// more submap points than at the odometry's position (LineMap::countSeenThrough, beams
    /// reaching kSeenThroughMargin beyond them): the slide puts free space where the submap
    /// holds surfaces that the scans before it saw. 0 = off. A slide often fits more readings
    /// because the place it slid to has more surfaces near them, true or not; free space seen
    /// through a wall is evidence that no fit outweighs.
    double alongHeadingFreeSpace = 0.1;
    /// A registration is good when at least this share of the scan's valid points ends on
    /// the local map...
    double minInlierRatio = 0.35;
    /// ... and the correction of the prediction stays within these bounds.
    double maxCorrectionDistance = 0.5;  ///< m
    double maxCorrectionAngle = 0.35;    ///< rad (20 deg)
    /// ... and moves the robot sideways (across its predicted heading) by at most this (m;
    /// 0 = no limit, for robots that can move sideways). Wheels do not slide sideways: ICP
    /// that says so has locked onto the wrong structure (seen in fast turns on mit-csail).
    double maxLateralCorrection = 0.06;
    /// Odometry increments larger than this between two scans, and as far from the robot's
    /// last registered motion (at a low scan rate every step is long), are jumps, not motion:
    /// the prediction is then the last motion and the graph matcher registers the scan. Without
    /// a jump, a graph-matcher answer that corrects the prediction by more is not used.
    double odometryJumpDistance = 0.5;  ///< m
    double odometryJumpAngle = 0.7854;  ///< rad (45 deg)
    /// Corrections of the odometry's step beyond the bounds above, when the submap confirms
    /// them (odometry that counts reversing as driving forward, as fr079's, is off by twice
    /// the step):
    ///  - the graph matcher's answer, up to twice the jump bounds, when ICP started there
    ///    agrees with it within the correction bounds and ends where ICP from the prediction
    ///    did, or puts at least secondOpinionMargin more of the scan's readings on the submap
    ///    (where ICP from the prediction already fits, as along a corridor seen the other way
    ///    round, it does neither);
    ///  - the robot's last registered motion instead of the odometry's step as the
    ///    prediction, when the two are farther apart than icpMaxDistance and ICP from the
    ///    last motion ends where ICP from the odometry does or fits by that margin better.
    bool confirmLargeCorrections = true;
    /// After an odometry jump (confirm_large_corrections), the scan chooses between the
    /// odometry's step, the robot's last motion and the graph matcher's answer: one is
    /// preferred over another when ICP on the submap from it puts this share more of the
    /// scan's valid readings within 5 cm of the submap. At a low scan rate a real step departs
    /// from the last motion by as much as a jump, and the two fit alike only where the scan
    /// sees new ground (ScanRegistration::jumpBorneOut, jumpMatchRefused, keepJumpedReading).
    double jumpChoiceMargin = 0.05;
    /// Where ICP from the prediction was rejected for too little of the scan on the submap
    /// (its correction within the bounds above) and the graph matcher answers elsewhere, the
    /// answer must be borne out without the scan's foreground objects (foregroundMaxRange,
    /// foregroundMaxWidth): ICP on the submap started at the answer ends where ICP from the
    /// prediction did, or the rest of the scan puts alongHeadingMargin more of its readings
    /// on the submap there; otherwise the scan keeps the prediction. People walking along
    /// with the robot stand in the last keyframe one step back, and the matcher, fitted to
    /// them, takes back the robot's step along a corridor whose walls fix nothing along it.
    bool matcherForegroundCheck = true;
    /// After an odometry jump that neither ICP from the odometry's step (confirm_large_corrections)
    /// nor the graph matcher places, ICP also starts between the odometry's step and the last
    /// motion, at most this far apart in heading (rad; 0 = off) and icpMaxDistance in
    /// position: a stalled odometry that catches up in one step overshoots the turn or falls
    /// short of it, and the robot turned somewhere between. An end two starts reach is taken
    /// if it puts secondOpinionMargin more of the scan on the submap than ICP from the last
    /// motion (ScanRegistration::jumpBetween).
    double jumpSearchStep = 15 * M_PI / 180;
    /// After an odometry jump that nothing above places, where the last scan's registered
    /// motion departed from its reading: ICP also starts from the scan before the last
    /// followed by both readings, an odometry that stalled within a scan interval having read
    /// too little of a step and the rest with the next (ScanRegistration::jumpOverTwoReadings).
    bool jumpOverTwoReadings = true;
    /// Where nothing above placed a scan predicted by the odometry's step, and short readings
    /// before it missed part of the registered turn (more than 10 deg) that this reading turned
    /// farther than, the same way: ICP also starts from the step less that turn
    /// (ScanRegistration::tryPastMissedTurn). A lagging odometry delivers a missed turn with a
    /// step of the robot's length, so it is no catch-up (OdometryLag::catchesUpShortfall).
    bool missedTurnStart = true;
    /// Where nothing above placed a scan predicted by a reading at least 0.6 times as long as the
    /// last motion (the wheels read the step; only the heading may have lagged), in a log whose
    /// odometry has jumped at least three times (clear jump choices), ICP also
    /// starts from the reading turned by +-1 to +-4 x secondOpinionTurn; taken where every
    /// start that settled within the jump bounds ended at the same pose, at least two did, and
    /// it went no farther sideways than the turn swings the step's chord
    /// (ScanRegistration::tryTurnedStarts).
    bool turnedStartSearch = true;
    /// After an odometry jump where ICP from the odometry's step and from the last motion both
    /// pass and neither fits jumpChoiceMargin better, the odometry's step is the prediction when
    /// this log's earlier clear jumps were mostly the odometry's own steps, before the graph
    /// matcher is asked (ScanRegistration::priorFavoursReading). Along a corridor ICP holds
    /// wherever it starts, and so does the matcher's answer confirmed on the submap: a stalled
    /// odometry's catch-up, taken for the last motion, lost the distance it caught up.
    bool undecidedJumpByPrior = true;
    /// Where the last keyframe was placed by odometry alone (Keyframe::placedByOdometry), the
    /// graph matcher matches the scan against the newest keyframe a registration placed first,
    /// and against the last one only when that finds nothing. A stall during a turn leaves
    /// such a keyframe tens of degrees off; an answer relative to it keeps the error.
    bool matcherFromRegisteredKeyframe = true;
    /// A scan of an odometry stall (Prediction::odometryStalled) that nothing placed does not
    /// become a keyframe, whatever keyframeDistance and keyframeAngle say: it kept the last
    /// motion, which may be tens of degrees off where the robot turned, and as a keyframe its
    /// readings would go into the submap (the next scans registered partly on them) and be the
    /// graph matcher's reference. The next scan that qualifies is the keyframe.
    bool deferKeyframeInStall = true;
    /// An odometry reading is a jump only where it is out of step with the reading before it
    /// (OdometryLag::inStep): at a low scan rate every step is beyond the jump bounds, and
    /// after one scan registration placed short along a corridor, each step in step with the
    /// one before departed from the (short) registered motion, was taken for a jump, and the
    /// robot stayed where it was for scan after scan.
    bool jumpOnlyOutOfStep = true;
    /// The first odometry reading after readings that repeated exactly (a stall) is the motion
    /// since the last reading that changed. Where registration saw less of the stall than that
    /// (along a corridor its scans keep the stall's standstill or go part of the way; where it
    /// saw the robot turn, only if the reading turned as far), the step predicted is that
    /// reading less the motion registered meanwhile, not the last motion, and the stall's
    /// scans registration left behind are placed between (OdometryLag.h,
    /// GraphSlam::placeStalledScans).
    bool bridgeOdometryStalls = true;
    /// A stall whose scans no registration placed (neither ICP nor the graph matcher: each
    /// kept the last motion) is bridged like one registration saw nothing of, whatever turn
    /// the last motion carried on: the turn was guessed, not seen (OdometryLag::
    /// stallUnplaced). Its scans are then placed between, their headings spread over the
    /// turn too. Off: such a stall counts as registered, and a reading that turned otherwise
    /// than the guess is not bridged.
    bool bridgeUnplacedStalls = true;
    /// A stall whose scans ICP placed none of (the graph matcher alone, or nothing) is bridged
    /// like one nothing placed where the first reading after it turned otherwise than the
    /// stall's scans were registered by more than odometryJumpAngle per scan interval it spans
    /// (OdometryLag::stallTurnRefuted): in a place that looks alike turned by 90 deg (a square
    /// room, a crossing) the guess-free matcher may take the turned look-alike, and the reading is
    /// the only other evidence of the turn. Its scans that are no keyframes are placed between; a
    /// keyframe among them stays where the graph has it (keeping the matcher's stall scans out
    /// of the submap broke far more tours than it mended, benchmarks.md B3).
    bool bridgeRefutedStalls = true;
    /// A catch-up after a stall that bridgeOdometryStalls' tests leave alone is bridged all the
    /// same where it is as long as the translation registered over the stall plus a step of the
    /// last motion's length, within 0.2 m, whatever it turned (OdometryLag::holdsStallAndStep):
    /// registration saw the stall right, the reading holds all of it, and the robot turned in
    /// the reading's own interval otherwise than over the stall. After a last motion of 0.2 m
    /// or less (a turn on the spot, a slow robot) the step the reading leaves must also turn
    /// as the last motion did, within 10 deg.
    bool bridgeStallAndStep = true;
    /// In the first catch-up after a stall whose scans a registration placed, where nothing
    /// from the last motion (the catch-up's prediction) nor from the reading placed the scan:
    /// ICP also starts from the reading less the motion registered over the stall
    /// (OdometryLag::stepSinceStall). The reading holds the stall's motion on top of its own,
    /// and a robot that stopped and turned on the spot after the stall is neither where the
    /// last motion nor where the reading from the last scan puts it.
    bool catchUpLessStall = true;
    /// A stalled reading (repeated exactly while the robot moved, and the scan changed:
    /// OdometryLag::scanChanged, not a robot that stopped) says nothing about the motion: ICP
    /// also starts from the last registered motion, and the standstill stays only where the
    /// scan fits it by secondOpinionMargin more or both starts end together
    /// (ScanRegistration::standstillBorneOut); the stalled reading is no odometry for the
    /// scans between keyframes either. Not after a turn on the spot (the laser fixes turns).
    bool predictStallsByLastMotion = true;
    /// Odometry noise (standard deviations) for edges that only odometry supports: a floor,
    /// plus a share of the distance travelled and of the angle turned.
    double odometrySigmaXY = 0.02;           ///< m
    double odometrySigmaXYPerMetre = 0.05;   ///< m per m
    double odometrySigmaPhi = 0.0175;        ///< rad (1 deg)
    double odometrySigmaPhiPerRadian = 0.1;  ///< rad per rad
    /// Smallest standard deviations of a registration edge: ICP's own covariance is far too
    /// confident (it ignores the map's errors).
    double edgeMinSigmaXY = 0.01;     ///< m
    double edgeMinSigmaPhi = 0.0035;  ///< rad (0.2 deg)
    /// Opt-in, for crowded places: a keyframe whose scan sees foreground objects
    /// (foregroundMaxRange, foregroundMaxWidth: people close by, mostly) has registration edges
    /// this many times as uncertain as the edge floor ((factor^2 - 1) times the floor's
    /// variances added). A person can pull ICP off by centimetres where its covariance says
    /// millimetres; the graph then corrects a loop's error mostly there, not evenly along the
    /// path. Off by default: the wider edges widen the loop gate too, and a short laser that
    /// sees furniture close by at half its keyframes let wrong loops in (benchmarks.md, B3,
    /// "Edges among people"). 1 = off.
    double foregroundEdgeSigmaFactor = 1;
    /// Output: re-estimate the positions of the scans between keyframes from their
    /// registration and the odometry together, each by its noise model above
    /// (TrajectorySmoother.h); keyframes and headings stay as the graph has them.
    bool smoothScans = true;
    /// The odometry's distance scale, learnt from the well-registered scans and applied to
    /// the prediction (OdometryCalibration.h).
    OdometryCalibration::Options odometryCalibration;

    // --- Loop closure ---
    bool loopClosure = true;
    /// Older keyframes are candidates only beyond this much travel along the trajectory and
    /// outside the active submaps.
    double loopMinTravel = 5;  ///< m
    /// Keyframes within this distance see enough of the same place to be matched.
    double loopOverlapDistance = 3;     ///< m
    double loopGateSigmas = 3;          ///< Mahalanobis gate of the relative pose uncertainty
    std::size_t loopMaxCandidates = 3;  ///< candidates verified per keyframe (nearest first)
    /// Loop search runs on every this-many-th keyframe (consecutive keyframes see the same
    /// place; one loop every few is as good as one on each, at a fraction of the cost).
    std::size_t loopSearchEvery = 2;
    /// Threads that verify loop candidates (the caller included). The loops found are the
    /// same for any number; 2 uses the second core of a small robot computer.
    std::size_t loopThreads = 2;
    /// Drift model. Two loops found along a path of length L turning by T may disagree by a
    /// random walk's a sqrt(L) in position and sqrt(b^2 L + c^2 T) in heading (loopGateSigmas
    /// of them, beyond the pair tolerances). The loop gate's uncertainty, propagated through
    /// the graph (PathUncertainty.h), adds at least (a l)^2 and (b l)^2 for an edge of length
    /// l, a narrower gate that keeps look-alike places out.
    double driftSigmaXY = 0.05;          ///< a, m per sqrt(m)
    double driftSigmaPhi = 0.01;         ///< b, rad per sqrt(m) (0.57 deg)
    double driftSigmaPhiPerTurn = 0.02;  ///< c, rad per sqrt(rad) (1.15 deg)
    /// Guess-free search against the keyframes outside the gate every this many keyframes
    /// (0 = off), matching the globalSearchCandidates most similar ones.
    std::size_t globalSearchEvery = 0;
    std::size_t globalSearchCandidates = 4;
    /// Smallest standard deviations of a loop edge (the graph matcher's covariance is as
    /// confident as ICP's).
    double loopMinSigmaXY = 0.03;     ///< m
    double loopMinSigmaPhi = 0.0087;  ///< rad (0.5 deg)
    /// Candidates chosen for verification are at least this far apart, so that look-alike
    /// places inside the gate are tried too and an ambiguity shows.
    double loopCandidateSpacing = 1.0;  ///< m
    /// Chi-square (3 degrees of freedom) bound on a new loop's disagreement with the graph (the
    /// gate). 16.27 = 99.9 %.
    double loopChi2 = 16.27;
    /// A loop outside the gate is let in where the path's full covariance explains it within
    /// loopChi2: each edge's heading variance swung by its lever arm to the current keyframe,
    /// which moves it and turns it alike (PathVariance::swung), and where it is off by a turn
    /// and no more shift than that turn makes across the chain's reach plus what the gate
    /// allows (LoopCloser::swungByTurn). Back round a building the two keyframes are close, but
    /// a heading error far along the chain moved the current one by far more than their
    /// distance says; a look-alike place one door along is a shift without that turn and stays
    /// out. Such loops are added without the robust loss (a right one is many of its own
    /// sigmas off the graph). The candidates and the chains are chosen as without it
    /// (benchmarks.md, B3 "The gate's lever arm").
    bool loopGateLeverArm = true;
    /// After optimisation the worst loop still above this chi-square is withdrawn. Far above
    /// the gate: scan-registration edges are overconfident (their floor is 1 cm), so a right
    /// loop that corrects a front-end error strains against them with a chi-square of 20-90
    /// (seen on fr079), while a loop to the wrong place (0.5 m off at sigma 3 cm) shows
    /// hundreds; withdrawing at the gate's bound removed right loops and left the error in.
    double loopWithdrawChi2 = 200;
    /// Guess-free loops must be confirmed by another guess-free or gated loop within this
    /// many keyframes that agrees with them (pairwise consistency).
    std::size_t loopConfirmWindow = 20;
    double loopPairTolerance = 0.3;          ///< m, disagreement of two loops around their cycle
    double loopPairAngleTolerance = 0.0873;  ///< rad (5 deg)
    /// Gated matches the gate rejected are kept for loopConfirmWindow keyframes; when this
    /// many of them agree pairwise, from at least two searches and against older keyframes of
    /// at least two visits of the place (runs of the path more than loopMinTravel apart),
    /// and past a keyframe the front end doubts (Keyframe::frontEndDoubt) after each older one,
    /// they are accepted together: the front end went wrong by more than the drift model
    /// allows (a step no registration could place, a laser dropout while the wheels slip), and only
    /// loops can repair it (fr079 at a quarter of its scan rate: 0.157 -> 0.029 m). 0 = never:
    /// a rejected match stays rejected.
    std::size_t loopContestedSupport = 4;

    // --- Back end ---
    /// Loop edges carry a Cauchy loss of this scale (in standard deviations), so one wrong
    /// loop cannot drag the graph far before it is withdrawn; 0 = plain least squares.
    double loopLossScale = 3;
    int optimizeMaxIterations = 10;
    /// A loop that disagrees with the graph by more than optimizeTrigger* is optimised at
    /// once over the last optimizeWindow keyframes (older ones hold still: cheap, and right
    /// while the old map is sound); one that disagrees by more than optimizeGlobal* (the
    /// first closure of a long loop) over the whole graph. Loops that agree wait for
    /// optimizeEveryLoops of them. The whole graph is optimised every optimizeGlobalEvery
    /// keyframes that added loops, but not before it has grown by half since the last time
    /// (a whole-graph run costs more the longer the log: their total stays within a few times
    /// the last one's cost), and at the end.
    double optimizeTriggerDistance = 0.1;  ///< m
    double optimizeTriggerAngle = 0.0349;  ///< rad (2 deg)
    double optimizeGlobalDistance = 0.3;   ///< m
    double optimizeGlobalAngle = 0.0524;   ///< rad (3 deg)
    std::size_t optimizeEveryLoops = 30;
    std::size_t optimizeWindow = 200;       ///< keyframes
    std::size_t optimizeGlobalEvery = 500;  ///< keyframes

    /// Feature extractor of the keyframes (features::featureExtractorNames()); its options
    /// come from its own section of the same file.
    std::string extractor = "corners";

    void declare(config::OptionsSchema& s) override;

    /// The line map every submap keeps (mapping::Submap), from these settings.
    matching::LineMapOptions lineMapOptions() const;
    /// ICP of a scan on a submap (ScanRegistration), from these settings.
    matching::IcpOptions icpOptions() const;

  private:
    void declareFrontEnd(config::OptionsSchema& s);
    void declareLoopClosure(config::OptionsSchema& s);
    void declareBackEnd(config::OptionsSchema& s);
};

}  // namespace toposlam::mapping
