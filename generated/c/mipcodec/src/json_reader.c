/* Reader of canonical JSON lines (no allocation). Generated: do not edit. */
#include "json_reader.h"

#include "hex.h"

#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_NESTING 64

void mipc_jr_init(mipc_jr_t *jr, const char *s, size_t len, char *msg, size_t msg_cap) {
    memset(jr, 0, sizeof *jr);
    jr->s = s;
    jr->len = s ? len : 0;
    jr->msg = msg;
    jr->msg_cap = msg ? msg_cap : 0;
    if (jr->msg_cap > 0) {
        jr->msg[0] = '\0';
    }
}

int mipc_jr_fail(mipc_jr_t *jr, const char *fmt, ...) {
    va_list ap;
    size_t len = 0;
    size_t i;
    if (jr->failed || jr->msg_cap == 0) {
        jr->failed = true;
        return -1;
    }
    jr->failed = true;
    for (i = 0; i < jr->depth && i < MIPC_JR_MAX_DEPTH && len < jr->msg_cap; i++) {
        int n;
        if (jr->index[i] != SIZE_MAX) {
            n = snprintf(jr->msg + len, jr->msg_cap - len, "%s%s[%zu]", i ? "." : "", jr->path[i],
                         jr->index[i]);
        } else {
            n = snprintf(jr->msg + len, jr->msg_cap - len, "%s%s", i ? "." : "", jr->path[i]);
        }
        len += n > 0 ? (size_t)n : 0;
    }
    if (jr->depth > 0 && len < jr->msg_cap) {
        int n = snprintf(jr->msg + len, jr->msg_cap - len, ": ");
        len += n > 0 ? (size_t)n : 0;
    }
    if (len < jr->msg_cap) {
        va_start(ap, fmt);
        vsnprintf(jr->msg + len, jr->msg_cap - len, fmt, ap);
        va_end(ap);
    }
    return -1;
}

void mipc_jr_push(mipc_jr_t *jr, const char *name) {
    if (jr->depth < MIPC_JR_MAX_DEPTH) {
        jr->path[jr->depth] = name;
        jr->index[jr->depth] = SIZE_MAX;
    }
    jr->depth++;
}

void mipc_jr_index(mipc_jr_t *jr, size_t index) {
    if (jr->depth > 0 && jr->depth <= MIPC_JR_MAX_DEPTH) {
        jr->index[jr->depth - 1] = index;
    }
}

void mipc_jr_pop(mipc_jr_t *jr) {
    if (jr->depth > 0) {
        jr->depth--;
    }
}

size_t mipc_jr_ws(const mipc_jr_t *jr, size_t pos) {
    while (pos < jr->len &&
           (jr->s[pos] == ' ' || jr->s[pos] == '\t' || jr->s[pos] == '\r' || jr->s[pos] == '\n')) {
        pos++;
    }
    return pos;
}

static int at(const mipc_jr_t *jr, size_t pos, char c) {
    return pos < jr->len && jr->s[pos] == c;
}

static int is_digit(const mipc_jr_t *jr, size_t pos) {
    return pos < jr->len && jr->s[pos] >= '0' && jr->s[pos] <= '9';
}

/* Length of the well-formed UTF-8 sequence at s (RFC 3629: no overlong forms, no surrogates,
 * at most U+10FFFF), or 0. */
static size_t utf8_length(const unsigned char *s, size_t n) {
    unsigned char c = s[0];
    size_t len;
    size_t k;
    unsigned char lo = 0x80;
    unsigned char hi = 0xBF;
    if (c >= 0xC2 && c <= 0xDF) {
        len = 2;
    } else if (c >= 0xE0 && c <= 0xEF) {
        len = 3;
        lo = c == 0xE0 ? 0xA0 : 0x80;
        hi = c == 0xED ? 0x9F : 0xBF;
    } else if (c >= 0xF0 && c <= 0xF4) {
        len = 4;
        lo = c == 0xF0 ? 0x90 : 0x80;
        hi = c == 0xF4 ? 0x8F : 0xBF;
    } else {
        return 0;
    }
    if (n < len || s[1] < lo || s[1] > hi) {
        return 0;
    }
    for (k = 2; k < len; k++) {
        if ((s[k] & 0xC0) != 0x80) {
            return 0;
        }
    }
    return len;
}

