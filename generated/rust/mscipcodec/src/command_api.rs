//! The typed command API of Memsense MS-CIP (std), generated from `spec/mscip/`: one
//! method per command set on [`Device`], one per command, and one call per function it supports
//! (`write`, `read`, `save`, `load`, `default`, ...) or a plain call, with typed parameters in and
//! the typed reply out. With a device model selected, a command or function the model does not
//! support is refused before sending ([`SessionError::Refused`]; see
//! [`Device::with_check_device`]).
//!
//! ```no_run
//! # fn main() -> Result<(), mscipcodec::device::SessionError> {
//! let mut device = mscipcodec::device::connect("tcp:192.168.1.100:5000", None, 115_200)?;
//! device.base().ping();
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
    /// Commands of set 0x01 (Base Messages).
    pub fn base(&mut self) -> BaseCommands<'_, T> {
        BaseCommands { device: self }
    }
}

/// Commands of set 0x01 (Base Messages), bound to a [`Device`].
#[derive(Debug)]
pub struct BaseCommands<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> BaseCommands<'d, T> {
    /// Ping (0x02). Sends `ping`.
    pub fn ping(self) -> Result<(), SessionError> {
        send_ping_ping(self.device)
    }
    /// Get device messages (0x03). Sends `get_device_messages`: returns the reply field.
    pub fn get_device_messages(self) -> Result<crate::base::DeviceMessages, SessionError> {
        send_get_device_messages_get_device_messages(self.device)
    }
    /// Device reset (0x04). Sends `device_reset`.
    pub fn device_reset(self) -> Result<(), SessionError> {
        send_device_reset_device_reset(self.device)
    }
    /// Get device model (0x05). Sends `get_device_model`: returns the reply field.
    pub fn get_device_model(self) -> Result<crate::base::DeviceModel, SessionError> {
        send_get_device_model_get_device_model(self.device)
    }
    /// Get device serial number (0x06). Sends `get_device_sn`: returns the reply field.
    pub fn get_device_sn(self) -> Result<crate::base::DeviceSn, SessionError> {
        send_get_device_sn_get_device_sn(self.device)
    }
    /// Get device firmware (0x07). Sends `get_device_fw`: returns the reply field.
    pub fn get_device_fw(self) -> Result<crate::base::DeviceFw, SessionError> {
        send_get_device_fw_get_device_fw(self.device)
    }
    /// Get device calibration date (0x08). Sends `get_device_cal`: returns the reply field.
    pub fn get_device_cal(self) -> Result<crate::base::DeviceCal, SessionError> {
        send_get_device_cal_get_device_cal(self.device)
    }
    /// Correlate GPS time (0x09). Sends `correlate_gps_time`.
    pub fn correlate_gps_time(self, week: u16, seconds: u32) -> Result<(), SessionError> {
        send_correlate_gps_time_correlate_gps_time(self.device, week, seconds)
    }
}

fn send_ping_ping<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::base::Ping {};
    let value = FieldValue::Base(crate::base::SetField::Ping(command));
    device.call(&value).map(|_| ())
}

fn send_get_device_messages_get_device_messages<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::base::DeviceMessages, SessionError> {
    let command = crate::base::GetDeviceMessages {};
    let value = FieldValue::Base(crate::base::SetField::GetDeviceMessages(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Base(crate::base::SetField::DeviceMessages(r)) => Some(r),
        _ => None,
    })
}

fn send_device_reset_device_reset<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::base::DeviceReset {};
    let value = FieldValue::Base(crate::base::SetField::DeviceReset(command));
    device.call(&value).map(|_| ())
}

fn send_get_device_model_get_device_model<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::base::DeviceModel, SessionError> {
    let command = crate::base::GetDeviceModel {};
    let value = FieldValue::Base(crate::base::SetField::GetDeviceModel(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Base(crate::base::SetField::DeviceModel(r)) => Some(r),
        _ => None,
    })
}

