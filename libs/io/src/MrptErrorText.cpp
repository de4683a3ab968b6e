#include "MrptErrorText.h"

namespace toposlam::io {

std::string mrptErrorSummary(const std::exception& e) {
    // MRPT's what(): "==== MRPT exception ====\nMessage:  <text>\nLocation: ...\nCall stack
    // backtrace: ..." with nested exceptions appended after "Original exception:". The last
    // "Message:" is the innermost cause.
    const std::string what = e.what();
    const auto at = what.rfind("Message:");
    if (at == std::string::npos)
        return what;
    auto begin = at + 8;
    auto end = what.find("\nLocation:", begin);
    const auto nested = what.find("\nOriginal exception:", begin);
    if (nested != std::string::npos && nested < end)
        end = nested;
    std::string text = what.substr(begin, end == std::string::npos ? end : end - begin);
    std::string oneLine;
    bool space = true;
    for (char c : text) {
        const bool blank = c == ' ' || c == '\n' || c == '\t' || c == '\r';
        if (blank) {
            if (!space)
                oneLine += ' ';
            space = true;
        } else {
            oneLine += c;
            space = false;
        }
    }
    while (!oneLine.empty() && oneLine.back() == ' ')
        oneLine.pop_back();
    return oneLine;
}

}  // namespace toposlam::io
