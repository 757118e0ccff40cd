// Json<T>: canonical JSON of a wire type (write) and the value back from JSON (read, for encode).
// Specialised here for primitives and enums, and in the generated *_json.hpp headers.
#pragma once

#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <string>
#include <type_traits>

#include "protopkg/json_reader.hpp"
#include "protopkg/json_writer.hpp"
#include "protopkg/wire.hpp"

namespace protopkg {

/// Why a JSON value does not fit a wire type; `path` names the parameter ("info.model_name").
struct JsonError {
    std::string path;
    std::string message;

    JsonError &enter(const char *name) {
        if (path.empty()) {
            path = name;
        } else if (path[0] == '[') {
            path = name + path;
        } else {
            path = std::string(name) + "." + path;
        }
        return *this;
    }
    JsonError &enter_index(std::size_t i) {
        const std::string idx = "[" + std::to_string(i) + "]";
        path = path.empty() || path[0] == '[' ? idx + path : idx + "." + path;
        return *this;
    }
    bool fail(const std::string &what) {
        message = what;
        return false;
    }
    bool missing(const char *name) {
        message = std::string("missing '") + name + "'";
        return false;
    }
    std::string text() const {
        return path.empty() ? message : path + ": " + message;
    }
};

template <class T, class Enable = void> struct Json;

namespace detail {

/// Sign and magnitude of a JSON integer (no fraction or exponent).
inline bool json_integer(const json::Value &x, bool &negative, std::uint64_t &magnitude) {
    if (!x.is_integer()) {
        return false;
    }
    const char *p = x.text.data();
    const char *end = p + x.text.size();
    negative = *p == '-';
    if (negative) {
        ++p;
    }
    const auto res = std::from_chars(p, end, magnitude);
    return res.ec == std::errc() && res.ptr == end;
}

inline bool parse_hex_bits(const std::string &s, std::size_t digits, std::uint64_t &bits) {
    if (s.size() != digits) {
        return false;
    }
    bits = 0;
    for (char c : s) {
        int h = -1;
        if (c >= '0' && c <= '9') {
            h = c - '0';
        } else if (c >= 'a' && c <= 'f') {
            h = c - 'a' + 10;
        } else if (c >= 'A' && c <= 'F') {
            h = c - 'A' + 10;
        }
        if (h < 0) {
            return false;
        }
        bits = (bits << 4) | static_cast<std::uint64_t>(h);
    }
    return true;
}

/// For a JSON number that from_chars found out of range: true when it is too large (its first
/// significant digit stands for 10^k with k >= 0), false when it is too small (rounds to zero).
inline bool json_number_is_large(const std::string &t) {
    std::size_t i = !t.empty() && t[0] == '-' ? 1 : 0;
    std::size_t int_digits = 0;
    while (i + int_digits < t.size() && t[i + int_digits] >= '0' && t[i + int_digits] <= '9') {
        ++int_digits;
    }
    long long first = 0; // power of ten of the first significant digit
    bool found = false;
    for (std::size_t j = 0; j < int_digits && !found; ++j) {
        if (t[i + j] != '0') {
            found = true;
            first = static_cast<long long>(int_digits - 1 - j);
        }
    }
    i += int_digits;
    if (i < t.size() && t[i] == '.') {
        ++i;
        for (long long place = -1; i < t.size() && t[i] >= '0' && t[i] <= '9'; ++i, --place) {
            if (!found && t[i] != '0') {
                found = true;
                first = place;
            }
        }
    }
    long long e = 0;
    bool negative = false;
    if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
        ++i;
        if (i < t.size() && (t[i] == '+' || t[i] == '-')) {
            negative = t[i] == '-';
            ++i;
        }
        for (; i < t.size() && t[i] >= '0' && t[i] <= '9'; ++i) {
            if (e < 100000000LL) {
                e = e * 10 + (t[i] - '0');
            }
        }
    }
    return found && first + (negative ? -e : e) >= 0;
}

/// A float/double from a number or "inf", "-inf", "nan", "nan:0x<bits>"; Bits is uint32_t or uint64_t.
template <class F, class Bits> bool json_float(const json::Value &x, F &v, JsonError &err) {
    constexpr std::size_t digits = sizeof(Bits) * 2;
    const std::string expected = std::string("expected a number, \"inf\", \"-inf\", \"nan\" or \"nan:0x<") +
                                 std::to_string(digits) + " hex digits>\"";
    if (x.type == json::Value::Type::string) {
        if (x.text == "inf") {
            v = std::numeric_limits<F>::infinity();
            return true;
        }
        if (x.text == "-inf") {
            v = -std::numeric_limits<F>::infinity();
            return true;
        }
        Bits bits = 0;
        if (x.text == "nan") {
            bits =
                sizeof(Bits) == 4 ? static_cast<Bits>(0x7fc00000u) : static_cast<Bits>(0x7ff8000000000000ull);
        } else if (x.text.compare(0, 6, "nan:0x") == 0) {
            std::uint64_t b = 0;
            if (!parse_hex_bits(x.text.substr(6), digits, b)) {
                return err.fail(expected);
            }
            bits = static_cast<Bits>(b);
        } else {
            return err.fail(expected);
        }
        std::memcpy(&v, &bits, sizeof v);
        if (!std::isnan(v)) {
            return err.fail("\"" + json::printable(x.text) + "\" is not a NaN bit pattern");
        }
        return true;
    }
    if (x.type != json::Value::Type::number) {
        return err.fail(expected);
    }
    // docs/conformance.md §5: the nearest double (ties to even), then for a float the nearest
    // float; a result that is infinite is an error, one that underflows is 0 or a denormal.
    double d = 0;
    const char *end = x.text.data() + x.text.size();
    const auto res = std::from_chars(x.text.data(), end, d);
    if (res.ec == std::errc::result_out_of_range && res.ptr == end && !json_number_is_large(x.text)) {
        d = x.text[0] == '-' ? -0.0 : 0.0; // underflow: rounds to zero
    } else if (res.ec != std::errc() || res.ptr != end || !std::isfinite(d)) {
        return err.fail("number " + x.text + " is out of range for a double");
    }
    if constexpr (sizeof(F) == 4) {
        // From half an ulp above FLT_MAX (0x1.ffffffp127) up, a double rounds to infinity as a
        // float; below it, a double beyond FLT_MAX rounds to FLT_MAX (spelled out: the cast is
        // undefined outside the float range).
        const double fmax = static_cast<double>(std::numeric_limits<float>::max());
        if (std::fabs(d) >= 0x1.ffffffp127) {
            return err.fail("number " + x.text + " is out of range for a float");
        }
        if (std::fabs(d) > fmax) {
            d = d > 0 ? fmax : -fmax;
        }
    }
    v = static_cast<F>(d);
    return true;
}

} // namespace detail

