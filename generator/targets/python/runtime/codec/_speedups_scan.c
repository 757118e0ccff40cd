/* The stream parser of the C accelerator (<package>): scan(), the loop of framing.Parser._scan. */
#include "_speedups.h"

/* ------------------------------------------------------------------------------ framing */
static int checksum_ok(const unsigned char *p, Py_ssize_t body) {
    unsigned int sum1 = 0, sum2 = 0;
    Py_ssize_t i = 0;
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    /* Eight bytes at a time, in groups of up to 15 blocks: the bytes of even and of odd positions
     * summed in four 16-bit lanes each (`before`: the lanes' sums before each block, for sum2),
     * folded into sum1 and sum2 at the end of the group by multiplications that sum the lanes into
     * the top one, weighing them by position (8..1) where sum2 needs it. No lane overflows within
     * a group (before: at most 510 * (1 + ... + 14) = 53550), and the top lane keeps the low 16 bits
     * of its sum, enough for sums taken modulo 256. */
    const unsigned long long lanes = 0x00FF00FF00FF00FFull;
    while (i + 8 <= body) {
        unsigned long long even = 0, odd = 0, before = 0;
        unsigned int m = 0;
        for (; m < 15 && i + 8 <= body; m++, i += 8) {
            unsigned long long x;
            memcpy(&x, p + i, 8);
            before += even + odd;
            even += x & lanes;
            odd += (x >> 8) & lanes;
        }
        unsigned long long h = (before & 0x0000FFFF0000FFFFull) + ((before >> 16) & 0x0000FFFF0000FFFFull);
        sum2 += 8 * m * sum1 + 8 * (unsigned int)(h + (h >> 32)) +
                (unsigned int)((even * 0x0008000600040002ull) >> 48) +
                (unsigned int)((odd * 0x0007000500030001ull) >> 48);
        sum1 += (unsigned int)(((even + odd) * 0x0001000100010001ull) >> 48);
    }
#endif
    for (; i + 4 <= body; i += 4) {
        /* Four steps of sum1 += b; sum2 += sum1, folded. */
        unsigned int b0 = p[i], b1 = p[i + 1], b2 = p[i + 2], b3 = p[i + 3];
        sum2 += 4 * sum1 + 4 * b0 + 3 * b1 + 2 * b2 + b3;
        sum1 += b0 + b1 + b2 + b3;
    }
    for (; i < body; i++) {
        sum1 += p[i];
        sum2 += sum1;
    }
    sum1 &= 0xFF;
    sum2 &= 0xFF;
#if CHECKSUM_SUM1_FIRST
    return p[body] == sum1 && p[body + 1] == sum2;
#else
    return p[body] == sum2 && p[body + 1] == sum1;
#endif
}

static Py_ssize_t find_sync(const unsigned char *p, Py_ssize_t pos, Py_ssize_t n) {
    while (pos < n) {
        const unsigned char *q = memchr(p + pos, SYNC[0], (size_t)(n - pos));
        if (q == NULL) {
            return -1;
        }
        Py_ssize_t i = q - p;
        if (n - i < SYNC_LEN) {
            return -1;
        }
        if (memcmp(q, SYNC, SYNC_LEN) == 0) {
            return i;
        }
        pos = i + 1;
    }
    return -1;
}

static int skipped(SkipRun *s, const unsigned char *p, Py_ssize_t base, Py_ssize_t a, Py_ssize_t b) {
    Py_ssize_t have = PyByteArray_GET_SIZE(s->bytes);
    if (have == 0) {
        s->at = base + a;
    }
    if (PyByteArray_Resize(s->bytes, have + (b - a)) < 0) {
        return -1;
    }
    memcpy(PyByteArray_AS_STRING(s->bytes) + have, p + a, (size_t)(b - a));
    return 0;
}

int flush_skip(SkipRun *s, PyObject *events) {
    Py_ssize_t have = PyByteArray_GET_SIZE(s->bytes);
    if (have == 0) {
        return 0;
    }
    PyObject *ev = new3(skip_type, PyLong_FromSsize_t(s->at),
                        PyBytes_FromStringAndSize(PyByteArray_AS_STRING(s->bytes), have), NULL);
    if (ev == NULL || PyList_Append(events, ev) < 0) {
        Py_XDECREF(ev);
        return -1;
    }
    Py_DECREF(ev);
    return PyByteArray_Resize(s->bytes, 0);
}

/* ------------------------------------------------------------------ foreign frames (section 1)
 * Where the parser would skip bytes, a whole NMEA-0183 sentence or RTCM3 frame becomes an Nmea or
 * Rtcm event (framing.py; its line in SCAN_TEXT, nothing in SCAN_COLUMNS); a candidate that fails
 * stays skipped bytes, one byte at a time. The same decisions as framing.foreign_frame. */
