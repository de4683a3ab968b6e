#pragma once
// A numeric command-line option with its valid range: TCLAP reads the text, NumberRange checks
// it strictly, and a bad value is a parse error ("error: --beams: '-1' is not an integer in
// [1, 100000] (see --help)", exit status 2) before the app does anything. Every numeric option
// of every app is one of these, so the checks and their messages are the same everywhere.
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <toposlam/cli/NumberRange.h>

#include <stdexcept>
#include <string>

namespace toposlam::cli {

template <typename T>
class NumberArg {
  public:
    /// An optional option `--name <unit>` (and `-flag` when `flag` is not empty) added to `cmd`;
    /// the help text gets the accepted range appended. `defaultValue` must lie in `range`.
    NumberArg(const std::string& flag, const std::string& name, const std::string& description,
              T defaultValue, NumberRange<T> range, const std::string& unit, TCLAP::CmdLine& cmd)
        : check_(name, range, unit),
          arg_(flag, name, description + " Range: " + range.interval() + ".", false, "", &check_,
               cmd),
          default_(defaultValue) {
        if (!range.contains(defaultValue))
            throw std::logic_error("--" + name + ": the default is outside the range");
    }
    NumberArg(const NumberArg&) = delete;
    NumberArg& operator=(const NumberArg&) = delete;

    T getValue() const { return arg_.isSet() ? check_.value : default_; }
    bool isSet() const { return arg_.isSet(); }
    const NumberRange<T>& range() const { return check_.range; }

  private:
    // TCLAP's hook for checking a value: parses and keeps it, or reports why not.
    struct Check : TCLAP::Constraint<std::string> {
        Check(std::string n, NumberRange<T> r, std::string u)
            : name(std::move(n)), range(r), unit(std::move(u)) {}
        std::string description() const override { return range.describe(); }
        std::string shortID() const override { return unit; }
        bool check(const std::string& text) const override {
            const auto v = range.parse(text);
            if (!v) {
                throw TCLAP::CmdLineParseException("'" + text + "' is not " + range.describe(),
                                                   "--" + name);
            }
            value = *v;
            return true;
        }
        std::string name;
        NumberRange<T> range;
        std::string unit;
        mutable T value{};
    };

    Check check_;  // before arg_, which keeps a pointer to it
    TCLAP::ValueArg<std::string> arg_;
    T default_;
};

}  // namespace toposlam::cli
