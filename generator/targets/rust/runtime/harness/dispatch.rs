//! Stand-in for the generated `dispatch` module (templates/rust/dispatch.rs.j2), for the tiny
//! protocol of harness/framing.rs: one device, a command set 0x01 with `ping` (descriptor 0x01,
//! no parameters) and the reserved `ack` (descriptor 0xF1: `echo`, `code`, two u8), and data set
//! 0x80 with one field, `counter` (descriptor 0x01: `count`, a u16). Just the API that the
//! runtime's `text` module, the command-line tools and the tests use; the JSON of packets, skip
//! runs and raw fields is written as the generated module writes it.

use core::fmt::{self, Write};

use crate::error::{DecodeError, DecodeErrorKind, EncodeError};
use crate::fields::{FieldItem, Packet};
use crate::json;
use crate::wire::{Reader, Wire, Writer};

/// The data set of the one field.
pub const DATA_SET: u8 = 0x80;
/// Descriptor of `counter` in [`DATA_SET`].
pub const COUNTER: u8 = 0x01;
/// The command set.
pub const COMMAND_SET: u8 = 0x01;
/// Descriptor of `ping` in [`COMMAND_SET`].
pub const PING: u8 = 0x01;
/// Descriptor of the reserved `ack` field.
pub const ACK: u8 = 0xF1;

/// A device of the protocol.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Device {
    /// The one device (`tiny`).
    Tiny,
}

impl Device {
    /// Every device, in spec order.
    pub const ALL: [Device; 1] = [Device::Tiny];

    /// Identifier in the spec (`--device ID`, `"device"` in JSON).
    pub fn id(self) -> &'static str {
        match self {
            Device::Tiny => "tiny",
        }
    }

    /// Product name.
    pub fn title(self) -> &'static str {
        match self {
            Device::Tiny => "Tiny",
        }
    }

    /// File name of the manual that documents the device.
    pub fn manual(self) -> &'static str {
        match self {
            Device::Tiny => "tiny.txt",
        }
    }

    /// True when the device supports (set, descriptor): ping only.
    pub fn supports(self, set: u8, descriptor: u8) -> bool {
        set == COMMAND_SET && descriptor == PING
    }

    /// The device with identifier `id`.
    pub fn from_id(id: &str) -> Option<Self> {
        Device::ALL.into_iter().find(|d| d.id() == id)
    }
}

/// Whether the protocol defines descriptor set `set`.
pub fn set_defined(set: u8) -> bool {
    matches!(set, 0x01 | DATA_SET)
}

/// A decoded field.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FieldValue {
    /// `counter` of set 0x80.
    Counter(u16),
    /// `ping` of set 0x01 (a command).
    Ping,
    /// `ack` (reserved): the echoed command descriptor and the code.
    Ack(u8, u8),
}

impl FieldValue {
    /// Field descriptor.
    pub fn descriptor(&self) -> u8 {
        match self {
            FieldValue::Counter(_) => COUNTER,
            FieldValue::Ping => PING,
            FieldValue::Ack(..) => ACK,
        }
    }

    /// Field name as printed in JSON.
    pub fn name(&self) -> &'static str {
        match self {
            FieldValue::Counter(_) => "counter",
            FieldValue::Ping => "ping",
            FieldValue::Ack(..) => "ack",
        }
    }

    /// Encodes the field data (without the field header).
    pub fn encode_data(&self, w: &mut Writer<'_>) -> Result<(), EncodeError> {
        match self {
            FieldValue::Counter(count) => count.encode(w),
            FieldValue::Ping => Ok(()),
            FieldValue::Ack(echo, code) => {
                echo.encode(w)?;
                code.encode(w)
            }
        }
    }

    /// Writes the canonical JSON of the field: descriptor, name and values.
    pub fn write_json(&self, w: &mut dyn Write) -> fmt::Result {
        write!(w, "{{\"descriptor\":{},\"name\":", self.descriptor())?;
        json::write_str(w, self.name())?;
        match self {
            FieldValue::Counter(count) => {
                w.write_str(",\"values\":{\"count\":")?;
                count.write_json(w)?;
            }
            FieldValue::Ping => w.write_str(",\"values\":{")?,
            FieldValue::Ack(echo, code) => {
                write!(w, ",\"values\":{{\"echo\":{echo},\"code\":{code}")?;
            }
        }
        w.write_str("}}")
    }

    /// Reads a decoded field back from JSON (dispatch as in [`decode_field`]).
    #[cfg(feature = "std")]
    pub fn from_json(
        set: u8,
        descriptor: u8,
        device: Option<Device>,
        values: &crate::json_read::Json,
    ) -> Result<Self, crate::json_read::JsonError> {
        use crate::json_read::{FromJson, JsonError, Obj};
        let _ = device;
        if (set, descriptor) == (COMMAND_SET, PING) {
            Obj::new(values, &[])?;
            return Ok(FieldValue::Ping);
        }
        if (set, descriptor) == (COMMAND_SET, ACK) {
            let o = Obj::new(values, &["echo", "code"])?;
            return Ok(FieldValue::Ack(
                o.req("echo", u8::from_json)?,
                o.req("code", u8::from_json)?,
            ));
        }
        if (set, descriptor) != (DATA_SET, COUNTER) {
            return Err(JsonError::new(std::format!(
                "descriptor {descriptor} is not defined in set {set}; write the field raw, with \"data\""
            ))
            .at("descriptor"));
        }
        let o = Obj::new(values, &["count"])?;
        Ok(FieldValue::Counter(o.req("count", u16::from_json)?))
    }
}

/// Decodes the data of field `descriptor` in a packet of set `set`.
pub fn decode_field(
    set: u8,
    descriptor: u8,
    data: &[u8],
    device: Option<Device>,
) -> Result<FieldValue, DecodeError> {
    let _ = device;
    if (set, descriptor) == (DATA_SET, COUNTER) {
        let mut r = Reader::new(data);
        let count = u16::decode(&mut r).map_err(|e| e.at("count"))?;
        r.finish()?;
        return Ok(FieldValue::Counter(count));
    }
    if (set, descriptor) == (COMMAND_SET, PING) {
        Reader::new(data).finish()?;
        return Ok(FieldValue::Ping);
    }
    if (set, descriptor) == (COMMAND_SET, ACK) {
        let mut r = Reader::new(data);
        let echo = u8::decode(&mut r).map_err(|e| e.at("echo"))?;
        let code = u8::decode(&mut r).map_err(|e| e.at("code"))?;
        r.finish()?;
        return Ok(FieldValue::Ack(echo, code));
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
