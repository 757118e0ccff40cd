/* Fuzz target `decode` (C): the lean companion of `parser`, built for execution count.
 *
 * Same input format as `parser` (byte 0 a control byte, device in its top 2 bits; the rest the
 * byte stream), and the same invariants on what it checks, minus the expensive extras (chunked
 * re-parse, JSON lines, every device, sample tracker). Per input:
 *  - the stream goes through the parser once; the events tile the stream (contiguous offsets
 *    from 0, lengths summing to its length, no two skip runs in a row, packet bytes equal the
 *    stream's bytes, every packet valid);
 *  - every packet's fields are walked and every complete field is decoded through the public
 *    dispatch with the control byte's device; a field that decodes re-encodes to exactly its
 *    bytes and is refused by a buffer one byte short; a decode error formats a message;
 *  - the stream's first byte and the following bytes are wrapped as (set, payload) into a valid
 *    packet, so every decoder is reached without the fuzzer solving checksums.
 * No allocation: buffers are on the stack, sized by the maximum packet. */
#include "fuzz_common.h"

#define HEADER FZU(HEADER_SIZE)
#define CHECKSUM FZU(CHECKSUM_SIZE)
#define MAX_PACKET FZU(MAX_PACKET)
#define MAX_PAYLOAD FZU(MAX_PAYLOAD)

typedef struct {
    const uint8_t *stream;
    size_t size;
    uint64_t end;  /* where the next event must start */
    int last_skip; /* the previous event was a skip run */
    size_t packets;
    FZ(device_t) device;
} fz_lean_t;

static void decode_one(uint8_t set, uint8_t descriptor, const uint8_t *data, size_t len,
                       FZ(device_t) device) {
    FZ(field_value_t) value;
    FZ(decode_error_t) err;
    uint8_t buf[MAX_PAYLOAD];
    size_t n = 0;
    FZ(status_t) st;
    memset(&err, 0, sizeof err);
    st = FZ(decode_field)(set, descriptor, data, len, device, &value, &err);
    if (st == FZU(OK)) {
        st = FZ(encode_field)(&value, buf, len, &n);
        FZ_CHECK(st == FZU(OK) && n == len && memcmp(buf, data, len) == 0,
                 "set %u descriptor %u: re-encode gives status %d, %zu bytes for data %s", set, descriptor,
                 (int)st, n, fz_hex(data, len));
        if (len > 0) {
            FZ_CHECK(FZ(encode_field)(&value, buf, len - 1, &n) != FZU(OK), "encoded %zu bytes into %zu", len,
                     len - 1);
        }
    } else if (st == FZU(ERR_DECODE)) {
        char msg[FZU(ERROR_MESSAGE_MAX)];
        size_t full = FZ(decode_error_format)(&err, msg, sizeof msg);
        FZ_CHECK(full > 0 && full < sizeof msg && strlen(msg) == full, "error message length %zu", full);
    } else {
        FZ_CHECK(st == FZU(ERR_UNKNOWN_SET) || st == FZU(ERR_UNKNOWN_DESCRIPTOR), "decode status %d",
                 (int)st);
    }
}

/* The straight-line decoder's entries left to the general path: they follow each other in
 * payload order. */
typedef struct {
    size_t count;
    size_t last; /* payload offset of the last one + 1 (0: none yet) */
} fz_other_t;

static void count_other(void *arg, const FZ(field_entry_t) * e) {
    fz_other_t *o = (fz_other_t *)arg;
    FZ_CHECK(e->offset + 1 > o->last, "entries to other out of order (%zu after %zu)", e->offset, o->last);
    o->last = e->offset + 1;
    o->count++;
}

/* The layout cache of one input (emptied by LLVMFuzzerTestOneInput: an input replays alone). */
static FZ(layout_cache_t) g_cache;

