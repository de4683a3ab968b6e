#include <mrpt/core/bits_math.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>
#include <toposlam/features/CObservationLaserFeatures.h>
#include <toposlam/features/CornerBearingRange.h>
#include <toposlam/features/LogAnnotation.h>
#include <toposlam/io/AtomicFile.h>
#include <toposlam/io/FileExtension.h>
#include <toposlam/io/InputError.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>

namespace toposlam::features {

void MotionNoise::validate() const {
    // Upper limits far beyond any real odometry: larger values are typing mistakes.
    const struct {
        const char* name;
        double value, max;
        bool positive;
    } values[] = {{"a1 (m/m)", a1, 1.0, false},     {"a2 (m/deg)", a2, 1.0, false},
                  {"a3 (deg/m)", a3, 90.0, false},  {"a4 (deg/deg)", a4, 1.0, false},
                  {"minXY (m)", minXY, 10.0, true}, {"minPhi (deg)", minPhi, 180.0, true}};
    for (const auto& v : values) {
        const bool tooSmall = v.positive ? !(v.value > 0) : !(v.value >= 0);
        if (!std::isfinite(v.value) || tooSmall || v.value > v.max) {
            throw std::invalid_argument(std::string("odometry noise ") + v.name + " = " +
                                        std::to_string(v.value) +
                                        " is out of range: " + (v.positive ? "(0, " : "[0, ") +
                                        std::to_string(v.max) + "]" +
                                        (v.positive ? " (zero would make a Kalman filter trust "
                                                      "odometry blindly)"
                                                    : ""));
        }
    }
}

mrpt::obs::CActionRobotMovement2D::TMotionModelOptions MotionNoise::toMrpt() const {
    // CActionRobotMovement2D computes std_xy = minStdXY + a1*d + a2*|dphi| and
    // std_phi = minStdPHI + a3*d + a4*|dphi| with d in m and dphi in RADIANS.
    mrpt::obs::CActionRobotMovement2D::TMotionModelOptions o;
    o.modelSelection = mrpt::obs::CActionRobotMovement2D::mmGaussian;
    o.gaussianModel.a1 = a1;
    o.gaussianModel.a2 = mrpt::RAD2DEG(a2);  // m/deg -> m/rad
    o.gaussianModel.a3 = mrpt::DEG2RAD(a3);  // deg/m -> rad/m
    o.gaussianModel.a4 = a4;                 // deg/deg = rad/rad
    o.gaussianModel.minStdXY = minXY;
    o.gaussianModel.minStdPHI = mrpt::DEG2RAD(minPhi);
    return o;
}

namespace {

std::unique_ptr<mrpt::io::CStream> openOutput(const std::string& path, const std::string& tmp) {
    const bool gz = io::hasExtension(path, ".gz");
    if (gz) {
        auto f = std::make_unique<mrpt::io::CFileGZOutputStream>();
        if (!f->open(tmp))
            throw std::runtime_error(path + ": cannot create the file");
        return f;
    }
    auto f = std::make_unique<mrpt::io::CFileOutputStream>();
    if (!f->open(tmp))
        throw std::runtime_error(path + ": cannot create the file");
    return f;
}

/// Writes one annotated scan at a time in the chosen format. The observation objects are
/// made once and reused for every scan (a sensory frame holds shared pointers).
class AnnotatedLogWriter {
  public:
    AnnotatedLogWriter(mrpt::serialization::CArchive& out, const LogAnnotationOptions& options)
        : out_(out), options_(options), motionModel_(options.motionNoise.toMrpt()) {
        odometry_->sensorLabel = "ODOMETRY";
    }

    CObservationLaserFeatures& features() { return *features_; }

    /// Writes the scan of `record` with features() (already filled); returns objects written.
    std::size_t write(const io::LaserLogRecord& record) {
        const mrpt::obs::CObservation2DRangeScan& scan = *record.scan;
        // Scans without a label (old rawlogs) get "LASER" as the base of ours.
        const std::string base = scan.sensorLabel.empty() ? "LASER" : scan.sensorLabel;
        features_->timestamp = scan.timestamp;
        features_->sensorLabel = base + options_.featuresLabelSuffix;
        features_->scanLabel = scan.sensorLabel;
        features_->sensorPose = scan.sensorPose;
        cornersToBearingRange(features_->features, scan, *corners_);
        corners_->sensorLabel = base + options_.cornersLabelSuffix;
        for (const auto& m : corners_->sensedData) {
            rangeVariance += m.covariance(0, 0);
            bearingVariance += m.covariance(1, 1);
        }
        const bool frames = options_.format == io::RawlogFormat::SensoryFrames;
        return frames ? writeFrame(record) : writeObservations(record);
    }

