// Getting through (transport.hpp Connection, docs/conformance.md section 8 "Getting through") on
// the rendered test protocol (tests/runtime_specs/): the link corpus tests/link/cases.txt (its path
// LINK_CASES from CMakeLists.txt; the format and the fake device's rules in tests/link/README.md),
// as the C and Python runtimes run it, then the cases of this API only. The test protocol has no
// idle command: a case gives the ping its place through LinkOptions unless it says `set idle none`.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "protopkg/protopkg.hpp"
#include "protopkg/transport.hpp"

namespace {

namespace control = protopkg::control;
using Bytes = std::vector<std::uint8_t>;

Bytes build(std::uint8_t set, std::uint8_t descriptor, const Bytes &data) {
    protopkg::PacketBuilder b(set);
    EXPECT_EQ(b.add_raw_field(descriptor, data.data(), data.size()), protopkg::EncodeError::none);
    const protopkg::PacketView p = b.finish();
    return Bytes(p.data, p.data + p.size);
}

/// A data packet of the sensor set (reading: count, offset, valid).
Bytes data_packet() {
    return build(0x80, 0x01, {0x01, 0x00, 0x00, 0x01});
}

struct FakePort : protopkg::Transport {
    Bytes to_host;
    std::vector<Bytes> commands;
    std::int64_t now = 0;
    bool streaming = false;
    int unanswered = 0;
    std::uint32_t answers_at = 0; // the only rate the device answers at (0: any)
    std::uint32_t rate = 115200;
    bool has_baud = true;
    bool lost = false;
    int reopen_failures = 0;
    int flushes = 0;
    std::vector<std::int64_t> sleeps;

