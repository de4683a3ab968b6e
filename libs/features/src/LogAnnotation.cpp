#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/serialization/CArchive.h>
#include <toposlam/features/CObservationLaserFeatures.h>
#include <toposlam/features/CornerBearingRange.h>
#include <toposlam/features/LogAnnotation.h>
#include <toposlam/io/AtomicFile.h>
#include <toposlam/io/InputError.h>

#include <chrono>
#include <memory>
#include <stdexcept>

namespace toposlam::features {

LogAnnotationSummary annotateLog(const std::string& inputPath, const std::string& outputPath,
                                 FeatureExtractor& extractor, const LogAnnotationOptions& options) {
    LogAnnotationSummary summary;
    io::LaserLogReader reader(inputPath, options.read);
    summary.inputFormat = reader.format();
    const bool gz =
        outputPath.size() >= 3 && outputPath.compare(outputPath.size() - 3, 3, ".gz") == 0;

    io::writeFileAtomically(outputPath, [&](const std::string& tmp) {
        std::unique_ptr<mrpt::io::CStream> stream;
        if (gz) {
            auto f = std::make_unique<mrpt::io::CFileGZOutputStream>();
            if (!f->open(tmp))
                throw std::runtime_error(outputPath + ": cannot create the file");
            stream = std::move(f);
        } else {
            auto f = std::make_unique<mrpt::io::CFileOutputStream>();
            if (!f->open(tmp))
                throw std::runtime_error(outputPath + ": cannot create the file");
            stream = std::move(f);
        }
        auto out = mrpt::serialization::archiveFrom(*stream);

        io::LaserLogRecord record;
        CObservationLaserFeatures annotated;
        annotated.extractor = extractor.name();
        mrpt::obs::CObservationBearingRange corners;
        mrpt::obs::CObservationOdometry odometry;
        odometry.sensorLabel = "ODOMETRY";
        while ((options.maxScans == 0 || summary.scans < options.maxScans) && reader.next(record)) {
            const mrpt::obs::CObservation2DRangeScan& scan = *record.scan;
            if (record.hasOdometry) {
                odometry.timestamp = scan.timestamp;
                odometry.odometry = record.odometry;
                out << odometry;
                ++summary.objects;
            }
            out << scan;
            ++summary.objects;

            const auto start = std::chrono::steady_clock::now();
            extractor.extract(scan, annotated.features);
            summary.extractionSeconds +=
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            // Scans without a label (old rawlogs) get "LASER" as the base of ours.
            const std::string base = scan.sensorLabel.empty() ? "LASER" : scan.sensorLabel;
            annotated.timestamp = scan.timestamp;
            annotated.sensorLabel = base + options.featuresLabelSuffix;
            annotated.scanLabel = scan.sensorLabel;
            annotated.sensorPose = scan.sensorPose;
            out << annotated;
            ++summary.objects;
            if (options.bearingRange) {
                cornersToBearingRange(annotated.features, scan, corners);
                corners.sensorLabel = base + options.cornersLabelSuffix;
                out << corners;
                ++summary.objects;
            }
            ++summary.scans;
            summary.segments += annotated.features.segments.size();
            summary.corners += annotated.features.corners.size();
            summary.endpoints += annotated.features.endpoints.size();
            if (options.progress)
                options.progress(reader.fractionRead(), summary.scans);
        }
        if (summary.scans == 0)
            throw io::InputError(inputPath, "no laser scans in the log");
    });
    return summary;
}

}  // namespace toposlam::features
