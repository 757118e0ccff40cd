// The float printer of json_writer.c (shortest round-trip digits, exact integer arithmetic)
// against an independent reference: the correctly rounded decimal of every precision from
// snprintf("%.*e"), read back with strtod, and its two neighbours (the old printer, slow but
// plain). Checked: a stride through every float32 bit pattern (JSON_FLOAT_EXHAUSTIVE=1 runs all
// 2^32 of them: about an hour), random doubles, and every exponent's edges. The canonical table of
// generator/testcases.py (checked against Python's repr in every package) covers the layout.
#include <gtest/gtest.h>

#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>

extern "C" {
#include "codec/json.h"
}

namespace {

// Significant digits of a decimal text (no sign, point, exponent, leading or trailing zeros).
std::string significant(const char *text) {
    std::string d;
    for (const char *p = text; *p && *p != 'e' && *p != 'E'; p++) {
        if (*p >= '0' && *p <= '9') {
            d += *p;
        }
    }
    size_t a = d.find_first_not_of('0');
    if (a == std::string::npos) {
        return "0";
    }
    d = d.substr(a);
    return d.substr(0, d.find_last_not_of('0') + 1);
}

// The reference: shortest digits that read back as v, the correctly rounded ones first.
std::string reference(double v) {
    char text[64];
    for (int prec = 1; prec <= 17; prec++) {
        std::snprintf(text, sizeof text, "%.*e", prec - 1, v);
        if (std::strtod(text, nullptr) == v) {
            return significant(text);
        }
        // The neighbours at this precision: digits +- one unit in the last place.
        const char *e = std::strchr(text, 'e');
        int x = std::atoi(e + 1);
        std::string d = significant(text);
        d.resize(static_cast<size_t>(prec), '0');
        long long m = std::atoll(d.c_str());
        for (long long alt : {m - 1, m + 1}) {
            char t2[64];
            std::snprintf(t2, sizeof t2, "%lldE%d", alt, x - prec + 1);
            if (alt > 0 && std::strtod(t2, nullptr) == v) {
                return significant(t2);
            }
        }
    }
    std::snprintf(text, sizeof text, "%.16e", v);
    return significant(text);
}

void check(double v) {
    char out[CODEC_JSON_NUMBER_MAX];
    codec_json_format_double(v, out, sizeof out);
    ASSERT_EQ(std::strtod(out, nullptr), v) << out;
    ASSERT_EQ(significant(out), reference(v)) << out;
}

double from_bits(uint64_t b) {
    double v;
    std::memcpy(&v, &b, sizeof v);
    return v;
}

} // namespace

TEST(JsonFloat, Float32StrideAndOptionallyEveryOne) {
    const char *all = std::getenv("JSON_FLOAT_EXHAUSTIVE");
    const uint64_t step =
        all && *all == '1' ? 1 : 16381; // a prime stride: about 130,000 floats of every exponent
    for (uint64_t b = 1; b < 0x7F800000u; b += step) {
        float f;
        uint32_t bits = static_cast<uint32_t>(b);
        std::memcpy(&f, &bits, sizeof f);
        ASSERT_NO_FATAL_FAILURE(check(static_cast<double>(f))) << "float32 bits 0x" << std::hex << bits;
        char out[CODEC_JSON_NUMBER_MAX];
        codec_json_format_float(f, out, sizeof out);
        char dbl[CODEC_JSON_NUMBER_MAX];
        codec_json_format_double(static_cast<double>(f), dbl, sizeof dbl);
        ASSERT_STREQ(out, dbl); // a float prints as its value widened to double
    }
}

TEST(JsonFloat, RandomDoubles) {
    std::mt19937_64 rng(20261125);
    for (int i = 0; i < 100000; i++) {
        double v = from_bits(rng() & 0x7FFFFFFFFFFFFFFFull);
        if (v != v || v > 1.7976931348623157e308) {
            continue;
        }
        ASSERT_NO_FATAL_FAILURE(check(v)) << "bits 0x" << std::hex << (rng() ^ 0);
    }
}

// Doubles of everyday magnitude (about 1e-15 to 1e24), where the digit loop runs in native
// 128-bit integers when the compiler has them; the other tests reach the multi-limb path too.
TEST(JsonFloat, RandomEverydayDoubles) {
    std::mt19937_64 rng(20261126);
    for (int i = 0; i < 200000; i++) {
        uint64_t exponent = 1023 - 50 + rng() % 131;
        double v = from_bits((exponent << 52) | (rng() & 0xFFFFFFFFFFFFFull));
        ASSERT_NO_FATAL_FAILURE(check(v)) << "value " << v;
    }
}

TEST(JsonFloat, EveryExponentEdges) {
    for (uint64_t e = 0; e < 0x7FF; e++) {
        for (uint64_t m :
             {0ull, 1ull, 2ull, 3ull, 0xFFFFFFFFFFFFFull, 0x8000000000000ull, 0x7FFFFFFFFFFFFull}) {
            uint64_t bits = (e << 52) | m;
            if (bits == 0) {
                continue;
            }
            ASSERT_NO_FATAL_FAILURE(check(from_bits(bits))) << "bits 0x" << std::hex << bits;
        }
    }
}

TEST(JsonFloat, PythonReprLayout) {
    // Values and texts from Python's repr(float).
    const struct {
        double v;
        const char *text;
    } cases[] = {{1.0, "1.0"},
                 {0.1, "0.1"},
                 {-0.0, "-0.0"},
                 {5e-324, "5e-324"},
                 {1e16, "1e+16"},
                 {1e15, "1000000000000000.0"},
                 {0.0001, "0.0001"},
                 {0.00001, "1e-05"},
                 {1.7976931348623157e308, "1.7976931348623157e+308"},
                 {2.2250738585072014e-308, "2.2250738585072014e-308"},
                 {1e23, "1e+23"},
                 {9007199254740993.0, "9007199254740992.0"},
                 {123456.789, "123456.789"},
                 {0.30000000000000004, "0.30000000000000004"},
                 {100.0, "100.0"},
                 {-2.5e-7, "-2.5e-07"}};
    for (const auto &c : cases) {
        char out[CODEC_JSON_NUMBER_MAX];
        codec_json_format_double(c.v, out, sizeof out);
        EXPECT_STREQ(out, c.text);
    }
}
