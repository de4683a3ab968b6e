#include <toposlam/mapping/OdometryLag.h>

#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace toposlam::mapping {

namespace {
bool zero(const mrpt::poses::CPose2D& increment) {
    return increment.x() == 0 && increment.y() == 0 && increment.phi() == 0;
}
}  // namespace

bool OdometryLag::catchingUp(const mrpt::poses::CPose2D& increment,
                             const mrpt::poses::CPose2D& lastMotion) {
    if (zero(increment)) {
        stalled_ = moved(lastMotion);
        return false;
    }
    if (stalled_) {
        stalled_ = false;
        catchUpLeft_ = kMaxCatchUpScans;
    }
    if (catchUpLeft_ == 0) {
        backlogDistance_ = backlogTurn_ = 0;
        return false;
    }
    --catchUpLeft_;
    // A backlog adds to the motion: a step that is not longer, nor turns farther, than the last
    // registered one by the margins is the odometry in step with the robot again (one that
    // reads less is the robot slowing down, which at a low scan rate is a large change too).
    if (!exceeds(increment, lastMotion)) {
        catchUpLeft_ = 0;
        backlogDistance_ = backlogTurn_ = 0;
        return false;
    }
    // What this increment holds beyond the motion predicted for it is backlog delivered. Once
    // no more than the margins is left the odometry is in step again, however short the
    // registered motion has become meanwhile (along a corridor ICP started from a short
    // prediction stays short, and the next catch-up would predict shorter still).
    backlogDistance_ -= std::max(0.0, increment.norm() - lastMotion.norm());
    backlogTurn_ -= std::max(0.0, std::abs(mrpt::math::wrapToPi(increment.phi())) -
                                      std::abs(mrpt::math::wrapToPi(lastMotion.phi())));
    if (backlogDistance_ <= kAgreeDistance && backlogTurn_ <= kAgreeAngle)
        catchUpLeft_ = 0;
    return true;
}

bool OdometryLag::exceeds(const mrpt::poses::CPose2D& increment,
                          const mrpt::poses::CPose2D& lastMotion) {
    const double longer = increment.norm() - lastMotion.norm();
    const double farther = std::abs(mrpt::math::wrapToPi(increment.phi())) -
                           std::abs(mrpt::math::wrapToPi(lastMotion.phi()));
    return longer > kAgreeDistance || farther > kAgreeAngle;
}

bool OdometryLag::translationStalled(const mrpt::poses::CPose2D& increment, double seconds,
                                     const mrpt::poses::CPose2D& lastMotion) {
    bool stalled = false;
    if (!zero(increment) && increment.norm() <= kStalledDistance && seconds > 0) {
        if (translationStalled_) {
            stalled = lastMotion.norm() >= kStalledAfter;
        } else if (lastReading_.norm() >= kStalledAfter && lastReadingSeconds_ > 0.5 * seconds &&
                   lastReadingSeconds_ < 2 * seconds) {
            // Speeds, over intervals alike: a scan stamped a few milliseconds after the last
            // reads millimetres at full speed (intel's bursts of scans).
            const double before = lastReading_.norm() / lastReadingSeconds_;
            const double now = increment.norm() / seconds;
            // (Beyond kMaxSpeed the stamps are wrong, not the odometry: intel's run at
            // 0.002 s for 0.11 m readings.)
            stalled = before <= kMaxSpeed && (before - now) / seconds > kMaxDeceleration;
        }
    }
    translationStalled_ = stalled;
    lastReading_ = increment;
    lastReadingSeconds_ = seconds;
    return stalled;
}

bool OdometryLag::moved(const mrpt::poses::CPose2D& motion) {
    return motion.norm() > kMovedDistance ||
           std::abs(mrpt::math::wrapToPi(motion.phi())) > kMovedAngle;
}

bool OdometryLag::turned(const mrpt::poses::CPose2D& motion) {
    return std::abs(mrpt::math::wrapToPi(motion.phi())) > kAgreeAngle;
}

bool OdometryLag::catchUpAfterStall(const mrpt::poses::CPose2D& increment,
                                    const mrpt::poses::CPose2D& lastMotion) const {
    return repeatedScans_ > 0 && !zero(increment) && movedBeforeStall_ &&
           exceeds(increment, lastMotion);
}

bool OdometryLag::bridges(const mrpt::poses::CPose2D& increment,
                          const mrpt::poses::CPose2D& lastMotion) const {
    if (!catchUpAfterStall(increment, lastMotion))
        return false;
    // Translation: a corridor fixes the heading, and ICP turns the stall's scans by its noise
    // (a degree or so) while it cannot see how far they went along it. Where nothing placed
    // the stall's scans, their motion is the last one carried on: no turn was seen, only
    // guessed (Bormann's lab_f toured at a third: 55 deg carried on where the robot turned 17,
    // and the catch-up, which turned 20 over both scans, was refused as a jump).
    return sinceReading_.norm() <= kMovedDistance || stallUnplaced() ||
           (turnedAsRegistered(increment) &&
            increment.norm() - sinceReading_.norm() > kAgreeDistance);
}

