// Extractor options: config_ini/features.ini documents every key with its default value, and
// keys read from an .ini file reach the extractor.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <toposlam/features/CornerExtractor.h>
#include <toposlam/features/FeatureExtractor.h>

#include <sstream>

#include "TestSupport.h"

using namespace toposlam::features;

TEST(FeatureOptions, ShippedIniHoldsTheDefaults) {
    const std::string ini = toposlam::test::shareDir() + "/../config_ini/features.ini";
    mrpt::config::CConfigFile cfg(ini);
    for (const std::string& name : featureExtractorNames()) {
        // Presets (corners-ls, ...) are applied after the file: they too keep their defaults.
        auto defaults = makeFeatureExtractor(name), loaded = makeFeatureExtractor(name, &cfg);
        std::ostringstream a, b;
        defaults->dumpOptions(a);
        loaded->dumpOptions(b);
        EXPECT_EQ(a.str(), b.str()) << name << " from " << ini;
    }
}

TEST(FeatureOptions, KeysReachTheExtractorAndBadValuesAreRejected) {
    mrpt::config::CConfigFileMemory cfg;
    cfg.write("CornerExtractor", "dk_th", 2.5);
    cfg.write("CornerExtractor", "paper_exact", "true");
    cfg.write("CornerExtractor", "line_fit", "least_squares");
    CornerExtractor ex;
    ex.loadOptions(cfg, "CornerExtractor");
    EXPECT_EQ(ex.options.dkThreshold, 2.5);
    EXPECT_TRUE(ex.options.paperExact);
    EXPECT_EQ(ex.options.assembly.lineFit, LineFitMethod::LeastSquares);
    EXPECT_EQ(ex.name(), "corners-paper");
    cfg.write("CornerExtractor", "line_fit", "cubic");
    EXPECT_THROW(ex.loadOptions(cfg, "CornerExtractor"), std::invalid_argument);
    EXPECT_THROW(makeFeatureExtractor("hough"), std::invalid_argument);
}
