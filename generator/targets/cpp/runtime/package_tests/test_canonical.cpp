// Canonical text (docs/conformance.md section 4): the float, double and string table of
// canonical_cases.hpp (generated from generator/testcases.py into every package's tests/) that the
// C, C++, Python and Rust packages all check, printed by the JSON writer and read back. Copied into
// every package (tests/test_canonical.cpp); in place, run on the stub package of tests/package/
// with the few cases of tests/package/canonical_cases.hpp.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "canonical_cases.hpp"
#include "test_support.hpp"

namespace {

namespace pkg = ::protopkg;
using canonical_cases::DoubleCase;
using canonical_cases::FloatCase;
using canonical_cases::kAllBytes;
using canonical_cases::kDoubles;
using canonical_cases::kFloats;

TEST(Canonical, DoublesPrintAndReadBack) {
    for (const DoubleCase &c : kDoubles) {
        double d;
        std::memcpy(&d, &c.bits, sizeof d);
        std::string s;
        pkg::JsonWriter w(pkg::string_sink, &s);
        w.float64(d);
        EXPECT_EQ(s, c.text) << "bits " << std::hex << c.bits;
        pkg::json::Value v;
        std::string error;
        ASSERT_TRUE(pkg::json::parse(c.text, v, error)) << c.text << ": " << error;
        double back = 0;
        pkg::JsonError err;
        ASSERT_TRUE(pkg::Json<double>::read(v, back, err)) << c.text << ": " << err.text();
        std::uint64_t bits;
        std::memcpy(&bits, &back, sizeof bits);
        if (std::string(c.text) == "\"nan\"") {
            EXPECT_TRUE(std::isnan(back));
        } else {
            EXPECT_EQ(bits, c.bits) << c.text;
        }
    }
}

TEST(Canonical, FloatsPrintAndReadBack) {
    for (const FloatCase &c : kFloats) {
        float f;
        std::memcpy(&f, &c.bits, sizeof f);
        std::string s;
        pkg::JsonWriter w(pkg::string_sink, &s);
        w.float32(f);
        EXPECT_EQ(s, c.text) << "bits " << std::hex << c.bits;
        pkg::json::Value v;
        std::string error;
        ASSERT_TRUE(pkg::json::parse(c.text, v, error)) << c.text << ": " << error;
        float back = 0;
        pkg::JsonError err;
        ASSERT_TRUE(pkg::Json<float>::read(v, back, err)) << c.text << ": " << err.text();
        std::uint32_t bits;
        std::memcpy(&bits, &back, sizeof bits);
        EXPECT_EQ(bits, c.bits) << c.text;
    }
}

TEST(Canonical, StringsEscapeEveryByte) {
    char all[256];
    for (int i = 0; i < 256; ++i) {
        all[i] = static_cast<char>(i);
    }
    std::string s;
    pkg::JsonWriter w(pkg::string_sink, &s);
    w.string(all, sizeof all);
    EXPECT_EQ(s, kAllBytes);
    pkg::json::Value v;
    std::string error;
    ASSERT_TRUE(pkg::json::parse(kAllBytes, v, error)) << error;
    EXPECT_EQ(v.text, std::string(all, sizeof all));
}

} // namespace
