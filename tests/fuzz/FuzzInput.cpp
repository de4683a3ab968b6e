#include "FuzzInput.h"

#include <toposlam/io/InputError.h>
#include <unistd.h>
#include <zlib.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace toposlam::fuzz {

const std::string& scratchDirectory() {
    static const std::string dir = [] {
        const char* tmp = std::getenv("TMPDIR");
        const std::filesystem::path base = tmp && *tmp ? tmp : "/tmp";
        const auto path = base / ("toposlam-fuzz-" + std::to_string(::getpid()));
        std::filesystem::create_directories(path);
        return path.string();
    }();
    return dir;
}

std::string writeScratchFile(const std::string& name, std::string_view bytes, bool gzip) {
    const std::string path = scratchDirectory() + "/" + name;
    if (gzip) {
        gzFile f = gzopen(path.c_str(), "wb1");
        if (!f || gzwrite(f, bytes.data(), static_cast<unsigned>(bytes.size())) !=
                      static_cast<int>(bytes.size())) {
            std::fprintf(stderr, "fuzz: cannot write %s\n", path.c_str());
            std::abort();
        }
        gzclose(f);
        return path;
    }
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) {
        std::fprintf(stderr, "fuzz: cannot write %s\n", path.c_str());
        std::abort();
    }
    return path;
}

std::pair<std::string_view, std::string_view> splitAtNul(const uint8_t* data, std::size_t size) {
    const std::string_view all(reinterpret_cast<const char*>(data), size);
    const auto nul = all.find('\0');
    if (nul == std::string_view::npos)
        return {all, {}};
    return {all.substr(0, nul), all.substr(nul + 1)};
}

void expectOnlyInputErrors(const char* reader, const std::function<void()>& read) {
    try {
        read();
    } catch (const io::InputError&) {
        // The expected way to reject bad input.
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fuzz %s: not an io::InputError: %s\n", reader, e.what());
        std::abort();
    }
}

}  // namespace toposlam::fuzz
