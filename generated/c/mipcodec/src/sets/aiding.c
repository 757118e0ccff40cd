/* Encoders and decoders of Aiding Command Set. Generated from the spec: do not edit. */
#include "mipcodec/sets/aiding.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mipc_aiding_frame_config_t */

static int mipc_aiding_frame_config_read(mipc_reader_t *r, mipc_aiding_frame_config_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "frame_id");
    if (mipc_rd_u8(r, &out->frame_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_format = true;
        mipc_rd_push(r, "format");
        if (mipc_rd_u8(r, &out->format)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_tracking_enabled = true;
        mipc_rd_push(r, "tracking_enabled");
        if (mipc_rd_bool(r, &out->tracking_enabled)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_translation = true;
        mipc_rd_push(r, "translation");
        for (i = 0; i < 3; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->translation[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_rotation = true;
        mipc_rd_push(r, "rotation");
        if (mipc_aiding_frame_rotation_read(r, out->format, &out->rotation)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_aiding_frame_config_write(mipc_writer_t *w, const mipc_aiding_frame_config_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->frame_id)) != MIPC_OK) {
        return st;
    }
    if (!in->has_format) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->format)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_tracking_enabled) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_bool(w, &in->tracking_enabled)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_translation) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mipc_wr_f32(w, &in->translation[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    if (!in->has_rotation) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_aiding_frame_rotation_write(w, in->format, &in->rotation)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_aiding_frame_config_encode(const mipc_aiding_frame_config_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_aiding_frame_config_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_aiding_frame_config_decode(const uint8_t *data, size_t len,
                                              mipc_aiding_frame_config_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_aiding_frame_config_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_aiding_frame_config_response_t */

static int mipc_aiding_frame_config_response_read(mipc_reader_t *r,
                                                  mipc_aiding_frame_config_response_t *out) {
    size_t i;
    mipc_rd_push(r, "frame_id");
    if (mipc_rd_u8(r, &out->frame_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "format");
    if (mipc_rd_u8(r, &out->format)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "tracking_enabled");
    if (mipc_rd_bool(r, &out->tracking_enabled)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "translation");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->translation[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "rotation");
    if (mipc_aiding_frame_rotation_read(r, out->format, &out->rotation)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_aiding_frame_config_response_write(mipc_writer_t *w,
                                                             const mipc_aiding_frame_config_response_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->frame_id)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->format)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_bool(w, &in->tracking_enabled)) != MIPC_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->translation[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_aiding_frame_rotation_write(w, in->format, &in->rotation)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_aiding_frame_config_response_encode(const mipc_aiding_frame_config_response_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_aiding_frame_config_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_aiding_frame_config_response_decode(const uint8_t *data, size_t len,
                                                       mipc_aiding_frame_config_response_t *out,
                                                       mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_aiding_frame_config_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_aiding_echo_control_t */

static int mipc_aiding_echo_control_read(mipc_reader_t *r, mipc_aiding_echo_control_t *out) {
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

static mipc_status_t mipc_aiding_echo_control_write(mipc_writer_t *w, const mipc_aiding_echo_control_t *in) {
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

mipc_status_t mipc_aiding_echo_control_encode(const mipc_aiding_echo_control_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_aiding_echo_control_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_aiding_echo_control_decode(const uint8_t *data, size_t len,
                                              mipc_aiding_echo_control_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_aiding_echo_control_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_aiding_echo_control_response_t */

static int mipc_aiding_echo_control_response_read(mipc_reader_t *r,
                                                  mipc_aiding_echo_control_response_t *out) {
    mipc_rd_push(r, "mode");
    if (mipc_rd_u8(r, &out->mode)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_aiding_echo_control_response_write(mipc_writer_t *w,
                                                             const mipc_aiding_echo_control_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->mode)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_aiding_echo_control_response_encode(const mipc_aiding_echo_control_response_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_aiding_echo_control_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_aiding_echo_control_response_load(const uint8_t *d,
                                                  mipc_aiding_echo_control_response_t *out) {
    out->mode = mipc_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_aiding_echo_control_response_decode_read(
    const uint8_t *data, size_t len, mipc_aiding_echo_control_response_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_aiding_echo_control_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_aiding_echo_control_response_decode(const uint8_t *data, size_t len,
                                                       mipc_aiding_echo_control_response_t *out,
                                                       mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mipc_aiding_echo_control_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_aiding_echo_control_response_decode_read(data, len, out, err);
}

/* ---- mipc_aiding_ecef_position_t */

static int mipc_aiding_ecef_position_read(mipc_reader_t *r, mipc_aiding_ecef_position_t *out) {
    size_t i;
    mipc_rd_push(r, "time");
    if (mipc_aiding_time_read(r, &out->time)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "frame_id");
    if (mipc_rd_u8(r, &out->frame_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "position");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f64(r, &out->position[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "uncertainty");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->uncertainty[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_aiding_ecef_position_write(mipc_writer_t *w,
                                                     const mipc_aiding_ecef_position_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_aiding_time_write(w, &in->time)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->frame_id)) != MIPC_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f64(w, &in->position[i])) != MIPC_OK) {
            return st;
        }
    }
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->uncertainty[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_aiding_ecef_position_encode(const mipc_aiding_ecef_position_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_aiding_ecef_position_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_aiding_ecef_position_decode(const uint8_t *data, size_t len,
                                               mipc_aiding_ecef_position_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_aiding_ecef_position_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_aiding_llh_position_t */

static int mipc_aiding_llh_position_read(mipc_reader_t *r, mipc_aiding_llh_position_t *out) {
    size_t i;
    mipc_rd_push(r, "time");
    if (mipc_aiding_time_read(r, &out->time)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "frame_id");
    if (mipc_rd_u8(r, &out->frame_id)) {
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
    mipc_rd_push(r, "uncertainty");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->uncertainty[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_aiding_llh_position_write(mipc_writer_t *w, const mipc_aiding_llh_position_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_aiding_time_write(w, &in->time)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->frame_id)) != MIPC_OK) {
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
        if ((st = mipc_wr_f32(w, &in->uncertainty[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_aiding_llh_position_encode(const mipc_aiding_llh_position_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_aiding_llh_position_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_aiding_llh_position_decode(const uint8_t *data, size_t len,
                                              mipc_aiding_llh_position_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_aiding_llh_position_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_aiding_height_above_ellipsoid_t */

static int mipc_aiding_height_above_ellipsoid_read(mipc_reader_t *r,
                                                   mipc_aiding_height_above_ellipsoid_t *out) {
    mipc_rd_push(r, "time");
    if (mipc_aiding_time_read(r, &out->time)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "frame_id");
    if (mipc_rd_u8(r, &out->frame_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "height");
    if (mipc_rd_f32(r, &out->height)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "uncertainty");
    if (mipc_rd_f32(r, &out->uncertainty)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_aiding_height_above_ellipsoid_write(mipc_writer_t *w, const mipc_aiding_height_above_ellipsoid_t *in) {
    mipc_status_t st;
    if ((st = mipc_aiding_time_write(w, &in->time)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->frame_id)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->height)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->uncertainty)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_aiding_height_above_ellipsoid_encode(const mipc_aiding_height_above_ellipsoid_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_aiding_height_above_ellipsoid_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_aiding_height_above_ellipsoid_decode(const uint8_t *data, size_t len,
                                                        mipc_aiding_height_above_ellipsoid_t *out,
                                                        mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_aiding_height_above_ellipsoid_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_aiding_ecef_velocity_t */

static int mipc_aiding_ecef_velocity_read(mipc_reader_t *r, mipc_aiding_ecef_velocity_t *out) {
    size_t i;
    mipc_rd_push(r, "time");
    if (mipc_aiding_time_read(r, &out->time)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "frame_id");
    if (mipc_rd_u8(r, &out->frame_id)) {
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
    mipc_rd_push(r, "uncertainty");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->uncertainty[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_aiding_ecef_velocity_write(mipc_writer_t *w,
                                                     const mipc_aiding_ecef_velocity_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_aiding_time_write(w, &in->time)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->frame_id)) != MIPC_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->velocity[i])) != MIPC_OK) {
            return st;
        }
    }
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->uncertainty[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_aiding_ecef_velocity_encode(const mipc_aiding_ecef_velocity_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_aiding_ecef_velocity_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_aiding_ecef_velocity_decode(const uint8_t *data, size_t len,
                                               mipc_aiding_ecef_velocity_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_aiding_ecef_velocity_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_aiding_ned_velocity_t */

static int mipc_aiding_ned_velocity_read(mipc_reader_t *r, mipc_aiding_ned_velocity_t *out) {
    size_t i;
    mipc_rd_push(r, "time");
    if (mipc_aiding_time_read(r, &out->time)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "frame_id");
    if (mipc_rd_u8(r, &out->frame_id)) {
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
    mipc_rd_push(r, "uncertainty");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->uncertainty[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_aiding_ned_velocity_write(mipc_writer_t *w, const mipc_aiding_ned_velocity_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_aiding_time_write(w, &in->time)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->frame_id)) != MIPC_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->velocity[i])) != MIPC_OK) {
            return st;
        }
    }
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->uncertainty[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_aiding_ned_velocity_encode(const mipc_aiding_ned_velocity_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_aiding_ned_velocity_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_aiding_ned_velocity_decode(const uint8_t *data, size_t len,
                                              mipc_aiding_ned_velocity_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_aiding_ned_velocity_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_aiding_body_frame_velocity_t */

static int mipc_aiding_body_frame_velocity_read(mipc_reader_t *r, mipc_aiding_body_frame_velocity_t *out) {
    size_t i;
    mipc_rd_push(r, "time");
    if (mipc_aiding_time_read(r, &out->time)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "frame_id");
    if (mipc_rd_u8(r, &out->frame_id)) {
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
    mipc_rd_push(r, "uncertainty");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->uncertainty[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_aiding_body_frame_velocity_write(mipc_writer_t *w,
                                                           const mipc_aiding_body_frame_velocity_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_aiding_time_write(w, &in->time)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->frame_id)) != MIPC_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->velocity[i])) != MIPC_OK) {
            return st;
        }
    }
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->uncertainty[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_aiding_body_frame_velocity_encode(const mipc_aiding_body_frame_velocity_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_aiding_body_frame_velocity_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_aiding_body_frame_velocity_decode(const uint8_t *data, size_t len,
                                                     mipc_aiding_body_frame_velocity_t *out,
                                                     mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_aiding_body_frame_velocity_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_aiding_true_heading_t */

static int mipc_aiding_true_heading_read(mipc_reader_t *r, mipc_aiding_true_heading_t *out) {
    mipc_rd_push(r, "time");
    if (mipc_aiding_time_read(r, &out->time)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "frame_id");
    if (mipc_rd_u8(r, &out->frame_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "heading");
    if (mipc_rd_f32(r, &out->heading)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "uncertainty");
    if (mipc_rd_f32(r, &out->uncertainty)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_aiding_true_heading_write(mipc_writer_t *w, const mipc_aiding_true_heading_t *in) {
    mipc_status_t st;
    if ((st = mipc_aiding_time_write(w, &in->time)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->frame_id)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->heading)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->uncertainty)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_aiding_true_heading_encode(const mipc_aiding_true_heading_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_aiding_true_heading_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_aiding_true_heading_decode(const uint8_t *data, size_t len,
                                              mipc_aiding_true_heading_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_aiding_true_heading_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_aiding_magnetic_field_t */

static int mipc_aiding_magnetic_field_read(mipc_reader_t *r, mipc_aiding_magnetic_field_t *out) {
    size_t i;
    mipc_rd_push(r, "time");
    if (mipc_aiding_time_read(r, &out->time)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "frame_id");
    if (mipc_rd_u8(r, &out->frame_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "magnetic_field");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->magnetic_field[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "uncertainty");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->uncertainty[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_aiding_magnetic_field_write(mipc_writer_t *w,
                                                      const mipc_aiding_magnetic_field_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_aiding_time_write(w, &in->time)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->frame_id)) != MIPC_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->magnetic_field[i])) != MIPC_OK) {
            return st;
        }
    }
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->uncertainty[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_aiding_magnetic_field_encode(const mipc_aiding_magnetic_field_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_aiding_magnetic_field_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_aiding_magnetic_field_decode(const uint8_t *data, size_t len,
                                                mipc_aiding_magnetic_field_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_aiding_magnetic_field_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_aiding_pressure_t */

static int mipc_aiding_pressure_read(mipc_reader_t *r, mipc_aiding_pressure_t *out) {
    mipc_rd_push(r, "time");
    if (mipc_aiding_time_read(r, &out->time)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "frame_id");
    if (mipc_rd_u8(r, &out->frame_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "pressure");
    if (mipc_rd_f32(r, &out->pressure)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "uncertainty");
    if (mipc_rd_f32(r, &out->uncertainty)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_aiding_pressure_write(mipc_writer_t *w, const mipc_aiding_pressure_t *in) {
    mipc_status_t st;
    if ((st = mipc_aiding_time_write(w, &in->time)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->frame_id)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->pressure)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->uncertainty)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_aiding_pressure_encode(const mipc_aiding_pressure_t *value, uint8_t *buf, size_t cap,
                                          size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_aiding_pressure_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_aiding_pressure_decode(const uint8_t *data, size_t len, mipc_aiding_pressure_t *out,
                                          mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_aiding_pressure_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}
