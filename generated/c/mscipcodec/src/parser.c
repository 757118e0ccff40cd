/* Stream parser of docs/conformance.md section 1. Generated: do not edit. */
#include "mscipcodec/parser.h"

#include <string.h>

void mscip_parser_init(mscip_parser_t *parser) {
    memset(parser, 0, sizeof *parser);
}

/* Marks the first n buffered bytes as skipped and drops them. */
static void skip(mscip_parser_t *parser, size_t n) {
    if (n == 0) {
        return;
    }
    if (parser->skip_count == 0) {
        parser->skip_offset = parser->base;
    }
    parser->skip_count += n;
    parser->used -= n;
    memmove(parser->buf, parser->buf + n, parser->used);
    parser->base += n;
}

static void emit_skip(mscip_parser_t *parser, mscip_event_fn fn, void *ctx) {
    mscip_event_t ev;
    if (parser->skip_count == 0) {
        return;
    }
    ev.kind = MSCIP_EVENT_SKIP;
    ev.offset = parser->skip_offset;
    ev.length = parser->skip_count;
    ev.packet = NULL;
    parser->skip_count = 0;
    if (fn) {
        fn(ctx, &ev);
    }
}

/* Index of the first full sync sequence, or of a partial one at the end, or used. */
static size_t find_sync(const mscip_parser_t *parser) {
    size_t i;
    for (i = 0; i < parser->used; i++) {
        size_t k = 0;
        while (k < MSCIP_SYNC_SIZE && i + k < parser->used && parser->buf[i + k] == mscip_sync[k]) {
            k++;
        }
        if (k == MSCIP_SYNC_SIZE || i + k == parser->used) {
            return i;
        }
    }
    return parser->used;
}

/* Consumes what the buffered bytes decide; stops when more input is needed. At the end of
 * input (final) there is no more: a candidate that would wait is a false sync instead. */
static void process(mscip_parser_t *parser, mscip_event_fn fn, void *ctx, int final) {
    for (;;) {
        uint8_t ck[MSCIP_CHECKSUM_SIZE];
        size_t payload;
        size_t total;
        skip(parser, find_sync(parser));
        if (parser->used == 0) {
            return;
        }
        if (parser->used < MSCIP_HEADER_SIZE) {
            if (!final) {
                return; /* a partial sync or an incomplete header: wait */
            }
            skip(parser, 1);
            continue;
        }
        payload = parser->buf[MSCIP_LENGTH_OFFSET];
        if (payload > MSCIP_MAX_PAYLOAD) {
            skip(parser, 1); /* false sync */
            continue;
        }
        total = MSCIP_HEADER_SIZE + payload + MSCIP_CHECKSUM_SIZE;
        if (parser->used < total) {
            if (!final) {
                return; /* incomplete packet: wait */
            }
            skip(parser, 1);
            continue;
        }
        mscip_checksum(parser->buf, MSCIP_HEADER_SIZE + payload, ck);
        if (memcmp(ck, parser->buf + MSCIP_HEADER_SIZE + payload, MSCIP_CHECKSUM_SIZE) != 0) {
            skip(parser, 1); /* false sync: resynchronise at the next byte */
            continue;
        }
        emit_skip(parser, fn, ctx);
        if (fn) {
            mscip_event_t ev;
            ev.kind = MSCIP_EVENT_PACKET;
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

void mscip_parser_feed(mscip_parser_t *parser, const uint8_t *data, size_t len, mscip_event_fn fn,
                       void *ctx) {
    while (len > 0) {
        size_t room = sizeof parser->buf - parser->used;
        size_t take = len < room ? len : room;
        memcpy(parser->buf + parser->used, data, take);
        parser->used += take;
        data += take;
        len -= take;
        process(parser, fn, ctx, 0);
    }
}

void mscip_parser_flush(mscip_parser_t *parser, mscip_event_fn fn, void *ctx) {
    process(parser, fn, ctx, 1);
    emit_skip(parser, fn, ctx);
}
