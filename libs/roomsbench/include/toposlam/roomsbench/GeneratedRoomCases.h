#pragma once
// Benchmark B4-gen: room segmentation on generated furnished buildings
// (simulation::generateFloorPlan) with their exact ground truth, unfurnished and furnished,
// at any angle, scored like Bormann's maps (rooms::RoomBenchmark).
#include <toposlam/rooms/RoomBenchmarkCase.h>
#include <toposlam/simulation/FloorPlanImages.h>

#include <vector>

namespace toposlam::roomsbench {

/// The fixed seeds of B4-gen: 1..20.
const std::vector<unsigned>& b4GenSeeds();

/// The name of seed `seed`'s plan in tables and files: "gen01".
std::string generatedPlanName(unsigned seed);

/// The unfurnished and the furnished map of one drawing, scored against its rooms and doors.
std::vector<rooms::RoomBenchmarkCase> casesOfDrawing(const simulation::FloorPlanImages& images,
                                                     const std::string& name);

/// Seed `seed`'s plan drawn at each of `rotationsDeg`: unfurnished then furnished per angle.
std::vector<rooms::RoomBenchmarkCase> generatedCases(unsigned seed,
                                                     const std::vector<double>& rotationsDeg);

}  // namespace toposlam::roomsbench
