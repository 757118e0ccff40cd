//! Straight-line packet decoders and the layout cache (issue 38; the same design as the C and
//! C++ packages').
//!
//! Each data set's module has a `Packet` (one member per field of the set with one layout: its
//! own fields and the shared data fields) and a `decode_packet(payload, &mut Packet, other)`
//! that walks the payload's field headers in place, matches the descriptor and decodes the
//! field's layout straight into its member: no [`FieldValue`](crate::FieldValue), no indirect
//! call. Every other entry goes to `other`, in packet order: a descriptor without a member
//! (undefined, or a field with per-device layouts), a field that does not decode (its member is
//! then unspecified), a second field with a descriptor already decoded, trailing bytes.
//! [`decode_packet`] picks the set of a whole packet; [`LayoutCache`] remembers the shapes of
//! the last packets of a stream and decodes a packet of a known shape without the header walk.
//! Nothing allocates; everything here is available without `std`, and each set's decoder only
//! with its set in the build (the cargo features `set-*`).

#![cfg_attr(
    feature = "select-sets",
    allow(dead_code, unused_imports, unused_variables, unused_mut)
)]

use crate::fields::{FieldItem, Fields, Packet as Framed};
use crate::framing::{
    field_length_adjust, FIELD_DESCRIPTOR_OFFSET, FIELD_HEADER_SIZE, FIELD_LENGTH_OFFSET,
    MAX_PAYLOAD,
};
use crate::wire::{Layout, Reader, Wire};

/// Most fields a packet can hold (each has at least a field header).
pub const PACKET_FIELDS_MAX: usize = MAX_PAYLOAD / FIELD_HEADER_SIZE;

/// What a straight-line decoder decoded, the first member of every set's `Packet`: the
/// descriptors of the fields decoded into their members, in packet order, and a bit per
/// descriptor.
#[derive(Clone, Debug)]
pub struct PacketIndex {
    present: [u32; 8],
    count: usize,
    descriptors: [u8; PACKET_FIELDS_MAX],
}

impl PacketIndex {
    /// No field decoded.
    pub const EMPTY: Self = Self {
        present: [0; 8],
        count: 0,
        descriptors: [0; PACKET_FIELDS_MAX],
    };

    /// The descriptors of the fields decoded into members, in packet order.
    #[inline]
    pub fn descriptors(&self) -> &[u8] {
        &self.descriptors[..self.count]
    }

    /// Number of fields decoded into members.
    #[inline]
    pub fn len(&self) -> usize {
        self.count
    }

    /// True when no field was decoded into a member.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.count == 0
    }

    /// True when field `descriptor` was decoded into its member.
    #[inline]
    pub fn contains(&self, descriptor: u8) -> bool {
        self.present[usize::from(descriptor >> 5)] & (1u32 << (descriptor & 31)) != 0
    }

    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn clear(&mut self) {
        self.present = [0; 8];
        self.count = 0;
    }

    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn push(&mut self, descriptor: u8) {
        self.present[usize::from(descriptor >> 5)] |= 1u32 << (descriptor & 31);
        // Each field has a header: a packet never holds more than PACKET_FIELDS_MAX.
        if let Some(slot) = self.descriptors.get_mut(self.count) {
            *slot = descriptor;
            self.count += 1;
        }
    }
}

impl Default for PacketIndex {
    fn default() -> Self {
        Self::EMPTY
    }
}

impl PartialEq for PacketIndex {
    fn eq(&self, other: &Self) -> bool {
        self.present == other.present && self.descriptors() == other.descriptors()
    }
}

impl Eq for PacketIndex {}

/// The packet of one data set (its module's `Packet`), as the decoders here use it.
pub trait SetPacket {
    /// The descriptor set.
    const SET: u8;
    /// What was decoded.
    fn index(&self) -> &PacketIndex;
    /// What was decoded, to fill.
    fn index_mut(&mut self) -> &mut PacketIndex;
    /// True when field `descriptor` has a member.
    fn has_member(descriptor: u8) -> bool;
    /// Decodes `data`, the data of field `descriptor`, into its member; false when the field
    /// has no member or does not decode.
    fn decode_member(&mut self, descriptor: u8, data: &[u8]) -> bool;
    /// The decoded field `descriptor` as [`decode_field`](crate::decode_field) gives it, when
    /// the index holds it.
    fn field(&self, descriptor: u8) -> Option<crate::FieldValue>;
}

