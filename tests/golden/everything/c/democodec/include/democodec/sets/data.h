/* Data (descriptor set 0x90): one struct per field layout, with its
 * encoder and decoder. Generated from the spec: do not edit. */
#ifndef DEMOC_SETS_DATA_H
#define DEMOC_SETS_DATA_H

#include "democodec/types.h"

#ifdef __cplusplus
extern "C" {
#endif

#define DEMOC_DATA_SET 0x90

/* ---- sample (data): Sample */
#define DEMOC_DATA_SAMPLE_DESCRIPTOR 0x01

/** Sample.  */
typedef struct {
    float quat[4]; /*  */
    uint64_t big;  /*  */
    int8_t small;  /*  */
    float f;       /*  */
} democ_data_sample_t;

/* Largest encoded data (after the field header). */
#define DEMOC_DATA_SAMPLE_MAX_SIZE 29

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
democ_status_t democ_data_sample_encode(const democ_data_sample_t *value, uint8_t *buf, size_t cap,
                                        size_t *len_out);
/** Decodes field data; on DEMOC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
democ_status_t democ_data_sample_decode(const uint8_t *data, size_t len, democ_data_sample_t *out,
                                        democ_decode_error_t *err);

#ifdef __cplusplus
}
#endif

#endif
