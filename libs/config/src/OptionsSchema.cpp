#include <toposlam/config/OptionsSchema.h>

#include <mrpt/core/bits_math.h>

#include <cmath>
#include <cstdio>

#include "ValueText.h"

namespace toposlam::config {

namespace {
std::string number(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.15g", v);
    return buffer;
}
std::string joined(const std::vector<std::string>& words) {
    std::string s;
    for (std::size_t i = 0; i < words.size(); ++i)
        s += (i == 0 ? "" : i + 1 == words.size() ? " or " : ", ") + words[i];
    return s;
}
}  // namespace

bool Range::contains(double v) const {
    const bool lowOk = lowOpen ? v > low : v >= low;
    const bool highOk = highOpen ? v < high : v <= high;
    return lowOk && highOk;
}

std::string Range::describe() const {
    const bool hasLow = std::isfinite(low), hasHigh = std::isfinite(high);
    if (hasLow && hasHigh) {
        return "must be in " + std::string(lowOpen ? "(" : "[") + number(low) + ", " +
               number(high) + (highOpen ? ")" : "]");
    }
    if (hasLow)
        return std::string("must be ") + (lowOpen ? "> " : ">= ") + number(low);
    if (hasHigh)
        return std::string("must be ") + (highOpen ? "< " : "<= ") + number(high);
    return "";
}

Field& Field::atLeast(double v) {
    rangeDeclared_ = true;
    range_.low = v;
    range_.lowOpen = false;
    return *this;
}
Field& Field::above(double v) {
    rangeDeclared_ = true;
    range_.low = v;
    range_.lowOpen = true;
    return *this;
}
Field& Field::atMost(double v) {
    rangeDeclared_ = true;
    range_.high = v;
    range_.highOpen = false;
    return *this;
}
Field& Field::below(double v) {
    rangeDeclared_ = true;
    range_.high = v;
    range_.highOpen = true;
    return *this;
}

std::string Field::assign(const std::string& text, bool store) {
    return parse_(text, store);
}

double Field::codeNumber() const {
    return codeNumber_ ? codeNumber_() : std::nan("");
}

std::string Field::check() const {
    if (!fileNumber_)
        return "";
    const double v = fileNumber_();
    if (!std::isfinite(v))
        return "must be a finite number";
    return range_.contains(v) ? "" : range_.describe();
}

std::string Field::documentation() const {
    std::string notes = unit_;
    std::string limits;
    if (kind_ == FieldKind::Choice) {
        bool named = true;  // the comment names every word already
        for (const std::string& w : words_)
            named = named && comment_.find(w) != std::string::npos;
        if (!named)
            limits = joined(words_);
    } else if ((kind_ == FieldKind::Real || kind_ == FieldKind::Integer) && rangeDeclared_) {
        limits = range_.describe();
        if (limits.rfind("must be ", 0) == 0)
            limits = limits.substr(8);
    }
    if (!limits.empty())
        notes += (notes.empty() ? "" : "; ") + limits;
    return notes.empty() ? comment_ : comment_ + " [" + notes + "]";
}

std::string OptionsSchema::prefixed(const std::string& key) const {
    std::string full;
    for (const std::string& p : prefixes_)
        full += p;
    return full + key;
}

Field& OptionsSchema::add(const std::string& key, FieldKind kind, const std::string& unit,
                          const std::string& comment) {
    Field& f = fields_.emplace_back();
    f.key_ = prefixed(key);
    f.kind_ = kind;
    f.unit_ = unit;
    f.comment_ = comment;
    return f;
}

Field* OptionsSchema::find(const std::string& key) {
    for (Field& f : fields_) {
        if (f.key() == key)
            return &f;
    }
    return nullptr;
}

const Field* OptionsSchema::find(const std::string& key) const {
    return const_cast<OptionsSchema*>(this)->find(key);
}

Field& OptionsSchema::addNumber(const std::string& key, std::function<double()> get,
                                std::function<void(double)> set,
                                std::function<double(double)> fromFile,
                                std::function<double(double)> toFile, const std::string& unit,
                                const std::string& comment) {
    Field& f = add(key, FieldKind::Real, unit, comment);
    f.fileNumber_ = [get, toFile] { return toFile(get()); };
    f.codeNumber_ = get;
    f.format_ = [get, toFile, fromFile] { return detail::formatReal(get(), toFile, fromFile); };
    const Range* range = &f.range_;  // deque element: stable
    f.parse_ = [set, fromFile, range](const std::string& text, bool store) -> std::string {
        const auto v = detail::parseReal(text);
        if (!v)
            return detail::notANumberProblem(text);
        if (!range->contains(*v))
            return range->describe();
        const double code = fromFile(*v);
        if (!std::isfinite(code))
            return "out of range";
        if (store)
            set(code);
        return "";
    };
    return f;
}

Field& OptionsSchema::real(const std::string& key, double& field, const std::string& unit,
                           const std::string& comment) {
    const auto same = [](double v) { return v; };
    return addNumber(
        key, [&field] { return field; }, [&field](double v) { field = v; }, same, same, unit,
        comment);
}

Field& OptionsSchema::real(const std::string& key, float& field, const std::string& unit,
                           const std::string& comment) {
    return addNumber(
        key, [&field] { return double(field); },
        [&field](double v) { field = static_cast<float>(v); },
        [](double v) { return double(static_cast<float>(v)); }, [](double v) { return v; }, unit,
        comment);
}

Field& OptionsSchema::angle(const std::string& key, double& radians, const std::string& comment,
                            const std::string& unit) {
    return addNumber(
        key + "_deg", [&radians] { return radians; }, [&radians](double v) { radians = v; },
        [](double deg) { return mrpt::DEG2RAD(deg); },
        [](double rad) { return mrpt::RAD2DEG(rad); }, unit, comment);
}

Field& OptionsSchema::converted(const std::string& key, double& field,
                                std::function<double(double)> fromFile,
                                std::function<double(double)> toFile, const std::string& unit,
                                const std::string& comment) {
    return addNumber(
        key, [&field] { return field; }, [&field](double v) { field = v; }, std::move(fromFile),
        std::move(toFile), unit, comment);
}

Field& OptionsSchema::computed(const std::string& key, std::function<double()> get,
                               std::function<void(double)> set, const std::string& unit,
                               const std::string& comment) {
    const auto same = [](double v) { return v; };
    return addNumber(key, std::move(get), std::move(set), same, same, unit, comment);
}

Field& OptionsSchema::computedAngle(const std::string& key, std::function<double()> get,
                                    std::function<void(double)> set, const std::string& comment) {
    return addNumber(
        key + "_deg", std::move(get), std::move(set), [](double deg) { return mrpt::DEG2RAD(deg); },
        [](double rad) { return mrpt::RAD2DEG(rad); }, "deg", comment);
}

Field& OptionsSchema::addInteger(const std::string& key, std::function<long double()> get,
                                 std::function<void(long double)> set, const std::string& unit,
                                 const std::string& comment) {
    Field& f = add(key, FieldKind::Integer, unit, comment);
    f.fileNumber_ = [get] { return static_cast<double>(get()); };
    f.codeNumber_ = f.fileNumber_;
    f.format_ = [get] {
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%.0Lf", get());
        return std::string(buffer);
    };
    const Range* range = &f.range_;
    f.parse_ = [set, range](const std::string& text, bool store) -> std::string {
        const auto v = detail::parseInteger(text);
        if (!v)
            return "not a whole number";
        if (!range->contains(static_cast<double>(*v)))
            return range->describe();
        if (store)
            set(static_cast<long double>(*v));
        return "";
    };
    return f;
}

Field& OptionsSchema::flag(const std::string& key, bool& field, const std::string& comment) {
    Field& f = add(key, FieldKind::Flag, "", comment);
    f.words_ = {"true", "false"};
    f.format_ = [&field] { return std::string(field ? "true" : "false"); };
    f.parse_ = [&field](const std::string& text, bool store) -> std::string {
        const auto v = detail::parseFlag(text);
        if (!v)
            return "expected true or false (also 1/0, yes/no, on/off)";
        if (store)
            field = *v;
        return "";
    };
    return f;
}

Field& OptionsSchema::text(const std::string& key, std::string& field, const std::string& comment) {
    Field& f = add(key, FieldKind::Text, "", comment);
    f.format_ = [&field] { return field; };
    f.parse_ = [&field](const std::string& text, bool store) -> std::string {
        if (text.empty())
            return "must not be empty";
        if (store)
            field = text;
        return "";
    };
    return f;
}

Field& OptionsSchema::addChoice(const std::string& key, const std::vector<std::string>& names,
                                std::function<std::size_t()> get,
                                std::function<void(std::size_t)> set, const std::string& comment) {
    Field& f = add(key, FieldKind::Choice, "", comment);
    f.words_ = names;
    f.format_ = [get, names] {
        const std::size_t i = get();
        return i < names.size() ? names[i] : std::string("?");
    };
    f.parse_ = [set, names](const std::string& text, bool store) -> std::string {
        for (std::size_t i = 0; i < names.size(); ++i) {
            if (names[i] == text) {
                if (store)
                    set(i);
                return "";
            }
        }
        return "expected " + joined(names);
    };
    return f;
}

void OptionsSchema::require(std::function<bool()> holds, const std::string& key,
                            const std::string& problem) {
    rules_.push_back({std::move(holds), prefixed(key), problem});
}

}  // namespace toposlam::config
