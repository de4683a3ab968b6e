#pragma once
// What every TopoSLAM fuzz harness needs: the fuzzer's bytes as files (TopoSLAM's readers take
// paths, like the apps), optionally gzip-compressed, and the rule that a reader may reject
// bad input only with io::InputError (the message the apps print as "error: <file>: ...").
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <utility>

namespace toposlam::fuzz {

/// A per-process scratch directory for the harness's files (under $TMPDIR or /tmp).
const std::string& scratchDirectory();

/// Writes `bytes` to scratchDirectory()/`name`, gzip-compressed when `gzip` is true (so that
/// mutations of the plain content reach the readers' gzip paths), and returns the path.
std::string writeScratchFile(const std::string& name, std::string_view bytes, bool gzip = false);

/// The input split at its first NUL byte: (before, after). No NUL: (all, "").
std::pair<std::string_view, std::string_view> splitAtNul(const uint8_t* data, std::size_t size);

/// Runs `read`; returns normally when it succeeds or throws io::InputError. Any other
/// exception is a finding: printed and aborted on, so libFuzzer saves the input.
void expectOnlyInputErrors(const char* reader, const std::function<void()>& read);

}  // namespace toposlam::fuzz
