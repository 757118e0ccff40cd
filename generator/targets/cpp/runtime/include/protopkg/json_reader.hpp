// A small strict JSON reader for the encode tool: one document -> a tree of json::Value.
// Strings keep one byte per character (U+0000..U+00FF, as the canonical writer prints them);
// numbers keep their text so that integers and floats are converted exactly later.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace protopkg::json {

struct Value {
    enum class Type : std::uint8_t { null, boolean, number, string, array, object };
    Type type = Type::null;
    bool boolean = false;
    bool wide = false;             ///< string: holds a character above U+00FF
    std::string text;              ///< number: its literal; string: one byte per character
    std::vector<Value> items;      ///< array elements, or object member values
    std::vector<std::string> keys; ///< object member names (same order as items)

    const Value *find(const char *key) const {
        for (std::size_t i = 0; i < keys.size(); ++i) {
            if (keys[i] == key) {
                return &items[i];
            }
        }
        return nullptr;
    }
    bool is_integer() const {
        return type == Type::number && text.find_first_of(".eE") == std::string::npos;
    }
};

inline const char *type_name(Value::Type t) {
    switch (t) {
    case Value::Type::null:
        return "null";
    case Value::Type::boolean:
        return "a boolean";
    case Value::Type::number:
        return "a number";
    case Value::Type::string:
        return "a string";
    case Value::Type::array:
        return "an array";
    case Value::Type::object:
        return "an object";
    }
    return "?";
}

/// Text from the input made safe for a one-line message (control and non-ASCII bytes as \u00xx).
inline std::string printable(const std::string &s) {
    static const char hexd[] = "0123456789abcdef";
    std::string out;
    for (char c : s) {
        const unsigned char b = static_cast<unsigned char>(c);
        if (b < 0x20 || b >= 0x7f) {
            out += "\\u00";
            out.push_back(hexd[b >> 4]);
            out.push_back(hexd[b & 15]);
        } else {
            out.push_back(c);
        }
    }
    return out;
}

class Parser {
  public:
    explicit Parser(const std::string &text) : s_(text) {}

    bool parse(Value &out, std::string &error) {
        skip_ws();
        if (!value(out, 0)) {
            error = error_;
            return false;
        }
        skip_ws();
        if (pos_ != s_.size()) {
            fail("unexpected text after the JSON value");
            error = error_;
            return false;
        }
        return true;
    }

  private:
    static constexpr int kMaxDepth = 64;

