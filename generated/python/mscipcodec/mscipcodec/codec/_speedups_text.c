/* The canonical JSON lines of the C accelerator (mscipcodec): scan_text(), float_text(); the CSV
 * text of float and time columns (repr_texts, relayout_texts, iso_texts). */
#include "_speedups.h"

/* ------------------------------------------------------------------------------ text */
/* scan_text: the canonical JSON lines of docs/conformance.md section 4, written here for the
 * fields of fast entries; any other field entry (slow layout, size mismatch, NaN, invalid bool)
 * is the pure-Python line of that entry, a packet that does not split into fields the pure-Python
 * line of the packet. The text is ASCII. */
static int text_reserve(Text *t, Py_ssize_t more) {
    if (t->len + more <= t->cap) {
        return 0;
    }
    Py_ssize_t cap = t->cap ? t->cap : 1 << 16;
    while (cap < t->len + more) {
        cap *= 2;
    }
    char *p = PyMem_Realloc(t->p, (size_t)cap);
    if (p == NULL) {
        PyErr_NoMemory();
        return -1;
    }
    t->p = p;
    t->cap = cap;
    return 0;
}

static int text_put(Text *t, const char *s, Py_ssize_t n) {
    if (text_reserve(t, n) < 0) {
        return -1;
    }
    memcpy(t->p + t->len, s, (size_t)n);
    t->len += n;
    return 0;
}

/* Decimal digits of v into the buffer (room reserved by the caller). */
static void text_u64(Text *t, unsigned long long v) {
    char d[20];
    int k = 0;
    do {
        d[k++] = (char)('0' + v % 10);
        v /= 10;
    } while (v);
    while (k) {
        t->p[t->len++] = d[--k];
    }
}

static void text_i64(Text *t, long long v) {
    if (v < 0) {
        t->p[t->len++] = '-';
        text_u64(t, 0ULL - (unsigned long long)v);
    } else {
        text_u64(t, (unsigned long long)v);
    }
}

/* ------------------------------------------------------------------------------ float text */
/* Shortest round-trip digits by Grisu3: grisu3.h, the same file as the C runtime's
 * (generator/targets/c/runtime/src/grisu3.h, copied beside this file into the package). */
#include "grisu3.h"

/* The layout of repr(float) for the digits d[0..n) (value 0.d1d2...dn x 10^decpt) after an
 * optional '-': format_float_short's for repr, exponent form when the decimal point falls before
 * -4 or after 16 digits ("1e+16", "1.5e-05"), else fixed with at least one digit after the point
 * ("100.0", "0.001"). out has room for n + 24 bytes; the length is returned. */
static int repr_layout(char *out, int neg, const char *d, int n, int decpt) {
    char *o = out;
    if (neg) {
        *o++ = '-';
    }
    if (decpt <= -4 || decpt > 16) {
        *o++ = d[0];
        if (n > 1) {
            *o++ = '.';
            memcpy(o, d + 1, (size_t)(n - 1));
            o += n - 1;
        }
        int x = decpt - 1;
        *o++ = 'e';
        *o++ = x < 0 ? '-' : '+';
        if (x < 0) {
            x = -x;
        }
        if (x >= 100) {
            *o++ = (char)('0' + x / 100);
            x %= 100;
        }
        *o++ = (char)('0' + x / 10);
        *o++ = (char)('0' + x % 10);
    } else if (decpt <= 0) {
        *o++ = '0';
        *o++ = '.';
        memset(o, '0', (size_t)-decpt);
        o += -decpt;
        memcpy(o, d, (size_t)n);
        o += n;
    } else if (decpt < n) {
        memcpy(o, d, (size_t)decpt);
        o += decpt;
        *o++ = '.';
        memcpy(o, d + decpt, (size_t)(n - decpt));
        o += n - decpt;
    } else {
        memcpy(o, d, (size_t)n);
        o += n;
        memset(o, '0', (size_t)(decpt - n));
        o += decpt - n;
        *o++ = '.';
        *o++ = '0';
    }
    return (int)(o - out);
}

/* repr(float) of a finite double into out (at least 32 bytes): its length, or -1 when Grisu3 gave
 * up (repr_layout). */
int repr_double(double v, char *out) {
    int neg = signbit(v) != 0;
    if (neg) {
        v = -v;
    }
    if (v == 0.0) {
        memcpy(out, neg ? "-0.0" : "0.0", neg ? 4 : 3);
        return neg ? 4 : 3;
    }
    char d[20];
    int n, e;
    if (!grisu3(v, d, &n, &e)) {
        return -1;
    }
    return repr_layout(out, neg, d, n, n + e);
}

/* A finite double as repr(float) prints it; the infinities as the canonical strings. */
static int text_double(Text *t, double d) {
    if (d == Py_HUGE_VAL) {
        return text_put(t, "\"inf\"", 5);
    }
    if (d == -Py_HUGE_VAL) {
        return text_put(t, "\"-inf\"", 6);
    }
    if (text_reserve(t, 32) < 0) {
        return -1;
    }
    int n = repr_double(d, t->p + t->len);
    if (n >= 0) {
        t->len += n;
        return 0;
    }
    char *s = PyOS_double_to_string(d, 'r', 0, Py_DTSF_ADD_DOT_0, NULL);
    if (s == NULL) {
        return -1;
    }
    int rc = text_put(t, s, (Py_ssize_t)strlen(s));
    PyMem_Free(s);
    return rc;
}

