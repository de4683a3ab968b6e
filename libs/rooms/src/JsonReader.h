#pragma once
// A small strict JSON reader (internal to libs/rooms): RFC 8259 values into a tree. Errors
// throw JsonError with the line and column. Fast on the long number arrays of label images.
#include <cstddef>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace toposlam::rooms::detail {

class JsonError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

class JsonValue {
  public:
    enum class Type { Null, Bool, Number, String, Array, Object };

    Type type() const { return type_; }
    bool isNumber() const { return type_ == Type::Number; }
    bool isString() const { return type_ == Type::String; }
    bool isArray() const { return type_ == Type::Array; }
    bool isObject() const { return type_ == Type::Object; }

    /// Typed access; throws JsonError("<what> must be a number") etc. `what` names the value
    /// for the message (e.g. "rooms[3].area").
    double number(const std::string& what) const;
    /// A number that is an integer in [lo, hi].
    long long integer(const std::string& what, long long lo, long long hi) const;
    const std::string& string(const std::string& what) const;
    bool boolean(const std::string& what) const;
    const std::vector<JsonValue>& array(const std::string& what) const;
    /// Member `key` of an object; throws when this is not an object or `key` is missing.
    const JsonValue& at(const std::string& key, const std::string& what) const;
    /// nullptr when this is not an object or has no member `key`.
    const JsonValue* find(const std::string& key) const;

    static JsonValue parse(const std::string& text);

  private:
    friend class JsonParser;
    Type type_ = Type::Null;
    bool bool_ = false;
    double number_ = 0;
    std::string string_;
    std::vector<JsonValue> array_;
    std::map<std::string, JsonValue> object_;
};

}  // namespace toposlam::rooms::detail
