#include <toposlam/config/ConfigError.h>

#include <utility>

namespace toposlam::config {

namespace {
std::string withFile(const std::string& file, const std::string& rest) {
    return file.empty() ? rest : file + ": " + rest;
}
std::string keyMessage(const std::string& file, const std::string& section, const std::string& key,
                       const std::string& value, const std::string& problem) {
    std::string where = "[" + section + "]";
    if (!key.empty())
        where += " " + key + " = " + value;
    return withFile(file, where + ": " + problem);
}
std::string lineMessage(const std::string& file, std::size_t line, const std::string& problem) {
    return withFile(file, line > 0 ? "line " + std::to_string(line) + ": " + problem : problem);
}
}  // namespace

ConfigError::ConfigError(std::string file, std::string section, std::string key, std::string value,
                         std::string problem)
    : std::runtime_error(keyMessage(file, section, key, value, problem)),
      file_(std::move(file)),
      section_(std::move(section)),
      key_(std::move(key)),
      value_(std::move(value)),
      problem_(std::move(problem)) {}

ConfigError::ConfigError(std::string file, std::size_t line, std::string problem)
    : std::runtime_error(lineMessage(file, line, problem)),
      file_(std::move(file)),
      problem_(std::move(problem)) {}

}  // namespace toposlam::config
