//! The typed command API of MicroStrain MIP (std), generated from `spec/mip/`: one
//! method per command set on [`Device`], one per command, and one call per function it supports
//! (`write`, `read`, `save`, `load`, `default`, ...) or a plain call, with typed parameters in and
//! the typed reply out. With a device model selected, a command or function the model does not
//! support is refused before sending ([`SessionError::Refused`]; see
//! [`Device::with_check_device`]).
//!
//! ```no_run
//! # fn main() -> Result<(), mipcodec::device::SessionError> {
//! let mut device = mipcodec::device::connect("tcp:192.168.1.100:5000", None, 115_200)?;
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
    /// Commands of set 0x01 (Base Command Set).
    pub fn base(&mut self) -> BaseCommands<'_, T> {
        BaseCommands { device: self }
    }
}

/// Commands of set 0x01 (Base Command Set), bound to a [`Device`].
#[derive(Debug)]
pub struct BaseCommands<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> BaseCommands<'d, T> {
    /// Ping (0x01). Sends `ping`.
    pub fn ping(self) -> Result<(), SessionError> {
        send_ping_ping(self.device)
    }
    /// Set to idle (0x02). Sends `set_to_idle`.
    pub fn set_to_idle(self) -> Result<(), SessionError> {
        send_set_to_idle_set_to_idle(self.device)
    }
    /// Get device information (0x03). Sends `get_device_info`: returns the reply field.
    pub fn get_device_info(self) -> Result<crate::base::DeviceInfo, SessionError> {
        send_get_device_info_get_device_info(self.device)
    }
    /// Get device descriptor sets (0x04). Sends `get_device_descriptors`: returns the reply field.
    pub fn get_device_descriptors(self) -> Result<crate::base::DeviceDescriptors, SessionError> {
        send_get_device_descriptors_get_device_descriptors(self.device)
    }
    /// Built-in test (0x05). Sends `built_in_test`: returns the reply field.
    pub fn built_in_test(self) -> Result<crate::base::BuiltInTestResult, SessionError> {
        send_built_in_test_built_in_test(self.device)
    }
    /// Resume (0x06). Sends `resume`.
    pub fn resume(self) -> Result<(), SessionError> {
        send_resume_resume(self.device)
    }
    /// Get extended device descriptor sets (0x07). Sends `get_extended_descriptors`: returns the reply field.
    pub fn get_extended_descriptors(
        self,
    ) -> Result<crate::base::ExtendedDescriptors, SessionError> {
        send_get_extended_descriptors_get_extended_descriptors(self.device)
    }
    /// Continuous built-in test (0x08). Sends `continuous_bit`: returns the reply field.
    pub fn continuous_bit(self) -> Result<crate::base::ContinuousBitResult, SessionError> {
        send_continuous_bit_continuous_bit(self.device)
    }
    /// Comm port speed (0x09).
    pub fn comm_port_speed(self) -> CommPortSpeedCommand<'d, T> {
        CommPortSpeedCommand {
            device: self.device,
        }
    }
    /// GPS time update (0x72).
    pub fn gps_time_update(self) -> GpsTimeUpdateCommand<'d, T> {
        GpsTimeUpdateCommand {
            device: self.device,
        }
    }
    /// Device reset (0x7E). Sends `device_reset`.
    pub fn device_reset(self) -> Result<(), SessionError> {
        send_device_reset_device_reset(self.device)
    }
}

fn send_ping_ping<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::base::Ping {};
    let value = FieldValue::Base(crate::base::SetField::Ping(command));
    device.call(&value).map(|_| ())
}

fn send_set_to_idle_set_to_idle<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::base::SetToIdle {};
    let value = FieldValue::Base(crate::base::SetField::SetToIdle(command));
    device.call(&value).map(|_| ())
}

fn send_get_device_info_get_device_info<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::base::DeviceInfo, SessionError> {
    let command = crate::base::GetDeviceInfo {};
    let value = FieldValue::Base(crate::base::SetField::GetDeviceInfo(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Base(crate::base::SetField::DeviceInfo(r)) => Some(r),
        _ => None,
    })
}

fn send_get_device_descriptors_get_device_descriptors<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::base::DeviceDescriptors, SessionError> {
    let command = crate::base::GetDeviceDescriptors {};
    let value = FieldValue::Base(crate::base::SetField::GetDeviceDescriptors(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Base(crate::base::SetField::DeviceDescriptors(r)) => Some(r),
        _ => None,
    })
}

fn send_built_in_test_built_in_test<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::base::BuiltInTestResult, SessionError> {
    let command = crate::base::BuiltInTest {};
    let value = FieldValue::Base(crate::base::SetField::BuiltInTest(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Base(crate::base::SetField::BuiltInTestResult(r)) => Some(r),
        _ => None,
    })
}

fn send_resume_resume<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::base::Resume {};
    let value = FieldValue::Base(crate::base::SetField::Resume(command));
    device.call(&value).map(|_| ())
}

fn send_get_extended_descriptors_get_extended_descriptors<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::base::ExtendedDescriptors, SessionError> {
    let command = crate::base::GetExtendedDescriptors {};
    let value = FieldValue::Base(crate::base::SetField::GetExtendedDescriptors(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Base(crate::base::SetField::ExtendedDescriptors(r)) => Some(r),
        _ => None,
    })
}

fn send_continuous_bit_continuous_bit<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::base::ContinuousBitResult, SessionError> {
    let command = crate::base::ContinuousBit {};
    let value = FieldValue::Base(crate::base::SetField::ContinuousBit(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Base(crate::base::SetField::ContinuousBitResult(r)) => Some(r),
        _ => None,
    })
}

/// Comm port speed (0x01, 0x09): one call per function.
#[derive(Debug)]
pub struct CommPortSpeedCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> CommPortSpeedCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, port: u8, baud: u32) -> Result<(), SessionError> {
        send_comm_port_speed_write(self.device, port, baud)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self, port: u8) -> Result<crate::base::CommPortSpeedResponse, SessionError> {
        send_comm_port_speed_read(self.device, port)
    }
    /// Function `save`.
    pub fn save(self, port: u8) -> Result<(), SessionError> {
        send_comm_port_speed_save(self.device, port)
    }
    /// Function `load`.
    pub fn load(self, port: u8) -> Result<(), SessionError> {
        send_comm_port_speed_load(self.device, port)
    }
    /// Function `default`.
    pub fn default(self, port: u8) -> Result<(), SessionError> {
        send_comm_port_speed_default(self.device, port)
    }
}

fn send_comm_port_speed_write<T: Transport>(
    device: &mut Device<T>,
    port: u8,
    baud: u32,
) -> Result<(), SessionError> {
    let command = crate::base::CommPortSpeed {
        function: crate::types::FunctionSelector(1),
        port,
        baud: Some(baud),
    };
    let value = FieldValue::Base(crate::base::SetField::CommPortSpeed(command));
    device.call(&value).map(|_| ())
}

fn send_comm_port_speed_read<T: Transport>(
    device: &mut Device<T>,
    port: u8,
) -> Result<crate::base::CommPortSpeedResponse, SessionError> {
    let command = crate::base::CommPortSpeed {
        function: crate::types::FunctionSelector(2),
        port,
        ..<crate::base::CommPortSpeed as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Base(crate::base::SetField::CommPortSpeed(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Base(crate::base::SetField::CommPortSpeedResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_comm_port_speed_save<T: Transport>(
    device: &mut Device<T>,
    port: u8,
) -> Result<(), SessionError> {
    let command = crate::base::CommPortSpeed {
        function: crate::types::FunctionSelector(3),
        port,
        ..<crate::base::CommPortSpeed as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Base(crate::base::SetField::CommPortSpeed(command));
    device.call(&value).map(|_| ())
}

fn send_comm_port_speed_load<T: Transport>(
    device: &mut Device<T>,
    port: u8,
) -> Result<(), SessionError> {
    let command = crate::base::CommPortSpeed {
        function: crate::types::FunctionSelector(4),
        port,
        ..<crate::base::CommPortSpeed as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Base(crate::base::SetField::CommPortSpeed(command));
    device.call(&value).map(|_| ())
}

fn send_comm_port_speed_default<T: Transport>(
    device: &mut Device<T>,
    port: u8,
) -> Result<(), SessionError> {
    let command = crate::base::CommPortSpeed {
        function: crate::types::FunctionSelector(5),
        port,
        ..<crate::base::CommPortSpeed as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Base(crate::base::SetField::CommPortSpeed(command));
    device.call(&value).map(|_| ())
}

/// GPS time update (0x01, 0x72): one call per function.
#[derive(Debug)]
pub struct GpsTimeUpdateCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> GpsTimeUpdateCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        field_id: crate::types::GpsTimeField,
        value: u32,
    ) -> Result<(), SessionError> {
        send_gps_time_update_write(self.device, field_id, value)
    }
    /// Function `read`: returns the reply field.
    pub fn read(
        self,
        field_id: crate::types::GpsTimeField,
    ) -> Result<Option<FieldValue>, SessionError> {
        send_gps_time_update_read(self.device, field_id)
    }
    /// Function `write_no_ack`.
    pub fn write_no_ack(
        self,
        field_id: crate::types::GpsTimeField,
        value: u32,
    ) -> Result<(), SessionError> {
        send_gps_time_update_write_no_ack(self.device, field_id, value)
    }
}

fn send_gps_time_update_write<T: Transport>(
    device: &mut Device<T>,
    field_id: crate::types::GpsTimeField,
    value: u32,
) -> Result<(), SessionError> {
    let value = match device.model() {
        Some(Model::Cv7Ins) => {
            let command = crate::base::GpsTimeUpdateCv7Ins {
                function: crate::types::FunctionSelector(1),
                field_id,
                value,
            };
            FieldValue::Base(crate::base::SetField::GpsTimeUpdate(
                crate::base::GpsTimeUpdate::Cv7Ins(command),
            ))
        }
        _ => {
            let command = crate::base::GpsTimeUpdateGx5_45 {
                function: crate::types::FunctionSelector(1),
                field_id,
                value: Some(value),
            };
            FieldValue::Base(crate::base::SetField::GpsTimeUpdate(
                crate::base::GpsTimeUpdate::Gx5_45(command),
            ))
        }
    };
    device.call(&value).map(|_| ())
}

fn send_gps_time_update_read<T: Transport>(
    device: &mut Device<T>,
    field_id: crate::types::GpsTimeField,
) -> Result<Option<FieldValue>, SessionError> {
    let command = crate::base::GpsTimeUpdateGx5_45 {
        function: crate::types::FunctionSelector(2),
        field_id,
        ..<crate::base::GpsTimeUpdateGx5_45 as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Base(crate::base::SetField::GpsTimeUpdate(
        crate::base::GpsTimeUpdate::Gx5_45(command),
    ));
    Ok(device.call(&value)?.response())
}

fn send_gps_time_update_write_no_ack<T: Transport>(
    device: &mut Device<T>,
    field_id: crate::types::GpsTimeField,
    value: u32,
) -> Result<(), SessionError> {
    let command = crate::base::GpsTimeUpdateGx5_45 {
        function: crate::types::FunctionSelector(6),
        field_id,
        value: Some(value),
    };
    let value = FieldValue::Base(crate::base::SetField::GpsTimeUpdate(
        crate::base::GpsTimeUpdate::Gx5_45(command),
    ));
    device.call(&value).map(|_| ())
}

fn send_device_reset_device_reset<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::base::DeviceReset {};
    let value = FieldValue::Base(crate::base::SetField::DeviceReset(command));
    device.call(&value).map(|_| ())
}

impl<T: Transport> Device<T> {
    /// Commands of set 0x0C (3DM Command Set).
    pub fn threedm(&mut self) -> ThreedmCommands<'_, T> {
        ThreedmCommands { device: self }
    }
}

/// Commands of set 0x0C (3DM Command Set), bound to a [`Device`].
#[derive(Debug)]
pub struct ThreedmCommands<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> ThreedmCommands<'d, T> {
    /// Event control (0x2B).
    pub fn event_control(self) -> EventControlCommand<'d, T> {
        EventControlCommand {
            device: self.device,
        }
    }
    /// Get event trigger status (0x2C). Sends `get_event_trigger_status`: returns the reply field.
    pub fn get_event_trigger_status(
        self,
        requested_instances: crate::bounded::BoundedVec<u8, 252>,
    ) -> Result<crate::threedm::EventTriggerStatus, SessionError> {
        send_get_event_trigger_status_get_event_trigger_status(self.device, requested_instances)
    }
    /// Get event action status (0x2D). Sends `get_event_action_status`: returns the reply field.
    pub fn get_event_action_status(
        self,
        requested_instances: crate::bounded::BoundedVec<u8, 252>,
    ) -> Result<crate::threedm::EventActionStatus, SessionError> {
        send_get_event_action_status_get_event_action_status(self.device, requested_instances)
    }
    /// Event trigger configuration (0x2E).
    pub fn event_trigger_config(self) -> EventTriggerConfigCommand<'d, T> {
        EventTriggerConfigCommand {
            device: self.device,
        }
    }
    /// Event action configuration (0x2F).
    pub fn event_action_config(self) -> EventActionConfigCommand<'d, T> {
        EventActionConfigCommand {
            device: self.device,
        }
    }
    /// Device startup settings (0x30).
    pub fn device_startup_settings(self) -> DeviceStartupSettingsCommand<'d, T> {
        DeviceStartupSettingsCommand {
            device: self.device,
        }
    }
    /// Sensor-to-vehicle frame transformation (Euler) (0x31).
    pub fn sensor_to_vehicle_euler(self) -> SensorToVehicleEulerCommand<'d, T> {
        SensorToVehicleEulerCommand {
            device: self.device,
        }
    }
    /// Sensor-to-vehicle frame transformation (quaternion) (0x32).
    pub fn sensor_to_vehicle_quaternion(self) -> SensorToVehicleQuaternionCommand<'d, T> {
        SensorToVehicleQuaternionCommand {
            device: self.device,
        }
    }
    /// Sensor-to-vehicle frame transformation (direction cosine matrix) (0x33).
    pub fn sensor_to_vehicle_dcm(self) -> SensorToVehicleDcmCommand<'d, T> {
        SensorToVehicleDcmCommand {
            device: self.device,
        }
    }
    /// Accelerometer bias (0x37).
    pub fn accel_bias(self) -> AccelBiasCommand<'d, T> {
        AccelBiasCommand {
            device: self.device,
        }
    }
    /// Gyro bias (0x38).
    pub fn gyro_bias(self) -> GyroBiasCommand<'d, T> {
        GyroBiasCommand {
            device: self.device,
        }
    }
    /// Capture gyro bias (0x39). Sends `capture_gyro_bias`: returns the reply field.
    pub fn capture_gyro_bias(
        self,
        averaging_time_ms: u16,
    ) -> Result<crate::threedm::GyroBiasResponse, SessionError> {
        send_capture_gyro_bias_capture_gyro_bias(self.device, averaging_time_ms)
    }
    /// Magnetometer hard iron offset (0x3A).
    pub fn mag_hard_iron_offset(self) -> MagHardIronOffsetCommand<'d, T> {
        MagHardIronOffsetCommand {
            device: self.device,
        }
    }
    /// Magnetometer soft iron matrix (0x3B).
    pub fn mag_soft_iron_matrix(self) -> MagSoftIronMatrixCommand<'d, T> {
        MagSoftIronMatrixCommand {
            device: self.device,
        }
    }
    /// Coning and sculling enable (0x3E).
    pub fn coning_sculling_enable(self) -> ConingScullingEnableCommand<'d, T> {
        ConingScullingEnableCommand {
            device: self.device,
        }
    }
    /// UART baud rate (0x40).
    pub fn uart_baudrate(self) -> UartBaudrateCommand<'d, T> {
        UartBaudrateCommand {
            device: self.device,
        }
    }
    /// GPIO configuration (0x41).
    pub fn gpio_config(self) -> GpioConfigCommand<'d, T> {
        GpioConfigCommand {
            device: self.device,
        }
    }
    /// GPIO state (0x42).
    pub fn gpio_state(self) -> GpioStateCommand<'d, T> {
        GpioStateCommand {
            device: self.device,
        }
    }
    /// Odometer configuration (0x43).
    pub fn odometer_config(self) -> OdometerConfigCommand<'d, T> {
        OdometerConfigCommand {
            device: self.device,
        }
    }
    /// Advanced low-pass filter settings (0x50).
    pub fn advanced_lowpass_filter(self) -> AdvancedLowpassFilterCommand<'d, T> {
        AdvancedLowpassFilterCommand {
            device: self.device,
        }
    }
    /// Complementary filter settings (0x51).
    pub fn complementary_filter(self) -> ComplementaryFilterCommand<'d, T> {
        ComplementaryFilterCommand {
            device: self.device,
        }
    }
    /// Sensor range (0x52).
    pub fn sensor_range(self) -> SensorRangeCommand<'d, T> {
        SensorRangeCommand {
            device: self.device,
        }
    }
    /// Get calibrated sensor ranges (0x53). Sends `get_calibrated_sensor_ranges`: returns the reply field.
    pub fn get_calibrated_sensor_ranges(
        self,
        sensor: crate::types::SensorRangeType,
    ) -> Result<crate::threedm::CalibratedSensorRanges, SessionError> {
        send_get_calibrated_sensor_ranges_get_calibrated_sensor_ranges(self.device, sensor)
    }
    /// Low-pass anti-aliasing filter (0x54).
    pub fn lowpass_filter(self) -> LowpassFilterCommand<'d, T> {
        LowpassFilterCommand {
            device: self.device,
        }
    }
    /// Poll IMU data (0x01). Sends `poll_imu_data`.
    pub fn poll_imu_data(
        self,
        option: crate::types::Gx5PollOption,
        descriptors: crate::bounded::BoundedVec<crate::types::Gx5PollDescriptor, 83>,
    ) -> Result<(), SessionError> {
        send_poll_imu_data_poll_imu_data(self.device, option, descriptors)
    }
    /// Poll GNSS data (0x02). Sends `poll_gnss_data`.
    pub fn poll_gnss_data(
        self,
        option: crate::types::Gx5PollOption,
        descriptors: crate::bounded::BoundedVec<crate::types::Gx5PollDescriptor, 83>,
    ) -> Result<(), SessionError> {
        send_poll_gnss_data_poll_gnss_data(self.device, option, descriptors)
    }
    /// Poll estimation filter data (0x03). Sends `poll_filter_data`.
    pub fn poll_filter_data(
        self,
        option: crate::types::Gx5PollOption,
        descriptors: crate::bounded::BoundedVec<crate::types::Gx5PollDescriptor, 83>,
    ) -> Result<(), SessionError> {
        send_poll_filter_data_poll_filter_data(self.device, option, descriptors)
    }
    /// Poll NMEA data (0x04). Sends `poll_nmea_data`.
    pub fn poll_nmea_data(
        self,
        suppress_ack: bool,
        format_entries: crate::bounded::BoundedVec<crate::types::NmeaMessage, 50>,
    ) -> Result<(), SessionError> {
        send_poll_nmea_data_poll_nmea_data(self.device, suppress_ack, format_entries)
    }
    /// Poll data (0x0D). Sends `poll_data`.
    pub fn poll_data(
        self,
        desc_set: u8,
        suppress_ack: bool,
        descriptors: crate::bounded::BoundedVec<u8, 250>,
    ) -> Result<(), SessionError> {
        send_poll_data_poll_data(self.device, desc_set, suppress_ack, descriptors)
    }
    /// Get IMU data base rate (0x06). Sends `get_imu_base_rate`: returns the reply field.
    pub fn get_imu_base_rate(self) -> Result<crate::threedm::ImuBaseRate, SessionError> {
        send_get_imu_base_rate_get_imu_base_rate(self.device)
    }
    /// Get GNSS data base rate (0x07). Sends `get_gnss_base_rate`: returns the reply field.
    pub fn get_gnss_base_rate(self) -> Result<crate::threedm::GnssBaseRate, SessionError> {
        send_get_gnss_base_rate_get_gnss_base_rate(self.device)
    }
    /// Get estimation filter data base rate (0x0B). Sends `get_filter_base_rate`: returns the reply field.
    pub fn get_filter_base_rate(self) -> Result<crate::threedm::FilterBaseRate, SessionError> {
        send_get_filter_base_rate_get_filter_base_rate(self.device)
    }
    /// Get data base rate (0x0E). Sends `get_base_rate`: returns the reply field.
    pub fn get_base_rate(self, desc_set: u8) -> Result<crate::threedm::BaseRate, SessionError> {
        send_get_base_rate_get_base_rate(self.device, desc_set)
    }
    /// IMU message format (0x08).
    pub fn imu_message_format(self) -> ImuMessageFormatCommand<'d, T> {
        ImuMessageFormatCommand {
            device: self.device,
        }
    }
    /// GNSS message format (0x09).
    pub fn gnss_message_format(self) -> GnssMessageFormatCommand<'d, T> {
        GnssMessageFormatCommand {
            device: self.device,
        }
    }
    /// Estimation filter message format (0x0A).
    pub fn filter_message_format(self) -> FilterMessageFormatCommand<'d, T> {
        FilterMessageFormatCommand {
            device: self.device,
        }
    }
    /// NMEA message format (0x0C).
    pub fn nmea_message_format(self) -> NmeaMessageFormatCommand<'d, T> {
        NmeaMessageFormatCommand {
            device: self.device,
        }
    }
    /// Message format (0x0F).
    pub fn message_format(self) -> MessageFormatCommand<'d, T> {
        MessageFormatCommand {
            device: self.device,
        }
    }
    /// Factory streaming (0x10). Sends `factory_streaming`.
    pub fn factory_streaming(
        self,
        action: crate::types::FactoryStreamingAction,
        reserved: u8,
    ) -> Result<(), SessionError> {
        send_factory_streaming_factory_streaming(self.device, action, reserved)
    }
    /// Data stream control (0x11).
    pub fn data_stream_control(self) -> DataStreamControlCommand<'d, T> {
        DataStreamControlCommand {
            device: self.device,
        }
    }
    /// Raw RTCM 2.3 message (0x20). Sends `raw_rtcm_message`.
    pub fn raw_rtcm_message(
        self,
        data: crate::bounded::BoundedVec<u8, 253>,
    ) -> Result<(), SessionError> {
        send_raw_rtcm_message_raw_rtcm_message(self.device, data)
    }
    /// GNSS constellation settings (0x21).
    pub fn gnss_constellation_settings(self) -> GnssConstellationSettingsCommand<'d, T> {
        GnssConstellationSettingsCommand {
            device: self.device,
        }
    }
    /// GNSS SBAS settings (0x22).
    pub fn gnss_sbas_settings(self) -> GnssSbasSettingsCommand<'d, T> {
        GnssSbasSettingsCommand {
            device: self.device,
        }
    }
    /// GNSS assisted fix control (0x23).
    pub fn gnss_assisted_fix_control(self) -> GnssAssistedFixControlCommand<'d, T> {
        GnssAssistedFixControlCommand {
            device: self.device,
        }
    }
    /// GNSS assist time update (0x24).
    pub fn gnss_assist_time_update(self) -> GnssAssistTimeUpdateCommand<'d, T> {
        GnssAssistTimeUpdateCommand {
            device: self.device,
        }
    }
    /// PPS source control (0x28).
    pub fn pps_source(self) -> PpsSourceCommand<'d, T> {
        PpsSourceCommand {
            device: self.device,
        }
    }
    /// Get supported events (0x2A). Sends `get_supported_events`: returns the reply field.
    pub fn get_supported_events(
        self,
        query: crate::types::SupportedEventsQuery,
    ) -> Result<crate::threedm::SupportedEvents, SessionError> {
        send_get_supported_events_get_supported_events(self.device, query)
    }
    /// Device status (0x64). Sends `device_status`: returns the reply field.
    pub fn device_status(
        self,
        model_number: u16,
        status_selector: crate::types::DeviceStatusSelector,
    ) -> Result<crate::threedm::DeviceStatusResponse, SessionError> {
        send_device_status_device_status(self.device, model_number, status_selector)
    }
}

/// Event control (0x0C, 0x2B): one call per function.
#[derive(Debug)]
pub struct EventControlCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> EventControlCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        instance: u8,
        mode: crate::types::EventControlMode,
    ) -> Result<(), SessionError> {
        send_event_control_write(self.device, instance, mode)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self, instance: u8) -> Result<crate::threedm::EventControlResponse, SessionError> {
        send_event_control_read(self.device, instance)
    }
    /// Function `save`.
    pub fn save(self, instance: u8) -> Result<(), SessionError> {
        send_event_control_save(self.device, instance)
    }
    /// Function `load`.
    pub fn load(self, instance: u8) -> Result<(), SessionError> {
        send_event_control_load(self.device, instance)
    }
    /// Function `default`.
    pub fn default(self, instance: u8) -> Result<(), SessionError> {
        send_event_control_default(self.device, instance)
    }
}

fn send_event_control_write<T: Transport>(
    device: &mut Device<T>,
    instance: u8,
    mode: crate::types::EventControlMode,
) -> Result<(), SessionError> {
    let command = crate::threedm::EventControl {
        function: crate::types::FunctionSelector(1),
        instance,
        mode: Some(mode),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::EventControl(command));
    device.call(&value).map(|_| ())
}

fn send_event_control_read<T: Transport>(
    device: &mut Device<T>,
    instance: u8,
) -> Result<crate::threedm::EventControlResponse, SessionError> {
    let command = crate::threedm::EventControl {
        function: crate::types::FunctionSelector(2),
        instance,
        ..<crate::threedm::EventControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::EventControl(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::EventControlResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_event_control_save<T: Transport>(
    device: &mut Device<T>,
    instance: u8,
) -> Result<(), SessionError> {
    let command = crate::threedm::EventControl {
        function: crate::types::FunctionSelector(3),
        instance,
        ..<crate::threedm::EventControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::EventControl(command));
    device.call(&value).map(|_| ())
}

fn send_event_control_load<T: Transport>(
    device: &mut Device<T>,
    instance: u8,
) -> Result<(), SessionError> {
    let command = crate::threedm::EventControl {
        function: crate::types::FunctionSelector(4),
        instance,
        ..<crate::threedm::EventControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::EventControl(command));
    device.call(&value).map(|_| ())
}

fn send_event_control_default<T: Transport>(
    device: &mut Device<T>,
    instance: u8,
) -> Result<(), SessionError> {
    let command = crate::threedm::EventControl {
        function: crate::types::FunctionSelector(5),
        instance,
        ..<crate::threedm::EventControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::EventControl(command));
    device.call(&value).map(|_| ())
}

fn send_get_event_trigger_status_get_event_trigger_status<T: Transport>(
    device: &mut Device<T>,
    requested_instances: crate::bounded::BoundedVec<u8, 252>,
) -> Result<crate::threedm::EventTriggerStatus, SessionError> {
    let command = crate::threedm::GetEventTriggerStatus {
        requested_instances,
        requested_count: requested_instances.len() as u8,
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::GetEventTriggerStatus(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::EventTriggerStatus(r)) => Some(r),
        _ => None,
    })
}

fn send_get_event_action_status_get_event_action_status<T: Transport>(
    device: &mut Device<T>,
    requested_instances: crate::bounded::BoundedVec<u8, 252>,
) -> Result<crate::threedm::EventActionStatus, SessionError> {
    let command = crate::threedm::GetEventActionStatus {
        requested_instances,
        requested_count: requested_instances.len() as u8,
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::GetEventActionStatus(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::EventActionStatus(r)) => Some(r),
        _ => None,
    })
}

/// Event trigger configuration (0x0C, 0x2E): one call per function.
#[derive(Debug)]
pub struct EventTriggerConfigCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> EventTriggerConfigCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        instance: u8,
        r#type: crate::types::TriggerType,
        parameters: crate::types::TriggerParams,
    ) -> Result<(), SessionError> {
        send_event_trigger_config_write(self.device, instance, r#type, parameters)
    }
    /// Function `read`: returns the reply field.
    pub fn read(
        self,
        instance: u8,
    ) -> Result<crate::threedm::EventTriggerConfigResponse, SessionError> {
        send_event_trigger_config_read(self.device, instance)
    }
    /// Function `save`.
    pub fn save(self, instance: u8) -> Result<(), SessionError> {
        send_event_trigger_config_save(self.device, instance)
    }
    /// Function `load`.
    pub fn load(self, instance: u8) -> Result<(), SessionError> {
        send_event_trigger_config_load(self.device, instance)
    }
    /// Function `default`.
    pub fn default(self, instance: u8) -> Result<(), SessionError> {
        send_event_trigger_config_default(self.device, instance)
    }
}

fn send_event_trigger_config_write<T: Transport>(
    device: &mut Device<T>,
    instance: u8,
    r#type: crate::types::TriggerType,
    parameters: crate::types::TriggerParams,
) -> Result<(), SessionError> {
    let command = crate::threedm::EventTriggerConfig {
        function: crate::types::FunctionSelector(1),
        instance,
        r#type: Some(r#type),
        parameters: Some(parameters),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::EventTriggerConfig(command));
    device.call(&value).map(|_| ())
}

