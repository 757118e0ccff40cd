/* Encoders and decoders of Receiver 2. Generated from the spec: do not edit. */
#include "democodec/sets/receiver_2.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- demo_receiver_2_llh_position_t */

static int demo_receiver_2_llh_position_read(demo_reader_t *r, demo_receiver_2_llh_position_t *out) {
    demo_rd_push(r, "latitude");
    if (demo_rd_f64(r, &out->latitude)) {
        return -1;
    }
    demo_rd_pop(r);
    demo_rd_push(r, "longitude");
    if (demo_rd_f64(r, &out->longitude)) {
        return -1;
    }
    demo_rd_pop(r);
    demo_rd_push(r, "valid_flags");
    if (demo_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    demo_rd_pop(r);
    return demo_rd_finish(r);
}

static demo_status_t demo_receiver_2_llh_position_write(demo_writer_t *w,
                                                        const demo_receiver_2_llh_position_t *in) {
    demo_status_t st;
    if ((st = demo_wr_f64(w, &in->latitude)) != DEMO_OK) {
        return st;
    }
    if ((st = demo_wr_f64(w, &in->longitude)) != DEMO_OK) {
        return st;
    }
    if ((st = demo_wr_u16(w, &in->valid_flags)) != DEMO_OK) {
        return st;
    }
    return DEMO_OK;
}

demo_status_t demo_receiver_2_llh_position_encode(const demo_receiver_2_llh_position_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out) {
    demo_writer_t w;
    demo_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    demo_writer_init(&w, buf, cap);
    st = demo_receiver_2_llh_position_write(&w, value);
    if (st == DEMO_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 18 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int demo_receiver_2_llh_position_load(const uint8_t *d, demo_receiver_2_llh_position_t *out) {
    out->latitude = demo_ld_f64(d + 0);
    out->longitude = demo_ld_f64(d + 8);
    out->valid_flags = demo_ld_u16(d + 16);
    return 0;
}

/* The general reader: lengths other than 18, bad bool bytes, error details. */
static DEMO_NOINLINE demo_status_t demo_receiver_2_llh_position_decode_read(
    const uint8_t *data, size_t len, demo_receiver_2_llh_position_t *out, demo_decode_error_t *err) {
    demo_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    demo_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return demo_receiver_2_llh_position_read(&r, out) ? DEMO_ERR_DECODE : DEMO_OK;
}

demo_status_t demo_receiver_2_llh_position_decode(const uint8_t *data, size_t len,
                                                  demo_receiver_2_llh_position_t *out,
                                                  demo_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 18 && demo_receiver_2_llh_position_load(data, out) == 0) {
        return DEMO_OK;
    }
    return demo_receiver_2_llh_position_decode_read(data, len, out, err);
}

void demo_receiver_2_llh_position_to_json(demo_jw_t *w, const demo_receiver_2_llh_position_t *in) {
    int first = 1;
    demo_jw_raw(w, "{", 1);
    demo_jw_key(w, &first, "latitude");
    demo_jw_f64(w, &in->latitude);
    demo_jw_key(w, &first, "longitude");
    demo_jw_f64(w, &in->longitude);
    demo_jw_key(w, &first, "valid_flags");
    demo_jw_u16(w, &in->valid_flags);
    demo_jw_raw(w, "}", 1);
}

int demo_receiver_2_llh_position_from_json(demo_jr_t *jr, size_t pos, demo_receiver_2_llh_position_t *out) {
    static const char *const keys[] = {"latitude", "longitude", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (demo_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = demo_jr_get(jr, pos, "latitude", &vp);
    if (found != 1) {
        return demo_jr_fail(jr, "missing parameter \"latitude\"");
    }
    {
        demo_jr_push(jr, "latitude");
        if (demo_jr_f64(jr, vp, &out->latitude)) {
            return -1;
        }
        demo_jr_pop(jr);
    }
    found = demo_jr_get(jr, pos, "longitude", &vp);
    if (found != 1) {
        return demo_jr_fail(jr, "missing parameter \"longitude\"");
    }
    {
        demo_jr_push(jr, "longitude");
        if (demo_jr_f64(jr, vp, &out->longitude)) {
            return -1;
        }
        demo_jr_pop(jr);
    }
    found = demo_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return demo_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        demo_jr_push(jr, "valid_flags");
        if (demo_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        demo_jr_pop(jr);
    }
    return 0;
}
