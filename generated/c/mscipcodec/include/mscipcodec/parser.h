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
    MSCIPC_EVENT_SKIP = 2,   /* a maximal run of skipped bytes */
    MSCIPC_EVENT_NMEA = 3,   /* an NMEA-0183 sentence between packets ('$' to LF; MSCIPC_FOREIGN_NMEA) */
    MSCIPC_EVENT_RTCM = 4    /* an RTCM3 frame between packets (0xD3 to its CRC; MSCIPC_FOREIGN_RTCM3) */
} mscipc_event_kind_t;

typedef struct {
    mscipc_event_kind_t kind;
    uint64_t offset;       /* stream offset of the packet, frame or first skipped byte */
    uint64_t length;       /* packet or frame size, or number of skipped bytes */
    const uint8_t *packet; /* the packet or frame bytes (valid during the callback); NULL for skips */
} mscipc_event_t;

/** The message number of an RTCM3 frame (the first 12 bits of its payload). */
static inline unsigned mscipc_rtcm_type(const uint8_t *frame) {
    return (unsigned)frame[3] << 4 | (unsigned)frame[4] >> 4;
}

typedef void (*mscipc_event_fn)(void *ctx, const mscipc_event_t *event);

/**
 * Fixed-size state: at most one maximum packet (or one longest foreign frame) is buffered. Events do not
 * depend on how the input is split into chunks; a skip run is reported just before the next packet or at
 * flush, and, when skip_piece is not 0, as soon as its pending length reaches skip_piece: then a run of
 * exactly skip_piece bytes is reported and the bytes skipped after it start a new run (sessions
 * set it to MSCIPC_SESSION_SKIP_PIECE, docs/conformance.md section 8; decoding leaves it 0).
 */
typedef struct {
    uint8_t buf[MSCIPC_PARSER_CAPACITY]; /* a maximum packet, or a longer foreign frame */
    size_t used;                         /* bytes in buf */
    uint64_t base;                       /* stream offset of buf[0] */
    uint64_t skip_offset;                /* pending skip run */
    uint64_t skip_count;
    uint64_t skip_piece; /* 0: skip runs whole; else reported in pieces of at most this many bytes */
} mscipc_parser_t;

void mscipc_parser_init(mscipc_parser_t *parser);
/** Feeds a chunk of the stream; events are delivered through fn (not NULL) with ctx (may be NULL). */
void mscipc_parser_feed(mscipc_parser_t *parser, const uint8_t *data, size_t len, mscipc_event_fn fn,
                        void *ctx);
/** End of stream: candidates that would wait for more input are false syncs (skipped one byte
 * at a time, so complete packets behind them are still found); the last skip run is reported. */
void mscipc_parser_flush(mscipc_parser_t *parser, mscipc_event_fn fn, void *ctx);
/** The look-ahead rule of section 8: when the parser waits for more input at buf[0], finds the
 * first position j > 0 of the buffered bytes where a sync sequence starts a complete packet with
 * a valid checksum (length within the maximum payload, all its bytes buffered); if there is one,
 * the bytes before it are skipped (one skip run with any pending one), parsing resumes at j (the
 * packet is reported, then what follows it is parsed) and it returns true. Otherwise nothing
 * changes and it returns false (a slow packet is never dropped by time). */
bool mscipc_parser_look_ahead(mscipc_parser_t *parser, mscipc_event_fn fn, void *ctx);

#ifdef __cplusplus
}
#endif

#endif
