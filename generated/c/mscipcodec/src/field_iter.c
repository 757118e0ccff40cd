/* Splits a packet payload into fields. Generated: do not edit. */
#include "mscipcodec/field_iter.h"

#include <stdio.h>

void mscip_field_iter_init(mscip_field_iter_t *it, uint8_t set, const uint8_t *payload, size_t len) {
    it->set = set;
    it->payload = payload;
    it->len = payload ? len : 0;
    it->pos = 0;
}

static bool trailing(mscip_field_iter_t *it, mscip_field_entry_t *entry, mscip_trailing_kind_t why) {
    entry->kind = MSCIP_ENTRY_TRAILING;
    entry->offset = it->pos;
    entry->descriptor = 0;
    entry->data = it->payload + it->pos;
    entry->length = it->len - it->pos;
    entry->trailing = why;
    it->pos = it->len;
    return true;
}

bool mscip_field_iter_next(mscip_field_iter_t *it, mscip_field_entry_t *entry) {
    size_t left = it->len - it->pos;
    int data_len;
    size_t total;
    const uint8_t *head;
    if (left == 0) {
        return false;
    }
    entry->length_byte = 0;
    if (left < MSCIP_FIELD_HEADER_SIZE) {
        return trailing(it, entry, MSCIP_TRAILING_SHORT_HEADER);
    }
    head = it->payload + it->pos;
    entry->length_byte = head[MSCIP_FIELD_LENGTH_OFFSET];
    data_len = (int)head[MSCIP_FIELD_LENGTH_OFFSET] -
               mscip_field_length_adjust(it->set, head[MSCIP_FIELD_DESCRIPTOR_OFFSET]);
    if (data_len < 0) {
        return trailing(it, entry, MSCIP_TRAILING_SHORT_LENGTH);
    }
    total = MSCIP_FIELD_HEADER_SIZE + (size_t)data_len;
    if (total > left) {
        return trailing(it, entry, MSCIP_TRAILING_OVERRUN);
    }
    entry->kind = MSCIP_ENTRY_FIELD;
    entry->offset = it->pos;
    entry->descriptor = head[MSCIP_FIELD_DESCRIPTOR_OFFSET];
    entry->data = head + MSCIP_FIELD_HEADER_SIZE;
    entry->length = total - MSCIP_FIELD_HEADER_SIZE;
    entry->trailing = MSCIP_TRAILING_SHORT_HEADER;
    it->pos += total;
    return true;
}

size_t mscip_trailing_format(const mscip_field_entry_t *entry, char *buf, size_t cap) {
    int n;
    switch (entry->trailing) {
    case MSCIP_TRAILING_SHORT_LENGTH:
        n = snprintf(buf, cap, "field length %u at payload offset %zu is shorter than the field header",
                     (unsigned)entry->length_byte, entry->offset);
        break;
    case MSCIP_TRAILING_OVERRUN:
        n = snprintf(buf, cap, "field length %u at payload offset %zu overruns the payload (%zu bytes left)",
                     (unsigned)entry->length_byte, entry->offset, entry->length);
        break;
    case MSCIP_TRAILING_SHORT_HEADER:
    default:
        n = snprintf(buf, cap, "field header at payload offset %zu needs %d bytes, %zu left", entry->offset,
                     MSCIP_FIELD_HEADER_SIZE, entry->length);
        break;
    }
    return n < 0 ? 0 : (size_t)n;
}
