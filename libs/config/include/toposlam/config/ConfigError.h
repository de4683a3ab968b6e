#pragma once
// The one exception for bad options files. Its message names the file, the section, the key
// and the value as written, and the problem, so that apps print it verbatim:
//     error: <file>: [section] key = value: <problem>
// Problems that belong to no key (a line that is not ini syntax, an unknown section) give
//     error: <file>: line 12: <problem>      or      error: <file>: [section]: <problem>
// Values that did not come from a file (set in code or on a command line and then validated)
// have no file: the message starts at "[section]".
#include <stdexcept>
#include <string>

namespace toposlam::config {

class ConfigError : public std::runtime_error {
  public:
    /// A bad value of `key` in `section` ("" key: the section itself).
    ConfigError(std::string file, std::string section, std::string key, std::string value,
                std::string problem);
    /// A problem with the file as a whole, or with one of its lines (line 0: none).
    ConfigError(std::string file, std::size_t line, std::string problem);

    const std::string& file() const { return file_; }
    const std::string& section() const { return section_; }
    const std::string& key() const { return key_; }
    const std::string& value() const { return value_; }
    const std::string& problem() const { return problem_; }

  private:
    std::string file_, section_, key_, value_, problem_;
};

}  // namespace toposlam::config
