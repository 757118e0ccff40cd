//! Stand-in for the generated `commands` module (templates/rust/commands.rs.j2): the ack rule
//! and the facts of the tiny protocol's one command, `ping`.

use crate::dispatch::{Device, FieldValue, ACK, COMMAND_SET, PING};
use crate::session::{AckSuppression, CommandFacts};

/// Descriptor of the ack/nack field.
pub const ACK_DESCRIPTOR: u8 = ACK;
/// The ack code of success.
pub const ACK_OK: u32 = 0;

/// The echoed command descriptor and the code of an ack field.
pub fn ack_of(value: &FieldValue) -> Option<(u8, u32)> {
    match value {
        FieldValue::Ack(echo, code) => Some((*echo, u32::from(*code))),
        _ => None,
    }
}

/// The spec's name of a function selector value (the tiny protocol has none).
pub fn function_name(value: u8) -> Option<&'static str> {
    let _ = value;
    None
}

/// Function selector values that only some devices accept.
pub static FUNCTION_DEVICES: &[(u8, &[Device])] = &[];

/// One row per command layout.
pub static COMMANDS: [CommandFacts; 1] = [CommandFacts {
    set: COMMAND_SET,
    descriptor: PING,
    name: "ping",
    device: None,
    devices: &[Device::Tiny],
    functions: None,
    replies: &[],
    ack: AckSuppression::Never,
    timeout: None,
}];

/// The facts of a command value's layout.
pub fn command_facts(value: &FieldValue) -> Option<&'static CommandFacts> {
    match value {
        FieldValue::Ping => Some(&COMMANDS[0]),
        _ => None,
    }
}

/// The function selector value of a command value.
pub fn command_function(value: &FieldValue) -> Option<u8> {
    let _ = value;
    None
}

/// A parameter value the facts name.
pub fn command_param(value: &FieldValue, name: &str) -> Option<i64> {
    let _ = (value, name);
    None
}
