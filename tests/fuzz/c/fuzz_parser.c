/* Fuzz target `parser` (C): untrusted bytes through the stream parser, the field iterator, the
 * dispatch decoder of every field, the typed encoder and the canonical JSON printer.
 *
 * Input: byte 0 is a control byte (chunk plan in its low 6 bits, device in its top 2 bits),
 * the rest is the byte stream. Checked (docs/conformance.md sections 1-5):
 *  - the events cover the stream exactly: offsets contiguous from 0, skip and packet lengths sum
 *    to the stream length, no two skip runs in a row, every packet has a valid checksum and its
 *    bytes are the stream's bytes at its offset;
 *  - the stream fed in chunks (sizes from the control byte) gives the same events;
 *  - every field entry: the iterator walks the payload contiguously (a trailing entry is last
 *    and holds the rest); every complete field is decoded through the public dispatch with no
 *    device and with each device; a field that decodes re-encodes through the typed encoder to
 *    exactly its bytes (the decoder rejects what it could not reproduce: bool bytes other than
 *    0/1, leftover bytes; strings and padding are kept), and the encoder refuses a buffer one byte
 *    short of it;
 *  - every JSON line is printable ASCII, the same whether printed into a small or an adequate
 *    buffer (a truncated prefix, NUL-terminated), and encodes back to exactly its bytes;
 *  - the sample tracker places every data packet in a sample not after the last one opened.
 * The stream's first byte and the following bytes are also wrapped as (set, payload) into a packet
 * with a valid checksum, so every decoder is reachable without the fuzzer solving checksums. */
#include "fuzz_common.h"

#define HEADER FZU(HEADER_SIZE)
#define CHECKSUM FZU(CHECKSUM_SIZE)
#define MAX_PACKET FZU(MAX_PACKET)
#define MAX_PAYLOAD FZU(MAX_PAYLOAD)
#define FIELD_HEADER FZU(FIELD_HEADER_SIZE)
#define SMALL_LINE 24

typedef struct {
    int kind;
    uint64_t offset;
    uint64_t length;
} fz_event_t;

typedef struct {
    const uint8_t *stream;
    size_t size;
    fz_event_t *events;
    size_t count;
    size_t cap;
    int inspect; /* walk, decode and print every event (the whole-input pass) */
    FZ(device_t) device;
    FZ(sample_tracker_t) tracker;
    uint64_t data_packets;
} fz_run_t;

static FZ(device_t) device_count(void) {
    int d = 1;
    while (FZ(device_id)((FZ(device_t))d) != NULL) {
        d++;
    }
    return (FZ(device_t))(d - 1);
}

/* The JSON line of an event (packet or skip run), printed twice, then encoded back. */
static void check_line(const uint8_t *bytes, size_t len, uint64_t offset, int packet, FZ(device_t) device) {
    char small[SMALL_LINE];
    char msg[512];
    char *line;
    uint8_t *out;
    size_t n;
    size_t n2;
    size_t i;
    size_t out_len = 0;
    FZ(status_t) st;
    n = packet ? FZ(json_packet_line)(bytes, len, offset, device, small, sizeof small)
               : FZ(json_skip_line)(offset, bytes, len, small, sizeof small);
    line = (char *)malloc(n + 1);
    FZ_CHECK(line != NULL, "out of memory");
    n2 = packet ? FZ(json_packet_line)(bytes, len, offset, device, line, n + 1)
                : FZ(json_skip_line)(offset, bytes, len, line, n + 1);
    FZ_CHECK(n2 == n, "line length %zu with an adequate buffer, %zu with a small one", n2, n);
    FZ_CHECK(line[n] == '\0' && strlen(line) == n, "line not NUL-terminated at its length %zu", n);
    i = n < sizeof small - 1 ? n : sizeof small - 1;
    FZ_CHECK(small[i] == '\0' && memcmp(small, line, i) == 0, "small-buffer line is not a prefix: %s", line);
    for (i = 0; i < n; i++) {
        FZ_CHECK(line[i] >= 0x20 && line[i] < 0x7f, "byte 0x%02x at %zu of the line: %s",
                 (unsigned char)line[i], i, line);
    }
    /* encode: exactly the bytes, into an exact-size buffer (the json target checks tighter ones) */
    out = (uint8_t *)malloc(len ? len : 1);
    FZ_CHECK(out != NULL, "out of memory");
    st = FZ(json_encode_line)(line, n, out, len, &out_len, msg, sizeof msg);
    FZ_CHECK(st == FZU(OK), "encode of a decoded line failed (%d: %s): %s", (int)st, msg, line);
    FZ_CHECK(out_len == len && memcmp(out, bytes, len) == 0, "encode gives %s", fz_hex(out, out_len));
    free(out);
    free(line);
}

