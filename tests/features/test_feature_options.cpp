// Extractor options: config_ini/features.ini documents every key with its default value, keys
// read from an .ini file reach the extractor, and bad values are refused with the key named.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <toposlam/config/ConfigError.h>
#include <toposlam/features/CornerExtractor.h>
#include <toposlam/features/FeatureExtractor.h>

#include <sstream>

#include "TestSupport.h"

using namespace toposlam::features;
using toposlam::config::ConfigError;

TEST(FeatureOptions, ShippedIniHoldsTheDefaults) {
    const std::string ini = toposlam::test::configIni("features.ini");
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
    cfg.write("CornerExtractor", "jump_k", 12);
    CornerExtractor ex;
    ex.loadOptions(cfg, "CornerExtractor");
    EXPECT_EQ(ex.options.dkThreshold, 2.5);
    EXPECT_TRUE(ex.options.paperExact);
    EXPECT_EQ(ex.options.assembly.lineFit, LineFitMethod::LeastSquares);
    EXPECT_EQ(ex.options.jumps.k, 12);
    EXPECT_EQ(ex.name(), "corners-paper");
    cfg.write("CornerExtractor", "line_fit", "cubic");
    EXPECT_THROW(ex.loadOptions(cfg, "CornerExtractor"), ConfigError);
    EXPECT_THROW(makeFeatureExtractor("hough"), std::invalid_argument);
}

TEST(FeatureOptions, NanNegativeAndMisspelledKeysAreErrors) {
    // (NaN thresholds used to drop intel's corners to 0 per scan without a word.)
    const auto error = [](const std::string& method, const std::string& key,
                          const std::string& value) -> std::string {
        mrpt::config::CConfigFileMemory cfg;
        cfg.write(defaultConfigSection(method), key, value);
        return toposlam::test::errorOf<ConfigError>([&] { makeFeatureExtractor(method, &cfg); });
    };
    EXPECT_EQ(error("corners", "dk_th", "nan"),
              "[CornerExtractor] dk_th = nan: must be a finite number");
    EXPECT_EQ(error("corners", "alpha", "-0.6"),
              "[CornerExtractor] alpha = -0.6: must be in (0, 1]");
    EXPECT_EQ(error("corners", "theta", "0.3"),
              "[CornerExtractor] theta = 0.3: unknown key; did you mean 'theta_th'?");
    EXPECT_EQ(error("segments", "turn_threshold", "1.0472"),
              "[SegmentExtractor] turn_threshold = 1.0472: unknown key; did you mean "
              "'turn_threshold_deg'?");
    EXPECT_EQ(error("segments", "median_window", "4"),
              "[SegmentExtractor] median_window = 4: must be odd");
    EXPECT_EQ(error("split-merge", "split_distance", "abc"),
              "[SplitAndMergeExtractor] split_distance = abc: not a number");
    EXPECT_EQ(error("split-merge", "jump_k", "0"),
              "[SplitAndMergeExtractor] jump_k = 0: must be > 0");
    EXPECT_EQ(error("corners", "min_segment_points", "-1"),
              "[CornerExtractor] min_segment_points = -1: must be in [2, 100000]");
    EXPECT_EQ(error("corners", "dk_th", "1.5"), "");
}
