/* Encoders and decoders of Data. Generated from the spec: do not edit. */
#include "democodec/sets/data.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- demo_data_sample_t */

static int demo_data_sample_read(demo_reader_t *r, demo_data_sample_t *out) {
    size_t i;
    demo_rd_push(r, "quat");
    for (i = 0; i < 4; i++) {
        demo_rd_index(r, i);
        if (demo_rd_f32(r, &out->quat[i])) {
            return -1;
        }
    }
    demo_rd_pop(r);
    demo_rd_push(r, "big");
    if (demo_rd_u64(r, &out->big)) {
        return -1;
    }
    demo_rd_pop(r);
    demo_rd_push(r, "small");
    if (demo_rd_s8(r, &out->small)) {
        return -1;
    }
    demo_rd_pop(r);
    demo_rd_push(r, "f");
    if (demo_rd_f32(r, &out->f)) {
        return -1;
    }
    demo_rd_pop(r);
    return demo_rd_finish(r);
}

static demo_status_t demo_data_sample_write(demo_writer_t *w, const demo_data_sample_t *in) {
    demo_status_t st;
    size_t i;
    for (i = 0; i < 4; i++) {
        if ((st = demo_wr_f32(w, &in->quat[i])) != DEMO_OK) {
            return st;
        }
    }
    if ((st = demo_wr_u64(w, &in->big)) != DEMO_OK) {
        return st;
    }
    if ((st = demo_wr_s8(w, &in->small)) != DEMO_OK) {
        return st;
    }
    if ((st = demo_wr_f32(w, &in->f)) != DEMO_OK) {
        return st;
    }
    return DEMO_OK;
}

demo_status_t demo_data_sample_encode(const demo_data_sample_t *value, uint8_t *buf, size_t cap,
                                      size_t *len_out) {
    demo_writer_t w;
    demo_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    demo_writer_init(&w, buf, cap);
    st = demo_data_sample_write(&w, value);
    if (st == DEMO_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 29 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int demo_data_sample_load(const uint8_t *d, demo_data_sample_t *out) {
    out->quat[0] = demo_ld_f32(d + 0);
    out->quat[1] = demo_ld_f32(d + 4);
    out->quat[2] = demo_ld_f32(d + 8);
    out->quat[3] = demo_ld_f32(d + 12);
    out->big = demo_ld_u64(d + 16);
    out->small = demo_ld_s8(d + 24);
    out->f = demo_ld_f32(d + 25);
    return 0;
}

/* The general reader: lengths other than 29, bad bool bytes, error details. */
static DEMO_NOINLINE demo_status_t demo_data_sample_decode_read(const uint8_t *data, size_t len,
                                                                demo_data_sample_t *out,
                                                                demo_decode_error_t *err) {
    demo_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    demo_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return demo_data_sample_read(&r, out) ? DEMO_ERR_DECODE : DEMO_OK;
}

demo_status_t demo_data_sample_decode(const uint8_t *data, size_t len, demo_data_sample_t *out,
                                      demo_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 29 && demo_data_sample_load(data, out) == 0) {
        return DEMO_OK;
    }
    return demo_data_sample_decode_read(data, len, out, err);
}

void demo_data_sample_to_json(demo_jw_t *w, const demo_data_sample_t *in) {
    int first = 1;
    size_t i;
    demo_jw_raw(w, "{", 1);
    demo_jw_key(w, &first, "quat");
    demo_jw_raw(w, "[", 1);
    for (i = 0; i < 4; i++) {
        demo_jw_sep(w, i);
        demo_jw_f32(w, &in->quat[i]);
    }
    demo_jw_raw(w, "]", 1);
    demo_jw_key(w, &first, "big");
    demo_jw_u64(w, &in->big);
    demo_jw_key(w, &first, "small");
    demo_jw_s8(w, &in->small);
    demo_jw_key(w, &first, "f");
    demo_jw_f32(w, &in->f);
    demo_jw_raw(w, "}", 1);
}

int demo_data_sample_from_json(demo_jr_t *jr, size_t pos, demo_data_sample_t *out) {
    static const char *const keys[] = {"quat", "big", "small", "f"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (demo_jr_object(jr, pos, keys, 4)) {
        return -1;
    }
    found = demo_jr_get(jr, pos, "quat", &vp);
    if (found != 1) {
        return demo_jr_fail(jr, "missing parameter \"quat\"");
    }
    {
        demo_jr_push(jr, "quat");
        if (demo_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = demo_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 4) {
                return demo_jr_fail(jr, "more than 4 elements");
            }
            demo_jr_index(jr, i);
            if (demo_jr_f32(jr, ep, &out->quat[i])) {
                return -1;
            }
        }
        demo_jr_index(jr, SIZE_MAX);
        if (i != 4) {
            return demo_jr_fail(jr, "expected 4 elements, got %zu", i);
        }
        demo_jr_pop(jr);
    }
    found = demo_jr_get(jr, pos, "big", &vp);
    if (found != 1) {
        return demo_jr_fail(jr, "missing parameter \"big\"");
    }
    {
        demo_jr_push(jr, "big");
        if (demo_jr_u64(jr, vp, &out->big)) {
            return -1;
        }
        demo_jr_pop(jr);
    }
    found = demo_jr_get(jr, pos, "small", &vp);
    if (found != 1) {
        return demo_jr_fail(jr, "missing parameter \"small\"");
    }
    {
        demo_jr_push(jr, "small");
        if (demo_jr_s8(jr, vp, &out->small)) {
            return -1;
        }
        demo_jr_pop(jr);
    }
    found = demo_jr_get(jr, pos, "f", &vp);
    if (found != 1) {
        return demo_jr_fail(jr, "missing parameter \"f\"");
    }
    {
        demo_jr_push(jr, "f");
        if (demo_jr_f32(jr, vp, &out->f)) {
            return -1;
        }
        demo_jr_pop(jr);
    }
    return 0;
}
