#include <toposlam/features/CornerExtractor.h>
#include <toposlam/features/SegmentExtractor.h>
#include <toposlam/features/SplitAndMergeExtractor.h>
#include <toposlam/mapping/GraphSlamOptions.h>
#include <toposlam/mapping/LogMapper.h>
#include <toposlam/mapping/OccupancyGridBuilder.h>
#include <toposlam/matching/CScanFeaturesMap.h>
#include <toposlam/mrptslam/CGraphMatcherAlignment.h>
#include <toposlam/rooms/RoomSegmenter.h>
#include <toposlam/simulation/SimulatorConfig.h>

#include <TestSupport.h>
#include "OptionsTable.h"

#include <algorithm>
#include <filesystem>

namespace toposlam::test {

const std::map<std::string, OptionsFactory>& sectionStructs() {
    static const simulation::SimulatorConfig sim;
    static const std::map<std::string, OptionsFactory> table = {
        {"CornerExtractor", make<features::CornerExtractorOptions>()},
        {"SegmentExtractor", make<features::SegmentExtractorOptions>()},
        {"SplitAndMergeExtractor", make<features::SplitAndMergeOptions>()},
        {"GraphScanMatcher", make<mrptslam::CGraphMatcherAlignment::Options>()},
        {"Laser", make(sim.log.laser)},
        {"Odometry", make(sim.log.odometry)},
        {"People", make(sim.log.people)},
        {"Tour", make(sim.tour)},
        {"Simulation", make(sim)},
        {"OccupancyGrid", make<mapping::OccupancyGridOptions>()},
        {"GraphSlam", make<mapping::GraphSlamOptions>()},
        {"Slam", make<mapping::SlamEngineOptions>()},
        {"RoomSegmenter", make<rooms::RoomSegmenter::Options>()},
    };
    return table;
}

OptionsFactory structOfSection(const std::string& section) {
    const auto it = sectionStructs().find(section);
    if (it != sectionStructs().end())
        return it->second;
    // TopoSLAM's map in MRPT map definitions: <prefix>_scanFeaturesMap_NN_<kind>Opts.
    const auto endsWith = [&](const std::string& tail) {
        return section.size() > tail.size() &&
               section.compare(section.size() - tail.size(), tail.size(), tail) == 0 &&
               section.find("_scanFeaturesMap_") != std::string::npos;
    };
    if (endsWith("_insertOpts"))
        return make<matching::CScanFeaturesMap::TInsertionOptions>();
    if (endsWith("_likelihoodOpts"))
        return make<matching::CScanFeaturesMap::TLikelihoodOptions>();
    return {};
}

bool isMrptSection(const std::string& section) {
    if (structOfSection(section))
        return false;
    // [ICP]: CICP; [MappingApplication*]: icp-slam / kf-slam and their map definitions;
    // [RangeBearingKFSLAM*]: kf-slam's filter.
    return section == "ICP" || section.rfind("MappingApplication", 0) == 0 ||
           section.rfind("RangeBearingKFSLAM", 0) == 0;
}

std::vector<std::string> configFiles() {
    std::vector<std::string> files;
    for (const auto& e : std::filesystem::directory_iterator(shareDir() + "/../config_ini")) {
        if (e.path().extension() == ".ini")
            files.push_back(e.path().string());
    }
    std::sort(files.begin(), files.end());
    return files;
}

}  // namespace toposlam::test
