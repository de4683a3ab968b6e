#pragma once
// A serialized MRPT object that MrptObjectCheck cannot verify (a class it does not know: camera
// images, IMU, GPS, topological maps...) is first deserialized in a child process whose memory
// and time are bounded; only when that dry run succeeds does the reader deserialize the same
// bytes itself (deserialization is deterministic), reading no more bytes than the dry run did.
// A corrupt length field then costs a child process, not the reader's memory, and a crash or
// endless loop inside a deserializer becomes an error message.
#include <cstddef>
#include <string>

#include "LookaheadStream.h"

namespace toposlam::io {

/// What one object may allocate while it is deserialized, and how long that may take.
constexpr std::size_t kDryRunMemoryBytes = std::size_t{1} << 30;  // 1 GiB
constexpr int kDryRunSeconds = 5;

struct DryRunResult {
    bool ok = false;
    std::size_t size = 0;  ///< bytes of the object, when ok
    std::string problem;   ///< why not, when !ok
};

/// Deserializes the object at the read position of `in` in a child process (MRPT's
/// CArchive::ReadObject on the bytes ahead, fetched from the file as needed), without consuming
/// anything.
DryRunResult dryRunNextObject(LookaheadStream& in);

}  // namespace toposlam::io
