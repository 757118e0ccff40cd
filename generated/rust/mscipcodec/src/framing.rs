//! Framing of the Memsense MS-CIP protocol, rendered from `ir.json` → `protocols[].framing`, and the
//! Fletcher-16 checksum.
//!
//! Packet: sync (A5 A5), header [set, payload_length], payload, checksum.
//! Field: header [descriptor, length], then the field data.

/// Sync bytes that start every packet.
pub const SYNC: [u8; 2] = [0xA5, 0xA5];
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
/// Size of a field header.
pub const FIELD_HEADER_SIZE: usize = 2;
/// Offset of the length byte within a field header.
pub const FIELD_LENGTH_OFFSET: usize = 1;
/// Offset of the descriptor byte within a field header.
pub const FIELD_DESCRIPTOR_OFFSET: usize = 0;
/// Whether the field length byte counts the field header as well as the data.
pub const FIELD_LENGTH_COUNTS_HEADER: bool = false;
/// What the field length byte adds to the length of the field data.
pub const FIELD_LENGTH_ADJUST: usize = 0;
/// Length byte minus data length of field `descriptor` in a packet of set `set`:
/// [`FIELD_LENGTH_ADJUST`], except for the fields the spec marks with `length_byte_adjust`
/// (1 in this protocol).
#[inline]
pub const fn field_length_adjust(set: u8, descriptor: u8) -> isize {
    if set == 0x02 && descriptor == 0x05 {
        return FIELD_LENGTH_ADJUST as isize + (-1);
    }
    FIELD_LENGTH_ADJUST as isize
}
/// Largest field data a single field can carry.
pub const MAX_FIELD_DATA: usize = 253;
/// Multi-byte values are big-endian.
pub const BIG_ENDIAN: bool = true;
/// Whether sum1 is transmitted before sum2.
pub const CHECKSUM_SUM1_FIRST: bool = true;

/// Fletcher-16 sums `(sum1, sum2)` of `bytes`: `sum1 += b; sum2 += sum1`, both modulo 256.
pub fn fletcher16(bytes: &[u8]) -> (u8, u8) {
    let mut sum1: u8 = 0;
    let mut sum2: u8 = 0;
    for &b in bytes {
        sum1 = sum1.wrapping_add(b);
        sum2 = sum2.wrapping_add(sum1);
    }
    (sum1, sum2)
}

/// The checksum bytes of `bytes` (header and payload) in transmission order.
pub fn checksum_bytes(bytes: &[u8]) -> [u8; CHECKSUM_SIZE] {
    let (sum1, sum2) = fletcher16(bytes);
    if CHECKSUM_SUM1_FIRST {
        [sum1, sum2]
    } else {
        [sum2, sum1]
    }
}
