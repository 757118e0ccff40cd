// In-place tests of session.hpp (docs/conformance.md section 8) on the stub package (alpha
// framing) with the hand-written package/protopkg/session_facts.hpp: matching, nack, timeout,
// invalid replies, refusal, ack suppression, a full queue, several acks in one packet, routing,
// and the timed inter-packet rule. The generated packages run the whole session corpus.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "protopkg/session.hpp"

namespace {

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
    protopkg::stub::Ping ping;
    EXPECT_FALSE(s.start(ping, 0, tag(1)).complete);
    protopkg::stub::InfoCv info;
    EXPECT_FALSE(s.start(info, 0, tag(2)).complete);
    EXPECT_EQ(s.pending(), 2u);
    // A packet of another set's data first (not a reply), then both acks in one packet: a nack
    // for info, an ack for ping.
    Log log;
    const Bytes both = packet({{0xF1, {0x02, 0x03}}, {0xF1, {0x01, 0x00}}});
    s.feed(both.data(), both.size(), 5, log);
    EXPECT_EQ(log.lines, (std::vector<std::string>{"result:nack:2:3", "result:ack:1:0"}));
    EXPECT_EQ(s.pending(), 0u);
}

TEST(Session, ReplyFieldsExpectedMissingAndTimeout) {
    Session<> s;
    protopkg::stub::Ping ping;
    ping.flags = 1; // expects reply field 0x02
    s.start(ping, 0, tag(1));
    Log log;
    const Bytes bare = packet({{0xF1, {0x01, 0x00}}});
    s.feed(bare.data(), bare.size(), 1, log);
    ASSERT_EQ(log.lines.size(), 1u);
    EXPECT_EQ(log.lines[0], "result:invalid:1:0:missing reply field 2");
    // With the reply field (InfoGx data: one byte), the ack carries it.
    s.start(ping, 10, tag(2));
    const Bytes full = packet({{0xF1, {0x01, 0x00}}, {0x02, {0x07}}});
    protopkg::Result got;
    s.feed(full.data(), full.size(), 11, [&](const SessionEvent &e) { got = *e.result; });
    EXPECT_EQ(got.status, Status::ack);
    ASSERT_TRUE(got.reply<protopkg::stub::InfoGx>().has_value());
    EXPECT_EQ(got.reply<protopkg::stub::InfoGx>()->level, 7);
    // No reply: a timeout at the deadline, reported first; the late ack is then a plain packet.
    s.start(ping, 100, tag(3));
    EXPECT_EQ(s.next_deadline(), std::optional<std::int64_t>(1100));
    Log late;
    s.feed(bare.data(), bare.size(), 1100, late);
    EXPECT_EQ(late.lines, (std::vector<std::string>{
                              "result:timeout:3",
                              "packet:" + std::to_string(2 * bare.size() + full.size() - bare.size())}));
}

TEST(Session, RefusalSuppressionAndFullQueue) {
    Session<2>::Options o;
    o.device = protopkg::Device::cv;
    Session<2> s(o);
    protopkg::stub::InfoGx gx;
    protopkg::Started r = s.start(gx, 0);
    EXPECT_TRUE(r.complete);
    EXPECT_EQ(r.packet.size, 0u);
    EXPECT_EQ(r.result.status, Status::refused);
    EXPECT_STREQ(r.result.error.c_str(), "info: this layout is for gx, not cv");
    protopkg::stub::Switch sw;
    r = s.start(sw, 0);
    EXPECT_STREQ(r.result.error.c_str(), "switch is not supported by CV (cv.txt)");
    protopkg::StartOptions unchecked;
    unchecked.check_device = false;
    sw.on = true; // suppresses the ack: sent at once
    r = s.start(sw, 0, unchecked);
    EXPECT_EQ(r.result.status, Status::sent);
    EXPECT_GT(r.packet.size, 0u);
    sw.on = false; // waits, with the 500 ms allowance
    r = s.start(sw, 0, unchecked);
    EXPECT_FALSE(r.complete);
    EXPECT_EQ(r.deadline, 1500);
    protopkg::stub::Ping ping;
    EXPECT_FALSE(s.start(ping, 0).complete);
    r = s.start(ping, 0);
    EXPECT_EQ(r.result.status, Status::refused);
    EXPECT_STREQ(r.result.error.c_str(), "2 commands already pending");
}

TEST(Session, HandlersAndTheTimedRule) {
    Session<> s;
    int packets = 0;
    int levels = 0;
    s.on_packet([&](const PacketView &, std::uint64_t) { ++packets; });
    s.on_field<protopkg::stub::Switch>(
        [&](const protopkg::stub::Switch &v, const PacketView &) { levels += v.on; });
    const Bytes data = packet({{0x03, {0x01}}});
    // A false sync (sync bytes, a length byte, nothing more) then nothing for longer than P.
    const Bytes false_sync = {data[0], data[1], 0x01, 0x20};
    Log log;
    s.feed(false_sync.data(), false_sync.size(), 0, log);
    EXPECT_EQ(s.next_deadline(), std::optional<std::int64_t>(101));
    s.feed(data.data(), data.size(), 200, log); // too late to complete it: the false sync is dropped first
    EXPECT_EQ(log.lines, (std::vector<std::string>{"skip:0+4", "packet:4"}));
    EXPECT_EQ(packets, 1);
    EXPECT_EQ(levels, 1);
    s.close(300, log);
    EXPECT_EQ(log.lines.size(), 2u);
}

} // namespace
