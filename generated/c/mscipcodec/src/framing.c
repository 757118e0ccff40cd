/* Checksum and packet builder. Generated: do not edit. */
#include "mscipcodec/framing.h"

#include <string.h>

const uint8_t mscip_sync[MSCIP_SYNC_SIZE] = {0xA5, 0xA5};

void mscip_checksum(const uint8_t *bytes, size_t len, uint8_t out[MSCIP_CHECKSUM_SIZE]) {
    unsigned sum1 = 0;
    unsigned sum2 = 0;
    size_t i;
    for (i = 0; i < len; i++) {
        sum1 = (sum1 + bytes[i]) & 0xFFu;
        sum2 = (sum2 + sum1) & 0xFFu;
    }
    out[0] = (uint8_t)sum1;
    out[1] = (uint8_t)sum2;
}

bool mscip_packet_valid(const uint8_t *packet, size_t len) {
    uint8_t ck[MSCIP_CHECKSUM_SIZE];
    size_t payload;
    if (len < MSCIP_HEADER_SIZE + MSCIP_CHECKSUM_SIZE || memcmp(packet, mscip_sync, MSCIP_SYNC_SIZE) != 0) {
        return false;
    }
    payload = packet[MSCIP_LENGTH_OFFSET];
    if (payload > MSCIP_MAX_PAYLOAD || len != MSCIP_HEADER_SIZE + payload + MSCIP_CHECKSUM_SIZE) {
        return false;
    }
    mscip_checksum(packet, MSCIP_HEADER_SIZE + payload, ck);
    return memcmp(ck, packet + MSCIP_HEADER_SIZE + payload, MSCIP_CHECKSUM_SIZE) == 0;
}

uint8_t mscip_packet_set(const uint8_t *packet) {
    return packet[MSCIP_SET_OFFSET];
}

uint8_t mscip_packet_payload_length(const uint8_t *packet) {
    return packet[MSCIP_LENGTH_OFFSET];
}

const uint8_t *mscip_packet_payload(const uint8_t *packet) {
    return packet + MSCIP_HEADER_SIZE;
}

void mscip_packet_begin(mscip_packet_builder_t *b, uint8_t *buf, size_t cap, uint8_t set) {
    b->buf = buf;
    b->cap = buf ? cap : 0;
    b->len = 0;
    b->status = MSCIP_OK;
    if (b->cap < MSCIP_HEADER_SIZE) {
        b->status = MSCIP_ERR_BUFFER;
        return;
    }
    memcpy(buf, mscip_sync, MSCIP_SYNC_SIZE);
    buf[MSCIP_SET_OFFSET] = set;
    b->set = set;
    buf[MSCIP_LENGTH_OFFSET] = 0;
    b->len = MSCIP_HEADER_SIZE;
}

static mscip_status_t reserve(mscip_packet_builder_t *b, size_t n) {
    if (b->status != MSCIP_OK) {
        return b->status;
    }
    if (b->len - MSCIP_HEADER_SIZE + n > MSCIP_MAX_PAYLOAD) {
        b->status = MSCIP_ERR_TOO_LONG;
    } else if (b->cap - b->len < n + MSCIP_CHECKSUM_SIZE) {
        b->status = MSCIP_ERR_BUFFER;
    }
    return b->status;
}

mscip_status_t mscip_packet_add_field(mscip_packet_builder_t *b, uint8_t descriptor, const uint8_t *data,
                                      size_t data_len) {
    int adjust = mscip_field_length_adjust(b->set, descriptor);
    if (b->status == MSCIP_OK && data_len > MSCIP_MAX_FIELD_DATA) {
        b->status = MSCIP_ERR_TOO_LONG;
    }
    if (b->status == MSCIP_OK && ((int)data_len + adjust < 0 || (int)data_len + adjust > 0xFF)) {
        /* too long for the length byte, or shorter than an irregular field's size byte allows */
        b->status = (int)data_len + adjust > 0xFF ? MSCIP_ERR_TOO_LONG : MSCIP_ERR_INVALID;
    }
    if (reserve(b, MSCIP_FIELD_HEADER_SIZE + data_len) != MSCIP_OK) {
        return b->status;
    }
    b->buf[b->len + MSCIP_FIELD_LENGTH_OFFSET] = (uint8_t)((int)data_len + adjust);
    b->buf[b->len + MSCIP_FIELD_DESCRIPTOR_OFFSET] = descriptor;
    if (data_len > 0) {
        memcpy(b->buf + b->len + MSCIP_FIELD_HEADER_SIZE, data, data_len);
    }
    b->len += MSCIP_FIELD_HEADER_SIZE + data_len;
    return MSCIP_OK;
}

mscip_status_t mscip_packet_add_raw(mscip_packet_builder_t *b, const uint8_t *bytes, size_t len) {
    if (reserve(b, len) != MSCIP_OK) {
        return b->status;
    }
    if (len > 0) {
        memcpy(b->buf + b->len, bytes, len);
    }
    b->len += len;
    return MSCIP_OK;
}

mscip_status_t mscip_packet_finish(mscip_packet_builder_t *b, size_t *len_out) {
    if (b->status != MSCIP_OK) {
        return b->status;
    }
    if (b->cap - b->len < MSCIP_CHECKSUM_SIZE) {
        b->status = MSCIP_ERR_BUFFER;
        return b->status;
    }
    b->buf[MSCIP_LENGTH_OFFSET] = (uint8_t)(b->len - MSCIP_HEADER_SIZE);
    mscip_checksum(b->buf, b->len, b->buf + b->len);
    b->len += MSCIP_CHECKSUM_SIZE;
    if (len_out) {
        *len_out = b->len;
    }
    return MSCIP_OK;
}