fn send_event_trigger_config_read<T: Transport>(
    device: &mut Device<T>,
    instance: u8,
) -> Result<crate::threedm::EventTriggerConfigResponse, SessionError> {
    let command = crate::threedm::EventTriggerConfig {
        function: crate::types::FunctionSelector(2),
        instance,
        ..<crate::threedm::EventTriggerConfig as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::EventTriggerConfig(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::EventTriggerConfigResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_event_trigger_config_save<T: Transport>(
    device: &mut Device<T>,
    instance: u8,
) -> Result<(), SessionError> {
    let command = crate::threedm::EventTriggerConfig {
        function: crate::types::FunctionSelector(3),
        instance,
        ..<crate::threedm::EventTriggerConfig as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::EventTriggerConfig(command));
    device.call(&value).map(|_| ())
}

fn send_event_trigger_config_load<T: Transport>(
    device: &mut Device<T>,
    instance: u8,
) -> Result<(), SessionError> {
    let command = crate::threedm::EventTriggerConfig {
        function: crate::types::FunctionSelector(4),
        instance,
        ..<crate::threedm::EventTriggerConfig as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::EventTriggerConfig(command));
    device.call(&value).map(|_| ())
}

fn send_event_trigger_config_default<T: Transport>(
    device: &mut Device<T>,
    instance: u8,
) -> Result<(), SessionError> {
    let command = crate::threedm::EventTriggerConfig {
        function: crate::types::FunctionSelector(5),
        instance,
        ..<crate::threedm::EventTriggerConfig as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::EventTriggerConfig(command));
    device.call(&value).map(|_| ())
}

/// Event action configuration (0x0C, 0x2F): one call per function.
#[derive(Debug)]
pub struct EventActionConfigCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> EventActionConfigCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        instance: u8,
        trigger: u8,
        r#type: crate::types::ActionType,
        parameters: crate::types::ActionParams,
    ) -> Result<(), SessionError> {
        send_event_action_config_write(self.device, instance, trigger, r#type, parameters)
    }
    /// Function `read`: returns the reply field.
    pub fn read(
        self,
        instance: u8,
    ) -> Result<crate::threedm::EventActionConfigResponse, SessionError> {
        send_event_action_config_read(self.device, instance)
    }
    /// Function `save`.
    pub fn save(self, instance: u8) -> Result<(), SessionError> {
        send_event_action_config_save(self.device, instance)
    }
    /// Function `load`.
    pub fn load(self, instance: u8) -> Result<(), SessionError> {
        send_event_action_config_load(self.device, instance)
    }
    /// Function `default`.
    pub fn default(self, instance: u8) -> Result<(), SessionError> {
        send_event_action_config_default(self.device, instance)
    }
}

fn send_event_action_config_write<T: Transport>(
    device: &mut Device<T>,
    instance: u8,
    trigger: u8,
    r#type: crate::types::ActionType,
    parameters: crate::types::ActionParams,
) -> Result<(), SessionError> {
    let command = crate::threedm::EventActionConfig {
        function: crate::types::FunctionSelector(1),
        instance,
        trigger: Some(trigger),
        r#type: Some(r#type),
        parameters: Some(parameters),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::EventActionConfig(command));
    device.call(&value).map(|_| ())
}

fn send_event_action_config_read<T: Transport>(
    device: &mut Device<T>,
    instance: u8,
) -> Result<crate::threedm::EventActionConfigResponse, SessionError> {
    let command = crate::threedm::EventActionConfig {
        function: crate::types::FunctionSelector(2),
        instance,
        ..<crate::threedm::EventActionConfig as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::EventActionConfig(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::EventActionConfigResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_event_action_config_save<T: Transport>(
    device: &mut Device<T>,
    instance: u8,
) -> Result<(), SessionError> {
    let command = crate::threedm::EventActionConfig {
        function: crate::types::FunctionSelector(3),
        instance,
        ..<crate::threedm::EventActionConfig as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::EventActionConfig(command));
    device.call(&value).map(|_| ())
}

fn send_event_action_config_load<T: Transport>(
    device: &mut Device<T>,
    instance: u8,
) -> Result<(), SessionError> {
    let command = crate::threedm::EventActionConfig {
        function: crate::types::FunctionSelector(4),
        instance,
        ..<crate::threedm::EventActionConfig as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::EventActionConfig(command));
    device.call(&value).map(|_| ())
}

fn send_event_action_config_default<T: Transport>(
    device: &mut Device<T>,
    instance: u8,
) -> Result<(), SessionError> {
    let command = crate::threedm::EventActionConfig {
        function: crate::types::FunctionSelector(5),
        instance,
        ..<crate::threedm::EventActionConfig as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::EventActionConfig(command));
    device.call(&value).map(|_| ())
}

/// Device startup settings (0x0C, 0x30): one call per function.
#[derive(Debug)]
pub struct DeviceStartupSettingsCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> DeviceStartupSettingsCommand<'d, T> {
    /// Function `read`.
    pub fn read(self) -> Result<(), SessionError> {
        send_device_startup_settings_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_device_startup_settings_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_device_startup_settings_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_device_startup_settings_default(self.device)
    }
}

fn send_device_startup_settings_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::threedm::DeviceStartupSettingsGx5_45 {
        function: crate::types::FunctionSelector(2),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::DeviceStartupSettings(
        crate::threedm::DeviceStartupSettings::Gx5_45(command),
    ));
    device.call(&value).map(|_| ())
}

fn send_device_startup_settings_save<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let value = match device.model() {
        Some(Model::Cv7Ins) => {
            let command = crate::threedm::DeviceStartupSettingsCv7Ins {
                function: crate::types::FunctionSelector(3),
            };
            FieldValue::Threedm(crate::threedm::SetField::DeviceStartupSettings(
                crate::threedm::DeviceStartupSettings::Cv7Ins(command),
            ))
        }
        _ => {
            let command = crate::threedm::DeviceStartupSettingsGx5_45 {
                function: crate::types::FunctionSelector(3),
            };
            FieldValue::Threedm(crate::threedm::SetField::DeviceStartupSettings(
                crate::threedm::DeviceStartupSettings::Gx5_45(command),
            ))
        }
    };
    device.call(&value).map(|_| ())
}

fn send_device_startup_settings_load<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let value = match device.model() {
        Some(Model::Cv7Ins) => {
            let command = crate::threedm::DeviceStartupSettingsCv7Ins {
                function: crate::types::FunctionSelector(4),
            };
            FieldValue::Threedm(crate::threedm::SetField::DeviceStartupSettings(
                crate::threedm::DeviceStartupSettings::Cv7Ins(command),
            ))
        }
        _ => {
            let command = crate::threedm::DeviceStartupSettingsGx5_45 {
                function: crate::types::FunctionSelector(4),
            };
            FieldValue::Threedm(crate::threedm::SetField::DeviceStartupSettings(
                crate::threedm::DeviceStartupSettings::Gx5_45(command),
            ))
        }
    };
    device.call(&value).map(|_| ())
}

fn send_device_startup_settings_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let value = match device.model() {
        Some(Model::Cv7Ins) => {
            let command = crate::threedm::DeviceStartupSettingsCv7Ins {
                function: crate::types::FunctionSelector(5),
            };
            FieldValue::Threedm(crate::threedm::SetField::DeviceStartupSettings(
                crate::threedm::DeviceStartupSettings::Cv7Ins(command),
            ))
        }
        _ => {
            let command = crate::threedm::DeviceStartupSettingsGx5_45 {
                function: crate::types::FunctionSelector(5),
            };
            FieldValue::Threedm(crate::threedm::SetField::DeviceStartupSettings(
                crate::threedm::DeviceStartupSettings::Gx5_45(command),
            ))
        }
    };
    device.call(&value).map(|_| ())
}

/// Sensor-to-vehicle frame transformation (Euler) (0x0C, 0x31): one call per function.
#[derive(Debug)]
pub struct SensorToVehicleEulerCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> SensorToVehicleEulerCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, roll: f32, pitch: f32, yaw: f32) -> Result<(), SessionError> {
        send_sensor_to_vehicle_euler_write(self.device, roll, pitch, yaw)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::threedm::SensorToVehicleEulerResponse, SessionError> {
        send_sensor_to_vehicle_euler_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_sensor_to_vehicle_euler_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_sensor_to_vehicle_euler_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_sensor_to_vehicle_euler_default(self.device)
    }
}

fn send_sensor_to_vehicle_euler_write<T: Transport>(
    device: &mut Device<T>,
    roll: f32,
    pitch: f32,
    yaw: f32,
) -> Result<(), SessionError> {
    let command = crate::threedm::SensorToVehicleEuler {
        function: crate::types::FunctionSelector(1),
        roll: Some(roll),
        pitch: Some(pitch),
        yaw: Some(yaw),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleEuler(command));
    device.call(&value).map(|_| ())
}

fn send_sensor_to_vehicle_euler_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::threedm::SensorToVehicleEulerResponse, SessionError> {
    let command = crate::threedm::SensorToVehicleEuler {
        function: crate::types::FunctionSelector(2),
        ..<crate::threedm::SensorToVehicleEuler as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleEuler(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleEulerResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_sensor_to_vehicle_euler_save<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::threedm::SensorToVehicleEuler {
        function: crate::types::FunctionSelector(3),
        ..<crate::threedm::SensorToVehicleEuler as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleEuler(command));
    device.call(&value).map(|_| ())
}

fn send_sensor_to_vehicle_euler_load<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::threedm::SensorToVehicleEuler {
        function: crate::types::FunctionSelector(4),
        ..<crate::threedm::SensorToVehicleEuler as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleEuler(command));
    device.call(&value).map(|_| ())
}

fn send_sensor_to_vehicle_euler_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::threedm::SensorToVehicleEuler {
        function: crate::types::FunctionSelector(5),
        ..<crate::threedm::SensorToVehicleEuler as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleEuler(command));
    device.call(&value).map(|_| ())
}

/// Sensor-to-vehicle frame transformation (quaternion) (0x0C, 0x32): one call per function.
#[derive(Debug)]
pub struct SensorToVehicleQuaternionCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> SensorToVehicleQuaternionCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, q: [f32; 4]) -> Result<(), SessionError> {
        send_sensor_to_vehicle_quaternion_write(self.device, q)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::threedm::SensorToVehicleQuaternionResponse, SessionError> {
        send_sensor_to_vehicle_quaternion_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_sensor_to_vehicle_quaternion_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_sensor_to_vehicle_quaternion_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_sensor_to_vehicle_quaternion_default(self.device)
    }
}

fn send_sensor_to_vehicle_quaternion_write<T: Transport>(
    device: &mut Device<T>,
    q: [f32; 4],
) -> Result<(), SessionError> {
    let command = crate::threedm::SensorToVehicleQuaternion {
        function: crate::types::FunctionSelector(1),
        q: Some(q),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleQuaternion(command));
    device.call(&value).map(|_| ())
}

fn send_sensor_to_vehicle_quaternion_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::threedm::SensorToVehicleQuaternionResponse, SessionError> {
    let command = crate::threedm::SensorToVehicleQuaternion {
        function: crate::types::FunctionSelector(2),
        ..<crate::threedm::SensorToVehicleQuaternion as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleQuaternion(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleQuaternionResponse(r)) => {
            Some(r)
        }
        _ => None,
    })
}

fn send_sensor_to_vehicle_quaternion_save<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::threedm::SensorToVehicleQuaternion {
        function: crate::types::FunctionSelector(3),
        ..<crate::threedm::SensorToVehicleQuaternion as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleQuaternion(command));
    device.call(&value).map(|_| ())
}

fn send_sensor_to_vehicle_quaternion_load<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::threedm::SensorToVehicleQuaternion {
        function: crate::types::FunctionSelector(4),
        ..<crate::threedm::SensorToVehicleQuaternion as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleQuaternion(command));
    device.call(&value).map(|_| ())
}

fn send_sensor_to_vehicle_quaternion_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::threedm::SensorToVehicleQuaternion {
        function: crate::types::FunctionSelector(5),
        ..<crate::threedm::SensorToVehicleQuaternion as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleQuaternion(command));
    device.call(&value).map(|_| ())
}

/// Sensor-to-vehicle frame transformation (direction cosine matrix) (0x0C, 0x33): one call per function.
#[derive(Debug)]
pub struct SensorToVehicleDcmCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> SensorToVehicleDcmCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, dcm: [f32; 9]) -> Result<(), SessionError> {
        send_sensor_to_vehicle_dcm_write(self.device, dcm)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::threedm::SensorToVehicleDcmResponse, SessionError> {
        send_sensor_to_vehicle_dcm_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_sensor_to_vehicle_dcm_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_sensor_to_vehicle_dcm_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_sensor_to_vehicle_dcm_default(self.device)
    }
}

fn send_sensor_to_vehicle_dcm_write<T: Transport>(
    device: &mut Device<T>,
    dcm: [f32; 9],
) -> Result<(), SessionError> {
    let command = crate::threedm::SensorToVehicleDcm {
        function: crate::types::FunctionSelector(1),
        dcm: Some(dcm),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleDcm(command));
    device.call(&value).map(|_| ())
}

fn send_sensor_to_vehicle_dcm_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::threedm::SensorToVehicleDcmResponse, SessionError> {
    let command = crate::threedm::SensorToVehicleDcm {
        function: crate::types::FunctionSelector(2),
        ..<crate::threedm::SensorToVehicleDcm as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleDcm(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleDcmResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_sensor_to_vehicle_dcm_save<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::threedm::SensorToVehicleDcm {
        function: crate::types::FunctionSelector(3),
        ..<crate::threedm::SensorToVehicleDcm as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleDcm(command));
    device.call(&value).map(|_| ())
}

fn send_sensor_to_vehicle_dcm_load<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::threedm::SensorToVehicleDcm {
        function: crate::types::FunctionSelector(4),
        ..<crate::threedm::SensorToVehicleDcm as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleDcm(command));
    device.call(&value).map(|_| ())
}

fn send_sensor_to_vehicle_dcm_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::threedm::SensorToVehicleDcm {
        function: crate::types::FunctionSelector(5),
        ..<crate::threedm::SensorToVehicleDcm as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleDcm(command));
    device.call(&value).map(|_| ())
}

/// Accelerometer bias (0x0C, 0x37): one call per function.
#[derive(Debug)]
pub struct AccelBiasCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> AccelBiasCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, bias: [f32; 3]) -> Result<(), SessionError> {
        send_accel_bias_write(self.device, bias)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::threedm::AccelBiasResponse, SessionError> {
        send_accel_bias_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_accel_bias_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_accel_bias_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_accel_bias_default(self.device)
    }
    /// Function `write_no_ack`.
    pub fn write_no_ack(self, bias: [f32; 3]) -> Result<(), SessionError> {
        send_accel_bias_write_no_ack(self.device, bias)
    }
}

fn send_accel_bias_write<T: Transport>(
    device: &mut Device<T>,
    bias: [f32; 3],
) -> Result<(), SessionError> {
    let value = match device.model() {
        Some(Model::Cv7Ins) => {
            let command = crate::threedm::AccelBiasCv7Ins {
                function: crate::types::FunctionSelector(1),
                bias: Some(bias),
            };
            FieldValue::Threedm(crate::threedm::SetField::AccelBias(
                crate::threedm::AccelBias::Cv7Ins(command),
            ))
        }
        _ => {
            let command = crate::threedm::AccelBiasGx5_45 {
                function: crate::types::FunctionSelector(1),
                bias: Some(bias),
            };
            FieldValue::Threedm(crate::threedm::SetField::AccelBias(
                crate::threedm::AccelBias::Gx5_45(command),
            ))
        }
    };
    device.call(&value).map(|_| ())
}

fn send_accel_bias_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::threedm::AccelBiasResponse, SessionError> {
    let value = match device.model() {
        Some(Model::Cv7Ins) => {
            let command = crate::threedm::AccelBiasCv7Ins {
                function: crate::types::FunctionSelector(2),
                ..<crate::threedm::AccelBiasCv7Ins as crate::wire::Wire>::ZERO
            };
            FieldValue::Threedm(crate::threedm::SetField::AccelBias(
                crate::threedm::AccelBias::Cv7Ins(command),
            ))
        }
        _ => {
            let command = crate::threedm::AccelBiasGx5_45 {
                function: crate::types::FunctionSelector(2),
                ..<crate::threedm::AccelBiasGx5_45 as crate::wire::Wire>::ZERO
            };
            FieldValue::Threedm(crate::threedm::SetField::AccelBias(
                crate::threedm::AccelBias::Gx5_45(command),
            ))
        }
    };
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::AccelBiasResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_accel_bias_save<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let value = match device.model() {
        Some(Model::Cv7Ins) => {
            let command = crate::threedm::AccelBiasCv7Ins {
                function: crate::types::FunctionSelector(3),
                ..<crate::threedm::AccelBiasCv7Ins as crate::wire::Wire>::ZERO
            };
            FieldValue::Threedm(crate::threedm::SetField::AccelBias(
                crate::threedm::AccelBias::Cv7Ins(command),
            ))
        }
        _ => {
            let command = crate::threedm::AccelBiasGx5_45 {
                function: crate::types::FunctionSelector(3),
                ..<crate::threedm::AccelBiasGx5_45 as crate::wire::Wire>::ZERO
            };
            FieldValue::Threedm(crate::threedm::SetField::AccelBias(
                crate::threedm::AccelBias::Gx5_45(command),
            ))
        }
    };
    device.call(&value).map(|_| ())
}

fn send_accel_bias_load<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let value = match device.model() {
        Some(Model::Cv7Ins) => {
            let command = crate::threedm::AccelBiasCv7Ins {
                function: crate::types::FunctionSelector(4),
                ..<crate::threedm::AccelBiasCv7Ins as crate::wire::Wire>::ZERO
            };
            FieldValue::Threedm(crate::threedm::SetField::AccelBias(
                crate::threedm::AccelBias::Cv7Ins(command),
            ))
        }
        _ => {
            let command = crate::threedm::AccelBiasGx5_45 {
                function: crate::types::FunctionSelector(4),
                ..<crate::threedm::AccelBiasGx5_45 as crate::wire::Wire>::ZERO
            };
            FieldValue::Threedm(crate::threedm::SetField::AccelBias(
                crate::threedm::AccelBias::Gx5_45(command),
            ))
        }
    };
    device.call(&value).map(|_| ())
}

fn send_accel_bias_default<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let value = match device.model() {
        Some(Model::Cv7Ins) => {
            let command = crate::threedm::AccelBiasCv7Ins {
                function: crate::types::FunctionSelector(5),
                ..<crate::threedm::AccelBiasCv7Ins as crate::wire::Wire>::ZERO
            };
            FieldValue::Threedm(crate::threedm::SetField::AccelBias(
                crate::threedm::AccelBias::Cv7Ins(command),
            ))
        }
        _ => {
            let command = crate::threedm::AccelBiasGx5_45 {
                function: crate::types::FunctionSelector(5),
                ..<crate::threedm::AccelBiasGx5_45 as crate::wire::Wire>::ZERO
            };
            FieldValue::Threedm(crate::threedm::SetField::AccelBias(
                crate::threedm::AccelBias::Gx5_45(command),
            ))
        }
    };
    device.call(&value).map(|_| ())
}

fn send_accel_bias_write_no_ack<T: Transport>(
    device: &mut Device<T>,
    bias: [f32; 3],
) -> Result<(), SessionError> {
    let command = crate::threedm::AccelBiasGx5_45 {
        function: crate::types::FunctionSelector(6),
        bias: Some(bias),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::AccelBias(
        crate::threedm::AccelBias::Gx5_45(command),
    ));
    device.call(&value).map(|_| ())
}

/// Gyro bias (0x0C, 0x38): one call per function.
#[derive(Debug)]
pub struct GyroBiasCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> GyroBiasCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, bias: [f32; 3]) -> Result<(), SessionError> {
        send_gyro_bias_write(self.device, bias)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::threedm::GyroBiasResponse, SessionError> {
        send_gyro_bias_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_gyro_bias_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_gyro_bias_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_gyro_bias_default(self.device)
    }
    /// Function `write_no_ack`.
    pub fn write_no_ack(self, bias: [f32; 3]) -> Result<(), SessionError> {
        send_gyro_bias_write_no_ack(self.device, bias)
    }
}

fn send_gyro_bias_write<T: Transport>(
    device: &mut Device<T>,
    bias: [f32; 3],
) -> Result<(), SessionError> {
    let value = match device.model() {
        Some(Model::Cv7Ins) => {
            let command = crate::threedm::GyroBiasCv7Ins {
                function: crate::types::FunctionSelector(1),
                bias: Some(bias),
            };
            FieldValue::Threedm(crate::threedm::SetField::GyroBias(
                crate::threedm::GyroBias::Cv7Ins(command),
            ))
        }
        _ => {
            let command = crate::threedm::GyroBiasGx5_45 {
                function: crate::types::FunctionSelector(1),
                bias: Some(bias),
            };
            FieldValue::Threedm(crate::threedm::SetField::GyroBias(
                crate::threedm::GyroBias::Gx5_45(command),
            ))
        }
    };
    device.call(&value).map(|_| ())
}

fn send_gyro_bias_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::threedm::GyroBiasResponse, SessionError> {
    let value = match device.model() {
        Some(Model::Cv7Ins) => {
            let command = crate::threedm::GyroBiasCv7Ins {
                function: crate::types::FunctionSelector(2),
                ..<crate::threedm::GyroBiasCv7Ins as crate::wire::Wire>::ZERO
            };
            FieldValue::Threedm(crate::threedm::SetField::GyroBias(
                crate::threedm::GyroBias::Cv7Ins(command),
            ))
        }
        _ => {
            let command = crate::threedm::GyroBiasGx5_45 {
                function: crate::types::FunctionSelector(2),
                ..<crate::threedm::GyroBiasGx5_45 as crate::wire::Wire>::ZERO
            };
            FieldValue::Threedm(crate::threedm::SetField::GyroBias(
                crate::threedm::GyroBias::Gx5_45(command),
            ))
        }
    };
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::GyroBiasResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_gyro_bias_save<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let value = match device.model() {
        Some(Model::Cv7Ins) => {
            let command = crate::threedm::GyroBiasCv7Ins {
                function: crate::types::FunctionSelector(3),
                ..<crate::threedm::GyroBiasCv7Ins as crate::wire::Wire>::ZERO
            };
            FieldValue::Threedm(crate::threedm::SetField::GyroBias(
                crate::threedm::GyroBias::Cv7Ins(command),
            ))
        }
        _ => {
            let command = crate::threedm::GyroBiasGx5_45 {
                function: crate::types::FunctionSelector(3),
                ..<crate::threedm::GyroBiasGx5_45 as crate::wire::Wire>::ZERO
            };
            FieldValue::Threedm(crate::threedm::SetField::GyroBias(
                crate::threedm::GyroBias::Gx5_45(command),
            ))
        }
    };
    device.call(&value).map(|_| ())
}

fn send_gyro_bias_load<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let value = match device.model() {
        Some(Model::Cv7Ins) => {
            let command = crate::threedm::GyroBiasCv7Ins {
                function: crate::types::FunctionSelector(4),
                ..<crate::threedm::GyroBiasCv7Ins as crate::wire::Wire>::ZERO
            };
            FieldValue::Threedm(crate::threedm::SetField::GyroBias(
                crate::threedm::GyroBias::Cv7Ins(command),
            ))
        }
        _ => {
            let command = crate::threedm::GyroBiasGx5_45 {
                function: crate::types::FunctionSelector(4),
                ..<crate::threedm::GyroBiasGx5_45 as crate::wire::Wire>::ZERO
            };
            FieldValue::Threedm(crate::threedm::SetField::GyroBias(
                crate::threedm::GyroBias::Gx5_45(command),
            ))
        }
    };
    device.call(&value).map(|_| ())
}

fn send_gyro_bias_default<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let value = match device.model() {
        Some(Model::Cv7Ins) => {
            let command = crate::threedm::GyroBiasCv7Ins {
                function: crate::types::FunctionSelector(5),
                ..<crate::threedm::GyroBiasCv7Ins as crate::wire::Wire>::ZERO
            };
            FieldValue::Threedm(crate::threedm::SetField::GyroBias(
                crate::threedm::GyroBias::Cv7Ins(command),
            ))
        }
        _ => {
            let command = crate::threedm::GyroBiasGx5_45 {
                function: crate::types::FunctionSelector(5),
                ..<crate::threedm::GyroBiasGx5_45 as crate::wire::Wire>::ZERO
            };
            FieldValue::Threedm(crate::threedm::SetField::GyroBias(
                crate::threedm::GyroBias::Gx5_45(command),
            ))
        }
    };
    device.call(&value).map(|_| ())
}

fn send_gyro_bias_write_no_ack<T: Transport>(
    device: &mut Device<T>,
    bias: [f32; 3],
) -> Result<(), SessionError> {
    let command = crate::threedm::GyroBiasGx5_45 {
        function: crate::types::FunctionSelector(6),
        bias: Some(bias),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::GyroBias(
        crate::threedm::GyroBias::Gx5_45(command),
    ));
    device.call(&value).map(|_| ())
}

fn send_capture_gyro_bias_capture_gyro_bias<T: Transport>(
    device: &mut Device<T>,
    averaging_time_ms: u16,
) -> Result<crate::threedm::GyroBiasResponse, SessionError> {
    let command = crate::threedm::CaptureGyroBias { averaging_time_ms };
    let value = FieldValue::Threedm(crate::threedm::SetField::CaptureGyroBias(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::GyroBiasResponse(r)) => Some(r),
        _ => None,
    })
}

/// Magnetometer hard iron offset (0x0C, 0x3A): one call per function.
#[derive(Debug)]
pub struct MagHardIronOffsetCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> MagHardIronOffsetCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, offset: [f32; 3]) -> Result<(), SessionError> {
        send_mag_hard_iron_offset_write(self.device, offset)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::threedm::MagHardIronOffsetResponse, SessionError> {
        send_mag_hard_iron_offset_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_mag_hard_iron_offset_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_mag_hard_iron_offset_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_mag_hard_iron_offset_default(self.device)
    }
    /// Function `write_no_ack`.
    pub fn write_no_ack(self, offset: [f32; 3]) -> Result<(), SessionError> {
        send_mag_hard_iron_offset_write_no_ack(self.device, offset)
    }
}

fn send_mag_hard_iron_offset_write<T: Transport>(
    device: &mut Device<T>,
    offset: [f32; 3],
) -> Result<(), SessionError> {
    let value = match device.model() {
        Some(Model::Cv7Ins) => {
            let command = crate::threedm::MagHardIronOffsetCv7Ins {
                function: crate::types::FunctionSelector(1),
                offset: Some(offset),
            };
            FieldValue::Threedm(crate::threedm::SetField::MagHardIronOffset(
                crate::threedm::MagHardIronOffset::Cv7Ins(command),
            ))
        }
        _ => {
            let command = crate::threedm::MagHardIronOffsetGx5_45 {
                function: crate::types::FunctionSelector(1),
                offset: Some(offset),
            };
            FieldValue::Threedm(crate::threedm::SetField::MagHardIronOffset(
                crate::threedm::MagHardIronOffset::Gx5_45(command),
            ))
        }
    };
    device.call(&value).map(|_| ())
}

fn send_mag_hard_iron_offset_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::threedm::MagHardIronOffsetResponse, SessionError> {
    let value = match device.model() {
        Some(Model::Cv7Ins) => {
            let command = crate::threedm::MagHardIronOffsetCv7Ins {
                function: crate::types::FunctionSelector(2),
                ..<crate::threedm::MagHardIronOffsetCv7Ins as crate::wire::Wire>::ZERO
            };
            FieldValue::Threedm(crate::threedm::SetField::MagHardIronOffset(
                crate::threedm::MagHardIronOffset::Cv7Ins(command),
            ))
        }
        _ => {
            let command = crate::threedm::MagHardIronOffsetGx5_45 {
                function: crate::types::FunctionSelector(2),
                ..<crate::threedm::MagHardIronOffsetGx5_45 as crate::wire::Wire>::ZERO
            };
            FieldValue::Threedm(crate::threedm::SetField::MagHardIronOffset(
                crate::threedm::MagHardIronOffset::Gx5_45(command),
            ))
        }
    };
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::MagHardIronOffsetResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_mag_hard_iron_offset_save<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let value = match device.model() {
        Some(Model::Cv7Ins) => {
            let command = crate::threedm::MagHardIronOffsetCv7Ins {
                function: crate::types::FunctionSelector(3),
                ..<crate::threedm::MagHardIronOffsetCv7Ins as crate::wire::Wire>::ZERO
            };
            FieldValue::Threedm(crate::threedm::SetField::MagHardIronOffset(
                crate::threedm::MagHardIronOffset::Cv7Ins(command),
            ))
        }
        _ => {
            let command = crate::threedm::MagHardIronOffsetGx5_45 {
                function: crate::types::FunctionSelector(3),
                ..<crate::threedm::MagHardIronOffsetGx5_45 as crate::wire::Wire>::ZERO
            };
            FieldValue::Threedm(crate::threedm::SetField::MagHardIronOffset(
                crate::threedm::MagHardIronOffset::Gx5_45(command),
            ))
        }
    };
    device.call(&value).map(|_| ())
}

fn send_mag_hard_iron_offset_load<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let value = match device.model() {
        Some(Model::Cv7Ins) => {
            let command = crate::threedm::MagHardIronOffsetCv7Ins {
                function: crate::types::FunctionSelector(4),
                ..<crate::threedm::MagHardIronOffsetCv7Ins as crate::wire::Wire>::ZERO
            };
            FieldValue::Threedm(crate::threedm::SetField::MagHardIronOffset(
                crate::threedm::MagHardIronOffset::Cv7Ins(command),
            ))
        }
        _ => {
            let command = crate::threedm::MagHardIronOffsetGx5_45 {
                function: crate::types::FunctionSelector(4),
                ..<crate::threedm::MagHardIronOffsetGx5_45 as crate::wire::Wire>::ZERO
            };
            FieldValue::Threedm(crate::threedm::SetField::MagHardIronOffset(
                crate::threedm::MagHardIronOffset::Gx5_45(command),
            ))
        }
    };
    device.call(&value).map(|_| ())
}

fn send_mag_hard_iron_offset_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let value = match device.model() {
        Some(Model::Cv7Ins) => {
            let command = crate::threedm::MagHardIronOffsetCv7Ins {
                function: crate::types::FunctionSelector(5),
                ..<crate::threedm::MagHardIronOffsetCv7Ins as crate::wire::Wire>::ZERO
            };
            FieldValue::Threedm(crate::threedm::SetField::MagHardIronOffset(
                crate::threedm::MagHardIronOffset::Cv7Ins(command),
            ))
        }
        _ => {
            let command = crate::threedm::MagHardIronOffsetGx5_45 {
                function: crate::types::FunctionSelector(5),
                ..<crate::threedm::MagHardIronOffsetGx5_45 as crate::wire::Wire>::ZERO
            };
            FieldValue::Threedm(crate::threedm::SetField::MagHardIronOffset(
                crate::threedm::MagHardIronOffset::Gx5_45(command),
            ))
        }
    };
    device.call(&value).map(|_| ())
}

fn send_mag_hard_iron_offset_write_no_ack<T: Transport>(
    device: &mut Device<T>,
    offset: [f32; 3],
) -> Result<(), SessionError> {
    let command = crate::threedm::MagHardIronOffsetGx5_45 {
        function: crate::types::FunctionSelector(6),
        offset: Some(offset),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::MagHardIronOffset(
        crate::threedm::MagHardIronOffset::Gx5_45(command),
    ));
    device.call(&value).map(|_| ())
}

/// Magnetometer soft iron matrix (0x0C, 0x3B): one call per function.
#[derive(Debug)]
pub struct MagSoftIronMatrixCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> MagSoftIronMatrixCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, matrix: [f32; 9]) -> Result<(), SessionError> {
        send_mag_soft_iron_matrix_write(self.device, matrix)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::threedm::MagSoftIronMatrixResponse, SessionError> {
        send_mag_soft_iron_matrix_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_mag_soft_iron_matrix_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_mag_soft_iron_matrix_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_mag_soft_iron_matrix_default(self.device)
    }
    /// Function `write_no_ack`.
    pub fn write_no_ack(self, matrix: [f32; 9]) -> Result<(), SessionError> {
        send_mag_soft_iron_matrix_write_no_ack(self.device, matrix)
    }
}

fn send_mag_soft_iron_matrix_write<T: Transport>(
    device: &mut Device<T>,
    matrix: [f32; 9],
) -> Result<(), SessionError> {
    let value = match device.model() {
        Some(Model::Cv7Ins) => {
            let command = crate::threedm::MagSoftIronMatrixCv7Ins {
                function: crate::types::FunctionSelector(1),
                matrix: Some(matrix),
            };
            FieldValue::Threedm(crate::threedm::SetField::MagSoftIronMatrix(
                crate::threedm::MagSoftIronMatrix::Cv7Ins(command),
            ))
        }
        _ => {
            let command = crate::threedm::MagSoftIronMatrixGx5_45 {
                function: crate::types::FunctionSelector(1),
                matrix: Some(matrix),
            };
            FieldValue::Threedm(crate::threedm::SetField::MagSoftIronMatrix(
                crate::threedm::MagSoftIronMatrix::Gx5_45(command),
            ))
        }
    };
    device.call(&value).map(|_| ())
}

fn send_mag_soft_iron_matrix_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::threedm::MagSoftIronMatrixResponse, SessionError> {
    let value = match device.model() {
        Some(Model::Cv7Ins) => {
            let command = crate::threedm::MagSoftIronMatrixCv7Ins {
                function: crate::types::FunctionSelector(2),
                ..<crate::threedm::MagSoftIronMatrixCv7Ins as crate::wire::Wire>::ZERO
            };
            FieldValue::Threedm(crate::threedm::SetField::MagSoftIronMatrix(
                crate::threedm::MagSoftIronMatrix::Cv7Ins(command),
            ))
        }
        _ => {
            let command = crate::threedm::MagSoftIronMatrixGx5_45 {
                function: crate::types::FunctionSelector(2),
                ..<crate::threedm::MagSoftIronMatrixGx5_45 as crate::wire::Wire>::ZERO
            };
            FieldValue::Threedm(crate::threedm::SetField::MagSoftIronMatrix(
                crate::threedm::MagSoftIronMatrix::Gx5_45(command),
            ))
        }
    };
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::MagSoftIronMatrixResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_mag_soft_iron_matrix_save<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let value = match device.model() {
        Some(Model::Cv7Ins) => {
            let command = crate::threedm::MagSoftIronMatrixCv7Ins {
                function: crate::types::FunctionSelector(3),
                ..<crate::threedm::MagSoftIronMatrixCv7Ins as crate::wire::Wire>::ZERO
            };
            FieldValue::Threedm(crate::threedm::SetField::MagSoftIronMatrix(
                crate::threedm::MagSoftIronMatrix::Cv7Ins(command),
            ))
        }
        _ => {
            let command = crate::threedm::MagSoftIronMatrixGx5_45 {
                function: crate::types::FunctionSelector(3),
                ..<crate::threedm::MagSoftIronMatrixGx5_45 as crate::wire::Wire>::ZERO
            };
            FieldValue::Threedm(crate::threedm::SetField::MagSoftIronMatrix(
                crate::threedm::MagSoftIronMatrix::Gx5_45(command),
            ))
        }
    };
    device.call(&value).map(|_| ())
}

fn send_mag_soft_iron_matrix_load<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let value = match device.model() {
        Some(Model::Cv7Ins) => {
            let command = crate::threedm::MagSoftIronMatrixCv7Ins {
                function: crate::types::FunctionSelector(4),
                ..<crate::threedm::MagSoftIronMatrixCv7Ins as crate::wire::Wire>::ZERO
            };
            FieldValue::Threedm(crate::threedm::SetField::MagSoftIronMatrix(
                crate::threedm::MagSoftIronMatrix::Cv7Ins(command),
            ))
        }
        _ => {
            let command = crate::threedm::MagSoftIronMatrixGx5_45 {
                function: crate::types::FunctionSelector(4),
                ..<crate::threedm::MagSoftIronMatrixGx5_45 as crate::wire::Wire>::ZERO
            };
            FieldValue::Threedm(crate::threedm::SetField::MagSoftIronMatrix(
                crate::threedm::MagSoftIronMatrix::Gx5_45(command),
            ))
        }
    };
    device.call(&value).map(|_| ())
}

