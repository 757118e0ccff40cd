/* Fuzz target `json` (C): arbitrary text through the JSON-line reader of the encode tool.
 *
 * The input is split at newlines like the encode tool does; each line is copied into an exact-size
 * buffer (no NUL after it) and encoded. When a line is accepted, its bytes are parsed as a stream;
 * every event's canonical line (docs/conformance.md section 4) must encode back to exactly that
 * event's bytes, and the events must cover the bytes. An accepted line must not fit into a buffer
 * one byte shorter than its output, and a rejected line leaves a NUL-terminated message. */
#include "fuzz_common.h"

typedef struct {
    const uint8_t *bytes;
    size_t size;
    uint64_t covered;
} fz_json_run_t;

/* A foreign frame's line is not encoder input (docs/conformance.md section 5): refused with a message. */
static void check_foreign(const FZ(event_t) * ev) {
    char line[1024];
    uint8_t out[8];
    char msg[256];
    size_t out_len = 0;
    size_t n = FZ(json_foreign_line)(ev, line, sizeof line);
    FZ(status_t) st;
    FZ_CHECK(n > 0 && n < sizeof line, "foreign line of %zu bytes", n);
    memset(msg, 'x', sizeof msg);
    st = FZ(json_encode_line)(line, n, out, sizeof out, &out_len, msg, sizeof msg);
    FZ_CHECK(st == FZU(ERR_JSON), "the foreign frame's line gives status %d: %s", (int)st, line);
    FZ_CHECK(memchr(msg, '\0', sizeof msg) != NULL && strlen(msg) > 0, "refused without a message: %s", line);
}

static void on_event(void *arg, const FZ(event_t) * ev) {
    fz_json_run_t *run = (fz_json_run_t *)arg;
    const uint8_t *bytes = run->bytes + ev->offset;
    size_t len = (size_t)ev->length;
    char *line;
    uint8_t *out;
    size_t n;
    size_t out_len = 0;
    char msg[512];
    FZ(status_t) st;
    FZ_CHECK(ev->offset == run->covered && ev->length <= run->size - ev->offset, "event at %llu, expected %llu",
             (unsigned long long)ev->offset, (unsigned long long)run->covered);
    run->covered += ev->length;
    if (ev->kind == FZU(EVENT_NMEA) || ev->kind == FZU(EVENT_RTCM)) {
        check_foreign(ev);
        return;
    }
    n = ev->kind == FZU(EVENT_PACKET) ? FZ(json_packet_line)(bytes, len, ev->offset, FZU(DEVICE_ANY), NULL, 0)
                                      : FZ(json_skip_line)(ev->offset, bytes, len, NULL, 0);
    line = (char *)malloc(n + 1);
    FZ_CHECK(line != NULL, "out of memory");
    if (ev->kind == FZU(EVENT_PACKET)) {
        FZ(json_packet_line)(bytes, len, ev->offset, FZU(DEVICE_ANY), line, n + 1);
    } else {
        FZ(json_skip_line)(ev->offset, bytes, len, line, n + 1);
    }
    out = (uint8_t *)malloc(len);
    FZ_CHECK(out != NULL, "out of memory");
    st = FZ(json_encode_line)(line, n, out, len, &out_len, msg, sizeof msg);
    FZ_CHECK(st == FZU(OK), "the decoded line does not encode (%d: %s): %s", (int)st, msg, line);
    FZ_CHECK(out_len == len && memcmp(out, bytes, len) == 0, "the decoded line encodes to %s, not %s: %s",
             fz_hex(out, out_len), fz_hex(bytes, len), line);
    free(out);
    free(line);
}

static void check_line(const char *text, size_t n) {
    /* the copy has no terminator: reading past n is an ASan report */
    char *line = (char *)malloc(n ? n : 1);
    size_t cap = n / 2 + FZU(MAX_PACKET);
    uint8_t *out = (uint8_t *)malloc(cap);
    char msg[256];
    size_t out_len = 12345;
    FZ(status_t) st;
    FZ(parser_t) parser;
    fz_json_run_t run;
    FZ_CHECK(line != NULL && out != NULL, "out of memory");
    if (n > 0) {
        memcpy(line, text, n);
    }
    memset(msg, 'x', sizeof msg);
    st = FZ(json_encode_line)(line, n, out, cap, &out_len, msg, sizeof msg);
    if (st != FZU(OK)) {
        FZ_CHECK(st == FZU(ERR_JSON) || st == FZU(ERR_BUFFER), "status %d", (int)st);
        FZ_CHECK(memchr(msg, '\0', sizeof msg) != NULL, "error message not NUL-terminated");
        FZ_CHECK(strlen(msg) > 0, "empty error message");
    } else {
        FZ_CHECK(out_len <= cap, "%zu bytes written into %zu", out_len, cap);
        run.bytes = out;
        run.size = out_len;
        run.covered = 0;
        FZ(parser_init)(&parser);
        FZ(parser_feed)(&parser, out, out_len, on_event, &run);
        FZ(parser_flush)(&parser, on_event, &run);
        FZ_CHECK(run.covered == out_len, "events cover %llu of %zu bytes", (unsigned long long)run.covered, out_len);
        if (out_len > 0) {
            uint8_t *tight = (uint8_t *)malloc(out_len - 1 ? out_len - 1 : 1);
            size_t tight_len = 0;
            FZ_CHECK(tight != NULL, "out of memory");
            st = FZ(json_encode_line)(line, n, tight, out_len - 1, &tight_len, msg, sizeof msg);
            FZ_CHECK(st != FZU(OK), "%zu bytes encoded into %zu", out_len, out_len - 1);
            free(tight);
        }
    }
    free(out);
    free(line);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    const char *text = (const char *)data;
    size_t start = 0;
    while (start < size) {
        const char *nl = (const char *)memchr(text + start, '\n', size - start);
        size_t n = nl ? (size_t)(nl - (text + start)) : size - start;
        check_line(text + start, n);
        start += n + 1;
    }
    return 0;
}