/* Scans a string starting at the quote; *end after the closing quote. */
static int scan_string(mipc_jr_t *jr, size_t pos, size_t *end) {
    size_t i = pos + 1;
    while (i < jr->len && jr->s[i] != '"') {
        unsigned char c = (unsigned char)jr->s[i];
        if (c < 0x20) {
            return mipc_jr_fail(jr, "control character in a string");
        }
        if (c >= 0x80) { /* the line is UTF-8 text (§5) */
            size_t len = utf8_length((const unsigned char *)jr->s + i, jr->len - i);
            if (len == 0) {
                return mipc_jr_fail(jr, "invalid UTF-8");
            }
            i += len;
            continue;
        }
        if (c == '\\') {
            i++;
            if (i >= jr->len) {
                break;
            }
            if (jr->s[i] == 'u') {
                int k;
                for (k = 1; k <= 4; k++) {
                    if (i + (size_t)k >= jr->len || mipc_hex_value(jr->s[i + (size_t)k]) < 0) {
                        return mipc_jr_fail(jr, "bad \\u escape in a string");
                    }
                }
                i += 4;
            } else if (jr->s[i] == '\0' || !strchr("\"\\/bfnrt", jr->s[i])) {
                return mipc_jr_fail(jr, "bad escape in a string");
            }
        }
        i++;
    }
    if (i >= jr->len) {
        return mipc_jr_fail(jr, "unterminated string");
    }
    *end = i + 1;
    return 0;
}

/* Scans a number; *is_int tells whether it has neither fraction nor exponent. */
static int scan_number(mipc_jr_t *jr, size_t pos, size_t *end, int *is_int) {
    size_t i = pos;
    *is_int = 1;
    if (at(jr, i, '-')) {
        i++;
    }
    if (at(jr, i, '0')) {
        i++;
    } else if (is_digit(jr, i)) {
        while (is_digit(jr, i)) {
            i++;
        }
    } else {
        return mipc_jr_fail(jr, "invalid number");
    }
    if (at(jr, i, '.')) {
        *is_int = 0;
        i++;
        if (!is_digit(jr, i)) {
            return mipc_jr_fail(jr, "invalid number");
        }
        while (is_digit(jr, i)) {
            i++;
        }
    }
    if (at(jr, i, 'e') || at(jr, i, 'E')) {
        *is_int = 0;
        i++;
        if (at(jr, i, '+') || at(jr, i, '-')) {
            i++;
        }
        if (!is_digit(jr, i)) {
            return mipc_jr_fail(jr, "invalid number");
        }
        while (is_digit(jr, i)) {
            i++;
        }
    }
    *end = i;
    return 0;
}

static int literal(mipc_jr_t *jr, size_t pos, const char *word, size_t *end) {
    size_t n = strlen(word);
    if (jr->len - pos < n || memcmp(jr->s + pos, word, n) != 0) {
        return mipc_jr_fail(jr, "invalid JSON value");
    }
    *end = pos + n;
    return 0;
}

static int skip_value(mipc_jr_t *jr, size_t pos, size_t *end, int nesting) {
    int is_int;
    pos = mipc_jr_ws(jr, pos);
    if (pos >= jr->len) {
        return mipc_jr_fail(jr, "missing JSON value");
    }
    if (nesting > MAX_NESTING) {
        return mipc_jr_fail(jr, "JSON nested too deeply");
    }
    switch (jr->s[pos]) {
    case '{':
    case '[': {
        char close = jr->s[pos] == '{' ? '}' : ']';
        int object = close == '}';
        pos = mipc_jr_ws(jr, pos + 1);
        if (at(jr, pos, close)) {
            *end = pos + 1;
            return 0;
        }
        for (;;) {
            if (object) {
                if (!at(jr, pos, '"')) {
                    return mipc_jr_fail(jr, "expected a key in quotes");
                }
                if (scan_string(jr, pos, &pos)) {
                    return -1;
                }
                pos = mipc_jr_ws(jr, pos);
                if (!at(jr, pos, ':')) {
                    return mipc_jr_fail(jr, "expected ':' after a key");
                }
                pos++;
            }
            if (skip_value(jr, pos, &pos, nesting + 1)) {
                return -1;
            }
            pos = mipc_jr_ws(jr, pos);
            if (at(jr, pos, close)) {
                *end = pos + 1;
                return 0;
            }
            if (!at(jr, pos, ',')) {
                return mipc_jr_fail(jr, object ? "expected ',' or '}'" : "expected ',' or ']'");
            }
            pos = mipc_jr_ws(jr, pos + 1);
        }
    }
    case '"':
        return scan_string(jr, pos, end);
    case 't':
        return literal(jr, pos, "true", end);
    case 'f':
        return literal(jr, pos, "false", end);
    case 'n':
        return literal(jr, pos, "null", end);
    default:
        return scan_number(jr, pos, end, &is_int);
    }
}