/* canonical.string_text: byte b is U+00bb; ", \ and bytes outside 0x20..0x7e escaped. */
static int text_string(Text *t, const unsigned char *p, Py_ssize_t n) {
    if (text_reserve(t, 6 * n + 2) < 0) {
        return -1;
    }
    static const char hex[] = "0123456789abcdef";
    char *o = t->p + t->len;
    *o++ = '"';
    for (Py_ssize_t k = 0; k < n; k++) {
        unsigned char b = p[k];
        if (b == '"' || b == '\\') {
            *o++ = '\\';
            *o++ = (char)b;
        } else if (b < 0x20 || b >= 0x7F) {
            memcpy(o, "\\u00", 4);
            o[4] = hex[b >> 4];
            o[5] = hex[b & 15];
            o += 6;
        } else {
            *o++ = (char)b;
        }
    }
    *o++ = '"';
    t->len = o - t->p;
    return 0;
}

/* One element; 0, TEXT_NOT_FAST (a NaN or an invalid bool), or -1 with an exception. */
static int text_element(Text *t, const Item *it, const unsigned char *p) {
    if (text_reserve(t, 24) < 0) {
        return -1;
    }
    switch (it->kind) {
    case 'f': {
        unsigned int bits = load32(p);
        float f;
        memcpy(&f, &bits, 4);
        return f != f ? TEXT_NOT_FAST : text_double(t, (double)f);
    }
    case 'd': {
        unsigned long long bits = load(p, 8);
        double d;
        memcpy(&d, &bits, 8);
        return d != d ? TEXT_NOT_FAST : text_double(t, d);
    }
    case 'u':
    case 'e':
    case 'F':
        text_u64(t, load(p, it->size));
        return 0;
    case 'i': {
        unsigned long long v = load(p, it->size);
        int shift = 64 - 8 * it->size;
        text_i64(t, shift ? (long long)(v << shift) >> shift : (long long)v);
        return 0;
    }
    case '?':
        if (p[0] > 1) {
            return TEXT_NOT_FAST;
        }
        return p[0] ? text_put(t, "true", 4) : text_put(t, "false", 5);
    case 'c':
    case 's':
        return text_string(t, p, it->size);
    default:
        PyErr_Format(PyExc_SystemError, "bad item kind %c", it->kind);
        return -1;
    }
}

/* The entry of a fast field; 0, TEXT_NOT_FAST, or -1 with an exception. */
static int text_fast_field(Text *t, const Entry *e, const unsigned char *p) {
    if (text_put(t, PyBytes_AS_STRING(e->head), PyBytes_GET_SIZE(e->head)) < 0) {
        return -1;
    }
    for (int k = 0; k < e->nitems; k++) {
        const Item *it = &e->items[k];
        if ((k && text_put(t, ",", 1) < 0) ||
            text_put(t, PyBytes_AS_STRING(it->key), PyBytes_GET_SIZE(it->key)) < 0) {
            return -1;
        }
        if (it->count < 0) {
            int rc = text_element(t, it, p);
            if (rc) {
                return rc;
            }
            p += it->size;
            continue;
        }
        if (text_put(t, "[", 1) < 0) {
            return -1;
        }
        for (int j = 0; j < it->count; j++) {
            int rc = (j && text_put(t, ",", 1) < 0) ? -1 : text_element(t, it, p);
            if (rc) {
                return rc;
            }
            p += it->size;
        }
        if (text_put(t, "]", 1) < 0) {
            return -1;
        }
    }
    return text_put(t, "}}", 2);
}

/* Appends the str a Python line writer returned (stolen); -1 with an exception. */
static int text_str(Text *t, PyObject *s) {
    if (s == NULL) {
        return -1;
    }
    Py_ssize_t n;
    const char *u = PyUnicode_Check(s) ? PyUnicode_AsUTF8AndSize(s, &n) : NULL;
    if (u == NULL) {
        if (!PyErr_Occurred()) {
            PyErr_SetString(PyExc_TypeError, "a line writer returned no str");
        }
        Py_DECREF(s);
        return -1;
    }
    int rc = text_put(t, u, n);
    Py_DECREF(s);
    return rc;
}

