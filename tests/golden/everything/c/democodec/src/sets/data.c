/* Encoders and decoders of Data. Generated from the spec: do not edit. */
#include "democodec/sets/data.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <stddef.h>
#include <string.h>

/* ---- democ_data_sample_t */

static int democ_data_sample_read(democ_reader_t *r, democ_data_sample_t *out) {
    size_t i;
    democ_rd_push(r, "quat");
    for (i = 0; i < 4; i++) {
        democ_rd_index(r, i);
        if (democ_rd_f32(r, &out->quat[i])) {
            return -1;
        }
    }
    democ_rd_pop(r);
    democ_rd_push(r, "big");
    if (democ_rd_u64(r, &out->big)) {
        return -1;
    }
    democ_rd_pop(r);
    democ_rd_push(r, "small");
    if (democ_rd_s8(r, &out->small)) {
        return -1;
    }
    democ_rd_pop(r);
    democ_rd_push(r, "f");
    if (democ_rd_f32(r, &out->f)) {
        return -1;
    }
    democ_rd_pop(r);
    return democ_rd_finish(r);
}

static democ_status_t democ_data_sample_write(democ_writer_t *w, const democ_data_sample_t *in) {
    democ_status_t st;
    size_t i;
    for (i = 0; i < 4; i++) {
        if ((st = democ_wr_f32(w, &in->quat[i])) != DEMOC_OK) {
            return st;
        }
    }
    if ((st = democ_wr_u64(w, &in->big)) != DEMOC_OK) {
        return st;
    }
    if ((st = democ_wr_s8(w, &in->small)) != DEMOC_OK) {
        return st;
    }
    if ((st = democ_wr_f32(w, &in->f)) != DEMOC_OK) {
        return st;
    }
    return DEMOC_OK;
}

