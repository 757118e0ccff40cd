/* The tables of the device tool (mscipcodec-device, tools/device/; docs/configure-a-device.md): every
 * setting of every model (a command with the write and read functions that the spec's `settings`
 * section does not exclude; the same derivation as the Python package's _settings.py,
 * generator/settings_rows.py), the enums their parameters name, the largest data size of every data
 * field (the link budget), and the facts of the spec's simulation section the tool uses.
 * Generated from the spec: do not edit. */
#ifndef MSCIPC_TOOLS_DEVICE_FACTS_H
#define MSCIPC_TOOLS_DEVICE_FACTS_H

#include <stddef.h>
#include <stdint.h>

typedef struct {
    const char *name; /* lower case, as in a settings file */
    int64_t value;
} dev_member_t;

typedef struct {
    const char *name; /* the type's name in messages */
    const dev_member_t *members;
    size_t count;
} dev_enum_t;

typedef struct {
    const char *name;  /* the write's parameter (the file's key) */
    const char *reply; /* the read reply's parameter */
    const char *units; /* NULL: none */
    int enum_index;    /* into DEV_ENUMS, -1: not an enum */
} dev_attr_t;

typedef struct {
    const char *name; /* the command */
    uint8_t set;
    uint8_t descriptor;
    const char *device;       /* the layout's device when the field has per-device layouts, else NULL */
    const char *reply;        /* the read reply field */
    const char *const *keyed; /* the parameters the read sends */
    size_t keyed_count;
    const dev_attr_t *attrs; /* what a file entry holds, in order */
    size_t attr_count;
    const char *const *counts; /* pairs: count parameter, list parameter */
    size_t count_count;
    const char *const *fill; /* written but not read back: sent as zero (or an empty list) */
    const unsigned char *fill_list;
    size_t fill_count;
    const int64_t *keys; /* key_count rows of keyed_count values: the key combinations dump reads */
    size_t key_count;
} dev_setting_t;

typedef struct {
    uint8_t set;
    uint8_t descriptor;
    uint16_t size; /* the largest data size, without the field header */
} dev_size_t;

typedef struct {
    uint8_t set;
    double hz;
} dev_rate_t;

typedef struct {
    const char *id;
    const char *model_name; /* the identity's model name (the spec's simulation) */
    const dev_setting_t *settings;
    size_t setting_count;
    const dev_size_t *sizes;
    size_t size_count;
    const dev_rate_t *base_rates;
    size_t base_rate_count;
    const uint8_t *unaddressed; /* data sets the stream control cannot address */
    size_t unaddressed_count;
} dev_model_t;

/* message formats: (set, descriptor) of the command; its data set (set >= 0) or the parameter that
 * names it; the list parameter and its items' descriptor and decimation members (NULL: none) */
typedef struct {
    uint8_t cmd_set;
    uint8_t cmd_descriptor;
    int set;
    const char *set_param;
    const char *list;
    const char *descriptor;
    const char *decimation;
} dev_format_t;

typedef struct {
    uint8_t cmd_set;
    uint8_t cmd_descriptor;
    int set;
    const char *set_param;
} dev_rate_query_t;

typedef struct {
    uint8_t cmd_set;
    uint8_t cmd_descriptor;
    const char *flag;
    const char *selector;        /* NULL: none */
    const int64_t *selector_map; /* pairs: selector value, data set */
    size_t selector_count;
    const char *set_param; /* NULL: none */
} dev_enable_t;

typedef struct {
    uint8_t cmd_set;
    uint8_t cmd_descriptor;
    const char *param;
} dev_baud_t;

typedef struct {
    uint8_t cmd_set;
    uint8_t cmd_descriptor;
    uint8_t reply_descriptor;
    const char *param;
    unsigned char u16; /* items are u16: (set << 8) | descriptor; else structs of two members */
} dev_list_t;

