/* 3DM Command Set (descriptor set 0x0C): one struct per field layout, with its
 * encoder and decoder. Generated from the spec: do not edit. */
#ifndef MIPC_SETS_THREEDM_H
#define MIPC_SETS_THREEDM_H

#include "mipcodec/types.h"

#ifdef __cplusplus
extern "C" {
#endif

#define MIPC_THREEDM_SET 0x0C

/* ---- event_control (command): Event control */
#define MIPC_THREEDM_EVENT_CONTROL_DESCRIPTOR 0x2B

/** Event control. Enable, disable or test an event trigger. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    uint8_t instance; /* Trigger instance; 0 applies to all configured triggers (not for read). */
    bool has_mode;    /* mode is present */
    mipc_event_control_mode_t mode; /* How to change the trigger state. */
} mipc_threedm_event_control_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_EVENT_CONTROL_MAX_SIZE 3

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_event_control_encode(const mipc_threedm_event_control_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_event_control_decode(const uint8_t *data, size_t len,
                                                mipc_threedm_event_control_t *out, mipc_decode_error_t *err);

/* ---- event_control_response (response): Event control (response) */
#define MIPC_THREEDM_EVENT_CONTROL_RESPONSE_DESCRIPTOR 0xB5

/** Event control (response). Current mode of a trigger. */
typedef struct {
    uint8_t instance;               /* Trigger instance. */
    mipc_event_control_mode_t mode; /* Trigger mode. */
} mipc_threedm_event_control_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_EVENT_CONTROL_RESPONSE_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_event_control_response_encode(const mipc_threedm_event_control_response_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_event_control_response_decode(const uint8_t *data, size_t len,
                                                         mipc_threedm_event_control_response_t *out,
                                                         mipc_decode_error_t *err);

/* ---- get_event_trigger_status (command): Get event trigger status */
#define MIPC_THREEDM_GET_EVENT_TRIGGER_STATUS_DESCRIPTOR 0x2C

/** Get event trigger status. Report the type and status of event triggers. */
typedef struct {
    uint8_t requested_count;          /* Number of entries requested; 0 requests all trigger slots. */
    uint8_t requested_instances[252]; /* Trigger instances to query. */
} mipc_threedm_get_event_trigger_status_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_GET_EVENT_TRIGGER_STATUS_MAX_SIZE 253

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_threedm_get_event_trigger_status_encode(const mipc_threedm_get_event_trigger_status_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_get_event_trigger_status_decode(const uint8_t *data, size_t len,
                                                           mipc_threedm_get_event_trigger_status_t *out,
                                                           mipc_decode_error_t *err);

/* ---- event_trigger_status (response): Event trigger status */
#define MIPC_THREEDM_EVENT_TRIGGER_STATUS_DESCRIPTOR 0xB6

/** Event trigger status. Status of the requested triggers, in the order requested (increasing if all). */
typedef struct {
    uint8_t count;                             /* Number of entries. */
    mipc_trigger_status_entry_t triggers[126]; /* The configured triggers. */
} mipc_threedm_event_trigger_status_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_EVENT_TRIGGER_STATUS_MAX_SIZE 253

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_event_trigger_status_encode(const mipc_threedm_event_trigger_status_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_event_trigger_status_decode(const uint8_t *data, size_t len,
                                                       mipc_threedm_event_trigger_status_t *out,
                                                       mipc_decode_error_t *err);

/* ---- get_event_action_status (command): Get event action status */
#define MIPC_THREEDM_GET_EVENT_ACTION_STATUS_DESCRIPTOR 0x2D

/** Get event action status. Report the type and trigger of event actions. */
typedef struct {
    uint8_t requested_count;          /* Number of entries requested; 0 requests all action slots. */
    uint8_t requested_instances[252]; /* Action instances to query. */
} mipc_threedm_get_event_action_status_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_GET_EVENT_ACTION_STATUS_MAX_SIZE 253

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_get_event_action_status_encode(const mipc_threedm_get_event_action_status_t *value,
                                                          uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_get_event_action_status_decode(const uint8_t *data, size_t len,
                                                          mipc_threedm_get_event_action_status_t *out,
                                                          mipc_decode_error_t *err);

/* ---- event_action_status (response): Event action status */
#define MIPC_THREEDM_EVENT_ACTION_STATUS_DESCRIPTOR 0xB7

/** Event action status. Status of the requested actions. */
typedef struct {
    uint8_t count;                           /* Number of entries. */
    mipc_action_status_entry_t actions[126]; /* The configured actions. */
} mipc_threedm_event_action_status_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_EVENT_ACTION_STATUS_MAX_SIZE 253

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_event_action_status_encode(const mipc_threedm_event_action_status_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_event_action_status_decode(const uint8_t *data, size_t len,
                                                      mipc_threedm_event_action_status_t *out,
                                                      mipc_decode_error_t *err);

/* ---- event_trigger_config (command): Event trigger configuration */
#define MIPC_THREEDM_EVENT_TRIGGER_CONFIG_DESCRIPTOR 0x2E

/** Event trigger configuration. Configure an event trigger (GPIO, threshold or combination). */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    uint8_t instance;         /* Trigger number; 0 applies to all instances for save, load and default. */
    bool has_type;            /* type is present */
    mipc_trigger_type_t type; /* Type of trigger. */
    bool has_parameters;      /* parameters is present */
    mipc_trigger_params_t parameters; /* Parameters of the trigger type. */
} mipc_threedm_event_trigger_config_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_EVENT_TRIGGER_CONFIG_MAX_SIZE 23

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_event_trigger_config_encode(const mipc_threedm_event_trigger_config_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_event_trigger_config_decode(const uint8_t *data, size_t len,
                                                       mipc_threedm_event_trigger_config_t *out,
                                                       mipc_decode_error_t *err);

/* ---- event_trigger_config_response (response): Event trigger configuration (response) */
#define MIPC_THREEDM_EVENT_TRIGGER_CONFIG_RESPONSE_DESCRIPTOR 0xB8

/** Event trigger configuration (response). Current configuration of a trigger. */
typedef struct {
    uint8_t instance;                 /* Trigger number. */
    mipc_trigger_type_t type;         /* Type of trigger. */
    mipc_trigger_params_t parameters; /* Parameters of the trigger type. */
} mipc_threedm_event_trigger_config_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_EVENT_TRIGGER_CONFIG_RESPONSE_MAX_SIZE 22

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_threedm_event_trigger_config_response_encode(const mipc_threedm_event_trigger_config_response_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_threedm_event_trigger_config_response_decode(const uint8_t *data, size_t len,
                                                  mipc_threedm_event_trigger_config_response_t *out,
                                                  mipc_decode_error_t *err);

/* ---- event_action_config (command): Event action configuration */
#define MIPC_THREEDM_EVENT_ACTION_CONFIG_DESCRIPTOR 0x2F

/** Event action configuration. Configure an event action (GPIO or message) and the trigger that fires it. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    uint8_t instance;        /* Action number; 0 applies to all instances for save, load and default. */
    bool has_trigger;        /* trigger is present */
    uint8_t trigger;         /* Trigger ID number. */
    bool has_type;           /* type is present */
    mipc_action_type_t type; /* Type of action. */
    bool has_parameters;     /* parameters is present */
    mipc_action_params_t parameters; /* Parameters of the action type. */
} mipc_threedm_event_action_config_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_EVENT_ACTION_CONFIG_MAX_SIZE 20

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_event_action_config_encode(const mipc_threedm_event_action_config_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_event_action_config_decode(const uint8_t *data, size_t len,
                                                      mipc_threedm_event_action_config_t *out,
                                                      mipc_decode_error_t *err);

/* ---- event_action_config_response (response): Event action configuration (response) */
#define MIPC_THREEDM_EVENT_ACTION_CONFIG_RESPONSE_DESCRIPTOR 0xB9

/** Event action configuration (response). Current configuration of an action. */
typedef struct {
    uint8_t instance;                /* Action number. */
    uint8_t trigger;                 /* Trigger ID number. */
    mipc_action_type_t type;         /* Type of action. */
    mipc_action_params_t parameters; /* Parameters of the action type. */
} mipc_threedm_event_action_config_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_EVENT_ACTION_CONFIG_RESPONSE_MAX_SIZE 19

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_threedm_event_action_config_response_encode(const mipc_threedm_event_action_config_response_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_threedm_event_action_config_response_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_event_action_config_response_t *out,
                                                 mipc_decode_error_t *err);

/* ---- device_startup_settings (command, 2 per-device variants): Device startup settings */
#define MIPC_THREEDM_DEVICE_STARTUP_SETTINGS_DESCRIPTOR 0x30

/** Device startup settings (gx5_45). Save all current settings as the startup settings, load the saved
 * startup settings, or reset all settings to the factory defaults. Saving may briefly disturb data output and
 * can take up to a second. */
typedef struct {
    mipc_function_selector_t function; /* function selector (read, save, load, default) */
} mipc_threedm_device_startup_settings_gx5_45_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_DEVICE_STARTUP_SETTINGS_GX5_45_MAX_SIZE 1

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_threedm_device_startup_settings_gx5_45_encode(const mipc_threedm_device_startup_settings_gx5_45_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_threedm_device_startup_settings_gx5_45_decode(const uint8_t *data, size_t len,
                                                   mipc_threedm_device_startup_settings_gx5_45_t *out,
                                                   mipc_decode_error_t *err);

/** Device startup settings (cv7_ins). Save all current settings as the startup settings, load the saved
 * startup settings, or reset all settings to the factory defaults. Saving may briefly disturb data output and
 * can take up to a second. */
typedef struct {
    mipc_function_selector_t function; /* function selector (save, load, default) */
} mipc_threedm_device_startup_settings_cv7_ins_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_DEVICE_STARTUP_SETTINGS_CV7_INS_MAX_SIZE 1

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_device_startup_settings_cv7_ins_encode(
    const mipc_threedm_device_startup_settings_cv7_ins_t *value, uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_threedm_device_startup_settings_cv7_ins_decode(const uint8_t *data, size_t len,
                                                    mipc_threedm_device_startup_settings_cv7_ins_t *out,
                                                    mipc_decode_error_t *err);

/* ---- sensor_to_vehicle_euler (command): Sensor-to-vehicle frame transformation (Euler) */
#define MIPC_THREEDM_SENSOR_TO_VEHICLE_EULER_DESCRIPTOR 0x31

/** Sensor-to-vehicle frame transformation (Euler). Mounting angles of the sensor in the vehicle frame as
 * roll, pitch and yaw: the transformation of vectors from the sensor frame to the vehicle frame (the inverse
 * of the rotation used by older products). Applied to the IMU and estimation filter outputs; changing it
 * resets the low-pass, complementary and estimation filters. Read-back angles may differ but are equivalent.
 */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_roll;                     /* roll is present */
    float roll;                        /* Roll angle. [rad] */
    bool has_pitch;                    /* pitch is present */
    float pitch;                       /* Pitch angle. [rad] */
    bool has_yaw;                      /* yaw is present */
    float yaw;                         /* Yaw angle. [rad] */
} mipc_threedm_sensor_to_vehicle_euler_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_SENSOR_TO_VEHICLE_EULER_MAX_SIZE 13

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_sensor_to_vehicle_euler_encode(const mipc_threedm_sensor_to_vehicle_euler_t *value,
                                                          uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_sensor_to_vehicle_euler_decode(const uint8_t *data, size_t len,
                                                          mipc_threedm_sensor_to_vehicle_euler_t *out,
                                                          mipc_decode_error_t *err);

/* ---- sensor_to_vehicle_euler_response (response): Sensor-to-vehicle frame transformation (Euler) (response)
 */
#define MIPC_THREEDM_SENSOR_TO_VEHICLE_EULER_RESPONSE_DESCRIPTOR 0xB1

/** Sensor-to-vehicle frame transformation (Euler) (response). Current sensor-to-vehicle transformation as
 * Euler angles. */
typedef struct {
    float roll;  /* Roll angle. [rad] */
    float pitch; /* Pitch angle. [rad] */
    float yaw;   /* Yaw angle. [rad] */
} mipc_threedm_sensor_to_vehicle_euler_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_SENSOR_TO_VEHICLE_EULER_RESPONSE_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_sensor_to_vehicle_euler_response_encode(
    const mipc_threedm_sensor_to_vehicle_euler_response_t *value, uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_threedm_sensor_to_vehicle_euler_response_decode(const uint8_t *data, size_t len,
                                                     mipc_threedm_sensor_to_vehicle_euler_response_t *out,
                                                     mipc_decode_error_t *err);

/* ---- sensor_to_vehicle_quaternion (command): Sensor-to-vehicle frame transformation (quaternion) */
#define MIPC_THREEDM_SENSOR_TO_VEHICLE_QUATERNION_DESCRIPTOR 0x32

/** Sensor-to-vehicle frame transformation (quaternion). Sensor-to-vehicle transformation as a unit quaternion
 * [w, i, j, k]. Same effects as the Euler form; a quaternion read back may differ but is equivalent. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_q;                        /* q is present */
    float q[4];                        /* Unit quaternion of the transformation, [w, i, j, k]. */
} mipc_threedm_sensor_to_vehicle_quaternion_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_SENSOR_TO_VEHICLE_QUATERNION_MAX_SIZE 17

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_threedm_sensor_to_vehicle_quaternion_encode(const mipc_threedm_sensor_to_vehicle_quaternion_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_threedm_sensor_to_vehicle_quaternion_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_sensor_to_vehicle_quaternion_t *out,
                                                 mipc_decode_error_t *err);

/* ---- sensor_to_vehicle_quaternion_response (response): Sensor-to-vehicle frame transformation (quaternion)
 * (response) */
#define MIPC_THREEDM_SENSOR_TO_VEHICLE_QUATERNION_RESPONSE_DESCRIPTOR 0xB2

/** Sensor-to-vehicle frame transformation (quaternion) (response). Current sensor-to-vehicle transformation
 * as a unit quaternion. */
typedef struct {
    float q[4]; /* Unit quaternion of the transformation, [w, i, j, k]. */
} mipc_threedm_sensor_to_vehicle_quaternion_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_SENSOR_TO_VEHICLE_QUATERNION_RESPONSE_MAX_SIZE 16

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_sensor_to_vehicle_quaternion_response_encode(
    const mipc_threedm_sensor_to_vehicle_quaternion_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_sensor_to_vehicle_quaternion_response_decode(
    const uint8_t *data, size_t len, mipc_threedm_sensor_to_vehicle_quaternion_response_t *out,
    mipc_decode_error_t *err);

/* ---- sensor_to_vehicle_dcm (command): Sensor-to-vehicle frame transformation (direction cosine matrix) */
#define MIPC_THREEDM_SENSOR_TO_VEHICLE_DCM_DESCRIPTOR 0x33

/** Sensor-to-vehicle frame transformation (direction cosine matrix). Sensor-to-vehicle transformation as a
 * 3x3 direction cosine matrix in row-major order (v_vehicle = M v_sensor). Same effects as the Euler form. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_dcm;                      /* dcm is present */
    float dcm[9];                      /* Direction cosine matrix, row-major. */
} mipc_threedm_sensor_to_vehicle_dcm_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_SENSOR_TO_VEHICLE_DCM_MAX_SIZE 37

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_sensor_to_vehicle_dcm_encode(const mipc_threedm_sensor_to_vehicle_dcm_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_sensor_to_vehicle_dcm_decode(const uint8_t *data, size_t len,
                                                        mipc_threedm_sensor_to_vehicle_dcm_t *out,
                                                        mipc_decode_error_t *err);

/* ---- sensor_to_vehicle_dcm_response (response): Sensor-to-vehicle frame transformation (DCM) (response) */
#define MIPC_THREEDM_SENSOR_TO_VEHICLE_DCM_RESPONSE_DESCRIPTOR 0xB3

/** Sensor-to-vehicle frame transformation (DCM) (response). Current sensor-to-vehicle transformation as a
 * row-major direction cosine matrix. */
typedef struct {
    float dcm[9]; /* Direction cosine matrix, row-major. */
} mipc_threedm_sensor_to_vehicle_dcm_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_SENSOR_TO_VEHICLE_DCM_RESPONSE_MAX_SIZE 36

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_threedm_sensor_to_vehicle_dcm_response_encode(const mipc_threedm_sensor_to_vehicle_dcm_response_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_threedm_sensor_to_vehicle_dcm_response_decode(const uint8_t *data, size_t len,
                                                   mipc_threedm_sensor_to_vehicle_dcm_response_t *out,
                                                   mipc_decode_error_t *err);

/* ---- accel_bias (command, 2 per-device variants): Accelerometer bias */
#define MIPC_THREEDM_ACCEL_BIAS_DESCRIPTOR 0x37

/** Accelerometer bias (gx5_45). User accelerometer bias in the sensor frame, subtracted from the scaled
 * (calibrated) accelerometer output. */
typedef struct {
    mipc_function_selector_t
        function;  /* function selector (write, read, save, load, default, write_no_ack) */
    bool has_bias; /* bias is present */
    float bias[3]; /* X, Y, Z accelerometer bias. [g] */
} mipc_threedm_accel_bias_gx5_45_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_ACCEL_BIAS_GX5_45_MAX_SIZE 13

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_accel_bias_gx5_45_encode(const mipc_threedm_accel_bias_gx5_45_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_accel_bias_gx5_45_decode(const uint8_t *data, size_t len,
                                                    mipc_threedm_accel_bias_gx5_45_t *out,
                                                    mipc_decode_error_t *err);

/** Accelerometer bias (cv7_ins). User accelerometer bias in the sensor frame, subtracted from the scaled
 * (calibrated) accelerometer output. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_bias;                     /* bias is present */
    float bias[3];                     /* X, Y, Z accelerometer bias in the sensor frame. [g] */
} mipc_threedm_accel_bias_cv7_ins_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_ACCEL_BIAS_CV7_INS_MAX_SIZE 13

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_accel_bias_cv7_ins_encode(const mipc_threedm_accel_bias_cv7_ins_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_accel_bias_cv7_ins_decode(const uint8_t *data, size_t len,
                                                     mipc_threedm_accel_bias_cv7_ins_t *out,
                                                     mipc_decode_error_t *err);

/* ---- accel_bias_response (response): Accelerometer bias (response) */
#define MIPC_THREEDM_ACCEL_BIAS_RESPONSE_DESCRIPTOR 0x9A

/** Accelerometer bias (response). Current user accelerometer bias. */
typedef struct {
    float bias[3]; /* X, Y, Z accelerometer bias in the sensor frame. [g] */
} mipc_threedm_accel_bias_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_ACCEL_BIAS_RESPONSE_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_accel_bias_response_encode(const mipc_threedm_accel_bias_response_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_accel_bias_response_decode(const uint8_t *data, size_t len,
                                                      mipc_threedm_accel_bias_response_t *out,
                                                      mipc_decode_error_t *err);

/* ---- gyro_bias (command, 2 per-device variants): Gyro bias */
#define MIPC_THREEDM_GYRO_BIAS_DESCRIPTOR 0x38

/** Gyro bias (gx5_45). User gyro bias in the sensor frame, subtracted from the scaled (calibrated) angular
 * rate output. */
typedef struct {
    mipc_function_selector_t
        function;  /* function selector (write, read, save, load, default, write_no_ack) */
    bool has_bias; /* bias is present */
    float bias[3]; /* X, Y, Z gyro bias. [rad/s] */
} mipc_threedm_gyro_bias_gx5_45_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_GYRO_BIAS_GX5_45_MAX_SIZE 13

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_gyro_bias_gx5_45_encode(const mipc_threedm_gyro_bias_gx5_45_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_gyro_bias_gx5_45_decode(const uint8_t *data, size_t len,
                                                   mipc_threedm_gyro_bias_gx5_45_t *out,
                                                   mipc_decode_error_t *err);

/** Gyro bias (cv7_ins). User gyro bias in the sensor frame, subtracted from the scaled (calibrated) angular
 * rate output. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_bias;                     /* bias is present */
    float bias[3];                     /* X, Y, Z gyro bias in the sensor frame. [rad/s] */
} mipc_threedm_gyro_bias_cv7_ins_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_GYRO_BIAS_CV7_INS_MAX_SIZE 13

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_gyro_bias_cv7_ins_encode(const mipc_threedm_gyro_bias_cv7_ins_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_gyro_bias_cv7_ins_decode(const uint8_t *data, size_t len,
                                                    mipc_threedm_gyro_bias_cv7_ins_t *out,
                                                    mipc_decode_error_t *err);

/* ---- gyro_bias_response (response): Gyro bias (response) */
#define MIPC_THREEDM_GYRO_BIAS_RESPONSE_DESCRIPTOR 0x9B

/** Gyro bias (response). Current user gyro bias; also the reply to Capture Gyro Bias (0x39), carrying the
 * newly captured bias. */
typedef struct {
    float bias[3]; /* X, Y, Z gyro bias in the sensor frame. [rad/s] */
} mipc_threedm_gyro_bias_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_GYRO_BIAS_RESPONSE_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_gyro_bias_response_encode(const mipc_threedm_gyro_bias_response_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_gyro_bias_response_decode(const uint8_t *data, size_t len,
                                                     mipc_threedm_gyro_bias_response_t *out,
                                                     mipc_decode_error_t *err);

/* ---- capture_gyro_bias (command): Capture gyro bias */
#define MIPC_THREEDM_CAPTURE_GYRO_BIAS_DESCRIPTOR 0x39

/** Capture gyro bias. Average the gyro output for the given time and write the result to the gyro bias (in
 * RAM only; save it with Gyro Bias 0x38). The device must be stationary, with minimal vibration. The reply
 * carries the captured bias (0x9B). */
typedef struct {
    uint16_t averaging_time_ms; /* Sampling time, 1000 to 30000 ms. [ms] */
} mipc_threedm_capture_gyro_bias_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_CAPTURE_GYRO_BIAS_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_capture_gyro_bias_encode(const mipc_threedm_capture_gyro_bias_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_capture_gyro_bias_decode(const uint8_t *data, size_t len,
                                                    mipc_threedm_capture_gyro_bias_t *out,
                                                    mipc_decode_error_t *err);

/* ---- mag_hard_iron_offset (command, 2 per-device variants): Magnetometer hard iron offset */
#define MIPC_THREEDM_MAG_HARD_IRON_OFFSET_DESCRIPTOR 0x3A

/** Magnetometer hard iron offset (gx5_45). User magnetometer hard iron offset in the sensor frame, subtracted
 * from the scaled magnetometer output. Determined from calibration data after installation (MicroStrain tools
 * or in-run auto-calibration where supported). Default [0, 0, 0]. */
typedef struct {
    mipc_function_selector_t
        function;    /* function selector (write, read, save, load, default, write_no_ack) */
    bool has_offset; /* offset is present */
    float offset[3]; /* X, Y, Z hard iron offset. [gauss] */
} mipc_threedm_mag_hard_iron_offset_gx5_45_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_MAG_HARD_IRON_OFFSET_GX5_45_MAX_SIZE 13

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_threedm_mag_hard_iron_offset_gx5_45_encode(const mipc_threedm_mag_hard_iron_offset_gx5_45_t *value,
                                                uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_mag_hard_iron_offset_gx5_45_decode(const uint8_t *data, size_t len,
                                                              mipc_threedm_mag_hard_iron_offset_gx5_45_t *out,
                                                              mipc_decode_error_t *err);

/** Magnetometer hard iron offset (cv7_ins). User magnetometer hard iron offset in the sensor frame,
 * subtracted from the scaled magnetometer output. Determined from calibration data after installation
 * (MicroStrain tools or in-run auto-calibration where supported). Default [0, 0, 0]. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_offset;                   /* offset is present */
    float offset[3];                   /* X, Y, Z hard iron offset in the sensor frame. [gauss] */
} mipc_threedm_mag_hard_iron_offset_cv7_ins_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_MAG_HARD_IRON_OFFSET_CV7_INS_MAX_SIZE 13

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_threedm_mag_hard_iron_offset_cv7_ins_encode(const mipc_threedm_mag_hard_iron_offset_cv7_ins_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_threedm_mag_hard_iron_offset_cv7_ins_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_mag_hard_iron_offset_cv7_ins_t *out,
                                                 mipc_decode_error_t *err);

/* ---- mag_hard_iron_offset_response (response): Magnetometer hard iron offset (response) */
#define MIPC_THREEDM_MAG_HARD_IRON_OFFSET_RESPONSE_DESCRIPTOR 0x9C

/** Magnetometer hard iron offset (response). Current magnetometer hard iron offset. */
typedef struct {
    float offset[3]; /* X, Y, Z hard iron offset in the sensor frame. [gauss] */
} mipc_threedm_mag_hard_iron_offset_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_MAG_HARD_IRON_OFFSET_RESPONSE_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_threedm_mag_hard_iron_offset_response_encode(const mipc_threedm_mag_hard_iron_offset_response_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_threedm_mag_hard_iron_offset_response_decode(const uint8_t *data, size_t len,
                                                  mipc_threedm_mag_hard_iron_offset_response_t *out,
                                                  mipc_decode_error_t *err);

/* ---- mag_soft_iron_matrix (command, 2 per-device variants): Magnetometer soft iron matrix */
#define MIPC_THREEDM_MAG_SOFT_IRON_MATRIX_DESCRIPTOR 0x3B

/** Magnetometer soft iron matrix (gx5_45). User magnetometer soft iron compensation matrix (row-major),
 * applied to the scaled magnetometer output. Determined from calibration data after installation. Default:
 * identity. */
typedef struct {
    mipc_function_selector_t
        function;    /* function selector (write, read, save, load, default, write_no_ack) */
    bool has_matrix; /* matrix is present */
    float matrix[9]; /* Soft iron matrix m11..m33, row-major (dimensionless). */
} mipc_threedm_mag_soft_iron_matrix_gx5_45_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_MAG_SOFT_IRON_MATRIX_GX5_45_MAX_SIZE 37

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_threedm_mag_soft_iron_matrix_gx5_45_encode(const mipc_threedm_mag_soft_iron_matrix_gx5_45_t *value,
                                                uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_mag_soft_iron_matrix_gx5_45_decode(const uint8_t *data, size_t len,
                                                              mipc_threedm_mag_soft_iron_matrix_gx5_45_t *out,
                                                              mipc_decode_error_t *err);

/** Magnetometer soft iron matrix (cv7_ins). User magnetometer soft iron compensation matrix (row-major),
 * applied to the scaled magnetometer output. Determined from calibration data after installation. Default:
 * identity. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_matrix;                   /* matrix is present */
    float matrix[9];                   /* Soft iron matrix, row-major (dimensionless). */
} mipc_threedm_mag_soft_iron_matrix_cv7_ins_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_MAG_SOFT_IRON_MATRIX_CV7_INS_MAX_SIZE 37

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_threedm_mag_soft_iron_matrix_cv7_ins_encode(const mipc_threedm_mag_soft_iron_matrix_cv7_ins_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_threedm_mag_soft_iron_matrix_cv7_ins_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_mag_soft_iron_matrix_cv7_ins_t *out,
                                                 mipc_decode_error_t *err);

/* ---- mag_soft_iron_matrix_response (response): Magnetometer soft iron matrix (response) */
#define MIPC_THREEDM_MAG_SOFT_IRON_MATRIX_RESPONSE_DESCRIPTOR 0x9D

/** Magnetometer soft iron matrix (response). Current magnetometer soft iron matrix, row-major. */
typedef struct {
    float matrix[9]; /* Soft iron matrix, row-major (dimensionless). */
} mipc_threedm_mag_soft_iron_matrix_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_MAG_SOFT_IRON_MATRIX_RESPONSE_MAX_SIZE 36

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_threedm_mag_soft_iron_matrix_response_encode(const mipc_threedm_mag_soft_iron_matrix_response_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_threedm_mag_soft_iron_matrix_response_decode(const uint8_t *data, size_t len,
                                                  mipc_threedm_mag_soft_iron_matrix_response_t *out,
                                                  mipc_decode_error_t *err);

/* ---- coning_sculling_enable (command): Coning and sculling enable */
#define MIPC_THREEDM_CONING_SCULLING_ENABLE_DESCRIPTOR 0x3E

/** Coning and sculling enable. Enable or disable coning and sculling compensation (enabled by default). */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_enable;                   /* enable is present */
    bool enable; /* True enables coning and sculling compensation (0x01), false disables it (0x00). */
} mipc_threedm_coning_sculling_enable_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_CONING_SCULLING_ENABLE_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_coning_sculling_enable_encode(const mipc_threedm_coning_sculling_enable_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_coning_sculling_enable_decode(const uint8_t *data, size_t len,
                                                         mipc_threedm_coning_sculling_enable_t *out,
                                                         mipc_decode_error_t *err);

/* ---- coning_sculling_enable_response (response): Coning and sculling enable (response) */
#define MIPC_THREEDM_CONING_SCULLING_ENABLE_RESPONSE_DESCRIPTOR 0x9E

/** Coning and sculling enable (response). Current coning and sculling compensation setting. */
typedef struct {
    bool enable; /* True if coning and sculling compensation is enabled. */
} mipc_threedm_coning_sculling_enable_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_CONING_SCULLING_ENABLE_RESPONSE_MAX_SIZE 1

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_coning_sculling_enable_response_encode(
    const mipc_threedm_coning_sculling_enable_response_t *value, uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_threedm_coning_sculling_enable_response_decode(const uint8_t *data, size_t len,
                                                    mipc_threedm_coning_sculling_enable_response_t *out,
                                                    mipc_decode_error_t *err);

/* ---- uart_baudrate (command): UART baud rate */
#define MIPC_THREEDM_UART_BAUDRATE_DESCRIPTOR 0x40

/** UART baud rate. Baud rate of the main communication port (UART1). The ack is sent at the old rate; the new
 * rate applies after pending data is sent (up to 250 ms). Send it alone, with the device idle, and wait 250
 * ms. GX5-45 rates: 9600, 19200, 115200 (default), 230400, 460800, 921600. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_baud;                     /* baud is present */
    uint32_t baud;                     /* New baud rate; must be a rate the device supports. [bit/s] */
} mipc_threedm_uart_baudrate_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_UART_BAUDRATE_MAX_SIZE 5

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_uart_baudrate_encode(const mipc_threedm_uart_baudrate_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_uart_baudrate_decode(const uint8_t *data, size_t len,
                                                mipc_threedm_uart_baudrate_t *out, mipc_decode_error_t *err);

/* ---- uart_baudrate_response (response): UART baud rate (response) */
#define MIPC_THREEDM_UART_BAUDRATE_RESPONSE_DESCRIPTOR 0x87

/** UART baud rate (response). Current baud rate of the main port. */
typedef struct {
    uint32_t baud; /* Current baud rate. [bit/s] */
} mipc_threedm_uart_baudrate_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_UART_BAUDRATE_RESPONSE_MAX_SIZE 4

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_uart_baudrate_response_encode(const mipc_threedm_uart_baudrate_response_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_uart_baudrate_response_decode(const uint8_t *data, size_t len,
                                                         mipc_threedm_uart_baudrate_response_t *out,
                                                         mipc_decode_error_t *err);

/* ---- gpio_config (command): GPIO configuration */
#define MIPC_THREEDM_GPIO_CONFIG_DESCRIPTOR 0x41

/** GPIO configuration. Configure a user GPIO pin: the feature it serves, its behavior within that feature,
 * and its electrical mode. Features and pin modes are pin- and device-dependent (User GPIO, line 1272).
 * Configure an output feature before the pin (to avoid glitches) and an input pin before its feature.
 * Features limited to one pin move to the most recently configured pin. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    uint8_t pin;                 /* GPIO pin number from 1; 0 selects all pins for save, load and default. */
    bool has_feature;            /* feature is present */
    mipc_gpio_feature_t feature; /* What the pin is used for. */
    bool has_behavior;           /* behavior is present */
    mipc_gpio_behavior_t behavior; /* Role of the pin within the feature (meaning depends on feature). */
    bool has_pin_mode;             /* pin_mode is present */
    mipc_gpio_pin_mode_t pin_mode; /* Electrical mode of the pin. */
} mipc_threedm_gpio_config_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_GPIO_CONFIG_MAX_SIZE 5

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_gpio_config_encode(const mipc_threedm_gpio_config_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_gpio_config_decode(const uint8_t *data, size_t len,
                                              mipc_threedm_gpio_config_t *out, mipc_decode_error_t *err);

/* ---- gpio_config_response (response): GPIO configuration (response) */
#define MIPC_THREEDM_GPIO_CONFIG_RESPONSE_DESCRIPTOR 0xC1

/** GPIO configuration (response). Current configuration of a GPIO pin. */
typedef struct {
    uint8_t pin;                   /* GPIO pin number from 1. */
    mipc_gpio_feature_t feature;   /* What the pin is used for. */
    mipc_gpio_behavior_t behavior; /* Role of the pin within the feature. */
    mipc_gpio_pin_mode_t pin_mode; /* Electrical mode of the pin. */
} mipc_threedm_gpio_config_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_GPIO_CONFIG_RESPONSE_MAX_SIZE 4

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_gpio_config_response_encode(const mipc_threedm_gpio_config_response_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_gpio_config_response_decode(const uint8_t *data, size_t len,
                                                       mipc_threedm_gpio_config_response_t *out,
                                                       mipc_decode_error_t *err);

/* ---- gpio_state (command): GPIO state */
#define MIPC_THREEDM_GPIO_STATE_DESCRIPTOR 0x42

/** GPIO state. Read the physical state of a pin or set its output state. Setting has a visible effect only
 * when the pin is an output; save, load and default are not supported (use 0x0C,0x41 to set the initial
 * state). */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read) */
    uint8_t pin;                       /* GPIO pin number from 1 (not 0). */
    bool has_state;                    /* state is present */
    bool state;                        /* Pin state (true = high). */
} mipc_threedm_gpio_state_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_GPIO_STATE_MAX_SIZE 3

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_gpio_state_encode(const mipc_threedm_gpio_state_t *value, uint8_t *buf, size_t cap,
                                             size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_gpio_state_decode(const uint8_t *data, size_t len, mipc_threedm_gpio_state_t *out,
                                             mipc_decode_error_t *err);

/* ---- gpio_state_response (response): GPIO state (response) */
#define MIPC_THREEDM_GPIO_STATE_RESPONSE_DESCRIPTOR 0xC2

/** GPIO state (response). Physical state of a pin. */
typedef struct {
    uint8_t pin; /* GPIO pin number from 1. */
    bool state;  /* Pin state (true = high). */
} mipc_threedm_gpio_state_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_GPIO_STATE_RESPONSE_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_gpio_state_response_encode(const mipc_threedm_gpio_state_response_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_gpio_state_response_decode(const uint8_t *data, size_t len,
                                                      mipc_threedm_gpio_state_response_t *out,
                                                      mipc_decode_error_t *err);

/* ---- odometer_config (command): Odometer configuration */
#define MIPC_THREEDM_ODOMETER_CONFIG_DESCRIPTOR 0x43

/** Odometer configuration. Configure the hardware odometer (wheel encoder) interface: mode, scale factor and
 * its uncertainty. Distance = pulses / scaling. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_mode;                     /* mode is present */
    mipc_odometer_mode_t mode;         /* Odometer mode. */
    bool has_scaling;                  /* scaling is present */
    float scaling;        /* Encoder pulses per metre (N / (2 pi R), N pulses per revolution, R wheel radius);
                             negative if the encoder turns backwards. [pulses/m] */
    bool has_uncertainty; /* uncertainty is present */
    float uncertainty;    /* 1-sigma uncertainty of the pulses-to-distance scale. [m/m] */
} mipc_threedm_odometer_config_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_ODOMETER_CONFIG_MAX_SIZE 10

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_odometer_config_encode(const mipc_threedm_odometer_config_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_odometer_config_decode(const uint8_t *data, size_t len,
                                                  mipc_threedm_odometer_config_t *out,
                                                  mipc_decode_error_t *err);

/* ---- odometer_config_response (response): Odometer configuration (response) */
#define MIPC_THREEDM_ODOMETER_CONFIG_RESPONSE_DESCRIPTOR 0xC3

/** Odometer configuration (response). Current odometer configuration. */
typedef struct {
    mipc_odometer_mode_t mode; /* Odometer mode. */
    float scaling;             /* Encoder pulses per metre. [pulses/m] */
    float uncertainty;         /* 1-sigma uncertainty of the scale. [m/m] */
} mipc_threedm_odometer_config_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_ODOMETER_CONFIG_RESPONSE_MAX_SIZE 9

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_threedm_odometer_config_response_encode(const mipc_threedm_odometer_config_response_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_odometer_config_response_decode(const uint8_t *data, size_t len,
                                                           mipc_threedm_odometer_config_response_t *out,
                                                           mipc_decode_error_t *err);

/* ---- advanced_lowpass_filter (command): Advanced low-pass filter settings */
#define MIPC_THREEDM_ADVANCED_LOWPASS_FILTER_DESCRIPTOR 0x50

/** Advanced low-pass filter settings. Per-quantity IIR low-pass filter on the scaled IMU data (0x80: accel
 * 0x04, gyro 0x05, mag 0x06, pressure 0x17): bypass it, or set its -3 dB cutoff manually instead of half the
 * reporting rate. Deprecated on the CV7 in favour of 0x0C,0x54. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    uint8_t target_descriptor; /* Field descriptor in the sensor set (0x80) of the filtered quantity; 0 = all
                                  (CV7, not for read). */
    bool has_enable;           /* enable is present */
    bool enable;               /* Apply the low-pass filter. */
    bool has_manual;           /* manual is present */
    bool manual;               /* Use the cutoff given below; false sets it to half the reporting rate. */
    bool has_frequency;        /* frequency is present */
    uint16_t frequency; /* -3 dB cutoff frequency (at most 250 Hz on GX5-45); ignored when not manual. [Hz] */
    bool has_reserved;  /* reserved is present */
    uint8_t reserved;   /* Reserved, send 0. */
} mipc_threedm_advanced_lowpass_filter_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_ADVANCED_LOWPASS_FILTER_MAX_SIZE 7

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_advanced_lowpass_filter_encode(const mipc_threedm_advanced_lowpass_filter_t *value,
                                                          uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_advanced_lowpass_filter_decode(const uint8_t *data, size_t len,
                                                          mipc_threedm_advanced_lowpass_filter_t *out,
                                                          mipc_decode_error_t *err);

/* ---- advanced_lowpass_filter_response (response): Advanced low-pass filter settings (response) */
#define MIPC_THREEDM_ADVANCED_LOWPASS_FILTER_RESPONSE_DESCRIPTOR 0x8B

/** Advanced low-pass filter settings (response). Current low-pass filter settings of one quantity. */
typedef struct {
    uint8_t target_descriptor; /* Field descriptor of the filtered quantity. */
    bool enable;               /* True if the filter is enabled. */
    bool manual;               /* True if the cutoff was set manually. */
    uint16_t frequency;        /* -3 dB cutoff frequency (unspecified in automatic mode). [Hz] */
    uint8_t reserved;          /* Reserved; ignore. */
} mipc_threedm_advanced_lowpass_filter_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_ADVANCED_LOWPASS_FILTER_RESPONSE_MAX_SIZE 6

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_advanced_lowpass_filter_response_encode(
    const mipc_threedm_advanced_lowpass_filter_response_t *value, uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_threedm_advanced_lowpass_filter_response_decode(const uint8_t *data, size_t len,
                                                     mipc_threedm_advanced_lowpass_filter_response_t *out,
                                                     mipc_decode_error_t *err);

/* ---- complementary_filter (command): Complementary filter settings */
#define MIPC_THREEDM_COMPLEMENTARY_FILTER_DESCRIPTOR 0x51

/** Complementary filter settings. Configure the AHRS complementary filter behind the 0x80 attitude outputs
 * (matrix 0x09, quaternion 0x0A, Euler 0x0C): pitch/roll correction from the accelerometer (GX5-45: "up
 * compensation") and heading correction from the magnetometer ("north compensation"), each with a time
 * constant of 1 to 1000 s (default 10 s; out-of-range values are NACK'd). */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_pitch_roll_enable;        /* pitch_roll_enable is present */
    bool pitch_roll_enable;            /* Enable pitch/roll (up) correction. */
    bool has_heading_enable;           /* heading_enable is present */
    bool heading_enable;               /* Enable heading (north) correction; needs a magnetometer. */
    bool has_pitch_roll_time_constant; /* pitch_roll_time_constant is present */
    float pitch_roll_time_constant;    /* Time constant of the pitch/roll correction. [s] */
    bool has_heading_time_constant;    /* heading_time_constant is present */
    float heading_time_constant;       /* Time constant of the heading correction. [s] */
} mipc_threedm_complementary_filter_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_COMPLEMENTARY_FILTER_MAX_SIZE 11

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_complementary_filter_encode(const mipc_threedm_complementary_filter_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_complementary_filter_decode(const uint8_t *data, size_t len,
                                                       mipc_threedm_complementary_filter_t *out,
                                                       mipc_decode_error_t *err);

/* ---- complementary_filter_response (response): Complementary filter settings (response) */
#define MIPC_THREEDM_COMPLEMENTARY_FILTER_RESPONSE_DESCRIPTOR 0x97

/** Complementary filter settings (response). Current complementary filter settings. */
typedef struct {
    bool pitch_roll_enable;         /* Pitch/roll (up) correction enabled. */
    bool heading_enable;            /* Heading (north) correction enabled. */
    float pitch_roll_time_constant; /* Time constant of the pitch/roll correction. [s] */
    float heading_time_constant;    /* Time constant of the heading correction. [s] */
} mipc_threedm_complementary_filter_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_COMPLEMENTARY_FILTER_RESPONSE_MAX_SIZE 10

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_threedm_complementary_filter_response_encode(const mipc_threedm_complementary_filter_response_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_threedm_complementary_filter_response_decode(const uint8_t *data, size_t len,
                                                  mipc_threedm_complementary_filter_response_t *out,
                                                  mipc_decode_error_t *err);

/* ---- sensor_range (command): Sensor range */
#define MIPC_THREEDM_SENSOR_RANGE_DESCRIPTOR 0x52

/** Sensor range. Select the range (gain) of an IMU sensor; the setting values come from Get Calibrated Sensor
 * Ranges (0x0C,0x53). Other values may be NACK'd or give inaccurate data. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    mipc_sensor_range_type_t sensor;   /* Sensor to configure; all only for save, load and default. */
    bool has_setting;                  /* setting is present */
    uint8_t setting;                   /* Range setting value (from 0x0C,0x53). */
} mipc_threedm_sensor_range_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_SENSOR_RANGE_MAX_SIZE 3

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_sensor_range_encode(const mipc_threedm_sensor_range_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_sensor_range_decode(const uint8_t *data, size_t len,
                                               mipc_threedm_sensor_range_t *out, mipc_decode_error_t *err);

/* ---- sensor_range_response (response): Sensor range (response) */
#define MIPC_THREEDM_SENSOR_RANGE_RESPONSE_DESCRIPTOR 0xD2

/** Sensor range (response). Current range setting of a sensor. */
typedef struct {
    mipc_sensor_range_type_t sensor; /* Sensor. */
    uint8_t setting;                 /* Range setting value. */
} mipc_threedm_sensor_range_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_SENSOR_RANGE_RESPONSE_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_sensor_range_response_encode(const mipc_threedm_sensor_range_response_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_sensor_range_response_decode(const uint8_t *data, size_t len,
                                                        mipc_threedm_sensor_range_response_t *out,
                                                        mipc_decode_error_t *err);

/* ---- get_calibrated_sensor_ranges (command): Get calibrated sensor ranges */
#define MIPC_THREEDM_GET_CALIBRATED_SENSOR_RANGES_DESCRIPTOR 0x53

/** Get calibrated sensor ranges. List the range settings a sensor supports, for use with Sensor Range
 * (0x0C,0x52). */
typedef struct {
    mipc_sensor_range_type_t sensor; /* Sensor to query (not all). */
} mipc_threedm_get_calibrated_sensor_ranges_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_GET_CALIBRATED_SENSOR_RANGES_MAX_SIZE 1

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_threedm_get_calibrated_sensor_ranges_encode(const mipc_threedm_get_calibrated_sensor_ranges_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_threedm_get_calibrated_sensor_ranges_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_get_calibrated_sensor_ranges_t *out,
                                                 mipc_decode_error_t *err);

/* ---- calibrated_sensor_ranges (response): Calibrated sensor ranges */
#define MIPC_THREEDM_CALIBRATED_SENSOR_RANGES_DESCRIPTOR 0xD3

/** Calibrated sensor ranges. Supported range settings of a sensor, each with its full-scale value. */
typedef struct {
    mipc_sensor_range_type_t sensor;      /* Sensor from the command. */
    uint8_t num_ranges;                   /* Number of supported ranges. */
    mipc_sensor_range_entry_t ranges[50]; /* Supported (setting, range) pairs. */
} mipc_threedm_calibrated_sensor_ranges_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_CALIBRATED_SENSOR_RANGES_MAX_SIZE 252

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_threedm_calibrated_sensor_ranges_encode(const mipc_threedm_calibrated_sensor_ranges_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_calibrated_sensor_ranges_decode(const uint8_t *data, size_t len,
                                                           mipc_threedm_calibrated_sensor_ranges_t *out,
                                                           mipc_decode_error_t *err);

/* ---- lowpass_filter (command): Low-pass anti-aliasing filter */
#define MIPC_THREEDM_LOWPASS_FILTER_DESCRIPTOR 0x54

/** Low-pass anti-aliasing filter. Final low-pass (anti-aliasing) filter of a data quantity (CV7: scaled
 * accel, gyro, mag and pressure in 0x80; compensated acceleration, angular rate and linear acceleration in
 * 0x82). In automatic mode the cutoff tracks half the quantity's message rate (0x0C,0x0F). For write, save,
 * load and default, descriptor set and/or field descriptor may be 0 for all (the field descriptor must be 0
 * if the set is 0). */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    uint8_t desc_set;                  /* Descriptor set of the filtered quantity (0 = all, not for read). */
    uint8_t field_desc; /* Field descriptor of the filtered quantity (0 = all in the set, not for read). */
    bool has_enable;    /* enable is present */
    bool enable;        /* Enable the filter. */
    bool has_manual;    /* manual is present */
    bool manual;        /* Use the given frequency; false tracks half the message rate. */
    bool has_frequency; /* frequency is present */
    float frequency;    /* Cutoff frequency (read back in automatic mode: the actual cutoff). [Hz] */
} mipc_threedm_lowpass_filter_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_LOWPASS_FILTER_MAX_SIZE 9

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_lowpass_filter_encode(const mipc_threedm_lowpass_filter_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_lowpass_filter_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_lowpass_filter_t *out,
                                                 mipc_decode_error_t *err);

/* ---- lowpass_filter_response (response): Low-pass anti-aliasing filter (response) */
#define MIPC_THREEDM_LOWPASS_FILTER_RESPONSE_DESCRIPTOR 0xD4

/** Low-pass anti-aliasing filter (response). Current anti-aliasing filter settings of a quantity. */
typedef struct {
    uint8_t desc_set;   /* Descriptor set of the filtered quantity. */
    uint8_t field_desc; /* Field descriptor of the filtered quantity. */
    bool enable;        /* True if the filter is enabled. */
    bool manual;        /* True if the frequency was set manually. */
    float frequency;    /* Cutoff frequency (the actual one in automatic mode). [Hz] */
} mipc_threedm_lowpass_filter_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_LOWPASS_FILTER_RESPONSE_MAX_SIZE 8

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_lowpass_filter_response_encode(const mipc_threedm_lowpass_filter_response_t *value,
                                                          uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_lowpass_filter_response_decode(const uint8_t *data, size_t len,
                                                          mipc_threedm_lowpass_filter_response_t *out,
                                                          mipc_decode_error_t *err);

/* ---- poll_imu_data (command): Poll IMU data */
#define MIPC_THREEDM_POLL_IMU_DATA_DESCRIPTOR 0x01

/** Poll IMU data. Poll one IMU data packet (set 0x80) with the stored or the given format. */
typedef struct {
    mipc_gx5_poll_option_t option;              /* Whether to send the ACK/NACK. */
    uint8_t num_descriptors;                    /* Number of descriptors; 0 uses the stored message format. */
    mipc_gx5_poll_descriptor_t descriptors[83]; /* Descriptors to poll, in output order. */
} mipc_threedm_poll_imu_data_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_POLL_IMU_DATA_MAX_SIZE 251

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_poll_imu_data_encode(const mipc_threedm_poll_imu_data_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_poll_imu_data_decode(const uint8_t *data, size_t len,
                                                mipc_threedm_poll_imu_data_t *out, mipc_decode_error_t *err);

/* ---- poll_gnss_data (command): Poll GNSS data */
#define MIPC_THREEDM_POLL_GNSS_DATA_DESCRIPTOR 0x02

/** Poll GNSS data. Poll one GNSS data packet (set 0x81) with the stored or the given format. */
typedef struct {
    mipc_gx5_poll_option_t option;              /* Whether to send the ACK/NACK. */
    uint8_t num_descriptors;                    /* Number of descriptors; 0 uses the stored message format. */
    mipc_gx5_poll_descriptor_t descriptors[83]; /* Descriptors to poll, in output order. */
} mipc_threedm_poll_gnss_data_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_POLL_GNSS_DATA_MAX_SIZE 251

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_poll_gnss_data_encode(const mipc_threedm_poll_gnss_data_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_poll_gnss_data_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_poll_gnss_data_t *out,
                                                 mipc_decode_error_t *err);

/* ---- poll_filter_data (command): Poll estimation filter data */
#define MIPC_THREEDM_POLL_FILTER_DATA_DESCRIPTOR 0x03

/** Poll estimation filter data. Poll one estimation filter data packet (set 0x82) with the stored or the
 * given format. */
typedef struct {
    mipc_gx5_poll_option_t option;              /* Whether to send the ACK/NACK. */
    uint8_t num_descriptors;                    /* Number of descriptors; 0 uses the stored message format. */
    mipc_gx5_poll_descriptor_t descriptors[83]; /* Descriptors to poll, in output order. */
} mipc_threedm_poll_filter_data_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_POLL_FILTER_DATA_MAX_SIZE 251

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_poll_filter_data_encode(const mipc_threedm_poll_filter_data_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_poll_filter_data_decode(const uint8_t *data, size_t len,
                                                   mipc_threedm_poll_filter_data_t *out,
                                                   mipc_decode_error_t *err);

/* ---- poll_nmea_data (command): Poll NMEA data */
#define MIPC_THREEDM_POLL_NMEA_DATA_DESCRIPTOR 0x04

/** Poll NMEA data. Poll NMEA sentences once, with the given format or (if none is given) the stored NMEA
 * message format. The sentences are sent separately as plain NMEA. */
typedef struct {
    bool suppress_ack;                      /* Do not send the ACK/NACK reply. */
    uint8_t count;                          /* Number of format entries. */
    mipc_nmea_message_t format_entries[50]; /* Sentences to produce. */
} mipc_threedm_poll_nmea_data_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_POLL_NMEA_DATA_MAX_SIZE 252

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_poll_nmea_data_encode(const mipc_threedm_poll_nmea_data_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_poll_nmea_data_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_poll_nmea_data_t *out,
                                                 mipc_decode_error_t *err);

/* ---- poll_data (command): Poll data */
#define MIPC_THREEDM_POLL_DATA_DESCRIPTOR 0x0D

/** Poll data. Poll one data packet of the given descriptor set, with the listed descriptors (in that order)
 * or, if none, the stored message format. The data comes as a separate data packet. */
typedef struct {
    uint8_t desc_set;         /* Data descriptor set to poll. */
    bool suppress_ack;        /* Do not send the ACK/NACK reply. */
    uint8_t num_descriptors;  /* Number of descriptors. */
    uint8_t descriptors[250]; /* Field descriptors, in output order. */
} mipc_threedm_poll_data_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_POLL_DATA_MAX_SIZE 253

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_poll_data_encode(const mipc_threedm_poll_data_t *value, uint8_t *buf, size_t cap,
                                            size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_poll_data_decode(const uint8_t *data, size_t len, mipc_threedm_poll_data_t *out,
                                            mipc_decode_error_t *err);

/* ---- get_imu_base_rate (command): Get IMU data base rate */
#define MIPC_THREEDM_GET_IMU_BASE_RATE_DESCRIPTOR 0x06

/** Get IMU data base rate. Get the IMU data base rate, from which message format decimations are computed. */
typedef struct {
    uint8_t unused_; /* no parameters */
} mipc_threedm_get_imu_base_rate_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_GET_IMU_BASE_RATE_MAX_SIZE 0

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_get_imu_base_rate_encode(const mipc_threedm_get_imu_base_rate_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_get_imu_base_rate_decode(const uint8_t *data, size_t len,
                                                    mipc_threedm_get_imu_base_rate_t *out,
                                                    mipc_decode_error_t *err);

/* ---- imu_base_rate (response): IMU data base rate */
#define MIPC_THREEDM_IMU_BASE_RATE_DESCRIPTOR 0x83

/** IMU data base rate. IMU data base rate. */
typedef struct {
    uint16_t rate; /* Base rate used for rate decimation calculations. [Hz] */
} mipc_threedm_imu_base_rate_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_IMU_BASE_RATE_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_imu_base_rate_encode(const mipc_threedm_imu_base_rate_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_imu_base_rate_decode(const uint8_t *data, size_t len,
                                                mipc_threedm_imu_base_rate_t *out, mipc_decode_error_t *err);

/* ---- get_gnss_base_rate (command): Get GNSS data base rate */
#define MIPC_THREEDM_GET_GNSS_BASE_RATE_DESCRIPTOR 0x07

/** Get GNSS data base rate. Get the GNSS data base rate, from which message format decimations are computed.
 */
typedef struct {
    uint8_t unused_; /* no parameters */
} mipc_threedm_get_gnss_base_rate_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_GET_GNSS_BASE_RATE_MAX_SIZE 0

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_get_gnss_base_rate_encode(const mipc_threedm_get_gnss_base_rate_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_get_gnss_base_rate_decode(const uint8_t *data, size_t len,
                                                     mipc_threedm_get_gnss_base_rate_t *out,
                                                     mipc_decode_error_t *err);

/* ---- gnss_base_rate (response): GNSS data base rate */
#define MIPC_THREEDM_GNSS_BASE_RATE_DESCRIPTOR 0x84

/** GNSS data base rate. GNSS data base rate (4 Hz on the 3DM-GX5). */
typedef struct {
    uint16_t rate; /* Base rate used for rate decimation calculations. [Hz] */
} mipc_threedm_gnss_base_rate_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_GNSS_BASE_RATE_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_gnss_base_rate_encode(const mipc_threedm_gnss_base_rate_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_gnss_base_rate_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_gnss_base_rate_t *out,
                                                 mipc_decode_error_t *err);

/* ---- get_filter_base_rate (command): Get estimation filter data base rate */
#define MIPC_THREEDM_GET_FILTER_BASE_RATE_DESCRIPTOR 0x0B

/** Get estimation filter data base rate. Get the estimation filter data base rate, from which message format
 * decimations are computed. */
typedef struct {
    uint8_t unused_; /* no parameters */
} mipc_threedm_get_filter_base_rate_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_GET_FILTER_BASE_RATE_MAX_SIZE 0

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_get_filter_base_rate_encode(const mipc_threedm_get_filter_base_rate_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_get_filter_base_rate_decode(const uint8_t *data, size_t len,
                                                       mipc_threedm_get_filter_base_rate_t *out,
                                                       mipc_decode_error_t *err);

/* ---- filter_base_rate (response): Estimation filter data base rate */
#define MIPC_THREEDM_FILTER_BASE_RATE_DESCRIPTOR 0x8A

/** Estimation filter data base rate. Estimation filter data base rate. */
typedef struct {
    uint16_t rate; /* Base rate used for rate decimation calculations. [Hz] */
} mipc_threedm_filter_base_rate_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_FILTER_BASE_RATE_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_filter_base_rate_encode(const mipc_threedm_filter_base_rate_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_filter_base_rate_decode(const uint8_t *data, size_t len,
                                                   mipc_threedm_filter_base_rate_t *out,
                                                   mipc_decode_error_t *err);

/* ---- get_base_rate (command): Get data base rate */
#define MIPC_THREEDM_GET_BASE_RATE_DESCRIPTOR 0x0E

/** Get data base rate. Get the base rate of a data descriptor set. */
typedef struct {
    uint8_t desc_set; /* Data descriptor set (must be supported). */
} mipc_threedm_get_base_rate_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_GET_BASE_RATE_MAX_SIZE 1

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_get_base_rate_encode(const mipc_threedm_get_base_rate_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_get_base_rate_decode(const uint8_t *data, size_t len,
                                                mipc_threedm_get_base_rate_t *out, mipc_decode_error_t *err);

/* ---- base_rate (response): Data base rate */
#define MIPC_THREEDM_BASE_RATE_DESCRIPTOR 0x8E

/** Data base rate. Base rate of a data descriptor set. */
typedef struct {
    uint8_t desc_set; /* Echo of the descriptor set in the command. */
    uint16_t rate;    /* Base rate; 0 means variable or unknown (data sent as it arrives). [Hz] */
} mipc_threedm_base_rate_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_BASE_RATE_MAX_SIZE 3

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_base_rate_encode(const mipc_threedm_base_rate_t *value, uint8_t *buf, size_t cap,
                                            size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_base_rate_decode(const uint8_t *data, size_t len, mipc_threedm_base_rate_t *out,
                                            mipc_decode_error_t *err);

/* ---- imu_message_format (command): IMU message format */
#define MIPC_THREEDM_IMU_MESSAGE_FORMAT_DESCRIPTOR 0x08

/** IMU message format. Set, read, save, load or reset the IMU data (0x80) message format. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_num_descriptors;          /* num_descriptors is present */
    uint8_t num_descriptors; /* Number of descriptors (0 for every function except write, which may also leave
                                it out). */
    bool has_descriptors;    /* descriptors is present */
    mipc_descriptor_rate_t
        descriptors[83]; /* Descriptors and rate decimations (decimation = base rate / desired rate). */
} mipc_threedm_imu_message_format_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_IMU_MESSAGE_FORMAT_MAX_SIZE 251

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_imu_message_format_encode(const mipc_threedm_imu_message_format_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_imu_message_format_decode(const uint8_t *data, size_t len,
                                                     mipc_threedm_imu_message_format_t *out,
                                                     mipc_decode_error_t *err);

/* ---- imu_message_format_response (response): Current IMU message format */
#define MIPC_THREEDM_IMU_MESSAGE_FORMAT_RESPONSE_DESCRIPTOR 0x80

/** Current IMU message format. The IMU data message format. */
typedef struct {
    uint8_t num_descriptors;                /* Number of descriptors. */
    mipc_descriptor_rate_t descriptors[84]; /* Descriptors and rate decimations. */
} mipc_threedm_imu_message_format_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_IMU_MESSAGE_FORMAT_RESPONSE_MAX_SIZE 253

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_threedm_imu_message_format_response_encode(const mipc_threedm_imu_message_format_response_t *value,
                                                uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_imu_message_format_response_decode(const uint8_t *data, size_t len,
                                                              mipc_threedm_imu_message_format_response_t *out,
                                                              mipc_decode_error_t *err);

/* ---- gnss_message_format (command): GNSS message format */
#define MIPC_THREEDM_GNSS_MESSAGE_FORMAT_DESCRIPTOR 0x09

/** GNSS message format. Set, read, save, load or reset the GNSS data (0x81) message format. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_num_descriptors;          /* num_descriptors is present */
    uint8_t num_descriptors; /* Number of descriptors (0 for every function except write, which may also leave
                                it out). */
    bool has_descriptors;    /* descriptors is present */
    mipc_descriptor_rate_t
        descriptors[83]; /* Descriptors and rate decimations (decimation = base rate / desired rate). */
} mipc_threedm_gnss_message_format_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_GNSS_MESSAGE_FORMAT_MAX_SIZE 251

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_gnss_message_format_encode(const mipc_threedm_gnss_message_format_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_gnss_message_format_decode(const uint8_t *data, size_t len,
                                                      mipc_threedm_gnss_message_format_t *out,
                                                      mipc_decode_error_t *err);

/* ---- gnss_message_format_response (response): Current GNSS message format */
#define MIPC_THREEDM_GNSS_MESSAGE_FORMAT_RESPONSE_DESCRIPTOR 0x81

/** Current GNSS message format. The GNSS data message format. */
typedef struct {
    uint8_t num_descriptors;                /* Number of descriptors. */
    mipc_descriptor_rate_t descriptors[84]; /* Descriptors and rate decimations. */
} mipc_threedm_gnss_message_format_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_GNSS_MESSAGE_FORMAT_RESPONSE_MAX_SIZE 253

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_threedm_gnss_message_format_response_encode(const mipc_threedm_gnss_message_format_response_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_threedm_gnss_message_format_response_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_gnss_message_format_response_t *out,
                                                 mipc_decode_error_t *err);

/* ---- filter_message_format (command): Estimation filter message format */
#define MIPC_THREEDM_FILTER_MESSAGE_FORMAT_DESCRIPTOR 0x0A

/** Estimation filter message format. Set, read, save, load or reset the estimation filter data (0x82) message
 * format. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_num_descriptors;          /* num_descriptors is present */
    uint8_t num_descriptors; /* Number of descriptors (0 for every function except write, which may also leave
                                it out). */
    bool has_descriptors;    /* descriptors is present */
    mipc_descriptor_rate_t
        descriptors[83]; /* Descriptors and rate decimations (decimation = base rate / desired rate). */
} mipc_threedm_filter_message_format_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_FILTER_MESSAGE_FORMAT_MAX_SIZE 251

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_filter_message_format_encode(const mipc_threedm_filter_message_format_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_filter_message_format_decode(const uint8_t *data, size_t len,
                                                        mipc_threedm_filter_message_format_t *out,
                                                        mipc_decode_error_t *err);

/* ---- filter_message_format_response (response): Current estimation filter message format */
#define MIPC_THREEDM_FILTER_MESSAGE_FORMAT_RESPONSE_DESCRIPTOR 0x82

/** Current estimation filter message format. The estimation filter data message format. */
typedef struct {
    uint8_t num_descriptors;                /* Number of descriptors. */
    mipc_descriptor_rate_t descriptors[84]; /* Descriptors and rate decimations. */
} mipc_threedm_filter_message_format_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_FILTER_MESSAGE_FORMAT_RESPONSE_MAX_SIZE 253

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_threedm_filter_message_format_response_encode(const mipc_threedm_filter_message_format_response_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_threedm_filter_message_format_response_decode(const uint8_t *data, size_t len,
                                                   mipc_threedm_filter_message_format_response_t *out,
                                                   mipc_decode_error_t *err);

/* ---- nmea_message_format (command): NMEA message format */
#define MIPC_THREEDM_NMEA_MESSAGE_FORMAT_DESCRIPTOR 0x0C

/** NMEA message format. Set, read, save, load or reset the list of NMEA sentences the device outputs. */
typedef struct {
    mipc_function_selector_t function;      /* function selector (write, read, save, load, default) */
    bool has_count;                         /* count is present */
    uint8_t count;                          /* Number of format entries. */
    bool has_format_entries;                /* format_entries is present */
    mipc_nmea_message_t format_entries[50]; /* Sentences, talkers, sources and decimations. */
} mipc_threedm_nmea_message_format_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_NMEA_MESSAGE_FORMAT_MAX_SIZE 252

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_nmea_message_format_encode(const mipc_threedm_nmea_message_format_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_nmea_message_format_decode(const uint8_t *data, size_t len,
                                                      mipc_threedm_nmea_message_format_t *out,
                                                      mipc_decode_error_t *err);

/* ---- nmea_message_format_response (response): Current NMEA message format */
#define MIPC_THREEDM_NMEA_MESSAGE_FORMAT_RESPONSE_DESCRIPTOR 0x8C

/** Current NMEA message format. The NMEA sentence list. */
typedef struct {
    uint8_t count;                          /* Number of format entries. */
    mipc_nmea_message_t format_entries[50]; /* Sentences, talkers, sources and decimations. */
} mipc_threedm_nmea_message_format_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_NMEA_MESSAGE_FORMAT_RESPONSE_MAX_SIZE 251

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_threedm_nmea_message_format_response_encode(const mipc_threedm_nmea_message_format_response_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_threedm_nmea_message_format_response_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_nmea_message_format_response_t *out,
                                                 mipc_decode_error_t *err);

/* ---- message_format (command): Message format */
#define MIPC_THREEDM_MESSAGE_FORMAT_DESCRIPTOR 0x0F

/** Message format. Set, read, save, load or reset the message format of a data descriptor set. Output keeps
 * the order of the list. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    uint8_t desc_set;                  /* Data descriptor set; 0 means all sets for save, load and default. */
    bool has_num_descriptors;          /* num_descriptors is present */
    uint8_t num_descriptors;           /* Number of descriptors. */
    bool has_descriptors;              /* descriptors is present */
    mipc_descriptor_rate_t descriptors[83]; /* Descriptors and decimations. */
} mipc_threedm_message_format_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_MESSAGE_FORMAT_MAX_SIZE 252

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_message_format_encode(const mipc_threedm_message_format_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_message_format_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_message_format_t *out,
                                                 mipc_decode_error_t *err);

/* ---- message_format_response (response): Current message format */
#define MIPC_THREEDM_MESSAGE_FORMAT_RESPONSE_DESCRIPTOR 0x8F

/** Current message format. The message format of a data descriptor set. */
typedef struct {
    uint8_t desc_set;                       /* Echo of the descriptor set in the command. */
    uint8_t num_descriptors;                /* Number of descriptors. */
    mipc_descriptor_rate_t descriptors[83]; /* Descriptors and decimations. */
} mipc_threedm_message_format_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_MESSAGE_FORMAT_RESPONSE_MAX_SIZE 251

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_message_format_response_encode(const mipc_threedm_message_format_response_t *value,
                                                          uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_message_format_response_decode(const uint8_t *data, size_t len,
                                                          mipc_threedm_message_format_response_t *out,
                                                          mipc_decode_error_t *err);

/* ---- factory_streaming (command): Factory streaming */
#define MIPC_THREEDM_FACTORY_STREAMING_DESCRIPTOR 0x10

/** Factory streaming. Configure every data stream with the predefined formats technical support asks for. */
typedef struct {
    mipc_factory_streaming_action_t
        action;       /* How to combine the support descriptors with the current formats. */
    uint8_t reserved; /* Reserved; set to 0x00. */
} mipc_threedm_factory_streaming_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_FACTORY_STREAMING_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_factory_streaming_encode(const mipc_threedm_factory_streaming_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_factory_streaming_decode(const uint8_t *data, size_t len,
                                                    mipc_threedm_factory_streaming_t *out,
                                                    mipc_decode_error_t *err);

/* ---- data_stream_control (command, 2 per-device variants): Data stream control */
#define MIPC_THREEDM_DATA_STREAM_CONTROL_DESCRIPTOR 0x11

/** Data stream control (gx5_45). Enable or disable continuous output of a data stream. All streams are
 * enabled by default. The enable value is used only by write. */
typedef struct {
    mipc_function_selector_t function;          /* function selector (write, read, save, load, default) */
    mipc_gx5_stream_selector_t device_selector; /* Stream to control. */
    bool has_enable;                            /* enable is present */
    uint8_t enable; /* 0x00 disable, 0x01 enable (default); ignored except for write, and may be left out by
                       the other functions. */
} mipc_threedm_data_stream_control_gx5_45_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_DATA_STREAM_CONTROL_GX5_45_MAX_SIZE 3

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_threedm_data_stream_control_gx5_45_encode(const mipc_threedm_data_stream_control_gx5_45_t *value,
                                               uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_data_stream_control_gx5_45_decode(const uint8_t *data, size_t len,
                                                             mipc_threedm_data_stream_control_gx5_45_t *out,
                                                             mipc_decode_error_t *err);

/** Data stream control (cv7_ins). Enable or disable continuous output of a data stream. All streams are
 * enabled by default. The enable value is used only by write. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    uint8_t desc_set; /* Data descriptor set of the stream; 0 means all streams for save, load and default. */
    bool has_enable;  /* enable is present */
    bool enable;      /* Enable (true) or disable (false) the stream. */
} mipc_threedm_data_stream_control_cv7_ins_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_DATA_STREAM_CONTROL_CV7_INS_MAX_SIZE 3

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_threedm_data_stream_control_cv7_ins_encode(const mipc_threedm_data_stream_control_cv7_ins_t *value,
                                                uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_data_stream_control_cv7_ins_decode(const uint8_t *data, size_t len,
                                                              mipc_threedm_data_stream_control_cv7_ins_t *out,
                                                              mipc_decode_error_t *err);

/* ---- data_stream_control_response (response, 2 per-device variants): Data stream control (response) */
#define MIPC_THREEDM_DATA_STREAM_CONTROL_RESPONSE_DESCRIPTOR 0x85

/** Data stream control (response) (gx5_45). Whether a data stream is enabled. */
typedef struct {
    mipc_gx5_stream_selector_t device_selector; /* Stream. */
    uint8_t enabled;                            /* Current enable flag: 0x00 disabled, 0x01 enabled. */
} mipc_threedm_data_stream_control_response_gx5_45_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_DATA_STREAM_CONTROL_RESPONSE_GX5_45_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_data_stream_control_response_gx5_45_encode(
    const mipc_threedm_data_stream_control_response_gx5_45_t *value, uint8_t *buf, size_t cap,
    size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_data_stream_control_response_gx5_45_decode(
    const uint8_t *data, size_t len, mipc_threedm_data_stream_control_response_gx5_45_t *out,
    mipc_decode_error_t *err);

/** Data stream control (response) (cv7_ins). Whether a data stream is enabled. */
typedef struct {
    uint8_t desc_set; /* Data descriptor set of the stream. */
    bool enabled;     /* Whether the stream is enabled. */
} mipc_threedm_data_stream_control_response_cv7_ins_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_DATA_STREAM_CONTROL_RESPONSE_CV7_INS_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_data_stream_control_response_cv7_ins_encode(
    const mipc_threedm_data_stream_control_response_cv7_ins_t *value, uint8_t *buf, size_t cap,
    size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_data_stream_control_response_cv7_ins_decode(
    const uint8_t *data, size_t len, mipc_threedm_data_stream_control_response_cv7_ins_t *out,
    mipc_decode_error_t *err);

/* ---- raw_rtcm_message (command): Raw RTCM 2.3 message */
#define MIPC_THREEDM_RAW_RTCM_MESSAGE_DESCRIPTOR 0x20

/** Raw RTCM 2.3 message. Send raw RTCM 2.3 differential corrections to the GNSS receiver (message types 1, 2,
 * 3 and 9; no RTK). A stream may be split into chunks of at most 253 bytes. */
typedef struct {
    size_t data_count; /* number of elements in data */
    uint8_t data[253]; /* Raw RTCM 2.3 bytes, passed through unchanged. */
} mipc_threedm_raw_rtcm_message_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_RAW_RTCM_MESSAGE_MAX_SIZE 253

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_raw_rtcm_message_encode(const mipc_threedm_raw_rtcm_message_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_raw_rtcm_message_decode(const uint8_t *data, size_t len,
                                                   mipc_threedm_raw_rtcm_message_t *out,
                                                   mipc_decode_error_t *err);

/* ---- gnss_constellation_settings (command): GNSS constellation settings */
#define MIPC_THREEDM_GNSS_CONSTELLATION_SETTINGS_DESCRIPTOR 0x21

/** GNSS constellation settings. Choose which satellite constellations the receiver tracks and how many
 * tracking channels each may reserve and use (32 channels in all; GLONASS and BeiDou not together). */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_max_channels;             /* max_channels is present */
    uint16_t max_channels; /* Maximum tracking channels to use in total (0 up to the available channels). */
    bool has_config_count; /* config_count is present */
    uint8_t config_count;  /* Number of constellation entries. */
    bool has_settings;     /* settings is present */
    mipc_constellation_settings_t settings[41]; /* Per-constellation settings. */
} mipc_threedm_gnss_constellation_settings_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_GNSS_CONSTELLATION_SETTINGS_MAX_SIZE 250

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_threedm_gnss_constellation_settings_encode(const mipc_threedm_gnss_constellation_settings_t *value,
                                                uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_gnss_constellation_settings_decode(const uint8_t *data, size_t len,
                                                              mipc_threedm_gnss_constellation_settings_t *out,
                                                              mipc_decode_error_t *err);

/* ---- gnss_constellation_settings_response (response): GNSS constellation settings (response) */
#define MIPC_THREEDM_GNSS_CONSTELLATION_SETTINGS_RESPONSE_DESCRIPTOR 0xA0

/** GNSS constellation settings (response). Current constellation configuration. */
typedef struct {
    uint16_t max_channels_available;            /* Tracking channels the receiver has. */
    uint16_t max_channels;                      /* Maximum tracking channels to use in total. */
    uint8_t config_count;                       /* Number of constellation entries. */
    mipc_constellation_settings_t settings[41]; /* Per-constellation settings. */
} mipc_threedm_gnss_constellation_settings_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_GNSS_CONSTELLATION_SETTINGS_RESPONSE_MAX_SIZE 251

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_gnss_constellation_settings_response_encode(
    const mipc_threedm_gnss_constellation_settings_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_gnss_constellation_settings_response_decode(
    const uint8_t *data, size_t len, mipc_threedm_gnss_constellation_settings_response_t *out,
    mipc_decode_error_t *err);

/* ---- gnss_sbas_settings (command): GNSS SBAS settings */
#define MIPC_THREEDM_GNSS_SBAS_SETTINGS_DESCRIPTOR 0x22

/** GNSS SBAS settings. Configure how SBAS satellites augment the GNSS solution: enable, options, and the SBAS
 * PRNs to search for (none listed = all). */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_enable_sbas;              /* enable_sbas is present */
    uint8_t enable_sbas;               /* 0 SBAS disabled, 1 SBAS enabled (default). */
    bool has_sbas_options;             /* sbas_options is present */
    mipc_sbas_options_t sbas_options;  /* SBAS options. */
    bool has_num_included_prns;        /* num_included_prns is present */
    uint8_t num_included_prns;         /* Number of SBAS PRNs listed; 0 includes all. */
    bool has_included_prns;            /* included_prns is present */
    uint16_t included_prns[124];       /* SBAS PRNs to search for. */
} mipc_threedm_gnss_sbas_settings_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_GNSS_SBAS_SETTINGS_MAX_SIZE 253

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_gnss_sbas_settings_encode(const mipc_threedm_gnss_sbas_settings_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_gnss_sbas_settings_decode(const uint8_t *data, size_t len,
                                                     mipc_threedm_gnss_sbas_settings_t *out,
                                                     mipc_decode_error_t *err);

/* ---- gnss_sbas_settings_response (response): GNSS SBAS settings (response) */
#define MIPC_THREEDM_GNSS_SBAS_SETTINGS_RESPONSE_DESCRIPTOR 0xA1

/** GNSS SBAS settings (response). Current SBAS configuration. */
typedef struct {
    uint8_t enable_sbas;              /* 0 SBAS disabled, 1 SBAS enabled. */
    mipc_sbas_options_t sbas_options; /* SBAS options. */
    uint8_t num_included_prns;        /* Number of SBAS PRNs listed; 0 means all. */
    uint16_t included_prns[124];      /* SBAS PRNs searched for. */
} mipc_threedm_gnss_sbas_settings_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_GNSS_SBAS_SETTINGS_RESPONSE_MAX_SIZE 252

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_threedm_gnss_sbas_settings_response_encode(const mipc_threedm_gnss_sbas_settings_response_t *value,
                                                uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_gnss_sbas_settings_response_decode(const uint8_t *data, size_t len,
                                                              mipc_threedm_gnss_sbas_settings_response_t *out,
                                                              mipc_decode_error_t *err);

/* ---- gnss_assisted_fix_control (command): GNSS assisted fix control */
#define MIPC_THREEDM_GNSS_ASSISTED_FIX_CONTROL_DESCRIPTOR 0x23

/** GNSS assisted fix control. Enable or disable assisted GNSS fix, which keeps the last fix in non-volatile
 * memory to shorten the time to first fix. Disabling it erases that memory. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_option;                   /* option is present */
    mipc_assisted_fix_option_t option; /* Assisted fix on or off. */
    bool has_flags;                    /* flags is present */
    uint8_t flags;                     /* No flags defined; set to 0xFF. */
} mipc_threedm_gnss_assisted_fix_control_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_GNSS_ASSISTED_FIX_CONTROL_MAX_SIZE 3

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_threedm_gnss_assisted_fix_control_encode(const mipc_threedm_gnss_assisted_fix_control_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_gnss_assisted_fix_control_decode(const uint8_t *data, size_t len,
                                                            mipc_threedm_gnss_assisted_fix_control_t *out,
                                                            mipc_decode_error_t *err);

/* ---- gnss_assisted_fix_control_response (response): GNSS assisted fix control (response) */
#define MIPC_THREEDM_GNSS_ASSISTED_FIX_CONTROL_RESPONSE_DESCRIPTOR 0xA2

/** GNSS assisted fix control (response). Current assisted fix setting. */
typedef struct {
    mipc_assisted_fix_option_t option; /* Assisted fix on or off. */
    uint8_t flags;                     /* Assisted fix flags. */
} mipc_threedm_gnss_assisted_fix_control_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_GNSS_ASSISTED_FIX_CONTROL_RESPONSE_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_gnss_assisted_fix_control_response_encode(
    const mipc_threedm_gnss_assisted_fix_control_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_threedm_gnss_assisted_fix_control_response_decode(const uint8_t *data, size_t len,
                                                       mipc_threedm_gnss_assisted_fix_control_response_t *out,
                                                       mipc_decode_error_t *err);

/* ---- gnss_assist_time_update (command): GNSS assist time update */
#define MIPC_THREEDM_GNSS_ASSIST_TIME_UPDATE_DESCRIPTOR 0x24

/** GNSS assist time update. Give the receiver the current GPS time right after power-up when assisted fix is
 * enabled, so it can judge whether its saved satellite information is still usable. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read) */
    bool has_tow;                      /* tow is present */
    double tow;                        /* GPS time of week. [s] */
    bool has_week_number;              /* week_number is present */
    uint16_t week_number;              /* GPS week number. */
    bool has_accuracy;                 /* accuracy is present */
    float accuracy;                    /* Accuracy of the given time. [s] */
} mipc_threedm_gnss_assist_time_update_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_GNSS_ASSIST_TIME_UPDATE_MAX_SIZE 15

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_gnss_assist_time_update_encode(const mipc_threedm_gnss_assist_time_update_t *value,
                                                          uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_gnss_assist_time_update_decode(const uint8_t *data, size_t len,
                                                          mipc_threedm_gnss_assist_time_update_t *out,
                                                          mipc_decode_error_t *err);

/* ---- gnss_assist_time_update_response (response): GNSS assist time update (response) */
#define MIPC_THREEDM_GNSS_ASSIST_TIME_UPDATE_RESPONSE_DESCRIPTOR 0xA3

/** GNSS assist time update (response). Current assist time values. */
typedef struct {
    double tow;           /* GPS time of week. [s] */
    uint16_t week_number; /* GPS week number. */
    float accuracy;       /* Time accuracy. [s] */
} mipc_threedm_gnss_assist_time_update_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_GNSS_ASSIST_TIME_UPDATE_RESPONSE_MAX_SIZE 14

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_gnss_assist_time_update_response_encode(
    const mipc_threedm_gnss_assist_time_update_response_t *value, uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_threedm_gnss_assist_time_update_response_decode(const uint8_t *data, size_t len,
                                                     mipc_threedm_gnss_assist_time_update_response_t *out,
                                                     mipc_decode_error_t *err);

/* ---- pps_source (command): PPS source control */
#define MIPC_THREEDM_PPS_SOURCE_DESCRIPTOR 0x28

/** PPS source control. Choose where the pulse-per-second signal comes from. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_source;                   /* source is present */
    mipc_pps_source_t source;          /* PPS source. */
} mipc_threedm_pps_source_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_PPS_SOURCE_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_pps_source_encode(const mipc_threedm_pps_source_t *value, uint8_t *buf, size_t cap,
                                             size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_pps_source_decode(const uint8_t *data, size_t len, mipc_threedm_pps_source_t *out,
                                             mipc_decode_error_t *err);

/* ---- pps_source_response (response): PPS source (response) */
#define MIPC_THREEDM_PPS_SOURCE_RESPONSE_DESCRIPTOR 0xA8

/** PPS source (response). Current PPS source. */
typedef struct {
    mipc_pps_source_t source; /* PPS source. */
} mipc_threedm_pps_source_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_PPS_SOURCE_RESPONSE_MAX_SIZE 1

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_pps_source_response_encode(const mipc_threedm_pps_source_response_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_pps_source_response_decode(const uint8_t *data, size_t len,
                                                      mipc_threedm_pps_source_response_t *out,
                                                      mipc_decode_error_t *err);

/* ---- get_supported_events (command): Get supported events */
#define MIPC_THREEDM_GET_SUPPORTED_EVENTS_DESCRIPTOR 0x2A

/** Get supported events. List the trigger or action types the device supports and how many slots it has. */
typedef struct {
    mipc_supported_events_query_t query; /* Trigger types or action types. */
} mipc_threedm_get_supported_events_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_GET_SUPPORTED_EVENTS_MAX_SIZE 1

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_get_supported_events_encode(const mipc_threedm_get_supported_events_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_get_supported_events_decode(const uint8_t *data, size_t len,
                                                       mipc_threedm_get_supported_events_t *out,
                                                       mipc_decode_error_t *err);

/* ---- supported_events (response): Supported events */
#define MIPC_THREEDM_SUPPORTED_EVENTS_DESCRIPTOR 0xB4

/** Supported events. Number of slots and the supported trigger or action types with their maximum counts. */
typedef struct {
    mipc_supported_events_query_t query; /* Echo of the query. */
    mipc_supported_events_info_t info;   /* Slots and supported types. */
} mipc_threedm_supported_events_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_SUPPORTED_EVENTS_MAX_SIZE 253

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_supported_events_encode(const mipc_threedm_supported_events_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_supported_events_decode(const uint8_t *data, size_t len,
                                                   mipc_threedm_supported_events_t *out,
                                                   mipc_decode_error_t *err);

/* ---- device_status (command): Device status */
#define MIPC_THREEDM_DEVICE_STATUS_DESCRIPTOR 0x64

/** Device status. Get the model-specific status of the device, in the basic or the diagnostic structure. The
 * reply layout is tied to the model number (6251 for the 3DM-GX5-45). */
typedef struct {
    uint16_t model_number; /* Device model number; 6251 (0x186B) for the 3DM-GX5-45. */
    mipc_device_status_selector_t status_selector; /* Which status structure to return. */
} mipc_threedm_device_status_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_DEVICE_STATUS_MAX_SIZE 3

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_device_status_encode(const mipc_threedm_device_status_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_device_status_decode(const uint8_t *data, size_t len,
                                                mipc_threedm_device_status_t *out, mipc_decode_error_t *err);

/* ---- device_status_response (response): Device status (response) */
#define MIPC_THREEDM_DEVICE_STATUS_RESPONSE_DESCRIPTOR 0x90

/** Device status (response). Echoes of the model number and selector, then the basic or diagnostic status
 * structure chosen by the echoed selector. */
typedef struct {
    uint16_t model_number;                         /* Echo of the model number. */
    mipc_device_status_selector_t status_selector; /* Echo of the status selector. */
    mipc_gx5_device_status_t status;               /* The selected status structure. */
} mipc_threedm_device_status_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_THREEDM_DEVICE_STATUS_RESPONSE_MAX_SIZE 73

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_threedm_device_status_response_encode(const mipc_threedm_device_status_response_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_threedm_device_status_response_decode(const uint8_t *data, size_t len,
                                                         mipc_threedm_device_status_response_t *out,
                                                         mipc_decode_error_t *err);

#ifdef __cplusplus
}
#endif

#endif
