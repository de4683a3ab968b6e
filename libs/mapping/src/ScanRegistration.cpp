#include <mrpt/math/wrap2pi.h>
#include <toposlam/mapping/MapRange.h>
#include <toposlam/mapping/OdometryLag.h>
#include <toposlam/mapping/ScanRegistration.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <utility>

namespace toposlam::mapping {

using mrpt::math::CMatrixDouble33;
using mrpt::poses::CPose2D;

namespace {
/// m: a reading this close to the submap's surface counts as explained by a pose.
constexpr double kFitDistance = 0.05;
/// rad: two ICP runs that end within kFitDistance and this angle found the same pose.
constexpr double kSameEndAngle = 0.0175;
/// ICP that did not converge has not settled when its residual RMS is more than this times the
/// median of the recent registrations. (Less than half of the scan on the map, tried as a
/// second sign, flagged 5 % of intel's scans and never changed a result.)
constexpr double kUnsettledResidualRatio = 2.0;
/// Along-heading check: ICP "slid" along a corridor only where at least this share of the
/// readings lies on the submap at its pose (a good fit, not a place where nothing fits).
constexpr double kSlideMinFit = 0.5;
/// Two ICP runs that end within kFitDistance and kSameEndAngle found the same pose.
bool sameEnd(const CPose2D& a, const CPose2D& b) {
    const CPose2D apart = b - a;
    return apart.norm() <= kFitDistance &&
           std::abs(mrpt::math::wrapToPi(apart.phi())) <= kSameEndAngle;
}
/// Readings of `scan` within kFitDistance of the submap's surface at sensor pose `sensor`.
std::size_t readingsOnMap(const matching::LineMap& map, const matching::PolarScan& scan,
                          const CPose2D& sensor) {
    return matching::PointToLineIcp::countOnMap(map, scan, sensor, kFitDistance);
}
/// ICP that ended at robot pose `candidate` bears out its answer against ICP that ended at
/// `other` (both on `map`): they found the same pose, or the scan fits clearly better at
/// `candidate` (`margin` more of its valid readings on the map, and at least one more: a scan
/// with (almost) no readings bears out nothing).
bool bearsOut(const matching::LineMap& map, const matching::PolarScan& scan,
              const CPose2D& sensorOnRobot, const CPose2D& candidate, const CPose2D& other,
              double margin) {
    if (sameEnd(candidate, other))
        return true;
    return double(readingsOnMap(map, scan, candidate + sensorOnRobot)) >=
           double(readingsOnMap(map, scan, other + sensorOnRobot)) +
               std::max(1.0, margin * double(scan.validCount()));
}
/// The covariance with every eigenvalue clamped to [lo, hi] (per eigen-direction of position
/// and heading together; position and heading are in different units, but ICP's covariance is
/// nearly block-diagonal, so this clamps each block).
CMatrixDouble33 clampEigen(const CMatrixDouble33& c, const Eigen::Vector3d& floor,
                           const Eigen::Vector3d& ceiling) {
    // Scale to unit floor so one eigen-decomposition treats m and rad alike.
    const Eigen::Vector3d s = floor.cwiseSqrt();
    const Eigen::Matrix3d scaled =
        s.cwiseInverse().asDiagonal() * c.asEigen() * s.cwiseInverse().asDiagonal();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(0.5 * (scaled + scaled.transpose()));
    const Eigen::Vector3d hi = ceiling.cwiseQuotient(floor);
    const double cap = hi.minCoeff();
    Eigen::Vector3d v = eig.eigenvalues();
    for (int k = 0; k < 3; ++k)
        v[k] = std::clamp(v[k], 1.0, std::max(1.0, cap));
    const Eigen::Matrix3d clamped =
        eig.eigenvectors() * v.asDiagonal() * eig.eigenvectors().transpose();
    CMatrixDouble33 out;
    out.asEigen() = s.asDiagonal() * clamped * s.asDiagonal();
    return out;
}
}  // namespace

bool beyondOdometryJump(const GraphSlamOptions& options, const CPose2D& motion, double scans) {
    return motion.norm() > scans * options.odometryJumpDistance ||
           std::abs(mrpt::math::wrapToPi(motion.phi())) > scans * options.odometryJumpAngle;
}

Prediction Prediction::fromRegistered() const {
    Prediction p = *this;
    p.lastKeyframe = registeredKeyframe;
    p.lastKeyframeReadings = registeredKeyframeReadings;
    p.fromLastKeyframe = fromRegisteredKeyframe;
    p.distanceFromLastKeyframe = distanceFromRegisteredKeyframe;
    p.turnFromLastKeyframe = turnFromRegisteredKeyframe;
    return p;
}

ScanRegistration::ScanRegistration(const GraphSlamOptions& options,
                                   const matching::GraphMatcherOptions& matcherOptions)
    : options_(options), icpOptions_(options.icpOptions()), matcher_(matcherOptions) {
    foregroundOptions_.maxRange = options.foregroundMaxRange;
    foregroundOptions_.maxWidth = options.foregroundMaxWidth;
}

CMatrixDouble33 ScanRegistration::odometryCovariance(double distance, double turn) const {
    const double sxy = options_.odometrySigmaXY + options_.odometrySigmaXYPerMetre * distance;
    const double sphi = options_.odometrySigmaPhi + options_.odometrySigmaPhiPerRadian * turn;
    CMatrixDouble33 c;
    c.setZero();
    c(0, 0) = c(1, 1) = sxy * sxy;
    c(2, 2) = sphi * sphi;
    return c;
}

CMatrixDouble33 ScanRegistration::edgeCovariance(const CMatrixDouble33& icp, double distance,
                                                 double turn) const {
    const CMatrixDouble33 odo = odometryCovariance(distance, turn);
    const Eigen::Vector3d floor(options_.edgeMinSigmaXY * options_.edgeMinSigmaXY,
                                options_.edgeMinSigmaXY * options_.edgeMinSigmaXY,
                                options_.edgeMinSigmaPhi * options_.edgeMinSigmaPhi);
    const Eigen::Vector3d ceiling(odo(0, 0), odo(1, 1), odo(2, 2));
    return clampEigen(icp, floor, ceiling.cwiseMax(floor));
}

ScanRegistration::IcpAttempt ScanRegistration::icpFrom(const matching::PolarScan& scan,
                                                       const CPose2D& sensorOnRobot,
                                                       const Submap& submap, const CPose2D& start) {
    IcpAttempt a;
    a.icp = icp_.refineOnMap(submap.map(), scan, start + sensorOnRobot, icpOptions_);
    a.robot = a.icp.pose + (-sensorOnRobot);  // sensor pose (+) mounting^-1
    // Share of the readings the map could hold (within its range) that landed on it.
    std::size_t mappable = 0;
    const double range = mapRange(scan, options_);
    for (std::size_t b = 0; b < scan.size(); ++b)
        mappable += scan.valid(b) && scan.range(b) <= range;
    a.overlap = double(a.icp.pointsUsed) / double(std::max<std::size_t>(1, mappable));
    return a;
}

double ScanRegistration::odometryChi2(const Prediction& prediction, const CPose2D& pose) const {
    const CPose2D correction = pose - prediction.inSubmap;
    const Eigen::Vector3d e(correction.x(), correction.y(), mrpt::math::wrapToPi(correction.phi()));
    const CMatrixDouble33 c =
        odometryCovariance(prediction.odometryStep.norm(),
                           std::abs(mrpt::math::wrapToPi(prediction.odometryStep.phi())));
    return e.dot(c.asEigen().ldlt().solve(e));
}

bool ScanRegistration::outrunsOdometry(const Prediction& prediction, const CPose2D& pose) const {
    return options_.unsettledMaxChi2 > 0 && prediction.odometryPredicted &&
           odometryChi2(prediction, pose) > options_.unsettledMaxChi2;
}

bool ScanRegistration::plausibleCorrection(const CPose2D& correction, bool boundSideways,
                                           double sidewaysScale) const {
    return correction.norm() <= options_.maxCorrectionDistance &&
           std::abs(mrpt::math::wrapToPi(correction.phi())) <= options_.maxCorrectionAngle &&
           (!boundSideways || options_.maxLateralCorrection <= 0 ||
            std::abs(correction.y()) <= sidewaysScale * options_.maxLateralCorrection);
}

bool ScanRegistration::acceptable(const IcpAttempt& attempt, const CPose2D& start,
                                  bool boundSideways, double sidewaysScale) const {
    return attempt.overlap >= options_.minInlierRatio &&
           plausibleCorrection(attempt.robot - start, boundSideways, sidewaysScale);
}

bool ScanRegistration::passesAlone(const matching::LineMap& map, const matching::PolarScan& scan,
                                   const CPose2D& sensorOnRobot, const IcpAttempt& attempt,
                                   const CPose2D& start, const IcpAttempt& other,
                                   const CPose2D& otherStart) const {
    return acceptable(attempt, start) && !acceptable(other, otherStart) &&
           readingsOnMap(map, scan, attempt.robot + sensorOnRobot) >
               readingsOnMap(map, scan, other.robot + sensorOnRobot);
}

bool ScanRegistration::seesForegroundObjects(const matching::PolarScan& scan) const {
    return ForegroundObjects::any(scan, foregroundOptions_);
}

CMatrixDouble33 ScanRegistration::foregroundEdgeVariance(const matching::PolarScan& scan) const {
    CMatrixDouble33 extra;
    extra.setZero();
    const double factor = options_.foregroundEdgeSigmaFactor;
    if (factor > 1 && seesForegroundObjects(scan)) {
        const double k = factor * factor - 1;
        extra(0, 0) = extra(1, 1) = k * options_.edgeMinSigmaXY * options_.edgeMinSigmaXY;
        extra(2, 2) = k * options_.edgeMinSigmaPhi * options_.edgeMinSigmaPhi;
    }
    return extra;
}

void ScanRegistration::checkAlongHeading(const matching::PolarScan& scan,
                                         const CPose2D& sensorOnRobot, const Prediction& prediction,
                                         const CPose2D& from, IcpAttempt& icp, Registration& out) {
    const double along = std::abs((icp.robot - from).x());
    const bool ahead = options_.foregroundCheck > 0 && along > options_.foregroundCheck;
    const bool outruns = options_.foregroundCheck > 0 && options_.foregroundBeyondOdometry &&
                         outrunsOdometry(prediction, icp.robot);
    const bool support = options_.alongHeadingCheck > 0 && along > options_.alongHeadingCheck;
    if ((ahead || outruns) && foreground_.remove(scan, foregroundOptions_, background_) > 0) {
        IcpAttempt alt = icpFrom(background_, sensorOnRobot, *prediction.submap, from);
        const CPose2D altCorrection = alt.robot - from;
        // Beyond the odometry's noise on the objects' evidence alone: without them ICP stays
        // within it and keeps less than half of the correction (a quarter of its chi-square),
        // and the rest of the scan fits that no worse. If it fits too little of the scan,
        // tryIcp fails it and the scan goes on as a failed ICP.
        if (outruns && !outrunsOdometry(prediction, alt.robot) &&
            odometryChi2(prediction, alt.robot) < 0.25 * odometryChi2(prediction, icp.robot)) {
            const matching::LineMap& map = prediction.submap->map();
            if (readingsOnMap(map, background_, alt.robot + sensorOnRobot) >=
                readingsOnMap(map, background_, icp.robot + sensorOnRobot)) {
                out.withoutForeground = true;
                icp = alt;
                return;
            }
        }
        if (ahead && acceptable(alt, from)) {
            // Without the objects ICP keeps most of the odometry's step: they took it back.
            // Or it slid along a corridor: the walls left fix nothing along it.
            const bool keptStep = std::abs(altCorrection.x()) < 0.5 * along;
            if (keptStep || (support && holdAlongHeading(background_, sensorOnRobot, prediction,
                                                         from, alt, out.alongHeading.emplace()))) {
                out.withoutForeground = true;
                icp = alt;
            }
            return;  // with the objects in view, only the rest of the scan is evidence
        }
    }
    if (support)
        holdAlongHeading(scan, sensorOnRobot, prediction, from, icp, out.alongHeading.emplace());
}

bool ScanRegistration::holdAlongHeading(const matching::PolarScan& scan,
                                        const CPose2D& sensorOnRobot, const Prediction& prediction,
                                        const CPose2D& from, IcpAttempt& attempt,
                                        AlongHeadingCheck& check) const {
    const CPose2D correction = attempt.robot - from;
    const CPose2D kept = from + CPose2D(0, correction.y(), correction.phi());
    const matching::LineMap& map = prediction.submap->map();
    check.correction = correction.x();
    check.readings = scan.validCount();
    check.onMapAtIcp = readingsOnMap(map, scan, attempt.robot + sensorOnRobot);
    check.onMapAtOdometry = readingsOnMap(map, scan, kept + sensorOnRobot);
    const double readings = double(check.readings), atAttempt = double(check.onMapAtIcp);
    // A corridor, not a place where nothing fits: most readings lie on the submap.
    const bool fits = atAttempt >= kSlideMinFit * readings;
    const bool fitsNoBetter =
        double(check.onMapAtOdometry) + options_.alongHeadingMargin * readings >= atAttempt;
    // Or ICP's pose makes the scan see through surfaces the submap's keyframes saw.
    bool seesThrough = false;
    if (options_.alongHeadingFreeSpace > 0) {
        check.seenThroughAtIcp =
            map.countSeenThrough(scan, attempt.robot + sensorOnRobot, kSeenThroughMargin);
        check.seenThroughAtOdometry =
            map.countSeenThrough(scan, kept + sensorOnRobot, kSeenThroughMargin);
        seesThrough =
            double(check.seenThroughAtIcp) >=
            double(check.seenThroughAtOdometry) + options_.alongHeadingFreeSpace * readings;
    }
    check.held = fits && (fitsNoBetter || seesThrough);
    check.heldForFreeSpace = check.held && !fitsNoBetter;
    if (check.held)
        attempt.robot = kept;
    return check.held;
}

bool ScanRegistration::tryIcp(const matching::PolarScan& scan, const CPose2D& sensorOnRobot,
                              const Prediction& prediction, Registration& out,
                              const IcpAttempt* started) {
    failedIcp_.reset();
    if (!prediction.submap || prediction.submap->map().size() == 0 || scan.validCount() == 0)
        return false;
    IcpAttempt best =
        started ? *started : icpFrom(scan, sensorOnRobot, *prediction.submap, prediction.inSubmap);
    // Before judging it: a person ahead can also push the answer beyond the plausible.
    const CPose2D& from = stallStepBorneOut_ && !prediction.odometryJumped ? *stallStepBorneOut_
                                                                           : prediction.inSubmap;
    checkAlongHeading(scan, sensorOnRobot, prediction, from, best, out);
    out.overlap = best.overlap;
    if (!acceptable(best, prediction.inSubmap, /*boundSideways=*/true, prediction.sidewaysScale)) {
        failedIcp_ = best.robot;
        return false;
    }
    if (options_.secondOpinion) {
        // Not settled: no convergence, and a residual well above the recent ones (a start too
        // far off for ICP's basin, typically the heading).
        icpUnsettled_ = !settled(best);
        recentResiduals_[residualCount_++ % recentResiduals_.size()] = best.icp.residualRms;
    }
    out.method = RegistrationMethod::Icp;
    out.reference = prediction.submap->anchor();
    out.pose = best.robot;
    out.rawCovariance = best.icp.covariance;
    // Undetermined directions (a corridor) fall back on odometry since the last keyframe.
    out.covariance = edgeCovariance(best.icp.covariance, prediction.distanceFromLastKeyframe,
                                    prediction.turnFromLastKeyframe);
    return true;
}

bool ScanRegistration::settled(const IcpAttempt& attempt) const {
    const double typical = typicalResidual();  // 0: too few registrations to judge, settled
    return attempt.icp.converged || typical <= 0 ||
           attempt.icp.residualRms <= kUnsettledResidualRatio * typical;
}

bool ScanRegistration::shortFromOdometry(const Prediction& prediction,
                                         const Registration& icp) const {
    return options_.secondOpinion && prediction.odometryPredicted && !prediction.odometryStalled &&
           icp.overlap < options_.keyframeMinOverlap;
}

bool ScanRegistration::shortOfTurn(const Prediction& prediction, const Registration& icp) const {
    if (!options_.shortTurnSecondOpinion || !shortFromOdometry(prediction, icp))
        return false;
    const double last = mrpt::math::wrapToPi(prediction.lastMotion.phi());
    const double step = mrpt::math::wrapToPi(prediction.odometryStep.phi());
    return last * step >= 0 && std::abs(last) - std::abs(step) > 2 * options_.secondOpinionTurn;
}

bool ScanRegistration::shortOnTheSpot(const Prediction& prediction, const Registration& icp) const {
    if (!options_.spotTurnSecondOpinion || !shortFromOdometry(prediction, icp))
        return false;
    // Only where the odometry is known to lag (as for tryTurnedStarts): at every scan of a
    // sound odometry the second starts settle on people or furniture as often as they mend.
    if (!odometryHasJumped())
        return false;
    return prediction.odometryStep.norm() <= OdometryLag::kMovedDistance &&
           std::abs(mrpt::math::wrapToPi(prediction.odometryStep.phi())) >
               options_.secondOpinionTurn;
}

bool ScanRegistration::secondOpinion(const matching::PolarScan& scan, const CPose2D& sensorOnRobot,
                                     const Prediction& prediction, const Registration* matched,
                                     Registration& icp, bool fromLastMotion) {
    const Submap& submap = *prediction.submap;
    const auto onMap = [&](const CPose2D& robot) {
        return readingsOnMap(submap.map(), scan, robot + sensorOnRobot);
    };
    // The refutation below weighs fits on the submap before its newest part only: a keyframe
    // placed by odometry alone may be far off, and a start that fits the copy of the place it
    // added (turned with it) refutes nothing.
    const auto onRegisteredMap = [&](const CPose2D& robot) {
        return submap.readingsBeforeNewestPart(scan, robot + sensorOnRobot, kFitDistance);
    };
    // A clear margin: along a corridor a shifted start explains nearly as much as the right one.
    const auto margin = std::size_t(options_.secondOpinionMargin * double(scan.validCount()));
    std::size_t bestOn = onMap(icp.pose) + margin;
    std::optional<IcpAttempt> best;
    bool bestWide = false;                              // from the wider ring of turned starts
    std::array<CPose2D, kMaxSecondStarts> settledEnds;  // where the starts' ICP settled
    std::size_t settledCount = 0;
    std::size_t beyondOn = 0;  // the best fit among ends beyond the jump bounds
    // `judgedFromItself`: the last motion's start is judged against the jump bounds from
    // itself, not from the reading it replaces (which missed part of the turn).
    const auto tryStart = [&](const CPose2D& start, bool judgedFromItself, bool wide) {
        IcpAttempt alt = icpFrom(scan, sensorOnRobot, submap, start);
        if (settled(alt))
            settledEnds[settledCount++] = alt.robot;
        const CPose2D& from = judgedFromItself ? start : prediction.inSubmap;
        if (!prediction.odometryJumped && beyondOdometryJump(options_, alt.robot - from)) {
            beyondOn = std::max(beyondOn, onRegisteredMap(alt.robot));
            return;
        }
        const std::size_t altOn = onMap(alt.robot);
        if (altOn <= bestOn)
            return;
        bestOn = altOn;
        best = std::move(alt);
        bestWide = wide;
    };
    // The last motion, the matcher's answer, and the prediction turned by +-1 and +-2 turns.
    if (fromLastMotion)
        tryStart(prediction.inSubmap + prediction.toLastMotion(), true, false);
    if (matched)
        tryStart(prediction.lastKeyframeInSubmap() + matched->pose, false, false);
    const auto tryTurns = [&](std::initializer_list<double> turns, bool wide) {
        for (const double k : turns)
            tryStart(turnedStart(prediction, k), false, wide);
    };
    if (options_.secondOpinionTurn > 0) {
        tryTurns({-2.0, -1.0, 1.0, 2.0}, false);
        // No start settled: the reading's heading is farther off than those starts reach (a
        // short reading that missed 30 deg of a turn), and a wider ring may find the basin.
        if (options_.secondOpinionWideTurns && settledCount == 0)
            tryTurns({-4.0, -3.0, 3.0, 4.0}, true);
    }
    if (best) {
        icp.pose = best->robot;
        icp.overlap = best->overlap;
        icp.rawCovariance = best->icp.covariance;
        icp.covariance = edgeCovariance(best->icp.covariance, prediction.distanceFromLastKeyframe,
                                        prediction.turnFromLastKeyframe);
        icp.secondStart = true;
        icp.wideTurn = bestWide;
    }
    // An end beyond the jump bounds that fits clearly better than the answer refutes it: the
    // answer is one of several poor fits, and the scan goes to the graph matcher (a step after
    // a turn on the spot, from a reading that missed most of it: the answer 24 deg off on 59
    // readings, ICP from the last motion right on 341 but 0.9 m from that start).
    if (options_.secondOpinionRefutedBeyondJump && beyondOn > onRegisteredMap(icp.pose) + margin) {
        icp.refutedBeyondJump = true;
        return false;
    }
    // Far beyond the odometry's noise an answer counts only where some start settled.
    return !outrunsOdometry(prediction, icp.pose) ||
           std::any_of(settledEnds.begin(), settledEnds.begin() + settledCount,
                       [&](const CPose2D& end) { return sameEnd(end, icp.pose); });
}

const Prediction& ScanRegistration::preferredPrediction(const matching::PolarScan& scan,
                                                        const CPose2D& sensorOnRobot,
                                                        const Prediction& prediction,
                                                        std::optional<IcpAttempt>& started) {
    jumpedIcpEnd_.reset();
    readingIcp_.reset();
    motionIcp_.reset();
    jumpChoiceRecorded_ = false;
    jumpByPrior_ = false;
    jumpSidewaysByTurn_ = false;
    stallStepBorneOut_.reset();
    if (!prediction.submap || prediction.submap->map().size() == 0 || scan.validCount() == 0)
        return prediction;
    if (prediction.odometryStalled)
        return standstillBorneOut(scan, sensorOnRobot, prediction, started);
    if (!options_.confirmLargeCorrections)
        return prediction;
    if (prediction.odometryJumped)
        return jumpBorneOut(scan, sensorOnRobot, prediction, started);
    const CPose2D toMotion = prediction.toLastMotion();
    if (toMotion.norm() <= options_.icpMaxDistance)
        return prediction;  // ICP from the odometry reaches it
    const Submap& submap = *prediction.submap;
    const CPose2D byMotion = prediction.inSubmap + toMotion;
    IcpAttempt fromOdometry = icpFrom(scan, sensorOnRobot, submap, prediction.inSubmap);
    IcpAttempt fromMotion = icpFrom(scan, sensorOnRobot, submap, byMotion);
    // Both found the same pose (then only the size of the odometry's correction is in doubt),
    // or the last motion's fits clearly better, or ICP from the odometry ends where tryIcp()
    // would reject it while from the last motion it passes and fits more of the scan.
    const bool onlyMotionPasses = passesAlone(submap.map(), scan, sensorOnRobot, fromMotion,
                                              byMotion, fromOdometry, prediction.inSubmap);
    if (!onlyMotionPasses && !bearsOut(submap.map(), scan, sensorOnRobot, fromMotion.robot,
                                       fromOdometry.robot, options_.secondOpinionMargin)) {
        started = std::move(fromOdometry);
        return prediction;
    }
    started = std::move(fromMotion);
    return shifted(prediction, toMotion);
}

const Prediction& ScanRegistration::standstillBorneOut(const matching::PolarScan& scan,
                                                       const CPose2D& sensorOnRobot,
                                                       const Prediction& prediction,
                                                       std::optional<IcpAttempt>& started) {
    // The stalled odometry's step is zero; the last motion is the robot's as far as anything
    // says. Along a corridor whose walls fix nothing along it ICP keeps whichever start it
    // gets, and from the standstill the stall's scans stay behind (keyframes among them, which
    // the scans after are registered against). Turns are left alone: the laser fixes them.
    const CPose2D toMotion = prediction.toLastMotion();
    if (toMotion.norm() <= OdometryLag::kMovedDistance)
        return prediction;
    const Submap& submap = *prediction.submap;
    IcpAttempt fromStandstill = icpFrom(scan, sensorOnRobot, submap, prediction.inSubmap);
    const CPose2D byMotion = prediction.inSubmap + toMotion;
    IcpAttempt fromMotion = icpFrom(scan, sensorOnRobot, submap, byMotion);
    // Both ended at the same pose, nearer the last motion's start, and the step went straight
    // on: the scan bore it out from both starts, and the checks of ICP's correction along the
    // heading measure it from the last motion (checkAlongHeading). From the standstill such a
    // step looked like one that something in the foreground had pushed (furniture beside the
    // robot), and was taken back. In a turn they still measure it from the standstill, whose
    // scans the stall's bridging places afterwards (mit-csail with one beam in four: worst
    // relation 0.29 m so, 0.55 m from the last motion). The prediction stays the standstill's.
    const CPose2D step = fromStandstill.robot - prediction.inSubmap;
    if (sameEnd(fromStandstill.robot, fromMotion.robot) &&
        (fromMotion.robot - byMotion).norm() < step.norm() &&
        std::abs(step.phi()) < kStraightStepTurn)
        stallStepBorneOut_ = byMotion;
    // Kept where both ended at the same pose, or the standstill's fits clearly more, or only
    // ICP from the standstill passes tryIcp()'s tests and fits more of the scan: where the
    // robot stops turning in a stall, the last motion's turn is a start farther off than
    // ICP's basin (ring51, stalling robot: 14 deg where the robot turned 2; ICP from there
    // ended at -12 deg on a third of the scan, and the failed scan kept the last motion).
    const bool onlyStandstillPasses = passesAlone(submap.map(), scan, sensorOnRobot, fromStandstill,
                                                  prediction.inSubmap, fromMotion, byMotion);
    if (onlyStandstillPasses || bearsOut(submap.map(), scan, sensorOnRobot, fromStandstill.robot,
                                         fromMotion.robot, options_.secondOpinionMargin)) {
        started = std::move(fromStandstill);
        return prediction;
    }
    started = std::move(fromMotion);
    return shifted(prediction, toMotion);
}

const Prediction& ScanRegistration::shifted(const Prediction& prediction, const CPose2D& shift) {
    motionPrediction_ = prediction;
    motionPrediction_.odometryStep = prediction.odometryStep + shift;
    motionPrediction_.inSubmap = prediction.inSubmap + shift;
    motionPrediction_.fromLastKeyframe = prediction.fromLastKeyframe + shift;
    motionPrediction_.fromRegisteredKeyframe = prediction.fromRegisteredKeyframe + shift;
    motionPrediction_.odometryPredicted = false;
    return motionPrediction_;
}

const Prediction& ScanRegistration::jumpBorneOut(const matching::PolarScan& scan,
                                                 const CPose2D& sensorOnRobot,
                                                 const Prediction& prediction,
                                                 std::optional<IcpAttempt>& started) {
    // The odometry's pose is the last motion's, less that motion, plus the odometry's step.
    const CPose2D toOdometry = prediction.toReading();
    const Submap& submap = *prediction.submap;
    const CPose2D byOdometry = prediction.inSubmap + toOdometry;
    IcpAttempt fromOdometry = icpFrom(scan, sensorOnRobot, submap, byOdometry);
    // The odometry's sideways error grows with the step: max_lateral_correction is for steps
    // up to the jump distance (a 1.1 m step at a third of the scan rate is 0.1 m off sideways).
    double sidewaysScale =
        std::max(1.0, prediction.readingStep.norm() / options_.odometryJumpDistance);
    if (!acceptable(fromOdometry, byOdometry, true, sidewaysScale)) {
        // Unless the reading holds a turn the last reading missed, and the chord's turn by it
        // accounts for ICP's sideways correction.
        const double widened =
            sidewaysScale + chordTurnAllowance(prediction, fromOdometry.robot - byOdometry);
        jumpSidewaysByTurn_ =
            widened > sidewaysScale && acceptable(fromOdometry, byOdometry, true, widened);
        if (!jumpSidewaysByTurn_) {
            jumpedIcpEnd_ = fromOdometry.robot;  // for jumpBetween() and jumpOverTwoReadings()
            readingIcp_ = fromOdometry;
            return prediction;
        }
        sidewaysScale = widened;
    }
    // A real jump (a stall caught up in one step) puts ICP from the odometry off the robot:
    // along a corridor it may fit as well as from the last motion, but not better. Where ICP
    // from the last motion fails the tests, that motion is off the robot instead.
    const IcpAttempt& fromMotion = icpFromLastMotion(scan, sensorOnRobot, prediction);
    const matching::LineMap& map = submap.map();
    const bool motionPasses = acceptable(fromMotion, prediction.inSubmap, /*boundSideways=*/false);
    const bool readingFitsBetter = bearsOut(map, scan, sensorOnRobot, fromOdometry.robot,
                                            fromMotion.robot, options_.jumpChoiceMargin);
    // A reading only the widened bound let through is no evidence of how this log's jumps go.
    if (!jumpSidewaysByTurn_)
        recordJumpChoice(submap, scan, sensorOnRobot, fromOdometry, fromMotion);
    // Undecided by the scan, the log's earlier jumps decide here, before the graph matcher:
    // along a corridor ICP holds wherever it starts, and the matcher's answer, confirmed on the
    // same submap, would be no better a guess (a stalled odometry's catch-up, taken for the
    // last motion, lost the distance it caught up).
    jumpByPrior_ = motionPasses && !readingFitsBetter && options_.undecidedJumpByPrior &&
                   priorFavoursReading(map, scan, sensorOnRobot, fromOdometry, fromMotion);
    if (motionPasses && !readingFitsBetter && !jumpByPrior_) {
        if (jumpSidewaysByTurn_) {  // not taken: as refused, for the searches after
            jumpSidewaysByTurn_ = false;
            jumpedIcpEnd_ = fromOdometry.robot;
        }
        readingIcp_ = std::move(fromOdometry);
        return prediction;
    }
    started = std::move(fromOdometry);
    shifted(prediction, toOdometry);
    motionPrediction_.odometryJumped = false;
    motionPrediction_.odometryPredicted = true;  // the odometry's own step, borne out
    // Judged again by tryIcp(): by the bound it passed here, not the one for shorter steps
    // (office_c, stalling robot, seed 6: 0.11 m sideways after a 1.04 m catch-up failed there,
    // and the failed scan kept the reading, 18 deg off the robot's turn).
    motionPrediction_.sidewaysScale = sidewaysScale;
    return motionPrediction_;
}

double ScanRegistration::chordTurnAllowance(const Prediction& prediction,
                                            const CPose2D& correction) const {
    if (!options_.jumpSidewaysByTurn || !(options_.maxLateralCorrection > 0) ||
        !prediction.lastReading)
        return 0;
    // The turn the last reading missed (registration turned that step further than it read),
    // and ICP's heading correction, which takes it back where the reading holds it.
    const double missed =
        mrpt::math::wrapToPi(prediction.lastMotion.phi() - prediction.lastReading->phi());
    const double back = mrpt::math::wrapToPi(correction.phi());
    if (missed * back >= 0)
        return 0;
    // The step's chord turned by half of what it took back.
    return prediction.readingStep.norm() *
           std::sin(0.5 * std::min(std::abs(missed), std::abs(back))) /
           options_.maxLateralCorrection;
}

const Prediction& ScanRegistration::jumpBetween(const matching::PolarScan& scan,
                                                const CPose2D& sensorOnRobot,
                                                const Prediction& prediction,
                                                std::optional<IcpAttempt>& started) {
    if (!(options_.jumpSearchStep > 0) || !jumpedIcpEnd_ || !prediction.odometryJumped)
        return prediction;
    const CPose2D fromOdometry = *jumpedIcpEnd_;
    // Steps from the last motion (the prediction's) to the odometry's, in the robot frame of
    // the last scan: the robot's true step lies between them when the odometry stalled.
    const CPose2D& from = prediction.odometryStep;
    const CPose2D& to = prediction.readingStep;
    const double dx = to.x() - from.x(), dy = to.y() - from.y();
    const double dphi = mrpt::math::wrapToPi(to.phi() - from.phi());
    const int intervals = std::min(
        kMaxJumpIntervals,
        static_cast<int>(std::max(std::ceil(std::abs(dphi) / options_.jumpSearchStep),
                                  std::ceil(std::hypot(dx, dy) / options_.icpMaxDistance))));
    if (intervals < 2)
        return prediction;  // nothing between that ICP from either end would not reach
    const Submap& submap = *prediction.submap;
    const matching::LineMap& map = submap.map();
    // ICP from each start between, its correction not bounded sideways: a start interpolated
    // between two steps is off the arc the robot turned on.
    std::size_t count = 0;
    for (int k = 1; k < intervals; ++k) {
        const double a = double(k) / intervals;
        const CPose2D step(from.x() + a * dx, from.y() + a * dy, from.phi() + a * dphi);
        const CPose2D start = prediction.inSubmap + ((-from) + step);
        IcpAttempt& attempt = betweenAttempts_[count];
        attempt = icpFrom(scan, sensorOnRobot, submap, start);
        if (acceptable(attempt, start, /*boundSideways=*/false))
            ++count;
    }
    // The best end that another start (or ICP from the odometry's step) also reached: a
    // basin, not a place one start happened to stop in.
    const IcpAttempt* best = nullptr;
    std::size_t bestOn = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const CPose2D& end = betweenAttempts_[i].robot;
        bool agreed = sameEnd(end, fromOdometry);
        for (std::size_t j = 0; j < count && !agreed; ++j)
            agreed = j != i && sameEnd(end, betweenAttempts_[j].robot);
        const std::size_t on = agreed ? readingsOnMap(map, scan, end + sensorOnRobot) : 0;
        if (agreed && (!best || on > bestOn)) {
            best = &betweenAttempts_[i];
            bestOn = on;
        }
    }
    if (!best)
        return prediction;
    // As for the odometry's own step: clearly better than ICP from the last motion.
    const IcpAttempt& fromMotion = icpFromLastMotion(scan, sensorOnRobot, prediction);
    const bool onlyBetweenPasses =
        !acceptable(fromMotion, prediction.inSubmap) &&
        bestOn > readingsOnMap(map, scan, fromMotion.robot + sensorOnRobot);
    if (!onlyBetweenPasses && !bearsOut(map, scan, sensorOnRobot, best->robot, fromMotion.robot,
                                        options_.secondOpinionMargin))
        return prediction;
    // Predicted where the starts agreed, and registered there by the ICP that ended there.
    shifted(prediction, best->robot - prediction.inSubmap);
    started = *best;
    motionPrediction_.odometryJumped = false;
    return motionPrediction_;
}

