/* Splits a packet payload into fields. Generated: do not edit. */
#include "democodec/field_iter.h"

#include <assert.h>

bool democ_field_iter_trailing_(democ_field_iter_t *it, democ_field_entry_t *entry, uint8_t length_byte,
                                democ_trailing_kind_t why) {
    entry->kind = DEMOC_ENTRY_TRAILING;
    entry->offset = it->pos;
    entry->descriptor = 0;
    entry->data = it->payload + it->pos;
    entry->length = it->len - it->pos;
    entry->trailing = why;
    entry->length_byte = length_byte;
    it->pos = it->len;
    return true;
}

/* democ_trailing_format is in status.c, with the other messages (no stdio). */
