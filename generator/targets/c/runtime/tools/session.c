/* codec-session --connect ADDRESS [--timeout-ms N] [--device ID] [--baud N] [--auto-baud]
 * [--reconnect-ms N]: the session conformance tool of docs/conformance.md section 8. Reads command
 * packets as canonical JSON lines on stdin (or {"link": "idle"}: get the device to idle; {"link":
 * "listen", "ms": M}: receive for M ms), runs them
 * in order over the connection and prints one result line per command; every other packet received
 * (and every skip run, in pieces of at most CODEC_SESSION_SKIP_PIECE bytes) is printed as its
 * canonical line, in arrival order. The steps of getting through (a baud rate searched, a lost port
 * reopened) are "link: ..." lines on stderr.
 * Exit 0 when every line ran, 1 when a line was bad (reported on stderr with its number and
 * skipped), 2 for usage or connection errors.
 * Bounded memory whatever arrives: the bytes the parser has not decided on (one packet at most)
 * and the pending skip piece (fewer than CODEC_SESSION_SKIP_PIECE bytes) plus one read; input lines
 * of at most TOOL_LINE_MAX bytes. */
#if !defined(_POSIX_C_SOURCE) || _POSIX_C_SOURCE < 200809L
#undef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L
#endif
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "codec/json.h"
#include "codec/link.h"
#include "codec/native_transport.h"

#define PROG "codec-session"
#define USAGE                                                                                                \
    "usage: session --connect ADDRESS [--timeout-ms N] [--device ID] [--baud N] [--auto-baud] "              \
    "[--reconnect-ms N]"

/* The longest input line (without its newline); a longer one is a bad line, read past. */
#define TOOL_LINE_MAX 1048576u
#define TOOL_TIMEOUT_MAX 600000ul
#define TOOL_RECONNECT_MAX 3600000ul
#define TOOL_LISTEN_MAX 3600000ul
/* The received bytes the tool keeps: the pending skip piece, the parser's candidate, one read. */
#define TOOL_KEEP (CODEC_SESSION_SKIP_PIECE + CODEC_PARSER_CAPACITY + CODEC_LINK_READ_MAX)

typedef struct {
    codec_device_t device;
    /* the bytes received from stream offset base on that the parser has not decided on yet (the
       pending skip piece and the candidate: skip lines print theirs) and the last read */
    size_t start; /* of the kept bytes in g_kept */
    size_t len;
    uint64_t base;
    const codec_parser_t *parser;
} tool_t;

static uint8_t g_kept[TOOL_KEEP];
/* A skip line of a whole piece: {"offset":N,"skipped":"<2 x 65536 hex digits>"}. */
static char g_line[2u * CODEC_SESSION_SKIP_PIECE + 128u];
static char g_input[TOOL_LINE_MAX + 1u];

/* Prints a line formatted by fmt (which returns the full length, like snprintf): whole, however
 * long (a longer one than g_line is formatted again into a buffer of its size). */
typedef size_t (*format_fn)(const void *arg, char *out, size_t cap);

static void print_formatted(format_fn fmt, const void *arg) {
    size_t n = fmt(arg, g_line, sizeof g_line);
    if (n < sizeof g_line) {
        fwrite(g_line, 1, n, stdout);
    } else {
        char *big = (char *)malloc(n + 1);
        if (big == NULL) {
            fprintf(stderr, PROG ": out of memory\n");
            exit(2);
        }
        n = fmt(arg, big, n + 1);
        fwrite(big, 1, n, stdout);
        free(big);
    }
    fputc('\n', stdout);
    fflush(stdout);
}

typedef struct {
    const codec_result_t *result;
    uint64_t line;
    codec_device_t device;
} result_arg_t;

static size_t result_fmt(const void *arg, char *out, size_t cap) {
    const result_arg_t *a = (const result_arg_t *)arg;
    return codec_json_result_line(a->result, a->line, a->device, out, cap);
}

static void print_result(const codec_result_t *result, uint64_t line, codec_device_t device) {
    result_arg_t a;
    a.result = result;
    a.line = line;
    a.device = device;
    print_formatted(result_fmt, &a);
}

typedef struct {
    const codec_event_t *event;
    const tool_t *tool;
} stream_arg_t;

