//! Command sessions (`docs/conformance.md` §8): start commands, match their replies, route
//! every other packet. [`Session`] is the sans-I/O core: it never reads a clock or a
//! connection. The caller gives it the current time in milliseconds with every call, sends the
//! bytes [`Session::start`] returns and feeds it the bytes it receives:
//!
//! ```text
//! let started = session.start(&command, now_ms, StartOptions::default())?;
//! transport.write(started.packet);
//! session.feed(&received, now_ms, |event| match event {
//!     SessionEvent::Result(r) => ...,          // ack / nack / timeout / invalid
//!     SessionEvent::Packet { offset, packet } => ...,  // not a reply: data and the rest
//!     SessionEvent::Skip { offset, count } => ...,
//! });
//! ```
//!
//! `no_std`, no allocation: the pending commands wait in a fixed queue of `N` slots (a const
//! generic, [`MAX_PENDING`] by default), a result borrows its reply from the packet it came in
//! (valid for the callback).
//!
//! Bounded window: whatever the device sends, a session holds at most
//! [`crate::framing::MAX_PACKET`] bytes of undecided input (the parser's candidate packet) plus
//! the offset and length of the pending skip run, which is reported in pieces of
//! [`SKIP_PIECE`] bytes as soon as it reaches that length (a caller that prints skipped bytes
//! keeps fewer than `SKIP_PIECE + MAX_PACKET` of them, see [`Session::retain_from`]).
//! Replies are recognised by content, not by inter-byte timing (the look-ahead rule, see
//! [`Session::feed`]): a slow packet is never dropped. Everything protocol-specific is the generated [`crate::commands`]
//! module: the ack rule and one [`CommandFacts`] row per command layout.

use core::fmt::{self, Write};

use crate::builder::PacketBuilder;
use crate::clock::ClockModel;
use crate::commands;
use crate::dispatch::{decode_field, write_field_json, Device, FieldValue};
use crate::error::{DecodeError, EncodeError};
use crate::fields::{FieldItem, Fields, FramingError, Packet};
use crate::json;
use crate::parser::{Event, Parser};

/// The reply timeout of a command (plus the spec's allowance), in milliseconds.
pub const DEFAULT_TIMEOUT_MS: u64 = 1000;
/// The inter-packet timeout (milliseconds): a partial packet waiting longer than this lets the
/// look-ahead rule skip it when a complete packet is buffered after it.
pub const DEFAULT_INTER_PACKET_TIMEOUT_MS: u64 = 100;
/// A skip run is reported as soon as its pending length reaches this many bytes (a run of
/// exactly this length; the bytes skipped after it start a new run), so a noise flood is
/// reported as it arrives and no skip run of a session is longer.
pub const SKIP_PIECE: u64 = 65_536;
/// Commands waiting for their replies at once, by default.
pub const MAX_PENDING: usize = 8;
/// Most reply descriptors one command expects (the generator checks the spec against it).
pub const MAX_EXPECT: usize = 4;

// ------------------------------------------------------------------------------ command facts

/// A reply field the command layout's `responses` list, with its `when`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ReplyFacts {
    /// Descriptor of the reply field (in the command's set).
    pub descriptor: u8,
    /// Sent only for this function selector value.
    pub function: Option<u8>,
    /// Sent only when this parameter ...
    pub param: Option<&'static str>,
    /// ... has this value (`None`: any non-zero value).
    pub value: Option<i64>,
}

/// When a command asks the device not to reply (`ack_suppressed_by`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AckSuppression {
    /// The command is always answered.
    Never,
    /// With this function selector value.
    Function(u8),
    /// When the parameter has the value (`None`: any non-zero value).
    Param {
        /// Parameter name.
        param: &'static str,
        /// Value that suppresses the ack.
        value: Option<i64>,
    },
}

/// Extra reply time of a long command (`timeout`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Allowance {
    /// Milliseconds added to the reply timeout.
    pub ms: u64,
    /// A parameter whose value (milliseconds) is added too.
    pub param: Option<&'static str>,
    /// Only for these function selector values (`None`: always).
    pub functions: Option<&'static [u8]>,
}

/// What the spec says about one command layout (generated into [`crate::commands::COMMANDS`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CommandFacts {
    /// Descriptor set.
    pub set: u8,
    /// Field descriptor.
    pub descriptor: u8,
    /// Field name.
    pub name: &'static str,
    /// The device of a per-device layout, else `None`.
    pub device: Option<Device>,
    /// The devices that support this layout.
    pub devices: &'static [Device],
    /// The function selector values it accepts (`None`: no function selector).
    pub functions: Option<&'static [u8]>,
    /// The reply fields that come with the ack.
    pub replies: &'static [ReplyFacts],
    /// When the command suppresses its ack.
    pub ack: AckSuppression,
    /// Extra reply time.
    pub timeout: Option<Allowance>,
}