template <class T>
struct Json<T,
            std::enable_if_t<std::is_integral_v<T> && !std::is_same_v<T, bool> && !std::is_same_v<T, char>>> {
    static void write(JsonWriter &w, const T &v) {
        if constexpr (std::is_signed_v<T>) {
            w.integer(static_cast<std::int64_t>(v));
        } else {
            w.uinteger(static_cast<std::uint64_t>(v));
        }
    }
    static bool read(const json::Value &x, T &v, JsonError &err) {
        bool negative = false;
        std::uint64_t mag = 0;
        if (detail::json_integer(x, negative, mag)) {
            if constexpr (std::is_signed_v<T>) {
                const std::uint64_t top = static_cast<std::uint64_t>(std::numeric_limits<T>::max());
                if (!negative && mag <= top) {
                    v = static_cast<T>(mag);
                    return true;
                }
                if (negative && mag <= top + 1) {
                    v = mag == 0 ? T{0} : static_cast<T>(-static_cast<std::int64_t>(mag - 1) - 1);
                    return true;
                }
            } else {
                if ((!negative || mag == 0) && mag <= std::numeric_limits<T>::max()) {
                    v = static_cast<T>(mag);
                    return true;
                }
            }
        }
        return err.fail("expected an integer in " + std::to_string(std::numeric_limits<T>::min()) + ".." +
                        std::to_string(std::numeric_limits<T>::max()));
    }
};

/// Enums: the integer value, written and read (docs/conformance.md section 5: a value name is
/// not accepted, in every language; from_string() gives a name's value to the caller's code).
template <class T> struct Json<T, std::enable_if_t<std::is_enum_v<T>>> {
    using U = std::underlying_type_t<T>;
    static void write(JsonWriter &w, const T &v) {
        Json<U>::write(w, static_cast<U>(v));
    }
    static bool read(const json::Value &x, T &v, JsonError &err) {
        U u{};
        if (!Json<U>::read(x, u, err)) {
            return false;
        }
        v = static_cast<T>(u);
        return true;
    }
};

