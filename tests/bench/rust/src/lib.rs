//! The work the Rust benchmark measures (issue 8), shared by the plain runner (`src/main.rs`)
//! and the criterion bench (`benches/codec.rs`).
//!
//! - frame:  the stream parser over the whole in-memory stream (find sync, length, Fletcher
//!   checksum), every packet reported with its offset and bytes, garbage skipped.
//! - decode: frame, then split every packet into fields and decode every field to its typed value
//!   through the general dispatch (`decode_field`: by set and descriptor, a `FieldValue` per
//!   field). The fastest of the three in Rust (issue 38, docs/benchmarks.md), so the `decode` row.
//! - decode-cached: frame, then decode every packet through a `LayoutCache` (issue 38): the set's
//!   straight-line decoder fills the set's typed `Packet`, a packet of a shape seen before is
//!   decoded with that shape's offsets; what it leaves (none on these streams) goes to
//!   `decode_field`.
//! - decode-straight: the straight-line decoder without the cache (`mipcodec::decode_packet`).
//!
//! Both return counts that are checked against the stream's sidecar, and a checksum of what
//! they saw so that nothing can be optimised away.

use std::fs;
use std::hint::black_box;
use std::path::Path;

use mipcodec::fields::{FieldItem, Packet};
use mipcodec::parser::{Event, Parser};
use mipcodec::{decode_field, AnyPacket, FieldValue, LayoutCache};

/// The benchmark streams written by `tests/bench/streams.py`, in report order.
pub const STREAMS: [&str; 4] = ["accel_gyro", "mixed", "accel_gyro_garbage", "mixed_garbage"];

/// A stream and the counts of its sidecar.
pub struct Stream {
    pub name: String,
    pub data: Vec<u8>,
    pub packets: u64,
    pub fields: u64,
    pub packet_bytes: u64,
}

fn sidecar_number(json: &str, key: &str) -> Result<u64, String> {
    let pat = format!("\"{key}\":");
    let at = json
        .find(&pat)
        .ok_or_else(|| format!("sidecar has no \"{key}\""))?
        + pat.len();
    let digits: String = json[at..]
        .trim_start()
        .chars()
        .take_while(char::is_ascii_digit)
        .collect();
    digits
        .parse()
        .map_err(|_| format!("sidecar \"{key}\" is not a number"))
}

impl Stream {
    /// Reads `<dir>/<name>.bin` and its sidecar `<dir>/<name>.json`.
    pub fn load(dir: &Path, name: &str) -> Result<Self, String> {
        let bin = dir.join(format!("{name}.bin"));
        let side = dir.join(format!("{name}.json"));
        let data = fs::read(&bin).map_err(|e| format!("{}: {e}", bin.display()))?;
        let json = fs::read_to_string(&side).map_err(|e| format!("{}: {e}", side.display()))?;
        let bytes = sidecar_number(&json, "bytes")?;
        if bytes != data.len() as u64 {
            return Err(format!(
                "{name}: sidecar says {bytes} bytes, file has {}",
                data.len()
            ));
        }
        Ok(Self {
            name: name.to_string(),
            data,
            packets: sidecar_number(&json, "packets")?,
            fields: sidecar_number(&json, "fields")?,
            packet_bytes: sidecar_number(&json, "packet_bytes")?,
        })
    }
}

/// What one pass saw.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Tally {
    pub packets: u64,
    pub packet_bytes: u64,
    pub skipped_bytes: u64,
    pub fields: u64,
    /// Fields that did not decode (or trailing bytes): must be 0 on the benchmark streams.
    pub errors: u64,
    /// Wrapping sum of packet offsets and last bytes (frame), or of the bits of one float of
    /// each decoded field (decode).
    pub checksum: u64,
}

