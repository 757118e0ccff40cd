// Hand-written stand-in for the generated session_facts.hpp of the stub package: the ack field is
// descriptor 0xF1 (data: echoed descriptor, code; 0 is success), decoded by hand here as the
// stub's lookup has no layout for it. Rows: Ping (expects reply field 0x02 when `flags` is
// non-zero), Info per device (gx, cv), Switch (ack suppressed when `on`; 500 ms allowance).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "protopkg/devices.hpp"
#include "protopkg/fields.hpp"
#include "protopkg/session_types.hpp"

namespace protopkg {

inline constexpr bool kHasAckRule = true;
inline constexpr std::uint8_t kAckDescriptor = 0xF1;
inline constexpr std::int64_t kAckOk = 0;

inline bool decode_ack(std::uint8_t set, const std::uint8_t *data, std::size_t size,
                       const std::optional<Device> &device, std::uint8_t &echo, std::int64_t &code) {
    (void)set;
    (void)device;
    if (size != 2) {
        return false;
    }
    echo = data[0];
    code = data[1];
    return true;
}

inline const char *function_name(std::int64_t value) {
    (void)value;
    return nullptr;
}

inline std::uint32_t function_devices(std::int64_t value) {
    (void)value;
    return 0;
}

namespace detail {
inline constexpr ReplyRule kReplies0[] = {{0x02, -1, 0, false, 0}};
} // namespace detail

inline constexpr std::array<CommandRow, 4> kCommandRows = {{
    {0x01, 0x01, "ping", -1, 0x3u, false, 0, detail::kReplies0, 1, 0, -1, false, 0, false, 0, -1, true, 0},
    {0x01, 0x02, "info", 0, 0x1u, false, 0, nullptr, 0, 0, -1, false, 0, false, 0, -1, true, 0},
    {0x01, 0x02, "info", 1, 0x2u, false, 0, nullptr, 0, 0, -1, false, 0, false, 0, -1, true, 0},
    {0x01, 0x03, "switch", -1, 0x1u, false, 0, nullptr, 0, 2, 0, false, 0, true, 500u, -1, true, 0},
}};

template <> struct CommandTraits<stub::Ping> {
    static constexpr bool kCommand = true;
    static constexpr std::size_t kRow = 0;
    static std::optional<std::int64_t> function(const stub::Ping &) {
        return std::nullopt;
    }
    static std::optional<std::int64_t> param(const stub::Ping &v, std::int8_t slot) {
        return slot == 0 ? std::optional<std::int64_t>(v.flags) : std::nullopt;
    }
};
template <> struct CommandTraits<stub::InfoGx> {
    static constexpr bool kCommand = true;
    static constexpr std::size_t kRow = 1;
    static std::optional<std::int64_t> function(const stub::InfoGx &) {
        return std::nullopt;
    }
    static std::optional<std::int64_t> param(const stub::InfoGx &, std::int8_t) {
        return std::nullopt;
    }
};
template <> struct CommandTraits<stub::InfoCv> {
    static constexpr bool kCommand = true;
    static constexpr std::size_t kRow = 2;
    static std::optional<std::int64_t> function(const stub::InfoCv &) {
        return std::nullopt;
    }
    static std::optional<std::int64_t> param(const stub::InfoCv &, std::int8_t) {
        return std::nullopt;
    }
};
template <> struct CommandTraits<stub::Switch> {
    static constexpr bool kCommand = true;
    static constexpr std::size_t kRow = 3;
    static std::optional<std::int64_t> function(const stub::Switch &) {
        return std::nullopt;
    }
    static std::optional<std::int64_t> param(const stub::Switch &v, std::int8_t slot) {
        return slot == 0 ? std::optional<std::int64_t>(v.on ? 1 : 0) : std::nullopt;
    }
};

} // namespace protopkg
