#include <toposlam/io/AtomicFile.h>
#include <toposlam/io/InputError.h>
#include <toposlam/io/Trajectory.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

namespace toposlam::io {

namespace {

// Shortest decimal text that parses back to exactly `v` (C++17 std::to_chars).
void appendShortest(std::string& out, double v) {
    std::array<char, 32> buf{};
    const auto res = std::to_chars(buf.data(), buf.data() + buf.size(), v);
    out.append(buf.data(), res.ptr);
}

// The same without an exponent where it fits: a time stamp of 1700000000 s reads as such, not
// as 1.7e+09 among the 1700000000.75 of the lines after it.
void appendShortestFixed(std::string& out, double v) {
    std::array<char, 32> buf{};
    const auto res =
        std::to_chars(buf.data(), buf.data() + buf.size(), v, std::chars_format::fixed);
    if (res.ec != std::errc())
        return appendShortest(out, v);
    out.append(buf.data(), res.ptr);
}

bool isBlankOrComment(const std::string& line) {
    const auto first = line.find_first_not_of(" \t\r");
    return first == std::string::npos || line[first] == '#';
}

}  // namespace

Trajectory2D loadTrajectory(const std::string& path) {
    std::ifstream in(path);
    if (!in)
        throw InputError(path, "cannot open the trajectory file (missing or unreadable)");
    Trajectory2D trajectory;
    std::string line;
    for (std::size_t lineNo = 1; std::getline(in, line); ++lineNo) {
        if (isBlankOrComment(line))
            continue;
        std::array<double, 4> v{};
        std::size_t nFields = 0;
        const char* p = line.c_str();
        const char* end = p + line.size();
        while (true) {
            while (p < end && (*p == ' ' || *p == '\t' || *p == '\r'))
                ++p;
            if (p >= end)
                break;
            char* next = nullptr;
            const double x = std::strtod(p, &next);
            if (next == p) {
                throw InputError(path, "line " + std::to_string(lineNo) + ": not a number: '" +
                                           std::string(p, std::min<std::size_t>(end - p, 20)) +
                                           "' (expected 'timestamp x y yaw')");
            }
            if (nFields < v.size())
                v[nFields] = x;
            ++nFields;
            p = next;
        }
        if (nFields != 4) {
            throw InputError(path, "line " + std::to_string(lineNo) + ": " +
                                       std::to_string(nFields) +
                                       " fields, expected 4 ('timestamp x y yaw')");
        }
        for (double x : v) {
            if (!std::isfinite(x)) {
                throw InputError(
                    path, "line " + std::to_string(lineNo) + ": non-finite value (NaN or inf)");
            }
        }
        trajectory.push_back({v[0], mrpt::math::TPose2D(v[1], v[2], v[3])});
    }
    if (in.bad())
        throw InputError(path, "read error");
    return trajectory;
}

void saveTrajectory(const Trajectory2D& trajectory, const std::string& path) {
    writeFileAtomically(path, [&](const std::string& tmp) {
        std::FILE* f = std::fopen(tmp.c_str(), "w");
        if (!f)
            throw std::runtime_error(path + ": cannot create the trajectory file");
        std::string text = "# timestamp x y yaw\n";
        for (const TimedPose2D& p : trajectory) {
            appendShortestFixed(text, p.stamp);
            text += ' ';
            appendShortest(text, p.pose.x);
            text += ' ';
            appendShortest(text, p.pose.y);
            text += ' ';
            appendShortest(text, p.pose.phi);
            text += '\n';
        }
        const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
        if (std::fclose(f) != 0 || !ok) {
            throw std::runtime_error(path + ": error while writing the trajectory file");
        }
    });
}

}  // namespace toposlam::io
