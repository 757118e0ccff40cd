/* The canonical JSON lines of the C accelerator (<package>): scan_text(), float_text(). */
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

/* repr(float) of a finite double into out (at least 32 bytes): its length, or -1 when Grisu3 gave
 * up. The layout is format_float_short's for repr: exponent form when the decimal point falls
 * before -4 or after 16 digits ("1e+16", "1.5e-05"), else fixed with at least one digit after the
 * point ("100.0", "0.001"). */
int repr_double(double v, char *out) {
    char *o = out;
    if (signbit(v)) {
        *o++ = '-';
        v = -v;
    }
    if (v == 0.0) {
        memcpy(o, "0.0", 3);
        return (int)(o + 3 - out);
    }
    char d[20];
    int n, e;
    if (!grisu3(v, d, &n, &e)) {
        return -1;
    }
    int decpt = n + e; /* value = 0.d1d2... x 10^decpt */
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
