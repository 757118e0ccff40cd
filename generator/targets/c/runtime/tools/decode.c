/* codec-decode [--device ID] [--samples] [--decoder general|straight|cached] [FILE|-]: binary stream
 * -> canonical JSON lines (docs/conformance.md section 5). --decoder straight or cached decodes the
 * data packets with codec_decode_packet or codec_decode_packet_cached (issue 38) and writes their
 * typed members (the same lines: the conformance corpus checks those decoders with it). The input is read in
 * blocks as it arrives and decoded in bounded memory: only the bytes the parser has not decided on are kept
 * (a candidate packet, or the bytes of a pending skip run; a skip run longer than k_skip_spill is printed as
 * it grows). When stdout is not a regular file, the lines of every block are flushed as soon as they are
 * printed, so a live stream shows each packet when it arrives. */
#if defined(__unix__) || defined(__APPLE__)
#define _POSIX_C_SOURCE 200809L
#endif
#include "codec/json.h"
#include "codec/parser.h"
#include "codec/samples.h"
#include "hex.h" /* the package's src/ (private headers) */
#include "tool_io.h"

static const char k_usage[] =
    "usage: codec-decode [--device ID] [--samples] [--decoder general|straight|cached] [FILE|-]\n";
static const char k_prog[] = "codec-decode";

enum {
    k_block = 65536,       /* bytes read at a time */
    k_skip_spill = 1 << 20 /* a pending skip run longer than this is printed as it grows */
};

typedef struct {
    unsigned char *hist; /* input bytes from stream offset hist_base on (not yet decided) */
    size_t hist_len;
    size_t hist_cap;
    uint64_t hist_base;
    codec_device_t device;
    char *line;
    size_t line_cap;
    int failed;    /* out of memory */
    int write_err; /* errno of the first failed write, or 0 */
    int samples;
    int skip_open;      /* a skip line's start is printed, its end is not */
    uint64_t skip_done; /* stream offset up to which the open skip line's bytes are printed */
    codec_sample_tracker_t tracker;
    int decoder;                       /* k_general, k_straight or k_cached */
    uint64_t mismatch;                 /* stream offset + 1 of a packet the decoder did not cover, or 0 */
    const codec_packet_index_t *index; /* of the packet being printed (k_straight, k_cached) */
    size_t other_count;                /* entries passed on, in g_others */
} decode_ctx_t;

enum { k_general, k_straight, k_cached };

/* What --decoder straight or cached decodes into, and the entries it passes on (static: large). */
static codec_packet_t g_packet;
static codec_layout_cache_t g_cache;
static codec_field_entry_t g_others[CODEC_PACKET_FIELDS_MAX + 1];

static void keep_other(void *arg, const codec_field_entry_t *entry) {
    decode_ctx_t *ctx = (decode_ctx_t *)arg;
    if (ctx->other_count < sizeof g_others / sizeof g_others[0]) {
        g_others[ctx->other_count] = *entry;
    }
    ctx->other_count++; /* more than fit: reported as a mismatch */
}

static int grow(decode_ctx_t *ctx, size_t need) {
    char *bigger = (char *)realloc(ctx->line, need + 1);
    if (!bigger) {
        ctx->failed = 1;
        return -1;
    }
    ctx->line = bigger;
    ctx->line_cap = need + 1;
    return 0;
}

/* Prints the hex of the kept input bytes at stream offsets [from, to). */
static void put_hex(decode_ctx_t *ctx, uint64_t from, uint64_t to) {
    const unsigned char *p = ctx->hist + (size_t)(from - ctx->hist_base);
    size_t n = (size_t)(to - from);
    char two[2];
    size_t i;
    for (i = 0; i < n; i++) {
        two[0] = codec_hex_digit(p[i] >> 4u);
        two[1] = codec_hex_digit(p[i]);
        tool_put(two, 2, &ctx->write_err);
    }
}

/* The line of an event into ctx->line; returns its full length. */
static size_t format(decode_ctx_t *ctx, const codec_event_t *ev) {
    if (ev->kind == CODEC_EVENT_NMEA || ev->kind == CODEC_EVENT_RTCM) {
        return codec_json_foreign_line(ev, ctx->line, ctx->line_cap);
    }
    if (ev->kind == CODEC_EVENT_SKIP) {
        return codec_json_skip_line(ev->offset, ctx->hist + (size_t)(ev->offset - ctx->hist_base),
                                    (size_t)ev->length, ctx->line, ctx->line_cap);
    }
    if (ctx->decoder != k_general) {
        size_t n = ctx->other_count <= sizeof g_others / sizeof g_others[0]
                       ? codec_json_decoded_packet_line(ev->packet, (size_t)ev->length, ev->offset,
                                                        ctx->device, ctx->index, g_others, ctx->other_count,
                                                        ctx->line, ctx->line_cap)
                       : 0;
        if (n == 0 && !ctx->mismatch) {
            ctx->mismatch = ev->offset + 1;
        }
        return n;
    }
    return codec_json_packet_line(ev->packet, (size_t)ev->length, ev->offset, ctx->device, ctx->line,
                                  ctx->line_cap);
}

