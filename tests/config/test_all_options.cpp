// Every options struct of TopoSLAM, one table: the generic contract (OptionsContract.h) for
// each, and every section of every config_ini/*.ini file either read strictly by the struct of
// its section (so every key there is known and every value valid) or passed through to MRPT.
// A new section in config_ini/ or a new options struct goes into the table below.
#include <gtest/gtest.h>
#include <toposlam/config/IniFile.h>
#include <toposlam/features/FeatureAssembly.h>
#include <toposlam/features/JumpDetector.h>
#include <toposlam/matching/CScanFeaturesMap.h>
#include <toposlam/matching/FeatureMap.h>
#include <toposlam/matching/GraphScanMatcher.h>
#include <toposlam/simulation/LaserModel.h>

#include <OptionsContract.h>
#include <TestSupport.h>
#include "OptionsTable.h"

#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <set>

namespace {

using namespace toposlam;
using test::make;
using test::sectionStructs;

}  // namespace

TEST(AllOptions, EveryStructKeepsTheContract) {
    for (const auto& [section, factory] : sectionStructs())
        test::expectOptionsContract(factory, section);
    // Structs that are only parts of others, on their own.
    test::expectOptionsContract(make<features::JumpDetectorOptions>(), "JumpDetector");
    test::expectOptionsContract(make<features::FeatureAssemblyOptions>(), "FeatureAssembly");
    test::expectOptionsContract(make<matching::GraphMatcherOptions>(), "GraphScanMatcher");
    test::expectOptionsContract(make<simulation::LaserModel>(), "Laser");
    test::expectOptionsContract(make<matching::FeatureMapOptions>(), "FeatureMap");
    test::expectOptionsContract(make<matching::CScanFeaturesMap::TInsertionOptions>(),
                                "map_scanFeaturesMap_00_insertOpts");
    test::expectOptionsContract(make<matching::CScanFeaturesMap::TLikelihoodOptions>(),
                                "map_scanFeaturesMap_00_likelihoodOpts");
}

TEST(AllOptions, EveryKeyOfEveryShippedIniFileIsKnownAndValid) {
    const auto files = test::configFiles();
    ASSERT_GE(files.size(), 8u);
    for (const std::string& path : files) {
        SCOPED_TRACE(path);
        std::unique_ptr<mrpt::config::CConfigFile> ini;
        ASSERT_NO_THROW(ini = config::openIniFile(path));
        std::vector<std::string> sections;
        ini->getAllSections(sections);
        for (const std::string& section : sections) {
            if (section.empty() || test::isMrptSection(section))
                continue;
            const auto factory = test::structOfSection(section);
            ASSERT_TRUE(factory) << "[" << section << "] has no options struct";
            auto options = factory();
            try {
                options->loadFromConfigFile(*ini, section);
            } catch (const std::exception& e) {
                ADD_FAILURE() << e.what();
            }
        }
    }
}

TEST(AllOptions, ShippedFilesSpellOutTheDefaults) {
    // These files document every key with its default: loading one changes nothing.
    for (const std::string name :
         {"features.ini", "graph-matcher.ini", "rooms.ini", "sim-office.ini"}) {
        const std::string path = test::configIni(name);
        SCOPED_TRACE(path);
        auto ini = config::openIniFile(path);
        std::vector<std::string> sections;
        ini->getAllSections(sections);
        for (const std::string& section : sections) {
            if (section.empty())
                continue;
            const auto& factory = sectionStructs().at(section);
            auto defaults = factory(), loaded = factory();
            loaded->loadFromConfigFile(*ini, section);
            EXPECT_EQ(test::savedText(*loaded, section), test::savedText(*defaults, section));
            // ... and spells out every key.
            std::vector<std::string> keys;
            ini->getAllKeys(section, keys);
            EXPECT_EQ(keys.size(), defaults->keys().size()) << "[" << section << "]";
            // Bit for bit where the text could differ from the value by an ulp (an angle no
            // decimal degree reaches exactly): share/office must come out the same with or
            // without -c sim-office.ini. (graph-matcher.ini has three such angles.)
            if (name != std::string("sim-office.ini"))
                continue;
            const config::OptionsSchema a = defaults->schema(), b = loaded->schema();
            for (std::size_t i = 0; i < a.fields().size(); ++i) {
                const double x = a.fields()[i].codeNumber(), y = b.fields()[i].codeNumber();
                if (!std::isnan(x)) {
                    EXPECT_EQ(x, y) << "[" << section << "] " << a.fields()[i].key();
                }
            }
        }
    }
}
