#pragma once
// Odometry that stalls, then catches up. Some logs carry the odometry in each laser line as the
// last odometry message received (CARMEN's FLASER lines): when those messages stop for a few
// scans the odometry reads the same while the robot moves on, and when they come back the
// first increments hold the motion of the stall on top of their own (mit-csail: 0.49 m and
// 29 deg in one scan where the robot turned 10). The stall itself does little harm
// (registration finds the motion from a standstill prediction), but a catch-up increment is a
// prediction off by the backlog, and ICP started there can settle at the wrong heading where
// nothing in range says otherwise (mit-csail with its laser clipped at 5.6 m: one scan 20 deg
// off, a corridor mapped at an angle).
//
// A stall is an increment of exactly zero while the robot moved at the last scan (a robot
// standing still reads zero too, but registers no motion). After a stall an increment that is
// longer, or turns farther, than the robot's last registered motion by more than kAgreeDistance
// or kAgreeAngle is taken for catching up, and that motion is predicted instead; the first
// increment within the margins ends it, and so do kMaxCatchUpScans scans. (Only more motion
// counts: a backlog adds to the step, while a robot slowing down reads less, and at a third of
// mit-csail's scan rate its turn rate changes by 15 deg between two scans.) The backlog is the
// motion registered over the stall; once the catch-up increments have delivered all but the
// margins of it (beyond the motion predicted for them), the odometry is in step again. Without
// that bound a catch-up fed itself where registration fell short: along a corridor ICP started
// from a short prediction stays short, the next reading in step then looks far longer than the
// registered motion, and the next prediction is shorter still (ring51, stalling robot, seed 2:
// 1.2 m lost over five scans, ATE 0.38 m).
//
// That holds where registration saw the robot move during the stall. Where nothing fixes the
// motion (along a corridor) the stall's scans stay where the stall left them, or go part of
// the way: the last registered motion is then too short a prediction. (Registration also
// starts the stall's scans from the last motion, ScanRegistration::standstillBorneOut, which
// along a corridor keeps them moving; predict_stalls_by_last_motion.) The first reading after
// the stall holds all the motion since the last reading that changed; so a catch-up after a
// stall in which registration saw no translation, or less than the reading by more than
// kAgreeDistance where the reading turned as far as registration saw (within kAgreeAngle;
// turnedAsRegistered()), is predicted as that reading less the motion registered since
// (bridges(), stepSinceStall(); bridge_odometry_stalls). Where registration left the stall's
// scans short of the reading's share per scan by that margin (stallScansBehind()), they are
// placed between (GraphSlam). Only there: the reading after a stall is not always all of it
// (mit-csail: 7.6 deg where the robot turned 25, the rest in the next readings; 85.5 where it
// turned 68.8: bridged during every turn, mit-csail read by a 5.6 m laser went from 0.032 to
// 0.046 m), and a robot that stopped and set off again reads no catch-up (bridged wherever
// registration saw no translation, intel with every other beam went from 0.017 to 0.044 m).
// A stall whose scans no registration placed (each kept the last motion) saw no turn either:
// whatever turn the last motion carried on was guessed, so its catch-up is bridged and its
// scans placed between, turned evenly too (stallUnplaced(); bridge_unplaced_stalls). So is a
// stall whose scans only the guess-free graph matcher placed, where the reading turned otherwise
// by more than the jump bound of the intervals it spans: the matcher took a look-alike of the
// place turned by 90 deg (stallTurnRefuted(); bridge_refuted_stalls). And so is a reading as
// long as the stall's registered translation plus a step like the last, whatever it turned:
// the lengths add up where registration saw the stall right and the reading holds all of it,
// while the robot may turn in the reading's own interval otherwise than over the stall
// (Bormann's office_a, stalling robot, seed 41: -11 deg over the stall, +19 after it, 1.39 m
// read = 1.05 + 0.34; predicted by the last motion, ICP settled 0.8 m on; holdsStallAndStep(),
// bridge_stall_and_step).
//
// At a low scan rate a stall seldom spans a whole scan interval: the readings are short, not
// zero (Bormann's lab_c toured by the stalling robot at a third of its scan rate: 0.68 m read
// twice where registration saw the robot go 1.02 m), and the next reading holds what they
// missed (1.48 m where the robot went 0.79 m and turned 43 deg; ICP from the last motion,
// 33 deg off, settled 0.36 m off, ATE 0.47 m). Readings short of the registered step by more
// than kMovedDistance add up to a shortfall (one that is not short ends it); a reading longer
// than the last motion by more than kAgreeDistance after a shortfall of more than that is
// predicted as the reading with its translation shortened by the shortfall, where that brings
// it nearer the last motion's length (catchesUpShortfall(), stepPastShortfall()). Its heading
// stays as read (mit-csail's odometry reads no translation for two scans while it reads the
// turn), less the turn the short readings missed where they read less of the registered turn
// and the reading turned farther, the same way (generated plan 61, stalling robot, a third of
// the scans: 0.17 m and 18 deg read where the robot went 0.48 m and turned 54, then 1.30 m and
// 54 deg where it went 1.0 m and turned 13; from the heading as read ICP settled 44 deg off).
// The odometry lags in heading as it does in distance: a short reading that still turned the
// way the robot had turned before missed all of the registered turn and its own (office_d,
// seed 1: 15 deg read where the robot turned 8 deg back), and a short reading that read more
// of the turn than registered delivered part of what an earlier one missed (office_b, seed 7:
// 32 deg missed, then 21 deg read beyond the turn, and the catch-up read 13 deg straight on).
//
// That odometry also stalls in distance alone: 0.004, 0 and 0 m read at three scans where the
// robot went 0.21 m in each 0.21 s, the turn read all along, then 0.834 m. Not zero, so no
// stall above; and along a corridor registration, started from the reading, saw no motion
// either, so no shortfall: with its laser read to 5.6 m the three scans stayed 0.3 m behind.
// A robot cannot slow from 1 m/s to nothing within 0.21 s, so such a reading is a stall of the
// translation (translationStalled(): speeds over intervals alike, beyond kMaxDeceleration) and
// is predicted as a stall is; the scans then register on, fall short of what was registered,
// and the catch-up after them is the shortfall's.
#include <mrpt/poses/CPose2D.h>
#include <toposlam/matching/PolarScan.h>

