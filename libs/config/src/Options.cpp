#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileBase.h>
#include <toposlam/config/ConfigError.h>
#include <toposlam/config/NearestName.h>
#include <toposlam/config/Options.h>

#include <ostream>

#include "ValueText.h"

namespace toposlam::config {

std::string configFileName(const mrpt::config::CConfigFileBase& config) {
    const auto* file = dynamic_cast<const mrpt::config::CConfigFile*>(&config);
    return file ? file->getAssociatedFile() : std::string();
}

std::string rawValue(const mrpt::config::CConfigFileBase& config, const std::string& section,
                     const std::string& key) {
    return detail::trim(config.read_string(section, key, "", false));
}

OptionsSchema Options::schema() {
    OptionsSchema s;
    declare(s);
    return s;
}

OptionsSchema Options::constSchema() const {
    // declare() only binds references; the const methods below never write through them.
    return const_cast<Options*>(this)->schema();
}

void Options::loadFromConfigFile(const mrpt::config::CConfigFileBase& source,
                                 const std::string& section) {
    OptionsSchema s = schema();
    const std::string file = configFileName(source);
    std::vector<std::string> known;
    for (const Field& f : s.fields())
        known.push_back(f.key());
    std::vector<std::string> present;
    source.getAllKeys(section, present);
    // First every key and value, then store: a bad file leaves the options as they were.
    for (const std::string& key : present) {
        const std::string value = rawValue(source, section, key);
        Field* f = s.find(key);
        if (!f)
            throw ConfigError(file, section, key, value, unknownNameProblem("key", key, known));
        const std::string problem = f->assign(value, false);
        if (!problem.empty())
            throw ConfigError(file, section, key, value, problem);
    }
    std::vector<std::string> before;
    for (const std::string& key : present) {
        before.push_back(s.find(key)->text());
        s.find(key)->assign(rawValue(source, section, key), true);
    }
    for (const Rule& r : s.rules()) {
        if (!r.holds()) {
            for (std::size_t i = 0; i < present.size(); ++i)
                s.find(present[i])->assign(before[i], true);  // as they were
            const Field* f = s.find(r.key);
            const std::string value = source.keyExists(section, r.key)
                                          ? rawValue(source, section, r.key)
                                          : (f ? f->text() + " (default)" : "");
            throw ConfigError(file, section, r.key, value, r.problem);
        }
    }
}

void Options::validate(const std::string& section) const {
    const OptionsSchema s = constSchema();
    for (const Field& f : s.fields()) {
        const std::string problem = f.check();
        if (!problem.empty())
            throw ConfigError("", section, f.key(), f.text(), problem);
    }
    for (const Rule& r : s.rules()) {
        if (!r.holds()) {
            const Field* f = s.find(r.key);
            throw ConfigError("", section, r.key, f ? f->text() : "", r.problem);
        }
    }
}

void Options::saveToConfigFile(mrpt::config::CConfigFileBase& target,
                               const std::string& section) const {
    const OptionsSchema s = constSchema();
    for (const Field& f : s.fields())
        target.write(section, f.key(), f.text(), -1, -1, f.documentation());
}

void Options::dumpToTextStream(std::ostream& out) const {
    const OptionsSchema s = constSchema();
    for (const Field& f : s.fields())
        out << "# " << f.documentation() << "\n" << f.key() << " = " << f.text() << "\n";
}

std::vector<std::string> Options::keys() const {
    std::vector<std::string> k;
    const OptionsSchema s = constSchema();
    for (const Field& f : s.fields())
        k.push_back(f.key());
    return k;
}

}  // namespace toposlam::config