static void on_event(void *arg, const codec_event_t *ev) {
    decode_ctx_t *ctx = (decode_ctx_t *)arg;
    size_t need;
    if (ctx->failed || ctx->write_err) {
        return;
    }
    if (ev->kind == CODEC_EVENT_SKIP && ctx->skip_open) {
        put_hex(ctx, ctx->skip_done, ev->offset + ev->length);
        tool_put("\"}\n", 3, &ctx->write_err);
        ctx->skip_open = 0;
        return;
    }
    if (ev->kind == CODEC_EVENT_PACKET && ctx->decoder != k_general) {
        ctx->other_count = 0;
        ctx->index = ctx->decoder == k_cached
                         ? codec_decode_packet_cached(&g_cache, ev->packet, &g_packet, keep_other, ctx)
                         : codec_decode_packet(ev->packet, &g_packet, keep_other, ctx);
    }
    need = format(ctx, ev);
    if (ctx->mismatch) {
        return;
    }
    if (need >= ctx->line_cap) {
        if (grow(ctx, need)) {
            return;
        }
        need = format(ctx, ev);
    }
    if (ctx->samples && ev->kind == CODEC_EVENT_PACKET) {
        codec_sample_info_t info;
        const char *at = strstr(ctx->line, ",\"fields\":");
        if (at && codec_sample_tracker_feed(&ctx->tracker, ev->packet, (size_t)ev->length, &info)) {
            char number[40];
            size_t head = (size_t)(at - ctx->line);
            int k = snprintf(number, sizeof number, ",\"sample\":%llu", (unsigned long long)info.number);
            tool_put(ctx->line, head, &ctx->write_err);
            tool_put(number, (size_t)k, &ctx->write_err);
            tool_put(at, need - head, &ctx->write_err);
            tool_put("\n", 1, &ctx->write_err);
            return;
        }
    }
    ctx->line[need] = '\n';
    tool_put(ctx->line, need + 1, &ctx->write_err);
}

/* After a block: a long pending skip run is printed so far, then the bytes the parser has
 * decided on are dropped. */
static void trim(decode_ctx_t *ctx, const codec_parser_t *parser) {
    uint64_t keep = parser->skip_count ? parser->skip_offset : parser->base;
    size_t drop;
    if (parser->skip_count && (ctx->skip_open || parser->skip_count > k_skip_spill) && !ctx->write_err) {
        uint64_t end = parser->skip_offset + parser->skip_count; /* the pending run so far */
        if (!ctx->skip_open) {
            char head[64];
            int k = snprintf(head, sizeof head, "{\"offset\":%llu,\"skipped\":\"",
                             (unsigned long long)parser->skip_offset);
            tool_put(head, (size_t)k, &ctx->write_err);
            ctx->skip_open = 1;
            ctx->skip_done = parser->skip_offset;
        }
        put_hex(ctx, ctx->skip_done, end);
        ctx->skip_done = end;
        keep = end;
    }
    drop = (size_t)(keep - ctx->hist_base);
    if (drop > 0) {
        memmove(ctx->hist, ctx->hist + drop, ctx->hist_len - drop);
        ctx->hist_len -= drop;
        ctx->hist_base = keep;
    }
}

/* The device ids the spec names, each after a space (devices are numbered from 1 up). */
static void print_device_ids(FILE *out) {
    int d;
    const char *id;
    for (d = 1; (id = codec_device_id((codec_device_t)d)) != NULL; d++) {
        fprintf(out, " %s", id);
    }
}

static int usage_error(const char *what) {
    fprintf(stderr, "%s: %s\n%s", k_prog, what, k_usage);
    return 2;
}

