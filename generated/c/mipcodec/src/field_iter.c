/* Splits a packet payload into fields. Generated: do not edit. */
#include "mipcodec/field_iter.h"

#include <assert.h>
#include <string.h>

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

void mipc_field_visit_at_(uint8_t set, const uint8_t *payload, size_t len, size_t pos, mipc_field_entry_fn fn,
                          void *ctx) {
    mipc_field_iter_t it;
    mipc_field_entry_t entry;
    assert(fn != NULL);
    mipc_field_iter_init(&it, set, payload, len);
    it.pos = pos;
    if (mipc_field_iter_next(&it, &entry)) {
        fn(ctx, &entry);
    }
}

void mipc_layout_cache_init(mipc_layout_cache_t *cache) {
    assert(cache != NULL);
    memset(cache, 0, sizeof *cache);
}

void mipc_layout_cache_record_(mipc_layout_cache_t *cache, uint8_t set, const uint8_t *payload, size_t len,
                               const mipc_packet_index_t *index, mipc_layout_decode_fn decode) {
    mipc_layout_shape_t *shape;
    size_t pos = 0;
    size_t i;
    assert(cache != NULL);
    assert(index != NULL);
    assert(decode != NULL);
    if (index->count == 0 || index->count > MIPC_LAYOUT_SHAPE_FIELDS || len > UINT8_MAX || payload == NULL) {
        return;
    }
    shape = &cache->shapes[cache->next];
    shape->used = 0;
    for (i = 0; i < index->count; i++) {
        const uint8_t *head;
        int data_len;
        if (len - pos < MIPC_FIELD_HEADER_SIZE) {
            return;
        }
        head = payload + pos;
        data_len = (int)head[MIPC_FIELD_LENGTH_OFFSET] -
                   mipc_field_length_adjust(set, head[MIPC_FIELD_DESCRIPTOR_OFFSET]);
        if (data_len < 0 || (size_t)data_len > len - pos - MIPC_FIELD_HEADER_SIZE ||
            head[MIPC_FIELD_DESCRIPTOR_OFFSET] != index->fields[i].descriptor) {
            return; /* not the packet the index was made from */
        }
        shape->pos[i] = (uint8_t)pos;
        shape->data_len[i] = (uint8_t)data_len;
        shape->head[i] = (uint16_t)(head[0] | (unsigned)head[1] << 8);
        shape->fields[i] = index->fields[i];
        pos += MIPC_FIELD_HEADER_SIZE + (size_t)data_len;
    }
    if (pos != len) {
        return;
    }
    memcpy(shape->present, index->present, sizeof shape->present);
    shape->decode = decode;
    shape->set = set;
    shape->length = (uint8_t)len;
    shape->count = (uint8_t)index->count;
    shape->used = 1;
    cache->last = cache->next;
    cache->next = (uint8_t)((cache->next + 1u) % MIPC_LAYOUT_CACHE_SHAPES);
}

/* mipc_trailing_format is in status.c, with the other messages (no stdio). */
