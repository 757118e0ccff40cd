/* Filter Command Set (descriptor set 0x0D): one struct per field layout, with its
 * encoder and decoder. Generated from the spec: do not edit. */
#ifndef MIPC_SETS_FILTER_H
#define MIPC_SETS_FILTER_H

#include "mipcodec/types.h"

#ifdef __cplusplus
extern "C" {
#endif

#define MIPC_FILTER_SET 0x0D

/* ---- reset_filter (command): Reset filter */
#define MIPC_FILTER_RESET_FILTER_DESCRIPTOR 0x01

/** Reset filter. Put the filter back into its initialisation state. With auto-initialisation disabled, an
 * initial attitude or heading must then be given before it runs again. */
typedef struct {
    uint8_t unused_; /* no parameters */
} mipc_filter_reset_filter_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_RESET_FILTER_MAX_SIZE 0

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_reset_filter_encode(const mipc_filter_reset_filter_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_reset_filter_decode(const uint8_t *data, size_t len,
                                              mipc_filter_reset_filter_t *out, mipc_decode_error_t *err);

/* ---- set_initial_attitude (command): Set initial attitude */
#define MIPC_FILTER_SET_INITIAL_ATTITUDE_DESCRIPTOR 0x02

/** Set initial attitude. Initialise the filter attitude from Euler angles of the sensor body frame relative
 * to the local NED frame. Only accepted in the INIT state. */
typedef struct {
    float roll;    /* Roll angle, in [-pi, pi]. [rad] */
    float pitch;   /* Pitch angle, in [-pi/2, pi/2]. [rad] */
    float heading; /* Heading (yaw) angle, in [-pi, pi]. [rad] */
} mipc_filter_set_initial_attitude_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_SET_INITIAL_ATTITUDE_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_set_initial_attitude_encode(const mipc_filter_set_initial_attitude_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_set_initial_attitude_decode(const uint8_t *data, size_t len,
                                                      mipc_filter_set_initial_attitude_t *out,
                                                      mipc_decode_error_t *err);

/* ---- set_initial_heading (command): Set initial heading */
#define MIPC_FILTER_SET_INITIAL_HEADING_DESCRIPTOR 0x03

/** Set initial heading. Initialise the filter heading; roll and pitch come from the accelerometers. GX5-45:
 * only accepted in the INIT state. CV7: the heading estimate is reset to this value, unless magnetometer
 * aiding is enabled, in which case the magnetic heading is used instead. */
typedef struct {
    float heading; /* Initial heading, in [-pi, pi]. [rad] */
} mipc_filter_set_initial_heading_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_SET_INITIAL_HEADING_MAX_SIZE 4

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_set_initial_heading_encode(const mipc_filter_set_initial_heading_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_set_initial_heading_decode(const uint8_t *data, size_t len,
                                                     mipc_filter_set_initial_heading_t *out,
                                                     mipc_decode_error_t *err);

/* ---- run_filter (command): Run navigation filter */
#define MIPC_FILTER_RUN_FILTER_DESCRIPTOR 0x05

/** Run navigation filter. Start the filter by hand when the initialisation configuration asks it to wait for
 * a run command; until then it stays in initialisation mode. */
typedef struct {
    uint8_t unused_; /* no parameters */
} mipc_filter_run_filter_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_RUN_FILTER_MAX_SIZE 0

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_run_filter_encode(const mipc_filter_run_filter_t *value, uint8_t *buf, size_t cap,
                                            size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_run_filter_decode(const uint8_t *data, size_t len, mipc_filter_run_filter_t *out,
                                            mipc_decode_error_t *err);

/* ---- vehicle_dynamics_mode (command): Vehicle dynamics mode */
#define MIPC_FILTER_VEHICLE_DYNAMICS_MODE_DESCRIPTOR 0x10

/** Vehicle dynamics mode. Set, read, save, load or reset the vehicle dynamics mode of the filter. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_mode;                     /* mode is present */
    mipc_vehicle_dynamics_mode_t mode; /* New dynamics mode. */
} mipc_filter_vehicle_dynamics_mode_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_VEHICLE_DYNAMICS_MODE_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_vehicle_dynamics_mode_encode(const mipc_filter_vehicle_dynamics_mode_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_vehicle_dynamics_mode_decode(const uint8_t *data, size_t len,
                                                       mipc_filter_vehicle_dynamics_mode_t *out,
                                                       mipc_decode_error_t *err);

/* ---- vehicle_dynamics_mode_response (response): Vehicle dynamics mode (response) */
#define MIPC_FILTER_VEHICLE_DYNAMICS_MODE_RESPONSE_DESCRIPTOR 0x80

/** Vehicle dynamics mode (response). Current vehicle dynamics mode (reply to read). */
typedef struct {
    mipc_vehicle_dynamics_mode_t mode; /* Current dynamics mode. */
} mipc_filter_vehicle_dynamics_mode_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_VEHICLE_DYNAMICS_MODE_RESPONSE_MAX_SIZE 1

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_vehicle_dynamics_mode_response_encode(const mipc_filter_vehicle_dynamics_mode_response_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_vehicle_dynamics_mode_response_decode(const uint8_t *data, size_t len,
                                                  mipc_filter_vehicle_dynamics_mode_response_t *out,
                                                  mipc_decode_error_t *err);

/* ---- sensor_to_vehicle_transform (command): Sensor to vehicle frame transformation */
#define MIPC_FILTER_SENSOR_TO_VEHICLE_TRANSFORM_DESCRIPTOR 0x11

/** Sensor to vehicle frame transformation. Euler angles (roll, pitch, yaw) of the rotation from the sensor
 * body frame to the vehicle frame. Applies to the scaled IMU vectors, delta theta/velocity and the filter's
 * orientation, linear acceleration, angular rate and gravity outputs. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_roll;                     /* roll is present */
    float roll;                        /* Roll angle of the sensor-to-vehicle rotation. [rad] */
    bool has_pitch;                    /* pitch is present */
    float pitch;                       /* Pitch angle of the sensor-to-vehicle rotation. [rad] */
    bool has_yaw;                      /* yaw is present */
    float yaw;                         /* Yaw angle of the sensor-to-vehicle rotation. [rad] */
} mipc_filter_sensor_to_vehicle_transform_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_SENSOR_TO_VEHICLE_TRANSFORM_MAX_SIZE 13

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_sensor_to_vehicle_transform_encode(const mipc_filter_sensor_to_vehicle_transform_t *value,
                                               uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_sensor_to_vehicle_transform_decode(const uint8_t *data, size_t len,
                                                             mipc_filter_sensor_to_vehicle_transform_t *out,
                                                             mipc_decode_error_t *err);

/* ---- sensor_to_vehicle_transform_response (response): Sensor to vehicle frame transformation (response) */
#define MIPC_FILTER_SENSOR_TO_VEHICLE_TRANSFORM_RESPONSE_DESCRIPTOR 0x81

/** Sensor to vehicle frame transformation (response). Current sensor-to-vehicle Euler angles (reply to read).
 */
typedef struct {
    float roll;  /* Roll angle. [rad] */
    float pitch; /* Pitch angle. [rad] */
    float yaw;   /* Yaw angle. [rad] */
} mipc_filter_sensor_to_vehicle_transform_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_SENSOR_TO_VEHICLE_TRANSFORM_RESPONSE_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_sensor_to_vehicle_transform_response_encode(
    const mipc_filter_sensor_to_vehicle_transform_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_sensor_to_vehicle_transform_response_decode(
    const uint8_t *data, size_t len, mipc_filter_sensor_to_vehicle_transform_response_t *out,
    mipc_decode_error_t *err);

/* ---- sensor_to_vehicle_offset (command): Sensor to vehicle frame offset */
#define MIPC_FILTER_SENSOR_TO_VEHICLE_OFFSET_DESCRIPTOR 0x12

/** Sensor to vehicle frame offset. Offset from the sensor to the vehicle reference point, in the sensor
 * frame, added to the estimated LLH position. Not a lever arm: no inertial compensation. Magnitude at most 10
 * m. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_offset;                   /* offset is present */
    float offset[3];                   /* (x, y, z) offset in the sensor body frame. [m] */
} mipc_filter_sensor_to_vehicle_offset_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_SENSOR_TO_VEHICLE_OFFSET_MAX_SIZE 13

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_sensor_to_vehicle_offset_encode(const mipc_filter_sensor_to_vehicle_offset_t *value,
                                                          uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_sensor_to_vehicle_offset_decode(const uint8_t *data, size_t len,
                                                          mipc_filter_sensor_to_vehicle_offset_t *out,
                                                          mipc_decode_error_t *err);

/* ---- sensor_to_vehicle_offset_response (response): Sensor to vehicle frame offset (response) */
#define MIPC_FILTER_SENSOR_TO_VEHICLE_OFFSET_RESPONSE_DESCRIPTOR 0x82

/** Sensor to vehicle frame offset (response). Current sensor-to-vehicle offset (reply to read). */
typedef struct {
    float offset[3]; /* (x, y, z) offset in the sensor body frame. [m] */
} mipc_filter_sensor_to_vehicle_offset_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_SENSOR_TO_VEHICLE_OFFSET_RESPONSE_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_sensor_to_vehicle_offset_response_encode(
    const mipc_filter_sensor_to_vehicle_offset_response_t *value, uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_sensor_to_vehicle_offset_response_decode(const uint8_t *data, size_t len,
                                                     mipc_filter_sensor_to_vehicle_offset_response_t *out,
                                                     mipc_decode_error_t *err);

/* ---- antenna_offset (command): GNSS antenna offset */
#define MIPC_FILTER_ANTENNA_OFFSET_DESCRIPTOR 0x13

/** GNSS antenna offset. Offset from the sensor origin to the GNSS antenna RF (phase) centre; magnitude at
 * most 10 m. GX5-45 (5-series): expressed in the sensor frame. CV7 (7-series): expressed in the vehicle
 * frame; also used for NMEA input over GPIO. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_offset;                   /* offset is present */
    float offset[3]; /* (x, y, z) antenna offset (sensor frame on GX5-45, vehicle frame on CV7). [m] */
} mipc_filter_antenna_offset_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_ANTENNA_OFFSET_MAX_SIZE 13

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_antenna_offset_encode(const mipc_filter_antenna_offset_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_antenna_offset_decode(const uint8_t *data, size_t len,
                                                mipc_filter_antenna_offset_t *out, mipc_decode_error_t *err);

/* ---- antenna_offset_response (response): GNSS antenna offset (response) */
#define MIPC_FILTER_ANTENNA_OFFSET_RESPONSE_DESCRIPTOR 0x83

/** GNSS antenna offset (response). Current antenna offset (reply to read). */
typedef struct {
    float offset[3]; /* (x, y, z) antenna offset. [m] */
} mipc_filter_antenna_offset_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_ANTENNA_OFFSET_RESPONSE_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_antenna_offset_response_encode(const mipc_filter_antenna_offset_response_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_antenna_offset_response_decode(const uint8_t *data, size_t len,
                                                         mipc_filter_antenna_offset_response_t *out,
                                                         mipc_decode_error_t *err);

/* ---- estimation_control (command): Estimation control flags */
#define MIPC_FILTER_ESTIMATION_CONTROL_DESCRIPTOR 0x14

/** Estimation control flags. Select which optional parameters the Kalman filter estimates. */
typedef struct {
    mipc_function_selector_t function;     /* function selector (write, read, save, load, default) */
    bool has_flags;                        /* flags is present */
    mipc_estimation_control_flags_t flags; /* States to estimate. */
} mipc_filter_estimation_control_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_ESTIMATION_CONTROL_MAX_SIZE 3

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_estimation_control_encode(const mipc_filter_estimation_control_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_estimation_control_decode(const uint8_t *data, size_t len,
                                                    mipc_filter_estimation_control_t *out,
                                                    mipc_decode_error_t *err);

/* ---- estimation_control_response (response): Estimation control flags (response) */
#define MIPC_FILTER_ESTIMATION_CONTROL_RESPONSE_DESCRIPTOR 0x84

/** Estimation control flags (response). Current estimation control flags (reply to read). */
typedef struct {
    mipc_estimation_control_flags_t flags; /* States being estimated. */
} mipc_filter_estimation_control_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_ESTIMATION_CONTROL_RESPONSE_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_estimation_control_response_encode(const mipc_filter_estimation_control_response_t *value,
                                               uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_estimation_control_response_decode(const uint8_t *data, size_t len,
                                                             mipc_filter_estimation_control_response_t *out,
                                                             mipc_decode_error_t *err);

/* ---- gnss_source_control (command): GNSS source control */
#define MIPC_FILTER_GNSS_SOURCE_CONTROL_DESCRIPTOR 0x15

/** GNSS source control. Choose the source of GNSS updates to the filter. Changing it while running may put
 * the filter back in its init state until data from the new source arrives. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_source;                   /* source is present */
    mipc_filter_gnss_source_t source;  /* GNSS source. */
} mipc_filter_gnss_source_control_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_GNSS_SOURCE_CONTROL_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_gnss_source_control_encode(const mipc_filter_gnss_source_control_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_gnss_source_control_decode(const uint8_t *data, size_t len,
                                                     mipc_filter_gnss_source_control_t *out,
                                                     mipc_decode_error_t *err);

/* ---- gnss_source_control_response (response): GNSS source control (response) */
#define MIPC_FILTER_GNSS_SOURCE_CONTROL_RESPONSE_DESCRIPTOR 0x86

/** GNSS source control (response). Current GNSS source (reply to read). */
typedef struct {
    mipc_filter_gnss_source_t source; /* GNSS source. */
} mipc_filter_gnss_source_control_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_GNSS_SOURCE_CONTROL_RESPONSE_MAX_SIZE 1

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_gnss_source_control_response_encode(const mipc_filter_gnss_source_control_response_t *value,
                                                uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_gnss_source_control_response_decode(const uint8_t *data, size_t len,
                                                              mipc_filter_gnss_source_control_response_t *out,
                                                              mipc_decode_error_t *err);

/* ---- external_gnss_update (command): External GNSS update */
#define MIPC_FILTER_EXTERNAL_GNSS_UPDATE_DESCRIPTOR 0x16

/** External GNSS update. Give the filter one GNSS measurement from an external receiver. Only used (otherwise
 * ignored or NACKed) when the GNSS source is external; at most 20 Hz. */
typedef struct {
    double gps_tow;                /* GPS time of week. [s] */
    uint16_t gps_week;             /* GPS week number. [weeks] */
    double latitude;               /* Latitude. [deg] */
    double longitude;              /* Longitude. [deg] */
    double height;                 /* Height above the WGS84 ellipsoid. [m] */
    float velocity[3];             /* (north, east, down) velocity. [m/s] */
    float position_uncertainty[3]; /* (north, east, down) position 1-sigma uncertainty. [m] */
    float velocity_uncertainty[3]; /* (north, east, down) velocity 1-sigma uncertainty. [m/s] */
} mipc_filter_external_gnss_update_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_EXTERNAL_GNSS_UPDATE_MAX_SIZE 70

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_external_gnss_update_encode(const mipc_filter_external_gnss_update_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_external_gnss_update_decode(const uint8_t *data, size_t len,
                                                      mipc_filter_external_gnss_update_t *out,
                                                      mipc_decode_error_t *err);

/* ---- external_heading_update (command): External heading update */
#define MIPC_FILTER_EXTERNAL_HEADING_UPDATE_DESCRIPTOR 0x17

/** External heading update. Give the filter one heading measurement (sensor frame relative to NED) from an
 * external source. Only used when external heading aiding is enabled, otherwise NACKed; uncertainties of 0 or
 * less are NACKed; a true (or magnetic) heading is NACKed when the declination source is invalid (see the
 * manuals for which model refuses which). */
typedef struct {
    float heading;                     /* Heading angle, within +-pi. [rad] */
    float heading_uncertainty;         /* Heading 1-sigma uncertainty; must be greater than 0. [rad] */
    mipc_external_heading_type_t type; /* True or magnetic heading. */
} mipc_filter_external_heading_update_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_EXTERNAL_HEADING_UPDATE_MAX_SIZE 9

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_external_heading_update_encode(const mipc_filter_external_heading_update_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_external_heading_update_decode(const uint8_t *data, size_t len,
                                                         mipc_filter_external_heading_update_t *out,
                                                         mipc_decode_error_t *err);

/* ---- heading_update_control (command): Heading update control */
#define MIPC_FILTER_HEADING_UPDATE_CONTROL_DESCRIPTOR 0x18

/** Heading update control. Select the aiding source(s) of filter heading updates. */
typedef struct {
    mipc_function_selector_t function;   /* function selector (write, read, save, load, default) */
    bool has_source;                     /* source is present */
    mipc_heading_update_source_t source; /* Heading aiding source (the manual's "Enable Flag"). */
} mipc_filter_heading_update_control_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_HEADING_UPDATE_CONTROL_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_heading_update_control_encode(const mipc_filter_heading_update_control_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_heading_update_control_decode(const uint8_t *data, size_t len,
                                                        mipc_filter_heading_update_control_t *out,
                                                        mipc_decode_error_t *err);

/* ---- heading_update_control_response (response): Heading update control (response) */
#define MIPC_FILTER_HEADING_UPDATE_CONTROL_RESPONSE_DESCRIPTOR 0x87

/** Heading update control (response). Current heading update source (reply to read). */
typedef struct {
    mipc_heading_update_source_t source; /* Heading aiding source. */
} mipc_filter_heading_update_control_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_HEADING_UPDATE_CONTROL_RESPONSE_MAX_SIZE 1

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_heading_update_control_response_encode(const mipc_filter_heading_update_control_response_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_heading_update_control_response_decode(const uint8_t *data, size_t len,
                                                   mipc_filter_heading_update_control_response_t *out,
                                                   mipc_decode_error_t *err);

/* ---- auto_init_control (command): Auto-initialization control */
#define MIPC_FILTER_AUTO_INIT_CONTROL_DESCRIPTOR 0x19

/** Auto-initialization control. Enable or disable automatic filter initialisation at startup (needs a valid
 * heading source; otherwise use Set initial heading or Set initial attitude). */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_enable;                   /* enable is present */
    uint8_t enable;                    /* 0 disables, 1 enables auto-initialisation. */
} mipc_filter_auto_init_control_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_AUTO_INIT_CONTROL_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_auto_init_control_encode(const mipc_filter_auto_init_control_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_auto_init_control_decode(const uint8_t *data, size_t len,
                                                   mipc_filter_auto_init_control_t *out,
                                                   mipc_decode_error_t *err);

/* ---- auto_init_control_response (response): Auto-initialization control (response) */
#define MIPC_FILTER_AUTO_INIT_CONTROL_RESPONSE_DESCRIPTOR 0x88

/** Auto-initialization control (response). Current auto-initialisation setting (reply to read). */
typedef struct {
    uint8_t enable; /* 0 disabled, 1 enabled. */
} mipc_filter_auto_init_control_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_AUTO_INIT_CONTROL_RESPONSE_MAX_SIZE 1

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_auto_init_control_response_encode(const mipc_filter_auto_init_control_response_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_auto_init_control_response_decode(const uint8_t *data, size_t len,
                                                            mipc_filter_auto_init_control_response_t *out,
                                                            mipc_decode_error_t *err);

/* ---- accel_noise (command): Accelerometer noise standard deviation */
#define MIPC_FILTER_ACCEL_NOISE_DESCRIPTOR 0x1A

/** Accelerometer noise standard deviation. Expected accelerometer (process) noise, 1-sigma per axis, used to
 * tune the filter. Each value must be greater than 0. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_noise;                    /* noise is present */
    float noise[3];                    /* (x, y, z) accelerometer noise 1-sigma. [m/s^2] */
} mipc_filter_accel_noise_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_ACCEL_NOISE_MAX_SIZE 13

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_accel_noise_encode(const mipc_filter_accel_noise_t *value, uint8_t *buf, size_t cap,
                                             size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_accel_noise_decode(const uint8_t *data, size_t len, mipc_filter_accel_noise_t *out,
                                             mipc_decode_error_t *err);

/* ---- accel_noise_response (response): Accelerometer noise standard deviation (response) */
#define MIPC_FILTER_ACCEL_NOISE_RESPONSE_DESCRIPTOR 0x89

/** Accelerometer noise standard deviation (response). Current accelerometer noise 1-sigma (reply to read). */
typedef struct {
    float noise[3]; /* (x, y, z) accelerometer noise 1-sigma. [m/s^2] */
} mipc_filter_accel_noise_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_ACCEL_NOISE_RESPONSE_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_accel_noise_response_encode(const mipc_filter_accel_noise_response_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_accel_noise_response_decode(const uint8_t *data, size_t len,
                                                      mipc_filter_accel_noise_response_t *out,
                                                      mipc_decode_error_t *err);

/* ---- gyro_noise (command): Gyroscope noise standard deviation */
#define MIPC_FILTER_GYRO_NOISE_DESCRIPTOR 0x1B

/** Gyroscope noise standard deviation. Expected gyro (process) noise, 1-sigma per axis, used to tune the
 * filter. Each value must be greater than 0. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_noise;                    /* noise is present */
    float noise[3];                    /* (x, y, z) gyro noise 1-sigma. [rad/s] */
} mipc_filter_gyro_noise_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_GYRO_NOISE_MAX_SIZE 13

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_gyro_noise_encode(const mipc_filter_gyro_noise_t *value, uint8_t *buf, size_t cap,
                                            size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_gyro_noise_decode(const uint8_t *data, size_t len, mipc_filter_gyro_noise_t *out,
                                            mipc_decode_error_t *err);

/* ---- gyro_noise_response (response): Gyroscope noise standard deviation (response) */
#define MIPC_FILTER_GYRO_NOISE_RESPONSE_DESCRIPTOR 0x8A

/** Gyroscope noise standard deviation (response). Current gyro noise 1-sigma (reply to read). */
typedef struct {
    float noise[3]; /* (x, y, z) gyro noise 1-sigma. [rad/s] */
} mipc_filter_gyro_noise_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_GYRO_NOISE_RESPONSE_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_gyro_noise_response_encode(const mipc_filter_gyro_noise_response_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_gyro_noise_response_decode(const uint8_t *data, size_t len,
                                                     mipc_filter_gyro_noise_response_t *out,
                                                     mipc_decode_error_t *err);

/* ---- accel_bias_model (command): Accelerometer bias model parameters */
#define MIPC_FILTER_ACCEL_BIAS_MODEL_DESCRIPTOR 0x1C

/** Accelerometer bias model parameters. First-order (Gauss-Markov) accelerometer bias model: time constant
 * inverse (beta) and bias noise 1-sigma per axis. Noise values must be greater than 0. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_beta;                     /* beta is present */
    float beta[3];                     /* (x, y, z) accelerometer bias beta. [1/s] */
    bool has_noise;                    /* noise is present */
    float noise[3];                    /* (x, y, z) accelerometer bias noise 1-sigma. [m/s^2] */
} mipc_filter_accel_bias_model_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_ACCEL_BIAS_MODEL_MAX_SIZE 25

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_accel_bias_model_encode(const mipc_filter_accel_bias_model_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_accel_bias_model_decode(const uint8_t *data, size_t len,
                                                  mipc_filter_accel_bias_model_t *out,
                                                  mipc_decode_error_t *err);

/* ---- accel_bias_model_response (response): Accelerometer bias model parameters (response) */
#define MIPC_FILTER_ACCEL_BIAS_MODEL_RESPONSE_DESCRIPTOR 0x8B

/** Accelerometer bias model parameters (response). Current accelerometer bias model (reply to read). */
typedef struct {
    float beta[3];  /* (x, y, z) accelerometer bias beta. [1/s] */
    float noise[3]; /* (x, y, z) accelerometer bias noise 1-sigma. [m/s^2] */
} mipc_filter_accel_bias_model_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_ACCEL_BIAS_MODEL_RESPONSE_MAX_SIZE 24

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_accel_bias_model_response_encode(const mipc_filter_accel_bias_model_response_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_accel_bias_model_response_decode(const uint8_t *data, size_t len,
                                                           mipc_filter_accel_bias_model_response_t *out,
                                                           mipc_decode_error_t *err);

/* ---- gyro_bias_model (command): Gyroscope bias model parameters */
#define MIPC_FILTER_GYRO_BIAS_MODEL_DESCRIPTOR 0x1D

/** Gyroscope bias model parameters. First-order (Gauss-Markov) gyro bias model: time constant inverse (beta)
 * and bias noise 1-sigma per axis. Noise values must be greater than 0. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_beta;                     /* beta is present */
    float beta[3];                     /* (x, y, z) gyro bias beta. [1/s] */
    bool has_noise;                    /* noise is present */
    float noise[3];                    /* (x, y, z) gyro bias noise 1-sigma. [rad/s] */
} mipc_filter_gyro_bias_model_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_GYRO_BIAS_MODEL_MAX_SIZE 25

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_gyro_bias_model_encode(const mipc_filter_gyro_bias_model_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_gyro_bias_model_decode(const uint8_t *data, size_t len,
                                                 mipc_filter_gyro_bias_model_t *out,
                                                 mipc_decode_error_t *err);

/* ---- gyro_bias_model_response (response): Gyroscope bias model parameters (response) */
#define MIPC_FILTER_GYRO_BIAS_MODEL_RESPONSE_DESCRIPTOR 0x8C

/** Gyroscope bias model parameters (response). Current gyro bias model (reply to read). */
typedef struct {
    float beta[3];  /* (x, y, z) gyro bias beta. [1/s] */
    float noise[3]; /* (x, y, z) gyro bias noise 1-sigma. [rad/s] */
} mipc_filter_gyro_bias_model_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_GYRO_BIAS_MODEL_RESPONSE_MAX_SIZE 24

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_gyro_bias_model_response_encode(const mipc_filter_gyro_bias_model_response_t *value,
                                                          uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_gyro_bias_model_response_decode(const uint8_t *data, size_t len,
                                                          mipc_filter_gyro_bias_model_response_t *out,
                                                          mipc_decode_error_t *err);

/* ---- zupt_control (command): Zero velocity update (ZUPT) control */
#define MIPC_FILTER_ZUPT_CONTROL_DESCRIPTOR 0x1E

/** Zero velocity update (ZUPT) control. Enable zero-velocity updates, applied when the GNSS velocity
 * magnitude is at or below the threshold. Negative thresholds are NACKed. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_enable;                   /* enable is present */
    uint8_t enable;                    /* 0 disables, 1 enables ZUPTs. */
    bool has_threshold;                /* threshold is present */
    float threshold;                   /* Velocity magnitude at or below which a ZUPT is applied. [m/s] */
} mipc_filter_zupt_control_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_ZUPT_CONTROL_MAX_SIZE 6

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_zupt_control_encode(const mipc_filter_zupt_control_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_zupt_control_decode(const uint8_t *data, size_t len,
                                              mipc_filter_zupt_control_t *out, mipc_decode_error_t *err);

/* ---- zupt_control_response (response): Zero velocity update control (response) */
#define MIPC_FILTER_ZUPT_CONTROL_RESPONSE_DESCRIPTOR 0x8D

/** Zero velocity update control (response). Current ZUPT setting (reply to read). */
typedef struct {
    uint8_t enable;  /* 0 disabled, 1 enabled. */
    float threshold; /* ZUPT velocity threshold. [m/s] */
} mipc_filter_zupt_control_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_ZUPT_CONTROL_RESPONSE_MAX_SIZE 5

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_zupt_control_response_encode(const mipc_filter_zupt_control_response_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_zupt_control_response_decode(const uint8_t *data, size_t len,
                                                       mipc_filter_zupt_control_response_t *out,
                                                       mipc_decode_error_t *err);

/* ---- external_heading_update_with_time (command): External heading update with timestamp */
#define MIPC_FILTER_EXTERNAL_HEADING_UPDATE_WITH_TIME_DESCRIPTOR 0x1F

/** External heading update with timestamp. External heading measurement tagged with the GPS time it was
 * taken; more accurate than 0x0D,0x17 under high angular rates. Same acceptance rules as 0x0D,0x17; at most
 * 20 Hz on the GX5-45. */
typedef struct {
    double gps_tow;                    /* GPS time of week of the measurement. [s] */
    uint16_t gps_week;                 /* GPS week number (not modulo 1024). [weeks] */
    float heading;                     /* Heading angle from true north, within +-pi. [rad] */
    float heading_uncertainty;         /* Heading 1-sigma uncertainty; must be greater than 0. [rad] */
    mipc_external_heading_type_t type; /* True or magnetic heading. */
} mipc_filter_external_heading_update_with_time_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_EXTERNAL_HEADING_UPDATE_WITH_TIME_MAX_SIZE 19

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_external_heading_update_with_time_encode(
    const mipc_filter_external_heading_update_with_time_t *value, uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_external_heading_update_with_time_decode(const uint8_t *data, size_t len,
                                                     mipc_filter_external_heading_update_with_time_t *out,
                                                     mipc_decode_error_t *err);

/* ---- zero_angular_rate_update_control (command): Zero angular rate update control */
#define MIPC_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL_DESCRIPTOR 0x20

/** Zero angular rate update control. Control the zero angular rate update: when the magnitude of the angular
 * rate vector is at or below the threshold, the filter applies a zero angular rate update. Negative
 * thresholds are NACK'd. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_enable;                   /* enable is present */
    uint8_t enable;                    /* 0 disables, 1 enables the update. */
    bool has_threshold;                /* threshold is present */
    float threshold; /* Angular rate magnitude at or below which the update is applied. [rad/s] */
} mipc_filter_zero_angular_rate_update_control_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL_MAX_SIZE 6

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_zero_angular_rate_update_control_encode(
    const mipc_filter_zero_angular_rate_update_control_t *value, uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_zero_angular_rate_update_control_decode(const uint8_t *data, size_t len,
                                                    mipc_filter_zero_angular_rate_update_control_t *out,
                                                    mipc_decode_error_t *err);

/* ---- zero_angular_rate_update_control_response (response): Zero angular rate update control (response) */
#define MIPC_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL_RESPONSE_DESCRIPTOR 0x8E

/** Zero angular rate update control (response). Current zero angular rate update settings. */
typedef struct {
    uint8_t enable;  /* 0 disabled, 1 enabled. */
    float threshold; /* Angular rate threshold. [rad/s] */
} mipc_filter_zero_angular_rate_update_control_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL_RESPONSE_MAX_SIZE 5

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_zero_angular_rate_update_control_response_encode(
    const mipc_filter_zero_angular_rate_update_control_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_zero_angular_rate_update_control_response_decode(
    const uint8_t *data, size_t len, mipc_filter_zero_angular_rate_update_control_response_t *out,
    mipc_decode_error_t *err);

/* ---- tare_orientation (command): Tare orientation */
#define MIPC_FILTER_TARE_ORIENTATION_DESCRIPTOR 0x21

/** Tare orientation. Use the current orientation relative to NED as the sensor-to-vehicle transformation for
 * the selected axes. The filter must be initialized with a valid attitude, otherwise the command is NACK'd.
 * Read is not supported. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, save, load, default) */
    bool has_axes;                     /* axes is present */
    mipc_tare_axes_t axes;             /* Axes to tare; 0 resets all axes. */
} mipc_filter_tare_orientation_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_TARE_ORIENTATION_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_tare_orientation_encode(const mipc_filter_tare_orientation_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_tare_orientation_decode(const uint8_t *data, size_t len,
                                                  mipc_filter_tare_orientation_t *out,
                                                  mipc_decode_error_t *err);

/* ---- commanded_zupt (command): Commanded zero velocity update */
#define MIPC_FILTER_COMMANDED_ZUPT_DESCRIPTOR 0x22

/** Commanded zero velocity update. Apply a zero velocity update now (at most 20 Hz). */
typedef struct {
    uint8_t unused_; /* no parameters */
} mipc_filter_commanded_zupt_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_COMMANDED_ZUPT_MAX_SIZE 0

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_commanded_zupt_encode(const mipc_filter_commanded_zupt_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_commanded_zupt_decode(const uint8_t *data, size_t len,
                                                mipc_filter_commanded_zupt_t *out, mipc_decode_error_t *err);

/* ---- commanded_zero_angular_rate_update (command): Commanded zero angular rate update */
#define MIPC_FILTER_COMMANDED_ZERO_ANGULAR_RATE_UPDATE_DESCRIPTOR 0x23

/** Commanded zero angular rate update. Apply a zero angular rate update now (at most 10 Hz). */
typedef struct {
    uint8_t unused_; /* no parameters */
} mipc_filter_commanded_zero_angular_rate_update_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_COMMANDED_ZERO_ANGULAR_RATE_UPDATE_MAX_SIZE 0

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_commanded_zero_angular_rate_update_encode(
    const mipc_filter_commanded_zero_angular_rate_update_t *value, uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_commanded_zero_angular_rate_update_decode(const uint8_t *data, size_t len,
                                                      mipc_filter_commanded_zero_angular_rate_update_t *out,
                                                      mipc_decode_error_t *err);

/* ---- mag_capture_auto_calibration (command): Magnetometer capture auto calibration */
#define MIPC_FILTER_MAG_CAPTURE_AUTO_CALIBRATION_DESCRIPTOR 0x27

/** Magnetometer capture auto calibration. Capture the current auto-calibration, fold it into the fixed hard
 * and soft iron coefficients and reset the auto-calibration. Function save stores the coefficients as startup
 * settings (like saving 0x0C,0x3A and 0x0C,0x3B). */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, save) */
} mipc_filter_mag_capture_auto_calibration_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_MAG_CAPTURE_AUTO_CALIBRATION_MAX_SIZE 1

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_mag_capture_auto_calibration_encode(const mipc_filter_mag_capture_auto_calibration_t *value,
                                                uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_mag_capture_auto_calibration_decode(const uint8_t *data, size_t len,
                                                              mipc_filter_mag_capture_auto_calibration_t *out,
                                                              mipc_decode_error_t *err);

/* ---- gravity_noise_std_dev (command): Gravity noise standard deviation */
#define MIPC_FILTER_GRAVITY_NOISE_STD_DEV_DESCRIPTOR 0x28

/** Gravity noise standard deviation. Expected gravity noise (1-sigma) per axis, used to tune the filter. Each
 * value must be greater than 0. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_noise;                    /* noise is present */
    float noise[3];                    /* Gravity noise 1-sigma (x, y, z). [g] */
} mipc_filter_gravity_noise_std_dev_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_GRAVITY_NOISE_STD_DEV_MAX_SIZE 13

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_gravity_noise_std_dev_encode(const mipc_filter_gravity_noise_std_dev_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_gravity_noise_std_dev_decode(const uint8_t *data, size_t len,
                                                       mipc_filter_gravity_noise_std_dev_t *out,
                                                       mipc_decode_error_t *err);

/* ---- gravity_noise_std_dev_response (response): Gravity noise standard deviation (response) */
#define MIPC_FILTER_GRAVITY_NOISE_STD_DEV_RESPONSE_DESCRIPTOR 0x93

/** Gravity noise standard deviation (response). Current gravity noise 1-sigma values. */
typedef struct {
    float noise[3]; /* Gravity noise 1-sigma (x, y, z). [g] */
} mipc_filter_gravity_noise_std_dev_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_GRAVITY_NOISE_STD_DEV_RESPONSE_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_gravity_noise_std_dev_response_encode(const mipc_filter_gravity_noise_std_dev_response_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_gravity_noise_std_dev_response_decode(const uint8_t *data, size_t len,
                                                  mipc_filter_gravity_noise_std_dev_response_t *out,
                                                  mipc_decode_error_t *err);

/* ---- pressure_altitude_noise_std_dev (command): Pressure altitude noise standard deviation */
#define MIPC_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV_DESCRIPTOR 0x29

/** Pressure altitude noise standard deviation. Expected pressure altitude noise (1-sigma). Lower values make
 * the height estimate follow pressure changes faster but more exposed to air pressure fluctuations. Must be
 * greater than 0. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_noise;                    /* noise is present */
    float noise;                       /* Pressure altitude noise 1-sigma. [m] */
} mipc_filter_pressure_altitude_noise_std_dev_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV_MAX_SIZE 5

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_pressure_altitude_noise_std_dev_encode(const mipc_filter_pressure_altitude_noise_std_dev_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_pressure_altitude_noise_std_dev_decode(const uint8_t *data, size_t len,
                                                   mipc_filter_pressure_altitude_noise_std_dev_t *out,
                                                   mipc_decode_error_t *err);

/* ---- pressure_altitude_noise_std_dev_response (response): Pressure altitude noise standard deviation
 * (response) */
#define MIPC_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV_RESPONSE_DESCRIPTOR 0x94

/** Pressure altitude noise standard deviation (response). Current pressure altitude noise 1-sigma. */
typedef struct {
    float noise; /* Pressure altitude noise 1-sigma. [m] */
} mipc_filter_pressure_altitude_noise_std_dev_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV_RESPONSE_MAX_SIZE 4

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_pressure_altitude_noise_std_dev_response_encode(
    const mipc_filter_pressure_altitude_noise_std_dev_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_pressure_altitude_noise_std_dev_response_decode(
    const uint8_t *data, size_t len, mipc_filter_pressure_altitude_noise_std_dev_response_t *out,
    mipc_decode_error_t *err);

/* ---- hard_iron_offset_noise (command): Hard iron offset process noise */
#define MIPC_FILTER_HARD_IRON_OFFSET_NOISE_DESCRIPTOR 0x2B

/** Hard iron offset process noise. Expected hard iron offset process noise (1-sigma) per axis, used to tune
 * the magnetometer auto-calibration states. Each value must be greater than 0. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_noise;                    /* noise is present */
    float noise[3];                    /* Hard iron offset noise 1-sigma (x, y, z). [gauss] */
} mipc_filter_hard_iron_offset_noise_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_HARD_IRON_OFFSET_NOISE_MAX_SIZE 13

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_hard_iron_offset_noise_encode(const mipc_filter_hard_iron_offset_noise_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_hard_iron_offset_noise_decode(const uint8_t *data, size_t len,
                                                        mipc_filter_hard_iron_offset_noise_t *out,
                                                        mipc_decode_error_t *err);

/* ---- hard_iron_offset_noise_response (response): Hard iron offset process noise (response) */
#define MIPC_FILTER_HARD_IRON_OFFSET_NOISE_RESPONSE_DESCRIPTOR 0x96

/** Hard iron offset process noise (response). Current hard iron offset process noise. */
typedef struct {
    float noise[3]; /* Hard iron offset noise 1-sigma (x, y, z). [gauss] */
} mipc_filter_hard_iron_offset_noise_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_HARD_IRON_OFFSET_NOISE_RESPONSE_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_hard_iron_offset_noise_response_encode(const mipc_filter_hard_iron_offset_noise_response_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_hard_iron_offset_noise_response_decode(const uint8_t *data, size_t len,
                                                   mipc_filter_hard_iron_offset_noise_response_t *out,
                                                   mipc_decode_error_t *err);

/* ---- soft_iron_matrix_noise (command): Soft iron matrix process noise */
#define MIPC_FILTER_SOFT_IRON_MATRIX_NOISE_DESCRIPTOR 0x2C

/** Soft iron matrix process noise. Expected soft iron matrix process noise (1-sigma), one value per matrix
 * element, row by row (m11, m12, m13, m21, ... m33). Each value must be greater than 0. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_noise;                    /* noise is present */
    float noise[9];                    /* Soft iron matrix noise 1-sigma, row-major m11..m33. */
} mipc_filter_soft_iron_matrix_noise_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_SOFT_IRON_MATRIX_NOISE_MAX_SIZE 37

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_soft_iron_matrix_noise_encode(const mipc_filter_soft_iron_matrix_noise_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_soft_iron_matrix_noise_decode(const uint8_t *data, size_t len,
                                                        mipc_filter_soft_iron_matrix_noise_t *out,
                                                        mipc_decode_error_t *err);

/* ---- soft_iron_matrix_noise_response (response): Soft iron matrix process noise (response) */
#define MIPC_FILTER_SOFT_IRON_MATRIX_NOISE_RESPONSE_DESCRIPTOR 0x97

/** Soft iron matrix process noise (response). Current soft iron matrix process noise. */
typedef struct {
    float noise[9]; /* Soft iron matrix noise 1-sigma, row-major m11..m33. */
} mipc_filter_soft_iron_matrix_noise_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_SOFT_IRON_MATRIX_NOISE_RESPONSE_MAX_SIZE 36

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_soft_iron_matrix_noise_response_encode(const mipc_filter_soft_iron_matrix_noise_response_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_soft_iron_matrix_noise_response_decode(const uint8_t *data, size_t len,
                                                   mipc_filter_soft_iron_matrix_noise_response_t *out,
                                                   mipc_decode_error_t *err);

/* ---- mag_noise_std_dev (command): Magnetometer noise standard deviation */
#define MIPC_FILTER_MAG_NOISE_STD_DEV_DESCRIPTOR 0x42

/** Magnetometer noise standard deviation. Expected magnetometer noise (1-sigma) per axis, used to tune the
 * filter. Each value must be greater than 0. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_noise;                    /* noise is present */
    float noise[3];                    /* Magnetometer noise 1-sigma (x, y, z). [gauss] */
} mipc_filter_mag_noise_std_dev_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_MAG_NOISE_STD_DEV_MAX_SIZE 13

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_mag_noise_std_dev_encode(const mipc_filter_mag_noise_std_dev_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_mag_noise_std_dev_decode(const uint8_t *data, size_t len,
                                                   mipc_filter_mag_noise_std_dev_t *out,
                                                   mipc_decode_error_t *err);

/* ---- mag_noise_std_dev_response (response): Magnetometer noise standard deviation (response) */
#define MIPC_FILTER_MAG_NOISE_STD_DEV_RESPONSE_DESCRIPTOR 0xB1

/** Magnetometer noise standard deviation (response). Current magnetometer noise 1-sigma values. */
typedef struct {
    float noise[3]; /* Magnetometer noise 1-sigma (x, y, z). [gauss] */
} mipc_filter_mag_noise_std_dev_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_MAG_NOISE_STD_DEV_RESPONSE_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_mag_noise_std_dev_response_encode(const mipc_filter_mag_noise_std_dev_response_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_mag_noise_std_dev_response_decode(const uint8_t *data, size_t len,
                                                            mipc_filter_mag_noise_std_dev_response_t *out,
                                                            mipc_decode_error_t *err);

/* ---- declination_source (command): Declination source */
#define MIPC_FILTER_DECLINATION_SOURCE_DESCRIPTOR 0x43

/** Declination source. Source of the local magnetic declination used to convert between magnetic and true
 * north. With a valid declination the device reports heading relative to true north. */
typedef struct {
    mipc_function_selector_t function;   /* function selector (write, read, save, load, default) */
    bool has_source;                     /* source is present */
    mipc_magnetic_param_source_t source; /* Declination source. */
    bool has_declination;                /* declination is present */
    float declination;                   /* Manual declination angle (used when source is manual). [rad] */
} mipc_filter_declination_source_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DECLINATION_SOURCE_MAX_SIZE 6

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_declination_source_encode(const mipc_filter_declination_source_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_declination_source_decode(const uint8_t *data, size_t len,
                                                    mipc_filter_declination_source_t *out,
                                                    mipc_decode_error_t *err);

/* ---- declination_source_response (response): Declination source (response) */
#define MIPC_FILTER_DECLINATION_SOURCE_RESPONSE_DESCRIPTOR 0xB2

/** Declination source (response). Current declination source and angle. */
typedef struct {
    mipc_magnetic_param_source_t source; /* Declination source. */
    float declination;                   /* Declination angle. [rad] */
} mipc_filter_declination_source_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DECLINATION_SOURCE_RESPONSE_MAX_SIZE 5

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_declination_source_response_encode(const mipc_filter_declination_source_response_t *value,
                                               uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_declination_source_response_decode(const uint8_t *data, size_t len,
                                                             mipc_filter_declination_source_response_t *out,
                                                             mipc_decode_error_t *err);

/* ---- gravity_magnitude_adaptive_measurement (command): Gravity magnitude error adaptive measurement */
#define MIPC_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT_DESCRIPTOR 0x44

/** Gravity magnitude error adaptive measurement. Configure the gravity (accelerometer) magnitude error
 * adaptive measurement, which rejects or de-weights gravity-vector aiding while the measured acceleration
 * magnitude is off. The filter and limit parameters are used only in fixed mode and may be left out: with
 * only the function and mode, the other values keep their previous settings. */
typedef struct {
    mipc_function_selector_t function;     /* function selector (write, read, save, load, default) */
    bool has_mode;                         /* mode is present */
    mipc_adaptive_measurement_mode_t mode; /* Disabled, fixed or auto-adaptive. */
    bool has_frequency;                    /* frequency is present */
    float frequency;                       /* Low-pass filter cutoff frequency. [Hz] */
    bool has_low_limit;                    /* low_limit is present */
    float low_limit;                       /* Low limit. [m/s^2] */
    bool has_high_limit;                   /* high_limit is present */
    float high_limit;                      /* High limit. [m/s^2] */
    bool has_low_limit_uncertainty;        /* low_limit_uncertainty is present */
    float low_limit_uncertainty;           /* Low limit uncertainty, 1-sigma. [m/s^2] */
    bool has_high_limit_uncertainty;       /* high_limit_uncertainty is present */
    float high_limit_uncertainty;          /* High limit uncertainty, 1-sigma. [m/s^2] */
    bool has_minimum_uncertainty;          /* minimum_uncertainty is present */
    float minimum_uncertainty;             /* Minimum uncertainty, 1-sigma. [m/s^2] */
} mipc_filter_gravity_magnitude_adaptive_measurement_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT_MAX_SIZE 26

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_gravity_magnitude_adaptive_measurement_encode(
    const mipc_filter_gravity_magnitude_adaptive_measurement_t *value, uint8_t *buf, size_t cap,
    size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_gravity_magnitude_adaptive_measurement_decode(
    const uint8_t *data, size_t len, mipc_filter_gravity_magnitude_adaptive_measurement_t *out,
    mipc_decode_error_t *err);

/* ---- gravity_magnitude_adaptive_measurement_response (response): Gravity magnitude error adaptive
 * measurement (response) */
#define MIPC_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT_RESPONSE_DESCRIPTOR 0xB3

/** Gravity magnitude error adaptive measurement (response). Current gravity magnitude adaptive measurement
 * settings. */
typedef struct {
    mipc_adaptive_measurement_mode_t mode; /* Disabled, fixed or auto-adaptive. */
    float frequency;                       /* Low-pass filter cutoff frequency. [Hz] */
    float low_limit;                       /* Low limit. [m/s^2] */
    float high_limit;                      /* High limit. [m/s^2] */
    float low_limit_uncertainty;           /* Low limit uncertainty, 1-sigma. [m/s^2] */
    float high_limit_uncertainty;          /* High limit uncertainty, 1-sigma. [m/s^2] */
    float minimum_uncertainty;             /* Minimum uncertainty, 1-sigma. [m/s^2] */
} mipc_filter_gravity_magnitude_adaptive_measurement_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT_RESPONSE_MAX_SIZE 25

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_gravity_magnitude_adaptive_measurement_response_encode(
    const mipc_filter_gravity_magnitude_adaptive_measurement_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_gravity_magnitude_adaptive_measurement_response_decode(
    const uint8_t *data, size_t len, mipc_filter_gravity_magnitude_adaptive_measurement_response_t *out,
    mipc_decode_error_t *err);

/* ---- mag_magnitude_adaptive_measurement (command): Magnetometer magnitude error adaptive measurement */
#define MIPC_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT_DESCRIPTOR 0x45

/** Magnetometer magnitude error adaptive measurement. Configure the magnetometer magnitude error adaptive
 * measurement, which rejects magnetometer readings whose magnitude is outside the fixed or internally
 * computed limits. The filter and limit parameters may be left out: with only the function and mode, the
 * other values keep their previous settings. */
typedef struct {
    mipc_function_selector_t function;     /* function selector (write, read, save, load, default) */
    bool has_mode;                         /* mode is present */
    mipc_adaptive_measurement_mode_t mode; /* Disabled, fixed or auto-adaptive. */
    bool has_frequency;                    /* frequency is present */
    float frequency;                       /* Low-pass filter cutoff frequency. [Hz] */
    bool has_low_limit;                    /* low_limit is present */
    float low_limit;                       /* Low limit. [gauss] */
    bool has_high_limit;                   /* high_limit is present */
    float high_limit;                      /* High limit. [gauss] */
    bool has_low_limit_uncertainty;        /* low_limit_uncertainty is present */
    float low_limit_uncertainty;           /* Low limit uncertainty, 1-sigma. [gauss] */
    bool has_high_limit_uncertainty;       /* high_limit_uncertainty is present */
    float high_limit_uncertainty;          /* High limit uncertainty, 1-sigma. [gauss] */
    bool has_minimum_uncertainty;          /* minimum_uncertainty is present */
    float minimum_uncertainty;             /* Minimum uncertainty, 1-sigma. [gauss] */
} mipc_filter_mag_magnitude_adaptive_measurement_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT_MAX_SIZE 26

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_mag_magnitude_adaptive_measurement_encode(
    const mipc_filter_mag_magnitude_adaptive_measurement_t *value, uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_mag_magnitude_adaptive_measurement_decode(const uint8_t *data, size_t len,
                                                      mipc_filter_mag_magnitude_adaptive_measurement_t *out,
                                                      mipc_decode_error_t *err);

/* ---- mag_magnitude_adaptive_measurement_response (response): Magnetometer magnitude error adaptive
 * measurement (response) */
#define MIPC_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT_RESPONSE_DESCRIPTOR 0xB4

/** Magnetometer magnitude error adaptive measurement (response). Current magnetometer magnitude adaptive
 * measurement settings. */
typedef struct {
    mipc_adaptive_measurement_mode_t mode; /* Disabled, fixed or auto-adaptive. */
    float frequency;                       /* Low-pass filter cutoff frequency. [Hz] */
    float low_limit;                       /* Low limit. [gauss] */
    float high_limit;                      /* High limit. [gauss] */
    float low_limit_uncertainty;           /* Low limit uncertainty, 1-sigma. [gauss] */
    float high_limit_uncertainty;          /* High limit uncertainty, 1-sigma. [gauss] */
    float minimum_uncertainty;             /* Minimum uncertainty, 1-sigma. [gauss] */
} mipc_filter_mag_magnitude_adaptive_measurement_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT_RESPONSE_MAX_SIZE 25

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_mag_magnitude_adaptive_measurement_response_encode(
    const mipc_filter_mag_magnitude_adaptive_measurement_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_mag_magnitude_adaptive_measurement_response_decode(
    const uint8_t *data, size_t len, mipc_filter_mag_magnitude_adaptive_measurement_response_t *out,
    mipc_decode_error_t *err);

/* ---- mag_dip_angle_adaptive_measurement (command): Magnetometer dip angle error adaptive measurement */
#define MIPC_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT_DESCRIPTOR 0x46

/** Magnetometer dip angle error adaptive measurement. Configure the magnetometer dip angle error adaptive
 * measurement, which rejects magnetometer readings whose dip angle error exceeds the limit. Ignored while an
 * auto-adaptive magnetometer or gravity magnitude mode is selected. Only disabled (0) and fixed (1) are
 * documented. */
typedef struct {
    mipc_function_selector_t function;     /* function selector (write, read, save, load, default) */
    bool has_mode;                         /* mode is present */
    mipc_adaptive_measurement_mode_t mode; /* Disabled (0) or fixed (1). */
    bool has_frequency;                    /* frequency is present */
    float frequency;                       /* Low-pass filter cutoff frequency. [Hz] */
    bool has_high_limit;                   /* high_limit is present */
    float high_limit;                      /* High limit of the dip angle error. [rad] */
    bool has_high_limit_uncertainty;       /* high_limit_uncertainty is present */
    float high_limit_uncertainty;          /* High limit uncertainty, 1-sigma. [rad] */
    bool has_minimum_uncertainty;          /* minimum_uncertainty is present */
    float minimum_uncertainty;             /* Minimum uncertainty, 1-sigma. [rad] */
} mipc_filter_mag_dip_angle_adaptive_measurement_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT_MAX_SIZE 18

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_mag_dip_angle_adaptive_measurement_encode(
    const mipc_filter_mag_dip_angle_adaptive_measurement_t *value, uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_mag_dip_angle_adaptive_measurement_decode(const uint8_t *data, size_t len,
                                                      mipc_filter_mag_dip_angle_adaptive_measurement_t *out,
                                                      mipc_decode_error_t *err);

/* ---- mag_dip_angle_adaptive_measurement_response (response): Magnetometer dip angle error adaptive
 * measurement (response) */
#define MIPC_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT_RESPONSE_DESCRIPTOR 0xB5

/** Magnetometer dip angle error adaptive measurement (response). Current dip angle adaptive measurement
 * settings. */
typedef struct {
    mipc_adaptive_measurement_mode_t mode; /* Disabled (0) or fixed (1). */
    float frequency;                       /* Low-pass filter cutoff frequency. [Hz] */
    float high_limit;                      /* High limit of the dip angle error. [rad] */
    float high_limit_uncertainty;          /* High limit uncertainty, 1-sigma. [rad] */
    float minimum_uncertainty;             /* Minimum uncertainty, 1-sigma. [rad] */
} mipc_filter_mag_dip_angle_adaptive_measurement_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT_RESPONSE_MAX_SIZE 17

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_mag_dip_angle_adaptive_measurement_response_encode(
    const mipc_filter_mag_dip_angle_adaptive_measurement_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_mag_dip_angle_adaptive_measurement_response_decode(
    const uint8_t *data, size_t len, mipc_filter_mag_dip_angle_adaptive_measurement_response_t *out,
    mipc_decode_error_t *err);

/* ---- altitude_aiding_control (command): Altitude aiding control */
#define MIPC_FILTER_ALTITUDE_AIDING_CONTROL_DESCRIPTOR 0x47

/** Altitude aiding control. Select the altitude aiding input. GNSS is always the primary altitude; the aiding
 * input improves it and bridges GNSS outages. Pressure altitude depends on weather and location and can vary
 * by more than 40 m. */
typedef struct {
    mipc_function_selector_t function;    /* function selector (write, read, save, load, default) */
    bool has_source;                      /* source is present */
    mipc_altitude_aiding_source_t source; /* Altitude aiding input (0 disabled, 1 pressure). */
} mipc_filter_altitude_aiding_control_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_ALTITUDE_AIDING_CONTROL_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_altitude_aiding_control_encode(const mipc_filter_altitude_aiding_control_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_altitude_aiding_control_decode(const uint8_t *data, size_t len,
                                                         mipc_filter_altitude_aiding_control_t *out,
                                                         mipc_decode_error_t *err);

/* ---- altitude_aiding_control_response (response): Altitude aiding control (response) */
#define MIPC_FILTER_ALTITUDE_AIDING_CONTROL_RESPONSE_DESCRIPTOR 0xB7

/** Altitude aiding control (response). Current altitude aiding input. */
typedef struct {
    mipc_altitude_aiding_source_t source; /* Altitude aiding input. */
} mipc_filter_altitude_aiding_control_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_ALTITUDE_AIDING_CONTROL_RESPONSE_MAX_SIZE 1

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_altitude_aiding_control_response_encode(
    const mipc_filter_altitude_aiding_control_response_t *value, uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_altitude_aiding_control_response_decode(const uint8_t *data, size_t len,
                                                    mipc_filter_altitude_aiding_control_response_t *out,
                                                    mipc_decode_error_t *err);

/* ---- pitch_roll_aiding_control (command): Pitch/roll aiding control */
#define MIPC_FILTER_PITCH_ROLL_AIDING_CONTROL_DESCRIPTOR 0x4B

/** Pitch/roll aiding control. Select the pitch/roll aiding input. Pitch and roll always come from the
 * GNSS-corrected inertial solution; the aiding input improves it at low dynamics and during GNSS outages. */
typedef struct {
    mipc_function_selector_t function;      /* function selector (write, read, save, load, default) */
    bool has_source;                        /* source is present */
    mipc_pitch_roll_aiding_source_t source; /* Pitch/roll aiding input (0 disabled, 1 gravity vector). */
} mipc_filter_pitch_roll_aiding_control_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_PITCH_ROLL_AIDING_CONTROL_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_pitch_roll_aiding_control_encode(const mipc_filter_pitch_roll_aiding_control_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_pitch_roll_aiding_control_decode(const uint8_t *data, size_t len,
                                                           mipc_filter_pitch_roll_aiding_control_t *out,
                                                           mipc_decode_error_t *err);

/* ---- pitch_roll_aiding_control_response (response): Pitch/roll aiding control (response) */
#define MIPC_FILTER_PITCH_ROLL_AIDING_CONTROL_RESPONSE_DESCRIPTOR 0xBB

/** Pitch/roll aiding control (response). Current pitch/roll aiding input. */
typedef struct {
    mipc_pitch_roll_aiding_source_t source; /* Pitch/roll aiding input. */
} mipc_filter_pitch_roll_aiding_control_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_PITCH_ROLL_AIDING_CONTROL_RESPONSE_MAX_SIZE 1

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_pitch_roll_aiding_control_response_encode(
    const mipc_filter_pitch_roll_aiding_control_response_t *value, uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_pitch_roll_aiding_control_response_decode(const uint8_t *data, size_t len,
                                                      mipc_filter_pitch_roll_aiding_control_response_t *out,
                                                      mipc_decode_error_t *err);

/* ---- inclination_source (command): Inclination source */
#define MIPC_FILTER_INCLINATION_SOURCE_DESCRIPTOR 0x4C

/** Inclination source. Source of the local magnetic inclination (dip angle), which matters for the
 * magnetometer auto-calibration; without an accurate source, leave auto-calibration off. */
typedef struct {
    mipc_function_selector_t function;   /* function selector (write, read, save, load, default) */
    bool has_source;                     /* source is present */
    mipc_magnetic_param_source_t source; /* Inclination source. */
    bool has_inclination;                /* inclination is present */
    float inclination;                   /* Manual inclination angle (used when source is manual). [rad] */
} mipc_filter_inclination_source_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_INCLINATION_SOURCE_MAX_SIZE 6

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_inclination_source_encode(const mipc_filter_inclination_source_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_inclination_source_decode(const uint8_t *data, size_t len,
                                                    mipc_filter_inclination_source_t *out,
                                                    mipc_decode_error_t *err);

/* ---- inclination_source_response (response): Inclination source (response) */
#define MIPC_FILTER_INCLINATION_SOURCE_RESPONSE_DESCRIPTOR 0xBC

/** Inclination source (response). Current inclination source and angle. */
typedef struct {
    mipc_magnetic_param_source_t source; /* Inclination source. */
    float inclination;                   /* Inclination angle. [rad] */
} mipc_filter_inclination_source_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_INCLINATION_SOURCE_RESPONSE_MAX_SIZE 5

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_inclination_source_response_encode(const mipc_filter_inclination_source_response_t *value,
                                               uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_inclination_source_response_decode(const uint8_t *data, size_t len,
                                                             mipc_filter_inclination_source_response_t *out,
                                                             mipc_decode_error_t *err);

/* ---- magnetic_field_magnitude_source (command): Magnetic field magnitude source */
#define MIPC_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE_DESCRIPTOR 0x4D

/** Magnetic field magnitude source. Source of the local magnetic field magnitude, used by the magnetometer
 * auto-calibration and the magnetometer magnitude adaptive measurement. Source none uses a fixed 0.5 gauss.
 */
typedef struct {
    mipc_function_selector_t function;   /* function selector (write, read, save, load, default) */
    bool has_source;                     /* source is present */
    mipc_magnetic_param_source_t source; /* Magnitude source. */
    bool has_magnitude;                  /* magnitude is present */
    float magnitude;                     /* Manual field magnitude (used when source is manual). [gauss] */
} mipc_filter_magnetic_field_magnitude_source_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE_MAX_SIZE 6

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_magnetic_field_magnitude_source_encode(const mipc_filter_magnetic_field_magnitude_source_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_magnetic_field_magnitude_source_decode(const uint8_t *data, size_t len,
                                                   mipc_filter_magnetic_field_magnitude_source_t *out,
                                                   mipc_decode_error_t *err);

/* ---- magnetic_field_magnitude_source_response (response): Magnetic field magnitude source (response) */
#define MIPC_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE_RESPONSE_DESCRIPTOR 0xBD

/** Magnetic field magnitude source (response). Current magnetic field magnitude source and value. */
typedef struct {
    mipc_magnetic_param_source_t source; /* Magnitude source. */
    float magnitude;                     /* Field magnitude. [gauss] */
} mipc_filter_magnetic_field_magnitude_source_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE_RESPONSE_MAX_SIZE 5

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_magnetic_field_magnitude_source_response_encode(
    const mipc_filter_magnetic_field_magnitude_source_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_magnetic_field_magnitude_source_response_decode(
    const uint8_t *data, size_t len, mipc_filter_magnetic_field_magnitude_source_response_t *out,
    mipc_decode_error_t *err);

/* ---- aiding_measurement_control (command): Aiding measurement control */
#define MIPC_FILTER_AIDING_MEASUREMENT_CONTROL_DESCRIPTOR 0x50

/** Aiding measurement control. Enable or disable an internal aiding measurement source. The source is sent
 * with every function; ALL (0xFFFF) applies save, load and default to every source. */
typedef struct {
    mipc_function_selector_t function;       /* function selector (write, read, save, load, default) */
    mipc_aiding_measurement_source_t source; /* Aiding measurement source. */
    bool has_enable;                         /* enable is present */
    bool enable;                             /* Whether the source is used. */
} mipc_filter_aiding_measurement_control_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_AIDING_MEASUREMENT_CONTROL_MAX_SIZE 4

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_aiding_measurement_control_encode(const mipc_filter_aiding_measurement_control_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_aiding_measurement_control_decode(const uint8_t *data, size_t len,
                                                            mipc_filter_aiding_measurement_control_t *out,
                                                            mipc_decode_error_t *err);

/* ---- aiding_measurement_control_response (response): Aiding measurement control (response) */
#define MIPC_FILTER_AIDING_MEASUREMENT_CONTROL_RESPONSE_DESCRIPTOR 0xD0

/** Aiding measurement control (response). Whether an aiding measurement source is enabled. */
typedef struct {
    mipc_aiding_measurement_source_t source; /* Aiding measurement source. */
    bool enable;                             /* Whether the source is used. */
} mipc_filter_aiding_measurement_control_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_AIDING_MEASUREMENT_CONTROL_RESPONSE_MAX_SIZE 3

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_aiding_measurement_control_response_encode(
    const mipc_filter_aiding_measurement_control_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_aiding_measurement_control_response_decode(const uint8_t *data, size_t len,
                                                       mipc_filter_aiding_measurement_control_response_t *out,
                                                       mipc_decode_error_t *err);

/* ---- initialization_configuration (command): Navigation filter initialization */
#define MIPC_FILTER_INITIALIZATION_CONFIGURATION_DESCRIPTOR 0x52

/** Navigation filter initialization. Source and values of the initial conditions (position, velocity,
 * attitude) of the navigation filter. Every parameter is always sent; the initial condition source decides
 * which of the user values are used, and the reference frame selector gives the units of the position (ECEF:
 * m; LLH: deg, deg, m) and the frame of the velocity. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_wait_for_run_command;     /* wait_for_run_command is present */
    uint8_t wait_for_run_command;      /* Non-zero: initialize the filter only after a Run Navigation Filter
                                          (0x0D,0x05) command. */
    bool has_initial_cond_src;         /* initial_cond_src is present */
    mipc_filter_initial_condition_source_t
        initial_cond_src; /* Which initial conditions are automatic and which user-specified. */
    bool has_auto_heading_alignment_selector; /* auto_heading_alignment_selector is present */
    mipc_heading_alignment_methods_t
        auto_heading_alignment_selector; /* Allowed automatic heading alignment methods. */
    bool has_initial_heading;            /* initial_heading is present */
    float initial_heading;               /* User-specified initial heading. [deg] */
    bool has_initial_pitch;              /* initial_pitch is present */
    float initial_pitch;                 /* User-specified initial pitch. [deg] */
    bool has_initial_roll;               /* initial_roll is present */
    float initial_roll;                  /* User-specified initial roll. [deg] */
    bool has_initial_position;           /* initial_position is present */
    float initial_position[3];           /* User-specified initial position (ECEF m, or LLH deg/deg/m, per
                                            reference_frame_selector). */
    bool has_initial_velocity;           /* initial_velocity is present */
    float initial_velocity[3];           /* User-specified initial velocity, in the frame chosen by
                                            reference_frame_selector. [m/s] */
    bool has_reference_frame_selector;   /* reference_frame_selector is present */
    mipc_filter_reference_frame_t reference_frame_selector; /* Frame of the initial position and velocity. */
} mipc_filter_initialization_configuration_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_INITIALIZATION_CONFIGURATION_MAX_SIZE 41

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_initialization_configuration_encode(const mipc_filter_initialization_configuration_t *value,
                                                uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_initialization_configuration_decode(const uint8_t *data, size_t len,
                                                              mipc_filter_initialization_configuration_t *out,
                                                              mipc_decode_error_t *err);

/* ---- initialization_configuration_response (response): Navigation filter initialization (response) */
#define MIPC_FILTER_INITIALIZATION_CONFIGURATION_RESPONSE_DESCRIPTOR 0xD2

/** Navigation filter initialization (response). Current initial condition configuration. */
typedef struct {
    uint8_t wait_for_run_command;                            /* Non-zero: wait for the run command. */
    mipc_filter_initial_condition_source_t initial_cond_src; /* Initial condition source. */
    mipc_heading_alignment_methods_t
        auto_heading_alignment_selector; /* Allowed automatic heading alignment methods. */
    float initial_heading;               /* User-specified initial heading. [deg] */
    float initial_pitch;                 /* User-specified initial pitch. [deg] */
    float initial_roll;                  /* User-specified initial roll. [deg] */
    float initial_position[3];           /* User-specified initial position (ECEF m, or LLH deg/deg/m). */
    float initial_velocity[3];           /* User-specified initial velocity. [m/s] */
    mipc_filter_reference_frame_t reference_frame_selector; /* Frame of the initial position and velocity. */
} mipc_filter_initialization_configuration_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_INITIALIZATION_CONFIGURATION_RESPONSE_MAX_SIZE 40

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_initialization_configuration_response_encode(
    const mipc_filter_initialization_configuration_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_initialization_configuration_response_decode(
    const uint8_t *data, size_t len, mipc_filter_initialization_configuration_response_t *out,
    mipc_decode_error_t *err);

/* ---- adaptive_filter_control (command): Adaptive filter control */
#define MIPC_FILTER_ADAPTIVE_FILTER_CONTROL_DESCRIPTOR 0x53

/** Adaptive filter control. Basic setup of the auto-adaptive filter: how aggressively it adjusts its
 * statistical models, and how long measurements may be rejected before it enters recovery mode. */
typedef struct {
    mipc_function_selector_t function;  /* function selector (write, read, save, load, default) */
    bool has_level;                     /* level is present */
    mipc_adaptive_filter_level_t level; /* Auto-adaptive operating level. */
    bool has_time_limit;                /* time_limit is present */
    uint16_t time_limit;                /* Longest measurement rejection before recovery mode. [ms] */
} mipc_filter_adaptive_filter_control_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_ADAPTIVE_FILTER_CONTROL_MAX_SIZE 4

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_adaptive_filter_control_encode(const mipc_filter_adaptive_filter_control_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_adaptive_filter_control_decode(const uint8_t *data, size_t len,
                                                         mipc_filter_adaptive_filter_control_t *out,
                                                         mipc_decode_error_t *err);

/* ---- adaptive_filter_control_response (response): Adaptive filter control (response) */
#define MIPC_FILTER_ADAPTIVE_FILTER_CONTROL_RESPONSE_DESCRIPTOR 0xD3

/** Adaptive filter control (response). Current adaptive filter settings. */
typedef struct {
    mipc_adaptive_filter_level_t level; /* Auto-adaptive operating level. */
    uint16_t time_limit;                /* Longest measurement rejection before recovery mode. [ms] */
} mipc_filter_adaptive_filter_control_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_ADAPTIVE_FILTER_CONTROL_RESPONSE_MAX_SIZE 3

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_adaptive_filter_control_response_encode(
    const mipc_filter_adaptive_filter_control_response_t *value, uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_adaptive_filter_control_response_decode(const uint8_t *data, size_t len,
                                                    mipc_filter_adaptive_filter_control_response_t *out,
                                                    mipc_decode_error_t *err);

/* ---- multi_antenna_offset (command): GNSS multi-antenna offset */
#define MIPC_FILTER_MULTI_ANTENNA_OFFSET_DESCRIPTOR 0x54

/** GNSS multi-antenna offset. Antenna lever arm of one GNSS receiver, in the vehicle frame, for devices with
 * several antennas. The offset magnitude is limited to 10 m. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    uint8_t receiver_id;               /* Receiver: 1, 2, ... */
    bool has_antenna_offset;           /* antenna_offset is present */
    float antenna_offset[3];           /* Antenna lever arm in the vehicle frame. [m] */
} mipc_filter_multi_antenna_offset_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_MULTI_ANTENNA_OFFSET_MAX_SIZE 14

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_multi_antenna_offset_encode(const mipc_filter_multi_antenna_offset_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_multi_antenna_offset_decode(const uint8_t *data, size_t len,
                                                      mipc_filter_multi_antenna_offset_t *out,
                                                      mipc_decode_error_t *err);

/* ---- multi_antenna_offset_response (response): GNSS multi-antenna offset (response) */
#define MIPC_FILTER_MULTI_ANTENNA_OFFSET_RESPONSE_DESCRIPTOR 0xD4

/** GNSS multi-antenna offset (response). Current antenna lever arm of a receiver. */
typedef struct {
    uint8_t receiver_id;     /* Receiver: 1, 2, ... */
    float antenna_offset[3]; /* Antenna lever arm in the vehicle frame. [m] */
} mipc_filter_multi_antenna_offset_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_MULTI_ANTENNA_OFFSET_RESPONSE_MAX_SIZE 13

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_multi_antenna_offset_response_encode(const mipc_filter_multi_antenna_offset_response_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_multi_antenna_offset_response_decode(const uint8_t *data, size_t len,
                                                 mipc_filter_multi_antenna_offset_response_t *out,
                                                 mipc_decode_error_t *err);

/* ---- relative_position_configuration (command): Relative position configuration */
#define MIPC_FILTER_RELATIVE_POSITION_CONFIGURATION_DESCRIPTOR 0x55

/** Relative position configuration. Reference location of the filter's relative position outputs. */
typedef struct {
    mipc_function_selector_t function;      /* function selector (write, read, save, load, default) */
    bool has_source;                        /* source is present */
    mipc_relative_position_source_t source; /* 0 automatic (RTK base station), 1 manual. */
    bool has_reference_frame_selector;      /* reference_frame_selector is present */
    mipc_filter_reference_frame_t reference_frame_selector; /* Frame of the reference coordinates. */
    bool has_reference_coordinates;                         /* reference_coordinates is present */
    double reference_coordinates[3]; /* Reference location (ECEF m, or LLH deg/deg/m). */
} mipc_filter_relative_position_configuration_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_RELATIVE_POSITION_CONFIGURATION_MAX_SIZE 27

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_relative_position_configuration_encode(const mipc_filter_relative_position_configuration_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_relative_position_configuration_decode(const uint8_t *data, size_t len,
                                                   mipc_filter_relative_position_configuration_t *out,
                                                   mipc_decode_error_t *err);

/* ---- relative_position_configuration_response (response): Relative position configuration (response) */
#define MIPC_FILTER_RELATIVE_POSITION_CONFIGURATION_RESPONSE_DESCRIPTOR 0xD5

/** Relative position configuration (response). Current relative position reference. */
typedef struct {
    mipc_relative_position_source_t source;                 /* 0 automatic (RTK base station), 1 manual. */
    mipc_filter_reference_frame_t reference_frame_selector; /* Frame of the reference coordinates. */
    double reference_coordinates[3]; /* Reference location (ECEF m, or LLH deg/deg/m). */
} mipc_filter_relative_position_configuration_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_RELATIVE_POSITION_CONFIGURATION_RESPONSE_MAX_SIZE 26

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_relative_position_configuration_response_encode(
    const mipc_filter_relative_position_configuration_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_relative_position_configuration_response_decode(
    const uint8_t *data, size_t len, mipc_filter_relative_position_configuration_response_t *out,
    mipc_decode_error_t *err);

/* ---- reference_point_lever_arm (command): Reference point lever arm */
#define MIPC_FILTER_REFERENCE_POINT_LEVER_ARM_DESCRIPTOR 0x56

/** Reference point lever arm. Lever arm from the sensor to the filter's reference point, in the vehicle
 * frame. Moving the reference point offsets the filter position and velocity outputs according to attitude
 * and angular rate. Limited to 10 m for the vehicle reference point. */
typedef struct {
    mipc_function_selector_t function;             /* function selector (write, read, save, load, default) */
    bool has_ref_point_sel;                        /* ref_point_sel is present */
    mipc_reference_point_selector_t ref_point_sel; /* Reference point; reserved, must be 1 (vehicle). */
    bool has_lever_arm_offset;                     /* lever_arm_offset is present */
    float lever_arm_offset[3];                     /* Lever arm in the vehicle frame. [m] */
} mipc_filter_reference_point_lever_arm_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_REFERENCE_POINT_LEVER_ARM_MAX_SIZE 14

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_reference_point_lever_arm_encode(const mipc_filter_reference_point_lever_arm_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_reference_point_lever_arm_decode(const uint8_t *data, size_t len,
                                                           mipc_filter_reference_point_lever_arm_t *out,
                                                           mipc_decode_error_t *err);

/* ---- reference_point_lever_arm_response (response): Reference point lever arm (response) */
#define MIPC_FILTER_REFERENCE_POINT_LEVER_ARM_RESPONSE_DESCRIPTOR 0xD6

/** Reference point lever arm (response). Current reference point lever arm. */
typedef struct {
    mipc_reference_point_selector_t ref_point_sel; /* Reference point. */
    float lever_arm_offset[3];                     /* Lever arm in the vehicle frame. [m] */
} mipc_filter_reference_point_lever_arm_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_REFERENCE_POINT_LEVER_ARM_RESPONSE_MAX_SIZE 13

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_reference_point_lever_arm_response_encode(
    const mipc_filter_reference_point_lever_arm_response_t *value, uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_reference_point_lever_arm_response_decode(const uint8_t *data, size_t len,
                                                      mipc_filter_reference_point_lever_arm_response_t *out,
                                                      mipc_decode_error_t *err);

/* ---- speed_lever_arm (command): Measurement speed lever arm */
#define MIPC_FILTER_SPEED_LEVER_ARM_DESCRIPTOR 0x61

/** Measurement speed lever arm. Lever arm of the speed measurement point (e.g. an odometer on one wheel), in
 * the vehicle frame, used to compensate the speed difference caused by vehicle rotation. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    uint8_t source;                    /* Speed source; reserved, must be 1. */
    bool has_lever_arm_offset;         /* lever_arm_offset is present */
    float lever_arm_offset[3];         /* Lever arm in the vehicle frame. [m] */
} mipc_filter_speed_lever_arm_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_SPEED_LEVER_ARM_MAX_SIZE 14

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_speed_lever_arm_encode(const mipc_filter_speed_lever_arm_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_speed_lever_arm_decode(const uint8_t *data, size_t len,
                                                 mipc_filter_speed_lever_arm_t *out,
                                                 mipc_decode_error_t *err);

/* ---- speed_lever_arm_response (response): Measurement speed lever arm (response) */
#define MIPC_FILTER_SPEED_LEVER_ARM_RESPONSE_DESCRIPTOR 0xE1

/** Measurement speed lever arm (response). Current speed measurement lever arm. */
typedef struct {
    uint8_t source;            /* Speed source (1). */
    float lever_arm_offset[3]; /* Lever arm in the vehicle frame. [m] */
} mipc_filter_speed_lever_arm_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_SPEED_LEVER_ARM_RESPONSE_MAX_SIZE 13

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_speed_lever_arm_response_encode(const mipc_filter_speed_lever_arm_response_t *value,
                                                          uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_speed_lever_arm_response_decode(const uint8_t *data, size_t len,
                                                          mipc_filter_speed_lever_arm_response_t *out,
                                                          mipc_decode_error_t *err);

/* ---- wheeled_vehicle_constraint_control (command): Wheeled vehicle constraint control */
#define MIPC_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL_DESCRIPTOR 0x63

/** Wheeled vehicle constraint control. Enable the wheeled vehicle kinematic constraint: velocity is assumed
 * to lie along the vehicle X axis. Helps heading for ground vehicles, especially with intermittent GNSS. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_enable;                   /* enable is present */
    uint8_t enable;                    /* 0 disables, 1 enables the constraint. */
} mipc_filter_wheeled_vehicle_constraint_control_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_wheeled_vehicle_constraint_control_encode(
    const mipc_filter_wheeled_vehicle_constraint_control_t *value, uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_wheeled_vehicle_constraint_control_decode(const uint8_t *data, size_t len,
                                                      mipc_filter_wheeled_vehicle_constraint_control_t *out,
                                                      mipc_decode_error_t *err);

/* ---- wheeled_vehicle_constraint_control_response (response): Wheeled vehicle constraint control (response)
 */
#define MIPC_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL_RESPONSE_DESCRIPTOR 0xE3

/** Wheeled vehicle constraint control (response). Whether the wheeled vehicle constraint is enabled. */
typedef struct {
    uint8_t enable; /* 0 disabled, 1 enabled. */
} mipc_filter_wheeled_vehicle_constraint_control_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL_RESPONSE_MAX_SIZE 1

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_wheeled_vehicle_constraint_control_response_encode(
    const mipc_filter_wheeled_vehicle_constraint_control_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_wheeled_vehicle_constraint_control_response_decode(
    const uint8_t *data, size_t len, mipc_filter_wheeled_vehicle_constraint_control_response_t *out,
    mipc_decode_error_t *err);

/* ---- gnss_antenna_calibration_control (command): GNSS antenna offset calibration control */
#define MIPC_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL_DESCRIPTOR 0x64

/** GNSS antenna offset calibration control. Enable tracking of the GNSS antenna lever arm error, up to the
 * given maximum offset error (CV7: default 0.1 m, at most 0.5 m). */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_enable;                   /* enable is present */
    uint8_t enable;                    /* 0 disables, 1 enables lever arm error tracking. */
    bool has_max_offset;               /* max_offset is present */
    float max_offset;                  /* Largest absolute lever arm offset error in the vehicle frame. [m] */
} mipc_filter_gnss_antenna_calibration_control_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL_MAX_SIZE 6

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_gnss_antenna_calibration_control_encode(
    const mipc_filter_gnss_antenna_calibration_control_t *value, uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_gnss_antenna_calibration_control_decode(const uint8_t *data, size_t len,
                                                    mipc_filter_gnss_antenna_calibration_control_t *out,
                                                    mipc_decode_error_t *err);

/* ---- gnss_antenna_calibration_control_response (response): GNSS antenna offset calibration control
 * (response) */
#define MIPC_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL_RESPONSE_DESCRIPTOR 0xE4

/** GNSS antenna offset calibration control (response). Current antenna lever arm calibration settings. */
typedef struct {
    uint8_t enable;   /* 0 disabled, 1 enabled. */
    float max_offset; /* Largest absolute lever arm offset error. [m] */
} mipc_filter_gnss_antenna_calibration_control_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL_RESPONSE_MAX_SIZE 5

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_gnss_antenna_calibration_control_response_encode(
    const mipc_filter_gnss_antenna_calibration_control_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_gnss_antenna_calibration_control_response_decode(
    const uint8_t *data, size_t len, mipc_filter_gnss_antenna_calibration_control_response_t *out,
    mipc_decode_error_t *err);

#ifdef __cplusplus
}
#endif

#endif