fn param_holds(command: &FieldValue, param: &str, value: Option<i64>) -> bool {
    match (commands::command_param(command, param), value) {
        (None, _) => false,
        (Some(v), None) => v != 0,
        (Some(v), Some(want)) => v == want,
    }
}

/// Why `device` does not support the command as given (`None` when it does).
pub fn support_error(command: &FieldValue, device: Device) -> Option<Refusal> {
    let facts = commands::command_facts(command)?;
    let name = facts.name;
    if !device.supports(facts.set, facts.descriptor) {
        return Some(Refusal::NotSupported { name, device });
    }
    if let Some(layout) = facts.device {
        if layout != device {
            return Some(Refusal::OtherLayout {
                name,
                layout,
                device,
            });
        }
    }
    if let (Some(functions), Some(function)) =
        (facts.functions, commands::command_function(command))
    {
        let limited = commands::FUNCTION_DEVICES
            .iter()
            .find(|(f, _)| *f == function)
            .map_or(false, |(_, devices)| !devices.contains(&device));
        if !functions.contains(&function) || limited {
            return Some(Refusal::Function {
                name,
                function,
                device,
            });
        }
    }
    None
}

/// True when the command as given asks the device not to reply.
pub fn ack_suppressed(command: &FieldValue, facts: &CommandFacts) -> bool {
    match facts.ack {
        AckSuppression::Never => false,
        AckSuppression::Function(f) => commands::command_function(command) == Some(f),
        AckSuppression::Param { param, value } => param_holds(command, param, value),
    }
}

/// The extra reply time the spec gives the command as given, in milliseconds.
pub fn allowance_ms(command: &FieldValue, facts: &CommandFacts) -> u64 {
    let Some(t) = facts.timeout else {
        return 0;
    };
    if let Some(functions) = t.functions {
        match commands::command_function(command) {
            Some(f) if functions.contains(&f) => {}
            _ => return 0,
        }
    }
    let extra = t
        .param
        .and_then(|p| commands::command_param(command, p))
        .map_or(0, |v| u64::try_from(v).unwrap_or(0));
    t.ms.saturating_add(extra)
}

/// The reply descriptors a command expects with its ack (at most [`MAX_EXPECT`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Expect {
    ids: [u8; MAX_EXPECT],
    len: u8,
}

impl Expect {
    /// The descriptors, in spec order.
    pub fn as_slice(&self) -> &[u8] {
        &self.ids[..usize::from(self.len)]
    }

    fn contains(&self, descriptor: u8) -> bool {
        self.as_slice().contains(&descriptor)
    }
}

/// The reply fields the command as given expects with its ack (spec `responses`).
pub fn expected_replies(command: &FieldValue, facts: &CommandFacts) -> Expect {
    let mut out = Expect::default();
    let function = commands::command_function(command);
    for r in facts.replies {
        if r.function.is_some() && r.function != function {
            continue;
        }
        if let Some(p) = r.param {
            if !param_holds(command, p, r.value) {
                continue;
            }
        }
        if usize::from(out.len) < MAX_EXPECT {
            out.ids[usize::from(out.len)] = r.descriptor;
            out.len += 1;
        }
    }
    out
}

// ------------------------------------------------------------------------------ results

/// The kind of a command's result.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Status {
    /// Acknowledged, with the expected reply fields.
    Ack,
    /// Not acknowledged: the device's error code.
    Nack,
    /// No reply before the deadline.
    Timeout,
    /// Acknowledged, but a reply field does not decode or the expected one is missing.
    Invalid,
    /// Sent; the command suppresses its ack.
    Sent,
    /// Not sent: the selected device does not support it, or the queue is full.
    Refused,
}

impl Status {
    /// The name printed by the session tool.
    pub fn as_str(self) -> &'static str {
        match self {
            Status::Ack => "ack",
            Status::Nack => "nack",
            Status::Timeout => "timeout",
            Status::Invalid => "invalid",
            Status::Sent => "sent",
            Status::Refused => "refused",
        }
    }
}

/// Why a command was refused before it was sent.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Refusal {
    /// No layout of the command lists the device.
    NotSupported {
        /// Command name.
        name: &'static str,
        /// The session's device.
        device: Device,
    },
    /// The layout given is another device's.
    OtherLayout {
        /// Command name.
        name: &'static str,
        /// The layout's device.
        layout: Device,
        /// The session's device.
        device: Device,
    },
    /// The function selector value is not accepted by the device.
    Function {
        /// Command name.
        name: &'static str,
        /// Function selector value.
        function: u8,
        /// The session's device.
        device: Device,
    },
    /// The queue of pending commands is full.
    QueueFull {
        /// Its size.
        pending: usize,
    },
}

