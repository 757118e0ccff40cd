// Helpers of the in-place runtime tests: a stream parser's events, packets built by PacketBuilder,
// bytes that never start a sync. Written against the test protocol's constants (protocols/*/).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <vector>

#include <gtest/gtest.h>

#include "protopkg/packet.hpp"
#include "protopkg/parser.hpp"

namespace runtime_test {

namespace pkg = ::protopkg;
using Bytes = std::vector<std::uint8_t>;

/// A parser event reduced to what the stream contract fixes: packet or skip, offset, byte count.
struct Event {
    bool packet;
    std::uint64_t offset;
    std::uint64_t count;
    bool operator==(const Event &o) const {
        return packet == o.packet && offset == o.offset && count == o.count;
    }
};

/// The events of a parser fed `input` in chunks of `chunk` bytes, then flushed.
inline std::vector<Event> events(const Bytes &input, std::size_t chunk) {
    pkg::StreamParser parser;
    std::vector<Event> out;
    auto on = [&](const pkg::StreamEvent &e) {
        if (e.kind == pkg::StreamEvent::Kind::packet) {
            out.push_back({true, e.offset, e.packet.size});
        } else {
            out.push_back({false, e.offset, e.count});
        }
    };
    for (std::size_t pos = 0; pos < input.size(); pos += chunk) {
        parser.feed(input.data() + pos, std::min(chunk, input.size() - pos), on);
    }
    parser.flush(on);
    return out;
}

/// Bytes that can never start a sync sequence.
inline Bytes garbage(std::size_t n, std::uint8_t seed) {
    Bytes out;
    for (std::size_t i = 0; i < n; ++i) {
        std::uint8_t b = static_cast<std::uint8_t>(seed + 37 * i);
        if (b == pkg::kSync[0]) {
            b = static_cast<std::uint8_t>(b + 1);
        }
        out.push_back(b);
    }
    return out;
}

/// A valid packet carrying one raw field with `n` data bytes.
inline Bytes packet(std::uint8_t set, std::uint8_t descriptor, std::size_t n) {
    pkg::PacketBuilder b(set);
    Bytes data(n);
    for (std::size_t i = 0; i < n; ++i) {
        data[i] = static_cast<std::uint8_t>(i * 7 + 1);
    }
    EXPECT_EQ(b.add_raw_field(descriptor, data.data(), data.size()), pkg::EncodeError::none);
    const pkg::PacketView p = b.finish();
    return Bytes(p.data, p.data + p.size);
}

inline Bytes cat(std::initializer_list<Bytes> parts) {
    Bytes out;
    for (const Bytes &p : parts) {
        out.insert(out.end(), p.begin(), p.end());
    }
    return out;
}

} // namespace runtime_test
