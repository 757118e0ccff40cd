/* System Command Set (descriptor set 0x7F): one struct per field layout, with its
 * encoder and decoder. Generated from the spec: do not edit. */
#ifndef MIPC_SETS_SYSTEM_H
#define MIPC_SETS_SYSTEM_H

#include "mipcodec/types.h"

#ifdef __cplusplus
extern "C" {
#endif

#define MIPC_SYSTEM_SET 0x7F

/* ---- communication_mode (command): Communication mode */
#define MIPC_SYSTEM_COMMUNICATION_MODE_DESCRIPTOR 0x10

/** Communication mode. Switch the communication protocol between standard MIP and the native protocols of an
 * internal sensor block (IMU direct, or u-blox GNSS direct). Always active, even in the direct modes; the
 * device acks just before switching. GNSS message settings are reloaded when returning to standard mode, and
 * switching to or from GNSS direct takes longer than most commands. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    bool has_mode;                     /* mode is present */
    mipc_system_comm_mode_t mode;      /* New communication mode (ignored for functions other than write). */
} mipc_system_communication_mode_t;

/* Largest encoded data (after the field header). */
#define MIPC_SYSTEM_COMMUNICATION_MODE_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_system_communication_mode_encode(const mipc_system_communication_mode_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_system_communication_mode_decode(const uint8_t *data, size_t len,
                                                    mipc_system_communication_mode_t *out,
                                                    mipc_decode_error_t *err);

/* ---- communication_mode_response (response): Communication mode (response) */
#define MIPC_SYSTEM_COMMUNICATION_MODE_RESPONSE_DESCRIPTOR 0x90

/** Communication mode (response). Current communication mode (reply to a read). */
typedef struct {
    mipc_system_comm_mode_t mode; /* Current communication mode. */
} mipc_system_communication_mode_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_SYSTEM_COMMUNICATION_MODE_RESPONSE_MAX_SIZE 1

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_system_communication_mode_response_encode(const mipc_system_communication_mode_response_t *value,
                                               uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_system_communication_mode_response_decode(const uint8_t *data, size_t len,
                                                             mipc_system_communication_mode_response_t *out,
                                                             mipc_decode_error_t *err);

#ifdef __cplusplus
}
#endif

#endif
