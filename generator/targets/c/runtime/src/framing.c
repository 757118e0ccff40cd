/* Checksum and packet builder. */
#include "codec/framing.h"

#include <assert.h>
#include <string.h>

#include "checksum_impl.h"

const uint8_t codec_sync[CODEC_SYNC_SIZE] = CODEC_SYNC_BYTES;

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
