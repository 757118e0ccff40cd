/* Private: bounded writer of canonical JSON text (docs/conformance.md section 4).
 * Generated: do not edit. */
#ifndef MIPC_JSON_WRITER_H
#define MIPC_JSON_WRITER_H

#include "mipcodec/status.h"

/* Writes into buf[0..cap); len counts every character, also those that did not fit. */
typedef struct {
    char *buf;
    size_t cap;
    size_t len;
} mipc_jw_t;

void mipc_jw_init(mipc_jw_t *w, char *buf, size_t cap);
/* NUL-terminates (truncating if needed) and returns the full length. */
size_t mipc_jw_finish(mipc_jw_t *w);

void mipc_jw_raw(mipc_jw_t *w, const char *text, size_t n);
void mipc_jw_lit(mipc_jw_t *w, const char *text);
/* `"key":`, preceded by a comma unless *first. */
void mipc_jw_key(mipc_jw_t *w, int *first, const char *key);
/* A comma before every array element but the first. */
void mipc_jw_sep(mipc_jw_t *w, size_t index);
void mipc_jw_uint(mipc_jw_t *w, uint64_t v);
void mipc_jw_int(mipc_jw_t *w, int64_t v);
/* Lowercase hex in quotes. */
void mipc_jw_hex(mipc_jw_t *w, const uint8_t *bytes, size_t n);
/* Bytes as a JSON string: byte b -> U+00bb, escaped per section 4. */
void mipc_jw_string(mipc_jw_t *w, const char *bytes, size_t n);

/* One function per wire primitive, all taking a pointer (like the generated ones). */
void mipc_jw_bool(mipc_jw_t *w, const bool *v);
void mipc_jw_char(mipc_jw_t *w, const char *v);
void mipc_jw_u8(mipc_jw_t *w, const uint8_t *v);
void mipc_jw_u16(mipc_jw_t *w, const uint16_t *v);
void mipc_jw_u32(mipc_jw_t *w, const uint32_t *v);
void mipc_jw_u64(mipc_jw_t *w, const uint64_t *v);
void mipc_jw_s8(mipc_jw_t *w, const int8_t *v);
void mipc_jw_s16(mipc_jw_t *w, const int16_t *v);
void mipc_jw_s32(mipc_jw_t *w, const int32_t *v);
void mipc_jw_s64(mipc_jw_t *w, const int64_t *v);
void mipc_jw_f32(mipc_jw_t *w, const float *v);
void mipc_jw_f64(mipc_jw_t *w, const double *v);
void mipc_jw_chars(mipc_jw_t *w, const char *v, size_t n);

#endif
