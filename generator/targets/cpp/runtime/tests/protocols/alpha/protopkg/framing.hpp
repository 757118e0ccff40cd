// Test protocol "alpha": hand-written constants in the shape of a package's generated
// include/<pkg>/framing.hpp (templates/cpp/include/framing.hpp.j2), for the in-place runtime tests.
// MIP-like framing: two sync bytes, set before length, field length counting the field header,
// big-endian values, checksum sums in order, shared timestamps from 0xD0.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace protopkg {

inline constexpr std::array<std::uint8_t, 2> kSync = {0x75, 0x65};
inline constexpr std::size_t kSyncSize = 2;
inline constexpr std::size_t kHeaderSize = 4;
inline constexpr std::size_t kSetOffset = 2;
inline constexpr std::size_t kLengthOffset = 3;
inline constexpr std::size_t kFieldHeaderSize = 2;
inline constexpr std::size_t kFieldLengthOffset = 0;
inline constexpr std::size_t kFieldDescriptorOffset = 1;
inline constexpr bool kFieldLengthCountsHeader = true;
inline constexpr std::size_t kFieldLengthAdjust = 2;
constexpr int field_length_adjust(std::uint8_t set, std::uint8_t descriptor) {
    (void)set;
    (void)descriptor;
    return static_cast<int>(kFieldLengthAdjust);
}
inline constexpr std::size_t kMaxPayload = 255;
inline constexpr std::size_t kChecksumSize = 2;
inline constexpr std::size_t kSum1Index = 0;
inline constexpr std::size_t kSum2Index = 1;
inline constexpr std::size_t kMaxPacket = 261;
inline constexpr std::size_t kMaxFieldData = 253;
inline constexpr bool kBigEndian = true;

inline constexpr std::size_t kMaxErrorPath = 48;
inline constexpr std::size_t kMaxJsonDepth = 11;

namespace sample_rule {
inline constexpr std::array<std::uint8_t, 2> kDataSets = {0x80, 0x82};
inline constexpr unsigned kFirstShared = 0xD0;
struct Timestamp {
    std::uint8_t descriptor;
    std::size_t size;
};
inline constexpr std::array<Timestamp, 2> kTimestamps = {{{0xD3, 12}, {0xD5, 8}}};
inline constexpr std::size_t kMaxKey = 24; // both timestamps with their field headers
constexpr bool is_shared(std::uint8_t descriptor) {
    return descriptor >= kFirstShared;
}
} // namespace sample_rule

} // namespace protopkg
