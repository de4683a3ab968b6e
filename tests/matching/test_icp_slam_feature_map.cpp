// MRPT's icp-slam building TopoSLAM's feature map on the simulated office, scored against the
// office's drawn floor plan (OfficeFloorPlan, exact walls):
//  - the map's frame is icp-slam's; the rigid transform that best aligns icp-slam's path with
//    the ground-truth path (the ATE alignment, libs/evaluation) puts it in the plan's frame;
//  - a wall face of the plan "was seen" over the length that beams of the log hit (ground-truth
//    poses, within 2 cm of the face); every face longer than 1 m seen over at least 1 m must
//    have a confirmed segment within 5 cm (both ends, from the face's line) and 2 deg that
//    overlaps it;
//  - no confirmed segment may lie farther than 10 cm from the plan (walls and furniture) at
//    any point (sampled every 5 cm), so a segment across a doorway counts as off the plan.
// The numbers are printed ("feature map vs plan: ..."). Skipped without mrpt-apps.
#include <gtest/gtest.h>
#include <toposlam/evaluation/AbsoluteTrajectoryError.h>
#include <toposlam/evaluation/IcpSlamPath.h>
#include <toposlam/io/LaserLogReader.h>
#include <toposlam/io/Trajectory.h>
#include <toposlam/matching/FeatureMap.h>
#include <toposlam/simulation/OfficeFloorPlan.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>

#include "TestSupport.h"

using mrpt::math::TPoint2D;
using mrpt::poses::CPose2D;
using toposlam::matching::pointToSegmentDistance;
namespace sim = toposlam::simulation;

namespace {

struct Segment {
    TPoint2D a, b;
    double length() const { return std::hypot(b.x - a.x, b.y - a.y); }
};

/// One face of a wall piece of the plan, with the beams that hit it.
struct Face {
    Segment s;
    std::vector<char> hit;  ///< per 5 cm bin along the face
    double seenLength() const {
        return 0.05 * static_cast<double>(std::count(hit.begin(), hit.end(), 1));
    }
};

std::vector<Face> wallFaces(const sim::FloorPlan& plan) {
    std::vector<Face> faces;
    for (const sim::Box& b : plan.wallPieces()) {
        const TPoint2D c[4] = {
            {b.xMin, b.yMin}, {b.xMax, b.yMin}, {b.xMax, b.yMax}, {b.xMin, b.yMax}};
        for (int k = 0; k < 4; ++k) {
            Face f;
            f.s = {c[k], c[(k + 1) % 4]};
            f.hit.assign(static_cast<std::size_t>(std::ceil(f.s.length() / 0.05)), 0);
            faces.push_back(f);
        }
    }
    return faces;
}

/// Marks the bins of every face hit by a beam of the log (ground-truth poses, one per scan).
void markSeen(std::vector<Face>& faces, const std::string& log,
              const toposlam::io::Trajectory2D& gt) {
    toposlam::io::LaserLogReader reader(log);
    toposlam::io::LaserLogRecord r;
    for (std::size_t i = 0; reader.next(r); ++i) {
        ASSERT_LT(i, gt.size());
        const CPose2D sensor = CPose2D(gt[i].pose) + CPose2D(r.scan->sensorPose);
        for (std::size_t k = 0; k < r.scan->getScanSize(); ++k) {
            if (!r.scan->getScanRangeValidity(k))
                continue;
            const double a = r.scan->getScanAngle(k), range = r.scan->getScanRange(k);
            double x, y;
            sensor.composePoint(range * std::cos(a), range * std::sin(a), x, y);
            for (Face& f : faces) {
                if (pointToSegmentDistance({x, y}, f.s.a, f.s.b) > 0.02)
                    continue;
                const double t =
                    ((x - f.s.a.x) * (f.s.b.x - f.s.a.x) + (y - f.s.a.y) * (f.s.b.y - f.s.a.y)) /
                    f.s.length();
                const auto bin =
                    static_cast<std::size_t>(std::clamp(t / 0.05, 0.0, double(f.hit.size() - 1)));
                f.hit[bin] = 1;
            }
        }
    }
}

std::vector<Segment> readSegments(const std::string& file, const CPose2D& toWorld) {
    std::ifstream in(file);
    std::vector<Segment> out;
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#')
            continue;
        std::istringstream ss(line);
        double x0, y0, x1, y1;
        ss >> x0 >> y0 >> x1 >> y1;
        Segment s;
        toWorld.composePoint(x0, y0, s.a.x, s.a.y);
        toWorld.composePoint(x1, y1, s.b.x, s.b.y);
        out.push_back(s);
    }
    return out;
}

