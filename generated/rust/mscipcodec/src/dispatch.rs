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

    /// File name of the manual that documents the device.
    pub fn manual(self) -> &'static str {
        match self {
            Device::MsImu3020 => "ms-cip-doc00419-revM.txt",
        }
    }

    /// Every command the device's manual documents: `(set << 8) | descriptor`, ascending (the
    /// IR's `capabilities`).
    pub fn commands(self) -> &'static [u16] {
        match self {
            Device::MsImu3020 => &[
                0x0102, 0x0103, 0x0104, 0x0105, 0x0106, 0x0107, 0x0108, 0x0109, 0x0201, 0x0203,
                0x0204, 0x0205, 0x0206, 0x0207, 0x0208, 0x0209, 0x020A, 0x020B, 0x020C, 0x020D,
            ],
        }
    }

    /// Every data quantity the device's manual documents: `(set << 8) | descriptor`, ascending.
    pub fn data(self) -> &'static [u16] {
        match self {
            Device::MsImu3020 => &[
                0xA281, 0xA282, 0xA283, 0xA284, 0xA285, 0xA286, 0xA287, 0xA288, 0xA289,
            ],
        }
    }

    /// The baud rates of the device's main port as its manual lists them, ascending (the IR's
    /// `link`; empty: none listed).
    pub fn baud_rates(self) -> &'static [u32] {
        match self {
            Device::MsImu3020 => &[9600, 19200, 115200, 230400, 460800, 921600],
        }
    }

    /// The names the device answers to in the wrong-model check: its title and its identity
    /// model name (the spec's `simulation.identity`), upper case without spaces and punctuation.
    pub fn model_names(self) -> &'static [&'static str] {
        match self {
            Device::MsImu3020 => &["MSIMU3020"],
        }
    }

    /// The default baud rate of the device's main port (`None`: its manual states none).
    pub fn default_baud(self) -> Option<u32> {
        match self {
            Device::MsImu3020 => None,
        }
    }

    /// True when the device's manual documents the command or data quantity (set, descriptor);
    /// the sessions refuse a command for which this is false, before sending it.
    pub fn supports(self, set: u8, descriptor: u8) -> bool {
        let key = (u16::from(set) << 8) | u16::from(descriptor);
        self.commands().binary_search(&key).is_ok() || self.data().binary_search(&key).is_ok()
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
#[repr(u8)]
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
            #[cfg(any(feature = "set-base", not(feature = "select-sets")))]
            0x01 => crate::base::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::Base)),
            #[cfg(any(feature = "set-imu-config", not(feature = "select-sets")))]
            0x02 => crate::imu_config::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::ImuConfig)),
            #[cfg(any(feature = "set-imu-data", not(feature = "select-sets")))]
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
///
/// With the cargo features `set-*` (Cargo.toml), only the selected sets' fields decode (the
/// others as an unknown set's: reserved fields only), and only their decoders are linked.
#[inline]
pub fn decode_field(
    set: u8,
    descriptor: u8,
    data: &[u8],
    device: Option<Device>,
) -> Result<FieldValue, DecodeError> {
    // The set's own fields and the shared data fields it does not define (the search order as
    // the generator resolves it): two table loads, straight to the field's decoder, which builds
    // the FieldValue in the caller's slot. Reserved fields and unknown descriptors go on.
    if let Some(decoders) = SET_DECODERS[usize::from(set)] {
        if let Some(decode) = decoders[usize::from(descriptor)] {
            return decode(data, device);
        }
    }
    decode_other_field(set, descriptor, data, device)
}

/// The decoder of one field (in `decoders`).
type Decoder = fn(&[u8], Option<Device>) -> Result<FieldValue, DecodeError>;

/// Decoders of a set's fields (its own and shared ones), by descriptor (`None`: look further).
type DescriptorDecoders = [Option<Decoder>; 256];

/// The decoder tables of every set that has any, by set (`None`: look further).
static SET_DECODERS: [Option<&DescriptorDecoders>; 256] = {
    // Only the sets of the dispatch (the cargo features `set-*`).
    #[allow(unused_mut)]
    let mut t: [Option<&DescriptorDecoders>; 256] = [None; 256];
    #[cfg(any(feature = "set-base", not(feature = "select-sets")))]
    {
        t[0x01] = Some(&BASE_DECODERS);
    }
    #[cfg(any(feature = "set-imu-config", not(feature = "select-sets")))]
    {
        t[0x02] = Some(&IMU_CONFIG_DECODERS);
    }
    #[cfg(any(feature = "set-imu-data", not(feature = "select-sets")))]
    {
        t[0xA2] = Some(&IMU_DATA_DECODERS);
    }
    t
};

