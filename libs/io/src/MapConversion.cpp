#include <toposlam/io/MapConversion.h>

#include <cstdio>

namespace toposlam::io {

MapConversionSummary convertGridMap(const std::string& inputPath, const std::string& outputPath,
                                    const std::optional<GridMapGeometry>& geometry,
                                    bool drawnPlan) {
    auto map = loadGridMap(inputPath, geometry);
    if (drawnPlan) {
        for (unsigned cy = 0; cy < map.getSizeY(); ++cy)
            for (unsigned cx = 0; cx < map.getSizeX(); ++cx)
                if (!(map.getCell(cx, cy) > kDrawnPlanFreeAbove))
                    map.setCell(cx, cy, 0.0f);
    }
    saveGridMap(map, outputPath);
    MapConversionSummary s;
    s.sizeX = map.getSizeX();
    s.sizeY = map.getSizeY();
    s.resolution = map.getResolution();
    s.originX = map.getXMin();
    s.originY = map.getYMin();
    s.freeCells = countFreeCells(map);
    return s;
}

std::string describe(const MapConversionSummary& s, const std::string& inputPath,
                     const std::string& outputPath) {
    char text[256];
    std::snprintf(text, sizeof text,
                  ": %u x %u cells of %.4g m, origin (%.6g, %.6g) m, %zu free cells -> ", s.sizeX,
                  s.sizeY, s.resolution, s.originX, s.originY, s.freeCells);
    return inputPath + text + outputPath;
}

}  // namespace toposlam::io
