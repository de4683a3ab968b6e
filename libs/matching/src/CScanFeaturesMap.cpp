#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/maps/TMetricMapTypesRegistry.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/serialization/CArchive.h>
#include <toposlam/features/CObservationLaserFeatures.h>
#include <toposlam/features/FeatureExtractor.h>
#include <toposlam/features/ScanFeaturesArchive.h>
#include <toposlam/io/AtomicFile.h>
#include <toposlam/io/ClassRegistration.h>
#include <toposlam/io/UprightScan.h>
#include <toposlam/matching/CScanFeaturesMap.h>
#include <toposlam/matching/FeatureMapRendering.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>

using namespace toposlam::matching;
using mrpt::poses::CPose2D;

// "scanFeaturesMap_count = 1" in .ini map definitions (or CScanFeaturesMap_count).
MAP_DEFINITION_REGISTER("toposlam::matching::CScanFeaturesMap,scanFeaturesMap",
                        toposlam::matching::CScanFeaturesMap)

// --- options -------------------------------------------------------------------------------

void CScanFeaturesMap::TInsertionOptions::declare(config::OptionsSchema& s) {
    s.choice("source", source, {{"scans", Source::Scans}, {"features", Source::Features}},
             "scans: extract from each inserted CObservation2DRangeScan; features: use the "
             "CObservationLaserFeatures of a toposlam-annotate-features rawlog");
    s.group("", merge);
}

void CScanFeaturesMap::TLikelihoodOptions::declare(config::OptionsSchema& s) {
    s.real("sigma_dist", sigma_dist, "m^2", "variance of a point's distance to the map's lines")
        .above(0);
    s.real("max_corr_distance", max_corr_distance, "m", "farther points count as this far")
        .above(0);
    s.integer("decimation", decimation, "", "use every decimation-th scan point").within(1, 10000);
}

CScanFeaturesMap::TMapDefinition::TMapDefinition() = default;

void CScanFeaturesMap::TMapDefinition::loadFromConfigFile_map_specific(
    const mrpt::config::CConfigFileBase& source, const std::string& sectionPrefix) {
    extractor = source.read_string(sectionPrefix + "_creationOpts", "extractor", extractor);
    insertionOpts.loadFromConfigFile(source, sectionPrefix + "_insertOpts");
    likelihoodOpts.loadFromConfigFile(source, sectionPrefix + "_likelihoodOpts");
}

void CScanFeaturesMap::TMapDefinition::dumpToTextStream_map_specific(std::ostream& out) const {
    out << "extractor           = " << extractor << "\n";
    insertionOpts.dumpToTextStream(out);
    likelihoodOpts.dumpToTextStream(out);
}

mrpt::maps::CMetricMap* CScanFeaturesMap::internal_CreateFromMapDefinition(
    const mrpt::maps::TMetricMapInitializer& def) {
    const auto& d = dynamic_cast<const TMapDefinition&>(def);
    auto* m = new CScanFeaturesMap(d.extractor);
    m->insertionOptions = d.insertionOpts;
    m->likelihoodOptions = d.likelihoodOpts;
    return m;
}

// --- serialization -------------------------------------------------------------------------

IMPLEMENTS_SERIALIZABLE(CScanFeaturesMap, CMetricMap, toposlam::matching)
TOPOSLAM_REGISTER_CLASS(CScanFeaturesMap)

CScanFeaturesMap::CScanFeaturesMap(const std::string& extractor)
    : extractor_(extractor), extractorObject_(features::makeFeatureExtractor(extractor)) {}

uint8_t CScanFeaturesMap::serializeGetVersion() const {
    return 1;
}

void CScanFeaturesMap::serializeTo(mrpt::serialization::CArchive& out) const {
    const FeatureMapOptions& o = insertionOptions.merge;
    out << extractor_ << static_cast<uint8_t>(insertionOptions.source) << o.mergeAngle
        << o.mergeDistance << o.mergeGap << o.minSegmentLength << o.cornerMergeRadius
        << o.endpointMergeRadius << o.poseStd << o.minObservations;
    out << likelihoodOptions.sigma_dist << likelihoodOptions.max_corr_distance
        << static_cast<uint32_t>(likelihoodOptions.decimation);
    out << static_cast<uint32_t>(keyframes_.size());
    for (const FeatureKeyframe& k : keyframes_) {
        out << k.robotPose << k.sensorOnRobot;
        features::writeScanFeatures(out, k.features);
    }
    out << hasScan_;
    if (hasScan_)
        out << scanRobotPose_ << scan_;
}

