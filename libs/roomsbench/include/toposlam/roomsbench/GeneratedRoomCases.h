#pragma once
// Benchmarks B4-gen (office buildings) and B4-flats (flats): room segmentation on generated
// furnished buildings (simulation::generateFloorPlan) with their exact ground truth,
// unfurnished and furnished, at any angle, scored like Bormann's maps (rooms::RoomBenchmark).
#include <toposlam/rooms/RoomBenchmarkCase.h>
#include <toposlam/simulation/FloorPlanGenerator.h>
#include <toposlam/simulation/FloorPlanImages.h>

#include <vector>

namespace toposlam::roomsbench {

/// The fixed seeds of B4-gen and B4-flats: 1..20.
const std::vector<unsigned>& b4GenSeeds();

/// The set's name in tables: "gen" (offices) or "flats".
std::string generatedSetName(simulation::BuildingStyle style);

/// The name of seed `seed`'s plan in tables and files: "gen01", "flat01".
std::string generatedPlanName(unsigned seed,
                              simulation::BuildingStyle style = simulation::BuildingStyle::Office);

/// The unfurnished and the furnished map of one drawing, scored against its rooms and doors,
/// in set `set`.
std::vector<rooms::RoomBenchmarkCase> casesOfDrawing(const simulation::FloorPlanImages& images,
                                                     const std::string& name,
                                                     const std::string& set = "gen");

/// Seed `seed`'s plan drawn at each of `rotationsDeg`: unfurnished then furnished per angle.
std::vector<rooms::RoomBenchmarkCase> generatedCases(
    unsigned seed, const std::vector<double>& rotationsDeg,
    simulation::BuildingStyle style = simulation::BuildingStyle::Office);

}  // namespace toposlam::roomsbench
