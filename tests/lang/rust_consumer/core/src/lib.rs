//! A `no_std` consumer of a generated crate built with `default-features = false`: it may use
//! only the core API, and neither `std` nor `alloc` (the firmware image links it without an
//! allocator). `protocodec` stands for the package name (tests/lang/rust.sh replaces it).
#![cfg_attr(not(test), no_std)]
#![forbid(unsafe_code)]

use core::fmt::{self, Write};

use protocodec::builder::PacketBuilder;
use protocodec::dispatch::{set_defined, write_packet_json};
use protocodec::error::DecodeErrorKind;
use protocodec::fields::{FieldItem, Packet};
use protocodec::parser::{Event, Parser};
use protocodec::prelude::Layout;
use protocodec::wire::Writer;
use protocodec::{decode_field, FieldValue};

/// The first field (by set, then descriptor) that decodes from empty data, such as a command
/// without parameters: every protocol of the generator has one.
pub fn first_empty_field() -> Option<(u8, u8, FieldValue)> {
    (0..=255u8).filter(|&set| set_defined(set)).find_map(|set| {
        (0..=255u8).find_map(|d| decode_field(set, d, &[], None).ok().map(|v| (set, d, v)))
    })
}

/// Whether set `set` is in the crate's dispatch: some descriptor of it is unknown as a descriptor
/// (an error `UnknownDescriptor`), not as a set (`UnknownSet`: the set is not defined, or not
/// selected by the crate's cargo features `set-*`).
pub fn in_dispatch(set: u8) -> bool {
    (0..=255u8).any(|d| {
        matches!(
            decode_field(set, d, &[], None),
            Err(e) if e.kind == DecodeErrorKind::UnknownDescriptor
        )
    })
}

/// A fixed-size text buffer (no allocation).
pub struct Text<const N: usize> {
    buf: [u8; N],
    len: usize,
}

impl<const N: usize> Text<N> {
    pub const fn new() -> Self {
        Self {
            buf: [0; N],
            len: 0,
        }
    }

    pub fn as_str(&self) -> &str {
        core::str::from_utf8(&self.buf[..self.len]).unwrap_or("")
    }
}

impl<const N: usize> Default for Text<N> {
    fn default() -> Self {
        Self::new()
    }
}

impl<const N: usize> Write for Text<N> {
    fn write_str(&mut self, s: &str) -> fmt::Result {
        let end = self.len + s.len();
        if end > N {
            return Err(fmt::Error);
        }
        self.buf[self.len..end].copy_from_slice(s.as_bytes());
        self.len = end;
        Ok(())
    }
}

/// Builds a packet of the first empty field, finds it with the parser in a stream with one
/// garbage byte before and after it (fed in chunks of 3), decodes and re-encodes its field and
/// prints its canonical JSON line into `line`. Returns the packet's length, or what went wrong.
pub fn round_trip<const N: usize>(line: &mut Text<N>) -> Result<usize, &'static str> {
    let (set, descriptor, value) = first_empty_field().ok_or("no field decodes from empty data")?;
    let mut builder = PacketBuilder::new(set);
    builder
        .add_field_with(descriptor, |w| value.encode_data(w))
        .map_err(|_| "the builder refused the field")?;
    let packet = builder.finish();
    let mut stream = [0u8; 300];
    let total = packet.len() + 2;
    if total > stream.len() {
        return Err("the packet is too long for the test stream");
    }
    stream[1..=packet.len()].copy_from_slice(packet);

    let mut parser = Parser::new();
    let mut events = 0;
    let mut result = Ok(());
    let mut on_event = |event: Event<'_>| {
        let expected = match (events, event) {
            (
                0,
                Event::Skip {
                    offset: 0,
                    count: 1,
                },
            ) => true,
            (1, Event::Packet { offset: 1, bytes }) => bytes == packet,
            (2, Event::Skip { offset, count: 1 }) => offset == total as u64 - 1,
            _ => false,
        };
        if !expected && result.is_ok() {
            result = Err("unexpected parser event");
        }
        events += 1;
    };
    for chunk in stream[..total].chunks(3) {
        parser.feed(chunk, &mut on_event);
    }
    parser.flush(&mut on_event);
    result?;
    if events != 3 {
        return Err("want three parser events (skip, packet, skip)");
    }

    let parsed = Packet::new(packet).ok_or("Packet::new refused a built packet")?;
    let mut fields = parsed.fields();
    match fields.next() {
        Some(FieldItem::Field {
            descriptor: d,
            data,
        }) if d == descriptor && data.is_empty() => {
            let again =
                decode_field(set, d, data, None).map_err(|_| "the field does not decode")?;
            if again.name() != value.name() {
                return Err("the field decodes to another value");
            }
            let mut buf = [0u8; 8];
            let mut w = Writer::new(&mut buf);
            again
                .encode_data(&mut w)
                .map_err(|_| "re-encoding failed")?;
            if !w.written().is_empty() {
                return Err("re-encoding wrote data for an empty field");
            }
        }
        _ => return Err("the packet does not hold the field"),
    }
    if fields.next().is_some() {
        return Err("the packet holds more than one field");
    }
    write_packet_json(line, 1, &parsed, None).map_err(|_| "the JSON line does not fit")?;
    Ok(packet.len())
}

