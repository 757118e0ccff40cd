/* GNSS Data Set (descriptor set 0x81): one struct per field layout, with its
 * encoder and decoder. Generated from the spec: do not edit. */
#ifndef MIPC_SETS_GNSS_DATA_H
#define MIPC_SETS_GNSS_DATA_H

#include "mipcodec/types.h"
#include "mipcodec/field_iter.h"
#include "mipcodec/sets/shared.h"

#ifdef __cplusplus
extern "C" {
#endif

#define MIPC_GNSS_DATA_SET 0x81

/* ---- llh_position (data): LLH position */
#define MIPC_GNSS_DATA_LLH_POSITION_DESCRIPTOR 0x03

/** LLH position. Receiver position in the geodetic frame (latitude, longitude, heights) with accuracy
 * estimates. */
typedef struct {
    double latitude;                                  /* Latitude (WGS84). [deg] */
    double longitude;                                 /* Longitude (WGS84). [deg] */
    double ellipsoid_height;                          /* Height above the WGS84 ellipsoid. [m] */
    double msl_height;                                /* Height above mean sea level. [m] */
    float horizontal_accuracy;                        /* Horizontal position accuracy estimate. [m] */
    float vertical_accuracy;                          /* Vertical position accuracy estimate. [m] */
    mipc_gnss_llh_position_valid_flags_t valid_flags; /* Which values are valid. */
} mipc_gnss_data_llh_position_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_DATA_LLH_POSITION_MAX_SIZE 42

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_data_llh_position_encode(const mipc_gnss_data_llh_position_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_data_llh_position_decode(const uint8_t *data, size_t len,
                                                 mipc_gnss_data_llh_position_t *out,
                                                 mipc_decode_error_t *err);

/* ---- ecef_position (data): ECEF position */
#define MIPC_GNSS_DATA_ECEF_POSITION_DESCRIPTOR 0x04

/** ECEF position. Receiver position in the Earth-centred, Earth-fixed frame with its accuracy estimate. */
typedef struct {
    double position[3];                                /* (x, y, z) ECEF position. [m] */
    float position_accuracy;                           /* Position accuracy estimate. [m] */
    mipc_gnss_ecef_position_valid_flags_t valid_flags; /* Which values are valid. */
} mipc_gnss_data_ecef_position_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_DATA_ECEF_POSITION_MAX_SIZE 30

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_data_ecef_position_encode(const mipc_gnss_data_ecef_position_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_data_ecef_position_decode(const uint8_t *data, size_t len,
                                                  mipc_gnss_data_ecef_position_t *out,
                                                  mipc_decode_error_t *err);

/* ---- ned_velocity (data): NED velocity */
#define MIPC_GNSS_DATA_NED_VELOCITY_DESCRIPTOR 0x05

/** NED velocity. Receiver velocity in the north-east-down frame, with 3D and ground speed, heading and
 * accuracy estimates. */
typedef struct {
    float velocity[3];                                /* (north, east, down) velocity. [m/s] */
    float speed;                                      /* 3D speed. [m/s] */
    float ground_speed;                               /* Horizontal (ground) speed. [m/s] */
    float heading;                                    /* Heading (direction of travel). [deg] */
    float speed_accuracy;                             /* Speed accuracy estimate. [m/s] */
    float heading_accuracy;                           /* Heading accuracy estimate. [deg] */
    mipc_gnss_ned_velocity_valid_flags_t valid_flags; /* Which values are valid. */
} mipc_gnss_data_ned_velocity_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_DATA_NED_VELOCITY_MAX_SIZE 34

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_data_ned_velocity_encode(const mipc_gnss_data_ned_velocity_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_data_ned_velocity_decode(const uint8_t *data, size_t len,
                                                 mipc_gnss_data_ned_velocity_t *out,
                                                 mipc_decode_error_t *err);

/* ---- ecef_velocity (data): ECEF velocity */
#define MIPC_GNSS_DATA_ECEF_VELOCITY_DESCRIPTOR 0x06

/** ECEF velocity. Receiver velocity in the Earth-centred, Earth-fixed frame with its accuracy estimate. */
typedef struct {
    float velocity[3];                                 /* (x, y, z) ECEF velocity. [m/s] */
    float velocity_accuracy;                           /* Velocity accuracy estimate. [m/s] */
    mipc_gnss_ecef_velocity_valid_flags_t valid_flags; /* Which values are valid. */
} mipc_gnss_data_ecef_velocity_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_DATA_ECEF_VELOCITY_MAX_SIZE 18

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_data_ecef_velocity_encode(const mipc_gnss_data_ecef_velocity_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_data_ecef_velocity_decode(const uint8_t *data, size_t len,
                                                  mipc_gnss_data_ecef_velocity_t *out,
                                                  mipc_decode_error_t *err);

/* ---- dop (data): DOP data */
#define MIPC_GNSS_DATA_DOP_DESCRIPTOR 0x07

/** DOP data. Geometric, position, horizontal, vertical, time, northing and easting dilution of precision. */
typedef struct {
    float gdop;                              /* Geometric DOP. */
    float pdop;                              /* Position DOP. */
    float hdop;                              /* Horizontal DOP. */
    float vdop;                              /* Vertical DOP. */
    float tdop;                              /* Time DOP. */
    float ndop;                              /* Northing DOP. */
    float edop;                              /* Easting DOP. */
    mipc_gnss_dop_valid_flags_t valid_flags; /* Which values are valid. */
} mipc_gnss_data_dop_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_DATA_DOP_MAX_SIZE 30

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_data_dop_encode(const mipc_gnss_data_dop_t *value, uint8_t *buf, size_t cap,
                                        size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_data_dop_decode(const uint8_t *data, size_t len, mipc_gnss_data_dop_t *out,
                                        mipc_decode_error_t *err);

/* ---- utc_time (data): UTC time */
#define MIPC_GNSS_DATA_UTC_TIME_DESCRIPTOR 0x08

/** UTC time. UTC date and time from the GNSS receiver, with separate date and time valid flags. */
typedef struct {
    uint16_t year;                                    /* Year (1999-2099). */
    uint8_t month;                                    /* Month (1-12). */
    uint8_t day;                                      /* Day of the month (1-31). */
    uint8_t hour;                                     /* Hour (0-23). */
    uint8_t minute;                                   /* Minute (0-59). */
    uint8_t second;                                   /* Second (0-59). */
    uint32_t millisecond;                             /* Millisecond. [ms] */
    mipc_gnss_utc_time_valid_flags_gx5_t valid_flags; /* Validity of the date and of the time. */
} mipc_gnss_data_utc_time_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_DATA_UTC_TIME_MAX_SIZE 13

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_data_utc_time_encode(const mipc_gnss_data_utc_time_t *value, uint8_t *buf, size_t cap,
                                             size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_data_utc_time_decode(const uint8_t *data, size_t len, mipc_gnss_data_utc_time_t *out,
                                             mipc_decode_error_t *err);

/* ---- gps_time (data): GPS time */
#define MIPC_GNSS_DATA_GPS_TIME_DESCRIPTOR 0x09

/** GPS time. GPS time of week and week number. */
typedef struct {
    double tow;                                   /* GPS time of week. [s] */
    uint16_t week_number;                         /* GPS week number (since 1980). [weeks] */
    mipc_gnss_gps_time_valid_flags_t valid_flags; /* Which values are valid. */
} mipc_gnss_data_gps_time_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_DATA_GPS_TIME_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_data_gps_time_encode(const mipc_gnss_data_gps_time_t *value, uint8_t *buf, size_t cap,
                                             size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_data_gps_time_decode(const uint8_t *data, size_t len, mipc_gnss_data_gps_time_t *out,
                                             mipc_decode_error_t *err);

/* ---- clock_info (data): Clock information */
#define MIPC_GNSS_DATA_CLOCK_INFO_DESCRIPTOR 0x0A

/** Clock information. GNSS receiver clock bias and drift, with an accuracy estimate. */
typedef struct {
    double bias;                                    /* Receiver clock bias. [s] */
    double drift;                                   /* Receiver clock drift. [s/s] */
    double accuracy_estimate;                       /* Clock accuracy estimate. [s] */
    mipc_gnss_clock_info_valid_flags_t valid_flags; /* Which values are valid. */
} mipc_gnss_data_clock_info_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_DATA_CLOCK_INFO_MAX_SIZE 26

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_data_clock_info_encode(const mipc_gnss_data_clock_info_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_data_clock_info_decode(const uint8_t *data, size_t len,
                                               mipc_gnss_data_clock_info_t *out, mipc_decode_error_t *err);

/* ---- fix_info (data): GNSS fix information */
#define MIPC_GNSS_DATA_FIX_INFO_DESCRIPTOR 0x0B

/** GNSS fix information. Fix type, number of satellites used and corrections applied. */
typedef struct {
    mipc_gnss_fix_type_gx5_t fix_type;            /* Type of fix. */
    uint8_t num_sv;                               /* Number of satellites used for the solution. */
    mipc_gnss_fix_flags_t fix_flags;              /* Corrections used. */
    mipc_gnss_fix_info_valid_flags_t valid_flags; /* Which values are valid. */
} mipc_gnss_data_fix_info_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_DATA_FIX_INFO_MAX_SIZE 6

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_data_fix_info_encode(const mipc_gnss_data_fix_info_t *value, uint8_t *buf, size_t cap,
                                             size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_data_fix_info_decode(const uint8_t *data, size_t len, mipc_gnss_data_fix_info_t *out,
                                             mipc_decode_error_t *err);

/* ---- sv_info (data): Space vehicle information */
#define MIPC_GNSS_DATA_SV_INFO_DESCRIPTOR 0x0C

/** Space vehicle information. One entry per space vehicle: channel, SV id, carrier-to-noise ratio, azimuth,
 * elevation and use/health flags. The entries arrive in a MIP packet of their own, separate from the other
 * GNSS fields, one field per vehicle. */
typedef struct {
    uint8_t channel;                             /* Receiver channel number. */
    uint8_t sv_id;                               /* Space vehicle id number. */
    uint16_t carrier_to_noise_ratio;             /* Carrier to noise ratio. [dBHz] */
    int16_t azimuth;                             /* Azimuth, whole degrees. [deg] */
    int16_t elevation;                           /* Elevation, whole degrees. [deg] */
    mipc_gnss_sv_flags_t sv_flags;               /* Use and health of the vehicle. */
    mipc_gnss_sv_info_valid_flags_t valid_flags; /* Which values are valid. */
} mipc_gnss_data_sv_info_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_DATA_SV_INFO_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_data_sv_info_encode(const mipc_gnss_data_sv_info_t *value, uint8_t *buf, size_t cap,
                                            size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_data_sv_info_decode(const uint8_t *data, size_t len, mipc_gnss_data_sv_info_t *out,
                                            mipc_decode_error_t *err);

/* ---- hardware_status (data): Hardware status */
#define MIPC_GNSS_DATA_HARDWARE_STATUS_DESCRIPTOR 0x0D

/** Hardware status. Receiver (sensor) power state, antenna connection state and antenna power. Only produced
 * at 1 Hz; higher rates have no effect. */
typedef struct {
    mipc_gnss_receiver_state_t receiver_state;           /* Receiver power state (GX5-45: sensor state). */
    mipc_gnss_antenna_state_t antenna_state;             /* Antenna connection state. */
    mipc_gnss_antenna_power_t antenna_power;             /* Antenna power state. */
    mipc_gnss_hardware_status_valid_flags_t valid_flags; /* Which values are valid. */
} mipc_gnss_data_hardware_status_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_DATA_HARDWARE_STATUS_MAX_SIZE 5

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_data_hardware_status_encode(const mipc_gnss_data_hardware_status_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_data_hardware_status_decode(const uint8_t *data, size_t len,
                                                    mipc_gnss_data_hardware_status_t *out,
                                                    mipc_decode_error_t *err);

/* ---- dgnss_info (data): DGNSS information */
#define MIPC_GNSS_DATA_DGNSS_INFO_DESCRIPTOR 0x0E

/** DGNSS information. Age of the newest differential correction, base station id and status, and the number
 * of DGNSS channels. */
typedef struct {
    float newest_age;        /* Age of the newest correction (valid flag: latest age). [s] */
    int16_t base_station_id; /* Base station id. */
    mipc_gnss_dgnss_base_station_status_t base_station_status; /* Base station status (UDRE scale factor). */
    uint16_t num_channels;                                     /* Number of DGNSS channels. */
    mipc_gnss_dgnss_info_valid_flags_t valid_flags;            /* Which values are valid. */
} mipc_gnss_data_dgnss_info_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_DATA_DGNSS_INFO_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_data_dgnss_info_encode(const mipc_gnss_data_dgnss_info_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_data_dgnss_info_decode(const uint8_t *data, size_t len,
                                               mipc_gnss_data_dgnss_info_t *out, mipc_decode_error_t *err);

/* ---- dgnss_channel_status (data): DGNSS channel status */
#define MIPC_GNSS_DATA_DGNSS_CHANNEL_STATUS_DESCRIPTOR 0x0F

/** DGNSS channel status. One entry per space vehicle with differential corrections: SV id, correction age,
 * pseudorange and pseudorange-rate corrections. One field per active vehicle. */
typedef struct {
    uint8_t sv_id;                                            /* Space vehicle id number. */
    float age;                                                /* Age of the correction. [s] */
    float pseudorange_correction;                             /* Pseudorange correction. [m] */
    float pseudorange_rate_correction;                        /* Pseudorange rate correction. [m/s] */
    mipc_gnss_dgnss_channel_status_valid_flags_t valid_flags; /* Which values are valid. */
} mipc_gnss_data_dgnss_channel_status_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_DATA_DGNSS_CHANNEL_STATUS_MAX_SIZE 15

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_data_dgnss_channel_status_encode(const mipc_gnss_data_dgnss_channel_status_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_data_dgnss_channel_status_decode(const uint8_t *data, size_t len,
                                                         mipc_gnss_data_dgnss_channel_status_t *out,
                                                         mipc_decode_error_t *err);

/**
 * The fields of one packet of this set, decoded in place by mipc_gnss_data_decode_packet: one member per
 * field the set defines with a single layout (its own, the reserved fields of its kind and the
 * shared data fields); `index` says which members hold a field of the packet, in packet order.
 */
typedef struct {
    mipc_packet_index_t index;
    mipc_gnss_data_llh_position_t gnss_data_llh_position;                 /* 0x03 */
    mipc_gnss_data_ecef_position_t gnss_data_ecef_position;               /* 0x04 */
    mipc_gnss_data_ned_velocity_t gnss_data_ned_velocity;                 /* 0x05 */
    mipc_gnss_data_ecef_velocity_t gnss_data_ecef_velocity;               /* 0x06 */
    mipc_gnss_data_dop_t gnss_data_dop;                                   /* 0x07 */
    mipc_gnss_data_utc_time_t gnss_data_utc_time;                         /* 0x08 */
    mipc_gnss_data_gps_time_t gnss_data_gps_time;                         /* 0x09 */
    mipc_gnss_data_clock_info_t gnss_data_clock_info;                     /* 0x0A */
    mipc_gnss_data_fix_info_t gnss_data_fix_info;                         /* 0x0B */
    mipc_gnss_data_sv_info_t gnss_data_sv_info;                           /* 0x0C */
    mipc_gnss_data_hardware_status_t gnss_data_hardware_status;           /* 0x0D */
    mipc_gnss_data_dgnss_info_t gnss_data_dgnss_info;                     /* 0x0E */
    mipc_gnss_data_dgnss_channel_status_t gnss_data_dgnss_channel_status; /* 0x0F */
    mipc_shared_event_source_t shared_event_source;                       /* 0xD0 (shared) */
    mipc_shared_gps_timestamp_t shared_gps_timestamp;                     /* 0xD3 (shared) */
    mipc_shared_delta_time_t shared_delta_time;                           /* 0xD4 (shared) */
    mipc_shared_reference_timestamp_t shared_reference_timestamp;         /* 0xD5 (shared) */
    mipc_shared_reference_time_delta_t shared_reference_time_delta;       /* 0xD6 (shared) */
    mipc_shared_external_timestamp_t shared_external_timestamp;           /* 0xD7 (shared) */
    mipc_shared_external_time_delta_t shared_external_time_delta;         /* 0xD8 (shared) */
} mipc_gnss_data_packet_t;

/**
 * The straight-line decoder of a packet of this set (issue 38): walks the fields of the payload
 * (len bytes at payload) with a switch on the descriptor and decodes each field's layout into its
 * member of *out, giving the value mipc_decode_field gives; no general value, no indirect call. Every
 * other entry goes to other (may be NULL: they are dropped) with ctx, in packet order with the
 * fields: a descriptor without a member (undefined, or a field with per-device variants), a field
 * that does not decode (its member is then unspecified), a second field with a descriptor already
 * decoded, trailing bytes. Returns out->index.count, the number of fields decoded into members.
 */
size_t mipc_gnss_data_decode_packet(const uint8_t *payload, size_t len, mipc_gnss_data_packet_t *out,
                                    mipc_field_entry_fn other, void *ctx);

/* Private (mipc_decode_packet_cached): the members of mipc_gnss_data_packet_t: descriptor, offset,
 * loader. */
extern const mipc_layout_member_t mipc_gnss_data_layout_members_[20];

#ifdef __cplusplus
}
#endif

#endif
