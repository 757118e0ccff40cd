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
    /// 3DM-GX5-45 (`gx5_45`).
    Gx5_45,
    /// 3DM-CV7-GNSS/INS (`cv7_ins`).
    Cv7Ins,
}

impl Device {
    /// Every device, in spec order.
    pub const ALL: [Device; 2] = [Device::Gx5_45, Device::Cv7Ins];

    /// Identifier in the spec (`--device ID`, `"device"` in JSON).
    pub fn id(self) -> &'static str {
        match self {
            Device::Gx5_45 => "gx5_45",
            Device::Cv7Ins => "cv7_ins",
        }
    }

    /// Product name.
    pub fn title(self) -> &'static str {
        match self {
            Device::Gx5_45 => "3DM-GX5-45",
            Device::Cv7Ins => "3DM-CV7-GNSS/INS",
        }
    }

    /// The device with identifier `id`.
    pub fn from_id(id: &str) -> Option<Self> {
        match id {
            "gx5_45" => Some(Device::Gx5_45),
            "cv7_ins" => Some(Device::Cv7Ins),
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
    matches!(
        set,
        0x01 | 0x0C
            | 0x0D
            | 0x0E
            | 0x13
            | 0x7F
            | 0x80
            | 0x81
            | 0x82
            | 0x91
            | 0x92
            | 0x93
            | 0x94
            | 0xA0
            | 0xFF
    )
}

/// A decoded field, by the group that defines it.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FieldValue {
    /// A field of set 0x01.
    Base(crate::base::SetField),
    /// A field of set 0x0C.
    Threedm(crate::threedm::SetField),
    /// A field of set 0x0D.
    Filter(crate::filter::SetField),
    /// A field of set 0x0E.
    Gnss(crate::gnss::SetField),
    /// A field of set 0x13.
    Aiding(crate::aiding::SetField),
    /// A field of set 0x7F.
    System(crate::system::SetField),
    /// A field of set 0x80.
    Sensor(crate::sensor::SetField),
    /// A field of set 0x81.
    GnssData(crate::gnss_data::SetField),
    /// A field of set 0x82.
    FilterData(crate::filter_data::SetField),
    /// A field of set 0x91.
    GnssReceiver1(crate::gnss_receiver_1::SetField),
    /// A field of set 0x92.
    GnssReceiver2(crate::gnss_receiver_2::SetField),
    /// A field of set 0x93.
    GnssCorrections(crate::gnss_corrections::SetField),
    /// A field of set 0x94.
    GnssExternal(crate::gnss_external::SetField),
    /// A field of set 0xA0.
    SystemData(crate::system_data::SetField),
    /// A field of set 0xFF.
    Shared(crate::shared::SetField),
    /// A reserved field.
    Reserved(crate::reserved::ReservedField),
}

impl FieldValue {
    /// Field descriptor.
    pub fn descriptor(&self) -> u8 {
        match self {
            FieldValue::Base(v) => v.descriptor(),
            FieldValue::Threedm(v) => v.descriptor(),
            FieldValue::Filter(v) => v.descriptor(),
            FieldValue::Gnss(v) => v.descriptor(),
            FieldValue::Aiding(v) => v.descriptor(),
            FieldValue::System(v) => v.descriptor(),
            FieldValue::Sensor(v) => v.descriptor(),
            FieldValue::GnssData(v) => v.descriptor(),
            FieldValue::FilterData(v) => v.descriptor(),
            FieldValue::GnssReceiver1(v) => v.descriptor(),
            FieldValue::GnssReceiver2(v) => v.descriptor(),
            FieldValue::GnssCorrections(v) => v.descriptor(),
            FieldValue::GnssExternal(v) => v.descriptor(),
            FieldValue::SystemData(v) => v.descriptor(),
            FieldValue::Shared(v) => v.descriptor(),
            FieldValue::Reserved(v) => v.descriptor(),
        }
    }

