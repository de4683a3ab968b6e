#include "RosMapMetadata.h"

#include <toposlam/io/GridMapIO.h>
#include <toposlam/io/InputError.h>
#include <yaml-cpp/yaml.h>

#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <string>
#include <system_error>

namespace toposlam::io {

namespace fs = std::filesystem;

namespace {

std::string shortest(double v) {
    // Limits are floats in COccupancyGridMap2D: printing the float keeps "-10.025" readable.
    std::array<char, 32> buf{};
    const auto res = std::to_chars(buf.data(), buf.data() + buf.size(), static_cast<float>(v));
    return std::string(buf.data(), res.ptr);
}

// A value out of range, as written (no float rounding: 1e-300 is not 0).
std::string asWritten(double v) {
    std::array<char, 32> buf{};
    const auto res = std::to_chars(buf.data(), buf.data() + buf.size(), v);
    return std::string(buf.data(), res.ptr);
}

// A map_server YAML is a few lines; anything much larger is not one (and is not parsed).
constexpr std::uintmax_t kMaxYamlBytes = 1 << 20;

YAML::Node loadYaml(const std::string& yamlPath) {
    std::error_code ec;
    if (!fs::is_regular_file(yamlPath, ec))
        throw InputError(yamlPath, "file not found");
    if (fs::file_size(yamlPath, ec) > kMaxYamlBytes)
        throw InputError(yamlPath, "not a ROS map_server YAML file (larger than 1 MiB)");
    try {
        return YAML::LoadFile(yamlPath);
    } catch (const YAML::BadFile&) {
        throw InputError(yamlPath, "cannot read the file");
    } catch (const std::exception& e) {
        // yaml-cpp's message: "yaml-cpp: error at line 2, column 5: <problem>".
        std::string what = e.what();
        if (what.rfind("yaml-cpp: ", 0) == 0)
            what.erase(0, 10);
        throw InputError(yamlPath, "not a valid YAML file (" + what + ")");
    }
}

RosMapMetadata::Mode modeNamed(const std::string& mode, const std::string& yamlPath) {
    if (mode == "trinary")
        return RosMapMetadata::Mode::Trinary;
    if (mode == "scale")
        return RosMapMetadata::Mode::Scale;
    if (mode == "raw")
        return RosMapMetadata::Mode::Raw;
    throw InputError(yamlPath, "unknown mode '" + mode + "' (trinary, scale or raw)");
}

}  // namespace

RosMapMetadata readRosMapMetadata(const std::string& yamlPath) {
    const YAML::Node doc = loadYaml(yamlPath);
    if (!doc.IsMap())
        throw InputError(yamlPath, "not a ROS map_server YAML file (no keys)");
    const auto required = [&](const char* key) {
        const YAML::Node node = doc[key];
        if (!node) {
            throw InputError(yamlPath, std::string("missing key '") + key +
                                           "' (ROS map_server YAML needs image, resolution, "
                                           "origin, negate, occupied_thresh, free_thresh)");
        }
        return node;
    };
    const auto scalar = [&](const YAML::Node& node, const char* key, const char* expected) {
        if (!node.IsScalar())
            throw InputError(yamlPath, std::string("key '") + key + "' is not " + expected);
        return node.Scalar();
    };
    const auto number = [&](const YAML::Node& node, const char* key) {
        scalar(node, key, "a number");
        double v = NAN;
        try {
            v = node.as<double>();  // as map_server reads it
        } catch (const YAML::Exception&) {
        }
        if (!std::isfinite(v))
            throw InputError(yamlPath, std::string("key '") + key + "' is not a number");
        return v;
    };
    RosMapMetadata meta;
    meta.image = scalar(required("image"), "image", "a file name");
    if (meta.image.empty())
        throw InputError(yamlPath, "key 'image' is empty");
    meta.resolution = number(required("resolution"), "resolution");
    // The grid keeps it as a float, and a cell under a millimetre is no map anyone drew.
    if (!(meta.resolution >= kMinCellSize && meta.resolution <= kMaxCellSize))
        throw InputError(yamlPath, "resolution " + asWritten(meta.resolution) +
                                       " m is out of range: a number in [0.001, 100]");
    const YAML::Node origin = required("origin");
    if (!origin.IsSequence() || origin.size() != 3)
        throw InputError(yamlPath, "origin must be [x, y, yaw]");
    meta.originX = number(origin[0], "origin");
    meta.originY = number(origin[1], "origin");
    meta.originYaw = number(origin[2], "origin");
    if (std::abs(meta.originX) > kMaxMapOrigin || std::abs(meta.originY) > kMaxMapOrigin) {
        throw InputError(yamlPath, "origin " + asWritten(meta.originX) + ", " +
                                       asWritten(meta.originY) +
                                       " is out of range: each within +-1e6 m");
    }
    if (meta.originYaw != 0.0) {
        throw InputError(yamlPath, "origin yaw " + shortest(meta.originYaw) +
                                       " is not supported (only axis-aligned maps, yaw 0)");
    }
    meta.negate = number(required("negate"), "negate") != 0.0;
    meta.occupiedThresh = number(required("occupied_thresh"), "occupied_thresh");
    meta.freeThresh = number(required("free_thresh"), "free_thresh");
    if (meta.freeThresh < 0 || meta.occupiedThresh > 1 || meta.freeThresh >= meta.occupiedThresh) {
        throw InputError(yamlPath,
                         "thresholds must satisfy 0 <= free_thresh < occupied_thresh <= 1");
    }
    meta.mode =
        modeNamed(doc["mode"] ? scalar(doc["mode"], "mode", "a word") : "trinary", yamlPath);
    return meta;
}

std::string formatRosMapMetadata(const RosMapMetadata& meta) {
    const char* mode = meta.mode == RosMapMetadata::Mode::Scale ? "scale"
                       : meta.mode == RosMapMetadata::Mode::Raw ? "raw"
                                                                : "trinary";
    return "image: " + meta.image + "\nresolution: " + shortest(meta.resolution) + "\norigin: [" +
           shortest(meta.originX) + ", " + shortest(meta.originY) + ", " +
           shortest(meta.originYaw) + "]\nnegate: " + (meta.negate ? "1" : "0") +
           "\noccupied_thresh: " + shortest(meta.occupiedThresh) +
           "\nfree_thresh: " + shortest(meta.freeThresh) + "\nmode: " + mode + "\n";
}

std::string resolveRosMapImage(const std::string& yamlPath, const RosMapMetadata& meta) {
    const fs::path image(meta.image);
    if (image.is_absolute())
        return image.string();
    return (fs::path(yamlPath).parent_path() / image).string();
}

}  // namespace toposlam::io