fn send_mag_soft_iron_matrix_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let value = match device.model() {
        Some(Model::Cv7Ins) => {
            let command = crate::threedm::MagSoftIronMatrixCv7Ins {
                function: crate::types::FunctionSelector(5),
                ..<crate::threedm::MagSoftIronMatrixCv7Ins as crate::wire::Wire>::ZERO
            };
            FieldValue::Threedm(crate::threedm::SetField::MagSoftIronMatrix(
                crate::threedm::MagSoftIronMatrix::Cv7Ins(command),
            ))
        }
        _ => {
            let command = crate::threedm::MagSoftIronMatrixGx5_45 {
                function: crate::types::FunctionSelector(5),
                ..<crate::threedm::MagSoftIronMatrixGx5_45 as crate::wire::Wire>::ZERO
            };
            FieldValue::Threedm(crate::threedm::SetField::MagSoftIronMatrix(
                crate::threedm::MagSoftIronMatrix::Gx5_45(command),
            ))
        }
    };
    device.call(&value).map(|_| ())
}

fn send_mag_soft_iron_matrix_write_no_ack<T: Transport>(
    device: &mut Device<T>,
    matrix: [f32; 9],
) -> Result<(), SessionError> {
    let command = crate::threedm::MagSoftIronMatrixGx5_45 {
        function: crate::types::FunctionSelector(6),
        matrix: Some(matrix),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::MagSoftIronMatrix(
        crate::threedm::MagSoftIronMatrix::Gx5_45(command),
    ));
    device.call(&value).map(|_| ())
}

/// Coning and sculling enable (0x0C, 0x3E): one call per function.
#[derive(Debug)]
pub struct ConingScullingEnableCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> ConingScullingEnableCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, enable: bool) -> Result<(), SessionError> {
        send_coning_sculling_enable_write(self.device, enable)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::threedm::ConingScullingEnableResponse, SessionError> {
        send_coning_sculling_enable_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_coning_sculling_enable_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_coning_sculling_enable_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_coning_sculling_enable_default(self.device)
    }
}

fn send_coning_sculling_enable_write<T: Transport>(
    device: &mut Device<T>,
    enable: bool,
) -> Result<(), SessionError> {
    let command = crate::threedm::ConingScullingEnable {
        function: crate::types::FunctionSelector(1),
        enable: Some(enable),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::ConingScullingEnable(command));
    device.call(&value).map(|_| ())
}

fn send_coning_sculling_enable_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::threedm::ConingScullingEnableResponse, SessionError> {
    let command = crate::threedm::ConingScullingEnable {
        function: crate::types::FunctionSelector(2),
        ..<crate::threedm::ConingScullingEnable as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::ConingScullingEnable(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::ConingScullingEnableResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_coning_sculling_enable_save<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::threedm::ConingScullingEnable {
        function: crate::types::FunctionSelector(3),
        ..<crate::threedm::ConingScullingEnable as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::ConingScullingEnable(command));
    device.call(&value).map(|_| ())
}

fn send_coning_sculling_enable_load<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::threedm::ConingScullingEnable {
        function: crate::types::FunctionSelector(4),
        ..<crate::threedm::ConingScullingEnable as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::ConingScullingEnable(command));
    device.call(&value).map(|_| ())
}

fn send_coning_sculling_enable_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::threedm::ConingScullingEnable {
        function: crate::types::FunctionSelector(5),
        ..<crate::threedm::ConingScullingEnable as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::ConingScullingEnable(command));
    device.call(&value).map(|_| ())
}

/// UART baud rate (0x0C, 0x40): one call per function.
#[derive(Debug)]
pub struct UartBaudrateCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> UartBaudrateCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, baud: u32) -> Result<(), SessionError> {
        send_uart_baudrate_write(self.device, baud)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::threedm::UartBaudrateResponse, SessionError> {
        send_uart_baudrate_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_uart_baudrate_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_uart_baudrate_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_uart_baudrate_default(self.device)
    }
}

fn send_uart_baudrate_write<T: Transport>(
    device: &mut Device<T>,
    baud: u32,
) -> Result<(), SessionError> {
    let command = crate::threedm::UartBaudrate {
        function: crate::types::FunctionSelector(1),
        baud: Some(baud),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::UartBaudrate(command));
    device.call(&value).map(|_| ())
}

fn send_uart_baudrate_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::threedm::UartBaudrateResponse, SessionError> {
    let command = crate::threedm::UartBaudrate {
        function: crate::types::FunctionSelector(2),
        ..<crate::threedm::UartBaudrate as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::UartBaudrate(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::UartBaudrateResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_uart_baudrate_save<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::threedm::UartBaudrate {
        function: crate::types::FunctionSelector(3),
        ..<crate::threedm::UartBaudrate as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::UartBaudrate(command));
    device.call(&value).map(|_| ())
}

fn send_uart_baudrate_load<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::threedm::UartBaudrate {
        function: crate::types::FunctionSelector(4),
        ..<crate::threedm::UartBaudrate as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::UartBaudrate(command));
    device.call(&value).map(|_| ())
}

fn send_uart_baudrate_default<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::threedm::UartBaudrate {
        function: crate::types::FunctionSelector(5),
        ..<crate::threedm::UartBaudrate as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::UartBaudrate(command));
    device.call(&value).map(|_| ())
}

/// GPIO configuration (0x0C, 0x41): one call per function.
#[derive(Debug)]
pub struct GpioConfigCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> GpioConfigCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        pin: u8,
        feature: crate::types::GpioFeature,
        behavior: crate::types::GpioBehavior,
        pin_mode: crate::types::GpioPinMode,
    ) -> Result<(), SessionError> {
        send_gpio_config_write(self.device, pin, feature, behavior, pin_mode)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self, pin: u8) -> Result<crate::threedm::GpioConfigResponse, SessionError> {
        send_gpio_config_read(self.device, pin)
    }
    /// Function `save`.
    pub fn save(self, pin: u8) -> Result<(), SessionError> {
        send_gpio_config_save(self.device, pin)
    }
    /// Function `load`.
    pub fn load(self, pin: u8) -> Result<(), SessionError> {
        send_gpio_config_load(self.device, pin)
    }
    /// Function `default`.
    pub fn default(self, pin: u8) -> Result<(), SessionError> {
        send_gpio_config_default(self.device, pin)
    }
}

fn send_gpio_config_write<T: Transport>(
    device: &mut Device<T>,
    pin: u8,
    feature: crate::types::GpioFeature,
    behavior: crate::types::GpioBehavior,
    pin_mode: crate::types::GpioPinMode,
) -> Result<(), SessionError> {
    let command = crate::threedm::GpioConfig {
        function: crate::types::FunctionSelector(1),
        pin,
        feature: Some(feature),
        behavior: Some(behavior),
        pin_mode: Some(pin_mode),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::GpioConfig(command));
    device.call(&value).map(|_| ())
}

fn send_gpio_config_read<T: Transport>(
    device: &mut Device<T>,
    pin: u8,
) -> Result<crate::threedm::GpioConfigResponse, SessionError> {
    let command = crate::threedm::GpioConfig {
        function: crate::types::FunctionSelector(2),
        pin,
        ..<crate::threedm::GpioConfig as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::GpioConfig(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::GpioConfigResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_gpio_config_save<T: Transport>(
    device: &mut Device<T>,
    pin: u8,
) -> Result<(), SessionError> {
    let command = crate::threedm::GpioConfig {
        function: crate::types::FunctionSelector(3),
        pin,
        ..<crate::threedm::GpioConfig as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::GpioConfig(command));
    device.call(&value).map(|_| ())
}

fn send_gpio_config_load<T: Transport>(
    device: &mut Device<T>,
    pin: u8,
) -> Result<(), SessionError> {
    let command = crate::threedm::GpioConfig {
        function: crate::types::FunctionSelector(4),
        pin,
        ..<crate::threedm::GpioConfig as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::GpioConfig(command));
    device.call(&value).map(|_| ())
}

fn send_gpio_config_default<T: Transport>(
    device: &mut Device<T>,
    pin: u8,
) -> Result<(), SessionError> {
    let command = crate::threedm::GpioConfig {
        function: crate::types::FunctionSelector(5),
        pin,
        ..<crate::threedm::GpioConfig as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::GpioConfig(command));
    device.call(&value).map(|_| ())
}

/// GPIO state (0x0C, 0x42): one call per function.
#[derive(Debug)]
pub struct GpioStateCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> GpioStateCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, pin: u8, state: bool) -> Result<(), SessionError> {
        send_gpio_state_write(self.device, pin, state)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self, pin: u8) -> Result<crate::threedm::GpioStateResponse, SessionError> {
        send_gpio_state_read(self.device, pin)
    }
}

fn send_gpio_state_write<T: Transport>(
    device: &mut Device<T>,
    pin: u8,
    state: bool,
) -> Result<(), SessionError> {
    let command = crate::threedm::GpioState {
        function: crate::types::FunctionSelector(1),
        pin,
        state: Some(state),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::GpioState(command));
    device.call(&value).map(|_| ())
}

fn send_gpio_state_read<T: Transport>(
    device: &mut Device<T>,
    pin: u8,
) -> Result<crate::threedm::GpioStateResponse, SessionError> {
    let command = crate::threedm::GpioState {
        function: crate::types::FunctionSelector(2),
        pin,
        ..<crate::threedm::GpioState as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::GpioState(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::GpioStateResponse(r)) => Some(r),
        _ => None,
    })
}

/// Odometer configuration (0x0C, 0x43): one call per function.
#[derive(Debug)]
pub struct OdometerConfigCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> OdometerConfigCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        mode: crate::types::OdometerMode,
        scaling: f32,
        uncertainty: f32,
    ) -> Result<(), SessionError> {
        send_odometer_config_write(self.device, mode, scaling, uncertainty)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::threedm::OdometerConfigResponse, SessionError> {
        send_odometer_config_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_odometer_config_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_odometer_config_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_odometer_config_default(self.device)
    }
}

fn send_odometer_config_write<T: Transport>(
    device: &mut Device<T>,
    mode: crate::types::OdometerMode,
    scaling: f32,
    uncertainty: f32,
) -> Result<(), SessionError> {
    let command = crate::threedm::OdometerConfig {
        function: crate::types::FunctionSelector(1),
        mode: Some(mode),
        scaling: Some(scaling),
        uncertainty: Some(uncertainty),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::OdometerConfig(command));
    device.call(&value).map(|_| ())
}

fn send_odometer_config_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::threedm::OdometerConfigResponse, SessionError> {
    let command = crate::threedm::OdometerConfig {
        function: crate::types::FunctionSelector(2),
        ..<crate::threedm::OdometerConfig as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::OdometerConfig(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::OdometerConfigResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_odometer_config_save<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::threedm::OdometerConfig {
        function: crate::types::FunctionSelector(3),
        ..<crate::threedm::OdometerConfig as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::OdometerConfig(command));
    device.call(&value).map(|_| ())
}

fn send_odometer_config_load<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::threedm::OdometerConfig {
        function: crate::types::FunctionSelector(4),
        ..<crate::threedm::OdometerConfig as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::OdometerConfig(command));
    device.call(&value).map(|_| ())
}

fn send_odometer_config_default<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::threedm::OdometerConfig {
        function: crate::types::FunctionSelector(5),
        ..<crate::threedm::OdometerConfig as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::OdometerConfig(command));
    device.call(&value).map(|_| ())
}

/// Advanced low-pass filter settings (0x0C, 0x50): one call per function.
#[derive(Debug)]
pub struct AdvancedLowpassFilterCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> AdvancedLowpassFilterCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        target_descriptor: u8,
        enable: bool,
        manual: bool,
        frequency: u16,
        reserved: u8,
    ) -> Result<(), SessionError> {
        send_advanced_lowpass_filter_write(
            self.device,
            target_descriptor,
            enable,
            manual,
            frequency,
            reserved,
        )
    }
    /// Function `read`: returns the reply field.
    pub fn read(
        self,
        target_descriptor: u8,
    ) -> Result<crate::threedm::AdvancedLowpassFilterResponse, SessionError> {
        send_advanced_lowpass_filter_read(self.device, target_descriptor)
    }
    /// Function `save`.
    pub fn save(self, target_descriptor: u8) -> Result<(), SessionError> {
        send_advanced_lowpass_filter_save(self.device, target_descriptor)
    }
    /// Function `load`.
    pub fn load(self, target_descriptor: u8) -> Result<(), SessionError> {
        send_advanced_lowpass_filter_load(self.device, target_descriptor)
    }
    /// Function `default`.
    pub fn default(self, target_descriptor: u8) -> Result<(), SessionError> {
        send_advanced_lowpass_filter_default(self.device, target_descriptor)
    }
}

fn send_advanced_lowpass_filter_write<T: Transport>(
    device: &mut Device<T>,
    target_descriptor: u8,
    enable: bool,
    manual: bool,
    frequency: u16,
    reserved: u8,
) -> Result<(), SessionError> {
    let command = crate::threedm::AdvancedLowpassFilter {
        function: crate::types::FunctionSelector(1),
        target_descriptor,
        enable: Some(enable),
        manual: Some(manual),
        frequency: Some(frequency),
        reserved: Some(reserved),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::AdvancedLowpassFilter(command));
    device.call(&value).map(|_| ())
}

fn send_advanced_lowpass_filter_read<T: Transport>(
    device: &mut Device<T>,
    target_descriptor: u8,
) -> Result<crate::threedm::AdvancedLowpassFilterResponse, SessionError> {
    let command = crate::threedm::AdvancedLowpassFilter {
        function: crate::types::FunctionSelector(2),
        target_descriptor,
        ..<crate::threedm::AdvancedLowpassFilter as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::AdvancedLowpassFilter(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::AdvancedLowpassFilterResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_advanced_lowpass_filter_save<T: Transport>(
    device: &mut Device<T>,
    target_descriptor: u8,
) -> Result<(), SessionError> {
    let command = crate::threedm::AdvancedLowpassFilter {
        function: crate::types::FunctionSelector(3),
        target_descriptor,
        ..<crate::threedm::AdvancedLowpassFilter as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::AdvancedLowpassFilter(command));
    device.call(&value).map(|_| ())
}

fn send_advanced_lowpass_filter_load<T: Transport>(
    device: &mut Device<T>,
    target_descriptor: u8,
) -> Result<(), SessionError> {
    let command = crate::threedm::AdvancedLowpassFilter {
        function: crate::types::FunctionSelector(4),
        target_descriptor,
        ..<crate::threedm::AdvancedLowpassFilter as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::AdvancedLowpassFilter(command));
    device.call(&value).map(|_| ())
}

fn send_advanced_lowpass_filter_default<T: Transport>(
    device: &mut Device<T>,
    target_descriptor: u8,
) -> Result<(), SessionError> {
    let command = crate::threedm::AdvancedLowpassFilter {
        function: crate::types::FunctionSelector(5),
        target_descriptor,
        ..<crate::threedm::AdvancedLowpassFilter as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::AdvancedLowpassFilter(command));
    device.call(&value).map(|_| ())
}

/// Complementary filter settings (0x0C, 0x51): one call per function.
#[derive(Debug)]
pub struct ComplementaryFilterCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> ComplementaryFilterCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        pitch_roll_enable: bool,
        heading_enable: bool,
        pitch_roll_time_constant: f32,
        heading_time_constant: f32,
    ) -> Result<(), SessionError> {
        send_complementary_filter_write(
            self.device,
            pitch_roll_enable,
            heading_enable,
            pitch_roll_time_constant,
            heading_time_constant,
        )
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::threedm::ComplementaryFilterResponse, SessionError> {
        send_complementary_filter_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_complementary_filter_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_complementary_filter_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_complementary_filter_default(self.device)
    }
}

fn send_complementary_filter_write<T: Transport>(
    device: &mut Device<T>,
    pitch_roll_enable: bool,
    heading_enable: bool,
    pitch_roll_time_constant: f32,
    heading_time_constant: f32,
) -> Result<(), SessionError> {
    let command = crate::threedm::ComplementaryFilter {
        function: crate::types::FunctionSelector(1),
        pitch_roll_enable: Some(pitch_roll_enable),
        heading_enable: Some(heading_enable),
        pitch_roll_time_constant: Some(pitch_roll_time_constant),
        heading_time_constant: Some(heading_time_constant),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::ComplementaryFilter(command));
    device.call(&value).map(|_| ())
}

fn send_complementary_filter_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::threedm::ComplementaryFilterResponse, SessionError> {
    let command = crate::threedm::ComplementaryFilter {
        function: crate::types::FunctionSelector(2),
        ..<crate::threedm::ComplementaryFilter as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::ComplementaryFilter(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::ComplementaryFilterResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_complementary_filter_save<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::threedm::ComplementaryFilter {
        function: crate::types::FunctionSelector(3),
        ..<crate::threedm::ComplementaryFilter as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::ComplementaryFilter(command));
    device.call(&value).map(|_| ())
}

fn send_complementary_filter_load<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::threedm::ComplementaryFilter {
        function: crate::types::FunctionSelector(4),
        ..<crate::threedm::ComplementaryFilter as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::ComplementaryFilter(command));
    device.call(&value).map(|_| ())
}

fn send_complementary_filter_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::threedm::ComplementaryFilter {
        function: crate::types::FunctionSelector(5),
        ..<crate::threedm::ComplementaryFilter as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::ComplementaryFilter(command));
    device.call(&value).map(|_| ())
}

/// Sensor range (0x0C, 0x52): one call per function.
#[derive(Debug)]
pub struct SensorRangeCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> SensorRangeCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        sensor: crate::types::SensorRangeType,
        setting: u8,
    ) -> Result<(), SessionError> {
        send_sensor_range_write(self.device, sensor, setting)
    }
    /// Function `read`: returns the reply field.
    pub fn read(
        self,
        sensor: crate::types::SensorRangeType,
    ) -> Result<crate::threedm::SensorRangeResponse, SessionError> {
        send_sensor_range_read(self.device, sensor)
    }
    /// Function `save`.
    pub fn save(self, sensor: crate::types::SensorRangeType) -> Result<(), SessionError> {
        send_sensor_range_save(self.device, sensor)
    }
    /// Function `load`.
    pub fn load(self, sensor: crate::types::SensorRangeType) -> Result<(), SessionError> {
        send_sensor_range_load(self.device, sensor)
    }
    /// Function `default`.
    pub fn default(self, sensor: crate::types::SensorRangeType) -> Result<(), SessionError> {
        send_sensor_range_default(self.device, sensor)
    }
}

fn send_sensor_range_write<T: Transport>(
    device: &mut Device<T>,
    sensor: crate::types::SensorRangeType,
    setting: u8,
) -> Result<(), SessionError> {
    let command = crate::threedm::SensorRange {
        function: crate::types::FunctionSelector(1),
        sensor,
        setting: Some(setting),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::SensorRange(command));
    device.call(&value).map(|_| ())
}

fn send_sensor_range_read<T: Transport>(
    device: &mut Device<T>,
    sensor: crate::types::SensorRangeType,
) -> Result<crate::threedm::SensorRangeResponse, SessionError> {
    let command = crate::threedm::SensorRange {
        function: crate::types::FunctionSelector(2),
        sensor,
        ..<crate::threedm::SensorRange as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::SensorRange(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::SensorRangeResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_sensor_range_save<T: Transport>(
    device: &mut Device<T>,
    sensor: crate::types::SensorRangeType,
) -> Result<(), SessionError> {
    let command = crate::threedm::SensorRange {
        function: crate::types::FunctionSelector(3),
        sensor,
        ..<crate::threedm::SensorRange as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::SensorRange(command));
    device.call(&value).map(|_| ())
}

fn send_sensor_range_load<T: Transport>(
    device: &mut Device<T>,
    sensor: crate::types::SensorRangeType,
) -> Result<(), SessionError> {
    let command = crate::threedm::SensorRange {
        function: crate::types::FunctionSelector(4),
        sensor,
        ..<crate::threedm::SensorRange as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::SensorRange(command));
    device.call(&value).map(|_| ())
}

fn send_sensor_range_default<T: Transport>(
    device: &mut Device<T>,
    sensor: crate::types::SensorRangeType,
) -> Result<(), SessionError> {
    let command = crate::threedm::SensorRange {
        function: crate::types::FunctionSelector(5),
        sensor,
        ..<crate::threedm::SensorRange as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::SensorRange(command));
    device.call(&value).map(|_| ())
}

fn send_get_calibrated_sensor_ranges_get_calibrated_sensor_ranges<T: Transport>(
    device: &mut Device<T>,
    sensor: crate::types::SensorRangeType,
) -> Result<crate::threedm::CalibratedSensorRanges, SessionError> {
    let command = crate::threedm::GetCalibratedSensorRanges { sensor };
    let value = FieldValue::Threedm(crate::threedm::SetField::GetCalibratedSensorRanges(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::CalibratedSensorRanges(r)) => Some(r),
        _ => None,
    })
}

/// Low-pass anti-aliasing filter (0x0C, 0x54): one call per function.
#[derive(Debug)]
pub struct LowpassFilterCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> LowpassFilterCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        desc_set: u8,
        field_desc: u8,
        enable: bool,
        manual: bool,
        frequency: f32,
    ) -> Result<(), SessionError> {
        send_lowpass_filter_write(self.device, desc_set, field_desc, enable, manual, frequency)
    }
    /// Function `read`: returns the reply field.
    pub fn read(
        self,
        desc_set: u8,
        field_desc: u8,
    ) -> Result<crate::threedm::LowpassFilterResponse, SessionError> {
        send_lowpass_filter_read(self.device, desc_set, field_desc)
    }
    /// Function `save`.
    pub fn save(self, desc_set: u8, field_desc: u8) -> Result<(), SessionError> {
        send_lowpass_filter_save(self.device, desc_set, field_desc)
    }
    /// Function `load`.
    pub fn load(self, desc_set: u8, field_desc: u8) -> Result<(), SessionError> {
        send_lowpass_filter_load(self.device, desc_set, field_desc)
    }
    /// Function `default`.
    pub fn default(self, desc_set: u8, field_desc: u8) -> Result<(), SessionError> {
        send_lowpass_filter_default(self.device, desc_set, field_desc)
    }
}

fn send_lowpass_filter_write<T: Transport>(
    device: &mut Device<T>,
    desc_set: u8,
    field_desc: u8,
    enable: bool,
    manual: bool,
    frequency: f32,
) -> Result<(), SessionError> {
    let command = crate::threedm::LowpassFilter {
        function: crate::types::FunctionSelector(1),
        desc_set,
        field_desc,
        enable: Some(enable),
        manual: Some(manual),
        frequency: Some(frequency),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::LowpassFilter(command));
    device.call(&value).map(|_| ())
}

fn send_lowpass_filter_read<T: Transport>(
    device: &mut Device<T>,
    desc_set: u8,
    field_desc: u8,
) -> Result<crate::threedm::LowpassFilterResponse, SessionError> {
    let command = crate::threedm::LowpassFilter {
        function: crate::types::FunctionSelector(2),
        desc_set,
        field_desc,
        ..<crate::threedm::LowpassFilter as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::LowpassFilter(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::LowpassFilterResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_lowpass_filter_save<T: Transport>(
    device: &mut Device<T>,
    desc_set: u8,
    field_desc: u8,
) -> Result<(), SessionError> {
    let command = crate::threedm::LowpassFilter {
        function: crate::types::FunctionSelector(3),
        desc_set,
        field_desc,
        ..<crate::threedm::LowpassFilter as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::LowpassFilter(command));
    device.call(&value).map(|_| ())
}

fn send_lowpass_filter_load<T: Transport>(
    device: &mut Device<T>,
    desc_set: u8,
    field_desc: u8,
) -> Result<(), SessionError> {
    let command = crate::threedm::LowpassFilter {
        function: crate::types::FunctionSelector(4),
        desc_set,
        field_desc,
        ..<crate::threedm::LowpassFilter as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::LowpassFilter(command));
    device.call(&value).map(|_| ())
}

fn send_lowpass_filter_default<T: Transport>(
    device: &mut Device<T>,
    desc_set: u8,
    field_desc: u8,
) -> Result<(), SessionError> {
    let command = crate::threedm::LowpassFilter {
        function: crate::types::FunctionSelector(5),
        desc_set,
        field_desc,
        ..<crate::threedm::LowpassFilter as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::LowpassFilter(command));
    device.call(&value).map(|_| ())
}

fn send_poll_imu_data_poll_imu_data<T: Transport>(
    device: &mut Device<T>,
    option: crate::types::Gx5PollOption,
    descriptors: crate::bounded::BoundedVec<crate::types::Gx5PollDescriptor, 83>,
) -> Result<(), SessionError> {
    let command = crate::threedm::PollImuData {
        option,
        descriptors,
        num_descriptors: descriptors.len() as u8,
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::PollImuData(command));
    device.call(&value).map(|_| ())
}

fn send_poll_gnss_data_poll_gnss_data<T: Transport>(
    device: &mut Device<T>,
    option: crate::types::Gx5PollOption,
    descriptors: crate::bounded::BoundedVec<crate::types::Gx5PollDescriptor, 83>,
) -> Result<(), SessionError> {
    let command = crate::threedm::PollGnssData {
        option,
        descriptors,
        num_descriptors: descriptors.len() as u8,
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::PollGnssData(command));
    device.call(&value).map(|_| ())
}

fn send_poll_filter_data_poll_filter_data<T: Transport>(
    device: &mut Device<T>,
    option: crate::types::Gx5PollOption,
    descriptors: crate::bounded::BoundedVec<crate::types::Gx5PollDescriptor, 83>,
) -> Result<(), SessionError> {
    let command = crate::threedm::PollFilterData {
        option,
        descriptors,
        num_descriptors: descriptors.len() as u8,
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::PollFilterData(command));
    device.call(&value).map(|_| ())
}

fn send_poll_nmea_data_poll_nmea_data<T: Transport>(
    device: &mut Device<T>,
    suppress_ack: bool,
    format_entries: crate::bounded::BoundedVec<crate::types::NmeaMessage, 50>,
) -> Result<(), SessionError> {
    let command = crate::threedm::PollNmeaData {
        suppress_ack,
        format_entries,
        count: format_entries.len() as u8,
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::PollNmeaData(command));
    device.call(&value).map(|_| ())
}

fn send_poll_data_poll_data<T: Transport>(
    device: &mut Device<T>,
    desc_set: u8,
    suppress_ack: bool,
    descriptors: crate::bounded::BoundedVec<u8, 250>,
) -> Result<(), SessionError> {
    let command = crate::threedm::PollData {
        desc_set,
        suppress_ack,
        descriptors,
        num_descriptors: descriptors.len() as u8,
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::PollData(command));
    device.call(&value).map(|_| ())
}

fn send_get_imu_base_rate_get_imu_base_rate<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::threedm::ImuBaseRate, SessionError> {
    let command = crate::threedm::GetImuBaseRate {};
    let value = FieldValue::Threedm(crate::threedm::SetField::GetImuBaseRate(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::ImuBaseRate(r)) => Some(r),
        _ => None,
    })
}

fn send_get_gnss_base_rate_get_gnss_base_rate<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::threedm::GnssBaseRate, SessionError> {
    let command = crate::threedm::GetGnssBaseRate {};
    let value = FieldValue::Threedm(crate::threedm::SetField::GetGnssBaseRate(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::GnssBaseRate(r)) => Some(r),
        _ => None,
    })
}

fn send_get_filter_base_rate_get_filter_base_rate<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::threedm::FilterBaseRate, SessionError> {
    let command = crate::threedm::GetFilterBaseRate {};
    let value = FieldValue::Threedm(crate::threedm::SetField::GetFilterBaseRate(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::FilterBaseRate(r)) => Some(r),
        _ => None,
    })
}

fn send_get_base_rate_get_base_rate<T: Transport>(
    device: &mut Device<T>,
    desc_set: u8,
) -> Result<crate::threedm::BaseRate, SessionError> {
    let command = crate::threedm::GetBaseRate { desc_set };
    let value = FieldValue::Threedm(crate::threedm::SetField::GetBaseRate(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::BaseRate(r)) => Some(r),
        _ => None,
    })
}

/// IMU message format (0x0C, 0x08): one call per function.
#[derive(Debug)]
pub struct ImuMessageFormatCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> ImuMessageFormatCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        descriptors: crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>,
    ) -> Result<(), SessionError> {
        send_imu_message_format_write(self.device, descriptors)
    }
    /// Function `read`: returns the reply field.
    pub fn read(
        self,
        descriptors: Option<crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>>,
    ) -> Result<crate::threedm::ImuMessageFormatResponse, SessionError> {
        send_imu_message_format_read(self.device, descriptors)
    }
    /// Function `save`.
    pub fn save(
        self,
        descriptors: Option<crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>>,
    ) -> Result<(), SessionError> {
        send_imu_message_format_save(self.device, descriptors)
    }
    /// Function `load`.
    pub fn load(
        self,
        descriptors: Option<crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>>,
    ) -> Result<(), SessionError> {
        send_imu_message_format_load(self.device, descriptors)
    }
    /// Function `default`.
    pub fn default(
        self,
        descriptors: Option<crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>>,
    ) -> Result<(), SessionError> {
        send_imu_message_format_default(self.device, descriptors)
    }
}

fn send_imu_message_format_write<T: Transport>(
    device: &mut Device<T>,
    descriptors: crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>,
) -> Result<(), SessionError> {
    let command = crate::threedm::ImuMessageFormat {
        function: crate::types::FunctionSelector(1),
        descriptors: Some(descriptors),
        num_descriptors: Some(descriptors.len() as u8),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::ImuMessageFormat(command));
    device.call(&value).map(|_| ())
}

