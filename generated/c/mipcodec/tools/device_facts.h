/* The tables of the device tool (mipcodec-device, tools/device/; docs/configure-a-device.md): every
 * setting of every model (a command with the write and read functions that the spec's `settings`
 * section does not exclude; the same derivation as the Python package's _settings.py,
 * generator/settings_rows.py), the enums their parameters name, the largest data size of every data
 * field (the link budget), and the facts of the spec's simulation section the tool uses.
 * Generated from the spec: do not edit. */
#ifndef MIPC_TOOLS_DEVICE_FACTS_H
#define MIPC_TOOLS_DEVICE_FACTS_H

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

static const dev_function_t DEV_FUNCTIONS[] = {{"write", 1},   {"read", 2},         {"save", 3}, {"load", 4},
                                               {"default", 5}, {"write_no_ack", 6}, {NULL, 0}};
static const size_t DEV_FUNCTION_COUNT = 6u;

static const dev_member_t DEV_ENUM_0[] = {
    {"disabled", 0}, {"enabled", 1}, {"test", 2}, {"test_pulse", 3}, {NULL, 0}};
static const dev_member_t DEV_ENUM_1[] = {
    {"none", 0}, {"gpio", 1}, {"threshold", 2}, {"combination", 3}, {NULL, 0}};
static const dev_member_t DEV_ENUM_2[] = {{"none", 0}, {"gpio", 1}, {"message", 2}, {NULL, 0}};
static const dev_member_t DEV_ENUM_3[] = {{"unused", 0},    {"gpio", 1}, {"pps", 2}, {"encoder", 3},
                                          {"timestamp", 4}, {"uart", 5}, {NULL, 0}};
static const dev_member_t DEV_ENUM_4[] = {{"disabled", 0}, {"quadrature", 2}, {NULL, 0}};
static const dev_member_t DEV_ENUM_5[] = {{"all", 0}, {"accel", 1}, {"gyro", 2},
                                          {"mag", 3}, {"press", 4}, {NULL, 0}};
static const dev_member_t DEV_ENUM_6[] = {{"imu", 1}, {"estimation_filter", 3}, {NULL, 0}};
static const dev_member_t DEV_ENUM_7[] = {{"none", 0}, {"enabled", 1}, {NULL, 0}};
static const dev_member_t DEV_ENUM_8[] = {{"disabled", 0}, {"receiver_1", 1}, {"receiver_2", 2},
                                          {"gpio", 3},     {"generated", 4},  {NULL, 0}};
static const dev_member_t DEV_ENUM_9[] = {
    {"portable", 1}, {"automotive", 2}, {"airborne", 3}, {"airborne_high_g", 4}, {NULL, 0}};
static const dev_member_t DEV_ENUM_10[] = {
    {"all_internal", 1}, {"external", 2}, {"internal_1", 3}, {"internal_2", 4}, {NULL, 0}};
static const dev_member_t DEV_ENUM_11[] = {{"none", 0},
                                           {"magnetometer", 1},
                                           {"gnss_velocity", 2},
                                           {"external", 3},
                                           {"gnss_velocity_and_magnetometer", 4},
                                           {"gnss_velocity_and_external", 5},
                                           {"magnetometer_and_external", 6},
                                           {"gnss_velocity_magnetometer_and_external", 7},
                                           {NULL, 0}};
static const dev_member_t DEV_ENUM_12[] = {{"none", 1}, {"wmm", 2}, {"manual", 3}, {NULL, 0}};
static const dev_member_t DEV_ENUM_13[] = {{"disabled", 0}, {"fixed", 1}, {"auto", 2}, {NULL, 0}};
static const dev_member_t DEV_ENUM_14[] = {{"none", 0}, {"pressure", 1}, {NULL, 0}};
static const dev_member_t DEV_ENUM_15[] = {{"none", 0}, {"gravity_vector", 1}, {NULL, 0}};
static const dev_member_t DEV_ENUM_16[] = {{"gnss_pos_vel", 0},
                                           {"gnss_heading", 1},
                                           {"altimeter", 2},
                                           {"speed", 3},
                                           {"magnetometer", 4},
                                           {"external_heading", 5},
                                           {"external_altimeter", 6},
                                           {"external_magnetometer", 7},
                                           {"body_frame_vel", 8},
                                           {"all", 65535},
                                           {NULL, 0}};
static const dev_member_t DEV_ENUM_17[] = {
    {"auto_pos_vel_att", 0}, {"auto_pos_vel_pitch_roll", 1}, {"auto_pos_vel", 2}, {"manual", 3}, {NULL, 0}};
static const dev_member_t DEV_ENUM_18[] = {{"ecef", 1}, {"llh", 2}, {NULL, 0}};
static const dev_member_t DEV_ENUM_19[] = {
    {"off", 0}, {"conservative", 1}, {"moderate", 2}, {"aggressive", 3}, {NULL, 0}};
static const dev_member_t DEV_ENUM_20[] = {{"auto", 0}, {"manual", 1}, {NULL, 0}};
static const dev_member_t DEV_ENUM_21[] = {{"veh", 1}, {NULL, 0}};
static const dev_member_t DEV_ENUM_22[] = {{"none", 0}, {"network", 1}, {"l_band", 2}, {NULL, 0}};
static const dev_member_t DEV_ENUM_23[] = {{"euler", 1}, {"quaternion", 2}, {NULL, 0}};
static const dev_member_t DEV_ENUM_24[] = {{"suppress_ack", 0}, {"standard", 1}, {"response", 2}, {NULL, 0}};
static const dev_member_t DEV_ENUM_25[] = {{"ok", 0},
                                           {"unknown_command", 1},
                                           {"bad_checksum", 2},
                                           {"invalid_parameter", 3},
                                           {"command_failed", 4},
                                           {"command_timeout", 5},
                                           {"unknown_descriptor_set", 6},
                                           {NULL, 0}};
static const dev_enum_t DEV_ENUMS[] = {{"EventControlMode", DEV_ENUM_0, 4u},
                                       {"TriggerType", DEV_ENUM_1, 4u},
                                       {"ActionType", DEV_ENUM_2, 3u},
                                       {"GpioFeature", DEV_ENUM_3, 6u},
                                       {"OdometerMode", DEV_ENUM_4, 2u},
                                       {"SensorRangeType", DEV_ENUM_5, 5u},
                                       {"Gx5StreamSelector", DEV_ENUM_6, 2u},
                                       {"AssistedFixOption", DEV_ENUM_7, 2u},
                                       {"PpsSource", DEV_ENUM_8, 5u},
                                       {"VehicleDynamicsMode", DEV_ENUM_9, 4u},
                                       {"FilterGnssSource", DEV_ENUM_10, 4u},
                                       {"HeadingUpdateSource", DEV_ENUM_11, 8u},
                                       {"MagneticParamSource", DEV_ENUM_12, 3u},
                                       {"AdaptiveMeasurementMode", DEV_ENUM_13, 3u},
                                       {"AltitudeAidingSource", DEV_ENUM_14, 2u},
                                       {"PitchRollAidingSource", DEV_ENUM_15, 2u},
                                       {"AidingMeasurementSource", DEV_ENUM_16, 10u},
                                       {"FilterInitialConditionSource", DEV_ENUM_17, 4u},
                                       {"FilterReferenceFrame", DEV_ENUM_18, 2u},
                                       {"AdaptiveFilterLevel", DEV_ENUM_19, 4u},
                                       {"RelativePositionSource", DEV_ENUM_20, 2u},
                                       {"ReferencePointSelector", DEV_ENUM_21, 1u},
                                       {"SpartnConnectionType", DEV_ENUM_22, 3u},
                                       {"AidingFrameFormat", DEV_ENUM_23, 2u},
                                       {"AidingEchoMode", DEV_ENUM_24, 3u},
                                       {"AckCode", DEV_ENUM_25, 7u},
                                       {NULL, NULL, 0}};
/* the ack code's enum (NACK messages), -1: none */
#define DEV_ACK_ENUM (25)

