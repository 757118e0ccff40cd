/* Named types of the MicroStrain MIP protocol: enums, bitfields, structs and unions.
 * Generated from the spec: do not edit. */
#ifndef MIP_TYPES_H
#define MIP_TYPES_H

#include "mipcodec/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Ack/Nack code.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_ack_code_t;
#define MIP_ACK_CODE_OK ((mip_ack_code_t)0u) /* Success (ACK). */
#define MIP_ACK_CODE_UNKNOWN_COMMAND                                                                         \
    ((mip_ack_code_t)1u) /* The command descriptor is not supported by this device. */
#define MIP_ACK_CODE_BAD_CHECKSUM ((mip_ack_code_t)2u) /* An otherwise complete packet has a bad checksum.   \
                                                        */
#define MIP_ACK_CODE_INVALID_PARAMETER ((mip_ack_code_t)3u) /* One or more parameters are invalid. */
#define MIP_ACK_CODE_COMMAND_FAILED ((mip_ack_code_t)4u)    /* Device could not complete the command. */
#define MIP_ACK_CODE_COMMAND_TIMEOUT ((mip_ack_code_t)5u) /* Device could not complete the command in time.  \
                                                           */
#define MIP_ACK_CODE_UNKNOWN_DESCRIPTOR_SET                                                                  \
    ((mip_ack_code_t)6u) /* Unknown descriptor set (CV7 only). (devices: cv7_ins) */

/** GPIO action mode.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_action_gpio_mode_t;
#define MIP_ACTION_GPIO_MODE_DISABLED ((mip_action_gpio_mode_t)0u) /* Pin state will not be changed. */
#define MIP_ACTION_GPIO_MODE_ACTIVE_HIGH                                                                     \
    ((mip_action_gpio_mode_t)1u) /* High while the trigger is active, low otherwise. */
#define MIP_ACTION_GPIO_MODE_ACTIVE_LOW                                                                      \
    ((mip_action_gpio_mode_t)2u) /* Low while the trigger is active, high otherwise. */
#define MIP_ACTION_GPIO_MODE_ONESHOT_HIGH                                                                    \
    ((mip_action_gpio_mode_t)5u) /* Set high each time the trigger activates. */
#define MIP_ACTION_GPIO_MODE_ONESHOT_LOW                                                                     \
    ((mip_action_gpio_mode_t)6u) /* Set low each time the trigger activates. */
#define MIP_ACTION_GPIO_MODE_TOGGLE ((mip_action_gpio_mode_t)7u) /* Toggle each time the trigger activates.  \
                                                                  */

/** Event action type.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_action_type_t;
#define MIP_ACTION_TYPE_NONE ((mip_action_type_t)0u)    /* No action. Parameters should be empty. */
#define MIP_ACTION_TYPE_GPIO ((mip_action_type_t)1u)    /* Control the state of a GPIO pin. */
#define MIP_ACTION_TYPE_MESSAGE ((mip_action_type_t)2u) /* Output a data packet. */

/** 3DM-CV7 commanded built-in test result.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint32_t mip_cv7_bit_flags_t;
#define MIP_CV7_BIT_FLAGS_GENERAL_HARDWARE_FAULT_MASK                                                        \
    ((mip_cv7_bit_flags_t)0x1u) /* bit 0: A critical hardware component has failed or is not operating       \
                                   properly. */
#define MIP_CV7_BIT_FLAGS_GENERAL_HARDWARE_FAULT_SHIFT 0
#define MIP_CV7_BIT_FLAGS_GENERAL_FIRMWARE_FAULT_MASK                                                        \
    ((mip_cv7_bit_flags_t)0x2u) /* bit 1: System firmware has detected a serious, unexpected or abnormal     \
                                   condition. */
#define MIP_CV7_BIT_FLAGS_GENERAL_FIRMWARE_FAULT_SHIFT 1
#define MIP_CV7_BIT_FLAGS_TIMING_OVERLOAD_MASK                                                               \
    ((mip_cv7_bit_flags_t)0x4u) /* bit 2: The system cannot keep up with the processing demand. */
#define MIP_CV7_BIT_FLAGS_TIMING_OVERLOAD_SHIFT 2
#define MIP_CV7_BIT_FLAGS_BUFFER_OVERRUN_MASK                                                                \
    ((mip_cv7_bit_flags_t)0x8u) /* bit 3: A data buffer has reached its capacity. */
#define MIP_CV7_BIT_FLAGS_BUFFER_OVERRUN_SHIFT 3
#define MIP_CV7_BIT_FLAGS_RESERVED_SYSTEM_MASK                                                               \
    ((mip_cv7_bit_flags_t)0xF0u) /* bits 4-7: (reserved) Reserved (system). */
