#pragma once
// Reading optional .ini keys so that an absent key keeps the current value bit for bit (a value
// converted to the file's units and back could differ in the last bit, and the simulator's
// output must not depend on whether a key is spelled out with its default).
#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/core/bits_math.h>

#include <string>

namespace toposlam::simulation::detail {

/// value = fromFile(number in the file) when `key` exists in `section`.
template <class Convert>
void readKey(const mrpt::config::CConfigFileBase& c, const std::string& section,
             const std::string& key, double& value, Convert fromFile) {
    if (c.keyExists(section, key))
        value = fromFile(c.read_double(section, key, 0.0, true));
}
inline void readKey(const mrpt::config::CConfigFileBase& c, const std::string& section,
                    const std::string& key, double& value) {
    readKey(c, section, key, value, [](double v) { return v; });
}
/// The file gives degrees; `value` is in radians.
inline void readDegrees(const mrpt::config::CConfigFileBase& c, const std::string& section,
                        const std::string& key, double& value) {
    readKey(c, section, key, value, [](double v) { return mrpt::DEG2RAD(v); });
}

}  // namespace toposlam::simulation::detail