fn send_get_device_sn_get_device_sn<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::base::DeviceSn, SessionError> {
    let command = crate::base::GetDeviceSn {};
    let value = FieldValue::Base(crate::base::SetField::GetDeviceSn(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Base(crate::base::SetField::DeviceSn(r)) => Some(r),
        _ => None,
    })
}

fn send_get_device_fw_get_device_fw<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::base::DeviceFw, SessionError> {
    let command = crate::base::GetDeviceFw {};
    let value = FieldValue::Base(crate::base::SetField::GetDeviceFw(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Base(crate::base::SetField::DeviceFw(r)) => Some(r),
        _ => None,
    })
}

fn send_get_device_cal_get_device_cal<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::base::DeviceCal, SessionError> {
    let command = crate::base::GetDeviceCal {};
    let value = FieldValue::Base(crate::base::SetField::GetDeviceCal(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Base(crate::base::SetField::DeviceCal(r)) => Some(r),
        _ => None,
    })
}

fn send_correlate_gps_time_correlate_gps_time<T: Transport>(
    device: &mut Device<T>,
    week: u16,
    seconds: u32,
) -> Result<(), SessionError> {
    let command = crate::base::CorrelateGpsTime { week, seconds };
    let value = FieldValue::Base(crate::base::SetField::CorrelateGpsTime(command));
    device.call(&value).map(|_| ())
}

impl<T: Transport> Device<T> {
    /// Commands of set 0x02 (IMU Configuration Messages).
    pub fn imu_config(&mut self) -> ImuConfigCommands<'_, T> {
        ImuConfigCommands { device: self }
    }
}

/// Commands of set 0x02 (IMU Configuration Messages), bound to a [`Device`].
#[derive(Debug)]
pub struct ImuConfigCommands<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> ImuConfigCommands<'d, T> {
    /// UART baud rate configure (0x01).
    pub fn uart_baud_rate(self) -> UartBaudRateCommand<'d, T> {
        UartBaudRateCommand {
            device: self.device,
        }
    }
    /// Configure filter (0x03).
    pub fn filter(self) -> FilterCommand<'d, T> {
        FilterCommand {
            device: self.device,
        }
    }
    /// IMU sample rate configure (0x04).
    pub fn sample_rate(self) -> SampleRateCommand<'d, T> {
        SampleRateCommand {
            device: self.device,
        }
    }
    /// Select sensors (Rev A) (0x05).
    pub fn select_sensors(self) -> SelectSensorsCommand<'d, T> {
        SelectSensorsCommand {
            device: self.device,
        }
    }
    /// Get IMU internal sample rate (0x06). Sends `get_internal_sample_rate`: returns the reply field.
    pub fn get_internal_sample_rate(
        self,
    ) -> Result<crate::imu_config::InternalSampleRate, SessionError> {
        send_get_internal_sample_rate_get_internal_sample_rate(self.device)
    }
    /// Config accel range (0x07).
    pub fn accel_range(self) -> AccelRangeCommand<'d, T> {
        AccelRangeCommand {
            device: self.device,
        }
    }
    /// Configure gyro range (0x08).
    pub fn gyro_range(self) -> GyroRangeCommand<'d, T> {
        GyroRangeCommand {
            device: self.device,
        }
    }
    /// Configure all (0x09).
    pub fn config_all(self) -> ConfigAllCommand<'d, T> {
        ConfigAllCommand {
            device: self.device,
        }
    }
    /// Data on/off (0x0A).
    pub fn data_on_off(self) -> DataOnOffCommand<'d, T> {
        DataOnOffCommand {
            device: self.device,
        }
    }
    /// XTRIG on/off (0x0B).
    pub fn xtrig_on_off(self) -> XtrigOnOffCommand<'d, T> {
        XtrigOnOffCommand {
            device: self.device,
        }
    }
    /// Select sensors (Rev B) (0x0C).
    pub fn select_sensors_rev_b(self) -> SelectSensorsRevBCommand<'d, T> {
        SelectSensorsRevBCommand {
            device: self.device,
        }
    }
    /// Config aux accel range (0x0D).
    pub fn aux_accel_range(self) -> AuxAccelRangeCommand<'d, T> {
        AuxAccelRangeCommand {
            device: self.device,
        }
    }
}

