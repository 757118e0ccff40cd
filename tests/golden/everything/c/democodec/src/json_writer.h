/* Private: bounded writer of canonical JSON text (docs/conformance.md section 4).
 * Generated: do not edit. */
#ifndef DEMO_JSON_WRITER_H
#define DEMO_JSON_WRITER_H

#include "democodec/status.h"

/* Writes into buf[0..cap); len counts every character, also those that did not fit. */
typedef struct {
    char *buf;
    size_t cap;
    size_t len;
} demo_jw_t;

void demo_jw_init(demo_jw_t *w, char *buf, size_t cap);
/* NUL-terminates (truncating if needed) and returns the full length. */
size_t demo_jw_finish(demo_jw_t *w);

void demo_jw_raw(demo_jw_t *w, const char *text, size_t n);
void demo_jw_lit(demo_jw_t *w, const char *text);
/* `"key":`, preceded by a comma unless *first. */
void demo_jw_key(demo_jw_t *w, int *first, const char *key);
/* A comma before every array element but the first. */
void demo_jw_sep(demo_jw_t *w, size_t index);
void demo_jw_uint(demo_jw_t *w, uint64_t v);
void demo_jw_int(demo_jw_t *w, int64_t v);
/* Lowercase hex in quotes. */
void demo_jw_hex(demo_jw_t *w, const uint8_t *bytes, size_t n);
/* Bytes as a JSON string: byte b -> U+00bb, escaped per section 4. */
void demo_jw_string(demo_jw_t *w, const char *bytes, size_t n);

/* One function per wire primitive, all taking a pointer (like the generated ones). */
void demo_jw_bool(demo_jw_t *w, const bool *v);
void demo_jw_char(demo_jw_t *w, const char *v);
void demo_jw_u8(demo_jw_t *w, const uint8_t *v);
void demo_jw_u16(demo_jw_t *w, const uint16_t *v);
void demo_jw_u32(demo_jw_t *w, const uint32_t *v);
void demo_jw_u64(demo_jw_t *w, const uint64_t *v);
void demo_jw_s8(demo_jw_t *w, const int8_t *v);
void demo_jw_s16(demo_jw_t *w, const int16_t *v);
void demo_jw_s32(demo_jw_t *w, const int32_t *v);
void demo_jw_s64(demo_jw_t *w, const int64_t *v);
void demo_jw_f32(demo_jw_t *w, const float *v);
void demo_jw_f64(demo_jw_t *w, const double *v);
void demo_jw_chars(demo_jw_t *w, const char *v, size_t n);

#endif
