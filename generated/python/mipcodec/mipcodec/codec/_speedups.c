/* Optional C accelerator of mipcodec (MicroStrain MIP), built by the package's setup.py.
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
#include "_speedups.h"

/* ------------------------------------------------------------------------------ base types */

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
PyTypeObject *raw_packet_type, *skip_type, *packet_type, *decoded_type;
PyObject *py_decode_packet; /* pure decode_packet(packet, offset, device) */
PyObject *py_decode_field;  /* decode_field(set, descriptor, data) */
PyObject *py_program;       /* program(set, descriptor) -> None or (cls, items, head, keys) */
PyObject *py_field_line;    /* field_line(set, descriptor, data) -> str: the canonical entry */
PyObject *py_packet_line;   /* packet_line(packet, offset) -> str: the canonical packet line */

PyObject *new3(PyTypeObject *tp, PyObject *a, PyObject *b, PyObject *c) {
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
    {"decode_columns", decode_columns, METH_VARARGS,
     "decode_columns(data, want=None): a complete stream as per-field tables (want: the fields)."},
    {"scan_text", scan_text, METH_VARARGS,
     "scan_text(buf, base, skip, skip_at, final): the parser loop printing canonical JSON lines."},
    {"float_text", float_text, METH_O, "float_text(x): repr(x) by the fast path, or None where it gives up."},
    {"repr_texts", repr_texts, METH_VARARGS,
     "repr_texts(values, offset, n, valid=None): repr() of float64 values as (int64 offsets, bytes)."},
    {"csv_rows", csv_rows, METH_VARARGS,
     "csv_rows(columns, n): the CSV rows of int, text and bool columns, as bytes."},
    {"f32_texts", f32_texts, METH_VARARGS,
     "f32_texts(values, offset, n, valid=None): float32 values' shortest digits as repr() lays them out, or "
     "None."},
    {"relayout_texts", relayout_texts, METH_VARARGS,
     "relayout_texts(offsets, data, offset, n, wide): shortest-digit texts laid out as repr()."},
    {"iso_texts", iso_texts, METH_VARARGS,
     "iso_texts(t_ns, offset, n, valid=None): ISO 8601 UTC texts of int64 ns, 27 bytes each (None: a year "
     "out of 1000-9999)."},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT,
    PROTOCOL_PACKAGE ".codec._speedups",
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
    if (ready_base(&EventBase, PROTOCOL_PACKAGE ".codec._speedups.EventBase", event_members) < 0 ||
        ready_base(&PacketBase, PROTOCOL_PACKAGE ".codec._speedups.PacketBase", packet_members) < 0 ||
        ready_lazy(&DecodedFieldBase, PROTOCOL_PACKAGE ".codec._speedups.DecodedFieldBase") < 0) {
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
