#include <toposlam/featureeval/SimulatedScans.h>
#include <toposlam/simulation/LaserModel.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace toposlam::featureeval {

std::string LaserSetup::name() const {
    return std::to_string(beams) + " x " +
           std::to_string(static_cast<int>(std::lround(aperture * 180 / M_PI))) + " deg";
}

std::vector<SyntheticScene> makeScenes(int rooms, unsigned seed,
                                       const SyntheticRoomOptions& options) {
    std::mt19937 rng(seed);
    std::vector<SyntheticScene> scenes;
    for (int r = 0; r < rooms; ++r)
        scenes.push_back(makeSyntheticRoom(rng, options));
    return scenes;
}

std::vector<SimulatedScan> simulateScans(const std::vector<SyntheticScene>& scenes,
                                         const LaserSetup& laserSetup, double sigma,
                                         unsigned noiseSeed, const GroundTruthOptions& truth) {
    simulation::LaserModel laser;
    laser.beams = laserSetup.beams;
    laser.aperture = laserSetup.aperture;
    laser.maxRange = laserSetup.maxRange;
    laser.rangeNoiseStd = sigma;
    std::mt19937 noise(noiseSeed);
    std::vector<SimulatedScan> out;
    for (const SyntheticScene& scene : scenes) {
        const simulation::PolygonWorld world = scene.world();
        for (const auto& pose : scene.poses) {
            SimulatedScan s;
            s.scan = simulation::simulateScan(world, laser, pose, noise);
            s.truth = computeGroundTruth(scene, pose, s.scan, truth);
            out.push_back(std::move(s));
        }
    }
    return out;
}

FeatureScores scoreExtractor(features::FeatureExtractor& extractor,
                             const std::vector<SimulatedScan>& scans) {
    FeatureScores scores;
    features::ScanFeatures f;
    for (const SimulatedScan& s : scans) {
        extractor.extract(s.scan, f);
        scores.add(f, s.truth);
    }
    return scores;
}

CornerAgreement compareCorners(features::FeatureExtractor& a, features::FeatureExtractor& b,
                               const std::vector<SimulatedScan>& scans, double radius) {
    std::vector<double> d;
    features::ScanFeatures fa, fb;
    for (const SimulatedScan& s : scans) {
        a.extract(s.scan, fa);
        b.extract(s.scan, fb);
        for (const features::Corner& ca : fa.corners) {
            double best = HUGE_VAL;
            for (const features::Corner& cb : fb.corners) {
                best = std::min(
                    best, std::hypot(ca.position.x - cb.position.x, ca.position.y - cb.position.y));
            }
            if (best <= radius)
                d.push_back(best);
        }
    }
    CornerAgreement out;
    out.pairs = d.size();
    if (d.empty())
        return out;
    std::sort(d.begin(), d.end());
    double sum = 0;
    for (double v : d)
        sum += v;
    out.mean = sum / static_cast<double>(d.size());
    out.p95 =
        d[std::min(d.size() - 1, static_cast<std::size_t>(0.95 * static_cast<double>(d.size())))];
    out.max = d.back();
    return out;
}

}  // namespace toposlam::featureeval
