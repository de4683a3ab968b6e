#include <toposlam/cli/CommandLine.h>
#include <toposlam/cli/UsageError.h>
#include <toposlam/io/FileExtension.h>
#include <toposlam/io/GridMapIO.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
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
        std::cerr << "error: " << optionName(e) << e.error() << " (see --help)\n";
    }

  private:
    // "--beams: " from TCLAP's "Argument: (--beams)", "Argument: -o (--out)" or "Argument:
    // --bogus"; nothing when TCLAP names no argument (" ", e.g. required ones are missing).
    static std::string optionName(const TCLAP::ArgException& e) {
        std::string id = e.argId();
        const std::string prefix = "Argument: ";
        if (id.compare(0, prefix.size(), prefix) == 0)
            id.erase(0, prefix.size());
        if (const auto open = id.find('('); open != std::string::npos && id.back() == ')')
            id = id.substr(open + 1, id.size() - open - 2);
        return id.find_first_not_of(' ') == std::string::npos ? std::string() : id + ": ";
    }
};

bool looksLikeOption(const std::string& s) {
    return s.size() >= 2 && s[0] == '-' &&
           (s[1] == '-' || std::isalpha(static_cast<unsigned char>(s[1])));
}

// TCLAP hands an unknown "--option" to a positional argument as its value when the app has one
// (toposlam-eval-slam's trajectories, toposlam-bench-planning's maps): find such a value among
// the words before "--" (after it, everything is positional on purpose).
std::optional<std::string> optionTakenAsPositional(TCLAP::CmdLine& cmd, int argc, char** argv) {
    std::vector<std::string> words;
    for (int i = 1; i < argc && std::string(argv[i]) != "--"; ++i)
        words.emplace_back(argv[i]);
    const auto given = [&](const std::string& v) {
        return looksLikeOption(v) && std::find(words.begin(), words.end(), v) != words.end();
    };
    for (TCLAP::Arg* arg : cmd.getArgList()) {
        std::vector<std::string> values;
        if (auto* one = dynamic_cast<TCLAP::UnlabeledValueArg<std::string>*>(arg)) {
            if (one->isSet())
                values.push_back(one->getValue());
        } else if (auto* many = dynamic_cast<TCLAP::UnlabeledMultiArg<std::string>*>(arg)) {
            values = many->getValue();
        }
        for (const std::string& v : values) {
            if (given(v))
                return v;
        }
    }
    return std::nullopt;
}

// "--seed=3" where --seed is an option of `cmd` (before "--"): TCLAP takes it for an option
// named "seed=3", or a positional argument's value, and says something else went wrong.
std::optional<std::string> optionWithEqualsSign(TCLAP::CmdLine& cmd, int argc, char** argv) {
    for (int i = 1; i < argc && std::string(argv[i]) != "--"; ++i) {
        const std::string word = argv[i];
        const auto eq = word.find('=');
        if (word.compare(0, 2, "--") != 0 || eq == std::string::npos)
            continue;
        for (TCLAP::Arg* arg : cmd.getArgList()) {
            if (!arg->getName().empty() && word.compare(0, eq, "--" + arg->getName()) == 0 &&
                eq == arg->getName().size() + 2)
                return word.substr(0, eq) + " " + word.substr(eq + 1);
        }
    }
    return std::nullopt;
}

}  // namespace

std::optional<int> parseCommandLine(TCLAP::CmdLine& cmd, int argc, char** argv) {
    if (const auto spaced = optionWithEqualsSign(cmd, argc, argv)) {
        std::cerr << "error: options take their value after a space: write '" << *spaced
                  << "' (see --help)\n";
        return kBadUsage;
    }
    // Outlives `cmd` (which keeps a pointer to it); apps parse one command line.
    static ErrorReportingOutput output;
    output.failed = false;
    // MRPT's TCLAP does not free its default output object once setOutput() replaces it.
    const std::unique_ptr<TCLAP::CmdLineOutput> defaultOutput(cmd.getOutput());
    cmd.setOutput(&output);
    if (!cmd.parse(argc, argv))
        return output.failed ? kBadUsage : kSuccess;
    if (const auto unknown = optionTakenAsPositional(cmd, argc, argv)) {
        std::cerr << "error: " << *unknown << ": unknown option (see --help)\n";
        return kBadUsage;
    }
    return std::nullopt;
}

std::vector<double> parseNumberList(const std::string& text, std::size_t count,
                                    const std::string& option, const NumberRange<double>& range) {
    std::vector<double> values;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ',')) {
        const auto v = range.parse(item);
        if (!v) {
            throw UsageError(option + ": '" + text + "' is not a list of numbers in " +
                             range.interval());
        }
        values.push_back(*v);
    }
    if (values.size() != count) {
        throw UsageError(option + ": expected " + std::to_string(count) +
                         " comma-separated numbers, got '" + text + "'");
    }
    return values;
}

std::string takeOption(int& argc, char** argv, const std::string& flag, std::string fallback) {
    for (int i = 1; i + 1 < argc; ++i) {
        if (flag == argv[i]) {
            fallback = argv[i + 1];
            std::copy(argv + i + 2, argv + argc, argv + i);
            argc -= 2;
            break;
        }
    }
    return fallback;
}

std::vector<std::string> splitList(const std::string& text) {
    std::vector<std::string> items;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        if (!item.empty())
            items.push_back(item);
    }
    return items;
}

