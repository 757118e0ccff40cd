/* Checksum and packet builder. Generated: do not edit. */
#include "mscipcodec/framing.h"

#include <assert.h>
#include <string.h>

const uint8_t mscipc_sync[MSCIPC_SYNC_SIZE] = MSCIPC_SYNC_BYTES;

/* Eight bytes as a little-endian word, whatever the host's byte order (compilers make this one
 * load on little-endian hosts). */
static uint64_t load_le64(const uint8_t *b) {
    return (uint64_t)b[0] | (uint64_t)b[1] << 8 | (uint64_t)b[2] << 16 | (uint64_t)b[3] << 24 |
           (uint64_t)b[4] << 32 | (uint64_t)b[5] << 40 | (uint64_t)b[6] << 48 | (uint64_t)b[7] << 56;
}

/*
 * Fletcher-16 with both sums modulo 256, eight bytes at a time. Over words B_0 .. B_{K-1} of
 * eight bytes (word sums S_k, weighted sums W_k = 8 b0 + 7 b1 + .. + 1 b7) the byte-serial
 * recurrence gives sum1 = sum1_0 + sum_k S_k and
 * sum2 = sum2_0 + 8 K sum1_0 + 8 sum_k (K - 1 - k) S_k + sum_k W_k. The even and odd bytes of a
 * little-endian word are spread into four 16-bit lanes and summed lane by lane:
 *   E, O = sum of the even, odd lanes; Q = sum of E + O after each word,
 * so sum_k S_k = hsum(E + O), sum_k (K - 1 - k) S_k = hsum(Q) - hsum(E + O) and sum_k W_k comes
 * from E and O with the lane weights (8, 6, 4, 2) and (7, 5, 3, 1).
 * No lane may carry into the next: over a run of n words a lane of E or O reaches at most 255 n,
 * and Q, reduced modulo 256 (masked: only the sums modulo 256 matter) after each add, at most
 * 255 + 510 n; both stay below 65536 for n <= 128 (1024 bytes, more than a packet). So words go
 * in runs of at most 128 with one mask per word; after a run every lane is reduced, a multiply by
 * lane constants adds the lanes into the top one (at most 255 * 20) and the run's sums are folded
 * into sum1 and sum2 with the recurrence above. Unsigned arithmetic wraps modulo 2^64, a multiple
 * of 256.
 */
uint16_t mscipc_checksum_word(const uint8_t *bytes, size_t len) {
    assert(bytes != NULL || len == 0);
    const uint64_t lanes = 0x00FF00FF00FF00FFu;
    const uint64_t ones = 0x0001000100010001u;
    uint64_t s1 = 0;
    uint64_t s2 = 0;
    unsigned sum1;
    unsigned sum2;
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
        s2 += 8 * words * s1 + 8 * (((q * ones) >> 48) - r1) + ((e * 0x0008000600040002u) >> 48) +
              ((o * 0x0007000500030001u) >> 48);
        s1 += r1;
    }
    for (; i < len; i++) {
        s1 += bytes[i];
        s2 += s1;
    }
    sum1 = (unsigned)(s1 & 0xFFu);
    sum2 = (unsigned)(s2 & 0xFFu);
#if MSCIPC_CHECKSUM_SUM1_FIRST
    return (uint16_t)(sum1 << 8 | sum2);
#else
    return (uint16_t)(sum2 << 8 | sum1);
#endif
}

void mscipc_checksum(const uint8_t *bytes, size_t len, uint8_t out[MSCIPC_CHECKSUM_SIZE]) {
    assert(bytes != NULL || len == 0);
    assert(out != NULL);
    unsigned word = mscipc_checksum_word(bytes, len);
    out[0] = (uint8_t)(word >> 8);
    out[1] = (uint8_t)(word & 0xFFu);
}

/* The checksum stays in a register: comparing it as bytes stored to memory and loaded back as
 * one wider word stalls on store forwarding, which cost the parser more than the checksum. */
bool mscipc_checksum_matches(const uint8_t *bytes, size_t len) {
    assert(bytes != NULL);
    return mscipc_checksum_word(bytes, len) == (unsigned)((unsigned)bytes[len] << 8 | bytes[len + 1]);
}

