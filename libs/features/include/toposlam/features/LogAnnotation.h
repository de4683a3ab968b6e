#pragma once
// A laser log annotated with the features of every scan: reads any log LaserLogReader reads
// (CARMEN, MRPT rawlogs of either format) and writes an observations-format rawlog where each
// scan is followed by its CObservationLaserFeatures (and, optionally, its corners as a
// CObservationBearingRange):
//     [CObservationOdometry] CObservation2DRangeScan CObservationLaserFeatures
//     [CObservationBearingRange]
// all with the scan's timestamp. The odometry is written when the log has it. Output is atomic
// (nothing is left behind on error) and gzip-compressed when the name ends in ".gz".
// What toposlam-annotate-features does.
#include <toposlam/features/FeatureExtractor.h>
#include <toposlam/io/LaserLogReader.h>

#include <cstddef>
#include <functional>
#include <string>

namespace toposlam::features {

struct LogAnnotationOptions {
    io::LaserLogOptions read;
    bool bearingRange = false;  ///< also write the corners as CObservationBearingRange
    /// Labels: the scan's label (or "LASER" if it has none) + these suffixes ("FLASER" ->
    /// "FLASER_FEATURES").
    std::string featuresLabelSuffix = "_FEATURES";
    std::string cornersLabelSuffix = "_CORNERS";
    std::size_t maxScans = 0;  ///< 0 = all
    /// Called after each scan with (fraction of the input read, scans so far).
    std::function<void(double, std::size_t)> progress;
};

struct LogAnnotationSummary {
    io::LaserLogFormat inputFormat = io::LaserLogFormat::Carmen;
    std::size_t scans = 0;
    std::size_t objects = 0;                               ///< top-level objects written
    std::size_t segments = 0, corners = 0, endpoints = 0;  ///< totals
    double extractionSeconds = 0;                          ///< time spent in the extractor
};

/// Throws io::InputError for bad input (and for a log without laser scans) and
/// std::runtime_error when the output cannot be written.
LogAnnotationSummary annotateLog(const std::string& inputPath, const std::string& outputPath,
                                 FeatureExtractor& extractor,
                                 const LogAnnotationOptions& options = {});

}  // namespace toposlam::features
