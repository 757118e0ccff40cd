// Fletcher-16 checksum (framing.checksum: fletcher16, sums modulo 256).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

// The vector path is chosen at build time: SSE2 is part of every x86-64 target (AVX2 when the
// consumer builds with it, e.g. -mavx2 or -march=native); other targets, and a build with
// PROTOPKG_FLETCHER_SCALAR defined, use the portable code, which is also the reference the
// vector code is tested against (tests/test_framing.cpp).
#if !defined(PROTOPKG_FLETCHER_SCALAR) && defined(__SSE2__)
#define PROTOPKG_FLETCHER_SSE2 1
#include <emmintrin.h>
#if defined(__AVX2__)
#define PROTOPKG_FLETCHER_AVX2 1
#include <immintrin.h>
#endif
#endif

#include "protopkg/framing.hpp"

/// Inlines a small hot function into its caller (also defined, identically, by wire.hpp).
#if !defined(PROTOPKG_INLINE)
#if defined(__GNUC__) || defined(__clang__)
#define PROTOPKG_INLINE inline __attribute__((always_inline))
#elif defined(_MSC_VER)
#define PROTOPKG_INLINE __forceinline
#else
#define PROTOPKG_INLINE inline
#endif
#endif

namespace protopkg {

struct Fletcher16 {
    std::uint8_t sum1 = 0;
    std::uint8_t sum2 = 0;

    /// Adds bytes to the sums: the vector path where there is one, else update_scalar().
    void update(const std::uint8_t *data, std::size_t size) {
#if defined(PROTOPKG_FLETCHER_SSE2)
        if (size >= 16) {
            update_vector(data, size);
            return;
        }
#endif
        update_scalar(data, size);
    }

    /// Eight bytes at a time. Over blocks B_0 .. B_{K-1} of eight bytes (block sums S_k, weighted
    /// sums W_k = 8 b0 + 7 b1 + .. + 1 b7) the byte-serial recurrence gives sum1 += sum_k S_k and
    /// sum2 += 8 K sum1 + 8 sum_k (K - 1 - k) S_k + sum_k W_k. Even and odd bytes of a
    /// little-endian word are spread into four 16-bit lanes and summed lane by lane: E, O (even,
    /// odd), R (running sum of both) and Q (sum of R after each block), so sum_k S_k = hsum(R),
    /// sum_k (K - 1 - k) S_k = hsum(Q) - hsum(R), and sum_k W_k comes from E and O with the lane
    /// weights (8, 6, 4, 2) and (7, 5, 3, 1). Only the sums modulo 256 matter: lanes are masked
    /// before they could carry into the next lane, and a multiply by lane constants adds
    /// the lanes into the top one (at most 255 * 20). Unsigned arithmetic wraps modulo 2^64.
    void update_scalar(const std::uint8_t *data, std::size_t size) {
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
#if defined(PROTOPKG_FLETCHER_SSE2)
    /// size >= 16. Over blocks of 16 bytes (block sums S_k, weighted sums W_k = 16 b0 + 15 b1 +
    /// .. + 1 b15) the byte-serial recurrence gives sum1 += sum_k S_k and sum2 += 16 (K sum1 +
    /// sum_k sum_{j<k} S_j) + sum_k W_k: S_k by psadbw, W_k by pmaddwd of the bytes widened to
    /// 16 bits, the inner double sum by adding the running S before each block. The last
    /// r = size % 16 bytes are the last 16 bytes of the data with the first 16 - r masked to zero
    /// (weights r .. 1), adding r sum1 + W to sum2: no byte loop. 32-bit lanes wrap modulo 2^32,
    /// a multiple of 256, so no lane ever needs reducing.
    PROTOPKG_INLINE void update_vector(const std::uint8_t *data, std::size_t size) {
        const __m128i zero = _mm_setzero_si128();
        const __m128i w_lo = _mm_set_epi16(9, 10, 11, 12, 13, 14, 15, 16);
        const __m128i w_hi = _mm_set_epi16(1, 2, 3, 4, 5, 6, 7, 8);
        __m128i s = zero;  // running sum of S_k (in lanes 0 and 2)
        __m128i ps = zero; // sum over blocks of s before the block
        __m128i w = zero;  // sum of W_k (four lanes)
        const std::size_t blocks = size / 16;
        std::size_t i = 0;
#if defined(PROTOPKG_FLETCHER_AVX2)
        // Two blocks at a time: block 2m in the low half and 2m + 1 in the high half of a
        // 32-byte load. The high half's inner sum also takes the low half's S (added below
        // through the low half's total, once per pair: ps_pair = 2 s + S_low).
        if (blocks >= 2) {
            const __m256i zero2 = _mm256_setzero_si256();
            const __m256i w2_lo = _mm256_set_m128i(w_lo, w_lo);
            const __m256i w2_hi = _mm256_set_m128i(w_hi, w_hi);
            __m256i s_pair = zero2;  // S of the pairs so far, per half
            __m256i ps_pair = zero2; // sum over pairs of s_pair before the pair
            __m256i low = zero2;     // sum of S of the low halves (their weight in the high halves)
            __m256i w2 = zero2;
            for (; i + 2 <= blocks; i += 2) {
                const __m256i v = _mm256_loadu_si256(reinterpret_cast<const __m256i *>(data + 16 * i));
                const __m256i sad = _mm256_sad_epu8(v, zero2);
                ps_pair = _mm256_add_epi32(ps_pair, s_pair);
                s_pair = _mm256_add_epi32(s_pair, sad);
                low = _mm256_add_epi32(low, _mm256_permute2x128_si256(sad, sad, 0x08));
                w2 = _mm256_add_epi32(w2, _mm256_madd_epi16(_mm256_unpacklo_epi8(v, zero2), w2_lo));
                w2 = _mm256_add_epi32(w2, _mm256_madd_epi16(_mm256_unpackhi_epi8(v, zero2), w2_hi));
            }
            // Per block of a pair, the sum of S before it: low half 2 ps_pair (both halves of every
            // earlier pair); high half the same plus the low half's own S.
            const __m128i ps_lo = _mm256_castsi256_si128(ps_pair);
            const __m128i ps_hi = _mm256_extracti128_si256(ps_pair, 1);
            const __m128i both = _mm_add_epi32(ps_lo, ps_hi);
            ps = _mm_add_epi32(_mm_add_epi32(both, both), _mm256_extracti128_si256(low, 1));
            s = _mm_add_epi32(_mm256_castsi256_si128(s_pair), _mm256_extracti128_si256(s_pair, 1));
            w = _mm_add_epi32(_mm256_castsi256_si128(w2), _mm256_extracti128_si256(w2, 1));
        }
#endif
        for (; i < blocks; ++i) {
            const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i *>(data + 16 * i));
            ps = _mm_add_epi32(ps, s);
            s = _mm_add_epi32(s, _mm_sad_epu8(v, zero));
            w = _mm_add_epi32(w, _mm_madd_epi16(_mm_unpacklo_epi8(v, zero), w_lo));
            w = _mm_add_epi32(w, _mm_madd_epi16(_mm_unpackhi_epi8(v, zero), w_hi));
        }
        // The last r = size % 16 bytes: sum2 += r sum1 (before them) + their weighted sum.
        const std::size_t r = size % 16;
        if (r != 0) {
            alignas(16) static constexpr std::uint8_t kMask[32] = {
                0,    0,    0,    0,    0,    0,    0,    0,    0,    0,    0,
                0,    0,    0,    0,    0,    0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF,
                0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF};
            const __m128i mask = _mm_loadu_si128(reinterpret_cast<const __m128i *>(kMask + r));
            const __m128i v =
                _mm_and_si128(_mm_loadu_si128(reinterpret_cast<const __m128i *>(data + size - 16)), mask);
            // r times the block sums so far: a 16-bit multiply keeps each lane's low 16 bits, and
            // only the low 8 bits of the lane total are kept in the end.
            w = _mm_add_epi32(w, _mm_mullo_epi16(s, _mm_set1_epi16(static_cast<short>(r))));
            w = _mm_add_epi32(w, _mm_madd_epi16(_mm_unpacklo_epi8(v, zero), w_lo));
            w = _mm_add_epi32(w, _mm_madd_epi16(_mm_unpackhi_epi8(v, zero), w_hi));
            s = _mm_add_epi32(s, _mm_sad_epu8(v, zero));
        }
        // sum2 += size sum1 + 16 ps + w (+ r S, folded in above), sum1 += S; one reduction of
        // two vectors: lanes 0 and 2 of s carry S (the psadbw sums), all four of t carry sum2.
        finish(s, _mm_add_epi32(_mm_slli_epi32(ps, 4), w), size);
    }

