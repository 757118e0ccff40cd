//! Shared data.
//!
//! Descriptor set 0xFF (data set; its fields are valid in every data set):
//! one struct per field layout, and `SetField`, the enum of all its fields.

/// Descriptor set of this module.
pub const SET: u8 = 0xFF;

/// Timestamp.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Timestamp {
    pub nanoseconds: u64,
}

impl Default for Timestamp {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for Timestamp {
    const ZERO: Self = Self {
        nanoseconds: <u64 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(8);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_nanoseconds =
            <u64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("nanoseconds"))?;
        Ok(Self {
            nanoseconds: p_nanoseconds,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.nanoseconds;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("nanoseconds"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.nanoseconds;
        crate::json::key(w, &mut first, "nanoseconds")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for Timestamp {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["nanoseconds"])?;
        let p_nanoseconds = o.req(
            "nanoseconds",
            <u64 as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            nanoseconds: p_nanoseconds,
        })
    }
}

impl Timestamp {
    /// Descriptor set of the field.
    pub const SET: u8 = 0xFF;
}

impl crate::wire::Layout for Timestamp {
    const DESCRIPTOR: u8 = 0xD3;
    const DESCRIPTOR_SET: Option<u8> = Some(0xFF);
    const NAME: &'static str = "timestamp";
}

/// A decoded field of set 0xFF (`shared`).
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SetField {
    /// `timestamp` (0xD3).
    Timestamp(Timestamp),
}

impl SetField {
    /// Field descriptor.
    pub fn descriptor(&self) -> u8 {
        match self {
            Self::Timestamp(_) => 0xD3,
        }
    }

    /// Field name as printed in JSON.
    pub fn name(&self) -> &'static str {
        match self {
            Self::Timestamp(_) => "timestamp",
        }
    }

    /// Device of the layout used, for fields with per-device layouts.
    pub fn device(&self) -> Option<crate::Device> {
        match self {
            Self::Timestamp(_) => None,
        }
    }

    /// Encodes the field data.
    pub fn encode_data(
        &self,
        w: &mut crate::wire::Writer<'_>,
    ) -> Result<(), crate::error::EncodeError> {
        match self {
            Self::Timestamp(v) => crate::wire::Layout::encode_data(v, w),
        }
    }

    /// Writes the canonical JSON of the values (`{...}`).
    pub fn write_values_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::Timestamp(v) => crate::wire::Wire::write_json(v, w),
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
            0xD3 => {
                Some(<Timestamp as crate::wire::Layout>::decode_data(data).map(Self::Timestamp))
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
            0xD3 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <Timestamp as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::Timestamp),
            ),
            _ => None,
        }
    }
}
