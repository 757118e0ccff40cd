// The session core (src/session.c) and the blocking link (src/link.c), on the rendered test
// protocol (tests/runtime_specs/: ping on every device; rate per device, alpha's reply allowed hz
// ms more, beta's answered with the reply field 0x84 unless hz is 0, which suppresses its ack):
// matching, timeouts, the timed inter-packet rule, refusals, ack suppression, the pending queue. The corpus
// (tests/sessions/) runs in every package's suite.
#include <gtest/gtest.h>

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

TEST(Session, TimedRuleDropsAFalseSync) {
    Fixture f;
    f.start(ping(), 0, 1);
    std::vector<uint8_t> stale = {CODEC_SYNC_0};
    f.feed(stale, 0);
    uint64_t d = 0;
    ASSERT_TRUE(codec_session_next_deadline(&f.s, &d));
    EXPECT_EQ(d, 101u);
    codec_session_poll(&f.s, 101);
    f.feed(packet({{0xF1, {0x01, 0x00}}}), 102);
    EXPECT_EQ(f.log.lines, (std::vector<std::string>{"skip 0+1", "ack 1 code 0"}));
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

} // namespace