int text_packet(Text *t, const unsigned char *p, Py_ssize_t n, Py_ssize_t offset) {
    int set_id = p[SET_OFFSET];
    const unsigned char *pl = p + HEADER_SIZE;
    Py_ssize_t len = n - HEADER_SIZE - CHECKSUM_SIZE;
    for (Py_ssize_t o = 0; o < len;) {
        int bad = len - o < FIELD_HEADER_SIZE;
        if (!bad) {
            int descriptor = pl[o + FIELD_DESCRIPTOR_OFFSET];
            int data_length = pl[o + FIELD_LENGTH_OFFSET] - field_length_adjust(set_id, descriptor);
            bad = data_length < 0 || FIELD_HEADER_SIZE + data_length > len - o;
            o += FIELD_HEADER_SIZE + (data_length < 0 ? 0 : data_length);
        }
        if (bad) { /* a payload that does not split into fields: the pure-Python line */
            if (text_str(t, PyObject_CallFunction(py_packet_line, "y#n", (const char *)p, n, offset)) < 0) {
                return -1;
            }
            return text_put(t, "\n", 1);
        }
    }
    if (text_reserve(t, 64) < 0) {
        return -1;
    }
    memcpy(t->p + t->len, "{\"offset\":", 10);
    t->len += 10;
    text_i64(t, (long long)offset);
    memcpy(t->p + t->len, ",\"set\":", 7);
    t->len += 7;
    text_u64(t, (unsigned long long)set_id);
    memcpy(t->p + t->len, ",\"fields\":[", 11);
    t->len += 11;
    for (Py_ssize_t o = 0, k = 0; o < len; k++) {
        int descriptor = pl[o + FIELD_DESCRIPTOR_OFFSET];
        Py_ssize_t data_length = pl[o + FIELD_LENGTH_OFFSET] - field_length_adjust(set_id, descriptor);
        const unsigned char *data = pl + o + FIELD_HEADER_SIZE;
        o += FIELD_HEADER_SIZE + data_length;
        Entry *e = entry_for(set_id, descriptor);
        if (e == NULL || (k && text_put(t, ",", 1) < 0)) {
            return -1;
        }
        Py_ssize_t mark = t->len;
        if (e->kind == ENTRY_FAST && e->size == data_length) {
            int rc = text_fast_field(t, e, data);
            if (rc < 0) {
                return -1;
            }
            if (rc == 0) {
                continue;
            }
            t->len = mark; /* a NaN or an invalid bool: the pure-Python entry */
        }
        if (text_str(t, PyObject_CallFunction(py_field_line, "iiy#", set_id, descriptor, (const char *)data,
                                              data_length)) < 0) {
            return -1;
        }
    }
    return text_put(t, "]}\n", 3);
}

/* The canonical line of a frame (docs/conformance.md section 5) into t. */
int text_foreign(Text *t, const unsigned char *p, Py_ssize_t n, Py_ssize_t offset) {
    if (text_reserve(t, 2 * n + 64) < 0) {
        return -1;
    }
    memcpy(t->p + t->len, "{\"offset\":", 10);
    t->len += 10;
    text_i64(t, (long long)offset);
    if (p[0] == 0xD3) {
        memcpy(t->p + t->len, ",\"rtcm\":", 8);
        t->len += 8;
        text_u64(t, (unsigned long long)(p[3] << 4 | p[4] >> 4));
        memcpy(t->p + t->len, ",\"length\":", 10);
        t->len += 10;
        text_u64(t, (unsigned long long)(n - 6));
        memcpy(t->p + t->len, "}\n", 2);
        t->len += 2;
        return 0;
    }
    memcpy(t->p + t->len, ",\"nmea\":\"", 9);
    t->len += 9;
    for (Py_ssize_t k = 0; k + 2 < n; k++) {
        if (p[k] == '"' || p[k] == '\\') {
            t->p[t->len++] = '\\';
        }
        t->p[t->len++] = (char)p[k];
    }
    memcpy(t->p + t->len, "\"}\n", 3);
    t->len += 3;
    return 0;
}

/* The line of the pending skip run, if any, and the run emptied. */
int text_skip(Text *t, SkipRun *s) {
    Py_ssize_t have = PyByteArray_GET_SIZE(s->bytes);
    if (have == 0) {
        return 0;
    }
    static const char hex[] = "0123456789abcdef";
    const unsigned char *b = (const unsigned char *)PyByteArray_AS_STRING(s->bytes);
    if (text_reserve(t, 2 * have + 48) < 0) {
        return -1;
    }
    memcpy(t->p + t->len, "{\"offset\":", 10);
    t->len += 10;
    text_i64(t, (long long)s->at);
    memcpy(t->p + t->len, ",\"skipped\":\"", 12);
    t->len += 12;
    for (Py_ssize_t k = 0; k < have; k++) {
        t->p[t->len++] = hex[b[k] >> 4];
        t->p[t->len++] = hex[b[k] & 15];
    }
    memcpy(t->p + t->len, "\"}\n", 3);
    t->len += 3;
    return PyByteArray_Resize(s->bytes, 0);
}

/* scan_text(buf: bytearray, base: int, skip: bytearray, skip_at: int, final: bool)
 *   -> (text: bytes, consumed, skip_at): the canonical lines of the packets (and the skip runs
 * before them) that scan() would return as events; a skip run still open stays in `skip`. */
