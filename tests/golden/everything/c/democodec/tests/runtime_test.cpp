// Hand-written tests of the runtime: checksum, builder, stream parser (chunking, garbage,
// resynchronisation, end of stream), field iterator, canonical JSON, JSON reader.
// Generated: do not edit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "test_support.hpp"

using namespace test_support;

namespace {

std::string format_double(double v) {
    char buf[DEMO_JSON_NUMBER_MAX];
    size_t n = demo_json_format_double(v, buf, sizeof buf);
    return std::string(buf, n);
}

std::string format_float_bits(uint32_t bits) {
    float f;
    std::memcpy(&f, &bits, sizeof f);
    char buf[DEMO_JSON_NUMBER_MAX];
    size_t n = demo_json_format_float(f, buf, sizeof buf);
    return std::string(buf, n);
}

std::string format_double_bits(uint64_t bits) {
    double d;
    std::memcpy(&d, &bits, sizeof d);
    return format_double(d);
}

// A set and descriptor that designate no field (for raw-field tests).
bool unknown_field(uint8_t *set, uint8_t *descriptor, demo_status_t want) {
    for (unsigned s = 0; s < 256; s++) {
        for (unsigned d = 0; d < 256; d++) {
            demo_status_t why = DEMO_OK;
            if (!demo_find_field(static_cast<uint8_t>(s), static_cast<uint8_t>(d), &why) && why == want) {
                *set = static_cast<uint8_t>(s);
                *descriptor = static_cast<uint8_t>(d);
                return true;
            }
        }
    }
    return false;
}

std::vector<uint8_t> concat(std::initializer_list<std::vector<uint8_t>> parts) {
    std::vector<uint8_t> out;
    for (const auto &p : parts) {
        out.insert(out.end(), p.begin(), p.end());
    }
    return out;
}

} // namespace

TEST(Checksum, Fletcher16) {
    const uint8_t bytes[] = {0x75, 0x65, 0x01, 0x02, 0x02, 0x01};
    uint8_t ck[DEMO_CHECKSUM_SIZE];
    demo_checksum(bytes, sizeof bytes, ck);
    // sum1 = 0xE0, sum2 = 0xC6, sent in the order sum1, sum2
    EXPECT_EQ(ck[0], 0xE0);
    EXPECT_EQ(ck[1], 0xC6);
    demo_checksum(bytes, 0, ck);
    EXPECT_EQ(ck[0], 0);
    EXPECT_EQ(ck[1], 0);
    // the same as a number (first wire byte high) and as a check of the two bytes that follow
    EXPECT_EQ(demo_checksum_word(bytes, sizeof bytes), 0xE0C6);
    uint8_t packet[sizeof bytes + DEMO_CHECKSUM_SIZE];
    memcpy(packet, bytes, sizeof bytes);
    packet[sizeof bytes + 0] = 0xE0;
    packet[sizeof bytes + 1] = 0xC6;
    EXPECT_TRUE(demo_checksum_matches(packet, sizeof bytes));
    for (size_t i = 0; i < DEMO_CHECKSUM_SIZE; i++) {
        packet[sizeof bytes + i] ^= 0x01;
        EXPECT_FALSE(demo_checksum_matches(packet, sizeof bytes)) << "checksum byte " << i << " changed";
        packet[sizeof bytes + i] ^= 0x01;
    }
}

// The checksum works eight bytes a step in runs of at most 128 words; it must equal the
// byte-serial definition (sum1 += b, sum2 += sum1, modulo 256) for every length and alignment,
// across run boundaries (1024 bytes) and with all bytes 0xFF (the largest lane sums).
static void expect_byte_serial(const uint8_t *bytes, size_t len, const char *what) {
    unsigned sum1 = 0, sum2 = 0;
    for (size_t i = 0; i < len; i++) {
        sum1 = (sum1 + bytes[i]) & 0xFFu;
        sum2 = (sum2 + sum1) & 0xFFu;
    }
    uint8_t ck[DEMO_CHECKSUM_SIZE];
    demo_checksum(bytes, len, ck);
    ASSERT_EQ(ck[0], sum1) << what << ", length " << len;
    ASSERT_EQ(ck[1], sum2) << what << ", length " << len;
}

