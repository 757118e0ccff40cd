/* Canonical JSON writer: integers, floats (shortest round-trip, Python repr layout), strings,
 * hex. Generated: do not edit. */
#include "json_writer.h"
#include "democodec/json.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void democ_jw_init(democ_jw_t *w, char *buf, size_t cap) {
    w->buf = buf;
    w->cap = buf ? cap : 0;
    w->len = 0;
}

size_t democ_jw_finish(democ_jw_t *w) {
    if (w->cap > 0) {
        w->buf[w->len < w->cap ? w->len : w->cap - 1] = '\0';
    }
    return w->len;
}

void democ_jw_raw(democ_jw_t *w, const char *text, size_t n) {
    size_t i;
    for (i = 0; i < n; i++) {
        if (w->len + 1 < w->cap) {
            w->buf[w->len] = text[i];
        }
        w->len++;
    }
}

void democ_jw_lit(democ_jw_t *w, const char *text) {
    democ_jw_raw(w, text, strlen(text));
}

void democ_jw_key(democ_jw_t *w, int *first, const char *key) {
    if (!*first) {
        democ_jw_raw(w, ",", 1);
    }
    *first = 0;
    democ_jw_raw(w, "\"", 1);
    democ_jw_lit(w, key);
    democ_jw_raw(w, "\":", 2);
}

void democ_jw_sep(democ_jw_t *w, size_t index) {
    if (index > 0) {
        democ_jw_raw(w, ",", 1);
    }
}

void democ_jw_uint(democ_jw_t *w, uint64_t v) {
    char buf[24];
    int n = snprintf(buf, sizeof buf, "%llu", (unsigned long long)v);
    democ_jw_raw(w, buf, n > 0 ? (size_t)n : 0);
}

void democ_jw_int(democ_jw_t *w, int64_t v) {
    char buf[24];
    int n = snprintf(buf, sizeof buf, "%lld", (long long)v);
    democ_jw_raw(w, buf, n > 0 ? (size_t)n : 0);
}

static const char k_hex[] = "0123456789abcdef";

void democ_jw_hex(democ_jw_t *w, const uint8_t *bytes, size_t n) {
    size_t i;
    democ_jw_raw(w, "\"", 1);
    for (i = 0; i < n; i++) {
        char two[2];
        two[0] = k_hex[bytes[i] >> 4];
        two[1] = k_hex[bytes[i] & 0x0F];
        democ_jw_raw(w, two, 2);
    }
    democ_jw_raw(w, "\"", 1);
}

void democ_jw_string(democ_jw_t *w, const char *bytes, size_t n) {
    size_t i;
    democ_jw_raw(w, "\"", 1);
    for (i = 0; i < n; i++) {
        unsigned char b = (unsigned char)bytes[i];
        if (b == '"') {
            democ_jw_raw(w, "\\\"", 2);
        } else if (b == '\\') {
            democ_jw_raw(w, "\\\\", 2);
        } else if (b < 0x20 || b >= 0x7F) {
            char esc[6];
            esc[0] = '\\';
            esc[1] = 'u';
            esc[2] = '0';
            esc[3] = '0';
            esc[4] = k_hex[b >> 4];
            esc[5] = k_hex[b & 0x0F];
            democ_jw_raw(w, esc, 6);
        } else {
            democ_jw_raw(w, (const char *)&bytes[i], 1);
        }
    }
    democ_jw_raw(w, "\"", 1);
}

void democ_jw_bool(democ_jw_t *w, const bool *v) {
    democ_jw_lit(w, *v ? "true" : "false");
}

void democ_jw_char(democ_jw_t *w, const char *v) {
    democ_jw_string(w, v, 1);
}

void democ_jw_u8(democ_jw_t *w, const uint8_t *v) {
    democ_jw_uint(w, *v);
}

void democ_jw_u16(democ_jw_t *w, const uint16_t *v) {
    democ_jw_uint(w, *v);
}

void democ_jw_u32(democ_jw_t *w, const uint32_t *v) {
    democ_jw_uint(w, *v);
}

void democ_jw_u64(democ_jw_t *w, const uint64_t *v) {
    democ_jw_uint(w, *v);
}

