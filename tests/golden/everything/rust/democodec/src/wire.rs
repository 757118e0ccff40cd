//! Reading and writing values on the wire (in the byte order that [`BIG_ENDIAN`] gives), the
//! [`Wire`] trait every value type implements, and the [`Layout`] trait of field layouts.

use core::fmt;

use crate::error::{DecodeError, DecodeErrorKind, EncodeError, EncodeErrorKind};
use crate::framing::BIG_ENDIAN;

/// Reads values from field data; offsets in errors are relative to the start of the data.
#[derive(Clone, Debug)]
pub struct Reader<'a> {
    data: &'a [u8],
    pos: usize,
}

impl<'a> Reader<'a> {
    /// A reader at the start of `data`.
    #[inline(always)]
    pub const fn new(data: &'a [u8]) -> Self {
        Self { data, pos: 0 }
    }

    /// Offset of the next byte.
    #[inline(always)]
    pub const fn pos(&self) -> usize {
        self.pos
    }

    /// Bytes left.
    #[inline(always)]
    pub const fn left(&self) -> usize {
        self.data.len() - self.pos
    }

    /// The next `n` bytes, or a "needs n bytes" error.
    #[inline(always)]
    pub fn take_slice(&mut self, n: usize) -> Result<&'a [u8], DecodeError> {
        if self.left() < n {
            return Err(self.short(n));
        }
        let out = &self.data[self.pos..self.pos + n];
        self.pos += n;
        Ok(out)
    }

    // Off the hot path: decoding a well-formed field never gets here.
    #[cold]
    #[inline(never)]
    fn short(&self, n: usize) -> DecodeError {
        DecodeError::new(DecodeErrorKind::Short {
            need: n,
            offset: self.pos,
            left: self.left(),
        })
    }

    /// The next `N` bytes as an array.
    #[inline(always)]
    pub fn take<const N: usize>(&mut self) -> Result<[u8; N], DecodeError> {
        let mut out = [0u8; N];
        out.copy_from_slice(self.take_slice(N)?);
        Ok(out)
    }

    /// Error if bytes are left after the last parameter.
    #[inline]
    pub fn finish(&self) -> Result<(), DecodeError> {
        if self.left() > 0 {
            return Err(DecodeError::new(DecodeErrorKind::Unexpected {
                left: self.left(),
                offset: self.pos,
            }));
        }
        Ok(())
    }
}

/// Writes values into a bounded buffer.
#[derive(Debug)]
pub struct Writer<'a> {
    buf: &'a mut [u8],
    len: usize,
}

impl<'a> Writer<'a> {
    /// A writer that may fill all of `buf`.
    pub fn new(buf: &'a mut [u8]) -> Self {
        Self { buf, len: 0 }
    }

    /// Bytes written so far.
    pub fn len(&self) -> usize {
        self.len
    }

    /// True if nothing was written.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The bytes written so far.
    pub fn written(&self) -> &[u8] {
        &self.buf[..self.len]
    }

    /// Appends `bytes`, or fails with [`EncodeErrorKind::Overflow`] (writing nothing).
    pub fn put(&mut self, bytes: &[u8]) -> Result<(), EncodeError> {
        if self.buf.len() - self.len < bytes.len() {
            return Err(EncodeError::new(EncodeErrorKind::Overflow));
        }
        self.buf[self.len..self.len + bytes.len()].copy_from_slice(bytes);
        self.len += bytes.len();
        Ok(())
    }
}

/// A value that has a wire form and a canonical JSON form.
pub trait Wire: Copy {
    /// The all-zero value (zero numbers, empty arrays, first union member).
    const ZERO: Self;
    /// Size on the wire when it does not depend on the value.
    const FIXED_SIZE: Option<usize>;
    /// Reads the value.
    fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError>;
    /// Writes the value.
    fn encode(&self, w: &mut Writer<'_>) -> Result<(), EncodeError>;
    /// Writes the canonical JSON of the value (`docs/conformance.md` §4).
    fn write_json(&self, w: &mut dyn fmt::Write) -> fmt::Result;
}

/// The layout of a field's data (a command, response, data or reserved field).
pub trait Layout: Wire {
    /// Field descriptor.
    const DESCRIPTOR: u8;
    /// Descriptor set the field belongs to; `None` for a reserved field (ack/nack), which every
    /// set of its kind answers. [`crate::builder::PacketBuilder::add`] checks it.
    const DESCRIPTOR_SET: Option<u8> = None;
    /// Field name as printed in JSON.
    const NAME: &'static str;