TEST(Checksum, WideStepsMatchTheByteSerialDefinition) {
    static uint8_t bytes[2100 + 7];
    static uint8_t all_ff[2100];
    uint32_t state = 12345;
    for (uint8_t &b : bytes) {
        state = state * 1103515245u + 12345u;
        b = (uint8_t)(state >> 16);
    }
    memset(all_ff, 0xFF, sizeof all_ff);
    for (size_t start = 0; start < 8; start++) {
        for (size_t len = 0; len <= 300; len++) {
            expect_byte_serial(bytes + start, len, start % 2 ? "random bytes, odd start" : "random bytes");
        }
    }
    const size_t long_lengths[] = {1016, 1023, 1024, 1025, 1031, 1032, 1040, 2047, 2048, 2049, 2100};
    for (size_t len : long_lengths) {
        expect_byte_serial(bytes + 3, len, "random bytes");
        expect_byte_serial(all_ff, len, "all 0xFF");
    }
    // 261 bytes of 0xFF (-1 modulo 256): sum1 = -261 = 0xFB, sum2 = -(1 + .. + 261) = -34191 = 0x71
    uint8_t ones[261];
    memset(ones, 0xFF, sizeof ones);
    uint8_t ck[DEMO_CHECKSUM_SIZE];
    demo_checksum(ones, sizeof ones, ck);
    EXPECT_EQ(ck[0], 0xFB);
    EXPECT_EQ(ck[1], 0x71);
}

TEST(Builder, BuildsAValidPacket) {
    std::vector<uint8_t> pkt = packet(0x01, {{0x10, {1, 2, 3}}, {0x11, {}}});
    ASSERT_EQ(pkt.size(), DEMO_HEADER_SIZE + 2u * DEMO_FIELD_HEADER_SIZE + 3u + DEMO_CHECKSUM_SIZE);
    EXPECT_TRUE(demo_packet_valid(pkt.data(), pkt.size()));
    EXPECT_EQ(demo_packet_set(pkt.data()), 0x01);
    EXPECT_EQ(demo_packet_payload_length(pkt.data()), 2u * DEMO_FIELD_HEADER_SIZE + 3u);
    const uint8_t *payload = demo_packet_payload(pkt.data());
    EXPECT_EQ(payload[DEMO_FIELD_LENGTH_OFFSET], 3 + DEMO_FIELD_LENGTH_ADJUST);
    EXPECT_EQ(payload[DEMO_FIELD_DESCRIPTOR_OFFSET], 0x10);
    pkt[pkt.size() - 1] ^= 1;
    EXPECT_FALSE(demo_packet_valid(pkt.data(), pkt.size()));
}

TEST(Builder, RejectsOverlongPayloadAndSmallBuffer) {
    std::vector<uint8_t> buf(DEMO_MAX_PACKET + 10);
    std::vector<uint8_t> data(DEMO_MAX_FIELD_DATA);
    demo_packet_builder_t b;
    demo_packet_begin(&b, buf.data(), buf.size(), 1);
    EXPECT_EQ(demo_packet_add_field(&b, 1, data.data(), data.size()), DEMO_OK);
    EXPECT_EQ(demo_packet_add_field(&b, 2, data.data(), 1), DEMO_ERR_TOO_LONG);
    size_t n = 0;
    EXPECT_EQ(demo_packet_finish(&b, &n), DEMO_ERR_TOO_LONG);
    demo_packet_begin(&b, buf.data(), DEMO_HEADER_SIZE + 3, 1);
    EXPECT_EQ(demo_packet_add_field(&b, 1, data.data(), 4), DEMO_ERR_BUFFER);
    demo_packet_begin(&b, buf.data(), buf.size(), 1);
    EXPECT_EQ(demo_packet_add_field(&b, 1, data.data(), DEMO_MAX_FIELD_DATA + 1), DEMO_ERR_TOO_LONG);
}

