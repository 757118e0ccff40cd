/* Checksum and packet builder. Generated: do not edit. */
#include "mipcodec/framing.h"

#include <string.h>

const uint8_t mip_sync[MIP_SYNC_SIZE] = {0x75, 0x65};

/* Eight bytes as a little-endian word, whatever the host's byte order (compilers make this one
 * load on little-endian hosts). */
static uint64_t load_le64(const uint8_t *b) {
    return (uint64_t)b[0] | (uint64_t)b[1] << 8 | (uint64_t)b[2] << 16 | (uint64_t)b[3] << 24 |
           (uint64_t)b[4] << 32 | (uint64_t)b[5] << 40 | (uint64_t)b[6] << 48 | (uint64_t)b[7] << 56;
}

/*
 * Fletcher-16 with both sums modulo 256, eight bytes at a time. Over blocks B_0 .. B_{K-1} of
 * eight bytes (block sums S_k, weighted sums W_k = 8 b0 + 7 b1 + .. + 1 b7) the byte-serial
 * recurrence gives sum1 = sum1_0 + sum_k S_k and
 * sum2 = sum2_0 + 8 K sum1_0 + 8 sum_k (K - 1 - k) S_k + sum_k W_k. The even and odd bytes of a
 * little-endian word are spread into four 16-bit lanes and summed lane by lane:
 *   E, O = sum of the even, odd lanes; R = running sum of both; Q = sum of R after each block,
 * so sum_k S_k = hsum(R), sum_k (K - 1 - k) S_k = hsum(Q) - hsum(R) and sum_k W_k comes from E
 * and O with the lane weights (8, 6, 4, 2) and (7, 5, 3, 1). Only the sums modulo 256 matter, so
 * every lane is reduced modulo 256 (masked) after each add and never carries into the next; a
 * multiply by lane constants adds the lanes into the top one (at most 255 * 20). Unsigned
 * arithmetic wraps modulo 2^64, a multiple of 256.
 */
void mip_checksum(const uint8_t *bytes, size_t len, uint8_t out[MIP_CHECKSUM_SIZE]) {
    const uint64_t lanes = 0x00FF00FF00FF00FFu;
    const uint64_t ones = 0x0001000100010001u;
    uint64_t s1 = 0;
    uint64_t s2 = 0;
    unsigned sum1;
    unsigned sum2;
    size_t i = 0;
    if (len >= 8) {
        uint64_t e_sum = 0;
        uint64_t o_sum = 0;
        uint64_t r = 0;
        uint64_t q = 0;
        for (; i + 8 <= len; i += 8) {
            uint64_t w = load_le64(bytes + i);
            uint64_t even = w & lanes;       /* b0, b2, b4, b6 */
            uint64_t odd = (w >> 8) & lanes; /* b1, b3, b5, b7 */
            e_sum = (e_sum + even) & lanes;
            o_sum = (o_sum + odd) & lanes;
            r = (r + even + odd) & lanes;
            q = (q + r) & lanes;
        }
        s1 = (r * ones) >> 48;
        s2 = 8 * (((q * ones) >> 48) - s1) + ((e_sum * 0x0008000600040002u) >> 48) +
             ((o_sum * 0x0007000500030001u) >> 48);
    }
    for (; i < len; i++) {
        s1 += bytes[i];
        s2 += s1;
    }
    sum1 = (unsigned)(s1 & 0xFFu);
    sum2 = (unsigned)(s2 & 0xFFu);
    out[0] = (uint8_t)sum1;
    out[1] = (uint8_t)sum2;
}

bool mip_packet_valid(const uint8_t *packet, size_t len) {
    uint8_t ck[MIP_CHECKSUM_SIZE];
    size_t payload;
    if (len < MIP_HEADER_SIZE + MIP_CHECKSUM_SIZE || memcmp(packet, mip_sync, MIP_SYNC_SIZE) != 0) {
        return false;
    }
    payload = packet[MIP_LENGTH_OFFSET];
    if (payload > MIP_MAX_PAYLOAD || len != MIP_HEADER_SIZE + payload + MIP_CHECKSUM_SIZE) {
        return false;
    }
    mip_checksum(packet, MIP_HEADER_SIZE + payload, ck);
    return memcmp(ck, packet + MIP_HEADER_SIZE + payload, MIP_CHECKSUM_SIZE) == 0;
}

