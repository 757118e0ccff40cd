/* Private: reader of the JSON lines the decoder prints (no allocation). Values are addressed
 * by their position in the line; objects are looked up by key, so key order does not matter.
 * Functions return 0 (or 1 = found) on success and -1 after recording a message that names the
 * JSON path of the bad value. Generated: do not edit. */
#ifndef MSCIP_JSON_READER_H
#define MSCIP_JSON_READER_H

#include "mscipcodec/status.h"

#define MSCIP_JR_MAX_DEPTH (MSCIP_PATH_MAX_DEPTH + 8)

typedef struct {
    const char *s;
    size_t len;
    char *msg;
    size_t msg_cap;
    bool failed;
    const char *path[MSCIP_JR_MAX_DEPTH];
    size_t index[MSCIP_JR_MAX_DEPTH];
    size_t depth;
} mscip_jr_t;

void mscip_jr_init(mscip_jr_t *jr, const char *s, size_t len, char *msg, size_t msg_cap);
/* Records "<path>: <message>" (only the first failure is kept); returns -1. */
int mscip_jr_fail(mscip_jr_t *jr, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
void mscip_jr_push(mscip_jr_t *jr, const char *name);
void mscip_jr_index(mscip_jr_t *jr, size_t index);
void mscip_jr_pop(mscip_jr_t *jr);

/* Position of the first non-space character at or after pos. */
size_t mscip_jr_ws(const mscip_jr_t *jr, size_t pos);
/* Checks the value at pos is well-formed JSON; *end is the position after it. */
int mscip_jr_skip(mscip_jr_t *jr, size_t pos, size_t *end);
/* The whole line is one JSON object (nothing after it). */
int mscip_jr_document(mscip_jr_t *jr, size_t *pos);
/* An object whose keys are all among keys[0..n) and appear once. */
int mscip_jr_object(mscip_jr_t *jr, size_t pos, const char *const *keys, size_t n);
/* After mscip_jr_object: 1 and the value position if key is present, else 0. */
int mscip_jr_get(mscip_jr_t *jr, size_t pos, const char *key, size_t *value);
/* Iterates an array: begin, then next returns 1 per element, 0 at the end. */
int mscip_jr_array(mscip_jr_t *jr, size_t pos, size_t *it);
int mscip_jr_next(mscip_jr_t *jr, size_t *it, size_t *elem);

int mscip_jr_uint(mscip_jr_t *jr, size_t pos, uint64_t max, uint64_t *out);
int mscip_jr_sint(mscip_jr_t *jr, size_t pos, int64_t min, int64_t max, int64_t *out);
int mscip_jr_null(mscip_jr_t *jr, size_t pos);
/* A string of lowercase or uppercase hex pairs, at most cap bytes. */
int mscip_jr_hex(mscip_jr_t *jr, size_t pos, uint8_t *out, size_t cap, size_t *n);
/* True when the value at pos is a string. */
bool mscip_jr_is_string(const mscip_jr_t *jr, size_t pos);

int mscip_jr_bool(mscip_jr_t *jr, size_t pos, bool *out);
int mscip_jr_char(mscip_jr_t *jr, size_t pos, char *out);
int mscip_jr_u8(mscip_jr_t *jr, size_t pos, uint8_t *out);
int mscip_jr_u16(mscip_jr_t *jr, size_t pos, uint16_t *out);
int mscip_jr_u32(mscip_jr_t *jr, size_t pos, uint32_t *out);
int mscip_jr_u64(mscip_jr_t *jr, size_t pos, uint64_t *out);
int mscip_jr_s8(mscip_jr_t *jr, size_t pos, int8_t *out);
int mscip_jr_s16(mscip_jr_t *jr, size_t pos, int16_t *out);
int mscip_jr_s32(mscip_jr_t *jr, size_t pos, int32_t *out);
int mscip_jr_s64(mscip_jr_t *jr, size_t pos, int64_t *out);
int mscip_jr_f32(mscip_jr_t *jr, size_t pos, float *out);
int mscip_jr_f64(mscip_jr_t *jr, size_t pos, double *out);
/* A string of exactly n characters (U+0000..U+00FF), stored as bytes. */
int mscip_jr_chars(mscip_jr_t *jr, size_t pos, char *out, size_t n);

#endif
