/* Shared data (descriptor set 0xFF): one struct per field layout, with its
 * encoder and decoder. Generated from the spec: do not edit. */
#ifndef DEMO_SETS_SHARED_H
#define DEMO_SETS_SHARED_H

#include "democodec/types.h"

#ifdef __cplusplus
extern "C" {
#endif

#define DEMO_SHARED_SET 0xFF

/* ---- timestamp (data): Timestamp */
#define DEMO_SHARED_TIMESTAMP_DESCRIPTOR 0xD3

/** Timestamp.  */
typedef struct {
    uint64_t nanoseconds; /*  */
} demo_shared_timestamp_t;

/* Largest encoded data (after the field header). */
#define DEMO_SHARED_TIMESTAMP_MAX_SIZE 8

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
demo_status_t demo_shared_timestamp_encode(const demo_shared_timestamp_t *value, uint8_t *buf, size_t cap,
                                           size_t *len_out);
/** Decodes field data; on DEMO_ERR_DECODE, *err (if not NULL) tells what is wrong. */
demo_status_t demo_shared_timestamp_decode(const uint8_t *data, size_t len, demo_shared_timestamp_t *out,
                                           demo_decode_error_t *err);

#ifdef __cplusplus
}
#endif

#endif
