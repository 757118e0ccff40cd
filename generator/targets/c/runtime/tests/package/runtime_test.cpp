// Tests of the runtime's JSON line codec (json_codec.c) through the protocol's dispatch: skip
// lines, raw fields for unknown sets and descriptors, JSON line errors, raw and trailing entries.
// They hold for any protocol: copied into every package (tests/runtime_test.cpp) and run in place
// against the test protocol of generator/targets/c/runtime/tests/stubs/. The rest of the runtime
// is tested in place only (generator/targets/c/runtime/tests/runtime_test.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "test_support.hpp"

using namespace test_support;

namespace {

// A set and descriptor that designate no field (for raw-field tests).
bool unknown_field(uint8_t *set, uint8_t *descriptor, codec_status_t want) {
    for (unsigned s = 0; s < 256; s++) {
        for (unsigned d = 0; d < 256; d++) {
            codec_status_t why = CODEC_OK;
            if (!codec_find_field(static_cast<uint8_t>(s), static_cast<uint8_t>(d), &why) && why == want) {
                *set = static_cast<uint8_t>(s);
                *descriptor = static_cast<uint8_t>(d);
                return true;
            }
        }
    }
    return false;
}

} // namespace

TEST(Parser, JsonLinesAreIndependentOfChunking) {
    uint8_t g = garbage_byte();
    std::vector<uint8_t> stream = {g, g};
    for (const auto &p : {packet(0x01, {{0x01, {}}}), packet(0x02, {{0x05, {9, 8, 7, 6}}})}) {
        stream.insert(stream.end(), p.begin(), p.end());
        stream.push_back(g);
    }
    std::string whole = decode_text(stream, 0);
    EXPECT_EQ(std::count(whole.begin(), whole.end(), '\n'), 5);
    for (size_t chunk = 1; chunk <= stream.size(); chunk++) {
        EXPECT_EQ(decode_text(stream, chunk), whole) << "chunk size " << chunk;
    }
}

TEST(Parser, SkipLineCarriesTheSkippedBytes) {
    std::vector<uint8_t> stream = {garbage_byte(), 0x22, 0xAB};
    char line[128];
    codec_json_skip_line(0, stream.data(), stream.size(), line, sizeof line);
    EXPECT_EQ(std::string(line), "{\"offset\":0,\"skipped\":\"" + to_hex(stream) + "\"}");
    EXPECT_EQ(decode_text(stream, 0), std::string(line) + "\n");
}
TEST(Dispatch, UnknownSetAndDescriptorBecomeRawFields) {
    uint8_t set = 0;
    uint8_t descriptor = 0;
    if (unknown_field(&set, &descriptor, CODEC_ERR_UNKNOWN_SET)) {
        std::vector<uint8_t> pkt = packet(set, {{descriptor, {0x3e, 0x7a}}});
        EXPECT_EQ(decode_text(pkt, 0), "{\"offset\":0,\"set\":" + std::to_string(set) +
                                           ",\"fields\":[{\"descriptor\":" + std::to_string(descriptor) +
                                           ",\"data\":\"3e7a\",\"error\":\"unknown descriptor set\"}]}\n");
    }
    if (unknown_field(&set, &descriptor, CODEC_ERR_UNKNOWN_DESCRIPTOR)) {
        std::vector<uint8_t> pkt = packet(set, {{descriptor, {}}});
        std::string text = decode_text(pkt, 0);
        EXPECT_EQ(text, "{\"offset\":0,\"set\":" + std::to_string(set) +
                            ",\"fields\":[{\"descriptor\":" + std::to_string(descriptor) +
                            ",\"data\":\"\",\"error\":\"unknown descriptor\"}]}\n");
        std::vector<uint8_t> back;
        std::string error;
        ASSERT_TRUE(encode_text(text, &back, &error)) << error;
        EXPECT_EQ(back, pkt);
    }
}
TEST(Json, EncodeLineErrors) {
    uint8_t out[CODEC_MAX_PACKET];
    char msg[512];
    size_t n = 0;
    const char *bad[] = {
        "",
        "[1]",
        "{\"offset\":0,\"skipped\":\"abc\"}",
        "{\"offset\":0,\"skipped\":\"zz\"}",
        "{\"offset\":0,\"set\":1}",
        "{\"offset\":0,\"set\":256,\"fields\":[]}",
        "{\"offset\":0,\"set\":1,\"fields\":[{\"trailing\":\"01\",\"oops\":1}]}",
        "{\"offset\":0,\"set\":1,\"fields\":[]} x",
        "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"data\":\"01\",\"error\":\"x\"},]}",
    };
    for (const char *line : bad) {
        EXPECT_EQ(codec_json_encode_line(line, std::strlen(line), out, sizeof out, &n, msg, sizeof msg),
                  CODEC_ERR_JSON)
            << line;
        EXPECT_NE(msg[0], '\0') << line;
    }
    const char *skip = " {\"skipped\":\"A5ff75\", \"offset\": 12} ";
    ASSERT_EQ(codec_json_encode_line(skip, std::strlen(skip), out, sizeof out, &n, msg, sizeof msg), CODEC_OK)
        << msg;
    ASSERT_EQ(n, 3u);
    EXPECT_EQ(out[0], 0xA5);
    EXPECT_EQ(out[2], 0x75);
    EXPECT_EQ(codec_json_encode_line(skip, std::strlen(skip), out, 2, &n, msg, sizeof msg), CODEC_ERR_JSON);
}

TEST(Json, RawAndTrailingEntriesRoundTrip) {
    const char *line =
        "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":200,\"data\":\"0102\",\"error\":\"e\"},"
        "{\"trailing\":\"09\",\"error\":\"e\"}]}";
    uint8_t out[CODEC_MAX_PACKET];
    char msg[512];
    size_t n = 0;
    ASSERT_EQ(codec_json_encode_line(line, std::strlen(line), out, sizeof out, &n, msg, sizeof msg), CODEC_OK)
        << msg;
    ASSERT_EQ(n, CODEC_HEADER_SIZE + CODEC_FIELD_HEADER_SIZE + 2u + 1u + CODEC_CHECKSUM_SIZE);
    EXPECT_TRUE(codec_packet_valid(out, n));
    const uint8_t *payload = codec_packet_payload(out);
    EXPECT_EQ(payload[CODEC_FIELD_DESCRIPTOR_OFFSET], 200);
    EXPECT_EQ(payload[CODEC_FIELD_LENGTH_OFFSET], 2 + CODEC_FIELD_LENGTH_ADJUST);
    EXPECT_EQ(payload[CODEC_FIELD_HEADER_SIZE + 2], 0x09);
}