void democ_jw_s8(democ_jw_t *w, const int8_t *v) {
    democ_jw_int(w, *v);
}

void democ_jw_s16(democ_jw_t *w, const int16_t *v) {
    democ_jw_int(w, *v);
}

void democ_jw_s32(democ_jw_t *w, const int32_t *v) {
    democ_jw_int(w, *v);
}

void democ_jw_s64(democ_jw_t *w, const int64_t *v) {
    democ_jw_int(w, *v);
}

void democ_jw_f32(democ_jw_t *w, const float *v) {
    char buf[DEMOC_JSON_NUMBER_MAX];
    size_t n = democ_json_format_float(*v, buf, sizeof buf);
    democ_jw_raw(w, buf, n);
}

void democ_jw_f64(democ_jw_t *w, const double *v) {
    char buf[DEMOC_JSON_NUMBER_MAX];
    size_t n = democ_json_format_double(*v, buf, sizeof buf);
    democ_jw_raw(w, buf, n);
}

void democ_jw_chars(democ_jw_t *w, const char *v, size_t n) {
    democ_jw_string(w, v, n);
}

/* ------------------------------------------------------------------ numbers */

/* Significant digits of a "%.*e" text and its exponent: text = d.ddd e x. */
static void split_e(const char *text, char *digits, int *n, int *x) {
    const char *s = text;
    *n = 0;
    if (*s == '-') {
        s++;
    }
    for (; *s && *s != 'e'; s++) {
        if (*s >= '0' && *s <= '9') {
            digits[(*n)++] = *s;
        }
    }
    digits[*n] = '\0';
    *x = *s == 'e' ? (int)strtol(s + 1, NULL, 10) : 0;
}

/* True when digits (d1.d2...dn) x 10^x, read back by strtod, is exactly v. */
static int round_trips(double v, const char *digits, int n, int x) {
    char text[48];
    snprintf(text, sizeof text, "%c.%se%d", digits[0], n > 1 ? digits + 1 : "0", x);
    return strtod(text, NULL) == v;
}

/* The next decimal of n digits above (delta = +1) or below (delta = -1). */
static void neighbour(const char *digits, int n, int x, int delta, char *out, int *out_x) {
    int i;
    memcpy(out, digits, (size_t)n + 1);
    *out_x = x;
    if (delta > 0) {
        for (i = n - 1; i >= 0 && out[i] == '9'; i--) {
            out[i] = '0';
        }
        if (i < 0) {
            out[0] = '1'; /* 99..9 -> 10..0 of the next decade */
            *out_x = x + 1;
        } else {
            out[i]++;
        }
    } else {
        for (i = n - 1; i >= 0 && out[i] == '0'; i--) {
            out[i] = '9';
        }
        if (i == 0 && out[0] == '1') {
            memset(out, '9', (size_t)n); /* 10..0 -> 99..9 of the previous decade */
            *out_x = x - 1;
        } else if (i >= 0) {
            out[i]--;
        }
    }
}

/* Shortest digits that round-trip to v (finite, > 0), and the scientific exponent. */
static void shortest(double v, char *digits, int *n, int *x) {
    int prec;
    char text[48];
    for (prec = 1; prec <= 17; prec++) {
        char alt[24];
        int alt_x;
        int delta;
        snprintf(text, sizeof text, "%.*e", prec - 1, v);
        split_e(text, digits, n, x);
        if (strtod(text, NULL) == v) {
            return;
        }
        /* The correctly rounded decimal may fall outside v's rounding interval on the narrow
         * side while the one on the other side is inside: that one is shorter still. */
        for (delta = -1; delta <= 1; delta += 2) {
            neighbour(digits, *n, *x, delta, alt, &alt_x);
            if (round_trips(v, alt, *n, alt_x)) {
                memcpy(digits, alt, (size_t)*n + 1);
                *x = alt_x;
                return;
            }
        }
    }
    snprintf(text, sizeof text, "%.16e", v);
    split_e(text, digits, n, x);
}

