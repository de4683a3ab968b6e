#include <toposlam/io/FileExtension.h>

#include <algorithm>
#include <cctype>

namespace toposlam::io {

bool hasExtension(std::string_view path, std::string_view extension) {
    return path.size() > extension.size() &&
           std::equal(
               extension.rbegin(), extension.rend(), path.rbegin(),
               [](unsigned char a, unsigned char b) { return std::tolower(a) == std::tolower(b); });
}

bool hasAnyExtension(std::string_view path, std::initializer_list<std::string_view> extensions) {
    return std::any_of(extensions.begin(), extensions.end(),
                       [path](std::string_view e) { return hasExtension(path, e); });
}

}  // namespace toposlam::io
