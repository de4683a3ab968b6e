#pragma once
// The project's own office floor plan (share/office): a 24 m x 13 m floor with a 1.9 m wide
// corridor along its length, ten rooms of different sizes (offices, open-plan offices, a
// meeting room with two doors, a lab, a kitchen, a copy room with a server room behind it),
// doors 0.8-1.0 m wide, and desks, cabinets, tables and counters. Two of the rooms have a
// second door, so a tour through them closes loops. Deterministic: always the same plan.
//
// Frame: x east, y north, the inner face of the outer walls' south-west corner at (0, 0).
// Outer walls 0.2 m thick, inner walls 0.1 m. Room ids: 1 = corridor, then south rooms west to
// east, then north rooms west to east (names in the plan).
#include <toposlam/simulation/FloorPlan.h>

namespace toposlam::simulation {

FloorPlan makeOfficeFloorPlan();

}  // namespace toposlam::simulation
