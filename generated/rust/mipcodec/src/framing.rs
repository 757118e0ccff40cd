//! Framing of the MicroStrain MIP protocol, rendered from `ir.json` → `protocols[].framing`, and the
//! Fletcher-16 checksum. These constants are the only protocol input of the runtime modules
//! (parser, builder, fields, wire, error, samples), which are the same in every crate.
//!
//! Packet: sync (75 65), header [set, payload_length], payload, checksum.
//! Field: header [length, descriptor], then the field data.

/// Sync bytes that start every packet.
pub const SYNC: [u8; 2] = [0x75, 0x65];
/// Size of the packet header: the sync bytes, the set byte and the payload length byte.
pub const HEADER_SIZE: usize = 4;
/// Offset of the descriptor set byte in a packet.
pub const SET_OFFSET: usize = 2;
/// Offset of the payload length byte in a packet.
pub const LENGTH_OFFSET: usize = 3;
/// Largest payload length a packet may declare.
pub const MAX_PAYLOAD: usize = 255;
/// Size of the checksum after the payload.
pub const CHECKSUM_SIZE: usize = 2;
/// Largest packet: header, maximum payload and checksum.
pub const MAX_PACKET: usize = 261;
/// Whether the parser reports NMEA-0183 sentences between packets (docs/conformance.md section 1).
pub const FOREIGN_NMEA: bool = true;
/// Whether the parser reports RTCM3 frames between packets.
pub const FOREIGN_RTCM3: bool = true;
/// Longest NMEA sentence recognised, '$' to LF (0: none).
pub const NMEA_MAX: usize = 128;
/// The parser's buffer: the longest candidate it may wait for (a packet or a foreign frame).
pub const PARSER_CAPACITY: usize = 1029;
/// Size of a field header.
pub const FIELD_HEADER_SIZE: usize = 2;
/// Offset of the length byte within a field header.
pub const FIELD_LENGTH_OFFSET: usize = 0;
/// Offset of the descriptor byte within a field header.
pub const FIELD_DESCRIPTOR_OFFSET: usize = 1;
/// Whether the field length byte counts the field header as well as the data.
pub const FIELD_LENGTH_COUNTS_HEADER: bool = true;
/// What the field length byte adds to the length of the field data.
pub const FIELD_LENGTH_ADJUST: usize = 2;
/// Length byte minus data length of field `descriptor` in a packet of set `set`:
/// [`FIELD_LENGTH_ADJUST`], except for the fields the spec marks with `length_byte_adjust`
/// (0 in this protocol).
#[inline]
pub const fn field_length_adjust(set: u8, descriptor: u8) -> isize {
    let _ = (set, descriptor);
    FIELD_LENGTH_ADJUST as isize
}
/// Largest field data a single field can carry.
pub const MAX_FIELD_DATA: usize = 253;
/// Multi-byte values are big-endian.
pub const BIG_ENDIAN: bool = true;
/// Whether sum1 is transmitted before sum2.
pub const CHECKSUM_SUM1_FIRST: bool = true;
/// Deepest parameter path of any layout in the spec (names and array indices).
pub const PATH_DEPTH: usize = 4;

// The sample rule: continuation packets of a data set grouped by their timestamp (samples.rs).
/// Data sets that group continuation packets (one sample tracker slot each).
pub const DATA_SETS: [u8; 8] = [0x80, 0x81, 0x82, 0x91, 0x92, 0x93, 0x94, 0xA0];
/// The first shared descriptor.
pub const FIRST_SHARED: u16 = 208;
/// (descriptor, data size) of the shared fields whose value identifies a sample.
pub const TIMESTAMPS: [(u8, usize); 3] = [(0xD3, 12), (0xD5, 8), (0xD7, 10)];
/// Bytes of the largest sample key.
pub const MAX_KEY: usize = 36;

/// Device time per bucket of the host clock model (ns; the spec's time.clock_model, the project's
/// own; `clock`, docs/time.md).
pub const CLOCK_BUCKET_NS: i64 = 1000000000;
/// Closed buckets the host clock model keeps.
pub const CLOCK_BUCKETS: usize = 64;
/// Closed buckets before the host clock model has an estimate.
pub const CLOCK_MIN_BUCKETS: usize = 2;
/// A larger disagreement (ns) of consecutive packets' arrival and device time steps restarts the
/// host clock model.
pub const CLOCK_RESTART_NS: i64 = 1000000000;