impl fmt::Display for Refusal {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Refusal::NotSupported { name, device } => {
                write!(
                    f,
                    "{name} is not supported by {} ({})",
                    device.title(),
                    device.manual()
                )
            }
            Refusal::OtherLayout {
                name,
                layout,
                device,
            } => write!(
                f,
                "{name}: this layout is for {}, not {}",
                layout.id(),
                device.id()
            ),
            Refusal::Function {
                name,
                function,
                device,
            } => {
                f.write_str("function ")?;
                match commands::function_name(function) {
                    Some(n) => f.write_str(n)?,
                    None => write!(f, "{function}")?,
                }
                write!(
                    f,
                    " of {name} is not supported by {} ({})",
                    device.title(),
                    device.manual()
                )
            }
            Refusal::QueueFull { pending } => write!(f, "{pending} commands already pending"),
        }
    }
}

/// Why an acknowledged reply is invalid.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ReplyError {
    /// A reply field that does not decode.
    Decode(DecodeError),
    /// The payload's framing breaks inside the reply.
    Framing(FramingError),
    /// The first expected reply field is missing.
    Missing(u8),
}

impl fmt::Display for ReplyError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ReplyError::Decode(e) => e.fmt(f),
            ReplyError::Framing(e) => e.fmt(f),
            ReplyError::Missing(d) => write!(f, "missing reply field {d}"),
        }
    }
}

/// The error of an invalid or refused result.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ResultError {
    /// Refused before sending.
    Refused(Refusal),
    /// The reply is invalid.
    Reply(ReplyError),
}

impl fmt::Display for ResultError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ResultError::Refused(r) => r.fmt(f),
            ResultError::Reply(r) => r.fmt(f),
        }
    }
}

/// The one result of a started command. Its reply borrows the packet it came in.
#[derive(Clone, Copy, Debug)]
pub struct CommandResult<'a> {
    /// The id [`Session::start`] gave the command.
    pub id: u32,
    /// The command layout's facts (set, descriptor, name, ...).
    pub facts: &'static CommandFacts,
    /// What happened.
    pub status: Status,
    /// The ack/nack code (ack, nack, invalid), else `None`.
    pub code: Option<u32>,
    /// The error of an invalid or refused result.
    pub error: Option<ResultError>,
    /// The reply fields the command expected.
    pub expect: Expect,
    pub(crate) device: Option<Device>,
    // The reply: the payload entries after the ack, from payload offset `start`.
    pub(crate) reply: &'a [u8],
    pub(crate) start: usize,
}

impl<'a> CommandResult<'a> {
    fn bare(id: u32, facts: &'static CommandFacts, status: Status, expect: Expect) -> Self {
        Self {
            id,
            facts,
            status,
            code: None,
            error: None,
            expect,
            device: None,
            reply: &[],
            start: 0,
        }
    }

    /// True for ack and sent.
    pub fn is_ok(&self) -> bool {
        matches!(self.status, Status::Ack | Status::Sent)
    }

    /// The field entries that follow the ack in its packet (the reply).
    pub fn reply(&self) -> Fields<'a> {
        Fields::at(self.facts.set, self.reply, self.start)
    }

    /// The raw reply: the bytes of the reply's entries (field headers included).
    pub fn reply_bytes(&self) -> &'a [u8] {
        self.reply
    }

    /// Payload offset of the reply's first entry.
    pub fn reply_offset(&self) -> usize {
        self.start
    }

    /// The typed reply field: the first decoded entry whose descriptor is expected, else the
    /// first decoded entry.
    pub fn response(&self) -> Option<FieldValue> {
        let mut first = None;
        for item in self.reply() {
            if let FieldItem::Field { descriptor, data } = item {
                if let Ok(v) = decode_field(self.facts.set, descriptor, data, self.device) {
                    if self.expect.contains(descriptor) {
                        return Some(v);
                    }
                    if first.is_none() {
                        first = Some(v);
                    }
                }
            }
        }
        first
    }

    /// Writes the session tool's line for input line `line` (`docs/conformance.md` §8, no
    /// newline).
    pub fn write_line(&self, w: &mut dyn Write, line: u64) -> fmt::Result {
        w.write_str("{\"line\":")?;
        write!(
            w,
            "{line},\"result\":\"{}\",\"code\":",
            self.status.as_str()
        )?;
        match self.code {
            Some(c) => write!(w, "{c}")?,
            None => w.write_str("null")?,
        }
        w.write_str(",\"reply\":[")?;
        for (i, item) in self.reply().enumerate() {
            if i > 0 {
                w.write_char(',')?;
            }
            write_item_json(w, self.facts.set, item, self.device)?;
        }
        w.write_char(']')?;
        if let Some(e) = &self.error {
            w.write_str(",\"error\":")?;
            json::write_display(w, e)?;
        }
        w.write_char('}')
    }

    /// A short description (`"ping: NACK, code 3"`, `"ping: no reply before the timeout"`).
    pub fn describe(&self, w: &mut dyn Write) -> fmt::Result {
        let name = self.facts.name;
        match self.status {
            Status::Nack => write!(w, "{name}: NACK, code {}", self.code.unwrap_or(0)),
            Status::Timeout => write!(w, "{name}: no reply before the timeout"),
            Status::Invalid | Status::Refused => match &self.error {
                Some(e) => write!(w, "{name}: {e}"),
                None => write!(w, "{name}: {}", self.status.as_str()),
            },
            _ => write!(w, "{name}: {}", self.status.as_str()),
        }
    }
}