fn send_imu_message_format_read<T: Transport>(
    device: &mut Device<T>,
    descriptors: Option<crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>>,
) -> Result<crate::threedm::ImuMessageFormatResponse, SessionError> {
    let command = crate::threedm::ImuMessageFormat {
        function: crate::types::FunctionSelector(2),
        descriptors,
        num_descriptors: Some(descriptors.as_ref().map_or(0, |a| a.len()) as u8),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::ImuMessageFormat(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::ImuMessageFormatResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_imu_message_format_save<T: Transport>(
    device: &mut Device<T>,
    descriptors: Option<crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>>,
) -> Result<(), SessionError> {
    let command = crate::threedm::ImuMessageFormat {
        function: crate::types::FunctionSelector(3),
        descriptors,
        num_descriptors: Some(descriptors.as_ref().map_or(0, |a| a.len()) as u8),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::ImuMessageFormat(command));
    device.call(&value).map(|_| ())
}

fn send_imu_message_format_load<T: Transport>(
    device: &mut Device<T>,
    descriptors: Option<crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>>,
) -> Result<(), SessionError> {
    let command = crate::threedm::ImuMessageFormat {
        function: crate::types::FunctionSelector(4),
        descriptors,
        num_descriptors: Some(descriptors.as_ref().map_or(0, |a| a.len()) as u8),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::ImuMessageFormat(command));
    device.call(&value).map(|_| ())
}

fn send_imu_message_format_default<T: Transport>(
    device: &mut Device<T>,
    descriptors: Option<crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>>,
) -> Result<(), SessionError> {
    let command = crate::threedm::ImuMessageFormat {
        function: crate::types::FunctionSelector(5),
        descriptors,
        num_descriptors: Some(descriptors.as_ref().map_or(0, |a| a.len()) as u8),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::ImuMessageFormat(command));
    device.call(&value).map(|_| ())
}

/// GNSS message format (0x0C, 0x09): one call per function.
#[derive(Debug)]
pub struct GnssMessageFormatCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> GnssMessageFormatCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        descriptors: crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>,
    ) -> Result<(), SessionError> {
        send_gnss_message_format_write(self.device, descriptors)
    }
    /// Function `read`: returns the reply field.
    pub fn read(
        self,
        descriptors: Option<crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>>,
    ) -> Result<crate::threedm::GnssMessageFormatResponse, SessionError> {
        send_gnss_message_format_read(self.device, descriptors)
    }
    /// Function `save`.
    pub fn save(
        self,
        descriptors: Option<crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>>,
    ) -> Result<(), SessionError> {
        send_gnss_message_format_save(self.device, descriptors)
    }
    /// Function `load`.
    pub fn load(
        self,
        descriptors: Option<crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>>,
    ) -> Result<(), SessionError> {
        send_gnss_message_format_load(self.device, descriptors)
    }
    /// Function `default`.
    pub fn default(
        self,
        descriptors: Option<crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>>,
    ) -> Result<(), SessionError> {
        send_gnss_message_format_default(self.device, descriptors)
    }
}

fn send_gnss_message_format_write<T: Transport>(
    device: &mut Device<T>,
    descriptors: crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>,
) -> Result<(), SessionError> {
    let command = crate::threedm::GnssMessageFormat {
        function: crate::types::FunctionSelector(1),
        descriptors: Some(descriptors),
        num_descriptors: Some(descriptors.len() as u8),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::GnssMessageFormat(command));
    device.call(&value).map(|_| ())
}

fn send_gnss_message_format_read<T: Transport>(
    device: &mut Device<T>,
    descriptors: Option<crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>>,
) -> Result<crate::threedm::GnssMessageFormatResponse, SessionError> {
    let command = crate::threedm::GnssMessageFormat {
        function: crate::types::FunctionSelector(2),
        descriptors,
        num_descriptors: Some(descriptors.as_ref().map_or(0, |a| a.len()) as u8),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::GnssMessageFormat(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::GnssMessageFormatResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_gnss_message_format_save<T: Transport>(
    device: &mut Device<T>,
    descriptors: Option<crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>>,
) -> Result<(), SessionError> {
    let command = crate::threedm::GnssMessageFormat {
        function: crate::types::FunctionSelector(3),
        descriptors,
        num_descriptors: Some(descriptors.as_ref().map_or(0, |a| a.len()) as u8),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::GnssMessageFormat(command));
    device.call(&value).map(|_| ())
}

fn send_gnss_message_format_load<T: Transport>(
    device: &mut Device<T>,
    descriptors: Option<crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>>,
) -> Result<(), SessionError> {
    let command = crate::threedm::GnssMessageFormat {
        function: crate::types::FunctionSelector(4),
        descriptors,
        num_descriptors: Some(descriptors.as_ref().map_or(0, |a| a.len()) as u8),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::GnssMessageFormat(command));
    device.call(&value).map(|_| ())
}

fn send_gnss_message_format_default<T: Transport>(
    device: &mut Device<T>,
    descriptors: Option<crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>>,
) -> Result<(), SessionError> {
    let command = crate::threedm::GnssMessageFormat {
        function: crate::types::FunctionSelector(5),
        descriptors,
        num_descriptors: Some(descriptors.as_ref().map_or(0, |a| a.len()) as u8),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::GnssMessageFormat(command));
    device.call(&value).map(|_| ())
}

/// Estimation filter message format (0x0C, 0x0A): one call per function.
#[derive(Debug)]
pub struct FilterMessageFormatCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> FilterMessageFormatCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        descriptors: crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>,
    ) -> Result<(), SessionError> {
        send_filter_message_format_write(self.device, descriptors)
    }
    /// Function `read`: returns the reply field.
    pub fn read(
        self,
        descriptors: Option<crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>>,
    ) -> Result<crate::threedm::FilterMessageFormatResponse, SessionError> {
        send_filter_message_format_read(self.device, descriptors)
    }
    /// Function `save`.
    pub fn save(
        self,
        descriptors: Option<crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>>,
    ) -> Result<(), SessionError> {
        send_filter_message_format_save(self.device, descriptors)
    }
    /// Function `load`.
    pub fn load(
        self,
        descriptors: Option<crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>>,
    ) -> Result<(), SessionError> {
        send_filter_message_format_load(self.device, descriptors)
    }
    /// Function `default`.
    pub fn default(
        self,
        descriptors: Option<crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>>,
    ) -> Result<(), SessionError> {
        send_filter_message_format_default(self.device, descriptors)
    }
}

fn send_filter_message_format_write<T: Transport>(
    device: &mut Device<T>,
    descriptors: crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>,
) -> Result<(), SessionError> {
    let command = crate::threedm::FilterMessageFormat {
        function: crate::types::FunctionSelector(1),
        descriptors: Some(descriptors),
        num_descriptors: Some(descriptors.len() as u8),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::FilterMessageFormat(command));
    device.call(&value).map(|_| ())
}

fn send_filter_message_format_read<T: Transport>(
    device: &mut Device<T>,
    descriptors: Option<crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>>,
) -> Result<crate::threedm::FilterMessageFormatResponse, SessionError> {
    let command = crate::threedm::FilterMessageFormat {
        function: crate::types::FunctionSelector(2),
        descriptors,
        num_descriptors: Some(descriptors.as_ref().map_or(0, |a| a.len()) as u8),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::FilterMessageFormat(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::FilterMessageFormatResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_filter_message_format_save<T: Transport>(
    device: &mut Device<T>,
    descriptors: Option<crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>>,
) -> Result<(), SessionError> {
    let command = crate::threedm::FilterMessageFormat {
        function: crate::types::FunctionSelector(3),
        descriptors,
        num_descriptors: Some(descriptors.as_ref().map_or(0, |a| a.len()) as u8),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::FilterMessageFormat(command));
    device.call(&value).map(|_| ())
}

fn send_filter_message_format_load<T: Transport>(
    device: &mut Device<T>,
    descriptors: Option<crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>>,
) -> Result<(), SessionError> {
    let command = crate::threedm::FilterMessageFormat {
        function: crate::types::FunctionSelector(4),
        descriptors,
        num_descriptors: Some(descriptors.as_ref().map_or(0, |a| a.len()) as u8),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::FilterMessageFormat(command));
    device.call(&value).map(|_| ())
}

fn send_filter_message_format_default<T: Transport>(
    device: &mut Device<T>,
    descriptors: Option<crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>>,
) -> Result<(), SessionError> {
    let command = crate::threedm::FilterMessageFormat {
        function: crate::types::FunctionSelector(5),
        descriptors,
        num_descriptors: Some(descriptors.as_ref().map_or(0, |a| a.len()) as u8),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::FilterMessageFormat(command));
    device.call(&value).map(|_| ())
}

/// NMEA message format (0x0C, 0x0C): one call per function.
#[derive(Debug)]
pub struct NmeaMessageFormatCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> NmeaMessageFormatCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        format_entries: crate::bounded::BoundedVec<crate::types::NmeaMessage, 50>,
    ) -> Result<(), SessionError> {
        send_nmea_message_format_write(self.device, format_entries)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::threedm::NmeaMessageFormatResponse, SessionError> {
        send_nmea_message_format_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_nmea_message_format_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_nmea_message_format_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_nmea_message_format_default(self.device)
    }
}

fn send_nmea_message_format_write<T: Transport>(
    device: &mut Device<T>,
    format_entries: crate::bounded::BoundedVec<crate::types::NmeaMessage, 50>,
) -> Result<(), SessionError> {
    let command = crate::threedm::NmeaMessageFormat {
        function: crate::types::FunctionSelector(1),
        format_entries: Some(format_entries),
        count: Some(format_entries.len() as u8),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::NmeaMessageFormat(command));
    device.call(&value).map(|_| ())
}

fn send_nmea_message_format_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::threedm::NmeaMessageFormatResponse, SessionError> {
    let command = crate::threedm::NmeaMessageFormat {
        function: crate::types::FunctionSelector(2),
        ..<crate::threedm::NmeaMessageFormat as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::NmeaMessageFormat(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::NmeaMessageFormatResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_nmea_message_format_save<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::threedm::NmeaMessageFormat {
        function: crate::types::FunctionSelector(3),
        ..<crate::threedm::NmeaMessageFormat as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::NmeaMessageFormat(command));
    device.call(&value).map(|_| ())
}

fn send_nmea_message_format_load<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::threedm::NmeaMessageFormat {
        function: crate::types::FunctionSelector(4),
        ..<crate::threedm::NmeaMessageFormat as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::NmeaMessageFormat(command));
    device.call(&value).map(|_| ())
}

fn send_nmea_message_format_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::threedm::NmeaMessageFormat {
        function: crate::types::FunctionSelector(5),
        ..<crate::threedm::NmeaMessageFormat as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::NmeaMessageFormat(command));
    device.call(&value).map(|_| ())
}

/// Message format (0x0C, 0x0F): one call per function.
#[derive(Debug)]
pub struct MessageFormatCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> MessageFormatCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        desc_set: u8,
        descriptors: crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>,
    ) -> Result<(), SessionError> {
        send_message_format_write(self.device, desc_set, descriptors)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self, desc_set: u8) -> Result<crate::threedm::MessageFormatResponse, SessionError> {
        send_message_format_read(self.device, desc_set)
    }
    /// Function `save`.
    pub fn save(self, desc_set: u8) -> Result<(), SessionError> {
        send_message_format_save(self.device, desc_set)
    }
    /// Function `load`.
    pub fn load(self, desc_set: u8) -> Result<(), SessionError> {
        send_message_format_load(self.device, desc_set)
    }
    /// Function `default`.
    pub fn default(self, desc_set: u8) -> Result<(), SessionError> {
        send_message_format_default(self.device, desc_set)
    }
}

fn send_message_format_write<T: Transport>(
    device: &mut Device<T>,
    desc_set: u8,
    descriptors: crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>,
) -> Result<(), SessionError> {
    let command = crate::threedm::MessageFormat {
        function: crate::types::FunctionSelector(1),
        desc_set,
        descriptors: Some(descriptors),
        num_descriptors: Some(descriptors.len() as u8),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::MessageFormat(command));
    device.call(&value).map(|_| ())
}

fn send_message_format_read<T: Transport>(
    device: &mut Device<T>,
    desc_set: u8,
) -> Result<crate::threedm::MessageFormatResponse, SessionError> {
    let command = crate::threedm::MessageFormat {
        function: crate::types::FunctionSelector(2),
        desc_set,
        ..<crate::threedm::MessageFormat as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::MessageFormat(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::MessageFormatResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_message_format_save<T: Transport>(
    device: &mut Device<T>,
    desc_set: u8,
) -> Result<(), SessionError> {
    let command = crate::threedm::MessageFormat {
        function: crate::types::FunctionSelector(3),
        desc_set,
        ..<crate::threedm::MessageFormat as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::MessageFormat(command));
    device.call(&value).map(|_| ())
}

fn send_message_format_load<T: Transport>(
    device: &mut Device<T>,
    desc_set: u8,
) -> Result<(), SessionError> {
    let command = crate::threedm::MessageFormat {
        function: crate::types::FunctionSelector(4),
        desc_set,
        ..<crate::threedm::MessageFormat as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::MessageFormat(command));
    device.call(&value).map(|_| ())
}

fn send_message_format_default<T: Transport>(
    device: &mut Device<T>,
    desc_set: u8,
) -> Result<(), SessionError> {
    let command = crate::threedm::MessageFormat {
        function: crate::types::FunctionSelector(5),
        desc_set,
        ..<crate::threedm::MessageFormat as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::MessageFormat(command));
    device.call(&value).map(|_| ())
}

fn send_factory_streaming_factory_streaming<T: Transport>(
    device: &mut Device<T>,
    action: crate::types::FactoryStreamingAction,
    reserved: u8,
) -> Result<(), SessionError> {
    let command = crate::threedm::FactoryStreaming { action, reserved };
    let value = FieldValue::Threedm(crate::threedm::SetField::FactoryStreaming(command));
    device.call(&value).map(|_| ())
}

/// Data stream control (0x0C, 0x11): one call per function.
#[derive(Debug)]
pub struct DataStreamControlCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> DataStreamControlCommand<'d, T> {
    /// Function `write` (layout for gx5_45).
    pub fn write_gx5_45(
        self,
        device_selector: crate::types::Gx5StreamSelector,
        enable: u8,
    ) -> Result<(), SessionError> {
        send_data_stream_control_write_gx5_45(self.device, device_selector, enable)
    }
    /// Function `write` (layout for cv7_ins).
    pub fn write_cv7_ins(self, desc_set: u8, enable: bool) -> Result<(), SessionError> {
        send_data_stream_control_write_cv7_ins(self.device, desc_set, enable)
    }
    /// Function `read` (layout for gx5_45): returns the reply field.
    pub fn read_gx5_45(
        self,
        device_selector: crate::types::Gx5StreamSelector,
        enable: Option<u8>,
    ) -> Result<crate::threedm::DataStreamControlResponse, SessionError> {
        send_data_stream_control_read_gx5_45(self.device, device_selector, enable)
    }
    /// Function `read` (layout for cv7_ins): returns the reply field.
    pub fn read_cv7_ins(
        self,
        desc_set: u8,
    ) -> Result<crate::threedm::DataStreamControlResponse, SessionError> {
        send_data_stream_control_read_cv7_ins(self.device, desc_set)
    }
    /// Function `save` (layout for gx5_45).
    pub fn save_gx5_45(
        self,
        device_selector: crate::types::Gx5StreamSelector,
        enable: Option<u8>,
    ) -> Result<(), SessionError> {
        send_data_stream_control_save_gx5_45(self.device, device_selector, enable)
    }
    /// Function `save` (layout for cv7_ins).
    pub fn save_cv7_ins(self, desc_set: u8) -> Result<(), SessionError> {
        send_data_stream_control_save_cv7_ins(self.device, desc_set)
    }
    /// Function `load` (layout for gx5_45).
    pub fn load_gx5_45(
        self,
        device_selector: crate::types::Gx5StreamSelector,
        enable: Option<u8>,
    ) -> Result<(), SessionError> {
        send_data_stream_control_load_gx5_45(self.device, device_selector, enable)
    }
    /// Function `load` (layout for cv7_ins).
    pub fn load_cv7_ins(self, desc_set: u8) -> Result<(), SessionError> {
        send_data_stream_control_load_cv7_ins(self.device, desc_set)
    }
    /// Function `default` (layout for gx5_45).
    pub fn default_gx5_45(
        self,
        device_selector: crate::types::Gx5StreamSelector,
        enable: Option<u8>,
    ) -> Result<(), SessionError> {
        send_data_stream_control_default_gx5_45(self.device, device_selector, enable)
    }
    /// Function `default` (layout for cv7_ins).
    pub fn default_cv7_ins(self, desc_set: u8) -> Result<(), SessionError> {
        send_data_stream_control_default_cv7_ins(self.device, desc_set)
    }
}

fn send_data_stream_control_write_gx5_45<T: Transport>(
    device: &mut Device<T>,
    device_selector: crate::types::Gx5StreamSelector,
    enable: u8,
) -> Result<(), SessionError> {
    let command = crate::threedm::DataStreamControlGx5_45 {
        function: crate::types::FunctionSelector(1),
        device_selector,
        enable: Some(enable),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::DataStreamControl(
        crate::threedm::DataStreamControl::Gx5_45(command),
    ));
    device.call(&value).map(|_| ())
}

fn send_data_stream_control_write_cv7_ins<T: Transport>(
    device: &mut Device<T>,
    desc_set: u8,
    enable: bool,
) -> Result<(), SessionError> {
    let command = crate::threedm::DataStreamControlCv7Ins {
        function: crate::types::FunctionSelector(1),
        desc_set,
        enable: Some(enable),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::DataStreamControl(
        crate::threedm::DataStreamControl::Cv7Ins(command),
    ));
    device.call(&value).map(|_| ())
}

fn send_data_stream_control_read_gx5_45<T: Transport>(
    device: &mut Device<T>,
    device_selector: crate::types::Gx5StreamSelector,
    enable: Option<u8>,
) -> Result<crate::threedm::DataStreamControlResponse, SessionError> {
    let command = crate::threedm::DataStreamControlGx5_45 {
        function: crate::types::FunctionSelector(2),
        device_selector,
        enable,
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::DataStreamControl(
        crate::threedm::DataStreamControl::Gx5_45(command),
    ));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::DataStreamControlResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_data_stream_control_read_cv7_ins<T: Transport>(
    device: &mut Device<T>,
    desc_set: u8,
) -> Result<crate::threedm::DataStreamControlResponse, SessionError> {
    let command = crate::threedm::DataStreamControlCv7Ins {
        function: crate::types::FunctionSelector(2),
        desc_set,
        ..<crate::threedm::DataStreamControlCv7Ins as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::DataStreamControl(
        crate::threedm::DataStreamControl::Cv7Ins(command),
    ));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::DataStreamControlResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_data_stream_control_save_gx5_45<T: Transport>(
    device: &mut Device<T>,
    device_selector: crate::types::Gx5StreamSelector,
    enable: Option<u8>,
) -> Result<(), SessionError> {
    let command = crate::threedm::DataStreamControlGx5_45 {
        function: crate::types::FunctionSelector(3),
        device_selector,
        enable,
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::DataStreamControl(
        crate::threedm::DataStreamControl::Gx5_45(command),
    ));
    device.call(&value).map(|_| ())
}

fn send_data_stream_control_save_cv7_ins<T: Transport>(
    device: &mut Device<T>,
    desc_set: u8,
) -> Result<(), SessionError> {
    let command = crate::threedm::DataStreamControlCv7Ins {
        function: crate::types::FunctionSelector(3),
        desc_set,
        ..<crate::threedm::DataStreamControlCv7Ins as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::DataStreamControl(
        crate::threedm::DataStreamControl::Cv7Ins(command),
    ));
    device.call(&value).map(|_| ())
}

fn send_data_stream_control_load_gx5_45<T: Transport>(
    device: &mut Device<T>,
    device_selector: crate::types::Gx5StreamSelector,
    enable: Option<u8>,
) -> Result<(), SessionError> {
    let command = crate::threedm::DataStreamControlGx5_45 {
        function: crate::types::FunctionSelector(4),
        device_selector,
        enable,
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::DataStreamControl(
        crate::threedm::DataStreamControl::Gx5_45(command),
    ));
    device.call(&value).map(|_| ())
}

fn send_data_stream_control_load_cv7_ins<T: Transport>(
    device: &mut Device<T>,
    desc_set: u8,
) -> Result<(), SessionError> {
    let command = crate::threedm::DataStreamControlCv7Ins {
        function: crate::types::FunctionSelector(4),
        desc_set,
        ..<crate::threedm::DataStreamControlCv7Ins as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::DataStreamControl(
        crate::threedm::DataStreamControl::Cv7Ins(command),
    ));
    device.call(&value).map(|_| ())
}

fn send_data_stream_control_default_gx5_45<T: Transport>(
    device: &mut Device<T>,
    device_selector: crate::types::Gx5StreamSelector,
    enable: Option<u8>,
) -> Result<(), SessionError> {
    let command = crate::threedm::DataStreamControlGx5_45 {
        function: crate::types::FunctionSelector(5),
        device_selector,
        enable,
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::DataStreamControl(
        crate::threedm::DataStreamControl::Gx5_45(command),
    ));
    device.call(&value).map(|_| ())
}

fn send_data_stream_control_default_cv7_ins<T: Transport>(
    device: &mut Device<T>,
    desc_set: u8,
) -> Result<(), SessionError> {
    let command = crate::threedm::DataStreamControlCv7Ins {
        function: crate::types::FunctionSelector(5),
        desc_set,
        ..<crate::threedm::DataStreamControlCv7Ins as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::DataStreamControl(
        crate::threedm::DataStreamControl::Cv7Ins(command),
    ));
    device.call(&value).map(|_| ())
}

fn send_raw_rtcm_message_raw_rtcm_message<T: Transport>(
    device: &mut Device<T>,
    data: crate::bounded::BoundedVec<u8, 253>,
) -> Result<(), SessionError> {
    let command = crate::threedm::RawRtcmMessage { data };
    let value = FieldValue::Threedm(crate::threedm::SetField::RawRtcmMessage(command));
    device.call(&value).map(|_| ())
}

/// GNSS constellation settings (0x0C, 0x21): one call per function.
#[derive(Debug)]
pub struct GnssConstellationSettingsCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> GnssConstellationSettingsCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        max_channels: u16,
        settings: crate::bounded::BoundedVec<crate::types::ConstellationSettings, 41>,
    ) -> Result<(), SessionError> {
        send_gnss_constellation_settings_write(self.device, max_channels, settings)
    }
    /// Function `read`: returns the reply field.
    pub fn read(
        self,
        max_channels: Option<u16>,
        settings: Option<crate::bounded::BoundedVec<crate::types::ConstellationSettings, 41>>,
    ) -> Result<crate::threedm::GnssConstellationSettingsResponse, SessionError> {
        send_gnss_constellation_settings_read(self.device, max_channels, settings)
    }
    /// Function `save`.
    pub fn save(
        self,
        max_channels: Option<u16>,
        settings: Option<crate::bounded::BoundedVec<crate::types::ConstellationSettings, 41>>,
    ) -> Result<(), SessionError> {
        send_gnss_constellation_settings_save(self.device, max_channels, settings)
    }
    /// Function `load`.
    pub fn load(
        self,
        max_channels: Option<u16>,
        settings: Option<crate::bounded::BoundedVec<crate::types::ConstellationSettings, 41>>,
    ) -> Result<(), SessionError> {
        send_gnss_constellation_settings_load(self.device, max_channels, settings)
    }
    /// Function `default`.
    pub fn default(
        self,
        max_channels: Option<u16>,
        settings: Option<crate::bounded::BoundedVec<crate::types::ConstellationSettings, 41>>,
    ) -> Result<(), SessionError> {
        send_gnss_constellation_settings_default(self.device, max_channels, settings)
    }
}

fn send_gnss_constellation_settings_write<T: Transport>(
    device: &mut Device<T>,
    max_channels: u16,
    settings: crate::bounded::BoundedVec<crate::types::ConstellationSettings, 41>,
) -> Result<(), SessionError> {
    let command = crate::threedm::GnssConstellationSettings {
        function: crate::types::FunctionSelector(1),
        max_channels: Some(max_channels),
        settings: Some(settings),
        config_count: Some(settings.len() as u8),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::GnssConstellationSettings(command));
    device.call(&value).map(|_| ())
}

fn send_gnss_constellation_settings_read<T: Transport>(
    device: &mut Device<T>,
    max_channels: Option<u16>,
    settings: Option<crate::bounded::BoundedVec<crate::types::ConstellationSettings, 41>>,
) -> Result<crate::threedm::GnssConstellationSettingsResponse, SessionError> {
    let command = crate::threedm::GnssConstellationSettings {
        function: crate::types::FunctionSelector(2),
        max_channels,
        settings,
        config_count: Some(settings.as_ref().map_or(0, |a| a.len()) as u8),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::GnssConstellationSettings(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::GnssConstellationSettingsResponse(r)) => {
            Some(r)
        }
        _ => None,
    })
}

fn send_gnss_constellation_settings_save<T: Transport>(
    device: &mut Device<T>,
    max_channels: Option<u16>,
    settings: Option<crate::bounded::BoundedVec<crate::types::ConstellationSettings, 41>>,
) -> Result<(), SessionError> {
    let command = crate::threedm::GnssConstellationSettings {
        function: crate::types::FunctionSelector(3),
        max_channels,
        settings,
        config_count: Some(settings.as_ref().map_or(0, |a| a.len()) as u8),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::GnssConstellationSettings(command));
    device.call(&value).map(|_| ())
}

fn send_gnss_constellation_settings_load<T: Transport>(
    device: &mut Device<T>,
    max_channels: Option<u16>,
    settings: Option<crate::bounded::BoundedVec<crate::types::ConstellationSettings, 41>>,
) -> Result<(), SessionError> {
    let command = crate::threedm::GnssConstellationSettings {
        function: crate::types::FunctionSelector(4),
        max_channels,
        settings,
        config_count: Some(settings.as_ref().map_or(0, |a| a.len()) as u8),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::GnssConstellationSettings(command));
    device.call(&value).map(|_| ())
}

fn send_gnss_constellation_settings_default<T: Transport>(
    device: &mut Device<T>,
    max_channels: Option<u16>,
    settings: Option<crate::bounded::BoundedVec<crate::types::ConstellationSettings, 41>>,
) -> Result<(), SessionError> {
    let command = crate::threedm::GnssConstellationSettings {
        function: crate::types::FunctionSelector(5),
        max_channels,
        settings,
        config_count: Some(settings.as_ref().map_or(0, |a| a.len()) as u8),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::GnssConstellationSettings(command));
    device.call(&value).map(|_| ())
}

/// GNSS SBAS settings (0x0C, 0x22): one call per function.
#[derive(Debug)]
pub struct GnssSbasSettingsCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> GnssSbasSettingsCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        enable_sbas: u8,
        sbas_options: crate::types::SbasOptions,
        included_prns: crate::bounded::BoundedVec<u16, 124>,
    ) -> Result<(), SessionError> {
        send_gnss_sbas_settings_write(self.device, enable_sbas, sbas_options, included_prns)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::threedm::GnssSbasSettingsResponse, SessionError> {
        send_gnss_sbas_settings_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_gnss_sbas_settings_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_gnss_sbas_settings_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_gnss_sbas_settings_default(self.device)
    }
}

fn send_gnss_sbas_settings_write<T: Transport>(
    device: &mut Device<T>,
    enable_sbas: u8,
    sbas_options: crate::types::SbasOptions,
    included_prns: crate::bounded::BoundedVec<u16, 124>,
) -> Result<(), SessionError> {
    let command = crate::threedm::GnssSbasSettings {
        function: crate::types::FunctionSelector(1),
        enable_sbas: Some(enable_sbas),
        sbas_options: Some(sbas_options),
        included_prns: Some(included_prns),
        num_included_prns: Some(included_prns.len() as u8),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::GnssSbasSettings(command));
    device.call(&value).map(|_| ())
}

fn send_gnss_sbas_settings_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::threedm::GnssSbasSettingsResponse, SessionError> {
    let command = crate::threedm::GnssSbasSettings {
        function: crate::types::FunctionSelector(2),
        ..<crate::threedm::GnssSbasSettings as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::GnssSbasSettings(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::GnssSbasSettingsResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_gnss_sbas_settings_save<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::threedm::GnssSbasSettings {
        function: crate::types::FunctionSelector(3),
        ..<crate::threedm::GnssSbasSettings as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::GnssSbasSettings(command));
    device.call(&value).map(|_| ())
}

fn send_gnss_sbas_settings_load<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::threedm::GnssSbasSettings {
        function: crate::types::FunctionSelector(4),
        ..<crate::threedm::GnssSbasSettings as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::GnssSbasSettings(command));
    device.call(&value).map(|_| ())
}

fn send_gnss_sbas_settings_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::threedm::GnssSbasSettings {
        function: crate::types::FunctionSelector(5),
        ..<crate::threedm::GnssSbasSettings as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::GnssSbasSettings(command));
    device.call(&value).map(|_| ())
}

/// GNSS assisted fix control (0x0C, 0x23): one call per function.
#[derive(Debug)]
pub struct GnssAssistedFixControlCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> GnssAssistedFixControlCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        option: crate::types::AssistedFixOption,
        flags: u8,
    ) -> Result<(), SessionError> {
        send_gnss_assisted_fix_control_write(self.device, option, flags)
    }
    /// Function `read`: returns the reply field.
    pub fn read(
        self,
        option: Option<crate::types::AssistedFixOption>,
        flags: Option<u8>,
    ) -> Result<crate::threedm::GnssAssistedFixControlResponse, SessionError> {
        send_gnss_assisted_fix_control_read(self.device, option, flags)
    }
    /// Function `save`.
    pub fn save(
        self,
        option: Option<crate::types::AssistedFixOption>,
        flags: Option<u8>,
    ) -> Result<(), SessionError> {
        send_gnss_assisted_fix_control_save(self.device, option, flags)
    }
    /// Function `load`.
    pub fn load(
        self,
        option: Option<crate::types::AssistedFixOption>,
        flags: Option<u8>,
    ) -> Result<(), SessionError> {
        send_gnss_assisted_fix_control_load(self.device, option, flags)
    }
    /// Function `default`.
    pub fn default(
        self,
        option: Option<crate::types::AssistedFixOption>,
        flags: Option<u8>,
    ) -> Result<(), SessionError> {
        send_gnss_assisted_fix_control_default(self.device, option, flags)
    }
}

fn send_gnss_assisted_fix_control_write<T: Transport>(
    device: &mut Device<T>,
    option: crate::types::AssistedFixOption,
    flags: u8,
) -> Result<(), SessionError> {
    let command = crate::threedm::GnssAssistedFixControl {
        function: crate::types::FunctionSelector(1),
        option: Some(option),
        flags: Some(flags),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::GnssAssistedFixControl(command));
    device.call(&value).map(|_| ())
}

fn send_gnss_assisted_fix_control_read<T: Transport>(
    device: &mut Device<T>,
    option: Option<crate::types::AssistedFixOption>,
    flags: Option<u8>,
) -> Result<crate::threedm::GnssAssistedFixControlResponse, SessionError> {
    let command = crate::threedm::GnssAssistedFixControl {
        function: crate::types::FunctionSelector(2),
        option,
        flags,
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::GnssAssistedFixControl(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::GnssAssistedFixControlResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_gnss_assisted_fix_control_save<T: Transport>(
    device: &mut Device<T>,
    option: Option<crate::types::AssistedFixOption>,
    flags: Option<u8>,
) -> Result<(), SessionError> {
    let command = crate::threedm::GnssAssistedFixControl {
        function: crate::types::FunctionSelector(3),
        option,
        flags,
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::GnssAssistedFixControl(command));
    device.call(&value).map(|_| ())
}

fn send_gnss_assisted_fix_control_load<T: Transport>(
    device: &mut Device<T>,
    option: Option<crate::types::AssistedFixOption>,
    flags: Option<u8>,
) -> Result<(), SessionError> {
    let command = crate::threedm::GnssAssistedFixControl {
        function: crate::types::FunctionSelector(4),
        option,
        flags,
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::GnssAssistedFixControl(command));
    device.call(&value).map(|_| ())
}

fn send_gnss_assisted_fix_control_default<T: Transport>(
    device: &mut Device<T>,
    option: Option<crate::types::AssistedFixOption>,
    flags: Option<u8>,
) -> Result<(), SessionError> {
    let command = crate::threedm::GnssAssistedFixControl {
        function: crate::types::FunctionSelector(5),
        option,
        flags,
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::GnssAssistedFixControl(command));
    device.call(&value).map(|_| ())
}

/// GNSS assist time update (0x0C, 0x24): one call per function.
#[derive(Debug)]
pub struct GnssAssistTimeUpdateCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> GnssAssistTimeUpdateCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, tow: f64, week_number: u16, accuracy: f32) -> Result<(), SessionError> {
        send_gnss_assist_time_update_write(self.device, tow, week_number, accuracy)
    }
    /// Function `read`: returns the reply field.
    pub fn read(
        self,
        tow: Option<f64>,
        week_number: Option<u16>,
        accuracy: Option<f32>,
    ) -> Result<crate::threedm::GnssAssistTimeUpdateResponse, SessionError> {
        send_gnss_assist_time_update_read(self.device, tow, week_number, accuracy)
    }
}

fn send_gnss_assist_time_update_write<T: Transport>(
    device: &mut Device<T>,
    tow: f64,
    week_number: u16,
    accuracy: f32,
) -> Result<(), SessionError> {
    let command = crate::threedm::GnssAssistTimeUpdate {
        function: crate::types::FunctionSelector(1),
        tow: Some(tow),
        week_number: Some(week_number),
        accuracy: Some(accuracy),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::GnssAssistTimeUpdate(command));
    device.call(&value).map(|_| ())
}

fn send_gnss_assist_time_update_read<T: Transport>(
    device: &mut Device<T>,
    tow: Option<f64>,
    week_number: Option<u16>,
    accuracy: Option<f32>,
) -> Result<crate::threedm::GnssAssistTimeUpdateResponse, SessionError> {
    let command = crate::threedm::GnssAssistTimeUpdate {
        function: crate::types::FunctionSelector(2),
        tow,
        week_number,
        accuracy,
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::GnssAssistTimeUpdate(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::GnssAssistTimeUpdateResponse(r)) => Some(r),
        _ => None,
    })
}

/// PPS source control (0x0C, 0x28): one call per function.
#[derive(Debug)]
pub struct PpsSourceCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> PpsSourceCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, source: crate::types::PpsSource) -> Result<(), SessionError> {
        send_pps_source_write(self.device, source)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::threedm::PpsSourceResponse, SessionError> {
        send_pps_source_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_pps_source_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_pps_source_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_pps_source_default(self.device)
    }
}

fn send_pps_source_write<T: Transport>(
    device: &mut Device<T>,
    source: crate::types::PpsSource,
) -> Result<(), SessionError> {
    let command = crate::threedm::PpsSource {
        function: crate::types::FunctionSelector(1),
        source: Some(source),
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::PpsSource(command));
    device.call(&value).map(|_| ())
}

fn send_pps_source_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::threedm::PpsSourceResponse, SessionError> {
    let command = crate::threedm::PpsSource {
        function: crate::types::FunctionSelector(2),
        ..<crate::threedm::PpsSource as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::PpsSource(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::PpsSourceResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_pps_source_save<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::threedm::PpsSource {
        function: crate::types::FunctionSelector(3),
        ..<crate::threedm::PpsSource as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::PpsSource(command));
    device.call(&value).map(|_| ())
}

fn send_pps_source_load<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::threedm::PpsSource {
        function: crate::types::FunctionSelector(4),
        ..<crate::threedm::PpsSource as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::PpsSource(command));
    device.call(&value).map(|_| ())
}

fn send_pps_source_default<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::threedm::PpsSource {
        function: crate::types::FunctionSelector(5),
        ..<crate::threedm::PpsSource as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::PpsSource(command));
    device.call(&value).map(|_| ())
}

