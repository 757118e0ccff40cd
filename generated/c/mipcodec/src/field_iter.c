/* Splits a packet payload into fields. Generated: do not edit. */
#include "mipcodec/field_iter.h"

#include <stdio.h>

bool mipc_field_iter_trailing_(mipc_field_iter_t *it, mipc_field_entry_t *entry, uint8_t length_byte,
                               mipc_trailing_kind_t why) {
    entry->kind = MIPC_ENTRY_TRAILING;
    entry->offset = it->pos;
    entry->descriptor = 0;
    entry->data = it->payload + it->pos;
    entry->length = it->len - it->pos;
    entry->trailing = why;
    entry->length_byte = length_byte;
    it->pos = it->len;
    return true;
}

size_t mipc_trailing_format(const mipc_field_entry_t *entry, char *buf, size_t cap) {
    int n;
    switch (entry->trailing) {
    case MIPC_TRAILING_SHORT_LENGTH:
        n = snprintf(buf, cap, "field length %u at payload offset %zu is shorter than the field header",
                     (unsigned)entry->length_byte, entry->offset);
        break;
    case MIPC_TRAILING_OVERRUN:
        n = snprintf(buf, cap, "field length %u at payload offset %zu overruns the payload (%zu bytes left)",
                     (unsigned)entry->length_byte, entry->offset, entry->length);
        break;
    case MIPC_TRAILING_SHORT_HEADER:
    default:
        n = snprintf(buf, cap, "field header at payload offset %zu needs %d bytes, %zu left", entry->offset,
                     MIPC_FIELD_HEADER_SIZE, entry->length);
        break;
    }
    return n < 0 ? 0 : (size_t)n;
}