PyObject *scan_text(PyObject *self, PyObject *args) {
    (void)self;
    if (packet_type == NULL || py_field_line == NULL) {
        PyErr_SetString(PyExc_RuntimeError, PROTOCOL_PACKAGE ".codec._speedups.setup() was not called");
        return NULL;
    }
    PyObject *buf;
    Py_ssize_t base;
    SkipRun skip;
    int final;
    if (!PyArg_ParseTuple(args, "O!nO!np", &PyByteArray_Type, &buf, &base, &PyByteArray_Type, &skip.bytes,
                          &skip.at, &final)) {
        return NULL;
    }
    /* The fallbacks run Python code: work on a private copy of the buffer. */
    PyObject *copy = PyBytes_FromStringAndSize(PyByteArray_AS_STRING(buf), PyByteArray_GET_SIZE(buf));
    if (copy == NULL) {
        return NULL;
    }
    Text t = {NULL, 0, 0};
    PyObject *events = PyList_New(0); /* stays empty: skip runs are written as text */
    PyObject *result = NULL;
    if (events != NULL) {
        int gc = gc_pause();
        Py_ssize_t pos = scan_core((const unsigned char *)PyBytes_AS_STRING(copy), PyBytes_GET_SIZE(copy),
                                   base, final, SCAN_TEXT, &t, &skip, events, NULL);
        gc_resume(gc);
        if (pos >= 0) {
            result = Py_BuildValue("y#nn", t.p ? t.p : "", t.len, pos, skip.at);
        }
    }
    Py_XDECREF(events);
    Py_DECREF(copy);
    PyMem_Free(t.p);
    return result;
}

/* ------------------------------------------------------------------------- float columns */
/* The CSV text of float columns (logs/arrow.py `float_texts`): one pass over a column, its texts
 * as the offsets (int64, n + 1 of them) and the bytes of an Arrow string array. */
static PyObject *column_result(Text *t, PyObject *offsets) {
    PyObject *body = PyBytes_FromStringAndSize(t->p ? t->p : "", t->len);
    PyMem_Free(t->p);
    if (body == NULL) {
        Py_DECREF(offsets);
        return NULL;
    }
    PyObject *out = PyTuple_Pack(2, offsets, body);
    Py_DECREF(offsets);
    Py_DECREF(body);
    return out;
}

/* The texts of a float column in one pass (repr_texts, f32_texts): the values [offset, offset + n)
 * of a buffer of `width`-byte floats, "nan", "inf", "-inf" for those, the empty text where valid
 * (bytes, one per value, or None) is 0. print(src, out) writes the text of the finite value stored
 * at src into out (room bytes) and returns its length; -1 with a Python exception set; -2 when it
 * gave up (the result is then None). */
typedef int (*FloatPrinter)(const char *src, char *out);

static PyObject *float_column(PyObject *args, const char *name, Py_ssize_t width, Py_ssize_t room,
                              FloatPrinter print) {
    Py_buffer vals, valid = {0};
    Py_ssize_t offset, n;
    if (!PyArg_ParseTuple(args, "y*nn|z*", &vals, &offset, &n, &valid)) {
        return NULL;
    }
    PyObject *offsets = NULL;
    if (offset < 0 || n < 0 || (offset + n) > vals.len / width || (valid.buf != NULL && valid.len < n)) {
        PyErr_Format(PyExc_ValueError, "%s: the buffers are too short", name);
        goto done;
    }
    offsets = PyBytes_FromStringAndSize(NULL, (n + 1) * (Py_ssize_t)sizeof(long long));
    if (offsets == NULL) {
        goto done;
    }
    long long *at = (long long *)PyBytes_AS_STRING(offsets);
    const unsigned char *ok = valid.buf;
    Text t = {NULL, 0, 0};
    at[0] = 0;
    for (Py_ssize_t i = 0; i < n; i++) {
        const char *src = (const char *)vals.buf + (offset + i) * width;
        if (ok == NULL || ok[i]) {
            double v;
            if (width == (Py_ssize_t)sizeof(double)) {
                memcpy(&v, src, sizeof v);
            } else {
                float f;
                memcpy(&f, src, sizeof f);
                v = f;
            }
            if (text_reserve(&t, room) < 0) {
                PyMem_Free(t.p);
                Py_CLEAR(offsets);
                goto done;
            }
            int k;
            if (isnan(v)) {
                k = 3;
                memcpy(t.p + t.len, "nan", 3);
            } else if (isinf(v)) {
                k = v < 0 ? 4 : 3;
                memcpy(t.p + t.len, v < 0 ? "-inf" : "inf", (size_t)k);
            } else if ((k = print(src, t.p + t.len)) < 0) {
                PyMem_Free(t.p);
                Py_CLEAR(offsets);
                if (k == -2) {
                    Py_INCREF(Py_None);
                    offsets = Py_None;
                }
                goto done;
            }
            t.len += k;
        }
        at[i + 1] = (long long)t.len;
    }
    PyBuffer_Release(&vals);
    if (valid.buf != NULL) {
        PyBuffer_Release(&valid);
    }
    return column_result(&t, offsets);
done:
    PyBuffer_Release(&vals);
    if (valid.buf != NULL) {
        PyBuffer_Release(&valid);
    }
    return offsets;
}