fn send_get_supported_events_get_supported_events<T: Transport>(
    device: &mut Device<T>,
    query: crate::types::SupportedEventsQuery,
) -> Result<crate::threedm::SupportedEvents, SessionError> {
    let command = crate::threedm::GetSupportedEvents { query };
    let value = FieldValue::Threedm(crate::threedm::SetField::GetSupportedEvents(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::SupportedEvents(r)) => Some(r),
        _ => None,
    })
}

fn send_device_status_device_status<T: Transport>(
    device: &mut Device<T>,
    model_number: u16,
    status_selector: crate::types::DeviceStatusSelector,
) -> Result<crate::threedm::DeviceStatusResponse, SessionError> {
    let command = crate::threedm::DeviceStatus {
        model_number,
        status_selector,
    };
    let value = FieldValue::Threedm(crate::threedm::SetField::DeviceStatus(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Threedm(crate::threedm::SetField::DeviceStatusResponse(r)) => Some(r),
        _ => None,
    })
}

impl<T: Transport> Device<T> {
    /// Commands of set 0x0D (Filter Command Set).
    pub fn filter(&mut self) -> FilterCommands<'_, T> {
        FilterCommands { device: self }
    }
}

/// Commands of set 0x0D (Filter Command Set), bound to a [`Device`].
#[derive(Debug)]
pub struct FilterCommands<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> FilterCommands<'d, T> {
    /// Reset filter (0x01). Sends `reset_filter`.
    pub fn reset_filter(self) -> Result<(), SessionError> {
        send_reset_filter_reset_filter(self.device)
    }
    /// Set initial attitude (0x02). Sends `set_initial_attitude`.
    pub fn set_initial_attitude(
        self,
        roll: f32,
        pitch: f32,
        heading: f32,
    ) -> Result<(), SessionError> {
        send_set_initial_attitude_set_initial_attitude(self.device, roll, pitch, heading)
    }
    /// Set initial heading (0x03). Sends `set_initial_heading`.
    pub fn set_initial_heading(self, heading: f32) -> Result<(), SessionError> {
        send_set_initial_heading_set_initial_heading(self.device, heading)
    }
    /// Run navigation filter (0x05). Sends `run_filter`.
    pub fn run_filter(self) -> Result<(), SessionError> {
        send_run_filter_run_filter(self.device)
    }
    /// Vehicle dynamics mode (0x10).
    pub fn vehicle_dynamics_mode(self) -> VehicleDynamicsModeCommand<'d, T> {
        VehicleDynamicsModeCommand {
            device: self.device,
        }
    }
    /// Sensor to vehicle frame transformation (0x11).
    pub fn sensor_to_vehicle_transform(self) -> SensorToVehicleTransformCommand<'d, T> {
        SensorToVehicleTransformCommand {
            device: self.device,
        }
    }
    /// Sensor to vehicle frame offset (0x12).
    pub fn sensor_to_vehicle_offset(self) -> SensorToVehicleOffsetCommand<'d, T> {
        SensorToVehicleOffsetCommand {
            device: self.device,
        }
    }
    /// GNSS antenna offset (0x13).
    pub fn antenna_offset(self) -> AntennaOffsetCommand<'d, T> {
        AntennaOffsetCommand {
            device: self.device,
        }
    }
    /// Estimation control flags (0x14).
    pub fn estimation_control(self) -> EstimationControlCommand<'d, T> {
        EstimationControlCommand {
            device: self.device,
        }
    }
    /// GNSS source control (0x15).
    pub fn gnss_source_control(self) -> GnssSourceControlCommand<'d, T> {
        GnssSourceControlCommand {
            device: self.device,
        }
    }
    /// External GNSS update (0x16). Sends `external_gnss_update`.
    pub fn external_gnss_update(
        self,
        gps_tow: f64,
        gps_week: u16,
        latitude: f64,
        longitude: f64,
        height: f64,
        velocity: [f32; 3],
        position_uncertainty: [f32; 3],
        velocity_uncertainty: [f32; 3],
    ) -> Result<(), SessionError> {
        send_external_gnss_update_external_gnss_update(
            self.device,
            gps_tow,
            gps_week,
            latitude,
            longitude,
            height,
            velocity,
            position_uncertainty,
            velocity_uncertainty,
        )
    }
    /// External heading update (0x17). Sends `external_heading_update`.
    pub fn external_heading_update(
        self,
        heading: f32,
        heading_uncertainty: f32,
        r#type: crate::types::ExternalHeadingType,
    ) -> Result<(), SessionError> {
        send_external_heading_update_external_heading_update(
            self.device,
            heading,
            heading_uncertainty,
            r#type,
        )
    }
    /// Heading update control (0x18).
    pub fn heading_update_control(self) -> HeadingUpdateControlCommand<'d, T> {
        HeadingUpdateControlCommand {
            device: self.device,
        }
    }
    /// Auto-initialization control (0x19).
    pub fn auto_init_control(self) -> AutoInitControlCommand<'d, T> {
        AutoInitControlCommand {
            device: self.device,
        }
    }
    /// Accelerometer noise standard deviation (0x1A).
    pub fn accel_noise(self) -> AccelNoiseCommand<'d, T> {
        AccelNoiseCommand {
            device: self.device,
        }
    }
    /// Gyroscope noise standard deviation (0x1B).
    pub fn gyro_noise(self) -> GyroNoiseCommand<'d, T> {
        GyroNoiseCommand {
            device: self.device,
        }
    }
    /// Accelerometer bias model parameters (0x1C).
    pub fn accel_bias_model(self) -> AccelBiasModelCommand<'d, T> {
        AccelBiasModelCommand {
            device: self.device,
        }
    }
    /// Gyroscope bias model parameters (0x1D).
    pub fn gyro_bias_model(self) -> GyroBiasModelCommand<'d, T> {
        GyroBiasModelCommand {
            device: self.device,
        }
    }
    /// Zero velocity update (ZUPT) control (0x1E).
    pub fn zupt_control(self) -> ZuptControlCommand<'d, T> {
        ZuptControlCommand {
            device: self.device,
        }
    }
    /// External heading update with timestamp (0x1F). Sends `external_heading_update_with_time`.
    pub fn external_heading_update_with_time(
        self,
        gps_tow: f64,
        gps_week: u16,
        heading: f32,
        heading_uncertainty: f32,
        r#type: crate::types::ExternalHeadingType,
    ) -> Result<(), SessionError> {
        send_external_heading_update_with_time_external_heading_update_with_time(
            self.device,
            gps_tow,
            gps_week,
            heading,
            heading_uncertainty,
            r#type,
        )
    }
    /// Zero angular rate update control (0x20).
    pub fn zero_angular_rate_update_control(self) -> ZeroAngularRateUpdateControlCommand<'d, T> {
        ZeroAngularRateUpdateControlCommand {
            device: self.device,
        }
    }
    /// Tare orientation (0x21).
    pub fn tare_orientation(self) -> TareOrientationCommand<'d, T> {
        TareOrientationCommand {
            device: self.device,
        }
    }
    /// Commanded zero velocity update (0x22). Sends `commanded_zupt`.
    pub fn commanded_zupt(self) -> Result<(), SessionError> {
        send_commanded_zupt_commanded_zupt(self.device)
    }
    /// Commanded zero angular rate update (0x23). Sends `commanded_zero_angular_rate_update`.
    pub fn commanded_zero_angular_rate_update(self) -> Result<(), SessionError> {
        send_commanded_zero_angular_rate_update_commanded_zero_angular_rate_update(self.device)
    }
    /// Magnetometer capture auto calibration (0x27).
    pub fn mag_capture_auto_calibration(self) -> MagCaptureAutoCalibrationCommand<'d, T> {
        MagCaptureAutoCalibrationCommand {
            device: self.device,
        }
    }
    /// Gravity noise standard deviation (0x28).
    pub fn gravity_noise_std_dev(self) -> GravityNoiseStdDevCommand<'d, T> {
        GravityNoiseStdDevCommand {
            device: self.device,
        }
    }
    /// Pressure altitude noise standard deviation (0x29).
    pub fn pressure_altitude_noise_std_dev(self) -> PressureAltitudeNoiseStdDevCommand<'d, T> {
        PressureAltitudeNoiseStdDevCommand {
            device: self.device,
        }
    }
    /// Hard iron offset process noise (0x2B).
    pub fn hard_iron_offset_noise(self) -> HardIronOffsetNoiseCommand<'d, T> {
        HardIronOffsetNoiseCommand {
            device: self.device,
        }
    }
    /// Soft iron matrix process noise (0x2C).
    pub fn soft_iron_matrix_noise(self) -> SoftIronMatrixNoiseCommand<'d, T> {
        SoftIronMatrixNoiseCommand {
            device: self.device,
        }
    }
    /// Magnetometer noise standard deviation (0x42).
    pub fn mag_noise_std_dev(self) -> MagNoiseStdDevCommand<'d, T> {
        MagNoiseStdDevCommand {
            device: self.device,
        }
    }
    /// Declination source (0x43).
    pub fn declination_source(self) -> DeclinationSourceCommand<'d, T> {
        DeclinationSourceCommand {
            device: self.device,
        }
    }
    /// Gravity magnitude error adaptive measurement (0x44).
    pub fn gravity_magnitude_adaptive_measurement(
        self,
    ) -> GravityMagnitudeAdaptiveMeasurementCommand<'d, T> {
        GravityMagnitudeAdaptiveMeasurementCommand {
            device: self.device,
        }
    }
    /// Magnetometer magnitude error adaptive measurement (0x45).
    pub fn mag_magnitude_adaptive_measurement(
        self,
    ) -> MagMagnitudeAdaptiveMeasurementCommand<'d, T> {
        MagMagnitudeAdaptiveMeasurementCommand {
            device: self.device,
        }
    }
    /// Magnetometer dip angle error adaptive measurement (0x46).
    pub fn mag_dip_angle_adaptive_measurement(
        self,
    ) -> MagDipAngleAdaptiveMeasurementCommand<'d, T> {
        MagDipAngleAdaptiveMeasurementCommand {
            device: self.device,
        }
    }
    /// Altitude aiding control (0x47).
    pub fn altitude_aiding_control(self) -> AltitudeAidingControlCommand<'d, T> {
        AltitudeAidingControlCommand {
            device: self.device,
        }
    }
    /// Pitch/roll aiding control (0x4B).
    pub fn pitch_roll_aiding_control(self) -> PitchRollAidingControlCommand<'d, T> {
        PitchRollAidingControlCommand {
            device: self.device,
        }
    }
    /// Inclination source (0x4C).
    pub fn inclination_source(self) -> InclinationSourceCommand<'d, T> {
        InclinationSourceCommand {
            device: self.device,
        }
    }
    /// Magnetic field magnitude source (0x4D).
    pub fn magnetic_field_magnitude_source(self) -> MagneticFieldMagnitudeSourceCommand<'d, T> {
        MagneticFieldMagnitudeSourceCommand {
            device: self.device,
        }
    }
    /// Aiding measurement control (0x50).
    pub fn aiding_measurement_control(self) -> AidingMeasurementControlCommand<'d, T> {
        AidingMeasurementControlCommand {
            device: self.device,
        }
    }
    /// Navigation filter initialization (0x52).
    pub fn initialization_configuration(self) -> InitializationConfigurationCommand<'d, T> {
        InitializationConfigurationCommand {
            device: self.device,
        }
    }
    /// Adaptive filter control (0x53).
    pub fn adaptive_filter_control(self) -> AdaptiveFilterControlCommand<'d, T> {
        AdaptiveFilterControlCommand {
            device: self.device,
        }
    }
    /// GNSS multi-antenna offset (0x54).
    pub fn multi_antenna_offset(self) -> MultiAntennaOffsetCommand<'d, T> {
        MultiAntennaOffsetCommand {
            device: self.device,
        }
    }
    /// Relative position configuration (0x55).
    pub fn relative_position_configuration(self) -> RelativePositionConfigurationCommand<'d, T> {
        RelativePositionConfigurationCommand {
            device: self.device,
        }
    }
    /// Reference point lever arm (0x56).
    pub fn reference_point_lever_arm(self) -> ReferencePointLeverArmCommand<'d, T> {
        ReferencePointLeverArmCommand {
            device: self.device,
        }
    }
    /// Measurement speed lever arm (0x61).
    pub fn speed_lever_arm(self) -> SpeedLeverArmCommand<'d, T> {
        SpeedLeverArmCommand {
            device: self.device,
        }
    }
    /// Wheeled vehicle constraint control (0x63).
    pub fn wheeled_vehicle_constraint_control(
        self,
    ) -> WheeledVehicleConstraintControlCommand<'d, T> {
        WheeledVehicleConstraintControlCommand {
            device: self.device,
        }
    }
    /// GNSS antenna offset calibration control (0x64).
    pub fn gnss_antenna_calibration_control(self) -> GnssAntennaCalibrationControlCommand<'d, T> {
        GnssAntennaCalibrationControlCommand {
            device: self.device,
        }
    }
}

fn send_reset_filter_reset_filter<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::ResetFilter {};
    let value = FieldValue::Filter(crate::filter::SetField::ResetFilter(command));
    device.call(&value).map(|_| ())
}

fn send_set_initial_attitude_set_initial_attitude<T: Transport>(
    device: &mut Device<T>,
    roll: f32,
    pitch: f32,
    heading: f32,
) -> Result<(), SessionError> {
    let command = crate::filter::SetInitialAttitude {
        roll,
        pitch,
        heading,
    };
    let value = FieldValue::Filter(crate::filter::SetField::SetInitialAttitude(command));
    device.call(&value).map(|_| ())
}

fn send_set_initial_heading_set_initial_heading<T: Transport>(
    device: &mut Device<T>,
    heading: f32,
) -> Result<(), SessionError> {
    let command = crate::filter::SetInitialHeading { heading };
    let value = FieldValue::Filter(crate::filter::SetField::SetInitialHeading(command));
    device.call(&value).map(|_| ())
}

fn send_run_filter_run_filter<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::filter::RunFilter {};
    let value = FieldValue::Filter(crate::filter::SetField::RunFilter(command));
    device.call(&value).map(|_| ())
}

/// Vehicle dynamics mode (0x0D, 0x10): one call per function.
#[derive(Debug)]
pub struct VehicleDynamicsModeCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> VehicleDynamicsModeCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, mode: crate::types::VehicleDynamicsMode) -> Result<(), SessionError> {
        send_vehicle_dynamics_mode_write(self.device, mode)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::filter::VehicleDynamicsModeResponse, SessionError> {
        send_vehicle_dynamics_mode_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_vehicle_dynamics_mode_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_vehicle_dynamics_mode_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_vehicle_dynamics_mode_default(self.device)
    }
}

fn send_vehicle_dynamics_mode_write<T: Transport>(
    device: &mut Device<T>,
    mode: crate::types::VehicleDynamicsMode,
) -> Result<(), SessionError> {
    let command = crate::filter::VehicleDynamicsMode {
        function: crate::types::FunctionSelector(1),
        mode: Some(mode),
    };
    let value = FieldValue::Filter(crate::filter::SetField::VehicleDynamicsMode(command));
    device.call(&value).map(|_| ())
}

fn send_vehicle_dynamics_mode_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::filter::VehicleDynamicsModeResponse, SessionError> {
    let command = crate::filter::VehicleDynamicsMode {
        function: crate::types::FunctionSelector(2),
        ..<crate::filter::VehicleDynamicsMode as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::VehicleDynamicsMode(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::VehicleDynamicsModeResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_vehicle_dynamics_mode_save<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::VehicleDynamicsMode {
        function: crate::types::FunctionSelector(3),
        ..<crate::filter::VehicleDynamicsMode as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::VehicleDynamicsMode(command));
    device.call(&value).map(|_| ())
}

fn send_vehicle_dynamics_mode_load<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::VehicleDynamicsMode {
        function: crate::types::FunctionSelector(4),
        ..<crate::filter::VehicleDynamicsMode as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::VehicleDynamicsMode(command));
    device.call(&value).map(|_| ())
}

fn send_vehicle_dynamics_mode_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::VehicleDynamicsMode {
        function: crate::types::FunctionSelector(5),
        ..<crate::filter::VehicleDynamicsMode as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::VehicleDynamicsMode(command));
    device.call(&value).map(|_| ())
}

/// Sensor to vehicle frame transformation (0x0D, 0x11): one call per function.
#[derive(Debug)]
pub struct SensorToVehicleTransformCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> SensorToVehicleTransformCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, roll: f32, pitch: f32, yaw: f32) -> Result<(), SessionError> {
        send_sensor_to_vehicle_transform_write(self.device, roll, pitch, yaw)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::filter::SensorToVehicleTransformResponse, SessionError> {
        send_sensor_to_vehicle_transform_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_sensor_to_vehicle_transform_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_sensor_to_vehicle_transform_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_sensor_to_vehicle_transform_default(self.device)
    }
}

fn send_sensor_to_vehicle_transform_write<T: Transport>(
    device: &mut Device<T>,
    roll: f32,
    pitch: f32,
    yaw: f32,
) -> Result<(), SessionError> {
    let command = crate::filter::SensorToVehicleTransform {
        function: crate::types::FunctionSelector(1),
        roll: Some(roll),
        pitch: Some(pitch),
        yaw: Some(yaw),
    };
    let value = FieldValue::Filter(crate::filter::SetField::SensorToVehicleTransform(command));
    device.call(&value).map(|_| ())
}

fn send_sensor_to_vehicle_transform_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::filter::SensorToVehicleTransformResponse, SessionError> {
    let command = crate::filter::SensorToVehicleTransform {
        function: crate::types::FunctionSelector(2),
        ..<crate::filter::SensorToVehicleTransform as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::SensorToVehicleTransform(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::SensorToVehicleTransformResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_sensor_to_vehicle_transform_save<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::SensorToVehicleTransform {
        function: crate::types::FunctionSelector(3),
        ..<crate::filter::SensorToVehicleTransform as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::SensorToVehicleTransform(command));
    device.call(&value).map(|_| ())
}

fn send_sensor_to_vehicle_transform_load<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::SensorToVehicleTransform {
        function: crate::types::FunctionSelector(4),
        ..<crate::filter::SensorToVehicleTransform as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::SensorToVehicleTransform(command));
    device.call(&value).map(|_| ())
}

fn send_sensor_to_vehicle_transform_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::SensorToVehicleTransform {
        function: crate::types::FunctionSelector(5),
        ..<crate::filter::SensorToVehicleTransform as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::SensorToVehicleTransform(command));
    device.call(&value).map(|_| ())
}

/// Sensor to vehicle frame offset (0x0D, 0x12): one call per function.
#[derive(Debug)]
pub struct SensorToVehicleOffsetCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> SensorToVehicleOffsetCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, offset: [f32; 3]) -> Result<(), SessionError> {
        send_sensor_to_vehicle_offset_write(self.device, offset)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::filter::SensorToVehicleOffsetResponse, SessionError> {
        send_sensor_to_vehicle_offset_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_sensor_to_vehicle_offset_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_sensor_to_vehicle_offset_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_sensor_to_vehicle_offset_default(self.device)
    }
}

fn send_sensor_to_vehicle_offset_write<T: Transport>(
    device: &mut Device<T>,
    offset: [f32; 3],
) -> Result<(), SessionError> {
    let command = crate::filter::SensorToVehicleOffset {
        function: crate::types::FunctionSelector(1),
        offset: Some(offset),
    };
    let value = FieldValue::Filter(crate::filter::SetField::SensorToVehicleOffset(command));
    device.call(&value).map(|_| ())
}

fn send_sensor_to_vehicle_offset_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::filter::SensorToVehicleOffsetResponse, SessionError> {
    let command = crate::filter::SensorToVehicleOffset {
        function: crate::types::FunctionSelector(2),
        ..<crate::filter::SensorToVehicleOffset as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::SensorToVehicleOffset(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::SensorToVehicleOffsetResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_sensor_to_vehicle_offset_save<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::SensorToVehicleOffset {
        function: crate::types::FunctionSelector(3),
        ..<crate::filter::SensorToVehicleOffset as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::SensorToVehicleOffset(command));
    device.call(&value).map(|_| ())
}

fn send_sensor_to_vehicle_offset_load<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::SensorToVehicleOffset {
        function: crate::types::FunctionSelector(4),
        ..<crate::filter::SensorToVehicleOffset as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::SensorToVehicleOffset(command));
    device.call(&value).map(|_| ())
}

fn send_sensor_to_vehicle_offset_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::SensorToVehicleOffset {
        function: crate::types::FunctionSelector(5),
        ..<crate::filter::SensorToVehicleOffset as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::SensorToVehicleOffset(command));
    device.call(&value).map(|_| ())
}

/// GNSS antenna offset (0x0D, 0x13): one call per function.
#[derive(Debug)]
pub struct AntennaOffsetCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> AntennaOffsetCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, offset: [f32; 3]) -> Result<(), SessionError> {
        send_antenna_offset_write(self.device, offset)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::filter::AntennaOffsetResponse, SessionError> {
        send_antenna_offset_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_antenna_offset_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_antenna_offset_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_antenna_offset_default(self.device)
    }
}

fn send_antenna_offset_write<T: Transport>(
    device: &mut Device<T>,
    offset: [f32; 3],
) -> Result<(), SessionError> {
    let command = crate::filter::AntennaOffset {
        function: crate::types::FunctionSelector(1),
        offset: Some(offset),
    };
    let value = FieldValue::Filter(crate::filter::SetField::AntennaOffset(command));
    device.call(&value).map(|_| ())
}

fn send_antenna_offset_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::filter::AntennaOffsetResponse, SessionError> {
    let command = crate::filter::AntennaOffset {
        function: crate::types::FunctionSelector(2),
        ..<crate::filter::AntennaOffset as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::AntennaOffset(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::AntennaOffsetResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_antenna_offset_save<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::filter::AntennaOffset {
        function: crate::types::FunctionSelector(3),
        ..<crate::filter::AntennaOffset as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::AntennaOffset(command));
    device.call(&value).map(|_| ())
}

fn send_antenna_offset_load<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::filter::AntennaOffset {
        function: crate::types::FunctionSelector(4),
        ..<crate::filter::AntennaOffset as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::AntennaOffset(command));
    device.call(&value).map(|_| ())
}

fn send_antenna_offset_default<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::filter::AntennaOffset {
        function: crate::types::FunctionSelector(5),
        ..<crate::filter::AntennaOffset as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::AntennaOffset(command));
    device.call(&value).map(|_| ())
}

/// Estimation control flags (0x0D, 0x14): one call per function.
#[derive(Debug)]
pub struct EstimationControlCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> EstimationControlCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, flags: crate::types::EstimationControlFlags) -> Result<(), SessionError> {
        send_estimation_control_write(self.device, flags)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::filter::EstimationControlResponse, SessionError> {
        send_estimation_control_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_estimation_control_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_estimation_control_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_estimation_control_default(self.device)
    }
}

fn send_estimation_control_write<T: Transport>(
    device: &mut Device<T>,
    flags: crate::types::EstimationControlFlags,
) -> Result<(), SessionError> {
    let command = crate::filter::EstimationControl {
        function: crate::types::FunctionSelector(1),
        flags: Some(flags),
    };
    let value = FieldValue::Filter(crate::filter::SetField::EstimationControl(command));
    device.call(&value).map(|_| ())
}

fn send_estimation_control_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::filter::EstimationControlResponse, SessionError> {
    let command = crate::filter::EstimationControl {
        function: crate::types::FunctionSelector(2),
        ..<crate::filter::EstimationControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::EstimationControl(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::EstimationControlResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_estimation_control_save<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::filter::EstimationControl {
        function: crate::types::FunctionSelector(3),
        ..<crate::filter::EstimationControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::EstimationControl(command));
    device.call(&value).map(|_| ())
}

fn send_estimation_control_load<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::filter::EstimationControl {
        function: crate::types::FunctionSelector(4),
        ..<crate::filter::EstimationControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::EstimationControl(command));
    device.call(&value).map(|_| ())
}

fn send_estimation_control_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::EstimationControl {
        function: crate::types::FunctionSelector(5),
        ..<crate::filter::EstimationControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::EstimationControl(command));
    device.call(&value).map(|_| ())
}

/// GNSS source control (0x0D, 0x15): one call per function.
#[derive(Debug)]
pub struct GnssSourceControlCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> GnssSourceControlCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, source: crate::types::FilterGnssSource) -> Result<(), SessionError> {
        send_gnss_source_control_write(self.device, source)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::filter::GnssSourceControlResponse, SessionError> {
        send_gnss_source_control_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_gnss_source_control_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_gnss_source_control_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_gnss_source_control_default(self.device)
    }
}

fn send_gnss_source_control_write<T: Transport>(
    device: &mut Device<T>,
    source: crate::types::FilterGnssSource,
) -> Result<(), SessionError> {
    let command = crate::filter::GnssSourceControl {
        function: crate::types::FunctionSelector(1),
        source: Some(source),
    };
    let value = FieldValue::Filter(crate::filter::SetField::GnssSourceControl(command));
    device.call(&value).map(|_| ())
}

fn send_gnss_source_control_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::filter::GnssSourceControlResponse, SessionError> {
    let command = crate::filter::GnssSourceControl {
        function: crate::types::FunctionSelector(2),
        ..<crate::filter::GnssSourceControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::GnssSourceControl(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::GnssSourceControlResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_gnss_source_control_save<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::filter::GnssSourceControl {
        function: crate::types::FunctionSelector(3),
        ..<crate::filter::GnssSourceControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::GnssSourceControl(command));
    device.call(&value).map(|_| ())
}

fn send_gnss_source_control_load<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::filter::GnssSourceControl {
        function: crate::types::FunctionSelector(4),
        ..<crate::filter::GnssSourceControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::GnssSourceControl(command));
    device.call(&value).map(|_| ())
}

fn send_gnss_source_control_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::GnssSourceControl {
        function: crate::types::FunctionSelector(5),
        ..<crate::filter::GnssSourceControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::GnssSourceControl(command));
    device.call(&value).map(|_| ())
}

fn send_external_gnss_update_external_gnss_update<T: Transport>(
    device: &mut Device<T>,
    gps_tow: f64,
    gps_week: u16,
    latitude: f64,
    longitude: f64,
    height: f64,
    velocity: [f32; 3],
    position_uncertainty: [f32; 3],
    velocity_uncertainty: [f32; 3],
) -> Result<(), SessionError> {
    let command = crate::filter::ExternalGnssUpdate {
        gps_tow,
        gps_week,
        latitude,
        longitude,
        height,
        velocity,
        position_uncertainty,
        velocity_uncertainty,
    };
    let value = FieldValue::Filter(crate::filter::SetField::ExternalGnssUpdate(command));
    device.call(&value).map(|_| ())
}

fn send_external_heading_update_external_heading_update<T: Transport>(
    device: &mut Device<T>,
    heading: f32,
    heading_uncertainty: f32,
    r#type: crate::types::ExternalHeadingType,
) -> Result<(), SessionError> {
    let command = crate::filter::ExternalHeadingUpdate {
        heading,
        heading_uncertainty,
        r#type,
    };
    let value = FieldValue::Filter(crate::filter::SetField::ExternalHeadingUpdate(command));
    device.call(&value).map(|_| ())
}

/// Heading update control (0x0D, 0x18): one call per function.
#[derive(Debug)]
pub struct HeadingUpdateControlCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> HeadingUpdateControlCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, source: crate::types::HeadingUpdateSource) -> Result<(), SessionError> {
        send_heading_update_control_write(self.device, source)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::filter::HeadingUpdateControlResponse, SessionError> {
        send_heading_update_control_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_heading_update_control_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_heading_update_control_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_heading_update_control_default(self.device)
    }
}

fn send_heading_update_control_write<T: Transport>(
    device: &mut Device<T>,
    source: crate::types::HeadingUpdateSource,
) -> Result<(), SessionError> {
    let command = crate::filter::HeadingUpdateControl {
        function: crate::types::FunctionSelector(1),
        source: Some(source),
    };
    let value = FieldValue::Filter(crate::filter::SetField::HeadingUpdateControl(command));
    device.call(&value).map(|_| ())
}

fn send_heading_update_control_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::filter::HeadingUpdateControlResponse, SessionError> {
    let command = crate::filter::HeadingUpdateControl {
        function: crate::types::FunctionSelector(2),
        ..<crate::filter::HeadingUpdateControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::HeadingUpdateControl(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::HeadingUpdateControlResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_heading_update_control_save<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::HeadingUpdateControl {
        function: crate::types::FunctionSelector(3),
        ..<crate::filter::HeadingUpdateControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::HeadingUpdateControl(command));
    device.call(&value).map(|_| ())
}

fn send_heading_update_control_load<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::HeadingUpdateControl {
        function: crate::types::FunctionSelector(4),
        ..<crate::filter::HeadingUpdateControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::HeadingUpdateControl(command));
    device.call(&value).map(|_| ())
}

fn send_heading_update_control_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::HeadingUpdateControl {
        function: crate::types::FunctionSelector(5),
        ..<crate::filter::HeadingUpdateControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::HeadingUpdateControl(command));
    device.call(&value).map(|_| ())
}

/// Auto-initialization control (0x0D, 0x19): one call per function.
#[derive(Debug)]
pub struct AutoInitControlCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> AutoInitControlCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, enable: u8) -> Result<(), SessionError> {
        send_auto_init_control_write(self.device, enable)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::filter::AutoInitControlResponse, SessionError> {
        send_auto_init_control_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_auto_init_control_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_auto_init_control_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_auto_init_control_default(self.device)
    }
}

fn send_auto_init_control_write<T: Transport>(
    device: &mut Device<T>,
    enable: u8,
) -> Result<(), SessionError> {
    let command = crate::filter::AutoInitControl {
        function: crate::types::FunctionSelector(1),
        enable: Some(enable),
    };
    let value = FieldValue::Filter(crate::filter::SetField::AutoInitControl(command));
    device.call(&value).map(|_| ())
}

fn send_auto_init_control_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::filter::AutoInitControlResponse, SessionError> {
    let command = crate::filter::AutoInitControl {
        function: crate::types::FunctionSelector(2),
        ..<crate::filter::AutoInitControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::AutoInitControl(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::AutoInitControlResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_auto_init_control_save<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::filter::AutoInitControl {
        function: crate::types::FunctionSelector(3),
        ..<crate::filter::AutoInitControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::AutoInitControl(command));
    device.call(&value).map(|_| ())
}

fn send_auto_init_control_load<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::filter::AutoInitControl {
        function: crate::types::FunctionSelector(4),
        ..<crate::filter::AutoInitControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::AutoInitControl(command));
    device.call(&value).map(|_| ())
}

fn send_auto_init_control_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::AutoInitControl {
        function: crate::types::FunctionSelector(5),
        ..<crate::filter::AutoInitControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::AutoInitControl(command));
    device.call(&value).map(|_| ())
}

/// Accelerometer noise standard deviation (0x0D, 0x1A): one call per function.
#[derive(Debug)]
pub struct AccelNoiseCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> AccelNoiseCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, noise: [f32; 3]) -> Result<(), SessionError> {
        send_accel_noise_write(self.device, noise)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::filter::AccelNoiseResponse, SessionError> {
        send_accel_noise_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_accel_noise_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_accel_noise_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_accel_noise_default(self.device)
    }
}

fn send_accel_noise_write<T: Transport>(
    device: &mut Device<T>,
    noise: [f32; 3],
) -> Result<(), SessionError> {
    let command = crate::filter::AccelNoise {
        function: crate::types::FunctionSelector(1),
        noise: Some(noise),
    };
    let value = FieldValue::Filter(crate::filter::SetField::AccelNoise(command));
    device.call(&value).map(|_| ())
}

fn send_accel_noise_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::filter::AccelNoiseResponse, SessionError> {
    let command = crate::filter::AccelNoise {
        function: crate::types::FunctionSelector(2),
        ..<crate::filter::AccelNoise as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::AccelNoise(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::AccelNoiseResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_accel_noise_save<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::filter::AccelNoise {
        function: crate::types::FunctionSelector(3),
        ..<crate::filter::AccelNoise as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::AccelNoise(command));
    device.call(&value).map(|_| ())
}

fn send_accel_noise_load<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::filter::AccelNoise {
        function: crate::types::FunctionSelector(4),
        ..<crate::filter::AccelNoise as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::AccelNoise(command));
    device.call(&value).map(|_| ())
}

fn send_accel_noise_default<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::filter::AccelNoise {
        function: crate::types::FunctionSelector(5),
        ..<crate::filter::AccelNoise as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::AccelNoise(command));
    device.call(&value).map(|_| ())
}

