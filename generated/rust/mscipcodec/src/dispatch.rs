//! Devices, set kinds, dispatch of a field by (set, descriptor) (`docs/conformance.md` §2) and
//! the canonical JSON of packets and skip runs (§4).

use core::fmt::{self, Write};

use crate::error::{DecodeError, DecodeErrorKind, EncodeError};
use crate::fields::{FieldItem, Packet};
use crate::json;
use crate::wire::Writer;

/// A device of the protocol; some fields have a layout per device.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Device {
    /// MS-IMU3020 (`ms_imu3020`).
    MsImu3020,
}

impl Device {
    /// Every device, in spec order.
    pub const ALL: [Device; 1] = [Device::MsImu3020];

    /// Identifier in the spec (`--device ID`, `"device"` in JSON).
    pub fn id(self) -> &'static str {
        match self {
            Device::MsImu3020 => "ms_imu3020",
        }
    }

    /// Product name.
    pub fn title(self) -> &'static str {
        match self {
            Device::MsImu3020 => "MS-IMU3020",
        }
    }

    /// The device with identifier `id`.
    pub fn from_id(id: &str) -> Option<Self> {
        match id {
            "ms_imu3020" => Some(Device::MsImu3020),
            _ => None,
        }
    }
}

/// Kind of a descriptor set, from the ranges of `set_kinds`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SetKind {
    /// Sets 0x01..=0x7F.
    Command,
    /// Sets 0x80..=0xFF.
    Data,
}

/// Kind of set `set`, if it is in a range of `set_kinds`.
pub fn set_kind(set: u8) -> Option<SetKind> {
    if (0x01..=0x7F).contains(&set) {
        return Some(SetKind::Command);
    }
    if (0x80..=0xFF).contains(&set) {
        return Some(SetKind::Data);
    }
    None
}

/// Whether the spec defines descriptor set `set`.
pub fn set_defined(set: u8) -> bool {
    matches!(set, 0x01 | 0x02 | 0xA2)
}

/// A decoded field, by the group that defines it.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FieldValue {
    /// A field of set 0x01.
    Base(crate::base::SetField),
    /// A field of set 0x02.
    ImuConfig(crate::imu_config::SetField),
    /// A field of set 0xA2.
    ImuData(crate::imu_data::SetField),
    /// A reserved field.
    Reserved(crate::reserved::ReservedField),
}

impl FieldValue {
    /// Field descriptor.
    pub fn descriptor(&self) -> u8 {
        match self {
            FieldValue::Base(v) => v.descriptor(),
            FieldValue::ImuConfig(v) => v.descriptor(),
            FieldValue::ImuData(v) => v.descriptor(),
            FieldValue::Reserved(v) => v.descriptor(),
        }
    }

    /// Field name as printed in JSON.
    pub fn name(&self) -> &'static str {
        match self {
            FieldValue::Base(v) => v.name(),
            FieldValue::ImuConfig(v) => v.name(),
            FieldValue::ImuData(v) => v.name(),
            FieldValue::Reserved(v) => v.name(),
        }
    }

    /// Device of the layout used, for fields with per-device layouts.
    pub fn device(&self) -> Option<Device> {
        match self {
            FieldValue::Base(v) => v.device(),
            FieldValue::ImuConfig(v) => v.device(),
            FieldValue::ImuData(v) => v.device(),
            FieldValue::Reserved(v) => v.device(),
        }
    }

    /// Encodes the field data (without the field header).
    pub fn encode_data(&self, w: &mut Writer<'_>) -> Result<(), EncodeError> {
        match self {
            FieldValue::Base(v) => v.encode_data(w),
            FieldValue::ImuConfig(v) => v.encode_data(w),
            FieldValue::ImuData(v) => v.encode_data(w),
            FieldValue::Reserved(v) => v.encode_data(w),
        }
    }

    /// Writes the canonical JSON of the values (`{...}`).
    pub fn write_values_json(&self, w: &mut dyn Write) -> fmt::Result {
        match self {
            FieldValue::Base(v) => v.write_values_json(w),
            FieldValue::ImuConfig(v) => v.write_values_json(w),
            FieldValue::ImuData(v) => v.write_values_json(w),
            FieldValue::Reserved(v) => v.write_values_json(w),
        }
    }

    /// Writes the canonical JSON of the field: descriptor, name, device (if the field has
    /// per-device layouts) and values.
    pub fn write_json(&self, w: &mut dyn Write) -> fmt::Result {
        w.write_char('{')?;
        write!(w, "\"descriptor\":{},\"name\":", self.descriptor())?;
        json::write_str(w, self.name())?;
        if let Some(device) = self.device() {
            w.write_str(",\"device\":")?;
            json::write_str(w, device.id())?;
        }
        w.write_str(",\"values\":")?;
        self.write_values_json(w)?;
        w.write_char('}')
    }

    /// Reads a decoded field back from JSON (dispatch as in [`decode_field`]).
    #[cfg(feature = "std")]
    pub fn from_json(
        set: u8,
        descriptor: u8,
        device: Option<Device>,
        values: &crate::json_read::Json,
    ) -> Result<Self, crate::json_read::JsonError> {
        let found = match set {
            0x01 => crate::base::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::Base)),
            0x02 => crate::imu_config::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::ImuConfig)),
            0xA2 => crate::imu_data::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::ImuData)),
            _ => None,
        };
        if let Some(result) = found {
            return result;
        }
        let kind = set_kind(set);
        if let Some(result) =
            crate::reserved::ReservedField::from_json(kind, descriptor, device, values)
        {
            return result.map(FieldValue::Reserved);
        }
        Err(crate::json_read::JsonError::new(std::format!(
            "descriptor {descriptor} is not defined in set {set}; write the field raw, with \"data\""
        ))
        .at("descriptor"))
    }
}

