/* Stream parser of docs/conformance.md section 1. Generated: do not edit. */
#include "mipcodec/parser.h"

#include <assert.h>
#include <string.h>

#include "checksum_impl.h"
#include "hex.h"

/* The sync sequence as a constant of this unit (mipc_sync lives in framing.c, where the compiler
 * could not fold its bytes into the comparisons). */
static const uint8_t k_sync[MIPC_SYNC_SIZE] = MIPC_SYNC_BYTES;

void mipc_parser_init(mipc_parser_t *parser) {
    assert(parser != NULL);
    memset(parser, 0, sizeof *parser);
}

static void emit_skip(mipc_parser_t *parser, mipc_event_fn fn, void *ctx);

/* Foreign frames (docs/conformance.md section 1): where the parser would skip bytes, a whole
 * NMEA-0183 sentence or RTCM3 frame is reported instead (MIPC_EVENT_NMEA, MIPC_EVENT_RTCM); a
 * candidate that fails stays skipped bytes, one byte at a time. Never on the packet path. */
#define FOREIGN (MIPC_FOREIGN_NMEA || MIPC_FOREIGN_RTCM3)
#if FOREIGN
#define FOREIGN_WAIT ((size_t)-1)

static inline bool foreign_start(uint8_t b) {
    return (MIPC_FOREIGN_NMEA && (b == 0x24 || b == 0x21)) || (MIPC_FOREIGN_RTCM3 && b == 0xD3);
}

/* Index in p[0..n) of the first byte that starts a foreign frame, else n. */
static size_t next_foreign(const uint8_t *p, size_t n) {
    size_t i;
    for (i = 0; i < n; i++) {
        if (foreign_start(p[i])) {
            return i;
        }
    }
    return n;
}

#if MIPC_FOREIGN_RTCM3
/* CRC-24Q of RTCM3: polynomial 0x1864CFB, initial value 0, not reflected. */
static uint32_t crc24q(const uint8_t *p, size_t n) {
    uint32_t crc = 0;
    size_t i;
    for (i = 0; i < n; i++) {
        int k;
        crc ^= (uint32_t)p[i] << 16;
        for (k = 0; k < 8; k++) {
            crc <<= 1;
            if (crc & 0x1000000u) {
                crc ^= 0x1864CFBu;
            }
        }
    }
    return crc;
}
#endif

/* The foreign frame at p[0] (a start byte) with n bytes available: its length when it is whole
 * and valid, 0 when it is not one, FOREIGN_WAIT when more bytes decide. */
static size_t foreign_frame(const uint8_t *p, size_t n) {
#if MIPC_FOREIGN_RTCM3
    if (p[0] == 0xD3) {
        size_t length;
        size_t total;
        if (n < 3) {
            return FOREIGN_WAIT;
        }
        if ((p[1] & 0xFC) != 0) {
            return 0;
        }
        length = (size_t)(p[1] & 3) << 8 | p[2];
        if (length < 2) {
            return 0; /* no message number */
        }
        total = 3 + length + 3;
        if (n < total) {
            return FOREIGN_WAIT;
        }
        return crc24q(p, total - 3) ==
                       ((uint32_t)p[total - 3] << 16 | (uint32_t)p[total - 2] << 8 | p[total - 1])
                   ? total
                   : 0;
    }
#endif
#if MIPC_FOREIGN_NMEA
    {
        const size_t lim = MIPC_NMEA_MAX - 4; /* the '*' stands before lim */
        size_t j = 1;
        unsigned x = 0;
        int hi;
        int lo;
        while (j < n && j < lim && p[j] >= 0x20 && p[j] <= 0x7E && p[j] != '$' && p[j] != '!' &&
               p[j] != '*') {
            x ^= p[j];
            j++;
        }
        if (j == lim) {
            return 0; /* overlong */
        }
        if (j == n) {
            return FOREIGN_WAIT;
        }
        if (p[j] != '*') {
            return 0;
        }
        if (n < j + 5) {
            return FOREIGN_WAIT;
        }
        hi = mipc_hex_value((char)p[j + 1]);
        lo = mipc_hex_value((char)p[j + 2]);
        if (hi < 0 || lo < 0 || p[j + 3] != '\r' || p[j + 4] != '\n' || (unsigned)(hi << 4 | lo) != x) {
            return 0;
        }
        return j + 5;
    }
#else
    (void)n;
    return 0;
#endif
}

/* Bytes the foreign candidate at p[0] (undecided with n bytes) needs at most before it is decided. */
static size_t foreign_wanted(const uint8_t *p, size_t n) {
    size_t total = MIPC_NMEA_MAX;
    if (p[0] == 0xD3) {
        total = n < 3 ? 3 : 3 + ((size_t)(p[1] & 3) << 8 | p[2]) + 3;
    }
    return total > n ? total - n : 1;
}