static size_t stream_fmt(const void *arg, char *out, size_t cap) {
    const stream_arg_t *a = (const stream_arg_t *)arg;
    const codec_event_t *ev = a->event;
    const tool_t *t = a->tool;
    if (ev->kind == CODEC_EVENT_PACKET) {
        return codec_json_packet_line(ev->packet, (size_t)ev->length, ev->offset, t->device, out, cap);
    }
    if (ev->kind == CODEC_EVENT_NMEA || ev->kind == CODEC_EVENT_RTCM) {
        return codec_json_foreign_line(ev, out, cap);
    }
    if (ev->offset < t->base || ev->offset - t->base + ev->length > t->len) {
        /* the tool keeps every byte a skip run can report: this does not happen */
        fprintf(stderr, PROG ": internal error: skipped bytes at offset %llu not kept\n",
                (unsigned long long)ev->offset);
        exit(2);
    }
    return codec_json_skip_line(ev->offset, g_kept + t->start + (size_t)(ev->offset - t->base),
                                (size_t)ev->length, out, cap);
}

static void on_event(void *ctx, const codec_session_event_t *ev) {
    tool_t *tool = (tool_t *)ctx;
    if (ev->kind == CODEC_SESSION_RESULT) {
        print_result(ev->result, ev->result->tag, tool->device);
    } else {
        stream_arg_t a;
        a.event = ev->stream;
        a.tool = tool;
        print_formatted(stream_fmt, &a);
    }
}

/* The transport, keeping what it reads until the parser has decided on it (skip lines print the
 * bytes). */
typedef struct {
    codec_transport_t inner;
    tool_t *tool;
} recorder_t;

static int rec_read(void *ctx, uint8_t *buf, size_t cap, uint32_t timeout_ms) {
    recorder_t *r = (recorder_t *)ctx;
    tool_t *t = r->tool;
    int n;
    /* the bytes before the parser's pending skip run and buffered candidate are printed already */
    uint64_t keep = t->parser->skip_count > 0 ? t->parser->skip_offset : t->parser->base;
    if (keep > t->base) {
        size_t drop = keep - t->base < t->len ? (size_t)(keep - t->base) : t->len;
        t->start += drop;
        t->len -= drop;
        t->base += drop;
    }
    if (t->len == 0) {
        t->start = 0;
    }
    if (cap > CODEC_LINK_READ_MAX) {
        cap = CODEC_LINK_READ_MAX;
    }
    n = r->inner.read(r->inner.ctx, buf, cap, timeout_ms);
    if (n > 0) {
        if (t->start + t->len + (size_t)n > sizeof g_kept) {
            memmove(g_kept, g_kept + t->start, t->len);
            t->start = 0;
        }
        if (t->len + (size_t)n > sizeof g_kept) {
            fprintf(stderr, PROG ": internal error: more than %u undecided bytes\n", (unsigned)TOOL_KEEP);
            exit(2);
        }
        memcpy(g_kept + t->start + t->len, buf, (size_t)n);
        t->len += (size_t)n;
    }
    return n;
}

static int rec_write(void *ctx, const uint8_t *data, size_t len) {
    recorder_t *r = (recorder_t *)ctx;
    return r->inner.write(r->inner.ctx, data, len);
}

static uint64_t rec_now(void *ctx) {
    recorder_t *r = (recorder_t *)ctx;
    return r->inner.now_ms(r->inner.ctx);
}

static void log_line(void *ctx, const char *line) {
    (void)ctx;
    fprintf(stderr, "%s\n", line);
    fflush(stderr);
}

