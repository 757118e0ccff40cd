/* Private: bounds-checked reader and writer used by the generated layouts, in the protocol's
 * byte order (MIPC_LITTLE_ENDIAN in protocol.h). Generated: do not edit. */
#ifndef MIPC_WIRE_H
#define MIPC_WIRE_H

#include "mipcodec/status.h"

#include <string.h>

/* Reads field data. Every read checks the bytes left first; on failure it fills *err with the
 * current parameter path and returns -1 (0 on success). */
typedef struct {
    const uint8_t *data;
    size_t len;
    size_t pos;
    mipc_path_segment_t path[MIPC_PATH_MAX_DEPTH];
    size_t depth;
    mipc_decode_error_t *err;
} mipc_reader_t;

void mipc_reader_init(mipc_reader_t *r, const uint8_t *data, size_t len, mipc_decode_error_t *err);

/* Parameter path bookkeeping (the names are string literals). */
void mipc_rd_push(mipc_reader_t *r, const char *name);
void mipc_rd_index(mipc_reader_t *r, size_t index);
void mipc_rd_pop(mipc_reader_t *r);

int mipc_rd_bool(mipc_reader_t *r, bool *out);
int mipc_rd_char(mipc_reader_t *r, char *out);
int mipc_rd_u8(mipc_reader_t *r, uint8_t *out);
int mipc_rd_u16(mipc_reader_t *r, uint16_t *out);
int mipc_rd_u32(mipc_reader_t *r, uint32_t *out);
int mipc_rd_u64(mipc_reader_t *r, uint64_t *out);
int mipc_rd_s8(mipc_reader_t *r, int8_t *out);
int mipc_rd_s16(mipc_reader_t *r, int16_t *out);
int mipc_rd_s32(mipc_reader_t *r, int32_t *out);
int mipc_rd_s64(mipc_reader_t *r, int64_t *out);
int mipc_rd_f32(mipc_reader_t *r, float *out);
int mipc_rd_f64(mipc_reader_t *r, double *out);
/* A string of exactly n bytes, kept verbatim. */
int mipc_rd_chars(mipc_reader_t *r, char *out, size_t n);
/* A `remaining` array of fixed-size elements: the element count, checked against max. */
int mipc_rd_remaining(mipc_reader_t *r, size_t elem_size, uint64_t max, size_t *count);
/* Errors raised by generated code. */
int mipc_rd_count_error(mipc_reader_t *r, uint64_t count, uint64_t max);
int mipc_rd_selector_error_u(mipc_reader_t *r, uint64_t value);
int mipc_rd_selector_error_s(mipc_reader_t *r, int64_t value);
/* After the last parameter: leftover bytes are an error. */
int mipc_rd_finish(mipc_reader_t *r);

/* Straight loads in the protocol's byte order for fixed layouts (the caller has checked the
 * length). Signed and floating values take the bits of the unsigned value (exact-width types have
 * no padding). */
static inline uint8_t mipc_ld_u8(const uint8_t *d) {
    return d[0];
}
#if MIPC_LITTLE_ENDIAN
static inline uint16_t mipc_ld_u16(const uint8_t *d) {
    return (uint16_t)((unsigned)d[1] << 8 | d[0]);
}
static inline uint32_t mipc_ld_u32(const uint8_t *d) {
    return (uint32_t)d[3] << 24 | (uint32_t)d[2] << 16 | (uint32_t)d[1] << 8 | (uint32_t)d[0];
}
static inline uint64_t mipc_ld_u64(const uint8_t *d) {
    return (uint64_t)mipc_ld_u32(d + 4) << 32 | mipc_ld_u32(d);
}
#else
static inline uint16_t mipc_ld_u16(const uint8_t *d) {
    return (uint16_t)((unsigned)d[0] << 8 | d[1]);
}
static inline uint32_t mipc_ld_u32(const uint8_t *d) {
    return (uint32_t)d[0] << 24 | (uint32_t)d[1] << 16 | (uint32_t)d[2] << 8 | (uint32_t)d[3];
}
static inline uint64_t mipc_ld_u64(const uint8_t *d) {
    return (uint64_t)mipc_ld_u32(d) << 32 | mipc_ld_u32(d + 4);
}
#endif
static inline bool mipc_ld_bool(const uint8_t *d) {
    return d[0] != 0;
}
static inline char mipc_ld_char(const uint8_t *d) {
    char c;
    memcpy(&c, d, 1);
    return c;
}
static inline int8_t mipc_ld_s8(const uint8_t *d) {
    int8_t v;
    memcpy(&v, d, 1);
    return v;
}
static inline int16_t mipc_ld_s16(const uint8_t *d) {
    uint16_t u = mipc_ld_u16(d);
    int16_t v;
    memcpy(&v, &u, sizeof v);
    return v;
}
static inline int32_t mipc_ld_s32(const uint8_t *d) {
    uint32_t u = mipc_ld_u32(d);
    int32_t v;
    memcpy(&v, &u, sizeof v);
    return v;
}
static inline int64_t mipc_ld_s64(const uint8_t *d) {
    uint64_t u = mipc_ld_u64(d);
    int64_t v;
    memcpy(&v, &u, sizeof v);
    return v;
}
static inline float mipc_ld_f32(const uint8_t *d) {
    uint32_t u = mipc_ld_u32(d);
    float v;
    memcpy(&v, &u, sizeof v);
    return v;
}
static inline double mipc_ld_f64(const uint8_t *d) {
    uint64_t u = mipc_ld_u64(d);
    double v;
    memcpy(&v, &u, sizeof v);
    return v;
}

/* Writes field data into a bounded buffer; functions return MIPC_OK or MIPC_ERR_BUFFER. */
typedef struct {
    uint8_t *buf;
    size_t cap;
    size_t len;
} mipc_writer_t;

void mipc_writer_init(mipc_writer_t *w, uint8_t *buf, size_t cap);

mipc_status_t mipc_wr_bool(mipc_writer_t *w, const bool *v);
mipc_status_t mipc_wr_char(mipc_writer_t *w, const char *v);
mipc_status_t mipc_wr_u8(mipc_writer_t *w, const uint8_t *v);
mipc_status_t mipc_wr_u16(mipc_writer_t *w, const uint16_t *v);
mipc_status_t mipc_wr_u32(mipc_writer_t *w, const uint32_t *v);
mipc_status_t mipc_wr_u64(mipc_writer_t *w, const uint64_t *v);
mipc_status_t mipc_wr_s8(mipc_writer_t *w, const int8_t *v);
mipc_status_t mipc_wr_s16(mipc_writer_t *w, const int16_t *v);
mipc_status_t mipc_wr_s32(mipc_writer_t *w, const int32_t *v);
mipc_status_t mipc_wr_s64(mipc_writer_t *w, const int64_t *v);
mipc_status_t mipc_wr_f32(mipc_writer_t *w, const float *v);
mipc_status_t mipc_wr_f64(mipc_writer_t *w, const double *v);
mipc_status_t mipc_wr_chars(mipc_writer_t *w, const char *v, size_t n);

#endif