bool ScanRegistration::tryPastMissedTurn(const matching::PolarScan& scan,
                                         const CPose2D& sensorOnRobot, const Prediction& prediction,
                                         Registration& out) {
    if (!prediction.pastMissedTurn || !prediction.odometryPredicted || !prediction.submap)
        return false;
    const CPose2D start = prediction.inSubmapAfter(*prediction.pastMissedTurn);
    if (!answerIcpFrom(scan, sensorOnRobot, prediction, start, out))
        return false;
    out.pastMissedTurn = true;
    return true;
}

bool ScanRegistration::tryTurnedStarts(const matching::PolarScan& scan,
                                       const CPose2D& sensorOnRobot, const Prediction& prediction,
                                       Registration& out) {
    if (!options_.turnedStartSearch || !(options_.secondOpinionTurn > 0) ||
        prediction.odometryJumped || !prediction.odometryPredicted || prediction.odometryStalled ||
        !prediction.submap || prediction.submap->map().size() == 0 || scan.validCount() == 0)
        return false;
    // Only in a log whose odometry has jumped (a low scan rate, a stalling odometry): at every
    // scan a failed registration is a crowd's doing, and turned starts settle on the people
    // (eight tours with 15 people at every scan broke, office_i seed 32 0.20 -> 5.41 m).
    if (!odometryHasJumped())
        return false;
    // A shorter reading stalled in distance too: turned starts settle on the right heading but
    // short along it, as far as the reading fell short (0.5-0.9 m on six such readings).
    if (prediction.odometryStep.norm() < kStepAsStepped * prediction.lastMotion.norm())
        return false;
    std::array<IcpAttempt, 8> ends;  // those that settled within the bounds
    std::size_t count = 0;
    for (const double k : {-4.0, -3.0, -2.0, -1.0, 1.0, 2.0, 3.0, 4.0}) {
        IcpAttempt a = icpFrom(scan, sensorOnRobot, *prediction.submap, turnedStart(prediction, k));
        const CPose2D correction = a.robot - prediction.inSubmap;
        if (!settled(a) || a.overlap < options_.minInlierRatio ||
            beyondOdometryJump(options_, correction))
            continue;
        // A heading that lagged through the step turned its chord by about half the lag.
        const double sideways =
            prediction.odometryStep.norm() * std::abs(std::sin(0.5 * correction.phi())) +
            prediction.sidewaysScale * options_.maxLateralCorrection;
        if (std::abs(correction.y()) > sideways)
            continue;
        ends[count++] = std::move(a);
    }
    // One answer, reached from two starts or more: ends that disagree are look-alikes.
    const auto agrees = [&](const IcpAttempt& e) { return sameEnd(e.robot, ends[0].robot); };
    if (count < 2 || !std::all_of(ends.begin() + 1, ends.begin() + count, agrees))
        return false;
    answerOnSubmap(ends[0], prediction, RegistrationMethod::Icp, out);
    out.turnedStart = true;
    return true;
}