#include <optional>

namespace toposlam::mapping {

class OdometryLag {
  public:
    /// Registered motion above this (m, rad) per scan is the robot moving, not noise.
    static constexpr double kMovedDistance = 0.02;
    static constexpr double kMovedAngle = 0.0175;  // 1 deg
    /// An odometry increment at most this much (m, rad) longer or farther turned than the last
    /// registered motion has caught up.
    static constexpr double kAgreeDistance = 0.2;
    static constexpr double kAgreeAngle = 0.1745;  // 10 deg
    /// Scans after a stall at most taken for catching up.
    static constexpr int kMaxCatchUpScans = 5;
    /// A reading of at most this translation (m) ...
    static constexpr double kStalledDistance = 0.005;
    /// ... after one of at least this (m) ...
    static constexpr double kStalledAfter = 0.1;
    /// ... that the robot could not have slowed from at this deceleration (m/s^2) within the
    /// scan interval is a stall of the translation.
    static constexpr double kMaxDeceleration = 3.0;
    /// m/s: no robot mapped indoors reads faster; such a speed says the stamps are wrong.
    static constexpr double kMaxSpeed = 5.0;
    /// A reading that changed by more than this (m) between two scans ...
    static constexpr double kChangedRange = 0.1;
    /// ... in at least this share of the beams valid in both: the robot moved between them.
    static constexpr double kChangedShare = 0.02;

    /// True when the odometry's reading `now` is in step with `before`, the reading at the
    /// scan before (both in the robot frame of their last scan): they differ by at most
    /// kAgreeDistance and kAgreeAngle. A jump is a change of the reading, not a departure
    /// from the registered motion alone (GraphSlamOptions::jumpOnlyOutOfStep).
    static bool inStep(const mrpt::poses::CPose2D& before, const mrpt::poses::CPose2D& now);

    /// True when `now` differs from `before` (the scan before it, same laser) by more than
    /// kChangedRange in at least kChangedShare of the beams valid in both: the robot moved.
    /// A robot that stopped reads the same zero as an odometry that stalled, but sees the
    /// same ranges again (along a corridor with nothing along it, a moving robot does too).
    static bool scanChanged(const matching::PolarScan& before, const matching::PolarScan& now);

    /// `increment`: the odometry since the last scan (robot frame of the last scan, m, rad);
    /// `lastMotion`: the motion registered at the last scan (same frame). True when the
    /// increment is taken for the odometry catching up: predict `lastMotion` instead. The
    /// stall's backlog comes from registered(): the catch-up ends once it is delivered.
    bool catchingUp(const mrpt::poses::CPose2D& increment, const mrpt::poses::CPose2D& lastMotion);