/* RFC 8259 white space (a line holding only these is blank). */
static bool json_space(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

/* The "ms" of a listen line: a JSON integer (no sign, fraction or exponent) from 0 to
 * TOOL_LISTEN_MAX. */
static bool listen_ms(const char *v, size_t n, unsigned long *ms) {
    size_t i;
    if (n == 0 || n > 7 || (n > 1 && v[0] == '0')) {
        return false;
    }
    *ms = 0;
    for (i = 0; i < n; i++) {
        if (v[i] < '0' || v[i] > '9') {
            return false;
        }
        *ms = *ms * 10u + (unsigned long)(v[i] - '0');
    }
    return *ms <= TOOL_LISTEN_MAX;
}

/* A scanner of one JSON object's top level, for the link lines (the command lines have their
 * own reader): keys and the text of their values. */
typedef struct {
    const char *s;
    size_t n;
    size_t pos;
} scan_t;

static void scan_ws(scan_t *sc) {
    while (sc->pos < sc->n && json_space(sc->s[sc->pos])) {
        sc->pos++;
    }
}

/* A string at pos (its quotes included); false when there is none. */
static bool scan_string(scan_t *sc) {
    if (sc->pos >= sc->n || sc->s[sc->pos] != '"') {
        return false;
    }
    for (sc->pos++; sc->pos < sc->n; sc->pos++) {
        if (sc->s[sc->pos] == '\\') {
            sc->pos++;
        } else if (sc->s[sc->pos] == '"') {
            sc->pos++;
            return true;
        }
    }
    return false;
}

/* Any value at pos (strings, nested objects and arrays matched, scalars up to a delimiter). */
static bool scan_value(scan_t *sc) {
    size_t depth = 0;
    size_t begin = sc->pos;
    while (sc->pos < sc->n) {
        char c = sc->s[sc->pos];
        if (c == '"') {
            if (!scan_string(sc)) {
                return false;
            }
            continue;
        }
        if (depth == 0 && (c == ',' || c == '}' || c == ']' || json_space(c))) {
            break;
        }
        if (c == '{' || c == '[') {
            depth++;
        } else if ((c == '}' || c == ']') && depth > 0) {
            depth--;
        }
        sc->pos++;
    }
    return depth == 0 && sc->pos > begin;
}

enum { LINK_NONE = 0, LINK_IDLE = 1, LINK_LISTEN = 2, LINK_BAD_MS = 3, LINK_BAD = 4 };

static bool token_is(const char *s, size_t begin, size_t end, const char *text) {
    return end - begin == strlen(text) && memcmp(s + begin, text, end - begin) == 0;
}

/* A line that is one JSON object with a top-level "link" key: {"link":"idle"}: LINK_IDLE;
 * {"link":"listen","ms":M} (either key first): LINK_LISTEN with *ms, LINK_BAD_MS when M is not an
 * integer from 0 to TOOL_LISTEN_MAX; any other: LINK_BAD. LINK_NONE without a "link" key or when
 * it is not such an object (a command line; its reader reports what is wrong). */
static int link_line(const char *s, size_t n, unsigned long *ms) {
    scan_t sc;
    size_t link_at = 0;
    size_t link_end = 0;
    size_t ms_at = 0;
    size_t ms_end = 0;
    size_t keys = 0;
    bool have_link = false;
    bool have_ms = false;
    sc.s = s;
    sc.n = n;
    sc.pos = 0;
    scan_ws(&sc);
    if (sc.pos >= n || s[sc.pos] != '{') {
        return LINK_NONE;
    }
    sc.pos++;
    scan_ws(&sc);
    if (sc.pos < n && s[sc.pos] == '}') {
        return LINK_NONE;
    }
    for (;;) {
        size_t key;
        size_t key_end;
        size_t value;
        scan_ws(&sc);
        key = sc.pos;
        if (!scan_string(&sc)) {
            return LINK_NONE;
        }
        key_end = sc.pos;
        scan_ws(&sc);
        if (sc.pos >= n || s[sc.pos] != ':') {
            return LINK_NONE;
        }
        sc.pos++;
        scan_ws(&sc);
        value = sc.pos;
        if (!scan_value(&sc)) {
            return LINK_NONE;
        }
        keys++;
        if (token_is(s, key, key_end, "\"link\"")) {
            have_link = true;
            link_at = value;
            link_end = sc.pos;
        } else if (token_is(s, key, key_end, "\"ms\"")) {
            have_ms = true;
            ms_at = value;
            ms_end = sc.pos;
        }
        scan_ws(&sc);
        if (sc.pos < n && s[sc.pos] == ',') {
            sc.pos++;
            continue;
        }
        if (sc.pos < n && s[sc.pos] == '}') {
            sc.pos++;
            break;
        }
        return LINK_NONE;
    }
    scan_ws(&sc);
    if (sc.pos != n || !have_link) {
        return LINK_NONE;
    }
    if (keys == 1 && token_is(s, link_at, link_end, "\"idle\"")) {
        return LINK_IDLE;
    }
    if (keys == 2 && have_ms && token_is(s, link_at, link_end, "\"listen\"")) {
        return listen_ms(s + ms_at, ms_end - ms_at, ms) ? LINK_LISTEN : LINK_BAD_MS;
    }
    return LINK_BAD;
}

static int usage_error(const char *fmt, const char *arg) {
    fprintf(stderr, PROG ": ");
    fprintf(stderr, fmt, arg);
    fprintf(stderr, " (" USAGE ")\n");
    return 2;
}

/* A decimal integer of ASCII digits only (leading zeros allowed) from low to high. */
static bool decimal(const char *text, unsigned long low, unsigned long high, unsigned long *out) {
    const char *p = text;
    unsigned long v = 0;
    if (*p == '\0') {
        return false;
    }
    for (; *p != '\0'; p++) {
        if (*p < '0' || *p > '9') {
            return false;
        }
        if (v > high) {
            continue; /* out of range already: only the digits are still checked */
        }
        v = v * 10u + (unsigned long)(*p - '0');
    }
    *out = v;
    return v >= low && v <= high;
}

/* The baud rates of the protocol's devices (the IR's link.baud_rates, every model), ascending,
 * each once. Returns how many. */
static size_t baud_rates(uint32_t *out, size_t cap) {
    size_t n = 0;
    unsigned d;
    for (d = 1u; d < 32u && codec_device_id((codec_device_t)d) != NULL; d++) {
        size_t k = 0;
        size_t i;
        const uint32_t *rates = codec_device_baud_rates((codec_device_t)d, &k);
        for (i = 0; i < k; i++) {
            size_t j;
            bool seen = false;
            for (j = 0; j < n && !seen; j++) {
                seen = out[j] == rates[i];
            }
            if (seen || n == cap) {
                continue;
            }
            for (j = n++; j > 0 && out[j - 1] > rates[i]; j--) {
                out[j] = out[j - 1];
            }
            out[j] = rates[i];
        }
    }
    return n;
}

static bool baud_option(const char *text, unsigned long *baud) {
    uint32_t rates[CODEC_LINK_MAX_BAUD_RATES * 4];
    size_t n = baud_rates(rates, sizeof rates / sizeof rates[0]);
    size_t i;
    unsigned long v = 0;
    if (decimal(text, 1, 0xffffffffUL, &v)) {
        for (i = 0; i < n; i++) {
            if (rates[i] == v) {
                *baud = v;
                return true;
            }
        }
    }
    fprintf(stderr, PROG ": --baud: %s is not a baud rate of %s devices (", text, CODEC_PROTOCOL_NAME);
    for (i = 0; i < n; i++) {
        fprintf(stderr, "%s%lu", i ? ", " : "", (unsigned long)rates[i]);
    }
    fprintf(stderr, ")\n");
    return false;
}

/* One input line (without its newline) into g_input: 1 with *len, 0 at the end of input, -1 for
 * a line longer than TOOL_LINE_MAX (read past, not kept). */
static int read_line(size_t *len) {
    int c = getchar();
    size_t n = 0;
    bool too_long = false;
    if (c == EOF) {
        return 0;
    }
    while (c != EOF && c != '\n') {
        if (n < TOOL_LINE_MAX) {
            g_input[n++] = (char)c;
        } else {
            too_long = true;
        }
        c = getchar();
    }
    g_input[n] = '\0';
    *len = n;
    return too_long ? -1 : 1;
}

static bool blank(const char *s, size_t n) {
    size_t i;
    for (i = 0; i < n; i++) {
        if (!json_space(s[i])) {
            return false;
        }
    }
    return true;
}

/* Strict UTF-8 (no overlong forms, surrogates or values past U+10FFFF). */
static bool utf8_ok(const unsigned char *s, size_t n) {
    size_t i = 0;
    while (i < n) {
        unsigned c = s[i];
        size_t k;
        unsigned v;
        unsigned min;
        if (c < 0x80) {
            i++;
            continue;
        }
        if (c >= 0xC2 && c <= 0xDF) {
            k = 1, v = c & 0x1Fu, min = 0x80;
        } else if (c >= 0xE0 && c <= 0xEF) {
            k = 2, v = c & 0x0Fu, min = 0x800;
        } else if (c >= 0xF0 && c <= 0xF4) {
            k = 3, v = c & 0x07u, min = 0x10000;
        } else {
            return false;
        }
        for (size_t j = 1; j <= k; j++) {
            if (i + j >= n || (s[i + j] & 0xC0u) != 0x80u) {
                return false;
            }
            v = (v << 6) | (s[i + j] & 0x3Fu);
        }
        if (v < min || v > 0x10FFFF || (v >= 0xD800 && v <= 0xDFFF)) {
            return false;
        }
        i += k + 1;
    }
    return true;
}

/* The command line's options. */
typedef struct {
    const char *connect;
    unsigned long timeout_ms;
    unsigned long baud;
    unsigned long reconnect_ms;
    bool auto_baud;
    codec_device_t device;
} args_t;

#define ARGS_READ (-1)

/* Every option checked before anything is opened or sent (docs/conformance.md section 8, the
 * option table: exit status 2 and one line): ARGS_READ, or the exit status. */
static int read_args(int argc, char **argv, args_t *args) {
    int i;
    args->connect = NULL;
    args->timeout_ms = CODEC_SESSION_DEFAULT_TIMEOUT_MS;
    args->baud = 115200;
    args->reconnect_ms = 0;
    args->auto_baud = false;
    args->device = CODEC_DEVICE_ANY;
    for (i = 1; i < argc; i++) {
        if (strcmp(argv[i], "-h") == 0 || strcmp(argv[i], "--help") == 0) {
            printf("%s\n", USAGE);
            return 0;
        }
    }
    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *eq = strchr(a, '=');
        char name[32];
        const char *value;
        size_t n = eq ? (size_t)(eq - a) : strlen(a);
        if (strcmp(a, "--auto-baud") == 0) {
            args->auto_baud = true;
            continue;
        }
        if (n >= sizeof name) {
            return usage_error("unknown argument '%s'", a);
        }
        memcpy(name, a, n);
        name[n] = '\0';
        if (strcmp(name, "--connect") != 0 && strcmp(name, "--timeout-ms") != 0 &&
            strcmp(name, "--device") != 0 && strcmp(name, "--baud") != 0 &&
            strcmp(name, "--reconnect-ms") != 0) {
            return usage_error("unknown argument '%s'", a);
        }
        if (eq) {
            value = eq + 1;
        } else if (i + 1 < argc) {
            value = argv[++i];
        } else {
            return usage_error("%s needs a value", name);
        }
        if (strcmp(name, "--connect") == 0) {
            args->connect = value;
        } else if (strcmp(name, "--timeout-ms") == 0) {
            if (!decimal(value, 1, TOOL_TIMEOUT_MAX, &args->timeout_ms)) {
                fprintf(stderr, PROG ": --timeout-ms: expected an integer from 1 to %lu, got %s\n",
                        TOOL_TIMEOUT_MAX, value);
                return 2;
            }
        } else if (strcmp(name, "--baud") == 0) {
            if (!baud_option(value, &args->baud)) {
                return 2;
            }
        } else if (strcmp(name, "--reconnect-ms") == 0) {
            if (!decimal(value, 1, TOOL_RECONNECT_MAX, &args->reconnect_ms)) {
                fprintf(stderr, PROG ": --reconnect-ms: expected an integer from 1 to %lu, got %s\n",
                        TOOL_RECONNECT_MAX, value);
                return 2;
            }
        } else if (!codec_device_from_id(value, &args->device) || args->device == CODEC_DEVICE_ANY) {
            return usage_error("unknown device '%s'", value);
        }
    }
    if (args->connect == NULL) {
        fprintf(stderr, PROG ": --connect ADDRESS is required\n");
        return 2;
    }
    return ARGS_READ;
}