int mipc_jr_skip(mipc_jr_t *jr, size_t pos, size_t *end) {
    return skip_value(jr, pos, end, 0);
}

int mipc_jr_document(mipc_jr_t *jr, size_t *pos) {
    size_t start = mipc_jr_ws(jr, 0);
    size_t end;
    if (!at(jr, start, '{')) {
        return mipc_jr_fail(jr, "expected a JSON object");
    }
    if (mipc_jr_skip(jr, start, &end)) {
        return -1;
    }
    if (mipc_jr_ws(jr, end) != jr->len) {
        return mipc_jr_fail(jr, "unexpected text after the JSON object");
    }
    *pos = start;
    return 0;
}

/* Walks an object that mipc_jr_skip accepted: calls back for each key. */
/* The character at jr->s[*i] inside a string that scan_string accepted: escapes decoded and a
 * UTF-8 sequence read as one code point; advances *i past it. */
static unsigned string_char(const mipc_jr_t *jr, size_t *i) {
    const unsigned char *u = (const unsigned char *)jr->s + *i;
    unsigned code = u[0];
    if (code == '\\') {
        const char *from = "bfnrt";
        const char *to = "\b\f\n\r\t";
        const char *at_e;
        if (u[1] == 'u') {
            *i += 6;
            return (unsigned)(mipc_hex_value((char)u[2]) << 12 | mipc_hex_value((char)u[3]) << 8 |
                              mipc_hex_value((char)u[4]) << 4 | mipc_hex_value((char)u[5]));
        }
        *i += 2;
        at_e = strchr(from, (char)u[1]);
        return (unsigned char)(at_e ? to[at_e - from] : (char)u[1]);
    }
    if (code >= 0x80) {
        size_t len = utf8_length(u, jr->len - *i);
        size_t k;
        code &= len == 2 ? 0x1Fu : len == 3 ? 0x0Fu : 0x07u;
        for (k = 1; k < len; k++) {
            code = code << 6 | (u[k] & 0x3Fu);
        }
        *i += len;
        return code;
    }
    *i += 1;
    return code;
}

/* True when the JSON string at key_pos..key_end (quotes included, already scanned) denotes the
 * ASCII text name: escapes are decoded first ("na\u006de" is the key "name", §5). */
static bool key_equals(const mipc_jr_t *jr, size_t key_pos, size_t key_end, const char *name) {
    size_t i = key_pos + 1;
    size_t k = 0;
    while (i < key_end - 1) {
        unsigned code = string_char(jr, &i);
        if (name[k] == '\0' || code != (unsigned char)name[k]) {
            return false;
        }
        k++;
    }
    return name[k] == '\0';
}

static size_t key_index(const mipc_jr_t *jr, size_t key_pos, size_t key_end, const char *const *keys,
                        size_t n) {
    size_t i;
    for (i = 0; i < n; i++) {
        if (key_equals(jr, key_pos, key_end, keys[i])) {
            return i;
        }
    }
    return n;
}