    bool write(const std::uint8_t *data, std::size_t size, protopkg::ErrorText &) override {
        if (lost) {
            return false;
        }
        commands.emplace_back(data, data + size);
        if ((answers_at != 0 && rate != answers_at) || unanswered-- > 0) {
            return true;
        }
        const std::uint8_t descriptor = data[protopkg::kHeaderSize + protopkg::kFieldDescriptorOffset];
        if (descriptor == control::Ping::kDescriptor) { // the idle command of these tests
            streaming = false;
        }
        const Bytes ack = build(0x01, 0xF1, {descriptor, 0x00});
        to_host.insert(to_host.end(), ack.begin(), ack.end());
        return true;
    }
    long read(std::uint8_t *buffer, std::size_t capacity, std::int64_t timeout_ms,
              protopkg::ErrorText &) override {
        if (lost) {
            return -1;
        }
        if (to_host.empty() && streaming) {
            const Bytes p = data_packet();
            to_host.insert(to_host.end(), p.begin(), p.end());
            now += 10;
        }
        if (to_host.empty()) {
            now += timeout_ms;
            return 0;
        }
        const std::size_t n = to_host.size() < capacity ? to_host.size() : capacity;
        std::memcpy(buffer, to_host.data(), n);
        to_host.erase(to_host.begin(), to_host.begin() + static_cast<long>(n));
        return static_cast<long>(n);
    }
    bool flush() override {
        ++flushes;
        to_host.clear();
        return true;
    }
    std::uint32_t baud() const override {
        return has_baud ? rate : 0;
    }
    bool set_baud(std::uint32_t r) override {
        rate = r;
        return true;
    }
    bool reopen() override {
        if (reopen_failures-- > 0) {
            return false;
        }
        lost = false;
        return true;
    }
    std::string address() const override {
        return "/tmp/x/dev";
    }
    std::string reason() const override {
        return "Input/output error";
    }
    bool sleep_ms(std::int64_t ms) override {
        sleeps.push_back(ms);
        now += ms;
        return true;
    }
};

struct Fixture {
    FakePort port;
    std::vector<std::string> log;
    int events = 0;
    int packets = 0;
    protopkg::Connection dev;
    explicit Fixture(std::int64_t reconnect_ms = 10000, bool ping_as_idle = true,
                     std::optional<protopkg::Device> device = protopkg::Device::alpha,
                     std::uint32_t baud = 115200)
        : dev(port, options(device), [this]() { return port.now; }) {
        port.rate = baud;
        protopkg::LinkOptions o;
        o.log = [this](const std::string &line) { log.push_back(line); };
        o.reconnect_ms = reconnect_ms;
        if (ping_as_idle) {
            o.idle = o.ping;
        }
        dev.link_options(o);
        dev.on_event([this](const protopkg::SessionEvent &e) {
            ++events;
            if (e.kind == protopkg::SessionEvent::Kind::packet) {
                ++packets;
            }
        });
    }
    static protopkg::Session<1>::Options options(std::optional<protopkg::Device> device) {
        protopkg::Session<1>::Options o;
        o.device = device;
        return o;
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
        const std::size_t space = line.find(' ');
        const std::string what = line.substr(0, space);
        const std::string rest = space == std::string::npos ? "" : line.substr(space + 1);
        if (what == "case") {
            c = LinkCase();
            c.name = rest;
        } else if (what == "set") {
            const std::size_t sp = rest.find(' ');
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

/// {data N} and {ack N}: N data or ACK packets' bytes.
std::string expanded(std::string line) {
    for (const std::string what : {"{data ", "{ack "}) {
        std::size_t at;
        while ((at = line.find(what)) != std::string::npos) {
            const std::size_t close = line.find('}', at);
            const std::size_t n = std::stoul(line.substr(at + what.size(), close - at - what.size()));
            const std::size_t size =
                what[1] == 'd' ? data_packet().size() : build(0x01, 0xF1, {0x01, 0x00}).size();
            line.replace(at, close - at + 1, std::to_string(n * size));
        }
    }
    return line;
}

control::Gain gain_of(const std::string &token) {
    control::Gain g;
    if (token == "read") {
        g.function = protopkg::types::Function::read;
    } else {
        g.function = protopkg::types::Function::write;
        g.gain = static_cast<std::uint16_t>(std::stoul(token.substr(6)));
    }
    return g;
}

Bytes token_packet(const std::string &token) {
    protopkg::PacketBuilder b(0x01);
    if (token == "ping") {
        EXPECT_EQ(b.add(control::Ping{}), protopkg::EncodeError::none);
    } else {
        EXPECT_EQ(b.add(gain_of(token)), protopkg::EncodeError::none);
    }
    const protopkg::PacketView p = b.finish();
    return Bytes(p.data, p.data + p.size);
}

std::string call_name(const protopkg::Call &call) {
    if (call.lost) {
        return "lost";
    }
    if (call.io_error) {
        return "error";
    }
    return protopkg::to_string(call.result.status);
}

std::string run_step(Fixture &f, const std::vector<std::string> &step) {
    const std::string &what = step[0];
    if (what == "to_idle") {
        return call_name(f.dev.to_idle());
    }
    if (what == "find_baud") {
        const protopkg::Call call = f.dev.find_baud();
        return call.ok() ? "ack" : call.result.status == protopkg::Status::timeout ? "fail" : call_name(call);
    }
    if (what == "listen") {
        return f.dev.listen(std::stoll(step[1])) ? "ok" : "fail";
    }
    if (what == "ping") {
        return call_name(f.dev.run(control::Ping{}));
    }
    return call_name(f.dev.run(gain_of(what == "write" ? "write:" + step[1] : what)));
}

void run_case(const LinkCase &c) {
    std::int64_t reconnect = 10000;
    std::uint32_t baud = 115200;
    std::optional<protopkg::Device> device = protopkg::Device::alpha;
    bool ping_as_idle = true;
    bool tcp = false;
    for (const auto &s : c.set) {
        if (s.first == "reconnect") {
            reconnect = s.second == "off" ? 0 : std::stoll(s.second);
        } else if (s.first == "baud") {
            tcp = s.second == "none";
            baud = tcp ? 115200 : static_cast<std::uint32_t>(std::stoul(s.second));
        } else if (s.first == "model") {
            device = s.second == "beta"   ? std::optional<protopkg::Device>(protopkg::Device::beta)
                     : s.second == "none" ? std::nullopt
                                          : device;
        } else if (s.first == "idle") {
            ping_as_idle = s.second != "none";
        }
    }
    std::unique_ptr<Fixture> f(new Fixture(reconnect, ping_as_idle, device, baud));
    f->port.has_baud = !tcp;
    for (const auto &s : c.set) {
        if (s.first == "streaming") {
            f->port.streaming = true;
        } else if (s.first == "unanswered") {
            f->port.unanswered = std::stoi(s.second);
        } else if (s.first == "answers_at") {
            f->port.answers_at = static_cast<std::uint32_t>(std::stoul(s.second));
        }
    }
    for (const auto &step : c.steps) {
        SCOPED_TRACE(step[0]);
        if (step[0] == "lose") {
            f->port.lost = true;
            f->port.reopen_failures = std::stoi(step[1]);
        } else if (step[0] == "stream") {
            f->port.streaming = true;
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
    EXPECT_EQ(f->log, log);
    for (const auto &e : c.expect) {
        SCOPED_TRACE(e.first);
        if (e.first == "sent") {
            std::vector<Bytes> sent;
            for (const auto &token : words(e.second)) {
                sent.push_back(token_packet(token));
            }
            EXPECT_EQ(f->port.commands, sent);
        } else if (e.first == "flushes") {
            EXPECT_EQ(f->port.flushes, std::stoi(e.second));
        } else if (e.first == "packets") {
            EXPECT_EQ(f->packets, std::stoi(e.second));
        } else if (e.first == "sleeps") {
            std::vector<std::int64_t> sleeps;
            for (const auto &ms : words(e.second)) {
                sleeps.push_back(std::stoll(ms));
            }
            EXPECT_EQ(f->port.sleeps, sleeps);
        } else if (e.first == "rate") {
            EXPECT_EQ(tcp ? std::string("none") : std::to_string(f->port.rate), e.second);
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

TEST(LinkGettingThrough, TheCallOfALostCommand) {
    Fixture f;
    f.port.lost = true;
    const protopkg::Call call = f.dev.run(control::Ping{});
    EXPECT_TRUE(call.io_error);
    EXPECT_TRUE(call.lost);
    EXPECT_STREQ(call.io.c_str(), "link lost: Input/output error");
    EXPECT_TRUE(f.dev.connected());
    Fixture g(1200);
    g.port.lost = true;
    g.port.reopen_failures = 100;
    EXPECT_TRUE(g.dev.run(control::Ping{}).io_error);
    EXPECT_FALSE(g.dev.connected());
    Fixture h(0);
    h.port.lost = true;
    EXPECT_FALSE(h.dev.run(control::Ping{}).lost);
    EXPECT_FALSE(h.dev.connected());
}

TEST(LinkGettingThrough, OneKeyPerSettingWithoutReadParameters) {
    Fixture f;
    EXPECT_TRUE(f.dev.run(gain_of("write:7")).ok());
    EXPECT_TRUE(f.dev.run(gain_of("write:9")).ok());
    f.dev.run(gain_of("read"));
    EXPECT_EQ(f.dev.settings(), 1u); // gain's read sends no parameter: one key
}

} // namespace