/// Writes the canonical JSON of one payload entry (a field, decoded or raw, or trailing bytes).
pub fn write_item_json(
    w: &mut dyn Write,
    set: u8,
    item: FieldItem<'_>,
    device: Option<Device>,
) -> fmt::Result {
    match item {
        FieldItem::Field { descriptor, data } => write_field_json(w, set, descriptor, data, device),
        FieldItem::Trailing { bytes, error } => {
            w.write_str("{\"trailing\":\"")?;
            json::write_hex(w, bytes)?;
            w.write_str("\",\"error\":")?;
            json::write_display(w, &error)?;
            w.write_char('}')
        }
    }
}

/// What a session reports, in stream order.
#[derive(Clone, Copy, Debug)]
pub enum SessionEvent<'a> {
    /// A command completed (ack, nack, timeout or invalid).
    Result(CommandResult<'a>),
    /// A packet that is not a reply (data, and replies that answer nothing pending).
    Packet {
        /// Stream offset.
        offset: u64,
        /// The packet.
        packet: Packet<'a>,
    },
    /// A run of skipped bytes.
    Skip {
        /// Stream offset of the first.
        offset: u64,
        /// How many.
        count: u64,
    },
    /// An NMEA-0183 sentence between packets (`$` or `!` to CR LF); ignore it if unwanted.
    Nmea {
        /// Stream offset.
        offset: u64,
        /// The sentence's bytes.
        bytes: &'a [u8],
    },
    /// An RTCM3 frame between packets (0xD3 to its CRC-24Q); ignore it if unwanted.
    Rtcm {
        /// Stream offset.
        offset: u64,
        /// The frame's bytes ([`crate::parser::rtcm_type`] gives its message number).
        bytes: &'a [u8],
    },
}

/// Options of one [`Session::start`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct StartOptions {
    /// The reply timeout of this command (default: the session's).
    pub timeout_ms: Option<u64>,
    /// Check the device's support (default: the session's setting).
    pub check_device: Option<bool>,
}

/// Why a command could not be started (a programming error: nothing is sent).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StartError {
    /// The value is not a command layout of a descriptor set.
    NotACommand,
    /// The command does not encode (a value out of its range).
    Encode(EncodeError),
}

impl fmt::Display for StartError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            StartError::NotACommand => f.write_str("not a command"),
            StartError::Encode(e) => e.fmt(f),
        }
    }
}

/// A started command: the bytes to send and, when it completed at once (sent or refused), its
/// result.
#[derive(Debug)]
pub struct Started<'s> {
    /// Id of the command, carried by its result.
    pub id: u32,
    /// The packet to send (empty when refused).
    pub packet: &'s [u8],
    /// When it times out (for a pending command).
    pub deadline: u64,
    /// The result of a command that completed at once (sent, refused), else `None`.
    pub result: Option<CommandResult<'static>>,
}

#[derive(Clone, Copy)]
struct Slot {
    id: u32,
    facts: &'static CommandFacts,
    deadline: u64,
    expect: Expect,
}

/// The queue of pending commands and what matching needs.
struct Queue<const N: usize> {
    slots: [Option<Slot>; N],
    len: usize,
    device: Option<Device>,
}

impl<const N: usize> Queue<N> {
    fn remove(&mut self, i: usize) -> Option<Slot> {
        if i >= self.len {
            return None;
        }
        let slot = self.slots[i].take();
        for k in i + 1..self.len {
            self.slots[k - 1] = self.slots[k].take();
        }
        self.len -= 1;
        slot
    }

    #[inline(always)]
    fn has_set(&self, set: u8) -> bool {
        self.slots[..self.len]
            .iter()
            .flatten()
            .any(|s| s.facts.set == set)
    }

