//! What the MicroStrain MIP spec says about every command, for the session layer
//! ([`crate::session`], `docs/conformance.md` §8): how a reply is matched (the ack rule) and
//! one [`CommandFacts`] row per command layout: set, descriptor, devices, function selector
//! values, the reply fields with their `when`, ack suppression and the timeout allowance.
//! Generated from `spec/mip/`; do not edit.

use crate::dispatch::{Device, FieldValue};
use crate::session::{AckSuppression, Allowance, CommandFacts, ReferenceTime, ReplyFacts};

/// Descriptor of the ack/nack field that answers a command (in a packet of the command's set).
pub const ACK_DESCRIPTOR: u8 = 0xF1;
/// The ack code of success; any other code is a NACK.
pub const ACK_OK: u32 = 0;

/// The echoed command descriptor and the code of an ack/nack field, or `None` for any other
/// value.
pub fn ack_of(value: &FieldValue) -> Option<(u8, u32)> {
    match value {
        FieldValue::Reserved(crate::reserved::ReservedField::AckNack(a)) => {
            Some((a.command_descriptor, u32::from(a.ack_code.0)))
        }
        _ => None,
    }
}

/// Per device, where a data packet carries the device's reference time (the spec's
/// `time.reference_time`; the host clock model, `docs/time.md`), read by
/// [`crate::session::reference_ns`].
pub static REFERENCE_TIMES: &[ReferenceTime] = &[
    // shared.reference_timestamp
    ReferenceTime {
        device: Device::Cv7Ins,
        set: 0xFF,
        shared: true,
        descriptor: 0xD5,
        gps: false,
        offset: 0,
        size: 8,
        week_offset: 0,
        week_size: 0,
        ns_per_unit: 1,
    },
    // sensor.gps_timestamp
    ReferenceTime {
        device: Device::Gx5_45,
        set: 0x80,
        shared: false,
        descriptor: 0x12,
        gps: true,
        offset: 0,
        size: 8,
        week_offset: 8,
        week_size: 2,
        ns_per_unit: 1,
    },
];

/// The spec's name of a function selector value.
pub fn function_name(value: u8) -> Option<&'static str> {
    match value {
        1 => Some("write"),
        2 => Some("read"),
        3 => Some("save"),
        4 => Some("load"),
        5 => Some("default"),
        6 => Some("write_no_ack"),
        _ => None,
    }
}

/// Function selector values that only some devices accept.
pub static FUNCTION_DEVICES: &[(u8, &[Device])] = &[(6, &[Device::Gx5_45])];