/// Decodes `data` as layout `L` into `slot`; false (slot unchanged) when it does not decode.
/// A fixed layout over exactly its size is a sequence of loads at constant offsets once this is
/// inlined (the length test folds the reader's bounds checks).
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline)]
pub(crate) fn decode_into<L: Layout>(data: &[u8], slot: &mut L) -> bool {
    match L::decode_data(data) {
        Ok(value) => {
            *slot = value;
            true
        }
        Err(_) => false,
    }
}

/// One plain value (a number, enum, bitfield, bool) at offset `at` of a fixed layout's data, for
/// the generated fast loads (the caller checked the length, and the bytes of bools).
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline)]
pub(crate) fn ld<T: Wire>(d: &[u8], at: usize) -> T {
    match d.get(at..) {
        Some(rest) => T::decode(&mut Reader::new(rest)).unwrap_or(T::ZERO),
        None => T::ZERO,
    }
}

/// The straight-line decoder of a packet of set `P::SET` (each set's `decode_packet`).
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline)]
pub(crate) fn decode_set_packet<P: SetPacket>(
    payload: &[u8],
    out: &mut P,
    mut other: impl FnMut(FieldItem<'_>),
) -> usize {
    let index = out.index_mut();
    index.clear();
    let mut pos = 0;
    // The field headers read in place (the iterator's entry is built only for trailing bytes).
    while payload.len() - pos >= FIELD_HEADER_SIZE {
        let head = &payload[pos..];
        let descriptor = head[FIELD_DESCRIPTOR_OFFSET];
        let Ok(data_len) = usize::try_from(
            isize::from(head[FIELD_LENGTH_OFFSET]) - field_length_adjust(P::SET, descriptor),
        ) else {
            break;
        };
        let Some(data) = head.get(FIELD_HEADER_SIZE..FIELD_HEADER_SIZE + data_len) else {
            break;
        };
        if !out.index().contains(descriptor) && out.decode_member(descriptor, data) {
            out.index_mut().push(descriptor);
        } else {
            other(FieldItem::Field { descriptor, data });
        }
        pos += FIELD_HEADER_SIZE + data_len;
    }
    if pos < payload.len() {
        if let Some(item) = Fields::at(P::SET, &payload[pos..], pos).next() {
            other(item);
        }
    }
    out.index().len()
}

/// A packet of any data set, decoded by its set's straight-line decoder ([`decode_packet`],
/// [`LayoutCache::decode`]): one `Packet` per data set in the build (not a union: a stream that
/// alternates sets does not reset a member each time), and the set of the last packet.
#[derive(Clone, Debug, Default)]
pub struct AnyPacket {
    set: Option<u8>,
    /// The last packet of set 0xA2.
    #[cfg(any(feature = "set-imu-data", not(feature = "select-sets")))]
    pub imu_data: crate::imu_data::Packet,
}

impl AnyPacket {
    /// Nothing decoded yet.
    pub const ZERO: Self = Self {
        set: None,
        #[cfg(any(feature = "set-imu-data", not(feature = "select-sets")))]
        imu_data: crate::imu_data::Packet::ZERO,
    };

    /// The set of the last packet decoded into it (`None`: none yet, or bytes that were not a
    /// packet).
    #[inline]
    pub fn set(&self) -> Option<u8> {
        self.set
    }

    /// What the last packet decoded into it: `None` when its set has no straight-line decoder
    /// (not a data set, or not in the build), and every entry went to `other`.
    #[inline]
    pub fn index(&self) -> Option<&PacketIndex> {
        match self.set {
            #[cfg(any(feature = "set-imu-data", not(feature = "select-sets")))]
            Some(0xA2) => Some(self.imu_data.index()),
            _ => None,
        }
    }

    /// Field `descriptor` of the last packet, as [`decode_field`](crate::decode_field) gives it,
    /// when it was decoded into its member.
    pub fn field(&self, descriptor: u8) -> Option<crate::FieldValue> {
        match self.set {
            #[cfg(any(feature = "set-imu-data", not(feature = "select-sets")))]
            Some(0xA2) => self.imu_data.field(descriptor),
            _ => None,
        }
    }

    /// True when field `descriptor` of the last packet's set has a member.
    pub fn has_member(&self, descriptor: u8) -> bool {
        match self.set {
            #[cfg(any(feature = "set-imu-data", not(feature = "select-sets")))]
            Some(0xA2) => <crate::imu_data::Packet as SetPacket>::has_member(descriptor),
            _ => false,
        }
    }
}

/// Decodes `packet` (a whole packet as the parser reports it, sync to checksum) with its set's
/// straight-line decoder into that set's member of `out`, and returns the number of fields
/// decoded into members; the entries it leaves go to `other`, in packet order. A packet of a set
/// without one (not a data set, or not in the build): every entry goes to `other`, 0. Bytes that
/// are not a packet (shorter than their header says): nothing, 0.
#[inline]
pub fn decode_packet(
    packet: &[u8],
    out: &mut AnyPacket,
    mut other: impl FnMut(FieldItem<'_>),
) -> usize {
    let Some(framed) = Framed::new(packet) else {
        out.set = None;
        return 0;
    };
    let set = framed.set();
    let payload = framed.payload();
    out.set = Some(set);
    match set {
        #[cfg(any(feature = "set-imu-data", not(feature = "select-sets")))]
        0xA2 => crate::imu_data::decode_packet(payload, &mut out.imu_data, other),
        _ => {
            for item in framed.fields() {
                other(item);
            }
            0
        }
    }
}

/// Shapes a [`LayoutCache`] remembers.
pub const LAYOUT_CACHE_SHAPES: usize = 4;

/// One field of a shape: where its header is, the header's bytes, its data and whether it has
/// a member.
#[derive(Clone, Copy, Debug)]
struct ShapeField {
    offset: u16,
    data_len: u16,
    head: [u8; FIELD_HEADER_SIZE],
    descriptor: u8,
    member: bool,
}

impl ShapeField {
    const ZERO: Self = Self {
        offset: 0,
        data_len: 0,
        head: [0; FIELD_HEADER_SIZE],
        descriptor: 0,
        member: false,
    };
}

/// The shape of a packet: its set, its payload's length and its field headers, with what the
/// straight-line decoder did with each field (decoded into its member, or to `other`).
#[derive(Clone, Debug)]
struct Shape {
    valid: bool,
    set: u8,
    len: u16,
    count: usize,
    has_other: bool,
    fields: [ShapeField; PACKET_FIELDS_MAX],
    index: PacketIndex,
}

impl Shape {
    const ZERO: Self = Self {
        valid: false,
        set: 0,
        len: 0,
        count: 0,
        has_other: false,
        fields: [ShapeField::ZERO; PACKET_FIELDS_MAX],
        index: PacketIndex::EMPTY,
    };

    /// True when `payload` of set `set` has this shape's set and length (its field headers are
    /// compared by [`Shape::decode`]).
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn matches(&self, set: u8, payload: &[u8]) -> bool {
        self.valid && self.set == set && usize::from(self.len) == payload.len()
    }

    /// Decodes `payload` (of this shape's set and length) into `out` with the shape's offsets,
    /// comparing each field header with the shape's as it goes; false, with nothing given to
    /// `other` and `out`'s index unspecified, when a header differs or a member does not decode
    /// (the caller then decodes the packet with the straight-line decoder).
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode<P: SetPacket>(
        &self,
        payload: &[u8],
        out: &mut P,
        other: &mut impl FnMut(FieldItem<'_>),
    ) -> bool {
        let fields = &self.fields[..self.count];
        for f in fields {
            let at = usize::from(f.offset);
            let Some(field) = payload.get(at..at + FIELD_HEADER_SIZE + usize::from(f.data_len))
            else {
                return false;
            };
            let (head, data) = field.split_at(FIELD_HEADER_SIZE);
            if head != f.head || (f.member && !out.decode_member(f.descriptor, data)) {
                return false;
            }
        }
        let index = out.index_mut();
        index.present = self.index.present;
        index.count = self.index.count;
        index.descriptors = self.index.descriptors;
        if self.has_other {
            for f in fields.iter().filter(|f| !f.member) {
                let at = usize::from(f.offset) + FIELD_HEADER_SIZE;
                if let Some(data) = payload.get(at..at + usize::from(f.data_len)) {
                    other(FieldItem::Field {
                        descriptor: f.descriptor,
                        data,
                    });
                }
            }
        }
        true
    }

    /// Records the shape of `payload` of set `P::SET` as the straight-line decoder decoded it
    /// into `out`; false (nothing recorded) when the shape does not decide what the decoder does
    /// (trailing bytes, or a field with a member that did not decode).
    fn record<P: SetPacket>(&mut self, payload: &[u8], out: &P) -> bool {
        self.valid = false;
        let Ok(len) = u16::try_from(payload.len()) else {
            return false;
        };
        let mut fields = Fields::new(P::SET, payload);
        let mut taken = PacketIndex::EMPTY;
        let mut count = 0;
        let mut has_other = false;
        loop {
            let offset = fields.offset();
            let Some(item) = fields.next() else {
                break;
            };
            let FieldItem::Field { descriptor, data } = item else {
                return false;
            };
            let member = out.index().contains(descriptor) && !taken.contains(descriptor);
            if member {
                taken.push(descriptor);
            } else if !taken.contains(descriptor) && P::has_member(descriptor) {
                return false; // did not decode: depends on the data, not on the shape
            }
            let (Ok(offset), Ok(data_len)) = (u16::try_from(offset), u16::try_from(data.len()))
            else {
                return false;
            };
            let mut head = [0; FIELD_HEADER_SIZE];
            head.copy_from_slice(
                &payload[usize::from(offset)..usize::from(offset) + FIELD_HEADER_SIZE],
            );
            let Some(slot) = self.fields.get_mut(count) else {
                return false;
            };
            *slot = ShapeField {
                offset,
                data_len,
                head,
                descriptor,
                member,
            };
            has_other |= !member;
            count += 1;
        }
        self.set = P::SET;
        self.len = len;
        self.count = count;
        self.has_other = has_other;
        self.index.clone_from(out.index());
        self.valid = true;
        true
    }
}

/// Remembers the shapes ([`LAYOUT_CACHE_SHAPES`]) of the last packets of a stream: (set, payload
/// length, the field headers at their offsets). A packet of a remembered shape is decoded with
/// that shape's offsets and members, without the per-field header walk; any other packet goes to
/// the straight-line decoder, and its shape replaces the oldest (round robin). The result is the
/// straight-line decoder's, always. Fixed arrays, no allocation.
#[derive(Clone, Debug)]
pub struct LayoutCache {
    shapes: [Shape; LAYOUT_CACHE_SHAPES],
    last: usize,
    next: usize,
}

impl Default for LayoutCache {
    fn default() -> Self {
        Self::new()
    }
}

impl LayoutCache {
    /// An empty cache.
    pub const fn new() -> Self {
        Self {
            shapes: [Shape::ZERO, Shape::ZERO, Shape::ZERO, Shape::ZERO],
            last: 0,
            next: 0,
        }
    }

    /// [`decode_packet`] through the cache: the same result, the same entries to `other`.
    #[inline]
    pub fn decode(
        &mut self,
        packet: &[u8],
        out: &mut AnyPacket,
        mut other: impl FnMut(FieldItem<'_>),
    ) -> usize {
        let Some(framed) = Framed::new(packet) else {
            out.set = None;
            return 0;
        };
        let set = framed.set();
        let payload = framed.payload();
        out.set = Some(set);
        match set {
            #[cfg(any(feature = "set-imu-data", not(feature = "select-sets")))]
            0xA2 => self.decode_set(payload, &mut out.imu_data, &mut other),
            _ => {
                for item in framed.fields() {
                    other(item);
                }
                0
            }
        }
    }

    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode_set<P: SetPacket>(
        &mut self,
        payload: &[u8],
        out: &mut P,
        other: &mut impl FnMut(FieldItem<'_>),
    ) -> usize {
        // The shape of the last packet first: a stream repeats its packets.
        let last = self.last;
        if self.shapes[last].matches(P::SET, payload) {
            if self.shapes[last].decode(payload, out, other) {
                return self.shapes[last].index.len();
            }
            return decode_set_packet(payload, out, other);
        }
        self.decode_other_shape(payload, out, other)
    }

    /// Any other remembered shape, else the straight-line decoder (and the shape recorded).
    #[inline(never)]
    fn decode_other_shape<P: SetPacket>(
        &mut self,
        payload: &[u8],
        out: &mut P,
        other: &mut impl FnMut(FieldItem<'_>),
    ) -> usize {
        for i in 0..LAYOUT_CACHE_SHAPES {
            if i != self.last && self.shapes[i].matches(P::SET, payload) {
                self.last = i;
                if self.shapes[i].decode(payload, out, other) {
                    return self.shapes[i].index.len();
                }
                return decode_set_packet(payload, out, other);
            }
        }
        let n = decode_set_packet(payload, out, other);
        let slot = self.next;
        if self.shapes[slot].record(payload, out) {
            self.last = slot;
            self.next = (slot + 1) % LAYOUT_CACHE_SHAPES;
        }
        n
    }
}
