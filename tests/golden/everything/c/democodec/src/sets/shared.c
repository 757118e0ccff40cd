/* Encoders and decoders of Shared data. Generated from the spec: do not edit. */
#include "democodec/sets/shared.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <stddef.h>
#include <string.h>

/* ---- democ_shared_timestamp_t */

static int democ_shared_timestamp_read(democ_reader_t *r, democ_shared_timestamp_t *out) {
    democ_rd_push(r, "nanoseconds");
    if (democ_rd_u64(r, &out->nanoseconds)) {
        return -1;
    }
    democ_rd_pop(r);
    return democ_rd_finish(r);
}

static democ_status_t democ_shared_timestamp_write(democ_writer_t *w, const democ_shared_timestamp_t *in) {
    democ_status_t st;
    if ((st = democ_wr_u64(w, &in->nanoseconds)) != DEMOC_OK) {
        return st;
    }
    return DEMOC_OK;
}

democ_status_t democ_shared_timestamp_encode(const democ_shared_timestamp_t *value, uint8_t *buf, size_t cap,
                                             size_t *len_out) {
    democ_writer_t w;
    democ_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    democ_writer_init(&w, buf, cap);
    st = democ_shared_timestamp_write(&w, value);
    if (st == DEMOC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 8 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int democ_shared_timestamp_load(const uint8_t *d, democ_shared_timestamp_t *out) {
    out->nanoseconds = democ_ld_u64(d + 0);
    return 0;
}

/* The general reader: lengths other than 8, bad bool bytes, error details. */
static DEMOC_NOINLINE democ_status_t democ_shared_timestamp_decode_read(const uint8_t *data, size_t len,
                                                                        democ_shared_timestamp_t *out,
                                                                        democ_decode_error_t *err) {
    democ_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    democ_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return democ_shared_timestamp_read(&r, out) ? DEMOC_ERR_DECODE : DEMOC_OK;
}

democ_status_t democ_shared_timestamp_decode(const uint8_t *data, size_t len, democ_shared_timestamp_t *out,
                                             democ_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 8 && democ_shared_timestamp_load(data, out) == 0) {
        return DEMOC_OK;
    }
    return democ_shared_timestamp_decode_read(data, len, out, err);
}

/* ---- the straight-line packet decoder */

size_t democ_shared_decode_packet(const uint8_t *payload, size_t len, democ_shared_packet_t *out,
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
            (int)head[DEMOC_FIELD_LENGTH_OFFSET] - democ_field_length_adjust(DEMOC_SHARED_SET, descriptor);
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
            case 0xD3:
                if (length == 8) {
                    out->shared_timestamp.nanoseconds = democ_ld_u64(d + 0);
                    ok = 1;
                } else {
                    ok = democ_shared_timestamp_decode(d, length, &out->shared_timestamp, NULL) == DEMOC_OK;
                }
                offset = offsetof(democ_shared_packet_t, shared_timestamp);
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
            democ_field_visit_at_(DEMOC_SHARED_SET, payload, len, pos, other, ctx);
        }
        pos += DEMOC_FIELD_HEADER_SIZE + length;
    }
    if (pos < len && other) {
        democ_field_visit_at_(DEMOC_SHARED_SET, payload, len, pos, other, ctx);
    }
    out->index.count = n;
    return n;
}

/* ---- the members' loaders (democ_decode_packet_cached, issue 38): each decodes its field's
 * data into its member of the democ_shared_packet_t at packet as democ_shared_decode_packet does; 0 when it
 * does not decode (the packet then takes the straight-line decoder, which gives the field to other) */

static int load_0xd3(const uint8_t *d, size_t length, void *packet) {
    democ_shared_packet_t *out = packet;
    if (length == 8) {
        out->shared_timestamp.nanoseconds = democ_ld_u64(d + 0);
        return 1;
    }
    return democ_shared_timestamp_decode(d, length, &out->shared_timestamp, NULL) == DEMOC_OK;
}

const democ_layout_member_t democ_shared_layout_members_[1] = {
    {0xD3, offsetof(democ_shared_packet_t, shared_timestamp), load_0xd3},
};
