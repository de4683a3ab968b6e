#include "RosMapMetadata.h"

#include <mrpt/containers/yaml.h>
#include <toposlam/io/InputError.h>

#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <string>

namespace toposlam::io {

namespace fs = std::filesystem;

namespace {

std::string shortest(double v) {
    // Limits are floats in COccupancyGridMap2D: printing the float keeps "-10.025" readable.
    std::array<char, 32> buf{};
    const auto res = std::to_chars(buf.data(), buf.data() + buf.size(), static_cast<float>(v));
    return std::string(buf.data(), res.ptr);
}

}  // namespace

RosMapMetadata readRosMapMetadata(const std::string& yamlPath) {
    if (!fs::is_regular_file(yamlPath))
        throw InputError(yamlPath, "file not found");
    mrpt::containers::yaml doc;
    try {
        doc = mrpt::containers::yaml::FromFile(yamlPath);
    } catch (const std::exception&) {
        throw InputError(yamlPath, "not a valid YAML file");
    }
    if (!doc.isMap())
        throw InputError(yamlPath, "not a ROS map_server YAML file (no keys)");

    RosMapMetadata meta;
    const auto required = [&](const char* key) {
        if (!doc.has(key)) {
            throw InputError(yamlPath, std::string("missing key '") + key +
                                           "' (ROS map_server YAML needs image, resolution, "
                                           "origin, negate, occupied_thresh, free_thresh)");
        }
        return doc[key];
    };
    const auto number = [&](const char* key) {
        try {
            const double v = required(key).as<double>();
            if (!std::isfinite(v))
                throw std::runtime_error("not finite");
            return v;
        } catch (const InputError&) {
            throw;
        } catch (const std::exception&) {
            throw InputError(yamlPath, std::string("key '") + key + "' is not a number");
        }
    };
    try {
        meta.image = required("image").as<std::string>();
    } catch (const InputError&) {
        throw;
    } catch (const std::exception&) {
        throw InputError(yamlPath, "key 'image' is not a file name");
    }
    meta.resolution = number("resolution");
    if (!(meta.resolution > 0))
        throw InputError(yamlPath, "resolution must be > 0");

    std::vector<double> origin;
    try {
        origin = required("origin").toStdVector<double>();
    } catch (const InputError&) {
        throw;
    } catch (const std::exception&) {
        origin.clear();
    }
    if (origin.size() != 3)
        throw InputError(yamlPath, "origin must be [x, y, yaw]");
    meta.originX = origin[0];
    meta.originY = origin[1];
    meta.originYaw = origin[2];
    if (meta.originYaw != 0.0) {
        throw InputError(yamlPath, "origin yaw " + shortest(meta.originYaw) +
                                       " is not supported (only axis-aligned maps, yaw 0)");
    }
    meta.negate = number("negate") != 0.0;
    meta.occupiedThresh = number("occupied_thresh");
    meta.freeThresh = number("free_thresh");
    if (meta.freeThresh < 0 || meta.occupiedThresh > 1 || meta.freeThresh >= meta.occupiedThresh) {
        throw InputError(yamlPath,
                         "thresholds must satisfy 0 <= free_thresh < occupied_thresh <= 1");
    }
    std::string mode = "trinary";
    if (doc.has("mode"))
        mode = doc["mode"].as<std::string>();
    if (mode == "trinary") {
        meta.mode = RosMapMetadata::Mode::Trinary;
    } else if (mode == "scale") {
        meta.mode = RosMapMetadata::Mode::Scale;
    } else if (mode == "raw") {
        meta.mode = RosMapMetadata::Mode::Raw;
    } else {
        throw InputError(yamlPath, "unknown mode '" + mode + "' (trinary, scale or raw)");
    }
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
