#include "TestSupport.h"

#include <unistd.h>

#include <array>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace toposlam::test {

namespace fs = std::filesystem;

std::string sharedDataDir() {
    std::error_code ec;
    const fs::path p = fs::weakly_canonical(TOPOSLAM_SHARED_DATA_DIR, ec);
    return !ec && fs::is_directory(p) ? p.string() : std::string();
}

std::string sharedDataFile(const std::string& relative) {
    const std::string dir = sharedDataDir();
    if (dir.empty())
        return {};
    const fs::path p = fs::path(dir) / relative;
    return fs::exists(p) ? p.string() : std::string();
}

std::string sourceDir() {
    return TOPOSLAM_SOURCE_DIR;
}

std::string shareDir() {
    return sourceDir() + "/share";
}

std::string configIni(const std::string& name) {
    return sourceDir() + "/config_ini/" + name;
}

std::string binDir() {
    return std::string(TOPOSLAM_BINARY_DIR) + "/bin";
}

TempDir::TempDir() {
    static std::atomic<unsigned> counter{0};
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = info ? std::string(info->test_suite_name()) + "." + info->name() : "tmp";
    for (char& c : name) {
        if (c == '/')
            c = '_';
    }
    const fs::path p = fs::path(TOPOSLAM_BINARY_DIR) / "test-tmp" /
                       (name + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    fs::remove_all(p);
    fs::create_directories(p);
    path_ = p.string();
}

TempDir::~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
}

CommandResult runCommand(const std::string& command) {
    CommandResult result;
    FILE* pipe = ::popen(("(" + command + ") </dev/null 2>&1").c_str(), "r");
    if (!pipe)
        return result;
    std::array<char, 4096> buf{};
    std::size_t n = 0;
    while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0)
        result.output.append(buf.data(), n);
    const int status = ::pclose(pipe);
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

CommandResult runApp(const std::string& app, const std::string& args) {
    return runCommand("'" + binDir() + "/" + app + "' " + args);
}

std::string quoted(const std::string& path) {
    return "'" + path + "'";
}

std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string pluginPath() {
    return std::filesystem::canonical(binDir() + "/../lib/libtoposlam-plugin.so").string();
}

void writeText(const std::string& path, const std::string& text) {
    std::ofstream(path) << text;
}

bool contains(const std::string& text, const std::string& what) {
    return text.find(what) != std::string::npos;
}

}  // namespace toposlam::test