/// Decodes the data of field `descriptor` in a packet of set `set`: the set's own field, else a
/// reserved field of the set's kind, else (in a data set) a field of the shared data set. With
/// `device`, fields that have per-device layouts use that device's layout.
pub fn decode_field(
    set: u8,
    descriptor: u8,
    data: &[u8],
    device: Option<Device>,
) -> Result<FieldValue, DecodeError> {
    // The set's own fields: one match on (set, descriptor), compiled to jump tables, straight to
    // the field's decoder, which builds the FieldValue in the caller's slot.
    match (set, descriptor) {
        (0x01, 0x02) => decoders::base_ping(data, device),
        (0x01, 0x03) => decoders::base_get_device_messages(data, device),
        (0x01, 0x83) => decoders::base_device_messages(data, device),
        (0x01, 0x04) => decoders::base_device_reset(data, device),
        (0x01, 0x05) => decoders::base_get_device_model(data, device),
        (0x01, 0x85) => decoders::base_device_model(data, device),
        (0x01, 0x06) => decoders::base_get_device_sn(data, device),
        (0x01, 0x86) => decoders::base_device_sn(data, device),
        (0x01, 0x07) => decoders::base_get_device_fw(data, device),
        (0x01, 0x87) => decoders::base_device_fw(data, device),
        (0x01, 0x08) => decoders::base_get_device_cal(data, device),
        (0x01, 0x88) => decoders::base_device_cal(data, device),
        (0x01, 0x09) => decoders::base_correlate_gps_time(data, device),
        (0x02, 0x01) => decoders::imu_config_uart_baud_rate(data, device),
        (0x02, 0x81) => decoders::imu_config_uart_baud_rate_response(data, device),
        (0x02, 0x03) => decoders::imu_config_filter(data, device),
        (0x02, 0x83) => decoders::imu_config_filter_response(data, device),
        (0x02, 0x04) => decoders::imu_config_sample_rate(data, device),
        (0x02, 0x84) => decoders::imu_config_sample_rate_response(data, device),
        (0x02, 0x05) => decoders::imu_config_select_sensors(data, device),
        (0x02, 0x85) => decoders::imu_config_select_sensors_response(data, device),
        (0x02, 0x06) => decoders::imu_config_get_internal_sample_rate(data, device),
        (0x02, 0x86) => decoders::imu_config_internal_sample_rate(data, device),
        (0x02, 0x07) => decoders::imu_config_accel_range(data, device),
        (0x02, 0x87) => decoders::imu_config_accel_range_response(data, device),
        (0x02, 0x08) => decoders::imu_config_gyro_range(data, device),
        (0x02, 0x88) => decoders::imu_config_gyro_range_response(data, device),
        (0x02, 0x09) => decoders::imu_config_config_all(data, device),
        (0x02, 0x0A) => decoders::imu_config_data_on_off(data, device),
        (0x02, 0x8A) => decoders::imu_config_data_on_off_response(data, device),
        (0x02, 0x0B) => decoders::imu_config_xtrig_on_off(data, device),
        (0x02, 0x8B) => decoders::imu_config_xtrig_on_off_response(data, device),
        (0x02, 0x0C) => decoders::imu_config_select_sensors_rev_b(data, device),
        (0x02, 0x8C) => decoders::imu_config_select_sensors_rev_b_response(data, device),
        (0x02, 0x0D) => decoders::imu_config_aux_accel_range(data, device),
        (0x02, 0x8D) => decoders::imu_config_aux_accel_range_response(data, device),
        (0xA2, 0x81) => decoders::imu_data_scaled_accel(data, device),
        (0xA2, 0x82) => decoders::imu_data_scaled_gyro(data, device),
        (0xA2, 0x83) => decoders::imu_data_scaled_mag(data, device),
        (0xA2, 0x84) => decoders::imu_data_delta_theta(data, device),
        (0xA2, 0x85) => decoders::imu_data_delta_velocity(data, device),
        (0xA2, 0x86) => decoders::imu_data_scaled_pressure(data, device),
        (0xA2, 0x87) => decoders::imu_data_scaled_temperature(data, device),
        (0xA2, 0x88) => decoders::imu_data_gps_correlated_time(data, device),
        (0xA2, 0x89) => decoders::imu_data_scaled_aux_accel(data, device),
        _ => decode_other_field(set, descriptor, data, device),
    }
}