TEST(Parser, GarbageBeforeBetweenAndAfterIsIndependentOfChunking) {
    uint8_t g = garbage_byte();
    std::vector<uint8_t> p1 = packet(0x01, {{0x01, {}}});
    std::vector<uint8_t> p2 = packet(0x02, {{0x05, {9, 8, 7, 6}}});
    std::vector<uint8_t> stream = concat(
        {std::vector<uint8_t>{g, g}, p1, std::vector<uint8_t>{g, g, g, g}, p2, std::vector<uint8_t>{g}});
    Collector whole = decode(stream, 0);
    std::vector<Event> want = {
        {DEMO_EVENT_SKIP, 0, 2},
        {DEMO_EVENT_PACKET, 2, p1.size()},
        {DEMO_EVENT_SKIP, 2 + p1.size(), 4},
        {DEMO_EVENT_PACKET, 6 + p1.size(), p2.size()},
        {DEMO_EVENT_SKIP, 6 + p1.size() + p2.size(), 1},
    };
    EXPECT_EQ(whole.events, want);
    for (size_t chunk = 1; chunk <= stream.size(); chunk++) {
        Collector c = decode(stream, chunk);
        EXPECT_EQ(c.events, want) << "chunk size " << chunk;
        EXPECT_EQ(c.text, whole.text) << "chunk size " << chunk;
    }
}

TEST(Parser, BadChecksumResynchronisesInsideTheFalsePacket) {
    // A header whose length covers a valid packet: the checksum fails, the parser skips one
    // byte at a time and finds the packet inside.
    std::vector<uint8_t> inner = packet(0x01, {{0x01, {}}});
    std::vector<uint8_t> stream(demo_sync, demo_sync + DEMO_SYNC_SIZE);
    stream.resize(DEMO_HEADER_SIZE);
    stream[DEMO_SET_OFFSET] = 0x01;
    stream[DEMO_LENGTH_OFFSET] = static_cast<uint8_t>(inner.size());
    stream.insert(stream.end(), inner.begin(), inner.end());
    stream.push_back(0x00);
    stream.push_back(0x00);
    std::vector<Event> want = {
        {DEMO_EVENT_SKIP, 0, DEMO_HEADER_SIZE},
        {DEMO_EVENT_PACKET, DEMO_HEADER_SIZE, inner.size()},
        {DEMO_EVENT_SKIP, DEMO_HEADER_SIZE + inner.size(), 2},
    };
    for (size_t chunk = 0; chunk <= stream.size(); chunk++) {
        EXPECT_EQ(decode(stream, chunk).events, want) << "chunk size " << chunk;
    }
}

TEST(Parser, BadChecksumFollowedByGarbageIsOneSkipRun) {
    uint8_t g = garbage_byte();
    std::vector<uint8_t> bad = packet(0x01, {{0x01, {}}});
    bad[bad.size() - 1] ^= 0xFF;
    std::vector<uint8_t> good = packet(0x01, {{0x02, {}}});
    std::vector<uint8_t> stream = concat({bad, std::vector<uint8_t>{g, g, g}, good});
    std::vector<Event> want = {
        {DEMO_EVENT_SKIP, 0, bad.size() + 3},
        {DEMO_EVENT_PACKET, bad.size() + 3, good.size()},
    };
    EXPECT_EQ(decode(stream, 0).events, want);
    EXPECT_EQ(decode(stream, 1).events, want);
}

TEST(Parser, TruncatedPacketAtEndOfStreamIsSkipped) {
    std::vector<uint8_t> good = packet(0x01, {{0x01, {}}});
    std::vector<uint8_t> cut = packet(0x01, {{0x03, {1, 2, 3, 4}}});
    cut.pop_back();
    std::vector<uint8_t> stream = concat({good, cut});
    std::vector<Event> want = {
        {DEMO_EVENT_PACKET, 0, good.size()},
        {DEMO_EVENT_SKIP, good.size(), cut.size()},
    };
    EXPECT_EQ(decode(stream, 0).events, want);
    EXPECT_EQ(decode(stream, 1).events, want);
    // A partial sync sequence at the very end waits, then is skipped at flush.
    std::vector<uint8_t> tail = concat({good, std::vector<uint8_t>{demo_sync[0]}});
    std::vector<Event> want_tail = {
        {DEMO_EVENT_PACKET, 0, good.size()},
        {DEMO_EVENT_SKIP, good.size(), 1},
    };
    EXPECT_EQ(decode(tail, 1).events, want_tail);
}