/* One input line, not blank and UTF-8: 0 done, 1 a bad line (reported, the next one runs), 2 the
 * connection is gone (reported: the tool stops). */
static int run_line(codec_link_t *link, const codec_native_t *posix, const char *line, size_t len,
                    unsigned long number, codec_device_t device) {
    codec_field_value_t command;
    codec_command_facts_t facts;
    codec_start_options_t opt;
    codec_result_kind_t kind;
    char msg[CODEC_ERROR_MESSAGE_MAX + 200];
    unsigned long ms = 0;
    switch (link_line(line, len, &ms)) {
    case LINK_IDLE:
        if (codec_link_to_idle(link) == CODEC_RESULT_REFUSED || !link->connected) {
            fprintf(stderr, PROG ": line %lu: %s\n", number, link->result.error);
            return 2;
        }
        print_result(&link->result, number, device);
        return 0;
    case LINK_LISTEN:
        if (codec_link_listen(link, (uint32_t)ms) < 0) {
            fprintf(stderr, PROG ": %s\n", posix->error);
            return 2;
        }
        printf("{\"line\":%lu,\"listened\":%lu}\n", number, ms);
        fflush(stdout);
        return 0;
    case LINK_BAD_MS:
        fprintf(stderr, PROG ": line %lu: \"ms\" must be an integer from 0 to %lu\n", number,
                TOOL_LISTEN_MAX);
        return 1;
    case LINK_BAD:
        fprintf(stderr, PROG ": line %lu: expected {\"link\":\"idle\"} or {\"link\":\"listen\",\"ms\":M}\n",
                number);
        return 1;
    default:
        break;
    }
    if (codec_json_command_line(line, len, &command, msg, sizeof msg) != CODEC_OK) {
        fprintf(stderr, PROG ": line %lu: %s\n", number, msg);
        return 1;
    }
    if (!codec_command_facts(&command, &facts)) {
        const codec_layout_info_t *info = codec_layout_info(command.id);
        fprintf(stderr, PROG ": line %lu: %s (descriptor %u) is not a command\n", number,
                info ? info->name : "?", info ? (unsigned)info->descriptor : 0u);
        return 1;
    }
    codec_start_options_init(&opt);
    opt.tag = number;
    kind = codec_link_run(link, &command, &opt, NULL);
    if (link->note[0] != '\0') { /* the first unknown-command NACK: the connected model is another one */
        fprintf(stderr, PROG ": %s\n", link->note);
        fflush(stderr);
    }
    if (kind == CODEC_RESULT_LOST && link->connected) { /* reconnected: the command was lost */
        print_result(&link->result, number, device);
        return 0;
    }
    if (kind == CODEC_RESULT_TRANSPORT || kind == CODEC_RESULT_LOST) {
        fprintf(stderr, PROG ": %s\n", posix->error);
        return 2;
    }
    return 0;
}

