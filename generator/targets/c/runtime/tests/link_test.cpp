// Getting through (src/link.c, docs/conformance.md section 8 "Getting through") on the rendered
// test protocol (tests/runtime_specs/): the link corpus tests/link/cases.txt (its path LINK_CASES
// from CMakeLists.txt; the format and the fake device's rules in tests/link/README.md), as the C++
// and Python runtimes run it, then the cases of this API only. The test protocol has no idle
// command: a case gives the ping its place through the options unless it says `set idle none`.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>
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
    bool has_baud = true;    // false: a port without a baud rate (TCP)
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
    explicit Fixture(uint32_t reconnect_ms = CODEC_LINK_DEFAULT_RECONNECT_MS,
                     codec_device_t device = CODEC_DEVICE_ALPHA, uint32_t baud = 115200,
                     bool ping_as_idle = true) {
        dev.baud = baud;
        codec_transport_t t{&dev, dev_read, dev_write, dev_now};
        codec_session_config_t c;
        codec_session_config_init(&c);
        c.device = device;
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
        port.baud = baud;
        codec_link_options_t o;
        codec_link_options_init(&o);
        o.log = dev_log;
        o.log_ctx = &dev;
        o.reconnect_ms = reconnect_ms;
        if (ping_as_idle) {
            o.idle = o.ping; // the ping in the idle command's place
        }
        codec_link_attach(&link, &port, &o);
    }
};

struct LinkCase {
    std::string name;
    std::vector<std::pair<std::string, std::string>> set;
    std::vector<std::vector<std::string>> steps;
    std::vector<std::string> log;
    std::vector<std::pair<std::string, std::string>> expect;
};

std::vector<std::string> words(const std::string &text) {
    std::istringstream in(text);
    std::vector<std::string> out;
    std::string w;
    while (in >> w) {
        out.push_back(w);
    }
    return out;
}

std::vector<LinkCase> read_cases() {
    std::ifstream in(LINK_CASES);
    EXPECT_TRUE(in.good()) << LINK_CASES;
    std::vector<LinkCase> cases;
    LinkCase c;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') {
            continue;
        }
        const size_t space = line.find(' ');
        const std::string what = line.substr(0, space);
        const std::string rest = space == std::string::npos ? "" : line.substr(space + 1);
        if (what == "case") {
            c = LinkCase();
            c.name = rest;
        } else if (what == "set") {
            const size_t sp = rest.find(' ');
            c.set.emplace_back(rest.substr(0, sp), sp == std::string::npos ? "" : rest.substr(sp + 1));
        } else if (what == "step") {
            c.steps.push_back(words(rest));
        } else if (what == "log") {
            c.log.push_back(rest);
        } else if (what == "end") {
            cases.push_back(c);
        } else {
            c.expect.emplace_back(what, rest);
        }
    }
    return cases;
}

// {data N} and {ack N}: N data or ACK packets' bytes.
std::string expanded(std::string line) {
    for (const char *what : {"{data ", "{ack "}) {
        size_t at;
        while ((at = line.find(what)) != std::string::npos) {
            const size_t close = line.find('}', at);
            const size_t n = std::stoul(line.substr(at + strlen(what), close - at - strlen(what)));
            const size_t size =
                what[1] == 'd' ? data_packet().size() : build(0x01, 0xF1, {0x01, 0x00}).size();
            line.replace(at, close - at + 1, std::to_string(n * size));
        }
    }
    return line;
}

codec_field_value_t gain_command(codec_function_t function, bool has_gain, uint16_t gain) {
    codec_field_value_t v;
    memset(&v, 0, sizeof v);
    v.id = CODEC_FIELD_CONTROL_GAIN;
    v.u.control_gain.function = function;
    v.u.control_gain.has_gain = has_gain;
    v.u.control_gain.gain = gain;
    return v;
}

codec_field_value_t ping_command() {
    codec_field_value_t v;
    memset(&v, 0, sizeof v);
    v.id = CODEC_FIELD_CONTROL_PING;
    return v;
}

codec_field_value_t token_command(const std::string &token) {
    if (token == "ping") {
        return ping_command();
    }
    if (token == "read") {
        return gain_command(CODEC_FUNCTION_READ, false, 0);
    }
    return gain_command(CODEC_FUNCTION_WRITE, true, static_cast<uint16_t>(std::stoul(token.substr(6))));
}

std::vector<uint8_t> token_packet(const std::string &token) {
    const codec_field_value_t v = token_command(token);
    uint8_t data[CODEC_MAX_FIELD_DATA];
    size_t n = 0;
    EXPECT_EQ(codec_encode_field(&v, data, sizeof data, &n), CODEC_OK);
    return build(0x01, token == "ping" ? 0x01 : 0x03, std::vector<uint8_t>(data, data + n));
}

std::string kind_name(codec_result_kind_t kind) {
    switch (kind) {
    case CODEC_RESULT_ACK:
        return "ack";
    case CODEC_RESULT_NACK:
        return "nack";
    case CODEC_RESULT_TIMEOUT:
        return "timeout";
    case CODEC_RESULT_INVALID:
        return "invalid";
    case CODEC_RESULT_SENT:
        return "sent";
    case CODEC_RESULT_REFUSED:
        return "refused";
    case CODEC_RESULT_TRANSPORT:
        return "error";
    case CODEC_RESULT_LOST:
        return "lost";
    }
    return "?";
}