int mipc_jr_object(mipc_jr_t *jr, size_t pos, const char *const *keys, size_t n) {
    size_t end;
    uint64_t seen = 0;
    pos = mipc_jr_ws(jr, pos);
    if (!at(jr, pos, '{')) {
        return mipc_jr_fail(jr, "expected an object");
    }
    if (mipc_jr_skip(jr, pos, &end)) {
        return -1;
    }
    pos = mipc_jr_ws(jr, pos + 1);
    while (!at(jr, pos, '}')) {
        size_t key_end;
        size_t k;
        scan_string(jr, pos, &key_end);
        k = key_index(jr, pos, key_end, keys, n);
        if (k == n) {
            int shown = (int)(key_end - pos > 40 ? 40 : key_end - pos);
            return mipc_jr_fail(jr, "unknown key %.*s", shown, jr->s + pos);
        }
        if (k < 64 && (seen & ((uint64_t)1 << k))) {
            return mipc_jr_fail(jr, "duplicate key \"%s\"", keys[k]);
        }
        if (k < 64) {
            seen |= (uint64_t)1 << k;
        }
        pos = mipc_jr_ws(jr, key_end) + 1;
        skip_value(jr, pos, &pos, 0);
        pos = mipc_jr_ws(jr, pos);
        if (at(jr, pos, ',')) {
            pos = mipc_jr_ws(jr, pos + 1);
        }
    }
    return 0;
}

int mipc_jr_get(mipc_jr_t *jr, size_t pos, const char *key, size_t *value) {
    pos = mipc_jr_ws(jr, pos) + 1;
    pos = mipc_jr_ws(jr, pos);
    while (at(jr, pos, '"')) {
        size_t key_end;
        scan_string(jr, pos, &key_end);
        if (key_index(jr, pos, key_end, &key, 1) == 0) {
            *value = mipc_jr_ws(jr, mipc_jr_ws(jr, key_end) + 1);
            return 1;
        }
        pos = mipc_jr_ws(jr, key_end) + 1;
        skip_value(jr, pos, &pos, 0);
        pos = mipc_jr_ws(jr, pos);
        if (at(jr, pos, ',')) {
            pos = mipc_jr_ws(jr, pos + 1);
        }
    }
    return 0;
}

int mipc_jr_array(mipc_jr_t *jr, size_t pos, size_t *it) {
    size_t end;
    pos = mipc_jr_ws(jr, pos);
    if (!at(jr, pos, '[')) {
        return mipc_jr_fail(jr, "expected an array");
    }
    if (mipc_jr_skip(jr, pos, &end)) {
        return -1;
    }
    *it = mipc_jr_ws(jr, pos + 1);
    return 0;
}

int mipc_jr_next(mipc_jr_t *jr, size_t *it, size_t *elem) {
    size_t pos = mipc_jr_ws(jr, *it);
    if (at(jr, pos, ']')) {
        return 0;
    }
    if (at(jr, pos, ',')) {
        pos = mipc_jr_ws(jr, pos + 1);
    }
    *elem = pos;
    if (skip_value(jr, pos, it, 0)) {
        return -1;
    }
    return 1;
}

int mipc_jr_members(mipc_jr_t *jr, size_t pos, size_t *it) {
    size_t end;
    pos = mipc_jr_ws(jr, pos);
    if (!at(jr, pos, '{')) {
        return mipc_jr_fail(jr, "expected an object");
    }
    if (mipc_jr_skip(jr, pos, &end)) {
        return -1;
    }
    *it = mipc_jr_ws(jr, pos + 1);
    return 0;
}

int mipc_jr_next_member(mipc_jr_t *jr, size_t *it, size_t *key, size_t *value) {
    size_t pos = mipc_jr_ws(jr, *it);
    size_t key_end;
    if (at(jr, pos, '}')) {
        return 0;
    }
    if (at(jr, pos, ',')) {
        pos = mipc_jr_ws(jr, pos + 1);
    }
    if (scan_string(jr, pos, &key_end)) {
        return -1;
    }
    *key = pos;
    *value = mipc_jr_ws(jr, mipc_jr_ws(jr, key_end) + 1);
    if (skip_value(jr, *value, it, 0)) {
        return -1;
    }
    return 1;
}

int mipc_jr_number(mipc_jr_t *jr, size_t pos, size_t *end, bool *is_int) {
    int whole;
    if (scan_number(jr, mipc_jr_ws(jr, pos), end, &whole)) {
        return -1;
    }
    *is_int = whole != 0;
    return 0;
}