/// UART baud rate configure (0x02, 0x01): one call per function.
#[derive(Debug)]
pub struct UartBaudRateCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> UartBaudRateCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, baud_rate: crate::types::BaudRate) -> Result<(), SessionError> {
        send_uart_baud_rate_write(self.device, baud_rate)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::imu_config::UartBaudRateResponse, SessionError> {
        send_uart_baud_rate_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_uart_baud_rate_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_uart_baud_rate_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_uart_baud_rate_default(self.device)
    }
}

fn send_uart_baud_rate_write<T: Transport>(
    device: &mut Device<T>,
    baud_rate: crate::types::BaudRate,
) -> Result<(), SessionError> {
    let command = crate::imu_config::UartBaudRate {
        function: crate::types::FunctionCode(1),
        baud_rate: Some(baud_rate),
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::UartBaudRate(command));
    device.call(&value).map(|_| ())
}

fn send_uart_baud_rate_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::imu_config::UartBaudRateResponse, SessionError> {
    let command = crate::imu_config::UartBaudRate {
        function: crate::types::FunctionCode(2),
        ..<crate::imu_config::UartBaudRate as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::UartBaudRate(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::ImuConfig(crate::imu_config::SetField::UartBaudRateResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_uart_baud_rate_save<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::imu_config::UartBaudRate {
        function: crate::types::FunctionCode(3),
        ..<crate::imu_config::UartBaudRate as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::UartBaudRate(command));
    device.call(&value).map(|_| ())
}

fn send_uart_baud_rate_load<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::imu_config::UartBaudRate {
        function: crate::types::FunctionCode(4),
        ..<crate::imu_config::UartBaudRate as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::UartBaudRate(command));
    device.call(&value).map(|_| ())
}

fn send_uart_baud_rate_default<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::imu_config::UartBaudRate {
        function: crate::types::FunctionCode(5),
        ..<crate::imu_config::UartBaudRate as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::UartBaudRate(command));
    device.call(&value).map(|_| ())
}

/// Configure filter (0x02, 0x03): one call per function.
#[derive(Debug)]
pub struct FilterCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> FilterCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, bandwidth: crate::types::FilterBandwidth) -> Result<(), SessionError> {
        send_filter_write(self.device, bandwidth)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::imu_config::FilterResponse, SessionError> {
        send_filter_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_filter_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_filter_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_filter_default(self.device)
    }
}

fn send_filter_write<T: Transport>(
    device: &mut Device<T>,
    bandwidth: crate::types::FilterBandwidth,
) -> Result<(), SessionError> {
    let command = crate::imu_config::Filter {
        function: crate::types::FunctionCode(1),
        bandwidth: Some(bandwidth),
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::Filter(command));
    device.call(&value).map(|_| ())
}

fn send_filter_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::imu_config::FilterResponse, SessionError> {
    let command = crate::imu_config::Filter {
        function: crate::types::FunctionCode(2),
        ..<crate::imu_config::Filter as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::Filter(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::ImuConfig(crate::imu_config::SetField::FilterResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_filter_save<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::imu_config::Filter {
        function: crate::types::FunctionCode(3),
        ..<crate::imu_config::Filter as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::Filter(command));
    device.call(&value).map(|_| ())
}

fn send_filter_load<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::imu_config::Filter {
        function: crate::types::FunctionCode(4),
        ..<crate::imu_config::Filter as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::Filter(command));
    device.call(&value).map(|_| ())
}

fn send_filter_default<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::imu_config::Filter {
        function: crate::types::FunctionCode(5),
        ..<crate::imu_config::Filter as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::Filter(command));
    device.call(&value).map(|_| ())
}

/// IMU sample rate configure (0x02, 0x04): one call per function.
#[derive(Debug)]
pub struct SampleRateCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> SampleRateCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, decimation: u16) -> Result<(), SessionError> {
        send_sample_rate_write(self.device, decimation)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::imu_config::SampleRateResponse, SessionError> {
        send_sample_rate_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_sample_rate_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_sample_rate_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_sample_rate_default(self.device)
    }
}

