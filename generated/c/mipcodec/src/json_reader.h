/* Private: reader of the JSON lines the decoder prints (no allocation). Values are addressed
 * by their position in the line; objects are looked up by key, so key order does not matter.
 * Functions return 0 (or 1 = found) on success and -1 after recording a message that names the
 * JSON path of the bad value. Generated: do not edit. */
#ifndef MIP_JSON_READER_H
#define MIP_JSON_READER_H

#include "mipcodec/status.h"

#define MIP_JR_MAX_DEPTH (MIP_PATH_MAX_DEPTH + 8)

typedef struct {
    const char *s;
    size_t len;
    char *msg;
    size_t msg_cap;
    bool failed;
    const char *path[MIP_JR_MAX_DEPTH];
    size_t index[MIP_JR_MAX_DEPTH];
    size_t depth;
} mip_jr_t;

void mip_jr_init(mip_jr_t *jr, const char *s, size_t len, char *msg, size_t msg_cap);
/* Records "<path>: <message>" (only the first failure is kept); returns -1. */
int mip_jr_fail(mip_jr_t *jr, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
void mip_jr_push(mip_jr_t *jr, const char *name);
void mip_jr_index(mip_jr_t *jr, size_t index);
void mip_jr_pop(mip_jr_t *jr);

/* Position of the first non-space character at or after pos. */
size_t mip_jr_ws(const mip_jr_t *jr, size_t pos);
/* Checks the value at pos is well-formed JSON; *end is the position after it. */
int mip_jr_skip(mip_jr_t *jr, size_t pos, size_t *end);
/* The whole line is one JSON object (nothing after it). */
int mip_jr_document(mip_jr_t *jr, size_t *pos);
/* An object whose keys are all among keys[0..n) and appear once. */
int mip_jr_object(mip_jr_t *jr, size_t pos, const char *const *keys, size_t n);
/* After mip_jr_object: 1 and the value position if key is present, else 0. */
int mip_jr_get(mip_jr_t *jr, size_t pos, const char *key, size_t *value);
/* Iterates an array: begin, then next returns 1 per element, 0 at the end. */
int mip_jr_array(mip_jr_t *jr, size_t pos, size_t *it);
int mip_jr_next(mip_jr_t *jr, size_t *it, size_t *elem);

int mip_jr_uint(mip_jr_t *jr, size_t pos, uint64_t max, uint64_t *out);
int mip_jr_sint(mip_jr_t *jr, size_t pos, int64_t min, int64_t max, int64_t *out);
int mip_jr_null(mip_jr_t *jr, size_t pos);
/* A string of lowercase or uppercase hex pairs, at most cap bytes. */
int mip_jr_hex(mip_jr_t *jr, size_t pos, uint8_t *out, size_t cap, size_t *n);
/* True when the value at pos is a string. */
bool mip_jr_is_string(const mip_jr_t *jr, size_t pos);

int mip_jr_bool(mip_jr_t *jr, size_t pos, bool *out);
int mip_jr_char(mip_jr_t *jr, size_t pos, char *out);
int mip_jr_u8(mip_jr_t *jr, size_t pos, uint8_t *out);
int mip_jr_u16(mip_jr_t *jr, size_t pos, uint16_t *out);
int mip_jr_u32(mip_jr_t *jr, size_t pos, uint32_t *out);
int mip_jr_u64(mip_jr_t *jr, size_t pos, uint64_t *out);
int mip_jr_s8(mip_jr_t *jr, size_t pos, int8_t *out);
int mip_jr_s16(mip_jr_t *jr, size_t pos, int16_t *out);
int mip_jr_s32(mip_jr_t *jr, size_t pos, int32_t *out);
int mip_jr_s64(mip_jr_t *jr, size_t pos, int64_t *out);
int mip_jr_f32(mip_jr_t *jr, size_t pos, float *out);
int mip_jr_f64(mip_jr_t *jr, size_t pos, double *out);
/* A string of exactly n characters (U+0000..U+00FF), stored as bytes. */
int mip_jr_chars(mip_jr_t *jr, size_t pos, char *out, size_t n);

#endif