bool mscipc_packet_valid(const uint8_t *packet, size_t len) {
    assert(packet != NULL || len == 0);
    size_t payload;
    if (len < MSCIPC_HEADER_SIZE + MSCIPC_CHECKSUM_SIZE ||
        memcmp(packet, mscipc_sync, MSCIPC_SYNC_SIZE) != 0) {
        return false;
    }
    payload = packet[MSCIPC_LENGTH_OFFSET];
    if (payload > MSCIPC_MAX_PAYLOAD || len != MSCIPC_HEADER_SIZE + payload + MSCIPC_CHECKSUM_SIZE) {
        return false;
    }
    return mscipc_checksum_matches(packet, MSCIPC_HEADER_SIZE + payload);
}

void mscipc_packet_begin(mscipc_packet_builder_t *b, uint8_t *buf, size_t cap, uint8_t set) {
    assert(b != NULL);
    assert(buf != NULL || cap == 0);
    b->buf = buf;
    b->cap = buf ? cap : 0;
    b->len = 0;
    b->status = MSCIPC_OK;
    if (b->cap < MSCIPC_HEADER_SIZE) {
        b->status = MSCIPC_ERR_BUFFER;
        return;
    }
    memcpy(buf, mscipc_sync, MSCIPC_SYNC_SIZE);
    buf[MSCIPC_SET_OFFSET] = set;
    b->set = set;
    buf[MSCIPC_LENGTH_OFFSET] = 0;
    b->len = MSCIPC_HEADER_SIZE;
}

static mscipc_status_t reserve(mscipc_packet_builder_t *b, size_t n) {
    if (b->status != MSCIPC_OK) {
        return b->status;
    }
    if (b->len - MSCIPC_HEADER_SIZE + n > MSCIPC_MAX_PAYLOAD) {
        b->status = MSCIPC_ERR_TOO_LONG;
    } else if (b->cap - b->len < n + MSCIPC_CHECKSUM_SIZE) {
        b->status = MSCIPC_ERR_BUFFER;
    }
    return b->status;
}

mscipc_status_t mscipc_packet_add_field(mscipc_packet_builder_t *b, uint8_t descriptor, const uint8_t *data,
                                        size_t data_len) {
    assert(b != NULL);
    assert(data != NULL || data_len == 0);
    int adjust = mscipc_field_length_adjust(b->set, descriptor);
    if (b->status == MSCIPC_OK && data_len > MSCIPC_MAX_FIELD_DATA) {
        b->status = MSCIPC_ERR_TOO_LONG;
    }
    if (b->status == MSCIPC_OK && ((int)data_len + adjust < 0 || (int)data_len + adjust > 0xFF)) {
        /* too long for the length byte, or shorter than an irregular field's size byte allows */
        b->status = (int)data_len + adjust > 0xFF ? MSCIPC_ERR_TOO_LONG : MSCIPC_ERR_INVALID;
    }
    if (reserve(b, MSCIPC_FIELD_HEADER_SIZE + data_len) != MSCIPC_OK) {
        return b->status;
    }
    b->buf[b->len + MSCIPC_FIELD_LENGTH_OFFSET] = (uint8_t)((int)data_len + adjust);
    b->buf[b->len + MSCIPC_FIELD_DESCRIPTOR_OFFSET] = descriptor;
    if (data_len > 0) {
        memcpy(b->buf + b->len + MSCIPC_FIELD_HEADER_SIZE, data, data_len);
    }
    b->len += MSCIPC_FIELD_HEADER_SIZE + data_len;
    return MSCIPC_OK;
}

mscipc_status_t mscipc_packet_add_raw(mscipc_packet_builder_t *b, const uint8_t *bytes, size_t len) {
    assert(b != NULL);
    assert(bytes != NULL || len == 0);
    if (reserve(b, len) != MSCIPC_OK) {
        return b->status;
    }
    if (len > 0) {
        memcpy(b->buf + b->len, bytes, len);
    }
    b->len += len;
    return MSCIPC_OK;
}

mscipc_status_t mscipc_packet_finish(mscipc_packet_builder_t *b, size_t *len_out) {
    assert(b != NULL);
    if (b->status != MSCIPC_OK) {
        return b->status;
    }
    if (b->cap - b->len < MSCIPC_CHECKSUM_SIZE) {
        b->status = MSCIPC_ERR_BUFFER;
        return b->status;
    }
    b->buf[MSCIPC_LENGTH_OFFSET] = (uint8_t)(b->len - MSCIPC_HEADER_SIZE);
    mscipc_checksum(b->buf, b->len, b->buf + b->len);
    b->len += MSCIPC_CHECKSUM_SIZE;
    if (len_out) {
        *len_out = b->len;
    }
    return MSCIPC_OK;
}
