#include <toposlam/simulation/OfficeFloorPlan.h>

namespace toposlam::simulation {

FloorPlan makeOfficeFloorPlan() {
    constexpr double W = 24.0, H = 13.0;        // inner size of the building, m
    constexpr double outer = 0.2, inner = 0.1;  // wall thicknesses, m
    constexpr double corrS = 5.5, corrN = 7.5;  // centre lines of the corridor walls
    constexpr double hi = inner / 2;            // half an inner wall
    FloorPlan plan;

    // Outer walls: centre lines half a thickness outside the inner faces; every wall extends
    // half its thickness past its end points, so the corners close.
    const double o = outer / 2;
    plan.addWall({-o, -o}, {W + o, -o}, outer);
    plan.addWall({-o, H + o}, {W + o, H + o}, outer);
    plan.addWall({-o, -o}, {-o, H + o}, outer);
    plan.addWall({W + o, -o}, {W + o, H + o}, outer);
    // Corridor walls and the partitions between rooms.
    plan.addWall({0, corrS}, {W, corrS}, inner);
    plan.addWall({0, corrN}, {W, corrN}, inner);
    for (double x : {6.0, 9.5, 12.5, 19.0})
        plan.addWall({x, 0}, {x, corrS}, inner);
    plan.addWall({9.5, 2.5}, {12.5, 2.5}, inner);  // copy room / server room
    for (double x : {4.5, 8.0, 15.0})
        plan.addWall({x, corrN}, {x, H}, inner);

    // Rooms: floors between the wall faces.
    const int corridor = plan.addRoom("corridor", "corridor", {0, corrS + hi, W, corrN - hi});
    const int openWest =
        plan.addRoom("open office S1", "open-plan office", {0, 0, 6 - hi, corrS - hi});
    const int officeS2 = plan.addRoom("office S2", "office", {6 + hi, 0, 9.5 - hi, corrS - hi});
    const int copy =
        plan.addRoom("copy room S3", "copy room", {9.5 + hi, 2.5 + hi, 12.5 - hi, corrS - hi});
    const int server =
        plan.addRoom("server room S4", "server room", {9.5 + hi, 0, 12.5 - hi, 2.5 - hi});
    const int meeting =
        plan.addRoom("meeting room S5", "meeting room", {12.5 + hi, 0, 19 - hi, corrS - hi});
    const int kitchen = plan.addRoom("kitchen S6", "kitchen", {19 + hi, 0, W, corrS - hi});
    const int officeN1 = plan.addRoom("office N1", "office", {0, corrN + hi, 4.5 - hi, H});
    const int officeN2 = plan.addRoom("office N2", "office", {4.5 + hi, corrN + hi, 8 - hi, H});
    const int lab = plan.addRoom("lab N3", "lab", {8 + hi, corrN + hi, 15 - hi, H});
    const int openEast =
        plan.addRoom("open office N4", "open-plan office", {15 + hi, corrN + hi, W, H});

    // Doors: jambs on the wall centre lines, 0.8-1.0 m wide.
    plan.addDoor({4.5, corrS}, {5.4, corrS}, openWest, corridor);
    plan.addDoor({6.6, corrS}, {7.45, corrS}, officeS2, corridor);
    plan.addDoor({10.6, corrS}, {11.4, corrS}, copy, corridor);
    plan.addDoor({11.3, 2.5}, {12.1, 2.5}, copy, server);
    plan.addDoor({13.0, corrS}, {14.0, corrS}, meeting, corridor);
    plan.addDoor({17.6, corrS}, {18.6, corrS}, meeting, corridor);
    plan.addDoor({19.8, corrS}, {20.75, corrS}, kitchen, corridor);
    plan.addDoor({3.2, corrN}, {4.1, corrN}, officeN1, corridor);
    plan.addDoor({5.0, corrN}, {5.85, corrN}, officeN2, corridor);
    plan.addDoor({9.0, corrN}, {10.0, corrN}, lab, corridor);
    plan.addDoor({15.0, 10.4}, {15.0, 11.35}, lab, openEast);
    plan.addDoor({21.0, corrN}, {21.9, corrN}, openEast, corridor);

    // Furniture: desks 1.6 x 0.8 m, cabinets 0.45 m deep, tables, counters.
    // S1, open-plan office: two desks face to face, a single desk, a cabinet.
    plan.addFurniture(Box{0.9, 1.2, 2.5, 2.8});
    plan.addFurniture(Box{3.7, 1.2, 5.3, 2.0});
    plan.addFurniture(Box{0.0, 3.4, 0.45, 4.6});
    // S2, office: desk at the south wall, cabinet at the east wall.
    plan.addFurniture(Box{6.9, 0.0, 8.5, 0.8});
    plan.addFurniture(Box{9.0, 2.0, 9.45, 3.2});
    // S3, copy room: copier; S4, server room: a row of racks.
    plan.addFurniture(Box{9.55, 2.55, 10.35, 3.25});
    plan.addFurniture(Box{9.8, 0.0, 12.2, 0.6});
    // S5, meeting room: a 3 m x 1.2 m table.
    plan.addFurniture(Box{14.25, 1.9, 17.25, 3.1});
    // S6, kitchen: counter along the east wall, round table.
    plan.addFurniture(Box{23.4, 0.5, 24.0, 4.5});
    plan.addFurniture(Disc{{21.0, 2.2}, 0.5});
    // N1, N2, offices: desks and a cabinet.
    plan.addFurniture(Box{1.0, 12.2, 2.6, 13.0});
    plan.addFurniture(Box{0.0, 8.6, 0.45, 9.8});
    plan.addFurniture(Box{4.55, 10.5, 5.35, 12.1});
    // N3, lab: bench along the north wall and an island.
    plan.addFurniture(Box{9.0, 12.2, 13.5, 13.0});
    plan.addFurniture(Box{10.5, 9.6, 13.0, 10.4});
    // N4, open-plan office: two desk blocks and a cabinet.
    plan.addFurniture(Box{16.5, 9.5, 18.1, 11.1});
    plan.addFurniture(Box{19.6, 9.5, 21.2, 11.1});
    plan.addFurniture(Box{23.55, 11.0, 24.0, 12.5});
    return plan;
}

}  // namespace toposlam::simulation
