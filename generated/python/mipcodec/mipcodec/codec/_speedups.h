/* The C accelerator's shared declarations (mipcodec, MicroStrain MIP): the includes, the
 * types and the functions and tables one of its files (codec/_speedups*.c, compiled together
 * into one module by setup.py) uses from another. Hidden: only PyInit__speedups is exported. */
#ifndef SPEEDUPS_H
#define SPEEDUPS_H

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

#if defined(__GNUC__)
#pragma GCC visibility push(hidden)
#endif

/* Base classes of RawPacket and Skip (offset, data), Packet (offset, set, fields) and
 * DecodedField (descriptor, value): the Python classes derive from them (with empty __slots__)
 * and keep their methods; instances made here are instances of those Python classes. */

typedef struct {
    PyObject_HEAD PyObject *a;
    PyObject *b;
    PyObject *c;
} Slots3;

/* Skip-run state: bytes in a bytearray and the stream offset of its first byte. */

typedef struct {
    PyObject *bytes; /* bytearray */
    Py_ssize_t at;
} SkipRun;

typedef struct Columns Columns;

/* A growing text buffer (the lines of scan_text). */

typedef struct {
    char *p;
    Py_ssize_t len, cap;
} Text;

enum { SCAN_RAW, SCAN_DECODE, SCAN_COLUMNS, SCAN_TEXT };

/* What scan() reports beside the events for the session (session.py): the indexes in events of
 * the packets whose set byte is flagged in mask[256] (sets with a pending command), and the number
 * of packets (so that no Skip event is among them when it equals the number of events). */

typedef struct {
    const unsigned char *mask; /* NULL: nothing watched */
    PyObject *hits;            /* list of int */
    Py_ssize_t packets;
} Watch;

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

static inline unsigned long long load(const unsigned char *p, int size) {
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

#define NOT_SPLIT ((PyObject *)1) /* the payload has trailing bytes: pure-Python decoder */

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
    Py_ssize_t size;           /* bytes of the input */
    PyObject *others;          /* [(offset, index, entry) | (offset, -1, Packet)] */
    const unsigned char *want; /* [set << 8 | descriptor]: nonzero for a field to decode (NULL: all) */
};

#define TEXT_NOT_FAST 1

/* ------------------------------------------------------------------ shared between the files */
extern PyTypeObject *raw_packet_type, *skip_type, *packet_type, *decoded_type;
extern PyObject *py_decode_packet;
extern PyObject *py_decode_field;
extern PyObject *py_program;
extern PyObject *py_field_line;
extern PyObject *py_packet_line;
PyObject *new3(PyTypeObject *tp, PyObject *a, PyObject *b, PyObject *c);
int flush_skip(SkipRun *s, PyObject *events);
Py_ssize_t scan_core(const unsigned char *p, Py_ssize_t n, Py_ssize_t base, int final, int mode, void *ctx,
                     SkipRun *skip, PyObject *events, Watch *watch);
int gc_pause(void);
void gc_resume(int was_enabled);
PyObject *scan(PyObject *self, PyObject *args);
extern PyObject *empty_tuple;
Entry *entry_for(int set_id, int descriptor);
int lazy_traverse(LazyField *self, visitproc visit, void *arg);
int lazy_clear(LazyField *self);
void lazy_dealloc(LazyField *self);
void heap_lazy_dealloc(LazyField *self);
extern PyMemberDef lazy_members[];
extern PyGetSetDef lazy_getset[];
PyObject *slow_field(int set_id, int descriptor, const unsigned char *data, Py_ssize_t len);
PyObject *decode_packet_c(const unsigned char *p, Py_ssize_t n, PyObject *offset);
PyObject *decode_packet(PyObject *self, PyObject *args, PyObject *kwargs);
PyObject *decode_all(PyObject *self, PyObject *arg);
int columnable(const Entry *e);
int column_packet(Columns *c, const unsigned char *p, Py_ssize_t n, Py_ssize_t offset);
PyObject *decode_columns(PyObject *self, PyObject *args);
int repr_double(double v, char *out);
int text_packet(Text *t, const unsigned char *p, Py_ssize_t n, Py_ssize_t offset);
int text_skip(Text *t, SkipRun *s);
int text_foreign(Text *t, const unsigned char *p, Py_ssize_t n, Py_ssize_t offset);
PyObject *setup_foreign(PyObject *self, PyObject *args);
PyObject *scan_text(PyObject *self, PyObject *args);
PyObject *repr_texts(PyObject *self, PyObject *args);
PyObject *csv_rows(PyObject *self, PyObject *args);
PyObject *f32_texts(PyObject *self, PyObject *args);
PyObject *relayout_texts(PyObject *self, PyObject *args);
PyObject *iso_texts(PyObject *self, PyObject *args);

#if defined(__GNUC__)
#pragma GCC visibility pop
#endif

#endif /* SPEEDUPS_H */