static PyObject *nmea_type, *rtcm_type; /* framing.Nmea, framing.Rtcm (setup_foreign) */
#define FOREIGN_WAIT (-1)

static int foreign_start(unsigned char b) {
    return (FOREIGN_NMEA && (b == 0x24 || b == 0x21)) || (FOREIGN_RTCM3 && b == 0xD3);
}

static unsigned long crc24q(const unsigned char *p, Py_ssize_t n) {
    unsigned long crc = 0;
    for (Py_ssize_t i = 0; i < n; i++) {
        crc ^= (unsigned long)p[i] << 16;
        for (int k = 0; k < 8; k++) {
            crc <<= 1;
            if (crc & 0x1000000UL) {
                crc ^= 0x1864CFBUL;
            }
        }
    }
    return crc;
}

static int hex_value(unsigned char c) {
    return c >= '0' && c <= '9'   ? c - '0'
           : c >= 'A' && c <= 'F' ? c - 'A' + 10
           : c >= 'a' && c <= 'f' ? c - 'a' + 10
                                  : -1;
}

/* The foreign frame at p[0] (a start byte) with n bytes available: its length when it is whole
 * and valid, 0 when it is not one, FOREIGN_WAIT when more bytes decide. */
static Py_ssize_t foreign_frame(const unsigned char *p, Py_ssize_t n) {
    if (p[0] == 0xD3) {
        if (n < 3) {
            return FOREIGN_WAIT;
        }
        if (p[1] & 0xFC) {
            return 0;
        }
        Py_ssize_t length = (Py_ssize_t)(p[1] & 3) << 8 | p[2];
        Py_ssize_t total = 3 + length + 3;
        if (length < 2) {
            return 0;
        }
        if (n < total) {
            return FOREIGN_WAIT;
        }
        unsigned long crc =
            (unsigned long)p[total - 3] << 16 | (unsigned long)p[total - 2] << 8 | p[total - 1];
        return crc24q(p, total - 3) == crc ? total : 0;
    }
    const Py_ssize_t lim = NMEA_MAX - 4; /* the '*' stands before lim */
    Py_ssize_t j = 1;
    unsigned x = 0;
    while (j < n && j < lim && p[j] >= 0x20 && p[j] <= 0x7E && p[j] != '$' && p[j] != '!' && p[j] != '*') {
        x ^= p[j++];
    }
    if (j == lim) {
        return 0; /* overlong */
    }
    if (j == n) {
        return FOREIGN_WAIT;
    }
    if (p[j] != '*') {
        return 0;
    }
    if (n < j + 5) {
        return FOREIGN_WAIT;
    }
    int hi = hex_value(p[j + 1]), lo = hex_value(p[j + 2]);
    if (hi < 0 || lo < 0 || p[j + 3] != '\r' || p[j + 4] != '\n' || (unsigned)(hi << 4 | lo) != x) {
        return 0;
    }
    return j + 5;
}

/* A frame found: the pending skip run goes first, then the frame's event (or line). */
static int foreign_found(const unsigned char *p, Py_ssize_t n, Py_ssize_t offset, int mode, void *ctx,
                         SkipRun *skip, PyObject *events) {
    if (mode == SCAN_TEXT) {
        return text_skip(ctx, skip) < 0 ? -1 : text_foreign(ctx, p, n, offset);
    }
    if (PyByteArray_GET_SIZE(skip->bytes) != 0 && flush_skip(skip, events) < 0) {
        return -1;
    }
    if (mode == SCAN_COLUMNS) {
        return 0; /* other protocols' frames hold no fields */
    }
    if (nmea_type == NULL || rtcm_type == NULL) {
        PyErr_SetString(PyExc_RuntimeError, PROTOCOL_PACKAGE "._speedups.setup_foreign() was not called");
        return -1;
    }
    PyObject *ev =
        PyObject_CallFunction(p[0] == 0xD3 ? rtcm_type : nmea_type, "ny#", offset, (const char *)p, n);
    if (ev == NULL || PyList_Append(events, ev) < 0) {
        Py_XDECREF(ev);
        return -1;
    }
    Py_DECREF(ev);
    return 0;
}

/* Bytes p[a..b) hold no sync: skipped, but for the foreign frames among them. Returns where
 * scanning goes on (b, or past b after a frame that runs over it), -2 - s to wait at s, or -1
 * with an exception set. */