/// [`decode_field`] for a descriptor that is not one of the set's own fields. Out of line, so
/// that `decode_field` itself is only the jump.
#[inline(never)]
fn decode_other_field(
    set: u8,
    descriptor: u8,
    data: &[u8],
    device: Option<Device>,
) -> Result<FieldValue, DecodeError> {
    // Not every protocol has reserved or shared fields to look at.
    let _ = (descriptor, data, device);
    let kind = set_kind(set);
    if let Some(result) = crate::reserved::ReservedField::decode(kind, descriptor, data) {
        return result.map(FieldValue::Reserved);
    }
    Err(DecodeError::new(if set_defined(set) {
        DecodeErrorKind::UnknownDescriptor
    } else {
        DecodeErrorKind::UnknownSet
    }))
}

/// One decoder per field of every set, for [`decode_field`]. Not inlined: each is called from
/// one place, so the compiler would otherwise merge all of them into `decode_field`, whose stack
/// frame would then hold the largest of every layout on every call.
mod decoders {
    use super::{DecodeError, Device, FieldValue};

    #[inline(never)]
    pub(super) fn base_ping(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::base::Ping as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Base(crate::base::SetField::Ping(v)))
    }

    #[inline(never)]
    pub(super) fn base_get_device_messages(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::base::GetDeviceMessages as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Base(crate::base::SetField::GetDeviceMessages(v)))
    }

    #[inline(never)]
    pub(super) fn base_device_messages(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::base::DeviceMessages as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Base(crate::base::SetField::DeviceMessages(v)))
    }

    #[inline(never)]
    pub(super) fn base_device_reset(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::base::DeviceReset as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Base(crate::base::SetField::DeviceReset(v)))
    }

    #[inline(never)]
    pub(super) fn base_get_device_model(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::base::GetDeviceModel as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Base(crate::base::SetField::GetDeviceModel(v)))
    }

    #[inline(never)]
    pub(super) fn base_device_model(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::base::DeviceModel as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Base(crate::base::SetField::DeviceModel(v)))
    }

    #[inline(never)]
    pub(super) fn base_get_device_sn(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::base::GetDeviceSn as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Base(crate::base::SetField::GetDeviceSn(v)))
    }

    #[inline(never)]
    pub(super) fn base_device_sn(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::base::DeviceSn as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Base(crate::base::SetField::DeviceSn(v)))
    }

    #[inline(never)]
    pub(super) fn base_get_device_fw(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::base::GetDeviceFw as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Base(crate::base::SetField::GetDeviceFw(v)))
    }

    #[inline(never)]
    pub(super) fn base_device_fw(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::base::DeviceFw as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Base(crate::base::SetField::DeviceFw(v)))
    }

    #[inline(never)]
    pub(super) fn base_get_device_cal(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::base::GetDeviceCal as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Base(crate::base::SetField::GetDeviceCal(v)))
    }

    #[inline(never)]
    pub(super) fn base_device_cal(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::base::DeviceCal as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Base(crate::base::SetField::DeviceCal(v)))
    }

    #[inline(never)]
    pub(super) fn base_correlate_gps_time(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::base::CorrelateGpsTime as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Base(crate::base::SetField::CorrelateGpsTime(v)))
    }

    #[inline(never)]
    pub(super) fn imu_config_uart_baud_rate(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::imu_config::UartBaudRate as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::ImuConfig(crate::imu_config::SetField::UartBaudRate(v)))
    }

    #[inline(never)]
    pub(super) fn imu_config_uart_baud_rate_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::imu_config::UartBaudRateResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::ImuConfig(crate::imu_config::SetField::UartBaudRateResponse(v)))
    }

    #[inline(never)]
    pub(super) fn imu_config_filter(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::imu_config::Filter as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::ImuConfig(crate::imu_config::SetField::Filter(v)))
    }

    #[inline(never)]
    pub(super) fn imu_config_filter_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::imu_config::FilterResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::ImuConfig(crate::imu_config::SetField::FilterResponse(v)))
    }

    #[inline(never)]
    pub(super) fn imu_config_sample_rate(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::imu_config::SampleRate as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::ImuConfig(crate::imu_config::SetField::SampleRate(v)))
    }

    #[inline(never)]
    pub(super) fn imu_config_sample_rate_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::imu_config::SampleRateResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::ImuConfig(crate::imu_config::SetField::SampleRateResponse(v)))
    }

    #[inline(never)]
    pub(super) fn imu_config_select_sensors(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::imu_config::SelectSensors as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::ImuConfig(crate::imu_config::SetField::SelectSensors(v)))
    }

    #[inline(never)]
    pub(super) fn imu_config_select_sensors_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::imu_config::SelectSensorsResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::ImuConfig(crate::imu_config::SetField::SelectSensorsResponse(v)))
    }

    #[inline(never)]
    pub(super) fn imu_config_get_internal_sample_rate(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::imu_config::GetInternalSampleRate as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::ImuConfig(crate::imu_config::SetField::GetInternalSampleRate(v)))
    }

    #[inline(never)]
    pub(super) fn imu_config_internal_sample_rate(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::imu_config::InternalSampleRate as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::ImuConfig(crate::imu_config::SetField::InternalSampleRate(v)))
    }

    #[inline(never)]
    pub(super) fn imu_config_accel_range(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::imu_config::AccelRange as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::ImuConfig(crate::imu_config::SetField::AccelRange(v)))
    }

    #[inline(never)]
    pub(super) fn imu_config_accel_range_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::imu_config::AccelRangeResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::ImuConfig(crate::imu_config::SetField::AccelRangeResponse(v)))
    }

    #[inline(never)]
    pub(super) fn imu_config_gyro_range(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::imu_config::GyroRange as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::ImuConfig(crate::imu_config::SetField::GyroRange(v)))
    }

    #[inline(never)]
    pub(super) fn imu_config_gyro_range_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::imu_config::GyroRangeResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::ImuConfig(crate::imu_config::SetField::GyroRangeResponse(v)))
    }

    #[inline(never)]
    pub(super) fn imu_config_config_all(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::imu_config::ConfigAll as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::ImuConfig(crate::imu_config::SetField::ConfigAll(v)))
    }

    #[inline(never)]
    pub(super) fn imu_config_data_on_off(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::imu_config::DataOnOff as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::ImuConfig(crate::imu_config::SetField::DataOnOff(v)))
    }

    #[inline(never)]
    pub(super) fn imu_config_data_on_off_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::imu_config::DataOnOffResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::ImuConfig(crate::imu_config::SetField::DataOnOffResponse(v)))
    }

    #[inline(never)]
    pub(super) fn imu_config_xtrig_on_off(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::imu_config::XtrigOnOff as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::ImuConfig(crate::imu_config::SetField::XtrigOnOff(v)))
    }

    #[inline(never)]
    pub(super) fn imu_config_xtrig_on_off_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::imu_config::XtrigOnOffResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::ImuConfig(crate::imu_config::SetField::XtrigOnOffResponse(v)))
    }

    #[inline(never)]
    pub(super) fn imu_config_select_sensors_rev_b(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::imu_config::SelectSensorsRevB as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::ImuConfig(crate::imu_config::SetField::SelectSensorsRevB(v)))
    }

    #[inline(never)]
    pub(super) fn imu_config_select_sensors_rev_b_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::imu_config::SelectSensorsRevBResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| {
                FieldValue::ImuConfig(crate::imu_config::SetField::SelectSensorsRevBResponse(v))
            })
    }

    #[inline(never)]
    pub(super) fn imu_config_aux_accel_range(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::imu_config::AuxAccelRange as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::ImuConfig(crate::imu_config::SetField::AuxAccelRange(v)))
    }

    #[inline(never)]
    pub(super) fn imu_config_aux_accel_range_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::imu_config::AuxAccelRangeResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::ImuConfig(crate::imu_config::SetField::AuxAccelRangeResponse(v)))
    }

    #[inline(never)]
    pub(super) fn imu_data_scaled_accel(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::imu_data::ScaledAccel as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::ImuData(crate::imu_data::SetField::ScaledAccel(v)))
    }

    #[inline(never)]
    pub(super) fn imu_data_scaled_gyro(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::imu_data::ScaledGyro as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::ImuData(crate::imu_data::SetField::ScaledGyro(v)))
    }

    #[inline(never)]
    pub(super) fn imu_data_scaled_mag(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::imu_data::ScaledMag as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::ImuData(crate::imu_data::SetField::ScaledMag(v)))
    }

    #[inline(never)]
    pub(super) fn imu_data_delta_theta(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::imu_data::DeltaTheta as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::ImuData(crate::imu_data::SetField::DeltaTheta(v)))
    }

    #[inline(never)]
    pub(super) fn imu_data_delta_velocity(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::imu_data::DeltaVelocity as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::ImuData(crate::imu_data::SetField::DeltaVelocity(v)))
    }

    #[inline(never)]
    pub(super) fn imu_data_scaled_pressure(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::imu_data::ScaledPressure as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::ImuData(crate::imu_data::SetField::ScaledPressure(v)))
    }

    #[inline(never)]
    pub(super) fn imu_data_scaled_temperature(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::imu_data::ScaledTemperature as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::ImuData(crate::imu_data::SetField::ScaledTemperature(v)))
    }

    #[inline(never)]
    pub(super) fn imu_data_gps_correlated_time(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::imu_data::GpsCorrelatedTime as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::ImuData(crate::imu_data::SetField::GpsCorrelatedTime(v)))
    }

    #[inline(never)]
    pub(super) fn imu_data_scaled_aux_accel(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::imu_data::ScaledAuxAccel as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::ImuData(crate::imu_data::SetField::ScaledAuxAccel(v)))
    }
}

