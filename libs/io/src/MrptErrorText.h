#pragma once
// MRPT exceptions carry a multi-line what() with source locations and a call stack; users
// need one line saying what went wrong.
#include <exception>
#include <string>

namespace toposlam::io {

/// The innermost human-readable message of an MRPT exception (or e.what() for others),
/// on one line.
std::string mrptErrorSummary(const std::exception& e);

}  // namespace toposlam::io
