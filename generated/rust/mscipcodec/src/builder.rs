//! Packet builder: appends fields (header + data) to a bounded buffer, then fills in the
//! payload length and the checksum.

use crate::error::{EncodeError, EncodeErrorKind};
use crate::framing::{
    checksum_bytes, field_length_adjust, CHECKSUM_SIZE, FIELD_DESCRIPTOR_OFFSET, FIELD_HEADER_SIZE,
    FIELD_LENGTH_OFFSET, FIRST_SHARED, HEADER_SIZE, LENGTH_OFFSET, MAX_FIELD_DATA, MAX_PACKET,
    MAX_PAYLOAD, SET_OFFSET, SYNC,
};
use crate::wire::{Layout, Writer};

/// Builds one packet.
#[derive(Clone)]
pub struct PacketBuilder {
    buf: [u8; MAX_PACKET],
    len: usize,
}

impl PacketBuilder {
    /// An empty packet for descriptor set `set`.
    pub fn new(set: u8) -> Self {
        let mut buf = [0u8; MAX_PACKET];
        buf[..SYNC.len()].copy_from_slice(&SYNC);
        buf[SET_OFFSET] = set;
        Self {
            buf,
            len: HEADER_SIZE,
        }
    }

    /// Descriptor set of the packet.
    pub fn set(&self) -> u8 {
        self.buf[SET_OFFSET]
    }

    /// Payload bytes so far.
    pub fn payload_len(&self) -> usize {
        self.len - HEADER_SIZE
    }

    /// Appends a field whose data `encode` writes. On error nothing is appended.
    pub fn add_field_with<F>(&mut self, descriptor: u8, encode: F) -> Result<(), EncodeError>
    where
        F: FnOnce(&mut Writer<'_>) -> Result<(), EncodeError>,
    {
        let start = self.len;
        let payload_end = HEADER_SIZE + MAX_PAYLOAD;
        if payload_end - start < FIELD_HEADER_SIZE {
            return Err(EncodeError::new(EncodeErrorKind::Overflow));
        }
        let data_start = start + FIELD_HEADER_SIZE;
        let data_end = payload_end.min(data_start + MAX_FIELD_DATA);
        let mut w = Writer::new(&mut self.buf[data_start..data_end]);
        encode(&mut w)?;
        let data_len = w.len();
        let length = data_len as isize + field_length_adjust(self.set(), descriptor);
        if length > 0xFF {
            return Err(EncodeError::new(EncodeErrorKind::Overflow));
        }
        if length < 0 {
            return Err(EncodeError::new(EncodeErrorKind::TooShort { data_len }));
        }
        self.buf[start + FIELD_LENGTH_OFFSET] = length as u8;
        self.buf[start + FIELD_DESCRIPTOR_OFFSET] = descriptor;
        self.len = data_start + data_len;
        Ok(())
    }

    /// Appends a field with raw data.
    pub fn add_raw_field(&mut self, descriptor: u8, data: &[u8]) -> Result<(), EncodeError> {
        self.add_field_with(descriptor, |w| w.put(data))
    }

    /// Appends a typed field. A layout of another descriptor set than the packet's fails with
    /// [`EncodeErrorKind::WrongSet`] (its descriptor means another field there); shared data
    /// fields (descriptor at or above [`FIRST_SHARED`]) go in any set, reserved fields (no
    /// [`Layout::DESCRIPTOR_SET`]) too.
    pub fn add<L: Layout>(&mut self, value: &L) -> Result<(), EncodeError> {
        if let Some(field_set) = L::DESCRIPTOR_SET {
            if field_set != self.set() && u16::from(L::DESCRIPTOR) < FIRST_SHARED {
                return Err(EncodeError::new(EncodeErrorKind::WrongSet {
                    field_set,
                    packet_set: self.set(),
                }));
            }
        }
        self.add_field_with(L::DESCRIPTOR, |w| value.encode_data(w))
    }

    /// Appends raw payload bytes (no field header), e.g. a trailing entry.
    pub fn add_bytes(&mut self, bytes: &[u8]) -> Result<(), EncodeError> {
        if HEADER_SIZE + MAX_PAYLOAD - self.len < bytes.len() {
            return Err(EncodeError::new(EncodeErrorKind::Overflow));
        }
        self.buf[self.len..self.len + bytes.len()].copy_from_slice(bytes);
        self.len += bytes.len();
        Ok(())
    }

    /// Fills in the payload length and checksum; returns the packet bytes.
    pub fn finish(&mut self) -> &[u8] {
        self.buf[LENGTH_OFFSET] = (self.len - HEADER_SIZE) as u8;
        let sum = checksum_bytes(&self.buf[..self.len]);
        self.buf[self.len..self.len + CHECKSUM_SIZE].copy_from_slice(&sum);
        &self.buf[..self.len + CHECKSUM_SIZE]
    }
}
