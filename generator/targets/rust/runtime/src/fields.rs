//! A packet's set and payload, and the field iterator (`docs/conformance.md` §2).

use core::fmt;

use crate::framing::{
    field_length_adjust, FIELD_DESCRIPTOR_OFFSET, FIELD_HEADER_SIZE, FIELD_LENGTH_OFFSET,
    HEADER_SIZE, LENGTH_OFFSET, SET_OFFSET,
};

/// A complete packet as the parser reports it (sync to checksum).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Packet<'a> {
    bytes: &'a [u8],
}

impl<'a> Packet<'a> {
    /// Wraps the bytes of a packet whose framing and checksum were checked (by the parser or
    /// the builder). Returns `None` if `bytes` is shorter than its header says.
    #[inline]
    pub fn new(bytes: &'a [u8]) -> Option<Self> {
        if bytes.len() < HEADER_SIZE
            || bytes.len() < HEADER_SIZE + usize::from(bytes[LENGTH_OFFSET])
        {
            return None;
        }
        Some(Self { bytes })
    }

    /// All bytes of the packet.
    #[inline]
    pub fn bytes(&self) -> &'a [u8] {
        self.bytes
    }

    /// Descriptor set.
    #[inline]
    pub fn set(&self) -> u8 {
        self.bytes[SET_OFFSET]
    }

    /// Payload (the fields).
    #[inline]
    pub fn payload(&self) -> &'a [u8] {
        &self.bytes[HEADER_SIZE..HEADER_SIZE + usize::from(self.bytes[LENGTH_OFFSET])]
    }

    /// The fields of the payload.
    #[inline]
    pub fn fields(&self) -> Fields<'a> {
        Fields::new(self.set(), self.payload())
    }
}

/// A framing problem in the payload; the rest of the payload becomes a trailing entry.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FramingError {
    /// Fewer bytes left than a field header.
    HeaderShort { offset: usize, left: usize },
    /// A field length smaller than the field header it counts.
    LengthShort { length: u8, offset: usize },
    /// A field that runs past the payload.
    Overrun {
        length: u8,
        offset: usize,
        left: usize,
    },
}

impl fmt::Display for FramingError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            FramingError::HeaderShort { offset, left } => {
                write!(f, "field header at payload offset {offset} needs {FIELD_HEADER_SIZE} bytes, {left} left")
            }
            FramingError::LengthShort { length, offset } => {
                write!(f, "field length {length} at payload offset {offset} is shorter than the field header")
            }
            FramingError::Overrun {
                length,
                offset,
                left,
            } => {
                write!(f, "field length {length} at payload offset {offset} overruns the payload ({left} bytes left)")
            }
        }
    }
}

/// One entry of a payload.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FieldItem<'a> {
    /// A complete field: descriptor and data (after the field header).
    Field { descriptor: u8, data: &'a [u8] },
    /// The rest of the payload after a framing problem.
    Trailing {
        bytes: &'a [u8],
        error: FramingError,
    },
}

/// Iterator over the fields of a payload.
#[derive(Clone, Debug)]
pub struct Fields<'a> {
    set: u8,
    // The payload from the next field on, and its offset in the payload.
    rest: &'a [u8],
    offset: usize,
}

impl<'a> Fields<'a> {
    /// Fields of `payload`, the payload of a packet of descriptor set `set` (the set decides
    /// irregular field lengths).
    #[inline]
    pub const fn new(set: u8, payload: &'a [u8]) -> Self {
        Self {
            set,
            rest: payload,
            offset: 0,
        }
    }
}

impl<'a> Fields<'a> {
    /// Fields of the part `rest` of a payload that starts at payload offset `offset` (at a field
    /// boundary): the offsets in framing errors count from the payload's start.
    #[inline]
    pub const fn at(set: u8, rest: &'a [u8], offset: usize) -> Self {
        Self { set, rest, offset }
    }

    /// Payload offset of the next entry.
    #[inline]
    pub fn offset(&self) -> usize {
        self.offset
    }
}

impl<'a> Iterator for Fields<'a> {
    type Item = FieldItem<'a>;

    #[inline]
    fn next(&mut self) -> Option<FieldItem<'a>> {
        let rest = self.rest;
        let offset = self.offset;
        let left = rest.len();
        if left == 0 {
            return None;
        }
        let mut trailing = |error| {
            self.rest = &[];
            self.offset += left;
            Some(FieldItem::Trailing { bytes: rest, error })
        };
        if left < FIELD_HEADER_SIZE {
            return trailing(FramingError::HeaderShort { offset, left });
        }
        let length = rest[FIELD_LENGTH_OFFSET];
        let descriptor = rest[FIELD_DESCRIPTOR_OFFSET];
        let data_len = match usize::try_from(
            isize::from(length) - field_length_adjust(self.set, descriptor),
        ) {
            Ok(n) => n,
            Err(_) => return trailing(FramingError::LengthShort { length, offset }),
        };
        let total = FIELD_HEADER_SIZE + data_len;
        if total > left {
            return trailing(FramingError::Overrun {
                length,
                offset,
                left,
            });
        }
        let (field, after) = rest.split_at(total);
        self.rest = after;
        self.offset += total;
        Some(FieldItem::Field {
            descriptor,
            data: &field[FIELD_HEADER_SIZE..],
        })
    }
}