    /// Sums over every corner so far of its range (m^2) and bearing (rad^2) variances.
    double rangeVariance = 0, bearingVariance = 0;

  private:
    std::size_t writeObservations(const io::LaserLogRecord& record) {
        std::size_t objects = 2;
        if (record.hasOdometry) {
            odometry_->timestamp = record.scan->timestamp;
            odometry_->odometry = record.odometry;
            out_ << *odometry_;
            ++objects;
        }
        out_ << *record.scan << *features_;
        if (options_.bearingRange) {
            out_ << *corners_;
            ++objects;
        }
        return objects;
    }

    std::size_t writeFrame(const io::LaserLogRecord& record) {
        // The odometry increment in the previous robot frame: previous^-1 (+) current.
        mrpt::poses::CPose2D increment;
        if (record.hasOdometry) {
            if (previousOdometry_)
                increment = record.odometry - *previousOdometry_;
            previousOdometry_ = record.odometry;
        }
        mrpt::obs::CActionRobotMovement2D movement;
        movement.computeFromOdometry(increment, motionModel_);
        movement.timestamp = record.scan->timestamp;
        actions_.clear();
        actions_.insert(movement);
        frame_.clear();
        frame_.insert(record.scan);
        frame_.insert(features_);
        frame_.insert(corners_);
        out_ << actions_ << frame_;
        return 2;
    }

    mrpt::serialization::CArchive& out_;
    const LogAnnotationOptions& options_;
    const mrpt::obs::CActionRobotMovement2D::TMotionModelOptions motionModel_;
    CObservationLaserFeatures::Ptr features_ = CObservationLaserFeatures::Create();
    mrpt::obs::CObservationBearingRange::Ptr corners_ =
        mrpt::obs::CObservationBearingRange::Create();
    mrpt::obs::CObservationOdometry::Ptr odometry_ = mrpt::obs::CObservationOdometry::Create();
    mrpt::obs::CActionCollection actions_;
    mrpt::obs::CSensoryFrame frame_;
    std::optional<mrpt::poses::CPose2D> previousOdometry_;
};

}  // namespace

LogAnnotationSummary annotateLog(const std::string& inputPath, const std::string& outputPath,
                                 FeatureExtractor& extractor, const LogAnnotationOptions& options) {
    options.motionNoise.validate();
    LogAnnotationSummary summary;
    io::LaserLogReader reader(inputPath, options.read);
    summary.inputFormat = reader.format();

    io::writeFileAtomically(outputPath, [&](const std::string& tmp) {
        const std::unique_ptr<mrpt::io::CStream> stream = openOutput(outputPath, tmp);
        auto out = mrpt::serialization::archiveFrom(*stream);
        AnnotatedLogWriter writer(out, options);
        writer.features().extractor = extractor.name();
        io::LaserLogRecord record;
        while ((options.maxScans == 0 || summary.scans < options.maxScans) && reader.next(record)) {
            ScanFeatures& f = writer.features().features;
            const auto start = std::chrono::steady_clock::now();
            extractor.extract(*record.scan, f);
            summary.extractionSeconds +=
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            summary.objects += writer.write(record);
            if (options.onScan)
                options.onScan(record, f);
            ++summary.scans;
            summary.segments += f.segments.size();
            summary.corners += f.corners.size();
            summary.endpoints += f.endpoints.size();
            if (options.progress)
                options.progress(reader.fractionRead(), summary.scans);
        }
        if (summary.scans == 0)
            throw io::InputError(inputPath, reader.noScansProblem());
        if (summary.corners > 0) {
            const double n = static_cast<double>(summary.corners);
            summary.cornerRangeStd = std::sqrt(writer.rangeVariance / n);
            summary.cornerBearingStd = std::sqrt(writer.bearingVariance / n);
        }
    });
    return summary;
}

}  // namespace toposlam::features
