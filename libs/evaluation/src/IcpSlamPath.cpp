#include <mrpt/core/Clock.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>
#include <toposlam/evaluation/IcpSlamPath.h>
#include <toposlam/io/InputError.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace toposlam::evaluation {

namespace {

using mrpt::obs::CActionCollection;
using mrpt::obs::CObservation;
using mrpt::obs::CObservation2DRangeScan;
using mrpt::obs::CSensoryFrame;

bool parseFinite(const std::string& token, double& value) {
    errno = 0;
    char* end = nullptr;
    value = std::strtod(token.c_str(), &end);
    return end != token.c_str() && *end == '\0' && errno != ERANGE && std::isfinite(value);
}

struct PathLine {
    std::size_t step;
    mrpt::math::TPose2D pose;
};

// log_estimated_path.txt: "%i %f %f %f" = step x y yaw, steps 0, 1, 2, ...
std::vector<PathLine> readPathFile(const std::string& path) {
    std::ifstream in(path);
    if (!in)
        throw io::InputError(path, "cannot open the icp-slam path file");
    std::vector<PathLine> lines;
    std::string line;
    for (std::size_t lineNo = 1; std::getline(in, line); ++lineNo) {
        if (line.find_first_not_of(" \t\r") == std::string::npos)
            continue;
        std::istringstream tokens(line);
        std::string t[5];
        int n = 0;
        while (n < 5 && tokens >> t[n])
            ++n;
        double v[4];
        const auto where = "line " + std::to_string(lineNo) + ": ";
        if (n != 4) {
            throw io::InputError(path, where +
                                           "expected 4 fields 'step x y yaw' (MRPT icp-slam's "
                                           "log_estimated_path.txt)");
        }
        for (int i = 0; i < 4; ++i) {
            if (!parseFinite(t[i], v[i])) {
                throw io::InputError(path, where + "'" + t[i] + "' is not a finite number");
            }
        }
        if (v[0] != static_cast<double>(lines.size())) {
            throw io::InputError(
                path, where + "step " + t[0] + ", expected " + std::to_string(lines.size()));
        }
        lines.push_back({lines.size(), mrpt::math::TPose2D(v[1], v[2], v[3])});
    }
    if (in.bad())
        throw io::InputError(path, "read error");
    return lines;
}

}  // namespace

IcpSlamSteps icpSlamStepsOf(const std::string& rawlogPath) {
    if (!std::filesystem::is_regular_file(rawlogPath)) {
        throw io::InputError(rawlogPath, "cannot open the rawlog");
    }
    mrpt::io::CFileGZInputStream file;
    if (!file.open(rawlogPath))
        throw io::InputError(rawlogPath, "cannot open the rawlog");
    auto archive = mrpt::serialization::archiveFrom(file);

    // Mirrors CRawlog::getActionObservationPairOrObservation (MRPT 2.5.8): an observation is an
    // entry of its own; an action collection waits for the next sensory frame, and the pair is
    // one entry; everything else is skipped.
    IcpSlamSteps steps;
    bool actionWaitsForFrame = false;
    for (std::size_t object = 0;; ++object) {
        mrpt::serialization::CSerializable::Ptr obj;
        try {
            obj = archive.ReadObject();
        } catch (const mrpt::serialization::CExceptionEOF&) {
            break;
        } catch (const std::exception& e) {
            throw io::InputError(
                rawlogPath, "object " + std::to_string(object) + " cannot be read: " + e.what());
        }
        if (!obj)
            continue;
        CObservation2DRangeScan::Ptr scan;
        if (actionWaitsForFrame) {
            if (obj->GetRuntimeClass() != CLASS_ID(CSensoryFrame))
                continue;
            actionWaitsForFrame = false;
            scan = std::dynamic_pointer_cast<CSensoryFrame>(obj)
                       ->getObservationByClass<CObservation2DRangeScan>();
        } else if (IS_CLASS(*obj, CActionCollection)) {
            actionWaitsForFrame = true;
            continue;
        } else if (IS_DERIVED(*obj, CObservation)) {
            if (IS_CLASS(*obj, CObservation2DRangeScan)) {
                scan = std::dynamic_pointer_cast<CObservation2DRangeScan>(obj);
            }
        } else {
            continue;
        }
        if (scan)
            steps.scans.push_back({steps.totalSteps, mrpt::Clock::toDouble(scan->timestamp)});
        ++steps.totalSteps;
    }
    return steps;
}

io::Trajectory2D loadIcpSlamPath(const std::string& pathFile, const std::string& rawlogPath,
                                 const std::vector<double>* scanStamps) {
    const std::vector<PathLine> lines = readPathFile(pathFile);
    const IcpSlamSteps steps = icpSlamStepsOf(rawlogPath);
    if (lines.size() != steps.totalSteps) {
        throw io::InputError(pathFile, "has " + std::to_string(lines.size()) +
                                           " poses, but icp-slam writes " +
                                           std::to_string(steps.totalSteps) + " for " + rawlogPath +
                                           " (one per entry): not a complete "
                                           "icp-slam run on that rawlog");
    }
    if (scanStamps && scanStamps->size() != steps.scans.size()) {
        throw io::InputError(rawlogPath, "has " + std::to_string(steps.scans.size()) +
                                             " scans, but " + std::to_string(scanStamps->size()) +
                                             " scan stamps were given");
    }
    io::Trajectory2D trajectory;
    trajectory.reserve(steps.scans.size());
    for (std::size_t k = 0; k < steps.scans.size(); ++k) {
        const double stamp = scanStamps ? (*scanStamps)[k] : steps.scans[k].stamp;
        trajectory.push_back({stamp, lines[steps.scans[k].step].pose});
    }
    return trajectory;
}

}  // namespace toposlam::evaluation
