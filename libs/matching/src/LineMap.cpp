#include <toposlam/matching/LineMap.h>
#include <toposlam/matching/LocalLine.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace toposlam::matching {

namespace {
/// Normals closer than this (cosine) belong to the same surface when fusing: 25 deg.
constexpr float kSameSurfaceCos = 0.9f;
/// The grid grows by at least this many cells on the side it grows (fewer re-copies).
constexpr long kGrowCells = 200;
}  // namespace

LineMap::LineMap(const LineMapOptions& options)
    : options_(options),
      inverseResolution_(1.0 / options.resolution),
      stampRadius_(long(std::ceil(options.radius / options.resolution))) {}

void LineMap::clear() {
    points_.clear();
    std::fill(cells_.begin(), cells_.end(), Cell());
}

void surfacePoints(const PolarScan& scan, const LineMapOptions& options,
                   std::vector<SurfacePoint>& out) {
    out.clear();
    for (std::size_t b = 0; b < scan.size(); ++b) {
        if (!scan.valid(b) || scan.range(b) > options.maxRange)
            continue;
        const auto line = fitLocalLine(scan, b, options.maxJoinDistance);
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
        inMapFrame_.push_back(m);
        minX = std::min(minX, m.x), maxX = std::max(maxX, m.x);
        minY = std::min(minY, m.y), maxY = std::max(maxY, m.y);
    }
    // Grow the grid once for the whole scan: point by point, far readings regrow (and copy)
    // it again and again.
    if (width_ == 0) {
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
    if (const LineMapPoint* near = nearest(p.x, p.y)) {
        const float dx = near->x - p.x, dy = near->y - p.y;
        const float fuse = float(options_.fuseDistance);
        if (dx * dx + dy * dy < fuse * fuse &&
            near->nx * p.nx + near->ny * p.ny > kSameSurfaceCos) {
            // Running mean; the point moves by less than fuseDistance, so the cells it was
            // stamped into still hold it (their stored distances are at most that stale).
            LineMapPoint& m = points_[std::size_t(near - points_.data())];
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
    stamp(std::uint32_t(points_.size() - 1));
}

void LineMap::cover(double boxMinX, double boxMinY, double boxMaxX, double boxMaxY) {
    const double margin = options_.radius + options_.resolution;
    const double res = options_.resolution;
    if (width_ > 0 && boxMinX - margin >= x0_ && boxMinY - margin >= y0_ &&
        boxMaxX + margin < x0_ + width_ * res && boxMaxY + margin < y0_ + height_ * res)
        return;
    // New extent: the old one plus the box, grown generously on the sides that grow.
    const double growth = kGrowCells * res;
    double minX = x0_, minY = y0_, maxX = x0_ + width_ * res, maxY = y0_ + height_ * res;
    if (width_ == 0) {
        minX = boxMinX - margin - growth / 2, maxX = boxMaxX + margin + growth / 2;
        minY = boxMinY - margin - growth / 2, maxY = boxMaxY + margin + growth / 2;
    } else {
        if (boxMinX - margin < minX)
            minX = boxMinX - margin - growth;
        if (boxMaxX + margin >= maxX)
            maxX = boxMaxX + margin + growth;
        if (boxMinY - margin < minY)
            minY = boxMinY - margin - growth;
        if (boxMaxY + margin >= maxY)
            maxY = boxMaxY + margin + growth;
    }
    // Keep the cell lattice: new corner on a whole number of cells from the old one.
    if (width_ == 0)
        latticeX_ = minX, latticeY_ = minY, firstCellX_ = firstCellY_ = 0;
    const long shiftX = width_ > 0 ? long(std::ceil((x0_ - minX) / res)) : 0;
    const long shiftY = width_ > 0 ? long(std::ceil((y0_ - minY) / res)) : 0;
    firstCellX_ -= shiftX, firstCellY_ -= shiftY;
    const double newX0 = latticeX_ + double(firstCellX_) * res;
    const double newY0 = latticeY_ + double(firstCellY_) * res;
    const long newWidth = long(std::ceil((maxX - newX0) / res)) + 1;
    const long newHeight = long(std::ceil((maxY - newY0) / res)) + 1;
    std::vector<Cell> cells(std::size_t(newWidth * newHeight));
    for (long cy = 0; cy < height_; ++cy)
        std::copy_n(cells_.begin() + cy * width_, width_,
                    cells.begin() + (cy + shiftY) * newWidth + shiftX);
    cells_.swap(cells);
    x0_ = newX0, y0_ = newY0, width_ = newWidth, height_ = newHeight;
}

void LineMap::stamp(std::uint32_t i) {
    const LineMapPoint& p = points_[i];
    const float res = float(options_.resolution);
    const long px = long(std::floor((p.x - x0_) * inverseResolution_));
    const long py = long(std::floor((p.y - y0_) * inverseResolution_));
    const float r2 = float(options_.radius * options_.radius);
    const long xBegin = std::max(0L, px - stampRadius_);
    const long xEnd = std::min(width_ - 1, px + stampRadius_) + 1;
    // Offsets of the first column's centre, stepped by one cell along the row (no per-cell
    // conversions: this runs for every cell around every new map point).
    const float dxBegin =
        float(latticeX_ + (double(firstCellX_ + xBegin) + 0.5) * options_.resolution) - p.x;
    for (long cy = std::max(0L, py - stampRadius_); cy <= std::min(height_ - 1, py + stampRadius_);
         ++cy) {
        const float dy =
            float(latticeY_ + (double(firstCellY_ + cy) + 0.5) * options_.resolution) - p.y;
        const float dy2 = dy * dy;
        Cell* row = &cells_[std::size_t(cy * width_)];
        float dx = dxBegin;
        for (long cx = xBegin; cx < xEnd; ++cx, dx += res) {
            const float d2 = dx * dx + dy2;
            Cell& cell = row[cx];
            if (d2 <= r2 && (cell.point == kNone || d2 < cell.distance2))
                cell = {i, d2};
        }
    }
}

}  // namespace toposlam::matching