/* The encoding of the i-th member of a packet index (the field's only layout); 0 if none. */
static size_t member_encoding(uint8_t set, const FZ(packet_index_t) * index, size_t i,
                              const FZ(packet_t) * whole, uint8_t *buf) {
    static FZ(field_value_t) value;
    const FZ(field_info_t) *info = FZ(find_field)(set, index->fields[i].descriptor, NULL);
    const uint8_t *member = (const uint8_t *)FZ(packet_value)(index, i);
    size_t room = (size_t)((const uint8_t *)(whole + 1) - member);
    size_t n = 0;
    if (info == NULL || info->layout_count != 1) {
        return 0;
    }
    memset(&value, 0, sizeof value);
    value.id = info->first_layout;
    memcpy(&value.u, member, room < sizeof value.u ? room : sizeof value.u);
    return FZ(encode_field)(&value, buf, MAX_PAYLOAD, &n) == FZU(OK) ? n : 0;
}

/* The layout cache (issue 38) against the straight-line decoder, twice through the cache (the
 * second by the packet's shape when the first recorded it): the same index and other entries,
 * members that encode to the same bytes. */
static void check_cached(const uint8_t *packet, const FZ(packet_index_t) * index,
                         const FZ(packet_t) * straight, const fz_other_t *other) {
    static FZ(packet_t) via;
    uint8_t want[MAX_PAYLOAD];
    uint8_t got[MAX_PAYLOAD];
    const uint8_t set = FZ(packet_set)(packet);
    int pass;
    for (pass = 0; pass < 2; pass++) {
        fz_other_t left = {0, 0};
        const FZ(packet_index_t) *ci = FZ(decode_packet_cached)(&g_cache, packet, &via, count_other, &left);
        size_t i;
        FZ_CHECK((ci == NULL) == (index == NULL) && left.count == other->count && left.last == other->last,
                 "cached decode %d: %zu entries to other, straight-line %zu", pass, left.count, other->count);
        if (index == NULL) {
            continue;
        }
        FZ_CHECK(ci->count == index->count && memcmp(ci->present, index->present, sizeof ci->present) == 0,
                 "cached decode %d: %zu fields, straight-line %zu", pass, ci->count, index->count);
        for (i = 0; i < index->count; i++) {
            size_t n = member_encoding(set, index, i, straight, want);
            FZ_CHECK(ci->fields[i].descriptor == index->fields[i].descriptor &&
                         ci->fields[i].offset == index->fields[i].offset &&
                         member_encoding(set, ci, i, &via, got) == n && memcmp(got, want, n) == 0,
                     "cached decode %d: set %u descriptor %u differs", pass, set,
                     index->fields[i].descriptor);
        }
    }
}

static void walk(const uint8_t *packet, size_t len, FZ(device_t) device) {
    static FZ(packet_t) straight;
    fz_other_t other = {0, 0};
    const FZ(packet_index_t) * index;
    size_t entries = 0;
    FZ(field_iter_t) it;
    FZ(field_entry_t) e;
    const uint8_t *payload = FZ(packet_payload)(packet);
    size_t plen = FZ(packet_payload_length)(packet);
    uint8_t set = FZ(packet_set)(packet);
    size_t pos = 0;
    FZ_CHECK(FZ(packet_valid)(packet, len) && len == HEADER + plen + CHECKSUM, "invalid packet %s",
             fz_hex(packet, len));
    FZ(field_iter_init)(&it, set, payload, plen);
    while (FZ(field_iter_next)(&it, &e)) {
        FZ_CHECK(e.offset == pos, "entry at payload offset %zu, expected %zu", e.offset, pos);
        if (e.kind == FZU(ENTRY_FIELD)) {
            FZ_CHECK(e.data == payload + pos + FZU(FIELD_HEADER_SIZE), "field data pointer at %zu", pos);
            pos += FZU(FIELD_HEADER_SIZE) + e.length;
            FZ_CHECK(pos <= plen, "field runs past the payload");
            decode_one(set, e.descriptor, e.data, e.length, device);
        } else {
            FZ_CHECK(e.kind == FZU(ENTRY_TRAILING) && e.length == plen - pos && e.length > 0,
                     "trailing entry");
            pos = plen;
        }
    }
    FZ_CHECK(pos == plen, "the entries cover %zu of %zu payload bytes", pos, plen);
    /* the straight-line decoder (issue 38): every entry either decoded into a member or passed on */
    FZ(field_iter_init)(&it, set, payload, plen);
    while (FZ(field_iter_next)(&it, &e)) {
        entries++;
    }
    index = FZ(decode_packet)(packet, &straight, count_other, &other);
    FZ_CHECK((index ? index->count : 0) + other.count == entries,
             "straight-line decode: %zu + %zu of %zu entries", index ? index->count : (size_t)0, other.count,
             entries);
    check_cached(packet, index, &straight, &other);
}