impl Tally {
    /// Error unless the counts match the sidecar (`fields` only for decode passes).
    pub fn check(&self, stream: &Stream, decode: bool) -> Result<(), String> {
        let name = &stream.name;
        if self.packets != stream.packets {
            return Err(format!(
                "{name}: saw {} packets, sidecar says {}",
                self.packets, stream.packets
            ));
        }
        if self.packet_bytes != stream.packet_bytes {
            return Err(format!(
                "{name}: saw {} packet bytes, sidecar says {}",
                self.packet_bytes, stream.packet_bytes
            ));
        }
        if self.packet_bytes + self.skipped_bytes != stream.data.len() as u64 {
            return Err(format!("{name}: packets and skips do not cover the stream"));
        }
        if decode {
            if self.fields != stream.fields {
                return Err(format!(
                    "{name}: saw {} fields, sidecar says {}",
                    self.fields, stream.fields
                ));
            }
            if self.errors != 0 {
                return Err(format!("{name}: {} fields did not decode", self.errors));
            }
        }
        Ok(())
    }
}

/// Frame: the stream parser over the whole stream, fed at once, then flushed.
pub fn frame(data: &[u8]) -> Tally {
    let mut t = Tally::default();
    let mut on = |event: Event<'_>| match event {
        Event::Packet { offset, bytes } => {
            t.packets += 1;
            t.packet_bytes += bytes.len() as u64;
            t.checksum = t
                .checksum
                .wrapping_add(offset ^ u64::from(bytes[bytes.len() - 1]));
        }
        Event::Skip { count, .. } => t.skipped_bytes += count,
        Event::Nmea { bytes, .. } | Event::Rtcm { bytes, .. } => {
            t.skipped_bytes += bytes.len() as u64
        }
    };
    let mut parser = Parser::new();
    parser.feed(data, &mut on);
    parser.flush(&mut on);
    t
}

/// The bits of one float of a decoded field (its first value), for the checksum; the
/// descriptor for the fields of the mixed streams not listed here.
#[inline]
pub fn first_float_bits(value: &FieldValue) -> u64 {
    use mipcodec::{filter_data as fd, gnss_data as gd, sensor};
    match value {
        FieldValue::Sensor(sensor::SetField::ScaledAccel(v)) => {
            u64::from(v.scaled_accel[0].to_bits())
        }
        FieldValue::Sensor(sensor::SetField::ScaledGyro(v)) => {
            u64::from(v.scaled_gyro[0].to_bits())
        }
        FieldValue::FilterData(fd::SetField::LlhPosition(v)) => v.latitude.to_bits(),
        FieldValue::FilterData(fd::SetField::NedVelocity(v)) => u64::from(v.north.to_bits()),
        FieldValue::GnssData(gd::SetField::LlhPosition(v)) => v.latitude.to_bits(),
        other => u64::from(other.descriptor()),
    }
}

/// The checksum of a packet decoded into `any`: per decoded field, the bits of its first float
/// for the fields `first_float_bits` lists, else its descriptor (the same sum as decode-field's).
#[inline]
pub fn packet_checksum(any: &AnyPacket) -> u64 {
    use mipcodec::wire::Layout;
    use mipcodec::{filter_data as fd, gnss_data as gd, sensor};
    const ACCEL: u8 = sensor::ScaledAccel::DESCRIPTOR;
    const GYRO: u8 = sensor::ScaledGyro::DESCRIPTOR;
    const FD_LLH: u8 = fd::LlhPosition::DESCRIPTOR;
    const FD_VEL: u8 = fd::NedVelocity::DESCRIPTOR;
    const GD_LLH: u8 = gd::LlhPosition::DESCRIPTOR;
    let sum = |descriptors: &[u8], bits: &dyn Fn(u8) -> u64| {
        descriptors
            .iter()
            .fold(0u64, |s, &d| s.wrapping_add(bits(d)))
    };
    match any.set() {
        Some(sensor::SET) => {
            let p = &any.sensor;
            sum(p.index.descriptors(), &|d| match d {
                ACCEL => u64::from(p.scaled_accel.scaled_accel[0].to_bits()),
                GYRO => u64::from(p.scaled_gyro.scaled_gyro[0].to_bits()),
                _ => u64::from(d),
            })
        }
        Some(fd::SET) => {
            let p = &any.filter_data;
            sum(p.index.descriptors(), &|d| match d {
                FD_LLH => p.llh_position.latitude.to_bits(),
                FD_VEL => u64::from(p.ned_velocity.north.to_bits()),
                _ => u64::from(d),
            })
        }
        Some(gd::SET) => {
            let p = &any.gnss_data;
            sum(p.index.descriptors(), &|d| match d {
                GD_LLH => p.llh_position.latitude.to_bits(),
                _ => u64::from(d),
            })
        }
        _ => any
            .index()
            .map_or(0, |index| sum(index.descriptors(), &|d| u64::from(d))),
    }
}

