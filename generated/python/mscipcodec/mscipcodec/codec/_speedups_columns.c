/* The columns of the C accelerator (mscipcodec): decode_columns(). */
#include "_speedups.h"

/* ------------------------------------------------------------------------------ columns */

int columnable(const Entry *e) {
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

int column_packet(Columns *c, const unsigned char *p, Py_ssize_t n, Py_ssize_t offset) {
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
        if (c->want != NULL && !c->want[(set_id << 8) | f->descriptor]) {
            continue; /* a field not asked for: neither a row nor an `others` entry */
        }
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

/* decode_columns(data, want=None) -> (packets, skips, tables, others); tables: [(set, descriptor,
 * class, rows, offsets, index, [column per item])], each column a bytearray of numbers in native
 * byte order. `want`: None (every field) or 65536 bytes, nonzero at [set << 8 | descriptor] for
 * the fields of packets of that set to decode (the others are left out; packets still counted). */
PyObject *decode_columns(PyObject *self, PyObject *args) {
    (void)self;
    PyObject *arg, *want = Py_None;
    if (!PyArg_ParseTuple(args, "O|O:decode_columns", &arg, &want)) {
        return NULL;
    }
    if (packet_type == NULL) {
        PyErr_SetString(PyExc_RuntimeError, PROTOCOL_PACKAGE ".codec._speedups.setup() was not called");
        return NULL;
    }
    if (want != Py_None && (!PyBytes_Check(want) || PyBytes_GET_SIZE(want) != 65536)) {
        PyErr_SetString(PyExc_TypeError, "decode_columns: want must be None or 65536 bytes");
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
    c->want = want == Py_None ? NULL : (const unsigned char *)PyBytes_AS_STRING(want);
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
