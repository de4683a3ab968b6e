#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/serialization/CArchive.h>
#include <toposlam/io/AtomicFile.h>
#include <toposlam/io/FileExtension.h>
#include <toposlam/io/GridMapIO.h>
#include <toposlam/io/InputError.h>
#include <toposlam/io/TextFile.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>

#include "GreyImage.h"
#include "GzipInputStream.h"
#include "LookaheadStream.h"
#include "MrptErrorText.h"
#include "MrptObjectCheck.h"
#include "RosMapMetadata.h"

namespace toposlam::io {

namespace fs = std::filesystem;
using mrpt::maps::COccupancyGridMap2D;

namespace {

enum class MapFormat { Serialized, RosYaml, Png, Pgm, OtherImage, Unknown };

MapFormat formatOf(const std::string& path) {
    if (hasAnyExtension(path, {".gridmap", ".gridmap.gz"}))
        return MapFormat::Serialized;
    if (hasAnyExtension(path, {".yaml", ".yml"}))
        return MapFormat::RosYaml;
    if (hasExtension(path, ".png"))
        return MapFormat::Png;
    if (hasExtension(path, ".pgm"))
        return MapFormat::Pgm;
    if (hasAnyExtension(path, {".bmp", ".jpg", ".jpeg", ".tif", ".tiff"}))
        return MapFormat::OtherImage;
    return MapFormat::Unknown;
}

const char* const kKnownExtensions =
    ".gridmap, .gridmap.gz, .yaml, .yml, .png, .pgm (input also .bmp, .jpg, .jpeg, .tif, .tiff)";

// COccupancyGridMap2D::setSize() rounds its limits to multiples of the resolution; a ROS
// map's origin need not be one. The limits are protected members: this accessor, a derived
// type that is never instantiated, reaches them through pointers to members.
struct GridLimitsAccess : COccupancyGridMap2D {
    static void setLimits(COccupancyGridMap2D& g, float xMin, float yMin) {
        const float res = g.getResolution();
        g.*(&GridLimitsAccess::m_xMin) = xMin;
        g.*(&GridLimitsAccess::m_yMin) = yMin;
        g.*(&GridLimitsAccess::m_xMax) = xMin + static_cast<float>(g.getSizeX()) * res;
        g.*(&GridLimitsAccess::m_yMax) = yMin + static_cast<float>(g.getSizeY()) * res;
    }
};

// A width x height grid with the given cell size and exact lower-left corner, all unknown.
COccupancyGridMap2D makeGrid(int width, int height, double resolution, double originX,
                             double originY) {
    const auto res = static_cast<float>(resolution);
    COccupancyGridMap2D grid;
    grid.setSize(0.0f, static_cast<float>(width) * res, 0.0f, static_cast<float>(height) * res, res,
                 0.5f);
    if (grid.getSizeX() != static_cast<unsigned>(width) ||
        grid.getSizeY() != static_cast<unsigned>(height)) {
        throw std::logic_error("grid size mismatch after setSize()");
    }
    setGridOrigin(grid, static_cast<float>(originX), static_cast<float>(originY));
    return grid;
}

// p(free) for each grey level, following the metadata's mode (see GridMapIO.h).
std::array<float, 256> freeProbabilityTable(const RosMapMetadata& meta) {
    std::array<float, 256> table{};
    for (int grey = 0; grey < 256; ++grey) {
        const double pOccupied = meta.negate ? grey / 255.0 : (255 - grey) / 255.0;
        double pFree = 0.5;
        switch (meta.mode) {
            case RosMapMetadata::Mode::Trinary:
                pFree = pOccupied > meta.occupiedThresh ? 0.0
                        : pOccupied < meta.freeThresh   ? 1.0
                                                        : 0.5;
                break;
            case RosMapMetadata::Mode::Scale:
                pFree = 1.0 - pOccupied;
                break;
            case RosMapMetadata::Mode::Raw:
                pFree = grey <= 100 ? 1.0 - grey / 100.0 : 0.5;
                break;
        }
        table[static_cast<std::size_t>(grey)] = static_cast<float>(pFree);
    }
    return table;
}

// OpenCV refuses, before decoding, images with more pixels than OPENCV_IO_MAX_IMAGE_PIXELS
// (default 2^30: 1 GiB of grey, several for colour) states; lower it to what a grid map may
// have. Read once by OpenCV at its first image: a setting the user made is kept.
void limitOpenCvImageSize() {
    static std::once_flag once;
    std::call_once(once, [] {
        ::setenv("OPENCV_IO_MAX_IMAGE_PIXELS", std::to_string(kMaxGridMapCells).c_str(), 0);
    });
}

}  // namespace

cv::Mat detail::readGreyImage(const std::string& path) {
    if (!fs::is_regular_file(path))
        throw InputError(path, "file not found");
    limitOpenCvImageSize();
    cv::Mat image;
    std::string problem = "corrupt, or not an image format OpenCV reads";
    try {
        image = cv::imread(path, cv::IMREAD_GRAYSCALE);
    } catch (const cv::Exception& e) {
        image.release();
        if (std::string(e.what()).find("MAX_IMAGE") != std::string::npos) {
            problem = "more than " + std::to_string(kMaxGridMapCells) + " pixels";
        }
    }
    if (image.empty())
        throw InputError(path, "cannot read the image (" + problem + ")");
    if (static_cast<unsigned long long>(image.total()) > kMaxGridMapCells) {
        throw InputError(path, "cannot read the image (more than " +
                                   std::to_string(kMaxGridMapCells) + " pixels)");
    }
    if (image.depth() != CV_8U)
        image.convertTo(image, CV_8U);
    return image;
}

namespace {

COccupancyGridMap2D gridFromImage(const cv::Mat& grey, const RosMapMetadata& meta) {
    COccupancyGridMap2D grid =
        makeGrid(grey.cols, grey.rows, meta.resolution, meta.originX, meta.originY);
    const auto table = freeProbabilityTable(meta);
    for (int row = 0; row < grey.rows; ++row) {
        const auto* pixels = grey.ptr<unsigned char>(row);
        const int cy = grey.rows - 1 - row;  // image row 0 is the top (max y) row
        for (int cx = 0; cx < grey.cols; ++cx)
            grid.setCell(cx, cy, table[pixels[cx]]);
    }
    return grid;
}

// The sidecar of an image: "<stem>.yaml" when it exists and names this image, or names the
// "<stem>.pgm" beside it (the ROS pair saveGridMap() writes with a .png picture: the picture
// then has the pair's geometry and its grey is p(free), as it was written).
std::optional<RosMapMetadata> sidecarOf(const std::string& imagePath) {
    const std::string yaml = fs::path(imagePath).replace_extension(".yaml").string();
    if (!fs::is_regular_file(yaml))
        return std::nullopt;
    RosMapMetadata meta = readRosMapMetadata(yaml);
    const std::string described = resolveRosMapImage(yaml, meta);
    std::error_code ec;
    if (fs::equivalent(described, imagePath, ec))
        return meta;
    const std::string pair = fs::path(imagePath).replace_extension(".pgm").string();
    if (formatOf(imagePath) == MapFormat::Png && fs::equivalent(described, pair, ec)) {
        meta.mode = RosMapMetadata::Mode::Scale;
        meta.negate = false;
        return meta;
    }
    return std::nullopt;
}

// True when every pixel is one of ROS map_saver's three greys (occupied 0, unknown 205, free
// 254): its picture, whose unknown grey read as p(free) = 205 / 255 would sit on the free
// threshold.
bool isMapSaverPicture(const cv::Mat& grey) {
    for (int row = 0; row < grey.rows; ++row) {
        const auto* pixels = grey.ptr<unsigned char>(row);
        for (int c = 0; c < grey.cols; ++c)
            if (pixels[c] != kMapSaverOccupiedGrey && pixels[c] != kMapSaverUnknownGrey &&
                pixels[c] != kMapSaverFreeGrey)
                return false;
    }
    return true;
}

// `meta`: the sidecar's, or nullopt for a bare picture: p(free) = grey / 255, except a
// map_saver picture, read with map_saver's own metadata (trinary, thresholds 0.65 / 0.196).
COccupancyGridMap2D loadImageMap(const std::string& path, std::optional<RosMapMetadata> meta,
                                 const std::optional<GridMapGeometry>& geometry) {
    const cv::Mat grey = detail::readGreyImage(path);
    if (!meta) {
        meta.emplace();
        if (!isMapSaverPicture(grey))
            meta->mode = RosMapMetadata::Mode::Scale;
    }
    if (geometry) {
        if (geometry->resolution) {
            if (!(*geometry->resolution > 0))
                throw InputError(path, "resolution must be > 0");
            meta->resolution = *geometry->resolution;
        }
        meta->originX = geometry->originX.value_or(meta->originX);
        meta->originY = geometry->originY.value_or(meta->originY);
    }
    return gridFromImage(grey, *meta);
}

// MRPT's reader passes the stored limits through setSize(), which rounds them to multiples of
// the resolution. Read the exact stored values from the object's header: class name, version
// (>= 2), bits per cell (uint8), size_x, size_y (uint32), x_min, x_max, y_min, y_max,
// resolution (float), little-endian (COccupancyGridMap2D::serializeTo).
struct StoredGridHeader {
    uint32_t sizeX = 0, sizeY = 0;
    float xMin = 0, yMin = 0;
};

std::optional<StoredGridHeader> readStoredGridHeader(const std::string& path) {
    GzipInputStream in(path);
    unsigned char nameLength = 0;
    if (in.Read(&nameLength, 1) != 1 || !(nameLength & 0x80))
        return std::nullopt;
    std::string name(nameLength & 0x7f, '\0');
    if (in.Read(name.data(), name.size()) != name.size() ||
        name != "mrpt::maps::COccupancyGridMap2D") {
        return std::nullopt;
    }
    unsigned char version = 0, bits = 0;
    unsigned char raw[4 * 7];
    if (in.Read(&version, 1) != 1 || version < 2 || in.Read(&bits, 1) != 1 ||
        in.Read(raw, sizeof raw) != sizeof raw) {
        return std::nullopt;
    }
    StoredGridHeader h;
    std::memcpy(&h.sizeX, raw, 4);
    std::memcpy(&h.sizeY, raw + 4, 4);
    std::memcpy(&h.xMin, raw + 8, 4);
    std::memcpy(&h.yMin, raw + 16, 4);
    return h;
}

COccupancyGridMap2D loadSerializedMap(const std::string& path) {
    GzipInputStream in(path);
    LookaheadStream bytes(in);
    const auto invalid = [&](const std::string& cause) {
        const std::string damage = in.streamError();
        return InputError(path,
                          "not a valid .gridmap file (" + (damage.empty() ? cause : damage) + ")");
    };
    // Checked before MRPT reads it: MRPT allocates the cells its stored limits imply.
    ObjectCheck check;
    try {
        check = checkNextObject(bytes);
    } catch (const MalformedObject& e) {
        throw invalid(e.what());
    }
    if (check.className.empty())
        throw InputError(path, "file is empty");
    if (check.className != "mrpt::maps::COccupancyGridMap2D" || !check.complete) {
        throw invalid("it holds a " + check.className +
                      ", not an mrpt::maps::COccupancyGridMap2D in MRPT's current format");
    }
    bytes.setReadLimit(check.size);
    COccupancyGridMap2D grid;
    try {
        mrpt::serialization::archiveFrom(bytes) >> grid;
    } catch (const std::exception& e) {
        throw invalid(mrptErrorSummary(e));
    }
    if (const std::string damage = in.streamError(); !damage.empty()) {
        throw InputError(path, "corrupt gzip data (" + damage + ")");
    }
    if (const auto stored = readStoredGridHeader(path)) {
        if (stored->sizeX == grid.getSizeX() && stored->sizeY == grid.getSizeY()) {
            setGridOrigin(grid, stored->xMin, stored->yMin);
        }
    }
    return grid;
}

// Grey level of p(free) as MRPT draws grids: 0 black = occupied, 255 white = free.
unsigned char greyOfFreeProbability(float pFree) {
    return static_cast<unsigned char>(std::lround(std::clamp(pFree, 0.0f, 1.0f) * 255.0f));
}

// map_saver's trinary picture: occupied 0, free 254, unknown 205.
unsigned char trinaryGrey(float pFree, const RosMapMetadata& meta) {
    const double pOccupied = 1.0 - pFree;
    if (pOccupied > meta.occupiedThresh)
        return kMapSaverOccupiedGrey;
    if (pOccupied < meta.freeThresh)
        return kMapSaverFreeGrey;
    return kMapSaverUnknownGrey;
}

template <typename GreyOf>
cv::Mat imageOfGrid(const COccupancyGridMap2D& grid, GreyOf greyOf) {
    const int w = static_cast<int>(grid.getSizeX()), h = static_cast<int>(grid.getSizeY());
    cv::Mat image(h, w, CV_8UC1);
    for (int row = 0; row < h; ++row) {
        auto* pixels = image.ptr<unsigned char>(row);
        const int cy = h - 1 - row;
        for (int cx = 0; cx < w; ++cx)
            pixels[cx] = greyOf(grid.getCell(cx, cy));
    }
    return image;
}

void writeImage(const cv::Mat& image, const std::string& path) {
    writeFileAtomically(path, [&](const std::string& tmp) {
        bool ok = false;
        try {
            ok = cv::imwrite(tmp, image);
        } catch (const cv::Exception&) {
            ok = false;
        }
        if (!ok)
            throw std::runtime_error(path + ": cannot write the image");
    });
}

RosMapMetadata metadataOf(const COccupancyGridMap2D& grid, const std::string& imageFileName,
                          RosMapMetadata::Mode mode) {
    RosMapMetadata meta;
    meta.image = imageFileName;
    meta.resolution = grid.getResolution();
    meta.originX = grid.getXMin();
    meta.originY = grid.getYMin();
    meta.mode = mode;
    return meta;
}

// Whether MRPT's reader, which rounds the limits to the resolution, gets the stored size back.
bool mrptReadsSizeBack(const COccupancyGridMap2D& grid) {
    const float res = grid.getResolution();
    const auto cells = [res](float lo, float hi) {
        return std::lround((res * std::round(hi / res) - res * std::round(lo / res)) / res);
    };
    return cells(grid.getXMin(), grid.getXMax()) == static_cast<long>(grid.getSizeX()) &&
           cells(grid.getYMin(), grid.getYMax()) == static_cast<long>(grid.getSizeY());
}

void saveSerializedMap(const COccupancyGridMap2D& grid, const std::string& path) {
    if (!mrptReadsSizeBack(grid)) {
        throw std::runtime_error(path +
                                 ": MRPT could not read this map back as .gridmap (its origin "
                                 "is not a multiple of the resolution); save it as .png or .yaml");
    }
    const bool gz = hasExtension(path, ".gz");
    writeFileAtomically(path, [&](const std::string& tmp) {
        if (gz) {
            mrpt::io::CFileGZOutputStream out;
            if (!out.open(tmp))
                throw std::runtime_error(path + ": cannot create the file");
            mrpt::serialization::archiveFrom(out) << grid;
        } else {
            mrpt::io::CFileOutputStream out;
            if (!out.open(tmp))
                throw std::runtime_error(path + ": cannot create the file");
            mrpt::serialization::archiveFrom(out) << grid;
        }
    });
}

// What ROS map_saver writes: "<stem>.pgm", trinary (occupied 0, free 254, unknown 205), and
// the YAML with mode trinary and the thresholds that classify those grey levels back.
void saveRosMapPair(const COccupancyGridMap2D& map, const std::string& yamlPath) {
    const fs::path image = fs::path(yamlPath).replace_extension(".pgm");
    const RosMapMetadata meta =
        metadataOf(map, image.filename().string(), RosMapMetadata::Mode::Trinary);
    writeImage(imageOfGrid(map, [&](float pFree) { return trinaryGrey(pFree, meta); }),
               image.string());
    saveTextFile(formatRosMapMetadata(meta), yamlPath);
}

}  // namespace

void setGridOrigin(COccupancyGridMap2D& map, float originX, float originY) {
    GridLimitsAccess::setLimits(map, originX, originY);
}

std::size_t countFreeCells(const COccupancyGridMap2D& map) {
    std::size_t n = 0;
    const unsigned w = map.getSizeX(), h = map.getSizeY();
    for (unsigned cy = 0; cy < h; ++cy) {
        for (unsigned cx = 0; cx < w; ++cx) {
            if (map.getCell(static_cast<int>(cx), static_cast<int>(cy)) > 0.5f)
                ++n;
        }
    }
    return n;
}

COccupancyGridMap2D loadGridMap(const std::string& path,
                                const std::optional<GridMapGeometry>& geometry) {
    COccupancyGridMap2D grid;
    switch (formatOf(path)) {
        case MapFormat::Serialized:
            grid = loadSerializedMap(path);
            break;
        case MapFormat::RosYaml: {
            const RosMapMetadata meta = readRosMapMetadata(path);
            grid = loadImageMap(resolveRosMapImage(path, meta), meta, geometry);
            break;
        }
        case MapFormat::Png:
        case MapFormat::Pgm:
        case MapFormat::OtherImage: {
            if (!fs::is_regular_file(path))
                throw InputError(path, "file not found");
            grid = loadImageMap(path, sidecarOf(path), geometry);
            break;
        }
        case MapFormat::Unknown:
            throw InputError(
                path, std::string("unknown grid map format (known: ") + kKnownExtensions + ")");
    }
    if (grid.getSizeX() == 0 || grid.getSizeY() == 0)
        throw InputError(path, "map is empty");
    if (countFreeCells(grid) == 0)
        throw InputError(path, "map has no free cells");
    return grid;
}

bool isGridMapPath(const std::string& path) {
    return formatOf(path) != MapFormat::Unknown;
}

bool isBareMapImage(const std::string& path) {
    switch (formatOf(path)) {
        case MapFormat::Png:
        case MapFormat::Pgm:
        case MapFormat::OtherImage:
            return !sidecarOf(path);
        default:
            return false;
    }
}

std::vector<std::string> gridMapFilesRead(const std::string& path) {
    std::vector<std::string> files = {path};
    switch (formatOf(path)) {
        case MapFormat::RosYaml:
            try {
                files.push_back(resolveRosMapImage(path, readRosMapMetadata(path)));
            } catch (const std::exception&) {
                // loadGridMap reports a .yaml it cannot read; it reads no picture then.
            }
            break;
        case MapFormat::Png:
        case MapFormat::Pgm:
        case MapFormat::OtherImage: {
            // sidecarOf() reads "<stem>.yaml" to tell whether it is this picture's: it counts
            // even when it turns out to describe another picture.
            const std::string yaml = fs::path(path).replace_extension(".yaml").string();
            if (fs::is_regular_file(yaml))
                files.push_back(yaml);
            break;
        }
        default:
            break;
    }
    return files;
}

std::vector<std::string> gridMapFilesWritten(const std::string& path) {
    const auto beside = [&](const char* extension) {
        return fs::path(path).replace_extension(extension).string();
    };
    switch (formatOf(path)) {
        case MapFormat::Png:
            return {path, beside(".yaml"), beside(".pgm")};
        case MapFormat::RosYaml:
            return {path, beside(".pgm")};
        case MapFormat::Pgm:
            return {path, beside(".yaml")};
        default:
            return {path};
    }
}

void saveGridMap(const COccupancyGridMap2D& map, const std::string& path) {
    const fs::path p(path);
    switch (formatOf(path)) {
        case MapFormat::Serialized:
            saveSerializedMap(map, path);
            return;
        case MapFormat::Png:
            // The picture, plus the ROS pair beside it (ROS tools need a trinary image).
            writeImage(imageOfGrid(map, greyOfFreeProbability), path);
            saveRosMapPair(map, fs::path(p).replace_extension(".yaml").string());
            return;
        case MapFormat::RosYaml:
            saveRosMapPair(map, path);
            return;
        case MapFormat::Pgm:
            saveRosMapPair(map, fs::path(p).replace_extension(".yaml").string());
            return;
        case MapFormat::OtherImage:
        case MapFormat::Unknown:
            break;
    }
    throw std::runtime_error(path +
                             ": cannot save a grid map in this format (use .gridmap, "
                             ".gridmap.gz, .png, .yaml or .pgm)");
}

}  // namespace toposlam::io
