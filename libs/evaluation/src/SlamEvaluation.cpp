#include <toposlam/evaluation/SlamEvaluation.h>
#include <toposlam/evaluation/TrajectoryPlot.h>
#include <toposlam/io/JsonFile.h>
#include <toposlam/io/TextFile.h>

#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <sstream>
#include <stdexcept>

namespace toposlam::evaluation {

namespace {

/// Fills one bin of a breakdown (TurnErrors, SeparationErrors): how many of the relations it
/// holds (`inBin(relation index)`) and the statistics of the matched ones among them.
template <class Bin, class InBin>
void summarizeBin(Bin& bin, std::size_t relationCount, const std::vector<RelationError>& errors,
                  const InBin& inBin) {
    bin.totalRelations = 0;
    for (std::size_t r = 0; r < relationCount; ++r)
        bin.totalRelations += inBin(r) ? 1 : 0;
    std::vector<double> translation, rotation;
    for (const RelationError& e : errors) {
        if (!inBin(e.relation))
            continue;
        translation.push_back(e.translation);
        rotation.push_back(e.rotationDeg);
    }
    bin.translation = summarizeErrors(translation);
    bin.rotation = summarizeErrors(rotation);
}

}  // namespace

MethodEvaluation evaluateMethod(const std::string& name, const std::string& source,
                                const io::Trajectory2D& estimate, const PoseRelations& relations,
                                const io::Trajectory2D* groundTruth, double stampTolerance,
                                const std::vector<double>* separations) {
    MethodEvaluation m;
    m.name = name;
    m.source = source;
    m.poses = estimate.size();
    m.relative = evaluateRelativePoseError(estimate, relations, {stampTolerance});
    if (groundTruth) {
        m.absolute = evaluateAbsoluteTrajectoryError(estimate, *groundTruth, stampTolerance);
    }
    for (std::size_t b = 0; b + 1 < std::size(kTurnBinEdgesDeg); ++b) {
        TurnErrors bin;
        bin.minTurnDeg = kTurnBinEdgesDeg[b];
        bin.maxTurnDeg = kTurnBinEdgesDeg[b + 1];
        const bool last = b + 2 == std::size(kTurnBinEdgesDeg);
        summarizeBin(bin, relations.size(), m.relative.errors, [&](std::size_t r) {
            const double turn =
                std::abs(mrpt::math::wrapToPi(relations[r].motion.phi)) * 180.0 / M_PI;
            return turn >= bin.minTurnDeg && (turn < bin.maxTurnDeg || last);
        });
        m.byTurn.push_back(bin);
    }
    m.bestFrame = fitFrameOffset(estimate, relations, m.relative);
    m.alongTrack = alongTrackScale(relations, m.relative);
    if (separations) {
        if (separations->size() != relations.size()) {
            throw std::invalid_argument("evaluateMethod: one separation per relation expected");
        }
        std::vector<double> scales = *separations;
        std::sort(scales.begin(), scales.end());
        scales.erase(std::unique(scales.begin(), scales.end()), scales.end());
        for (const double scale : scales) {
            SeparationErrors s;
            s.separation = scale;
            summarizeBin(s, relations.size(), m.relative.errors,
                         [&](std::size_t r) { return (*separations)[r] == scale; });
            m.bySeparation.push_back(s);
        }
    }
    return m;
}

// ---- table --------------------------------------------------------------------------------

namespace {

/// A table of the translational error per bin of a breakdown (one column per bin of the first
/// method, headed `label(bin)` and its relation count; one row per method), after `title`;
/// nothing when there are no bins.
template <class Bin, class Label>
void appendBreakdownTable(std::ostringstream& out, const std::string& title,
                          const std::vector<MethodEvaluation>& methods,
                          std::vector<Bin> MethodEvaluation::*bins, const Label& label) {
    if (methods.empty() || (methods.front().*bins).empty())
        return;
    const std::vector<Bin>& columns = methods.front().*bins;
    out << "\n" << title << "\n\n| method |";
    for (const Bin& bin : columns)
        out << " " << label(bin) << " (" << bin.totalRelations << ") |";
    out << "\n|---|";
    for (std::size_t i = 0; i < columns.size(); ++i)
        out << "---|";
    out << "\n";
    for (const MethodEvaluation& m : methods) {
        out << "| " << m.name << " |";
        for (const Bin& bin : m.*bins) {
            out << " "
                << (bin.translation.count ? formatMeanStd(bin.translation, 4) : std::string("–"))
                << " |";
        }
        out << "\n";
    }
}

// Where each method's poses sit on the robot, as the odometry of ev.mountingLog sees it.
void appendMountingTable(std::ostringstream& out, const SlamEvaluation& ev) {
    if (ev.mountingLog.empty())
        return;
    out << "\nWhere each trajectory's poses sit on the robot, from the odometry of "
        << ev.mountingLog
        << " (planar hand-eye calibration over pairs of poses that turn; robot (+) mounting = "
           "pose; x forward, y left; 0 m, 0 m, 0° = the odometry's own frame):\n\n"
           "| method | x (m) | y (m) | yaw (deg) | odometry scale | turning pairs | residual "
           "RMS (m) |\n|---|---|---|---|---|---|---|\n";
    for (const MethodEvaluation& m : ev.methods) {
        out << "| " << m.name << " | ";
        if (!m.mounting) {
            out << "– | – | – | – | too few | – |\n";
            continue;
        }
        const SensorMounting& k = *m.mounting;
        out << formatFixed(k.mounting.x, 4) << " ± " << formatFixed(k.stdX, 4) << " | "
            << formatFixed(k.mounting.y, 4) << " ± " << formatFixed(k.stdY, 4) << " | "
            << formatFixed(k.mounting.phi * 180.0 / M_PI, 2) << " | "
            << formatFixed(k.odometryScale, 4) << " | " << k.pairs << " | "
            << formatFixed(k.residualRms, 4) << " |\n";
    }
}

// Each method's along-track scale: whether its motion reads long or short.
void appendAlongTrack(std::ostringstream& out, const std::vector<MethodEvaluation>& methods) {
    out << "\nAlong the direction of travel (relations moving "
        << formatFixed(kAlongTrackMinLength, 2) << "–" << formatFixed(kAlongTrackMaxLength, 1)
        << " m within " << formatFixed(kAlongTrackMaxSeconds, 0)
        << " s; negative: the motion reads short):\n\n"
           "| method | relations | true travel (m) | along-track error (m) | scale |\n"
           "|---|---|---|---|---|\n";
    for (const MethodEvaluation& m : methods) {
        const AlongTrackScale& a = m.alongTrack;
        out << "| " << m.name << " | " << a.relations << " | ";
        if (a.relations == 0) {
            out << "– | – | – |\n";
            continue;
        }
        out << formatFixed(a.pathLength, 1) << " | " << formatFixed(a.error, 3) << " | "
            << (a.error >= 0 ? "+" : "") << formatFixed(a.percent(), 3) << " % |\n";
    }
}

// The frame along the heading that fits the relations clearly better than the poses as scored,
// for each method where there is one.
void appendFrameOffsets(std::ostringstream& out, const std::vector<MethodEvaluation>& methods) {
    bool header = false;
    for (const MethodEvaluation& m : methods) {
        const FrameOffsetFit& f = m.bestFrame;
        if (!(f.gain() >= kFrameOffsetNote * f.meanErrorAsIs && f.gain() > 0))
            continue;
        if (!header) {
            out << "\nThe frame on the robot that fits the relations best, along the heading "
                   "(score it with --frame-offset; a frame off the reference's shows as error "
                   "growing with the turn, above):\n";
            header = true;
        }
        out << "- " << m.name << ": " << formatFixed(std::abs(f.offset), 3) << " m "
            << (f.offset >= 0 ? "ahead of" : "behind") << " the poses scored, mean translational "
            << "error " << formatFixed(f.meanErrorAsIs, 4) << " -> " << formatFixed(f.meanError, 4)
            << " m\n";
    }
}
}  // namespace

std::string formatEvaluationTable(const SlamEvaluation& ev) {
    std::ostringstream out;
    out << "Reference: " << ev.referenceFile << " (" << (ev.referenceMirrored ? "mirrored, " : "");
    if (ev.referenceIsGroundTruth) {
        out << "ground-truth trajectory, " << ev.groundTruthPoses << " poses -> "
            << ev.relationCount << " relations: consecutive"
            << (ev.groundTruthRelations.baseSeparation > 0
                    ? " + path separations " +
                          formatFixed(ev.groundTruthRelations.baseSeparation, 2) + " m x 2^k"
                    : std::string())
            << ")\n";
    } else {
        out << ev.relationCount << " relations";
        if (ev.repeatedRelations > 0) {
            out << ", " << ev.repeatedRelations
                << " repeating an earlier line, scored as published";
        }
        out << ")\n";
    }
    out << "Metric: Kümmerle et al. 2009, e = δ_gt⁻¹ ⊕ δ_est, δ_est = x_t1⁻¹ ⊕ x_t2; mean ± "
           "std; stamps matched within "
        << ev.stampTolerance << " s\n";
    if (!ev.laserFrameLog.empty()) {
        out << "Scored at the laser of each scan of " << ev.laserFrameLog << " (typically "
            << formatFixed(ev.laserPosition.x, 3) << ", " << formatFixed(ev.laserPosition.y, 3)
            << " m on the robot)\n";
    }
    out << "\n";

    const bool withAte = std::any_of(ev.methods.begin(), ev.methods.end(),
                                     [](const MethodEvaluation& m) { return m.absolute; });
    out << "| method | relations matched | translational error (m) | rotational error (deg) | "
           "squared transl. (m²) | squared rot. (deg²) | max transl. (m) / rot. (deg) |";
    if (withAte)
        out << " ATE RMSE (m) | ATE max (m) |";
    out << "\n|---|---|---|---|---|---|---|" << (withAte ? "---|---|" : "") << "\n";
    for (const MethodEvaluation& m : ev.methods) {
        const RelativePoseErrorResult& r = m.relative;
        out << "| " << m.name << " | " << r.matchedRelations << " / " << r.totalRelations << " | ";
        if (r.matchedRelations == 0) {
            out << "– | – | – | – | – |";
        } else {
            out << formatMeanStd(r.translation, 4) << " | " << formatMeanStd(r.rotation, 3) << " | "
                << formatMeanStd(r.translationSquared) << " | " << formatMeanStd(r.rotationSquared)
                << " | " << formatFixed(r.translation.max, 4) << " / "
                << formatFixed(r.rotation.max, 3) << " |";
        }
        if (withAte) {
            if (m.absolute && m.absolute->matchedPoses > 0) {
                out << " " << formatFixed(m.absolute->position.rms, 4) << " | "
                    << formatFixed(m.absolute->position.max, 4) << " |";
            } else {
                out << " – | – |";
            }
        }
        out << "\n";
    }

    appendBreakdownTable(
        out,
        "Translational error (m) by the reference motion's turn |Δyaw|, mean ± std "
        "(relations); scoring a frame d m off the reference's adds up to "
        "2·d·sin(|Δyaw|/2) (compare with --frame-offset):",
        ev.methods, &MethodEvaluation::byTurn, [](const TurnErrors& t) {
            return formatFixed(t.minTurnDeg, 0) + "–" + formatFixed(t.maxTurnDeg, 0) + "°";
        });
    appendAlongTrack(out, ev.methods);
    appendFrameOffsets(out, ev.methods);
    appendBreakdownTable(
        out,
        "Translational error (m) by relation separation (travelled path), mean ± std "
        "(relations):",
        ev.methods, &MethodEvaluation::bySeparation, [](const SeparationErrors& s) {
            return s.separation == 0 ? std::string("consecutive")
                                     : formatFixed(s.separation, 2) + " m";
        });
    appendMountingTable(out, ev);
    out << formatWorstRelations(ev);
    return out.str();
}

// ---- JSON ---------------------------------------------------------------------------------

namespace {

double jsonNumber(double v) {
    return io::roundSignificant(v, 10);
}

io::Json jsonStats(const ErrorStatistics& s) {
    return {{"count", s.count},
            {"mean", jsonNumber(s.mean)},
            {"std", jsonNumber(s.std)},
            {"max", jsonNumber(s.max)},
            {"rms", jsonNumber(s.rms)}};
}

io::Json referenceJson(const SlamEvaluation& ev) {
    io::Json reference = {{"file", ev.referenceFile},
                          {"kind", ev.referenceIsGroundTruth ? "ground_truth" : "relations"},
                          {"relations", ev.relationCount},
                          {"mirrored", ev.referenceMirrored}};
    if (ev.referenceIsGroundTruth) {
        reference["ground_truth_poses"] = ev.groundTruthPoses;
        reference["relation_scheme"] = {
            {"consecutive", ev.groundTruthRelations.consecutive},
            {"base_separation_m", jsonNumber(ev.groundTruthRelations.baseSeparation)}};
    } else {
        reference["repeated_relations"] = ev.repeatedRelations;
    }
    return reference;
}

}  // namespace

io::Json evaluationJson(const MethodEvaluation& m) {
    const RelativePoseErrorResult& r = m.relative;
    io::Json out = {{"name", m.name},
                    {"source", m.source},
                    {"poses", m.poses},
                    {"relations_total", r.totalRelations},
                    {"relations_matched", r.matchedRelations},
                    {"relations_unmatched", r.unmatchedRelations()},
                    {"translation_m", jsonStats(r.translation)},
                    {"rotation_deg", jsonStats(r.rotation)},
                    {"translation_squared_m2", jsonStats(r.translationSquared)},
                    {"rotation_squared_deg2", jsonStats(r.rotationSquared)},
                    {"best_frame_offset",
                     {{"offset_m", jsonNumber(m.bestFrame.offset)},
                      {"mean_translation_m", jsonNumber(m.bestFrame.meanError)}}},
                    {"along_track",
                     {{"relations", m.alongTrack.relations},
                      {"path_m", jsonNumber(m.alongTrack.pathLength)},
                      {"error_m", jsonNumber(m.alongTrack.error)},
                      {"percent", jsonNumber(m.alongTrack.percent())}}}};
    if (m.absolute) {
        const AbsoluteTrajectoryErrorResult& a = *m.absolute;
        out["ate"] = {{"matched_poses", a.matchedPoses},
                      {"alignment",
                       {{"x", jsonNumber(a.alignment.x)},
                        {"y", jsonNumber(a.alignment.y)},
                        {"phi_rad", jsonNumber(a.alignment.phi)}}},
                      {"position_m", jsonStats(a.position)},
                      {"heading_deg", jsonStats(a.heading)}};
    }
    io::Json turns = io::Json::array();
    for (const TurnErrors& t : m.byTurn) {
        turns.push_back({{"min_turn_deg", jsonNumber(t.minTurnDeg)},
                         {"max_turn_deg", jsonNumber(t.maxTurnDeg)},
                         {"relations_total", t.totalRelations},
                         {"translation_m", jsonStats(t.translation)},
                         {"rotation_deg", jsonStats(t.rotation)}});
    }
    out["by_turn"] = turns;
    if (!m.bySeparation.empty()) {
        io::Json scales = io::Json::array();
        for (const SeparationErrors& s : m.bySeparation) {
            scales.push_back({{"separation_m", jsonNumber(s.separation)},
                              {"relations_total", s.totalRelations},
                              {"translation_m", jsonStats(s.translation)},
                              {"rotation_deg", jsonStats(s.rotation)}});
        }
        out["by_separation"] = scales;
    }
    if (m.mounting) {
        const SensorMounting& k = *m.mounting;
        out["mounting"] = {{"x", jsonNumber(k.mounting.x)},
                           {"y", jsonNumber(k.mounting.y)},
                           {"yaw_deg", jsonNumber(k.mounting.phi * 180.0 / M_PI)},
                           {"x_std", jsonNumber(k.stdX)},
                           {"y_std", jsonNumber(k.stdY)},
                           {"odometry_scale", jsonNumber(k.odometryScale)},
                           {"pairs", k.pairs},
                           {"residual_rms_m", jsonNumber(k.residualRms)}};
    }
    if (!m.worst.empty()) {
        const auto motion = [](const mrpt::math::TPose2D& p) {
            return io::Json{{"x", jsonNumber(p.x)},
                            {"y", jsonNumber(p.y)},
                            {"yaw_deg", jsonNumber(p.phi * 180.0 / M_PI)}};
        };
        io::Json worst = io::Json::array();
        for (const WorstRelation& w : m.worst) {
            worst.push_back({{"relation", w.relation},
                             {"t1", w.stamp1},
                             {"t2", w.stamp2},
                             {"reference", motion(w.reference)},
                             {"estimate", motion(w.estimate)},
                             {"translation_m", jsonNumber(w.translation)},
                             {"rotation_deg", jsonNumber(w.rotationDeg)}});
        }
        out["worst_relations"] = worst;
    }
    return out;
}

std::string formatEvaluationJson(const SlamEvaluation& ev) {
    io::Json methods = io::Json::array();
    for (const MethodEvaluation& m : ev.methods)
        methods.push_back(evaluationJson(m));
    return io::formatJson(
        {{"tool", "toposlam-eval-slam"},
         {"metric",
          "Kuemmerle et al. 2009 relation error e = inv(delta_gt) (+) delta_est, delta_est = "
          "inv(x_t1) (+) x_t2; std is the sample std (n-1)"},
         {"reference", referenceJson(ev)},
         {"stamp_tolerance_s", jsonNumber(ev.stampTolerance)},
         {"frame_offset_m", jsonNumber(ev.frameOffset)},
         {"mounting_log", ev.mountingLog},
         {"laser_frame",
          {{"log", ev.laserFrameLog},
           {"position_m", {jsonNumber(ev.laserPosition.x), jsonNumber(ev.laserPosition.y)}}}},
         {"methods", methods}});
}

void saveEvaluationJson(const SlamEvaluation& evaluation, const std::string& path) {
    io::saveTextFile(formatEvaluationJson(evaluation), path);
}

// ---- plot ---------------------------------------------------------------------------------

void saveEvaluationPlot(const SlamEvaluation& ev, const std::vector<io::Trajectory2D>& estimates,
                        const io::Trajectory2D* groundTruth, const std::string& path) {
    if (estimates.size() != ev.methods.size()) {
        throw std::invalid_argument("saveEvaluationPlot: one trajectory per method expected");
    }
    std::vector<PlottedTrajectory> plotted;
    std::size_t best = 0;
    for (std::size_t i = 0; i < estimates.size(); ++i) {
        const RelativePoseErrorResult& r = ev.methods[i].relative;
        plotted.push_back(
            {ev.methods[i].name + (r.matchedRelations
                                       ? ": " + formatFixed(r.translation.mean, 4) + " m"
                                       : std::string(": no relation matched")),
             estimates[i]});
        const RelativePoseErrorResult& b = ev.methods[best].relative;
        if (r.matchedRelations &&
            (!b.matchedRelations || r.translation.mean < b.translation.mean)) {
            best = i;
        }
    }
    if (groundTruth) {
        plotted = alignedTo(*groundTruth, std::move(plotted), ev.stampTolerance);
        plotted.insert(plotted.begin(), {"ground truth", *groundTruth});
    } else if (!estimates.empty()) {
        plotted = alignedTo(estimates[best], std::move(plotted), ev.stampTolerance);
    }
    saveTrajectoryPlot(plotted, path);
}

}  // namespace toposlam::evaluation