TEST(Parser, SkipLineCarriesTheSkippedBytes) {
    std::vector<uint8_t> stream = {garbage_byte(), 0x22, 0xAB};
    char line[128];
    demo_json_skip_line(0, stream.data(), stream.size(), line, sizeof line);
    EXPECT_EQ(std::string(line), "{\"offset\":0,\"skipped\":\"" + to_hex(stream) + "\"}");
    EXPECT_EQ(decode_text(stream, 0), std::string(line) + "\n");
}

TEST(FieldIterator, TrailingEntries) {
    char msg[256];
    demo_field_iter_t it;
    demo_field_entry_t e;
    // one byte left: no room for a field header
    const uint8_t one[] = {0x07};
    demo_field_iter_init(&it, 0x01, one, sizeof one);
    ASSERT_TRUE(demo_field_iter_next(&it, &e));
    EXPECT_EQ(e.kind, DEMO_ENTRY_TRAILING);
    demo_trailing_format(&e, msg, sizeof msg);
    EXPECT_STREQ(msg, "field header at payload offset 0 needs 2 bytes, 1 left");
    EXPECT_FALSE(demo_field_iter_next(&it, &e));
    // a field, then one that runs past the payload
    uint8_t two[6] = {0};
    two[DEMO_FIELD_LENGTH_OFFSET] = DEMO_FIELD_LENGTH_ADJUST;
    two[DEMO_FIELD_DESCRIPTOR_OFFSET] = 0x01;
    two[2 + DEMO_FIELD_LENGTH_OFFSET] = 5 + DEMO_FIELD_LENGTH_ADJUST;
    two[2 + DEMO_FIELD_DESCRIPTOR_OFFSET] = 0x02;
    demo_field_iter_init(&it, 0x01, two, sizeof two);
    ASSERT_TRUE(demo_field_iter_next(&it, &e));
    EXPECT_EQ(e.kind, DEMO_ENTRY_FIELD);
    EXPECT_EQ(e.descriptor, 0x01);
    EXPECT_EQ(e.length, 0u);
    ASSERT_TRUE(demo_field_iter_next(&it, &e));
    EXPECT_EQ(e.kind, DEMO_ENTRY_TRAILING);
    EXPECT_EQ(e.length, 4u);
    demo_trailing_format(&e, msg, sizeof msg);
    EXPECT_EQ(std::string(msg), "field length " + std::to_string(5 + DEMO_FIELD_LENGTH_ADJUST) +
                                    " at payload offset 2 overruns the payload (4 bytes left)");
}

