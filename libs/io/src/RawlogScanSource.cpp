#include "RawlogScanSource.h"

#include <mrpt/core/Clock.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/rtti/CObject.h>
#include <toposlam/io/InputError.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <exception>

#include "MrptErrorText.h"
#include "MrptObjectCheck.h"
#include "ObjectDryRun.h"

namespace toposlam::io {

namespace {

// Observations format: a scan waits for an odometry sample at or after its time so that
// odometry can be interpolated; after this many waiting scans the last earlier sample is
// used instead (a log whose odometry stops).
constexpr std::size_t kMaxScansAwaitingOdometry = 100;

// Defined in libs/features (which depends on this library); recognised by name.
constexpr const char* kLaserFeaturesClass = "toposlam::features::CObservationLaserFeatures";

// A quoted C++ class name right after `prefix` in an MRPT error message, or "".
std::string quotedClassAfter(const std::string& text, const std::string& prefix) {
    const auto at = text.find(prefix + "'");
    if (at == std::string::npos)
        return {};
    const auto begin = at + prefix.size() + 1;
    const auto end = text.find('\'', begin);
    if (end == std::string::npos || end == begin)
        return {};
    const std::string name = text.substr(begin, end - begin);
    for (char c : name) {
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == ':'))
            return {};
    }
    return name;
}

}  // namespace

RawlogScanSource::RawlogScanSource(const std::string& path, const LaserLogOptions& options)
    : path_(path), options_(options), in_(path), lookahead_(in_), archive_(lookahead_) {
    firstObject_ = readObject();
    if (!firstObject_)
        throw InputError(path, "empty rawlog (no objects)");
    using namespace mrpt::obs;
    if (std::dynamic_pointer_cast<CActionCollection>(firstObject_) ||
        std::dynamic_pointer_cast<CSensoryFrame>(firstObject_)) {
        format_ = LaserLogFormat::RawlogSensoryFrames;
    }
}

std::string RawlogScanSource::position() const {
    // 0-based, as RawLogViewer numbers objects.
    std::string where = "object #" + std::to_string(objectsRead_);
    if (!lastClass_.empty())
        where += " (after a " + lastClass_ + ")";
    return where;
}

InputError RawlogScanSource::objectError(const std::string& className,
                                         const std::string& cause) const {
    const std::string damage = in_.streamError();
    // A first object whose class MRPT does not know: the file is probably no rawlog at all.
    if (objectsRead_ == 0 && damage.empty() &&
        (className.empty() || !mrpt::rtti::findRegisteredClass(className))) {
        return InputError(path_,
                          "neither a CARMEN log nor an MRPT rawlog (cannot read the first "
                          "object: " +
                              cause + ")");
    }
    std::string where = position();
    if (!className.empty())
        where += ", a " + className;
    if (!damage.empty())
        return InputError(path_, where + ": truncated or corrupt gzip data (" + damage + ")");
    return InputError(path_, where + ": truncated or corrupt data (" + cause + ")");
}

mrpt::serialization::CSerializable::Ptr RawlogScanSource::deserialize(const ObjectCheck& check) {
    // What MRPT may read: the checked bytes, or, for an object the check could not verify,
    // the bytes a dry run in a child process with bounded memory and time read.
    std::size_t size = check.size;
    if (!check.complete && !mrpt::rtti::findRegisteredClass(check.className))
        throw unregisteredClassError(check.className);
    if (!check.complete) {
        const DryRunResult dry = dryRunNextObject(lookahead_);
        if (!dry.ok) {
            const std::string unregistered =
                quotedClassAfter(dry.problem, "Stored object has class ");
            if (!unregistered.empty())
                throw unregisteredClassError(unregistered);
            throw objectError(check.className, dry.problem);
        }
        size = dry.size;
    }
    lookahead_.setReadLimit(size);
    struct ClearLimit {
        LookaheadStream& stream;
        ~ClearLimit() { stream.setReadLimit(std::nullopt); }
    } clearLimit{lookahead_};
    const uint64_t start = lookahead_.position();
    auto object = archive_.ReadObject();
    if (lookahead_.position() - start != size) {
        throw objectError(check.className, "MRPT read " +
                                               std::to_string(lookahead_.position() - start) +
                                               " of its " + std::to_string(size) + " bytes");
    }
    return object;
}