    /// True when `increment` is the first that moves after increments of exactly zero that
    /// followed a registered motion (a stall; not a robot that stood still), is longer, or
    /// turns farther, than `lastMotion` by more than kAgreeDistance or kAgreeAngle (a
    /// catch-up), and registration saw no translation since (at most kMovedDistance), or
    /// placed none of the stall's scans (stallUnplaced()), or, where the reading turned as
    /// registered (turnedAsRegistered()), saw a translation shorter than the reading's by more
    /// than kAgreeDistance: then stepSinceStall() is the step to predict.
    bool bridges(const mrpt::poses::CPose2D& increment,
                 const mrpt::poses::CPose2D& lastMotion) const;
    /// True when `increment` is such a catch-up (the first reading that moves after a stall,
    /// longer or farther turned than `lastMotion` by the margins) and as long as the
    /// translation registered over the stall plus a step of `lastMotion`'s length, within
    /// kAgreeDistance, whatever it turned: registration saw the stall's motion, and the reading
    /// holds it and its own interval's (bridge_stall_and_step). A `lastMotion` no longer than
    /// kAgreeDistance (a turn on the spot, a slow robot) does not tell the stall and a step
    /// from the stall alone by its length: there the step the reading leaves must also turn as
    /// `lastMotion` did, within kAgreeAngle. stepSinceStall() is then the step to predict, as
    /// for bridges().
    bool holdsStallAndStep(const mrpt::poses::CPose2D& increment,
                           const mrpt::poses::CPose2D& lastMotion) const;
    /// The step from the last scan that `increment` (which bridges()) reads: the motion since
    /// the last reading that changed, less the motion registered since (robot frame of the last
    /// scan, m, rad).
    mrpt::poses::CPose2D stepSinceStall(const mrpt::poses::CPose2D& increment) const;
    /// True when `increment` catches up with readings that fell short (a stall within a scan
    /// interval, see above): they fell short of the registered motion by more than
    /// kAgreeDistance in all, and `increment` is longer than `lastMotion` by more than
    /// kAgreeDistance and, less the shortfall, nearer its length; by more than kMovedDistance
    /// where a stall of the distance alone (translationStalled()) fell short. (A stall of whole
    /// scans is bridges()'s.)
    bool catchesUpShortfall(const mrpt::poses::CPose2D& increment,
                            const mrpt::poses::CPose2D& lastMotion) const;
    /// The step that `increment` (which catchesUpShortfall()) reads less the shortfall: its
    /// translation shortened by the distance the readings fell short, its heading as read less
    /// the turn they missed where that is more than kAgreeAngle, whichever way it turned, or
    /// where it turned farther the same way (robot frame of the last scan, m, rad).
    mrpt::poses::CPose2D stepPastShortfall(const mrpt::poses::CPose2D& increment) const;
    /// m by which the readings since the odometry was last in step fell short of the motion
    /// registered for them.
    double shortfall() const { return shortfall_; }
    /// `increment` with its heading less the turn the short readings since the odometry was
    /// last in step missed, where that is more than kAgreeAngle and `increment` turned farther
    /// the same way (it may hold the missed turn on top of its own: robot frame of the last
    /// scan, m, rad); nothing otherwise.
    std::optional<mrpt::poses::CPose2D> pastMissedTurn(const mrpt::poses::CPose2D& increment) const;
    /// After each scan with odometry: its `increment`, and the `step` registered for it (robot
    /// frame of the last scan). A stalled scan's step adds to the backlog. `placed`: a
    /// registration (ICP or the graph matcher) placed the scan; false where nothing did and
    /// `step` is only the prediction (the last motion, in a stall). GraphSlam passes true for
    /// every scan with bridge_unplaced_stalls off, so that no stall counts as unplaced.
    /// `guessFree`: the graph matcher placed it, with no guess to check its answer by (the
    /// stalled reading gave none).
    void registered(const mrpt::poses::CPose2D& increment, const mrpt::poses::CPose2D& step,
                    bool placed = true, bool guessFree = false);
    /// No registration placed any scan since the last increment that moved: the motion
    /// "registered" over the stall is the last motion carried on, no measurement at all.
    bool stallUnplaced() const { return repeatedScans_ > 0 && stallUnplaced_; }
    /// The stall's turn as registered is refuted by `increment`, the first reading after it:
    /// ICP placed none of its scans (the guess-free graph matcher or nothing did), and the
    /// reading turned otherwise than registered by more than `maxTurnPerScan` (rad) for each
    /// scan interval it spans (repeatedScans() + 1, as the jump bounds scale), more than a
    /// right answer leaves to the catch-up's own interval. In a place that looks alike turned
    /// (a square room, a crossing) the matcher may take the turned look-alike, and over a
    /// stall the reading is the only other evidence of the turn.
    bool stallTurnRefuted(const mrpt::poses::CPose2D& increment, double maxTurnPerScan) const;
    /// Scans since the last increment that moved (0 when the last one did).
    int repeatedScans() const { return repeatedScans_; }
    /// For each scan with odometry, before registration: its `increment` over the scan
    /// interval of `seconds` (0: not known), and `lastMotion` (see catchingUp()). True when
    /// it is a stall of the translation: not zero, at most kStalledDistance, where the reading
    /// before went kStalledAfter or more, at a speed the robot could not have come down from
    /// within this interval at kMaxDeceleration (the wheels' count stopped while the heading
    /// still reads: mit-csail 0.004, 0 and 0 m where the robot went 0.21 m in each 0.21 s);
    /// the readings of at most kStalledDistance after it continue the stall while the robot
    /// still registers kStalledAfter or more. (A reading of exactly zero is stalled().)
    bool translationStalled(const mrpt::poses::CPose2D& increment, double seconds,
                            const mrpt::poses::CPose2D& lastMotion);
    /// The increment last given to catchingUp() was a stall: exactly zero while the robot
    /// moved at the scan before (more than kMovedDistance or kMovedAngle).
    bool stalled() const { return stalled_; }
    /// For `increment` that bridges(): registration left the stall's scans behind where the
    /// reading turned as registered, the translation registered over them shorter than the
    /// reading's share of those scan intervals (of repeatedScans() + 1) by more than
    /// kAgreeDistance; or it placed none of them (stallUnplaced()).
    bool stallScansBehind(const mrpt::poses::CPose2D& increment) const;