/// Builds a packet of one field from its set, descriptor and data; returns its length in `out`
/// (0 when the field does not fit or `out` is too short).
pub fn build_packet(set: u8, descriptor: u8, data: &[u8], out: &mut [u8]) -> usize {
    let mut builder = PacketBuilder::new(set);
    if builder.add_raw_field(descriptor, data).is_err() {
        return 0;
    }
    let packet = builder.finish();
    match out.get_mut(..packet.len()) {
        Some(dst) => {
            dst.copy_from_slice(packet);
            packet.len()
        }
        None => 0,
    }
}

/// Parses `input` (as a firmware would its serial bytes) and iterates the fields of every packet
/// without decoding them; returns (packets, fields).
pub fn count_packets(input: &[u8]) -> (usize, usize) {
    let mut parser = Parser::new();
    let (mut packets, mut fields) = (0, 0);
    let mut on_event = |event: Event<'_>| {
        if let Event::Packet { bytes, .. } = event {
            if let Some(packet) = Packet::new(bytes) {
                packets += 1;
                fields += packet
                    .fields()
                    .filter(|item| matches!(item, FieldItem::Field { .. }))
                    .count();
            }
        }
    };
    parser.feed(input, &mut on_event);
    parser.flush(&mut on_event);
    (packets, fields)
}

/// Parses `input` (as a firmware would its serial bytes) and decodes every field of every
/// packet; returns (packets, fields that decode).
pub fn count_fields(input: &[u8]) -> (usize, usize) {
    let mut parser = Parser::new();
    let (mut packets, mut decoded) = (0, 0);
    let mut on_event = |event: Event<'_>| {
        if let Event::Packet { bytes, .. } = event {
            if let Some(packet) = Packet::new(bytes) {
                packets += 1;
                for item in packet.fields() {
                    if let FieldItem::Field { descriptor, data } = item {
                        if decode_field(packet.set(), descriptor, data, None).is_ok() {
                            decoded += 1;
                        }
                    }
                }
            }
        }
    };
    parser.feed(input, &mut on_event);
    parser.flush(&mut on_event);
    (packets, decoded)
}

/// A field's typed value from its data, for any field type (the crate documentation's "One
/// field, typed" in a `no_std` build): the prelude brings the `Layout` trait into scope.
pub fn decode_typed<L: Layout>(data: &[u8]) -> Option<L> {
    L::decode_data(data).ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    // Needs a field that decodes from empty data (a command without parameters), which the
    // one-set selection (a data set) need not have.
    #[cfg(not(feature = "one-set"))]
    #[test]
    fn round_trip_without_std() {
        let mut line = Text::<512>::new();
        let len = round_trip(&mut line).unwrap();
        let (set, _, value) = first_empty_field().unwrap();
        assert!(len > 0);
        let head = format!("{{\"offset\":1,\"set\":{set},\"fields\":[");
        assert!(line.as_str().starts_with(&head), "{}", line.as_str());
        assert!(line
            .as_str()
            .contains(&format!("\"name\":\"{}\"", value.name())));
    }

    /// Without the feature `one-set`, every set the spec defines is in the dispatch (the crate's
    /// default: no `set-*` feature on); with it, exactly one of them (the crate's feature of its
    /// first data set, tests/lang/rust.sh).
    #[test]
    fn sets_in_dispatch() {
        let sets: Vec<u8> = (0..=255u8).filter(|&s| in_dispatch(s)).collect();
        let defined: Vec<u8> = (0..=255u8).filter(|&s| set_defined(s)).collect();
        assert!(defined.len() > 1, "{defined:?}");
        if cfg!(feature = "one-set") {
            assert_eq!(sets.len(), 1, "{sets:?}");
            assert!(set_defined(sets[0]));
        } else {
            assert_eq!(sets, defined);
        }
    }

    // Needs a field that decodes from empty data (a command without parameters), which the
    // one-set selection (a data set) need not have.
    #[cfg(not(feature = "one-set"))]
    #[test]
    fn counts_packets_and_fields() {
        let (set, descriptor, value) = first_empty_field().unwrap();
        let mut builder = PacketBuilder::new(set);
        builder
            .add_field_with(descriptor, |w| value.encode_data(w))
            .unwrap();
        builder
            .add_field_with(descriptor, |w| value.encode_data(w))
            .unwrap();
        let packet = builder.finish().to_vec();
        let mut stream = vec![0x00, 0x01];
        stream.extend_from_slice(&packet);
        stream.extend_from_slice(&packet[..packet.len() - 1]); // cut short: never reported
        stream.extend_from_slice(&packet);
        assert_eq!(count_fields(&stream), (2, 4));
        assert_eq!(count_packets(&stream), (2, 4));
        assert_eq!(count_fields(&[]), (0, 0));
        let mut out = [0u8; 300];
        let n = build_packet(set, descriptor, &[], &mut out);
        let mut one = PacketBuilder::new(set);
        one.add_field_with(descriptor, |w| value.encode_data(w))
            .unwrap();
        assert_eq!(&out[..n], one.finish());
        assert_eq!(count_fields(&out[..n]), (1, 1));
        assert_eq!(build_packet(set, descriptor, &[], &mut [0u8; 4]), 0);
    }
}
