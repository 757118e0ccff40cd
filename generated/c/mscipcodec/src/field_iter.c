/* Splits a packet payload into fields. Generated: do not edit. */
#include "mscipcodec/field_iter.h"

#include <assert.h>

bool mscipc_field_iter_trailing_(mscipc_field_iter_t *it, mscipc_field_entry_t *entry, uint8_t length_byte,
                                 mscipc_trailing_kind_t why) {
    entry->kind = MSCIPC_ENTRY_TRAILING;
    entry->offset = it->pos;
    entry->descriptor = 0;
    entry->data = it->payload + it->pos;
    entry->length = it->len - it->pos;
    entry->trailing = why;
    entry->length_byte = length_byte;
    it->pos = it->len;
    return true;
}

/* mscipc_trailing_format is in status.c, with the other messages (no stdio). */