fn send_sample_rate_write<T: Transport>(
    device: &mut Device<T>,
    decimation: u16,
) -> Result<(), SessionError> {
    let command = crate::imu_config::SampleRate {
        function: crate::types::FunctionCode(1),
        decimation: Some(decimation),
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::SampleRate(command));
    device.call(&value).map(|_| ())
}

fn send_sample_rate_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::imu_config::SampleRateResponse, SessionError> {
    let command = crate::imu_config::SampleRate {
        function: crate::types::FunctionCode(2),
        ..<crate::imu_config::SampleRate as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::SampleRate(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::ImuConfig(crate::imu_config::SetField::SampleRateResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_sample_rate_save<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::imu_config::SampleRate {
        function: crate::types::FunctionCode(3),
        ..<crate::imu_config::SampleRate as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::SampleRate(command));
    device.call(&value).map(|_| ())
}

fn send_sample_rate_load<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::imu_config::SampleRate {
        function: crate::types::FunctionCode(4),
        ..<crate::imu_config::SampleRate as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::SampleRate(command));
    device.call(&value).map(|_| ())
}

fn send_sample_rate_default<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::imu_config::SampleRate {
        function: crate::types::FunctionCode(5),
        ..<crate::imu_config::SampleRate as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::SampleRate(command));
    device.call(&value).map(|_| ())
}

/// Select sensors (Rev A) (0x02, 0x05): one call per function.
#[derive(Debug)]
pub struct SelectSensorsCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> SelectSensorsCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        reserved: u8,
        sensors: crate::bounded::BoundedVec<crate::types::SensorCode, 251>,
    ) -> Result<(), SessionError> {
        send_select_sensors_write(self.device, reserved, sensors)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::imu_config::SelectSensorsResponse, SessionError> {
        send_select_sensors_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_select_sensors_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_select_sensors_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_select_sensors_default(self.device)
    }
}

fn send_select_sensors_write<T: Transport>(
    device: &mut Device<T>,
    reserved: u8,
    sensors: crate::bounded::BoundedVec<crate::types::SensorCode, 251>,
) -> Result<(), SessionError> {
    let command = crate::imu_config::SelectSensors {
        function: crate::types::FunctionCode(1),
        reserved: Some(reserved),
        sensors: Some(sensors),
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::SelectSensors(command));
    device.call(&value).map(|_| ())
}

fn send_select_sensors_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::imu_config::SelectSensorsResponse, SessionError> {
    let command = crate::imu_config::SelectSensors {
        function: crate::types::FunctionCode(2),
        ..<crate::imu_config::SelectSensors as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::SelectSensors(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::ImuConfig(crate::imu_config::SetField::SelectSensorsResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_select_sensors_save<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::imu_config::SelectSensors {
        function: crate::types::FunctionCode(3),
        ..<crate::imu_config::SelectSensors as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::SelectSensors(command));
    device.call(&value).map(|_| ())
}

fn send_select_sensors_load<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::imu_config::SelectSensors {
        function: crate::types::FunctionCode(4),
        ..<crate::imu_config::SelectSensors as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::SelectSensors(command));
    device.call(&value).map(|_| ())
}

fn send_select_sensors_default<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::imu_config::SelectSensors {
        function: crate::types::FunctionCode(5),
        ..<crate::imu_config::SelectSensors as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::SelectSensors(command));
    device.call(&value).map(|_| ())
}

fn send_get_internal_sample_rate_get_internal_sample_rate<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::imu_config::InternalSampleRate, SessionError> {
    let command = crate::imu_config::GetInternalSampleRate {};
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::GetInternalSampleRate(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::ImuConfig(crate::imu_config::SetField::InternalSampleRate(r)) => Some(r),
        _ => None,
    })
}

/// Config accel range (0x02, 0x07): one call per function.
#[derive(Debug)]
pub struct AccelRangeCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> AccelRangeCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, range: crate::types::AccelRange) -> Result<(), SessionError> {
        send_accel_range_write(self.device, range)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::imu_config::AccelRangeResponse, SessionError> {
        send_accel_range_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_accel_range_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_accel_range_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_accel_range_default(self.device)
    }
}

