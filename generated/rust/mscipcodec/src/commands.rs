//! What the Memsense MS-CIP spec says about every command, for the session layer
//! ([`crate::session`], `docs/conformance.md` §8): how a reply is matched (the ack rule) and
//! one [`CommandFacts`] row per command layout: set, descriptor, devices, function selector
//! values, the reply fields with their `when`, ack suppression and the timeout allowance.
//! Generated from `spec/mscip/`; do not edit.

use crate::dispatch::{Device, FieldValue};
use crate::session::{AckSuppression, CommandFacts, ReferenceTime, ReplyFacts};

/// Descriptor of the ack/nack field that answers a command (in a packet of the command's set).
pub const ACK_DESCRIPTOR: u8 = 0x80;
/// The ack code of success; any other code is a NACK.
pub const ACK_OK: u32 = 0;

/// The echoed command descriptor and the code of an ack/nack field, or `None` for any other
/// value.
pub fn ack_of(value: &FieldValue) -> Option<(u8, u32)> {
    match value {
        FieldValue::Reserved(crate::reserved::ReservedField::Ack(a)) => {
            Some((a.command_code, u32::from(a.error_code.0)))
        }
        _ => None,
    }
}

/// Per device, where a data packet carries the device's reference time (the spec's
/// `time.reference_time`; the host clock model, `docs/time.md`), read by
/// [`crate::session::reference_ns`].
pub static REFERENCE_TIMES: &[ReferenceTime] = &[];

/// The spec's name of a function selector value.
pub fn function_name(value: u8) -> Option<&'static str> {
    match value {
        1 => Some("write"),
        2 => Some("read"),
        3 => Some("save"),
        4 => Some("load"),
        5 => Some("default"),
        _ => None,
    }
}

/// Function selector values that only some devices accept.
pub static FUNCTION_DEVICES: &[(u8, &[Device])] = &[];

