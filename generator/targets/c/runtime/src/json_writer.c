/* Canonical JSON writer: integers, floats (shortest round-trip, Python repr layout), strings,
 * hex. */
#include "json_writer.h"
#include "codec/json.h"
#include "grisu3.h"
#include "hex.h"

#include <assert.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void codec_jw_init(codec_jw_t *w, char *buf, size_t cap) {
    w->buf = buf;
    w->cap = buf ? cap : 0;
    w->len = 0;
}

size_t codec_jw_finish(codec_jw_t *w) {
    if (w->cap > 0) {
        w->buf[w->len < w->cap ? w->len : w->cap - 1] = '\0';
    }
    return w->len;
}

void codec_jw_raw(codec_jw_t *w, const char *text, size_t n) {
    size_t i;
    for (i = 0; i < n; i++) {
        if (w->len + 1 < w->cap) {
            w->buf[w->len] = text[i];
        }
        w->len++;
    }
}

void codec_jw_lit(codec_jw_t *w, const char *text) {
    codec_jw_raw(w, text, strlen(text));
}

void codec_jw_key(codec_jw_t *w, int *first, const char *key) {
    if (!*first) {
        codec_jw_raw(w, ",", 1);
    }
    *first = 0;
    codec_jw_raw(w, "\"", 1);
    codec_jw_lit(w, key);
    codec_jw_raw(w, "\":", 2);
}

void codec_jw_sep(codec_jw_t *w, size_t index) {
    if (index > 0) {
        codec_jw_raw(w, ",", 1);
    }
}

void codec_jw_uint(codec_jw_t *w, uint64_t v) {
    char buf[24];
    int n = snprintf(buf, sizeof buf, "%llu", (unsigned long long)v);
    codec_jw_raw(w, buf, n > 0 ? (size_t)n : 0);
}

void codec_jw_int(codec_jw_t *w, int64_t v) {
    char buf[24];
    int n = snprintf(buf, sizeof buf, "%lld", (long long)v);
    codec_jw_raw(w, buf, n > 0 ? (size_t)n : 0);
}

void codec_jw_hex(codec_jw_t *w, const uint8_t *bytes, size_t n) {
    size_t i;
    codec_jw_raw(w, "\"", 1);
    for (i = 0; i < n; i++) {
        char two[2];
        two[0] = codec_hex_digit(bytes[i] >> 4);
        two[1] = codec_hex_digit(bytes[i]);
        codec_jw_raw(w, two, 2);
    }
    codec_jw_raw(w, "\"", 1);
}

void codec_jw_string(codec_jw_t *w, const char *bytes, size_t n) {
    size_t i;
    codec_jw_raw(w, "\"", 1);
    for (i = 0; i < n; i++) {
        unsigned char b = (unsigned char)bytes[i];
        if (b == '"') {
            codec_jw_raw(w, "\\\"", 2);
        } else if (b == '\\') {
            codec_jw_raw(w, "\\\\", 2);
        } else if (b < 0x20 || b >= 0x7F) {
            char esc[6];
            esc[0] = '\\';
            esc[1] = 'u';
            esc[2] = '0';
            esc[3] = '0';
            esc[4] = codec_hex_digit(b >> 4u);
            esc[5] = codec_hex_digit(b);
            codec_jw_raw(w, esc, 6);
        } else {
            codec_jw_raw(w, (const char *)&bytes[i], 1);
        }
    }
    codec_jw_raw(w, "\"", 1);
}

void codec_jw_bool(codec_jw_t *w, const bool *v) {
    codec_jw_lit(w, *v ? "true" : "false");
}

void codec_jw_char(codec_jw_t *w, const char *v) {
    codec_jw_string(w, v, 1);
}

void codec_jw_u8(codec_jw_t *w, const uint8_t *v) {
    codec_jw_uint(w, *v);
}

void codec_jw_u16(codec_jw_t *w, const uint16_t *v) {
    codec_jw_uint(w, *v);
}

void codec_jw_u32(codec_jw_t *w, const uint32_t *v) {
    codec_jw_uint(w, *v);
}

void codec_jw_u64(codec_jw_t *w, const uint64_t *v) {
    codec_jw_uint(w, *v);
}

void codec_jw_s8(codec_jw_t *w, const int8_t *v) {
    codec_jw_int(w, *v);
}

void codec_jw_s16(codec_jw_t *w, const int16_t *v) {
    codec_jw_int(w, *v);
}

void codec_jw_s32(codec_jw_t *w, const int32_t *v) {
    codec_jw_int(w, *v);
}

void codec_jw_s64(codec_jw_t *w, const int64_t *v) {
    codec_jw_int(w, *v);
}