    /// Field name as printed in JSON.
    pub fn name(&self) -> &'static str {
        match self {
            FieldValue::Base(v) => v.name(),
            FieldValue::Threedm(v) => v.name(),
            FieldValue::Filter(v) => v.name(),
            FieldValue::Gnss(v) => v.name(),
            FieldValue::Aiding(v) => v.name(),
            FieldValue::System(v) => v.name(),
            FieldValue::Sensor(v) => v.name(),
            FieldValue::GnssData(v) => v.name(),
            FieldValue::FilterData(v) => v.name(),
            FieldValue::GnssReceiver1(v) => v.name(),
            FieldValue::GnssReceiver2(v) => v.name(),
            FieldValue::GnssCorrections(v) => v.name(),
            FieldValue::GnssExternal(v) => v.name(),
            FieldValue::SystemData(v) => v.name(),
            FieldValue::Shared(v) => v.name(),
            FieldValue::Reserved(v) => v.name(),
        }
    }

    /// Device of the layout used, for fields with per-device layouts.
    pub fn device(&self) -> Option<Device> {
        match self {
            FieldValue::Base(v) => v.device(),
            FieldValue::Threedm(v) => v.device(),
            FieldValue::Filter(v) => v.device(),
            FieldValue::Gnss(v) => v.device(),
            FieldValue::Aiding(v) => v.device(),
            FieldValue::System(v) => v.device(),
            FieldValue::Sensor(v) => v.device(),
            FieldValue::GnssData(v) => v.device(),
            FieldValue::FilterData(v) => v.device(),
            FieldValue::GnssReceiver1(v) => v.device(),
            FieldValue::GnssReceiver2(v) => v.device(),
            FieldValue::GnssCorrections(v) => v.device(),
            FieldValue::GnssExternal(v) => v.device(),
            FieldValue::SystemData(v) => v.device(),
            FieldValue::Shared(v) => v.device(),
            FieldValue::Reserved(v) => v.device(),
        }
    }

    /// Encodes the field data (without the field header).
    pub fn encode_data(&self, w: &mut Writer<'_>) -> Result<(), EncodeError> {
        match self {
            FieldValue::Base(v) => v.encode_data(w),
            FieldValue::Threedm(v) => v.encode_data(w),
            FieldValue::Filter(v) => v.encode_data(w),
            FieldValue::Gnss(v) => v.encode_data(w),
            FieldValue::Aiding(v) => v.encode_data(w),
            FieldValue::System(v) => v.encode_data(w),
            FieldValue::Sensor(v) => v.encode_data(w),
            FieldValue::GnssData(v) => v.encode_data(w),
            FieldValue::FilterData(v) => v.encode_data(w),
            FieldValue::GnssReceiver1(v) => v.encode_data(w),
            FieldValue::GnssReceiver2(v) => v.encode_data(w),
            FieldValue::GnssCorrections(v) => v.encode_data(w),
            FieldValue::GnssExternal(v) => v.encode_data(w),
            FieldValue::SystemData(v) => v.encode_data(w),
            FieldValue::Shared(v) => v.encode_data(w),
            FieldValue::Reserved(v) => v.encode_data(w),
        }
    }

    /// Writes the canonical JSON of the values (`{...}`).
    pub fn write_values_json(&self, w: &mut dyn Write) -> fmt::Result {
        match self {
            FieldValue::Base(v) => v.write_values_json(w),
            FieldValue::Threedm(v) => v.write_values_json(w),
            FieldValue::Filter(v) => v.write_values_json(w),
            FieldValue::Gnss(v) => v.write_values_json(w),
            FieldValue::Aiding(v) => v.write_values_json(w),
            FieldValue::System(v) => v.write_values_json(w),
            FieldValue::Sensor(v) => v.write_values_json(w),
            FieldValue::GnssData(v) => v.write_values_json(w),
            FieldValue::FilterData(v) => v.write_values_json(w),
            FieldValue::GnssReceiver1(v) => v.write_values_json(w),
            FieldValue::GnssReceiver2(v) => v.write_values_json(w),
            FieldValue::GnssCorrections(v) => v.write_values_json(w),
            FieldValue::GnssExternal(v) => v.write_values_json(w),
            FieldValue::SystemData(v) => v.write_values_json(w),
            FieldValue::Shared(v) => v.write_values_json(w),
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
            0x0C => crate::threedm::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::Threedm)),
            0x0D => crate::filter::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::Filter)),
            0x0E => crate::gnss::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::Gnss)),
            0x13 => crate::aiding::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::Aiding)),
            0x7F => crate::system::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::System)),
            0x80 => crate::sensor::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::Sensor)),
            0x81 => crate::gnss_data::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::GnssData)),
            0x82 => crate::filter_data::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::FilterData)),
            0x91 => crate::gnss_receiver_1::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::GnssReceiver1)),
            0x92 => crate::gnss_receiver_2::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::GnssReceiver2)),
            0x93 => crate::gnss_corrections::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::GnssCorrections)),
            0x94 => crate::gnss_external::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::GnssExternal)),
            0xA0 => crate::system_data::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::SystemData)),
            0xFF => crate::shared::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::Shared)),
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
        if kind == Some(SetKind::Data) {
            if let Some(result) = crate::shared::SetField::from_json(descriptor, device, values) {
                return result.map(FieldValue::Shared);
            }
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
        (0x01, 0x01) => decoders::base_ping(data, device),
        (0x01, 0x02) => decoders::base_set_to_idle(data, device),
        (0x01, 0x03) => decoders::base_get_device_info(data, device),
        (0x01, 0x81) => decoders::base_device_info(data, device),
        (0x01, 0x04) => decoders::base_get_device_descriptors(data, device),
        (0x01, 0x82) => decoders::base_device_descriptors(data, device),
        (0x01, 0x05) => decoders::base_built_in_test(data, device),
        (0x01, 0x83) => decoders::base_built_in_test_result(data, device),
        (0x01, 0x06) => decoders::base_resume(data, device),
        (0x01, 0x07) => decoders::base_get_extended_descriptors(data, device),
        (0x01, 0x86) => decoders::base_extended_descriptors(data, device),
        (0x01, 0x08) => decoders::base_continuous_bit(data, device),
        (0x01, 0x88) => decoders::base_continuous_bit_result(data, device),
        (0x01, 0x09) => decoders::base_comm_port_speed(data, device),
        (0x01, 0x89) => decoders::base_comm_port_speed_response(data, device),
        (0x01, 0x72) => decoders::base_gps_time_update(data, device),
        (0x01, 0x84) => decoders::base_gps_week(data, device),
        (0x01, 0x85) => decoders::base_gps_seconds(data, device),
        (0x01, 0x7E) => decoders::base_device_reset(data, device),
        (0x0C, 0x2B) => decoders::threedm_event_control(data, device),
        (0x0C, 0xB5) => decoders::threedm_event_control_response(data, device),
        (0x0C, 0x2C) => decoders::threedm_get_event_trigger_status(data, device),
        (0x0C, 0xB6) => decoders::threedm_event_trigger_status(data, device),
        (0x0C, 0x2D) => decoders::threedm_get_event_action_status(data, device),
        (0x0C, 0xB7) => decoders::threedm_event_action_status(data, device),
        (0x0C, 0x2E) => decoders::threedm_event_trigger_config(data, device),
        (0x0C, 0xB8) => decoders::threedm_event_trigger_config_response(data, device),
        (0x0C, 0x2F) => decoders::threedm_event_action_config(data, device),
        (0x0C, 0xB9) => decoders::threedm_event_action_config_response(data, device),
        (0x0C, 0x30) => decoders::threedm_device_startup_settings(data, device),
        (0x0C, 0x31) => decoders::threedm_sensor_to_vehicle_euler(data, device),
        (0x0C, 0xB1) => decoders::threedm_sensor_to_vehicle_euler_response(data, device),
        (0x0C, 0x32) => decoders::threedm_sensor_to_vehicle_quaternion(data, device),
        (0x0C, 0xB2) => decoders::threedm_sensor_to_vehicle_quaternion_response(data, device),
        (0x0C, 0x33) => decoders::threedm_sensor_to_vehicle_dcm(data, device),
        (0x0C, 0xB3) => decoders::threedm_sensor_to_vehicle_dcm_response(data, device),
        (0x0C, 0x37) => decoders::threedm_accel_bias(data, device),
        (0x0C, 0x9A) => decoders::threedm_accel_bias_response(data, device),
        (0x0C, 0x38) => decoders::threedm_gyro_bias(data, device),
        (0x0C, 0x9B) => decoders::threedm_gyro_bias_response(data, device),
        (0x0C, 0x39) => decoders::threedm_capture_gyro_bias(data, device),
        (0x0C, 0x3A) => decoders::threedm_mag_hard_iron_offset(data, device),
        (0x0C, 0x9C) => decoders::threedm_mag_hard_iron_offset_response(data, device),
        (0x0C, 0x3B) => decoders::threedm_mag_soft_iron_matrix(data, device),
        (0x0C, 0x9D) => decoders::threedm_mag_soft_iron_matrix_response(data, device),
        (0x0C, 0x3E) => decoders::threedm_coning_sculling_enable(data, device),
        (0x0C, 0x9E) => decoders::threedm_coning_sculling_enable_response(data, device),
        (0x0C, 0x40) => decoders::threedm_uart_baudrate(data, device),
        (0x0C, 0x87) => decoders::threedm_uart_baudrate_response(data, device),
        (0x0C, 0x41) => decoders::threedm_gpio_config(data, device),
        (0x0C, 0xC1) => decoders::threedm_gpio_config_response(data, device),
        (0x0C, 0x42) => decoders::threedm_gpio_state(data, device),
        (0x0C, 0xC2) => decoders::threedm_gpio_state_response(data, device),
        (0x0C, 0x43) => decoders::threedm_odometer_config(data, device),
        (0x0C, 0xC3) => decoders::threedm_odometer_config_response(data, device),
        (0x0C, 0x50) => decoders::threedm_advanced_lowpass_filter(data, device),
        (0x0C, 0x8B) => decoders::threedm_advanced_lowpass_filter_response(data, device),
        (0x0C, 0x51) => decoders::threedm_complementary_filter(data, device),
        (0x0C, 0x97) => decoders::threedm_complementary_filter_response(data, device),
        (0x0C, 0x52) => decoders::threedm_sensor_range(data, device),
        (0x0C, 0xD2) => decoders::threedm_sensor_range_response(data, device),
        (0x0C, 0x53) => decoders::threedm_get_calibrated_sensor_ranges(data, device),
        (0x0C, 0xD3) => decoders::threedm_calibrated_sensor_ranges(data, device),
        (0x0C, 0x54) => decoders::threedm_lowpass_filter(data, device),
        (0x0C, 0xD4) => decoders::threedm_lowpass_filter_response(data, device),
        (0x0C, 0x01) => decoders::threedm_poll_imu_data(data, device),
        (0x0C, 0x02) => decoders::threedm_poll_gnss_data(data, device),
        (0x0C, 0x03) => decoders::threedm_poll_filter_data(data, device),
        (0x0C, 0x04) => decoders::threedm_poll_nmea_data(data, device),
        (0x0C, 0x0D) => decoders::threedm_poll_data(data, device),
        (0x0C, 0x06) => decoders::threedm_get_imu_base_rate(data, device),
        (0x0C, 0x83) => decoders::threedm_imu_base_rate(data, device),
        (0x0C, 0x07) => decoders::threedm_get_gnss_base_rate(data, device),
        (0x0C, 0x84) => decoders::threedm_gnss_base_rate(data, device),
        (0x0C, 0x0B) => decoders::threedm_get_filter_base_rate(data, device),
        (0x0C, 0x8A) => decoders::threedm_filter_base_rate(data, device),
        (0x0C, 0x0E) => decoders::threedm_get_base_rate(data, device),
        (0x0C, 0x8E) => decoders::threedm_base_rate(data, device),
        (0x0C, 0x08) => decoders::threedm_imu_message_format(data, device),
        (0x0C, 0x80) => decoders::threedm_imu_message_format_response(data, device),
        (0x0C, 0x09) => decoders::threedm_gnss_message_format(data, device),
        (0x0C, 0x81) => decoders::threedm_gnss_message_format_response(data, device),
        (0x0C, 0x0A) => decoders::threedm_filter_message_format(data, device),
        (0x0C, 0x82) => decoders::threedm_filter_message_format_response(data, device),
        (0x0C, 0x0C) => decoders::threedm_nmea_message_format(data, device),
        (0x0C, 0x8C) => decoders::threedm_nmea_message_format_response(data, device),
        (0x0C, 0x0F) => decoders::threedm_message_format(data, device),
        (0x0C, 0x8F) => decoders::threedm_message_format_response(data, device),
        (0x0C, 0x10) => decoders::threedm_factory_streaming(data, device),
        (0x0C, 0x11) => decoders::threedm_data_stream_control(data, device),
        (0x0C, 0x85) => decoders::threedm_data_stream_control_response(data, device),
        (0x0C, 0x20) => decoders::threedm_raw_rtcm_message(data, device),
        (0x0C, 0x21) => decoders::threedm_gnss_constellation_settings(data, device),
        (0x0C, 0xA0) => decoders::threedm_gnss_constellation_settings_response(data, device),
        (0x0C, 0x22) => decoders::threedm_gnss_sbas_settings(data, device),
        (0x0C, 0xA1) => decoders::threedm_gnss_sbas_settings_response(data, device),
        (0x0C, 0x23) => decoders::threedm_gnss_assisted_fix_control(data, device),
        (0x0C, 0xA2) => decoders::threedm_gnss_assisted_fix_control_response(data, device),
        (0x0C, 0x24) => decoders::threedm_gnss_assist_time_update(data, device),
        (0x0C, 0xA3) => decoders::threedm_gnss_assist_time_update_response(data, device),
        (0x0C, 0x28) => decoders::threedm_pps_source(data, device),
        (0x0C, 0xA8) => decoders::threedm_pps_source_response(data, device),
        (0x0C, 0x2A) => decoders::threedm_get_supported_events(data, device),
        (0x0C, 0xB4) => decoders::threedm_supported_events(data, device),
        (0x0C, 0x64) => decoders::threedm_device_status(data, device),
        (0x0C, 0x90) => decoders::threedm_device_status_response(data, device),
        (0x0D, 0x01) => decoders::filter_reset_filter(data, device),
        (0x0D, 0x02) => decoders::filter_set_initial_attitude(data, device),
        (0x0D, 0x03) => decoders::filter_set_initial_heading(data, device),
        (0x0D, 0x05) => decoders::filter_run_filter(data, device),
        (0x0D, 0x10) => decoders::filter_vehicle_dynamics_mode(data, device),
        (0x0D, 0x80) => decoders::filter_vehicle_dynamics_mode_response(data, device),
        (0x0D, 0x11) => decoders::filter_sensor_to_vehicle_transform(data, device),
        (0x0D, 0x81) => decoders::filter_sensor_to_vehicle_transform_response(data, device),
        (0x0D, 0x12) => decoders::filter_sensor_to_vehicle_offset(data, device),
        (0x0D, 0x82) => decoders::filter_sensor_to_vehicle_offset_response(data, device),
        (0x0D, 0x13) => decoders::filter_antenna_offset(data, device),
        (0x0D, 0x83) => decoders::filter_antenna_offset_response(data, device),
        (0x0D, 0x14) => decoders::filter_estimation_control(data, device),
        (0x0D, 0x84) => decoders::filter_estimation_control_response(data, device),
        (0x0D, 0x15) => decoders::filter_gnss_source_control(data, device),
        (0x0D, 0x86) => decoders::filter_gnss_source_control_response(data, device),
        (0x0D, 0x16) => decoders::filter_external_gnss_update(data, device),
        (0x0D, 0x17) => decoders::filter_external_heading_update(data, device),
        (0x0D, 0x18) => decoders::filter_heading_update_control(data, device),
        (0x0D, 0x87) => decoders::filter_heading_update_control_response(data, device),
        (0x0D, 0x19) => decoders::filter_auto_init_control(data, device),
        (0x0D, 0x88) => decoders::filter_auto_init_control_response(data, device),
        (0x0D, 0x1A) => decoders::filter_accel_noise(data, device),
        (0x0D, 0x89) => decoders::filter_accel_noise_response(data, device),
        (0x0D, 0x1B) => decoders::filter_gyro_noise(data, device),
        (0x0D, 0x8A) => decoders::filter_gyro_noise_response(data, device),
        (0x0D, 0x1C) => decoders::filter_accel_bias_model(data, device),
        (0x0D, 0x8B) => decoders::filter_accel_bias_model_response(data, device),
        (0x0D, 0x1D) => decoders::filter_gyro_bias_model(data, device),
        (0x0D, 0x8C) => decoders::filter_gyro_bias_model_response(data, device),
        (0x0D, 0x1E) => decoders::filter_zupt_control(data, device),
        (0x0D, 0x8D) => decoders::filter_zupt_control_response(data, device),
        (0x0D, 0x1F) => decoders::filter_external_heading_update_with_time(data, device),
        (0x0D, 0x20) => decoders::filter_zero_angular_rate_update_control(data, device),
        (0x0D, 0x8E) => decoders::filter_zero_angular_rate_update_control_response(data, device),
        (0x0D, 0x21) => decoders::filter_tare_orientation(data, device),
        (0x0D, 0x22) => decoders::filter_commanded_zupt(data, device),
        (0x0D, 0x23) => decoders::filter_commanded_zero_angular_rate_update(data, device),
        (0x0D, 0x27) => decoders::filter_mag_capture_auto_calibration(data, device),
        (0x0D, 0x28) => decoders::filter_gravity_noise_std_dev(data, device),
        (0x0D, 0x93) => decoders::filter_gravity_noise_std_dev_response(data, device),
        (0x0D, 0x29) => decoders::filter_pressure_altitude_noise_std_dev(data, device),
        (0x0D, 0x94) => decoders::filter_pressure_altitude_noise_std_dev_response(data, device),
        (0x0D, 0x2B) => decoders::filter_hard_iron_offset_noise(data, device),
        (0x0D, 0x96) => decoders::filter_hard_iron_offset_noise_response(data, device),
        (0x0D, 0x2C) => decoders::filter_soft_iron_matrix_noise(data, device),
        (0x0D, 0x97) => decoders::filter_soft_iron_matrix_noise_response(data, device),
        (0x0D, 0x42) => decoders::filter_mag_noise_std_dev(data, device),
        (0x0D, 0xB1) => decoders::filter_mag_noise_std_dev_response(data, device),
        (0x0D, 0x43) => decoders::filter_declination_source(data, device),
        (0x0D, 0xB2) => decoders::filter_declination_source_response(data, device),
        (0x0D, 0x44) => decoders::filter_gravity_magnitude_adaptive_measurement(data, device),
        (0x0D, 0xB3) => {
            decoders::filter_gravity_magnitude_adaptive_measurement_response(data, device)
        }
        (0x0D, 0x45) => decoders::filter_mag_magnitude_adaptive_measurement(data, device),
        (0x0D, 0xB4) => decoders::filter_mag_magnitude_adaptive_measurement_response(data, device),
        (0x0D, 0x46) => decoders::filter_mag_dip_angle_adaptive_measurement(data, device),
        (0x0D, 0xB5) => decoders::filter_mag_dip_angle_adaptive_measurement_response(data, device),
        (0x0D, 0x47) => decoders::filter_altitude_aiding_control(data, device),
        (0x0D, 0xB7) => decoders::filter_altitude_aiding_control_response(data, device),
        (0x0D, 0x4B) => decoders::filter_pitch_roll_aiding_control(data, device),
        (0x0D, 0xBB) => decoders::filter_pitch_roll_aiding_control_response(data, device),
        (0x0D, 0x4C) => decoders::filter_inclination_source(data, device),
        (0x0D, 0xBC) => decoders::filter_inclination_source_response(data, device),
        (0x0D, 0x4D) => decoders::filter_magnetic_field_magnitude_source(data, device),
        (0x0D, 0xBD) => decoders::filter_magnetic_field_magnitude_source_response(data, device),
        (0x0D, 0x50) => decoders::filter_aiding_measurement_control(data, device),
        (0x0D, 0xD0) => decoders::filter_aiding_measurement_control_response(data, device),
        (0x0D, 0x52) => decoders::filter_initialization_configuration(data, device),
        (0x0D, 0xD2) => decoders::filter_initialization_configuration_response(data, device),
        (0x0D, 0x53) => decoders::filter_adaptive_filter_control(data, device),
        (0x0D, 0xD3) => decoders::filter_adaptive_filter_control_response(data, device),
        (0x0D, 0x54) => decoders::filter_multi_antenna_offset(data, device),
        (0x0D, 0xD4) => decoders::filter_multi_antenna_offset_response(data, device),
        (0x0D, 0x55) => decoders::filter_relative_position_configuration(data, device),
        (0x0D, 0xD5) => decoders::filter_relative_position_configuration_response(data, device),
        (0x0D, 0x56) => decoders::filter_reference_point_lever_arm(data, device),
        (0x0D, 0xD6) => decoders::filter_reference_point_lever_arm_response(data, device),
        (0x0D, 0x61) => decoders::filter_speed_lever_arm(data, device),
        (0x0D, 0xE1) => decoders::filter_speed_lever_arm_response(data, device),
        (0x0D, 0x63) => decoders::filter_wheeled_vehicle_constraint_control(data, device),
        (0x0D, 0xE3) => decoders::filter_wheeled_vehicle_constraint_control_response(data, device),
        (0x0D, 0x64) => decoders::filter_gnss_antenna_calibration_control(data, device),
        (0x0D, 0xE4) => decoders::filter_gnss_antenna_calibration_control_response(data, device),
        (0x0E, 0x01) => decoders::gnss_receiver_info(data, device),
        (0x0E, 0x81) => decoders::gnss_receiver_info_response(data, device),
        (0x0E, 0x02) => decoders::gnss_signal_configuration(data, device),
        (0x0E, 0x82) => decoders::gnss_signal_configuration_response(data, device),
        (0x0E, 0x20) => decoders::gnss_spartn_configuration(data, device),
        (0x0E, 0xA0) => decoders::gnss_spartn_configuration_response(data, device),
        (0x13, 0x01) => decoders::aiding_frame_config(data, device),
        (0x13, 0x81) => decoders::aiding_frame_config_response(data, device),
        (0x13, 0x1F) => decoders::aiding_echo_control(data, device),
        (0x13, 0x9F) => decoders::aiding_echo_control_response(data, device),
        (0x13, 0x21) => decoders::aiding_ecef_position(data, device),
        (0x13, 0x22) => decoders::aiding_llh_position(data, device),
        (0x13, 0x23) => decoders::aiding_height_above_ellipsoid(data, device),
        (0x13, 0x28) => decoders::aiding_ecef_velocity(data, device),
        (0x13, 0x29) => decoders::aiding_ned_velocity(data, device),
        (0x13, 0x2A) => decoders::aiding_body_frame_velocity(data, device),
        (0x13, 0x31) => decoders::aiding_true_heading(data, device),
        (0x13, 0x32) => decoders::aiding_magnetic_field(data, device),
        (0x13, 0x33) => decoders::aiding_pressure(data, device),
        (0x7F, 0x10) => decoders::system_communication_mode(data, device),
        (0x7F, 0x90) => decoders::system_communication_mode_response(data, device),
        (0x80, 0x04) => decoders::sensor_scaled_accel(data, device),
        (0x80, 0x05) => decoders::sensor_scaled_gyro(data, device),
        (0x80, 0x06) => decoders::sensor_scaled_mag(data, device),
        (0x80, 0x07) => decoders::sensor_delta_theta(data, device),
        (0x80, 0x08) => decoders::sensor_delta_velocity(data, device),
        (0x80, 0x09) => decoders::sensor_cf_orientation_matrix(data, device),
        (0x80, 0x0A) => decoders::sensor_cf_quaternion(data, device),
        (0x80, 0x0C) => decoders::sensor_cf_euler_angles(data, device),
        (0x80, 0x10) => decoders::sensor_cf_stabilized_north(data, device),
        (0x80, 0x11) => decoders::sensor_cf_stabilized_up(data, device),
        (0x80, 0x12) => decoders::sensor_gps_timestamp(data, device),
        (0x80, 0x14) => decoders::sensor_temperature_statistics(data, device),
        (0x80, 0x17) => decoders::sensor_scaled_pressure(data, device),
        (0x80, 0x18) => decoders::sensor_overrange_status(data, device),
        (0x80, 0x40) => decoders::sensor_odometer_data(data, device),
        (0x81, 0x03) => decoders::gnss_data_llh_position(data, device),
        (0x81, 0x04) => decoders::gnss_data_ecef_position(data, device),
        (0x81, 0x05) => decoders::gnss_data_ned_velocity(data, device),
        (0x81, 0x06) => decoders::gnss_data_ecef_velocity(data, device),
        (0x81, 0x07) => decoders::gnss_data_dop(data, device),
        (0x81, 0x08) => decoders::gnss_data_utc_time(data, device),
        (0x81, 0x09) => decoders::gnss_data_gps_time(data, device),
        (0x81, 0x0A) => decoders::gnss_data_clock_info(data, device),
        (0x81, 0x0B) => decoders::gnss_data_fix_info(data, device),
        (0x81, 0x0C) => decoders::gnss_data_sv_info(data, device),
        (0x81, 0x0D) => decoders::gnss_data_hardware_status(data, device),
        (0x81, 0x0E) => decoders::gnss_data_dgnss_info(data, device),
        (0x81, 0x0F) => decoders::gnss_data_dgnss_channel_status(data, device),
        (0x82, 0x01) => decoders::filter_data_llh_position(data, device),
        (0x82, 0x02) => decoders::filter_data_ned_velocity(data, device),
        (0x82, 0x03) => decoders::filter_data_attitude_quaternion(data, device),
        (0x82, 0x04) => decoders::filter_data_attitude_dcm(data, device),
        (0x82, 0x05) => decoders::filter_data_euler_angles(data, device),
        (0x82, 0x06) => decoders::filter_data_gyro_bias(data, device),
        (0x82, 0x07) => decoders::filter_data_accel_bias(data, device),
        (0x82, 0x08) => decoders::filter_data_llh_position_uncertainty(data, device),
        (0x82, 0x09) => decoders::filter_data_ned_velocity_uncertainty(data, device),
        (0x82, 0x0A) => decoders::filter_data_euler_angles_uncertainty(data, device),
        (0x82, 0x0B) => decoders::filter_data_gyro_bias_uncertainty(data, device),
        (0x82, 0x0C) => decoders::filter_data_accel_bias_uncertainty(data, device),
        (0x82, 0x0D) => decoders::filter_data_linear_accel(data, device),
        (0x82, 0x0E) => decoders::filter_data_comp_angular_rate(data, device),
        (0x82, 0x0F) => decoders::filter_data_wgs84_gravity_magnitude(data, device),
        (0x82, 0x10) => decoders::filter_data_filter_status(data, device),
        (0x82, 0x11) => decoders::filter_data_gps_timestamp(data, device),
        (0x82, 0x12) => decoders::filter_data_quaternion_attitude_uncertainty(data, device),
        (0x82, 0x13) => decoders::filter_data_gravity_vector(data, device),
        (0x82, 0x14) => decoders::filter_data_heading_update_state(data, device),
        (0x82, 0x15) => decoders::filter_data_magnetic_model(data, device),
        (0x82, 0x16) => decoders::filter_data_gyro_scale_factor(data, device),
        (0x82, 0x17) => decoders::filter_data_accel_scale_factor(data, device),
        (0x82, 0x18) => decoders::filter_data_gyro_scale_factor_uncertainty(data, device),
        (0x82, 0x19) => decoders::filter_data_accel_scale_factor_uncertainty(data, device),
        (0x82, 0x1C) => decoders::filter_data_compensated_accel(data, device),
        (0x82, 0x20) => decoders::filter_data_standard_atmosphere(data, device),
        (0x82, 0x21) => decoders::filter_data_pressure_altitude(data, device),
        (0x82, 0x25) => decoders::filter_data_mag_auto_hard_iron_offset(data, device),
        (0x82, 0x26) => decoders::filter_data_mag_auto_soft_iron_matrix(data, device),
        (0x82, 0x28) => decoders::filter_data_mag_auto_hard_iron_offset_uncertainty(data, device),
        (0x82, 0x29) => decoders::filter_data_mag_auto_soft_iron_matrix_uncertainty(data, device),
        (0x82, 0x30) => decoders::filter_data_gnss_antenna_offset_correction(data, device),
        (0x82, 0x31) => {
            decoders::filter_data_gnss_antenna_offset_correction_uncertainty(data, device)
        }
        (0x82, 0x34) => decoders::filter_data_multi_antenna_offset_correction(data, device),
        (0x82, 0x35) => {
            decoders::filter_data_multi_antenna_offset_correction_uncertainty(data, device)
        }
        (0x82, 0x36) => decoders::filter_data_ecef_position_uncertainty(data, device),
        (0x82, 0x37) => decoders::filter_data_ecef_velocity_uncertainty(data, device),
        (0x82, 0x40) => decoders::filter_data_ecef_position(data, device),
        (0x82, 0x41) => decoders::filter_data_ecef_velocity(data, device),
        (0x82, 0x42) => decoders::filter_data_ned_relative_position(data, device),
        (0x82, 0x43) => decoders::filter_data_gnss_position_aiding_status(data, device),
        (0x82, 0x46) => decoders::filter_data_aiding_measurement_summary(data, device),
        (0x82, 0x47) => decoders::filter_data_odometer_scale_factor_error(data, device),
        (0x82, 0x48) => decoders::filter_data_odometer_scale_factor_error_uncertainty(data, device),
        (0x82, 0x49) => decoders::filter_data_gnss_dual_antenna_status(data, device),
        (0x82, 0x50) => decoders::filter_data_aiding_frame_config_error(data, device),
        (0x82, 0x51) => decoders::filter_data_aiding_frame_config_error_uncertainty(data, device),
        (0x91, 0x03) => decoders::gnss_receiver_1_llh_position(data, device),
        (0x91, 0x04) => decoders::gnss_receiver_1_ecef_position(data, device),
        (0x91, 0x05) => decoders::gnss_receiver_1_ned_velocity(data, device),
        (0x91, 0x06) => decoders::gnss_receiver_1_ecef_velocity(data, device),
        (0x91, 0x07) => decoders::gnss_receiver_1_dop(data, device),
        (0x91, 0x08) => decoders::gnss_receiver_1_utc_time(data, device),
        (0x91, 0x09) => decoders::gnss_receiver_1_gps_time(data, device),
        (0x91, 0x0B) => decoders::gnss_receiver_1_fix_info(data, device),
        (0x91, 0x0D) => decoders::gnss_receiver_1_hardware_status(data, device),
        (0x91, 0x10) => decoders::gnss_receiver_1_clock_info_2(data, device),
        (0x91, 0x11) => decoders::gnss_receiver_1_gps_leap_seconds(data, device),
        (0x91, 0x12) => decoders::gnss_receiver_1_sbas_info(data, device),
        (0x91, 0x20) => decoders::gnss_receiver_1_satellite_status(data, device),
        (0x91, 0x22) => decoders::gnss_receiver_1_raw(data, device),
        (0x91, 0x61) => decoders::gnss_receiver_1_gps_ephemeris(data, device),
        (0x91, 0x62) => decoders::gnss_receiver_1_glonass_ephemeris(data, device),
        (0x91, 0x63) => decoders::gnss_receiver_1_galileo_ephemeris(data, device),
        (0x91, 0x64) => decoders::gnss_receiver_1_beidou_ephemeris(data, device),
        (0x92, 0x03) => decoders::gnss_receiver_2_llh_position(data, device),
        (0x92, 0x04) => decoders::gnss_receiver_2_ecef_position(data, device),
        (0x92, 0x05) => decoders::gnss_receiver_2_ned_velocity(data, device),
        (0x92, 0x06) => decoders::gnss_receiver_2_ecef_velocity(data, device),
        (0x92, 0x07) => decoders::gnss_receiver_2_dop(data, device),
        (0x92, 0x08) => decoders::gnss_receiver_2_utc_time(data, device),
        (0x92, 0x09) => decoders::gnss_receiver_2_gps_time(data, device),
        (0x92, 0x0B) => decoders::gnss_receiver_2_fix_info(data, device),
        (0x92, 0x0D) => decoders::gnss_receiver_2_hardware_status(data, device),
        (0x92, 0x10) => decoders::gnss_receiver_2_clock_info_2(data, device),
        (0x92, 0x11) => decoders::gnss_receiver_2_gps_leap_seconds(data, device),
        (0x92, 0x12) => decoders::gnss_receiver_2_sbas_info(data, device),
        (0x92, 0x20) => decoders::gnss_receiver_2_satellite_status(data, device),
        (0x92, 0x22) => decoders::gnss_receiver_2_raw(data, device),
        (0x92, 0x61) => decoders::gnss_receiver_2_gps_ephemeris(data, device),
        (0x92, 0x62) => decoders::gnss_receiver_2_glonass_ephemeris(data, device),
        (0x92, 0x63) => decoders::gnss_receiver_2_galileo_ephemeris(data, device),
        (0x92, 0x64) => decoders::gnss_receiver_2_beidou_ephemeris(data, device),
        (0x93, 0x30) => decoders::gnss_corrections_base_station_info(data, device),
        (0x93, 0x31) => decoders::gnss_corrections_rtk_corrections_status(data, device),
        (0x94, 0x03) => decoders::gnss_external_llh_position(data, device),
        (0x94, 0x05) => decoders::gnss_external_ned_velocity(data, device),
        (0x94, 0x08) => decoders::gnss_external_utc_time(data, device),
        (0x94, 0x0B) => decoders::gnss_external_fix_info(data, device),
        (0x94, 0x20) => decoders::gnss_external_satellite_status(data, device),
        (0xA0, 0x01) => decoders::system_data_built_in_test(data, device),
        (0xA0, 0x02) => decoders::system_data_time_sync_status(data, device),
        (0xA0, 0x03) => decoders::system_data_gpio_state(data, device),
        (0xFF, 0xD0) => decoders::shared_event_source(data, device),
        (0xFF, 0xD3) => decoders::shared_gps_timestamp(data, device),
        (0xFF, 0xD4) => decoders::shared_delta_time(data, device),
        (0xFF, 0xD5) => decoders::shared_reference_timestamp(data, device),
        (0xFF, 0xD6) => decoders::shared_reference_time_delta(data, device),
        (0xFF, 0xD7) => decoders::shared_external_timestamp(data, device),
        (0xFF, 0xD8) => decoders::shared_external_time_delta(data, device),
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
    if kind == Some(SetKind::Data) {
        if let Some(result) = crate::shared::SetField::decode(descriptor, data, device) {
            return result.map(FieldValue::Shared);
        }
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
    pub(super) fn base_set_to_idle(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::base::SetToIdle as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Base(crate::base::SetField::SetToIdle(v)))
    }

    #[inline(never)]
    pub(super) fn base_get_device_info(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::base::GetDeviceInfo as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Base(crate::base::SetField::GetDeviceInfo(v)))
    }

    #[inline(never)]
    pub(super) fn base_device_info(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::base::DeviceInfo as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Base(crate::base::SetField::DeviceInfo(v)))
    }

    #[inline(never)]
    pub(super) fn base_get_device_descriptors(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::base::GetDeviceDescriptors as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Base(crate::base::SetField::GetDeviceDescriptors(v)))
    }

    #[inline(never)]
    pub(super) fn base_device_descriptors(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::base::DeviceDescriptors as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Base(crate::base::SetField::DeviceDescriptors(v)))
    }

    #[inline(never)]
    pub(super) fn base_built_in_test(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::base::BuiltInTest as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Base(crate::base::SetField::BuiltInTest(v)))
    }

    #[inline(never)]
    pub(super) fn base_built_in_test_result(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        crate::base::BuiltInTestResult::decode_data(data, device)
            .map(|v| FieldValue::Base(crate::base::SetField::BuiltInTestResult(v)))
    }

    #[inline(never)]
    pub(super) fn base_resume(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::base::Resume as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Base(crate::base::SetField::Resume(v)))
    }

    #[inline(never)]
    pub(super) fn base_get_extended_descriptors(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::base::GetExtendedDescriptors as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Base(crate::base::SetField::GetExtendedDescriptors(v)))
    }

    #[inline(never)]
    pub(super) fn base_extended_descriptors(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::base::ExtendedDescriptors as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Base(crate::base::SetField::ExtendedDescriptors(v)))
    }

    #[inline(never)]
    pub(super) fn base_continuous_bit(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::base::ContinuousBit as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Base(crate::base::SetField::ContinuousBit(v)))
    }

    #[inline(never)]
    pub(super) fn base_continuous_bit_result(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::base::ContinuousBitResult as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Base(crate::base::SetField::ContinuousBitResult(v)))
    }

    #[inline(never)]
    pub(super) fn base_comm_port_speed(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::base::CommPortSpeed as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Base(crate::base::SetField::CommPortSpeed(v)))
    }

    #[inline(never)]
    pub(super) fn base_comm_port_speed_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::base::CommPortSpeedResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Base(crate::base::SetField::CommPortSpeedResponse(v)))
    }

    #[inline(never)]
    pub(super) fn base_gps_time_update(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        crate::base::GpsTimeUpdate::decode_data(data, device)
            .map(|v| FieldValue::Base(crate::base::SetField::GpsTimeUpdate(v)))
    }

    #[inline(never)]
    pub(super) fn base_gps_week(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::base::GpsWeek as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Base(crate::base::SetField::GpsWeek(v)))
    }

    #[inline(never)]
    pub(super) fn base_gps_seconds(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::base::GpsSeconds as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Base(crate::base::SetField::GpsSeconds(v)))
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
    pub(super) fn threedm_event_control(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::EventControl as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::EventControl(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_event_control_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::EventControlResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::EventControlResponse(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_get_event_trigger_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::GetEventTriggerStatus as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::GetEventTriggerStatus(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_event_trigger_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::EventTriggerStatus as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::EventTriggerStatus(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_get_event_action_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::GetEventActionStatus as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::GetEventActionStatus(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_event_action_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::EventActionStatus as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::EventActionStatus(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_event_trigger_config(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::EventTriggerConfig as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::EventTriggerConfig(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_event_trigger_config_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::EventTriggerConfigResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::EventTriggerConfigResponse(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_event_action_config(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::EventActionConfig as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::EventActionConfig(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_event_action_config_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::EventActionConfigResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::EventActionConfigResponse(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_device_startup_settings(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        crate::threedm::DeviceStartupSettings::decode_data(data, device)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::DeviceStartupSettings(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_sensor_to_vehicle_euler(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::SensorToVehicleEuler as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleEuler(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_sensor_to_vehicle_euler_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::SensorToVehicleEulerResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleEulerResponse(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_sensor_to_vehicle_quaternion(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::SensorToVehicleQuaternion as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleQuaternion(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_sensor_to_vehicle_quaternion_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::SensorToVehicleQuaternionResponse as crate::wire::Layout>::decode_data(
            data,
        )
        .map(|v| {
            FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleQuaternionResponse(
                v,
            ))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_sensor_to_vehicle_dcm(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::SensorToVehicleDcm as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleDcm(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_sensor_to_vehicle_dcm_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::SensorToVehicleDcmResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::SensorToVehicleDcmResponse(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_accel_bias(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        crate::threedm::AccelBias::decode_data(data, device)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::AccelBias(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_accel_bias_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::AccelBiasResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::AccelBiasResponse(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_gyro_bias(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        crate::threedm::GyroBias::decode_data(data, device)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::GyroBias(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_gyro_bias_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::GyroBiasResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::GyroBiasResponse(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_capture_gyro_bias(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::CaptureGyroBias as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::CaptureGyroBias(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_mag_hard_iron_offset(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        crate::threedm::MagHardIronOffset::decode_data(data, device)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::MagHardIronOffset(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_mag_hard_iron_offset_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::MagHardIronOffsetResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::MagHardIronOffsetResponse(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_mag_soft_iron_matrix(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        crate::threedm::MagSoftIronMatrix::decode_data(data, device)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::MagSoftIronMatrix(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_mag_soft_iron_matrix_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::MagSoftIronMatrixResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::MagSoftIronMatrixResponse(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_coning_sculling_enable(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::ConingScullingEnable as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::ConingScullingEnable(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_coning_sculling_enable_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::ConingScullingEnableResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::ConingScullingEnableResponse(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_uart_baudrate(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::UartBaudrate as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::UartBaudrate(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_uart_baudrate_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::UartBaudrateResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::UartBaudrateResponse(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_gpio_config(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::GpioConfig as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::GpioConfig(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_gpio_config_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::GpioConfigResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::GpioConfigResponse(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_gpio_state(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::GpioState as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::GpioState(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_gpio_state_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::GpioStateResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::GpioStateResponse(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_odometer_config(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::OdometerConfig as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::OdometerConfig(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_odometer_config_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::OdometerConfigResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::OdometerConfigResponse(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_advanced_lowpass_filter(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::AdvancedLowpassFilter as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::AdvancedLowpassFilter(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_advanced_lowpass_filter_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::AdvancedLowpassFilterResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| {
                FieldValue::Threedm(crate::threedm::SetField::AdvancedLowpassFilterResponse(v))
            })
    }

    #[inline(never)]
    pub(super) fn threedm_complementary_filter(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::ComplementaryFilter as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::ComplementaryFilter(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_complementary_filter_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::ComplementaryFilterResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::ComplementaryFilterResponse(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_sensor_range(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::SensorRange as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::SensorRange(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_sensor_range_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::SensorRangeResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::SensorRangeResponse(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_get_calibrated_sensor_ranges(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::GetCalibratedSensorRanges as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::GetCalibratedSensorRanges(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_calibrated_sensor_ranges(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::CalibratedSensorRanges as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::CalibratedSensorRanges(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_lowpass_filter(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::LowpassFilter as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::LowpassFilter(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_lowpass_filter_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::LowpassFilterResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::LowpassFilterResponse(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_poll_imu_data(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::PollImuData as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::PollImuData(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_poll_gnss_data(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::PollGnssData as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::PollGnssData(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_poll_filter_data(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::PollFilterData as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::PollFilterData(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_poll_nmea_data(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::PollNmeaData as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::PollNmeaData(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_poll_data(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::PollData as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::PollData(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_get_imu_base_rate(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::GetImuBaseRate as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::GetImuBaseRate(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_imu_base_rate(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::ImuBaseRate as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::ImuBaseRate(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_get_gnss_base_rate(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::GetGnssBaseRate as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::GetGnssBaseRate(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_gnss_base_rate(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::GnssBaseRate as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::GnssBaseRate(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_get_filter_base_rate(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::GetFilterBaseRate as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::GetFilterBaseRate(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_filter_base_rate(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::FilterBaseRate as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::FilterBaseRate(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_get_base_rate(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::GetBaseRate as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::GetBaseRate(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_base_rate(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::BaseRate as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::BaseRate(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_imu_message_format(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::ImuMessageFormat as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::ImuMessageFormat(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_imu_message_format_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::ImuMessageFormatResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::ImuMessageFormatResponse(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_gnss_message_format(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::GnssMessageFormat as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::GnssMessageFormat(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_gnss_message_format_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::GnssMessageFormatResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::GnssMessageFormatResponse(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_filter_message_format(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::FilterMessageFormat as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::FilterMessageFormat(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_filter_message_format_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::FilterMessageFormatResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::FilterMessageFormatResponse(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_nmea_message_format(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::NmeaMessageFormat as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::NmeaMessageFormat(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_nmea_message_format_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::NmeaMessageFormatResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::NmeaMessageFormatResponse(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_message_format(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::MessageFormat as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::MessageFormat(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_message_format_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::MessageFormatResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::MessageFormatResponse(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_factory_streaming(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::FactoryStreaming as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::FactoryStreaming(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_data_stream_control(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        crate::threedm::DataStreamControl::decode_data(data, device)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::DataStreamControl(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_data_stream_control_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        crate::threedm::DataStreamControlResponse::decode_data(data, device)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::DataStreamControlResponse(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_raw_rtcm_message(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::RawRtcmMessage as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::RawRtcmMessage(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_gnss_constellation_settings(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::GnssConstellationSettings as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::GnssConstellationSettings(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_gnss_constellation_settings_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::GnssConstellationSettingsResponse as crate::wire::Layout>::decode_data(
            data,
        )
        .map(|v| {
            FieldValue::Threedm(crate::threedm::SetField::GnssConstellationSettingsResponse(
                v,
            ))
        })
    }

    #[inline(never)]
    pub(super) fn threedm_gnss_sbas_settings(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::GnssSbasSettings as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::GnssSbasSettings(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_gnss_sbas_settings_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::GnssSbasSettingsResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::GnssSbasSettingsResponse(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_gnss_assisted_fix_control(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::GnssAssistedFixControl as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::GnssAssistedFixControl(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_gnss_assisted_fix_control_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::GnssAssistedFixControlResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| {
                FieldValue::Threedm(crate::threedm::SetField::GnssAssistedFixControlResponse(v))
            })
    }

    #[inline(never)]
    pub(super) fn threedm_gnss_assist_time_update(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::GnssAssistTimeUpdate as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::GnssAssistTimeUpdate(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_gnss_assist_time_update_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::GnssAssistTimeUpdateResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::GnssAssistTimeUpdateResponse(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_pps_source(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::PpsSource as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::PpsSource(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_pps_source_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::PpsSourceResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::PpsSourceResponse(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_get_supported_events(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::GetSupportedEvents as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::GetSupportedEvents(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_supported_events(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::SupportedEvents as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::SupportedEvents(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_device_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::DeviceStatus as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::DeviceStatus(v)))
    }

    #[inline(never)]
    pub(super) fn threedm_device_status_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::threedm::DeviceStatusResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Threedm(crate::threedm::SetField::DeviceStatusResponse(v)))
    }

    #[inline(never)]
    pub(super) fn filter_reset_filter(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::ResetFilter as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::ResetFilter(v)))
    }

    #[inline(never)]
    pub(super) fn filter_set_initial_attitude(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::SetInitialAttitude as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::SetInitialAttitude(v)))
    }

    #[inline(never)]
    pub(super) fn filter_set_initial_heading(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::SetInitialHeading as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::SetInitialHeading(v)))
    }

    #[inline(never)]
    pub(super) fn filter_run_filter(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::RunFilter as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::RunFilter(v)))
    }

    #[inline(never)]
    pub(super) fn filter_vehicle_dynamics_mode(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::VehicleDynamicsMode as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::VehicleDynamicsMode(v)))
    }

    #[inline(never)]
    pub(super) fn filter_vehicle_dynamics_mode_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::VehicleDynamicsModeResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::VehicleDynamicsModeResponse(v)))
    }

    #[inline(never)]
    pub(super) fn filter_sensor_to_vehicle_transform(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::SensorToVehicleTransform as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::SensorToVehicleTransform(v)))
    }

    #[inline(never)]
    pub(super) fn filter_sensor_to_vehicle_transform_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::SensorToVehicleTransformResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| {
                FieldValue::Filter(crate::filter::SetField::SensorToVehicleTransformResponse(v))
            })
    }

    #[inline(never)]
    pub(super) fn filter_sensor_to_vehicle_offset(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::SensorToVehicleOffset as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::SensorToVehicleOffset(v)))
    }

    #[inline(never)]
    pub(super) fn filter_sensor_to_vehicle_offset_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::SensorToVehicleOffsetResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::SensorToVehicleOffsetResponse(v)))
    }

    #[inline(never)]
    pub(super) fn filter_antenna_offset(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::AntennaOffset as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::AntennaOffset(v)))
    }

    #[inline(never)]
    pub(super) fn filter_antenna_offset_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::AntennaOffsetResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::AntennaOffsetResponse(v)))
    }

    #[inline(never)]
    pub(super) fn filter_estimation_control(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::EstimationControl as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::EstimationControl(v)))
    }

    #[inline(never)]
    pub(super) fn filter_estimation_control_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::EstimationControlResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::EstimationControlResponse(v)))
    }

    #[inline(never)]
    pub(super) fn filter_gnss_source_control(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::GnssSourceControl as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::GnssSourceControl(v)))
    }

    #[inline(never)]
    pub(super) fn filter_gnss_source_control_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::GnssSourceControlResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::GnssSourceControlResponse(v)))
    }

    #[inline(never)]
    pub(super) fn filter_external_gnss_update(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::ExternalGnssUpdate as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::ExternalGnssUpdate(v)))
    }

    #[inline(never)]
    pub(super) fn filter_external_heading_update(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::ExternalHeadingUpdate as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::ExternalHeadingUpdate(v)))
    }

    #[inline(never)]
    pub(super) fn filter_heading_update_control(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::HeadingUpdateControl as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::HeadingUpdateControl(v)))
    }

    #[inline(never)]
    pub(super) fn filter_heading_update_control_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::HeadingUpdateControlResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::HeadingUpdateControlResponse(v)))
    }

    #[inline(never)]
    pub(super) fn filter_auto_init_control(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::AutoInitControl as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::AutoInitControl(v)))
    }

    #[inline(never)]
    pub(super) fn filter_auto_init_control_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::AutoInitControlResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::AutoInitControlResponse(v)))
    }

    #[inline(never)]
    pub(super) fn filter_accel_noise(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::AccelNoise as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::AccelNoise(v)))
    }

    #[inline(never)]
    pub(super) fn filter_accel_noise_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::AccelNoiseResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::AccelNoiseResponse(v)))
    }

    #[inline(never)]
    pub(super) fn filter_gyro_noise(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::GyroNoise as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::GyroNoise(v)))
    }

    #[inline(never)]
    pub(super) fn filter_gyro_noise_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::GyroNoiseResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::GyroNoiseResponse(v)))
    }

    #[inline(never)]
    pub(super) fn filter_accel_bias_model(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::AccelBiasModel as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::AccelBiasModel(v)))
    }

    #[inline(never)]
    pub(super) fn filter_accel_bias_model_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::AccelBiasModelResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::AccelBiasModelResponse(v)))
    }

    #[inline(never)]
    pub(super) fn filter_gyro_bias_model(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::GyroBiasModel as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::GyroBiasModel(v)))
    }

    #[inline(never)]
    pub(super) fn filter_gyro_bias_model_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::GyroBiasModelResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::GyroBiasModelResponse(v)))
    }

    #[inline(never)]
    pub(super) fn filter_zupt_control(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::ZuptControl as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::ZuptControl(v)))
    }

    #[inline(never)]
    pub(super) fn filter_zupt_control_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::ZuptControlResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::ZuptControlResponse(v)))
    }

    #[inline(never)]
    pub(super) fn filter_external_heading_update_with_time(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::ExternalHeadingUpdateWithTime as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::ExternalHeadingUpdateWithTime(v)))
    }

    #[inline(never)]
    pub(super) fn filter_zero_angular_rate_update_control(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::ZeroAngularRateUpdateControl as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::ZeroAngularRateUpdateControl(v)))
    }

    #[inline(never)]
    pub(super) fn filter_zero_angular_rate_update_control_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::ZeroAngularRateUpdateControlResponse as crate::wire::Layout>::decode_data(
            data,
        )
        .map(|v| {
            FieldValue::Filter(crate::filter::SetField::ZeroAngularRateUpdateControlResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_tare_orientation(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::TareOrientation as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::TareOrientation(v)))
    }

    #[inline(never)]
    pub(super) fn filter_commanded_zupt(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::CommandedZupt as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::CommandedZupt(v)))
    }

    #[inline(never)]
    pub(super) fn filter_commanded_zero_angular_rate_update(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::CommandedZeroAngularRateUpdate as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::CommandedZeroAngularRateUpdate(v)))
    }

    #[inline(never)]
    pub(super) fn filter_mag_capture_auto_calibration(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::MagCaptureAutoCalibration as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::MagCaptureAutoCalibration(v)))
    }

    #[inline(never)]
    pub(super) fn filter_gravity_noise_std_dev(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::GravityNoiseStdDev as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::GravityNoiseStdDev(v)))
    }

    #[inline(never)]
    pub(super) fn filter_gravity_noise_std_dev_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::GravityNoiseStdDevResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::GravityNoiseStdDevResponse(v)))
    }

    #[inline(never)]
    pub(super) fn filter_pressure_altitude_noise_std_dev(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::PressureAltitudeNoiseStdDev as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::PressureAltitudeNoiseStdDev(v)))
    }

    #[inline(never)]
    pub(super) fn filter_pressure_altitude_noise_std_dev_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::PressureAltitudeNoiseStdDevResponse as crate::wire::Layout>::decode_data(
            data,
        )
        .map(|v| {
            FieldValue::Filter(crate::filter::SetField::PressureAltitudeNoiseStdDevResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_hard_iron_offset_noise(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::HardIronOffsetNoise as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::HardIronOffsetNoise(v)))
    }

    #[inline(never)]
    pub(super) fn filter_hard_iron_offset_noise_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::HardIronOffsetNoiseResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::HardIronOffsetNoiseResponse(v)))
    }

    #[inline(never)]
    pub(super) fn filter_soft_iron_matrix_noise(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::SoftIronMatrixNoise as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::SoftIronMatrixNoise(v)))
    }

    #[inline(never)]
    pub(super) fn filter_soft_iron_matrix_noise_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::SoftIronMatrixNoiseResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::SoftIronMatrixNoiseResponse(v)))
    }

    #[inline(never)]
    pub(super) fn filter_mag_noise_std_dev(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::MagNoiseStdDev as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::MagNoiseStdDev(v)))
    }

    #[inline(never)]
    pub(super) fn filter_mag_noise_std_dev_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::MagNoiseStdDevResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::MagNoiseStdDevResponse(v)))
    }

    #[inline(never)]
    pub(super) fn filter_declination_source(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::DeclinationSource as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::DeclinationSource(v)))
    }

    #[inline(never)]
    pub(super) fn filter_declination_source_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::DeclinationSourceResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::DeclinationSourceResponse(v)))
    }

    #[inline(never)]
    pub(super) fn filter_gravity_magnitude_adaptive_measurement(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::GravityMagnitudeAdaptiveMeasurement as crate::wire::Layout>::decode_data(
            data,
        )
        .map(|v| {
            FieldValue::Filter(crate::filter::SetField::GravityMagnitudeAdaptiveMeasurement(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_gravity_magnitude_adaptive_measurement_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::GravityMagnitudeAdaptiveMeasurementResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::GravityMagnitudeAdaptiveMeasurementResponse(v)))
    }

    #[inline(never)]
    pub(super) fn filter_mag_magnitude_adaptive_measurement(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::MagMagnitudeAdaptiveMeasurement as crate::wire::Layout>::decode_data(data)
            .map(|v| {
                FieldValue::Filter(crate::filter::SetField::MagMagnitudeAdaptiveMeasurement(v))
            })
    }

    #[inline(never)]
    pub(super) fn filter_mag_magnitude_adaptive_measurement_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::MagMagnitudeAdaptiveMeasurementResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::MagMagnitudeAdaptiveMeasurementResponse(v)))
    }

    #[inline(never)]
    pub(super) fn filter_mag_dip_angle_adaptive_measurement(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::MagDipAngleAdaptiveMeasurement as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::MagDipAngleAdaptiveMeasurement(v)))
    }

    #[inline(never)]
    pub(super) fn filter_mag_dip_angle_adaptive_measurement_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::MagDipAngleAdaptiveMeasurementResponse as crate::wire::Layout>::decode_data(
            data,
        )
        .map(|v| {
            FieldValue::Filter(crate::filter::SetField::MagDipAngleAdaptiveMeasurementResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_altitude_aiding_control(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::AltitudeAidingControl as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::AltitudeAidingControl(v)))
    }

    #[inline(never)]
    pub(super) fn filter_altitude_aiding_control_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::AltitudeAidingControlResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::AltitudeAidingControlResponse(v)))
    }

    #[inline(never)]
    pub(super) fn filter_pitch_roll_aiding_control(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::PitchRollAidingControl as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::PitchRollAidingControl(v)))
    }

    #[inline(never)]
    pub(super) fn filter_pitch_roll_aiding_control_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::PitchRollAidingControlResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::PitchRollAidingControlResponse(v)))
    }

    #[inline(never)]
    pub(super) fn filter_inclination_source(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::InclinationSource as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::InclinationSource(v)))
    }

    #[inline(never)]
    pub(super) fn filter_inclination_source_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::InclinationSourceResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::InclinationSourceResponse(v)))
    }

    #[inline(never)]
    pub(super) fn filter_magnetic_field_magnitude_source(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::MagneticFieldMagnitudeSource as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::MagneticFieldMagnitudeSource(v)))
    }

    #[inline(never)]
    pub(super) fn filter_magnetic_field_magnitude_source_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::MagneticFieldMagnitudeSourceResponse as crate::wire::Layout>::decode_data(
            data,
        )
        .map(|v| {
            FieldValue::Filter(crate::filter::SetField::MagneticFieldMagnitudeSourceResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_aiding_measurement_control(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::AidingMeasurementControl as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::AidingMeasurementControl(v)))
    }

    #[inline(never)]
    pub(super) fn filter_aiding_measurement_control_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::AidingMeasurementControlResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| {
                FieldValue::Filter(crate::filter::SetField::AidingMeasurementControlResponse(v))
            })
    }

    #[inline(never)]
    pub(super) fn filter_initialization_configuration(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::InitializationConfiguration as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::InitializationConfiguration(v)))
    }

    #[inline(never)]
    pub(super) fn filter_initialization_configuration_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::InitializationConfigurationResponse as crate::wire::Layout>::decode_data(
            data,
        )
        .map(|v| {
            FieldValue::Filter(crate::filter::SetField::InitializationConfigurationResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_adaptive_filter_control(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::AdaptiveFilterControl as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::AdaptiveFilterControl(v)))
    }

    #[inline(never)]
    pub(super) fn filter_adaptive_filter_control_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::AdaptiveFilterControlResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::AdaptiveFilterControlResponse(v)))
    }

    #[inline(never)]
    pub(super) fn filter_multi_antenna_offset(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::MultiAntennaOffset as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::MultiAntennaOffset(v)))
    }

    #[inline(never)]
    pub(super) fn filter_multi_antenna_offset_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::MultiAntennaOffsetResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::MultiAntennaOffsetResponse(v)))
    }

    #[inline(never)]
    pub(super) fn filter_relative_position_configuration(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::RelativePositionConfiguration as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::RelativePositionConfiguration(v)))
    }

    #[inline(never)]
    pub(super) fn filter_relative_position_configuration_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::RelativePositionConfigurationResponse as crate::wire::Layout>::decode_data(
            data,
        )
        .map(|v| {
            FieldValue::Filter(crate::filter::SetField::RelativePositionConfigurationResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn filter_reference_point_lever_arm(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::ReferencePointLeverArm as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::ReferencePointLeverArm(v)))
    }

    #[inline(never)]
    pub(super) fn filter_reference_point_lever_arm_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::ReferencePointLeverArmResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::ReferencePointLeverArmResponse(v)))
    }

    #[inline(never)]
    pub(super) fn filter_speed_lever_arm(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::SpeedLeverArm as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::SpeedLeverArm(v)))
    }

    #[inline(never)]
    pub(super) fn filter_speed_lever_arm_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::SpeedLeverArmResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::SpeedLeverArmResponse(v)))
    }

    #[inline(never)]
    pub(super) fn filter_wheeled_vehicle_constraint_control(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::WheeledVehicleConstraintControl as crate::wire::Layout>::decode_data(data)
            .map(|v| {
                FieldValue::Filter(crate::filter::SetField::WheeledVehicleConstraintControl(v))
            })
    }

    #[inline(never)]
    pub(super) fn filter_wheeled_vehicle_constraint_control_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::WheeledVehicleConstraintControlResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::WheeledVehicleConstraintControlResponse(v)))
    }

    #[inline(never)]
    pub(super) fn filter_gnss_antenna_calibration_control(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::GnssAntennaCalibrationControl as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Filter(crate::filter::SetField::GnssAntennaCalibrationControl(v)))
    }

    #[inline(never)]
    pub(super) fn filter_gnss_antenna_calibration_control_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter::GnssAntennaCalibrationControlResponse as crate::wire::Layout>::decode_data(
            data,
        )
        .map(|v| {
            FieldValue::Filter(crate::filter::SetField::GnssAntennaCalibrationControlResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_info(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss::ReceiverInfo as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Gnss(crate::gnss::SetField::ReceiverInfo(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_info_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss::ReceiverInfoResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Gnss(crate::gnss::SetField::ReceiverInfoResponse(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_signal_configuration(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss::SignalConfiguration as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Gnss(crate::gnss::SetField::SignalConfiguration(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_signal_configuration_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss::SignalConfigurationResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Gnss(crate::gnss::SetField::SignalConfigurationResponse(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_spartn_configuration(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss::SpartnConfiguration as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Gnss(crate::gnss::SetField::SpartnConfiguration(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_spartn_configuration_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss::SpartnConfigurationResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Gnss(crate::gnss::SetField::SpartnConfigurationResponse(v)))
    }

    #[inline(never)]
    pub(super) fn aiding_frame_config(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::aiding::FrameConfig as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Aiding(crate::aiding::SetField::FrameConfig(v)))
    }

    #[inline(never)]
    pub(super) fn aiding_frame_config_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::aiding::FrameConfigResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Aiding(crate::aiding::SetField::FrameConfigResponse(v)))
    }

    #[inline(never)]
    pub(super) fn aiding_echo_control(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::aiding::EchoControl as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Aiding(crate::aiding::SetField::EchoControl(v)))
    }

    #[inline(never)]
    pub(super) fn aiding_echo_control_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::aiding::EchoControlResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Aiding(crate::aiding::SetField::EchoControlResponse(v)))
    }

    #[inline(never)]
    pub(super) fn aiding_ecef_position(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::aiding::EcefPosition as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Aiding(crate::aiding::SetField::EcefPosition(v)))
    }

    #[inline(never)]
    pub(super) fn aiding_llh_position(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::aiding::LlhPosition as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Aiding(crate::aiding::SetField::LlhPosition(v)))
    }

    #[inline(never)]
    pub(super) fn aiding_height_above_ellipsoid(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::aiding::HeightAboveEllipsoid as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Aiding(crate::aiding::SetField::HeightAboveEllipsoid(v)))
    }

    #[inline(never)]
    pub(super) fn aiding_ecef_velocity(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::aiding::EcefVelocity as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Aiding(crate::aiding::SetField::EcefVelocity(v)))
    }

    #[inline(never)]
    pub(super) fn aiding_ned_velocity(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::aiding::NedVelocity as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Aiding(crate::aiding::SetField::NedVelocity(v)))
    }

    #[inline(never)]
    pub(super) fn aiding_body_frame_velocity(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::aiding::BodyFrameVelocity as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Aiding(crate::aiding::SetField::BodyFrameVelocity(v)))
    }

    #[inline(never)]
    pub(super) fn aiding_true_heading(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::aiding::TrueHeading as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Aiding(crate::aiding::SetField::TrueHeading(v)))
    }

    #[inline(never)]
    pub(super) fn aiding_magnetic_field(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::aiding::MagneticField as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Aiding(crate::aiding::SetField::MagneticField(v)))
    }

    #[inline(never)]
    pub(super) fn aiding_pressure(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::aiding::Pressure as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Aiding(crate::aiding::SetField::Pressure(v)))
    }

    #[inline(never)]
    pub(super) fn system_communication_mode(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::system::CommunicationMode as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::System(crate::system::SetField::CommunicationMode(v)))
    }

    #[inline(never)]
    pub(super) fn system_communication_mode_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::system::CommunicationModeResponse as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::System(crate::system::SetField::CommunicationModeResponse(v)))
    }

    #[inline(never)]
    pub(super) fn sensor_scaled_accel(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::sensor::ScaledAccel as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Sensor(crate::sensor::SetField::ScaledAccel(v)))
    }

    #[inline(never)]
    pub(super) fn sensor_scaled_gyro(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::sensor::ScaledGyro as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Sensor(crate::sensor::SetField::ScaledGyro(v)))
    }

    #[inline(never)]
    pub(super) fn sensor_scaled_mag(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::sensor::ScaledMag as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Sensor(crate::sensor::SetField::ScaledMag(v)))
    }

    #[inline(never)]
    pub(super) fn sensor_delta_theta(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::sensor::DeltaTheta as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Sensor(crate::sensor::SetField::DeltaTheta(v)))
    }

    #[inline(never)]
    pub(super) fn sensor_delta_velocity(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::sensor::DeltaVelocity as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Sensor(crate::sensor::SetField::DeltaVelocity(v)))
    }

    #[inline(never)]
    pub(super) fn sensor_cf_orientation_matrix(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::sensor::CfOrientationMatrix as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Sensor(crate::sensor::SetField::CfOrientationMatrix(v)))
    }

    #[inline(never)]
    pub(super) fn sensor_cf_quaternion(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::sensor::CfQuaternion as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Sensor(crate::sensor::SetField::CfQuaternion(v)))
    }

    #[inline(never)]
    pub(super) fn sensor_cf_euler_angles(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::sensor::CfEulerAngles as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Sensor(crate::sensor::SetField::CfEulerAngles(v)))
    }

    #[inline(never)]
    pub(super) fn sensor_cf_stabilized_north(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::sensor::CfStabilizedNorth as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Sensor(crate::sensor::SetField::CfStabilizedNorth(v)))
    }

    #[inline(never)]
    pub(super) fn sensor_cf_stabilized_up(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::sensor::CfStabilizedUp as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Sensor(crate::sensor::SetField::CfStabilizedUp(v)))
    }

    #[inline(never)]
    pub(super) fn sensor_gps_timestamp(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::sensor::GpsTimestamp as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Sensor(crate::sensor::SetField::GpsTimestamp(v)))
    }

    #[inline(never)]
    pub(super) fn sensor_temperature_statistics(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::sensor::TemperatureStatistics as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Sensor(crate::sensor::SetField::TemperatureStatistics(v)))
    }

    #[inline(never)]
    pub(super) fn sensor_scaled_pressure(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::sensor::ScaledPressure as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Sensor(crate::sensor::SetField::ScaledPressure(v)))
    }

    #[inline(never)]
    pub(super) fn sensor_overrange_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::sensor::OverrangeStatus as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Sensor(crate::sensor::SetField::OverrangeStatus(v)))
    }

    #[inline(never)]
    pub(super) fn sensor_odometer_data(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::sensor::OdometerData as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Sensor(crate::sensor::SetField::OdometerData(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_data_llh_position(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_data::LlhPosition as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssData(crate::gnss_data::SetField::LlhPosition(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_data_ecef_position(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_data::EcefPosition as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssData(crate::gnss_data::SetField::EcefPosition(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_data_ned_velocity(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_data::NedVelocity as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssData(crate::gnss_data::SetField::NedVelocity(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_data_ecef_velocity(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_data::EcefVelocity as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssData(crate::gnss_data::SetField::EcefVelocity(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_data_dop(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_data::Dop as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssData(crate::gnss_data::SetField::Dop(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_data_utc_time(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_data::UtcTime as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssData(crate::gnss_data::SetField::UtcTime(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_data_gps_time(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_data::GpsTime as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssData(crate::gnss_data::SetField::GpsTime(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_data_clock_info(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_data::ClockInfo as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssData(crate::gnss_data::SetField::ClockInfo(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_data_fix_info(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_data::FixInfo as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssData(crate::gnss_data::SetField::FixInfo(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_data_sv_info(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_data::SvInfo as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssData(crate::gnss_data::SetField::SvInfo(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_data_hardware_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_data::HardwareStatus as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssData(crate::gnss_data::SetField::HardwareStatus(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_data_dgnss_info(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_data::DgnssInfo as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssData(crate::gnss_data::SetField::DgnssInfo(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_data_dgnss_channel_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_data::DgnssChannelStatus as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssData(crate::gnss_data::SetField::DgnssChannelStatus(v)))
    }

    #[inline(never)]
    pub(super) fn filter_data_llh_position(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::LlhPosition as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::FilterData(crate::filter_data::SetField::LlhPosition(v)))
    }

    #[inline(never)]
    pub(super) fn filter_data_ned_velocity(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::NedVelocity as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::FilterData(crate::filter_data::SetField::NedVelocity(v)))
    }

    #[inline(never)]
    pub(super) fn filter_data_attitude_quaternion(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::AttitudeQuaternion as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::FilterData(crate::filter_data::SetField::AttitudeQuaternion(v)))
    }

    #[inline(never)]
    pub(super) fn filter_data_attitude_dcm(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::AttitudeDcm as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::FilterData(crate::filter_data::SetField::AttitudeDcm(v)))
    }

    #[inline(never)]
    pub(super) fn filter_data_euler_angles(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::EulerAngles as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::FilterData(crate::filter_data::SetField::EulerAngles(v)))
    }

    #[inline(never)]
    pub(super) fn filter_data_gyro_bias(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::GyroBias as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::FilterData(crate::filter_data::SetField::GyroBias(v)))
    }

    #[inline(never)]
    pub(super) fn filter_data_accel_bias(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::AccelBias as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::FilterData(crate::filter_data::SetField::AccelBias(v)))
    }

    #[inline(never)]
    pub(super) fn filter_data_llh_position_uncertainty(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::LlhPositionUncertainty as crate::wire::Layout>::decode_data(data).map(
            |v| FieldValue::FilterData(crate::filter_data::SetField::LlhPositionUncertainty(v)),
        )
    }

    #[inline(never)]
    pub(super) fn filter_data_ned_velocity_uncertainty(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::NedVelocityUncertainty as crate::wire::Layout>::decode_data(data).map(
            |v| FieldValue::FilterData(crate::filter_data::SetField::NedVelocityUncertainty(v)),
        )
    }

    #[inline(never)]
    pub(super) fn filter_data_euler_angles_uncertainty(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::EulerAnglesUncertainty as crate::wire::Layout>::decode_data(data).map(
            |v| FieldValue::FilterData(crate::filter_data::SetField::EulerAnglesUncertainty(v)),
        )
    }

    #[inline(never)]
    pub(super) fn filter_data_gyro_bias_uncertainty(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::GyroBiasUncertainty as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::FilterData(crate::filter_data::SetField::GyroBiasUncertainty(v)))
    }

    #[inline(never)]
    pub(super) fn filter_data_accel_bias_uncertainty(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::AccelBiasUncertainty as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::FilterData(crate::filter_data::SetField::AccelBiasUncertainty(v)))
    }

    #[inline(never)]
    pub(super) fn filter_data_linear_accel(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::LinearAccel as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::FilterData(crate::filter_data::SetField::LinearAccel(v)))
    }

    #[inline(never)]
    pub(super) fn filter_data_comp_angular_rate(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::CompAngularRate as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::FilterData(crate::filter_data::SetField::CompAngularRate(v)))
    }

    #[inline(never)]
    pub(super) fn filter_data_wgs84_gravity_magnitude(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::Wgs84GravityMagnitude as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::FilterData(crate::filter_data::SetField::Wgs84GravityMagnitude(v)))
    }

    #[inline(never)]
    pub(super) fn filter_data_filter_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        crate::filter_data::FilterStatus::decode_data(data, device)
            .map(|v| FieldValue::FilterData(crate::filter_data::SetField::FilterStatus(v)))
    }

    #[inline(never)]
    pub(super) fn filter_data_gps_timestamp(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::GpsTimestamp as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::FilterData(crate::filter_data::SetField::GpsTimestamp(v)))
    }

    #[inline(never)]
    pub(super) fn filter_data_quaternion_attitude_uncertainty(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::QuaternionAttitudeUncertainty as crate::wire::Layout>::decode_data(
            data,
        )
        .map(|v| {
            FieldValue::FilterData(crate::filter_data::SetField::QuaternionAttitudeUncertainty(
                v,
            ))
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_gravity_vector(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::GravityVector as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::FilterData(crate::filter_data::SetField::GravityVector(v)))
    }

    #[inline(never)]
    pub(super) fn filter_data_heading_update_state(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::HeadingUpdateState as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::FilterData(crate::filter_data::SetField::HeadingUpdateState(v)))
    }

    #[inline(never)]
    pub(super) fn filter_data_magnetic_model(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::MagneticModel as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::FilterData(crate::filter_data::SetField::MagneticModel(v)))
    }

    #[inline(never)]
    pub(super) fn filter_data_gyro_scale_factor(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::GyroScaleFactor as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::FilterData(crate::filter_data::SetField::GyroScaleFactor(v)))
    }

    #[inline(never)]
    pub(super) fn filter_data_accel_scale_factor(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::AccelScaleFactor as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::FilterData(crate::filter_data::SetField::AccelScaleFactor(v)))
    }

    #[inline(never)]
    pub(super) fn filter_data_gyro_scale_factor_uncertainty(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::GyroScaleFactorUncertainty as crate::wire::Layout>::decode_data(data)
            .map(|v| {
                FieldValue::FilterData(crate::filter_data::SetField::GyroScaleFactorUncertainty(v))
            })
    }

    #[inline(never)]
    pub(super) fn filter_data_accel_scale_factor_uncertainty(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::AccelScaleFactorUncertainty as crate::wire::Layout>::decode_data(data)
            .map(|v| {
                FieldValue::FilterData(crate::filter_data::SetField::AccelScaleFactorUncertainty(v))
            })
    }

    #[inline(never)]
    pub(super) fn filter_data_compensated_accel(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::CompensatedAccel as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::FilterData(crate::filter_data::SetField::CompensatedAccel(v)))
    }

    #[inline(never)]
    pub(super) fn filter_data_standard_atmosphere(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::StandardAtmosphere as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::FilterData(crate::filter_data::SetField::StandardAtmosphere(v)))
    }

    #[inline(never)]
    pub(super) fn filter_data_pressure_altitude(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::PressureAltitude as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::FilterData(crate::filter_data::SetField::PressureAltitude(v)))
    }

    #[inline(never)]
    pub(super) fn filter_data_mag_auto_hard_iron_offset(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::MagAutoHardIronOffset as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::FilterData(crate::filter_data::SetField::MagAutoHardIronOffset(v)))
    }

    #[inline(never)]
    pub(super) fn filter_data_mag_auto_soft_iron_matrix(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::MagAutoSoftIronMatrix as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::FilterData(crate::filter_data::SetField::MagAutoSoftIronMatrix(v)))
    }

    #[inline(never)]
    pub(super) fn filter_data_mag_auto_hard_iron_offset_uncertainty(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::MagAutoHardIronOffsetUncertainty as crate::wire::Layout>::decode_data(
            data,
        )
        .map(|v| {
            FieldValue::FilterData(
                crate::filter_data::SetField::MagAutoHardIronOffsetUncertainty(v),
            )
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_mag_auto_soft_iron_matrix_uncertainty(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::MagAutoSoftIronMatrixUncertainty as crate::wire::Layout>::decode_data(
            data,
        )
        .map(|v| {
            FieldValue::FilterData(
                crate::filter_data::SetField::MagAutoSoftIronMatrixUncertainty(v),
            )
        })
    }

    #[inline(never)]
    pub(super) fn filter_data_gnss_antenna_offset_correction(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::GnssAntennaOffsetCorrection as crate::wire::Layout>::decode_data(data)
            .map(|v| {
                FieldValue::FilterData(crate::filter_data::SetField::GnssAntennaOffsetCorrection(v))
            })
    }

    #[inline(never)]
    pub(super) fn filter_data_gnss_antenna_offset_correction_uncertainty(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::GnssAntennaOffsetCorrectionUncertainty as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::FilterData(crate::filter_data::SetField::GnssAntennaOffsetCorrectionUncertainty(v)))
    }

    #[inline(never)]
    pub(super) fn filter_data_multi_antenna_offset_correction(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::MultiAntennaOffsetCorrection as crate::wire::Layout>::decode_data(data)
            .map(|v| {
                FieldValue::FilterData(crate::filter_data::SetField::MultiAntennaOffsetCorrection(
                    v,
                ))
            })
    }

    #[inline(never)]
    pub(super) fn filter_data_multi_antenna_offset_correction_uncertainty(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::MultiAntennaOffsetCorrectionUncertainty as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::FilterData(crate::filter_data::SetField::MultiAntennaOffsetCorrectionUncertainty(v)))
    }

    #[inline(never)]
    pub(super) fn filter_data_ecef_position_uncertainty(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::EcefPositionUncertainty as crate::wire::Layout>::decode_data(data).map(
            |v| FieldValue::FilterData(crate::filter_data::SetField::EcefPositionUncertainty(v)),
        )
    }

    #[inline(never)]
    pub(super) fn filter_data_ecef_velocity_uncertainty(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::EcefVelocityUncertainty as crate::wire::Layout>::decode_data(data).map(
            |v| FieldValue::FilterData(crate::filter_data::SetField::EcefVelocityUncertainty(v)),
        )
    }

    #[inline(never)]
    pub(super) fn filter_data_ecef_position(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::EcefPosition as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::FilterData(crate::filter_data::SetField::EcefPosition(v)))
    }

    #[inline(never)]
    pub(super) fn filter_data_ecef_velocity(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::EcefVelocity as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::FilterData(crate::filter_data::SetField::EcefVelocity(v)))
    }

    #[inline(never)]
    pub(super) fn filter_data_ned_relative_position(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::NedRelativePosition as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::FilterData(crate::filter_data::SetField::NedRelativePosition(v)))
    }

    #[inline(never)]
    pub(super) fn filter_data_gnss_position_aiding_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::GnssPositionAidingStatus as crate::wire::Layout>::decode_data(data)
            .map(|v| {
                FieldValue::FilterData(crate::filter_data::SetField::GnssPositionAidingStatus(v))
            })
    }

    #[inline(never)]
    pub(super) fn filter_data_aiding_measurement_summary(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::AidingMeasurementSummary as crate::wire::Layout>::decode_data(data)
            .map(|v| {
                FieldValue::FilterData(crate::filter_data::SetField::AidingMeasurementSummary(v))
            })
    }

    #[inline(never)]
    pub(super) fn filter_data_odometer_scale_factor_error(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::OdometerScaleFactorError as crate::wire::Layout>::decode_data(data)
            .map(|v| {
                FieldValue::FilterData(crate::filter_data::SetField::OdometerScaleFactorError(v))
            })
    }

    #[inline(never)]
    pub(super) fn filter_data_odometer_scale_factor_error_uncertainty(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::OdometerScaleFactorErrorUncertainty as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::FilterData(crate::filter_data::SetField::OdometerScaleFactorErrorUncertainty(v)))
    }

    #[inline(never)]
    pub(super) fn filter_data_gnss_dual_antenna_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::GnssDualAntennaStatus as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::FilterData(crate::filter_data::SetField::GnssDualAntennaStatus(v)))
    }

    #[inline(never)]
    pub(super) fn filter_data_aiding_frame_config_error(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::AidingFrameConfigError as crate::wire::Layout>::decode_data(data).map(
            |v| FieldValue::FilterData(crate::filter_data::SetField::AidingFrameConfigError(v)),
        )
    }

    #[inline(never)]
    pub(super) fn filter_data_aiding_frame_config_error_uncertainty(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::filter_data::AidingFrameConfigErrorUncertainty as crate::wire::Layout>::decode_data(
            data,
        )
        .map(|v| {
            FieldValue::FilterData(
                crate::filter_data::SetField::AidingFrameConfigErrorUncertainty(v),
            )
        })
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_llh_position(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_1::LlhPosition as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::LlhPosition(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_ecef_position(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_1::EcefPosition as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::EcefPosition(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_ned_velocity(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_1::NedVelocity as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::NedVelocity(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_ecef_velocity(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_1::EcefVelocity as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::EcefVelocity(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_dop(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_1::Dop as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::Dop(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_utc_time(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_1::UtcTime as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::UtcTime(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_gps_time(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_1::GpsTime as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::GpsTime(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_fix_info(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_1::FixInfo as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::FixInfo(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_hardware_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_1::HardwareStatus as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::HardwareStatus(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_clock_info_2(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_1::ClockInfo2 as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::ClockInfo2(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_gps_leap_seconds(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_1::GpsLeapSeconds as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::GpsLeapSeconds(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_sbas_info(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_1::SbasInfo as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::SbasInfo(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_satellite_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_1::SatelliteStatus as crate::wire::Layout>::decode_data(data).map(
            |v| FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::SatelliteStatus(v)),
        )
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_raw(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_1::Raw as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::Raw(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_gps_ephemeris(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_1::GpsEphemeris as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::GpsEphemeris(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_glonass_ephemeris(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_1::GlonassEphemeris as crate::wire::Layout>::decode_data(data).map(
            |v| FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::GlonassEphemeris(v)),
        )
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_galileo_ephemeris(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_1::GalileoEphemeris as crate::wire::Layout>::decode_data(data).map(
            |v| FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::GalileoEphemeris(v)),
        )
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_1_beidou_ephemeris(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_1::BeidouEphemeris as crate::wire::Layout>::decode_data(data).map(
            |v| FieldValue::GnssReceiver1(crate::gnss_receiver_1::SetField::BeidouEphemeris(v)),
        )
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_llh_position(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_2::LlhPosition as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::LlhPosition(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_ecef_position(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_2::EcefPosition as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::EcefPosition(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_ned_velocity(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_2::NedVelocity as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::NedVelocity(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_ecef_velocity(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_2::EcefVelocity as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::EcefVelocity(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_dop(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_2::Dop as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::Dop(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_utc_time(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_2::UtcTime as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::UtcTime(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_gps_time(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_2::GpsTime as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::GpsTime(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_fix_info(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_2::FixInfo as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::FixInfo(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_hardware_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_2::HardwareStatus as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::HardwareStatus(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_clock_info_2(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_2::ClockInfo2 as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::ClockInfo2(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_gps_leap_seconds(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_2::GpsLeapSeconds as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::GpsLeapSeconds(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_sbas_info(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_2::SbasInfo as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::SbasInfo(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_satellite_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_2::SatelliteStatus as crate::wire::Layout>::decode_data(data).map(
            |v| FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::SatelliteStatus(v)),
        )
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_raw(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_2::Raw as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::Raw(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_gps_ephemeris(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_2::GpsEphemeris as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::GpsEphemeris(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_glonass_ephemeris(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_2::GlonassEphemeris as crate::wire::Layout>::decode_data(data).map(
            |v| FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::GlonassEphemeris(v)),
        )
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_galileo_ephemeris(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_2::GalileoEphemeris as crate::wire::Layout>::decode_data(data).map(
            |v| FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::GalileoEphemeris(v)),
        )
    }

    #[inline(never)]
    pub(super) fn gnss_receiver_2_beidou_ephemeris(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_receiver_2::BeidouEphemeris as crate::wire::Layout>::decode_data(data).map(
            |v| FieldValue::GnssReceiver2(crate::gnss_receiver_2::SetField::BeidouEphemeris(v)),
        )
    }

    #[inline(never)]
    pub(super) fn gnss_corrections_base_station_info(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_corrections::BaseStationInfo as crate::wire::Layout>::decode_data(data).map(
            |v| FieldValue::GnssCorrections(crate::gnss_corrections::SetField::BaseStationInfo(v)),
        )
    }

    #[inline(never)]
    pub(super) fn gnss_corrections_rtk_corrections_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_corrections::RtkCorrectionsStatus as crate::wire::Layout>::decode_data(data)
            .map(|v| {
                FieldValue::GnssCorrections(
                    crate::gnss_corrections::SetField::RtkCorrectionsStatus(v),
                )
            })
    }

    #[inline(never)]
    pub(super) fn gnss_external_llh_position(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_external::LlhPosition as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssExternal(crate::gnss_external::SetField::LlhPosition(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_external_ned_velocity(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_external::NedVelocity as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssExternal(crate::gnss_external::SetField::NedVelocity(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_external_utc_time(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_external::UtcTime as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssExternal(crate::gnss_external::SetField::UtcTime(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_external_fix_info(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_external::FixInfo as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssExternal(crate::gnss_external::SetField::FixInfo(v)))
    }

    #[inline(never)]
    pub(super) fn gnss_external_satellite_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::gnss_external::SatelliteStatus as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::GnssExternal(crate::gnss_external::SetField::SatelliteStatus(v)))
    }

    #[inline(never)]
    pub(super) fn system_data_built_in_test(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::system_data::BuiltInTest as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::SystemData(crate::system_data::SetField::BuiltInTest(v)))
    }

    #[inline(never)]
    pub(super) fn system_data_time_sync_status(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::system_data::TimeSyncStatus as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::SystemData(crate::system_data::SetField::TimeSyncStatus(v)))
    }

    #[inline(never)]
    pub(super) fn system_data_gpio_state(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::system_data::GpioState as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::SystemData(crate::system_data::SetField::GpioState(v)))
    }

    #[inline(never)]
    pub(super) fn shared_event_source(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::shared::EventSource as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Shared(crate::shared::SetField::EventSource(v)))
    }

    #[inline(never)]
    pub(super) fn shared_gps_timestamp(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::shared::GpsTimestamp as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Shared(crate::shared::SetField::GpsTimestamp(v)))
    }

    #[inline(never)]
    pub(super) fn shared_delta_time(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::shared::DeltaTime as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Shared(crate::shared::SetField::DeltaTime(v)))
    }

    #[inline(never)]
    pub(super) fn shared_reference_timestamp(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::shared::ReferenceTimestamp as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Shared(crate::shared::SetField::ReferenceTimestamp(v)))
    }

    #[inline(never)]
    pub(super) fn shared_reference_time_delta(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::shared::ReferenceTimeDelta as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Shared(crate::shared::SetField::ReferenceTimeDelta(v)))
    }

    #[inline(never)]
    pub(super) fn shared_external_timestamp(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::shared::ExternalTimestamp as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Shared(crate::shared::SetField::ExternalTimestamp(v)))
    }

    #[inline(never)]
    pub(super) fn shared_external_time_delta(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        <crate::shared::ExternalTimeDelta as crate::wire::Layout>::decode_data(data)
            .map(|v| FieldValue::Shared(crate::shared::SetField::ExternalTimeDelta(v)))
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
