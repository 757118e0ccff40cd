/* Aiding Command Set (descriptor set 0x13): one struct per field layout, with its
 * encoder and decoder. Generated from the spec: do not edit. */
#ifndef MIPC_SETS_AIDING_H
#define MIPC_SETS_AIDING_H

#include "mipcodec/types.h"

#ifdef __cplusplus
extern "C" {
#endif

#define MIPC_AIDING_SET 0x13

/* ---- frame_config (command): Frame configuration */
#define MIPC_AIDING_FRAME_CONFIG_DESCRIPTOR 0x01

/** Frame configuration. Define an aiding frame: the translation (lever arm) and rotation of an external
 * aiding sensor relative to the vehicle frame. Aiding measurements name the frame they were taken in with
 * their frame_id. Optionally the filter tracks errors in the frame definition. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    uint8_t frame_id;                  /* Reference frame number (at most 4). */
    bool has_format;                   /* format is present */
    mipc_aiding_frame_format_t format; /* Format of the rotation (also selects the format a read reports). */
    bool has_tracking_enabled;         /* tracking_enabled is present */
    bool tracking_enabled; /* If true, the Kalman filter tracks errors in this frame definition. */
    bool has_translation;  /* translation is present */
    float translation[3];  /* Translation X, Y, Z of the frame in the vehicle frame. [m] */
    bool has_rotation;     /* rotation is present */
    mipc_aiding_frame_rotation_t rotation; /* Rotation of the frame, in the given format. */
} mipc_aiding_frame_config_t;

/* Largest encoded data (after the field header). */
#define MIPC_AIDING_FRAME_CONFIG_MAX_SIZE 32

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_aiding_frame_config_encode(const mipc_aiding_frame_config_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_aiding_frame_config_decode(const uint8_t *data, size_t len,
                                              mipc_aiding_frame_config_t *out, mipc_decode_error_t *err);

/* ---- frame_config_response (response): Frame configuration (response) */
#define MIPC_AIDING_FRAME_CONFIG_RESPONSE_DESCRIPTOR 0x81

/** Frame configuration (response). Current definition of an aiding frame. */
typedef struct {
    uint8_t frame_id;                      /* Reference frame number. */
    mipc_aiding_frame_format_t format;     /* Format of the rotation. */
    bool tracking_enabled;                 /* Whether the Kalman filter tracks errors in this frame. */
    float translation[3];                  /* Translation X, Y, Z. [m] */
    mipc_aiding_frame_rotation_t rotation; /* Rotation, in the given format. */
} mipc_aiding_frame_config_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_AIDING_FRAME_CONFIG_RESPONSE_MAX_SIZE 31

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_aiding_frame_config_response_encode(const mipc_aiding_frame_config_response_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_aiding_frame_config_response_decode(const uint8_t *data, size_t len,
                                                       mipc_aiding_frame_config_response_t *out,
                                                       mipc_decode_error_t *err);

/* ---- echo_control (command): Echo control */
#define MIPC_AIDING_ECHO_CONTROL_DESCRIPTOR 0x1F

/** Echo control. Control how the device answers aiding measurement commands: no ack, normal ack/nack, or
 * echoing the aiding data back (useful for logging and post-processing). */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_mode;                     /* mode is present */
    mipc_aiding_echo_mode_t mode;      /* How aiding commands are answered. */
} mipc_aiding_echo_control_t;

/* Largest encoded data (after the field header). */
#define MIPC_AIDING_ECHO_CONTROL_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_aiding_echo_control_encode(const mipc_aiding_echo_control_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_aiding_echo_control_decode(const uint8_t *data, size_t len,
                                              mipc_aiding_echo_control_t *out, mipc_decode_error_t *err);

/* ---- echo_control_response (response): Echo control (response) */
#define MIPC_AIDING_ECHO_CONTROL_RESPONSE_DESCRIPTOR 0x9F