/* repr(float) of a finite float64 (repr_double; Python's own where Grisu3 gives up). */
static int print_double(const char *src, char *out) {
    double v;
    memcpy(&v, src, sizeof v);
    int k = repr_double(v, out);
    if (k >= 0) {
        return k;
    }
    char *r = PyOS_double_to_string(v, 'r', 0, Py_DTSF_ADD_DOT_0, NULL);
    if (r == NULL) {
        return -1;
    }
    k = (int)strlen(r);
    memcpy(out, r, (size_t)k);
    PyMem_Free(r);
    return k;
}

/* repr_texts(values, offset, n, valid): repr(float) of the float64 values [offset, offset + n)
 * of a buffer ("nan", "inf", "-inf" for those); valid (bytes, one per value, or None): the
 * empty text where 0. */
PyObject *repr_texts(PyObject *self, PyObject *args) {
    (void)self;
    return float_column(args, "repr_texts", (Py_ssize_t)sizeof(double), 32, print_double);
}

/* The shortest digits of a finite positive float32 where Grisu3 gives up (about 1% of all float32
 * values, mostly above 2^24): for 1 to 9 digits, the value rounded to that many significant digits
 * (printf's "%.*e", exact and half to even, as double-conversion's exact fallback breaks a tie),
 * then, when the lower neighbour is the closer one (lower_closer: the interval of values that read
 * back as f is wider above it), the next such decimal up; the first that reads back as f (strtof,
 * correctly rounded) is the shortest and the closest. Its digits into d (no trailing zero), their
 * count in *n; the decimal point's position returned (value 0.d1d2... x 10^decpt), INT_MIN when
 * the C library printed something unexpected. */
static int single_digits(float f, int lower_closer, char *d, int *n) {
    for (int p = 1; p <= 9; p++) {
        char s[40];
        int len = snprintf(s, sizeof s, "%.*e", p - 1, (double)f);
        char *e = strchr(s, 'e');
        if (len <= 0 || len >= (int)sizeof s || e == NULL) {
            return INT_MIN;
        }
        int k = 0;
        for (const char *c = s; c < e; c++) {
            if (*c >= '0' && *c <= '9') {
                d[k++] = *c;
            }
        }
        int exp10 = atoi(e + 1);
        for (int up = 0; up <= lower_closer; up++) {
            if (up) { /* one unit up in the last digit */
                int i = k - 1;
                while (i >= 0 && d[i] == '9') {
                    d[i--] = '0';
                }
                if (i < 0) {
                    d[0] = '1';
                    memset(d + 1, '0', (size_t)(k - 1));
                    exp10++;
                } else {
                    d[i]++;
                }
            }
            char t[40];
            snprintf(t, sizeof t, "%c.%.*se%d", d[0], k - 1, d + 1, exp10);
            if (strtof(t, NULL) == f) {
                while (k > 1 && d[k - 1] == '0') {
                    k--;
                }
                *n = k;
                return exp10 + 1;
            }
        }
    }
    return INT_MIN;
}

/* The shortest digits of a finite float32 (the digits pyarrow's cast to string prints: Grisu3 with
 * a float's boundaries, as double-conversion's SHORTEST_SINGLE) laid out as repr(float) lays out
 * the same digits (repr_layout; what relayout_one makes of pyarrow's text); where Grisu3 gives up,
 * single_digits' (-1 when the C library failed it: the caller falls back to pyarrow's digits). out
 * has room for 40 bytes. */
static int repr_single(float f, char *out) {
    unsigned int bits;
    memcpy(&bits, &f, 4);
    int neg = (bits >> 31) != 0;
    unsigned int frac = bits & 0x7FFFFFu;
    int bexp = (int)((bits >> 23) & 0xFF);
    if (bexp == 0 && frac == 0) {
        memcpy(out, neg ? "-0.0" : "0.0", neg ? 4 : 3);
        return neg ? 4 : 3;
    }
    DiyFp w;
    if (bexp) {
        w.f = frac | 0x800000u;
        w.e = bexp - 150;
    } else {
        w.f = frac;
        w.e = -149;
    }
    char d[20];
    int n, e;
    if (grisu3_bounded(w, frac == 0 && bexp > 1, d, &n, &e)) {
        return repr_layout(out, neg, d, n, n + e);
    }
    int decpt = single_digits(neg ? -f : f, frac == 0 && bexp > 1, d, &n);
    return decpt == INT_MIN ? -1 : repr_layout(out, neg, d, n, decpt);
}

/* repr_single of a float32 as stored; -2 (give up) where the C library failed it. */
static int print_single(const char *src, char *out) {
    float v;
    memcpy(&v, src, sizeof v);
    int k = repr_single(v, out);
    return k < 0 ? -2 : k;
}

/* f32_texts(values, offset, n, valid): the float32 values [offset, offset + n) of a buffer as the
 * CSV prints them (repr_single; "nan", "inf", "-inf" as pyarrow prints those), the empty text where
 * valid (bytes, one per value, or None) is 0; None when repr_single failed on a value (the C
 * library's printf or strtof: the caller then takes pyarrow's digits, relayout_texts). */