std::vector<unsigned> parseSeedList(const std::string& text, const std::string& option) {
    std::vector<unsigned> seeds;
    for (const std::string& item : splitList(text)) {
        const auto dash = item.find('-', 1);
        const auto range = parseNumberList(
            dash == std::string::npos ? item : item.substr(0, dash) + "," + item.substr(dash + 1),
            dash == std::string::npos ? 1 : 2, option);
        for (double s = range.front(); s <= range.back(); ++s) {
            if (s < 0 || s != std::floor(s) || s > 1e9)
                throw UsageError(option + ": seeds are whole numbers >= 0");
            seeds.push_back(static_cast<unsigned>(s));
        }
    }
    return seeds;
}

namespace {

bool sameFile(const std::string& a, const std::string& b) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::exists(a, ec) && fs::exists(b, ec)) {
        const bool same = fs::equivalent(a, b, ec);
        if (!ec)
            return same;
    }
    const fs::path ca = fs::weakly_canonical(fs::absolute(a, ec), ec);
    const fs::path cb = fs::weakly_canonical(fs::absolute(b, ec), ec);
    return ca == cb;
}

std::string named(const FileArgument& f) {
    return (f.option.empty() ? std::string("'") : f.option + " '") + f.path + "'" +
           (f.via.empty() ? "" : " (" + f.via + ")");
}

// The files after the first of `paths`, which `first` names, as files that go with it.
std::vector<FileArgument> alongWith(const FileArgument& first,
                                    const std::vector<std::string>& paths, const char* how) {
    std::vector<FileArgument> files = {first};
    for (std::size_t i = 1; i < paths.size(); ++i)
        files.push_back({"", paths[i], how + named(first)});
    return files;
}

}  // namespace

void requireOutputsOfTheirOwn(const std::vector<FileArgument>& inputs,
                              const std::vector<FileArgument>& outputs) {
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        const FileArgument& out = outputs[i];
        if (out.path.empty())
            continue;
        for (const FileArgument& in : inputs) {
            if (!in.path.empty() && sameFile(out.path, in.path)) {
                throw UsageError(named(out) + ": the same file as the input " + named(in) +
                                 " (it would be overwritten)");
            }
        }
        for (std::size_t j = 0; j < i; ++j) {
            if (!outputs[j].path.empty() && sameFile(out.path, outputs[j].path)) {
                throw UsageError(named(out) + ": the same file as the output " + named(outputs[j]));
            }
        }
    }
}

std::vector<FileArgument> mapFilesRead(const FileArgument& map) {
    if (map.path.empty())
        return {map};
    return alongWith(map, io::gridMapFilesRead(map.path), "read with ");
}

std::vector<FileArgument> mapFilesWritten(const FileArgument& map) {
    if (map.path.empty())
        return {map};
    return alongWith(map, io::gridMapFilesWritten(map.path), "written with ");
}

std::vector<FileArgument> filesInFolder(const FileArgument& folder,
                                        const std::vector<std::string>& names) {
    std::vector<FileArgument> files;
    for (const std::string& name : names)
        files.push_back(
            {"", (std::filesystem::path(folder.path) / name).string(), "in " + named(folder)});
    return files;
}

void requireExtension(const FileArgument& file, const std::vector<std::string>& extensions) {
    if (file.path.empty())
        return;
    for (const std::string& e : extensions) {
        if (io::hasExtension(file.path, e))
            return;
    }
    std::string list;
    for (std::size_t i = 0; i < extensions.size(); ++i)
        list += (i == 0 ? "" : i + 1 == extensions.size() ? " or " : ", ") + extensions[i];
    throw UsageError(named(file) + ": must end in " + list);
}

void requireWritableOutputFolder(const FileArgument& folder) {
    namespace fs = std::filesystem;
    if (folder.path.empty())
        throw UsageError(folder.option + ": the output folder is empty");
    // Nothing is created here (a run that fails later leaves nothing behind): the folder, or
    // the nearest of its parents that exists, must be a folder the app can make files in.
    std::error_code ec;
    fs::path existing = fs::absolute(folder.path, ec);
    while (!fs::exists(existing, ec) && existing.has_relative_path())
        existing = existing.parent_path();
    if (!fs::is_directory(existing, ec)) {
        throw std::runtime_error(folder.path + ": cannot create the output folder (" +
                                 existing.string() + " is not a folder)");
    }
    if (::access(existing.c_str(), W_OK | X_OK) != 0) {
        throw std::runtime_error(folder.path + ": cannot create the output folder (" +
                                 existing.string() + ": " + std::strerror(errno) + ")");
    }
}

void requireWritableOutputFiles(const std::vector<FileArgument>& files) {
    namespace fs = std::filesystem;
    for (const FileArgument& file : files) {
        if (file.path.empty())
            continue;
        const auto refuse = [&](const std::string& why) {
            throw std::runtime_error(file.path + ": cannot write the file (" + why + ")");
        };
        std::error_code ec;
        if (fs::is_directory(file.path, ec))
            refuse("it is a folder");
        const fs::path folder = fs::absolute(file.path, ec).parent_path();
        if (!fs::exists(folder, ec))
            refuse("no folder " + folder.string());
        if (!fs::is_directory(folder, ec))
            refuse(folder.string() + " is not a folder");
        if (::access(folder.c_str(), W_OK | X_OK) != 0)
            refuse(folder.string() + ": " + std::strerror(errno));
    }
}

int runReportingErrors(int (*run)(int, char**), int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const UsageError& e) {
        std::cerr << "error: " << e.what() << " (see --help)\n";
        return kBadUsage;
    } catch (const TCLAP::ArgException& e) {
        std::cerr << "error: " << e.argId() << ": " << e.error() << "\n";
        return kBadUsage;
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
    }
    return kBadInput;
}

}  // namespace toposlam::cli