/// Gyroscope noise standard deviation (0x0D, 0x1B): one call per function.
#[derive(Debug)]
pub struct GyroNoiseCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> GyroNoiseCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, noise: [f32; 3]) -> Result<(), SessionError> {
        send_gyro_noise_write(self.device, noise)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::filter::GyroNoiseResponse, SessionError> {
        send_gyro_noise_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_gyro_noise_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_gyro_noise_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_gyro_noise_default(self.device)
    }
}

fn send_gyro_noise_write<T: Transport>(
    device: &mut Device<T>,
    noise: [f32; 3],
) -> Result<(), SessionError> {
    let command = crate::filter::GyroNoise {
        function: crate::types::FunctionSelector(1),
        noise: Some(noise),
    };
    let value = FieldValue::Filter(crate::filter::SetField::GyroNoise(command));
    device.call(&value).map(|_| ())
}

fn send_gyro_noise_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::filter::GyroNoiseResponse, SessionError> {
    let command = crate::filter::GyroNoise {
        function: crate::types::FunctionSelector(2),
        ..<crate::filter::GyroNoise as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::GyroNoise(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::GyroNoiseResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_gyro_noise_save<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::filter::GyroNoise {
        function: crate::types::FunctionSelector(3),
        ..<crate::filter::GyroNoise as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::GyroNoise(command));
    device.call(&value).map(|_| ())
}

fn send_gyro_noise_load<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::filter::GyroNoise {
        function: crate::types::FunctionSelector(4),
        ..<crate::filter::GyroNoise as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::GyroNoise(command));
    device.call(&value).map(|_| ())
}

fn send_gyro_noise_default<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::filter::GyroNoise {
        function: crate::types::FunctionSelector(5),
        ..<crate::filter::GyroNoise as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::GyroNoise(command));
    device.call(&value).map(|_| ())
}

/// Accelerometer bias model parameters (0x0D, 0x1C): one call per function.
#[derive(Debug)]
pub struct AccelBiasModelCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> AccelBiasModelCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, beta: [f32; 3], noise: [f32; 3]) -> Result<(), SessionError> {
        send_accel_bias_model_write(self.device, beta, noise)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::filter::AccelBiasModelResponse, SessionError> {
        send_accel_bias_model_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_accel_bias_model_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_accel_bias_model_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_accel_bias_model_default(self.device)
    }
}

fn send_accel_bias_model_write<T: Transport>(
    device: &mut Device<T>,
    beta: [f32; 3],
    noise: [f32; 3],
) -> Result<(), SessionError> {
    let command = crate::filter::AccelBiasModel {
        function: crate::types::FunctionSelector(1),
        beta: Some(beta),
        noise: Some(noise),
    };
    let value = FieldValue::Filter(crate::filter::SetField::AccelBiasModel(command));
    device.call(&value).map(|_| ())
}

fn send_accel_bias_model_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::filter::AccelBiasModelResponse, SessionError> {
    let command = crate::filter::AccelBiasModel {
        function: crate::types::FunctionSelector(2),
        ..<crate::filter::AccelBiasModel as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::AccelBiasModel(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::AccelBiasModelResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_accel_bias_model_save<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::filter::AccelBiasModel {
        function: crate::types::FunctionSelector(3),
        ..<crate::filter::AccelBiasModel as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::AccelBiasModel(command));
    device.call(&value).map(|_| ())
}

fn send_accel_bias_model_load<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::filter::AccelBiasModel {
        function: crate::types::FunctionSelector(4),
        ..<crate::filter::AccelBiasModel as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::AccelBiasModel(command));
    device.call(&value).map(|_| ())
}

fn send_accel_bias_model_default<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::filter::AccelBiasModel {
        function: crate::types::FunctionSelector(5),
        ..<crate::filter::AccelBiasModel as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::AccelBiasModel(command));
    device.call(&value).map(|_| ())
}

/// Gyroscope bias model parameters (0x0D, 0x1D): one call per function.
#[derive(Debug)]
pub struct GyroBiasModelCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> GyroBiasModelCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, beta: [f32; 3], noise: [f32; 3]) -> Result<(), SessionError> {
        send_gyro_bias_model_write(self.device, beta, noise)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::filter::GyroBiasModelResponse, SessionError> {
        send_gyro_bias_model_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_gyro_bias_model_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_gyro_bias_model_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_gyro_bias_model_default(self.device)
    }
}

fn send_gyro_bias_model_write<T: Transport>(
    device: &mut Device<T>,
    beta: [f32; 3],
    noise: [f32; 3],
) -> Result<(), SessionError> {
    let command = crate::filter::GyroBiasModel {
        function: crate::types::FunctionSelector(1),
        beta: Some(beta),
        noise: Some(noise),
    };
    let value = FieldValue::Filter(crate::filter::SetField::GyroBiasModel(command));
    device.call(&value).map(|_| ())
}

fn send_gyro_bias_model_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::filter::GyroBiasModelResponse, SessionError> {
    let command = crate::filter::GyroBiasModel {
        function: crate::types::FunctionSelector(2),
        ..<crate::filter::GyroBiasModel as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::GyroBiasModel(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::GyroBiasModelResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_gyro_bias_model_save<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::filter::GyroBiasModel {
        function: crate::types::FunctionSelector(3),
        ..<crate::filter::GyroBiasModel as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::GyroBiasModel(command));
    device.call(&value).map(|_| ())
}

fn send_gyro_bias_model_load<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::filter::GyroBiasModel {
        function: crate::types::FunctionSelector(4),
        ..<crate::filter::GyroBiasModel as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::GyroBiasModel(command));
    device.call(&value).map(|_| ())
}

fn send_gyro_bias_model_default<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::filter::GyroBiasModel {
        function: crate::types::FunctionSelector(5),
        ..<crate::filter::GyroBiasModel as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::GyroBiasModel(command));
    device.call(&value).map(|_| ())
}

/// Zero velocity update (ZUPT) control (0x0D, 0x1E): one call per function.
#[derive(Debug)]
pub struct ZuptControlCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> ZuptControlCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, enable: u8, threshold: f32) -> Result<(), SessionError> {
        send_zupt_control_write(self.device, enable, threshold)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::filter::ZuptControlResponse, SessionError> {
        send_zupt_control_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_zupt_control_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_zupt_control_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_zupt_control_default(self.device)
    }
}

fn send_zupt_control_write<T: Transport>(
    device: &mut Device<T>,
    enable: u8,
    threshold: f32,
) -> Result<(), SessionError> {
    let command = crate::filter::ZuptControl {
        function: crate::types::FunctionSelector(1),
        enable: Some(enable),
        threshold: Some(threshold),
    };
    let value = FieldValue::Filter(crate::filter::SetField::ZuptControl(command));
    device.call(&value).map(|_| ())
}

fn send_zupt_control_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::filter::ZuptControlResponse, SessionError> {
    let command = crate::filter::ZuptControl {
        function: crate::types::FunctionSelector(2),
        ..<crate::filter::ZuptControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::ZuptControl(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::ZuptControlResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_zupt_control_save<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::filter::ZuptControl {
        function: crate::types::FunctionSelector(3),
        ..<crate::filter::ZuptControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::ZuptControl(command));
    device.call(&value).map(|_| ())
}

fn send_zupt_control_load<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::filter::ZuptControl {
        function: crate::types::FunctionSelector(4),
        ..<crate::filter::ZuptControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::ZuptControl(command));
    device.call(&value).map(|_| ())
}

fn send_zupt_control_default<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::filter::ZuptControl {
        function: crate::types::FunctionSelector(5),
        ..<crate::filter::ZuptControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::ZuptControl(command));
    device.call(&value).map(|_| ())
}

fn send_external_heading_update_with_time_external_heading_update_with_time<T: Transport>(
    device: &mut Device<T>,
    gps_tow: f64,
    gps_week: u16,
    heading: f32,
    heading_uncertainty: f32,
    r#type: crate::types::ExternalHeadingType,
) -> Result<(), SessionError> {
    let command = crate::filter::ExternalHeadingUpdateWithTime {
        gps_tow,
        gps_week,
        heading,
        heading_uncertainty,
        r#type,
    };
    let value = FieldValue::Filter(crate::filter::SetField::ExternalHeadingUpdateWithTime(
        command,
    ));
    device.call(&value).map(|_| ())
}

/// Zero angular rate update control (0x0D, 0x20): one call per function.
#[derive(Debug)]
pub struct ZeroAngularRateUpdateControlCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> ZeroAngularRateUpdateControlCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, enable: u8, threshold: f32) -> Result<(), SessionError> {
        send_zero_angular_rate_update_control_write(self.device, enable, threshold)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::filter::ZeroAngularRateUpdateControlResponse, SessionError> {
        send_zero_angular_rate_update_control_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_zero_angular_rate_update_control_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_zero_angular_rate_update_control_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_zero_angular_rate_update_control_default(self.device)
    }
}

fn send_zero_angular_rate_update_control_write<T: Transport>(
    device: &mut Device<T>,
    enable: u8,
    threshold: f32,
) -> Result<(), SessionError> {
    let command = crate::filter::ZeroAngularRateUpdateControl {
        function: crate::types::FunctionSelector(1),
        enable: Some(enable),
        threshold: Some(threshold),
    };
    let value = FieldValue::Filter(crate::filter::SetField::ZeroAngularRateUpdateControl(
        command,
    ));
    device.call(&value).map(|_| ())
}

fn send_zero_angular_rate_update_control_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::filter::ZeroAngularRateUpdateControlResponse, SessionError> {
    let command = crate::filter::ZeroAngularRateUpdateControl {
        function: crate::types::FunctionSelector(2),
        ..<crate::filter::ZeroAngularRateUpdateControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::ZeroAngularRateUpdateControl(
        command,
    ));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::ZeroAngularRateUpdateControlResponse(r)) => {
            Some(r)
        }
        _ => None,
    })
}

fn send_zero_angular_rate_update_control_save<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::ZeroAngularRateUpdateControl {
        function: crate::types::FunctionSelector(3),
        ..<crate::filter::ZeroAngularRateUpdateControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::ZeroAngularRateUpdateControl(
        command,
    ));
    device.call(&value).map(|_| ())
}

fn send_zero_angular_rate_update_control_load<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::ZeroAngularRateUpdateControl {
        function: crate::types::FunctionSelector(4),
        ..<crate::filter::ZeroAngularRateUpdateControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::ZeroAngularRateUpdateControl(
        command,
    ));
    device.call(&value).map(|_| ())
}

fn send_zero_angular_rate_update_control_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::ZeroAngularRateUpdateControl {
        function: crate::types::FunctionSelector(5),
        ..<crate::filter::ZeroAngularRateUpdateControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::ZeroAngularRateUpdateControl(
        command,
    ));
    device.call(&value).map(|_| ())
}

/// Tare orientation (0x0D, 0x21): one call per function.
#[derive(Debug)]
pub struct TareOrientationCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> TareOrientationCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, axes: crate::types::TareAxes) -> Result<(), SessionError> {
        send_tare_orientation_write(self.device, axes)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_tare_orientation_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_tare_orientation_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_tare_orientation_default(self.device)
    }
}

fn send_tare_orientation_write<T: Transport>(
    device: &mut Device<T>,
    axes: crate::types::TareAxes,
) -> Result<(), SessionError> {
    let command = crate::filter::TareOrientation {
        function: crate::types::FunctionSelector(1),
        axes: Some(axes),
    };
    let value = FieldValue::Filter(crate::filter::SetField::TareOrientation(command));
    device.call(&value).map(|_| ())
}

fn send_tare_orientation_save<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::filter::TareOrientation {
        function: crate::types::FunctionSelector(3),
        ..<crate::filter::TareOrientation as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::TareOrientation(command));
    device.call(&value).map(|_| ())
}

fn send_tare_orientation_load<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::filter::TareOrientation {
        function: crate::types::FunctionSelector(4),
        ..<crate::filter::TareOrientation as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::TareOrientation(command));
    device.call(&value).map(|_| ())
}

fn send_tare_orientation_default<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::filter::TareOrientation {
        function: crate::types::FunctionSelector(5),
        ..<crate::filter::TareOrientation as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::TareOrientation(command));
    device.call(&value).map(|_| ())
}

fn send_commanded_zupt_commanded_zupt<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::CommandedZupt {};
    let value = FieldValue::Filter(crate::filter::SetField::CommandedZupt(command));
    device.call(&value).map(|_| ())
}

fn send_commanded_zero_angular_rate_update_commanded_zero_angular_rate_update<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::CommandedZeroAngularRateUpdate {};
    let value = FieldValue::Filter(crate::filter::SetField::CommandedZeroAngularRateUpdate(
        command,
    ));
    device.call(&value).map(|_| ())
}

/// Magnetometer capture auto calibration (0x0D, 0x27): one call per function.
#[derive(Debug)]
pub struct MagCaptureAutoCalibrationCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> MagCaptureAutoCalibrationCommand<'d, T> {
    /// Function `write`.
    pub fn write(self) -> Result<(), SessionError> {
        send_mag_capture_auto_calibration_write(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_mag_capture_auto_calibration_save(self.device)
    }
}

fn send_mag_capture_auto_calibration_write<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::MagCaptureAutoCalibration {
        function: crate::types::FunctionSelector(1),
    };
    let value = FieldValue::Filter(crate::filter::SetField::MagCaptureAutoCalibration(command));
    device.call(&value).map(|_| ())
}

fn send_mag_capture_auto_calibration_save<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::MagCaptureAutoCalibration {
        function: crate::types::FunctionSelector(3),
    };
    let value = FieldValue::Filter(crate::filter::SetField::MagCaptureAutoCalibration(command));
    device.call(&value).map(|_| ())
}

/// Gravity noise standard deviation (0x0D, 0x28): one call per function.
#[derive(Debug)]
pub struct GravityNoiseStdDevCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> GravityNoiseStdDevCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, noise: [f32; 3]) -> Result<(), SessionError> {
        send_gravity_noise_std_dev_write(self.device, noise)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::filter::GravityNoiseStdDevResponse, SessionError> {
        send_gravity_noise_std_dev_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_gravity_noise_std_dev_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_gravity_noise_std_dev_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_gravity_noise_std_dev_default(self.device)
    }
}

fn send_gravity_noise_std_dev_write<T: Transport>(
    device: &mut Device<T>,
    noise: [f32; 3],
) -> Result<(), SessionError> {
    let command = crate::filter::GravityNoiseStdDev {
        function: crate::types::FunctionSelector(1),
        noise: Some(noise),
    };
    let value = FieldValue::Filter(crate::filter::SetField::GravityNoiseStdDev(command));
    device.call(&value).map(|_| ())
}

fn send_gravity_noise_std_dev_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::filter::GravityNoiseStdDevResponse, SessionError> {
    let command = crate::filter::GravityNoiseStdDev {
        function: crate::types::FunctionSelector(2),
        ..<crate::filter::GravityNoiseStdDev as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::GravityNoiseStdDev(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::GravityNoiseStdDevResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_gravity_noise_std_dev_save<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::GravityNoiseStdDev {
        function: crate::types::FunctionSelector(3),
        ..<crate::filter::GravityNoiseStdDev as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::GravityNoiseStdDev(command));
    device.call(&value).map(|_| ())
}

fn send_gravity_noise_std_dev_load<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::GravityNoiseStdDev {
        function: crate::types::FunctionSelector(4),
        ..<crate::filter::GravityNoiseStdDev as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::GravityNoiseStdDev(command));
    device.call(&value).map(|_| ())
}

fn send_gravity_noise_std_dev_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::GravityNoiseStdDev {
        function: crate::types::FunctionSelector(5),
        ..<crate::filter::GravityNoiseStdDev as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::GravityNoiseStdDev(command));
    device.call(&value).map(|_| ())
}

/// Pressure altitude noise standard deviation (0x0D, 0x29): one call per function.
#[derive(Debug)]
pub struct PressureAltitudeNoiseStdDevCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> PressureAltitudeNoiseStdDevCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, noise: f32) -> Result<(), SessionError> {
        send_pressure_altitude_noise_std_dev_write(self.device, noise)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::filter::PressureAltitudeNoiseStdDevResponse, SessionError> {
        send_pressure_altitude_noise_std_dev_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_pressure_altitude_noise_std_dev_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_pressure_altitude_noise_std_dev_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_pressure_altitude_noise_std_dev_default(self.device)
    }
}

fn send_pressure_altitude_noise_std_dev_write<T: Transport>(
    device: &mut Device<T>,
    noise: f32,
) -> Result<(), SessionError> {
    let command = crate::filter::PressureAltitudeNoiseStdDev {
        function: crate::types::FunctionSelector(1),
        noise: Some(noise),
    };
    let value = FieldValue::Filter(crate::filter::SetField::PressureAltitudeNoiseStdDev(
        command,
    ));
    device.call(&value).map(|_| ())
}

fn send_pressure_altitude_noise_std_dev_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::filter::PressureAltitudeNoiseStdDevResponse, SessionError> {
    let command = crate::filter::PressureAltitudeNoiseStdDev {
        function: crate::types::FunctionSelector(2),
        ..<crate::filter::PressureAltitudeNoiseStdDev as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::PressureAltitudeNoiseStdDev(
        command,
    ));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::PressureAltitudeNoiseStdDevResponse(r)) => {
            Some(r)
        }
        _ => None,
    })
}

fn send_pressure_altitude_noise_std_dev_save<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::PressureAltitudeNoiseStdDev {
        function: crate::types::FunctionSelector(3),
        ..<crate::filter::PressureAltitudeNoiseStdDev as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::PressureAltitudeNoiseStdDev(
        command,
    ));
    device.call(&value).map(|_| ())
}

fn send_pressure_altitude_noise_std_dev_load<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::PressureAltitudeNoiseStdDev {
        function: crate::types::FunctionSelector(4),
        ..<crate::filter::PressureAltitudeNoiseStdDev as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::PressureAltitudeNoiseStdDev(
        command,
    ));
    device.call(&value).map(|_| ())
}

fn send_pressure_altitude_noise_std_dev_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::PressureAltitudeNoiseStdDev {
        function: crate::types::FunctionSelector(5),
        ..<crate::filter::PressureAltitudeNoiseStdDev as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::PressureAltitudeNoiseStdDev(
        command,
    ));
    device.call(&value).map(|_| ())
}

/// Hard iron offset process noise (0x0D, 0x2B): one call per function.
#[derive(Debug)]
pub struct HardIronOffsetNoiseCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> HardIronOffsetNoiseCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, noise: [f32; 3]) -> Result<(), SessionError> {
        send_hard_iron_offset_noise_write(self.device, noise)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::filter::HardIronOffsetNoiseResponse, SessionError> {
        send_hard_iron_offset_noise_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_hard_iron_offset_noise_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_hard_iron_offset_noise_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_hard_iron_offset_noise_default(self.device)
    }
}

fn send_hard_iron_offset_noise_write<T: Transport>(
    device: &mut Device<T>,
    noise: [f32; 3],
) -> Result<(), SessionError> {
    let command = crate::filter::HardIronOffsetNoise {
        function: crate::types::FunctionSelector(1),
        noise: Some(noise),
    };
    let value = FieldValue::Filter(crate::filter::SetField::HardIronOffsetNoise(command));
    device.call(&value).map(|_| ())
}

fn send_hard_iron_offset_noise_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::filter::HardIronOffsetNoiseResponse, SessionError> {
    let command = crate::filter::HardIronOffsetNoise {
        function: crate::types::FunctionSelector(2),
        ..<crate::filter::HardIronOffsetNoise as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::HardIronOffsetNoise(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::HardIronOffsetNoiseResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_hard_iron_offset_noise_save<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::HardIronOffsetNoise {
        function: crate::types::FunctionSelector(3),
        ..<crate::filter::HardIronOffsetNoise as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::HardIronOffsetNoise(command));
    device.call(&value).map(|_| ())
}

fn send_hard_iron_offset_noise_load<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::HardIronOffsetNoise {
        function: crate::types::FunctionSelector(4),
        ..<crate::filter::HardIronOffsetNoise as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::HardIronOffsetNoise(command));
    device.call(&value).map(|_| ())
}

fn send_hard_iron_offset_noise_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::HardIronOffsetNoise {
        function: crate::types::FunctionSelector(5),
        ..<crate::filter::HardIronOffsetNoise as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::HardIronOffsetNoise(command));
    device.call(&value).map(|_| ())
}

/// Soft iron matrix process noise (0x0D, 0x2C): one call per function.
#[derive(Debug)]
pub struct SoftIronMatrixNoiseCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> SoftIronMatrixNoiseCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, noise: [f32; 9]) -> Result<(), SessionError> {
        send_soft_iron_matrix_noise_write(self.device, noise)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::filter::SoftIronMatrixNoiseResponse, SessionError> {
        send_soft_iron_matrix_noise_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_soft_iron_matrix_noise_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_soft_iron_matrix_noise_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_soft_iron_matrix_noise_default(self.device)
    }
}

fn send_soft_iron_matrix_noise_write<T: Transport>(
    device: &mut Device<T>,
    noise: [f32; 9],
) -> Result<(), SessionError> {
    let command = crate::filter::SoftIronMatrixNoise {
        function: crate::types::FunctionSelector(1),
        noise: Some(noise),
    };
    let value = FieldValue::Filter(crate::filter::SetField::SoftIronMatrixNoise(command));
    device.call(&value).map(|_| ())
}

fn send_soft_iron_matrix_noise_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::filter::SoftIronMatrixNoiseResponse, SessionError> {
    let command = crate::filter::SoftIronMatrixNoise {
        function: crate::types::FunctionSelector(2),
        ..<crate::filter::SoftIronMatrixNoise as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::SoftIronMatrixNoise(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::SoftIronMatrixNoiseResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_soft_iron_matrix_noise_save<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::SoftIronMatrixNoise {
        function: crate::types::FunctionSelector(3),
        ..<crate::filter::SoftIronMatrixNoise as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::SoftIronMatrixNoise(command));
    device.call(&value).map(|_| ())
}

fn send_soft_iron_matrix_noise_load<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::SoftIronMatrixNoise {
        function: crate::types::FunctionSelector(4),
        ..<crate::filter::SoftIronMatrixNoise as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::SoftIronMatrixNoise(command));
    device.call(&value).map(|_| ())
}

fn send_soft_iron_matrix_noise_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::SoftIronMatrixNoise {
        function: crate::types::FunctionSelector(5),
        ..<crate::filter::SoftIronMatrixNoise as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::SoftIronMatrixNoise(command));
    device.call(&value).map(|_| ())
}

/// Magnetometer noise standard deviation (0x0D, 0x42): one call per function.
#[derive(Debug)]
pub struct MagNoiseStdDevCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> MagNoiseStdDevCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, noise: [f32; 3]) -> Result<(), SessionError> {
        send_mag_noise_std_dev_write(self.device, noise)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::filter::MagNoiseStdDevResponse, SessionError> {
        send_mag_noise_std_dev_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_mag_noise_std_dev_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_mag_noise_std_dev_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_mag_noise_std_dev_default(self.device)
    }
}

fn send_mag_noise_std_dev_write<T: Transport>(
    device: &mut Device<T>,
    noise: [f32; 3],
) -> Result<(), SessionError> {
    let command = crate::filter::MagNoiseStdDev {
        function: crate::types::FunctionSelector(1),
        noise: Some(noise),
    };
    let value = FieldValue::Filter(crate::filter::SetField::MagNoiseStdDev(command));
    device.call(&value).map(|_| ())
}

fn send_mag_noise_std_dev_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::filter::MagNoiseStdDevResponse, SessionError> {
    let command = crate::filter::MagNoiseStdDev {
        function: crate::types::FunctionSelector(2),
        ..<crate::filter::MagNoiseStdDev as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::MagNoiseStdDev(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::MagNoiseStdDevResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_mag_noise_std_dev_save<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::filter::MagNoiseStdDev {
        function: crate::types::FunctionSelector(3),
        ..<crate::filter::MagNoiseStdDev as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::MagNoiseStdDev(command));
    device.call(&value).map(|_| ())
}

fn send_mag_noise_std_dev_load<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::filter::MagNoiseStdDev {
        function: crate::types::FunctionSelector(4),
        ..<crate::filter::MagNoiseStdDev as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::MagNoiseStdDev(command));
    device.call(&value).map(|_| ())
}

fn send_mag_noise_std_dev_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::MagNoiseStdDev {
        function: crate::types::FunctionSelector(5),
        ..<crate::filter::MagNoiseStdDev as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::MagNoiseStdDev(command));
    device.call(&value).map(|_| ())
}

/// Declination source (0x0D, 0x43): one call per function.
#[derive(Debug)]
pub struct DeclinationSourceCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> DeclinationSourceCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        source: crate::types::MagneticParamSource,
        declination: f32,
    ) -> Result<(), SessionError> {
        send_declination_source_write(self.device, source, declination)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::filter::DeclinationSourceResponse, SessionError> {
        send_declination_source_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_declination_source_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_declination_source_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_declination_source_default(self.device)
    }
}

fn send_declination_source_write<T: Transport>(
    device: &mut Device<T>,
    source: crate::types::MagneticParamSource,
    declination: f32,
) -> Result<(), SessionError> {
    let command = crate::filter::DeclinationSource {
        function: crate::types::FunctionSelector(1),
        source: Some(source),
        declination: Some(declination),
    };
    let value = FieldValue::Filter(crate::filter::SetField::DeclinationSource(command));
    device.call(&value).map(|_| ())
}

fn send_declination_source_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::filter::DeclinationSourceResponse, SessionError> {
    let command = crate::filter::DeclinationSource {
        function: crate::types::FunctionSelector(2),
        ..<crate::filter::DeclinationSource as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::DeclinationSource(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::DeclinationSourceResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_declination_source_save<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::filter::DeclinationSource {
        function: crate::types::FunctionSelector(3),
        ..<crate::filter::DeclinationSource as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::DeclinationSource(command));
    device.call(&value).map(|_| ())
}

fn send_declination_source_load<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::filter::DeclinationSource {
        function: crate::types::FunctionSelector(4),
        ..<crate::filter::DeclinationSource as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::DeclinationSource(command));
    device.call(&value).map(|_| ())
}

fn send_declination_source_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::DeclinationSource {
        function: crate::types::FunctionSelector(5),
        ..<crate::filter::DeclinationSource as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::DeclinationSource(command));
    device.call(&value).map(|_| ())
}

/// Gravity magnitude error adaptive measurement (0x0D, 0x44): one call per function.
#[derive(Debug)]
pub struct GravityMagnitudeAdaptiveMeasurementCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> GravityMagnitudeAdaptiveMeasurementCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        mode: crate::types::AdaptiveMeasurementMode,
        frequency: f32,
        low_limit: f32,
        high_limit: f32,
        low_limit_uncertainty: f32,
        high_limit_uncertainty: f32,
        minimum_uncertainty: f32,
    ) -> Result<(), SessionError> {
        send_gravity_magnitude_adaptive_measurement_write(
            self.device,
            mode,
            frequency,
            low_limit,
            high_limit,
            low_limit_uncertainty,
            high_limit_uncertainty,
            minimum_uncertainty,
        )
    }
    /// Function `read`: returns the reply field.
    pub fn read(
        self,
    ) -> Result<crate::filter::GravityMagnitudeAdaptiveMeasurementResponse, SessionError> {
        send_gravity_magnitude_adaptive_measurement_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_gravity_magnitude_adaptive_measurement_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_gravity_magnitude_adaptive_measurement_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_gravity_magnitude_adaptive_measurement_default(self.device)
    }
}

fn send_gravity_magnitude_adaptive_measurement_write<T: Transport>(
    device: &mut Device<T>,
    mode: crate::types::AdaptiveMeasurementMode,
    frequency: f32,
    low_limit: f32,
    high_limit: f32,
    low_limit_uncertainty: f32,
    high_limit_uncertainty: f32,
    minimum_uncertainty: f32,
) -> Result<(), SessionError> {
    let command = crate::filter::GravityMagnitudeAdaptiveMeasurement {
        function: crate::types::FunctionSelector(1),
        mode: Some(mode),
        frequency: Some(frequency),
        low_limit: Some(low_limit),
        high_limit: Some(high_limit),
        low_limit_uncertainty: Some(low_limit_uncertainty),
        high_limit_uncertainty: Some(high_limit_uncertainty),
        minimum_uncertainty: Some(minimum_uncertainty),
    };
    let value =
        FieldValue::Filter(crate::filter::SetField::GravityMagnitudeAdaptiveMeasurement(command));
    device.call(&value).map(|_| ())
}

fn send_gravity_magnitude_adaptive_measurement_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::filter::GravityMagnitudeAdaptiveMeasurementResponse, SessionError> {
    let command = crate::filter::GravityMagnitudeAdaptiveMeasurement {
        function: crate::types::FunctionSelector(2),
        ..<crate::filter::GravityMagnitudeAdaptiveMeasurement as crate::wire::Wire>::ZERO
    };
    let value =
        FieldValue::Filter(crate::filter::SetField::GravityMagnitudeAdaptiveMeasurement(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(
            crate::filter::SetField::GravityMagnitudeAdaptiveMeasurementResponse(r),
        ) => Some(r),
        _ => None,
    })
}

fn send_gravity_magnitude_adaptive_measurement_save<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::GravityMagnitudeAdaptiveMeasurement {
        function: crate::types::FunctionSelector(3),
        ..<crate::filter::GravityMagnitudeAdaptiveMeasurement as crate::wire::Wire>::ZERO
    };
    let value =
        FieldValue::Filter(crate::filter::SetField::GravityMagnitudeAdaptiveMeasurement(command));
    device.call(&value).map(|_| ())
}

fn send_gravity_magnitude_adaptive_measurement_load<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::GravityMagnitudeAdaptiveMeasurement {
        function: crate::types::FunctionSelector(4),
        ..<crate::filter::GravityMagnitudeAdaptiveMeasurement as crate::wire::Wire>::ZERO
    };
    let value =
        FieldValue::Filter(crate::filter::SetField::GravityMagnitudeAdaptiveMeasurement(command));
    device.call(&value).map(|_| ())
}

fn send_gravity_magnitude_adaptive_measurement_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::GravityMagnitudeAdaptiveMeasurement {
        function: crate::types::FunctionSelector(5),
        ..<crate::filter::GravityMagnitudeAdaptiveMeasurement as crate::wire::Wire>::ZERO
    };
    let value =
        FieldValue::Filter(crate::filter::SetField::GravityMagnitudeAdaptiveMeasurement(command));
    device.call(&value).map(|_| ())
}

/// Magnetometer magnitude error adaptive measurement (0x0D, 0x45): one call per function.
#[derive(Debug)]
pub struct MagMagnitudeAdaptiveMeasurementCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> MagMagnitudeAdaptiveMeasurementCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        mode: crate::types::AdaptiveMeasurementMode,
        frequency: f32,
        low_limit: f32,
        high_limit: f32,
        low_limit_uncertainty: f32,
        high_limit_uncertainty: f32,
        minimum_uncertainty: f32,
    ) -> Result<(), SessionError> {
        send_mag_magnitude_adaptive_measurement_write(
            self.device,
            mode,
            frequency,
            low_limit,
            high_limit,
            low_limit_uncertainty,
            high_limit_uncertainty,
            minimum_uncertainty,
        )
    }
    /// Function `read`: returns the reply field.
    pub fn read(
        self,
    ) -> Result<crate::filter::MagMagnitudeAdaptiveMeasurementResponse, SessionError> {
        send_mag_magnitude_adaptive_measurement_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_mag_magnitude_adaptive_measurement_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_mag_magnitude_adaptive_measurement_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_mag_magnitude_adaptive_measurement_default(self.device)
    }
}

fn send_mag_magnitude_adaptive_measurement_write<T: Transport>(
    device: &mut Device<T>,
    mode: crate::types::AdaptiveMeasurementMode,
    frequency: f32,
    low_limit: f32,
    high_limit: f32,
    low_limit_uncertainty: f32,
    high_limit_uncertainty: f32,
    minimum_uncertainty: f32,
) -> Result<(), SessionError> {
    let command = crate::filter::MagMagnitudeAdaptiveMeasurement {
        function: crate::types::FunctionSelector(1),
        mode: Some(mode),
        frequency: Some(frequency),
        low_limit: Some(low_limit),
        high_limit: Some(high_limit),
        low_limit_uncertainty: Some(low_limit_uncertainty),
        high_limit_uncertainty: Some(high_limit_uncertainty),
        minimum_uncertainty: Some(minimum_uncertainty),
    };
    let value = FieldValue::Filter(crate::filter::SetField::MagMagnitudeAdaptiveMeasurement(
        command,
    ));
    device.call(&value).map(|_| ())
}