const Prediction& ScanRegistration::jumpOverTwoReadings(const matching::PolarScan& scan,
                                                        const CPose2D& sensorOnRobot,
                                                        const Prediction& prediction,
                                                        std::optional<IcpAttempt>& started) {
    if (!options_.jumpOverTwoReadings || !jumpedIcpEnd_ || !prediction.odometryJumped ||
        !prediction.lastReading)
        return prediction;
    // Only where registration departed from the last reading: otherwise the two readings
    // start where this one alone did.
    const CPose2D& lastReading = *prediction.lastReading;
    const CPose2D departure = (-prediction.lastMotion) + lastReading;
    if (departure.norm() <= OdometryLag::kAgreeDistance &&
        std::abs(mrpt::math::wrapToPi(departure.phi())) <= OdometryLag::kAgreeAngle)
        return prediction;
    // From the pose of the scan before the last (the prediction less the predicted step and
    // the last motion), both readings as the odometry read them.
    const CPose2D toBoth = (-prediction.odometryStep) + (-prediction.lastMotion) + lastReading +
                           prediction.readingStep;
    const CPose2D byBoth = prediction.inSubmap + toBoth;
    const Submap& submap = *prediction.submap;
    IcpAttempt fromBoth = icpFrom(scan, sensorOnRobot, submap, byBoth);
    // As for a jumped reading (jumpBorneOut): the sideways bound grows with the steps' length.
    const double sidewaysScale = std::max(
        1.0, (lastReading + prediction.readingStep).norm() / options_.odometryJumpDistance);
    if (!acceptable(fromBoth, byBoth, true, sidewaysScale))
        return prediction;
    const IcpAttempt& fromMotion = icpFromLastMotion(scan, sensorOnRobot, prediction);
    if (acceptable(fromMotion, prediction.inSubmap, /*boundSideways=*/false) &&
        !bearsOut(submap.map(), scan, sensorOnRobot, fromBoth.robot, fromMotion.robot,
                  options_.jumpChoiceMargin))
        return prediction;
    started = std::move(fromBoth);
    shifted(prediction, toBoth);
    motionPrediction_.odometryJumped = false;
    motionPrediction_.odometryPredicted = true;  // the odometry's own steps
    motionPrediction_.sidewaysScale = sidewaysScale;
    return motionPrediction_;
}

