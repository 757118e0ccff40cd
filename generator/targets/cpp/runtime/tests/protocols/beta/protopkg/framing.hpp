// Test protocol "beta": hand-written constants in the shape of a package's generated
// include/<pkg>/framing.hpp (templates/cpp/include/framing.hpp.j2), for the in-place runtime tests.
// Everything alpha does not do: three sync bytes, length before set, descriptor before length in
// the field header, a length byte of the data alone (one field with its own adjustment),
// little-endian values, checksum sums swapped, one shared timestamp of 4 bytes from 0xF0.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace protopkg {

inline constexpr std::array<std::uint8_t, 3> kSync = {0xAA, 0x44, 0x12};
inline constexpr std::size_t kSyncSize = 3;
inline constexpr std::size_t kHeaderSize = 5;
inline constexpr std::size_t kSetOffset = 4;
inline constexpr std::size_t kLengthOffset = 3;
inline constexpr std::size_t kFieldHeaderSize = 2;
inline constexpr std::size_t kFieldLengthOffset = 1;
inline constexpr std::size_t kFieldDescriptorOffset = 0;
inline constexpr bool kFieldLengthCountsHeader = false;
inline constexpr std::size_t kFieldLengthAdjust = 0;
constexpr int field_length_adjust(std::uint8_t set, std::uint8_t descriptor) {
    if (set == 0x0C && descriptor == 0x01) {
        return static_cast<int>(kFieldLengthAdjust) + (1);
    }
    return static_cast<int>(kFieldLengthAdjust);
}
inline constexpr std::size_t kMaxPayload = 255;
inline constexpr std::size_t kChecksumSize = 2;
inline constexpr std::size_t kSum1Index = 1;
inline constexpr std::size_t kSum2Index = 0;
inline constexpr std::size_t kMaxPacket = 262;
inline constexpr std::size_t kMaxFieldData = 253;
inline constexpr bool kBigEndian = false;

inline constexpr std::size_t kMaxErrorPath = 40;
inline constexpr std::size_t kMaxJsonDepth = 10;

namespace sample_rule {
inline constexpr std::array<std::uint8_t, 1> kDataSets = {0x90};
inline constexpr unsigned kFirstShared = 0xF0;
struct Timestamp {
    std::uint8_t descriptor;
    std::size_t size;
};
inline constexpr std::array<Timestamp, 1> kTimestamps = {{{0xF1, 4}}};
inline constexpr std::size_t kMaxKey = 6; // the timestamp with its field header
constexpr bool is_shared(std::uint8_t descriptor) {
    return descriptor >= kFirstShared;
}
} // namespace sample_rule

} // namespace protopkg