/* One complete field: decoded with the given device, re-encoded when it decodes. */
static void check_field(uint8_t set, uint8_t descriptor, const uint8_t *data, size_t len,
                        FZ(device_t) device) {
    FZ(field_value_t) value;
    FZ(decode_error_t) err;
    FZ(status_t) st;
    FZ(status_t) why = FZU(OK);
    uint8_t *buf;
    size_t n = 0;
    const FZ(field_info_t) *info = FZ(find_field)(set, descriptor, &why);
    memset(&err, 0, sizeof err);
    st = FZ(decode_field)(set, descriptor, data, len, device, &value, &err);
    if (st == FZU(OK)) {
        const FZ(layout_info_t) *layout = FZ(layout_info)(value.id);
        FZ_CHECK(info != NULL, "decoded a field find_field does not know (set %u descriptor %u)", set,
                 descriptor);
        FZ_CHECK(layout != NULL && layout->descriptor == descriptor, "layout info of id %d", (int)value.id);
        FZ_CHECK((size_t)value.id >= (size_t)info->first_layout &&
                     (size_t)value.id < (size_t)info->first_layout + info->layout_count,
                 "layout id %d is not one of the field's", (int)value.id);
        buf = (uint8_t *)malloc(len ? len : 1);
        FZ_CHECK(buf != NULL, "out of memory");
        st = FZ(encode_field)(&value, buf, len, &n);
        FZ_CHECK(st == FZU(OK), "re-encode of %s (set %u descriptor %u) failed: %d, data %s", layout->name,
                 set, descriptor, (int)st, fz_hex(data, len));
        FZ_CHECK(n == len && memcmp(buf, data, len) == 0,
                 "%s (set %u descriptor %u) re-encodes to different bytes: data %s", layout->name, set,
                 descriptor, fz_hex(data, len));
        if (len > 0) {
            st = FZ(encode_field)(&value, buf, len - 1, &n);
            FZ_CHECK(st != FZU(OK), "%s encoded %zu bytes into %zu", layout->name, len, len - 1);
        }
        free(buf);
    } else if (st == FZU(ERR_DECODE)) {
        char small[8];
        char msg[FZU(ERROR_MESSAGE_MAX)];
        size_t full = FZ(decode_error_format)(&err, small, sizeof small);
        size_t full2 = FZ(decode_error_format)(&err, msg, sizeof msg);
        FZ_CHECK(info != NULL, "a decode error for a field find_field does not know");
        FZ_CHECK(full == full2 && full < sizeof msg, "error message length %zu / %zu", full, full2);
        FZ_CHECK(strlen(msg) == full && memcmp(small, msg, sizeof small - 1) == 0 &&
                     small[sizeof small - 1] == 0,
                 "error message truncation: %s", msg);
    } else {
        FZ_CHECK(st == FZU(ERR_UNKNOWN_SET) || st == FZU(ERR_UNKNOWN_DESCRIPTOR), "decode status %d",
                 (int)st);
        FZ_CHECK(info == NULL && why == st, "find_field and decode_field disagree (%d / %d)", (int)why,
                 (int)st);
    }
}