/* Magnitude of an integer token; *negative for a leading '-'. Returns 0, or -1 after recording
 * the failure: a literal -1 on every failing path (not mipc_jr_fail's result), so that the
 * compiler sees that *mag and *negative are written whenever 0 is returned (gcc -O3 otherwise
 * warns that the callers' values may be used uninitialized). */
static int integer(mipc_jr_t *jr, size_t pos, uint64_t *mag, int *negative, const char *expected) {
    size_t end;
    size_t i;
    int is_int;
    pos = mipc_jr_ws(jr, pos);
    if (pos >= jr->len || !(jr->s[pos] == '-' || (jr->s[pos] >= '0' && jr->s[pos] <= '9'))) {
        (void)mipc_jr_fail(jr, "expected %s", expected);
        return -1;
    }
    if (scan_number(jr, pos, &end, &is_int)) {
        return -1;
    }
    if (!is_int) {
        (void)mipc_jr_fail(jr, "expected %s", expected);
        return -1;
    }
    *negative = jr->s[pos] == '-';
    *mag = 0;
    for (i = pos + (*negative ? 1u : 0u); i < end; i++) {
        unsigned d = (unsigned)(jr->s[i] - '0');
        if (*mag > (UINT64_MAX - d) / 10) {
            (void)mipc_jr_fail(jr, "expected %s", expected);
            return -1;
        }
        *mag = *mag * 10 + d;
    }
    return 0;
}

int mipc_jr_uint(mipc_jr_t *jr, size_t pos, uint64_t max, uint64_t *out) {
    char expected[64];
    uint64_t mag;
    int negative;
    snprintf(expected, sizeof expected, "an integer in 0..%llu", (unsigned long long)max);
    if (integer(jr, pos, &mag, &negative, expected)) {
        return -1;
    }
    if ((negative && mag != 0) || mag > max) {
        (void)mipc_jr_fail(jr, "expected %s", expected);
        return -1;
    }
    *out = mag;
    return 0;
}

int mipc_jr_sint(mipc_jr_t *jr, size_t pos, int64_t min, int64_t max, int64_t *out) {
    char expected[80];
    uint64_t mag;
    int negative;
    snprintf(expected, sizeof expected, "an integer in %lld..%lld", (long long)min, (long long)max);
    if (integer(jr, pos, &mag, &negative, expected)) {
        return -1;
    }
    if (negative) {
        /* -mag >= min  <=>  mag <= -(min + 1) + 1 */
        uint64_t limit = (uint64_t)(-(min + 1)) + 1u;
        if (mag > limit) {
            (void)mipc_jr_fail(jr, "expected %s", expected);
            return -1;
        }
        *out = mag == 0 ? 0 : -(int64_t)(mag - 1) - 1;
    } else {
        if (mag > (uint64_t)max) {
            (void)mipc_jr_fail(jr, "expected %s", expected);
            return -1;
        }
        *out = (int64_t)mag;
    }
    return 0;
}

int mipc_jr_null(mipc_jr_t *jr, size_t pos) {
    pos = mipc_jr_ws(jr, pos);
    if (jr->len - pos < 4 || memcmp(jr->s + pos, "null", 4) != 0) {
        return mipc_jr_fail(jr, "expected null");
    }
    return 0;
}

bool mipc_jr_is_string(const mipc_jr_t *jr, size_t pos) {
    return at(jr, mipc_jr_ws(jr, pos), '"');
}

/* Decodes the string at pos into bytes (code points up to U+00FF); *n gets the byte count,
 * which may exceed cap (then only cap bytes are stored). */