fn send_accel_range_write<T: Transport>(
    device: &mut Device<T>,
    range: crate::types::AccelRange,
) -> Result<(), SessionError> {
    let command = crate::imu_config::AccelRange {
        function: crate::types::FunctionCode(1),
        range: Some(range),
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::AccelRange(command));
    device.call(&value).map(|_| ())
}

fn send_accel_range_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::imu_config::AccelRangeResponse, SessionError> {
    let command = crate::imu_config::AccelRange {
        function: crate::types::FunctionCode(2),
        ..<crate::imu_config::AccelRange as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::AccelRange(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::ImuConfig(crate::imu_config::SetField::AccelRangeResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_accel_range_save<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::imu_config::AccelRange {
        function: crate::types::FunctionCode(3),
        ..<crate::imu_config::AccelRange as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::AccelRange(command));
    device.call(&value).map(|_| ())
}

fn send_accel_range_load<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::imu_config::AccelRange {
        function: crate::types::FunctionCode(4),
        ..<crate::imu_config::AccelRange as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::AccelRange(command));
    device.call(&value).map(|_| ())
}

fn send_accel_range_default<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::imu_config::AccelRange {
        function: crate::types::FunctionCode(5),
        ..<crate::imu_config::AccelRange as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::AccelRange(command));
    device.call(&value).map(|_| ())
}

/// Configure gyro range (0x02, 0x08): one call per function.
#[derive(Debug)]
pub struct GyroRangeCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> GyroRangeCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, range: crate::types::GyroRange) -> Result<(), SessionError> {
        send_gyro_range_write(self.device, range)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::imu_config::GyroRangeResponse, SessionError> {
        send_gyro_range_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_gyro_range_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_gyro_range_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_gyro_range_default(self.device)
    }
}

fn send_gyro_range_write<T: Transport>(
    device: &mut Device<T>,
    range: crate::types::GyroRange,
) -> Result<(), SessionError> {
    let command = crate::imu_config::GyroRange {
        function: crate::types::FunctionCode(1),
        range: Some(range),
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::GyroRange(command));
    device.call(&value).map(|_| ())
}

fn send_gyro_range_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::imu_config::GyroRangeResponse, SessionError> {
    let command = crate::imu_config::GyroRange {
        function: crate::types::FunctionCode(2),
        ..<crate::imu_config::GyroRange as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::GyroRange(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::ImuConfig(crate::imu_config::SetField::GyroRangeResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_gyro_range_save<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::imu_config::GyroRange {
        function: crate::types::FunctionCode(3),
        ..<crate::imu_config::GyroRange as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::GyroRange(command));
    device.call(&value).map(|_| ())
}

fn send_gyro_range_load<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::imu_config::GyroRange {
        function: crate::types::FunctionCode(4),
        ..<crate::imu_config::GyroRange as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::GyroRange(command));
    device.call(&value).map(|_| ())
}

fn send_gyro_range_default<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::imu_config::GyroRange {
        function: crate::types::FunctionCode(5),
        ..<crate::imu_config::GyroRange as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::GyroRange(command));
    device.call(&value).map(|_| ())
}

/// Configure all (0x02, 0x09): one call per function.
#[derive(Debug)]
pub struct ConfigAllCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> ConfigAllCommand<'d, T> {
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_config_all_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_config_all_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_config_all_default(self.device)
    }
}

fn send_config_all_save<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::imu_config::ConfigAll {
        function: crate::types::FunctionCode(3),
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::ConfigAll(command));
    device.call(&value).map(|_| ())
}

fn send_config_all_load<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::imu_config::ConfigAll {
        function: crate::types::FunctionCode(4),
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::ConfigAll(command));
    device.call(&value).map(|_| ())
}

fn send_config_all_default<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::imu_config::ConfigAll {
        function: crate::types::FunctionCode(5),
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::ConfigAll(command));
    device.call(&value).map(|_| ())
}

