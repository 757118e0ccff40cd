/* Checksum and packet builder. */
#include "codec/framing.h"

#include <assert.h>
#include <string.h>

const uint8_t codec_sync[CODEC_SYNC_SIZE] = CODEC_SYNC_BYTES;

/* Fletcher-16 sums in progress: both are only ever read modulo 256, so any wider unsigned
 * arithmetic that wraps (modulo 2^32 or 2^64, multiples of 256) gives the same checksum. */
typedef struct {
    uint64_t s1;
    uint64_t s2;
} sums_t;

/* The byte-serial definition, for what is left after the wider steps. */
static sums_t sums_bytes(sums_t s, const uint8_t *bytes, size_t len) {
    size_t i;
    for (i = 0; i < len; i++) {
        s.s1 += bytes[i];
        s.s2 += s.s1;
    }
    return s;
}

/* Eight bytes as a little-endian word, whatever the host's byte order (compilers make this one
 * load on little-endian hosts). */
static uint64_t load_le64(const uint8_t *b) {
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
static sums_t sums_scalar(sums_t s, const uint8_t *bytes, size_t len) {
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
static uint32_t hsum_epi32(__m128i v) {
    v = _mm_add_epi32(v, _mm_shuffle_epi32(v, 0x4E));
    v = _mm_add_epi32(v, _mm_shuffle_epi32(v, 0xB1));
    return (uint32_t)_mm_cvtsi128_si32(v);
}

/* 0x00 x 16 then 0xFF x 16: 16 bytes from offset t keep the last t bytes of a block. */
static const uint8_t k_tail_mask[32] = {0,    0,    0,    0,    0,    0,    0,    0,    0,    0,    0,
                                        0,    0,    0,    0,    0,    0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF,
                                        0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF};

/* bytes[0 .. len) where bytes - before .. bytes may be read too: before >= 16 - len % 16 when
 * len % 16 != 0 (the tail block reaches back), so len + before >= 16. */
static sums_t sums_sse2(sums_t s, const uint8_t *bytes, size_t len) {
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
    s.s2 += 16 * blocks * s.s1 + 16 * (uint64_t)hsum_epi32(v_p) + hsum_epi32(v_w);
    s.s1 += hsum_epi32(v_s);
    if (tail != 0) {
        __m128i v = _mm_loadu_si128((const __m128i *)(const void *)(bytes + len - 16));
        v = _mm_and_si128(v, _mm_loadu_si128((const __m128i *)(const void *)(k_tail_mask + tail)));
        s.s2 += tail * s.s1 + hsum_epi32(_mm_add_epi32(_mm_madd_epi16(_mm_unpacklo_epi8(v, zero), w_lo),
                                                       _mm_madd_epi16(_mm_unpackhi_epi8(v, zero), w_hi)));
        s.s1 += hsum_epi32(_mm_sad_epu8(v, zero));
    }
    return s;
}
#endif

#if CHECKSUM_AVX2
CHECKSUM_AVX2_TARGET static sums_t sums_avx2(sums_t s, const uint8_t *bytes, size_t len) {
    const __m256i zero = _mm256_setzero_si256();
    const __m256i weights = _mm256_set_epi8(1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19,
                                            20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32);
    const __m256i ones = _mm256_set1_epi16(1);
    __m256i v_s = zero;
    __m256i v_p = zero;
    __m256i v_w = zero;
    size_t blocks = len / 32;
    size_t k;
    for (k = 0; k < blocks; k++) {
        __m256i v = _mm256_loadu_si256((const __m256i *)(const void *)(bytes + 32 * k));
        v_p = _mm256_add_epi32(v_p, v_s);
        v_s = _mm256_add_epi32(v_s, _mm256_sad_epu8(v, zero));
        /* 255 * (32 + 31) fits a signed 16-bit lane: pmaddubsw never saturates here */
        v_w = _mm256_add_epi32(v_w, _mm256_madd_epi16(_mm256_maddubs_epi16(v, weights), ones));
    }
    s.s2 += 32 * blocks * s.s1 +
            32 * (uint64_t)hsum_epi32(
                     _mm_add_epi32(_mm256_castsi256_si128(v_p), _mm256_extracti128_si256(v_p, 1))) +
            hsum_epi32(_mm_add_epi32(_mm256_castsi256_si128(v_w), _mm256_extracti128_si256(v_w, 1)));
    s.s1 += hsum_epi32(_mm_add_epi32(_mm256_castsi256_si128(v_s), _mm256_extracti128_si256(v_s, 1)));
    /* the compiler does not always clear the upper halves when leaving a target("avx2")
     * function; SSE code after dirty upper halves runs at half speed or worse */
    _mm256_zeroupper();
    return sums_sse2(s, bytes + 32 * blocks, len - 32 * blocks); /* 32 * blocks >= 16 bytes lie before */
}
#endif

static uint16_t sums_word(sums_t s) {
    unsigned sum1 = (unsigned)(s.s1 & 0xFFu);
    unsigned sum2 = (unsigned)(s.s2 & 0xFFu);
#if CODEC_CHECKSUM_SUM1_FIRST
    return (uint16_t)(sum1 << 8 | sum2);
#else
    return (uint16_t)(sum2 << 8 | sum1);
#endif
}

bool codec_checksum_word_impl(codec_checksum_impl_t impl, const uint8_t *bytes, size_t len, uint16_t *word) {
    sums_t s = {0, 0};
    assert(bytes != NULL || len == 0);
    assert(word != NULL);
    switch (impl) {
    case CODEC_CHECKSUM_IMPL_SCALAR:
        s = sums_scalar(s, bytes, len);
        break;
#if CHECKSUM_SSE2
    case CODEC_CHECKSUM_IMPL_SSE2:
        s = len < 16 ? sums_scalar(s, bytes, len) : sums_sse2(s, bytes, len);
        break;
#endif
#if CHECKSUM_AVX2
    case CODEC_CHECKSUM_IMPL_AVX2:
        if (!CHECKSUM_HAVE_AVX2()) {
            return false;
        }
        s = len < 32 ? sums_scalar(s, bytes, len) : sums_avx2(s, bytes, len);
        break;
#endif
    default:
        return false;
    }
    *word = sums_word(s);
    return true;
}

/* The fastest implementation the build and the CPU have for the length: under 16 bytes the
 * scalar steps, under 64 SSE2 (AVX2's wider reduction and the vzeroupper cost more than they
 * save there), then AVX2. */
static uint16_t checksum_word(const uint8_t *bytes, size_t len) {
    sums_t s = {0, 0};
#if CHECKSUM_AVX2
    if (len >= 64 && CHECKSUM_HAVE_AVX2()) {
        return sums_word(sums_avx2(s, bytes, len));
    }
#endif
#if CHECKSUM_SSE2
    if (len >= 16) {
        return sums_word(sums_sse2(s, bytes, len));
    }
#endif
    return sums_word(sums_scalar(s, bytes, len));
}

uint16_t codec_checksum_word(const uint8_t *bytes, size_t len) {
    assert(bytes != NULL || len == 0);
    return checksum_word(bytes, len);
}

void codec_checksum(const uint8_t *bytes, size_t len, uint8_t out[CODEC_CHECKSUM_SIZE]) {
    assert(bytes != NULL || len == 0);
    assert(out != NULL);
    unsigned word = codec_checksum_word(bytes, len);
    out[0] = (uint8_t)(word >> 8);
    out[1] = (uint8_t)(word & 0xFFu);
}

/* The checksum stays in a register: comparing it as bytes stored to memory and loaded back as
 * one wider word stalls on store forwarding, which cost the parser more than the checksum. */
bool codec_checksum_matches(const uint8_t *bytes, size_t len) {
    assert(bytes != NULL);
    return checksum_word(bytes, len) == (unsigned)((unsigned)bytes[len] << 8 | bytes[len + 1]);
}

bool codec_packet_valid(const uint8_t *packet, size_t len) {
    assert(packet != NULL || len == 0);
    size_t payload;
    if (len < CODEC_HEADER_SIZE + CODEC_CHECKSUM_SIZE || memcmp(packet, codec_sync, CODEC_SYNC_SIZE) != 0) {
        return false;
    }
    payload = packet[CODEC_LENGTH_OFFSET];
    if (payload > CODEC_MAX_PAYLOAD || len != CODEC_HEADER_SIZE + payload + CODEC_CHECKSUM_SIZE) {
        return false;
    }
    return codec_checksum_matches(packet, CODEC_HEADER_SIZE + payload);
}

void codec_packet_begin(codec_packet_builder_t *b, uint8_t *buf, size_t cap, uint8_t set) {
    assert(b != NULL);
    assert(buf != NULL || cap == 0);
    b->buf = buf;
    b->cap = buf ? cap : 0;
    b->len = 0;
    b->status = CODEC_OK;
    if (b->cap < CODEC_HEADER_SIZE) {
        b->status = CODEC_ERR_BUFFER;
        return;
    }
    memcpy(buf, codec_sync, CODEC_SYNC_SIZE);
    buf[CODEC_SET_OFFSET] = set;
    b->set = set;
    buf[CODEC_LENGTH_OFFSET] = 0;
    b->len = CODEC_HEADER_SIZE;
}

static codec_status_t reserve(codec_packet_builder_t *b, size_t n) {
    if (b->status != CODEC_OK) {
        return b->status;
    }
    if (b->len - CODEC_HEADER_SIZE + n > CODEC_MAX_PAYLOAD) {
        b->status = CODEC_ERR_TOO_LONG;
    } else if (b->cap - b->len < n + CODEC_CHECKSUM_SIZE) {
        b->status = CODEC_ERR_BUFFER;
    }
    return b->status;
}

codec_status_t codec_packet_add_field(codec_packet_builder_t *b, uint8_t descriptor, const uint8_t *data,
                                      size_t data_len) {
    assert(b != NULL);
    assert(data != NULL || data_len == 0);
    int adjust = codec_field_length_adjust(b->set, descriptor);
    if (b->status == CODEC_OK && data_len > CODEC_MAX_FIELD_DATA) {
        b->status = CODEC_ERR_TOO_LONG;
    }
    if (b->status == CODEC_OK && ((int)data_len + adjust < 0 || (int)data_len + adjust > 0xFF)) {
        /* too long for the length byte, or shorter than an irregular field's size byte allows */
        b->status = (int)data_len + adjust > 0xFF ? CODEC_ERR_TOO_LONG : CODEC_ERR_INVALID;
    }
    if (reserve(b, CODEC_FIELD_HEADER_SIZE + data_len) != CODEC_OK) {
        return b->status;
    }
    b->buf[b->len + CODEC_FIELD_LENGTH_OFFSET] = (uint8_t)((int)data_len + adjust);
    b->buf[b->len + CODEC_FIELD_DESCRIPTOR_OFFSET] = descriptor;
    if (data_len > 0) {
        memcpy(b->buf + b->len + CODEC_FIELD_HEADER_SIZE, data, data_len);
    }
    b->len += CODEC_FIELD_HEADER_SIZE + data_len;
    return CODEC_OK;
}

codec_status_t codec_packet_add_raw(codec_packet_builder_t *b, const uint8_t *bytes, size_t len) {
    assert(b != NULL);
    assert(bytes != NULL || len == 0);
    if (reserve(b, len) != CODEC_OK) {
        return b->status;
    }
    if (len > 0) {
        memcpy(b->buf + b->len, bytes, len);
    }
    b->len += len;
    return CODEC_OK;
}

codec_status_t codec_packet_finish(codec_packet_builder_t *b, size_t *len_out) {
    assert(b != NULL);
    if (b->status != CODEC_OK) {
        return b->status;
    }
    if (b->cap - b->len < CODEC_CHECKSUM_SIZE) {
        b->status = CODEC_ERR_BUFFER;
        return b->status;
    }
    b->buf[CODEC_LENGTH_OFFSET] = (uint8_t)(b->len - CODEC_HEADER_SIZE);
    codec_checksum(b->buf, b->len, b->buf + b->len);
    b->len += CODEC_CHECKSUM_SIZE;
    if (len_out) {
        *len_out = b->len;
    }
    return CODEC_OK;
}
