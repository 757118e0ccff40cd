// Getting through (src/link.c, docs/conformance.md section 8 "Getting through") on the rendered
// test protocol (tests/runtime_specs/: its link section names ping, alpha's main port 9600, 115200
// (default), 921600 baud, 3 idle attempts by default; it has no idle command: these tests give the
// ping its place through the options): to idle while the device streams, the baud rate found, a
// lost port reopened with the configuration re-sent, and the log lines. A fake device over a fake clock:
// every read of a streaming device returns one data packet 10 ms later.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

extern "C" {
#include "codec/link.h"
}

namespace {

std::vector<uint8_t> build(uint8_t set, uint8_t descriptor, std::vector<uint8_t> data) {
    uint8_t buf[CODEC_MAX_PACKET];
    size_t n = 0;
    codec_packet_builder_t b;
    codec_packet_begin(&b, buf, sizeof buf, set);
    codec_packet_add_field(&b, descriptor, data.data(), data.size());
    EXPECT_EQ(codec_packet_finish(&b, &n), CODEC_OK);
    return std::vector<uint8_t>(buf, buf + n);
}

// A data packet of the sensor set (reading: count, offset, valid).
std::vector<uint8_t> data_packet() {
    return build(0x80, 0x01, {0x01, 0x00, 0x00, 0x01});
}

struct Device {
    std::vector<uint8_t> to_host;
    std::vector<std::vector<uint8_t>> commands; // every packet the host wrote
    uint64_t now = 0;
    bool streaming = false;
    int unanswered = 0;      // commands left that get no reply
    uint32_t answers_at = 0; // the only baud rate the device answers at (0: any)
    uint32_t baud = 115200;  // the host side's rate
    bool lost = false;       // the port is gone
    int reopen_failures = 0; // reopens that fail before one succeeds
    int flushes = 0;
    std::vector<uint32_t> sleeps;
    std::vector<std::string> log;
    int events = 0; // events the application saw
    int packets = 0;
};

int dev_read(void *ctx, uint8_t *buf, size_t cap, uint32_t timeout_ms) {
    Device *d = static_cast<Device *>(ctx);
    if (d->lost) {
        return -1;
    }
    if (d->to_host.empty() && d->streaming) {
        std::vector<uint8_t> p = data_packet();
        d->to_host.insert(d->to_host.end(), p.begin(), p.end());
        d->now += 10;
    }
    if (d->to_host.empty()) {
        d->now += timeout_ms;
        return 0;
    }
    size_t n = d->to_host.size() < cap ? d->to_host.size() : cap;
    memcpy(buf, d->to_host.data(), n);
    d->to_host.erase(d->to_host.begin(), d->to_host.begin() + static_cast<long>(n));
    return static_cast<int>(n);
}

int dev_write(void *ctx, const uint8_t *data, size_t len) {
    Device *d = static_cast<Device *>(ctx);
    if (d->lost) {
        return -1;
    }
    d->commands.emplace_back(data, data + len);
    if ((d->answers_at != 0 && d->baud != d->answers_at) || d->unanswered-- > 0) {
        return 0;
    }
    const uint8_t descriptor = data[CODEC_HEADER_SIZE + CODEC_FIELD_DESCRIPTOR_OFFSET];
    if (descriptor == CODEC_LINK_PING_DESCRIPTOR) { /* the idle command of these tests */
        d->streaming = false;
    }
    std::vector<uint8_t> ack = build(0x01, 0xF1, {descriptor, 0x00});
    d->to_host.insert(d->to_host.end(), ack.begin(), ack.end());
    return 0;
}

uint64_t dev_now(void *ctx) {
    return static_cast<Device *>(ctx)->now;
}

int dev_flush(void *ctx) {
    Device *d = static_cast<Device *>(ctx);
    d->flushes++;
    d->to_host.clear();
    return 0;
}

int dev_set_baud(void *ctx, uint32_t baud) {
    static_cast<Device *>(ctx)->baud = baud;
    return 0;
}

int dev_reopen(void *ctx) {
    Device *d = static_cast<Device *>(ctx);
    if (d->reopen_failures-- > 0) {
        return -1;
    }
    d->lost = false;
    return 0;
}

const char *dev_address(void *) {
    return "/tmp/x/dev";
}

const char *dev_reason(void *) {
    return "Input/output error";
}

void dev_sleep(void *ctx, uint32_t ms) {
    Device *d = static_cast<Device *>(ctx);
    d->sleeps.push_back(ms);
    d->now += ms;
}

void dev_log(void *ctx, const char *line) {
    static_cast<Device *>(ctx)->log.push_back(line);
}

void dev_event(void *ctx, const codec_session_event_t *ev) {
    Device *d = static_cast<Device *>(ctx);
    d->events++;
    if (ev->kind == CODEC_SESSION_PACKET) {
        d->packets++;
    }
}

struct Fixture {
    Device dev;
    codec_link_t link;
    codec_port_t port;
    explicit Fixture(uint32_t reconnect_ms = CODEC_LINK_DEFAULT_RECONNECT_MS) {
        codec_transport_t t{&dev, dev_read, dev_write, dev_now};
        codec_session_config_t c;
        codec_session_config_init(&c);
        c.device = CODEC_DEVICE_ALPHA;
        c.on_event = dev_event;
        c.ctx = &dev;
        EXPECT_EQ(codec_link_init(&link, &t, &c), CODEC_OK);
        memset(&port, 0, sizeof port);
        port.ctx = &dev;
        port.flush = dev_flush;
        port.set_baud = dev_set_baud;
        port.reopen = dev_reopen;
        port.address = dev_address;
        port.reason = dev_reason;
        port.sleep_ms = dev_sleep;
        port.baud = 115200;
        codec_link_options_t o;
        codec_link_options_init(&o);
        o.log = dev_log;
        o.log_ctx = &dev;
        o.reconnect_ms = reconnect_ms;
        o.idle = o.ping; // the ping in the idle command's place
        codec_link_attach(&link, &port, &o);
    }
};

codec_field_value_t command(uint8_t descriptor, std::vector<uint8_t> data) {
    codec_field_value_t v;
    EXPECT_EQ(codec_decode_field(0x01, descriptor, data.data(), data.size(), CODEC_DEVICE_ALPHA, &v, NULL),
              CODEC_OK);
    return v;
}

TEST(LinkGettingThrough, IdleWhileStreaming) {
    static Fixture f;
    f.dev.streaming = true;
    f.dev.unanswered = 2;
    EXPECT_EQ(codec_link_to_idle(&f.link), CODEC_RESULT_ACK);
    // Each unanswered attempt waits T = 1000 ms: the packets read at 10, 20, ... 1000 ms are
    // dropped (the last one after the timeout, in the same read): 100 packets (12 bytes in framing
    // a, 13 with framing b's 3 sync bytes).
    const std::string dropped = std::to_string(100 * data_packet().size());
    EXPECT_EQ(f.dev.log, (std::vector<std::string>{
                             "link: idle: no ACK in 1000 ms while streaming (" + dropped +
                                 " bytes dropped), flushing, attempt 2 of 3",
                             "link: idle: no ACK in 1000 ms while streaming (" + dropped +
                                 " bytes dropped), flushing, attempt 3 of 3",
                             "link: idle: ACK on attempt 3 of 3 (0 bytes dropped)",
                         }));
    EXPECT_EQ(f.dev.commands.size(), 3u);
    EXPECT_EQ(f.dev.flushes, 4); // before and after the quiet time, twice
    EXPECT_EQ(f.dev.events, 0);  // the application saw none of it
    EXPECT_FALSE(f.dev.streaming);
    // The application's data flows again afterwards.
    f.dev.streaming = true;
    EXPECT_EQ(codec_link_listen(&f.link, 100), 0);
    EXPECT_GT(f.dev.packets, 0);
}

TEST(LinkGettingThrough, IdleGivesUpAfterTheAttempts) {
    static Fixture f;
    f.dev.unanswered = 100;
    EXPECT_EQ(codec_link_to_idle(&f.link), CODEC_RESULT_TIMEOUT);
    EXPECT_EQ(f.dev.commands.size(), (size_t)CODEC_LINK_IDLE_ATTEMPTS);
    EXPECT_EQ(f.dev.log, (std::vector<std::string>{"link: idle: no ACK in 1000 ms, flushing, attempt 2 of 3",
                                                   "link: idle: no ACK in 1000 ms, flushing, attempt 3 of 3",
                                                   "link: idle: no ACK after 3 attempts, giving up"}));
}

TEST(LinkGettingThrough, FindsTheBaudRate) {
    static Fixture f;
    f.dev.answers_at = 921600;
    EXPECT_EQ(codec_link_find_baud(&f.link), CODEC_RESULT_ACK);
    // The configured 115200 is also alpha's default: next the highest, 921600.
    EXPECT_EQ(f.dev.log, (std::vector<std::string>{"link: baud: no answer at 115200, trying 921600",
                                                   "link: baud: device answers at 921600"}));
    EXPECT_EQ(f.dev.baud, 921600u);
    EXPECT_EQ(f.link.port.baud, 921600u);
    EXPECT_EQ(f.dev.flushes, 1); // after switching
}

TEST(LinkGettingThrough, BaudSearchTriesEveryRateOnce) {
    static Fixture f;
    f.dev.answers_at = 1; // never
    EXPECT_EQ(codec_link_find_baud(&f.link), CODEC_RESULT_TIMEOUT);
    EXPECT_EQ(f.dev.log, (std::vector<std::string>{"link: baud: no answer at 115200, trying 921600",
                                                   "link: baud: no answer at 921600, trying 9600",
                                                   "link: baud: no answer at any rate"}));
    EXPECT_EQ(f.dev.commands.size(), 3u);
}

TEST(LinkGettingThrough, NoBaudSearchWithoutABaudRate) {
    static Fixture f;
    f.link.port.set_baud = NULL; // TCP
    f.dev.answers_at = 1;
    EXPECT_EQ(codec_link_find_baud(&f.link), CODEC_RESULT_TIMEOUT);
    EXPECT_TRUE(f.dev.log.empty());
    EXPECT_EQ(f.dev.commands.size(), 1u);
}

TEST(LinkGettingThrough, ReconnectsAndReappliesTheConfiguration) {
    static Fixture f;
    codec_field_value_t gain = command(0x03, {0x01, 0x07, 0x00}); // write gain 7
    codec_field_value_t read = command(0x03, {0x02});             // read: not recorded
    EXPECT_EQ(codec_link_run(&f.link, &gain, NULL, NULL), CODEC_RESULT_ACK);
    codec_link_run(&f.link, &read, NULL, NULL);
    EXPECT_EQ(f.link.setting_count, 1u);
    std::vector<uint8_t> written = f.dev.commands[0];
    f.dev.commands.clear();
    f.dev.lost = true;
    f.dev.reopen_failures = 2;
    codec_field_value_t ping = command(0x01, {});
    codec_result_t r;
    EXPECT_EQ(codec_link_run(&f.link, &ping, NULL, &r), CODEC_RESULT_LOST);
    EXPECT_STREQ(r.error, "link lost: Input/output error");
    EXPECT_TRUE(f.link.connected);
    // Reopened at 0, 500 and 1000 ms (the third succeeds), then to idle and the write again (the
    // test protocol has no resume command).
    EXPECT_EQ(f.dev.log, (std::vector<std::string>{
                             "link: port lost (Input/output error), reopening /tmp/x/dev every 500 ms",
                             "link: idle: ACK on attempt 1 of 3 (0 bytes dropped)",
                             "link: reconnected after 1.0 s, re-applied 1 settings"}));
    ASSERT_EQ(f.dev.commands.size(), 2u);
    EXPECT_EQ(f.dev.commands[0][CODEC_HEADER_SIZE + CODEC_FIELD_DESCRIPTOR_OFFSET],
              CODEC_LINK_PING_DESCRIPTOR);
    EXPECT_EQ(f.dev.commands[1], written);
    EXPECT_EQ(codec_link_run(&f.link, &ping, NULL, NULL), CODEC_RESULT_ACK); // and on it goes
}

TEST(LinkGettingThrough, TheLatestWriteOfASettingWins) {
    static Fixture f;
    codec_field_value_t gain7 = command(0x03, {0x01, 0x07, 0x00});
    codec_field_value_t gain9 = command(0x03, {0x01, 0x09, 0x00});
    EXPECT_EQ(codec_link_run(&f.link, &gain7, NULL, NULL), CODEC_RESULT_ACK);
    EXPECT_EQ(codec_link_run(&f.link, &gain9, NULL, NULL), CODEC_RESULT_ACK);
    EXPECT_EQ(codec_link_run(&f.link, &gain9, NULL, NULL), CODEC_RESULT_ACK);
    // gain's read sends no parameter: one key, the latest write.
    ASSERT_EQ(f.link.setting_count, 1u);
    EXPECT_EQ(f.link.settings[0].key_len, 0u);
    EXPECT_EQ(f.link.settings[0].data[1], 0x09);
}

TEST(LinkGettingThrough, GivesUpWhenThePortStaysAway) {
    static Fixture f(1200);
    f.dev.lost = true;
    f.dev.reopen_failures = 100;
    codec_field_value_t ping = command(0x01, {});
    EXPECT_EQ(codec_link_run(&f.link, &ping, NULL, NULL), CODEC_RESULT_LOST);
    EXPECT_FALSE(f.link.connected);
    // Reopened at 0, 500 and 1000 ms: another 500 ms would be past the 1200 ms.
    ASSERT_EQ(f.dev.log.size(), 2u);
    EXPECT_EQ(f.dev.log[1], "link: gave up reopening /tmp/x/dev after 1200 ms");
    EXPECT_EQ(f.dev.sleeps, (std::vector<uint32_t>{500, 500}));
    EXPECT_EQ(codec_link_listen(&f.link, 10), -1);
}

TEST(LinkGettingThrough, WithoutAnIdleCommandToIdleIsRefused) {
    static Fixture f;
    codec_link_options_t o;
    codec_link_options_init(&o);
    EXPECT_FALSE(o.idle.present); // the test protocol names none
    o.log = dev_log;
    o.log_ctx = &f.dev;
    codec_link_attach(&f.link, &f.port, &o);
    EXPECT_EQ(codec_link_to_idle(&f.link), CODEC_RESULT_REFUSED);
    EXPECT_STREQ(f.link.result.error, "the protocol has no idle command");
    EXPECT_EQ(f.dev.log, (std::vector<std::string>{"link: idle: the protocol has no idle command"}));
    EXPECT_TRUE(f.dev.commands.empty());
}

TEST(LinkGettingThrough, NoReconnectWithoutTheOption) {
    static Fixture f(0);
    f.dev.lost = true;
    codec_field_value_t ping = command(0x01, {});
    EXPECT_EQ(codec_link_run(&f.link, &ping, NULL, NULL), CODEC_RESULT_TRANSPORT);
    EXPECT_FALSE(f.link.connected);
    EXPECT_TRUE(f.dev.log.empty());
}

} // namespace