double ScanRegistration::typicalResidual() const {
    // The median of five registrations already tells a poor fit: with more, a log's first turns
    // on the spot went unchecked (office_c, stalling robot, seed 9: ICP 15 deg off, unconverged,
    // on 74 of 361 readings at the 20th scan).
    constexpr std::size_t kMinCount = 5;
    if (residualCount_ < kMinCount)
        return 0;
    std::array<double, 101> sorted = recentResiduals_;
    const std::size_t n = std::min(residualCount_, sorted.size());
    std::nth_element(sorted.begin(), sorted.begin() + n / 2, sorted.begin() + n);
    return sorted[n / 2];
}

bool ScanRegistration::tryGraphMatcher(const matching::PolarScan& scan,
                                       const CPose2D& sensorOnRobot, const Prediction& prediction,
                                       const features::ScanFeatures& features,
                                       const CPose2D* failedIcp, Registration& out) {
    // A keyframe placed by odometry alone may be tens of degrees off (a stall during a turn):
    // an answer relative to it would keep the error.
    if (prediction.registeredKeyframe &&
        matchKeyframe(scan, sensorOnRobot, prediction.fromRegistered(), features, failedIcp, out)) {
        out.fromRegisteredKeyframe = true;
        return true;
    }
    return matchKeyframe(scan, sensorOnRobot, prediction, features, failedIcp, out);
}

