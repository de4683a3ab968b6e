#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>
#include <toposlam/io/AtomicFile.h>
#include <toposlam/io/FileExtension.h>
#include <toposlam/io/RawlogWriter.h>

#include <optional>
#include <stdexcept>

namespace toposlam::io {

const char* toString(RawlogFormat f) {
    return f == RawlogFormat::SensoryFrames ? "sf" : "obs";
}

struct RawlogWriter::Impl {
    TemporaryOutputFile file;
    RawlogFormat format;
    std::unique_ptr<mrpt::io::CStream> stream;
    std::size_t objects = 0;
    std::optional<mrpt::poses::CPose2D> previousOdometry;

    Impl(const std::string& path, RawlogFormat f) : file(path), format(f) {
        const std::string& tmp = file.temporaryPath();
        const bool gz = hasExtension(path, ".gz");
        if (gz) {
            auto out = std::make_unique<mrpt::io::CFileGZOutputStream>();
            if (!out->open(tmp))
                throw std::runtime_error(path + ": cannot create the file");
            stream = std::move(out);
        } else {
            auto out = std::make_unique<mrpt::io::CFileOutputStream>();
            if (!out->open(tmp))
                throw std::runtime_error(path + ": cannot create the file");
            stream = std::move(out);
        }
    }
};

RawlogWriter::RawlogWriter(const std::string& path, RawlogFormat format)
    : impl_(std::make_unique<Impl>(path, format)) {}

RawlogWriter::~RawlogWriter() = default;

void RawlogWriter::write(const LaserLogRecord& record) {
    if (!impl_->stream)
        throw std::logic_error("RawlogWriter::write() after commit()");
    if (!record.scan)
        throw std::invalid_argument("RawlogWriter::write(): record without scan");
    try {
        writeRecord(record);
    } catch (...) {
        rethrowWriteError(impl_->file.path());
    }
}

void RawlogWriter::writeRecord(const LaserLogRecord& record) {
    auto archive = mrpt::serialization::archiveFrom(*impl_->stream);
    if (impl_->format == RawlogFormat::Observations) {
        if (record.hasOdometry) {
            mrpt::obs::CObservationOdometry odometry;
            odometry.sensorLabel = "ODOMETRY";
            odometry.timestamp = record.scan->timestamp;
            odometry.odometry = record.odometry;
            archive << odometry;
            ++impl_->objects;
        }
        archive << *record.scan;
        ++impl_->objects;
        return;
    }
    // Increment in the previous robot frame: previous^-1 (+) current. A scan without odometry
    // gets no action at all (a zero increment would read as a robot standing still).
    mrpt::obs::CActionCollection actions;
    if (record.hasOdometry) {
        mrpt::poses::CPose2D increment;
        if (impl_->previousOdometry)
            increment = record.odometry - *impl_->previousOdometry;
        impl_->previousOdometry = record.odometry;
        mrpt::obs::CActionRobotMovement2D movement;
        movement.computeFromOdometry(increment,
                                     mrpt::obs::CActionRobotMovement2D::TMotionModelOptions());
        movement.timestamp = record.scan->timestamp;
        actions.insert(movement);
    }
    mrpt::obs::CSensoryFrame frame;
    frame.insert(record.scan);
    archive << actions << frame;
    impl_->objects += 2;
}

void RawlogWriter::commit() {
    if (!impl_->stream)
        return;
    impl_->stream.reset();  // closes (and flushes) the file
    impl_->file.commit();
}

std::size_t RawlogWriter::objectCount() const {
    return impl_->objects;
}

RawlogFormat RawlogWriter::format() const {
    return impl_->format;
}

}  // namespace toposlam::io