    bool fail(const char *what) {
        if (error_.empty()) {
            error_ = std::string("invalid JSON at column ") + std::to_string(pos_ + 1) + ": " + what;
        }
        return false;
    }
    void skip_ws() {
        while (pos_ < s_.size() &&
               (s_[pos_] == ' ' || s_[pos_] == '\t' || s_[pos_] == '\n' || s_[pos_] == '\r')) {
            ++pos_;
        }
    }
    bool literal(const char *word) {
        const std::size_t n = std::strlen(word);
        if (s_.compare(pos_, n, word) != 0) {
            return fail("unknown literal");
        }
        pos_ += n;
        return true;
    }
    bool value(Value &out, int depth) {
        if (depth > kMaxDepth) {
            return fail("nested too deeply");
        }
        if (pos_ >= s_.size()) {
            return fail("a value is missing");
        }
        const char c = s_[pos_];
        if (c == '{') {
            return object(out, depth);
        }
        if (c == '[') {
            return array(out, depth);
        }
        if (c == '"') {
            out.type = Value::Type::string;
            return string(out.text, out.wide);
        }
        if (c == 't') {
            out.type = Value::Type::boolean;
            out.boolean = true;
            return literal("true");
        }
        if (c == 'f') {
            out.type = Value::Type::boolean;
            out.boolean = false;
            return literal("false");
        }
        if (c == 'n') {
            out.type = Value::Type::null;
            return literal("null");
        }
        if (c == '-' || (c >= '0' && c <= '9')) {
            out.type = Value::Type::number;
            return number(out.text);
        }
        return fail("unexpected character");
    }
    bool digits() {
        const std::size_t start = pos_;
        while (pos_ < s_.size() && s_[pos_] >= '0' && s_[pos_] <= '9') {
            ++pos_;
        }
        return pos_ > start;
    }
    bool number(std::string &out) {
        const std::size_t start = pos_;
        if (s_[pos_] == '-') {
            ++pos_;
        }
        if (pos_ < s_.size() && s_[pos_] == '0') {
            ++pos_;
        } else if (!digits()) {
            return fail("bad number");
        }
        if (pos_ < s_.size() && s_[pos_] == '.') {
            ++pos_;
            if (!digits()) {
                return fail("bad number");
            }
        }
        if (pos_ < s_.size() && (s_[pos_] == 'e' || s_[pos_] == 'E')) {
            ++pos_;
            if (pos_ < s_.size() && (s_[pos_] == '+' || s_[pos_] == '-')) {
                ++pos_;
            }
            if (!digits()) {
                return fail("bad number");
            }
        }
        out.assign(s_, start, pos_ - start);
        return true;
    }
    static int hexval(char c) {
        if (c >= '0' && c <= '9') {
            return c - '0';
        }
        if (c >= 'a' && c <= 'f') {
            return c - 'a' + 10;
        }
        if (c >= 'A' && c <= 'F') {
            return c - 'A' + 10;
        }
        return -1;
    }
    void put(std::string &out, bool &wide, std::uint32_t cp) {
        if (cp > 0xFF) {
            wide = true;
            out.push_back('?');
        } else {
            out.push_back(static_cast<char>(static_cast<unsigned char>(cp)));
        }
    }
    bool string(std::string &out, bool &wide) {
        ++pos_; // opening quote
        out.clear();
        wide = false;
        while (true) {
            if (pos_ >= s_.size()) {
                return fail("unterminated string");
            }
            const unsigned char c = static_cast<unsigned char>(s_[pos_]);
            if (c == '"') {
                ++pos_;
                return true;
            }
            if (c < 0x20) {
                return fail("control character in string");
            }
            if (c == '\\') {
                if (pos_ + 1 >= s_.size()) {
                    return fail("unterminated string");
                }
                const char e = s_[pos_ + 1];
                pos_ += 2;
                switch (e) {
                case '"':
                    out.push_back('"');
                    break;
                case '\\':
                    out.push_back('\\');
                    break;
                case '/':
                    out.push_back('/');
                    break;
                case 'b':
                    out.push_back('\b');
                    break;
                case 'f':
                    out.push_back('\f');
                    break;
                case 'n':
                    out.push_back('\n');
                    break;
                case 'r':
                    out.push_back('\r');
                    break;
                case 't':
                    out.push_back('\t');
                    break;
                case 'u': {
                    if (pos_ + 4 > s_.size()) {
                        return fail("bad \\u escape");
                    }
                    std::uint32_t cp = 0;
                    for (int i = 0; i < 4; ++i) {
                        const int h = hexval(s_[pos_ + static_cast<std::size_t>(i)]);
                        if (h < 0) {
                            return fail("bad \\u escape");
                        }
                        cp = cp * 16 + static_cast<std::uint32_t>(h);
                    }
                    pos_ += 4;
                    put(out, wide, cp);
                    break;
                }
                default:
                    return fail("bad escape");
                }
                continue;
            }
            if (c < 0x80) {
                out.push_back(static_cast<char>(c));
                ++pos_;
                continue;
            }
            // UTF-8 sequence
            std::size_t n = 0;
            std::uint32_t cp = 0;
            if ((c & 0xE0) == 0xC0) {
                n = 1;
                cp = c & 0x1F;
            } else if ((c & 0xF0) == 0xE0) {
                n = 2;
                cp = c & 0x0F;
            } else if ((c & 0xF8) == 0xF0) {
                n = 3;
                cp = c & 0x07;
            } else {
                return fail("invalid UTF-8");
            }
            if (pos_ + n >= s_.size()) {
                return fail("invalid UTF-8");
            }
            for (std::size_t i = 1; i <= n; ++i) {
                const unsigned char d = static_cast<unsigned char>(s_[pos_ + i]);
                if ((d & 0xC0) != 0x80) {
                    return fail("invalid UTF-8");
                }
                cp = (cp << 6) | (d & 0x3F);
            }
            // RFC 3629: the shortest form only, no surrogates, nothing above U+10FFFF.
            static constexpr std::uint32_t kLeast[] = {0, 0x80, 0x800, 0x10000};
            if (cp < kLeast[n] || (cp >= 0xD800 && cp <= 0xDFFF) || cp > 0x10FFFF) {
                return fail("invalid UTF-8");
            }
            pos_ += n + 1;
            put(out, wide, cp);
        }
    }
    bool array(Value &out, int depth) {
        out.type = Value::Type::array;
        ++pos_;
        skip_ws();
        if (pos_ < s_.size() && s_[pos_] == ']') {
            ++pos_;
            return true;
        }
        while (true) {
            skip_ws();
            out.items.emplace_back();
            if (!value(out.items.back(), depth + 1)) {
                return false;
            }
            skip_ws();
            if (pos_ < s_.size() && s_[pos_] == ',') {
                ++pos_;
                continue;
            }
            if (pos_ < s_.size() && s_[pos_] == ']') {
                ++pos_;
                return true;
            }
            return fail("expected ',' or ']'");
        }
    }
    bool object(Value &out, int depth) {
        out.type = Value::Type::object;
        ++pos_;
        skip_ws();
        if (pos_ < s_.size() && s_[pos_] == '}') {
            ++pos_;
            return true;
        }
        while (true) {
            skip_ws();
            if (pos_ >= s_.size() || s_[pos_] != '"') {
                return fail("expected a key");
            }
            std::string key;
            bool wide = false;
            if (!string(key, wide)) {
                return false;
            }
            for (const std::string &k : out.keys) {
                if (k == key) {
                    return fail("duplicate key");
                }
            }
            skip_ws();
            if (pos_ >= s_.size() || s_[pos_] != ':') {
                return fail("expected ':'");
            }
            ++pos_;
            skip_ws();
            out.keys.push_back(key);
            out.items.emplace_back();
            if (!value(out.items.back(), depth + 1)) {
                return false;
            }
            skip_ws();
            if (pos_ < s_.size() && s_[pos_] == ',') {
                ++pos_;
                continue;
            }
            if (pos_ < s_.size() && s_[pos_] == '}') {
                ++pos_;
                return true;
            }
            return fail("expected ',' or '}'");
        }
    }

    const std::string &s_;
    std::size_t pos_ = 0;
    std::string error_;
};

/// Parses one JSON document; on failure `error` says where and what.
inline bool parse(const std::string &text, Value &out, std::string &error) {
    out = Value{};
    return Parser(text).parse(out, error);
}

} // namespace protopkg::json