    /// Decodes the whole field data; bytes after the last parameter are an error.
    #[inline(always)]
    fn decode_data(data: &[u8]) -> Result<Self, DecodeError> {
        if let Some(size) = Self::FIXED_SIZE {
            if size == data.len() {
                // A fixed layout over exactly its size: every read is in bounds and nothing is
                // left, so once `decode` is inlined its length checks fold into this one.
                return Self::decode(&mut Reader::new(data));
            }
            return fixed_size_mismatch(data);
        }
        let mut r = Reader::new(data);
        let value = Self::decode(&mut r)?;
        r.finish()?;
        Ok(value)
    }

    /// Encodes the field data (without the field header).
    fn encode_data(&self, w: &mut Writer<'_>) -> Result<(), EncodeError> {
        self.encode(w)
    }
}

/// Field data whose length differs from its fixed layout's size: always an error, found by the
/// checked decode so that it is the same error (and path) as for any other layout. Out of line,
/// so that the straight-line path of [`Layout::decode_data`] stays small.
#[cold]
#[inline(never)]
fn fixed_size_mismatch<T: Wire>(data: &[u8]) -> Result<T, DecodeError> {
    let mut r = Reader::new(data);
    let value = T::decode(&mut r)?;
    r.finish()?;
    Ok(value)
}

macro_rules! wire_int {
    ($($t:ty),*) => {$(
        impl Wire for $t {
            const ZERO: Self = 0;
            const FIXED_SIZE: Option<usize> = Some(core::mem::size_of::<$t>());

            #[inline(always)]
    fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
                let bytes = r.take::<{ core::mem::size_of::<$t>() }>()?;
                Ok(if BIG_ENDIAN { <$t>::from_be_bytes(bytes) } else { <$t>::from_le_bytes(bytes) })
            }

            fn encode(&self, w: &mut Writer<'_>) -> Result<(), EncodeError> {
                w.put(&if BIG_ENDIAN { self.to_be_bytes() } else { self.to_le_bytes() })
            }

            fn write_json(&self, w: &mut dyn fmt::Write) -> fmt::Result {
                write!(w, "{}", self)
            }
        }
    )*};
}

wire_int!(u8, u16, u32, u64, i8, i16, i32, i64);

impl Wire for f32 {
    const ZERO: Self = 0.0;
    const FIXED_SIZE: Option<usize> = Some(4);

    #[inline(always)]
    fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        // From the raw bits: NaN payloads are kept.
        u32::decode(r).map(f32::from_bits)
    }

    fn encode(&self, w: &mut Writer<'_>) -> Result<(), EncodeError> {
        self.to_bits().encode(w)
    }

    fn write_json(&self, w: &mut dyn fmt::Write) -> fmt::Result {
        crate::json::write_f32(w, *self)
    }
}

impl Wire for f64 {
    const ZERO: Self = 0.0;
    const FIXED_SIZE: Option<usize> = Some(8);

    #[inline(always)]
    fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        u64::decode(r).map(f64::from_bits)
    }

    fn encode(&self, w: &mut Writer<'_>) -> Result<(), EncodeError> {
        self.to_bits().encode(w)
    }

    fn write_json(&self, w: &mut dyn fmt::Write) -> fmt::Result {
        crate::json::write_f64(w, *self)
    }
}

impl Wire for bool {
    const ZERO: Self = false;
    const FIXED_SIZE: Option<usize> = Some(1);

    #[inline(always)]
    fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        let offset = r.pos();
        match r.take::<1>()?[0] {
            0 => Ok(false),
            1 => Ok(true),
            value => Err(DecodeError::new(DecodeErrorKind::InvalidBool {
                value,
                offset,
            })),
        }
    }

    fn encode(&self, w: &mut Writer<'_>) -> Result<(), EncodeError> {
        w.put(&[u8::from(*self)])
    }

    fn write_json(&self, w: &mut dyn fmt::Write) -> fmt::Result {
        w.write_str(if *self { "true" } else { "false" })
    }
}

