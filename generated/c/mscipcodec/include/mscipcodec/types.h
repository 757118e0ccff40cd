/* Named types of the Memsense MS-CIP protocol: enums, bitfields, structs and unions.
 * Generated from the spec: do not edit. */
#ifndef MSCIPC_TYPES_H
#define MSCIPC_TYPES_H

#include "mscipcodec/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Accelerometer range code. Dynamic range of all three accelerometer axes (Tables 37 and 60; device
 * specific). An integer, so that values the spec does not list are kept. */
typedef uint8_t mscipc_accel_range_t;
/** Accelerometer range +-2 g. */
#define MSCIPC_ACCEL_RANGE_RANGE_2G ((mscipc_accel_range_t)0u)
/** Accelerometer range +-4 g. */
#define MSCIPC_ACCEL_RANGE_RANGE_4G ((mscipc_accel_range_t)1u)
/** Accelerometer range +-8 g. */
#define MSCIPC_ACCEL_RANGE_RANGE_8G ((mscipc_accel_range_t)2u)
/** Accelerometer range +-10 g. */
#define MSCIPC_ACCEL_RANGE_RANGE_10G ((mscipc_accel_range_t)3u)
/** Accelerometer range +-15 g. */
#define MSCIPC_ACCEL_RANGE_RANGE_15G ((mscipc_accel_range_t)4u)
/** Accelerometer range +-20 g. */
#define MSCIPC_ACCEL_RANGE_RANGE_20G ((mscipc_accel_range_t)5u)
/** Accelerometer range +-40 g. */
#define MSCIPC_ACCEL_RANGE_RANGE_40G ((mscipc_accel_range_t)6u)

/** UART baud rate. Baud rates the UART accepts, sent as their value (Table 20).
 * An integer, so that values the spec does not list are kept. */
typedef uint32_t mscipc_baud_rate_t;
/** 9600 baud (0x00002580). */
#define MSCIPC_BAUD_RATE_BAUD_9600 ((mscipc_baud_rate_t)9600u)
/** 19200 baud (0x00004B00). */
#define MSCIPC_BAUD_RATE_BAUD_19200 ((mscipc_baud_rate_t)19200u)
/** 115200 baud (0x0001C200). */
#define MSCIPC_BAUD_RATE_BAUD_115200 ((mscipc_baud_rate_t)115200u)
/** 230400 baud (0x00038400). */
#define MSCIPC_BAUD_RATE_BAUD_230400 ((mscipc_baud_rate_t)230400u)
/** 460800 baud (0x00070800). */
#define MSCIPC_BAUD_RATE_BAUD_460800 ((mscipc_baud_rate_t)460800u)
/** 921600 baud (0x000E1000). */
#define MSCIPC_BAUD_RATE_BAUD_921600 ((mscipc_baud_rate_t)921600u)

/** Error code. Second data byte of the ack field (Table 2).
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mscipc_error_code_t;
/** The message was received without error. */
#define MSCIPC_ERROR_CODE_OK ((mscipc_error_code_t)0u)
/** The checksum sent with the previous message does not calculate to the correct value. */
#define MSCIPC_ERROR_CODE_CHECKSUM_ERROR ((mscipc_error_code_t)1u)
/** The previous message contained an invalid message type. */
#define MSCIPC_ERROR_CODE_INVALID_MESSAGE_TYPE ((mscipc_error_code_t)2u)
/** The previous message had an invalid message code. */
#define MSCIPC_ERROR_CODE_INVALID_MESSAGE_CODE ((mscipc_error_code_t)3u)
/** A parameter in the previous message is not valid. */
#define MSCIPC_ERROR_CODE_INVALID_PARAMETER ((mscipc_error_code_t)4u)

/** Filter bandwidth control code. Digital filter setting: disabled, or an IIR low-pass with the given -3 dB
 * cutoff. The cutoffs are device specific; these are the MS-IMU3020's (Table 24). An integer, so that values
 * the spec does not list are kept. */
