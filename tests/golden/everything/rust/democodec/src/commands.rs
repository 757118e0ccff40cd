//! What the Demo protocol with every spec feature spec says about every command, for the session layer
//! ([`crate::session`], `docs/conformance.md` §8): how a reply is matched (the ack rule) and
//! one [`CommandFacts`] row per command layout: set, descriptor, devices, function selector
//! values, the reply fields with their `when`, ack suppression and the timeout allowance.
//! Generated from `spec/demo/`; do not edit.

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
            Some((a.echo, u32::from(a.code)))
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
        _ => None,
    }
}

/// Function selector values that only some devices accept.
pub static FUNCTION_DEVICES: &[(u8, &[Device])] = &[];

/// One row per command layout, in spec order.
pub static COMMANDS: [CommandFacts; 4] = [
    CommandFacts {
        set: 0x01,
        descriptor: 0x01,
        name: "ping",
        device: None,
        devices: &[Device::DevA],
        functions: None,
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x01,
        descriptor: 0x02,
        name: "configure",
        device: None,
        devices: &[Device::DevA],
        functions: Some(&[1, 2, 3]),
        replies: &[ReplyFacts {
            descriptor: 0x82,
            function: Some(2),
            param: None,
            value: None,
        }],
        ack: AckSuppression::Param {
            param: "suppress_ack",
            value: None,
        },
        timeout: None,
    },
    CommandFacts {
        set: 0x01,
        descriptor: 0x03,
        name: "per_device",
        device: Some(Device::DevA),
        devices: &[Device::DevA],
        functions: None,
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
    CommandFacts {
        set: 0x01,
        descriptor: 0x03,
        name: "per_device",
        device: Some(Device::DevB),
        devices: &[Device::DevB],
        functions: None,
        replies: &[],
        ack: AckSuppression::Never,
        timeout: None,
    },
];

/// The facts of a command value's layout, or `None` when the value is not a command.
pub fn command_facts(value: &FieldValue) -> Option<&'static CommandFacts> {
    match value {
        FieldValue::CommandsSet(crate::commands_set::SetField::Ping(_)) => Some(&COMMANDS[0]),
        FieldValue::CommandsSet(crate::commands_set::SetField::Configure(_)) => Some(&COMMANDS[1]),
        FieldValue::CommandsSet(crate::commands_set::SetField::PerDevice(
            crate::commands_set::PerDevice::DevA(_),
        )) => Some(&COMMANDS[2]),
        FieldValue::CommandsSet(crate::commands_set::SetField::PerDevice(
            crate::commands_set::PerDevice::DevB(_),
        )) => Some(&COMMANDS[3]),
        _ => None,
    }
}

/// The function selector value of a command value, or `None` when it has none.
pub fn command_function(value: &FieldValue) -> Option<u8> {
    match value {
        FieldValue::CommandsSet(crate::commands_set::SetField::Configure(v)) => Some(v.function.0),
        _ => None,
    }
}

/// The integer value of a command parameter that the facts name (in a `when`, the ack
/// suppression or the allowance), or `None` when the value does not have it.
#[allow(clippy::match_single_binding)]
pub fn command_param(value: &FieldValue, name: &str) -> Option<i64> {
    match (value, name) {
        (FieldValue::CommandsSet(crate::commands_set::SetField::Configure(v)), "suppress_ack") => {
            v.suppress_ack.map(|x| i64::from(x))
        }
        _ => None,
    }
}
