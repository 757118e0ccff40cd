// Getting through (transport.hpp Connection, docs/conformance.md section 8 "Getting through") on
// the rendered test protocol (tests/runtime_specs/: its link section names ping, alpha's main port
// 9600, 115200 (default), 921600 baud, 3 idle attempts by default; it has no idle command: these
// tests give the ping its place through LinkOptions): the same cases and lines as the C runtime's
// link_test.cpp. A fake device over a fake clock: every read of a streaming device returns one data
// packet 10 ms later.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>
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
    explicit Fixture(std::int64_t reconnect_ms = 10000, bool ping_as_idle = true)
        : dev(port, options(), [this]() { return port.now; }) {
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
    static protopkg::Session<1>::Options options() {
        protopkg::Session<1>::Options o;
        o.device = protopkg::Device::alpha;
        return o;
    }
};

control::Gain gain(std::uint16_t value) {
    control::Gain g;
    g.function = protopkg::types::Function::write;
    g.gain = value;
    return g;
}

TEST(LinkGettingThrough, IdleWhileStreaming) {
    Fixture f;
    f.port.streaming = true;
    f.port.unanswered = 2;
    EXPECT_TRUE(f.dev.to_idle().ok());
    // Each unanswered attempt waits T = 1000 ms: the packets read at 10, 20, ... 1000 ms are
    // dropped (the last one after the timeout, in the same read): 100 packets.
    const std::string dropped = std::to_string(100 * data_packet().size());
    EXPECT_EQ(f.log, (std::vector<std::string>{
                         "link: idle: no ACK in 1000 ms while streaming (" + dropped +
                             " bytes dropped), flushing, attempt 2 of 3",
                         "link: idle: no ACK in 1000 ms while streaming (" + dropped +
                             " bytes dropped), flushing, attempt 3 of 3",
                         "link: idle: ACK on attempt 3 of 3 (0 bytes dropped)",
                     }));
    EXPECT_EQ(f.port.commands.size(), 3u);
    EXPECT_EQ(f.port.flushes, 4);
    EXPECT_EQ(f.events, 0);
    f.port.streaming = true;
    EXPECT_TRUE(f.dev.listen(100));
    EXPECT_GT(f.packets, 0);
}

TEST(LinkGettingThrough, IdleGivesUpAfterTheAttempts) {
    Fixture f;
    f.port.unanswered = 100;
    const protopkg::Call call = f.dev.to_idle();
    EXPECT_EQ(call.result.status, protopkg::Status::timeout);
    EXPECT_EQ(f.port.commands.size(), std::size_t{protopkg::kLinkIdleAttempts});
    EXPECT_EQ(f.log, (std::vector<std::string>{"link: idle: no ACK in 1000 ms, flushing, attempt 2 of 3",
                                               "link: idle: no ACK in 1000 ms, flushing, attempt 3 of 3",
                                               "link: idle: no ACK after 3 attempts, giving up"}));
}

TEST(LinkGettingThrough, WithoutAnIdleCommandToIdleIsRefused) {
    Fixture f(10000, false);
    const protopkg::Call call = f.dev.to_idle();
    EXPECT_EQ(call.result.status, protopkg::Status::refused);
    EXPECT_STREQ(call.result.error.c_str(), "the protocol has no idle command");
    EXPECT_EQ(f.log, (std::vector<std::string>{"link: idle: the protocol has no idle command"}));
    EXPECT_TRUE(f.port.commands.empty());
}

TEST(LinkGettingThrough, FindsTheBaudRate) {
    Fixture f;
    f.port.answers_at = 921600;
    EXPECT_TRUE(f.dev.find_baud().ok());
    EXPECT_EQ(f.log, (std::vector<std::string>{"link: baud: no answer at 115200, trying 921600",
                                               "link: baud: device answers at 921600"}));
    EXPECT_EQ(f.port.rate, 921600u);
    EXPECT_EQ(f.port.flushes, 1);
}

