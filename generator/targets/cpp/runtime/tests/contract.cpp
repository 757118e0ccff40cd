// The C++ runtime contract (docs/runtime-contract.md, "C++"): everything the runtime headers take
// from the generated ones, stated with the types the runtime uses. Built into the runtime's test
// binary against the package rendered from tests/runtime_specs/ (CMakeLists.txt): a template that
// drops or retypes one of them fails this build.
#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <type_traits>

#include "protopkg/protopkg.hpp"
#include "protopkg/session_facts.hpp"

namespace {

namespace pkg = ::protopkg;

template <typename T, typename U>
constexpr bool is = std::is_same_v<std::remove_cv_t<std::remove_reference_t<T>>, U>;
template <typename T> constexpr bool is_byte_array = false;
template <std::size_t N> constexpr bool is_byte_array<std::array<std::uint8_t, N>> = true;

// framing.hpp
static_assert(is_byte_array<std::remove_cv_t<decltype(pkg::kSync)>> && pkg::kSync.size() == pkg::kSyncSize);
static_assert(is<decltype(pkg::kSyncSize), std::size_t> && is<decltype(pkg::kHeaderSize), std::size_t> &&
              is<decltype(pkg::kSetOffset), std::size_t> && is<decltype(pkg::kLengthOffset), std::size_t>);
static_assert(is<decltype(pkg::kFieldHeaderSize), std::size_t> &&
              is<decltype(pkg::kFieldLengthOffset), std::size_t> &&
              is<decltype(pkg::kFieldDescriptorOffset), std::size_t> &&
              is<decltype(pkg::kFieldLengthCountsHeader), bool> &&
              is<decltype(pkg::kFieldLengthAdjust), std::size_t>);
static_assert(is<decltype(pkg::field_length_adjust(std::uint8_t{}, std::uint8_t{})), int>);
static_assert(is<decltype(pkg::kMaxPayload), std::size_t> && is<decltype(pkg::kChecksumSize), std::size_t> &&
              is<decltype(pkg::kSum1Index), std::size_t> && is<decltype(pkg::kSum2Index), std::size_t> &&
              is<decltype(pkg::kMaxPacket), std::size_t> && is<decltype(pkg::kMaxFieldData), std::size_t>);
static_assert(is<decltype(pkg::kBigEndian), bool> && is<decltype(pkg::kMaxErrorPath), std::size_t> &&
              is<decltype(pkg::kMaxJsonDepth), std::size_t>);
static_assert(pkg::kMaxPacket == pkg::kHeaderSize + pkg::kMaxPayload + pkg::kChecksumSize);
static_assert(is<decltype(pkg::kClockBucketNs), std::int64_t> &&
              is<decltype(pkg::kClockBuckets), std::size_t> &&
              is<decltype(pkg::kClockMinBuckets), std::size_t> &&
              is<decltype(pkg::kClockRestartNs), std::int64_t>);
static_assert(is_byte_array<std::remove_cv_t<decltype(pkg::sample_rule::kDataSets)>> &&
              is<decltype(pkg::sample_rule::kFirstShared), unsigned> &&
              is<decltype(pkg::sample_rule::kTimestamps[0].descriptor), std::uint8_t> &&
              is<decltype(pkg::sample_rule::kTimestamps[0].size), std::size_t> &&
              is<decltype(pkg::sample_rule::kMaxKey), std::size_t> &&
              is<decltype(pkg::sample_rule::is_shared(std::uint8_t{})), bool>);

// devices.hpp
static_assert(std::is_enum_v<pkg::Device>);
static_assert(is<decltype(pkg::kDevices[0]), pkg::Device>);
static_assert(is<decltype(pkg::device_name(pkg::Device{})), const char *>);
static_assert(is<decltype(pkg::device_from_name("")), std::optional<pkg::Device>>);
static_assert(is<decltype(pkg::device_title(pkg::Device{})), const char *>);
static_assert(is<decltype(pkg::device_manual(pkg::Device{})), const char *>);
static_assert(is<decltype(pkg::device_supports(pkg::Device{}, std::uint8_t{}, std::uint8_t{})), bool>);
static_assert(is<decltype(pkg::kLinkIdle), pkg::LinkCommand> &&
              is<decltype(pkg::kLinkPing), pkg::LinkCommand> &&
              is<decltype(pkg::kLinkResume), pkg::LinkCommand> &&
              is<decltype(pkg::kLinkIdle.present), bool> && is<decltype(pkg::kLinkIdle.set), std::uint8_t> &&
              is<decltype(pkg::kLinkIdle.descriptor), std::uint8_t>);
static_assert(is<decltype(pkg::kLinkIdleAttempts), unsigned> && is<decltype(pkg::kLinkBaudSettleMs), int> &&
              is<decltype(pkg::kLinkHasBandwidth), bool> && is<decltype(pkg::kLinkUartWordBits), unsigned> &&
              is<decltype(pkg::kLinkPacketOverhead), unsigned> &&
              is<decltype(pkg::kLinkFieldOverhead), unsigned>);
static_assert(is<decltype(pkg::device_baud_rates(pkg::Device{})), pkg::BaudTable> &&
              is<decltype(*pkg::device_baud_rates(pkg::Device{}).begin()), std::uint32_t> &&
              is<decltype(pkg::device_default_baud(pkg::Device{})), std::uint32_t>);
static_assert(is<decltype(pkg::kProtocolName), const char *>);

// lookup_tables.hpp (namespace detail: read by the runtime's lookup.hpp)
static_assert(is<std::remove_all_extents_t<decltype(pkg::detail::kSetRow)>, std::uint8_t> &&
              std::extent_v<decltype(pkg::detail::kSetRow)> == 256);
static_assert(is<std::remove_all_extents_t<decltype(pkg::detail::kFieldCases)>, std::uint8_t> &&
              std::extent_v<decltype(pkg::detail::kFieldCases), 1> == 256);
static_assert(sizeof(pkg::detail::FieldCases) > 0);

// session_facts.hpp
static_assert(is<decltype(pkg::kHasAckRule), bool> && is<decltype(pkg::kAckDescriptor), std::uint8_t> &&
              is<decltype(pkg::kAckOk), std::int64_t>);
static_assert(is<decltype(pkg::kCommandRows[0]), pkg::CommandRow>);
static_assert(is<decltype(pkg::function_name(std::int64_t{})), const char *> &&
              is<decltype(pkg::function_devices(std::int64_t{})), std::uint32_t>);
using DecodeAck = bool (*)(std::uint8_t, const std::uint8_t *, std::size_t,
                           const std::optional<pkg::Device> &, std::uint8_t &, std::int64_t &);
static_assert(std::is_convertible_v<decltype(&pkg::decode_ack), DecodeAck>);

// Per layout and named type (checked on one of each of the test protocol): Json<T> from
// layouts_json.hpp and types_json.hpp, CommandTraits<T> from session_facts.hpp.
static_assert(sizeof(pkg::Json<pkg::control::Ping>) > 0 && sizeof(pkg::Json<pkg::types::Mode>) > 0);
static_assert(sizeof(pkg::CommandTraits<pkg::control::Ping>) > 0 && sizeof(pkg::ReplyRule) > 0);

} // namespace

TEST(Contract, TheRenderedPackageProvidesWhatTheRuntimeTakes) {
    // The checks above are static; this records that they were compiled into the suite.
    EXPECT_EQ(pkg::kSync.size(), pkg::kSyncSize);
    EXPECT_LE(pkg::kHeaderSize + pkg::kChecksumSize, pkg::kMaxPacket);
}
