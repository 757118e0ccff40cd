/* Encoders and decoders of Filter Command Set. Generated from the spec: do not edit. */
#include "mipcodec/sets/filter.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_reset_filter_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_set_initial_attitude_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_set_initial_attitude_decode(const uint8_t *data, size_t len,
                                                      mipc_filter_set_initial_attitude_t *out,
                                                      mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mipc_filter_set_initial_attitude_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_set_initial_attitude_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_set_initial_heading_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_set_initial_heading_decode(const uint8_t *data, size_t len,
                                                     mipc_filter_set_initial_heading_t *out,
                                                     mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 4 && mipc_filter_set_initial_heading_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_set_initial_heading_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_run_filter_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_vehicle_dynamics_mode_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_vehicle_dynamics_mode_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_vehicle_dynamics_mode_response_decode(const uint8_t *data, size_t len,
                                                  mipc_filter_vehicle_dynamics_mode_response_t *out,
                                                  mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mipc_filter_vehicle_dynamics_mode_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_vehicle_dynamics_mode_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_sensor_to_vehicle_transform_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_sensor_to_vehicle_transform_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_sensor_to_vehicle_transform_response_decode(
    const uint8_t *data, size_t len, mipc_filter_sensor_to_vehicle_transform_response_t *out,
    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mipc_filter_sensor_to_vehicle_transform_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_sensor_to_vehicle_transform_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_sensor_to_vehicle_offset_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_sensor_to_vehicle_offset_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_sensor_to_vehicle_offset_response_decode(const uint8_t *data, size_t len,
                                                     mipc_filter_sensor_to_vehicle_offset_response_t *out,
                                                     mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mipc_filter_sensor_to_vehicle_offset_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_sensor_to_vehicle_offset_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_antenna_offset_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_antenna_offset_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_antenna_offset_response_decode(const uint8_t *data, size_t len,
                                                         mipc_filter_antenna_offset_response_t *out,
                                                         mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mipc_filter_antenna_offset_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_antenna_offset_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_estimation_control_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_estimation_control_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_estimation_control_response_decode(const uint8_t *data, size_t len,
                                                             mipc_filter_estimation_control_response_t *out,
                                                             mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 2 && mipc_filter_estimation_control_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_estimation_control_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_gnss_source_control_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_gnss_source_control_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_gnss_source_control_response_decode(const uint8_t *data, size_t len,
                                                              mipc_filter_gnss_source_control_response_t *out,
                                                              mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mipc_filter_gnss_source_control_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_gnss_source_control_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_external_gnss_update_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_external_gnss_update_decode(const uint8_t *data, size_t len,
                                                      mipc_filter_external_gnss_update_t *out,
                                                      mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 70 && mipc_filter_external_gnss_update_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_external_gnss_update_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_external_heading_update_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_external_heading_update_decode(const uint8_t *data, size_t len,
                                                         mipc_filter_external_heading_update_t *out,
                                                         mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 9 && mipc_filter_external_heading_update_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_external_heading_update_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_heading_update_control_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_heading_update_control_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_heading_update_control_response_decode(const uint8_t *data, size_t len,
                                                   mipc_filter_heading_update_control_response_t *out,
                                                   mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mipc_filter_heading_update_control_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_heading_update_control_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_auto_init_control_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_auto_init_control_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_auto_init_control_response_decode(const uint8_t *data, size_t len,
                                                            mipc_filter_auto_init_control_response_t *out,
                                                            mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mipc_filter_auto_init_control_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_auto_init_control_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_accel_noise_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_accel_noise_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_accel_noise_response_decode(const uint8_t *data, size_t len,
                                                      mipc_filter_accel_noise_response_t *out,
                                                      mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mipc_filter_accel_noise_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_accel_noise_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_gyro_noise_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_gyro_noise_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_gyro_noise_response_decode(const uint8_t *data, size_t len,
                                                     mipc_filter_gyro_noise_response_t *out,
                                                     mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mipc_filter_gyro_noise_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_gyro_noise_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_accel_bias_model_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_accel_bias_model_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_accel_bias_model_response_decode(const uint8_t *data, size_t len,
                                                           mipc_filter_accel_bias_model_response_t *out,
                                                           mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 24 && mipc_filter_accel_bias_model_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_accel_bias_model_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_gyro_bias_model_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_gyro_bias_model_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_gyro_bias_model_response_decode(const uint8_t *data, size_t len,
                                                          mipc_filter_gyro_bias_model_response_t *out,
                                                          mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 24 && mipc_filter_gyro_bias_model_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_gyro_bias_model_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_zupt_control_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_zupt_control_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_zupt_control_response_decode(const uint8_t *data, size_t len,
                                                       mipc_filter_zupt_control_response_t *out,
                                                       mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 5 && mipc_filter_zupt_control_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_zupt_control_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_external_heading_update_with_time_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_external_heading_update_with_time_decode(const uint8_t *data, size_t len,
                                                     mipc_filter_external_heading_update_with_time_t *out,
                                                     mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 19 && mipc_filter_external_heading_update_with_time_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_external_heading_update_with_time_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_zero_angular_rate_update_control_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_zero_angular_rate_update_control_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_zero_angular_rate_update_control_response_decode(
    const uint8_t *data, size_t len, mipc_filter_zero_angular_rate_update_control_response_t *out,
    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 5 && mipc_filter_zero_angular_rate_update_control_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_zero_angular_rate_update_control_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_tare_orientation_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_commanded_zupt_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_commanded_zero_angular_rate_update_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_mag_capture_auto_calibration_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_mag_capture_auto_calibration_decode(const uint8_t *data, size_t len,
                                                              mipc_filter_mag_capture_auto_calibration_t *out,
                                                              mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mipc_filter_mag_capture_auto_calibration_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_mag_capture_auto_calibration_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_gravity_noise_std_dev_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_gravity_noise_std_dev_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_gravity_noise_std_dev_response_decode(const uint8_t *data, size_t len,
                                                  mipc_filter_gravity_noise_std_dev_response_t *out,
                                                  mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mipc_filter_gravity_noise_std_dev_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_gravity_noise_std_dev_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_pressure_altitude_noise_std_dev_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_pressure_altitude_noise_std_dev_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_pressure_altitude_noise_std_dev_response_decode(
    const uint8_t *data, size_t len, mipc_filter_pressure_altitude_noise_std_dev_response_t *out,
    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 4 && mipc_filter_pressure_altitude_noise_std_dev_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_pressure_altitude_noise_std_dev_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_hard_iron_offset_noise_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_hard_iron_offset_noise_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_hard_iron_offset_noise_response_decode(const uint8_t *data, size_t len,
                                                   mipc_filter_hard_iron_offset_noise_response_t *out,
                                                   mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mipc_filter_hard_iron_offset_noise_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_hard_iron_offset_noise_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_soft_iron_matrix_noise_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_soft_iron_matrix_noise_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_soft_iron_matrix_noise_response_decode(const uint8_t *data, size_t len,
                                                   mipc_filter_soft_iron_matrix_noise_response_t *out,
                                                   mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 36 && mipc_filter_soft_iron_matrix_noise_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_soft_iron_matrix_noise_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_mag_noise_std_dev_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_mag_noise_std_dev_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_mag_noise_std_dev_response_decode(const uint8_t *data, size_t len,
                                                            mipc_filter_mag_noise_std_dev_response_t *out,
                                                            mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mipc_filter_mag_noise_std_dev_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_mag_noise_std_dev_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_declination_source_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_declination_source_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_declination_source_response_decode(const uint8_t *data, size_t len,
                                                             mipc_filter_declination_source_response_t *out,
                                                             mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 5 && mipc_filter_declination_source_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_declination_source_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_gravity_magnitude_adaptive_measurement_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_gravity_magnitude_adaptive_measurement_response_read(&r, out) ? MIPC_ERR_DECODE
                                                                                     : MIPC_OK;
}

mipc_status_t mipc_filter_gravity_magnitude_adaptive_measurement_response_decode(
    const uint8_t *data, size_t len, mipc_filter_gravity_magnitude_adaptive_measurement_response_t *out,
    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 25 && mipc_filter_gravity_magnitude_adaptive_measurement_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_gravity_magnitude_adaptive_measurement_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_mag_magnitude_adaptive_measurement_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_mag_magnitude_adaptive_measurement_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_mag_magnitude_adaptive_measurement_response_decode(
    const uint8_t *data, size_t len, mipc_filter_mag_magnitude_adaptive_measurement_response_t *out,
    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 25 && mipc_filter_mag_magnitude_adaptive_measurement_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_mag_magnitude_adaptive_measurement_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_mag_dip_angle_adaptive_measurement_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_mag_dip_angle_adaptive_measurement_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_mag_dip_angle_adaptive_measurement_response_decode(
    const uint8_t *data, size_t len, mipc_filter_mag_dip_angle_adaptive_measurement_response_t *out,
    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 17 && mipc_filter_mag_dip_angle_adaptive_measurement_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_mag_dip_angle_adaptive_measurement_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_altitude_aiding_control_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_altitude_aiding_control_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_altitude_aiding_control_response_decode(const uint8_t *data, size_t len,
                                                    mipc_filter_altitude_aiding_control_response_t *out,
                                                    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mipc_filter_altitude_aiding_control_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_altitude_aiding_control_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_pitch_roll_aiding_control_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_pitch_roll_aiding_control_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_pitch_roll_aiding_control_response_decode(const uint8_t *data, size_t len,
                                                      mipc_filter_pitch_roll_aiding_control_response_t *out,
                                                      mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mipc_filter_pitch_roll_aiding_control_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_pitch_roll_aiding_control_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_inclination_source_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_inclination_source_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_inclination_source_response_decode(const uint8_t *data, size_t len,
                                                             mipc_filter_inclination_source_response_t *out,
                                                             mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 5 && mipc_filter_inclination_source_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_inclination_source_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_magnetic_field_magnitude_source_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_magnetic_field_magnitude_source_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_magnetic_field_magnitude_source_response_decode(
    const uint8_t *data, size_t len, mipc_filter_magnetic_field_magnitude_source_response_t *out,
    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 5 && mipc_filter_magnetic_field_magnitude_source_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_magnetic_field_magnitude_source_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_aiding_measurement_control_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_aiding_measurement_control_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_aiding_measurement_control_response_decode(const uint8_t *data, size_t len,
                                                       mipc_filter_aiding_measurement_control_response_t *out,
                                                       mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 3 && mipc_filter_aiding_measurement_control_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_aiding_measurement_control_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_initialization_configuration_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_initialization_configuration_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_initialization_configuration_response_decode(
    const uint8_t *data, size_t len, mipc_filter_initialization_configuration_response_t *out,
    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 40 && mipc_filter_initialization_configuration_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_initialization_configuration_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_adaptive_filter_control_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_adaptive_filter_control_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_adaptive_filter_control_response_decode(const uint8_t *data, size_t len,
                                                    mipc_filter_adaptive_filter_control_response_t *out,
                                                    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 3 && mipc_filter_adaptive_filter_control_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_adaptive_filter_control_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_multi_antenna_offset_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_multi_antenna_offset_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_multi_antenna_offset_response_decode(const uint8_t *data, size_t len,
                                                 mipc_filter_multi_antenna_offset_response_t *out,
                                                 mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 13 && mipc_filter_multi_antenna_offset_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_multi_antenna_offset_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_relative_position_configuration_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_relative_position_configuration_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_relative_position_configuration_response_decode(
    const uint8_t *data, size_t len, mipc_filter_relative_position_configuration_response_t *out,
    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 26 && mipc_filter_relative_position_configuration_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_relative_position_configuration_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_reference_point_lever_arm_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_reference_point_lever_arm_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_reference_point_lever_arm_response_decode(const uint8_t *data, size_t len,
                                                      mipc_filter_reference_point_lever_arm_response_t *out,
                                                      mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 13 && mipc_filter_reference_point_lever_arm_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_reference_point_lever_arm_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_speed_lever_arm_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_speed_lever_arm_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_speed_lever_arm_response_decode(const uint8_t *data, size_t len,
                                                          mipc_filter_speed_lever_arm_response_t *out,
                                                          mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 13 && mipc_filter_speed_lever_arm_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_speed_lever_arm_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_wheeled_vehicle_constraint_control_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_wheeled_vehicle_constraint_control_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_wheeled_vehicle_constraint_control_response_decode(
    const uint8_t *data, size_t len, mipc_filter_wheeled_vehicle_constraint_control_response_t *out,
    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mipc_filter_wheeled_vehicle_constraint_control_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_wheeled_vehicle_constraint_control_response_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_gnss_antenna_calibration_control_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_gnss_antenna_calibration_control_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_gnss_antenna_calibration_control_response_decode(
    const uint8_t *data, size_t len, mipc_filter_gnss_antenna_calibration_control_response_t *out,
    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 5 && mipc_filter_gnss_antenna_calibration_control_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_gnss_antenna_calibration_control_response_decode_read(data, len, out, err);
}
