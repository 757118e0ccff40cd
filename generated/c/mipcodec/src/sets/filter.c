/* Encoders and decoders of Filter Command Set. Generated from the spec: do not edit. */
#include "mipcodec/sets/filter.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mip_filter_reset_filter_t */

static int mip_filter_reset_filter_read(mip_reader_t *r, mip_filter_reset_filter_t *out) {
    (void)out;
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_reset_filter_write(mip_writer_t *w, const mip_filter_reset_filter_t *in) {
    (void)w;
    (void)in;
    return MIP_OK;
}

mip_status_t mip_filter_reset_filter_encode(const mip_filter_reset_filter_t *value, uint8_t *buf, size_t cap,
                                            size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_reset_filter_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_reset_filter_decode(const uint8_t *data, size_t len, mip_filter_reset_filter_t *out,
                                            mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_reset_filter_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_reset_filter_to_json(mip_jw_t *w, const mip_filter_reset_filter_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mip_filter_reset_filter_from_json(mip_jr_t *jr, size_t pos, mip_filter_reset_filter_t *out) {
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mip_filter_set_initial_attitude_t */

static int mip_filter_set_initial_attitude_read(mip_reader_t *r, mip_filter_set_initial_attitude_t *out) {
    mip_rd_push(r, "roll");
    if (mip_rd_f32(r, &out->roll)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "pitch");
    if (mip_rd_f32(r, &out->pitch)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "heading");
    if (mip_rd_f32(r, &out->heading)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_set_initial_attitude_write(mip_writer_t *w,
                                                          const mip_filter_set_initial_attitude_t *in) {
    mip_status_t st;
    if ((st = mip_wr_f32(w, &in->roll)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->pitch)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->heading)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_filter_set_initial_attitude_encode(const mip_filter_set_initial_attitude_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_set_initial_attitude_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_filter_set_initial_attitude_load(const uint8_t *d, mip_filter_set_initial_attitude_t *out) {
    out->roll = mip_ld_f32(d + 0);
    out->pitch = mip_ld_f32(d + 4);
    out->heading = mip_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_set_initial_attitude_decode_read(
    const uint8_t *data, size_t len, mip_filter_set_initial_attitude_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_set_initial_attitude_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_filter_set_initial_attitude_decode(const uint8_t *data, size_t len,
                                                    mip_filter_set_initial_attitude_t *out,
                                                    mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mip_filter_set_initial_attitude_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_set_initial_attitude_decode_read(data, len, out, err);
}

void mip_filter_set_initial_attitude_to_json(mip_jw_t *w, const mip_filter_set_initial_attitude_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "roll");
    mip_jw_f32(w, &in->roll);
    mip_jw_key(w, &first, "pitch");
    mip_jw_f32(w, &in->pitch);
    mip_jw_key(w, &first, "heading");
    mip_jw_f32(w, &in->heading);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_set_initial_attitude_from_json(mip_jr_t *jr, size_t pos,
                                              mip_filter_set_initial_attitude_t *out) {
    static const char *const keys[] = {"roll", "pitch", "heading"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "roll", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"roll\"");
    }
    {
        mip_jr_push(jr, "roll");
        if (mip_jr_f32(jr, vp, &out->roll)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "pitch", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"pitch\"");
    }
    {
        mip_jr_push(jr, "pitch");
        if (mip_jr_f32(jr, vp, &out->pitch)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "heading", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"heading\"");
    }
    {
        mip_jr_push(jr, "heading");
        if (mip_jr_f32(jr, vp, &out->heading)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_set_initial_heading_t */

static int mip_filter_set_initial_heading_read(mip_reader_t *r, mip_filter_set_initial_heading_t *out) {
    mip_rd_push(r, "heading");
    if (mip_rd_f32(r, &out->heading)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_set_initial_heading_write(mip_writer_t *w,
                                                         const mip_filter_set_initial_heading_t *in) {
    mip_status_t st;
    if ((st = mip_wr_f32(w, &in->heading)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_filter_set_initial_heading_encode(const mip_filter_set_initial_heading_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_set_initial_heading_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 4 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_filter_set_initial_heading_load(const uint8_t *d, mip_filter_set_initial_heading_t *out) {
    out->heading = mip_ld_f32(d + 0);
    return 0;
}

/* The general reader: lengths other than 4, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_set_initial_heading_decode_read(
    const uint8_t *data, size_t len, mip_filter_set_initial_heading_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_set_initial_heading_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_filter_set_initial_heading_decode(const uint8_t *data, size_t len,
                                                   mip_filter_set_initial_heading_t *out,
                                                   mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 4 && mip_filter_set_initial_heading_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_set_initial_heading_decode_read(data, len, out, err);
}

void mip_filter_set_initial_heading_to_json(mip_jw_t *w, const mip_filter_set_initial_heading_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "heading");
    mip_jw_f32(w, &in->heading);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_set_initial_heading_from_json(mip_jr_t *jr, size_t pos,
                                             mip_filter_set_initial_heading_t *out) {
    static const char *const keys[] = {"heading"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "heading", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"heading\"");
    }
    {
        mip_jr_push(jr, "heading");
        if (mip_jr_f32(jr, vp, &out->heading)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_run_filter_t */

static int mip_filter_run_filter_read(mip_reader_t *r, mip_filter_run_filter_t *out) {
    (void)out;
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_run_filter_write(mip_writer_t *w, const mip_filter_run_filter_t *in) {
    (void)w;
    (void)in;
    return MIP_OK;
}

mip_status_t mip_filter_run_filter_encode(const mip_filter_run_filter_t *value, uint8_t *buf, size_t cap,
                                          size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_run_filter_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_run_filter_decode(const uint8_t *data, size_t len, mip_filter_run_filter_t *out,
                                          mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_run_filter_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_run_filter_to_json(mip_jw_t *w, const mip_filter_run_filter_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mip_filter_run_filter_from_json(mip_jr_t *jr, size_t pos, mip_filter_run_filter_t *out) {
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mip_filter_vehicle_dynamics_mode_t */

static int mip_filter_vehicle_dynamics_mode_read(mip_reader_t *r, mip_filter_vehicle_dynamics_mode_t *out) {
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_mode = true;
        mip_rd_push(r, "mode");
        if (mip_rd_u8(r, &out->mode)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_vehicle_dynamics_mode_write(mip_writer_t *w,
                                                           const mip_filter_vehicle_dynamics_mode_t *in) {
    mip_status_t st;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_mode) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u8(w, &in->mode)) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_vehicle_dynamics_mode_encode(const mip_filter_vehicle_dynamics_mode_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_vehicle_dynamics_mode_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_vehicle_dynamics_mode_decode(const uint8_t *data, size_t len,
                                                     mip_filter_vehicle_dynamics_mode_t *out,
                                                     mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_vehicle_dynamics_mode_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_vehicle_dynamics_mode_to_json(mip_jw_t *w, const mip_filter_vehicle_dynamics_mode_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_mode) {
        mip_jw_key(w, &first, "mode");
        mip_jw_u8(w, &in->mode);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_vehicle_dynamics_mode_from_json(mip_jr_t *jr, size_t pos,
                                               mip_filter_vehicle_dynamics_mode_t *out) {
    static const char *const keys[] = {"function", "mode"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "mode", &vp);
    out->has_mode = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"mode\" given after an absent one");
    } else {
        mip_jr_push(jr, "mode");
        if (mip_jr_u8(jr, vp, &out->mode)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_vehicle_dynamics_mode_response_t */

static int mip_filter_vehicle_dynamics_mode_response_read(mip_reader_t *r,
                                                          mip_filter_vehicle_dynamics_mode_response_t *out) {
    mip_rd_push(r, "mode");
    if (mip_rd_u8(r, &out->mode)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t
mip_filter_vehicle_dynamics_mode_response_write(mip_writer_t *w,
                                                const mip_filter_vehicle_dynamics_mode_response_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->mode)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t
mip_filter_vehicle_dynamics_mode_response_encode(const mip_filter_vehicle_dynamics_mode_response_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_vehicle_dynamics_mode_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_filter_vehicle_dynamics_mode_response_load(const uint8_t *d,
                                                          mip_filter_vehicle_dynamics_mode_response_t *out) {
    out->mode = mip_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_vehicle_dynamics_mode_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_vehicle_dynamics_mode_response_t *out,
    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_vehicle_dynamics_mode_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t
mip_filter_vehicle_dynamics_mode_response_decode(const uint8_t *data, size_t len,
                                                 mip_filter_vehicle_dynamics_mode_response_t *out,
                                                 mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mip_filter_vehicle_dynamics_mode_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_vehicle_dynamics_mode_response_decode_read(data, len, out, err);
}

void mip_filter_vehicle_dynamics_mode_response_to_json(
    mip_jw_t *w, const mip_filter_vehicle_dynamics_mode_response_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "mode");
    mip_jw_u8(w, &in->mode);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_vehicle_dynamics_mode_response_from_json(mip_jr_t *jr, size_t pos,
                                                        mip_filter_vehicle_dynamics_mode_response_t *out) {
    static const char *const keys[] = {"mode"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "mode", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"mode\"");
    }
    {
        mip_jr_push(jr, "mode");
        if (mip_jr_u8(jr, vp, &out->mode)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_sensor_to_vehicle_transform_t */

static int mip_filter_sensor_to_vehicle_transform_read(mip_reader_t *r,
                                                       mip_filter_sensor_to_vehicle_transform_t *out) {
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_roll = true;
        mip_rd_push(r, "roll");
        if (mip_rd_f32(r, &out->roll)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_pitch = true;
        mip_rd_push(r, "pitch");
        if (mip_rd_f32(r, &out->pitch)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_yaw = true;
        mip_rd_push(r, "yaw");
        if (mip_rd_f32(r, &out->yaw)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t
mip_filter_sensor_to_vehicle_transform_write(mip_writer_t *w,
                                             const mip_filter_sensor_to_vehicle_transform_t *in) {
    mip_status_t st;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_roll) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_f32(w, &in->roll)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_pitch) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_f32(w, &in->pitch)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_yaw) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_f32(w, &in->yaw)) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t
mip_filter_sensor_to_vehicle_transform_encode(const mip_filter_sensor_to_vehicle_transform_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_sensor_to_vehicle_transform_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_sensor_to_vehicle_transform_decode(const uint8_t *data, size_t len,
                                                           mip_filter_sensor_to_vehicle_transform_t *out,
                                                           mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_sensor_to_vehicle_transform_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_sensor_to_vehicle_transform_to_json(mip_jw_t *w,
                                                    const mip_filter_sensor_to_vehicle_transform_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_roll) {
        mip_jw_key(w, &first, "roll");
        mip_jw_f32(w, &in->roll);
    }
    if (in->has_pitch) {
        mip_jw_key(w, &first, "pitch");
        mip_jw_f32(w, &in->pitch);
    }
    if (in->has_yaw) {
        mip_jw_key(w, &first, "yaw");
        mip_jw_f32(w, &in->yaw);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_sensor_to_vehicle_transform_from_json(mip_jr_t *jr, size_t pos,
                                                     mip_filter_sensor_to_vehicle_transform_t *out) {
    static const char *const keys[] = {"function", "roll", "pitch", "yaw"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 4)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "roll", &vp);
    out->has_roll = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"roll\" given after an absent one");
    } else {
        mip_jr_push(jr, "roll");
        if (mip_jr_f32(jr, vp, &out->roll)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "pitch", &vp);
    out->has_pitch = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"pitch\" given after an absent one");
    } else {
        mip_jr_push(jr, "pitch");
        if (mip_jr_f32(jr, vp, &out->pitch)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "yaw", &vp);
    out->has_yaw = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"yaw\" given after an absent one");
    } else {
        mip_jr_push(jr, "yaw");
        if (mip_jr_f32(jr, vp, &out->yaw)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_sensor_to_vehicle_transform_response_t */

static int
mip_filter_sensor_to_vehicle_transform_response_read(mip_reader_t *r,
                                                     mip_filter_sensor_to_vehicle_transform_response_t *out) {
    mip_rd_push(r, "roll");
    if (mip_rd_f32(r, &out->roll)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "pitch");
    if (mip_rd_f32(r, &out->pitch)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "yaw");
    if (mip_rd_f32(r, &out->yaw)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_sensor_to_vehicle_transform_response_write(
    mip_writer_t *w, const mip_filter_sensor_to_vehicle_transform_response_t *in) {
    mip_status_t st;
    if ((st = mip_wr_f32(w, &in->roll)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->pitch)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->yaw)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_filter_sensor_to_vehicle_transform_response_encode(
    const mip_filter_sensor_to_vehicle_transform_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_sensor_to_vehicle_transform_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mip_filter_sensor_to_vehicle_transform_response_load(const uint8_t *d,
                                                     mip_filter_sensor_to_vehicle_transform_response_t *out) {
    out->roll = mip_ld_f32(d + 0);
    out->pitch = mip_ld_f32(d + 4);
    out->yaw = mip_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_sensor_to_vehicle_transform_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_sensor_to_vehicle_transform_response_t *out,
    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_sensor_to_vehicle_transform_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t
mip_filter_sensor_to_vehicle_transform_response_decode(const uint8_t *data, size_t len,
                                                       mip_filter_sensor_to_vehicle_transform_response_t *out,
                                                       mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mip_filter_sensor_to_vehicle_transform_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_sensor_to_vehicle_transform_response_decode_read(data, len, out, err);
}

void mip_filter_sensor_to_vehicle_transform_response_to_json(
    mip_jw_t *w, const mip_filter_sensor_to_vehicle_transform_response_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "roll");
    mip_jw_f32(w, &in->roll);
    mip_jw_key(w, &first, "pitch");
    mip_jw_f32(w, &in->pitch);
    mip_jw_key(w, &first, "yaw");
    mip_jw_f32(w, &in->yaw);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_sensor_to_vehicle_transform_response_from_json(
    mip_jr_t *jr, size_t pos, mip_filter_sensor_to_vehicle_transform_response_t *out) {
    static const char *const keys[] = {"roll", "pitch", "yaw"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "roll", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"roll\"");
    }
    {
        mip_jr_push(jr, "roll");
        if (mip_jr_f32(jr, vp, &out->roll)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "pitch", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"pitch\"");
    }
    {
        mip_jr_push(jr, "pitch");
        if (mip_jr_f32(jr, vp, &out->pitch)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "yaw", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"yaw\"");
    }
    {
        mip_jr_push(jr, "yaw");
        if (mip_jr_f32(jr, vp, &out->yaw)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_sensor_to_vehicle_offset_t */

static int mip_filter_sensor_to_vehicle_offset_read(mip_reader_t *r,
                                                    mip_filter_sensor_to_vehicle_offset_t *out) {
    size_t i;
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_offset = true;
        mip_rd_push(r, "offset");
        for (i = 0; i < 3; i++) {
            mip_rd_index(r, i);
            if (mip_rd_f32(r, &out->offset[i])) {
                return -1;
            }
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t
mip_filter_sensor_to_vehicle_offset_write(mip_writer_t *w, const mip_filter_sensor_to_vehicle_offset_t *in) {
    mip_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_offset) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mip_wr_f32(w, &in->offset[i])) != MIP_OK) {
                return st;
            }
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_sensor_to_vehicle_offset_encode(const mip_filter_sensor_to_vehicle_offset_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_sensor_to_vehicle_offset_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_sensor_to_vehicle_offset_decode(const uint8_t *data, size_t len,
                                                        mip_filter_sensor_to_vehicle_offset_t *out,
                                                        mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_sensor_to_vehicle_offset_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_sensor_to_vehicle_offset_to_json(mip_jw_t *w,
                                                 const mip_filter_sensor_to_vehicle_offset_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_offset) {
        mip_jw_key(w, &first, "offset");
        mip_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mip_jw_sep(w, i);
            mip_jw_f32(w, &in->offset[i]);
        }
        mip_jw_raw(w, "]", 1);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_sensor_to_vehicle_offset_from_json(mip_jr_t *jr, size_t pos,
                                                  mip_filter_sensor_to_vehicle_offset_t *out) {
    static const char *const keys[] = {"function", "offset"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "offset", &vp);
    out->has_offset = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"offset\" given after an absent one");
    } else {
        mip_jr_push(jr, "offset");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->offset[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_sensor_to_vehicle_offset_response_t */

static int
mip_filter_sensor_to_vehicle_offset_response_read(mip_reader_t *r,
                                                  mip_filter_sensor_to_vehicle_offset_response_t *out) {
    size_t i;
    mip_rd_push(r, "offset");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->offset[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t
mip_filter_sensor_to_vehicle_offset_response_write(mip_writer_t *w,
                                                   const mip_filter_sensor_to_vehicle_offset_response_t *in) {
    mip_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->offset[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_sensor_to_vehicle_offset_response_encode(
    const mip_filter_sensor_to_vehicle_offset_response_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_sensor_to_vehicle_offset_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mip_filter_sensor_to_vehicle_offset_response_load(const uint8_t *d,
                                                  mip_filter_sensor_to_vehicle_offset_response_t *out) {
    out->offset[0] = mip_ld_f32(d + 0);
    out->offset[1] = mip_ld_f32(d + 4);
    out->offset[2] = mip_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_sensor_to_vehicle_offset_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_sensor_to_vehicle_offset_response_t *out,
    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_sensor_to_vehicle_offset_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t
mip_filter_sensor_to_vehicle_offset_response_decode(const uint8_t *data, size_t len,
                                                    mip_filter_sensor_to_vehicle_offset_response_t *out,
                                                    mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mip_filter_sensor_to_vehicle_offset_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_sensor_to_vehicle_offset_response_decode_read(data, len, out, err);
}

void mip_filter_sensor_to_vehicle_offset_response_to_json(
    mip_jw_t *w, const mip_filter_sensor_to_vehicle_offset_response_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "offset");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->offset[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_sensor_to_vehicle_offset_response_from_json(
    mip_jr_t *jr, size_t pos, mip_filter_sensor_to_vehicle_offset_response_t *out) {
    static const char *const keys[] = {"offset"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "offset", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"offset\"");
    }
    {
        mip_jr_push(jr, "offset");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->offset[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_antenna_offset_t */

static int mip_filter_antenna_offset_read(mip_reader_t *r, mip_filter_antenna_offset_t *out) {
    size_t i;
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_offset = true;
        mip_rd_push(r, "offset");
        for (i = 0; i < 3; i++) {
            mip_rd_index(r, i);
            if (mip_rd_f32(r, &out->offset[i])) {
                return -1;
            }
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_antenna_offset_write(mip_writer_t *w, const mip_filter_antenna_offset_t *in) {
    mip_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_offset) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mip_wr_f32(w, &in->offset[i])) != MIP_OK) {
                return st;
            }
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_antenna_offset_encode(const mip_filter_antenna_offset_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_antenna_offset_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_antenna_offset_decode(const uint8_t *data, size_t len,
                                              mip_filter_antenna_offset_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_antenna_offset_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_antenna_offset_to_json(mip_jw_t *w, const mip_filter_antenna_offset_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_offset) {
        mip_jw_key(w, &first, "offset");
        mip_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mip_jw_sep(w, i);
            mip_jw_f32(w, &in->offset[i]);
        }
        mip_jw_raw(w, "]", 1);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_antenna_offset_from_json(mip_jr_t *jr, size_t pos, mip_filter_antenna_offset_t *out) {
    static const char *const keys[] = {"function", "offset"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "offset", &vp);
    out->has_offset = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"offset\" given after an absent one");
    } else {
        mip_jr_push(jr, "offset");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->offset[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_antenna_offset_response_t */

static int mip_filter_antenna_offset_response_read(mip_reader_t *r,
                                                   mip_filter_antenna_offset_response_t *out) {
    size_t i;
    mip_rd_push(r, "offset");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->offset[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_antenna_offset_response_write(mip_writer_t *w,
                                                             const mip_filter_antenna_offset_response_t *in) {
    mip_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->offset[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_antenna_offset_response_encode(const mip_filter_antenna_offset_response_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_antenna_offset_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_filter_antenna_offset_response_load(const uint8_t *d,
                                                   mip_filter_antenna_offset_response_t *out) {
    out->offset[0] = mip_ld_f32(d + 0);
    out->offset[1] = mip_ld_f32(d + 4);
    out->offset[2] = mip_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_antenna_offset_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_antenna_offset_response_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_antenna_offset_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_filter_antenna_offset_response_decode(const uint8_t *data, size_t len,
                                                       mip_filter_antenna_offset_response_t *out,
                                                       mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mip_filter_antenna_offset_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_antenna_offset_response_decode_read(data, len, out, err);
}

void mip_filter_antenna_offset_response_to_json(mip_jw_t *w, const mip_filter_antenna_offset_response_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "offset");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->offset[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_antenna_offset_response_from_json(mip_jr_t *jr, size_t pos,
                                                 mip_filter_antenna_offset_response_t *out) {
    static const char *const keys[] = {"offset"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "offset", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"offset\"");
    }
    {
        mip_jr_push(jr, "offset");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->offset[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_estimation_control_t */

static int mip_filter_estimation_control_read(mip_reader_t *r, mip_filter_estimation_control_t *out) {
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_flags = true;
        mip_rd_push(r, "flags");
        if (mip_rd_u16(r, &out->flags)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_estimation_control_write(mip_writer_t *w,
                                                        const mip_filter_estimation_control_t *in) {
    mip_status_t st;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_flags) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u16(w, &in->flags)) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_estimation_control_encode(const mip_filter_estimation_control_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_estimation_control_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_estimation_control_decode(const uint8_t *data, size_t len,
                                                  mip_filter_estimation_control_t *out,
                                                  mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_estimation_control_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_estimation_control_to_json(mip_jw_t *w, const mip_filter_estimation_control_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_flags) {
        mip_jw_key(w, &first, "flags");
        mip_jw_u16(w, &in->flags);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_estimation_control_from_json(mip_jr_t *jr, size_t pos, mip_filter_estimation_control_t *out) {
    static const char *const keys[] = {"function", "flags"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "flags", &vp);
    out->has_flags = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"flags\" given after an absent one");
    } else {
        mip_jr_push(jr, "flags");
        if (mip_jr_u16(jr, vp, &out->flags)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_estimation_control_response_t */

static int mip_filter_estimation_control_response_read(mip_reader_t *r,
                                                       mip_filter_estimation_control_response_t *out) {
    mip_rd_push(r, "flags");
    if (mip_rd_u16(r, &out->flags)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t
mip_filter_estimation_control_response_write(mip_writer_t *w,
                                             const mip_filter_estimation_control_response_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u16(w, &in->flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t
mip_filter_estimation_control_response_encode(const mip_filter_estimation_control_response_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_estimation_control_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_filter_estimation_control_response_load(const uint8_t *d,
                                                       mip_filter_estimation_control_response_t *out) {
    out->flags = mip_ld_u16(d + 0);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_estimation_control_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_estimation_control_response_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_estimation_control_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_filter_estimation_control_response_decode(const uint8_t *data, size_t len,
                                                           mip_filter_estimation_control_response_t *out,
                                                           mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 2 && mip_filter_estimation_control_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_estimation_control_response_decode_read(data, len, out, err);
}

void mip_filter_estimation_control_response_to_json(mip_jw_t *w,
                                                    const mip_filter_estimation_control_response_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "flags");
    mip_jw_u16(w, &in->flags);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_estimation_control_response_from_json(mip_jr_t *jr, size_t pos,
                                                     mip_filter_estimation_control_response_t *out) {
    static const char *const keys[] = {"flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "flags", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"flags\"");
    }
    {
        mip_jr_push(jr, "flags");
        if (mip_jr_u16(jr, vp, &out->flags)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_gnss_source_control_t */

static int mip_filter_gnss_source_control_read(mip_reader_t *r, mip_filter_gnss_source_control_t *out) {
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_source = true;
        mip_rd_push(r, "source");
        if (mip_rd_u8(r, &out->source)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_gnss_source_control_write(mip_writer_t *w,
                                                         const mip_filter_gnss_source_control_t *in) {
    mip_status_t st;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_source) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u8(w, &in->source)) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_gnss_source_control_encode(const mip_filter_gnss_source_control_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_gnss_source_control_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_gnss_source_control_decode(const uint8_t *data, size_t len,
                                                   mip_filter_gnss_source_control_t *out,
                                                   mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_gnss_source_control_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_gnss_source_control_to_json(mip_jw_t *w, const mip_filter_gnss_source_control_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_source) {
        mip_jw_key(w, &first, "source");
        mip_jw_u8(w, &in->source);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_gnss_source_control_from_json(mip_jr_t *jr, size_t pos,
                                             mip_filter_gnss_source_control_t *out) {
    static const char *const keys[] = {"function", "source"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "source", &vp);
    out->has_source = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"source\" given after an absent one");
    } else {
        mip_jr_push(jr, "source");
        if (mip_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_gnss_source_control_response_t */

static int mip_filter_gnss_source_control_response_read(mip_reader_t *r,
                                                        mip_filter_gnss_source_control_response_t *out) {
    mip_rd_push(r, "source");
    if (mip_rd_u8(r, &out->source)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t
mip_filter_gnss_source_control_response_write(mip_writer_t *w,
                                              const mip_filter_gnss_source_control_response_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->source)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t
mip_filter_gnss_source_control_response_encode(const mip_filter_gnss_source_control_response_t *value,
                                               uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_gnss_source_control_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_filter_gnss_source_control_response_load(const uint8_t *d,
                                                        mip_filter_gnss_source_control_response_t *out) {
    out->source = mip_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_gnss_source_control_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_gnss_source_control_response_t *out,
    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_gnss_source_control_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_filter_gnss_source_control_response_decode(const uint8_t *data, size_t len,
                                                            mip_filter_gnss_source_control_response_t *out,
                                                            mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mip_filter_gnss_source_control_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_gnss_source_control_response_decode_read(data, len, out, err);
}

void mip_filter_gnss_source_control_response_to_json(mip_jw_t *w,
                                                     const mip_filter_gnss_source_control_response_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "source");
    mip_jw_u8(w, &in->source);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_gnss_source_control_response_from_json(mip_jr_t *jr, size_t pos,
                                                      mip_filter_gnss_source_control_response_t *out) {
    static const char *const keys[] = {"source"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "source", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"source\"");
    }
    {
        mip_jr_push(jr, "source");
        if (mip_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_external_gnss_update_t */

static int mip_filter_external_gnss_update_read(mip_reader_t *r, mip_filter_external_gnss_update_t *out) {
    size_t i;
    mip_rd_push(r, "gps_tow");
    if (mip_rd_f64(r, &out->gps_tow)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "gps_week");
    if (mip_rd_u16(r, &out->gps_week)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "latitude");
    if (mip_rd_f64(r, &out->latitude)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "longitude");
    if (mip_rd_f64(r, &out->longitude)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "height");
    if (mip_rd_f64(r, &out->height)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "velocity");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->velocity[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    mip_rd_push(r, "position_uncertainty");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->position_uncertainty[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    mip_rd_push(r, "velocity_uncertainty");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->velocity_uncertainty[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_external_gnss_update_write(mip_writer_t *w,
                                                          const mip_filter_external_gnss_update_t *in) {
    mip_status_t st;
    size_t i;
    if ((st = mip_wr_f64(w, &in->gps_tow)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->gps_week)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->latitude)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->longitude)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->height)) != MIP_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->velocity[i])) != MIP_OK) {
            return st;
        }
    }
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->position_uncertainty[i])) != MIP_OK) {
            return st;
        }
    }
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->velocity_uncertainty[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_external_gnss_update_encode(const mip_filter_external_gnss_update_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_external_gnss_update_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 70 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_filter_external_gnss_update_load(const uint8_t *d, mip_filter_external_gnss_update_t *out) {
    out->gps_tow = mip_ld_f64(d + 0);
    out->gps_week = mip_ld_u16(d + 8);
    out->latitude = mip_ld_f64(d + 10);
    out->longitude = mip_ld_f64(d + 18);
    out->height = mip_ld_f64(d + 26);
    out->velocity[0] = mip_ld_f32(d + 34);
    out->velocity[1] = mip_ld_f32(d + 38);
    out->velocity[2] = mip_ld_f32(d + 42);
    out->position_uncertainty[0] = mip_ld_f32(d + 46);
    out->position_uncertainty[1] = mip_ld_f32(d + 50);
    out->position_uncertainty[2] = mip_ld_f32(d + 54);
    out->velocity_uncertainty[0] = mip_ld_f32(d + 58);
    out->velocity_uncertainty[1] = mip_ld_f32(d + 62);
    out->velocity_uncertainty[2] = mip_ld_f32(d + 66);
    return 0;
}

/* The general reader: lengths other than 70, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_external_gnss_update_decode_read(
    const uint8_t *data, size_t len, mip_filter_external_gnss_update_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_external_gnss_update_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_filter_external_gnss_update_decode(const uint8_t *data, size_t len,
                                                    mip_filter_external_gnss_update_t *out,
                                                    mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 70 && mip_filter_external_gnss_update_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_external_gnss_update_decode_read(data, len, out, err);
}

void mip_filter_external_gnss_update_to_json(mip_jw_t *w, const mip_filter_external_gnss_update_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "gps_tow");
    mip_jw_f64(w, &in->gps_tow);
    mip_jw_key(w, &first, "gps_week");
    mip_jw_u16(w, &in->gps_week);
    mip_jw_key(w, &first, "latitude");
    mip_jw_f64(w, &in->latitude);
    mip_jw_key(w, &first, "longitude");
    mip_jw_f64(w, &in->longitude);
    mip_jw_key(w, &first, "height");
    mip_jw_f64(w, &in->height);
    mip_jw_key(w, &first, "velocity");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->velocity[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_key(w, &first, "position_uncertainty");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->position_uncertainty[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_key(w, &first, "velocity_uncertainty");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->velocity_uncertainty[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_external_gnss_update_from_json(mip_jr_t *jr, size_t pos,
                                              mip_filter_external_gnss_update_t *out) {
    static const char *const keys[] = {"gps_tow",
                                       "gps_week",
                                       "latitude",
                                       "longitude",
                                       "height",
                                       "velocity",
                                       "position_uncertainty",
                                       "velocity_uncertainty"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 8)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "gps_tow", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"gps_tow\"");
    }
    {
        mip_jr_push(jr, "gps_tow");
        if (mip_jr_f64(jr, vp, &out->gps_tow)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "gps_week", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"gps_week\"");
    }
    {
        mip_jr_push(jr, "gps_week");
        if (mip_jr_u16(jr, vp, &out->gps_week)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "latitude", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"latitude\"");
    }
    {
        mip_jr_push(jr, "latitude");
        if (mip_jr_f64(jr, vp, &out->latitude)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "longitude", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"longitude\"");
    }
    {
        mip_jr_push(jr, "longitude");
        if (mip_jr_f64(jr, vp, &out->longitude)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "height", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"height\"");
    }
    {
        mip_jr_push(jr, "height");
        if (mip_jr_f64(jr, vp, &out->height)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "velocity", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"velocity\"");
    }
    {
        mip_jr_push(jr, "velocity");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->velocity[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "position_uncertainty", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"position_uncertainty\"");
    }
    {
        mip_jr_push(jr, "position_uncertainty");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->position_uncertainty[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "velocity_uncertainty", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"velocity_uncertainty\"");
    }
    {
        mip_jr_push(jr, "velocity_uncertainty");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->velocity_uncertainty[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_external_heading_update_t */

static int mip_filter_external_heading_update_read(mip_reader_t *r,
                                                   mip_filter_external_heading_update_t *out) {
    mip_rd_push(r, "heading");
    if (mip_rd_f32(r, &out->heading)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "heading_uncertainty");
    if (mip_rd_f32(r, &out->heading_uncertainty)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "type");
    if (mip_rd_u8(r, &out->type)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_external_heading_update_write(mip_writer_t *w,
                                                             const mip_filter_external_heading_update_t *in) {
    mip_status_t st;
    if ((st = mip_wr_f32(w, &in->heading)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->heading_uncertainty)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->type)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_filter_external_heading_update_encode(const mip_filter_external_heading_update_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_external_heading_update_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 9 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_filter_external_heading_update_load(const uint8_t *d,
                                                   mip_filter_external_heading_update_t *out) {
    out->heading = mip_ld_f32(d + 0);
    out->heading_uncertainty = mip_ld_f32(d + 4);
    out->type = mip_ld_u8(d + 8);
    return 0;
}

/* The general reader: lengths other than 9, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_external_heading_update_decode_read(
    const uint8_t *data, size_t len, mip_filter_external_heading_update_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_external_heading_update_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_filter_external_heading_update_decode(const uint8_t *data, size_t len,
                                                       mip_filter_external_heading_update_t *out,
                                                       mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 9 && mip_filter_external_heading_update_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_external_heading_update_decode_read(data, len, out, err);
}

void mip_filter_external_heading_update_to_json(mip_jw_t *w, const mip_filter_external_heading_update_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "heading");
    mip_jw_f32(w, &in->heading);
    mip_jw_key(w, &first, "heading_uncertainty");
    mip_jw_f32(w, &in->heading_uncertainty);
    mip_jw_key(w, &first, "type");
    mip_jw_u8(w, &in->type);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_external_heading_update_from_json(mip_jr_t *jr, size_t pos,
                                                 mip_filter_external_heading_update_t *out) {
    static const char *const keys[] = {"heading", "heading_uncertainty", "type"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "heading", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"heading\"");
    }
    {
        mip_jr_push(jr, "heading");
        if (mip_jr_f32(jr, vp, &out->heading)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "heading_uncertainty", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"heading_uncertainty\"");
    }
    {
        mip_jr_push(jr, "heading_uncertainty");
        if (mip_jr_f32(jr, vp, &out->heading_uncertainty)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "type", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"type\"");
    }
    {
        mip_jr_push(jr, "type");
        if (mip_jr_u8(jr, vp, &out->type)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_heading_update_control_t */

static int mip_filter_heading_update_control_read(mip_reader_t *r, mip_filter_heading_update_control_t *out) {
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_source = true;
        mip_rd_push(r, "source");
        if (mip_rd_u8(r, &out->source)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_heading_update_control_write(mip_writer_t *w,
                                                            const mip_filter_heading_update_control_t *in) {
    mip_status_t st;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_source) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u8(w, &in->source)) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_heading_update_control_encode(const mip_filter_heading_update_control_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_heading_update_control_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_heading_update_control_decode(const uint8_t *data, size_t len,
                                                      mip_filter_heading_update_control_t *out,
                                                      mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_heading_update_control_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_heading_update_control_to_json(mip_jw_t *w, const mip_filter_heading_update_control_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_source) {
        mip_jw_key(w, &first, "source");
        mip_jw_u8(w, &in->source);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_heading_update_control_from_json(mip_jr_t *jr, size_t pos,
                                                mip_filter_heading_update_control_t *out) {
    static const char *const keys[] = {"function", "source"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "source", &vp);
    out->has_source = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"source\" given after an absent one");
    } else {
        mip_jr_push(jr, "source");
        if (mip_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_heading_update_control_response_t */

static int
mip_filter_heading_update_control_response_read(mip_reader_t *r,
                                                mip_filter_heading_update_control_response_t *out) {
    mip_rd_push(r, "source");
    if (mip_rd_u8(r, &out->source)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t
mip_filter_heading_update_control_response_write(mip_writer_t *w,
                                                 const mip_filter_heading_update_control_response_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->source)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t
mip_filter_heading_update_control_response_encode(const mip_filter_heading_update_control_response_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_heading_update_control_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mip_filter_heading_update_control_response_load(const uint8_t *d,
                                                mip_filter_heading_update_control_response_t *out) {
    out->source = mip_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_heading_update_control_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_heading_update_control_response_t *out,
    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_heading_update_control_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t
mip_filter_heading_update_control_response_decode(const uint8_t *data, size_t len,
                                                  mip_filter_heading_update_control_response_t *out,
                                                  mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mip_filter_heading_update_control_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_heading_update_control_response_decode_read(data, len, out, err);
}

void mip_filter_heading_update_control_response_to_json(
    mip_jw_t *w, const mip_filter_heading_update_control_response_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "source");
    mip_jw_u8(w, &in->source);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_heading_update_control_response_from_json(mip_jr_t *jr, size_t pos,
                                                         mip_filter_heading_update_control_response_t *out) {
    static const char *const keys[] = {"source"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "source", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"source\"");
    }
    {
        mip_jr_push(jr, "source");
        if (mip_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_auto_init_control_t */

static int mip_filter_auto_init_control_read(mip_reader_t *r, mip_filter_auto_init_control_t *out) {
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_enable = true;
        mip_rd_push(r, "enable");
        if (mip_rd_u8(r, &out->enable)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_auto_init_control_write(mip_writer_t *w,
                                                       const mip_filter_auto_init_control_t *in) {
    mip_status_t st;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_enable) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u8(w, &in->enable)) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_auto_init_control_encode(const mip_filter_auto_init_control_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_auto_init_control_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_auto_init_control_decode(const uint8_t *data, size_t len,
                                                 mip_filter_auto_init_control_t *out,
                                                 mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_auto_init_control_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_auto_init_control_to_json(mip_jw_t *w, const mip_filter_auto_init_control_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_enable) {
        mip_jw_key(w, &first, "enable");
        mip_jw_u8(w, &in->enable);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_auto_init_control_from_json(mip_jr_t *jr, size_t pos, mip_filter_auto_init_control_t *out) {
    static const char *const keys[] = {"function", "enable"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "enable", &vp);
    out->has_enable = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"enable\" given after an absent one");
    } else {
        mip_jr_push(jr, "enable");
        if (mip_jr_u8(jr, vp, &out->enable)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_auto_init_control_response_t */

static int mip_filter_auto_init_control_response_read(mip_reader_t *r,
                                                      mip_filter_auto_init_control_response_t *out) {
    mip_rd_push(r, "enable");
    if (mip_rd_u8(r, &out->enable)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t
mip_filter_auto_init_control_response_write(mip_writer_t *w,
                                            const mip_filter_auto_init_control_response_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->enable)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t
mip_filter_auto_init_control_response_encode(const mip_filter_auto_init_control_response_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_auto_init_control_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_filter_auto_init_control_response_load(const uint8_t *d,
                                                      mip_filter_auto_init_control_response_t *out) {
    out->enable = mip_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_auto_init_control_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_auto_init_control_response_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_auto_init_control_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_filter_auto_init_control_response_decode(const uint8_t *data, size_t len,
                                                          mip_filter_auto_init_control_response_t *out,
                                                          mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mip_filter_auto_init_control_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_auto_init_control_response_decode_read(data, len, out, err);
}

void mip_filter_auto_init_control_response_to_json(mip_jw_t *w,
                                                   const mip_filter_auto_init_control_response_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "enable");
    mip_jw_u8(w, &in->enable);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_auto_init_control_response_from_json(mip_jr_t *jr, size_t pos,
                                                    mip_filter_auto_init_control_response_t *out) {
    static const char *const keys[] = {"enable"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "enable", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"enable\"");
    }
    {
        mip_jr_push(jr, "enable");
        if (mip_jr_u8(jr, vp, &out->enable)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_accel_noise_t */

static int mip_filter_accel_noise_read(mip_reader_t *r, mip_filter_accel_noise_t *out) {
    size_t i;
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_noise = true;
        mip_rd_push(r, "noise");
        for (i = 0; i < 3; i++) {
            mip_rd_index(r, i);
            if (mip_rd_f32(r, &out->noise[i])) {
                return -1;
            }
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_accel_noise_write(mip_writer_t *w, const mip_filter_accel_noise_t *in) {
    mip_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_noise) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mip_wr_f32(w, &in->noise[i])) != MIP_OK) {
                return st;
            }
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_accel_noise_encode(const mip_filter_accel_noise_t *value, uint8_t *buf, size_t cap,
                                           size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_accel_noise_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_accel_noise_decode(const uint8_t *data, size_t len, mip_filter_accel_noise_t *out,
                                           mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_accel_noise_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_accel_noise_to_json(mip_jw_t *w, const mip_filter_accel_noise_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_noise) {
        mip_jw_key(w, &first, "noise");
        mip_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mip_jw_sep(w, i);
            mip_jw_f32(w, &in->noise[i]);
        }
        mip_jw_raw(w, "]", 1);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_accel_noise_from_json(mip_jr_t *jr, size_t pos, mip_filter_accel_noise_t *out) {
    static const char *const keys[] = {"function", "noise"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "noise", &vp);
    out->has_noise = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"noise\" given after an absent one");
    } else {
        mip_jr_push(jr, "noise");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->noise[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_accel_noise_response_t */

static int mip_filter_accel_noise_response_read(mip_reader_t *r, mip_filter_accel_noise_response_t *out) {
    size_t i;
    mip_rd_push(r, "noise");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->noise[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_accel_noise_response_write(mip_writer_t *w,
                                                          const mip_filter_accel_noise_response_t *in) {
    mip_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->noise[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_accel_noise_response_encode(const mip_filter_accel_noise_response_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_accel_noise_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_filter_accel_noise_response_load(const uint8_t *d, mip_filter_accel_noise_response_t *out) {
    out->noise[0] = mip_ld_f32(d + 0);
    out->noise[1] = mip_ld_f32(d + 4);
    out->noise[2] = mip_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_accel_noise_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_accel_noise_response_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_accel_noise_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_filter_accel_noise_response_decode(const uint8_t *data, size_t len,
                                                    mip_filter_accel_noise_response_t *out,
                                                    mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mip_filter_accel_noise_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_accel_noise_response_decode_read(data, len, out, err);
}

void mip_filter_accel_noise_response_to_json(mip_jw_t *w, const mip_filter_accel_noise_response_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "noise");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->noise[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_accel_noise_response_from_json(mip_jr_t *jr, size_t pos,
                                              mip_filter_accel_noise_response_t *out) {
    static const char *const keys[] = {"noise"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "noise", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"noise\"");
    }
    {
        mip_jr_push(jr, "noise");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->noise[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_gyro_noise_t */

static int mip_filter_gyro_noise_read(mip_reader_t *r, mip_filter_gyro_noise_t *out) {
    size_t i;
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_noise = true;
        mip_rd_push(r, "noise");
        for (i = 0; i < 3; i++) {
            mip_rd_index(r, i);
            if (mip_rd_f32(r, &out->noise[i])) {
                return -1;
            }
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_gyro_noise_write(mip_writer_t *w, const mip_filter_gyro_noise_t *in) {
    mip_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_noise) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mip_wr_f32(w, &in->noise[i])) != MIP_OK) {
                return st;
            }
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_gyro_noise_encode(const mip_filter_gyro_noise_t *value, uint8_t *buf, size_t cap,
                                          size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_gyro_noise_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_gyro_noise_decode(const uint8_t *data, size_t len, mip_filter_gyro_noise_t *out,
                                          mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_gyro_noise_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_gyro_noise_to_json(mip_jw_t *w, const mip_filter_gyro_noise_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_noise) {
        mip_jw_key(w, &first, "noise");
        mip_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mip_jw_sep(w, i);
            mip_jw_f32(w, &in->noise[i]);
        }
        mip_jw_raw(w, "]", 1);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_gyro_noise_from_json(mip_jr_t *jr, size_t pos, mip_filter_gyro_noise_t *out) {
    static const char *const keys[] = {"function", "noise"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "noise", &vp);
    out->has_noise = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"noise\" given after an absent one");
    } else {
        mip_jr_push(jr, "noise");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->noise[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_gyro_noise_response_t */

static int mip_filter_gyro_noise_response_read(mip_reader_t *r, mip_filter_gyro_noise_response_t *out) {
    size_t i;
    mip_rd_push(r, "noise");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->noise[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_gyro_noise_response_write(mip_writer_t *w,
                                                         const mip_filter_gyro_noise_response_t *in) {
    mip_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->noise[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_gyro_noise_response_encode(const mip_filter_gyro_noise_response_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_gyro_noise_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_filter_gyro_noise_response_load(const uint8_t *d, mip_filter_gyro_noise_response_t *out) {
    out->noise[0] = mip_ld_f32(d + 0);
    out->noise[1] = mip_ld_f32(d + 4);
    out->noise[2] = mip_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_gyro_noise_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_gyro_noise_response_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_gyro_noise_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_filter_gyro_noise_response_decode(const uint8_t *data, size_t len,
                                                   mip_filter_gyro_noise_response_t *out,
                                                   mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mip_filter_gyro_noise_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_gyro_noise_response_decode_read(data, len, out, err);
}

void mip_filter_gyro_noise_response_to_json(mip_jw_t *w, const mip_filter_gyro_noise_response_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "noise");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->noise[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_gyro_noise_response_from_json(mip_jr_t *jr, size_t pos,
                                             mip_filter_gyro_noise_response_t *out) {
    static const char *const keys[] = {"noise"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "noise", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"noise\"");
    }
    {
        mip_jr_push(jr, "noise");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->noise[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_accel_bias_model_t */

static int mip_filter_accel_bias_model_read(mip_reader_t *r, mip_filter_accel_bias_model_t *out) {
    size_t i;
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_beta = true;
        mip_rd_push(r, "beta");
        for (i = 0; i < 3; i++) {
            mip_rd_index(r, i);
            if (mip_rd_f32(r, &out->beta[i])) {
                return -1;
            }
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_noise = true;
        mip_rd_push(r, "noise");
        for (i = 0; i < 3; i++) {
            mip_rd_index(r, i);
            if (mip_rd_f32(r, &out->noise[i])) {
                return -1;
            }
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_accel_bias_model_write(mip_writer_t *w,
                                                      const mip_filter_accel_bias_model_t *in) {
    mip_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_beta) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mip_wr_f32(w, &in->beta[i])) != MIP_OK) {
                return st;
            }
        }
    }
    if (!in->has_noise) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mip_wr_f32(w, &in->noise[i])) != MIP_OK) {
                return st;
            }
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_accel_bias_model_encode(const mip_filter_accel_bias_model_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_accel_bias_model_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_accel_bias_model_decode(const uint8_t *data, size_t len,
                                                mip_filter_accel_bias_model_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_accel_bias_model_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_accel_bias_model_to_json(mip_jw_t *w, const mip_filter_accel_bias_model_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_beta) {
        mip_jw_key(w, &first, "beta");
        mip_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mip_jw_sep(w, i);
            mip_jw_f32(w, &in->beta[i]);
        }
        mip_jw_raw(w, "]", 1);
    }
    if (in->has_noise) {
        mip_jw_key(w, &first, "noise");
        mip_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mip_jw_sep(w, i);
            mip_jw_f32(w, &in->noise[i]);
        }
        mip_jw_raw(w, "]", 1);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_accel_bias_model_from_json(mip_jr_t *jr, size_t pos, mip_filter_accel_bias_model_t *out) {
    static const char *const keys[] = {"function", "beta", "noise"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "beta", &vp);
    out->has_beta = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"beta\" given after an absent one");
    } else {
        mip_jr_push(jr, "beta");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->beta[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "noise", &vp);
    out->has_noise = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"noise\" given after an absent one");
    } else {
        mip_jr_push(jr, "noise");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->noise[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_accel_bias_model_response_t */

static int mip_filter_accel_bias_model_response_read(mip_reader_t *r,
                                                     mip_filter_accel_bias_model_response_t *out) {
    size_t i;
    mip_rd_push(r, "beta");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->beta[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    mip_rd_push(r, "noise");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->noise[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t
mip_filter_accel_bias_model_response_write(mip_writer_t *w,
                                           const mip_filter_accel_bias_model_response_t *in) {
    mip_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->beta[i])) != MIP_OK) {
            return st;
        }
    }
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->noise[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_accel_bias_model_response_encode(const mip_filter_accel_bias_model_response_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_accel_bias_model_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 24 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_filter_accel_bias_model_response_load(const uint8_t *d,
                                                     mip_filter_accel_bias_model_response_t *out) {
    out->beta[0] = mip_ld_f32(d + 0);
    out->beta[1] = mip_ld_f32(d + 4);
    out->beta[2] = mip_ld_f32(d + 8);
    out->noise[0] = mip_ld_f32(d + 12);
    out->noise[1] = mip_ld_f32(d + 16);
    out->noise[2] = mip_ld_f32(d + 20);
    return 0;
}

/* The general reader: lengths other than 24, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_accel_bias_model_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_accel_bias_model_response_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_accel_bias_model_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_filter_accel_bias_model_response_decode(const uint8_t *data, size_t len,
                                                         mip_filter_accel_bias_model_response_t *out,
                                                         mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 24 && mip_filter_accel_bias_model_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_accel_bias_model_response_decode_read(data, len, out, err);
}

void mip_filter_accel_bias_model_response_to_json(mip_jw_t *w,
                                                  const mip_filter_accel_bias_model_response_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "beta");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->beta[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_key(w, &first, "noise");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->noise[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_accel_bias_model_response_from_json(mip_jr_t *jr, size_t pos,
                                                   mip_filter_accel_bias_model_response_t *out) {
    static const char *const keys[] = {"beta", "noise"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "beta", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"beta\"");
    }
    {
        mip_jr_push(jr, "beta");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->beta[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "noise", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"noise\"");
    }
    {
        mip_jr_push(jr, "noise");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->noise[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_gyro_bias_model_t */

static int mip_filter_gyro_bias_model_read(mip_reader_t *r, mip_filter_gyro_bias_model_t *out) {
    size_t i;
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_beta = true;
        mip_rd_push(r, "beta");
        for (i = 0; i < 3; i++) {
            mip_rd_index(r, i);
            if (mip_rd_f32(r, &out->beta[i])) {
                return -1;
            }
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_noise = true;
        mip_rd_push(r, "noise");
        for (i = 0; i < 3; i++) {
            mip_rd_index(r, i);
            if (mip_rd_f32(r, &out->noise[i])) {
                return -1;
            }
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_gyro_bias_model_write(mip_writer_t *w,
                                                     const mip_filter_gyro_bias_model_t *in) {
    mip_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_beta) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mip_wr_f32(w, &in->beta[i])) != MIP_OK) {
                return st;
            }
        }
    }
    if (!in->has_noise) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mip_wr_f32(w, &in->noise[i])) != MIP_OK) {
                return st;
            }
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_gyro_bias_model_encode(const mip_filter_gyro_bias_model_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_gyro_bias_model_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_gyro_bias_model_decode(const uint8_t *data, size_t len,
                                               mip_filter_gyro_bias_model_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_gyro_bias_model_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_gyro_bias_model_to_json(mip_jw_t *w, const mip_filter_gyro_bias_model_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_beta) {
        mip_jw_key(w, &first, "beta");
        mip_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mip_jw_sep(w, i);
            mip_jw_f32(w, &in->beta[i]);
        }
        mip_jw_raw(w, "]", 1);
    }
    if (in->has_noise) {
        mip_jw_key(w, &first, "noise");
        mip_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mip_jw_sep(w, i);
            mip_jw_f32(w, &in->noise[i]);
        }
        mip_jw_raw(w, "]", 1);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_gyro_bias_model_from_json(mip_jr_t *jr, size_t pos, mip_filter_gyro_bias_model_t *out) {
    static const char *const keys[] = {"function", "beta", "noise"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "beta", &vp);
    out->has_beta = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"beta\" given after an absent one");
    } else {
        mip_jr_push(jr, "beta");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->beta[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "noise", &vp);
    out->has_noise = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"noise\" given after an absent one");
    } else {
        mip_jr_push(jr, "noise");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->noise[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_gyro_bias_model_response_t */

static int mip_filter_gyro_bias_model_response_read(mip_reader_t *r,
                                                    mip_filter_gyro_bias_model_response_t *out) {
    size_t i;
    mip_rd_push(r, "beta");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->beta[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    mip_rd_push(r, "noise");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->noise[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t
mip_filter_gyro_bias_model_response_write(mip_writer_t *w, const mip_filter_gyro_bias_model_response_t *in) {
    mip_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->beta[i])) != MIP_OK) {
            return st;
        }
    }
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->noise[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_gyro_bias_model_response_encode(const mip_filter_gyro_bias_model_response_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_gyro_bias_model_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 24 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_filter_gyro_bias_model_response_load(const uint8_t *d,
                                                    mip_filter_gyro_bias_model_response_t *out) {
    out->beta[0] = mip_ld_f32(d + 0);
    out->beta[1] = mip_ld_f32(d + 4);
    out->beta[2] = mip_ld_f32(d + 8);
    out->noise[0] = mip_ld_f32(d + 12);
    out->noise[1] = mip_ld_f32(d + 16);
    out->noise[2] = mip_ld_f32(d + 20);
    return 0;
}

/* The general reader: lengths other than 24, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_gyro_bias_model_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_gyro_bias_model_response_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_gyro_bias_model_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_filter_gyro_bias_model_response_decode(const uint8_t *data, size_t len,
                                                        mip_filter_gyro_bias_model_response_t *out,
                                                        mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 24 && mip_filter_gyro_bias_model_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_gyro_bias_model_response_decode_read(data, len, out, err);
}

void mip_filter_gyro_bias_model_response_to_json(mip_jw_t *w,
                                                 const mip_filter_gyro_bias_model_response_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "beta");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->beta[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_key(w, &first, "noise");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->noise[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_gyro_bias_model_response_from_json(mip_jr_t *jr, size_t pos,
                                                  mip_filter_gyro_bias_model_response_t *out) {
    static const char *const keys[] = {"beta", "noise"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "beta", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"beta\"");
    }
    {
        mip_jr_push(jr, "beta");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->beta[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "noise", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"noise\"");
    }
    {
        mip_jr_push(jr, "noise");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->noise[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_zupt_control_t */

static int mip_filter_zupt_control_read(mip_reader_t *r, mip_filter_zupt_control_t *out) {
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_enable = true;
        mip_rd_push(r, "enable");
        if (mip_rd_u8(r, &out->enable)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_threshold = true;
        mip_rd_push(r, "threshold");
        if (mip_rd_f32(r, &out->threshold)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_zupt_control_write(mip_writer_t *w, const mip_filter_zupt_control_t *in) {
    mip_status_t st;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_enable) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u8(w, &in->enable)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_threshold) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_f32(w, &in->threshold)) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_zupt_control_encode(const mip_filter_zupt_control_t *value, uint8_t *buf, size_t cap,
                                            size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_zupt_control_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_zupt_control_decode(const uint8_t *data, size_t len, mip_filter_zupt_control_t *out,
                                            mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_zupt_control_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_zupt_control_to_json(mip_jw_t *w, const mip_filter_zupt_control_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_enable) {
        mip_jw_key(w, &first, "enable");
        mip_jw_u8(w, &in->enable);
    }
    if (in->has_threshold) {
        mip_jw_key(w, &first, "threshold");
        mip_jw_f32(w, &in->threshold);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_zupt_control_from_json(mip_jr_t *jr, size_t pos, mip_filter_zupt_control_t *out) {
    static const char *const keys[] = {"function", "enable", "threshold"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "enable", &vp);
    out->has_enable = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"enable\" given after an absent one");
    } else {
        mip_jr_push(jr, "enable");
        if (mip_jr_u8(jr, vp, &out->enable)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "threshold", &vp);
    out->has_threshold = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"threshold\" given after an absent one");
    } else {
        mip_jr_push(jr, "threshold");
        if (mip_jr_f32(jr, vp, &out->threshold)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_zupt_control_response_t */

static int mip_filter_zupt_control_response_read(mip_reader_t *r, mip_filter_zupt_control_response_t *out) {
    mip_rd_push(r, "enable");
    if (mip_rd_u8(r, &out->enable)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "threshold");
    if (mip_rd_f32(r, &out->threshold)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_zupt_control_response_write(mip_writer_t *w,
                                                           const mip_filter_zupt_control_response_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->enable)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->threshold)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_filter_zupt_control_response_encode(const mip_filter_zupt_control_response_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_zupt_control_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 5 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_filter_zupt_control_response_load(const uint8_t *d, mip_filter_zupt_control_response_t *out) {
    out->enable = mip_ld_u8(d + 0);
    out->threshold = mip_ld_f32(d + 1);
    return 0;
}

/* The general reader: lengths other than 5, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_zupt_control_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_zupt_control_response_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_zupt_control_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_filter_zupt_control_response_decode(const uint8_t *data, size_t len,
                                                     mip_filter_zupt_control_response_t *out,
                                                     mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 5 && mip_filter_zupt_control_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_zupt_control_response_decode_read(data, len, out, err);
}

void mip_filter_zupt_control_response_to_json(mip_jw_t *w, const mip_filter_zupt_control_response_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "enable");
    mip_jw_u8(w, &in->enable);
    mip_jw_key(w, &first, "threshold");
    mip_jw_f32(w, &in->threshold);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_zupt_control_response_from_json(mip_jr_t *jr, size_t pos,
                                               mip_filter_zupt_control_response_t *out) {
    static const char *const keys[] = {"enable", "threshold"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "enable", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"enable\"");
    }
    {
        mip_jr_push(jr, "enable");
        if (mip_jr_u8(jr, vp, &out->enable)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "threshold", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"threshold\"");
    }
    {
        mip_jr_push(jr, "threshold");
        if (mip_jr_f32(jr, vp, &out->threshold)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_external_heading_update_with_time_t */

static int
mip_filter_external_heading_update_with_time_read(mip_reader_t *r,
                                                  mip_filter_external_heading_update_with_time_t *out) {
    mip_rd_push(r, "gps_tow");
    if (mip_rd_f64(r, &out->gps_tow)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "gps_week");
    if (mip_rd_u16(r, &out->gps_week)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "heading");
    if (mip_rd_f32(r, &out->heading)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "heading_uncertainty");
    if (mip_rd_f32(r, &out->heading_uncertainty)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "type");
    if (mip_rd_u8(r, &out->type)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t
mip_filter_external_heading_update_with_time_write(mip_writer_t *w,
                                                   const mip_filter_external_heading_update_with_time_t *in) {
    mip_status_t st;
    if ((st = mip_wr_f64(w, &in->gps_tow)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->gps_week)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->heading)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->heading_uncertainty)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->type)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_filter_external_heading_update_with_time_encode(
    const mip_filter_external_heading_update_with_time_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_external_heading_update_with_time_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 19 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mip_filter_external_heading_update_with_time_load(const uint8_t *d,
                                                  mip_filter_external_heading_update_with_time_t *out) {
    out->gps_tow = mip_ld_f64(d + 0);
    out->gps_week = mip_ld_u16(d + 8);
    out->heading = mip_ld_f32(d + 10);
    out->heading_uncertainty = mip_ld_f32(d + 14);
    out->type = mip_ld_u8(d + 18);
    return 0;
}

/* The general reader: lengths other than 19, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_external_heading_update_with_time_decode_read(
    const uint8_t *data, size_t len, mip_filter_external_heading_update_with_time_t *out,
    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_external_heading_update_with_time_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t
mip_filter_external_heading_update_with_time_decode(const uint8_t *data, size_t len,
                                                    mip_filter_external_heading_update_with_time_t *out,
                                                    mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 19 && mip_filter_external_heading_update_with_time_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_external_heading_update_with_time_decode_read(data, len, out, err);
}

void mip_filter_external_heading_update_with_time_to_json(
    mip_jw_t *w, const mip_filter_external_heading_update_with_time_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "gps_tow");
    mip_jw_f64(w, &in->gps_tow);
    mip_jw_key(w, &first, "gps_week");
    mip_jw_u16(w, &in->gps_week);
    mip_jw_key(w, &first, "heading");
    mip_jw_f32(w, &in->heading);
    mip_jw_key(w, &first, "heading_uncertainty");
    mip_jw_f32(w, &in->heading_uncertainty);
    mip_jw_key(w, &first, "type");
    mip_jw_u8(w, &in->type);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_external_heading_update_with_time_from_json(
    mip_jr_t *jr, size_t pos, mip_filter_external_heading_update_with_time_t *out) {
    static const char *const keys[] = {"gps_tow", "gps_week", "heading", "heading_uncertainty", "type"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "gps_tow", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"gps_tow\"");
    }
    {
        mip_jr_push(jr, "gps_tow");
        if (mip_jr_f64(jr, vp, &out->gps_tow)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "gps_week", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"gps_week\"");
    }
    {
        mip_jr_push(jr, "gps_week");
        if (mip_jr_u16(jr, vp, &out->gps_week)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "heading", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"heading\"");
    }
    {
        mip_jr_push(jr, "heading");
        if (mip_jr_f32(jr, vp, &out->heading)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "heading_uncertainty", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"heading_uncertainty\"");
    }
    {
        mip_jr_push(jr, "heading_uncertainty");
        if (mip_jr_f32(jr, vp, &out->heading_uncertainty)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "type", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"type\"");
    }
    {
        mip_jr_push(jr, "type");
        if (mip_jr_u8(jr, vp, &out->type)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_zero_angular_rate_update_control_t */

static int
mip_filter_zero_angular_rate_update_control_read(mip_reader_t *r,
                                                 mip_filter_zero_angular_rate_update_control_t *out) {
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_enable = true;
        mip_rd_push(r, "enable");
        if (mip_rd_u8(r, &out->enable)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_threshold = true;
        mip_rd_push(r, "threshold");
        if (mip_rd_f32(r, &out->threshold)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t
mip_filter_zero_angular_rate_update_control_write(mip_writer_t *w,
                                                  const mip_filter_zero_angular_rate_update_control_t *in) {
    mip_status_t st;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_enable) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u8(w, &in->enable)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_threshold) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_f32(w, &in->threshold)) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t
mip_filter_zero_angular_rate_update_control_encode(const mip_filter_zero_angular_rate_update_control_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_zero_angular_rate_update_control_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t
mip_filter_zero_angular_rate_update_control_decode(const uint8_t *data, size_t len,
                                                   mip_filter_zero_angular_rate_update_control_t *out,
                                                   mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_zero_angular_rate_update_control_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_zero_angular_rate_update_control_to_json(
    mip_jw_t *w, const mip_filter_zero_angular_rate_update_control_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_enable) {
        mip_jw_key(w, &first, "enable");
        mip_jw_u8(w, &in->enable);
    }
    if (in->has_threshold) {
        mip_jw_key(w, &first, "threshold");
        mip_jw_f32(w, &in->threshold);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_zero_angular_rate_update_control_from_json(
    mip_jr_t *jr, size_t pos, mip_filter_zero_angular_rate_update_control_t *out) {
    static const char *const keys[] = {"function", "enable", "threshold"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "enable", &vp);
    out->has_enable = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"enable\" given after an absent one");
    } else {
        mip_jr_push(jr, "enable");
        if (mip_jr_u8(jr, vp, &out->enable)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "threshold", &vp);
    out->has_threshold = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"threshold\" given after an absent one");
    } else {
        mip_jr_push(jr, "threshold");
        if (mip_jr_f32(jr, vp, &out->threshold)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_zero_angular_rate_update_control_response_t */

static int mip_filter_zero_angular_rate_update_control_response_read(
    mip_reader_t *r, mip_filter_zero_angular_rate_update_control_response_t *out) {
    mip_rd_push(r, "enable");
    if (mip_rd_u8(r, &out->enable)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "threshold");
    if (mip_rd_f32(r, &out->threshold)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_zero_angular_rate_update_control_response_write(
    mip_writer_t *w, const mip_filter_zero_angular_rate_update_control_response_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->enable)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->threshold)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_filter_zero_angular_rate_update_control_response_encode(
    const mip_filter_zero_angular_rate_update_control_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_zero_angular_rate_update_control_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 5 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_filter_zero_angular_rate_update_control_response_load(
    const uint8_t *d, mip_filter_zero_angular_rate_update_control_response_t *out) {
    out->enable = mip_ld_u8(d + 0);
    out->threshold = mip_ld_f32(d + 1);
    return 0;
}

/* The general reader: lengths other than 5, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_zero_angular_rate_update_control_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_zero_angular_rate_update_control_response_t *out,
    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_zero_angular_rate_update_control_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_filter_zero_angular_rate_update_control_response_decode(
    const uint8_t *data, size_t len, mip_filter_zero_angular_rate_update_control_response_t *out,
    mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 5 && mip_filter_zero_angular_rate_update_control_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_zero_angular_rate_update_control_response_decode_read(data, len, out, err);
}

void mip_filter_zero_angular_rate_update_control_response_to_json(
    mip_jw_t *w, const mip_filter_zero_angular_rate_update_control_response_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "enable");
    mip_jw_u8(w, &in->enable);
    mip_jw_key(w, &first, "threshold");
    mip_jw_f32(w, &in->threshold);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_zero_angular_rate_update_control_response_from_json(
    mip_jr_t *jr, size_t pos, mip_filter_zero_angular_rate_update_control_response_t *out) {
    static const char *const keys[] = {"enable", "threshold"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "enable", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"enable\"");
    }
    {
        mip_jr_push(jr, "enable");
        if (mip_jr_u8(jr, vp, &out->enable)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "threshold", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"threshold\"");
    }
    {
        mip_jr_push(jr, "threshold");
        if (mip_jr_f32(jr, vp, &out->threshold)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_tare_orientation_t */

static int mip_filter_tare_orientation_read(mip_reader_t *r, mip_filter_tare_orientation_t *out) {
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_axes = true;
        mip_rd_push(r, "axes");
        if (mip_rd_u8(r, &out->axes)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_tare_orientation_write(mip_writer_t *w,
                                                      const mip_filter_tare_orientation_t *in) {
    mip_status_t st;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_axes) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u8(w, &in->axes)) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_tare_orientation_encode(const mip_filter_tare_orientation_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_tare_orientation_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_tare_orientation_decode(const uint8_t *data, size_t len,
                                                mip_filter_tare_orientation_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_tare_orientation_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_tare_orientation_to_json(mip_jw_t *w, const mip_filter_tare_orientation_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_axes) {
        mip_jw_key(w, &first, "axes");
        mip_jw_u8(w, &in->axes);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_tare_orientation_from_json(mip_jr_t *jr, size_t pos, mip_filter_tare_orientation_t *out) {
    static const char *const keys[] = {"function", "axes"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "axes", &vp);
    out->has_axes = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"axes\" given after an absent one");
    } else {
        mip_jr_push(jr, "axes");
        if (mip_jr_u8(jr, vp, &out->axes)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_commanded_zupt_t */

static int mip_filter_commanded_zupt_read(mip_reader_t *r, mip_filter_commanded_zupt_t *out) {
    (void)out;
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_commanded_zupt_write(mip_writer_t *w, const mip_filter_commanded_zupt_t *in) {
    (void)w;
    (void)in;
    return MIP_OK;
}

mip_status_t mip_filter_commanded_zupt_encode(const mip_filter_commanded_zupt_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_commanded_zupt_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_commanded_zupt_decode(const uint8_t *data, size_t len,
                                              mip_filter_commanded_zupt_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_commanded_zupt_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_commanded_zupt_to_json(mip_jw_t *w, const mip_filter_commanded_zupt_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mip_filter_commanded_zupt_from_json(mip_jr_t *jr, size_t pos, mip_filter_commanded_zupt_t *out) {
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mip_filter_commanded_zero_angular_rate_update_t */

static int
mip_filter_commanded_zero_angular_rate_update_read(mip_reader_t *r,
                                                   mip_filter_commanded_zero_angular_rate_update_t *out) {
    (void)out;
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_commanded_zero_angular_rate_update_write(
    mip_writer_t *w, const mip_filter_commanded_zero_angular_rate_update_t *in) {
    (void)w;
    (void)in;
    return MIP_OK;
}

mip_status_t mip_filter_commanded_zero_angular_rate_update_encode(
    const mip_filter_commanded_zero_angular_rate_update_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_commanded_zero_angular_rate_update_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t
mip_filter_commanded_zero_angular_rate_update_decode(const uint8_t *data, size_t len,
                                                     mip_filter_commanded_zero_angular_rate_update_t *out,
                                                     mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_commanded_zero_angular_rate_update_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_commanded_zero_angular_rate_update_to_json(
    mip_jw_t *w, const mip_filter_commanded_zero_angular_rate_update_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mip_filter_commanded_zero_angular_rate_update_from_json(
    mip_jr_t *jr, size_t pos, mip_filter_commanded_zero_angular_rate_update_t *out) {
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mip_filter_mag_capture_auto_calibration_t */

static int mip_filter_mag_capture_auto_calibration_read(mip_reader_t *r,
                                                        mip_filter_mag_capture_auto_calibration_t *out) {
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t
mip_filter_mag_capture_auto_calibration_write(mip_writer_t *w,
                                              const mip_filter_mag_capture_auto_calibration_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t
mip_filter_mag_capture_auto_calibration_encode(const mip_filter_mag_capture_auto_calibration_t *value,
                                               uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_mag_capture_auto_calibration_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_filter_mag_capture_auto_calibration_load(const uint8_t *d,
                                                        mip_filter_mag_capture_auto_calibration_t *out) {
    out->function = mip_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_mag_capture_auto_calibration_decode_read(
    const uint8_t *data, size_t len, mip_filter_mag_capture_auto_calibration_t *out,
    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_mag_capture_auto_calibration_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_filter_mag_capture_auto_calibration_decode(const uint8_t *data, size_t len,
                                                            mip_filter_mag_capture_auto_calibration_t *out,
                                                            mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mip_filter_mag_capture_auto_calibration_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_mag_capture_auto_calibration_decode_read(data, len, out, err);
}

void mip_filter_mag_capture_auto_calibration_to_json(mip_jw_t *w,
                                                     const mip_filter_mag_capture_auto_calibration_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_mag_capture_auto_calibration_from_json(mip_jr_t *jr, size_t pos,
                                                      mip_filter_mag_capture_auto_calibration_t *out) {
    static const char *const keys[] = {"function"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_gravity_noise_std_dev_t */

static int mip_filter_gravity_noise_std_dev_read(mip_reader_t *r, mip_filter_gravity_noise_std_dev_t *out) {
    size_t i;
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_noise = true;
        mip_rd_push(r, "noise");
        for (i = 0; i < 3; i++) {
            mip_rd_index(r, i);
            if (mip_rd_f32(r, &out->noise[i])) {
                return -1;
            }
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_gravity_noise_std_dev_write(mip_writer_t *w,
                                                           const mip_filter_gravity_noise_std_dev_t *in) {
    mip_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_noise) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mip_wr_f32(w, &in->noise[i])) != MIP_OK) {
                return st;
            }
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_gravity_noise_std_dev_encode(const mip_filter_gravity_noise_std_dev_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_gravity_noise_std_dev_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_gravity_noise_std_dev_decode(const uint8_t *data, size_t len,
                                                     mip_filter_gravity_noise_std_dev_t *out,
                                                     mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_gravity_noise_std_dev_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_gravity_noise_std_dev_to_json(mip_jw_t *w, const mip_filter_gravity_noise_std_dev_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_noise) {
        mip_jw_key(w, &first, "noise");
        mip_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mip_jw_sep(w, i);
            mip_jw_f32(w, &in->noise[i]);
        }
        mip_jw_raw(w, "]", 1);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_gravity_noise_std_dev_from_json(mip_jr_t *jr, size_t pos,
                                               mip_filter_gravity_noise_std_dev_t *out) {
    static const char *const keys[] = {"function", "noise"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "noise", &vp);
    out->has_noise = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"noise\" given after an absent one");
    } else {
        mip_jr_push(jr, "noise");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->noise[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_gravity_noise_std_dev_response_t */

static int mip_filter_gravity_noise_std_dev_response_read(mip_reader_t *r,
                                                          mip_filter_gravity_noise_std_dev_response_t *out) {
    size_t i;
    mip_rd_push(r, "noise");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->noise[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t
mip_filter_gravity_noise_std_dev_response_write(mip_writer_t *w,
                                                const mip_filter_gravity_noise_std_dev_response_t *in) {
    mip_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->noise[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t
mip_filter_gravity_noise_std_dev_response_encode(const mip_filter_gravity_noise_std_dev_response_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_gravity_noise_std_dev_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_filter_gravity_noise_std_dev_response_load(const uint8_t *d,
                                                          mip_filter_gravity_noise_std_dev_response_t *out) {
    out->noise[0] = mip_ld_f32(d + 0);
    out->noise[1] = mip_ld_f32(d + 4);
    out->noise[2] = mip_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_gravity_noise_std_dev_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_gravity_noise_std_dev_response_t *out,
    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_gravity_noise_std_dev_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t
mip_filter_gravity_noise_std_dev_response_decode(const uint8_t *data, size_t len,
                                                 mip_filter_gravity_noise_std_dev_response_t *out,
                                                 mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mip_filter_gravity_noise_std_dev_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_gravity_noise_std_dev_response_decode_read(data, len, out, err);
}

void mip_filter_gravity_noise_std_dev_response_to_json(
    mip_jw_t *w, const mip_filter_gravity_noise_std_dev_response_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "noise");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->noise[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_gravity_noise_std_dev_response_from_json(mip_jr_t *jr, size_t pos,
                                                        mip_filter_gravity_noise_std_dev_response_t *out) {
    static const char *const keys[] = {"noise"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "noise", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"noise\"");
    }
    {
        mip_jr_push(jr, "noise");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->noise[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_pressure_altitude_noise_std_dev_t */

static int
mip_filter_pressure_altitude_noise_std_dev_read(mip_reader_t *r,
                                                mip_filter_pressure_altitude_noise_std_dev_t *out) {
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_noise = true;
        mip_rd_push(r, "noise");
        if (mip_rd_f32(r, &out->noise)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t
mip_filter_pressure_altitude_noise_std_dev_write(mip_writer_t *w,
                                                 const mip_filter_pressure_altitude_noise_std_dev_t *in) {
    mip_status_t st;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_noise) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_f32(w, &in->noise)) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t
mip_filter_pressure_altitude_noise_std_dev_encode(const mip_filter_pressure_altitude_noise_std_dev_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_pressure_altitude_noise_std_dev_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t
mip_filter_pressure_altitude_noise_std_dev_decode(const uint8_t *data, size_t len,
                                                  mip_filter_pressure_altitude_noise_std_dev_t *out,
                                                  mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_pressure_altitude_noise_std_dev_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_pressure_altitude_noise_std_dev_to_json(
    mip_jw_t *w, const mip_filter_pressure_altitude_noise_std_dev_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_noise) {
        mip_jw_key(w, &first, "noise");
        mip_jw_f32(w, &in->noise);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_pressure_altitude_noise_std_dev_from_json(mip_jr_t *jr, size_t pos,
                                                         mip_filter_pressure_altitude_noise_std_dev_t *out) {
    static const char *const keys[] = {"function", "noise"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "noise", &vp);
    out->has_noise = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"noise\" given after an absent one");
    } else {
        mip_jr_push(jr, "noise");
        if (mip_jr_f32(jr, vp, &out->noise)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_pressure_altitude_noise_std_dev_response_t */

static int mip_filter_pressure_altitude_noise_std_dev_response_read(
    mip_reader_t *r, mip_filter_pressure_altitude_noise_std_dev_response_t *out) {
    mip_rd_push(r, "noise");
    if (mip_rd_f32(r, &out->noise)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_pressure_altitude_noise_std_dev_response_write(
    mip_writer_t *w, const mip_filter_pressure_altitude_noise_std_dev_response_t *in) {
    mip_status_t st;
    if ((st = mip_wr_f32(w, &in->noise)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_filter_pressure_altitude_noise_std_dev_response_encode(
    const mip_filter_pressure_altitude_noise_std_dev_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_pressure_altitude_noise_std_dev_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 4 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_filter_pressure_altitude_noise_std_dev_response_load(
    const uint8_t *d, mip_filter_pressure_altitude_noise_std_dev_response_t *out) {
    out->noise = mip_ld_f32(d + 0);
    return 0;
}

/* The general reader: lengths other than 4, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_pressure_altitude_noise_std_dev_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_pressure_altitude_noise_std_dev_response_t *out,
    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_pressure_altitude_noise_std_dev_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_filter_pressure_altitude_noise_std_dev_response_decode(
    const uint8_t *data, size_t len, mip_filter_pressure_altitude_noise_std_dev_response_t *out,
    mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 4 && mip_filter_pressure_altitude_noise_std_dev_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_pressure_altitude_noise_std_dev_response_decode_read(data, len, out, err);
}

void mip_filter_pressure_altitude_noise_std_dev_response_to_json(
    mip_jw_t *w, const mip_filter_pressure_altitude_noise_std_dev_response_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "noise");
    mip_jw_f32(w, &in->noise);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_pressure_altitude_noise_std_dev_response_from_json(
    mip_jr_t *jr, size_t pos, mip_filter_pressure_altitude_noise_std_dev_response_t *out) {
    static const char *const keys[] = {"noise"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "noise", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"noise\"");
    }
    {
        mip_jr_push(jr, "noise");
        if (mip_jr_f32(jr, vp, &out->noise)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_hard_iron_offset_noise_t */

static int mip_filter_hard_iron_offset_noise_read(mip_reader_t *r, mip_filter_hard_iron_offset_noise_t *out) {
    size_t i;
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_noise = true;
        mip_rd_push(r, "noise");
        for (i = 0; i < 3; i++) {
            mip_rd_index(r, i);
            if (mip_rd_f32(r, &out->noise[i])) {
                return -1;
            }
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_hard_iron_offset_noise_write(mip_writer_t *w,
                                                            const mip_filter_hard_iron_offset_noise_t *in) {
    mip_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_noise) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mip_wr_f32(w, &in->noise[i])) != MIP_OK) {
                return st;
            }
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_hard_iron_offset_noise_encode(const mip_filter_hard_iron_offset_noise_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_hard_iron_offset_noise_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_hard_iron_offset_noise_decode(const uint8_t *data, size_t len,
                                                      mip_filter_hard_iron_offset_noise_t *out,
                                                      mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_hard_iron_offset_noise_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_hard_iron_offset_noise_to_json(mip_jw_t *w, const mip_filter_hard_iron_offset_noise_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_noise) {
        mip_jw_key(w, &first, "noise");
        mip_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mip_jw_sep(w, i);
            mip_jw_f32(w, &in->noise[i]);
        }
        mip_jw_raw(w, "]", 1);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_hard_iron_offset_noise_from_json(mip_jr_t *jr, size_t pos,
                                                mip_filter_hard_iron_offset_noise_t *out) {
    static const char *const keys[] = {"function", "noise"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "noise", &vp);
    out->has_noise = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"noise\" given after an absent one");
    } else {
        mip_jr_push(jr, "noise");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->noise[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_hard_iron_offset_noise_response_t */

static int
mip_filter_hard_iron_offset_noise_response_read(mip_reader_t *r,
                                                mip_filter_hard_iron_offset_noise_response_t *out) {
    size_t i;
    mip_rd_push(r, "noise");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->noise[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t
mip_filter_hard_iron_offset_noise_response_write(mip_writer_t *w,
                                                 const mip_filter_hard_iron_offset_noise_response_t *in) {
    mip_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->noise[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t
mip_filter_hard_iron_offset_noise_response_encode(const mip_filter_hard_iron_offset_noise_response_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_hard_iron_offset_noise_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mip_filter_hard_iron_offset_noise_response_load(const uint8_t *d,
                                                mip_filter_hard_iron_offset_noise_response_t *out) {
    out->noise[0] = mip_ld_f32(d + 0);
    out->noise[1] = mip_ld_f32(d + 4);
    out->noise[2] = mip_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_hard_iron_offset_noise_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_hard_iron_offset_noise_response_t *out,
    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_hard_iron_offset_noise_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t
mip_filter_hard_iron_offset_noise_response_decode(const uint8_t *data, size_t len,
                                                  mip_filter_hard_iron_offset_noise_response_t *out,
                                                  mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mip_filter_hard_iron_offset_noise_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_hard_iron_offset_noise_response_decode_read(data, len, out, err);
}

void mip_filter_hard_iron_offset_noise_response_to_json(
    mip_jw_t *w, const mip_filter_hard_iron_offset_noise_response_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "noise");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->noise[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_hard_iron_offset_noise_response_from_json(mip_jr_t *jr, size_t pos,
                                                         mip_filter_hard_iron_offset_noise_response_t *out) {
    static const char *const keys[] = {"noise"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "noise", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"noise\"");
    }
    {
        mip_jr_push(jr, "noise");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->noise[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_soft_iron_matrix_noise_t */

static int mip_filter_soft_iron_matrix_noise_read(mip_reader_t *r, mip_filter_soft_iron_matrix_noise_t *out) {
    size_t i;
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_noise = true;
        mip_rd_push(r, "noise");
        for (i = 0; i < 9; i++) {
            mip_rd_index(r, i);
            if (mip_rd_f32(r, &out->noise[i])) {
                return -1;
            }
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_soft_iron_matrix_noise_write(mip_writer_t *w,
                                                            const mip_filter_soft_iron_matrix_noise_t *in) {
    mip_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_noise) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 9; i++) {
            if ((st = mip_wr_f32(w, &in->noise[i])) != MIP_OK) {
                return st;
            }
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_soft_iron_matrix_noise_encode(const mip_filter_soft_iron_matrix_noise_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_soft_iron_matrix_noise_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_soft_iron_matrix_noise_decode(const uint8_t *data, size_t len,
                                                      mip_filter_soft_iron_matrix_noise_t *out,
                                                      mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_soft_iron_matrix_noise_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_soft_iron_matrix_noise_to_json(mip_jw_t *w, const mip_filter_soft_iron_matrix_noise_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_noise) {
        mip_jw_key(w, &first, "noise");
        mip_jw_raw(w, "[", 1);
        for (i = 0; i < 9; i++) {
            mip_jw_sep(w, i);
            mip_jw_f32(w, &in->noise[i]);
        }
        mip_jw_raw(w, "]", 1);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_soft_iron_matrix_noise_from_json(mip_jr_t *jr, size_t pos,
                                                mip_filter_soft_iron_matrix_noise_t *out) {
    static const char *const keys[] = {"function", "noise"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "noise", &vp);
    out->has_noise = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"noise\" given after an absent one");
    } else {
        mip_jr_push(jr, "noise");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 9) {
                return mip_jr_fail(jr, "more than 9 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->noise[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 9) {
            return mip_jr_fail(jr, "expected 9 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_soft_iron_matrix_noise_response_t */

static int
mip_filter_soft_iron_matrix_noise_response_read(mip_reader_t *r,
                                                mip_filter_soft_iron_matrix_noise_response_t *out) {
    size_t i;
    mip_rd_push(r, "noise");
    for (i = 0; i < 9; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->noise[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t
mip_filter_soft_iron_matrix_noise_response_write(mip_writer_t *w,
                                                 const mip_filter_soft_iron_matrix_noise_response_t *in) {
    mip_status_t st;
    size_t i;
    for (i = 0; i < 9; i++) {
        if ((st = mip_wr_f32(w, &in->noise[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t
mip_filter_soft_iron_matrix_noise_response_encode(const mip_filter_soft_iron_matrix_noise_response_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_soft_iron_matrix_noise_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 36 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mip_filter_soft_iron_matrix_noise_response_load(const uint8_t *d,
                                                mip_filter_soft_iron_matrix_noise_response_t *out) {
    out->noise[0] = mip_ld_f32(d + 0);
    out->noise[1] = mip_ld_f32(d + 4);
    out->noise[2] = mip_ld_f32(d + 8);
    out->noise[3] = mip_ld_f32(d + 12);
    out->noise[4] = mip_ld_f32(d + 16);
    out->noise[5] = mip_ld_f32(d + 20);
    out->noise[6] = mip_ld_f32(d + 24);
    out->noise[7] = mip_ld_f32(d + 28);
    out->noise[8] = mip_ld_f32(d + 32);
    return 0;
}

/* The general reader: lengths other than 36, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_soft_iron_matrix_noise_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_soft_iron_matrix_noise_response_t *out,
    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_soft_iron_matrix_noise_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t
mip_filter_soft_iron_matrix_noise_response_decode(const uint8_t *data, size_t len,
                                                  mip_filter_soft_iron_matrix_noise_response_t *out,
                                                  mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 36 && mip_filter_soft_iron_matrix_noise_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_soft_iron_matrix_noise_response_decode_read(data, len, out, err);
}

void mip_filter_soft_iron_matrix_noise_response_to_json(
    mip_jw_t *w, const mip_filter_soft_iron_matrix_noise_response_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "noise");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 9; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->noise[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_soft_iron_matrix_noise_response_from_json(mip_jr_t *jr, size_t pos,
                                                         mip_filter_soft_iron_matrix_noise_response_t *out) {
    static const char *const keys[] = {"noise"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "noise", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"noise\"");
    }
    {
        mip_jr_push(jr, "noise");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 9) {
                return mip_jr_fail(jr, "more than 9 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->noise[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 9) {
            return mip_jr_fail(jr, "expected 9 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_mag_noise_std_dev_t */

static int mip_filter_mag_noise_std_dev_read(mip_reader_t *r, mip_filter_mag_noise_std_dev_t *out) {
    size_t i;
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_noise = true;
        mip_rd_push(r, "noise");
        for (i = 0; i < 3; i++) {
            mip_rd_index(r, i);
            if (mip_rd_f32(r, &out->noise[i])) {
                return -1;
            }
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_mag_noise_std_dev_write(mip_writer_t *w,
                                                       const mip_filter_mag_noise_std_dev_t *in) {
    mip_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_noise) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mip_wr_f32(w, &in->noise[i])) != MIP_OK) {
                return st;
            }
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_mag_noise_std_dev_encode(const mip_filter_mag_noise_std_dev_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_mag_noise_std_dev_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_mag_noise_std_dev_decode(const uint8_t *data, size_t len,
                                                 mip_filter_mag_noise_std_dev_t *out,
                                                 mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_mag_noise_std_dev_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_mag_noise_std_dev_to_json(mip_jw_t *w, const mip_filter_mag_noise_std_dev_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_noise) {
        mip_jw_key(w, &first, "noise");
        mip_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mip_jw_sep(w, i);
            mip_jw_f32(w, &in->noise[i]);
        }
        mip_jw_raw(w, "]", 1);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_mag_noise_std_dev_from_json(mip_jr_t *jr, size_t pos, mip_filter_mag_noise_std_dev_t *out) {
    static const char *const keys[] = {"function", "noise"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "noise", &vp);
    out->has_noise = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"noise\" given after an absent one");
    } else {
        mip_jr_push(jr, "noise");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->noise[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_mag_noise_std_dev_response_t */

static int mip_filter_mag_noise_std_dev_response_read(mip_reader_t *r,
                                                      mip_filter_mag_noise_std_dev_response_t *out) {
    size_t i;
    mip_rd_push(r, "noise");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->noise[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t
mip_filter_mag_noise_std_dev_response_write(mip_writer_t *w,
                                            const mip_filter_mag_noise_std_dev_response_t *in) {
    mip_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->noise[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t
mip_filter_mag_noise_std_dev_response_encode(const mip_filter_mag_noise_std_dev_response_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_mag_noise_std_dev_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_filter_mag_noise_std_dev_response_load(const uint8_t *d,
                                                      mip_filter_mag_noise_std_dev_response_t *out) {
    out->noise[0] = mip_ld_f32(d + 0);
    out->noise[1] = mip_ld_f32(d + 4);
    out->noise[2] = mip_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_mag_noise_std_dev_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_mag_noise_std_dev_response_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_mag_noise_std_dev_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_filter_mag_noise_std_dev_response_decode(const uint8_t *data, size_t len,
                                                          mip_filter_mag_noise_std_dev_response_t *out,
                                                          mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mip_filter_mag_noise_std_dev_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_mag_noise_std_dev_response_decode_read(data, len, out, err);
}

void mip_filter_mag_noise_std_dev_response_to_json(mip_jw_t *w,
                                                   const mip_filter_mag_noise_std_dev_response_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "noise");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->noise[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_mag_noise_std_dev_response_from_json(mip_jr_t *jr, size_t pos,
                                                    mip_filter_mag_noise_std_dev_response_t *out) {
    static const char *const keys[] = {"noise"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "noise", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"noise\"");
    }
    {
        mip_jr_push(jr, "noise");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->noise[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_declination_source_t */

static int mip_filter_declination_source_read(mip_reader_t *r, mip_filter_declination_source_t *out) {
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_source = true;
        mip_rd_push(r, "source");
        if (mip_rd_u8(r, &out->source)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_declination = true;
        mip_rd_push(r, "declination");
        if (mip_rd_f32(r, &out->declination)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_declination_source_write(mip_writer_t *w,
                                                        const mip_filter_declination_source_t *in) {
    mip_status_t st;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_source) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u8(w, &in->source)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_declination) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_f32(w, &in->declination)) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_declination_source_encode(const mip_filter_declination_source_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_declination_source_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_declination_source_decode(const uint8_t *data, size_t len,
                                                  mip_filter_declination_source_t *out,
                                                  mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_declination_source_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_declination_source_to_json(mip_jw_t *w, const mip_filter_declination_source_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_source) {
        mip_jw_key(w, &first, "source");
        mip_jw_u8(w, &in->source);
    }
    if (in->has_declination) {
        mip_jw_key(w, &first, "declination");
        mip_jw_f32(w, &in->declination);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_declination_source_from_json(mip_jr_t *jr, size_t pos, mip_filter_declination_source_t *out) {
    static const char *const keys[] = {"function", "source", "declination"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "source", &vp);
    out->has_source = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"source\" given after an absent one");
    } else {
        mip_jr_push(jr, "source");
        if (mip_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "declination", &vp);
    out->has_declination = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"declination\" given after an absent one");
    } else {
        mip_jr_push(jr, "declination");
        if (mip_jr_f32(jr, vp, &out->declination)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_declination_source_response_t */

static int mip_filter_declination_source_response_read(mip_reader_t *r,
                                                       mip_filter_declination_source_response_t *out) {
    mip_rd_push(r, "source");
    if (mip_rd_u8(r, &out->source)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "declination");
    if (mip_rd_f32(r, &out->declination)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t
mip_filter_declination_source_response_write(mip_writer_t *w,
                                             const mip_filter_declination_source_response_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->source)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->declination)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t
mip_filter_declination_source_response_encode(const mip_filter_declination_source_response_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_declination_source_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 5 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_filter_declination_source_response_load(const uint8_t *d,
                                                       mip_filter_declination_source_response_t *out) {
    out->source = mip_ld_u8(d + 0);
    out->declination = mip_ld_f32(d + 1);
    return 0;
}

/* The general reader: lengths other than 5, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_declination_source_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_declination_source_response_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_declination_source_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_filter_declination_source_response_decode(const uint8_t *data, size_t len,
                                                           mip_filter_declination_source_response_t *out,
                                                           mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 5 && mip_filter_declination_source_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_declination_source_response_decode_read(data, len, out, err);
}

void mip_filter_declination_source_response_to_json(mip_jw_t *w,
                                                    const mip_filter_declination_source_response_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "source");
    mip_jw_u8(w, &in->source);
    mip_jw_key(w, &first, "declination");
    mip_jw_f32(w, &in->declination);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_declination_source_response_from_json(mip_jr_t *jr, size_t pos,
                                                     mip_filter_declination_source_response_t *out) {
    static const char *const keys[] = {"source", "declination"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "source", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"source\"");
    }
    {
        mip_jr_push(jr, "source");
        if (mip_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "declination", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"declination\"");
    }
    {
        mip_jr_push(jr, "declination");
        if (mip_jr_f32(jr, vp, &out->declination)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_gravity_magnitude_adaptive_measurement_t */

static int mip_filter_gravity_magnitude_adaptive_measurement_read(
    mip_reader_t *r, mip_filter_gravity_magnitude_adaptive_measurement_t *out) {
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_mode = true;
        mip_rd_push(r, "mode");
        if (mip_rd_u8(r, &out->mode)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_frequency = true;
        mip_rd_push(r, "frequency");
        if (mip_rd_f32(r, &out->frequency)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_low_limit = true;
        mip_rd_push(r, "low_limit");
        if (mip_rd_f32(r, &out->low_limit)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_high_limit = true;
        mip_rd_push(r, "high_limit");
        if (mip_rd_f32(r, &out->high_limit)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_low_limit_uncertainty = true;
        mip_rd_push(r, "low_limit_uncertainty");
        if (mip_rd_f32(r, &out->low_limit_uncertainty)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_high_limit_uncertainty = true;
        mip_rd_push(r, "high_limit_uncertainty");
        if (mip_rd_f32(r, &out->high_limit_uncertainty)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_minimum_uncertainty = true;
        mip_rd_push(r, "minimum_uncertainty");
        if (mip_rd_f32(r, &out->minimum_uncertainty)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_gravity_magnitude_adaptive_measurement_write(
    mip_writer_t *w, const mip_filter_gravity_magnitude_adaptive_measurement_t *in) {
    mip_status_t st;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_mode) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u8(w, &in->mode)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_frequency) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_f32(w, &in->frequency)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_low_limit) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_f32(w, &in->low_limit)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_high_limit) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_f32(w, &in->high_limit)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_low_limit_uncertainty) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_f32(w, &in->low_limit_uncertainty)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_high_limit_uncertainty) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_f32(w, &in->high_limit_uncertainty)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_minimum_uncertainty) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_f32(w, &in->minimum_uncertainty)) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_gravity_magnitude_adaptive_measurement_encode(
    const mip_filter_gravity_magnitude_adaptive_measurement_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_gravity_magnitude_adaptive_measurement_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_gravity_magnitude_adaptive_measurement_decode(
    const uint8_t *data, size_t len, mip_filter_gravity_magnitude_adaptive_measurement_t *out,
    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_gravity_magnitude_adaptive_measurement_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_gravity_magnitude_adaptive_measurement_to_json(
    mip_jw_t *w, const mip_filter_gravity_magnitude_adaptive_measurement_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_mode) {
        mip_jw_key(w, &first, "mode");
        mip_jw_u8(w, &in->mode);
    }
    if (in->has_frequency) {
        mip_jw_key(w, &first, "frequency");
        mip_jw_f32(w, &in->frequency);
    }
    if (in->has_low_limit) {
        mip_jw_key(w, &first, "low_limit");
        mip_jw_f32(w, &in->low_limit);
    }
    if (in->has_high_limit) {
        mip_jw_key(w, &first, "high_limit");
        mip_jw_f32(w, &in->high_limit);
    }
    if (in->has_low_limit_uncertainty) {
        mip_jw_key(w, &first, "low_limit_uncertainty");
        mip_jw_f32(w, &in->low_limit_uncertainty);
    }
    if (in->has_high_limit_uncertainty) {
        mip_jw_key(w, &first, "high_limit_uncertainty");
        mip_jw_f32(w, &in->high_limit_uncertainty);
    }
    if (in->has_minimum_uncertainty) {
        mip_jw_key(w, &first, "minimum_uncertainty");
        mip_jw_f32(w, &in->minimum_uncertainty);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_gravity_magnitude_adaptive_measurement_from_json(
    mip_jr_t *jr, size_t pos, mip_filter_gravity_magnitude_adaptive_measurement_t *out) {
    static const char *const keys[] = {"function",
                                       "mode",
                                       "frequency",
                                       "low_limit",
                                       "high_limit",
                                       "low_limit_uncertainty",
                                       "high_limit_uncertainty",
                                       "minimum_uncertainty"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 8)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "mode", &vp);
    out->has_mode = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"mode\" given after an absent one");
    } else {
        mip_jr_push(jr, "mode");
        if (mip_jr_u8(jr, vp, &out->mode)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "frequency", &vp);
    out->has_frequency = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"frequency\" given after an absent one");
    } else {
        mip_jr_push(jr, "frequency");
        if (mip_jr_f32(jr, vp, &out->frequency)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "low_limit", &vp);
    out->has_low_limit = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"low_limit\" given after an absent one");
    } else {
        mip_jr_push(jr, "low_limit");
        if (mip_jr_f32(jr, vp, &out->low_limit)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "high_limit", &vp);
    out->has_high_limit = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"high_limit\" given after an absent one");
    } else {
        mip_jr_push(jr, "high_limit");
        if (mip_jr_f32(jr, vp, &out->high_limit)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "low_limit_uncertainty", &vp);
    out->has_low_limit_uncertainty = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"low_limit_uncertainty\" given after an absent one");
    } else {
        mip_jr_push(jr, "low_limit_uncertainty");
        if (mip_jr_f32(jr, vp, &out->low_limit_uncertainty)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "high_limit_uncertainty", &vp);
    out->has_high_limit_uncertainty = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"high_limit_uncertainty\" given after an absent one");
    } else {
        mip_jr_push(jr, "high_limit_uncertainty");
        if (mip_jr_f32(jr, vp, &out->high_limit_uncertainty)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "minimum_uncertainty", &vp);
    out->has_minimum_uncertainty = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"minimum_uncertainty\" given after an absent one");
    } else {
        mip_jr_push(jr, "minimum_uncertainty");
        if (mip_jr_f32(jr, vp, &out->minimum_uncertainty)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_gravity_magnitude_adaptive_measurement_response_t */

static int mip_filter_gravity_magnitude_adaptive_measurement_response_read(
    mip_reader_t *r, mip_filter_gravity_magnitude_adaptive_measurement_response_t *out) {
    mip_rd_push(r, "mode");
    if (mip_rd_u8(r, &out->mode)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "frequency");
    if (mip_rd_f32(r, &out->frequency)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "low_limit");
    if (mip_rd_f32(r, &out->low_limit)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "high_limit");
    if (mip_rd_f32(r, &out->high_limit)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "low_limit_uncertainty");
    if (mip_rd_f32(r, &out->low_limit_uncertainty)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "high_limit_uncertainty");
    if (mip_rd_f32(r, &out->high_limit_uncertainty)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "minimum_uncertainty");
    if (mip_rd_f32(r, &out->minimum_uncertainty)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_gravity_magnitude_adaptive_measurement_response_write(
    mip_writer_t *w, const mip_filter_gravity_magnitude_adaptive_measurement_response_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->mode)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->frequency)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->low_limit)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->high_limit)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->low_limit_uncertainty)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->high_limit_uncertainty)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->minimum_uncertainty)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_filter_gravity_magnitude_adaptive_measurement_response_encode(
    const mip_filter_gravity_magnitude_adaptive_measurement_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_gravity_magnitude_adaptive_measurement_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 25 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_filter_gravity_magnitude_adaptive_measurement_response_load(
    const uint8_t *d, mip_filter_gravity_magnitude_adaptive_measurement_response_t *out) {
    out->mode = mip_ld_u8(d + 0);
    out->frequency = mip_ld_f32(d + 1);
    out->low_limit = mip_ld_f32(d + 5);
    out->high_limit = mip_ld_f32(d + 9);
    out->low_limit_uncertainty = mip_ld_f32(d + 13);
    out->high_limit_uncertainty = mip_ld_f32(d + 17);
    out->minimum_uncertainty = mip_ld_f32(d + 21);
    return 0;
}

/* The general reader: lengths other than 25, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_gravity_magnitude_adaptive_measurement_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_gravity_magnitude_adaptive_measurement_response_t *out,
    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_gravity_magnitude_adaptive_measurement_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_filter_gravity_magnitude_adaptive_measurement_response_decode(
    const uint8_t *data, size_t len, mip_filter_gravity_magnitude_adaptive_measurement_response_t *out,
    mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 25 && mip_filter_gravity_magnitude_adaptive_measurement_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_gravity_magnitude_adaptive_measurement_response_decode_read(data, len, out, err);
}

void mip_filter_gravity_magnitude_adaptive_measurement_response_to_json(
    mip_jw_t *w, const mip_filter_gravity_magnitude_adaptive_measurement_response_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "mode");
    mip_jw_u8(w, &in->mode);
    mip_jw_key(w, &first, "frequency");
    mip_jw_f32(w, &in->frequency);
    mip_jw_key(w, &first, "low_limit");
    mip_jw_f32(w, &in->low_limit);
    mip_jw_key(w, &first, "high_limit");
    mip_jw_f32(w, &in->high_limit);
    mip_jw_key(w, &first, "low_limit_uncertainty");
    mip_jw_f32(w, &in->low_limit_uncertainty);
    mip_jw_key(w, &first, "high_limit_uncertainty");
    mip_jw_f32(w, &in->high_limit_uncertainty);
    mip_jw_key(w, &first, "minimum_uncertainty");
    mip_jw_f32(w, &in->minimum_uncertainty);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_gravity_magnitude_adaptive_measurement_response_from_json(
    mip_jr_t *jr, size_t pos, mip_filter_gravity_magnitude_adaptive_measurement_response_t *out) {
    static const char *const keys[] = {"mode",
                                       "frequency",
                                       "low_limit",
                                       "high_limit",
                                       "low_limit_uncertainty",
                                       "high_limit_uncertainty",
                                       "minimum_uncertainty"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 7)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "mode", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"mode\"");
    }
    {
        mip_jr_push(jr, "mode");
        if (mip_jr_u8(jr, vp, &out->mode)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "frequency", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"frequency\"");
    }
    {
        mip_jr_push(jr, "frequency");
        if (mip_jr_f32(jr, vp, &out->frequency)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "low_limit", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"low_limit\"");
    }
    {
        mip_jr_push(jr, "low_limit");
        if (mip_jr_f32(jr, vp, &out->low_limit)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "high_limit", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"high_limit\"");
    }
    {
        mip_jr_push(jr, "high_limit");
        if (mip_jr_f32(jr, vp, &out->high_limit)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "low_limit_uncertainty", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"low_limit_uncertainty\"");
    }
    {
        mip_jr_push(jr, "low_limit_uncertainty");
        if (mip_jr_f32(jr, vp, &out->low_limit_uncertainty)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "high_limit_uncertainty", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"high_limit_uncertainty\"");
    }
    {
        mip_jr_push(jr, "high_limit_uncertainty");
        if (mip_jr_f32(jr, vp, &out->high_limit_uncertainty)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "minimum_uncertainty", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"minimum_uncertainty\"");
    }
    {
        mip_jr_push(jr, "minimum_uncertainty");
        if (mip_jr_f32(jr, vp, &out->minimum_uncertainty)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_mag_magnitude_adaptive_measurement_t */

static int
mip_filter_mag_magnitude_adaptive_measurement_read(mip_reader_t *r,
                                                   mip_filter_mag_magnitude_adaptive_measurement_t *out) {
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_mode = true;
        mip_rd_push(r, "mode");
        if (mip_rd_u8(r, &out->mode)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_frequency = true;
        mip_rd_push(r, "frequency");
        if (mip_rd_f32(r, &out->frequency)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_low_limit = true;
        mip_rd_push(r, "low_limit");
        if (mip_rd_f32(r, &out->low_limit)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_high_limit = true;
        mip_rd_push(r, "high_limit");
        if (mip_rd_f32(r, &out->high_limit)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_low_limit_uncertainty = true;
        mip_rd_push(r, "low_limit_uncertainty");
        if (mip_rd_f32(r, &out->low_limit_uncertainty)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_high_limit_uncertainty = true;
        mip_rd_push(r, "high_limit_uncertainty");
        if (mip_rd_f32(r, &out->high_limit_uncertainty)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_minimum_uncertainty = true;
        mip_rd_push(r, "minimum_uncertainty");
        if (mip_rd_f32(r, &out->minimum_uncertainty)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_mag_magnitude_adaptive_measurement_write(
    mip_writer_t *w, const mip_filter_mag_magnitude_adaptive_measurement_t *in) {
    mip_status_t st;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_mode) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u8(w, &in->mode)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_frequency) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_f32(w, &in->frequency)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_low_limit) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_f32(w, &in->low_limit)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_high_limit) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_f32(w, &in->high_limit)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_low_limit_uncertainty) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_f32(w, &in->low_limit_uncertainty)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_high_limit_uncertainty) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_f32(w, &in->high_limit_uncertainty)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_minimum_uncertainty) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_f32(w, &in->minimum_uncertainty)) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_mag_magnitude_adaptive_measurement_encode(
    const mip_filter_mag_magnitude_adaptive_measurement_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_mag_magnitude_adaptive_measurement_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t
mip_filter_mag_magnitude_adaptive_measurement_decode(const uint8_t *data, size_t len,
                                                     mip_filter_mag_magnitude_adaptive_measurement_t *out,
                                                     mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_mag_magnitude_adaptive_measurement_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_mag_magnitude_adaptive_measurement_to_json(
    mip_jw_t *w, const mip_filter_mag_magnitude_adaptive_measurement_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_mode) {
        mip_jw_key(w, &first, "mode");
        mip_jw_u8(w, &in->mode);
    }
    if (in->has_frequency) {
        mip_jw_key(w, &first, "frequency");
        mip_jw_f32(w, &in->frequency);
    }
    if (in->has_low_limit) {
        mip_jw_key(w, &first, "low_limit");
        mip_jw_f32(w, &in->low_limit);
    }
    if (in->has_high_limit) {
        mip_jw_key(w, &first, "high_limit");
        mip_jw_f32(w, &in->high_limit);
    }
    if (in->has_low_limit_uncertainty) {
        mip_jw_key(w, &first, "low_limit_uncertainty");
        mip_jw_f32(w, &in->low_limit_uncertainty);
    }
    if (in->has_high_limit_uncertainty) {
        mip_jw_key(w, &first, "high_limit_uncertainty");
        mip_jw_f32(w, &in->high_limit_uncertainty);
    }
    if (in->has_minimum_uncertainty) {
        mip_jw_key(w, &first, "minimum_uncertainty");
        mip_jw_f32(w, &in->minimum_uncertainty);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_mag_magnitude_adaptive_measurement_from_json(
    mip_jr_t *jr, size_t pos, mip_filter_mag_magnitude_adaptive_measurement_t *out) {
    static const char *const keys[] = {"function",
                                       "mode",
                                       "frequency",
                                       "low_limit",
                                       "high_limit",
                                       "low_limit_uncertainty",
                                       "high_limit_uncertainty",
                                       "minimum_uncertainty"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 8)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "mode", &vp);
    out->has_mode = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"mode\" given after an absent one");
    } else {
        mip_jr_push(jr, "mode");
        if (mip_jr_u8(jr, vp, &out->mode)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "frequency", &vp);
    out->has_frequency = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"frequency\" given after an absent one");
    } else {
        mip_jr_push(jr, "frequency");
        if (mip_jr_f32(jr, vp, &out->frequency)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "low_limit", &vp);
    out->has_low_limit = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"low_limit\" given after an absent one");
    } else {
        mip_jr_push(jr, "low_limit");
        if (mip_jr_f32(jr, vp, &out->low_limit)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "high_limit", &vp);
    out->has_high_limit = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"high_limit\" given after an absent one");
    } else {
        mip_jr_push(jr, "high_limit");
        if (mip_jr_f32(jr, vp, &out->high_limit)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "low_limit_uncertainty", &vp);
    out->has_low_limit_uncertainty = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"low_limit_uncertainty\" given after an absent one");
    } else {
        mip_jr_push(jr, "low_limit_uncertainty");
        if (mip_jr_f32(jr, vp, &out->low_limit_uncertainty)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "high_limit_uncertainty", &vp);
    out->has_high_limit_uncertainty = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"high_limit_uncertainty\" given after an absent one");
    } else {
        mip_jr_push(jr, "high_limit_uncertainty");
        if (mip_jr_f32(jr, vp, &out->high_limit_uncertainty)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "minimum_uncertainty", &vp);
    out->has_minimum_uncertainty = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"minimum_uncertainty\" given after an absent one");
    } else {
        mip_jr_push(jr, "minimum_uncertainty");
        if (mip_jr_f32(jr, vp, &out->minimum_uncertainty)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_mag_magnitude_adaptive_measurement_response_t */

static int mip_filter_mag_magnitude_adaptive_measurement_response_read(
    mip_reader_t *r, mip_filter_mag_magnitude_adaptive_measurement_response_t *out) {
    mip_rd_push(r, "mode");
    if (mip_rd_u8(r, &out->mode)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "frequency");
    if (mip_rd_f32(r, &out->frequency)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "low_limit");
    if (mip_rd_f32(r, &out->low_limit)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "high_limit");
    if (mip_rd_f32(r, &out->high_limit)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "low_limit_uncertainty");
    if (mip_rd_f32(r, &out->low_limit_uncertainty)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "high_limit_uncertainty");
    if (mip_rd_f32(r, &out->high_limit_uncertainty)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "minimum_uncertainty");
    if (mip_rd_f32(r, &out->minimum_uncertainty)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_mag_magnitude_adaptive_measurement_response_write(
    mip_writer_t *w, const mip_filter_mag_magnitude_adaptive_measurement_response_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->mode)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->frequency)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->low_limit)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->high_limit)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->low_limit_uncertainty)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->high_limit_uncertainty)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->minimum_uncertainty)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_filter_mag_magnitude_adaptive_measurement_response_encode(
    const mip_filter_mag_magnitude_adaptive_measurement_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_mag_magnitude_adaptive_measurement_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 25 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_filter_mag_magnitude_adaptive_measurement_response_load(
    const uint8_t *d, mip_filter_mag_magnitude_adaptive_measurement_response_t *out) {
    out->mode = mip_ld_u8(d + 0);
    out->frequency = mip_ld_f32(d + 1);
    out->low_limit = mip_ld_f32(d + 5);
    out->high_limit = mip_ld_f32(d + 9);
    out->low_limit_uncertainty = mip_ld_f32(d + 13);
    out->high_limit_uncertainty = mip_ld_f32(d + 17);
    out->minimum_uncertainty = mip_ld_f32(d + 21);
    return 0;
}

/* The general reader: lengths other than 25, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_mag_magnitude_adaptive_measurement_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_mag_magnitude_adaptive_measurement_response_t *out,
    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_mag_magnitude_adaptive_measurement_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_filter_mag_magnitude_adaptive_measurement_response_decode(
    const uint8_t *data, size_t len, mip_filter_mag_magnitude_adaptive_measurement_response_t *out,
    mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 25 && mip_filter_mag_magnitude_adaptive_measurement_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_mag_magnitude_adaptive_measurement_response_decode_read(data, len, out, err);
}

void mip_filter_mag_magnitude_adaptive_measurement_response_to_json(
    mip_jw_t *w, const mip_filter_mag_magnitude_adaptive_measurement_response_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "mode");
    mip_jw_u8(w, &in->mode);
    mip_jw_key(w, &first, "frequency");
    mip_jw_f32(w, &in->frequency);
    mip_jw_key(w, &first, "low_limit");
    mip_jw_f32(w, &in->low_limit);
    mip_jw_key(w, &first, "high_limit");
    mip_jw_f32(w, &in->high_limit);
    mip_jw_key(w, &first, "low_limit_uncertainty");
    mip_jw_f32(w, &in->low_limit_uncertainty);
    mip_jw_key(w, &first, "high_limit_uncertainty");
    mip_jw_f32(w, &in->high_limit_uncertainty);
    mip_jw_key(w, &first, "minimum_uncertainty");
    mip_jw_f32(w, &in->minimum_uncertainty);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_mag_magnitude_adaptive_measurement_response_from_json(
    mip_jr_t *jr, size_t pos, mip_filter_mag_magnitude_adaptive_measurement_response_t *out) {
    static const char *const keys[] = {"mode",
                                       "frequency",
                                       "low_limit",
                                       "high_limit",
                                       "low_limit_uncertainty",
                                       "high_limit_uncertainty",
                                       "minimum_uncertainty"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 7)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "mode", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"mode\"");
    }
    {
        mip_jr_push(jr, "mode");
        if (mip_jr_u8(jr, vp, &out->mode)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "frequency", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"frequency\"");
    }
    {
        mip_jr_push(jr, "frequency");
        if (mip_jr_f32(jr, vp, &out->frequency)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "low_limit", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"low_limit\"");
    }
    {
        mip_jr_push(jr, "low_limit");
        if (mip_jr_f32(jr, vp, &out->low_limit)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "high_limit", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"high_limit\"");
    }
    {
        mip_jr_push(jr, "high_limit");
        if (mip_jr_f32(jr, vp, &out->high_limit)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "low_limit_uncertainty", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"low_limit_uncertainty\"");
    }
    {
        mip_jr_push(jr, "low_limit_uncertainty");
        if (mip_jr_f32(jr, vp, &out->low_limit_uncertainty)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "high_limit_uncertainty", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"high_limit_uncertainty\"");
    }
    {
        mip_jr_push(jr, "high_limit_uncertainty");
        if (mip_jr_f32(jr, vp, &out->high_limit_uncertainty)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "minimum_uncertainty", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"minimum_uncertainty\"");
    }
    {
        mip_jr_push(jr, "minimum_uncertainty");
        if (mip_jr_f32(jr, vp, &out->minimum_uncertainty)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_mag_dip_angle_adaptive_measurement_t */

static int
mip_filter_mag_dip_angle_adaptive_measurement_read(mip_reader_t *r,
                                                   mip_filter_mag_dip_angle_adaptive_measurement_t *out) {
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_mode = true;
        mip_rd_push(r, "mode");
        if (mip_rd_u8(r, &out->mode)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_frequency = true;
        mip_rd_push(r, "frequency");
        if (mip_rd_f32(r, &out->frequency)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_high_limit = true;
        mip_rd_push(r, "high_limit");
        if (mip_rd_f32(r, &out->high_limit)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_high_limit_uncertainty = true;
        mip_rd_push(r, "high_limit_uncertainty");
        if (mip_rd_f32(r, &out->high_limit_uncertainty)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_minimum_uncertainty = true;
        mip_rd_push(r, "minimum_uncertainty");
        if (mip_rd_f32(r, &out->minimum_uncertainty)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_mag_dip_angle_adaptive_measurement_write(
    mip_writer_t *w, const mip_filter_mag_dip_angle_adaptive_measurement_t *in) {
    mip_status_t st;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_mode) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u8(w, &in->mode)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_frequency) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_f32(w, &in->frequency)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_high_limit) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_f32(w, &in->high_limit)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_high_limit_uncertainty) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_f32(w, &in->high_limit_uncertainty)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_minimum_uncertainty) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_f32(w, &in->minimum_uncertainty)) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_mag_dip_angle_adaptive_measurement_encode(
    const mip_filter_mag_dip_angle_adaptive_measurement_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_mag_dip_angle_adaptive_measurement_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t
mip_filter_mag_dip_angle_adaptive_measurement_decode(const uint8_t *data, size_t len,
                                                     mip_filter_mag_dip_angle_adaptive_measurement_t *out,
                                                     mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_mag_dip_angle_adaptive_measurement_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_mag_dip_angle_adaptive_measurement_to_json(
    mip_jw_t *w, const mip_filter_mag_dip_angle_adaptive_measurement_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_mode) {
        mip_jw_key(w, &first, "mode");
        mip_jw_u8(w, &in->mode);
    }
    if (in->has_frequency) {
        mip_jw_key(w, &first, "frequency");
        mip_jw_f32(w, &in->frequency);
    }
    if (in->has_high_limit) {
        mip_jw_key(w, &first, "high_limit");
        mip_jw_f32(w, &in->high_limit);
    }
    if (in->has_high_limit_uncertainty) {
        mip_jw_key(w, &first, "high_limit_uncertainty");
        mip_jw_f32(w, &in->high_limit_uncertainty);
    }
    if (in->has_minimum_uncertainty) {
        mip_jw_key(w, &first, "minimum_uncertainty");
        mip_jw_f32(w, &in->minimum_uncertainty);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_mag_dip_angle_adaptive_measurement_from_json(
    mip_jr_t *jr, size_t pos, mip_filter_mag_dip_angle_adaptive_measurement_t *out) {
    static const char *const keys[] = {
        "function", "mode", "frequency", "high_limit", "high_limit_uncertainty", "minimum_uncertainty"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 6)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "mode", &vp);
    out->has_mode = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"mode\" given after an absent one");
    } else {
        mip_jr_push(jr, "mode");
        if (mip_jr_u8(jr, vp, &out->mode)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "frequency", &vp);
    out->has_frequency = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"frequency\" given after an absent one");
    } else {
        mip_jr_push(jr, "frequency");
        if (mip_jr_f32(jr, vp, &out->frequency)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "high_limit", &vp);
    out->has_high_limit = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"high_limit\" given after an absent one");
    } else {
        mip_jr_push(jr, "high_limit");
        if (mip_jr_f32(jr, vp, &out->high_limit)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "high_limit_uncertainty", &vp);
    out->has_high_limit_uncertainty = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"high_limit_uncertainty\" given after an absent one");
    } else {
        mip_jr_push(jr, "high_limit_uncertainty");
        if (mip_jr_f32(jr, vp, &out->high_limit_uncertainty)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "minimum_uncertainty", &vp);
    out->has_minimum_uncertainty = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"minimum_uncertainty\" given after an absent one");
    } else {
        mip_jr_push(jr, "minimum_uncertainty");
        if (mip_jr_f32(jr, vp, &out->minimum_uncertainty)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_mag_dip_angle_adaptive_measurement_response_t */

static int mip_filter_mag_dip_angle_adaptive_measurement_response_read(
    mip_reader_t *r, mip_filter_mag_dip_angle_adaptive_measurement_response_t *out) {
    mip_rd_push(r, "mode");
    if (mip_rd_u8(r, &out->mode)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "frequency");
    if (mip_rd_f32(r, &out->frequency)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "high_limit");
    if (mip_rd_f32(r, &out->high_limit)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "high_limit_uncertainty");
    if (mip_rd_f32(r, &out->high_limit_uncertainty)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "minimum_uncertainty");
    if (mip_rd_f32(r, &out->minimum_uncertainty)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_mag_dip_angle_adaptive_measurement_response_write(
    mip_writer_t *w, const mip_filter_mag_dip_angle_adaptive_measurement_response_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->mode)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->frequency)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->high_limit)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->high_limit_uncertainty)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->minimum_uncertainty)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_filter_mag_dip_angle_adaptive_measurement_response_encode(
    const mip_filter_mag_dip_angle_adaptive_measurement_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_mag_dip_angle_adaptive_measurement_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 17 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_filter_mag_dip_angle_adaptive_measurement_response_load(
    const uint8_t *d, mip_filter_mag_dip_angle_adaptive_measurement_response_t *out) {
    out->mode = mip_ld_u8(d + 0);
    out->frequency = mip_ld_f32(d + 1);
    out->high_limit = mip_ld_f32(d + 5);
    out->high_limit_uncertainty = mip_ld_f32(d + 9);
    out->minimum_uncertainty = mip_ld_f32(d + 13);
    return 0;
}

/* The general reader: lengths other than 17, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_mag_dip_angle_adaptive_measurement_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_mag_dip_angle_adaptive_measurement_response_t *out,
    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_mag_dip_angle_adaptive_measurement_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_filter_mag_dip_angle_adaptive_measurement_response_decode(
    const uint8_t *data, size_t len, mip_filter_mag_dip_angle_adaptive_measurement_response_t *out,
    mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 17 && mip_filter_mag_dip_angle_adaptive_measurement_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_mag_dip_angle_adaptive_measurement_response_decode_read(data, len, out, err);
}

void mip_filter_mag_dip_angle_adaptive_measurement_response_to_json(
    mip_jw_t *w, const mip_filter_mag_dip_angle_adaptive_measurement_response_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "mode");
    mip_jw_u8(w, &in->mode);
    mip_jw_key(w, &first, "frequency");
    mip_jw_f32(w, &in->frequency);
    mip_jw_key(w, &first, "high_limit");
    mip_jw_f32(w, &in->high_limit);
    mip_jw_key(w, &first, "high_limit_uncertainty");
    mip_jw_f32(w, &in->high_limit_uncertainty);
    mip_jw_key(w, &first, "minimum_uncertainty");
    mip_jw_f32(w, &in->minimum_uncertainty);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_mag_dip_angle_adaptive_measurement_response_from_json(
    mip_jr_t *jr, size_t pos, mip_filter_mag_dip_angle_adaptive_measurement_response_t *out) {
    static const char *const keys[] = {"mode", "frequency", "high_limit", "high_limit_uncertainty",
                                       "minimum_uncertainty"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "mode", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"mode\"");
    }
    {
        mip_jr_push(jr, "mode");
        if (mip_jr_u8(jr, vp, &out->mode)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "frequency", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"frequency\"");
    }
    {
        mip_jr_push(jr, "frequency");
        if (mip_jr_f32(jr, vp, &out->frequency)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "high_limit", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"high_limit\"");
    }
    {
        mip_jr_push(jr, "high_limit");
        if (mip_jr_f32(jr, vp, &out->high_limit)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "high_limit_uncertainty", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"high_limit_uncertainty\"");
    }
    {
        mip_jr_push(jr, "high_limit_uncertainty");
        if (mip_jr_f32(jr, vp, &out->high_limit_uncertainty)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "minimum_uncertainty", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"minimum_uncertainty\"");
    }
    {
        mip_jr_push(jr, "minimum_uncertainty");
        if (mip_jr_f32(jr, vp, &out->minimum_uncertainty)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_altitude_aiding_control_t */

static int mip_filter_altitude_aiding_control_read(mip_reader_t *r,
                                                   mip_filter_altitude_aiding_control_t *out) {
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_source = true;
        mip_rd_push(r, "source");
        if (mip_rd_u8(r, &out->source)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_altitude_aiding_control_write(mip_writer_t *w,
                                                             const mip_filter_altitude_aiding_control_t *in) {
    mip_status_t st;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_source) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u8(w, &in->source)) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_altitude_aiding_control_encode(const mip_filter_altitude_aiding_control_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_altitude_aiding_control_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_altitude_aiding_control_decode(const uint8_t *data, size_t len,
                                                       mip_filter_altitude_aiding_control_t *out,
                                                       mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_altitude_aiding_control_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_altitude_aiding_control_to_json(mip_jw_t *w, const mip_filter_altitude_aiding_control_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_source) {
        mip_jw_key(w, &first, "source");
        mip_jw_u8(w, &in->source);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_altitude_aiding_control_from_json(mip_jr_t *jr, size_t pos,
                                                 mip_filter_altitude_aiding_control_t *out) {
    static const char *const keys[] = {"function", "source"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "source", &vp);
    out->has_source = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"source\" given after an absent one");
    } else {
        mip_jr_push(jr, "source");
        if (mip_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_altitude_aiding_control_response_t */

static int
mip_filter_altitude_aiding_control_response_read(mip_reader_t *r,
                                                 mip_filter_altitude_aiding_control_response_t *out) {
    mip_rd_push(r, "source");
    if (mip_rd_u8(r, &out->source)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t
mip_filter_altitude_aiding_control_response_write(mip_writer_t *w,
                                                  const mip_filter_altitude_aiding_control_response_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->source)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t
mip_filter_altitude_aiding_control_response_encode(const mip_filter_altitude_aiding_control_response_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_altitude_aiding_control_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mip_filter_altitude_aiding_control_response_load(const uint8_t *d,
                                                 mip_filter_altitude_aiding_control_response_t *out) {
    out->source = mip_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_altitude_aiding_control_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_altitude_aiding_control_response_t *out,
    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_altitude_aiding_control_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t
mip_filter_altitude_aiding_control_response_decode(const uint8_t *data, size_t len,
                                                   mip_filter_altitude_aiding_control_response_t *out,
                                                   mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mip_filter_altitude_aiding_control_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_altitude_aiding_control_response_decode_read(data, len, out, err);
}

void mip_filter_altitude_aiding_control_response_to_json(
    mip_jw_t *w, const mip_filter_altitude_aiding_control_response_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "source");
    mip_jw_u8(w, &in->source);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_altitude_aiding_control_response_from_json(
    mip_jr_t *jr, size_t pos, mip_filter_altitude_aiding_control_response_t *out) {
    static const char *const keys[] = {"source"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "source", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"source\"");
    }
    {
        mip_jr_push(jr, "source");
        if (mip_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_pitch_roll_aiding_control_t */

static int mip_filter_pitch_roll_aiding_control_read(mip_reader_t *r,
                                                     mip_filter_pitch_roll_aiding_control_t *out) {
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_source = true;
        mip_rd_push(r, "source");
        if (mip_rd_u8(r, &out->source)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t
mip_filter_pitch_roll_aiding_control_write(mip_writer_t *w,
                                           const mip_filter_pitch_roll_aiding_control_t *in) {
    mip_status_t st;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_source) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u8(w, &in->source)) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_pitch_roll_aiding_control_encode(const mip_filter_pitch_roll_aiding_control_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_pitch_roll_aiding_control_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_pitch_roll_aiding_control_decode(const uint8_t *data, size_t len,
                                                         mip_filter_pitch_roll_aiding_control_t *out,
                                                         mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_pitch_roll_aiding_control_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_pitch_roll_aiding_control_to_json(mip_jw_t *w,
                                                  const mip_filter_pitch_roll_aiding_control_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_source) {
        mip_jw_key(w, &first, "source");
        mip_jw_u8(w, &in->source);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_pitch_roll_aiding_control_from_json(mip_jr_t *jr, size_t pos,
                                                   mip_filter_pitch_roll_aiding_control_t *out) {
    static const char *const keys[] = {"function", "source"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "source", &vp);
    out->has_source = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"source\" given after an absent one");
    } else {
        mip_jr_push(jr, "source");
        if (mip_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_pitch_roll_aiding_control_response_t */

static int
mip_filter_pitch_roll_aiding_control_response_read(mip_reader_t *r,
                                                   mip_filter_pitch_roll_aiding_control_response_t *out) {
    mip_rd_push(r, "source");
    if (mip_rd_u8(r, &out->source)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_pitch_roll_aiding_control_response_write(
    mip_writer_t *w, const mip_filter_pitch_roll_aiding_control_response_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->source)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_filter_pitch_roll_aiding_control_response_encode(
    const mip_filter_pitch_roll_aiding_control_response_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_pitch_roll_aiding_control_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mip_filter_pitch_roll_aiding_control_response_load(const uint8_t *d,
                                                   mip_filter_pitch_roll_aiding_control_response_t *out) {
    out->source = mip_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_pitch_roll_aiding_control_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_pitch_roll_aiding_control_response_t *out,
    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_pitch_roll_aiding_control_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t
mip_filter_pitch_roll_aiding_control_response_decode(const uint8_t *data, size_t len,
                                                     mip_filter_pitch_roll_aiding_control_response_t *out,
                                                     mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mip_filter_pitch_roll_aiding_control_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_pitch_roll_aiding_control_response_decode_read(data, len, out, err);
}

void mip_filter_pitch_roll_aiding_control_response_to_json(
    mip_jw_t *w, const mip_filter_pitch_roll_aiding_control_response_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "source");
    mip_jw_u8(w, &in->source);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_pitch_roll_aiding_control_response_from_json(
    mip_jr_t *jr, size_t pos, mip_filter_pitch_roll_aiding_control_response_t *out) {
    static const char *const keys[] = {"source"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "source", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"source\"");
    }
    {
        mip_jr_push(jr, "source");
        if (mip_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_inclination_source_t */

static int mip_filter_inclination_source_read(mip_reader_t *r, mip_filter_inclination_source_t *out) {
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_source = true;
        mip_rd_push(r, "source");
        if (mip_rd_u8(r, &out->source)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_inclination = true;
        mip_rd_push(r, "inclination");
        if (mip_rd_f32(r, &out->inclination)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_inclination_source_write(mip_writer_t *w,
                                                        const mip_filter_inclination_source_t *in) {
    mip_status_t st;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_source) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u8(w, &in->source)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_inclination) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_f32(w, &in->inclination)) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_inclination_source_encode(const mip_filter_inclination_source_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_inclination_source_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_inclination_source_decode(const uint8_t *data, size_t len,
                                                  mip_filter_inclination_source_t *out,
                                                  mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_inclination_source_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_inclination_source_to_json(mip_jw_t *w, const mip_filter_inclination_source_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_source) {
        mip_jw_key(w, &first, "source");
        mip_jw_u8(w, &in->source);
    }
    if (in->has_inclination) {
        mip_jw_key(w, &first, "inclination");
        mip_jw_f32(w, &in->inclination);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_inclination_source_from_json(mip_jr_t *jr, size_t pos, mip_filter_inclination_source_t *out) {
    static const char *const keys[] = {"function", "source", "inclination"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "source", &vp);
    out->has_source = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"source\" given after an absent one");
    } else {
        mip_jr_push(jr, "source");
        if (mip_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "inclination", &vp);
    out->has_inclination = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"inclination\" given after an absent one");
    } else {
        mip_jr_push(jr, "inclination");
        if (mip_jr_f32(jr, vp, &out->inclination)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_inclination_source_response_t */

static int mip_filter_inclination_source_response_read(mip_reader_t *r,
                                                       mip_filter_inclination_source_response_t *out) {
    mip_rd_push(r, "source");
    if (mip_rd_u8(r, &out->source)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "inclination");
    if (mip_rd_f32(r, &out->inclination)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t
mip_filter_inclination_source_response_write(mip_writer_t *w,
                                             const mip_filter_inclination_source_response_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->source)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->inclination)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t
mip_filter_inclination_source_response_encode(const mip_filter_inclination_source_response_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_inclination_source_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 5 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_filter_inclination_source_response_load(const uint8_t *d,
                                                       mip_filter_inclination_source_response_t *out) {
    out->source = mip_ld_u8(d + 0);
    out->inclination = mip_ld_f32(d + 1);
    return 0;
}

/* The general reader: lengths other than 5, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_inclination_source_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_inclination_source_response_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_inclination_source_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_filter_inclination_source_response_decode(const uint8_t *data, size_t len,
                                                           mip_filter_inclination_source_response_t *out,
                                                           mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 5 && mip_filter_inclination_source_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_inclination_source_response_decode_read(data, len, out, err);
}

void mip_filter_inclination_source_response_to_json(mip_jw_t *w,
                                                    const mip_filter_inclination_source_response_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "source");
    mip_jw_u8(w, &in->source);
    mip_jw_key(w, &first, "inclination");
    mip_jw_f32(w, &in->inclination);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_inclination_source_response_from_json(mip_jr_t *jr, size_t pos,
                                                     mip_filter_inclination_source_response_t *out) {
    static const char *const keys[] = {"source", "inclination"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "source", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"source\"");
    }
    {
        mip_jr_push(jr, "source");
        if (mip_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "inclination", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"inclination\"");
    }
    {
        mip_jr_push(jr, "inclination");
        if (mip_jr_f32(jr, vp, &out->inclination)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_magnetic_field_magnitude_source_t */

static int
mip_filter_magnetic_field_magnitude_source_read(mip_reader_t *r,
                                                mip_filter_magnetic_field_magnitude_source_t *out) {
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_source = true;
        mip_rd_push(r, "source");
        if (mip_rd_u8(r, &out->source)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_magnitude = true;
        mip_rd_push(r, "magnitude");
        if (mip_rd_f32(r, &out->magnitude)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t
mip_filter_magnetic_field_magnitude_source_write(mip_writer_t *w,
                                                 const mip_filter_magnetic_field_magnitude_source_t *in) {
    mip_status_t st;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_source) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u8(w, &in->source)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_magnitude) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_f32(w, &in->magnitude)) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t
mip_filter_magnetic_field_magnitude_source_encode(const mip_filter_magnetic_field_magnitude_source_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_magnetic_field_magnitude_source_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t
mip_filter_magnetic_field_magnitude_source_decode(const uint8_t *data, size_t len,
                                                  mip_filter_magnetic_field_magnitude_source_t *out,
                                                  mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_magnetic_field_magnitude_source_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_magnetic_field_magnitude_source_to_json(
    mip_jw_t *w, const mip_filter_magnetic_field_magnitude_source_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_source) {
        mip_jw_key(w, &first, "source");
        mip_jw_u8(w, &in->source);
    }
    if (in->has_magnitude) {
        mip_jw_key(w, &first, "magnitude");
        mip_jw_f32(w, &in->magnitude);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_magnetic_field_magnitude_source_from_json(mip_jr_t *jr, size_t pos,
                                                         mip_filter_magnetic_field_magnitude_source_t *out) {
    static const char *const keys[] = {"function", "source", "magnitude"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "source", &vp);
    out->has_source = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"source\" given after an absent one");
    } else {
        mip_jr_push(jr, "source");
        if (mip_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "magnitude", &vp);
    out->has_magnitude = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"magnitude\" given after an absent one");
    } else {
        mip_jr_push(jr, "magnitude");
        if (mip_jr_f32(jr, vp, &out->magnitude)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_magnetic_field_magnitude_source_response_t */

static int mip_filter_magnetic_field_magnitude_source_response_read(
    mip_reader_t *r, mip_filter_magnetic_field_magnitude_source_response_t *out) {
    mip_rd_push(r, "source");
    if (mip_rd_u8(r, &out->source)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "magnitude");
    if (mip_rd_f32(r, &out->magnitude)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_magnetic_field_magnitude_source_response_write(
    mip_writer_t *w, const mip_filter_magnetic_field_magnitude_source_response_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->source)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->magnitude)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_filter_magnetic_field_magnitude_source_response_encode(
    const mip_filter_magnetic_field_magnitude_source_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_magnetic_field_magnitude_source_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 5 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_filter_magnetic_field_magnitude_source_response_load(
    const uint8_t *d, mip_filter_magnetic_field_magnitude_source_response_t *out) {
    out->source = mip_ld_u8(d + 0);
    out->magnitude = mip_ld_f32(d + 1);
    return 0;
}

/* The general reader: lengths other than 5, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_magnetic_field_magnitude_source_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_magnetic_field_magnitude_source_response_t *out,
    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_magnetic_field_magnitude_source_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_filter_magnetic_field_magnitude_source_response_decode(
    const uint8_t *data, size_t len, mip_filter_magnetic_field_magnitude_source_response_t *out,
    mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 5 && mip_filter_magnetic_field_magnitude_source_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_magnetic_field_magnitude_source_response_decode_read(data, len, out, err);
}

void mip_filter_magnetic_field_magnitude_source_response_to_json(
    mip_jw_t *w, const mip_filter_magnetic_field_magnitude_source_response_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "source");
    mip_jw_u8(w, &in->source);
    mip_jw_key(w, &first, "magnitude");
    mip_jw_f32(w, &in->magnitude);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_magnetic_field_magnitude_source_response_from_json(
    mip_jr_t *jr, size_t pos, mip_filter_magnetic_field_magnitude_source_response_t *out) {
    static const char *const keys[] = {"source", "magnitude"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "source", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"source\"");
    }
    {
        mip_jr_push(jr, "source");
        if (mip_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "magnitude", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"magnitude\"");
    }
    {
        mip_jr_push(jr, "magnitude");
        if (mip_jr_f32(jr, vp, &out->magnitude)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_aiding_measurement_control_t */

static int mip_filter_aiding_measurement_control_read(mip_reader_t *r,
                                                      mip_filter_aiding_measurement_control_t *out) {
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "source");
    if (mip_rd_u16(r, &out->source)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_enable = true;
        mip_rd_push(r, "enable");
        if (mip_rd_bool(r, &out->enable)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t
mip_filter_aiding_measurement_control_write(mip_writer_t *w,
                                            const mip_filter_aiding_measurement_control_t *in) {
    mip_status_t st;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->source)) != MIP_OK) {
        return st;
    }
    if (!in->has_enable) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_bool(w, &in->enable)) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t
mip_filter_aiding_measurement_control_encode(const mip_filter_aiding_measurement_control_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_aiding_measurement_control_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_aiding_measurement_control_decode(const uint8_t *data, size_t len,
                                                          mip_filter_aiding_measurement_control_t *out,
                                                          mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_aiding_measurement_control_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_aiding_measurement_control_to_json(mip_jw_t *w,
                                                   const mip_filter_aiding_measurement_control_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    mip_jw_key(w, &first, "source");
    mip_jw_u16(w, &in->source);
    if (in->has_enable) {
        mip_jw_key(w, &first, "enable");
        mip_jw_bool(w, &in->enable);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_aiding_measurement_control_from_json(mip_jr_t *jr, size_t pos,
                                                    mip_filter_aiding_measurement_control_t *out) {
    static const char *const keys[] = {"function", "source", "enable"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "source", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"source\"");
    }
    {
        mip_jr_push(jr, "source");
        if (mip_jr_u16(jr, vp, &out->source)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "enable", &vp);
    out->has_enable = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"enable\" given after an absent one");
    } else {
        mip_jr_push(jr, "enable");
        if (mip_jr_bool(jr, vp, &out->enable)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_aiding_measurement_control_response_t */

static int
mip_filter_aiding_measurement_control_response_read(mip_reader_t *r,
                                                    mip_filter_aiding_measurement_control_response_t *out) {
    mip_rd_push(r, "source");
    if (mip_rd_u16(r, &out->source)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "enable");
    if (mip_rd_bool(r, &out->enable)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_aiding_measurement_control_response_write(
    mip_writer_t *w, const mip_filter_aiding_measurement_control_response_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u16(w, &in->source)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_bool(w, &in->enable)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_filter_aiding_measurement_control_response_encode(
    const mip_filter_aiding_measurement_control_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_aiding_measurement_control_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 3 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mip_filter_aiding_measurement_control_response_load(const uint8_t *d,
                                                    mip_filter_aiding_measurement_control_response_t *out) {
    out->source = mip_ld_u16(d + 0);
    if (d[2] > 1) {
        return -1;
    }
    out->enable = mip_ld_bool(d + 2);
    return 0;
}

/* The general reader: lengths other than 3, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_aiding_measurement_control_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_aiding_measurement_control_response_t *out,
    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_aiding_measurement_control_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t
mip_filter_aiding_measurement_control_response_decode(const uint8_t *data, size_t len,
                                                      mip_filter_aiding_measurement_control_response_t *out,
                                                      mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 3 && mip_filter_aiding_measurement_control_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_aiding_measurement_control_response_decode_read(data, len, out, err);
}

void mip_filter_aiding_measurement_control_response_to_json(
    mip_jw_t *w, const mip_filter_aiding_measurement_control_response_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "source");
    mip_jw_u16(w, &in->source);
    mip_jw_key(w, &first, "enable");
    mip_jw_bool(w, &in->enable);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_aiding_measurement_control_response_from_json(
    mip_jr_t *jr, size_t pos, mip_filter_aiding_measurement_control_response_t *out) {
    static const char *const keys[] = {"source", "enable"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "source", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"source\"");
    }
    {
        mip_jr_push(jr, "source");
        if (mip_jr_u16(jr, vp, &out->source)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "enable", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"enable\"");
    }
    {
        mip_jr_push(jr, "enable");
        if (mip_jr_bool(jr, vp, &out->enable)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_initialization_configuration_t */

static int mip_filter_initialization_configuration_read(mip_reader_t *r,
                                                        mip_filter_initialization_configuration_t *out) {
    size_t i;
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_wait_for_run_command = true;
        mip_rd_push(r, "wait_for_run_command");
        if (mip_rd_u8(r, &out->wait_for_run_command)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_initial_cond_src = true;
        mip_rd_push(r, "initial_cond_src");
        if (mip_rd_u8(r, &out->initial_cond_src)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_auto_heading_alignment_selector = true;
        mip_rd_push(r, "auto_heading_alignment_selector");
        if (mip_rd_u8(r, &out->auto_heading_alignment_selector)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_initial_heading = true;
        mip_rd_push(r, "initial_heading");
        if (mip_rd_f32(r, &out->initial_heading)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_initial_pitch = true;
        mip_rd_push(r, "initial_pitch");
        if (mip_rd_f32(r, &out->initial_pitch)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_initial_roll = true;
        mip_rd_push(r, "initial_roll");
        if (mip_rd_f32(r, &out->initial_roll)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_initial_position = true;
        mip_rd_push(r, "initial_position");
        for (i = 0; i < 3; i++) {
            mip_rd_index(r, i);
            if (mip_rd_f32(r, &out->initial_position[i])) {
                return -1;
            }
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_initial_velocity = true;
        mip_rd_push(r, "initial_velocity");
        for (i = 0; i < 3; i++) {
            mip_rd_index(r, i);
            if (mip_rd_f32(r, &out->initial_velocity[i])) {
                return -1;
            }
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_reference_frame_selector = true;
        mip_rd_push(r, "reference_frame_selector");
        if (mip_rd_u8(r, &out->reference_frame_selector)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t
mip_filter_initialization_configuration_write(mip_writer_t *w,
                                              const mip_filter_initialization_configuration_t *in) {
    mip_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_wait_for_run_command) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u8(w, &in->wait_for_run_command)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_initial_cond_src) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u8(w, &in->initial_cond_src)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_auto_heading_alignment_selector) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u8(w, &in->auto_heading_alignment_selector)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_initial_heading) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_f32(w, &in->initial_heading)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_initial_pitch) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_f32(w, &in->initial_pitch)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_initial_roll) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_f32(w, &in->initial_roll)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_initial_position) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mip_wr_f32(w, &in->initial_position[i])) != MIP_OK) {
                return st;
            }
        }
    }
    if (!in->has_initial_velocity) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mip_wr_f32(w, &in->initial_velocity[i])) != MIP_OK) {
                return st;
            }
        }
    }
    if (!in->has_reference_frame_selector) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u8(w, &in->reference_frame_selector)) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t
mip_filter_initialization_configuration_encode(const mip_filter_initialization_configuration_t *value,
                                               uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_initialization_configuration_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_initialization_configuration_decode(const uint8_t *data, size_t len,
                                                            mip_filter_initialization_configuration_t *out,
                                                            mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_initialization_configuration_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_initialization_configuration_to_json(mip_jw_t *w,
                                                     const mip_filter_initialization_configuration_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_wait_for_run_command) {
        mip_jw_key(w, &first, "wait_for_run_command");
        mip_jw_u8(w, &in->wait_for_run_command);
    }
    if (in->has_initial_cond_src) {
        mip_jw_key(w, &first, "initial_cond_src");
        mip_jw_u8(w, &in->initial_cond_src);
    }
    if (in->has_auto_heading_alignment_selector) {
        mip_jw_key(w, &first, "auto_heading_alignment_selector");
        mip_jw_u8(w, &in->auto_heading_alignment_selector);
    }
    if (in->has_initial_heading) {
        mip_jw_key(w, &first, "initial_heading");
        mip_jw_f32(w, &in->initial_heading);
    }
    if (in->has_initial_pitch) {
        mip_jw_key(w, &first, "initial_pitch");
        mip_jw_f32(w, &in->initial_pitch);
    }
    if (in->has_initial_roll) {
        mip_jw_key(w, &first, "initial_roll");
        mip_jw_f32(w, &in->initial_roll);
    }
    if (in->has_initial_position) {
        mip_jw_key(w, &first, "initial_position");
        mip_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mip_jw_sep(w, i);
            mip_jw_f32(w, &in->initial_position[i]);
        }
        mip_jw_raw(w, "]", 1);
    }
    if (in->has_initial_velocity) {
        mip_jw_key(w, &first, "initial_velocity");
        mip_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mip_jw_sep(w, i);
            mip_jw_f32(w, &in->initial_velocity[i]);
        }
        mip_jw_raw(w, "]", 1);
    }
    if (in->has_reference_frame_selector) {
        mip_jw_key(w, &first, "reference_frame_selector");
        mip_jw_u8(w, &in->reference_frame_selector);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_initialization_configuration_from_json(mip_jr_t *jr, size_t pos,
                                                      mip_filter_initialization_configuration_t *out) {
    static const char *const keys[] = {
        "function",         "wait_for_run_command",    "initial_cond_src", "auto_heading_alignment_selector",
        "initial_heading",  "initial_pitch",           "initial_roll",     "initial_position",
        "initial_velocity", "reference_frame_selector"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 10)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "wait_for_run_command", &vp);
    out->has_wait_for_run_command = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"wait_for_run_command\" given after an absent one");
    } else {
        mip_jr_push(jr, "wait_for_run_command");
        if (mip_jr_u8(jr, vp, &out->wait_for_run_command)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "initial_cond_src", &vp);
    out->has_initial_cond_src = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"initial_cond_src\" given after an absent one");
    } else {
        mip_jr_push(jr, "initial_cond_src");
        if (mip_jr_u8(jr, vp, &out->initial_cond_src)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "auto_heading_alignment_selector", &vp);
    out->has_auto_heading_alignment_selector = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(
            jr, "optional parameter \"auto_heading_alignment_selector\" given after an absent one");
    } else {
        mip_jr_push(jr, "auto_heading_alignment_selector");
        if (mip_jr_u8(jr, vp, &out->auto_heading_alignment_selector)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "initial_heading", &vp);
    out->has_initial_heading = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"initial_heading\" given after an absent one");
    } else {
        mip_jr_push(jr, "initial_heading");
        if (mip_jr_f32(jr, vp, &out->initial_heading)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "initial_pitch", &vp);
    out->has_initial_pitch = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"initial_pitch\" given after an absent one");
    } else {
        mip_jr_push(jr, "initial_pitch");
        if (mip_jr_f32(jr, vp, &out->initial_pitch)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "initial_roll", &vp);
    out->has_initial_roll = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"initial_roll\" given after an absent one");
    } else {
        mip_jr_push(jr, "initial_roll");
        if (mip_jr_f32(jr, vp, &out->initial_roll)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "initial_position", &vp);
    out->has_initial_position = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"initial_position\" given after an absent one");
    } else {
        mip_jr_push(jr, "initial_position");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->initial_position[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "initial_velocity", &vp);
    out->has_initial_velocity = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"initial_velocity\" given after an absent one");
    } else {
        mip_jr_push(jr, "initial_velocity");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->initial_velocity[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "reference_frame_selector", &vp);
    out->has_reference_frame_selector = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"reference_frame_selector\" given after an absent one");
    } else {
        mip_jr_push(jr, "reference_frame_selector");
        if (mip_jr_u8(jr, vp, &out->reference_frame_selector)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_initialization_configuration_response_t */

static int mip_filter_initialization_configuration_response_read(
    mip_reader_t *r, mip_filter_initialization_configuration_response_t *out) {
    size_t i;
    mip_rd_push(r, "wait_for_run_command");
    if (mip_rd_u8(r, &out->wait_for_run_command)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "initial_cond_src");
    if (mip_rd_u8(r, &out->initial_cond_src)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "auto_heading_alignment_selector");
    if (mip_rd_u8(r, &out->auto_heading_alignment_selector)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "initial_heading");
    if (mip_rd_f32(r, &out->initial_heading)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "initial_pitch");
    if (mip_rd_f32(r, &out->initial_pitch)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "initial_roll");
    if (mip_rd_f32(r, &out->initial_roll)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "initial_position");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->initial_position[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    mip_rd_push(r, "initial_velocity");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->initial_velocity[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    mip_rd_push(r, "reference_frame_selector");
    if (mip_rd_u8(r, &out->reference_frame_selector)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_initialization_configuration_response_write(
    mip_writer_t *w, const mip_filter_initialization_configuration_response_t *in) {
    mip_status_t st;
    size_t i;
    if ((st = mip_wr_u8(w, &in->wait_for_run_command)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->initial_cond_src)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->auto_heading_alignment_selector)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->initial_heading)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->initial_pitch)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->initial_roll)) != MIP_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->initial_position[i])) != MIP_OK) {
            return st;
        }
    }
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->initial_velocity[i])) != MIP_OK) {
            return st;
        }
    }
    if ((st = mip_wr_u8(w, &in->reference_frame_selector)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_filter_initialization_configuration_response_encode(
    const mip_filter_initialization_configuration_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_initialization_configuration_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 40 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_filter_initialization_configuration_response_load(
    const uint8_t *d, mip_filter_initialization_configuration_response_t *out) {
    out->wait_for_run_command = mip_ld_u8(d + 0);
    out->initial_cond_src = mip_ld_u8(d + 1);
    out->auto_heading_alignment_selector = mip_ld_u8(d + 2);
    out->initial_heading = mip_ld_f32(d + 3);
    out->initial_pitch = mip_ld_f32(d + 7);
    out->initial_roll = mip_ld_f32(d + 11);
    out->initial_position[0] = mip_ld_f32(d + 15);
    out->initial_position[1] = mip_ld_f32(d + 19);
    out->initial_position[2] = mip_ld_f32(d + 23);
    out->initial_velocity[0] = mip_ld_f32(d + 27);
    out->initial_velocity[1] = mip_ld_f32(d + 31);
    out->initial_velocity[2] = mip_ld_f32(d + 35);
    out->reference_frame_selector = mip_ld_u8(d + 39);
    return 0;
}

/* The general reader: lengths other than 40, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_initialization_configuration_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_initialization_configuration_response_t *out,
    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_initialization_configuration_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_filter_initialization_configuration_response_decode(
    const uint8_t *data, size_t len, mip_filter_initialization_configuration_response_t *out,
    mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 40 && mip_filter_initialization_configuration_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_initialization_configuration_response_decode_read(data, len, out, err);
}

void mip_filter_initialization_configuration_response_to_json(
    mip_jw_t *w, const mip_filter_initialization_configuration_response_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "wait_for_run_command");
    mip_jw_u8(w, &in->wait_for_run_command);
    mip_jw_key(w, &first, "initial_cond_src");
    mip_jw_u8(w, &in->initial_cond_src);
    mip_jw_key(w, &first, "auto_heading_alignment_selector");
    mip_jw_u8(w, &in->auto_heading_alignment_selector);
    mip_jw_key(w, &first, "initial_heading");
    mip_jw_f32(w, &in->initial_heading);
    mip_jw_key(w, &first, "initial_pitch");
    mip_jw_f32(w, &in->initial_pitch);
    mip_jw_key(w, &first, "initial_roll");
    mip_jw_f32(w, &in->initial_roll);
    mip_jw_key(w, &first, "initial_position");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->initial_position[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_key(w, &first, "initial_velocity");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->initial_velocity[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_key(w, &first, "reference_frame_selector");
    mip_jw_u8(w, &in->reference_frame_selector);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_initialization_configuration_response_from_json(
    mip_jr_t *jr, size_t pos, mip_filter_initialization_configuration_response_t *out) {
    static const char *const keys[] = {
        "wait_for_run_command", "initial_cond_src", "auto_heading_alignment_selector",
        "initial_heading",      "initial_pitch",    "initial_roll",
        "initial_position",     "initial_velocity", "reference_frame_selector"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 9)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "wait_for_run_command", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"wait_for_run_command\"");
    }
    {
        mip_jr_push(jr, "wait_for_run_command");
        if (mip_jr_u8(jr, vp, &out->wait_for_run_command)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "initial_cond_src", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"initial_cond_src\"");
    }
    {
        mip_jr_push(jr, "initial_cond_src");
        if (mip_jr_u8(jr, vp, &out->initial_cond_src)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "auto_heading_alignment_selector", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"auto_heading_alignment_selector\"");
    }
    {
        mip_jr_push(jr, "auto_heading_alignment_selector");
        if (mip_jr_u8(jr, vp, &out->auto_heading_alignment_selector)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "initial_heading", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"initial_heading\"");
    }
    {
        mip_jr_push(jr, "initial_heading");
        if (mip_jr_f32(jr, vp, &out->initial_heading)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "initial_pitch", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"initial_pitch\"");
    }
    {
        mip_jr_push(jr, "initial_pitch");
        if (mip_jr_f32(jr, vp, &out->initial_pitch)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "initial_roll", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"initial_roll\"");
    }
    {
        mip_jr_push(jr, "initial_roll");
        if (mip_jr_f32(jr, vp, &out->initial_roll)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "initial_position", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"initial_position\"");
    }
    {
        mip_jr_push(jr, "initial_position");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->initial_position[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "initial_velocity", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"initial_velocity\"");
    }
    {
        mip_jr_push(jr, "initial_velocity");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->initial_velocity[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "reference_frame_selector", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"reference_frame_selector\"");
    }
    {
        mip_jr_push(jr, "reference_frame_selector");
        if (mip_jr_u8(jr, vp, &out->reference_frame_selector)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_adaptive_filter_control_t */

static int mip_filter_adaptive_filter_control_read(mip_reader_t *r,
                                                   mip_filter_adaptive_filter_control_t *out) {
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_level = true;
        mip_rd_push(r, "level");
        if (mip_rd_u8(r, &out->level)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_time_limit = true;
        mip_rd_push(r, "time_limit");
        if (mip_rd_u16(r, &out->time_limit)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_adaptive_filter_control_write(mip_writer_t *w,
                                                             const mip_filter_adaptive_filter_control_t *in) {
    mip_status_t st;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_level) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u8(w, &in->level)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_time_limit) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u16(w, &in->time_limit)) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_adaptive_filter_control_encode(const mip_filter_adaptive_filter_control_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_adaptive_filter_control_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_adaptive_filter_control_decode(const uint8_t *data, size_t len,
                                                       mip_filter_adaptive_filter_control_t *out,
                                                       mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_adaptive_filter_control_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_adaptive_filter_control_to_json(mip_jw_t *w, const mip_filter_adaptive_filter_control_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_level) {
        mip_jw_key(w, &first, "level");
        mip_jw_u8(w, &in->level);
    }
    if (in->has_time_limit) {
        mip_jw_key(w, &first, "time_limit");
        mip_jw_u16(w, &in->time_limit);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_adaptive_filter_control_from_json(mip_jr_t *jr, size_t pos,
                                                 mip_filter_adaptive_filter_control_t *out) {
    static const char *const keys[] = {"function", "level", "time_limit"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "level", &vp);
    out->has_level = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"level\" given after an absent one");
    } else {
        mip_jr_push(jr, "level");
        if (mip_jr_u8(jr, vp, &out->level)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "time_limit", &vp);
    out->has_time_limit = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"time_limit\" given after an absent one");
    } else {
        mip_jr_push(jr, "time_limit");
        if (mip_jr_u16(jr, vp, &out->time_limit)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_adaptive_filter_control_response_t */

static int
mip_filter_adaptive_filter_control_response_read(mip_reader_t *r,
                                                 mip_filter_adaptive_filter_control_response_t *out) {
    mip_rd_push(r, "level");
    if (mip_rd_u8(r, &out->level)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "time_limit");
    if (mip_rd_u16(r, &out->time_limit)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t
mip_filter_adaptive_filter_control_response_write(mip_writer_t *w,
                                                  const mip_filter_adaptive_filter_control_response_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->level)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->time_limit)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t
mip_filter_adaptive_filter_control_response_encode(const mip_filter_adaptive_filter_control_response_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_adaptive_filter_control_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 3 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mip_filter_adaptive_filter_control_response_load(const uint8_t *d,
                                                 mip_filter_adaptive_filter_control_response_t *out) {
    out->level = mip_ld_u8(d + 0);
    out->time_limit = mip_ld_u16(d + 1);
    return 0;
}

/* The general reader: lengths other than 3, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_adaptive_filter_control_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_adaptive_filter_control_response_t *out,
    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_adaptive_filter_control_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t
mip_filter_adaptive_filter_control_response_decode(const uint8_t *data, size_t len,
                                                   mip_filter_adaptive_filter_control_response_t *out,
                                                   mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 3 && mip_filter_adaptive_filter_control_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_adaptive_filter_control_response_decode_read(data, len, out, err);
}

void mip_filter_adaptive_filter_control_response_to_json(
    mip_jw_t *w, const mip_filter_adaptive_filter_control_response_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "level");
    mip_jw_u8(w, &in->level);
    mip_jw_key(w, &first, "time_limit");
    mip_jw_u16(w, &in->time_limit);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_adaptive_filter_control_response_from_json(
    mip_jr_t *jr, size_t pos, mip_filter_adaptive_filter_control_response_t *out) {
    static const char *const keys[] = {"level", "time_limit"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "level", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"level\"");
    }
    {
        mip_jr_push(jr, "level");
        if (mip_jr_u8(jr, vp, &out->level)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "time_limit", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"time_limit\"");
    }
    {
        mip_jr_push(jr, "time_limit");
        if (mip_jr_u16(jr, vp, &out->time_limit)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_multi_antenna_offset_t */

static int mip_filter_multi_antenna_offset_read(mip_reader_t *r, mip_filter_multi_antenna_offset_t *out) {
    size_t i;
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "receiver_id");
    if (mip_rd_u8(r, &out->receiver_id)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_antenna_offset = true;
        mip_rd_push(r, "antenna_offset");
        for (i = 0; i < 3; i++) {
            mip_rd_index(r, i);
            if (mip_rd_f32(r, &out->antenna_offset[i])) {
                return -1;
            }
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_multi_antenna_offset_write(mip_writer_t *w,
                                                          const mip_filter_multi_antenna_offset_t *in) {
    mip_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->receiver_id)) != MIP_OK) {
        return st;
    }
    if (!in->has_antenna_offset) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mip_wr_f32(w, &in->antenna_offset[i])) != MIP_OK) {
                return st;
            }
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_multi_antenna_offset_encode(const mip_filter_multi_antenna_offset_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_multi_antenna_offset_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_multi_antenna_offset_decode(const uint8_t *data, size_t len,
                                                    mip_filter_multi_antenna_offset_t *out,
                                                    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_multi_antenna_offset_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_multi_antenna_offset_to_json(mip_jw_t *w, const mip_filter_multi_antenna_offset_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    mip_jw_key(w, &first, "receiver_id");
    mip_jw_u8(w, &in->receiver_id);
    if (in->has_antenna_offset) {
        mip_jw_key(w, &first, "antenna_offset");
        mip_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mip_jw_sep(w, i);
            mip_jw_f32(w, &in->antenna_offset[i]);
        }
        mip_jw_raw(w, "]", 1);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_multi_antenna_offset_from_json(mip_jr_t *jr, size_t pos,
                                              mip_filter_multi_antenna_offset_t *out) {
    static const char *const keys[] = {"function", "receiver_id", "antenna_offset"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "receiver_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"receiver_id\"");
    }
    {
        mip_jr_push(jr, "receiver_id");
        if (mip_jr_u8(jr, vp, &out->receiver_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "antenna_offset", &vp);
    out->has_antenna_offset = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"antenna_offset\" given after an absent one");
    } else {
        mip_jr_push(jr, "antenna_offset");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->antenna_offset[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_multi_antenna_offset_response_t */

static int mip_filter_multi_antenna_offset_response_read(mip_reader_t *r,
                                                         mip_filter_multi_antenna_offset_response_t *out) {
    size_t i;
    mip_rd_push(r, "receiver_id");
    if (mip_rd_u8(r, &out->receiver_id)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "antenna_offset");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->antenna_offset[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t
mip_filter_multi_antenna_offset_response_write(mip_writer_t *w,
                                               const mip_filter_multi_antenna_offset_response_t *in) {
    mip_status_t st;
    size_t i;
    if ((st = mip_wr_u8(w, &in->receiver_id)) != MIP_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->antenna_offset[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t
mip_filter_multi_antenna_offset_response_encode(const mip_filter_multi_antenna_offset_response_t *value,
                                                uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_multi_antenna_offset_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 13 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_filter_multi_antenna_offset_response_load(const uint8_t *d,
                                                         mip_filter_multi_antenna_offset_response_t *out) {
    out->receiver_id = mip_ld_u8(d + 0);
    out->antenna_offset[0] = mip_ld_f32(d + 1);
    out->antenna_offset[1] = mip_ld_f32(d + 5);
    out->antenna_offset[2] = mip_ld_f32(d + 9);
    return 0;
}

/* The general reader: lengths other than 13, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_multi_antenna_offset_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_multi_antenna_offset_response_t *out,
    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_multi_antenna_offset_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_filter_multi_antenna_offset_response_decode(const uint8_t *data, size_t len,
                                                             mip_filter_multi_antenna_offset_response_t *out,
                                                             mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 13 && mip_filter_multi_antenna_offset_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_multi_antenna_offset_response_decode_read(data, len, out, err);
}

void mip_filter_multi_antenna_offset_response_to_json(mip_jw_t *w,
                                                      const mip_filter_multi_antenna_offset_response_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "receiver_id");
    mip_jw_u8(w, &in->receiver_id);
    mip_jw_key(w, &first, "antenna_offset");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->antenna_offset[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_multi_antenna_offset_response_from_json(mip_jr_t *jr, size_t pos,
                                                       mip_filter_multi_antenna_offset_response_t *out) {
    static const char *const keys[] = {"receiver_id", "antenna_offset"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "receiver_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"receiver_id\"");
    }
    {
        mip_jr_push(jr, "receiver_id");
        if (mip_jr_u8(jr, vp, &out->receiver_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "antenna_offset", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"antenna_offset\"");
    }
    {
        mip_jr_push(jr, "antenna_offset");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->antenna_offset[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_relative_position_configuration_t */

static int
mip_filter_relative_position_configuration_read(mip_reader_t *r,
                                                mip_filter_relative_position_configuration_t *out) {
    size_t i;
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_source = true;
        mip_rd_push(r, "source");
        if (mip_rd_u8(r, &out->source)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_reference_frame_selector = true;
        mip_rd_push(r, "reference_frame_selector");
        if (mip_rd_u8(r, &out->reference_frame_selector)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_reference_coordinates = true;
        mip_rd_push(r, "reference_coordinates");
        for (i = 0; i < 3; i++) {
            mip_rd_index(r, i);
            if (mip_rd_f64(r, &out->reference_coordinates[i])) {
                return -1;
            }
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t
mip_filter_relative_position_configuration_write(mip_writer_t *w,
                                                 const mip_filter_relative_position_configuration_t *in) {
    mip_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_source) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u8(w, &in->source)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_reference_frame_selector) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u8(w, &in->reference_frame_selector)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_reference_coordinates) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mip_wr_f64(w, &in->reference_coordinates[i])) != MIP_OK) {
                return st;
            }
        }
    }
    return MIP_OK;
}

mip_status_t
mip_filter_relative_position_configuration_encode(const mip_filter_relative_position_configuration_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_relative_position_configuration_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t
mip_filter_relative_position_configuration_decode(const uint8_t *data, size_t len,
                                                  mip_filter_relative_position_configuration_t *out,
                                                  mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_relative_position_configuration_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_relative_position_configuration_to_json(
    mip_jw_t *w, const mip_filter_relative_position_configuration_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_source) {
        mip_jw_key(w, &first, "source");
        mip_jw_u8(w, &in->source);
    }
    if (in->has_reference_frame_selector) {
        mip_jw_key(w, &first, "reference_frame_selector");
        mip_jw_u8(w, &in->reference_frame_selector);
    }
    if (in->has_reference_coordinates) {
        mip_jw_key(w, &first, "reference_coordinates");
        mip_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mip_jw_sep(w, i);
            mip_jw_f64(w, &in->reference_coordinates[i]);
        }
        mip_jw_raw(w, "]", 1);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_relative_position_configuration_from_json(mip_jr_t *jr, size_t pos,
                                                         mip_filter_relative_position_configuration_t *out) {
    static const char *const keys[] = {"function", "source", "reference_frame_selector",
                                       "reference_coordinates"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 4)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "source", &vp);
    out->has_source = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"source\" given after an absent one");
    } else {
        mip_jr_push(jr, "source");
        if (mip_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "reference_frame_selector", &vp);
    out->has_reference_frame_selector = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"reference_frame_selector\" given after an absent one");
    } else {
        mip_jr_push(jr, "reference_frame_selector");
        if (mip_jr_u8(jr, vp, &out->reference_frame_selector)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "reference_coordinates", &vp);
    out->has_reference_coordinates = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"reference_coordinates\" given after an absent one");
    } else {
        mip_jr_push(jr, "reference_coordinates");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f64(jr, ep, &out->reference_coordinates[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_relative_position_configuration_response_t */

static int mip_filter_relative_position_configuration_response_read(
    mip_reader_t *r, mip_filter_relative_position_configuration_response_t *out) {
    size_t i;
    mip_rd_push(r, "source");
    if (mip_rd_u8(r, &out->source)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "reference_frame_selector");
    if (mip_rd_u8(r, &out->reference_frame_selector)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "reference_coordinates");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f64(r, &out->reference_coordinates[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_relative_position_configuration_response_write(
    mip_writer_t *w, const mip_filter_relative_position_configuration_response_t *in) {
    mip_status_t st;
    size_t i;
    if ((st = mip_wr_u8(w, &in->source)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->reference_frame_selector)) != MIP_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f64(w, &in->reference_coordinates[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_relative_position_configuration_response_encode(
    const mip_filter_relative_position_configuration_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_relative_position_configuration_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 26 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_filter_relative_position_configuration_response_load(
    const uint8_t *d, mip_filter_relative_position_configuration_response_t *out) {
    out->source = mip_ld_u8(d + 0);
    out->reference_frame_selector = mip_ld_u8(d + 1);
    out->reference_coordinates[0] = mip_ld_f64(d + 2);
    out->reference_coordinates[1] = mip_ld_f64(d + 10);
    out->reference_coordinates[2] = mip_ld_f64(d + 18);
    return 0;
}

/* The general reader: lengths other than 26, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_relative_position_configuration_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_relative_position_configuration_response_t *out,
    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_relative_position_configuration_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_filter_relative_position_configuration_response_decode(
    const uint8_t *data, size_t len, mip_filter_relative_position_configuration_response_t *out,
    mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 26 && mip_filter_relative_position_configuration_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_relative_position_configuration_response_decode_read(data, len, out, err);
}

void mip_filter_relative_position_configuration_response_to_json(
    mip_jw_t *w, const mip_filter_relative_position_configuration_response_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "source");
    mip_jw_u8(w, &in->source);
    mip_jw_key(w, &first, "reference_frame_selector");
    mip_jw_u8(w, &in->reference_frame_selector);
    mip_jw_key(w, &first, "reference_coordinates");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f64(w, &in->reference_coordinates[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_relative_position_configuration_response_from_json(
    mip_jr_t *jr, size_t pos, mip_filter_relative_position_configuration_response_t *out) {
    static const char *const keys[] = {"source", "reference_frame_selector", "reference_coordinates"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "source", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"source\"");
    }
    {
        mip_jr_push(jr, "source");
        if (mip_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "reference_frame_selector", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"reference_frame_selector\"");
    }
    {
        mip_jr_push(jr, "reference_frame_selector");
        if (mip_jr_u8(jr, vp, &out->reference_frame_selector)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "reference_coordinates", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"reference_coordinates\"");
    }
    {
        mip_jr_push(jr, "reference_coordinates");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f64(jr, ep, &out->reference_coordinates[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_reference_point_lever_arm_t */

static int mip_filter_reference_point_lever_arm_read(mip_reader_t *r,
                                                     mip_filter_reference_point_lever_arm_t *out) {
    size_t i;
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_ref_point_sel = true;
        mip_rd_push(r, "ref_point_sel");
        if (mip_rd_u8(r, &out->ref_point_sel)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_lever_arm_offset = true;
        mip_rd_push(r, "lever_arm_offset");
        for (i = 0; i < 3; i++) {
            mip_rd_index(r, i);
            if (mip_rd_f32(r, &out->lever_arm_offset[i])) {
                return -1;
            }
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t
mip_filter_reference_point_lever_arm_write(mip_writer_t *w,
                                           const mip_filter_reference_point_lever_arm_t *in) {
    mip_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_ref_point_sel) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u8(w, &in->ref_point_sel)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_lever_arm_offset) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mip_wr_f32(w, &in->lever_arm_offset[i])) != MIP_OK) {
                return st;
            }
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_reference_point_lever_arm_encode(const mip_filter_reference_point_lever_arm_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_reference_point_lever_arm_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_reference_point_lever_arm_decode(const uint8_t *data, size_t len,
                                                         mip_filter_reference_point_lever_arm_t *out,
                                                         mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_reference_point_lever_arm_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_reference_point_lever_arm_to_json(mip_jw_t *w,
                                                  const mip_filter_reference_point_lever_arm_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_ref_point_sel) {
        mip_jw_key(w, &first, "ref_point_sel");
        mip_jw_u8(w, &in->ref_point_sel);
    }
    if (in->has_lever_arm_offset) {
        mip_jw_key(w, &first, "lever_arm_offset");
        mip_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mip_jw_sep(w, i);
            mip_jw_f32(w, &in->lever_arm_offset[i]);
        }
        mip_jw_raw(w, "]", 1);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_reference_point_lever_arm_from_json(mip_jr_t *jr, size_t pos,
                                                   mip_filter_reference_point_lever_arm_t *out) {
    static const char *const keys[] = {"function", "ref_point_sel", "lever_arm_offset"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "ref_point_sel", &vp);
    out->has_ref_point_sel = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"ref_point_sel\" given after an absent one");
    } else {
        mip_jr_push(jr, "ref_point_sel");
        if (mip_jr_u8(jr, vp, &out->ref_point_sel)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "lever_arm_offset", &vp);
    out->has_lever_arm_offset = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"lever_arm_offset\" given after an absent one");
    } else {
        mip_jr_push(jr, "lever_arm_offset");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->lever_arm_offset[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_reference_point_lever_arm_response_t */

static int
mip_filter_reference_point_lever_arm_response_read(mip_reader_t *r,
                                                   mip_filter_reference_point_lever_arm_response_t *out) {
    size_t i;
    mip_rd_push(r, "ref_point_sel");
    if (mip_rd_u8(r, &out->ref_point_sel)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "lever_arm_offset");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->lever_arm_offset[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_reference_point_lever_arm_response_write(
    mip_writer_t *w, const mip_filter_reference_point_lever_arm_response_t *in) {
    mip_status_t st;
    size_t i;
    if ((st = mip_wr_u8(w, &in->ref_point_sel)) != MIP_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->lever_arm_offset[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_reference_point_lever_arm_response_encode(
    const mip_filter_reference_point_lever_arm_response_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_reference_point_lever_arm_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 13 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mip_filter_reference_point_lever_arm_response_load(const uint8_t *d,
                                                   mip_filter_reference_point_lever_arm_response_t *out) {
    out->ref_point_sel = mip_ld_u8(d + 0);
    out->lever_arm_offset[0] = mip_ld_f32(d + 1);
    out->lever_arm_offset[1] = mip_ld_f32(d + 5);
    out->lever_arm_offset[2] = mip_ld_f32(d + 9);
    return 0;
}

/* The general reader: lengths other than 13, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_reference_point_lever_arm_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_reference_point_lever_arm_response_t *out,
    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_reference_point_lever_arm_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t
mip_filter_reference_point_lever_arm_response_decode(const uint8_t *data, size_t len,
                                                     mip_filter_reference_point_lever_arm_response_t *out,
                                                     mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 13 && mip_filter_reference_point_lever_arm_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_reference_point_lever_arm_response_decode_read(data, len, out, err);
}

void mip_filter_reference_point_lever_arm_response_to_json(
    mip_jw_t *w, const mip_filter_reference_point_lever_arm_response_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "ref_point_sel");
    mip_jw_u8(w, &in->ref_point_sel);
    mip_jw_key(w, &first, "lever_arm_offset");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->lever_arm_offset[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_reference_point_lever_arm_response_from_json(
    mip_jr_t *jr, size_t pos, mip_filter_reference_point_lever_arm_response_t *out) {
    static const char *const keys[] = {"ref_point_sel", "lever_arm_offset"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "ref_point_sel", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"ref_point_sel\"");
    }
    {
        mip_jr_push(jr, "ref_point_sel");
        if (mip_jr_u8(jr, vp, &out->ref_point_sel)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "lever_arm_offset", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"lever_arm_offset\"");
    }
    {
        mip_jr_push(jr, "lever_arm_offset");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->lever_arm_offset[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_speed_lever_arm_t */

static int mip_filter_speed_lever_arm_read(mip_reader_t *r, mip_filter_speed_lever_arm_t *out) {
    size_t i;
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "source");
    if (mip_rd_u8(r, &out->source)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_lever_arm_offset = true;
        mip_rd_push(r, "lever_arm_offset");
        for (i = 0; i < 3; i++) {
            mip_rd_index(r, i);
            if (mip_rd_f32(r, &out->lever_arm_offset[i])) {
                return -1;
            }
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_speed_lever_arm_write(mip_writer_t *w,
                                                     const mip_filter_speed_lever_arm_t *in) {
    mip_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->source)) != MIP_OK) {
        return st;
    }
    if (!in->has_lever_arm_offset) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mip_wr_f32(w, &in->lever_arm_offset[i])) != MIP_OK) {
                return st;
            }
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_speed_lever_arm_encode(const mip_filter_speed_lever_arm_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_speed_lever_arm_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_speed_lever_arm_decode(const uint8_t *data, size_t len,
                                               mip_filter_speed_lever_arm_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_speed_lever_arm_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_speed_lever_arm_to_json(mip_jw_t *w, const mip_filter_speed_lever_arm_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    mip_jw_key(w, &first, "source");
    mip_jw_u8(w, &in->source);
    if (in->has_lever_arm_offset) {
        mip_jw_key(w, &first, "lever_arm_offset");
        mip_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mip_jw_sep(w, i);
            mip_jw_f32(w, &in->lever_arm_offset[i]);
        }
        mip_jw_raw(w, "]", 1);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_speed_lever_arm_from_json(mip_jr_t *jr, size_t pos, mip_filter_speed_lever_arm_t *out) {
    static const char *const keys[] = {"function", "source", "lever_arm_offset"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "source", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"source\"");
    }
    {
        mip_jr_push(jr, "source");
        if (mip_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "lever_arm_offset", &vp);
    out->has_lever_arm_offset = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"lever_arm_offset\" given after an absent one");
    } else {
        mip_jr_push(jr, "lever_arm_offset");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->lever_arm_offset[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_speed_lever_arm_response_t */

static int mip_filter_speed_lever_arm_response_read(mip_reader_t *r,
                                                    mip_filter_speed_lever_arm_response_t *out) {
    size_t i;
    mip_rd_push(r, "source");
    if (mip_rd_u8(r, &out->source)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "lever_arm_offset");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->lever_arm_offset[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t
mip_filter_speed_lever_arm_response_write(mip_writer_t *w, const mip_filter_speed_lever_arm_response_t *in) {
    mip_status_t st;
    size_t i;
    if ((st = mip_wr_u8(w, &in->source)) != MIP_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->lever_arm_offset[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_speed_lever_arm_response_encode(const mip_filter_speed_lever_arm_response_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_speed_lever_arm_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 13 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_filter_speed_lever_arm_response_load(const uint8_t *d,
                                                    mip_filter_speed_lever_arm_response_t *out) {
    out->source = mip_ld_u8(d + 0);
    out->lever_arm_offset[0] = mip_ld_f32(d + 1);
    out->lever_arm_offset[1] = mip_ld_f32(d + 5);
    out->lever_arm_offset[2] = mip_ld_f32(d + 9);
    return 0;
}

/* The general reader: lengths other than 13, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_speed_lever_arm_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_speed_lever_arm_response_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_speed_lever_arm_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_filter_speed_lever_arm_response_decode(const uint8_t *data, size_t len,
                                                        mip_filter_speed_lever_arm_response_t *out,
                                                        mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 13 && mip_filter_speed_lever_arm_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_speed_lever_arm_response_decode_read(data, len, out, err);
}

void mip_filter_speed_lever_arm_response_to_json(mip_jw_t *w,
                                                 const mip_filter_speed_lever_arm_response_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "source");
    mip_jw_u8(w, &in->source);
    mip_jw_key(w, &first, "lever_arm_offset");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->lever_arm_offset[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_speed_lever_arm_response_from_json(mip_jr_t *jr, size_t pos,
                                                  mip_filter_speed_lever_arm_response_t *out) {
    static const char *const keys[] = {"source", "lever_arm_offset"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "source", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"source\"");
    }
    {
        mip_jr_push(jr, "source");
        if (mip_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "lever_arm_offset", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"lever_arm_offset\"");
    }
    {
        mip_jr_push(jr, "lever_arm_offset");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->lever_arm_offset[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_wheeled_vehicle_constraint_control_t */

static int
mip_filter_wheeled_vehicle_constraint_control_read(mip_reader_t *r,
                                                   mip_filter_wheeled_vehicle_constraint_control_t *out) {
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_enable = true;
        mip_rd_push(r, "enable");
        if (mip_rd_u8(r, &out->enable)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_wheeled_vehicle_constraint_control_write(
    mip_writer_t *w, const mip_filter_wheeled_vehicle_constraint_control_t *in) {
    mip_status_t st;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_enable) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u8(w, &in->enable)) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_filter_wheeled_vehicle_constraint_control_encode(
    const mip_filter_wheeled_vehicle_constraint_control_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_wheeled_vehicle_constraint_control_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t
mip_filter_wheeled_vehicle_constraint_control_decode(const uint8_t *data, size_t len,
                                                     mip_filter_wheeled_vehicle_constraint_control_t *out,
                                                     mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_wheeled_vehicle_constraint_control_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_wheeled_vehicle_constraint_control_to_json(
    mip_jw_t *w, const mip_filter_wheeled_vehicle_constraint_control_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_enable) {
        mip_jw_key(w, &first, "enable");
        mip_jw_u8(w, &in->enable);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_wheeled_vehicle_constraint_control_from_json(
    mip_jr_t *jr, size_t pos, mip_filter_wheeled_vehicle_constraint_control_t *out) {
    static const char *const keys[] = {"function", "enable"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "enable", &vp);
    out->has_enable = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"enable\" given after an absent one");
    } else {
        mip_jr_push(jr, "enable");
        if (mip_jr_u8(jr, vp, &out->enable)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_wheeled_vehicle_constraint_control_response_t */

static int mip_filter_wheeled_vehicle_constraint_control_response_read(
    mip_reader_t *r, mip_filter_wheeled_vehicle_constraint_control_response_t *out) {
    mip_rd_push(r, "enable");
    if (mip_rd_u8(r, &out->enable)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_wheeled_vehicle_constraint_control_response_write(
    mip_writer_t *w, const mip_filter_wheeled_vehicle_constraint_control_response_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->enable)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_filter_wheeled_vehicle_constraint_control_response_encode(
    const mip_filter_wheeled_vehicle_constraint_control_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_wheeled_vehicle_constraint_control_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_filter_wheeled_vehicle_constraint_control_response_load(
    const uint8_t *d, mip_filter_wheeled_vehicle_constraint_control_response_t *out) {
    out->enable = mip_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_wheeled_vehicle_constraint_control_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_wheeled_vehicle_constraint_control_response_t *out,
    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_wheeled_vehicle_constraint_control_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_filter_wheeled_vehicle_constraint_control_response_decode(
    const uint8_t *data, size_t len, mip_filter_wheeled_vehicle_constraint_control_response_t *out,
    mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mip_filter_wheeled_vehicle_constraint_control_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_wheeled_vehicle_constraint_control_response_decode_read(data, len, out, err);
}

void mip_filter_wheeled_vehicle_constraint_control_response_to_json(
    mip_jw_t *w, const mip_filter_wheeled_vehicle_constraint_control_response_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "enable");
    mip_jw_u8(w, &in->enable);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_wheeled_vehicle_constraint_control_response_from_json(
    mip_jr_t *jr, size_t pos, mip_filter_wheeled_vehicle_constraint_control_response_t *out) {
    static const char *const keys[] = {"enable"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "enable", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"enable\"");
    }
    {
        mip_jr_push(jr, "enable");
        if (mip_jr_u8(jr, vp, &out->enable)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_gnss_antenna_calibration_control_t */

static int
mip_filter_gnss_antenna_calibration_control_read(mip_reader_t *r,
                                                 mip_filter_gnss_antenna_calibration_control_t *out) {
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_enable = true;
        mip_rd_push(r, "enable");
        if (mip_rd_u8(r, &out->enable)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_max_offset = true;
        mip_rd_push(r, "max_offset");
        if (mip_rd_f32(r, &out->max_offset)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t
mip_filter_gnss_antenna_calibration_control_write(mip_writer_t *w,
                                                  const mip_filter_gnss_antenna_calibration_control_t *in) {
    mip_status_t st;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_enable) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u8(w, &in->enable)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_max_offset) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_f32(w, &in->max_offset)) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t
mip_filter_gnss_antenna_calibration_control_encode(const mip_filter_gnss_antenna_calibration_control_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_gnss_antenna_calibration_control_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t
mip_filter_gnss_antenna_calibration_control_decode(const uint8_t *data, size_t len,
                                                   mip_filter_gnss_antenna_calibration_control_t *out,
                                                   mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_gnss_antenna_calibration_control_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_filter_gnss_antenna_calibration_control_to_json(
    mip_jw_t *w, const mip_filter_gnss_antenna_calibration_control_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_enable) {
        mip_jw_key(w, &first, "enable");
        mip_jw_u8(w, &in->enable);
    }
    if (in->has_max_offset) {
        mip_jw_key(w, &first, "max_offset");
        mip_jw_f32(w, &in->max_offset);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_filter_gnss_antenna_calibration_control_from_json(
    mip_jr_t *jr, size_t pos, mip_filter_gnss_antenna_calibration_control_t *out) {
    static const char *const keys[] = {"function", "enable", "max_offset"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "enable", &vp);
    out->has_enable = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"enable\" given after an absent one");
    } else {
        mip_jr_push(jr, "enable");
        if (mip_jr_u8(jr, vp, &out->enable)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "max_offset", &vp);
    out->has_max_offset = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"max_offset\" given after an absent one");
    } else {
        mip_jr_push(jr, "max_offset");
        if (mip_jr_f32(jr, vp, &out->max_offset)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_filter_gnss_antenna_calibration_control_response_t */

static int mip_filter_gnss_antenna_calibration_control_response_read(
    mip_reader_t *r, mip_filter_gnss_antenna_calibration_control_response_t *out) {
    mip_rd_push(r, "enable");
    if (mip_rd_u8(r, &out->enable)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "max_offset");
    if (mip_rd_f32(r, &out->max_offset)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_filter_gnss_antenna_calibration_control_response_write(
    mip_writer_t *w, const mip_filter_gnss_antenna_calibration_control_response_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->enable)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->max_offset)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_filter_gnss_antenna_calibration_control_response_encode(
    const mip_filter_gnss_antenna_calibration_control_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_filter_gnss_antenna_calibration_control_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 5 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_filter_gnss_antenna_calibration_control_response_load(
    const uint8_t *d, mip_filter_gnss_antenna_calibration_control_response_t *out) {
    out->enable = mip_ld_u8(d + 0);
    out->max_offset = mip_ld_f32(d + 1);
    return 0;
}

/* The general reader: lengths other than 5, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_filter_gnss_antenna_calibration_control_response_decode_read(
    const uint8_t *data, size_t len, mip_filter_gnss_antenna_calibration_control_response_t *out,
    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_gnss_antenna_calibration_control_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_filter_gnss_antenna_calibration_control_response_decode(
    const uint8_t *data, size_t len, mip_filter_gnss_antenna_calibration_control_response_t *out,
    mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 5 && mip_filter_gnss_antenna_calibration_control_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_filter_gnss_antenna_calibration_control_response_decode_read(data, len, out, err);
}

void mip_filter_gnss_antenna_calibration_control_response_to_json(
    mip_jw_t *w, const mip_filter_gnss_antenna_calibration_control_response_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "enable");
    mip_jw_u8(w, &in->enable);
    mip_jw_key(w, &first, "max_offset");
    mip_jw_f32(w, &in->max_offset);
    mip_jw_raw(w, "}", 1);
}

int mip_filter_gnss_antenna_calibration_control_response_from_json(
    mip_jr_t *jr, size_t pos, mip_filter_gnss_antenna_calibration_control_response_t *out) {
    static const char *const keys[] = {"enable", "max_offset"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "enable", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"enable\"");
    }
    {
        mip_jr_push(jr, "enable");
        if (mip_jr_u8(jr, vp, &out->enable)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "max_offset", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"max_offset\"");
    }
    {
        mip_jr_push(jr, "max_offset");
        if (mip_jr_f32(jr, vp, &out->max_offset)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}