typedef uint8_t mscipc_filter_bandwidth_t;
/** Disable filter. */
#define MSCIPC_FILTER_BANDWIDTH_DISABLED ((mscipc_filter_bandwidth_t)0u)
/** IIR filter, -3 dB at 25 Hz. */
#define MSCIPC_FILTER_BANDWIDTH_IIR_25HZ ((mscipc_filter_bandwidth_t)1u)
/** IIR filter, -3 dB at 50 Hz. */
#define MSCIPC_FILTER_BANDWIDTH_IIR_50HZ ((mscipc_filter_bandwidth_t)2u)
/** IIR filter, -3 dB at 75 Hz. */
#define MSCIPC_FILTER_BANDWIDTH_IIR_75HZ ((mscipc_filter_bandwidth_t)3u)
/** IIR filter, -3 dB at 100 Hz. */
#define MSCIPC_FILTER_BANDWIDTH_IIR_100HZ ((mscipc_filter_bandwidth_t)4u)
/** IIR filter, -3 dB at 10 Hz. */
#define MSCIPC_FILTER_BANDWIDTH_IIR_10HZ ((mscipc_filter_bandwidth_t)5u)
/** IIR filter, -3 dB at 150 Hz. */
#define MSCIPC_FILTER_BANDWIDTH_IIR_150HZ ((mscipc_filter_bandwidth_t)6u)
/** IIR filter, -3 dB at 200 Hz. */
#define MSCIPC_FILTER_BANDWIDTH_IIR_200HZ ((mscipc_filter_bandwidth_t)7u)

/** Function code. First data byte of the configuration messages (0x0201, 0x0203-0x0205, 0x0207-0x020D):
 * chooses what the message does. An integer, so that values the spec does not list are kept. */
typedef uint8_t mscipc_function_code_t;
/** Use new settings. */
#define MSCIPC_FUNCTION_CODE_WRITE ((mscipc_function_code_t)1u)
/** Request current settings. */
#define MSCIPC_FUNCTION_CODE_READ ((mscipc_function_code_t)2u)
/** Save current settings as startup settings. */
#define MSCIPC_FUNCTION_CODE_SAVE ((mscipc_function_code_t)3u)
/** Load saved startup settings. */
#define MSCIPC_FUNCTION_CODE_LOAD ((mscipc_function_code_t)4u)
/** Reset to default settings. */
#define MSCIPC_FUNCTION_CODE_DEFAULT ((mscipc_function_code_t)5u)

/** GPS correlated time flags. Status of the GPS time correlation (Table 71).
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mscipc_gps_time_flags_t;
/** bit 0: GPS 1 PPS received: set for one sample after the pulse (only once GPS time is set). */
#define MSCIPC_GPS_TIME_FLAGS_PPS_RECEIVED_MASK ((mscipc_gps_time_flags_t)0x1u)
#define MSCIPC_GPS_TIME_FLAGS_PPS_RECEIVED_SHIFT 0
/** bit 1: GPS time was set: set for one sample after the message that set it. */
#define MSCIPC_GPS_TIME_FLAGS_TIME_SET_MASK ((mscipc_gps_time_flags_t)0x2u)
#define MSCIPC_GPS_TIME_FLAGS_TIME_SET_SHIFT 1
/** bit 2: No GPS time set: the time counts from week 0, time 0 on the internal clock. */
#define MSCIPC_GPS_TIME_FLAGS_TIME_NOT_SET_MASK ((mscipc_gps_time_flags_t)0x4u)
#define MSCIPC_GPS_TIME_FLAGS_TIME_NOT_SET_SHIFT 2
/** bit 3: 1 PPS lost: more than 1 s without a pulse since the time was set; the internal clock carries on. */
#define MSCIPC_GPS_TIME_FLAGS_PPS_LOST_MASK ((mscipc_gps_time_flags_t)0x8u)
#define MSCIPC_GPS_TIME_FLAGS_PPS_LOST_SHIFT 3
/** bits 4-15: (reserved) Reserved. */
#define MSCIPC_GPS_TIME_FLAGS_RESERVED_MASK ((mscipc_gps_time_flags_t)0xFFF0u)
#define MSCIPC_GPS_TIME_FLAGS_RESERVED_SHIFT 4

