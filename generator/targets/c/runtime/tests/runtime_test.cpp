// Tests of the C runtime in place: checksum, packet builder, stream parser (chunking, garbage,
// resynchronisation, end of stream), field iterator, decode error messages, the wire reader and
// writer in the protocol's byte order, canonical JSON numbers and strings, the JSON reader, samples.
// Built once per framing of the rendered test protocol (tests/runtime_specs/): everything that
// differs between protocols is read from codec/protocol.h, as the runtime itself does.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "codec/field_iter.h"
#include "codec/json.h"
#include "codec/parser.h"
#include "codec/samples.h"

extern "C" { // private headers of the runtime (C only)
#include "json_reader.h"
#include "json_writer.h"
#include "wire.h"
}

namespace {

std::vector<uint8_t> concat(std::initializer_list<std::vector<uint8_t>> parts) {
    std::vector<uint8_t> out;
    for (const auto &p : parts) {
        out.insert(out.end(), p.begin(), p.end());
    }
    return out;
}

// A packet of descriptor set `set` holding the given (descriptor, data) fields.
std::vector<uint8_t> packet(uint8_t set,
                            const std::vector<std::pair<uint8_t, std::vector<uint8_t>>> &fields) {
    std::vector<uint8_t> buf(CODEC_MAX_PACKET);
    codec_packet_builder_t b;
    codec_packet_begin(&b, buf.data(), buf.size(), set);
    for (const auto &f : fields) {
        codec_packet_add_field(&b, f.first, f.second.data(), f.second.size());
    }
    size_t n = 0;
    if (codec_packet_finish(&b, &n) != CODEC_OK) {
        return {};
    }
    buf.resize(n);
    return buf;
}

// A byte that is not part of the sync sequence (garbage that cannot start a packet).
uint8_t garbage_byte() {
    for (unsigned b = 0;; b++) {
        bool in_sync = false;
        for (size_t i = 0; i < CODEC_SYNC_SIZE; i++) {
            in_sync = in_sync || codec_sync[i] == b;
        }
        if (!in_sync) {
            return static_cast<uint8_t>(b);
        }
    }
}

struct Event {
    codec_event_kind_t kind;
    uint64_t offset;
    uint64_t length;
    bool operator==(const Event &o) const {
        return kind == o.kind && offset == o.offset && length == o.length;
    }
};

std::ostream &operator<<(std::ostream &os, const Event &e) {
    return os << (e.kind == CODEC_EVENT_PACKET ? "packet" : "skip") << "@" << e.offset << "+" << e.length;
}

struct Collector {
    std::vector<Event> events;
    std::vector<std::vector<uint8_t>> packets; // the bytes of each packet event
};

void collect(void *arg, const codec_event_t *ev) {
    Collector *c = static_cast<Collector *>(arg);
    c->events.push_back(Event{ev->kind, ev->offset, ev->length});
    if (ev->kind == CODEC_EVENT_PACKET) {
        c->packets.emplace_back(ev->packet, ev->packet + ev->length);
    }
}

// Feeds the bytes in chunks of `chunk` bytes (0: all at once).
Collector decode(const std::vector<uint8_t> &bytes, size_t chunk) {
    Collector c;
    codec_parser_t parser;
    codec_parser_init(&parser);
    if (chunk == 0) {
        codec_parser_feed(&parser, bytes.data(), bytes.size(), collect, &c);
    } else {
        for (size_t i = 0; i < bytes.size(); i += chunk) {
            size_t n = bytes.size() - i < chunk ? bytes.size() - i : chunk;
            codec_parser_feed(&parser, bytes.data() + i, n, collect, &c);
        }
    }
    codec_parser_flush(&parser, collect, &c);
    return c;
}

// The two checksum bytes in wire order, from sum1 and sum2.
std::vector<uint8_t> wire_checksum(uint8_t sum1, uint8_t sum2) {
    return CODEC_CHECKSUM_SUM1_FIRST ? std::vector<uint8_t>{sum1, sum2} : std::vector<uint8_t>{sum2, sum1};
}

// The n low bytes of v in the protocol's byte order.
std::vector<uint8_t> wire_bytes(uint64_t v, size_t n) {
    std::vector<uint8_t> out(n);
    for (size_t i = 0; i < n; i++) {
        size_t shift = CODEC_LITTLE_ENDIAN ? i : n - 1 - i;
        out[i] = static_cast<uint8_t>(v >> (8 * shift));
    }
    return out;
}

std::string format_double(double v) {
    char buf[CODEC_JSON_NUMBER_MAX];
    size_t n = codec_json_format_double(v, buf, sizeof buf);
    return std::string(buf, n);
}

std::string format_float_bits(uint32_t bits) {
    float f;
    std::memcpy(&f, &bits, sizeof f);
    char buf[CODEC_JSON_NUMBER_MAX];
    size_t n = codec_json_format_float(f, buf, sizeof buf);
    return std::string(buf, n);
}

std::string format_double_bits(uint64_t bits) {
    double d;
    std::memcpy(&d, &bits, sizeof d);
    return format_double(d);
}

} // namespace