PyObject *f32_texts(PyObject *self, PyObject *args) {
    (void)self;
    return float_column(args, "f32_texts", (Py_ssize_t)sizeof(float), 40, print_single);
}

/* One text of shortest digits ("-1.5e-05", "0.001", "100", pyarrow's) laid out as repr(float)
 * (repr_layout); 0 when it is not such a number (nan, inf: the caller copies it as it is). */
static int relayout_one(const char *s, Py_ssize_t len, char *out) {
    char d[40];
    int n = 0, zeros = 0, point = 0, neg = 0, seen_point = 0, exp = 0, exp_neg = 0;
    Py_ssize_t i = 0;
    if (i < len && s[i] == '-') {
        neg = 1;
        i++;
    }
    if (i >= len) {
        return 0;
    }
    for (; i < len && ((s[i] >= '0' && s[i] <= '9') || s[i] == '.'); i++) {
        if (s[i] == '.') {
            if (seen_point) {
                return 0;
            }
            seen_point = 1;
        } else if (n == 0 && s[i] == '0') {
            point -= seen_point; /* a leading zero: after the point, the value is 10x smaller */
        } else {
            point += !seen_point;
            if (s[i] == '0') {
                zeros++; /* kept only when a non-zero digit follows */
                continue;
            }
            if (n + zeros >= (int)sizeof d) {
                return 0;
            }
            memset(d + n, '0', (size_t)zeros);
            n += zeros;
            zeros = 0;
            d[n++] = s[i];
        }
    }
    if (i < len) {
        if (s[i] != 'e' && s[i] != 'E') {
            return 0;
        }
        i++;
        if (i < len && (s[i] == '+' || s[i] == '-')) {
            exp_neg = s[i] == '-';
            i++;
        }
        if (i >= len) {
            return 0;
        }
        for (; i < len; i++) {
            if (s[i] < '0' || s[i] > '9' || exp > 10000) {
                return 0;
            }
            exp = exp * 10 + (s[i] - '0');
        }
    }
    if (n == 0) {
        memcpy(out, neg ? "-0.0" : "0.0", neg ? 4 : 3);
        return neg ? 4 : 3;
    }
    int decpt = point + (exp_neg ? -exp : exp);
    if (decpt < -400 || decpt > 400) {
        return 0;
    }
    return repr_layout(out, neg, d, n, decpt);
}

/* relayout_texts(offsets, data, offset, n, wide): the texts [offset, offset + n) of an Arrow
 * string array (offsets int32, or int64 when wide) of shortest digits (pyarrow's float32 text)
 * laid out as repr(float) prints the same digits; texts that are not numbers as they are. */
PyObject *relayout_texts(PyObject *self, PyObject *args) {
    (void)self;
    Py_buffer offs, data;
    Py_ssize_t offset, n;
    int wide;
    if (!PyArg_ParseTuple(args, "y*y*nnp", &offs, &data, &offset, &n, &wide)) {
        return NULL;
    }
    PyObject *offsets = NULL;
    Py_ssize_t width = wide ? 8 : 4;
    if (offset < 0 || n < 0 || (offset + n + 1) > offs.len / width) {
        PyErr_SetString(PyExc_ValueError, "relayout_texts: the buffers are too short");
        goto done;
    }
    offsets = PyBytes_FromStringAndSize(NULL, (n + 1) * (Py_ssize_t)sizeof(long long));
    if (offsets == NULL) {
        goto done;
    }
    long long *at = (long long *)PyBytes_AS_STRING(offsets);
    Text t = {NULL, 0, 0};
    at[0] = 0;
    for (Py_ssize_t i = 0; i < n; i++) {
        long long a, b;
        if (wide) {
            memcpy(&a, (const char *)offs.buf + (offset + i) * 8, 8);
            memcpy(&b, (const char *)offs.buf + (offset + i + 1) * 8, 8);
        } else {
            int a32, b32;
            memcpy(&a32, (const char *)offs.buf + (offset + i) * 4, 4);
            memcpy(&b32, (const char *)offs.buf + (offset + i + 1) * 4, 4);
            a = a32;
            b = b32;
        }
        if (a < 0 || b < a || b > (long long)data.len) {
            PyErr_SetString(PyExc_ValueError, "relayout_texts: an offset out of the data");
            PyMem_Free(t.p);
            Py_CLEAR(offsets);
            goto done;
        }
        const char *s = (const char *)data.buf + a;
        Py_ssize_t len = (Py_ssize_t)(b - a);
        if (text_reserve(&t, len + 64) < 0) {
            PyMem_Free(t.p);
            Py_CLEAR(offsets);
            goto done;
        }
        int k = len ? relayout_one(s, len, t.p + t.len) : 0;
        if (k == 0 && len) {
            memcpy(t.p + t.len, s, (size_t)len);
            k = (int)len;
        }
        t.len += k;
        at[i + 1] = (long long)t.len;
    }
    PyBuffer_Release(&offs);
    PyBuffer_Release(&data);
    return column_result(&t, offsets);
done:
    PyBuffer_Release(&offs);
    PyBuffer_Release(&data);
    return offsets;
}

