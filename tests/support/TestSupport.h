#pragma once
// Helpers shared by the test suite: where the data and the built apps are, temporary
// directories, running an app and capturing its output.
#include <gtest/gtest.h>

#include <string>

namespace toposlam::test {

/// ../shared/data (public benchmark data), or "" when it is not there.
std::string sharedDataDir();
/// Absolute path of `relative` under ../shared/data, or "" when that file is absent.
std::string sharedDataFile(const std::string& relative);
/// The project's source tree (the folder holding CMakeLists.txt, libs/, config_ini/ ...).
std::string sourceDir();
/// The project's share/ folder (bundled sample data).
std::string shareDir();
/// The path of config_ini/<name>, the shipped configuration files.
std::string configIni(const std::string& name);
/// build/<preset>/bin, where the apps are.
std::string binDir();
/// The TopoSLAM plugin for MRPT's apps (`-l` / `-p`): lib/libtoposlam-plugin.so of this build.
std::string pluginPath();

/// A fresh directory under the build tree's test-tmp/, removed by the destructor.
class TempDir {
  public:
    TempDir();
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    const std::string& path() const { return path_; }
    std::string file(const std::string& name) const { return path_ + "/" + name; }

  private:
    std::string path_;
};

struct CommandResult {
    int exitCode = -1;
    std::string output;  ///< stdout and stderr, interleaved
};
/// Runs a shell command (stdin from /dev/null) and captures its output.
CommandResult runCommand(const std::string& command);
/// Runs bin/<app> with `args`.
CommandResult runApp(const std::string& app, const std::string& args);
/// `path` in single quotes, one word of runApp's `args` whatever blanks it holds.
std::string quoted(const std::string& path);

/// The whole content of the file at `path` ("" when it cannot be read).
std::string readFile(const std::string& path);
/// Writes `text` to the file at `path` (replacing it).
void writeText(const std::string& path, const std::string& text);
/// Whether `text` contains `what`.
bool contains(const std::string& text, const std::string& what);

/// The message of the `Error` that `call()` throws, or "" when it returns normally. Any other
/// exception propagates and fails the test.
template <class Error, class Call>
std::string errorOf(Call&& call) {
    try {
        call();
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

}  // namespace toposlam::test

/// Skips the current test, with a message, when ../shared/data/<relative> is absent;
/// otherwise declares `var` holding its absolute path.
#define TOPOSLAM_SHARED_DATA_OR_SKIP(var, relative)                                      \
    const std::string var = ::toposlam::test::sharedDataFile(relative);                  \
    if (var.empty()) {                                                                   \
        GTEST_SKIP() << "public benchmark data not found: ../shared/data/" << (relative) \
                     << " (tests that need it are skipped where ../shared is absent)";   \
    }
