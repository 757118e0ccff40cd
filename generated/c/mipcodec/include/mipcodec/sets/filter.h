/* Filter Command Set (descriptor set 0x0D): one struct per field layout, with its
 * encoder and decoder. Generated from the spec: do not edit. */
#ifndef MIP_SETS_FILTER_H
#define MIP_SETS_FILTER_H

#include "mipcodec/types.h"

#ifdef __cplusplus
extern "C" {
#endif

#define MIP_FILTER_SET 0x0D

/* ---- reset_filter (command): Reset filter */
#define MIP_FILTER_RESET_FILTER_DESCRIPTOR 0x01

/** Reset filter. Put the filter back into its initialisation state. With auto-initialisation disabled, an
 * initial attitude or heading must then be given before it runs again. */
typedef struct {
    uint8_t unused_; /* no parameters */
} mip_filter_reset_filter_t;

/* Largest encoded data (after the field header). */
#define MIP_FILTER_RESET_FILTER_MAX_SIZE 0

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_filter_reset_filter_encode(const mip_filter_reset_filter_t *value, uint8_t *buf, size_t cap,
                                            size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_filter_reset_filter_decode(const uint8_t *data, size_t len, mip_filter_reset_filter_t *out,
                                            mip_decode_error_t *err);

/* ---- set_initial_attitude (command): Set initial attitude */
#define MIP_FILTER_SET_INITIAL_ATTITUDE_DESCRIPTOR 0x02

/** Set initial attitude. Initialise the filter attitude from Euler angles of the sensor body frame relative
 * to the local NED frame. Only accepted in the INIT state. */
typedef struct {
    float roll;    /* Roll angle, in [-pi, pi]. [rad] */
    float pitch;   /* Pitch angle, in [-pi/2, pi/2]. [rad] */
    float heading; /* Heading (yaw) angle, in [-pi, pi]. [rad] */
} mip_filter_set_initial_attitude_t;

/* Largest encoded data (after the field header). */
#define MIP_FILTER_SET_INITIAL_ATTITUDE_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_filter_set_initial_attitude_encode(const mip_filter_set_initial_attitude_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_filter_set_initial_attitude_decode(const uint8_t *data, size_t len,
                                                    mip_filter_set_initial_attitude_t *out,
                                                    mip_decode_error_t *err);

/* ---- set_initial_heading (command): Set initial heading */
#define MIP_FILTER_SET_INITIAL_HEADING_DESCRIPTOR 0x03

/** Set initial heading. Initialise the filter heading; roll and pitch come from the accelerometers. GX5-45:
 * only accepted in the INIT state. CV7: the heading estimate is reset to this value, unless magnetometer
 * aiding is enabled, in which case the magnetic heading is used instead. */
typedef struct {
    float heading; /* Initial heading, in [-pi, pi]. [rad] */
} mip_filter_set_initial_heading_t;

/* Largest encoded data (after the field header). */
#define MIP_FILTER_SET_INITIAL_HEADING_MAX_SIZE 4

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_filter_set_initial_heading_encode(const mip_filter_set_initial_heading_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_filter_set_initial_heading_decode(const uint8_t *data, size_t len,
                                                   mip_filter_set_initial_heading_t *out,
                                                   mip_decode_error_t *err);

/* ---- run_filter (command): Run navigation filter */
#define MIP_FILTER_RUN_FILTER_DESCRIPTOR 0x05

/** Run navigation filter. Start the filter by hand when the initialisation configuration asks it to wait for
 * a run command; until then it stays in initialisation mode. */
typedef struct {
    uint8_t unused_; /* no parameters */
} mip_filter_run_filter_t;

/* Largest encoded data (after the field header). */
#define MIP_FILTER_RUN_FILTER_MAX_SIZE 0

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_filter_run_filter_encode(const mip_filter_run_filter_t *value, uint8_t *buf, size_t cap,
                                          size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_filter_run_filter_decode(const uint8_t *data, size_t len, mip_filter_run_filter_t *out,
                                          mip_decode_error_t *err);

/* ---- vehicle_dynamics_mode (command): Vehicle dynamics mode */
#define MIP_FILTER_VEHICLE_DYNAMICS_MODE_DESCRIPTOR 0x10

/** Vehicle dynamics mode. Set, read, save, load or reset the vehicle dynamics mode of the filter. */
typedef struct {
    mip_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_mode;                    /* mode is present */
    mip_vehicle_dynamics_mode_t mode; /* New dynamics mode. */
} mip_filter_vehicle_dynamics_mode_t;

/* Largest encoded data (after the field header). */
#define MIP_FILTER_VEHICLE_DYNAMICS_MODE_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_filter_vehicle_dynamics_mode_encode(const mip_filter_vehicle_dynamics_mode_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_filter_vehicle_dynamics_mode_decode(const uint8_t *data, size_t len,
                                                     mip_filter_vehicle_dynamics_mode_t *out,
                                                     mip_decode_error_t *err);

/* ---- vehicle_dynamics_mode_response (response): Vehicle dynamics mode (response) */
#define MIP_FILTER_VEHICLE_DYNAMICS_MODE_RESPONSE_DESCRIPTOR 0x80

/** Vehicle dynamics mode (response). Current vehicle dynamics mode (reply to read). */
typedef struct {
    mip_vehicle_dynamics_mode_t mode; /* Current dynamics mode. */
} mip_filter_vehicle_dynamics_mode_response_t;

/* Largest encoded data (after the field header). */
#define MIP_FILTER_VEHICLE_DYNAMICS_MODE_RESPONSE_MAX_SIZE 1

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t
mip_filter_vehicle_dynamics_mode_response_encode(const mip_filter_vehicle_dynamics_mode_response_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t
mip_filter_vehicle_dynamics_mode_response_decode(const uint8_t *data, size_t len,
                                                 mip_filter_vehicle_dynamics_mode_response_t *out,
                                                 mip_decode_error_t *err);

/* ---- sensor_to_vehicle_transform (command): Sensor to vehicle frame transformation */
#define MIP_FILTER_SENSOR_TO_VEHICLE_TRANSFORM_DESCRIPTOR 0x11

/** Sensor to vehicle frame transformation. Euler angles (roll, pitch, yaw) of the rotation from the sensor
 * body frame to the vehicle frame. Applies to the scaled IMU vectors, delta theta/velocity and the filter's
 * orientation, linear acceleration, angular rate and gravity outputs. */
typedef struct {
    mip_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_roll;                    /* roll is present */
    float roll;                       /* Roll angle of the sensor-to-vehicle rotation. [rad] */
    bool has_pitch;                   /* pitch is present */
    float pitch;                      /* Pitch angle of the sensor-to-vehicle rotation. [rad] */
    bool has_yaw;                     /* yaw is present */
    float yaw;                        /* Yaw angle of the sensor-to-vehicle rotation. [rad] */
} mip_filter_sensor_to_vehicle_transform_t;

/* Largest encoded data (after the field header). */
#define MIP_FILTER_SENSOR_TO_VEHICLE_TRANSFORM_MAX_SIZE 13

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t
mip_filter_sensor_to_vehicle_transform_encode(const mip_filter_sensor_to_vehicle_transform_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_filter_sensor_to_vehicle_transform_decode(const uint8_t *data, size_t len,
                                                           mip_filter_sensor_to_vehicle_transform_t *out,
                                                           mip_decode_error_t *err);

/* ---- sensor_to_vehicle_transform_response (response): Sensor to vehicle frame transformation (response) */
#define MIP_FILTER_SENSOR_TO_VEHICLE_TRANSFORM_RESPONSE_DESCRIPTOR 0x81

/** Sensor to vehicle frame transformation (response). Current sensor-to-vehicle Euler angles (reply to read).
 */
typedef struct {
    float roll;  /* Roll angle. [rad] */
    float pitch; /* Pitch angle. [rad] */
    float yaw;   /* Yaw angle. [rad] */
} mip_filter_sensor_to_vehicle_transform_response_t;

/* Largest encoded data (after the field header). */
#define MIP_FILTER_SENSOR_TO_VEHICLE_TRANSFORM_RESPONSE_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_filter_sensor_to_vehicle_transform_response_encode(
    const mip_filter_sensor_to_vehicle_transform_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t
mip_filter_sensor_to_vehicle_transform_response_decode(const uint8_t *data, size_t len,
                                                       mip_filter_sensor_to_vehicle_transform_response_t *out,
                                                       mip_decode_error_t *err);

/* ---- sensor_to_vehicle_offset (command): Sensor to vehicle frame offset */
#define MIP_FILTER_SENSOR_TO_VEHICLE_OFFSET_DESCRIPTOR 0x12

/** Sensor to vehicle frame offset. Offset from the sensor to the vehicle reference point, in the sensor
 * frame, added to the estimated LLH position. Not a lever arm: no inertial compensation. Magnitude at most 10
 * m. */
typedef struct {
    mip_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_offset;                  /* offset is present */
    float offset[3];                  /* (x, y, z) offset in the sensor body frame. [m] */
} mip_filter_sensor_to_vehicle_offset_t;

/* Largest encoded data (after the field header). */
#define MIP_FILTER_SENSOR_TO_VEHICLE_OFFSET_MAX_SIZE 13

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_filter_sensor_to_vehicle_offset_encode(const mip_filter_sensor_to_vehicle_offset_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_filter_sensor_to_vehicle_offset_decode(const uint8_t *data, size_t len,
                                                        mip_filter_sensor_to_vehicle_offset_t *out,
                                                        mip_decode_error_t *err);

/* ---- sensor_to_vehicle_offset_response (response): Sensor to vehicle frame offset (response) */
#define MIP_FILTER_SENSOR_TO_VEHICLE_OFFSET_RESPONSE_DESCRIPTOR 0x82

/** Sensor to vehicle frame offset (response). Current sensor-to-vehicle offset (reply to read). */
typedef struct {
    float offset[3]; /* (x, y, z) offset in the sensor body frame. [m] */
} mip_filter_sensor_to_vehicle_offset_response_t;

/* Largest encoded data (after the field header). */
#define MIP_FILTER_SENSOR_TO_VEHICLE_OFFSET_RESPONSE_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_filter_sensor_to_vehicle_offset_response_encode(
    const mip_filter_sensor_to_vehicle_offset_response_t *value, uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t
mip_filter_sensor_to_vehicle_offset_response_decode(const uint8_t *data, size_t len,
                                                    mip_filter_sensor_to_vehicle_offset_response_t *out,
                                                    mip_decode_error_t *err);

/* ---- antenna_offset (command): GNSS antenna offset */
#define MIP_FILTER_ANTENNA_OFFSET_DESCRIPTOR 0x13

/** GNSS antenna offset. Offset from the sensor origin to the GNSS antenna RF (phase) centre; magnitude at
 * most 10 m. GX5-45 (5-series): expressed in the sensor frame. CV7 (7-series): expressed in the vehicle
 * frame; also used for NMEA input over GPIO. */
typedef struct {
    mip_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_offset;                  /* offset is present */
    float offset[3]; /* (x, y, z) antenna offset (sensor frame on GX5-45, vehicle frame on CV7). [m] */
} mip_filter_antenna_offset_t;

/* Largest encoded data (after the field header). */
#define MIP_FILTER_ANTENNA_OFFSET_MAX_SIZE 13

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_filter_antenna_offset_encode(const mip_filter_antenna_offset_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_filter_antenna_offset_decode(const uint8_t *data, size_t len,
                                              mip_filter_antenna_offset_t *out, mip_decode_error_t *err);

/* ---- antenna_offset_response (response): GNSS antenna offset (response) */
#define MIP_FILTER_ANTENNA_OFFSET_RESPONSE_DESCRIPTOR 0x83

/** GNSS antenna offset (response). Current antenna offset (reply to read). */
typedef struct {
    float offset[3]; /* (x, y, z) antenna offset. [m] */
} mip_filter_antenna_offset_response_t;

/* Largest encoded data (after the field header). */
#define MIP_FILTER_ANTENNA_OFFSET_RESPONSE_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_filter_antenna_offset_response_encode(const mip_filter_antenna_offset_response_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_filter_antenna_offset_response_decode(const uint8_t *data, size_t len,
                                                       mip_filter_antenna_offset_response_t *out,
                                                       mip_decode_error_t *err);

/* ---- estimation_control (command): Estimation control flags */
#define MIP_FILTER_ESTIMATION_CONTROL_DESCRIPTOR 0x14

/** Estimation control flags. Select which optional parameters the Kalman filter estimates. */
typedef struct {
    mip_function_selector_t function;     /* function selector (write, read, save, load, default) */
    bool has_flags;                       /* flags is present */
    mip_estimation_control_flags_t flags; /* States to estimate. */
} mip_filter_estimation_control_t;

/* Largest encoded data (after the field header). */
#define MIP_FILTER_ESTIMATION_CONTROL_MAX_SIZE 3

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_filter_estimation_control_encode(const mip_filter_estimation_control_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_filter_estimation_control_decode(const uint8_t *data, size_t len,
                                                  mip_filter_estimation_control_t *out,
                                                  mip_decode_error_t *err);

/* ---- estimation_control_response (response): Estimation control flags (response) */
#define MIP_FILTER_ESTIMATION_CONTROL_RESPONSE_DESCRIPTOR 0x84

/** Estimation control flags (response). Current estimation control flags (reply to read). */
typedef struct {
    mip_estimation_control_flags_t flags; /* States being estimated. */
} mip_filter_estimation_control_response_t;

/* Largest encoded data (after the field header). */
#define MIP_FILTER_ESTIMATION_CONTROL_RESPONSE_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t
mip_filter_estimation_control_response_encode(const mip_filter_estimation_control_response_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_filter_estimation_control_response_decode(const uint8_t *data, size_t len,
                                                           mip_filter_estimation_control_response_t *out,
                                                           mip_decode_error_t *err);

/* ---- gnss_source_control (command): GNSS source control */
#define MIP_FILTER_GNSS_SOURCE_CONTROL_DESCRIPTOR 0x15

/** GNSS source control. Choose the source of GNSS updates to the filter. Changing it while running may put
 * the filter back in its init state until data from the new source arrives. */
typedef struct {
    mip_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_source;                  /* source is present */
    mip_filter_gnss_source_t source;  /* GNSS source. */
} mip_filter_gnss_source_control_t;

/* Largest encoded data (after the field header). */
#define MIP_FILTER_GNSS_SOURCE_CONTROL_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_filter_gnss_source_control_encode(const mip_filter_gnss_source_control_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_filter_gnss_source_control_decode(const uint8_t *data, size_t len,
                                                   mip_filter_gnss_source_control_t *out,
                                                   mip_decode_error_t *err);

/* ---- gnss_source_control_response (response): GNSS source control (response) */
#define MIP_FILTER_GNSS_SOURCE_CONTROL_RESPONSE_DESCRIPTOR 0x86

/** GNSS source control (response). Current GNSS source (reply to read). */
typedef struct {
    mip_filter_gnss_source_t source; /* GNSS source. */
} mip_filter_gnss_source_control_response_t;

/* Largest encoded data (after the field header). */
#define MIP_FILTER_GNSS_SOURCE_CONTROL_RESPONSE_MAX_SIZE 1

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t
mip_filter_gnss_source_control_response_encode(const mip_filter_gnss_source_control_response_t *value,
                                               uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_filter_gnss_source_control_response_decode(const uint8_t *data, size_t len,
                                                            mip_filter_gnss_source_control_response_t *out,
                                                            mip_decode_error_t *err);

/* ---- external_gnss_update (command): External GNSS update */
#define MIP_FILTER_EXTERNAL_GNSS_UPDATE_DESCRIPTOR 0x16

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
} mip_filter_external_gnss_update_t;

/* Largest encoded data (after the field header). */
#define MIP_FILTER_EXTERNAL_GNSS_UPDATE_MAX_SIZE 70

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_filter_external_gnss_update_encode(const mip_filter_external_gnss_update_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_filter_external_gnss_update_decode(const uint8_t *data, size_t len,
                                                    mip_filter_external_gnss_update_t *out,
                                                    mip_decode_error_t *err);

/* ---- external_heading_update (command): External heading update */
#define MIP_FILTER_EXTERNAL_HEADING_UPDATE_DESCRIPTOR 0x17

/** External heading update. Give the filter one heading measurement (sensor frame relative to NED) from an
 * external source. Only used when external heading aiding is enabled, otherwise NACKed; uncertainties of 0 or
 * less are NACKed; a true (or magnetic) heading is NACKed when the declination source is invalid (see the
 * manuals for which model refuses which). */
typedef struct {
    float heading;                    /* Heading angle, within +-pi. [rad] */
    float heading_uncertainty;        /* Heading 1-sigma uncertainty; must be greater than 0. [rad] */
    mip_external_heading_type_t type; /* True or magnetic heading. */
} mip_filter_external_heading_update_t;

/* Largest encoded data (after the field header). */
#define MIP_FILTER_EXTERNAL_HEADING_UPDATE_MAX_SIZE 9

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_filter_external_heading_update_encode(const mip_filter_external_heading_update_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_filter_external_heading_update_decode(const uint8_t *data, size_t len,
                                                       mip_filter_external_heading_update_t *out,
                                                       mip_decode_error_t *err);

/* ---- heading_update_control (command): Heading update control */
#define MIP_FILTER_HEADING_UPDATE_CONTROL_DESCRIPTOR 0x18

/** Heading update control. Select the aiding source(s) of filter heading updates. */
typedef struct {
    mip_function_selector_t function;   /* function selector (write, read, save, load, default) */
    bool has_source;                    /* source is present */
    mip_heading_update_source_t source; /* Heading aiding source (the manual's "Enable Flag"). */
} mip_filter_heading_update_control_t;

/* Largest encoded data (after the field header). */
#define MIP_FILTER_HEADING_UPDATE_CONTROL_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_filter_heading_update_control_encode(const mip_filter_heading_update_control_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_filter_heading_update_control_decode(const uint8_t *data, size_t len,
                                                      mip_filter_heading_update_control_t *out,
                                                      mip_decode_error_t *err);

/* ---- heading_update_control_response (response): Heading update control (response) */
#define MIP_FILTER_HEADING_UPDATE_CONTROL_RESPONSE_DESCRIPTOR 0x87

/** Heading update control (response). Current heading update source (reply to read). */
typedef struct {
    mip_heading_update_source_t source; /* Heading aiding source. */
} mip_filter_heading_update_control_response_t;

/* Largest encoded data (after the field header). */
#define MIP_FILTER_HEADING_UPDATE_CONTROL_RESPONSE_MAX_SIZE 1

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t
mip_filter_heading_update_control_response_encode(const mip_filter_heading_update_control_response_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t
mip_filter_heading_update_control_response_decode(const uint8_t *data, size_t len,
                                                  mip_filter_heading_update_control_response_t *out,
                                                  mip_decode_error_t *err);

/* ---- auto_init_control (command): Auto-initialization control */
#define MIP_FILTER_AUTO_INIT_CONTROL_DESCRIPTOR 0x19

/** Auto-initialization control. Enable or disable automatic filter initialisation at startup (needs a valid
 * heading source; otherwise use Set initial heading or Set initial attitude). */
typedef struct {
    mip_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_enable;                  /* enable is present */
    uint8_t enable;                   /* 0 disables, 1 enables auto-initialisation. */
} mip_filter_auto_init_control_t;

/* Largest encoded data (after the field header). */
#define MIP_FILTER_AUTO_INIT_CONTROL_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_filter_auto_init_control_encode(const mip_filter_auto_init_control_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_filter_auto_init_control_decode(const uint8_t *data, size_t len,
                                                 mip_filter_auto_init_control_t *out,
                                                 mip_decode_error_t *err);

/* ---- auto_init_control_response (response): Auto-initialization control (response) */
#define MIP_FILTER_AUTO_INIT_CONTROL_RESPONSE_DESCRIPTOR 0x88

/** Auto-initialization control (response). Current auto-initialisation setting (reply to read). */
typedef struct {
    uint8_t enable; /* 0 disabled, 1 enabled. */
} mip_filter_auto_init_control_response_t;

/* Largest encoded data (after the field header). */
#define MIP_FILTER_AUTO_INIT_CONTROL_RESPONSE_MAX_SIZE 1

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t
mip_filter_auto_init_control_response_encode(const mip_filter_auto_init_control_response_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_filter_auto_init_control_response_decode(const uint8_t *data, size_t len,
                                                          mip_filter_auto_init_control_response_t *out,
                                                          mip_decode_error_t *err);

/* ---- accel_noise (command): Accelerometer noise standard deviation */
#define MIP_FILTER_ACCEL_NOISE_DESCRIPTOR 0x1A

/** Accelerometer noise standard deviation. Expected accelerometer (process) noise, 1-sigma per axis, used to
 * tune the filter. Each value must be greater than 0. */
typedef struct {
    mip_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_noise;                   /* noise is present */
    float noise[3];                   /* (x, y, z) accelerometer noise 1-sigma. [m/s^2] */
} mip_filter_accel_noise_t;

/* Largest encoded data (after the field header). */
#define MIP_FILTER_ACCEL_NOISE_MAX_SIZE 13

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_filter_accel_noise_encode(const mip_filter_accel_noise_t *value, uint8_t *buf, size_t cap,
                                           size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_filter_accel_noise_decode(const uint8_t *data, size_t len, mip_filter_accel_noise_t *out,
                                           mip_decode_error_t *err);

/* ---- accel_noise_response (response): Accelerometer noise standard deviation (response) */
#define MIP_FILTER_ACCEL_NOISE_RESPONSE_DESCRIPTOR 0x89

/** Accelerometer noise standard deviation (response). Current accelerometer noise 1-sigma (reply to read). */
typedef struct {
    float noise[3]; /* (x, y, z) accelerometer noise 1-sigma. [m/s^2] */
} mip_filter_accel_noise_response_t;

/* Largest encoded data (after the field header). */
#define MIP_FILTER_ACCEL_NOISE_RESPONSE_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_filter_accel_noise_response_encode(const mip_filter_accel_noise_response_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_filter_accel_noise_response_decode(const uint8_t *data, size_t len,
                                                    mip_filter_accel_noise_response_t *out,
                                                    mip_decode_error_t *err);

/* ---- gyro_noise (command): Gyroscope noise standard deviation */
#define MIP_FILTER_GYRO_NOISE_DESCRIPTOR 0x1B

/** Gyroscope noise standard deviation. Expected gyro (process) noise, 1-sigma per axis, used to tune the
 * filter. Each value must be greater than 0. */
typedef struct {
    mip_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_noise;                   /* noise is present */
    float noise[3];                   /* (x, y, z) gyro noise 1-sigma. [rad/s] */
} mip_filter_gyro_noise_t;

/* Largest encoded data (after the field header). */
#define MIP_FILTER_GYRO_NOISE_MAX_SIZE 13

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_filter_gyro_noise_encode(const mip_filter_gyro_noise_t *value, uint8_t *buf, size_t cap,
                                          size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_filter_gyro_noise_decode(const uint8_t *data, size_t len, mip_filter_gyro_noise_t *out,
                                          mip_decode_error_t *err);

/* ---- gyro_noise_response (response): Gyroscope noise standard deviation (response) */
#define MIP_FILTER_GYRO_NOISE_RESPONSE_DESCRIPTOR 0x8A

/** Gyroscope noise standard deviation (response). Current gyro noise 1-sigma (reply to read). */
typedef struct {
    float noise[3]; /* (x, y, z) gyro noise 1-sigma. [rad/s] */
} mip_filter_gyro_noise_response_t;

/* Largest encoded data (after the field header). */
#define MIP_FILTER_GYRO_NOISE_RESPONSE_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_filter_gyro_noise_response_encode(const mip_filter_gyro_noise_response_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_filter_gyro_noise_response_decode(const uint8_t *data, size_t len,
                                                   mip_filter_gyro_noise_response_t *out,
                                                   mip_decode_error_t *err);

/* ---- accel_bias_model (command): Accelerometer bias model parameters */
#define MIP_FILTER_ACCEL_BIAS_MODEL_DESCRIPTOR 0x1C

/** Accelerometer bias model parameters. First-order (Gauss-Markov) accelerometer bias model: time constant
 * inverse (beta) and bias noise 1-sigma per axis. Noise values must be greater than 0. */
typedef struct {
    mip_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_beta;                    /* beta is present */
    float beta[3];                    /* (x, y, z) accelerometer bias beta. [1/s] */
    bool has_noise;                   /* noise is present */
    float noise[3];                   /* (x, y, z) accelerometer bias noise 1-sigma. [m/s^2] */
} mip_filter_accel_bias_model_t;

/* Largest encoded data (after the field header). */
#define MIP_FILTER_ACCEL_BIAS_MODEL_MAX_SIZE 25

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_filter_accel_bias_model_encode(const mip_filter_accel_bias_model_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_filter_accel_bias_model_decode(const uint8_t *data, size_t len,
                                                mip_filter_accel_bias_model_t *out, mip_decode_error_t *err);

/* ---- accel_bias_model_response (response): Accelerometer bias model parameters (response) */
#define MIP_FILTER_ACCEL_BIAS_MODEL_RESPONSE_DESCRIPTOR 0x8B

/** Accelerometer bias model parameters (response). Current accelerometer bias model (reply to read). */
typedef struct {
    float beta[3];  /* (x, y, z) accelerometer bias beta. [1/s] */
    float noise[3]; /* (x, y, z) accelerometer bias noise 1-sigma. [m/s^2] */
} mip_filter_accel_bias_model_response_t;

/* Largest encoded data (after the field header). */
#define MIP_FILTER_ACCEL_BIAS_MODEL_RESPONSE_MAX_SIZE 24

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_filter_accel_bias_model_response_encode(const mip_filter_accel_bias_model_response_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_filter_accel_bias_model_response_decode(const uint8_t *data, size_t len,
                                                         mip_filter_accel_bias_model_response_t *out,
                                                         mip_decode_error_t *err);

/* ---- gyro_bias_model (command): Gyroscope bias model parameters */
#define MIP_FILTER_GYRO_BIAS_MODEL_DESCRIPTOR 0x1D

/** Gyroscope bias model parameters. First-order (Gauss-Markov) gyro bias model: time constant inverse (beta)
 * and bias noise 1-sigma per axis. Noise values must be greater than 0. */
typedef struct {
    mip_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_beta;                    /* beta is present */
    float beta[3];                    /* (x, y, z) gyro bias beta. [1/s] */
    bool has_noise;                   /* noise is present */
    float noise[3];                   /* (x, y, z) gyro bias noise 1-sigma. [rad/s] */
} mip_filter_gyro_bias_model_t;

/* Largest encoded data (after the field header). */
#define MIP_FILTER_GYRO_BIAS_MODEL_MAX_SIZE 25

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_filter_gyro_bias_model_encode(const mip_filter_gyro_bias_model_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_filter_gyro_bias_model_decode(const uint8_t *data, size_t len,
                                               mip_filter_gyro_bias_model_t *out, mip_decode_error_t *err);

/* ---- gyro_bias_model_response (response): Gyroscope bias model parameters (response) */
#define MIP_FILTER_GYRO_BIAS_MODEL_RESPONSE_DESCRIPTOR 0x8C

/** Gyroscope bias model parameters (response). Current gyro bias model (reply to read). */
typedef struct {
    float beta[3];  /* (x, y, z) gyro bias beta. [1/s] */
    float noise[3]; /* (x, y, z) gyro bias noise 1-sigma. [rad/s] */
} mip_filter_gyro_bias_model_response_t;

/* Largest encoded data (after the field header). */
#define MIP_FILTER_GYRO_BIAS_MODEL_RESPONSE_MAX_SIZE 24

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_filter_gyro_bias_model_response_encode(const mip_filter_gyro_bias_model_response_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_filter_gyro_bias_model_response_decode(const uint8_t *data, size_t len,
                                                        mip_filter_gyro_bias_model_response_t *out,
                                                        mip_decode_error_t *err);

/* ---- zupt_control (command): Zero velocity update (ZUPT) control */
#define MIP_FILTER_ZUPT_CONTROL_DESCRIPTOR 0x1E

/** Zero velocity update (ZUPT) control. Enable zero-velocity updates, applied when the GNSS velocity
 * magnitude is at or below the threshold. Negative thresholds are NACKed. */
typedef struct {
    mip_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_enable;                  /* enable is present */
    uint8_t enable;                   /* 0 disables, 1 enables ZUPTs. */
    bool has_threshold;               /* threshold is present */
    float threshold;                  /* Velocity magnitude at or below which a ZUPT is applied. [m/s] */
} mip_filter_zupt_control_t;

/* Largest encoded data (after the field header). */
#define MIP_FILTER_ZUPT_CONTROL_MAX_SIZE 6

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_filter_zupt_control_encode(const mip_filter_zupt_control_t *value, uint8_t *buf, size_t cap,
                                            size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_filter_zupt_control_decode(const uint8_t *data, size_t len, mip_filter_zupt_control_t *out,
                                            mip_decode_error_t *err);

/* ---- zupt_control_response (response): Zero velocity update control (response) */
#define MIP_FILTER_ZUPT_CONTROL_RESPONSE_DESCRIPTOR 0x8D

/** Zero velocity update control (response). Current ZUPT setting (reply to read). */
typedef struct {
    uint8_t enable;  /* 0 disabled, 1 enabled. */
    float threshold; /* ZUPT velocity threshold. [m/s] */
} mip_filter_zupt_control_response_t;

/* Largest encoded data (after the field header). */
#define MIP_FILTER_ZUPT_CONTROL_RESPONSE_MAX_SIZE 5

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_filter_zupt_control_response_encode(const mip_filter_zupt_control_response_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_filter_zupt_control_response_decode(const uint8_t *data, size_t len,
                                                     mip_filter_zupt_control_response_t *out,
                                                     mip_decode_error_t *err);

/* ---- external_heading_update_with_time (command): External heading update with timestamp */
#define MIP_FILTER_EXTERNAL_HEADING_UPDATE_WITH_TIME_DESCRIPTOR 0x1F

/** External heading update with timestamp. External heading measurement tagged with the GPS time it was
 * taken; more accurate than 0x0D,0x17 under high angular rates. Same acceptance rules as 0x0D,0x17; at most
 * 20 Hz on the GX5-45. */
typedef struct {
    double gps_tow;                   /* GPS time of week of the measurement. [s] */
    uint16_t gps_week;                /* GPS week number (not modulo 1024). [weeks] */
    float heading;                    /* Heading angle from true north, within +-pi. [rad] */
    float heading_uncertainty;        /* Heading 1-sigma uncertainty; must be greater than 0. [rad] */
    mip_external_heading_type_t type; /* True or magnetic heading. */
} mip_filter_external_heading_update_with_time_t;

/* Largest encoded data (after the field header). */
#define MIP_FILTER_EXTERNAL_HEADING_UPDATE_WITH_TIME_MAX_SIZE 19

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_filter_external_heading_update_with_time_encode(
    const mip_filter_external_heading_update_with_time_t *value, uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t
mip_filter_external_heading_update_with_time_decode(const uint8_t *data, size_t len,
                                                    mip_filter_external_heading_update_with_time_t *out,
                                                    mip_decode_error_t *err);

#ifdef __cplusplus
}
#endif

#endif