typedef struct {
    uint8_t set; /* of the reply */
    uint8_t descriptor;
    const char *path[4]; /* the parameter path in the reply, NULL-terminated */
    const char *item;
} dev_report_t;

typedef struct {
    const char *name;
    int64_t value;
} dev_function_t;

static const dev_function_t DEV_FUNCTIONS[] = {{"write", 1}, {"read", 2},    {"save", 3},
                                               {"load", 4},  {"default", 5}, {NULL, 0}};
static const size_t DEV_FUNCTION_COUNT = 5u;

static const dev_member_t DEV_ENUM_0[] = {{"baud_9600", 9600},
                                          {"baud_19200", 19200},
                                          {"baud_115200", 115200},
                                          {"baud_230400", 230400},
                                          {"baud_460800", 460800},
                                          {"baud_921600", 921600},
                                          {NULL, 0}};
static const dev_member_t DEV_ENUM_1[] = {{"disabled", 0},  {"iir_25hz", 1},  {"iir_50hz", 2},
                                          {"iir_75hz", 3},  {"iir_100hz", 4}, {"iir_10hz", 5},
                                          {"iir_150hz", 6}, {"iir_200hz", 7}, {NULL, 0}};
static const dev_member_t DEV_ENUM_2[] = {{"range_2g", 0},  {"range_4g", 1},  {"range_8g", 2},
                                          {"range_10g", 3}, {"range_15g", 4}, {"range_20g", 5},
                                          {"range_40g", 6}, {NULL, 0}};
static const dev_member_t DEV_ENUM_3[] = {
    {"range_120dps", 1},  {"range_240dps", 2}, {"range_480dps", 3}, {"range_960dps", 4},
    {"range_1920dps", 5}, {"range_75dps", 6},  {"range_200dps", 7}, {NULL, 0}};
static const dev_member_t DEV_ENUM_4[] = {{"off", 0}, {"on", 1}, {NULL, 0}};
static const dev_member_t DEV_ENUM_5[] = {{"ok", 0},
                                          {"checksum_error", 1},
                                          {"invalid_message_type", 2},
                                          {"invalid_message_code", 3},
                                          {"invalid_parameter", 4},
                                          {NULL, 0}};
static const dev_enum_t DEV_ENUMS[] = {{"BaudRate", DEV_ENUM_0, 6u},
                                       {"FilterBandwidth", DEV_ENUM_1, 8u},
                                       {"AccelRange", DEV_ENUM_2, 7u},
                                       {"GyroRange", DEV_ENUM_3, 7u},
                                       {"OnOff", DEV_ENUM_4, 2u},
                                       {"ErrorCode", DEV_ENUM_5, 5u},
                                       {NULL, NULL, 0}};
/* the ack code's enum (NACK messages), -1: none */
#define DEV_ACK_ENUM (5)