/** Gyroscope range code. Dynamic range of all three gyroscope axes (Table 41; device specific).
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mscipc_gyro_range_t;
/** Gyroscope range +-120 deg/s. */
#define MSCIPC_GYRO_RANGE_RANGE_120DPS ((mscipc_gyro_range_t)1u)
/** Gyroscope range +-240 deg/s. */
#define MSCIPC_GYRO_RANGE_RANGE_240DPS ((mscipc_gyro_range_t)2u)
/** Gyroscope range +-480 deg/s. */
#define MSCIPC_GYRO_RANGE_RANGE_480DPS ((mscipc_gyro_range_t)3u)
/** Gyroscope range +-960 deg/s. */
#define MSCIPC_GYRO_RANGE_RANGE_960DPS ((mscipc_gyro_range_t)4u)
/** Gyroscope range +-1920 deg/s. */
#define MSCIPC_GYRO_RANGE_RANGE_1920DPS ((mscipc_gyro_range_t)5u)
/** Gyroscope range +-75 deg/s. */
#define MSCIPC_GYRO_RANGE_RANGE_75DPS ((mscipc_gyro_range_t)6u)
/** Gyroscope range +-200 deg/s. */
#define MSCIPC_GYRO_RANGE_RANGE_200DPS ((mscipc_gyro_range_t)7u)

/** On/off control code. Control code of Data On/Off (Table 48) and XTRIG On/Off (Table 52).
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mscipc_on_off_t;
/** Off. */
#define MSCIPC_ON_OFF_OFF ((mscipc_on_off_t)0u)
/** On. */
#define MSCIPC_ON_OFF_ON ((mscipc_on_off_t)1u)

/** Sensor select code. A measurement to include in the IMU data message: the message code of its 0xA2 data
 * field (Tables 31 and 56). An integer, so that values the spec does not list are kept. */
typedef uint8_t mscipc_sensor_code_t;
/** Scaled acceleration vector in g. */
#define MSCIPC_SENSOR_CODE_SCALED_ACCEL ((mscipc_sensor_code_t)129u)
/** Scaled angular rate vector in deg/s. */
#define MSCIPC_SENSOR_CODE_SCALED_GYRO ((mscipc_sensor_code_t)130u)
/** Scaled magnetic field vector in gauss. */
#define MSCIPC_SENSOR_CODE_SCALED_MAG ((mscipc_sensor_code_t)131u)
/** Delta theta vector in radians. */
#define MSCIPC_SENSOR_CODE_DELTA_THETA ((mscipc_sensor_code_t)132u)
/** Delta velocity vector in m/s. */
#define MSCIPC_SENSOR_CODE_DELTA_VELOCITY ((mscipc_sensor_code_t)133u)
/** Scaled pressure in millibar. */
#define MSCIPC_SENSOR_CODE_SCALED_PRESSURE ((mscipc_sensor_code_t)134u)
/** Scaled temperature in degrees Celsius. */
#define MSCIPC_SENSOR_CODE_SCALED_TEMPERATURE ((mscipc_sensor_code_t)135u)
/** GPS correlated time. */
#define MSCIPC_SENSOR_CODE_GPS_CORRELATED_TIME ((mscipc_sensor_code_t)136u)
/** Scaled auxiliary acceleration vector in g (Select Sensors Rev B only). */
#define MSCIPC_SENSOR_CODE_SCALED_AUX_ACCEL ((mscipc_sensor_code_t)137u)

/** Message identifier. One supported message: "2 bytes for each message supported indicating the Message Type
 * in the MSB and the Message ID Code in the LSB" (line 200). */
typedef struct {
    uint8_t message_type; /* Message type (0x01, 0x02, 0xA2, ...). */
    uint8_t message_code; /* Message code within the type. */
} mscipc_message_id_t;

#ifdef __cplusplus
}
#endif

#endif