/// Writes the canonical JSON of one field: decoded, or raw with the decode error.
pub fn write_field_json(
    w: &mut dyn Write,
    set: u8,
    descriptor: u8,
    data: &[u8],
    device: Option<Device>,
) -> fmt::Result {
    match decode_field(set, descriptor, data, device) {
        Ok(value) => value.write_json(w),
        Err(error) => {
            w.write_char('{')?;
            write!(w, "\"descriptor\":{descriptor},\"data\":\"")?;
            json::write_hex(w, data)?;
            w.write_str("\",\"error\":")?;
            json::write_display(w, &error)?;
            w.write_char('}')
        }
    }
}

/// Writes the canonical JSON line of a packet found at stream offset `offset` (no newline).
pub fn write_packet_json(
    w: &mut dyn Write,
    offset: u64,
    packet: &Packet<'_>,
    device: Option<Device>,
) -> fmt::Result {
    let set = packet.set();
    w.write_char('{')?;
    write!(w, "\"offset\":{offset},\"set\":{set},\"fields\":[")?;
    for (i, item) in packet.fields().enumerate() {
        if i > 0 {
            w.write_char(',')?;
        }
        match item {
            FieldItem::Field { descriptor, data } => {
                write_field_json(w, set, descriptor, data, device)?
            }
            FieldItem::Trailing { bytes, error } => {
                w.write_str("{\"trailing\":\"")?;
                json::write_hex(w, bytes)?;
                w.write_str("\",\"error\":")?;
                json::write_display(w, &error)?;
                w.write_char('}')?;
            }
        }
    }
    w.write_str("]}")
}

/// Writes the canonical JSON line of a skip run (no newline).
pub fn write_skip_json(w: &mut dyn Write, offset: u64, bytes: &[u8]) -> fmt::Result {
    w.write_char('{')?;
    write!(w, "\"offset\":{offset},\"skipped\":\"")?;
    json::write_hex(w, bytes)?;
    w.write_str("\"}")
}

/// Error unless `device` is `None` (for fields without per-device layouts).
#[cfg(feature = "std")]
pub fn no_device(device: Option<Device>) -> Result<(), crate::json_read::JsonError> {
    match device {
        None => Ok(()),
        Some(d) => Err(crate::json_read::JsonError::new(std::format!(
            "this field has no per-device layouts (got device {})",
            d.id()
        ))
        .at("device")),
    }
}