double lineDistance(const TPoint2D& p, const Segment& s) {
    const double len = s.length();
    return std::abs((s.b.x - s.a.x) * (p.y - s.a.y) - (s.b.y - s.a.y) * (p.x - s.a.x)) / len;
}

double angleBetween(const Segment& u, const Segment& v) {
    const double a = std::atan2(u.b.y - u.a.y, u.b.x - u.a.x),
                 b = std::atan2(v.b.y - v.a.y, v.b.x - v.a.x);
    return std::abs(std::remainder(a - b, M_PI));
}

/// Length (m) of u's projection onto v that falls within v.
double overlap(const Segment& u, const Segment& v) {
    const double len = v.length();
    const auto along = [&](const TPoint2D& p) {
        return ((p.x - v.a.x) * (v.b.x - v.a.x) + (p.y - v.a.y) * (v.b.y - v.a.y)) / len;
    };
    const double t0 = std::min(along(u.a), along(u.b)), t1 = std::max(along(u.a), along(u.b));
    return std::max(0.0, std::min(t1, len) - std::max(t0, 0.0));
}

}  // namespace

TEST(IcpSlamFeatureMap, OfficeFeatureMapMatchesTheDrawnPlan) {
    if (toposlam::test::runCommand("command -v icp-slam").exitCode != 0)
        GTEST_SKIP() << "icp-slam (mrpt-apps) not installed";
#ifdef TOPOSLAM_SANITIZED_BUILD
    GTEST_SKIP() << "the plugin is built with AddressSanitizer and MRPT's icp-slam is not";
#endif
    toposlam::test::TempDir dir;
    const std::string share = toposlam::test::shareDir();
    const std::string log = share + "/office/office.rawlog";
    std::ifstream iniIn(toposlam::test::configIni("icp-slam-feature-map.ini"));
    ASSERT_TRUE(iniIn);
    std::stringstream ini;
    ini << iniIn.rdbuf();
    std::ofstream(dir.file("icp.ini")) << std::regex_replace(
        ini.str(), std::regex("logOutput_dir = .*"), "logOutput_dir = " + dir.file("out"));
    const std::string plugin = toposlam::test::pluginPath();
    const auto run = toposlam::test::runCommand("LD_PRELOAD='" + plugin + "' icp-slam '" +
                                                dir.file("icp.ini") + "' '" + log + "'");
    std::string segmentsFile;
    for (const auto& e : std::filesystem::directory_iterator(dir.file("out")))
        if (std::regex_search(e.path().filename().string(),
                              std::regex("CScanFeaturesMap_[0-9]+_segments\\.txt$")))
            segmentsFile = e.path().string();
    ASSERT_FALSE(segmentsFile.empty()) << "icp-slam wrote no feature map:\n"
                                       << run.output.substr(0, 2000);

    // icp-slam's frame -> the plan's frame.
    const auto gt = toposlam::io::loadTrajectory(share + "/office/office_gt.txt");
    const auto path =
        toposlam::evaluation::loadIcpSlamPath(dir.file("out") + "/log_estimated_path.txt", log);
    const auto ate = toposlam::evaluation::evaluateAbsoluteTrajectoryError(path, gt);
    const sim::FloorPlan plan = sim::makeOfficeFloorPlan();
    const sim::PolygonWorld drawn = plan.toPolygonWorld();
    const std::vector<Segment> segments = readSegments(segmentsFile, CPose2D(ate.alignment));
    ASSERT_GT(segments.size(), 50u);
    double worstDistance = 0;
    std::size_t far = 0;
    for (const Segment& s : segments) {
        // Every point of the segment, 5 cm apart: a segment across a door is off the plan.
        double d = 0;
        const int n = static_cast<int>(s.length() / 0.05) + 1;
        for (int k = 0; k <= n; ++k) {
            const TPoint2D p(s.a.x + (s.b.x - s.a.x) * k / n, s.a.y + (s.b.y - s.a.y) * k / n);
            double best = 1e9;
            for (const sim::WallSegment& w : drawn.segments())
                best = std::min(best, pointToSegmentDistance(p, w.a, w.b));
            for (const sim::Disc& c : drawn.discs())
                best = std::min(
                    best, std::abs(std::hypot(p.x - c.centre.x, p.y - c.centre.y) - c.radius));
            d = std::max(d, best);
        }
        worstDistance = std::max(worstDistance, d);
        far += d > 0.10 ? 1 : 0;
        if (d > 0.10)
            std::cout << "  segment off the plan by " << d << " m: (" << s.a.x << "," << s.a.y
                      << ")-(" << s.b.x << "," << s.b.y << ")\n";
    }

    std::vector<Face> faces = wallFaces(plan);
    markSeen(faces, log, gt);
    std::size_t walls = 0, matched = 0;
    for (const Face& f : faces) {
        if (f.s.length() <= 1.0 || f.seenLength() < 1.0)
            continue;
        ++walls;
        bool found = false;
        for (const Segment& s : segments)
            found =
                found || (angleBetween(s, f.s) < 2 * M_PI / 180 && lineDistance(s.a, f.s) < 0.05 &&
                          lineDistance(s.b, f.s) < 0.05 && overlap(s, f.s) > 0.0);
        matched += found ? 1 : 0;
        if (!found)
            std::cout << "  unmatched wall face (" << f.s.a.x << "," << f.s.a.y << ")-(" << f.s.b.x
                      << "," << f.s.b.y << "), seen " << f.seenLength() << " m\n";
    }
    std::cout << "feature map vs plan: " << segments.size() << " segments; " << matched << " of "
              << walls << " seen wall faces > 1 m matched within 5 cm and 2 deg; " << far
              << " segments farther than 10 cm from the plan (worst " << worstDistance
              << " m); icp-slam ATE " << ate.position.rms << " m\n";
    EXPECT_EQ(matched, walls);
    EXPECT_EQ(far, 0u);

    // MRPT's observations2map rebuilds the same feature map from icp-slam's keyframes.
    if (toposlam::test::runCommand("command -v observations2map").exitCode != 0)
        return;
    const auto rebuilt = toposlam::test::runCommand(
        "LD_PRELOAD='" + plugin + "' observations2map '" + dir.file("icp.ini") + "' '" +
        dir.file("out") + "/_finalmap_.simplemap' '" + dir.file("o2m") + "'");
    std::string rebuiltFile;
    for (const auto& e : std::filesystem::directory_iterator(dir.path()))
        if (std::regex_search(e.path().filename().string(),
                              std::regex("^o2m_.*CScanFeaturesMap_[0-9]+_segments\\.txt$")))
            rebuiltFile = e.path().string();
    ASSERT_FALSE(rebuiltFile.empty()) << rebuilt.output;
    const auto slurp = [](const std::string& f) {
        std::ifstream in(f);
        std::stringstream ss;
        ss << in.rdbuf();
        return ss.str();
    };
    EXPECT_EQ(slurp(rebuiltFile), slurp(segmentsFile));
}
