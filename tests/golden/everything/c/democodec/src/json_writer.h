/* Private: bounded writer of canonical JSON text (docs/conformance.md section 4).
 * Generated: do not edit. */
#ifndef DEMOC_JSON_WRITER_H
#define DEMOC_JSON_WRITER_H

#include "democodec/status.h"

/* Writes into buf[0..cap); len counts every character, also those that did not fit. */
typedef struct {
    char *buf;
    size_t cap;
    size_t len;
} democ_jw_t;

void democ_jw_init(democ_jw_t *w, char *buf, size_t cap);
/* NUL-terminates (truncating if needed) and returns the full length. */
size_t democ_jw_finish(democ_jw_t *w);

void democ_jw_raw(democ_jw_t *w, const char *text, size_t n);
void democ_jw_lit(democ_jw_t *w, const char *text);
/* `"key":`, preceded by a comma unless *first. */
void democ_jw_key(democ_jw_t *w, int *first, const char *key);
/* A comma before every array element but the first. */
void democ_jw_sep(democ_jw_t *w, size_t index);
void democ_jw_uint(democ_jw_t *w, uint64_t v);
void democ_jw_int(democ_jw_t *w, int64_t v);
/* Lowercase hex in quotes. */
void democ_jw_hex(democ_jw_t *w, const uint8_t *bytes, size_t n);
/* Bytes as a JSON string: byte b -> U+00bb, escaped per section 4. */
void democ_jw_string(democ_jw_t *w, const char *bytes, size_t n);

/* One function per wire primitive, all taking a pointer (like the generated ones). */
void democ_jw_bool(democ_jw_t *w, const bool *v);
void democ_jw_char(democ_jw_t *w, const char *v);
void democ_jw_u8(democ_jw_t *w, const uint8_t *v);
void democ_jw_u16(democ_jw_t *w, const uint16_t *v);
void democ_jw_u32(democ_jw_t *w, const uint32_t *v);
void democ_jw_u64(democ_jw_t *w, const uint64_t *v);
void democ_jw_s8(democ_jw_t *w, const int8_t *v);
void democ_jw_s16(democ_jw_t *w, const int16_t *v);
void democ_jw_s32(democ_jw_t *w, const int32_t *v);
void democ_jw_s64(democ_jw_t *w, const int64_t *v);
void democ_jw_f32(democ_jw_t *w, const float *v);
void democ_jw_f64(democ_jw_t *w, const double *v);
void democ_jw_chars(democ_jw_t *w, const char *v, size_t n);

#endif
