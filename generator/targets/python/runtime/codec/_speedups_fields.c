/* The typed values and lazy fields of the C accelerator (<package>): decode_packet(), decode_all(). */
#include "_speedups.h"

/* ------------------------------------------------------------------------------ typed values */

static Entry **entries[256]; /* [set][descriptor], filled on first use */

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

PyObject *empty_tuple;

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
Entry *entry_for(int set_id, int descriptor) {
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

int lazy_traverse(LazyField *self, visitproc visit, void *arg) {
    Py_VISIT(self->descriptor);
    Py_VISIT(self->value);
    return 0;
}

int lazy_clear(LazyField *self) {
    Py_CLEAR(self->descriptor);
    Py_CLEAR(self->value);
    return 0;
}

void lazy_dealloc(LazyField *self) {
    PyTypeObject *tp = Py_TYPE(self);
    PyObject_GC_UnTrack(self);
    lazy_clear(self);
    tp->tp_free((PyObject *)self);
}

/* The dealloc of DecodedField (see heap_slots_dealloc). */
void heap_lazy_dealloc(LazyField *self) {
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

PyMemberDef lazy_members[] = {
    {"descriptor", T_OBJECT_EX, offsetof(LazyField, descriptor), 0, "field descriptor"},
    {NULL, 0, 0, 0, NULL},
};

PyGetSetDef lazy_getset[] = {
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

PyObject *slow_field(int set_id, int descriptor, const unsigned char *data, Py_ssize_t len) {
    return PyObject_CallFunction(py_decode_field, "iiy#", set_id, descriptor, (const char *)data, len);
}

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
PyObject *decode_packet_c(const unsigned char *p, Py_ssize_t n, PyObject *offset) {
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
PyObject *decode_packet(PyObject *self, PyObject *args, PyObject *kwargs) {
    (void)self;
    if (packet_type == NULL) {
        PyErr_SetString(PyExc_RuntimeError, PROTOCOL_PACKAGE ".codec._speedups.setup() was not called");
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
PyObject *decode_all(PyObject *self, PyObject *arg) {
    (void)self;
    if (packet_type == NULL) {
        PyErr_SetString(PyExc_RuntimeError, PROTOCOL_PACKAGE ".codec._speedups.setup() was not called");
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
