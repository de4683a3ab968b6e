#pragma once
// A minimal streaming JSON writer (internal to libs/rooms): objects, arrays, strings, numbers,
// booleans, with two-space indentation. Numbers keep full double precision; non-finite numbers
// become null (JSON has no NaN).
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace toposlam::rooms::detail {

class JsonWriter {
  public:
    JsonWriter& beginObject() { return open('{'); }
    JsonWriter& endObject() { return close('}'); }
    JsonWriter& beginArray() { return open('['); }
    JsonWriter& endArray() { return close(']'); }
    /// Arrays printed on one line (numbers): beginInlineArray ... endArray.
    JsonWriter& beginInlineArray() {
        open('[');
        inlineDepth_ = depth_;
        return *this;
    }
    JsonWriter& key(const std::string& k) {
        separate();
        string(k);
        out_ += ": ";
        afterKey_ = true;
        return *this;
    }
    JsonWriter& value(const std::string& s) {
        separate();
        string(s);
        return *this;
    }
    JsonWriter& value(const char* s) { return value(std::string(s)); }
    JsonWriter& value(bool b) {
        separate();
        out_ += b ? "true" : "false";
        return *this;
    }
    JsonWriter& value(double v) {
        separate();
        if (!std::isfinite(v)) {
            out_ += "null";
        } else {
            char buf[32];
            std::snprintf(buf, sizeof buf, "%.17g", v);
            out_ += buf;
        }
        return *this;
    }
    JsonWriter& value(int v) { return integer(v); }
    JsonWriter& value(long v) { return integer(v); }
    JsonWriter& value(long long v) { return integer(v); }
    JsonWriter& value(unsigned v) { return integer(static_cast<long long>(v)); }
    JsonWriter& value(unsigned long v) { return integer(static_cast<long long>(v)); }
    JsonWriter& value(unsigned long long v) { return integer(static_cast<long long>(v)); }
    template <class T>
    JsonWriter& field(const std::string& k, const T& v) {
        key(k);
        return value(v);
    }
    const std::string& str() const { return out_; }

  private:
    JsonWriter& integer(long long v) {
        separate();
        out_ += std::to_string(v);
        return *this;
    }
    JsonWriter& open(char c) {
        separate();
        out_ += c;
        first_.push_back(true);
        ++depth_;
        return *this;
    }
    JsonWriter& close(char c) {
        const bool empty = first_.back();
        first_.pop_back();
        --depth_;
        if (!empty && !isInline())
            newline();
        if (inlineDepth_ > depth_)
            inlineDepth_ = -1;
        out_ += c;
        if (depth_ == 0)
            out_ += '\n';
        return *this;
    }
    bool isInline() const { return inlineDepth_ >= 0 && depth_ + 1 >= inlineDepth_; }
    void separate() {
        if (afterKey_) {
            afterKey_ = false;
            return;
        }
        if (first_.empty())
            return;
        if (!first_.back())
            out_ += isInline() ? ", " : ",";
        first_.back() = false;
        if (!isInline())
            newline();
    }
    void newline() {
        out_ += '\n';
        out_.append(static_cast<std::size_t>(2 * depth_), ' ');
    }
    void string(const std::string& s) {
        out_ += '"';
        for (const char ch : s) {
            const auto u = static_cast<unsigned char>(ch);
            if (ch == '"' || ch == '\\') {
                out_ += '\\';
                out_ += ch;
            } else if (ch == '\n') {
                out_ += "\\n";
            } else if (ch == '\t') {
                out_ += "\\t";
            } else if (u < 0x20) {
                char buf[8];
                std::snprintf(buf, sizeof buf, "\\u%04x", u);
                out_ += buf;
            } else {
                out_ += ch;
            }
        }
        out_ += '"';
    }

    std::string out_;
    std::vector<bool> first_;
    int depth_ = 0;
    int inlineDepth_ = -1;
    bool afterKey_ = false;
};

}  // namespace toposlam::rooms::detail