bool OdometryLag::holdsStallAndStep(const mrpt::poses::CPose2D& increment,
                                    const mrpt::poses::CPose2D& lastMotion) const {
    // The lengths: the turns may differ (the robot turned -11 deg over the stall and +19 in
    // its own interval), and a reading that turned otherwise than registration saw is what
    // bridges() refuses. A stall registration left short, or a reading that is not all of the
    // stall, does not add up.
    if (!catchUpAfterStall(increment, lastMotion) ||
        std::abs(increment.norm() - (sinceReading_.norm() + lastMotion.norm())) > kAgreeDistance)
        return false;
    if (lastMotion.norm() > kAgreeDistance)
        return true;
    // A step within the margin (a turn on the spot, a slow robot) does not tell the stall and a
    // step from the stall alone by its length: the step the reading leaves must also turn as
    // the last motion did.
    return std::abs(mrpt::math::wrapToPi(stepSinceStall(increment).phi() - lastMotion.phi())) <=
           kAgreeAngle;
}

bool OdometryLag::stallTurnRefuted(const mrpt::poses::CPose2D& increment,
                                   double maxTurnPerScan) const {
    if (repeatedScans_ == 0 || zero(increment) || !movedBeforeStall_ || !stallGuessFree_)
        return false;
    // Bounded over every interval the reading spans, as the jump bounds are: the catch-up's
    // own interval alone may turn beyond one interval's bound (office_a, stalling robot at a
    // third, seed 1: 49 deg where the matcher had the stall's turn right).
    const double maxTurn = double(repeatedScans_ + 1) * maxTurnPerScan;
    return std::abs(mrpt::math::wrapToPi(increment.phi() - sinceReading_.phi())) > maxTurn;
}

bool OdometryLag::stallScansBehind(const mrpt::poses::CPose2D& increment) const {
    if (stallUnplaced())
        return true;  // where the last motion put them, not where anything saw them
    const double scans = repeatedScans_;
    return turnedAsRegistered(increment) &&
           sinceReading_.norm() < increment.norm() * scans / (scans + 1) - kAgreeDistance;
}

bool OdometryLag::turnedAsRegistered(const mrpt::poses::CPose2D& increment) const {
    // A turn shows walls across, so registration saw it; a reading that turned as far holds
    // the stall's motion, one that turned less is what fell short (mit-csail: 7.6 deg where
    // the robot turned 25).
    return !turned(sinceReading_) ||
           std::abs(mrpt::math::wrapToPi(increment.phi() - sinceReading_.phi())) <= kAgreeAngle;
}

bool OdometryLag::inStep(const mrpt::poses::CPose2D& before, const mrpt::poses::CPose2D& now) {
    const mrpt::poses::CPose2D change = (-before) + now;
    return change.norm() <= kAgreeDistance &&
           std::abs(mrpt::math::wrapToPi(change.phi())) <= kAgreeAngle;
}

bool OdometryLag::scanChanged(const matching::PolarScan& before, const matching::PolarScan& now) {
    if (before.size() != now.size())
        return true;  // another laser or setting: nothing says the robot stood
    std::size_t both = 0, changed = 0;
    for (std::size_t b = 0; b < now.size(); ++b) {
        if (!before.valid(b) || !now.valid(b))
            continue;
        ++both;
        changed += std::abs(now.range(b) - before.range(b)) > kChangedRange;
    }
    return double(changed) >= kChangedShare * double(both) && changed > 0;
}

bool OdometryLag::catchesUpShortfall(const mrpt::poses::CPose2D& increment,
                                     const mrpt::poses::CPose2D& lastMotion) const {
    // (A stall of whole scans resets the shortfall: registered() leaves it to bridges().)
    // After a stall of the distance alone the shortfall is no reading's noise: a stall of one
    // scan falls a step short, and its catch-up reads a step more (a robot at 1 m/s scanned
    // every 0.2 m: 0.2 m, the margin itself).
    const double margin = shortfallAfterStall_ ? kMovedDistance : kAgreeDistance;
    const double longer = increment.norm() - lastMotion.norm();
    if (shortfall_ <= margin || longer <= margin)
        return false;
    // A catch-up holds the shortfall on top of a step like the last one; a robot that sped up
    // (or an odometry whose short readings were registration's error) does not.
    return std::abs(stepPastShortfall(increment).norm() - lastMotion.norm()) < longer;
}