    fn find(&self, set: u8, descriptor: u8) -> Option<usize> {
        self.slots[..self.len].iter().position(|s| {
            s.map_or(false, |s| {
                s.facts.set == set && s.facts.descriptor == descriptor
            })
        })
    }

    /// Routes one parser event: results of the commands a packet answers, else the packet
    /// (inlined into the parser's loop: this is the per-packet path of data streams).
    #[inline(always)]
    fn route<F: FnMut(SessionEvent<'_>)>(&mut self, event: Event<'_>, on: &mut F) {
        match event {
            Event::Skip {
                mut offset,
                mut count,
            } => {
                // In pieces of at most SKIP_PIECE bytes.
                while count > SKIP_PIECE {
                    on(SessionEvent::Skip {
                        offset,
                        count: SKIP_PIECE,
                    });
                    offset += SKIP_PIECE;
                    count -= SKIP_PIECE;
                }
                on(SessionEvent::Skip { offset, count })
            }
            Event::Nmea { offset, bytes } => on(SessionEvent::Nmea { offset, bytes }),
            Event::Rtcm { offset, bytes } => on(SessionEvent::Rtcm { offset, bytes }),
            Event::Packet { offset, bytes } => {
                let Some(packet) = Packet::new(bytes) else {
                    return;
                };
                if self.len > 0 && self.has_set(packet.set()) && self.answer(&packet, on) {
                    return;
                }
                on(SessionEvent::Packet { offset, packet });
            }
        }
    }

    /// Completes the commands the packet's ack fields answer; false when it answers none.
    fn answer<F: FnMut(SessionEvent<'_>)>(&mut self, packet: &Packet<'_>, on: &mut F) -> bool {
        let set = packet.set();
        let payload = packet.payload();
        // The reply being collected: (slot, code, payload offset of its first entry).
        let mut current: Option<(Slot, u32, usize)> = None;
        let mut answered = false;
        let mut fields = packet.fields();
        loop {
            let at = fields.offset();
            let item = fields.next();
            let ends = match item {
                None => true,
                Some(FieldItem::Field { descriptor, .. }) => descriptor == commands::ACK_DESCRIPTOR,
                Some(FieldItem::Trailing { .. }) => false,
            };
            if !ends {
                continue;
            }
            if let Some((slot, code, start)) = current.take() {
                let r = complete(slot, code, set, &payload[start..at], start, self.device);
                on(SessionEvent::Result(r));
                answered = true;
            }
            let Some(FieldItem::Field { descriptor, data }) = item else {
                break;
            };
            let ack = decode_field(set, descriptor, data, self.device)
                .ok()
                .and_then(|v| commands::ack_of(&v));
            if let Some((echo, code)) = ack {
                if let Some(slot) = self.find(set, echo).and_then(|i| self.remove(i)) {
                    current = Some((slot, code, fields.offset()));
                    // The result is reported when the reply ends (in ack order).
                    answered = true;
                }
            }
        }
        answered
    }
}

fn complete<'a>(
    slot: Slot,
    code: u32,
    set: u8,
    reply: &'a [u8],
    start: usize,
    device: Option<Device>,
) -> CommandResult<'a> {
    let mut r = CommandResult {
        code: Some(code),
        device,
        reply,
        start,
        ..CommandResult::bare(slot.id, slot.facts, Status::Ack, slot.expect)
    };
    if code != commands::ACK_OK {
        r.status = Status::Nack;
        return r;
    }
    let mut found = false;
    for item in Fields::at(set, reply, start) {
        match item {
            FieldItem::Trailing { error, .. } => {
                r.status = Status::Invalid;
                r.error = Some(ResultError::Reply(ReplyError::Framing(error)));
                return r;
            }
            FieldItem::Field { descriptor, data } => {
                if let Err(e) = decode_field(set, descriptor, data, device) {
                    r.status = Status::Invalid;
                    r.error = Some(ResultError::Reply(ReplyError::Decode(e)));
                    return r;
                }
                found |= slot.expect.contains(descriptor);
            }
        }
    }
    if let (false, Some(&first)) = (found, slot.expect.as_slice().first()) {
        r.status = Status::Invalid;
        r.error = Some(ResultError::Reply(ReplyError::Missing(first)));
    }
    r
}

/// Where a data packet carries a device's reference time (the spec's `time.reference_time`,
/// [`commands::REFERENCE_TIMES`]): a count of units (`ns_per_unit` ns each) or a GPS time (the
/// time of week, f64 s, at `offset`; the week, `week_size` bytes, at `week_offset`).
#[derive(Clone, Copy, Debug)]
pub struct ReferenceTime {
    /// The device.
    pub device: Device,
    /// The field's set.
    pub set: u8,
    /// The set is the shared one: the field is valid in every data set.
    pub shared: bool,
    /// The field's descriptor.
    pub descriptor: u8,
    /// A GPS time (else a count).
    pub gps: bool,
    /// Of the count or of the time of week, in the field data.
    pub offset: u8,
    /// Of the count.
    pub size: u8,
    /// Of the week number.
    pub week_offset: u8,
    /// Of the week number.
    pub week_size: u8,
    /// Of the count.
    pub ns_per_unit: i64,
}

