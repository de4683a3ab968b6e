#include <mrpt/math/wrap2pi.h>
#include <mrpt/system/datetime.h>
#include <toposlam/io/CpuTime.h>
#include <toposlam/mapping/GraphSlam.h>
#include <toposlam/mapping/MapRange.h>
#include <toposlam/mapping/TrajectorySmoother.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <utility>

namespace toposlam::mapping {

using mrpt::poses::CPose2D;

namespace {
EdgeKind edgeKind(RegistrationMethod m) {
    switch (m) {
        case RegistrationMethod::Icp:
            return EdgeKind::Registration;
        case RegistrationMethod::GraphMatcher:
            return EdgeKind::GraphMatch;
        case RegistrationMethod::Odometry:
            break;
    }
    return EdgeKind::Odometry;
}

}  // namespace

GraphSlam::GraphSlam(const GraphSlamOptions& options,
                     const matching::GraphMatcherOptions& matcherOptions,
                     std::unique_ptr<features::FeatureExtractor> extractor,
                     const CPose2D& initialPose)
    : options_(options),
      extractor_(std::move(extractor)),
      registration_(options_, matcherOptions),
      odometryCalibration_(options_.odometryCalibration),
      loopCloser_(options_, matcherOptions),
      graph_(options.loopLossScale),
      initialPose_(initialPose),
      current_(initialPose) {
    currentCovariance_.setZero();
}

CPose2D GraphSlam::scanPose(std::size_t i) const {
    return graph_.pose(scans_[i].keyframe) + scans_[i].fromKeyframe;
}

std::vector<CPose2D> GraphSlam::scanPoses() const {
    if (!options_.smoothScans) {
        std::vector<CPose2D> out;
        out.reserve(scans_.size());
        for (std::size_t i = 0; i < scans_.size(); ++i)
            out.push_back(scanPose(i));
        return out;
    }
    std::vector<SmoothingInput> in(scans_.size());
    for (std::size_t i = 0; i < scans_.size(); ++i) {
        const ScanRecord& s = scans_[i];
        in[i].pose = scanPose(i);
        in[i].fixed = keyframes_[s.keyframe].scanIndex == i;  // the keyframe's own scan
        in[i].poseVariance = s.registrationVariance;
        in[i].odometry = s.odometry;
        if (s.odometry)  // the position noise of the graph's own odometry model
            in[i].odometryVariance = registration_.odometryCovariance(s.odometry->norm(), 0)(0, 0);
    }
    return smoothScanPositions(in);
}

bool GraphSlam::odometryNeverMoved(const CPose2D& increment) {
    if (odometryMoved_)
        return false;
    if (increment.x() != 0 || increment.y() != 0 || increment.phi() != 0) {
        odometryMoved_ = true;
        return false;
    }
    // Exactly no motion since the log began: what a log recorded without odometry states
    // (zeros in CARMEN's FLASER lines, rawlog actions of zero). Read as none, the scan is
    // predicted to move as the robot last did, as in a laser-only log: a robot that stands
    // still at the start registers no motion either way.
    ++stats_.scansOfUnmovedOdometry;
    return true;
}

Prediction GraphSlam::predict(const std::optional<CPose2D>& odometryIncrement,
                              double scanInterval) {
    Prediction p;
    // Without odometry (a laser-only log) the robot is predicted to move as it last did.
    CPose2D increment = odometryIncrement.value_or(lastMotion_);
    stats_.scansWithoutOdometry += !odometryIncrement;
    // A catch-up after a stall registration saw too little of: not the last motion, but the
    // reading less what was registered, over that many scan intervals (a jump only beyond the
    // bounds for all of them).
    // Or one whose turn only the guess-free matcher registered and the reading refutes: as if
    // nothing had placed the stall's scans (bridge_refuted_stalls).
    const bool refuted =
        odometryIncrement && options_.bridgeOdometryStalls && options_.bridgeRefutedStalls &&
        odometryLag_.stallTurnRefuted(*odometryIncrement, options_.odometryJumpAngle);
    const bool bridgedByStallTests =
        odometryIncrement && options_.bridgeOdometryStalls &&
        (refuted || odometryLag_.bridges(*odometryIncrement, lastMotion_));
    // Or one as long as the stall's registered translation plus a step, whatever it turned
    // (bridge_stall_and_step).
    const bool byLength = !bridgedByStallTests && odometryIncrement &&
                          options_.bridgeOdometryStalls && options_.bridgeStallAndStep &&
                          odometryLag_.holdsStallAndStep(*odometryIncrement, lastMotion_);
    const bool bridged = bridgedByStallTests || byLength;
    // Or one after readings that fell short of the registered motion (a stall within a scan
    // interval, as at a low scan rate): the reading less what they missed.
    const bool shortfallBridged = !bridged && odometryIncrement && options_.bridgeOdometryStalls &&
                                  odometryLag_.catchesUpShortfall(*odometryIncrement, lastMotion_);
    bool catchingUp = odometryIncrement && odometryLag_.catchingUp(*odometryIncrement, lastMotion_);
    double intervals = 1;
    if (bridged) {
        increment = odometryLag_.stepSinceStall(*odometryIncrement);
        intervals += odometryLag_.repeatedScans();
        p.stallScans = odometryLag_.repeatedScans();
        p.stallScansBehind = refuted || odometryLag_.stallScansBehind(*odometryIncrement);
        p.stallUnplaced = refuted || odometryLag_.stallUnplaced();
        stats_.odometryUnplacedStallsBridged += odometryLag_.stallUnplaced();
        stats_.odometryRefutedStallsBridged += refuted && !odometryLag_.stallUnplaced();
        stats_.odometryStallsAndStepBridged += byLength;
        catchingUp = false;
        ++stats_.odometryStallsBridged;
    } else if (shortfallBridged) {
        increment = odometryLag_.stepPastShortfall(*odometryIncrement);
        catchingUp = false;
        ++stats_.odometryShortfallsBridged;
    }
    odometrySinceKeyframe_ += increment.norm();
    turnSinceKeyframe_ += std::abs(mrpt::math::wrapToPi(increment.phi()));
    // A jump is a step beyond the bounds that also departs from the last registered motion by
    // more than them: at a low scan rate, or on a fast robot, every step is long.
    // Not where the reading is in step with the one before it: the odometry did not jump, the
    // registered motion departed from it (registration that lost the robot along a corridor).
    const bool inStep = options_.jumpOnlyOutOfStep && odometryIncrement && lastReading_ &&
                        !bridged && !shortfallBridged &&
                        OdometryLag::inStep(*lastReading_, *odometryIncrement);
    if (!inStep && beyondOdometryJump(options_, increment, intervals) &&
        beyondOdometryJump(options_, (-lastMotion_) + increment, intervals)) {
        // Wheels do not teleport: predict the motion of the last scan instead (a stalled
        // odometry that catches up in one step jumps; the robot kept moving meanwhile).
        p.odometryJumped = true;
        p.readingStep = increment;
        ++stats_.odometryJumps;
        increment = lastMotion_;
    } else if (catchingUp) {
        // Within the jump bounds but still catching up after a stall (OdometryLag.h): ICP
        // starts from the last motion.
        p.odometryLagging = true;
        p.readingStep = increment;
        // Right after a stall registration placed, the reading holds the stall's registered
        // motion and this interval's own (catch_up_less_stall).
        if (options_.catchUpLessStall && odometryLag_.repeatedScans() > 0 &&
            !odometryLag_.stallUnplaced())
            p.catchUpLessStall = odometryLag_.stepSinceStall(*odometryIncrement);
        ++stats_.odometryCatchUps;
        increment = lastMotion_;
    }
    p.odometryBridged = bridged || shortfallBridged;
    // A reading right after a stall that no rule above took for a catch-up may still hold the
    // stall's motion: a robot that nearly stopped reads no more than its last motion.
    if (options_.matcherBoundedByCatchUp && odometryIncrement && !p.odometryBridged &&
        !p.odometryJumped && !p.odometryLagging && odometryLag_.repeatedScans() > 0)
        p.stallCatchUpStep = odometryLag_.stepSinceStall(*odometryIncrement);
    // A stall, not a stop: the scan changed. Also where only the wheels' count stalled and
    // the heading still reads (OdometryLag::translationStalled).
    const bool translationStalled =
        odometryIncrement &&
        odometryLag_.translationStalled(*odometryIncrement, scanInterval, lastMotion_);
    p.odometryStalled = options_.predictStallsByLastMotion && odometryIncrement &&
                        (odometryLag_.stalled() || translationStalled) &&
                        OdometryLag::scanChanged(previousPolar_, polar_);
    stats_.odometryTranslationStalls += p.odometryStalled && translationStalled;
    p.odometryPredicted = odometryIncrement && !p.odometryJumped && !p.odometryLagging;
    if (options_.missedTurnStart && p.odometryPredicted && !shortfallBridged && !bridged)
        p.pastMissedTurn = odometryLag_.pastMissedTurn(increment);
    p.odometryStep = increment;
    p.lastMotion = lastMotion_;
    p.longestRecentStep = *std::max_element(recentSteps_.begin(), recentSteps_.end());
    p.lastReading = lastReading_;
    const CPose2D predicted = current_ + increment;
    const Keyframe& last = keyframes_.back();
    p.lastKeyframe = &last;
    p.lastKeyframeReadings = &lastKeyframeReadings_;
    p.fromLastKeyframe = predicted - graph_.pose(last.id);
    p.distanceFromLastKeyframe = odometrySinceKeyframe_;
    p.turnFromLastKeyframe = turnSinceKeyframe_;
    if (options_.matcherFromRegisteredKeyframe && last.placedByOdometry) {
        const Keyframe& registered = keyframes_[registeredKeyframe_];
        p.registeredKeyframe = &registered;
        p.registeredKeyframeReadings = &registeredKeyframeReadings_;
        p.fromRegisteredKeyframe = predicted - graph_.pose(registered.id);
        // Along the estimated trajectory to the last keyframe, then by odometry.
        p.distanceFromRegisteredKeyframe =
            last.travelled - registered.travelled + odometrySinceKeyframe_;
        p.turnFromRegisteredKeyframe = last.turned - registered.turned + turnSinceKeyframe_;
    }
    if (firstActiveSubmap_ < submaps_.size()) {
        p.submap = &submaps_[firstActiveSubmap_];
        p.inSubmap = predicted - graph_.pose(p.submap->anchor());
    }
    return p;
}

bool GraphSlam::isKeyframe(const Registration& r, const CPose2D& pose) const {
    const CPose2D sinceKeyframe = pose - graph_.pose(keyframes_.back().id);
    return sinceKeyframe.norm() >= options_.keyframeDistance ||
           std::abs(mrpt::math::wrapToPi(sinceKeyframe.phi())) >= options_.keyframeAngle ||
           (r.method == RegistrationMethod::Icp && r.overlap < options_.keyframeMinOverlap);
}

void GraphSlam::processScan(const mrpt::obs::CObservation2DRangeScan::Ptr& scan,
                            const std::optional<CPose2D>& odometryIncrement,
                            const features::CObservationLaserFeatures::Ptr& storedFeatures) {
    ++stats_.scans;
    const double start = io::threadCpuSeconds();
    // This thread's back-end time (the workers' is counted by the loop closer).
    const auto backEnd = [this] {
        return stats_.loopSeconds + stats_.optimizationSeconds - stats_.offloadedSeconds;
    };
    const double backEndBefore = backEnd();
    processScanTimed(scan, odometryIncrement, storedFeatures);
    stats_.frontEndSeconds += io::threadCpuSeconds() - start - (backEnd() - backEndBefore);
}

void GraphSlam::processScanTimed(const mrpt::obs::CObservation2DRangeScan::Ptr& scan,
                                 const std::optional<CPose2D>& odometryIncrement,
                                 const features::CObservationLaserFeatures::Ptr& storedFeatures) {
    std::swap(previousPolar_, polar_);  // both keep their storage
    polar_.assign(*scan);
    // Not known for the first scan (previousStamp_ is still invalid) or an unstamped one.
    const double scanInterval =
        previousStamp_ == INVALID_TIMESTAMP || scan->timestamp == INVALID_TIMESTAMP
            ? 0.0
            : mrpt::system::timeDifference(previousStamp_, scan->timestamp);
    previousStamp_ = scan->timestamp;
    bool haveFeatures = false;
    const auto extract = [&](features::ScanFeatures& f) {
        if (haveFeatures)
            return;
        if (storedFeatures)
            f = storedFeatures->features;
        else
            extractor_->extract(*scan, f);
        haveFeatures = true;
    };
    if (keyframes_.empty()) {  // the first scan is the origin
        extract(features_);
        addKeyframe(scan, Registration(), initialPose_, storedFeatures);
        return;
    }
    // The odometry as the graph uses it: its distance scale calibrated.
    std::optional<CPose2D> odometry;
    if (odometryIncrement && !odometryNeverMoved(*odometryIncrement))
        odometry = odometryCalibration_.corrected(*odometryIncrement);
    const Prediction prediction = predict(odometry, scanInterval);
    const CPose2D sensorOnRobot(scan->sensorPose);
    const Registration r =
        registration_.registerScan(polar_, sensorOnRobot, prediction, extract, features_);
    stats_.lastMotionPredictions += r.byLastMotion;
    stats_.odometryJumpsBorneOut += r.jumpBorneOut && !r.jumpByPrior;
    stats_.odometryJumpsByPrior += r.jumpByPrior;
    stats_.odometryJumpsSidewaysByTurn += r.jumpSidewaysByTurn;
    stats_.odometryJumpsBetween += r.jumpBetween;
    stats_.odometryJumpsOverTwoReadings += r.jumpOverTwoReadings;
    stats_.icpPastMissedTurn += r.pastMissedTurn;
    stats_.icpFromTurnedStarts += r.turnedStart;
    stats_.odometryCatchUpsKept += r.catchUpReadingKept;
    stats_.odometryCatchUpsLessStall += r.catchUpLessStall;
    stats_.odometryJumpReadingsKept += r.jumpReadingKept;
    stats_.icpUnsettledRefused += r.unsettledRefused;
    stats_.icpRefutedBeyondJump += r.refutedBeyondJump;
    if (r.alongHeading) {
        stats_.alongHeadingChecks.push_back(*r.alongHeading);
        stats_.alongHeadingChecks.back().scan = stats_.scans - 1;
    }
    switch (r.method) {
        case RegistrationMethod::Icp:
            ++stats_.registeredByIcp;
            stats_.icpUnsettled += r.unsettled;
            stats_.icpSecondStarts += r.secondStart && r.unsettled;  // see SlamStatistics
            stats_.icpShortOfTurn += r.shortOfTurn;
            stats_.icpShortOfTurnReplaced += r.shortOfTurn && r.secondStart;
            stats_.icpShortOnTheSpot += r.shortOnTheSpot;
            stats_.icpShortOnTheSpotReplaced += r.shortOnTheSpot && r.secondStart;
            stats_.icpWideTurnStarts += r.secondStart && r.wideTurn;
            stats_.icpOutfittedMatcher += r.outfitsMatcher;
            stats_.icpWithoutForeground += r.withoutForeground;
            stats_.icpHeldAlongHeading += r.heldAlongHeading();
            stats_.icpHeldForFreeSpace += r.heldAlongHeading() && r.alongHeading->heldForFreeSpace;
            break;
        case RegistrationMethod::GraphMatcher:
            ++stats_.registeredByGraphMatcher;
            stats_.graphMatcherConfirmed += r.confirmedOnSubmap;
            stats_.graphMatcherFromRegisteredKeyframe += r.fromRegisteredKeyframe;
            stats_.graphMatcherWithinStallCatchUp += r.withinStallCatchUp;
            break;
        case RegistrationMethod::Odometry:
            ++stats_.registrationFailed;
            stats_.matcherRefusedForeground += r.matcherRefusedForeground;
            break;
    }
    const CPose2D pose = graph_.pose(r.reference) + r.pose;
    const CPose2D step = pose - current_;
    // What the scan shows of the odometry's scale: only ICP that settled where the scan put
    // it (not held at the odometry's position along the heading; not after a jump), and not
    // among people close by: walking along with the robot, they make ICP take back some of
    // its step (ten people in the office: the scale 0.4 % short, 0.1 % without such scans).
    // Counted also with odometry_calibration off, for the summary to say what it would do.
    if (odometry && !prediction.odometryJumped && !prediction.odometryLagging &&
        !prediction.odometryBridged && r.method == RegistrationMethod::Icp &&
        !r.heldAlongHeading() && !registration_.seesForegroundObjects(polar_)) {
        odometryCalibration_.observe(*odometryIncrement, step, r.rawCovariance);
        stats_.odometryScale = odometryCalibration_.scale();
        // Reported once there is as much evidence as the calibration waits for.
        if (odometryCalibration_.evidenceDistance() >= options_.odometryCalibration.minDistance) {
            stats_.odometryScaleEstimate = odometryCalibration_.estimate();
            stats_.odometryScaleEstimated = true;
        }
        stats_.odometryCalibrationDistance = odometryCalibration_.evidenceDistance();
    }
    doubtSinceKeyframe_ = doubtSinceKeyframe_ || r.method != RegistrationMethod::Icp;
    if (odometry)
        odometryLag_.registered(
            *odometry, step,
            !options_.bridgeUnplacedStalls || r.method != RegistrationMethod::Odometry,
            r.method == RegistrationMethod::GraphMatcher);
    lastReading_ = odometry;
    lastMotion_ = step;
    recentSteps_[stats_.scans % recentSteps_.size()] = step.norm();
    travelled_ += step.norm();
    turned_ += std::abs(mrpt::math::wrapToPi(step.phi()));
    current_ = pose;
    currentCovariance_ = r.covariance;
    // A scan of an odometry stall that nothing placed kept the last motion, tens of degrees
    // off where the robot turned: as a keyframe its readings would go into the submap and be
    // the graph matcher's reference, and the scans after it would keep its error.
    const bool deferred = options_.deferKeyframeInStall &&
                          r.method == RegistrationMethod::Odometry && prediction.odometryStalled;
    const bool keyframe = isKeyframe(r, pose);
    stats_.keyframesDeferredInStall += keyframe && deferred;
    if (keyframe && !deferred) {
        extract(features_);
        addKeyframe(scan, r, pose, storedFeatures);
    } else {
        const std::size_t kf = keyframes_.back().id;
        scans_.push_back({kf, pose - graph_.pose(kf), std::nullopt, 0});
    }
    // What places this scan apart from the graph: its registration, and the odometry since
    // the previous scan (not when it jumped: then the prediction was not the odometry's).
    ScanRecord& record = scans_.back();
    record.registrationVariance = 0.5 * (r.covariance(0, 0) + r.covariance(1, 1));
    // Nor from a stalled reading, whose zero is no measurement of the motion.
    if (odometry && !prediction.odometryJumped && !prediction.odometryLagging &&
        !prediction.odometryStalled)
        record.odometry = prediction.odometryBridged ? prediction.odometryStep : *odometry;
    // Not after a bridged step judged a jump the scan did not bear out: the reading was not
    // taken for the motion then.
    if (prediction.odometryBridged && prediction.stallScansBehind && odometry &&
        (!prediction.odometryJumped || r.jumpBorneOut))
        placeStalledScans(std::size_t(prediction.stallScans), *odometry, prediction.stallUnplaced);
}

void GraphSlam::placeStalledScans(std::size_t stallScans, const CPose2D& reading,
                                  bool turnBetween) {
    const std::size_t last = scans_.size() - 1;  // the catch-up scan
    if (last < stallScans + 1)
        return;
    const std::size_t before = last - stallScans - 1;  // its reading was the last that changed
    const CPose2D from = scanPose(before), to = scanPose(last);
    const double intervals = double(stallScans + 1);
    const CPose2D share(reading.x() / intervals, reading.y() / intervals,
                        reading.phi() / intervals);
    for (std::size_t k = 1; k <= stallScans; ++k) {
        const std::size_t i = before + k;
        ScanRecord& s = scans_[i];
        if (keyframes_[s.keyframe].scanIndex == i)
            continue;  // a keyframe stays where the graph has it
        const double a = double(k) / intervals;
        const double heading = turnBetween
                                   ? from.phi() + a * mrpt::math::wrapToPi(to.phi() - from.phi())
                                   : scanPose(i).phi();
        const CPose2D placed(from.x() + a * (to.x() - from.x()), from.y() + a * (to.y() - from.y()),
                             heading);
        s.fromKeyframe = placed - graph_.pose(s.keyframe);
        s.odometry = share;
        ++stats_.stalledScansPlaced;
    }
    scans_[last].odometry = share;
}

void GraphSlam::addKeyframe(const mrpt::obs::CObservation2DRangeScan::Ptr& scan,
                            const Registration& r, const CPose2D& pose,
                            features::CObservationLaserFeatures::Ptr stored) {
    Keyframe kf;
    kf.id = graph_.addNode(pose);
    kf.scanIndex = scans_.size();
    kf.scan = scan;
    kf.fieldOfView = std::abs(polar_.bearingStep()) * double(polar_.size());
    matching::LineMapOptions surface = options_.lineMapOptions();
    surface.maxRange = mapRange(polar_, options_);
    matching::surfacePoints(polar_, surface, kf.surface);
    kf.sensorOnRobot = CPose2D(scan->sensorPose);
    kf.travelled = travelled_;
    kf.turned = turned_;
    kf.frontEndDoubt = doubtSinceKeyframe_;
    if (!keyframes_.empty() && r.method == RegistrationMethod::Odometry) {
        kf.placedByOdometry = r.covariance;
        if (options_.submapParts)
            kf.part = kf.id;
    }
    // The last keyframe a registration placed keeps its readings while odometry places more.
    if (kf.placedByOdometry && !keyframes_.back().placedByOdometry) {
        std::swap(registeredKeyframeReadings_, lastKeyframeReadings_);
        registeredKeyframe_ = keyframes_.back().id;
    }
    lastKeyframeReadings_ = polar_;
    kf.signature = scanSignature(polar_);
    kf.features = stored;
    if (!kf.features) {
        kf.features = features::CObservationLaserFeatures::Create();
        kf.features->features = features_;
        kf.features->sensorPose = scan->sensorPose;
        kf.features->extractor = extractor_->name();
        kf.features->scanLabel = scan->sensorLabel;
        kf.features->sensorLabel = scan->sensorLabel + "_FEATURES";
        kf.features->timestamp = scan->timestamp;
    }
    keyframes_.push_back(std::move(kf));
    if (keyframes_.size() > 1)
        addKeyframeEdges(r, keyframes_.back());
    scans_.push_back({keyframes_.back().id, CPose2D(), std::nullopt, 0});
    odometrySinceKeyframe_ = turnSinceKeyframe_ = 0;
    doubtSinceKeyframe_ = false;
    ++stats_.keyframes;
    updateSubmaps(keyframes_.back());

    const std::size_t every = std::max<std::size_t>(1, options_.loopSearchEvery);
    if (options_.loopClosure && keyframes_.size() > 1 && keyframes_.back().id % every == 0) {
        const LoopClosureOutcome loops =
            loopCloser_.closeLoops(keyframes_.back().id, lastKeyframeReadings_,
                                   firstActiveKeyframe(), keyframes_, graph_, stats_);
        loopsWaiting_ += loops.accepted;
        scheduleOptimization(loops);
    }
}

void GraphSlam::scheduleOptimization(const LoopClosureOutcome& loops) {
    const std::size_t newest = keyframes_.back().id;
    // Periodic whole-graph runs wait for the graph to grow by half: each costs more the larger
    // the graph, and growing steps keep their sum within a few times the last one's cost.
    const std::size_t globalEvery =
        std::max(options_.optimizeGlobalEvery, lastGlobalOptimization_ / 2);
    if (loops.maxDistanceError > options_.optimizeGlobalDistance ||
        loops.maxAngleError > options_.optimizeGlobalAngle ||
        (loopsWaiting_ > 0 && newest >= lastGlobalOptimization_ + globalEvery)) {
        optimize(1);
    } else if (loops.maxDistanceError > options_.optimizeTriggerDistance ||
               loops.maxAngleError > options_.optimizeTriggerAngle ||
               loopsWaiting_ >= options_.optimizeEveryLoops) {
        optimize(newest > options_.optimizeWindow ? newest - options_.optimizeWindow : 1);
    }
}

void GraphSlam::addKeyframeEdges(const Registration& r, Keyframe& kf) {
    const Keyframe& previous = keyframes_[kf.id - 1];
    if (r.method != RegistrationMethod::Icp) {  // relative to the previous keyframe
        graph_.addEdge(r.reference, kf.id, r.pose, r.covariance, edgeKind(r.method));
        return;
    }
    // To the submap's anchor: what ties the keyframes of a submap rigidly together. Where the
    // map did not determine the pose (a corridor), odometry since the anchor is all there is.
    // Or to the keyframe placed by odometry alone that starts the part of the submap the scan
    // lies on: the scan's pose is known relative to that part, which may be off the anchor by
    // more than ICP's covariance says (Submap.h).
    const Submap& submap = submaps_[firstActiveSubmap_];
    const std::size_t holder =
        options_.submapParts
            ? submap.partHolding(polar_, r.pose + kf.sensorOnRobot, options_.mapConfirmDistance)
            : submap.anchor();
    const Keyframe& tiedTo = keyframes_[holder];
    // People close by can pull a registration off by more than ICP's covariance says, and least
    // squares would then spread a loop's correction evenly along the chain instead of over the
    // edges they bent (foreground_edge_sigma_factor, opt-in: GraphSlamOptions.h).
    const mrpt::math::CMatrixDouble33 foreground = registration_.foregroundEdgeVariance(polar_);
    mrpt::math::CMatrixDouble33 toHolder = registration_.edgeCovariance(
        r.rawCovariance, kf.travelled - tiedTo.travelled, kf.turned - tiedTo.turned);
    toHolder += foreground;
    stats_.keyframesSeeingForeground += foreground(0, 0) > 0;
    graph_.addEdge(tiedTo.id, kf.id,
                   holder == r.reference ? r.pose : graph_.pose(kf.id) - graph_.pose(tiedTo.id),
                   toHolder, EdgeKind::Registration);
    // (Tied to an anchor that lies in a later part, the keyframe counts in none: taken into the
    // anchor's part, fr079 at a third of its scans came out at 0.095 m instead of 0.062 m.)
    if (holder != r.reference) {
        kf.part = holder;
        ++stats_.tiedToLaterPart;
    }
    // To the previous keyframe: in those directions, odometry over one keyframe's motion is
    // far better than since the anchor, and keeps neighbours together when loops pull. Across
    // parts their relative pose is as uncertain as the odometry that placed each part's start.
    // (Left out there, fr079 at a third of its scans broke: 0.063 -> 0.874 m.)
    if (previous.id == tiedTo.id)
        return;
    mrpt::math::CMatrixDouble33 covariance = r.covariance + foreground;
    if (previous.part != kf.part)
        for (const std::size_t start : {previous.part, kf.part})
            if (start != Keyframe::kNoPart)
                covariance += *keyframes_[start].placedByOdometry;
    graph_.addEdge(previous.id, kf.id, graph_.pose(kf.id) - graph_.pose(previous.id), covariance,
                   EdgeKind::Registration);
}

void GraphSlam::updateSubmaps(const Keyframe& kf) {
    const std::size_t perSubmap = std::max<std::size_t>(2, options_.submapKeyframes);
    if (submaps_.empty()) {
        submaps_.emplace_back(kf.id, options_.lineMapOptions());
        submaps_.back().insert(kf, CPose2D());
        stats_.submaps = 1;
        return;
    }
    for (std::size_t s = firstActiveSubmap_; s < submaps_.size(); ++s)
        submaps_[s].insert(kf, graph_.pose(kf.id) - graph_.pose(submaps_[s].anchor()));
    if (submaps_[firstActiveSubmap_].keyframes().size() >= perSubmap &&
        firstActiveSubmap_ + 1 < submaps_.size()) {
        spareLineMap_ = submaps_[firstActiveSubmap_].finish();
        ++firstActiveSubmap_;
        // Keyframes older than every active submap are never inserted into one again.
        for (std::size_t id = submaps_[firstActiveSubmap_ - 1].anchor(); id < firstActiveKeyframe();
             ++id)
            std::vector<matching::SurfacePoint>().swap(keyframes_[id].surface);
    }
    if (submaps_.back().keyframes().size() >= perSubmap / 2) {
        if (spareLineMap_) {
            submaps_.emplace_back(kf.id, std::move(*spareLineMap_));
            spareLineMap_.reset();
        } else {
            submaps_.emplace_back(kf.id, options_.lineMapOptions());
        }
        submaps_.back().insert(kf, CPose2D());
        stats_.submaps = submaps_.size();
    }
}

std::size_t GraphSlam::firstActiveKeyframe() const {
    return submaps_[firstActiveSubmap_].anchor();
}

void GraphSlam::optimize(std::size_t firstFree) {
    if (firstFree <= 1)
        lastGlobalOptimization_ = keyframes_.back().id;
    for (int round = 0;; ++round) {
        const OptimizationResult r = graph_.optimize(options_.optimizeMaxIterations, firstFree);
        ++stats_.optimizations;
        stats_.optimizationSeconds += r.seconds;
        // A loop the optimised graph still cannot explain was wrong: withdraw it, once
        // at a time (the worst first: one false loop strains the true ones around it too).
        if (round >= 2 || !loopCloser_.withdrawWorstOutlier(graph_, stats_))
            break;
    }
    loopsWaiting_ = 0;
    rebuildActiveSubmaps();
    current_ = scanPose(scans_.size() - 1);
}

void GraphSlam::rebuildActiveSubmaps() {
    for (std::size_t s = firstActiveSubmap_; s < submaps_.size(); ++s) {
        Submap& submap = submaps_[s];
        const std::vector<std::size_t> members = submap.keyframes();
        const CPose2D anchor = graph_.pose(submap.anchor());
        submap.clear();
        for (std::size_t id : members)
            submap.insert(keyframes_[id], graph_.pose(id) - anchor);
    }
}

void GraphSlam::finish() {
    loopCloser_.finish(keyframes_, graph_, stats_);
    if (stats_.loopsAccepted > 0)
        optimize(1);
}

}  // namespace toposlam::mapping
