/* Status codes and decode errors of the library. */
/*
 * Pointer arguments (every function of this header): a pointer must be valid for what the function
 * reads or writes, and not NULL, unless its documentation says "may be NULL". A buffer pointer
 * paired with a size (bytes/len, buf/cap, out/cap) may be NULL when that size is 0. Debug builds
 * (without NDEBUG) check these preconditions with assert(); docs/conformance.md section 7.
 */
#ifndef CODEC_STATUS_H
#define CODEC_STATUS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "codec/protocol.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Result of every encode/decode/dispatch call. */
typedef enum {
    CODEC_OK = 0,
    CODEC_ERR_DECODE = 1,      /* field data does not match the layout (see codec_decode_error_t) */
    CODEC_ERR_BUFFER = 2,      /* the output buffer is too small */
    CODEC_ERR_INVALID = 3,     /* the value cannot be encoded (count above maximum, absent optional, ...) */
    CODEC_ERR_UNKNOWN_SET = 4, /* "unknown descriptor set" */
    CODEC_ERR_UNKNOWN_DESCRIPTOR = 5, /* "unknown descriptor" */
    CODEC_ERR_TOO_LONG = 6,           /* a field or payload exceeds the framing limits */
    CODEC_ERR_JSON = 7                /* a JSON line is malformed or names unknown things */
} codec_status_t;

/** Short English text of a status code. */
const char *codec_status_text(codec_status_t status);

/** One step of a parameter path: a name, and an element index when index != SIZE_MAX. */
typedef struct {
    const char *name;
    size_t index;
} codec_path_segment_t;

/** Which of the messages of docs/conformance.md section 3 a decode error is. */
typedef enum {
    CODEC_DECODE_NONE = 0,
    CODEC_DECODE_NEEDS_BYTES, /* {path}: needs {need} bytes at offset {offset}, {have} left */
    CODEC_DECODE_COUNT,       /* {path}: count {count} exceeds maximum {max} */
    CODEC_DECODE_REMAINING,   /* {path}: {have} bytes left at offset {offset}, not a multiple of {need} */
    CODEC_DECODE_BOOL,        /* {path}: invalid bool value {value} at offset {offset} */
    CODEC_DECODE_SELECTOR,    /* {path}: no member for selector value {value} */
    CODEC_DECODE_UNEXPECTED   /* {have} unexpected bytes at offset {offset} */
} codec_decode_error_kind_t;

/** Everything needed to print the exact message of a decode error. */
typedef struct {
    codec_decode_error_kind_t kind;
    codec_path_segment_t path[CODEC_PATH_MAX_DEPTH];
    size_t depth;      /* number of path segments */
    size_t offset;     /* offset within the field data */
    size_t need;       /* bytes the value needs / element size */
    size_t have;       /* bytes left */
    uint64_t count;    /* count that exceeds the maximum */
    uint64_t max;      /* maximum element count */
    uint64_t value;    /* invalid bool / selector value (two's complement when value_signed) */
    bool value_signed; /* value is an int64_t */
} codec_decode_error_t;

/**
 * Writes the message of a decode error into buf (always NUL-terminated when cap > 0).
 * Returns the length the full message has (like snprintf).
 */
size_t codec_decode_error_format(const codec_decode_error_t *err, char *buf, size_t cap);

#ifdef __cplusplus
}
#endif

#endif
