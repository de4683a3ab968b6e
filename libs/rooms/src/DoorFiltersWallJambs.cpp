// The wall-jamb test of the door filters (DoorFilters.h): both jambs on the building's walls,
// one of them the end of the wall the door is in.
#include <toposlam/rooms/DoorFilters.h>

#include "GridRay.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace toposlam::rooms {

namespace {

// m across a wall within which a jamb still counts as on it (onWall in DoorFilters::wallJambs).
constexpr double kOnWallSlack = 0.1;

// m: the shortest wall segment from which piers are searched (markPiers): longer than
// furniture (RoomSegmenter's maxFurnitureSize), whose edges carry segments too.
constexpr double kPierWallLength = 2.0;

// m between the probes along a hollow wall (DoorFilters::Options::hollowWallLength).
constexpr double kHollowProbeStep = 0.25;

// Length (pixels, capped at `cap`) of the obstacle that starts at `jamb` in direction (ux, uy).
// A free cell ends it only when its neighbours across the walking direction, up to `slack`
// cells to either side, are free too: a thin wall drawn as a digital line at an angle is
// followed to its end instead of being left through the steps of its staircase.
double wallRun(const cv::Mat& free, const cv::Point& jamb, double ux, double uy, double cap,
               int slack = 1) {
    const cv::Point side(cvRound(-uy), cvRound(ux));
    cv::Point hit;
    // The ray's cells lie within cap + 1 of the jamb, the cells beside them `slack` more.
    const bool ended = detail::withMaskReader(free, jamb, cap + 1 + slack, [&](const auto& isFree) {
        auto open = [&](int x, int y) {
            if (!isFree(x, y))
                return false;
            for (int k = 1; k <= slack; ++k) {
                if (!isFree(x + k * side.x, y + k * side.y) ||
                    !isFree(x - k * side.x, y - k * side.y))
                    return false;
            }
            return true;
        };
        return detail::walkRay(jamb, ux, uy, cap, open, hit);
    });
    if (!ended)
        return cap;
    return detail::cellDistance(hit.x - jamb.x, hit.y - jamb.y);
}

// Distance from the origin to the segment from a to b.
double pointSegmentDistance(const cv::Point2d& a, const cv::Point2d& b) {
    const cv::Point2d ab = b - a;
    const double t = std::clamp(-a.dot(ab) / std::max(1e-12, ab.dot(ab)), 0.0, 1.0);
    const cv::Point2d closest = a + t * ab;
    return std::hypot(closest.x, closest.y);
}

// A wall segment runs across a door line when it is within 20 degrees of the line's normal,
// and passes through a jamb when within a quarter metre of it: the staircase of a wall at an
// angle, and the corner where the cut lands a few cells along the other wall.
const double kAcross = std::cos(20 * M_PI / 180);
constexpr double kOnWallMetres = 0.25;

/// The wall segments near a point: each segment is listed in every bucket (square, at least
/// twice `radius` cells wide) within `radius` of it, so the segments within `radius` of a point
/// are among those listed in the point's bucket.
class SegmentsNear {
  public:
    SegmentsNear(const std::vector<LineSegment>& walls, cv::Size image, double radius)
        : size_(std::max(8, static_cast<int>(std::ceil(2 * radius)))),
          cols_(image.width / size_ + 1),
          rows_(image.height / size_ + 1),
          buckets_(static_cast<std::size_t>(cols_ * rows_)) {
        // Sampled every half bucket; each sample marks the buckets within radius plus half a
        // bucket of it, which covers the segment between samples.
        const double reach = radius + 0.5 * size_;
        for (std::size_t i = 0; i < walls.size(); ++i) {
            const LineSegment& w = walls[i];
            const int samples = 1 + static_cast<int>(std::ceil(w.length() / (0.5 * size_)));
            for (int k = 0; k <= samples; ++k) {
                const cv::Point2f p =
                    w.start + (w.end - w.start) * (static_cast<float>(k) / samples);
                for (int by = bucketOf(p.y - reach, rows_); by <= bucketOf(p.y + reach, rows_);
                     ++by) {
                    for (int bx = bucketOf(p.x - reach, cols_); bx <= bucketOf(p.x + reach, cols_);
                         ++bx) {
                        auto& bucket = buckets_[static_cast<std::size_t>(by * cols_ + bx)];
                        if (bucket.empty() || bucket.back() != i)
                            bucket.push_back(i);
                    }
                }
            }
        }
    }
    /// Indices of the segments that may pass within the radius of p.
    const std::vector<std::size_t>& at(const cv::Point& p) const {
        return buckets_[static_cast<std::size_t>(bucketOf(p.y, rows_) * cols_ +
                                                 bucketOf(p.x, cols_))];
    }

