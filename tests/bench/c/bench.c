/* Benchmark of the generated C package mipcodec (issue 8): a plain timed loop.
 *
 *   bench DIR [--passes N] [--stream NAME] [--mode MODE]
 *
 * For every stream DIR/<name>.bin (with its sidecar DIR/<name>.json) it times, best of N passes
 * over the whole file in memory (read once, not timed):
 *   mode=bulk    one memcpy of the whole stream into another buffer (allocated and written once
 *                before timing): every byte read and written once, the limit the parsers' rows
 *                are divided by (tests/bench/run.py)
 *   mode=frame   mipc_parser_feed + flush: every packet reported, garbage skipped
 *   mode=decode  the same, plus the typed decode of every field: mipc_decode_packet_cached, the
 *                layout cache (one per pass, as a program has one per stream) in front of the
 *                straight-line decoder of the packet's set (issue 38; a field it leaves goes to
 *                mipc_decode_field)
 *   mode=decode-straight  the same without the cache: mipc_decode_packet for every packet
 *   mode=copy-per-packet  diagnostic only: memchr(sync byte) + memcpy of each packet into a
 *                buffer (trusts every 75 65 pair and length byte, so it does not do the parsers'
 *                work on the garbage streams; never the base of a ratio)
 *   mode=session-ingest  the stream fed to a command session (mipcodec/session.h) with a ping
 *                pending whose reply never comes: every packet routed to a per-packet handler
 *                that decodes as mode=decode
 *   mode=none    nothing (no line): with --stream, the fixed cost of the program (loading the
 *                stream) that instruction counts subtract (tests/bench/run.py --instructions)
 * and once, after the streams:
 *   lang=c stream=loopback-tcp mode=session-roundtrip  pings through the blocking API
 *                                      (mipc_base_ping over mipc_link_t and the POSIX TCP
 *                                      transport) to a forked responder that acks each one;
 *                                      packets = round trips, bytes = bytes sent + received
 * and prints one line per measurement:
 *   BENCH lang=c stream=accel_gyro mode=frame packets=N bytes=B seconds=S
 * The packet and field counts are checked against the sidecar (exit 1 on mismatch); a checksum
 * of the decoded values is printed to stderr so the work cannot be optimised away.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "mipcodec/mipcodec.h"
#include "mipcodec/posix_transport.h"

static const char *const k_streams[] = {"accel_gyro", "mixed", "accel_gyro_garbage", "mixed_garbage"};

typedef struct {
    uint8_t *data;
    size_t len;
    uint64_t packets; /* sidecar */
    uint64_t fields;
} stream_t;

typedef struct {
    uint64_t packets;
    uint64_t fields;
    uint64_t errors;
    uint64_t check;             /* consumes the decoded values */
    uint8_t set;                /* decode: the set of the packet being decoded */
    mipc_layout_cache_t *cache; /* decode: the layout cache (NULL: decode-straight) */
} counts_t;

