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
    /// Device A (`dev_a`).
    DevA,
    /// Device B (`dev_b`).
    DevB,
}

impl Device {
    /// Every device, in spec order.
    pub const ALL: [Device; 2] = [Device::DevA, Device::DevB];

    /// Identifier in the spec (`--device ID`, `"device"` in JSON).
    pub fn id(self) -> &'static str {
        match self {
            Device::DevA => "dev_a",
            Device::DevB => "dev_b",
        }
    }

    /// Product name.
    pub fn title(self) -> &'static str {
        match self {
            Device::DevA => "Device A",
            Device::DevB => "Device B",
        }
    }

    /// File name of the manual that documents the device.
    pub fn manual(self) -> &'static str {
        match self {
            Device::DevA => "demo.txt",
            Device::DevB => "demo-b.txt",
        }
    }

    /// Every command the device's manual documents: `(set << 8) | descriptor`, ascending (the
    /// IR's `capabilities`).
    pub fn commands(self) -> &'static [u16] {
        match self {
            Device::DevA => &[0x0101, 0x0102, 0x0103],
            Device::DevB => &[0x0103],
        }
    }

    /// Every data quantity the device's manual documents: `(set << 8) | descriptor`, ascending.
    pub fn data(self) -> &'static [u16] {
        match self {
            Device::DevA => &[0x9001, 0x9103, 0x9203],
            Device::DevB => &[],
        }
    }

    /// The baud rates of the device's main port as its manual lists them, ascending (the IR's
    /// `link`; empty: none listed).
    pub fn baud_rates(self) -> &'static [u32] {
        match self {
            Device::DevA => &[],
            Device::DevB => &[],
        }
    }

    /// The names the device answers to in the wrong-model check: its title and its identity
    /// model name (the spec's `simulation.identity`), upper case without spaces and punctuation.
    pub fn model_names(self) -> &'static [&'static str] {
        match self {
            Device::DevA => &[],
            Device::DevB => &[],
        }
    }

    /// The default baud rate of the device's main port (`None`: its manual states none).
    pub fn default_baud(self) -> Option<u32> {
        match self {
            Device::DevA => None,
            Device::DevB => None,
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
            "dev_a" => Some(Device::DevA),
            "dev_b" => Some(Device::DevB),
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
    matches!(set, 0x01 | 0x90 | 0x91 | 0x92 | 0xFF)
}

/// A decoded field, by the group that defines it.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(u8)]
pub enum FieldValue {
    /// A field of set 0x01.
    CommandsSet(crate::commands_set::SetField),
    /// A field of set 0x90.
    Data(crate::data::SetField),
    /// A field of set 0x91.
    Receiver1(crate::receiver_1::SetField),
    /// A field of set 0x92.
    Receiver2(crate::receiver_2::SetField),
    /// A field of set 0xFF.
    Shared(crate::shared::SetField),
    /// A reserved field.
    Reserved(crate::reserved::ReservedField),
}

impl FieldValue {
    /// Field descriptor.
    pub fn descriptor(&self) -> u8 {
        match self {
            FieldValue::CommandsSet(v) => v.descriptor(),
            FieldValue::Data(v) => v.descriptor(),
            FieldValue::Receiver1(v) => v.descriptor(),
            FieldValue::Receiver2(v) => v.descriptor(),
            FieldValue::Shared(v) => v.descriptor(),
            FieldValue::Reserved(v) => v.descriptor(),
        }
    }

    /// Field name as printed in JSON.
    pub fn name(&self) -> &'static str {
        match self {
            FieldValue::CommandsSet(v) => v.name(),
            FieldValue::Data(v) => v.name(),
            FieldValue::Receiver1(v) => v.name(),
            FieldValue::Receiver2(v) => v.name(),
            FieldValue::Shared(v) => v.name(),
            FieldValue::Reserved(v) => v.name(),
        }
    }

    /// Device of the layout used, for fields with per-device layouts.
    pub fn device(&self) -> Option<Device> {
        match self {
            FieldValue::CommandsSet(v) => v.device(),
            FieldValue::Data(v) => v.device(),
            FieldValue::Receiver1(v) => v.device(),
            FieldValue::Receiver2(v) => v.device(),
            FieldValue::Shared(v) => v.device(),
            FieldValue::Reserved(v) => v.device(),
        }
    }

    /// Encodes the field data (without the field header).
    pub fn encode_data(&self, w: &mut Writer<'_>) -> Result<(), EncodeError> {
        match self {
            FieldValue::CommandsSet(v) => v.encode_data(w),
            FieldValue::Data(v) => v.encode_data(w),
            FieldValue::Receiver1(v) => v.encode_data(w),
            FieldValue::Receiver2(v) => v.encode_data(w),
            FieldValue::Shared(v) => v.encode_data(w),
            FieldValue::Reserved(v) => v.encode_data(w),
        }
    }

    /// Writes the canonical JSON of the values (`{...}`).
    pub fn write_values_json(&self, w: &mut dyn Write) -> fmt::Result {
        match self {
            FieldValue::CommandsSet(v) => v.write_values_json(w),
            FieldValue::Data(v) => v.write_values_json(w),
            FieldValue::Receiver1(v) => v.write_values_json(w),
            FieldValue::Receiver2(v) => v.write_values_json(w),
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
            #[cfg(any(feature = "set-commands-set", not(feature = "select-sets")))]
            0x01 => crate::commands_set::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::CommandsSet)),
            #[cfg(any(feature = "set-data", not(feature = "select-sets")))]
            0x90 => crate::data::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::Data)),
            #[cfg(any(feature = "set-receiver-1", not(feature = "select-sets")))]
            0x91 => crate::receiver_1::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::Receiver1)),
            #[cfg(any(feature = "set-receiver-2", not(feature = "select-sets")))]
            0x92 => crate::receiver_2::SetField::from_json(descriptor, device, values)
                .map(|r| r.map(FieldValue::Receiver2)),
            #[cfg(any(feature = "set-shared", not(feature = "select-sets")))]
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
        #[cfg(any(feature = "set-shared", not(feature = "select-sets")))]
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
    #[cfg(any(feature = "set-commands-set", not(feature = "select-sets")))]
    {
        t[0x01] = Some(&COMMANDS_SET_DECODERS);
    }
    #[cfg(any(feature = "set-data", not(feature = "select-sets")))]
    {
        t[0x90] = Some(&DATA_DECODERS);
    }
    #[cfg(any(feature = "set-receiver-1", not(feature = "select-sets")))]
    {
        t[0x91] = Some(&RECEIVER_1_DECODERS);
    }
    #[cfg(any(feature = "set-receiver-2", not(feature = "select-sets")))]
    {
        t[0x92] = Some(&RECEIVER_2_DECODERS);
    }
    #[cfg(any(feature = "set-shared", not(feature = "select-sets")))]
    {
        t[0xFF] = Some(&SHARED_DECODERS);
    }
    t
};

