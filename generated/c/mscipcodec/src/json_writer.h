/* Private: bounded writer of canonical JSON text (docs/conformance.md section 4).
 * Generated: do not edit. */
#ifndef MSCIP_JSON_WRITER_H
#define MSCIP_JSON_WRITER_H

#include "mscipcodec/status.h"

/* Writes into buf[0..cap); len counts every character, also those that did not fit. */
typedef struct {
    char *buf;
    size_t cap;
    size_t len;
} mscip_jw_t;

void mscip_jw_init(mscip_jw_t *w, char *buf, size_t cap);
/* NUL-terminates (truncating if needed) and returns the full length. */
size_t mscip_jw_finish(mscip_jw_t *w);

void mscip_jw_raw(mscip_jw_t *w, const char *text, size_t n);
void mscip_jw_lit(mscip_jw_t *w, const char *text);
/* `"key":`, preceded by a comma unless *first. */
void mscip_jw_key(mscip_jw_t *w, int *first, const char *key);
/* A comma before every array element but the first. */
void mscip_jw_sep(mscip_jw_t *w, size_t index);
void mscip_jw_uint(mscip_jw_t *w, uint64_t v);
void mscip_jw_int(mscip_jw_t *w, int64_t v);
/* Lowercase hex in quotes. */
void mscip_jw_hex(mscip_jw_t *w, const uint8_t *bytes, size_t n);
/* Bytes as a JSON string: byte b -> U+00bb, escaped per section 4. */
void mscip_jw_string(mscip_jw_t *w, const char *bytes, size_t n);

/* One function per wire primitive, all taking a pointer (like the generated ones). */
void mscip_jw_bool(mscip_jw_t *w, const bool *v);
void mscip_jw_char(mscip_jw_t *w, const char *v);
void mscip_jw_u8(mscip_jw_t *w, const uint8_t *v);
void mscip_jw_u16(mscip_jw_t *w, const uint16_t *v);
void mscip_jw_u32(mscip_jw_t *w, const uint32_t *v);
void mscip_jw_u64(mscip_jw_t *w, const uint64_t *v);
void mscip_jw_s8(mscip_jw_t *w, const int8_t *v);
void mscip_jw_s16(mscip_jw_t *w, const int16_t *v);
void mscip_jw_s32(mscip_jw_t *w, const int32_t *v);
void mscip_jw_s64(mscip_jw_t *w, const int64_t *v);
void mscip_jw_f32(mscip_jw_t *w, const float *v);
void mscip_jw_f64(mscip_jw_t *w, const double *v);
void mscip_jw_chars(mscip_jw_t *w, const char *v, size_t n);

#endif