void codec_jw_f32(codec_jw_t *w, const float *v) {
    char buf[CODEC_JSON_NUMBER_MAX];
    size_t n = codec_json_format_float(*v, buf, sizeof buf);
    codec_jw_raw(w, buf, n);
}

void codec_jw_f64(codec_jw_t *w, const double *v) {
    char buf[CODEC_JSON_NUMBER_MAX];
    size_t n = codec_json_format_double(*v, buf, sizeof buf);
    codec_jw_raw(w, buf, n);
}

void codec_jw_chars(codec_jw_t *w, const char *v, size_t n) {
    codec_jw_string(w, v, n);
}

/* ------------------------------------------------------------------ numbers */

/* Shortest round-trip digits (Python's repr(float)): the free-format algorithm of Steele & White
 * as given by Burger & Dybvig ("Printing Floating-Point Numbers Quickly and Accurately", PLDI
 * 1996), in exact integer arithmetic. v = r / s x 10^k; the decimals that read back as v are those
 * strictly inside (or, for an even mantissa, on the edge of) v's rounding interval, whose
 * half-widths are m- and m+ in the same units. Digits are generated until the number so far is
 * within the interval; the last digit is the one closer to v (round half to even on a tie). No
 * snprintf/strtod search; tests/json_float_test.cpp compares it with an independent reference on
 * every float32 (JSON_FLOAT_EXHAUSTIVE=1), a stride of them, random and boundary doubles. */
#define BIG_LIMBS 40 /* 1280 bits: r, s, m+, m- stay under 2^1140 for every finite double */

typedef struct {
    uint32_t d[BIG_LIMBS]; /* little-endian limbs */
    int n;                 /* limbs in use (no leading zero limbs; 0 for zero) */
} big_t;

static void big_set(big_t *a, uint64_t v) {
    a->n = 0;
    while (v) {
        a->d[a->n++] = (uint32_t)v;
        v >>= 32;
    }
}

static void big_mul_small(big_t *a, uint32_t m) {
    uint64_t carry = 0;
    int i;
    for (i = 0; i < a->n; i++) {
        uint64_t t = (uint64_t)a->d[i] * m + carry;
        a->d[i] = (uint32_t)t;
        carry = t >> 32;
    }
    if (carry) {
        a->d[a->n++] = (uint32_t)carry;
    }
}

static void big_shl(big_t *a, int bits) {
    int limbs = bits / 32;
    int shift = bits % 32;
    int i;
    if (a->n == 0) {
        return;
    }
    if (shift) {
        uint32_t carry = 0;
        for (i = 0; i < a->n; i++) {
            uint32_t next = a->d[i] >> (32 - shift);
            a->d[i] = (a->d[i] << shift) | carry;
            carry = next;
        }
        if (carry) {
            a->d[a->n++] = carry;
        }
    }
    if (limbs) {
        for (i = a->n - 1; i >= 0; i--) {
            a->d[i + limbs] = a->d[i];
        }
        for (i = 0; i < limbs; i++) {
            a->d[i] = 0;
        }
        a->n += limbs;
    }
}

static void big_mul_pow10(big_t *a, int k) {
    for (; k >= 9; k -= 9) {
        big_mul_small(a, 1000000000u);
    }
    for (; k > 0; k--) {
        big_mul_small(a, 10u);
    }
}

static int big_cmp(const big_t *a, const big_t *b) {
    int i;
    if (a->n != b->n) {
        return a->n < b->n ? -1 : 1;
    }
    for (i = a->n - 1; i >= 0; i--) {
        if (a->d[i] != b->d[i]) {
            return a->d[i] < b->d[i] ? -1 : 1;
        }
    }
    return 0;
}

/* Compare a + b with c. */
static int big_cmp_sum(const big_t *a, const big_t *b, const big_t *c) {
    big_t t;
    uint64_t carry = 0;
    int n = a->n > b->n ? a->n : b->n;
    int i;
    for (i = 0; i < n; i++) {
        uint64_t x = (uint64_t)(i < a->n ? a->d[i] : 0) + (i < b->n ? b->d[i] : 0) + carry;
        t.d[i] = (uint32_t)x;
        carry = x >> 32;
    }
    if (carry) {
        t.d[n++] = (uint32_t)carry;
    }
    t.n = n;
    return big_cmp(&t, c);
}

/* a -= b (a >= b). */
static void big_sub(big_t *a, const big_t *b) {
    int64_t borrow = 0;
    int i;
    for (i = 0; i < a->n; i++) {
        int64_t x = (int64_t)a->d[i] - (i < b->n ? b->d[i] : 0) - borrow;
        borrow = x < 0;
        a->d[i] = (uint32_t)x;
    }
    while (a->n > 0 && a->d[a->n - 1] == 0) {
        a->n--;
    }
}