/// A single character (one byte, any value); JSON: a one-character string.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Char(pub u8);

impl Wire for Char {
    const ZERO: Self = Char(0);
    const FIXED_SIZE: Option<usize> = Some(1);

    #[inline(always)]
    fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        Ok(Char(r.take::<1>()?[0]))
    }

    fn encode(&self, w: &mut Writer<'_>) -> Result<(), EncodeError> {
        w.put(&[self.0])
    }

    fn write_json(&self, w: &mut dyn fmt::Write) -> fmt::Result {
        crate::json::write_str_bytes(w, &[self.0])
    }
}

/// A fixed-length string of `N` bytes, kept exactly as sent (padding included).
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Str<const N: usize>(pub [u8; N]);

impl<const N: usize> Str<N> {
    /// The string with these exact bytes.
    pub const fn new(bytes: [u8; N]) -> Self {
        Self(bytes)
    }

    /// `text` (cut to `N` bytes) followed by `pad` bytes.
    pub fn padded(text: &[u8], pad: u8) -> Self {
        let mut bytes = [pad; N];
        let n = text.len().min(N);
        bytes[..n].copy_from_slice(&text[..n]);
        Self(bytes)
    }

    /// All `N` bytes.
    pub const fn as_bytes(&self) -> &[u8; N] {
        &self.0
    }

    /// The bytes without trailing spaces and NULs (padding).
    pub fn trimmed(&self) -> &[u8] {
        let mut end = N;
        while end > 0 && (self.0[end - 1] == b' ' || self.0[end - 1] == 0) {
            end -= 1;
        }
        &self.0[..end]
    }
}

impl<const N: usize> Default for Str<N> {
    fn default() -> Self {
        Self([0; N])
    }
}

impl<const N: usize> fmt::Debug for Str<N> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "\"{}\"", self.0.escape_ascii())
    }
}

impl<const N: usize> Wire for Str<N> {
    const ZERO: Self = Self([0; N]);
    const FIXED_SIZE: Option<usize> = Some(N);

    #[inline(always)]
    fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        r.take::<N>().map(Self)
    }

    fn encode(&self, w: &mut Writer<'_>) -> Result<(), EncodeError> {
        w.put(&self.0)
    }

    fn write_json(&self, w: &mut dyn fmt::Write) -> fmt::Result {
        crate::json::write_str_bytes(w, &self.0)
    }
}

impl<T: Wire, const N: usize> Wire for [T; N] {
    const ZERO: Self = [T::ZERO; N];
    const FIXED_SIZE: Option<usize> = match T::FIXED_SIZE {
        Some(size) => Some(size * N),
        None => None,
    };

    #[inline(always)]
    fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        let mut out = [T::ZERO; N];
        for (i, slot) in out.iter_mut().enumerate() {
            *slot = T::decode(r).map_err(|e| e.index(i))?;
        }
        Ok(out)
    }

    fn encode(&self, w: &mut Writer<'_>) -> Result<(), EncodeError> {
        for (i, v) in self.iter().enumerate() {
            v.encode(w).map_err(|e| e.index(i))?;
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn fmt::Write) -> fmt::Result {
        crate::json::write_array(w, self)
    }
}

/// Tracks optional parameters while encoding: once one is absent, no later one may be present.
#[derive(Clone, Copy, Debug, Default)]
pub struct Optionals {
    absent: Option<&'static str>,
}

impl Optionals {
    /// No optional parameter seen yet.
    pub const fn new() -> Self {
        Self { absent: None }
    }

    /// Optional parameter `name` is present: error if an earlier one was absent.
    pub fn present(&self, name: &'static str) -> Result<(), EncodeError> {
        match self.absent {
            Some(earlier) => {
                Err(EncodeError::new(EncodeErrorKind::OptionalGap { later: name }).at(earlier))
            }
            None => Ok(()),
        }
    }

    /// Optional parameter `name` is absent.
    pub fn absent(&mut self, name: &'static str) {
        if self.absent.is_none() {
            self.absent = Some(name);
        }
    }
}
