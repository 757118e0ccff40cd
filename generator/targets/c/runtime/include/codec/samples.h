/* Samples: continuation packets grouped by their shared timestamp (docs/conformance.md section 6). */
/*
 * Pointer arguments (every function of this header): a pointer must be valid for what the function
 * reads or writes, and not NULL, unless its documentation says "may be NULL". A buffer pointer
 * paired with a size (bytes/len, buf/cap, out/cap) may be NULL when that size is 0. Debug builds
 * (without NDEBUG) check these preconditions with assert(); docs/conformance.md section 7.
 */
#ifndef CODEC_SAMPLES_H
#define CODEC_SAMPLES_H

#include "codec/framing.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    uint64_t number; /* sample number of the last packet of this set */
    uint8_t key_len; /* 0: that packet had no key */
    uint8_t used;    /* a packet of this set was seen */
    uint8_t key[CODEC_SAMPLE_KEY_MAX];
} codec_sample_slot_t;

/** Fixed-size state (no allocation): the key and sample number of the last packet of each set. */
typedef struct {
    codec_sample_slot_t slots[CODEC_SAMPLE_SETS];
    uint64_t next; /* number of the next new sample */
} codec_sample_tracker_t;

typedef struct {
    uint64_t number;      /* the sample the packet belongs to (numbered from 0 in stream order) */
    bool continues;       /* true: a continuation of an earlier packet's sample */
    size_t shared_prefix; /* payload bytes of the leading shared run (copies, in a continuation) */
} codec_sample_info_t;

void codec_sample_tracker_init(codec_sample_tracker_t *tracker);
/**
 * Places one complete packet (as delivered by the parser). Returns true and fills *info for a
 * packet of a data set; false for other packets (command sets, unknown sets, a malformed buffer).
 */
bool codec_sample_tracker_feed(codec_sample_tracker_t *tracker, const uint8_t *packet, size_t len,
                               codec_sample_info_t *info);
/**
 * The key of a complete packet into key[CODEC_SAMPLE_KEY_MAX]; returns its length (0: no key).
 * *shared_prefix (if not NULL) receives the payload bytes of the leading shared run.
 */
size_t codec_sample_key(const uint8_t *packet, size_t len, uint8_t *key, size_t *shared_prefix);

#ifdef __cplusplus
}
#endif

#endif
