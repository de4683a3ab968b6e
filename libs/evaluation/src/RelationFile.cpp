#include <toposlam/evaluation/RelationFile.h>
#include <toposlam/io/AtomicFile.h>
#include <toposlam/io/InputError.h>
#include <toposlam/io/MirrorImage.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace toposlam::evaluation {

namespace {

constexpr int kFieldsPerLine = 8;  // t1 t2 x y z roll pitch yaw

// Parses the whole token as a finite double (std::stod would accept "1.5abc").
bool parseFinite(const std::string& token, double& value) {
    errno = 0;
    char* end = nullptr;
    value = std::strtod(token.c_str(), &end);
    return end != token.c_str() && *end == '\0' && errno != ERANGE && std::isfinite(value);
}

bool isBlankOrComment(const std::string& line) {
    const auto first = line.find_first_not_of(" \t\r");
    return first == std::string::npos || line[first] == '#';
}

}  // namespace

PoseRelations loadRelations(const std::string& path) {
    std::ifstream in(path);
    if (!in)
        throw io::InputError(path, "cannot open the relation file");

    PoseRelations relations;
    std::string line;
    for (std::size_t lineNo = 1; std::getline(in, line); ++lineNo) {
        if (isBlankOrComment(line))
            continue;
        std::istringstream tokens(line);
        double v[kFieldsPerLine];
        int n = 0;
        for (std::string token; tokens >> token; ++n) {
            if (n >= kFieldsPerLine)
                continue;  // extra fields are only counted
            if (!parseFinite(token, v[n])) {
                throw io::InputError(path, "line " + std::to_string(lineNo) + ": field " +
                                               std::to_string(n + 1) + " '" + token +
                                               "' is not a finite number");
            }
        }
        if (n != kFieldsPerLine) {
            throw io::InputError(path,
                                 "line " + std::to_string(lineNo) +
                                     ": expected 8 fields 't1 t2 x y z roll pitch yaw', got " +
                                     std::to_string(n));
        }
        if (v[4] != 0 || v[5] != 0 || v[6] != 0) {
            throw io::InputError(path, "line " + std::to_string(lineNo) +
                                           ": z, roll and pitch must be 0 (2D relations only)");
        }
        relations.push_back({v[0], v[1], mrpt::math::TPose2D(v[2], v[3], v[7])});
    }
    if (in.bad())
        throw io::InputError(path, "read error");
    if (relations.empty())
        throw io::InputError(path, "no relation in the file");
    return relations;
}

std::size_t countRepeatedRelations(const PoseRelations& relations) {
    using Key = std::array<double, 5>;
    std::vector<Key> keys;
    keys.reserve(relations.size());
    for (const PoseRelation& r : relations)
        keys.push_back({r.stamp1, r.stamp2, r.motion.x, r.motion.y, r.motion.phi});
    std::sort(keys.begin(), keys.end());
    return static_cast<std::size_t>(keys.end() - std::unique(keys.begin(), keys.end()));
}

PoseRelations mirroredRelations(const PoseRelations& relations) {
    PoseRelations out = relations;
    for (PoseRelation& r : out)
        r.motion = io::mirroredPose(r.motion);
    return out;
}

void saveRelations(const PoseRelations& relations, const std::string& path) {
    io::writeFileAtomically(path, [&](const std::string& tmp) {
        std::FILE* f = std::fopen(tmp.c_str(), "w");
        if (!f)
            throw std::runtime_error(path + ": cannot write the relation file");
        for (const PoseRelation& r : relations) {
            std::fprintf(f, "%.6f %.6f %.9f %.9f 0.000000 0.000000 0.000000 %.9f\n", r.stamp1,
                         r.stamp2, r.motion.x, r.motion.y, r.motion.phi);
        }
        const bool ok = std::ferror(f) == 0;
        if (std::fclose(f) != 0 || !ok) {
            throw std::runtime_error(path + ": error writing the relation file");
        }
    });
}

}  // namespace toposlam::evaluation
