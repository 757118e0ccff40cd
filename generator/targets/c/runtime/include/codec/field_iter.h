/* Splits a packet payload into fields (docs/conformance.md section 2). */
/*
 * Pointer arguments (every function of this header): a pointer must be valid for what the function
 * reads or writes, and not NULL, unless its documentation says "may be NULL". A buffer pointer
 * paired with a size (bytes/len, buf/cap, out/cap) may be NULL when that size is 0. Debug builds
 * (without NDEBUG) check these preconditions with assert(); docs/conformance.md section 7.
 */
#ifndef CODEC_FIELD_ITER_H
#define CODEC_FIELD_ITER_H

#include "codec/framing.h"

#include <assert.h>
#include <string.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
    CODEC_ENTRY_FIELD = 1,   /* a complete field */
    CODEC_ENTRY_TRAILING = 2 /* the rest of the payload, which is not a complete field */
} codec_entry_kind_t;

typedef enum {
    CODEC_TRAILING_SHORT_HEADER = 1, /* field header at payload offset {offset} needs N bytes, {left} left */
    CODEC_TRAILING_SHORT_LENGTH =
        2, /* field length {length} at payload offset {offset} is shorter than the field header */
    CODEC_TRAILING_OVERRUN =
        3 /* field length {length} at payload offset {offset} overruns the payload ({left} bytes left) */
} codec_trailing_kind_t;

typedef struct {
    codec_entry_kind_t kind;
    size_t offset;                  /* payload offset of the field header / trailing bytes */
    uint8_t descriptor;             /* fields */
    const uint8_t *data;            /* field data (after the header), or the trailing bytes */
    size_t length;                  /* bytes at data */
    codec_trailing_kind_t trailing; /* trailing entries: why */
    uint8_t length_byte;            /* trailing entries: the field length byte as sent */
} codec_field_entry_t;

typedef struct {
    const uint8_t *payload;
    size_t len;
    size_t pos;
    uint8_t set;
} codec_field_iter_t;

/* Private: the trailing entry of codec_field_iter_next (out of line: it is rare). */
bool codec_field_iter_trailing_(codec_field_iter_t *it, codec_field_entry_t *entry, uint8_t length_byte,
                                codec_trailing_kind_t why);

/* init and next are inline: a decode loop calls next for every field, and inline the iterator
 * and the entry stay in registers. */
/** Iterates the payload of a packet of descriptor set `set` (the set decides irregular field lengths).
 * `payload` may be NULL (an empty payload, whatever len says). */
static inline void codec_field_iter_init(codec_field_iter_t *it, uint8_t set, const uint8_t *payload,
                                         size_t len) {
    assert(it != NULL);
    it->set = set;
    it->payload = payload;
    it->len = payload ? len : 0;
    it->pos = 0;
}

/** Next entry: returns true and fills *entry, or false after the last one. */
static inline bool codec_field_iter_next(codec_field_iter_t *it, codec_field_entry_t *entry) {
    size_t left;
    int data_len;
    size_t total;
    assert(it != NULL);
    assert(entry != NULL);
    left = it->len - it->pos;
    const uint8_t *head;
    if (left == 0) {
        return false;
    }
    if (left < CODEC_FIELD_HEADER_SIZE) {
        return codec_field_iter_trailing_(it, entry, 0, CODEC_TRAILING_SHORT_HEADER);
    }
    head = it->payload + it->pos;
    data_len = (int)head[CODEC_FIELD_LENGTH_OFFSET] -
               codec_field_length_adjust(it->set, head[CODEC_FIELD_DESCRIPTOR_OFFSET]);
    if (data_len < 0) {
        return codec_field_iter_trailing_(it, entry, head[CODEC_FIELD_LENGTH_OFFSET],
                                          CODEC_TRAILING_SHORT_LENGTH);
    }
    total = CODEC_FIELD_HEADER_SIZE + (size_t)data_len;
    if (total > left) {
        return codec_field_iter_trailing_(it, entry, head[CODEC_FIELD_LENGTH_OFFSET], CODEC_TRAILING_OVERRUN);
    }
    entry->kind = CODEC_ENTRY_FIELD;
    entry->offset = it->pos;
    entry->descriptor = head[CODEC_FIELD_DESCRIPTOR_OFFSET];
    entry->data = head + CODEC_FIELD_HEADER_SIZE;
    entry->length = (size_t)data_len;
    entry->trailing = CODEC_TRAILING_SHORT_HEADER;
    entry->length_byte = head[CODEC_FIELD_LENGTH_OFFSET];
    it->pos += total;
    return true;
}