/// Decode: frame, then every packet through a layout cache into its set's typed packet; the
/// entries the straight-line decoders leave go to `decode_field`.
pub fn decode(data: &[u8]) -> Tally {
    decode_with(data, true)
}

/// Decode-straight: decode without the layout cache (`mipcodec::decode_packet`).
pub fn decode_straight(data: &[u8]) -> Tally {
    decode_with(data, false)
}

#[inline(always)]
fn decode_with(data: &[u8], cached: bool) -> Tally {
    let mut t = Tally::default();
    let mut any = Box::new(AnyPacket::default());
    let mut cache = Box::new(LayoutCache::new());
    let mut on = |event: Event<'_>| match event {
        Event::Packet { bytes, .. } => {
            t.packets += 1;
            t.packet_bytes += bytes.len() as u64;
            let set = bytes[mipcodec::framing::SET_OFFSET];
            let mut left = 0u64;
            let mut errors = 0u64;
            let mut sum = 0u64;
            let other = |item: FieldItem<'_>| match item {
                FieldItem::Field { descriptor, data } => {
                    left += 1;
                    match &decode_field(set, descriptor, data, None) {
                        Ok(value) => {
                            let value = black_box(value);
                            sum = sum.wrapping_add(first_float_bits(value));
                        }
                        Err(_) => errors += 1,
                    }
                }
                FieldItem::Trailing { .. } => errors += 1,
            };
            let n = if cached {
                cache.decode(bytes, &mut any, other)
            } else {
                mipcodec::decode_packet(bytes, &mut any, other)
            };
            // The whole typed packet is produced, not only the floats summed.
            let any = black_box(&*any);
            t.fields += n as u64 + left;
            t.errors += errors;
            t.checksum = t
                .checksum
                .wrapping_add(packet_checksum(any))
                .wrapping_add(sum);
        }
        Event::Skip { count, .. } => t.skipped_bytes += count,
        Event::Nmea { bytes, .. } | Event::Rtcm { bytes, .. } => {
            t.skipped_bytes += bytes.len() as u64
        }
    };
    let mut parser = Parser::new();
    parser.feed(data, &mut on);
    parser.flush(&mut on);
    t
}

/// Decode-field: frame, split every packet into fields and decode each one through the general
/// dispatch.
pub fn decode_field_each(data: &[u8]) -> Tally {
    let mut t = Tally::default();
    let mut on = |event: Event<'_>| match event {
        Event::Packet { bytes, .. } => {
            t.packets += 1;
            t.packet_bytes += bytes.len() as u64;
            let Some(packet) = Packet::new(bytes) else {
                t.errors += 1;
                return;
            };
            let set = packet.set();
            for item in packet.fields() {
                match item {
                    FieldItem::Field { descriptor, data } => {
                        t.fields += 1;
                        // By reference: the typed value stays where decode_field built it.
                        match &decode_field(set, descriptor, data, None) {
                            Ok(value) => {
                                // The whole typed value is produced, not only the float summed.
                                let value = black_box(value);
                                t.checksum = t.checksum.wrapping_add(first_float_bits(value));
                            }
                            Err(_) => t.errors += 1,
                        }
                    }
                    FieldItem::Trailing { .. } => t.errors += 1,
                }
            }
        }
        Event::Skip { count, .. } => t.skipped_bytes += count,
        Event::Nmea { bytes, .. } | Event::Rtcm { bytes, .. } => {
            t.skipped_bytes += bytes.len() as u64
        }
    };
    let mut parser = Parser::new();
    parser.feed(data, &mut on);
    parser.flush(&mut on);
    t
}

