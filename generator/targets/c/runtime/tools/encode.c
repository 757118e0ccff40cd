/* codec-encode: canonical JSON lines on stdin -> bytes on stdout (docs/conformance.md
 * section 5). A bad line is reported on stderr with its number and nothing is written for it;
 * the other lines are still encoded and the exit status is 1. Input is read in blocks and
 * encoded line by line (memory grows only with the longest line); when stdout is not a regular
 * file, what a block gave is flushed at once. I/O faults as in tool_io.h. */
#if defined(__unix__) || defined(__APPLE__)
#define _POSIX_C_SOURCE 200809L
#endif
#include "codec/json.h"
#include "tool_io.h"

static const char k_prog[] = "codec-encode";

enum { k_block = 65536 };

/* RFC 8259 whitespace only: a line of nothing else is blank. */
static int blank(const char *s, size_t n) {
    size_t i;
    for (i = 0; i < n; i++) {
        if (s[i] != ' ' && s[i] != '\t' && s[i] != '\r' && s[i] != '\n') {
            return 0;
        }
    }
    return 1;
}

/* Encodes one line (without its newline); returns 0, 1 for a bad line, 2 out of memory. */
static int encode_one(const char *line, size_t n, unsigned long line_no, int *write_err) {
    char msg[512];
    size_t cap = n / 2 + CODEC_MAX_PACKET;
    size_t out_len = 0;
    uint8_t *out;
    codec_status_t st;
    if (blank(line, n)) {
        return 0;
    }
    out = (uint8_t *)malloc(cap);
    if (!out) {
        return 2;
    }
    st = codec_json_encode_line(line, n, out, cap, &out_len, msg, sizeof msg);
    if (st == CODEC_OK) {
        tool_put(out, out_len, write_err);
    } else {
        fprintf(stderr, "line %lu: %s\n", line_no, msg);
    }
    free(out);
    return st == CODEC_OK ? 0 : 1;
}

int main(int argc, char **argv) {
    unsigned char *buf = NULL;
    size_t cap = 0;
    size_t used = 0;  /* bytes in buf */
    size_t start = 0; /* first byte of the current line */
    size_t scan = 0;  /* bytes before this are known not to be newlines */
    unsigned long line_no = 0;
    int status = 0;
    int write_err = 0;
    int done = 0;
    int flush_blocks;
    if (argc > 1) {
        if (strcmp(argv[1], "-h") == 0 || strcmp(argv[1], "--help") == 0) {
            fputs("usage: codec-encode < JSON-LINES > BYTES\n", stdout);
            return 0;
        }
        fprintf(stderr, "%s: unexpected argument %s\nusage: codec-encode < JSON-LINES > BYTES\n", k_prog,
                argv[1]);
        return 2;
    }
    tool_binary_stdio();
    setvbuf(stdout, NULL, _IOFBF, k_block);
    flush_blocks = !tool_stdout_is_file();
    while (!done) {
        long n;
        const unsigned char *nl;
        if (start > 0) { /* drop the lines already encoded */
            memmove(buf, buf + start, used - start);
            used -= start;
            scan -= start;
            start = 0;
        }
        if (cap - used < k_block) {
            unsigned char *bigger = (unsigned char *)realloc(buf, used + k_block);
            if (!bigger) {
                free(buf);
                fprintf(stderr, "%s: out of memory\n", k_prog);
                return 2;
            }
            buf = bigger;
            cap = used + k_block;
        }
        n = tool_read(stdin, buf + used, k_block);
        if (n < 0) {
            int err = errno;
            free(buf);
            tool_flush(&write_err);
            return write_err ? tool_write_error(k_prog, write_err)
                             : tool_read_error(k_prog, "standard input", err);
        }
        used += (size_t)n;
        done = n == 0;
        while ((nl = (const unsigned char *)memchr(buf + scan, '\n', used - scan)) != NULL ||
               (done && start < used)) {
            size_t end = nl ? (size_t)(nl - buf) : used;
            int r = encode_one((const char *)buf + start, end - start, ++line_no, &write_err);
            if (r == 2) {
                free(buf);
                fprintf(stderr, "%s: out of memory\n", k_prog);
                return 2;
            }
            status |= r;
            start = scan = nl ? end + 1 : used;
            if (write_err) {
                free(buf);
                return tool_write_error(k_prog, write_err);
            }
        }
        scan = used;
        if (flush_blocks) {
            tool_flush(&write_err);
            if (write_err) {
                free(buf);
                return tool_write_error(k_prog, write_err);
            }
        }
    }
    free(buf);
    tool_flush(&write_err);
    if (write_err) {
        return tool_write_error(k_prog, write_err);
    }
    return status;
}