static int string_bytes(mipc_jr_t *jr, size_t pos, char *out, size_t cap, size_t *n, const char *expected) {
    size_t end;
    size_t i;
    pos = mipc_jr_ws(jr, pos);
    if (!at(jr, pos, '"')) {
        return mipc_jr_fail(jr, "expected %s", expected);
    }
    if (scan_string(jr, pos, &end)) {
        return -1;
    }
    *n = 0;
    for (i = pos + 1; i < end - 1; i++) {
        unsigned char c = (unsigned char)jr->s[i];
        unsigned code = c;
        if (c == '\\') {
            char e = jr->s[++i];
            switch (e) {
            case 'b':
                code = 0x08;
                break;
            case 'f':
                code = 0x0C;
                break;
            case 'n':
                code = 0x0A;
                break;
            case 'r':
                code = 0x0D;
                break;
            case 't':
                code = 0x09;
                break;
            case 'u':
                code = (unsigned)(mipc_hex_value(jr->s[i + 1]) << 12 | mipc_hex_value(jr->s[i + 2]) << 8 |
                                  mipc_hex_value(jr->s[i + 3]) << 4 | mipc_hex_value(jr->s[i + 4]));
                i += 4;
                break;
            default:
                code = (unsigned char)e;
                break;
            }
        } else if (c >= 0x80) {
            /* UTF-8 of U+0080..U+00FF */
            unsigned char c2 = i + 1 < end - 1 ? (unsigned char)jr->s[i + 1] : 0;
            if ((c != 0xC2 && c != 0xC3) || (c2 & 0xC0) != 0x80) {
                return mipc_jr_fail(jr, "character outside U+0000..U+00FF in a string");
            }
            code = ((unsigned)(c & 0x1F) << 6) | (c2 & 0x3Fu);
            i++;
        }
        if (code > 0xFF) {
            return mipc_jr_fail(jr, "character outside U+0000..U+00FF in a string");
        }
        if (*n < cap) {
            out[*n] = (char)(unsigned char)code;
        }
        (*n)++;
    }
    return 0;
}

int mipc_jr_bytes(mipc_jr_t *jr, size_t pos, char *out, size_t cap, size_t *n) {
    return string_bytes(jr, pos, out, cap, n, "a string");
}

int mipc_jr_chars(mipc_jr_t *jr, size_t pos, char *out, size_t n) {
    char expected[64];
    size_t got;
    snprintf(expected, sizeof expected, "a string of exactly %zu characters", n);
    if (string_bytes(jr, pos, out, n, &got, expected)) {
        return -1;
    }
    if (got != n) {
        return mipc_jr_fail(jr, "expected %s, got %zu", expected, got);
    }
    return 0;
}

int mipc_jr_hex(mipc_jr_t *jr, size_t pos, uint8_t *out, size_t cap, size_t *n) {
    size_t end;
    size_t i;
    size_t digits = 0;
    int hi = 0;
    pos = mipc_jr_ws(jr, pos);
    if (!at(jr, pos, '"')) {
        return mipc_jr_fail(jr, "expected a hex string");
    }
    if (scan_string(jr, pos, &end)) {
        return -1;
    }
    /* The digits are the string's characters, escapes decoded (§5). */
    for (i = pos + 1; i < end - 1;) {
        unsigned code = string_char(jr, &i);
        int d = code < 0x80 ? mipc_hex_value((char)code) : -1;
        if (d < 0) {
            return mipc_jr_fail(jr, "expected hex digits");
        }
        if (digits % 2 == 0) {
            hi = d;
        } else if (digits / 2 < cap) {
            out[digits / 2] = (uint8_t)(hi << 4 | d);
        }
        digits++;
    }
    if (digits % 2 != 0) {
        return mipc_jr_fail(jr, "expected an even number of hex digits");
    }
    *n = digits / 2;
    if (*n > cap) {
        return mipc_jr_fail(jr, "%zu bytes is more than the %zu allowed here", *n, cap);
    }
    return 0;
}

int mipc_jr_bool(mipc_jr_t *jr, size_t pos, bool *out) {
    pos = mipc_jr_ws(jr, pos);
    if (jr->len - pos >= 4 && memcmp(jr->s + pos, "true", 4) == 0) {
        *out = true;
        return 0;
    }
    if (jr->len - pos >= 5 && memcmp(jr->s + pos, "false", 5) == 0) {
        *out = false;
        return 0;
    }
    return mipc_jr_fail(jr, "expected true or false");
}

int mipc_jr_char(mipc_jr_t *jr, size_t pos, char *out) {
    return mipc_jr_chars(jr, pos, out, 1);
}

int mipc_jr_u8(mipc_jr_t *jr, size_t pos, uint8_t *out) {
    uint64_t v;
    if (mipc_jr_uint(jr, pos, UINT8_MAX, &v)) {
        return -1;
    }
    *out = (uint8_t)v;
    return 0;
}

