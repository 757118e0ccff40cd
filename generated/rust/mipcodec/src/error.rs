//! Decode and encode errors. A decode error formats as the exact message of
//! `docs/conformance.md` §3, with the parameter path (`info.model_name`, `descriptors[3]`).

use core::fmt;

/// Deepest parameter path of any layout in the spec (names and array indices).
pub use crate::framing::PATH_DEPTH;

/// One step of a parameter path.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Segment {
    /// A parameter or struct member name.
    Name(&'static str),
    /// An array element.
    Index(u32),
}

/// Path of the value an error is about, built while the error travels up from the value.
#[derive(Clone, Copy, PartialEq, Eq)]
pub struct Path {
    // Innermost segment first.
    segs: [Segment; PATH_DEPTH],
    len: usize,
}

impl Path {
    /// The empty path (errors about the whole field).
    pub const EMPTY: Self = Self {
        segs: [Segment::Index(0); PATH_DEPTH],
        len: 0,
    };

    /// Number of segments.
    pub fn len(&self) -> usize {
        self.len
    }

    /// True for the empty path.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Segments from the outermost (the parameter) to the innermost.
    pub fn segments(&self) -> impl Iterator<Item = Segment> + '_ {
        self.segs[..self.len].iter().rev().copied()
    }

    fn push(&mut self, seg: Segment) {
        if self.len < PATH_DEPTH {
            self.segs[self.len] = seg;
            self.len += 1;
        }
    }
}

impl fmt::Display for Path {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, seg) in self.segments().enumerate() {
            match seg {
                Segment::Name(name) => {
                    if i > 0 {
                        f.write_str(".")?;
                    }
                    f.write_str(name)?;
                }
                Segment::Index(k) => write!(f, "[{k}]")?,
            }
        }
        Ok(())
    }
}

impl fmt::Debug for Path {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "\"{self}\"")
    }
}

/// What went wrong while decoding field data.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DecodeErrorKind {
    /// Not enough bytes for a value of `need` bytes at `offset`; `left` bytes were left.
    Short {
        need: usize,
        offset: usize,
        left: usize,
    },
    /// A counted array is longer than the layout allows.
    CountExceeds { count: u64, max: usize },
    /// An array that runs to the end of the data has a partial element.
    Partial {
        left: usize,
        offset: usize,
        size: usize,
    },
    /// A bool byte that is neither 0 nor 1.
    InvalidBool { value: u8, offset: usize },
    /// A union selector value without a member.
    NoMember { value: i128 },
    /// Bytes left after the last parameter.
    Unexpected { left: usize, offset: usize },
    /// The packet's descriptor set is not defined (and no reserved or shared field applies).
    UnknownSet,
    /// The set is defined but has no field with this descriptor.
    UnknownDescriptor,
}

/// A decode error: what went wrong and the path of the value.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DecodeError {
    pub kind: DecodeErrorKind,
    pub path: Path,
}

impl DecodeError {
    /// An error about the whole field (empty path).
    pub const fn new(kind: DecodeErrorKind) -> Self {
        Self {
            kind,
            path: Path::EMPTY,
        }
    }

    /// The error happened inside the parameter or member `name`.
    #[cold]
    pub fn at(mut self, name: &'static str) -> Self {
        self.path.push(Segment::Name(name));
        self
    }

    /// The error happened inside array element `index`.
    #[cold]
    pub fn index(mut self, index: usize) -> Self {
        self.path.push(Segment::Index(index as u32));
        self
    }
}

impl fmt::Display for DecodeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if !self.path.is_empty() {
            write!(f, "{}: ", self.path)?;
        }
        match self.kind {
            DecodeErrorKind::Short { need, offset, left } => {
                write!(f, "needs {need} bytes at offset {offset}, {left} left")
            }
            DecodeErrorKind::CountExceeds { count, max } => {
                write!(f, "count {count} exceeds maximum {max}")
            }
            DecodeErrorKind::Partial { left, offset, size } => {
                write!(
                    f,
                    "{left} bytes left at offset {offset}, not a multiple of {size}"
                )
            }
            DecodeErrorKind::InvalidBool { value, offset } => {
                write!(f, "invalid bool value {value} at offset {offset}")
            }
            DecodeErrorKind::NoMember { value } => {
                write!(f, "no member for selector value {value}")
            }
            DecodeErrorKind::Unexpected { left, offset } => {
                write!(f, "{left} unexpected bytes at offset {offset}")
            }
            DecodeErrorKind::UnknownSet => f.write_str("unknown descriptor set"),
            DecodeErrorKind::UnknownDescriptor => f.write_str("unknown descriptor"),
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for DecodeError {}

/// What went wrong while encoding a value.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EncodeErrorKind {
    /// The data does not fit in the field or the packet.
    Overflow,
    /// A counted array's length differs from its count parameter.
    CountMismatch { count: u64, len: usize },
    /// A union value is not the member its selector chooses.
    UnionMismatch { value: i128 },
    /// A union selector value without a member.
    NoMember { value: i128 },
    /// An optional parameter is absent but a later one is present.
    OptionalGap { later: &'static str },
    /// Field data shorter than an irregular field's size byte allows (`length_byte_adjust`).
    TooShort { data_len: usize },
    /// A typed field of another descriptor set than the packet's: its descriptor would mean
    /// another field there.
    WrongSet { field_set: u8, packet_set: u8 },
}

/// An encode error: what went wrong and the path of the value.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EncodeError {
    pub kind: EncodeErrorKind,
    pub path: Path,
}

impl EncodeError {
    /// An error about the whole field (empty path).
    pub const fn new(kind: EncodeErrorKind) -> Self {
        Self {
            kind,
            path: Path::EMPTY,
        }
    }

    /// The error happened inside the parameter or member `name`.
    #[cold]
    pub fn at(mut self, name: &'static str) -> Self {
        self.path.push(Segment::Name(name));
        self
    }

    /// The error happened inside array element `index`.
    #[cold]
    pub fn index(mut self, index: usize) -> Self {
        self.path.push(Segment::Index(index as u32));
        self
    }
}

impl fmt::Display for EncodeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if !self.path.is_empty() {
            write!(f, "{}: ", self.path)?;
        }
        match self.kind {
            EncodeErrorKind::Overflow => write!(
                f,
                "does not fit in a packet (at most {} bytes of field data, {} bytes of payload)",
                crate::framing::MAX_FIELD_DATA,
                crate::framing::MAX_PAYLOAD
            ),
            EncodeErrorKind::CountMismatch { count, len } => {
                write!(
                    f,
                    "the count parameter says {count} but the array has {len} elements"
                )
            }
            EncodeErrorKind::UnionMismatch { value } => {
                write!(f, "union member does not match the selector value {value}")
            }
            EncodeErrorKind::NoMember { value } => {
                write!(f, "no member for selector value {value}")
            }
            EncodeErrorKind::TooShort { data_len } => {
                write!(
                    f,
                    "field data of {data_len} bytes is too short for its size byte"
                )
            }
            EncodeErrorKind::WrongSet {
                field_set,
                packet_set,
            } => {
                write!(
                    f,
                    "a field of descriptor set 0x{field_set:02x} cannot go in a packet of set 0x{packet_set:02x}"
                )
            }
            EncodeErrorKind::OptionalGap { later } => {
                write!(
                    f,
                    "absent, but the later optional parameter {later} is present"
                )
            }
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for EncodeError {}
