/* Reserved fields (valid in every set of their kind): one struct per field layout, with its
 * encoder and decoder. Generated from the spec: do not edit. */
#ifndef DEMOC_RESERVED_H
#define DEMOC_RESERVED_H

#include "democodec/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- ack (ack): Ack */
#define DEMOC_ACK_DESCRIPTOR 0x80

/** Ack.  */
typedef struct {
    uint8_t echo; /*  */
    uint8_t code; /*  */
} democ_ack_t;

/* Largest encoded data (after the field header). */
#define DEMOC_ACK_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
democ_status_t democ_ack_encode(const democ_ack_t *value, uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on DEMOC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
democ_status_t democ_ack_decode(const uint8_t *data, size_t len, democ_ack_t *out, democ_decode_error_t *err);

#ifdef __cplusplus
}
#endif

#endif
