/* Splits a packet payload into fields. */
#include "codec/field_iter.h"

#include <assert.h>

bool codec_field_iter_trailing_(codec_field_iter_t *it, codec_field_entry_t *entry, uint8_t length_byte,
                                codec_trailing_kind_t why) {
    entry->kind = CODEC_ENTRY_TRAILING;
    entry->offset = it->pos;
    entry->descriptor = 0;
    entry->data = it->payload + it->pos;
    entry->length = it->len - it->pos;
    entry->trailing = why;
    entry->length_byte = length_byte;
    it->pos = it->len;
    return true;
}

void codec_field_visit_at_(uint8_t set, const uint8_t *payload, size_t len, size_t pos,
                           codec_field_entry_fn fn, void *ctx) {
    codec_field_iter_t it;
    codec_field_entry_t entry;
    assert(fn != NULL);
    codec_field_iter_init(&it, set, payload, len);
    it.pos = pos;
    if (codec_field_iter_next(&it, &entry)) {
        fn(ctx, &entry);
    }
}

/* codec_trailing_format is in status.c, with the other messages (no stdio). */