/* A packet the parser reported: field walk, every field decoded, its line printed and encoded. */
static void check_packet(fz_run_t *run, const uint8_t *packet, size_t len, uint64_t offset) {
    FZ(field_iter_t) it;
    FZ(field_entry_t) e;
    FZ(sample_info_t) info;
    const uint8_t *payload = FZ(packet_payload)(packet);
    size_t plen;
    size_t pos = 0;
    int ended = 0;
    uint8_t set;
    FZ(device_t) d;
    FZ(device_t) devices = device_count();
    FZ_CHECK(len >= HEADER + CHECKSUM && FZ(packet_valid)(packet, len), "invalid packet %s",
             fz_hex(packet, len));
    set = FZ(packet_set)(packet);
    plen = FZ(packet_payload_length)(packet);
    FZ_CHECK(len == HEADER + plen + CHECKSUM, "packet length %zu for payload %zu", len, plen);
    FZ(field_iter_init)(&it, set, payload, plen);
    while (FZ(field_iter_next)(&it, &e)) {
        FZ_CHECK(!ended, "an entry after the trailing entry");
        FZ_CHECK(e.offset == pos, "entry at payload offset %zu, expected %zu", e.offset, pos);
        if (e.kind == FZU(ENTRY_FIELD)) {
            const uint8_t *head = payload + pos;
            int adjust = FZ(field_length_adjust)(set, head[FZU(FIELD_DESCRIPTOR_OFFSET)]);
            FZ_CHECK(e.descriptor == head[FZU(FIELD_DESCRIPTOR_OFFSET)] && e.data == head + FIELD_HEADER,
                     "field entry at %zu", pos);
            FZ_CHECK((int)e.length == (int)head[FZU(FIELD_LENGTH_OFFSET)] - adjust, "field length %zu",
                     e.length);
            pos += FIELD_HEADER + e.length;
            FZ_CHECK(pos <= plen, "field runs past the payload");
            check_field(set, e.descriptor, e.data, e.length, FZU(DEVICE_ANY));
            for (d = (FZ(device_t))1; d <= devices; d = (FZ(device_t))(d + 1)) {
                check_field(set, e.descriptor, e.data, e.length, d);
            }
        } else {
            char small[8];
            char msg[160];
            size_t full;
            FZ_CHECK(e.kind == FZU(ENTRY_TRAILING), "entry kind %d", (int)e.kind);
            FZ_CHECK(e.data == payload + pos && e.length == plen - pos,
                     "trailing entry does not hold the rest");
            FZ_CHECK(e.length > 0, "empty trailing entry");
            full = FZ(trailing_format)(&e, small, sizeof small);
            FZ_CHECK(full == FZ(trailing_format)(&e, msg, sizeof msg) && full < sizeof msg &&
                         strlen(msg) == full,
                     "trailing message length %zu", full);
            pos = plen;
            ended = 1;
        }
    }
    FZ_CHECK(pos == plen, "the entries cover %zu of %zu payload bytes", pos, plen);
    check_line(packet, len, offset, 1, run->device);
    if (FZ(sample_tracker_feed)(&run->tracker, packet, len, &info)) {
        run->data_packets++;
        FZ_CHECK(info.number < run->data_packets, "sample %llu after %llu data packets",
                 (unsigned long long)info.number, (unsigned long long)run->data_packets);
        FZ_CHECK(info.shared_prefix <= plen, "shared prefix %zu of a %zu-byte payload", info.shared_prefix,
                 plen);
    }
}

static void on_event(void *arg, const FZ(event_t) * ev) {
    fz_run_t *run = (fz_run_t *)arg;
    uint64_t expected = 0;
    if (run->count > 0) {
        const fz_event_t *last = &run->events[run->count - 1];
        expected = last->offset + last->length;
        FZ_CHECK(!(last->kind == FZU(EVENT_SKIP) && ev->kind == FZU(EVENT_SKIP)), "two skip runs in a row");
    }
    FZ_CHECK(ev->offset == expected, "event at offset %llu, expected %llu", (unsigned long long)ev->offset,
             (unsigned long long)expected);
    FZ_CHECK(ev->length > 0 && ev->length <= run->size - ev->offset, "event length %llu at %llu of %zu",
             (unsigned long long)ev->length, (unsigned long long)ev->offset, run->size);
    FZ_CHECK(run->count < run->cap, "more events than stream bytes");
    if (ev->kind == FZU(EVENT_PACKET) || ev->kind == FZU(EVENT_NMEA) || ev->kind == FZU(EVENT_RTCM)) {
        FZ_CHECK(ev->packet != NULL && memcmp(ev->packet, run->stream + ev->offset, (size_t)ev->length) == 0,
                 "packet bytes differ from the stream at %llu", (unsigned long long)ev->offset);
    } else {
        FZ_CHECK(ev->kind == FZU(EVENT_SKIP) && ev->packet == NULL, "event kind %d", (int)ev->kind);
    }
    run->events[run->count].kind = (int)ev->kind;
    run->events[run->count].offset = ev->offset;
    run->events[run->count].length = ev->length;
    run->count++;
    if (run->inspect) {
        if (ev->kind == FZU(EVENT_PACKET)) {
            check_packet(run, ev->packet, (size_t)ev->length, ev->offset);
        } else if (ev->kind == FZU(EVENT_SKIP)) {
            check_line(run->stream + ev->offset, (size_t)ev->length, ev->offset, 0, run->device);
        }
    }
}

