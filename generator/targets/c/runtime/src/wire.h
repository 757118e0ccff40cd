/* Private: bounds-checked reader and writer used by the generated layouts, in the protocol's
 * byte order (CODEC_LITTLE_ENDIAN in protocol.h). */
#ifndef CODEC_WIRE_H
#define CODEC_WIRE_H

#include "codec/status.h"

#include <string.h>

/* Reads field data. Every read checks the bytes left first; on failure it fills *err with the
 * current parameter path and returns -1 (0 on success). */
typedef struct {
    const uint8_t *data;
    size_t len;
    size_t pos;
    codec_path_segment_t path[CODEC_PATH_MAX_DEPTH];
    size_t depth;
    codec_decode_error_t *err;
} codec_reader_t;

void codec_reader_init(codec_reader_t *r, const uint8_t *data, size_t len, codec_decode_error_t *err);

/* Parameter path bookkeeping (the names are string literals). */
void codec_rd_push(codec_reader_t *r, const char *name);
void codec_rd_index(codec_reader_t *r, size_t index);
void codec_rd_pop(codec_reader_t *r);

int codec_rd_bool(codec_reader_t *r, bool *out);
int codec_rd_char(codec_reader_t *r, char *out);
int codec_rd_u8(codec_reader_t *r, uint8_t *out);
int codec_rd_u16(codec_reader_t *r, uint16_t *out);
int codec_rd_u32(codec_reader_t *r, uint32_t *out);
int codec_rd_u64(codec_reader_t *r, uint64_t *out);
int codec_rd_s8(codec_reader_t *r, int8_t *out);
int codec_rd_s16(codec_reader_t *r, int16_t *out);
int codec_rd_s32(codec_reader_t *r, int32_t *out);
int codec_rd_s64(codec_reader_t *r, int64_t *out);
int codec_rd_f32(codec_reader_t *r, float *out);
int codec_rd_f64(codec_reader_t *r, double *out);
/* A string of exactly n bytes, kept verbatim. */
int codec_rd_chars(codec_reader_t *r, char *out, size_t n);
/* A `remaining` array of fixed-size elements: the element count, checked against max. */
int codec_rd_remaining(codec_reader_t *r, size_t elem_size, uint64_t max, size_t *count);
/* Errors raised by generated code. */
int codec_rd_count_error(codec_reader_t *r, uint64_t count, uint64_t max);
int codec_rd_selector_error_u(codec_reader_t *r, uint64_t value);
int codec_rd_selector_error_s(codec_reader_t *r, int64_t value);
/* After the last parameter: leftover bytes are an error. */
int codec_rd_finish(codec_reader_t *r);

/* Straight loads in the protocol's byte order for fixed layouts (the caller has checked the
 * length). Signed and floating values take the bits of the unsigned value (exact-width types have
 * no padding). */
static inline uint8_t codec_ld_u8(const uint8_t *d) {
    return d[0];
}
#if CODEC_LITTLE_ENDIAN
static inline uint16_t codec_ld_u16(const uint8_t *d) {
    return (uint16_t)((unsigned)d[1] << 8 | d[0]);
}
static inline uint32_t codec_ld_u32(const uint8_t *d) {
    return (uint32_t)d[3] << 24 | (uint32_t)d[2] << 16 | (uint32_t)d[1] << 8 | (uint32_t)d[0];
}
static inline uint64_t codec_ld_u64(const uint8_t *d) {
    return (uint64_t)codec_ld_u32(d + 4) << 32 | codec_ld_u32(d);
}
#else
static inline uint16_t codec_ld_u16(const uint8_t *d) {
    return (uint16_t)((unsigned)d[0] << 8 | d[1]);
}
static inline uint32_t codec_ld_u32(const uint8_t *d) {
    return (uint32_t)d[0] << 24 | (uint32_t)d[1] << 16 | (uint32_t)d[2] << 8 | (uint32_t)d[3];
}
static inline uint64_t codec_ld_u64(const uint8_t *d) {
    return (uint64_t)codec_ld_u32(d) << 32 | codec_ld_u32(d + 4);
}
#endif
static inline bool codec_ld_bool(const uint8_t *d) {
    return d[0] != 0;
}
static inline char codec_ld_char(const uint8_t *d) {
    char c;
    memcpy(&c, d, 1);
    return c;
}
static inline int8_t codec_ld_s8(const uint8_t *d) {
    int8_t v;
    memcpy(&v, d, 1);
    return v;
}
static inline int16_t codec_ld_s16(const uint8_t *d) {
    uint16_t u = codec_ld_u16(d);
    int16_t v;
    memcpy(&v, &u, sizeof v);
    return v;
}
static inline int32_t codec_ld_s32(const uint8_t *d) {
    uint32_t u = codec_ld_u32(d);
    int32_t v;
    memcpy(&v, &u, sizeof v);
    return v;
}
static inline int64_t codec_ld_s64(const uint8_t *d) {
    uint64_t u = codec_ld_u64(d);
    int64_t v;
    memcpy(&v, &u, sizeof v);
    return v;
}
static inline float codec_ld_f32(const uint8_t *d) {
    uint32_t u = codec_ld_u32(d);
    float v;
    memcpy(&v, &u, sizeof v);
    return v;
}
static inline double codec_ld_f64(const uint8_t *d) {
    uint64_t u = codec_ld_u64(d);
    double v;
    memcpy(&v, &u, sizeof v);
    return v;
}

/* Writes field data into a bounded buffer; functions return CODEC_OK or CODEC_ERR_BUFFER. */
typedef struct {
    uint8_t *buf;
    size_t cap;
    size_t len;
} codec_writer_t;

void codec_writer_init(codec_writer_t *w, uint8_t *buf, size_t cap);

codec_status_t codec_wr_bool(codec_writer_t *w, const bool *v);
codec_status_t codec_wr_char(codec_writer_t *w, const char *v);
codec_status_t codec_wr_u8(codec_writer_t *w, const uint8_t *v);
codec_status_t codec_wr_u16(codec_writer_t *w, const uint16_t *v);
codec_status_t codec_wr_u32(codec_writer_t *w, const uint32_t *v);
codec_status_t codec_wr_u64(codec_writer_t *w, const uint64_t *v);
codec_status_t codec_wr_s8(codec_writer_t *w, const int8_t *v);
codec_status_t codec_wr_s16(codec_writer_t *w, const int16_t *v);
codec_status_t codec_wr_s32(codec_writer_t *w, const int32_t *v);
codec_status_t codec_wr_s64(codec_writer_t *w, const int64_t *v);
codec_status_t codec_wr_f32(codec_writer_t *w, const float *v);
codec_status_t codec_wr_f64(codec_writer_t *w, const double *v);
codec_status_t codec_wr_chars(codec_writer_t *w, const char *v, size_t n);

#endif