/// Decoders of the fields of set 0x01 (its own and the shared ones), by descriptor.
#[cfg(any(feature = "set-commands-set", not(feature = "select-sets")))]
static COMMANDS_SET_DECODERS: DescriptorDecoders = {
    let mut t: DescriptorDecoders = [None; 256];
    t[0x01] = Some(decoders::commands_set_ping);
    t[0x02] = Some(decoders::commands_set_configure);
    t[0x03] = Some(decoders::commands_set_per_device);
    t[0x82] = Some(decoders::commands_set_configuration);
    t
};

/// Decoders of the fields of set 0x90 (its own and the shared ones), by descriptor.
#[cfg(any(feature = "set-data", not(feature = "select-sets")))]
static DATA_DECODERS: DescriptorDecoders = {
    let mut t: DescriptorDecoders = [None; 256];
    t[0x01] = Some(decoders::data_sample);
    t[0xD3] = Some(decoders::shared_timestamp);
    t
};

/// Decoders of the fields of set 0x91 (its own and the shared ones), by descriptor.
#[cfg(any(feature = "set-receiver-1", not(feature = "select-sets")))]
static RECEIVER_1_DECODERS: DescriptorDecoders = {
    let mut t: DescriptorDecoders = [None; 256];
    t[0x03] = Some(decoders::receiver_1_llh_position);
    t[0xD3] = Some(decoders::shared_timestamp);
    t
};

