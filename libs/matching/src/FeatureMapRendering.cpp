#include <mrpt/opengl/CPointCloudColoured.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <toposlam/matching/FeatureMapRendering.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace toposlam::matching {

using features::EndpointType;

namespace {

struct Rgb {
    float r, g, b;
};

constexpr Rgb kSegment{0.1f, 0.2f, 0.6f};
constexpr Rgb kConvexCorner{0.9f, 0.1f, 0.1f};
constexpr Rgb kConcaveCorner{0.1f, 0.7f, 0.1f};
constexpr Rgb kEndpoint{1.0f, 0.55f, 0.0f};
constexpr Rgb kJump{0.45f, 0.45f, 0.45f};

Rgb cornerColour(EndpointType t) {
    return t == EndpointType::Concave ? kConcaveCorner : kConvexCorner;
}

Rgb endpointColour(EndpointType t) {
    return t == EndpointType::Jump ? kJump : kEndpoint;
}

mrpt::img::TColor toColour(const Rgb& c) {
    return mrpt::img::TColor(static_cast<uint8_t>(255 * c.r), static_cast<uint8_t>(255 * c.g),
                             static_cast<uint8_t>(255 * c.b));
}

}  // namespace

void appendFeatureMapVisualization(const FeatureMap& map, mrpt::opengl::CSetOfObjects& out) {
    auto lines = mrpt::opengl::CSetOfLines::Create();
    lines->setLineWidth(3.0f);
    lines->setColor(kSegment.r, kSegment.g, kSegment.b);
    for (const MapSegment& s : map.segments()) {
        if (!map.confirmed(s))
            continue;
        for (const SegmentPiece& p : s.pieces)
            lines->appendLine(p.start.x, p.start.y, 0.0, p.end.x, p.end.y, 0.0);
    }
    // Corners large, endpoints small, slightly above the lines so they are not hidden.
    auto corners = mrpt::opengl::CPointCloudColoured::Create();
    corners->setPointSize(9.0f);
    for (const MapPoint& p : map.corners()) {
        if (!map.confirmed(p))
            continue;
        const Rgb c = cornerColour(p.type);
        corners->push_back(float(p.position.x), float(p.position.y), 0.02f, c.r, c.g, c.b);
    }
    auto endpoints = mrpt::opengl::CPointCloudColoured::Create();
    endpoints->setPointSize(5.0f);
    for (const MapPoint& p : map.endpoints()) {
        if (!map.confirmed(p))
            continue;
        const Rgb c = endpointColour(p.type);
        endpoints->push_back(float(p.position.x), float(p.position.y), 0.01f, c.r, c.g, c.b);
    }
    out.insert(lines);
    out.insert(endpoints);
    out.insert(corners);
}

mrpt::img::CImage drawFeatureMap(const FeatureMap& map, double metresPerPixel) {
    double xMin = std::numeric_limits<double>::max(), yMin = xMin;
    double xMax = std::numeric_limits<double>::lowest(), yMax = xMax;
    const auto extend = [&](const mrpt::math::TPoint2D& p) {
        xMin = std::min(xMin, p.x);
        xMax = std::max(xMax, p.x);
        yMin = std::min(yMin, p.y);
        yMax = std::max(yMax, p.y);
    };
    for (const MapSegment& s : map.segments()) {
        if (!map.confirmed(s))
            continue;
        for (const SegmentPiece& p : s.pieces) {
            extend(p.start);
            extend(p.end);
        }
    }
    for (const auto* points : {&map.corners(), &map.endpoints()})
        for (const MapPoint& p : *points)
            if (map.confirmed(p))
                extend(p.position);
    if (xMin > xMax)
        xMin = yMin = xMax = yMax = 0;
    constexpr double kMargin = 0.5;
    constexpr double kMaxPixels = 4000;
    xMin -= kMargin;
    yMin -= kMargin;
    xMax += kMargin;
    yMax += kMargin;
    const double scale =
        std::max({metresPerPixel, (xMax - xMin) / kMaxPixels, (yMax - yMin) / kMaxPixels});
    const int width = static_cast<int>(std::ceil((xMax - xMin) / scale));
    const int height = static_cast<int>(std::ceil((yMax - yMin) / scale));

    mrpt::img::CImage img(width, height, mrpt::img::CH_RGB);
    img.filledRectangle(0, 0, width - 1, height - 1, mrpt::img::TColor(255, 255, 255));
    const auto px = [&](double x) { return static_cast<int>(std::lround((x - xMin) / scale)); };
    const auto py = [&](double y) {
        return static_cast<int>(std::lround((yMax - y) / scale));  // y up
    };
    for (const MapSegment& s : map.segments()) {
        if (!map.confirmed(s))
            continue;
        for (const SegmentPiece& p : s.pieces)
            img.line(px(p.start.x), py(p.start.y), px(p.end.x), py(p.end.y), toColour(kSegment), 2);
    }
    for (const MapPoint& p : map.endpoints()) {
        if (map.confirmed(p))
            img.drawCircle(px(p.position.x), py(p.position.y), 2, toColour(endpointColour(p.type)));
    }
    for (const MapPoint& p : map.corners()) {
        if (!map.confirmed(p))
            continue;
        const char mark = p.type == EndpointType::Concave ? 's' : 'x';
        img.drawMark(px(p.position.x), py(p.position.y), toColour(cornerColour(p.type)), mark, 5,
                     2);
    }
    return img;
}

}  // namespace toposlam::matching
