/* Reserved fields (valid in every set of their kind): one struct per field layout, with its
 * encoder and decoder. Generated from the spec: do not edit. */
#ifndef MIPC_RESERVED_H
#define MIPC_RESERVED_H

#include "mipcodec/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- ack_nack (ack): Ack/Nack */
#define MIPC_ACK_NACK_DESCRIPTOR 0xF1

/** Ack/Nack. Reply to every command field: echoes the command descriptor and gives an ack code. Reserved in
 * every command descriptor set. */
typedef struct {
    uint8_t command_descriptor; /* Descriptor of the command being answered. */
    mipc_ack_code_t ack_code;   /* 0 is an ACK; any other value is a NACK. */
} mipc_ack_nack_t;

/* Largest encoded data (after the field header). */
#define MIPC_ACK_NACK_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_ack_nack_encode(const mipc_ack_nack_t *value, uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_ack_nack_decode(const uint8_t *data, size_t len, mipc_ack_nack_t *out,
                                   mipc_decode_error_t *err);

#ifdef __cplusplus
}
#endif

#endif
