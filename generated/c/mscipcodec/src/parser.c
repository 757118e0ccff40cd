/* Stream parser of docs/conformance.md section 1. Generated: do not edit. */
#include "mscipcodec/parser.h"

#include <assert.h>
#include <string.h>

void mscipc_parser_init(mscipc_parser_t *parser) {
    assert(parser != NULL);
    memset(parser, 0, sizeof *parser);
}

static void emit_skip(mscipc_parser_t *parser, mscipc_event_fn fn, void *ctx);

/* Adds the n bytes from stream offset `at` to the pending skip run; with skip_piece set, a run
 * that reaches skip_piece bytes is reported at once. */
static void add_skip(mscipc_parser_t *parser, uint64_t at, uint64_t n, mscipc_event_fn fn, void *ctx) {
    while (n > 0) {
        uint64_t take = n;
        if (parser->skip_count == 0) {
            parser->skip_offset = at;
        }
        if (parser->skip_piece != 0 && take > parser->skip_piece - parser->skip_count) {
            take = parser->skip_piece - parser->skip_count;
        }
        parser->skip_count += take;
        at += take;
        n -= take;
        if (parser->skip_piece != 0 && parser->skip_count >= parser->skip_piece) {
            emit_skip(parser, fn, ctx);
        }
    }
}

/* Marks the first n buffered bytes as skipped and drops them. */
static void skip(mscipc_parser_t *parser, size_t n, mscipc_event_fn fn, void *ctx) {
    if (n == 0) {
        return;
    }
    add_skip(parser, parser->base, n, fn, ctx);
    parser->used -= n;
    memmove(parser->buf, parser->buf + n, parser->used);
    parser->base += n;
}

static void emit_skip(mscipc_parser_t *parser, mscipc_event_fn fn, void *ctx) {
    mscipc_event_t ev;
    if (parser->skip_count == 0) {
        return;
    }
    ev.kind = MSCIPC_EVENT_SKIP;
    ev.offset = parser->skip_offset;
    ev.length = parser->skip_count;
    ev.packet = NULL;
    parser->skip_count = 0;
    if (fn) {
        fn(ctx, &ev);
    }
}

/* Index of the first full sync sequence, or of a partial one at the end, or used. */
static size_t find_sync(const mscipc_parser_t *parser) {
    size_t i;
    for (i = 0; i < parser->used; i++) {
        size_t k = 0;
        while (k < MSCIPC_SYNC_SIZE && i + k < parser->used && parser->buf[i + k] == mscipc_sync[k]) {
            k++;
        }
        if (k == MSCIPC_SYNC_SIZE || i + k == parser->used) {
            return i;
        }
    }
    return parser->used;
}

/* Consumes what the buffered bytes decide; stops when more input is needed. At the end of
 * input (final) there is no more: a candidate that would wait is a false sync instead. */
static void process(mscipc_parser_t *parser, mscipc_event_fn fn, void *ctx, int final) {
    for (;;) {
        size_t payload;
        size_t total;
        skip(parser, find_sync(parser), fn, ctx);
        if (parser->used == 0) {
            return;
        }
        if (parser->used < MSCIPC_HEADER_SIZE) {
            if (!final) {
                return; /* a partial sync or an incomplete header: wait */
            }
            skip(parser, 1, fn, ctx);
            continue;
        }
        payload = parser->buf[MSCIPC_LENGTH_OFFSET];
        if (payload > MSCIPC_MAX_PAYLOAD) {
            skip(parser, 1, fn, ctx); /* false sync */
            continue;
        }
        total = MSCIPC_HEADER_SIZE + payload + MSCIPC_CHECKSUM_SIZE;
        if (parser->used < total) {
            if (!final) {
                return; /* incomplete packet: wait */
            }
            skip(parser, 1, fn, ctx);
            continue;
        }
        if (!mscipc_checksum_matches(parser->buf, MSCIPC_HEADER_SIZE + payload)) {
            skip(parser, 1, fn, ctx); /* false sync: resynchronise at the next byte */
            continue;
        }
        emit_skip(parser, fn, ctx);
        if (fn) {
            mscipc_event_t ev;
            ev.kind = MSCIPC_EVENT_PACKET;
            ev.offset = parser->base;
            ev.length = total;
            ev.packet = parser->buf;
            fn(ctx, &ev);
        }
        parser->used -= total;
        memmove(parser->buf, parser->buf + total, parser->used);
        parser->base += total;
    }
}

/* Bytes the buffered candidate at buf[0] needs before process() can decide on it (0: none
 * buffered). A partial sync or header needs the header; a header, the whole packet. */
