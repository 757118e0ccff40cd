/* Reads a whole stream into memory (the command-line tools may allocate). Generated: do not edit. */
#ifndef MIPC_TOOLS_READ_ALL_H
#define MIPC_TOOLS_READ_ALL_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Returns a malloc'd buffer (NUL-terminated, *len bytes before the NUL), or NULL on error. */
static unsigned char *read_all(FILE *in, size_t *len) {
    size_t cap = 65536;
    size_t used = 0;
    unsigned char *buf = (unsigned char *)malloc(cap + 1);
    if (!buf) {
        return NULL;
    }
    for (;;) {
        size_t n;
        if (used == cap) {
            unsigned char *bigger;
            cap *= 2;
            bigger = (unsigned char *)realloc(buf, cap + 1);
            if (!bigger) {
                free(buf);
                return NULL;
            }
            buf = bigger;
        }
        n = fread(buf + used, 1, cap - used, in);
        used += n;
        if (n == 0) {
            break;
        }
    }
    if (ferror(in)) {
        free(buf);
        return NULL;
    }
    buf[used] = '\0';
    *len = used;
    return buf;
}

#endif
