// Runtime tests of dispatch.hpp and json_lines.hpp on the test protocol rendered from
// tests/runtime_specs/ (sensor reading: u16 count, s8 offset, bool valid; control rate per device,
// a u16 on alpha, a u32 on beta): the canonical line of each kind of field, per-device variants,
// and the errors of encode_json_line.
#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "protopkg/protopkg.hpp"
#include "test_support.hpp"

namespace {

namespace pkg = ::protopkg;
using Bytes = std::vector<std::uint8_t>;

Bytes one_packet(pkg::PacketBuilder &b) {
    const pkg::PacketView p = b.finish();
    return Bytes(p.data, p.data + p.size);
}

std::string hex(const std::uint8_t *data, std::size_t n) {
    static const char digits[] = "0123456789abcdef";
    std::string out;
    for (std::size_t i = 0; i < n; ++i) {
        out += digits[data[i] >> 4];
        out += digits[data[i] & 0x0F];
    }
    return out;
}

// Issue 28: a typed field of another descriptor set would be another command on the wire.
TEST(Builder, TypedAddRefusesALayoutOfAnotherSet) {
    pkg::PacketBuilder other(0x0C);
    EXPECT_EQ(other.add(pkg::control::Ping{}), pkg::EncodeError::wrong_set);
    EXPECT_EQ(other.error(), pkg::EncodeError::wrong_set);
    EXPECT_EQ(other.payload_size(), 0u);
    EXPECT_STREQ(pkg::to_string(other.error()), "the field belongs to another descriptor set");
    pkg::PacketBuilder same(pkg::control::Ping::kSet);
    EXPECT_EQ(same.add(pkg::control::Ping{}), pkg::EncodeError::none);
    EXPECT_GT(same.payload_size(), 0u);
}

std::string line_of(const Bytes &bytes, const char *device = nullptr) {
    const std::vector<std::string> lines = protopkg_test::decode_lines(bytes, bytes.size(), device);
    return lines.size() == 1 ? lines[0] : "(" + std::to_string(lines.size()) + " lines)";
}

std::string encode_error(const std::string &line) {
    Bytes out;
    std::string error;
    EXPECT_FALSE(pkg::encode_json_line(line, out, error)) << line;
    EXPECT_TRUE(out.empty());
    return error;
}

TEST(JsonLines, DecodedRawAndTrailingFields) {
    pkg::PacketBuilder b(pkg::sensor::Reading::kSet);
    pkg::sensor::Reading reading;
    reading.count = 0x1234;
    reading.offset = 7;
    reading.valid = true;
    ASSERT_EQ(b.add(reading), pkg::EncodeError::none);
    const std::uint8_t junk[] = {0xAB};
    ASSERT_EQ(b.add_raw_field(0x7F, junk, 1), pkg::EncodeError::none); // unknown descriptor
    const std::uint8_t bad_bool[] = {0, 0, 0, 2};
    ASSERT_EQ(b.add_raw_field(0x01, bad_bool, 4), pkg::EncodeError::none); // reading: valid not a bool
    const std::uint8_t trailing[] = {0x09};
    ASSERT_EQ(b.append(trailing, 1), pkg::EncodeError::none);
    const Bytes bytes = one_packet(b);
    const std::size_t at = 3 * pkg::kFieldHeaderSize + 4 + 1 + 4; // where the trailing byte is
    EXPECT_EQ(
        line_of(bytes),
        "{\"offset\":0,\"set\":128,\"fields\":["
        "{\"descriptor\":1,\"name\":\"reading\",\"values\":{\"count\":4660,\"offset\":7,\"valid\":true}},"
        "{\"descriptor\":127,\"data\":\"ab\",\"error\":\"unknown descriptor\"},"
        "{\"descriptor\":1,\"data\":\"00000002\",\"error\":\"valid: invalid bool value 2 at offset 3\"},"
        "{\"trailing\":\"09\",\"error\":\"field header at payload offset " +
            std::to_string(at) + " needs 2 bytes, 1 left\"}]}");
    EXPECT_EQ(protopkg_test::encode_lines({line_of(bytes)}), bytes);
}

TEST(JsonLines, PerDeviceLayouts) {
    pkg::PacketBuilder b(0x01);
    pkg::control::RateBeta rate;
    rate.hz = 70000;
    ASSERT_EQ(b.add(rate), pkg::EncodeError::none);
    const Bytes bytes = one_packet(b);
    // The first layout that decodes the data wins (alpha needs 2 bytes: beta's 4 bytes are too
    // many), unless a device is chosen.
    const std::string beta =
        "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":4,\"name\":\"rate\",\"device\":\"beta\","
        "\"values\":{\"hz\":70000}}]}";
    EXPECT_EQ(line_of(bytes), beta);
    EXPECT_EQ(line_of(bytes, "beta"), beta);
    EXPECT_EQ(line_of(bytes, "alpha"), "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":4,\"data\":\"" +
                                           hex(bytes.data() + pkg::kHeaderSize + pkg::kFieldHeaderSize, 4) +
                                           "\",\"error\":\"2 unexpected bytes at offset 2\"}]}");
    EXPECT_EQ(protopkg_test::encode_lines({beta}), bytes);
}

TEST(JsonLines, SkipRunsAndUnknownSets) {
    const Bytes garbage = {0x00, 0x01};
    pkg::PacketBuilder b(0x40);
    const Bytes bytes = [&] {
        Bytes out = garbage;
        const Bytes p = one_packet(b);
        out.insert(out.end(), p.begin(), p.end());
        return out;
    }();
    const std::vector<std::string> lines = protopkg_test::decode_lines(bytes, 1, nullptr);
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[0], "{\"offset\":0,\"skipped\":\"0001\"}");
    EXPECT_EQ(lines[1], "{\"offset\":2,\"set\":64,\"fields\":[]}");
    EXPECT_EQ(protopkg_test::encode_lines(lines), bytes);
}