/// Decoders of the fields of set 0x01 (its own and the shared ones), by descriptor.
#[cfg(any(feature = "set-base", not(feature = "select-sets")))]
static BASE_DECODERS: DescriptorDecoders = {
    let mut t: DescriptorDecoders = [None; 256];
    t[0x02] = Some(decoders::base_ping);
    t[0x03] = Some(decoders::base_get_device_messages);
    t[0x04] = Some(decoders::base_device_reset);
    t[0x05] = Some(decoders::base_get_device_model);
    t[0x06] = Some(decoders::base_get_device_sn);
    t[0x07] = Some(decoders::base_get_device_fw);
    t[0x08] = Some(decoders::base_get_device_cal);
    t[0x09] = Some(decoders::base_correlate_gps_time);
    t[0x83] = Some(decoders::base_device_messages);
    t[0x85] = Some(decoders::base_device_model);
    t[0x86] = Some(decoders::base_device_sn);
    t[0x87] = Some(decoders::base_device_fw);
    t[0x88] = Some(decoders::base_device_cal);
    t
};

/// Decoders of the fields of set 0x02 (its own and the shared ones), by descriptor.
#[cfg(any(feature = "set-imu-config", not(feature = "select-sets")))]
static IMU_CONFIG_DECODERS: DescriptorDecoders = {
    let mut t: DescriptorDecoders = [None; 256];
    t[0x01] = Some(decoders::imu_config_uart_baud_rate);
    t[0x03] = Some(decoders::imu_config_filter);
    t[0x04] = Some(decoders::imu_config_sample_rate);
    t[0x05] = Some(decoders::imu_config_select_sensors);
    t[0x06] = Some(decoders::imu_config_get_internal_sample_rate);
    t[0x07] = Some(decoders::imu_config_accel_range);
    t[0x08] = Some(decoders::imu_config_gyro_range);
    t[0x09] = Some(decoders::imu_config_config_all);
    t[0x0A] = Some(decoders::imu_config_data_on_off);
    t[0x0B] = Some(decoders::imu_config_xtrig_on_off);
    t[0x0C] = Some(decoders::imu_config_select_sensors_rev_b);
    t[0x0D] = Some(decoders::imu_config_aux_accel_range);
    t[0x81] = Some(decoders::imu_config_uart_baud_rate_response);
    t[0x83] = Some(decoders::imu_config_filter_response);
    t[0x84] = Some(decoders::imu_config_sample_rate_response);
    t[0x85] = Some(decoders::imu_config_select_sensors_response);
    t[0x86] = Some(decoders::imu_config_internal_sample_rate);
    t[0x87] = Some(decoders::imu_config_accel_range_response);
    t[0x88] = Some(decoders::imu_config_gyro_range_response);
    t[0x8A] = Some(decoders::imu_config_data_on_off_response);
    t[0x8B] = Some(decoders::imu_config_xtrig_on_off_response);
    t[0x8C] = Some(decoders::imu_config_select_sensors_rev_b_response);
    t[0x8D] = Some(decoders::imu_config_aux_accel_range_response);
    t
};

/// Decoders of the fields of set 0xA2 (its own and the shared ones), by descriptor.
#[cfg(any(feature = "set-imu-data", not(feature = "select-sets")))]
static IMU_DATA_DECODERS: DescriptorDecoders = {
    let mut t: DescriptorDecoders = [None; 256];
    t[0x81] = Some(decoders::imu_data_scaled_accel);
    t[0x82] = Some(decoders::imu_data_scaled_gyro);
    t[0x83] = Some(decoders::imu_data_scaled_mag);
    t[0x84] = Some(decoders::imu_data_delta_theta);
    t[0x85] = Some(decoders::imu_data_delta_velocity);
    t[0x86] = Some(decoders::imu_data_scaled_pressure);
    t[0x87] = Some(decoders::imu_data_scaled_temperature);
    t[0x88] = Some(decoders::imu_data_gps_correlated_time);
    t[0x89] = Some(decoders::imu_data_scaled_aux_accel);
    t
};

