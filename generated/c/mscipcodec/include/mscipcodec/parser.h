/* Stream parser of docs/conformance.md section 1. Generated: do not edit. */
/*
 * Pointer arguments (every function of this header): a pointer must be valid for what the function
 * reads or writes, and not NULL, unless its documentation says "may be NULL". A buffer pointer
 * paired with a size (bytes/len, buf/cap, out/cap) may be NULL when that size is 0. Debug builds
 * (without NDEBUG) check these preconditions with assert(); docs/conformance.md section 7.
 */
#ifndef MSCIPC_PARSER_H
#define MSCIPC_PARSER_H

#include "mscipcodec/framing.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
    MSCIPC_EVENT_PACKET = 1, /* a packet with a valid checksum */
    MSCIPC_EVENT_SKIP = 2    /* a maximal run of skipped bytes */
} mscipc_event_kind_t;

typedef struct {
    mscipc_event_kind_t kind;
    uint64_t offset;       /* stream offset of the packet or of the first skipped byte */
    uint64_t length;       /* packet size, or number of skipped bytes */
    const uint8_t *packet; /* the packet bytes (valid during the callback); NULL for skips */
} mscipc_event_t;

typedef void (*mscipc_event_fn)(void *ctx, const mscipc_event_t *event);

/**
 * Fixed-size state: at most one maximum packet is buffered. Events do not depend on how the
 * input is split into chunks; a skip run is reported just before the next packet or at flush.
 */
typedef struct {
    uint8_t buf[MSCIPC_MAX_PACKET];
    size_t used;          /* bytes in buf */
    uint64_t base;        /* stream offset of buf[0] */
    uint64_t skip_offset; /* pending skip run */
    uint64_t skip_count;
} mscipc_parser_t;

void mscipc_parser_init(mscipc_parser_t *parser);
/** Feeds a chunk of the stream; events are delivered through fn (not NULL) with ctx (may be NULL). */
void mscipc_parser_feed(mscipc_parser_t *parser, const uint8_t *data, size_t len, mscipc_event_fn fn,
                        void *ctx);
/** End of stream: candidates that would wait for more input are false syncs (skipped one byte
 * at a time, so complete packets behind them are still found); the last skip run is reported. */
void mscipc_parser_flush(mscipc_parser_t *parser, mscipc_event_fn fn, void *ctx);
/** The timed rule of section 8: the first buffered byte (where the parser waits for more input)
 * is skipped as a false sync and parsing resumes at the next byte, with no new input. Does
 * nothing when nothing is buffered. */
void mscipc_parser_drop_first(mscipc_parser_t *parser, mscipc_event_fn fn, void *ctx);

#ifdef __cplusplus
}
#endif

#endif
