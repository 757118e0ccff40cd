// Canonical JSON writer (docs/conformance.md section 4): no spaces, ASCII only, floats as the
// shortest round-trip digits laid out like Python's repr, NaN payloads kept. Writes to a sink.
#pragma once

#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "protopkg/framing.hpp"

namespace protopkg {

/// Text of a finite double: shortest round-trip digits, positional when -4 <= exponent < 16.
/// `out` must hold 32 characters; returns the length.
inline std::size_t format_double(double value, char *out) {
    char sci[40];
    const auto res = std::to_chars(sci, sci + sizeof sci, value, std::chars_format::scientific);
    const char *p = sci;
    const char *end = res.ptr;
    std::size_t n = 0;
    if (*p == '-') {
        out[n++] = '-';
        ++p;
    }
    char digits[24];
    std::size_t nd = 0;
    while (p < end && *p != 'e') {
        if (*p != '.' && nd < sizeof digits) {
            digits[nd++] = *p;
        }
        ++p;
    }
    int exp10 = 0;
    if (p < end) {
        ++p; // 'e'
        const bool neg = *p == '-';
        ++p;
        while (p < end) {
            exp10 = exp10 * 10 + (*p - '0');
            ++p;
        }
        if (neg) {
            exp10 = -exp10;
        }
    }
    if (exp10 >= -4 && exp10 < 16) {
        if (exp10 >= 0) {
            const std::size_t int_digits = static_cast<std::size_t>(exp10) + 1;
            for (std::size_t i = 0; i < int_digits; ++i) {
                out[n++] = i < nd ? digits[i] : '0';
            }
            out[n++] = '.';
            if (nd > int_digits) {
                for (std::size_t i = int_digits; i < nd; ++i) {
                    out[n++] = digits[i];
                }
            } else {
                out[n++] = '0';
            }
        } else {
            out[n++] = '0';
            out[n++] = '.';
            for (int i = -1; i > exp10; --i) {
                out[n++] = '0';
            }
            for (std::size_t i = 0; i < nd; ++i) {
                out[n++] = digits[i];
            }
        }
    } else {
        out[n++] = digits[0];
        if (nd > 1) {
            out[n++] = '.';
            for (std::size_t i = 1; i < nd; ++i) {
                out[n++] = digits[i];
            }
        }
        out[n++] = 'e';
        out[n++] = exp10 < 0 ? '-' : '+';
        const int a = exp10 < 0 ? -exp10 : exp10;
        if (a >= 100) {
            out[n++] = static_cast<char>('0' + a / 100);
        }
        out[n++] = static_cast<char>('0' + (a / 10) % 10);
        out[n++] = static_cast<char>('0' + a % 10);
    }
    return n;
}

class JsonWriter {
  public:
    /// Receives the text; called many times per line.
    using Sink = void (*)(void *context, const char *data, std::size_t size);

    JsonWriter(Sink sink, void *context) : sink_(sink), context_(context) {}

