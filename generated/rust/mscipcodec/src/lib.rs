//! Memsense MS-CIP: codec generated from `spec/mscip/` by `python -m generator`. Do not edit.
//!
//! The core is `no_std` and allocation-free: bounded arrays ([`bounded::BoundedVec`]), a stream
//! parser whose state is one maximum packet ([`parser::Parser`]), a sample tracker for
//! continuation packets ([`samples`]), a packet builder
//! ([`builder::PacketBuilder`]), a field iterator ([`fields::Packet`]), typed values for every
//! field (one module per descriptor set, [`reserved`], [`types`]) and the canonical JSON writer
//! ([`json`]), and the sans-I/O command session ([`session`], with the spec's facts of every
//! command in [`commands`]). The default `std` feature adds the JSON reader ([`json_read`]), the
//! text helpers used by the command-line tools ([`text`]), the tools themselves, and the
//! blocking session API over TCP or (feature `serial`) a serial port ([`device`]) with the typed
//! command API ([`command_api`]).
//!
//! ```
//! use mscipcodec::builder::PacketBuilder;
//! use mscipcodec::fields::{FieldItem, Packet};
//! use mscipcodec::parser::{Event, Parser};
//!
//! // Build a packet with one raw field, then find it in a stream with garbage around it.
//! let mut builder = PacketBuilder::new(0x01);
//! builder.add_raw_field(0x01, &[]).unwrap();
//! let mut stream = vec![0x00];
//! stream.extend_from_slice(builder.finish());
//!
//! let mut parser = Parser::new();
//! let mut packets = Vec::new();
//! let mut on_event = |event: Event<'_>| match event {
//!     Event::Packet { offset, bytes } => packets.push((offset, bytes.to_vec())),
//!     Event::Skip { offset, count } => assert_eq!((offset, count), (0, 1)),
//!     Event::Nmea { .. } | Event::Rtcm { .. } => {} // other protocols' frames between packets
//! };
//! parser.feed(&stream, &mut on_event);
//! parser.flush(&mut on_event);
//!
//! let packet = Packet::new(&packets[0].1).unwrap();
//! for item in packet.fields() {
//!     if let FieldItem::Field { descriptor, data } = item {
//!         // A typed value (FieldValue), or the decode error of a raw field.
//!         let _value = mscipcodec::decode_field(packet.set(), descriptor, data, None);
//!     }
//! }
//! ```
//!
//! # One field, typed (firmware too)
//!
//! Every field type implements [`wire::Layout`] (its descriptor and set, `decode_data`,
//! `encode_data`), so the trait must be in scope: `use mscipcodec::prelude::*;` brings it and
//! the parser, packet and builder types. With `default-features = false` this needs neither `std`
//! nor an allocator (`tests/lang/rust_consumer/core` uses the prelude in a `no_std` build for a
//! Cortex-M4F).
//!
//! ```
//! use mscipcodec::prelude::*;
//! use mscipcodec::imu_data::ScaledAccel;
//!
//! // The data of a received 0xA2,0x81 field (after its header), e.g. from
//! // `FieldItem::Field { descriptor, data }` of `Packet::fields`.
//! let data = [0u8; 12];
//! let value = ScaledAccel::decode_data(&data).unwrap();
//! assert_eq!((ScaledAccel::DESCRIPTOR_SET, ScaledAccel::DESCRIPTOR), (Some(0xA2), 0x81));
//!
//! // And back into a packet of its set.
//! let mut builder = PacketBuilder::new(0xA2);
//! builder.add(&value).unwrap();
//! let packet = Packet::new(builder.finish()).unwrap();
//! assert!(matches!(packet.fields().next(), Some(FieldItem::Field { descriptor: 0x81, .. })));
//! ```
#![cfg_attr(not(feature = "std"), no_std)]
#![forbid(unsafe_code)]

/// What typed decoding needs in scope, `use mscipcodec::prelude::*;`: the
/// [`crate::wire::Layout`] and [`crate::wire::Wire`] traits, the stream parser, the packet view,
/// the builder, the errors.
pub mod prelude {
    pub use crate::builder::PacketBuilder;
    pub use crate::error::{DecodeError, EncodeError};
    pub use crate::fields::{FieldItem, Packet};
    pub use crate::parser::{Event, Parser};
    pub use crate::wire::{Layout, Reader, Wire, Writer};
    pub use crate::{decode_field, FieldValue};
}

pub mod bounded;
pub mod builder;
pub mod clock;
#[cfg(feature = "std")]
pub mod command_api;
pub mod commands;
#[cfg(feature = "std")]
pub mod device;
pub mod dispatch;
pub mod error;
pub mod fields;
pub mod framing;
pub mod json;
#[cfg(feature = "std")]
pub mod json_read;
pub mod packets;
pub mod parser;
pub mod reserved;
pub mod samples;
pub mod session;
#[cfg(feature = "std")]
pub mod text;
pub mod types;
pub mod wire;

pub mod base;
pub mod imu_config;
pub mod imu_data;

/// The package's version (semantic versioning: MAJOR.MINOR.PATCH; every package of a release has
/// it), also the crate's version.
///
/// ```
/// assert_eq!(mscipcodec::VERSION, env!("CARGO_PKG_VERSION"));
/// ```
pub const VERSION: &str = "0.1.0";
/// The parts of [`VERSION`].
pub const VERSION_MAJOR: u32 = 0;
/// The parts of [`VERSION`].
pub const VERSION_MINOR: u32 = 1;
/// The parts of [`VERSION`].
pub const VERSION_PATCH: u32 = 0;
/// First 16 hex digits of the SHA-256 of the mscip protocol's canonical IR: two crates
/// with the same hash were generated from the same spec.
pub const SPEC_HASH: &str = "3314b414c7a35ed5";
/// The protocol's name in the spec (`spec/mscip/`), as the tools print it.
pub const PROTOCOL: &str = "mscip";

pub use dispatch::{decode_field, set_kind, Device, FieldValue, SetKind};
pub use error::{DecodeError, EncodeError};
pub use packets::{decode_packet, AnyPacket, LayoutCache, PacketIndex};