#define MIP_CV7_BIT_FLAGS_RESERVED_SYSTEM_SHIFT 4
#define MIP_CV7_BIT_FLAGS_RESERVED_COMMS_MASK                                                                \
    ((mip_cv7_bit_flags_t)0xF00u) /* bits 8-11: (reserved) Reserved (comms). */
#define MIP_CV7_BIT_FLAGS_RESERVED_COMMS_SHIFT 8
#define MIP_CV7_BIT_FLAGS_ACCELEROMETER_FAULT_MASK                                                           \
    ((mip_cv7_bit_flags_t)0x1000u) /* bit 12: The accelerometer has been damaged or is inoperative. */
#define MIP_CV7_BIT_FLAGS_ACCELEROMETER_FAULT_SHIFT 12
#define MIP_CV7_BIT_FLAGS_GYROSCOPE_FAULT_MASK                                                               \
    ((mip_cv7_bit_flags_t)0x2000u) /* bit 13: The gyroscope has been damaged or is inoperative. */
#define MIP_CV7_BIT_FLAGS_GYROSCOPE_FAULT_SHIFT 13
#define MIP_CV7_BIT_FLAGS_MAGNETOMETER_FAULT_MASK                                                            \
    ((mip_cv7_bit_flags_t)0x4000u) /* bit 14: The magnetometer has been damaged or is inoperative. */
#define MIP_CV7_BIT_FLAGS_MAGNETOMETER_FAULT_SHIFT 14
#define MIP_CV7_BIT_FLAGS_PRESSURE_SENSOR_FAULT_MASK                                                         \
    ((mip_cv7_bit_flags_t)0x8000u) /* bit 15: The pressure sensor has been damaged or is inoperative. */
#define MIP_CV7_BIT_FLAGS_PRESSURE_SENSOR_FAULT_SHIFT 15
#define MIP_CV7_BIT_FLAGS_RESERVED_IMU_MASK                                                                  \
    ((mip_cv7_bit_flags_t)0x30000u) /* bits 16-17: (reserved) Reserved (IMU). */
#define MIP_CV7_BIT_FLAGS_RESERVED_IMU_SHIFT 16
#define MIP_CV7_BIT_FLAGS_CALIBRATION_ERROR_MASK                                                             \
    ((mip_cv7_bit_flags_t)0x40000u) /* bit 18: One or more IMU calibration tables are invalid. */
#define MIP_CV7_BIT_FLAGS_CALIBRATION_ERROR_SHIFT 18
#define MIP_CV7_BIT_FLAGS_GENERAL_IMU_FAULT_MASK                                                             \
    ((mip_cv7_bit_flags_t)0x80000u) /* bit 19: A problem has been detected in the IMU subsystem. */
#define MIP_CV7_BIT_FLAGS_GENERAL_IMU_FAULT_SHIFT 19
#define MIP_CV7_BIT_FLAGS_RESERVED_FILTER_MASK                                                               \
    ((mip_cv7_bit_flags_t)0x300000u) /* bits 20-21: (reserved) Reserved (filter). */
#define MIP_CV7_BIT_FLAGS_RESERVED_FILTER_SHIFT 20
#define MIP_CV7_BIT_FLAGS_FILTER_SOLUTION_FAULT_MASK                                                         \
    ((mip_cv7_bit_flags_t)0x400000u) /* bit 22: The filter solution is invalid (NaN in the filter output).   \
                                      */
#define MIP_CV7_BIT_FLAGS_FILTER_SOLUTION_FAULT_SHIFT 22
#define MIP_CV7_BIT_FLAGS_GENERAL_FILTER_FAULT_MASK                                                          \
    ((mip_cv7_bit_flags_t)0x800000u) /* bit 23: A problem has been detected in the filter subsystem. */
#define MIP_CV7_BIT_FLAGS_GENERAL_FILTER_FAULT_SHIFT 23
#define MIP_CV7_BIT_FLAGS_RESERVED_MASK                                                                      \
    ((mip_cv7_bit_flags_t)0xFF000000u) /* bits 24-31: (reserved) Reserved. */
#define MIP_CV7_BIT_FLAGS_RESERVED_SHIFT 24

/** Event trigger control mode.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_event_control_mode_t;
#define MIP_EVENT_CONTROL_MODE_DISABLED ((mip_event_control_mode_t)0u) /* Trigger is disabled. */
#define MIP_EVENT_CONTROL_MODE_ENABLED                                                                       \
    ((mip_event_control_mode_t)1u) /* Trigger is enabled and will work normally. */
#define MIP_EVENT_CONTROL_MODE_TEST                                                                          \
    ((mip_event_control_mode_t)2u) /* Forces the trigger to the active state for testing purposes. */
