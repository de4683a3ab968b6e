#include <toposlam/features/CornerExtractor.h>
#include <toposlam/features/FeatureExtractor.h>
#include <toposlam/features/SegmentExtractor.h>

#include <stdexcept>

namespace toposlam::features {

const std::vector<std::string>& featureExtractorNames() {
    static const std::vector<std::string> names = {"corners", "corners-ls", "corners-paper",
                                                   "segments", "segments-paper"};
    return names;
}

std::string defaultConfigSection(const std::string& name) {
    if (name.rfind("corners", 0) == 0)
        return "CornerExtractor";
    if (name.rfind("segments", 0) == 0)
        return "SegmentExtractor";
    throw std::invalid_argument("unknown feature extractor '" + name + "'");
}

std::unique_ptr<FeatureExtractor> makeFeatureExtractor(const std::string& name) {
    if (name == "corners" || name == "corners-ls" || name == "corners-paper") {
        auto e = std::make_unique<CornerExtractor>();
        if (name == "corners-ls")
            e->options.assembly.lineFit = LineFitMethod::LeastSquares;
        if (name == "corners-paper")
            e->options.paperExact = true;
        return e;
    }
    if (name == "segments" || name == "segments-paper") {
        auto e = std::make_unique<SegmentExtractor>();
        e->options.paperExact = name == "segments-paper";
        return e;
    }
    std::string known;
    for (const auto& n : featureExtractorNames())
        known += (known.empty() ? "" : ", ") + n;
    throw std::invalid_argument("unknown feature extractor '" + name + "' (known: " + known + ")");
}

}  // namespace toposlam::features
