#pragma once
// Floor plans drawn with OpenCV for the rooms tests, with their exact ground truth: where the
// rooms and doors are. Images are 8-bit map images (row 0 = top, 0.05 m per pixel):
// 255 = free, 0 = occupied, 128 = unknown.
#include <toposlam/rooms/GridImageFrame.h>
#include <toposlam/rooms/TopologicalMap.h>

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPoint2D.h>

#include <opencv2/core/mat.hpp>

#include <vector>

namespace toposlam::rooms::test {

constexpr double kResolution = 0.05;  // m per pixel

struct DrawnDoor {
    mrpt::math::TPoint2D middle;  // m, world frame
    double width = 0;             // m, clear opening
};

struct DrawnMap {
    cv::Mat image;                            // 255 free, 0 occupied, 128 unknown
    std::vector<mrpt::math::TPoint2D> rooms;  // one point inside each room (m)
    std::vector<DrawnDoor> doors;
    std::vector<mrpt::math::TPoint2D> tour;  // a robot path through every door (m)
};

/// Intersection over union of label `labelA` of `a` and label `labelB` of `b` (CV_32S, same
/// size); 0 when neither has any pixel.
double labelIoU(const cv::Mat& a, int labelA, const cv::Mat& b, int labelB);
/// Distance (m) from `p` to the middle of the nearest door of `map` (1e9 without doors).
double distanceToNearestDoor(const TopologicalMap& map, const mrpt::math::TPoint2D& p);

/// The world frame of a drawn image: origin (0, 0) at the lower-left corner.
GridImageFrame frameOf(const cv::Mat& image);
/// p(free) = 1 for 255, 0 for 0, 0.5 for anything else.
mrpt::maps::COccupancyGridMap2D gridOf(const cv::Mat& image);

/// A 20 x 12 m office: a 2 m corridor across the middle, three rooms above it, two below, a
/// door between the two left upper rooms. 6 rooms, 6 doors (0.9-1.0 m). Walls 0.2 m.
DrawnMap office();
/// The office with furniture: tables, chairs, cabinets against walls, bins and plants, some of
/// them a door width away from walls or from each other.
DrawnMap furnishedOffice();
/// The office with sensor noise: isolated occupied specks in free space, free specks in the
/// unknown outside, ragged walls. `seed` for the random generator.
DrawnMap noisyOffice(unsigned seed);
/// `map` rotated by `degrees` about the image centre (the image grows to hold it all).
DrawnMap rotated(const DrawnMap& map, double degrees);
/// One 6 x 4 m room.
DrawnMap singleRoom();
/// A 13.2 x 8 m hall with a row of three 3.2 x 2.4 m cubicles along its top wall: 0.1 m
/// partitions with 0.6 m stubs at the front, so each cubicle opens to the hall through 2.0 m
/// framed by wall ends (wider than any door). 4 rooms, 3 openings.
DrawnMap cubicles();
/// cubicles() with 0.75 m stubs and posts 0.2 m back from the stubs' ends, the left one on the
/// cubicle's side, the right one on the hall's (as a SLAM grid draws ragged wall ends, or a
/// plant beside an opening): the middle of each 1.7 m opening lies 0.65 m from an obstacle,
/// nearer than half its width, and no straight cut between the posts is door-wide and framed by
/// walls. 4 rooms, 3 openings.
DrawnMap raggedCubicles();
/// A 2 m corridor below four rooms in a row, each entered through a double door in the
/// corridor's 0.1 m wall: clear openings 1.45, 1.5, 1.55 and 1.6 m, around the widest door
/// (1.6 m between the jamb cells' centres is the 1.55 m one). 5 rooms, 4 doors.
DrawnMap doubleDoors();
/// A 2 m corridor below two rooms, in its 0.1 m upper wall: into the left room a 1.8 m opening
/// and a 1.1 m door with a 0.45 m pier between them (too short to carry a wall segment), into
/// the right room a 1 m door. 3 rooms, 3 doors.
DrawnMap pierBetweenDoorways();
/// A 2.2 m corridor between three rooms above and three below, each entered through a 1 m door
/// beside a partition, the doors above and below opposite each other: the corridor's
/// cross-section there is 2.2 m, framed by wall corners, and no room border. 7 rooms, 6 doors.
DrawnMap corridorWithOppositeDoors();
/// An L-shaped 1.8 m corridor along the top and the left of two rooms, each entered by a 1 m
/// door from the top arm. At the bend the clearance ridge runs diagonally; a cut along it, from
/// the outer corner to the rooms' corner, is 2.7 m long: no room border. 3 rooms, 2 doors.
DrawnMap corridorBend();
/// A 1.4 m corridor leaving a hall between the outer wall and a wall stub: the stub (1 m) runs
/// from the corner of the hall's wall to a 1 m door into the room above the corridor. The cut
/// across the corridor's mouth has a wall end (the hall's wall) and opens on both sides (the
/// hall; the side door), but both its jambs are on walls running along the corridor: no door.
/// 2 rooms (hall with corridor, room), 1 door.
DrawnMap corridorOffAHall();
/// Two rooms either side of a 0.1 m partition with a 1 m door at its lower end. In the left
/// room a 0.5 m deep column stands against the partition's upper half, flush with its face (a
/// duct shaft). The right room is 2.4 m wide, and across from the column's lower end a 1.2 x
/// 0.8 m cabinet stands against its far wall: the 1.3 m cut from the partition's face to the
/// cabinet opens on both sides, and where the column ends the obstacle runs 0.6 m along the
/// cut with free space below it, as at a wall end. But that jamb lies on the partition's face,
/// which runs on above and below it: no door. 2 rooms, 1 door.
DrawnMap cabinetAcrossFromAColumnEnd();
/// A row of four 3.9 x 6 m rooms behind each other, parted by walls only 0.1 m (two cells)
/// thick, each with a 1 m door (in the middle, near the top, near the bottom). At an angle to
/// the grid such a wall is a two-cell staircase, and the cut between its two ends is a few
/// degrees off the wall. 4 rooms, 3 doors.
DrawnMap thinWalls();
/// A 16 x 8 m hall parted by a 0.15 m wall at 56 degrees to the others (a wing at an angle),
/// with a 1 m door in it: the wall is a staircase at any angle of the plan, and off both of the
/// building's main directions. 2 rooms, 1 door.
DrawnMap wallAtAnAngle();
/// A 6.1 x 4.7 m room parted by a 0.15 m wall from the left outer wall that ends 0.7 m short of
/// the right one, where a 0.2 m stub in its line stands out of the outer wall (as the B4-flats
/// generator draws a door at a wall's end). From the wall's end a cut runs to the stub and two
/// run diagonally to the outer wall's face, all three within a door's width. 2 rooms, 1 door.
DrawnMap doorAtAWallsEndBesideAnOuterWall();
/// Two 4.4 x 4 m rooms either side of a 0.55 m thick wall (as thick as B4's Freiburg52 walls)
/// with a 1 m door in it. 2 rooms, 1 door.
DrawnMap thickWall();
/// A `length` x 1.8 m corridor above a `length` x 3.4 m office, as a SLAM grid shows them: the
/// 1 m wall between them is two 0.1 m faces the laser saw with its unseen inside between (a
/// double wall, a duct), and a 1 m doorway goes through it 0.8 m from the left end (its sides
/// seen). 2 rooms, 1 door.
DrawnMap hollowWall(double length = 11);
/// A 14 x 8 m hall with a free-standing row of desks 0.7 m deep across the middle, 1 m apart:
/// the gaps are door-wide and framed by the desks' long edges (wall segments of step 2), but
/// the desks are deeper than any wall. One room, no door.
DrawnMap deskRow();
/// A 16 x 10 m open-plan hall: no walls inside, four pillars, desks; one room, no door.
DrawnMap openPlan();
/// An 8 x 6 m room as a SLAM grid shows it: a 0.8 m wall stub from the left wall and, 1 m to
/// its right, the unknown shadow of a table (1.2 m wide, from the table 1.6 m above the stub
/// down to the bottom wall, the laser never saw behind it). The gap between the stub's end and
/// the shadow is door-wide, the pocket below it 2.9 m^2; but the shadow is no wall: one room,
/// no door.
DrawnMap tableShadow();
/// An 8 x 6 m room as a SLAM grid shows it, with a 2.5 x 2.4 m closet (0.9 m door; the unseen
/// shadow of a table in its corner, a third of its boundary, enclosed by the walls the laser
/// saw) and, along the top wall, two cabinets of which
/// the laser saw the fronts only (their bodies and the wall behind them unknown, joined to the
/// unknown outside). Between them a pocket 1.2 m wide at its mouth, widening behind it where
/// the right cabinet's flank lies in a diagonal shadow: the cabinet fronts frame the mouth like
/// wall ends (with unknown behind, a face looks like the building's edge), but most of the
/// pocket's boundary was never observed. 2 rooms (the pocket belongs to the room), 1 door.
DrawnMap cabinetPocket();
/// A 2.2 m corridor (walls 0.2 m) with three 4.2 x 4 m offices along one side, as a SLAM grid
/// shows them when the robot only drove along the corridor: the laser saw each office through
/// its 1 m door, so the office's two corners beside the door, and the inner face of the wall
/// the door is in there, stayed unknown (wedges from the door's jambs up the side walls), and
/// between the beams fanning in through the door broken one-cell streaks stayed unknown.
/// 4 rooms, 3 doors.
DrawnMap officesSeenThroughTheirDoors();
/// A 40 x 20 m ring corridor (2.2 m wide, walls 0.2 m) with four 4 x 5 m offices (1 m doors)
/// inside the ring along each long side; everything else solid. The tour is the loop along the
/// corridor's centre line, corner to corner, starting and ending at (9, 3.1): a robot driving
/// it maps the offices only through their doors. 9 rooms, 8 doors.
DrawnMap corridorRing();

}  // namespace toposlam::rooms::test