// The decode tool's streaming decoder: the same lines as the whole-input decode, whatever the
// chunks, and it keeps no more than the undecided bytes (its lines carry skip runs that span
// many chunks).
TEST(JsonLines, StreamingDecoderMatchesWholeDecode) {
    Bytes bytes;
    for (int k = 0; k < 40; ++k) {
        const Bytes junk(static_cast<std::size_t>(k * 7 % 23), static_cast<std::uint8_t>(k));
        bytes.insert(bytes.end(), junk.begin(), junk.end());
        pkg::PacketBuilder b(0x40);
        const Bytes p = one_packet(b);
        bytes.insert(bytes.end(), p.begin(), p.end());
    }
    bytes.push_back(bytes.front() == 0 ? 0x11 : 0x00);
    std::vector<std::string> whole;
    pkg::decode_to_json_lines(bytes.data(), bytes.size(), bytes.size(), std::nullopt,
                              [&](const std::string &line) { whole.push_back(line); });
    ASSERT_GT(whole.size(), 40u);
    for (const std::size_t chunk : {std::size_t{1}, std::size_t{3}, std::size_t{64}, bytes.size()}) {
        std::vector<std::string> streamed;
        pkg::JsonLinesDecoder decoder(std::nullopt);
        const auto on_line = [&](const std::string &line) { streamed.push_back(line); };
        for (std::size_t pos = 0; pos < bytes.size(); pos += chunk) {
            decoder.feed(bytes.data() + pos, std::min(chunk, bytes.size() - pos), on_line);
        }
        decoder.finish(on_line);
        EXPECT_EQ(streamed, whole) << "chunk " << chunk;
    }
}

TEST(JsonLines, EncodeErrors) {
    EXPECT_EQ(encode_error("[]"), "expected a JSON object");
    EXPECT_EQ(encode_error("{\"offset\":0}"), "expected a packet (set, fields) or a skip run (skipped)");
    EXPECT_EQ(encode_error("{\"offset\":0,\"set\":256,\"fields\":[]}"), "set: expected an integer in 0..255");
    EXPECT_EQ(encode_error("{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":1,\"name\":\"reading\","
                           "\"values\":{\"count\":70000,\"offset\":0,\"valid\":false}}]}")
                  .rfind("fields[0].values.count: ", 0),
              0u);
    EXPECT_EQ(encode_error("{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":4,\"name\":\"rate\","
                           "\"values\":{\"hz\":1}}]}"),
              "fields[0].device: field 'rate' has per-device layouts; name the device");
    EXPECT_EQ(encode_error("{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"pong\","
                           "\"values\":{}}]}"),
              "fields[0].name: descriptor 1 is 'ping', not 'pong'");
    EXPECT_EQ(encode_error(
                  "{\"offset\":0,\"set\":2,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}"),
              "fields[0].descriptor: set 2 is unknown; write the field as raw data");
}

} // namespace
