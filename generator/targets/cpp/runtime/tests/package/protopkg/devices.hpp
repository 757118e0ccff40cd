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
