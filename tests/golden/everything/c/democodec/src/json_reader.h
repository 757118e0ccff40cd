/* Private: reader of the JSON lines the decoder prints (no allocation). Values are addressed
 * by their position in the line; objects are looked up by key, so key order does not matter.
 * Functions return 0 (or 1 = found) on success and -1 after recording a message that names the
 * JSON path of the bad value. Generated: do not edit. */
#ifndef DEMOC_JSON_READER_H
#define DEMOC_JSON_READER_H

#include "democodec/status.h"

#define DEMOC_JR_MAX_DEPTH (DEMOC_PATH_MAX_DEPTH + 8)

typedef struct {
    const char *s;
    size_t len;
    char *msg;
    size_t msg_cap;
    bool failed;
    const char *path[DEMOC_JR_MAX_DEPTH];
    size_t index[DEMOC_JR_MAX_DEPTH];
    size_t depth;
} democ_jr_t;

void democ_jr_init(democ_jr_t *jr, const char *s, size_t len, char *msg, size_t msg_cap);
/* Records "<path>: <message>" (only the first failure is kept); returns -1. */
int democ_jr_fail(democ_jr_t *jr, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
void democ_jr_push(democ_jr_t *jr, const char *name);
void democ_jr_index(democ_jr_t *jr, size_t index);
void democ_jr_pop(democ_jr_t *jr);

/* Position of the first non-space character at or after pos. */
size_t democ_jr_ws(const democ_jr_t *jr, size_t pos);
/* Checks the value at pos is well-formed JSON; *end is the position after it. */
int democ_jr_skip(democ_jr_t *jr, size_t pos, size_t *end);
/* The whole line is one JSON object (nothing after it). */
int democ_jr_document(democ_jr_t *jr, size_t *pos);
/* An object whose keys are all among keys[0..n) and appear once. */
int democ_jr_object(democ_jr_t *jr, size_t pos, const char *const *keys, size_t n);
/* After democ_jr_object: 1 and the value position if key is present, else 0. */
int democ_jr_get(democ_jr_t *jr, size_t pos, const char *key, size_t *value);
/* Iterates an array: begin, then next returns 1 per element, 0 at the end. */
int democ_jr_array(democ_jr_t *jr, size_t pos, size_t *it);
int democ_jr_next(democ_jr_t *jr, size_t *it, size_t *elem);

int democ_jr_uint(democ_jr_t *jr, size_t pos, uint64_t max, uint64_t *out);
int democ_jr_sint(democ_jr_t *jr, size_t pos, int64_t min, int64_t max, int64_t *out);
int democ_jr_null(democ_jr_t *jr, size_t pos);
/* A string of lowercase or uppercase hex pairs, at most cap bytes. */
int democ_jr_hex(democ_jr_t *jr, size_t pos, uint8_t *out, size_t cap, size_t *n);
/* True when the value at pos is a string. */
bool democ_jr_is_string(const democ_jr_t *jr, size_t pos);

int democ_jr_bool(democ_jr_t *jr, size_t pos, bool *out);
int democ_jr_char(democ_jr_t *jr, size_t pos, char *out);
int democ_jr_u8(democ_jr_t *jr, size_t pos, uint8_t *out);
int democ_jr_u16(democ_jr_t *jr, size_t pos, uint16_t *out);
int democ_jr_u32(democ_jr_t *jr, size_t pos, uint32_t *out);
int democ_jr_u64(democ_jr_t *jr, size_t pos, uint64_t *out);
int democ_jr_s8(democ_jr_t *jr, size_t pos, int8_t *out);
int democ_jr_s16(democ_jr_t *jr, size_t pos, int16_t *out);
int democ_jr_s32(democ_jr_t *jr, size_t pos, int32_t *out);
int democ_jr_s64(democ_jr_t *jr, size_t pos, int64_t *out);
int democ_jr_f32(democ_jr_t *jr, size_t pos, float *out);
int democ_jr_f64(democ_jr_t *jr, size_t pos, double *out);
/* A string of exactly n characters (U+0000..U+00FF), stored as bytes. */
int democ_jr_chars(democ_jr_t *jr, size_t pos, char *out, size_t n);

#endif
