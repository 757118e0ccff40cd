/* Optional C accelerator of democodec (Demo protocol with every spec feature), built by the package's
 * setup.py.
 *
 * It replaces the two hot loops of the pure-Python runtime and nothing else:
 *   - scan(): the stream parser (framing.Parser._scan): sync search, length, Fletcher-16, skip runs;
 *   - decode_packet() / decode_all(): field splitting and dispatch by (set, descriptor), with the
 *     typed values of layouts made of fixed-size scalars (codec.Run of ints, floats, bools, chars,
 *     strings, enums, bitfields) built here, each when it is first read (a DecodedField holds the
 *     field's bytes until then); every other layout, every error and every NaN goes back to the
 *     pure-Python decoder, so messages and values are those of the pure path;
 *   - decode_columns(): the same fixed layouts as rows of per-field tables of numbers;
 *   - scan_text(): the decode CLI's loop, parser + decode + canonical JSON lines written here for
 *     the same fixed layouts (floats by PyOS_double_to_string 'r', i.e. repr); every other field,
 *     NaN or invalid bool is printed by the pure-Python line writer, so the text is the same.
 * The objects it returns are instances of the package's own classes (RawPacket, Skip, Packet,
 * DecodedField and the generated dataclasses), equal to what the pure path returns. The protocol's
 * constants come from _protocol.h, generated from the IR like _protocol.py.
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <structmember.h>
#include <math.h>
#include <string.h>
#if defined(__linux__)
#include <sys/mman.h>
#endif

#if PY_VERSION_HEX < 0x030A0000
static inline PyObject *Py_NewRef(PyObject *o) {
    Py_INCREF(o);
    return o;
}
#endif

#include "_protocol.h"

/* ------------------------------------------------------------------------------ base types */
/* Base classes of RawPacket and Skip (offset, data), Packet (offset, set, fields) and
 * DecodedField (descriptor, value): the Python classes derive from them (with empty __slots__)
 * and keep their methods; instances made here are instances of those Python classes. */
typedef struct {
    PyObject_HEAD PyObject *a;
    PyObject *b;
    PyObject *c;
} Slots3;

static int slots_traverse(Slots3 *self, visitproc visit, void *arg) {
    Py_VISIT(self->a);
    Py_VISIT(self->b);
    Py_VISIT(self->c);
    return 0;
}

static int slots_clear(Slots3 *self) {
    Py_CLEAR(self->a);
    Py_CLEAR(self->b);
    Py_CLEAR(self->c);
    return 0;
}

static void slots_dealloc(Slots3 *self) {
    PyTypeObject *tp = Py_TYPE(self);
    /* Instances of the Python subclasses come through subtype_dealloc, which drops the type. */
    PyObject_GC_UnTrack(self);
    slots_clear(self);
    tp->tp_free((PyObject *)self);
}

/* The dealloc of the package's Python subclasses (setup() installs it in place of CPython's generic
 * subtype_dealloc when the class adds nothing to the instance: no __dict__, no weak references,
 * no finalizer): the three slots released, the memory freed and the class's reference dropped.
 * Their instances nest at most packet > fields list > entry, so no trashcan is needed. */
static void heap_slots_dealloc(Slots3 *self) {
    PyTypeObject *tp = Py_TYPE(self);
    PyObject_GC_UnTrack(self);
    slots_clear(self);
    tp->tp_free((PyObject *)self);
    Py_DECREF(tp);
}

static PyMemberDef event_members[] = {
    {"offset", T_OBJECT_EX, offsetof(Slots3, a), 0, "stream offset"},
    {"data", T_OBJECT_EX, offsetof(Slots3, b), 0, "bytes"},
    {NULL, 0, 0, 0, NULL},
};

static PyMemberDef packet_members[] = {
    {"offset", T_OBJECT_EX, offsetof(Slots3, a), 0, "stream offset"},
    {"set", T_OBJECT_EX, offsetof(Slots3, b), 0, "descriptor set"},
    {"fields", T_OBJECT_EX, offsetof(Slots3, c), 0, "field entries"},
    {NULL, 0, 0, 0, NULL},
};

static PyTypeObject EventBase = {PyVarObject_HEAD_INIT(NULL, 0).tp_name = NULL};
static PyTypeObject PacketBase = {PyVarObject_HEAD_INIT(NULL, 0).tp_name = NULL};
static PyTypeObject DecodedFieldBase = {PyVarObject_HEAD_INIT(NULL, 0).tp_name = NULL};

static int ready_base(PyTypeObject *tp, const char *name, PyMemberDef *members) {
    tp->tp_name = name;
    tp->tp_basicsize = sizeof(Slots3);
    tp->tp_flags = Py_TPFLAGS_DEFAULT | Py_TPFLAGS_BASETYPE | Py_TPFLAGS_HAVE_GC;
    tp->tp_traverse = (traverseproc)slots_traverse;
    tp->tp_clear = (inquiry)slots_clear;
    tp->tp_dealloc = (destructor)slots_dealloc;
    tp->tp_members = members;
    tp->tp_new = PyType_GenericNew;
    return PyType_Ready(tp);
}

/* The package's classes and pure-Python fallbacks, given by setup(). */
static PyTypeObject *raw_packet_type, *skip_type, *packet_type, *decoded_type;
static PyObject *py_decode_packet; /* pure decode_packet(packet, offset, device) */
static PyObject *py_decode_field;  /* decode_field(set, descriptor, data) */
static PyObject *py_program;       /* program(set, descriptor) -> None or (cls, items, head, keys) */
static PyObject *py_field_line;    /* field_line(set, descriptor, data) -> str: the canonical entry */
static PyObject *py_packet_line;   /* packet_line(packet, offset) -> str: the canonical packet line */

static PyObject *new3(PyTypeObject *tp, PyObject *a, PyObject *b, PyObject *c) {
    /* Steals a, b, c (which may be NULL on error: then returns NULL). */
    if (a == NULL || b == NULL || (tp == packet_type && c == NULL)) {
        Py_XDECREF(a);
        Py_XDECREF(b);
        Py_XDECREF(c);
        return NULL;
    }
    Slots3 *o = (Slots3 *)tp->tp_alloc(tp, 0);
    if (o == NULL) {
        Py_DECREF(a);
        Py_DECREF(b);
        Py_XDECREF(c);
        return NULL;
    }
    o->a = a;
    o->b = b;
    o->c = c;
    return (PyObject *)o;
}

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

/* Skip-run state: bytes in a bytearray and the stream offset of its first byte. */
typedef struct {
    PyObject *bytes; /* bytearray */
    Py_ssize_t at;
} SkipRun;

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