static size_t wanted(const mscipc_parser_t *parser) {
    size_t total;
    if (parser->used == 0) {
        return 0;
    }
    if (parser->used < MSCIPC_HEADER_SIZE) {
        return MSCIPC_HEADER_SIZE - parser->used;
    }
    total = MSCIPC_HEADER_SIZE + (size_t)parser->buf[MSCIPC_LENGTH_OFFSET] + MSCIPC_CHECKSUM_SIZE;
    return total > parser->used ? total - parser->used : 1;
}

/* The fast path: the same decisions as process(), made in place on the caller's bytes (no copy).
 * Returns the number of bytes consumed; the rest (a candidate that needs more input, shorter
 * than a maximum packet) is left for the caller to buffer. parser->base is the stream offset
 * of data[0] on entry and of data[consumed] on return. */
static size_t scan(const uint8_t *data, size_t len, mscipc_parser_t *parser, mscipc_event_fn fn, void *ctx) {
    const uint64_t base = parser->base;
    size_t pos = 0;
    while (pos < len) {
        const uint8_t *p = data + pos;
        size_t left = len - pos;
        size_t payload;
        size_t total;
        if (p[0] != mscipc_sync[0]) {
            const uint8_t *q = memchr(p, mscipc_sync[0], left);
            size_t n = q ? (size_t)(q - p) : left;
            add_skip(parser, base + pos, n, fn, ctx);
            pos += n;
            continue;
        }
        if (left < MSCIPC_HEADER_SIZE) {
            /* a partial sync or header at the end: the caller buffers it (unless it already
             * differs from the sync sequence, then skip its first byte) */
            if (memcmp(p, mscipc_sync, left < MSCIPC_SYNC_SIZE ? left : MSCIPC_SYNC_SIZE) == 0) {
                break;
            }
        } else if (memcmp(p, mscipc_sync, MSCIPC_SYNC_SIZE) == 0 &&
                   (payload = p[MSCIPC_LENGTH_OFFSET]) <= MSCIPC_MAX_PAYLOAD) {
            total = MSCIPC_HEADER_SIZE + payload + MSCIPC_CHECKSUM_SIZE;
            if (left < total) {
                break; /* incomplete packet: the caller buffers it */
            }
            if (mscipc_checksum_matches(p, MSCIPC_HEADER_SIZE + payload)) {
                parser->base = base + pos;
                emit_skip(parser, fn, ctx);
                if (fn) {
                    mscipc_event_t ev;
                    ev.kind = MSCIPC_EVENT_PACKET;
                    ev.offset = base + pos;
                    ev.length = total;
                    ev.packet = p;
                    fn(ctx, &ev);
                }
                pos += total;
                continue;
            }
        }
        /* false sync: skip one byte and resynchronise */
        add_skip(parser, base + pos, 1, fn, ctx);
        pos++;
    }
    parser->base = base + pos;
    return pos;
}

void mscipc_parser_feed(mscipc_parser_t *parser, const uint8_t *data, size_t len, mscipc_event_fn fn,
                        void *ctx) {
    assert(parser != NULL);
    assert(data != NULL || len == 0);
    assert(fn != NULL);
    while (len > 0) {
        size_t take;
        if (parser->used == 0) {
            /* nothing buffered: packets are checked and reported in place */
            size_t done = scan(data, len, parser, fn, ctx);
            data += done;
            len -= done;
            memcpy(parser->buf, data, len); /* < one maximum packet: a candidate that waits */
            parser->used = len;
            return;
        }
        /* complete the buffered candidate, no more: once the buffer is empty again the fast
         * path takes over */
        take = wanted(parser);
        if (take > len) {
            take = len;
        }
        memcpy(parser->buf + parser->used, data, take);
        parser->used += take;
        data += take;
        len -= take;
        process(parser, fn, ctx, 0);
    }
}

void mscipc_parser_flush(mscipc_parser_t *parser, mscipc_event_fn fn, void *ctx) {
    assert(parser != NULL);
    assert(fn != NULL);
    process(parser, fn, ctx, 1);
    emit_skip(parser, fn, ctx);
}

bool mscipc_parser_look_ahead(mscipc_parser_t *parser, mscipc_event_fn fn, void *ctx) {
    size_t j;
    assert(parser != NULL);
    assert(fn != NULL);
    for (j = 1; j + MSCIPC_HEADER_SIZE <= parser->used; j++) {
        const uint8_t *p = parser->buf + j;
        size_t payload;
        if (memcmp(p, mscipc_sync, MSCIPC_SYNC_SIZE) != 0) {
            continue;
        }
        payload = p[MSCIPC_LENGTH_OFFSET];
        if (payload > MSCIPC_MAX_PAYLOAD ||
            j + MSCIPC_HEADER_SIZE + payload + MSCIPC_CHECKSUM_SIZE > parser->used ||
            !mscipc_checksum_matches(p, MSCIPC_HEADER_SIZE + payload)) {
            continue;
        }
        skip(parser, j, fn, ctx);
        process(parser, fn, ctx, 0);
        return true;
    }
    return false;
}
