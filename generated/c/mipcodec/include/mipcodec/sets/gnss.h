/* GNSS Command Set (descriptor set 0x0E): one struct per field layout, with its
 * encoder and decoder. Generated from the spec: do not edit. */
#ifndef MIPC_SETS_GNSS_H
#define MIPC_SETS_GNSS_H

#include "mipcodec/types.h"

#ifdef __cplusplus
extern "C" {
#endif

#define MIPC_GNSS_SET 0x0E

/* ---- receiver_info (command): Receiver info */
#define MIPC_GNSS_RECEIVER_INFO_DESCRIPTOR 0x01

/** Receiver info. Get information about the GNSS receivers in the device. */
typedef struct {
    uint8_t unused_; /* no parameters */
} mipc_gnss_receiver_info_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_RECEIVER_INFO_MAX_SIZE 0

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_receiver_info_encode(const mipc_gnss_receiver_info_t *value, uint8_t *buf, size_t cap,
                                             size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_receiver_info_decode(const uint8_t *data, size_t len, mipc_gnss_receiver_info_t *out,
                                             mipc_decode_error_t *err);

/* ---- receiver_info_response (response): Receiver info (response) */
#define MIPC_GNSS_RECEIVER_INFO_RESPONSE_DESCRIPTOR 0x81

/** Receiver info (response). One entry per physical GNSS receiver. */
typedef struct {
    uint8_t num_receivers;                            /* Number of physical receivers in the device. */
    mipc_gnss_receiver_info_entry_t receiver_info[7]; /* Information on each receiver. */
} mipc_gnss_receiver_info_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_RECEIVER_INFO_RESPONSE_MAX_SIZE 239

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_receiver_info_response_encode(const mipc_gnss_receiver_info_response_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_receiver_info_response_decode(const uint8_t *data, size_t len,
                                                      mipc_gnss_receiver_info_response_t *out,
                                                      mipc_decode_error_t *err);

/* ---- signal_configuration (command): Signal configuration */
#define MIPC_GNSS_SIGNAL_CONFIGURATION_DESCRIPTOR 0x02

/** Signal configuration. Choose the GNSS constellations and frequency bands the receivers use. Only some
 * combinations are valid: GPS or Galileo must be enabled, GPS L1 with BeiDou L1 alone is not allowed, and per
 * constellation GPS none / L1 / L1+L5, GLONASS none / L1, Galileo none / L1+L5, BeiDou none / L1 / L1+L5. */
typedef struct {
    mipc_function_selector_t function;          /* function selector (write, read, save, load, default) */
    bool has_gps_enable;                        /* gps_enable is present */
    mipc_gnss_gps_signals_t gps_enable;         /* GPS signals to use. */
    bool has_glonass_enable;                    /* glonass_enable is present */
    mipc_gnss_glonass_signals_t glonass_enable; /* GLONASS signals to use. */
    bool has_galileo_enable;                    /* galileo_enable is present */
    mipc_gnss_galileo_signals_t galileo_enable; /* Galileo signals to use. */
    bool has_beidou_enable;                     /* beidou_enable is present */
    mipc_gnss_beidou_signals_t beidou_enable;   /* BeiDou signals to use. */
    bool has_reserved;                          /* reserved is present */
    uint8_t reserved[4];                        /* Reserved. */
} mipc_gnss_signal_configuration_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_SIGNAL_CONFIGURATION_MAX_SIZE 9

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_signal_configuration_encode(const mipc_gnss_signal_configuration_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_signal_configuration_decode(const uint8_t *data, size_t len,
                                                    mipc_gnss_signal_configuration_t *out,
                                                    mipc_decode_error_t *err);

/* ---- signal_configuration_response (response): Signal configuration (response) */
#define MIPC_GNSS_SIGNAL_CONFIGURATION_RESPONSE_DESCRIPTOR 0x82

/** Signal configuration (response). GNSS signals currently enabled. */
typedef struct {
    mipc_gnss_gps_signals_t gps_enable;         /* GPS signals in use. */
    mipc_gnss_glonass_signals_t glonass_enable; /* GLONASS signals in use. */
    mipc_gnss_galileo_signals_t galileo_enable; /* Galileo signals in use. */
    mipc_gnss_beidou_signals_t beidou_enable;   /* BeiDou signals in use. */
    uint8_t reserved[4];                        /* Reserved. */
} mipc_gnss_signal_configuration_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_SIGNAL_CONFIGURATION_RESPONSE_MAX_SIZE 8

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_gnss_signal_configuration_response_encode(const mipc_gnss_signal_configuration_response_t *value,
                                               uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_signal_configuration_response_decode(const uint8_t *data, size_t len,
                                                             mipc_gnss_signal_configuration_response_t *out,
                                                             mipc_decode_error_t *err);

/* ---- spartn_configuration (command): SPARTN configuration */
#define MIPC_GNSS_SPARTN_CONFIGURATION_DESCRIPTOR 0x20

/** SPARTN configuration. Configure the SPARTN corrections service: enable, connection type, and the current
 * and next decryption keys with the GPS week and time of week until which each is valid. Enable and type take
 * effect after a power cycle; keys can be updated while running. Enabling SPARTN blocks RTCM corrections. */
typedef struct {
    mipc_function_selector_t function;  /* function selector (write, read, save, load, default) */
    bool has_enable;                    /* enable is present */
    uint8_t enable;                     /* SPARTN subsystem: 0 disabled, 1 enabled. */
    bool has_type;                      /* type is present */
    mipc_spartn_connection_type_t type; /* Connection type. */
    bool has_current_key_tow;           /* current_key_tow is present */
    uint32_t current_key_tow;           /* GPS time of week until which the current key is valid. [s] */
    bool has_current_key_week;          /* current_key_week is present */
    uint16_t current_key_week;          /* GPS week until which the current key is valid. [weeks] */
    bool has_current_key;               /* current_key is present */
    char current_key[32];               /* Current key: 32 ASCII hex characters (e.g. "bc" for 0xBC). */
    bool has_next_key_tow;              /* next_key_tow is present */
    uint32_t next_key_tow;              /* GPS time of week until which the next key is valid. [s] */
    bool has_next_key_week;             /* next_key_week is present */
    uint16_t next_key_week;             /* GPS week until which the next key is valid. [weeks] */
    bool has_next_key;                  /* next_key is present */
    char next_key[32];                  /* Next key: 32 ASCII hex characters. */
} mipc_gnss_spartn_configuration_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_SPARTN_CONFIGURATION_MAX_SIZE 79

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_gnss_spartn_configuration_encode(const mipc_gnss_spartn_configuration_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_spartn_configuration_decode(const uint8_t *data, size_t len,
                                                    mipc_gnss_spartn_configuration_t *out,
                                                    mipc_decode_error_t *err);

/* ---- spartn_configuration_response (response): SPARTN configuration (response) */
#define MIPC_GNSS_SPARTN_CONFIGURATION_RESPONSE_DESCRIPTOR 0xA0

/** SPARTN configuration (response). Current SPARTN configuration. */
typedef struct {
    uint8_t enable;                     /* SPARTN subsystem: 0 disabled, 1 enabled. */
    mipc_spartn_connection_type_t type; /* Connection type. */
    uint32_t current_key_tow;           /* GPS time of week until which the current key is valid. [s] */
    uint16_t current_key_week;          /* GPS week until which the current key is valid. [weeks] */
    char current_key[32];               /* Current key: 32 ASCII hex characters. */
    uint32_t next_key_tow;              /* GPS time of week until which the next key is valid. [s] */
    uint16_t next_key_week;             /* GPS week until which the next key is valid. [weeks] */
    char next_key[32];                  /* Next key: 32 ASCII hex characters. */
} mipc_gnss_spartn_configuration_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_GNSS_SPARTN_CONFIGURATION_RESPONSE_MAX_SIZE 78

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_gnss_spartn_configuration_response_encode(const mipc_gnss_spartn_configuration_response_t *value,
                                               uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_gnss_spartn_configuration_response_decode(const uint8_t *data, size_t len,
                                                             mipc_gnss_spartn_configuration_response_t *out,
                                                             mipc_decode_error_t *err);

#ifdef __cplusplus
}
#endif

#endif
