/* Private: bounded writer of canonical JSON text (docs/conformance.md section 4).
 * Generated: do not edit. */
#ifndef MIP_JSON_WRITER_H
#define MIP_JSON_WRITER_H

#include "mipcodec/status.h"

/* Writes into buf[0..cap); len counts every character, also those that did not fit. */
typedef struct {
    char *buf;
    size_t cap;
    size_t len;
} mip_jw_t;

void mip_jw_init(mip_jw_t *w, char *buf, size_t cap);
/* NUL-terminates (truncating if needed) and returns the full length. */
size_t mip_jw_finish(mip_jw_t *w);

void mip_jw_raw(mip_jw_t *w, const char *text, size_t n);
void mip_jw_lit(mip_jw_t *w, const char *text);
/* `"key":`, preceded by a comma unless *first. */
void mip_jw_key(mip_jw_t *w, int *first, const char *key);
/* A comma before every array element but the first. */
void mip_jw_sep(mip_jw_t *w, size_t index);
void mip_jw_uint(mip_jw_t *w, uint64_t v);
void mip_jw_int(mip_jw_t *w, int64_t v);
/* Lowercase hex in quotes. */
void mip_jw_hex(mip_jw_t *w, const uint8_t *bytes, size_t n);
/* Bytes as a JSON string: byte b -> U+00bb, escaped per section 4. */
void mip_jw_string(mip_jw_t *w, const char *bytes, size_t n);

/* One function per wire primitive, all taking a pointer (like the generated ones). */
void mip_jw_bool(mip_jw_t *w, const bool *v);
void mip_jw_char(mip_jw_t *w, const char *v);
void mip_jw_u8(mip_jw_t *w, const uint8_t *v);
void mip_jw_u16(mip_jw_t *w, const uint16_t *v);
void mip_jw_u32(mip_jw_t *w, const uint32_t *v);
void mip_jw_u64(mip_jw_t *w, const uint64_t *v);
void mip_jw_s8(mip_jw_t *w, const int8_t *v);
void mip_jw_s16(mip_jw_t *w, const int16_t *v);
void mip_jw_s32(mip_jw_t *w, const int32_t *v);
void mip_jw_s64(mip_jw_t *w, const int64_t *v);
void mip_jw_f32(mip_jw_t *w, const float *v);
void mip_jw_f64(mip_jw_t *w, const double *v);
void mip_jw_chars(mip_jw_t *w, const char *v, size_t n);

#endif
