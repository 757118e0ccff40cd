/* Splits a packet payload into fields (docs/conformance.md section 2). Generated: do not edit. */
#ifndef MSCIP_FIELD_ITER_H
#define MSCIP_FIELD_ITER_H

#include "mscipcodec/framing.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
    MSCIP_ENTRY_FIELD = 1,   /* a complete field */
    MSCIP_ENTRY_TRAILING = 2 /* the rest of the payload, which is not a complete field */
} mscip_entry_kind_t;

typedef enum {
    MSCIP_TRAILING_SHORT_HEADER = 1, /* field header at payload offset {offset} needs N bytes, {left} left */
    MSCIP_TRAILING_SHORT_LENGTH =
        2, /* field length {length} at payload offset {offset} is shorter than the field header */
    MSCIP_TRAILING_OVERRUN =
        3 /* field length {length} at payload offset {offset} overruns the payload ({left} bytes left) */
} mscip_trailing_kind_t;

typedef struct {
    mscip_entry_kind_t kind;
    size_t offset;                  /* payload offset of the field header / trailing bytes */
    uint8_t descriptor;             /* fields */
    const uint8_t *data;            /* field data (after the header), or the trailing bytes */
    size_t length;                  /* bytes at data */
    mscip_trailing_kind_t trailing; /* trailing entries: why */
    uint8_t length_byte;            /* trailing entries: the field length byte as sent */
} mscip_field_entry_t;

typedef struct {
    const uint8_t *payload;
    size_t len;
    size_t pos;
    uint8_t set;
} mscip_field_iter_t;

/** Iterates the payload of a packet of descriptor set `set` (the set decides irregular field lengths). */
void mscip_field_iter_init(mscip_field_iter_t *it, uint8_t set, const uint8_t *payload, size_t len);
/** Next entry: returns true and fills *entry, or false after the last one. */
bool mscip_field_iter_next(mscip_field_iter_t *it, mscip_field_entry_t *entry);
/** Message of a trailing entry (NUL-terminated when cap > 0); returns its full length. */
size_t mscip_trailing_format(const mscip_field_entry_t *entry, char *buf, size_t cap);

#ifdef __cplusplus
}
#endif

#endif
