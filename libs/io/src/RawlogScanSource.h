#pragma once
// MRPT rawlogs (either format, plain or gzip) as a stream of laser records, read object by
// object so that bad content is reported precisely (object index and class) instead of
// ending the stream silently as MRPT's own readers do. Every object is checked
// (MrptObjectCheck.h) before MRPT deserializes it; one the check cannot verify is first
// deserialized in a child process with bounded memory and time (ObjectDryRun.h).
#include <mrpt/serialization/CArchive.h>
#include <mrpt/serialization/CSerializable.h>
#include <toposlam/io/InputError.h>

#include <deque>
#include <exception>
#include <optional>
#include <string>

#include "GzipInputStream.h"
#include "LookaheadStream.h"
#include "MrptObjectCheck.h"
#include "OdometryTrack.h"
#include "ScanSource.h"

namespace toposlam::io {

class RawlogScanSource : public ScanSource {
  public:
    /// Reads the first object to learn the format; throws InputError if it cannot.
    RawlogScanSource(const std::string& path, const LaserLogOptions& options);

    bool next(LaserLogRecord& out) override;
    LaserLogFormat format() const override { return format_; }
    double fractionRead() const override { return lookahead_.fractionRead(); }

  private:
    struct PendingScan {
        mrpt::obs::CObservation2DRangeScan::Ptr scan;
        std::optional<mrpt::poses::CPose2D> odometry;  // SF format: accumulated actions
        mrpt::obs::CObservation::Ptr features;         // its CObservationLaserFeatures
        bool followerRead = false;  // an object after it was read: its features would be in
    };

    /// The next object, or nullptr at the clean end of the file.
    mrpt::serialization::CSerializable::Ptr readObject();
    void consume(const mrpt::serialization::CSerializable::Ptr& object);
    mrpt::serialization::CSerializable::Ptr deserialize(const ObjectCheck& check);
    /// "object #N (after a <class>)", where reading stands.
    std::string position() const;
    InputError objectError(const std::string& className, const std::string& cause) const;
    InputError unregisteredClassError(const std::string& className) const;
    /// "object #N, a <class>: <problem>" for the object just read, whole but with invalid
    /// content (MRPT serializes what it is given).
    InputError invalidContentError(const char* className, const std::string& problem) const;
    /// Throws InputError naming the object just read when `pose` (odometry) is not finite.
    void checkFinite(const mrpt::poses::CPose2D& pose, const char* className) const;
    void addScan(const mrpt::obs::CObservation2DRangeScan::Ptr& scan);
    void consumeObservation(const mrpt::obs::CObservation::Ptr& observation);
    void attachFeatures(const mrpt::obs::CObservation::Ptr& features);
    bool readyToEmit() const;
    void emit(LaserLogRecord& out);

    std::string path_;
    LaserLogOptions options_;
    GzipInputStream in_;
    LookaheadStream lookahead_;
    mrpt::serialization::CArchiveStreamBase<mrpt::io::CStream> archive_;
    LaserLogFormat format_ = LaserLogFormat::RawlogObservations;
    std::size_t objectsRead_ = 0;
    std::string lastClass_;
    mrpt::serialization::CSerializable::Ptr firstObject_;
    bool end_ = false;
    std::exception_ptr error_;  // why the stream ended, reported after the scans before it
    std::optional<mrpt::poses::CPose2D> accumulatedActions_;
    OdometryTrack odometry_;  // observations format
    std::deque<PendingScan> pending_;
};

}  // namespace toposlam::io
