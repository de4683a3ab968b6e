#include <mrpt/config/CConfigFileMemory.h>
#include <toposlam/evaluation/IniWithSettings.h>
#include <toposlam/io/AtomicFile.h>
#include <toposlam/io/InputError.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace toposlam::evaluation {

namespace {

mrpt::config::CConfigFileMemory readIni(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw io::InputError(path, "cannot read the configuration file");
    std::ostringstream text;
    text << in.rdbuf();
    return mrpt::config::CConfigFileMemory(text.str());
}

}  // namespace

void writeIniWithSettings(const std::string& source, const std::string& destination,
                          const std::vector<IniSetting>& settings) {
    mrpt::config::CConfigFileMemory ini = readIni(source);
    for (const IniSetting& s : settings)
        ini.write(s.section, s.key, s.value);
    const std::string content = ini.getContent();
    io::writeFileAtomically(destination, [&](const std::string& tmp) {
        std::ofstream out(tmp, std::ios::binary);
        out << "# " << source << " with settings changed by the benchmark\n" << content;
        out.close();
        if (!out)
            throw std::runtime_error(destination + ": cannot write the file");
    });
}

double readIniNumber(const std::string& path, const std::string& section, const std::string& key,
                     double fallback) {
    return readIni(path).read_double(section, key, fallback);
}

}  // namespace toposlam::evaluation
