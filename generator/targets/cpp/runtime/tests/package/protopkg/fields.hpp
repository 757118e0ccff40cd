// Stub package "protopkg" for the in-place runtime tests: hand-written layouts in the shape of a
// generated fields/<set>.hpp (templates/cpp/include/fields.hpp.j2). Set 0x01 has Ping (0x01,
// plain), Info (0x02, one layout per device) and Switch (0x03, a bool: never plain).
#pragma once

#include <cstddef>
#include <cstdint>

#include "protopkg/devices.hpp"
#include "protopkg/wire.hpp"

namespace protopkg::stub {

struct Ping {
    static constexpr std::uint8_t kSet = 0x01;
    static constexpr std::uint8_t kDescriptor = 0x01;
    static constexpr const char *kName = "ping";
    static constexpr bool kHasVariants = false;
    static constexpr const char *kDevice = nullptr;

    std::uint16_t value{};
    std::uint8_t flags{};
    friend bool operator==(const Ping &a, const Ping &b) {
        return a.value == b.value && a.flags == b.flags;
    }
};

struct InfoGx {
    static constexpr std::uint8_t kSet = 0x01;
    static constexpr std::uint8_t kDescriptor = 0x02;
    static constexpr const char *kName = "info";
    static constexpr bool kHasVariants = true;
    static constexpr const char *kDevice = "gx";
    static constexpr ::protopkg::Device kDeviceId = ::protopkg::Device::gx;

    std::uint8_t level{};
};

struct InfoCv {
    static constexpr std::uint8_t kSet = 0x01;
    static constexpr std::uint8_t kDescriptor = 0x02;
    static constexpr const char *kName = "info";
    static constexpr bool kHasVariants = true;
    static constexpr const char *kDevice = "cv";
    static constexpr ::protopkg::Device kDeviceId = ::protopkg::Device::cv;

    std::uint16_t level{};
    std::int16_t offset{};
};

struct Switch {
    static constexpr std::uint8_t kSet = 0x01;
    static constexpr std::uint8_t kDescriptor = 0x03;
    static constexpr const char *kName = "switch";
    static constexpr bool kHasVariants = false;
    static constexpr const char *kDevice = nullptr;

    bool on{};
};

} // namespace protopkg::stub

namespace protopkg {

template <> struct Codec<stub::Ping> {
    static constexpr bool kPlain = true;
    static constexpr std::size_t kPlainSize = Plain<std::uint16_t>::kSize + Plain<std::uint8_t>::kSize;
    PROTOPKG_INLINE static void load(const std::uint8_t *p, stub::Ping &v) {
        Plain<std::uint16_t>::load(p, v.value);
        Plain<std::uint8_t>::load(p + Plain<std::uint16_t>::kSize, v.flags);
    }
    static constexpr bool kFixedSize = true;
    static constexpr std::size_t kSize = kPlainSize;
    static bool read(Reader &r, stub::Ping &v, DecodeError &err) {
        if (!read_value(r, v.value, err)) {
            err.enter("value");
            return false;
        }
        if (!read_value(r, v.flags, err)) {
            err.enter("flags");
            return false;
        }
        return true;
    }
    static void write(Writer &w, const stub::Ping &v) {
        write_value(w, v.value);
        write_value(w, v.flags);
    }
};

template <> struct Codec<stub::InfoGx> {
    static constexpr bool kPlain = true;
    static constexpr std::size_t kPlainSize = Plain<std::uint8_t>::kSize;
    PROTOPKG_INLINE static void load(const std::uint8_t *p, stub::InfoGx &v) {
        Plain<std::uint8_t>::load(p, v.level);
    }
    static constexpr bool kFixedSize = true;
    static constexpr std::size_t kSize = kPlainSize;
    static bool read(Reader &r, stub::InfoGx &v, DecodeError &err) {
        if (!read_value(r, v.level, err)) {
            err.enter("level");
            return false;
        }
        return true;
    }
    static void write(Writer &w, const stub::InfoGx &v) {
        write_value(w, v.level);
    }
};

template <> struct Codec<stub::InfoCv> {
    static constexpr bool kPlain = true;
    static constexpr std::size_t kPlainSize = Plain<std::uint16_t>::kSize + Plain<std::int16_t>::kSize;
    PROTOPKG_INLINE static void load(const std::uint8_t *p, stub::InfoCv &v) {
        Plain<std::uint16_t>::load(p, v.level);
        Plain<std::int16_t>::load(p + Plain<std::uint16_t>::kSize, v.offset);
    }
    static constexpr bool kFixedSize = true;
    static constexpr std::size_t kSize = kPlainSize;
    static bool read(Reader &r, stub::InfoCv &v, DecodeError &err) {
        if (!read_value(r, v.level, err)) {
            err.enter("level");
            return false;
        }
        if (!read_value(r, v.offset, err)) {
            err.enter("offset");
            return false;
        }
        return true;
    }
    static void write(Writer &w, const stub::InfoCv &v) {
        write_value(w, v.level);
        write_value(w, v.offset);
    }
};

template <> struct Codec<stub::Switch> {
    static constexpr bool kPlain = false;
    static constexpr bool kFixedSize = true;
    static constexpr std::size_t kSize = 1;
    static bool read(Reader &r, stub::Switch &v, DecodeError &err) {
        if (!read_value(r, v.on, err)) {
            err.enter("on");
            return false;
        }
        return true;
    }
    static void write(Writer &w, const stub::Switch &v) {
        write_value(w, v.on);
    }
};

} // namespace protopkg
