#include <toposlam/rooms/DoorFilters.h>

#include "GridRay.h"

#include <boost/pending/disjoint_sets.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace toposlam::rooms {

namespace {

// Union-find over 0..n-1 (union by rank, path compression).
using DisjointSets = boost::disjoint_sets_with_storage<>;

// m across a wall within which a jamb still counts as on it (onWall in DoorFilters::wallJambs).
constexpr double kOnWallSlack = 0.1;

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

// Whether the free space across direction (ux, uy) through the cell `at` is wider than `cap`
// pixels (from the non-free cell on one side to the one on the other; none within cap on a
// side: wider).
bool wider(const cv::Mat& free, const cv::Point& at, double ux, double uy, double cap) {
    cv::Point a, b;
    const bool bounded = detail::withMaskReader(free, at, cap + 1, [&](const auto& isFree) {
        auto blocked = [&](int x, int y) { return !isFree(x, y); };
        // Beyond farSideReach the other side is wider than cap anyway.
        return detail::walkRay(at, ux, uy, cap, blocked, a) &&
               detail::walkRay(at, -ux, -uy,
                               std::min(cap, detail::farSideReach(at, a, ux, uy, cap)), blocked, b);
    });
    return !bounded || detail::cellDistance(a.x - b.x, a.y - b.y) > cap;
}

// Whether two cuts fan out from one jamb (their other ends apart): two cross-sections of one
// opening, measured from the same jamb cell to different far cells. Cut as two 8-connected
// lines that diverge at a small angle, they touch the rooms on both sides of each other, so
// keeping both would join the rooms when the filters drop one.
bool fanFromOneJamb(const VirtualDoor& a, const VirtualDoor& b) {
    auto near = [](const cv::Point& p, const cv::Point& q) {
        return std::abs(p.x - q.x) <= 1 && std::abs(p.y - q.y) <= 1;
    };
    const cv::Point2d da = cv::Point2d(a.jambB - a.jambA) * (1.0 / a.width);
    const cv::Point2d db = cv::Point2d(b.jambB - b.jambA) * (1.0 / b.width);
    const bool shared = near(a.jambA, b.jambA) || near(a.jambB, b.jambB) ||
                        near(a.jambA, b.jambB) || near(a.jambB, b.jambA);
    return shared && std::abs(da.x * db.x + da.y * db.y) > std::cos(M_PI / 6);  // < 30 deg
}

double jambDistance(const VirtualDoor& a, const VirtualDoor& b) {
    auto d = [](const cv::Point& p, const cv::Point& q) {
        return detail::cellDistance(p.x - q.x, p.y - q.y);
    };
    return std::min(std::max(d(a.jambA, b.jambA), d(a.jambB, b.jambB)),
                    std::max(d(a.jambA, b.jambB), d(a.jambB, b.jambA)));
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

/// Doors bucketed by the midpoints of their jambs on a grid of `size` cells: doors whose jambs
/// are within `size` of each other's have midpoints within `size`, so only the neighbouring
/// buckets need comparing.
class MidpointBuckets {
  public:
    explicit MidpointBuckets(double size) : size_(std::max(1.0, size)) {}
    void add(const VirtualDoor& d, std::size_t index) {
        const cv::Point b = bucketOf(d);
        grid_[keyOf(b.x, b.y)].push_back(index);
    }
    /// Calls f(index) for every door added in the 3 x 3 buckets around d's.
    template <class F>
    void forNeighbours(const VirtualDoor& d, F&& f) const {
        const cv::Point b = bucketOf(d);
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                auto it = grid_.find(keyOf(b.x + dx, b.y + dy));
                if (it == grid_.end())
                    continue;
                for (std::size_t j : it->second)
                    f(j);
            }
        }
    }