/* iso_texts(t_ns, offset, n, valid): the `time` text of UTC ns [offset, offset + n) of an int64
 * buffer as logs/timebase.iso writes it, 27 bytes a row ("2026-03-14T09:14:02.010000Z": the
 * microseconds truncated toward zero, as logs/writers.iso_texts); a null (valid: bytes, one per
 * row, or None) as the time 0. None when a year is before 1000 or after 9999. */
PyObject *iso_texts(PyObject *self, PyObject *args) {
    (void)self;
    Py_buffer ns, valid = {0};
    Py_ssize_t offset, n;
    if (!PyArg_ParseTuple(args, "y*nn|z*", &ns, &offset, &n, &valid)) {
        return NULL;
    }
    PyObject *out = NULL;
    if (offset < 0 || n < 0 || (offset + n) > ns.len / 8 || (valid.buf != NULL && valid.len < n)) {
        PyErr_SetString(PyExc_ValueError, "iso_texts: the buffers are too short");
        goto done;
    }
    out = PyBytes_FromStringAndSize(NULL, n * 27);
    if (out == NULL) {
        goto done;
    }
    char *o = PyBytes_AS_STRING(out);
    const unsigned char *ok = valid.buf;
    long long last_sec = 0;
    char head[19];
    int have = 0;
    for (Py_ssize_t i = 0; i < n; i++, o += 27) {
        long long t = 0;
        if (ok == NULL || ok[i]) {
            memcpy(&t, (const char *)ns.buf + (offset + i) * 8, 8);
        }
        long long us = t / 1000; /* toward zero */
        long long sec = us / 1000000, frac = us % 1000000;
        if (frac < 0) { /* the second floored, as numpy's divmod */
            frac += 1000000;
            sec--;
        }
        if (!have || sec != last_sec) {
            long long days = sec / 86400, rem = sec % 86400;
            if (rem < 0) {
                rem += 86400;
                days--;
            }
            /* civil date of a day count (H. Hinnant's days_from_civil, inverted) */
            long long z = days + 719468;
            long long era = (z >= 0 ? z : z - 146096) / 146097;
            long long doe = z - era * 146097;
            long long yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
            long long doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
            long long mp = (5 * doy + 2) / 153;
            long long d = doy - (153 * mp + 2) / 5 + 1;
            long long m = mp < 10 ? mp + 3 : mp - 9;
            long long y = yoe + era * 400 + (m <= 2);
            if (y < 1000 || y > 9999) {
                Py_CLEAR(out);
                Py_INCREF(Py_None);
                out = Py_None;
                goto done;
            }
            long long f[6] = {y, m, d, rem / 3600, rem / 60 % 60, rem % 60};
            static const int at[6] = {0, 5, 8, 11, 14, 17}, width[6] = {4, 2, 2, 2, 2, 2};
            memcpy(head, "0000-00-00T00:00:00", 19);
            for (int k = 0; k < 6; k++) {
                long long v = f[k];
                for (int j = width[k] - 1; j >= 0; j--) {
                    head[at[k] + j] = (char)('0' + v % 10);
                    v /= 10;
                }
            }
            last_sec = sec;
            have = 1;
        }
        memcpy(o, head, 19);
        o[19] = '.';
        for (int j = 25; j >= 20; j--) {
            o[j] = (char)('0' + frac % 10);
            frac /= 10;
        }
        o[26] = 'Z';
    }
done:
    PyBuffer_Release(&ns);
    if (valid.buf != NULL) {
        PyBuffer_Release(&valid);
    }
    return out;
}

/* ------------------------------------------------------------------------------- CSV rows */
/* csv_rows(columns, n): the CSV rows (cells joined by ",", each row ended by "\n") of n rows of
 * columns, as bytes: what pyarrow's CSV writer writes (quoting_style "none", no header) for the
 * columns logs/export.py hands it, in one pass. A column is a tuple (kind, values, body, offset,
 * valid): kind 0 int64 values, 1 uint64 values (decimal digits), 2 text (values: int32 offsets
 * into body, its bytes copied as they are), 3 text with int64 offsets, 4 bools (values: one byte
 * a row, "true" / "false"); rows [offset, offset + n) of it; valid (bytes, one a row, or None):
 * the empty cell where 0. */
typedef struct {
    int kind;
    Py_buffer values, body, valid;
    Py_ssize_t offset;
} CsvColumn;

static void csv_release(CsvColumn *c, Py_ssize_t k) {
    for (Py_ssize_t j = 0; j < k; j++) {
        PyBuffer_Release(&c[j].values);
        if (c[j].body.buf != NULL) {
            PyBuffer_Release(&c[j].body);
        }
        if (c[j].valid.buf != NULL) {
            PyBuffer_Release(&c[j].valid);
        }
    }
    PyMem_Free(c);
}

