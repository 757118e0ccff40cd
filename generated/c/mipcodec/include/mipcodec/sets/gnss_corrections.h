/* GNSS Corrections Data Set (descriptor set 0x93): one struct per field layout, with its
 * encoder and decoder. Generated from the spec: do not edit. */
#ifndef MIPC_SETS_GNSS_CORRECTIONS_H
#define MIPC_SETS_GNSS_CORRECTIONS_H

#include "mipcodec/types.h"
#include "mipcodec/field_iter.h"
#include "mipcodec/sets/shared.h"

#ifdef __cplusplus
extern "C" {
#endif

#define MIPC_GNSS_CORRECTIONS_SET 0x93

/* ---- base_station_info (data): Base station information */
#define MIPC_GNSS_CORRECTIONS_BASE_STATION_INFO_DESCRIPTOR 0x30

/** Base station information. Base station reported by the RTCM corrections (message 1005 or 1006): its ECEF
 * position, antenna height, station id and indicators, with the GPS time the message was received. */
typedef struct {
    double tow;                                     /* GPS time of week the message was received. [s] */
    uint16_t week_number;                           /* GPS week number (since 1980). [weeks] */
    double ecef_position[3];                        /* (x, y, z) ECEF position of the base station. [m] */
    float height;                                   /* Antenna height above the survey marker. [m] */
    uint16_t station_id;                            /* Reference station id (0-4095). */
    mipc_gnss_base_station_indicators_t indicators; /* Base station indicator bits. */
    mipc_gnss_base_station_info_valid_flags_t valid_flags; /* Which values are valid. */
} mipc_gnss_corrections_base_station_info_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_CORRECTIONS_BASE_STATION_INFO_MAX_SIZE 44

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_gnss_corrections_base_station_info_encode(const mipc_gnss_corrections_base_station_info_t *value,
                                               uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_corrections_base_station_info_decode(const uint8_t *data, size_t len,
                                                             mipc_gnss_corrections_base_station_info_t *out,
                                                             mipc_decode_error_t *err);

/* ---- rtk_corrections_status (data): RTK corrections status */
#define MIPC_GNSS_CORRECTIONS_RTK_CORRECTIONS_STATUS_DESCRIPTOR 0x31

/** RTK corrections status. Status of the RTK corrections received in the current epoch, the RTK dongle status
 * and the latency of the last correction per constellation, with the GPS time. */
typedef struct {
    double tow;           /* GPS time of week. [s] */
    uint16_t week_number; /* GPS week number (since 1980). [weeks] */
    mipc_rtk_corrections_epoch_status_t
        epoch_status;                 /* Status of the corrections received during this epoch. */
    uint32_t dongle_status;           /* RTK dongle status flags (only valid when an RTK dongle is used). */
    float gps_correction_latency;     /* Latency of the last GPS correction. [s] */
    float glonass_correction_latency; /* Latency of the last GLONASS correction. [s] */
    float galileo_correction_latency; /* Latency of the last Galileo correction. [s] */
    float beidou_correction_latency;  /* Latency of the last BeiDou correction. [s] */
    uint32_t reserved[4];             /* Reserved for future use. */
    mipc_rtk_corrections_status_valid_flags_t valid_flags; /* Which values are valid. */
} mipc_gnss_corrections_rtk_corrections_status_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_CORRECTIONS_RTK_CORRECTIONS_STATUS_MAX_SIZE 50

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_corrections_rtk_corrections_status_encode(
    const mipc_gnss_corrections_rtk_corrections_status_t *value, uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_gnss_corrections_rtk_corrections_status_decode(const uint8_t *data, size_t len,
                                                    mipc_gnss_corrections_rtk_corrections_status_t *out,
                                                    mipc_decode_error_t *err);

/**
 * The fields of one packet of this set, decoded in place by mipc_gnss_corrections_decode_packet: one member
 * per field the set defines with a single layout (its own, the reserved fields of its kind and the shared
 * data fields); `index` says which members hold a field of the packet, in packet order.
 */
typedef struct {
    mipc_packet_index_t index;
    mipc_gnss_corrections_base_station_info_t gnss_corrections_base_station_info;           /* 0x30 */
    mipc_gnss_corrections_rtk_corrections_status_t gnss_corrections_rtk_corrections_status; /* 0x31 */
    mipc_shared_event_source_t shared_event_source;                 /* 0xD0 (shared) */
    mipc_shared_gps_timestamp_t shared_gps_timestamp;               /* 0xD3 (shared) */
    mipc_shared_delta_time_t shared_delta_time;                     /* 0xD4 (shared) */
    mipc_shared_reference_timestamp_t shared_reference_timestamp;   /* 0xD5 (shared) */
    mipc_shared_reference_time_delta_t shared_reference_time_delta; /* 0xD6 (shared) */
    mipc_shared_external_timestamp_t shared_external_timestamp;     /* 0xD7 (shared) */
    mipc_shared_external_time_delta_t shared_external_time_delta;   /* 0xD8 (shared) */
} mipc_gnss_corrections_packet_t;

/**
 * The straight-line decoder of a packet of this set (issue 38): walks the fields of the payload
 * (len bytes at payload) with a switch on the descriptor and decodes each field's layout into its
 * member of *out, giving the value mipc_decode_field gives; no general value, no indirect call. Every
 * other entry goes to other (may be NULL: they are dropped) with ctx, in packet order with the
 * fields: a descriptor without a member (undefined, or a field with per-device variants), a field
 * that does not decode (its member is then unspecified), a second field with a descriptor already
 * decoded, trailing bytes. Returns out->index.count, the number of fields decoded into members.
 */
size_t mipc_gnss_corrections_decode_packet(const uint8_t *payload, size_t len,
                                           mipc_gnss_corrections_packet_t *out, mipc_field_entry_fn other,
                                           void *ctx);

/* Private (mipc_decode_packet_cached): the members of mipc_gnss_corrections_packet_t: descriptor, offset,
 * loader. */
extern const mipc_layout_member_t mipc_gnss_corrections_layout_members_[9];

#ifdef __cplusplus
}
#endif

#endif
