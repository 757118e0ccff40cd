/* Bounds-checked reader and writer in the protocol's byte order (CODEC_LITTLE_ENDIAN). */
#include "wire.h"

#include <string.h>

void codec_reader_init(codec_reader_t *r, const uint8_t *data, size_t len, codec_decode_error_t *err) {
    memset(r, 0, sizeof *r);
    r->data = data;
    r->len = data ? len : 0;
    r->err = err;
}

void codec_rd_push(codec_reader_t *r, const char *name) {
    if (r->depth < CODEC_PATH_MAX_DEPTH) {
        r->path[r->depth].name = name;
        r->path[r->depth].index = SIZE_MAX;
    }
    r->depth++;
}

void codec_rd_index(codec_reader_t *r, size_t index) {
    if (r->depth > 0 && r->depth <= CODEC_PATH_MAX_DEPTH) {
        r->path[r->depth - 1].index = index;
    }
}

void codec_rd_pop(codec_reader_t *r) {
    if (r->depth > 0) {
        r->depth--;
    }
}

static codec_decode_error_t *begin_error(codec_reader_t *r, codec_decode_error_kind_t kind) {
    size_t i;
    codec_decode_error_t *e = r->err;
    if (!e) {
        return NULL;
    }
    memset(e, 0, sizeof *e);
    e->kind = kind;
    e->depth = r->depth < CODEC_PATH_MAX_DEPTH ? r->depth : CODEC_PATH_MAX_DEPTH;
    for (i = 0; i < e->depth; i++) {
        e->path[i] = r->path[i];
    }
    e->offset = r->pos;
    e->have = r->len - r->pos;
    return e;
}

static int need(codec_reader_t *r, size_t n) {
    codec_decode_error_t *e;
    if (r->len - r->pos >= n) {
        return 0;
    }
    e = begin_error(r, CODEC_DECODE_NEEDS_BYTES);
    if (e) {
        e->need = n;
    }
    return -1;
}

/* An n-byte unsigned value in the protocol's byte order. */
static uint64_t get_uint(codec_reader_t *r, size_t n) {
    uint64_t v = 0;
    size_t i;
    for (i = 0; i < n; i++) {
#if CODEC_LITTLE_ENDIAN
        v |= (uint64_t)r->data[r->pos + i] << (8 * i);
#else
        v = (v << 8) | (uint64_t)r->data[r->pos + i];
#endif
    }
    r->pos += n;
    return v;
}

/* Two's complement without implementation-defined conversions. */
static int64_t to_signed(uint64_t u, unsigned bits) {
    uint64_t sign = (uint64_t)1 << (bits - 1);
    if (u & sign) {
        uint64_t mag = ((~u) & ((sign << 1) - 1)) + 1; /* 1 .. 2^(bits-1) */
        return -(int64_t)(mag - 1) - 1;
    }
    return (int64_t)u;
}

int codec_rd_bool(codec_reader_t *r, bool *out) {
    uint8_t b;
    codec_decode_error_t *e;
    if (need(r, 1)) {
        return -1;
    }
    b = r->data[r->pos];
    if (b > 1) {
        e = begin_error(r, CODEC_DECODE_BOOL);
        if (e) {
            e->value = b;
        }
        return -1;
    }
    r->pos++;
    *out = b == 1;
    return 0;
}

int codec_rd_char(codec_reader_t *r, char *out) {
    return codec_rd_chars(r, out, 1);
}

int codec_rd_u8(codec_reader_t *r, uint8_t *out) {
    if (need(r, 1)) {
        return -1;
    }
    *out = (uint8_t)get_uint(r, 1);
    return 0;
}

int codec_rd_u16(codec_reader_t *r, uint16_t *out) {
    if (need(r, 2)) {
        return -1;
    }
    *out = (uint16_t)get_uint(r, 2);
    return 0;
}

int codec_rd_u32(codec_reader_t *r, uint32_t *out) {
    if (need(r, 4)) {
        return -1;
    }
    *out = (uint32_t)get_uint(r, 4);
    return 0;
}

int codec_rd_u64(codec_reader_t *r, uint64_t *out) {
    if (need(r, 8)) {
        return -1;
    }
    *out = get_uint(r, 8);
    return 0;
}

int codec_rd_s8(codec_reader_t *r, int8_t *out) {
    if (need(r, 1)) {
        return -1;
    }
    *out = (int8_t)to_signed(get_uint(r, 1), 8);
    return 0;
}

int codec_rd_s16(codec_reader_t *r, int16_t *out) {
    if (need(r, 2)) {
        return -1;
    }
    *out = (int16_t)to_signed(get_uint(r, 2), 16);
    return 0;
}

int codec_rd_s32(codec_reader_t *r, int32_t *out) {
    if (need(r, 4)) {
        return -1;
    }
    *out = (int32_t)to_signed(get_uint(r, 4), 32);
    return 0;
}

int codec_rd_s64(codec_reader_t *r, int64_t *out) {
    if (need(r, 8)) {
        return -1;
    }
    *out = to_signed(get_uint(r, 8), 64);
    return 0;
}

int codec_rd_f32(codec_reader_t *r, float *out) {
    uint32_t bits;
    if (need(r, 4)) {
        return -1;
    }
    bits = (uint32_t)get_uint(r, 4);
    memcpy(out, &bits, sizeof bits);
    return 0;
}

