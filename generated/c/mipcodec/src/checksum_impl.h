/* Fletcher-16 sums shared by framing.c (the checksum API) and parser.c (the stream parser's
 * inlined checksum test): static inline functions, private to the package (not installed).
 * Generated: do not edit. */
#ifndef MIPC_CHECKSUM_IMPL_H
#define MIPC_CHECKSUM_IMPL_H

#include "mipcodec/framing.h"

/* Fletcher-16 sums in progress: both are only ever read modulo 256, so any wider unsigned
 * arithmetic that wraps (modulo 2^32 or 2^64, multiples of 256) gives the same checksum. */
typedef struct {
    uint64_t s1;
    uint64_t s2;
} sums_t;

/* The byte-serial definition, for what is left after the wider steps. */
static inline sums_t sums_bytes(sums_t s, const uint8_t *bytes, size_t len) {
    size_t i;
    for (i = 0; i < len; i++) {
        s.s1 += bytes[i];
        s.s2 += s.s1;
    }
    return s;
}

/* Eight bytes as a little-endian word, whatever the host's byte order (compilers make this one
 * load on little-endian hosts). */
static inline uint64_t load_le64(const uint8_t *b) {
    return (uint64_t)b[0] | (uint64_t)b[1] << 8 | (uint64_t)b[2] << 16 | (uint64_t)b[3] << 24 |
           (uint64_t)b[4] << 32 | (uint64_t)b[5] << 40 | (uint64_t)b[6] << 48 | (uint64_t)b[7] << 56;
}

/*
 * The portable implementation (every target, the only one on Cortex-M and big-endian hosts):
 * eight bytes at a time in a 64-bit register. Over words B_0 .. B_{K-1} of eight bytes (word
 * sums S_k, weighted sums W_k = 8 b0 + 7 b1 + .. + 1 b7) the byte-serial recurrence gives
 * sum1 = sum1_0 + sum_k S_k and sum2 = sum2_0 + 8 K sum1_0 + 8 sum_k (K - 1 - k) S_k + sum_k W_k.
 * The even and odd bytes of a little-endian word are spread into four 16-bit lanes and summed
 * lane by lane:
 *   E, O = sum of the even, odd lanes; Q = sum of E + O after each word,
 * so sum_k S_k = hsum(E + O), sum_k (K - 1 - k) S_k = hsum(Q) - hsum(E + O) and sum_k W_k comes
 * from E and O with the lane weights (8, 6, 4, 2) and (7, 5, 3, 1).
 * No lane may carry into the next: over a run of n words a lane of E or O reaches at most 255 n,
 * and Q, reduced modulo 256 (masked: only the sums modulo 256 matter) after each add, at most
 * 255 + 510 n; both stay below 65536 for n <= 128 (1024 bytes, more than a packet). So words go
 * in runs of at most 128 with one mask per word; after a run every lane is reduced, a multiply by
 * lane constants adds the lanes into the top one (at most 255 * 20) and the run's sums are folded
 * into sum1 and sum2 with the recurrence above.
 */
static inline sums_t sums_scalar(sums_t s, const uint8_t *bytes, size_t len) {
    const uint64_t lanes = 0x00FF00FF00FF00FFu;
    const uint64_t ones = 0x0001000100010001u;
    size_t i = 0;
    while (len - i >= 8) {
        size_t words = (len - i) / 8;
        size_t end;
        uint64_t e = 0;
        uint64_t o = 0;
        uint64_t q = 0;
        uint64_t r1;
        if (words > 128) {
            words = 128;
        }
        end = i + 8 * words;
        for (; i < end; i += 8) {
            uint64_t w = load_le64(bytes + i);
            e += w & lanes;        /* b0, b2, b4, b6 */
            o += (w >> 8) & lanes; /* b1, b3, b5, b7 */
            q = (q + e + o) & lanes;
        }
        e &= lanes;
        o &= lanes;
        r1 = ((e + o) * ones) >> 48;
        s.s2 += 8 * words * s.s1 + 8 * (((q * ones) >> 48) - r1) + ((e * 0x0008000600040002u) >> 48) +
                ((o * 0x0007000500030001u) >> 48);
        s.s1 += r1;
    }
    return sums_bytes(s, bytes + i, len - i);
}

/*
 * Vector implementations (x86-64: SSE2 always, AVX2 when the CPU has it, chosen at run time).
 * A block of n bytes b_0 .. b_{n-1} moves the sums by sum1 += S, sum2 += n sum1 + W with
 * S = sum b_i and W = sum (n - i) b_i. Over K blocks, with P = sum over blocks of the S of the
 * blocks before it, sum2 += n K sum1_0 + n P + sum W: a vector accumulates S (psadbw), one adds
 * the S accumulator before each block (P), one accumulates W (bytes times the weights n .. 1,
 * pmaddwd / pmaddubsw); 32-bit lanes wrap, which only the sums modulo 256 need.
 * A tail of t < 16 bytes after at least 16 is the last 16 bytes with the first 16 - t zeroed:
 * zeros add nothing to S or W, so only the sum2 step changes, to t sum1.
 */