static Py_ssize_t scan_gap(const unsigned char *p, Py_ssize_t n, Py_ssize_t base, Py_ssize_t a, Py_ssize_t b,
                           int final, int mode, void *ctx, SkipRun *skip, PyObject *events) {
    while (FOREIGN_NMEA || FOREIGN_RTCM3) {
        Py_ssize_t s = a;
        while (s < b && !foreign_start(p[s])) {
            s++;
        }
        if (s == b) {
            break;
        }
        if (s > a && skipped(skip, p, base, a, s) < 0) {
            return -1;
        }
        Py_ssize_t r = foreign_frame(p + s, n - s);
        if (r == FOREIGN_WAIT && !final) {
            return -2 - s;
        }
        if (r > 0) {
            if (foreign_found(p + s, r, base + s, mode, ctx, skip, events) < 0) {
                return -1;
            }
            a = s + r;
            if (a >= b) {
                return a;
            }
            continue;
        }
        if (skipped(skip, p, base, s, s + 1) < 0) {
            return -1;
        }
        a = s + 1;
    }
    if (a < b && skipped(skip, p, base, a, b) < 0) {
        return -1;
    }
    return b;
}

/* setup_foreign(Nmea, Rtcm): the event classes of foreign frames (framing.py). */
PyObject *setup_foreign(PyObject *self, PyObject *args) {
    (void)self;
    PyObject *a, *b;
    if (!PyArg_ParseTuple(args, "O!O!", &PyType_Type, &a, &PyType_Type, &b)) {
        return NULL;
    }
    Py_XDECREF(nmea_type);
    Py_XDECREF(rtcm_type);
    nmea_type = Py_NewRef(a);
    rtcm_type = Py_NewRef(b);
    Py_RETURN_NONE;
}

/* The parser loop of framing.Parser._scan over p[0:n] (stream offset `base`). A packet becomes
 * a RawPacket (SCAN_RAW), a decoded Packet (SCAN_DECODE), rows of `ctx` (SCAN_COLUMNS, a
 * Columns) or its canonical line in `ctx` (SCAN_TEXT, a Text, skip runs too); Skip events go to
 * `events`. Returns the number of bytes consumed, or -1 with an exception set. */
Py_ssize_t scan_core(const unsigned char *p, Py_ssize_t n, Py_ssize_t base, int final, int mode, void *ctx,
                     SkipRun *skip, PyObject *events, Watch *watch) {
    Py_ssize_t pos = 0;
    while (pos < n) {
        /* Most packets start where the last one ended. */
        Py_ssize_t i =
            n - pos >= SYNC_LEN && memcmp(p + pos, SYNC, SYNC_LEN) == 0 ? pos : find_sync(p, pos, n);
        if (i < 0) {
            /* Keep a partial sync sequence at the very end (unless this is the end of input). */
            Py_ssize_t keep = n;
            if (!final) {
                Py_ssize_t j = n - SYNC_LEN + 1;
                if (j < pos) {
                    j = pos;
                }
                for (; j < n; j++) {
                    if (memcmp(p + j, SYNC, (size_t)(n - j)) == 0) {
                        keep = j;
                        break;
                    }
                }
            }
            Py_ssize_t at =
                keep > pos ? scan_gap(p, n, base, pos, keep, final, mode, ctx, skip, events) : keep;
            if (at == -1) {
                return -1;
            }
            if (at < -1 || at > keep) {
                pos = at < -1 ? -2 - at : at; /* wait at a frame, or go on after one */
                if (at < -1) {
                    break;
                }
                continue;
            }
            pos = keep;
            break;
        }
        if (i > pos) {
            Py_ssize_t at = scan_gap(p, n, base, pos, i, final, mode, ctx, skip, events);
            if (at == -1) {
                return -1;
            }
            if (at < -1) {
                pos = -2 - at; /* wait at a frame */
                break;
            }
            if (at != i) {
                pos = at; /* a frame ran over the sync: go on after it */
                continue;
            }
        }
        int length = n - i >= HEADER_SIZE ? p[i + LENGTH_OFFSET] : -1;
        if (length >= 0 && length <= MAX_PAYLOAD) {
            Py_ssize_t body = HEADER_SIZE + length;
            Py_ssize_t total = body + CHECKSUM_SIZE;
            if (n - i >= total) {
                if (checksum_ok(p + i, body)) {
                    if (mode == SCAN_TEXT) {
                        if (text_skip(ctx, skip) < 0 || text_packet(ctx, p + i, total, base + i) < 0) {
                            return -1;
                        }
                        pos = i + total;
                        continue;
                    }
                    if (PyByteArray_GET_SIZE(skip->bytes) != 0 && flush_skip(skip, events) < 0) {
                        return -1;
                    }
                    if (mode == SCAN_COLUMNS) {
                        if (column_packet(ctx, p + i, total, base + i) < 0) {
                            return -1;
                        }
                        pos = i + total;
                        continue;
                    }
                    PyObject *off = PyLong_FromSsize_t(base + i);
                    PyObject *ev;
                    if (mode == SCAN_DECODE) {
                        ev = off == NULL ? NULL : decode_packet_c(p + i, total, off);
                        Py_XDECREF(off);
                    } else {
                        ev = new3(raw_packet_type, off, PyBytes_FromStringAndSize((const char *)p + i, total),
                                  NULL);
                    }
                    if (ev == NULL || PyList_Append(events, ev) < 0) {
                        Py_XDECREF(ev);
                        return -1;
                    }
                    Py_DECREF(ev);
                    if (watch != NULL) {
                        watch->packets++;
                        if (watch->mask != NULL && watch->mask[p[i + SET_OFFSET]]) {
                            PyObject *at = PyLong_FromSsize_t(PyList_GET_SIZE(events) - 1);
                            if (at == NULL || PyList_Append(watch->hits, at) < 0) {
                                Py_XDECREF(at);
                                return -1;
                            }
                            Py_DECREF(at);
                        }
                    }
                    pos = i + total;
                    continue;
                }
            } else if (!final) {
                pos = i; /* wait for the rest of the packet */
                break;
            }
        } else if (length < 0 && !final) {
            pos = i; /* wait for the rest of the header */
            break;
        }
        /* A false sync (bad length or checksum, or incomplete at end of input): skip one byte. */
        if (skipped(skip, p, base, i, i + 1) < 0) {
            return -1;
        }
        pos = i + 1;
    }
    return pos;
}