bool ScanRegistration::matchKeyframe(const matching::PolarScan& scan, const CPose2D& sensorOnRobot,
                                     const Prediction& prediction,
                                     const features::ScanFeatures& features,
                                     const CPose2D* failedIcp, Registration& out) {
    const Keyframe& kf = *prediction.lastKeyframe;
    // The prediction as a guess (the matcher retries guess-free when it leads nowhere).
    const CPose2D guess =
        (prediction.fromLastKeyframe + sensorOnRobot) - (CPose2D() + kf.sensorOnRobot);
    const matching::MatchResult& m = matcher_.match(*prediction.lastKeyframeReadings,
                                                    kf.features->features, scan, features, guess);
    if (!m.reliable())
        return false;
    const CPose2D pose = kf.sensorOnRobot + m.pose + (-sensorOnRobot);
    if (prediction.odometryJumped && options_.confirmLargeCorrections &&
        jumpMatchRefused(scan, sensorOnRobot, prediction, pose))
        return false;
    // Unless the odometry jumped, it bounds the answer: a correction it would have counted as
    // a jump is a look-alike match (a corridor seen the other way round), not the robot's
    // motion. Guess-free answers are exactly the ones that can land there.
    if (!prediction.odometryJumped && answerBeyondJump(prediction, pose, 1)) {
        return options_.confirmLargeCorrections && failedIcp &&
               confirmOnSubmap(scan, sensorOnRobot, prediction, pose, *failedIcp, out);
    }
    // Where ICP from the prediction stayed within the correction bounds (rejected for too
    // little of the scan on the submap), a refused answer leaves the scan at a prediction ICP
    // agreed with. (Beyond them, ICP and the matcher may both be right and the prediction
    // wrong: mit-csail at a third of its scans, 0.036 -> 0.044 m when refused there too.)
    if (options_.matcherForegroundCheck && failedIcp &&
        plausibleCorrection(*failedIcp - prediction.inSubmap) &&
        !bornOutWithoutForeground(scan, sensorOnRobot, prediction, pose, *failedIcp)) {
        out.matcherRefusedForeground = true;
        return false;
    }
    // A fast turn the odometry misread can leave the matcher on a turned copy of the place;
    // ICP from turned starts, which fits clearly more of the scan, knows better.
    if (options_.matcherSecondOpinion && failedIcp && options_.secondOpinionTurn > 0) {
        if (const auto better =
                icpOutfitsMatcher(scan, sensorOnRobot, prediction,
                                  prediction.lastKeyframeInSubmap() + pose, *failedIcp)) {
            answerOnSubmap(*better, prediction, RegistrationMethod::Icp, out);
            out.outfitsMatcher = true;
            return true;
        }
    }
    out.method = RegistrationMethod::GraphMatcher;
    out.reference = kf.id;
    out.pose = pose;
    // Within the jump bounds only of the catch-up the reading after a stall may be.
    out.withinStallCatchUp = prediction.stallCatchUpStep &&
                             beyondOdometryJump(options_, pose - prediction.fromLastKeyframe);
    out.rawCovariance = m.covariance;
    out.covariance = edgeCovariance(m.covariance, prediction.distanceFromLastKeyframe,
                                    prediction.turnFromLastKeyframe);
    out.overlap = 0;
    return true;
}

