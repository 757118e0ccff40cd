/* Private: bounded writer of canonical JSON text (docs/conformance.md section 4).
 * Generated: do not edit. */
#ifndef MSCIPC_JSON_WRITER_H
#define MSCIPC_JSON_WRITER_H

#include "mscipcodec/status.h"

/* Writes into buf[0..cap); len counts every character, also those that did not fit. */
typedef struct {
    char *buf;
    size_t cap;
    size_t len;
} mscipc_jw_t;

void mscipc_jw_init(mscipc_jw_t *w, char *buf, size_t cap);
/* NUL-terminates (truncating if needed) and returns the full length. */
size_t mscipc_jw_finish(mscipc_jw_t *w);

void mscipc_jw_raw(mscipc_jw_t *w, const char *text, size_t n);
void mscipc_jw_lit(mscipc_jw_t *w, const char *text);
/* `"key":`, preceded by a comma unless *first. */
void mscipc_jw_key(mscipc_jw_t *w, int *first, const char *key);
/* A comma before every array element but the first. */
void mscipc_jw_sep(mscipc_jw_t *w, size_t index);
void mscipc_jw_uint(mscipc_jw_t *w, uint64_t v);
void mscipc_jw_int(mscipc_jw_t *w, int64_t v);
/* Lowercase hex in quotes. */
void mscipc_jw_hex(mscipc_jw_t *w, const uint8_t *bytes, size_t n);
/* Bytes as a JSON string: byte b -> U+00bb, escaped per section 4. */
void mscipc_jw_string(mscipc_jw_t *w, const char *bytes, size_t n);

/* One function per wire primitive, all taking a pointer (like the generated ones). */
void mscipc_jw_bool(mscipc_jw_t *w, const bool *v);
void mscipc_jw_char(mscipc_jw_t *w, const char *v);
void mscipc_jw_u8(mscipc_jw_t *w, const uint8_t *v);
void mscipc_jw_u16(mscipc_jw_t *w, const uint16_t *v);
void mscipc_jw_u32(mscipc_jw_t *w, const uint32_t *v);
void mscipc_jw_u64(mscipc_jw_t *w, const uint64_t *v);
void mscipc_jw_s8(mscipc_jw_t *w, const int8_t *v);
void mscipc_jw_s16(mscipc_jw_t *w, const int16_t *v);
void mscipc_jw_s32(mscipc_jw_t *w, const int32_t *v);
void mscipc_jw_s64(mscipc_jw_t *w, const int64_t *v);
void mscipc_jw_f32(mscipc_jw_t *w, const float *v);
void mscipc_jw_f64(mscipc_jw_t *w, const double *v);
void mscipc_jw_chars(mscipc_jw_t *w, const char *v, size_t n);

#endif