mrpt::poses::CPose2D OdometryLag::stepPastShortfall(const mrpt::poses::CPose2D& increment) const {
    const double distance = increment.norm();
    const double kept = distance > 0 ? std::max(0.0, distance - shortfall_) / distance : 0.0;
    // The turn the short readings missed: beyond the readings' noise (kAgreeAngle) this one
    // holds it on top of its own, whichever way that went (Bormann's office_i toured at a
    // third, seed 9: 27 deg missed right, this one read 0 where the robot turned 21 left);
    // within it, only where this one turned farther the same way.
    const double turn = mrpt::math::wrapToPi(increment.phi());
    const bool holdsMissedTurn =
        (turn * shortfallTurn_ > 0 && std::abs(turn) > std::abs(shortfallTurn_)) ||
        std::abs(shortfallTurn_) > kAgreeAngle;
    return {increment.x() * kept, increment.y() * kept,
            holdsMissedTurn ? turn - shortfallTurn_ : increment.phi()};
}

std::optional<mrpt::poses::CPose2D> OdometryLag::pastMissedTurn(
    const mrpt::poses::CPose2D& increment) const {
    const double turn = mrpt::math::wrapToPi(increment.phi());
    if (std::abs(shortfallTurn_) <= kAgreeAngle || turn * shortfallTurn_ <= 0 ||
        std::abs(turn) <= std::abs(shortfallTurn_))
        return std::nullopt;
    // Turned along the step, the missed turn bent its chord by half of it.
    const double c = std::cos(-0.5 * shortfallTurn_), s = std::sin(-0.5 * shortfallTurn_);
    return mrpt::poses::CPose2D(c * increment.x() - s * increment.y(),
                                s * increment.x() + c * increment.y(), turn - shortfallTurn_);
}

mrpt::poses::CPose2D OdometryLag::stepSinceStall(const mrpt::poses::CPose2D& increment) const {
    return (-sinceReading_) + increment;
}

void OdometryLag::registered(const mrpt::poses::CPose2D& increment,
                             const mrpt::poses::CPose2D& step, bool placed, bool guessFree) {
    if (zero(increment)) {
        shortfall_ = shortfallTurn_ = 0;  // a stall of whole scans: bridges(), catchingUp()
        shortfallAfterStall_ = false;
        // The motion the odometry missed, for catchingUp() to expect in the increments after.
        backlogDistance_ += step.norm();
        backlogTurn_ += std::abs(mrpt::math::wrapToPi(step.phi()));
        if (repeatedScans_++ == 0) {
            movedBeforeStall_ = moved(lastStep_);
            sinceReading_ = step;
            stallUnplaced_ = !placed;
            stallGuessFree_ = !placed || guessFree;
        } else {
            sinceReading_ = sinceReading_ + step;
            stallUnplaced_ = stallUnplaced_ && !placed;
            stallGuessFree_ = stallGuessFree_ && (!placed || guessFree);
        }
    } else {
        repeatedScans_ = 0;
        sinceReading_ = mrpt::poses::CPose2D();
        // A reading short of the registered step by more than noise adds to the shortfall;
        // one that is not short is in step (or catching up), and ends it.
        const double missed = step.norm() - increment.norm();
        shortfall_ = missed > kMovedDistance ? shortfall_ + missed : 0.0;
        // Such a reading may miss some of the turn too: it read less of the registered turn, or
        // turned the other way (a lagging odometry still reads the turn before). One that read
        // more of the turn than registered, the other way from what is missed, delivers some
        // of it: that much is no longer missed (never more than was).
        const double registeredTurn = mrpt::math::wrapToPi(step.phi());
        const double readTurn = mrpt::math::wrapToPi(increment.phi());
        const double turnMissed = mrpt::math::wrapToPi(registeredTurn - readTurn);
        const bool turnsApart = std::abs(turnMissed) > kMovedAngle;
        double missedTurn = shortfallTurn_;
        if (turnsApart && turnMissed * shortfallTurn_ < 0) {
            missedTurn = shortfallTurn_ > 0 ? std::max(0.0, shortfallTurn_ + turnMissed)
                                            : std::min(0.0, shortfallTurn_ + turnMissed);
        } else if (turnsApart && (std::abs(registeredTurn) > std::abs(readTurn) ||
                                  registeredTurn * readTurn < 0)) {
            missedTurn += turnMissed;
        }
        shortfallTurn_ = shortfall_ > 0 ? missedTurn : 0.0;
        shortfallAfterStall_ = shortfall_ > 0 && (shortfallAfterStall_ || translationStalled_);
    }
    lastStep_ = step;
}

}  // namespace toposlam::mapping