int mipc_jr_u16(mipc_jr_t *jr, size_t pos, uint16_t *out) {
    uint64_t v;
    if (mipc_jr_uint(jr, pos, UINT16_MAX, &v)) {
        return -1;
    }
    *out = (uint16_t)v;
    return 0;
}

int mipc_jr_u32(mipc_jr_t *jr, size_t pos, uint32_t *out) {
    uint64_t v;
    if (mipc_jr_uint(jr, pos, UINT32_MAX, &v)) {
        return -1;
    }
    *out = (uint32_t)v;
    return 0;
}

int mipc_jr_u64(mipc_jr_t *jr, size_t pos, uint64_t *out) {
    uint64_t v;
    if (mipc_jr_uint(jr, pos, UINT64_MAX, &v)) {
        return -1;
    }
    *out = (uint64_t)v;
    return 0;
}

int mipc_jr_s8(mipc_jr_t *jr, size_t pos, int8_t *out) {
    int64_t v;
    if (mipc_jr_sint(jr, pos, INT8_MIN, INT8_MAX, &v)) {
        return -1;
    }
    *out = (int8_t)v;
    return 0;
}

int mipc_jr_s16(mipc_jr_t *jr, size_t pos, int16_t *out) {
    int64_t v;
    if (mipc_jr_sint(jr, pos, INT16_MIN, INT16_MAX, &v)) {
        return -1;
    }
    *out = (int16_t)v;
    return 0;
}

int mipc_jr_s32(mipc_jr_t *jr, size_t pos, int32_t *out) {
    int64_t v;
    if (mipc_jr_sint(jr, pos, INT32_MIN, INT32_MAX, &v)) {
        return -1;
    }
    *out = (int32_t)v;
    return 0;
}

int mipc_jr_s64(mipc_jr_t *jr, size_t pos, int64_t *out) {
    int64_t v;
    if (mipc_jr_sint(jr, pos, INT64_MIN, INT64_MAX, &v)) {
        return -1;
    }
    *out = (int64_t)v;
    return 0;
}

/* The double nearest to a JSON number of any length (docs/conformance.md §5: round to nearest,
 * ties to even; +-HUGE_VAL when it overflows, 0 or a denormal when it underflows). The number
 * is rewritten as at most NUMBER_DIGITS significant digits and an exponent for strtod: a 1 is
 * appended when a dropped digit is not zero, which keeps the rounding exact (a double needs at
 * most 767 significant digits to decide it), and the exponent is clamped where the result is
 * 0 or infinite anyway. */
#define NUMBER_DIGITS 800
static double number_value(const char *s, size_t n) {
    char text[NUMBER_DIGITS + 32];
    size_t i = 0;
    size_t k = 0;
    long exp10 = 0;
    long e = 0;
    int sticky = 0;
    int seen = 0;
    if (i < n && s[i] == '-') {
        text[k++] = '-';
        i++;
    }
    {
        size_t first = k;
        int fraction = 0;
        for (; i < n && (s[i] == '.' || (s[i] >= '0' && s[i] <= '9')); i++) {
            char c = s[i];
            if (c == '.') {
                fraction = 1;
                continue;
            }
            if (!seen && c == '0') {
                exp10 -= fraction;
                continue;
            }
            seen = 1;
            if (k - first < NUMBER_DIGITS) {
                text[k++] = c;
                exp10 -= fraction;
            } else {
                exp10 += !fraction;
                sticky |= c != '0';
            }
        }
        if (sticky) {
            text[k++] = '1';
            exp10--;
        }
        if (k == first) {
            text[k++] = '0';
        }
    }
    if (i < n && (s[i] == 'e' || s[i] == 'E')) {
        int negative = 0;
        i++;
        if (i < n && (s[i] == '+' || s[i] == '-')) {
            negative = s[i] == '-';
            i++;
        }
        for (; i < n && s[i] >= '0' && s[i] <= '9'; i++) {
            if (e < 100000000L) {
                e = e * 10 + (s[i] - '0');
            }
        }
        exp10 += negative ? -e : e;
    }
    if (exp10 > 100000L) {
        exp10 = 100000L;
    } else if (exp10 < -100000L) {
        exp10 = -100000L;
    }
    snprintf(text + k, sizeof text - k, "e%ld", exp10);
    return strtod(text, NULL);
}