  private:
    /// More than kMovedDistance or kMovedAngle.
    static bool moved(const mrpt::poses::CPose2D& motion);
    /// Turns by more than kAgreeAngle.
    static bool turned(const mrpt::poses::CPose2D& motion);
    /// `increment` is the first that moves after a stall that followed a registered motion,
    /// and exceeds() `lastMotion`: what bridges() and holdsStallAndStep() take up.
    bool catchUpAfterStall(const mrpt::poses::CPose2D& increment,
                           const mrpt::poses::CPose2D& lastMotion) const;
    /// Registration saw no turn since the last reading that changed (at most kAgreeAngle), or
    /// `increment` turned as far as it saw, within kAgreeAngle.
    bool turnedAsRegistered(const mrpt::poses::CPose2D& increment) const;
    /// Longer, or turning farther, than `lastMotion` by more than kAgreeDistance or kAgreeAngle.
    static bool exceeds(const mrpt::poses::CPose2D& increment,
                        const mrpt::poses::CPose2D& lastMotion);

    bool stalled_ = false;  ///< the last increment was a stall
    int catchUpLeft_ = 0;   ///< scans still taken for catching up
    /// The motion registered over the stalls since the odometry was last in step, less what
    /// the catch-up increments delivered beyond their predictions (m, rad).
    double backlogDistance_ = 0, backlogTurn_ = 0;
    /// Scans since the last increment that moved, and the motion registered over them.
    int repeatedScans_ = 0;
    mrpt::poses::CPose2D sinceReading_;
    bool movedBeforeStall_ = false;  ///< the scan before the repeated increments moved
    bool stallUnplaced_ = false;     ///< no registration placed any of those scans
    bool stallGuessFree_ = false;    ///< ICP placed none of them (stallTurnRefuted)
    mrpt::poses::CPose2D lastStep_;  ///< the last scan's registered step
    /// translationStalled(): the last increment and its interval (s), and whether it stalled.
    mrpt::poses::CPose2D lastReading_;
    double lastReadingSeconds_ = 0;
    bool translationStalled_ = false;
    double shortfall_ = 0;  ///< shortfall()
    /// rad of the registered turn the readings of the shortfall missed, less what later ones
    /// delivered (signed)
    double shortfallTurn_ = 0;
    bool shortfallAfterStall_ = false;  ///< a stall of the distance alone added to it
};

}  // namespace toposlam::mapping