TEST(Protocol, TheTestProtocolIsConsistent) {
    const uint8_t sync[] = CODEC_SYNC_BYTES;
    static_assert(sizeof sync == CODEC_SYNC_SIZE, "CODEC_SYNC_BYTES has CODEC_SYNC_SIZE bytes");
    EXPECT_EQ(sync[0], CODEC_SYNC_0);
    EXPECT_EQ(std::memcmp(sync, codec_sync, CODEC_SYNC_SIZE), 0);
    EXPECT_EQ(CODEC_MAX_PACKET, CODEC_HEADER_SIZE + CODEC_MAX_PAYLOAD + CODEC_CHECKSUM_SIZE);
}

TEST(Checksum, Fletcher16) {
    const uint8_t bytes[] = {0x75, 0x65, 0x01, 0x02, 0x02, 0x01};
    uint8_t ck[CODEC_CHECKSUM_SIZE];
    codec_checksum(bytes, sizeof bytes, ck);
    // sum1 = 0xE0, sum2 = 0xC6, sent in the protocol's order
    const std::vector<uint8_t> want = wire_checksum(0xE0, 0xC6);
    EXPECT_EQ(std::vector<uint8_t>(ck, ck + CODEC_CHECKSUM_SIZE), want);
    codec_checksum(bytes, 0, ck);
    EXPECT_EQ(ck[0], 0);
    EXPECT_EQ(ck[1], 0);
    // the same as a number (first wire byte high) and as a check of the two bytes that follow
    EXPECT_EQ(codec_checksum_word(bytes, sizeof bytes), CODEC_CHECKSUM_SUM1_FIRST ? 0xE0C6 : 0xC6E0);
    uint8_t packet_bytes[sizeof bytes + CODEC_CHECKSUM_SIZE];
    std::memcpy(packet_bytes, bytes, sizeof bytes);
    std::memcpy(packet_bytes + sizeof bytes, want.data(), CODEC_CHECKSUM_SIZE);
    EXPECT_TRUE(codec_checksum_matches(packet_bytes, sizeof bytes));
    for (size_t i = 0; i < CODEC_CHECKSUM_SIZE; i++) {
        packet_bytes[sizeof bytes + i] ^= 0x01;
        EXPECT_FALSE(codec_checksum_matches(packet_bytes, sizeof bytes))
            << "checksum byte " << i << " changed";
        packet_bytes[sizeof bytes + i] ^= 0x01;
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
    uint8_t ck[CODEC_CHECKSUM_SIZE];
    codec_checksum(bytes, len, ck);
    ASSERT_EQ(std::vector<uint8_t>(ck, ck + CODEC_CHECKSUM_SIZE),
              wire_checksum(static_cast<uint8_t>(sum1), static_cast<uint8_t>(sum2)))
        << what << ", length " << len;
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
    uint8_t ck[CODEC_CHECKSUM_SIZE];
    codec_checksum(ones, sizeof ones, ck);
    EXPECT_EQ(std::vector<uint8_t>(ck, ck + CODEC_CHECKSUM_SIZE), wire_checksum(0xFB, 0x71));
}

// Every implementation this build and CPU have (scalar always; SSE2 and AVX2 on x86-64) equals
// the byte-serial definition at every length 0..300 and every alignment 0..63, on random bytes
// and on all 0xFF (the largest lane sums), and codec_checksum_word() equals them all.
TEST(Checksum, EveryImplementationMatchesTheByteSerialDefinition) {
    alignas(64) static uint8_t random_bytes[64 + 2100];
    alignas(64) static uint8_t all_ff[64 + 2100];
    uint32_t state = 777;
    for (uint8_t &b : random_bytes) {
        state = state * 1103515245u + 12345u;
        b = (uint8_t)(state >> 16);
    }
    memset(all_ff, 0xFF, sizeof all_ff);
    int available = 0;
    for (int impl = 0; impl < CODEC_CHECKSUM_IMPL_COUNT; impl++) {
        uint16_t word = 0;
        if (!codec_checksum_word_impl((codec_checksum_impl_t)impl, random_bytes, 0, &word)) {
            continue;
        }
        available++;
        for (const uint8_t *buf :
             {static_cast<const uint8_t *>(random_bytes), static_cast<const uint8_t *>(all_ff)}) {
            for (size_t align = 0; align < 64; align++) {
                for (size_t len = 0; len <= 300; len++) {
                    const uint8_t *bytes = buf + align;
                    unsigned sum1 = 0, sum2 = 0;
                    for (size_t i = 0; i < len; i++) {
                        sum1 = (sum1 + bytes[i]) & 0xFFu;
                        sum2 = (sum2 + sum1) & 0xFFu;
                    }
                    const unsigned want = CODEC_CHECKSUM_SUM1_FIRST ? (sum1 << 8 | sum2) : (sum2 << 8 | sum1);
                    ASSERT_TRUE(codec_checksum_word_impl((codec_checksum_impl_t)impl, bytes, len, &word));
                    ASSERT_EQ(word, want)
                        << "implementation " << impl << ", alignment " << align << ", length " << len;
                    ASSERT_EQ(codec_checksum_word(bytes, len), want)
                        << "alignment " << align << ", length " << len;
                }
            }
        }
        for (size_t len : {1023u, 1024u, 1025u, 2047u, 2048u, 2100u}) {
            unsigned sum1 = 0, sum2 = 0;
            for (size_t i = 0; i < len; i++) {
                sum1 = (sum1 + random_bytes[5 + i]) & 0xFFu;
                sum2 = (sum2 + sum1) & 0xFFu;
            }
            ASSERT_TRUE(codec_checksum_word_impl((codec_checksum_impl_t)impl, random_bytes + 5, len, &word));
            EXPECT_EQ(word, CODEC_CHECKSUM_SUM1_FIRST ? (sum1 << 8 | sum2) : (sum2 << 8 | sum1))
                << "implementation " << impl << ", length " << len;
        }
    }
    EXPECT_GE(available, 1); // the scalar one, at least
#if defined(__x86_64__) || defined(_M_X64)
    uint16_t word = 0;
    EXPECT_TRUE(codec_checksum_word_impl(CODEC_CHECKSUM_IMPL_SSE2, random_bytes, 20, &word))
        << "every x86-64 build has the SSE2 checksum";
#endif
    uint16_t untouched = 0x1234;
    EXPECT_FALSE(codec_checksum_word_impl(CODEC_CHECKSUM_IMPL_COUNT, random_bytes, 4, &untouched));
    EXPECT_EQ(untouched, 0x1234);
}

TEST(Builder, BuildsAValidPacket) {
    std::vector<uint8_t> pkt = packet(0x01, {{0x10, {1, 2, 3}}, {0x11, {}}});
    ASSERT_EQ(pkt.size(), CODEC_HEADER_SIZE + 2u * CODEC_FIELD_HEADER_SIZE + 3u + CODEC_CHECKSUM_SIZE);
    EXPECT_EQ(std::memcmp(pkt.data(), codec_sync, CODEC_SYNC_SIZE), 0);
    EXPECT_TRUE(codec_packet_valid(pkt.data(), pkt.size()));
    EXPECT_EQ(codec_packet_set(pkt.data()), 0x01);
    EXPECT_EQ(codec_packet_payload_length(pkt.data()), 2u * CODEC_FIELD_HEADER_SIZE + 3u);
    const uint8_t *payload = codec_packet_payload(pkt.data());
    EXPECT_EQ(payload[CODEC_FIELD_LENGTH_OFFSET], 3 + CODEC_FIELD_LENGTH_ADJUST);
    EXPECT_EQ(payload[CODEC_FIELD_DESCRIPTOR_OFFSET], 0x10);
    pkt[pkt.size() - 1] ^= 1;
    EXPECT_FALSE(codec_packet_valid(pkt.data(), pkt.size()));
}

TEST(Builder, RejectsOverlongPayloadAndSmallBuffer) {
    std::vector<uint8_t> buf(CODEC_MAX_PACKET + 10);
    std::vector<uint8_t> data(CODEC_MAX_FIELD_DATA);
    codec_packet_builder_t b;
    codec_packet_begin(&b, buf.data(), buf.size(), 1);
    EXPECT_EQ(codec_packet_add_field(&b, 1, data.data(), data.size()), CODEC_OK);
    EXPECT_EQ(codec_packet_add_field(&b, 2, data.data(), 1), CODEC_ERR_TOO_LONG);
    size_t n = 0;
    EXPECT_EQ(codec_packet_finish(&b, &n), CODEC_ERR_TOO_LONG);
    codec_packet_begin(&b, buf.data(), CODEC_HEADER_SIZE + 3, 1);
    EXPECT_EQ(codec_packet_add_field(&b, 1, data.data(), 4), CODEC_ERR_BUFFER);
    codec_packet_begin(&b, buf.data(), buf.size(), 1);
    EXPECT_EQ(codec_packet_add_field(&b, 1, data.data(), CODEC_MAX_FIELD_DATA + 1), CODEC_ERR_TOO_LONG);
}

TEST(Parser, GarbageBeforeBetweenAndAfterIsIndependentOfChunking) {
    uint8_t g = garbage_byte();
    std::vector<uint8_t> p1 = packet(0x01, {{0x01, {}}});
    std::vector<uint8_t> p2 = packet(0x02, {{0x05, {9, 8, 7, 6}}});
    std::vector<uint8_t> stream = concat(
        {std::vector<uint8_t>{g, g}, p1, std::vector<uint8_t>{g, g, g, g}, p2, std::vector<uint8_t>{g}});
    std::vector<Event> want = {
        {CODEC_EVENT_SKIP, 0, 2},
        {CODEC_EVENT_PACKET, 2, p1.size()},
        {CODEC_EVENT_SKIP, 2 + p1.size(), 4},
        {CODEC_EVENT_PACKET, 6 + p1.size(), p2.size()},
        {CODEC_EVENT_SKIP, 6 + p1.size() + p2.size(), 1},
    };
    const std::vector<std::vector<uint8_t>> want_packets = {p1, p2};
    for (size_t chunk = 0; chunk <= stream.size(); chunk++) {
        Collector c = decode(stream, chunk);
        EXPECT_EQ(c.events, want) << "chunk size " << chunk;
        EXPECT_EQ(c.packets, want_packets) << "chunk size " << chunk;
    }
}

TEST(Parser, BadChecksumResynchronisesInsideTheFalsePacket) {
    // A header whose length covers a valid packet: the checksum fails, the parser skips one
    // byte at a time and finds the packet inside.
    std::vector<uint8_t> inner = packet(0x01, {{0x01, {}}});
    std::vector<uint8_t> stream(codec_sync, codec_sync + CODEC_SYNC_SIZE);
    stream.resize(CODEC_HEADER_SIZE);
    stream[CODEC_SET_OFFSET] = 0x01;
    stream[CODEC_LENGTH_OFFSET] = static_cast<uint8_t>(inner.size());
    stream.insert(stream.end(), inner.begin(), inner.end());
    stream.push_back(0x00);
    stream.push_back(0x00);
    std::vector<Event> want = {
        {CODEC_EVENT_SKIP, 0, CODEC_HEADER_SIZE},
        {CODEC_EVENT_PACKET, CODEC_HEADER_SIZE, inner.size()},
        {CODEC_EVENT_SKIP, CODEC_HEADER_SIZE + inner.size(), 2},
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
        {CODEC_EVENT_SKIP, 0, bad.size() + 3},
        {CODEC_EVENT_PACKET, bad.size() + 3, good.size()},
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
        {CODEC_EVENT_PACKET, 0, good.size()},
        {CODEC_EVENT_SKIP, good.size(), cut.size()},
    };
    EXPECT_EQ(decode(stream, 0).events, want);
    EXPECT_EQ(decode(stream, 1).events, want);
    // A partial sync sequence at the very end waits, then is skipped at flush.
    std::vector<uint8_t> tail = concat({good, std::vector<uint8_t>{codec_sync[0]}});
    std::vector<Event> want_tail = {
        {CODEC_EVENT_PACKET, 0, good.size()},
        {CODEC_EVENT_SKIP, good.size(), 1},
    };
    EXPECT_EQ(decode(tail, 1).events, want_tail);
}

TEST(FieldIterator, TrailingEntries) {
    char msg[256];
    codec_field_iter_t it;
    codec_field_entry_t e;
    // one byte left: no room for a field header
    const uint8_t one[] = {0x07};
    codec_field_iter_init(&it, 0x01, one, sizeof one);
    ASSERT_TRUE(codec_field_iter_next(&it, &e));
    EXPECT_EQ(e.kind, CODEC_ENTRY_TRAILING);
    codec_trailing_format(&e, msg, sizeof msg);
    EXPECT_STREQ(msg, "field header at payload offset 0 needs 2 bytes, 1 left");
    EXPECT_FALSE(codec_field_iter_next(&it, &e));
    // a field, then one that runs past the payload
    uint8_t two[6] = {0};
    two[CODEC_FIELD_LENGTH_OFFSET] = CODEC_FIELD_LENGTH_ADJUST;
    two[CODEC_FIELD_DESCRIPTOR_OFFSET] = 0x01;
    two[2 + CODEC_FIELD_LENGTH_OFFSET] = 5 + CODEC_FIELD_LENGTH_ADJUST;
    two[2 + CODEC_FIELD_DESCRIPTOR_OFFSET] = 0x02;
    codec_field_iter_init(&it, 0x01, two, sizeof two);
    ASSERT_TRUE(codec_field_iter_next(&it, &e));
    EXPECT_EQ(e.kind, CODEC_ENTRY_FIELD);
    EXPECT_EQ(e.descriptor, 0x01);
    EXPECT_EQ(e.length, 0u);
    ASSERT_TRUE(codec_field_iter_next(&it, &e));
    EXPECT_EQ(e.kind, CODEC_ENTRY_TRAILING);
    EXPECT_EQ(e.length, 4u);
    codec_trailing_format(&e, msg, sizeof msg);
    EXPECT_EQ(std::string(msg), "field length " + std::to_string(5 + CODEC_FIELD_LENGTH_ADJUST) +
                                    " at payload offset 2 overruns the payload (4 bytes left)");
#if CODEC_FIELD_LENGTH_ADJUST > 0
    // a length byte smaller than the field header it counts
    uint8_t short_len[3] = {0};
    short_len[CODEC_FIELD_LENGTH_OFFSET] = 1;
    codec_field_iter_init(&it, 0x01, short_len, sizeof short_len);
    ASSERT_TRUE(codec_field_iter_next(&it, &e));
    EXPECT_EQ(e.kind, CODEC_ENTRY_TRAILING);
    EXPECT_EQ(e.length, 3u);
    codec_trailing_format(&e, msg, sizeof msg);
    EXPECT_STREQ(msg, "field length 1 at payload offset 0 is shorter than the field header");
#endif
}

// Field (set 0x80, descriptor 0x06: odd) is irregular in the test protocol (its length byte is one
// less than the data length) and descriptor 0x06 of set 0x01 is regular: the builder and the
// iterator agree on it either way, and only in its own set.
TEST(FieldIterator, IrregularLengthsRoundTrip) {
    for (uint8_t set : {0x01, 0x80}) {
        std::vector<uint8_t> pkt = packet(set, {{0x06, {1, 2, 3}}, {0x07, {4}}});
        ASSERT_FALSE(pkt.empty());
        const uint8_t *payload = codec_packet_payload(pkt.data());
        EXPECT_EQ(payload[CODEC_FIELD_LENGTH_OFFSET], 3 + codec_field_length_adjust(set, 0x06));
        codec_field_iter_t it;
        codec_field_entry_t e;
        codec_field_iter_init(&it, set, payload, codec_packet_payload_length(pkt.data()));
        ASSERT_TRUE(codec_field_iter_next(&it, &e));
        EXPECT_EQ(e.kind, CODEC_ENTRY_FIELD);
        EXPECT_EQ(e.descriptor, 0x06);
        EXPECT_EQ(e.length, 3u);
        ASSERT_TRUE(codec_field_iter_next(&it, &e));
        EXPECT_EQ(e.descriptor, 0x07);
        EXPECT_EQ(e.length, 1u);
        EXPECT_FALSE(codec_field_iter_next(&it, &e));
    }
}

TEST(DecodeError, Messages) {
    codec_decode_error_t e;
    char msg[CODEC_ERROR_MESSAGE_MAX];
    std::memset(&e, 0, sizeof e);
    e.kind = CODEC_DECODE_NEEDS_BYTES;
    e.depth = 1;
    e.path[0].name = "descriptors";
    e.path[0].index = 5;
    e.need = 2;
    e.offset = 10;
    e.have = 1;
    codec_decode_error_format(&e, msg, sizeof msg);
    EXPECT_STREQ(msg, "descriptors[5]: needs 2 bytes at offset 10, 1 left");
#if CODEC_PATH_MAX_DEPTH > 1
    e.depth = 2;
    e.path[0].name = "entries";
    e.path[0].index = 2;
    e.path[1].name = "rate";
    e.path[1].index = SIZE_MAX;
    e.need = 4;
    codec_decode_error_format(&e, msg, sizeof msg);
    EXPECT_STREQ(msg, "entries[2].rate: needs 4 bytes at offset 10, 1 left");
    e.depth = 1;
#endif
    e.kind = CODEC_DECODE_COUNT;
    e.path[0].name = "items";
    e.path[0].index = SIZE_MAX;
    e.count = 300;
    e.max = 126;
    codec_decode_error_format(&e, msg, sizeof msg);
    EXPECT_STREQ(msg, "items: count 300 exceeds maximum 126");
    e.kind = CODEC_DECODE_REMAINING;
    e.have = 3;
    e.offset = 4;
    e.need = 2;
    codec_decode_error_format(&e, msg, sizeof msg);
    EXPECT_STREQ(msg, "items: 3 bytes left at offset 4, not a multiple of 2");
    e.kind = CODEC_DECODE_BOOL;
    e.value = 7;
    codec_decode_error_format(&e, msg, sizeof msg);
    EXPECT_STREQ(msg, "items: invalid bool value 7 at offset 4");
    e.kind = CODEC_DECODE_SELECTOR;
    e.value = static_cast<uint64_t>(-3);
    e.value_signed = true;
    codec_decode_error_format(&e, msg, sizeof msg);
    EXPECT_STREQ(msg, "items: no member for selector value -3");
    e.kind = CODEC_DECODE_UNEXPECTED;
    e.have = 2;
    e.offset = 6;
    codec_decode_error_format(&e, msg, sizeof msg);
    EXPECT_STREQ(msg, "2 unexpected bytes at offset 6");
    char small[8];
    size_t n = codec_decode_error_format(&e, small, sizeof small);
    EXPECT_EQ(n, std::strlen("2 unexpected bytes at offset 6"));
    EXPECT_STREQ(small, "2 unexp");
}

// Every multi-byte value goes on the wire in the protocol's byte order (CODEC_LITTLE_ENDIAN):
// the writer, the bounds-checked reader and the straight loads of fixed layouts agree on it.
TEST(Wire, ValuesUseTheProtocolByteOrder) {
    const uint16_t u16 = 0x1234;
    const uint32_t u32 = 0x89ABCDEFu;
    const uint64_t u64 = 0x0102030405060708ull;
    const int16_t s16 = -2;
    const int32_t s32 = -100000;
    const int64_t s64 = std::numeric_limits<int64_t>::min() + 5;
    const float f32 = 1.5f;
    const double f64 = -0.1;
    uint32_t f32_bits;
    uint64_t f64_bits;
    std::memcpy(&f32_bits, &f32, sizeof f32_bits);
    std::memcpy(&f64_bits, &f64, sizeof f64_bits);

    uint8_t buf[64];
    codec_writer_t w;
    codec_writer_init(&w, buf, sizeof buf);
    ASSERT_EQ(codec_wr_u16(&w, &u16), CODEC_OK);
    ASSERT_EQ(codec_wr_u32(&w, &u32), CODEC_OK);
    ASSERT_EQ(codec_wr_u64(&w, &u64), CODEC_OK);
    ASSERT_EQ(codec_wr_s16(&w, &s16), CODEC_OK);
    ASSERT_EQ(codec_wr_s32(&w, &s32), CODEC_OK);
    ASSERT_EQ(codec_wr_s64(&w, &s64), CODEC_OK);
    ASSERT_EQ(codec_wr_f32(&w, &f32), CODEC_OK);
    ASSERT_EQ(codec_wr_f64(&w, &f64), CODEC_OK);
    std::vector<uint8_t> want =
        concat({wire_bytes(u16, 2), wire_bytes(u32, 4), wire_bytes(u64, 8),
                wire_bytes(static_cast<uint16_t>(s16), 2), wire_bytes(static_cast<uint32_t>(s32), 4),
                wire_bytes(static_cast<uint64_t>(s64), 8), wire_bytes(f32_bits, 4), wire_bytes(f64_bits, 8)});
    ASSERT_EQ(std::vector<uint8_t>(buf, buf + w.len), want);
#if CODEC_LITTLE_ENDIAN
    EXPECT_EQ(buf[0], 0x34);
#else
    EXPECT_EQ(buf[0], 0x12);
#endif

    codec_decode_error_t err;
    codec_reader_t r;
    codec_reader_init(&r, buf, w.len, &err);
    uint16_t ru16 = 0;
    uint32_t ru32 = 0;
    uint64_t ru64 = 0;
    int16_t rs16 = 0;
    int32_t rs32 = 0;
    int64_t rs64 = 0;
    float rf32 = 0;
    double rf64 = 0;
    ASSERT_EQ(codec_rd_u16(&r, &ru16), 0);
    ASSERT_EQ(codec_rd_u32(&r, &ru32), 0);
    ASSERT_EQ(codec_rd_u64(&r, &ru64), 0);
    ASSERT_EQ(codec_rd_s16(&r, &rs16), 0);
    ASSERT_EQ(codec_rd_s32(&r, &rs32), 0);
    ASSERT_EQ(codec_rd_s64(&r, &rs64), 0);
    ASSERT_EQ(codec_rd_f32(&r, &rf32), 0);
    ASSERT_EQ(codec_rd_f64(&r, &rf64), 0);
    EXPECT_EQ(codec_rd_finish(&r), 0);
    EXPECT_EQ(ru16, u16);
    EXPECT_EQ(ru32, u32);
    EXPECT_EQ(ru64, u64);
    EXPECT_EQ(rs16, s16);
    EXPECT_EQ(rs32, s32);
    EXPECT_EQ(rs64, s64);
    EXPECT_EQ(rf32, f32);
    EXPECT_EQ(rf64, f64);

    EXPECT_EQ(codec_ld_u16(buf), u16);
    EXPECT_EQ(codec_ld_u32(buf + 2), u32);
    EXPECT_EQ(codec_ld_u64(buf + 6), u64);
    EXPECT_EQ(codec_ld_s16(buf + 14), s16);
    EXPECT_EQ(codec_ld_s32(buf + 16), s32);
    EXPECT_EQ(codec_ld_s64(buf + 20), s64);
    EXPECT_EQ(codec_ld_f32(buf + 28), f32);
    EXPECT_EQ(codec_ld_f64(buf + 32), f64);
}

TEST(Wire, ReaderErrorsCarryThePath) {
    const uint8_t data[] = {0x01, 0x02, 0x03};
    codec_decode_error_t err;
    codec_reader_t r;
    char msg[CODEC_ERROR_MESSAGE_MAX];
    uint16_t u16 = 0;
    uint32_t u32 = 0;
    codec_reader_init(&r, data, sizeof data, &err);
    codec_rd_push(&r, "rate");
    ASSERT_EQ(codec_rd_u16(&r, &u16), 0);
    EXPECT_EQ(codec_rd_u32(&r, &u32), -1);
    codec_decode_error_format(&err, msg, sizeof msg);
    EXPECT_STREQ(msg, "rate: needs 4 bytes at offset 2, 1 left");
    bool flag = false;
    codec_reader_init(&r, data + 2, 1, &err);
    codec_rd_push(&r, "flag");
    EXPECT_EQ(codec_rd_bool(&r, &flag), -1);
    codec_decode_error_format(&err, msg, sizeof msg);
    EXPECT_STREQ(msg, "flag: invalid bool value 3 at offset 0");
    codec_reader_init(&r, data, sizeof data, &err);
    uint8_t u8 = 0;
    ASSERT_EQ(codec_rd_u8(&r, &u8), 0);
    EXPECT_EQ(codec_rd_finish(&r), -1);
    codec_decode_error_format(&err, msg, sizeof msg);
    EXPECT_STREQ(msg, "2 unexpected bytes at offset 1");
}

TEST(Wire, WriterStopsAtTheEndOfTheBuffer) {
    uint8_t buf[3];
    codec_writer_t w;
    codec_writer_init(&w, buf, sizeof buf);
    const uint16_t u16 = 1;
    EXPECT_EQ(codec_wr_u16(&w, &u16), CODEC_OK);
    EXPECT_EQ(codec_wr_u16(&w, &u16), CODEC_ERR_BUFFER);
    EXPECT_EQ(w.len, 2u);
    EXPECT_EQ(codec_wr_chars(&w, "ab", 2), CODEC_ERR_BUFFER);
    EXPECT_EQ(codec_wr_chars(&w, "a", 1), CODEC_OK);
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
    codec_json_format_string(raw, sizeof raw, buf, sizeof buf);
    EXPECT_STREQ(buf, "\"a\\\"\\\\\\u0001\\u001f\\u007f\\u00e9 ~\"");
}

TEST(JsonReader, ValuesAndRangeErrors) {
    const std::string line =
        "{\"small\": 255, \"big\": 256, \"neg\": -129, \"hex\": \"0aFf\", \"list\": [1, 2]}";
    const char *const keys[] = {"small", "big", "neg", "hex", "list"};
    char msg[256] = "";
    codec_jr_t jr;
    codec_jr_init(&jr, line.data(), line.size(), msg, sizeof msg);
    size_t pos = 0;
    size_t vp = 0;
    ASSERT_EQ(codec_jr_document(&jr, &pos), 0) << msg;
    ASSERT_EQ(codec_jr_object(&jr, pos, keys, 5), 0) << msg;
    uint8_t u8 = 0;
    ASSERT_EQ(codec_jr_get(&jr, pos, "small", &vp), 1);
    EXPECT_EQ(codec_jr_u8(&jr, vp, &u8), 0);
    EXPECT_EQ(u8, 255);
    uint8_t hex[4];
    size_t n = 0;
    ASSERT_EQ(codec_jr_get(&jr, pos, "hex", &vp), 1);
    ASSERT_EQ(codec_jr_hex(&jr, vp, hex, sizeof hex, &n), 0);
    EXPECT_EQ(std::vector<uint8_t>(hex, hex + n), (std::vector<uint8_t>{0x0A, 0xFF}));
    size_t it = 0;
    size_t elem = 0;
    int sum = 0;
    ASSERT_EQ(codec_jr_get(&jr, pos, "list", &vp), 1);
    ASSERT_EQ(codec_jr_array(&jr, vp, &it), 0);
    while (codec_jr_next(&jr, &it, &elem) == 1) {
        uint8_t v = 0;
        ASSERT_EQ(codec_jr_u8(&jr, elem, &v), 0);
        sum += v;
    }
    EXPECT_EQ(sum, 3);
    EXPECT_EQ(codec_jr_get(&jr, pos, "absent", &vp), 0);
    int8_t s8 = 0;
    ASSERT_EQ(codec_jr_get(&jr, pos, "neg", &vp), 1);
    EXPECT_EQ(codec_jr_s8(&jr, vp, &s8), -1);
    EXPECT_NE(msg[0], '\0');
    // only the first failure is kept
    std::string first = msg;
    ASSERT_EQ(codec_jr_get(&jr, pos, "big", &vp), 1);
    EXPECT_EQ(codec_jr_u8(&jr, vp, &u8), -1);
    EXPECT_EQ(std::string(msg), first);
}

TEST(JsonReader, RejectsMalformedLines) {
    const char *bad[] = {"", "[1]", "{\"a\":1} x", "{\"a\":1,}", "{\"a\" 1}", "{\"a\":01}"};
    for (const char *line : bad) {
        char msg[256] = "";
        codec_jr_t jr;
        codec_jr_init(&jr, line, std::strlen(line), msg, sizeof msg);
        size_t pos = 0;
        EXPECT_EQ(codec_jr_document(&jr, &pos), -1) << line;
        EXPECT_NE(msg[0], '\0') << line;
    }
}

#if CODEC_SAMPLE_TIMESTAMPS > 0
static std::vector<uint8_t> stamped(uint8_t stamp, bool key, uint8_t descriptor) {
    static const uint8_t k_stamp_descriptor[] = CODEC_SAMPLE_STAMP_DESCRIPTORS;
    static const uint8_t k_stamp_size[] = CODEC_SAMPLE_STAMP_SIZES;
    static const uint8_t k_data_sets[] = CODEC_SAMPLE_DATA_SETS;
    std::vector<uint8_t> buf(CODEC_MAX_PACKET);
    std::vector<uint8_t> value(k_stamp_size[0], stamp);
    const uint8_t one = 0x55;
    codec_packet_builder_t b;
    size_t n = 0;
    codec_packet_begin(&b, buf.data(), buf.size(), k_data_sets[0]);
    if (key) {
        EXPECT_EQ(codec_packet_add_field(&b, k_stamp_descriptor[0], value.data(), value.size()), CODEC_OK);
    }
    EXPECT_EQ(codec_packet_add_field(&b, descriptor, &one, 1), CODEC_OK);
    EXPECT_EQ(codec_packet_finish(&b, &n), CODEC_OK);
    buf.resize(n);
    return buf;
}

TEST(Samples, TrackerNumbersContinuationPackets) {
    static const uint8_t k_stamp_size[] = CODEC_SAMPLE_STAMP_SIZES;
    const std::vector<std::vector<uint8_t>> packets = {stamped(1, true, 1), stamped(1, true, 2),
                                                       stamped(2, true, 3), stamped(0, false, 4),
                                                       stamped(0, false, 5)};
    const uint64_t want_number[] = {0, 0, 1, 2, 3};
    const bool want_continues[] = {false, true, false, false, false};
    codec_sample_tracker_t tracker;
    codec_sample_tracker_init(&tracker);
    for (size_t i = 0; i < packets.size(); i++) {
        codec_sample_info_t info;
        ASSERT_TRUE(codec_sample_tracker_feed(&tracker, packets[i].data(), packets[i].size(), &info));
        EXPECT_EQ(info.number, want_number[i]) << i;
        EXPECT_EQ(info.continues, want_continues[i]) << i;
        /* The leading shared run: the timestamp field (header + data), or nothing. */
        EXPECT_EQ(info.shared_prefix, i < 3 ? CODEC_FIELD_HEADER_SIZE + k_stamp_size[0] : 0u) << i;
    }
    /* Malformed buffers and command sets are not samples. */
    codec_sample_info_t info;
    EXPECT_FALSE(codec_sample_tracker_feed(&tracker, packets[0].data(), 3, &info));
    EXPECT_FALSE(codec_sample_tracker_feed(&tracker, packets[0].data(), packets[0].size() - 3, &info));
    EXPECT_FALSE(codec_sample_tracker_feed(&tracker, nullptr, 0, &info));
    std::vector<uint8_t> cmd = packets[0];
    cmd[CODEC_SET_OFFSET] = 0x01;
    EXPECT_FALSE(codec_sample_tracker_feed(&tracker, cmd.data(), cmd.size(), &info));
}
#else
TEST(Samples, WithoutDataSetsNoPacketIsASample) {
    codec_sample_tracker_t tracker;
    codec_sample_tracker_init(&tracker);
    codec_sample_info_t info;
    for (uint8_t set : {0x01, 0x80, 0x82}) {
        std::vector<uint8_t> pkt = packet(set, {{0xD3, {1, 2, 3, 4}}, {0x01, {5}}});
        EXPECT_FALSE(codec_sample_tracker_feed(&tracker, pkt.data(), pkt.size(), &info)) << int(set);
        uint8_t key[CODEC_SAMPLE_KEY_MAX];
        size_t prefix = 99;
        EXPECT_EQ(codec_sample_key(pkt.data(), pkt.size(), key, &prefix), 0u);
        EXPECT_EQ(prefix, 0u); // no descriptor is shared
    }
}
#endif

// Issue 28: every pointer precondition is documented in the headers and checked by assert() in
// debug builds (this suite is built without NDEBUG); a NULL buffer with size 0 is allowed.
#ifndef NDEBUG
TEST(Preconditions, NullPointersAreCaughtInDebugBuilds) {
    uint8_t buf[CODEC_MAX_PACKET];
    codec_packet_builder_t b;
    codec_parser_t parser;
    codec_field_iter_t it;
    codec_field_entry_t entry;
    codec_sample_tracker_t tracker;
    codec_sample_info_t info;
    EXPECT_DEATH(codec_packet_begin(nullptr, buf, sizeof buf, 1), "b != NULL");
    EXPECT_DEATH(codec_packet_begin(&b, nullptr, 10, 1), "buf != NULL \\|\\| cap == 0");
    codec_packet_begin(&b, buf, sizeof buf, 1);
    EXPECT_DEATH(codec_packet_add_field(&b, 1, nullptr, 3), "data != NULL \\|\\| data_len == 0");
    EXPECT_DEATH(codec_packet_add_raw(nullptr, buf, 1), "b != NULL");
    EXPECT_DEATH(codec_packet_finish(nullptr, nullptr), "b != NULL");
    EXPECT_DEATH(codec_checksum(nullptr, 4, buf), "bytes != NULL");
    EXPECT_DEATH(codec_packet_valid(nullptr, 8), "packet != NULL");
    EXPECT_DEATH(codec_parser_init(nullptr), "parser != NULL");
    codec_parser_init(&parser);
    EXPECT_DEATH(codec_parser_feed(&parser, nullptr, 5, nullptr, nullptr), "data != NULL");
    EXPECT_DEATH(codec_parser_feed(&parser, buf, 0, nullptr, nullptr), "fn != NULL");
    EXPECT_DEATH(codec_field_iter_init(nullptr, 1, buf, 1), "it != NULL");
    codec_field_iter_init(&it, 1, buf, 0);
    EXPECT_DEATH(codec_field_iter_next(&it, nullptr), "entry != NULL");
    EXPECT_DEATH(codec_trailing_format(nullptr, nullptr, 0), "entry != NULL");
    codec_sample_tracker_init(&tracker);
    EXPECT_DEATH(codec_sample_tracker_feed(&tracker, nullptr, 9, &info), "packet != NULL");
    EXPECT_DEATH(codec_sample_key(buf, 0, nullptr, nullptr), "key != NULL");
    EXPECT_DEATH(codec_json_skip_line(0, nullptr, 2, nullptr, 0), "bytes != NULL");
    EXPECT_DEATH(codec_json_packet_line(buf, 0, 0, CODEC_DEVICE_ANY, nullptr, 4), "out != NULL");
    EXPECT_DEATH(codec_json_encode_line(nullptr, 3, buf, sizeof buf, nullptr, nullptr, 0), "line != NULL");
    EXPECT_DEATH(codec_json_format_double(1.0, nullptr, 8), "buf != NULL");
    EXPECT_DEATH(codec_decode_error_format(nullptr, nullptr, 0), "err != NULL");
    // NULL with a zero size is fine: nothing is read or written.
    codec_packet_begin(&b, buf, sizeof buf, 1);
    EXPECT_EQ(codec_packet_add_field(&b, 1, nullptr, 0), CODEC_OK);
    size_t len = 0;
    EXPECT_EQ(codec_packet_finish(&b, &len), CODEC_OK);
    EXPECT_TRUE(codec_packet_valid(buf, len));
    EXPECT_EQ(codec_json_format_double(1.5, nullptr, 0), 3u);
    codec_field_iter_init(&it, 1, nullptr, 5);
    EXPECT_FALSE(codec_field_iter_next(&it, &entry));
}
#endif
