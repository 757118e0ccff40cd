//! Fuzz harnesses over the generated Rust crates, one module per package (`mipcodec`,
//! `mscipcodec`), each with the two targets of the C harnesses (tests/fuzz/c/) and the same
//! input format, so an input saved by any language replays in all of them:
//!
//! - `parser(data)`: byte 0 is a control byte (chunk plan in its low 6 bits, device in its top
//!   2 bits), the rest a byte stream. The events must cover the stream exactly (contiguous
//!   offsets, skip and packet lengths summing to its length, no two skip runs in a row, packets
//!   with a valid checksum equal to the stream's bytes); the stream fed in chunks must give the
//!   same events; every field is walked and decoded through `decode_field` (no device and each
//!   device) and a field that decodes re-encodes to exactly its bytes (and not into one byte
//!   less); every canonical JSON line is printable ASCII, its truncated print into a small
//!   buffer is a prefix of it, and it encodes back to the event's bytes. The stream is also
//!   wrapped as (set, payload) into a packet with a valid checksum.
//! - `decode(data)`: the lean companion of `parser` (for execution count; the same input format):
//!   one whole parse with the event checks, every field walked and decoded with the control
//!   byte's device only and re-encoded, and the stream wrapped into a packet; no chunked
//!   re-parse, no JSON lines, no sample tracker. Every packet also goes through the straight-line
//!   decoder (`decode_packet`) and the layout cache (twice, so that the second is a hit when its
//!   shape was recorded): each entry is decoded into its member with `decode_field`'s value (no
//!   device) or passed on, in packet order, as the general dispatch says (issue 38).
//! - `json(data)`: each line of the input (UTF-8; other input is not a line the encode tool
//!   could read) goes through `text::encode_line`; when it is accepted, the bytes are parsed and
//!   every event's line must encode back to that event's bytes.
//!
//! A failed check panics, which libFuzzer reports as a crash and `cargo test` as a failure.

use core::fmt;

/// A `fmt::Write` that keeps at most `cap` bytes and fails once more is written.
struct Bounded {
    text: String,
    cap: usize,
}

impl fmt::Write for Bounded {
    fn write_str(&mut self, s: &str) -> fmt::Result {
        if self.text.len() + s.len() > self.cap {
            let room = self.cap - self.text.len();
            let mut cut = room;
            while !s.is_char_boundary(cut) {
                cut -= 1;
            }
            self.text.push_str(&s[..cut]);
            return Err(fmt::Error);
        }
        self.text.push_str(s);
        Ok(())
    }
}

fn hex(bytes: &[u8]) -> String {
    bytes.iter().map(|b| format!("{b:02x}")).collect()
}

/// Chunk sizes of the chunked parse (the same plan as tests/fuzz/c/fuzz_common.h).
struct Chunks {
    state: u32,
    max: u32,
}

impl Chunks {
    fn new(control: u8) -> Self {
        Self {
            state: u32::from(control),
            max: u32::from(control & 0x3f) + 1,
        }
    }
    fn next_size(&mut self) -> usize {
        self.state = (self.state * 73 + 41) & 0xff;
        (1 + self.state % self.max) as usize
    }
}

const SMALL_LINE: usize = 24;

