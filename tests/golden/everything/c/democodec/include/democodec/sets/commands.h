/* Commands (descriptor set 0x01): one struct per field layout, with its
 * encoder and decoder. Generated from the spec: do not edit. */
#ifndef DEMO_SETS_COMMANDS_H
#define DEMO_SETS_COMMANDS_H

#include "democodec/types.h"

#ifdef __cplusplus
extern "C" {
#endif

#define DEMO_COMMANDS_SET 0x01

/* ---- ping (command): Ping */
#define DEMO_COMMANDS_PING_DESCRIPTOR 0x01

/** Ping.  */
typedef struct {
    uint8_t unused_; /* no parameters */
} demo_commands_ping_t;

/* Largest encoded data (after the field header). */
#define DEMO_COMMANDS_PING_MAX_SIZE 0

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
demo_status_t demo_commands_ping_encode(const demo_commands_ping_t *value, uint8_t *buf, size_t cap,
                                        size_t *len_out);
/** Decodes field data; on DEMO_ERR_DECODE, *err (if not NULL) tells what is wrong. */
demo_status_t demo_commands_ping_decode(const uint8_t *data, size_t len, demo_commands_ping_t *out,
                                        demo_decode_error_t *err);

/* ---- configure (command): Configure */
#define DEMO_COMMANDS_CONFIGURE_DESCRIPTOR 0x02

/** Configure.  */
typedef struct {
    demo_function_t function;     /* function selector (write, read, save) */
    uint8_t instance;             /*  */
    bool has_mode;                /* mode is present */
    demo_mode_t mode;             /*  */
    bool has_params;              /* params is present */
    demo_trigger_params_t params; /*  */
    bool has_suppress_ack;        /* suppress_ack is present */
    bool suppress_ack;            /*  */
} demo_commands_configure_t;

/* Largest encoded data (after the field header). */
#define DEMO_COMMANDS_CONFIGURE_MAX_SIZE 32

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
demo_status_t demo_commands_configure_encode(const demo_commands_configure_t *value, uint8_t *buf, size_t cap,
                                             size_t *len_out);
/** Decodes field data; on DEMO_ERR_DECODE, *err (if not NULL) tells what is wrong. */
demo_status_t demo_commands_configure_decode(const uint8_t *data, size_t len, demo_commands_configure_t *out,
                                             demo_decode_error_t *err);

/* ---- configuration (response): Configuration */
#define DEMO_COMMANDS_CONFIGURATION_DESCRIPTOR 0x82

/** Configuration.  */
typedef struct {
    uint8_t instance;      /*  */
    uint8_t count;         /*  */
    uint16_t rates[10];    /*  */
    char name[8];          /*  */
    char label[16];        /*  */
    double matrix[9];      /*  */
    int32_t fixed[4];      /*  */
    demo_flags_t flags;    /*  */
    demo_signed_t signed_; /*  */
    size_t tail_count;     /* number of elements in tail */
    char tail[135];        /*  */
} demo_commands_configuration_t;

/* Largest encoded data (after the field header). */
#define DEMO_COMMANDS_CONFIGURATION_MAX_SIZE 273

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
demo_status_t demo_commands_configuration_encode(const demo_commands_configuration_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out);
/** Decodes field data; on DEMO_ERR_DECODE, *err (if not NULL) tells what is wrong. */
demo_status_t demo_commands_configuration_decode(const uint8_t *data, size_t len,
                                                 demo_commands_configuration_t *out,
                                                 demo_decode_error_t *err);

/* ---- per_device (command, 2 per-device variants): Per-device command */
#define DEMO_COMMANDS_PER_DEVICE_DESCRIPTOR 0x03

/** Per-device command (dev_a).  */
typedef struct {
    uint32_t a; /*  */
} demo_commands_per_device_dev_a_t;

/* Largest encoded data (after the field header). */
#define DEMO_COMMANDS_PER_DEVICE_DEV_A_MAX_SIZE 4

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
demo_status_t demo_commands_per_device_dev_a_encode(const demo_commands_per_device_dev_a_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on DEMO_ERR_DECODE, *err (if not NULL) tells what is wrong. */
demo_status_t demo_commands_per_device_dev_a_decode(const uint8_t *data, size_t len,
                                                    demo_commands_per_device_dev_a_t *out,
                                                    demo_decode_error_t *err);

/** Per-device command (dev_b).  */
typedef struct {
    uint64_t b;     /*  */
    bool has_extra; /* extra is present */
    uint8_t extra;  /*  */
} demo_commands_per_device_dev_b_t;

/* Largest encoded data (after the field header). */
#define DEMO_COMMANDS_PER_DEVICE_DEV_B_MAX_SIZE 9

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
demo_status_t demo_commands_per_device_dev_b_encode(const demo_commands_per_device_dev_b_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on DEMO_ERR_DECODE, *err (if not NULL) tells what is wrong. */
demo_status_t demo_commands_per_device_dev_b_decode(const uint8_t *data, size_t len,
                                                    demo_commands_per_device_dev_b_t *out,
                                                    demo_decode_error_t *err);

#ifdef __cplusplus
}
#endif

#endif