  private:
    int bucketOf(double v, int count) const {
        return std::clamp(static_cast<int>(std::floor(v / size_)), 0, count - 1);
    }
    int size_, cols_, rows_;
    std::vector<std::vector<std::size_t>> buckets_;
};

/// Per obstacle label (FreeSpace::obstacles): whether it belongs to the building, and whether
/// it does as a pier (see markPiers).
struct BuildingStructure {
    std::vector<bool> structure, pier;
};

/// Those obstacles that reach the border of the map (the outer walls and everything joined to
/// them) and those that carry a wall segment belong to the building; the others are
/// free-standing things: furniture, bins, plants.
std::vector<bool> structureOf(const FreeSpace& space, const std::vector<LineSegment>& walls) {
    std::vector<bool> structure(space.obstacleOnBorder.begin(), space.obstacleOnBorder.end());
    for (const LineSegment& w : walls) {
        cv::LineIterator it(space.obstacles, cv::Point(cvRound(w.start.x), cvRound(w.start.y)),
                            cv::Point(cvRound(w.end.x), cvRound(w.end.y)), 8);
        for (int k = 0; k < it.count; ++k, ++it)
            structure[static_cast<std::size_t>(space.obstacles.at<int>(it.pos()))] = true;
    }
    structure[0] = false;  // label 0: free cells
    return structure;
}

/// Marks the piers: a piece of wall between two openings, too short to carry a wall segment
/// of its own (0.45 m between a 1.8 m and a 1.1 m doorway). Walking on from the end of a wall
/// segment (kPierWallLength or longer) along its line, across the openings (at most `maxGap` cells
/// each), the first obstacle met lies within the wall's band (the cells across the wall where the
/// segment ends, a cell and a half of slack) and the next one beyond it belongs to the building:
/// wall, gap, piece, gap, wall, all on one line, the piece no thicker than the wall and longer than
/// thick. The wall is an inner one (free on both sides) as thick as the building's walls
/// (`measured`, if given). Furniture stands against walls (then it joins them) or in the rooms,
/// seldom exactly in a wall's line with the wall's thickness.
void markPiers(const FreeSpace& space, const cv::Mat& open, const std::vector<LineSegment>& walls,
               double maxGap, double maxThickness, const WallThickness* measured,
               BuildingStructure& building) {
    if (maxGap <= 0 || space.islandRuns.empty())
        return;
    auto labelAt = [&](const cv::Point2d& p) {
        const int x = cvRound(p.x), y = cvRound(p.y);
        if (x < 0 || y < 0 || x >= open.cols || y >= open.rows || detail::isSet(open, x, y))
            return 0;
        return space.obstacles.at<int>(y, x);
    };
    auto freeAt = [&](const cv::Point2d& p) {
        const int x = cvRound(p.x), y = cvRound(p.y);
        return detail::isSet(space.free, x, y) ||
               (!space.otherFree.empty() && detail::isSet(space.otherFree, x, y));
    };
    // Cells of slack across the band (a wall at an angle to the grid is a staircase), and per
    // cell along the line (a Hough segment's direction may be a degree or two off its wall's).
    constexpr double kSlack = 1.5;
    // Cells a wall may go on past the end of its segment.
    constexpr double kPastSegmentEnd = 6;
    const double driftPerCell = std::tan(2.5 * M_PI / 180);
    const double minSpan = detail::toCells(kPierWallLength, space.frame.resolution);
    for (const LineSegment& w : walls) {
        const double span = w.length();
        if (span < minSpan)
            continue;
        const cv::Point2d d((w.end.x - w.start.x) / span, (w.end.y - w.start.y) / span);
        const cv::Point2d n(-d.y, d.x);
        for (const bool atEnd : {false, true}) {
            const cv::Point2d e = atEnd ? cv::Point2d(w.end) : cv::Point2d(w.start);
            const cv::Point2d out = atEnd ? d : -d;
            // The wall's band across its line, two cells or more in from the segment's end (a
            // segment may reach a few cells past its wall's end at an angle to the grid).
            cv::Point2d q = e;
            int wall = 0;
            for (double in = 2; in <= 6 && wall == 0; ++in) {
                q = e - in * out;
                wall = labelAt(q);
            }
            if (wall == 0 || !building.structure[static_cast<std::size_t>(wall)])
                continue;
            double lo = 0, hi = 0;
            while (lo > -maxThickness && labelAt(q + (lo - 1) * n) != 0)
                --lo;
            while (hi < maxThickness && labelAt(q + (hi + 1) * n) != 0)
                ++hi;
            // An inner wall: free space on both sides (an outer wall has the unknown outside
            // beyond it, furniture against it makes it thicker than any wall).
            if (!freeAt(q + (lo - 1) * n) || !freeAt(q + (hi + 1) * n) ||
                (measured != nullptr && !measured->isWallThickness(hi - lo + 1)))
                continue;
            // The first obstacle across the band `at` cells out from the segment's end (0: none).
            auto acrossBand = [&](double at, int skip) {
                const double drift = std::floor(at * driftPerCell);
                for (double o = lo - drift; o <= hi + drift; o += 1) {
                    const int label = labelAt(e + at * out + o * n);
                    if (label != 0 && label != skip)
                        return label;
                }
                return 0;
            };
            // The first obstacle other than `skip` from `from` on, within `reach`; `at` where.
            auto firstInBand = [&](double from, double reach, int skip, double& at) {
                for (at = from; at <= from + reach; at += 0.5) {
                    if (const int label = acrossBand(at, skip))
                        return label;
                }
                return 0;
            };
            // Past the wall's end (the segment may stop a few cells short of it; where the wall
            // goes on farther, another segment carries it), the first obstacle across the
            // opening.
            double at = 0.5;
            while (at <= kPastSegmentEnd && acrossBand(at, 0) != 0)
                at += 0.5;
            if (at > kPastSegmentEnd)
                continue;
            const int piece = firstInBand(at, maxGap, 0, at);
            if (piece == 0 || building.structure[static_cast<std::size_t>(piece)])
                continue;  // the wall goes on, or the opening is wider than maxGap
            // The piece within the band, no thicker than the wall, and how far along the line
            // it reaches.
            double farthest = at, nearSide = hi, farSide = lo;
            bool inBand = true;
            for (const ConnectedRuns::Run& run : space.islandRuns) {
                if (run.label != piece)
                    continue;  // a few pieces per map: a scan, not an index
                for (int x = run.begin; x < run.end && inBand; ++x) {
                    const cv::Point2d c(x - e.x, run.row - e.y);
                    const double across = c.dot(n), slack = kSlack + c.dot(out) * driftPerCell;
                    inBand = across >= lo - slack && across <= hi + slack;
                    nearSide = std::min(nearSide, across);
                    farSide = std::max(farSide, across);
                    farthest = std::max(farthest, c.dot(out));
                }
            }
            // No thicker than the wall, and longer along its line than thick: a piece of wall,
            // not a post, a chair or a bin that happens to stand in the wall's line.
            const double thick = farSide - nearSide;
            if (!inBand || thick > hi - lo + 2 * kSlack || farthest - at <= thick)
                continue;
            double beyond = 0;
            const int next = firstInBand(farthest + 1, maxGap, piece, beyond);
            if (next != 0 && building.structure[static_cast<std::size_t>(next)]) {
                building.structure[static_cast<std::size_t>(piece)] = true;
                building.pier[static_cast<std::size_t>(piece)] = true;
            }
        }
    }
}

}  // namespace