static double now(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* The CPU time of this thread: what a pass costs, without the ticks the scheduler gives to other
 * tasks on a shared machine (a 4 ms tick lost shows as +4 ms on the wall clock; docs/benchmarks.md). */
static double cpu_now(void) {
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static int read_file(const char *path, uint8_t **data, size_t *len) {
    FILE *f = fopen(path, "rb");
    long n;
    if (!f) {
        return -1;
    }
    if (fseek(f, 0, SEEK_END) != 0 || (n = ftell(f)) < 0 || fseek(f, 0, SEEK_SET) != 0) {
        fclose(f);
        return -1;
    }
    *data = malloc((size_t)n + 1);
    if (!*data || fread(*data, 1, (size_t)n, f) != (size_t)n) {
        fclose(f);
        return -1;
    }
    fclose(f);
    *len = (size_t)n;
    return 0;
}

/* The integer value of "key": in a flat JSON object (the sidecar). */
static int json_u64(const char *json, const char *key, uint64_t *out) {
    char pat[64];
    const char *p;
    snprintf(pat, sizeof pat, "\"%s\":", key);
    p = strstr(json, pat);
    if (!p) {
        return -1;
    }
    *out = strtoull(p + strlen(pat), NULL, 10);
    return 0;
}

static int load(const char *dir, const char *name, stream_t *s) {
    char path[4096];
    uint8_t *json;
    size_t json_len;
    snprintf(path, sizeof path, "%s/%s.json", dir, name);
    if (read_file(path, &json, &json_len) != 0) {
        fprintf(stderr, "bench: cannot read %s\n", path);
        return -1;
    }
    json[json_len] = 0;
    if (json_u64((const char *)json, "packets", &s->packets) != 0 ||
        json_u64((const char *)json, "fields", &s->fields) != 0) {
        fprintf(stderr, "bench: %s has no packets/fields counts\n", path);
        free(json);
        return -1;
    }
    free(json);
    snprintf(path, sizeof path, "%s/%s.bin", dir, name);
    if (read_file(path, &s->data, &s->len) != 0) {
        fprintf(stderr, "bench: cannot read %s\n", path);
        return -1;
    }
    return 0;
}

/* ---- frame: the callback parser ---- */

static void on_frame(void *ctx, const mipc_event_t *ev) {
    counts_t *c = ctx;
    if (ev->kind == MIPC_EVENT_PACKET) {
        c->packets++;
        c->check += ev->length + ev->packet[MIPC_SET_OFFSET];
    }
}

/* ---- decode: callback parser + the straight-line decoder of the packet's set ---- */

/* The first 4 bytes of a decoded struct (the first float of scaled accel / gyro, ...), as a
 * reader of one value would load them (an 8-byte load over two 4-byte stores would stall on
 * store forwarding and measure that instead of the decoder). */
static uint32_t first_word(const void *value) {
    uint32_t word = 0;
    memcpy(&word, value, sizeof word);
    return word;
}

/* An entry the straight-line decoder leaves (a field with per-device variants, anything it
 * cannot decode): the general dispatch, as a program that handles every field would. */
static void on_other(void *ctx, const mipc_field_entry_t *e) {
    counts_t *c = ctx;
    mipc_field_value_t value;
    if (e->kind != MIPC_ENTRY_FIELD || mipc_decode_field(c->set, e->descriptor, e->data, e->length,
                                                         MIPC_DEVICE_ANY, &value, NULL) != MIPC_OK) {
        c->errors++;
        return;
    }
    c->fields++;
    c->check += (uint64_t)first_word(&value.u) ^ (uint64_t)e->descriptor;
}

static void on_decode(void *ctx, const mipc_event_t *ev) {
    static mipc_packet_t packet;
    counts_t *c = ctx;
    const mipc_packet_index_t *index;
    size_t i;
    if (ev->kind != MIPC_EVENT_PACKET) {
        return;
    }
    c->packets++;
    c->set = mipc_packet_set(ev->packet);
    index = c->cache ? mipc_decode_packet_cached(c->cache, ev->packet, &packet, on_other, c)
                     : mipc_decode_packet(ev->packet, &packet, on_other, c);
    if (index == NULL) {
        return;
    }
    c->fields += index->count;
    for (i = 0; i < index->count; i++) {
        c->check += (uint64_t)first_word(mipc_packet_value(index, i)) ^ (uint64_t)index->fields[i].descriptor;
    }
}

/* ---- bulk: one memcpy of the whole stream ---- */

/* Called through a volatile pointer so that the compiler cannot drop or split the copy. */
static void *(*volatile bulk_copy)(void *, const void *, size_t) = memcpy;

static void bulk_pass(const stream_t *s, uint8_t *into, counts_t *c) {
    bulk_copy(into, s->data, s->len);
    c->packets = s->packets;
    c->check += s->len ? into[s->len - 1] : 0;
}

/* ---- copy-per-packet (diagnostic): memchr + memcpy of each packet ---- */

static void copy_pass(const stream_t *s, counts_t *c) {
    static uint8_t buf[MIPC_MAX_PACKET];
    const uint8_t *p = s->data;
    const uint8_t *end = s->data + s->len;
    while (p + MIPC_HEADER_SIZE <= end) {
        size_t total;
        if (*p != MIPC_SYNC_0) {
            p = memchr(p, MIPC_SYNC_0, (size_t)(end - p));
        }
        if (!p || p + MIPC_HEADER_SIZE > end) {
            break;
        }
        total = MIPC_HEADER_SIZE + (size_t)p[MIPC_LENGTH_OFFSET] + MIPC_CHECKSUM_SIZE;
        if (p[1] != MIPC_SYNC_1 || total > (size_t)(end - p)) {
            p++;
            continue;
        }
        memcpy(buf, p, total);
        c->packets++;
        c->check += buf[total - 1];
        p += total;
    }
}

/* ---- session-ingest: a session with a command pending routes every packet to on_decode ---- */

static void session_pass(const stream_t *s, counts_t *c) {
    static mipc_session_t session;
    mipc_session_config_t config;
    mipc_field_value_t ping;
    mipc_started_t started;
    uint8_t packet[MIPC_MAX_PACKET];
    mipc_session_config_init(&config);
    config.timeout_ms = 0xFFFFFFFFu; /* the reply never comes, and the deadline is far away */
    mipc_session_init(&session, &config);
    mipc_session_on_packet(&session, on_decode, c);
    memset(&ping, 0, sizeof ping);
    ping.id = MIPC_FIELD_BASE_PING;
    if (mipc_session_start(&session, &ping, 0, NULL, packet, sizeof packet, &started) != MIPC_OK ||
        started.done) {
        c->errors++;
    }
    mipc_session_feed(&session, s->data, s->len, 1);
    mipc_session_close(&session, 2);
    if (mipc_session_pending(&session) != 1) {
        c->errors++;
    }
}

/* ---- session-roundtrip: pings over loopback TCP to a forked responder ---- */

/* The responder: acks every ping (75 65 01 02 02 01 E0 C6) it reads. */
static void respond(int fd) {
    static const uint8_t ack[] = {0x75, 0x65, 0x01, 0x04, 0x04, 0xF1, 0x01, 0x00, 0xD5, 0x6A};
    uint8_t buf[4096];
    size_t have = 0;
    for (;;) {
        ssize_t n = recv(fd, buf + have, sizeof buf - have, 0);
        size_t i = 0;
        if (n <= 0) {
            return;
        }
        have += (size_t)n;
        while (have - i >= 8) {
            if (send(fd, ack, sizeof ack, 0) != (ssize_t)sizeof ack) {
                return;
            }
            i += 8;
        }
        memmove(buf, buf + i, have - i);
        have -= i;
    }
}

static int roundtrip(int count, double *seconds, uint64_t *bytes) {
    struct sockaddr_in addr;
    socklen_t len = sizeof addr;
    static mipc_link_t link;
    mipc_posix_t port;
    mipc_transport_t transport;
    mipc_session_config_t config;
    char address[64];
    int srv = socket(AF_INET, SOCK_STREAM, 0);
    int one = 1;
    pid_t child;
    int i;
    int ok = 1;
    double t0;
    memset(&addr, 0, sizeof addr);
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (srv < 0 || bind(srv, (struct sockaddr *)&addr, sizeof addr) != 0 || listen(srv, 1) != 0 ||
        getsockname(srv, (struct sockaddr *)&addr, &len) != 0) {
        return -1;
    }
    child = fork();
    if (child == 0) {
        int fd = accept(srv, NULL, NULL);
        if (fd >= 0) {
            setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
            respond(fd);
        }
        _exit(0);
    }
    close(srv);
    snprintf(address, sizeof address, "tcp:127.0.0.1:%u", (unsigned)ntohs(addr.sin_port));
    if (mipc_posix_open(&port, address, 115200) != MIPC_OK) {
        fprintf(stderr, "bench: %s\n", port.error);
        kill(child, SIGTERM);
        return -1;
    }
    mipc_posix_transport(&port, &transport);
    mipc_session_config_init(&config);
    mipc_link_init(&link, &transport, &config);
    t0 = now();
    for (i = 0; i < count && ok; i++) {
        ok = mipc_base_ping(&link) == MIPC_RESULT_ACK;
    }
    *seconds = now() - t0;
    *bytes = (uint64_t)count * (8u + 10u);
    mipc_posix_close(&port);
    waitpid(child, NULL, 0);
    return ok ? 0 : -1;
}

typedef enum {
    MODE_BULK,
    MODE_FRAME,
    MODE_DECODE,
    MODE_COPY,
    MODE_SESSION,
    MODE_UNCACHED,
    MODE_COUNT
} mode_t_;

static void run_pass(const stream_t *s, uint8_t *into, mode_t_ mode, counts_t *c) {
    static mipc_layout_cache_t cache;
    mipc_parser_t parser;
    memset(c, 0, sizeof *c);
    if (mode == MODE_DECODE || mode == MODE_SESSION) {
        mipc_layout_cache_init(&cache);
        c->cache = &cache;
    }
    if (mode == MODE_BULK) {
        bulk_pass(s, into, c);
        return;
    }
    if (mode == MODE_COPY) {
        copy_pass(s, c);
        return;
    }
    if (mode == MODE_SESSION) {
        session_pass(s, c);
        return;
    }
    mipc_parser_init(&parser);
    mipc_parser_feed(&parser, s->data, s->len, mode == MODE_FRAME ? on_frame : on_decode, c);
    mipc_parser_flush(&parser, mode == MODE_FRAME ? on_frame : on_decode, c);
}

int main(int argc, char **argv) {
    static const char *const mode_names[] = {"bulk",           "frame",          "decode", "copy-per-packet",
                                             "session-ingest", "decode-straight"};
    const char *dir = NULL;
    int passes = 5;
    const char *only = NULL;
    const char *only_mode = NULL;
    int failed = 0;
    size_t si;
    int i;
    for (i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--passes") == 0 && i + 1 < argc) {
            passes = atoi(argv[++i]);
        } else if (strcmp(argv[i], "--mode") == 0 && i + 1 < argc) {
            only_mode = argv[++i];
        } else if (strcmp(argv[i], "--stream") == 0 && i + 1 < argc) {
            only = argv[++i];
        } else if (!dir) {
            dir = argv[i];
        } else {
            dir = NULL;
            break;
        }
    }
    if (!dir || passes < 1) {
        fprintf(stderr,
                "usage: bench DIR [--passes N] [--stream NAME] "
                "[--mode bulk|frame|decode|decode-straight|copy-per-packet|session-ingest|session-roundtrip|"
                "none]\n");
        return 2;
    }
    for (si = 0; si < sizeof k_streams / sizeof k_streams[0]; si++) {
        stream_t s;
        uint8_t *into;
        int m;
        if (only && strcmp(only, k_streams[si]) != 0) {
            continue;
        }
        if (load(dir, k_streams[si], &s) != 0) {
            return 1;
        }
        /* bulk's destination, written once so that no page fault is timed */
        into = malloc(s.len + 1);
        if (!into) {
            fprintf(stderr, "bench: out of memory\n");
            return 1;
        }
        memset(into, 0, s.len + 1);
        for (m = MODE_BULK; m < MODE_COUNT; m++) {
            double best = 1e30;
            counts_t c;
            int k;
            if (only_mode && strcmp(only_mode, mode_names[m]) != 0) {
                continue;
            }
            for (k = 0; k < passes; k++) {
                double t0 = cpu_now();
                double dt;
                run_pass(&s, into, (mode_t_)m, &c);
                dt = cpu_now() - t0;
                if (dt < best) {
                    best = dt;
                }
            }
            if (m != MODE_COPY && m != MODE_BULK && c.packets != s.packets) {
                fprintf(stderr, "bench: %s %s: %llu packets, the sidecar says %llu\n", k_streams[si],
                        mode_names[m], (unsigned long long)c.packets, (unsigned long long)s.packets);
                failed = 1;
            }
            if ((m == MODE_DECODE || m == MODE_SESSION || m == MODE_UNCACHED) &&
                (c.fields != s.fields || c.errors != 0)) {
                fprintf(stderr, "bench: %s %s: %llu fields (%llu errors), the sidecar says %llu\n",
                        k_streams[si], mode_names[m], (unsigned long long)c.fields,
                        (unsigned long long)c.errors, (unsigned long long)s.fields);
                failed = 1;
            }
            if (m == MODE_BULK && memcmp(into, s.data, s.len) != 0) {
                fprintf(stderr, "bench: %s bulk: the copy differs from the stream\n", k_streams[si]);
                failed = 1;
            }
            printf("BENCH lang=c stream=%s mode=%s packets=%llu bytes=%zu seconds=%.9f\n", k_streams[si],
                   mode_names[m], (unsigned long long)(m == MODE_COPY ? s.packets : c.packets), s.len, best);
            fprintf(stderr, "bench: %s %s check %016llx\n", k_streams[si], mode_names[m],
                    (unsigned long long)c.check);
            fflush(stdout);
        }
        free(into);
        free(s.data);
    }
    if (!only && (!only_mode || strcmp(only_mode, "session-roundtrip") == 0)) {
        int count = 200 * passes;
        double best = 0;
        uint64_t bytes = 0;
        if (roundtrip(count, &best, &bytes) != 0) {
            fprintf(stderr, "bench: session-roundtrip failed\n");
            failed = 1;
        } else {
            printf("BENCH lang=c stream=loopback-tcp mode=session-roundtrip packets=%d bytes=%llu "
                   "seconds=%.6f\n",
                   count, (unsigned long long)bytes, best);
        }
    }
    return failed;
}
