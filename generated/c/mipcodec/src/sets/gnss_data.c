/* Encoders and decoders of GNSS Data Set. Generated from the spec: do not edit. */
#include "mipcodec/sets/gnss_data.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <string.h>

/* ---- mipc_gnss_data_llh_position_t */

static int mipc_gnss_data_llh_position_read(mipc_reader_t *r, mipc_gnss_data_llh_position_t *out) {
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
    mipc_rd_push(r, "ellipsoid_height");
    if (mipc_rd_f64(r, &out->ellipsoid_height)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "msl_height");
    if (mipc_rd_f64(r, &out->msl_height)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "horizontal_accuracy");
    if (mipc_rd_f32(r, &out->horizontal_accuracy)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "vertical_accuracy");
    if (mipc_rd_f32(r, &out->vertical_accuracy)) {
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

static mipc_status_t mipc_gnss_data_llh_position_write(mipc_writer_t *w,
                                                       const mipc_gnss_data_llh_position_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f64(w, &in->latitude)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->longitude)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->ellipsoid_height)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->msl_height)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->horizontal_accuracy)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->vertical_accuracy)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_gnss_data_llh_position_encode(const mipc_gnss_data_llh_position_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_data_llh_position_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 42 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_data_llh_position_load(const uint8_t *d, mipc_gnss_data_llh_position_t *out) {
    out->latitude = mipc_ld_f64(d + 0);
    out->longitude = mipc_ld_f64(d + 8);
    out->ellipsoid_height = mipc_ld_f64(d + 16);
    out->msl_height = mipc_ld_f64(d + 24);
    out->horizontal_accuracy = mipc_ld_f32(d + 32);
    out->vertical_accuracy = mipc_ld_f32(d + 36);
    out->valid_flags = mipc_ld_u16(d + 40);
    return 0;
}

/* The general reader: lengths other than 42, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_gnss_data_llh_position_decode_read(const uint8_t *data, size_t len,
                                                                           mipc_gnss_data_llh_position_t *out,
                                                                           mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_data_llh_position_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_data_llh_position_decode(const uint8_t *data, size_t len,
                                                 mipc_gnss_data_llh_position_t *out,
                                                 mipc_decode_error_t *err) {
    if (len == 42 && mipc_gnss_data_llh_position_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_data_llh_position_decode_read(data, len, out, err);
}

void mipc_gnss_data_llh_position_to_json(mipc_jw_t *w, const mipc_gnss_data_llh_position_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "latitude");
    mipc_jw_f64(w, &in->latitude);
    mipc_jw_key(w, &first, "longitude");
    mipc_jw_f64(w, &in->longitude);
    mipc_jw_key(w, &first, "ellipsoid_height");
    mipc_jw_f64(w, &in->ellipsoid_height);
    mipc_jw_key(w, &first, "msl_height");
    mipc_jw_f64(w, &in->msl_height);
    mipc_jw_key(w, &first, "horizontal_accuracy");
    mipc_jw_f32(w, &in->horizontal_accuracy);
    mipc_jw_key(w, &first, "vertical_accuracy");
    mipc_jw_f32(w, &in->vertical_accuracy);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_data_llh_position_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_data_llh_position_t *out) {
    static const char *const keys[] = {"latitude",   "longitude",           "ellipsoid_height",
                                       "msl_height", "horizontal_accuracy", "vertical_accuracy",
                                       "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 7)) {
        return -1;
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
    found = mipc_jr_get(jr, pos, "ellipsoid_height", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"ellipsoid_height\"");
    }
    {
        mipc_jr_push(jr, "ellipsoid_height");
        if (mipc_jr_f64(jr, vp, &out->ellipsoid_height)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "msl_height", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"msl_height\"");
    }
    {
        mipc_jr_push(jr, "msl_height");
        if (mipc_jr_f64(jr, vp, &out->msl_height)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "horizontal_accuracy", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"horizontal_accuracy\"");
    }
    {
        mipc_jr_push(jr, "horizontal_accuracy");
        if (mipc_jr_f32(jr, vp, &out->horizontal_accuracy)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "vertical_accuracy", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"vertical_accuracy\"");
    }
    {
        mipc_jr_push(jr, "vertical_accuracy");
        if (mipc_jr_f32(jr, vp, &out->vertical_accuracy)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mipc_jr_push(jr, "valid_flags");
        if (mipc_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_gnss_data_ecef_position_t */

static int mipc_gnss_data_ecef_position_read(mipc_reader_t *r, mipc_gnss_data_ecef_position_t *out) {
    size_t i;
    mipc_rd_push(r, "position");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f64(r, &out->position[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "position_accuracy");
    if (mipc_rd_f32(r, &out->position_accuracy)) {
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

static mipc_status_t mipc_gnss_data_ecef_position_write(mipc_writer_t *w,
                                                        const mipc_gnss_data_ecef_position_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f64(w, &in->position[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_f32(w, &in->position_accuracy)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_gnss_data_ecef_position_encode(const mipc_gnss_data_ecef_position_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_data_ecef_position_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 30 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_data_ecef_position_load(const uint8_t *d, mipc_gnss_data_ecef_position_t *out) {
    out->position[0] = mipc_ld_f64(d + 0);
    out->position[1] = mipc_ld_f64(d + 8);
    out->position[2] = mipc_ld_f64(d + 16);
    out->position_accuracy = mipc_ld_f32(d + 24);
    out->valid_flags = mipc_ld_u16(d + 28);
    return 0;
}

/* The general reader: lengths other than 30, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_gnss_data_ecef_position_decode_read(
    const uint8_t *data, size_t len, mipc_gnss_data_ecef_position_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_data_ecef_position_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_data_ecef_position_decode(const uint8_t *data, size_t len,
                                                  mipc_gnss_data_ecef_position_t *out,
                                                  mipc_decode_error_t *err) {
    if (len == 30 && mipc_gnss_data_ecef_position_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_data_ecef_position_decode_read(data, len, out, err);
}

void mipc_gnss_data_ecef_position_to_json(mipc_jw_t *w, const mipc_gnss_data_ecef_position_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "position");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f64(w, &in->position[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "position_accuracy");
    mipc_jw_f32(w, &in->position_accuracy);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_data_ecef_position_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_data_ecef_position_t *out) {
    static const char *const keys[] = {"position", "position_accuracy", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "position", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"position\"");
    }
    {
        mipc_jr_push(jr, "position");
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
            if (mipc_jr_f64(jr, ep, &out->position[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "position_accuracy", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"position_accuracy\"");
    }
    {
        mipc_jr_push(jr, "position_accuracy");
        if (mipc_jr_f32(jr, vp, &out->position_accuracy)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mipc_jr_push(jr, "valid_flags");
        if (mipc_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_gnss_data_ned_velocity_t */

static int mipc_gnss_data_ned_velocity_read(mipc_reader_t *r, mipc_gnss_data_ned_velocity_t *out) {
    size_t i;
    mipc_rd_push(r, "velocity");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->velocity[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "speed");
    if (mipc_rd_f32(r, &out->speed)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "ground_speed");
    if (mipc_rd_f32(r, &out->ground_speed)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "heading");
    if (mipc_rd_f32(r, &out->heading)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "speed_accuracy");
    if (mipc_rd_f32(r, &out->speed_accuracy)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "heading_accuracy");
    if (mipc_rd_f32(r, &out->heading_accuracy)) {
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

static mipc_status_t mipc_gnss_data_ned_velocity_write(mipc_writer_t *w,
                                                       const mipc_gnss_data_ned_velocity_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->velocity[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_f32(w, &in->speed)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->ground_speed)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->heading)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->speed_accuracy)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->heading_accuracy)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_gnss_data_ned_velocity_encode(const mipc_gnss_data_ned_velocity_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_data_ned_velocity_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 34 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_data_ned_velocity_load(const uint8_t *d, mipc_gnss_data_ned_velocity_t *out) {
    out->velocity[0] = mipc_ld_f32(d + 0);
    out->velocity[1] = mipc_ld_f32(d + 4);
    out->velocity[2] = mipc_ld_f32(d + 8);
    out->speed = mipc_ld_f32(d + 12);
    out->ground_speed = mipc_ld_f32(d + 16);
    out->heading = mipc_ld_f32(d + 20);
    out->speed_accuracy = mipc_ld_f32(d + 24);
    out->heading_accuracy = mipc_ld_f32(d + 28);
    out->valid_flags = mipc_ld_u16(d + 32);
    return 0;
}

/* The general reader: lengths other than 34, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_gnss_data_ned_velocity_decode_read(const uint8_t *data, size_t len,
                                                                           mipc_gnss_data_ned_velocity_t *out,
                                                                           mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_data_ned_velocity_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_data_ned_velocity_decode(const uint8_t *data, size_t len,
                                                 mipc_gnss_data_ned_velocity_t *out,
                                                 mipc_decode_error_t *err) {
    if (len == 34 && mipc_gnss_data_ned_velocity_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_data_ned_velocity_decode_read(data, len, out, err);
}

void mipc_gnss_data_ned_velocity_to_json(mipc_jw_t *w, const mipc_gnss_data_ned_velocity_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "velocity");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->velocity[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "speed");
    mipc_jw_f32(w, &in->speed);
    mipc_jw_key(w, &first, "ground_speed");
    mipc_jw_f32(w, &in->ground_speed);
    mipc_jw_key(w, &first, "heading");
    mipc_jw_f32(w, &in->heading);
    mipc_jw_key(w, &first, "speed_accuracy");
    mipc_jw_f32(w, &in->speed_accuracy);
    mipc_jw_key(w, &first, "heading_accuracy");
    mipc_jw_f32(w, &in->heading_accuracy);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_data_ned_velocity_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_data_ned_velocity_t *out) {
    static const char *const keys[] = {
        "velocity", "speed", "ground_speed", "heading", "speed_accuracy", "heading_accuracy", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 7)) {
        return -1;
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
    found = mipc_jr_get(jr, pos, "speed", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"speed\"");
    }
    {
        mipc_jr_push(jr, "speed");
        if (mipc_jr_f32(jr, vp, &out->speed)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "ground_speed", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"ground_speed\"");
    }
    {
        mipc_jr_push(jr, "ground_speed");
        if (mipc_jr_f32(jr, vp, &out->ground_speed)) {
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
    found = mipc_jr_get(jr, pos, "speed_accuracy", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"speed_accuracy\"");
    }
    {
        mipc_jr_push(jr, "speed_accuracy");
        if (mipc_jr_f32(jr, vp, &out->speed_accuracy)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "heading_accuracy", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"heading_accuracy\"");
    }
    {
        mipc_jr_push(jr, "heading_accuracy");
        if (mipc_jr_f32(jr, vp, &out->heading_accuracy)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mipc_jr_push(jr, "valid_flags");
        if (mipc_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_gnss_data_ecef_velocity_t */

static int mipc_gnss_data_ecef_velocity_read(mipc_reader_t *r, mipc_gnss_data_ecef_velocity_t *out) {
    size_t i;
    mipc_rd_push(r, "velocity");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->velocity[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "velocity_accuracy");
    if (mipc_rd_f32(r, &out->velocity_accuracy)) {
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

static mipc_status_t mipc_gnss_data_ecef_velocity_write(mipc_writer_t *w,
                                                        const mipc_gnss_data_ecef_velocity_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->velocity[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_f32(w, &in->velocity_accuracy)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_gnss_data_ecef_velocity_encode(const mipc_gnss_data_ecef_velocity_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_data_ecef_velocity_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 18 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_data_ecef_velocity_load(const uint8_t *d, mipc_gnss_data_ecef_velocity_t *out) {
    out->velocity[0] = mipc_ld_f32(d + 0);
    out->velocity[1] = mipc_ld_f32(d + 4);
    out->velocity[2] = mipc_ld_f32(d + 8);
    out->velocity_accuracy = mipc_ld_f32(d + 12);
    out->valid_flags = mipc_ld_u16(d + 16);
    return 0;
}

/* The general reader: lengths other than 18, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_gnss_data_ecef_velocity_decode_read(
    const uint8_t *data, size_t len, mipc_gnss_data_ecef_velocity_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_data_ecef_velocity_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_data_ecef_velocity_decode(const uint8_t *data, size_t len,
                                                  mipc_gnss_data_ecef_velocity_t *out,
                                                  mipc_decode_error_t *err) {
    if (len == 18 && mipc_gnss_data_ecef_velocity_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_data_ecef_velocity_decode_read(data, len, out, err);
}

void mipc_gnss_data_ecef_velocity_to_json(mipc_jw_t *w, const mipc_gnss_data_ecef_velocity_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "velocity");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->velocity[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "velocity_accuracy");
    mipc_jw_f32(w, &in->velocity_accuracy);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_data_ecef_velocity_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_data_ecef_velocity_t *out) {
    static const char *const keys[] = {"velocity", "velocity_accuracy", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
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
    found = mipc_jr_get(jr, pos, "velocity_accuracy", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"velocity_accuracy\"");
    }
    {
        mipc_jr_push(jr, "velocity_accuracy");
        if (mipc_jr_f32(jr, vp, &out->velocity_accuracy)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mipc_jr_push(jr, "valid_flags");
        if (mipc_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_gnss_data_dop_t */

static int mipc_gnss_data_dop_read(mipc_reader_t *r, mipc_gnss_data_dop_t *out) {
    mipc_rd_push(r, "gdop");
    if (mipc_rd_f32(r, &out->gdop)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "pdop");
    if (mipc_rd_f32(r, &out->pdop)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "hdop");
    if (mipc_rd_f32(r, &out->hdop)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "vdop");
    if (mipc_rd_f32(r, &out->vdop)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "tdop");
    if (mipc_rd_f32(r, &out->tdop)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "ndop");
    if (mipc_rd_f32(r, &out->ndop)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "edop");
    if (mipc_rd_f32(r, &out->edop)) {
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

static mipc_status_t mipc_gnss_data_dop_write(mipc_writer_t *w, const mipc_gnss_data_dop_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f32(w, &in->gdop)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->pdop)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->hdop)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->vdop)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->tdop)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->ndop)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->edop)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_gnss_data_dop_encode(const mipc_gnss_data_dop_t *value, uint8_t *buf, size_t cap,
                                        size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_data_dop_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 30 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_data_dop_load(const uint8_t *d, mipc_gnss_data_dop_t *out) {
    out->gdop = mipc_ld_f32(d + 0);
    out->pdop = mipc_ld_f32(d + 4);
    out->hdop = mipc_ld_f32(d + 8);
    out->vdop = mipc_ld_f32(d + 12);
    out->tdop = mipc_ld_f32(d + 16);
    out->ndop = mipc_ld_f32(d + 20);
    out->edop = mipc_ld_f32(d + 24);
    out->valid_flags = mipc_ld_u16(d + 28);
    return 0;
}

/* The general reader: lengths other than 30, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_gnss_data_dop_decode_read(const uint8_t *data, size_t len,
                                                                  mipc_gnss_data_dop_t *out,
                                                                  mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_data_dop_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_data_dop_decode(const uint8_t *data, size_t len, mipc_gnss_data_dop_t *out,
                                        mipc_decode_error_t *err) {
    if (len == 30 && mipc_gnss_data_dop_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_data_dop_decode_read(data, len, out, err);
}

void mipc_gnss_data_dop_to_json(mipc_jw_t *w, const mipc_gnss_data_dop_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "gdop");
    mipc_jw_f32(w, &in->gdop);
    mipc_jw_key(w, &first, "pdop");
    mipc_jw_f32(w, &in->pdop);
    mipc_jw_key(w, &first, "hdop");
    mipc_jw_f32(w, &in->hdop);
    mipc_jw_key(w, &first, "vdop");
    mipc_jw_f32(w, &in->vdop);
    mipc_jw_key(w, &first, "tdop");
    mipc_jw_f32(w, &in->tdop);
    mipc_jw_key(w, &first, "ndop");
    mipc_jw_f32(w, &in->ndop);
    mipc_jw_key(w, &first, "edop");
    mipc_jw_f32(w, &in->edop);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_data_dop_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_data_dop_t *out) {
    static const char *const keys[] = {"gdop", "pdop", "hdop", "vdop", "tdop", "ndop", "edop", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 8)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "gdop", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"gdop\"");
    }
    {
        mipc_jr_push(jr, "gdop");
        if (mipc_jr_f32(jr, vp, &out->gdop)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "pdop", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"pdop\"");
    }
    {
        mipc_jr_push(jr, "pdop");
        if (mipc_jr_f32(jr, vp, &out->pdop)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "hdop", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"hdop\"");
    }
    {
        mipc_jr_push(jr, "hdop");
        if (mipc_jr_f32(jr, vp, &out->hdop)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "vdop", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"vdop\"");
    }
    {
        mipc_jr_push(jr, "vdop");
        if (mipc_jr_f32(jr, vp, &out->vdop)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "tdop", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"tdop\"");
    }
    {
        mipc_jr_push(jr, "tdop");
        if (mipc_jr_f32(jr, vp, &out->tdop)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "ndop", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"ndop\"");
    }
    {
        mipc_jr_push(jr, "ndop");
        if (mipc_jr_f32(jr, vp, &out->ndop)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "edop", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"edop\"");
    }
    {
        mipc_jr_push(jr, "edop");
        if (mipc_jr_f32(jr, vp, &out->edop)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mipc_jr_push(jr, "valid_flags");
        if (mipc_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_gnss_data_utc_time_t */

static int mipc_gnss_data_utc_time_read(mipc_reader_t *r, mipc_gnss_data_utc_time_t *out) {
    mipc_rd_push(r, "year");
    if (mipc_rd_u16(r, &out->year)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "month");
    if (mipc_rd_u8(r, &out->month)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "day");
    if (mipc_rd_u8(r, &out->day)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "hour");
    if (mipc_rd_u8(r, &out->hour)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "minute");
    if (mipc_rd_u8(r, &out->minute)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "second");
    if (mipc_rd_u8(r, &out->second)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "millisecond");
    if (mipc_rd_u32(r, &out->millisecond)) {
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

static mipc_status_t mipc_gnss_data_utc_time_write(mipc_writer_t *w, const mipc_gnss_data_utc_time_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u16(w, &in->year)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->month)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->day)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->hour)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->minute)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->second)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u32(w, &in->millisecond)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_gnss_data_utc_time_encode(const mipc_gnss_data_utc_time_t *value, uint8_t *buf, size_t cap,
                                             size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_data_utc_time_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 13 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_data_utc_time_load(const uint8_t *d, mipc_gnss_data_utc_time_t *out) {
    out->year = mipc_ld_u16(d + 0);
    out->month = mipc_ld_u8(d + 2);
    out->day = mipc_ld_u8(d + 3);
    out->hour = mipc_ld_u8(d + 4);
    out->minute = mipc_ld_u8(d + 5);
    out->second = mipc_ld_u8(d + 6);
    out->millisecond = mipc_ld_u32(d + 7);
    out->valid_flags = mipc_ld_u16(d + 11);
    return 0;
}

/* The general reader: lengths other than 13, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_gnss_data_utc_time_decode_read(const uint8_t *data, size_t len,
                                                                       mipc_gnss_data_utc_time_t *out,
                                                                       mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_data_utc_time_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_data_utc_time_decode(const uint8_t *data, size_t len, mipc_gnss_data_utc_time_t *out,
                                             mipc_decode_error_t *err) {
    if (len == 13 && mipc_gnss_data_utc_time_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_data_utc_time_decode_read(data, len, out, err);
}

void mipc_gnss_data_utc_time_to_json(mipc_jw_t *w, const mipc_gnss_data_utc_time_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "year");
    mipc_jw_u16(w, &in->year);
    mipc_jw_key(w, &first, "month");
    mipc_jw_u8(w, &in->month);
    mipc_jw_key(w, &first, "day");
    mipc_jw_u8(w, &in->day);
    mipc_jw_key(w, &first, "hour");
    mipc_jw_u8(w, &in->hour);
    mipc_jw_key(w, &first, "minute");
    mipc_jw_u8(w, &in->minute);
    mipc_jw_key(w, &first, "second");
    mipc_jw_u8(w, &in->second);
    mipc_jw_key(w, &first, "millisecond");
    mipc_jw_u32(w, &in->millisecond);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_data_utc_time_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_data_utc_time_t *out) {
    static const char *const keys[] = {"year",   "month",  "day",         "hour",
                                       "minute", "second", "millisecond", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 8)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "year", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"year\"");
    }
    {
        mipc_jr_push(jr, "year");
        if (mipc_jr_u16(jr, vp, &out->year)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "month", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"month\"");
    }
    {
        mipc_jr_push(jr, "month");
        if (mipc_jr_u8(jr, vp, &out->month)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "day", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"day\"");
    }
    {
        mipc_jr_push(jr, "day");
        if (mipc_jr_u8(jr, vp, &out->day)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "hour", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"hour\"");
    }
    {
        mipc_jr_push(jr, "hour");
        if (mipc_jr_u8(jr, vp, &out->hour)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "minute", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"minute\"");
    }
    {
        mipc_jr_push(jr, "minute");
        if (mipc_jr_u8(jr, vp, &out->minute)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "second", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"second\"");
    }
    {
        mipc_jr_push(jr, "second");
        if (mipc_jr_u8(jr, vp, &out->second)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "millisecond", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"millisecond\"");
    }
    {
        mipc_jr_push(jr, "millisecond");
        if (mipc_jr_u32(jr, vp, &out->millisecond)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mipc_jr_push(jr, "valid_flags");
        if (mipc_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_gnss_data_gps_time_t */

static int mipc_gnss_data_gps_time_read(mipc_reader_t *r, mipc_gnss_data_gps_time_t *out) {
    mipc_rd_push(r, "tow");
    if (mipc_rd_f64(r, &out->tow)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "week_number");
    if (mipc_rd_u16(r, &out->week_number)) {
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

static mipc_status_t mipc_gnss_data_gps_time_write(mipc_writer_t *w, const mipc_gnss_data_gps_time_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f64(w, &in->tow)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->week_number)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_gnss_data_gps_time_encode(const mipc_gnss_data_gps_time_t *value, uint8_t *buf, size_t cap,
                                             size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_data_gps_time_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_data_gps_time_load(const uint8_t *d, mipc_gnss_data_gps_time_t *out) {
    out->tow = mipc_ld_f64(d + 0);
    out->week_number = mipc_ld_u16(d + 8);
    out->valid_flags = mipc_ld_u16(d + 10);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_gnss_data_gps_time_decode_read(const uint8_t *data, size_t len,
                                                                       mipc_gnss_data_gps_time_t *out,
                                                                       mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_data_gps_time_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_data_gps_time_decode(const uint8_t *data, size_t len, mipc_gnss_data_gps_time_t *out,
                                             mipc_decode_error_t *err) {
    if (len == 12 && mipc_gnss_data_gps_time_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_data_gps_time_decode_read(data, len, out, err);
}

void mipc_gnss_data_gps_time_to_json(mipc_jw_t *w, const mipc_gnss_data_gps_time_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "tow");
    mipc_jw_f64(w, &in->tow);
    mipc_jw_key(w, &first, "week_number");
    mipc_jw_u16(w, &in->week_number);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_data_gps_time_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_data_gps_time_t *out) {
    static const char *const keys[] = {"tow", "week_number", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "tow", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"tow\"");
    }
    {
        mipc_jr_push(jr, "tow");
        if (mipc_jr_f64(jr, vp, &out->tow)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "week_number", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"week_number\"");
    }
    {
        mipc_jr_push(jr, "week_number");
        if (mipc_jr_u16(jr, vp, &out->week_number)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mipc_jr_push(jr, "valid_flags");
        if (mipc_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_gnss_data_clock_info_t */

static int mipc_gnss_data_clock_info_read(mipc_reader_t *r, mipc_gnss_data_clock_info_t *out) {
    mipc_rd_push(r, "bias");
    if (mipc_rd_f64(r, &out->bias)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "drift");
    if (mipc_rd_f64(r, &out->drift)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "accuracy_estimate");
    if (mipc_rd_f64(r, &out->accuracy_estimate)) {
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

static mipc_status_t mipc_gnss_data_clock_info_write(mipc_writer_t *w,
                                                     const mipc_gnss_data_clock_info_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f64(w, &in->bias)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->drift)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->accuracy_estimate)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_gnss_data_clock_info_encode(const mipc_gnss_data_clock_info_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_data_clock_info_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 26 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_data_clock_info_load(const uint8_t *d, mipc_gnss_data_clock_info_t *out) {
    out->bias = mipc_ld_f64(d + 0);
    out->drift = mipc_ld_f64(d + 8);
    out->accuracy_estimate = mipc_ld_f64(d + 16);
    out->valid_flags = mipc_ld_u16(d + 24);
    return 0;
}

/* The general reader: lengths other than 26, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_gnss_data_clock_info_decode_read(const uint8_t *data, size_t len,
                                                                         mipc_gnss_data_clock_info_t *out,
                                                                         mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_data_clock_info_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_data_clock_info_decode(const uint8_t *data, size_t len,
                                               mipc_gnss_data_clock_info_t *out, mipc_decode_error_t *err) {
    if (len == 26 && mipc_gnss_data_clock_info_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_data_clock_info_decode_read(data, len, out, err);
}

void mipc_gnss_data_clock_info_to_json(mipc_jw_t *w, const mipc_gnss_data_clock_info_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "bias");
    mipc_jw_f64(w, &in->bias);
    mipc_jw_key(w, &first, "drift");
    mipc_jw_f64(w, &in->drift);
    mipc_jw_key(w, &first, "accuracy_estimate");
    mipc_jw_f64(w, &in->accuracy_estimate);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_data_clock_info_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_data_clock_info_t *out) {
    static const char *const keys[] = {"bias", "drift", "accuracy_estimate", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 4)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "bias", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"bias\"");
    }
    {
        mipc_jr_push(jr, "bias");
        if (mipc_jr_f64(jr, vp, &out->bias)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "drift", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"drift\"");
    }
    {
        mipc_jr_push(jr, "drift");
        if (mipc_jr_f64(jr, vp, &out->drift)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "accuracy_estimate", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"accuracy_estimate\"");
    }
    {
        mipc_jr_push(jr, "accuracy_estimate");
        if (mipc_jr_f64(jr, vp, &out->accuracy_estimate)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mipc_jr_push(jr, "valid_flags");
        if (mipc_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_gnss_data_fix_info_t */

static int mipc_gnss_data_fix_info_read(mipc_reader_t *r, mipc_gnss_data_fix_info_t *out) {
    mipc_rd_push(r, "fix_type");
    if (mipc_rd_u8(r, &out->fix_type)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "num_sv");
    if (mipc_rd_u8(r, &out->num_sv)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "fix_flags");
    if (mipc_rd_u16(r, &out->fix_flags)) {
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

static mipc_status_t mipc_gnss_data_fix_info_write(mipc_writer_t *w, const mipc_gnss_data_fix_info_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->fix_type)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->num_sv)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->fix_flags)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_gnss_data_fix_info_encode(const mipc_gnss_data_fix_info_t *value, uint8_t *buf, size_t cap,
                                             size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_data_fix_info_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 6 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_data_fix_info_load(const uint8_t *d, mipc_gnss_data_fix_info_t *out) {
    out->fix_type = mipc_ld_u8(d + 0);
    out->num_sv = mipc_ld_u8(d + 1);
    out->fix_flags = mipc_ld_u16(d + 2);
    out->valid_flags = mipc_ld_u16(d + 4);
    return 0;
}

/* The general reader: lengths other than 6, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_gnss_data_fix_info_decode_read(const uint8_t *data, size_t len,
                                                                       mipc_gnss_data_fix_info_t *out,
                                                                       mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_data_fix_info_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_data_fix_info_decode(const uint8_t *data, size_t len, mipc_gnss_data_fix_info_t *out,
                                             mipc_decode_error_t *err) {
    if (len == 6 && mipc_gnss_data_fix_info_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_data_fix_info_decode_read(data, len, out, err);
}

void mipc_gnss_data_fix_info_to_json(mipc_jw_t *w, const mipc_gnss_data_fix_info_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "fix_type");
    mipc_jw_u8(w, &in->fix_type);
    mipc_jw_key(w, &first, "num_sv");
    mipc_jw_u8(w, &in->num_sv);
    mipc_jw_key(w, &first, "fix_flags");
    mipc_jw_u16(w, &in->fix_flags);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_data_fix_info_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_data_fix_info_t *out) {
    static const char *const keys[] = {"fix_type", "num_sv", "fix_flags", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 4)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "fix_type", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"fix_type\"");
    }
    {
        mipc_jr_push(jr, "fix_type");
        if (mipc_jr_u8(jr, vp, &out->fix_type)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "num_sv", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"num_sv\"");
    }
    {
        mipc_jr_push(jr, "num_sv");
        if (mipc_jr_u8(jr, vp, &out->num_sv)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "fix_flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"fix_flags\"");
    }
    {
        mipc_jr_push(jr, "fix_flags");
        if (mipc_jr_u16(jr, vp, &out->fix_flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mipc_jr_push(jr, "valid_flags");
        if (mipc_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_gnss_data_sv_info_t */

static int mipc_gnss_data_sv_info_read(mipc_reader_t *r, mipc_gnss_data_sv_info_t *out) {
    mipc_rd_push(r, "channel");
    if (mipc_rd_u8(r, &out->channel)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "sv_id");
    if (mipc_rd_u8(r, &out->sv_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "carrier_to_noise_ratio");
    if (mipc_rd_u16(r, &out->carrier_to_noise_ratio)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "azimuth");
    if (mipc_rd_s16(r, &out->azimuth)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "elevation");
    if (mipc_rd_s16(r, &out->elevation)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "sv_flags");
    if (mipc_rd_u16(r, &out->sv_flags)) {
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

static mipc_status_t mipc_gnss_data_sv_info_write(mipc_writer_t *w, const mipc_gnss_data_sv_info_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->channel)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->sv_id)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->carrier_to_noise_ratio)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_s16(w, &in->azimuth)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_s16(w, &in->elevation)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->sv_flags)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_gnss_data_sv_info_encode(const mipc_gnss_data_sv_info_t *value, uint8_t *buf, size_t cap,
                                            size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_data_sv_info_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_data_sv_info_load(const uint8_t *d, mipc_gnss_data_sv_info_t *out) {
    out->channel = mipc_ld_u8(d + 0);
    out->sv_id = mipc_ld_u8(d + 1);
    out->carrier_to_noise_ratio = mipc_ld_u16(d + 2);
    out->azimuth = mipc_ld_s16(d + 4);
    out->elevation = mipc_ld_s16(d + 6);
    out->sv_flags = mipc_ld_u16(d + 8);
    out->valid_flags = mipc_ld_u16(d + 10);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_gnss_data_sv_info_decode_read(const uint8_t *data, size_t len,
                                                                      mipc_gnss_data_sv_info_t *out,
                                                                      mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_data_sv_info_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_data_sv_info_decode(const uint8_t *data, size_t len, mipc_gnss_data_sv_info_t *out,
                                            mipc_decode_error_t *err) {
    if (len == 12 && mipc_gnss_data_sv_info_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_data_sv_info_decode_read(data, len, out, err);
}

void mipc_gnss_data_sv_info_to_json(mipc_jw_t *w, const mipc_gnss_data_sv_info_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "channel");
    mipc_jw_u8(w, &in->channel);
    mipc_jw_key(w, &first, "sv_id");
    mipc_jw_u8(w, &in->sv_id);
    mipc_jw_key(w, &first, "carrier_to_noise_ratio");
    mipc_jw_u16(w, &in->carrier_to_noise_ratio);
    mipc_jw_key(w, &first, "azimuth");
    mipc_jw_s16(w, &in->azimuth);
    mipc_jw_key(w, &first, "elevation");
    mipc_jw_s16(w, &in->elevation);
    mipc_jw_key(w, &first, "sv_flags");
    mipc_jw_u16(w, &in->sv_flags);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_data_sv_info_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_data_sv_info_t *out) {
    static const char *const keys[] = {
        "channel", "sv_id", "carrier_to_noise_ratio", "azimuth", "elevation", "sv_flags", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 7)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "channel", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"channel\"");
    }
    {
        mipc_jr_push(jr, "channel");
        if (mipc_jr_u8(jr, vp, &out->channel)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "sv_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"sv_id\"");
    }
    {
        mipc_jr_push(jr, "sv_id");
        if (mipc_jr_u8(jr, vp, &out->sv_id)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "carrier_to_noise_ratio", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"carrier_to_noise_ratio\"");
    }
    {
        mipc_jr_push(jr, "carrier_to_noise_ratio");
        if (mipc_jr_u16(jr, vp, &out->carrier_to_noise_ratio)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "azimuth", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"azimuth\"");
    }
    {
        mipc_jr_push(jr, "azimuth");
        if (mipc_jr_s16(jr, vp, &out->azimuth)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "elevation", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"elevation\"");
    }
    {
        mipc_jr_push(jr, "elevation");
        if (mipc_jr_s16(jr, vp, &out->elevation)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "sv_flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"sv_flags\"");
    }
    {
        mipc_jr_push(jr, "sv_flags");
        if (mipc_jr_u16(jr, vp, &out->sv_flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mipc_jr_push(jr, "valid_flags");
        if (mipc_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_gnss_data_hardware_status_t */

static int mipc_gnss_data_hardware_status_read(mipc_reader_t *r, mipc_gnss_data_hardware_status_t *out) {
    mipc_rd_push(r, "receiver_state");
    if (mipc_rd_u8(r, &out->receiver_state)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "antenna_state");
    if (mipc_rd_u8(r, &out->antenna_state)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "antenna_power");
    if (mipc_rd_u8(r, &out->antenna_power)) {
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

static mipc_status_t mipc_gnss_data_hardware_status_write(mipc_writer_t *w,
                                                          const mipc_gnss_data_hardware_status_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->receiver_state)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->antenna_state)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->antenna_power)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_gnss_data_hardware_status_encode(const mipc_gnss_data_hardware_status_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_data_hardware_status_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 5 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_data_hardware_status_load(const uint8_t *d, mipc_gnss_data_hardware_status_t *out) {
    out->receiver_state = mipc_ld_u8(d + 0);
    out->antenna_state = mipc_ld_u8(d + 1);
    out->antenna_power = mipc_ld_u8(d + 2);
    out->valid_flags = mipc_ld_u16(d + 3);
    return 0;
}

/* The general reader: lengths other than 5, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_gnss_data_hardware_status_decode_read(
    const uint8_t *data, size_t len, mipc_gnss_data_hardware_status_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_data_hardware_status_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_data_hardware_status_decode(const uint8_t *data, size_t len,
                                                    mipc_gnss_data_hardware_status_t *out,
                                                    mipc_decode_error_t *err) {
    if (len == 5 && mipc_gnss_data_hardware_status_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_data_hardware_status_decode_read(data, len, out, err);
}

void mipc_gnss_data_hardware_status_to_json(mipc_jw_t *w, const mipc_gnss_data_hardware_status_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "receiver_state");
    mipc_jw_u8(w, &in->receiver_state);
    mipc_jw_key(w, &first, "antenna_state");
    mipc_jw_u8(w, &in->antenna_state);
    mipc_jw_key(w, &first, "antenna_power");
    mipc_jw_u8(w, &in->antenna_power);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_data_hardware_status_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_gnss_data_hardware_status_t *out) {
    static const char *const keys[] = {"receiver_state", "antenna_state", "antenna_power", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 4)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "receiver_state", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"receiver_state\"");
    }
    {
        mipc_jr_push(jr, "receiver_state");
        if (mipc_jr_u8(jr, vp, &out->receiver_state)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "antenna_state", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"antenna_state\"");
    }
    {
        mipc_jr_push(jr, "antenna_state");
        if (mipc_jr_u8(jr, vp, &out->antenna_state)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "antenna_power", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"antenna_power\"");
    }
    {
        mipc_jr_push(jr, "antenna_power");
        if (mipc_jr_u8(jr, vp, &out->antenna_power)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mipc_jr_push(jr, "valid_flags");
        if (mipc_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_gnss_data_dgnss_info_t */

static int mipc_gnss_data_dgnss_info_read(mipc_reader_t *r, mipc_gnss_data_dgnss_info_t *out) {
    mipc_rd_push(r, "newest_age");
    if (mipc_rd_f32(r, &out->newest_age)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "base_station_id");
    if (mipc_rd_s16(r, &out->base_station_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "base_station_status");
    if (mipc_rd_s16(r, &out->base_station_status)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "num_channels");
    if (mipc_rd_u16(r, &out->num_channels)) {
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

static mipc_status_t mipc_gnss_data_dgnss_info_write(mipc_writer_t *w,
                                                     const mipc_gnss_data_dgnss_info_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f32(w, &in->newest_age)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_s16(w, &in->base_station_id)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_s16(w, &in->base_station_status)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->num_channels)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_gnss_data_dgnss_info_encode(const mipc_gnss_data_dgnss_info_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_data_dgnss_info_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_data_dgnss_info_load(const uint8_t *d, mipc_gnss_data_dgnss_info_t *out) {
    out->newest_age = mipc_ld_f32(d + 0);
    out->base_station_id = mipc_ld_s16(d + 4);
    out->base_station_status = mipc_ld_s16(d + 6);
    out->num_channels = mipc_ld_u16(d + 8);
    out->valid_flags = mipc_ld_u16(d + 10);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_gnss_data_dgnss_info_decode_read(const uint8_t *data, size_t len,
                                                                         mipc_gnss_data_dgnss_info_t *out,
                                                                         mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_data_dgnss_info_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_data_dgnss_info_decode(const uint8_t *data, size_t len,
                                               mipc_gnss_data_dgnss_info_t *out, mipc_decode_error_t *err) {
    if (len == 12 && mipc_gnss_data_dgnss_info_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_data_dgnss_info_decode_read(data, len, out, err);
}

void mipc_gnss_data_dgnss_info_to_json(mipc_jw_t *w, const mipc_gnss_data_dgnss_info_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "newest_age");
    mipc_jw_f32(w, &in->newest_age);
    mipc_jw_key(w, &first, "base_station_id");
    mipc_jw_s16(w, &in->base_station_id);
    mipc_jw_key(w, &first, "base_station_status");
    mipc_jw_s16(w, &in->base_station_status);
    mipc_jw_key(w, &first, "num_channels");
    mipc_jw_u16(w, &in->num_channels);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_data_dgnss_info_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_data_dgnss_info_t *out) {
    static const char *const keys[] = {"newest_age", "base_station_id", "base_station_status", "num_channels",
                                       "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "newest_age", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"newest_age\"");
    }
    {
        mipc_jr_push(jr, "newest_age");
        if (mipc_jr_f32(jr, vp, &out->newest_age)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "base_station_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"base_station_id\"");
    }
    {
        mipc_jr_push(jr, "base_station_id");
        if (mipc_jr_s16(jr, vp, &out->base_station_id)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "base_station_status", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"base_station_status\"");
    }
    {
        mipc_jr_push(jr, "base_station_status");
        if (mipc_jr_s16(jr, vp, &out->base_station_status)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "num_channels", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"num_channels\"");
    }
    {
        mipc_jr_push(jr, "num_channels");
        if (mipc_jr_u16(jr, vp, &out->num_channels)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mipc_jr_push(jr, "valid_flags");
        if (mipc_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_gnss_data_dgnss_channel_status_t */

static int mipc_gnss_data_dgnss_channel_status_read(mipc_reader_t *r,
                                                    mipc_gnss_data_dgnss_channel_status_t *out) {
    mipc_rd_push(r, "sv_id");
    if (mipc_rd_u8(r, &out->sv_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "age");
    if (mipc_rd_f32(r, &out->age)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "pseudorange_correction");
    if (mipc_rd_f32(r, &out->pseudorange_correction)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "pseudorange_rate_correction");
    if (mipc_rd_f32(r, &out->pseudorange_rate_correction)) {
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
mipc_gnss_data_dgnss_channel_status_write(mipc_writer_t *w, const mipc_gnss_data_dgnss_channel_status_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->sv_id)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->age)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->pseudorange_correction)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->pseudorange_rate_correction)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_gnss_data_dgnss_channel_status_encode(const mipc_gnss_data_dgnss_channel_status_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_data_dgnss_channel_status_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 15 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_data_dgnss_channel_status_load(const uint8_t *d,
                                                    mipc_gnss_data_dgnss_channel_status_t *out) {
    out->sv_id = mipc_ld_u8(d + 0);
    out->age = mipc_ld_f32(d + 1);
    out->pseudorange_correction = mipc_ld_f32(d + 5);
    out->pseudorange_rate_correction = mipc_ld_f32(d + 9);
    out->valid_flags = mipc_ld_u16(d + 13);
    return 0;
}

/* The general reader: lengths other than 15, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_gnss_data_dgnss_channel_status_decode_read(
    const uint8_t *data, size_t len, mipc_gnss_data_dgnss_channel_status_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_data_dgnss_channel_status_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_data_dgnss_channel_status_decode(const uint8_t *data, size_t len,
                                                         mipc_gnss_data_dgnss_channel_status_t *out,
                                                         mipc_decode_error_t *err) {
    if (len == 15 && mipc_gnss_data_dgnss_channel_status_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_data_dgnss_channel_status_decode_read(data, len, out, err);
}

void mipc_gnss_data_dgnss_channel_status_to_json(mipc_jw_t *w,
                                                 const mipc_gnss_data_dgnss_channel_status_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "sv_id");
    mipc_jw_u8(w, &in->sv_id);
    mipc_jw_key(w, &first, "age");
    mipc_jw_f32(w, &in->age);
    mipc_jw_key(w, &first, "pseudorange_correction");
    mipc_jw_f32(w, &in->pseudorange_correction);
    mipc_jw_key(w, &first, "pseudorange_rate_correction");
    mipc_jw_f32(w, &in->pseudorange_rate_correction);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_data_dgnss_channel_status_from_json(mipc_jr_t *jr, size_t pos,
                                                  mipc_gnss_data_dgnss_channel_status_t *out) {
    static const char *const keys[] = {"sv_id", "age", "pseudorange_correction",
                                       "pseudorange_rate_correction", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "sv_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"sv_id\"");
    }
    {
        mipc_jr_push(jr, "sv_id");
        if (mipc_jr_u8(jr, vp, &out->sv_id)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "age", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"age\"");
    }
    {
        mipc_jr_push(jr, "age");
        if (mipc_jr_f32(jr, vp, &out->age)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "pseudorange_correction", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"pseudorange_correction\"");
    }
    {
        mipc_jr_push(jr, "pseudorange_correction");
        if (mipc_jr_f32(jr, vp, &out->pseudorange_correction)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "pseudorange_rate_correction", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"pseudorange_rate_correction\"");
    }
    {
        mipc_jr_push(jr, "pseudorange_rate_correction");
        if (mipc_jr_f32(jr, vp, &out->pseudorange_rate_correction)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mipc_jr_push(jr, "valid_flags");
        if (mipc_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}
