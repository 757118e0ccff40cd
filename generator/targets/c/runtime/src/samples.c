/* Samples: continuation packets grouped by their shared timestamp (docs/conformance.md section 6). */
#include "codec/samples.h"

#include <assert.h>
#include <string.h>

#include "codec/field_iter.h"

/* The protocol's rule (protocol.h). A protocol without data sets or timestamps still gets
 * one-element arrays (C has no empty ones); the #if blocks below leave them unused. */
static const uint8_t k_data_sets[CODEC_SAMPLE_SETS] = CODEC_SAMPLE_DATA_SETS;
#define TIMESTAMPS CODEC_SAMPLE_TIMESTAMPS
#if TIMESTAMPS > 0
static const uint8_t k_stamp_descriptor[TIMESTAMPS] = CODEC_SAMPLE_STAMP_DESCRIPTORS;
static const uint8_t k_stamp_size[TIMESTAMPS] = CODEC_SAMPLE_STAMP_SIZES;
#endif

static bool is_shared(uint8_t descriptor) {
#if CODEC_SAMPLE_FIRST_SHARED < 256
    return descriptor >= CODEC_SAMPLE_FIRST_SHARED;
#else
    (void)descriptor;
    return false;
#endif
}

static int slot_of(uint8_t set) {
#if CODEC_SAMPLE_DATA_SET_COUNT > 0
    int i;
    for (i = 0; i < CODEC_SAMPLE_SETS; i++) {
        if (k_data_sets[i] == set) {
            return i;
        }
    }
#else
    (void)set;
    (void)k_data_sets;
#endif
    return -1;
}

/* The payload of a complete packet, or NULL when the buffer does not hold one. */
static const uint8_t *payload_of(const uint8_t *packet, size_t len, size_t *plen) {
    size_t n;
    if (!packet || len < CODEC_HEADER_SIZE + CODEC_CHECKSUM_SIZE) {
        return NULL;
    }
    n = packet[CODEC_LENGTH_OFFSET];
    if (CODEC_HEADER_SIZE + n + CODEC_CHECKSUM_SIZE > len) {
        return NULL;
    }
    *plen = n;
    return packet + CODEC_HEADER_SIZE;
}

size_t codec_sample_key(const uint8_t *packet, size_t len, uint8_t *key, size_t *shared_prefix) {
    assert(packet != NULL || len == 0);
    assert(key != NULL);
    codec_field_iter_t it;
    codec_field_entry_t e;
    size_t plen = 0;
    size_t key_len = 0;
    size_t prefix = 0;
    const uint8_t *payload = payload_of(packet, len, &plen);
#if TIMESTAMPS > 0
    bool seen[TIMESTAMPS] = {false};
#endif
    if (shared_prefix) {
        *shared_prefix = 0;
    }
    if (!payload) {
        return 0;
    }
    codec_field_iter_init(&it, codec_packet_set(packet), payload, plen);
    while (codec_field_iter_next(&it, &e) && e.kind == CODEC_ENTRY_FIELD && is_shared(e.descriptor)) {
#if TIMESTAMPS > 0
        int t;
        for (t = 0; t < TIMESTAMPS; t++) {
            if (k_stamp_descriptor[t] == e.descriptor && k_stamp_size[t] == e.length && !seen[t]) {
                size_t n = CODEC_FIELD_HEADER_SIZE + e.length;
                seen[t] = true;
                if (key_len + n <= CODEC_SAMPLE_KEY_MAX) {
                    memcpy(key + key_len, payload + e.offset, n);
                    key_len += n;
                }
                break;
            }
        }
#else
        (void)key;
#endif
        prefix = e.offset + CODEC_FIELD_HEADER_SIZE + e.length;
    }
    if (shared_prefix) {
        *shared_prefix = prefix;
    }
    return key_len;
}

void codec_sample_tracker_init(codec_sample_tracker_t *tracker) {
    assert(tracker != NULL);
    memset(tracker, 0, sizeof *tracker);
}

bool codec_sample_tracker_feed(codec_sample_tracker_t *tracker, const uint8_t *packet, size_t len,
                               codec_sample_info_t *info) {
    assert(tracker != NULL);
    assert(packet != NULL || len == 0);
    assert(info != NULL);
    uint8_t key[CODEC_SAMPLE_KEY_MAX];
    size_t key_len;
    size_t prefix = 0;
    size_t plen = 0;
    codec_sample_slot_t *slot;
    int i;
    if (!payload_of(packet, len, &plen)) {
        return false;
    }
    i = slot_of(packet[CODEC_SET_OFFSET]);
    if (i < 0) {
        return false;
    }
    slot = &tracker->slots[i];
    key_len = codec_sample_key(packet, len, key, &prefix);
    info->shared_prefix = prefix;
    if (key_len > 0 && slot->used && slot->key_len == key_len && memcmp(slot->key, key, key_len) == 0) {
        info->number = slot->number;
        info->continues = true;
        return true;
    }
    slot->used = 1;
    slot->number = tracker->next++;
    slot->key_len = (uint8_t)key_len;
    memcpy(slot->key, key, key_len);
    info->number = slot->number;
    info->continues = false;
    return true;
}