/// Decodes every field of a packet into the tally (the per-packet work of decode).
#[inline(always)]
fn decode_packet_fields(t: &mut Tally, packet: &Packet<'_>) {
    let set = packet.set();
    for item in packet.fields() {
        match item {
            FieldItem::Field { descriptor, data } => {
                t.fields += 1;
                match &decode_field(set, descriptor, data, None) {
                    Ok(value) => {
                        let value = black_box(value);
                        t.checksum = t.checksum.wrapping_add(first_float_bits(value));
                    }
                    Err(_) => t.errors += 1,
                }
            }
            FieldItem::Trailing { .. } => t.errors += 1,
        }
    }
}

/// Session ingest (issue 20): the stream fed to a command session that has one command (a
/// ping) pending whose reply never comes, its deadline far away; every packet that is not a
/// reply goes to a per-packet handler that decodes its fields as `decode` does.
pub fn session_ingest(data: &[u8]) -> Tally {
    use mipcodec::base::{Ping, SetField};
    use mipcodec::session::{Session, SessionEvent, StartOptions};
    let mut t = Tally::default();
    let mut session: Session = Session::new(None).with_timeout_ms(u64::MAX / 4);
    let ping = FieldValue::Base(SetField::Ping(Ping {}));
    if session.start(&ping, 0, StartOptions::default()).is_err() {
        t.errors += 1;
    }
    let mut on = |event: SessionEvent<'_>| match event {
        SessionEvent::Packet { packet, .. } => {
            t.packets += 1;
            t.packet_bytes += packet.bytes().len() as u64;
            decode_packet_fields(&mut t, &packet);
        }
        SessionEvent::Skip { count, .. } => t.skipped_bytes += count,
        SessionEvent::Nmea { bytes, .. } | SessionEvent::Rtcm { bytes, .. } => {
            t.skipped_bytes += bytes.len() as u64
        }
        SessionEvent::Result(_) => t.errors += 1,
    };
    session.feed(data, 1, &mut on);
    session.close(1, &mut on);
    t
}

/// Session round trips (issue 20): `n` pings through the blocking API (`Device`, the typed
/// `device.base().ping()`) over a loopback TCP socket to a responder thread that answers each
/// ping with its ack. Returns the bytes sent and received.
pub fn session_roundtrip(n: u64) -> Result<u64, String> {
    use std::io::{Read, Write};
    use std::net::{TcpListener, TcpStream};

    use mipcodec::device::{Device, TcpTransport};

    const PING: [u8; 8] = [0x75, 0x65, 0x01, 0x02, 0x02, 0x01, 0xE0, 0xC6];
    const ACK: [u8; 10] = [0x75, 0x65, 0x01, 0x04, 0x04, 0xF1, 0x01, 0x00, 0xD5, 0x6A];
    let listener = TcpListener::bind("127.0.0.1:0").map_err(|e| e.to_string())?;
    let port = listener.local_addr().map_err(|e| e.to_string())?.port();
    let responder = std::thread::spawn(move || -> Result<(), String> {
        let (mut conn, _) = listener.accept().map_err(|e| e.to_string())?;
        let _ = conn.set_nodelay(true);
        let mut packet = [0u8; 8];
        for _ in 0..n {
            conn.read_exact(&mut packet).map_err(|e| e.to_string())?;
            if packet != PING {
                return Err(format!("responder: not a ping: {packet:02x?}"));
            }
            conn.write_all(&ACK).map_err(|e| e.to_string())?;
        }
        Ok(())
    });
    let stream = TcpStream::connect(("127.0.0.1", port)).map_err(|e| e.to_string())?;
    let mut device = Device::new(TcpTransport::new(stream), None);
    for i in 0..n {
        device
            .base()
            .ping()
            .map_err(|e| format!("round trip {i}: {e}"))?;
    }
    drop(device);
    responder
        .join()
        .map_err(|_| "responder panicked".to_string())??;
    Ok(n * (PING.len() + ACK.len()) as u64)
}
