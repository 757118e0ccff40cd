// The session core (src/session.c) and the blocking link (src/link.c), on the rendered test
// protocol (tests/runtime_specs/: ping on every device; rate per device, alpha's reply allowed hz
// ms more, beta's answered with the reply field 0x84 unless hz is 0, which suppresses its ack):
// matching, timeouts, the look-ahead rule (replies recognised by content, issue 37), skip runs in
// pieces of CODEC_SESSION_SKIP_PIECE, refusals, ack suppression, the pending queue. The corpus
// (tests/sessions/) runs in every package's suite.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

extern "C" {
#include "codec/link.h"
}

namespace {

struct Log {
    std::vector<std::string> lines;
};

void on_event(void *ctx, const codec_session_event_t *ev) {
    Log *log = static_cast<Log *>(ctx);
    if (ev->kind == CODEC_SESSION_RESULT) {
        std::string s =
            std::string(codec_result_kind_name(ev->result->kind)) + " " + std::to_string(ev->result->tag);
        if (ev->result->has_code) {
            s += " code " + std::to_string(ev->result->code);
        }
        if (ev->result->error[0]) {
            s += std::string(" ") + ev->result->error;
        }
        log->lines.push_back(s);
    } else if (ev->kind == CODEC_SESSION_PACKET) {
        log->lines.push_back("packet " + std::to_string(ev->stream->offset));
    } else if (ev->kind == CODEC_SESSION_FOREIGN) {
        log->lines.push_back(std::string(ev->stream->kind == CODEC_EVENT_NMEA ? "nmea " : "rtcm ") +
                             std::to_string(ev->stream->offset) + "+" + std::to_string(ev->stream->length));
    } else {
        log->lines.push_back("skip " + std::to_string(ev->stream->offset) + "+" +
                             std::to_string(ev->stream->length));
    }
}

std::vector<uint8_t> packet(std::vector<std::pair<uint8_t, std::vector<uint8_t>>> fields) {
    uint8_t buf[CODEC_MAX_PACKET];
    size_t n = 0;
    codec_packet_builder_t b;
    codec_packet_begin(&b, buf, sizeof buf, 0x01);
    for (auto &f : fields) {
        codec_packet_add_field(&b, f.first, f.second.data(), f.second.size());
    }
    EXPECT_EQ(codec_packet_finish(&b, &n), CODEC_OK);
    return std::vector<uint8_t>(buf, buf + n);
}

struct Fixture {
    codec_session_t s;
    Log log;
    explicit Fixture(codec_device_t device = CODEC_DEVICE_ANY,
                     size_t max_pending = CODEC_SESSION_MAX_PENDING) {
        codec_session_config_t c;
        codec_session_config_init(&c);
        c.device = device;
        c.max_pending = max_pending;
        c.on_event = on_event;
        c.ctx = &log;
        EXPECT_EQ(codec_session_init(&s, &c), CODEC_OK);
    }
    codec_started_t start(const codec_field_value_t &v, uint64_t now, uintptr_t tag) {
        codec_start_options_t o;
        codec_start_options_init(&o);
        o.tag = tag;
        uint8_t buf[CODEC_MAX_PACKET];
        codec_started_t st;
        EXPECT_EQ(codec_session_start(&s, &v, now, &o, buf, sizeof buf, &st), CODEC_OK);
        return st;
    }
    void feed(const std::vector<uint8_t> &b, uint64_t now) {
        codec_session_feed(&s, b.data(), b.size(), now);
    }
};

// A header of a packet that claims 192 payload bytes and never comes: a false sync that waits.
std::vector<uint8_t> false_sync() {
    std::vector<uint8_t> h(CODEC_HEADER_SIZE, 0);
    for (size_t i = 0; i < CODEC_SYNC_SIZE; ++i) {
        h[i] = codec_sync[i];
    }
    h[CODEC_SET_OFFSET] = 0x01;
    h[CODEC_LENGTH_OFFSET] = 0xC0;
    return h;
}
const std::string H = std::to_string(CODEC_HEADER_SIZE);

codec_field_value_t ping() {
    codec_field_value_t v;
    memset(&v, 0, sizeof v);
    v.id = CODEC_FIELD_CONTROL_PING;
    return v;
}

TEST(Session, AckMatchesAndDataIsRouted) {
    Fixture f;
    codec_started_t st = f.start(ping(), 0, 7);
    EXPECT_FALSE(st.done);
    EXPECT_EQ(st.deadline, 1000u);
    std::vector<uint8_t> data = packet({{0x02, {0x00, 0x01}}}); // not an ack: data
    std::vector<uint8_t> ack = packet({{0xF1, {0x01, 0x00}}});
    f.feed(data, 5);
    f.feed(ack, 6);
    EXPECT_EQ(f.log.lines, (std::vector<std::string>{"packet 0", "ack 7 code 0"}));
    EXPECT_EQ(codec_session_pending(&f.s), 0u);
}

// The example GGA sentence NMEA references quote (checksum 47, 67 bytes) and the RTCM 10403
// example frame of message 1005 (25 bytes, CRC-24Q 36 0B 98) between a data packet and a reply:
// framing a carries them (CODEC_FOREIGN_NMEA, CODEC_FOREIGN_RTCM3; docs/conformance.md section 1)
// and the session hands them on as CODEC_SESSION_FOREIGN events in stream order, whatever the
// split; framing b has none, and the same bytes are skip runs.
TEST(Session, ForeignFramesGoToTheHandler) {
    const std::string gga = "$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,*47\r\n";
    const std::vector<uint8_t> rtcm = {0xD3, 0x00, 0x13, 0x3E, 0xD7, 0xD3, 0x02, 0x02, 0x98,
                                       0x0E, 0xDE, 0xEF, 0x34, 0xB4, 0xBD, 0x62, 0xAC, 0x09,
                                       0x41, 0x98, 0x6F, 0x33, 0x36, 0x0B, 0x98};
    std::vector<uint8_t> data = packet({{0x02, {0x00, 0x01}}});
    std::vector<uint8_t> stream(gga.begin(), gga.end());
    stream.insert(stream.end(), data.begin(), data.end());
    stream.insert(stream.end(), rtcm.begin(), rtcm.end());
    std::vector<uint8_t> ack = packet({{0xF1, {0x01, 0x00}}});
    stream.insert(stream.end(), ack.begin(), ack.end());
    const std::string at_data = std::to_string(gga.size());
    const std::string at_rtcm = std::to_string(gga.size() + data.size());
    const bool foreign = CODEC_FOREIGN_NMEA && CODEC_FOREIGN_RTCM3;
    const std::vector<std::string> want = {
        std::string(foreign ? "nmea 0+" : "skip 0+") + std::to_string(gga.size()), "packet " + at_data,
        std::string(foreign ? "rtcm " : "skip ") + at_rtcm + "+25", "ack 7 code 0"};
    for (size_t cut = 0; cut <= stream.size(); ++cut) {
        Fixture f;
        f.start(ping(), 0, 7);
        f.feed(std::vector<uint8_t>(stream.begin(), stream.begin() + static_cast<std::ptrdiff_t>(cut)), 1);
        f.feed(std::vector<uint8_t>(stream.begin() + static_cast<std::ptrdiff_t>(cut), stream.end()), 1);
        EXPECT_EQ(f.log.lines, want) << "cut " << cut;
    }
}

TEST(Session, TwoAcksInOnePacketAndTimeout) {
    Fixture f;
    f.start(ping(), 0, 1);
    f.start(ping(), 0, 2);
    f.start(ping(), 0, 3);
    f.feed(packet({{0xF1, {0x01, 0x00}}, {0xF1, {0x01, 0x05}}}), 10);
    uint64_t d = 0;
    ASSERT_TRUE(codec_session_next_deadline(&f.s, &d));
    EXPECT_EQ(d, 1000u);
    codec_session_poll(&f.s, 999);
    codec_session_poll(&f.s, 1000);
    EXPECT_EQ(f.log.lines, (std::vector<std::string>{"ack 1 code 0", "nack 2 code 5", "timeout 3"}));
}

// A false sync (a header claiming 240 payload bytes) with nothing complete after it is not dropped
// by time: the wake-up at s + P + 1 finds nothing, and then there is no wake-up for it any more.
TEST(Session, LookAheadKeepsAFalseSyncWithNothingAfterIt) {
    Fixture f;
    f.start(ping(), 0, 1);
    f.feed(false_sync(), 5);
    uint64_t d = 0;
    ASSERT_TRUE(codec_session_next_deadline(&f.s, &d));
    EXPECT_EQ(d, 106u); // s + P + 1
    codec_session_poll(&f.s, 106);
    EXPECT_TRUE(f.log.lines.empty());
    ASSERT_TRUE(codec_session_next_deadline(&f.s, &d));
    EXPECT_EQ(d, 1000u); // the expired wait wakes nobody: only the command's deadline
    EXPECT_EQ(f.s.parser.used, (size_t)CODEC_HEADER_SIZE);
    codec_session_poll(&f.s, 1000);
    codec_session_close(&f.s, 1000);
    EXPECT_EQ(f.log.lines, (std::vector<std::string>{"timeout 1", "skip 0+" + H}));
}

// The same false sync, and the ACK behind it in the same chunk: at s + P + 1 the look-ahead finds
// the complete ACK at offset 4 and skips the four bytes before it.
TEST(Session, LookAheadFindsACompletePacketAfterTheWait) {
    Fixture f;
    f.start(ping(), 0, 1);
    std::vector<uint8_t> bytes = false_sync();
    std::vector<uint8_t> ack = packet({{0xF1, {0x01, 0x00}}});
    bytes.insert(bytes.end(), ack.begin(), ack.end());
    f.feed(bytes, 5);
    codec_session_poll(&f.s, 105); // not expired yet (105 - 5 = P)
    EXPECT_TRUE(f.log.lines.empty());
    codec_session_poll(&f.s, 106);
    EXPECT_EQ(f.log.lines, (std::vector<std::string>{"skip 0+" + H, "ack 1 code 0"}));
    EXPECT_EQ(codec_session_pending(&f.s), 0u);
    uint64_t d = 0;
    EXPECT_FALSE(codec_session_next_deadline(&f.s, &d));
}

// Without a poll at the wake-up, the next feed runs the rule on the old buffer first (a): the same
// events, and the new bytes are parsed after the ACK.
TEST(Session, LookAheadBeforeTheNewBytesIsTheSameAsAPoll) {
    Fixture f;
    f.start(ping(), 0, 1);
    std::vector<uint8_t> bytes = false_sync();
    std::vector<uint8_t> ack = packet({{0xF1, {0x01, 0x00}}});
    bytes.insert(bytes.end(), ack.begin(), ack.end());
    f.feed(bytes, 5);
    f.feed(packet({{0x02, {0x00, 0x01}}}), 300);
    EXPECT_EQ(f.log.lines,
              (std::vector<std::string>{"skip 0+" + H, "ack 1 code 0",
                                        "packet " + std::to_string(CODEC_HEADER_SIZE + ack.size())}));
}

// A slow reply: half of it, then nothing for far longer than P, then the rest: kept waiting and
// acknowledged (the old timed rule dropped it).
TEST(Session, LookAheadKeepsASlowReply) {
    Fixture f;
    f.start(ping(), 0, 1);
    std::vector<uint8_t> ack = packet({{0xF1, {0x01, 0x00}}});
    f.feed(std::vector<uint8_t>(ack.begin(), ack.begin() + 5), 5);
    uint64_t d = 0;
    while (codec_session_next_deadline(&f.s, &d) && d <= 300) {
        codec_session_poll(&f.s, d);
    }
    EXPECT_TRUE(f.log.lines.empty());
    f.feed(std::vector<uint8_t>(ack.begin() + 5, ack.end()), 300);
    EXPECT_EQ(f.log.lines, (std::vector<std::string>{"ack 1 code 0"}));
}

// (b): the wait at offset 0 expired long ago; the ACK arrives behind it at 300 ms and the
// look-ahead after the new bytes finds it. A new wait (the packet cut at the end) starts at 300.
TEST(Session, LookAheadAfterTheNewBytes) {
    Fixture f;
    f.start(ping(), 0, 1);
    f.feed(false_sync(), 5);
    codec_session_poll(&f.s, 106);
    std::vector<uint8_t> ack = packet({{0xF1, {0x01, 0x00}}});
    std::vector<uint8_t> more = ack;
    more.push_back(CODEC_SYNC_0);
    f.feed(more, 300);
    EXPECT_EQ(f.log.lines, (std::vector<std::string>{"skip 0+" + H, "ack 1 code 0"}));
    uint64_t d = 0;
    ASSERT_TRUE(codec_session_next_deadline(&f.s, &d));
    EXPECT_EQ(d, 401u);
    EXPECT_EQ(f.s.wait_at, CODEC_HEADER_SIZE + ack.size());
}

// A wake-up after an expired check: the look-ahead jumps to a packet whose successor is a new
// partial packet; that new wait begins at the time of the jump, so the next wake-up is P + 1 later.
TEST(Session, WakeUpAfterAnExpiredCheck) {
    Fixture f;
    std::vector<uint8_t> bytes = false_sync();
    std::vector<uint8_t> data = packet({{0x02, {0x00, 0x01}}});
    bytes.insert(bytes.end(), data.begin(), data.end());
    std::vector<uint8_t> second = false_sync(); // a second false sync
    bytes.insert(bytes.end(), second.begin(), second.end());
    f.feed(bytes, 10);
    uint64_t d = 0;
    ASSERT_TRUE(codec_session_next_deadline(&f.s, &d));
    EXPECT_EQ(d, 111u);
    codec_session_poll(&f.s, 111);
    EXPECT_EQ(f.log.lines, (std::vector<std::string>{"skip 0+" + H, "packet " + H}));
    ASSERT_TRUE(codec_session_next_deadline(&f.s, &d));
    EXPECT_EQ(d, 212u); // the wait at the second false sync began at 111
    codec_session_poll(&f.s, 212);
    EXPECT_FALSE(codec_session_next_deadline(&f.s, &d)); // expired, nothing after it: no wake-up
    codec_session_close(&f.s, 300);
    EXPECT_EQ(f.log.lines, (std::vector<std::string>{
                               "skip 0+" + H, "packet " + H,
                               "skip " + std::to_string(CODEC_HEADER_SIZE + data.size()) + "+" + H}));
}

// Skip runs in pieces: noise is reported as runs of exactly CODEC_SESSION_SKIP_PIECE bytes as soon
// as the pending run reaches that length, whatever the chunks; the rest at the next packet.
TEST(Session, SkipRunsInPiecesOf65536) {
    ASSERT_EQ(CODEC_SESSION_SKIP_PIECE, 65536u);
    for (size_t chunk : {size_t(1000), size_t(65536), size_t(70000), size_t(200000)}) {
        Fixture f;
        std::vector<uint8_t> noise(2 * 65536 + 10, 0x00);
        for (size_t pos = 0; pos < noise.size(); pos += chunk) {
            size_t n = std::min(chunk, noise.size() - pos);
            f.feed(std::vector<uint8_t>(noise.begin() + pos, noise.begin() + pos + n), 1);
            if (pos + n >= 65536 && pos < 65536) {
                // reported in the call where the run reached 65536 bytes
                ASSERT_FALSE(f.log.lines.empty()) << chunk;
                EXPECT_EQ(f.log.lines[0], "skip 0+65536") << chunk;
            }
        }
        EXPECT_EQ(f.log.lines, (std::vector<std::string>{"skip 0+65536", "skip 65536+65536"})) << chunk;
        f.feed(packet({{0x02, {0x00, 0x01}}}), 2);
        EXPECT_EQ(f.log.lines, (std::vector<std::string>{"skip 0+65536", "skip 65536+65536", "skip 131072+10",
                                                         "packet 131082"}))
            << chunk;
    }
}

// False syncs (75 65 01 F0 repeated) are skipped one byte at a time by the buffered path: the
// pieces are exactly 65536 bytes there too, and the parser never holds more than a packet.
TEST(Session, SkipPiecesOfRepeatedFalseSyncs) {
    Fixture f;
    std::vector<uint8_t> chunk;
    for (int i = 0; i < 1024; ++i) {
        {
            std::vector<uint8_t> fs = false_sync();
            chunk.insert(chunk.end(), fs.begin(), fs.end());
        }
    }
    uint64_t now = 0;
    for (int i = 0; i < 40; ++i) { // 160 KiB
        f.feed(chunk, now);
        now += 1;
        EXPECT_LE(f.s.parser.used, (size_t)CODEC_MAX_PACKET);
        EXPECT_LT(f.s.parser.skip_count, 65536u);
    }
    std::vector<std::string> pieces;
    for (size_t k = 0; k < 40 * chunk.size() / 65536; ++k) {
        pieces.push_back("skip " + std::to_string(k * 65536) + "+65536");
    }
    EXPECT_EQ(f.log.lines, pieces);
}

// The decoder's parser (skip_piece 0) still reports one run.
TEST(Parser, SkipRunWholeWithoutPieces) {
    codec_parser_t p;
    codec_parser_init(&p);
    std::vector<std::string> got;
    auto fn = [](void *ctx, const codec_event_t *ev) {
        static_cast<std::vector<std::string> *>(ctx)->push_back(std::to_string(ev->offset) + "+" +
                                                                std::to_string(ev->length));
    };
    std::vector<uint8_t> noise(200000, 0x00);
    codec_parser_feed(&p, noise.data(), noise.size(), fn, &got);
    codec_parser_flush(&p, fn, &got);
    EXPECT_EQ(got, (std::vector<std::string>{"0+200000"}));
}

TEST(Session, RefusalsSuppressionAndFullQueue) {
    Fixture f(CODEC_DEVICE_BETA, 1);
    codec_field_value_t alpha;
    memset(&alpha, 0, sizeof alpha);
    alpha.id = CODEC_FIELD_CONTROL_RATE_ALPHA;
    codec_started_t st = f.start(alpha, 0, 1);
    EXPECT_TRUE(st.done);
    EXPECT_EQ(st.packet_len, 0u);
    EXPECT_EQ(st.result.kind, CODEC_RESULT_REFUSED);
    EXPECT_STREQ(st.result.error, "rate: this layout is for alpha, not beta");
    codec_field_value_t beta;
    memset(&beta, 0, sizeof beta);
    beta.id = CODEC_FIELD_CONTROL_RATE_BETA;
    st = f.start(beta, 0, 2);
    EXPECT_TRUE(st.done);
    EXPECT_GT(st.packet_len, 0u);
    EXPECT_EQ(st.result.kind, CODEC_RESULT_SENT);
    beta.u.control_rate_beta.hz = 10;
    st = f.start(beta, 0, 3);
    EXPECT_FALSE(st.done);
    st = f.start(ping(), 0, 4);
    EXPECT_EQ(st.result.kind, CODEC_RESULT_REFUSED);
    EXPECT_STREQ(st.result.error, "1 commands already pending");
    // The ack comes without the expected reply field 0x84: invalid.
    f.feed(packet({{0xF1, {0x04, 0x00}}}), 5);
    EXPECT_EQ(f.log.lines, (std::vector<std::string>{"invalid 3 code 0 missing reply field 132"}));
}

// A transport over two byte queues and a fake clock: the device answers each ping at once.
struct Loop {
    std::vector<uint8_t> to_device;
    std::vector<uint8_t> to_host;
    uint64_t now = 0;
};

int loop_read(void *ctx, uint8_t *buf, size_t cap, uint32_t timeout_ms) {
    Loop *l = static_cast<Loop *>(ctx);
    if (l->to_host.empty()) {
        l->now += timeout_ms;
        return 0;
    }
    size_t n = l->to_host.size() < cap ? l->to_host.size() : cap;
    memcpy(buf, l->to_host.data(), n);
    l->to_host.erase(l->to_host.begin(), l->to_host.begin() + static_cast<long>(n));
    return static_cast<int>(n);
}

int loop_write(void *ctx, const uint8_t *data, size_t len) {
    Loop *l = static_cast<Loop *>(ctx);
    l->to_device.insert(l->to_device.end(), data, data + len);
    std::vector<uint8_t> ack =
        packet({{0xF1, {data[CODEC_HEADER_SIZE + CODEC_FIELD_DESCRIPTOR_OFFSET], 0x00}}});
    l->to_host.insert(l->to_host.end(), ack.begin(), ack.end());
    return 0;
}

uint64_t loop_now(void *ctx) {
    return static_cast<Loop *>(ctx)->now;
}

TEST(Link, RunsACommandOverATransport) {
    Loop loop;
    codec_transport_t t{&loop, loop_read, loop_write, loop_now};
    codec_session_config_t c;
    codec_session_config_init(&c);
    static codec_link_t link;
    ASSERT_EQ(codec_link_init(&link, &t, &c), CODEC_OK);
    codec_field_value_t v = ping();
    codec_result_t r;
    EXPECT_EQ(codec_link_run(&link, &v, NULL, &r), CODEC_RESULT_ACK);
    EXPECT_FALSE(loop.to_device.empty());
    // A device that never answers: a timeout after T.
    t.write = [](void *, const uint8_t *, size_t) { return 0; };
    ASSERT_EQ(codec_link_init(&link, &t, &c), CODEC_OK);
    uint64_t before = loop.now;
    EXPECT_EQ(codec_link_run(&link, &v, NULL, &r), CODEC_RESULT_TIMEOUT);
    EXPECT_EQ(loop.now - before, 1000u);
}

// Listening wakes at the session's next wake-up: a false sync with a data packet behind it is
// resolved by the look-ahead at s + P + 1, not at the end of the listening time.
struct Timed {
    Loop *loop;
    std::vector<std::string> lines;
};

TEST(Link, ListenWakesForTheLookAhead) {
    Loop loop;
    codec_transport_t t{&loop, loop_read, loop_write, loop_now};
    codec_session_config_t c;
    codec_session_config_init(&c);
    Timed timed{&loop, {}};
    c.on_event = [](void *ctx, const codec_session_event_t *ev) {
        Timed *tm = static_cast<Timed *>(ctx);
        tm->lines.push_back((ev->kind == CODEC_SESSION_SKIP ? "skip at " : "packet at ") +
                            std::to_string(tm->loop->now));
    };
    c.ctx = &timed;
    static codec_link_t link;
    ASSERT_EQ(codec_link_init(&link, &t, &c), CODEC_OK);
    loop.to_host = false_sync();
    std::vector<uint8_t> data = packet({{0x02, {0x00, 0x01}}});
    loop.to_host.insert(loop.to_host.end(), data.begin(), data.end());
    EXPECT_EQ(codec_link_listen(&link, 1000), 0);
    EXPECT_EQ(timed.lines, (std::vector<std::string>{"skip at 101", "packet at 101"}));
}

} // namespace