int main(int argc, char **argv) {
    args_t args;
    codec_result_kind_t kind;
    codec_port_t port;
    codec_link_options_t link_options;
    codec_native_t posix; /* the platform's transport: POSIX, or Win32 on Windows */
    recorder_t rec;
    codec_transport_t transport;
    codec_session_config_t config;
    static codec_link_t link;
    static tool_t tool;
    size_t len = 0;
    int got;
    unsigned long number = 0;
    int status = read_args(argc, argv, &args);
    if (status != ARGS_READ) {
        return status;
    }
    status = 0;
    if (codec_native_open(&posix, args.connect, args.baud) != CODEC_OK) {
        fprintf(stderr, PROG ": %s\n", posix.error);
        return 2;
    }
    tool.device = args.device;
    codec_native_transport(&posix, &rec.inner);
    rec.tool = &tool;
    transport.ctx = &rec;
    transport.read = rec_read;
    transport.write = rec_write;
    transport.now_ms = rec_now;
    codec_session_config_init(&config);
    config.device = args.device;
    config.timeout_ms = (uint32_t)args.timeout_ms;
    config.on_event = on_event;
    config.ctx = &tool;
    if (codec_link_init(&link, &transport, &config) != CODEC_OK) {
        fprintf(stderr, PROG ": cannot start the session\n");
        return 2;
    }
    codec_native_port(&posix, &port);
    codec_link_options_init(&link_options);
    link_options.log = log_line;
    link_options.reconnect_ms = (uint32_t)args.reconnect_ms;
    link_options.auto_baud = args.auto_baud;
    codec_link_attach(&link, &port, &link_options);
    tool.parser = &link.session.parser;
    if (args.auto_baud && port.set_baud != NULL) {
        kind = codec_link_find_baud(&link);
        if (kind != CODEC_RESULT_ACK) {
            fprintf(stderr, PROG ": %s\n", kind == CODEC_RESULT_TRANSPORT ? posix.error : link.result.error);
            codec_native_close(&posix);
            return 2;
        }
    }
    while ((got = read_line(&len)) != 0) {
        int outcome;
        number++;
        if (got < 0) {
            fprintf(stderr, PROG ": line %lu: longer than %u bytes\n", number, (unsigned)TOOL_LINE_MAX);
            status = 1;
            continue;
        }
        if (!utf8_ok((const unsigned char *)g_input, len)) {
            fprintf(stderr, PROG ": line %lu: not UTF-8\n", number);
            status = 1;
            continue;
        }
        if (blank(g_input, len)) {
            continue;
        }
        outcome = run_line(&link, &posix, g_input, len, number, args.device);
        if (outcome == 2) {
            codec_native_close(&posix);
            return 2;
        }
        status = outcome ? outcome : status;
    }
    codec_link_close(&link);
    codec_native_close(&posix);
    return status;
}
