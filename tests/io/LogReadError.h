// The error a log reader gives, for the reader tests of several files.
#pragma once

#include <toposlam/io/InputError.h>
#include <toposlam/io/LaserLogReader.h>

#include <TestSupport.h>

#include <string>

namespace toposlam::test {

/// The InputError message of reading the log at `path` (CARMEN or rawlog), or "" when it reads.
inline std::string logReadError(const std::string& path) {
    return errorOf<io::InputError>([&] { io::LaserLogReader::readAll(path); });
}

}  // namespace toposlam::test
