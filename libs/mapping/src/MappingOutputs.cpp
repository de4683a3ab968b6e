#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/serialization/CArchive.h>
#include <toposlam/io/AtomicFile.h>
#include <toposlam/io/GridMapIO.h>
#include <toposlam/io/JsonFile.h>
#include <toposlam/io/LaserPosition.h>
#include <toposlam/io/TextFile.h>
#include <toposlam/mapping/MappingOutputs.h>

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <future>
#include <stdexcept>
#include <utility>
#include <vector>

namespace toposlam::mapping {

namespace {
std::string line(const char* format, ...) __attribute__((format(printf, 1, 2)));
std::string line(const char* format, ...) {
    va_list args, again;
    va_start(args, format);
    va_copy(again, args);
    // Measured first: the registration line runs past any fixed buffer (it was cut at 512).
    const int length = std::vsnprintf(nullptr, 0, format, args);
    va_end(args);
    std::string out(static_cast<std::size_t>(std::max(length, 0)) + 1, '\0');
    std::vsnprintf(out.data(), out.size(), format, again);
    va_end(again);
    out.back() = '\n';  // in place of the terminating zero
    return out;
}

// "1 odometry jump", "2 odometry jumps".
std::string counted(std::size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

// A count of the summary's registration breakdown, and the counts it splits into.
struct Count {
    Count(std::size_t n, const char* phrase, std::vector<Count> parts = {})
        : Count(n, phrase, phrase, std::move(parts)) {}
    Count(std::size_t n, const char* one, const char* many, std::vector<Count> parts = {})
        : n(n), one(one), many(many), parts(std::move(parts)) {}
    std::size_t n;
    const char *one, *many;  // the phrase after 1, after any other number
    std::vector<Count> parts;
};

// "3 unsettled (1 of them from a second start); 2 without foreground objects": the counts that
// are not 0, each with its parts that are not 0 in parentheses.
std::string nonZero(const std::vector<Count>& counts, const char* separator = "; ") {
    std::string out;
    for (const Count& c : counts) {
        if (c.n == 0)
            continue;
        out += (out.empty() ? "" : separator) + counted(c.n, c.one, c.many);
        const std::string parts = nonZero(c.parts, ", ");
        if (!parts.empty())
            out += " (" + parts + ")";
    }
    return out;
}

double percent(std::size_t part, std::size_t whole) {
    return whole > 0 ? 100.0 * double(part) / double(whole) : 0.0;
}

/// An odometry whose distances are off by this much (percent) stretches or shrinks a long
/// corridor visibly (a 50 m corridor by a metre): the summary suggests odometry_calibration.
constexpr double kSuggestCalibrationPercent = 2.0;

// How the odometry's distances were taken (odometry_calibration).
std::string odometryLine(const MappingResult& r, const SlamStatistics& st) {
    // How long the odometry reads by the scale the well-registered scans show (percent).
    const auto longBy = [](double scale) { return 100.0 * (1.0 / scale - 1.0); };
    if (!r.odometryCalibration) {
        if (!st.odometryScaleEstimated)  // too little evidence to tell (or none)
            return line("odometry: distances as read (odometry_calibration off)");
        // Where the laser fixes nothing along a corridor, that error stays in the map.
        const double off = longBy(st.odometryScaleEstimate);
        return line(
            "odometry: distances as read (odometry_calibration off); over %.0f m of "
            "well-registered motion it read %.1f %% %s%s",
            st.odometryCalibrationDistance, std::abs(off), off >= 0 ? "long" : "short",
            std::abs(off) >= kSuggestCalibrationPercent
                ? ": in long corridors odometry_calibration = true keeps that out of the map"
                : "");
    }
    if (!st.odometryScaleEstimated) {
        return line(
            "odometry: distances as read (%.1f m of well-registered motion, fewer than "
            "odometry_calibration_min_distance)",
            st.odometryCalibrationDistance);
    }
    return line(
        "odometry: distances scaled by %.4f, learnt from %.0f m of well-registered motion (the "
        "odometry reads %.1f %% %s)",
        st.odometryScale, st.odometryCalibrationDistance, std::abs(longBy(st.odometryScale)),
        st.odometryScale < 1.0 ? "long" : "short");
}

/// The stamp of scan `scan` in trajectory.txt (0 if there is none).
double stampOf(const MappingResult& r, std::size_t scan) {
    return scan < r.trajectory.size() ? r.trajectory[scan].stamp : 0.0;
}
}  // namespace

bool mostlyUnregistered(const MappingResult& result) {
    return result.statistics && result.statistics->registeredShare() < 0.5;
}

bool openLoopAtEnd(const MappingResult& result) {
    return result.statistics && result.statistics->loopsOpenAtEnd > 0;
}

bool weakFrontEnd(const MappingResult& result) {
    constexpr double kMinIcpShare = 0.9;
    const auto& st = result.statistics;
    return st && st->scans > 1 && !mostlyUnregistered(result) &&
           double(st->registeredByIcp) < kMinIcpShare * double(st->scans - 1);
}

std::optional<double> realTimeFactor(const MappingResult& r) {
    // Stamps less than a millisecond apart on average are none: the fastest scanners take
    // 20 ms a scan; a log whose stamps were lost states 0 for all (the reader then spaces
    // them 1 us apart).
    constexpr double kMinSecondsPerScan = 1e-3;
    if (!(r.wallSeconds > 0) || r.scans < 2 ||
        r.logDuration < kMinSecondsPerScan * double(r.scans - 1))
        return std::nullopt;
    return r.logDuration / r.wallSeconds;
}

std::string formatSummary(const MappingResult& r) {
    std::string s;
    s += line("engine: %s", r.engine.c_str());
    if (const auto factor = realTimeFactor(r)) {
        s += line(
            "scans: %zu, log duration %.1f s, mapped in %.2f s wall, %.2f s CPU (%.1fx real "
            "time)",
            r.scans, r.logDuration, r.wallSeconds, r.cpuSeconds, *factor);
    } else {
        s += line(
            "scans: %zu, log duration %.3f s (the log's stamps do not tell its time), mapped "
            "in %.2f s wall, %.2f s CPU",
            r.scans, r.logDuration, r.wallSeconds, r.cpuSeconds);
    }
    // Kuemmerle et al.'s relations are the laser's: say which poses trajectory.txt gives.
    if (io::laserOffCentre(r.laserPosition)) {
        s += line(
            "laser: %s; trajectory.txt gives the robot's poses (toposlam-eval-slam "
            "--laser-frame-of <log> scores the laser's)",
            io::describeLaserPosition(r.laserPosition).c_str());
    }
    if (!r.otherLaserScans.empty()) {
        const auto named = [](const std::string& label) {
            return label.empty() ? std::string("(no label)") : label;
        };
        std::string others;
        for (const auto& [label, count] : r.otherLaserScans)
            others += (others.empty() ? "" : ", ") + std::to_string(count) + " of " + named(label);
        s += line(
            "laser: %s; scans of the log's other lasers left out: %s ([Slam] scan_label "
            "chooses the laser)",
            named(r.laserLabel).c_str(), others.c_str());
    }
    if (const auto& st = r.statistics) {
        const std::size_t n = st->scans > 1 ? st->scans - 1 : 0;
        const std::string parts =
            st->tiedToLaterPart == 0
                ? std::string()
                : " (" + std::to_string(st->tiedToLaterPart) +
                      " of them tied to the part of their submap after a keyframe placed by "
                      "odometry alone)";
        const std::string deferred =
            st->keyframesDeferredInStall == 0
                ? std::string()
                : " (" + std::to_string(st->keyframesDeferredInStall) +
                      " more deferred: scans of an odometry stall that nothing placed)";
        s +=
            line("keyframes: %zu%s in %s%s; the scans between them placed by %s", st->keyframes,
                 deferred.c_str(), counted(st->submaps, "submap", "submaps").c_str(), parts.c_str(),
                 r.smoothedScans ? "registration and odometry together"
                                 : "registration alone (smooth_scans off)");
        if (st->keyframesSeeingForeground > 0)
            s += line(
                "keyframes that saw people or other objects close by: %zu (their "
                "registration edges less certain, foreground_edge_sigma_factor)",
                st->keyframesSeeingForeground);
        // The three outcomes on one line; below it, one line each for ICP, the graph matcher,
        // the failures and the odometry's steps, with the rarer cases that occurred in this log
        // (summary.json's "registration" has every count, zeros too).
        s += line(
            "registration: %zu by ICP (%.1f %%), %zu by the graph matcher (%.1f %%), %zu "
            "failed (%.1f %%, odometry kept)",
            st->registeredByIcp, percent(st->registeredByIcp, n), st->registeredByGraphMatcher,
            percent(st->registeredByGraphMatcher, n), st->registrationFailed,
            percent(st->registrationFailed, n));
        const std::vector<Count> byIcp = {
            {st->icpUnsettled, "unsettled", {{st->icpSecondStarts, "of them from a second start"}}},
            {st->icpUnsettledRefused,
             "answer refused",
             "answers refused",
             {{st->icpRefutedBeyondJump,
               "of them where ICP ended beyond a jump on clearly more of the scan"},
              {st->icpUnsettledRefused -
                   std::min(st->icpRefutedBeyondJump, st->icpUnsettledRefused),
               "beyond the odometry's noise"}}},
            {st->icpWithoutForeground, "without foreground objects"},
            {st->icpHeldAlongHeading,
             "held at the odometry's position along the heading",
             {{st->icpHeldForFreeSpace, "of them where ICP's pose saw through the submap"}}},
            {st->icpPastMissedTurn,
             "from the reading less the turn short readings before it missed"},
            {st->icpFromTurnedStarts,
             "from the reading turned farther where nothing else placed the scan"},
            {st->icpShortOfTurn,
             "short of the last motion's turn on little of the scan",
             {{st->icpShortOfTurnReplaced, "of them replaced from a second start"}}},
            {st->icpShortOnTheSpot,
             "from a reading of a turn on the spot on little of the scan",
             {{st->icpShortOnTheSpotReplaced, "of them replaced from a second start"}}},
            {st->icpWideTurnStarts, "from a start turned farther where no nearer one settled"},
            {st->icpOutfittedMatcher,
             "from a turned start that fitted clearly more of the scan "
             "than the graph matcher's answer after ICP failed"}};
        const std::vector<Count> byMatcher = {
            {st->graphMatcherConfirmed, "beyond a jump, confirmed on the submap"},
            {st->graphMatcherFromRegisteredKeyframe,
             "against the last keyframe a registration placed, where odometry alone placed the "
             "last"},
            {st->graphMatcherWithinStallCatchUp,
             "beyond a jump from the reading after a stall, within the bounds of the catch-up it "
             "may hold"}};
        const std::vector<Count> failed = {
            {st->matcherRefusedForeground,
             "with a graph-matcher answer only foreground objects bore out"}};
        const std::vector<Count> odometry = {
            {st->odometryJumps,
             "odometry jump",
             "odometry jumps",
             {{st->odometryJumpsBorneOut, "of them borne out by the scan: a fast turn"},
              {st->odometryJumpsByPrior,
               "taken as read where the scan fitted them and the last motion alike"},
              {st->odometryJumpsSidewaysByTurn,
               "of those two corrected sideways by the turn of the step's chord"},
              {st->odometryJumpsBetween,
               "placed by ICP between the odometry's step and the last motion"},
              {st->odometryJumpsOverTwoReadings,
               "placed by ICP over the last two readings together (the first fell short)"},
              {st->odometryJumpReadingsKept, "placed by nothing and kept as read"}}},
            {st->odometryStallsBridged,
             "odometry stall bridged",
             "odometry stalls bridged",
             {{st->odometryUnplacedStallsBridged, "of them stalls nothing had placed"},
              {st->odometryRefutedStallsBridged,
               "whose turn the graph matcher alone registered and the reading after refuted"},
              {st->odometryStallsAndStepBridged,
               "read as long as the registered stall plus a step, whatever they turned"},
              {st->stalledScansPlaced, "of their scans placed between"}}},
            {st->odometryTranslationStalls, "stall of the distance alone",
             "stalls of the distance alone"},
            {st->odometryShortfallsBridged, "catch-up after short readings bridged",
             "catch-ups after short readings bridged"},
            {st->odometryCatchUps,
             "odometry step catching up after a stall",
             "odometry steps catching up after a stall",
             {{st->odometryCatchUpsKept,
               "placed by ICP from the reading where nothing from the last motion placed them",
               {{st->odometryCatchUpsLessStall,
                 "of those from the reading less the stall's registered motion"}}}}},
            {st->lastMotionPredictions, "predicted by the last motion instead of the odometry"}};
        for (const auto& [kind, counts] :
             {std::pair{"ICP", &byIcp}, std::pair{"graph matcher", &byMatcher},
              std::pair{"failed", &failed}, std::pair{"odometry steps", &odometry}}) {
            const std::string listed = nonZero(*counts);
            if (!listed.empty())
                s += line("  %s: %s", kind, listed.c_str());
        }
        if (st->scansWithoutOdometry > 0)
            s += line(
                "odometry: none for %zu of %zu scans (%zu of them before the odometry first "
                "read any motion: a log that never does has none), each of them predicted by "
                "the robot's last registered motion",
                st->scansWithoutOdometry, n, st->scansOfUnmovedOdometry);
        if (st->scansWithoutOdometry < n)  // a laser-only log has nothing to calibrate
            s += odometryLine(r, *st);
        // A rule that is off says so, instead of a count that could not be anything but 0.
        const std::string guessFree =
            r.guessFreeSearch ? std::to_string(st->globalConfirmed) + " of them guess-free"
                              : "guess-free search off";
        const std::string contested = r.contestedLoops ? std::to_string(st->loopsContested) +
                                                             " beyond the gate on agreeing evidence"
                                                       : "acceptance beyond the gate off";
        const std::string swungIn =
            r.leverArmGate ? std::to_string(st->loopsSwungIn) + " let in by the gate's lever arm"
                           : "the gate's lever arm off";
        s += line(
            "loop closures: %s verified, %zu accepted (%s, %s, %s), %zu not matched, %zu "
            "rejected by the consistency checks, %zu unconfirmed, %zu withdrawn after "
            "optimisation",
            counted(st->loopCandidates, "candidate", "candidates").c_str(), st->loopsAccepted,
            guessFree.c_str(), contested.c_str(), swungIn.c_str(), st->loopsUnmatched,
            st->loopsGateRejected, st->loopsUnconfirmed, st->loopsWithdrawn);
        s += line(
            "CPU time: front end %.2f s, loop search %.2f s (%.2f s of it on worker threads), "
            "optimisation %.2f s (%s)",
            st->frontEndSeconds, st->loopSeconds, st->offloadedSeconds, st->optimizationSeconds,
            counted(st->optimizations, "run", "runs").c_str());
    }
    s += line("grid: %u x %u cells of %.2f m, x [%.2f, %.2f] y [%.2f, %.2f] m", r.grid.getSizeX(),
              r.grid.getSizeY(), r.grid.getResolution(), r.grid.getXMin(), r.grid.getXMax(),
              r.grid.getYMin(), r.grid.getYMax());
    if (r.wallAlignment != 0)
        s += line(
            "map turned by %.2f deg to line the walls up with the axes (wall direction "
            "strength %.2f)",
            r.wallAlignment * 180.0 / M_PI, r.wallDirectionStrength);
    if (mostlyUnregistered(r))
        s += line(
            "WARNING: only %.1f %% of the scans could be registered: the trajectory is "
            "mostly raw odometry and the map is not reliable",
            100.0 * r.statistics->registeredShare());
    if (openLoopAtEnd(r)) {
        const SlamStatistics::OpenLoop& o = r.statistics->largestOpenLoop;
        s += line(
            "WARNING: the log ends with %s that would move the map: the largest, from the scan "
            "at t = %.3f s back to the one at t = %.3f s (trajectory.txt stamps), is %.2f m and "
            "%.1f deg off it. Either the map is open there or the scans match a look-alike "
            "place; without a second, agreeing match nothing tells which, so the loop was left "
            "out. A few more metres of the log past that place would settle it",
            counted(r.statistics->loopsOpenAtEnd, "unconfirmed loop", "unconfirmed loops").c_str(),
            stampOf(r, o.currentScan), stampOf(r, o.olderScan), o.distance, o.angle * 180.0 / M_PI);
    }
    if (weakFrontEnd(r))
        s += line(
            "WARNING: only %.1f %% of the scans were registered by ICP against the local map: "
            "the front end struggled (a narrow field of view, bare walls, crowds) and the map "
            "may be distorted; compare the trajectory with the odometry (toposlam-eval-slam "
            "--odometry-of)",
            percent(r.statistics->registeredByIcp, r.statistics->scans - 1));
    return s;
}

nlohmann::json summaryJson(const MappingResult& r) {
    nlohmann::json j = {
        {"engine", r.engine},
        {"scans", r.scans},
        {"log_duration_s", r.logDuration},
        {"wall_s", r.wallSeconds},
        {"cpu_s", r.cpuSeconds},
        {"real_time_factor", realTimeFactor(r) ? nlohmann::json(*realTimeFactor(r)) : nullptr},
        {"laser",
         {{"label", r.laserLabel},
          {"other_lasers", r.otherLaserScans},
          {"position_m", {r.laserPosition.x, r.laserPosition.y}}}},
        {"wall_alignment_deg", r.wallAlignment * 180.0 / M_PI}};
    if (const auto& st = r.statistics) {
        j["keyframes"] = st->keyframes;
        j["submaps"] = st->submaps;
        j["keyframes_tied_to_later_part"] = st->tiedToLaterPart;
        j["keyframes_deferred_in_stall"] = st->keyframesDeferredInStall;
        j["keyframes_seeing_foreground"] = st->keyframesSeeingForeground;
        j["smoothed_scans"] = r.smoothedScans;
        j["registration"] = {
            {"icp", st->registeredByIcp},
            {"icp_unsettled", st->icpUnsettled},
            {"icp_second_start", st->icpSecondStarts},
            {"icp_unsettled_refused", st->icpUnsettledRefused},
            {"icp_refuted_beyond_jump", st->icpRefutedBeyondJump},
            {"icp_without_foreground", st->icpWithoutForeground},
            {"icp_held_along_heading", st->icpHeldAlongHeading},
            {"icp_held_for_free_space", st->icpHeldForFreeSpace},
            {"icp_past_missed_turn", st->icpPastMissedTurn},
            {"icp_from_turned_starts", st->icpFromTurnedStarts},
            {"icp_short_of_turn", st->icpShortOfTurn},
            {"icp_short_of_turn_replaced", st->icpShortOfTurnReplaced},
            {"icp_short_on_the_spot", st->icpShortOnTheSpot},
            {"icp_short_on_the_spot_replaced", st->icpShortOnTheSpotReplaced},
            {"icp_wide_turn_starts", st->icpWideTurnStarts},
            {"icp_outfitted_matcher", st->icpOutfittedMatcher},
            {"graph_matcher", st->registeredByGraphMatcher},
            {"graph_matcher_confirmed", st->graphMatcherConfirmed},
            {"graph_matcher_from_registered_keyframe", st->graphMatcherFromRegisteredKeyframe},
            {"graph_matcher_within_stall_catch_up", st->graphMatcherWithinStallCatchUp},
            {"last_motion_predictions", st->lastMotionPredictions},
            {"failed", st->registrationFailed},
            {"failed_matcher_refused_foreground", st->matcherRefusedForeground},
            {"odometry_jumps", st->odometryJumps},
            {"odometry_jumps_borne_out", st->odometryJumpsBorneOut},
            {"odometry_jumps_by_prior", st->odometryJumpsByPrior},
            {"odometry_jumps_sideways_by_turn", st->odometryJumpsSidewaysByTurn},
            {"odometry_jumps_between", st->odometryJumpsBetween},
            {"odometry_jumps_over_two_readings", st->odometryJumpsOverTwoReadings},
            {"odometry_jump_readings_kept", st->odometryJumpReadingsKept},
            {"odometry_catch_ups", st->odometryCatchUps},
            {"odometry_catch_ups_kept", st->odometryCatchUpsKept},
            {"odometry_catch_ups_less_stall", st->odometryCatchUpsLessStall},
            {"odometry_stalls_bridged", st->odometryStallsBridged},
            {"odometry_unplaced_stalls_bridged", st->odometryUnplacedStallsBridged},
            {"odometry_refuted_stalls_bridged", st->odometryRefutedStallsBridged},
            {"odometry_stalls_and_step_bridged", st->odometryStallsAndStepBridged},
            {"odometry_shortfalls_bridged", st->odometryShortfallsBridged},
            {"odometry_translation_stalls", st->odometryTranslationStalls},
            {"stalled_scans_placed", st->stalledScansPlaced},
            {"registered_share", st->registeredShare()}};
        // Where ICP and the odometry disagreed along the heading, and what the scan said
        // (along_heading_check): the stamp is the scan's, as in trajectory.txt.
        nlohmann::json checks = nlohmann::json::array();
        for (const AlongHeadingCheck& c : st->alongHeadingChecks) {
            checks.push_back({{"scan", c.scan},
                              {"stamp", stampOf(r, c.scan)},
                              {"correction_m", c.correction},
                              {"readings", c.readings},
                              {"on_map_at_icp", c.onMapAtIcp},
                              {"on_map_at_odometry", c.onMapAtOdometry},
                              {"seen_through_at_icp", c.seenThroughAtIcp},
                              {"seen_through_at_odometry", c.seenThroughAtOdometry},
                              {"held", c.held},
                              {"held_for_free_space", c.heldForFreeSpace}});
        }
        j["registration"]["along_heading_checks"] = std::move(checks);
        j["odometry"] = {{"scans_without", st->scansWithoutOdometry},
                         {"scans_unmoved_since_start", st->scansOfUnmovedOdometry},
                         {"calibration", r.odometryCalibration},
                         {"distance_scale", st->odometryScale},
                         {"estimated_scale", st->odometryScaleEstimate},
                         {"scale_estimated", st->odometryScaleEstimated},
                         {"calibration_distance_m", st->odometryCalibrationDistance}};
        j["loops"] = {{"candidates", st->loopCandidates},
                      {"accepted", st->loopsAccepted},
                      {"guess_free_accepted", st->globalConfirmed},
                      {"contested_accepted", st->loopsContested},
                      {"guess_free_search", r.guessFreeSearch},
                      {"contested_rule", r.contestedLoops},
                      {"lever_arm_accepted", st->loopsSwungIn},
                      {"lever_arm_gate", r.leverArmGate},
                      {"unmatched", st->loopsUnmatched},
                      {"rejected", st->loopsGateRejected},
                      {"withdrawn", st->loopsWithdrawn},
                      {"unconfirmed", st->loopsUnconfirmed},
                      {"open_at_end", st->loopsOpenAtEnd}};
        if (openLoopAtEnd(r)) {
            const SlamStatistics::OpenLoop& o = st->largestOpenLoop;
            j["loops"]["largest_open_at_end"] = {{"from_stamp", stampOf(r, o.currentScan)},
                                                 {"to_stamp", stampOf(r, o.olderScan)},
                                                 {"distance_m", o.distance},
                                                 {"angle_deg", o.angle * 180.0 / M_PI}};
        }
        j["cpu_by_stage_s"] = {{"front_end", st->frontEndSeconds},
                               {"loop_search", st->loopSeconds},
                               {"loop_search_on_workers", st->offloadedSeconds},
                               {"optimization", st->optimizationSeconds}};
        j["optimizations"] = st->optimizations;
        j["mostly_unregistered"] = mostlyUnregistered(r);
        j["weak_front_end"] = weakFrontEnd(r);
        j["open_loop_at_end"] = openLoopAtEnd(r);
    }
    return j;
}

std::vector<std::string> mappingOutputFileNames() {
    return {"trajectory.txt",  "map.gridmap.gz",      "map.png",     "map.yaml",    "map.pgm",
            "keyframes.graph", "keyframes.simplemap", "summary.txt", "summary.json"};
}

std::vector<std::string> saveMappingOutputs(const MappingResult& result,
                                            const std::string& directory) {
    namespace fs = std::filesystem;
    const fs::path out(directory);
    fs::create_directories(out);
    std::vector<std::string> files;
    const auto path = [&](const char* name) {
        files.push_back((out / name).string());
        return files.back();
    };
    const std::string trajectoryFile = path("trajectory.txt"), gridFile = path("map.gridmap.gz"),
                      imageFile = path("map.png");
    files.push_back((out / "map.yaml").string());  // with map.png: the ROS map_server pair
    files.push_back((out / "map.pgm").string());
    const std::string graphFile = result.graph ? path("keyframes.graph") : "";
    const std::string keyframesFile = !result.keyframes.empty() ? path("keyframes.simplemap") : "";
    // All the files or none: a folder never holds one run's map beside another's trajectory.
    io::OutputGroup outputs;
    // The keyframe outputs (compressing the simplemap is the slowest write) go on a second
    // thread while this one writes the grid files: a shorter run on a machine with two cores.
    std::future<void> keyframeOutputs = std::async(std::launch::async, [&] {
        const auto inGroup = outputs.joinFromThisThread();
        if (result.graph)
            result.graph->save(graphFile);
        if (!result.keyframes.empty()) {
            io::writeFileAtomically(keyframesFile, [&](const std::string& tmp) {
                mrpt::io::CFileGZOutputStream f(tmp);
                mrpt::serialization::archiveFrom(f) << result.keyframes;
            });
        }
    });
    io::saveTrajectory(result.trajectory, trajectoryFile);
    io::saveGridMap(result.grid, gridFile);
    io::saveGridMap(result.grid, imageFile);
    keyframeOutputs.get();  // rethrows its error, if any
    io::saveTextFile(formatSummary(result), path("summary.txt"));
    io::saveJsonFile(summaryJson(result), path("summary.json"));
    outputs.commit();
    return files;
}

}  // namespace toposlam::mapping
