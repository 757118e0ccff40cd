/* Reserved fields (valid in every set of their kind): one struct per field layout, with its
 * encoder and decoder. Generated from the spec: do not edit. */
#ifndef MIP_RESERVED_H
#define MIP_RESERVED_H

#include "mipcodec/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- ack_nack (ack): Ack/Nack */
#define MIP_ACK_NACK_DESCRIPTOR 0xF1

/** Ack/Nack. Reply to every command field: echoes the command descriptor and gives an ack code. Reserved in
 * every command descriptor set. */
typedef struct {
    uint8_t command_descriptor; /* Descriptor of the command being answered. */
    mip_ack_code_t ack_code;    /* 0 is an ACK; any other value is a NACK. */
} mip_ack_nack_t;

/* Largest encoded data (after the field header). */
#define MIP_ACK_NACK_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_ack_nack_encode(const mip_ack_nack_t *value, uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_ack_nack_decode(const uint8_t *data, size_t len, mip_ack_nack_t *out,
                                 mip_decode_error_t *err);

#ifdef __cplusplus
}
#endif

#endif