/* The cyclic garbage collector is paused while one call builds its objects: they form no cycle,
 * and a collection in the middle would only rescan them (promoting them to older generations,
 * which then get rescanned over and over on long streams). Objects the caller drops before the
 * next call are never scanned at all; those it keeps are collected as usual afterwards. */
int gc_pause(void) {
#if PY_VERSION_HEX >= 0x030A0000
    return PyGC_Disable();
#else
    return 0;
#endif
}

void gc_resume(int was_enabled) {
#if PY_VERSION_HEX >= 0x030A0000
    if (was_enabled) {
        PyGC_Enable();
    }
#else
    (void)was_enabled;
#endif
}

/* scan(buf: bytearray, base: int, skip: bytearray, skip_at: int, final: bool, decode: bool = False,
 *      watch: bytes | None = None)
 *   -> (events, consumed, skip_at); with decode, packets are decoded (Packet) instead of RawPacket.
 * With watch (256 bytes, non-zero at the set bytes to watch): (events, consumed, skip_at, hits,
 * packets), hits the indexes in events of the packets of the watched sets, packets their number. */
PyObject *scan(PyObject *self, PyObject *args) {
    (void)self;
    if (packet_type == NULL) {
        PyErr_SetString(PyExc_RuntimeError, PROTOCOL_PACKAGE ".codec._speedups.setup() was not called");
        return NULL;
    }
    PyObject *buf;
    Py_ssize_t base;
    SkipRun skip;
    int final, decode = 0;
    PyObject *mask = Py_None;
    if (!PyArg_ParseTuple(args, "O!nO!np|pO", &PyByteArray_Type, &buf, &base, &PyByteArray_Type, &skip.bytes,
                          &skip.at, &final, &decode, &mask)) {
        return NULL;
    }
    Watch watch = {NULL, NULL, 0};
    if (mask != Py_None) {
        if (!PyBytes_Check(mask) || PyBytes_GET_SIZE(mask) != 256) {
            PyErr_SetString(PyExc_TypeError, "watch must be 256 bytes or None");
            return NULL;
        }
        watch.mask = (const unsigned char *)PyBytes_AS_STRING(mask);
        watch.hits = PyList_New(0);
        if (watch.hits == NULL) {
            return NULL;
        }
    }
    /* Decoding may run Python code (the fallbacks): it works on a private copy of the buffer.
     * Framing alone runs none (only our own objects are made), so it reads buf in place. */
    PyObject *copy = NULL;
    const unsigned char *p = (const unsigned char *)PyByteArray_AS_STRING(buf);
    Py_ssize_t n = PyByteArray_GET_SIZE(buf);
    if (decode) {
        copy = PyBytes_FromStringAndSize((const char *)p, n);
        if (copy == NULL) {
            Py_XDECREF(watch.hits);
            return NULL;
        }
        p = (const unsigned char *)PyBytes_AS_STRING(copy);
    }
    PyObject *events = PyList_New(0);
    if (events == NULL) {
        Py_XDECREF(copy);
        Py_XDECREF(watch.hits);
        return NULL;
    }
    int gc = gc_pause();
    Py_ssize_t pos = scan_core(p, n, base, final, decode ? SCAN_DECODE : SCAN_RAW, NULL, &skip, events,
                               watch.mask != NULL ? &watch : NULL);
    gc_resume(gc);
    Py_XDECREF(copy);
    if (pos < 0) {
        Py_DECREF(events);
        Py_XDECREF(watch.hits);
        return NULL;
    }
    if (watch.mask != NULL) {
        return Py_BuildValue("NnnNn", events, pos, skip.at, watch.hits, watch.packets);
    }
    return Py_BuildValue("Nnn", events, pos, skip.at);
}
