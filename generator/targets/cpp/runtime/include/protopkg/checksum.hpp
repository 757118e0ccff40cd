// Fletcher-16 checksum (framing.checksum: fletcher16, sums modulo 256).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "protopkg/framing.hpp"

namespace protopkg {

struct Fletcher16 {
    std::uint8_t sum1 = 0;
    std::uint8_t sum2 = 0;

    /// Eight bytes at a time. Over blocks B_0 .. B_{K-1} of eight bytes (block sums S_k, weighted
    /// sums W_k = 8 b0 + 7 b1 + .. + 1 b7) the byte-serial recurrence gives sum1 += sum_k S_k and
    /// sum2 += 8 K sum1 + 8 sum_k (K - 1 - k) S_k + sum_k W_k. Even and odd bytes of a
    /// little-endian word are spread into four 16-bit lanes and summed lane by lane: E, O (even,
    /// odd), R (running sum of both) and Q (sum of R after each block), so sum_k S_k = hsum(R),
    /// sum_k (K - 1 - k) S_k = hsum(Q) - hsum(R), and sum_k W_k comes from E and O with the lane
    /// weights (8, 6, 4, 2) and (7, 5, 3, 1). Only the sums modulo 256 matter: lanes are masked
    /// before they could carry into the next lane, and a multiply by lane constants adds
    /// the lanes into the top one (at most 255 * 20). Unsigned arithmetic wraps modulo 2^64.
    void update(const std::uint8_t *data, std::size_t size) {
        constexpr std::uint64_t kLanes = 0x00FF00FF00FF00FFu;
        constexpr std::uint64_t kOnes = 0x0001000100010001u;
        std::uint64_t s1 = sum1;
        std::uint64_t s2 = sum2;
        std::size_t i = 0;
        if (size >= 8) {
            std::uint64_t e_sum = 0;
            std::uint64_t o_sum = 0;
            std::uint64_t r = 0;
            std::uint64_t q = 0;
            // E, O and R are masked once per run of at most kRun blocks (a lane then stays below
            // 255 + 2 * 255 * kRun < 2^16, so no carry crosses lanes), Q after every block.
            constexpr std::size_t kRun = 32;
            const std::size_t whole = size & ~static_cast<std::size_t>(7);
            while (i < whole) {
                const std::size_t end = whole - i > 8 * kRun ? i + 8 * kRun : whole;
                for (; i < end; i += 8) {
                    const std::uint64_t w = load_le64(data + i);
                    const std::uint64_t even = w & kLanes;
                    const std::uint64_t odd = (w >> 8) & kLanes;
                    e_sum += even;
                    o_sum += odd;
                    r += even + odd;
                    q = (q + r) & kLanes;
                }
                e_sum &= kLanes;
                o_sum &= kLanes;
                r &= kLanes;
            }
            const std::uint64_t blocks = whole / 8;
            const std::uint64_t block_sum = (r * kOnes) >> 48;
            s2 += 8 * blocks * s1 + 8 * (((q * kOnes) >> 48) - block_sum) +
                  ((e_sum * 0x0008000600040002u) >> 48) + ((o_sum * 0x0007000500030001u) >> 48);
            s1 += block_sum;
        }
        for (; i < size; ++i) {
            s1 += data[i];
            s2 += s1;
        }
        sum1 = static_cast<std::uint8_t>(s1);
        sum2 = static_cast<std::uint8_t>(s2);
    }
    /// Eight bytes as a little-endian word on any host (one load on little-endian ones).
    static std::uint64_t load_le64(const std::uint8_t *b) {
        return static_cast<std::uint64_t>(b[0]) | static_cast<std::uint64_t>(b[1]) << 8 |
               static_cast<std::uint64_t>(b[2]) << 16 | static_cast<std::uint64_t>(b[3]) << 24 |
               static_cast<std::uint64_t>(b[4]) << 32 | static_cast<std::uint64_t>(b[5]) << 40 |
               static_cast<std::uint64_t>(b[6]) << 48 | static_cast<std::uint64_t>(b[7]) << 56;
    }
    /// The two checksum bytes in transmission order (framing.checksum.order).
    std::array<std::uint8_t, 2> bytes() const {
        std::array<std::uint8_t, 2> out{};
        out[kSum1Index] = sum1;
        out[kSum2Index] = sum2;
        return out;
    }
};

inline Fletcher16 fletcher16(const std::uint8_t *data, std::size_t size) {
    Fletcher16 f;
    f.update(data, size);
    return f;
}

} // namespace protopkg