fn send_mag_magnitude_adaptive_measurement_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::filter::MagMagnitudeAdaptiveMeasurementResponse, SessionError> {
    let command = crate::filter::MagMagnitudeAdaptiveMeasurement {
        function: crate::types::FunctionSelector(2),
        ..<crate::filter::MagMagnitudeAdaptiveMeasurement as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::MagMagnitudeAdaptiveMeasurement(
        command,
    ));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::MagMagnitudeAdaptiveMeasurementResponse(r)) => {
            Some(r)
        }
        _ => None,
    })
}

fn send_mag_magnitude_adaptive_measurement_save<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::MagMagnitudeAdaptiveMeasurement {
        function: crate::types::FunctionSelector(3),
        ..<crate::filter::MagMagnitudeAdaptiveMeasurement as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::MagMagnitudeAdaptiveMeasurement(
        command,
    ));
    device.call(&value).map(|_| ())
}

fn send_mag_magnitude_adaptive_measurement_load<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::MagMagnitudeAdaptiveMeasurement {
        function: crate::types::FunctionSelector(4),
        ..<crate::filter::MagMagnitudeAdaptiveMeasurement as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::MagMagnitudeAdaptiveMeasurement(
        command,
    ));
    device.call(&value).map(|_| ())
}

fn send_mag_magnitude_adaptive_measurement_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::MagMagnitudeAdaptiveMeasurement {
        function: crate::types::FunctionSelector(5),
        ..<crate::filter::MagMagnitudeAdaptiveMeasurement as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::MagMagnitudeAdaptiveMeasurement(
        command,
    ));
    device.call(&value).map(|_| ())
}

/// Magnetometer dip angle error adaptive measurement (0x0D, 0x46): one call per function.
#[derive(Debug)]
pub struct MagDipAngleAdaptiveMeasurementCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> MagDipAngleAdaptiveMeasurementCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        mode: crate::types::AdaptiveMeasurementMode,
        frequency: f32,
        high_limit: f32,
        high_limit_uncertainty: f32,
        minimum_uncertainty: f32,
    ) -> Result<(), SessionError> {
        send_mag_dip_angle_adaptive_measurement_write(
            self.device,
            mode,
            frequency,
            high_limit,
            high_limit_uncertainty,
            minimum_uncertainty,
        )
    }
    /// Function `read`: returns the reply field.
    pub fn read(
        self,
    ) -> Result<crate::filter::MagDipAngleAdaptiveMeasurementResponse, SessionError> {
        send_mag_dip_angle_adaptive_measurement_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_mag_dip_angle_adaptive_measurement_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_mag_dip_angle_adaptive_measurement_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_mag_dip_angle_adaptive_measurement_default(self.device)
    }
}

fn send_mag_dip_angle_adaptive_measurement_write<T: Transport>(
    device: &mut Device<T>,
    mode: crate::types::AdaptiveMeasurementMode,
    frequency: f32,
    high_limit: f32,
    high_limit_uncertainty: f32,
    minimum_uncertainty: f32,
) -> Result<(), SessionError> {
    let command = crate::filter::MagDipAngleAdaptiveMeasurement {
        function: crate::types::FunctionSelector(1),
        mode: Some(mode),
        frequency: Some(frequency),
        high_limit: Some(high_limit),
        high_limit_uncertainty: Some(high_limit_uncertainty),
        minimum_uncertainty: Some(minimum_uncertainty),
    };
    let value = FieldValue::Filter(crate::filter::SetField::MagDipAngleAdaptiveMeasurement(
        command,
    ));
    device.call(&value).map(|_| ())
}

fn send_mag_dip_angle_adaptive_measurement_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::filter::MagDipAngleAdaptiveMeasurementResponse, SessionError> {
    let command = crate::filter::MagDipAngleAdaptiveMeasurement {
        function: crate::types::FunctionSelector(2),
        ..<crate::filter::MagDipAngleAdaptiveMeasurement as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::MagDipAngleAdaptiveMeasurement(
        command,
    ));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::MagDipAngleAdaptiveMeasurementResponse(r)) => {
            Some(r)
        }
        _ => None,
    })
}

fn send_mag_dip_angle_adaptive_measurement_save<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::MagDipAngleAdaptiveMeasurement {
        function: crate::types::FunctionSelector(3),
        ..<crate::filter::MagDipAngleAdaptiveMeasurement as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::MagDipAngleAdaptiveMeasurement(
        command,
    ));
    device.call(&value).map(|_| ())
}

fn send_mag_dip_angle_adaptive_measurement_load<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::MagDipAngleAdaptiveMeasurement {
        function: crate::types::FunctionSelector(4),
        ..<crate::filter::MagDipAngleAdaptiveMeasurement as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::MagDipAngleAdaptiveMeasurement(
        command,
    ));
    device.call(&value).map(|_| ())
}

fn send_mag_dip_angle_adaptive_measurement_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::MagDipAngleAdaptiveMeasurement {
        function: crate::types::FunctionSelector(5),
        ..<crate::filter::MagDipAngleAdaptiveMeasurement as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::MagDipAngleAdaptiveMeasurement(
        command,
    ));
    device.call(&value).map(|_| ())
}

/// Altitude aiding control (0x0D, 0x47): one call per function.
#[derive(Debug)]
pub struct AltitudeAidingControlCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> AltitudeAidingControlCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, source: crate::types::AltitudeAidingSource) -> Result<(), SessionError> {
        send_altitude_aiding_control_write(self.device, source)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::filter::AltitudeAidingControlResponse, SessionError> {
        send_altitude_aiding_control_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_altitude_aiding_control_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_altitude_aiding_control_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_altitude_aiding_control_default(self.device)
    }
}

fn send_altitude_aiding_control_write<T: Transport>(
    device: &mut Device<T>,
    source: crate::types::AltitudeAidingSource,
) -> Result<(), SessionError> {
    let command = crate::filter::AltitudeAidingControl {
        function: crate::types::FunctionSelector(1),
        source: Some(source),
    };
    let value = FieldValue::Filter(crate::filter::SetField::AltitudeAidingControl(command));
    device.call(&value).map(|_| ())
}

fn send_altitude_aiding_control_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::filter::AltitudeAidingControlResponse, SessionError> {
    let command = crate::filter::AltitudeAidingControl {
        function: crate::types::FunctionSelector(2),
        ..<crate::filter::AltitudeAidingControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::AltitudeAidingControl(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::AltitudeAidingControlResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_altitude_aiding_control_save<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::AltitudeAidingControl {
        function: crate::types::FunctionSelector(3),
        ..<crate::filter::AltitudeAidingControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::AltitudeAidingControl(command));
    device.call(&value).map(|_| ())
}

fn send_altitude_aiding_control_load<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::AltitudeAidingControl {
        function: crate::types::FunctionSelector(4),
        ..<crate::filter::AltitudeAidingControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::AltitudeAidingControl(command));
    device.call(&value).map(|_| ())
}

fn send_altitude_aiding_control_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::AltitudeAidingControl {
        function: crate::types::FunctionSelector(5),
        ..<crate::filter::AltitudeAidingControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::AltitudeAidingControl(command));
    device.call(&value).map(|_| ())
}

/// Pitch/roll aiding control (0x0D, 0x4B): one call per function.
#[derive(Debug)]
pub struct PitchRollAidingControlCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> PitchRollAidingControlCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, source: crate::types::PitchRollAidingSource) -> Result<(), SessionError> {
        send_pitch_roll_aiding_control_write(self.device, source)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::filter::PitchRollAidingControlResponse, SessionError> {
        send_pitch_roll_aiding_control_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_pitch_roll_aiding_control_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_pitch_roll_aiding_control_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_pitch_roll_aiding_control_default(self.device)
    }
}

fn send_pitch_roll_aiding_control_write<T: Transport>(
    device: &mut Device<T>,
    source: crate::types::PitchRollAidingSource,
) -> Result<(), SessionError> {
    let command = crate::filter::PitchRollAidingControl {
        function: crate::types::FunctionSelector(1),
        source: Some(source),
    };
    let value = FieldValue::Filter(crate::filter::SetField::PitchRollAidingControl(command));
    device.call(&value).map(|_| ())
}

fn send_pitch_roll_aiding_control_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::filter::PitchRollAidingControlResponse, SessionError> {
    let command = crate::filter::PitchRollAidingControl {
        function: crate::types::FunctionSelector(2),
        ..<crate::filter::PitchRollAidingControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::PitchRollAidingControl(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::PitchRollAidingControlResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_pitch_roll_aiding_control_save<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::PitchRollAidingControl {
        function: crate::types::FunctionSelector(3),
        ..<crate::filter::PitchRollAidingControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::PitchRollAidingControl(command));
    device.call(&value).map(|_| ())
}

fn send_pitch_roll_aiding_control_load<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::PitchRollAidingControl {
        function: crate::types::FunctionSelector(4),
        ..<crate::filter::PitchRollAidingControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::PitchRollAidingControl(command));
    device.call(&value).map(|_| ())
}

fn send_pitch_roll_aiding_control_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::PitchRollAidingControl {
        function: crate::types::FunctionSelector(5),
        ..<crate::filter::PitchRollAidingControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::PitchRollAidingControl(command));
    device.call(&value).map(|_| ())
}

/// Inclination source (0x0D, 0x4C): one call per function.
#[derive(Debug)]
pub struct InclinationSourceCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> InclinationSourceCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        source: crate::types::MagneticParamSource,
        inclination: f32,
    ) -> Result<(), SessionError> {
        send_inclination_source_write(self.device, source, inclination)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::filter::InclinationSourceResponse, SessionError> {
        send_inclination_source_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_inclination_source_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_inclination_source_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_inclination_source_default(self.device)
    }
}

fn send_inclination_source_write<T: Transport>(
    device: &mut Device<T>,
    source: crate::types::MagneticParamSource,
    inclination: f32,
) -> Result<(), SessionError> {
    let command = crate::filter::InclinationSource {
        function: crate::types::FunctionSelector(1),
        source: Some(source),
        inclination: Some(inclination),
    };
    let value = FieldValue::Filter(crate::filter::SetField::InclinationSource(command));
    device.call(&value).map(|_| ())
}

fn send_inclination_source_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::filter::InclinationSourceResponse, SessionError> {
    let command = crate::filter::InclinationSource {
        function: crate::types::FunctionSelector(2),
        ..<crate::filter::InclinationSource as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::InclinationSource(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::InclinationSourceResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_inclination_source_save<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::filter::InclinationSource {
        function: crate::types::FunctionSelector(3),
        ..<crate::filter::InclinationSource as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::InclinationSource(command));
    device.call(&value).map(|_| ())
}

fn send_inclination_source_load<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::filter::InclinationSource {
        function: crate::types::FunctionSelector(4),
        ..<crate::filter::InclinationSource as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::InclinationSource(command));
    device.call(&value).map(|_| ())
}

fn send_inclination_source_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::InclinationSource {
        function: crate::types::FunctionSelector(5),
        ..<crate::filter::InclinationSource as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::InclinationSource(command));
    device.call(&value).map(|_| ())
}

/// Magnetic field magnitude source (0x0D, 0x4D): one call per function.
#[derive(Debug)]
pub struct MagneticFieldMagnitudeSourceCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> MagneticFieldMagnitudeSourceCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        source: crate::types::MagneticParamSource,
        magnitude: f32,
    ) -> Result<(), SessionError> {
        send_magnetic_field_magnitude_source_write(self.device, source, magnitude)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::filter::MagneticFieldMagnitudeSourceResponse, SessionError> {
        send_magnetic_field_magnitude_source_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_magnetic_field_magnitude_source_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_magnetic_field_magnitude_source_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_magnetic_field_magnitude_source_default(self.device)
    }
}

fn send_magnetic_field_magnitude_source_write<T: Transport>(
    device: &mut Device<T>,
    source: crate::types::MagneticParamSource,
    magnitude: f32,
) -> Result<(), SessionError> {
    let command = crate::filter::MagneticFieldMagnitudeSource {
        function: crate::types::FunctionSelector(1),
        source: Some(source),
        magnitude: Some(magnitude),
    };
    let value = FieldValue::Filter(crate::filter::SetField::MagneticFieldMagnitudeSource(
        command,
    ));
    device.call(&value).map(|_| ())
}

fn send_magnetic_field_magnitude_source_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::filter::MagneticFieldMagnitudeSourceResponse, SessionError> {
    let command = crate::filter::MagneticFieldMagnitudeSource {
        function: crate::types::FunctionSelector(2),
        ..<crate::filter::MagneticFieldMagnitudeSource as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::MagneticFieldMagnitudeSource(
        command,
    ));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::MagneticFieldMagnitudeSourceResponse(r)) => {
            Some(r)
        }
        _ => None,
    })
}

fn send_magnetic_field_magnitude_source_save<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::MagneticFieldMagnitudeSource {
        function: crate::types::FunctionSelector(3),
        ..<crate::filter::MagneticFieldMagnitudeSource as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::MagneticFieldMagnitudeSource(
        command,
    ));
    device.call(&value).map(|_| ())
}

fn send_magnetic_field_magnitude_source_load<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::MagneticFieldMagnitudeSource {
        function: crate::types::FunctionSelector(4),
        ..<crate::filter::MagneticFieldMagnitudeSource as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::MagneticFieldMagnitudeSource(
        command,
    ));
    device.call(&value).map(|_| ())
}

fn send_magnetic_field_magnitude_source_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::MagneticFieldMagnitudeSource {
        function: crate::types::FunctionSelector(5),
        ..<crate::filter::MagneticFieldMagnitudeSource as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::MagneticFieldMagnitudeSource(
        command,
    ));
    device.call(&value).map(|_| ())
}

/// Aiding measurement control (0x0D, 0x50): one call per function.
#[derive(Debug)]
pub struct AidingMeasurementControlCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> AidingMeasurementControlCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        source: crate::types::AidingMeasurementSource,
        enable: bool,
    ) -> Result<(), SessionError> {
        send_aiding_measurement_control_write(self.device, source, enable)
    }
    /// Function `read`: returns the reply field.
    pub fn read(
        self,
        source: crate::types::AidingMeasurementSource,
    ) -> Result<crate::filter::AidingMeasurementControlResponse, SessionError> {
        send_aiding_measurement_control_read(self.device, source)
    }
    /// Function `save`.
    pub fn save(self, source: crate::types::AidingMeasurementSource) -> Result<(), SessionError> {
        send_aiding_measurement_control_save(self.device, source)
    }
    /// Function `load`.
    pub fn load(self, source: crate::types::AidingMeasurementSource) -> Result<(), SessionError> {
        send_aiding_measurement_control_load(self.device, source)
    }
    /// Function `default`.
    pub fn default(
        self,
        source: crate::types::AidingMeasurementSource,
    ) -> Result<(), SessionError> {
        send_aiding_measurement_control_default(self.device, source)
    }
}

fn send_aiding_measurement_control_write<T: Transport>(
    device: &mut Device<T>,
    source: crate::types::AidingMeasurementSource,
    enable: bool,
) -> Result<(), SessionError> {
    let command = crate::filter::AidingMeasurementControl {
        function: crate::types::FunctionSelector(1),
        source,
        enable: Some(enable),
    };
    let value = FieldValue::Filter(crate::filter::SetField::AidingMeasurementControl(command));
    device.call(&value).map(|_| ())
}

fn send_aiding_measurement_control_read<T: Transport>(
    device: &mut Device<T>,
    source: crate::types::AidingMeasurementSource,
) -> Result<crate::filter::AidingMeasurementControlResponse, SessionError> {
    let command = crate::filter::AidingMeasurementControl {
        function: crate::types::FunctionSelector(2),
        source,
        ..<crate::filter::AidingMeasurementControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::AidingMeasurementControl(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::AidingMeasurementControlResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_aiding_measurement_control_save<T: Transport>(
    device: &mut Device<T>,
    source: crate::types::AidingMeasurementSource,
) -> Result<(), SessionError> {
    let command = crate::filter::AidingMeasurementControl {
        function: crate::types::FunctionSelector(3),
        source,
        ..<crate::filter::AidingMeasurementControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::AidingMeasurementControl(command));
    device.call(&value).map(|_| ())
}

fn send_aiding_measurement_control_load<T: Transport>(
    device: &mut Device<T>,
    source: crate::types::AidingMeasurementSource,
) -> Result<(), SessionError> {
    let command = crate::filter::AidingMeasurementControl {
        function: crate::types::FunctionSelector(4),
        source,
        ..<crate::filter::AidingMeasurementControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::AidingMeasurementControl(command));
    device.call(&value).map(|_| ())
}

fn send_aiding_measurement_control_default<T: Transport>(
    device: &mut Device<T>,
    source: crate::types::AidingMeasurementSource,
) -> Result<(), SessionError> {
    let command = crate::filter::AidingMeasurementControl {
        function: crate::types::FunctionSelector(5),
        source,
        ..<crate::filter::AidingMeasurementControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::AidingMeasurementControl(command));
    device.call(&value).map(|_| ())
}

/// Navigation filter initialization (0x0D, 0x52): one call per function.
#[derive(Debug)]
pub struct InitializationConfigurationCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> InitializationConfigurationCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        wait_for_run_command: u8,
        initial_cond_src: crate::types::FilterInitialConditionSource,
        auto_heading_alignment_selector: crate::types::HeadingAlignmentMethods,
        initial_heading: f32,
        initial_pitch: f32,
        initial_roll: f32,
        initial_position: [f32; 3],
        initial_velocity: [f32; 3],
        reference_frame_selector: crate::types::FilterReferenceFrame,
    ) -> Result<(), SessionError> {
        send_initialization_configuration_write(
            self.device,
            wait_for_run_command,
            initial_cond_src,
            auto_heading_alignment_selector,
            initial_heading,
            initial_pitch,
            initial_roll,
            initial_position,
            initial_velocity,
            reference_frame_selector,
        )
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::filter::InitializationConfigurationResponse, SessionError> {
        send_initialization_configuration_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_initialization_configuration_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_initialization_configuration_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_initialization_configuration_default(self.device)
    }
}

fn send_initialization_configuration_write<T: Transport>(
    device: &mut Device<T>,
    wait_for_run_command: u8,
    initial_cond_src: crate::types::FilterInitialConditionSource,
    auto_heading_alignment_selector: crate::types::HeadingAlignmentMethods,
    initial_heading: f32,
    initial_pitch: f32,
    initial_roll: f32,
    initial_position: [f32; 3],
    initial_velocity: [f32; 3],
    reference_frame_selector: crate::types::FilterReferenceFrame,
) -> Result<(), SessionError> {
    let command = crate::filter::InitializationConfiguration {
        function: crate::types::FunctionSelector(1),
        wait_for_run_command: Some(wait_for_run_command),
        initial_cond_src: Some(initial_cond_src),
        auto_heading_alignment_selector: Some(auto_heading_alignment_selector),
        initial_heading: Some(initial_heading),
        initial_pitch: Some(initial_pitch),
        initial_roll: Some(initial_roll),
        initial_position: Some(initial_position),
        initial_velocity: Some(initial_velocity),
        reference_frame_selector: Some(reference_frame_selector),
    };
    let value = FieldValue::Filter(crate::filter::SetField::InitializationConfiguration(
        command,
    ));
    device.call(&value).map(|_| ())
}

fn send_initialization_configuration_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::filter::InitializationConfigurationResponse, SessionError> {
    let command = crate::filter::InitializationConfiguration {
        function: crate::types::FunctionSelector(2),
        ..<crate::filter::InitializationConfiguration as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::InitializationConfiguration(
        command,
    ));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::InitializationConfigurationResponse(r)) => {
            Some(r)
        }
        _ => None,
    })
}

fn send_initialization_configuration_save<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::InitializationConfiguration {
        function: crate::types::FunctionSelector(3),
        ..<crate::filter::InitializationConfiguration as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::InitializationConfiguration(
        command,
    ));
    device.call(&value).map(|_| ())
}

fn send_initialization_configuration_load<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::InitializationConfiguration {
        function: crate::types::FunctionSelector(4),
        ..<crate::filter::InitializationConfiguration as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::InitializationConfiguration(
        command,
    ));
    device.call(&value).map(|_| ())
}

fn send_initialization_configuration_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::InitializationConfiguration {
        function: crate::types::FunctionSelector(5),
        ..<crate::filter::InitializationConfiguration as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::InitializationConfiguration(
        command,
    ));
    device.call(&value).map(|_| ())
}

/// Adaptive filter control (0x0D, 0x53): one call per function.
#[derive(Debug)]
pub struct AdaptiveFilterControlCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> AdaptiveFilterControlCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        level: crate::types::AdaptiveFilterLevel,
        time_limit: u16,
    ) -> Result<(), SessionError> {
        send_adaptive_filter_control_write(self.device, level, time_limit)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::filter::AdaptiveFilterControlResponse, SessionError> {
        send_adaptive_filter_control_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_adaptive_filter_control_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_adaptive_filter_control_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_adaptive_filter_control_default(self.device)
    }
}

fn send_adaptive_filter_control_write<T: Transport>(
    device: &mut Device<T>,
    level: crate::types::AdaptiveFilterLevel,
    time_limit: u16,
) -> Result<(), SessionError> {
    let command = crate::filter::AdaptiveFilterControl {
        function: crate::types::FunctionSelector(1),
        level: Some(level),
        time_limit: Some(time_limit),
    };
    let value = FieldValue::Filter(crate::filter::SetField::AdaptiveFilterControl(command));
    device.call(&value).map(|_| ())
}

fn send_adaptive_filter_control_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::filter::AdaptiveFilterControlResponse, SessionError> {
    let command = crate::filter::AdaptiveFilterControl {
        function: crate::types::FunctionSelector(2),
        ..<crate::filter::AdaptiveFilterControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::AdaptiveFilterControl(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::AdaptiveFilterControlResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_adaptive_filter_control_save<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::AdaptiveFilterControl {
        function: crate::types::FunctionSelector(3),
        ..<crate::filter::AdaptiveFilterControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::AdaptiveFilterControl(command));
    device.call(&value).map(|_| ())
}

fn send_adaptive_filter_control_load<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::AdaptiveFilterControl {
        function: crate::types::FunctionSelector(4),
        ..<crate::filter::AdaptiveFilterControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::AdaptiveFilterControl(command));
    device.call(&value).map(|_| ())
}

fn send_adaptive_filter_control_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::AdaptiveFilterControl {
        function: crate::types::FunctionSelector(5),
        ..<crate::filter::AdaptiveFilterControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::AdaptiveFilterControl(command));
    device.call(&value).map(|_| ())
}

/// GNSS multi-antenna offset (0x0D, 0x54): one call per function.
#[derive(Debug)]
pub struct MultiAntennaOffsetCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> MultiAntennaOffsetCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, receiver_id: u8, antenna_offset: [f32; 3]) -> Result<(), SessionError> {
        send_multi_antenna_offset_write(self.device, receiver_id, antenna_offset)
    }
    /// Function `read`: returns the reply field.
    pub fn read(
        self,
        receiver_id: u8,
    ) -> Result<crate::filter::MultiAntennaOffsetResponse, SessionError> {
        send_multi_antenna_offset_read(self.device, receiver_id)
    }
    /// Function `save`.
    pub fn save(self, receiver_id: u8) -> Result<(), SessionError> {
        send_multi_antenna_offset_save(self.device, receiver_id)
    }
    /// Function `load`.
    pub fn load(self, receiver_id: u8) -> Result<(), SessionError> {
        send_multi_antenna_offset_load(self.device, receiver_id)
    }
    /// Function `default`.
    pub fn default(self, receiver_id: u8) -> Result<(), SessionError> {
        send_multi_antenna_offset_default(self.device, receiver_id)
    }
}

fn send_multi_antenna_offset_write<T: Transport>(
    device: &mut Device<T>,
    receiver_id: u8,
    antenna_offset: [f32; 3],
) -> Result<(), SessionError> {
    let command = crate::filter::MultiAntennaOffset {
        function: crate::types::FunctionSelector(1),
        receiver_id,
        antenna_offset: Some(antenna_offset),
    };
    let value = FieldValue::Filter(crate::filter::SetField::MultiAntennaOffset(command));
    device.call(&value).map(|_| ())
}

fn send_multi_antenna_offset_read<T: Transport>(
    device: &mut Device<T>,
    receiver_id: u8,
) -> Result<crate::filter::MultiAntennaOffsetResponse, SessionError> {
    let command = crate::filter::MultiAntennaOffset {
        function: crate::types::FunctionSelector(2),
        receiver_id,
        ..<crate::filter::MultiAntennaOffset as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::MultiAntennaOffset(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::MultiAntennaOffsetResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_multi_antenna_offset_save<T: Transport>(
    device: &mut Device<T>,
    receiver_id: u8,
) -> Result<(), SessionError> {
    let command = crate::filter::MultiAntennaOffset {
        function: crate::types::FunctionSelector(3),
        receiver_id,
        ..<crate::filter::MultiAntennaOffset as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::MultiAntennaOffset(command));
    device.call(&value).map(|_| ())
}

fn send_multi_antenna_offset_load<T: Transport>(
    device: &mut Device<T>,
    receiver_id: u8,
) -> Result<(), SessionError> {
    let command = crate::filter::MultiAntennaOffset {
        function: crate::types::FunctionSelector(4),
        receiver_id,
        ..<crate::filter::MultiAntennaOffset as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::MultiAntennaOffset(command));
    device.call(&value).map(|_| ())
}

fn send_multi_antenna_offset_default<T: Transport>(
    device: &mut Device<T>,
    receiver_id: u8,
) -> Result<(), SessionError> {
    let command = crate::filter::MultiAntennaOffset {
        function: crate::types::FunctionSelector(5),
        receiver_id,
        ..<crate::filter::MultiAntennaOffset as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::MultiAntennaOffset(command));
    device.call(&value).map(|_| ())
}

/// Relative position configuration (0x0D, 0x55): one call per function.
#[derive(Debug)]
pub struct RelativePositionConfigurationCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> RelativePositionConfigurationCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        source: crate::types::RelativePositionSource,
        reference_frame_selector: crate::types::FilterReferenceFrame,
        reference_coordinates: [f64; 3],
    ) -> Result<(), SessionError> {
        send_relative_position_configuration_write(
            self.device,
            source,
            reference_frame_selector,
            reference_coordinates,
        )
    }
    /// Function `read`: returns the reply field.
    pub fn read(
        self,
    ) -> Result<crate::filter::RelativePositionConfigurationResponse, SessionError> {
        send_relative_position_configuration_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_relative_position_configuration_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_relative_position_configuration_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_relative_position_configuration_default(self.device)
    }
}

fn send_relative_position_configuration_write<T: Transport>(
    device: &mut Device<T>,
    source: crate::types::RelativePositionSource,
    reference_frame_selector: crate::types::FilterReferenceFrame,
    reference_coordinates: [f64; 3],
) -> Result<(), SessionError> {
    let command = crate::filter::RelativePositionConfiguration {
        function: crate::types::FunctionSelector(1),
        source: Some(source),
        reference_frame_selector: Some(reference_frame_selector),
        reference_coordinates: Some(reference_coordinates),
    };
    let value = FieldValue::Filter(crate::filter::SetField::RelativePositionConfiguration(
        command,
    ));
    device.call(&value).map(|_| ())
}

fn send_relative_position_configuration_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::filter::RelativePositionConfigurationResponse, SessionError> {
    let command = crate::filter::RelativePositionConfiguration {
        function: crate::types::FunctionSelector(2),
        ..<crate::filter::RelativePositionConfiguration as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::RelativePositionConfiguration(
        command,
    ));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::RelativePositionConfigurationResponse(r)) => {
            Some(r)
        }
        _ => None,
    })
}

fn send_relative_position_configuration_save<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::RelativePositionConfiguration {
        function: crate::types::FunctionSelector(3),
        ..<crate::filter::RelativePositionConfiguration as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::RelativePositionConfiguration(
        command,
    ));
    device.call(&value).map(|_| ())
}

fn send_relative_position_configuration_load<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::RelativePositionConfiguration {
        function: crate::types::FunctionSelector(4),
        ..<crate::filter::RelativePositionConfiguration as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::RelativePositionConfiguration(
        command,
    ));
    device.call(&value).map(|_| ())
}

fn send_relative_position_configuration_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::RelativePositionConfiguration {
        function: crate::types::FunctionSelector(5),
        ..<crate::filter::RelativePositionConfiguration as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::RelativePositionConfiguration(
        command,
    ));
    device.call(&value).map(|_| ())
}

/// Reference point lever arm (0x0D, 0x56): one call per function.
#[derive(Debug)]
pub struct ReferencePointLeverArmCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> ReferencePointLeverArmCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        ref_point_sel: crate::types::ReferencePointSelector,
        lever_arm_offset: [f32; 3],
    ) -> Result<(), SessionError> {
        send_reference_point_lever_arm_write(self.device, ref_point_sel, lever_arm_offset)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::filter::ReferencePointLeverArmResponse, SessionError> {
        send_reference_point_lever_arm_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_reference_point_lever_arm_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_reference_point_lever_arm_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_reference_point_lever_arm_default(self.device)
    }
}

fn send_reference_point_lever_arm_write<T: Transport>(
    device: &mut Device<T>,
    ref_point_sel: crate::types::ReferencePointSelector,
    lever_arm_offset: [f32; 3],
) -> Result<(), SessionError> {
    let command = crate::filter::ReferencePointLeverArm {
        function: crate::types::FunctionSelector(1),
        ref_point_sel: Some(ref_point_sel),
        lever_arm_offset: Some(lever_arm_offset),
    };
    let value = FieldValue::Filter(crate::filter::SetField::ReferencePointLeverArm(command));
    device.call(&value).map(|_| ())
}

fn send_reference_point_lever_arm_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::filter::ReferencePointLeverArmResponse, SessionError> {
    let command = crate::filter::ReferencePointLeverArm {
        function: crate::types::FunctionSelector(2),
        ..<crate::filter::ReferencePointLeverArm as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::ReferencePointLeverArm(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::ReferencePointLeverArmResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_reference_point_lever_arm_save<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::ReferencePointLeverArm {
        function: crate::types::FunctionSelector(3),
        ..<crate::filter::ReferencePointLeverArm as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::ReferencePointLeverArm(command));
    device.call(&value).map(|_| ())
}

fn send_reference_point_lever_arm_load<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::ReferencePointLeverArm {
        function: crate::types::FunctionSelector(4),
        ..<crate::filter::ReferencePointLeverArm as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::ReferencePointLeverArm(command));
    device.call(&value).map(|_| ())
}

fn send_reference_point_lever_arm_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::ReferencePointLeverArm {
        function: crate::types::FunctionSelector(5),
        ..<crate::filter::ReferencePointLeverArm as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::ReferencePointLeverArm(command));
    device.call(&value).map(|_| ())
}

/// Measurement speed lever arm (0x0D, 0x61): one call per function.
#[derive(Debug)]
pub struct SpeedLeverArmCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> SpeedLeverArmCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, source: u8, lever_arm_offset: [f32; 3]) -> Result<(), SessionError> {
        send_speed_lever_arm_write(self.device, source, lever_arm_offset)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self, source: u8) -> Result<crate::filter::SpeedLeverArmResponse, SessionError> {
        send_speed_lever_arm_read(self.device, source)
    }
    /// Function `save`.
    pub fn save(self, source: u8) -> Result<(), SessionError> {
        send_speed_lever_arm_save(self.device, source)
    }
    /// Function `load`.
    pub fn load(self, source: u8) -> Result<(), SessionError> {
        send_speed_lever_arm_load(self.device, source)
    }
    /// Function `default`.
    pub fn default(self, source: u8) -> Result<(), SessionError> {
        send_speed_lever_arm_default(self.device, source)
    }
}

fn send_speed_lever_arm_write<T: Transport>(
    device: &mut Device<T>,
    source: u8,
    lever_arm_offset: [f32; 3],
) -> Result<(), SessionError> {
    let command = crate::filter::SpeedLeverArm {
        function: crate::types::FunctionSelector(1),
        source,
        lever_arm_offset: Some(lever_arm_offset),
    };
    let value = FieldValue::Filter(crate::filter::SetField::SpeedLeverArm(command));
    device.call(&value).map(|_| ())
}