static size_t put(char *buf, size_t cap, size_t len, char c) {
    if (len + 1 < cap) {
        buf[len] = c;
    }
    return len + 1;
}

static size_t finish(char *buf, size_t cap, size_t len) {
    if (cap > 0) {
        buf[len < cap ? len : cap - 1] = '\0';
    }
    return len;
}

static size_t put_text(char *buf, size_t cap, size_t len, const char *text) {
    for (; *text; text++) {
        len = put(buf, cap, len, *text);
    }
    return len;
}

/* Finite double laid out like Python's repr(float). */
static size_t format_finite(double v, char *buf, size_t cap) {
    char digits[24];
    int n;
    int x;
    int i;
    size_t len = 0;
    if (v == 0.0) {
        uint64_t bits;
        memcpy(&bits, &v, sizeof bits);
        return finish(buf, cap, put_text(buf, cap, 0, (bits >> 63) ? "-0.0" : "0.0"));
    }
    if (v < 0) {
        len = put(buf, cap, len, '-');
        v = -v;
    }
    shortest(v, digits, &n, &x);
    while (n > 1 && digits[n - 1] == '0') {
        digits[--n] = '\0';
    }
    if (x >= -4 && x < 16) {
        if (x >= 0) {
            for (i = 0; i <= x; i++) {
                len = put(buf, cap, len, i < n ? digits[i] : '0');
            }
            len = put(buf, cap, len, '.');
            if (n > x + 1) {
                for (i = x + 1; i < n; i++) {
                    len = put(buf, cap, len, digits[i]);
                }
            } else {
                len = put(buf, cap, len, '0');
            }
        } else {
            len = put_text(buf, cap, len, "0.");
            for (i = 0; i < -x - 1; i++) {
                len = put(buf, cap, len, '0');
            }
            len = put_text(buf, cap, len, digits);
        }
    } else {
        char exp[16];
        len = put(buf, cap, len, digits[0]);
        if (n > 1) {
            len = put(buf, cap, len, '.');
            len = put_text(buf, cap, len, digits + 1);
        }
        snprintf(exp, sizeof exp, "e%c%02d", x < 0 ? '-' : '+', x < 0 ? -x : x);
        len = put_text(buf, cap, len, exp);
    }
    return finish(buf, cap, len);
}

size_t democ_json_format_double(double v, char *buf, size_t cap) {
    uint64_t bits;
    char text[32];
    memcpy(&bits, &v, sizeof bits);
    if (((bits >> 52) & 0x7FF) == 0x7FF) {
        if ((bits & 0xFFFFFFFFFFFFFull) == 0) {
            return finish(buf, cap, put_text(buf, cap, 0, (bits >> 63) ? "\"-inf\"" : "\"inf\""));
        }
        if (bits == 0x7FF8000000000000ull) {
            return finish(buf, cap, put_text(buf, cap, 0, "\"nan\""));
        }
        snprintf(text, sizeof text, "\"nan:0x%016llx\"", (unsigned long long)bits);
        return finish(buf, cap, put_text(buf, cap, 0, text));
    }
    return format_finite(v, buf, cap);
}

size_t democ_json_format_float(float v, char *buf, size_t cap) {
    uint32_t bits;
    char text[32];
    memcpy(&bits, &v, sizeof bits);
    if (((bits >> 23) & 0xFF) == 0xFF) {
        if ((bits & 0x7FFFFFu) == 0) {
            return finish(buf, cap, put_text(buf, cap, 0, (bits >> 31) ? "\"-inf\"" : "\"inf\""));
        }
        if (bits == 0x7FC00000u) {
            return finish(buf, cap, put_text(buf, cap, 0, "\"nan\""));
        }
        snprintf(text, sizeof text, "\"nan:0x%08lx\"", (unsigned long)bits);
        return finish(buf, cap, put_text(buf, cap, 0, text));
    }
    return format_finite((double)v, buf, cap);
}

size_t democ_json_format_string(const char *bytes, size_t n, char *buf, size_t cap) {
    democ_jw_t w;
    democ_jw_init(&w, buf, cap);
    democ_jw_string(&w, bytes, n);
    return democ_jw_finish(&w);
}