static const char *const DEV_KEYED_ms_imu3020_0[] = {NULL};
static const dev_attr_t DEV_ATTRS_ms_imu3020_0[] = {{"baud_rate", "baud_rate", "baud", 0},
                                                    {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_ms_imu3020_0[] = {NULL};
static const char *const DEV_FILL_ms_imu3020_0[] = {NULL};
static const unsigned char DEV_FILL_LIST_ms_imu3020_0[] = {0};
static const int64_t DEV_KEYS_ms_imu3020_0[] = {0};
static const char *const DEV_KEYED_ms_imu3020_1[] = {NULL};
static const dev_attr_t DEV_ATTRS_ms_imu3020_1[] = {{"bandwidth", "bandwidth", NULL, 1},
                                                    {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_ms_imu3020_1[] = {NULL};
static const char *const DEV_FILL_ms_imu3020_1[] = {NULL};
static const unsigned char DEV_FILL_LIST_ms_imu3020_1[] = {0};
static const int64_t DEV_KEYS_ms_imu3020_1[] = {0};
static const char *const DEV_KEYED_ms_imu3020_2[] = {NULL};
static const dev_attr_t DEV_ATTRS_ms_imu3020_2[] = {{"decimation", "decimation", NULL, -1},
                                                    {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_ms_imu3020_2[] = {NULL};
static const char *const DEV_FILL_ms_imu3020_2[] = {NULL};
static const unsigned char DEV_FILL_LIST_ms_imu3020_2[] = {0};
static const int64_t DEV_KEYS_ms_imu3020_2[] = {0};
static const char *const DEV_KEYED_ms_imu3020_3[] = {NULL};
static const dev_attr_t DEV_ATTRS_ms_imu3020_3[] = {{"sensors", "sensors", NULL, -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_ms_imu3020_3[] = {NULL};
static const char *const DEV_FILL_ms_imu3020_3[] = {"reserved", NULL};
static const unsigned char DEV_FILL_LIST_ms_imu3020_3[] = {0, 0};
static const int64_t DEV_KEYS_ms_imu3020_3[] = {0};
static const char *const DEV_KEYED_ms_imu3020_4[] = {NULL};
static const dev_attr_t DEV_ATTRS_ms_imu3020_4[] = {{"range", "range", NULL, 2}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_ms_imu3020_4[] = {NULL};
static const char *const DEV_FILL_ms_imu3020_4[] = {NULL};
static const unsigned char DEV_FILL_LIST_ms_imu3020_4[] = {0};
static const int64_t DEV_KEYS_ms_imu3020_4[] = {0};
static const char *const DEV_KEYED_ms_imu3020_5[] = {NULL};
static const dev_attr_t DEV_ATTRS_ms_imu3020_5[] = {{"range", "range", NULL, 3}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_ms_imu3020_5[] = {NULL};
static const char *const DEV_FILL_ms_imu3020_5[] = {NULL};
static const unsigned char DEV_FILL_LIST_ms_imu3020_5[] = {0};
static const int64_t DEV_KEYS_ms_imu3020_5[] = {0};
static const char *const DEV_KEYED_ms_imu3020_6[] = {NULL};
static const dev_attr_t DEV_ATTRS_ms_imu3020_6[] = {{"control", "control", NULL, 4}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_ms_imu3020_6[] = {NULL};
static const char *const DEV_FILL_ms_imu3020_6[] = {NULL};
static const unsigned char DEV_FILL_LIST_ms_imu3020_6[] = {0};
static const int64_t DEV_KEYS_ms_imu3020_6[] = {0};
static const char *const DEV_KEYED_ms_imu3020_7[] = {NULL};
static const dev_attr_t DEV_ATTRS_ms_imu3020_7[] = {{"control", "control", NULL, 4}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_ms_imu3020_7[] = {NULL};
static const char *const DEV_FILL_ms_imu3020_7[] = {NULL};
static const unsigned char DEV_FILL_LIST_ms_imu3020_7[] = {0};
static const int64_t DEV_KEYS_ms_imu3020_7[] = {0};
static const char *const DEV_KEYED_ms_imu3020_8[] = {NULL};
static const dev_attr_t DEV_ATTRS_ms_imu3020_8[] = {{"sensors", "sensors", NULL, -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_ms_imu3020_8[] = {NULL};
static const char *const DEV_FILL_ms_imu3020_8[] = {NULL};
static const unsigned char DEV_FILL_LIST_ms_imu3020_8[] = {0};
static const int64_t DEV_KEYS_ms_imu3020_8[] = {0};
static const char *const DEV_KEYED_ms_imu3020_9[] = {NULL};
static const dev_attr_t DEV_ATTRS_ms_imu3020_9[] = {{"range", "range", NULL, 2}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_ms_imu3020_9[] = {NULL};
static const char *const DEV_FILL_ms_imu3020_9[] = {NULL};
static const unsigned char DEV_FILL_LIST_ms_imu3020_9[] = {0};
static const int64_t DEV_KEYS_ms_imu3020_9[] = {0};
static const dev_setting_t DEV_SETTINGS_ms_imu3020[] = {
    {"uart_baud_rate", 2, 1, NULL, "uart_baud_rate_response", DEV_KEYED_ms_imu3020_0, 0u,
     DEV_ATTRS_ms_imu3020_0, 1u, DEV_COUNTS_ms_imu3020_0, 0u, DEV_FILL_ms_imu3020_0,
     DEV_FILL_LIST_ms_imu3020_0, 0u, DEV_KEYS_ms_imu3020_0, 1u},
    {"filter", 2, 3, NULL, "filter_response", DEV_KEYED_ms_imu3020_1, 0u, DEV_ATTRS_ms_imu3020_1, 1u,
     DEV_COUNTS_ms_imu3020_1, 0u, DEV_FILL_ms_imu3020_1, DEV_FILL_LIST_ms_imu3020_1, 0u,
     DEV_KEYS_ms_imu3020_1, 1u},
    {"sample_rate", 2, 4, NULL, "sample_rate_response", DEV_KEYED_ms_imu3020_2, 0u, DEV_ATTRS_ms_imu3020_2,
     1u, DEV_COUNTS_ms_imu3020_2, 0u, DEV_FILL_ms_imu3020_2, DEV_FILL_LIST_ms_imu3020_2, 0u,
     DEV_KEYS_ms_imu3020_2, 1u},
    {"select_sensors", 2, 5, NULL, "select_sensors_response", DEV_KEYED_ms_imu3020_3, 0u,
     DEV_ATTRS_ms_imu3020_3, 1u, DEV_COUNTS_ms_imu3020_3, 0u, DEV_FILL_ms_imu3020_3,
     DEV_FILL_LIST_ms_imu3020_3, 1u, DEV_KEYS_ms_imu3020_3, 1u},
    {"accel_range", 2, 7, NULL, "accel_range_response", DEV_KEYED_ms_imu3020_4, 0u, DEV_ATTRS_ms_imu3020_4,
     1u, DEV_COUNTS_ms_imu3020_4, 0u, DEV_FILL_ms_imu3020_4, DEV_FILL_LIST_ms_imu3020_4, 0u,
     DEV_KEYS_ms_imu3020_4, 1u},
    {"gyro_range", 2, 8, NULL, "gyro_range_response", DEV_KEYED_ms_imu3020_5, 0u, DEV_ATTRS_ms_imu3020_5, 1u,
     DEV_COUNTS_ms_imu3020_5, 0u, DEV_FILL_ms_imu3020_5, DEV_FILL_LIST_ms_imu3020_5, 0u,
     DEV_KEYS_ms_imu3020_5, 1u},
    {"data_on_off", 2, 10, NULL, "data_on_off_response", DEV_KEYED_ms_imu3020_6, 0u, DEV_ATTRS_ms_imu3020_6,
     1u, DEV_COUNTS_ms_imu3020_6, 0u, DEV_FILL_ms_imu3020_6, DEV_FILL_LIST_ms_imu3020_6, 0u,
     DEV_KEYS_ms_imu3020_6, 1u},
    {"xtrig_on_off", 2, 11, NULL, "xtrig_on_off_response", DEV_KEYED_ms_imu3020_7, 0u, DEV_ATTRS_ms_imu3020_7,
     1u, DEV_COUNTS_ms_imu3020_7, 0u, DEV_FILL_ms_imu3020_7, DEV_FILL_LIST_ms_imu3020_7, 0u,
     DEV_KEYS_ms_imu3020_7, 1u},
    {"select_sensors_rev_b", 2, 12, NULL, "select_sensors_rev_b_response", DEV_KEYED_ms_imu3020_8, 0u,
     DEV_ATTRS_ms_imu3020_8, 1u, DEV_COUNTS_ms_imu3020_8, 0u, DEV_FILL_ms_imu3020_8,
     DEV_FILL_LIST_ms_imu3020_8, 0u, DEV_KEYS_ms_imu3020_8, 1u},
    {"aux_accel_range", 2, 13, NULL, "aux_accel_range_response", DEV_KEYED_ms_imu3020_9, 0u,
     DEV_ATTRS_ms_imu3020_9, 1u, DEV_COUNTS_ms_imu3020_9, 0u, DEV_FILL_ms_imu3020_9,
     DEV_FILL_LIST_ms_imu3020_9, 0u, DEV_KEYS_ms_imu3020_9, 1u},
    {NULL, 0, 0, NULL, NULL, NULL, 0, NULL, 0, NULL, 0, NULL, NULL, 0, NULL, 0}};
static const dev_size_t DEV_SIZES_ms_imu3020[] = {
    {162, 129, 12}, {162, 130, 12}, {162, 131, 12}, {162, 132, 12}, {162, 133, 12},
    {162, 134, 4},  {162, 135, 4},  {162, 136, 12}, {162, 137, 12}, {0, 0, 0}};
static const dev_rate_t DEV_BASE_RATES_ms_imu3020[] = {{162, 1000}, {0, 0}};
static const uint8_t DEV_UNADDRESSED_ms_imu3020[] = {0};
static const dev_model_t DEV_MODELS[] = {{"ms_imu3020", "MS_IMU3020", DEV_SETTINGS_ms_imu3020, 10u,
                                          DEV_SIZES_ms_imu3020, 9u, DEV_BASE_RATES_ms_imu3020, 1u,
                                          DEV_UNADDRESSED_ms_imu3020, 0u},
                                         {NULL, NULL, NULL, 0, NULL, 0, NULL, 0, NULL, 0}};
static const size_t DEV_MODEL_COUNT = 1u;

static const dev_format_t DEV_FORMATS[] = {{2, 5, 162, NULL, "sensors", NULL, NULL},
                                           {2, 12, 162, NULL, "sensors", NULL, NULL},
                                           {0, 0, -1, NULL, NULL, NULL, NULL}};
static const size_t DEV_FORMAT_COUNT = 2u;

static const dev_rate_query_t DEV_RATE_QUERIES[] = {{2, 6, 162, NULL}, {0, 0, -1, NULL}};
static const size_t DEV_RATE_QUERY_COUNT = 1u;
static const int64_t DEV_ENABLE_MAP_0[] = {0};
static const dev_enable_t DEV_ENABLES[] = {{2, 10, "control", NULL, DEV_ENABLE_MAP_0, 0u, NULL},
                                           {0, 0, NULL, NULL, NULL, 0, NULL}};
static const size_t DEV_ENABLE_COUNT = 1u;

static const dev_baud_t DEV_BAUD[] = {{2, 1, "baud_rate"}, {0, 0, NULL}};
static const size_t DEV_BAUD_COUNT = 1u;

/* the commands whose save and default apply to every setting */
static const uint8_t DEV_ALL_SETTINGS[][2] = {{2, 9}, {0, 0}};
static const size_t DEV_ALL_SETTINGS_COUNT = 1u;

static const dev_list_t DEV_LISTS[] = {{1, 3, 131, "messages", 0}, {0, 0, 0, NULL, 0}};
static const size_t DEV_LIST_COUNT = 1u;

static const dev_report_t DEV_REPORTS[] = {{1, 133, {"model", NULL}, "model_name"},
                                           {1, 134, {"serial_number", NULL}, "serial_number"},
                                           {1, 135, {"firmware", NULL}, "firmware"},
                                           {1, 136, {"date", NULL}, "calibration_date"},
                                           {0, 0, {NULL}, NULL}};
static const size_t DEV_REPORT_COUNT = 4u;

typedef struct {
    uint8_t id;
    const char *name;
} dev_set_name_t;

static const dev_set_name_t DEV_SET_NAMES[] = {{1, "base"}, {2, "imu_config"}, {162, "imu_data"}, {0, NULL}};

/* the command whose reply reports the identity: set, descriptor (0, 0: none) */
#define DEV_IDENTITY_SET 1u
#define DEV_IDENTITY_DESCRIPTOR 5u

/* the manuals' lines of the UART bandwidth calculation (the spec's link: bandwidth) */
#define DEV_BANDWIDTH_SOURCES "no manual (the spec has no link bandwidth)"
/* the data set of the shared fields (valid in every data set), -1: none */
#define DEV_SHARED_SET (-1)

/* time synchronization (the spec's time.sync; tools/device/timesync.c, docs/timesync.md) */
typedef enum { DEV_PPS_NONE, DEV_PPS_INPUT, DEV_PPS_RECEIVER, DEV_PPS_GENERATED } dev_pps_kind_t;

typedef struct {
    const char *name; /* lower case, as --pps-source takes it */
    int64_t value;
    dev_pps_kind_t kind;
} dev_pps_member_t;

typedef struct {
    uint8_t set; /* the field (the shared set's: in every data set) */
    uint8_t descriptor;
    const char *flags;
    const char *tow;
    uint32_t tow_mask;
    uint32_t week_mask;
} dev_sync_time_t;

typedef struct {
    const char *device;
    /* the GPS Time Update command: its selector and value parameters, the selector's values */
    uint8_t update_set;
    uint8_t update_descriptor;
    const char *update_selector;
    const char *update_value;
    int64_t update_week;
    int64_t update_tow;
    /* the PPS source setting (pps_param NULL: none); its members in their enum's order */
    uint8_t pps_set;
    uint8_t pps_descriptor;
    const char *pps_param;
    const dev_pps_member_t *pps_members;
    size_t pps_member_count;
    /* the status field (status_set -1: none) and its synced parameter */
    int status_set;
    uint8_t status_descriptor;
    const char *status_synced;
    /* the external time fields with a time of week and week */
    const dev_sync_time_t *external;
    size_t external_count;
    /* the correlation timestamp (corr_set -1: none): its flags and their masks */
    int corr_set;
    uint8_t corr_descriptor;
    const char *corr_flags;
    const char *corr_tow;
    uint32_t corr_pps;
    uint32_t corr_refresh;
    uint32_t corr_initialized;
} dev_timesync_t;
static const dev_timesync_t DEV_TIMESYNC[] = {
    {NULL, 0, 0, NULL, NULL, 0, 0, 0, 0, NULL, NULL, 0, -1, 0, NULL, NULL, 0, -1, 0, NULL, NULL, 0, 0, 0}};
static const size_t DEV_TIMESYNC_COUNT = 0u;

/* The GPS time scale (spec/common/gps_time.yaml, the same for every protocol): the GPS epoch
   1980-01-06T00:00:00Z in Unix seconds, and GPS - UTC in seconds from each UTC instant on (the
   Unix time of the first UTC second with the new offset; IERS Bulletin C), 0 before the first. */
#define DEV_GPS_EPOCH_UNIX_S 315964800LL
typedef struct {
    int64_t from_unix_s;
    int gps_minus_utc_s;
} dev_leap_t;
static const dev_leap_t DEV_LEAP_TABLE[] = {
    {362793600LL, 1},   {394329600LL, 2},   {425865600LL, 3},   {489024000LL, 4},   {567993600LL, 5},
    {631152000LL, 6},   {662688000LL, 7},   {709948800LL, 8},   {741484800LL, 9},   {773020800LL, 10},
    {820454400LL, 11},  {867715200LL, 12},  {915148800LL, 13},  {1136073600LL, 14}, {1230768000LL, 15},
    {1341100800LL, 16}, {1435708800LL, 17}, {1483228800LL, 18},
};
static const size_t DEV_LEAP_COUNT = 18u;

#endif
