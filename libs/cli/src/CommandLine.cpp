#include <toposlam/cli/CommandLine.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace toposlam::cli {

namespace {

// TCLAP's default output prints usage on errors and exits; this one prints the project's
// one-line error and remembers that there was one.
class ErrorReportingOutput : public TCLAP::StdOutput {
  public:
    bool failed = false;
    void failure(TCLAP::CmdLineInterface&, TCLAP::ArgException& e) override {
        failed = true;
        // TCLAP names no argument (argId " ") when required ones are missing.
        const std::string id = e.argId();
        const bool named = id.find_first_not_of(' ') != std::string::npos;
        std::cerr << "error: " << (named ? id + ": " : "") << e.error() << " (see --help)\n";
    }
};

}  // namespace

std::optional<int> parseCommandLine(TCLAP::CmdLine& cmd, int argc, char** argv) {
    // Outlives `cmd` (which keeps a pointer to it); apps parse one command line.
    static ErrorReportingOutput output;
    output.failed = false;
    // MRPT's TCLAP does not free its default output object once setOutput() replaces it.
    const std::unique_ptr<TCLAP::CmdLineOutput> defaultOutput(cmd.getOutput());
    cmd.setOutput(&output);
    if (cmd.parse(argc, argv))
        return std::nullopt;
    return output.failed ? 1 : 0;
}

std::vector<double> parseNumberList(const std::string& text, std::size_t count,
                                    const std::string& option) {
    std::vector<double> values;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ',')) {
        char* end = nullptr;
        const double v = std::strtod(item.c_str(), &end);
        if (item.empty() || *end != '\0' || !std::isfinite(v)) {
            throw std::invalid_argument(option + ": '" + text + "' is not a list of numbers");
        }
        values.push_back(v);
    }
    if (values.size() != count) {
        throw std::invalid_argument(option + ": expected " + std::to_string(count) +
                                    " comma-separated numbers, got '" + text + "'");
    }
    return values;
}

int runReportingErrors(int (*run)(int, char**), int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const TCLAP::ArgException& e) {
        std::cerr << "error: " << e.argId() << ": " << e.error() << "\n";
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
    }
    return EXIT_FAILURE;
}

}  // namespace toposlam::cli
