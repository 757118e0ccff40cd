/* Receiver 2 (descriptor set 0x92): one struct per field layout, with its
 * encoder and decoder. Generated from the spec: do not edit. */
#ifndef DEMO_SETS_RECEIVER_2_H
#define DEMO_SETS_RECEIVER_2_H

#include "democodec/types.h"

#ifdef __cplusplus
extern "C" {
#endif

#define DEMO_RECEIVER_2_SET 0x92

/* ---- llh_position (data): LLH position */
#define DEMO_RECEIVER_2_LLH_POSITION_DESCRIPTOR 0x03

/** LLH position.  */
typedef struct {
    double latitude;      /*  [deg] */
    double longitude;     /*  [deg] */
    uint16_t valid_flags; /*  */
} demo_receiver_2_llh_position_t;

/* Largest encoded data (after the field header). */
#define DEMO_RECEIVER_2_LLH_POSITION_MAX_SIZE 18

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
demo_status_t demo_receiver_2_llh_position_encode(const demo_receiver_2_llh_position_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out);
/** Decodes field data; on DEMO_ERR_DECODE, *err (if not NULL) tells what is wrong. */
demo_status_t demo_receiver_2_llh_position_decode(const uint8_t *data, size_t len,
                                                  demo_receiver_2_llh_position_t *out,
                                                  demo_decode_error_t *err);

#ifdef __cplusplus
}
#endif

#endif