std::vector<VirtualDoor> DoorFilters::wallJambs(const FreeSpace& space,
                                                std::vector<VirtualDoor> doors,
                                                const std::vector<LineSegment>& walls,
                                                const WallThickness* wallThickness) const {
    if (!options_.requireWallJambs || doors.empty())
        return doors;
    const double extent = detail::toCells(options_.minWallExtent, space.frame.resolution);
    const cv::Mat& obstacleLabels = space.obstacles;
    // Where no wall can be: free cells, and on SLAM grids also the unknown cells away from
    // every occupied cell (FreeSpace::noWall): a shadow behind a table is no jamb and no wall.
    const cv::Mat& open = space.noWall.empty() ? space.free : space.noWall;
    const double thickness = detail::toCells(options_.maxWallThickness, space.frame.resolution);
    BuildingStructure building{structureOf(space, walls), {}};
    building.pier.assign(building.structure.size(), false);
    const WallThickness* measured = options_.wallThicknessFromMap ? wallThickness : nullptr;
    markPiers(space, open, walls, detail::toCells(options_.maxPierGap, space.frame.resolution),
              thickness, measured, building);
    const std::vector<bool>& structure = building.structure;
    auto inside = [&](const cv::Point& jamb) {
        return jamb.x >= 0 && jamb.y >= 0 && jamb.x < obstacleLabels.cols &&
               jamb.y < obstacleLabels.rows;
    };
    auto labelOf = [&](const cv::Point& jamb) {
        return inside(jamb) ? static_cast<std::size_t>(obstacleLabels.at<int>(jamb)) : 0;
    };
    auto onStructure = [&](const cv::Point& jamb) {
        return !inside(jamb) || (structure[labelOf(jamb)] && !detail::isSet(open, jamb.x, jamb.y));
    };
    // Along the door line (both ways: one leads back into the opening and stops at once) and
    // across it, with kOnWallSlack of slack (two cells of 5 cm; as many cells as make 0.1 m on
    // finer grids, where the same offset is more cells): where a wall runs a few degrees off the
    // door line (at an angle to the building's main directions, the two wall ends of a doorway
    // lie a cell or two apart across the wall), a jamb on its face is left after a few cells with
    // one. The wall-end test and the walls across the door line keep one cell: with two there as
    // well, B4-gen's furnished plans at 30 degrees gained two false doors (one from a shelf drawn
    // at an angle that passed for the end of a wall).
    const int onWallSlack = std::max(
        2, static_cast<int>(std::lround(detail::toCells(kOnWallSlack, space.frame.resolution))));
    auto onWall = [&](const cv::Point& jamb, double ux, double uy) {
        return wallRun(open, jamb, ux, uy, extent, onWallSlack) >= extent ||
               wallRun(open, jamb, -ux, -uy, extent, onWallSlack) >= extent ||
               wallRun(open, jamb, -uy, ux, extent, onWallSlack) >= extent ||
               wallRun(open, jamb, uy, -ux, extent, onWallSlack) >= extent;
    };
    // The wall the door is in: from the jamb, away from the opening, the obstacle goes on for
    // wallEndProbe (past the corner of the jamb), and there it is a wall: free space on both
    // sides of it at most maxWallThickness apart (an inner wall; not a desk), or on one side
    // only with nothing free within edgeDepth on the other (the edge of the mapped space, not a
    // bed or a sofa against an inner wall, with the next room behind it). A wall across the door
    // line walked through instead runs on to both sides there: no wall end.
    const double edgeDepth =
        std::max(2 * thickness, detail::toCells(options_.edgeDepth, space.frame.resolution));
    const double length =
        std::max(extent, detail::toCells(options_.wallEndProbe, space.frame.resolution));
    auto toFree = [&](const cv::Point& from, double ux, double uy, double reach) {
        cv::Point hit;
        const bool found = detail::withMaskReader(
            space.free, from, reach + 1,
            [&](const auto& isFree) { return detail::walkRay(from, ux, uy, reach, isFree, hit); });
        return found ? detail::cellDistance(hit.x - from.x, hit.y - from.y) : 1e9;
    };
    // SLAM grids: a wall the laser saw from both sides but not inside. Its faces are occupied
    // cells with unknown runs of at most 2 x wallHoleReach between them (holes where the laser
    // grazed a face); a longer unknown run between two faces is its unseen inside.
    const double hollowGap = 2 * detail::toCells(space.wallHoleReach, space.frame.resolution);
    const bool hollowWalls = options_.hollowWallLength > 0 && hollowGap > 0;
    // Cells of the faces on the ray from `from` (itself included) to the first free cell.
    auto faceCells = [&](const cv::Point& from, double ux, double uy, double reach) {
        int faces = 0, gap = 0;
        auto take = [&](int x, int y) {
            if (detail::isSet(space.free, x, y))
                return true;
            if (detail::isSet(space.unknown, x, y)) {
                ++gap;
            } else {
                faces += 1 + (gap <= hollowGap ? gap : 0);
                gap = 0;
            }
            return false;
        };
        take(from.x, from.y);
        cv::Point hit;
        detail::walkRay(from, ux, uy, reach, take, hit);
        return faces + (gap <= hollowGap ? gap : 0);
    };
    // At `probe`, across (ux, uy), free `a` and `b` cells away (toFree): free on both sides
    // within twice the thickest wall, with an unseen inside between faces together no thicker
    // than the thickest wall.
    auto hollowAcross = [&](const cv::Point& probe, double ux, double uy, double a, double b) {
        if (a > 2 * thickness || b > 2 * thickness)
            return false;
        const int faces =
            faceCells(probe, -uy, ux, 2 * thickness) + faceCells(probe, uy, -ux, 2 * thickness) - 1;
        return faces < a + b - 1 && faces <= thickness;
    };
    // From the jamb along (ux, uy), the obstacle goes on as a hollow wall for hollowWallLength:
    // longer than furniture, whose unseen inside looks the same from its front. Probed every
    // kHollowProbeStep; a fifth of the probes may land where another wall joins it.
    const double hollowLength = detail::toCells(options_.hollowWallLength, space.frame.resolution);
    const double hollowStep =
        std::max(1.0, detail::toCells(kHollowProbeStep, space.frame.resolution));
    // The depth (cells) of the hollow walls the current door's jambs end: its doorway's sides
    // are as long.
    double hollowDepth = 0;
    auto hollowAlong = [&](const cv::Point& jamb, double ux, double uy, double from) {
        if (wallRun(open, jamb, ux, uy, hollowLength) < hollowLength)
            return false;
        int probes = 0, hollow = 0;
        for (double at = from; at <= hollowLength; at += hollowStep, ++probes) {
            const cv::Point p(cvRound(jamb.x + ux * at), cvRound(jamb.y + uy * at));
            if (!detail::isSet(open, p.x, p.y) &&
                hollowAcross(p, ux, uy, toFree(p, -uy, ux, 2 * thickness),
                             toFree(p, uy, -ux, 2 * thickness))) {
                ++hollow;
            }
        }
        return 5 * hollow >= 4 * probes;
    };
    // At `at` cells from the jamb along (ux, uy), inside the obstacle, the obstacle is a wall
    // along that line: free on both sides of it at most `thickness` apart, as thick as the
    // building's walls (or free on one side only: the edge of the mapped space).
    auto wallAcross = [&](const cv::Point& jamb, double ux, double uy, double at) {
        const cv::Point probe(cvRound(jamb.x + ux * at), cvRound(jamb.y + uy * at));
        if (detail::isSet(open, probe.x, probe.y))
            return false;  // the run went on through a gap in a wall at an angle, not along it
        const double a = toFree(probe, -uy, ux, 2 * thickness),
                     b = toFree(probe, uy, -ux, 2 * thickness);
        if (a <= thickness && b <= thickness) {
            // a + b - 1 obstacle cells across: as thick as the building's walls?
            return a + b <= thickness + 1.0 &&
                   (measured == nullptr || measured->isWallThickness(a + b - 1.0));
        }
        if (hollowWalls) {
            // Seen from both sides but not inside: as thick as its faces, if it goes on so. Two
            // skins need not be as thick as the building's walls (and at an angle to the grid
            // their staircases measure a cell or two more): no WallThickness check here.
            if (hollowAcross(probe, ux, uy, a, b) && hollowAlong(jamb, ux, uy, at)) {
                hollowDepth = std::max(hollowDepth, a + b - 1);
                return true;
            }
        }
        if (!(std::min(a, b) <= thickness && std::max(a, b) > 2 * thickness))
            return false;
        return edgeDepth <= 2 * thickness ||
               (a > b ? toFree(probe, -uy, ux, edgeDepth) : toFree(probe, uy, -ux, edgeDepth)) >
                   edgeDepth;
    };
    // Probed a third of the way in, past the corner of the jamb: where the wall the door is in
    // goes on (a wall stub beside a corner door meets the other wall farther on). Probing at
    // the end of the run instead took a line that crosses a cabinet and the wall behind it for
    // a wall end: there it reaches the wall's face, where a wall at an angle to the grid
    // measures a cell or two across along its staircase.
    // The depth is counted in whole steps of WallThickness::kThicknessStep (a cell on coarser
    // grids): a third of wallEndProbe is 0.2 m on a 5 cm grid, and on a finer one a third
    // rounded to its own cells fell short of the corner of a jamb that the 5 cm grid probes past.
    const double stepCells =
        std::max(1.0, detail::toCells(WallThickness::kThicknessStep, space.frame.resolution));
    const double probeDepth = std::round(std::round(length / 3 / stepCells) * stepCells);
    // A pier (markPiers) ends its wall at both of its ends, however short: at least
    // minWallExtent, as every jamb's wall.
    auto wallEnd = [&](const cv::Point& jamb, double ux, double uy) {
        const double run = wallRun(open, jamb, ux, uy, length);
        return (run >= length || (building.pier[labelOf(jamb)] && run >= extent)) &&
               wallAcross(jamb, ux, uy, probeDepth);
    };
    // The sides of the door line (bit 0: (-uy, ux), bit 1: the other) to which a wall goes on
    // from the jamb across the door line.
    auto wallsAcross = [&](const cv::Point& jamb, double ux, double uy, double reach) {
        return (wallRun(open, jamb, -uy, ux, reach) >= reach ? 1 : 0) |
               (wallRun(open, jamb, uy, -ux, reach) >= reach ? 2 : 0);
    };
    // The same from the wall segments of step 2 that pass through the jamb: at an angle to
    // the grid a cut ends anywhere on a wall's staircase, where walking the wall cell by cell
    // is cut short.
    const double throughJamb = detail::toCells(kOnWallMetres, space.frame.resolution);
    const SegmentsNear nearJamb(walls, space.free.size(), throughJamb);
    auto segmentsAcross = [&](const cv::Point& jamb, double ux, double uy, double reach) {
        const cv::Point2d n(-uy, ux);  // bit 0 side
        int sides = 0;
        for (const std::size_t i : nearJamb.at(jamb)) {
            const LineSegment& w = walls[i];
            const cv::Point2d a(w.start.x - jamb.x, w.start.y - jamb.y);
            const cv::Point2d b(w.end.x - jamb.x, w.end.y - jamb.y);
            const double span = w.length();
            if (span < 1 || std::abs((b - a).dot(n)) < kAcross * span ||
                pointSegmentDistance(a, b) > throughJamb) {
                continue;
            }
            sides |= (std::max(a.dot(n), b.dot(n)) >= reach ? 1 : 0) |
                     (std::min(a.dot(n), b.dot(n)) <= -reach ? 2 : 0);
        }
        return sides;
    };
    auto sidesOf = [&](const cv::Point& jamb, double ux, double uy, double reach) {
        return wallsAcross(jamb, ux, uy, reach) | segmentsAcross(jamb, ux, uy, reach);
    };
    // A wall end that lies on the face of a wall running on to both sides of the door line
    // (seen edge-on, or a T-junction) bounds the space the cut crosses; it frames no doorway.
    auto endsItsWall = [&](const cv::Point& jamb, double ux, double uy) {
        return wallEnd(jamb, ux, uy) &&
               !(options_.wallEndNotOnAFace && sidesOf(jamb, ux, uy, length) == 3);
    };
    // Both jambs framed by wall ends: neither in the middle of a wall that runs across the door
    // line, and the two not on walls that go on to the same side (the two side walls of a
    // corridor, with the cut across it).
    auto framed = [&](const VirtualDoor& d, double ux, double uy) {
        const int a = sidesOf(d.jambA, ux, uy, length), b = sidesOf(d.jambB, ux, uy, length);
        return a != 3 && b != 3 && (a & b) == 0;
    };
    // Both jambs on walls that go on, beyond any wall's thickness (or that of the hollow wall
    // the door is in), to one side of the door line: the cut runs across a corridor between its
    // side walls (next to a side door, whose wall end makes the wall-end test pass), not
    // through a wall.
    auto acrossCorridor = [&](const VirtualDoor& d, double ux, double uy) {
        const double corridorWall = std::max(thickness, hollowDepth) + 2;
        return (sidesOf(d.jambA, ux, uy, corridorWall) & sidesOf(d.jambB, ux, uy, corridorWall)) !=
               0;
    };
    doors.erase(std::remove_if(doors.begin(), doors.end(),
                               [&](const VirtualDoor& d) {
                                   const double ux = (d.jambB.x - d.jambA.x) / d.width;
                                   const double uy = (d.jambB.y - d.jambA.y) / d.width;
                                   if (!onStructure(d.jambA) || !onStructure(d.jambB) ||
                                       !onWall(d.jambA, ux, uy) || !onWall(d.jambB, ux, uy)) {
                                       return true;
                                   }
                                   if (!options_.requireWallEnd)
                                       return false;
                                   hollowDepth = 0;
                                   const bool endA = endsItsWall(d.jambA, -ux, -uy);
                                   const bool endB = endsItsWall(d.jambB, ux, uy);
                                   if (!options_.requireBothWallEnds) {
                                       return !(endA || endB) || (options_.rejectCorridorCuts &&
                                                                  acrossCorridor(d, ux, uy));
                                   }
                                   return !endA || !endB || !framed(d, ux, uy);
                               }),
                doors.end());
    return doors;
}

}  // namespace toposlam::rooms
