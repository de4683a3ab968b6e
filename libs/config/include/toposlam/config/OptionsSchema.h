#pragma once
// The single declaration of an options struct's .ini keys. An options struct (config::Options)
// lists each field once, in declare():
//     s.real("max_range", maxRange, "m", "farther returns are invalid").above(0);
//     s.angle("fov", aperture, "first to last beam").above(0).atMost(360);  // key fov_deg
//     s.integer("beams", beams, "", "readings per scan").within(2, 100000);
//     s.flag("paper_exact", paperExact, "the paper's rules as printed");
//     s.choice("line_fit", lineFit, {{"two_point", TwoPoint}, {"least_squares", LeastSquares}},
//              "fit of each segment");
//     s.group("jump_", jumps);            // nested options: jumps.declare(s), keys jump_...
//     s.require([&] { return minRange < maxRange; }, "min_range", "must be below max_range");
// and everything else (strict loading, saving every field with its comment, validation, the
// list of known keys, the unknown-key check) follows from that list (config/Options.h).
// Units: a field holds code units (SI, radians); ranges and texts are in FILE units (angle():
// degrees, key suffix "_deg"; converted(): any pair of conversions).
// Key rule for TopoSLAM's own sections: snake_case, "_deg" for angles, units in the comment.
#include <deque>
#include <functional>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace toposlam::config {

/// Values a number may take, in file units; either end open or closed.
struct Range {
    double low = -std::numeric_limits<double>::infinity();
    double high = std::numeric_limits<double>::infinity();
    bool lowOpen = false, highOpen = false;
    bool contains(double v) const;
    /// e.g. "must be > 0", "must be in [0, 1]"; "" when unbounded.
    std::string describe() const;
};

enum class FieldKind { Real, Integer, Flag, Choice, Text };

/// One key: its name, unit and comment, its allowed values, and access to the bound field.
class Field {
  public:
    /// Allowed values (file units); chain them: .above(0).atMost(1).
    Field& atLeast(double v);
    Field& above(double v);
    Field& atMost(double v);
    Field& below(double v);
    Field& within(double low, double high) { return atLeast(low).atMost(high); }

    const std::string& key() const { return key_; }
    const std::string& unit() const { return unit_; }
    const std::string& comment() const { return comment_; }
    FieldKind kind() const { return kind_; }
    const Range& range() const { return range_; }
    /// The accepted words of a Choice (Flag: true, false).
    const std::vector<std::string>& words() const { return words_; }

    /// The field's current value as it is written in a file.
    std::string text() const { return format_(); }
    /// Numbers: the field's value in code units (bit for bit); NaN for other kinds.
    double codeNumber() const;
    /// Parses `text` (a value from a file); stores it when `store` and it is acceptable.
    /// Returns the problem ("" = accepted).
    std::string assign(const std::string& text, bool store);
    /// The problem with the field's current value (out of range, not finite), or "".
    std::string check() const;
    /// The comment as written above the key: "<comment> (<unit>; <range>)".
    std::string documentation() const;

  private:
    friend class OptionsSchema;
    std::string key_, unit_, comment_;
    FieldKind kind_ = FieldKind::Real;
    Range range_;
    bool rangeDeclared_ = false;
    std::vector<std::string> words_;
    std::function<std::string()> format_;
    // Parses a file text: problem or "" ; stores when asked.
    std::function<std::string(const std::string&, bool)> parse_;
    // The current value in file / code units, for numbers (range check of values set in code).
    std::function<double()> fileNumber_, codeNumber_;
};

/// A cross-field condition (e.g. min < max), reported against `key`.
struct Rule {
    std::function<bool()> holds;
    std::string key, problem;
};

class OptionsSchema {
  public:
    OptionsSchema() = default;
    // Fields refer to their own place in fields_: move, never copy.
    OptionsSchema(const OptionsSchema&) = delete;
    OptionsSchema& operator=(const OptionsSchema&) = delete;
    OptionsSchema(OptionsSchema&&) = default;
    OptionsSchema& operator=(OptionsSchema&&) = default;

