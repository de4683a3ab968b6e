#include <mrpt/core/Clock.h>
#include <toposlam/io/InputError.h>
#include <toposlam/io/LaserLogReader.h>
#include <toposlam/io/UprightScan.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "CarmenScanSource.h"
#include "GzipInputStream.h"
#include "RawlogScanSource.h"

namespace toposlam::io {

namespace {

// CARMEN logs are text; rawlogs are binary (every object starts with a byte >= 0x80, or
// with a NUL-padded header in pre-2007 files). Look at the first decompressed bytes.
bool looksLikeText(const std::string& path) {
    GzipInputStream in(path);
    unsigned char head[512];
    const std::size_t n = in.Read(head, sizeof head);
    if (n == 0)
        throw InputError(path, "file is empty");
    for (std::size_t i = 0; i < n; ++i) {
        const unsigned char c = head[i];
        if (!(c == '\n' || c == '\r' || c == '\t' || (c >= 0x20 && c < 0x7f)))
            return false;
    }
    return true;
}

}  // namespace

mrpt::obs::CObservationOdometry::Ptr LaserLogRecord::odometryObservation() const {
    if (!hasOdometry)
        return nullptr;
    auto observation = mrpt::obs::CObservationOdometry::Create();
    observation->odometry = odometry;
    observation->timestamp = scan->timestamp;
    observation->sensorLabel = "ODOMETRY";
    return observation;
}

const char* toString(LaserLogFormat f) {
    switch (f) {
        case LaserLogFormat::RawlogSensoryFrames:
            return "rawlog (actions/sensory frames)";
        case LaserLogFormat::RawlogObservations:
            return "rawlog (observations)";
        case LaserLogFormat::Carmen:
            return "CARMEN";
    }
    return "?";
}

struct LaserLogReader::Impl {
    std::string path;
    std::unique_ptr<ScanSource> source;
    std::size_t count = 0;
    std::size_t adjusted = 0;
    std::size_t upsideDown = 0;
    double lastTime = -INFINITY;
    bool oneLaser = false;
    bool labelChosen = false;  // oneLaser: label is the one to keep (it may be "")
    std::string label;         // kept scans' label (oneLaser or scanLabel)
    std::map<std::string, std::size_t> others;
};

LaserLogReader::LaserLogReader(const std::string& path, const LaserLogOptions& options)
    : impl_(std::make_unique<Impl>()) {
    impl_->path = path;
    if (looksLikeText(path)) {
        impl_->source = std::make_unique<CarmenScanSource>(path, options);
    } else {
        impl_->source = std::make_unique<RawlogScanSource>(path, options);
    }
    impl_->label = options.scanLabel;
    impl_->oneLaser = options.oneLaser && options.scanLabel.empty();
    if (impl_->oneLaser) {
        impl_->label = impl_->source->preferredLaser();
        impl_->labelChosen = !impl_->label.empty();
    }
}

LaserLogReader::~LaserLogReader() = default;

bool LaserLogReader::next(LaserLogRecord& out) {
    for (;;) {
        out.storedFeatures.reset();
        if (!impl_->source->next(out))
            return false;
        if (!impl_->oneLaser)
            break;
        if (!impl_->labelChosen) {
            impl_->label = out.scan->sensorLabel;
            impl_->labelChosen = true;
        }
        if (out.scan->sensorLabel == impl_->label)
            break;
        ++impl_->others[out.scan->sensorLabel];
    }
    out.index = impl_->count++;
    if (makeUpright(*out.scan)) {
        ++impl_->upsideDown;
        out.storedFeatures.reset();  // extracted in the mirrored frame: extract them again
    }
    // Strictly increasing acquisition times (CARMEN times are already repaired).
    double t = mrpt::Clock::toDouble(out.scan->timestamp);
    if (!(t > impl_->lastTime)) {
        t = impl_->lastTime + 1e-6;
        out.scan->timestamp = mrpt::Clock::fromDouble(t);
    }
    impl_->lastTime = t;
    if (std::abs(t - out.fileStamp) > 1e-6)
        ++impl_->adjusted;
    return true;
}

LaserLogFormat LaserLogReader::format() const {
    return impl_->source->format();
}

const std::string& LaserLogReader::path() const {
    return impl_->path;
}

double LaserLogReader::fractionRead() const {
    return impl_->source->fractionRead();
}

std::size_t LaserLogReader::adjustedTimestamps() const {
    return impl_->adjusted;
}

std::size_t LaserLogReader::upsideDownScans() const {
    return impl_->upsideDown;
}

const std::string& LaserLogReader::laserLabel() const {
    return impl_->label;
}

const std::map<std::string, std::size_t>& LaserLogReader::otherLaserScans() const {
    return impl_->others;
}

std::string LaserLogReader::noScansProblem() const {
    const auto& others = impl_->source->scansOfOtherLabels();
    if (impl_->oneLaser || impl_->label.empty() || others.empty())
        return "no laser scans in the log";
    std::string list;
    for (const auto& [label, count] : others) {
        list += (list.empty() ? "" : ", ") + (label.empty() ? std::string("''") : label) + ": " +
                std::to_string(count);
    }
    return "no laser scans labelled '" + impl_->label + "' in the log (it has " + list + ")";
}

std::vector<LaserLogRecord> LaserLogReader::readAll(const std::string& path,
                                                    const LaserLogOptions& options) {
    LaserLogReader reader(path, options);
    std::vector<LaserLogRecord> records;
    LaserLogRecord record;
    while (reader.next(record))
        records.push_back(std::move(record));
    return records;
}

}  // namespace toposlam::io
