#pragma once
// The flats of FloorPlanGenerator (BuildingStyle::Flat): see FloorPlanGenerator.h.
#include <toposlam/simulation/FloorPlanGenerator.h>

namespace toposlam::simulation {

/// Seed `seed`'s flat: the same seed and options always give the same plan.
GeneratedFloorPlan generateFlatPlan(unsigned seed, const FloorPlanGeneratorOptions& options);

}  // namespace toposlam::simulation