/** Echo control (response). Current aiding echo mode. */
typedef struct {
    mipc_aiding_echo_mode_t mode; /* How aiding commands are answered. */
} mipc_aiding_echo_control_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_AIDING_ECHO_CONTROL_RESPONSE_MAX_SIZE 1

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_aiding_echo_control_response_encode(const mipc_aiding_echo_control_response_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_aiding_echo_control_response_decode(const uint8_t *data, size_t len,
                                                       mipc_aiding_echo_control_response_t *out,
                                                       mipc_decode_error_t *err);

/* ---- ecef_position (command): ECEF position */
#define MIPC_AIDING_ECEF_POSITION_DESCRIPTOR 0x21

/** ECEF position. Position aiding measurement in the WGS84 Earth-centred, Earth-fixed frame. */
typedef struct {
    mipc_aiding_time_t time; /* Timestamp of the measurement. */
    uint8_t frame_id;        /* Aiding frame the measurement was taken in (see frame_config). */
    double position[3];      /* ECEF position X, Y, Z. [m] */
    float uncertainty[3];    /* ECEF position 1-sigma uncertainty; not 0 for a valid axis. [m] */
    mipc_aiding_vector_valid_flags_t valid_flags; /* Valid axes; invalid axes are ignored. */
} mipc_aiding_ecef_position_t;

/* Largest encoded data (after the field header). */
#define MIPC_AIDING_ECEF_POSITION_MAX_SIZE 49

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_aiding_ecef_position_encode(const mipc_aiding_ecef_position_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_aiding_ecef_position_decode(const uint8_t *data, size_t len,
                                               mipc_aiding_ecef_position_t *out, mipc_decode_error_t *err);

/* ---- llh_position (command): LLH position */
#define MIPC_AIDING_LLH_POSITION_DESCRIPTOR 0x22

/** LLH position. Geodetic position aiding measurement: WGS84 latitude, longitude and height above the
 * ellipsoid, with uncertainty in north, east, down components. With latitude and longitude marked invalid it
 * aids height only. */
typedef struct {
    mipc_aiding_time_t time; /* Timestamp of the measurement. */
    uint8_t frame_id;        /* Aiding frame the measurement was taken in. */
    double latitude;         /* WGS84 latitude. [deg] */
    double longitude;        /* WGS84 longitude. [deg] */
    double height;           /* Height above the WGS84 ellipsoid. [m] */
    float uncertainty[3]; /* 1-sigma uncertainty in north, east, down (the table prints no unit); not 0 for a
                             valid component. [m] */
    mipc_aiding_llh_valid_flags_t valid_flags; /* Valid components; invalid ones are ignored. */
} mipc_aiding_llh_position_t;

/* Largest encoded data (after the field header). */
#define MIPC_AIDING_LLH_POSITION_MAX_SIZE 49

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_aiding_llh_position_encode(const mipc_aiding_llh_position_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_aiding_llh_position_decode(const uint8_t *data, size_t len,
                                              mipc_aiding_llh_position_t *out, mipc_decode_error_t *err);

/* ---- height_above_ellipsoid (command): Height above ellipsoid */
#define MIPC_AIDING_HEIGHT_ABOVE_ELLIPSOID_DESCRIPTOR 0x23

/** Height above ellipsoid. Height aiding measurement above the WGS84 ellipsoid. */
typedef struct {
    mipc_aiding_time_t time; /* Timestamp of the measurement. */
    uint8_t frame_id;        /* Aiding frame the measurement was taken in. */
    float height;            /* Height above the ellipsoid. [m] */
    float uncertainty;       /* 1-sigma uncertainty. [m] */
    uint16_t valid_flags;    /* Valid flags; 0 means the measurement is ignored (no bits are defined). */
} mipc_aiding_height_above_ellipsoid_t;

/* Largest encoded data (after the field header). */
#define MIPC_AIDING_HEIGHT_ABOVE_ELLIPSOID_MAX_SIZE 21

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_aiding_height_above_ellipsoid_encode(const mipc_aiding_height_above_ellipsoid_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_aiding_height_above_ellipsoid_decode(const uint8_t *data, size_t len,
                                                        mipc_aiding_height_above_ellipsoid_t *out,
                                                        mipc_decode_error_t *err);

/* ---- ecef_velocity (command): ECEF velocity */
#define MIPC_AIDING_ECEF_VELOCITY_DESCRIPTOR 0x28

/** ECEF velocity. Velocity aiding measurement in the WGS84 ECEF frame. Not for body-fixed sensors such as
 * radar (use body frame velocity). */
typedef struct {
    mipc_aiding_time_t time; /* Timestamp of the measurement. */
    uint8_t frame_id;        /* Aiding frame the measurement was taken in. */
    float velocity[3];       /* ECEF velocity X, Y, Z. [m/s] */
    float uncertainty[3];    /* ECEF velocity 1-sigma uncertainty; not 0 for a valid axis. [m/s] */
    mipc_aiding_vector_valid_flags_t valid_flags; /* Valid axes; invalid axes are ignored. */
} mipc_aiding_ecef_velocity_t;

/* Largest encoded data (after the field header). */
#define MIPC_AIDING_ECEF_VELOCITY_MAX_SIZE 37

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_aiding_ecef_velocity_encode(const mipc_aiding_ecef_velocity_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_aiding_ecef_velocity_decode(const uint8_t *data, size_t len,
                                               mipc_aiding_ecef_velocity_t *out, mipc_decode_error_t *err);

/* ---- ned_velocity (command): NED velocity */
#define MIPC_AIDING_NED_VELOCITY_DESCRIPTOR 0x29

/** NED velocity. Velocity aiding measurement in the local north-east-down frame. Not for body-fixed sensors
 * (use body frame velocity). */
typedef struct {
    mipc_aiding_time_t time; /* Timestamp of the measurement. */
    uint8_t frame_id;        /* Aiding frame the measurement was taken in. */
    float velocity[3];       /* NED velocity (north, east, down). [m/s] */
    float uncertainty[3];    /* NED velocity 1-sigma uncertainty; not 0 for a valid axis. [m/s] */
    mipc_aiding_vector_valid_flags_t valid_flags; /* Valid components (x = north, y = east, z = down). */
} mipc_aiding_ned_velocity_t;

/* Largest encoded data (after the field header). */
#define MIPC_AIDING_NED_VELOCITY_MAX_SIZE 37

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_aiding_ned_velocity_encode(const mipc_aiding_ned_velocity_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_aiding_ned_velocity_decode(const uint8_t *data, size_t len,
                                              mipc_aiding_ned_velocity_t *out, mipc_decode_error_t *err);

/* ---- body_frame_velocity (command): Body frame velocity */
#define MIPC_AIDING_BODY_FRAME_VELOCITY_DESCRIPTOR 0x2A

/** Body frame velocity. Velocity aiding measurement in a frame fixed to the vehicle (the aiding frame given
 * by frame_id), e.g. pre-processed radar, lidar, wheel-speed or air-speed velocity. Up to four such sensors.
 */
typedef struct {
    mipc_aiding_time_t time; /* Timestamp of the measurement. */
    uint8_t frame_id;        /* Aiding frame the measurement was taken in (must be > 0). */
    float velocity[3];       /* Velocity X, Y, Z in the aiding frame. [m/s] */
    float uncertainty[3];    /* 1-sigma uncertainty; not 0 (or negative) for a valid axis. [m/s] */
    mipc_aiding_vector_valid_flags_t valid_flags; /* Valid axes; invalid axes are ignored. */
} mipc_aiding_body_frame_velocity_t;

/* Largest encoded data (after the field header). */
#define MIPC_AIDING_BODY_FRAME_VELOCITY_MAX_SIZE 37

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_aiding_body_frame_velocity_encode(const mipc_aiding_body_frame_velocity_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_aiding_body_frame_velocity_decode(const uint8_t *data, size_t len,
                                                     mipc_aiding_body_frame_velocity_t *out,
                                                     mipc_decode_error_t *err);

/* ---- true_heading (command): True heading */
#define MIPC_AIDING_TRUE_HEADING_DESCRIPTOR 0x31

/** True heading. Heading aiding measurement relative to true north (e.g. dual-antenna GNSS compass). */
typedef struct {
    mipc_aiding_time_t time; /* Timestamp of the measurement. */
    uint8_t frame_id;        /* Aiding frame the measurement was taken in. */
    float heading;           /* True heading, within +/- pi. [rad] */
    float uncertainty;       /* 1-sigma uncertainty; not 0 unless the valid flags are 0. [rad] */
    uint16_t valid_flags;    /* Valid flags; 0 means the measurement is ignored (no bits are defined). */
} mipc_aiding_true_heading_t;

/* Largest encoded data (after the field header). */
#define MIPC_AIDING_TRUE_HEADING_MAX_SIZE 21

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_aiding_true_heading_encode(const mipc_aiding_true_heading_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_aiding_true_heading_decode(const uint8_t *data, size_t len,
                                              mipc_aiding_true_heading_t *out, mipc_decode_error_t *err);

/* ---- magnetic_field (command): Magnetic field */
#define MIPC_AIDING_MAGNETIC_FIELD_DESCRIPTOR 0x32

/** Magnetic field. Magnetic field aiding measurement from a calibrated external magnetometer, in the aiding
 * frame given by frame_id. */
typedef struct {
    mipc_aiding_time_t time; /* Timestamp of the measurement. */
    uint8_t frame_id;        /* Aiding frame the measurement was taken in (must be > 0). */
    float magnetic_field[3]; /* Magnetic field X, Y, Z. [gauss] */
    float uncertainty[3];    /* 1-sigma uncertainty; not 0 for a valid axis. [gauss] */
    mipc_aiding_vector_valid_flags_t valid_flags; /* Valid axes; invalid axes are ignored. */
} mipc_aiding_magnetic_field_t;

/* Largest encoded data (after the field header). */
#define MIPC_AIDING_MAGNETIC_FIELD_MAX_SIZE 37

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_aiding_magnetic_field_encode(const mipc_aiding_magnetic_field_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_aiding_magnetic_field_decode(const uint8_t *data, size_t len,
                                                mipc_aiding_magnetic_field_t *out, mipc_decode_error_t *err);

/* ---- pressure (command): Pressure */
#define MIPC_AIDING_PRESSURE_DESCRIPTOR 0x33

/** Pressure. Static air pressure aiding measurement, to constrain altitude drift during GNSS outages. */
typedef struct {
    mipc_aiding_time_t time; /* Timestamp of the measurement. */
    uint8_t frame_id;        /* Aiding frame the measurement was taken in. */
    float pressure;          /* Static pressure. [mbar] */
    float uncertainty;       /* 1-sigma uncertainty; not 0 unless the valid flags are 0. [mbar] */
    uint16_t valid_flags;    /* Valid flags; 0 means the measurement is ignored (no bits are defined). */
} mipc_aiding_pressure_t;

/* Largest encoded data (after the field header). */
#define MIPC_AIDING_PRESSURE_MAX_SIZE 21

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_aiding_pressure_encode(const mipc_aiding_pressure_t *value, uint8_t *buf, size_t cap,
                                          size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_aiding_pressure_decode(const uint8_t *data, size_t len, mipc_aiding_pressure_t *out,
                                          mipc_decode_error_t *err);

#ifdef __cplusplus
}
#endif

#endif
