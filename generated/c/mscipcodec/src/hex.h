/* Private: the runtime's one hex-digit helper: the lowercase digit of a value 0..15 and the value
 * of a digit (either case), for the JSON reader and writer, the link's messages and the tools.
 * Generated: do not edit. */
#ifndef MSCIPC_HEX_H
#define MSCIPC_HEX_H

static inline char mscipc_hex_digit(unsigned value) {
    return "0123456789abcdef"[value & 0x0Fu];
}

/* 0..15, or -1 when c is not a hex digit. */
static inline int mscipc_hex_value(char c) {
    if (c >= '0' && c <= '9') {
        return c - '0';
    }
    if (c >= 'a' && c <= 'f') {
        return c - 'a' + 10;
    }
    if (c >= 'A' && c <= 'F') {
        return c - 'A' + 10;
    }
    return -1;
}

#endif