InputError RawlogScanSource::unregisteredClassError(const std::string& className) const {
    // A class name is an identifier; anything else read where one should be (the bytes of a
    // PNG, a NUL that would cut the message short) is shown escaped, and at most 60 of them.
    std::string shown;
    for (const char c : className.substr(0, 60)) {
        if (std::isprint(static_cast<unsigned char>(c)) != 0) {
            shown += c;
        } else {
            char hex[5];
            std::snprintf(hex, sizeof hex, "\\x%02x", static_cast<unsigned char>(c));
            shown += hex;
        }
    }
    if (className.size() > 60)
        shown += "...";
    // The first object of a file that is no rawlog at all (an image, a text file).
    if (objectsRead_ == 0 && !mrpt::rtti::findRegisteredClass(className))
        return InputError(path_,
                          "neither a CARMEN log nor an MRPT rawlog (the first object's "
                          "class would be '" +
                              shown + "')");
    return InputError(path_, position() + ": class '" + shown +
                                 "' is not registered with MRPT (it is defined by a library or "
                                 "plugin this program does not load); the rest of the rawlog "
                                 "cannot be read");
}

mrpt::serialization::CSerializable::Ptr RawlogScanSource::readObject() {
    ObjectCheck check;
    try {
        check = checkNextObject(lookahead_);
    } catch (const MalformedObject& e) {
        throw objectError(e.topClass(), e.what());
    }
    if (check.className.empty()) {
        // No byte left where an object would start: the regular end, unless the gzip data
        // stopped early.
        if (const std::string damage = in_.streamError(); !damage.empty())
            throw objectError("", damage);
        return nullptr;
    }
    try {
        auto object = deserialize(check);
        ++objectsRead_;
        lastClass_ = object ? object->GetRuntimeClass()->className : "nullptr";
        return object;
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        const std::string what = e.what();
        const std::string unregistered = quotedClassAfter(what, "Stored object has class ");
        if (!unregistered.empty())
            throw unregisteredClassError(unregistered);
        const std::string cls = quotedClassAfter(what, "parsing typed object ");
        throw objectError(cls.empty() ? check.className : cls, mrptErrorSummary(e));
    }
}

InputError RawlogScanSource::invalidContentError(const char* className,
                                                 const std::string& problem) const {
    return InputError(
        path_, "object #" + std::to_string(objectsRead_ - 1) + ", a " + className + ": " + problem);
}

void RawlogScanSource::checkFinite(const mrpt::poses::CPose2D& pose, const char* className) const {
    if (!(std::isfinite(pose.x()) && std::isfinite(pose.y()) && std::isfinite(pose.phi())))
        throw invalidContentError(className,
                                  "the odometry pose is not finite (" + pose.asString() + ")");
}

void RawlogScanSource::addScan(const mrpt::obs::CObservation2DRangeScan::Ptr& scan) {
    if (!options_.scanLabel.empty() && scan->sensorLabel != options_.scanLabel) {
        countOtherLabel(scan->sensorLabel);
        return;
    }
    // A NaN, infinite or negative distance marked valid is corrupt data, as in a CARMEN log:
    // MRPT serializes it without complaint, and the grid's insertion asserts on it later.
    for (std::size_t i = 0; i < scan->getScanSize(); ++i) {
        const float r = scan->getScanRange(i);
        if (scan->getScanRangeValidity(i) && !(std::isfinite(r) && r >= 0)) {
            throw invalidContentError(
                "CObservation2DRangeScan",
                "reading " + std::to_string(i) + " is " + std::to_string(r) + ", marked valid");
        }
    }
    pending_.push_back({scan, accumulatedActions_, nullptr, false});
}

void RawlogScanSource::attachFeatures(const mrpt::obs::CObservation::Ptr& features) {
    // The latest scan of the same time whose label begins the features' label
    // (toposlam-annotate-features: "<scan label or LASER>_FEATURES", written after the scan).
    for (auto it = pending_.rbegin(); it != pending_.rend(); ++it) {
        const auto& scan = *it->scan;
        const std::string base = scan.sensorLabel.empty() ? "LASER" : scan.sensorLabel;
        if (scan.timestamp == features->timestamp &&
            features->sensorLabel.compare(0, base.size(), base) == 0) {
            it->features = features;
            return;
        }
    }
}

