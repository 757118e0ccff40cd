/* Encoders and decoders of Shared data. Generated from the spec: do not edit. */
#include "democodec/sets/shared.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- demo_shared_timestamp_t */

static int demo_shared_timestamp_read(demo_reader_t *r, demo_shared_timestamp_t *out) {
    demo_rd_push(r, "nanoseconds");
    if (demo_rd_u64(r, &out->nanoseconds)) {
        return -1;
    }
    demo_rd_pop(r);
    return demo_rd_finish(r);
}

static demo_status_t demo_shared_timestamp_write(demo_writer_t *w, const demo_shared_timestamp_t *in) {
    demo_status_t st;
    if ((st = demo_wr_u64(w, &in->nanoseconds)) != DEMO_OK) {
        return st;
    }
    return DEMO_OK;
}

demo_status_t demo_shared_timestamp_encode(const demo_shared_timestamp_t *value, uint8_t *buf, size_t cap,
                                           size_t *len_out) {
    demo_writer_t w;
    demo_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    demo_writer_init(&w, buf, cap);
    st = demo_shared_timestamp_write(&w, value);
    if (st == DEMO_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 8 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int demo_shared_timestamp_load(const uint8_t *d, demo_shared_timestamp_t *out) {
    out->nanoseconds = demo_ld_u64(d + 0);
    return 0;
}

/* The general reader: lengths other than 8, bad bool bytes, error details. */
static DEMO_NOINLINE demo_status_t demo_shared_timestamp_decode_read(const uint8_t *data, size_t len,
                                                                     demo_shared_timestamp_t *out,
                                                                     demo_decode_error_t *err) {
    demo_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    demo_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return demo_shared_timestamp_read(&r, out) ? DEMO_ERR_DECODE : DEMO_OK;
}

demo_status_t demo_shared_timestamp_decode(const uint8_t *data, size_t len, demo_shared_timestamp_t *out,
                                           demo_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 8 && demo_shared_timestamp_load(data, out) == 0) {
        return DEMO_OK;
    }
    return demo_shared_timestamp_decode_read(data, len, out, err);
}

void demo_shared_timestamp_to_json(demo_jw_t *w, const demo_shared_timestamp_t *in) {
    int first = 1;
    demo_jw_raw(w, "{", 1);
    demo_jw_key(w, &first, "nanoseconds");
    demo_jw_u64(w, &in->nanoseconds);
    demo_jw_raw(w, "}", 1);
}

int demo_shared_timestamp_from_json(demo_jr_t *jr, size_t pos, demo_shared_timestamp_t *out) {
    static const char *const keys[] = {"nanoseconds"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (demo_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = demo_jr_get(jr, pos, "nanoseconds", &vp);
    if (found != 1) {
        return demo_jr_fail(jr, "missing parameter \"nanoseconds\"");
    }
    {
        demo_jr_push(jr, "nanoseconds");
        if (demo_jr_u64(jr, vp, &out->nanoseconds)) {
            return -1;
        }
        demo_jr_pop(jr);
    }
    return 0;
}