static const char *const DEV_KEYED_gx5_45_0[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_0[] = {{"bias", "bias", "g", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_0[] = {NULL};
static const char *const DEV_FILL_gx5_45_0[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_0[] = {0};
static const int64_t DEV_KEYS_gx5_45_0[] = {0};
static const char *const DEV_KEYED_gx5_45_1[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_1[] = {{"bias", "bias", "rad/s", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_1[] = {NULL};
static const char *const DEV_FILL_gx5_45_1[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_1[] = {0};
static const int64_t DEV_KEYS_gx5_45_1[] = {0};
static const char *const DEV_KEYED_gx5_45_2[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_2[] = {{"offset", "offset", "gauss", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_2[] = {NULL};
static const char *const DEV_FILL_gx5_45_2[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_2[] = {0};
static const int64_t DEV_KEYS_gx5_45_2[] = {0};
static const char *const DEV_KEYED_gx5_45_3[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_3[] = {{"matrix", "matrix", NULL, -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_3[] = {NULL};
static const char *const DEV_FILL_gx5_45_3[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_3[] = {0};
static const int64_t DEV_KEYS_gx5_45_3[] = {0};
static const char *const DEV_KEYED_gx5_45_4[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_4[] = {{"enable", "enable", NULL, -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_4[] = {NULL};
static const char *const DEV_FILL_gx5_45_4[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_4[] = {0};
static const int64_t DEV_KEYS_gx5_45_4[] = {0};
static const char *const DEV_KEYED_gx5_45_5[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_5[] = {{"baud", "baud", "bit/s", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_5[] = {NULL};
static const char *const DEV_FILL_gx5_45_5[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_5[] = {0};
static const int64_t DEV_KEYS_gx5_45_5[] = {0};
static const char *const DEV_KEYED_gx5_45_6[] = {"target_descriptor", NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_6[] = {{"target_descriptor", "target_descriptor", NULL, -1},
                                                {"enable", "enable", NULL, -1},
                                                {"manual", "manual", NULL, -1},
                                                {"frequency", "frequency", "Hz", -1},
                                                {"reserved", "reserved", NULL, -1},
                                                {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_6[] = {NULL};
static const char *const DEV_FILL_gx5_45_6[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_6[] = {0};
static const int64_t DEV_KEYS_gx5_45_6[] = {4, 5, 6, 23, 0};
static const char *const DEV_KEYED_gx5_45_7[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_7[] = {
    {"pitch_roll_enable", "pitch_roll_enable", NULL, -1},
    {"heading_enable", "heading_enable", NULL, -1},
    {"pitch_roll_time_constant", "pitch_roll_time_constant", "s", -1},
    {"heading_time_constant", "heading_time_constant", "s", -1},
    {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_7[] = {NULL};
static const char *const DEV_FILL_gx5_45_7[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_7[] = {0};
static const int64_t DEV_KEYS_gx5_45_7[] = {0};
static const char *const DEV_KEYED_gx5_45_8[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_8[] = {{"descriptors", "descriptors", NULL, -1},
                                                {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_8[] = {"num_descriptors", "descriptors", NULL};
static const char *const DEV_FILL_gx5_45_8[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_8[] = {0};
static const int64_t DEV_KEYS_gx5_45_8[] = {0};
static const char *const DEV_KEYED_gx5_45_9[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_9[] = {{"descriptors", "descriptors", NULL, -1},
                                                {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_9[] = {"num_descriptors", "descriptors", NULL};
static const char *const DEV_FILL_gx5_45_9[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_9[] = {0};
static const int64_t DEV_KEYS_gx5_45_9[] = {0};
static const char *const DEV_KEYED_gx5_45_10[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_10[] = {{"descriptors", "descriptors", NULL, -1},
                                                 {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_10[] = {"num_descriptors", "descriptors", NULL};
static const char *const DEV_FILL_gx5_45_10[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_10[] = {0};
static const int64_t DEV_KEYS_gx5_45_10[] = {0};
static const char *const DEV_KEYED_gx5_45_11[] = {"device_selector", NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_11[] = {
    {"device_selector", "device_selector", NULL, 6}, {"enable", "enabled", NULL, -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_11[] = {NULL};
static const char *const DEV_FILL_gx5_45_11[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_11[] = {0};
static const int64_t DEV_KEYS_gx5_45_11[] = {1, 3, 0};
static const char *const DEV_KEYED_gx5_45_12[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_12[] = {
    {"max_channels", "max_channels", NULL, -1}, {"settings", "settings", NULL, -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_12[] = {"config_count", "settings", NULL};
static const char *const DEV_FILL_gx5_45_12[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_12[] = {0};
static const int64_t DEV_KEYS_gx5_45_12[] = {0};
static const char *const DEV_KEYED_gx5_45_13[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_13[] = {{"enable_sbas", "enable_sbas", NULL, -1},
                                                 {"sbas_options", "sbas_options", NULL, -1},
                                                 {"included_prns", "included_prns", NULL, -1},
                                                 {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_13[] = {"num_included_prns", "included_prns", NULL};
static const char *const DEV_FILL_gx5_45_13[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_13[] = {0};
static const int64_t DEV_KEYS_gx5_45_13[] = {0};
static const char *const DEV_KEYED_gx5_45_14[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_14[] = {
    {"option", "option", NULL, 7}, {"flags", "flags", NULL, -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_14[] = {NULL};
static const char *const DEV_FILL_gx5_45_14[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_14[] = {0};
static const int64_t DEV_KEYS_gx5_45_14[] = {0};
static const char *const DEV_KEYED_gx5_45_15[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_15[] = {{"mode", "mode", NULL, 9}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_15[] = {NULL};
static const char *const DEV_FILL_gx5_45_15[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_15[] = {0};
static const int64_t DEV_KEYS_gx5_45_15[] = {0};
static const char *const DEV_KEYED_gx5_45_16[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_16[] = {{"roll", "roll", "rad", -1},
                                                 {"pitch", "pitch", "rad", -1},
                                                 {"yaw", "yaw", "rad", -1},
                                                 {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_16[] = {NULL};
static const char *const DEV_FILL_gx5_45_16[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_16[] = {0};
static const int64_t DEV_KEYS_gx5_45_16[] = {0};
static const char *const DEV_KEYED_gx5_45_17[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_17[] = {{"offset", "offset", "m", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_17[] = {NULL};
static const char *const DEV_FILL_gx5_45_17[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_17[] = {0};
static const int64_t DEV_KEYS_gx5_45_17[] = {0};
static const char *const DEV_KEYED_gx5_45_18[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_18[] = {{"offset", "offset", "m", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_18[] = {NULL};
static const char *const DEV_FILL_gx5_45_18[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_18[] = {0};
static const int64_t DEV_KEYS_gx5_45_18[] = {0};
static const char *const DEV_KEYED_gx5_45_19[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_19[] = {{"flags", "flags", NULL, -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_19[] = {NULL};
static const char *const DEV_FILL_gx5_45_19[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_19[] = {0};
static const int64_t DEV_KEYS_gx5_45_19[] = {0};
static const char *const DEV_KEYED_gx5_45_20[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_20[] = {{"source", "source", NULL, 10}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_20[] = {NULL};
static const char *const DEV_FILL_gx5_45_20[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_20[] = {0};
static const int64_t DEV_KEYS_gx5_45_20[] = {0};
static const char *const DEV_KEYED_gx5_45_21[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_21[] = {{"source", "source", NULL, 11}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_21[] = {NULL};
static const char *const DEV_FILL_gx5_45_21[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_21[] = {0};
static const int64_t DEV_KEYS_gx5_45_21[] = {0};
static const char *const DEV_KEYED_gx5_45_22[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_22[] = {{"enable", "enable", NULL, -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_22[] = {NULL};
static const char *const DEV_FILL_gx5_45_22[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_22[] = {0};
static const int64_t DEV_KEYS_gx5_45_22[] = {0};
static const char *const DEV_KEYED_gx5_45_23[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_23[] = {{"noise", "noise", "m/s^2", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_23[] = {NULL};
static const char *const DEV_FILL_gx5_45_23[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_23[] = {0};
static const int64_t DEV_KEYS_gx5_45_23[] = {0};
static const char *const DEV_KEYED_gx5_45_24[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_24[] = {{"noise", "noise", "rad/s", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_24[] = {NULL};
static const char *const DEV_FILL_gx5_45_24[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_24[] = {0};
static const int64_t DEV_KEYS_gx5_45_24[] = {0};
static const char *const DEV_KEYED_gx5_45_25[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_25[] = {
    {"beta", "beta", "1/s", -1}, {"noise", "noise", "m/s^2", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_25[] = {NULL};
static const char *const DEV_FILL_gx5_45_25[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_25[] = {0};
static const int64_t DEV_KEYS_gx5_45_25[] = {0};
static const char *const DEV_KEYED_gx5_45_26[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_26[] = {
    {"beta", "beta", "1/s", -1}, {"noise", "noise", "rad/s", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_26[] = {NULL};
static const char *const DEV_FILL_gx5_45_26[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_26[] = {0};
static const int64_t DEV_KEYS_gx5_45_26[] = {0};
static const char *const DEV_KEYED_gx5_45_27[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_27[] = {
    {"enable", "enable", NULL, -1}, {"threshold", "threshold", "m/s", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_27[] = {NULL};
static const char *const DEV_FILL_gx5_45_27[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_27[] = {0};
static const int64_t DEV_KEYS_gx5_45_27[] = {0};
static const char *const DEV_KEYED_gx5_45_28[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_28[] = {
    {"enable", "enable", NULL, -1}, {"threshold", "threshold", "rad/s", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_28[] = {NULL};
static const char *const DEV_FILL_gx5_45_28[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_28[] = {0};
static const int64_t DEV_KEYS_gx5_45_28[] = {0};
static const char *const DEV_KEYED_gx5_45_29[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_29[] = {{"noise", "noise", "g", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_29[] = {NULL};
static const char *const DEV_FILL_gx5_45_29[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_29[] = {0};
static const int64_t DEV_KEYS_gx5_45_29[] = {0};
static const char *const DEV_KEYED_gx5_45_30[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_30[] = {{"noise", "noise", "m", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_30[] = {NULL};
static const char *const DEV_FILL_gx5_45_30[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_30[] = {0};
static const int64_t DEV_KEYS_gx5_45_30[] = {0};
static const char *const DEV_KEYED_gx5_45_31[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_31[] = {{"noise", "noise", "gauss", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_31[] = {NULL};
static const char *const DEV_FILL_gx5_45_31[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_31[] = {0};
static const int64_t DEV_KEYS_gx5_45_31[] = {0};
static const char *const DEV_KEYED_gx5_45_32[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_32[] = {{"noise", "noise", NULL, -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_32[] = {NULL};
static const char *const DEV_FILL_gx5_45_32[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_32[] = {0};
static const int64_t DEV_KEYS_gx5_45_32[] = {0};
static const char *const DEV_KEYED_gx5_45_33[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_33[] = {{"noise", "noise", "gauss", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_33[] = {NULL};
static const char *const DEV_FILL_gx5_45_33[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_33[] = {0};
static const int64_t DEV_KEYS_gx5_45_33[] = {0};
static const char *const DEV_KEYED_gx5_45_34[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_34[] = {
    {"source", "source", NULL, 12}, {"declination", "declination", "rad", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_34[] = {NULL};
static const char *const DEV_FILL_gx5_45_34[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_34[] = {0};
static const int64_t DEV_KEYS_gx5_45_34[] = {0};
static const char *const DEV_KEYED_gx5_45_35[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_35[] = {
    {"mode", "mode", NULL, 13},
    {"frequency", "frequency", "Hz", -1},
    {"low_limit", "low_limit", "m/s^2", -1},
    {"high_limit", "high_limit", "m/s^2", -1},
    {"low_limit_uncertainty", "low_limit_uncertainty", "m/s^2", -1},
    {"high_limit_uncertainty", "high_limit_uncertainty", "m/s^2", -1},
    {"minimum_uncertainty", "minimum_uncertainty", "m/s^2", -1},
    {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_35[] = {NULL};
static const char *const DEV_FILL_gx5_45_35[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_35[] = {0};
static const int64_t DEV_KEYS_gx5_45_35[] = {0};
static const char *const DEV_KEYED_gx5_45_36[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_36[] = {
    {"mode", "mode", NULL, 13},
    {"frequency", "frequency", "Hz", -1},
    {"low_limit", "low_limit", "gauss", -1},
    {"high_limit", "high_limit", "gauss", -1},
    {"low_limit_uncertainty", "low_limit_uncertainty", "gauss", -1},
    {"high_limit_uncertainty", "high_limit_uncertainty", "gauss", -1},
    {"minimum_uncertainty", "minimum_uncertainty", "gauss", -1},
    {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_36[] = {NULL};
static const char *const DEV_FILL_gx5_45_36[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_36[] = {0};
static const int64_t DEV_KEYS_gx5_45_36[] = {0};
static const char *const DEV_KEYED_gx5_45_37[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_37[] = {
    {"mode", "mode", NULL, 13},
    {"frequency", "frequency", "Hz", -1},
    {"high_limit", "high_limit", "rad", -1},
    {"high_limit_uncertainty", "high_limit_uncertainty", "rad", -1},
    {"minimum_uncertainty", "minimum_uncertainty", "rad", -1},
    {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_37[] = {NULL};
static const char *const DEV_FILL_gx5_45_37[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_37[] = {0};
static const int64_t DEV_KEYS_gx5_45_37[] = {0};
static const char *const DEV_KEYED_gx5_45_38[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_38[] = {{"source", "source", NULL, 14}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_38[] = {NULL};
static const char *const DEV_FILL_gx5_45_38[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_38[] = {0};
static const int64_t DEV_KEYS_gx5_45_38[] = {0};
static const char *const DEV_KEYED_gx5_45_39[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_39[] = {{"source", "source", NULL, 15}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_39[] = {NULL};
static const char *const DEV_FILL_gx5_45_39[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_39[] = {0};
static const int64_t DEV_KEYS_gx5_45_39[] = {0};
static const char *const DEV_KEYED_gx5_45_40[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_40[] = {
    {"source", "source", NULL, 12}, {"inclination", "inclination", "rad", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_40[] = {NULL};
static const char *const DEV_FILL_gx5_45_40[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_40[] = {0};
static const int64_t DEV_KEYS_gx5_45_40[] = {0};
static const char *const DEV_KEYED_gx5_45_41[] = {NULL};
static const dev_attr_t DEV_ATTRS_gx5_45_41[] = {
    {"source", "source", NULL, 12}, {"magnitude", "magnitude", "gauss", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_gx5_45_41[] = {NULL};
static const char *const DEV_FILL_gx5_45_41[] = {NULL};
static const unsigned char DEV_FILL_LIST_gx5_45_41[] = {0};
static const int64_t DEV_KEYS_gx5_45_41[] = {0};
static const dev_setting_t DEV_SETTINGS_gx5_45[] = {
    {"accel_bias", 12, 55, "gx5_45", "accel_bias_response", DEV_KEYED_gx5_45_0, 0u, DEV_ATTRS_gx5_45_0, 1u,
     DEV_COUNTS_gx5_45_0, 0u, DEV_FILL_gx5_45_0, DEV_FILL_LIST_gx5_45_0, 0u, DEV_KEYS_gx5_45_0, 1u},
    {"gyro_bias", 12, 56, "gx5_45", "gyro_bias_response", DEV_KEYED_gx5_45_1, 0u, DEV_ATTRS_gx5_45_1, 1u,
     DEV_COUNTS_gx5_45_1, 0u, DEV_FILL_gx5_45_1, DEV_FILL_LIST_gx5_45_1, 0u, DEV_KEYS_gx5_45_1, 1u},
    {"mag_hard_iron_offset", 12, 58, "gx5_45", "mag_hard_iron_offset_response", DEV_KEYED_gx5_45_2, 0u,
     DEV_ATTRS_gx5_45_2, 1u, DEV_COUNTS_gx5_45_2, 0u, DEV_FILL_gx5_45_2, DEV_FILL_LIST_gx5_45_2, 0u,
     DEV_KEYS_gx5_45_2, 1u},
    {"mag_soft_iron_matrix", 12, 59, "gx5_45", "mag_soft_iron_matrix_response", DEV_KEYED_gx5_45_3, 0u,
     DEV_ATTRS_gx5_45_3, 1u, DEV_COUNTS_gx5_45_3, 0u, DEV_FILL_gx5_45_3, DEV_FILL_LIST_gx5_45_3, 0u,
     DEV_KEYS_gx5_45_3, 1u},
    {"coning_sculling_enable", 12, 62, NULL, "coning_sculling_enable_response", DEV_KEYED_gx5_45_4, 0u,
     DEV_ATTRS_gx5_45_4, 1u, DEV_COUNTS_gx5_45_4, 0u, DEV_FILL_gx5_45_4, DEV_FILL_LIST_gx5_45_4, 0u,
     DEV_KEYS_gx5_45_4, 1u},
    {"uart_baudrate", 12, 64, NULL, "uart_baudrate_response", DEV_KEYED_gx5_45_5, 0u, DEV_ATTRS_gx5_45_5, 1u,
     DEV_COUNTS_gx5_45_5, 0u, DEV_FILL_gx5_45_5, DEV_FILL_LIST_gx5_45_5, 0u, DEV_KEYS_gx5_45_5, 1u},
    {"advanced_lowpass_filter", 12, 80, NULL, "advanced_lowpass_filter_response", DEV_KEYED_gx5_45_6, 1u,
     DEV_ATTRS_gx5_45_6, 5u, DEV_COUNTS_gx5_45_6, 0u, DEV_FILL_gx5_45_6, DEV_FILL_LIST_gx5_45_6, 0u,
     DEV_KEYS_gx5_45_6, 4u},
    {"complementary_filter", 12, 81, NULL, "complementary_filter_response", DEV_KEYED_gx5_45_7, 0u,
     DEV_ATTRS_gx5_45_7, 4u, DEV_COUNTS_gx5_45_7, 0u, DEV_FILL_gx5_45_7, DEV_FILL_LIST_gx5_45_7, 0u,
     DEV_KEYS_gx5_45_7, 1u},
    {"imu_message_format", 12, 8, NULL, "imu_message_format_response", DEV_KEYED_gx5_45_8, 0u,
     DEV_ATTRS_gx5_45_8, 1u, DEV_COUNTS_gx5_45_8, 1u, DEV_FILL_gx5_45_8, DEV_FILL_LIST_gx5_45_8, 0u,
     DEV_KEYS_gx5_45_8, 1u},
    {"gnss_message_format", 12, 9, NULL, "gnss_message_format_response", DEV_KEYED_gx5_45_9, 0u,
     DEV_ATTRS_gx5_45_9, 1u, DEV_COUNTS_gx5_45_9, 1u, DEV_FILL_gx5_45_9, DEV_FILL_LIST_gx5_45_9, 0u,
     DEV_KEYS_gx5_45_9, 1u},
    {"filter_message_format", 12, 10, NULL, "filter_message_format_response", DEV_KEYED_gx5_45_10, 0u,
     DEV_ATTRS_gx5_45_10, 1u, DEV_COUNTS_gx5_45_10, 1u, DEV_FILL_gx5_45_10, DEV_FILL_LIST_gx5_45_10, 0u,
     DEV_KEYS_gx5_45_10, 1u},
    {"data_stream_control", 12, 17, "gx5_45", "data_stream_control_response", DEV_KEYED_gx5_45_11, 1u,
     DEV_ATTRS_gx5_45_11, 2u, DEV_COUNTS_gx5_45_11, 0u, DEV_FILL_gx5_45_11, DEV_FILL_LIST_gx5_45_11, 0u,
     DEV_KEYS_gx5_45_11, 2u},
    {"gnss_constellation_settings", 12, 33, NULL, "gnss_constellation_settings_response", DEV_KEYED_gx5_45_12,
     0u, DEV_ATTRS_gx5_45_12, 2u, DEV_COUNTS_gx5_45_12, 1u, DEV_FILL_gx5_45_12, DEV_FILL_LIST_gx5_45_12, 0u,
     DEV_KEYS_gx5_45_12, 1u},
    {"gnss_sbas_settings", 12, 34, NULL, "gnss_sbas_settings_response", DEV_KEYED_gx5_45_13, 0u,
     DEV_ATTRS_gx5_45_13, 3u, DEV_COUNTS_gx5_45_13, 1u, DEV_FILL_gx5_45_13, DEV_FILL_LIST_gx5_45_13, 0u,
     DEV_KEYS_gx5_45_13, 1u},
    {"gnss_assisted_fix_control", 12, 35, NULL, "gnss_assisted_fix_control_response", DEV_KEYED_gx5_45_14, 0u,
     DEV_ATTRS_gx5_45_14, 2u, DEV_COUNTS_gx5_45_14, 0u, DEV_FILL_gx5_45_14, DEV_FILL_LIST_gx5_45_14, 0u,
     DEV_KEYS_gx5_45_14, 1u},
    {"vehicle_dynamics_mode", 13, 16, NULL, "vehicle_dynamics_mode_response", DEV_KEYED_gx5_45_15, 0u,
     DEV_ATTRS_gx5_45_15, 1u, DEV_COUNTS_gx5_45_15, 0u, DEV_FILL_gx5_45_15, DEV_FILL_LIST_gx5_45_15, 0u,
     DEV_KEYS_gx5_45_15, 1u},
    {"sensor_to_vehicle_transform", 13, 17, NULL, "sensor_to_vehicle_transform_response", DEV_KEYED_gx5_45_16,
     0u, DEV_ATTRS_gx5_45_16, 3u, DEV_COUNTS_gx5_45_16, 0u, DEV_FILL_gx5_45_16, DEV_FILL_LIST_gx5_45_16, 0u,
     DEV_KEYS_gx5_45_16, 1u},
    {"sensor_to_vehicle_offset", 13, 18, NULL, "sensor_to_vehicle_offset_response", DEV_KEYED_gx5_45_17, 0u,
     DEV_ATTRS_gx5_45_17, 1u, DEV_COUNTS_gx5_45_17, 0u, DEV_FILL_gx5_45_17, DEV_FILL_LIST_gx5_45_17, 0u,
     DEV_KEYS_gx5_45_17, 1u},
    {"antenna_offset", 13, 19, NULL, "antenna_offset_response", DEV_KEYED_gx5_45_18, 0u, DEV_ATTRS_gx5_45_18,
     1u, DEV_COUNTS_gx5_45_18, 0u, DEV_FILL_gx5_45_18, DEV_FILL_LIST_gx5_45_18, 0u, DEV_KEYS_gx5_45_18, 1u},
    {"estimation_control", 13, 20, NULL, "estimation_control_response", DEV_KEYED_gx5_45_19, 0u,
     DEV_ATTRS_gx5_45_19, 1u, DEV_COUNTS_gx5_45_19, 0u, DEV_FILL_gx5_45_19, DEV_FILL_LIST_gx5_45_19, 0u,
     DEV_KEYS_gx5_45_19, 1u},
    {"gnss_source_control", 13, 21, NULL, "gnss_source_control_response", DEV_KEYED_gx5_45_20, 0u,
     DEV_ATTRS_gx5_45_20, 1u, DEV_COUNTS_gx5_45_20, 0u, DEV_FILL_gx5_45_20, DEV_FILL_LIST_gx5_45_20, 0u,
     DEV_KEYS_gx5_45_20, 1u},
    {"heading_update_control", 13, 24, NULL, "heading_update_control_response", DEV_KEYED_gx5_45_21, 0u,
     DEV_ATTRS_gx5_45_21, 1u, DEV_COUNTS_gx5_45_21, 0u, DEV_FILL_gx5_45_21, DEV_FILL_LIST_gx5_45_21, 0u,
     DEV_KEYS_gx5_45_21, 1u},
    {"auto_init_control", 13, 25, NULL, "auto_init_control_response", DEV_KEYED_gx5_45_22, 0u,
     DEV_ATTRS_gx5_45_22, 1u, DEV_COUNTS_gx5_45_22, 0u, DEV_FILL_gx5_45_22, DEV_FILL_LIST_gx5_45_22, 0u,
     DEV_KEYS_gx5_45_22, 1u},
    {"accel_noise", 13, 26, NULL, "accel_noise_response", DEV_KEYED_gx5_45_23, 0u, DEV_ATTRS_gx5_45_23, 1u,
     DEV_COUNTS_gx5_45_23, 0u, DEV_FILL_gx5_45_23, DEV_FILL_LIST_gx5_45_23, 0u, DEV_KEYS_gx5_45_23, 1u},
    {"gyro_noise", 13, 27, NULL, "gyro_noise_response", DEV_KEYED_gx5_45_24, 0u, DEV_ATTRS_gx5_45_24, 1u,
     DEV_COUNTS_gx5_45_24, 0u, DEV_FILL_gx5_45_24, DEV_FILL_LIST_gx5_45_24, 0u, DEV_KEYS_gx5_45_24, 1u},
    {"accel_bias_model", 13, 28, NULL, "accel_bias_model_response", DEV_KEYED_gx5_45_25, 0u,
     DEV_ATTRS_gx5_45_25, 2u, DEV_COUNTS_gx5_45_25, 0u, DEV_FILL_gx5_45_25, DEV_FILL_LIST_gx5_45_25, 0u,
     DEV_KEYS_gx5_45_25, 1u},
    {"gyro_bias_model", 13, 29, NULL, "gyro_bias_model_response", DEV_KEYED_gx5_45_26, 0u,
     DEV_ATTRS_gx5_45_26, 2u, DEV_COUNTS_gx5_45_26, 0u, DEV_FILL_gx5_45_26, DEV_FILL_LIST_gx5_45_26, 0u,
     DEV_KEYS_gx5_45_26, 1u},
    {"zupt_control", 13, 30, NULL, "zupt_control_response", DEV_KEYED_gx5_45_27, 0u, DEV_ATTRS_gx5_45_27, 2u,
     DEV_COUNTS_gx5_45_27, 0u, DEV_FILL_gx5_45_27, DEV_FILL_LIST_gx5_45_27, 0u, DEV_KEYS_gx5_45_27, 1u},
    {"zero_angular_rate_update_control", 13, 32, NULL, "zero_angular_rate_update_control_response",
     DEV_KEYED_gx5_45_28, 0u, DEV_ATTRS_gx5_45_28, 2u, DEV_COUNTS_gx5_45_28, 0u, DEV_FILL_gx5_45_28,
     DEV_FILL_LIST_gx5_45_28, 0u, DEV_KEYS_gx5_45_28, 1u},
    {"gravity_noise_std_dev", 13, 40, NULL, "gravity_noise_std_dev_response", DEV_KEYED_gx5_45_29, 0u,
     DEV_ATTRS_gx5_45_29, 1u, DEV_COUNTS_gx5_45_29, 0u, DEV_FILL_gx5_45_29, DEV_FILL_LIST_gx5_45_29, 0u,
     DEV_KEYS_gx5_45_29, 1u},
    {"pressure_altitude_noise_std_dev", 13, 41, NULL, "pressure_altitude_noise_std_dev_response",
     DEV_KEYED_gx5_45_30, 0u, DEV_ATTRS_gx5_45_30, 1u, DEV_COUNTS_gx5_45_30, 0u, DEV_FILL_gx5_45_30,
     DEV_FILL_LIST_gx5_45_30, 0u, DEV_KEYS_gx5_45_30, 1u},
    {"hard_iron_offset_noise", 13, 43, NULL, "hard_iron_offset_noise_response", DEV_KEYED_gx5_45_31, 0u,
     DEV_ATTRS_gx5_45_31, 1u, DEV_COUNTS_gx5_45_31, 0u, DEV_FILL_gx5_45_31, DEV_FILL_LIST_gx5_45_31, 0u,
     DEV_KEYS_gx5_45_31, 1u},
    {"soft_iron_matrix_noise", 13, 44, NULL, "soft_iron_matrix_noise_response", DEV_KEYED_gx5_45_32, 0u,
     DEV_ATTRS_gx5_45_32, 1u, DEV_COUNTS_gx5_45_32, 0u, DEV_FILL_gx5_45_32, DEV_FILL_LIST_gx5_45_32, 0u,
     DEV_KEYS_gx5_45_32, 1u},
    {"mag_noise_std_dev", 13, 66, NULL, "mag_noise_std_dev_response", DEV_KEYED_gx5_45_33, 0u,
     DEV_ATTRS_gx5_45_33, 1u, DEV_COUNTS_gx5_45_33, 0u, DEV_FILL_gx5_45_33, DEV_FILL_LIST_gx5_45_33, 0u,
     DEV_KEYS_gx5_45_33, 1u},
    {"declination_source", 13, 67, NULL, "declination_source_response", DEV_KEYED_gx5_45_34, 0u,
     DEV_ATTRS_gx5_45_34, 2u, DEV_COUNTS_gx5_45_34, 0u, DEV_FILL_gx5_45_34, DEV_FILL_LIST_gx5_45_34, 0u,
     DEV_KEYS_gx5_45_34, 1u},
    {"gravity_magnitude_adaptive_measurement", 13, 68, NULL,
     "gravity_magnitude_adaptive_measurement_response", DEV_KEYED_gx5_45_35, 0u, DEV_ATTRS_gx5_45_35, 7u,
     DEV_COUNTS_gx5_45_35, 0u, DEV_FILL_gx5_45_35, DEV_FILL_LIST_gx5_45_35, 0u, DEV_KEYS_gx5_45_35, 1u},
    {"mag_magnitude_adaptive_measurement", 13, 69, NULL, "mag_magnitude_adaptive_measurement_response",
     DEV_KEYED_gx5_45_36, 0u, DEV_ATTRS_gx5_45_36, 7u, DEV_COUNTS_gx5_45_36, 0u, DEV_FILL_gx5_45_36,
     DEV_FILL_LIST_gx5_45_36, 0u, DEV_KEYS_gx5_45_36, 1u},
    {"mag_dip_angle_adaptive_measurement", 13, 70, NULL, "mag_dip_angle_adaptive_measurement_response",
     DEV_KEYED_gx5_45_37, 0u, DEV_ATTRS_gx5_45_37, 5u, DEV_COUNTS_gx5_45_37, 0u, DEV_FILL_gx5_45_37,
     DEV_FILL_LIST_gx5_45_37, 0u, DEV_KEYS_gx5_45_37, 1u},
    {"altitude_aiding_control", 13, 71, NULL, "altitude_aiding_control_response", DEV_KEYED_gx5_45_38, 0u,
     DEV_ATTRS_gx5_45_38, 1u, DEV_COUNTS_gx5_45_38, 0u, DEV_FILL_gx5_45_38, DEV_FILL_LIST_gx5_45_38, 0u,
     DEV_KEYS_gx5_45_38, 1u},
    {"pitch_roll_aiding_control", 13, 75, NULL, "pitch_roll_aiding_control_response", DEV_KEYED_gx5_45_39, 0u,
     DEV_ATTRS_gx5_45_39, 1u, DEV_COUNTS_gx5_45_39, 0u, DEV_FILL_gx5_45_39, DEV_FILL_LIST_gx5_45_39, 0u,
     DEV_KEYS_gx5_45_39, 1u},
    {"inclination_source", 13, 76, NULL, "inclination_source_response", DEV_KEYED_gx5_45_40, 0u,
     DEV_ATTRS_gx5_45_40, 2u, DEV_COUNTS_gx5_45_40, 0u, DEV_FILL_gx5_45_40, DEV_FILL_LIST_gx5_45_40, 0u,
     DEV_KEYS_gx5_45_40, 1u},
    {"magnetic_field_magnitude_source", 13, 77, NULL, "magnetic_field_magnitude_source_response",
     DEV_KEYED_gx5_45_41, 0u, DEV_ATTRS_gx5_45_41, 2u, DEV_COUNTS_gx5_45_41, 0u, DEV_FILL_gx5_45_41,
     DEV_FILL_LIST_gx5_45_41, 0u, DEV_KEYS_gx5_45_41, 1u},
    {NULL, 0, 0, NULL, NULL, NULL, 0, NULL, 0, NULL, 0, NULL, NULL, 0, NULL, 0}};
static const dev_size_t DEV_SIZES_gx5_45[] = {
    {128, 4, 12},  {128, 5, 12},  {128, 6, 12},  {128, 7, 12},  {128, 8, 12},  {128, 9, 36},  {128, 10, 16},
    {128, 12, 12}, {128, 16, 12}, {128, 17, 12}, {128, 18, 12}, {128, 23, 4},  {129, 3, 42},  {129, 4, 30},
    {129, 5, 34},  {129, 6, 18},  {129, 7, 30},  {129, 8, 13},  {129, 9, 12},  {129, 10, 26}, {129, 11, 6},
    {129, 12, 12}, {129, 13, 5},  {129, 14, 12}, {129, 15, 15}, {130, 1, 26},  {130, 2, 14},  {130, 3, 18},
    {130, 4, 38},  {130, 5, 14},  {130, 6, 14},  {130, 7, 14},  {130, 8, 14},  {130, 9, 14},  {130, 10, 14},
    {130, 11, 14}, {130, 12, 14}, {130, 13, 14}, {130, 14, 14}, {130, 15, 6},  {130, 16, 6},  {130, 17, 12},
    {130, 18, 18}, {130, 19, 14}, {130, 20, 12}, {130, 21, 22}, {130, 22, 14}, {130, 23, 14}, {130, 24, 14},
    {130, 25, 14}, {130, 28, 14}, {130, 32, 22}, {130, 33, 6},  {130, 37, 14}, {130, 38, 38}, {130, 40, 14},
    {130, 41, 38}, {130, 48, 14}, {130, 49, 14}, {0, 0, 0}};
static const dev_rate_t DEV_BASE_RATES_gx5_45[] = {{128, 500}, {129, 4}, {130, 500}, {0, 0}};
static const uint8_t DEV_UNADDRESSED_gx5_45[] = {129, 0};
static const char *const DEV_KEYED_cv7_ins_0[] = {"port", NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_0[] = {
    {"port", "port", NULL, -1}, {"baud", "baud", "bit/s", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_0[] = {NULL};
static const char *const DEV_FILL_cv7_ins_0[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_0[] = {0};
static const int64_t DEV_KEYS_cv7_ins_0[] = {17, 18, 19, 0};
static const char *const DEV_KEYED_cv7_ins_1[] = {"instance", NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_1[] = {
    {"instance", "instance", NULL, -1}, {"mode", "mode", NULL, 0}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_1[] = {NULL};
static const char *const DEV_FILL_cv7_ins_1[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_1[] = {0};
static const int64_t DEV_KEYS_cv7_ins_1[] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 0};
static const char *const DEV_KEYED_cv7_ins_2[] = {"instance", NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_2[] = {{"instance", "instance", NULL, -1},
                                                 {"type", "type", NULL, 1},
                                                 {"parameters", "parameters", NULL, -1},
                                                 {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_2[] = {NULL};
static const char *const DEV_FILL_cv7_ins_2[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_2[] = {0};
static const int64_t DEV_KEYS_cv7_ins_2[] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 0};
static const char *const DEV_KEYED_cv7_ins_3[] = {"instance", NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_3[] = {{"instance", "instance", NULL, -1},
                                                 {"trigger", "trigger", NULL, -1},
                                                 {"type", "type", NULL, 2},
                                                 {"parameters", "parameters", NULL, -1},
                                                 {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_3[] = {NULL};
static const char *const DEV_FILL_cv7_ins_3[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_3[] = {0};
static const int64_t DEV_KEYS_cv7_ins_3[] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 0};
static const char *const DEV_KEYED_cv7_ins_4[] = {NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_4[] = {{"roll", "roll", "rad", -1},
                                                 {"pitch", "pitch", "rad", -1},
                                                 {"yaw", "yaw", "rad", -1},
                                                 {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_4[] = {NULL};
static const char *const DEV_FILL_cv7_ins_4[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_4[] = {0};
static const int64_t DEV_KEYS_cv7_ins_4[] = {0};
static const char *const DEV_KEYED_cv7_ins_5[] = {NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_5[] = {{"q", "q", NULL, -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_5[] = {NULL};
static const char *const DEV_FILL_cv7_ins_5[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_5[] = {0};
static const int64_t DEV_KEYS_cv7_ins_5[] = {0};
static const char *const DEV_KEYED_cv7_ins_6[] = {NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_6[] = {{"dcm", "dcm", NULL, -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_6[] = {NULL};
static const char *const DEV_FILL_cv7_ins_6[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_6[] = {0};
static const int64_t DEV_KEYS_cv7_ins_6[] = {0};
static const char *const DEV_KEYED_cv7_ins_7[] = {NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_7[] = {{"bias", "bias", "g", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_7[] = {NULL};
static const char *const DEV_FILL_cv7_ins_7[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_7[] = {0};
static const int64_t DEV_KEYS_cv7_ins_7[] = {0};
static const char *const DEV_KEYED_cv7_ins_8[] = {NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_8[] = {{"bias", "bias", "rad/s", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_8[] = {NULL};
static const char *const DEV_FILL_cv7_ins_8[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_8[] = {0};
static const int64_t DEV_KEYS_cv7_ins_8[] = {0};
static const char *const DEV_KEYED_cv7_ins_9[] = {NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_9[] = {{"offset", "offset", "gauss", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_9[] = {NULL};
static const char *const DEV_FILL_cv7_ins_9[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_9[] = {0};
static const int64_t DEV_KEYS_cv7_ins_9[] = {0};
static const char *const DEV_KEYED_cv7_ins_10[] = {NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_10[] = {{"matrix", "matrix", NULL, -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_10[] = {NULL};
static const char *const DEV_FILL_cv7_ins_10[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_10[] = {0};
static const int64_t DEV_KEYS_cv7_ins_10[] = {0};
static const char *const DEV_KEYED_cv7_ins_11[] = {NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_11[] = {{"baud", "baud", "bit/s", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_11[] = {NULL};
static const char *const DEV_FILL_cv7_ins_11[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_11[] = {0};
static const int64_t DEV_KEYS_cv7_ins_11[] = {0};
static const char *const DEV_KEYED_cv7_ins_12[] = {"pin", NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_12[] = {{"pin", "pin", NULL, -1},
                                                  {"feature", "feature", NULL, 3},
                                                  {"behavior", "behavior", NULL, -1},
                                                  {"pin_mode", "pin_mode", NULL, -1},
                                                  {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_12[] = {NULL};
static const char *const DEV_FILL_cv7_ins_12[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_12[] = {0};
static const int64_t DEV_KEYS_cv7_ins_12[] = {1, 2, 3, 4, 0};
static const char *const DEV_KEYED_cv7_ins_13[] = {NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_13[] = {{"mode", "mode", NULL, 4},
                                                  {"scaling", "scaling", "pulses/m", -1},
                                                  {"uncertainty", "uncertainty", "m/m", -1},
                                                  {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_13[] = {NULL};
static const char *const DEV_FILL_cv7_ins_13[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_13[] = {0};
static const int64_t DEV_KEYS_cv7_ins_13[] = {0};
static const char *const DEV_KEYED_cv7_ins_14[] = {"target_descriptor", NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_14[] = {{"target_descriptor", "target_descriptor", NULL, -1},
                                                  {"enable", "enable", NULL, -1},
                                                  {"manual", "manual", NULL, -1},
                                                  {"frequency", "frequency", "Hz", -1},
                                                  {"reserved", "reserved", NULL, -1},
                                                  {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_14[] = {NULL};
static const char *const DEV_FILL_cv7_ins_14[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_14[] = {0};
static const int64_t DEV_KEYS_cv7_ins_14[] = {4, 5, 6, 23, 0};
static const char *const DEV_KEYED_cv7_ins_15[] = {NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_15[] = {
    {"pitch_roll_enable", "pitch_roll_enable", NULL, -1},
    {"heading_enable", "heading_enable", NULL, -1},
    {"pitch_roll_time_constant", "pitch_roll_time_constant", "s", -1},
    {"heading_time_constant", "heading_time_constant", "s", -1},
    {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_15[] = {NULL};
static const char *const DEV_FILL_cv7_ins_15[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_15[] = {0};
static const int64_t DEV_KEYS_cv7_ins_15[] = {0};
static const char *const DEV_KEYED_cv7_ins_16[] = {"sensor", NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_16[] = {
    {"sensor", "sensor", NULL, 5}, {"setting", "setting", NULL, -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_16[] = {NULL};
static const char *const DEV_FILL_cv7_ins_16[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_16[] = {0};
static const int64_t DEV_KEYS_cv7_ins_16[] = {1, 2, 3, 4, 0};
static const char *const DEV_KEYED_cv7_ins_17[] = {"desc_set", "field_desc", NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_17[] = {
    {"desc_set", "desc_set", NULL, -1},   {"field_desc", "field_desc", NULL, -1},
    {"enable", "enable", NULL, -1},       {"manual", "manual", NULL, -1},
    {"frequency", "frequency", "Hz", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_17[] = {NULL};
static const char *const DEV_FILL_cv7_ins_17[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_17[] = {0};
static const int64_t DEV_KEYS_cv7_ins_17[] = {128, 4, 128, 5, 128, 6, 128, 23, 0};
static const char *const DEV_KEYED_cv7_ins_18[] = {NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_18[] = {{"format_entries", "format_entries", NULL, -1},
                                                  {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_18[] = {"count", "format_entries", NULL};
static const char *const DEV_FILL_cv7_ins_18[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_18[] = {0};
static const int64_t DEV_KEYS_cv7_ins_18[] = {0};
static const char *const DEV_KEYED_cv7_ins_19[] = {"desc_set", NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_19[] = {
    {"desc_set", "desc_set", NULL, -1}, {"descriptors", "descriptors", NULL, -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_19[] = {"num_descriptors", "descriptors", NULL};
static const char *const DEV_FILL_cv7_ins_19[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_19[] = {0};
static const int64_t DEV_KEYS_cv7_ins_19[] = {128, 130, 145, 146, 160, 0};
static const char *const DEV_KEYED_cv7_ins_20[] = {"desc_set", NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_20[] = {
    {"desc_set", "desc_set", NULL, -1}, {"enable", "enabled", NULL, -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_20[] = {NULL};
static const char *const DEV_FILL_cv7_ins_20[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_20[] = {0};
static const int64_t DEV_KEYS_cv7_ins_20[] = {128, 130, 145, 146, 160, 0};
static const char *const DEV_KEYED_cv7_ins_21[] = {NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_21[] = {{"enable_sbas", "enable_sbas", NULL, -1},
                                                  {"sbas_options", "sbas_options", NULL, -1},
                                                  {"included_prns", "included_prns", NULL, -1},
                                                  {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_21[] = {"num_included_prns", "included_prns", NULL};
static const char *const DEV_FILL_cv7_ins_21[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_21[] = {0};
static const int64_t DEV_KEYS_cv7_ins_21[] = {0};
static const char *const DEV_KEYED_cv7_ins_22[] = {NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_22[] = {{"source", "source", NULL, 8}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_22[] = {NULL};
static const char *const DEV_FILL_cv7_ins_22[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_22[] = {0};
static const int64_t DEV_KEYS_cv7_ins_22[] = {0};
static const char *const DEV_KEYED_cv7_ins_23[] = {NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_23[] = {{"offset", "offset", "m", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_23[] = {NULL};
static const char *const DEV_FILL_cv7_ins_23[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_23[] = {0};
static const int64_t DEV_KEYS_cv7_ins_23[] = {0};
static const char *const DEV_KEYED_cv7_ins_24[] = {NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_24[] = {{"source", "source", NULL, 10}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_24[] = {NULL};
static const char *const DEV_FILL_cv7_ins_24[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_24[] = {0};
static const int64_t DEV_KEYS_cv7_ins_24[] = {0};
static const char *const DEV_KEYED_cv7_ins_25[] = {NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_25[] = {{"noise", "noise", "m/s^2", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_25[] = {NULL};
static const char *const DEV_FILL_cv7_ins_25[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_25[] = {0};
static const int64_t DEV_KEYS_cv7_ins_25[] = {0};
static const char *const DEV_KEYED_cv7_ins_26[] = {NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_26[] = {{"noise", "noise", "rad/s", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_26[] = {NULL};
static const char *const DEV_FILL_cv7_ins_26[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_26[] = {0};
static const int64_t DEV_KEYS_cv7_ins_26[] = {0};
static const char *const DEV_KEYED_cv7_ins_27[] = {NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_27[] = {
    {"beta", "beta", "1/s", -1}, {"noise", "noise", "m/s^2", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_27[] = {NULL};
static const char *const DEV_FILL_cv7_ins_27[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_27[] = {0};
static const int64_t DEV_KEYS_cv7_ins_27[] = {0};
static const char *const DEV_KEYED_cv7_ins_28[] = {NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_28[] = {
    {"beta", "beta", "1/s", -1}, {"noise", "noise", "rad/s", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_28[] = {NULL};
static const char *const DEV_FILL_cv7_ins_28[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_28[] = {0};
static const int64_t DEV_KEYS_cv7_ins_28[] = {0};
static const char *const DEV_KEYED_cv7_ins_29[] = {NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_29[] = {
    {"enable", "enable", NULL, -1}, {"threshold", "threshold", "rad/s", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_29[] = {NULL};
static const char *const DEV_FILL_cv7_ins_29[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_29[] = {0};
static const int64_t DEV_KEYS_cv7_ins_29[] = {0};
static const char *const DEV_KEYED_cv7_ins_30[] = {NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_30[] = {{"noise", "noise", "g", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_30[] = {NULL};
static const char *const DEV_FILL_cv7_ins_30[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_30[] = {0};
static const int64_t DEV_KEYS_cv7_ins_30[] = {0};
static const char *const DEV_KEYED_cv7_ins_31[] = {NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_31[] = {
    {"source", "source", NULL, 12}, {"declination", "declination", "rad", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_31[] = {NULL};
static const char *const DEV_FILL_cv7_ins_31[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_31[] = {0};
static const int64_t DEV_KEYS_cv7_ins_31[] = {0};
static const char *const DEV_KEYED_cv7_ins_32[] = {"source", NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_32[] = {
    {"source", "source", NULL, 16}, {"enable", "enable", NULL, -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_32[] = {NULL};
static const char *const DEV_FILL_cv7_ins_32[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_32[] = {0};
static const int64_t DEV_KEYS_cv7_ins_32[] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 0};
static const char *const DEV_KEYED_cv7_ins_33[] = {NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_33[] = {
    {"wait_for_run_command", "wait_for_run_command", NULL, -1},
    {"initial_cond_src", "initial_cond_src", NULL, 17},
    {"auto_heading_alignment_selector", "auto_heading_alignment_selector", NULL, -1},
    {"initial_heading", "initial_heading", "deg", -1},
    {"initial_pitch", "initial_pitch", "deg", -1},
    {"initial_roll", "initial_roll", "deg", -1},
    {"initial_position", "initial_position", NULL, -1},
    {"initial_velocity", "initial_velocity", "m/s", -1},
    {"reference_frame_selector", "reference_frame_selector", NULL, 18},
    {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_33[] = {NULL};
static const char *const DEV_FILL_cv7_ins_33[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_33[] = {0};
static const int64_t DEV_KEYS_cv7_ins_33[] = {0};
static const char *const DEV_KEYED_cv7_ins_34[] = {NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_34[] = {
    {"level", "level", NULL, 19}, {"time_limit", "time_limit", "ms", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_34[] = {NULL};
static const char *const DEV_FILL_cv7_ins_34[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_34[] = {0};
static const int64_t DEV_KEYS_cv7_ins_34[] = {0};
static const char *const DEV_KEYED_cv7_ins_35[] = {"receiver_id", NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_35[] = {{"receiver_id", "receiver_id", NULL, -1},
                                                  {"antenna_offset", "antenna_offset", "m", -1},
                                                  {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_35[] = {NULL};
static const char *const DEV_FILL_cv7_ins_35[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_35[] = {0};
static const int64_t DEV_KEYS_cv7_ins_35[] = {1, 2, 0};
static const char *const DEV_KEYED_cv7_ins_36[] = {NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_36[] = {
    {"source", "source", NULL, 20},
    {"reference_frame_selector", "reference_frame_selector", NULL, 18},
    {"reference_coordinates", "reference_coordinates", NULL, -1},
    {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_36[] = {NULL};
static const char *const DEV_FILL_cv7_ins_36[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_36[] = {0};
static const int64_t DEV_KEYS_cv7_ins_36[] = {0};
static const char *const DEV_KEYED_cv7_ins_37[] = {NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_37[] = {{"ref_point_sel", "ref_point_sel", NULL, 21},
                                                  {"lever_arm_offset", "lever_arm_offset", "m", -1},
                                                  {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_37[] = {NULL};
static const char *const DEV_FILL_cv7_ins_37[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_37[] = {0};
static const int64_t DEV_KEYS_cv7_ins_37[] = {0};
static const char *const DEV_KEYED_cv7_ins_38[] = {"source", NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_38[] = {{"source", "source", NULL, -1},
                                                  {"lever_arm_offset", "lever_arm_offset", "m", -1},
                                                  {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_38[] = {NULL};
static const char *const DEV_FILL_cv7_ins_38[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_38[] = {0};
static const int64_t DEV_KEYS_cv7_ins_38[] = {1, 0};
static const char *const DEV_KEYED_cv7_ins_39[] = {NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_39[] = {{"enable", "enable", NULL, -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_39[] = {NULL};
static const char *const DEV_FILL_cv7_ins_39[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_39[] = {0};
static const int64_t DEV_KEYS_cv7_ins_39[] = {0};
static const char *const DEV_KEYED_cv7_ins_40[] = {NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_40[] = {
    {"enable", "enable", NULL, -1}, {"max_offset", "max_offset", "m", -1}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_40[] = {NULL};
static const char *const DEV_FILL_cv7_ins_40[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_40[] = {0};
static const int64_t DEV_KEYS_cv7_ins_40[] = {0};
static const char *const DEV_KEYED_cv7_ins_41[] = {NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_41[] = {{"gps_enable", "gps_enable", NULL, -1},
                                                  {"glonass_enable", "glonass_enable", NULL, -1},
                                                  {"galileo_enable", "galileo_enable", NULL, -1},
                                                  {"beidou_enable", "beidou_enable", NULL, -1},
                                                  {"reserved", "reserved", NULL, -1},
                                                  {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_41[] = {NULL};
static const char *const DEV_FILL_cv7_ins_41[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_41[] = {0};
static const int64_t DEV_KEYS_cv7_ins_41[] = {0};
static const char *const DEV_KEYED_cv7_ins_42[] = {NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_42[] = {{"enable", "enable", NULL, -1},
                                                  {"type", "type", NULL, 22},
                                                  {"current_key_tow", "current_key_tow", "s", -1},
                                                  {"current_key_week", "current_key_week", "weeks", -1},
                                                  {"current_key", "current_key", NULL, -1},
                                                  {"next_key_tow", "next_key_tow", "s", -1},
                                                  {"next_key_week", "next_key_week", "weeks", -1},
                                                  {"next_key", "next_key", NULL, -1},
                                                  {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_42[] = {NULL};
static const char *const DEV_FILL_cv7_ins_42[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_42[] = {0};
static const int64_t DEV_KEYS_cv7_ins_42[] = {0};
static const char *const DEV_KEYED_cv7_ins_43[] = {"frame_id", NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_43[] = {{"frame_id", "frame_id", NULL, -1},
                                                  {"format", "format", NULL, 23},
                                                  {"tracking_enabled", "tracking_enabled", NULL, -1},
                                                  {"translation", "translation", "m", -1},
                                                  {"rotation", "rotation", NULL, -1},
                                                  {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_43[] = {NULL};
static const char *const DEV_FILL_cv7_ins_43[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_43[] = {0};
static const int64_t DEV_KEYS_cv7_ins_43[] = {1, 2, 3, 4, 0};
static const char *const DEV_KEYED_cv7_ins_44[] = {NULL};
static const dev_attr_t DEV_ATTRS_cv7_ins_44[] = {{"mode", "mode", NULL, 24}, {NULL, NULL, NULL, -1}};
static const char *const DEV_COUNTS_cv7_ins_44[] = {NULL};
static const char *const DEV_FILL_cv7_ins_44[] = {NULL};
static const unsigned char DEV_FILL_LIST_cv7_ins_44[] = {0};
static const int64_t DEV_KEYS_cv7_ins_44[] = {0};
static const dev_setting_t DEV_SETTINGS_cv7_ins[] = {
    {"comm_port_speed", 1, 9, NULL, "comm_port_speed_response", DEV_KEYED_cv7_ins_0, 1u, DEV_ATTRS_cv7_ins_0,
     2u, DEV_COUNTS_cv7_ins_0, 0u, DEV_FILL_cv7_ins_0, DEV_FILL_LIST_cv7_ins_0, 0u, DEV_KEYS_cv7_ins_0, 3u},
    {"event_control", 12, 43, NULL, "event_control_response", DEV_KEYED_cv7_ins_1, 1u, DEV_ATTRS_cv7_ins_1,
     2u, DEV_COUNTS_cv7_ins_1, 0u, DEV_FILL_cv7_ins_1, DEV_FILL_LIST_cv7_ins_1, 0u, DEV_KEYS_cv7_ins_1, 12u},
    {"event_trigger_config", 12, 46, NULL, "event_trigger_config_response", DEV_KEYED_cv7_ins_2, 1u,
     DEV_ATTRS_cv7_ins_2, 3u, DEV_COUNTS_cv7_ins_2, 0u, DEV_FILL_cv7_ins_2, DEV_FILL_LIST_cv7_ins_2, 0u,
     DEV_KEYS_cv7_ins_2, 12u},
    {"event_action_config", 12, 47, NULL, "event_action_config_response", DEV_KEYED_cv7_ins_3, 1u,
     DEV_ATTRS_cv7_ins_3, 4u, DEV_COUNTS_cv7_ins_3, 0u, DEV_FILL_cv7_ins_3, DEV_FILL_LIST_cv7_ins_3, 0u,
     DEV_KEYS_cv7_ins_3, 12u},
    {"sensor_to_vehicle_euler", 12, 49, NULL, "sensor_to_vehicle_euler_response", DEV_KEYED_cv7_ins_4, 0u,
     DEV_ATTRS_cv7_ins_4, 3u, DEV_COUNTS_cv7_ins_4, 0u, DEV_FILL_cv7_ins_4, DEV_FILL_LIST_cv7_ins_4, 0u,
     DEV_KEYS_cv7_ins_4, 1u},
    {"sensor_to_vehicle_quaternion", 12, 50, NULL, "sensor_to_vehicle_quaternion_response",
     DEV_KEYED_cv7_ins_5, 0u, DEV_ATTRS_cv7_ins_5, 1u, DEV_COUNTS_cv7_ins_5, 0u, DEV_FILL_cv7_ins_5,
     DEV_FILL_LIST_cv7_ins_5, 0u, DEV_KEYS_cv7_ins_5, 1u},
    {"sensor_to_vehicle_dcm", 12, 51, NULL, "sensor_to_vehicle_dcm_response", DEV_KEYED_cv7_ins_6, 0u,
     DEV_ATTRS_cv7_ins_6, 1u, DEV_COUNTS_cv7_ins_6, 0u, DEV_FILL_cv7_ins_6, DEV_FILL_LIST_cv7_ins_6, 0u,
     DEV_KEYS_cv7_ins_6, 1u},
    {"accel_bias", 12, 55, "cv7_ins", "accel_bias_response", DEV_KEYED_cv7_ins_7, 0u, DEV_ATTRS_cv7_ins_7, 1u,
     DEV_COUNTS_cv7_ins_7, 0u, DEV_FILL_cv7_ins_7, DEV_FILL_LIST_cv7_ins_7, 0u, DEV_KEYS_cv7_ins_7, 1u},
    {"gyro_bias", 12, 56, "cv7_ins", "gyro_bias_response", DEV_KEYED_cv7_ins_8, 0u, DEV_ATTRS_cv7_ins_8, 1u,
     DEV_COUNTS_cv7_ins_8, 0u, DEV_FILL_cv7_ins_8, DEV_FILL_LIST_cv7_ins_8, 0u, DEV_KEYS_cv7_ins_8, 1u},
    {"mag_hard_iron_offset", 12, 58, "cv7_ins", "mag_hard_iron_offset_response", DEV_KEYED_cv7_ins_9, 0u,
     DEV_ATTRS_cv7_ins_9, 1u, DEV_COUNTS_cv7_ins_9, 0u, DEV_FILL_cv7_ins_9, DEV_FILL_LIST_cv7_ins_9, 0u,
     DEV_KEYS_cv7_ins_9, 1u},
    {"mag_soft_iron_matrix", 12, 59, "cv7_ins", "mag_soft_iron_matrix_response", DEV_KEYED_cv7_ins_10, 0u,
     DEV_ATTRS_cv7_ins_10, 1u, DEV_COUNTS_cv7_ins_10, 0u, DEV_FILL_cv7_ins_10, DEV_FILL_LIST_cv7_ins_10, 0u,
     DEV_KEYS_cv7_ins_10, 1u},
    {"uart_baudrate", 12, 64, NULL, "uart_baudrate_response", DEV_KEYED_cv7_ins_11, 0u, DEV_ATTRS_cv7_ins_11,
     1u, DEV_COUNTS_cv7_ins_11, 0u, DEV_FILL_cv7_ins_11, DEV_FILL_LIST_cv7_ins_11, 0u, DEV_KEYS_cv7_ins_11,
     1u},
    {"gpio_config", 12, 65, NULL, "gpio_config_response", DEV_KEYED_cv7_ins_12, 1u, DEV_ATTRS_cv7_ins_12, 4u,
     DEV_COUNTS_cv7_ins_12, 0u, DEV_FILL_cv7_ins_12, DEV_FILL_LIST_cv7_ins_12, 0u, DEV_KEYS_cv7_ins_12, 4u},
    {"odometer_config", 12, 67, NULL, "odometer_config_response", DEV_KEYED_cv7_ins_13, 0u,
     DEV_ATTRS_cv7_ins_13, 3u, DEV_COUNTS_cv7_ins_13, 0u, DEV_FILL_cv7_ins_13, DEV_FILL_LIST_cv7_ins_13, 0u,
     DEV_KEYS_cv7_ins_13, 1u},
    {"advanced_lowpass_filter", 12, 80, NULL, "advanced_lowpass_filter_response", DEV_KEYED_cv7_ins_14, 1u,
     DEV_ATTRS_cv7_ins_14, 5u, DEV_COUNTS_cv7_ins_14, 0u, DEV_FILL_cv7_ins_14, DEV_FILL_LIST_cv7_ins_14, 0u,
     DEV_KEYS_cv7_ins_14, 4u},
    {"complementary_filter", 12, 81, NULL, "complementary_filter_response", DEV_KEYED_cv7_ins_15, 0u,
     DEV_ATTRS_cv7_ins_15, 4u, DEV_COUNTS_cv7_ins_15, 0u, DEV_FILL_cv7_ins_15, DEV_FILL_LIST_cv7_ins_15, 0u,
     DEV_KEYS_cv7_ins_15, 1u},
    {"sensor_range", 12, 82, NULL, "sensor_range_response", DEV_KEYED_cv7_ins_16, 1u, DEV_ATTRS_cv7_ins_16,
     2u, DEV_COUNTS_cv7_ins_16, 0u, DEV_FILL_cv7_ins_16, DEV_FILL_LIST_cv7_ins_16, 0u, DEV_KEYS_cv7_ins_16,
     4u},
    {"lowpass_filter", 12, 84, NULL, "lowpass_filter_response", DEV_KEYED_cv7_ins_17, 2u,
     DEV_ATTRS_cv7_ins_17, 5u, DEV_COUNTS_cv7_ins_17, 0u, DEV_FILL_cv7_ins_17, DEV_FILL_LIST_cv7_ins_17, 0u,
     DEV_KEYS_cv7_ins_17, 4u},
    {"nmea_message_format", 12, 12, NULL, "nmea_message_format_response", DEV_KEYED_cv7_ins_18, 0u,
     DEV_ATTRS_cv7_ins_18, 1u, DEV_COUNTS_cv7_ins_18, 1u, DEV_FILL_cv7_ins_18, DEV_FILL_LIST_cv7_ins_18, 0u,
     DEV_KEYS_cv7_ins_18, 1u},
    {"message_format", 12, 15, NULL, "message_format_response", DEV_KEYED_cv7_ins_19, 1u,
     DEV_ATTRS_cv7_ins_19, 2u, DEV_COUNTS_cv7_ins_19, 1u, DEV_FILL_cv7_ins_19, DEV_FILL_LIST_cv7_ins_19, 0u,
     DEV_KEYS_cv7_ins_19, 5u},
    {"data_stream_control", 12, 17, "cv7_ins", "data_stream_control_response", DEV_KEYED_cv7_ins_20, 1u,
     DEV_ATTRS_cv7_ins_20, 2u, DEV_COUNTS_cv7_ins_20, 0u, DEV_FILL_cv7_ins_20, DEV_FILL_LIST_cv7_ins_20, 0u,
     DEV_KEYS_cv7_ins_20, 5u},
    {"gnss_sbas_settings", 12, 34, NULL, "gnss_sbas_settings_response", DEV_KEYED_cv7_ins_21, 0u,
     DEV_ATTRS_cv7_ins_21, 3u, DEV_COUNTS_cv7_ins_21, 1u, DEV_FILL_cv7_ins_21, DEV_FILL_LIST_cv7_ins_21, 0u,
     DEV_KEYS_cv7_ins_21, 1u},
    {"pps_source", 12, 40, NULL, "pps_source_response", DEV_KEYED_cv7_ins_22, 0u, DEV_ATTRS_cv7_ins_22, 1u,
     DEV_COUNTS_cv7_ins_22, 0u, DEV_FILL_cv7_ins_22, DEV_FILL_LIST_cv7_ins_22, 0u, DEV_KEYS_cv7_ins_22, 1u},
    {"antenna_offset", 13, 19, NULL, "antenna_offset_response", DEV_KEYED_cv7_ins_23, 0u,
     DEV_ATTRS_cv7_ins_23, 1u, DEV_COUNTS_cv7_ins_23, 0u, DEV_FILL_cv7_ins_23, DEV_FILL_LIST_cv7_ins_23, 0u,
     DEV_KEYS_cv7_ins_23, 1u},
    {"gnss_source_control", 13, 21, NULL, "gnss_source_control_response", DEV_KEYED_cv7_ins_24, 0u,
     DEV_ATTRS_cv7_ins_24, 1u, DEV_COUNTS_cv7_ins_24, 0u, DEV_FILL_cv7_ins_24, DEV_FILL_LIST_cv7_ins_24, 0u,
     DEV_KEYS_cv7_ins_24, 1u},
    {"accel_noise", 13, 26, NULL, "accel_noise_response", DEV_KEYED_cv7_ins_25, 0u, DEV_ATTRS_cv7_ins_25, 1u,
     DEV_COUNTS_cv7_ins_25, 0u, DEV_FILL_cv7_ins_25, DEV_FILL_LIST_cv7_ins_25, 0u, DEV_KEYS_cv7_ins_25, 1u},
    {"gyro_noise", 13, 27, NULL, "gyro_noise_response", DEV_KEYED_cv7_ins_26, 0u, DEV_ATTRS_cv7_ins_26, 1u,
     DEV_COUNTS_cv7_ins_26, 0u, DEV_FILL_cv7_ins_26, DEV_FILL_LIST_cv7_ins_26, 0u, DEV_KEYS_cv7_ins_26, 1u},
    {"accel_bias_model", 13, 28, NULL, "accel_bias_model_response", DEV_KEYED_cv7_ins_27, 0u,
     DEV_ATTRS_cv7_ins_27, 2u, DEV_COUNTS_cv7_ins_27, 0u, DEV_FILL_cv7_ins_27, DEV_FILL_LIST_cv7_ins_27, 0u,
     DEV_KEYS_cv7_ins_27, 1u},
    {"gyro_bias_model", 13, 29, NULL, "gyro_bias_model_response", DEV_KEYED_cv7_ins_28, 0u,
     DEV_ATTRS_cv7_ins_28, 2u, DEV_COUNTS_cv7_ins_28, 0u, DEV_FILL_cv7_ins_28, DEV_FILL_LIST_cv7_ins_28, 0u,
     DEV_KEYS_cv7_ins_28, 1u},
    {"zero_angular_rate_update_control", 13, 32, NULL, "zero_angular_rate_update_control_response",
     DEV_KEYED_cv7_ins_29, 0u, DEV_ATTRS_cv7_ins_29, 2u, DEV_COUNTS_cv7_ins_29, 0u, DEV_FILL_cv7_ins_29,
     DEV_FILL_LIST_cv7_ins_29, 0u, DEV_KEYS_cv7_ins_29, 1u},
    {"gravity_noise_std_dev", 13, 40, NULL, "gravity_noise_std_dev_response", DEV_KEYED_cv7_ins_30, 0u,
     DEV_ATTRS_cv7_ins_30, 1u, DEV_COUNTS_cv7_ins_30, 0u, DEV_FILL_cv7_ins_30, DEV_FILL_LIST_cv7_ins_30, 0u,
     DEV_KEYS_cv7_ins_30, 1u},
    {"declination_source", 13, 67, NULL, "declination_source_response", DEV_KEYED_cv7_ins_31, 0u,
     DEV_ATTRS_cv7_ins_31, 2u, DEV_COUNTS_cv7_ins_31, 0u, DEV_FILL_cv7_ins_31, DEV_FILL_LIST_cv7_ins_31, 0u,
     DEV_KEYS_cv7_ins_31, 1u},
    {"aiding_measurement_control", 13, 80, NULL, "aiding_measurement_control_response", DEV_KEYED_cv7_ins_32,
     1u, DEV_ATTRS_cv7_ins_32, 2u, DEV_COUNTS_cv7_ins_32, 0u, DEV_FILL_cv7_ins_32, DEV_FILL_LIST_cv7_ins_32,
     0u, DEV_KEYS_cv7_ins_32, 9u},
    {"initialization_configuration", 13, 82, NULL, "initialization_configuration_response",
     DEV_KEYED_cv7_ins_33, 0u, DEV_ATTRS_cv7_ins_33, 9u, DEV_COUNTS_cv7_ins_33, 0u, DEV_FILL_cv7_ins_33,
     DEV_FILL_LIST_cv7_ins_33, 0u, DEV_KEYS_cv7_ins_33, 1u},
    {"adaptive_filter_control", 13, 83, NULL, "adaptive_filter_control_response", DEV_KEYED_cv7_ins_34, 0u,
     DEV_ATTRS_cv7_ins_34, 2u, DEV_COUNTS_cv7_ins_34, 0u, DEV_FILL_cv7_ins_34, DEV_FILL_LIST_cv7_ins_34, 0u,
     DEV_KEYS_cv7_ins_34, 1u},
    {"multi_antenna_offset", 13, 84, NULL, "multi_antenna_offset_response", DEV_KEYED_cv7_ins_35, 1u,
     DEV_ATTRS_cv7_ins_35, 2u, DEV_COUNTS_cv7_ins_35, 0u, DEV_FILL_cv7_ins_35, DEV_FILL_LIST_cv7_ins_35, 0u,
     DEV_KEYS_cv7_ins_35, 2u},
    {"relative_position_configuration", 13, 85, NULL, "relative_position_configuration_response",
     DEV_KEYED_cv7_ins_36, 0u, DEV_ATTRS_cv7_ins_36, 3u, DEV_COUNTS_cv7_ins_36, 0u, DEV_FILL_cv7_ins_36,
     DEV_FILL_LIST_cv7_ins_36, 0u, DEV_KEYS_cv7_ins_36, 1u},
    {"reference_point_lever_arm", 13, 86, NULL, "reference_point_lever_arm_response", DEV_KEYED_cv7_ins_37,
     0u, DEV_ATTRS_cv7_ins_37, 2u, DEV_COUNTS_cv7_ins_37, 0u, DEV_FILL_cv7_ins_37, DEV_FILL_LIST_cv7_ins_37,
     0u, DEV_KEYS_cv7_ins_37, 1u},
    {"speed_lever_arm", 13, 97, NULL, "speed_lever_arm_response", DEV_KEYED_cv7_ins_38, 1u,
     DEV_ATTRS_cv7_ins_38, 2u, DEV_COUNTS_cv7_ins_38, 0u, DEV_FILL_cv7_ins_38, DEV_FILL_LIST_cv7_ins_38, 0u,
     DEV_KEYS_cv7_ins_38, 1u},
    {"wheeled_vehicle_constraint_control", 13, 99, NULL, "wheeled_vehicle_constraint_control_response",
     DEV_KEYED_cv7_ins_39, 0u, DEV_ATTRS_cv7_ins_39, 1u, DEV_COUNTS_cv7_ins_39, 0u, DEV_FILL_cv7_ins_39,
     DEV_FILL_LIST_cv7_ins_39, 0u, DEV_KEYS_cv7_ins_39, 1u},
    {"gnss_antenna_calibration_control", 13, 100, NULL, "gnss_antenna_calibration_control_response",
     DEV_KEYED_cv7_ins_40, 0u, DEV_ATTRS_cv7_ins_40, 2u, DEV_COUNTS_cv7_ins_40, 0u, DEV_FILL_cv7_ins_40,
     DEV_FILL_LIST_cv7_ins_40, 0u, DEV_KEYS_cv7_ins_40, 1u},
    {"signal_configuration", 14, 2, NULL, "signal_configuration_response", DEV_KEYED_cv7_ins_41, 0u,
     DEV_ATTRS_cv7_ins_41, 5u, DEV_COUNTS_cv7_ins_41, 0u, DEV_FILL_cv7_ins_41, DEV_FILL_LIST_cv7_ins_41, 0u,
     DEV_KEYS_cv7_ins_41, 1u},
    {"spartn_configuration", 14, 32, NULL, "spartn_configuration_response", DEV_KEYED_cv7_ins_42, 0u,
     DEV_ATTRS_cv7_ins_42, 8u, DEV_COUNTS_cv7_ins_42, 0u, DEV_FILL_cv7_ins_42, DEV_FILL_LIST_cv7_ins_42, 0u,
     DEV_KEYS_cv7_ins_42, 1u},
    {"frame_config", 19, 1, NULL, "frame_config_response", DEV_KEYED_cv7_ins_43, 1u, DEV_ATTRS_cv7_ins_43, 5u,
     DEV_COUNTS_cv7_ins_43, 0u, DEV_FILL_cv7_ins_43, DEV_FILL_LIST_cv7_ins_43, 0u, DEV_KEYS_cv7_ins_43, 4u},
    {"echo_control", 19, 31, NULL, "echo_control_response", DEV_KEYED_cv7_ins_44, 0u, DEV_ATTRS_cv7_ins_44,
     1u, DEV_COUNTS_cv7_ins_44, 0u, DEV_FILL_cv7_ins_44, DEV_FILL_LIST_cv7_ins_44, 0u, DEV_KEYS_cv7_ins_44,
     1u},
    {NULL, 0, 0, NULL, NULL, NULL, 0, NULL, 0, NULL, 0, NULL, NULL, 0, NULL, 0}};
static const dev_size_t DEV_SIZES_cv7_ins[] = {
    {128, 4, 12},  {128, 5, 12},  {128, 6, 12},   {128, 7, 12},   {128, 8, 12},   {128, 9, 36},
    {128, 10, 16}, {128, 12, 12}, {128, 18, 12},  {128, 20, 12},  {128, 23, 4},   {128, 24, 2},
    {128, 64, 10}, {130, 1, 26},  {130, 2, 14},   {130, 3, 18},   {130, 4, 38},   {130, 5, 14},
    {130, 6, 14},  {130, 7, 14},  {130, 8, 14},   {130, 9, 14},   {130, 10, 14},  {130, 11, 14},
    {130, 12, 14}, {130, 13, 14}, {130, 14, 14},  {130, 16, 6},   {130, 17, 12},  {130, 18, 18},
    {130, 19, 14}, {130, 21, 22}, {130, 28, 14},  {130, 33, 6},   {130, 52, 15},  {130, 53, 15},
    {130, 54, 14}, {130, 55, 14}, {130, 64, 26},  {130, 65, 14},  {130, 66, 26},  {130, 67, 15},
    {130, 70, 7},  {130, 71, 6},  {130, 72, 6},   {130, 73, 17},  {130, 80, 29},  {130, 81, 25},
    {145, 3, 42},  {145, 4, 30},  {145, 5, 34},   {145, 6, 18},   {145, 7, 30},   {145, 8, 13},
    {145, 9, 12},  {145, 11, 6},  {145, 13, 5},   {145, 16, 34},  {145, 17, 3},   {145, 18, 16},
    {145, 32, 25}, {145, 34, 61}, {145, 97, 218}, {145, 98, 102}, {145, 99, 218}, {145, 100, 218},
    {146, 3, 42},  {146, 4, 30},  {146, 5, 34},   {146, 6, 18},   {146, 7, 30},   {146, 8, 13},
    {146, 9, 12},  {146, 11, 6},  {146, 13, 5},   {146, 16, 34},  {146, 17, 3},   {146, 18, 16},
    {146, 32, 25}, {146, 34, 61}, {146, 97, 218}, {146, 98, 102}, {146, 99, 218}, {146, 100, 218},
    {147, 48, 44}, {147, 49, 50}, {148, 3, 42},   {148, 5, 34},   {148, 8, 13},   {148, 11, 6},
    {148, 32, 25}, {160, 1, 16},  {160, 2, 2},    {160, 3, 1},    {255, 208, 1},  {255, 211, 12},
    {255, 212, 8}, {255, 213, 8}, {255, 214, 8},  {255, 215, 10}, {255, 216, 10}, {0, 0, 0}};
static const dev_rate_t DEV_BASE_RATES_cv7_ins[] = {{128, 1000}, {130, 1000}, {145, 5},
                                                    {146, 5},    {160, 1000}, {0, 0}};
static const uint8_t DEV_UNADDRESSED_cv7_ins[] = {0};
static const dev_model_t DEV_MODELS[] = {{"gx5_45", "3DM-GX5-45", DEV_SETTINGS_gx5_45, 42u, DEV_SIZES_gx5_45,
                                          59u, DEV_BASE_RATES_gx5_45, 3u, DEV_UNADDRESSED_gx5_45, 1u},
                                         {"cv7_ins", "3DM-CV7-GNSS/INS", DEV_SETTINGS_cv7_ins, 45u,
                                          DEV_SIZES_cv7_ins, 101u, DEV_BASE_RATES_cv7_ins, 5u,
                                          DEV_UNADDRESSED_cv7_ins, 0u},
                                         {NULL, NULL, NULL, 0, NULL, 0, NULL, 0, NULL, 0}};
static const size_t DEV_MODEL_COUNT = 2u;

static const dev_format_t DEV_FORMATS[] = {
    {12, 15, -1, "desc_set", "descriptors", "descriptor", "decimation"},
    {12, 8, 128, NULL, "descriptors", "descriptor", "decimation"},
    {12, 9, 129, NULL, "descriptors", "descriptor", "decimation"},
    {12, 10, 130, NULL, "descriptors", "descriptor", "decimation"},
    {0, 0, -1, NULL, NULL, NULL, NULL}};
static const size_t DEV_FORMAT_COUNT = 4u;

static const dev_rate_query_t DEV_RATE_QUERIES[] = {
    {12, 14, -1, "desc_set"}, {12, 6, 128, NULL}, {12, 7, 129, NULL}, {12, 11, 130, NULL}, {0, 0, -1, NULL}};
static const size_t DEV_RATE_QUERY_COUNT = 4u;
static const int64_t DEV_ENABLE_MAP_0[] = {1, 128, 2, 129, 3, 130, 0};
static const dev_enable_t DEV_ENABLES[] = {
    {12, 17, "enable", "device_selector", DEV_ENABLE_MAP_0, 3u, "desc_set"},
    {0, 0, NULL, NULL, NULL, 0, NULL}};
static const size_t DEV_ENABLE_COUNT = 1u;

static const dev_baud_t DEV_BAUD[] = {{1, 9, "baud"}, {12, 64, "baud"}, {0, 0, NULL}};
static const size_t DEV_BAUD_COUNT = 2u;

/* the commands whose save and default apply to every setting */
static const uint8_t DEV_ALL_SETTINGS[][2] = {{12, 48}, {0, 0}};
static const size_t DEV_ALL_SETTINGS_COUNT = 1u;

static const dev_list_t DEV_LISTS[] = {
    {1, 4, 130, "descriptors", 1}, {1, 7, 134, "descriptors", 1}, {0, 0, 0, NULL, 0}};
static const size_t DEV_LIST_COUNT = 2u;

static const dev_report_t DEV_REPORTS[] = {{1, 129, {"info", "firmware_version", NULL}, "firmware"},
                                           {1, 129, {"info", "model_name", NULL}, "model_name"},
                                           {1, 129, {"info", "model_number", NULL}, "model_number"},
                                           {1, 129, {"info", "serial_number", NULL}, "serial_number"},
                                           {1, 129, {"info", "lot_number", NULL}, "lot_number"},
                                           {1, 129, {"info", "device_options", NULL}, "options"},
                                           {0, 0, {NULL}, NULL}};
static const size_t DEV_REPORT_COUNT = 6u;

typedef struct {
    uint8_t id;
    const char *name;
} dev_set_name_t;

static const dev_set_name_t DEV_SET_NAMES[] = {{1, "base"},
                                               {12, "threedm"},
                                               {13, "filter"},
                                               {14, "gnss"},
                                               {19, "aiding"},
                                               {127, "system"},
                                               {128, "sensor"},
                                               {129, "gnss_data"},
                                               {130, "filter_data"},
                                               {145, "gnss_receiver_1"},
                                               {146, "gnss_receiver_2"},
                                               {147, "gnss_corrections"},
                                               {148, "gnss_external"},
                                               {160, "system_data"},
                                               {255, "shared"},
                                               {0, NULL}};

/* the command whose reply reports the identity: set, descriptor (0, 0: none) */
#define DEV_IDENTITY_SET 1u
#define DEV_IDENTITY_DESCRIPTOR 3u

/* the manuals' lines of the UART bandwidth calculation (the spec's link: bandwidth) */
#define DEV_BANDWIDTH_SOURCES "3dm-gx5-45-dcp.txt line 536, 3dm-cv7-ins-docs.txt line 4099"
/* the data set of the shared fields (valid in every data set), -1: none */
#define DEV_SHARED_SET (255)

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
static const dev_pps_member_t DEV_PPS_MEMBERS_0[] = {
    {"disabled", 0, DEV_PPS_NONE}, {"receiver_1", 1, DEV_PPS_RECEIVER}, {"receiver_2", 2, DEV_PPS_RECEIVER},
    {"gpio", 3, DEV_PPS_INPUT},    {"generated", 4, DEV_PPS_GENERATED}, {NULL, 0, DEV_PPS_NONE}};
static const dev_sync_time_t DEV_SYNC_TIMES_0[] = {{255, 211, "valid_flags", "tow", 1u, 2u},
                                                   {0, 0, NULL, NULL, 0, 0}};
static const dev_pps_member_t DEV_PPS_MEMBERS_1[] = {{NULL, 0, DEV_PPS_NONE}};
static const dev_sync_time_t DEV_SYNC_TIMES_1[] = {{0, 0, NULL, NULL, 0, 0}};
static const dev_timesync_t DEV_TIMESYNC[] = {
    {"cv7_ins", 1,   114, "field_id",  "value",          1,  2,  12, 40,   "source", DEV_PPS_MEMBERS_0,
     5u,        160, 2,   "time_sync", DEV_SYNC_TIMES_0, 1u, -1, 0,  NULL, NULL,     0u,
     0u,        0u},
    {"gx5_45",
     1,
     114,
     "field_id",
     "value",
     1,
     2,
     0,
     0,
     NULL,
     DEV_PPS_MEMBERS_1,
     0u,
     -1,
     0,
     NULL,
     DEV_SYNC_TIMES_1,
     0u,
     128,
     18,
     "valid_flags",
     "tow",
     1u,
     2u,
     4u},
    {NULL, 0, 0, NULL, NULL, 0, 0, 0, 0, NULL, NULL, 0, -1, 0, NULL, NULL, 0, -1, 0, NULL, NULL, 0, 0, 0}};
static const size_t DEV_TIMESYNC_COUNT = 2u;

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
