#pragma once
// MRPT rawlogs (either format, plain or gzip) as a stream of laser records, read object by
// object so that bad content is reported precisely (object index and class) instead of
// ending the stream silently as MRPT's own readers do.
#include <mrpt/serialization/CArchive.h>
#include <mrpt/serialization/CSerializable.h>

#include <deque>
#include <optional>
#include <string>

#include "GzipInputStream.h"
#include "ScanSource.h"

namespace toposlam::io {

class RawlogScanSource : public ScanSource {
  public:
    /// Reads the first object to learn the format; throws InputError if it cannot.
    RawlogScanSource(const std::string& path, const LaserLogOptions& options);

    bool next(LaserLogRecord& out) override;
    LaserLogFormat format() const override { return format_; }
    double fractionRead() const override { return in_.fractionRead(); }

  private:
    struct OdometrySample {
        double time;  // s
        mrpt::poses::CPose2D pose;
    };
    struct PendingScan {
        mrpt::obs::CObservation2DRangeScan::Ptr scan;
        std::optional<mrpt::poses::CPose2D> odometry;  // SF format: accumulated actions
    };

    /// The next object, or nullptr at the clean end of the file.
    mrpt::serialization::CSerializable::Ptr readObject();
    void consume(const mrpt::serialization::CSerializable::Ptr& object);
    void addScan(const mrpt::obs::CObservation2DRangeScan::Ptr& scan);
    bool readyToEmit() const;
    void emit(LaserLogRecord& out);
    std::optional<mrpt::poses::CPose2D> odometryAt(double time);

    std::string path_;
    LaserLogOptions options_;
    GzipInputStream in_;
    mrpt::serialization::CArchiveStreamBase<mrpt::io::CStream> archive_;
    LaserLogFormat format_ = LaserLogFormat::RawlogObservations;
    std::size_t objectsRead_ = 0;
    std::string lastClass_;
    mrpt::serialization::CSerializable::Ptr firstObject_;
    bool end_ = false;
    std::optional<mrpt::poses::CPose2D> accumulatedActions_;
    std::deque<OdometrySample> odometry_;
    std::deque<PendingScan> pending_;
};

}  // namespace toposlam::io