static void on_event(void *arg, const FZ(event_t) * ev) {
    fz_lean_t *run = (fz_lean_t *)arg;
    int skip = ev->kind == FZU(EVENT_SKIP);
    FZ_CHECK(ev->offset == run->end, "event at offset %llu, expected %llu", (unsigned long long)ev->offset,
             (unsigned long long)run->end);
    FZ_CHECK(ev->length > 0 && ev->length <= run->size - ev->offset, "event length %llu at %llu",
             (unsigned long long)ev->length, (unsigned long long)ev->offset);
    FZ_CHECK(!(skip && run->last_skip), "two skip runs in a row");
    if (ev->kind == FZU(EVENT_NMEA) || ev->kind == FZU(EVENT_RTCM)) {
        /* a sentence or correction frame between packets (docs/conformance.md section 1): its
         * bytes, nothing to decode */
        FZ_CHECK(ev->packet != NULL && memcmp(ev->packet, run->stream + ev->offset, (size_t)ev->length) == 0,
                 "frame bytes differ from the stream at %llu", (unsigned long long)ev->offset);
    } else if (!skip) {
        FZ_CHECK(ev->kind == FZU(EVENT_PACKET) && ev->packet != NULL &&
                     memcmp(ev->packet, run->stream + ev->offset, (size_t)ev->length) == 0,
                 "packet bytes differ from the stream at %llu", (unsigned long long)ev->offset);
        walk(ev->packet, (size_t)ev->length, run->device);
        run->packets++;
    } else {
        FZ_CHECK(ev->packet == NULL, "a skip run with packet bytes");
    }
    run->last_skip = skip;
    run->end = ev->offset + ev->length;
}

static void parse(fz_lean_t *run) {
    FZ(parser_t) parser;
    FZ(parser_init)(&parser);
    FZ(parser_feed)(&parser, run->stream, run->size, on_event, run);
    FZ(parser_flush)(&parser, on_event, run);
    FZ_CHECK(run->end == run->size, "events cover %llu of %zu bytes", (unsigned long long)run->end,
             run->size);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    fz_lean_t run;
    fz_lean_t one;
    uint8_t buf[MAX_PACKET];
    FZ(packet_builder_t) b;
    size_t plen;
    size_t len = 0;
    int dev;
    FZ(device_t) devices = (FZ(device_t))0;
    if (size == 0) {
        return 0;
    }
    while (FZ(device_id)((FZ(device_t))(devices + 1)) != NULL) {
        devices = (FZ(device_t))(devices + 1);
    }
    dev = data[0] >> 6;
    FZ(layout_cache_init)(&g_cache);
    memset(&run, 0, sizeof run);
    run.stream = data + 1;
    run.size = size - 1;
    run.device = dev <= (int)devices ? (FZ(device_t))dev : FZU(DEVICE_ANY);
    parse(&run);
    if (run.size == 0) {
        return 0;
    }
    plen = run.size - 1 < MAX_PAYLOAD ? run.size - 1 : MAX_PAYLOAD;
    FZ(packet_begin)(&b, buf, sizeof buf, run.stream[0]);
    FZ_CHECK(FZ(packet_add_raw)(&b, run.stream + 1, plen) == FZU(OK), "add_raw of %zu bytes", plen);
    FZ_CHECK(FZ(packet_finish)(&b, &len) == FZU(OK) && len == HEADER + plen + CHECKSUM, "finish: %zu bytes",
             len);
    memset(&one, 0, sizeof one);
    one.stream = buf;
    one.size = len;
    one.device = run.device;
    parse(&one);
    FZ_CHECK(one.packets == 1, "a built packet parses as %zu packets", one.packets);
    return 0;
}
