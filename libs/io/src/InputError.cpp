#include <toposlam/io/InputError.h>

namespace toposlam::io {

InputError::InputError(const std::string& file, const std::string& problem)
    : std::runtime_error(file + ": " + problem), file_(file), problem_(problem) {}

}  // namespace toposlam::io