/* The text span [a, b) of row i of a text column; -1 with an exception when it is out of its body. */
static int csv_span(const CsvColumn *c, Py_ssize_t i, long long *a, long long *b) {
    if (c->kind == 2) {
        int a32, b32;
        memcpy(&a32, (const char *)c->values.buf + (c->offset + i) * 4, 4);
        memcpy(&b32, (const char *)c->values.buf + (c->offset + i + 1) * 4, 4);
        *a = a32;
        *b = b32;
    } else {
        memcpy(a, (const char *)c->values.buf + (c->offset + i) * 8, 8);
        memcpy(b, (const char *)c->values.buf + (c->offset + i + 1) * 8, 8);
    }
    if (*a < 0 || *b < *a || *b > (long long)c->body.len) {
        PyErr_SetString(PyExc_ValueError, "csv_rows: an offset out of the text");
        return -1;
    }
    return 0;
}

PyObject *csv_rows(PyObject *self, PyObject *args) {
    (void)self;
    PyObject *list;
    Py_ssize_t n;
    if (!PyArg_ParseTuple(args, "O!n", &PyList_Type, &list, &n)) {
        return NULL;
    }
    Py_ssize_t k = PyList_GET_SIZE(list);
    if (n < 0 || k == 0) {
        PyErr_SetString(PyExc_ValueError, "csv_rows: needs n >= 0 and a column");
        return NULL;
    }
    CsvColumn *c = PyMem_Calloc((size_t)k, sizeof *c);
    if (c == NULL) {
        return PyErr_NoMemory();
    }
    Py_ssize_t bound = n; /* the line ends, then each column's widest text */
    for (Py_ssize_t j = 0; j < k; j++) {
        PyObject *body = NULL, *valid = NULL;
        if (!PyArg_ParseTuple(PyList_GET_ITEM(list, j), "iy*OnO", &c[j].kind, &c[j].values, &body,
                              &c[j].offset, &valid)) {
            csv_release(c, j);
            return NULL;
        }
        int bad = c[j].kind < 0 || c[j].kind > 4 || c[j].offset < 0;
        if (!bad && body != Py_None && PyObject_GetBuffer(body, &c[j].body, PyBUF_SIMPLE) < 0) {
            csv_release(c, j + 1);
            return NULL;
        }
        if (!bad && valid != Py_None && PyObject_GetBuffer(valid, &c[j].valid, PyBUF_SIMPLE) < 0) {
            csv_release(c, j + 1);
            return NULL;
        }
        Py_ssize_t width = c[j].kind <= 1 ? 8 : c[j].kind == 2 ? 4 : c[j].kind == 3 ? 8 : 1;
        Py_ssize_t rows = c[j].kind == 2 || c[j].kind == 3 ? n + 1 : n;
        bad = bad || c[j].offset + rows > c[j].values.len / width ||
              (c[j].valid.buf != NULL && c[j].valid.len < n) ||
              ((c[j].kind == 2 || c[j].kind == 3) && c[j].body.buf == NULL);
        if (bad) {
            PyErr_SetString(PyExc_ValueError, "csv_rows: a column's buffers are too short");
            csv_release(c, j + 1);
            return NULL;
        }
        if (c[j].kind == 2 || c[j].kind == 3) { /* each span checked: their total is last - first */
            long long a = 0, b = 0;
            for (Py_ssize_t i = 0; i < n; i++) {
                if (csv_span(&c[j], i, &a, &b) < 0) {
                    csv_release(c, j + 1);
                    return NULL;
                }
                bound += (Py_ssize_t)(b - a);
            }
        } else if (c[j].kind <= 1 || c[j].kind == 4) {
            bound += n * (c[j].kind == 4 ? 5 : 20);
        }
        bound += n; /* the separator (or the line end, counted above, for the last) */
    }
    PyObject *out = PyBytes_FromStringAndSize(NULL, bound);
    if (out == NULL) {
        csv_release(c, k);
        return NULL;
    }
    Text t = {PyBytes_AS_STRING(out), 0, bound};
    for (Py_ssize_t i = 0; i < n; i++) {
        for (Py_ssize_t j = 0; j < k; j++) {
            const CsvColumn *col = &c[j];
            if (col->valid.buf == NULL || ((const unsigned char *)col->valid.buf)[i]) {
                Py_ssize_t r = col->offset + i;
                if (col->kind == 0) {
                    long long v;
                    memcpy(&v, (const char *)col->values.buf + r * 8, 8);
                    text_i64(&t, v);
                } else if (col->kind == 1) {
                    unsigned long long v;
                    memcpy(&v, (const char *)col->values.buf + r * 8, 8);
                    text_u64(&t, v);
                } else if (col->kind == 4) {
                    int v = ((const unsigned char *)col->values.buf)[r] != 0;
                    memcpy(t.p + t.len, v ? "true" : "false", v ? 4 : 5);
                    t.len += v ? 4 : 5;
                } else {
                    long long a, b;
                    (void)csv_span(col, i, &a, &b); /* (checked above) */
                    memcpy(t.p + t.len, (const char *)col->body.buf + a, (size_t)(b - a));
                    t.len += (Py_ssize_t)(b - a);
                }
            }
            t.p[t.len++] = j + 1 < k ? ',' : '\n';
        }
    }
    csv_release(c, k);
    if (_PyBytes_Resize(&out, t.len) < 0) {
        return NULL;
    }
    return out;
}