/* Decodes `in` to stdout; returns the exit status. */
static int run(decode_ctx_t *ctx, FILE *in, const char *name) {
    codec_parser_t parser;
    const int flush_blocks = !tool_stdout_is_file();
    codec_parser_init(&parser);
    codec_layout_cache_init(&g_cache);
    codec_sample_tracker_init(&ctx->tracker);
    for (;;) {
        long n;
        if (ctx->hist_cap - ctx->hist_len < k_block) {
            size_t cap = ctx->hist_len + k_block;
            unsigned char *bigger = (unsigned char *)realloc(ctx->hist, cap);
            if (!bigger) {
                ctx->failed = 1;
                break;
            }
            ctx->hist = bigger;
            ctx->hist_cap = cap;
        }
        n = tool_read(in, ctx->hist + ctx->hist_len, k_block);
        if (n < 0) {
            int err = errno;
            tool_flush(&ctx->write_err);
            if (ctx->write_err) {
                return tool_write_error(k_prog, ctx->write_err);
            }
            return tool_read_error(k_prog, name, err);
        }
        if (n == 0) {
            break;
        }
        ctx->hist_len += (size_t)n;
        codec_parser_feed(&parser, ctx->hist + ctx->hist_len - (size_t)n, (size_t)n, on_event, ctx);
        trim(ctx, &parser);
        if (flush_blocks) {
            tool_flush(&ctx->write_err);
        }
        if (ctx->write_err) {
            return tool_write_error(k_prog, ctx->write_err);
        }
        if (ctx->failed || ctx->mismatch) {
            break;
        }
    }
    if (!ctx->failed && !ctx->mismatch) {
        codec_parser_flush(&parser, on_event, ctx);
    }
    if (ctx->mismatch) {
        tool_flush(&ctx->write_err);
        fprintf(stderr,
                "%s: the %s decoder's fields and passed-on entries of the packet at offset %llu do not make "
                "up its entries\n",
                k_prog, ctx->decoder == k_cached ? "cached" : "straight",
                (unsigned long long)(ctx->mismatch - 1));
        return 1;
    }
    if (ctx->failed) {
        fprintf(stderr, "%s: out of memory\n", k_prog);
        return 2;
    }
    tool_flush(&ctx->write_err);
    if (ctx->write_err) {
        return tool_write_error(k_prog, ctx->write_err);
    }
    return 0;
}

int main(int argc, char **argv) {
    const char *path = NULL;
    decode_ctx_t ctx;
    FILE *in = stdin;
    int i;
    int status;
    memset(&ctx, 0, sizeof ctx);
    ctx.device = CODEC_DEVICE_ANY;
    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *id = NULL;
        if (strcmp(a, "--samples") == 0) {
            ctx.samples = 1;
        } else if (strcmp(a, "--device") == 0) {
            if (i + 1 >= argc) {
                return usage_error("--device needs a device id");
            }
            id = argv[++i];
        } else if (strncmp(a, "--device=", 9) == 0) {
            id = a + 9;
        } else if (strcmp(a, "--decoder") == 0 || strncmp(a, "--decoder=", 10) == 0) {
            const char *name = a[9] == '=' ? a + 10 : (i + 1 < argc ? argv[++i] : NULL);
            if (!name) {
                return usage_error("--decoder needs general, straight or cached");
            }
            if (strcmp(name, "general") == 0) {
                ctx.decoder = k_general;
            } else if (strcmp(name, "straight") == 0) {
                ctx.decoder = k_straight;
            } else if (strcmp(name, "cached") == 0) {
                ctx.decoder = k_cached;
            } else {
                fprintf(stderr, "%s: unknown decoder '%s' (expected general, straight or cached)\n%s", k_prog,
                        name, k_usage);
                return 2;
            }
        } else if (strcmp(a, "-h") == 0 || strcmp(a, "--help") == 0) {
            fputs(k_usage, stdout);
            return 0;
        } else if (a[0] == '-' && a[1] != '\0') {
            fprintf(stderr, "%s: unknown option %s\n%s", k_prog, a, k_usage);
            return 2;
        } else if (path) {
            return usage_error("only one input file");
        } else {
            path = a;
        }
        if (id && !codec_device_from_id(id, &ctx.device)) {
            fprintf(stderr, "%s: unknown device '%s' (expected one of:", k_prog, id);
            print_device_ids(stderr);
            fputs(")\n", stderr);
            return 2;
        }
    }
    if (path && strcmp(path, "-") != 0) {
        in = fopen(path, "rb");
        if (!in) {
            fprintf(stderr, "%s: cannot open %s: %s\n", k_prog, path, strerror(errno));
            return 2;
        }
    }
    tool_binary_stdio();
    setvbuf(stdout, NULL, _IOFBF, k_block);
    ctx.line_cap = 65536;
    ctx.line = (char *)malloc(ctx.line_cap);
    if (!ctx.line) {
        fprintf(stderr, "%s: out of memory\n", k_prog);
        status = 2;
    } else {
        status = run(&ctx, in, path && strcmp(path, "-") != 0 ? path : "standard input");
    }
    if (in != stdin) {
        fclose(in);
    }
    free(ctx.line);
    free(ctx.hist);
    return status;
}