    void begin_object() {
        open('{');
    }
    void end_object() {
        close('}');
    }
    void begin_array() {
        open('[');
    }
    void end_array() {
        close(']');
    }
    /// An object key (plain ASCII names from the spec).
    void key(const char *name) {
        separate();
        raw("\"");
        raw(name);
        raw("\":");
        after_key_ = true;
    }
    void null() {
        separate();
        raw("null");
    }
    void boolean(bool v) {
        separate();
        raw(v ? "true" : "false");
    }
    void integer(std::int64_t v) {
        separate();
        char buf[24];
        const auto res = std::to_chars(buf, buf + sizeof buf, v);
        raw(buf, static_cast<std::size_t>(res.ptr - buf));
    }
    void uinteger(std::uint64_t v) {
        separate();
        char buf[24];
        const auto res = std::to_chars(buf, buf + sizeof buf, v);
        raw(buf, static_cast<std::size_t>(res.ptr - buf));
    }
    /// A float: widened to double, except NaN ("nan:0x" + 8 hex digits unless 0x7fc00000).
    void float32(float v) {
        if (std::isnan(v)) {
            std::uint32_t bits;
            std::memcpy(&bits, &v, 4);
            nan(bits, 8, bits == 0x7fc00000u);
            return;
        }
        float64(static_cast<double>(v));
    }
    void float64(double v) {
        if (std::isnan(v)) {
            std::uint64_t bits;
            std::memcpy(&bits, &v, 8);
            nan(bits, 16, bits == 0x7ff8000000000000ull);
            return;
        }
        separate();
        if (std::isinf(v)) {
            raw(v > 0 ? "\"inf\"" : "\"-inf\"");
            return;
        }
        char buf[40];
        raw(buf, format_double(v, buf));
    }
    /// A string of raw bytes: byte b -> U+00bb, escaped per docs/conformance.md.
    void string(const char *s, std::size_t n) {
        separate();
        raw("\"");
        static const char hexd[] = "0123456789abcdef";
        for (std::size_t i = 0; i < n; ++i) {
            const unsigned char b = static_cast<unsigned char>(s[i]);
            if (b == '"') {
                raw("\\\"");
            } else if (b == '\\') {
                raw("\\\\");
            } else if (b < 0x20 || b >= 0x7f) {
                char e[6] = {'\\', 'u', '0', '0', hexd[b >> 4], hexd[b & 15]};
                raw(e, 6);
            } else {
                raw(s + i, 1);
            }
        }
        raw("\"");
    }
    void string(const char *s) {
        string(s, std::strlen(s));
    }
    /// Lowercase hex of bytes, as a JSON string.
    void hex(const std::uint8_t *p, std::size_t n) {
        separate();
        raw("\"");
        static const char hexd[] = "0123456789abcdef";
        char chunk[64];
        std::size_t k = 0;
        for (std::size_t i = 0; i < n; ++i) {
            chunk[k++] = hexd[p[i] >> 4];
            chunk[k++] = hexd[p[i] & 15];
            if (k == sizeof chunk) {
                raw(chunk, k);
                k = 0;
            }
        }
        raw(chunk, k);
        raw("\"");
    }
    /// Raw text (no separator handling).
    void raw(const char *s, std::size_t n) {
        if (n > 0) {
            sink_(context_, s, n);
        }
    }
    void raw(const char *s) {
        raw(s, std::strlen(s));
    }

  private:
    void nan(std::uint64_t bits, int digits, bool canonical) {
        separate();
        if (canonical) {
            raw("\"nan\"");
            return;
        }
        char buf[32] = "\"nan:0x";
        std::size_t n = 7;
        static const char hexd[] = "0123456789abcdef";
        for (int i = digits - 1; i >= 0; --i) {
            buf[n++] = hexd[(bits >> (4 * i)) & 15];
        }
        buf[n++] = '"';
        raw(buf, n);
    }
    void separate() {
        if (after_key_) {
            after_key_ = false;
            return;
        }
        if (depth_ > 0 && depth_ <= first_.size()) {
            if (!first_[depth_ - 1]) {
                raw(",");
            }
            first_[depth_ - 1] = false;
        }
    }
    void open(char c) {
        separate();
        raw(&c, 1);
        ++depth_;
        if (depth_ <= first_.size()) {
            first_[depth_ - 1] = true;
        }
    }
    void close(char c) {
        if (depth_ > 0) {
            --depth_;
        }
        after_key_ = false;
        raw(&c, 1);
    }

    Sink sink_;
    void *context_;
    std::array<bool, kMaxJsonDepth> first_{};
    std::size_t depth_ = 0;
    bool after_key_ = false;
};

/// Sink that appends to a std::string (context = std::string*).
inline void string_sink(void *context, const char *data, std::size_t size) {
    static_cast<std::string *>(context)->append(data, size);
}

} // namespace protopkg