/// One row per command layout, in spec order.
pub static COMMANDS: [CommandFacts; 128] = [
    CommandFacts {
        set: 0x01,
        descriptor: 0x01,
        name: "ping",
        device: None,
        devices: &[Device::Gx5_45, Device::Cv7Ins],
        functions: None,
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x01,
        descriptor: 0x02,
        name: "set_to_idle",
        device: None,
        devices: &[Device::Gx5_45, Device::Cv7Ins],
        functions: None,
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x01,
        descriptor: 0x03,
        name: "get_device_info",
        device: None,
        devices: &[Device::Gx5_45, Device::Cv7Ins],
        functions: None,
        replies: &[ReplyFacts {
            descriptor: 0x81,
            function: None,
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x01,
        descriptor: 0x04,
        name: "get_device_descriptors",
        device: None,
        devices: &[Device::Gx5_45, Device::Cv7Ins],
        functions: None,
        replies: &[ReplyFacts {
            descriptor: 0x82,
            function: None,
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x01,
        descriptor: 0x05,
        name: "built_in_test",
        device: None,
        devices: &[Device::Gx5_45, Device::Cv7Ins],
        functions: None,
        replies: &[ReplyFacts {
            descriptor: 0x83,
            function: None,
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: Some(Allowance {
            ms: 5000,
            param: None,
            functions: None,
        }),
    },
    CommandFacts {
        set: 0x01,
        descriptor: 0x06,
        name: "resume",
        device: None,
        devices: &[Device::Gx5_45, Device::Cv7Ins],
        functions: None,
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x01,
        descriptor: 0x07,
        name: "get_extended_descriptors",
        device: None,
        devices: &[Device::Gx5_45, Device::Cv7Ins],
        functions: None,
        replies: &[ReplyFacts {
            descriptor: 0x86,
            function: None,
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x01,
        descriptor: 0x08,
        name: "continuous_bit",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: None,
        replies: &[ReplyFacts {
            descriptor: 0x88,
            function: None,
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x01,
        descriptor: 0x09,
        name: "comm_port_speed",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x89,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x01,
        descriptor: 0x72,
        name: "gps_time_update",
        device: Some(Device::Gx5_45),
        devices: &[Device::Gx5_45],
        functions: Some(&[1, 2, 6]),
        replies: &[
            ReplyFacts {
                descriptor: 0x84,
                function: Some(2),
                param: Some("field_id"),
                value: Some(1),
            },
            ReplyFacts {
                descriptor: 0x85,
                function: Some(2),
                param: Some("field_id"),
                value: Some(2),
            },
        ],
        ack: AckSuppression::Function(6),
        timeout: None,
    },
    CommandFacts {
        set: 0x01,
        descriptor: 0x72,
        name: "gps_time_update",
        device: Some(Device::Cv7Ins),
        devices: &[Device::Cv7Ins],
        functions: Some(&[1]),
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x01,
        descriptor: 0x7E,
        name: "device_reset",
        device: None,
        devices: &[Device::Gx5_45, Device::Cv7Ins],
        functions: None,
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x2B,
        name: "event_control",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0xB5,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x2C,
        name: "get_event_trigger_status",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: None,
        replies: &[ReplyFacts {
            descriptor: 0xB6,
            function: None,
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x2D,
        name: "get_event_action_status",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: None,
        replies: &[ReplyFacts {
            descriptor: 0xB7,
            function: None,
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x2E,
        name: "event_trigger_config",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0xB8,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x2F,
        name: "event_action_config",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0xB9,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x30,
        name: "device_startup_settings",
        device: Some(Device::Gx5_45),
        devices: &[Device::Gx5_45],
        functions: Some(&[2, 3, 4, 5]),
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x30,
        name: "device_startup_settings",
        device: Some(Device::Cv7Ins),
        devices: &[Device::Cv7Ins],
        functions: Some(&[3, 4, 5]),
        replies: &[],
        ack: AckSuppression::Never,
        timeout: Some(Allowance {
            ms: 1000,
            param: None,
            functions: None,
        }),
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x31,
        name: "sensor_to_vehicle_euler",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0xB1,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x32,
        name: "sensor_to_vehicle_quaternion",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0xB2,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x33,
        name: "sensor_to_vehicle_dcm",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0xB3,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x37,
        name: "accel_bias",
        device: Some(Device::Gx5_45),
        devices: &[Device::Gx5_45],
        functions: Some(&[1, 2, 3, 4, 5, 6]),
        replies: &[ReplyFacts {
            descriptor: 0x9A,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Function(6),
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x37,
        name: "accel_bias",
        device: Some(Device::Cv7Ins),
        devices: &[Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x9A,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x38,
        name: "gyro_bias",
        device: Some(Device::Gx5_45),
        devices: &[Device::Gx5_45],
        functions: Some(&[1, 2, 3, 4, 5, 6]),
        replies: &[ReplyFacts {
            descriptor: 0x9B,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Function(6),
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x38,
        name: "gyro_bias",
        device: Some(Device::Cv7Ins),
        devices: &[Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x9B,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x39,
        name: "capture_gyro_bias",
        device: None,
        devices: &[Device::Gx5_45, Device::Cv7Ins],
        functions: None,
        replies: &[ReplyFacts {
            descriptor: 0x9B,
            function: None,
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: Some(Allowance {
            ms: 0,
            param: Some("averaging_time_ms"),
            functions: None,
        }),
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x3A,
        name: "mag_hard_iron_offset",
        device: Some(Device::Gx5_45),
        devices: &[Device::Gx5_45],
        functions: Some(&[1, 2, 3, 4, 5, 6]),
        replies: &[ReplyFacts {
            descriptor: 0x9C,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Function(6),
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x3A,
        name: "mag_hard_iron_offset",
        device: Some(Device::Cv7Ins),
        devices: &[Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x9C,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x3B,
        name: "mag_soft_iron_matrix",
        device: Some(Device::Gx5_45),
        devices: &[Device::Gx5_45],
        functions: Some(&[1, 2, 3, 4, 5, 6]),
        replies: &[ReplyFacts {
            descriptor: 0x9D,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Function(6),
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x3B,
        name: "mag_soft_iron_matrix",
        device: Some(Device::Cv7Ins),
        devices: &[Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x9D,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x3E,
        name: "coning_sculling_enable",
        device: None,
        devices: &[Device::Gx5_45],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x9E,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x40,
        name: "uart_baudrate",
        device: None,
        devices: &[Device::Gx5_45, Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x87,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x41,
        name: "gpio_config",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0xC1,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x42,
        name: "gpio_state",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: Some(&[1, 2]),
        replies: &[ReplyFacts {
            descriptor: 0xC2,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x43,
        name: "odometer_config",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0xC3,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x50,
        name: "advanced_lowpass_filter",
        device: None,
        devices: &[Device::Gx5_45, Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x8B,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x51,
        name: "complementary_filter",
        device: None,
        devices: &[Device::Gx5_45, Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x97,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x52,
        name: "sensor_range",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0xD2,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x53,
        name: "get_calibrated_sensor_ranges",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: None,
        replies: &[ReplyFacts {
            descriptor: 0xD3,
            function: None,
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x54,
        name: "lowpass_filter",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0xD4,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x01,
        name: "poll_imu_data",
        device: None,
        devices: &[Device::Gx5_45],
        functions: None,
        replies: &[],
        ack: AckSuppression::Param {
            param: "option",
            value: Some(1),
        },
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x02,
        name: "poll_gnss_data",
        device: None,
        devices: &[Device::Gx5_45],
        functions: None,
        replies: &[],
        ack: AckSuppression::Param {
            param: "option",
            value: Some(1),
        },
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x03,
        name: "poll_filter_data",
        device: None,
        devices: &[Device::Gx5_45],
        functions: None,
        replies: &[],
        ack: AckSuppression::Param {
            param: "option",
            value: Some(1),
        },
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x04,
        name: "poll_nmea_data",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: None,
        replies: &[],
        ack: AckSuppression::Param {
            param: "suppress_ack",
            value: None,
        },
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x0D,
        name: "poll_data",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: None,
        replies: &[],
        ack: AckSuppression::Param {
            param: "suppress_ack",
            value: None,
        },
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x06,
        name: "get_imu_base_rate",
        device: None,
        devices: &[Device::Gx5_45],
        functions: None,
        replies: &[ReplyFacts {
            descriptor: 0x83,
            function: None,
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x07,
        name: "get_gnss_base_rate",
        device: None,
        devices: &[Device::Gx5_45],
        functions: None,
        replies: &[ReplyFacts {
            descriptor: 0x84,
            function: None,
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x0B,
        name: "get_filter_base_rate",
        device: None,
        devices: &[Device::Gx5_45],
        functions: None,
        replies: &[ReplyFacts {
            descriptor: 0x8A,
            function: None,
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x0E,
        name: "get_base_rate",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: None,
        replies: &[ReplyFacts {
            descriptor: 0x8E,
            function: None,
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x08,
        name: "imu_message_format",
        device: None,
        devices: &[Device::Gx5_45],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x80,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x09,
        name: "gnss_message_format",
        device: None,
        devices: &[Device::Gx5_45],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x81,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x0A,
        name: "filter_message_format",
        device: None,
        devices: &[Device::Gx5_45],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x82,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x0C,
        name: "nmea_message_format",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x8C,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x0F,
        name: "message_format",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x8F,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x10,
        name: "factory_streaming",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: None,
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x11,
        name: "data_stream_control",
        device: Some(Device::Gx5_45),
        devices: &[Device::Gx5_45],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x85,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x11,
        name: "data_stream_control",
        device: Some(Device::Cv7Ins),
        devices: &[Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x85,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x20,
        name: "raw_rtcm_message",
        device: None,
        devices: &[Device::Gx5_45],
        functions: None,
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x21,
        name: "gnss_constellation_settings",
        device: None,
        devices: &[Device::Gx5_45],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0xA0,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x22,
        name: "gnss_sbas_settings",
        device: None,
        devices: &[Device::Gx5_45, Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0xA1,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x23,
        name: "gnss_assisted_fix_control",
        device: None,
        devices: &[Device::Gx5_45],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0xA2,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x24,
        name: "gnss_assist_time_update",
        device: None,
        devices: &[Device::Gx5_45],
        functions: Some(&[1, 2]),
        replies: &[ReplyFacts {
            descriptor: 0xA3,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x28,
        name: "pps_source",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0xA8,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x2A,
        name: "get_supported_events",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: None,
        replies: &[ReplyFacts {
            descriptor: 0xB4,
            function: None,
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0C,
        descriptor: 0x64,
        name: "device_status",
        device: None,
        devices: &[Device::Gx5_45],
        functions: None,
        replies: &[ReplyFacts {
            descriptor: 0x90,
            function: None,
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x01,
        name: "reset_filter",
        device: None,
        devices: &[Device::Gx5_45, Device::Cv7Ins],
        functions: None,
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x02,
        name: "set_initial_attitude",
        device: None,
        devices: &[Device::Gx5_45],
        functions: None,
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x03,
        name: "set_initial_heading",
        device: None,
        devices: &[Device::Gx5_45, Device::Cv7Ins],
        functions: None,
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x05,
        name: "run_filter",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: None,
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x10,
        name: "vehicle_dynamics_mode",
        device: None,
        devices: &[Device::Gx5_45],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x80,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x11,
        name: "sensor_to_vehicle_transform",
        device: None,
        devices: &[Device::Gx5_45],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x81,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x12,
        name: "sensor_to_vehicle_offset",
        device: None,
        devices: &[Device::Gx5_45],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x82,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x13,
        name: "antenna_offset",
        device: None,
        devices: &[Device::Gx5_45, Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x83,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x14,
        name: "estimation_control",
        device: None,
        devices: &[Device::Gx5_45],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x84,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x15,
        name: "gnss_source_control",
        device: None,
        devices: &[Device::Gx5_45, Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x86,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x16,
        name: "external_gnss_update",
        device: None,
        devices: &[Device::Gx5_45],
        functions: None,
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x17,
        name: "external_heading_update",
        device: None,
        devices: &[Device::Gx5_45, Device::Cv7Ins],
        functions: None,
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x18,
        name: "heading_update_control",
        device: None,
        devices: &[Device::Gx5_45],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x87,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x19,
        name: "auto_init_control",
        device: None,
        devices: &[Device::Gx5_45],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x88,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x1A,
        name: "accel_noise",
        device: None,
        devices: &[Device::Gx5_45, Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x89,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x1B,
        name: "gyro_noise",
        device: None,
        devices: &[Device::Gx5_45, Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x8A,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x1C,
        name: "accel_bias_model",
        device: None,
        devices: &[Device::Gx5_45, Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x8B,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x1D,
        name: "gyro_bias_model",
        device: None,
        devices: &[Device::Gx5_45, Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x8C,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x1E,
        name: "zupt_control",
        device: None,
        devices: &[Device::Gx5_45],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x8D,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x1F,
        name: "external_heading_update_with_time",
        device: None,
        devices: &[Device::Gx5_45, Device::Cv7Ins],
        functions: None,
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x20,
        name: "zero_angular_rate_update_control",
        device: None,
        devices: &[Device::Gx5_45, Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x8E,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x21,
        name: "tare_orientation",
        device: None,
        devices: &[Device::Gx5_45],
        functions: Some(&[1, 3, 4, 5]),
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x22,
        name: "commanded_zupt",
        device: None,
        devices: &[Device::Gx5_45],
        functions: None,
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x23,
        name: "commanded_zero_angular_rate_update",
        device: None,
        devices: &[Device::Gx5_45],
        functions: None,
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x27,
        name: "mag_capture_auto_calibration",
        device: None,
        devices: &[Device::Gx5_45],
        functions: Some(&[1, 3]),
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x28,
        name: "gravity_noise_std_dev",
        device: None,
        devices: &[Device::Gx5_45, Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x93,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x29,
        name: "pressure_altitude_noise_std_dev",
        device: None,
        devices: &[Device::Gx5_45],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x94,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x2B,
        name: "hard_iron_offset_noise",
        device: None,
        devices: &[Device::Gx5_45],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x96,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x2C,
        name: "soft_iron_matrix_noise",
        device: None,
        devices: &[Device::Gx5_45],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x97,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x42,
        name: "mag_noise_std_dev",
        device: None,
        devices: &[Device::Gx5_45],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0xB1,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x43,
        name: "declination_source",
        device: None,
        devices: &[Device::Gx5_45, Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0xB2,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x44,
        name: "gravity_magnitude_adaptive_measurement",
        device: None,
        devices: &[Device::Gx5_45],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0xB3,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x45,
        name: "mag_magnitude_adaptive_measurement",
        device: None,
        devices: &[Device::Gx5_45],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0xB4,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x46,
        name: "mag_dip_angle_adaptive_measurement",
        device: None,
        devices: &[Device::Gx5_45],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0xB5,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x47,
        name: "altitude_aiding_control",
        device: None,
        devices: &[Device::Gx5_45],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0xB7,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x4B,
        name: "pitch_roll_aiding_control",
        device: None,
        devices: &[Device::Gx5_45],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0xBB,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x4C,
        name: "inclination_source",
        device: None,
        devices: &[Device::Gx5_45],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0xBC,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x4D,
        name: "magnetic_field_magnitude_source",
        device: None,
        devices: &[Device::Gx5_45],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0xBD,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x50,
        name: "aiding_measurement_control",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0xD0,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x52,
        name: "initialization_configuration",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0xD2,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x53,
        name: "adaptive_filter_control",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0xD3,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x54,
        name: "multi_antenna_offset",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0xD4,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x55,
        name: "relative_position_configuration",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0xD5,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x56,
        name: "reference_point_lever_arm",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0xD6,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x61,
        name: "speed_lever_arm",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0xE1,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x63,
        name: "wheeled_vehicle_constraint_control",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0xE3,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0D,
        descriptor: 0x64,
        name: "gnss_antenna_calibration_control",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0xE4,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0E,
        descriptor: 0x01,
        name: "receiver_info",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: None,
        replies: &[ReplyFacts {
            descriptor: 0x81,
            function: None,
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0E,
        descriptor: 0x02,
        name: "signal_configuration",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x82,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x0E,
        descriptor: 0x20,
        name: "spartn_configuration",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0xA0,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x13,
        descriptor: 0x01,
        name: "frame_config",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x81,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x13,
        descriptor: 0x1F,
        name: "echo_control",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x9F,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x13,
        descriptor: 0x21,
        name: "ecef_position",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: None,
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x13,
        descriptor: 0x22,
        name: "llh_position",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: None,
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x13,
        descriptor: 0x23,
        name: "height_above_ellipsoid",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: None,
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x13,
        descriptor: 0x28,
        name: "ecef_velocity",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: None,
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x13,
        descriptor: 0x29,
        name: "ned_velocity",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: None,
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x13,
        descriptor: 0x2A,
        name: "body_frame_velocity",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: None,
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x13,
        descriptor: 0x31,
        name: "true_heading",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: None,
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x13,
        descriptor: 0x32,
        name: "magnetic_field",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: None,
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x13,
        descriptor: 0x33,
        name: "pressure",
        device: None,
        devices: &[Device::Cv7Ins],
        functions: None,
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x7F,
        descriptor: 0x10,
        name: "communication_mode",
        device: None,
        devices: &[Device::Gx5_45],
        functions: Some(&[1, 2, 3, 4, 5]),
        replies: &[ReplyFacts {
            descriptor: 0x90,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
];

/// The facts of a command value's layout, or `None` when the value is not a command.
pub fn command_facts(value: &FieldValue) -> Option<&'static CommandFacts> {
    match value {
        FieldValue::Base(crate::base::SetField::Ping(_)) => Some(&COMMANDS[0]),
        FieldValue::Base(crate::base::SetField::SetToIdle(_)) => Some(&COMMANDS[1]),
        FieldValue::Base(crate::base::SetField::GetDeviceInfo(_)) => Some(&COMMANDS[2]),
        FieldValue::Base(crate::base::SetField::GetDeviceDescriptors(_)) => Some(&COMMANDS[3]),
        FieldValue::Base(crate::base::SetField::BuiltInTest(_)) => Some(&COMMANDS[4]),
        FieldValue::Base(crate::base::SetField::Resume(_)) => Some(&COMMANDS[5]),
        FieldValue::Base(crate::base::SetField::GetExtendedDescriptors(_)) => Some(&COMMANDS[6]),
        FieldValue::Base(crate::base::SetField::ContinuousBit(_)) => Some(&COMMANDS[7]),
        FieldValue::Base(crate::base::SetField::CommPortSpeed(_)) => Some(&COMMANDS[8]),
        FieldValue::Base(crate::base::SetField::GpsTimeUpdate(
            crate::base::GpsTimeUpdate::Gx5_45(_),
        )) => Some(&COMMANDS[9]),
        FieldValue::Base(crate::base::SetField::GpsTimeUpdate(
            crate::base::GpsTimeUpdate::Cv7Ins(_),
        )) => Some(&COMMANDS[10]),
        FieldValue::Base(crate::base::SetField::DeviceReset(_)) => Some(&COMMANDS[11]),
        FieldValue::Threedm(crate::threedm::SetField::EventControl(_)) => Some(&COMMANDS[12]),
        FieldValue::Threedm(crate::threedm::SetField::GetEventTriggerStatus(_)) => {
            Some(&COMMANDS[13])
        }
        FieldValue::Threedm(crate::threedm::SetField::GetEventActionStatus(_)) => {
            Some(&COMMANDS[14])
        }
        FieldValue::Threedm(crate::threedm::SetField::EventTriggerConfig(_)) => Some(&COMMANDS[15]),
        FieldValue::Threedm(crate::threedm::SetField::EventActionConfig(_)) => Some(&COMMANDS[16]),
        FieldValue::Threedm(crate::threedm::SetField::DeviceStartupSettings(
            crate::threedm::DeviceStartupSettings::Gx5_45(_),
        )) => Some(&COMMANDS[17]),
        FieldValue::Threedm(crate::threedm::SetField::DeviceStartupSettings(
            crate::threedm::DeviceStartupSettings::Cv7Ins(_),
        )) => Some(&COMMANDS[18]),
        FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleEuler(_)) => {
            Some(&COMMANDS[19])
        }
        FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleQuaternion(_)) => {
            Some(&COMMANDS[20])
        }
        FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleDcm(_)) => Some(&COMMANDS[21]),
        FieldValue::Threedm(crate::threedm::SetField::AccelBias(
            crate::threedm::AccelBias::Gx5_45(_),
        )) => Some(&COMMANDS[22]),
        FieldValue::Threedm(crate::threedm::SetField::AccelBias(
            crate::threedm::AccelBias::Cv7Ins(_),
        )) => Some(&COMMANDS[23]),
        FieldValue::Threedm(crate::threedm::SetField::GyroBias(
            crate::threedm::GyroBias::Gx5_45(_),
        )) => Some(&COMMANDS[24]),
        FieldValue::Threedm(crate::threedm::SetField::GyroBias(
            crate::threedm::GyroBias::Cv7Ins(_),
        )) => Some(&COMMANDS[25]),
        FieldValue::Threedm(crate::threedm::SetField::CaptureGyroBias(_)) => Some(&COMMANDS[26]),
        FieldValue::Threedm(crate::threedm::SetField::MagHardIronOffset(
            crate::threedm::MagHardIronOffset::Gx5_45(_),
        )) => Some(&COMMANDS[27]),
        FieldValue::Threedm(crate::threedm::SetField::MagHardIronOffset(
            crate::threedm::MagHardIronOffset::Cv7Ins(_),
        )) => Some(&COMMANDS[28]),
        FieldValue::Threedm(crate::threedm::SetField::MagSoftIronMatrix(
            crate::threedm::MagSoftIronMatrix::Gx5_45(_),
        )) => Some(&COMMANDS[29]),
        FieldValue::Threedm(crate::threedm::SetField::MagSoftIronMatrix(
            crate::threedm::MagSoftIronMatrix::Cv7Ins(_),
        )) => Some(&COMMANDS[30]),
        FieldValue::Threedm(crate::threedm::SetField::ConingScullingEnable(_)) => {
            Some(&COMMANDS[31])
        }
        FieldValue::Threedm(crate::threedm::SetField::UartBaudrate(_)) => Some(&COMMANDS[32]),
        FieldValue::Threedm(crate::threedm::SetField::GpioConfig(_)) => Some(&COMMANDS[33]),
        FieldValue::Threedm(crate::threedm::SetField::GpioState(_)) => Some(&COMMANDS[34]),
        FieldValue::Threedm(crate::threedm::SetField::OdometerConfig(_)) => Some(&COMMANDS[35]),
        FieldValue::Threedm(crate::threedm::SetField::AdvancedLowpassFilter(_)) => {
            Some(&COMMANDS[36])
        }
        FieldValue::Threedm(crate::threedm::SetField::ComplementaryFilter(_)) => {
            Some(&COMMANDS[37])
        }
        FieldValue::Threedm(crate::threedm::SetField::SensorRange(_)) => Some(&COMMANDS[38]),
        FieldValue::Threedm(crate::threedm::SetField::GetCalibratedSensorRanges(_)) => {
            Some(&COMMANDS[39])
        }
        FieldValue::Threedm(crate::threedm::SetField::LowpassFilter(_)) => Some(&COMMANDS[40]),
        FieldValue::Threedm(crate::threedm::SetField::PollImuData(_)) => Some(&COMMANDS[41]),
        FieldValue::Threedm(crate::threedm::SetField::PollGnssData(_)) => Some(&COMMANDS[42]),
        FieldValue::Threedm(crate::threedm::SetField::PollFilterData(_)) => Some(&COMMANDS[43]),
        FieldValue::Threedm(crate::threedm::SetField::PollNmeaData(_)) => Some(&COMMANDS[44]),
        FieldValue::Threedm(crate::threedm::SetField::PollData(_)) => Some(&COMMANDS[45]),
        FieldValue::Threedm(crate::threedm::SetField::GetImuBaseRate(_)) => Some(&COMMANDS[46]),
        FieldValue::Threedm(crate::threedm::SetField::GetGnssBaseRate(_)) => Some(&COMMANDS[47]),
        FieldValue::Threedm(crate::threedm::SetField::GetFilterBaseRate(_)) => Some(&COMMANDS[48]),
        FieldValue::Threedm(crate::threedm::SetField::GetBaseRate(_)) => Some(&COMMANDS[49]),
        FieldValue::Threedm(crate::threedm::SetField::ImuMessageFormat(_)) => Some(&COMMANDS[50]),
        FieldValue::Threedm(crate::threedm::SetField::GnssMessageFormat(_)) => Some(&COMMANDS[51]),
        FieldValue::Threedm(crate::threedm::SetField::FilterMessageFormat(_)) => {
            Some(&COMMANDS[52])
        }
        FieldValue::Threedm(crate::threedm::SetField::NmeaMessageFormat(_)) => Some(&COMMANDS[53]),
        FieldValue::Threedm(crate::threedm::SetField::MessageFormat(_)) => Some(&COMMANDS[54]),
        FieldValue::Threedm(crate::threedm::SetField::FactoryStreaming(_)) => Some(&COMMANDS[55]),
        FieldValue::Threedm(crate::threedm::SetField::DataStreamControl(
            crate::threedm::DataStreamControl::Gx5_45(_),
        )) => Some(&COMMANDS[56]),
        FieldValue::Threedm(crate::threedm::SetField::DataStreamControl(
            crate::threedm::DataStreamControl::Cv7Ins(_),
        )) => Some(&COMMANDS[57]),
        FieldValue::Threedm(crate::threedm::SetField::RawRtcmMessage(_)) => Some(&COMMANDS[58]),
        FieldValue::Threedm(crate::threedm::SetField::GnssConstellationSettings(_)) => {
            Some(&COMMANDS[59])
        }
        FieldValue::Threedm(crate::threedm::SetField::GnssSbasSettings(_)) => Some(&COMMANDS[60]),
        FieldValue::Threedm(crate::threedm::SetField::GnssAssistedFixControl(_)) => {
            Some(&COMMANDS[61])
        }
        FieldValue::Threedm(crate::threedm::SetField::GnssAssistTimeUpdate(_)) => {
            Some(&COMMANDS[62])
        }
        FieldValue::Threedm(crate::threedm::SetField::PpsSource(_)) => Some(&COMMANDS[63]),
        FieldValue::Threedm(crate::threedm::SetField::GetSupportedEvents(_)) => Some(&COMMANDS[64]),
        FieldValue::Threedm(crate::threedm::SetField::DeviceStatus(_)) => Some(&COMMANDS[65]),
        FieldValue::Filter(crate::filter::SetField::ResetFilter(_)) => Some(&COMMANDS[66]),
        FieldValue::Filter(crate::filter::SetField::SetInitialAttitude(_)) => Some(&COMMANDS[67]),
        FieldValue::Filter(crate::filter::SetField::SetInitialHeading(_)) => Some(&COMMANDS[68]),
        FieldValue::Filter(crate::filter::SetField::RunFilter(_)) => Some(&COMMANDS[69]),
        FieldValue::Filter(crate::filter::SetField::VehicleDynamicsMode(_)) => Some(&COMMANDS[70]),
        FieldValue::Filter(crate::filter::SetField::SensorToVehicleTransform(_)) => {
            Some(&COMMANDS[71])
        }
        FieldValue::Filter(crate::filter::SetField::SensorToVehicleOffset(_)) => {
            Some(&COMMANDS[72])
        }
        FieldValue::Filter(crate::filter::SetField::AntennaOffset(_)) => Some(&COMMANDS[73]),
        FieldValue::Filter(crate::filter::SetField::EstimationControl(_)) => Some(&COMMANDS[74]),
        FieldValue::Filter(crate::filter::SetField::GnssSourceControl(_)) => Some(&COMMANDS[75]),
        FieldValue::Filter(crate::filter::SetField::ExternalGnssUpdate(_)) => Some(&COMMANDS[76]),
        FieldValue::Filter(crate::filter::SetField::ExternalHeadingUpdate(_)) => {
            Some(&COMMANDS[77])
        }
        FieldValue::Filter(crate::filter::SetField::HeadingUpdateControl(_)) => Some(&COMMANDS[78]),
        FieldValue::Filter(crate::filter::SetField::AutoInitControl(_)) => Some(&COMMANDS[79]),
        FieldValue::Filter(crate::filter::SetField::AccelNoise(_)) => Some(&COMMANDS[80]),
        FieldValue::Filter(crate::filter::SetField::GyroNoise(_)) => Some(&COMMANDS[81]),
        FieldValue::Filter(crate::filter::SetField::AccelBiasModel(_)) => Some(&COMMANDS[82]),
        FieldValue::Filter(crate::filter::SetField::GyroBiasModel(_)) => Some(&COMMANDS[83]),
        FieldValue::Filter(crate::filter::SetField::ZuptControl(_)) => Some(&COMMANDS[84]),
        FieldValue::Filter(crate::filter::SetField::ExternalHeadingUpdateWithTime(_)) => {
            Some(&COMMANDS[85])
        }
        FieldValue::Filter(crate::filter::SetField::ZeroAngularRateUpdateControl(_)) => {
            Some(&COMMANDS[86])
        }
        FieldValue::Filter(crate::filter::SetField::TareOrientation(_)) => Some(&COMMANDS[87]),
        FieldValue::Filter(crate::filter::SetField::CommandedZupt(_)) => Some(&COMMANDS[88]),
        FieldValue::Filter(crate::filter::SetField::CommandedZeroAngularRateUpdate(_)) => {
            Some(&COMMANDS[89])
        }
        FieldValue::Filter(crate::filter::SetField::MagCaptureAutoCalibration(_)) => {
            Some(&COMMANDS[90])
        }
        FieldValue::Filter(crate::filter::SetField::GravityNoiseStdDev(_)) => Some(&COMMANDS[91]),
        FieldValue::Filter(crate::filter::SetField::PressureAltitudeNoiseStdDev(_)) => {
            Some(&COMMANDS[92])
        }
        FieldValue::Filter(crate::filter::SetField::HardIronOffsetNoise(_)) => Some(&COMMANDS[93]),
        FieldValue::Filter(crate::filter::SetField::SoftIronMatrixNoise(_)) => Some(&COMMANDS[94]),
        FieldValue::Filter(crate::filter::SetField::MagNoiseStdDev(_)) => Some(&COMMANDS[95]),
        FieldValue::Filter(crate::filter::SetField::DeclinationSource(_)) => Some(&COMMANDS[96]),
        FieldValue::Filter(crate::filter::SetField::GravityMagnitudeAdaptiveMeasurement(_)) => {
            Some(&COMMANDS[97])
        }
        FieldValue::Filter(crate::filter::SetField::MagMagnitudeAdaptiveMeasurement(_)) => {
            Some(&COMMANDS[98])
        }
        FieldValue::Filter(crate::filter::SetField::MagDipAngleAdaptiveMeasurement(_)) => {
            Some(&COMMANDS[99])
        }
        FieldValue::Filter(crate::filter::SetField::AltitudeAidingControl(_)) => {
            Some(&COMMANDS[100])
        }
        FieldValue::Filter(crate::filter::SetField::PitchRollAidingControl(_)) => {
            Some(&COMMANDS[101])
        }
        FieldValue::Filter(crate::filter::SetField::InclinationSource(_)) => Some(&COMMANDS[102]),
        FieldValue::Filter(crate::filter::SetField::MagneticFieldMagnitudeSource(_)) => {
            Some(&COMMANDS[103])
        }
        FieldValue::Filter(crate::filter::SetField::AidingMeasurementControl(_)) => {
            Some(&COMMANDS[104])
        }
        FieldValue::Filter(crate::filter::SetField::InitializationConfiguration(_)) => {
            Some(&COMMANDS[105])
        }
        FieldValue::Filter(crate::filter::SetField::AdaptiveFilterControl(_)) => {
            Some(&COMMANDS[106])
        }
        FieldValue::Filter(crate::filter::SetField::MultiAntennaOffset(_)) => Some(&COMMANDS[107]),
        FieldValue::Filter(crate::filter::SetField::RelativePositionConfiguration(_)) => {
            Some(&COMMANDS[108])
        }
        FieldValue::Filter(crate::filter::SetField::ReferencePointLeverArm(_)) => {
            Some(&COMMANDS[109])
        }
        FieldValue::Filter(crate::filter::SetField::SpeedLeverArm(_)) => Some(&COMMANDS[110]),
        FieldValue::Filter(crate::filter::SetField::WheeledVehicleConstraintControl(_)) => {
            Some(&COMMANDS[111])
        }
        FieldValue::Filter(crate::filter::SetField::GnssAntennaCalibrationControl(_)) => {
            Some(&COMMANDS[112])
        }
        FieldValue::Gnss(crate::gnss::SetField::ReceiverInfo(_)) => Some(&COMMANDS[113]),
        FieldValue::Gnss(crate::gnss::SetField::SignalConfiguration(_)) => Some(&COMMANDS[114]),
        FieldValue::Gnss(crate::gnss::SetField::SpartnConfiguration(_)) => Some(&COMMANDS[115]),
        FieldValue::Aiding(crate::aiding::SetField::FrameConfig(_)) => Some(&COMMANDS[116]),
        FieldValue::Aiding(crate::aiding::SetField::EchoControl(_)) => Some(&COMMANDS[117]),
        FieldValue::Aiding(crate::aiding::SetField::EcefPosition(_)) => Some(&COMMANDS[118]),
        FieldValue::Aiding(crate::aiding::SetField::LlhPosition(_)) => Some(&COMMANDS[119]),
        FieldValue::Aiding(crate::aiding::SetField::HeightAboveEllipsoid(_)) => {
            Some(&COMMANDS[120])
        }
        FieldValue::Aiding(crate::aiding::SetField::EcefVelocity(_)) => Some(&COMMANDS[121]),
        FieldValue::Aiding(crate::aiding::SetField::NedVelocity(_)) => Some(&COMMANDS[122]),
        FieldValue::Aiding(crate::aiding::SetField::BodyFrameVelocity(_)) => Some(&COMMANDS[123]),
        FieldValue::Aiding(crate::aiding::SetField::TrueHeading(_)) => Some(&COMMANDS[124]),
        FieldValue::Aiding(crate::aiding::SetField::MagneticField(_)) => Some(&COMMANDS[125]),
        FieldValue::Aiding(crate::aiding::SetField::Pressure(_)) => Some(&COMMANDS[126]),
        FieldValue::System(crate::system::SetField::CommunicationMode(_)) => Some(&COMMANDS[127]),
        _ => None,
    }
}

/// The function selector value of a command value, or `None` when it has none.
pub fn command_function(value: &FieldValue) -> Option<u8> {
    match value {
        FieldValue::Base(crate::base::SetField::CommPortSpeed(v)) => Some(v.function.0),
        FieldValue::Base(crate::base::SetField::GpsTimeUpdate(
            crate::base::GpsTimeUpdate::Gx5_45(v),
        )) => Some(v.function.0),
        FieldValue::Base(crate::base::SetField::GpsTimeUpdate(
            crate::base::GpsTimeUpdate::Cv7Ins(v),
        )) => Some(v.function.0),
        FieldValue::Threedm(crate::threedm::SetField::EventControl(v)) => Some(v.function.0),
        FieldValue::Threedm(crate::threedm::SetField::EventTriggerConfig(v)) => Some(v.function.0),
        FieldValue::Threedm(crate::threedm::SetField::EventActionConfig(v)) => Some(v.function.0),
        FieldValue::Threedm(crate::threedm::SetField::DeviceStartupSettings(
            crate::threedm::DeviceStartupSettings::Gx5_45(v),
        )) => Some(v.function.0),
        FieldValue::Threedm(crate::threedm::SetField::DeviceStartupSettings(
            crate::threedm::DeviceStartupSettings::Cv7Ins(v),
        )) => Some(v.function.0),
        FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleEuler(v)) => {
            Some(v.function.0)
        }
        FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleQuaternion(v)) => {
            Some(v.function.0)
        }
        FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleDcm(v)) => Some(v.function.0),
        FieldValue::Threedm(crate::threedm::SetField::AccelBias(
            crate::threedm::AccelBias::Gx5_45(v),
        )) => Some(v.function.0),
        FieldValue::Threedm(crate::threedm::SetField::AccelBias(
            crate::threedm::AccelBias::Cv7Ins(v),
        )) => Some(v.function.0),
        FieldValue::Threedm(crate::threedm::SetField::GyroBias(
            crate::threedm::GyroBias::Gx5_45(v),
        )) => Some(v.function.0),
        FieldValue::Threedm(crate::threedm::SetField::GyroBias(
            crate::threedm::GyroBias::Cv7Ins(v),
        )) => Some(v.function.0),
        FieldValue::Threedm(crate::threedm::SetField::MagHardIronOffset(
            crate::threedm::MagHardIronOffset::Gx5_45(v),
        )) => Some(v.function.0),
        FieldValue::Threedm(crate::threedm::SetField::MagHardIronOffset(
            crate::threedm::MagHardIronOffset::Cv7Ins(v),
        )) => Some(v.function.0),
        FieldValue::Threedm(crate::threedm::SetField::MagSoftIronMatrix(
            crate::threedm::MagSoftIronMatrix::Gx5_45(v),
        )) => Some(v.function.0),
        FieldValue::Threedm(crate::threedm::SetField::MagSoftIronMatrix(
            crate::threedm::MagSoftIronMatrix::Cv7Ins(v),
        )) => Some(v.function.0),
        FieldValue::Threedm(crate::threedm::SetField::ConingScullingEnable(v)) => {
            Some(v.function.0)
        }
        FieldValue::Threedm(crate::threedm::SetField::UartBaudrate(v)) => Some(v.function.0),
        FieldValue::Threedm(crate::threedm::SetField::GpioConfig(v)) => Some(v.function.0),
        FieldValue::Threedm(crate::threedm::SetField::GpioState(v)) => Some(v.function.0),
        FieldValue::Threedm(crate::threedm::SetField::OdometerConfig(v)) => Some(v.function.0),
        FieldValue::Threedm(crate::threedm::SetField::AdvancedLowpassFilter(v)) => {
            Some(v.function.0)
        }
        FieldValue::Threedm(crate::threedm::SetField::ComplementaryFilter(v)) => Some(v.function.0),
        FieldValue::Threedm(crate::threedm::SetField::SensorRange(v)) => Some(v.function.0),
        FieldValue::Threedm(crate::threedm::SetField::LowpassFilter(v)) => Some(v.function.0),
        FieldValue::Threedm(crate::threedm::SetField::ImuMessageFormat(v)) => Some(v.function.0),
        FieldValue::Threedm(crate::threedm::SetField::GnssMessageFormat(v)) => Some(v.function.0),
        FieldValue::Threedm(crate::threedm::SetField::FilterMessageFormat(v)) => Some(v.function.0),
        FieldValue::Threedm(crate::threedm::SetField::NmeaMessageFormat(v)) => Some(v.function.0),
        FieldValue::Threedm(crate::threedm::SetField::MessageFormat(v)) => Some(v.function.0),
        FieldValue::Threedm(crate::threedm::SetField::DataStreamControl(
            crate::threedm::DataStreamControl::Gx5_45(v),
        )) => Some(v.function.0),
        FieldValue::Threedm(crate::threedm::SetField::DataStreamControl(
            crate::threedm::DataStreamControl::Cv7Ins(v),
        )) => Some(v.function.0),
        FieldValue::Threedm(crate::threedm::SetField::GnssConstellationSettings(v)) => {
            Some(v.function.0)
        }
        FieldValue::Threedm(crate::threedm::SetField::GnssSbasSettings(v)) => Some(v.function.0),
        FieldValue::Threedm(crate::threedm::SetField::GnssAssistedFixControl(v)) => {
            Some(v.function.0)
        }
        FieldValue::Threedm(crate::threedm::SetField::GnssAssistTimeUpdate(v)) => {
            Some(v.function.0)
        }
        FieldValue::Threedm(crate::threedm::SetField::PpsSource(v)) => Some(v.function.0),
        FieldValue::Filter(crate::filter::SetField::VehicleDynamicsMode(v)) => Some(v.function.0),
        FieldValue::Filter(crate::filter::SetField::SensorToVehicleTransform(v)) => {
            Some(v.function.0)
        }
        FieldValue::Filter(crate::filter::SetField::SensorToVehicleOffset(v)) => Some(v.function.0),
        FieldValue::Filter(crate::filter::SetField::AntennaOffset(v)) => Some(v.function.0),
        FieldValue::Filter(crate::filter::SetField::EstimationControl(v)) => Some(v.function.0),
        FieldValue::Filter(crate::filter::SetField::GnssSourceControl(v)) => Some(v.function.0),
        FieldValue::Filter(crate::filter::SetField::HeadingUpdateControl(v)) => Some(v.function.0),
        FieldValue::Filter(crate::filter::SetField::AutoInitControl(v)) => Some(v.function.0),
        FieldValue::Filter(crate::filter::SetField::AccelNoise(v)) => Some(v.function.0),
        FieldValue::Filter(crate::filter::SetField::GyroNoise(v)) => Some(v.function.0),
        FieldValue::Filter(crate::filter::SetField::AccelBiasModel(v)) => Some(v.function.0),
        FieldValue::Filter(crate::filter::SetField::GyroBiasModel(v)) => Some(v.function.0),
        FieldValue::Filter(crate::filter::SetField::ZuptControl(v)) => Some(v.function.0),
        FieldValue::Filter(crate::filter::SetField::ZeroAngularRateUpdateControl(v)) => {
            Some(v.function.0)
        }
        FieldValue::Filter(crate::filter::SetField::TareOrientation(v)) => Some(v.function.0),
        FieldValue::Filter(crate::filter::SetField::MagCaptureAutoCalibration(v)) => {
            Some(v.function.0)
        }
        FieldValue::Filter(crate::filter::SetField::GravityNoiseStdDev(v)) => Some(v.function.0),
        FieldValue::Filter(crate::filter::SetField::PressureAltitudeNoiseStdDev(v)) => {
            Some(v.function.0)
        }
        FieldValue::Filter(crate::filter::SetField::HardIronOffsetNoise(v)) => Some(v.function.0),
        FieldValue::Filter(crate::filter::SetField::SoftIronMatrixNoise(v)) => Some(v.function.0),
        FieldValue::Filter(crate::filter::SetField::MagNoiseStdDev(v)) => Some(v.function.0),
        FieldValue::Filter(crate::filter::SetField::DeclinationSource(v)) => Some(v.function.0),
        FieldValue::Filter(crate::filter::SetField::GravityMagnitudeAdaptiveMeasurement(v)) => {
            Some(v.function.0)
        }
        FieldValue::Filter(crate::filter::SetField::MagMagnitudeAdaptiveMeasurement(v)) => {
            Some(v.function.0)
        }
        FieldValue::Filter(crate::filter::SetField::MagDipAngleAdaptiveMeasurement(v)) => {
            Some(v.function.0)
        }
        FieldValue::Filter(crate::filter::SetField::AltitudeAidingControl(v)) => Some(v.function.0),
        FieldValue::Filter(crate::filter::SetField::PitchRollAidingControl(v)) => {
            Some(v.function.0)
        }
        FieldValue::Filter(crate::filter::SetField::InclinationSource(v)) => Some(v.function.0),
        FieldValue::Filter(crate::filter::SetField::MagneticFieldMagnitudeSource(v)) => {
            Some(v.function.0)
        }
        FieldValue::Filter(crate::filter::SetField::AidingMeasurementControl(v)) => {
            Some(v.function.0)
        }
        FieldValue::Filter(crate::filter::SetField::InitializationConfiguration(v)) => {
            Some(v.function.0)
        }
        FieldValue::Filter(crate::filter::SetField::AdaptiveFilterControl(v)) => Some(v.function.0),
        FieldValue::Filter(crate::filter::SetField::MultiAntennaOffset(v)) => Some(v.function.0),
        FieldValue::Filter(crate::filter::SetField::RelativePositionConfiguration(v)) => {
            Some(v.function.0)
        }
        FieldValue::Filter(crate::filter::SetField::ReferencePointLeverArm(v)) => {
            Some(v.function.0)
        }
        FieldValue::Filter(crate::filter::SetField::SpeedLeverArm(v)) => Some(v.function.0),
        FieldValue::Filter(crate::filter::SetField::WheeledVehicleConstraintControl(v)) => {
            Some(v.function.0)
        }
        FieldValue::Filter(crate::filter::SetField::GnssAntennaCalibrationControl(v)) => {
            Some(v.function.0)
        }
        FieldValue::Gnss(crate::gnss::SetField::SignalConfiguration(v)) => Some(v.function.0),
        FieldValue::Gnss(crate::gnss::SetField::SpartnConfiguration(v)) => Some(v.function.0),
        FieldValue::Aiding(crate::aiding::SetField::FrameConfig(v)) => Some(v.function.0),
        FieldValue::Aiding(crate::aiding::SetField::EchoControl(v)) => Some(v.function.0),
        FieldValue::System(crate::system::SetField::CommunicationMode(v)) => Some(v.function.0),
        _ => None,
    }
}

/// The integer value of a command parameter that the facts name (in a `when`, the ack
/// suppression or the allowance), or `None` when the value does not have it.
#[allow(clippy::match_single_binding)]
pub fn command_param(value: &FieldValue, name: &str) -> Option<i64> {
    match (value, name) {
        (
            FieldValue::Base(crate::base::SetField::GpsTimeUpdate(
                crate::base::GpsTimeUpdate::Gx5_45(v),
            )),
            "field_id",
        ) => Some(v.field_id.0 as i64),
        (
            FieldValue::Threedm(crate::threedm::SetField::CaptureGyroBias(v)),
            "averaging_time_ms",
        ) => Some(v.averaging_time_ms as i64),
        (FieldValue::Threedm(crate::threedm::SetField::PollImuData(v)), "option") => {
            Some(v.option.0 as i64)
        }
        (FieldValue::Threedm(crate::threedm::SetField::PollGnssData(v)), "option") => {
            Some(v.option.0 as i64)
        }
        (FieldValue::Threedm(crate::threedm::SetField::PollFilterData(v)), "option") => {
            Some(v.option.0 as i64)
        }
        (FieldValue::Threedm(crate::threedm::SetField::PollNmeaData(v)), "suppress_ack") => {
            Some(i64::from(v.suppress_ack))
        }
        (FieldValue::Threedm(crate::threedm::SetField::PollData(v)), "suppress_ack") => {
            Some(i64::from(v.suppress_ack))
        }
        _ => None,
    }
}
