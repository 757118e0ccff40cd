/* Encoders and decoders of Filter Command Set. Generated from the spec: do not edit. */
#include "mipcodec/sets/filter.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <string.h>

/* ---- mipc_filter_reset_filter_t */

static int mipc_filter_reset_filter_read(mipc_reader_t *r, mipc_filter_reset_filter_t *out) {
    (void)out;
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_reset_filter_write(mipc_writer_t *w, const mipc_filter_reset_filter_t *in) {
    (void)w;
    (void)in;
    return MIPC_OK;
}

mipc_status_t mipc_filter_reset_filter_encode(const mipc_filter_reset_filter_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_reset_filter_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_filter_reset_filter_decode(const uint8_t *data, size_t len,
                                              mipc_filter_reset_filter_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_reset_filter_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_reset_filter_to_json(mipc_jw_t *w, const mipc_filter_reset_filter_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mipc_filter_reset_filter_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_reset_filter_t *out) {
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mipc_filter_set_initial_attitude_t */

static int mipc_filter_set_initial_attitude_read(mipc_reader_t *r, mipc_filter_set_initial_attitude_t *out) {
    mipc_rd_push(r, "roll");
    if (mipc_rd_f32(r, &out->roll)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "pitch");
    if (mipc_rd_f32(r, &out->pitch)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "heading");
    if (mipc_rd_f32(r, &out->heading)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_set_initial_attitude_write(mipc_writer_t *w,
                                                            const mipc_filter_set_initial_attitude_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f32(w, &in->roll)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->pitch)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->heading)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_set_initial_attitude_encode(const mipc_filter_set_initial_attitude_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_set_initial_attitude_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_set_initial_attitude_load(const uint8_t *d, mipc_filter_set_initial_attitude_t *out) {
    out->roll = mipc_ld_f32(d + 0);
    out->pitch = mipc_ld_f32(d + 4);
    out->heading = mipc_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_set_initial_attitude_decode_read(
    const uint8_t *data, size_t len, mipc_filter_set_initial_attitude_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_set_initial_attitude_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_set_initial_attitude_decode(const uint8_t *data, size_t len,
                                                      mipc_filter_set_initial_attitude_t *out,
                                                      mipc_decode_error_t *err) {
    if (len == 12 && mipc_filter_set_initial_attitude_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_set_initial_attitude_decode_read(data, len, out, err);
}

void mipc_filter_set_initial_attitude_to_json(mipc_jw_t *w, const mipc_filter_set_initial_attitude_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "roll");
    mipc_jw_f32(w, &in->roll);
    mipc_jw_key(w, &first, "pitch");
    mipc_jw_f32(w, &in->pitch);
    mipc_jw_key(w, &first, "heading");
    mipc_jw_f32(w, &in->heading);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_set_initial_attitude_from_json(mipc_jr_t *jr, size_t pos,
                                               mipc_filter_set_initial_attitude_t *out) {
    static const char *const keys[] = {"roll", "pitch", "heading"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "roll", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"roll\"");
    }
    {
        mipc_jr_push(jr, "roll");
        if (mipc_jr_f32(jr, vp, &out->roll)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "pitch", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"pitch\"");
    }
    {
        mipc_jr_push(jr, "pitch");
        if (mipc_jr_f32(jr, vp, &out->pitch)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "heading", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"heading\"");
    }
    {
        mipc_jr_push(jr, "heading");
        if (mipc_jr_f32(jr, vp, &out->heading)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_set_initial_heading_t */

static int mipc_filter_set_initial_heading_read(mipc_reader_t *r, mipc_filter_set_initial_heading_t *out) {
    mipc_rd_push(r, "heading");
    if (mipc_rd_f32(r, &out->heading)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_set_initial_heading_write(mipc_writer_t *w,
                                                           const mipc_filter_set_initial_heading_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f32(w, &in->heading)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_set_initial_heading_encode(const mipc_filter_set_initial_heading_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_set_initial_heading_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 4 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_set_initial_heading_load(const uint8_t *d, mipc_filter_set_initial_heading_t *out) {
    out->heading = mipc_ld_f32(d + 0);
    return 0;
}

/* The general reader: lengths other than 4, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_set_initial_heading_decode_read(
    const uint8_t *data, size_t len, mipc_filter_set_initial_heading_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_set_initial_heading_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_set_initial_heading_decode(const uint8_t *data, size_t len,
                                                     mipc_filter_set_initial_heading_t *out,
                                                     mipc_decode_error_t *err) {
    if (len == 4 && mipc_filter_set_initial_heading_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_set_initial_heading_decode_read(data, len, out, err);
}

void mipc_filter_set_initial_heading_to_json(mipc_jw_t *w, const mipc_filter_set_initial_heading_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "heading");
    mipc_jw_f32(w, &in->heading);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_set_initial_heading_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_filter_set_initial_heading_t *out) {
    static const char *const keys[] = {"heading"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "heading", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"heading\"");
    }
    {
        mipc_jr_push(jr, "heading");
        if (mipc_jr_f32(jr, vp, &out->heading)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_run_filter_t */

static int mipc_filter_run_filter_read(mipc_reader_t *r, mipc_filter_run_filter_t *out) {
    (void)out;
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_run_filter_write(mipc_writer_t *w, const mipc_filter_run_filter_t *in) {
    (void)w;
    (void)in;
    return MIPC_OK;
}

mipc_status_t mipc_filter_run_filter_encode(const mipc_filter_run_filter_t *value, uint8_t *buf, size_t cap,
                                            size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_run_filter_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_filter_run_filter_decode(const uint8_t *data, size_t len, mipc_filter_run_filter_t *out,
                                            mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_run_filter_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_run_filter_to_json(mipc_jw_t *w, const mipc_filter_run_filter_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mipc_filter_run_filter_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_run_filter_t *out) {
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mipc_filter_vehicle_dynamics_mode_t */

static int mipc_filter_vehicle_dynamics_mode_read(mipc_reader_t *r,
                                                  mipc_filter_vehicle_dynamics_mode_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_mode = true;
        mipc_rd_push(r, "mode");
        if (mipc_rd_u8(r, &out->mode)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_vehicle_dynamics_mode_write(mipc_writer_t *w,
                                                             const mipc_filter_vehicle_dynamics_mode_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_mode) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->mode)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_vehicle_dynamics_mode_encode(const mipc_filter_vehicle_dynamics_mode_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_vehicle_dynamics_mode_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_filter_vehicle_dynamics_mode_decode(const uint8_t *data, size_t len,
                                                       mipc_filter_vehicle_dynamics_mode_t *out,
                                                       mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_vehicle_dynamics_mode_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_vehicle_dynamics_mode_to_json(mipc_jw_t *w, const mipc_filter_vehicle_dynamics_mode_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_mode) {
        mipc_jw_key(w, &first, "mode");
        mipc_jw_u8(w, &in->mode);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_vehicle_dynamics_mode_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_filter_vehicle_dynamics_mode_t *out) {
    static const char *const keys[] = {"function", "mode"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "mode", &vp);
    out->has_mode = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"mode\" given after an absent one");
    } else {
        mipc_jr_push(jr, "mode");
        if (mipc_jr_u8(jr, vp, &out->mode)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_vehicle_dynamics_mode_response_t */

static int
mipc_filter_vehicle_dynamics_mode_response_read(mipc_reader_t *r,
                                                mipc_filter_vehicle_dynamics_mode_response_t *out) {
    mipc_rd_push(r, "mode");
    if (mipc_rd_u8(r, &out->mode)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_vehicle_dynamics_mode_response_write(mipc_writer_t *w,
                                                 const mipc_filter_vehicle_dynamics_mode_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->mode)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_vehicle_dynamics_mode_response_encode(const mipc_filter_vehicle_dynamics_mode_response_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_vehicle_dynamics_mode_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_filter_vehicle_dynamics_mode_response_load(const uint8_t *d,
                                                mipc_filter_vehicle_dynamics_mode_response_t *out) {
    out->mode = mipc_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_vehicle_dynamics_mode_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_vehicle_dynamics_mode_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_vehicle_dynamics_mode_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_vehicle_dynamics_mode_response_decode(const uint8_t *data, size_t len,
                                                  mipc_filter_vehicle_dynamics_mode_response_t *out,
                                                  mipc_decode_error_t *err) {
    if (len == 1 && mipc_filter_vehicle_dynamics_mode_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_vehicle_dynamics_mode_response_decode_read(data, len, out, err);
}

void mipc_filter_vehicle_dynamics_mode_response_to_json(
    mipc_jw_t *w, const mipc_filter_vehicle_dynamics_mode_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "mode");
    mipc_jw_u8(w, &in->mode);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_vehicle_dynamics_mode_response_from_json(mipc_jr_t *jr, size_t pos,
                                                         mipc_filter_vehicle_dynamics_mode_response_t *out) {
    static const char *const keys[] = {"mode"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "mode", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"mode\"");
    }
    {
        mipc_jr_push(jr, "mode");
        if (mipc_jr_u8(jr, vp, &out->mode)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_sensor_to_vehicle_transform_t */

static int mipc_filter_sensor_to_vehicle_transform_read(mipc_reader_t *r,
                                                        mipc_filter_sensor_to_vehicle_transform_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_roll = true;
        mipc_rd_push(r, "roll");
        if (mipc_rd_f32(r, &out->roll)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_pitch = true;
        mipc_rd_push(r, "pitch");
        if (mipc_rd_f32(r, &out->pitch)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_yaw = true;
        mipc_rd_push(r, "yaw");
        if (mipc_rd_f32(r, &out->yaw)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_sensor_to_vehicle_transform_write(mipc_writer_t *w,
                                              const mipc_filter_sensor_to_vehicle_transform_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_roll) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->roll)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_pitch) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->pitch)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_yaw) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->yaw)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_sensor_to_vehicle_transform_encode(const mipc_filter_sensor_to_vehicle_transform_t *value,
                                               uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_sensor_to_vehicle_transform_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_filter_sensor_to_vehicle_transform_decode(const uint8_t *data, size_t len,
                                                             mipc_filter_sensor_to_vehicle_transform_t *out,
                                                             mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_sensor_to_vehicle_transform_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_sensor_to_vehicle_transform_to_json(mipc_jw_t *w,
                                                     const mipc_filter_sensor_to_vehicle_transform_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_roll) {
        mipc_jw_key(w, &first, "roll");
        mipc_jw_f32(w, &in->roll);
    }
    if (in->has_pitch) {
        mipc_jw_key(w, &first, "pitch");
        mipc_jw_f32(w, &in->pitch);
    }
    if (in->has_yaw) {
        mipc_jw_key(w, &first, "yaw");
        mipc_jw_f32(w, &in->yaw);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_sensor_to_vehicle_transform_from_json(mipc_jr_t *jr, size_t pos,
                                                      mipc_filter_sensor_to_vehicle_transform_t *out) {
    static const char *const keys[] = {"function", "roll", "pitch", "yaw"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 4)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "roll", &vp);
    out->has_roll = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"roll\" given after an absent one");
    } else {
        mipc_jr_push(jr, "roll");
        if (mipc_jr_f32(jr, vp, &out->roll)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "pitch", &vp);
    out->has_pitch = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"pitch\" given after an absent one");
    } else {
        mipc_jr_push(jr, "pitch");
        if (mipc_jr_f32(jr, vp, &out->pitch)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "yaw", &vp);
    out->has_yaw = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"yaw\" given after an absent one");
    } else {
        mipc_jr_push(jr, "yaw");
        if (mipc_jr_f32(jr, vp, &out->yaw)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_sensor_to_vehicle_transform_response_t */

static int mipc_filter_sensor_to_vehicle_transform_response_read(
    mipc_reader_t *r, mipc_filter_sensor_to_vehicle_transform_response_t *out) {
    mipc_rd_push(r, "roll");
    if (mipc_rd_f32(r, &out->roll)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "pitch");
    if (mipc_rd_f32(r, &out->pitch)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "yaw");
    if (mipc_rd_f32(r, &out->yaw)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_sensor_to_vehicle_transform_response_write(
    mipc_writer_t *w, const mipc_filter_sensor_to_vehicle_transform_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f32(w, &in->roll)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->pitch)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->yaw)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_sensor_to_vehicle_transform_response_encode(
    const mipc_filter_sensor_to_vehicle_transform_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_sensor_to_vehicle_transform_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_sensor_to_vehicle_transform_response_load(
    const uint8_t *d, mipc_filter_sensor_to_vehicle_transform_response_t *out) {
    out->roll = mipc_ld_f32(d + 0);
    out->pitch = mipc_ld_f32(d + 4);
    out->yaw = mipc_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_sensor_to_vehicle_transform_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_sensor_to_vehicle_transform_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_sensor_to_vehicle_transform_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_sensor_to_vehicle_transform_response_decode(
    const uint8_t *data, size_t len, mipc_filter_sensor_to_vehicle_transform_response_t *out,
    mipc_decode_error_t *err) {
    if (len == 12 && mipc_filter_sensor_to_vehicle_transform_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_sensor_to_vehicle_transform_response_decode_read(data, len, out, err);
}

void mipc_filter_sensor_to_vehicle_transform_response_to_json(
    mipc_jw_t *w, const mipc_filter_sensor_to_vehicle_transform_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "roll");
    mipc_jw_f32(w, &in->roll);
    mipc_jw_key(w, &first, "pitch");
    mipc_jw_f32(w, &in->pitch);
    mipc_jw_key(w, &first, "yaw");
    mipc_jw_f32(w, &in->yaw);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_sensor_to_vehicle_transform_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_sensor_to_vehicle_transform_response_t *out) {
    static const char *const keys[] = {"roll", "pitch", "yaw"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "roll", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"roll\"");
    }
    {
        mipc_jr_push(jr, "roll");
        if (mipc_jr_f32(jr, vp, &out->roll)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "pitch", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"pitch\"");
    }
    {
        mipc_jr_push(jr, "pitch");
        if (mipc_jr_f32(jr, vp, &out->pitch)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "yaw", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"yaw\"");
    }
    {
        mipc_jr_push(jr, "yaw");
        if (mipc_jr_f32(jr, vp, &out->yaw)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_sensor_to_vehicle_offset_t */

static int mipc_filter_sensor_to_vehicle_offset_read(mipc_reader_t *r,
                                                     mipc_filter_sensor_to_vehicle_offset_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_offset = true;
        mipc_rd_push(r, "offset");
        for (i = 0; i < 3; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->offset[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_sensor_to_vehicle_offset_write(mipc_writer_t *w,
                                           const mipc_filter_sensor_to_vehicle_offset_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_offset) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mipc_wr_f32(w, &in->offset[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_sensor_to_vehicle_offset_encode(const mipc_filter_sensor_to_vehicle_offset_t *value,
                                                          uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_sensor_to_vehicle_offset_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_filter_sensor_to_vehicle_offset_decode(const uint8_t *data, size_t len,
                                                          mipc_filter_sensor_to_vehicle_offset_t *out,
                                                          mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_sensor_to_vehicle_offset_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_sensor_to_vehicle_offset_to_json(mipc_jw_t *w,
                                                  const mipc_filter_sensor_to_vehicle_offset_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_offset) {
        mipc_jw_key(w, &first, "offset");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->offset[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_sensor_to_vehicle_offset_from_json(mipc_jr_t *jr, size_t pos,
                                                   mipc_filter_sensor_to_vehicle_offset_t *out) {
    static const char *const keys[] = {"function", "offset"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "offset", &vp);
    out->has_offset = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"offset\" given after an absent one");
    } else {
        mipc_jr_push(jr, "offset");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->offset[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_sensor_to_vehicle_offset_response_t */

static int
mipc_filter_sensor_to_vehicle_offset_response_read(mipc_reader_t *r,
                                                   mipc_filter_sensor_to_vehicle_offset_response_t *out) {
    size_t i;
    mipc_rd_push(r, "offset");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->offset[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_sensor_to_vehicle_offset_response_write(
    mipc_writer_t *w, const mipc_filter_sensor_to_vehicle_offset_response_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->offset[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_sensor_to_vehicle_offset_response_encode(
    const mipc_filter_sensor_to_vehicle_offset_response_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_sensor_to_vehicle_offset_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_filter_sensor_to_vehicle_offset_response_load(const uint8_t *d,
                                                   mipc_filter_sensor_to_vehicle_offset_response_t *out) {
    out->offset[0] = mipc_ld_f32(d + 0);
    out->offset[1] = mipc_ld_f32(d + 4);
    out->offset[2] = mipc_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_sensor_to_vehicle_offset_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_sensor_to_vehicle_offset_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_sensor_to_vehicle_offset_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_sensor_to_vehicle_offset_response_decode(const uint8_t *data, size_t len,
                                                     mipc_filter_sensor_to_vehicle_offset_response_t *out,
                                                     mipc_decode_error_t *err) {
    if (len == 12 && mipc_filter_sensor_to_vehicle_offset_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_sensor_to_vehicle_offset_response_decode_read(data, len, out, err);
}

void mipc_filter_sensor_to_vehicle_offset_response_to_json(
    mipc_jw_t *w, const mipc_filter_sensor_to_vehicle_offset_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "offset");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->offset[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_sensor_to_vehicle_offset_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_sensor_to_vehicle_offset_response_t *out) {
    static const char *const keys[] = {"offset"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "offset", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"offset\"");
    }
    {
        mipc_jr_push(jr, "offset");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->offset[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_antenna_offset_t */

static int mipc_filter_antenna_offset_read(mipc_reader_t *r, mipc_filter_antenna_offset_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_offset = true;
        mipc_rd_push(r, "offset");
        for (i = 0; i < 3; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->offset[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_antenna_offset_write(mipc_writer_t *w,
                                                      const mipc_filter_antenna_offset_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_offset) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mipc_wr_f32(w, &in->offset[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_antenna_offset_encode(const mipc_filter_antenna_offset_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_antenna_offset_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_filter_antenna_offset_decode(const uint8_t *data, size_t len,
                                                mipc_filter_antenna_offset_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_antenna_offset_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_antenna_offset_to_json(mipc_jw_t *w, const mipc_filter_antenna_offset_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_offset) {
        mipc_jw_key(w, &first, "offset");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->offset[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_antenna_offset_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_antenna_offset_t *out) {
    static const char *const keys[] = {"function", "offset"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "offset", &vp);
    out->has_offset = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"offset\" given after an absent one");
    } else {
        mipc_jr_push(jr, "offset");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->offset[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_antenna_offset_response_t */

static int mipc_filter_antenna_offset_response_read(mipc_reader_t *r,
                                                    mipc_filter_antenna_offset_response_t *out) {
    size_t i;
    mipc_rd_push(r, "offset");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->offset[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_antenna_offset_response_write(mipc_writer_t *w, const mipc_filter_antenna_offset_response_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->offset[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_antenna_offset_response_encode(const mipc_filter_antenna_offset_response_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_antenna_offset_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_antenna_offset_response_load(const uint8_t *d,
                                                    mipc_filter_antenna_offset_response_t *out) {
    out->offset[0] = mipc_ld_f32(d + 0);
    out->offset[1] = mipc_ld_f32(d + 4);
    out->offset[2] = mipc_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_antenna_offset_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_antenna_offset_response_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_antenna_offset_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_antenna_offset_response_decode(const uint8_t *data, size_t len,
                                                         mipc_filter_antenna_offset_response_t *out,
                                                         mipc_decode_error_t *err) {
    if (len == 12 && mipc_filter_antenna_offset_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_antenna_offset_response_decode_read(data, len, out, err);
}

void mipc_filter_antenna_offset_response_to_json(mipc_jw_t *w,
                                                 const mipc_filter_antenna_offset_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "offset");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->offset[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_antenna_offset_response_from_json(mipc_jr_t *jr, size_t pos,
                                                  mipc_filter_antenna_offset_response_t *out) {
    static const char *const keys[] = {"offset"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "offset", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"offset\"");
    }
    {
        mipc_jr_push(jr, "offset");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->offset[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_estimation_control_t */

static int mipc_filter_estimation_control_read(mipc_reader_t *r, mipc_filter_estimation_control_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_flags = true;
        mipc_rd_push(r, "flags");
        if (mipc_rd_u16(r, &out->flags)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_estimation_control_write(mipc_writer_t *w,
                                                          const mipc_filter_estimation_control_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_flags) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u16(w, &in->flags)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_estimation_control_encode(const mipc_filter_estimation_control_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_estimation_control_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_filter_estimation_control_decode(const uint8_t *data, size_t len,
                                                    mipc_filter_estimation_control_t *out,
                                                    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_estimation_control_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_estimation_control_to_json(mipc_jw_t *w, const mipc_filter_estimation_control_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_flags) {
        mipc_jw_key(w, &first, "flags");
        mipc_jw_u16(w, &in->flags);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_estimation_control_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_filter_estimation_control_t *out) {
    static const char *const keys[] = {"function", "flags"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "flags", &vp);
    out->has_flags = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"flags\" given after an absent one");
    } else {
        mipc_jr_push(jr, "flags");
        if (mipc_jr_u16(jr, vp, &out->flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_estimation_control_response_t */

static int mipc_filter_estimation_control_response_read(mipc_reader_t *r,
                                                        mipc_filter_estimation_control_response_t *out) {
    mipc_rd_push(r, "flags");
    if (mipc_rd_u16(r, &out->flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_estimation_control_response_write(mipc_writer_t *w,
                                              const mipc_filter_estimation_control_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u16(w, &in->flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_estimation_control_response_encode(const mipc_filter_estimation_control_response_t *value,
                                               uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_estimation_control_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_estimation_control_response_load(const uint8_t *d,
                                                        mipc_filter_estimation_control_response_t *out) {
    out->flags = mipc_ld_u16(d + 0);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_estimation_control_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_estimation_control_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_estimation_control_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_estimation_control_response_decode(const uint8_t *data, size_t len,
                                                             mipc_filter_estimation_control_response_t *out,
                                                             mipc_decode_error_t *err) {
    if (len == 2 && mipc_filter_estimation_control_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_estimation_control_response_decode_read(data, len, out, err);
}

void mipc_filter_estimation_control_response_to_json(mipc_jw_t *w,
                                                     const mipc_filter_estimation_control_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "flags");
    mipc_jw_u16(w, &in->flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_estimation_control_response_from_json(mipc_jr_t *jr, size_t pos,
                                                      mipc_filter_estimation_control_response_t *out) {
    static const char *const keys[] = {"flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"flags\"");
    }
    {
        mipc_jr_push(jr, "flags");
        if (mipc_jr_u16(jr, vp, &out->flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_gnss_source_control_t */

static int mipc_filter_gnss_source_control_read(mipc_reader_t *r, mipc_filter_gnss_source_control_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_source = true;
        mipc_rd_push(r, "source");
        if (mipc_rd_u8(r, &out->source)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_gnss_source_control_write(mipc_writer_t *w,
                                                           const mipc_filter_gnss_source_control_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_source) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->source)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_gnss_source_control_encode(const mipc_filter_gnss_source_control_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_gnss_source_control_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_filter_gnss_source_control_decode(const uint8_t *data, size_t len,
                                                     mipc_filter_gnss_source_control_t *out,
                                                     mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_gnss_source_control_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_gnss_source_control_to_json(mipc_jw_t *w, const mipc_filter_gnss_source_control_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_source) {
        mipc_jw_key(w, &first, "source");
        mipc_jw_u8(w, &in->source);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_gnss_source_control_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_filter_gnss_source_control_t *out) {
    static const char *const keys[] = {"function", "source"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "source", &vp);
    out->has_source = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"source\" given after an absent one");
    } else {
        mipc_jr_push(jr, "source");
        if (mipc_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_gnss_source_control_response_t */

static int mipc_filter_gnss_source_control_response_read(mipc_reader_t *r,
                                                         mipc_filter_gnss_source_control_response_t *out) {
    mipc_rd_push(r, "source");
    if (mipc_rd_u8(r, &out->source)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_gnss_source_control_response_write(mipc_writer_t *w,
                                               const mipc_filter_gnss_source_control_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->source)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_gnss_source_control_response_encode(const mipc_filter_gnss_source_control_response_t *value,
                                                uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_gnss_source_control_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_gnss_source_control_response_load(const uint8_t *d,
                                                         mipc_filter_gnss_source_control_response_t *out) {
    out->source = mipc_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_gnss_source_control_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_gnss_source_control_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_gnss_source_control_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_gnss_source_control_response_decode(const uint8_t *data, size_t len,
                                                              mipc_filter_gnss_source_control_response_t *out,
                                                              mipc_decode_error_t *err) {
    if (len == 1 && mipc_filter_gnss_source_control_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_gnss_source_control_response_decode_read(data, len, out, err);
}

void mipc_filter_gnss_source_control_response_to_json(mipc_jw_t *w,
                                                      const mipc_filter_gnss_source_control_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "source");
    mipc_jw_u8(w, &in->source);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_gnss_source_control_response_from_json(mipc_jr_t *jr, size_t pos,
                                                       mipc_filter_gnss_source_control_response_t *out) {
    static const char *const keys[] = {"source"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "source", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"source\"");
    }
    {
        mipc_jr_push(jr, "source");
        if (mipc_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_external_gnss_update_t */

static int mipc_filter_external_gnss_update_read(mipc_reader_t *r, mipc_filter_external_gnss_update_t *out) {
    size_t i;
    mipc_rd_push(r, "gps_tow");
    if (mipc_rd_f64(r, &out->gps_tow)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "gps_week");
    if (mipc_rd_u16(r, &out->gps_week)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "latitude");
    if (mipc_rd_f64(r, &out->latitude)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "longitude");
    if (mipc_rd_f64(r, &out->longitude)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "height");
    if (mipc_rd_f64(r, &out->height)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "velocity");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->velocity[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "position_uncertainty");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->position_uncertainty[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "velocity_uncertainty");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->velocity_uncertainty[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_external_gnss_update_write(mipc_writer_t *w,
                                                            const mipc_filter_external_gnss_update_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_f64(w, &in->gps_tow)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->gps_week)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->latitude)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->longitude)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->height)) != MIPC_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->velocity[i])) != MIPC_OK) {
            return st;
        }
    }
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->position_uncertainty[i])) != MIPC_OK) {
            return st;
        }
    }
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->velocity_uncertainty[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_external_gnss_update_encode(const mipc_filter_external_gnss_update_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_external_gnss_update_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 70 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_external_gnss_update_load(const uint8_t *d, mipc_filter_external_gnss_update_t *out) {
    out->gps_tow = mipc_ld_f64(d + 0);
    out->gps_week = mipc_ld_u16(d + 8);
    out->latitude = mipc_ld_f64(d + 10);
    out->longitude = mipc_ld_f64(d + 18);
    out->height = mipc_ld_f64(d + 26);
    out->velocity[0] = mipc_ld_f32(d + 34);
    out->velocity[1] = mipc_ld_f32(d + 38);
    out->velocity[2] = mipc_ld_f32(d + 42);
    out->position_uncertainty[0] = mipc_ld_f32(d + 46);
    out->position_uncertainty[1] = mipc_ld_f32(d + 50);
    out->position_uncertainty[2] = mipc_ld_f32(d + 54);
    out->velocity_uncertainty[0] = mipc_ld_f32(d + 58);
    out->velocity_uncertainty[1] = mipc_ld_f32(d + 62);
    out->velocity_uncertainty[2] = mipc_ld_f32(d + 66);
    return 0;
}

/* The general reader: lengths other than 70, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_external_gnss_update_decode_read(
    const uint8_t *data, size_t len, mipc_filter_external_gnss_update_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_external_gnss_update_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_external_gnss_update_decode(const uint8_t *data, size_t len,
                                                      mipc_filter_external_gnss_update_t *out,
                                                      mipc_decode_error_t *err) {
    if (len == 70 && mipc_filter_external_gnss_update_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_external_gnss_update_decode_read(data, len, out, err);
}

void mipc_filter_external_gnss_update_to_json(mipc_jw_t *w, const mipc_filter_external_gnss_update_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "gps_tow");
    mipc_jw_f64(w, &in->gps_tow);
    mipc_jw_key(w, &first, "gps_week");
    mipc_jw_u16(w, &in->gps_week);
    mipc_jw_key(w, &first, "latitude");
    mipc_jw_f64(w, &in->latitude);
    mipc_jw_key(w, &first, "longitude");
    mipc_jw_f64(w, &in->longitude);
    mipc_jw_key(w, &first, "height");
    mipc_jw_f64(w, &in->height);
    mipc_jw_key(w, &first, "velocity");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->velocity[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "position_uncertainty");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->position_uncertainty[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "velocity_uncertainty");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->velocity_uncertainty[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_external_gnss_update_from_json(mipc_jr_t *jr, size_t pos,
                                               mipc_filter_external_gnss_update_t *out) {
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
    if (mipc_jr_object(jr, pos, keys, 8)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "gps_tow", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"gps_tow\"");
    }
    {
        mipc_jr_push(jr, "gps_tow");
        if (mipc_jr_f64(jr, vp, &out->gps_tow)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "gps_week", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"gps_week\"");
    }
    {
        mipc_jr_push(jr, "gps_week");
        if (mipc_jr_u16(jr, vp, &out->gps_week)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "latitude", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"latitude\"");
    }
    {
        mipc_jr_push(jr, "latitude");
        if (mipc_jr_f64(jr, vp, &out->latitude)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "longitude", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"longitude\"");
    }
    {
        mipc_jr_push(jr, "longitude");
        if (mipc_jr_f64(jr, vp, &out->longitude)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "height", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"height\"");
    }
    {
        mipc_jr_push(jr, "height");
        if (mipc_jr_f64(jr, vp, &out->height)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "velocity", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"velocity\"");
    }
    {
        mipc_jr_push(jr, "velocity");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->velocity[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "position_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"position_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "position_uncertainty");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->position_uncertainty[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "velocity_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"velocity_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "velocity_uncertainty");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->velocity_uncertainty[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_external_heading_update_t */

static int mipc_filter_external_heading_update_read(mipc_reader_t *r,
                                                    mipc_filter_external_heading_update_t *out) {
    mipc_rd_push(r, "heading");
    if (mipc_rd_f32(r, &out->heading)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "heading_uncertainty");
    if (mipc_rd_f32(r, &out->heading_uncertainty)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "type");
    if (mipc_rd_u8(r, &out->type)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_external_heading_update_write(mipc_writer_t *w, const mipc_filter_external_heading_update_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f32(w, &in->heading)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->heading_uncertainty)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->type)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_external_heading_update_encode(const mipc_filter_external_heading_update_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_external_heading_update_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 9 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_external_heading_update_load(const uint8_t *d,
                                                    mipc_filter_external_heading_update_t *out) {
    out->heading = mipc_ld_f32(d + 0);
    out->heading_uncertainty = mipc_ld_f32(d + 4);
    out->type = mipc_ld_u8(d + 8);
    return 0;
}

/* The general reader: lengths other than 9, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_external_heading_update_decode_read(
    const uint8_t *data, size_t len, mipc_filter_external_heading_update_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_external_heading_update_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_external_heading_update_decode(const uint8_t *data, size_t len,
                                                         mipc_filter_external_heading_update_t *out,
                                                         mipc_decode_error_t *err) {
    if (len == 9 && mipc_filter_external_heading_update_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_external_heading_update_decode_read(data, len, out, err);
}

void mipc_filter_external_heading_update_to_json(mipc_jw_t *w,
                                                 const mipc_filter_external_heading_update_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "heading");
    mipc_jw_f32(w, &in->heading);
    mipc_jw_key(w, &first, "heading_uncertainty");
    mipc_jw_f32(w, &in->heading_uncertainty);
    mipc_jw_key(w, &first, "type");
    mipc_jw_u8(w, &in->type);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_external_heading_update_from_json(mipc_jr_t *jr, size_t pos,
                                                  mipc_filter_external_heading_update_t *out) {
    static const char *const keys[] = {"heading", "heading_uncertainty", "type"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "heading", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"heading\"");
    }
    {
        mipc_jr_push(jr, "heading");
        if (mipc_jr_f32(jr, vp, &out->heading)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "heading_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"heading_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "heading_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->heading_uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "type", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"type\"");
    }
    {
        mipc_jr_push(jr, "type");
        if (mipc_jr_u8(jr, vp, &out->type)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_heading_update_control_t */

static int mipc_filter_heading_update_control_read(mipc_reader_t *r,
                                                   mipc_filter_heading_update_control_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_source = true;
        mipc_rd_push(r, "source");
        if (mipc_rd_u8(r, &out->source)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_heading_update_control_write(mipc_writer_t *w, const mipc_filter_heading_update_control_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_source) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->source)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_heading_update_control_encode(const mipc_filter_heading_update_control_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_heading_update_control_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_filter_heading_update_control_decode(const uint8_t *data, size_t len,
                                                        mipc_filter_heading_update_control_t *out,
                                                        mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_heading_update_control_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_heading_update_control_to_json(mipc_jw_t *w,
                                                const mipc_filter_heading_update_control_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_source) {
        mipc_jw_key(w, &first, "source");
        mipc_jw_u8(w, &in->source);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_heading_update_control_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_filter_heading_update_control_t *out) {
    static const char *const keys[] = {"function", "source"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "source", &vp);
    out->has_source = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"source\" given after an absent one");
    } else {
        mipc_jr_push(jr, "source");
        if (mipc_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_heading_update_control_response_t */

static int
mipc_filter_heading_update_control_response_read(mipc_reader_t *r,
                                                 mipc_filter_heading_update_control_response_t *out) {
    mipc_rd_push(r, "source");
    if (mipc_rd_u8(r, &out->source)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_heading_update_control_response_write(mipc_writer_t *w,
                                                  const mipc_filter_heading_update_control_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->source)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_heading_update_control_response_encode(const mipc_filter_heading_update_control_response_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_heading_update_control_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_filter_heading_update_control_response_load(const uint8_t *d,
                                                 mipc_filter_heading_update_control_response_t *out) {
    out->source = mipc_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_heading_update_control_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_heading_update_control_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_heading_update_control_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_heading_update_control_response_decode(const uint8_t *data, size_t len,
                                                   mipc_filter_heading_update_control_response_t *out,
                                                   mipc_decode_error_t *err) {
    if (len == 1 && mipc_filter_heading_update_control_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_heading_update_control_response_decode_read(data, len, out, err);
}

void mipc_filter_heading_update_control_response_to_json(
    mipc_jw_t *w, const mipc_filter_heading_update_control_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "source");
    mipc_jw_u8(w, &in->source);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_heading_update_control_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_heading_update_control_response_t *out) {
    static const char *const keys[] = {"source"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "source", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"source\"");
    }
    {
        mipc_jr_push(jr, "source");
        if (mipc_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_auto_init_control_t */

static int mipc_filter_auto_init_control_read(mipc_reader_t *r, mipc_filter_auto_init_control_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_enable = true;
        mipc_rd_push(r, "enable");
        if (mipc_rd_u8(r, &out->enable)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_auto_init_control_write(mipc_writer_t *w,
                                                         const mipc_filter_auto_init_control_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_enable) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->enable)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_auto_init_control_encode(const mipc_filter_auto_init_control_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_auto_init_control_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_filter_auto_init_control_decode(const uint8_t *data, size_t len,
                                                   mipc_filter_auto_init_control_t *out,
                                                   mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_auto_init_control_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_auto_init_control_to_json(mipc_jw_t *w, const mipc_filter_auto_init_control_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_enable) {
        mipc_jw_key(w, &first, "enable");
        mipc_jw_u8(w, &in->enable);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_auto_init_control_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_auto_init_control_t *out) {
    static const char *const keys[] = {"function", "enable"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "enable", &vp);
    out->has_enable = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"enable\" given after an absent one");
    } else {
        mipc_jr_push(jr, "enable");
        if (mipc_jr_u8(jr, vp, &out->enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_auto_init_control_response_t */

static int mipc_filter_auto_init_control_response_read(mipc_reader_t *r,
                                                       mipc_filter_auto_init_control_response_t *out) {
    mipc_rd_push(r, "enable");
    if (mipc_rd_u8(r, &out->enable)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_auto_init_control_response_write(mipc_writer_t *w,
                                             const mipc_filter_auto_init_control_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->enable)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_auto_init_control_response_encode(const mipc_filter_auto_init_control_response_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_auto_init_control_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_auto_init_control_response_load(const uint8_t *d,
                                                       mipc_filter_auto_init_control_response_t *out) {
    out->enable = mipc_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_auto_init_control_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_auto_init_control_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_auto_init_control_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_auto_init_control_response_decode(const uint8_t *data, size_t len,
                                                            mipc_filter_auto_init_control_response_t *out,
                                                            mipc_decode_error_t *err) {
    if (len == 1 && mipc_filter_auto_init_control_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_auto_init_control_response_decode_read(data, len, out, err);
}

void mipc_filter_auto_init_control_response_to_json(mipc_jw_t *w,
                                                    const mipc_filter_auto_init_control_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "enable");
    mipc_jw_u8(w, &in->enable);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_auto_init_control_response_from_json(mipc_jr_t *jr, size_t pos,
                                                     mipc_filter_auto_init_control_response_t *out) {
    static const char *const keys[] = {"enable"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "enable", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"enable\"");
    }
    {
        mipc_jr_push(jr, "enable");
        if (mipc_jr_u8(jr, vp, &out->enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_accel_noise_t */

static int mipc_filter_accel_noise_read(mipc_reader_t *r, mipc_filter_accel_noise_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_noise = true;
        mipc_rd_push(r, "noise");
        for (i = 0; i < 3; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->noise[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_accel_noise_write(mipc_writer_t *w, const mipc_filter_accel_noise_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_noise) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mipc_wr_f32(w, &in->noise[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_accel_noise_encode(const mipc_filter_accel_noise_t *value, uint8_t *buf, size_t cap,
                                             size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_accel_noise_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_filter_accel_noise_decode(const uint8_t *data, size_t len, mipc_filter_accel_noise_t *out,
                                             mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_accel_noise_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_accel_noise_to_json(mipc_jw_t *w, const mipc_filter_accel_noise_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_noise) {
        mipc_jw_key(w, &first, "noise");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->noise[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_accel_noise_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_accel_noise_t *out) {
    static const char *const keys[] = {"function", "noise"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "noise", &vp);
    out->has_noise = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"noise\" given after an absent one");
    } else {
        mipc_jr_push(jr, "noise");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->noise[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_accel_noise_response_t */

static int mipc_filter_accel_noise_response_read(mipc_reader_t *r, mipc_filter_accel_noise_response_t *out) {
    size_t i;
    mipc_rd_push(r, "noise");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->noise[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_accel_noise_response_write(mipc_writer_t *w,
                                                            const mipc_filter_accel_noise_response_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->noise[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_accel_noise_response_encode(const mipc_filter_accel_noise_response_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_accel_noise_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_accel_noise_response_load(const uint8_t *d, mipc_filter_accel_noise_response_t *out) {
    out->noise[0] = mipc_ld_f32(d + 0);
    out->noise[1] = mipc_ld_f32(d + 4);
    out->noise[2] = mipc_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_accel_noise_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_accel_noise_response_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_accel_noise_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_accel_noise_response_decode(const uint8_t *data, size_t len,
                                                      mipc_filter_accel_noise_response_t *out,
                                                      mipc_decode_error_t *err) {
    if (len == 12 && mipc_filter_accel_noise_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_accel_noise_response_decode_read(data, len, out, err);
}

void mipc_filter_accel_noise_response_to_json(mipc_jw_t *w, const mipc_filter_accel_noise_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "noise");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->noise[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_accel_noise_response_from_json(mipc_jr_t *jr, size_t pos,
                                               mipc_filter_accel_noise_response_t *out) {
    static const char *const keys[] = {"noise"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "noise", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"noise\"");
    }
    {
        mipc_jr_push(jr, "noise");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->noise[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_gyro_noise_t */

static int mipc_filter_gyro_noise_read(mipc_reader_t *r, mipc_filter_gyro_noise_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_noise = true;
        mipc_rd_push(r, "noise");
        for (i = 0; i < 3; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->noise[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_gyro_noise_write(mipc_writer_t *w, const mipc_filter_gyro_noise_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_noise) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mipc_wr_f32(w, &in->noise[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_gyro_noise_encode(const mipc_filter_gyro_noise_t *value, uint8_t *buf, size_t cap,
                                            size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_gyro_noise_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_filter_gyro_noise_decode(const uint8_t *data, size_t len, mipc_filter_gyro_noise_t *out,
                                            mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_gyro_noise_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_gyro_noise_to_json(mipc_jw_t *w, const mipc_filter_gyro_noise_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_noise) {
        mipc_jw_key(w, &first, "noise");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->noise[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_gyro_noise_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_gyro_noise_t *out) {
    static const char *const keys[] = {"function", "noise"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "noise", &vp);
    out->has_noise = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"noise\" given after an absent one");
    } else {
        mipc_jr_push(jr, "noise");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->noise[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_gyro_noise_response_t */

static int mipc_filter_gyro_noise_response_read(mipc_reader_t *r, mipc_filter_gyro_noise_response_t *out) {
    size_t i;
    mipc_rd_push(r, "noise");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->noise[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_gyro_noise_response_write(mipc_writer_t *w,
                                                           const mipc_filter_gyro_noise_response_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->noise[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_gyro_noise_response_encode(const mipc_filter_gyro_noise_response_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_gyro_noise_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_gyro_noise_response_load(const uint8_t *d, mipc_filter_gyro_noise_response_t *out) {
    out->noise[0] = mipc_ld_f32(d + 0);
    out->noise[1] = mipc_ld_f32(d + 4);
    out->noise[2] = mipc_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_gyro_noise_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_gyro_noise_response_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_gyro_noise_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_gyro_noise_response_decode(const uint8_t *data, size_t len,
                                                     mipc_filter_gyro_noise_response_t *out,
                                                     mipc_decode_error_t *err) {
    if (len == 12 && mipc_filter_gyro_noise_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_gyro_noise_response_decode_read(data, len, out, err);
}

void mipc_filter_gyro_noise_response_to_json(mipc_jw_t *w, const mipc_filter_gyro_noise_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "noise");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->noise[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_gyro_noise_response_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_filter_gyro_noise_response_t *out) {
    static const char *const keys[] = {"noise"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "noise", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"noise\"");
    }
    {
        mipc_jr_push(jr, "noise");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->noise[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_accel_bias_model_t */

static int mipc_filter_accel_bias_model_read(mipc_reader_t *r, mipc_filter_accel_bias_model_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_beta = true;
        mipc_rd_push(r, "beta");
        for (i = 0; i < 3; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->beta[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_noise = true;
        mipc_rd_push(r, "noise");
        for (i = 0; i < 3; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->noise[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_accel_bias_model_write(mipc_writer_t *w,
                                                        const mipc_filter_accel_bias_model_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_beta) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mipc_wr_f32(w, &in->beta[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    if (!in->has_noise) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mipc_wr_f32(w, &in->noise[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_accel_bias_model_encode(const mipc_filter_accel_bias_model_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_accel_bias_model_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_filter_accel_bias_model_decode(const uint8_t *data, size_t len,
                                                  mipc_filter_accel_bias_model_t *out,
                                                  mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_accel_bias_model_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_accel_bias_model_to_json(mipc_jw_t *w, const mipc_filter_accel_bias_model_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_beta) {
        mipc_jw_key(w, &first, "beta");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->beta[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    if (in->has_noise) {
        mipc_jw_key(w, &first, "noise");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->noise[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_accel_bias_model_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_accel_bias_model_t *out) {
    static const char *const keys[] = {"function", "beta", "noise"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "beta", &vp);
    out->has_beta = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"beta\" given after an absent one");
    } else {
        mipc_jr_push(jr, "beta");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->beta[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "noise", &vp);
    out->has_noise = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"noise\" given after an absent one");
    } else {
        mipc_jr_push(jr, "noise");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->noise[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_accel_bias_model_response_t */

static int mipc_filter_accel_bias_model_response_read(mipc_reader_t *r,
                                                      mipc_filter_accel_bias_model_response_t *out) {
    size_t i;
    mipc_rd_push(r, "beta");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->beta[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "noise");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->noise[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_accel_bias_model_response_write(mipc_writer_t *w,
                                            const mipc_filter_accel_bias_model_response_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->beta[i])) != MIPC_OK) {
            return st;
        }
    }
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->noise[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_accel_bias_model_response_encode(const mipc_filter_accel_bias_model_response_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_accel_bias_model_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 24 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_accel_bias_model_response_load(const uint8_t *d,
                                                      mipc_filter_accel_bias_model_response_t *out) {
    out->beta[0] = mipc_ld_f32(d + 0);
    out->beta[1] = mipc_ld_f32(d + 4);
    out->beta[2] = mipc_ld_f32(d + 8);
    out->noise[0] = mipc_ld_f32(d + 12);
    out->noise[1] = mipc_ld_f32(d + 16);
    out->noise[2] = mipc_ld_f32(d + 20);
    return 0;
}

/* The general reader: lengths other than 24, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_accel_bias_model_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_accel_bias_model_response_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_accel_bias_model_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_accel_bias_model_response_decode(const uint8_t *data, size_t len,
                                                           mipc_filter_accel_bias_model_response_t *out,
                                                           mipc_decode_error_t *err) {
    if (len == 24 && mipc_filter_accel_bias_model_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_accel_bias_model_response_decode_read(data, len, out, err);
}

void mipc_filter_accel_bias_model_response_to_json(mipc_jw_t *w,
                                                   const mipc_filter_accel_bias_model_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "beta");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->beta[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "noise");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->noise[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_accel_bias_model_response_from_json(mipc_jr_t *jr, size_t pos,
                                                    mipc_filter_accel_bias_model_response_t *out) {
    static const char *const keys[] = {"beta", "noise"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "beta", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"beta\"");
    }
    {
        mipc_jr_push(jr, "beta");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->beta[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "noise", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"noise\"");
    }
    {
        mipc_jr_push(jr, "noise");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->noise[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_gyro_bias_model_t */

static int mipc_filter_gyro_bias_model_read(mipc_reader_t *r, mipc_filter_gyro_bias_model_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_beta = true;
        mipc_rd_push(r, "beta");
        for (i = 0; i < 3; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->beta[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_noise = true;
        mipc_rd_push(r, "noise");
        for (i = 0; i < 3; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->noise[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_gyro_bias_model_write(mipc_writer_t *w,
                                                       const mipc_filter_gyro_bias_model_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_beta) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mipc_wr_f32(w, &in->beta[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    if (!in->has_noise) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mipc_wr_f32(w, &in->noise[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_gyro_bias_model_encode(const mipc_filter_gyro_bias_model_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_gyro_bias_model_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_filter_gyro_bias_model_decode(const uint8_t *data, size_t len,
                                                 mipc_filter_gyro_bias_model_t *out,
                                                 mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_gyro_bias_model_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_gyro_bias_model_to_json(mipc_jw_t *w, const mipc_filter_gyro_bias_model_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_beta) {
        mipc_jw_key(w, &first, "beta");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->beta[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    if (in->has_noise) {
        mipc_jw_key(w, &first, "noise");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->noise[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_gyro_bias_model_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_gyro_bias_model_t *out) {
    static const char *const keys[] = {"function", "beta", "noise"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "beta", &vp);
    out->has_beta = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"beta\" given after an absent one");
    } else {
        mipc_jr_push(jr, "beta");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->beta[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "noise", &vp);
    out->has_noise = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"noise\" given after an absent one");
    } else {
        mipc_jr_push(jr, "noise");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->noise[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_gyro_bias_model_response_t */

static int mipc_filter_gyro_bias_model_response_read(mipc_reader_t *r,
                                                     mipc_filter_gyro_bias_model_response_t *out) {
    size_t i;
    mipc_rd_push(r, "beta");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->beta[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "noise");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->noise[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_gyro_bias_model_response_write(mipc_writer_t *w,
                                           const mipc_filter_gyro_bias_model_response_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->beta[i])) != MIPC_OK) {
            return st;
        }
    }
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->noise[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_gyro_bias_model_response_encode(const mipc_filter_gyro_bias_model_response_t *value,
                                                          uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_gyro_bias_model_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 24 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_gyro_bias_model_response_load(const uint8_t *d,
                                                     mipc_filter_gyro_bias_model_response_t *out) {
    out->beta[0] = mipc_ld_f32(d + 0);
    out->beta[1] = mipc_ld_f32(d + 4);
    out->beta[2] = mipc_ld_f32(d + 8);
    out->noise[0] = mipc_ld_f32(d + 12);
    out->noise[1] = mipc_ld_f32(d + 16);
    out->noise[2] = mipc_ld_f32(d + 20);
    return 0;
}

/* The general reader: lengths other than 24, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_gyro_bias_model_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_gyro_bias_model_response_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_gyro_bias_model_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_gyro_bias_model_response_decode(const uint8_t *data, size_t len,
                                                          mipc_filter_gyro_bias_model_response_t *out,
                                                          mipc_decode_error_t *err) {
    if (len == 24 && mipc_filter_gyro_bias_model_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_gyro_bias_model_response_decode_read(data, len, out, err);
}

void mipc_filter_gyro_bias_model_response_to_json(mipc_jw_t *w,
                                                  const mipc_filter_gyro_bias_model_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "beta");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->beta[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "noise");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->noise[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_gyro_bias_model_response_from_json(mipc_jr_t *jr, size_t pos,
                                                   mipc_filter_gyro_bias_model_response_t *out) {
    static const char *const keys[] = {"beta", "noise"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "beta", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"beta\"");
    }
    {
        mipc_jr_push(jr, "beta");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->beta[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "noise", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"noise\"");
    }
    {
        mipc_jr_push(jr, "noise");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->noise[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_zupt_control_t */

static int mipc_filter_zupt_control_read(mipc_reader_t *r, mipc_filter_zupt_control_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_enable = true;
        mipc_rd_push(r, "enable");
        if (mipc_rd_u8(r, &out->enable)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_threshold = true;
        mipc_rd_push(r, "threshold");
        if (mipc_rd_f32(r, &out->threshold)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_zupt_control_write(mipc_writer_t *w, const mipc_filter_zupt_control_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_enable) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->enable)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_threshold) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->threshold)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_zupt_control_encode(const mipc_filter_zupt_control_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_zupt_control_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_filter_zupt_control_decode(const uint8_t *data, size_t len,
                                              mipc_filter_zupt_control_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_zupt_control_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_zupt_control_to_json(mipc_jw_t *w, const mipc_filter_zupt_control_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_enable) {
        mipc_jw_key(w, &first, "enable");
        mipc_jw_u8(w, &in->enable);
    }
    if (in->has_threshold) {
        mipc_jw_key(w, &first, "threshold");
        mipc_jw_f32(w, &in->threshold);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_zupt_control_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_zupt_control_t *out) {
    static const char *const keys[] = {"function", "enable", "threshold"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "enable", &vp);
    out->has_enable = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"enable\" given after an absent one");
    } else {
        mipc_jr_push(jr, "enable");
        if (mipc_jr_u8(jr, vp, &out->enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "threshold", &vp);
    out->has_threshold = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"threshold\" given after an absent one");
    } else {
        mipc_jr_push(jr, "threshold");
        if (mipc_jr_f32(jr, vp, &out->threshold)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_zupt_control_response_t */

static int mipc_filter_zupt_control_response_read(mipc_reader_t *r,
                                                  mipc_filter_zupt_control_response_t *out) {
    mipc_rd_push(r, "enable");
    if (mipc_rd_u8(r, &out->enable)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "threshold");
    if (mipc_rd_f32(r, &out->threshold)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_zupt_control_response_write(mipc_writer_t *w,
                                                             const mipc_filter_zupt_control_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->enable)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->threshold)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_zupt_control_response_encode(const mipc_filter_zupt_control_response_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_zupt_control_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 5 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_zupt_control_response_load(const uint8_t *d,
                                                  mipc_filter_zupt_control_response_t *out) {
    out->enable = mipc_ld_u8(d + 0);
    out->threshold = mipc_ld_f32(d + 1);
    return 0;
}

/* The general reader: lengths other than 5, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_zupt_control_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_zupt_control_response_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_zupt_control_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_zupt_control_response_decode(const uint8_t *data, size_t len,
                                                       mipc_filter_zupt_control_response_t *out,
                                                       mipc_decode_error_t *err) {
    if (len == 5 && mipc_filter_zupt_control_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_zupt_control_response_decode_read(data, len, out, err);
}

void mipc_filter_zupt_control_response_to_json(mipc_jw_t *w, const mipc_filter_zupt_control_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "enable");
    mipc_jw_u8(w, &in->enable);
    mipc_jw_key(w, &first, "threshold");
    mipc_jw_f32(w, &in->threshold);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_zupt_control_response_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_filter_zupt_control_response_t *out) {
    static const char *const keys[] = {"enable", "threshold"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "enable", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"enable\"");
    }
    {
        mipc_jr_push(jr, "enable");
        if (mipc_jr_u8(jr, vp, &out->enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "threshold", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"threshold\"");
    }
    {
        mipc_jr_push(jr, "threshold");
        if (mipc_jr_f32(jr, vp, &out->threshold)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_external_heading_update_with_time_t */

static int
mipc_filter_external_heading_update_with_time_read(mipc_reader_t *r,
                                                   mipc_filter_external_heading_update_with_time_t *out) {
    mipc_rd_push(r, "gps_tow");
    if (mipc_rd_f64(r, &out->gps_tow)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "gps_week");
    if (mipc_rd_u16(r, &out->gps_week)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "heading");
    if (mipc_rd_f32(r, &out->heading)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "heading_uncertainty");
    if (mipc_rd_f32(r, &out->heading_uncertainty)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "type");
    if (mipc_rd_u8(r, &out->type)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_external_heading_update_with_time_write(
    mipc_writer_t *w, const mipc_filter_external_heading_update_with_time_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f64(w, &in->gps_tow)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->gps_week)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->heading)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->heading_uncertainty)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->type)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_external_heading_update_with_time_encode(
    const mipc_filter_external_heading_update_with_time_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_external_heading_update_with_time_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 19 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_filter_external_heading_update_with_time_load(const uint8_t *d,
                                                   mipc_filter_external_heading_update_with_time_t *out) {
    out->gps_tow = mipc_ld_f64(d + 0);
    out->gps_week = mipc_ld_u16(d + 8);
    out->heading = mipc_ld_f32(d + 10);
    out->heading_uncertainty = mipc_ld_f32(d + 14);
    out->type = mipc_ld_u8(d + 18);
    return 0;
}

/* The general reader: lengths other than 19, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_external_heading_update_with_time_decode_read(
    const uint8_t *data, size_t len, mipc_filter_external_heading_update_with_time_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_external_heading_update_with_time_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_external_heading_update_with_time_decode(const uint8_t *data, size_t len,
                                                     mipc_filter_external_heading_update_with_time_t *out,
                                                     mipc_decode_error_t *err) {
    if (len == 19 && mipc_filter_external_heading_update_with_time_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_external_heading_update_with_time_decode_read(data, len, out, err);
}

void mipc_filter_external_heading_update_with_time_to_json(
    mipc_jw_t *w, const mipc_filter_external_heading_update_with_time_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "gps_tow");
    mipc_jw_f64(w, &in->gps_tow);
    mipc_jw_key(w, &first, "gps_week");
    mipc_jw_u16(w, &in->gps_week);
    mipc_jw_key(w, &first, "heading");
    mipc_jw_f32(w, &in->heading);
    mipc_jw_key(w, &first, "heading_uncertainty");
    mipc_jw_f32(w, &in->heading_uncertainty);
    mipc_jw_key(w, &first, "type");
    mipc_jw_u8(w, &in->type);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_external_heading_update_with_time_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_external_heading_update_with_time_t *out) {
    static const char *const keys[] = {"gps_tow", "gps_week", "heading", "heading_uncertainty", "type"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "gps_tow", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"gps_tow\"");
    }
    {
        mipc_jr_push(jr, "gps_tow");
        if (mipc_jr_f64(jr, vp, &out->gps_tow)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "gps_week", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"gps_week\"");
    }
    {
        mipc_jr_push(jr, "gps_week");
        if (mipc_jr_u16(jr, vp, &out->gps_week)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "heading", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"heading\"");
    }
    {
        mipc_jr_push(jr, "heading");
        if (mipc_jr_f32(jr, vp, &out->heading)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "heading_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"heading_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "heading_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->heading_uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "type", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"type\"");
    }
    {
        mipc_jr_push(jr, "type");
        if (mipc_jr_u8(jr, vp, &out->type)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_zero_angular_rate_update_control_t */

static int
mipc_filter_zero_angular_rate_update_control_read(mipc_reader_t *r,
                                                  mipc_filter_zero_angular_rate_update_control_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_enable = true;
        mipc_rd_push(r, "enable");
        if (mipc_rd_u8(r, &out->enable)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_threshold = true;
        mipc_rd_push(r, "threshold");
        if (mipc_rd_f32(r, &out->threshold)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_zero_angular_rate_update_control_write(mipc_writer_t *w,
                                                   const mipc_filter_zero_angular_rate_update_control_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_enable) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->enable)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_threshold) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->threshold)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_zero_angular_rate_update_control_encode(
    const mipc_filter_zero_angular_rate_update_control_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_zero_angular_rate_update_control_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t
mipc_filter_zero_angular_rate_update_control_decode(const uint8_t *data, size_t len,
                                                    mipc_filter_zero_angular_rate_update_control_t *out,
                                                    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_zero_angular_rate_update_control_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_zero_angular_rate_update_control_to_json(
    mipc_jw_t *w, const mipc_filter_zero_angular_rate_update_control_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_enable) {
        mipc_jw_key(w, &first, "enable");
        mipc_jw_u8(w, &in->enable);
    }
    if (in->has_threshold) {
        mipc_jw_key(w, &first, "threshold");
        mipc_jw_f32(w, &in->threshold);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_zero_angular_rate_update_control_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_zero_angular_rate_update_control_t *out) {
    static const char *const keys[] = {"function", "enable", "threshold"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "enable", &vp);
    out->has_enable = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"enable\" given after an absent one");
    } else {
        mipc_jr_push(jr, "enable");
        if (mipc_jr_u8(jr, vp, &out->enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "threshold", &vp);
    out->has_threshold = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"threshold\" given after an absent one");
    } else {
        mipc_jr_push(jr, "threshold");
        if (mipc_jr_f32(jr, vp, &out->threshold)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_zero_angular_rate_update_control_response_t */

static int mipc_filter_zero_angular_rate_update_control_response_read(
    mipc_reader_t *r, mipc_filter_zero_angular_rate_update_control_response_t *out) {
    mipc_rd_push(r, "enable");
    if (mipc_rd_u8(r, &out->enable)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "threshold");
    if (mipc_rd_f32(r, &out->threshold)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_zero_angular_rate_update_control_response_write(
    mipc_writer_t *w, const mipc_filter_zero_angular_rate_update_control_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->enable)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->threshold)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_zero_angular_rate_update_control_response_encode(
    const mipc_filter_zero_angular_rate_update_control_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_zero_angular_rate_update_control_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 5 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_zero_angular_rate_update_control_response_load(
    const uint8_t *d, mipc_filter_zero_angular_rate_update_control_response_t *out) {
    out->enable = mipc_ld_u8(d + 0);
    out->threshold = mipc_ld_f32(d + 1);
    return 0;
}

/* The general reader: lengths other than 5, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_zero_angular_rate_update_control_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_zero_angular_rate_update_control_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_zero_angular_rate_update_control_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_zero_angular_rate_update_control_response_decode(
    const uint8_t *data, size_t len, mipc_filter_zero_angular_rate_update_control_response_t *out,
    mipc_decode_error_t *err) {
    if (len == 5 && mipc_filter_zero_angular_rate_update_control_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_zero_angular_rate_update_control_response_decode_read(data, len, out, err);
}

void mipc_filter_zero_angular_rate_update_control_response_to_json(
    mipc_jw_t *w, const mipc_filter_zero_angular_rate_update_control_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "enable");
    mipc_jw_u8(w, &in->enable);
    mipc_jw_key(w, &first, "threshold");
    mipc_jw_f32(w, &in->threshold);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_zero_angular_rate_update_control_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_zero_angular_rate_update_control_response_t *out) {
    static const char *const keys[] = {"enable", "threshold"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "enable", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"enable\"");
    }
    {
        mipc_jr_push(jr, "enable");
        if (mipc_jr_u8(jr, vp, &out->enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "threshold", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"threshold\"");
    }
    {
        mipc_jr_push(jr, "threshold");
        if (mipc_jr_f32(jr, vp, &out->threshold)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_tare_orientation_t */

static int mipc_filter_tare_orientation_read(mipc_reader_t *r, mipc_filter_tare_orientation_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_axes = true;
        mipc_rd_push(r, "axes");
        if (mipc_rd_u8(r, &out->axes)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_tare_orientation_write(mipc_writer_t *w,
                                                        const mipc_filter_tare_orientation_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_axes) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->axes)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_tare_orientation_encode(const mipc_filter_tare_orientation_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_tare_orientation_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_filter_tare_orientation_decode(const uint8_t *data, size_t len,
                                                  mipc_filter_tare_orientation_t *out,
                                                  mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_tare_orientation_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_tare_orientation_to_json(mipc_jw_t *w, const mipc_filter_tare_orientation_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_axes) {
        mipc_jw_key(w, &first, "axes");
        mipc_jw_u8(w, &in->axes);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_tare_orientation_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_tare_orientation_t *out) {
    static const char *const keys[] = {"function", "axes"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "axes", &vp);
    out->has_axes = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"axes\" given after an absent one");
    } else {
        mipc_jr_push(jr, "axes");
        if (mipc_jr_u8(jr, vp, &out->axes)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_commanded_zupt_t */

static int mipc_filter_commanded_zupt_read(mipc_reader_t *r, mipc_filter_commanded_zupt_t *out) {
    (void)out;
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_commanded_zupt_write(mipc_writer_t *w,
                                                      const mipc_filter_commanded_zupt_t *in) {
    (void)w;
    (void)in;
    return MIPC_OK;
}

mipc_status_t mipc_filter_commanded_zupt_encode(const mipc_filter_commanded_zupt_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_commanded_zupt_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_filter_commanded_zupt_decode(const uint8_t *data, size_t len,
                                                mipc_filter_commanded_zupt_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_commanded_zupt_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_commanded_zupt_to_json(mipc_jw_t *w, const mipc_filter_commanded_zupt_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mipc_filter_commanded_zupt_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_commanded_zupt_t *out) {
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mipc_filter_commanded_zero_angular_rate_update_t */

static int
mipc_filter_commanded_zero_angular_rate_update_read(mipc_reader_t *r,
                                                    mipc_filter_commanded_zero_angular_rate_update_t *out) {
    (void)out;
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_commanded_zero_angular_rate_update_write(
    mipc_writer_t *w, const mipc_filter_commanded_zero_angular_rate_update_t *in) {
    (void)w;
    (void)in;
    return MIPC_OK;
}

mipc_status_t mipc_filter_commanded_zero_angular_rate_update_encode(
    const mipc_filter_commanded_zero_angular_rate_update_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_commanded_zero_angular_rate_update_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t
mipc_filter_commanded_zero_angular_rate_update_decode(const uint8_t *data, size_t len,
                                                      mipc_filter_commanded_zero_angular_rate_update_t *out,
                                                      mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_commanded_zero_angular_rate_update_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_commanded_zero_angular_rate_update_to_json(
    mipc_jw_t *w, const mipc_filter_commanded_zero_angular_rate_update_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mipc_filter_commanded_zero_angular_rate_update_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_commanded_zero_angular_rate_update_t *out) {
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mipc_filter_mag_capture_auto_calibration_t */

static int mipc_filter_mag_capture_auto_calibration_read(mipc_reader_t *r,
                                                         mipc_filter_mag_capture_auto_calibration_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_mag_capture_auto_calibration_write(mipc_writer_t *w,
                                               const mipc_filter_mag_capture_auto_calibration_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_mag_capture_auto_calibration_encode(const mipc_filter_mag_capture_auto_calibration_t *value,
                                                uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_mag_capture_auto_calibration_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_mag_capture_auto_calibration_load(const uint8_t *d,
                                                         mipc_filter_mag_capture_auto_calibration_t *out) {
    out->function = mipc_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_mag_capture_auto_calibration_decode_read(
    const uint8_t *data, size_t len, mipc_filter_mag_capture_auto_calibration_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_mag_capture_auto_calibration_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_mag_capture_auto_calibration_decode(const uint8_t *data, size_t len,
                                                              mipc_filter_mag_capture_auto_calibration_t *out,
                                                              mipc_decode_error_t *err) {
    if (len == 1 && mipc_filter_mag_capture_auto_calibration_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_mag_capture_auto_calibration_decode_read(data, len, out, err);
}

void mipc_filter_mag_capture_auto_calibration_to_json(mipc_jw_t *w,
                                                      const mipc_filter_mag_capture_auto_calibration_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_mag_capture_auto_calibration_from_json(mipc_jr_t *jr, size_t pos,
                                                       mipc_filter_mag_capture_auto_calibration_t *out) {
    static const char *const keys[] = {"function"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_gravity_noise_std_dev_t */

static int mipc_filter_gravity_noise_std_dev_read(mipc_reader_t *r,
                                                  mipc_filter_gravity_noise_std_dev_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_noise = true;
        mipc_rd_push(r, "noise");
        for (i = 0; i < 3; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->noise[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_gravity_noise_std_dev_write(mipc_writer_t *w,
                                                             const mipc_filter_gravity_noise_std_dev_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_noise) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mipc_wr_f32(w, &in->noise[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_gravity_noise_std_dev_encode(const mipc_filter_gravity_noise_std_dev_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_gravity_noise_std_dev_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_filter_gravity_noise_std_dev_decode(const uint8_t *data, size_t len,
                                                       mipc_filter_gravity_noise_std_dev_t *out,
                                                       mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_gravity_noise_std_dev_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_gravity_noise_std_dev_to_json(mipc_jw_t *w, const mipc_filter_gravity_noise_std_dev_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_noise) {
        mipc_jw_key(w, &first, "noise");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->noise[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_gravity_noise_std_dev_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_filter_gravity_noise_std_dev_t *out) {
    static const char *const keys[] = {"function", "noise"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "noise", &vp);
    out->has_noise = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"noise\" given after an absent one");
    } else {
        mipc_jr_push(jr, "noise");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->noise[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_gravity_noise_std_dev_response_t */

static int
mipc_filter_gravity_noise_std_dev_response_read(mipc_reader_t *r,
                                                mipc_filter_gravity_noise_std_dev_response_t *out) {
    size_t i;
    mipc_rd_push(r, "noise");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->noise[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_gravity_noise_std_dev_response_write(mipc_writer_t *w,
                                                 const mipc_filter_gravity_noise_std_dev_response_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->noise[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_gravity_noise_std_dev_response_encode(const mipc_filter_gravity_noise_std_dev_response_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_gravity_noise_std_dev_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_filter_gravity_noise_std_dev_response_load(const uint8_t *d,
                                                mipc_filter_gravity_noise_std_dev_response_t *out) {
    out->noise[0] = mipc_ld_f32(d + 0);
    out->noise[1] = mipc_ld_f32(d + 4);
    out->noise[2] = mipc_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_gravity_noise_std_dev_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_gravity_noise_std_dev_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_gravity_noise_std_dev_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_gravity_noise_std_dev_response_decode(const uint8_t *data, size_t len,
                                                  mipc_filter_gravity_noise_std_dev_response_t *out,
                                                  mipc_decode_error_t *err) {
    if (len == 12 && mipc_filter_gravity_noise_std_dev_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_gravity_noise_std_dev_response_decode_read(data, len, out, err);
}

void mipc_filter_gravity_noise_std_dev_response_to_json(
    mipc_jw_t *w, const mipc_filter_gravity_noise_std_dev_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "noise");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->noise[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_gravity_noise_std_dev_response_from_json(mipc_jr_t *jr, size_t pos,
                                                         mipc_filter_gravity_noise_std_dev_response_t *out) {
    static const char *const keys[] = {"noise"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "noise", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"noise\"");
    }
    {
        mipc_jr_push(jr, "noise");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->noise[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_pressure_altitude_noise_std_dev_t */

static int
mipc_filter_pressure_altitude_noise_std_dev_read(mipc_reader_t *r,
                                                 mipc_filter_pressure_altitude_noise_std_dev_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_noise = true;
        mipc_rd_push(r, "noise");
        if (mipc_rd_f32(r, &out->noise)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_pressure_altitude_noise_std_dev_write(mipc_writer_t *w,
                                                  const mipc_filter_pressure_altitude_noise_std_dev_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_noise) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->noise)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_pressure_altitude_noise_std_dev_encode(const mipc_filter_pressure_altitude_noise_std_dev_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_pressure_altitude_noise_std_dev_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t
mipc_filter_pressure_altitude_noise_std_dev_decode(const uint8_t *data, size_t len,
                                                   mipc_filter_pressure_altitude_noise_std_dev_t *out,
                                                   mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_pressure_altitude_noise_std_dev_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_pressure_altitude_noise_std_dev_to_json(
    mipc_jw_t *w, const mipc_filter_pressure_altitude_noise_std_dev_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_noise) {
        mipc_jw_key(w, &first, "noise");
        mipc_jw_f32(w, &in->noise);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_pressure_altitude_noise_std_dev_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_pressure_altitude_noise_std_dev_t *out) {
    static const char *const keys[] = {"function", "noise"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "noise", &vp);
    out->has_noise = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"noise\" given after an absent one");
    } else {
        mipc_jr_push(jr, "noise");
        if (mipc_jr_f32(jr, vp, &out->noise)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_pressure_altitude_noise_std_dev_response_t */

static int mipc_filter_pressure_altitude_noise_std_dev_response_read(
    mipc_reader_t *r, mipc_filter_pressure_altitude_noise_std_dev_response_t *out) {
    mipc_rd_push(r, "noise");
    if (mipc_rd_f32(r, &out->noise)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_pressure_altitude_noise_std_dev_response_write(
    mipc_writer_t *w, const mipc_filter_pressure_altitude_noise_std_dev_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f32(w, &in->noise)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_pressure_altitude_noise_std_dev_response_encode(
    const mipc_filter_pressure_altitude_noise_std_dev_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_pressure_altitude_noise_std_dev_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 4 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_pressure_altitude_noise_std_dev_response_load(
    const uint8_t *d, mipc_filter_pressure_altitude_noise_std_dev_response_t *out) {
    out->noise = mipc_ld_f32(d + 0);
    return 0;
}

/* The general reader: lengths other than 4, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_pressure_altitude_noise_std_dev_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_pressure_altitude_noise_std_dev_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_pressure_altitude_noise_std_dev_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_pressure_altitude_noise_std_dev_response_decode(
    const uint8_t *data, size_t len, mipc_filter_pressure_altitude_noise_std_dev_response_t *out,
    mipc_decode_error_t *err) {
    if (len == 4 && mipc_filter_pressure_altitude_noise_std_dev_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_pressure_altitude_noise_std_dev_response_decode_read(data, len, out, err);
}

void mipc_filter_pressure_altitude_noise_std_dev_response_to_json(
    mipc_jw_t *w, const mipc_filter_pressure_altitude_noise_std_dev_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "noise");
    mipc_jw_f32(w, &in->noise);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_pressure_altitude_noise_std_dev_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_pressure_altitude_noise_std_dev_response_t *out) {
    static const char *const keys[] = {"noise"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "noise", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"noise\"");
    }
    {
        mipc_jr_push(jr, "noise");
        if (mipc_jr_f32(jr, vp, &out->noise)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_hard_iron_offset_noise_t */

static int mipc_filter_hard_iron_offset_noise_read(mipc_reader_t *r,
                                                   mipc_filter_hard_iron_offset_noise_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_noise = true;
        mipc_rd_push(r, "noise");
        for (i = 0; i < 3; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->noise[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_hard_iron_offset_noise_write(mipc_writer_t *w, const mipc_filter_hard_iron_offset_noise_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_noise) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mipc_wr_f32(w, &in->noise[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_hard_iron_offset_noise_encode(const mipc_filter_hard_iron_offset_noise_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_hard_iron_offset_noise_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_filter_hard_iron_offset_noise_decode(const uint8_t *data, size_t len,
                                                        mipc_filter_hard_iron_offset_noise_t *out,
                                                        mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_hard_iron_offset_noise_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_hard_iron_offset_noise_to_json(mipc_jw_t *w,
                                                const mipc_filter_hard_iron_offset_noise_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_noise) {
        mipc_jw_key(w, &first, "noise");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->noise[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_hard_iron_offset_noise_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_filter_hard_iron_offset_noise_t *out) {
    static const char *const keys[] = {"function", "noise"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "noise", &vp);
    out->has_noise = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"noise\" given after an absent one");
    } else {
        mipc_jr_push(jr, "noise");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->noise[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_hard_iron_offset_noise_response_t */

static int
mipc_filter_hard_iron_offset_noise_response_read(mipc_reader_t *r,
                                                 mipc_filter_hard_iron_offset_noise_response_t *out) {
    size_t i;
    mipc_rd_push(r, "noise");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->noise[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_hard_iron_offset_noise_response_write(mipc_writer_t *w,
                                                  const mipc_filter_hard_iron_offset_noise_response_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->noise[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_hard_iron_offset_noise_response_encode(const mipc_filter_hard_iron_offset_noise_response_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_hard_iron_offset_noise_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_filter_hard_iron_offset_noise_response_load(const uint8_t *d,
                                                 mipc_filter_hard_iron_offset_noise_response_t *out) {
    out->noise[0] = mipc_ld_f32(d + 0);
    out->noise[1] = mipc_ld_f32(d + 4);
    out->noise[2] = mipc_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_hard_iron_offset_noise_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_hard_iron_offset_noise_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_hard_iron_offset_noise_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_hard_iron_offset_noise_response_decode(const uint8_t *data, size_t len,
                                                   mipc_filter_hard_iron_offset_noise_response_t *out,
                                                   mipc_decode_error_t *err) {
    if (len == 12 && mipc_filter_hard_iron_offset_noise_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_hard_iron_offset_noise_response_decode_read(data, len, out, err);
}

void mipc_filter_hard_iron_offset_noise_response_to_json(
    mipc_jw_t *w, const mipc_filter_hard_iron_offset_noise_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "noise");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->noise[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_hard_iron_offset_noise_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_hard_iron_offset_noise_response_t *out) {
    static const char *const keys[] = {"noise"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "noise", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"noise\"");
    }
    {
        mipc_jr_push(jr, "noise");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->noise[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_soft_iron_matrix_noise_t */

static int mipc_filter_soft_iron_matrix_noise_read(mipc_reader_t *r,
                                                   mipc_filter_soft_iron_matrix_noise_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_noise = true;
        mipc_rd_push(r, "noise");
        for (i = 0; i < 9; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->noise[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_soft_iron_matrix_noise_write(mipc_writer_t *w, const mipc_filter_soft_iron_matrix_noise_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_noise) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 9; i++) {
            if ((st = mipc_wr_f32(w, &in->noise[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_soft_iron_matrix_noise_encode(const mipc_filter_soft_iron_matrix_noise_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_soft_iron_matrix_noise_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_filter_soft_iron_matrix_noise_decode(const uint8_t *data, size_t len,
                                                        mipc_filter_soft_iron_matrix_noise_t *out,
                                                        mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_soft_iron_matrix_noise_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_soft_iron_matrix_noise_to_json(mipc_jw_t *w,
                                                const mipc_filter_soft_iron_matrix_noise_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_noise) {
        mipc_jw_key(w, &first, "noise");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 9; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->noise[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_soft_iron_matrix_noise_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_filter_soft_iron_matrix_noise_t *out) {
    static const char *const keys[] = {"function", "noise"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "noise", &vp);
    out->has_noise = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"noise\" given after an absent one");
    } else {
        mipc_jr_push(jr, "noise");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 9) {
                return mipc_jr_fail(jr, "more than 9 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->noise[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 9) {
            return mipc_jr_fail(jr, "expected 9 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_soft_iron_matrix_noise_response_t */

static int
mipc_filter_soft_iron_matrix_noise_response_read(mipc_reader_t *r,
                                                 mipc_filter_soft_iron_matrix_noise_response_t *out) {
    size_t i;
    mipc_rd_push(r, "noise");
    for (i = 0; i < 9; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->noise[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_soft_iron_matrix_noise_response_write(mipc_writer_t *w,
                                                  const mipc_filter_soft_iron_matrix_noise_response_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 9; i++) {
        if ((st = mipc_wr_f32(w, &in->noise[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_soft_iron_matrix_noise_response_encode(const mipc_filter_soft_iron_matrix_noise_response_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_soft_iron_matrix_noise_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 36 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_filter_soft_iron_matrix_noise_response_load(const uint8_t *d,
                                                 mipc_filter_soft_iron_matrix_noise_response_t *out) {
    out->noise[0] = mipc_ld_f32(d + 0);
    out->noise[1] = mipc_ld_f32(d + 4);
    out->noise[2] = mipc_ld_f32(d + 8);
    out->noise[3] = mipc_ld_f32(d + 12);
    out->noise[4] = mipc_ld_f32(d + 16);
    out->noise[5] = mipc_ld_f32(d + 20);
    out->noise[6] = mipc_ld_f32(d + 24);
    out->noise[7] = mipc_ld_f32(d + 28);
    out->noise[8] = mipc_ld_f32(d + 32);
    return 0;
}

/* The general reader: lengths other than 36, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_soft_iron_matrix_noise_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_soft_iron_matrix_noise_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_soft_iron_matrix_noise_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_soft_iron_matrix_noise_response_decode(const uint8_t *data, size_t len,
                                                   mipc_filter_soft_iron_matrix_noise_response_t *out,
                                                   mipc_decode_error_t *err) {
    if (len == 36 && mipc_filter_soft_iron_matrix_noise_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_soft_iron_matrix_noise_response_decode_read(data, len, out, err);
}

void mipc_filter_soft_iron_matrix_noise_response_to_json(
    mipc_jw_t *w, const mipc_filter_soft_iron_matrix_noise_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "noise");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 9; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->noise[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_soft_iron_matrix_noise_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_soft_iron_matrix_noise_response_t *out) {
    static const char *const keys[] = {"noise"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "noise", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"noise\"");
    }
    {
        mipc_jr_push(jr, "noise");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 9) {
                return mipc_jr_fail(jr, "more than 9 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->noise[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 9) {
            return mipc_jr_fail(jr, "expected 9 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_mag_noise_std_dev_t */

static int mipc_filter_mag_noise_std_dev_read(mipc_reader_t *r, mipc_filter_mag_noise_std_dev_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_noise = true;
        mipc_rd_push(r, "noise");
        for (i = 0; i < 3; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->noise[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_mag_noise_std_dev_write(mipc_writer_t *w,
                                                         const mipc_filter_mag_noise_std_dev_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_noise) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mipc_wr_f32(w, &in->noise[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_mag_noise_std_dev_encode(const mipc_filter_mag_noise_std_dev_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_mag_noise_std_dev_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_filter_mag_noise_std_dev_decode(const uint8_t *data, size_t len,
                                                   mipc_filter_mag_noise_std_dev_t *out,
                                                   mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_mag_noise_std_dev_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_mag_noise_std_dev_to_json(mipc_jw_t *w, const mipc_filter_mag_noise_std_dev_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_noise) {
        mipc_jw_key(w, &first, "noise");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->noise[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_mag_noise_std_dev_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_mag_noise_std_dev_t *out) {
    static const char *const keys[] = {"function", "noise"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "noise", &vp);
    out->has_noise = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"noise\" given after an absent one");
    } else {
        mipc_jr_push(jr, "noise");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->noise[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_mag_noise_std_dev_response_t */

static int mipc_filter_mag_noise_std_dev_response_read(mipc_reader_t *r,
                                                       mipc_filter_mag_noise_std_dev_response_t *out) {
    size_t i;
    mipc_rd_push(r, "noise");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->noise[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_mag_noise_std_dev_response_write(mipc_writer_t *w,
                                             const mipc_filter_mag_noise_std_dev_response_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->noise[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_mag_noise_std_dev_response_encode(const mipc_filter_mag_noise_std_dev_response_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_mag_noise_std_dev_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_mag_noise_std_dev_response_load(const uint8_t *d,
                                                       mipc_filter_mag_noise_std_dev_response_t *out) {
    out->noise[0] = mipc_ld_f32(d + 0);
    out->noise[1] = mipc_ld_f32(d + 4);
    out->noise[2] = mipc_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_mag_noise_std_dev_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_mag_noise_std_dev_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_mag_noise_std_dev_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_mag_noise_std_dev_response_decode(const uint8_t *data, size_t len,
                                                            mipc_filter_mag_noise_std_dev_response_t *out,
                                                            mipc_decode_error_t *err) {
    if (len == 12 && mipc_filter_mag_noise_std_dev_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_mag_noise_std_dev_response_decode_read(data, len, out, err);
}

void mipc_filter_mag_noise_std_dev_response_to_json(mipc_jw_t *w,
                                                    const mipc_filter_mag_noise_std_dev_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "noise");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->noise[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_mag_noise_std_dev_response_from_json(mipc_jr_t *jr, size_t pos,
                                                     mipc_filter_mag_noise_std_dev_response_t *out) {
    static const char *const keys[] = {"noise"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "noise", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"noise\"");
    }
    {
        mipc_jr_push(jr, "noise");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->noise[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_declination_source_t */

static int mipc_filter_declination_source_read(mipc_reader_t *r, mipc_filter_declination_source_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_source = true;
        mipc_rd_push(r, "source");
        if (mipc_rd_u8(r, &out->source)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_declination = true;
        mipc_rd_push(r, "declination");
        if (mipc_rd_f32(r, &out->declination)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_declination_source_write(mipc_writer_t *w,
                                                          const mipc_filter_declination_source_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_source) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->source)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_declination) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->declination)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_declination_source_encode(const mipc_filter_declination_source_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_declination_source_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_filter_declination_source_decode(const uint8_t *data, size_t len,
                                                    mipc_filter_declination_source_t *out,
                                                    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_declination_source_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_declination_source_to_json(mipc_jw_t *w, const mipc_filter_declination_source_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_source) {
        mipc_jw_key(w, &first, "source");
        mipc_jw_u8(w, &in->source);
    }
    if (in->has_declination) {
        mipc_jw_key(w, &first, "declination");
        mipc_jw_f32(w, &in->declination);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_declination_source_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_filter_declination_source_t *out) {
    static const char *const keys[] = {"function", "source", "declination"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "source", &vp);
    out->has_source = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"source\" given after an absent one");
    } else {
        mipc_jr_push(jr, "source");
        if (mipc_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "declination", &vp);
    out->has_declination = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"declination\" given after an absent one");
    } else {
        mipc_jr_push(jr, "declination");
        if (mipc_jr_f32(jr, vp, &out->declination)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_declination_source_response_t */

static int mipc_filter_declination_source_response_read(mipc_reader_t *r,
                                                        mipc_filter_declination_source_response_t *out) {
    mipc_rd_push(r, "source");
    if (mipc_rd_u8(r, &out->source)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "declination");
    if (mipc_rd_f32(r, &out->declination)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_declination_source_response_write(mipc_writer_t *w,
                                              const mipc_filter_declination_source_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->source)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->declination)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_declination_source_response_encode(const mipc_filter_declination_source_response_t *value,
                                               uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_declination_source_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 5 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_declination_source_response_load(const uint8_t *d,
                                                        mipc_filter_declination_source_response_t *out) {
    out->source = mipc_ld_u8(d + 0);
    out->declination = mipc_ld_f32(d + 1);
    return 0;
}

/* The general reader: lengths other than 5, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_declination_source_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_declination_source_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_declination_source_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_declination_source_response_decode(const uint8_t *data, size_t len,
                                                             mipc_filter_declination_source_response_t *out,
                                                             mipc_decode_error_t *err) {
    if (len == 5 && mipc_filter_declination_source_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_declination_source_response_decode_read(data, len, out, err);
}

void mipc_filter_declination_source_response_to_json(mipc_jw_t *w,
                                                     const mipc_filter_declination_source_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "source");
    mipc_jw_u8(w, &in->source);
    mipc_jw_key(w, &first, "declination");
    mipc_jw_f32(w, &in->declination);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_declination_source_response_from_json(mipc_jr_t *jr, size_t pos,
                                                      mipc_filter_declination_source_response_t *out) {
    static const char *const keys[] = {"source", "declination"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "source", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"source\"");
    }
    {
        mipc_jr_push(jr, "source");
        if (mipc_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "declination", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"declination\"");
    }
    {
        mipc_jr_push(jr, "declination");
        if (mipc_jr_f32(jr, vp, &out->declination)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_gravity_magnitude_adaptive_measurement_t */

static int mipc_filter_gravity_magnitude_adaptive_measurement_read(
    mipc_reader_t *r, mipc_filter_gravity_magnitude_adaptive_measurement_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_mode = true;
        mipc_rd_push(r, "mode");
        if (mipc_rd_u8(r, &out->mode)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_frequency = true;
        mipc_rd_push(r, "frequency");
        if (mipc_rd_f32(r, &out->frequency)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_low_limit = true;
        mipc_rd_push(r, "low_limit");
        if (mipc_rd_f32(r, &out->low_limit)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_high_limit = true;
        mipc_rd_push(r, "high_limit");
        if (mipc_rd_f32(r, &out->high_limit)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_low_limit_uncertainty = true;
        mipc_rd_push(r, "low_limit_uncertainty");
        if (mipc_rd_f32(r, &out->low_limit_uncertainty)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_high_limit_uncertainty = true;
        mipc_rd_push(r, "high_limit_uncertainty");
        if (mipc_rd_f32(r, &out->high_limit_uncertainty)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_minimum_uncertainty = true;
        mipc_rd_push(r, "minimum_uncertainty");
        if (mipc_rd_f32(r, &out->minimum_uncertainty)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_gravity_magnitude_adaptive_measurement_write(
    mipc_writer_t *w, const mipc_filter_gravity_magnitude_adaptive_measurement_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_mode) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->mode)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_frequency) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->frequency)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_low_limit) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->low_limit)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_high_limit) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->high_limit)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_low_limit_uncertainty) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->low_limit_uncertainty)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_high_limit_uncertainty) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->high_limit_uncertainty)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_minimum_uncertainty) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->minimum_uncertainty)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_gravity_magnitude_adaptive_measurement_encode(
    const mipc_filter_gravity_magnitude_adaptive_measurement_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_gravity_magnitude_adaptive_measurement_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_filter_gravity_magnitude_adaptive_measurement_decode(
    const uint8_t *data, size_t len, mipc_filter_gravity_magnitude_adaptive_measurement_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_gravity_magnitude_adaptive_measurement_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_gravity_magnitude_adaptive_measurement_to_json(
    mipc_jw_t *w, const mipc_filter_gravity_magnitude_adaptive_measurement_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_mode) {
        mipc_jw_key(w, &first, "mode");
        mipc_jw_u8(w, &in->mode);
    }
    if (in->has_frequency) {
        mipc_jw_key(w, &first, "frequency");
        mipc_jw_f32(w, &in->frequency);
    }
    if (in->has_low_limit) {
        mipc_jw_key(w, &first, "low_limit");
        mipc_jw_f32(w, &in->low_limit);
    }
    if (in->has_high_limit) {
        mipc_jw_key(w, &first, "high_limit");
        mipc_jw_f32(w, &in->high_limit);
    }
    if (in->has_low_limit_uncertainty) {
        mipc_jw_key(w, &first, "low_limit_uncertainty");
        mipc_jw_f32(w, &in->low_limit_uncertainty);
    }
    if (in->has_high_limit_uncertainty) {
        mipc_jw_key(w, &first, "high_limit_uncertainty");
        mipc_jw_f32(w, &in->high_limit_uncertainty);
    }
    if (in->has_minimum_uncertainty) {
        mipc_jw_key(w, &first, "minimum_uncertainty");
        mipc_jw_f32(w, &in->minimum_uncertainty);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_gravity_magnitude_adaptive_measurement_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_gravity_magnitude_adaptive_measurement_t *out) {
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
    if (mipc_jr_object(jr, pos, keys, 8)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "mode", &vp);
    out->has_mode = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"mode\" given after an absent one");
    } else {
        mipc_jr_push(jr, "mode");
        if (mipc_jr_u8(jr, vp, &out->mode)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "frequency", &vp);
    out->has_frequency = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"frequency\" given after an absent one");
    } else {
        mipc_jr_push(jr, "frequency");
        if (mipc_jr_f32(jr, vp, &out->frequency)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "low_limit", &vp);
    out->has_low_limit = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"low_limit\" given after an absent one");
    } else {
        mipc_jr_push(jr, "low_limit");
        if (mipc_jr_f32(jr, vp, &out->low_limit)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "high_limit", &vp);
    out->has_high_limit = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"high_limit\" given after an absent one");
    } else {
        mipc_jr_push(jr, "high_limit");
        if (mipc_jr_f32(jr, vp, &out->high_limit)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "low_limit_uncertainty", &vp);
    out->has_low_limit_uncertainty = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"low_limit_uncertainty\" given after an absent one");
    } else {
        mipc_jr_push(jr, "low_limit_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->low_limit_uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "high_limit_uncertainty", &vp);
    out->has_high_limit_uncertainty = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"high_limit_uncertainty\" given after an absent one");
    } else {
        mipc_jr_push(jr, "high_limit_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->high_limit_uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "minimum_uncertainty", &vp);
    out->has_minimum_uncertainty = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"minimum_uncertainty\" given after an absent one");
    } else {
        mipc_jr_push(jr, "minimum_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->minimum_uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_gravity_magnitude_adaptive_measurement_response_t */

static int mipc_filter_gravity_magnitude_adaptive_measurement_response_read(
    mipc_reader_t *r, mipc_filter_gravity_magnitude_adaptive_measurement_response_t *out) {
    mipc_rd_push(r, "mode");
    if (mipc_rd_u8(r, &out->mode)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "frequency");
    if (mipc_rd_f32(r, &out->frequency)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "low_limit");
    if (mipc_rd_f32(r, &out->low_limit)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "high_limit");
    if (mipc_rd_f32(r, &out->high_limit)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "low_limit_uncertainty");
    if (mipc_rd_f32(r, &out->low_limit_uncertainty)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "high_limit_uncertainty");
    if (mipc_rd_f32(r, &out->high_limit_uncertainty)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "minimum_uncertainty");
    if (mipc_rd_f32(r, &out->minimum_uncertainty)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_gravity_magnitude_adaptive_measurement_response_write(
    mipc_writer_t *w, const mipc_filter_gravity_magnitude_adaptive_measurement_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->mode)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->frequency)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->low_limit)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->high_limit)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->low_limit_uncertainty)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->high_limit_uncertainty)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->minimum_uncertainty)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_gravity_magnitude_adaptive_measurement_response_encode(
    const mipc_filter_gravity_magnitude_adaptive_measurement_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_gravity_magnitude_adaptive_measurement_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 25 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_gravity_magnitude_adaptive_measurement_response_load(
    const uint8_t *d, mipc_filter_gravity_magnitude_adaptive_measurement_response_t *out) {
    out->mode = mipc_ld_u8(d + 0);
    out->frequency = mipc_ld_f32(d + 1);
    out->low_limit = mipc_ld_f32(d + 5);
    out->high_limit = mipc_ld_f32(d + 9);
    out->low_limit_uncertainty = mipc_ld_f32(d + 13);
    out->high_limit_uncertainty = mipc_ld_f32(d + 17);
    out->minimum_uncertainty = mipc_ld_f32(d + 21);
    return 0;
}

/* The general reader: lengths other than 25, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_gravity_magnitude_adaptive_measurement_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_gravity_magnitude_adaptive_measurement_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_gravity_magnitude_adaptive_measurement_response_read(&r, out) ? MIPC_ERR_DECODE
                                                                                     : MIPC_OK;
}

mipc_status_t mipc_filter_gravity_magnitude_adaptive_measurement_response_decode(
    const uint8_t *data, size_t len, mipc_filter_gravity_magnitude_adaptive_measurement_response_t *out,
    mipc_decode_error_t *err) {
    if (len == 25 && mipc_filter_gravity_magnitude_adaptive_measurement_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_gravity_magnitude_adaptive_measurement_response_decode_read(data, len, out, err);
}

void mipc_filter_gravity_magnitude_adaptive_measurement_response_to_json(
    mipc_jw_t *w, const mipc_filter_gravity_magnitude_adaptive_measurement_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "mode");
    mipc_jw_u8(w, &in->mode);
    mipc_jw_key(w, &first, "frequency");
    mipc_jw_f32(w, &in->frequency);
    mipc_jw_key(w, &first, "low_limit");
    mipc_jw_f32(w, &in->low_limit);
    mipc_jw_key(w, &first, "high_limit");
    mipc_jw_f32(w, &in->high_limit);
    mipc_jw_key(w, &first, "low_limit_uncertainty");
    mipc_jw_f32(w, &in->low_limit_uncertainty);
    mipc_jw_key(w, &first, "high_limit_uncertainty");
    mipc_jw_f32(w, &in->high_limit_uncertainty);
    mipc_jw_key(w, &first, "minimum_uncertainty");
    mipc_jw_f32(w, &in->minimum_uncertainty);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_gravity_magnitude_adaptive_measurement_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_gravity_magnitude_adaptive_measurement_response_t *out) {
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
    if (mipc_jr_object(jr, pos, keys, 7)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "mode", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"mode\"");
    }
    {
        mipc_jr_push(jr, "mode");
        if (mipc_jr_u8(jr, vp, &out->mode)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "frequency", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"frequency\"");
    }
    {
        mipc_jr_push(jr, "frequency");
        if (mipc_jr_f32(jr, vp, &out->frequency)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "low_limit", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"low_limit\"");
    }
    {
        mipc_jr_push(jr, "low_limit");
        if (mipc_jr_f32(jr, vp, &out->low_limit)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "high_limit", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"high_limit\"");
    }
    {
        mipc_jr_push(jr, "high_limit");
        if (mipc_jr_f32(jr, vp, &out->high_limit)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "low_limit_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"low_limit_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "low_limit_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->low_limit_uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "high_limit_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"high_limit_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "high_limit_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->high_limit_uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "minimum_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"minimum_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "minimum_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->minimum_uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_mag_magnitude_adaptive_measurement_t */

static int
mipc_filter_mag_magnitude_adaptive_measurement_read(mipc_reader_t *r,
                                                    mipc_filter_mag_magnitude_adaptive_measurement_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_mode = true;
        mipc_rd_push(r, "mode");
        if (mipc_rd_u8(r, &out->mode)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_frequency = true;
        mipc_rd_push(r, "frequency");
        if (mipc_rd_f32(r, &out->frequency)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_low_limit = true;
        mipc_rd_push(r, "low_limit");
        if (mipc_rd_f32(r, &out->low_limit)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_high_limit = true;
        mipc_rd_push(r, "high_limit");
        if (mipc_rd_f32(r, &out->high_limit)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_low_limit_uncertainty = true;
        mipc_rd_push(r, "low_limit_uncertainty");
        if (mipc_rd_f32(r, &out->low_limit_uncertainty)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_high_limit_uncertainty = true;
        mipc_rd_push(r, "high_limit_uncertainty");
        if (mipc_rd_f32(r, &out->high_limit_uncertainty)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_minimum_uncertainty = true;
        mipc_rd_push(r, "minimum_uncertainty");
        if (mipc_rd_f32(r, &out->minimum_uncertainty)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_mag_magnitude_adaptive_measurement_write(
    mipc_writer_t *w, const mipc_filter_mag_magnitude_adaptive_measurement_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_mode) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->mode)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_frequency) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->frequency)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_low_limit) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->low_limit)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_high_limit) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->high_limit)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_low_limit_uncertainty) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->low_limit_uncertainty)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_high_limit_uncertainty) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->high_limit_uncertainty)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_minimum_uncertainty) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->minimum_uncertainty)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_mag_magnitude_adaptive_measurement_encode(
    const mipc_filter_mag_magnitude_adaptive_measurement_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_mag_magnitude_adaptive_measurement_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t
mipc_filter_mag_magnitude_adaptive_measurement_decode(const uint8_t *data, size_t len,
                                                      mipc_filter_mag_magnitude_adaptive_measurement_t *out,
                                                      mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_mag_magnitude_adaptive_measurement_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_mag_magnitude_adaptive_measurement_to_json(
    mipc_jw_t *w, const mipc_filter_mag_magnitude_adaptive_measurement_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_mode) {
        mipc_jw_key(w, &first, "mode");
        mipc_jw_u8(w, &in->mode);
    }
    if (in->has_frequency) {
        mipc_jw_key(w, &first, "frequency");
        mipc_jw_f32(w, &in->frequency);
    }
    if (in->has_low_limit) {
        mipc_jw_key(w, &first, "low_limit");
        mipc_jw_f32(w, &in->low_limit);
    }
    if (in->has_high_limit) {
        mipc_jw_key(w, &first, "high_limit");
        mipc_jw_f32(w, &in->high_limit);
    }
    if (in->has_low_limit_uncertainty) {
        mipc_jw_key(w, &first, "low_limit_uncertainty");
        mipc_jw_f32(w, &in->low_limit_uncertainty);
    }
    if (in->has_high_limit_uncertainty) {
        mipc_jw_key(w, &first, "high_limit_uncertainty");
        mipc_jw_f32(w, &in->high_limit_uncertainty);
    }
    if (in->has_minimum_uncertainty) {
        mipc_jw_key(w, &first, "minimum_uncertainty");
        mipc_jw_f32(w, &in->minimum_uncertainty);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_mag_magnitude_adaptive_measurement_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_mag_magnitude_adaptive_measurement_t *out) {
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
    if (mipc_jr_object(jr, pos, keys, 8)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "mode", &vp);
    out->has_mode = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"mode\" given after an absent one");
    } else {
        mipc_jr_push(jr, "mode");
        if (mipc_jr_u8(jr, vp, &out->mode)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "frequency", &vp);
    out->has_frequency = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"frequency\" given after an absent one");
    } else {
        mipc_jr_push(jr, "frequency");
        if (mipc_jr_f32(jr, vp, &out->frequency)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "low_limit", &vp);
    out->has_low_limit = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"low_limit\" given after an absent one");
    } else {
        mipc_jr_push(jr, "low_limit");
        if (mipc_jr_f32(jr, vp, &out->low_limit)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "high_limit", &vp);
    out->has_high_limit = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"high_limit\" given after an absent one");
    } else {
        mipc_jr_push(jr, "high_limit");
        if (mipc_jr_f32(jr, vp, &out->high_limit)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "low_limit_uncertainty", &vp);
    out->has_low_limit_uncertainty = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"low_limit_uncertainty\" given after an absent one");
    } else {
        mipc_jr_push(jr, "low_limit_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->low_limit_uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "high_limit_uncertainty", &vp);
    out->has_high_limit_uncertainty = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"high_limit_uncertainty\" given after an absent one");
    } else {
        mipc_jr_push(jr, "high_limit_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->high_limit_uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "minimum_uncertainty", &vp);
    out->has_minimum_uncertainty = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"minimum_uncertainty\" given after an absent one");
    } else {
        mipc_jr_push(jr, "minimum_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->minimum_uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_mag_magnitude_adaptive_measurement_response_t */

static int mipc_filter_mag_magnitude_adaptive_measurement_response_read(
    mipc_reader_t *r, mipc_filter_mag_magnitude_adaptive_measurement_response_t *out) {
    mipc_rd_push(r, "mode");
    if (mipc_rd_u8(r, &out->mode)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "frequency");
    if (mipc_rd_f32(r, &out->frequency)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "low_limit");
    if (mipc_rd_f32(r, &out->low_limit)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "high_limit");
    if (mipc_rd_f32(r, &out->high_limit)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "low_limit_uncertainty");
    if (mipc_rd_f32(r, &out->low_limit_uncertainty)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "high_limit_uncertainty");
    if (mipc_rd_f32(r, &out->high_limit_uncertainty)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "minimum_uncertainty");
    if (mipc_rd_f32(r, &out->minimum_uncertainty)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_mag_magnitude_adaptive_measurement_response_write(
    mipc_writer_t *w, const mipc_filter_mag_magnitude_adaptive_measurement_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->mode)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->frequency)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->low_limit)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->high_limit)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->low_limit_uncertainty)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->high_limit_uncertainty)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->minimum_uncertainty)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_mag_magnitude_adaptive_measurement_response_encode(
    const mipc_filter_mag_magnitude_adaptive_measurement_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_mag_magnitude_adaptive_measurement_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 25 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_mag_magnitude_adaptive_measurement_response_load(
    const uint8_t *d, mipc_filter_mag_magnitude_adaptive_measurement_response_t *out) {
    out->mode = mipc_ld_u8(d + 0);
    out->frequency = mipc_ld_f32(d + 1);
    out->low_limit = mipc_ld_f32(d + 5);
    out->high_limit = mipc_ld_f32(d + 9);
    out->low_limit_uncertainty = mipc_ld_f32(d + 13);
    out->high_limit_uncertainty = mipc_ld_f32(d + 17);
    out->minimum_uncertainty = mipc_ld_f32(d + 21);
    return 0;
}

/* The general reader: lengths other than 25, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_mag_magnitude_adaptive_measurement_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_mag_magnitude_adaptive_measurement_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_mag_magnitude_adaptive_measurement_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_mag_magnitude_adaptive_measurement_response_decode(
    const uint8_t *data, size_t len, mipc_filter_mag_magnitude_adaptive_measurement_response_t *out,
    mipc_decode_error_t *err) {
    if (len == 25 && mipc_filter_mag_magnitude_adaptive_measurement_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_mag_magnitude_adaptive_measurement_response_decode_read(data, len, out, err);
}

void mipc_filter_mag_magnitude_adaptive_measurement_response_to_json(
    mipc_jw_t *w, const mipc_filter_mag_magnitude_adaptive_measurement_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "mode");
    mipc_jw_u8(w, &in->mode);
    mipc_jw_key(w, &first, "frequency");
    mipc_jw_f32(w, &in->frequency);
    mipc_jw_key(w, &first, "low_limit");
    mipc_jw_f32(w, &in->low_limit);
    mipc_jw_key(w, &first, "high_limit");
    mipc_jw_f32(w, &in->high_limit);
    mipc_jw_key(w, &first, "low_limit_uncertainty");
    mipc_jw_f32(w, &in->low_limit_uncertainty);
    mipc_jw_key(w, &first, "high_limit_uncertainty");
    mipc_jw_f32(w, &in->high_limit_uncertainty);
    mipc_jw_key(w, &first, "minimum_uncertainty");
    mipc_jw_f32(w, &in->minimum_uncertainty);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_mag_magnitude_adaptive_measurement_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_mag_magnitude_adaptive_measurement_response_t *out) {
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
    if (mipc_jr_object(jr, pos, keys, 7)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "mode", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"mode\"");
    }
    {
        mipc_jr_push(jr, "mode");
        if (mipc_jr_u8(jr, vp, &out->mode)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "frequency", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"frequency\"");
    }
    {
        mipc_jr_push(jr, "frequency");
        if (mipc_jr_f32(jr, vp, &out->frequency)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "low_limit", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"low_limit\"");
    }
    {
        mipc_jr_push(jr, "low_limit");
        if (mipc_jr_f32(jr, vp, &out->low_limit)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "high_limit", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"high_limit\"");
    }
    {
        mipc_jr_push(jr, "high_limit");
        if (mipc_jr_f32(jr, vp, &out->high_limit)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "low_limit_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"low_limit_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "low_limit_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->low_limit_uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "high_limit_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"high_limit_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "high_limit_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->high_limit_uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "minimum_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"minimum_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "minimum_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->minimum_uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_mag_dip_angle_adaptive_measurement_t */

static int
mipc_filter_mag_dip_angle_adaptive_measurement_read(mipc_reader_t *r,
                                                    mipc_filter_mag_dip_angle_adaptive_measurement_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_mode = true;
        mipc_rd_push(r, "mode");
        if (mipc_rd_u8(r, &out->mode)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_frequency = true;
        mipc_rd_push(r, "frequency");
        if (mipc_rd_f32(r, &out->frequency)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_high_limit = true;
        mipc_rd_push(r, "high_limit");
        if (mipc_rd_f32(r, &out->high_limit)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_high_limit_uncertainty = true;
        mipc_rd_push(r, "high_limit_uncertainty");
        if (mipc_rd_f32(r, &out->high_limit_uncertainty)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_minimum_uncertainty = true;
        mipc_rd_push(r, "minimum_uncertainty");
        if (mipc_rd_f32(r, &out->minimum_uncertainty)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_mag_dip_angle_adaptive_measurement_write(
    mipc_writer_t *w, const mipc_filter_mag_dip_angle_adaptive_measurement_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_mode) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->mode)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_frequency) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->frequency)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_high_limit) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->high_limit)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_high_limit_uncertainty) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->high_limit_uncertainty)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_minimum_uncertainty) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->minimum_uncertainty)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_mag_dip_angle_adaptive_measurement_encode(
    const mipc_filter_mag_dip_angle_adaptive_measurement_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_mag_dip_angle_adaptive_measurement_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t
mipc_filter_mag_dip_angle_adaptive_measurement_decode(const uint8_t *data, size_t len,
                                                      mipc_filter_mag_dip_angle_adaptive_measurement_t *out,
                                                      mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_mag_dip_angle_adaptive_measurement_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_mag_dip_angle_adaptive_measurement_to_json(
    mipc_jw_t *w, const mipc_filter_mag_dip_angle_adaptive_measurement_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_mode) {
        mipc_jw_key(w, &first, "mode");
        mipc_jw_u8(w, &in->mode);
    }
    if (in->has_frequency) {
        mipc_jw_key(w, &first, "frequency");
        mipc_jw_f32(w, &in->frequency);
    }
    if (in->has_high_limit) {
        mipc_jw_key(w, &first, "high_limit");
        mipc_jw_f32(w, &in->high_limit);
    }
    if (in->has_high_limit_uncertainty) {
        mipc_jw_key(w, &first, "high_limit_uncertainty");
        mipc_jw_f32(w, &in->high_limit_uncertainty);
    }
    if (in->has_minimum_uncertainty) {
        mipc_jw_key(w, &first, "minimum_uncertainty");
        mipc_jw_f32(w, &in->minimum_uncertainty);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_mag_dip_angle_adaptive_measurement_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_mag_dip_angle_adaptive_measurement_t *out) {
    static const char *const keys[] = {
        "function", "mode", "frequency", "high_limit", "high_limit_uncertainty", "minimum_uncertainty"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 6)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "mode", &vp);
    out->has_mode = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"mode\" given after an absent one");
    } else {
        mipc_jr_push(jr, "mode");
        if (mipc_jr_u8(jr, vp, &out->mode)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "frequency", &vp);
    out->has_frequency = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"frequency\" given after an absent one");
    } else {
        mipc_jr_push(jr, "frequency");
        if (mipc_jr_f32(jr, vp, &out->frequency)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "high_limit", &vp);
    out->has_high_limit = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"high_limit\" given after an absent one");
    } else {
        mipc_jr_push(jr, "high_limit");
        if (mipc_jr_f32(jr, vp, &out->high_limit)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "high_limit_uncertainty", &vp);
    out->has_high_limit_uncertainty = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"high_limit_uncertainty\" given after an absent one");
    } else {
        mipc_jr_push(jr, "high_limit_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->high_limit_uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "minimum_uncertainty", &vp);
    out->has_minimum_uncertainty = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"minimum_uncertainty\" given after an absent one");
    } else {
        mipc_jr_push(jr, "minimum_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->minimum_uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_mag_dip_angle_adaptive_measurement_response_t */

static int mipc_filter_mag_dip_angle_adaptive_measurement_response_read(
    mipc_reader_t *r, mipc_filter_mag_dip_angle_adaptive_measurement_response_t *out) {
    mipc_rd_push(r, "mode");
    if (mipc_rd_u8(r, &out->mode)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "frequency");
    if (mipc_rd_f32(r, &out->frequency)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "high_limit");
    if (mipc_rd_f32(r, &out->high_limit)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "high_limit_uncertainty");
    if (mipc_rd_f32(r, &out->high_limit_uncertainty)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "minimum_uncertainty");
    if (mipc_rd_f32(r, &out->minimum_uncertainty)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_mag_dip_angle_adaptive_measurement_response_write(
    mipc_writer_t *w, const mipc_filter_mag_dip_angle_adaptive_measurement_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->mode)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->frequency)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->high_limit)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->high_limit_uncertainty)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->minimum_uncertainty)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_mag_dip_angle_adaptive_measurement_response_encode(
    const mipc_filter_mag_dip_angle_adaptive_measurement_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_mag_dip_angle_adaptive_measurement_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 17 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_mag_dip_angle_adaptive_measurement_response_load(
    const uint8_t *d, mipc_filter_mag_dip_angle_adaptive_measurement_response_t *out) {
    out->mode = mipc_ld_u8(d + 0);
    out->frequency = mipc_ld_f32(d + 1);
    out->high_limit = mipc_ld_f32(d + 5);
    out->high_limit_uncertainty = mipc_ld_f32(d + 9);
    out->minimum_uncertainty = mipc_ld_f32(d + 13);
    return 0;
}

/* The general reader: lengths other than 17, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_mag_dip_angle_adaptive_measurement_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_mag_dip_angle_adaptive_measurement_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_mag_dip_angle_adaptive_measurement_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_mag_dip_angle_adaptive_measurement_response_decode(
    const uint8_t *data, size_t len, mipc_filter_mag_dip_angle_adaptive_measurement_response_t *out,
    mipc_decode_error_t *err) {
    if (len == 17 && mipc_filter_mag_dip_angle_adaptive_measurement_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_mag_dip_angle_adaptive_measurement_response_decode_read(data, len, out, err);
}

void mipc_filter_mag_dip_angle_adaptive_measurement_response_to_json(
    mipc_jw_t *w, const mipc_filter_mag_dip_angle_adaptive_measurement_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "mode");
    mipc_jw_u8(w, &in->mode);
    mipc_jw_key(w, &first, "frequency");
    mipc_jw_f32(w, &in->frequency);
    mipc_jw_key(w, &first, "high_limit");
    mipc_jw_f32(w, &in->high_limit);
    mipc_jw_key(w, &first, "high_limit_uncertainty");
    mipc_jw_f32(w, &in->high_limit_uncertainty);
    mipc_jw_key(w, &first, "minimum_uncertainty");
    mipc_jw_f32(w, &in->minimum_uncertainty);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_mag_dip_angle_adaptive_measurement_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_mag_dip_angle_adaptive_measurement_response_t *out) {
    static const char *const keys[] = {"mode", "frequency", "high_limit", "high_limit_uncertainty",
                                       "minimum_uncertainty"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "mode", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"mode\"");
    }
    {
        mipc_jr_push(jr, "mode");
        if (mipc_jr_u8(jr, vp, &out->mode)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "frequency", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"frequency\"");
    }
    {
        mipc_jr_push(jr, "frequency");
        if (mipc_jr_f32(jr, vp, &out->frequency)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "high_limit", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"high_limit\"");
    }
    {
        mipc_jr_push(jr, "high_limit");
        if (mipc_jr_f32(jr, vp, &out->high_limit)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "high_limit_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"high_limit_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "high_limit_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->high_limit_uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "minimum_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"minimum_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "minimum_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->minimum_uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_altitude_aiding_control_t */

static int mipc_filter_altitude_aiding_control_read(mipc_reader_t *r,
                                                    mipc_filter_altitude_aiding_control_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_source = true;
        mipc_rd_push(r, "source");
        if (mipc_rd_u8(r, &out->source)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_altitude_aiding_control_write(mipc_writer_t *w, const mipc_filter_altitude_aiding_control_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_source) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->source)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_altitude_aiding_control_encode(const mipc_filter_altitude_aiding_control_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_altitude_aiding_control_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_filter_altitude_aiding_control_decode(const uint8_t *data, size_t len,
                                                         mipc_filter_altitude_aiding_control_t *out,
                                                         mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_altitude_aiding_control_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_altitude_aiding_control_to_json(mipc_jw_t *w,
                                                 const mipc_filter_altitude_aiding_control_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_source) {
        mipc_jw_key(w, &first, "source");
        mipc_jw_u8(w, &in->source);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_altitude_aiding_control_from_json(mipc_jr_t *jr, size_t pos,
                                                  mipc_filter_altitude_aiding_control_t *out) {
    static const char *const keys[] = {"function", "source"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "source", &vp);
    out->has_source = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"source\" given after an absent one");
    } else {
        mipc_jr_push(jr, "source");
        if (mipc_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_altitude_aiding_control_response_t */

static int
mipc_filter_altitude_aiding_control_response_read(mipc_reader_t *r,
                                                  mipc_filter_altitude_aiding_control_response_t *out) {
    mipc_rd_push(r, "source");
    if (mipc_rd_u8(r, &out->source)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_altitude_aiding_control_response_write(mipc_writer_t *w,
                                                   const mipc_filter_altitude_aiding_control_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->source)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_altitude_aiding_control_response_encode(
    const mipc_filter_altitude_aiding_control_response_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_altitude_aiding_control_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_filter_altitude_aiding_control_response_load(const uint8_t *d,
                                                  mipc_filter_altitude_aiding_control_response_t *out) {
    out->source = mipc_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_altitude_aiding_control_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_altitude_aiding_control_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_altitude_aiding_control_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_altitude_aiding_control_response_decode(const uint8_t *data, size_t len,
                                                    mipc_filter_altitude_aiding_control_response_t *out,
                                                    mipc_decode_error_t *err) {
    if (len == 1 && mipc_filter_altitude_aiding_control_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_altitude_aiding_control_response_decode_read(data, len, out, err);
}

void mipc_filter_altitude_aiding_control_response_to_json(
    mipc_jw_t *w, const mipc_filter_altitude_aiding_control_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "source");
    mipc_jw_u8(w, &in->source);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_altitude_aiding_control_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_altitude_aiding_control_response_t *out) {
    static const char *const keys[] = {"source"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "source", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"source\"");
    }
    {
        mipc_jr_push(jr, "source");
        if (mipc_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_pitch_roll_aiding_control_t */

static int mipc_filter_pitch_roll_aiding_control_read(mipc_reader_t *r,
                                                      mipc_filter_pitch_roll_aiding_control_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_source = true;
        mipc_rd_push(r, "source");
        if (mipc_rd_u8(r, &out->source)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_pitch_roll_aiding_control_write(mipc_writer_t *w,
                                            const mipc_filter_pitch_roll_aiding_control_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_source) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->source)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_pitch_roll_aiding_control_encode(const mipc_filter_pitch_roll_aiding_control_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_pitch_roll_aiding_control_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_filter_pitch_roll_aiding_control_decode(const uint8_t *data, size_t len,
                                                           mipc_filter_pitch_roll_aiding_control_t *out,
                                                           mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_pitch_roll_aiding_control_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_pitch_roll_aiding_control_to_json(mipc_jw_t *w,
                                                   const mipc_filter_pitch_roll_aiding_control_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_source) {
        mipc_jw_key(w, &first, "source");
        mipc_jw_u8(w, &in->source);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_pitch_roll_aiding_control_from_json(mipc_jr_t *jr, size_t pos,
                                                    mipc_filter_pitch_roll_aiding_control_t *out) {
    static const char *const keys[] = {"function", "source"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "source", &vp);
    out->has_source = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"source\" given after an absent one");
    } else {
        mipc_jr_push(jr, "source");
        if (mipc_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_pitch_roll_aiding_control_response_t */

static int
mipc_filter_pitch_roll_aiding_control_response_read(mipc_reader_t *r,
                                                    mipc_filter_pitch_roll_aiding_control_response_t *out) {
    mipc_rd_push(r, "source");
    if (mipc_rd_u8(r, &out->source)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_pitch_roll_aiding_control_response_write(
    mipc_writer_t *w, const mipc_filter_pitch_roll_aiding_control_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->source)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_pitch_roll_aiding_control_response_encode(
    const mipc_filter_pitch_roll_aiding_control_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_pitch_roll_aiding_control_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_filter_pitch_roll_aiding_control_response_load(const uint8_t *d,
                                                    mipc_filter_pitch_roll_aiding_control_response_t *out) {
    out->source = mipc_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_pitch_roll_aiding_control_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_pitch_roll_aiding_control_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_pitch_roll_aiding_control_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_pitch_roll_aiding_control_response_decode(const uint8_t *data, size_t len,
                                                      mipc_filter_pitch_roll_aiding_control_response_t *out,
                                                      mipc_decode_error_t *err) {
    if (len == 1 && mipc_filter_pitch_roll_aiding_control_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_pitch_roll_aiding_control_response_decode_read(data, len, out, err);
}

void mipc_filter_pitch_roll_aiding_control_response_to_json(
    mipc_jw_t *w, const mipc_filter_pitch_roll_aiding_control_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "source");
    mipc_jw_u8(w, &in->source);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_pitch_roll_aiding_control_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_pitch_roll_aiding_control_response_t *out) {
    static const char *const keys[] = {"source"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "source", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"source\"");
    }
    {
        mipc_jr_push(jr, "source");
        if (mipc_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_inclination_source_t */

static int mipc_filter_inclination_source_read(mipc_reader_t *r, mipc_filter_inclination_source_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_source = true;
        mipc_rd_push(r, "source");
        if (mipc_rd_u8(r, &out->source)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_inclination = true;
        mipc_rd_push(r, "inclination");
        if (mipc_rd_f32(r, &out->inclination)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_inclination_source_write(mipc_writer_t *w,
                                                          const mipc_filter_inclination_source_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_source) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->source)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_inclination) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->inclination)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_inclination_source_encode(const mipc_filter_inclination_source_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_inclination_source_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_filter_inclination_source_decode(const uint8_t *data, size_t len,
                                                    mipc_filter_inclination_source_t *out,
                                                    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_inclination_source_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_inclination_source_to_json(mipc_jw_t *w, const mipc_filter_inclination_source_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_source) {
        mipc_jw_key(w, &first, "source");
        mipc_jw_u8(w, &in->source);
    }
    if (in->has_inclination) {
        mipc_jw_key(w, &first, "inclination");
        mipc_jw_f32(w, &in->inclination);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_inclination_source_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_filter_inclination_source_t *out) {
    static const char *const keys[] = {"function", "source", "inclination"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "source", &vp);
    out->has_source = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"source\" given after an absent one");
    } else {
        mipc_jr_push(jr, "source");
        if (mipc_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "inclination", &vp);
    out->has_inclination = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"inclination\" given after an absent one");
    } else {
        mipc_jr_push(jr, "inclination");
        if (mipc_jr_f32(jr, vp, &out->inclination)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_inclination_source_response_t */

static int mipc_filter_inclination_source_response_read(mipc_reader_t *r,
                                                        mipc_filter_inclination_source_response_t *out) {
    mipc_rd_push(r, "source");
    if (mipc_rd_u8(r, &out->source)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "inclination");
    if (mipc_rd_f32(r, &out->inclination)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_inclination_source_response_write(mipc_writer_t *w,
                                              const mipc_filter_inclination_source_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->source)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->inclination)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_inclination_source_response_encode(const mipc_filter_inclination_source_response_t *value,
                                               uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_inclination_source_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 5 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_inclination_source_response_load(const uint8_t *d,
                                                        mipc_filter_inclination_source_response_t *out) {
    out->source = mipc_ld_u8(d + 0);
    out->inclination = mipc_ld_f32(d + 1);
    return 0;
}

/* The general reader: lengths other than 5, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_inclination_source_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_inclination_source_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_inclination_source_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_inclination_source_response_decode(const uint8_t *data, size_t len,
                                                             mipc_filter_inclination_source_response_t *out,
                                                             mipc_decode_error_t *err) {
    if (len == 5 && mipc_filter_inclination_source_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_inclination_source_response_decode_read(data, len, out, err);
}

void mipc_filter_inclination_source_response_to_json(mipc_jw_t *w,
                                                     const mipc_filter_inclination_source_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "source");
    mipc_jw_u8(w, &in->source);
    mipc_jw_key(w, &first, "inclination");
    mipc_jw_f32(w, &in->inclination);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_inclination_source_response_from_json(mipc_jr_t *jr, size_t pos,
                                                      mipc_filter_inclination_source_response_t *out) {
    static const char *const keys[] = {"source", "inclination"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "source", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"source\"");
    }
    {
        mipc_jr_push(jr, "source");
        if (mipc_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "inclination", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"inclination\"");
    }
    {
        mipc_jr_push(jr, "inclination");
        if (mipc_jr_f32(jr, vp, &out->inclination)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_magnetic_field_magnitude_source_t */

static int
mipc_filter_magnetic_field_magnitude_source_read(mipc_reader_t *r,
                                                 mipc_filter_magnetic_field_magnitude_source_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_source = true;
        mipc_rd_push(r, "source");
        if (mipc_rd_u8(r, &out->source)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_magnitude = true;
        mipc_rd_push(r, "magnitude");
        if (mipc_rd_f32(r, &out->magnitude)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_magnetic_field_magnitude_source_write(mipc_writer_t *w,
                                                  const mipc_filter_magnetic_field_magnitude_source_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_source) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->source)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_magnitude) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->magnitude)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_magnetic_field_magnitude_source_encode(const mipc_filter_magnetic_field_magnitude_source_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_magnetic_field_magnitude_source_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t
mipc_filter_magnetic_field_magnitude_source_decode(const uint8_t *data, size_t len,
                                                   mipc_filter_magnetic_field_magnitude_source_t *out,
                                                   mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_magnetic_field_magnitude_source_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_magnetic_field_magnitude_source_to_json(
    mipc_jw_t *w, const mipc_filter_magnetic_field_magnitude_source_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_source) {
        mipc_jw_key(w, &first, "source");
        mipc_jw_u8(w, &in->source);
    }
    if (in->has_magnitude) {
        mipc_jw_key(w, &first, "magnitude");
        mipc_jw_f32(w, &in->magnitude);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_magnetic_field_magnitude_source_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_magnetic_field_magnitude_source_t *out) {
    static const char *const keys[] = {"function", "source", "magnitude"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "source", &vp);
    out->has_source = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"source\" given after an absent one");
    } else {
        mipc_jr_push(jr, "source");
        if (mipc_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "magnitude", &vp);
    out->has_magnitude = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"magnitude\" given after an absent one");
    } else {
        mipc_jr_push(jr, "magnitude");
        if (mipc_jr_f32(jr, vp, &out->magnitude)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_magnetic_field_magnitude_source_response_t */

static int mipc_filter_magnetic_field_magnitude_source_response_read(
    mipc_reader_t *r, mipc_filter_magnetic_field_magnitude_source_response_t *out) {
    mipc_rd_push(r, "source");
    if (mipc_rd_u8(r, &out->source)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "magnitude");
    if (mipc_rd_f32(r, &out->magnitude)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_magnetic_field_magnitude_source_response_write(
    mipc_writer_t *w, const mipc_filter_magnetic_field_magnitude_source_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->source)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->magnitude)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_magnetic_field_magnitude_source_response_encode(
    const mipc_filter_magnetic_field_magnitude_source_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_magnetic_field_magnitude_source_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 5 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_magnetic_field_magnitude_source_response_load(
    const uint8_t *d, mipc_filter_magnetic_field_magnitude_source_response_t *out) {
    out->source = mipc_ld_u8(d + 0);
    out->magnitude = mipc_ld_f32(d + 1);
    return 0;
}

/* The general reader: lengths other than 5, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_magnetic_field_magnitude_source_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_magnetic_field_magnitude_source_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_magnetic_field_magnitude_source_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_magnetic_field_magnitude_source_response_decode(
    const uint8_t *data, size_t len, mipc_filter_magnetic_field_magnitude_source_response_t *out,
    mipc_decode_error_t *err) {
    if (len == 5 && mipc_filter_magnetic_field_magnitude_source_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_magnetic_field_magnitude_source_response_decode_read(data, len, out, err);
}

void mipc_filter_magnetic_field_magnitude_source_response_to_json(
    mipc_jw_t *w, const mipc_filter_magnetic_field_magnitude_source_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "source");
    mipc_jw_u8(w, &in->source);
    mipc_jw_key(w, &first, "magnitude");
    mipc_jw_f32(w, &in->magnitude);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_magnetic_field_magnitude_source_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_magnetic_field_magnitude_source_response_t *out) {
    static const char *const keys[] = {"source", "magnitude"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "source", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"source\"");
    }
    {
        mipc_jr_push(jr, "source");
        if (mipc_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "magnitude", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"magnitude\"");
    }
    {
        mipc_jr_push(jr, "magnitude");
        if (mipc_jr_f32(jr, vp, &out->magnitude)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_aiding_measurement_control_t */

static int mipc_filter_aiding_measurement_control_read(mipc_reader_t *r,
                                                       mipc_filter_aiding_measurement_control_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "source");
    if (mipc_rd_u16(r, &out->source)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_enable = true;
        mipc_rd_push(r, "enable");
        if (mipc_rd_bool(r, &out->enable)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_aiding_measurement_control_write(mipc_writer_t *w,
                                             const mipc_filter_aiding_measurement_control_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->source)) != MIPC_OK) {
        return st;
    }
    if (!in->has_enable) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_bool(w, &in->enable)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_aiding_measurement_control_encode(const mipc_filter_aiding_measurement_control_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_aiding_measurement_control_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_filter_aiding_measurement_control_decode(const uint8_t *data, size_t len,
                                                            mipc_filter_aiding_measurement_control_t *out,
                                                            mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_aiding_measurement_control_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_aiding_measurement_control_to_json(mipc_jw_t *w,
                                                    const mipc_filter_aiding_measurement_control_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    mipc_jw_key(w, &first, "source");
    mipc_jw_u16(w, &in->source);
    if (in->has_enable) {
        mipc_jw_key(w, &first, "enable");
        mipc_jw_bool(w, &in->enable);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_aiding_measurement_control_from_json(mipc_jr_t *jr, size_t pos,
                                                     mipc_filter_aiding_measurement_control_t *out) {
    static const char *const keys[] = {"function", "source", "enable"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "source", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"source\"");
    }
    {
        mipc_jr_push(jr, "source");
        if (mipc_jr_u16(jr, vp, &out->source)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "enable", &vp);
    out->has_enable = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"enable\" given after an absent one");
    } else {
        mipc_jr_push(jr, "enable");
        if (mipc_jr_bool(jr, vp, &out->enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_aiding_measurement_control_response_t */

static int
mipc_filter_aiding_measurement_control_response_read(mipc_reader_t *r,
                                                     mipc_filter_aiding_measurement_control_response_t *out) {
    mipc_rd_push(r, "source");
    if (mipc_rd_u16(r, &out->source)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "enable");
    if (mipc_rd_bool(r, &out->enable)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_aiding_measurement_control_response_write(
    mipc_writer_t *w, const mipc_filter_aiding_measurement_control_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u16(w, &in->source)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_bool(w, &in->enable)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_aiding_measurement_control_response_encode(
    const mipc_filter_aiding_measurement_control_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_aiding_measurement_control_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 3 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_filter_aiding_measurement_control_response_load(const uint8_t *d,
                                                     mipc_filter_aiding_measurement_control_response_t *out) {
    out->source = mipc_ld_u16(d + 0);
    if (d[2] > 1) {
        return -1;
    }
    out->enable = mipc_ld_bool(d + 2);
    return 0;
}

/* The general reader: lengths other than 3, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_aiding_measurement_control_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_aiding_measurement_control_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_aiding_measurement_control_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_aiding_measurement_control_response_decode(const uint8_t *data, size_t len,
                                                       mipc_filter_aiding_measurement_control_response_t *out,
                                                       mipc_decode_error_t *err) {
    if (len == 3 && mipc_filter_aiding_measurement_control_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_aiding_measurement_control_response_decode_read(data, len, out, err);
}

void mipc_filter_aiding_measurement_control_response_to_json(
    mipc_jw_t *w, const mipc_filter_aiding_measurement_control_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "source");
    mipc_jw_u16(w, &in->source);
    mipc_jw_key(w, &first, "enable");
    mipc_jw_bool(w, &in->enable);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_aiding_measurement_control_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_aiding_measurement_control_response_t *out) {
    static const char *const keys[] = {"source", "enable"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "source", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"source\"");
    }
    {
        mipc_jr_push(jr, "source");
        if (mipc_jr_u16(jr, vp, &out->source)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "enable", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"enable\"");
    }
    {
        mipc_jr_push(jr, "enable");
        if (mipc_jr_bool(jr, vp, &out->enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_initialization_configuration_t */

static int mipc_filter_initialization_configuration_read(mipc_reader_t *r,
                                                         mipc_filter_initialization_configuration_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_wait_for_run_command = true;
        mipc_rd_push(r, "wait_for_run_command");
        if (mipc_rd_u8(r, &out->wait_for_run_command)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_initial_cond_src = true;
        mipc_rd_push(r, "initial_cond_src");
        if (mipc_rd_u8(r, &out->initial_cond_src)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_auto_heading_alignment_selector = true;
        mipc_rd_push(r, "auto_heading_alignment_selector");
        if (mipc_rd_u8(r, &out->auto_heading_alignment_selector)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_initial_heading = true;
        mipc_rd_push(r, "initial_heading");
        if (mipc_rd_f32(r, &out->initial_heading)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_initial_pitch = true;
        mipc_rd_push(r, "initial_pitch");
        if (mipc_rd_f32(r, &out->initial_pitch)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_initial_roll = true;
        mipc_rd_push(r, "initial_roll");
        if (mipc_rd_f32(r, &out->initial_roll)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_initial_position = true;
        mipc_rd_push(r, "initial_position");
        for (i = 0; i < 3; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->initial_position[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_initial_velocity = true;
        mipc_rd_push(r, "initial_velocity");
        for (i = 0; i < 3; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->initial_velocity[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_reference_frame_selector = true;
        mipc_rd_push(r, "reference_frame_selector");
        if (mipc_rd_u8(r, &out->reference_frame_selector)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_initialization_configuration_write(mipc_writer_t *w,
                                               const mipc_filter_initialization_configuration_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_wait_for_run_command) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->wait_for_run_command)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_initial_cond_src) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->initial_cond_src)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_auto_heading_alignment_selector) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->auto_heading_alignment_selector)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_initial_heading) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->initial_heading)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_initial_pitch) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->initial_pitch)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_initial_roll) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->initial_roll)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_initial_position) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mipc_wr_f32(w, &in->initial_position[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    if (!in->has_initial_velocity) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mipc_wr_f32(w, &in->initial_velocity[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    if (!in->has_reference_frame_selector) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->reference_frame_selector)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_initialization_configuration_encode(const mipc_filter_initialization_configuration_t *value,
                                                uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_initialization_configuration_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_filter_initialization_configuration_decode(const uint8_t *data, size_t len,
                                                              mipc_filter_initialization_configuration_t *out,
                                                              mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_initialization_configuration_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_initialization_configuration_to_json(mipc_jw_t *w,
                                                      const mipc_filter_initialization_configuration_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_wait_for_run_command) {
        mipc_jw_key(w, &first, "wait_for_run_command");
        mipc_jw_u8(w, &in->wait_for_run_command);
    }
    if (in->has_initial_cond_src) {
        mipc_jw_key(w, &first, "initial_cond_src");
        mipc_jw_u8(w, &in->initial_cond_src);
    }
    if (in->has_auto_heading_alignment_selector) {
        mipc_jw_key(w, &first, "auto_heading_alignment_selector");
        mipc_jw_u8(w, &in->auto_heading_alignment_selector);
    }
    if (in->has_initial_heading) {
        mipc_jw_key(w, &first, "initial_heading");
        mipc_jw_f32(w, &in->initial_heading);
    }
    if (in->has_initial_pitch) {
        mipc_jw_key(w, &first, "initial_pitch");
        mipc_jw_f32(w, &in->initial_pitch);
    }
    if (in->has_initial_roll) {
        mipc_jw_key(w, &first, "initial_roll");
        mipc_jw_f32(w, &in->initial_roll);
    }
    if (in->has_initial_position) {
        mipc_jw_key(w, &first, "initial_position");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->initial_position[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    if (in->has_initial_velocity) {
        mipc_jw_key(w, &first, "initial_velocity");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->initial_velocity[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    if (in->has_reference_frame_selector) {
        mipc_jw_key(w, &first, "reference_frame_selector");
        mipc_jw_u8(w, &in->reference_frame_selector);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_initialization_configuration_from_json(mipc_jr_t *jr, size_t pos,
                                                       mipc_filter_initialization_configuration_t *out) {
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
    if (mipc_jr_object(jr, pos, keys, 10)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "wait_for_run_command", &vp);
    out->has_wait_for_run_command = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"wait_for_run_command\" given after an absent one");
    } else {
        mipc_jr_push(jr, "wait_for_run_command");
        if (mipc_jr_u8(jr, vp, &out->wait_for_run_command)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "initial_cond_src", &vp);
    out->has_initial_cond_src = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"initial_cond_src\" given after an absent one");
    } else {
        mipc_jr_push(jr, "initial_cond_src");
        if (mipc_jr_u8(jr, vp, &out->initial_cond_src)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "auto_heading_alignment_selector", &vp);
    out->has_auto_heading_alignment_selector = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(
            jr, "optional parameter \"auto_heading_alignment_selector\" given after an absent one");
    } else {
        mipc_jr_push(jr, "auto_heading_alignment_selector");
        if (mipc_jr_u8(jr, vp, &out->auto_heading_alignment_selector)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "initial_heading", &vp);
    out->has_initial_heading = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"initial_heading\" given after an absent one");
    } else {
        mipc_jr_push(jr, "initial_heading");
        if (mipc_jr_f32(jr, vp, &out->initial_heading)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "initial_pitch", &vp);
    out->has_initial_pitch = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"initial_pitch\" given after an absent one");
    } else {
        mipc_jr_push(jr, "initial_pitch");
        if (mipc_jr_f32(jr, vp, &out->initial_pitch)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "initial_roll", &vp);
    out->has_initial_roll = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"initial_roll\" given after an absent one");
    } else {
        mipc_jr_push(jr, "initial_roll");
        if (mipc_jr_f32(jr, vp, &out->initial_roll)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "initial_position", &vp);
    out->has_initial_position = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"initial_position\" given after an absent one");
    } else {
        mipc_jr_push(jr, "initial_position");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->initial_position[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "initial_velocity", &vp);
    out->has_initial_velocity = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"initial_velocity\" given after an absent one");
    } else {
        mipc_jr_push(jr, "initial_velocity");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->initial_velocity[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "reference_frame_selector", &vp);
    out->has_reference_frame_selector = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"reference_frame_selector\" given after an absent one");
    } else {
        mipc_jr_push(jr, "reference_frame_selector");
        if (mipc_jr_u8(jr, vp, &out->reference_frame_selector)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_initialization_configuration_response_t */

static int mipc_filter_initialization_configuration_response_read(
    mipc_reader_t *r, mipc_filter_initialization_configuration_response_t *out) {
    size_t i;
    mipc_rd_push(r, "wait_for_run_command");
    if (mipc_rd_u8(r, &out->wait_for_run_command)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "initial_cond_src");
    if (mipc_rd_u8(r, &out->initial_cond_src)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "auto_heading_alignment_selector");
    if (mipc_rd_u8(r, &out->auto_heading_alignment_selector)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "initial_heading");
    if (mipc_rd_f32(r, &out->initial_heading)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "initial_pitch");
    if (mipc_rd_f32(r, &out->initial_pitch)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "initial_roll");
    if (mipc_rd_f32(r, &out->initial_roll)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "initial_position");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->initial_position[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "initial_velocity");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->initial_velocity[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "reference_frame_selector");
    if (mipc_rd_u8(r, &out->reference_frame_selector)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_initialization_configuration_response_write(
    mipc_writer_t *w, const mipc_filter_initialization_configuration_response_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->wait_for_run_command)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->initial_cond_src)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->auto_heading_alignment_selector)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->initial_heading)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->initial_pitch)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->initial_roll)) != MIPC_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->initial_position[i])) != MIPC_OK) {
            return st;
        }
    }
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->initial_velocity[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u8(w, &in->reference_frame_selector)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_initialization_configuration_response_encode(
    const mipc_filter_initialization_configuration_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_initialization_configuration_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 40 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_initialization_configuration_response_load(
    const uint8_t *d, mipc_filter_initialization_configuration_response_t *out) {
    out->wait_for_run_command = mipc_ld_u8(d + 0);
    out->initial_cond_src = mipc_ld_u8(d + 1);
    out->auto_heading_alignment_selector = mipc_ld_u8(d + 2);
    out->initial_heading = mipc_ld_f32(d + 3);
    out->initial_pitch = mipc_ld_f32(d + 7);
    out->initial_roll = mipc_ld_f32(d + 11);
    out->initial_position[0] = mipc_ld_f32(d + 15);
    out->initial_position[1] = mipc_ld_f32(d + 19);
    out->initial_position[2] = mipc_ld_f32(d + 23);
    out->initial_velocity[0] = mipc_ld_f32(d + 27);
    out->initial_velocity[1] = mipc_ld_f32(d + 31);
    out->initial_velocity[2] = mipc_ld_f32(d + 35);
    out->reference_frame_selector = mipc_ld_u8(d + 39);
    return 0;
}

/* The general reader: lengths other than 40, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_initialization_configuration_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_initialization_configuration_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_initialization_configuration_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_initialization_configuration_response_decode(
    const uint8_t *data, size_t len, mipc_filter_initialization_configuration_response_t *out,
    mipc_decode_error_t *err) {
    if (len == 40 && mipc_filter_initialization_configuration_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_initialization_configuration_response_decode_read(data, len, out, err);
}

void mipc_filter_initialization_configuration_response_to_json(
    mipc_jw_t *w, const mipc_filter_initialization_configuration_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "wait_for_run_command");
    mipc_jw_u8(w, &in->wait_for_run_command);
    mipc_jw_key(w, &first, "initial_cond_src");
    mipc_jw_u8(w, &in->initial_cond_src);
    mipc_jw_key(w, &first, "auto_heading_alignment_selector");
    mipc_jw_u8(w, &in->auto_heading_alignment_selector);
    mipc_jw_key(w, &first, "initial_heading");
    mipc_jw_f32(w, &in->initial_heading);
    mipc_jw_key(w, &first, "initial_pitch");
    mipc_jw_f32(w, &in->initial_pitch);
    mipc_jw_key(w, &first, "initial_roll");
    mipc_jw_f32(w, &in->initial_roll);
    mipc_jw_key(w, &first, "initial_position");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->initial_position[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "initial_velocity");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->initial_velocity[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "reference_frame_selector");
    mipc_jw_u8(w, &in->reference_frame_selector);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_initialization_configuration_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_initialization_configuration_response_t *out) {
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
    if (mipc_jr_object(jr, pos, keys, 9)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "wait_for_run_command", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"wait_for_run_command\"");
    }
    {
        mipc_jr_push(jr, "wait_for_run_command");
        if (mipc_jr_u8(jr, vp, &out->wait_for_run_command)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "initial_cond_src", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"initial_cond_src\"");
    }
    {
        mipc_jr_push(jr, "initial_cond_src");
        if (mipc_jr_u8(jr, vp, &out->initial_cond_src)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "auto_heading_alignment_selector", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"auto_heading_alignment_selector\"");
    }
    {
        mipc_jr_push(jr, "auto_heading_alignment_selector");
        if (mipc_jr_u8(jr, vp, &out->auto_heading_alignment_selector)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "initial_heading", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"initial_heading\"");
    }
    {
        mipc_jr_push(jr, "initial_heading");
        if (mipc_jr_f32(jr, vp, &out->initial_heading)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "initial_pitch", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"initial_pitch\"");
    }
    {
        mipc_jr_push(jr, "initial_pitch");
        if (mipc_jr_f32(jr, vp, &out->initial_pitch)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "initial_roll", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"initial_roll\"");
    }
    {
        mipc_jr_push(jr, "initial_roll");
        if (mipc_jr_f32(jr, vp, &out->initial_roll)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "initial_position", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"initial_position\"");
    }
    {
        mipc_jr_push(jr, "initial_position");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->initial_position[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "initial_velocity", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"initial_velocity\"");
    }
    {
        mipc_jr_push(jr, "initial_velocity");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->initial_velocity[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "reference_frame_selector", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"reference_frame_selector\"");
    }
    {
        mipc_jr_push(jr, "reference_frame_selector");
        if (mipc_jr_u8(jr, vp, &out->reference_frame_selector)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_adaptive_filter_control_t */

static int mipc_filter_adaptive_filter_control_read(mipc_reader_t *r,
                                                    mipc_filter_adaptive_filter_control_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_level = true;
        mipc_rd_push(r, "level");
        if (mipc_rd_u8(r, &out->level)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_time_limit = true;
        mipc_rd_push(r, "time_limit");
        if (mipc_rd_u16(r, &out->time_limit)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_adaptive_filter_control_write(mipc_writer_t *w, const mipc_filter_adaptive_filter_control_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_level) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->level)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_time_limit) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u16(w, &in->time_limit)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_adaptive_filter_control_encode(const mipc_filter_adaptive_filter_control_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_adaptive_filter_control_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_filter_adaptive_filter_control_decode(const uint8_t *data, size_t len,
                                                         mipc_filter_adaptive_filter_control_t *out,
                                                         mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_adaptive_filter_control_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_adaptive_filter_control_to_json(mipc_jw_t *w,
                                                 const mipc_filter_adaptive_filter_control_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_level) {
        mipc_jw_key(w, &first, "level");
        mipc_jw_u8(w, &in->level);
    }
    if (in->has_time_limit) {
        mipc_jw_key(w, &first, "time_limit");
        mipc_jw_u16(w, &in->time_limit);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_adaptive_filter_control_from_json(mipc_jr_t *jr, size_t pos,
                                                  mipc_filter_adaptive_filter_control_t *out) {
    static const char *const keys[] = {"function", "level", "time_limit"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "level", &vp);
    out->has_level = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"level\" given after an absent one");
    } else {
        mipc_jr_push(jr, "level");
        if (mipc_jr_u8(jr, vp, &out->level)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "time_limit", &vp);
    out->has_time_limit = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"time_limit\" given after an absent one");
    } else {
        mipc_jr_push(jr, "time_limit");
        if (mipc_jr_u16(jr, vp, &out->time_limit)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_adaptive_filter_control_response_t */

static int
mipc_filter_adaptive_filter_control_response_read(mipc_reader_t *r,
                                                  mipc_filter_adaptive_filter_control_response_t *out) {
    mipc_rd_push(r, "level");
    if (mipc_rd_u8(r, &out->level)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "time_limit");
    if (mipc_rd_u16(r, &out->time_limit)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_adaptive_filter_control_response_write(mipc_writer_t *w,
                                                   const mipc_filter_adaptive_filter_control_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->level)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->time_limit)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_adaptive_filter_control_response_encode(
    const mipc_filter_adaptive_filter_control_response_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_adaptive_filter_control_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 3 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_filter_adaptive_filter_control_response_load(const uint8_t *d,
                                                  mipc_filter_adaptive_filter_control_response_t *out) {
    out->level = mipc_ld_u8(d + 0);
    out->time_limit = mipc_ld_u16(d + 1);
    return 0;
}

/* The general reader: lengths other than 3, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_adaptive_filter_control_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_adaptive_filter_control_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_adaptive_filter_control_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_adaptive_filter_control_response_decode(const uint8_t *data, size_t len,
                                                    mipc_filter_adaptive_filter_control_response_t *out,
                                                    mipc_decode_error_t *err) {
    if (len == 3 && mipc_filter_adaptive_filter_control_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_adaptive_filter_control_response_decode_read(data, len, out, err);
}

void mipc_filter_adaptive_filter_control_response_to_json(
    mipc_jw_t *w, const mipc_filter_adaptive_filter_control_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "level");
    mipc_jw_u8(w, &in->level);
    mipc_jw_key(w, &first, "time_limit");
    mipc_jw_u16(w, &in->time_limit);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_adaptive_filter_control_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_adaptive_filter_control_response_t *out) {
    static const char *const keys[] = {"level", "time_limit"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "level", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"level\"");
    }
    {
        mipc_jr_push(jr, "level");
        if (mipc_jr_u8(jr, vp, &out->level)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "time_limit", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"time_limit\"");
    }
    {
        mipc_jr_push(jr, "time_limit");
        if (mipc_jr_u16(jr, vp, &out->time_limit)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_multi_antenna_offset_t */

static int mipc_filter_multi_antenna_offset_read(mipc_reader_t *r, mipc_filter_multi_antenna_offset_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "receiver_id");
    if (mipc_rd_u8(r, &out->receiver_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_antenna_offset = true;
        mipc_rd_push(r, "antenna_offset");
        for (i = 0; i < 3; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->antenna_offset[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_multi_antenna_offset_write(mipc_writer_t *w,
                                                            const mipc_filter_multi_antenna_offset_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->receiver_id)) != MIPC_OK) {
        return st;
    }
    if (!in->has_antenna_offset) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mipc_wr_f32(w, &in->antenna_offset[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_multi_antenna_offset_encode(const mipc_filter_multi_antenna_offset_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_multi_antenna_offset_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_filter_multi_antenna_offset_decode(const uint8_t *data, size_t len,
                                                      mipc_filter_multi_antenna_offset_t *out,
                                                      mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_multi_antenna_offset_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_multi_antenna_offset_to_json(mipc_jw_t *w, const mipc_filter_multi_antenna_offset_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    mipc_jw_key(w, &first, "receiver_id");
    mipc_jw_u8(w, &in->receiver_id);
    if (in->has_antenna_offset) {
        mipc_jw_key(w, &first, "antenna_offset");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->antenna_offset[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_multi_antenna_offset_from_json(mipc_jr_t *jr, size_t pos,
                                               mipc_filter_multi_antenna_offset_t *out) {
    static const char *const keys[] = {"function", "receiver_id", "antenna_offset"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "receiver_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"receiver_id\"");
    }
    {
        mipc_jr_push(jr, "receiver_id");
        if (mipc_jr_u8(jr, vp, &out->receiver_id)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "antenna_offset", &vp);
    out->has_antenna_offset = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"antenna_offset\" given after an absent one");
    } else {
        mipc_jr_push(jr, "antenna_offset");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->antenna_offset[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_multi_antenna_offset_response_t */

static int mipc_filter_multi_antenna_offset_response_read(mipc_reader_t *r,
                                                          mipc_filter_multi_antenna_offset_response_t *out) {
    size_t i;
    mipc_rd_push(r, "receiver_id");
    if (mipc_rd_u8(r, &out->receiver_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "antenna_offset");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->antenna_offset[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_multi_antenna_offset_response_write(mipc_writer_t *w,
                                                const mipc_filter_multi_antenna_offset_response_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->receiver_id)) != MIPC_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->antenna_offset[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_multi_antenna_offset_response_encode(const mipc_filter_multi_antenna_offset_response_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_multi_antenna_offset_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 13 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_multi_antenna_offset_response_load(const uint8_t *d,
                                                          mipc_filter_multi_antenna_offset_response_t *out) {
    out->receiver_id = mipc_ld_u8(d + 0);
    out->antenna_offset[0] = mipc_ld_f32(d + 1);
    out->antenna_offset[1] = mipc_ld_f32(d + 5);
    out->antenna_offset[2] = mipc_ld_f32(d + 9);
    return 0;
}

/* The general reader: lengths other than 13, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_multi_antenna_offset_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_multi_antenna_offset_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_multi_antenna_offset_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_multi_antenna_offset_response_decode(const uint8_t *data, size_t len,
                                                 mipc_filter_multi_antenna_offset_response_t *out,
                                                 mipc_decode_error_t *err) {
    if (len == 13 && mipc_filter_multi_antenna_offset_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_multi_antenna_offset_response_decode_read(data, len, out, err);
}

void mipc_filter_multi_antenna_offset_response_to_json(
    mipc_jw_t *w, const mipc_filter_multi_antenna_offset_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "receiver_id");
    mipc_jw_u8(w, &in->receiver_id);
    mipc_jw_key(w, &first, "antenna_offset");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->antenna_offset[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_multi_antenna_offset_response_from_json(mipc_jr_t *jr, size_t pos,
                                                        mipc_filter_multi_antenna_offset_response_t *out) {
    static const char *const keys[] = {"receiver_id", "antenna_offset"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "receiver_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"receiver_id\"");
    }
    {
        mipc_jr_push(jr, "receiver_id");
        if (mipc_jr_u8(jr, vp, &out->receiver_id)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "antenna_offset", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"antenna_offset\"");
    }
    {
        mipc_jr_push(jr, "antenna_offset");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->antenna_offset[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_relative_position_configuration_t */

static int
mipc_filter_relative_position_configuration_read(mipc_reader_t *r,
                                                 mipc_filter_relative_position_configuration_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_source = true;
        mipc_rd_push(r, "source");
        if (mipc_rd_u8(r, &out->source)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_reference_frame_selector = true;
        mipc_rd_push(r, "reference_frame_selector");
        if (mipc_rd_u8(r, &out->reference_frame_selector)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_reference_coordinates = true;
        mipc_rd_push(r, "reference_coordinates");
        for (i = 0; i < 3; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f64(r, &out->reference_coordinates[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_relative_position_configuration_write(mipc_writer_t *w,
                                                  const mipc_filter_relative_position_configuration_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_source) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->source)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_reference_frame_selector) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->reference_frame_selector)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_reference_coordinates) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mipc_wr_f64(w, &in->reference_coordinates[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_relative_position_configuration_encode(const mipc_filter_relative_position_configuration_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_relative_position_configuration_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t
mipc_filter_relative_position_configuration_decode(const uint8_t *data, size_t len,
                                                   mipc_filter_relative_position_configuration_t *out,
                                                   mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_relative_position_configuration_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_relative_position_configuration_to_json(
    mipc_jw_t *w, const mipc_filter_relative_position_configuration_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_source) {
        mipc_jw_key(w, &first, "source");
        mipc_jw_u8(w, &in->source);
    }
    if (in->has_reference_frame_selector) {
        mipc_jw_key(w, &first, "reference_frame_selector");
        mipc_jw_u8(w, &in->reference_frame_selector);
    }
    if (in->has_reference_coordinates) {
        mipc_jw_key(w, &first, "reference_coordinates");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f64(w, &in->reference_coordinates[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_relative_position_configuration_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_relative_position_configuration_t *out) {
    static const char *const keys[] = {"function", "source", "reference_frame_selector",
                                       "reference_coordinates"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 4)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "source", &vp);
    out->has_source = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"source\" given after an absent one");
    } else {
        mipc_jr_push(jr, "source");
        if (mipc_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "reference_frame_selector", &vp);
    out->has_reference_frame_selector = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"reference_frame_selector\" given after an absent one");
    } else {
        mipc_jr_push(jr, "reference_frame_selector");
        if (mipc_jr_u8(jr, vp, &out->reference_frame_selector)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "reference_coordinates", &vp);
    out->has_reference_coordinates = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"reference_coordinates\" given after an absent one");
    } else {
        mipc_jr_push(jr, "reference_coordinates");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f64(jr, ep, &out->reference_coordinates[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_relative_position_configuration_response_t */

static int mipc_filter_relative_position_configuration_response_read(
    mipc_reader_t *r, mipc_filter_relative_position_configuration_response_t *out) {
    size_t i;
    mipc_rd_push(r, "source");
    if (mipc_rd_u8(r, &out->source)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "reference_frame_selector");
    if (mipc_rd_u8(r, &out->reference_frame_selector)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "reference_coordinates");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f64(r, &out->reference_coordinates[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_relative_position_configuration_response_write(
    mipc_writer_t *w, const mipc_filter_relative_position_configuration_response_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->source)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->reference_frame_selector)) != MIPC_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f64(w, &in->reference_coordinates[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_relative_position_configuration_response_encode(
    const mipc_filter_relative_position_configuration_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_relative_position_configuration_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 26 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_relative_position_configuration_response_load(
    const uint8_t *d, mipc_filter_relative_position_configuration_response_t *out) {
    out->source = mipc_ld_u8(d + 0);
    out->reference_frame_selector = mipc_ld_u8(d + 1);
    out->reference_coordinates[0] = mipc_ld_f64(d + 2);
    out->reference_coordinates[1] = mipc_ld_f64(d + 10);
    out->reference_coordinates[2] = mipc_ld_f64(d + 18);
    return 0;
}

/* The general reader: lengths other than 26, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_relative_position_configuration_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_relative_position_configuration_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_relative_position_configuration_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_relative_position_configuration_response_decode(
    const uint8_t *data, size_t len, mipc_filter_relative_position_configuration_response_t *out,
    mipc_decode_error_t *err) {
    if (len == 26 && mipc_filter_relative_position_configuration_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_relative_position_configuration_response_decode_read(data, len, out, err);
}

void mipc_filter_relative_position_configuration_response_to_json(
    mipc_jw_t *w, const mipc_filter_relative_position_configuration_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "source");
    mipc_jw_u8(w, &in->source);
    mipc_jw_key(w, &first, "reference_frame_selector");
    mipc_jw_u8(w, &in->reference_frame_selector);
    mipc_jw_key(w, &first, "reference_coordinates");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f64(w, &in->reference_coordinates[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_relative_position_configuration_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_relative_position_configuration_response_t *out) {
    static const char *const keys[] = {"source", "reference_frame_selector", "reference_coordinates"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "source", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"source\"");
    }
    {
        mipc_jr_push(jr, "source");
        if (mipc_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "reference_frame_selector", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"reference_frame_selector\"");
    }
    {
        mipc_jr_push(jr, "reference_frame_selector");
        if (mipc_jr_u8(jr, vp, &out->reference_frame_selector)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "reference_coordinates", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"reference_coordinates\"");
    }
    {
        mipc_jr_push(jr, "reference_coordinates");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f64(jr, ep, &out->reference_coordinates[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_reference_point_lever_arm_t */

static int mipc_filter_reference_point_lever_arm_read(mipc_reader_t *r,
                                                      mipc_filter_reference_point_lever_arm_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_ref_point_sel = true;
        mipc_rd_push(r, "ref_point_sel");
        if (mipc_rd_u8(r, &out->ref_point_sel)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_lever_arm_offset = true;
        mipc_rd_push(r, "lever_arm_offset");
        for (i = 0; i < 3; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->lever_arm_offset[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_reference_point_lever_arm_write(mipc_writer_t *w,
                                            const mipc_filter_reference_point_lever_arm_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_ref_point_sel) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->ref_point_sel)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_lever_arm_offset) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mipc_wr_f32(w, &in->lever_arm_offset[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_reference_point_lever_arm_encode(const mipc_filter_reference_point_lever_arm_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_reference_point_lever_arm_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_filter_reference_point_lever_arm_decode(const uint8_t *data, size_t len,
                                                           mipc_filter_reference_point_lever_arm_t *out,
                                                           mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_reference_point_lever_arm_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_reference_point_lever_arm_to_json(mipc_jw_t *w,
                                                   const mipc_filter_reference_point_lever_arm_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_ref_point_sel) {
        mipc_jw_key(w, &first, "ref_point_sel");
        mipc_jw_u8(w, &in->ref_point_sel);
    }
    if (in->has_lever_arm_offset) {
        mipc_jw_key(w, &first, "lever_arm_offset");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->lever_arm_offset[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_reference_point_lever_arm_from_json(mipc_jr_t *jr, size_t pos,
                                                    mipc_filter_reference_point_lever_arm_t *out) {
    static const char *const keys[] = {"function", "ref_point_sel", "lever_arm_offset"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "ref_point_sel", &vp);
    out->has_ref_point_sel = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"ref_point_sel\" given after an absent one");
    } else {
        mipc_jr_push(jr, "ref_point_sel");
        if (mipc_jr_u8(jr, vp, &out->ref_point_sel)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "lever_arm_offset", &vp);
    out->has_lever_arm_offset = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"lever_arm_offset\" given after an absent one");
    } else {
        mipc_jr_push(jr, "lever_arm_offset");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->lever_arm_offset[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_reference_point_lever_arm_response_t */

static int
mipc_filter_reference_point_lever_arm_response_read(mipc_reader_t *r,
                                                    mipc_filter_reference_point_lever_arm_response_t *out) {
    size_t i;
    mipc_rd_push(r, "ref_point_sel");
    if (mipc_rd_u8(r, &out->ref_point_sel)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "lever_arm_offset");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->lever_arm_offset[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_reference_point_lever_arm_response_write(
    mipc_writer_t *w, const mipc_filter_reference_point_lever_arm_response_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->ref_point_sel)) != MIPC_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->lever_arm_offset[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_reference_point_lever_arm_response_encode(
    const mipc_filter_reference_point_lever_arm_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_reference_point_lever_arm_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 13 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_filter_reference_point_lever_arm_response_load(const uint8_t *d,
                                                    mipc_filter_reference_point_lever_arm_response_t *out) {
    out->ref_point_sel = mipc_ld_u8(d + 0);
    out->lever_arm_offset[0] = mipc_ld_f32(d + 1);
    out->lever_arm_offset[1] = mipc_ld_f32(d + 5);
    out->lever_arm_offset[2] = mipc_ld_f32(d + 9);
    return 0;
}

/* The general reader: lengths other than 13, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_reference_point_lever_arm_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_reference_point_lever_arm_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_reference_point_lever_arm_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_reference_point_lever_arm_response_decode(const uint8_t *data, size_t len,
                                                      mipc_filter_reference_point_lever_arm_response_t *out,
                                                      mipc_decode_error_t *err) {
    if (len == 13 && mipc_filter_reference_point_lever_arm_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_reference_point_lever_arm_response_decode_read(data, len, out, err);
}

void mipc_filter_reference_point_lever_arm_response_to_json(
    mipc_jw_t *w, const mipc_filter_reference_point_lever_arm_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "ref_point_sel");
    mipc_jw_u8(w, &in->ref_point_sel);
    mipc_jw_key(w, &first, "lever_arm_offset");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->lever_arm_offset[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_reference_point_lever_arm_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_reference_point_lever_arm_response_t *out) {
    static const char *const keys[] = {"ref_point_sel", "lever_arm_offset"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "ref_point_sel", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"ref_point_sel\"");
    }
    {
        mipc_jr_push(jr, "ref_point_sel");
        if (mipc_jr_u8(jr, vp, &out->ref_point_sel)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "lever_arm_offset", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"lever_arm_offset\"");
    }
    {
        mipc_jr_push(jr, "lever_arm_offset");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->lever_arm_offset[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_speed_lever_arm_t */

static int mipc_filter_speed_lever_arm_read(mipc_reader_t *r, mipc_filter_speed_lever_arm_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "source");
    if (mipc_rd_u8(r, &out->source)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_lever_arm_offset = true;
        mipc_rd_push(r, "lever_arm_offset");
        for (i = 0; i < 3; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->lever_arm_offset[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_speed_lever_arm_write(mipc_writer_t *w,
                                                       const mipc_filter_speed_lever_arm_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->source)) != MIPC_OK) {
        return st;
    }
    if (!in->has_lever_arm_offset) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mipc_wr_f32(w, &in->lever_arm_offset[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_speed_lever_arm_encode(const mipc_filter_speed_lever_arm_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_speed_lever_arm_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_filter_speed_lever_arm_decode(const uint8_t *data, size_t len,
                                                 mipc_filter_speed_lever_arm_t *out,
                                                 mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_speed_lever_arm_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_speed_lever_arm_to_json(mipc_jw_t *w, const mipc_filter_speed_lever_arm_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    mipc_jw_key(w, &first, "source");
    mipc_jw_u8(w, &in->source);
    if (in->has_lever_arm_offset) {
        mipc_jw_key(w, &first, "lever_arm_offset");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->lever_arm_offset[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_speed_lever_arm_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_speed_lever_arm_t *out) {
    static const char *const keys[] = {"function", "source", "lever_arm_offset"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "source", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"source\"");
    }
    {
        mipc_jr_push(jr, "source");
        if (mipc_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "lever_arm_offset", &vp);
    out->has_lever_arm_offset = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"lever_arm_offset\" given after an absent one");
    } else {
        mipc_jr_push(jr, "lever_arm_offset");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->lever_arm_offset[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_speed_lever_arm_response_t */

static int mipc_filter_speed_lever_arm_response_read(mipc_reader_t *r,
                                                     mipc_filter_speed_lever_arm_response_t *out) {
    size_t i;
    mipc_rd_push(r, "source");
    if (mipc_rd_u8(r, &out->source)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "lever_arm_offset");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->lever_arm_offset[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_speed_lever_arm_response_write(mipc_writer_t *w,
                                           const mipc_filter_speed_lever_arm_response_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->source)) != MIPC_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->lever_arm_offset[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_speed_lever_arm_response_encode(const mipc_filter_speed_lever_arm_response_t *value,
                                                          uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_speed_lever_arm_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 13 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_speed_lever_arm_response_load(const uint8_t *d,
                                                     mipc_filter_speed_lever_arm_response_t *out) {
    out->source = mipc_ld_u8(d + 0);
    out->lever_arm_offset[0] = mipc_ld_f32(d + 1);
    out->lever_arm_offset[1] = mipc_ld_f32(d + 5);
    out->lever_arm_offset[2] = mipc_ld_f32(d + 9);
    return 0;
}

/* The general reader: lengths other than 13, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_speed_lever_arm_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_speed_lever_arm_response_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_speed_lever_arm_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_speed_lever_arm_response_decode(const uint8_t *data, size_t len,
                                                          mipc_filter_speed_lever_arm_response_t *out,
                                                          mipc_decode_error_t *err) {
    if (len == 13 && mipc_filter_speed_lever_arm_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_speed_lever_arm_response_decode_read(data, len, out, err);
}

void mipc_filter_speed_lever_arm_response_to_json(mipc_jw_t *w,
                                                  const mipc_filter_speed_lever_arm_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "source");
    mipc_jw_u8(w, &in->source);
    mipc_jw_key(w, &first, "lever_arm_offset");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->lever_arm_offset[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_speed_lever_arm_response_from_json(mipc_jr_t *jr, size_t pos,
                                                   mipc_filter_speed_lever_arm_response_t *out) {
    static const char *const keys[] = {"source", "lever_arm_offset"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "source", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"source\"");
    }
    {
        mipc_jr_push(jr, "source");
        if (mipc_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "lever_arm_offset", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"lever_arm_offset\"");
    }
    {
        mipc_jr_push(jr, "lever_arm_offset");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->lever_arm_offset[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_wheeled_vehicle_constraint_control_t */

static int
mipc_filter_wheeled_vehicle_constraint_control_read(mipc_reader_t *r,
                                                    mipc_filter_wheeled_vehicle_constraint_control_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_enable = true;
        mipc_rd_push(r, "enable");
        if (mipc_rd_u8(r, &out->enable)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_wheeled_vehicle_constraint_control_write(
    mipc_writer_t *w, const mipc_filter_wheeled_vehicle_constraint_control_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_enable) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->enable)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_wheeled_vehicle_constraint_control_encode(
    const mipc_filter_wheeled_vehicle_constraint_control_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_wheeled_vehicle_constraint_control_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t
mipc_filter_wheeled_vehicle_constraint_control_decode(const uint8_t *data, size_t len,
                                                      mipc_filter_wheeled_vehicle_constraint_control_t *out,
                                                      mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_wheeled_vehicle_constraint_control_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_wheeled_vehicle_constraint_control_to_json(
    mipc_jw_t *w, const mipc_filter_wheeled_vehicle_constraint_control_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_enable) {
        mipc_jw_key(w, &first, "enable");
        mipc_jw_u8(w, &in->enable);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_wheeled_vehicle_constraint_control_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_wheeled_vehicle_constraint_control_t *out) {
    static const char *const keys[] = {"function", "enable"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "enable", &vp);
    out->has_enable = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"enable\" given after an absent one");
    } else {
        mipc_jr_push(jr, "enable");
        if (mipc_jr_u8(jr, vp, &out->enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_wheeled_vehicle_constraint_control_response_t */

static int mipc_filter_wheeled_vehicle_constraint_control_response_read(
    mipc_reader_t *r, mipc_filter_wheeled_vehicle_constraint_control_response_t *out) {
    mipc_rd_push(r, "enable");
    if (mipc_rd_u8(r, &out->enable)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_wheeled_vehicle_constraint_control_response_write(
    mipc_writer_t *w, const mipc_filter_wheeled_vehicle_constraint_control_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->enable)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_wheeled_vehicle_constraint_control_response_encode(
    const mipc_filter_wheeled_vehicle_constraint_control_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_wheeled_vehicle_constraint_control_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_wheeled_vehicle_constraint_control_response_load(
    const uint8_t *d, mipc_filter_wheeled_vehicle_constraint_control_response_t *out) {
    out->enable = mipc_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_wheeled_vehicle_constraint_control_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_wheeled_vehicle_constraint_control_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_wheeled_vehicle_constraint_control_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_wheeled_vehicle_constraint_control_response_decode(
    const uint8_t *data, size_t len, mipc_filter_wheeled_vehicle_constraint_control_response_t *out,
    mipc_decode_error_t *err) {
    if (len == 1 && mipc_filter_wheeled_vehicle_constraint_control_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_wheeled_vehicle_constraint_control_response_decode_read(data, len, out, err);
}

void mipc_filter_wheeled_vehicle_constraint_control_response_to_json(
    mipc_jw_t *w, const mipc_filter_wheeled_vehicle_constraint_control_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "enable");
    mipc_jw_u8(w, &in->enable);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_wheeled_vehicle_constraint_control_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_wheeled_vehicle_constraint_control_response_t *out) {
    static const char *const keys[] = {"enable"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "enable", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"enable\"");
    }
    {
        mipc_jr_push(jr, "enable");
        if (mipc_jr_u8(jr, vp, &out->enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_gnss_antenna_calibration_control_t */

static int
mipc_filter_gnss_antenna_calibration_control_read(mipc_reader_t *r,
                                                  mipc_filter_gnss_antenna_calibration_control_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_enable = true;
        mipc_rd_push(r, "enable");
        if (mipc_rd_u8(r, &out->enable)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_max_offset = true;
        mipc_rd_push(r, "max_offset");
        if (mipc_rd_f32(r, &out->max_offset)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_gnss_antenna_calibration_control_write(mipc_writer_t *w,
                                                   const mipc_filter_gnss_antenna_calibration_control_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_enable) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->enable)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_max_offset) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->max_offset)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_gnss_antenna_calibration_control_encode(
    const mipc_filter_gnss_antenna_calibration_control_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_gnss_antenna_calibration_control_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t
mipc_filter_gnss_antenna_calibration_control_decode(const uint8_t *data, size_t len,
                                                    mipc_filter_gnss_antenna_calibration_control_t *out,
                                                    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_gnss_antenna_calibration_control_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_filter_gnss_antenna_calibration_control_to_json(
    mipc_jw_t *w, const mipc_filter_gnss_antenna_calibration_control_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_enable) {
        mipc_jw_key(w, &first, "enable");
        mipc_jw_u8(w, &in->enable);
    }
    if (in->has_max_offset) {
        mipc_jw_key(w, &first, "max_offset");
        mipc_jw_f32(w, &in->max_offset);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_gnss_antenna_calibration_control_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_gnss_antenna_calibration_control_t *out) {
    static const char *const keys[] = {"function", "enable", "max_offset"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "enable", &vp);
    out->has_enable = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"enable\" given after an absent one");
    } else {
        mipc_jr_push(jr, "enable");
        if (mipc_jr_u8(jr, vp, &out->enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "max_offset", &vp);
    out->has_max_offset = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"max_offset\" given after an absent one");
    } else {
        mipc_jr_push(jr, "max_offset");
        if (mipc_jr_f32(jr, vp, &out->max_offset)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_gnss_antenna_calibration_control_response_t */

static int mipc_filter_gnss_antenna_calibration_control_response_read(
    mipc_reader_t *r, mipc_filter_gnss_antenna_calibration_control_response_t *out) {
    mipc_rd_push(r, "enable");
    if (mipc_rd_u8(r, &out->enable)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "max_offset");
    if (mipc_rd_f32(r, &out->max_offset)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_gnss_antenna_calibration_control_response_write(
    mipc_writer_t *w, const mipc_filter_gnss_antenna_calibration_control_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->enable)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->max_offset)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_gnss_antenna_calibration_control_response_encode(
    const mipc_filter_gnss_antenna_calibration_control_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_gnss_antenna_calibration_control_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 5 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_gnss_antenna_calibration_control_response_load(
    const uint8_t *d, mipc_filter_gnss_antenna_calibration_control_response_t *out) {
    out->enable = mipc_ld_u8(d + 0);
    out->max_offset = mipc_ld_f32(d + 1);
    return 0;
}

/* The general reader: lengths other than 5, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_gnss_antenna_calibration_control_response_decode_read(
    const uint8_t *data, size_t len, mipc_filter_gnss_antenna_calibration_control_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_gnss_antenna_calibration_control_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_gnss_antenna_calibration_control_response_decode(
    const uint8_t *data, size_t len, mipc_filter_gnss_antenna_calibration_control_response_t *out,
    mipc_decode_error_t *err) {
    if (len == 5 && mipc_filter_gnss_antenna_calibration_control_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_gnss_antenna_calibration_control_response_decode_read(data, len, out, err);
}

void mipc_filter_gnss_antenna_calibration_control_response_to_json(
    mipc_jw_t *w, const mipc_filter_gnss_antenna_calibration_control_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "enable");
    mipc_jw_u8(w, &in->enable);
    mipc_jw_key(w, &first, "max_offset");
    mipc_jw_f32(w, &in->max_offset);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_gnss_antenna_calibration_control_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_gnss_antenna_calibration_control_response_t *out) {
    static const char *const keys[] = {"enable", "max_offset"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "enable", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"enable\"");
    }
    {
        mipc_jr_push(jr, "enable");
        if (mipc_jr_u8(jr, vp, &out->enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "max_offset", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"max_offset\"");
    }
    {
        mipc_jr_push(jr, "max_offset");
        if (mipc_jr_f32(jr, vp, &out->max_offset)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}
