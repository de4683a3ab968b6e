#pragma once
// Errors about bad input files. Every reader in TopoSLAM reports a problem with an input by
// throwing InputError, whose message names the file and says what is wrong with it, so apps
// can print it verbatim and exit non-zero.
#include <stdexcept>
#include <string>

namespace toposlam::io {

class InputError : public std::runtime_error {
  public:
    /// `file`: the offending path; `problem`: what is wrong, e.g. "line 12: FLASER has 183
    /// fields, expected 188". what() is "<file>: <problem>".
    InputError(const std::string& file, const std::string& problem);

    const std::string& file() const { return file_; }
    const std::string& problem() const { return problem_; }

  private:
    std::string file_;
    std::string problem_;
};

}  // namespace toposlam::io