#define MIP_EVENT_CONTROL_MODE_TEST_PULSE                                                                    \
    ((mip_event_control_mode_t)3u) /* Trigger is forced active for one event cycle only, then reverts. */

/** Function selector. First parameter of settings commands; chooses what the command does.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_function_selector_t;
#define MIP_FUNCTION_SELECTOR_WRITE ((mip_function_selector_t)1u) /* Apply new setting. */
#define MIP_FUNCTION_SELECTOR_READ ((mip_function_selector_t)2u)  /* Read current setting. */
#define MIP_FUNCTION_SELECTOR_SAVE                                                                           \
    ((mip_function_selector_t)3u) /* Save current setting to non-volatile memory. */
#define MIP_FUNCTION_SELECTOR_LOAD ((mip_function_selector_t)4u) /* Load setting from non-volatile memory.   \
                                                                  */
#define MIP_FUNCTION_SELECTOR_DEFAULT ((mip_function_selector_t)5u) /* Reset to the factory default. */
#define MIP_FUNCTION_SELECTOR_WRITE_NO_ACK                                                                   \
    ((mip_function_selector_t)6u) /* Apply new setting with no ACK/NACK reply (GX5-45 only). (devices:       \
                                     gx5_45) */

/** GPS time field selector.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_gps_time_field_t;
#define MIP_GPS_TIME_FIELD_WEEK_NUMBER ((mip_gps_time_field_t)1u) /* Week number (GX5-45: GPS Week Number).  \
                                                                   */
#define MIP_GPS_TIME_FIELD_TIME_OF_WEEK                                                                      \
    ((mip_gps_time_field_t)2u) /* Time of week in seconds (GX5-45: GPS Seconds). */

/** 3DM-GX5-45 built-in test error flags.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint32_t mip_gx5_bit_flags_t;
#define MIP_GX5_BIT_FLAGS_PROCESSOR_WDT_RESET_MASK                                                           \
    ((mip_gx5_bit_flags_t)0x1u) /* bit 0: Processor board: watchdog reset (latching, cleared after first     \
                                   commanded BIT). */
#define MIP_GX5_BIT_FLAGS_PROCESSOR_WDT_RESET_SHIFT 0
#define MIP_GX5_BIT_FLAGS_IMU_COMMUNICATION_FAULT_MASK                                                       \
    ((mip_gx5_bit_flags_t)0x100u) /* bit 8: Sensor board: IMU communication fault. */
#define MIP_GX5_BIT_FLAGS_IMU_COMMUNICATION_FAULT_SHIFT 8
#define MIP_GX5_BIT_FLAGS_MAGNETOMETER_FAULT_MASK                                                            \
    ((mip_gx5_bit_flags_t)0x200u) /* bit 9: Sensor board: magnetometer fault (if applicable). */
#define MIP_GX5_BIT_FLAGS_MAGNETOMETER_FAULT_SHIFT 9
#define MIP_GX5_BIT_FLAGS_PRESSURE_SENSOR_FAULT_MASK                                                         \
    ((mip_gx5_bit_flags_t)0x400u) /* bit 10: Sensor board: pressure sensor fault (if applicable). */
#define MIP_GX5_BIT_FLAGS_PRESSURE_SENSOR_FAULT_SHIFT 10
#define MIP_GX5_BIT_FLAGS_FILTER_SOLUTION_FAULT_MASK                                                         \
    ((mip_gx5_bit_flags_t)0x1000000u) /* bit 24: Kalman filter: solution fault. */
#define MIP_GX5_BIT_FLAGS_FILTER_SOLUTION_FAULT_SHIFT 24

/** Threshold comparison type.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_threshold_type_t;
#define MIP_THRESHOLD_TYPE_WINDOW                                                                            \
    ((mip_threshold_type_t)1u) /* Active if low_thres <= value <= high_thres (reversed thresholds invert     \
                                  it). */
#define MIP_THRESHOLD_TYPE_INTERVAL                                                                          \
    ((mip_threshold_type_t)2u) /* Active when (value % high_thres) <= low_thres: periodic triggering. */

/** GPIO trigger mode.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_trigger_gpio_mode_t;
#define MIP_TRIGGER_GPIO_MODE_DISABLED                                                                       \
    ((mip_trigger_gpio_mode_t)0u) /* The pin has no effect and the trigger never activates. */
#define MIP_TRIGGER_GPIO_MODE_WHILE_HIGH ((mip_trigger_gpio_mode_t)1u) /* Active while the pin is high. */
#define MIP_TRIGGER_GPIO_MODE_WHILE_LOW ((mip_trigger_gpio_mode_t)2u)  /* Active while the pin is low. */
#define MIP_TRIGGER_GPIO_MODE_EDGE                                                                           \
    ((mip_trigger_gpio_mode_t)4u) /* Use if the pin is configured for timestamping (0x0C,0x41). */

