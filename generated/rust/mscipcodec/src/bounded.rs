//! [`BoundedVec`]: a vector with a fixed capacity and no allocation, for counted arrays and
//! arrays that run to the end of the field (capacity = `max_count` from the IR).

use core::fmt;
use core::ops::{Deref, DerefMut};

use crate::error::{DecodeError, DecodeErrorKind, EncodeError, EncodeErrorKind};
use crate::wire::{Reader, Wire, Writer};

/// Up to `N` elements of `T`, stored inline.
#[derive(Clone, Copy)]
pub struct BoundedVec<T: Wire, const N: usize> {
    items: [T; N],
    len: usize,
}

impl<T: Wire, const N: usize> BoundedVec<T, N> {
    /// Most elements the vector can hold.
    pub const CAPACITY: usize = N;

    /// An empty vector.
    pub const fn new() -> Self {
        Self {
            items: [T::ZERO; N],
            len: 0,
        }
    }

    /// A vector holding a copy of `items`, or `None` if there are more than `N`.
    pub fn from_slice(items: &[T]) -> Option<Self> {
        if items.len() > N {
            return None;
        }
        let mut out = Self::new();
        out.items[..items.len()].copy_from_slice(items);
        out.len = items.len();
        Some(out)
    }

    /// Number of elements.
    pub const fn len(&self) -> usize {
        self.len
    }

    /// True if there are no elements.
    pub const fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// True if no more elements fit.
    pub const fn is_full(&self) -> bool {
        self.len == N
    }

    /// Appends `value`; gives it back if the vector is full.
    pub fn push(&mut self, value: T) -> Result<(), T> {
        if self.len == N {
            return Err(value);
        }
        self.items[self.len] = value;
        self.len += 1;
        Ok(())
    }

    /// Removes and returns the last element.
    pub fn pop(&mut self) -> Option<T> {
        if self.len == 0 {
            return None;
        }
        self.len -= 1;
        Some(self.items[self.len])
    }

    /// Removes every element.
    pub fn clear(&mut self) {
        self.len = 0;
    }

    /// The elements.
    pub fn as_slice(&self) -> &[T] {
        &self.items[..self.len]
    }

    /// The elements, mutable.
    pub fn as_mut_slice(&mut self) -> &mut [T] {
        &mut self.items[..self.len]
    }

    /// Reads `count` elements (a counted array).
    pub fn decode_counted(r: &mut Reader<'_>, count: u64) -> Result<Self, DecodeError> {
        if count > N as u64 {
            return Err(DecodeError::new(DecodeErrorKind::CountExceeds {
                count,
                max: N,
            }));
        }
        let mut out = Self::new();
        for i in 0..count as usize {
            out.items[i] = T::decode(r).map_err(|e| e.index(i))?;
        }
        out.len = count as usize;
        Ok(out)
    }

    /// Reads elements until the data ends (an array that runs to the end of the field).
    pub fn decode_remaining(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        if let Some(size) = T::FIXED_SIZE {
            let left = r.left();
            // `%` rather than `is_multiple_of` (Rust 1.87): the crates support Rust 1.65.
            if size > 0 && left % size != 0 {
                return Err(DecodeError::new(DecodeErrorKind::Partial {
                    left,
                    offset: r.pos(),
                    size,
                }));
            }
            if size > 0 && left / size > N {
                return Err(DecodeError::new(DecodeErrorKind::CountExceeds {
                    count: (left / size) as u64,
                    max: N,
                }));
            }
        }
        let mut out = Self::new();
        while r.left() > 0 {
            if out.len == N {
                return Err(DecodeError::new(DecodeErrorKind::CountExceeds {
                    count: N as u64 + 1,
                    max: N,
                }));
            }
            out.items[out.len] = T::decode(r).map_err(|e| e.index(out.len))?;
            out.len += 1;
        }
        Ok(out)
    }

    /// Writes the elements after checking that the count parameter equals the length.
    pub fn encode_counted(&self, w: &mut Writer<'_>, count: u64) -> Result<(), EncodeError> {
        if count != self.len as u64 {
            return Err(EncodeError::new(EncodeErrorKind::CountMismatch {
                count,
                len: self.len,
            }));
        }
        self.encode(w)
    }
}

impl<T: Wire, const N: usize> Default for BoundedVec<T, N> {
    fn default() -> Self {
        Self::new()
    }
}

impl<T: Wire, const N: usize> Deref for BoundedVec<T, N> {
    type Target = [T];

    fn deref(&self) -> &[T] {
        self.as_slice()
    }
}

impl<T: Wire, const N: usize> DerefMut for BoundedVec<T, N> {
    fn deref_mut(&mut self) -> &mut [T] {
        self.as_mut_slice()
    }
}

impl<T: Wire + PartialEq, const N: usize> PartialEq for BoundedVec<T, N> {
    fn eq(&self, other: &Self) -> bool {
        self.as_slice() == other.as_slice()
    }
}

impl<T: Wire + fmt::Debug, const N: usize> fmt::Debug for BoundedVec<T, N> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_list().entries(self.as_slice()).finish()
    }
}

impl<T: Wire, const N: usize> Wire for BoundedVec<T, N> {
    const ZERO: Self = Self::new();
    const FIXED_SIZE: Option<usize> = None;

    /// Reads elements until the data ends.
    fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        Self::decode_remaining(r)
    }

    fn encode(&self, w: &mut Writer<'_>) -> Result<(), EncodeError> {
        for (i, v) in self.as_slice().iter().enumerate() {
            v.encode(w).map_err(|e| e.index(i))?;
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn fmt::Write) -> fmt::Result {
        crate::json::write_array(w, self.as_slice())
    }
}