static void check_covered(const fz_run_t *run) {
    uint64_t end = run->count ? run->events[run->count - 1].offset + run->events[run->count - 1].length : 0;
    FZ_CHECK(end == run->size, "events cover %llu of %zu bytes", (unsigned long long)end, run->size);
}

/* The stream wrapped as one packet: set = first byte, payload = the next (at most the maximum). */
static void check_wrapped(fz_run_t *run) {
    uint8_t buf[MAX_PACKET];
    FZ(packet_builder_t) b;
    FZ(parser_t) parser;
    fz_run_t one;
    fz_event_t ev[4];
    size_t plen;
    size_t len = 0;
    if (run->size == 0) {
        return;
    }
    plen = run->size - 1 < MAX_PAYLOAD ? run->size - 1 : MAX_PAYLOAD;
    FZ(packet_begin)(&b, buf, sizeof buf, run->stream[0]);
    FZ_CHECK(FZ(packet_add_raw)(&b, run->stream + 1, plen) == FZU(OK), "add_raw of %zu bytes", plen);
    FZ_CHECK(FZ(packet_finish)(&b, &len) == FZU(OK) && len == HEADER + plen + CHECKSUM, "finish: %zu bytes",
             len);
    memset(&one, 0, sizeof one);
    one.stream = buf;
    one.size = len;
    one.events = ev;
    one.cap = 4;
    one.device = run->device;
    FZ(sample_tracker_init)(&one.tracker);
    FZ(parser_init)(&parser);
    FZ(parser_feed)(&parser, buf, len, on_event, &one);
    FZ(parser_flush)(&parser, on_event, &one);
    FZ_CHECK(one.count == 1 && ev[0].kind == FZU(EVENT_PACKET) && ev[0].length == len,
             "a built packet parses as %zu events", one.count);
    check_packet(&one, buf, len, 0);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    FZ(parser_t) parser;
    fz_run_t whole;
    fz_run_t chunked;
    fz_chunks_t plan;
    uint8_t control;
    size_t pos;
    size_t i;
    int dev;
    if (size == 0) {
        return 0;
    }
    control = data[0];
    memset(&whole, 0, sizeof whole);
    whole.stream = data + 1;
    whole.size = size - 1;
    whole.cap = whole.size + 1;
    whole.events = (fz_event_t *)malloc(whole.cap * sizeof *whole.events);
    FZ_CHECK(whole.events != NULL, "out of memory");
    whole.inspect = 1;
    dev = control >> 6;
    whole.device = dev <= (int)device_count() ? (FZ(device_t))dev : FZU(DEVICE_ANY);
    FZ(sample_tracker_init)(&whole.tracker);
    chunked = whole;
    chunked.inspect = 0;
    chunked.events = (fz_event_t *)malloc(chunked.cap * sizeof *chunked.events);
    FZ_CHECK(chunked.events != NULL, "out of memory");

    FZ(parser_init)(&parser);
    FZ(parser_feed)(&parser, whole.stream, whole.size, on_event, &whole);
    FZ(parser_flush)(&parser, on_event, &whole);
    check_covered(&whole);

    FZ(parser_init)(&parser);
    fz_chunks_init(&plan, control);
    for (pos = 0; pos < chunked.size;) {
        size_t n = fz_chunks_next(&plan);
        if (n > chunked.size - pos) {
            n = chunked.size - pos;
        }
        FZ(parser_feed)(&parser, chunked.stream + pos, n, on_event, &chunked);
        pos += n;
    }
    FZ(parser_flush)(&parser, on_event, &chunked);
    check_covered(&chunked);
    FZ_CHECK(chunked.count == whole.count, "%zu events in chunks, %zu whole", chunked.count, whole.count);
    for (i = 0; i < whole.count; i++) {
        FZ_CHECK(chunked.events[i].kind == whole.events[i].kind &&
                     chunked.events[i].length == whole.events[i].length,
                 "event %zu differs when fed in chunks", i);
    }
    check_wrapped(&whole);
    free(chunked.events);
    free(whole.events);
    return 0;
}