bool ScanRegistration::jumpMatchRefused(const matching::PolarScan& scan,
                                        const CPose2D& sensorOnRobot, const Prediction& prediction,
                                        const CPose2D& matched) {
    // The odometry's step, in the last keyframe's frame like `matched`.
    const CPose2D byReading = prediction.fromLastKeyframe + prediction.toReading();
    const CPose2D fromMotion = matched - prediction.fromLastKeyframe;
    const CPose2D fromReading = matched - byReading;
    // A stall caught up in one step is off by the stall's motion, within the jump bounds of
    // the scans it lasted; the matcher's look-alikes are metres off (a corridor seen the other
    // way round: 2.7 m and 180 deg, `gen51` at a third of its scans).
    if (beyondOdometryJump(options_, fromMotion, 2) && beyondOdometryJump(options_, fromReading, 2))
        return true;
    if (!beyondOdometryJump(options_, fromMotion) || !beyondOdometryJump(options_, fromReading) ||
        !readingIcp_ || !prediction.submap)
        return false;
    const Submap& submap = *prediction.submap;
    const CPose2D start = prediction.lastKeyframeInSubmap() + matched;
    const IcpAttempt icp = icpFrom(scan, sensorOnRobot, submap, start);
    const IcpAttempt& reading = *readingIcp_;
    // Where ICP from the odometry's step corrected it plausibly, the step is a candidate the
    // answer must beat; where it did not, the answer only must not fit clearly worse.
    const CPose2D readingStart = prediction.lastKeyframeInSubmap() + byReading;
    if (plausibleCorrection(reading.robot - readingStart, /*boundSideways=*/false))
        return !bearsOut(submap.map(), scan, sensorOnRobot, icp.robot, reading.robot,
                         options_.jumpChoiceMargin);
    return !sameEnd(icp.robot, reading.robot) &&
           bearsOut(submap.map(), scan, sensorOnRobot, reading.robot, icp.robot,
                    options_.jumpChoiceMargin);
}