TEST(Dispatch, UnknownSetAndDescriptorBecomeRawFields) {
    uint8_t set = 0;
    uint8_t descriptor = 0;
    if (unknown_field(&set, &descriptor, DEMO_ERR_UNKNOWN_SET)) {
        std::vector<uint8_t> pkt = packet(set, {{descriptor, {0x3e, 0x7a}}});
        EXPECT_EQ(decode_text(pkt, 0), "{\"offset\":0,\"set\":" + std::to_string(set) +
                                           ",\"fields\":[{\"descriptor\":" + std::to_string(descriptor) +
                                           ",\"data\":\"3e7a\",\"error\":\"unknown descriptor set\"}]}\n");
    }
    if (unknown_field(&set, &descriptor, DEMO_ERR_UNKNOWN_DESCRIPTOR)) {
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

TEST(DecodeError, Messages) {
    demo_decode_error_t e;
    char msg[DEMO_ERROR_MESSAGE_MAX];
    std::memset(&e, 0, sizeof e);
    e.kind = DEMO_DECODE_NEEDS_BYTES;
    e.depth = 1;
    e.path[0].name = "descriptors";
    e.path[0].index = 5;
    e.need = 2;
    e.offset = 10;
    e.have = 1;
    demo_decode_error_format(&e, msg, sizeof msg);
    EXPECT_STREQ(msg, "descriptors[5]: needs 2 bytes at offset 10, 1 left");
    e.depth = 2;
    e.path[0].name = "entries";
    e.path[0].index = 2;
    e.path[1].name = "rate";
    e.path[1].index = SIZE_MAX;
    e.need = 4;
    demo_decode_error_format(&e, msg, sizeof msg);
    EXPECT_STREQ(msg, "entries[2].rate: needs 4 bytes at offset 10, 1 left");
    e.depth = 1;
    e.path[0].name = "info";
    e.path[0].index = SIZE_MAX;
    e.kind = DEMO_DECODE_COUNT;
    e.path[0].name = "items";
    e.path[0].index = SIZE_MAX;
    e.count = 300;
    e.max = 126;
    demo_decode_error_format(&e, msg, sizeof msg);
    EXPECT_STREQ(msg, "items: count 300 exceeds maximum 126");
    e.kind = DEMO_DECODE_REMAINING;
    e.have = 3;
    e.offset = 4;
    e.need = 2;
    demo_decode_error_format(&e, msg, sizeof msg);
    EXPECT_STREQ(msg, "items: 3 bytes left at offset 4, not a multiple of 2");
    e.kind = DEMO_DECODE_BOOL;
    e.value = 7;
    demo_decode_error_format(&e, msg, sizeof msg);
    EXPECT_STREQ(msg, "items: invalid bool value 7 at offset 4");
    e.kind = DEMO_DECODE_SELECTOR;
    e.value = static_cast<uint64_t>(-3);
    e.value_signed = true;
    demo_decode_error_format(&e, msg, sizeof msg);
    EXPECT_STREQ(msg, "items: no member for selector value -3");
    e.kind = DEMO_DECODE_UNEXPECTED;
    e.have = 2;
    e.offset = 6;
    demo_decode_error_format(&e, msg, sizeof msg);
    EXPECT_STREQ(msg, "2 unexpected bytes at offset 6");
    char small[8];
    size_t n = demo_decode_error_format(&e, small, sizeof small);
    EXPECT_EQ(n, std::strlen("2 unexpected bytes at offset 6"));
    EXPECT_STREQ(small, "2 unexp");
}

TEST(Json, Numbers) {
    EXPECT_EQ(format_double(1.0), "1.0");
    EXPECT_EQ(format_double(0.0), "0.0");
    EXPECT_EQ(format_double(-0.0), "-0.0");
    EXPECT_EQ(format_double(0.0001), "0.0001");
    EXPECT_EQ(format_double(1e-05), "1e-05");
    EXPECT_EQ(format_double(123.456), "123.456");
    EXPECT_EQ(format_double(-2.5), "-2.5");
    EXPECT_EQ(format_double(1e16), "1e+16");
    EXPECT_EQ(format_double(1.5e16), "1.5e+16");
    EXPECT_EQ(format_double(1e15), "1000000000000000.0");
    EXPECT_EQ(format_double(9007199254740992.0), "9007199254740992.0");
    EXPECT_EQ(format_double(123456789012345678.0), "1.2345678901234568e+17");
    EXPECT_EQ(format_double(2.5e-310), "2.5e-310");
    EXPECT_EQ(format_double(5e-324), "5e-324");
    EXPECT_EQ(format_double(1e22), "1e+22");
    EXPECT_EQ(format_double(1e100), "1e+100");
    EXPECT_EQ(format_double(0.1), "0.1");
    EXPECT_EQ(format_double(1.0 / 3.0), "0.3333333333333333");
    EXPECT_EQ(format_double(std::numeric_limits<double>::max()), "1.7976931348623157e+308");
    EXPECT_EQ(format_double(std::numeric_limits<double>::min()), "2.2250738585072014e-308");
    EXPECT_EQ(format_double(std::numeric_limits<double>::infinity()), "\"inf\"");
    EXPECT_EQ(format_double(-std::numeric_limits<double>::infinity()), "\"-inf\"");
    EXPECT_EQ(format_double_bits(0x7FF8000000000000ull), "\"nan\"");
    EXPECT_EQ(format_double_bits(0xFFF8000000000000ull), "\"nan:0xfff8000000000000\"");
    EXPECT_EQ(format_double_bits(0x7FF0000000000001ull), "\"nan:0x7ff0000000000001\"");
    // floats are widened to double exactly
    EXPECT_EQ(format_float_bits(0x3DCCCCCDu), "0.10000000149011612");
    EXPECT_EQ(format_float_bits(0x3F800000u), "1.0");
    EXPECT_EQ(format_float_bits(0x80000000u), "-0.0");
    EXPECT_EQ(format_float_bits(0x7F800000u), "\"inf\"");
    EXPECT_EQ(format_float_bits(0x7FC00000u), "\"nan\"");
    EXPECT_EQ(format_float_bits(0xFFC00000u), "\"nan:0xffc00000\"");
    EXPECT_EQ(format_float_bits(0x7FE5BF7Fu), "\"nan:0x7fe5bf7f\"");
    EXPECT_EQ(format_float_bits(0x00000001u), "1.401298464324817e-45");
}

TEST(Json, Strings) {
    const char raw[] = {'a', '"', '\\', 0x01, 0x1F, 0x7F, static_cast<char>(0xE9), ' ', '~'};
    char buf[128];
    demo_json_format_string(raw, sizeof raw, buf, sizeof buf);
    EXPECT_STREQ(buf, "\"a\\\"\\\\\\u0001\\u001f\\u007f\\u00e9 ~\"");
}

TEST(Json, EncodeLineErrors) {
    uint8_t out[DEMO_MAX_PACKET];
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
        EXPECT_EQ(demo_json_encode_line(line, std::strlen(line), out, sizeof out, &n, msg, sizeof msg),
                  DEMO_ERR_JSON)
            << line;
        EXPECT_NE(msg[0], '\0') << line;
    }
    const char *skip = " {\"skipped\":\"A5ff75\", \"offset\": 12} ";
    ASSERT_EQ(demo_json_encode_line(skip, std::strlen(skip), out, sizeof out, &n, msg, sizeof msg), DEMO_OK)
        << msg;
    ASSERT_EQ(n, 3u);
    EXPECT_EQ(out[0], 0xA5);
    EXPECT_EQ(out[2], 0x75);
    EXPECT_EQ(demo_json_encode_line(skip, std::strlen(skip), out, 2, &n, msg, sizeof msg), DEMO_ERR_JSON);
}

TEST(Json, RawAndTrailingEntriesRoundTrip) {
    const char *line =
        "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":200,\"data\":\"0102\",\"error\":\"e\"},"
        "{\"trailing\":\"09\",\"error\":\"e\"}]}";
    uint8_t out[DEMO_MAX_PACKET];
    char msg[512];
    size_t n = 0;
    ASSERT_EQ(demo_json_encode_line(line, std::strlen(line), out, sizeof out, &n, msg, sizeof msg), DEMO_OK)
        << msg;
    ASSERT_EQ(n, DEMO_HEADER_SIZE + DEMO_FIELD_HEADER_SIZE + 2u + 1u + DEMO_CHECKSUM_SIZE);
    EXPECT_TRUE(demo_packet_valid(out, n));
    const uint8_t *payload = demo_packet_payload(out);
    EXPECT_EQ(payload[DEMO_FIELD_DESCRIPTOR_OFFSET], 200);
    EXPECT_EQ(payload[DEMO_FIELD_LENGTH_OFFSET], 2 + DEMO_FIELD_LENGTH_ADJUST);
    EXPECT_EQ(payload[DEMO_FIELD_HEADER_SIZE + 2], 0x09);
}