/* A number, or "inf", "-inf", "nan", "nan:0x<hex_digits>"; *bits set for "nan:0x..". */
static int number(mipc_jr_t *jr, size_t pos, double *out, uint64_t *bits, int *has_bits, size_t hex_digits,
                  const char *expected) {
    size_t end;
    int is_int;
    *has_bits = 0;
    pos = mipc_jr_ws(jr, pos);
    if (at(jr, pos, '"')) {
        size_t n;
        char text[32];
        if (string_bytes(jr, pos, text, sizeof text - 1, &n, expected)) {
            return -1;
        }
        if (n < sizeof text) {
            text[n] = '\0';
            if (strcmp(text, "inf") == 0) {
                *out = HUGE_VAL;
                return 0;
            }
            if (strcmp(text, "-inf") == 0) {
                *out = -HUGE_VAL;
                return 0;
            }
            if (strcmp(text, "nan") == 0) {
                *bits = hex_digits == 8 ? 0x7FC00000u : 0x7FF8000000000000ull;
                *has_bits = 1;
                return 0;
            }
            if (n == 6 + hex_digits && memcmp(text, "nan:0x", 6) == 0) {
                size_t i;
                *bits = 0;
                for (i = 6; i < n; i++) {
                    int d = mipc_hex_value(text[i]);
                    if (d < 0) {
                        break;
                    }
                    *bits = (*bits << 4) | (uint64_t)d;
                }
                if (i == n) {
                    *has_bits = 1;
                    return 0;
                }
            }
        }
        return mipc_jr_fail(jr, "expected %s", expected);
    }
    if (scan_number(jr, pos, &end, &is_int)) {
        return -1;
    }
    *out = number_value(jr->s + pos, end - pos);
    if (*out == HUGE_VAL || *out == -HUGE_VAL) {
        return mipc_jr_fail(jr, "number out of range for a double");
    }
    return 0;
}

int mipc_jr_f64(mipc_jr_t *jr, size_t pos, double *out) {
    uint64_t bits;
    int has_bits;
    const char *expected = "a number, \"inf\", \"-inf\", \"nan\" or \"nan:0x\" and 16 hex digits";
    if (number(jr, pos, out, &bits, &has_bits, 16, expected)) {
        return -1;
    }
    if (has_bits) {
        if (((bits >> 52) & 0x7FF) != 0x7FF || (bits & 0xFFFFFFFFFFFFFull) == 0) {
            return mipc_jr_fail(jr, "not a NaN bit pattern");
        }
        memcpy(out, &bits, sizeof bits);
    }
    return 0;
}

int mipc_jr_f32(mipc_jr_t *jr, size_t pos, float *out) {
    uint64_t bits;
    int has_bits;
    double d = 0;
    const char *expected = "a number, \"inf\", \"-inf\", \"nan\" or \"nan:0x\" and 8 hex digits";
    if (number(jr, pos, &d, &bits, &has_bits, 8, expected)) {
        return -1;
    }
    if (has_bits) {
        uint32_t b32 = (uint32_t)bits;
        if (((b32 >> 23) & 0xFF) != 0xFF || (b32 & 0x7FFFFFu) == 0) {
            return mipc_jr_fail(jr, "not a NaN bit pattern");
        }
        memcpy(out, &b32, sizeof b32);
        return 0;
    }
    if (d == HUGE_VAL || d == -HUGE_VAL) { /* "inf", "-inf" */
        *out = d > 0 ? HUGE_VALF : -HUGE_VALF;
        return 0;
    }
    /* Rounded to nearest (ties to even), a double from half an ulp above FLT_MAX
     * (0x1.ffffffp127) up is infinite as a float: out of range (§5). Below it, a double beyond
     * FLT_MAX rounds to FLT_MAX (spelled out: C leaves that conversion undefined). */
    if (d >= 0x1.ffffffp127 || d <= -0x1.ffffffp127) {
        return mipc_jr_fail(jr, "number out of range for a float");
    }
    if (d > FLT_MAX || d < -FLT_MAX) {
        *out = d > 0 ? FLT_MAX : -FLT_MAX;
        return 0;
    }
    *out = (float)d;
    return 0;
}