macro_rules! harness {
    ($pkg:ident) => {
        pub mod $pkg {
            //! The harnesses over this generated crate.

            use ::$pkg::builder::PacketBuilder;
            use ::$pkg::dispatch::{write_packet_json, write_skip_json};
            use ::$pkg::fields::{FieldItem, Packet};
            use ::$pkg::framing::{field_length_adjust, CHECKSUM_SIZE, FIELD_HEADER_SIZE, HEADER_SIZE, MAX_PAYLOAD};
            use ::$pkg::parser::{Event, Parser};
            use ::$pkg::samples::SampleTracker;
            use ::$pkg::text::encode_line;
            use ::$pkg::wire::Writer;
            use ::$pkg::{decode_field, decode_packet, AnyPacket, Device, LayoutCache};

            use super::{hex, Bounded, Chunks, SMALL_LINE};

            #[derive(Clone, Copy, Debug, PartialEq, Eq)]
            enum Kind {
                Packet,
                Skip,
                Foreign,
            }

            /// Parses `stream` (whole, or in chunks from `plan`), checking each event against the
            /// stream; returns (kind, offset, length) per event and calls `each` on the events.
            fn events(
                stream: &[u8],
                plan: Option<&mut Chunks>,
                mut each: impl FnMut(Kind, u64, &[u8]),
            ) -> Vec<(Kind, u64, u64)> {
                let mut out: Vec<(Kind, u64, u64)> = Vec::new();
                let mut on = |ev: Event<'_>| {
                    let (kind, offset, len, bytes) = match ev {
                        Event::Packet { offset, bytes } => (Kind::Packet, offset, bytes.len() as u64, bytes),
                        Event::Skip { offset, count } => (Kind::Skip, offset, count, &[][..]),
                        Event::Nmea { offset, bytes } | Event::Rtcm { offset, bytes } => {
                            (Kind::Foreign, offset, bytes.len() as u64, bytes)
                        }
                    };
                    let expected = out.last().map_or(0, |&(_, o, l)| o + l);
                    if let Some(&(last, _, _)) = out.last() {
                        assert!(!(last == Kind::Skip && kind == Kind::Skip), "two skip runs in a row");
                    }
                    assert_eq!(offset, expected, "event offset");
                    assert!(len > 0 && len <= stream.len() as u64 - offset, "event length {len} at {offset}");
                    let slice = &stream[offset as usize..(offset + len) as usize];
                    if kind != Kind::Skip {
                        assert_eq!(bytes, slice, "packet bytes differ from the stream at {offset}");
                    }
                    out.push((kind, offset, len));
                    if kind != Kind::Foreign {
                        // a foreign frame's line is not encoder input (docs/conformance.md §5)
                        each(kind, offset, slice);
                    }
                };
                let mut parser = Parser::new();
                match plan {
                    None => parser.feed(stream, &mut on),
                    Some(plan) => {
                        let mut pos = 0;
                        while pos < stream.len() {
                            let n = plan.next_size().min(stream.len() - pos);
                            parser.feed(&stream[pos..pos + n], &mut on);
                            pos += n;
                        }
                    }
                }
                parser.flush(&mut on);
                let end = out.last().map_or(0, |&(_, o, l)| o + l);
                assert_eq!(end, stream.len() as u64, "the events do not cover the stream");
                out
            }

            fn check_field(set: u8, descriptor: u8, data: &[u8], device: Option<Device>) {
                match decode_field(set, descriptor, data, device) {
                    Ok(value) => {
                        assert_eq!(value.descriptor(), descriptor, "decoded descriptor");
                        let mut buf = vec![0u8; data.len()];
                        let mut w = Writer::new(&mut buf);
                        if let Err(e) = value.encode_data(&mut w) {
                            panic!(
                                "re-encode of {} (set {set} descriptor {descriptor}) failed: {e}; data {}",
                                value.name(),
                                hex(data)
                            );
                        }
                        // compared as bytes (hex only on failure: this runs for every field)
                        assert!(
                            w.written() == data,
                            "{} (set {set} descriptor {descriptor}) re-encodes to {}, data {}",
                            value.name(),
                            hex(w.written()),
                            hex(data)
                        );
                        if !data.is_empty() {
                            let mut short = vec![0u8; data.len() - 1];
                            let mut w = Writer::new(&mut short);
                            assert!(value.encode_data(&mut w).is_err(), "encoded into one byte less");
                        }
                    }
                    Err(e) => {
                        let text = e.to_string();
                        assert!(!text.is_empty() && text.is_ascii(), "decode error text {text:?}");
                    }
                }
            }

            /// Prints the line of an event into a small and an adequate buffer, then encodes it.
            fn check_line(bytes: &[u8], offset: u64, packet: bool, device: Option<Device>) {
                let print = |w: &mut dyn core::fmt::Write| {
                    if packet {
                        write_packet_json(w, offset, &Packet::new(bytes).expect("packet"), device)
                    } else {
                        write_skip_json(w, offset, bytes)
                    }
                };
                let mut line = String::new();
                print(&mut line).expect("printing into a String");
                assert!(line.bytes().all(|b| (0x20..0x7f).contains(&b)), "not printable ASCII: {line}");
                let mut small = Bounded { text: String::new(), cap: SMALL_LINE };
                let res = print(&mut small);
                assert_eq!(res.is_ok(), line.len() <= SMALL_LINE, "small buffer result");
                assert!(line.starts_with(&small.text), "small-buffer print is not a prefix: {line}");
                match encode_line(&line) {
                    Ok(out) => assert_eq!(hex(&out), hex(bytes), "the line encodes to other bytes: {line}"),
                    Err(e) => panic!("the decoded line does not encode ({e}): {line}"),
                }
            }

            fn check_packet(bytes: &[u8], offset: u64, device: Option<Device>, tracker: &mut SampleTracker) {
                let packet = Packet::new(bytes).expect("a packet the parser reported");
                let set = packet.set();
                let payload = packet.payload();
                assert_eq!(bytes.len(), HEADER_SIZE + payload.len() + CHECKSUM_SIZE, "packet length");
                let mut pos = 0usize;
                let mut ended = false;
                for item in packet.fields() {
                    assert!(!ended, "an entry after the trailing entry");
                    match item {
                        FieldItem::Field { descriptor, data } => {
                            let adjust = field_length_adjust(set, descriptor);
                            let length = payload[pos + ::$pkg::framing::FIELD_LENGTH_OFFSET];
                            assert_eq!(payload[pos + ::$pkg::framing::FIELD_DESCRIPTOR_OFFSET], descriptor);
                            assert_eq!(data.len() as isize, isize::from(length) - adjust, "field length");
                            assert_eq!(data, &payload[pos + FIELD_HEADER_SIZE..pos + FIELD_HEADER_SIZE + data.len()]);
                            pos += FIELD_HEADER_SIZE + data.len();
                            check_field(set, descriptor, data, None);
                            for d in Device::ALL {
                                check_field(set, descriptor, data, Some(d));
                            }
                        }
                        FieldItem::Trailing { bytes: rest, error } => {
                            assert_eq!(rest, &payload[pos..], "trailing entry is not the rest");
                            assert!(!rest.is_empty(), "empty trailing entry");
                            assert!(!error.to_string().is_empty());
                            pos = payload.len();
                            ended = true;
                        }
                    }
                }
                assert_eq!(pos, payload.len(), "the entries do not cover the payload");
                check_line(bytes, offset, true, device);
                if let Some(place) = tracker.feed(&packet) {
                    assert!(place.shared_prefix <= payload.len(), "shared prefix");
                }
            }

            /// The `parser` target.
            pub fn parser(data: &[u8]) {
                let Some((&control, stream)) = data.split_first() else {
                    return;
                };
                let dev = usize::from(control >> 6);
                let device = if dev >= 1 && dev <= Device::ALL.len() { Some(Device::ALL[dev - 1]) } else { None };
                let mut tracker = SampleTracker::new();
                let whole = events(stream, None, |kind, offset, bytes| {
                    if kind == Kind::Packet {
                        check_packet(bytes, offset, device, &mut tracker);
                    } else {
                        check_line(bytes, offset, false, device);
                    }
                });
                let mut plan = Chunks::new(control);
                let chunked = events(stream, Some(&mut plan), |_, _, _| {});
                assert_eq!(whole, chunked, "events differ when fed in chunks");
                if let Some((&set, rest)) = stream.split_first() {
                    let payload = &rest[..rest.len().min(MAX_PAYLOAD)];
                    let mut b = PacketBuilder::new(set);
                    b.add_bytes(payload).expect("a payload of at most the maximum");
                    let built = b.finish().to_vec();
                    let one = events(&built, None, |_, _, _| {});
                    assert_eq!(one, vec![(Kind::Packet, 0, built.len() as u64)], "a built packet");
                    check_packet(&built, 0, device, &mut SampleTracker::new());
                }
            }

            fn decode_fields(bytes: &[u8], device: Option<Device>) {
                let packet = Packet::new(bytes).expect("a packet the parser reported");
                let set = packet.set();
                let payload = packet.payload();
                assert_eq!(bytes.len(), HEADER_SIZE + payload.len() + CHECKSUM_SIZE, "packet length");
                let mut pos = 0usize;
                for item in packet.fields() {
                    match item {
                        FieldItem::Field { descriptor, data } => {
                            assert_eq!(data, &payload[pos + FIELD_HEADER_SIZE..pos + FIELD_HEADER_SIZE + data.len()]);
                            pos += FIELD_HEADER_SIZE + data.len();
                            check_field(set, descriptor, data, device);
                        }
                        FieldItem::Trailing { bytes: rest, .. } => {
                            assert_eq!(rest, &payload[pos..], "trailing entry is not the rest");
                            assert!(!rest.is_empty(), "empty trailing entry");
                            pos = payload.len();
                        }
                    }
                }
                assert_eq!(pos, payload.len(), "the entries do not cover the payload");
            }

            /// What a straight-line decode gave: (descriptor, JSON) of the members in index order,
            /// then the entries passed on.
            fn straight(any: &AnyPacket, other: Vec<String>, n: usize) -> (Vec<(u8, String)>, Vec<String>) {
                let members: Vec<(u8, String)> = any
                    .index()
                    .map(|index| {
                        index
                            .descriptors()
                            .iter()
                            .map(|&d| {
                                let mut s = String::new();
                                any.field(d).expect("a decoded member").write_json(&mut s).expect("JSON");
                                (d, s)
                            })
                            .collect()
                    })
                    .unwrap_or_default();
                assert_eq!(members.len(), n, "the count returned is the index's");
                (members, other)
            }

            /// The straight-line decoder and the layout cache against the general dispatch.
            fn check_straight(bytes: &[u8], any: &mut AnyPacket, cache: &mut LayoutCache) {
                let packet = Packet::new(bytes).expect("a packet the parser reported");
                let set = packet.set();
                let mut other = Vec::new();
                let n = decode_packet(bytes, any, |item| other.push(format!("{item:?}")));
                let got = straight(any, other, n);
                let mut want = (Vec::new(), Vec::new());
                let mut taken = [false; 256];
                for item in packet.fields() {
                    if let FieldItem::Field { descriptor, data } = item {
                        let d = usize::from(descriptor);
                        if !taken[d] && any.has_member(descriptor) {
                            if let Ok(value) = decode_field(set, descriptor, data, None) {
                                taken[d] = true;
                                let mut s = String::new();
                                value.write_json(&mut s).expect("JSON");
                                want.0.push((descriptor, s));
                                continue;
                            }
                        }
                    }
                    want.1.push(format!("{item:?}"));
                }
                assert_eq!(got, want, "straight-line decode of {}", hex(bytes));
                for pass in 0..2 {
                    let mut other = Vec::new();
                    let n = cache.decode(bytes, any, |item| other.push(format!("{item:?}")));
                    assert_eq!(straight(any, other, n), want, "layout cache (pass {pass}) on {}", hex(bytes));
                }
            }

            /// The `decode` target.
            pub fn decode(data: &[u8]) {
                let Some((&control, stream)) = data.split_first() else {
                    return;
                };
                let dev = usize::from(control >> 6);
                let device = if dev >= 1 && dev <= Device::ALL.len() { Some(Device::ALL[dev - 1]) } else { None };
                let mut any = Box::new(AnyPacket::default());
                let mut cache = Box::new(LayoutCache::new());
                events(stream, None, |kind, _, bytes| {
                    if kind == Kind::Packet {
                        decode_fields(bytes, device);
                        check_straight(bytes, &mut any, &mut cache);
                    }
                });
                if let Some((&set, rest)) = stream.split_first() {
                    let payload = &rest[..rest.len().min(MAX_PAYLOAD)];
                    let mut b = PacketBuilder::new(set);
                    b.add_bytes(payload).expect("a payload of at most the maximum");
                    let built = b.finish().to_vec();
                    let one = events(&built, None, |_, _, bytes| {
                        decode_fields(bytes, device);
                        check_straight(bytes, &mut any, &mut cache);
                    });
                    assert_eq!(one, vec![(Kind::Packet, 0, built.len() as u64)], "a built packet");
                }
            }

            /// The `json` target.
            pub fn json(data: &[u8]) {
                let Ok(text) = core::str::from_utf8(data) else {
                    return;
                };
                for line in text.split('\n') {
                    let Ok(bytes) = encode_line(line) else {
                        continue;
                    };
                    let mut line_of = String::new();
                    events(&bytes, None, |kind, offset, ev| {
                        line_of.clear();
                        let packet = kind == Kind::Packet;
                        if packet {
                            write_packet_json(&mut line_of, offset, &Packet::new(ev).expect("packet"), None)
                        } else {
                            write_skip_json(&mut line_of, offset, ev)
                        }
                        .expect("printing into a String");
                        match encode_line(&line_of) {
                            Ok(out) => assert_eq!(hex(&out), hex(ev), "line {line:?} -> {line_of}"),
                            Err(e) => panic!("the decoded line does not encode ({e}): {line_of}"),
                        }
                    });
                }
            }
        }
    };
}

harness!(mipcodec);
harness!(mscipcodec);
