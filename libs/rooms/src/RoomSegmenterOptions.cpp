// RoomSegmenter's options: the paper preset, the .ini keys and their checks.
#include <toposlam/rooms/RoomSegmenter.h>

#include <mrpt/config/CConfigFileBase.h>
#include <toposlam/config/IniFile.h>

namespace toposlam::rooms {

RoomSegmenter::Options RoomSegmenter::Options::paperExact() {
    Options o;
    o.applyPaperPreset();
    return o;
}

void RoomSegmenter::Options::applyPaperPreset() {
    freeSpace.maxSpeckArea = 0;
    freeSpace.freeUnseenHoles = false;
    freeSpace.occupiedThreshold = 1;  // every non-free cell is a wall
    door.localDirection = false;
    filters.keepNarrowestOfGroup = false;
    filters.mergeSmallestFirst = false;
    filters.requireWallJambs = false;
    filters.requireWallEnd = false;
    filters.requireConstriction = false;
    filters.constrictionAtWaist = false;
    filters.rejectCorridorCuts = false;
    filters.wallEndNotOnAFace = false;
    filters.wallThicknessFromMap = false;
    filters.maxOpenBoundary = 1;
    wide.enabled = false;
    labelIslands = false;
    maxSliverArea = 0;
    maxFurnitureSize = 0;
    medialAxisWithTrajectory = false;
}

RoomSegmenter::Options RoomSegmenter::Options::load(const std::string& iniPath, bool paper) {
    Options o;
    if (!iniPath.empty()) {
        const auto ini = config::openIniFile(iniPath);  // InputError / ConfigError
        config::requireSection(*ini, "RoomSegmenter");
        o.loadFromConfigFile(*ini, "RoomSegmenter");
    }
    if (paper)
        o.applyPaperPreset();
    o.validate();
    return o;
}

void RoomSegmenter::Options::validate() const {
    config::Options::validate("RoomSegmenter");
}

void RoomSegmenter::Options::loadFromConfigFile(const mrpt::config::CConfigFileBase& ini,
                                                const std::string& section) {
    if (config::rawValue(ini, section, "variant") == "paper")
        applyPaperPreset();  // the keys of the section override it
    config::Options::loadFromConfigFile(ini, section);
}

void RoomSegmenter::Options::declare(config::OptionsSchema& s) {
    s.choice("variant", variant, {{"improved", Variant::Improved}, {"paper", Variant::Paper}},
             "improved: the defaults (paper + TopoSLAM's deviations); paper: every deviation "
             "off, before the keys below");
    // Step 1: binarisation.
    s.real("free_threshold", freeSpace.freeThreshold, "", "a cell is free when p(free) > this")
        .atLeast(0)
        .below(1);
    s.real("max_speck_area", freeSpace.maxSpeckArea, "m^2",
           "non-free specks up to this area inside free space count as free (0: paper)")
        .atLeast(0);
    s.flag("free_unseen_holes", freeSpace.freeUnseenHoles,
           "islands of unknown cells with no occupied cell inside free space are free: floor "
           "the laser did not reach (deviation)");
    s.real("occupied_threshold", freeSpace.occupiedThreshold, "",
           "a non-free cell is occupied when p(free) < this, else unknown (deviation)")
        .atLeast(0)
        .atMost(1);
    s.real("wall_hole_reach", freeSpace.wallHoleReach, "m",
           "unknown cells this close to an occupied cell are wall, farther ones no wall")
        .atLeast(0);
    // Step 2: wall segments and their merge.
    s.real("hough_angle_resolution_deg", hough.angleResolutionDeg, "deg",
           "Hough accumulator angle step")
        .above(0)
        .atMost(45);
    s.real("hough_min_votes_length", hough.minVotesLength, "m",
           "accumulator threshold as metres of wall voting for a line")
        .above(0);
    s.real("hough_min_line_length", hough.minLineLength, "m", "shortest wall segment kept")
        .above(0);
    s.real("hough_max_line_gap", hough.maxLineGap, "m", "largest gap bridged inside a segment")
        .atLeast(0);
    s.real("merge_max_angle_deg", lineMerge.maxAngleDeg, "deg",
           "delta_phi of the line merge and the main-direction voter")
        .above(0)
        .atMost(45);
    s.real("merge_max_distance", lineMerge.maxDistance, "m", "delta_d of the line merge")
        .atLeast(0);
    // Step 4: virtual doors.
    s.real("door_width", door.doorWidth, "m", "openings of door_width ...").above(0);
    s.real("door_width_tolerance", door.doorWidthTolerance, "m", "... +- this are doors").above(0);
    s.require([this] { return door.doorWidthTolerance < door.doorWidth; }, "door_width_tolerance",
              "must be below door_width");
    s.flag("local_direction", door.localDirection,
           "search doors across the local wall direction too (deviation)");
    // Step 5: filters.
    s.real("frame_distance", filters.frameDistance, "m",
           "doors closer than this to each other are one group")
        .atLeast(0);
    s.real("min_room_area", filters.minRoomArea, "m^2", "smaller regions are merged (N_s)")
        .atLeast(0);
    s.flag("keep_narrowest_of_group", filters.keepNarrowestOfGroup,
           "keep the narrowest door of a group (deviation)");
    s.flag("merge_smallest_first", filters.mergeSmallestFirst,
           "merge the smallest region first (deviation)");
    s.flag("require_wall_jambs", filters.requireWallJambs,
           "both ends of a door must be walls (deviation)");
    s.real("min_wall_extent", filters.minWallExtent, "m", "a jamb's wall extends this far")
        .above(0);
    s.flag("require_wall_end", filters.requireWallEnd,
           "one jamb must be the end of a wall (deviation)");
    s.real("max_wall_thickness", filters.maxWallThickness, "m", "thickest wall end").above(0);
    s.real("wall_end_probe", filters.wallEndProbe, "m", "probe length along the wall").above(0);
    s.real("edge_depth", filters.edgeDepth, "m",
           "a wall end free on one side only is the map's edge when nothing is free this deep "
           "behind it")
        .atLeast(0);
    s.real("max_pier_gap", filters.maxPierGap, "m",
           "a short piece of wall in a wall's line, with openings of at most this much to walls "
           "on both sides, is a pier of the building (0 = off)")
        .atLeast(0);
    s.real("hollow_wall_length", filters.hollowWallLength, "m",
           "a wall seen from both sides but not inside is as thick as its faces where it goes "
           "on so this long (0 = off)")
        .atLeast(0);
    s.flag(
        "reject_corridor_cuts", filters.rejectCorridorCuts,
        "no door with both jambs on walls going on to one side of it: a corridor's cross-section "
        "(deviation)");
    s.flag("wall_end_not_on_a_face", filters.wallEndNotOnAFace,
           "a jamb on the face of a wall running on to both sides of the door line is no wall end "
           "(deviation)");
    s.flag("wall_thickness_from_map", filters.wallThicknessFromMap,
           "wall ends as thick as the building's walls, measured on the map (deviation)");
    s.flag("require_constriction", filters.requireConstriction,
           "a door must be narrower than the space on both sides (deviation)");
    s.real("opening_margin", filters.openingMargin, "m", "by at least this").atLeast(0);
    s.flag("constriction_at_waist", filters.constrictionAtWaist,
           "a cut is dropped when a narrower cut of the same opening is no constriction "
           "(deviation)");
    s.real("max_open_boundary", filters.maxOpenBoundary, "",
           "a region whose boundary is more than this fraction open to the unobserved outside is "
           "merged (deviation; 1 = off)")
        .atLeast(0)
        .atMost(1);
    // Wide openings (deviation).
    s.flag("wide_openings", wide.enabled, "openings wider than a door may be room borders");
    s.real("max_opening_width", wide.maxWidth, "m", "widest such opening").above(0);
    s.flag("wide_local_direction", wide.localDirection,
           "search wide openings across the clearance ridge too (off: the main directions only)");
    s.real("wide_opening_margin", wide.openingMargin, "m", "the space behind must be wider by this")
        .atLeast(0);
    s.flag("label_islands", labelIslands,
           "free-standing furniture inside a room takes its label (deviation)");
    s.real("max_sliver_area", maxSliverArea, "m^2",
           "free pockets up to this size cut off from the free space join the one room they "
           "touch, or inside a wall the nearest room (deviation; 0 = off)")
        .atLeast(0);
    s.real("max_furniture_size", maxFurnitureSize, "m",
           "non-free pockets along a room's walls up to this long both ways (furniture) join the "
           "room (deviation; 0 = off)")
        .atLeast(0);
    s.flag("medial_axis_with_trajectory", medialAxisWithTrajectory,
           "with a trajectory, search the medial axis too (deviation)");
}

}  // namespace toposlam::rooms
