/* mscipcodec-decode [--device ID] [--samples] [FILE|-]: binary stream -> canonical JSON lines
 * (docs/conformance.md section 5). Generated: do not edit. */
#include "mscipcodec/json.h"
#include "mscipcodec/parser.h"
#include "mscipcodec/samples.h"
#include "read_all.h"

static const char k_usage[] = "usage: mscipcodec-decode [--device ID] [--samples] [FILE|-]\n";

typedef struct {
    const unsigned char *input;
    mscipc_device_t device;
    char *line;
    size_t line_cap;
    int failed;
    int samples;
    mscipc_sample_tracker_t tracker;
} decode_ctx_t;

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

/* The line of an event into ctx->line; returns its full length. */
static size_t format(decode_ctx_t *ctx, const mscipc_event_t *ev) {
    if (ev->kind == MSCIPC_EVENT_SKIP) {
        return mscipc_json_skip_line(ev->offset, ctx->input + (size_t)ev->offset, (size_t)ev->length,
                                     ctx->line, ctx->line_cap);
    }
    return mscipc_json_packet_line(ev->packet, (size_t)ev->length, ev->offset, ctx->device, ctx->line,
                                   ctx->line_cap);
}

static void on_event(void *arg, const mscipc_event_t *ev) {
    decode_ctx_t *ctx = (decode_ctx_t *)arg;
    size_t need;
    if (ctx->failed) {
        return;
    }
    need = format(ctx, ev);
    if (need >= ctx->line_cap) {
        if (grow(ctx, need)) {
            return;
        }
        need = format(ctx, ev);
    }
    if (ctx->samples && ev->kind == MSCIPC_EVENT_PACKET) {
        mscipc_sample_info_t info;
        const char *at = strstr(ctx->line, ",\"fields\":");
        if (at && mscipc_sample_tracker_feed(&ctx->tracker, ev->packet, (size_t)ev->length, &info)) {
            size_t head = (size_t)(at - ctx->line);
            fwrite(ctx->line, 1, head, stdout);
            fprintf(stdout, ",\"sample\":%llu", (unsigned long long)info.number);
            fwrite(at, 1, need - head, stdout);
            fputc('\n', stdout);
            return;
        }
    }
    fwrite(ctx->line, 1, need, stdout);
    fputc('\n', stdout);
}

/* The device ids the spec names, each after a space (devices are numbered from 1 up). */
static void print_device_ids(FILE *out) {
    int d;
    const char *id;
    for (d = 1; (id = mscipc_device_id((mscipc_device_t)d)) != NULL; d++) {
        fprintf(out, " %s", id);
    }
}

static int usage_error(const char *what) {
    fprintf(stderr, "mscipcodec-decode: %s\n%s", what, k_usage);
    return 2;
}

int main(int argc, char **argv) {
    const char *path = NULL;
    decode_ctx_t ctx;
    mscipc_parser_t parser;
    unsigned char *input;
    size_t len = 0;
    FILE *in = stdin;
    int i;
    memset(&ctx, 0, sizeof ctx);
    ctx.device = MSCIPC_DEVICE_ANY;
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
        } else if (strcmp(a, "-h") == 0 || strcmp(a, "--help") == 0) {
            fputs(k_usage, stdout);
            return 0;
        } else if (a[0] == '-' && a[1] != '\0') {
            fprintf(stderr, "mscipcodec-decode: unknown option %s\n%s", a, k_usage);
            return 2;
        } else if (path) {
            return usage_error("only one input file");
        } else {
            path = a;
        }
        if (id && !mscipc_device_from_id(id, &ctx.device)) {
            fprintf(stderr, "mscipcodec-decode: unknown device '%s' (expected one of:", id);
            print_device_ids(stderr);
            fputs(")\n", stderr);
            return 2;
        }
    }
    if (path && strcmp(path, "-") != 0) {
        in = fopen(path, "rb");
        if (!in) {
            fprintf(stderr, "mscipcodec-decode: cannot open %s\n", path);
            return 2;
        }
    }
    input = read_all(in, &len);
    if (in != stdin) {
        fclose(in);
    }
    if (!input) {
        fprintf(stderr, "mscipcodec-decode: cannot read %s\n", path ? path : "standard input");
        return 2;
    }
    ctx.input = input;
    ctx.line_cap = 65536;
    ctx.line = (char *)malloc(ctx.line_cap);
    if (!ctx.line) {
        free(input);
        fprintf(stderr, "mscipcodec-decode: out of memory\n");
        return 2;
    }
    mscipc_parser_init(&parser);
    mscipc_sample_tracker_init(&ctx.tracker);
    mscipc_parser_feed(&parser, input, len, on_event, &ctx);
    mscipc_parser_flush(&parser, on_event, &ctx);
    free(ctx.line);
    free(input);
    if (ctx.failed) {
        fprintf(stderr, "mscipcodec-decode: out of memory\n");
        return 2;
    }
    if (fflush(stdout) != 0 || ferror(stdout)) {
        fprintf(stderr, "mscipcodec-decode: cannot write the output\n");
        return 2;
    }
    return 0;
}
