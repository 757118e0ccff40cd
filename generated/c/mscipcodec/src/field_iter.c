/* Splits a packet payload into fields. Generated: do not edit. */
#include "mscipcodec/field_iter.h"

#include <assert.h>
#include <string.h>

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

void mscipc_field_visit_at_(uint8_t set, const uint8_t *payload, size_t len, size_t pos,
                            mscipc_field_entry_fn fn, void *ctx) {
    mscipc_field_iter_t it;
    mscipc_field_entry_t entry;
    assert(fn != NULL);
    mscipc_field_iter_init(&it, set, payload, len);
    it.pos = pos;
    if (mscipc_field_iter_next(&it, &entry)) {
        fn(ctx, &entry);
    }
}

void mscipc_layout_cache_init(mscipc_layout_cache_t *cache) {
    assert(cache != NULL);
    memset(cache, 0, sizeof *cache);
}

void mscipc_layout_cache_record_(mscipc_layout_cache_t *cache, uint8_t set, const uint8_t *payload,
                                 size_t len, const mscipc_packet_index_t *index, const size_t *other_pos,
                                 size_t others, const mscipc_layout_member_t *members, size_t member_count) {
    mscipc_layout_shape_t *shape;
    uint32_t decoded[8] = {0};
    size_t pos = 0;
    size_t n = 0; /* fields */
    size_t m = 0; /* index entries */
    size_t o = 0; /* fields passed on */
    size_t k;
    assert(cache != NULL);
    assert(index != NULL);
    assert(other_pos != NULL || others == 0);
    assert(members != NULL || member_count == 0);
    if (index->count > MSCIPC_LAYOUT_SHAPE_FIELDS || others > MSCIPC_LAYOUT_SHAPE_FIELDS || len > UINT8_MAX ||
        payload == NULL || index->count + others == 0) {
        return;
    }
    shape = &cache->shapes[cache->next];
    shape->used = 0;
    while (pos < len) {
        const uint8_t *head;
        uint8_t descriptor;
        int data_len;
        if (n == MSCIPC_LAYOUT_SHAPE_FIELDS || len - pos < MSCIPC_FIELD_HEADER_SIZE) {
            return;
        }
        head = payload + pos;
        descriptor = head[MSCIPC_FIELD_DESCRIPTOR_OFFSET];
        data_len = (int)head[MSCIPC_FIELD_LENGTH_OFFSET] - mscipc_field_length_adjust(set, descriptor);
        if (data_len < 0 || (size_t)data_len > len - pos - MSCIPC_FIELD_HEADER_SIZE) {
            return; /* trailing bytes */
        }
        shape->pos[n] = (uint8_t)pos;
        shape->head[n] = (uint16_t)(head[0] | (unsigned)head[1] << 8);
        for (k = 0; k < member_count && members[k].descriptor != descriptor; k++) {
        }
        if (o < others && other_pos[o] == pos) {
            /* passed on: only when no packet of this shape could have it decoded (no member, or a
             * repeated descriptor: decoded before in this packet) */
            if (k < member_count && (decoded[descriptor / 32u] >> (descriptor % 32u) & 1u) == 0) {
                return;
            }
            shape->other_pos[o++] = (uint8_t)pos;
        } else {
            if (m == index->count || index->fields[m].descriptor != descriptor || k == member_count ||
                index->fields[m].offset != members[k].offset) {
                return; /* not the packet the index was made from */
            }
            shape->load[m] = members[k].load;
            decoded[descriptor / 32u] |= (uint32_t)1u << (descriptor % 32u);
            shape->member_pos[m] = (uint8_t)pos;
            shape->data_len[m] = (uint8_t)data_len;
            shape->fields[m] = index->fields[m];
            m++;
        }
        n++;
        pos += MSCIPC_FIELD_HEADER_SIZE + (size_t)data_len;
    }
    if (m != index->count || o != others) {
        return;
    }
    memcpy(shape->present, index->present, sizeof shape->present);
    shape->set = set;
    shape->length = (uint8_t)len;
    shape->count = (uint8_t)n;
    shape->members = (uint8_t)m;
    shape->others = (uint8_t)o;
    shape->used = 1;
    cache->last = cache->next;
    cache->next = (uint8_t)((cache->next + 1u) % MSCIPC_LAYOUT_CACHE_SHAPES);
}

void mscipc_layout_shape_others_(const mscipc_layout_shape_t *shape, const uint8_t *payload,
                                 mscipc_field_entry_fn fn, void *ctx) {
    size_t i;
    assert(shape != NULL);
    assert(fn != NULL);
    for (i = 0; i < shape->others; i++) {
        mscipc_field_visit_at_(shape->set, payload, shape->length, shape->other_pos[i], fn, ctx);
    }
}

/* mscipc_trailing_format is in status.c, with the other messages (no stdio). */