bool ScanRegistration::keepCaughtUpReading(const matching::PolarScan& scan,
                                           const CPose2D& sensorOnRobot,
                                           const Prediction& prediction, Registration& out) {
    if (!prediction.odometryLagging || !prediction.submap)
        return false;
    // A catch-up is a guess from the size of the step alone: at a low scan rate a turn on the
    // spot after a stall reads as much more turn than the last motion, and is the robot's.
    const CPose2D byReading = prediction.inSubmap + prediction.toReading();
    if (!answerIcpFrom(scan, sensorOnRobot, prediction, byReading, out)) {
        // Where registration placed the stall's scans, the reading holds their motion too: a
        // robot that stopped and turned on the spot after the stall reads the stall's step
        // once more (office_b, stalling robot at a third, seed 14: 1.09 m and -63 deg read
        // after a stall of 1.04 m and -18 deg where the robot went 0.04 m and turned -47).
        if (!prediction.catchUpLessStall)
            return false;
        const CPose2D lessStall = prediction.inSubmapAfter(*prediction.catchUpLessStall);
        if (!answerIcpFrom(scan, sensorOnRobot, prediction, lessStall, out))
            return false;
        out.catchUpLessStall = true;
    }
    out.catchUpReadingKept = true;
    return true;
}

bool ScanRegistration::keepJumpedReading(const matching::PolarScan& scan,
                                         const CPose2D& sensorOnRobot, const Prediction& prediction,
                                         Registration& out) {
    if (!prediction.odometryJumped || !readingIcp_ || !prediction.submap)
        return false;
    const IcpAttempt& reading = *readingIcp_;
    const Submap& submap = *prediction.submap;
    const CPose2D byReading = prediction.inSubmap + prediction.toReading();
    if (!plausibleCorrection(reading.robot - byReading, /*boundSideways=*/false))
        return false;
    const IcpAttempt& fromMotion = icpFromLastMotion(scan, sensorOnRobot, prediction);
    if (sameEnd(reading.robot, fromMotion.robot))
        return false;
    recordJumpChoice(submap, scan, sensorOnRobot, reading, fromMotion);
    const matching::LineMap& map = submap.map();
    const double margin = options_.jumpChoiceMargin;
    // Undecided by the scan (both fit alike: new ground), this log's earlier jumps decide.
    if (!bearsOut(map, scan, sensorOnRobot, reading.robot, fromMotion.robot, margin) &&
        !priorFavoursReading(map, scan, sensorOnRobot, reading, fromMotion))
        return false;
    answerOnSubmap(reading, prediction, RegistrationMethod::Icp, out);
    out.jumpBorneOut = true;
    return true;
}