#if defined(__SIZEOF_INT128__)
#define CODEC_U128 1
__extension__ typedef unsigned __int128 codec_u128_t;

static codec_u128_t big_u128(const big_t *a) {
    codec_u128_t v = 0;
    int i;
    for (i = a->n - 1; i >= 0; i--) {
        v = (v << 32) | a->d[i];
    }
    return v;
}

/* The digit loop of `shortest` below on values that fit in 128 bits (see there). */
static void shortest_u128(codec_u128_t r, codec_u128_t s, codec_u128_t mp, codec_u128_t mm, int even,
                          char *digits, int *n) {
    for (;;) {
        int d = 0;
        int low;
        int high;
        r *= 10;
        mp *= 10;
        mm *= 10;
        while (r >= s) {
            r -= s;
            d++;
        }
        low = even ? r <= mm : r < mm;
        high = even ? r + mp >= s : r + mp > s;
        if (!low && !high) {
            digits[(*n)++] = (char)('0' + d);
            continue;
        }
        if (low && high) {
            codec_u128_t r2 = r + r; /* 2r against s: which of d, d + 1 is closer */
            if (r2 > s || (r2 == s && (d & 1))) {
                d++;
            }
        } else if (high) {
            d++;
        }
        digits[(*n)++] = (char)('0' + d);
        break;
    }
    digits[*n] = '\0';
}

/* The same digit loop in four 64-bit limbs (256 bits) for larger values: s < 2^224 keeps every
 * value under 20 s < 2^229 (float32 values of every magnitude, doubles within about 1e+/-60). */
typedef struct {
    uint64_t d[4]; /* little-endian limbs */
} w256_t;

static w256_t big_w256(const big_t *a) {
    w256_t v;
    int i;
    memset(&v, 0, sizeof v);
    for (i = 0; i < a->n; i++) {
        v.d[i / 2] |= (uint64_t)a->d[i] << (32 * (i % 2));
    }
    return v;
}

static void w256_mul10(w256_t *a) {
    codec_u128_t carry = 0;
    int i;
    for (i = 0; i < 4; i++) {
        codec_u128_t t = (codec_u128_t)a->d[i] * 10u + carry;
        a->d[i] = (uint64_t)t;
        carry = t >> 64;
    }
}

static w256_t w256_add(const w256_t *a, const w256_t *b) {
    w256_t t;
    uint64_t carry = 0;
    int i;
    for (i = 0; i < 4; i++) {
        uint64_t x = a->d[i] + carry;
        uint64_t c1 = x < carry;
        t.d[i] = x + b->d[i];
        carry = c1 + (t.d[i] < x);
    }
    return t;
}

static int w256_cmp(const w256_t *a, const w256_t *b) {
    int i;
    for (i = 3; i >= 0; i--) {
        if (a->d[i] != b->d[i]) {
            return a->d[i] < b->d[i] ? -1 : 1;
        }
    }
    return 0;
}

static void w256_sub(w256_t *a, const w256_t *b) {
    uint64_t borrow = 0;
    int i;
    for (i = 0; i < 4; i++) {
        uint64_t x = a->d[i] - b->d[i];
        uint64_t b1 = a->d[i] < b->d[i];
        a->d[i] = x - borrow;
        borrow = b1 + (x < borrow);
    }
}

static void shortest_w256(w256_t r, w256_t s, w256_t mp, w256_t mm, int even, char *digits, int *n) {
    for (;;) {
        int d = 0;
        int low;
        int high;
        w256_t t;
        w256_mul10(&r);
        w256_mul10(&mp);
        w256_mul10(&mm);
        while (w256_cmp(&r, &s) >= 0) {
            w256_sub(&r, &s);
            d++;
        }
        low = even ? w256_cmp(&r, &mm) <= 0 : w256_cmp(&r, &mm) < 0;
        t = w256_add(&r, &mp);
        high = even ? w256_cmp(&t, &s) >= 0 : w256_cmp(&t, &s) > 0;
        if (!low && !high) {
            digits[(*n)++] = (char)('0' + d);
            continue;
        }
        if (low && high) {
            int c;
            t = w256_add(&r, &r); /* 2r against s: which of d, d + 1 is closer */
            c = w256_cmp(&t, &s);
            if (c > 0 || (c == 0 && (d & 1))) {
                d++;
            }
        } else if (high) {
            d++;
        }
        digits[(*n)++] = (char)('0' + d);
        break;
    }
    digits[*n] = '\0';
}
#endif

