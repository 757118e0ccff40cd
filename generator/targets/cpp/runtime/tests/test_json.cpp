// Runtime tests of the canonical JSON writer, the JSON reader and Json<T> of primitives
// (json_writer.hpp, json_reader.hpp, json_codec.hpp).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "protopkg/json_codec.hpp"
#include "protopkg/json_reader.hpp"
#include "protopkg/json_writer.hpp"

namespace {

namespace pkg = ::protopkg;

std::string json_of_double(double d) {
    std::string s;
    pkg::JsonWriter w(pkg::string_sink, &s);
    w.float64(d);
    return s;
}

std::string json_of_float_bits(std::uint32_t bits) {
    float f;
    std::memcpy(&f, &bits, 4);
    std::string s;
    pkg::JsonWriter w(pkg::string_sink, &s);
    w.float32(f);
    return s;
}

TEST(Json, FloatsLikePythonRepr) {
    EXPECT_EQ(json_of_double(1.0), "1.0");
    EXPECT_EQ(json_of_double(0.0), "0.0");
    EXPECT_EQ(json_of_double(-0.0), "-0.0");
    EXPECT_EQ(json_of_double(0.0001), "0.0001");
    EXPECT_EQ(json_of_double(0.00001), "1e-05");
    EXPECT_EQ(json_of_double(123.456), "123.456");
    EXPECT_EQ(json_of_double(1e16), "1e+16");
    EXPECT_EQ(json_of_double(1.5e16), "1.5e+16");
    EXPECT_EQ(json_of_double(9999999999999998.0), "9999999999999998.0");
    EXPECT_EQ(json_of_double(2.5e-310), "2.5e-310");
    EXPECT_EQ(json_of_double(1.7976931348623157e308), "1.7976931348623157e+308");
    EXPECT_EQ(json_of_double(0.1), "0.1");
    EXPECT_EQ(json_of_double(-123456789.125), "-123456789.125");
    EXPECT_EQ(json_of_double(std::numeric_limits<double>::infinity()), "\"inf\"");
    EXPECT_EQ(json_of_double(-std::numeric_limits<double>::infinity()), "\"-inf\"");
    EXPECT_EQ(json_of_double(std::numeric_limits<double>::quiet_NaN()), "\"nan\"");
    EXPECT_EQ(json_of_float_bits(0x3dcccccd), "0.10000000149011612"); // 0.1f widened
    EXPECT_EQ(json_of_float_bits(0x7fc00000), "\"nan\"");
    EXPECT_EQ(json_of_float_bits(0xffc00000), "\"nan:0xffc00000\"");
    EXPECT_EQ(json_of_float_bits(0x7fe5bf7f), "\"nan:0x7fe5bf7f\"");
}

TEST(Json, NanPayloadReadsBack) {
    pkg::json::Value v;
    std::string error;
    ASSERT_TRUE(pkg::json::parse("\"nan:0x7fe5bf7f\"", v, error)) << error;
    float f = 0;
    pkg::JsonError err;
    ASSERT_TRUE(pkg::Json<float>::read(v, f, err)) << err.text();
    std::uint32_t bits;
    std::memcpy(&bits, &f, 4);
    EXPECT_EQ(bits, 0x7fe5bf7fu);
    ASSERT_TRUE(pkg::json::parse("\"nan:0x7ff0000000000001\"", v, error)) << error;
    double d = 0;
    ASSERT_TRUE(pkg::Json<double>::read(v, d, err)) << err.text();
    std::uint64_t dbits;
    std::memcpy(&dbits, &d, 8);
    EXPECT_EQ(dbits, 0x7ff0000000000001ull);
    ASSERT_TRUE(pkg::json::parse("\"nan:0x3f800000\"", v, error));
    EXPECT_FALSE(pkg::Json<float>::read(v, f, err)); // 1.0f is not a NaN
    ASSERT_TRUE(pkg::json::parse("-0.0", v, error));
    ASSERT_TRUE(pkg::Json<double>::read(v, d, err));
    EXPECT_TRUE(std::signbit(d));
}

TEST(Json, StringsEscapeBytes) {
    std::string s;
    pkg::JsonWriter w(pkg::string_sink, &s);
    const char raw[] = {'a', '"', '\\', '\x00', '\x1f', '\x7f', '\xe9', 'z'};
    w.string(raw, sizeof raw);
    EXPECT_EQ(s, "\"a\\\"\\\\\\u0000\\u001f\\u007f\\u00e9z\"");
    pkg::json::Value v;
    std::string error;
    ASSERT_TRUE(pkg::json::parse(s, v, error)) << error;
    EXPECT_EQ(v.text, std::string(raw, sizeof raw));
}

} // namespace