void CScanFeaturesMap::serializeFrom(mrpt::serialization::CArchive& in, uint8_t version) {
    internal_clear();
    switch (version) {
        case 0: {  // one scan: extractor, hasScan, robot pose, scan
            CPose2D robotPose;
            in >> extractor_ >> hasScan_ >> robotPose;
            extractorObject_ = features::makeFeatureExtractor(extractor_);  // validates the name
            if (hasScan_) {
                in >> scan_;
                insertScan(scan_, robotPose);
            }
        } break;
        case 1: {
            FeatureMapOptions& o = insertionOptions.merge;
            uint8_t source = 0;
            uint32_t decimation = 0, n = 0;
            in >> extractor_ >> source >> o.mergeAngle >> o.mergeDistance >> o.mergeGap >>
                o.minSegmentLength >> o.cornerMergeRadius >> o.endpointMergeRadius >> o.poseStd >>
                o.minObservations;
            in >> likelihoodOptions.sigma_dist >> likelihoodOptions.max_corr_distance >> decimation;
            if (source > 1 || decimation < 1)
                throw std::runtime_error("CScanFeaturesMap: corrupt options");
            extractorObject_ = features::makeFeatureExtractor(extractor_);  // validates the name
            try {
                o.validate("FeatureMap");
            } catch (const std::exception& e) {
                throw std::runtime_error(std::string("CScanFeaturesMap: corrupt options: ") +
                                         e.what());
            }
            insertionOptions.source = static_cast<Source>(source);
            likelihoodOptions.decimation = decimation;
            in >> n;
            std::vector<FeatureKeyframe> keyframes;
            for (uint32_t i = 0; i < n; ++i) {  // no reserve(n): n comes from the file
                FeatureKeyframe& k = keyframes.emplace_back();
                in >> k.robotPose >> k.sensorOnRobot;
                features::readScanFeatures(in, k.features);
            }
            bool hasScan = false;
            in >> hasScan;
            if (hasScan) {
                CPose2D robotPose;
                in >> robotPose >> scan_;
                keepScan(scan_, robotPose);
            }
            rebuild(std::move(keyframes));
        } break;
        default:
            MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
    }
}

// --- building ------------------------------------------------------------------------------

void CScanFeaturesMap::insertKeyframe(const FeatureKeyframe& keyframe) {
    map_.options = insertionOptions.merge;
    keyframes_.push_back(keyframe);
    map_.insert(keyframe.features, keyframe.sensorPose());
}

void CScanFeaturesMap::keepScan(const mrpt::obs::CObservation2DRangeScan& scan,
                                const CPose2D& robotPose) {
    if (&scan != &scan_)
        scan_ = scan;
    io::makeUpright(scan_);  // an upside-down laser's, as LaserLogReader reads it
    scanRobotPose_ = robotPose;
    sensorPose_ = robotPose + CPose2D(scan_.sensorPose);
    polar_.assign(scan_);
    hasScan_ = true;
    // One extractor per map, made on first use (it keeps its workspaces between scans).
    if (!extractorObject_)
        extractorObject_ = features::makeFeatureExtractor(extractor_);
    extractorObject_->extract(scan_, scanFeatures_);
}

void CScanFeaturesMap::insertScan(const mrpt::obs::CObservation2DRangeScan& scan,
                                  const CPose2D& robotPose) {
    keepScan(scan, robotPose);
    FeatureKeyframe k;
    k.robotPose = robotPose;
    k.sensorOnRobot = CPose2D(scan_.sensorPose);
    k.features = scanFeatures_;
    insertKeyframe(k);
}

void CScanFeaturesMap::setScan(const mrpt::obs::CObservation2DRangeScan& scan,
                               const CPose2D& robotPose) {
    internal_clear();
    insertScan(scan, robotPose);
}