int codec_rd_f64(codec_reader_t *r, double *out) {
    uint64_t bits;
    if (need(r, 8)) {
        return -1;
    }
    bits = get_uint(r, 8);
    memcpy(out, &bits, sizeof bits);
    return 0;
}

int codec_rd_chars(codec_reader_t *r, char *out, size_t n) {
    if (need(r, n)) {
        return -1;
    }
    if (n > 0) {
        memcpy(out, r->data + r->pos, n);
    }
    r->pos += n;
    return 0;
}

int codec_rd_remaining(codec_reader_t *r, size_t elem_size, uint64_t max, size_t *count) {
    size_t left = r->len - r->pos;
    codec_decode_error_t *e;
    if (left % elem_size != 0) {
        e = begin_error(r, CODEC_DECODE_REMAINING);
        if (e) {
            e->need = elem_size;
        }
        return -1;
    }
    if ((uint64_t)(left / elem_size) > max) {
        return codec_rd_count_error(r, (uint64_t)(left / elem_size), max);
    }
    *count = left / elem_size;
    return 0;
}

int codec_rd_count_error(codec_reader_t *r, uint64_t count, uint64_t max) {
    codec_decode_error_t *e = begin_error(r, CODEC_DECODE_COUNT);
    if (e) {
        e->count = count;
        e->max = max;
    }
    return -1;
}

int codec_rd_selector_error_u(codec_reader_t *r, uint64_t value) {
    codec_decode_error_t *e = begin_error(r, CODEC_DECODE_SELECTOR);
    if (e) {
        e->value = value;
    }
    return -1;
}

int codec_rd_selector_error_s(codec_reader_t *r, int64_t value) {
    codec_decode_error_t *e = begin_error(r, CODEC_DECODE_SELECTOR);
    if (e) {
        e->value = (uint64_t)value;
        e->value_signed = true;
    }
    return -1;
}

int codec_rd_finish(codec_reader_t *r) {
    if (r->pos < r->len) {
        r->depth = 0;
        begin_error(r, CODEC_DECODE_UNEXPECTED);
        return -1;
    }
    return 0;
}

void codec_writer_init(codec_writer_t *w, uint8_t *buf, size_t cap) {
    w->buf = buf;
    w->cap = buf ? cap : 0;
    w->len = 0;
}

/* The low n bytes of v in the protocol's byte order. */
static codec_status_t put_uint(codec_writer_t *w, uint64_t v, size_t n) {
    size_t i;
    if (w->cap - w->len < n) {
        return CODEC_ERR_BUFFER;
    }
    for (i = 0; i < n; i++) {
#if CODEC_LITTLE_ENDIAN
        w->buf[w->len + i] = (uint8_t)(v >> (8 * i));
#else
        w->buf[w->len + i] = (uint8_t)(v >> (8 * (n - 1 - i)));
#endif
    }
    w->len += n;
    return CODEC_OK;
}

codec_status_t codec_wr_bool(codec_writer_t *w, const bool *v) {
    return put_uint(w, *v ? 1u : 0u, 1);
}

codec_status_t codec_wr_char(codec_writer_t *w, const char *v) {
    return codec_wr_chars(w, v, 1);
}

codec_status_t codec_wr_u8(codec_writer_t *w, const uint8_t *v) {
    return put_uint(w, *v, 1);
}

codec_status_t codec_wr_u16(codec_writer_t *w, const uint16_t *v) {
    return put_uint(w, *v, 2);
}

codec_status_t codec_wr_u32(codec_writer_t *w, const uint32_t *v) {
    return put_uint(w, *v, 4);
}

codec_status_t codec_wr_u64(codec_writer_t *w, const uint64_t *v) {
    return put_uint(w, *v, 8);
}

codec_status_t codec_wr_s8(codec_writer_t *w, const int8_t *v) {
    return put_uint(w, (uint64_t)(int64_t)*v, 1);
}

codec_status_t codec_wr_s16(codec_writer_t *w, const int16_t *v) {
    return put_uint(w, (uint64_t)(int64_t)*v, 2);
}

codec_status_t codec_wr_s32(codec_writer_t *w, const int32_t *v) {
    return put_uint(w, (uint64_t)(int64_t)*v, 4);
}

codec_status_t codec_wr_s64(codec_writer_t *w, const int64_t *v) {
    return put_uint(w, (uint64_t)*v, 8);
}

codec_status_t codec_wr_f32(codec_writer_t *w, const float *v) {
    uint32_t bits;
    memcpy(&bits, v, sizeof bits);
    return put_uint(w, bits, 4);
}

codec_status_t codec_wr_f64(codec_writer_t *w, const double *v) {
    uint64_t bits;
    memcpy(&bits, v, sizeof bits);
    return put_uint(w, bits, 8);
}

codec_status_t codec_wr_chars(codec_writer_t *w, const char *v, size_t n) {
    if (w->cap - w->len < n) {
        return CODEC_ERR_BUFFER;
    }
    if (n > 0) {
        memcpy(w->buf + w->len, v, n);
    }
    w->len += n;
    return CODEC_OK;
}