/* Shortest digits of v (finite, > 0), closest to v among the shortest; x = scientific exponent. */
static void shortest(double v, char *digits, int *n, int *x) {
    uint64_t bits;
    uint64_t f;
    int e;
    int be;
    int even;
    int unequal;
    int k;
    int bitlen = 0;
    big_t r;
    big_t s;
    big_t mp;
    big_t mm;
    memcpy(&bits, &v, sizeof bits);
    be = (int)((bits >> 52) & 0x7FF);
    f = bits & 0xFFFFFFFFFFFFFull;
    if (be == 0) {
        e = -1074;
    } else {
        f |= 1ull << 52;
        e = be - 1075;
    }
    even = (f & 1) == 0;
    unequal = f == (1ull << 52) && be > 1; /* the gap below v is half the gap above */
    big_set(&r, f);
    big_set(&s, 1);
    big_set(&mp, 1);
    big_set(&mm, 1);
    if (e >= 0) {
        big_shl(&r, e + (unequal ? 2 : 1));
        big_set(&s, unequal ? 4 : 2);
        big_shl(&mp, e + (unequal ? 1 : 0));
        big_shl(&mm, e);
    } else {
        big_shl(&r, unequal ? 2 : 1);
        big_shl(&s, (unequal ? 2 : 1) - e);
        big_set(&mp, unequal ? 2 : 1);
    }
    /* k = ceil(log10(v)) or one less, from the binary exponent; fixed below. */
    while (bitlen < 64 && (f >> bitlen) != 0) {
        bitlen++;
    }
    {
        double est = (e + bitlen - 1) * 0.30102999566398114 - 1e-10; /* log10(2^(e+bitlen-1)) */
        k = (int)est;
        k += est > (double)k; /* ceil, without libm */
    }
    if (k >= 0) {
        big_mul_pow10(&s, k);
    } else {
        big_mul_pow10(&r, -k);
        big_mul_pow10(&mp, -k);
        big_mul_pow10(&mm, -k);
    }
    /* v + m+ reaches 10^k: one more digit before the point. */
    while (even ? big_cmp_sum(&r, &mp, &s) >= 0 : big_cmp_sum(&r, &mp, &s) > 0) {
        big_mul_small(&s, 10);
        k++;
    }
    *n = 0;
#ifdef CODEC_U128
    if (s.n <= 3) {
        /* r, m+, m- < s < 2^96 from here on, and every value below stays under 20 s < 2^101:
         * the same steps in native 128-bit integers (most values of everyday magnitude). */
        shortest_u128(big_u128(&r), big_u128(&s), big_u128(&mp), big_u128(&mm), even, digits, n);
        *x = k - 1;
        return;
    }
    if (s.n <= 7) {
        shortest_w256(big_w256(&r), big_w256(&s), big_w256(&mp), big_w256(&mm), even, digits, n);
        *x = k - 1;
        return;
    }
#endif
    for (;;) {
        int d = 0;
        int low;
        int high;
        big_mul_small(&r, 10);
        big_mul_small(&mp, 10);
        big_mul_small(&mm, 10);
        while (big_cmp(&r, &s) >= 0) {
            big_sub(&r, &s);
            d++;
        }
        low = even ? big_cmp(&r, &mm) <= 0 : big_cmp(&r, &mm) < 0;
        high = even ? big_cmp_sum(&r, &mp, &s) >= 0 : big_cmp_sum(&r, &mp, &s) > 0;
        if (!low && !high) {
            digits[(*n)++] = (char)('0' + d);
            continue;
        }
        if (low && high) {
            int c = big_cmp_sum(&r, &r, &s); /* 2r against s: which of d, d + 1 is closer */
            if (c > 0 || (c == 0 && (d & 1))) {
                d++;
            }
        } else if (high) {
            d++;
        }
        digits[(*n)++] = (char)('0' + d);
        break;
    }
    digits[*n] = '\0';
    *x = k - 1;
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
    {
        int last; /* Grisu3 first: value = digits x 10^last; the exact search when it cannot tell */
        if (grisu3(v, digits, &n, &last)) {
            digits[n] = '\0';
            x = n - 1 + last;
        } else {
            shortest(v, digits, &n, &x);
        }
    }
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

size_t codec_json_format_double(double v, char *buf, size_t cap) {
    assert(buf != NULL || cap == 0);
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

size_t codec_json_format_float(float v, char *buf, size_t cap) {
    assert(buf != NULL || cap == 0);
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

size_t codec_json_format_string(const char *bytes, size_t n, char *buf, size_t cap) {
    assert(bytes != NULL || n == 0);
    assert(buf != NULL || cap == 0);
    codec_jw_t w;
    codec_jw_init(&w, buf, cap);
    codec_jw_string(&w, bytes, n);
    return codec_jw_finish(&w);
}
