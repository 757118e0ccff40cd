/* mscipcodec-encode: canonical JSON lines on stdin -> bytes on stdout (docs/conformance.md
 * section 5). A bad line is reported on stderr with its number and nothing is written for it;
 * the other lines are still encoded and the exit status is 1. Generated: do not edit. */
#include "mscipcodec/json.h"
#include "read_all.h"

static int blank(const char *s, size_t n) {
    size_t i;
    for (i = 0; i < n; i++) {
        if (s[i] != ' ' && s[i] != '\t' && s[i] != '\r') {
            return 0;
        }
    }
    return 1;
}

int main(int argc, char **argv) {
    unsigned char *input;
    size_t len = 0;
    size_t start = 0;
    unsigned long line_no = 0;
    int status = 0;
    char msg[512];
    if (argc > 1) {
        if (strcmp(argv[1], "-h") == 0 || strcmp(argv[1], "--help") == 0) {
            fputs("usage: mscipcodec-encode < JSON-LINES > BYTES\n", stdout);
            return 0;
        }
        fprintf(stderr,
                "mscipcodec-encode: unexpected argument %s\nusage: mscipcodec-encode < JSON-LINES > BYTES\n",
                argv[1]);
        return 2;
    }
    input = read_all(stdin, &len);
    if (!input) {
        fprintf(stderr, "mscipcodec-encode: cannot read standard input\n");
        return 2;
    }
    while (start < len) {
        const char *line = (const char *)input + start;
        const char *nl = (const char *)memchr(line, '\n', len - start);
        size_t n = nl ? (size_t)(nl - line) : len - start;
        start += n + 1;
        line_no++;
        if (!blank(line, n)) {
            size_t cap = n / 2 + MSCIPC_MAX_PACKET;
            size_t out_len = 0;
            uint8_t *out = (uint8_t *)malloc(cap);
            mscipc_status_t st;
            if (!out) {
                fprintf(stderr, "mscipcodec-encode: out of memory\n");
                free(input);
                return 2;
            }
            st = mscipc_json_encode_line(line, n, out, cap, &out_len, msg, sizeof msg);
            if (st == MSCIPC_OK) {
                fwrite(out, 1, out_len, stdout);
            } else {
                fprintf(stderr, "line %lu: %s\n", line_no, msg);
                status = 1;
            }
            free(out);
        }
    }
    free(input);
    if (fflush(stdout) != 0 || ferror(stdout)) {
        fprintf(stderr, "mscipcodec-encode: cannot write the output\n");
        return 2;
    }
    return status;
}
