/* Private: bounds-checked reader and writer used by the generated layouts, in the protocol's
 * byte order (MSCIPC_LITTLE_ENDIAN in protocol.h). Generated: do not edit. */
#ifndef MSCIPC_WIRE_H
#define MSCIPC_WIRE_H

#include "mscipcodec/status.h"

#include <string.h>

/* Reads field data. Every read checks the bytes left first; on failure it fills *err with the
 * current parameter path and returns -1 (0 on success). */
typedef struct {
    const uint8_t *data;
    size_t len;
    size_t pos;
    mscipc_path_segment_t path[MSCIPC_PATH_MAX_DEPTH];
    size_t depth;
    mscipc_decode_error_t *err;
} mscipc_reader_t;

void mscipc_reader_init(mscipc_reader_t *r, const uint8_t *data, size_t len, mscipc_decode_error_t *err);

/* Parameter path bookkeeping (the names are string literals). */
void mscipc_rd_push(mscipc_reader_t *r, const char *name);
void mscipc_rd_index(mscipc_reader_t *r, size_t index);
void mscipc_rd_pop(mscipc_reader_t *r);

int mscipc_rd_bool(mscipc_reader_t *r, bool *out);
int mscipc_rd_char(mscipc_reader_t *r, char *out);
int mscipc_rd_u8(mscipc_reader_t *r, uint8_t *out);
int mscipc_rd_u16(mscipc_reader_t *r, uint16_t *out);
int mscipc_rd_u32(mscipc_reader_t *r, uint32_t *out);
int mscipc_rd_u64(mscipc_reader_t *r, uint64_t *out);
int mscipc_rd_s8(mscipc_reader_t *r, int8_t *out);
int mscipc_rd_s16(mscipc_reader_t *r, int16_t *out);
int mscipc_rd_s32(mscipc_reader_t *r, int32_t *out);
int mscipc_rd_s64(mscipc_reader_t *r, int64_t *out);
int mscipc_rd_f32(mscipc_reader_t *r, float *out);
int mscipc_rd_f64(mscipc_reader_t *r, double *out);
/* A string of exactly n bytes, kept verbatim. */
int mscipc_rd_chars(mscipc_reader_t *r, char *out, size_t n);
/* A `remaining` array of fixed-size elements: the element count, checked against max. */
int mscipc_rd_remaining(mscipc_reader_t *r, size_t elem_size, uint64_t max, size_t *count);
/* Errors raised by generated code. */
int mscipc_rd_count_error(mscipc_reader_t *r, uint64_t count, uint64_t max);
int mscipc_rd_selector_error_u(mscipc_reader_t *r, uint64_t value);
int mscipc_rd_selector_error_s(mscipc_reader_t *r, int64_t value);
/* After the last parameter: leftover bytes are an error. */
int mscipc_rd_finish(mscipc_reader_t *r);

/* Straight loads in the protocol's byte order for fixed layouts (the caller has checked the
 * length). Signed and floating values take the bits of the unsigned value (exact-width types have
 * no padding). */
static inline uint8_t mscipc_ld_u8(const uint8_t *d) {
    return d[0];
}
#if MSCIPC_LITTLE_ENDIAN
static inline uint16_t mscipc_ld_u16(const uint8_t *d) {
    return (uint16_t)((unsigned)d[1] << 8 | d[0]);
}
static inline uint32_t mscipc_ld_u32(const uint8_t *d) {
    return (uint32_t)d[3] << 24 | (uint32_t)d[2] << 16 | (uint32_t)d[1] << 8 | (uint32_t)d[0];
}
static inline uint64_t mscipc_ld_u64(const uint8_t *d) {
    return (uint64_t)mscipc_ld_u32(d + 4) << 32 | mscipc_ld_u32(d);
}
#else
static inline uint16_t mscipc_ld_u16(const uint8_t *d) {
    return (uint16_t)((unsigned)d[0] << 8 | d[1]);
}
static inline uint32_t mscipc_ld_u32(const uint8_t *d) {
    return (uint32_t)d[0] << 24 | (uint32_t)d[1] << 16 | (uint32_t)d[2] << 8 | (uint32_t)d[3];
}
static inline uint64_t mscipc_ld_u64(const uint8_t *d) {
    return (uint64_t)mscipc_ld_u32(d) << 32 | mscipc_ld_u32(d + 4);
}
#endif
static inline bool mscipc_ld_bool(const uint8_t *d) {
    return d[0] != 0;
}
static inline char mscipc_ld_char(const uint8_t *d) {
    char c;
    memcpy(&c, d, 1);
    return c;
}
static inline int8_t mscipc_ld_s8(const uint8_t *d) {
    int8_t v;
    memcpy(&v, d, 1);
    return v;
}
static inline int16_t mscipc_ld_s16(const uint8_t *d) {
    uint16_t u = mscipc_ld_u16(d);
    int16_t v;
    memcpy(&v, &u, sizeof v);
    return v;
}
static inline int32_t mscipc_ld_s32(const uint8_t *d) {
    uint32_t u = mscipc_ld_u32(d);
    int32_t v;
    memcpy(&v, &u, sizeof v);
    return v;
}
static inline int64_t mscipc_ld_s64(const uint8_t *d) {
    uint64_t u = mscipc_ld_u64(d);
    int64_t v;
    memcpy(&v, &u, sizeof v);
    return v;
}
static inline float mscipc_ld_f32(const uint8_t *d) {
    uint32_t u = mscipc_ld_u32(d);
    float v;
    memcpy(&v, &u, sizeof v);
    return v;
}
static inline double mscipc_ld_f64(const uint8_t *d) {
    uint64_t u = mscipc_ld_u64(d);
    double v;
    memcpy(&v, &u, sizeof v);
    return v;
}

/* Writes field data into a bounded buffer; functions return MSCIPC_OK or MSCIPC_ERR_BUFFER. */
typedef struct {
    uint8_t *buf;
    size_t cap;
    size_t len;
} mscipc_writer_t;

void mscipc_writer_init(mscipc_writer_t *w, uint8_t *buf, size_t cap);

mscipc_status_t mscipc_wr_bool(mscipc_writer_t *w, const bool *v);
mscipc_status_t mscipc_wr_char(mscipc_writer_t *w, const char *v);
mscipc_status_t mscipc_wr_u8(mscipc_writer_t *w, const uint8_t *v);
mscipc_status_t mscipc_wr_u16(mscipc_writer_t *w, const uint16_t *v);
mscipc_status_t mscipc_wr_u32(mscipc_writer_t *w, const uint32_t *v);
mscipc_status_t mscipc_wr_u64(mscipc_writer_t *w, const uint64_t *v);
mscipc_status_t mscipc_wr_s8(mscipc_writer_t *w, const int8_t *v);
mscipc_status_t mscipc_wr_s16(mscipc_writer_t *w, const int16_t *v);
mscipc_status_t mscipc_wr_s32(mscipc_writer_t *w, const int32_t *v);
mscipc_status_t mscipc_wr_s64(mscipc_writer_t *w, const int64_t *v);
mscipc_status_t mscipc_wr_f32(mscipc_writer_t *w, const float *v);
mscipc_status_t mscipc_wr_f64(mscipc_writer_t *w, const double *v);
mscipc_status_t mscipc_wr_chars(mscipc_writer_t *w, const char *v, size_t n);

#endif
