/* 3DM Command Set (descriptor set 0x0C): one struct per field layout, with its
 * encoder and decoder. Generated from the spec: do not edit. */
#ifndef MIP_SETS_THREEDM_H
#define MIP_SETS_THREEDM_H

#include "mipcodec/types.h"

#ifdef __cplusplus
extern "C" {
#endif

#define MIP_THREEDM_SET 0x0C

/* ---- event_control (command): Event control */
#define MIP_THREEDM_EVENT_CONTROL_DESCRIPTOR 0x2B

/** Event control. Enable, disable or test an event trigger. */
typedef struct {
    mip_function_selector_t function; /* function selector (write, read, save, load, default) */
    uint8_t instance; /* Trigger instance; 0 applies to all configured triggers (not for read). */
    bool has_mode;    /* mode is present */
    mip_event_control_mode_t mode; /* How to change the trigger state. */
} mip_threedm_event_control_t;

/* Largest encoded data (after the field header). */
#define MIP_THREEDM_EVENT_CONTROL_MAX_SIZE 3

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_threedm_event_control_encode(const mip_threedm_event_control_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_threedm_event_control_decode(const uint8_t *data, size_t len,
                                              mip_threedm_event_control_t *out, mip_decode_error_t *err);

/* ---- event_control_response (response): Event control (response) */
#define MIP_THREEDM_EVENT_CONTROL_RESPONSE_DESCRIPTOR 0xB5

/** Event control (response). Current mode of a trigger. */
typedef struct {
    uint8_t instance;              /* Trigger instance. */
    mip_event_control_mode_t mode; /* Trigger mode. */
} mip_threedm_event_control_response_t;

/* Largest encoded data (after the field header). */
#define MIP_THREEDM_EVENT_CONTROL_RESPONSE_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_threedm_event_control_response_encode(const mip_threedm_event_control_response_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_threedm_event_control_response_decode(const uint8_t *data, size_t len,
                                                       mip_threedm_event_control_response_t *out,
                                                       mip_decode_error_t *err);

/* ---- get_event_trigger_status (command): Get event trigger status */
#define MIP_THREEDM_GET_EVENT_TRIGGER_STATUS_DESCRIPTOR 0x2C

/** Get event trigger status. Report the type and status of event triggers. */
typedef struct {
    uint8_t requested_count;          /* Number of entries requested; 0 requests all trigger slots. */
    uint8_t requested_instances[252]; /* Trigger instances to query. */
} mip_threedm_get_event_trigger_status_t;

/* Largest encoded data (after the field header). */
#define MIP_THREEDM_GET_EVENT_TRIGGER_STATUS_MAX_SIZE 253

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_threedm_get_event_trigger_status_encode(const mip_threedm_get_event_trigger_status_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_threedm_get_event_trigger_status_decode(const uint8_t *data, size_t len,
                                                         mip_threedm_get_event_trigger_status_t *out,
                                                         mip_decode_error_t *err);

/* ---- event_trigger_status (response): Event trigger status */
#define MIP_THREEDM_EVENT_TRIGGER_STATUS_DESCRIPTOR 0xB6

/** Event trigger status. Status of the requested triggers, in the order requested (increasing if all). */
typedef struct {
    uint8_t count;                            /* Number of entries. */
    mip_trigger_status_entry_t triggers[126]; /* The configured triggers. */
} mip_threedm_event_trigger_status_t;

/* Largest encoded data (after the field header). */
#define MIP_THREEDM_EVENT_TRIGGER_STATUS_MAX_SIZE 253

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_threedm_event_trigger_status_encode(const mip_threedm_event_trigger_status_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_threedm_event_trigger_status_decode(const uint8_t *data, size_t len,
                                                     mip_threedm_event_trigger_status_t *out,
                                                     mip_decode_error_t *err);

/* ---- get_event_action_status (command): Get event action status */
#define MIP_THREEDM_GET_EVENT_ACTION_STATUS_DESCRIPTOR 0x2D

/** Get event action status. Report the type and trigger of event actions. */
typedef struct {
    uint8_t requested_count;          /* Number of entries requested; 0 requests all action slots. */
    uint8_t requested_instances[252]; /* Action instances to query. */
} mip_threedm_get_event_action_status_t;

/* Largest encoded data (after the field header). */
#define MIP_THREEDM_GET_EVENT_ACTION_STATUS_MAX_SIZE 253

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_threedm_get_event_action_status_encode(const mip_threedm_get_event_action_status_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_threedm_get_event_action_status_decode(const uint8_t *data, size_t len,
                                                        mip_threedm_get_event_action_status_t *out,
                                                        mip_decode_error_t *err);

/* ---- event_action_status (response): Event action status */
#define MIP_THREEDM_EVENT_ACTION_STATUS_DESCRIPTOR 0xB7

/** Event action status. Status of the requested actions. */
typedef struct {
    uint8_t count;                          /* Number of entries. */
    mip_action_status_entry_t actions[126]; /* The configured actions. */
} mip_threedm_event_action_status_t;

/* Largest encoded data (after the field header). */
#define MIP_THREEDM_EVENT_ACTION_STATUS_MAX_SIZE 253

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_threedm_event_action_status_encode(const mip_threedm_event_action_status_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_threedm_event_action_status_decode(const uint8_t *data, size_t len,
                                                    mip_threedm_event_action_status_t *out,
                                                    mip_decode_error_t *err);

/* ---- event_trigger_config (command): Event trigger configuration */
#define MIP_THREEDM_EVENT_TRIGGER_CONFIG_DESCRIPTOR 0x2E

/** Event trigger configuration. Configure an event trigger (GPIO, threshold or combination). */
typedef struct {
    mip_function_selector_t function; /* function selector (write, read, save, load, default) */
    uint8_t instance;        /* Trigger number; 0 applies to all instances for save, load and default. */
    bool has_type;           /* type is present */
    mip_trigger_type_t type; /* Type of trigger. */
    bool has_parameters;     /* parameters is present */
    mip_trigger_params_t parameters; /* Parameters of the trigger type. */
} mip_threedm_event_trigger_config_t;

/* Largest encoded data (after the field header). */
#define MIP_THREEDM_EVENT_TRIGGER_CONFIG_MAX_SIZE 23

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_threedm_event_trigger_config_encode(const mip_threedm_event_trigger_config_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_threedm_event_trigger_config_decode(const uint8_t *data, size_t len,
                                                     mip_threedm_event_trigger_config_t *out,
                                                     mip_decode_error_t *err);

/* ---- event_trigger_config_response (response): Event trigger configuration (response) */
#define MIP_THREEDM_EVENT_TRIGGER_CONFIG_RESPONSE_DESCRIPTOR 0xB8

/** Event trigger configuration (response). Current configuration of a trigger. */
typedef struct {
    uint8_t instance;                /* Trigger number. */
    mip_trigger_type_t type;         /* Type of trigger. */
    mip_trigger_params_t parameters; /* Parameters of the trigger type. */
} mip_threedm_event_trigger_config_response_t;

/* Largest encoded data (after the field header). */
#define MIP_THREEDM_EVENT_TRIGGER_CONFIG_RESPONSE_MAX_SIZE 22

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t
mip_threedm_event_trigger_config_response_encode(const mip_threedm_event_trigger_config_response_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t
mip_threedm_event_trigger_config_response_decode(const uint8_t *data, size_t len,
                                                 mip_threedm_event_trigger_config_response_t *out,
                                                 mip_decode_error_t *err);

/* ---- event_action_config (command): Event action configuration */
#define MIP_THREEDM_EVENT_ACTION_CONFIG_DESCRIPTOR 0x2F

/** Event action configuration. Configure an event action (GPIO or message) and the trigger that fires it. */
typedef struct {
    mip_function_selector_t function; /* function selector (write, read, save, load, default) */
    uint8_t instance;       /* Action number; 0 applies to all instances for save, load and default. */
    bool has_trigger;       /* trigger is present */
    uint8_t trigger;        /* Trigger ID number. */
    bool has_type;          /* type is present */
    mip_action_type_t type; /* Type of action. */
    bool has_parameters;    /* parameters is present */
    mip_action_params_t parameters; /* Parameters of the action type. */
} mip_threedm_event_action_config_t;

/* Largest encoded data (after the field header). */
#define MIP_THREEDM_EVENT_ACTION_CONFIG_MAX_SIZE 20

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_threedm_event_action_config_encode(const mip_threedm_event_action_config_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_threedm_event_action_config_decode(const uint8_t *data, size_t len,
                                                    mip_threedm_event_action_config_t *out,
                                                    mip_decode_error_t *err);

/* ---- event_action_config_response (response): Event action configuration (response) */
#define MIP_THREEDM_EVENT_ACTION_CONFIG_RESPONSE_DESCRIPTOR 0xB9

/** Event action configuration (response). Current configuration of an action. */
typedef struct {
    uint8_t instance;               /* Action number. */
    uint8_t trigger;                /* Trigger ID number. */
    mip_action_type_t type;         /* Type of action. */
    mip_action_params_t parameters; /* Parameters of the action type. */
} mip_threedm_event_action_config_response_t;

/* Largest encoded data (after the field header). */
#define MIP_THREEDM_EVENT_ACTION_CONFIG_RESPONSE_MAX_SIZE 19

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t
mip_threedm_event_action_config_response_encode(const mip_threedm_event_action_config_response_t *value,
                                                uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_threedm_event_action_config_response_decode(const uint8_t *data, size_t len,
                                                             mip_threedm_event_action_config_response_t *out,
                                                             mip_decode_error_t *err);

#ifdef __cplusplus
}
#endif

#endif