/// Data on/off (0x02, 0x0A): one call per function.
#[derive(Debug)]
pub struct DataOnOffCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> DataOnOffCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, control: crate::types::OnOff) -> Result<(), SessionError> {
        send_data_on_off_write(self.device, control)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::imu_config::DataOnOffResponse, SessionError> {
        send_data_on_off_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_data_on_off_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_data_on_off_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_data_on_off_default(self.device)
    }
}

fn send_data_on_off_write<T: Transport>(
    device: &mut Device<T>,
    control: crate::types::OnOff,
) -> Result<(), SessionError> {
    let command = crate::imu_config::DataOnOff {
        function: crate::types::FunctionCode(1),
        control: Some(control),
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::DataOnOff(command));
    device.call(&value).map(|_| ())
}

fn send_data_on_off_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::imu_config::DataOnOffResponse, SessionError> {
    let command = crate::imu_config::DataOnOff {
        function: crate::types::FunctionCode(2),
        ..<crate::imu_config::DataOnOff as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::DataOnOff(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::ImuConfig(crate::imu_config::SetField::DataOnOffResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_data_on_off_save<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::imu_config::DataOnOff {
        function: crate::types::FunctionCode(3),
        ..<crate::imu_config::DataOnOff as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::DataOnOff(command));
    device.call(&value).map(|_| ())
}

fn send_data_on_off_load<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::imu_config::DataOnOff {
        function: crate::types::FunctionCode(4),
        ..<crate::imu_config::DataOnOff as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::DataOnOff(command));
    device.call(&value).map(|_| ())
}

fn send_data_on_off_default<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::imu_config::DataOnOff {
        function: crate::types::FunctionCode(5),
        ..<crate::imu_config::DataOnOff as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::DataOnOff(command));
    device.call(&value).map(|_| ())
}

/// XTRIG on/off (0x02, 0x0B): one call per function.
#[derive(Debug)]
pub struct XtrigOnOffCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> XtrigOnOffCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, control: crate::types::OnOff) -> Result<(), SessionError> {
        send_xtrig_on_off_write(self.device, control)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::imu_config::XtrigOnOffResponse, SessionError> {
        send_xtrig_on_off_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_xtrig_on_off_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_xtrig_on_off_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_xtrig_on_off_default(self.device)
    }
}

fn send_xtrig_on_off_write<T: Transport>(
    device: &mut Device<T>,
    control: crate::types::OnOff,
) -> Result<(), SessionError> {
    let command = crate::imu_config::XtrigOnOff {
        function: crate::types::FunctionCode(1),
        control: Some(control),
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::XtrigOnOff(command));
    device.call(&value).map(|_| ())
}

fn send_xtrig_on_off_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::imu_config::XtrigOnOffResponse, SessionError> {
    let command = crate::imu_config::XtrigOnOff {
        function: crate::types::FunctionCode(2),
        ..<crate::imu_config::XtrigOnOff as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::XtrigOnOff(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::ImuConfig(crate::imu_config::SetField::XtrigOnOffResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_xtrig_on_off_save<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::imu_config::XtrigOnOff {
        function: crate::types::FunctionCode(3),
        ..<crate::imu_config::XtrigOnOff as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::XtrigOnOff(command));
    device.call(&value).map(|_| ())
}

fn send_xtrig_on_off_load<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::imu_config::XtrigOnOff {
        function: crate::types::FunctionCode(4),
        ..<crate::imu_config::XtrigOnOff as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::XtrigOnOff(command));
    device.call(&value).map(|_| ())
}

fn send_xtrig_on_off_default<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::imu_config::XtrigOnOff {
        function: crate::types::FunctionCode(5),
        ..<crate::imu_config::XtrigOnOff as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::XtrigOnOff(command));
    device.call(&value).map(|_| ())
}

/// Select sensors (Rev B) (0x02, 0x0C): one call per function.
#[derive(Debug)]
pub struct SelectSensorsRevBCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> SelectSensorsRevBCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        sensors: crate::bounded::BoundedVec<crate::types::SensorCode, 252>,
    ) -> Result<(), SessionError> {
        send_select_sensors_rev_b_write(self.device, sensors)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::imu_config::SelectSensorsRevBResponse, SessionError> {
        send_select_sensors_rev_b_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_select_sensors_rev_b_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_select_sensors_rev_b_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_select_sensors_rev_b_default(self.device)
    }
}