void CScanFeaturesMap::updateKeyframePoses(const std::vector<CPose2D>& robotPoses) {
    if (robotPoses.size() != keyframes_.size()) {
        throw std::invalid_argument(
            "CScanFeaturesMap::updateKeyframePoses: " + std::to_string(robotPoses.size()) +
            " poses for " + std::to_string(keyframes_.size()) + " keyframes");
    }
    for (std::size_t i = 0; i < robotPoses.size(); ++i)
        keyframes_[i].robotPose = robotPoses[i];
    rebuildMap();
}

void CScanFeaturesMap::rebuild(std::vector<FeatureKeyframe> keyframes) {
    keyframes_ = std::move(keyframes);
    rebuildMap();
}

void CScanFeaturesMap::rebuildMap() {
    map_.clear();
    map_.options = insertionOptions.merge;
    for (const FeatureKeyframe& k : keyframes_)
        map_.insert(k.features, k.sensorPose());
}

void CScanFeaturesMap::setExtractor(const std::string& name) {
    extractorObject_ = features::makeFeatureExtractor(name);  // validates
    extractor_ = name;
    if (hasScan_)
        keepScan(scan_, scanRobotPose_);
}

void CScanFeaturesMap::internal_clear() {
    map_.clear();
    keyframes_.clear();
    hasScan_ = false;
    scan_ = mrpt::obs::CObservation2DRangeScan();
    polar_ = PolarScan();
    scanFeatures_.clear();
    scanRobotPose_ = sensorPose_ = CPose2D();
}

bool CScanFeaturesMap::isEmpty() const {
    return keyframes_.empty() && !hasScan_;
}

bool CScanFeaturesMap::internal_insertObservation(
    const mrpt::obs::CObservation& obs,
    const std::optional<const mrpt::poses::CPose3D>& robotPose) {
    const CPose2D robot = robotPose ? CPose2D(*robotPose) : CPose2D();
    if (insertionOptions.source == Source::Scans) {
        const auto* scan = dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(&obs);
        if (!scan)
            return false;
        insertScan(*scan, robot);
        return true;
    }
    const auto* f = dynamic_cast<const features::CObservationLaserFeatures*>(&obs);
    if (!f)
        return false;
    FeatureKeyframe k;
    k.robotPose = robot;
    k.sensorOnRobot = CPose2D(f->sensorPose);
    k.features = f->features;
    insertKeyframe(k);
    return true;
}

// --- likelihood ----------------------------------------------------------------------------

bool CScanFeaturesMap::internal_canComputeObservationLikelihood(
    const mrpt::obs::CObservation& obs) const {
    return dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(&obs) != nullptr ||
           dynamic_cast<const features::CObservationLaserFeatures*>(&obs) != nullptr;
}

double CScanFeaturesMap::internal_computeObservationLikelihood(
    const mrpt::obs::CObservation& obs, const mrpt::poses::CPose3D& takenFrom) const {
    if (map_.confirmedSegments() == 0)
        return 0.0;
    const double maxD = likelihoodOptions.max_corr_distance;
    double sum = 0;
    std::size_t n = 0;
    const auto add = [&](const CPose2D& sensor, double x, double y) {
        double gx, gy;
        sensor.composePoint(x, y, gx, gy);
        const double d = map_.distanceToSegments({gx, gy}, maxD);
        sum += d * d;
        ++n;
    };
    const CPose2D robot(takenFrom);
    if (const auto* observed = dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(&obs)) {
        // An upside-down laser's scan, upright (a copy: rare).
        std::optional<mrpt::obs::CObservation2DRangeScan> upright;
        const mrpt::obs::CObservation2DRangeScan* scan = observed;
        if (io::isUpsideDown(*observed)) {
            upright.emplace(*observed);
            io::makeUpright(*upright);
            scan = &*upright;
        }
        const CPose2D sensor = robot + CPose2D(scan->sensorPose);
        const std::size_t beams = scan->getScanSize();
        for (std::size_t i = 0; i < beams; i += likelihoodOptions.decimation) {
            const float r = scan->getScanRange(i);
            if (!scan->getScanRangeValidity(i) || !(r > 0) || r >= scan->maxRange)
                continue;
            const double a = scan->getScanAngle(i);
            add(sensor, r * std::cos(a), r * std::sin(a));
        }
    } else if (const auto* f = dynamic_cast<const features::CObservationLaserFeatures*>(&obs)) {
        const CPose2D sensor = robot + CPose2D(f->sensorPose);
        for (const features::Corner& c : f->features.corners)
            add(sensor, c.position.x, c.position.y);
        for (const features::LineSegment& s : f->features.segments) {
            const auto mid = s.midpoint();
            add(sensor, s.start.x, s.start.y);
            add(sensor, mid.x, mid.y);
            add(sensor, s.end.x, s.end.y);
        }
    }
    return n == 0 ? 0.0 : -(sum / static_cast<double>(n)) / likelihoodOptions.sigma_dist;
}

