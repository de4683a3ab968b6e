#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/maps/TMetricMapTypesRegistry.h>
#include <mrpt/opengl/CPointCloud.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/serialization/CArchive.h>
#include <toposlam/features/FeatureExtractor.h>
#include <toposlam/matching/AlignmentScorer.h>
#include <toposlam/matching/CScanFeaturesMap.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

using namespace toposlam::matching;

// "scanFeaturesMap_count = 1" in .ini map definitions (or CScanFeaturesMap_count).
MAP_DEFINITION_REGISTER("toposlam::matching::CScanFeaturesMap,scanFeaturesMap",
                        toposlam::matching::CScanFeaturesMap)

CScanFeaturesMap::TMapDefinition::TMapDefinition() = default;

void CScanFeaturesMap::TMapDefinition::loadFromConfigFile_map_specific(
    const mrpt::config::CConfigFileBase& source, const std::string& sectionPrefix) {
    extractor = source.read_string(sectionPrefix + "_creationOpts", "extractor", extractor);
}

void CScanFeaturesMap::TMapDefinition::dumpToTextStream_map_specific(std::ostream& out) const {
    out << "extractor = " << extractor << "\n";
}

mrpt::maps::CMetricMap* CScanFeaturesMap::internal_CreateFromMapDefinition(
    const mrpt::maps::TMetricMapInitializer& def) {
    return new CScanFeaturesMap(dynamic_cast<const TMapDefinition&>(def).extractor);
}

IMPLEMENTS_SERIALIZABLE(CScanFeaturesMap, CMetricMap, toposlam::matching)

CScanFeaturesMap::CScanFeaturesMap(const std::string& extractor) : extractor_(extractor) {
    features::makeFeatureExtractor(extractor_);  // throws for an unknown name
}

uint8_t CScanFeaturesMap::serializeGetVersion() const {
    return 0;
}

void CScanFeaturesMap::serializeTo(mrpt::serialization::CArchive& out) const {
    out << extractor_ << hasScan_ << robotPose_;
    if (hasScan_)
        out << scan_;
}

void CScanFeaturesMap::serializeFrom(mrpt::serialization::CArchive& in, uint8_t version) {
    switch (version) {
        case 0: {
            in >> extractor_ >> hasScan_ >> robotPose_;
            if (hasScan_) {
                in >> scan_;
                setScan(scan_, robotPose_);
            } else {
                internal_clear();
            }
            break;
        }
        default:
            MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
    }
}

void CScanFeaturesMap::setScan(const mrpt::obs::CObservation2DRangeScan& scan,
                               const mrpt::poses::CPose2D& robotPose) {
    if (&scan != &scan_)
        scan_ = scan;
    robotPose_ = robotPose;
    sensorPose_ = robotPose + mrpt::poses::CPose2D(scan.sensorPose);
    polar_.assign(scan_);
    hasScan_ = true;
    extract();
}

void CScanFeaturesMap::setExtractor(const std::string& name) {
    features::makeFeatureExtractor(name);  // validates
    extractor_ = name;
    if (hasScan_)
        extract();
}

void CScanFeaturesMap::extract() {
    // Extractors keep workspaces; maps are few and long-lived, so one per call is fine.
    features::makeFeatureExtractor(extractor_)->extract(scan_, features_);
}

bool CScanFeaturesMap::isEmpty() const {
    return !hasScan_ || polar_.validCount() == 0;
}

void CScanFeaturesMap::internal_clear() {
    hasScan_ = false;
    scan_ = mrpt::obs::CObservation2DRangeScan();
    polar_ = PolarScan();
    features_.clear();
    robotPose_ = sensorPose_ = mrpt::poses::CPose2D();
}

bool CScanFeaturesMap::internal_insertObservation(
    const mrpt::obs::CObservation& obs,
    const std::optional<const mrpt::poses::CPose3D>& robotPose) {
    const auto* scan = dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(&obs);
    if (!scan)
        return false;
    setScan(*scan, robotPose ? mrpt::poses::CPose2D(*robotPose) : mrpt::poses::CPose2D());
    return true;
}

double CScanFeaturesMap::internal_computeObservationLikelihood(
    const mrpt::obs::CObservation& obs, const mrpt::poses::CPose3D& takenFrom) const {
    const auto* scan = dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(&obs);
    if (!scan || !hasScan_)
        return 0.0;
    PolarScan other;
    other.assign(*scan);
    const mrpt::poses::CPose2D sensor =
        mrpt::poses::CPose2D(takenFrom) + mrpt::poses::CPose2D(scan->sensorPose);
    const AlignmentScore s = scoreAlignment(polar_, other, sensor - sensorPose_);
    return std::log(std::max(1e-3, s.inlierFraction()));
}

void CScanFeaturesMap::saveMetricMapRepresentationToFile(const std::string& prefix) const {
    std::ofstream points(prefix + "_points.txt"), segments(prefix + "_segments.txt");
    if (!points || !segments)
        throw std::runtime_error("cannot write " + prefix + "_points.txt / _segments.txt");
    for (std::size_t i = 0; i < polar_.size(); ++i) {
        if (!polar_.valid(i))
            continue;
        double x, y;
        sensorPose_.composePoint(polar_.point(i).x, polar_.point(i).y, x, y);
        points << x << " " << y << "\n";
    }
    for (const features::LineSegment& s : features_.segments) {
        double x0, y0, x1, y1;
        sensorPose_.composePoint(s.start.x, s.start.y, x0, y0);
        sensorPose_.composePoint(s.end.x, s.end.y, x1, y1);
        segments << x0 << " " << y0 << " " << x1 << " " << y1 << "\n";
    }
}

void CScanFeaturesMap::getVisualizationInto(mrpt::opengl::CSetOfObjects& outObj) const {
    auto cloud = mrpt::opengl::CPointCloud::Create();
    cloud->setPointSize(2.0f);
    cloud->setColor(0.2f, 0.2f, 0.8f);
    auto lines = mrpt::opengl::CSetOfLines::Create();
    lines->setLineWidth(3.0f);
    lines->setColor(0.9f, 0.3f, 0.1f);
    for (std::size_t i = 0; i < polar_.size(); ++i) {
        if (!polar_.valid(i))
            continue;
        double x, y;
        sensorPose_.composePoint(polar_.point(i).x, polar_.point(i).y, x, y);
        cloud->insertPoint(float(x), float(y), 0.0f);
    }
    for (const features::LineSegment& s : features_.segments) {
        double x0, y0, x1, y1;
        sensorPose_.composePoint(s.start.x, s.start.y, x0, y0);
        sensorPose_.composePoint(s.end.x, s.end.y, x1, y1);
        lines->appendLine(x0, y0, 0.0, x1, y1, 0.0);
    }
    outObj.insert(cloud);
    outObj.insert(lines);
}

std::string CScanFeaturesMap::asString() const {
    std::ostringstream o;
    o << "CScanFeaturesMap: " << (hasScan_ ? polar_.validCount() : 0) << " points, "
      << features_.segments.size() << " segments (extractor " << extractor_ << "), sensor at "
      << sensorPose_.asString();
    return o.str();
}
