//! Receiver 2.
//!
//! Descriptor set 0x92 (data set):
//! one struct per field layout, and `SetField`, the enum of all its fields.

/// Descriptor set of this module.
pub const SET: u8 = 0x92;

/// LLH position.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LlhPosition {
    /// Units: deg.
    pub latitude: f64,
    /// Units: deg.
    pub longitude: f64,
    pub valid_flags: u16,
}

impl Default for LlhPosition {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for LlhPosition {
    const ZERO: Self = Self {
        latitude: <f64 as crate::wire::Wire>::ZERO,
        longitude: <f64 as crate::wire::Wire>::ZERO,
        valid_flags: <u16 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(18);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_latitude = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("latitude"))?;
        let p_longitude = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("longitude"))?;
        let p_valid_flags =
            <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            latitude: p_latitude,
            longitude: p_longitude,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.latitude;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("latitude"))?;
        let v = &self.longitude;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("longitude"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.latitude;
        crate::json::key(w, &mut first, "latitude")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.longitude;
        crate::json::key(w, &mut first, "longitude")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for LlhPosition {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["latitude", "longitude", "valid_flags"])?;
        let p_latitude = o.req("latitude", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_longitude = o.req("longitude", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_valid_flags = o.req(
            "valid_flags",
            <u16 as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            latitude: p_latitude,
            longitude: p_longitude,
            valid_flags: p_valid_flags,
        })
    }
}

impl LlhPosition {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x92;
}

impl crate::wire::Layout for LlhPosition {
    const DESCRIPTOR: u8 = 0x03;
    const DESCRIPTOR_SET: Option<u8> = Some(0x92);
    const NAME: &'static str = "llh_position";
}

/// A decoded field of set 0x92 (`receiver_2`).
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SetField {
    /// `llh_position` (0x03).
    LlhPosition(LlhPosition),
}

impl SetField {
    /// Field descriptor.
    pub fn descriptor(&self) -> u8 {
        match self {
            Self::LlhPosition(_) => 0x03,
        }
    }

    /// Field name as printed in JSON.
    pub fn name(&self) -> &'static str {
        match self {
            Self::LlhPosition(_) => "llh_position",
        }
    }

    /// Device of the layout used, for fields with per-device layouts.
    pub fn device(&self) -> Option<crate::Device> {
        match self {
            Self::LlhPosition(_) => None,
        }
    }

    /// Encodes the field data.
    pub fn encode_data(
        &self,
        w: &mut crate::wire::Writer<'_>,
    ) -> Result<(), crate::error::EncodeError> {
        match self {
            Self::LlhPosition(v) => crate::wire::Layout::encode_data(v, w),
        }
    }

    /// Writes the canonical JSON of the values (`{...}`).
    pub fn write_values_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::LlhPosition(v) => crate::wire::Wire::write_json(v, w),
        }
    }

    /// Decodes field `descriptor` of this set; `None` if the set has no such field.
    pub fn decode(
        descriptor: u8,
        data: &[u8],
        device: Option<crate::Device>,
    ) -> Option<Result<Self, crate::error::DecodeError>> {
        let _ = device;
        match descriptor {
            0x03 => {
                Some(<LlhPosition as crate::wire::Layout>::decode_data(data).map(Self::LlhPosition))
            }
            _ => None,
        }
    }

    /// Reads the values of field `descriptor` of this set; `None` if the set has no such field.
    #[cfg(feature = "std")]
    pub fn from_json(
        descriptor: u8,
        device: Option<crate::Device>,
        values: &crate::json_read::Json,
    ) -> Option<Result<Self, crate::json_read::JsonError>> {
        match descriptor {
            0x03 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <LlhPosition as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::LlhPosition),
            ),
            _ => None,
        }
    }
}

/// The fields of one packet of this set, decoded in place by [`decode_packet`]: one member per
/// field of the set with one layout (its own and the shared data fields); `index` says which members hold a field of the last packet, in packet order
/// (the others hold whatever they held).
#[cfg(any(feature = "set-receiver-2", not(feature = "select-sets")))]
#[derive(Clone, Debug)]
pub struct Packet {
    /// The fields decoded into their members, in packet order.
    pub index: crate::packets::PacketIndex,
    /// Field 0x03.
    pub llh_position: crate::receiver_2::LlhPosition,
    /// Field 0xD3 (shared).
    pub timestamp: crate::shared::Timestamp,
}

#[cfg(any(feature = "set-receiver-2", not(feature = "select-sets")))]
impl Packet {
    /// Nothing decoded, every member zero.
    pub const ZERO: Self = Self {
        index: crate::packets::PacketIndex::EMPTY,
        llh_position: <crate::receiver_2::LlhPosition as crate::wire::Wire>::ZERO,
        timestamp: <crate::shared::Timestamp as crate::wire::Wire>::ZERO,
    };
}

#[cfg(any(feature = "set-receiver-2", not(feature = "select-sets")))]
impl Default for Packet {
    fn default() -> Self {
        Self::ZERO
    }
}

#[cfg(any(feature = "set-receiver-2", not(feature = "select-sets")))]
impl crate::packets::SetPacket for Packet {
    const SET: u8 = SET;

    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn index(&self) -> &crate::packets::PacketIndex {
        &self.index
    }

    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn index_mut(&mut self) -> &mut crate::packets::PacketIndex {
        &mut self.index
    }

    #[inline]
    #[allow(clippy::manual_range_patterns)]
    fn has_member(descriptor: u8) -> bool {
        matches!(descriptor, 0x03 | 0xD3)
    }

    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode_member(&mut self, descriptor: u8, data: &[u8]) -> bool {
        match descriptor {
            0x03 => match <&[u8; 18]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.llh_position;
                    s.latitude = crate::packets::ld(d, 0);
                    s.longitude = crate::packets::ld(d, 8);
                    s.valid_flags = crate::packets::ld(d, 16);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.llh_position),
            },
            0xD3 => match <&[u8; 8]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.timestamp;
                    s.nanoseconds = crate::packets::ld(d, 0);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.timestamp),
            },
            _ => false,
        }
    }

    fn field(&self, descriptor: u8) -> Option<crate::FieldValue> {
        if !self.index.contains(descriptor) {
            return None;
        }
        match descriptor {
            0x03 => Some(crate::FieldValue::Receiver2(
                crate::receiver_2::SetField::LlhPosition(self.llh_position),
            )),
            0xD3 => Some(crate::FieldValue::Shared(
                crate::shared::SetField::Timestamp(self.timestamp),
            )),
            _ => None,
        }
    }
}

/// The straight-line decoder of a packet of this set (issue 38): walks the fields of `payload`
/// (a packet's payload) matching the descriptor and decodes each field's layout into its member of
/// `out`, the value [`decode_field`](crate::decode_field) gives, with no general value and no
/// indirect call. Every other entry goes to `other`, in packet order: a descriptor without a
/// member (undefined, or a field with per-device layouts), a field that does not decode (its
/// member is then unspecified), a second field with a descriptor already decoded, trailing
/// bytes. Returns the number of fields decoded into members (`out.index.len()`).
#[cfg(any(feature = "set-receiver-2", not(feature = "select-sets")))]
pub fn decode_packet(
    payload: &[u8],
    out: &mut Packet,
    other: impl FnMut(crate::fields::FieldItem<'_>),
) -> usize {
    crate::packets::decode_set_packet(payload, out, other)
}
