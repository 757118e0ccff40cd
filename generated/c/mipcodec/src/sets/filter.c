/* Encoders and decoders of Filter Command Set. Generated from the spec: do not edit. */
#include "mipcodec/sets/filter.h"
#include "layouts_internal.h"
#include "types_internal.h"

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
    mip_writer_init(&w, buf, cap);
    st = mip_filter_set_initial_attitude_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_set_initial_attitude_decode(const uint8_t *data, size_t len,
                                                    mip_filter_set_initial_attitude_t *out,
                                                    mip_decode_error_t *err) {
    mip_reader_t r;
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_set_initial_attitude_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
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
    mip_writer_init(&w, buf, cap);
    st = mip_filter_set_initial_heading_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_set_initial_heading_decode(const uint8_t *data, size_t len,
                                                   mip_filter_set_initial_heading_t *out,
                                                   mip_decode_error_t *err) {
    mip_reader_t r;
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_set_initial_heading_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
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
    mip_writer_init(&w, buf, cap);
    st = mip_filter_vehicle_dynamics_mode_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t
mip_filter_vehicle_dynamics_mode_response_decode(const uint8_t *data, size_t len,
                                                 mip_filter_vehicle_dynamics_mode_response_t *out,
                                                 mip_decode_error_t *err) {
    mip_reader_t r;
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_vehicle_dynamics_mode_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
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
    mip_writer_init(&w, buf, cap);
    st = mip_filter_sensor_to_vehicle_transform_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t
mip_filter_sensor_to_vehicle_transform_response_decode(const uint8_t *data, size_t len,
                                                       mip_filter_sensor_to_vehicle_transform_response_t *out,
                                                       mip_decode_error_t *err) {
    mip_reader_t r;
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_sensor_to_vehicle_transform_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
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
    mip_writer_init(&w, buf, cap);
    st = mip_filter_sensor_to_vehicle_offset_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t
mip_filter_sensor_to_vehicle_offset_response_decode(const uint8_t *data, size_t len,
                                                    mip_filter_sensor_to_vehicle_offset_response_t *out,
                                                    mip_decode_error_t *err) {
    mip_reader_t r;
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_sensor_to_vehicle_offset_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
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
    mip_writer_init(&w, buf, cap);
    st = mip_filter_antenna_offset_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_antenna_offset_response_decode(const uint8_t *data, size_t len,
                                                       mip_filter_antenna_offset_response_t *out,
                                                       mip_decode_error_t *err) {
    mip_reader_t r;
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_antenna_offset_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
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
    mip_writer_init(&w, buf, cap);
    st = mip_filter_estimation_control_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_estimation_control_response_decode(const uint8_t *data, size_t len,
                                                           mip_filter_estimation_control_response_t *out,
                                                           mip_decode_error_t *err) {
    mip_reader_t r;
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_estimation_control_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
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
    mip_writer_init(&w, buf, cap);
    st = mip_filter_gnss_source_control_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_gnss_source_control_response_decode(const uint8_t *data, size_t len,
                                                            mip_filter_gnss_source_control_response_t *out,
                                                            mip_decode_error_t *err) {
    mip_reader_t r;
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_gnss_source_control_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
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
    mip_writer_init(&w, buf, cap);
    st = mip_filter_external_gnss_update_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_external_gnss_update_decode(const uint8_t *data, size_t len,
                                                    mip_filter_external_gnss_update_t *out,
                                                    mip_decode_error_t *err) {
    mip_reader_t r;
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_external_gnss_update_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
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
    mip_writer_init(&w, buf, cap);
    st = mip_filter_external_heading_update_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_external_heading_update_decode(const uint8_t *data, size_t len,
                                                       mip_filter_external_heading_update_t *out,
                                                       mip_decode_error_t *err) {
    mip_reader_t r;
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_external_heading_update_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
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
    mip_writer_init(&w, buf, cap);
    st = mip_filter_heading_update_control_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t
mip_filter_heading_update_control_response_decode(const uint8_t *data, size_t len,
                                                  mip_filter_heading_update_control_response_t *out,
                                                  mip_decode_error_t *err) {
    mip_reader_t r;
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_heading_update_control_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
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
    mip_writer_init(&w, buf, cap);
    st = mip_filter_auto_init_control_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_auto_init_control_response_decode(const uint8_t *data, size_t len,
                                                          mip_filter_auto_init_control_response_t *out,
                                                          mip_decode_error_t *err) {
    mip_reader_t r;
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_auto_init_control_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
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
    mip_writer_init(&w, buf, cap);
    st = mip_filter_accel_noise_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_accel_noise_response_decode(const uint8_t *data, size_t len,
                                                    mip_filter_accel_noise_response_t *out,
                                                    mip_decode_error_t *err) {
    mip_reader_t r;
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_accel_noise_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
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
    mip_writer_init(&w, buf, cap);
    st = mip_filter_gyro_noise_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_gyro_noise_response_decode(const uint8_t *data, size_t len,
                                                   mip_filter_gyro_noise_response_t *out,
                                                   mip_decode_error_t *err) {
    mip_reader_t r;
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_gyro_noise_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
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
    mip_writer_init(&w, buf, cap);
    st = mip_filter_accel_bias_model_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_accel_bias_model_response_decode(const uint8_t *data, size_t len,
                                                         mip_filter_accel_bias_model_response_t *out,
                                                         mip_decode_error_t *err) {
    mip_reader_t r;
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_accel_bias_model_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
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
    mip_writer_init(&w, buf, cap);
    st = mip_filter_gyro_bias_model_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_gyro_bias_model_response_decode(const uint8_t *data, size_t len,
                                                        mip_filter_gyro_bias_model_response_t *out,
                                                        mip_decode_error_t *err) {
    mip_reader_t r;
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_gyro_bias_model_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
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
    mip_writer_init(&w, buf, cap);
    st = mip_filter_zupt_control_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_filter_zupt_control_response_decode(const uint8_t *data, size_t len,
                                                     mip_filter_zupt_control_response_t *out,
                                                     mip_decode_error_t *err) {
    mip_reader_t r;
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_zupt_control_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
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
    mip_writer_init(&w, buf, cap);
    st = mip_filter_external_heading_update_with_time_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t
mip_filter_external_heading_update_with_time_decode(const uint8_t *data, size_t len,
                                                    mip_filter_external_heading_update_with_time_t *out,
                                                    mip_decode_error_t *err) {
    mip_reader_t r;
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_filter_external_heading_update_with_time_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
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
