/* mipcodec-session --connect ADDRESS [--timeout-ms N] [--device ID] [--baud N] [--auto-baud]
 * [--reconnect-ms N]: the session conformance tool of docs/conformance.md section 8. Reads command
 * packets as canonical JSON lines on stdin (or {"link": "idle"}: get the device to idle; {"link":
 * "listen", "ms": M}: receive for M ms), runs them
 * in order over the connection and prints one result line per command; every other packet received
 * (and every skip run) is printed as its canonical line, in arrival order. The steps of getting
 * through (a baud rate searched, a lost port reopened) are "link: ..." lines on stderr.
 * Exit 0 when every line ran, 1 when a line was bad (reported on stderr with its number and
 * skipped), 2 for usage or connection errors. Generated: do not edit. */
#if !defined(_POSIX_C_SOURCE) || _POSIX_C_SOURCE < 200809L
#undef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L
#endif
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mipcodec/json.h"
#include "mipcodec/link.h"
#include "mipcodec/native_transport.h"

#define PROG "mipcodec-session"
#define USAGE                                                                                                \
    "usage: session --connect ADDRESS [--timeout-ms N] [--device ID] [--baud N] [--auto-baud] "              \
    "[--reconnect-ms N]"

typedef struct {
    mipc_device_t device;
    uint8_t *received; /* the bytes received from stream offset received_base on that the parser has
                          not decided on yet (skip lines print theirs) */
    size_t received_len;
    size_t received_cap;
    uint64_t received_base;
    const mipc_parser_t *parser;
    int failed;
} tool_t;

static char g_line[64 * 1024];

static void print_line(size_t n) {
    if (n >= sizeof g_line) {
        n = sizeof g_line - 1;
    }
    fwrite(g_line, 1, n, stdout);
    fputc('\n', stdout);
    fflush(stdout);
}

static void on_event(void *ctx, const mipc_session_event_t *ev) {
    tool_t *tool = (tool_t *)ctx;
    size_t n;
    if (ev->kind == MIPC_SESSION_RESULT) {
        n = mipc_json_result_line(ev->result, ev->result->tag, tool->device, g_line, sizeof g_line);
    } else if (ev->kind == MIPC_SESSION_PACKET) {
        n = mipc_json_packet_line(ev->stream->packet, (size_t)ev->stream->length, ev->stream->offset,
                                  tool->device, g_line, sizeof g_line);
    } else {
        uint64_t off = ev->stream->offset;
        uint64_t len = ev->stream->length;
        const uint8_t *bytes =
            off >= tool->received_base && off - tool->received_base + len <= tool->received_len
                ? tool->received + (off - tool->received_base)
                : NULL;
        n = mipc_json_skip_line(off, bytes, bytes ? (size_t)len : 0, g_line, sizeof g_line);
    }
    print_line(n);
}

/* The transport, recording what it reads (skip lines print the bytes). */
typedef struct {
    mipc_transport_t inner;
    tool_t *tool;
} recorder_t;

