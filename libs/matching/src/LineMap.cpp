#include <toposlam/matching/LineMap.h>
#include <toposlam/matching/LocalLine.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace toposlam::matching {

namespace {
/// Normals closer than this (cosine) belong to the same surface when fusing: 25 deg.
constexpr float kSameSurfaceCos = 0.9f;
/// The directory grows by this many tiles on the side it grows (fewer re-copies).
constexpr long kGrowTiles = 4;
/// The lattice's anchor lies this many cells below and left of the first point's box.
constexpr long kAnchorCells = 100;

/// a / b rounded towards minus infinity (b > 0).
long floorDiv(long a, long b) {
    return a >= 0 ? a / b : -((-a + b - 1) / b);
}
}  // namespace

LineMap::LineMap(const LineMapOptions& options)
    : options_(options),
      inverseResolution_(1.0 / options.resolution),
      stampRadius_(long(std::ceil(options.radius / options.resolution))),
      columnDx2_(std::size_t(2 * stampRadius_ + 1)) {}

void LineMap::clear() {
    points_.clear();
    scans_ = 0;
    tilesUsed_ = 0;
    std::fill(tileOf_.begin(), tileOf_.end(), kNone);
}

void LineMap::reset() {
    points_.clear();
    scans_ = 0;
    tilesUsed_ = 0;
    tileOf_.clear();
    tilesX_ = tilesY_ = 0;
    latticeX_ = latticeY_ = 0;
    firstCellX_ = firstCellY_ = 0;
}

void surfacePoints(const PolarScan& scan, const LineMapOptions& options,
                   std::vector<SurfacePoint>& out) {
    out.clear();
    const double reach = localLineReach(surfaceNoise(scan, options.maxJoinDistance));
    for (std::size_t b = 0; b < scan.size(); ++b) {
        if (!scan.valid(b) || scan.range(b) > options.maxRange)
            continue;
        const auto line = fitLocalLine(scan, b, options.maxJoinDistance, reach);
        if (!line)
            continue;
        const mrpt::math::TPoint2D& p = scan.point(b);
        out.push_back({p.x, p.y, line->nx, line->ny});
    }
}

void LineMap::insertScan(const PolarScan& scan, const mrpt::poses::CPose2D& sensorPose) {
    surfacePoints(scan, options_, surface_);
    insertSurface(surface_, sensorPose);
}

void LineMap::insertSurface(const std::vector<SurfacePoint>& points,
                            const mrpt::poses::CPose2D& sensorPose) {
    ++scans_;
    if (points.empty())
        return;
    const double c = std::cos(sensorPose.phi()), s = std::sin(sensorPose.phi());
    inMapFrame_.clear();
    float minX = std::numeric_limits<float>::infinity(), minY = minX;
    float maxX = -minX, maxY = -minX;
    for (const SurfacePoint& p : points) {
        LineMapPoint m;
        m.x = float(sensorPose.x() + c * p.x - s * p.y);
        m.y = float(sensorPose.y() + s * p.x + c * p.y);
        m.nx = float(c * p.nx - s * p.ny);
        m.ny = float(s * p.nx + c * p.ny);
        m.weight = 1;
        m.lastScan = m.firstScan = scans_;
        inMapFrame_.push_back(m);
        minX = std::min(minX, m.x), maxX = std::max(maxX, m.x);
        minY = std::min(minY, m.y), maxY = std::max(maxY, m.y);
    }
    // Grow the grid once for the whole scan: point by point, far readings regrow (and copy)
    // it again and again.
    if (tilesX_ == 0) {
        // The lattice's corner where the first point alone puts it, as point-by-point growth
        // did: the cells (and so every lookup) depend on where the lattice lies, not on how
        // far the grid reaches.
        cover(inMapFrame_.front().x, inMapFrame_.front().y, inMapFrame_.front().x,
              inMapFrame_.front().y);
    }
    cover(minX, minY, maxX, maxY);
    for (const LineMapPoint& m : inMapFrame_)
        insert(m);
}

