// Fuzzes .ini files as TopoSLAM's apps read them: mrpt::config::CConfigFile on a file (and
// CConfigFileMemory on the text), every section and key, read as each type the options
// loaders ask for. MRPT reports bad values with std::exception (the apps' loaders turn that
// into a message naming file, section and key), so any std::exception is accepted here: the
// harness looks for crashes, hangs and runaway memory.
#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <exception>
#include <string>
#include <vector>

#include "FuzzInput.h"

namespace {

void readEverything(const mrpt::config::CConfigFileBase& ini) {
    std::vector<std::string> sections;
    ini.getAllSections(sections);
    for (const std::string& section : sections) {
        std::vector<std::string> keys;
        ini.getAllKeys(section, keys);
        for (const std::string& key : keys) {
            try {
                (void)ini.read_string(section, key, "");
                (void)ini.read_double(section, key, 0.0);
                (void)ini.read_float(section, key, 0.0f);
                (void)ini.read_int(section, key, 0);
                (void)ini.read_uint64_t(section, key, 0);
                (void)ini.read_bool(section, key, false);
                std::vector<double> values;
                ini.read_vector(section, key, std::vector<double>(), values);
            } catch (const std::exception&) {
                // A value MRPT cannot convert: reported, not a crash.
            }
        }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const std::string path = toposlam::fuzz::writeScratchFile("fuzz.ini", text);
    try {
        readEverything(mrpt::config::CConfigFile(path));
        readEverything(mrpt::config::CConfigFileMemory(text));
    } catch (const std::exception&) {
        // MRPT rejected the file as a whole: reported, not a crash.
    }
    return 0;
}