democ_status_t democ_data_sample_encode(const democ_data_sample_t *value, uint8_t *buf, size_t cap,
                                        size_t *len_out) {
    democ_writer_t w;
    democ_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    democ_writer_init(&w, buf, cap);
    st = democ_data_sample_write(&w, value);
    if (st == DEMOC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 29 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int democ_data_sample_load(const uint8_t *d, democ_data_sample_t *out) {
    out->quat[0] = democ_ld_f32(d + 0);
    out->quat[1] = democ_ld_f32(d + 4);
    out->quat[2] = democ_ld_f32(d + 8);
    out->quat[3] = democ_ld_f32(d + 12);
    out->big = democ_ld_u64(d + 16);
    out->small = democ_ld_s8(d + 24);
    out->f = democ_ld_f32(d + 25);
    return 0;
}

/* The general reader: lengths other than 29, bad bool bytes, error details. */
static DEMOC_NOINLINE democ_status_t democ_data_sample_decode_read(const uint8_t *data, size_t len,
                                                                   democ_data_sample_t *out,
                                                                   democ_decode_error_t *err) {
    democ_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    democ_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return democ_data_sample_read(&r, out) ? DEMOC_ERR_DECODE : DEMOC_OK;
}

democ_status_t democ_data_sample_decode(const uint8_t *data, size_t len, democ_data_sample_t *out,
                                        democ_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 29 && democ_data_sample_load(data, out) == 0) {
        return DEMOC_OK;
    }
    return democ_data_sample_decode_read(data, len, out, err);
}

/* ---- the straight-line packet decoder */

size_t democ_data_decode_packet(const uint8_t *payload, size_t len, democ_data_packet_t *out,
                                democ_field_entry_fn other, void *ctx) {
    size_t pos = 0;
    size_t n = 0;
    assert(payload != NULL || len == 0);
    assert(out != NULL);
    memset(out->index.present, 0, sizeof out->index.present);
    if (payload == NULL) {
        len = 0;
    }
    /* the field headers read in place (the iterator's entry is built only for what goes to other) */
    while (len - pos >= DEMOC_FIELD_HEADER_SIZE) {
        const uint8_t *head = payload + pos;
        const uint8_t descriptor = head[DEMOC_FIELD_DESCRIPTOR_OFFSET];
        const int data_len =
            (int)head[DEMOC_FIELD_LENGTH_OFFSET] - democ_field_length_adjust(DEMOC_DATA_SET, descriptor);
        const uint8_t *d = head + DEMOC_FIELD_HEADER_SIZE;
        const uint32_t bit = (uint32_t)1u << (descriptor % 32u);
        size_t length;
        size_t offset = 0;
        int ok = 0;
        if (data_len < 0 || (size_t)data_len > len - pos - DEMOC_FIELD_HEADER_SIZE) {
            break; /* trailing bytes: the iterator reports them below */
        }
        length = (size_t)data_len;
        if ((out->index.present[descriptor / 32u] & bit) == 0) {
            switch (descriptor) {
            case 0x01:
                if (length == 29) {
                    out->data_sample.quat[0] = democ_ld_f32(d + 0);
                    out->data_sample.quat[1] = democ_ld_f32(d + 4);
                    out->data_sample.quat[2] = democ_ld_f32(d + 8);
                    out->data_sample.quat[3] = democ_ld_f32(d + 12);
                    out->data_sample.big = democ_ld_u64(d + 16);
                    out->data_sample.small = democ_ld_s8(d + 24);
                    out->data_sample.f = democ_ld_f32(d + 25);
                    ok = 1;
                } else {
                    ok = democ_data_sample_decode(d, length, &out->data_sample, NULL) == DEMOC_OK;
                }
                offset = offsetof(democ_data_packet_t, data_sample);
                break;
            case 0xD3:
                if (length == 8) {
                    out->shared_timestamp.nanoseconds = democ_ld_u64(d + 0);
                    ok = 1;
                } else {
                    ok = democ_shared_timestamp_decode(d, length, &out->shared_timestamp, NULL) == DEMOC_OK;
                }
                offset = offsetof(democ_data_packet_t, shared_timestamp);
                break;
            default:
                break;
            }
        }
        if (ok) {
            out->index.present[descriptor / 32u] |= bit;
            out->index.fields[n].descriptor = descriptor;
            out->index.fields[n].offset = (uint32_t)offset;
            n++;
        } else if (other) {
            democ_field_visit_at_(DEMOC_DATA_SET, payload, len, pos, other, ctx);
        }
        pos += DEMOC_FIELD_HEADER_SIZE + length;
    }
    if (pos < len && other) {
        democ_field_visit_at_(DEMOC_DATA_SET, payload, len, pos, other, ctx);
    }
    out->index.count = n;
    return n;
}

/* ---- the members' loaders (democ_decode_packet_cached, issue 38): each decodes its field's
 * data into its member of the democ_data_packet_t at packet as democ_data_decode_packet does; 0 when it does
 * not decode (the packet then takes the straight-line decoder, which gives the field to other) */

static int load_0x01(const uint8_t *d, size_t length, void *packet) {
    democ_data_packet_t *out = packet;
    if (length == 29) {
        out->data_sample.quat[0] = democ_ld_f32(d + 0);
        out->data_sample.quat[1] = democ_ld_f32(d + 4);
        out->data_sample.quat[2] = democ_ld_f32(d + 8);
        out->data_sample.quat[3] = democ_ld_f32(d + 12);
        out->data_sample.big = democ_ld_u64(d + 16);
        out->data_sample.small = democ_ld_s8(d + 24);
        out->data_sample.f = democ_ld_f32(d + 25);
        return 1;
    }
    return democ_data_sample_decode(d, length, &out->data_sample, NULL) == DEMOC_OK;
}

static int load_0xd3(const uint8_t *d, size_t length, void *packet) {
    democ_data_packet_t *out = packet;
    if (length == 8) {
        out->shared_timestamp.nanoseconds = democ_ld_u64(d + 0);
        return 1;
    }
    return democ_shared_timestamp_decode(d, length, &out->shared_timestamp, NULL) == DEMOC_OK;
}

const democ_layout_member_t democ_data_layout_members_[2] = {
    {0x01, offsetof(democ_data_packet_t, data_sample), load_0x01},
    {0xD3, offsetof(democ_data_packet_t, shared_timestamp), load_0xd3},
};