void LineMap::insert(const LineMapPoint& p) {
    cover(p.x, p.y, p.x, p.y);
    std::uint32_t views = p.views;
    if (const LineMapPoint* near = nearest(p.x, p.y)) {
        LineMapPoint& m = points_[std::size_t(near - points_.data())];
        const float dx = m.x - p.x, dy = m.y - p.y;
        const float d2 = dx * dx + dy * dy;
        const float confirm = float(options_.confirmDistance);
        if (d2 < confirm * confirm && m.lastScan != p.lastScan) {
            // An earlier scan saw a surface here: both points are confirmed. (A neighbour that
            // only this scan has confirmed so far passes nothing on: inheriting it measured
            // worse on the noisy laser of MRPT's simul.rawlog, B3 in benchmarks.md.)
            m.views += p.views;
            m.lastScan = p.lastScan;
            views = std::max(views, m.views);
        }
        const float fuse = float(options_.fuseDistance);
        if (d2 < fuse * fuse && m.nx * p.nx + m.ny * p.ny > kSameSurfaceCos) {
            // Running mean; the point moves by less than fuseDistance, so the cells it was
            // stamped into still hold it (their stored distances are at most that stale).
            const float w = m.weight + p.weight;
            m.x = (m.x * m.weight + p.x * p.weight) / w;
            m.y = (m.y * m.weight + p.y * p.weight) / w;
            const float nx = m.nx * m.weight + p.nx * p.weight;
            const float ny = m.ny * m.weight + p.ny * p.weight;
            const float norm = std::hypot(nx, ny);
            m.nx = nx / norm, m.ny = ny / norm;
            m.weight = w;
            return;
        }
    }
    points_.push_back(p);
    points_.back().views = views;
    stamp(std::uint32_t(points_.size() - 1));
}

void LineMap::cover(double boxMinX, double boxMinY, double boxMaxX, double boxMaxY) {
    const double margin = options_.radius + options_.resolution;
    if (tilesX_ == 0) {
        latticeX_ = boxMinX - margin - double(kAnchorCells) * options_.resolution;
        latticeY_ = boxMinY - margin - double(kAnchorCells) * options_.resolution;
    }
    // Tiles (counted from the lattice's anchor) that the box plus margin touches.
    const auto tileIndex = [&](double v, double lattice) {
        return floorDiv(long(std::floor((v - lattice) * inverseResolution_)), kTile);
    };
    const long needMinX = tileIndex(boxMinX - margin, latticeX_);
    const long needMinY = tileIndex(boxMinY - margin, latticeY_);
    const long needMaxX = tileIndex(boxMaxX + margin, latticeX_);
    const long needMaxY = tileIndex(boxMaxY + margin, latticeY_);
    const long firstX = firstCellX_ / kTile, firstY = firstCellY_ / kTile;
    if (tilesX_ > 0 && needMinX >= firstX && needMinY >= firstY && needMaxX < firstX + tilesX_ &&
        needMaxY < firstY + tilesY_)
        return;
    // New extent: the old one plus the box, grown on the sides that grow.
    long minX = needMinX, minY = needMinY, maxX = needMaxX, maxY = needMaxY;
    if (tilesX_ > 0) {
        minX = needMinX < firstX ? needMinX - kGrowTiles : firstX;
        minY = needMinY < firstY ? needMinY - kGrowTiles : firstY;
        maxX = needMaxX >= firstX + tilesX_ ? needMaxX + kGrowTiles : firstX + tilesX_ - 1;
        maxY = needMaxY >= firstY + tilesY_ ? needMaxY + kGrowTiles : firstY + tilesY_ - 1;
    }
    const long newTilesX = maxX - minX + 1, newTilesY = maxY - minY + 1;
    std::vector<std::uint32_t> tileOf(std::size_t(newTilesX * newTilesY), kNone);
    for (long ty = 0; ty < tilesY_; ++ty)
        std::copy_n(tileOf_.begin() + ty * tilesX_, tilesX_,
                    tileOf.begin() + (ty + firstY - minY) * newTilesX + (firstX - minX));
    tileOf_.swap(tileOf);
    tilesX_ = newTilesX, tilesY_ = newTilesY;
    firstCellX_ = minX * kTile, firstCellY_ = minY * kTile;
}

