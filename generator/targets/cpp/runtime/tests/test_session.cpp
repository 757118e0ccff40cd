// Tests of session.hpp (docs/conformance.md section 8) on the test protocol rendered from
// tests/runtime_specs/ (ping on every device; set_mode on alpha only, its ack suppressed by mode
// auto, 500 ms allowance; rate per device, beta's answered with the reply field rate_reply 0x84
// unless hz is 0): matching, nack, timeout, invalid replies, refusal, ack suppression, a full
// queue, several acks in one packet, routing, the look-ahead rule that replaced the timed one, its
// wake-up, and skip runs in pieces (issue 37). The generated packages run the whole session corpus.
#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "protopkg/protopkg.hpp"
#include "protopkg/session.hpp"
#include "protopkg/transport.hpp"

namespace {

namespace control = protopkg::control;

using protopkg::PacketBuilder;
using protopkg::PacketView;
using protopkg::Session;
using protopkg::SessionEvent;
using protopkg::Status;
using Bytes = std::vector<std::uint8_t>;

/// One packet of set 1 with the given fields (descriptor, data).
Bytes packet(const std::vector<std::pair<std::uint8_t, Bytes>> &fields) {
    PacketBuilder b(1);
    for (const auto &f : fields) {
        EXPECT_EQ(b.add_raw_field(f.first, f.second.data(), f.second.size()), protopkg::EncodeError::none);
    }
    const PacketView p = b.finish();
    return Bytes(p.data, p.data + p.size);
}

/// "result:<status>:<tag>[:<code>]", "packet:<offset>", "skip:<offset>+<count>" for each event.
struct Log {
    std::vector<std::string> lines;
    void operator()(const SessionEvent &e) {
        if (e.kind == SessionEvent::Kind::result) {
            std::string s = std::string("result:") + protopkg::to_string(e.result->status) + ":" +
                            std::to_string(e.result->tag);
            if (e.result->has_code) {
                s += ":" + std::to_string(e.result->code);
            }
            if (e.result->has_error) {
                s += ":" + std::string(e.result->error.c_str());
            }
            lines.push_back(s);
        } else if (e.kind == SessionEvent::Kind::packet) {
            lines.push_back("packet:" + std::to_string(e.offset));
        } else if (e.kind == SessionEvent::Kind::nmea || e.kind == SessionEvent::Kind::rtcm) {
            lines.push_back(std::string(e.kind == SessionEvent::Kind::nmea ? "nmea:" : "rtcm:") +
                            std::to_string(e.offset) + "+" + std::to_string(e.packet.size));
        } else {
            lines.push_back("skip:" + std::to_string(e.offset) + "+" + std::to_string(e.count));
        }
    }
};

protopkg::StartOptions tag(std::uint64_t t) {
    protopkg::StartOptions o;
    o.tag = t;
    return o;
}

TEST(Session, AckNackAndSeveralAcksInOnePacket) {
    Session<> s;
    control::Ping ping;
    EXPECT_FALSE(s.start(ping, 0, tag(1)).complete);
    control::SetMode mode;
    EXPECT_FALSE(s.start(mode, 0, tag(2)).complete);
    EXPECT_EQ(s.pending(), 2u);
    // Both acks in one packet: a nack for set_mode, an ack for ping.
    Log log;
    const Bytes both = packet({{0xF1, {0x02, 0x03}}, {0xF1, {0x01, 0x00}}});
    s.feed(both.data(), both.size(), 5, log);
    EXPECT_EQ(log.lines, (std::vector<std::string>{"result:nack:2:3", "result:ack:1:0"}));
    EXPECT_EQ(s.pending(), 0u);
}

// The example GGA sentence NMEA references quote (checksum 47, 67 bytes) and the RTCM 10403
// example frame of message 1005 (25 bytes, CRC-24Q 36 0B 98) between a data packet and a reply:
// framing a carries them (kForeignNmea, kForeignRtcm3; docs/conformance.md section 1) and the
// session hands them on as nmea and rtcm events in stream order, whatever the split; framing b
// has none, and the same bytes are skip runs.
TEST(Session, ForeignFramesGoToTheHandler) {
    const std::string gga = "$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,*47\r\n";
    const Bytes rtcm = {0xD3, 0x00, 0x13, 0x3E, 0xD7, 0xD3, 0x02, 0x02, 0x98, 0x0E, 0xDE, 0xEF, 0x34,
                        0xB4, 0xBD, 0x62, 0xAC, 0x09, 0x41, 0x98, 0x6F, 0x33, 0x36, 0x0B, 0x98};
    const Bytes data = packet({{0x02, {0x00, 0x01}}});
    const Bytes ack = packet({{0xF1, {0x01, 0x00}}});
    Bytes stream(gga.begin(), gga.end());
    stream.insert(stream.end(), data.begin(), data.end());
    stream.insert(stream.end(), rtcm.begin(), rtcm.end());
    stream.insert(stream.end(), ack.begin(), ack.end());
    const bool foreign = protopkg::kForeignNmea && protopkg::kForeignRtcm3;
    const std::vector<std::string> want = {
        std::string(foreign ? "nmea:0+" : "skip:0+") + std::to_string(gga.size()),
        "packet:" + std::to_string(gga.size()),
        std::string(foreign ? "rtcm:" : "skip:") + std::to_string(gga.size() + data.size()) + "+25",
        "result:ack:7:0"};
    for (std::size_t cut = 0; cut <= stream.size(); ++cut) {
        Session<> s;
        control::Ping ping;
        s.start(ping, 0, tag(7));
        Log log;
        s.feed(stream.data(), cut, 1, log);
        s.feed(stream.data() + cut, stream.size() - cut, 1, log);
        EXPECT_EQ(log.lines, want) << "cut " << cut;
    }
}

TEST(Session, ReplyFieldsExpectedMissingAndTimeout) {
    Session<> s;
    control::RateBeta rate;
    rate.hz = 1; // expects reply field 0x84
    s.start(rate, 0, tag(1));
    Log log;
    const Bytes bare = packet({{0xF1, {0x04, 0x00}}});
    s.feed(bare.data(), bare.size(), 1, log);
    ASSERT_EQ(log.lines.size(), 1u);
    EXPECT_EQ(log.lines[0], "result:invalid:1:0:missing reply field 132");
    // With the reply field (rate_reply: a u32), the ack carries it.
    s.start(rate, 10, tag(2));
    const Bytes full = packet({{0xF1, {0x04, 0x00}}, {0x84, {0x07, 0x07, 0x07, 0x07}}});
    protopkg::Result got;
    s.feed(full.data(), full.size(), 11, [&](const SessionEvent &e) { got = *e.result; });
    EXPECT_EQ(got.status, Status::ack);
    ASSERT_TRUE(got.reply<control::RateReply>().has_value());
    EXPECT_EQ(got.reply<control::RateReply>()->hz, 0x07070707u);
    // No reply: a timeout at the deadline, reported first; the late ack is then a plain packet.
    s.start(rate, 100, tag(3));
    EXPECT_EQ(s.next_deadline(), std::optional<std::int64_t>(1100));
    Log late;
    s.feed(bare.data(), bare.size(), 1100, late);
    EXPECT_EQ(late.lines, (std::vector<std::string>{
                              "result:timeout:3",
                              "packet:" + std::to_string(2 * bare.size() + full.size() - bare.size())}));
}

TEST(Session, RefusalSuppressionAndFullQueue) {
    Session<2>::Options o;
    o.device = protopkg::Device::beta;
    Session<2> s(o);
    control::RateAlpha alpha;
    protopkg::Started r = s.start(alpha, 0);
    EXPECT_TRUE(r.complete);
    EXPECT_EQ(r.packet.size, 0u);
    EXPECT_EQ(r.result.status, Status::refused);
    EXPECT_STREQ(r.result.error.c_str(), "rate: this layout is for alpha, not beta");
    control::SetMode sw;
    r = s.start(sw, 0);
    EXPECT_STREQ(r.result.error.c_str(), "set_mode is not supported by Beta (beta.txt)");
    protopkg::StartOptions unchecked;
    unchecked.check_device = false;
    sw.mode = protopkg::types::Mode::auto_; // suppresses the ack: sent at once
    r = s.start(sw, 0, unchecked);
    EXPECT_EQ(r.result.status, Status::sent);
    EXPECT_GT(r.packet.size, 0u);
    sw.mode = protopkg::types::Mode::on; // waits, with the 500 ms allowance
    r = s.start(sw, 0, unchecked);
    EXPECT_FALSE(r.complete);
    EXPECT_EQ(r.deadline, 1500);
    control::Ping ping;
    EXPECT_FALSE(s.start(ping, 0).complete);
    r = s.start(ping, 0);
    EXPECT_EQ(r.result.status, Status::refused);
    EXPECT_STREQ(r.result.error.c_str(), "2 commands already pending");
}

/// A false sync: the sync bytes, the set and a length byte claiming `length` payload bytes that
/// never come (taken from a real packet's header).
Bytes false_sync(std::uint8_t length) {
    const Bytes p = packet({{0x02, {0x01}}});
    Bytes out(p.begin(), p.begin() + protopkg::kHeaderSize);
    out[protopkg::kLengthOffset] = length;
    return out;
}

Bytes operator+(Bytes a, const Bytes &b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

const std::string kHeader = std::to_string(protopkg::kHeaderSize);

// The look-ahead rule (docs/conformance.md section 8, issue 37): past the inter-packet timeout P a
// waiting candidate is dropped only for a complete valid packet buffered after it. Here the packet
// comes after the wait expired: it is added behind the false sync and found by the look-ahead
// after the new bytes (rule b); the handlers see it.
TEST(Session, LookAheadAfterTheNewBytesDropsAFalseSync) {
    Session<> s;
    int packets = 0;
    int levels = 0;
    s.on_packet([&](const PacketView &, std::uint64_t) { ++packets; });
    s.on_field<control::SetMode>([&](const control::SetMode &v, const PacketView &) {
        levels += v.mode == protopkg::types::Mode::on;
    });
    const Bytes data = packet({{0x02, {0x01}}});
    const Bytes fs = false_sync(0x20);
    Log log;
    s.feed(fs.data(), fs.size(), 0, log);
    // The wake-up for the rule: P + 1 after the wait began.
    EXPECT_EQ(s.next_deadline(), std::optional<std::int64_t>(101));
    s.poll(101, log); // expired, but nothing complete after it: nothing is dropped
    EXPECT_TRUE(log.lines.empty());
    // Once the wait has expired, a poll can change nothing: no wake-up (the next feed looks itself).
    EXPECT_EQ(s.next_deadline(), std::nullopt);
    s.feed(data.data(), data.size(), 200, log);
    EXPECT_EQ(log.lines, (std::vector<std::string>{"skip:0+" + kHeader, "packet:" + kHeader}));
    EXPECT_EQ(packets, 1);
    EXPECT_EQ(levels, 1);
    EXPECT_EQ(s.next_deadline(), std::nullopt); // nothing buffered
    s.close(300, log);
    EXPECT_EQ(log.lines.size(), 2u);
}

// A false sync with a complete packet behind it in the same receive: the parser waits at the false
// sync (its claimed length is not there); a poll once the wait has expired looks ahead on the
// buffered bytes (rule a) and finds the packet. The same at a feed after the expiry: the old
// buffer is looked at before the new bytes are added.
TEST(Session, LookAheadOnTheBufferedBytes) {
    const Bytes data = packet({{0x02, {0x01}}});
    const Bytes both = false_sync(0x20) + data;
    const std::string after = std::to_string(both.size());
    {
        Session<> s;
        Log log;
        s.feed(both.data(), both.size(), 0, log);
        EXPECT_TRUE(log.lines.empty());
        s.poll(100, log); // not yet expired: now - s == P
        EXPECT_TRUE(log.lines.empty());
        EXPECT_EQ(s.next_deadline(), std::optional<std::int64_t>(101));
        s.poll(101, log);
        EXPECT_EQ(log.lines, (std::vector<std::string>{"skip:0+" + kHeader, "packet:" + kHeader}));
    }
    {
        Session<> s;
        Log log;
        s.feed(both.data(), both.size(), 0, log);
        s.feed(data.data(), data.size(), 150, log); // rule (a) first, then the new packet
        EXPECT_EQ(log.lines,
                  (std::vector<std::string>{"skip:0+" + kHeader, "packet:" + kHeader, "packet:" + after}));
    }
}

// A slow packet is never thrown away: its first part waits long past P and the rest completes it
// (no complete packet after its start, so the look-ahead drops nothing).
TEST(Session, SlowPacketKeptWaiting) {
    Session<> s;
    control::Ping ping;
    s.start(ping, 0, tag(1));
    const Bytes ack = packet({{0xF1, {0x01, 0x00}}});
    const std::size_t half = ack.size() / 2;
    Log log;
    s.feed(ack.data(), half, 5, log);
    EXPECT_EQ(s.next_deadline(), std::optional<std::int64_t>(106));
    s.poll(106, log);
    EXPECT_TRUE(log.lines.empty());
    // Expired: the wake-up is the command's deadline only.
    EXPECT_EQ(s.next_deadline(), std::optional<std::int64_t>(1000));
    s.feed(ack.data() + half, ack.size() - half, 600, log);
    EXPECT_EQ(log.lines, (std::vector<std::string>{"result:ack:1:0"}));
}

// After a jump the parser waits at a new candidate: its wait begins at that call, so the wake-up is
// P + 1 later and the new candidate is not dropped in the same call.
TEST(Session, TheWaitBeginsAgainAfterAJump) {
    const Bytes data = packet({{0x02, {0x01}}});
    const Bytes stream = false_sync(0x20) + data + false_sync(0x30) + data;
    Session<> s;
    Log log;
    s.feed(stream.data(), stream.size(), 0, log);
    EXPECT_TRUE(log.lines.empty());
    s.poll(101, log);
    const std::size_t second = protopkg::kHeaderSize + data.size();
    EXPECT_EQ(log.lines, (std::vector<std::string>{"skip:0+" + kHeader, "packet:" + kHeader}));
    EXPECT_EQ(s.next_deadline(), std::optional<std::int64_t>(202));
    s.poll(202, log);
    EXPECT_EQ(log.lines,
              (std::vector<std::string>{"skip:0+" + kHeader, "packet:" + kHeader,
                                        "skip:" + std::to_string(second) + "+" + kHeader,
                                        "packet:" + std::to_string(second + protopkg::kHeaderSize)}));
}

// Skip runs in pieces of kSkipPiece (SKIP_PIECE) bytes, reported as soon as the pending run reaches
// it: a noise flood gives pieces as it arrives, tiling the offsets; the rest at close or before the
// next packet.
TEST(Session, SkipRunsInPieces) {
    static_assert(protopkg::kSkipPiece == 65536, "SKIP_PIECE of docs/conformance.md section 8");
    // Bytes that never start a sync: the sync's first byte plus one (any other value would do).
    const Bytes noise(1000, static_cast<std::uint8_t>(protopkg::kSync[0] + 1));
    Session<> s;
    Log log;
    std::uint64_t fed = 0;
    while (fed + noise.size() <= 65536) {
        s.feed(noise.data(), noise.size(), 0, log);
        fed += noise.size();
    }
    EXPECT_TRUE(log.lines.empty()); // 65000 pending
    s.feed(noise.data(), noise.size(), 0, log);
    fed += noise.size();
    EXPECT_EQ(log.lines, (std::vector<std::string>{"skip:0+65536"}));
    EXPECT_EQ(s.retain_from(), 65536u); // the caller keeps only the pending piece's bytes
    for (int i = 0; i < 140; ++i) {
        s.feed(noise.data(), noise.size(), 0, log);
        fed += noise.size();
    }
    EXPECT_EQ(fed, 206000u);
    EXPECT_EQ(log.lines, (std::vector<std::string>{"skip:0+65536", "skip:65536+65536", "skip:131072+65536"}));
    s.close(0, log);
    EXPECT_EQ(log.lines.back(), "skip:196608+9392");

    // One receive of 140000 noise bytes and a packet: the pieces, the rest, then the packet.
    const Bytes data = packet({{0x02, {0x01}}});
    Bytes big;
    for (int i = 0; i < 140; ++i) {
        big = big + noise;
    }
    big = big + data;
    Session<> t;
    Log one;
    t.feed(big.data(), big.size(), 0, one);
    EXPECT_EQ(one.lines, (std::vector<std::string>{"skip:0+65536", "skip:65536+65536", "skip:131072+8928",
                                                   "packet:140000"}));
}

/// A device that floods: every read returns as many noise bytes as asked (zeros, or repeated false
/// syncs: a sync and a length byte claiming more payload than ever comes) 1 ms later.
struct FloodPort : protopkg::Transport {
    bool false_syncs = false;
    std::int64_t now = 0;
    std::size_t largest_read = 0;
    std::uint64_t sent = 0;
    bool write(const std::uint8_t *, std::size_t, protopkg::ErrorText &) override {
        return true;
    }
    long read(std::uint8_t *buffer, std::size_t capacity, std::int64_t, protopkg::ErrorText &) override {
        largest_read = capacity > largest_read ? capacity : largest_read;
        const Bytes fs = false_sync(0xF0);
        for (std::size_t i = 0; i < capacity; ++i) {
            buffer[i] = false_syncs ? fs[(sent + i) % fs.size()] : 0;
        }
        sent += capacity;
        now += 1;
        return static_cast<long>(capacity);
    }
};

// The blocking API under a flood (issue 37, docs/conformance.md section 8): reads of at most 65536
// bytes, the command's timeout at the first read at or after its deadline, skip runs in pieces of at
// most kSkipPiece bytes that tile the stream.
TEST(Session, ConnectionKeepsItsDeadlineUnderAFlood) {
    for (const bool false_syncs : {false, true}) {
        FloodPort port;
        port.false_syncs = false_syncs;
        Session<1>::Options o;
        o.timeout_ms = 500;
        protopkg::Connection c(port, o, [&port]() { return port.now; });
        std::uint64_t next = 0;
        bool tiled = true;
        std::uint64_t largest = 0;
        c.on_event([&](const SessionEvent &e) {
            if (e.kind == SessionEvent::Kind::skip) {
                tiled = tiled && e.offset == next;
                next = e.offset + e.count;
                largest = e.count > largest ? e.count : largest;
            }
        });
        control::Ping ping;
        const protopkg::Call call = c.run(ping);
        EXPECT_EQ(call.result.status, Status::timeout);
        EXPECT_EQ(port.now, 500); // the read that reached the deadline
        EXPECT_LE(port.largest_read, 65536u);
        EXPECT_TRUE(tiled);
        EXPECT_LE(largest, protopkg::kSkipPiece);
        EXPECT_GT(next, 0u);
        EXPECT_LE(port.sent - next, protopkg::kSkipPiece + protopkg::kMaxPacket); // the rest pending
    }
}

} // namespace
