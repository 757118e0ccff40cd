/* Private: reader of the JSON lines the decoder prints (no allocation). Values are addressed
 * by their position in the line; objects are looked up by key, so key order does not matter.
 * Functions return 0 (or 1 = found) on success and -1 after recording a message that names the
 * JSON path of the bad value. Generated: do not edit. */
#ifndef MIPC_JSON_READER_H
#define MIPC_JSON_READER_H

#include "mipcodec/status.h"

#define MIPC_JR_MAX_DEPTH (MIPC_PATH_MAX_DEPTH + 8)

typedef struct {
    const char *s;
    size_t len;
    char *msg;
    size_t msg_cap;
    bool failed;
    const char *path[MIPC_JR_MAX_DEPTH];
    size_t index[MIPC_JR_MAX_DEPTH];
    size_t depth;
} mipc_jr_t;

void mipc_jr_init(mipc_jr_t *jr, const char *s, size_t len, char *msg, size_t msg_cap);
/* Records "<path>: <message>" (only the first failure is kept); returns -1. */
int mipc_jr_fail(mipc_jr_t *jr, const char *fmt, ...)
#if defined(__MINGW32__)
    /* MinGW-w64: the package builds with __USE_MINGW_ANSI_STDIO (C99 formats), not msvcrt's */
    __attribute__((format(gnu_printf, 2, 3)))
#elif defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
void mipc_jr_push(mipc_jr_t *jr, const char *name);
void mipc_jr_index(mipc_jr_t *jr, size_t index);
void mipc_jr_pop(mipc_jr_t *jr);

/* Position of the first non-space character at or after pos. */
size_t mipc_jr_ws(const mipc_jr_t *jr, size_t pos);
/* Checks the value at pos is well-formed JSON; *end is the position after it. */
int mipc_jr_skip(mipc_jr_t *jr, size_t pos, size_t *end);
/* The whole line is one JSON object (nothing after it). */
int mipc_jr_document(mipc_jr_t *jr, size_t *pos);
/* An object whose keys are all among keys[0..n) and appear once. */
int mipc_jr_object(mipc_jr_t *jr, size_t pos, const char *const *keys, size_t n);
/* After mipc_jr_object: 1 and the value position if key is present, else 0. */
int mipc_jr_get(mipc_jr_t *jr, size_t pos, const char *key, size_t *value);
/* Iterates an array: begin, then next returns 1 per element, 0 at the end. */
int mipc_jr_array(mipc_jr_t *jr, size_t pos, size_t *it);
int mipc_jr_next(mipc_jr_t *jr, size_t *it, size_t *elem);

/* Iterates an object: begin, then next returns 1 per member (the positions of its key, a string,
 * and of its value), 0 at the end. */
int mipc_jr_members(mipc_jr_t *jr, size_t pos, size_t *it);
int mipc_jr_next_member(mipc_jr_t *jr, size_t *it, size_t *key, size_t *value);
/* A number's token (the JSON grammar): *end after it; *is_int when it has no fraction or exponent. */
int mipc_jr_number(mipc_jr_t *jr, size_t pos, size_t *end, bool *is_int);
/* A string of code points U+0000..U+00FF as bytes: *n is the count, of which at most cap are
 * stored (as the writer's mipc_jw_string writes bytes). */
int mipc_jr_bytes(mipc_jr_t *jr, size_t pos, char *out, size_t cap, size_t *n);

int mipc_jr_uint(mipc_jr_t *jr, size_t pos, uint64_t max, uint64_t *out);
int mipc_jr_sint(mipc_jr_t *jr, size_t pos, int64_t min, int64_t max, int64_t *out);
int mipc_jr_null(mipc_jr_t *jr, size_t pos);
/* A string of lowercase or uppercase hex pairs, at most cap bytes. */
int mipc_jr_hex(mipc_jr_t *jr, size_t pos, uint8_t *out, size_t cap, size_t *n);
/* True when the value at pos is a string. */
bool mipc_jr_is_string(const mipc_jr_t *jr, size_t pos);

int mipc_jr_bool(mipc_jr_t *jr, size_t pos, bool *out);
int mipc_jr_char(mipc_jr_t *jr, size_t pos, char *out);
int mipc_jr_u8(mipc_jr_t *jr, size_t pos, uint8_t *out);
int mipc_jr_u16(mipc_jr_t *jr, size_t pos, uint16_t *out);
int mipc_jr_u32(mipc_jr_t *jr, size_t pos, uint32_t *out);
int mipc_jr_u64(mipc_jr_t *jr, size_t pos, uint64_t *out);
int mipc_jr_s8(mipc_jr_t *jr, size_t pos, int8_t *out);
int mipc_jr_s16(mipc_jr_t *jr, size_t pos, int16_t *out);
int mipc_jr_s32(mipc_jr_t *jr, size_t pos, int32_t *out);
int mipc_jr_s64(mipc_jr_t *jr, size_t pos, int64_t *out);
int mipc_jr_f32(mipc_jr_t *jr, size_t pos, float *out);
int mipc_jr_f64(mipc_jr_t *jr, size_t pos, double *out);
/* A string of exactly n characters (U+0000..U+00FF), stored as bytes. */
int mipc_jr_chars(mipc_jr_t *jr, size_t pos, char *out, size_t n);

#endif