bool ScanRegistration::answerIcpFrom(const matching::PolarScan& scan, const CPose2D& sensorOnRobot,
                                     const Prediction& prediction, const CPose2D& start,
                                     Registration& out) {
    const IcpAttempt icp = icpFrom(scan, sensorOnRobot, *prediction.submap, start);
    if (!acceptable(icp, start))
        return false;
    answerOnSubmap(icp, prediction, RegistrationMethod::Icp, out);
    return true;
}

void ScanRegistration::answerOnSubmap(const IcpAttempt& icp, const Prediction& prediction,
                                      RegistrationMethod method, Registration& out) const {
    out.method = method;
    out.reference = prediction.submap->anchor();
    out.pose = icp.robot;
    out.overlap = icp.overlap;
    out.rawCovariance = icp.icp.covariance;
    out.covariance = edgeCovariance(icp.icp.covariance, prediction.distanceFromLastKeyframe,
                                    prediction.turnFromLastKeyframe);
}

const ScanRegistration::IcpAttempt& ScanRegistration::icpFromLastMotion(
    const matching::PolarScan& scan, const CPose2D& sensorOnRobot, const Prediction& prediction) {
    if (!motionIcp_)
        motionIcp_ = icpFrom(scan, sensorOnRobot, *prediction.submap, prediction.inSubmap);
    return *motionIcp_;
}

bool ScanRegistration::priorFavoursReading(const matching::LineMap& map,
                                           const matching::PolarScan& scan,
                                           const CPose2D& sensorOnRobot, const IcpAttempt& reading,
                                           const IcpAttempt& motion) const {
    return odometryUsuallyRight() && !bearsOut(map, scan, sensorOnRobot, motion.robot,
                                               reading.robot, options_.jumpChoiceMargin);
}

void ScanRegistration::recordJumpChoice(const Submap& submap, const matching::PolarScan& scan,
                                        const CPose2D& sensorOnRobot, const IcpAttempt& reading,
                                        const IcpAttempt& motion) {
    if (sameEnd(reading.robot, motion.robot))
        return;
    if (jumpChoiceRecorded_)
        return;  // jumpBorneOut() and keepJumpedReading() see the same two ICP ends
    jumpChoiceRecorded_ = true;
    const double margin = options_.jumpChoiceMargin;
    if (bearsOut(submap.map(), scan, sensorOnRobot, reading.robot, motion.robot, margin))
        ++jumpsForOdometry_;
    else if (bearsOut(submap.map(), scan, sensorOnRobot, motion.robot, reading.robot, margin))
        ++jumpsForLastMotion_;
}

bool ScanRegistration::bornOutWithoutForeground(const matching::PolarScan& scan,
                                                const CPose2D& sensorOnRobot,
                                                const Prediction& prediction,
                                                const CPose2D& matched, const CPose2D& failedIcp) {
    if (!prediction.submap || foreground_.remove(scan, foregroundOptions_, background_) == 0)
        return true;
    const Submap& submap = *prediction.submap;
    const CPose2D start = prediction.lastKeyframeInSubmap() + matched;
    const IcpAttempt icp = icpFrom(scan, sensorOnRobot, submap, start);
    // The along-heading check's margin: the people's pull is along the heading too. (A
    // quarter, second_opinion_margin, refused right answers that fitted 16 % more at fr079's
    // fast turns at a third of its scans.)
    return bearsOut(submap.map(), background_, sensorOnRobot, icp.robot, failedIcp,
                    options_.alongHeadingMargin);
}

bool ScanRegistration::answerBeyondJump(const Prediction& prediction, const CPose2D& matched,
                                        double scans) const {
    if (!beyondOdometryJump(options_, matched - prediction.fromLastKeyframe, scans))
        return false;
    // Right after a stall the reading may hold the stall's motion too: an answer within the
    // bounds of that catch-up is no jump (lab_b, stalling robot, seed 12: 1.19 m read where the
    // robot, having gone 1.04 m in the stall, went 0.16 m and turned 47 deg on the spot).
    if (prediction.stallCatchUpStep &&
        !beyondOdometryJump(
            options_, matched - (prediction.lastScanPose() + *prediction.stallCatchUpStep), scans))
        return false;
    // A stalled odometry's step says nothing: the robot may have stood where it was or moved
    // on by its last motion (or turned in place), and the answer is bounded from either.
    return !prediction.odometryStalled ||
           beyondOdometryJump(options_, matched - prediction.lastScanPose(), scans);
}

std::optional<ScanRegistration::IcpAttempt> ScanRegistration::icpOutfitsMatcher(
    const matching::PolarScan& scan, const CPose2D& sensorOnRobot, const Prediction& prediction,
    const CPose2D& matchedInSubmap, const CPose2D& failedIcp) {
    const Submap& submap = *prediction.submap;
    // Fits as secondOpinion() counts them: readings within 5 cm of the submap, a clear margin.
    const double margin = std::max(1.0, options_.secondOpinionMargin * double(scan.validCount()));
    double bestOn =
        double(readingsOnMap(submap.map(), scan, matchedInSubmap + sensorOnRobot)) + margin;
    std::optional<IcpAttempt> best;
    for (const double k : {-2.0, -1.0, 1.0, 2.0}) {
        const CPose2D start = prediction.inSubmap + CPose2D(0, 0, k * options_.secondOpinionTurn);
        IcpAttempt alt = icpFrom(scan, sensorOnRobot, submap, start);
        if (!settled(alt) || !acceptable(alt, start, false) || sameEnd(alt.robot, failedIcp) ||
            beyondOdometryJump(options_, alt.robot - prediction.inSubmap))
            continue;
        const double on = double(readingsOnMap(submap.map(), scan, alt.robot + sensorOnRobot));
        if (on < bestOn)
            continue;
        bestOn = on;
        best = std::move(alt);
    }
    return best;
}

bool ScanRegistration::confirmOnSubmap(const matching::PolarScan& scan,
                                       const CPose2D& sensorOnRobot, const Prediction& prediction,
                                       const CPose2D& matched, const CPose2D& failedIcp,
                                       Registration& out) {
    if (answerBeyondJump(prediction, matched, 2))
        return false;
    const Submap& submap = *prediction.submap;
    const CPose2D start = prediction.lastKeyframeInSubmap() + matched;
    const IcpAttempt icp = icpFrom(scan, sensorOnRobot, submap, start);
    if (!acceptable(icp, start))
        return false;
    // Either ICP from the prediction ended there too (rejected only for the size of the
    // correction), or the scan fits clearly better there than where it ended.
    if (!bearsOut(submap.map(), scan, sensorOnRobot, icp.robot, failedIcp,
                  options_.secondOpinionMargin))
        return false;
    answerOnSubmap(icp, prediction, RegistrationMethod::GraphMatcher, out);
    out.confirmedOnSubmap = true;
    return true;
}

}  // namespace toposlam::mapping
