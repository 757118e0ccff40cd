/* Encoders and decoders of GNSS Data Set. Generated from the spec: do not edit. */
#include "mipcodec/sets/gnss_data.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <stddef.h>
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_data_llh_position_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_data_llh_position_decode(const uint8_t *data, size_t len,
                                                 mipc_gnss_data_llh_position_t *out,
                                                 mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 42 && mipc_gnss_data_llh_position_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_data_llh_position_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_data_ecef_position_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_data_ecef_position_decode(const uint8_t *data, size_t len,
                                                  mipc_gnss_data_ecef_position_t *out,
                                                  mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 30 && mipc_gnss_data_ecef_position_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_data_ecef_position_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_data_ned_velocity_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_data_ned_velocity_decode(const uint8_t *data, size_t len,
                                                 mipc_gnss_data_ned_velocity_t *out,
                                                 mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 34 && mipc_gnss_data_ned_velocity_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_data_ned_velocity_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_data_ecef_velocity_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_data_ecef_velocity_decode(const uint8_t *data, size_t len,
                                                  mipc_gnss_data_ecef_velocity_t *out,
                                                  mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 18 && mipc_gnss_data_ecef_velocity_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_data_ecef_velocity_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_data_dop_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_data_dop_decode(const uint8_t *data, size_t len, mipc_gnss_data_dop_t *out,
                                        mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 30 && mipc_gnss_data_dop_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_data_dop_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_data_utc_time_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_data_utc_time_decode(const uint8_t *data, size_t len, mipc_gnss_data_utc_time_t *out,
                                             mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 13 && mipc_gnss_data_utc_time_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_data_utc_time_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_data_gps_time_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_data_gps_time_decode(const uint8_t *data, size_t len, mipc_gnss_data_gps_time_t *out,
                                             mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mipc_gnss_data_gps_time_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_data_gps_time_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_data_clock_info_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_data_clock_info_decode(const uint8_t *data, size_t len,
                                               mipc_gnss_data_clock_info_t *out, mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 26 && mipc_gnss_data_clock_info_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_data_clock_info_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_data_fix_info_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_data_fix_info_decode(const uint8_t *data, size_t len, mipc_gnss_data_fix_info_t *out,
                                             mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 6 && mipc_gnss_data_fix_info_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_data_fix_info_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_data_sv_info_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_data_sv_info_decode(const uint8_t *data, size_t len, mipc_gnss_data_sv_info_t *out,
                                            mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mipc_gnss_data_sv_info_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_data_sv_info_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_data_hardware_status_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_data_hardware_status_decode(const uint8_t *data, size_t len,
                                                    mipc_gnss_data_hardware_status_t *out,
                                                    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 5 && mipc_gnss_data_hardware_status_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_data_hardware_status_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_data_dgnss_info_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_data_dgnss_info_decode(const uint8_t *data, size_t len,
                                               mipc_gnss_data_dgnss_info_t *out, mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mipc_gnss_data_dgnss_info_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_data_dgnss_info_decode_read(data, len, out, err);
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
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
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
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_data_dgnss_channel_status_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_data_dgnss_channel_status_decode(const uint8_t *data, size_t len,
                                                         mipc_gnss_data_dgnss_channel_status_t *out,
                                                         mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 15 && mipc_gnss_data_dgnss_channel_status_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_data_dgnss_channel_status_decode_read(data, len, out, err);
}

/* ---- the straight-line packet decoder */

size_t mipc_gnss_data_decode_packet(const uint8_t *payload, size_t len, mipc_gnss_data_packet_t *out,
                                    mipc_field_entry_fn other, void *ctx) {
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
        const int data_len =
            (int)head[MIPC_FIELD_LENGTH_OFFSET] - mipc_field_length_adjust(MIPC_GNSS_DATA_SET, descriptor);
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
                    out->gnss_data_llh_position.latitude = mipc_ld_f64(d + 0);
                    out->gnss_data_llh_position.longitude = mipc_ld_f64(d + 8);
                    out->gnss_data_llh_position.ellipsoid_height = mipc_ld_f64(d + 16);
                    out->gnss_data_llh_position.msl_height = mipc_ld_f64(d + 24);
                    out->gnss_data_llh_position.horizontal_accuracy = mipc_ld_f32(d + 32);
                    out->gnss_data_llh_position.vertical_accuracy = mipc_ld_f32(d + 36);
                    out->gnss_data_llh_position.valid_flags = mipc_ld_u16(d + 40);
                    ok = 1;
                } else {
                    ok = mipc_gnss_data_llh_position_decode(d, length, &out->gnss_data_llh_position, NULL) ==
                         MIPC_OK;
                }
                offset = offsetof(mipc_gnss_data_packet_t, gnss_data_llh_position);
                break;
            case 0x04:
                if (length == 30) {
                    out->gnss_data_ecef_position.position[0] = mipc_ld_f64(d + 0);
                    out->gnss_data_ecef_position.position[1] = mipc_ld_f64(d + 8);
                    out->gnss_data_ecef_position.position[2] = mipc_ld_f64(d + 16);
                    out->gnss_data_ecef_position.position_accuracy = mipc_ld_f32(d + 24);
                    out->gnss_data_ecef_position.valid_flags = mipc_ld_u16(d + 28);
                    ok = 1;
                } else {
                    ok = mipc_gnss_data_ecef_position_decode(d, length, &out->gnss_data_ecef_position,
                                                             NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_data_packet_t, gnss_data_ecef_position);
                break;
            case 0x05:
                if (length == 34) {
                    out->gnss_data_ned_velocity.velocity[0] = mipc_ld_f32(d + 0);
                    out->gnss_data_ned_velocity.velocity[1] = mipc_ld_f32(d + 4);
                    out->gnss_data_ned_velocity.velocity[2] = mipc_ld_f32(d + 8);
                    out->gnss_data_ned_velocity.speed = mipc_ld_f32(d + 12);
                    out->gnss_data_ned_velocity.ground_speed = mipc_ld_f32(d + 16);
                    out->gnss_data_ned_velocity.heading = mipc_ld_f32(d + 20);
                    out->gnss_data_ned_velocity.speed_accuracy = mipc_ld_f32(d + 24);
                    out->gnss_data_ned_velocity.heading_accuracy = mipc_ld_f32(d + 28);
                    out->gnss_data_ned_velocity.valid_flags = mipc_ld_u16(d + 32);
                    ok = 1;
                } else {
                    ok = mipc_gnss_data_ned_velocity_decode(d, length, &out->gnss_data_ned_velocity, NULL) ==
                         MIPC_OK;
                }
                offset = offsetof(mipc_gnss_data_packet_t, gnss_data_ned_velocity);
                break;
            case 0x06:
                if (length == 18) {
                    out->gnss_data_ecef_velocity.velocity[0] = mipc_ld_f32(d + 0);
                    out->gnss_data_ecef_velocity.velocity[1] = mipc_ld_f32(d + 4);
                    out->gnss_data_ecef_velocity.velocity[2] = mipc_ld_f32(d + 8);
                    out->gnss_data_ecef_velocity.velocity_accuracy = mipc_ld_f32(d + 12);
                    out->gnss_data_ecef_velocity.valid_flags = mipc_ld_u16(d + 16);
                    ok = 1;
                } else {
                    ok = mipc_gnss_data_ecef_velocity_decode(d, length, &out->gnss_data_ecef_velocity,
                                                             NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_data_packet_t, gnss_data_ecef_velocity);
                break;
            case 0x07:
                if (length == 30) {
                    out->gnss_data_dop.gdop = mipc_ld_f32(d + 0);
                    out->gnss_data_dop.pdop = mipc_ld_f32(d + 4);
                    out->gnss_data_dop.hdop = mipc_ld_f32(d + 8);
                    out->gnss_data_dop.vdop = mipc_ld_f32(d + 12);
                    out->gnss_data_dop.tdop = mipc_ld_f32(d + 16);
                    out->gnss_data_dop.ndop = mipc_ld_f32(d + 20);
                    out->gnss_data_dop.edop = mipc_ld_f32(d + 24);
                    out->gnss_data_dop.valid_flags = mipc_ld_u16(d + 28);
                    ok = 1;
                } else {
                    ok = mipc_gnss_data_dop_decode(d, length, &out->gnss_data_dop, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_data_packet_t, gnss_data_dop);
                break;
            case 0x08:
                if (length == 13) {
                    out->gnss_data_utc_time.year = mipc_ld_u16(d + 0);
                    out->gnss_data_utc_time.month = mipc_ld_u8(d + 2);
                    out->gnss_data_utc_time.day = mipc_ld_u8(d + 3);
                    out->gnss_data_utc_time.hour = mipc_ld_u8(d + 4);
                    out->gnss_data_utc_time.minute = mipc_ld_u8(d + 5);
                    out->gnss_data_utc_time.second = mipc_ld_u8(d + 6);
                    out->gnss_data_utc_time.millisecond = mipc_ld_u32(d + 7);
                    out->gnss_data_utc_time.valid_flags = mipc_ld_u16(d + 11);
                    ok = 1;
                } else {
                    ok = mipc_gnss_data_utc_time_decode(d, length, &out->gnss_data_utc_time, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_data_packet_t, gnss_data_utc_time);
                break;
            case 0x09:
                if (length == 12) {
                    out->gnss_data_gps_time.tow = mipc_ld_f64(d + 0);
                    out->gnss_data_gps_time.week_number = mipc_ld_u16(d + 8);
                    out->gnss_data_gps_time.valid_flags = mipc_ld_u16(d + 10);
                    ok = 1;
                } else {
                    ok = mipc_gnss_data_gps_time_decode(d, length, &out->gnss_data_gps_time, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_data_packet_t, gnss_data_gps_time);
                break;
            case 0x0A:
                if (length == 26) {
                    out->gnss_data_clock_info.bias = mipc_ld_f64(d + 0);
                    out->gnss_data_clock_info.drift = mipc_ld_f64(d + 8);
                    out->gnss_data_clock_info.accuracy_estimate = mipc_ld_f64(d + 16);
                    out->gnss_data_clock_info.valid_flags = mipc_ld_u16(d + 24);
                    ok = 1;
                } else {
                    ok = mipc_gnss_data_clock_info_decode(d, length, &out->gnss_data_clock_info, NULL) ==
                         MIPC_OK;
                }
                offset = offsetof(mipc_gnss_data_packet_t, gnss_data_clock_info);
                break;
            case 0x0B:
                if (length == 6) {
                    out->gnss_data_fix_info.fix_type = mipc_ld_u8(d + 0);
                    out->gnss_data_fix_info.num_sv = mipc_ld_u8(d + 1);
                    out->gnss_data_fix_info.fix_flags = mipc_ld_u16(d + 2);
                    out->gnss_data_fix_info.valid_flags = mipc_ld_u16(d + 4);
                    ok = 1;
                } else {
                    ok = mipc_gnss_data_fix_info_decode(d, length, &out->gnss_data_fix_info, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_data_packet_t, gnss_data_fix_info);
                break;
            case 0x0C:
                if (length == 12) {
                    out->gnss_data_sv_info.channel = mipc_ld_u8(d + 0);
                    out->gnss_data_sv_info.sv_id = mipc_ld_u8(d + 1);
                    out->gnss_data_sv_info.carrier_to_noise_ratio = mipc_ld_u16(d + 2);
                    out->gnss_data_sv_info.azimuth = mipc_ld_s16(d + 4);
                    out->gnss_data_sv_info.elevation = mipc_ld_s16(d + 6);
                    out->gnss_data_sv_info.sv_flags = mipc_ld_u16(d + 8);
                    out->gnss_data_sv_info.valid_flags = mipc_ld_u16(d + 10);
                    ok = 1;
                } else {
                    ok = mipc_gnss_data_sv_info_decode(d, length, &out->gnss_data_sv_info, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_data_packet_t, gnss_data_sv_info);
                break;
            case 0x0D:
                if (length == 5) {
                    out->gnss_data_hardware_status.receiver_state = mipc_ld_u8(d + 0);
                    out->gnss_data_hardware_status.antenna_state = mipc_ld_u8(d + 1);
                    out->gnss_data_hardware_status.antenna_power = mipc_ld_u8(d + 2);
                    out->gnss_data_hardware_status.valid_flags = mipc_ld_u16(d + 3);
                    ok = 1;
                } else {
                    ok = mipc_gnss_data_hardware_status_decode(d, length, &out->gnss_data_hardware_status,
                                                               NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_data_packet_t, gnss_data_hardware_status);
                break;
            case 0x0E:
                if (length == 12) {
                    out->gnss_data_dgnss_info.newest_age = mipc_ld_f32(d + 0);
                    out->gnss_data_dgnss_info.base_station_id = mipc_ld_s16(d + 4);
                    out->gnss_data_dgnss_info.base_station_status = mipc_ld_s16(d + 6);
                    out->gnss_data_dgnss_info.num_channels = mipc_ld_u16(d + 8);
                    out->gnss_data_dgnss_info.valid_flags = mipc_ld_u16(d + 10);
                    ok = 1;
                } else {
                    ok = mipc_gnss_data_dgnss_info_decode(d, length, &out->gnss_data_dgnss_info, NULL) ==
                         MIPC_OK;
                }
                offset = offsetof(mipc_gnss_data_packet_t, gnss_data_dgnss_info);
                break;
            case 0x0F:
                if (length == 15) {
                    out->gnss_data_dgnss_channel_status.sv_id = mipc_ld_u8(d + 0);
                    out->gnss_data_dgnss_channel_status.age = mipc_ld_f32(d + 1);
                    out->gnss_data_dgnss_channel_status.pseudorange_correction = mipc_ld_f32(d + 5);
                    out->gnss_data_dgnss_channel_status.pseudorange_rate_correction = mipc_ld_f32(d + 9);
                    out->gnss_data_dgnss_channel_status.valid_flags = mipc_ld_u16(d + 13);
                    ok = 1;
                } else {
                    ok = mipc_gnss_data_dgnss_channel_status_decode(
                             d, length, &out->gnss_data_dgnss_channel_status, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_data_packet_t, gnss_data_dgnss_channel_status);
                break;
            case 0xD0:
                if (length == 1) {
                    out->shared_event_source.trigger_id = mipc_ld_u8(d + 0);
                    ok = 1;
                } else {
                    ok = mipc_shared_event_source_decode(d, length, &out->shared_event_source, NULL) ==
                         MIPC_OK;
                }
                offset = offsetof(mipc_gnss_data_packet_t, shared_event_source);
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
                offset = offsetof(mipc_gnss_data_packet_t, shared_gps_timestamp);
                break;
            case 0xD4:
                if (length == 8) {
                    out->shared_delta_time.seconds = mipc_ld_f64(d + 0);
                    ok = 1;
                } else {
                    ok = mipc_shared_delta_time_decode(d, length, &out->shared_delta_time, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_data_packet_t, shared_delta_time);
                break;
            case 0xD5:
                if (length == 8) {
                    out->shared_reference_timestamp.nanoseconds = mipc_ld_u64(d + 0);
                    ok = 1;
                } else {
                    ok = mipc_shared_reference_timestamp_decode(d, length, &out->shared_reference_timestamp,
                                                                NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_data_packet_t, shared_reference_timestamp);
                break;
            case 0xD6:
                if (length == 8) {
                    out->shared_reference_time_delta.dt_nanos = mipc_ld_u64(d + 0);
                    ok = 1;
                } else {
                    ok = mipc_shared_reference_time_delta_decode(d, length, &out->shared_reference_time_delta,
                                                                 NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_data_packet_t, shared_reference_time_delta);
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
                offset = offsetof(mipc_gnss_data_packet_t, shared_external_timestamp);
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
                offset = offsetof(mipc_gnss_data_packet_t, shared_external_time_delta);
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
            mipc_field_visit_at_(MIPC_GNSS_DATA_SET, payload, len, pos, other, ctx);
        }
        pos += MIPC_FIELD_HEADER_SIZE + length;
    }
    if (pos < len && other) {
        mipc_field_visit_at_(MIPC_GNSS_DATA_SET, payload, len, pos, other, ctx);
    }
    out->index.count = n;
    return n;
}

/* ---- the members' loaders (mipc_decode_packet_cached, issue 38): each decodes its field's
 * data into its member of the mipc_gnss_data_packet_t at packet as mipc_gnss_data_decode_packet does; 0 when
 * it does not decode (the packet then takes the straight-line decoder, which gives the field to other) */

static int load_0x03(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_data_packet_t *out = packet;
    if (length == 42) {
        out->gnss_data_llh_position.latitude = mipc_ld_f64(d + 0);
        out->gnss_data_llh_position.longitude = mipc_ld_f64(d + 8);
        out->gnss_data_llh_position.ellipsoid_height = mipc_ld_f64(d + 16);
        out->gnss_data_llh_position.msl_height = mipc_ld_f64(d + 24);
        out->gnss_data_llh_position.horizontal_accuracy = mipc_ld_f32(d + 32);
        out->gnss_data_llh_position.vertical_accuracy = mipc_ld_f32(d + 36);
        out->gnss_data_llh_position.valid_flags = mipc_ld_u16(d + 40);
        return 1;
    }
    return mipc_gnss_data_llh_position_decode(d, length, &out->gnss_data_llh_position, NULL) == MIPC_OK;
}

static int load_0x04(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_data_packet_t *out = packet;
    if (length == 30) {
        out->gnss_data_ecef_position.position[0] = mipc_ld_f64(d + 0);
        out->gnss_data_ecef_position.position[1] = mipc_ld_f64(d + 8);
        out->gnss_data_ecef_position.position[2] = mipc_ld_f64(d + 16);
        out->gnss_data_ecef_position.position_accuracy = mipc_ld_f32(d + 24);
        out->gnss_data_ecef_position.valid_flags = mipc_ld_u16(d + 28);
        return 1;
    }
    return mipc_gnss_data_ecef_position_decode(d, length, &out->gnss_data_ecef_position, NULL) == MIPC_OK;
}

static int load_0x05(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_data_packet_t *out = packet;
    if (length == 34) {
        out->gnss_data_ned_velocity.velocity[0] = mipc_ld_f32(d + 0);
        out->gnss_data_ned_velocity.velocity[1] = mipc_ld_f32(d + 4);
        out->gnss_data_ned_velocity.velocity[2] = mipc_ld_f32(d + 8);
        out->gnss_data_ned_velocity.speed = mipc_ld_f32(d + 12);
        out->gnss_data_ned_velocity.ground_speed = mipc_ld_f32(d + 16);
        out->gnss_data_ned_velocity.heading = mipc_ld_f32(d + 20);
        out->gnss_data_ned_velocity.speed_accuracy = mipc_ld_f32(d + 24);
        out->gnss_data_ned_velocity.heading_accuracy = mipc_ld_f32(d + 28);
        out->gnss_data_ned_velocity.valid_flags = mipc_ld_u16(d + 32);
        return 1;
    }
    return mipc_gnss_data_ned_velocity_decode(d, length, &out->gnss_data_ned_velocity, NULL) == MIPC_OK;
}

static int load_0x06(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_data_packet_t *out = packet;
    if (length == 18) {
        out->gnss_data_ecef_velocity.velocity[0] = mipc_ld_f32(d + 0);
        out->gnss_data_ecef_velocity.velocity[1] = mipc_ld_f32(d + 4);
        out->gnss_data_ecef_velocity.velocity[2] = mipc_ld_f32(d + 8);
        out->gnss_data_ecef_velocity.velocity_accuracy = mipc_ld_f32(d + 12);
        out->gnss_data_ecef_velocity.valid_flags = mipc_ld_u16(d + 16);
        return 1;
    }
    return mipc_gnss_data_ecef_velocity_decode(d, length, &out->gnss_data_ecef_velocity, NULL) == MIPC_OK;
}

static int load_0x07(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_data_packet_t *out = packet;
    if (length == 30) {
        out->gnss_data_dop.gdop = mipc_ld_f32(d + 0);
        out->gnss_data_dop.pdop = mipc_ld_f32(d + 4);
        out->gnss_data_dop.hdop = mipc_ld_f32(d + 8);
        out->gnss_data_dop.vdop = mipc_ld_f32(d + 12);
        out->gnss_data_dop.tdop = mipc_ld_f32(d + 16);
        out->gnss_data_dop.ndop = mipc_ld_f32(d + 20);
        out->gnss_data_dop.edop = mipc_ld_f32(d + 24);
        out->gnss_data_dop.valid_flags = mipc_ld_u16(d + 28);
        return 1;
    }
    return mipc_gnss_data_dop_decode(d, length, &out->gnss_data_dop, NULL) == MIPC_OK;
}

static int load_0x08(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_data_packet_t *out = packet;
    if (length == 13) {
        out->gnss_data_utc_time.year = mipc_ld_u16(d + 0);
        out->gnss_data_utc_time.month = mipc_ld_u8(d + 2);
        out->gnss_data_utc_time.day = mipc_ld_u8(d + 3);
        out->gnss_data_utc_time.hour = mipc_ld_u8(d + 4);
        out->gnss_data_utc_time.minute = mipc_ld_u8(d + 5);
        out->gnss_data_utc_time.second = mipc_ld_u8(d + 6);
        out->gnss_data_utc_time.millisecond = mipc_ld_u32(d + 7);
        out->gnss_data_utc_time.valid_flags = mipc_ld_u16(d + 11);
        return 1;
    }
    return mipc_gnss_data_utc_time_decode(d, length, &out->gnss_data_utc_time, NULL) == MIPC_OK;
}

static int load_0x09(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_data_packet_t *out = packet;
    if (length == 12) {
        out->gnss_data_gps_time.tow = mipc_ld_f64(d + 0);
        out->gnss_data_gps_time.week_number = mipc_ld_u16(d + 8);
        out->gnss_data_gps_time.valid_flags = mipc_ld_u16(d + 10);
        return 1;
    }
    return mipc_gnss_data_gps_time_decode(d, length, &out->gnss_data_gps_time, NULL) == MIPC_OK;
}

static int load_0x0a(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_data_packet_t *out = packet;
    if (length == 26) {
        out->gnss_data_clock_info.bias = mipc_ld_f64(d + 0);
        out->gnss_data_clock_info.drift = mipc_ld_f64(d + 8);
        out->gnss_data_clock_info.accuracy_estimate = mipc_ld_f64(d + 16);
        out->gnss_data_clock_info.valid_flags = mipc_ld_u16(d + 24);
        return 1;
    }
    return mipc_gnss_data_clock_info_decode(d, length, &out->gnss_data_clock_info, NULL) == MIPC_OK;
}

static int load_0x0b(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_data_packet_t *out = packet;
    if (length == 6) {
        out->gnss_data_fix_info.fix_type = mipc_ld_u8(d + 0);
        out->gnss_data_fix_info.num_sv = mipc_ld_u8(d + 1);
        out->gnss_data_fix_info.fix_flags = mipc_ld_u16(d + 2);
        out->gnss_data_fix_info.valid_flags = mipc_ld_u16(d + 4);
        return 1;
    }
    return mipc_gnss_data_fix_info_decode(d, length, &out->gnss_data_fix_info, NULL) == MIPC_OK;
}

static int load_0x0c(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_data_packet_t *out = packet;
    if (length == 12) {
        out->gnss_data_sv_info.channel = mipc_ld_u8(d + 0);
        out->gnss_data_sv_info.sv_id = mipc_ld_u8(d + 1);
        out->gnss_data_sv_info.carrier_to_noise_ratio = mipc_ld_u16(d + 2);
        out->gnss_data_sv_info.azimuth = mipc_ld_s16(d + 4);
        out->gnss_data_sv_info.elevation = mipc_ld_s16(d + 6);
        out->gnss_data_sv_info.sv_flags = mipc_ld_u16(d + 8);
        out->gnss_data_sv_info.valid_flags = mipc_ld_u16(d + 10);
        return 1;
    }
    return mipc_gnss_data_sv_info_decode(d, length, &out->gnss_data_sv_info, NULL) == MIPC_OK;
}

static int load_0x0d(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_data_packet_t *out = packet;
    if (length == 5) {
        out->gnss_data_hardware_status.receiver_state = mipc_ld_u8(d + 0);
        out->gnss_data_hardware_status.antenna_state = mipc_ld_u8(d + 1);
        out->gnss_data_hardware_status.antenna_power = mipc_ld_u8(d + 2);
        out->gnss_data_hardware_status.valid_flags = mipc_ld_u16(d + 3);
        return 1;
    }
    return mipc_gnss_data_hardware_status_decode(d, length, &out->gnss_data_hardware_status, NULL) == MIPC_OK;
}

static int load_0x0e(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_data_packet_t *out = packet;
    if (length == 12) {
        out->gnss_data_dgnss_info.newest_age = mipc_ld_f32(d + 0);
        out->gnss_data_dgnss_info.base_station_id = mipc_ld_s16(d + 4);
        out->gnss_data_dgnss_info.base_station_status = mipc_ld_s16(d + 6);
        out->gnss_data_dgnss_info.num_channels = mipc_ld_u16(d + 8);
        out->gnss_data_dgnss_info.valid_flags = mipc_ld_u16(d + 10);
        return 1;
    }
    return mipc_gnss_data_dgnss_info_decode(d, length, &out->gnss_data_dgnss_info, NULL) == MIPC_OK;
}

static int load_0x0f(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_data_packet_t *out = packet;
    if (length == 15) {
        out->gnss_data_dgnss_channel_status.sv_id = mipc_ld_u8(d + 0);
        out->gnss_data_dgnss_channel_status.age = mipc_ld_f32(d + 1);
        out->gnss_data_dgnss_channel_status.pseudorange_correction = mipc_ld_f32(d + 5);
        out->gnss_data_dgnss_channel_status.pseudorange_rate_correction = mipc_ld_f32(d + 9);
        out->gnss_data_dgnss_channel_status.valid_flags = mipc_ld_u16(d + 13);
        return 1;
    }
    return mipc_gnss_data_dgnss_channel_status_decode(d, length, &out->gnss_data_dgnss_channel_status,
                                                      NULL) == MIPC_OK;
}

static int load_0xd0(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_data_packet_t *out = packet;
    if (length == 1) {
        out->shared_event_source.trigger_id = mipc_ld_u8(d + 0);
        return 1;
    }
    return mipc_shared_event_source_decode(d, length, &out->shared_event_source, NULL) == MIPC_OK;
}

static int load_0xd3(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_data_packet_t *out = packet;
    if (length == 12) {
        out->shared_gps_timestamp.tow = mipc_ld_f64(d + 0);
        out->shared_gps_timestamp.week_number = mipc_ld_u16(d + 8);
        out->shared_gps_timestamp.valid_flags = mipc_ld_u16(d + 10);
        return 1;
    }
    return mipc_shared_gps_timestamp_decode(d, length, &out->shared_gps_timestamp, NULL) == MIPC_OK;
}

static int load_0xd4(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_data_packet_t *out = packet;
    if (length == 8) {
        out->shared_delta_time.seconds = mipc_ld_f64(d + 0);
        return 1;
    }
    return mipc_shared_delta_time_decode(d, length, &out->shared_delta_time, NULL) == MIPC_OK;
}

static int load_0xd5(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_data_packet_t *out = packet;
    if (length == 8) {
        out->shared_reference_timestamp.nanoseconds = mipc_ld_u64(d + 0);
        return 1;
    }
    return mipc_shared_reference_timestamp_decode(d, length, &out->shared_reference_timestamp, NULL) ==
           MIPC_OK;
}

static int load_0xd6(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_data_packet_t *out = packet;
    if (length == 8) {
        out->shared_reference_time_delta.dt_nanos = mipc_ld_u64(d + 0);
        return 1;
    }
    return mipc_shared_reference_time_delta_decode(d, length, &out->shared_reference_time_delta, NULL) ==
           MIPC_OK;
}

static int load_0xd7(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_data_packet_t *out = packet;
    if (length == 10) {
        out->shared_external_timestamp.nanoseconds = mipc_ld_u64(d + 0);
        out->shared_external_timestamp.valid_flags = mipc_ld_u16(d + 8);
        return 1;
    }
    return mipc_shared_external_timestamp_decode(d, length, &out->shared_external_timestamp, NULL) == MIPC_OK;
}

static int load_0xd8(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_data_packet_t *out = packet;
    if (length == 10) {
        out->shared_external_time_delta.dt_nanos = mipc_ld_u64(d + 0);
        out->shared_external_time_delta.valid_flags = mipc_ld_u16(d + 8);
        return 1;
    }
    return mipc_shared_external_time_delta_decode(d, length, &out->shared_external_time_delta, NULL) ==
           MIPC_OK;
}

const mipc_layout_member_t mipc_gnss_data_layout_members_[20] = {
    {0x03, offsetof(mipc_gnss_data_packet_t, gnss_data_llh_position), load_0x03},
    {0x04, offsetof(mipc_gnss_data_packet_t, gnss_data_ecef_position), load_0x04},
    {0x05, offsetof(mipc_gnss_data_packet_t, gnss_data_ned_velocity), load_0x05},
    {0x06, offsetof(mipc_gnss_data_packet_t, gnss_data_ecef_velocity), load_0x06},
    {0x07, offsetof(mipc_gnss_data_packet_t, gnss_data_dop), load_0x07},
    {0x08, offsetof(mipc_gnss_data_packet_t, gnss_data_utc_time), load_0x08},
    {0x09, offsetof(mipc_gnss_data_packet_t, gnss_data_gps_time), load_0x09},
    {0x0A, offsetof(mipc_gnss_data_packet_t, gnss_data_clock_info), load_0x0a},
    {0x0B, offsetof(mipc_gnss_data_packet_t, gnss_data_fix_info), load_0x0b},
    {0x0C, offsetof(mipc_gnss_data_packet_t, gnss_data_sv_info), load_0x0c},
    {0x0D, offsetof(mipc_gnss_data_packet_t, gnss_data_hardware_status), load_0x0d},
    {0x0E, offsetof(mipc_gnss_data_packet_t, gnss_data_dgnss_info), load_0x0e},
    {0x0F, offsetof(mipc_gnss_data_packet_t, gnss_data_dgnss_channel_status), load_0x0f},
    {0xD0, offsetof(mipc_gnss_data_packet_t, shared_event_source), load_0xd0},
    {0xD3, offsetof(mipc_gnss_data_packet_t, shared_gps_timestamp), load_0xd3},
    {0xD4, offsetof(mipc_gnss_data_packet_t, shared_delta_time), load_0xd4},
    {0xD5, offsetof(mipc_gnss_data_packet_t, shared_reference_timestamp), load_0xd5},
    {0xD6, offsetof(mipc_gnss_data_packet_t, shared_reference_time_delta), load_0xd6},
    {0xD7, offsetof(mipc_gnss_data_packet_t, shared_external_timestamp), load_0xd7},
    {0xD8, offsetof(mipc_gnss_data_packet_t, shared_external_time_delta), load_0xd8},
};
