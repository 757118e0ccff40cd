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
    let found =
        match set {
            0x01 => crate::base::SetField::decode(descriptor, data, device)
                .map(|r| r.map(FieldValue::Base)),
            0x0C => crate::threedm::SetField::decode(descriptor, data, device)
                .map(|r| r.map(FieldValue::Threedm)),
            0x0D => crate::filter::SetField::decode(descriptor, data, device)
                .map(|r| r.map(FieldValue::Filter)),
            0x0E => crate::gnss::SetField::decode(descriptor, data, device)
                .map(|r| r.map(FieldValue::Gnss)),
            0x13 => crate::aiding::SetField::decode(descriptor, data, device)
                .map(|r| r.map(FieldValue::Aiding)),
            0x7F => crate::system::SetField::decode(descriptor, data, device)
                .map(|r| r.map(FieldValue::System)),
            0x80 => crate::sensor::SetField::decode(descriptor, data, device)
                .map(|r| r.map(FieldValue::Sensor)),
            0x81 => crate::gnss_data::SetField::decode(descriptor, data, device)
                .map(|r| r.map(FieldValue::GnssData)),
            0x82 => crate::filter_data::SetField::decode(descriptor, data, device)
                .map(|r| r.map(FieldValue::FilterData)),
            0x91 => crate::gnss_receiver_1::SetField::decode(descriptor, data, device)
                .map(|r| r.map(FieldValue::GnssReceiver1)),
            0x92 => crate::gnss_receiver_2::SetField::decode(descriptor, data, device)
                .map(|r| r.map(FieldValue::GnssReceiver2)),
            0x93 => crate::gnss_corrections::SetField::decode(descriptor, data, device)
                .map(|r| r.map(FieldValue::GnssCorrections)),
            0x94 => crate::gnss_external::SetField::decode(descriptor, data, device)
                .map(|r| r.map(FieldValue::GnssExternal)),
            0xA0 => crate::system_data::SetField::decode(descriptor, data, device)
                .map(|r| r.map(FieldValue::SystemData)),
            0xFF => crate::shared::SetField::decode(descriptor, data, device)
                .map(|r| r.map(FieldValue::Shared)),
            _ => None,
        };
    if let Some(result) = found {
        return result;
    }
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
