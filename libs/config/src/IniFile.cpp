#include <toposlam/config/ConfigError.h>
#include <toposlam/config/IniFile.h>
#include <toposlam/config/NearestName.h>
#include <toposlam/config/Options.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "ValueText.h"

namespace toposlam::config {

namespace {

constexpr std::uintmax_t kMaxFileSize = 4u << 20;  // options files are a few kB

/// Length of the UTF-8 sequence starting at s[i], 0 when it is not valid UTF-8.
std::size_t utf8Length(const std::string& s, std::size_t i) {
    const auto c = static_cast<unsigned char>(s[i]);
    const std::size_t n = c < 0x80         ? 1
                          : (c >> 5) == 6  ? 2
                          : (c >> 4) == 14 ? 3
                          : (c >> 3) == 30 ? 4
                                           : 0;
    if (n == 0 || i + n > s.size())
        return 0;
    for (std::size_t k = 1; k < n; ++k) {
        if ((static_cast<unsigned char>(s[i + k]) >> 6) != 2)
            return 0;
    }
    return n;
}

/// The problem with one line's characters, or "".
std::string characterProblem(const std::string& line) {
    for (std::size_t i = 0; i < line.size();) {
        const auto c = static_cast<unsigned char>(line[i]);
        if (c < 0x20 && c != '\t' && c != '\r')
            return "control character (byte " + std::to_string(c) + "): not a text file";
        const std::size_t n = utf8Length(line, i);
        if (n == 0)
            return "not UTF-8 text";
        i += n;
    }
    return "";
}

bool isComment(const std::string& t) {
    return t[0] == '#' || t[0] == ';' || t.rfind("//", 0) == 0;
}

bool isKeyName(const std::string& key) {
    return !key.empty() && std::all_of(key.begin(), key.end(), [](unsigned char c) {
        return std::isalnum(c) || c == '_' || c == '.' || c == '-';
    });
}

/// Checks the syntax of the file's text line by line (throws ConfigError).
void checkSyntax(const std::string& path, const std::string& text) {
    std::istringstream in(text);
    std::string section;
    bool inSection = false;
    std::map<std::string, std::size_t> seen;  // "section\nkey" -> line
    std::size_t number = 0;
    for (std::string line; std::getline(in, line);) {
        ++number;
        const std::string problem = characterProblem(line);
        if (!problem.empty())
            throw ConfigError(path, number, problem);
        const std::string t = detail::trim(line);
        if (t.empty() || isComment(t))
            continue;
        if (t.front() == '[') {
            if (t.back() != ']' || t.size() < 3 ||
                !isKeyName(detail::trim(t.substr(1, t.size() - 2))))
                throw ConfigError(path, number,
                                  "expected [section] with a name of letters, digits, _ . -");
            section = detail::trim(t.substr(1, t.size() - 2));
            inSection = true;
            continue;
        }
        const std::size_t eq = t.find('=');
        const std::string key = eq == std::string::npos ? "" : detail::trim(t.substr(0, eq));
        if (!isKeyName(key))
            throw ConfigError(path, number, "expected 'key = value', '[section]' or a # comment");
        if (!inSection)
            throw ConfigError(path, number, "'" + key + "' comes before any [section]");
        const auto [it, fresh] = seen.emplace(section + "\n" + key, number);
        if (!fresh) {
            throw ConfigError(path, number,
                              "[" + section + "] " + key + " is set again (first on line " +
                                  std::to_string(it->second) + ")");
        }
    }
}

}  // namespace

std::unique_ptr<mrpt::config::CConfigFile> openIniFile(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::exists(path, ec))
        throw ConfigError(path, 0, "no such file");
    if (!fs::is_regular_file(path, ec))
        throw ConfigError(path, 0, "not a regular file");
    if (fs::file_size(path, ec) > kMaxFileSize)
        throw ConfigError(path, 0, "larger than 4 MB: not an options file");
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    if (!in)
        throw ConfigError(path, 0, "cannot be read");
    checkSyntax(path, text.str());
    auto file = std::make_unique<mrpt::config::CConfigFile>(path);
    file->discardSavingChanges();
    return file;
}

void requireSection(const mrpt::config::CConfigFileBase& config, const std::string& section) {
    if (config.sectionExists(section))
        return;
    std::vector<std::string> sections;
    config.getAllSections(sections);
    sections.erase(std::remove(sections.begin(), sections.end(), std::string()), sections.end());
    std::string problem = "no such section in the file";
    if (!sections.empty())
        problem += "; did you mean [" + nearestName(section, sections) + "]?";
    throw ConfigError(configFileName(config), section, "", "", problem);
}

std::optional<WrittenNumber> readWrittenNumber(const mrpt::config::CConfigFileBase& config,
                                               const std::string& section, const std::string& key) {
    if (!config.keyExists(section, key))
        return std::nullopt;
    std::string text = config.read_string(section, key, "", false);
    // MRPT strips a "//" comment itself; "#" and ";" after a blank are comments to it too
    // (it reads the number before them).
    for (std::size_t i = 1; i < text.size(); ++i) {
        if ((text[i] == '#' || text[i] == ';' || text.compare(i, 2, "//") == 0) &&
            std::isspace(static_cast<unsigned char>(text[i - 1]))) {
            text.erase(i);
            break;
        }
    }
    text = detail::trim(text);
    if (const std::optional<double> value = detail::parseReal(text))
        return WrittenNumber{*value, text};
    throw ConfigError(configFileName(config), section, key, text, detail::notANumberProblem(text));
}

void requireKnownSections(const mrpt::config::CConfigFileBase& config,
                          const std::vector<std::string>& known) {
    std::vector<std::string> sections;
    config.getAllSections(sections);
    for (const std::string& s : sections) {
        if (s.empty() || std::find(known.begin(), known.end(), s) != known.end())
            continue;
        const std::string nearest = nearestName(s, known);
        throw ConfigError(
            configFileName(config), s, "", "",
            "unknown section" + (nearest.empty() ? "" : "; did you mean [" + nearest + "]?"));
    }
}

}  // namespace toposlam::config