/// [`decode_field`] for a descriptor that is not one of the set's own fields. Out of line, so
/// that `decode_field` itself is only the table lookup.
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
    Err(DecodeError::new(if set_in_dispatch(set) {
        DecodeErrorKind::UnknownDescriptor
    } else {
        DecodeErrorKind::UnknownSet
    }))
}

/// Whether set `set` is in the dispatch: defined by the spec and selected by the cargo features
/// `set-*` (every defined set when none of them is on).
fn set_in_dispatch(set: u8) -> bool {
    match set {
        #[cfg(any(feature = "set-base", not(feature = "select-sets")))]
        0x01 => true,
        #[cfg(any(feature = "set-imu-config", not(feature = "select-sets")))]
        0x02 => true,
        #[cfg(any(feature = "set-imu-data", not(feature = "select-sets")))]
        0xA2 => true,
        _ => false,
    }
}

/// One decoder per field of every set, for [`decode_field`] (through the tables above). Not
/// inlined, so that each keeps its own stack frame, as large as its own layout only. With a
/// selection of sets (the cargo features `set-*`) the others' decoders are not used.
mod decoders {
    #![cfg_attr(feature = "select-sets", allow(dead_code))]

    use super::{DecodeError, Device, FieldValue};
    use crate::wire::{Layout, Reader};

    /// Decodes `data` as layout `L` and wraps it into a FieldValue. A fixed layout over exactly
    /// its size is read straight into the caller's slot; anything else (a wrong length, an
    /// invalid value) goes to the checked decode, out of line, so that the straight path needs
    /// no room for an error.
    #[inline(always)]
    fn decode_layout<L: Layout, W: FnOnce(L) -> FieldValue>(
        data: &[u8],
        wrap: W,
    ) -> Result<FieldValue, DecodeError> {
        match L::FIXED_SIZE {
            Some(size) => {
                if size == data.len() {
                    if let Ok(value) = L::decode(&mut Reader::new(data)) {
                        return Ok(wrap(value));
                    }
                }
                decode_layout_checked(data, wrap)
            }
            None => L::decode_data(data).map(wrap),
        }
    }

    /// The checked decode of [`decode_layout`] (the same value or error as
    /// [`Layout::decode_data`]).
    #[cold]
    #[inline(never)]
    fn decode_layout_checked<L: Layout, W: FnOnce(L) -> FieldValue>(
        data: &[u8],
        wrap: W,
    ) -> Result<FieldValue, DecodeError> {
        L::decode_data(data).map(wrap)
    }