/** An entry a straight-line packet decoder (<set>_decode_packet, issue 38) leaves to the general
 * path: called with ctx (may be NULL) and the entry, valid during the call. */
typedef void (*codec_field_entry_fn)(void *ctx, const codec_field_entry_t *entry);

/* Private (the straight-line packet decoders): passes the entry at payload offset pos, and for
 * trailing bytes the one entry they make, to fn (out of line: rare). */
void codec_field_visit_at_(uint8_t set, const uint8_t *payload, size_t len, size_t pos,
                           codec_field_entry_fn fn, void *ctx);

/** Most fields a packet can hold (each has at least a field header). */
#define CODEC_PACKET_FIELDS_MAX (CODEC_MAX_PAYLOAD / CODEC_FIELD_HEADER_SIZE)

/** A field a straight-line packet decoder decoded: its descriptor and where its typed struct is
 * (the member's offset from the start of the packet struct, whose first member is the index). */
typedef struct {
    uint8_t descriptor;
    uint32_t offset;
} codec_decoded_field_t;

/** What a straight-line packet decoder decoded, the first member of every <set>_packet_t: the
 * fields decoded into their members, in packet order, and a bit per descriptor. */
typedef struct {
    uint32_t present[8]; /* bit d % 32 of present[d / 32]: descriptor d is in its member */
    size_t count;        /* entries of fields */
    codec_decoded_field_t fields[CODEC_PACKET_FIELDS_MAX];
} codec_packet_index_t;

/** True when the packet's field with this descriptor was decoded into its member. */
static inline bool codec_packet_has(const codec_packet_index_t *index, uint8_t descriptor) {
    assert(index != NULL);
    return (index->present[descriptor / 32u] >> (descriptor % 32u) & 1u) != 0;
}

/** The typed struct of the i-th decoded field (i < index->count): the member of the packet
 * struct that starts with *index, of the type of the set's field index->fields[i].descriptor. */
static inline const void *codec_packet_value(const codec_packet_index_t *index, size_t i) {
    assert(index != NULL);
    assert(i < index->count);
    return (const uint8_t *)index + index->fields[i].offset;
}

/* ---- the layout cache (issue 38): packet shapes seen before, decoded without the header walk */

/** Shapes a layout cache holds (replaced round-robin) and most fields a cached shape has (a
 * packet with more is decoded by the straight-line decoder every time). */
#define CODEC_LAYOUT_CACHE_SHAPES 4
#define CODEC_LAYOUT_SHAPE_FIELDS 16

/* Private: decodes a field's data (length bytes at d) into its member of a set's packet struct
 * (packet: a <set>_packet_t) as the set's straight-line decoder does; 0 when it does not decode. */
typedef int (*codec_layout_load_fn)(const uint8_t *d, size_t length, void *packet);

/* Private: a member of a set's packet struct (generated tables <set>_layout_members_). */
typedef struct {
    uint8_t descriptor;
    uint32_t offset; /* offsetof the packet struct */
    codec_layout_load_fn load;
} codec_layout_member_t;

/** A packet shape: (set, payload length, every field header at its offset), recorded from a
 * packet the straight-line decoder decoded without trailing bytes, with the index it made and the
 * fields it passed to `other` because of their place in the shape (a descriptor without a member,
 * a repeated descriptor). Private. */
typedef struct {
    uint8_t used;                                            /* 0: an empty slot */
    uint8_t set;                                             /* descriptor set */
    uint8_t length;                                          /* payload length */
    uint8_t count;                                           /* fields (headers compared) */
    uint8_t members;                                         /* of them decoded into members */
    uint8_t others;                                          /* of them passed to other */
    uint8_t pos[CODEC_LAYOUT_SHAPE_FIELDS];                  /* payload offset of each field header */
    uint16_t head[CODEC_LAYOUT_SHAPE_FIELDS];                /* its two header bytes, first | second << 8 */
    codec_layout_load_fn load[CODEC_LAYOUT_SHAPE_FIELDS];    /* each decoded field's loader */
    uint8_t member_pos[CODEC_LAYOUT_SHAPE_FIELDS];           /* its payload offset */
    uint8_t data_len[CODEC_LAYOUT_SHAPE_FIELDS];             /* its data length */
    codec_decoded_field_t fields[CODEC_LAYOUT_SHAPE_FIELDS]; /* its index entry */
    uint8_t other_pos[CODEC_LAYOUT_SHAPE_FIELDS];            /* payload offset of each field passed on */
    uint32_t present[8];                                     /* the index's present bits */
} codec_layout_shape_t;