uint8_t mip_packet_set(const uint8_t *packet) {
    return packet[MIP_SET_OFFSET];
}

uint8_t mip_packet_payload_length(const uint8_t *packet) {
    return packet[MIP_LENGTH_OFFSET];
}

const uint8_t *mip_packet_payload(const uint8_t *packet) {
    return packet + MIP_HEADER_SIZE;
}

void mip_packet_begin(mip_packet_builder_t *b, uint8_t *buf, size_t cap, uint8_t set) {
    b->buf = buf;
    b->cap = buf ? cap : 0;
    b->len = 0;
    b->status = MIP_OK;
    if (b->cap < MIP_HEADER_SIZE) {
        b->status = MIP_ERR_BUFFER;
        return;
    }
    memcpy(buf, mip_sync, MIP_SYNC_SIZE);
    buf[MIP_SET_OFFSET] = set;
    b->set = set;
    buf[MIP_LENGTH_OFFSET] = 0;
    b->len = MIP_HEADER_SIZE;
}

static mip_status_t reserve(mip_packet_builder_t *b, size_t n) {
    if (b->status != MIP_OK) {
        return b->status;
    }
    if (b->len - MIP_HEADER_SIZE + n > MIP_MAX_PAYLOAD) {
        b->status = MIP_ERR_TOO_LONG;
    } else if (b->cap - b->len < n + MIP_CHECKSUM_SIZE) {
        b->status = MIP_ERR_BUFFER;
    }
    return b->status;
}

mip_status_t mip_packet_add_field(mip_packet_builder_t *b, uint8_t descriptor, const uint8_t *data,
                                  size_t data_len) {
    int adjust = mip_field_length_adjust(b->set, descriptor);
    if (b->status == MIP_OK && data_len > MIP_MAX_FIELD_DATA) {
        b->status = MIP_ERR_TOO_LONG;
    }
    if (b->status == MIP_OK && ((int)data_len + adjust < 0 || (int)data_len + adjust > 0xFF)) {
        /* too long for the length byte, or shorter than an irregular field's size byte allows */
        b->status = (int)data_len + adjust > 0xFF ? MIP_ERR_TOO_LONG : MIP_ERR_INVALID;
    }
    if (reserve(b, MIP_FIELD_HEADER_SIZE + data_len) != MIP_OK) {
        return b->status;
    }
    b->buf[b->len + MIP_FIELD_LENGTH_OFFSET] = (uint8_t)((int)data_len + adjust);
    b->buf[b->len + MIP_FIELD_DESCRIPTOR_OFFSET] = descriptor;
    if (data_len > 0) {
        memcpy(b->buf + b->len + MIP_FIELD_HEADER_SIZE, data, data_len);
    }
    b->len += MIP_FIELD_HEADER_SIZE + data_len;
    return MIP_OK;
}

mip_status_t mip_packet_add_raw(mip_packet_builder_t *b, const uint8_t *bytes, size_t len) {
    if (reserve(b, len) != MIP_OK) {
        return b->status;
    }
    if (len > 0) {
        memcpy(b->buf + b->len, bytes, len);
    }
    b->len += len;
    return MIP_OK;
}

mip_status_t mip_packet_finish(mip_packet_builder_t *b, size_t *len_out) {
    if (b->status != MIP_OK) {
        return b->status;
    }
    if (b->cap - b->len < MIP_CHECKSUM_SIZE) {
        b->status = MIP_ERR_BUFFER;
        return b->status;
    }
    b->buf[MIP_LENGTH_OFFSET] = (uint8_t)(b->len - MIP_HEADER_SIZE);
    mip_checksum(b->buf, b->len, b->buf + b->len);
    b->len += MIP_CHECKSUM_SIZE;
    if (len_out) {
        *len_out = b->len;
    }
    return MIP_OK;
}