fn send_select_sensors_rev_b_write<T: Transport>(
    device: &mut Device<T>,
    sensors: crate::bounded::BoundedVec<crate::types::SensorCode, 252>,
) -> Result<(), SessionError> {
    let command = crate::imu_config::SelectSensorsRevB {
        function: crate::types::FunctionCode(1),
        sensors: Some(sensors),
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::SelectSensorsRevB(command));
    device.call(&value).map(|_| ())
}

fn send_select_sensors_rev_b_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::imu_config::SelectSensorsRevBResponse, SessionError> {
    let command = crate::imu_config::SelectSensorsRevB {
        function: crate::types::FunctionCode(2),
        ..<crate::imu_config::SelectSensorsRevB as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::SelectSensorsRevB(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::ImuConfig(crate::imu_config::SetField::SelectSensorsRevBResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_select_sensors_rev_b_save<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::imu_config::SelectSensorsRevB {
        function: crate::types::FunctionCode(3),
        ..<crate::imu_config::SelectSensorsRevB as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::SelectSensorsRevB(command));
    device.call(&value).map(|_| ())
}

fn send_select_sensors_rev_b_load<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::imu_config::SelectSensorsRevB {
        function: crate::types::FunctionCode(4),
        ..<crate::imu_config::SelectSensorsRevB as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::SelectSensorsRevB(command));
    device.call(&value).map(|_| ())
}

fn send_select_sensors_rev_b_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::imu_config::SelectSensorsRevB {
        function: crate::types::FunctionCode(5),
        ..<crate::imu_config::SelectSensorsRevB as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::SelectSensorsRevB(command));
    device.call(&value).map(|_| ())
}

/// Config aux accel range (0x02, 0x0D): one call per function.
#[derive(Debug)]
pub struct AuxAccelRangeCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> AuxAccelRangeCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, range: crate::types::AccelRange) -> Result<(), SessionError> {
        send_aux_accel_range_write(self.device, range)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::imu_config::AuxAccelRangeResponse, SessionError> {
        send_aux_accel_range_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_aux_accel_range_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_aux_accel_range_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_aux_accel_range_default(self.device)
    }
}

fn send_aux_accel_range_write<T: Transport>(
    device: &mut Device<T>,
    range: crate::types::AccelRange,
) -> Result<(), SessionError> {
    let command = crate::imu_config::AuxAccelRange {
        function: crate::types::FunctionCode(1),
        range: Some(range),
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::AuxAccelRange(command));
    device.call(&value).map(|_| ())
}

fn send_aux_accel_range_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::imu_config::AuxAccelRangeResponse, SessionError> {
    let command = crate::imu_config::AuxAccelRange {
        function: crate::types::FunctionCode(2),
        ..<crate::imu_config::AuxAccelRange as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::AuxAccelRange(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::ImuConfig(crate::imu_config::SetField::AuxAccelRangeResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_aux_accel_range_save<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::imu_config::AuxAccelRange {
        function: crate::types::FunctionCode(3),
        ..<crate::imu_config::AuxAccelRange as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::AuxAccelRange(command));
    device.call(&value).map(|_| ())
}

fn send_aux_accel_range_load<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::imu_config::AuxAccelRange {
        function: crate::types::FunctionCode(4),
        ..<crate::imu_config::AuxAccelRange as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::AuxAccelRange(command));
    device.call(&value).map(|_| ())
}

fn send_aux_accel_range_default<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::imu_config::AuxAccelRange {
        function: crate::types::FunctionCode(5),
        ..<crate::imu_config::AuxAccelRange as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::ImuConfig(crate::imu_config::SetField::AuxAccelRange(command));
    device.call(&value).map(|_| ())
}
