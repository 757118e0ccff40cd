/* Encoders and decoders of GNSS External Data Set. Generated from the spec: do not edit. */
#include "mipcodec/sets/gnss_external.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mipc_gnss_external_llh_position_t */

static int mipc_gnss_external_llh_position_read(mipc_reader_t *r, mipc_gnss_external_llh_position_t *out) {
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

static mipc_status_t mipc_gnss_external_llh_position_write(mipc_writer_t *w,
                                                           const mipc_gnss_external_llh_position_t *in) {
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

mipc_status_t mipc_gnss_external_llh_position_encode(const mipc_gnss_external_llh_position_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_external_llh_position_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 42 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_external_llh_position_load(const uint8_t *d, mipc_gnss_external_llh_position_t *out) {
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
static MIPC_NOINLINE mipc_status_t mipc_gnss_external_llh_position_decode_read(
    const uint8_t *data, size_t len, mipc_gnss_external_llh_position_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_external_llh_position_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_external_llh_position_decode(const uint8_t *data, size_t len,
                                                     mipc_gnss_external_llh_position_t *out,
                                                     mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 42 && mipc_gnss_external_llh_position_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_external_llh_position_decode_read(data, len, out, err);
}

/* ---- mipc_gnss_external_ned_velocity_t */

static int mipc_gnss_external_ned_velocity_read(mipc_reader_t *r, mipc_gnss_external_ned_velocity_t *out) {
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

static mipc_status_t mipc_gnss_external_ned_velocity_write(mipc_writer_t *w,
                                                           const mipc_gnss_external_ned_velocity_t *in) {
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

mipc_status_t mipc_gnss_external_ned_velocity_encode(const mipc_gnss_external_ned_velocity_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_external_ned_velocity_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 34 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_external_ned_velocity_load(const uint8_t *d, mipc_gnss_external_ned_velocity_t *out) {
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
static MIPC_NOINLINE mipc_status_t mipc_gnss_external_ned_velocity_decode_read(
    const uint8_t *data, size_t len, mipc_gnss_external_ned_velocity_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_external_ned_velocity_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_external_ned_velocity_decode(const uint8_t *data, size_t len,
                                                     mipc_gnss_external_ned_velocity_t *out,
                                                     mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 34 && mipc_gnss_external_ned_velocity_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_external_ned_velocity_decode_read(data, len, out, err);
}

/* ---- mipc_gnss_external_utc_time_t */

static int mipc_gnss_external_utc_time_read(mipc_reader_t *r, mipc_gnss_external_utc_time_t *out) {
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

static mipc_status_t mipc_gnss_external_utc_time_write(mipc_writer_t *w,
                                                       const mipc_gnss_external_utc_time_t *in) {
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

mipc_status_t mipc_gnss_external_utc_time_encode(const mipc_gnss_external_utc_time_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_external_utc_time_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 13 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_external_utc_time_load(const uint8_t *d, mipc_gnss_external_utc_time_t *out) {
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
static MIPC_NOINLINE mipc_status_t mipc_gnss_external_utc_time_decode_read(const uint8_t *data, size_t len,
                                                                           mipc_gnss_external_utc_time_t *out,
                                                                           mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_external_utc_time_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_external_utc_time_decode(const uint8_t *data, size_t len,
                                                 mipc_gnss_external_utc_time_t *out,
                                                 mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 13 && mipc_gnss_external_utc_time_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_external_utc_time_decode_read(data, len, out, err);
}

/* ---- mipc_gnss_external_fix_info_t */

static int mipc_gnss_external_fix_info_read(mipc_reader_t *r, mipc_gnss_external_fix_info_t *out) {
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

static mipc_status_t mipc_gnss_external_fix_info_write(mipc_writer_t *w,
                                                       const mipc_gnss_external_fix_info_t *in) {
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

mipc_status_t mipc_gnss_external_fix_info_encode(const mipc_gnss_external_fix_info_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_external_fix_info_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 6 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_external_fix_info_load(const uint8_t *d, mipc_gnss_external_fix_info_t *out) {
    out->fix_type = mipc_ld_u8(d + 0);
    out->num_sv = mipc_ld_u8(d + 1);
    out->fix_flags = mipc_ld_u16(d + 2);
    out->valid_flags = mipc_ld_u16(d + 4);
    return 0;
}

/* The general reader: lengths other than 6, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_gnss_external_fix_info_decode_read(const uint8_t *data, size_t len,
                                                                           mipc_gnss_external_fix_info_t *out,
                                                                           mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_external_fix_info_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_external_fix_info_decode(const uint8_t *data, size_t len,
                                                 mipc_gnss_external_fix_info_t *out,
                                                 mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 6 && mipc_gnss_external_fix_info_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_external_fix_info_decode_read(data, len, out, err);
}

/* ---- mipc_gnss_external_satellite_status_t */

static int mipc_gnss_external_satellite_status_read(mipc_reader_t *r,
                                                    mipc_gnss_external_satellite_status_t *out) {
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
mipc_gnss_external_satellite_status_write(mipc_writer_t *w, const mipc_gnss_external_satellite_status_t *in) {
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

mipc_status_t mipc_gnss_external_satellite_status_encode(const mipc_gnss_external_satellite_status_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_external_satellite_status_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 25 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_external_satellite_status_load(const uint8_t *d,
                                                    mipc_gnss_external_satellite_status_t *out) {
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
static MIPC_NOINLINE mipc_status_t mipc_gnss_external_satellite_status_decode_read(
    const uint8_t *data, size_t len, mipc_gnss_external_satellite_status_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_external_satellite_status_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_external_satellite_status_decode(const uint8_t *data, size_t len,
                                                         mipc_gnss_external_satellite_status_t *out,
                                                         mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 25 && mipc_gnss_external_satellite_status_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_external_satellite_status_decode_read(data, len, out, err);
}