/// One row per command layout, in spec order.
pub static COMMANDS: [CommandFacts; 20] = [
    CommandFacts {
        set: 0x01,
        descriptor: 0x02,
        name: "ping",
        device: None,
        devices: &[Device::MsImu3020],
        functions: None,
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x01,
        descriptor: 0x03,
        name: "get_device_messages",
        device: None,
        devices: &[Device::MsImu3020],
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
        set: 0x01,
        descriptor: 0x04,
        name: "device_reset",
        device: None,
        devices: &[Device::MsImu3020],
        functions: None,
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x01,
        descriptor: 0x05,
        name: "get_device_model",
        device: None,
        devices: &[Device::MsImu3020],
        functions: None,
        replies: &[ReplyFacts {
            descriptor: 0x85,
            function: None,
            param: None,
            value: None,
        }],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x01,
        descriptor: 0x06,
        name: "get_device_sn",
        device: None,
        devices: &[Device::MsImu3020],
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
        descriptor: 0x07,
        name: "get_device_fw",
        device: None,
        devices: &[Device::MsImu3020],
        functions: None,
        replies: &[ReplyFacts {
            descriptor: 0x87,
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
        name: "get_device_cal",
        device: None,
        devices: &[Device::MsImu3020],
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
        name: "correlate_gps_time",
        device: None,
        devices: &[Device::MsImu3020],
        functions: None,
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x02,
        descriptor: 0x01,
        name: "uart_baud_rate",
        device: None,
        devices: &[Device::MsImu3020],
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
        set: 0x02,
        descriptor: 0x03,
        name: "filter",
        device: None,
        devices: &[Device::MsImu3020],
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
        set: 0x02,
        descriptor: 0x04,
        name: "sample_rate",
        device: None,
        devices: &[Device::MsImu3020],
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
        set: 0x02,
        descriptor: 0x05,
        name: "select_sensors",
        device: None,
        devices: &[Device::MsImu3020],
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
        set: 0x02,
        descriptor: 0x06,
        name: "get_internal_sample_rate",
        device: None,
        devices: &[Device::MsImu3020],
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
        set: 0x02,
        descriptor: 0x07,
        name: "accel_range",
        device: None,
        devices: &[Device::MsImu3020],
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
        set: 0x02,
        descriptor: 0x08,
        name: "gyro_range",
        device: None,
        devices: &[Device::MsImu3020],
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
        set: 0x02,
        descriptor: 0x09,
        name: "config_all",
        device: None,
        devices: &[Device::MsImu3020],
        functions: Some(&[3, 4, 5]),
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x02,
        descriptor: 0x0A,
        name: "data_on_off",
        device: None,
        devices: &[Device::MsImu3020],
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
        set: 0x02,
        descriptor: 0x0B,
        name: "xtrig_on_off",
        device: None,
        devices: &[Device::MsImu3020],
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
        set: 0x02,
        descriptor: 0x0C,
        name: "select_sensors_rev_b",
        device: None,
        devices: &[Device::MsImu3020],
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
        set: 0x02,
        descriptor: 0x0D,
        name: "aux_accel_range",
        device: None,
        devices: &[Device::MsImu3020],
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
];

/// The facts of a command value's layout, or `None` when the value is not a command.
pub fn command_facts(value: &FieldValue) -> Option<&'static CommandFacts> {
    match value {
        FieldValue::Base(crate::base::SetField::Ping(_)) => Some(&COMMANDS[0]),
        FieldValue::Base(crate::base::SetField::GetDeviceMessages(_)) => Some(&COMMANDS[1]),
        FieldValue::Base(crate::base::SetField::DeviceReset(_)) => Some(&COMMANDS[2]),
        FieldValue::Base(crate::base::SetField::GetDeviceModel(_)) => Some(&COMMANDS[3]),
        FieldValue::Base(crate::base::SetField::GetDeviceSn(_)) => Some(&COMMANDS[4]),
        FieldValue::Base(crate::base::SetField::GetDeviceFw(_)) => Some(&COMMANDS[5]),
        FieldValue::Base(crate::base::SetField::GetDeviceCal(_)) => Some(&COMMANDS[6]),
        FieldValue::Base(crate::base::SetField::CorrelateGpsTime(_)) => Some(&COMMANDS[7]),
        FieldValue::ImuConfig(crate::imu_config::SetField::UartBaudRate(_)) => Some(&COMMANDS[8]),
        FieldValue::ImuConfig(crate::imu_config::SetField::Filter(_)) => Some(&COMMANDS[9]),
        FieldValue::ImuConfig(crate::imu_config::SetField::SampleRate(_)) => Some(&COMMANDS[10]),
        FieldValue::ImuConfig(crate::imu_config::SetField::SelectSensors(_)) => Some(&COMMANDS[11]),
        FieldValue::ImuConfig(crate::imu_config::SetField::GetInternalSampleRate(_)) => {
            Some(&COMMANDS[12])
        }
        FieldValue::ImuConfig(crate::imu_config::SetField::AccelRange(_)) => Some(&COMMANDS[13]),
        FieldValue::ImuConfig(crate::imu_config::SetField::GyroRange(_)) => Some(&COMMANDS[14]),
        FieldValue::ImuConfig(crate::imu_config::SetField::ConfigAll(_)) => Some(&COMMANDS[15]),
        FieldValue::ImuConfig(crate::imu_config::SetField::DataOnOff(_)) => Some(&COMMANDS[16]),
        FieldValue::ImuConfig(crate::imu_config::SetField::XtrigOnOff(_)) => Some(&COMMANDS[17]),
        FieldValue::ImuConfig(crate::imu_config::SetField::SelectSensorsRevB(_)) => {
            Some(&COMMANDS[18])
        }
        FieldValue::ImuConfig(crate::imu_config::SetField::AuxAccelRange(_)) => Some(&COMMANDS[19]),
        _ => None,
    }
}

/// The function selector value of a command value, or `None` when it has none.
pub fn command_function(value: &FieldValue) -> Option<u8> {
    match value {
        FieldValue::ImuConfig(crate::imu_config::SetField::UartBaudRate(v)) => Some(v.function.0),
        FieldValue::ImuConfig(crate::imu_config::SetField::Filter(v)) => Some(v.function.0),
        FieldValue::ImuConfig(crate::imu_config::SetField::SampleRate(v)) => Some(v.function.0),
        FieldValue::ImuConfig(crate::imu_config::SetField::SelectSensors(v)) => Some(v.function.0),
        FieldValue::ImuConfig(crate::imu_config::SetField::AccelRange(v)) => Some(v.function.0),
        FieldValue::ImuConfig(crate::imu_config::SetField::GyroRange(v)) => Some(v.function.0),
        FieldValue::ImuConfig(crate::imu_config::SetField::ConfigAll(v)) => Some(v.function.0),
        FieldValue::ImuConfig(crate::imu_config::SetField::DataOnOff(v)) => Some(v.function.0),
        FieldValue::ImuConfig(crate::imu_config::SetField::XtrigOnOff(v)) => Some(v.function.0),
        FieldValue::ImuConfig(crate::imu_config::SetField::SelectSensorsRevB(v)) => {
            Some(v.function.0)
        }
        FieldValue::ImuConfig(crate::imu_config::SetField::AuxAccelRange(v)) => Some(v.function.0),
        _ => None,
    }
}

/// The integer value of a command parameter that the facts name (in a `when`, the ack
/// suppression or the allowance), or `None` when the value does not have it.
#[allow(clippy::match_single_binding)]
pub fn command_param(value: &FieldValue, name: &str) -> Option<i64> {
    match (value, name) {
        _ => None,
    }
}
