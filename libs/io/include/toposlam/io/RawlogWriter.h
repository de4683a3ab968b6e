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
    /// rbpf-slam needs.
    SensoryFrames,
    /// CObservationOdometry + CObservation2DRangeScan, one object each; what graphslam-engine
    /// needs. icp-slam reads both.
    Observations
};

class RawlogWriter {
public:
    /// Output is gzip-compressed when `path` ends in ".gz" (MRPT reads both).
    RawlogWriter(const std::string& path, RawlogFormat format);
    ~RawlogWriter();
    RawlogWriter(const RawlogWriter&) = delete;
    RawlogWriter& operator=(const RawlogWriter&) = delete;

    /// Appends one record. Observations format: the odometry (label "ODOMETRY", same timestamp)
    /// then the scan. SensoryFrames format: the odometry increment since the previous record
    /// as a CActionRobotMovement2D, then a sensory frame holding the scan.
    void write(const LaserLogRecord& record);
    /// Finishes the file and moves it to its final name.
    void commit();
    /// Number of serialized top-level objects so far.
    std::size_t objectCount() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace toposlam::io