fn load(data: &[u8], at: usize, size: usize) -> Option<u64> {
    let bytes = data.get(at..at.checked_add(size)?)?;
    let mut v = 0u64;
    for k in 0..size {
        let b = if crate::framing::BIG_ENDIAN {
            bytes[k]
        } else {
            bytes[size - 1 - k]
        };
        v = (v << 8) | u64::from(b);
    }
    Some(v)
}

fn field_reference(r: &ReferenceTime, data: &[u8]) -> Option<i64> {
    if !r.gps {
        let units = load(data, usize::from(r.offset), usize::from(r.size))?;
        return Some((units as i64).wrapping_mul(r.ns_per_unit));
    }
    let tow = f64::from_bits(load(data, usize::from(r.offset), 8)?);
    let week = load(data, usize::from(r.week_offset), usize::from(r.week_size))?;
    if !(0.0..1e7).contains(&tow) {
        return None; // not a time of week (NaN, negative, absurd)
    }
    Some(week as i64 * 604_800_000_000_000 + (tow * 1e9 + 0.5) as i64)
}

/// The device's reference time (ns) in a data packet (the spec's `time.reference_time`,
/// [`commands::REFERENCE_TIMES`]): the first field the table names for `device` (every device's
/// for `None`); `None` when it carries none.
pub fn reference_ns(device: Option<Device>, packet: &Packet<'_>) -> Option<i64> {
    let set = packet.set();
    commands::REFERENCE_TIMES
        .iter()
        .filter(|r| device.map_or(true, |d| d == r.device) && (r.shared || r.set == set))
        .find_map(|r| {
            packet.fields().find_map(|item| match item {
                FieldItem::Field { descriptor, data } if descriptor == r.descriptor => {
                    field_reference(r, data)
                }
                _ => None,
            })
        })
}

/// The sans-I/O session core (`docs/conformance.md` §8), with at most `N` pending commands.
pub struct Session<const N: usize = MAX_PENDING> {
    parser: Parser,
    // The look-ahead rule: the stream position the parser waits at, and since when.
    wait_at: Option<u64>,
    wait_since: u64,
    // The time of the last feed or poll.
    last_now: u64,
    queue: Queue<N>,
    timeout_ms: u64,
    inter_packet_timeout_ms: u64,
    check_device: bool,
    next_id: u32,
    builder: PacketBuilder,
    clock: Option<ClockModel>,
}

impl<const N: usize> Default for Session<N> {
    fn default() -> Self {
        Self::new(None)
    }
}

impl<const N: usize> Session<N> {
    /// A session for `device` (its layouts decode replies and data, and [`Session::start`]
    /// refuses what it does not support), with the default timeouts.
    pub fn new(device: Option<Device>) -> Self {
        Self {
            parser: Parser::new(),
            wait_at: None,
            wait_since: 0,
            last_now: 0,
            queue: Queue {
                slots: [None; N],
                len: 0,
                device,
            },
            timeout_ms: DEFAULT_TIMEOUT_MS,
            inter_packet_timeout_ms: DEFAULT_INTER_PACKET_TIMEOUT_MS,
            check_device: true,
            next_id: 1,
            builder: PacketBuilder::new(0),
            clock: None,
        }
    }

    /// Sets the reply timeout of every command (plus the spec's allowance).
    pub fn with_timeout_ms(mut self, ms: u64) -> Self {
        self.timeout_ms = ms;
        self
    }

    /// Sets the inter-packet timeout of the look-ahead rule.
    pub fn with_inter_packet_timeout_ms(mut self, ms: u64) -> Self {
        self.inter_packet_timeout_ms = ms;
        self
    }

    /// Turns the device support check off (or on) for every command.
    pub fn with_check_device(mut self, check: bool) -> Self {
        self.check_device = check;
        self
    }

    /// The session's device.
    pub fn device(&self) -> Option<Device> {
        self.queue.device
    }

    /// Number of commands waiting for their replies.
    pub fn pending(&self) -> usize {
        self.queue.len
    }

    /// The earliest stream offset whose byte may still be reported (in a skip run or a packet):
    /// a caller that keeps the input to print skipped bytes can drop everything before it.
    pub fn retain_from(&self) -> u64 {
        self.parser.retain_from()
    }

