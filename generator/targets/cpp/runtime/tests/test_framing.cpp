// Runtime tests of the framing layer (checksum.hpp, packet.hpp, parser.hpp, samples.hpp) that
// hold for any framing: checksum, builder, stream parser (garbage, resync, truncation, chunking),
// field iterator messages, sample grouping. Built once per test protocol (protocols/*/).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "protopkg/checksum.hpp"
#include "protopkg/packet.hpp"
#include "protopkg/parser.hpp"
#include "protopkg/samples.hpp"
#include "runtime_test_support.hpp"

namespace {

using namespace runtime_test;

TEST(Checksum, Fletcher16KnownAnswer) {
    const std::uint8_t data[] = {0x01, 0x02};
    const pkg::Fletcher16 f = pkg::fletcher16(data, 2);
    EXPECT_EQ(f.sum1, 3);
    EXPECT_EQ(f.sum2, 4);
    const std::uint8_t all[] = {0xFF, 0xFF, 0xFF};
    const pkg::Fletcher16 g = pkg::fletcher16(all, 3);
    EXPECT_EQ(g.sum1, 0xFD); // 0xFF, 0xFE, 0xFD (mod 256)
    EXPECT_EQ(g.sum2, 0xFA); // 0xFF, 0xFD, 0xFA
    EXPECT_EQ(g.bytes()[pkg::kSum1Index], 0xFD);
    EXPECT_EQ(g.bytes()[pkg::kSum2Index], 0xFA);
}

TEST(Checksum, WideStepsMatchTheByteSerialDefinition) {
    // Lengths past 256 bytes: the lanes are masked once per run of 32 eight-byte blocks.
    std::uint8_t bytes[600 + 7];
    std::uint32_t state = 12345;
    for (std::uint8_t &b : bytes) {
        state = state * 1103515245u + 12345u;
        b = static_cast<std::uint8_t>(state >> 16);
    }
    for (std::size_t start = 0; start < 8; ++start) {
        for (std::size_t len = 0; len <= 600; ++len) {
            unsigned sum1 = 0;
            unsigned sum2 = 0;
            for (std::size_t i = 0; i < len; ++i) {
                sum1 = (sum1 + bytes[start + i]) & 0xFFu;
                sum2 = (sum2 + sum1) & 0xFFu;
            }
            const pkg::Fletcher16 whole = pkg::fletcher16(bytes + start, len);
            ASSERT_EQ(whole.sum1, sum1) << "start " << start << " length " << len;
            ASSERT_EQ(whole.sum2, sum2) << "start " << start << " length " << len;
            const std::size_t cut = len / 3;
            pkg::Fletcher16 split;
            split.update(bytes + start, cut);
            split.update(bytes + start + cut, len - cut);
            ASSERT_EQ(split.sum1, sum1) << "start " << start << " length " << len << " cut " << cut;
            ASSERT_EQ(split.sum2, sum2) << "start " << start << " length " << len << " cut " << cut;
        }
    }
    // 261 bytes of 0xFF (-1 modulo 256): sum1 = -261 = 0xFB, sum2 = -(1 + .. + 261) = -34191 = 0x71
    std::uint8_t ones[261];
    std::memset(ones, 0xFF, sizeof ones);
    const pkg::Fletcher16 f = pkg::fletcher16(ones, sizeof ones);
    EXPECT_EQ(f.sum1, 0xFB);
    EXPECT_EQ(f.sum2, 0x71);
    // 4000 bytes of 0xFF, the largest lane values (16 runs; one unmasked run of all 500 blocks
    // would overflow a 16-bit lane): sum1 = -4000 = 0x60 (4000 = 0xFA0),
    // sum2 = -(1 + .. + 4000) = -8002000 = 0x30 (8002000 = 0x7A19D0).
    std::uint8_t many[4000];
    std::memset(many, 0xFF, sizeof many);
    const pkg::Fletcher16 g = pkg::fletcher16(many, sizeof many);
    EXPECT_EQ(g.sum1, 0x60);
    EXPECT_EQ(g.sum2, 0x30);
}

TEST(Checksum, VectorPathMatchesTheScalarReference) {
    // update() takes the vector path of the build (SSE2, AVX2; none on other targets) from 16
    // bytes on; update_scalar() is the reference. Every length 0..300 at every alignment 0..63,
    // from any starting sums, over random bytes and over 0xFF (the largest lane values).
    alignas(64) std::uint8_t bytes[64 + 300];
    for (int fill = 0; fill < 2; ++fill) {
        std::uint32_t state = 2024;
        for (std::uint8_t &b : bytes) {
            state = state * 1103515245u + 12345u;
            b = fill == 0 ? static_cast<std::uint8_t>(state >> 16) : 0xFF;
        }
        for (std::size_t align = 0; align < 64; ++align) {
            for (std::size_t len = 0; len <= 300; ++len) {
                pkg::Fletcher16 ref;
                ref.sum1 = static_cast<std::uint8_t>(align * 37 + len);
                ref.sum2 = static_cast<std::uint8_t>(len * 11);
                pkg::Fletcher16 got = ref;
                ref.update_scalar(bytes + align, len);
                got.update(bytes + align, len);
                ASSERT_EQ(got.sum1, ref.sum1) << "fill " << fill << " align " << align << " length " << len;
                ASSERT_EQ(got.sum2, ref.sum2) << "fill " << fill << " align " << align << " length " << len;
                // the parser's test: the reference sums in transmission order match, others not
                const pkg::Fletcher16 from_zero = [&] {
                    pkg::Fletcher16 f;
                    f.update_scalar(bytes + align, len);
                    return f;
                }();
                const std::array<std::uint8_t, 2> sums = from_zero.bytes();
                ASSERT_TRUE(pkg::fletcher16_matches(bytes + align, len, sums.data())) << align << " " << len;
                std::array<std::uint8_t, 2> wrong = sums;
                wrong[len % 2] = static_cast<std::uint8_t>(wrong[len % 2] + 1);
                ASSERT_FALSE(pkg::fletcher16_matches(bytes + align, len, wrong.data()))
                    << align << " " << len;
            }
        }
    }
}

TEST(Checksum, BuilderWritesHeaderAndChecksum) {
    const Bytes p = packet(0x01, 0x7A, 3);
    ASSERT_EQ(p.size(), pkg::kHeaderSize + pkg::kFieldHeaderSize + 3 + pkg::kChecksumSize);
    EXPECT_EQ(0, std::memcmp(p.data(), pkg::kSync.data(), pkg::kSyncSize));
    EXPECT_EQ(p[pkg::kSetOffset], 0x01);
    EXPECT_EQ(p[pkg::kLengthOffset], pkg::kFieldHeaderSize + 3);
    const std::uint8_t *field = p.data() + pkg::kHeaderSize;
    EXPECT_EQ(field[pkg::kFieldLengthOffset], 3 + pkg::kFieldLengthAdjust);
    EXPECT_EQ(field[pkg::kFieldDescriptorOffset], 0x7A);
    const auto sums = pkg::fletcher16(p.data(), p.size() - 2).bytes();
    EXPECT_EQ(p[p.size() - 2], sums[0]);
    EXPECT_EQ(p[p.size() - 1], sums[1]);
    // one bit flipped in the checksum: the whole packet is skipped
    Bytes bad = p;
    bad.back() ^= 1;
    EXPECT_EQ(events(bad, 64), (std::vector<Event>{{false, 0, bad.size()}}));
}

TEST(Parser, GarbageAndResync) {
    const Bytes a = packet(0x01, 0x10, 4);
    const Bytes b = packet(0x02, 0x11, 0);
    const Bytes input = cat({garbage(3, 1), a, garbage(5, 2), b, garbage(2, 3)});
    const std::vector<Event> want = {
        {false, 0, 3},
        {true, 3, a.size()},
        {false, 3 + a.size(), 5},
        {true, 8 + a.size(), b.size()},
        {false, 8 + a.size() + b.size(), 2},
    };
    EXPECT_EQ(events(input, input.size()), want);
    EXPECT_EQ(events(input, 1), want);
    EXPECT_EQ(events(input, 3), want);
}

TEST(Parser, FalseSyncIsSkippedOneByteAtATime) {
    // A sync with a length that takes in the next packet: the checksum fails, the parser resumes
    // at the byte after the false sync and finds the real packet.
    const Bytes real = packet(0x03, 0x12, 2);
    Bytes fake(pkg::kSync.begin(), pkg::kSync.end());
    fake.resize(pkg::kHeaderSize, 0x00);
    fake[pkg::kSetOffset] = static_cast<std::uint8_t>(pkg::kSync[0] ^ 0x5A);
    fake[pkg::kLengthOffset] = 3;
    const Bytes input = cat({fake, real});
    ASSERT_NE(pkg::fletcher16(input.data(), pkg::kHeaderSize + 3).bytes()[0], input[pkg::kHeaderSize + 3]);
    const std::vector<Event> want = {{false, 0, fake.size()}, {true, fake.size(), real.size()}};
    EXPECT_EQ(events(input, input.size()), want);
    EXPECT_EQ(events(input, 1), want);
}

TEST(Parser, TruncatedAtEndOfStream) {
    const Bytes p = packet(0x01, 0x20, 6);
    const Bytes input = cat({p, Bytes(p.begin(), p.end() - 1)});
    const std::vector<Event> want = {{true, 0, p.size()}, {false, p.size(), p.size() - 1}};
    EXPECT_EQ(events(input, input.size()), want);
    EXPECT_EQ(events(input, 1), want);
    // a lone partial sync at the very end is skipped at flush
    const Bytes lone = cat({p, Bytes(pkg::kSync.begin(), pkg::kSync.begin() + 1)});
    EXPECT_EQ(events(lone, 1), (std::vector<Event>{{true, 0, p.size()}, {false, p.size(), 1}}));
}

TEST(Parser, FalseSyncRunningPastTheEndKeepsThePacketBehindIt) {
    // At end of input a header whose length runs past the data is a false sync: skipped one byte
    // at a time, so the complete packet inside it is still found.
    const Bytes real = packet(0x01, 0x21, 1);
    Bytes fake(pkg::kSync.begin(), pkg::kSync.end());
    fake.resize(pkg::kHeaderSize, 0x00);
    fake[pkg::kSetOffset] = static_cast<std::uint8_t>(pkg::kSync[0] ^ 0x5A);
    fake[pkg::kLengthOffset] =
        static_cast<std::uint8_t>(real.size() + 10 <= pkg::kMaxPayload ? real.size() + 10 : pkg::kMaxPayload);
    const Bytes input = cat({fake, real});
    const std::vector<Event> want = {{false, 0, fake.size()}, {true, fake.size(), real.size()}};
    EXPECT_EQ(events(input, input.size()), want);
    EXPECT_EQ(events(input, 1), want);
}

TEST(Parser, GarbageRunsOfEveryLength) {
    // Runs of 0..40 bytes without a sync byte between packets: the search for the next sync byte
    // looks at 16 bytes at once where the vector path exists, then the rest; every run is one
    // skip event, whole or fed a byte at a time (the buffered path).
    Bytes input;
    std::vector<Event> want;
    for (std::size_t n = 0; n <= 40; ++n) {
        const Bytes g = garbage(n, static_cast<std::uint8_t>(n));
        const Bytes p = packet(0x01, static_cast<std::uint8_t>(n), n % 7);
        if (n > 0) {
            want.push_back({false, input.size(), n});
        }
        input.insert(input.end(), g.begin(), g.end());
        want.push_back({true, input.size(), p.size()});
        input.insert(input.end(), p.begin(), p.end());
    }
    const Bytes tail = garbage(33, 99);
    want.push_back({false, input.size(), tail.size()});
    input.insert(input.end(), tail.begin(), tail.end());
    EXPECT_EQ(events(input, input.size()), want);
    EXPECT_EQ(events(input, 1), want);
}

TEST(Parser, ChunkIndependent) {
    Bytes input;
    std::uint32_t seed = 12345;
    auto next = [&]() {
        seed = seed * 1103515245u + 12345u;
        return (seed >> 16) & 0x7FFF;
    };
    for (int i = 0; i < 60; ++i) {
        const Bytes p = packet(static_cast<std::uint8_t>(1 + next() % 200), static_cast<std::uint8_t>(next()),
                               next() % 40);
        switch (next() % 4) {
        case 0:
            input.insert(input.end(), p.begin(), p.end());
            break;
        case 1: // corrupted
            input.insert(input.end(), p.begin(), p.end());
            input[input.size() - 1 - next() % p.size()] ^= 0x40;
            break;
        case 2: // cut short
            input.insert(input.end(), p.begin(), p.begin() + static_cast<long>(next() % p.size()));
            break;
        default: // random bytes, sync bytes included
            for (unsigned k = next() % 9; k > 0; --k) {
                input.push_back(next() % 3 == 0 ? pkg::kSync[next() % pkg::kSyncSize]
                                                : static_cast<std::uint8_t>(next()));
            }
        }
    }
    const std::vector<Event> whole = events(input, input.size());
    ASSERT_FALSE(whole.empty());
    for (std::size_t chunk : {std::size_t{1}, std::size_t{2}, std::size_t{7}, std::size_t{pkg::kMaxPacket},
                              std::size_t{pkg::kMaxPacket + 1}, std::size_t{1000}}) {
        EXPECT_EQ(events(input, chunk), whole) << "chunk " << chunk;
    }
    // every byte is accounted for, in order
    std::uint64_t pos = 0;
    for (const Event &e : whole) {
        EXPECT_EQ(e.offset, pos);
        pos += e.count;
    }
    EXPECT_EQ(pos, input.size());
}

TEST(Fields, TrailingMessages) {
    const std::uint8_t one[] = {0x05};
    pkg::FieldIterator a(0x01, one, 1);
    pkg::FieldEntry e;
    ASSERT_TRUE(a.next(e));
    EXPECT_EQ(e.kind, pkg::FieldEntry::Kind::trailing);
    EXPECT_STREQ(e.text().c_str(), "field header at payload offset 0 needs 2 bytes, 1 left");
    EXPECT_FALSE(a.next(e));

    std::uint8_t two[2] = {};
    two[pkg::kFieldLengthOffset] = 200;
    two[pkg::kFieldDescriptorOffset] = 0x01;
    pkg::FieldIterator b(0x01, two, 2);
    ASSERT_TRUE(b.next(e));
    EXPECT_STREQ(e.text().c_str(),
                 "field length 200 at payload offset 0 overruns the payload (2 bytes left)");
    if (pkg::kFieldLengthCountsHeader) {
        two[pkg::kFieldLengthOffset] = 1;
        pkg::FieldIterator c(0x01, two, 2);
        ASSERT_TRUE(c.next(e));
        EXPECT_STREQ(e.text().c_str(), "field length 1 at payload offset 0 is shorter than the field header");
    }
}

// Issue 28: a view over a user's buffer is read within its size, whatever the length byte says.
TEST(Fields, ViewOfATruncatedBufferIsReadWithinItsSize) {
    pkg::PacketBuilder b(0x01);
    const std::uint8_t data[6] = {1, 2, 3, 4, 5, 6};
    ASSERT_EQ(b.add_raw_field(0x01, data, sizeof data), pkg::EncodeError::none);
    const pkg::PacketView whole = b.finish();
    ASSERT_TRUE(whole.valid());
    // A heap copy cut after the first payload byte: ASan reports any read past it.
    const std::size_t cut = pkg::kHeaderSize + 1;
    std::vector<std::uint8_t> heap(whole.data, whole.data + cut);
    const pkg::PacketView view{heap.data(), heap.size()};
    EXPECT_FALSE(view.valid());
    EXPECT_EQ(view.set(), 0x01);
    EXPECT_EQ(view.payload_size(), 1u);
    pkg::FieldIterator it(view);
    pkg::FieldEntry e;
    ASSERT_TRUE(it.next(e));
    EXPECT_EQ(e.kind, pkg::FieldEntry::Kind::trailing);
    EXPECT_EQ(e.size, 1u);
    EXPECT_FALSE(it.next(e));
    // Shorter than a header, empty, or null: nothing to read.
    std::vector<std::uint8_t> two(whole.data, whole.data + 2);
    for (const pkg::PacketView v : {pkg::PacketView{two.data(), two.size()}, pkg::PacketView{}}) {
        EXPECT_FALSE(v.valid());
        EXPECT_EQ(v.set(), 0);
        EXPECT_EQ(v.payload_size(), 0u);
        pkg::FieldIterator none(v);
        EXPECT_FALSE(none.next(e));
    }
    // Without its checksum the payload is whole but the view is not a packet.
    std::vector<std::uint8_t> no_sum(whole.data, whole.data + whole.size - pkg::kChecksumSize);
    const pkg::PacketView unsummed{no_sum.data(), no_sum.size()};
    EXPECT_FALSE(unsummed.valid());
    EXPECT_EQ(unsummed.payload_size(), pkg::kFieldHeaderSize + sizeof data);
}

Bytes stamped(std::uint8_t stamp, bool key, std::uint8_t descriptor, char data) {
    pkg::PacketBuilder b(pkg::sample_rule::kDataSets[0]);
    const auto &ts = pkg::sample_rule::kTimestamps[0];
    const Bytes value(ts.size, stamp);
    if (key) {
        EXPECT_EQ(b.add_raw_field(ts.descriptor, value.data(), value.size()), pkg::EncodeError::none);
    }
    const std::uint8_t d = static_cast<std::uint8_t>(data);
    EXPECT_EQ(b.add_raw_field(descriptor, &d, 1), pkg::EncodeError::none);
    const pkg::PacketView p = b.finish();
    return Bytes(p.data, p.data + p.size);
}

TEST(Samples, GrouperMergesContinuationPackets) {
    const std::vector<Bytes> packets = {stamped(1, true, 0x01, 'a'), stamped(1, true, 0x02, 'b'),
                                        stamped(2, true, 0x03, 'c'), stamped(0, false, 0x04, 'd')};
    pkg::SampleTracker tracker;
    std::vector<std::pair<std::uint64_t, bool>> places;
    for (const Bytes &p : packets) {
        const auto place = tracker.feed(pkg::PacketView{p.data(), p.size()});
        ASSERT_TRUE(place.has_value());
        places.emplace_back(place->number, place->continues);
    }
    const std::vector<std::pair<std::uint64_t, bool>> want = {{0, false}, {0, true}, {1, false}, {2, false}};
    EXPECT_EQ(places, want);
    pkg::SampleGrouper grouper;
    std::vector<pkg::Sample> done;
    auto keep = [&](pkg::Sample &&s) { done.push_back(std::move(s)); };
    for (std::size_t i = 0; i < packets.size(); ++i) {
        grouper.feed(pkg::PacketView{packets[i].data(), packets[i].size()}, i * 100, keep);
    }
    ASSERT_EQ(done.size(), 2u);
    EXPECT_EQ(done[0].number, 0u);
    EXPECT_EQ(done[1].number, 1u);
    EXPECT_EQ(done[0].offsets, (std::vector<std::uint64_t>{0, 100}));
    std::vector<std::uint8_t> descriptors;
    done[0].for_each_field([&](const pkg::FieldEntry &e) { descriptors.push_back(e.descriptor); });
    EXPECT_EQ(descriptors,
              (std::vector<std::uint8_t>{pkg::sample_rule::kTimestamps[0].descriptor, 0x01, 0x02}));
    grouper.flush(keep);
    ASSERT_EQ(done.size(), 3u);
    EXPECT_EQ(done[2].number, 2u);
    descriptors.clear();
    done[2].for_each_field([&](const pkg::FieldEntry &e) { descriptors.push_back(e.descriptor); });
    EXPECT_EQ(descriptors, (std::vector<std::uint8_t>{0x04}));
    pkg::PacketBuilder command(0x01);
    EXPECT_FALSE(tracker.feed(command.finish()).has_value());
}

} // namespace
