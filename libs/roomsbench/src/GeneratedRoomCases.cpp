#include <toposlam/rooms/RoomBenchmarkCase.h>
#include <toposlam/roomsbench/GeneratedRoomCases.h>
#include <toposlam/simulation/FloorPlanGenerator.h>

#include <cstdio>

namespace toposlam::roomsbench {

const std::vector<unsigned>& b4GenSeeds() {
    static const std::vector<unsigned> seeds = [] {
        std::vector<unsigned> s;
        for (unsigned k = 1; k <= 20; ++k)
            s.push_back(k);
        return s;
    }();
    return seeds;
}

std::string generatedSetName(simulation::BuildingStyle style) {
    switch (style) {
        case simulation::BuildingStyle::Flat:
            return "flats";
        case simulation::BuildingStyle::Ring:
            return "rings";
        case simulation::BuildingStyle::Office:
            break;
    }
    return "gen";
}

std::string generatedPlanName(unsigned seed, simulation::BuildingStyle style) {
    std::string set = generatedSetName(style);
    if (style != simulation::BuildingStyle::Office)
        set.pop_back();  // "flat01", "ring01"
    char buf[32];
    std::snprintf(buf, sizeof buf, "%s%02u", set.c_str(), seed);
    return buf;
}

std::vector<rooms::RoomBenchmarkCase> casesOfDrawing(const simulation::FloorPlanImages& images,
                                                     const std::string& name,
                                                     const std::string& set) {
    const cv::Mat free = images.map == 255;
    const cv::Mat furnished = images.furnished == 255;
    return {rooms::drawnCase(set, name, false, images.rotationDeg, free, free, images.rooms,
                             images.resolution),
            rooms::drawnCase(set, name + "_furnitures", true, images.rotationDeg, furnished, free,
                             images.rooms, images.resolution)};
}

std::vector<rooms::RoomBenchmarkCase> generatedCases(unsigned seed,
                                                     const std::vector<double>& rotationsDeg,
                                                     simulation::BuildingStyle style) {
    simulation::FloorPlanGeneratorOptions options;
    options.style = style;
    const simulation::GeneratedFloorPlan plan = simulation::generateFloorPlan(seed, options);
    std::vector<rooms::RoomBenchmarkCase> cases;
    for (const double angle : rotationsDeg) {
        for (auto& c :
             casesOfDrawing(simulation::drawFloorPlan(plan, rooms::kBenchmarkMapResolution, angle),
                            generatedPlanName(seed, style), generatedSetName(style))) {
            cases.push_back(std::move(c));
        }
    }
    return cases;
}

}  // namespace toposlam::roomsbench
