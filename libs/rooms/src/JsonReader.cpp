#include "JsonReader.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace toposlam::rooms::detail {

class JsonParser {
  public:
    explicit JsonParser(const std::string& text) : s_(text) {}

    JsonValue document() {
        JsonValue v = value();
        skipSpace();
        if (i_ != s_.size())
            fail("unexpected text after the JSON value");
        return v;
    }

  private:
    [[noreturn]] void fail(const std::string& what) const {
        std::size_t line = 1, column = 1;
        for (std::size_t k = 0; k < i_ && k < s_.size(); ++k) {
            if (s_[k] == '\n') {
                ++line;
                column = 1;
            } else {
                ++column;
            }
        }
        throw JsonError("JSON syntax error at line " + std::to_string(line) + ", column " +
                        std::to_string(column) + ": " + what);
    }
    void skipSpace() {
        while (i_ < s_.size() &&
               (s_[i_] == ' ' || s_[i_] == '\t' || s_[i_] == '\n' || s_[i_] == '\r'))
            ++i_;
    }
    char peek() {
        skipSpace();
        if (i_ >= s_.size())
            fail("unexpected end of file");
        return s_[i_];
    }
    void expect(char c) {
        if (peek() != c)
            fail(std::string("expected '") + c + "'");
        ++i_;
    }
    void literal(const char* word) {
        for (const char* p = word; *p; ++p, ++i_) {
            if (i_ >= s_.size() || s_[i_] != *p)
                fail(std::string("expected '") + word + "'");
        }
    }
    JsonValue value() {
        JsonValue v;
        const char c = peek();
        if (c == '{') {
            v.type_ = JsonValue::Type::Object;
            ++i_;
            if (peek() == '}') {
                ++i_;
                return v;
            }
            while (true) {
                if (peek() != '"')
                    fail("expected a member name in quotes");
                std::string key = stringLiteral();
                expect(':');
                v.object_[key] = value();
                if (peek() == ',') {
                    ++i_;
                    continue;
                }
                expect('}');
                return v;
            }
        }
        if (c == '[') {
            v.type_ = JsonValue::Type::Array;
            ++i_;
            if (peek() == ']') {
                ++i_;
                return v;
            }
            while (true) {
                v.array_.push_back(value());
                if (peek() == ',') {
                    ++i_;
                    continue;
                }
                expect(']');
                return v;
            }
        }
        if (c == '"') {
            v.type_ = JsonValue::Type::String;
            v.string_ = stringLiteral();
            return v;
        }
        if (c == 't' || c == 'f') {
            v.type_ = JsonValue::Type::Bool;
            v.bool_ = c == 't';
            literal(c == 't' ? "true" : "false");
            return v;
        }
        if (c == 'n') {
            literal("null");
            return v;
        }
        if (c == '-' || (c >= '0' && c <= '9')) {
            const char* begin = s_.c_str() + i_;
            char* end = nullptr;
            errno = 0;
            v.number_ = std::strtod(begin, &end);
            if (end == begin || errno == ERANGE || !std::isfinite(v.number_))
                fail("bad number");
            v.type_ = JsonValue::Type::Number;
            i_ += static_cast<std::size_t>(end - begin);
            return v;
        }
        fail(std::string("unexpected character '") + c + "'");
    }
    std::string stringLiteral() {
        ++i_;  // opening quote
        std::string out;
        while (true) {
            if (i_ >= s_.size())
                fail("unterminated string");
            const char c = s_[i_++];
            if (c == '"')
                return out;
            if (static_cast<unsigned char>(c) < 0x20)
                fail("control character in a string");
            if (c != '\\') {
                out += c;
                continue;
            }
            if (i_ >= s_.size())
                fail("unterminated string");
            const char e = s_[i_++];
            switch (e) {
                case '"':
                    out += '"';
                    break;
                case '\\':
                    out += '\\';
                    break;
                case '/':
                    out += '/';
                    break;
                case 'b':
                    out += '\b';
                    break;
                case 'f':
                    out += '\f';
                    break;
                case 'n':
                    out += '\n';
                    break;
                case 'r':
                    out += '\r';
                    break;
                case 't':
                    out += '\t';
                    break;
                case 'u': {
                    if (i_ + 4 > s_.size())
                        fail("bad \\u escape");
                    const unsigned code =
                        static_cast<unsigned>(std::stoul(s_.substr(i_, 4), nullptr, 16));
                    i_ += 4;
                    // UTF-8 for the basic multilingual plane (surrogate pairs are not needed
                    // for room names and are kept as two 3-byte sequences).
                    if (code < 0x80) {
                        out += static_cast<char>(code);
                    } else if (code < 0x800) {
                        out += static_cast<char>(0xC0 | (code >> 6));
                        out += static_cast<char>(0x80 | (code & 0x3F));
                    } else {
                        out += static_cast<char>(0xE0 | (code >> 12));
                        out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
                        out += static_cast<char>(0x80 | (code & 0x3F));
                    }
                    break;
                }
                default:
                    fail("bad escape in a string");
            }
        }
    }

    const std::string& s_;
    std::size_t i_ = 0;
};

JsonValue JsonValue::parse(const std::string& text) {
    return JsonParser(text).document();
}

double JsonValue::number(const std::string& what) const {
    if (type_ != Type::Number)
        throw JsonError(what + " must be a number");
    return number_;
}

long long JsonValue::integer(const std::string& what, long long lo, long long hi) const {
    const double v = number(what);
    if (v != std::floor(v) || v < static_cast<double>(lo) || v > static_cast<double>(hi)) {
        throw JsonError(what + " must be an integer in [" + std::to_string(lo) + ", " +
                        std::to_string(hi) + "]");
    }
    return static_cast<long long>(v);
}

const std::string& JsonValue::string(const std::string& what) const {
    if (type_ != Type::String)
        throw JsonError(what + " must be a string");
    return string_;
}

bool JsonValue::boolean(const std::string& what) const {
    if (type_ != Type::Bool)
        throw JsonError(what + " must be true or false");
    return bool_;
}

const std::vector<JsonValue>& JsonValue::array(const std::string& what) const {
    if (type_ != Type::Array)
        throw JsonError(what + " must be an array");
    return array_;
}

const JsonValue& JsonValue::at(const std::string& key, const std::string& what) const {
    if (type_ != Type::Object)
        throw JsonError(what + " must be an object");
    auto it = object_.find(key);
    if (it == object_.end())
        throw JsonError(what + " has no member \"" + key + "\"");
    return it->second;
}

const JsonValue* JsonValue::find(const std::string& key) const {
    if (type_ != Type::Object)
        return nullptr;
    auto it = object_.find(key);
    return it == object_.end() ? nullptr : &it->second;
}

}  // namespace toposlam::rooms::detail
