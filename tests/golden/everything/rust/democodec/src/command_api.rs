//! The typed command API of Demo protocol with every spec feature (std), generated from `spec/demo/`: one
//! method per command set on [`Device`], one per command, and one call per function it supports
//! (`write`, `read`, `save`, `load`, `default`, ...) or a plain call, with typed parameters in and
//! the typed reply out. With a device model selected, a command or function the model does not
//! support is refused before sending ([`SessionError::Refused`]; see
//! [`Device::with_check_device`]).
//!
//! ```no_run
//! # fn main() -> Result<(), democodec::device::SessionError> {
//! let mut device = democodec::device::connect("tcp:192.168.1.100:5000", None, 115_200)?;
//! device.commands_set().ping();
//! # Ok(())
//! # }
//! ```
#![allow(clippy::too_many_arguments)]

use crate::device::{Device, SessionError, Transport};
#[allow(unused_imports)]
use crate::dispatch::{Device as Model, FieldValue};

/// Checks the result's reply and picks the typed field.
fn reply<R>(
    name: &'static str,
    value: Option<FieldValue>,
    pick: impl FnOnce(FieldValue) -> Option<R>,
) -> Result<R, SessionError> {
    value.and_then(pick).ok_or(SessionError::Invalid {
        name,
        error: "the reply field is missing".into(),
    })
}

impl<T: Transport> Device<T> {
    /// Commands of set 0x01 (Commands).
    pub fn commands_set(&mut self) -> CommandsSetCommands<'_, T> {
        CommandsSetCommands { device: self }
    }
}

/// Commands of set 0x01 (Commands), bound to a [`Device`].
#[derive(Debug)]
pub struct CommandsSetCommands<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> CommandsSetCommands<'d, T> {
    /// Ping (0x01). Sends `ping`.
    pub fn ping(self) -> Result<(), SessionError> {
        send_ping_ping(self.device)
    }
    /// Configure (0x02).
    pub fn configure(self) -> ConfigureCommand<'d, T> {
        ConfigureCommand {
            device: self.device,
        }
    }
    /// Per-device command (0x03). Sends `per_device` (layout for dev_a).
    pub fn per_device_dev_a(self, a: u32) -> Result<(), SessionError> {
        send_per_device_per_device_dev_a(self.device, a)
    }
    /// Per-device command (0x03). Sends `per_device` (layout for dev_b).
    pub fn per_device_dev_b(self, b: u64, extra: Option<u8>) -> Result<(), SessionError> {
        send_per_device_per_device_dev_b(self.device, b, extra)
    }
}

fn send_ping_ping<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::commands_set::Ping {};
    let value = FieldValue::CommandsSet(crate::commands_set::SetField::Ping(command));
    device.call(&value).map(|_| ())
}

/// Configure (0x01, 0x02): one call per function.
#[derive(Debug)]
pub struct ConfigureCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> ConfigureCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        instance: u8,
        mode: crate::types::Mode,
        params: crate::types::TriggerParams,
        suppress_ack: bool,
    ) -> Result<(), SessionError> {
        send_configure_write(self.device, instance, mode, params, suppress_ack)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self, instance: u8) -> Result<crate::commands_set::Configuration, SessionError> {
        send_configure_read(self.device, instance)
    }
    /// Function `save`.
    pub fn save(self, instance: u8) -> Result<(), SessionError> {
        send_configure_save(self.device, instance)
    }
}

fn send_configure_write<T: Transport>(
    device: &mut Device<T>,
    instance: u8,
    mode: crate::types::Mode,
    params: crate::types::TriggerParams,
    suppress_ack: bool,
) -> Result<(), SessionError> {
    let command = crate::commands_set::Configure {
        function: crate::types::Function(1),
        instance,
        mode: Some(mode),
        params: Some(params),
        suppress_ack: Some(suppress_ack),
    };
    let value = FieldValue::CommandsSet(crate::commands_set::SetField::Configure(command));
    device.call(&value).map(|_| ())
}

fn send_configure_read<T: Transport>(
    device: &mut Device<T>,
    instance: u8,
) -> Result<crate::commands_set::Configuration, SessionError> {
    let command = crate::commands_set::Configure {
        function: crate::types::Function(2),
        instance,
        ..<crate::commands_set::Configure as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::CommandsSet(crate::commands_set::SetField::Configure(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::CommandsSet(crate::commands_set::SetField::Configuration(r)) => Some(r),
        _ => None,
    })
}

fn send_configure_save<T: Transport>(
    device: &mut Device<T>,
    instance: u8,
) -> Result<(), SessionError> {
    let command = crate::commands_set::Configure {
        function: crate::types::Function(3),
        instance,
        ..<crate::commands_set::Configure as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::CommandsSet(crate::commands_set::SetField::Configure(command));
    device.call(&value).map(|_| ())
}

fn send_per_device_per_device_dev_a<T: Transport>(
    device: &mut Device<T>,
    a: u32,
) -> Result<(), SessionError> {
    let command = crate::commands_set::PerDeviceDevA { a };
    let value = FieldValue::CommandsSet(crate::commands_set::SetField::PerDevice(
        crate::commands_set::PerDevice::DevA(command),
    ));
    device.call(&value).map(|_| ())
}

fn send_per_device_per_device_dev_b<T: Transport>(
    device: &mut Device<T>,
    b: u64,
    extra: Option<u8>,
) -> Result<(), SessionError> {
    let command = crate::commands_set::PerDeviceDevB { b, extra };
    let value = FieldValue::CommandsSet(crate::commands_set::SetField::PerDevice(
        crate::commands_set::PerDevice::DevB(command),
    ));
    device.call(&value).map(|_| ())
}
