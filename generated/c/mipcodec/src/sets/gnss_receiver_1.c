/* Encoders and decoders of GNSS Receiver 1 Data Set. Generated from the spec: do not edit. */
#include "mipcodec/sets/gnss_receiver_1.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <stddef.h>
#include <string.h>

/* ---- mipc_gnss_receiver_1_llh_position_t */

static int mipc_gnss_receiver_1_llh_position_read(mipc_reader_t *r,
                                                  mipc_gnss_receiver_1_llh_position_t *out) {
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

static mipc_status_t mipc_gnss_receiver_1_llh_position_write(mipc_writer_t *w,
                                                             const mipc_gnss_receiver_1_llh_position_t *in) {
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

mipc_status_t mipc_gnss_receiver_1_llh_position_encode(const mipc_gnss_receiver_1_llh_position_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_receiver_1_llh_position_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 42 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_receiver_1_llh_position_load(const uint8_t *d,
                                                  mipc_gnss_receiver_1_llh_position_t *out) {
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
static MIPC_NOINLINE mipc_status_t mipc_gnss_receiver_1_llh_position_decode_read(
    const uint8_t *data, size_t len, mipc_gnss_receiver_1_llh_position_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_receiver_1_llh_position_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_receiver_1_llh_position_decode(const uint8_t *data, size_t len,
                                                       mipc_gnss_receiver_1_llh_position_t *out,
                                                       mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 42 && mipc_gnss_receiver_1_llh_position_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_receiver_1_llh_position_decode_read(data, len, out, err);
}

/* ---- mipc_gnss_receiver_1_ecef_position_t */

static int mipc_gnss_receiver_1_ecef_position_read(mipc_reader_t *r,
                                                   mipc_gnss_receiver_1_ecef_position_t *out) {
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

static mipc_status_t
mipc_gnss_receiver_1_ecef_position_write(mipc_writer_t *w, const mipc_gnss_receiver_1_ecef_position_t *in) {
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

mipc_status_t mipc_gnss_receiver_1_ecef_position_encode(const mipc_gnss_receiver_1_ecef_position_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_receiver_1_ecef_position_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 30 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_receiver_1_ecef_position_load(const uint8_t *d,
                                                   mipc_gnss_receiver_1_ecef_position_t *out) {
    out->position[0] = mipc_ld_f64(d + 0);
    out->position[1] = mipc_ld_f64(d + 8);
    out->position[2] = mipc_ld_f64(d + 16);
    out->position_accuracy = mipc_ld_f32(d + 24);
    out->valid_flags = mipc_ld_u16(d + 28);
    return 0;
}

/* The general reader: lengths other than 30, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_gnss_receiver_1_ecef_position_decode_read(
    const uint8_t *data, size_t len, mipc_gnss_receiver_1_ecef_position_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_receiver_1_ecef_position_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_receiver_1_ecef_position_decode(const uint8_t *data, size_t len,
                                                        mipc_gnss_receiver_1_ecef_position_t *out,
                                                        mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 30 && mipc_gnss_receiver_1_ecef_position_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_receiver_1_ecef_position_decode_read(data, len, out, err);
}

/* ---- mipc_gnss_receiver_1_ned_velocity_t */

static int mipc_gnss_receiver_1_ned_velocity_read(mipc_reader_t *r,
                                                  mipc_gnss_receiver_1_ned_velocity_t *out) {
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

static mipc_status_t mipc_gnss_receiver_1_ned_velocity_write(mipc_writer_t *w,
                                                             const mipc_gnss_receiver_1_ned_velocity_t *in) {
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

mipc_status_t mipc_gnss_receiver_1_ned_velocity_encode(const mipc_gnss_receiver_1_ned_velocity_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_receiver_1_ned_velocity_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 34 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_receiver_1_ned_velocity_load(const uint8_t *d,
                                                  mipc_gnss_receiver_1_ned_velocity_t *out) {
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
static MIPC_NOINLINE mipc_status_t mipc_gnss_receiver_1_ned_velocity_decode_read(
    const uint8_t *data, size_t len, mipc_gnss_receiver_1_ned_velocity_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_receiver_1_ned_velocity_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_receiver_1_ned_velocity_decode(const uint8_t *data, size_t len,
                                                       mipc_gnss_receiver_1_ned_velocity_t *out,
                                                       mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 34 && mipc_gnss_receiver_1_ned_velocity_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_receiver_1_ned_velocity_decode_read(data, len, out, err);
}

/* ---- mipc_gnss_receiver_1_ecef_velocity_t */

static int mipc_gnss_receiver_1_ecef_velocity_read(mipc_reader_t *r,
                                                   mipc_gnss_receiver_1_ecef_velocity_t *out) {
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

static mipc_status_t
mipc_gnss_receiver_1_ecef_velocity_write(mipc_writer_t *w, const mipc_gnss_receiver_1_ecef_velocity_t *in) {
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

mipc_status_t mipc_gnss_receiver_1_ecef_velocity_encode(const mipc_gnss_receiver_1_ecef_velocity_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_receiver_1_ecef_velocity_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 18 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_receiver_1_ecef_velocity_load(const uint8_t *d,
                                                   mipc_gnss_receiver_1_ecef_velocity_t *out) {
    out->velocity[0] = mipc_ld_f32(d + 0);
    out->velocity[1] = mipc_ld_f32(d + 4);
    out->velocity[2] = mipc_ld_f32(d + 8);
    out->velocity_accuracy = mipc_ld_f32(d + 12);
    out->valid_flags = mipc_ld_u16(d + 16);
    return 0;
}

/* The general reader: lengths other than 18, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_gnss_receiver_1_ecef_velocity_decode_read(
    const uint8_t *data, size_t len, mipc_gnss_receiver_1_ecef_velocity_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_receiver_1_ecef_velocity_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_receiver_1_ecef_velocity_decode(const uint8_t *data, size_t len,
                                                        mipc_gnss_receiver_1_ecef_velocity_t *out,
                                                        mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 18 && mipc_gnss_receiver_1_ecef_velocity_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_receiver_1_ecef_velocity_decode_read(data, len, out, err);
}

/* ---- mipc_gnss_receiver_1_dop_t */

static int mipc_gnss_receiver_1_dop_read(mipc_reader_t *r, mipc_gnss_receiver_1_dop_t *out) {
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

static mipc_status_t mipc_gnss_receiver_1_dop_write(mipc_writer_t *w, const mipc_gnss_receiver_1_dop_t *in) {
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

mipc_status_t mipc_gnss_receiver_1_dop_encode(const mipc_gnss_receiver_1_dop_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_receiver_1_dop_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 30 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_receiver_1_dop_load(const uint8_t *d, mipc_gnss_receiver_1_dop_t *out) {
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
static MIPC_NOINLINE mipc_status_t mipc_gnss_receiver_1_dop_decode_read(const uint8_t *data, size_t len,
                                                                        mipc_gnss_receiver_1_dop_t *out,
                                                                        mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_receiver_1_dop_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_receiver_1_dop_decode(const uint8_t *data, size_t len,
                                              mipc_gnss_receiver_1_dop_t *out, mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 30 && mipc_gnss_receiver_1_dop_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_receiver_1_dop_decode_read(data, len, out, err);
}

/* ---- mipc_gnss_receiver_1_utc_time_t */

static int mipc_gnss_receiver_1_utc_time_read(mipc_reader_t *r, mipc_gnss_receiver_1_utc_time_t *out) {
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

static mipc_status_t mipc_gnss_receiver_1_utc_time_write(mipc_writer_t *w,
                                                         const mipc_gnss_receiver_1_utc_time_t *in) {
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

mipc_status_t mipc_gnss_receiver_1_utc_time_encode(const mipc_gnss_receiver_1_utc_time_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_receiver_1_utc_time_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 13 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_receiver_1_utc_time_load(const uint8_t *d, mipc_gnss_receiver_1_utc_time_t *out) {
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
static MIPC_NOINLINE mipc_status_t mipc_gnss_receiver_1_utc_time_decode_read(
    const uint8_t *data, size_t len, mipc_gnss_receiver_1_utc_time_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_receiver_1_utc_time_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_receiver_1_utc_time_decode(const uint8_t *data, size_t len,
                                                   mipc_gnss_receiver_1_utc_time_t *out,
                                                   mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 13 && mipc_gnss_receiver_1_utc_time_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_receiver_1_utc_time_decode_read(data, len, out, err);
}

/* ---- mipc_gnss_receiver_1_gps_time_t */

static int mipc_gnss_receiver_1_gps_time_read(mipc_reader_t *r, mipc_gnss_receiver_1_gps_time_t *out) {
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

static mipc_status_t mipc_gnss_receiver_1_gps_time_write(mipc_writer_t *w,
                                                         const mipc_gnss_receiver_1_gps_time_t *in) {
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

mipc_status_t mipc_gnss_receiver_1_gps_time_encode(const mipc_gnss_receiver_1_gps_time_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_receiver_1_gps_time_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_receiver_1_gps_time_load(const uint8_t *d, mipc_gnss_receiver_1_gps_time_t *out) {
    out->tow = mipc_ld_f64(d + 0);
    out->week_number = mipc_ld_u16(d + 8);
    out->valid_flags = mipc_ld_u16(d + 10);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_gnss_receiver_1_gps_time_decode_read(
    const uint8_t *data, size_t len, mipc_gnss_receiver_1_gps_time_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_receiver_1_gps_time_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_receiver_1_gps_time_decode(const uint8_t *data, size_t len,
                                                   mipc_gnss_receiver_1_gps_time_t *out,
                                                   mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mipc_gnss_receiver_1_gps_time_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_receiver_1_gps_time_decode_read(data, len, out, err);
}

/* ---- mipc_gnss_receiver_1_fix_info_t */

static int mipc_gnss_receiver_1_fix_info_read(mipc_reader_t *r, mipc_gnss_receiver_1_fix_info_t *out) {
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

static mipc_status_t mipc_gnss_receiver_1_fix_info_write(mipc_writer_t *w,
                                                         const mipc_gnss_receiver_1_fix_info_t *in) {
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

mipc_status_t mipc_gnss_receiver_1_fix_info_encode(const mipc_gnss_receiver_1_fix_info_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_receiver_1_fix_info_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 6 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_receiver_1_fix_info_load(const uint8_t *d, mipc_gnss_receiver_1_fix_info_t *out) {
    out->fix_type = mipc_ld_u8(d + 0);
    out->num_sv = mipc_ld_u8(d + 1);
    out->fix_flags = mipc_ld_u16(d + 2);
    out->valid_flags = mipc_ld_u16(d + 4);
    return 0;
}

/* The general reader: lengths other than 6, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_gnss_receiver_1_fix_info_decode_read(
    const uint8_t *data, size_t len, mipc_gnss_receiver_1_fix_info_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_receiver_1_fix_info_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_receiver_1_fix_info_decode(const uint8_t *data, size_t len,
                                                   mipc_gnss_receiver_1_fix_info_t *out,
                                                   mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 6 && mipc_gnss_receiver_1_fix_info_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_receiver_1_fix_info_decode_read(data, len, out, err);
}

/* ---- mipc_gnss_receiver_1_hardware_status_t */

static int mipc_gnss_receiver_1_hardware_status_read(mipc_reader_t *r,
                                                     mipc_gnss_receiver_1_hardware_status_t *out) {
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

static mipc_status_t
mipc_gnss_receiver_1_hardware_status_write(mipc_writer_t *w,
                                           const mipc_gnss_receiver_1_hardware_status_t *in) {
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

mipc_status_t mipc_gnss_receiver_1_hardware_status_encode(const mipc_gnss_receiver_1_hardware_status_t *value,
                                                          uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_receiver_1_hardware_status_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 5 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_receiver_1_hardware_status_load(const uint8_t *d,
                                                     mipc_gnss_receiver_1_hardware_status_t *out) {
    out->receiver_state = mipc_ld_u8(d + 0);
    out->antenna_state = mipc_ld_u8(d + 1);
    out->antenna_power = mipc_ld_u8(d + 2);
    out->valid_flags = mipc_ld_u16(d + 3);
    return 0;
}

/* The general reader: lengths other than 5, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_gnss_receiver_1_hardware_status_decode_read(
    const uint8_t *data, size_t len, mipc_gnss_receiver_1_hardware_status_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_receiver_1_hardware_status_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_receiver_1_hardware_status_decode(const uint8_t *data, size_t len,
                                                          mipc_gnss_receiver_1_hardware_status_t *out,
                                                          mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 5 && mipc_gnss_receiver_1_hardware_status_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_receiver_1_hardware_status_decode_read(data, len, out, err);
}

/* ---- mipc_gnss_receiver_1_clock_info_2_t */

static int mipc_gnss_receiver_1_clock_info_2_read(mipc_reader_t *r,
                                                  mipc_gnss_receiver_1_clock_info_2_t *out) {
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
    mipc_rd_push(r, "bias_accuracy_estimate");
    if (mipc_rd_f64(r, &out->bias_accuracy_estimate)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "drift_accuracy_estimate");
    if (mipc_rd_f64(r, &out->drift_accuracy_estimate)) {
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

static mipc_status_t mipc_gnss_receiver_1_clock_info_2_write(mipc_writer_t *w,
                                                             const mipc_gnss_receiver_1_clock_info_2_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f64(w, &in->bias)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->drift)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->bias_accuracy_estimate)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->drift_accuracy_estimate)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_gnss_receiver_1_clock_info_2_encode(const mipc_gnss_receiver_1_clock_info_2_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_receiver_1_clock_info_2_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 34 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_receiver_1_clock_info_2_load(const uint8_t *d,
                                                  mipc_gnss_receiver_1_clock_info_2_t *out) {
    out->bias = mipc_ld_f64(d + 0);
    out->drift = mipc_ld_f64(d + 8);
    out->bias_accuracy_estimate = mipc_ld_f64(d + 16);
    out->drift_accuracy_estimate = mipc_ld_f64(d + 24);
    out->valid_flags = mipc_ld_u16(d + 32);
    return 0;
}

/* The general reader: lengths other than 34, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_gnss_receiver_1_clock_info_2_decode_read(
    const uint8_t *data, size_t len, mipc_gnss_receiver_1_clock_info_2_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_receiver_1_clock_info_2_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_receiver_1_clock_info_2_decode(const uint8_t *data, size_t len,
                                                       mipc_gnss_receiver_1_clock_info_2_t *out,
                                                       mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 34 && mipc_gnss_receiver_1_clock_info_2_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_receiver_1_clock_info_2_decode_read(data, len, out, err);
}

/* ---- mipc_gnss_receiver_1_gps_leap_seconds_t */

static int mipc_gnss_receiver_1_gps_leap_seconds_read(mipc_reader_t *r,
                                                      mipc_gnss_receiver_1_gps_leap_seconds_t *out) {
    mipc_rd_push(r, "leap_seconds");
    if (mipc_rd_u8(r, &out->leap_seconds)) {
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
mipc_gnss_receiver_1_gps_leap_seconds_write(mipc_writer_t *w,
                                            const mipc_gnss_receiver_1_gps_leap_seconds_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->leap_seconds)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_gnss_receiver_1_gps_leap_seconds_encode(const mipc_gnss_receiver_1_gps_leap_seconds_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_receiver_1_gps_leap_seconds_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 3 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_receiver_1_gps_leap_seconds_load(const uint8_t *d,
                                                      mipc_gnss_receiver_1_gps_leap_seconds_t *out) {
    out->leap_seconds = mipc_ld_u8(d + 0);
    out->valid_flags = mipc_ld_u16(d + 1);
    return 0;
}

/* The general reader: lengths other than 3, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_gnss_receiver_1_gps_leap_seconds_decode_read(
    const uint8_t *data, size_t len, mipc_gnss_receiver_1_gps_leap_seconds_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_receiver_1_gps_leap_seconds_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_receiver_1_gps_leap_seconds_decode(const uint8_t *data, size_t len,
                                                           mipc_gnss_receiver_1_gps_leap_seconds_t *out,
                                                           mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 3 && mipc_gnss_receiver_1_gps_leap_seconds_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_receiver_1_gps_leap_seconds_decode_read(data, len, out, err);
}

/* ---- mipc_gnss_receiver_1_sbas_info_t */

static int mipc_gnss_receiver_1_sbas_info_read(mipc_reader_t *r, mipc_gnss_receiver_1_sbas_info_t *out) {
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
    mipc_rd_push(r, "sbas_system");
    if (mipc_rd_u8(r, &out->sbas_system)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "sbas_id");
    if (mipc_rd_u8(r, &out->sbas_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "count");
    if (mipc_rd_u8(r, &out->count)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "sbas_status");
    if (mipc_rd_u8(r, &out->sbas_status)) {
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

static mipc_status_t mipc_gnss_receiver_1_sbas_info_write(mipc_writer_t *w,
                                                          const mipc_gnss_receiver_1_sbas_info_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f64(w, &in->tow)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->week_number)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->sbas_system)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->sbas_id)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->count)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->sbas_status)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_gnss_receiver_1_sbas_info_encode(const mipc_gnss_receiver_1_sbas_info_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_receiver_1_sbas_info_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 16 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_receiver_1_sbas_info_load(const uint8_t *d, mipc_gnss_receiver_1_sbas_info_t *out) {
    out->tow = mipc_ld_f64(d + 0);
    out->week_number = mipc_ld_u16(d + 8);
    out->sbas_system = mipc_ld_u8(d + 10);
    out->sbas_id = mipc_ld_u8(d + 11);
    out->count = mipc_ld_u8(d + 12);
    out->sbas_status = mipc_ld_u8(d + 13);
    out->valid_flags = mipc_ld_u16(d + 14);
    return 0;
}

/* The general reader: lengths other than 16, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_gnss_receiver_1_sbas_info_decode_read(
    const uint8_t *data, size_t len, mipc_gnss_receiver_1_sbas_info_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_receiver_1_sbas_info_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_receiver_1_sbas_info_decode(const uint8_t *data, size_t len,
                                                    mipc_gnss_receiver_1_sbas_info_t *out,
                                                    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 16 && mipc_gnss_receiver_1_sbas_info_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_receiver_1_sbas_info_decode_read(data, len, out, err);
}

/* ---- mipc_gnss_receiver_1_satellite_status_t */

static int mipc_gnss_receiver_1_satellite_status_read(mipc_reader_t *r,
                                                      mipc_gnss_receiver_1_satellite_status_t *out) {
    mipc_rd_push(r, "index");
    if (mipc_rd_u8(r, &out->index)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "count");
    if (mipc_rd_u8(r, &out->count)) {
        return -1;
    }
    mipc_rd_pop(r);
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
    mipc_rd_push(r, "gnss_id");
    if (mipc_rd_u8(r, &out->gnss_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "satellite_id");
    if (mipc_rd_u8(r, &out->satellite_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "elevation");
    if (mipc_rd_f32(r, &out->elevation)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "azimuth");
    if (mipc_rd_f32(r, &out->azimuth)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "health");
    if (mipc_rd_bool(r, &out->health)) {
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
mipc_gnss_receiver_1_satellite_status_write(mipc_writer_t *w,
                                            const mipc_gnss_receiver_1_satellite_status_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->index)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->count)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->tow)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->week_number)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->gnss_id)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->satellite_id)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->elevation)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->azimuth)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_bool(w, &in->health)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_gnss_receiver_1_satellite_status_encode(const mipc_gnss_receiver_1_satellite_status_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_receiver_1_satellite_status_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 25 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_receiver_1_satellite_status_load(const uint8_t *d,
                                                      mipc_gnss_receiver_1_satellite_status_t *out) {
    out->index = mipc_ld_u8(d + 0);
    out->count = mipc_ld_u8(d + 1);
    out->tow = mipc_ld_f64(d + 2);
    out->week_number = mipc_ld_u16(d + 10);
    out->gnss_id = mipc_ld_u8(d + 12);
    out->satellite_id = mipc_ld_u8(d + 13);
    out->elevation = mipc_ld_f32(d + 14);
    out->azimuth = mipc_ld_f32(d + 18);
    if (d[22] > 1) {
        return -1;
    }
    out->health = mipc_ld_bool(d + 22);
    out->valid_flags = mipc_ld_u16(d + 23);
    return 0;
}

/* The general reader: lengths other than 25, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_gnss_receiver_1_satellite_status_decode_read(
    const uint8_t *data, size_t len, mipc_gnss_receiver_1_satellite_status_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_receiver_1_satellite_status_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_receiver_1_satellite_status_decode(const uint8_t *data, size_t len,
                                                           mipc_gnss_receiver_1_satellite_status_t *out,
                                                           mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 25 && mipc_gnss_receiver_1_satellite_status_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_receiver_1_satellite_status_decode_read(data, len, out, err);
}

/* ---- mipc_gnss_receiver_1_raw_t */

static int mipc_gnss_receiver_1_raw_read(mipc_reader_t *r, mipc_gnss_receiver_1_raw_t *out) {
    mipc_rd_push(r, "index");
    if (mipc_rd_u8(r, &out->index)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "count");
    if (mipc_rd_u8(r, &out->count)) {
        return -1;
    }
    mipc_rd_pop(r);
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
    mipc_rd_push(r, "receiver_id");
    if (mipc_rd_u16(r, &out->receiver_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "tracking_channel");
    if (mipc_rd_u8(r, &out->tracking_channel)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "gnss_id");
    if (mipc_rd_u8(r, &out->gnss_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "satellite_id");
    if (mipc_rd_u8(r, &out->satellite_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "signal_id");
    if (mipc_rd_u8(r, &out->signal_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "signal_strength");
    if (mipc_rd_f32(r, &out->signal_strength)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "quality");
    if (mipc_rd_u8(r, &out->quality)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "pseudorange");
    if (mipc_rd_f64(r, &out->pseudorange)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "carrier_phase");
    if (mipc_rd_f64(r, &out->carrier_phase)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "doppler");
    if (mipc_rd_f32(r, &out->doppler)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "range_uncert");
    if (mipc_rd_f32(r, &out->range_uncert)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "phase_uncert");
    if (mipc_rd_f32(r, &out->phase_uncert)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "doppler_uncert");
    if (mipc_rd_f32(r, &out->doppler_uncert)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "lock_time");
    if (mipc_rd_f32(r, &out->lock_time)) {
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

static mipc_status_t mipc_gnss_receiver_1_raw_write(mipc_writer_t *w, const mipc_gnss_receiver_1_raw_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->index)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->count)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->tow)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->week_number)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->receiver_id)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->tracking_channel)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->gnss_id)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->satellite_id)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->signal_id)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->signal_strength)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->quality)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->pseudorange)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->carrier_phase)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->doppler)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->range_uncert)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->phase_uncert)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->doppler_uncert)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->lock_time)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_gnss_receiver_1_raw_encode(const mipc_gnss_receiver_1_raw_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_receiver_1_raw_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 61 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_receiver_1_raw_load(const uint8_t *d, mipc_gnss_receiver_1_raw_t *out) {
    out->index = mipc_ld_u8(d + 0);
    out->count = mipc_ld_u8(d + 1);
    out->tow = mipc_ld_f64(d + 2);
    out->week_number = mipc_ld_u16(d + 10);
    out->receiver_id = mipc_ld_u16(d + 12);
    out->tracking_channel = mipc_ld_u8(d + 14);
    out->gnss_id = mipc_ld_u8(d + 15);
    out->satellite_id = mipc_ld_u8(d + 16);
    out->signal_id = mipc_ld_u8(d + 17);
    out->signal_strength = mipc_ld_f32(d + 18);
    out->quality = mipc_ld_u8(d + 22);
    out->pseudorange = mipc_ld_f64(d + 23);
    out->carrier_phase = mipc_ld_f64(d + 31);
    out->doppler = mipc_ld_f32(d + 39);
    out->range_uncert = mipc_ld_f32(d + 43);
    out->phase_uncert = mipc_ld_f32(d + 47);
    out->doppler_uncert = mipc_ld_f32(d + 51);
    out->lock_time = mipc_ld_f32(d + 55);
    out->valid_flags = mipc_ld_u16(d + 59);
    return 0;
}

/* The general reader: lengths other than 61, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_gnss_receiver_1_raw_decode_read(const uint8_t *data, size_t len,
                                                                        mipc_gnss_receiver_1_raw_t *out,
                                                                        mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_receiver_1_raw_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_receiver_1_raw_decode(const uint8_t *data, size_t len,
                                              mipc_gnss_receiver_1_raw_t *out, mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 61 && mipc_gnss_receiver_1_raw_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_receiver_1_raw_decode_read(data, len, out, err);
}

/* ---- mipc_gnss_receiver_1_gps_ephemeris_t */

static int mipc_gnss_receiver_1_gps_ephemeris_read(mipc_reader_t *r,
                                                   mipc_gnss_receiver_1_gps_ephemeris_t *out) {
    mipc_rd_push(r, "index");
    if (mipc_rd_u8(r, &out->index)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "count");
    if (mipc_rd_u8(r, &out->count)) {
        return -1;
    }
    mipc_rd_pop(r);
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
    mipc_rd_push(r, "satellite_id");
    if (mipc_rd_u8(r, &out->satellite_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "health");
    if (mipc_rd_u8(r, &out->health)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "iodc");
    if (mipc_rd_u8(r, &out->iodc)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "iode");
    if (mipc_rd_u8(r, &out->iode)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "t_oc");
    if (mipc_rd_f64(r, &out->t_oc)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "af0");
    if (mipc_rd_f64(r, &out->af0)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "af1");
    if (mipc_rd_f64(r, &out->af1)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "af2");
    if (mipc_rd_f64(r, &out->af2)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "t_gd");
    if (mipc_rd_f64(r, &out->t_gd)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "isc_l1ca");
    if (mipc_rd_f64(r, &out->isc_l1ca)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "isc_l2c");
    if (mipc_rd_f64(r, &out->isc_l2c)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "t_oe");
    if (mipc_rd_f64(r, &out->t_oe)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "a");
    if (mipc_rd_f64(r, &out->a)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "a_dot");
    if (mipc_rd_f64(r, &out->a_dot)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "mean_anomaly");
    if (mipc_rd_f64(r, &out->mean_anomaly)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "delta_mean_motion");
    if (mipc_rd_f64(r, &out->delta_mean_motion)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "delta_mean_motion_dot");
    if (mipc_rd_f64(r, &out->delta_mean_motion_dot)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "eccentricity");
    if (mipc_rd_f64(r, &out->eccentricity)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "argument_of_perigee");
    if (mipc_rd_f64(r, &out->argument_of_perigee)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "omega");
    if (mipc_rd_f64(r, &out->omega)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "omega_dot");
    if (mipc_rd_f64(r, &out->omega_dot)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "inclination");
    if (mipc_rd_f64(r, &out->inclination)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "inclination_dot");
    if (mipc_rd_f64(r, &out->inclination_dot)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "c_ic");
    if (mipc_rd_f64(r, &out->c_ic)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "c_is");
    if (mipc_rd_f64(r, &out->c_is)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "c_uc");
    if (mipc_rd_f64(r, &out->c_uc)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "c_us");
    if (mipc_rd_f64(r, &out->c_us)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "c_rc");
    if (mipc_rd_f64(r, &out->c_rc)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "c_rs");
    if (mipc_rd_f64(r, &out->c_rs)) {
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
mipc_gnss_receiver_1_gps_ephemeris_write(mipc_writer_t *w, const mipc_gnss_receiver_1_gps_ephemeris_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->index)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->count)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->tow)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->week_number)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->satellite_id)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->health)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->iodc)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->iode)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->t_oc)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->af0)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->af1)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->af2)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->t_gd)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->isc_l1ca)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->isc_l2c)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->t_oe)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->a)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->a_dot)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->mean_anomaly)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->delta_mean_motion)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->delta_mean_motion_dot)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->eccentricity)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->argument_of_perigee)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->omega)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->omega_dot)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->inclination)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->inclination_dot)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->c_ic)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->c_is)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->c_uc)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->c_us)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->c_rc)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->c_rs)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_gnss_receiver_1_gps_ephemeris_encode(const mipc_gnss_receiver_1_gps_ephemeris_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_receiver_1_gps_ephemeris_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 218 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_receiver_1_gps_ephemeris_load(const uint8_t *d,
                                                   mipc_gnss_receiver_1_gps_ephemeris_t *out) {
    out->index = mipc_ld_u8(d + 0);
    out->count = mipc_ld_u8(d + 1);
    out->tow = mipc_ld_f64(d + 2);
    out->week_number = mipc_ld_u16(d + 10);
    out->satellite_id = mipc_ld_u8(d + 12);
    out->health = mipc_ld_u8(d + 13);
    out->iodc = mipc_ld_u8(d + 14);
    out->iode = mipc_ld_u8(d + 15);
    out->t_oc = mipc_ld_f64(d + 16);
    out->af0 = mipc_ld_f64(d + 24);
    out->af1 = mipc_ld_f64(d + 32);
    out->af2 = mipc_ld_f64(d + 40);
    out->t_gd = mipc_ld_f64(d + 48);
    out->isc_l1ca = mipc_ld_f64(d + 56);
    out->isc_l2c = mipc_ld_f64(d + 64);
    out->t_oe = mipc_ld_f64(d + 72);
    out->a = mipc_ld_f64(d + 80);
    out->a_dot = mipc_ld_f64(d + 88);
    out->mean_anomaly = mipc_ld_f64(d + 96);
    out->delta_mean_motion = mipc_ld_f64(d + 104);
    out->delta_mean_motion_dot = mipc_ld_f64(d + 112);
    out->eccentricity = mipc_ld_f64(d + 120);
    out->argument_of_perigee = mipc_ld_f64(d + 128);
    out->omega = mipc_ld_f64(d + 136);
    out->omega_dot = mipc_ld_f64(d + 144);
    out->inclination = mipc_ld_f64(d + 152);
    out->inclination_dot = mipc_ld_f64(d + 160);
    out->c_ic = mipc_ld_f64(d + 168);
    out->c_is = mipc_ld_f64(d + 176);
    out->c_uc = mipc_ld_f64(d + 184);
    out->c_us = mipc_ld_f64(d + 192);
    out->c_rc = mipc_ld_f64(d + 200);
    out->c_rs = mipc_ld_f64(d + 208);
    out->valid_flags = mipc_ld_u16(d + 216);
    return 0;
}

/* The general reader: lengths other than 218, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_gnss_receiver_1_gps_ephemeris_decode_read(
    const uint8_t *data, size_t len, mipc_gnss_receiver_1_gps_ephemeris_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_receiver_1_gps_ephemeris_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_receiver_1_gps_ephemeris_decode(const uint8_t *data, size_t len,
                                                        mipc_gnss_receiver_1_gps_ephemeris_t *out,
                                                        mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 218 && mipc_gnss_receiver_1_gps_ephemeris_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_receiver_1_gps_ephemeris_decode_read(data, len, out, err);
}

/* ---- mipc_gnss_receiver_1_glonass_ephemeris_t */

static int mipc_gnss_receiver_1_glonass_ephemeris_read(mipc_reader_t *r,
                                                       mipc_gnss_receiver_1_glonass_ephemeris_t *out) {
    size_t i;
    mipc_rd_push(r, "index");
    if (mipc_rd_u8(r, &out->index)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "count");
    if (mipc_rd_u8(r, &out->count)) {
        return -1;
    }
    mipc_rd_pop(r);
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
    mipc_rd_push(r, "satellite_id");
    if (mipc_rd_u8(r, &out->satellite_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "freq_number");
    if (mipc_rd_s8(r, &out->freq_number)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "tk");
    if (mipc_rd_u32(r, &out->tk)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "tb");
    if (mipc_rd_u32(r, &out->tb)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "sat_type");
    if (mipc_rd_u8(r, &out->sat_type)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "gamma");
    if (mipc_rd_f64(r, &out->gamma)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "tau_n");
    if (mipc_rd_f64(r, &out->tau_n)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "x");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f64(r, &out->x[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "v");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->v[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "a");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->a[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "health");
    if (mipc_rd_u8(r, &out->health)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "p");
    if (mipc_rd_u8(r, &out->p)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "nt");
    if (mipc_rd_u8(r, &out->nt)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "delta_tau_n");
    if (mipc_rd_f32(r, &out->delta_tau_n)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "ft");
    if (mipc_rd_u8(r, &out->ft)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "en");
    if (mipc_rd_u8(r, &out->en)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "p1");
    if (mipc_rd_u8(r, &out->p1)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "p2");
    if (mipc_rd_u8(r, &out->p2)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "p3");
    if (mipc_rd_u8(r, &out->p3)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "p4");
    if (mipc_rd_u8(r, &out->p4)) {
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
mipc_gnss_receiver_1_glonass_ephemeris_write(mipc_writer_t *w,
                                             const mipc_gnss_receiver_1_glonass_ephemeris_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->index)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->count)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->tow)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->week_number)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->satellite_id)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_s8(w, &in->freq_number)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u32(w, &in->tk)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u32(w, &in->tb)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->sat_type)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->gamma)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->tau_n)) != MIPC_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f64(w, &in->x[i])) != MIPC_OK) {
            return st;
        }
    }
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->v[i])) != MIPC_OK) {
            return st;
        }
    }
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->a[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u8(w, &in->health)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->p)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->nt)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->delta_tau_n)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->ft)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->en)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->p1)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->p2)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->p3)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->p4)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_gnss_receiver_1_glonass_ephemeris_encode(const mipc_gnss_receiver_1_glonass_ephemeris_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_receiver_1_glonass_ephemeris_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 102 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_receiver_1_glonass_ephemeris_load(const uint8_t *d,
                                                       mipc_gnss_receiver_1_glonass_ephemeris_t *out) {
    out->index = mipc_ld_u8(d + 0);
    out->count = mipc_ld_u8(d + 1);
    out->tow = mipc_ld_f64(d + 2);
    out->week_number = mipc_ld_u16(d + 10);
    out->satellite_id = mipc_ld_u8(d + 12);
    out->freq_number = mipc_ld_s8(d + 13);
    out->tk = mipc_ld_u32(d + 14);
    out->tb = mipc_ld_u32(d + 18);
    out->sat_type = mipc_ld_u8(d + 22);
    out->gamma = mipc_ld_f64(d + 23);
    out->tau_n = mipc_ld_f64(d + 31);
    out->x[0] = mipc_ld_f64(d + 39);
    out->x[1] = mipc_ld_f64(d + 47);
    out->x[2] = mipc_ld_f64(d + 55);
    out->v[0] = mipc_ld_f32(d + 63);
    out->v[1] = mipc_ld_f32(d + 67);
    out->v[2] = mipc_ld_f32(d + 71);
    out->a[0] = mipc_ld_f32(d + 75);
    out->a[1] = mipc_ld_f32(d + 79);
    out->a[2] = mipc_ld_f32(d + 83);
    out->health = mipc_ld_u8(d + 87);
    out->p = mipc_ld_u8(d + 88);
    out->nt = mipc_ld_u8(d + 89);
    out->delta_tau_n = mipc_ld_f32(d + 90);
    out->ft = mipc_ld_u8(d + 94);
    out->en = mipc_ld_u8(d + 95);
    out->p1 = mipc_ld_u8(d + 96);
    out->p2 = mipc_ld_u8(d + 97);
    out->p3 = mipc_ld_u8(d + 98);
    out->p4 = mipc_ld_u8(d + 99);
    out->valid_flags = mipc_ld_u16(d + 100);
    return 0;
}

/* The general reader: lengths other than 102, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_gnss_receiver_1_glonass_ephemeris_decode_read(
    const uint8_t *data, size_t len, mipc_gnss_receiver_1_glonass_ephemeris_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_receiver_1_glonass_ephemeris_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_receiver_1_glonass_ephemeris_decode(const uint8_t *data, size_t len,
                                                            mipc_gnss_receiver_1_glonass_ephemeris_t *out,
                                                            mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 102 && mipc_gnss_receiver_1_glonass_ephemeris_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_receiver_1_glonass_ephemeris_decode_read(data, len, out, err);
}

/* ---- mipc_gnss_receiver_1_galileo_ephemeris_t */

static int mipc_gnss_receiver_1_galileo_ephemeris_read(mipc_reader_t *r,
                                                       mipc_gnss_receiver_1_galileo_ephemeris_t *out) {
    mipc_rd_push(r, "index");
    if (mipc_rd_u8(r, &out->index)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "count");
    if (mipc_rd_u8(r, &out->count)) {
        return -1;
    }
    mipc_rd_pop(r);
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
    mipc_rd_push(r, "satellite_id");
    if (mipc_rd_u8(r, &out->satellite_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "health");
    if (mipc_rd_u8(r, &out->health)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "iodc");
    if (mipc_rd_u8(r, &out->iodc)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "iode");
    if (mipc_rd_u8(r, &out->iode)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "t_oc");
    if (mipc_rd_f64(r, &out->t_oc)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "af0");
    if (mipc_rd_f64(r, &out->af0)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "af1");
    if (mipc_rd_f64(r, &out->af1)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "af2");
    if (mipc_rd_f64(r, &out->af2)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "t_gd");
    if (mipc_rd_f64(r, &out->t_gd)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "isc_l1ca");
    if (mipc_rd_f64(r, &out->isc_l1ca)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "isc_l2c");
    if (mipc_rd_f64(r, &out->isc_l2c)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "t_oe");
    if (mipc_rd_f64(r, &out->t_oe)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "a");
    if (mipc_rd_f64(r, &out->a)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "a_dot");
    if (mipc_rd_f64(r, &out->a_dot)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "mean_anomaly");
    if (mipc_rd_f64(r, &out->mean_anomaly)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "delta_mean_motion");
    if (mipc_rd_f64(r, &out->delta_mean_motion)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "delta_mean_motion_dot");
    if (mipc_rd_f64(r, &out->delta_mean_motion_dot)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "eccentricity");
    if (mipc_rd_f64(r, &out->eccentricity)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "argument_of_perigee");
    if (mipc_rd_f64(r, &out->argument_of_perigee)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "omega");
    if (mipc_rd_f64(r, &out->omega)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "omega_dot");
    if (mipc_rd_f64(r, &out->omega_dot)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "inclination");
    if (mipc_rd_f64(r, &out->inclination)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "inclination_dot");
    if (mipc_rd_f64(r, &out->inclination_dot)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "c_ic");
    if (mipc_rd_f64(r, &out->c_ic)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "c_is");
    if (mipc_rd_f64(r, &out->c_is)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "c_uc");
    if (mipc_rd_f64(r, &out->c_uc)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "c_us");
    if (mipc_rd_f64(r, &out->c_us)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "c_rc");
    if (mipc_rd_f64(r, &out->c_rc)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "c_rs");
    if (mipc_rd_f64(r, &out->c_rs)) {
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
mipc_gnss_receiver_1_galileo_ephemeris_write(mipc_writer_t *w,
                                             const mipc_gnss_receiver_1_galileo_ephemeris_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->index)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->count)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->tow)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->week_number)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->satellite_id)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->health)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->iodc)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->iode)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->t_oc)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->af0)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->af1)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->af2)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->t_gd)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->isc_l1ca)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->isc_l2c)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->t_oe)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->a)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->a_dot)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->mean_anomaly)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->delta_mean_motion)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->delta_mean_motion_dot)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->eccentricity)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->argument_of_perigee)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->omega)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->omega_dot)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->inclination)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->inclination_dot)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->c_ic)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->c_is)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->c_uc)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->c_us)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->c_rc)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->c_rs)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_gnss_receiver_1_galileo_ephemeris_encode(const mipc_gnss_receiver_1_galileo_ephemeris_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_receiver_1_galileo_ephemeris_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 218 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_receiver_1_galileo_ephemeris_load(const uint8_t *d,
                                                       mipc_gnss_receiver_1_galileo_ephemeris_t *out) {
    out->index = mipc_ld_u8(d + 0);
    out->count = mipc_ld_u8(d + 1);
    out->tow = mipc_ld_f64(d + 2);
    out->week_number = mipc_ld_u16(d + 10);
    out->satellite_id = mipc_ld_u8(d + 12);
    out->health = mipc_ld_u8(d + 13);
    out->iodc = mipc_ld_u8(d + 14);
    out->iode = mipc_ld_u8(d + 15);
    out->t_oc = mipc_ld_f64(d + 16);
    out->af0 = mipc_ld_f64(d + 24);
    out->af1 = mipc_ld_f64(d + 32);
    out->af2 = mipc_ld_f64(d + 40);
    out->t_gd = mipc_ld_f64(d + 48);
    out->isc_l1ca = mipc_ld_f64(d + 56);
    out->isc_l2c = mipc_ld_f64(d + 64);
    out->t_oe = mipc_ld_f64(d + 72);
    out->a = mipc_ld_f64(d + 80);
    out->a_dot = mipc_ld_f64(d + 88);
    out->mean_anomaly = mipc_ld_f64(d + 96);
    out->delta_mean_motion = mipc_ld_f64(d + 104);
    out->delta_mean_motion_dot = mipc_ld_f64(d + 112);
    out->eccentricity = mipc_ld_f64(d + 120);
    out->argument_of_perigee = mipc_ld_f64(d + 128);
    out->omega = mipc_ld_f64(d + 136);
    out->omega_dot = mipc_ld_f64(d + 144);
    out->inclination = mipc_ld_f64(d + 152);
    out->inclination_dot = mipc_ld_f64(d + 160);
    out->c_ic = mipc_ld_f64(d + 168);
    out->c_is = mipc_ld_f64(d + 176);
    out->c_uc = mipc_ld_f64(d + 184);
    out->c_us = mipc_ld_f64(d + 192);
    out->c_rc = mipc_ld_f64(d + 200);
    out->c_rs = mipc_ld_f64(d + 208);
    out->valid_flags = mipc_ld_u16(d + 216);
    return 0;
}

/* The general reader: lengths other than 218, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_gnss_receiver_1_galileo_ephemeris_decode_read(
    const uint8_t *data, size_t len, mipc_gnss_receiver_1_galileo_ephemeris_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_receiver_1_galileo_ephemeris_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_receiver_1_galileo_ephemeris_decode(const uint8_t *data, size_t len,
                                                            mipc_gnss_receiver_1_galileo_ephemeris_t *out,
                                                            mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 218 && mipc_gnss_receiver_1_galileo_ephemeris_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_receiver_1_galileo_ephemeris_decode_read(data, len, out, err);
}

/* ---- mipc_gnss_receiver_1_beidou_ephemeris_t */

static int mipc_gnss_receiver_1_beidou_ephemeris_read(mipc_reader_t *r,
                                                      mipc_gnss_receiver_1_beidou_ephemeris_t *out) {
    mipc_rd_push(r, "index");
    if (mipc_rd_u8(r, &out->index)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "count");
    if (mipc_rd_u8(r, &out->count)) {
        return -1;
    }
    mipc_rd_pop(r);
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
    mipc_rd_push(r, "satellite_id");
    if (mipc_rd_u8(r, &out->satellite_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "health");
    if (mipc_rd_u8(r, &out->health)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "iodc");
    if (mipc_rd_u8(r, &out->iodc)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "iode");
    if (mipc_rd_u8(r, &out->iode)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "t_oc");
    if (mipc_rd_f64(r, &out->t_oc)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "af0");
    if (mipc_rd_f64(r, &out->af0)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "af1");
    if (mipc_rd_f64(r, &out->af1)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "af2");
    if (mipc_rd_f64(r, &out->af2)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "t_gd");
    if (mipc_rd_f64(r, &out->t_gd)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "isc_l1ca");
    if (mipc_rd_f64(r, &out->isc_l1ca)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "isc_l2c");
    if (mipc_rd_f64(r, &out->isc_l2c)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "t_oe");
    if (mipc_rd_f64(r, &out->t_oe)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "a");
    if (mipc_rd_f64(r, &out->a)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "a_dot");
    if (mipc_rd_f64(r, &out->a_dot)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "mean_anomaly");
    if (mipc_rd_f64(r, &out->mean_anomaly)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "delta_mean_motion");
    if (mipc_rd_f64(r, &out->delta_mean_motion)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "delta_mean_motion_dot");
    if (mipc_rd_f64(r, &out->delta_mean_motion_dot)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "eccentricity");
    if (mipc_rd_f64(r, &out->eccentricity)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "argument_of_perigee");
    if (mipc_rd_f64(r, &out->argument_of_perigee)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "omega");
    if (mipc_rd_f64(r, &out->omega)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "omega_dot");
    if (mipc_rd_f64(r, &out->omega_dot)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "inclination");
    if (mipc_rd_f64(r, &out->inclination)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "inclination_dot");
    if (mipc_rd_f64(r, &out->inclination_dot)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "c_ic");
    if (mipc_rd_f64(r, &out->c_ic)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "c_is");
    if (mipc_rd_f64(r, &out->c_is)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "c_uc");
    if (mipc_rd_f64(r, &out->c_uc)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "c_us");
    if (mipc_rd_f64(r, &out->c_us)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "c_rc");
    if (mipc_rd_f64(r, &out->c_rc)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "c_rs");
    if (mipc_rd_f64(r, &out->c_rs)) {
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
mipc_gnss_receiver_1_beidou_ephemeris_write(mipc_writer_t *w,
                                            const mipc_gnss_receiver_1_beidou_ephemeris_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->index)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->count)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->tow)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->week_number)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->satellite_id)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->health)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->iodc)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->iode)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->t_oc)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->af0)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->af1)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->af2)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->t_gd)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->isc_l1ca)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->isc_l2c)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->t_oe)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->a)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->a_dot)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->mean_anomaly)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->delta_mean_motion)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->delta_mean_motion_dot)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->eccentricity)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->argument_of_perigee)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->omega)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->omega_dot)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->inclination)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->inclination_dot)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->c_ic)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->c_is)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->c_uc)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->c_us)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->c_rc)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->c_rs)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_gnss_receiver_1_beidou_ephemeris_encode(const mipc_gnss_receiver_1_beidou_ephemeris_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_receiver_1_beidou_ephemeris_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 218 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_receiver_1_beidou_ephemeris_load(const uint8_t *d,
                                                      mipc_gnss_receiver_1_beidou_ephemeris_t *out) {
    out->index = mipc_ld_u8(d + 0);
    out->count = mipc_ld_u8(d + 1);
    out->tow = mipc_ld_f64(d + 2);
    out->week_number = mipc_ld_u16(d + 10);
    out->satellite_id = mipc_ld_u8(d + 12);
    out->health = mipc_ld_u8(d + 13);
    out->iodc = mipc_ld_u8(d + 14);
    out->iode = mipc_ld_u8(d + 15);
    out->t_oc = mipc_ld_f64(d + 16);
    out->af0 = mipc_ld_f64(d + 24);
    out->af1 = mipc_ld_f64(d + 32);
    out->af2 = mipc_ld_f64(d + 40);
    out->t_gd = mipc_ld_f64(d + 48);
    out->isc_l1ca = mipc_ld_f64(d + 56);
    out->isc_l2c = mipc_ld_f64(d + 64);
    out->t_oe = mipc_ld_f64(d + 72);
    out->a = mipc_ld_f64(d + 80);
    out->a_dot = mipc_ld_f64(d + 88);
    out->mean_anomaly = mipc_ld_f64(d + 96);
    out->delta_mean_motion = mipc_ld_f64(d + 104);
    out->delta_mean_motion_dot = mipc_ld_f64(d + 112);
    out->eccentricity = mipc_ld_f64(d + 120);
    out->argument_of_perigee = mipc_ld_f64(d + 128);
    out->omega = mipc_ld_f64(d + 136);
    out->omega_dot = mipc_ld_f64(d + 144);
    out->inclination = mipc_ld_f64(d + 152);
    out->inclination_dot = mipc_ld_f64(d + 160);
    out->c_ic = mipc_ld_f64(d + 168);
    out->c_is = mipc_ld_f64(d + 176);
    out->c_uc = mipc_ld_f64(d + 184);
    out->c_us = mipc_ld_f64(d + 192);
    out->c_rc = mipc_ld_f64(d + 200);
    out->c_rs = mipc_ld_f64(d + 208);
    out->valid_flags = mipc_ld_u16(d + 216);
    return 0;
}

/* The general reader: lengths other than 218, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_gnss_receiver_1_beidou_ephemeris_decode_read(
    const uint8_t *data, size_t len, mipc_gnss_receiver_1_beidou_ephemeris_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_receiver_1_beidou_ephemeris_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_receiver_1_beidou_ephemeris_decode(const uint8_t *data, size_t len,
                                                           mipc_gnss_receiver_1_beidou_ephemeris_t *out,
                                                           mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 218 && mipc_gnss_receiver_1_beidou_ephemeris_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_receiver_1_beidou_ephemeris_decode_read(data, len, out, err);
}

/* ---- the straight-line packet decoder */

size_t mipc_gnss_receiver_1_decode_packet(const uint8_t *payload, size_t len,
                                          mipc_gnss_receiver_1_packet_t *out, mipc_field_entry_fn other,
                                          void *ctx) {
    size_t pos = 0;
    size_t n = 0;
    assert(payload != NULL || len == 0);
    assert(out != NULL);
    memset(out->index.present, 0, sizeof out->index.present);
    if (payload == NULL) {
        len = 0;
    }
    /* the field headers read in place (the iterator's entry is built only for what goes to other) */
    while (len - pos >= MIPC_FIELD_HEADER_SIZE) {
        const uint8_t *head = payload + pos;
        const uint8_t descriptor = head[MIPC_FIELD_DESCRIPTOR_OFFSET];
        const int data_len = (int)head[MIPC_FIELD_LENGTH_OFFSET] -
                             mipc_field_length_adjust(MIPC_GNSS_RECEIVER_1_SET, descriptor);
        const uint8_t *d = head + MIPC_FIELD_HEADER_SIZE;
        const uint32_t bit = (uint32_t)1u << (descriptor % 32u);
        size_t length;
        size_t offset = 0;
        int ok = 0;
        if (data_len < 0 || (size_t)data_len > len - pos - MIPC_FIELD_HEADER_SIZE) {
            break; /* trailing bytes: the iterator reports them below */
        }
        length = (size_t)data_len;
        if ((out->index.present[descriptor / 32u] & bit) == 0) {
            switch (descriptor) {
            case 0x03:
                if (length == 42) {
                    out->gnss_receiver_1_llh_position.latitude = mipc_ld_f64(d + 0);
                    out->gnss_receiver_1_llh_position.longitude = mipc_ld_f64(d + 8);
                    out->gnss_receiver_1_llh_position.ellipsoid_height = mipc_ld_f64(d + 16);
                    out->gnss_receiver_1_llh_position.msl_height = mipc_ld_f64(d + 24);
                    out->gnss_receiver_1_llh_position.horizontal_accuracy = mipc_ld_f32(d + 32);
                    out->gnss_receiver_1_llh_position.vertical_accuracy = mipc_ld_f32(d + 36);
                    out->gnss_receiver_1_llh_position.valid_flags = mipc_ld_u16(d + 40);
                    ok = 1;
                } else {
                    ok = mipc_gnss_receiver_1_llh_position_decode(
                             d, length, &out->gnss_receiver_1_llh_position, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_llh_position);
                break;
            case 0x04:
                if (length == 30) {
                    out->gnss_receiver_1_ecef_position.position[0] = mipc_ld_f64(d + 0);
                    out->gnss_receiver_1_ecef_position.position[1] = mipc_ld_f64(d + 8);
                    out->gnss_receiver_1_ecef_position.position[2] = mipc_ld_f64(d + 16);
                    out->gnss_receiver_1_ecef_position.position_accuracy = mipc_ld_f32(d + 24);
                    out->gnss_receiver_1_ecef_position.valid_flags = mipc_ld_u16(d + 28);
                    ok = 1;
                } else {
                    ok = mipc_gnss_receiver_1_ecef_position_decode(
                             d, length, &out->gnss_receiver_1_ecef_position, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_ecef_position);
                break;
            case 0x05:
                if (length == 34) {
                    out->gnss_receiver_1_ned_velocity.velocity[0] = mipc_ld_f32(d + 0);
                    out->gnss_receiver_1_ned_velocity.velocity[1] = mipc_ld_f32(d + 4);
                    out->gnss_receiver_1_ned_velocity.velocity[2] = mipc_ld_f32(d + 8);
                    out->gnss_receiver_1_ned_velocity.speed = mipc_ld_f32(d + 12);
                    out->gnss_receiver_1_ned_velocity.ground_speed = mipc_ld_f32(d + 16);
                    out->gnss_receiver_1_ned_velocity.heading = mipc_ld_f32(d + 20);
                    out->gnss_receiver_1_ned_velocity.speed_accuracy = mipc_ld_f32(d + 24);
                    out->gnss_receiver_1_ned_velocity.heading_accuracy = mipc_ld_f32(d + 28);
                    out->gnss_receiver_1_ned_velocity.valid_flags = mipc_ld_u16(d + 32);
                    ok = 1;
                } else {
                    ok = mipc_gnss_receiver_1_ned_velocity_decode(
                             d, length, &out->gnss_receiver_1_ned_velocity, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_ned_velocity);
                break;
            case 0x06:
                if (length == 18) {
                    out->gnss_receiver_1_ecef_velocity.velocity[0] = mipc_ld_f32(d + 0);
                    out->gnss_receiver_1_ecef_velocity.velocity[1] = mipc_ld_f32(d + 4);
                    out->gnss_receiver_1_ecef_velocity.velocity[2] = mipc_ld_f32(d + 8);
                    out->gnss_receiver_1_ecef_velocity.velocity_accuracy = mipc_ld_f32(d + 12);
                    out->gnss_receiver_1_ecef_velocity.valid_flags = mipc_ld_u16(d + 16);
                    ok = 1;
                } else {
                    ok = mipc_gnss_receiver_1_ecef_velocity_decode(
                             d, length, &out->gnss_receiver_1_ecef_velocity, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_ecef_velocity);
                break;
            case 0x07:
                if (length == 30) {
                    out->gnss_receiver_1_dop.gdop = mipc_ld_f32(d + 0);
                    out->gnss_receiver_1_dop.pdop = mipc_ld_f32(d + 4);
                    out->gnss_receiver_1_dop.hdop = mipc_ld_f32(d + 8);
                    out->gnss_receiver_1_dop.vdop = mipc_ld_f32(d + 12);
                    out->gnss_receiver_1_dop.tdop = mipc_ld_f32(d + 16);
                    out->gnss_receiver_1_dop.ndop = mipc_ld_f32(d + 20);
                    out->gnss_receiver_1_dop.edop = mipc_ld_f32(d + 24);
                    out->gnss_receiver_1_dop.valid_flags = mipc_ld_u16(d + 28);
                    ok = 1;
                } else {
                    ok = mipc_gnss_receiver_1_dop_decode(d, length, &out->gnss_receiver_1_dop, NULL) ==
                         MIPC_OK;
                }
                offset = offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_dop);
                break;
            case 0x08:
                if (length == 13) {
                    out->gnss_receiver_1_utc_time.year = mipc_ld_u16(d + 0);
                    out->gnss_receiver_1_utc_time.month = mipc_ld_u8(d + 2);
                    out->gnss_receiver_1_utc_time.day = mipc_ld_u8(d + 3);
                    out->gnss_receiver_1_utc_time.hour = mipc_ld_u8(d + 4);
                    out->gnss_receiver_1_utc_time.minute = mipc_ld_u8(d + 5);
                    out->gnss_receiver_1_utc_time.second = mipc_ld_u8(d + 6);
                    out->gnss_receiver_1_utc_time.millisecond = mipc_ld_u32(d + 7);
                    out->gnss_receiver_1_utc_time.valid_flags = mipc_ld_u16(d + 11);
                    ok = 1;
                } else {
                    ok = mipc_gnss_receiver_1_utc_time_decode(d, length, &out->gnss_receiver_1_utc_time,
                                                              NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_utc_time);
                break;
            case 0x09:
                if (length == 12) {
                    out->gnss_receiver_1_gps_time.tow = mipc_ld_f64(d + 0);
                    out->gnss_receiver_1_gps_time.week_number = mipc_ld_u16(d + 8);
                    out->gnss_receiver_1_gps_time.valid_flags = mipc_ld_u16(d + 10);
                    ok = 1;
                } else {
                    ok = mipc_gnss_receiver_1_gps_time_decode(d, length, &out->gnss_receiver_1_gps_time,
                                                              NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_gps_time);
                break;
            case 0x0B:
                if (length == 6) {
                    out->gnss_receiver_1_fix_info.fix_type = mipc_ld_u8(d + 0);
                    out->gnss_receiver_1_fix_info.num_sv = mipc_ld_u8(d + 1);
                    out->gnss_receiver_1_fix_info.fix_flags = mipc_ld_u16(d + 2);
                    out->gnss_receiver_1_fix_info.valid_flags = mipc_ld_u16(d + 4);
                    ok = 1;
                } else {
                    ok = mipc_gnss_receiver_1_fix_info_decode(d, length, &out->gnss_receiver_1_fix_info,
                                                              NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_fix_info);
                break;
            case 0x0D:
                if (length == 5) {
                    out->gnss_receiver_1_hardware_status.receiver_state = mipc_ld_u8(d + 0);
                    out->gnss_receiver_1_hardware_status.antenna_state = mipc_ld_u8(d + 1);
                    out->gnss_receiver_1_hardware_status.antenna_power = mipc_ld_u8(d + 2);
                    out->gnss_receiver_1_hardware_status.valid_flags = mipc_ld_u16(d + 3);
                    ok = 1;
                } else {
                    ok = mipc_gnss_receiver_1_hardware_status_decode(
                             d, length, &out->gnss_receiver_1_hardware_status, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_hardware_status);
                break;
            case 0x10:
                if (length == 34) {
                    out->gnss_receiver_1_clock_info_2.bias = mipc_ld_f64(d + 0);
                    out->gnss_receiver_1_clock_info_2.drift = mipc_ld_f64(d + 8);
                    out->gnss_receiver_1_clock_info_2.bias_accuracy_estimate = mipc_ld_f64(d + 16);
                    out->gnss_receiver_1_clock_info_2.drift_accuracy_estimate = mipc_ld_f64(d + 24);
                    out->gnss_receiver_1_clock_info_2.valid_flags = mipc_ld_u16(d + 32);
                    ok = 1;
                } else {
                    ok = mipc_gnss_receiver_1_clock_info_2_decode(
                             d, length, &out->gnss_receiver_1_clock_info_2, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_clock_info_2);
                break;
            case 0x11:
                if (length == 3) {
                    out->gnss_receiver_1_gps_leap_seconds.leap_seconds = mipc_ld_u8(d + 0);
                    out->gnss_receiver_1_gps_leap_seconds.valid_flags = mipc_ld_u16(d + 1);
                    ok = 1;
                } else {
                    ok = mipc_gnss_receiver_1_gps_leap_seconds_decode(
                             d, length, &out->gnss_receiver_1_gps_leap_seconds, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_gps_leap_seconds);
                break;
            case 0x12:
                if (length == 16) {
                    out->gnss_receiver_1_sbas_info.tow = mipc_ld_f64(d + 0);
                    out->gnss_receiver_1_sbas_info.week_number = mipc_ld_u16(d + 8);
                    out->gnss_receiver_1_sbas_info.sbas_system = mipc_ld_u8(d + 10);
                    out->gnss_receiver_1_sbas_info.sbas_id = mipc_ld_u8(d + 11);
                    out->gnss_receiver_1_sbas_info.count = mipc_ld_u8(d + 12);
                    out->gnss_receiver_1_sbas_info.sbas_status = mipc_ld_u8(d + 13);
                    out->gnss_receiver_1_sbas_info.valid_flags = mipc_ld_u16(d + 14);
                    ok = 1;
                } else {
                    ok = mipc_gnss_receiver_1_sbas_info_decode(d, length, &out->gnss_receiver_1_sbas_info,
                                                               NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_sbas_info);
                break;
            case 0x20:
                if (length == 25 && d[22] <= 1) {
                    out->gnss_receiver_1_satellite_status.index = mipc_ld_u8(d + 0);
                    out->gnss_receiver_1_satellite_status.count = mipc_ld_u8(d + 1);
                    out->gnss_receiver_1_satellite_status.tow = mipc_ld_f64(d + 2);
                    out->gnss_receiver_1_satellite_status.week_number = mipc_ld_u16(d + 10);
                    out->gnss_receiver_1_satellite_status.gnss_id = mipc_ld_u8(d + 12);
                    out->gnss_receiver_1_satellite_status.satellite_id = mipc_ld_u8(d + 13);
                    out->gnss_receiver_1_satellite_status.elevation = mipc_ld_f32(d + 14);
                    out->gnss_receiver_1_satellite_status.azimuth = mipc_ld_f32(d + 18);
                    out->gnss_receiver_1_satellite_status.health = mipc_ld_bool(d + 22);
                    out->gnss_receiver_1_satellite_status.valid_flags = mipc_ld_u16(d + 23);
                    ok = 1;
                } else {
                    ok = mipc_gnss_receiver_1_satellite_status_decode(
                             d, length, &out->gnss_receiver_1_satellite_status, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_satellite_status);
                break;
            case 0x22:
                if (length == 61) {
                    out->gnss_receiver_1_raw.index = mipc_ld_u8(d + 0);
                    out->gnss_receiver_1_raw.count = mipc_ld_u8(d + 1);
                    out->gnss_receiver_1_raw.tow = mipc_ld_f64(d + 2);
                    out->gnss_receiver_1_raw.week_number = mipc_ld_u16(d + 10);
                    out->gnss_receiver_1_raw.receiver_id = mipc_ld_u16(d + 12);
                    out->gnss_receiver_1_raw.tracking_channel = mipc_ld_u8(d + 14);
                    out->gnss_receiver_1_raw.gnss_id = mipc_ld_u8(d + 15);
                    out->gnss_receiver_1_raw.satellite_id = mipc_ld_u8(d + 16);
                    out->gnss_receiver_1_raw.signal_id = mipc_ld_u8(d + 17);
                    out->gnss_receiver_1_raw.signal_strength = mipc_ld_f32(d + 18);
                    out->gnss_receiver_1_raw.quality = mipc_ld_u8(d + 22);
                    out->gnss_receiver_1_raw.pseudorange = mipc_ld_f64(d + 23);
                    out->gnss_receiver_1_raw.carrier_phase = mipc_ld_f64(d + 31);
                    out->gnss_receiver_1_raw.doppler = mipc_ld_f32(d + 39);
                    out->gnss_receiver_1_raw.range_uncert = mipc_ld_f32(d + 43);
                    out->gnss_receiver_1_raw.phase_uncert = mipc_ld_f32(d + 47);
                    out->gnss_receiver_1_raw.doppler_uncert = mipc_ld_f32(d + 51);
                    out->gnss_receiver_1_raw.lock_time = mipc_ld_f32(d + 55);
                    out->gnss_receiver_1_raw.valid_flags = mipc_ld_u16(d + 59);
                    ok = 1;
                } else {
                    ok = mipc_gnss_receiver_1_raw_decode(d, length, &out->gnss_receiver_1_raw, NULL) ==
                         MIPC_OK;
                }
                offset = offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_raw);
                break;
            case 0x61:
                if (length == 218) {
                    out->gnss_receiver_1_gps_ephemeris.index = mipc_ld_u8(d + 0);
                    out->gnss_receiver_1_gps_ephemeris.count = mipc_ld_u8(d + 1);
                    out->gnss_receiver_1_gps_ephemeris.tow = mipc_ld_f64(d + 2);
                    out->gnss_receiver_1_gps_ephemeris.week_number = mipc_ld_u16(d + 10);
                    out->gnss_receiver_1_gps_ephemeris.satellite_id = mipc_ld_u8(d + 12);
                    out->gnss_receiver_1_gps_ephemeris.health = mipc_ld_u8(d + 13);
                    out->gnss_receiver_1_gps_ephemeris.iodc = mipc_ld_u8(d + 14);
                    out->gnss_receiver_1_gps_ephemeris.iode = mipc_ld_u8(d + 15);
                    out->gnss_receiver_1_gps_ephemeris.t_oc = mipc_ld_f64(d + 16);
                    out->gnss_receiver_1_gps_ephemeris.af0 = mipc_ld_f64(d + 24);
                    out->gnss_receiver_1_gps_ephemeris.af1 = mipc_ld_f64(d + 32);
                    out->gnss_receiver_1_gps_ephemeris.af2 = mipc_ld_f64(d + 40);
                    out->gnss_receiver_1_gps_ephemeris.t_gd = mipc_ld_f64(d + 48);
                    out->gnss_receiver_1_gps_ephemeris.isc_l1ca = mipc_ld_f64(d + 56);
                    out->gnss_receiver_1_gps_ephemeris.isc_l2c = mipc_ld_f64(d + 64);
                    out->gnss_receiver_1_gps_ephemeris.t_oe = mipc_ld_f64(d + 72);
                    out->gnss_receiver_1_gps_ephemeris.a = mipc_ld_f64(d + 80);
                    out->gnss_receiver_1_gps_ephemeris.a_dot = mipc_ld_f64(d + 88);
                    out->gnss_receiver_1_gps_ephemeris.mean_anomaly = mipc_ld_f64(d + 96);
                    out->gnss_receiver_1_gps_ephemeris.delta_mean_motion = mipc_ld_f64(d + 104);
                    out->gnss_receiver_1_gps_ephemeris.delta_mean_motion_dot = mipc_ld_f64(d + 112);
                    out->gnss_receiver_1_gps_ephemeris.eccentricity = mipc_ld_f64(d + 120);
                    out->gnss_receiver_1_gps_ephemeris.argument_of_perigee = mipc_ld_f64(d + 128);
                    out->gnss_receiver_1_gps_ephemeris.omega = mipc_ld_f64(d + 136);
                    out->gnss_receiver_1_gps_ephemeris.omega_dot = mipc_ld_f64(d + 144);
                    out->gnss_receiver_1_gps_ephemeris.inclination = mipc_ld_f64(d + 152);
                    out->gnss_receiver_1_gps_ephemeris.inclination_dot = mipc_ld_f64(d + 160);
                    out->gnss_receiver_1_gps_ephemeris.c_ic = mipc_ld_f64(d + 168);
                    out->gnss_receiver_1_gps_ephemeris.c_is = mipc_ld_f64(d + 176);
                    out->gnss_receiver_1_gps_ephemeris.c_uc = mipc_ld_f64(d + 184);
                    out->gnss_receiver_1_gps_ephemeris.c_us = mipc_ld_f64(d + 192);
                    out->gnss_receiver_1_gps_ephemeris.c_rc = mipc_ld_f64(d + 200);
                    out->gnss_receiver_1_gps_ephemeris.c_rs = mipc_ld_f64(d + 208);
                    out->gnss_receiver_1_gps_ephemeris.valid_flags = mipc_ld_u16(d + 216);
                    ok = 1;
                } else {
                    ok = mipc_gnss_receiver_1_gps_ephemeris_decode(
                             d, length, &out->gnss_receiver_1_gps_ephemeris, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_gps_ephemeris);
                break;
            case 0x62:
                if (length == 102) {
                    out->gnss_receiver_1_glonass_ephemeris.index = mipc_ld_u8(d + 0);
                    out->gnss_receiver_1_glonass_ephemeris.count = mipc_ld_u8(d + 1);
                    out->gnss_receiver_1_glonass_ephemeris.tow = mipc_ld_f64(d + 2);
                    out->gnss_receiver_1_glonass_ephemeris.week_number = mipc_ld_u16(d + 10);
                    out->gnss_receiver_1_glonass_ephemeris.satellite_id = mipc_ld_u8(d + 12);
                    out->gnss_receiver_1_glonass_ephemeris.freq_number = mipc_ld_s8(d + 13);
                    out->gnss_receiver_1_glonass_ephemeris.tk = mipc_ld_u32(d + 14);
                    out->gnss_receiver_1_glonass_ephemeris.tb = mipc_ld_u32(d + 18);
                    out->gnss_receiver_1_glonass_ephemeris.sat_type = mipc_ld_u8(d + 22);
                    out->gnss_receiver_1_glonass_ephemeris.gamma = mipc_ld_f64(d + 23);
                    out->gnss_receiver_1_glonass_ephemeris.tau_n = mipc_ld_f64(d + 31);
                    out->gnss_receiver_1_glonass_ephemeris.x[0] = mipc_ld_f64(d + 39);
                    out->gnss_receiver_1_glonass_ephemeris.x[1] = mipc_ld_f64(d + 47);
                    out->gnss_receiver_1_glonass_ephemeris.x[2] = mipc_ld_f64(d + 55);
                    out->gnss_receiver_1_glonass_ephemeris.v[0] = mipc_ld_f32(d + 63);
                    out->gnss_receiver_1_glonass_ephemeris.v[1] = mipc_ld_f32(d + 67);
                    out->gnss_receiver_1_glonass_ephemeris.v[2] = mipc_ld_f32(d + 71);
                    out->gnss_receiver_1_glonass_ephemeris.a[0] = mipc_ld_f32(d + 75);
                    out->gnss_receiver_1_glonass_ephemeris.a[1] = mipc_ld_f32(d + 79);
                    out->gnss_receiver_1_glonass_ephemeris.a[2] = mipc_ld_f32(d + 83);
                    out->gnss_receiver_1_glonass_ephemeris.health = mipc_ld_u8(d + 87);
                    out->gnss_receiver_1_glonass_ephemeris.p = mipc_ld_u8(d + 88);
                    out->gnss_receiver_1_glonass_ephemeris.nt = mipc_ld_u8(d + 89);
                    out->gnss_receiver_1_glonass_ephemeris.delta_tau_n = mipc_ld_f32(d + 90);
                    out->gnss_receiver_1_glonass_ephemeris.ft = mipc_ld_u8(d + 94);
                    out->gnss_receiver_1_glonass_ephemeris.en = mipc_ld_u8(d + 95);
                    out->gnss_receiver_1_glonass_ephemeris.p1 = mipc_ld_u8(d + 96);
                    out->gnss_receiver_1_glonass_ephemeris.p2 = mipc_ld_u8(d + 97);
                    out->gnss_receiver_1_glonass_ephemeris.p3 = mipc_ld_u8(d + 98);
                    out->gnss_receiver_1_glonass_ephemeris.p4 = mipc_ld_u8(d + 99);
                    out->gnss_receiver_1_glonass_ephemeris.valid_flags = mipc_ld_u16(d + 100);
                    ok = 1;
                } else {
                    ok = mipc_gnss_receiver_1_glonass_ephemeris_decode(
                             d, length, &out->gnss_receiver_1_glonass_ephemeris, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_glonass_ephemeris);
                break;
            case 0x63:
                if (length == 218) {
                    out->gnss_receiver_1_galileo_ephemeris.index = mipc_ld_u8(d + 0);
                    out->gnss_receiver_1_galileo_ephemeris.count = mipc_ld_u8(d + 1);
                    out->gnss_receiver_1_galileo_ephemeris.tow = mipc_ld_f64(d + 2);
                    out->gnss_receiver_1_galileo_ephemeris.week_number = mipc_ld_u16(d + 10);
                    out->gnss_receiver_1_galileo_ephemeris.satellite_id = mipc_ld_u8(d + 12);
                    out->gnss_receiver_1_galileo_ephemeris.health = mipc_ld_u8(d + 13);
                    out->gnss_receiver_1_galileo_ephemeris.iodc = mipc_ld_u8(d + 14);
                    out->gnss_receiver_1_galileo_ephemeris.iode = mipc_ld_u8(d + 15);
                    out->gnss_receiver_1_galileo_ephemeris.t_oc = mipc_ld_f64(d + 16);
                    out->gnss_receiver_1_galileo_ephemeris.af0 = mipc_ld_f64(d + 24);
                    out->gnss_receiver_1_galileo_ephemeris.af1 = mipc_ld_f64(d + 32);
                    out->gnss_receiver_1_galileo_ephemeris.af2 = mipc_ld_f64(d + 40);
                    out->gnss_receiver_1_galileo_ephemeris.t_gd = mipc_ld_f64(d + 48);
                    out->gnss_receiver_1_galileo_ephemeris.isc_l1ca = mipc_ld_f64(d + 56);
                    out->gnss_receiver_1_galileo_ephemeris.isc_l2c = mipc_ld_f64(d + 64);
                    out->gnss_receiver_1_galileo_ephemeris.t_oe = mipc_ld_f64(d + 72);
                    out->gnss_receiver_1_galileo_ephemeris.a = mipc_ld_f64(d + 80);
                    out->gnss_receiver_1_galileo_ephemeris.a_dot = mipc_ld_f64(d + 88);
                    out->gnss_receiver_1_galileo_ephemeris.mean_anomaly = mipc_ld_f64(d + 96);
                    out->gnss_receiver_1_galileo_ephemeris.delta_mean_motion = mipc_ld_f64(d + 104);
                    out->gnss_receiver_1_galileo_ephemeris.delta_mean_motion_dot = mipc_ld_f64(d + 112);
                    out->gnss_receiver_1_galileo_ephemeris.eccentricity = mipc_ld_f64(d + 120);
                    out->gnss_receiver_1_galileo_ephemeris.argument_of_perigee = mipc_ld_f64(d + 128);
                    out->gnss_receiver_1_galileo_ephemeris.omega = mipc_ld_f64(d + 136);
                    out->gnss_receiver_1_galileo_ephemeris.omega_dot = mipc_ld_f64(d + 144);
                    out->gnss_receiver_1_galileo_ephemeris.inclination = mipc_ld_f64(d + 152);
                    out->gnss_receiver_1_galileo_ephemeris.inclination_dot = mipc_ld_f64(d + 160);
                    out->gnss_receiver_1_galileo_ephemeris.c_ic = mipc_ld_f64(d + 168);
                    out->gnss_receiver_1_galileo_ephemeris.c_is = mipc_ld_f64(d + 176);
                    out->gnss_receiver_1_galileo_ephemeris.c_uc = mipc_ld_f64(d + 184);
                    out->gnss_receiver_1_galileo_ephemeris.c_us = mipc_ld_f64(d + 192);
                    out->gnss_receiver_1_galileo_ephemeris.c_rc = mipc_ld_f64(d + 200);
                    out->gnss_receiver_1_galileo_ephemeris.c_rs = mipc_ld_f64(d + 208);
                    out->gnss_receiver_1_galileo_ephemeris.valid_flags = mipc_ld_u16(d + 216);
                    ok = 1;
                } else {
                    ok = mipc_gnss_receiver_1_galileo_ephemeris_decode(
                             d, length, &out->gnss_receiver_1_galileo_ephemeris, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_galileo_ephemeris);
                break;
            case 0x64:
                if (length == 218) {
                    out->gnss_receiver_1_beidou_ephemeris.index = mipc_ld_u8(d + 0);
                    out->gnss_receiver_1_beidou_ephemeris.count = mipc_ld_u8(d + 1);
                    out->gnss_receiver_1_beidou_ephemeris.tow = mipc_ld_f64(d + 2);
                    out->gnss_receiver_1_beidou_ephemeris.week_number = mipc_ld_u16(d + 10);
                    out->gnss_receiver_1_beidou_ephemeris.satellite_id = mipc_ld_u8(d + 12);
                    out->gnss_receiver_1_beidou_ephemeris.health = mipc_ld_u8(d + 13);
                    out->gnss_receiver_1_beidou_ephemeris.iodc = mipc_ld_u8(d + 14);
                    out->gnss_receiver_1_beidou_ephemeris.iode = mipc_ld_u8(d + 15);
                    out->gnss_receiver_1_beidou_ephemeris.t_oc = mipc_ld_f64(d + 16);
                    out->gnss_receiver_1_beidou_ephemeris.af0 = mipc_ld_f64(d + 24);
                    out->gnss_receiver_1_beidou_ephemeris.af1 = mipc_ld_f64(d + 32);
                    out->gnss_receiver_1_beidou_ephemeris.af2 = mipc_ld_f64(d + 40);
                    out->gnss_receiver_1_beidou_ephemeris.t_gd = mipc_ld_f64(d + 48);
                    out->gnss_receiver_1_beidou_ephemeris.isc_l1ca = mipc_ld_f64(d + 56);
                    out->gnss_receiver_1_beidou_ephemeris.isc_l2c = mipc_ld_f64(d + 64);
                    out->gnss_receiver_1_beidou_ephemeris.t_oe = mipc_ld_f64(d + 72);
                    out->gnss_receiver_1_beidou_ephemeris.a = mipc_ld_f64(d + 80);
                    out->gnss_receiver_1_beidou_ephemeris.a_dot = mipc_ld_f64(d + 88);
                    out->gnss_receiver_1_beidou_ephemeris.mean_anomaly = mipc_ld_f64(d + 96);
                    out->gnss_receiver_1_beidou_ephemeris.delta_mean_motion = mipc_ld_f64(d + 104);
                    out->gnss_receiver_1_beidou_ephemeris.delta_mean_motion_dot = mipc_ld_f64(d + 112);
                    out->gnss_receiver_1_beidou_ephemeris.eccentricity = mipc_ld_f64(d + 120);
                    out->gnss_receiver_1_beidou_ephemeris.argument_of_perigee = mipc_ld_f64(d + 128);
                    out->gnss_receiver_1_beidou_ephemeris.omega = mipc_ld_f64(d + 136);
                    out->gnss_receiver_1_beidou_ephemeris.omega_dot = mipc_ld_f64(d + 144);
                    out->gnss_receiver_1_beidou_ephemeris.inclination = mipc_ld_f64(d + 152);
                    out->gnss_receiver_1_beidou_ephemeris.inclination_dot = mipc_ld_f64(d + 160);
                    out->gnss_receiver_1_beidou_ephemeris.c_ic = mipc_ld_f64(d + 168);
                    out->gnss_receiver_1_beidou_ephemeris.c_is = mipc_ld_f64(d + 176);
                    out->gnss_receiver_1_beidou_ephemeris.c_uc = mipc_ld_f64(d + 184);
                    out->gnss_receiver_1_beidou_ephemeris.c_us = mipc_ld_f64(d + 192);
                    out->gnss_receiver_1_beidou_ephemeris.c_rc = mipc_ld_f64(d + 200);
                    out->gnss_receiver_1_beidou_ephemeris.c_rs = mipc_ld_f64(d + 208);
                    out->gnss_receiver_1_beidou_ephemeris.valid_flags = mipc_ld_u16(d + 216);
                    ok = 1;
                } else {
                    ok = mipc_gnss_receiver_1_beidou_ephemeris_decode(
                             d, length, &out->gnss_receiver_1_beidou_ephemeris, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_beidou_ephemeris);
                break;
            case 0xD0:
                if (length == 1) {
                    out->shared_event_source.trigger_id = mipc_ld_u8(d + 0);
                    ok = 1;
                } else {
                    ok = mipc_shared_event_source_decode(d, length, &out->shared_event_source, NULL) ==
                         MIPC_OK;
                }
                offset = offsetof(mipc_gnss_receiver_1_packet_t, shared_event_source);
                break;
            case 0xD3:
                if (length == 12) {
                    out->shared_gps_timestamp.tow = mipc_ld_f64(d + 0);
                    out->shared_gps_timestamp.week_number = mipc_ld_u16(d + 8);
                    out->shared_gps_timestamp.valid_flags = mipc_ld_u16(d + 10);
                    ok = 1;
                } else {
                    ok = mipc_shared_gps_timestamp_decode(d, length, &out->shared_gps_timestamp, NULL) ==
                         MIPC_OK;
                }
                offset = offsetof(mipc_gnss_receiver_1_packet_t, shared_gps_timestamp);
                break;
            case 0xD4:
                if (length == 8) {
                    out->shared_delta_time.seconds = mipc_ld_f64(d + 0);
                    ok = 1;
                } else {
                    ok = mipc_shared_delta_time_decode(d, length, &out->shared_delta_time, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_receiver_1_packet_t, shared_delta_time);
                break;
            case 0xD5:
                if (length == 8) {
                    out->shared_reference_timestamp.nanoseconds = mipc_ld_u64(d + 0);
                    ok = 1;
                } else {
                    ok = mipc_shared_reference_timestamp_decode(d, length, &out->shared_reference_timestamp,
                                                                NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_receiver_1_packet_t, shared_reference_timestamp);
                break;
            case 0xD6:
                if (length == 8) {
                    out->shared_reference_time_delta.dt_nanos = mipc_ld_u64(d + 0);
                    ok = 1;
                } else {
                    ok = mipc_shared_reference_time_delta_decode(d, length, &out->shared_reference_time_delta,
                                                                 NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_receiver_1_packet_t, shared_reference_time_delta);
                break;
            case 0xD7:
                if (length == 10) {
                    out->shared_external_timestamp.nanoseconds = mipc_ld_u64(d + 0);
                    out->shared_external_timestamp.valid_flags = mipc_ld_u16(d + 8);
                    ok = 1;
                } else {
                    ok = mipc_shared_external_timestamp_decode(d, length, &out->shared_external_timestamp,
                                                               NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_receiver_1_packet_t, shared_external_timestamp);
                break;
            case 0xD8:
                if (length == 10) {
                    out->shared_external_time_delta.dt_nanos = mipc_ld_u64(d + 0);
                    out->shared_external_time_delta.valid_flags = mipc_ld_u16(d + 8);
                    ok = 1;
                } else {
                    ok = mipc_shared_external_time_delta_decode(d, length, &out->shared_external_time_delta,
                                                                NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_receiver_1_packet_t, shared_external_time_delta);
                break;
            default:
                break;
            }
        }
        if (ok) {
            out->index.present[descriptor / 32u] |= bit;
            out->index.fields[n].descriptor = descriptor;
            out->index.fields[n].offset = (uint32_t)offset;
            n++;
        } else if (other) {
            mipc_field_visit_at_(MIPC_GNSS_RECEIVER_1_SET, payload, len, pos, other, ctx);
        }
        pos += MIPC_FIELD_HEADER_SIZE + length;
    }
    if (pos < len && other) {
        mipc_field_visit_at_(MIPC_GNSS_RECEIVER_1_SET, payload, len, pos, other, ctx);
    }
    out->index.count = n;
    return n;
}

/* ---- the members' loaders (mipc_decode_packet_cached, issue 38): each decodes its field's
 * data into its member of the mipc_gnss_receiver_1_packet_t at packet as mipc_gnss_receiver_1_decode_packet
 * does; 0 when it does not decode (the packet then takes the straight-line decoder, which gives the field to
 * other) */

static int load_0x03(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_receiver_1_packet_t *out = packet;
    if (length == 42) {
        out->gnss_receiver_1_llh_position.latitude = mipc_ld_f64(d + 0);
        out->gnss_receiver_1_llh_position.longitude = mipc_ld_f64(d + 8);
        out->gnss_receiver_1_llh_position.ellipsoid_height = mipc_ld_f64(d + 16);
        out->gnss_receiver_1_llh_position.msl_height = mipc_ld_f64(d + 24);
        out->gnss_receiver_1_llh_position.horizontal_accuracy = mipc_ld_f32(d + 32);
        out->gnss_receiver_1_llh_position.vertical_accuracy = mipc_ld_f32(d + 36);
        out->gnss_receiver_1_llh_position.valid_flags = mipc_ld_u16(d + 40);
        return 1;
    }
    return mipc_gnss_receiver_1_llh_position_decode(d, length, &out->gnss_receiver_1_llh_position, NULL) ==
           MIPC_OK;
}

static int load_0x04(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_receiver_1_packet_t *out = packet;
    if (length == 30) {
        out->gnss_receiver_1_ecef_position.position[0] = mipc_ld_f64(d + 0);
        out->gnss_receiver_1_ecef_position.position[1] = mipc_ld_f64(d + 8);
        out->gnss_receiver_1_ecef_position.position[2] = mipc_ld_f64(d + 16);
        out->gnss_receiver_1_ecef_position.position_accuracy = mipc_ld_f32(d + 24);
        out->gnss_receiver_1_ecef_position.valid_flags = mipc_ld_u16(d + 28);
        return 1;
    }
    return mipc_gnss_receiver_1_ecef_position_decode(d, length, &out->gnss_receiver_1_ecef_position, NULL) ==
           MIPC_OK;
}

static int load_0x05(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_receiver_1_packet_t *out = packet;
    if (length == 34) {
        out->gnss_receiver_1_ned_velocity.velocity[0] = mipc_ld_f32(d + 0);
        out->gnss_receiver_1_ned_velocity.velocity[1] = mipc_ld_f32(d + 4);
        out->gnss_receiver_1_ned_velocity.velocity[2] = mipc_ld_f32(d + 8);
        out->gnss_receiver_1_ned_velocity.speed = mipc_ld_f32(d + 12);
        out->gnss_receiver_1_ned_velocity.ground_speed = mipc_ld_f32(d + 16);
        out->gnss_receiver_1_ned_velocity.heading = mipc_ld_f32(d + 20);
        out->gnss_receiver_1_ned_velocity.speed_accuracy = mipc_ld_f32(d + 24);
        out->gnss_receiver_1_ned_velocity.heading_accuracy = mipc_ld_f32(d + 28);
        out->gnss_receiver_1_ned_velocity.valid_flags = mipc_ld_u16(d + 32);
        return 1;
    }
    return mipc_gnss_receiver_1_ned_velocity_decode(d, length, &out->gnss_receiver_1_ned_velocity, NULL) ==
           MIPC_OK;
}

static int load_0x06(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_receiver_1_packet_t *out = packet;
    if (length == 18) {
        out->gnss_receiver_1_ecef_velocity.velocity[0] = mipc_ld_f32(d + 0);
        out->gnss_receiver_1_ecef_velocity.velocity[1] = mipc_ld_f32(d + 4);
        out->gnss_receiver_1_ecef_velocity.velocity[2] = mipc_ld_f32(d + 8);
        out->gnss_receiver_1_ecef_velocity.velocity_accuracy = mipc_ld_f32(d + 12);
        out->gnss_receiver_1_ecef_velocity.valid_flags = mipc_ld_u16(d + 16);
        return 1;
    }
    return mipc_gnss_receiver_1_ecef_velocity_decode(d, length, &out->gnss_receiver_1_ecef_velocity, NULL) ==
           MIPC_OK;
}

static int load_0x07(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_receiver_1_packet_t *out = packet;
    if (length == 30) {
        out->gnss_receiver_1_dop.gdop = mipc_ld_f32(d + 0);
        out->gnss_receiver_1_dop.pdop = mipc_ld_f32(d + 4);
        out->gnss_receiver_1_dop.hdop = mipc_ld_f32(d + 8);
        out->gnss_receiver_1_dop.vdop = mipc_ld_f32(d + 12);
        out->gnss_receiver_1_dop.tdop = mipc_ld_f32(d + 16);
        out->gnss_receiver_1_dop.ndop = mipc_ld_f32(d + 20);
        out->gnss_receiver_1_dop.edop = mipc_ld_f32(d + 24);
        out->gnss_receiver_1_dop.valid_flags = mipc_ld_u16(d + 28);
        return 1;
    }
    return mipc_gnss_receiver_1_dop_decode(d, length, &out->gnss_receiver_1_dop, NULL) == MIPC_OK;
}

static int load_0x08(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_receiver_1_packet_t *out = packet;
    if (length == 13) {
        out->gnss_receiver_1_utc_time.year = mipc_ld_u16(d + 0);
        out->gnss_receiver_1_utc_time.month = mipc_ld_u8(d + 2);
        out->gnss_receiver_1_utc_time.day = mipc_ld_u8(d + 3);
        out->gnss_receiver_1_utc_time.hour = mipc_ld_u8(d + 4);
        out->gnss_receiver_1_utc_time.minute = mipc_ld_u8(d + 5);
        out->gnss_receiver_1_utc_time.second = mipc_ld_u8(d + 6);
        out->gnss_receiver_1_utc_time.millisecond = mipc_ld_u32(d + 7);
        out->gnss_receiver_1_utc_time.valid_flags = mipc_ld_u16(d + 11);
        return 1;
    }
    return mipc_gnss_receiver_1_utc_time_decode(d, length, &out->gnss_receiver_1_utc_time, NULL) == MIPC_OK;
}

static int load_0x09(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_receiver_1_packet_t *out = packet;
    if (length == 12) {
        out->gnss_receiver_1_gps_time.tow = mipc_ld_f64(d + 0);
        out->gnss_receiver_1_gps_time.week_number = mipc_ld_u16(d + 8);
        out->gnss_receiver_1_gps_time.valid_flags = mipc_ld_u16(d + 10);
        return 1;
    }
    return mipc_gnss_receiver_1_gps_time_decode(d, length, &out->gnss_receiver_1_gps_time, NULL) == MIPC_OK;
}

static int load_0x0b(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_receiver_1_packet_t *out = packet;
    if (length == 6) {
        out->gnss_receiver_1_fix_info.fix_type = mipc_ld_u8(d + 0);
        out->gnss_receiver_1_fix_info.num_sv = mipc_ld_u8(d + 1);
        out->gnss_receiver_1_fix_info.fix_flags = mipc_ld_u16(d + 2);
        out->gnss_receiver_1_fix_info.valid_flags = mipc_ld_u16(d + 4);
        return 1;
    }
    return mipc_gnss_receiver_1_fix_info_decode(d, length, &out->gnss_receiver_1_fix_info, NULL) == MIPC_OK;
}

static int load_0x0d(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_receiver_1_packet_t *out = packet;
    if (length == 5) {
        out->gnss_receiver_1_hardware_status.receiver_state = mipc_ld_u8(d + 0);
        out->gnss_receiver_1_hardware_status.antenna_state = mipc_ld_u8(d + 1);
        out->gnss_receiver_1_hardware_status.antenna_power = mipc_ld_u8(d + 2);
        out->gnss_receiver_1_hardware_status.valid_flags = mipc_ld_u16(d + 3);
        return 1;
    }
    return mipc_gnss_receiver_1_hardware_status_decode(d, length, &out->gnss_receiver_1_hardware_status,
                                                       NULL) == MIPC_OK;
}

static int load_0x10(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_receiver_1_packet_t *out = packet;
    if (length == 34) {
        out->gnss_receiver_1_clock_info_2.bias = mipc_ld_f64(d + 0);
        out->gnss_receiver_1_clock_info_2.drift = mipc_ld_f64(d + 8);
        out->gnss_receiver_1_clock_info_2.bias_accuracy_estimate = mipc_ld_f64(d + 16);
        out->gnss_receiver_1_clock_info_2.drift_accuracy_estimate = mipc_ld_f64(d + 24);
        out->gnss_receiver_1_clock_info_2.valid_flags = mipc_ld_u16(d + 32);
        return 1;
    }
    return mipc_gnss_receiver_1_clock_info_2_decode(d, length, &out->gnss_receiver_1_clock_info_2, NULL) ==
           MIPC_OK;
}

static int load_0x11(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_receiver_1_packet_t *out = packet;
    if (length == 3) {
        out->gnss_receiver_1_gps_leap_seconds.leap_seconds = mipc_ld_u8(d + 0);
        out->gnss_receiver_1_gps_leap_seconds.valid_flags = mipc_ld_u16(d + 1);
        return 1;
    }
    return mipc_gnss_receiver_1_gps_leap_seconds_decode(d, length, &out->gnss_receiver_1_gps_leap_seconds,
                                                        NULL) == MIPC_OK;
}

static int load_0x12(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_receiver_1_packet_t *out = packet;
    if (length == 16) {
        out->gnss_receiver_1_sbas_info.tow = mipc_ld_f64(d + 0);
        out->gnss_receiver_1_sbas_info.week_number = mipc_ld_u16(d + 8);
        out->gnss_receiver_1_sbas_info.sbas_system = mipc_ld_u8(d + 10);
        out->gnss_receiver_1_sbas_info.sbas_id = mipc_ld_u8(d + 11);
        out->gnss_receiver_1_sbas_info.count = mipc_ld_u8(d + 12);
        out->gnss_receiver_1_sbas_info.sbas_status = mipc_ld_u8(d + 13);
        out->gnss_receiver_1_sbas_info.valid_flags = mipc_ld_u16(d + 14);
        return 1;
    }
    return mipc_gnss_receiver_1_sbas_info_decode(d, length, &out->gnss_receiver_1_sbas_info, NULL) == MIPC_OK;
}

static int load_0x20(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_receiver_1_packet_t *out = packet;
    if (length == 25 && d[22] <= 1) {
        out->gnss_receiver_1_satellite_status.index = mipc_ld_u8(d + 0);
        out->gnss_receiver_1_satellite_status.count = mipc_ld_u8(d + 1);
        out->gnss_receiver_1_satellite_status.tow = mipc_ld_f64(d + 2);
        out->gnss_receiver_1_satellite_status.week_number = mipc_ld_u16(d + 10);
        out->gnss_receiver_1_satellite_status.gnss_id = mipc_ld_u8(d + 12);
        out->gnss_receiver_1_satellite_status.satellite_id = mipc_ld_u8(d + 13);
        out->gnss_receiver_1_satellite_status.elevation = mipc_ld_f32(d + 14);
        out->gnss_receiver_1_satellite_status.azimuth = mipc_ld_f32(d + 18);
        out->gnss_receiver_1_satellite_status.health = mipc_ld_bool(d + 22);
        out->gnss_receiver_1_satellite_status.valid_flags = mipc_ld_u16(d + 23);
        return 1;
    }
    return mipc_gnss_receiver_1_satellite_status_decode(d, length, &out->gnss_receiver_1_satellite_status,
                                                        NULL) == MIPC_OK;
}

static int load_0x22(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_receiver_1_packet_t *out = packet;
    if (length == 61) {
        out->gnss_receiver_1_raw.index = mipc_ld_u8(d + 0);
        out->gnss_receiver_1_raw.count = mipc_ld_u8(d + 1);
        out->gnss_receiver_1_raw.tow = mipc_ld_f64(d + 2);
        out->gnss_receiver_1_raw.week_number = mipc_ld_u16(d + 10);
        out->gnss_receiver_1_raw.receiver_id = mipc_ld_u16(d + 12);
        out->gnss_receiver_1_raw.tracking_channel = mipc_ld_u8(d + 14);
        out->gnss_receiver_1_raw.gnss_id = mipc_ld_u8(d + 15);
        out->gnss_receiver_1_raw.satellite_id = mipc_ld_u8(d + 16);
        out->gnss_receiver_1_raw.signal_id = mipc_ld_u8(d + 17);
        out->gnss_receiver_1_raw.signal_strength = mipc_ld_f32(d + 18);
        out->gnss_receiver_1_raw.quality = mipc_ld_u8(d + 22);
        out->gnss_receiver_1_raw.pseudorange = mipc_ld_f64(d + 23);
        out->gnss_receiver_1_raw.carrier_phase = mipc_ld_f64(d + 31);
        out->gnss_receiver_1_raw.doppler = mipc_ld_f32(d + 39);
        out->gnss_receiver_1_raw.range_uncert = mipc_ld_f32(d + 43);
        out->gnss_receiver_1_raw.phase_uncert = mipc_ld_f32(d + 47);
        out->gnss_receiver_1_raw.doppler_uncert = mipc_ld_f32(d + 51);
        out->gnss_receiver_1_raw.lock_time = mipc_ld_f32(d + 55);
        out->gnss_receiver_1_raw.valid_flags = mipc_ld_u16(d + 59);
        return 1;
    }
    return mipc_gnss_receiver_1_raw_decode(d, length, &out->gnss_receiver_1_raw, NULL) == MIPC_OK;
}

static int load_0x61(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_receiver_1_packet_t *out = packet;
    if (length == 218) {
        out->gnss_receiver_1_gps_ephemeris.index = mipc_ld_u8(d + 0);
        out->gnss_receiver_1_gps_ephemeris.count = mipc_ld_u8(d + 1);
        out->gnss_receiver_1_gps_ephemeris.tow = mipc_ld_f64(d + 2);
        out->gnss_receiver_1_gps_ephemeris.week_number = mipc_ld_u16(d + 10);
        out->gnss_receiver_1_gps_ephemeris.satellite_id = mipc_ld_u8(d + 12);
        out->gnss_receiver_1_gps_ephemeris.health = mipc_ld_u8(d + 13);
        out->gnss_receiver_1_gps_ephemeris.iodc = mipc_ld_u8(d + 14);
        out->gnss_receiver_1_gps_ephemeris.iode = mipc_ld_u8(d + 15);
        out->gnss_receiver_1_gps_ephemeris.t_oc = mipc_ld_f64(d + 16);
        out->gnss_receiver_1_gps_ephemeris.af0 = mipc_ld_f64(d + 24);
        out->gnss_receiver_1_gps_ephemeris.af1 = mipc_ld_f64(d + 32);
        out->gnss_receiver_1_gps_ephemeris.af2 = mipc_ld_f64(d + 40);
        out->gnss_receiver_1_gps_ephemeris.t_gd = mipc_ld_f64(d + 48);
        out->gnss_receiver_1_gps_ephemeris.isc_l1ca = mipc_ld_f64(d + 56);
        out->gnss_receiver_1_gps_ephemeris.isc_l2c = mipc_ld_f64(d + 64);
        out->gnss_receiver_1_gps_ephemeris.t_oe = mipc_ld_f64(d + 72);
        out->gnss_receiver_1_gps_ephemeris.a = mipc_ld_f64(d + 80);
        out->gnss_receiver_1_gps_ephemeris.a_dot = mipc_ld_f64(d + 88);
        out->gnss_receiver_1_gps_ephemeris.mean_anomaly = mipc_ld_f64(d + 96);
        out->gnss_receiver_1_gps_ephemeris.delta_mean_motion = mipc_ld_f64(d + 104);
        out->gnss_receiver_1_gps_ephemeris.delta_mean_motion_dot = mipc_ld_f64(d + 112);
        out->gnss_receiver_1_gps_ephemeris.eccentricity = mipc_ld_f64(d + 120);
        out->gnss_receiver_1_gps_ephemeris.argument_of_perigee = mipc_ld_f64(d + 128);
        out->gnss_receiver_1_gps_ephemeris.omega = mipc_ld_f64(d + 136);
        out->gnss_receiver_1_gps_ephemeris.omega_dot = mipc_ld_f64(d + 144);
        out->gnss_receiver_1_gps_ephemeris.inclination = mipc_ld_f64(d + 152);
        out->gnss_receiver_1_gps_ephemeris.inclination_dot = mipc_ld_f64(d + 160);
        out->gnss_receiver_1_gps_ephemeris.c_ic = mipc_ld_f64(d + 168);
        out->gnss_receiver_1_gps_ephemeris.c_is = mipc_ld_f64(d + 176);
        out->gnss_receiver_1_gps_ephemeris.c_uc = mipc_ld_f64(d + 184);
        out->gnss_receiver_1_gps_ephemeris.c_us = mipc_ld_f64(d + 192);
        out->gnss_receiver_1_gps_ephemeris.c_rc = mipc_ld_f64(d + 200);
        out->gnss_receiver_1_gps_ephemeris.c_rs = mipc_ld_f64(d + 208);
        out->gnss_receiver_1_gps_ephemeris.valid_flags = mipc_ld_u16(d + 216);
        return 1;
    }
    return mipc_gnss_receiver_1_gps_ephemeris_decode(d, length, &out->gnss_receiver_1_gps_ephemeris, NULL) ==
           MIPC_OK;
}

static int load_0x62(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_receiver_1_packet_t *out = packet;
    if (length == 102) {
        out->gnss_receiver_1_glonass_ephemeris.index = mipc_ld_u8(d + 0);
        out->gnss_receiver_1_glonass_ephemeris.count = mipc_ld_u8(d + 1);
        out->gnss_receiver_1_glonass_ephemeris.tow = mipc_ld_f64(d + 2);
        out->gnss_receiver_1_glonass_ephemeris.week_number = mipc_ld_u16(d + 10);
        out->gnss_receiver_1_glonass_ephemeris.satellite_id = mipc_ld_u8(d + 12);
        out->gnss_receiver_1_glonass_ephemeris.freq_number = mipc_ld_s8(d + 13);
        out->gnss_receiver_1_glonass_ephemeris.tk = mipc_ld_u32(d + 14);
        out->gnss_receiver_1_glonass_ephemeris.tb = mipc_ld_u32(d + 18);
        out->gnss_receiver_1_glonass_ephemeris.sat_type = mipc_ld_u8(d + 22);
        out->gnss_receiver_1_glonass_ephemeris.gamma = mipc_ld_f64(d + 23);
        out->gnss_receiver_1_glonass_ephemeris.tau_n = mipc_ld_f64(d + 31);
        out->gnss_receiver_1_glonass_ephemeris.x[0] = mipc_ld_f64(d + 39);
        out->gnss_receiver_1_glonass_ephemeris.x[1] = mipc_ld_f64(d + 47);
        out->gnss_receiver_1_glonass_ephemeris.x[2] = mipc_ld_f64(d + 55);
        out->gnss_receiver_1_glonass_ephemeris.v[0] = mipc_ld_f32(d + 63);
        out->gnss_receiver_1_glonass_ephemeris.v[1] = mipc_ld_f32(d + 67);
        out->gnss_receiver_1_glonass_ephemeris.v[2] = mipc_ld_f32(d + 71);
        out->gnss_receiver_1_glonass_ephemeris.a[0] = mipc_ld_f32(d + 75);
        out->gnss_receiver_1_glonass_ephemeris.a[1] = mipc_ld_f32(d + 79);
        out->gnss_receiver_1_glonass_ephemeris.a[2] = mipc_ld_f32(d + 83);
        out->gnss_receiver_1_glonass_ephemeris.health = mipc_ld_u8(d + 87);
        out->gnss_receiver_1_glonass_ephemeris.p = mipc_ld_u8(d + 88);
        out->gnss_receiver_1_glonass_ephemeris.nt = mipc_ld_u8(d + 89);
        out->gnss_receiver_1_glonass_ephemeris.delta_tau_n = mipc_ld_f32(d + 90);
        out->gnss_receiver_1_glonass_ephemeris.ft = mipc_ld_u8(d + 94);
        out->gnss_receiver_1_glonass_ephemeris.en = mipc_ld_u8(d + 95);
        out->gnss_receiver_1_glonass_ephemeris.p1 = mipc_ld_u8(d + 96);
        out->gnss_receiver_1_glonass_ephemeris.p2 = mipc_ld_u8(d + 97);
        out->gnss_receiver_1_glonass_ephemeris.p3 = mipc_ld_u8(d + 98);
        out->gnss_receiver_1_glonass_ephemeris.p4 = mipc_ld_u8(d + 99);
        out->gnss_receiver_1_glonass_ephemeris.valid_flags = mipc_ld_u16(d + 100);
        return 1;
    }
    return mipc_gnss_receiver_1_glonass_ephemeris_decode(d, length, &out->gnss_receiver_1_glonass_ephemeris,
                                                         NULL) == MIPC_OK;
}

static int load_0x63(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_receiver_1_packet_t *out = packet;
    if (length == 218) {
        out->gnss_receiver_1_galileo_ephemeris.index = mipc_ld_u8(d + 0);
        out->gnss_receiver_1_galileo_ephemeris.count = mipc_ld_u8(d + 1);
        out->gnss_receiver_1_galileo_ephemeris.tow = mipc_ld_f64(d + 2);
        out->gnss_receiver_1_galileo_ephemeris.week_number = mipc_ld_u16(d + 10);
        out->gnss_receiver_1_galileo_ephemeris.satellite_id = mipc_ld_u8(d + 12);
        out->gnss_receiver_1_galileo_ephemeris.health = mipc_ld_u8(d + 13);
        out->gnss_receiver_1_galileo_ephemeris.iodc = mipc_ld_u8(d + 14);
        out->gnss_receiver_1_galileo_ephemeris.iode = mipc_ld_u8(d + 15);
        out->gnss_receiver_1_galileo_ephemeris.t_oc = mipc_ld_f64(d + 16);
        out->gnss_receiver_1_galileo_ephemeris.af0 = mipc_ld_f64(d + 24);
        out->gnss_receiver_1_galileo_ephemeris.af1 = mipc_ld_f64(d + 32);
        out->gnss_receiver_1_galileo_ephemeris.af2 = mipc_ld_f64(d + 40);
        out->gnss_receiver_1_galileo_ephemeris.t_gd = mipc_ld_f64(d + 48);
        out->gnss_receiver_1_galileo_ephemeris.isc_l1ca = mipc_ld_f64(d + 56);
        out->gnss_receiver_1_galileo_ephemeris.isc_l2c = mipc_ld_f64(d + 64);
        out->gnss_receiver_1_galileo_ephemeris.t_oe = mipc_ld_f64(d + 72);
        out->gnss_receiver_1_galileo_ephemeris.a = mipc_ld_f64(d + 80);
        out->gnss_receiver_1_galileo_ephemeris.a_dot = mipc_ld_f64(d + 88);
        out->gnss_receiver_1_galileo_ephemeris.mean_anomaly = mipc_ld_f64(d + 96);
        out->gnss_receiver_1_galileo_ephemeris.delta_mean_motion = mipc_ld_f64(d + 104);
        out->gnss_receiver_1_galileo_ephemeris.delta_mean_motion_dot = mipc_ld_f64(d + 112);
        out->gnss_receiver_1_galileo_ephemeris.eccentricity = mipc_ld_f64(d + 120);
        out->gnss_receiver_1_galileo_ephemeris.argument_of_perigee = mipc_ld_f64(d + 128);
        out->gnss_receiver_1_galileo_ephemeris.omega = mipc_ld_f64(d + 136);
        out->gnss_receiver_1_galileo_ephemeris.omega_dot = mipc_ld_f64(d + 144);
        out->gnss_receiver_1_galileo_ephemeris.inclination = mipc_ld_f64(d + 152);
        out->gnss_receiver_1_galileo_ephemeris.inclination_dot = mipc_ld_f64(d + 160);
        out->gnss_receiver_1_galileo_ephemeris.c_ic = mipc_ld_f64(d + 168);
        out->gnss_receiver_1_galileo_ephemeris.c_is = mipc_ld_f64(d + 176);
        out->gnss_receiver_1_galileo_ephemeris.c_uc = mipc_ld_f64(d + 184);
        out->gnss_receiver_1_galileo_ephemeris.c_us = mipc_ld_f64(d + 192);
        out->gnss_receiver_1_galileo_ephemeris.c_rc = mipc_ld_f64(d + 200);
        out->gnss_receiver_1_galileo_ephemeris.c_rs = mipc_ld_f64(d + 208);
        out->gnss_receiver_1_galileo_ephemeris.valid_flags = mipc_ld_u16(d + 216);
        return 1;
    }
    return mipc_gnss_receiver_1_galileo_ephemeris_decode(d, length, &out->gnss_receiver_1_galileo_ephemeris,
                                                         NULL) == MIPC_OK;
}

static int load_0x64(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_receiver_1_packet_t *out = packet;
    if (length == 218) {
        out->gnss_receiver_1_beidou_ephemeris.index = mipc_ld_u8(d + 0);
        out->gnss_receiver_1_beidou_ephemeris.count = mipc_ld_u8(d + 1);
        out->gnss_receiver_1_beidou_ephemeris.tow = mipc_ld_f64(d + 2);
        out->gnss_receiver_1_beidou_ephemeris.week_number = mipc_ld_u16(d + 10);
        out->gnss_receiver_1_beidou_ephemeris.satellite_id = mipc_ld_u8(d + 12);
        out->gnss_receiver_1_beidou_ephemeris.health = mipc_ld_u8(d + 13);
        out->gnss_receiver_1_beidou_ephemeris.iodc = mipc_ld_u8(d + 14);
        out->gnss_receiver_1_beidou_ephemeris.iode = mipc_ld_u8(d + 15);
        out->gnss_receiver_1_beidou_ephemeris.t_oc = mipc_ld_f64(d + 16);
        out->gnss_receiver_1_beidou_ephemeris.af0 = mipc_ld_f64(d + 24);
        out->gnss_receiver_1_beidou_ephemeris.af1 = mipc_ld_f64(d + 32);
        out->gnss_receiver_1_beidou_ephemeris.af2 = mipc_ld_f64(d + 40);
        out->gnss_receiver_1_beidou_ephemeris.t_gd = mipc_ld_f64(d + 48);
        out->gnss_receiver_1_beidou_ephemeris.isc_l1ca = mipc_ld_f64(d + 56);
        out->gnss_receiver_1_beidou_ephemeris.isc_l2c = mipc_ld_f64(d + 64);
        out->gnss_receiver_1_beidou_ephemeris.t_oe = mipc_ld_f64(d + 72);
        out->gnss_receiver_1_beidou_ephemeris.a = mipc_ld_f64(d + 80);
        out->gnss_receiver_1_beidou_ephemeris.a_dot = mipc_ld_f64(d + 88);
        out->gnss_receiver_1_beidou_ephemeris.mean_anomaly = mipc_ld_f64(d + 96);
        out->gnss_receiver_1_beidou_ephemeris.delta_mean_motion = mipc_ld_f64(d + 104);
        out->gnss_receiver_1_beidou_ephemeris.delta_mean_motion_dot = mipc_ld_f64(d + 112);
        out->gnss_receiver_1_beidou_ephemeris.eccentricity = mipc_ld_f64(d + 120);
        out->gnss_receiver_1_beidou_ephemeris.argument_of_perigee = mipc_ld_f64(d + 128);
        out->gnss_receiver_1_beidou_ephemeris.omega = mipc_ld_f64(d + 136);
        out->gnss_receiver_1_beidou_ephemeris.omega_dot = mipc_ld_f64(d + 144);
        out->gnss_receiver_1_beidou_ephemeris.inclination = mipc_ld_f64(d + 152);
        out->gnss_receiver_1_beidou_ephemeris.inclination_dot = mipc_ld_f64(d + 160);
        out->gnss_receiver_1_beidou_ephemeris.c_ic = mipc_ld_f64(d + 168);
        out->gnss_receiver_1_beidou_ephemeris.c_is = mipc_ld_f64(d + 176);
        out->gnss_receiver_1_beidou_ephemeris.c_uc = mipc_ld_f64(d + 184);
        out->gnss_receiver_1_beidou_ephemeris.c_us = mipc_ld_f64(d + 192);
        out->gnss_receiver_1_beidou_ephemeris.c_rc = mipc_ld_f64(d + 200);
        out->gnss_receiver_1_beidou_ephemeris.c_rs = mipc_ld_f64(d + 208);
        out->gnss_receiver_1_beidou_ephemeris.valid_flags = mipc_ld_u16(d + 216);
        return 1;
    }
    return mipc_gnss_receiver_1_beidou_ephemeris_decode(d, length, &out->gnss_receiver_1_beidou_ephemeris,
                                                        NULL) == MIPC_OK;
}

static int load_0xd0(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_receiver_1_packet_t *out = packet;
    if (length == 1) {
        out->shared_event_source.trigger_id = mipc_ld_u8(d + 0);
        return 1;
    }
    return mipc_shared_event_source_decode(d, length, &out->shared_event_source, NULL) == MIPC_OK;
}

static int load_0xd3(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_receiver_1_packet_t *out = packet;
    if (length == 12) {
        out->shared_gps_timestamp.tow = mipc_ld_f64(d + 0);
        out->shared_gps_timestamp.week_number = mipc_ld_u16(d + 8);
        out->shared_gps_timestamp.valid_flags = mipc_ld_u16(d + 10);
        return 1;
    }
    return mipc_shared_gps_timestamp_decode(d, length, &out->shared_gps_timestamp, NULL) == MIPC_OK;
}

static int load_0xd4(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_receiver_1_packet_t *out = packet;
    if (length == 8) {
        out->shared_delta_time.seconds = mipc_ld_f64(d + 0);
        return 1;
    }
    return mipc_shared_delta_time_decode(d, length, &out->shared_delta_time, NULL) == MIPC_OK;
}

static int load_0xd5(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_receiver_1_packet_t *out = packet;
    if (length == 8) {
        out->shared_reference_timestamp.nanoseconds = mipc_ld_u64(d + 0);
        return 1;
    }
    return mipc_shared_reference_timestamp_decode(d, length, &out->shared_reference_timestamp, NULL) ==
           MIPC_OK;
}

static int load_0xd6(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_receiver_1_packet_t *out = packet;
    if (length == 8) {
        out->shared_reference_time_delta.dt_nanos = mipc_ld_u64(d + 0);
        return 1;
    }
    return mipc_shared_reference_time_delta_decode(d, length, &out->shared_reference_time_delta, NULL) ==
           MIPC_OK;
}

static int load_0xd7(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_receiver_1_packet_t *out = packet;
    if (length == 10) {
        out->shared_external_timestamp.nanoseconds = mipc_ld_u64(d + 0);
        out->shared_external_timestamp.valid_flags = mipc_ld_u16(d + 8);
        return 1;
    }
    return mipc_shared_external_timestamp_decode(d, length, &out->shared_external_timestamp, NULL) == MIPC_OK;
}

static int load_0xd8(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_receiver_1_packet_t *out = packet;
    if (length == 10) {
        out->shared_external_time_delta.dt_nanos = mipc_ld_u64(d + 0);
        out->shared_external_time_delta.valid_flags = mipc_ld_u16(d + 8);
        return 1;
    }
    return mipc_shared_external_time_delta_decode(d, length, &out->shared_external_time_delta, NULL) ==
           MIPC_OK;
}

const mipc_layout_member_t mipc_gnss_receiver_1_layout_members_[25] = {
    {0x03, offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_llh_position), load_0x03},
    {0x04, offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_ecef_position), load_0x04},
    {0x05, offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_ned_velocity), load_0x05},
    {0x06, offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_ecef_velocity), load_0x06},
    {0x07, offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_dop), load_0x07},
    {0x08, offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_utc_time), load_0x08},
    {0x09, offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_gps_time), load_0x09},
    {0x0B, offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_fix_info), load_0x0b},
    {0x0D, offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_hardware_status), load_0x0d},
    {0x10, offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_clock_info_2), load_0x10},
    {0x11, offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_gps_leap_seconds), load_0x11},
    {0x12, offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_sbas_info), load_0x12},
    {0x20, offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_satellite_status), load_0x20},
    {0x22, offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_raw), load_0x22},
    {0x61, offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_gps_ephemeris), load_0x61},
    {0x62, offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_glonass_ephemeris), load_0x62},
    {0x63, offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_galileo_ephemeris), load_0x63},
    {0x64, offsetof(mipc_gnss_receiver_1_packet_t, gnss_receiver_1_beidou_ephemeris), load_0x64},
    {0xD0, offsetof(mipc_gnss_receiver_1_packet_t, shared_event_source), load_0xd0},
    {0xD3, offsetof(mipc_gnss_receiver_1_packet_t, shared_gps_timestamp), load_0xd3},
    {0xD4, offsetof(mipc_gnss_receiver_1_packet_t, shared_delta_time), load_0xd4},
    {0xD5, offsetof(mipc_gnss_receiver_1_packet_t, shared_reference_timestamp), load_0xd5},
    {0xD6, offsetof(mipc_gnss_receiver_1_packet_t, shared_reference_time_delta), load_0xd6},
    {0xD7, offsetof(mipc_gnss_receiver_1_packet_t, shared_external_timestamp), load_0xd7},
    {0xD8, offsetof(mipc_gnss_receiver_1_packet_t, shared_external_time_delta), load_0xd8},
};