// Getting through to a device (the IR's `link`, docs/conformance.md section 8 "Getting through";
// per device: `Device::baud_rates`, `Device::default_baud`).
/// (set, descriptor) of set_to_idle, sent as it is: 3dm-gx5-45-dcp.txt:363, 3dm-gx5-45-dcp.txt:759, 3dm-cv7-ins-docs.txt:8043.
pub const LINK_IDLE: Option<(u8, u8)> = Some((0x01, 0x02));
/// (set, descriptor) of ping, sent as it is: 3dm-gx5-45-dcp.txt:748, 3dm-cv7-ins-docs.txt:8032.
pub const LINK_PING: Option<(u8, u8)> = Some((0x01, 0x01));
/// (set, descriptor) of resume, sent as it is: 3dm-gx5-45-dcp.txt:832, 3dm-cv7-ins-docs.txt:8099.
pub const LINK_RESUME: Option<(u8, u8)> = Some((0x01, 0x06));
/// Times the idle command is sent (each with the command's reply timeout) before giving up.
pub const LINK_IDLE_ATTEMPTS: u32 = 3;
/// Milliseconds after a baud-rate change before the device answers at the new rate (`None`: the
/// manual states none): 3dm-gx5-45-dcp.txt:1297, 3dm-cv7-ins-docs.txt:7417, 3dm-cv7-ins-docs.txt:8144.
pub const LINK_BAUD_SETTLE_MS: Option<u32> = Some(250);
/// Whether the manual gives the UART bandwidth calculation (3dm-gx5-45-dcp.txt:536, 3dm-cv7-ins-docs.txt:4099):
/// bits/s = LINK_UART_WORD_BITS * (LINK_PACKET_OVERHEAD * packets/s + sum of (field data size +
/// LINK_FIELD_OVERHEAD) * field rate).
pub const LINK_HAS_BANDWIDTH: bool = true;
/// Bits per UART word (0 without the calculation).
pub const LINK_UART_WORD_BITS: u32 = 10;
/// Bytes of packet overhead per packet: sync, header, checksum (0 without the calculation).
pub const LINK_PACKET_OVERHEAD: u32 = 6;
/// Bytes of field header per field (0 without the calculation).
pub const LINK_FIELD_OVERHEAD: u32 = 2;

// The wrong-model check (issue 39, `docs/conformance.md` section 8): after the first NACK whose
// code is an unknown-command code, a device told a model sends the identity command once and
// compares the model name it reports with that model's names (`Device::model_names`).
/// (set, descriptor of get_device_info, descriptor of its reply device_info, byte
/// offset and length of the model name in the reply's data).
pub const IDENTITY: Option<(u8, u8, u8, usize, usize)> = Some((0x01, 0x03, 0x81, 2, 16));
/// The NACK codes of a command the device does not know (the spec's `simulation.nack`
/// unknown_descriptor and unknown_set).
pub const IDENTITY_UNKNOWN_CODES: &[u32] = &[1, 6];

/// Fletcher-16 sums `(sum1, sum2)` of `bytes`: `sum1 += b; sum2 += sum1`, both modulo 256.
///
/// [`fletcher16_lanes`] where the target has vector registers the compiler can use for it (every
/// x86_64, aarch64, 32-bit x86 with SSE2 and Arm with NEON), else [`fletcher16_portable`]. Both
/// are safe code without a dependency, tested against the byte-serial definition at every length
/// and alignment.
#[inline]
pub fn fletcher16(bytes: &[u8]) -> (u8, u8) {
    if VECTOR_CHECKSUM {
        fletcher16_lanes(bytes)
    } else {
        fletcher16_portable(bytes)
    }
}

/// Whether [`fletcher16`] uses [`fletcher16_lanes`] on this target.
pub const VECTOR_CHECKSUM: bool = cfg!(any(
    target_arch = "x86_64",
    target_arch = "aarch64",
    all(target_arch = "x86", target_feature = "sse2"),
    all(target_arch = "arm", target_feature = "neon")
));