static int flush_skip(SkipRun *s, PyObject *events) {
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

static PyObject *decode_packet_c(const unsigned char *p, Py_ssize_t n, PyObject *offset);

typedef struct Columns Columns;
static int column_packet(Columns *c, const unsigned char *p, Py_ssize_t n, Py_ssize_t offset);

/* A growing text buffer (the lines of scan_text). */
typedef struct {
    char *p;
    Py_ssize_t len, cap;
} Text;

static int text_packet(Text *t, const unsigned char *p, Py_ssize_t n, Py_ssize_t offset);
static int text_skip(Text *t, SkipRun *s);

enum { SCAN_RAW, SCAN_DECODE, SCAN_COLUMNS, SCAN_TEXT };

static int text_reserve(Text *t, Py_ssize_t more);
static void text_u64(Text *t, unsigned long long v);
static void text_i64(Text *t, long long v);

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

/* The canonical line of a frame (docs/conformance.md section 5) into t. */
static int text_foreign(Text *t, const unsigned char *p, Py_ssize_t n, Py_ssize_t offset) {
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
static PyObject *setup_foreign(PyObject *self, PyObject *args) {
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

/* What scan() reports beside the events for the session (session.py): the indexes in events of
 * the packets whose set byte is flagged in mask[256] (sets with a pending command), and the number
 * of packets (so that no Skip event is among them when it equals the number of events). */
typedef struct {
    const unsigned char *mask; /* NULL: nothing watched */
    PyObject *hits;            /* list of int */
    Py_ssize_t packets;
} Watch;

/* The parser loop of framing.Parser._scan over p[0:n] (stream offset `base`). A packet becomes
 * a RawPacket (SCAN_RAW), a decoded Packet (SCAN_DECODE), rows of `ctx` (SCAN_COLUMNS, a
 * Columns) or its canonical line in `ctx` (SCAN_TEXT, a Text, skip runs too); Skip events go to
 * `events`. Returns the number of bytes consumed, or -1 with an exception set. */
static Py_ssize_t scan_core(const unsigned char *p, Py_ssize_t n, Py_ssize_t base, int final, int mode,
                            void *ctx, SkipRun *skip, PyObject *events, Watch *watch) {
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
static int gc_pause(void) {
#if PY_VERSION_HEX >= 0x030A0000
    return PyGC_Disable();
#else
    return 0;
#endif
}

static void gc_resume(int was_enabled) {
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
static PyObject *scan(PyObject *self, PyObject *args) {
    (void)self;
    if (packet_type == NULL) {
        PyErr_SetString(PyExc_RuntimeError, PROTOCOL_PACKAGE "._speedups.setup() was not called");
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

/* ------------------------------------------------------------------------------ typed values */
/* One wire item of a fixed layout: a scalar (count < 0) or a fixed array (a list). */
typedef struct {
    char kind;       /* u: unsigned, i: signed, f: float32, d: float64, ?: bool, c: char, s: string,
                        e: enum (aux: value -> member dict), F: bitfield (aux: class) */
    int size;        /* bytes of one element */
    int count;       /* -1: scalar */
    PyObject *aux;   /* owned */
    PyObject *attr;  /* owned, interned attribute name */
    PyObject *key;   /* owned bytes: '"name":' of the canonical JSON */
    Py_ssize_t slot; /* offset of the attribute's slot in the instance (slotted classes), else 0 */
} Item;

typedef enum { ENTRY_SLOW = 1, ENTRY_FAST = 2 } EntryKind;

typedef struct {
    EntryKind kind;
    PyObject *cls;   /* owned */
    PyObject *head;  /* owned bytes: '{"descriptor":D,"name":"N",["device":"X",]"values":{' */
    Py_ssize_t size; /* data bytes */
    int slotted;     /* every item has a slot and instances no __dict__: values stored by offset */
    int columnable;  /* no char or string item: decode_columns reads it (see columnable()) */
    int nitems;
    Item items[];
} Entry;

static Entry **entries[256]; /* [set][descriptor], filled on first use */

static unsigned long long load(const unsigned char *p, int size) {
    unsigned long long v = 0;
#if BIG_ENDIAN_WIRE
    for (int k = 0; k < size; k++) {
        v = (v << 8) | p[k];
    }
#else
    for (int k = size - 1; k >= 0; k--) {
        v = (v << 8) | p[k];
    }
#endif
    return v;
}

static inline unsigned int load32(const unsigned char *p) {
#if BIG_ENDIAN_WIRE
    return ((unsigned int)p[0] << 24) | ((unsigned int)p[1] << 16) | ((unsigned int)p[2] << 8) | p[3];
#else
    return ((unsigned int)p[3] << 24) | ((unsigned int)p[2] << 16) | ((unsigned int)p[1] << 8) | p[0];
#endif
}

#define NOT_FAST ((PyObject *)1) /* the value needs the pure-Python decoder */

/* One element; NULL with an exception, or NOT_FAST. */
static PyObject *element(const Item *it, const unsigned char *p) {
    switch (it->kind) {
    case 'f': {
        unsigned int bits = load32(p);
        float f;
        memcpy(&f, &bits, 4);
        if (f != f) {
            return NOT_FAST;
        }
        return PyFloat_FromDouble((double)f);
    }
    case 'd': {
        unsigned long long bits = load(p, 8);
        double d;
        memcpy(&d, &bits, 8);
        if (d != d) {
            return NOT_FAST;
        }
        return PyFloat_FromDouble(d);
    }
    case 'u':
        return PyLong_FromUnsignedLongLong(load(p, it->size));
    case 'i': {
        unsigned long long v = load(p, it->size);
        int shift = 64 - 8 * it->size;
        long long s = shift ? (long long)(v << shift) >> shift : (long long)v;
        return PyLong_FromLongLong(s);
    }
    case '?':
        if (p[0] > 1) {
            return NOT_FAST;
        }
        return PyBool_FromLong(p[0]);
    case 'c':
    case 's':
        return PyBytes_FromStringAndSize((const char *)p, it->size);
    case 'e': {
        PyObject *v = PyLong_FromUnsignedLongLong(load(p, it->size));
        if (v == NULL) {
            return NULL;
        }
        PyObject *m = PyDict_GetItemWithError(it->aux, v);
        if (m != NULL) {
            Py_INCREF(m);
            Py_DECREF(v);
            return m;
        }
        if (PyErr_Occurred()) {
            Py_DECREF(v);
            return NULL;
        }
        return v;
    }
    case 'F': {
        PyObject *v = PyLong_FromUnsignedLongLong(load(p, it->size));
        if (v == NULL) {
            return NULL;
        }
        PyObject *r = PyObject_CallOneArg(it->aux, v);
        Py_DECREF(v);
        return r;
    }
    default:
        PyErr_Format(PyExc_SystemError, "bad item kind %c", it->kind);
        return NULL;
    }
}

static PyObject *empty_tuple;

/* The typed value of a fast entry; NULL with an exception, or NOT_FAST. */
static PyObject *fast_value(const Entry *e, const unsigned char *p) {
    PyTypeObject *tp = (PyTypeObject *)e->cls;
    PyObject *obj = e->slotted ? tp->tp_alloc(tp, 0) : PyBaseObject_Type.tp_new(tp, empty_tuple, NULL);
    if (obj == NULL) {
        return NULL;
    }
    for (int k = 0; k < e->nitems; k++) {
        const Item *it = &e->items[k];
        PyObject *v;
        if (it->count < 0) {
            v = element(it, p);
            p += it->size;
        } else {
            v = PyList_New(it->count);
            for (int j = 0; v != NULL && j < it->count; j++) {
                PyObject *x = element(it, p);
                p += it->size;
                if (x == NULL || x == NOT_FAST) {
                    Py_DECREF(v);
                    v = x;
                    break;
                }
                PyList_SET_ITEM(v, j, x);
            }
        }
        if (v == NULL || v == NOT_FAST) {
            Py_DECREF(obj);
            return v;
        }
        if (e->slotted) {
            *(PyObject **)((char *)obj + it->slot) = v; /* a fresh object: the slot is empty */
            continue;
        }
        int rc = PyObject_GenericSetAttr(obj, it->attr, v);
        Py_DECREF(v);
        if (rc < 0) {
            Py_DECREF(obj);
            return NULL;
        }
    }
    return obj;
}

static int columnable(const Entry *e);

/* 1 when the instances of e->cls hold every item in a slot of their own and have no __dict__
 * (codec.slotted): the item's slot offsets are set; 0 otherwise (values set as attributes); -1
 * with an exception. */
static int slots_of(Entry *e) {
    PyTypeObject *tp = (PyTypeObject *)e->cls;
    if (!PyType_Check(e->cls) || tp->tp_dictoffset != 0 || tp->tp_new != PyBaseObject_Type.tp_new ||
        tp->tp_init == NULL) {
        return 0;
    }
    for (int k = 0; k < e->nitems; k++) {
        Item *it = &e->items[k];
        PyObject *d = PyObject_GetAttr(e->cls, it->attr);
        if (d == NULL) {
            PyErr_Clear();
            return 0;
        }
        int ok = Py_IS_TYPE(d, &PyMemberDescr_Type) &&
                 ((PyMemberDescrObject *)d)->d_member->type == T_OBJECT_EX &&
                 !(((PyMemberDescrObject *)d)->d_member->flags & READONLY) &&
                 PyType_IsSubtype(tp, ((PyDescrObject *)d)->d_type);
        if (ok) {
            it->slot = ((PyMemberDescrObject *)d)->d_member->offset;
        }
        Py_DECREF(d);
        if (!ok || it->slot <= 0 || it->slot + (Py_ssize_t)sizeof(PyObject *) > tp->tp_basicsize) {
            return 0;
        }
    }
    return 1;
}

/* The entry of (set, descriptor), asking the Python side on first use. */
static Entry *entry_for(int set_id, int descriptor) {
    Entry **row = entries[set_id];
    if (row == NULL) {
        row = PyMem_Calloc(256, sizeof(Entry *));
        if (row == NULL) {
            PyErr_NoMemory();
            return NULL;
        }
        entries[set_id] = row;
    }
    if (row[descriptor] != NULL) {
        return row[descriptor];
    }
    PyObject *prog = PyObject_CallFunction(py_program, "ii", set_id, descriptor);
    if (prog == NULL) {
        return NULL;
    }
    Entry *e;
    if (prog == Py_None) {
        e = PyMem_Calloc(1, sizeof(Entry));
        if (e == NULL) {
            Py_DECREF(prog);
            PyErr_NoMemory();
            return NULL;
        }
        e->kind = ENTRY_SLOW;
    } else {
        PyObject *cls, *items, *head, *keys;
        if (!PyArg_ParseTuple(prog, "OO!SO!", &cls, &PyTuple_Type, &items, &head, &PyTuple_Type, &keys)) {
            Py_DECREF(prog);
            return NULL;
        }
        Py_ssize_t n = PyTuple_GET_SIZE(items);
        if (PyTuple_GET_SIZE(keys) != n) {
            Py_DECREF(prog);
            PyErr_SetString(PyExc_SystemError, "program(): one key per item expected");
            return NULL;
        }
        e = PyMem_Calloc(1, sizeof(Entry) + (size_t)n * sizeof(Item));
        if (e == NULL) {
            Py_DECREF(prog);
            PyErr_NoMemory();
            return NULL;
        }
        e->kind = ENTRY_FAST;
        e->cls = Py_NewRef(cls);
        e->head = Py_NewRef(head);
        e->nitems = (int)n;
        for (Py_ssize_t k = 0; k < n; k++) {
            Item *it = &e->items[k];
            const char *kind;
            PyObject *attr, *aux;
            if (!PyArg_ParseTuple(PyTuple_GET_ITEM(items, k), "UsiiO", &attr, &kind, &it->size, &it->count,
                                  &aux)) {
                Py_DECREF(prog);
                return NULL; /* the half-built entry leaks, once, on a programming error */
            }
            it->kind = kind[0];
            it->key = PyTuple_GET_ITEM(keys, k);
            if (!PyBytes_Check(it->key)) {
                Py_DECREF(prog);
                PyErr_SetString(PyExc_SystemError, "program(): keys must be bytes");
                return NULL;
            }
            Py_INCREF(it->key);
            it->attr = Py_NewRef(attr);
            PyUnicode_InternInPlace(&it->attr);
            it->aux = Py_NewRef(aux);
            e->size += (Py_ssize_t)it->size * (it->count < 0 ? 1 : it->count);
        }
        e->columnable = columnable(e);
        e->slotted = slots_of(e);
        if (e->slotted < 0) {
            Py_DECREF(prog);
            return NULL;
        }
    }
    Py_DECREF(prog);
    row[descriptor] = e;
    return e;
}

/* ------------------------------------------------------------------------------ lazy fields */
/* DecodedField's base: the descriptor and the typed value. A field of a fixed layout decoded here
 * builds its value only when it is first read: until then the instance holds a copy of the field's
 * data bytes (checked when decoded to read here as the pure-Python decoder reads them: no NaN, no
 * invalid bool) and the layout that reads them; the value then built is cached. A field made from
 * Python (DecodedField(descriptor, value)) holds its value from the start. */
typedef struct {
    PyObject_VAR_HEAD /* ob_size: bytes of data (0 unless made lazy) */
        PyObject *descriptor;
    PyObject *value;    /* NULL while lazy (or after `del field.value`) */
    const Entry *entry; /* the layout that reads data; NULL once the value is set */
    unsigned char data[1];
} LazyField;

#define LAZY_BASICSIZE ((Py_ssize_t)offsetof(LazyField, data))

static int lazy_traverse(LazyField *self, visitproc visit, void *arg) {
    Py_VISIT(self->descriptor);
    Py_VISIT(self->value);
    return 0;
}

static int lazy_clear(LazyField *self) {
    Py_CLEAR(self->descriptor);
    Py_CLEAR(self->value);
    return 0;
}

static void lazy_dealloc(LazyField *self) {
    PyTypeObject *tp = Py_TYPE(self);
    PyObject_GC_UnTrack(self);
    lazy_clear(self);
    tp->tp_free((PyObject *)self);
}

/* The dealloc of DecodedField (see heap_slots_dealloc). */
static void heap_lazy_dealloc(LazyField *self) {
    PyTypeObject *tp = Py_TYPE(self);
    PyObject_GC_UnTrack(self);
    lazy_clear(self);
    tp->tp_free((PyObject *)self);
    Py_DECREF(tp);
}

static PyObject *lazy_get_value(LazyField *self, void *closure) {
    (void)closure;
    if (self->value == NULL) {
        if (self->entry == NULL) {
            PyErr_SetString(PyExc_AttributeError, "value");
            return NULL;
        }
        PyObject *v = fast_value(self->entry, self->data);
        if (v == NOT_FAST) { /* checked when decoded: cannot happen */
            PyErr_SetString(PyExc_SystemError, "a lazily decoded field does not read");
            return NULL;
        }
        if (v == NULL) {
            return NULL;
        }
        if (self->value != NULL) { /* set meanwhile (a bitfield class runs Python code) */
            Py_DECREF(v);
        } else {
            self->value = v;
            self->entry = NULL;
        }
    }
    return Py_NewRef(self->value);
}

static int lazy_set_value(LazyField *self, PyObject *value, void *closure) {
    (void)closure;
    if (value == NULL && self->value == NULL && self->entry == NULL) {
        PyErr_SetString(PyExc_AttributeError, "value");
        return -1;
    }
    Py_XSETREF(self->value, Py_XNewRef(value));
    self->entry = NULL;
    return 0;
}

static PyMemberDef lazy_members[] = {
    {"descriptor", T_OBJECT_EX, offsetof(LazyField, descriptor), 0, "field descriptor"},
    {NULL, 0, 0, 0, NULL},
};

static PyGetSetDef lazy_getset[] = {
    {"value", (getter)lazy_get_value, (setter)lazy_set_value, "typed value (decoded on first read)", NULL},
    {NULL, NULL, NULL, NULL, NULL},
};

/* 1 when every element of fast entry e's data p reads here as the pure decoder reads it (no NaN
 * float, no bool other than 0 or 1), else 0. */
static int fast_reads(const Entry *e, const unsigned char *p) {
    for (int k = 0; k < e->nitems; k++) {
        const Item *it = &e->items[k];
        int n = it->count < 0 ? 1 : it->count;
        switch (it->kind) {
        case 'f':
            for (int j = 0; j < n; j++, p += 4) {
                if ((load32(p) << 1) > 0xFF000000u) {
                    return 0;
                }
            }
            break;
        case 'd':
            for (int j = 0; j < n; j++, p += 8) {
                if ((load(p, 8) << 1) > 0xFFE0000000000000ull) {
                    return 0;
                }
            }
            break;
        case '?':
            for (int j = 0; j < n; j++, p++) {
                if (p[0] > 1) {
                    return 0;
                }
            }
            break;
        default:
            p += (Py_ssize_t)it->size * n;
            break;
        }
    }
    return 1;
}

/* A DecodedField whose value is built on first read; NULL with an exception. */
static PyObject *lazy_field(int descriptor, const Entry *e, const unsigned char *data) {
    LazyField *o = (LazyField *)decoded_type->tp_alloc(decoded_type, e->size);
    if (o == NULL) {
        return NULL;
    }
    o->descriptor = PyLong_FromLong(descriptor);
    if (o->descriptor == NULL) {
        Py_DECREF(o);
        return NULL;
    }
    o->entry = e;
    memcpy(o->data, data, (size_t)e->size);
    return (PyObject *)o;
}

static PyObject *slow_field(int set_id, int descriptor, const unsigned char *data, Py_ssize_t len) {
    return PyObject_CallFunction(py_decode_field, "iiy#", set_id, descriptor, (const char *)data, len);
}

#define NOT_SPLIT ((PyObject *)1) /* the payload has trailing bytes: pure-Python decoder */

/* Field entries of a payload, or NULL with an exception, or NOT_SPLIT. */
static PyObject *decode_fields(int set_id, const unsigned char *pl, Py_ssize_t n) {
    /* Count the fields first (and see that the payload splits cleanly). */
    Py_ssize_t count = 0;
    for (Py_ssize_t o = 0; o < n;) {
        if (n - o < FIELD_HEADER_SIZE) {
            return NOT_SPLIT;
        }
        int descriptor = pl[o + FIELD_DESCRIPTOR_OFFSET];
        int data_length = pl[o + FIELD_LENGTH_OFFSET] - field_length_adjust(set_id, descriptor);
        if (data_length < 0 || FIELD_HEADER_SIZE + data_length > n - o) {
            return NOT_SPLIT;
        }
        o += FIELD_HEADER_SIZE + data_length;
        count++;
    }
    PyObject *fields = PyList_New(count);
    if (fields == NULL) {
        return NULL;
    }
    Py_ssize_t k = 0;
    for (Py_ssize_t o = 0; o < n; k++) {
        int descriptor = pl[o + FIELD_DESCRIPTOR_OFFSET];
        Py_ssize_t data_length = pl[o + FIELD_LENGTH_OFFSET] - field_length_adjust(set_id, descriptor);
        const unsigned char *data = pl + o + FIELD_HEADER_SIZE;
        o += FIELD_HEADER_SIZE + data_length;
        Entry *e = entry_for(set_id, descriptor);
        if (e == NULL) {
            Py_DECREF(fields);
            return NULL;
        }
        PyObject *entry = NULL;
        if (e->kind == ENTRY_FAST && e->size == data_length && fast_reads(e, data)) {
            entry = lazy_field(descriptor, e, data);
            if (entry == NULL) {
                Py_DECREF(fields);
                return NULL;
            }
        }
        if (entry == NULL) {
            entry = slow_field(set_id, descriptor, data, data_length);
            if (entry == NULL) {
                Py_DECREF(fields);
                return NULL;
            }
        }
        PyList_SET_ITEM(fields, k, entry);
    }
    return fields;
}

/* A Packet from a complete packet p[0:n] (as found by the parser); NULL with an exception. */
static PyObject *decode_packet_c(const unsigned char *p, Py_ssize_t n, PyObject *offset) {
    PyObject *fields = NOT_SPLIT;
    if (n >= HEADER_SIZE + CHECKSUM_SIZE) {
        fields = decode_fields(p[SET_OFFSET], p + HEADER_SIZE, n - HEADER_SIZE - CHECKSUM_SIZE);
    }
    if (fields == NOT_SPLIT) {
        return PyObject_CallFunction(py_decode_packet, "y#OO", (const char *)p, n, offset, Py_None);
    }
    Py_INCREF(offset);
    return new3(packet_type, offset, PyLong_FromLong(p[SET_OFFSET]), fields);
}

/* decode_packet(packet, offset=0, device=None) */
static PyObject *decode_packet(PyObject *self, PyObject *args, PyObject *kwargs) {
    (void)self;
    if (packet_type == NULL) {
        PyErr_SetString(PyExc_RuntimeError, PROTOCOL_PACKAGE "._speedups.setup() was not called");
        return NULL;
    }
    static char *names[] = {"packet", "offset", "device", NULL};
    PyObject *packet, *offset = NULL, *device = Py_None;
    if (!PyArg_ParseTupleAndKeywords(args, kwargs, "O|OO", names, &packet, &offset, &device)) {
        return NULL;
    }
    if (offset == NULL) {
        offset = PyLong_FromLong(0);
    } else {
        Py_INCREF(offset);
    }
    PyObject *r;
    if (device != Py_None) {
        r = PyObject_CallFunctionObjArgs(py_decode_packet, packet, offset, device, NULL);
    } else {
        Py_buffer view;
        if (PyObject_GetBuffer(packet, &view, PyBUF_SIMPLE) < 0) {
            Py_DECREF(offset);
            return NULL;
        }
        /* Copy: Python code run by the fallbacks must not see (or resize) the caller's buffer. */
        PyObject *copy = PyBytes_FromStringAndSize(view.buf, view.len);
        PyBuffer_Release(&view);
        if (copy == NULL) {
            Py_DECREF(offset);
            return NULL;
        }
        r = decode_packet_c((const unsigned char *)PyBytes_AS_STRING(copy), PyBytes_GET_SIZE(copy), offset);
        Py_DECREF(copy);
    }
    Py_DECREF(offset);
    return r;
}

/* decode_all(data) -> [Packet | Skip]: a complete stream, parsed and decoded in one pass. */
static PyObject *decode_all(PyObject *self, PyObject *arg) {
    (void)self;
    if (packet_type == NULL) {
        PyErr_SetString(PyExc_RuntimeError, PROTOCOL_PACKAGE "._speedups.setup() was not called");
        return NULL;
    }
    PyObject *copy = PyBytes_FromObject(arg); /* a private immutable copy (no copy for bytes) */
    if (copy == NULL) {
        return NULL;
    }
    SkipRun skip = {PyByteArray_FromStringAndSize(NULL, 0), 0};
    PyObject *events = PyList_New(0);
    if (skip.bytes == NULL || events == NULL) {
        Py_XDECREF(skip.bytes);
        Py_XDECREF(events);
        Py_DECREF(copy);
        return NULL;
    }
    int gc = gc_pause();
    Py_ssize_t pos = scan_core((const unsigned char *)PyBytes_AS_STRING(copy), PyBytes_GET_SIZE(copy), 0, 1,
                               SCAN_DECODE, NULL, &skip, events, NULL);
    gc_resume(gc);
    Py_DECREF(copy);
    if (pos < 0 || flush_skip(&skip, events) < 0) {
        Py_DECREF(skip.bytes);
        Py_DECREF(events);
        return NULL;
    }
    Py_DECREF(skip.bytes);
    return events;
}

/* ------------------------------------------------------------------------------ columns */
/* decode_columns: the fields the C side reads (fast entries without char or string items) become
 * rows of per-(set, descriptor) tables of native numbers; every other field entry (and every
 * packet that does not split into fields) goes to `others` as Python objects.
 *
 * Rows are written straight into their final buffers: one bytearray per column, sized when the
 * table is made from the input still to read (as if the rest of the stream were packets like the
 * one that made it; grown by doubling when that falls short) and cut to the rows at the end, so
 * nothing is copied on the way to Python. A packet is matched against the layouts already seen
 * (set, payload length, the field headers at their offsets): a known layout gives its fields'
 * tables, offsets and entries without splitting and dispatching again. */
typedef struct {
    PyObject *ba; /* bytearray; its size is the capacity until the end */
    char *p;
    Py_ssize_t width; /* bytes per row */
} Col;

typedef struct {
    const Entry *e;
    int set_id, descriptor;
    Py_ssize_t rows, cap;
    int ncols; /* 2 + items: offsets (long long per row: packet offset), index (long long per row:
                  position of the field in its packet), then per item: double (f, d), long long
                  (i), unsigned long long (u, e, F), unsigned char (?), count values per row */
    Col cols[];
} Table;

/* One field of a known layout. */
typedef struct {
    Table **slot; /* the table's place in Columns.by_set (NULL: an `others` entry) */
    const Entry *e;
    int hdr; /* offset of the field header in the payload */
    unsigned char length_byte, descriptor;
    int data_len;
} LField;

#define LAYOUTS_KEPT 16 /* per set and payload length, most recently seen first */

typedef struct Layout {
    struct Layout *next;
    int nfields;
    LField f[];
} Layout;

struct Columns {
    Table **by_set[256];   /* [set][descriptor], rows allocated on first use */
    Layout **layouts[256]; /* [set][payload length]: chains of known layouts */
    Table **list;
    Py_ssize_t ntables, cap;
    Py_ssize_t packets;
    Py_ssize_t size;  /* bytes of the input */
    PyObject *others; /* [(offset, index, entry) | (offset, -1, Packet)] */
};

static int columnable(const Entry *e) {
    if (e->kind != ENTRY_FAST) {
        return 0;
    }
    for (int k = 0; k < e->nitems; k++) {
        if (e->items[k].kind == 'c' || e->items[k].kind == 's') {
            return 0;
        }
    }
    return 1;
}

static Py_ssize_t column_width(const Item *it) {
    return (Py_ssize_t)(it->count < 0 ? 1 : it->count) * (it->kind == '?' ? 1 : 8);
}

static void table_free(Table *t) {
    for (int k = 0; k < t->ncols; k++) {
        Py_XDECREF(t->cols[k].ba);
    }
    PyMem_Free(t);
}

/* Large column buffers are asked for in huge pages where the kernel gives them on request (Linux
 * transparent huge pages in "madvise" mode): writing the rows of a large input otherwise spends
 * about as long in page faults (one per 4 KiB) as in decoding. A hint: nothing changes if refused. */
static void huge_pages(char *p, Py_ssize_t n) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    const uintptr_t huge = (uintptr_t)2 << 20;
    if (n < (Py_ssize_t)huge) {
        return;
    }
    uintptr_t a = ((uintptr_t)p + huge - 1) & ~(huge - 1), b = ((uintptr_t)p + (uintptr_t)n) & ~(huge - 1);
    if (b > a) {
        (void)madvise((void *)a, b - a, MADV_HUGEPAGE);
    }
#else
    (void)p;
    (void)n;
#endif
}

/* Every column of t holds room for `cap` rows: 0, or -1 with an exception. */
static int table_reserve(Table *t, Py_ssize_t cap) {
    for (int k = 0; k < t->ncols; k++) {
        Col *c = &t->cols[k];
        if (c->ba == NULL) {
            c->ba = PyByteArray_FromStringAndSize(NULL, cap * c->width);
            if (c->ba == NULL) {
                return -1;
            }
        } else if (PyByteArray_Resize(c->ba, cap * c->width) < 0) {
            return -1;
        }
        c->p = PyByteArray_AS_STRING(c->ba);
        huge_pages(c->p, cap * c->width);
    }
    t->cap = cap;
    return 0;
}

/* The table of (set, descriptor), made on first use with room for the rows the rest of the input
 * (from byte `at`, in packets of `total` bytes) could hold. */
static Table *table_for(Columns *c, Table **slot, const Entry *e, int set_id, int descriptor, Py_ssize_t at,
                        Py_ssize_t total) {
    if (*slot != NULL) {
        return *slot;
    }
    Table *t = PyMem_Calloc(1, sizeof(Table) + (size_t)(e->nitems + 2) * sizeof(Col));
    if (t == NULL) {
        PyErr_NoMemory();
        return NULL;
    }
    t->e = e;
    t->set_id = set_id;
    t->descriptor = descriptor;
    t->ncols = e->nitems + 2;
    t->cols[0].width = t->cols[1].width = 8;
    Py_ssize_t row_bytes = 16;
    for (int k = 0; k < e->nitems; k++) {
        t->cols[k + 2].width = column_width(&e->items[k]);
        row_bytes += t->cols[k + 2].width;
    }
    Py_ssize_t rest = c->size - at;
    Py_ssize_t cap = rest / (total > 0 ? total : 1) + 16;
    /* At most 256 MiB reserved up front per table; beyond, the rows grow by doubling. */
    if (cap > ((Py_ssize_t)256 << 20) / row_bytes) {
        cap = ((Py_ssize_t)256 << 20) / row_bytes;
    }
    if (table_reserve(t, cap) < 0) {
        PyErr_Clear();
        if (table_reserve(t, 16) < 0) {
            table_free(t);
            return NULL;
        }
    }
    if (c->ntables == c->cap) {
        Py_ssize_t n = c->cap ? 2 * c->cap : 16;
        Table **q = PyMem_Realloc(c->list, (size_t)n * sizeof(Table *));
        if (q == NULL) {
            table_free(t);
            PyErr_NoMemory();
            return NULL;
        }
        c->list = q;
        c->cap = n;
    }
    c->list[c->ntables++] = t;
    *slot = t;
    return t;
}

/* Writes the row of field data p into t: 0; 1 (nothing written) when an element does not read as
 * the pure decoder reads it (a NaN, an invalid bool); -1 with an exception. */
static int put_row(Table *t, const unsigned char *p, long long offset, long long index) {
    if (t->rows == t->cap && table_reserve(t, 2 * t->cap) < 0) {
        return -1;
    }
    const Entry *e = t->e;
    Py_ssize_t r = t->rows;
    const Col *c = &t->cols[2];
    /* Written past the row count first, which moves only when the whole row reads. */
    for (int k = 0; k < e->nitems; k++, c++) {
        const Item *it = &e->items[k];
        Py_ssize_t n = c->width; /* elements: width / 8, or width for bools */
        char *out = c->p + r * n;
        switch (it->kind) {
        case 'f':
            for (char *end = out + n; out < end; p += 4, out += 8) {
                unsigned int bits = load32(p);
                if ((bits << 1) > 0xFF000000u) { /* a NaN */
                    return 1;
                }
                float f;
                memcpy(&f, &bits, 4);
                double d = f;
                memcpy(out, &d, 8);
            }
            break;
        case 'd':
            for (char *end = out + n; out < end; p += 8, out += 8) {
                unsigned long long bits = load(p, 8);
                if ((bits << 1) > 0xFFE0000000000000ull) { /* a NaN */
                    return 1;
                }
                memcpy(out, &bits, 8);
            }
            break;
        case 'i': {
            int size = it->size, shift = 64 - 8 * size;
            for (char *end = out + n; out < end; p += size, out += 8) {
                unsigned long long v = load(p, size);
                long long x = shift ? (long long)(v << shift) >> shift : (long long)v;
                memcpy(out, &x, 8);
            }
            break;
        }
        case '?':
            for (Py_ssize_t j = 0; j < n; j++, p++) {
                if (p[0] > 1) {
                    return 1;
                }
                out[j] = (char)p[0];
            }
            break;
        default: { /* u, e, F */
            int size = it->size;
            for (char *end = out + n; out < end; p += size, out += 8) {
                unsigned long long v = load(p, size);
                memcpy(out, &v, 8);
            }
            break;
        }
        }
    }
    memcpy(t->cols[0].p + r * 8, &offset, 8);
    memcpy(t->cols[1].p + r * 8, &index, 8);
    t->rows = r + 1;
    return 0;
}

static int add_other(Columns *c, long long offset, long long index, PyObject *entry) {
    if (entry == NULL) {
        return -1;
    }
    PyObject *t = Py_BuildValue("LLN", offset, index, entry);
    if (t == NULL || PyList_Append(c->others, t) < 0) {
        Py_XDECREF(t);
        return -1;
    }
    Py_DECREF(t);
    return 0;
}

/* The layout of payload pl[0:len] of set `set_id`, from the known ones or made (and kept); NULL
 * with no exception when the payload does not split into fields, NULL with one on error. */
static Layout *layout_for(Columns *c, int set_id, const unsigned char *pl, Py_ssize_t len) {
    Layout **chains = c->layouts[set_id];
    int known = 0;
    if (chains != NULL) {
        Layout **at = &chains[len];
        for (Layout *l = *at, *prev = NULL; l != NULL; prev = l, l = l->next, known++) {
            int k = 0;
            for (; k < l->nfields; k++) {
                const LField *f = &l->f[k];
                if (pl[f->hdr + FIELD_LENGTH_OFFSET] != f->length_byte ||
                    pl[f->hdr + FIELD_DESCRIPTOR_OFFSET] != f->descriptor) {
                    break;
                }
            }
            if (k == l->nfields) {
                if (prev != NULL) { /* to the front: the next packet is likely alike */
                    prev->next = l->next;
                    l->next = *at;
                    *at = l;
                }
                return l;
            }
        }
    }
    int count = 0;
    for (Py_ssize_t o = 0; o < len; count++) {
        if (len - o < FIELD_HEADER_SIZE) {
            return NULL;
        }
        int descriptor = pl[o + FIELD_DESCRIPTOR_OFFSET];
        int data_length = pl[o + FIELD_LENGTH_OFFSET] - field_length_adjust(set_id, descriptor);
        if (data_length < 0 || FIELD_HEADER_SIZE + data_length > len - o) {
            return NULL;
        }
        o += FIELD_HEADER_SIZE + data_length;
    }
    if (chains == NULL) {
        chains = PyMem_Calloc(MAX_PAYLOAD + 1, sizeof(Layout *));
        if (chains == NULL) {
            PyErr_NoMemory();
            return NULL;
        }
        c->layouts[set_id] = chains;
    }
    Layout *l = PyMem_Calloc(1, sizeof(Layout) + (size_t)count * sizeof(LField));
    if (l == NULL) {
        PyErr_NoMemory();
        return NULL;
    }
    l->nfields = count;
    Py_ssize_t o = 0;
    for (int k = 0; k < count; k++) {
        LField *f = &l->f[k];
        f->hdr = (int)o;
        f->length_byte = pl[o + FIELD_LENGTH_OFFSET];
        f->descriptor = pl[o + FIELD_DESCRIPTOR_OFFSET];
        f->data_len = f->length_byte - field_length_adjust(set_id, f->descriptor);
        o += FIELD_HEADER_SIZE + f->data_len;
        Entry *e = entry_for(set_id, f->descriptor);
        if (e == NULL) {
            PyMem_Free(l);
            return NULL;
        }
        f->e = e;
        if (e->kind == ENTRY_FAST && e->size == f->data_len && e->columnable) {
            Table **row = c->by_set[set_id];
            if (row == NULL) {
                row = c->by_set[set_id] = PyMem_Calloc(256, sizeof(Table *));
                if (row == NULL) {
                    PyMem_Free(l);
                    PyErr_NoMemory();
                    return NULL;
                }
            }
            f->slot = &row[f->descriptor];
        }
    }
    if (known >= LAYOUTS_KEPT) { /* the least recently seen layout of this length makes room */
        Layout **last = &chains[len];
        while ((*last)->next != NULL) {
            last = &(*last)->next;
        }
        PyMem_Free(*last);
        *last = NULL;
    }
    l->next = chains[len];
    chains[len] = l;
    return l;
}

static int column_packet(Columns *c, const unsigned char *p, Py_ssize_t n, Py_ssize_t offset) {
    int set_id = p[SET_OFFSET];
    const unsigned char *pl = p + HEADER_SIZE;
    Py_ssize_t len = n - HEADER_SIZE - CHECKSUM_SIZE;
    c->packets++;
    Layout *l = layout_for(c, set_id, pl, len);
    if (l == NULL) {
        if (PyErr_Occurred()) {
            return -1;
        }
        /* A payload that does not split into fields: the whole packet, decoded in Python. */
        PyObject *off = PyLong_FromSsize_t(offset);
        if (off == NULL) {
            return -1;
        }
        PyObject *pkt = PyObject_CallFunction(py_decode_packet, "y#OO", (const char *)p, n, off, Py_None);
        Py_DECREF(off);
        return add_other(c, offset, -1, pkt);
    }
    for (int k = 0; k < l->nfields; k++) {
        const LField *f = &l->f[k];
        const unsigned char *data = pl + f->hdr + FIELD_HEADER_SIZE;
        int rc = 1;
        if (f->slot != NULL) {
            Table *t = *f->slot;
            if (t == NULL) {
                t = table_for(c, f->slot, f->e, set_id, f->descriptor, offset, n);
                if (t == NULL) {
                    return -1;
                }
            }
            rc = put_row(t, data, offset, k);
            if (rc < 0) {
                return -1;
            }
            if (rc == 1 && t->rows == 0) {
                /* Made for this row, which does not read: dropped, as if never made (table order). */
                *f->slot = NULL;
                c->ntables--;
                table_free(t);
            }
        }
        if (rc == 1 && add_other(c, offset, k, slow_field(set_id, f->descriptor, data, f->data_len)) < 0) {
            return -1;
        }
    }
    return 0;
}

static PyObject *tables_out(Columns *c) {
    PyObject *out = PyList_New(c->ntables);
    for (Py_ssize_t k = 0; out != NULL && k < c->ntables; k++) {
        Table *t = c->list[k];
        PyObject *cols = PyList_New(t->e->nitems);
        for (int j = 0; cols != NULL && j < t->ncols; j++) {
            /* Cut to the rows (a large cut gives the rest back to the allocator). */
            if (PyByteArray_Resize(t->cols[j].ba, t->rows * t->cols[j].width) < 0) {
                Py_CLEAR(cols);
                break;
            }
            if (j >= 2) {
                PyList_SET_ITEM(cols, j - 2, Py_NewRef(t->cols[j].ba));
            }
        }
        PyObject *row = cols == NULL ? NULL
                                     : Py_BuildValue("iiOnOON", t->set_id, t->descriptor, t->e->cls, t->rows,
                                                     t->cols[0].ba, t->cols[1].ba, cols);
        if (row == NULL) {
            Py_CLEAR(out);
            break;
        }
        PyList_SET_ITEM(out, k, row);
    }
    return out;
}

static void columns_free(Columns *c) {
    for (Py_ssize_t k = 0; k < c->ntables; k++) {
        table_free(c->list[k]);
    }
    for (int s = 0; s < 256; s++) {
        PyMem_Free(c->by_set[s]);
        if (c->layouts[s] != NULL) {
            for (int n = 0; n <= MAX_PAYLOAD; n++) {
                for (Layout *l = c->layouts[s][n]; l != NULL;) {
                    Layout *next = l->next;
                    PyMem_Free(l);
                    l = next;
                }
            }
            PyMem_Free(c->layouts[s]);
        }
    }
    PyMem_Free(c->list);
    Py_XDECREF(c->others);
}

/* decode_columns(data) -> (packets, skips, tables, others); tables: [(set, descriptor, class, rows,
 * offsets, index, [column per item])], each column a bytearray of numbers in native byte order. */
static PyObject *decode_columns(PyObject *self, PyObject *arg) {
    (void)self;
    if (packet_type == NULL) {
        PyErr_SetString(PyExc_RuntimeError, PROTOCOL_PACKAGE "._speedups.setup() was not called");
        return NULL;
    }
    PyObject *copy = PyBytes_FromObject(arg);
    if (copy == NULL) {
        return NULL;
    }
    Columns *c = PyMem_Calloc(1, sizeof(Columns));
    if (c == NULL) {
        Py_DECREF(copy);
        return PyErr_NoMemory();
    }
    c->size = PyBytes_GET_SIZE(copy);
    c->others = PyList_New(0);
    SkipRun skip = {PyByteArray_FromStringAndSize(NULL, 0), 0};
    PyObject *skips = PyList_New(0), *result = NULL;
    if (c->others != NULL && skip.bytes != NULL && skips != NULL) {
        int gc = gc_pause();
        Py_ssize_t pos = scan_core((const unsigned char *)PyBytes_AS_STRING(copy), PyBytes_GET_SIZE(copy), 0,
                                   1, SCAN_COLUMNS, c, &skip, skips, NULL);
        gc_resume(gc);
        if (pos >= 0 && flush_skip(&skip, skips) >= 0) {
            PyObject *tables = tables_out(c);
            if (tables != NULL) {
                result = Py_BuildValue("nONO", c->packets, skips, tables, c->others);
            }
        }
    }
    Py_DECREF(copy);
    Py_XDECREF(skip.bytes);
    Py_XDECREF(skips);
    columns_free(c);
    PyMem_Free(c);
    return result;
}

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
static int repr_double(double v, char *out) {
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

#define TEXT_NOT_FAST 1

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

static int text_packet(Text *t, const unsigned char *p, Py_ssize_t n, Py_ssize_t offset) {
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

/* The line of the pending skip run, if any, and the run emptied. */
static int text_skip(Text *t, SkipRun *s) {
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
static PyObject *scan_text(PyObject *self, PyObject *args) {
    (void)self;
    if (packet_type == NULL || py_field_line == NULL) {
        PyErr_SetString(PyExc_RuntimeError, PROTOCOL_PACKAGE "._speedups.setup() was not called");
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

static int ready_lazy(PyTypeObject *tp, const char *name) {
    tp->tp_name = name;
    tp->tp_basicsize = LAZY_BASICSIZE;
    tp->tp_itemsize = 1;
    tp->tp_flags = Py_TPFLAGS_DEFAULT | Py_TPFLAGS_BASETYPE | Py_TPFLAGS_HAVE_GC;
    tp->tp_traverse = (traverseproc)lazy_traverse;
    tp->tp_clear = (inquiry)lazy_clear;
    tp->tp_dealloc = (destructor)lazy_dealloc;
    tp->tp_members = lazy_members;
    tp->tp_getset = lazy_getset;
    tp->tp_new = PyType_GenericNew;
    return PyType_Ready(tp);
}

/* setup(RawPacket, Skip, Packet, DecodedField, decode_packet, decode_field, program, field_line,
 *       packet_line) */
static PyObject *setup(PyObject *self, PyObject *args) {
    (void)self;
    PyObject *t[4], *f[5];
    if (!PyArg_ParseTuple(args, "O!O!O!O!OOOOO", &PyType_Type, &t[0], &PyType_Type, &t[1], &PyType_Type,
                          &t[2], &PyType_Type, &t[3], &f[0], &f[1], &f[2], &f[3], &f[4])) {
        return NULL;
    }
    PyTypeObject *bases[4] = {&EventBase, &EventBase, &PacketBase, &DecodedFieldBase};
    for (int k = 0; k < 4; k++) {
        if (!PyType_IsSubtype((PyTypeObject *)t[k], bases[k]) ||
            ((PyTypeObject *)t[k])->tp_basicsize != (k == 3 ? LAZY_BASICSIZE : (Py_ssize_t)sizeof(Slots3))) {
            PyErr_Format(PyExc_TypeError, "%s must derive from %s with empty __slots__",
                         ((PyTypeObject *)t[k])->tp_name, bases[k]->tp_name);
            return NULL;
        }
    }
    for (int k = 0; k < 4; k++) {
        PyTypeObject *tp = (PyTypeObject *)t[k];
        if ((tp->tp_flags & Py_TPFLAGS_HEAPTYPE) && tp->tp_base == bases[k] && tp->tp_dictoffset == 0 &&
            tp->tp_weaklistoffset == 0 && tp->tp_finalize == NULL && tp->tp_del == NULL &&
            tp->tp_free == PyObject_GC_Del) {
            tp->tp_dealloc = k == 3 ? (destructor)heap_lazy_dealloc : (destructor)heap_slots_dealloc;
        }
    }
    raw_packet_type = (PyTypeObject *)Py_NewRef(t[0]);
    skip_type = (PyTypeObject *)Py_NewRef(t[1]);
    packet_type = (PyTypeObject *)Py_NewRef(t[2]);
    decoded_type = (PyTypeObject *)Py_NewRef(t[3]);
    py_decode_packet = Py_NewRef(f[0]);
    py_decode_field = Py_NewRef(f[1]);
    py_program = Py_NewRef(f[2]);
    py_field_line = Py_NewRef(f[3]);
    py_packet_line = Py_NewRef(f[4]);
    Py_RETURN_NONE;
}

/* float_text(x: float) -> str | None: repr(x) as the fast path prints it, None when it gives up
 * (for the tests: the text must be repr's). */
static PyObject *float_text(PyObject *self, PyObject *arg) {
    (void)self;
    double d = PyFloat_AsDouble(arg);
    if (d == -1.0 && PyErr_Occurred()) {
        return NULL;
    }
    if (!isfinite(d)) {
        PyErr_SetString(PyExc_ValueError, "float_text: a finite float expected");
        return NULL;
    }
    char out[32];
    int n = repr_double(d, out);
    if (n < 0) {
        Py_RETURN_NONE;
    }
    return PyUnicode_FromStringAndSize(out, n);
}

static PyMethodDef methods[] = {
    {"setup", setup, METH_VARARGS, "Register the package's classes and pure-Python fallbacks."},
    {"scan", scan, METH_VARARGS, "The stream parser loop (framing.Parser._scan)."},
    {"setup_foreign", setup_foreign, METH_VARARGS, "Register the event classes of foreign frames."},
    {"decode_packet", (PyCFunction)(void (*)(void))decode_packet, METH_VARARGS | METH_KEYWORDS,
     "decode_packet(packet, offset=0, device=None): a complete packet decoded into typed fields."},
    {"decode_all", decode_all, METH_O,
     "decode_all(data): every event of a complete stream, packets decoded."},
    {"decode_columns", decode_columns, METH_O,
     "decode_columns(data): a complete stream as per-field tables."},
    {"scan_text", scan_text, METH_VARARGS,
     "scan_text(buf, base, skip, skip_at, final): the parser loop printing canonical JSON lines."},
    {"float_text", float_text, METH_O, "float_text(x): repr(x) by the fast path, or None where it gives up."},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT,
    PROTOCOL_PACKAGE "._speedups",
    "C accelerator of " PROTOCOL_PACKAGE " (optional).",
    -1,
    methods,
    NULL,
    NULL,
    NULL,
    NULL,
};

PyMODINIT_FUNC PyInit__speedups(void) {
    PyTypeObject *types[3] = {&EventBase, &PacketBase, &DecodedFieldBase};
    if (ready_base(&EventBase, PROTOCOL_PACKAGE "._speedups.EventBase", event_members) < 0 ||
        ready_base(&PacketBase, PROTOCOL_PACKAGE "._speedups.PacketBase", packet_members) < 0 ||
        ready_lazy(&DecodedFieldBase, PROTOCOL_PACKAGE "._speedups.DecodedFieldBase") < 0) {
        return NULL;
    }
    empty_tuple = PyTuple_New(0);
    if (empty_tuple == NULL) {
        return NULL;
    }
    PyObject *m = PyModule_Create(&module);
    if (m == NULL) {
        return NULL;
    }
    const char *names[3] = {"EventBase", "PacketBase", "DecodedFieldBase"};
    for (int k = 0; k < 3; k++) {
        Py_INCREF(types[k]);
        if (PyModule_AddObject(m, names[k], (PyObject *)types[k]) < 0) {
            Py_DECREF(types[k]);
            Py_DECREF(m);
            return NULL;
        }
    }
    return m;
}