/** Event trigger status.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint8_t mip_trigger_status_t;
#define MIP_TRIGGER_STATUS_ACTIVE_MASK                                                                       \
    ((mip_trigger_status_t)0x1u) /* bit 0: The trigger is currently active (by its logic or in test mode).   \
                                  */
#define MIP_TRIGGER_STATUS_ACTIVE_SHIFT 0
#define MIP_TRIGGER_STATUS_ENABLED_MASK ((mip_trigger_status_t)0x2u) /* bit 1: The trigger is enabled. */
#define MIP_TRIGGER_STATUS_ENABLED_SHIFT 1
#define MIP_TRIGGER_STATUS_TEST_MASK ((mip_trigger_status_t)0x4u) /* bit 2: The trigger is in test mode. */
#define MIP_TRIGGER_STATUS_TEST_SHIFT 2

/** Event trigger type.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_trigger_type_t;
#define MIP_TRIGGER_TYPE_NONE                                                                                \
    ((mip_trigger_type_t)0u) /* No trigger selected. The state will always be inactive. */
#define MIP_TRIGGER_TYPE_GPIO ((mip_trigger_type_t)1u) /* Trigger based on the state of a GPIO pin. */
#define MIP_TRIGGER_TYPE_THRESHOLD                                                                           \
    ((mip_trigger_type_t)2u) /* Compare a data quantity against a high and low threshold. */
#define MIP_TRIGGER_TYPE_COMBINATION                                                                         \
    ((mip_trigger_type_t)3u) /* Logical combination of two or more triggers. */

/** ActionGpioParams.  */
typedef struct {
    uint8_t pin;                 /* GPIO pin number. */
    mip_action_gpio_mode_t mode; /* Behavior of the pin. */
} mip_action_gpio_params_t;

/** MessageParams.  */
typedef struct {
    uint8_t desc_set;        /* MIP data descriptor set. */
    uint16_t decimation;     /* Decimation from the base rate; 0 emits one packet per activation. */
    uint8_t num_fields;      /* Number of fields in the packet (at most 12). */
    uint8_t descriptors[12]; /* Field descriptors. */
} mip_message_params_t;

/** ActionParams.
 * The member is chosen by a parameter of type mip_action_type_t next to it. */
typedef union {
    mip_action_gpio_params_t gpio; /* gpio:  */
    mip_message_params_t message;  /* message:  */
    uint8_t none_;                 /* members without data */
} mip_action_params_t;

/** ActionStatusEntry.  */
typedef struct {
    mip_action_type_t action_type; /* Configured action type. */
    uint8_t trigger_id;            /* Associated trigger instance. */
} mip_action_status_entry_t;

/** CombinationParams.  */
typedef struct {
    uint16_t logic_table;      /* Last column of the truth table of the inputs. */
    uint8_t input_triggers[4]; /* Trigger IDs of the inputs; 0 for unused inputs. */
} mip_combination_params_t;

/** Device information. Firmware version and five 16-character identification strings, padded with spaces. */
typedef struct {
    uint16_t firmware_version; /* Firmware version number. */
    char model_name[16];       /* Model name. */
    char model_number[16];     /* Model number. */
    char serial_number[16];    /* Serial number. */
    char lot_number[16];       /* Lot number. */
    char device_options[16];   /* Device options (e.g. sensor ranges). */
} mip_device_info_t;

/** ThresholdParams.  */
typedef struct {
    uint8_t desc_set;          /* Descriptor set of the target data quantity. */
    uint8_t field_desc;        /* Field descriptor of the target data quantity. */
    uint8_t param_id;          /* 1-based index of the target parameter within the field. */
    mip_threshold_type_t type; /* Type of comparison. */
    double low_thres;          /* Low threshold (window) or active time (interval). */
    double high_thres;         /* High threshold (window) or interval (interval). */
} mip_threshold_params_t;

/** TriggerGpioParams.  */
typedef struct {
    uint8_t pin;                  /* GPIO pin number. */
    mip_trigger_gpio_mode_t mode; /* How the pin state affects the trigger. */
} mip_trigger_gpio_params_t;

/** TriggerParams.
 * The member is chosen by a parameter of type mip_trigger_type_t next to it. */
typedef union {
    mip_trigger_gpio_params_t gpio;       /* gpio:  */
    mip_threshold_params_t threshold;     /* threshold:  */
    mip_combination_params_t combination; /* combination:  */
    uint8_t none_;                        /* members without data */
} mip_trigger_params_t;

/** TriggerStatusEntry.  */
typedef struct {
    mip_trigger_type_t type;     /* Configured trigger type. */
    mip_trigger_status_t status; /* Trigger status. */
} mip_trigger_status_entry_t;

#ifdef __cplusplus
}
#endif

#endif
