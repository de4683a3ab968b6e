#include <toposlam/features/CornerExtractor.h>
#include <toposlam/features/FeatureExtractor.h>
#include <toposlam/features/SegmentExtractor.h>
#include <toposlam/features/SplitAndMergeExtractor.h>

#include <stdexcept>

namespace toposlam::features {

const std::vector<std::string>& featureExtractorNames() {
    static const std::vector<std::string> names = {"corners",  "corners-ls",     "corners-paper",
                                                   "segments", "segments-paper", "split-merge"};
    return names;
}

namespace {
[[noreturn]] void unknown(const std::string& name) {
    std::string known;
    for (const auto& n : featureExtractorNames())
        known += (known.empty() ? "" : ", ") + n;
    throw std::invalid_argument("unknown feature extractor '" + name + "' (known: " + known + ")");
}
}  // namespace

std::string defaultConfigSection(const std::string& name) {
    if (name == "corners" || name == "corners-ls" || name == "corners-paper") {
        return "CornerExtractor";
    }
    if (name == "segments" || name == "segments-paper")
        return "SegmentExtractor";
    if (name == "split-merge")
        return "SplitAndMergeExtractor";
    unknown(name);
}

std::unique_ptr<FeatureExtractor> makeFeatureExtractor(const std::string& name,
                                                       const mrpt::config::CConfigFileBase* config,
                                                       const std::string& section) {
    const std::string sec = section.empty() ? defaultConfigSection(name) : section;
    if (name == "corners" || name == "corners-ls" || name == "corners-paper") {
        auto e = std::make_unique<CornerExtractor>();
        if (config)
            e->loadOptions(*config, sec);
        if (name == "corners-ls")
            e->options.assembly.lineFit = LineFitMethod::LeastSquares;
        if (name == "corners-paper")
            e->options.paperExact = true;
        return e;
    }
    if (name == "segments" || name == "segments-paper") {
        auto e = std::make_unique<SegmentExtractor>();
        if (config)
            e->loadOptions(*config, sec);
        if (name == "segments-paper")
            e->options.paperExact = true;
        return e;
    }
    auto e = std::make_unique<SplitAndMergeExtractor>();  // defaultConfigSection() checked the name
    if (config)
        e->loadOptions(*config, sec);
    return e;
}

}  // namespace toposlam::features