    #[inline(never)]
    pub(super) fn base_ping(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::base::Ping| {
            FieldValue::Base(crate::base::SetField::Ping(v))
        })
    }

    #[inline(never)]
    pub(super) fn base_get_device_messages(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::base::GetDeviceMessages| {
            FieldValue::Base(crate::base::SetField::GetDeviceMessages(v))
        })
    }

    #[inline(never)]
    pub(super) fn base_device_messages(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::base::DeviceMessages| {
            FieldValue::Base(crate::base::SetField::DeviceMessages(v))
        })
    }

    #[inline(never)]
    pub(super) fn base_device_reset(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::base::DeviceReset| {
            FieldValue::Base(crate::base::SetField::DeviceReset(v))
        })
    }

    #[inline(never)]
    pub(super) fn base_get_device_model(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::base::GetDeviceModel| {
            FieldValue::Base(crate::base::SetField::GetDeviceModel(v))
        })
    }

    #[inline(never)]
    pub(super) fn base_device_model(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::base::DeviceModel| {
            FieldValue::Base(crate::base::SetField::DeviceModel(v))
        })
    }

    #[inline(never)]
    pub(super) fn base_get_device_sn(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::base::GetDeviceSn| {
            FieldValue::Base(crate::base::SetField::GetDeviceSn(v))
        })
    }

    #[inline(never)]
    pub(super) fn base_device_sn(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::base::DeviceSn| {
            FieldValue::Base(crate::base::SetField::DeviceSn(v))
        })
    }

    #[inline(never)]
    pub(super) fn base_get_device_fw(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::base::GetDeviceFw| {
            FieldValue::Base(crate::base::SetField::GetDeviceFw(v))
        })
    }

    #[inline(never)]
    pub(super) fn base_device_fw(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::base::DeviceFw| {
            FieldValue::Base(crate::base::SetField::DeviceFw(v))
        })
    }

    #[inline(never)]
    pub(super) fn base_get_device_cal(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::base::GetDeviceCal| {
            FieldValue::Base(crate::base::SetField::GetDeviceCal(v))
        })
    }

    #[inline(never)]
    pub(super) fn base_device_cal(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::base::DeviceCal| {
            FieldValue::Base(crate::base::SetField::DeviceCal(v))
        })
    }

    #[inline(never)]
    pub(super) fn base_correlate_gps_time(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::base::CorrelateGpsTime| {
            FieldValue::Base(crate::base::SetField::CorrelateGpsTime(v))
        })
    }

    #[inline(never)]
    pub(super) fn imu_config_uart_baud_rate(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::imu_config::UartBaudRate| {
            FieldValue::ImuConfig(crate::imu_config::SetField::UartBaudRate(v))
        })
    }

    #[inline(never)]
    pub(super) fn imu_config_uart_baud_rate_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::imu_config::UartBaudRateResponse| {
            FieldValue::ImuConfig(crate::imu_config::SetField::UartBaudRateResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn imu_config_filter(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::imu_config::Filter| {
            FieldValue::ImuConfig(crate::imu_config::SetField::Filter(v))
        })
    }

    #[inline(never)]
    pub(super) fn imu_config_filter_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::imu_config::FilterResponse| {
            FieldValue::ImuConfig(crate::imu_config::SetField::FilterResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn imu_config_sample_rate(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::imu_config::SampleRate| {
            FieldValue::ImuConfig(crate::imu_config::SetField::SampleRate(v))
        })
    }

    #[inline(never)]
    pub(super) fn imu_config_sample_rate_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::imu_config::SampleRateResponse| {
            FieldValue::ImuConfig(crate::imu_config::SetField::SampleRateResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn imu_config_select_sensors(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::imu_config::SelectSensors| {
            FieldValue::ImuConfig(crate::imu_config::SetField::SelectSensors(v))
        })
    }

    #[inline(never)]
    pub(super) fn imu_config_select_sensors_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::imu_config::SelectSensorsResponse| {
            FieldValue::ImuConfig(crate::imu_config::SetField::SelectSensorsResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn imu_config_get_internal_sample_rate(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::imu_config::GetInternalSampleRate| {
            FieldValue::ImuConfig(crate::imu_config::SetField::GetInternalSampleRate(v))
        })
    }

    #[inline(never)]
    pub(super) fn imu_config_internal_sample_rate(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::imu_config::InternalSampleRate| {
            FieldValue::ImuConfig(crate::imu_config::SetField::InternalSampleRate(v))
        })
    }

    #[inline(never)]
    pub(super) fn imu_config_accel_range(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::imu_config::AccelRange| {
            FieldValue::ImuConfig(crate::imu_config::SetField::AccelRange(v))
        })
    }

    #[inline(never)]
    pub(super) fn imu_config_accel_range_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::imu_config::AccelRangeResponse| {
            FieldValue::ImuConfig(crate::imu_config::SetField::AccelRangeResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn imu_config_gyro_range(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::imu_config::GyroRange| {
            FieldValue::ImuConfig(crate::imu_config::SetField::GyroRange(v))
        })
    }

    #[inline(never)]
    pub(super) fn imu_config_gyro_range_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::imu_config::GyroRangeResponse| {
            FieldValue::ImuConfig(crate::imu_config::SetField::GyroRangeResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn imu_config_config_all(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::imu_config::ConfigAll| {
            FieldValue::ImuConfig(crate::imu_config::SetField::ConfigAll(v))
        })
    }

    #[inline(never)]
    pub(super) fn imu_config_data_on_off(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::imu_config::DataOnOff| {
            FieldValue::ImuConfig(crate::imu_config::SetField::DataOnOff(v))
        })
    }

    #[inline(never)]
    pub(super) fn imu_config_data_on_off_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::imu_config::DataOnOffResponse| {
            FieldValue::ImuConfig(crate::imu_config::SetField::DataOnOffResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn imu_config_xtrig_on_off(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::imu_config::XtrigOnOff| {
            FieldValue::ImuConfig(crate::imu_config::SetField::XtrigOnOff(v))
        })
    }

    #[inline(never)]
    pub(super) fn imu_config_xtrig_on_off_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::imu_config::XtrigOnOffResponse| {
            FieldValue::ImuConfig(crate::imu_config::SetField::XtrigOnOffResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn imu_config_select_sensors_rev_b(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::imu_config::SelectSensorsRevB| {
            FieldValue::ImuConfig(crate::imu_config::SetField::SelectSensorsRevB(v))
        })
    }

    #[inline(never)]
    pub(super) fn imu_config_select_sensors_rev_b_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::imu_config::SelectSensorsRevBResponse| {
            FieldValue::ImuConfig(crate::imu_config::SetField::SelectSensorsRevBResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn imu_config_aux_accel_range(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::imu_config::AuxAccelRange| {
            FieldValue::ImuConfig(crate::imu_config::SetField::AuxAccelRange(v))
        })
    }

    #[inline(never)]
    pub(super) fn imu_config_aux_accel_range_response(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::imu_config::AuxAccelRangeResponse| {
            FieldValue::ImuConfig(crate::imu_config::SetField::AuxAccelRangeResponse(v))
        })
    }

    #[inline(never)]
    pub(super) fn imu_data_scaled_accel(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::imu_data::ScaledAccel| {
            FieldValue::ImuData(crate::imu_data::SetField::ScaledAccel(v))
        })
    }

    #[inline(never)]
    pub(super) fn imu_data_scaled_gyro(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::imu_data::ScaledGyro| {
            FieldValue::ImuData(crate::imu_data::SetField::ScaledGyro(v))
        })
    }

    #[inline(never)]
    pub(super) fn imu_data_scaled_mag(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::imu_data::ScaledMag| {
            FieldValue::ImuData(crate::imu_data::SetField::ScaledMag(v))
        })
    }

    #[inline(never)]
    pub(super) fn imu_data_delta_theta(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::imu_data::DeltaTheta| {
            FieldValue::ImuData(crate::imu_data::SetField::DeltaTheta(v))
        })
    }

    #[inline(never)]
    pub(super) fn imu_data_delta_velocity(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::imu_data::DeltaVelocity| {
            FieldValue::ImuData(crate::imu_data::SetField::DeltaVelocity(v))
        })
    }

    #[inline(never)]
    pub(super) fn imu_data_scaled_pressure(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::imu_data::ScaledPressure| {
            FieldValue::ImuData(crate::imu_data::SetField::ScaledPressure(v))
        })
    }

    #[inline(never)]
    pub(super) fn imu_data_scaled_temperature(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::imu_data::ScaledTemperature| {
            FieldValue::ImuData(crate::imu_data::SetField::ScaledTemperature(v))
        })
    }

    #[inline(never)]
    pub(super) fn imu_data_gps_correlated_time(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::imu_data::GpsCorrelatedTime| {
            FieldValue::ImuData(crate::imu_data::SetField::GpsCorrelatedTime(v))
        })
    }

    #[inline(never)]
    pub(super) fn imu_data_scaled_aux_accel(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::imu_data::ScaledAuxAccel| {
            FieldValue::ImuData(crate::imu_data::SetField::ScaledAuxAccel(v))
        })
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

/// Writes the canonical JSON line of a foreign frame (no newline; `docs/conformance.md` §5): an
/// NMEA sentence without its CR LF, or an RTCM3 frame's message number and payload length.
pub fn write_foreign_json(w: &mut dyn Write, offset: u64, bytes: &[u8]) -> fmt::Result {
    w.write_char('{')?;
    if bytes[0] == 0xD3 {
        let kind = crate::parser::rtcm_type(bytes);
        write!(
            w,
            "\"offset\":{offset},\"rtcm\":{kind},\"length\":{}",
            bytes.len() - 6
        )?;
        return w.write_char('}');
    }
    write!(w, "\"offset\":{offset},\"nmea\":\"")?;
    for &b in &bytes[..bytes.len() - 2] {
        if b == b'"' || b == b'\\' {
            w.write_char('\\')?;
        }
        w.write_char(char::from(b))?;
    }
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
