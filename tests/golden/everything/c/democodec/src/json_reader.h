/* Private: reader of the JSON lines the decoder prints (no allocation). Values are addressed
 * by their position in the line; objects are looked up by key, so key order does not matter.
 * Functions return 0 (or 1 = found) on success and -1 after recording a message that names the
 * JSON path of the bad value. Generated: do not edit. */
#ifndef DEMO_JSON_READER_H
#define DEMO_JSON_READER_H

#include "democodec/status.h"

#define DEMO_JR_MAX_DEPTH (DEMO_PATH_MAX_DEPTH + 8)

typedef struct {
    const char *s;
    size_t len;
    char *msg;
    size_t msg_cap;
    bool failed;
    const char *path[DEMO_JR_MAX_DEPTH];
    size_t index[DEMO_JR_MAX_DEPTH];
    size_t depth;
} demo_jr_t;

void demo_jr_init(demo_jr_t *jr, const char *s, size_t len, char *msg, size_t msg_cap);
/* Records "<path>: <message>" (only the first failure is kept); returns -1. */
int demo_jr_fail(demo_jr_t *jr, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
void demo_jr_push(demo_jr_t *jr, const char *name);
void demo_jr_index(demo_jr_t *jr, size_t index);
void demo_jr_pop(demo_jr_t *jr);

/* Position of the first non-space character at or after pos. */
size_t demo_jr_ws(const demo_jr_t *jr, size_t pos);
/* Checks the value at pos is well-formed JSON; *end is the position after it. */
int demo_jr_skip(demo_jr_t *jr, size_t pos, size_t *end);
/* The whole line is one JSON object (nothing after it). */
int demo_jr_document(demo_jr_t *jr, size_t *pos);
/* An object whose keys are all among keys[0..n) and appear once. */
int demo_jr_object(demo_jr_t *jr, size_t pos, const char *const *keys, size_t n);
/* After demo_jr_object: 1 and the value position if key is present, else 0. */
int demo_jr_get(demo_jr_t *jr, size_t pos, const char *key, size_t *value);
/* Iterates an array: begin, then next returns 1 per element, 0 at the end. */
int demo_jr_array(demo_jr_t *jr, size_t pos, size_t *it);
int demo_jr_next(demo_jr_t *jr, size_t *it, size_t *elem);

int demo_jr_uint(demo_jr_t *jr, size_t pos, uint64_t max, uint64_t *out);
int demo_jr_sint(demo_jr_t *jr, size_t pos, int64_t min, int64_t max, int64_t *out);
int demo_jr_null(demo_jr_t *jr, size_t pos);
/* A string of lowercase or uppercase hex pairs, at most cap bytes. */
int demo_jr_hex(demo_jr_t *jr, size_t pos, uint8_t *out, size_t cap, size_t *n);
/* True when the value at pos is a string. */
bool demo_jr_is_string(const demo_jr_t *jr, size_t pos);

int demo_jr_bool(demo_jr_t *jr, size_t pos, bool *out);
int demo_jr_char(demo_jr_t *jr, size_t pos, char *out);
int demo_jr_u8(demo_jr_t *jr, size_t pos, uint8_t *out);
int demo_jr_u16(demo_jr_t *jr, size_t pos, uint16_t *out);
int demo_jr_u32(demo_jr_t *jr, size_t pos, uint32_t *out);
int demo_jr_u64(demo_jr_t *jr, size_t pos, uint64_t *out);
int demo_jr_s8(demo_jr_t *jr, size_t pos, int8_t *out);
int demo_jr_s16(demo_jr_t *jr, size_t pos, int16_t *out);
int demo_jr_s32(demo_jr_t *jr, size_t pos, int32_t *out);
int demo_jr_s64(demo_jr_t *jr, size_t pos, int64_t *out);
int demo_jr_f32(demo_jr_t *jr, size_t pos, float *out);
int demo_jr_f64(demo_jr_t *jr, size_t pos, double *out);
/* A string of exactly n characters (U+0000..U+00FF), stored as bytes. */
int demo_jr_chars(demo_jr_t *jr, size_t pos, char *out, size_t n);

#endif