/// Decoders of the fields of set 0x92 (its own and the shared ones), by descriptor.
#[cfg(any(feature = "set-receiver-2", not(feature = "select-sets")))]
static RECEIVER_2_DECODERS: DescriptorDecoders = {
    let mut t: DescriptorDecoders = [None; 256];
    t[0x03] = Some(decoders::receiver_2_llh_position);
    t[0xD3] = Some(decoders::shared_timestamp);
    t
};

/// Decoders of the fields of set 0xFF (its own and the shared ones), by descriptor.
#[cfg(any(feature = "set-shared", not(feature = "select-sets")))]
static SHARED_DECODERS: DescriptorDecoders = {
    let mut t: DescriptorDecoders = [None; 256];
    t[0xD3] = Some(decoders::shared_timestamp);
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
    #[cfg(any(feature = "set-shared", not(feature = "select-sets")))]
    if kind == Some(SetKind::Data) {
        if let Some(result) = crate::shared::SetField::decode(descriptor, data, device) {
            return result.map(FieldValue::Shared);
        }
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
        #[cfg(any(feature = "set-commands-set", not(feature = "select-sets")))]
        0x01 => true,
        #[cfg(any(feature = "set-data", not(feature = "select-sets")))]
        0x90 => true,
        #[cfg(any(feature = "set-receiver-1", not(feature = "select-sets")))]
        0x91 => true,
        #[cfg(any(feature = "set-receiver-2", not(feature = "select-sets")))]
        0x92 => true,
        #[cfg(any(feature = "set-shared", not(feature = "select-sets")))]
        0xFF => true,
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
    pub(super) fn commands_set_ping(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::commands_set::Ping| {
            FieldValue::CommandsSet(crate::commands_set::SetField::Ping(v))
        })
    }

    #[inline(never)]
    pub(super) fn commands_set_configure(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::commands_set::Configure| {
            FieldValue::CommandsSet(crate::commands_set::SetField::Configure(v))
        })
    }

    #[inline(never)]
    pub(super) fn commands_set_configuration(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::commands_set::Configuration| {
            FieldValue::CommandsSet(crate::commands_set::SetField::Configuration(v))
        })
    }

    #[inline(never)]
    pub(super) fn commands_set_per_device(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        crate::commands_set::PerDevice::decode_data(data, device)
            .map(|v| FieldValue::CommandsSet(crate::commands_set::SetField::PerDevice(v)))
    }

    #[inline(never)]
    pub(super) fn data_sample(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::data::Sample| {
            FieldValue::Data(crate::data::SetField::Sample(v))
        })
    }

    #[inline(never)]
    pub(super) fn receiver_1_llh_position(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::receiver_1::LlhPosition| {
            FieldValue::Receiver1(crate::receiver_1::SetField::LlhPosition(v))
        })
    }

    #[inline(never)]
    pub(super) fn receiver_2_llh_position(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::receiver_2::LlhPosition| {
            FieldValue::Receiver2(crate::receiver_2::SetField::LlhPosition(v))
        })
    }

    #[inline(never)]
    pub(super) fn shared_timestamp(
        data: &[u8],
        device: Option<Device>,
    ) -> Result<FieldValue, DecodeError> {
        let _ = device;
        decode_layout(data, |v: crate::shared::Timestamp| {
            FieldValue::Shared(crate::shared::SetField::Timestamp(v))
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