LineMap::Cell* LineMap::tileAt(long tx, long ty) {
    std::uint32_t& tile = tileOf_[std::size_t(ty * tilesX_ + tx)];
    if (tile == kNone) {
        if ((tilesUsed_ + 1) * kTileCells > cells_.size())
            cells_.resize((tilesUsed_ + 1) * kTileCells);
        std::fill_n(cells_.begin() + std::ptrdiff_t(tilesUsed_ * kTileCells), kTileCells, Cell());
        tile = std::uint32_t(tilesUsed_++);
    }
    return &cells_[std::size_t(tile) * kTileCells];
}

void LineMap::stamp(std::uint32_t i) {
    const LineMapPoint& p = points_[i];
    const float res = float(options_.resolution);
    // Cells counted from the directory's first one; cover() put the whole stamp inside it.
    const long px = long(std::floor((p.x - latticeX_) * inverseResolution_)) - firstCellX_;
    const long py = long(std::floor((p.y - latticeY_) * inverseResolution_)) - firstCellY_;
    const float r2 = float(options_.radius * options_.radius);
    const long xBegin = px - stampRadius_;
    // The squared offsets of the stamp's columns from the point, once per point rather than
    // once per row: the first column's centre, stepped by one cell along the row. They fall,
    // then rise, so the cells of a row within radius are one run of columns.
    float dx = float(latticeX_ + (double(firstCellX_ + xBegin) + 0.5) * options_.resolution) - p.x;
    for (float& dx2 : columnDx2_) {
        dx2 = dx * dx;
        dx += res;
    }
    const long columns = long(columnDx2_.size());
    for (long cy = py - stampRadius_; cy <= py + stampRadius_; ++cy) {
        const float dy =
            float(latticeY_ + (double(firstCellY_ + cy) + 0.5) * options_.resolution) - p.y;
        const float dy2 = dy * dy;
        long first = 0, last = columns - 1;
        while (first <= last && columnDx2_[std::size_t(first)] + dy2 > r2)
            ++first;
        while (last >= first && columnDx2_[std::size_t(last)] + dy2 > r2)
            --last;
        // Columns xBegin + [first, last]: the run within radius (none: this row makes no tile).
        for (long cx = xBegin + first, end = xBegin + last + 1; cx < end;) {
            // The part of the run inside one tile.
            const long tx = cx / kTile, runEnd = std::min(end, (tx + 1) * kTile);
            Cell* row = tileAt(tx, cy / kTile) + (cy % kTile) * kTile;
            for (; cx < runEnd; ++cx) {
                // An empty cell's distance is infinite: the nearer point takes the cell.
                const float d2 = columnDx2_[std::size_t(cx - xBegin)] + dy2;
                Cell& cell = row[cx - tx * kTile];
                if (d2 < cell.distance2)
                    cell = {i, d2};
            }
        }
    }
}

template <typename Seen>
void LineMap::forEachSeenThrough(const PolarScan& scan, const mrpt::poses::CPose2D& sensorPose,
                                 std::size_t first, double margin, Seen&& seen) const {
    const double c = std::cos(sensorPose.phi()), s = std::sin(sensorPose.phi());
    const auto beyond = [&](long beam, double range) {
        return beam >= 0 && scan.valid(std::size_t(beam)) &&
               scan.range(std::size_t(beam)) >= range + margin;
    };
    for (std::size_t i = first; i < points_.size(); ++i) {
        const LineMapPoint& p = points_[i];
        const double dx = p.x - sensorPose.x(), dy = p.y - sensorPose.y();
        const double lx = c * dx + s * dy, ly = -s * dx + c * dy;
        const double range = std::hypot(lx, ly);
        if (range + margin > scan.maxRange())
            continue;
        const long beam = scan.beamAtPoint(lx, ly);
        if (beyond(beam, range) && beyond(scan.neighbour(beam, -1), range) &&
            beyond(scan.neighbour(beam, 1), range))
            seen(i);
    }
}

void LineMap::carve(const PolarScan& scan, const mrpt::poses::CPose2D& sensorPose,
                    std::size_t first, double margin) {
    forEachSeenThrough(scan, sensorPose, first, margin,
                       [this](std::size_t i) { ++points_[i].seenThrough; });
}

std::size_t LineMap::countSeenThrough(const PolarScan& scan, const mrpt::poses::CPose2D& sensorPose,
                                      double margin) const {
    std::size_t count = 0;
    forEachSeenThrough(scan, sensorPose, 0, margin, [&count](std::size_t) { ++count; });
    return count;
}

}  // namespace toposlam::matching