  private:
    // Buckets left of or above the image are negative: shifted as unsigned (a negative value
    // shifted left is undefined).
    static long long keyOf(int bx, int by) {
        return static_cast<long long>(
            (static_cast<unsigned long long>(static_cast<unsigned>(bx)) << 32) |
            static_cast<unsigned>(by));
    }
    cv::Point bucketOf(const VirtualDoor& d) const {
        const cv::Point2d m = 0.5 * (cv::Point2d(d.jambA) + cv::Point2d(d.jambB));
        return cv::Point(static_cast<int>(std::floor(m.x / size_)),
                         static_cast<int>(std::floor(m.y / size_)));
    }
    double size_;
    std::unordered_map<long long, std::vector<std::size_t>> grid_;
};

/// Per obstacle label (FreeSpace::obstacles): whether it belongs to the building. Those that
/// reach the border of the map (the outer walls and everything joined to them) and those that
/// carry a wall segment do; the others are free-standing things: furniture, bins, plants.
std::vector<bool> buildingStructure(const FreeSpace& space, const std::vector<LineSegment>& walls) {
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

}  // namespace

std::vector<VirtualDoor> DoorFilters::wallJambs(const FreeSpace& space,
                                                std::vector<VirtualDoor> doors,
                                                const std::vector<LineSegment>& walls,
                                                const WallThickness* wallThickness) const {
    if (!options_.requireWallJambs || doors.empty())
        return doors;
    const double extent = detail::toCells(options_.minWallExtent, space.frame.resolution);
    const cv::Mat& obstacleLabels = space.obstacles;
    const std::vector<bool> structure = buildingStructure(space, walls);
    // Where no wall can be: free cells, and on SLAM grids also the unknown cells away from
    // every occupied cell (FreeSpace::noWall): a shadow behind a table is no jamb and no wall.
    const cv::Mat& open = space.noWall.empty() ? space.free : space.noWall;
    auto onStructure = [&](const cv::Point& jamb) {
        const bool inside = jamb.x >= 0 && jamb.y >= 0 && jamb.x < obstacleLabels.cols &&
                            jamb.y < obstacleLabels.rows;
        return !inside || (structure[static_cast<std::size_t>(obstacleLabels.at<int>(jamb))] &&
                           !detail::isSet(open, jamb.x, jamb.y));
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
    const double thickness = detail::toCells(options_.maxWallThickness, space.frame.resolution);
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
    const WallThickness* measured = options_.wallThicknessFromMap ? wallThickness : nullptr;
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
    auto wallEnd = [&](const cv::Point& jamb, double ux, double uy) {
        return wallRun(open, jamb, ux, uy, length) >= length &&
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
    // Both jambs on walls that go on, beyond any wall's thickness, to one side of the door line:
    // the cut runs across a corridor between its side walls (next to a side door, whose wall
    // end makes the wall-end test pass), not through a wall.
    const double corridorWall = thickness + 2;
    auto acrossCorridor = [&](const VirtualDoor& d, double ux, double uy) {
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

std::vector<VirtualDoor> DoorFilters::constriction(const FreeSpace& space,
                                                   std::vector<VirtualDoor> doors,
                                                   double probeDistance) const {
    if (!options_.requireConstriction)
        return doors;
    const double margin = detail::toCells(options_.openingMargin, space.frame.resolution);
    const int steps = std::max(
        1, static_cast<int>(std::ceil(detail::toCells(probeDistance, space.frame.resolution))));
    auto opensOnSide = [&](const VirtualDoor& d, double side) {
        const double ux = (d.jambB.x - d.jambA.x) / d.width;
        const double uy = (d.jambB.y - d.jambA.y) / d.width;
        const cv::Point2d centre = 0.5 * (cv::Point2d(d.jambA) + cv::Point2d(d.jambB));
        const double opened = d.width + margin;
        for (int k = 1; k <= steps; ++k) {
            const cv::Point q(cvRound(centre.x - side * k * uy), cvRound(centre.y + side * k * ux));
            if (!detail::isSet(space.free, q.x, q.y))
                return false;  // a wall before it opened
            if (wider(space.free, q, ux, uy, opened))
                return true;
        }
        return false;
    };
    std::vector<std::uint8_t> opens(doors.size());
    for (std::size_t i = 0; i < doors.size(); ++i)
        opens[i] = opensOnSide(doors[i], 1.0) && opensOnSide(doors[i], -1.0);
    if (options_.constrictionAtWaist) {
        // A cut that opens is dropped when a narrower cut of the same opening (jambs within
        // frameDistance) does not: the opening is judged at its waist. An oblique cut across a
        // corridor is longer than the corridor is wide, and its probes, drifting along the
        // corridor, can reach a side door and find it "wider"; the straight cut does not.
        const double nd = detail::toCells(options_.frameDistance, space.frame.resolution);
        MidpointBuckets closed(nd);
        for (std::size_t j = 0; j < doors.size(); ++j) {
            if (!opens[j])
                closed.add(doors[j], j);
        }
        std::vector<std::uint8_t> keep(opens);
        for (std::size_t i = 0; i < doors.size(); ++i) {
            if (!opens[i])
                continue;
            closed.forNeighbours(doors[i], [&](std::size_t j) {
                if (doors[j].width < doors[i].width - 1.0 && jambDistance(doors[i], doors[j]) <= nd)
                    keep[i] = 0;
            });
        }
        opens.swap(keep);
    }
    std::size_t kept = 0;
    for (std::size_t i = 0; i < doors.size(); ++i) {
        if (opens[i])
            doors[kept++] = doors[i];
    }
    doors.resize(kept);
    return doors;
}

std::vector<VirtualDoor> DoorFilters::distance(std::vector<VirtualDoor> doors,
                                               double resolution) const {
    const double nd = detail::toCells(options_.frameDistance, resolution);
    MidpointBuckets grid(nd);

    if (!options_.keepNarrowestOfGroup) {  // the paper: greedy, in search order
        std::vector<VirtualDoor> kept;
        for (const VirtualDoor& d : doors) {
            bool tooClose = false;
            grid.forNeighbours(
                d, [&](std::size_t j) { tooClose = tooClose || jambDistance(d, kept[j]) <= nd; });
            if (tooClose)
                continue;
            grid.add(d, kept.size());
            kept.push_back(d);
        }
        return kept;
    }

    // Groups: connected components of the "closer than N_d" relation.
    for (std::size_t i = 0; i < doors.size(); ++i)
        grid.add(doors[i], i);
    DisjointSets groups(doors.size());
    for (std::size_t i = 0; i < doors.size(); ++i) {
        grid.forNeighbours(doors[i], [&](std::size_t j) {
            if (j > i &&
                (jambDistance(doors[i], doors[j]) <= nd || fanFromOneJamb(doors[i], doors[j]))) {
                groups.union_set(i, j);
            }
        });
    }
    std::unordered_map<std::size_t, std::vector<std::size_t>> members;
    for (std::size_t i = 0; i < doors.size(); ++i)
        members[groups.find_set(i)].push_back(i);
    std::vector<std::size_t> chosen;
    for (auto& [root, group] : members) {
        (void)root;
        double narrowest = 1e18;
        for (std::size_t i : group)
            narrowest = std::min(narrowest, doors[i].width);
        cv::Point2d middle(0, 0);
        for (std::size_t i : group)
            middle += 0.5 * (cv::Point2d(doors[i].jambA) + cv::Point2d(doors[i].jambB));
        middle *= 1.0 / static_cast<double>(group.size());
        std::size_t best = group.front();
        double bestOffset = 1e18;
        for (std::size_t i : group) {
            if (doors[i].width > narrowest + 0.5)
                continue;  // half a cell: same width
            const cv::Point2d m = 0.5 * (cv::Point2d(doors[i].jambA) + cv::Point2d(doors[i].jambB));
            const double offset = std::hypot(m.x - middle.x, m.y - middle.y);
            if (offset < bestOffset) {
                bestOffset = offset;
                best = i;
            }
        }
        chosen.push_back(best);
    }
    std::sort(chosen.begin(), chosen.end());  // keep the search order
    std::vector<VirtualDoor> kept;
    kept.reserve(chosen.size());
    for (std::size_t i : chosen)
        kept.push_back(doors[i]);
    return kept;
}

std::vector<std::size_t> DoorFilters::adjacency(const RegionPartition& partition) {
    std::vector<std::size_t> kept;
    for (std::size_t i = 0; i < partition.doorCount(); ++i) {
        if (partition.regionsAt(i).size() >= 2)
            kept.push_back(i);
    }
    return kept;
}

namespace {

// The regions of a partition merged through removed doors (the minimum-area filter's state):
// a union-find over the regions with each set's area at its representative, and which of the
// candidate doors are removed.
class RegionMerge {
  public:
    RegionMerge(const RegionPartition& partition, const std::vector<std::size_t>& candidates,
                const RegionBoundary* boundary)
        : partition_(partition),
          candidates_(candidates),
          sets_(static_cast<std::size_t>(partition.regionCount()) + 1),
          area_(partition.areas().begin(), partition.areas().end()),
          closed_(area_.size(), 0),
          open_(area_.size(), 0),
          removed_(candidates.size(), false) {
        if (boundary != nullptr) {
            closed_.assign(boundary->closed().begin(), boundary->closed().end());
            open_.assign(boundary->open().begin(), boundary->open().end());
        }
    }

    int rootOf(int region) {
        return static_cast<int>(sets_.find_set(static_cast<std::size_t>(region)));
    }
    double area(int root) const { return area_[static_cast<std::size_t>(root)]; }
    /// Whether more than `maxFraction` of the set's boundary is open to the unobserved
    /// outside (RegionBoundary).
    bool mostlyOpen(int root, double maxFraction) const {
        const auto i = static_cast<std::size_t>(root);
        return open_[i] > maxFraction * (closed_[i] + open_[i]);
    }
    bool removed(std::size_t k) const { return removed_[k]; }
    std::size_t size() const { return candidates_.size(); }
    int sideA(std::size_t k) const { return partition_.regionsAt(candidates_[k])[0].first; }
    int sideB(std::size_t k) const { return partition_.regionsAt(candidates_[k])[1].first; }
    /// The sets on the two sides of candidate k.
    std::pair<int, int> liveSides(std::size_t k) { return {rootOf(sideA(k)), rootOf(sideB(k))}; }

    /// Removes candidate k and joins every region it touches.
    void removeDoor(std::size_t k) {
        removed_[k] = true;
        for (const auto& [region, contacts] : partition_.regionsAt(candidates_[k])) {
            (void)contacts;
            join(sideA(k), region);
        }
    }

    /// Whether candidate k still touches three or more sets (crossing cuts).
    bool touchesMoreThanTwo(std::size_t k) {
        std::vector<int> roots;
        for (const auto& [region, contacts] : partition_.regionsAt(candidates_[k])) {
            (void)contacts;
            roots.push_back(rootOf(region));
        }
        std::sort(roots.begin(), roots.end());
        return std::unique(roots.begin(), roots.end()) - roots.begin() > 2;
    }

    DoorFilters::Rooms rooms() {
        const int regions = partition_.regionCount();
        DoorFilters::Rooms out;
        out.roomOfRegion.assign(static_cast<std::size_t>(regions) + 1, 0);
        std::vector<int> roomOfRoot(static_cast<std::size_t>(regions) + 1, 0);
        for (int r = 1; r <= regions; ++r) {
            int& room = roomOfRoot[static_cast<std::size_t>(rootOf(r))];
            if (room == 0)
                room = ++out.roomCount;
            out.roomOfRegion[static_cast<std::size_t>(r)] = room;
        }
        for (std::size_t k = 0; k < candidates_.size(); ++k) {
            if (removed_[k])
                continue;
            const int a = out.roomOfRegion[static_cast<std::size_t>(sideA(k))];
            const int b = out.roomOfRegion[static_cast<std::size_t>(sideB(k))];
            if (a != b)
                out.doors.push_back({candidates_[k], std::min(a, b), std::max(a, b)});
        }
        return out;
    }

  private:
    void join(int a, int b) {
        a = rootOf(a);
        b = rootOf(b);
        if (a == b)
            return;
        const double total = area(a) + area(b);
        const double closed =
            closed_[static_cast<std::size_t>(a)] + closed_[static_cast<std::size_t>(b)];
        const double open = open_[static_cast<std::size_t>(a)] + open_[static_cast<std::size_t>(b)];
        sets_.link(static_cast<std::size_t>(a), static_cast<std::size_t>(b));
        const auto root = static_cast<std::size_t>(rootOf(a));
        area_[root] = total;
        closed_[root] = closed;
        open_[root] = open;
    }

    const RegionPartition& partition_;
    const std::vector<std::size_t>& candidates_;
    DisjointSets sets_;
    std::vector<double> area_;           // cells
    std::vector<double> closed_, open_;  // boundary cell edges (RegionBoundary)
    std::vector<bool> removed_;
};

// The smallest set that is too small or mostly open to the unobserved outside (not known to be
// enclosed) and still has a door to another set; -1 when none.
int smallestToMerge(RegionMerge& m, double minCells, double maxOpen) {
    int smallest = -1;
    double smallestArea = 0;
    for (std::size_t k = 0; k < m.size(); ++k) {
        const auto [a, b] = m.liveSides(k);
        if (m.removed(k) || a == b)
            continue;
        for (int r : {a, b}) {
            if (m.area(r) > minCells && !m.mostlyOpen(r, maxOpen))
                continue;
            if (smallest < 0 || m.area(r) <= smallestArea) {
                smallest = r;
                smallestArea = m.area(r);
            }
        }
    }
    return smallest;
}

// The widest door of set `smallest` (of two cuts through one doorway the waist stays; a sliver
// between a doorway's cut and a cut along a wall face keeps the doorway's), ties (half a cell):
// the door to its smallest neighbour.
std::size_t widestDoor(RegionMerge& m, int smallest, const std::vector<VirtualDoor>& doors,
                       const std::vector<std::size_t>& candidates) {
    std::size_t through = 0;
    double worstFit = -1, neighbourArea = 1e300;
    for (std::size_t k = 0; k < m.size(); ++k) {
        const auto [a, b] = m.liveSides(k);
        if (m.removed(k) || a == b || (a != smallest && b != smallest))
            continue;
        const double fit = doors[candidates[k]].width;
        const double other = m.area(a == smallest ? b : a);
        if (fit > worstFit + 0.5 || (std::abs(fit - worstFit) <= 0.5 && other < neighbourArea)) {
            worstFit = fit;
            neighbourArea = other;
            through = k;
        }
    }
    return through;
}

}  // namespace

DoorFilters::Rooms DoorFilters::minimumArea(const RegionPartition& partition,
                                            const std::vector<VirtualDoor>& doors,
                                            const std::vector<std::size_t>& candidates,
                                            double cellArea, const RegionBoundary* boundary) const {
    const double minCells = detail::toCells(options_.minRoomArea, cellArea);
    const double maxOpen = options_.maxOpenBoundary;
    RegionMerge merge(partition, candidates, boundary);
    if (!options_.mergeSmallestFirst) {  // the paper: one pass over all doors
        auto fails = [&](int region) {
            return merge.area(region) <= minCells || merge.mostlyOpen(region, maxOpen);
        };
        std::vector<std::size_t> failing;
        for (std::size_t k = 0; k < candidates.size(); ++k) {
            if (fails(merge.sideA(k)) || fails(merge.sideB(k)))
                failing.push_back(k);
        }
        for (std::size_t k : failing)
            merge.removeDoor(k);
    } else {
        // The smallest region to merge is merged through its widest door, again and again.
        for (int smallest = smallestToMerge(merge, minCells, maxOpen); smallest >= 0;
             smallest = smallestToMerge(merge, minCells, maxOpen)) {
            merge.removeDoor(widestDoor(merge, smallest, doors, candidates));
        }
    }
    // A door separates exactly two rooms: one that still touches three or more (crossing cuts)
    // is removed as well, until none is left, so that every two rooms that touch share a door.
    for (bool changed = true; changed;) {
        changed = false;
        for (std::size_t k = 0; k < candidates.size(); ++k) {
            if (!merge.removed(k) && merge.touchesMoreThanTwo(k)) {
                merge.removeDoor(k);
                changed = true;
            }
        }
    }
    return merge.rooms();
}

}  // namespace toposlam::rooms