/* Reports a foreign frame (out of line: never on the packet path). */
#if defined(__GNUC__) || defined(__clang__)
__attribute__((noinline))
#endif
static void report_foreign(const uint8_t *p, size_t n, uint64_t offset, mipc_event_fn fn, void *ctx) {
    mipc_event_t ev;
    ev.kind = p[0] == 0xD3 ? MIPC_EVENT_RTCM : MIPC_EVENT_NMEA;
    ev.offset = offset;
    ev.length = n;
    ev.packet = p;
    if (fn) {
        fn(ctx, &ev);
    }
}
#endif

/* Adds the n bytes from stream offset `at` to the pending skip run; with skip_piece set, a run
 * that reaches skip_piece bytes is reported at once. */
static void add_skip(mipc_parser_t *parser, uint64_t at, uint64_t n, mipc_event_fn fn, void *ctx) {
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
static void skip(mipc_parser_t *parser, size_t n, mipc_event_fn fn, void *ctx) {
    if (n == 0) {
        return;
    }
    add_skip(parser, parser->base, n, fn, ctx);
    parser->used -= n;
    memmove(parser->buf, parser->buf + n, parser->used);
    parser->base += n;
}

static void emit_skip(mipc_parser_t *parser, mipc_event_fn fn, void *ctx) {
    mipc_event_t ev;
    if (parser->skip_count == 0) {
        return;
    }
    ev.kind = MIPC_EVENT_SKIP;
    ev.offset = parser->skip_offset;
    ev.length = parser->skip_count;
    ev.packet = NULL;
    parser->skip_count = 0;
    if (fn) {
        fn(ctx, &ev);
    }
}

/* Index of the first full sync sequence, or of a partial one at the end, or used. */
static size_t find_sync(const mipc_parser_t *parser) {
    size_t i;
    for (i = 0; i < parser->used; i++) {
        size_t k = 0;
        while (k < MIPC_SYNC_SIZE && i + k < parser->used && parser->buf[i + k] == mipc_sync[k]) {
            k++;
        }
        if (k == MIPC_SYNC_SIZE || i + k == parser->used) {
            return i;
        }
    }
    return parser->used;
}

/* Consumes what the buffered bytes decide; stops when more input is needed. At the end of
 * input (final) there is no more: a candidate that would wait is a false sync instead. */
static void process(mipc_parser_t *parser, mipc_event_fn fn, void *ctx, int final) {
    for (;;) {
        size_t payload;
        size_t total;
        size_t i = find_sync(parser);
#if FOREIGN
        const size_t s = next_foreign(parser->buf, i);
        if (s < i) {
            size_t r;
            skip(parser, s, fn, ctx);
            r = foreign_frame(parser->buf, parser->used);
            if (r == FOREIGN_WAIT) {
                if (!final) {
                    return; /* an undecided frame: wait */
                }
                r = 0;
            }
            if (r == 0) {
                skip(parser, 1, fn, ctx); /* not a frame: its first byte is skipped */
                continue;
            }
            emit_skip(parser, fn, ctx);
            report_foreign(parser->buf, r, parser->base, fn, ctx);
            parser->used -= r;
            memmove(parser->buf, parser->buf + r, parser->used);
            parser->base += r;
            continue;
        }
#endif
        skip(parser, i, fn, ctx);
        if (parser->used == 0) {
            return;
        }
        if (parser->used < MIPC_HEADER_SIZE) {
            if (!final) {
                return; /* a partial sync or an incomplete header: wait */
            }
            skip(parser, 1, fn, ctx);
            continue;
        }
        payload = parser->buf[MIPC_LENGTH_OFFSET];
        if (payload > MIPC_MAX_PAYLOAD) {
            skip(parser, 1, fn, ctx); /* false sync */
            continue;
        }
        total = MIPC_HEADER_SIZE + payload + MIPC_CHECKSUM_SIZE;
        if (parser->used < total) {
            if (!final) {
                return; /* incomplete packet: wait */
            }
            skip(parser, 1, fn, ctx);
            continue;
        }
        if (!mipc_checksum_matches(parser->buf, MIPC_HEADER_SIZE + payload)) {
            skip(parser, 1, fn, ctx); /* false sync: resynchronise at the next byte */
            continue;
        }
        emit_skip(parser, fn, ctx);
        if (fn) {
            mipc_event_t ev;
            ev.kind = MIPC_EVENT_PACKET;
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
static size_t wanted(const mipc_parser_t *parser) {
    size_t total;
    if (parser->used == 0) {
        return 0;
    }
#if FOREIGN
    if (foreign_start(parser->buf[0])) {
        return foreign_wanted(parser->buf, parser->used);
    }
#endif
    if (parser->used < MIPC_HEADER_SIZE) {
        return MIPC_HEADER_SIZE - parser->used;
    }
    total = MIPC_HEADER_SIZE + (size_t)parser->buf[MIPC_LENGTH_OFFSET] + MIPC_CHECKSUM_SIZE;
    return total > parser->used ? total - parser->used : 1;
}

/* Reports a skip run (out of line: rare on the packet path). */
#if defined(__GNUC__) || defined(__clang__)
__attribute__((noinline))
#endif
static void report_run(uint64_t offset, uint64_t count, mipc_event_fn fn, void *ctx) {
    mipc_event_t ev;
    ev.kind = MIPC_EVENT_SKIP;
    ev.offset = offset;
    ev.length = count;
    ev.packet = NULL;
    if (fn) {
        fn(ctx, &ev);
    }
}

/* True when the MIPC_SYNC_SIZE bytes at p are the sync sequence (byte by byte: no library call). */
static inline bool is_sync(const uint8_t *p) {
    size_t k;
    for (k = 0; k < MIPC_SYNC_SIZE; k++) {
        if (p[k] != k_sync[k]) {
            return false;
        }
    }
    return true;
}

/* Index of the lowest set bit of a non-zero word. */
static inline unsigned lowest_bit(uint64_t x) {
#if defined(__GNUC__) || defined(__clang__)
    return (unsigned)__builtin_ctzll(x);
#else
    unsigned n = 0;
    while ((x & 1u) == 0) {
        x >>= 1;
        n++;
    }
    return n;
#endif
}

/* Index in p[0..n) of the first full sync sequence, or of a proper prefix of it that ends the
 * bytes (a candidate that waits for more input), else n: every position before it is skipped
 * by the decisions of section 1 (its first byte is not the sync's, or the sync breaks off).
 * Sixteen positions at a time (eight where there is no SSE2) while the whole sync fits after
 * all of them: byte k of the sync is compared with the bytes at position + k, and a position
 * matches where every comparison does. One branch per sixteen bytes of garbage, none per byte
 * that merely equals the sync's first. */
static inline size_t next_sync(const uint8_t *p, size_t n) {
    size_t at = 0;
    size_t k;
#if CHECKSUM_SSE2
    while (n - at >= 16 + MIPC_SYNC_SIZE - 1) {
        int hits = 0xFFFF;
        for (k = 0; k < MIPC_SYNC_SIZE; k++) {
            const __m128i v = _mm_loadu_si128((const __m128i *)(const void *)(p + at + k));
            hits &= _mm_movemask_epi8(_mm_cmpeq_epi8(v, _mm_set1_epi8((char)k_sync[k])));
        }
        if (hits != 0) {
            return at + lowest_bit((uint64_t)(unsigned)hits);
        }
        at += 16;
    }
#else
    /* Zero bytes of diff are the matches; the lowest flagged byte is the first match (a flag can
     * be wrong only above a zero byte). */
    const uint64_t low = UINT64_C(0x0101010101010101);
    const uint64_t high = UINT64_C(0x8080808080808080);
    while (n - at >= 8 + MIPC_SYNC_SIZE - 1) {
        uint64_t diff = 0;
        uint64_t zero;
        for (k = 0; k < MIPC_SYNC_SIZE; k++) {
            diff |= load_le64(p + at + k) ^ (low * k_sync[k]);
        }
        zero = (diff - low) & ~diff & high;
        if (zero != 0) {
            return at + lowest_bit(zero) / 8;
        }
        at += 8;
    }
#endif
    for (; at < n; at++) {
        size_t m = n - at < MIPC_SYNC_SIZE ? n - at : MIPC_SYNC_SIZE;
        k = 0;
        while (k < m && p[at + k] == k_sync[k]) {
            k++;
        }
        if (k == m) {
            return at;
        }
    }
    return n;
}

/* The checksum test of a candidate: inlined for the short packets of a data stream (the scalar
 * steps under 16 bytes, SSE2 under 64), the library function (AVX2 where the CPU has it) for
 * longer ones. */
static inline bool checksum_ok(const uint8_t *p, size_t body) {
    sums_t s = {0, 0};
#if CHECKSUM_SSE2
    if (body >= 64) {
        return mipc_checksum_matches(p, body);
    }
    s = body >= 16 ? sums_sse2(s, p, body) : sums_scalar(s, p, body);
#else
    s = sums_scalar(s, p, body);
#endif
    return sums_word(s) == (unsigned)((unsigned)p[body] << 8 | p[body + 1]);
}

/* The skip run pending after n more bytes at stream offset `at`: with skip_piece set, every
 * piece it completes is reported now (as add_skip does). */
typedef struct {
    uint64_t offset;
    uint64_t count;
} run_t;

static run_t grow_run(run_t run, uint64_t at, uint64_t n, uint64_t piece, mipc_event_fn fn, void *ctx) {
    if (run.count == 0) {
        run.offset = at;
    }
    run.count += n;
    while (piece != 0 && run.count >= piece) {
        report_run(run.offset, piece, fn, ctx);
        run.offset += piece;
        run.count -= piece;
    }
    return run;
}

/* The fast path: the same decisions as process(), made in place on the caller's bytes (no copy).
 * Returns the number of bytes consumed; the rest (a candidate that needs more input, shorter
 * than a maximum packet) is left for the caller to buffer. parser->base is the stream offset
 * of data[0] on entry and of data[consumed] on return. The pending skip run lives in locals
 * (the callback's stores could otherwise alias the parser and force it to memory on every
 * packet); the parser's fields are up to date again on return. */
static size_t scan(const uint8_t *data, size_t len, mipc_parser_t *parser, mipc_event_fn fn, void *ctx) {
    const uint64_t base = parser->base;
    const uint64_t piece = parser->skip_piece;
    run_t run;
    size_t pos = 0;
    run.offset = parser->skip_offset;
    run.count = parser->skip_count;
    while (pos < len) {
        const uint8_t *p = data + pos;
        const size_t left = len - pos;
        size_t skipped = 1; /* a false sync: resynchronise at the next byte */
        if (left < MIPC_SYNC_SIZE || !is_sync(p)) {
            skipped = next_sync(p, left);
            if (skipped == 0) {
                break; /* a partial sync at the end: the caller buffers it */
            }
#if FOREIGN
            {
                const size_t s = next_foreign(p, skipped);
                if (s < skipped) {
                    size_t r;
                    if (s > 0) {
                        run = grow_run(run, base + pos, s, piece, fn, ctx);
                        pos += s;
                    }
                    r = foreign_frame(data + pos, len - pos);
                    if (r == FOREIGN_WAIT) {
                        break; /* an undecided frame at the end: the caller buffers it */
                    }
                    if (r != 0) {
                        if (run.count != 0) {
                            report_run(run.offset, run.count, fn, ctx);
                            run.count = 0;
                        }
                        report_foreign(data + pos, r, base + pos, fn, ctx);
                        pos += r;
                        continue;
                    }
                    skipped = 1; /* not a frame: its first byte is skipped */
                }
            }
#endif
        } else if (left < MIPC_HEADER_SIZE) {
            break; /* a partial header at the end: the caller buffers it */
        } else {
            const size_t payload = p[MIPC_LENGTH_OFFSET];
            if (payload <= MIPC_MAX_PAYLOAD) {
                const size_t body = MIPC_HEADER_SIZE + payload;
                if (left < body + MIPC_CHECKSUM_SIZE) {
                    break; /* incomplete packet: the caller buffers it */
                }
                if (checksum_ok(p, body)) {
                    if (run.count != 0) {
                        report_run(run.offset, run.count, fn, ctx);
                        run.count = 0;
                    }
                    if (fn) {
                        mipc_event_t ev;
                        ev.kind = MIPC_EVENT_PACKET;
                        ev.offset = base + pos;
                        ev.length = body + MIPC_CHECKSUM_SIZE;
                        ev.packet = p;
                        fn(ctx, &ev);
                    }
                    pos += body + MIPC_CHECKSUM_SIZE;
                    continue;
                }
            }
        }
        run = grow_run(run, base + pos, skipped, piece, fn, ctx);
        pos += skipped;
    }
    parser->skip_offset = run.offset;
    parser->skip_count = run.count;
    parser->base = base + pos;
    return pos;
}

void mipc_parser_feed(mipc_parser_t *parser, const uint8_t *data, size_t len, mipc_event_fn fn, void *ctx) {
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

void mipc_parser_flush(mipc_parser_t *parser, mipc_event_fn fn, void *ctx) {
    assert(parser != NULL);
    assert(fn != NULL);
    process(parser, fn, ctx, 1);
    emit_skip(parser, fn, ctx);
}

bool mipc_parser_look_ahead(mipc_parser_t *parser, mipc_event_fn fn, void *ctx) {
    size_t j;
    assert(parser != NULL);
    assert(fn != NULL);
    for (j = 1; j + MIPC_HEADER_SIZE <= parser->used; j++) {
        const uint8_t *p = parser->buf + j;
        size_t payload;
        if (memcmp(p, mipc_sync, MIPC_SYNC_SIZE) != 0) {
            continue;
        }
        payload = p[MIPC_LENGTH_OFFSET];
        if (payload > MIPC_MAX_PAYLOAD ||
            j + MIPC_HEADER_SIZE + payload + MIPC_CHECKSUM_SIZE > parser->used ||
            !mipc_checksum_matches(p, MIPC_HEADER_SIZE + payload)) {
            continue;
        }
        skip(parser, j, fn, ctx);
        process(parser, fn, ctx, 0);
        return true;
    }
    return false;
}