void RawlogScanSource::consume(const mrpt::serialization::CSerializable::Ptr& object) {
    using namespace mrpt::obs;
    if (!object)
        return;
    for (PendingScan& p : pending_)
        p.followerRead = true;
    if (const auto actions = std::dynamic_pointer_cast<CActionCollection>(object)) {
        // SF format: odometry is the composition of the robot-movement increments.
        const auto movement = actions->getBestMovementEstimation();
        if (!movement)
            return;
        const mrpt::poses::CPose2D increment =
            movement->estimationMethod == CActionRobotMovement2D::emOdometry
                ? movement->rawOdometryIncrementReading
                : movement->poseChange->getMeanVal();
        checkFinite(increment, "CActionCollection");
        accumulatedActions_ = accumulatedActions_ ? *accumulatedActions_ + increment : increment;
    } else if (const auto frame = std::dynamic_pointer_cast<CSensoryFrame>(object)) {
        for (const auto& observation : *frame) {
            // MRPT leaves an entry it could not make (an abstract or unknown class) empty.
            if (!observation)
                throw invalidContentError("CSensoryFrame",
                                          "holds an observation MRPT could not read");
            consumeObservation(observation);
        }
    } else if (const auto observation = std::dynamic_pointer_cast<CObservation>(object)) {
        consumeObservation(observation);
    }
    // Any other object (a topological map, ...) is not part of the laser stream.
}

void RawlogScanSource::consumeObservation(const mrpt::obs::CObservation::Ptr& observation) {
    using namespace mrpt::obs;
    if (auto scan = std::dynamic_pointer_cast<CObservation2DRangeScan>(observation)) {
        addScan(scan);
    } else if (const auto odometry = std::dynamic_pointer_cast<CObservationOdometry>(observation)) {
        checkFinite(odometry->odometry, "CObservationOdometry");
        if (format_ == LaserLogFormat::RawlogObservations) {
            odometry_.add(mrpt::Clock::toDouble(odometry->timestamp), odometry->odometry);
        }
    } else if (std::string(observation->GetRuntimeClass()->className) == kLaserFeaturesClass) {
        attachFeatures(observation);
    }
    // Any other observation (images, IMU, bearing-range, ...) is not part of the laser stream.
}

bool RawlogScanSource::readyToEmit() const {
    if (pending_.empty())
        return false;
    if (end_ || format_ == LaserLogFormat::RawlogSensoryFrames)
        return true;
    if (pending_.size() > kMaxScansAwaitingOdometry)
        return true;
    // Observations format: the scan's features, if any, follow it.
    if (!pending_.front().followerRead)
        return false;
    const double t = mrpt::Clock::toDouble(pending_.front().scan->timestamp);
    return !odometry_.empty() && odometry_.lastTime() >= t;
}

void RawlogScanSource::emit(LaserLogRecord& out) {
    PendingScan p = std::move(pending_.front());
    pending_.pop_front();
    out.fileStamp = mrpt::Clock::toDouble(p.scan->timestamp);
    std::optional<mrpt::poses::CPose2D> odometry =
        format_ == LaserLogFormat::RawlogSensoryFrames ? p.odometry : odometry_.at(out.fileStamp);
    out.hasOdometry = odometry.has_value();
    out.odometry = odometry.value_or(mrpt::poses::CPose2D());
    out.scan = std::move(p.scan);
    out.storedFeatures = std::move(p.features);
}

bool RawlogScanSource::next(LaserLogRecord& out) {
    if (firstObject_)
        consume(std::move(firstObject_));
    firstObject_.reset();
    while (!readyToEmit()) {
        if (end_) {
            if (error_)
                std::rethrow_exception(error_);
            return false;
        }
        try {
            const auto object = readObject();
            if (object) {
                consume(object);
            } else {
                end_ = true;
            }
        } catch (const InputError&) {
            // The scans read before the stream broke are delivered first.
            error_ = std::current_exception();
            end_ = true;
        }
    }
    emit(out);
    return true;
}

}  // namespace toposlam::io
