/* Commands (descriptor set 0x01): one struct per field layout, with its
 * encoder and decoder. Generated from the spec: do not edit. */
#ifndef DEMOC_SETS_COMMANDS_H
#define DEMOC_SETS_COMMANDS_H

#include "democodec/types.h"

#ifdef __cplusplus
extern "C" {
#endif

#define DEMOC_COMMANDS_SET 0x01

/* ---- ping (command): Ping */
#define DEMOC_COMMANDS_PING_DESCRIPTOR 0x01

/** Ping.  */
typedef struct {
    uint8_t unused_; /* no parameters */
} democ_commands_ping_t;

/* Largest encoded data (after the field header). */
#define DEMOC_COMMANDS_PING_MAX_SIZE 0

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
democ_status_t democ_commands_ping_encode(const democ_commands_ping_t *value, uint8_t *buf, size_t cap,
                                          size_t *len_out);
/** Decodes field data; on DEMOC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
democ_status_t democ_commands_ping_decode(const uint8_t *data, size_t len, democ_commands_ping_t *out,
                                          democ_decode_error_t *err);

/* ---- configure (command): Configure */
#define DEMOC_COMMANDS_CONFIGURE_DESCRIPTOR 0x02

/** Configure.  */
typedef struct {
    democ_function_t function;     /* function selector (write, read, save) */
    uint8_t instance;              /*  */
    bool has_mode;                 /* mode is present */
    democ_mode_t mode;             /*  */
    bool has_params;               /* params is present */
    democ_trigger_params_t params; /*  */
    bool has_suppress_ack;         /* suppress_ack is present */
    bool suppress_ack;             /*  */
} democ_commands_configure_t;

/* Largest encoded data (after the field header). */
#define DEMOC_COMMANDS_CONFIGURE_MAX_SIZE 32

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
democ_status_t democ_commands_configure_encode(const democ_commands_configure_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out);
/** Decodes field data; on DEMOC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
democ_status_t democ_commands_configure_decode(const uint8_t *data, size_t len,
                                               democ_commands_configure_t *out, democ_decode_error_t *err);

/* ---- configuration (response): Configuration */
#define DEMOC_COMMANDS_CONFIGURATION_DESCRIPTOR 0x82

/** Configuration.  */
typedef struct {
    uint8_t instance;       /*  */
    uint8_t count;          /*  */
    uint16_t rates[10];     /*  */
    char name[8];           /*  */
    char label[16];         /*  */
    double matrix[9];       /*  */
    int32_t fixed[4];       /*  */
    democ_flags_t flags;    /*  */
    democ_signed_t signed_; /*  */
    size_t tail_count;      /* number of elements in tail */
    char tail[135];         /*  */
} democ_commands_configuration_t;

/* Largest encoded data (after the field header). */
#define DEMOC_COMMANDS_CONFIGURATION_MAX_SIZE 273

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
democ_status_t democ_commands_configuration_encode(const democ_commands_configuration_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out);
/** Decodes field data; on DEMOC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
democ_status_t democ_commands_configuration_decode(const uint8_t *data, size_t len,
                                                   democ_commands_configuration_t *out,
                                                   democ_decode_error_t *err);

/* ---- per_device (command, 2 per-device variants): Per-device command */
#define DEMOC_COMMANDS_PER_DEVICE_DESCRIPTOR 0x03

/** Per-device command (dev_a).  */
typedef struct {
    uint32_t a; /*  */
} democ_commands_per_device_dev_a_t;

/* Largest encoded data (after the field header). */
#define DEMOC_COMMANDS_PER_DEVICE_DEV_A_MAX_SIZE 4

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
democ_status_t democ_commands_per_device_dev_a_encode(const democ_commands_per_device_dev_a_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on DEMOC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
democ_status_t democ_commands_per_device_dev_a_decode(const uint8_t *data, size_t len,
                                                      democ_commands_per_device_dev_a_t *out,
                                                      democ_decode_error_t *err);

/** Per-device command (dev_b).  */
typedef struct {
    uint64_t b;     /*  */
    bool has_extra; /* extra is present */
    uint8_t extra;  /*  */
} democ_commands_per_device_dev_b_t;

/* Largest encoded data (after the field header). */
#define DEMOC_COMMANDS_PER_DEVICE_DEV_B_MAX_SIZE 9

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
democ_status_t democ_commands_per_device_dev_b_encode(const democ_commands_per_device_dev_b_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on DEMOC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
democ_status_t democ_commands_per_device_dev_b_decode(const uint8_t *data, size_t len,
                                                      democ_commands_per_device_dev_b_t *out,
                                                      democ_decode_error_t *err);

#ifdef __cplusplus
}
#endif

#endif
