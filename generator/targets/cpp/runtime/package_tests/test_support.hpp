// Helpers of the protopkg googletest suite.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "protopkg/packets.hpp"
#include "protopkg/protopkg.hpp"

namespace protopkg_test {

inline std::vector<std::uint8_t> from_hex(const std::string &hex) {
    std::vector<std::uint8_t> out;
    for (std::size_t i = 0; i + 1 < hex.size(); i += 2) {
        out.push_back(static_cast<std::uint8_t>(std::stoul(hex.substr(i, 2), nullptr, 16)));
    }
    return out;
}

inline std::string to_hex(const std::vector<std::uint8_t> &bytes) {
    static const char digits[] = "0123456789abcdef";
    std::string out;
    for (std::uint8_t b : bytes) {
        out.push_back(digits[b >> 4]);
        out.push_back(digits[b & 15]);
    }
    return out;
}

/// Canonical JSON lines of a stream fed `chunk` bytes at a time.
inline std::vector<std::string> decode_lines(const std::vector<std::uint8_t> &bytes, std::size_t chunk,
                                             const char *device) {
    std::optional<protopkg::Device> dev;
    if (device != nullptr) {
        dev = protopkg::device_from_name(device);
        EXPECT_TRUE(dev.has_value()) << "unknown device " << device;
    }
    std::vector<std::string> out;
    protopkg::decode_to_json_lines(bytes.data(), bytes.size(), chunk, dev,
                                   [&](const std::string &line) { out.push_back(line); });
    return out;
}

/// Bytes of JSON lines, as the encode tool writes them.
inline std::vector<std::uint8_t> encode_lines(const std::vector<std::string> &lines) {
    std::vector<std::uint8_t> out;
    for (const std::string &line : lines) {
        std::string error;
        EXPECT_TRUE(protopkg::encode_json_line(line, out, error)) << line << "\n" << error;
    }
    return out;
}

/// One decoded field as the comparison below sees it: descriptor and encoded data.
using Decoded = std::pair<std::uint8_t, std::vector<std::uint8_t>>;

template <class T> Decoded decoded_of(const T &value) {
    std::vector<std::uint8_t> buf(protopkg::kMaxPayload + 1);
    std::size_t n = 0;
    if (protopkg::encode(value, buf.data(), buf.size(), n) != protopkg::EncodeError::none) {
        return {T::kDescriptor, {0xEE, 0xEE}}; // an encode error: never equal to a field's data
    }
    buf.resize(n);
    return {T::kDescriptor, buf};
}

/// What a straight-line decode gave: the decoded fields in packet order (encoded) and the payload
/// offsets of the entries left to other.
struct StraightLine {
    bool has_index = false;
    std::vector<Decoded> fields;
    std::vector<std::size_t> other;
    bool operator==(const StraightLine &o) const {
        return has_index == o.has_index && fields == o.fields && other == o.other;
    }
};

/// decode (protopkg::decode_packet, or a LayoutCache's decode) of one packet.
template <class Decode>
StraightLine straight_line(const protopkg::PacketView &packet, protopkg::AnyPacket &any, Decode &&decode) {
    StraightLine out;
    const protopkg::PacketIndex *index =
        decode(packet, any, [&out](const protopkg::FieldEntry &e) { out.other.push_back(e.payload_offset); });
    out.has_index = index != nullptr;
    if (index != nullptr && index != any.index()) {
        out.other.push_back(999999); // the index of another set's member: a mismatch
    }
    any.visit([&out](const auto &value) { out.fields.push_back(decoded_of(value)); });
    return out;
}

/// decode_field's visitor: takes a field of a single layout (the straight-line decoder's members).
struct TakeSingleLayout {
    StraightLine &out;
    bool &taken;
    template <class T> void field(const T &value) {
        if constexpr (!T::kHasVariants) {
            out.fields.push_back(decoded_of(value));
            taken = true;
        }
    }
    void raw(const protopkg::DecodeError &) {}
};

/// The general dispatch (decode_field) of one packet, as the straight-line decoder must give it:
/// each field decoded with a field's only layout (the first time its descriptor occurs) in
/// packet order, every other entry (variants, unknown, does not decode, repeated, trailing) left.
inline StraightLine general_of(const protopkg::PacketView &packet, bool has_index) {
    StraightLine out;
    out.has_index = has_index;
    const std::uint8_t set = packet.set();
    protopkg::FieldIterator it(packet);
    protopkg::FieldEntry e;
    bool seen[256] = {};
    const std::optional<protopkg::Device> any;
    while (it.next(e)) {
        bool taken = false;
        if (has_index && e.kind == protopkg::FieldEntry::Kind::field && !seen[e.descriptor]) {
            protopkg::decode_field(set, e.descriptor, e.data, e.size, any, TakeSingleLayout{out, taken});
        }
        if (taken) {
            seen[e.descriptor] = true;
        } else {
            out.other.push_back(e.payload_offset);
        }
    }
    return out;
}

/// The straight-line decoder (protopkg::decode_packet, issue 38) and the layout cache against the
/// general dispatch on every packet of a stream: "" when they agree, else what differs. The cache
/// sees the packets twice (the second time its shapes are known).
inline std::string straight_line_mismatch(const std::vector<std::uint8_t> &bytes) {
    std::vector<std::vector<std::uint8_t>> packets;
    protopkg::StreamParser parser;
    auto keep = [&packets](const protopkg::StreamEvent &ev) {
        if (ev.kind == protopkg::StreamEvent::Kind::packet) {
            packets.emplace_back(ev.packet.data, ev.packet.data + ev.packet.size);
        }
    };
    parser.feed(bytes.data(), bytes.size(), keep);
    parser.flush(keep);
    const auto any = std::make_unique<protopkg::AnyPacket>();
    const auto cache = std::make_unique<protopkg::LayoutCache>();
    for (int round = 0; round < 2; ++round) {
        for (const std::vector<std::uint8_t> &pk : packets) {
            const protopkg::PacketView view{pk.data(), pk.size()};
            const StraightLine straight = straight_line(
                view, *any, [](const protopkg::PacketView &p, protopkg::AnyPacket &a, auto &&other) {
                    return protopkg::decode_packet(p, a, other);
                });
            const StraightLine general = general_of(view, straight.has_index);
            const std::string where = "set " + std::to_string(view.set()) + " packet " + to_hex(pk);
            if (!(straight == general)) {
                return where + ": the straight-line decoder differs from the general dispatch";
            }
            const StraightLine cached = straight_line(
                view, *any, [&cache](const protopkg::PacketView &p, protopkg::AnyPacket &a, auto &&other) {
                    return cache->decode(p, a, other);
                });
            if (!(cached == general)) {
                return where + ": the layout cache differs from the general dispatch (round " +
                       std::to_string(round) + ")";
            }
        }
    }
    return "";
}

/// A golden vector: decode whole and one byte at a time, then encode the lines back.
inline void check_vector(const std::string &hex, const char *device, bool rejected,
                         const std::vector<std::string> &expect) {
    const std::vector<std::uint8_t> bytes = from_hex(hex);
    EXPECT_EQ(decode_lines(bytes, bytes.size() + 1, device), expect) << "decoded whole";
    // Every chunking: the events must not depend on how the input is split (the first size that
    // differs is reported, not every one).
    for (std::size_t chunk = 1; chunk < bytes.size(); ++chunk) {
        const std::vector<std::string> got = decode_lines(bytes, chunk, device);
        if (got != expect) {
            EXPECT_EQ(got, expect) << "decoded in chunks of " << chunk << " bytes";
            break;
        }
    }
    EXPECT_EQ(straight_line_mismatch(bytes), "") << "straight-line decode";
    (void)rejected; // rejected cases are one skip run, which also encodes back to the bytes
    EXPECT_EQ(to_hex(encode_lines(expect)), hex) << "encoded back";
}

} // namespace protopkg_test