    /// Whether the command with this id still waits for its reply.
    pub fn is_pending(&self, id: u32) -> bool {
        self.queue.slots[..self.queue.len]
            .iter()
            .flatten()
            .any(|s| s.id == id)
    }

    /// The earliest time at which [`Session::poll`] has something to do, or `None`: the
    /// earliest command deadline, and while the parser waits at a position whose wait had not
    /// expired at the last call, the time it expires (`since + inter-packet timeout + 1`). Once
    /// the wait has expired a poll without new bytes can change nothing (the next feed checks
    /// by itself), so it adds no wake-up.
    pub fn next_deadline(&self) -> Option<u64> {
        let deadlines = self.queue.slots[..self.queue.len]
            .iter()
            .flatten()
            .map(|s| s.deadline);
        deadlines.chain(self.wait_wake()).min()
    }

    fn wait_wake(&self) -> Option<u64> {
        let waiting = self.parser.waiting() > 0
            && self.last_now.saturating_sub(self.wait_since) <= self.inter_packet_timeout_ms;
        waiting.then(|| {
            self.wait_since
                .saturating_add(self.inter_packet_timeout_ms)
                .saturating_add(1)
        })
    }

    /// Starts a command at `now`: returns the packet to send. A refused command (nothing to
    /// send) and one that suppresses its ack complete at once (`result`).
    pub fn start(
        &mut self,
        command: &FieldValue,
        now: u64,
        options: StartOptions,
    ) -> Result<Started<'_>, StartError> {
        let facts = commands::command_facts(command).ok_or(StartError::NotACommand)?;
        let id = self.next_id;
        self.next_id = self.next_id.wrapping_add(1).max(1);
        let expect = expected_replies(command, facts);
        let check = options.check_device.unwrap_or(self.check_device);
        if let (true, Some(device)) = (check, self.queue.device) {
            if let Some(why) = support_error(command, device) {
                let mut r = CommandResult::bare(id, facts, Status::Refused, expect);
                r.error = Some(ResultError::Refused(why));
                return Ok(Started {
                    id,
                    packet: &[],
                    deadline: now,
                    result: Some(r),
                });
            }
        }
        self.builder = PacketBuilder::new(facts.set);
        self.builder
            .add_field_with(facts.descriptor, |w| command.encode_data(w))
            .map_err(StartError::Encode)?;
        let base = options.timeout_ms.unwrap_or(self.timeout_ms);
        let deadline = now
            .saturating_add(base)
            .saturating_add(allowance_ms(command, facts));
        if ack_suppressed(command, facts) {
            return Ok(Started {
                id,
                packet: self.builder.finish(),
                deadline,
                result: Some(CommandResult::bare(id, facts, Status::Sent, expect)),
            });
        }
        if self.queue.len >= N {
            let mut r = CommandResult::bare(id, facts, Status::Refused, expect);
            r.error = Some(ResultError::Refused(Refusal::QueueFull { pending: N }));
            return Ok(Started {
                id,
                packet: &[],
                deadline,
                result: Some(r),
            });
        }
        self.queue.slots[self.queue.len] = Some(Slot {
            id,
            facts,
            deadline,
            expect,
        });
        self.queue.len += 1;
        Ok(Started {
            id,
            packet: self.builder.finish(),
            deadline,
            result: None,
        })
    }

    /// Bytes received at `now` (may be empty): calls `on` for every event, in stream order
    /// (timeouts first).
    ///
    /// The look-ahead rule (`docs/conformance.md` §8): when the parser has waited at the same
    /// position (a partial sync, header or packet) for more than the inter-packet timeout, the
    /// bytes buffered after it are searched for the first complete packet with a valid
    /// checksum; if there is one, the bytes before it are skipped and parsing resumes there,
    /// else nothing is dropped. It runs after the timeouts on the bytes buffered before this
    /// call, and again after `data` is parsed. A skip run is reported in pieces of
    /// [`SKIP_PIECE`] bytes as soon as it reaches that length.
    ///
    /// With a clock model ([`Session::use_clock`]) every data packet is fed to it at `now` ms
    /// (as [`Session::feed_at`] with `now` x 1000000 ns).
    pub fn feed<F: FnMut(SessionEvent<'_>)>(&mut self, data: &[u8], now: u64, mut on: F) {
        if self.clock.is_some() {
            let read_ns = i64::try_from(now).unwrap_or(i64::MAX / 1_000_000) * 1_000_000;
            self.feed_at(data, now, read_ns, |e, _| on(e));
        } else {
            self.feed_events(data, now, on);
        }
    }

    /// The host clock model (`docs/time.md`) this session feeds (`None`: none): from then on
    /// every packet that is not a reply and carries the device's reference time
    /// ([`reference_ns`]) is added to it at the host time of its bytes ([`Session::feed_at`]).
    pub fn use_clock(&mut self, model: Option<ClockModel>) {
        self.clock = model;
    }

    /// The host clock model, when the session feeds one.
    pub fn clock(&self) -> Option<&ClockModel> {
        self.clock.as_ref()
    }

    /// [`Session::feed`] with the host time the bytes were read (`read_ns`, ns of a monotonic
    /// clock: the clock model's arrival time); `on` gets every event with, for a packet, its host
    /// time by the clock model (`None` without a model, an estimate or the reference time).
    pub fn feed_at<F: FnMut(SessionEvent<'_>, Option<i64>)>(
        &mut self,
        data: &[u8],
        now: u64,
        read_ns: i64,
        mut on: F,
    ) {
        let mut clock = self.clock.take();
        let device = self.queue.device;
        self.feed_events(data, now, |e: SessionEvent<'_>| {
            let host = match (&e, clock.as_mut()) {
                (SessionEvent::Packet { packet, .. }, Some(c)) => {
                    reference_ns(device, packet).and_then(|d| c.add(d, read_ns))
                }
                _ => None,
            };
            on(e, host)
        });
        self.clock = clock;
    }

    fn feed_events<F: FnMut(SessionEvent<'_>)>(&mut self, data: &[u8], now: u64, mut on: F) {
        self.expire(now, &mut on);
        self.look_ahead(now, &mut on);
        if !data.is_empty() {
            let queue = &mut self.queue;
            self.parser.feed(data, |e| queue.route(e, &mut on));
            self.look_ahead(now, &mut on);
        }
        let queue = &mut self.queue;
        self.parser
            .report_skip_pieces(SKIP_PIECE, |e| queue.route(e, &mut on));
        self.last_now = now;
    }

    /// Notes the position the parser waits at: a new one's wait begins at `now`.
    fn note_wait(&mut self, now: u64) {
        if self.parser.waiting() == 0 {
            self.wait_at = None;
        } else if self.wait_at != Some(self.parser.waiting_at()) {
            self.wait_at = Some(self.parser.waiting_at());
            self.wait_since = now;
        }
    }

    /// The look-ahead rule at `now`, repeated while it finds a packet (after a jump the parser
    /// waits at a new position whose wait begins at `now`, so in practice it runs once).
    fn look_ahead<F: FnMut(SessionEvent<'_>)>(&mut self, now: u64, on: &mut F) {
        self.note_wait(now);
        while self.parser.waiting() > 0
            && now.saturating_sub(self.wait_since) > self.inter_packet_timeout_ms
        {
            let queue = &mut self.queue;
            if !self
                .parser
                .skip_to_complete_packet(|e| queue.route(e, &mut *on))
            {
                break;
            }
            self.note_wait(now);
        }
    }

    /// Nothing received: runs the timeouts and the look-ahead rule at `now`.
    pub fn poll<F: FnMut(SessionEvent<'_>)>(&mut self, now: u64, on: F) {
        self.feed(&[], now, on);
    }

    /// End of input: [`Session::poll`], then every buffered byte that is not a complete packet
    /// is skipped. Pending commands stay pending.
    pub fn close<F: FnMut(SessionEvent<'_>)>(&mut self, now: u64, mut on: F) {
        self.poll(now, &mut on);
        let queue = &mut self.queue;
        self.parser.flush(|e| queue.route(e, &mut on));
        self.wait_at = None;
    }

    /// The link was lost: every pending command is forgotten (no result is reported; the
    /// caller reports them as lost, they are not retried). Returns how many there were.
    pub fn abandon(&mut self) -> usize {
        let n = self.queue.len;
        for slot in self.queue.slots.iter_mut() {
            *slot = None;
        }
        self.queue.len = 0;
        n
    }

    fn expire<F: FnMut(SessionEvent<'_>)>(&mut self, now: u64, on: &mut F) {
        let mut i = 0;
        while i < self.queue.len {
            match self.queue.slots[i] {
                Some(s) if now >= s.deadline => {
                    self.queue.remove(i);
                    on(SessionEvent::Result(CommandResult::bare(
                        s.id,
                        s.facts,
                        Status::Timeout,
                        s.expect,
                    )));
                }
                _ => i += 1,
            }
        }
    }
}

/// Calls `on(descriptor, value)` for every field of `packet` that decodes (for routing data to
/// handlers per (set, descriptor)).
pub fn for_each_field<F: FnMut(u8, &FieldValue)>(
    packet: &Packet<'_>,
    device: Option<Device>,
    mut on: F,
) {
    let set = packet.set();
    for item in packet.fields() {
        if let FieldItem::Field { descriptor, data } = item {
            if let Ok(v) = decode_field(set, descriptor, data, device) {
                on(descriptor, &v);
            }
        }
    }
}