#if defined(__x86_64__) || defined(_M_X64)
#include <emmintrin.h>
#define CHECKSUM_SSE2 1
#if defined(__GNUC__) && !defined(__AVX2__)
#include <immintrin.h>
#define CHECKSUM_AVX2 1 /* compiled for AVX2 with a target attribute, used if the CPU has it */
#define CHECKSUM_AVX2_TARGET __attribute__((target("avx2")))
#define CHECKSUM_HAVE_AVX2() __builtin_cpu_supports("avx2")
#elif defined(__AVX2__)
#include <immintrin.h>
#define CHECKSUM_AVX2 1 /* the build targets AVX2: always used */
#define CHECKSUM_AVX2_TARGET
#define CHECKSUM_HAVE_AVX2() 1
#endif
#endif

#if CHECKSUM_SSE2
static inline uint32_t hsum_epi32(__m128i v) {
    v = _mm_add_epi32(v, _mm_shuffle_epi32(v, 0x4E));
    v = _mm_add_epi32(v, _mm_shuffle_epi32(v, 0xB1));
    return (uint32_t)_mm_cvtsi128_si32(v);
}

/* bytes[0 .. len) where bytes - before .. bytes may be read too: before >= 16 - len % 16 when
 * len % 16 != 0 (the tail block reaches back), so len + before >= 16. */
static inline sums_t sums_sse2(sums_t s, const uint8_t *bytes, size_t len) {
    /* 0x00 x 16 then 0xFF x 16: 16 bytes from offset t keep the last t bytes of a block. */
    static const uint8_t k_tail_mask[32] = {0,    0,    0,    0,    0,    0,    0,    0,    0,    0,    0,
                                            0,    0,    0,    0,    0,    0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF,
                                            0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF};
    const __m128i zero = _mm_setzero_si128();
    const __m128i w_lo = _mm_set_epi16(9, 10, 11, 12, 13, 14, 15, 16);
    const __m128i w_hi = _mm_set_epi16(1, 2, 3, 4, 5, 6, 7, 8);
    __m128i v_s = zero;
    __m128i v_p = zero;
    __m128i v_w = zero;
    size_t blocks = len / 16;
    size_t tail = len % 16;
    size_t k;
    for (k = 0; k < blocks; k++) {
        __m128i v = _mm_loadu_si128((const __m128i *)(const void *)(bytes + 16 * k));
        v_p = _mm_add_epi32(v_p, v_s);
        v_s = _mm_add_epi32(v_s, _mm_sad_epu8(v, zero));
        v_w = _mm_add_epi32(v_w, _mm_madd_epi16(_mm_unpacklo_epi8(v, zero), w_lo));
        v_w = _mm_add_epi32(v_w, _mm_madd_epi16(_mm_unpackhi_epi8(v, zero), w_hi));
    }
    /* sum2 += len sum1 + T with T = 16 P + W (+ the tail's t S + W below); 32-bit lanes wrap */
    v_w = _mm_add_epi32(_mm_slli_epi32(v_p, 4), v_w);
    if (tail != 0) {
        __m128i v = _mm_loadu_si128((const __m128i *)(const void *)(bytes + len - 16));
        v = _mm_and_si128(v, _mm_loadu_si128((const __m128i *)(const void *)(k_tail_mask + tail)));
        /* t times the blocks' S: a 16-bit multiply keeps each half lane's low 16 bits, which
         * loses only multiples of 65536 (nothing modulo 256) */
        v_w = _mm_add_epi32(v_w, _mm_mullo_epi16(v_s, _mm_set1_epi16((short)tail)));
        v_w = _mm_add_epi32(v_w, _mm_madd_epi16(_mm_unpacklo_epi8(v, zero), w_lo));
        v_w = _mm_add_epi32(v_w, _mm_madd_epi16(_mm_unpackhi_epi8(v, zero), w_hi));
        v_s = _mm_add_epi32(v_s, _mm_sad_epu8(v, zero));
    }
    /* both reductions at once: S is in lanes 0 and 2 of v_s (psadbw; lanes 1 and 3 are zero),
     * T in the four lanes of v_w */
    {
        const __m128i a = _mm_add_epi32(_mm_unpacklo_epi64(v_s, v_w), _mm_unpackhi_epi64(v_s, v_w));
        const __m128i b = _mm_add_epi32(a, _mm_shuffle_epi32(a, 0xB1));
        const uint32_t total_s = (uint32_t)_mm_cvtsi128_si32(b);
        const uint32_t total_t = (uint32_t)_mm_cvtsi128_si32(_mm_unpackhi_epi64(b, b));
        s.s2 += len * s.s1 + total_t;
        s.s1 += total_s;
    }
    return s;
}
#endif

static inline uint16_t sums_word(sums_t s) {
    unsigned sum1 = (unsigned)(s.s1 & 0xFFu);
    unsigned sum2 = (unsigned)(s.s2 & 0xFFu);
#if MIPC_CHECKSUM_SUM1_FIRST
    return (uint16_t)(sum1 << 8 | sum2);
#else
    return (uint16_t)(sum2 << 8 | sum1);
#endif
}

#endif