// --- output --------------------------------------------------------------------------------

namespace {

void writeTextFile(const std::string& path, const std::string& content) {
    toposlam::io::writeFileAtomically(path, [&](const std::string& tmp) {
        std::ofstream f(tmp);
        f << content;
        if (!f.flush())
            throw std::runtime_error(path + ": cannot write");
    });
}

}  // namespace

void CScanFeaturesMap::saveMetricMapRepresentationToFile(const std::string& prefix) const {
    std::ostringstream segments, corners, endpoints;
    segments << "# confirmed wall segments, map frame (m); the wall was seen from the left of "
                "start->end;\n# pieces of one line (walls on both sides of a door) share its "
                "line number\n# x0 y0 x1 y1 length line observations\n";
    for (std::size_t i = 0; i < map_.segments().size(); ++i) {
        const MapSegment& s = map_.segments()[i];
        if (!map_.confirmed(s))
            continue;
        for (const SegmentPiece& p : s.pieces)
            segments << p.start.x << " " << p.start.y << " " << p.end.x << " " << p.end.y << " "
                     << p.length() << " " << i << " " << s.observations << "\n";
    }
    corners << "# confirmed corners, map frame (m)\n"
               "# x y type angle_deg std_x std_y observations\n";
    for (const MapPoint& p : map_.corners()) {
        if (map_.confirmed(p))
            corners << p.position.x << " " << p.position.y << " " << toString(p.type) << " "
                    << p.angle * 180 / M_PI << " " << std::sqrt(p.covariance(0, 0)) << " "
                    << std::sqrt(p.covariance(1, 1)) << " " << p.observations << "\n";
    }
    endpoints << "# confirmed segment endpoints, map frame (m)\n# x y type observations\n";
    for (const MapPoint& p : map_.endpoints()) {
        if (map_.confirmed(p))
            endpoints << p.position.x << " " << p.position.y << " " << toString(p.type) << " "
                      << p.observations << "\n";
    }
    writeTextFile(prefix + "_segments.txt", segments.str());
    writeTextFile(prefix + "_corners.txt", corners.str());
    writeTextFile(prefix + "_endpoints.txt", endpoints.str());
    const mrpt::img::CImage picture = drawFeatureMap(map_);
    toposlam::io::writeFileAtomically(prefix + ".png", [&](const std::string& tmp) {
        if (!picture.saveToFile(tmp))  // tmp keeps the ".png" that selects the format
            throw std::runtime_error(prefix + ".png: cannot write");
    });
}

void CScanFeaturesMap::getVisualizationInto(mrpt::opengl::CSetOfObjects& outObj) const {
    appendFeatureMapVisualization(map_, outObj);
}

std::string CScanFeaturesMap::asString() const {
    std::ostringstream o;
    o << "CScanFeaturesMap: " << keyframes_.size() << " keyframes; " << map_.confirmedSegments()
      << " segments, " << map_.confirmedCorners() << " corners, " << map_.confirmedEndpoints()
      << " endpoints confirmed (seen >= " << insertionOptions.merge.minObservations << " times) of "
      << map_.segments().size() << " / " << map_.corners().size() << " / "
      << map_.endpoints().size() << "; extractor " << extractor_;
    return o.str();
}
