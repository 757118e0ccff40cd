// The JSON line codec (json_codec.c) over the rendered test protocol (tests/runtime_specs/: command
// set 0x01 with ping 0x01 and rate 0x04, {"hz": u16} on device alpha, {"hz": u32} on beta): decoded
// fields, per-device variants, decode errors as raw fields, and JSON lines back to the same bytes.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "test_support.hpp"

using namespace test_support;

namespace {

std::string line_of(const std::vector<uint8_t> &pkt, codec_device_t device = CODEC_DEVICE_ANY) {
    return decode_text(pkt, 0, device);
}

// The bytes of a value in the protocol's byte order.
std::vector<uint8_t> wire(uint64_t v, size_t n) {
    std::vector<uint8_t> out(n);
    for (size_t i = 0; i < n; i++) {
        out[i] = static_cast<uint8_t>(v >> (8 * (CODEC_LITTLE_ENDIAN ? i : n - 1 - i)));
    }
    return out;
}

} // namespace

TEST(JsonCodec, DecodedFieldsAndDeviceVariantsRoundTrip) {
    const std::vector<uint8_t> ping = packet(0x01, {{0x01, {}}});
    const std::vector<uint8_t> alpha = packet(0x01, {{0x04, wire(500, 2)}});
    const std::vector<uint8_t> beta = packet(0x01, {{0x04, wire(70000, 4)}});
    EXPECT_EQ(line_of(ping),
              "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}\n");
    EXPECT_EQ(line_of(alpha),
              "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":4,\"name\":\"rate\",\"device\":"
              "\"alpha\",\"values\":{\"hz\":500}}]}\n");
    // the first variant that decodes wins; a device chooses its own variant
    EXPECT_EQ(line_of(beta),
              "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":4,\"name\":\"rate\",\"device\":"
              "\"beta\",\"values\":{\"hz\":70000}}]}\n");
    EXPECT_NE(line_of(alpha, CODEC_DEVICE_BETA).find("\"error\":\"hz: needs 4 bytes at offset 0, 2 left\""),
              std::string::npos);
    for (const auto &pkt : {ping, alpha, beta}) {
        std::vector<uint8_t> back;
        std::string error;
        ASSERT_TRUE(encode_text(line_of(pkt), &back, &error)) << error;
        EXPECT_EQ(back, pkt);
    }
}

TEST(JsonCodec, UndecodableDataIsARawFieldWithTheFirstVariantsError) {
    const std::vector<uint8_t> pkt = packet(0x01, {{0x04, {1, 2, 3}}});
    EXPECT_EQ(line_of(pkt),
              "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":4,\"data\":\"010203\",\"error\":"
              "\"1 unexpected bytes at offset 2\"}]}\n");
    std::vector<uint8_t> back;
    std::string error;
    ASSERT_TRUE(encode_text(line_of(pkt), &back, &error)) << error;
    EXPECT_EQ(back, pkt);
}

TEST(JsonCodec, EncodeErrorsNameTheProblem) {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":4,\"name\":\"rate\",\"values\":{\"hz\":1}}]}",
         "\"device\" is required"},
        {"{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":4,\"name\":\"rate\",\"device\":\"gamma\","
         "\"values\":{\"hz\":1}}]}",
         "not a device with a variant of \"rate\""},
        {"{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"pong\",\"values\":{}}]}",
         "descriptor 1 in set 1 is \"ping\""},
        {"{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":4,\"name\":\"rate\",\"device\":\"alpha\","
         "\"values\":{\"hz\":70000}}]}",
         "hz"},
    };
    for (const auto &c : cases) {
        std::vector<uint8_t> back;
        std::string error;
        EXPECT_FALSE(encode_text(c.first, &back, &error)) << c.first;
        EXPECT_NE(error.find(c.second), std::string::npos) << error;
    }
}
