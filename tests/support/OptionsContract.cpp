#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <toposlam/config/ConfigError.h>

#include <OptionsContract.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

namespace toposlam::test {

namespace {

std::map<std::string, std::string> savedValues(const config::Options& o,
                                               const std::string& section) {
    mrpt::config::CConfigFileMemory c;
    o.saveToConfigFile(c, section);
    std::vector<std::string> keys;
    c.getAllKeys(section, keys);
    std::map<std::string, std::string> values;
    for (const std::string& k : keys)
        values[k] = config::rawValue(c, section, k);
    return values;
}

std::string number(double v) {
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.17g", v);
    return buffer;
}

/// Other valid texts for a field, most likely to be accepted first.
std::vector<std::string> alternatives(const config::Field& f) {
    const std::string now = f.text();
    std::vector<std::string> out;
    switch (f.kind()) {
        case config::FieldKind::Flag:
            out.push_back(now == "true" ? "false" : "true");
            break;
        case config::FieldKind::Choice:
            for (const std::string& w : f.words())
                if (w != now)
                    out.push_back(w);
            break;
        case config::FieldKind::Text:
            out.push_back(now + "_x");
            break;
        case config::FieldKind::Integer: {
            const long long v = std::stoll(now);
            for (long long c : {v + 1, v - 1, v + 2, v * 2 + 1})
                if (f.range().contains(double(c)))
                    out.push_back(std::to_string(c));
            break;
        }
        case config::FieldKind::Real: {
            const double v = std::strtod(now.c_str(), nullptr);
            const config::Range& r = f.range();
            std::vector<double> c = {v * 1.25, v * 0.75, v + 0.5, v - 0.5, v + 0.01, v - 0.01};
            if (std::isfinite(r.low) && std::isfinite(r.high))
                c.push_back(0.5 * (r.low + r.high));
            for (double x : c)
                if (x != v && r.contains(x))
                    out.push_back(number(x));
            break;
        }
    }
    return out;
}

}  // namespace

std::string savedText(const config::Options& options, const std::string& section) {
    mrpt::config::CConfigFileMemory c;
    options.saveToConfigFile(c, section);
    return c.getContent();
}

void expectOptionsContract(const OptionsFactory& make, const std::string& section) {
    SCOPED_TRACE("[" + section + "]");
    const auto defaults = make();
    EXPECT_NO_THROW(defaults->validate(section));
    const std::vector<std::string> keys = defaults->keys();
    ASSERT_FALSE(keys.empty());
    const auto saved = savedValues(*defaults, section);
    EXPECT_EQ(saved.size(), keys.size()) << "keys declared twice or saved without a declaration";
    const std::string text = savedText(*defaults, section);
    for (const std::string& k : keys) {
        EXPECT_EQ(saved.count(k), 1u) << k << " is not written";
        EXPECT_NE(text.find(k + " = "), std::string::npos) << k;
    }
    const config::OptionsSchema schema = defaults->schema();
    for (const config::Field& f : schema.fields())
        EXPECT_FALSE(f.comment().empty()) << f.key() << " has no comment";

    mrpt::config::CConfigFileMemory file;
    file.setContent(text);
    auto loaded = make();
    loaded->loadFromConfigFile(file, section);
    EXPECT_EQ(savedText(*loaded, section), text) << "save -> load -> save changed the text";

    // Each key on its own, then all together.
    mrpt::config::CConfigFileMemory all;
    all.setContent(text);
    for (const config::Field& f : schema.fields()) {
        bool bound = false;
        for (const std::string& value : alternatives(f)) {
            mrpt::config::CConfigFileMemory one;
            one.setContent(text);
            one.write(section, f.key(), value);
            auto changed = make();
            try {
                changed->loadFromConfigFile(one, section);
            } catch (const config::ConfigError&) {
                continue;  // a rule between fields refused this value: try another
            }
            auto after = savedValues(*changed, section);
            for (const auto& [k, v] : saved) {
                if (k != f.key()) {
                    EXPECT_EQ(after[k], v) << "setting " << f.key() << " changed " << k;
                }
            }
            EXPECT_NE(after[f.key()], saved.at(f.key()))
                << f.key() << " = " << value << " did not reach a field";
            all.write(section, f.key(), after[f.key()]);
            bound = true;
            break;
        }
        EXPECT_TRUE(bound) << f.key() << ": no other value is accepted";
    }
    auto allChanged = make();
    try {
        allChanged->loadFromConfigFile(all, section);
        const std::string once = savedText(*allChanged, section);
        mrpt::config::CConfigFileMemory again;
        again.setContent(once);
        auto twice = make();
        twice->loadFromConfigFile(again, section);
        EXPECT_EQ(savedText(*twice, section), once);
    } catch (const config::ConfigError& e) {
        // Every key changed at once may break a rule between fields; each alone did not.
        SUCCEED() << e.what();
    }
}

}  // namespace toposlam::test