/** The layout cache of codec_decode_packet_cached: fixed arrays (no allocation), one per stream
 * (not shared between threads without a lock). Initialise with codec_layout_cache_init. */
typedef struct {
    codec_layout_shape_t shapes[CODEC_LAYOUT_CACHE_SHAPES];
    uint8_t next; /* the slot the next recorded shape replaces */
    uint8_t last; /* the slot of the last hit, tried first */
} codec_layout_cache_t;

/** Empties a layout cache. */
void codec_layout_cache_init(codec_layout_cache_t *cache);

/* Private (codec_decode_packet_cached): true when the packet (set, payload of len bytes) has this
 * shape. Compares the set, the length and each field header; reads only bytes below len (a
 * shape's headers lie inside its length). */
static inline bool codec_layout_shape_matches_(const codec_layout_shape_t *shape, uint8_t set,
                                               const uint8_t *payload, size_t len) {
    unsigned i;
    if (!shape->used || shape->set != set || shape->length != len) {
        return false;
    }
    for (i = 0; i < shape->count; i++) {
        const uint8_t *head = payload + shape->pos[i];
        if ((uint16_t)(head[0] | (unsigned)head[1] << 8) != shape->head[i]) {
            return false;
        }
    }
    return true;
}

/* Private (codec_decode_packet_cached): decodes the payload of a packet of the shape into its set's
 * packet struct (packet: the <set>_packet_t, which starts with its index) with the members'
 * loaders; 0 when a field does not decode (the straight-line decoder then takes the packet). */
static inline int codec_layout_shape_decode_(const codec_layout_shape_t *shape, const uint8_t *payload,
                                             codec_packet_index_t *packet) {
    unsigned i;
    for (i = 0; i < shape->members; i++) {
        if (!shape->load[i](payload + shape->member_pos[i] + CODEC_FIELD_HEADER_SIZE, shape->data_len[i],
                            packet)) {
            return 0;
        }
        packet->fields[i] = shape->fields[i];
    }
    memcpy(packet->present, shape->present, sizeof packet->present);
    packet->count = shape->members;
    return 1;
}

/* Private: the cached shape of this packet, or NULL (the slot found becomes the one tried first). */
static inline const codec_layout_shape_t *codec_layout_cache_find_(codec_layout_cache_t *cache, uint8_t set,
                                                                   const uint8_t *payload, size_t len) {
    unsigned k;
    for (k = 0; k < CODEC_LAYOUT_CACHE_SHAPES; k++) {
        const unsigned slot = (cache->last + k) % CODEC_LAYOUT_CACHE_SHAPES;
        if (codec_layout_shape_matches_(&cache->shapes[slot], set, payload, len)) {
            cache->last = (uint8_t)slot;
            return &cache->shapes[slot];
        }
    }
    return NULL;
}

/* Private (codec_decode_packet_cached): records the shape of a packet (set, payload of len bytes)
 * that the straight-line decoder decoded into index, passing the fields at payload offsets
 * other_pos[0..others) to other (no trailing bytes); members: the member_count members of the set's
 * packet struct (the generated <set>_layout_members_).
 * Does nothing when the packet does not fit a shape, or when a field passed on could be decoded
 * into a member by another packet of the same shape (its data did not decode). */
void codec_layout_cache_record_(codec_layout_cache_t *cache, uint8_t set, const uint8_t *payload, size_t len,
                                const codec_packet_index_t *index, const size_t *other_pos, size_t others,
                                const codec_layout_member_t *members, size_t member_count);

/* Private (codec_decode_packet_cached): passes the fields a shape passes on to fn, in order. */
void codec_layout_shape_others_(const codec_layout_shape_t *shape, const uint8_t *payload,
                                codec_field_entry_fn fn, void *ctx);

/** Message of a trailing entry (NUL-terminated when cap > 0); returns its full length. */
size_t codec_trailing_format(const codec_field_entry_t *entry, char *buf, size_t cap);

#ifdef __cplusplus
}
#endif

#endif
