/* Private: bounded writer of canonical JSON text (docs/conformance.md section 4). */
#ifndef CODEC_JSON_WRITER_H
#define CODEC_JSON_WRITER_H

#include "codec/status.h"

/* Writes into buf[0..cap); len counts every character, also those that did not fit. */
typedef struct {
    char *buf;
    size_t cap;
    size_t len;
} codec_jw_t;

void codec_jw_init(codec_jw_t *w, char *buf, size_t cap);
/* NUL-terminates (truncating if needed) and returns the full length. */
size_t codec_jw_finish(codec_jw_t *w);

void codec_jw_raw(codec_jw_t *w, const char *text, size_t n);
void codec_jw_lit(codec_jw_t *w, const char *text);
/* `"key":`, preceded by a comma unless *first. */
void codec_jw_key(codec_jw_t *w, int *first, const char *key);
/* A comma before every array element but the first. */
void codec_jw_sep(codec_jw_t *w, size_t index);
void codec_jw_uint(codec_jw_t *w, uint64_t v);
void codec_jw_int(codec_jw_t *w, int64_t v);
/* Lowercase hex in quotes. */
void codec_jw_hex(codec_jw_t *w, const uint8_t *bytes, size_t n);
/* Bytes as a JSON string: byte b -> U+00bb, escaped per section 4. */
void codec_jw_string(codec_jw_t *w, const char *bytes, size_t n);

/* One function per wire primitive, all taking a pointer (like the generated ones). */
void codec_jw_bool(codec_jw_t *w, const bool *v);
void codec_jw_char(codec_jw_t *w, const char *v);
void codec_jw_u8(codec_jw_t *w, const uint8_t *v);
void codec_jw_u16(codec_jw_t *w, const uint16_t *v);
void codec_jw_u32(codec_jw_t *w, const uint32_t *v);
void codec_jw_u64(codec_jw_t *w, const uint64_t *v);
void codec_jw_s8(codec_jw_t *w, const int8_t *v);
void codec_jw_s16(codec_jw_t *w, const int16_t *v);
void codec_jw_s32(codec_jw_t *w, const int32_t *v);
void codec_jw_s64(codec_jw_t *w, const int64_t *v);
void codec_jw_f32(codec_jw_t *w, const float *v);
void codec_jw_f64(codec_jw_t *w, const double *v);
void codec_jw_chars(codec_jw_t *w, const char *v, size_t n);

#endif
