#pragma once
// The base of every TopoSLAM options struct: an mrpt::config::CLoadableOptions whose fields are
// declared once (declare(), see OptionsSchema.h), from which it gets
//  - loadFromConfigFile(): strict. Keys are optional (absent ones keep their value, bit for
//    bit), but every key present must be a declared one (else ConfigError naming the nearest
//    declared key) and its value must parse completely (no "abc" read as 0, no NaN or inf) and
//    lie in the declared range; cross-field rules are checked last. The error names the file
//    (when the config object is an mrpt::config::CConfigFile), section, key and value.
//  - saveToConfigFile(): writes every declared field, with its comment, in MRPT's own format.
//  - dumpToTextStream(): every field as ini lines with the comment on the line above, a valid
//    section body to paste into a file.
//  - validate(): the same range and rule checks for values set in code or from a command line.
//  - keys(): the declared keys, in declaration order.
// Fields not declared are not options (derived values, workspaces).
#include <mrpt/config/CLoadableOptions.h>
#include <toposlam/config/OptionsSchema.h>

#include <iosfwd>
#include <string>
#include <vector>

namespace mrpt::config {
class CConfigFileBase;
}

namespace toposlam::config {

class Options : public mrpt::config::CLoadableOptions {
  public:
    /// Lists every option field (see OptionsSchema.h). Binds references to the fields: the
    /// schema is used at once and not kept.
    virtual void declare(OptionsSchema& schema) = 0;

    void loadFromConfigFile(const mrpt::config::CConfigFileBase& source,
                            const std::string& section) override;
    void saveToConfigFile(mrpt::config::CConfigFileBase& target,
                          const std::string& section) const override;
    void dumpToTextStream(std::ostream& out) const override;

    /// Throws ConfigError (no file; the message starts at [section]) when a field is out of
    /// its declared range or a rule is broken.
    void validate(const std::string& section) const;
    /// The declared keys, as written in files.
    std::vector<std::string> keys() const;
    /// The declaration itself, bound to this object's fields (tests, documentation).
    OptionsSchema schema();

  protected:
    Options() = default;
    Options(const Options&) = default;
    Options& operator=(const Options&) = default;

  private:
    OptionsSchema constSchema() const;
};

/// The file behind `config` (mrpt::config::CConfigFile::getAssociatedFile()), "" otherwise.
std::string configFileName(const mrpt::config::CConfigFileBase& config);

/// The value of `key` in `section` as MRPT reads it (trimmed).
std::string rawValue(const mrpt::config::CConfigFileBase& config, const std::string& section,
                     const std::string& key);

}  // namespace toposlam::config
