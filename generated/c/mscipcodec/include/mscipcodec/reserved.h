/* Reserved fields (valid in every set of their kind): one struct per field layout, with its
 * encoder and decoder. Generated from the spec: do not edit. */
#ifndef MSCIPC_RESERVED_H
#define MSCIPC_RESERVED_H

#include "mscipcodec/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- ack (ack): Ack */
#define MSCIPC_ACK_DESCRIPTOR 0x80

/** Ack. First field of every reply: the echoed message code of the command and an error code (0 when the
 * command was received without error). */
typedef struct {
    uint8_t command_code;           /* Message code of the command being answered ("Message echo"). */
    mscipc_error_code_t error_code; /* 0 when the command was received without error. */
} mscipc_ack_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_ACK_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_ack_encode(const mscipc_ack_t *value, uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_ack_decode(const uint8_t *data, size_t len, mscipc_ack_t *out,
                                  mscipc_decode_error_t *err);

#ifdef __cplusplus
}
#endif

#endif
