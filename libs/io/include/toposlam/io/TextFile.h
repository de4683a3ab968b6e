#pragma once
// Whole text files in and out: reading names the file in its errors (InputError), writing is
// atomic (AtomicFile.h), byte for byte.
#include <string>

namespace toposlam::io {

/// The whole file at `path`; throws InputError when it cannot be opened or read.
std::string loadTextFile(const std::string& path);

/// Writes `text` to `path` atomically; throws std::runtime_error naming `path` on failure.
void saveTextFile(const std::string& text, const std::string& path);

}  // namespace toposlam::io
