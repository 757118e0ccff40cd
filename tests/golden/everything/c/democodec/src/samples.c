/* Samples: continuation packets grouped by their shared timestamp (docs/conformance.md section 6).
 * Generated: do not edit. */
#include "democodec/samples.h"

#include <assert.h>
#include <string.h>

#include "democodec/field_iter.h"

/* The protocol's rule (protocol.h). A protocol without data sets or timestamps still gets
 * one-element arrays (C has no empty ones); the #if blocks below leave them unused. */
static const uint8_t k_data_sets[DEMOC_SAMPLE_SETS] = DEMOC_SAMPLE_DATA_SETS;
#define TIMESTAMPS DEMOC_SAMPLE_TIMESTAMPS
#if TIMESTAMPS > 0
static const uint8_t k_stamp_descriptor[TIMESTAMPS] = DEMOC_SAMPLE_STAMP_DESCRIPTORS;
static const uint8_t k_stamp_size[TIMESTAMPS] = DEMOC_SAMPLE_STAMP_SIZES;
#endif

static bool is_shared(uint8_t descriptor) {
#if DEMOC_SAMPLE_FIRST_SHARED < 256
    return descriptor >= DEMOC_SAMPLE_FIRST_SHARED;
#else
    (void)descriptor;
    return false;
#endif
}

static int slot_of(uint8_t set) {
#if DEMOC_SAMPLE_DATA_SET_COUNT > 0
    int i;
    for (i = 0; i < DEMOC_SAMPLE_SETS; i++) {
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
    if (!packet || len < DEMOC_HEADER_SIZE + DEMOC_CHECKSUM_SIZE) {
        return NULL;
    }
    n = packet[DEMOC_LENGTH_OFFSET];
    if (DEMOC_HEADER_SIZE + n + DEMOC_CHECKSUM_SIZE > len) {
        return NULL;
    }
    *plen = n;
    return packet + DEMOC_HEADER_SIZE;
}

size_t democ_sample_key(const uint8_t *packet, size_t len, uint8_t *key, size_t *shared_prefix) {
    assert(packet != NULL || len == 0);
    assert(key != NULL);
    democ_field_iter_t it;
    democ_field_entry_t e;
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
    democ_field_iter_init(&it, democ_packet_set(packet), payload, plen);
    while (democ_field_iter_next(&it, &e) && e.kind == DEMOC_ENTRY_FIELD && is_shared(e.descriptor)) {
#if TIMESTAMPS > 0
        int t;
        for (t = 0; t < TIMESTAMPS; t++) {
            if (k_stamp_descriptor[t] == e.descriptor && k_stamp_size[t] == e.length && !seen[t]) {
                size_t n = DEMOC_FIELD_HEADER_SIZE + e.length;
                seen[t] = true;
                if (key_len + n <= DEMOC_SAMPLE_KEY_MAX) {
                    memcpy(key + key_len, payload + e.offset, n);
                    key_len += n;
                }
                break;
            }
        }
#else
        (void)key;
#endif
        prefix = e.offset + DEMOC_FIELD_HEADER_SIZE + e.length;
    }
    if (shared_prefix) {
        *shared_prefix = prefix;
    }
    return key_len;
}

void democ_sample_tracker_init(democ_sample_tracker_t *tracker) {
    assert(tracker != NULL);
    memset(tracker, 0, sizeof *tracker);
}

bool democ_sample_tracker_feed(democ_sample_tracker_t *tracker, const uint8_t *packet, size_t len,
                               democ_sample_info_t *info) {
    assert(tracker != NULL);
    assert(packet != NULL || len == 0);
    assert(info != NULL);
    uint8_t key[DEMOC_SAMPLE_KEY_MAX];
    size_t key_len;
    size_t prefix = 0;
    size_t plen = 0;
    democ_sample_slot_t *slot;
    int i;
    if (!payload_of(packet, len, &plen)) {
        return false;
    }
    i = slot_of(packet[DEMOC_SET_OFFSET]);
    if (i < 0) {
        return false;
    }
    slot = &tracker->slots[i];
    key_len = democ_sample_key(packet, len, key, &prefix);
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