static int rec_read(void *ctx, uint8_t *buf, size_t cap, uint32_t timeout_ms) {
    recorder_t *r = (recorder_t *)ctx;
    tool_t *t = r->tool;
    int n;
    /* the bytes before the parser's pending skip run and buffered candidate are printed already:
     * dropped, so that the recording stays bounded while data streams */
    uint64_t keep = t->parser->skip_count > 0 ? t->parser->skip_offset : t->parser->base;
    if (keep > t->received_base) {
        size_t drop = (size_t)(keep - t->received_base);
        drop = drop < t->received_len ? drop : t->received_len;
        memmove(t->received, t->received + drop, t->received_len - drop);
        t->received_len -= drop;
        t->received_base += drop;
    }
    n = r->inner.read(r->inner.ctx, buf, cap, timeout_ms);
    if (n > 0) {
        if (t->received_len + (size_t)n > t->received_cap) {
            size_t cap2 = (t->received_cap + (size_t)n) * 2;
            uint8_t *p = (uint8_t *)realloc(t->received, cap2);
            if (p == NULL) {
                fprintf(stderr, PROG ": out of memory\n");
                exit(2);
            }
            t->received = p;
            t->received_cap = cap2;
        }
        memcpy(t->received + t->received_len, buf, (size_t)n);
        t->received_len += (size_t)n;
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

/* The line without white space into out (cap bytes); false when it does not fit. */
static bool compact(const char *s, size_t n, char *out, size_t cap) {
    size_t i;
    size_t k = 0;
    for (i = 0; i < n; i++) {
        char c = s[i];
        if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
            continue;
        }
        if (k + 1 >= cap) {
            return false;
        }
        out[k++] = c;
    }
    out[k] = '\0';
    return true;
}

/* {"link":"idle"}: 1; {"link":"listen","ms":M} (either key first): 2 with *ms; else 0. */
static int link_line(const char *s, size_t n, unsigned long *ms) {
    char c[64];
    const char *digits = NULL;
    size_t len;
    if (!compact(s, n, c, sizeof c)) {
        return 0;
    }
    if (strcmp(c, "{\"link\":\"idle\"}") == 0) {
        return 1;
    }
    if (strncmp(c, "{\"link\":\"listen\",\"ms\":", 22) == 0) {
        digits = c + 22;
        len = strlen(digits);
        if (len < 2 || digits[len - 1] != '}') {
            return 0;
        }
        c[strlen(c) - 1] = '\0';
    } else if (strncmp(c, "{\"ms\":", 6) == 0) {
        char *end = strchr(c + 6, ',');
        if (end == NULL || strcmp(end, ",\"link\":\"listen\"}") != 0) {
            return 0;
        }
        *end = '\0';
        digits = c + 6;
    } else {
        return 0;
    }
    if (digits[0] == '\0' || strspn(digits, "0123456789") != strlen(digits) || strlen(digits) > 9) {
        return 0;
    }
    *ms = strtoul(digits, NULL, 10);
    return 2;
}

static int usage_error(const char *fmt, const char *arg) {
    fprintf(stderr, PROG ": ");
    fprintf(stderr, fmt, arg);
    fprintf(stderr, " (" USAGE ")\n");
    return 2;
}

static int int_option(const char *name, const char *text, unsigned long low, unsigned long *out) {
    char *end;
    if (text[0] < '0' || text[0] > '9' || strspn(text, "0123456789") != strlen(text)) {
        fprintf(stderr, PROG ": %s needs an integer >= %lu, not '%s' (" USAGE ")\n", name, low, text);
        return -1;
    }
    *out = strtoul(text, &end, 10);
    if (*out < low || *out > 0xffffffffUL) {
        fprintf(stderr, PROG ": %s needs an integer >= %lu, not '%s' (" USAGE ")\n", name, low, text);
        return -1;
    }
    return 0;
}

/* Reads one line of any length (without its newline) into *buf; false at the end of input. */
static bool read_line(char **buf, size_t *cap, size_t *len) {
    int c;
    *len = 0;
    c = getchar();
    if (c == EOF) {
        return false;
    }
    while (c != EOF && c != '\n') {
        if (*len + 1 >= *cap) {
            size_t cap2 = *cap ? *cap * 2 : 4096;
            char *p = (char *)realloc(*buf, cap2);
            if (p == NULL) {
                fprintf(stderr, PROG ": out of memory\n");
                exit(2);
            }
            *buf = p;
            *cap = cap2;
        }
        (*buf)[(*len)++] = (char)c;
        c = getchar();
    }
    if (*buf) {
        (*buf)[*len] = '\0';
    }
    return true;
}

static bool blank(const char *s, size_t n) {
    size_t i;
    for (i = 0; i < n; i++) {
        if (s[i] != ' ' && s[i] != '\t' && s[i] != '\r' && s[i] != '\f' && s[i] != '\v') {
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

int main(int argc, char **argv) {
    const char *connect = NULL;
    unsigned long timeout_ms = MIPC_SESSION_DEFAULT_TIMEOUT_MS;
    unsigned long baud = 115200;
    unsigned long reconnect_ms = 0;
    unsigned long listen_ms = 0;
    mipc_result_kind_t kind;
    bool auto_baud = false;
    mipc_port_t port;
    mipc_link_options_t link_options;
    mipc_device_t device = MIPC_DEVICE_ANY;
    mipc_native_t posix; /* the platform's transport: POSIX, or Win32 on Windows */
    recorder_t rec;
    mipc_transport_t transport;
    mipc_session_config_t config;
    static mipc_link_t link;
    static tool_t tool;
    char *line = NULL;
    size_t cap = 0;
    size_t len;
    unsigned long number = 0;
    int status = 0;
    int i;
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
            auto_baud = true;
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
            connect = value;
        } else if (strcmp(name, "--timeout-ms") == 0) {
            if (int_option(name, value, 0, &timeout_ms)) {
                return 2;
            }
        } else if (strcmp(name, "--baud") == 0) {
            if (int_option(name, value, 1, &baud)) {
                return 2;
            }
        } else if (strcmp(name, "--reconnect-ms") == 0) {
            if (int_option(name, value, 0, &reconnect_ms)) {
                return 2;
            }
        } else if (!mipc_device_from_id(value, &device) || device == MIPC_DEVICE_ANY) {
            return usage_error("unknown device '%s'", value);
        }
    }
    if (connect == NULL) {
        return usage_error("%s", "--connect ADDRESS is required");
    }
    if (mipc_native_open(&posix, connect, baud) != MIPC_OK) {
        fprintf(stderr, PROG ": %s\n", posix.error);
        return 2;
    }
    tool.device = device;
    mipc_native_transport(&posix, &rec.inner);
    rec.tool = &tool;
    transport.ctx = &rec;
    transport.read = rec_read;
    transport.write = rec_write;
    transport.now_ms = rec_now;
    mipc_session_config_init(&config);
    config.device = device;
    config.timeout_ms = (uint32_t)timeout_ms;
    config.on_event = on_event;
    config.ctx = &tool;
    if (mipc_link_init(&link, &transport, &config) != MIPC_OK) {
        fprintf(stderr, PROG ": cannot start the session\n");
        return 2;
    }
    mipc_native_port(&posix, &port);
    mipc_link_options_init(&link_options);
    link_options.log = log_line;
    link_options.reconnect_ms = (uint32_t)reconnect_ms;
    link_options.auto_baud = auto_baud;
    mipc_link_attach(&link, &port, &link_options);
    tool.parser = &link.session.parser;
    if (auto_baud && port.set_baud != NULL) {
        kind = mipc_link_find_baud(&link);
        if (kind != MIPC_RESULT_ACK) {
            fprintf(stderr, PROG ": %s\n", kind == MIPC_RESULT_TRANSPORT ? posix.error : link.result.error);
            mipc_native_close(&posix);
            return 2;
        }
    }
    while (read_line(&line, &cap, &len)) {
        mipc_field_value_t command;
        mipc_command_facts_t facts;
        mipc_start_options_t opt;
        char msg[MIPC_ERROR_MESSAGE_MAX + 200];
        number++;
        if (!utf8_ok((const unsigned char *)line, len)) {
            fprintf(stderr, PROG ": line %lu: not UTF-8\n", number);
            status = 1;
            continue;
        }
        if (line == NULL || blank(line, len)) {
            continue;
        }
        switch (link_line(line, len, &listen_ms)) {
        case 1:
            if (mipc_link_to_idle(&link) == MIPC_RESULT_REFUSED || !link.connected) {
                fprintf(stderr, PROG ": line %lu: %s\n", number, link.result.error);
                mipc_native_close(&posix);
                return 2;
            }
            print_line(mipc_json_result_line(&link.result, number, device, g_line, sizeof g_line));
            continue;
        case 2:
            if (mipc_link_listen(&link, (uint32_t)listen_ms) < 0) {
                fprintf(stderr, PROG ": %s\n", posix.error);
                mipc_native_close(&posix);
                return 2;
            }
            printf("{\"line\":%lu,\"listened\":%lu}\n", number, listen_ms);
            fflush(stdout);
            continue;
        default:
            break;
        }
        if (mipc_json_command_line(line, len, &command, msg, sizeof msg) != MIPC_OK) {
            fprintf(stderr, PROG ": line %lu: %s\n", number, msg);
            status = 1;
            continue;
        }
        if (!mipc_command_facts(&command, &facts)) {
            const mipc_layout_info_t *info = mipc_layout_info(command.id);
            fprintf(stderr, PROG ": line %lu: %s (descriptor %u) is not a command\n", number,
                    info ? info->name : "?", info ? (unsigned)info->descriptor : 0u);
            status = 1;
            continue;
        }
        mipc_start_options_init(&opt);
        opt.tag = number;
        kind = mipc_link_run(&link, &command, &opt, NULL);
        if (kind == MIPC_RESULT_LOST && link.connected) { /* reconnected: the command was lost */
            print_line(mipc_json_result_line(&link.result, number, device, g_line, sizeof g_line));
            continue;
        }
        if (kind == MIPC_RESULT_TRANSPORT || kind == MIPC_RESULT_LOST) {
            fprintf(stderr, PROG ": %s\n", posix.error);
            mipc_native_close(&posix);
            return 2;
        }
    }
    mipc_link_close(&link);
    mipc_native_close(&posix);
    free(line);
    free(tool.received);
    return status;
}
