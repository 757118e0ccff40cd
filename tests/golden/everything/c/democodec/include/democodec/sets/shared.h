/* Shared data (descriptor set 0xFF): one struct per field layout, with its
 * encoder and decoder. Generated from the spec: do not edit. */
#ifndef DEMOC_SETS_SHARED_H
#define DEMOC_SETS_SHARED_H

#include "democodec/types.h"

#ifdef __cplusplus
extern "C" {
#endif

#define DEMOC_SHARED_SET 0xFF

/* ---- timestamp (data): Timestamp */
#define DEMOC_SHARED_TIMESTAMP_DESCRIPTOR 0xD3

/** Timestamp.  */
typedef struct {
    uint64_t nanoseconds; /*  */
} democ_shared_timestamp_t;

/* Largest encoded data (after the field header). */
#define DEMOC_SHARED_TIMESTAMP_MAX_SIZE 8

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
democ_status_t democ_shared_timestamp_encode(const democ_shared_timestamp_t *value, uint8_t *buf, size_t cap,
                                             size_t *len_out);
/** Decodes field data; on DEMOC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
democ_status_t democ_shared_timestamp_decode(const uint8_t *data, size_t len, democ_shared_timestamp_t *out,
                                             democ_decode_error_t *err);

#ifdef __cplusplus
}
#endif

#endif
