#pragma once
// Writes laser + odometry records as an MRPT rawlog in either of MRPT's two formats.
// Output is atomic: everything goes to a temporary file that commit() renames into place;
// a writer destroyed without commit() (e.g. by an exception) deletes it.
#include <toposlam/io/LaserLogReader.h>

#include <cstddef>
#include <memory>
#include <string>

namespace toposlam::io {

enum class RawlogFormat {
    /// [CActionCollection(CActionRobotMovement2D) , CSensoryFrame(scan)] pairs; what
    /// rbpf-slam needs. Odometry is stored only as increments: the first record's increment
    /// is zero, so reading the file back gives odometry relative to the first record
    /// (odometry_0^-1 (+) odometry_i), not the absolute values.
    SensoryFrames,
    /// CObservationOdometry + CObservation2DRangeScan, one object each; what graphslam-engine
    /// needs. icp-slam reads both. Absolute odometry is kept.
    Observations
};

/// "sf" / "obs".
const char* toString(RawlogFormat f);

class RawlogWriter {
  public:
    /// Output is gzip-compressed when `path` ends in ".gz" (MRPT reads both). Throws
    /// std::runtime_error naming `path` when the file cannot be created.
    RawlogWriter(const std::string& path, RawlogFormat format);
    ~RawlogWriter();
    RawlogWriter(const RawlogWriter&) = delete;
    RawlogWriter& operator=(const RawlogWriter&) = delete;

    /// Appends one record (2 objects). Observations format: the odometry (label "ODOMETRY",
    /// the scan's timestamp) then the scan; a record with hasOdometry == false writes the
    /// scan only. SensoryFrames format: the odometry increment since the previous record as
    /// a CActionRobotMovement2D (MRPT's default Gaussian motion model, the scan's timestamp),
    /// then a sensory frame holding the scan.
    void write(const LaserLogRecord& record);
    /// Finishes the file and moves it to its final name.
    void commit();
    /// Number of serialized top-level objects so far.
    std::size_t objectCount() const;
    RawlogFormat format() const;

  private:
    void writeRecord(const LaserLogRecord& record);

    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace toposlam::io
