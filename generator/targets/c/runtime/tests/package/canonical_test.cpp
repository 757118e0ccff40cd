// Canonical text (docs/conformance.md section 4): the float, double and string table of
// canonical_cases.hpp (generated from generator/testcases.py into every package's tests/) that the
// C, C++, Python and Rust packages all check, printed by the JSON number and string formatters.
// Copied into every package (tests/canonical_test.cpp); in place, run on the few cases of
// generator/targets/c/runtime/tests/package/canonical_cases.hpp.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>

#include "canonical_cases.hpp"
#include "test_support.hpp"

namespace {

using canonical_cases::DoubleCase;
using canonical_cases::FloatCase;
using canonical_cases::kAllBytes;
using canonical_cases::kDoubles;
using canonical_cases::kFloats;

TEST(Canonical, Doubles) {
    for (const DoubleCase &c : kDoubles) {
        double d;
        std::memcpy(&d, &c.bits, sizeof d);
        char buf[CODEC_JSON_NUMBER_MAX];
        size_t n = codec_json_format_double(d, buf, sizeof buf);
        EXPECT_EQ(std::string(buf, n), c.text) << "bits " << std::hex << c.bits;
    }
}

TEST(Canonical, Floats) {
    for (const FloatCase &c : kFloats) {
        float f;
        std::memcpy(&f, &c.bits, sizeof f);
        char buf[CODEC_JSON_NUMBER_MAX];
        size_t n = codec_json_format_float(f, buf, sizeof buf);
        EXPECT_EQ(std::string(buf, n), c.text) << "bits " << std::hex << c.bits;
    }
}

TEST(Canonical, StringsEscapeEveryByte) {
    char all[256];
    for (int i = 0; i < 256; ++i) {
        all[i] = static_cast<char>(i);
    }
    char buf[sizeof kAllBytes + 1];
    codec_json_format_string(all, sizeof all, buf, sizeof buf);
    EXPECT_STREQ(buf, kAllBytes);
}

} // namespace
