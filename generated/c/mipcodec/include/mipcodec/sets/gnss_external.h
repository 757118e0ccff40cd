/* GNSS External Data Set (descriptor set 0x94): one struct per field layout, with its
 * encoder and decoder. Generated from the spec: do not edit. */
#ifndef MIPC_SETS_GNSS_EXTERNAL_H
#define MIPC_SETS_GNSS_EXTERNAL_H

#include "mipcodec/types.h"
#include "mipcodec/field_iter.h"
#include "mipcodec/sets/shared.h"

#ifdef __cplusplus
extern "C" {
#endif

#define MIPC_GNSS_EXTERNAL_SET 0x94

/* ---- llh_position (data): GNSS LLH position */
#define MIPC_GNSS_EXTERNAL_LLH_POSITION_DESCRIPTOR 0x03

/** GNSS LLH position. External receiver position in the WGS84 geodetic frame (latitude, longitude, heights)
 * with accuracy estimates. */
typedef struct {
    double latitude;                                  /* Latitude (WGS84). [deg] */
    double longitude;                                 /* Longitude (WGS84). [deg] */
    double ellipsoid_height;                          /* Height above the WGS84 ellipsoid. [m] */
    double msl_height;                                /* Height above mean sea level. [m] */
    float horizontal_accuracy;                        /* Horizontal position accuracy estimate. [m] */
    float vertical_accuracy;                          /* Vertical position accuracy estimate. [m] */
    mipc_gnss_llh_position_valid_flags_t valid_flags; /* Which values are valid. */
} mipc_gnss_external_llh_position_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_EXTERNAL_LLH_POSITION_MAX_SIZE 42

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_external_llh_position_encode(const mipc_gnss_external_llh_position_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_external_llh_position_decode(const uint8_t *data, size_t len,
                                                     mipc_gnss_external_llh_position_t *out,
                                                     mipc_decode_error_t *err);

/* ---- ned_velocity (data): GNSS NED velocity */
#define MIPC_GNSS_EXTERNAL_NED_VELOCITY_DESCRIPTOR 0x05

/** GNSS NED velocity. External receiver velocity in the north-east-down frame, with 3D and ground speed,
 * heading and accuracy estimates. */
typedef struct {
    float velocity[3];                                /* (north, east, down) velocity. [m/s] */
    float speed;                                      /* 3D speed. [m/s] */
    float ground_speed;                               /* Horizontal (ground) speed. [m/s] */
    float heading;                                    /* Heading (direction of travel). [deg] */
    float speed_accuracy;                             /* Speed accuracy estimate. [m/s] */
    float heading_accuracy;                           /* Heading accuracy estimate. [deg] */
    mipc_gnss_ned_velocity_valid_flags_t valid_flags; /* Which values are valid. */
} mipc_gnss_external_ned_velocity_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_EXTERNAL_NED_VELOCITY_MAX_SIZE 34

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_external_ned_velocity_encode(const mipc_gnss_external_ned_velocity_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_external_ned_velocity_decode(const uint8_t *data, size_t len,
                                                     mipc_gnss_external_ned_velocity_t *out,
                                                     mipc_decode_error_t *err);

/* ---- utc_time (data): GNSS UTC time */
#define MIPC_GNSS_EXTERNAL_UTC_TIME_DESCRIPTOR 0x08

/** GNSS UTC time. UTC date and time from the external receiver, with a flag telling whether the leap seconds
 * are known. */
typedef struct {
    uint16_t year;                                    /* Year. */
    uint8_t month;                                    /* Month (1-12). */
    uint8_t day;                                      /* Day of the month (1-31). */
    uint8_t hour;                                     /* Hour (0-23). */
    uint8_t minute;                                   /* Minute (0-59). */
    uint8_t second;                                   /* Second (0-59). */
    uint32_t millisecond;                             /* Millisecond (0-999). [ms] */
    mipc_gnss_utc_time_valid_flags_cv7_t valid_flags; /* Validity of the date/time and of the leap seconds. */
} mipc_gnss_external_utc_time_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_EXTERNAL_UTC_TIME_MAX_SIZE 13

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_external_utc_time_encode(const mipc_gnss_external_utc_time_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_external_utc_time_decode(const uint8_t *data, size_t len,
                                                 mipc_gnss_external_utc_time_t *out,
                                                 mipc_decode_error_t *err);

/* ---- fix_info (data): GNSS fix information */
#define MIPC_GNSS_EXTERNAL_FIX_INFO_DESCRIPTOR 0x0B

/** GNSS fix information. Fix type, number of satellites used and corrections applied, from the external
 * receiver. */
typedef struct {
    mipc_gnss_fix_type_cv7_t fix_type;            /* Type of fix. */
    uint8_t num_sv;                               /* Number of satellites used in the solution. */
    mipc_gnss_fix_flags_t fix_flags;              /* Corrections used. */
    mipc_gnss_fix_info_valid_flags_t valid_flags; /* Which values are valid. */
} mipc_gnss_external_fix_info_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_EXTERNAL_FIX_INFO_MAX_SIZE 6

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_external_fix_info_encode(const mipc_gnss_external_fix_info_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_external_fix_info_decode(const uint8_t *data, size_t len,
                                                 mipc_gnss_external_fix_info_t *out,
                                                 mipc_decode_error_t *err);

/* ---- satellite_status (data): Satellite status */
#define MIPC_GNSS_EXTERNAL_SATELLITE_STATUS_DESCRIPTOR 0x20

/** Satellite status. Sky position and health of one satellite reported by the external receiver; one field
 * per satellite. */
typedef struct {
    uint8_t index;        /* Index of this field among the satellite status fields of this epoch. */
    uint8_t count;        /* Number of satellite status fields in this epoch. */
    double tow;           /* GPS time of week. [s] */
    uint16_t week_number; /* GPS week number since 1980. [weeks] */
    mipc_gnss_constellation_id_t gnss_id; /* Constellation of the satellite. */
    uint8_t satellite_id;                 /* Satellite number within its constellation. */
    float elevation;                      /* Elevation of the satellite seen from the receiver. [deg] */
    float azimuth;                        /* Azimuth of the satellite seen from the receiver. [deg] */
    bool health;                          /* True if the satellite is healthy. */
    mipc_gnss_satellite_status_valid_flags_t valid_flags; /* Which parameters are valid. */
} mipc_gnss_external_satellite_status_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_EXTERNAL_SATELLITE_STATUS_MAX_SIZE 25

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_external_satellite_status_encode(const mipc_gnss_external_satellite_status_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_external_satellite_status_decode(const uint8_t *data, size_t len,
                                                         mipc_gnss_external_satellite_status_t *out,
                                                         mipc_decode_error_t *err);

/**
 * The fields of one packet of this set, decoded in place by mipc_gnss_external_decode_packet: one member per
 * field the set defines with a single layout (its own, the reserved fields of its kind and the
 * shared data fields); `index` says which members hold a field of the packet, in packet order.
 */
typedef struct {
    mipc_packet_index_t index;
    mipc_gnss_external_llh_position_t gnss_external_llh_position;         /* 0x03 */
    mipc_gnss_external_ned_velocity_t gnss_external_ned_velocity;         /* 0x05 */
    mipc_gnss_external_utc_time_t gnss_external_utc_time;                 /* 0x08 */
    mipc_gnss_external_fix_info_t gnss_external_fix_info;                 /* 0x0B */
    mipc_gnss_external_satellite_status_t gnss_external_satellite_status; /* 0x20 */
    mipc_shared_event_source_t shared_event_source;                       /* 0xD0 (shared) */
    mipc_shared_gps_timestamp_t shared_gps_timestamp;                     /* 0xD3 (shared) */
    mipc_shared_delta_time_t shared_delta_time;                           /* 0xD4 (shared) */
    mipc_shared_reference_timestamp_t shared_reference_timestamp;         /* 0xD5 (shared) */
    mipc_shared_reference_time_delta_t shared_reference_time_delta;       /* 0xD6 (shared) */
    mipc_shared_external_timestamp_t shared_external_timestamp;           /* 0xD7 (shared) */
    mipc_shared_external_time_delta_t shared_external_time_delta;         /* 0xD8 (shared) */
} mipc_gnss_external_packet_t;

/**
 * The straight-line decoder of a packet of this set (issue 38): walks the fields of the payload
 * (len bytes at payload) with a switch on the descriptor and decodes each field's layout into its
 * member of *out, giving the value mipc_decode_field gives; no general value, no indirect call. Every
 * other entry goes to other (may be NULL: they are dropped) with ctx, in packet order with the
 * fields: a descriptor without a member (undefined, or a field with per-device variants), a field
 * that does not decode (its member is then unspecified), a second field with a descriptor already
 * decoded, trailing bytes. Returns out->index.count, the number of fields decoded into members.
 */
size_t mipc_gnss_external_decode_packet(const uint8_t *payload, size_t len, mipc_gnss_external_packet_t *out,
                                        mipc_field_entry_fn other, void *ctx);

/* Private (mipc_decode_packet_cached): the members of mipc_gnss_external_packet_t: descriptor, offset,
 * loader. */
extern const mipc_layout_member_t mipc_gnss_external_layout_members_[12];

#ifdef __cplusplus
}
#endif

#endif