    /// sum1 += S, sum2 += size sum1 + T, where S is the sum of the lanes 0 and 2 of s (lanes 1 and
    /// 3 are zero) and T the sum of the four lanes of t: both reductions at once.
    PROTOPKG_INLINE void finish(__m128i s, __m128i t, std::size_t size) {
        const __m128i a = _mm_add_epi32(_mm_unpacklo_epi64(s, t), _mm_unpackhi_epi64(s, t));
        const __m128i b = _mm_add_epi32(a, _mm_shuffle_epi32(a, 0xB1));
        const auto total_s = static_cast<std::uint32_t>(_mm_cvtsi128_si32(b));
        const auto total_t = static_cast<std::uint32_t>(_mm_cvtsi128_si32(_mm_unpackhi_epi64(b, b)));
        const std::uint32_t s1 = sum1;
        sum2 = static_cast<std::uint8_t>(sum2 + static_cast<std::uint32_t>(size) * s1 + total_t);
        sum1 = static_cast<std::uint8_t>(s1 + total_s);
    }
#endif

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

/// True when sums[0..2) is the checksum of data[0..size) in transmission order: the stream
/// parser's test of every candidate packet, inlined there.
PROTOPKG_INLINE bool fletcher16_matches(const std::uint8_t *data, std::size_t size,
                                        const std::uint8_t *sums) {
    Fletcher16 f;
#if defined(PROTOPKG_FLETCHER_SSE2)
    if (size >= 16) {
        f.update_vector(data, size);
    } else {
        f.update_scalar(data, size);
    }
#else
    f.update_scalar(data, size);
#endif
    return sums[kSum1Index] == f.sum1 && sums[kSum2Index] == f.sum2;
}

} // namespace protopkg