fn send_speed_lever_arm_read<T: Transport>(
    device: &mut Device<T>,
    source: u8,
) -> Result<crate::filter::SpeedLeverArmResponse, SessionError> {
    let command = crate::filter::SpeedLeverArm {
        function: crate::types::FunctionSelector(2),
        source,
        ..<crate::filter::SpeedLeverArm as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::SpeedLeverArm(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::SpeedLeverArmResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_speed_lever_arm_save<T: Transport>(
    device: &mut Device<T>,
    source: u8,
) -> Result<(), SessionError> {
    let command = crate::filter::SpeedLeverArm {
        function: crate::types::FunctionSelector(3),
        source,
        ..<crate::filter::SpeedLeverArm as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::SpeedLeverArm(command));
    device.call(&value).map(|_| ())
}

fn send_speed_lever_arm_load<T: Transport>(
    device: &mut Device<T>,
    source: u8,
) -> Result<(), SessionError> {
    let command = crate::filter::SpeedLeverArm {
        function: crate::types::FunctionSelector(4),
        source,
        ..<crate::filter::SpeedLeverArm as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::SpeedLeverArm(command));
    device.call(&value).map(|_| ())
}

fn send_speed_lever_arm_default<T: Transport>(
    device: &mut Device<T>,
    source: u8,
) -> Result<(), SessionError> {
    let command = crate::filter::SpeedLeverArm {
        function: crate::types::FunctionSelector(5),
        source,
        ..<crate::filter::SpeedLeverArm as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::SpeedLeverArm(command));
    device.call(&value).map(|_| ())
}

/// Wheeled vehicle constraint control (0x0D, 0x63): one call per function.
#[derive(Debug)]
pub struct WheeledVehicleConstraintControlCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> WheeledVehicleConstraintControlCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, enable: u8) -> Result<(), SessionError> {
        send_wheeled_vehicle_constraint_control_write(self.device, enable)
    }
    /// Function `read`: returns the reply field.
    pub fn read(
        self,
    ) -> Result<crate::filter::WheeledVehicleConstraintControlResponse, SessionError> {
        send_wheeled_vehicle_constraint_control_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_wheeled_vehicle_constraint_control_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_wheeled_vehicle_constraint_control_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_wheeled_vehicle_constraint_control_default(self.device)
    }
}

fn send_wheeled_vehicle_constraint_control_write<T: Transport>(
    device: &mut Device<T>,
    enable: u8,
) -> Result<(), SessionError> {
    let command = crate::filter::WheeledVehicleConstraintControl {
        function: crate::types::FunctionSelector(1),
        enable: Some(enable),
    };
    let value = FieldValue::Filter(crate::filter::SetField::WheeledVehicleConstraintControl(
        command,
    ));
    device.call(&value).map(|_| ())
}

fn send_wheeled_vehicle_constraint_control_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::filter::WheeledVehicleConstraintControlResponse, SessionError> {
    let command = crate::filter::WheeledVehicleConstraintControl {
        function: crate::types::FunctionSelector(2),
        ..<crate::filter::WheeledVehicleConstraintControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::WheeledVehicleConstraintControl(
        command,
    ));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::WheeledVehicleConstraintControlResponse(r)) => {
            Some(r)
        }
        _ => None,
    })
}

fn send_wheeled_vehicle_constraint_control_save<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::WheeledVehicleConstraintControl {
        function: crate::types::FunctionSelector(3),
        ..<crate::filter::WheeledVehicleConstraintControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::WheeledVehicleConstraintControl(
        command,
    ));
    device.call(&value).map(|_| ())
}

fn send_wheeled_vehicle_constraint_control_load<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::WheeledVehicleConstraintControl {
        function: crate::types::FunctionSelector(4),
        ..<crate::filter::WheeledVehicleConstraintControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::WheeledVehicleConstraintControl(
        command,
    ));
    device.call(&value).map(|_| ())
}

fn send_wheeled_vehicle_constraint_control_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::WheeledVehicleConstraintControl {
        function: crate::types::FunctionSelector(5),
        ..<crate::filter::WheeledVehicleConstraintControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::WheeledVehicleConstraintControl(
        command,
    ));
    device.call(&value).map(|_| ())
}

/// GNSS antenna offset calibration control (0x0D, 0x64): one call per function.
#[derive(Debug)]
pub struct GnssAntennaCalibrationControlCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> GnssAntennaCalibrationControlCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, enable: u8, max_offset: f32) -> Result<(), SessionError> {
        send_gnss_antenna_calibration_control_write(self.device, enable, max_offset)
    }
    /// Function `read`: returns the reply field.
    pub fn read(
        self,
    ) -> Result<crate::filter::GnssAntennaCalibrationControlResponse, SessionError> {
        send_gnss_antenna_calibration_control_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_gnss_antenna_calibration_control_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_gnss_antenna_calibration_control_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_gnss_antenna_calibration_control_default(self.device)
    }
}

fn send_gnss_antenna_calibration_control_write<T: Transport>(
    device: &mut Device<T>,
    enable: u8,
    max_offset: f32,
) -> Result<(), SessionError> {
    let command = crate::filter::GnssAntennaCalibrationControl {
        function: crate::types::FunctionSelector(1),
        enable: Some(enable),
        max_offset: Some(max_offset),
    };
    let value = FieldValue::Filter(crate::filter::SetField::GnssAntennaCalibrationControl(
        command,
    ));
    device.call(&value).map(|_| ())
}

fn send_gnss_antenna_calibration_control_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::filter::GnssAntennaCalibrationControlResponse, SessionError> {
    let command = crate::filter::GnssAntennaCalibrationControl {
        function: crate::types::FunctionSelector(2),
        ..<crate::filter::GnssAntennaCalibrationControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::GnssAntennaCalibrationControl(
        command,
    ));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Filter(crate::filter::SetField::GnssAntennaCalibrationControlResponse(r)) => {
            Some(r)
        }
        _ => None,
    })
}

fn send_gnss_antenna_calibration_control_save<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::GnssAntennaCalibrationControl {
        function: crate::types::FunctionSelector(3),
        ..<crate::filter::GnssAntennaCalibrationControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::GnssAntennaCalibrationControl(
        command,
    ));
    device.call(&value).map(|_| ())
}

fn send_gnss_antenna_calibration_control_load<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::GnssAntennaCalibrationControl {
        function: crate::types::FunctionSelector(4),
        ..<crate::filter::GnssAntennaCalibrationControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::GnssAntennaCalibrationControl(
        command,
    ));
    device.call(&value).map(|_| ())
}

fn send_gnss_antenna_calibration_control_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::filter::GnssAntennaCalibrationControl {
        function: crate::types::FunctionSelector(5),
        ..<crate::filter::GnssAntennaCalibrationControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Filter(crate::filter::SetField::GnssAntennaCalibrationControl(
        command,
    ));
    device.call(&value).map(|_| ())
}

impl<T: Transport> Device<T> {
    /// Commands of set 0x0E (GNSS Command Set).
    pub fn gnss(&mut self) -> GnssCommands<'_, T> {
        GnssCommands { device: self }
    }
}

/// Commands of set 0x0E (GNSS Command Set), bound to a [`Device`].
#[derive(Debug)]
pub struct GnssCommands<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> GnssCommands<'d, T> {
    /// Receiver info (0x01). Sends `receiver_info`: returns the reply field.
    pub fn receiver_info(self) -> Result<crate::gnss::ReceiverInfoResponse, SessionError> {
        send_receiver_info_receiver_info(self.device)
    }
    /// Signal configuration (0x02).
    pub fn signal_configuration(self) -> SignalConfigurationCommand<'d, T> {
        SignalConfigurationCommand {
            device: self.device,
        }
    }
    /// SPARTN configuration (0x20).
    pub fn spartn_configuration(self) -> SpartnConfigurationCommand<'d, T> {
        SpartnConfigurationCommand {
            device: self.device,
        }
    }
}

fn send_receiver_info_receiver_info<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::gnss::ReceiverInfoResponse, SessionError> {
    let command = crate::gnss::ReceiverInfo {};
    let value = FieldValue::Gnss(crate::gnss::SetField::ReceiverInfo(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Gnss(crate::gnss::SetField::ReceiverInfoResponse(r)) => Some(r),
        _ => None,
    })
}

/// Signal configuration (0x0E, 0x02): one call per function.
#[derive(Debug)]
pub struct SignalConfigurationCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> SignalConfigurationCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        gps_enable: crate::types::GnssGpsSignals,
        glonass_enable: crate::types::GnssGlonassSignals,
        galileo_enable: crate::types::GnssGalileoSignals,
        beidou_enable: crate::types::GnssBeidouSignals,
        reserved: [u8; 4],
    ) -> Result<(), SessionError> {
        send_signal_configuration_write(
            self.device,
            gps_enable,
            glonass_enable,
            galileo_enable,
            beidou_enable,
            reserved,
        )
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::gnss::SignalConfigurationResponse, SessionError> {
        send_signal_configuration_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_signal_configuration_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_signal_configuration_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_signal_configuration_default(self.device)
    }
}

fn send_signal_configuration_write<T: Transport>(
    device: &mut Device<T>,
    gps_enable: crate::types::GnssGpsSignals,
    glonass_enable: crate::types::GnssGlonassSignals,
    galileo_enable: crate::types::GnssGalileoSignals,
    beidou_enable: crate::types::GnssBeidouSignals,
    reserved: [u8; 4],
) -> Result<(), SessionError> {
    let command = crate::gnss::SignalConfiguration {
        function: crate::types::FunctionSelector(1),
        gps_enable: Some(gps_enable),
        glonass_enable: Some(glonass_enable),
        galileo_enable: Some(galileo_enable),
        beidou_enable: Some(beidou_enable),
        reserved: Some(reserved),
    };
    let value = FieldValue::Gnss(crate::gnss::SetField::SignalConfiguration(command));
    device.call(&value).map(|_| ())
}

fn send_signal_configuration_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::gnss::SignalConfigurationResponse, SessionError> {
    let command = crate::gnss::SignalConfiguration {
        function: crate::types::FunctionSelector(2),
        ..<crate::gnss::SignalConfiguration as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Gnss(crate::gnss::SetField::SignalConfiguration(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Gnss(crate::gnss::SetField::SignalConfigurationResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_signal_configuration_save<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::gnss::SignalConfiguration {
        function: crate::types::FunctionSelector(3),
        ..<crate::gnss::SignalConfiguration as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Gnss(crate::gnss::SetField::SignalConfiguration(command));
    device.call(&value).map(|_| ())
}

fn send_signal_configuration_load<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::gnss::SignalConfiguration {
        function: crate::types::FunctionSelector(4),
        ..<crate::gnss::SignalConfiguration as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Gnss(crate::gnss::SetField::SignalConfiguration(command));
    device.call(&value).map(|_| ())
}

fn send_signal_configuration_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::gnss::SignalConfiguration {
        function: crate::types::FunctionSelector(5),
        ..<crate::gnss::SignalConfiguration as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Gnss(crate::gnss::SetField::SignalConfiguration(command));
    device.call(&value).map(|_| ())
}

/// SPARTN configuration (0x0E, 0x20): one call per function.
#[derive(Debug)]
pub struct SpartnConfigurationCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> SpartnConfigurationCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        enable: u8,
        r#type: crate::types::SpartnConnectionType,
        current_key_tow: u32,
        current_key_week: u16,
        current_key: crate::wire::Str<32>,
        next_key_tow: u32,
        next_key_week: u16,
        next_key: crate::wire::Str<32>,
    ) -> Result<(), SessionError> {
        send_spartn_configuration_write(
            self.device,
            enable,
            r#type,
            current_key_tow,
            current_key_week,
            current_key,
            next_key_tow,
            next_key_week,
            next_key,
        )
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::gnss::SpartnConfigurationResponse, SessionError> {
        send_spartn_configuration_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_spartn_configuration_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_spartn_configuration_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_spartn_configuration_default(self.device)
    }
}

fn send_spartn_configuration_write<T: Transport>(
    device: &mut Device<T>,
    enable: u8,
    r#type: crate::types::SpartnConnectionType,
    current_key_tow: u32,
    current_key_week: u16,
    current_key: crate::wire::Str<32>,
    next_key_tow: u32,
    next_key_week: u16,
    next_key: crate::wire::Str<32>,
) -> Result<(), SessionError> {
    let command = crate::gnss::SpartnConfiguration {
        function: crate::types::FunctionSelector(1),
        enable: Some(enable),
        r#type: Some(r#type),
        current_key_tow: Some(current_key_tow),
        current_key_week: Some(current_key_week),
        current_key: Some(current_key),
        next_key_tow: Some(next_key_tow),
        next_key_week: Some(next_key_week),
        next_key: Some(next_key),
    };
    let value = FieldValue::Gnss(crate::gnss::SetField::SpartnConfiguration(command));
    device.call(&value).map(|_| ())
}

fn send_spartn_configuration_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::gnss::SpartnConfigurationResponse, SessionError> {
    let command = crate::gnss::SpartnConfiguration {
        function: crate::types::FunctionSelector(2),
        ..<crate::gnss::SpartnConfiguration as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Gnss(crate::gnss::SetField::SpartnConfiguration(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Gnss(crate::gnss::SetField::SpartnConfigurationResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_spartn_configuration_save<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::gnss::SpartnConfiguration {
        function: crate::types::FunctionSelector(3),
        ..<crate::gnss::SpartnConfiguration as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Gnss(crate::gnss::SetField::SpartnConfiguration(command));
    device.call(&value).map(|_| ())
}

fn send_spartn_configuration_load<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::gnss::SpartnConfiguration {
        function: crate::types::FunctionSelector(4),
        ..<crate::gnss::SpartnConfiguration as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Gnss(crate::gnss::SetField::SpartnConfiguration(command));
    device.call(&value).map(|_| ())
}

fn send_spartn_configuration_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::gnss::SpartnConfiguration {
        function: crate::types::FunctionSelector(5),
        ..<crate::gnss::SpartnConfiguration as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Gnss(crate::gnss::SetField::SpartnConfiguration(command));
    device.call(&value).map(|_| ())
}

impl<T: Transport> Device<T> {
    /// Commands of set 0x13 (Aiding Command Set).
    pub fn aiding(&mut self) -> AidingCommands<'_, T> {
        AidingCommands { device: self }
    }
}

/// Commands of set 0x13 (Aiding Command Set), bound to a [`Device`].
#[derive(Debug)]
pub struct AidingCommands<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> AidingCommands<'d, T> {
    /// Frame configuration (0x01).
    pub fn frame_config(self) -> FrameConfigCommand<'d, T> {
        FrameConfigCommand {
            device: self.device,
        }
    }
    /// Echo control (0x1F).
    pub fn echo_control(self) -> EchoControlCommand<'d, T> {
        EchoControlCommand {
            device: self.device,
        }
    }
    /// ECEF position (0x21). Sends `ecef_position`.
    pub fn ecef_position(
        self,
        time: crate::types::AidingTime,
        frame_id: u8,
        position: [f64; 3],
        uncertainty: [f32; 3],
        valid_flags: crate::types::AidingVectorValidFlags,
    ) -> Result<(), SessionError> {
        send_ecef_position_ecef_position(
            self.device,
            time,
            frame_id,
            position,
            uncertainty,
            valid_flags,
        )
    }
    /// LLH position (0x22). Sends `llh_position`.
    pub fn llh_position(
        self,
        time: crate::types::AidingTime,
        frame_id: u8,
        latitude: f64,
        longitude: f64,
        height: f64,
        uncertainty: [f32; 3],
        valid_flags: crate::types::AidingLlhValidFlags,
    ) -> Result<(), SessionError> {
        send_llh_position_llh_position(
            self.device,
            time,
            frame_id,
            latitude,
            longitude,
            height,
            uncertainty,
            valid_flags,
        )
    }
    /// Height above ellipsoid (0x23). Sends `height_above_ellipsoid`.
    pub fn height_above_ellipsoid(
        self,
        time: crate::types::AidingTime,
        frame_id: u8,
        height: f32,
        uncertainty: f32,
        valid_flags: u16,
    ) -> Result<(), SessionError> {
        send_height_above_ellipsoid_height_above_ellipsoid(
            self.device,
            time,
            frame_id,
            height,
            uncertainty,
            valid_flags,
        )
    }
    /// ECEF velocity (0x28). Sends `ecef_velocity`.
    pub fn ecef_velocity(
        self,
        time: crate::types::AidingTime,
        frame_id: u8,
        velocity: [f32; 3],
        uncertainty: [f32; 3],
        valid_flags: crate::types::AidingVectorValidFlags,
    ) -> Result<(), SessionError> {
        send_ecef_velocity_ecef_velocity(
            self.device,
            time,
            frame_id,
            velocity,
            uncertainty,
            valid_flags,
        )
    }
    /// NED velocity (0x29). Sends `ned_velocity`.
    pub fn ned_velocity(
        self,
        time: crate::types::AidingTime,
        frame_id: u8,
        velocity: [f32; 3],
        uncertainty: [f32; 3],
        valid_flags: crate::types::AidingVectorValidFlags,
    ) -> Result<(), SessionError> {
        send_ned_velocity_ned_velocity(
            self.device,
            time,
            frame_id,
            velocity,
            uncertainty,
            valid_flags,
        )
    }
    /// Body frame velocity (0x2A). Sends `body_frame_velocity`.
    pub fn body_frame_velocity(
        self,
        time: crate::types::AidingTime,
        frame_id: u8,
        velocity: [f32; 3],
        uncertainty: [f32; 3],
        valid_flags: crate::types::AidingVectorValidFlags,
    ) -> Result<(), SessionError> {
        send_body_frame_velocity_body_frame_velocity(
            self.device,
            time,
            frame_id,
            velocity,
            uncertainty,
            valid_flags,
        )
    }
    /// True heading (0x31). Sends `true_heading`.
    pub fn true_heading(
        self,
        time: crate::types::AidingTime,
        frame_id: u8,
        heading: f32,
        uncertainty: f32,
        valid_flags: u16,
    ) -> Result<(), SessionError> {
        send_true_heading_true_heading(
            self.device,
            time,
            frame_id,
            heading,
            uncertainty,
            valid_flags,
        )
    }
    /// Magnetic field (0x32). Sends `magnetic_field`.
    pub fn magnetic_field(
        self,
        time: crate::types::AidingTime,
        frame_id: u8,
        magnetic_field: [f32; 3],
        uncertainty: [f32; 3],
        valid_flags: crate::types::AidingVectorValidFlags,
    ) -> Result<(), SessionError> {
        send_magnetic_field_magnetic_field(
            self.device,
            time,
            frame_id,
            magnetic_field,
            uncertainty,
            valid_flags,
        )
    }
    /// Pressure (0x33). Sends `pressure`.
    pub fn pressure(
        self,
        time: crate::types::AidingTime,
        frame_id: u8,
        pressure: f32,
        uncertainty: f32,
        valid_flags: u16,
    ) -> Result<(), SessionError> {
        send_pressure_pressure(
            self.device,
            time,
            frame_id,
            pressure,
            uncertainty,
            valid_flags,
        )
    }
}

/// Frame configuration (0x13, 0x01): one call per function.
#[derive(Debug)]
pub struct FrameConfigCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> FrameConfigCommand<'d, T> {
    /// Function `write`.
    pub fn write(
        self,
        frame_id: u8,
        format: crate::types::AidingFrameFormat,
        tracking_enabled: bool,
        translation: [f32; 3],
        rotation: crate::types::AidingFrameRotation,
    ) -> Result<(), SessionError> {
        send_frame_config_write(
            self.device,
            frame_id,
            format,
            tracking_enabled,
            translation,
            rotation,
        )
    }
    /// Function `read`: returns the reply field.
    pub fn read(
        self,
        frame_id: u8,
        format: crate::types::AidingFrameFormat,
    ) -> Result<crate::aiding::FrameConfigResponse, SessionError> {
        send_frame_config_read(self.device, frame_id, format)
    }
    /// Function `save`.
    pub fn save(self, frame_id: u8) -> Result<(), SessionError> {
        send_frame_config_save(self.device, frame_id)
    }
    /// Function `load`.
    pub fn load(self, frame_id: u8) -> Result<(), SessionError> {
        send_frame_config_load(self.device, frame_id)
    }
    /// Function `default`.
    pub fn default(self, frame_id: u8) -> Result<(), SessionError> {
        send_frame_config_default(self.device, frame_id)
    }
}

fn send_frame_config_write<T: Transport>(
    device: &mut Device<T>,
    frame_id: u8,
    format: crate::types::AidingFrameFormat,
    tracking_enabled: bool,
    translation: [f32; 3],
    rotation: crate::types::AidingFrameRotation,
) -> Result<(), SessionError> {
    let command = crate::aiding::FrameConfig {
        function: crate::types::FunctionSelector(1),
        frame_id,
        format: Some(format),
        tracking_enabled: Some(tracking_enabled),
        translation: Some(translation),
        rotation: Some(rotation),
    };
    let value = FieldValue::Aiding(crate::aiding::SetField::FrameConfig(command));
    device.call(&value).map(|_| ())
}

fn send_frame_config_read<T: Transport>(
    device: &mut Device<T>,
    frame_id: u8,
    format: crate::types::AidingFrameFormat,
) -> Result<crate::aiding::FrameConfigResponse, SessionError> {
    let command = crate::aiding::FrameConfig {
        function: crate::types::FunctionSelector(2),
        frame_id,
        format: Some(format),
        ..<crate::aiding::FrameConfig as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Aiding(crate::aiding::SetField::FrameConfig(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Aiding(crate::aiding::SetField::FrameConfigResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_frame_config_save<T: Transport>(
    device: &mut Device<T>,
    frame_id: u8,
) -> Result<(), SessionError> {
    let command = crate::aiding::FrameConfig {
        function: crate::types::FunctionSelector(3),
        frame_id,
        ..<crate::aiding::FrameConfig as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Aiding(crate::aiding::SetField::FrameConfig(command));
    device.call(&value).map(|_| ())
}

fn send_frame_config_load<T: Transport>(
    device: &mut Device<T>,
    frame_id: u8,
) -> Result<(), SessionError> {
    let command = crate::aiding::FrameConfig {
        function: crate::types::FunctionSelector(4),
        frame_id,
        ..<crate::aiding::FrameConfig as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Aiding(crate::aiding::SetField::FrameConfig(command));
    device.call(&value).map(|_| ())
}

fn send_frame_config_default<T: Transport>(
    device: &mut Device<T>,
    frame_id: u8,
) -> Result<(), SessionError> {
    let command = crate::aiding::FrameConfig {
        function: crate::types::FunctionSelector(5),
        frame_id,
        ..<crate::aiding::FrameConfig as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Aiding(crate::aiding::SetField::FrameConfig(command));
    device.call(&value).map(|_| ())
}

/// Echo control (0x13, 0x1F): one call per function.
#[derive(Debug)]
pub struct EchoControlCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> EchoControlCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, mode: crate::types::AidingEchoMode) -> Result<(), SessionError> {
        send_echo_control_write(self.device, mode)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::aiding::EchoControlResponse, SessionError> {
        send_echo_control_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_echo_control_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_echo_control_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_echo_control_default(self.device)
    }
}

fn send_echo_control_write<T: Transport>(
    device: &mut Device<T>,
    mode: crate::types::AidingEchoMode,
) -> Result<(), SessionError> {
    let command = crate::aiding::EchoControl {
        function: crate::types::FunctionSelector(1),
        mode: Some(mode),
    };
    let value = FieldValue::Aiding(crate::aiding::SetField::EchoControl(command));
    device.call(&value).map(|_| ())
}

fn send_echo_control_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::aiding::EchoControlResponse, SessionError> {
    let command = crate::aiding::EchoControl {
        function: crate::types::FunctionSelector(2),
        ..<crate::aiding::EchoControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Aiding(crate::aiding::SetField::EchoControl(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::Aiding(crate::aiding::SetField::EchoControlResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_echo_control_save<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::aiding::EchoControl {
        function: crate::types::FunctionSelector(3),
        ..<crate::aiding::EchoControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Aiding(crate::aiding::SetField::EchoControl(command));
    device.call(&value).map(|_| ())
}

fn send_echo_control_load<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::aiding::EchoControl {
        function: crate::types::FunctionSelector(4),
        ..<crate::aiding::EchoControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Aiding(crate::aiding::SetField::EchoControl(command));
    device.call(&value).map(|_| ())
}

fn send_echo_control_default<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::aiding::EchoControl {
        function: crate::types::FunctionSelector(5),
        ..<crate::aiding::EchoControl as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::Aiding(crate::aiding::SetField::EchoControl(command));
    device.call(&value).map(|_| ())
}

fn send_ecef_position_ecef_position<T: Transport>(
    device: &mut Device<T>,
    time: crate::types::AidingTime,
    frame_id: u8,
    position: [f64; 3],
    uncertainty: [f32; 3],
    valid_flags: crate::types::AidingVectorValidFlags,
) -> Result<(), SessionError> {
    let command = crate::aiding::EcefPosition {
        time,
        frame_id,
        position,
        uncertainty,
        valid_flags,
    };
    let value = FieldValue::Aiding(crate::aiding::SetField::EcefPosition(command));
    device.call(&value).map(|_| ())
}

fn send_llh_position_llh_position<T: Transport>(
    device: &mut Device<T>,
    time: crate::types::AidingTime,
    frame_id: u8,
    latitude: f64,
    longitude: f64,
    height: f64,
    uncertainty: [f32; 3],
    valid_flags: crate::types::AidingLlhValidFlags,
) -> Result<(), SessionError> {
    let command = crate::aiding::LlhPosition {
        time,
        frame_id,
        latitude,
        longitude,
        height,
        uncertainty,
        valid_flags,
    };
    let value = FieldValue::Aiding(crate::aiding::SetField::LlhPosition(command));
    device.call(&value).map(|_| ())
}

fn send_height_above_ellipsoid_height_above_ellipsoid<T: Transport>(
    device: &mut Device<T>,
    time: crate::types::AidingTime,
    frame_id: u8,
    height: f32,
    uncertainty: f32,
    valid_flags: u16,
) -> Result<(), SessionError> {
    let command = crate::aiding::HeightAboveEllipsoid {
        time,
        frame_id,
        height,
        uncertainty,
        valid_flags,
    };
    let value = FieldValue::Aiding(crate::aiding::SetField::HeightAboveEllipsoid(command));
    device.call(&value).map(|_| ())
}

fn send_ecef_velocity_ecef_velocity<T: Transport>(
    device: &mut Device<T>,
    time: crate::types::AidingTime,
    frame_id: u8,
    velocity: [f32; 3],
    uncertainty: [f32; 3],
    valid_flags: crate::types::AidingVectorValidFlags,
) -> Result<(), SessionError> {
    let command = crate::aiding::EcefVelocity {
        time,
        frame_id,
        velocity,
        uncertainty,
        valid_flags,
    };
    let value = FieldValue::Aiding(crate::aiding::SetField::EcefVelocity(command));
    device.call(&value).map(|_| ())
}

fn send_ned_velocity_ned_velocity<T: Transport>(
    device: &mut Device<T>,
    time: crate::types::AidingTime,
    frame_id: u8,
    velocity: [f32; 3],
    uncertainty: [f32; 3],
    valid_flags: crate::types::AidingVectorValidFlags,
) -> Result<(), SessionError> {
    let command = crate::aiding::NedVelocity {
        time,
        frame_id,
        velocity,
        uncertainty,
        valid_flags,
    };
    let value = FieldValue::Aiding(crate::aiding::SetField::NedVelocity(command));
    device.call(&value).map(|_| ())
}

fn send_body_frame_velocity_body_frame_velocity<T: Transport>(
    device: &mut Device<T>,
    time: crate::types::AidingTime,
    frame_id: u8,
    velocity: [f32; 3],
    uncertainty: [f32; 3],
    valid_flags: crate::types::AidingVectorValidFlags,
) -> Result<(), SessionError> {
    let command = crate::aiding::BodyFrameVelocity {
        time,
        frame_id,
        velocity,
        uncertainty,
        valid_flags,
    };
    let value = FieldValue::Aiding(crate::aiding::SetField::BodyFrameVelocity(command));
    device.call(&value).map(|_| ())
}

fn send_true_heading_true_heading<T: Transport>(
    device: &mut Device<T>,
    time: crate::types::AidingTime,
    frame_id: u8,
    heading: f32,
    uncertainty: f32,
    valid_flags: u16,
) -> Result<(), SessionError> {
    let command = crate::aiding::TrueHeading {
        time,
        frame_id,
        heading,
        uncertainty,
        valid_flags,
    };
    let value = FieldValue::Aiding(crate::aiding::SetField::TrueHeading(command));
    device.call(&value).map(|_| ())
}

fn send_magnetic_field_magnetic_field<T: Transport>(
    device: &mut Device<T>,
    time: crate::types::AidingTime,
    frame_id: u8,
    magnetic_field: [f32; 3],
    uncertainty: [f32; 3],
    valid_flags: crate::types::AidingVectorValidFlags,
) -> Result<(), SessionError> {
    let command = crate::aiding::MagneticField {
        time,
        frame_id,
        magnetic_field,
        uncertainty,
        valid_flags,
    };
    let value = FieldValue::Aiding(crate::aiding::SetField::MagneticField(command));
    device.call(&value).map(|_| ())
}

fn send_pressure_pressure<T: Transport>(
    device: &mut Device<T>,
    time: crate::types::AidingTime,
    frame_id: u8,
    pressure: f32,
    uncertainty: f32,
    valid_flags: u16,
) -> Result<(), SessionError> {
    let command = crate::aiding::Pressure {
        time,
        frame_id,
        pressure,
        uncertainty,
        valid_flags,
    };
    let value = FieldValue::Aiding(crate::aiding::SetField::Pressure(command));
    device.call(&value).map(|_| ())
}

impl<T: Transport> Device<T> {
    /// Commands of set 0x7F (System Command Set).
    pub fn system(&mut self) -> SystemCommands<'_, T> {
        SystemCommands { device: self }
    }
}

/// Commands of set 0x7F (System Command Set), bound to a [`Device`].
#[derive(Debug)]
pub struct SystemCommands<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> SystemCommands<'d, T> {
    /// Communication mode (0x10).
    pub fn communication_mode(self) -> CommunicationModeCommand<'d, T> {
        CommunicationModeCommand {
            device: self.device,
        }
    }
}

/// Communication mode (0x7F, 0x10): one call per function.
#[derive(Debug)]
pub struct CommunicationModeCommand<'d, T: Transport> {
    device: &'d mut Device<T>,
}

impl<'d, T: Transport> CommunicationModeCommand<'d, T> {
    /// Function `write`.
    pub fn write(self, mode: crate::types::SystemCommMode) -> Result<(), SessionError> {
        send_communication_mode_write(self.device, mode)
    }
    /// Function `read`: returns the reply field.
    pub fn read(self) -> Result<crate::system::CommunicationModeResponse, SessionError> {
        send_communication_mode_read(self.device)
    }
    /// Function `save`.
    pub fn save(self) -> Result<(), SessionError> {
        send_communication_mode_save(self.device)
    }
    /// Function `load`.
    pub fn load(self) -> Result<(), SessionError> {
        send_communication_mode_load(self.device)
    }
    /// Function `default`.
    pub fn default(self) -> Result<(), SessionError> {
        send_communication_mode_default(self.device)
    }
}

fn send_communication_mode_write<T: Transport>(
    device: &mut Device<T>,
    mode: crate::types::SystemCommMode,
) -> Result<(), SessionError> {
    let command = crate::system::CommunicationMode {
        function: crate::types::FunctionSelector(1),
        mode: Some(mode),
    };
    let value = FieldValue::System(crate::system::SetField::CommunicationMode(command));
    device.call(&value).map(|_| ())
}

fn send_communication_mode_read<T: Transport>(
    device: &mut Device<T>,
) -> Result<crate::system::CommunicationModeResponse, SessionError> {
    let command = crate::system::CommunicationMode {
        function: crate::types::FunctionSelector(2),
        ..<crate::system::CommunicationMode as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::System(crate::system::SetField::CommunicationMode(command));
    let done = device.call(&value)?;
    reply(done.facts.name, done.response(), |v| match v {
        FieldValue::System(crate::system::SetField::CommunicationModeResponse(r)) => Some(r),
        _ => None,
    })
}

fn send_communication_mode_save<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::system::CommunicationMode {
        function: crate::types::FunctionSelector(3),
        ..<crate::system::CommunicationMode as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::System(crate::system::SetField::CommunicationMode(command));
    device.call(&value).map(|_| ())
}

fn send_communication_mode_load<T: Transport>(device: &mut Device<T>) -> Result<(), SessionError> {
    let command = crate::system::CommunicationMode {
        function: crate::types::FunctionSelector(4),
        ..<crate::system::CommunicationMode as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::System(crate::system::SetField::CommunicationMode(command));
    device.call(&value).map(|_| ())
}

fn send_communication_mode_default<T: Transport>(
    device: &mut Device<T>,
) -> Result<(), SessionError> {
    let command = crate::system::CommunicationMode {
        function: crate::types::FunctionSelector(5),
        ..<crate::system::CommunicationMode as crate::wire::Wire>::ZERO
    };
    let value = FieldValue::System(crate::system::SetField::CommunicationMode(command));
    device.call(&value).map(|_| ())
}
