// Golden vectors (tests/vectors/): decode the bytes (whole and byte by byte) and compare the
// exact JSON lines; encode the lines back and compare the bytes. Generated: do not edit.
#include <gtest/gtest.h>

#include "test_support.hpp"

namespace {

[[maybe_unused]] void check_vector(const char *hex, mscip_device_t device, const char *expect) {
    using namespace test_support;
    std::vector<uint8_t> bytes = from_hex(hex);
    EXPECT_EQ(decode_text(bytes, 0, device), expect) << "decoded whole";
    EXPECT_EQ(decode_text(bytes, 1, device), expect) << "decoded one byte at a time";
    std::vector<uint8_t> encoded;
    std::string error;
    ASSERT_TRUE(encode_text(expect, &encoded, &error)) << error;
    EXPECT_EQ(to_hex(encoded), hex) << "encoded from the expected lines";
}

} // namespace