template <> struct Json<bool> {
    static void write(JsonWriter &w, const bool &v) {
        w.boolean(v);
    }
    static bool read(const json::Value &x, bool &v, JsonError &err) {
        if (x.type != json::Value::Type::boolean) {
            return err.fail("expected true or false");
        }
        v = x.boolean;
        return true;
    }
};

template <> struct Json<char> {
    static void write(JsonWriter &w, const char &v) {
        w.string(&v, 1);
    }
    static bool read(const json::Value &x, char &v, JsonError &err) {
        if (x.type != json::Value::Type::string || x.wide || x.text.size() != 1) {
            return err.fail("expected a string of 1 character (U+0000..U+00FF)");
        }
        v = x.text[0];
        return true;
    }
};

template <> struct Json<float> {
    static void write(JsonWriter &w, const float &v) {
        w.float32(v);
    }
    static bool read(const json::Value &x, float &v, JsonError &err) {
        return detail::json_float<float, std::uint32_t>(x, v, err);
    }
};

template <> struct Json<double> {
    static void write(JsonWriter &w, const double &v) {
        w.float64(v);
    }
    static bool read(const json::Value &x, double &v, JsonError &err) {
        return detail::json_float<double, std::uint64_t>(x, v, err);
    }
};

// ---- parameter helpers used by the generated JSON codecs

template <class T> void json_write_value(JsonWriter &w, const T &v) {
    Json<T>::write(w, v);
}
template <class T> bool json_read_value(const json::Value &x, T &v, JsonError &err) {
    return Json<T>::read(x, v, err);
}

template <std::size_t N> void json_write_string(JsonWriter &w, const std::array<char, N> &v) {
    w.string(v.data(), N);
}
template <std::size_t N> bool json_read_string(const json::Value &x, std::array<char, N> &v, JsonError &err) {
    if (x.type != json::Value::Type::string || x.wide || x.text.size() != N) {
        return err.fail("expected a string of exactly " + std::to_string(N) + " characters (U+0000..U+00FF)");
    }
    std::memcpy(v.data(), x.text.data(), N);
    return true;
}

template <class C> void json_write_array(JsonWriter &w, const C &items) {
    w.begin_array();
    for (const auto &item : items) {
        Json<typename C::value_type>::write(w, item);
    }
    w.end_array();
}

namespace detail {
template <class T, class C>
bool json_read_items(const json::Value &x, C &out, std::size_t n, JsonError &err) {
    for (std::size_t i = 0; i < n; ++i) {
        if (!Json<T>::read(x.items[i], out[i], err)) {
            err.enter_index(i);
            return false;
        }
    }
    return true;
}
} // namespace detail

template <class T, std::size_t N>
bool json_read_fixed(const json::Value &x, std::array<T, N> &v, JsonError &err) {
    if (x.type != json::Value::Type::array || x.items.size() != N) {
        return err.fail("expected an array of " + std::to_string(N) + " elements");
    }
    return detail::json_read_items<T>(x, v, N, err);
}

template <class T, std::size_t M>
bool json_read_remaining(const json::Value &x, BoundedVector<T, M> &v, JsonError &err) {
    if (x.type != json::Value::Type::array) {
        return err.fail("expected an array");
    }
    if (x.items.size() > M) {
        return err.fail("has " + std::to_string(x.items.size()) + " elements, more than the maximum " +
                        std::to_string(M));
    }
    v.resize(x.items.size());
    return detail::json_read_items<T>(x, v, x.items.size(), err);
}

template <class T, std::size_t M>
bool json_read_counted(const json::Value &x, BoundedVector<T, M> &v, std::uint64_t count, JsonError &err) {
    if (!json_read_remaining(x, v, err)) {
        return false;
    }
    if (v.size() != count) {
        return err.fail("has " + std::to_string(v.size()) + " elements but its count parameter is " +
                        std::to_string(count));
    }
    return true;
}

/// True when x is an object whose keys are all among `known`.
inline bool json_check_object(const json::Value &x, std::initializer_list<const char *> known,
                              JsonError &err) {
    if (x.type != json::Value::Type::object) {
        return err.fail(std::string("expected an object, not ") + json::type_name(x.type));
    }
    for (const std::string &k : x.keys) {
        bool ok = false;
        for (const char *name : known) {
            if (k == name) {
                ok = true;
                break;
            }
        }
        if (!ok) {
            return err.fail("unknown key '" + json::printable(k) + "'");
        }
    }
    return true;
}

} // namespace protopkg
