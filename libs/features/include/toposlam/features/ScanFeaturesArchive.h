#pragma once
// ScanFeatures in MRPT archives: one byte layout shared by every serializable class that
// stores features (CObservationLaserFeatures, the keyframes of matching::CScanFeaturesMap),
// so a change of ScanFeatures is made in one place. Geometry is stored as is (whatever frame
// the caller keeps it in).
#include <mrpt/serialization/CArchive.h>
#include <toposlam/features/ScanFeatures.h>

namespace toposlam::features {

/// Segments, corners (with their covariance) and endpoints, each list prefixed by its size.
void writeScanFeatures(mrpt::serialization::CArchive& out, const ScanFeatures& features);
/// Reads what writeScanFeatures wrote into `features` (replacing its content). Throws
/// std::runtime_error on an unknown endpoint type or a corner that refers to a missing segment.
void readScanFeatures(mrpt::serialization::CArchive& in, ScanFeatures& features);

}  // namespace toposlam::features
