#pragma once
// Acquisition times of CARMEN laser scans from their ipc_timestamps as printed in the log.
//
// Old CARMEN loggers printed timestamps as "%ld.%ld" (seconds, microseconds) without zero
// padding, so 12.034567 s became "12.34567" (read back as 12.34567 s, up to 0.9 s late);
// logs re-emitted later with six decimals show it as "12.345670". In intel.clf 631 of 13631
// laser stamps step backwards because of this. The printed stamp stays the scan's identity
// (ground-truth relation files use it); this module recovers the real, strictly increasing
// time:
//  1. Candidates per stamp: the value as printed, and every "unpadded microseconds" reading
//     of its fractional digits: drop k >= 0 trailing zeros, and if the remaining digits
//     (at most six, no leading zero) are not already six, they are the microseconds.
//     "12.345670" -> 12.345670 (as printed) or 12.034567; "12.34567" -> 12.034567.
//  2. Choose one candidate per scan by dynamic programming over the whole log: minimise
//     1000 x (number of steps that do not increase) + (number of reinterpreted stamps), with
//     a small preference for dropping fewer zeros. A stamp is thus reinterpreted only where
//     that explains a step backwards (a chain of such stamps if needed).
//  3. Steps that no reinterpretation explains are made strictly increasing minimally: such a
//     time becomes 1 microsecond after its predecessor.
// On intel.clf: 1060 stamps reinterpreted and one unexplained step forced (toposlam-convert
// reports "1061 timestamps repaired"); all 13631 times strictly increasing, and every
// relation stamp of intel.relations is a printed stamp (tests/io/test_carmen_reader.cpp).
#include <cstddef>
#include <string_view>
#include <vector>

namespace toposlam::io {

/// The candidate readings of one printed stamp (step 1). Element 0 is the value as printed.
/// Empty if `printed` is not a plain decimal number.
std::vector<double> carmenStampCandidates(std::string_view printed);

struct CarmenTimestampRepair {
    std::vector<double> times;      ///< s, strictly increasing, one per input stamp
    std::size_t reinterpreted = 0;  ///< stamps read as unpadded microseconds (step 2)
    std::size_t forced = 0;         ///< times moved to predecessor + 1 us (step 3)
};

/// Steps 1-3 for the printed stamps of a log's laser scans, in file order. A stamp that is
/// not a decimal number is treated as its predecessor (callers reject such lines anyway).
CarmenTimestampRepair repairCarmenTimestamps(const std::vector<std::string_view>& printed);

}  // namespace toposlam::io
