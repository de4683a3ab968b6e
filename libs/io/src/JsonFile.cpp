#include <toposlam/io/InputError.h>
#include <toposlam/io/JsonFile.h>
#include <toposlam/io/TextFile.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace toposlam::io {

namespace {

// nlohmann's messages start with "[json.exception.parse_error.101] parse error at line 1, column
// 5: syntax error while parsing value - ..." or "[json.exception.out_of_range.406] number
// overflow parsing '1e999'"; keep what a user needs.
std::string describeJsonError(const nlohmann::json::exception& e) {
    std::string message = e.what();
    if (const auto bracket = message.find("] ");
        message.rfind("[json.exception", 0) == 0 && bracket != std::string::npos) {
        message.erase(0, bracket + 2);
    }
    const std::string prefix = "parse error ";
    if (message.rfind(prefix, 0) == 0) {
        message.erase(0, prefix.size());  // "at line 1, column 5: syntax error while ..."
        if (const auto said = message.find(": syntax error "); said != std::string::npos)
            message.erase(said + 2, std::string("syntax error ").size());
        return "JSON syntax error " + message;
    }
    return "JSON: " + message;
}

}  // namespace

Json parseJson(const std::string& text, const std::string& sourceName) {
    // The parser itself is iterative; the callback bounds what later tree walks may meet.
    const Json::parser_callback_t limitDepth = [&](int depth, Json::parse_event_t event, Json&) {
        if ((event == Json::parse_event_t::object_start ||
             event == Json::parse_event_t::array_start) &&
            depth >= kMaxJsonDepth) {
            throw InputError(
                sourceName, "JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
        }
        return true;
    };
    try {
        return Json::parse(text, limitDepth);
    } catch (const nlohmann::json::exception& e) {  // parse_error, out_of_range (overflow)
        throw InputError(sourceName, describeJsonError(e));
    }
}

Json loadJsonFile(const std::string& path) {
    return parseJson(loadTextFile(path), path);
}

std::string formatJson(const Json& document) {
    // Invalid UTF-8 in strings (e.g. a Latin-1 file name) is replaced, not an exception.
    return document.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

double roundSignificant(double v, int digits) {
    if (!std::isfinite(v))
        return v;
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    return std::strtod(buf, nullptr);
}

double roundDecimals(double v, int decimals) {
    if (!std::isfinite(v) || std::abs(v) > 1e15)
        return v;
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return std::strtod(buf, nullptr);
}

void saveJsonFile(const Json& document, const std::string& path) {
    saveTextFile(formatJson(document), path);
}

}  // namespace toposlam::io
