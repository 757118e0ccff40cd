/* Shared by the C fuzz harnesses: one source serves every generated C package. The build passes
 *   -DFZ_PACKAGE_HEADER='"mipcodec/mipcodec.h"' -DFZ_PREFIX=mip_ -DFZ_UPREFIX=MIP_
 * and FZ(x) / FZU(X) name the package's functions, types and constants. A failed check prints
 * what went wrong and aborts, which libFuzzer (and the replay runner) reports as a finding. */
#ifndef FUZZ_COMMON_H
#define FUZZ_COMMON_H

#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include FZ_PACKAGE_HEADER

#define FZ_CAT2(a, b) a##b
#define FZ_CAT(a, b) FZ_CAT2(a, b)
#define FZ(name) FZ_CAT(FZ_PREFIX, name)
#define FZU(name) FZ_CAT(FZ_UPREFIX, name)

static inline void fz_fail(const char *file, int line, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4), noreturn))
#endif
    ;

static inline void fz_fail(const char *file, int line, const char *fmt, ...) {
    va_list ap;
    fprintf(stderr, "FUZZ CHECK FAILED at %s:%d: ", file, line);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    fflush(stderr);
    abort();
}

#define FZ_CHECK(cond, ...)                                                                                 \
    do {                                                                                                    \
        if (!(cond)) {                                                                                      \
            fz_fail(__FILE__, __LINE__, __VA_ARGS__);                                                       \
        }                                                                                                   \
    } while (0)

/* Hex dump of at most 64 bytes into a static buffer, for messages. */
static inline const char *fz_hex(const uint8_t *p, size_t n) {
    static char text[2 * 64 + 4];
    size_t i;
    size_t m = n < 64 ? n : 64;
    for (i = 0; i < m; i++) {
        snprintf(text + 2 * i, 3, "%02x", p[i]);
    }
    strcpy(text + 2 * m, n > m ? "..." : "");
    return text;
}

/* Chunk sizes of the chunked parse: a small generator seeded by the control byte, sizes in
 * 1 .. (control & 0x3f) + 1. The same plan is used by every language's harness. */
typedef struct {
    unsigned state;
    unsigned max;
} fz_chunks_t;

static inline void fz_chunks_init(fz_chunks_t *c, uint8_t control) {
    c->state = control;
    c->max = (unsigned)(control & 0x3f) + 1u;
}

static inline size_t fz_chunks_next(fz_chunks_t *c) {
    c->state = (c->state * 73u + 41u) & 0xffu;
    return 1u + c->state % c->max;
}

#endif