std::string run_step(Fixture &f, const std::vector<std::string> &step) {
    const std::string &what = step[0];
    if (what == "to_idle") {
        return kind_name(codec_link_to_idle(&f.link));
    }
    if (what == "find_baud") {
        const codec_result_kind_t kind = codec_link_find_baud(&f.link);
        return kind == CODEC_RESULT_ACK ? "ack" : kind == CODEC_RESULT_TIMEOUT ? "fail" : kind_name(kind);
    }
    if (what == "listen") {
        return codec_link_listen(&f.link, static_cast<uint32_t>(std::stoul(step[1]))) == 0 ? "ok" : "fail";
    }
    const codec_field_value_t command = token_command(what == "write" ? "write:" + step[1] : what);
    return kind_name(codec_link_run(&f.link, &command, NULL, NULL));
}

void run_case(const LinkCase &c) {
    uint32_t reconnect = CODEC_LINK_DEFAULT_RECONNECT_MS;
    uint32_t baud = 115200;
    codec_device_t device = CODEC_DEVICE_ALPHA;
    bool ping_as_idle = true;
    bool tcp = false;
    for (const auto &s : c.set) {
        if (s.first == "reconnect") {
            reconnect = s.second == "off" ? 0 : static_cast<uint32_t>(std::stoul(s.second));
        } else if (s.first == "baud") {
            tcp = s.second == "none";
            baud = tcp ? 115200 : static_cast<uint32_t>(std::stoul(s.second));
        } else if (s.first == "model") {
            device = s.second == "beta" ? CODEC_DEVICE_BETA : s.second == "none" ? CODEC_DEVICE_ANY : device;
        } else if (s.first == "idle") {
            ping_as_idle = s.second != "none";
        }
    }
    std::unique_ptr<Fixture> f(new Fixture(reconnect, device, baud, ping_as_idle));
    if (tcp) {
        f->link.port.set_baud = NULL;
        f->dev.has_baud = false;
    }
    for (const auto &s : c.set) {
        if (s.first == "streaming") {
            f->dev.streaming = true;
        } else if (s.first == "unanswered") {
            f->dev.unanswered = std::stoi(s.second);
        } else if (s.first == "answers_at") {
            f->dev.answers_at = static_cast<uint32_t>(std::stoul(s.second));
        }
    }
    for (const auto &step : c.steps) {
        SCOPED_TRACE(step[0]);
        if (step[0] == "lose") {
            f->dev.lost = true;
            f->dev.reopen_failures = std::stoi(step[1]);
        } else if (step[0] == "stream") {
            f->dev.streaming = true;
        } else {
            const std::string got = run_step(*f, step);
            if (step.back() != "any") {
                EXPECT_EQ(got, step.back());
            }
        }
    }
    std::vector<std::string> log;
    for (const auto &line : c.log) {
        log.push_back(expanded(line));
    }
    EXPECT_EQ(f->dev.log, log);
    for (const auto &e : c.expect) {
        SCOPED_TRACE(e.first);
        if (e.first == "sent") {
            std::vector<std::vector<uint8_t>> sent;
            for (const auto &token : words(e.second)) {
                sent.push_back(token_packet(token));
            }
            EXPECT_EQ(f->dev.commands, sent);
        } else if (e.first == "flushes") {
            EXPECT_EQ(f->dev.flushes, std::stoi(e.second));
        } else if (e.first == "packets") {
            EXPECT_EQ(f->dev.packets, std::stoi(e.second));
        } else if (e.first == "sleeps") {
            std::vector<uint32_t> sleeps;
            for (const auto &ms : words(e.second)) {
                sleeps.push_back(static_cast<uint32_t>(std::stoul(ms)));
            }
            EXPECT_EQ(f->dev.sleeps, sleeps);
        } else if (e.first == "rate") {
            EXPECT_EQ(tcp ? std::string("none") : std::to_string(f->dev.baud), e.second);
        } else {
            ADD_FAILURE() << "unknown line " << e.first;
        }
    }
}

TEST(LinkGettingThrough, TheLinkCorpus) {
    const std::vector<LinkCase> cases = read_cases();
    ASSERT_GE(cases.size(), 10u);
    for (const LinkCase &c : cases) {
        SCOPED_TRACE(c.name);
        run_case(c);
    }
}

// The cases of this API only.

TEST(LinkGettingThrough, TheLinkStateAfterALoss) {
    static Fixture f(1200);
    f.dev.lost = true;
    f.dev.reopen_failures = 100;
    codec_field_value_t ping = ping_command();
    codec_result_t r;
    EXPECT_EQ(codec_link_run(&f.link, &ping, NULL, &r), CODEC_RESULT_LOST);
    EXPECT_STREQ(r.error, "link lost: Input/output error");
    EXPECT_FALSE(f.link.connected);
    EXPECT_EQ(codec_link_listen(&f.link, 10), -1);
    static Fixture g(0);
    g.dev.lost = true;
    EXPECT_EQ(codec_link_run(&g.link, &ping, NULL, NULL), CODEC_RESULT_TRANSPORT);
    EXPECT_FALSE(g.link.connected);
}

TEST(LinkGettingThrough, TheLatestWriteIsTheOneRecorded) {
    static Fixture f;
    codec_field_value_t gain7 = gain_command(CODEC_FUNCTION_WRITE, true, 7);
    codec_field_value_t gain9 = gain_command(CODEC_FUNCTION_WRITE, true, 9);
    EXPECT_EQ(codec_link_run(&f.link, &gain7, NULL, NULL), CODEC_RESULT_ACK);
    EXPECT_EQ(codec_link_run(&f.link, &gain9, NULL, NULL), CODEC_RESULT_ACK);
    // gain's read sends no parameter: one key, the latest write.
    ASSERT_EQ(f.link.setting_count, 1u);
    EXPECT_EQ(f.link.settings[0].key_len, 0u);
}

} // namespace
