//! Stand-in for the generated `crate::framing` (templates/rust/framing.rs.j2): the constants of
//! a tiny protocol, chosen to differ from the real specs where the runtime must not assume them
//! (a three-byte sync, a payload limit below 255, an irregular field length, little-endian
//! values, sum2 sent first), then the Fletcher-16 half, which the back end appends verbatim.
//!
//! Packet: sync (AA 55 01), header [set, payload_length], payload, checksum.
//! Field: header [length, descriptor], then the field data.

/// Sync bytes that start every packet.
pub const SYNC: [u8; 3] = [0xAA, 0x55, 0x01];
/// Size of the packet header: the sync bytes, the set byte and the payload length byte.
pub const HEADER_SIZE: usize = 5;
/// Offset of the descriptor set byte in a packet.
pub const SET_OFFSET: usize = 3;
/// Offset of the payload length byte in a packet.
pub const LENGTH_OFFSET: usize = 4;
/// Largest payload length a packet may declare.
pub const MAX_PAYLOAD: usize = 100;
/// Size of the checksum after the payload.
pub const CHECKSUM_SIZE: usize = 2;
/// Largest packet: header, maximum payload and checksum.
pub const MAX_PACKET: usize = 107;
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
/// (1 in this protocol).
#[inline]
pub const fn field_length_adjust(set: u8, descriptor: u8) -> isize {
    if set == 0x01 && descriptor == 0x05 {
        return FIELD_LENGTH_ADJUST as isize + (-1);
    }
    FIELD_LENGTH_ADJUST as isize
}
/// Largest field data a single field can carry.
pub const MAX_FIELD_DATA: usize = 98;
/// Multi-byte values are little-endian.
pub const BIG_ENDIAN: bool = false;
/// Whether sum1 is transmitted before sum2.
pub const CHECKSUM_SUM1_FIRST: bool = false;
/// Deepest parameter path of any layout in the spec (names and array indices).
pub const PATH_DEPTH: usize = 2;

// The sample rule: continuation packets of a data set grouped by their timestamp (samples.rs).
/// Data sets that group continuation packets (one sample tracker slot each).
pub const DATA_SETS: [u8; 2] = [0x80, 0x81];
/// The first shared descriptor.
pub const FIRST_SHARED: u16 = 208;
/// (descriptor, data size) of the shared fields whose value identifies a sample.
pub const TIMESTAMPS: [(u8, usize); 1] = [(0xD3, 4)];
/// Bytes of the largest sample key.
pub const MAX_KEY: usize = 6;

include!("../src/framing_checksum.rs");
