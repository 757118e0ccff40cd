// Helpers of the protopkg googletest suite.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

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
    (void)rejected; // rejected cases are one skip run, which also encodes back to the bytes
    EXPECT_EQ(to_hex(encode_lines(expect)), hex) << "encoded back";
}

} // namespace protopkg_test
