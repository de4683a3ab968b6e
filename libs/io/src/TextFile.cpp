#include <toposlam/io/AtomicFile.h>
#include <toposlam/io/InputError.h>
#include <toposlam/io/TextFile.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace toposlam::io {

std::string loadTextFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw InputError(path, "cannot open the file");
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad())
        throw InputError(path, "read error");
    return text.str();
}

void saveTextFile(const std::string& text, const std::string& path) {
    writeFileAtomically(path, [&](const std::string& tmp) {
        std::ofstream out(tmp, std::ios::binary);
        out << text;
        out.close();
        if (!out)
            throw std::runtime_error(path + ": cannot write the file");
    });
}

}  // namespace toposlam::io
