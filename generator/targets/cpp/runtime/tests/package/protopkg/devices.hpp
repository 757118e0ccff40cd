// Stub package "protopkg" for the in-place runtime tests: hand-written in the shape of the
// generated devices.hpp (templates/cpp/include/devices.hpp.j2), two devices.
#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <optional>

namespace protopkg {

enum class Device : std::uint8_t {
    gx,
    cv,
};

inline constexpr std::array<Device, 2> kDevices = {Device::gx, Device::cv};

inline const char *device_name(Device d) {
    switch (d) {
    case Device::gx:
        return "gx";
    case Device::cv:
        return "cv";
    }
    return "";
}

inline constexpr const char *device_title(Device d) {
    return d == Device::gx ? "GX" : "CV";
}

inline constexpr const char *device_manual(Device d) {
    return d == Device::gx ? "gx.txt" : "cv.txt";
}

// Both devices support ping (0x01,0x01) and info (0x01,0x02); switch (0x01,0x03) is gx's only.
inline constexpr bool device_supports(Device d, std::uint8_t set, std::uint8_t descriptor) {
    return set == 0x01 &&
           (descriptor == 0x01 || descriptor == 0x02 || (descriptor == 0x03 && d == Device::gx));
}

inline std::optional<Device> device_from_name(const char *name) {
    if (std::strcmp(name, "gx") == 0) {
        return Device::gx;
    }
    if (std::strcmp(name, "cv") == 0) {
        return Device::cv;
    }
    return std::nullopt;
}

} // namespace protopkg
