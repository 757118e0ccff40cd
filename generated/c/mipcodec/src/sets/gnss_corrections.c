/* Encoders and decoders of GNSS Corrections Data Set. Generated from the spec: do not edit. */
#include "mipcodec/sets/gnss_corrections.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <stddef.h>
#include <string.h>

/* ---- mipc_gnss_corrections_base_station_info_t */

static int mipc_gnss_corrections_base_station_info_read(mipc_reader_t *r,
                                                        mipc_gnss_corrections_base_station_info_t *out) {
    size_t i;
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
    mipc_rd_push(r, "ecef_position");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f64(r, &out->ecef_position[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "height");
    if (mipc_rd_f32(r, &out->height)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "station_id");
    if (mipc_rd_u16(r, &out->station_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "indicators");
    if (mipc_rd_u16(r, &out->indicators)) {
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
mipc_gnss_corrections_base_station_info_write(mipc_writer_t *w,
                                              const mipc_gnss_corrections_base_station_info_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_f64(w, &in->tow)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->week_number)) != MIPC_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f64(w, &in->ecef_position[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_f32(w, &in->height)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->station_id)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->indicators)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_gnss_corrections_base_station_info_encode(const mipc_gnss_corrections_base_station_info_t *value,
                                               uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_corrections_base_station_info_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 44 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_corrections_base_station_info_load(const uint8_t *d,
                                                        mipc_gnss_corrections_base_station_info_t *out) {
    out->tow = mipc_ld_f64(d + 0);
    out->week_number = mipc_ld_u16(d + 8);
    out->ecef_position[0] = mipc_ld_f64(d + 10);
    out->ecef_position[1] = mipc_ld_f64(d + 18);
    out->ecef_position[2] = mipc_ld_f64(d + 26);
    out->height = mipc_ld_f32(d + 34);
    out->station_id = mipc_ld_u16(d + 38);
    out->indicators = mipc_ld_u16(d + 40);
    out->valid_flags = mipc_ld_u16(d + 42);
    return 0;
}

/* The general reader: lengths other than 44, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_gnss_corrections_base_station_info_decode_read(
    const uint8_t *data, size_t len, mipc_gnss_corrections_base_station_info_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_corrections_base_station_info_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_corrections_base_station_info_decode(const uint8_t *data, size_t len,
                                                             mipc_gnss_corrections_base_station_info_t *out,
                                                             mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 44 && mipc_gnss_corrections_base_station_info_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_corrections_base_station_info_decode_read(data, len, out, err);
}

/* ---- mipc_gnss_corrections_rtk_corrections_status_t */

static int
mipc_gnss_corrections_rtk_corrections_status_read(mipc_reader_t *r,
                                                  mipc_gnss_corrections_rtk_corrections_status_t *out) {
    size_t i;
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
    mipc_rd_push(r, "epoch_status");
    if (mipc_rd_u16(r, &out->epoch_status)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "dongle_status");
    if (mipc_rd_u32(r, &out->dongle_status)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "gps_correction_latency");
    if (mipc_rd_f32(r, &out->gps_correction_latency)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "glonass_correction_latency");
    if (mipc_rd_f32(r, &out->glonass_correction_latency)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "galileo_correction_latency");
    if (mipc_rd_f32(r, &out->galileo_correction_latency)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "beidou_correction_latency");
    if (mipc_rd_f32(r, &out->beidou_correction_latency)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "reserved");
    for (i = 0; i < 4; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_u32(r, &out->reserved[i])) {
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

static mipc_status_t
mipc_gnss_corrections_rtk_corrections_status_write(mipc_writer_t *w,
                                                   const mipc_gnss_corrections_rtk_corrections_status_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_f64(w, &in->tow)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->week_number)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->epoch_status)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u32(w, &in->dongle_status)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->gps_correction_latency)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->glonass_correction_latency)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->galileo_correction_latency)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->beidou_correction_latency)) != MIPC_OK) {
        return st;
    }
    for (i = 0; i < 4; i++) {
        if ((st = mipc_wr_u32(w, &in->reserved[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_gnss_corrections_rtk_corrections_status_encode(
    const mipc_gnss_corrections_rtk_corrections_status_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_corrections_rtk_corrections_status_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 50 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_gnss_corrections_rtk_corrections_status_load(const uint8_t *d,
                                                  mipc_gnss_corrections_rtk_corrections_status_t *out) {
    out->tow = mipc_ld_f64(d + 0);
    out->week_number = mipc_ld_u16(d + 8);
    out->epoch_status = mipc_ld_u16(d + 10);
    out->dongle_status = mipc_ld_u32(d + 12);
    out->gps_correction_latency = mipc_ld_f32(d + 16);
    out->glonass_correction_latency = mipc_ld_f32(d + 20);
    out->galileo_correction_latency = mipc_ld_f32(d + 24);
    out->beidou_correction_latency = mipc_ld_f32(d + 28);
    out->reserved[0] = mipc_ld_u32(d + 32);
    out->reserved[1] = mipc_ld_u32(d + 36);
    out->reserved[2] = mipc_ld_u32(d + 40);
    out->reserved[3] = mipc_ld_u32(d + 44);
    out->valid_flags = mipc_ld_u16(d + 48);
    return 0;
}

/* The general reader: lengths other than 50, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_gnss_corrections_rtk_corrections_status_decode_read(
    const uint8_t *data, size_t len, mipc_gnss_corrections_rtk_corrections_status_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_corrections_rtk_corrections_status_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_gnss_corrections_rtk_corrections_status_decode(const uint8_t *data, size_t len,
                                                    mipc_gnss_corrections_rtk_corrections_status_t *out,
                                                    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 50 && mipc_gnss_corrections_rtk_corrections_status_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_corrections_rtk_corrections_status_decode_read(data, len, out, err);
}

/* ---- the straight-line packet decoder */

size_t mipc_gnss_corrections_decode_packet(const uint8_t *payload, size_t len,
                                           mipc_gnss_corrections_packet_t *out, mipc_field_entry_fn other,
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
                             mipc_field_length_adjust(MIPC_GNSS_CORRECTIONS_SET, descriptor);
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
            case 0x30:
                if (length == 44) {
                    out->gnss_corrections_base_station_info.tow = mipc_ld_f64(d + 0);
                    out->gnss_corrections_base_station_info.week_number = mipc_ld_u16(d + 8);
                    out->gnss_corrections_base_station_info.ecef_position[0] = mipc_ld_f64(d + 10);
                    out->gnss_corrections_base_station_info.ecef_position[1] = mipc_ld_f64(d + 18);
                    out->gnss_corrections_base_station_info.ecef_position[2] = mipc_ld_f64(d + 26);
                    out->gnss_corrections_base_station_info.height = mipc_ld_f32(d + 34);
                    out->gnss_corrections_base_station_info.station_id = mipc_ld_u16(d + 38);
                    out->gnss_corrections_base_station_info.indicators = mipc_ld_u16(d + 40);
                    out->gnss_corrections_base_station_info.valid_flags = mipc_ld_u16(d + 42);
                    ok = 1;
                } else {
                    ok = mipc_gnss_corrections_base_station_info_decode(
                             d, length, &out->gnss_corrections_base_station_info, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_corrections_packet_t, gnss_corrections_base_station_info);
                break;
            case 0x31:
                if (length == 50) {
                    out->gnss_corrections_rtk_corrections_status.tow = mipc_ld_f64(d + 0);
                    out->gnss_corrections_rtk_corrections_status.week_number = mipc_ld_u16(d + 8);
                    out->gnss_corrections_rtk_corrections_status.epoch_status = mipc_ld_u16(d + 10);
                    out->gnss_corrections_rtk_corrections_status.dongle_status = mipc_ld_u32(d + 12);
                    out->gnss_corrections_rtk_corrections_status.gps_correction_latency = mipc_ld_f32(d + 16);
                    out->gnss_corrections_rtk_corrections_status.glonass_correction_latency =
                        mipc_ld_f32(d + 20);
                    out->gnss_corrections_rtk_corrections_status.galileo_correction_latency =
                        mipc_ld_f32(d + 24);
                    out->gnss_corrections_rtk_corrections_status.beidou_correction_latency =
                        mipc_ld_f32(d + 28);
                    out->gnss_corrections_rtk_corrections_status.reserved[0] = mipc_ld_u32(d + 32);
                    out->gnss_corrections_rtk_corrections_status.reserved[1] = mipc_ld_u32(d + 36);
                    out->gnss_corrections_rtk_corrections_status.reserved[2] = mipc_ld_u32(d + 40);
                    out->gnss_corrections_rtk_corrections_status.reserved[3] = mipc_ld_u32(d + 44);
                    out->gnss_corrections_rtk_corrections_status.valid_flags = mipc_ld_u16(d + 48);
                    ok = 1;
                } else {
                    ok = mipc_gnss_corrections_rtk_corrections_status_decode(
                             d, length, &out->gnss_corrections_rtk_corrections_status, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_corrections_packet_t, gnss_corrections_rtk_corrections_status);
                break;
            case 0xD0:
                if (length == 1) {
                    out->shared_event_source.trigger_id = mipc_ld_u8(d + 0);
                    ok = 1;
                } else {
                    ok = mipc_shared_event_source_decode(d, length, &out->shared_event_source, NULL) ==
                         MIPC_OK;
                }
                offset = offsetof(mipc_gnss_corrections_packet_t, shared_event_source);
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
                offset = offsetof(mipc_gnss_corrections_packet_t, shared_gps_timestamp);
                break;
            case 0xD4:
                if (length == 8) {
                    out->shared_delta_time.seconds = mipc_ld_f64(d + 0);
                    ok = 1;
                } else {
                    ok = mipc_shared_delta_time_decode(d, length, &out->shared_delta_time, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_corrections_packet_t, shared_delta_time);
                break;
            case 0xD5:
                if (length == 8) {
                    out->shared_reference_timestamp.nanoseconds = mipc_ld_u64(d + 0);
                    ok = 1;
                } else {
                    ok = mipc_shared_reference_timestamp_decode(d, length, &out->shared_reference_timestamp,
                                                                NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_corrections_packet_t, shared_reference_timestamp);
                break;
            case 0xD6:
                if (length == 8) {
                    out->shared_reference_time_delta.dt_nanos = mipc_ld_u64(d + 0);
                    ok = 1;
                } else {
                    ok = mipc_shared_reference_time_delta_decode(d, length, &out->shared_reference_time_delta,
                                                                 NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_gnss_corrections_packet_t, shared_reference_time_delta);
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
                offset = offsetof(mipc_gnss_corrections_packet_t, shared_external_timestamp);
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
                offset = offsetof(mipc_gnss_corrections_packet_t, shared_external_time_delta);
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
            mipc_field_visit_at_(MIPC_GNSS_CORRECTIONS_SET, payload, len, pos, other, ctx);
        }
        pos += MIPC_FIELD_HEADER_SIZE + length;
    }
    if (pos < len && other) {
        mipc_field_visit_at_(MIPC_GNSS_CORRECTIONS_SET, payload, len, pos, other, ctx);
    }
    out->index.count = n;
    return n;
}

/* ---- the members' loaders (mipc_decode_packet_cached, issue 38): each decodes its field's
 * data into its member of the mipc_gnss_corrections_packet_t at packet as mipc_gnss_corrections_decode_packet
 * does; 0 when it does not decode (the packet then takes the straight-line decoder, which gives the field to
 * other) */

static int load_0x30(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_corrections_packet_t *out = packet;
    if (length == 44) {
        out->gnss_corrections_base_station_info.tow = mipc_ld_f64(d + 0);
        out->gnss_corrections_base_station_info.week_number = mipc_ld_u16(d + 8);
        out->gnss_corrections_base_station_info.ecef_position[0] = mipc_ld_f64(d + 10);
        out->gnss_corrections_base_station_info.ecef_position[1] = mipc_ld_f64(d + 18);
        out->gnss_corrections_base_station_info.ecef_position[2] = mipc_ld_f64(d + 26);
        out->gnss_corrections_base_station_info.height = mipc_ld_f32(d + 34);
        out->gnss_corrections_base_station_info.station_id = mipc_ld_u16(d + 38);
        out->gnss_corrections_base_station_info.indicators = mipc_ld_u16(d + 40);
        out->gnss_corrections_base_station_info.valid_flags = mipc_ld_u16(d + 42);
        return 1;
    }
    return mipc_gnss_corrections_base_station_info_decode(d, length, &out->gnss_corrections_base_station_info,
                                                          NULL) == MIPC_OK;
}

static int load_0x31(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_corrections_packet_t *out = packet;
    if (length == 50) {
        out->gnss_corrections_rtk_corrections_status.tow = mipc_ld_f64(d + 0);
        out->gnss_corrections_rtk_corrections_status.week_number = mipc_ld_u16(d + 8);
        out->gnss_corrections_rtk_corrections_status.epoch_status = mipc_ld_u16(d + 10);
        out->gnss_corrections_rtk_corrections_status.dongle_status = mipc_ld_u32(d + 12);
        out->gnss_corrections_rtk_corrections_status.gps_correction_latency = mipc_ld_f32(d + 16);
        out->gnss_corrections_rtk_corrections_status.glonass_correction_latency = mipc_ld_f32(d + 20);
        out->gnss_corrections_rtk_corrections_status.galileo_correction_latency = mipc_ld_f32(d + 24);
        out->gnss_corrections_rtk_corrections_status.beidou_correction_latency = mipc_ld_f32(d + 28);
        out->gnss_corrections_rtk_corrections_status.reserved[0] = mipc_ld_u32(d + 32);
        out->gnss_corrections_rtk_corrections_status.reserved[1] = mipc_ld_u32(d + 36);
        out->gnss_corrections_rtk_corrections_status.reserved[2] = mipc_ld_u32(d + 40);
        out->gnss_corrections_rtk_corrections_status.reserved[3] = mipc_ld_u32(d + 44);
        out->gnss_corrections_rtk_corrections_status.valid_flags = mipc_ld_u16(d + 48);
        return 1;
    }
    return mipc_gnss_corrections_rtk_corrections_status_decode(
               d, length, &out->gnss_corrections_rtk_corrections_status, NULL) == MIPC_OK;
}

static int load_0xd0(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_corrections_packet_t *out = packet;
    if (length == 1) {
        out->shared_event_source.trigger_id = mipc_ld_u8(d + 0);
        return 1;
    }
    return mipc_shared_event_source_decode(d, length, &out->shared_event_source, NULL) == MIPC_OK;
}

static int load_0xd3(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_corrections_packet_t *out = packet;
    if (length == 12) {
        out->shared_gps_timestamp.tow = mipc_ld_f64(d + 0);
        out->shared_gps_timestamp.week_number = mipc_ld_u16(d + 8);
        out->shared_gps_timestamp.valid_flags = mipc_ld_u16(d + 10);
        return 1;
    }
    return mipc_shared_gps_timestamp_decode(d, length, &out->shared_gps_timestamp, NULL) == MIPC_OK;
}

static int load_0xd4(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_corrections_packet_t *out = packet;
    if (length == 8) {
        out->shared_delta_time.seconds = mipc_ld_f64(d + 0);
        return 1;
    }
    return mipc_shared_delta_time_decode(d, length, &out->shared_delta_time, NULL) == MIPC_OK;
}

static int load_0xd5(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_corrections_packet_t *out = packet;
    if (length == 8) {
        out->shared_reference_timestamp.nanoseconds = mipc_ld_u64(d + 0);
        return 1;
    }
    return mipc_shared_reference_timestamp_decode(d, length, &out->shared_reference_timestamp, NULL) ==
           MIPC_OK;
}

static int load_0xd6(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_corrections_packet_t *out = packet;
    if (length == 8) {
        out->shared_reference_time_delta.dt_nanos = mipc_ld_u64(d + 0);
        return 1;
    }
    return mipc_shared_reference_time_delta_decode(d, length, &out->shared_reference_time_delta, NULL) ==
           MIPC_OK;
}

static int load_0xd7(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_corrections_packet_t *out = packet;
    if (length == 10) {
        out->shared_external_timestamp.nanoseconds = mipc_ld_u64(d + 0);
        out->shared_external_timestamp.valid_flags = mipc_ld_u16(d + 8);
        return 1;
    }
    return mipc_shared_external_timestamp_decode(d, length, &out->shared_external_timestamp, NULL) == MIPC_OK;
}

static int load_0xd8(const uint8_t *d, size_t length, void *packet) {
    mipc_gnss_corrections_packet_t *out = packet;
    if (length == 10) {
        out->shared_external_time_delta.dt_nanos = mipc_ld_u64(d + 0);
        out->shared_external_time_delta.valid_flags = mipc_ld_u16(d + 8);
        return 1;
    }
    return mipc_shared_external_time_delta_decode(d, length, &out->shared_external_time_delta, NULL) ==
           MIPC_OK;
}

const mipc_layout_member_t mipc_gnss_corrections_layout_members_[9] = {
    {0x30, offsetof(mipc_gnss_corrections_packet_t, gnss_corrections_base_station_info), load_0x30},
    {0x31, offsetof(mipc_gnss_corrections_packet_t, gnss_corrections_rtk_corrections_status), load_0x31},
    {0xD0, offsetof(mipc_gnss_corrections_packet_t, shared_event_source), load_0xd0},
    {0xD3, offsetof(mipc_gnss_corrections_packet_t, shared_gps_timestamp), load_0xd3},
    {0xD4, offsetof(mipc_gnss_corrections_packet_t, shared_delta_time), load_0xd4},
    {0xD5, offsetof(mipc_gnss_corrections_packet_t, shared_reference_timestamp), load_0xd5},
    {0xD6, offsetof(mipc_gnss_corrections_packet_t, shared_reference_time_delta), load_0xd6},
    {0xD7, offsetof(mipc_gnss_corrections_packet_t, shared_external_timestamp), load_0xd7},
    {0xD8, offsetof(mipc_gnss_corrections_packet_t, shared_external_time_delta), load_0xd8},
};
