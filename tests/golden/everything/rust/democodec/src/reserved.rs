//! Reserved fields (`protocols[].reserved_fields`): valid in every set of their kind, whether
//! or not the spec defines the set.

/// Ack. Reserved in every command set.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ack {
    pub echo: u8,
    pub code: u8,
}

impl Default for Ack {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for Ack {
    const ZERO: Self = Self {
        echo: <u8 as crate::wire::Wire>::ZERO,
        code: <u8 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(2);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_echo = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("echo"))?;
        let p_code = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("code"))?;
        Ok(Self {
            echo: p_echo,
            code: p_code,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.echo;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("echo"))?;
        let v = &self.code;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("code"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.echo;
        crate::json::key(w, &mut first, "echo")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.code;
        crate::json::key(w, &mut first, "code")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for Ack {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["echo", "code"])?;
        let p_echo = o.req("echo", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_code = o.req("code", <u8 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            echo: p_echo,
            code: p_code,
        })
    }
}

impl crate::wire::Layout for Ack {
    const DESCRIPTOR: u8 = 0x80;
    const NAME: &'static str = "ack";
}

/// A decoded reserved field.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ReservedField {
    /// `ack` (0x80).
    Ack(Ack),
}

impl ReservedField {
    /// Field descriptor.
    pub fn descriptor(&self) -> u8 {
        match self {
            Self::Ack(_) => 0x80,
        }
    }

    /// Field name as printed in JSON.
    pub fn name(&self) -> &'static str {
        match self {
            Self::Ack(_) => "ack",
        }
    }

    /// Device of the layout used, for fields with per-device layouts.
    pub fn device(&self) -> Option<crate::Device> {
        match self {
            Self::Ack(_) => None,
        }
    }

    /// Encodes the field data.
    pub fn encode_data(
        &self,
        w: &mut crate::wire::Writer<'_>,
    ) -> Result<(), crate::error::EncodeError> {
        match self {
            Self::Ack(v) => crate::wire::Layout::encode_data(v, w),
        }
    }

    /// Writes the canonical JSON of the values (`{...}`).
    pub fn write_values_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::Ack(v) => crate::wire::Wire::write_json(v, w),
        }
    }

    /// Decodes a reserved field of a set of kind `kind`; `None` if no reserved field applies.
    pub fn decode(
        kind: Option<crate::SetKind>,
        descriptor: u8,
        data: &[u8],
    ) -> Option<Result<Self, crate::error::DecodeError>> {
        match (kind, descriptor) {
            (Some(crate::SetKind::Command), 0x80) => {
                Some(<Ack as crate::wire::Layout>::decode_data(data).map(Self::Ack))
            }
            _ => None,
        }
    }

    /// Reads the values of a reserved field; `None` if no reserved field applies.
    #[cfg(feature = "std")]
    pub fn from_json(
        kind: Option<crate::SetKind>,
        descriptor: u8,
        device: Option<crate::Device>,
        values: &crate::json_read::Json,
    ) -> Option<Result<Self, crate::json_read::JsonError>> {
        match (kind, descriptor) {
            (Some(crate::SetKind::Command), 0x80) => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <Ack as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::Ack),
            ),
            _ => None,
        }
    }
}
