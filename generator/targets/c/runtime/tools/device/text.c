/* The device tool's messages (say, note), allocation that exits on failure and growing strings. */
#include "device.h"

/* src into dst[cap], cut to fit. Not snprintf("%s"): gcc -O3 warns that it may truncate, which is
 * the point here. */
void copy_text(char *dst, size_t cap, const char *src) {
    size_t n = strlen(src);
    if (cap == 0) {
        return;
    }
    if (n >= cap) {
        n = cap - 1;
    }
    memcpy(dst, src, n);
    dst[n] = '\0';
}

/* Set while `auto` tries a port: a failed attempt is not an error of the run. */
bool quiet_notes;

void note(const char *fmt, ...) {
    va_list ap;
    if (quiet_notes) {
        return;
    }
    fprintf(stderr, PROG ": ");
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    fflush(stderr);
}

void say(const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    fputc('\n', stdout);
    fflush(stdout);
}

void *xalloc(size_t n) {
    void *p = calloc(1, n ? n : 1);
    if (p == NULL) {
        note("out of memory");
        exit(2);
    }
    return p;
}

void *xrealloc(void *p, size_t n) {
    void *q = realloc(p, n ? n : 1);
    if (q == NULL) {
        note("out of memory");
        exit(2);
    }
    return q;
}

char *xstrndup(const char *s, size_t n) {
    char *p = (char *)xalloc(n + 1);
    memcpy(p, s, n);
    p[n] = '\0';
    return p;
}

void buf_add(buf_t *b, const char *s, size_t n) {
    if (b->n + n + 1 > b->cap) {
        b->cap = (b->n + n + 1) * 2;
        b->s = (char *)xrealloc(b->s, b->cap);
    }
    memcpy(b->s + b->n, s, n);
    b->n += n;
    b->s[b->n] = '\0';
}

void buf_str(buf_t *b, const char *s) {
    buf_add(b, s, strlen(s));
}

void buf_fmt(buf_t *b, const char *fmt, ...) {
    char tmp[512];
    va_list ap;
    int n;
    va_start(ap, fmt);
    n = vsnprintf(tmp, sizeof tmp, fmt, ap);
    va_end(ap);
    if (n < 0) {
        return;
    }
    if ((size_t)n >= sizeof tmp) {
        char *big = (char *)xalloc((size_t)n + 1);
        va_start(ap, fmt);
        vsnprintf(big, (size_t)n + 1, fmt, ap);
        va_end(ap);
        buf_add(b, big, (size_t)n);
        free(big);
        return;
    }
    buf_add(b, tmp, (size_t)n);
}

void buf_reset(buf_t *b) {
    b->n = 0;
    if (b->s) {
        b->s[0] = '\0';
    }
}

const char *buf_text(const buf_t *b) {
    return b->s ? b->s : "";
}