/// Fletcher-16 as one pass that the compiler vectorises (SSE2 on every x86_64, AVX2 where the
/// build enables it, NEON on aarch64): over n bytes b_0 .. b_{n-1}, sum1 = Σ b_i and sum2 =
/// Σ (n - i)·b_i = n·sum1 - Σ i·b_i, all modulo 256. The loop has no carried dependency but two
/// sums, so it runs in vector lanes (byte index, byte product and two byte sums per lane, then
/// one reduction); a byte-serial loop cannot, as every step needs the previous sum1. About twice
/// as fast as [`fletcher16_portable`] on packets of 100 bytes and more, 1.4 times on 32.
#[inline]
pub fn fletcher16_lanes(bytes: &[u8]) -> (u8, u8) {
    let (mut sum1, mut weighted) = (0u8, 0u8);
    for (i, &b) in bytes.iter().enumerate() {
        // Only i modulo 256 matters for a sum modulo 256.
        sum1 = sum1.wrapping_add(b);
        weighted = weighted.wrapping_add(b.wrapping_mul(i as u8));
    }
    let n = bytes.len() as u8;
    (sum1, n.wrapping_mul(sum1).wrapping_sub(weighted))
}

/// Fletcher-16 without vector registers (targets without them, such as Cortex-M): eight bytes at
/// a time in a `u64`.
///
/// Over blocks B_0 .. B_{K-1} of eight bytes (block sums S_k, weighted sums W_k = 8·b0 + 7·b1 +
/// … + 1·b7), starting from zero, the byte-serial recurrence gives sum1 = Σ S_k and sum2 = 8·Σ
/// (K - 1 - k)·S_k + Σ W_k. The even and odd bytes of a little-endian word are spread into four
/// 16-bit lanes and summed lane by lane: E, O = sums of the even and odd lanes, Q = sum of E + O
/// (the running sum of both) after each block; then Σ S_k = hsum(E + O), Σ (K - 1 - k)·S_k =
/// hsum(Q) - hsum(E + O), and Σ W_k comes from E and O with the lane weights (8, 6, 4, 2) and
/// (7, 5, 3, 1). Only the sums modulo 256 matter, so every lane is reduced modulo 256 (masked)
/// after each add and never carries into the next (Q + E + O is at most 3 · 255 before it is
/// masked); a multiplication by lane constants adds the lanes into the top one (at most 255 · 20)
/// without a carry from the lanes below.
#[inline]
pub fn fletcher16_portable(bytes: &[u8]) -> (u8, u8) {
    const LANES: u64 = 0x00FF_00FF_00FF_00FF;
    const ONES: u64 = 0x0001_0001_0001_0001;
    const W_EVEN: u64 = 0x0008_0006_0004_0002;
    const W_ODD: u64 = 0x0007_0005_0003_0001;
    let (mut e, mut o, mut q) = (0u64, 0u64, 0u64);
    let mut blocks = bytes.chunks_exact(8);
    let word = |block: &[u8]| {
        let mut word = [0u8; 8];
        word.copy_from_slice(block);
        u64::from_le_bytes(word)
    };
    if bytes.len() <= 8 * 64 {
        // Up to 64 blocks (every packet): E and O stay below 255 · 64 per lane, so they need
        // no reduction until the end (Q + E + O stays below 2^16).
        for block in &mut blocks {
            let x = word(block);
            e += x & LANES;
            o += (x >> 8) & LANES;
            q = (q + e + o) & LANES;
        }
        e &= LANES;
        o &= LANES;
    } else {
        for block in &mut blocks {
            let x = word(block);
            e = (e + (x & LANES)) & LANES;
            o = (o + ((x >> 8) & LANES)) & LANES;
            q = (q + e + o) & LANES;
        }
    }
    let hsum = |lanes: u64| lanes.wrapping_mul(ONES) >> 48;
    let mut sum1 = hsum(e + o);
    let mut sum2 = (hsum(q).wrapping_sub(sum1))
        .wrapping_mul(8)
        .wrapping_add(e.wrapping_mul(W_EVEN) >> 48)
        .wrapping_add(o.wrapping_mul(W_ODD) >> 48);
    for &b in blocks.remainder() {
        sum1 = sum1.wrapping_add(u64::from(b));
        sum2 = sum2.wrapping_add(sum1);
    }
    (sum1 as u8, sum2 as u8)
}

/// The checksum bytes of `bytes` (header and payload) in transmission order.
#[inline]
pub fn checksum_bytes(bytes: &[u8]) -> [u8; CHECKSUM_SIZE] {
    let (sum1, sum2) = fletcher16(bytes);
    if CHECKSUM_SUM1_FIRST {
        [sum1, sum2]
    } else {
        [sum2, sum1]
    }
}
