/* Receiver 2 (descriptor set 0x92): one struct per field layout, with its
 * encoder and decoder. Generated from the spec: do not edit. */
#ifndef DEMOC_SETS_RECEIVER_2_H
#define DEMOC_SETS_RECEIVER_2_H

#include "democodec/types.h"

#ifdef __cplusplus
extern "C" {
#endif

#define DEMOC_RECEIVER_2_SET 0x92

/* ---- llh_position (data): LLH position */
#define DEMOC_RECEIVER_2_LLH_POSITION_DESCRIPTOR 0x03

/** LLH position.  */
typedef struct {
    double latitude;      /*  [deg] */
    double longitude;     /*  [deg] */
    uint16_t valid_flags; /*  */
} democ_receiver_2_llh_position_t;

/* Largest encoded data (after the field header). */
#define DEMOC_RECEIVER_2_LLH_POSITION_MAX_SIZE 18

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
democ_status_t democ_receiver_2_llh_position_encode(const democ_receiver_2_llh_position_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on DEMOC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
democ_status_t democ_receiver_2_llh_position_decode(const uint8_t *data, size_t len,
                                                    democ_receiver_2_llh_position_t *out,
                                                    democ_decode_error_t *err);

#ifdef __cplusplus
}
#endif

#endif
