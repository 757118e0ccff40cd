// Runtime tests of wire.hpp: decode error texts, and the byte order of the test protocol.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "protopkg/wire.hpp"

namespace {

namespace pkg = ::protopkg;

TEST(Errors, DecodeErrorText) {
    pkg::DecodeError e = pkg::DecodeError::short_data(16, 2, 3);
    e.enter("model_name").enter("info");
    EXPECT_STREQ(e.text().c_str(), "info.model_name: needs 16 bytes at offset 2, 3 left");
    pkg::DecodeError f = pkg::DecodeError::short_data(2, 10, 1);
    f.enter("rate").enter_index(2).enter("entries");
    EXPECT_STREQ(f.text().c_str(), "entries[2].rate: needs 2 bytes at offset 10, 1 left");
    pkg::DecodeError g = pkg::DecodeError::short_data(2, 10, 1);
    g.enter_index(5).enter("descriptors");
    EXPECT_STREQ(g.text().c_str(), "descriptors[5]: needs 2 bytes at offset 10, 1 left");
    EXPECT_STREQ(pkg::DecodeError::unexpected_bytes(3, 4).text().c_str(), "3 unexpected bytes at offset 4");
    pkg::DecodeError h = pkg::no_union_member_error(std::int16_t{-7});
    h.enter("params");
    EXPECT_STREQ(h.text().c_str(), "params: no member for selector value -7");
    pkg::Reader r(nullptr, 0);
    bool flag = false;
    pkg::DecodeError i;
    const std::uint8_t two[] = {2};
    pkg::Reader rb(two, 1);
    EXPECT_FALSE(pkg::Codec<bool>::read(rb, flag, i));
    i.enter("on");
    EXPECT_STREQ(i.text().c_str(), "on: invalid bool value 2 at offset 0");
    (void)r;
}

// Multi-byte values follow the protocol's byte order (kBigEndian), through the checked Reader and
// Writer and through the straight loads of Plain<T> alike.
TEST(Wire, ByteOrderOfTheProtocol) {
    std::uint8_t buf[8] = {};
    std::size_t written = 0;
    ASSERT_EQ(pkg::encode(std::uint32_t{0x11223344}, buf, sizeof buf, written), pkg::EncodeError::none);
    ASSERT_EQ(written, 4u);
    const std::uint8_t big[] = {0x11, 0x22, 0x33, 0x44};
    const std::uint8_t little[] = {0x44, 0x33, 0x22, 0x11};
    EXPECT_EQ(0, std::memcmp(buf, pkg::kBigEndian ? big : little, 4));

    std::uint32_t checked = 0;
    pkg::DecodeError err;
    pkg::Reader r(buf, 4);
    ASSERT_TRUE(pkg::Codec<std::uint32_t>::read(r, checked, err));
    EXPECT_EQ(checked, 0x11223344u);
    std::uint32_t straight = 0;
    pkg::Plain<std::uint32_t>::load(buf, straight);
    EXPECT_EQ(straight, 0x11223344u);

    std::int16_t negative = 0;
    ASSERT_EQ(pkg::encode(std::int16_t{-2}, buf, sizeof buf, written), pkg::EncodeError::none);
    EXPECT_EQ(buf[pkg::kBigEndian ? 1 : 0], 0xFE);
    ASSERT_TRUE(pkg::decode(buf, written, negative, err));
    EXPECT_EQ(negative, -2);

    double d = 0;
    ASSERT_EQ(pkg::encode(-1.5, buf, sizeof buf, written), pkg::EncodeError::none);
    EXPECT_EQ(buf[pkg::kBigEndian ? 0 : 7], 0xBF); // sign and exponent byte of -1.5
    ASSERT_TRUE(pkg::decode(buf, written, d, err));
    EXPECT_EQ(d, -1.5);
}

TEST(Wire, WriterReportsAFullBuffer) {
    std::uint8_t buf[3] = {};
    std::size_t written = 99;
    EXPECT_NE(pkg::encode(std::uint32_t{1}, buf, sizeof buf, written), pkg::EncodeError::none);
    EXPECT_EQ(written, 0u);
}

} // namespace
