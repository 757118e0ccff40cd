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