TEST(LinkGettingThrough, BaudSearchTriesEveryRateOnce) {
    Fixture f;
    f.port.answers_at = 1;
    EXPECT_FALSE(f.dev.find_baud().ok());
    EXPECT_EQ(f.log, (std::vector<std::string>{"link: baud: no answer at 115200, trying 921600",
                                               "link: baud: no answer at 921600, trying 9600",
                                               "link: baud: no answer at any rate"}));
    EXPECT_EQ(f.port.commands.size(), 3u);
}

TEST(LinkGettingThrough, NoBaudSearchWithoutABaudRate) {
    Fixture f;
    f.port.has_baud = false; // TCP
    f.port.answers_at = 1;
    EXPECT_FALSE(f.dev.find_baud().ok());
    EXPECT_TRUE(f.log.empty());
    EXPECT_EQ(f.port.commands.size(), 1u);
}

TEST(LinkGettingThrough, ReconnectsAndReappliesTheConfiguration) {
    Fixture f;
    EXPECT_TRUE(f.dev.run(gain(7)).ok());
    control::Gain read;
    read.function = protopkg::types::Function::read;
    f.dev.run(read);
    EXPECT_EQ(f.dev.settings(), 1u);
    const Bytes written = f.port.commands[0];
    f.port.commands.clear();
    f.port.lost = true;
    f.port.reopen_failures = 2;
    const protopkg::Call call = f.dev.run(control::Ping{});
    EXPECT_TRUE(call.io_error);
    EXPECT_TRUE(call.lost);
    EXPECT_STREQ(call.io.c_str(), "link lost: Input/output error");
    EXPECT_TRUE(f.dev.connected());
    EXPECT_EQ(f.log, (std::vector<std::string>{
                         "link: port lost (Input/output error), reopening /tmp/x/dev every 500 ms",
                         "link: idle: ACK on attempt 1 of 3 (0 bytes dropped)",
                         "link: reconnected after 1.0 s, re-applied 1 settings"}));
    ASSERT_EQ(f.port.commands.size(), 2u);
    EXPECT_EQ(f.port.commands[0][protopkg::kHeaderSize + protopkg::kFieldDescriptorOffset],
              control::Ping::kDescriptor);
    EXPECT_EQ(f.port.commands[1], written);
    EXPECT_TRUE(f.dev.run(control::Ping{}).ok());
}

TEST(LinkGettingThrough, TheLatestWriteOfASettingWins) {
    Fixture f;
    EXPECT_TRUE(f.dev.run(gain(7)).ok());
    f.port.commands.clear();
    EXPECT_TRUE(f.dev.run(gain(9)).ok());
    const Bytes written = f.port.commands[0];
    EXPECT_EQ(f.dev.settings(), 1u); // gain's read sends no parameter: one key
    f.port.commands.clear();
    f.port.lost = true;
    f.dev.run(control::Ping{});
    ASSERT_EQ(f.port.commands.size(), 2u);
    EXPECT_EQ(f.port.commands[1], written);
}

TEST(LinkGettingThrough, GivesUpWhenThePortStaysAway) {
    Fixture f(1200);
    f.port.lost = true;
    f.port.reopen_failures = 100;
    const protopkg::Call call = f.dev.run(control::Ping{});
    EXPECT_TRUE(call.io_error);
    EXPECT_FALSE(f.dev.connected());
    ASSERT_EQ(f.log.size(), 2u);
    EXPECT_EQ(f.log[1], "link: gave up reopening /tmp/x/dev after 1200 ms");
    EXPECT_EQ(f.port.sleeps, (std::vector<std::int64_t>{500, 500})); // 1000 + 500 is past 1200
}

TEST(LinkGettingThrough, NoReconnectWithoutTheOption) {
    Fixture f(0);
    f.port.lost = true;
    const protopkg::Call call = f.dev.run(control::Ping{});
    EXPECT_TRUE(call.io_error);
    EXPECT_FALSE(call.lost);
    EXPECT_FALSE(f.dev.connected());
    EXPECT_TRUE(f.log.empty());
}

} // namespace