    /// A real number. `unit`: as written in the file ("m", "s", "" for none).
    Field& real(const std::string& key, double& field, const std::string& unit,
                const std::string& comment);
    Field& real(const std::string& key, float& field, const std::string& unit,
                const std::string& comment);
    /// An angle: radians in `field`, degrees in the file under key + "_deg". `unit` for
    /// compound units ("deg/s": the field is in rad/s).
    Field& angle(const std::string& key, double& radians, const std::string& comment,
                 const std::string& unit = "deg");
    /// A real number stored converted: field = fromFile(file value), file = toFile(field).
    Field& converted(const std::string& key, double& field, std::function<double(double)> fromFile,
                     std::function<double(double)> toFile, const std::string& unit,
                     const std::string& comment);
    /// A number that is no field of its own (e.g. the yaw of a CPose3D): `get` reads it in
    /// code units, `set` stores it; angle: radians in code, degrees in the file, key + "_deg".
    Field& computed(const std::string& key, std::function<double()> get,
                    std::function<void(double)> set, const std::string& unit,
                    const std::string& comment);
    Field& computedAngle(const std::string& key, std::function<double()> get,
                         std::function<void(double)> set, const std::string& comment);
    /// An integer of any width or signedness (not bool); file values beyond it are refused.
    template <class T, class = std::enable_if_t<std::is_integral_v<T> && !std::is_same_v<T, bool>>>
    Field& integer(const std::string& key, T& field, const std::string& unit,
                   const std::string& comment) {
        Field& f = addInteger(
            key, [&field] { return static_cast<long double>(field); },
            [&field](long double v) { field = static_cast<T>(v); }, unit, comment);
        f.atLeast(static_cast<double>(std::numeric_limits<T>::lowest()))
            .atMost(static_cast<double>(std::numeric_limits<T>::max()));
        f.rangeDeclared_ = false;  // the type's limits, not a declared range
        return f;
    }
    Field& flag(const std::string& key, bool& field, const std::string& comment);
    Field& text(const std::string& key, std::string& field, const std::string& comment);
    /// One of a fixed set of words, each standing for a value of `field` (an enum, usually).
    template <class T>
    Field& choice(const std::string& key, T& field,
                  const std::vector<std::pair<std::string, T>>& words, const std::string& comment) {
        std::vector<std::string> names;
        for (const auto& w : words)
            names.push_back(w.first);
        return addChoice(
            key, names,
            [&field, words] {
                for (std::size_t i = 0; i < words.size(); ++i)
                    if (words[i].second == field)
                        return i;
                return words.size();
            },
            [&field, words](std::size_t i) { field = words[i].second; }, comment);
    }
    /// Nested options (anything with declare(OptionsSchema&)), keys prefixed by `prefix`.
    template <class Nested>
    void group(const std::string& prefix, Nested& nested) {
        prefixes_.push_back(prefix);
        nested.declare(*this);
        prefixes_.pop_back();
    }
    /// A condition between fields, checked after loading and by validate().
    void require(std::function<bool()> holds, const std::string& key, const std::string& problem);

    const std::deque<Field>& fields() const { return fields_; }
    const std::vector<Rule>& rules() const { return rules_; }
    /// The field of `key` (full key as in the file), or nullptr.
    Field* find(const std::string& key);
    const Field* find(const std::string& key) const;

  private:
    Field& add(const std::string& key, FieldKind kind, const std::string& unit,
               const std::string& comment);
    Field& addNumber(const std::string& key, std::function<double()> get,
                     std::function<void(double)> set, std::function<double(double)> fromFile,
                     std::function<double(double)> toFile, const std::string& unit,
                     const std::string& comment);
    Field& addInteger(const std::string& key, std::function<long double()> get,
                      std::function<void(long double)> set, const std::string& unit,
                      const std::string& comment);
    Field& addChoice(const std::string& key, const std::vector<std::string>& names,
                     std::function<std::size_t()> get, std::function<void(std::size_t)> set,
                     const std::string& comment);
    std::string prefixed(const std::string& key) const;

    std::deque<Field> fields_;  // deque: Field& handed out stay valid
    std::vector<Rule> rules_;
    std::vector<std::string> prefixes_;
};

}  // namespace toposlam::config
