//! Reserved fields (`protocols[].reserved_fields`): valid in every set of their kind, whether
//! or not the spec defines the set.

/// Ack/Nack. Reply to every command field: echoes the command descriptor and gives an ack code. Reserved in every command descriptor set. Reserved in every command set.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AckNack {
    /// Descriptor of the command being answered.
    pub command_descriptor: u8,
    /// 0 is an ACK; any other value is a NACK.
    pub ack_code: crate::types::AckCode,
}

impl Default for AckNack {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AckNack {
    const ZERO: Self = Self {
        command_descriptor: <u8 as crate::wire::Wire>::ZERO,
        ack_code: <crate::types::AckCode as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(2);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_command_descriptor =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("command_descriptor"))?;
        let p_ack_code = <crate::types::AckCode as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("ack_code"))?;
        Ok(Self {
            command_descriptor: p_command_descriptor,
            ack_code: p_ack_code,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.command_descriptor;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("command_descriptor"))?;
        let v = &self.ack_code;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("ack_code"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.command_descriptor;
        crate::json::key(w, &mut first, "command_descriptor")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.ack_code;
        crate::json::key(w, &mut first, "ack_code")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AckNack {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["command_descriptor", "ack_code"])?;
        let p_command_descriptor = o.req(
            "command_descriptor",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_ack_code = o.req(
            "ack_code",
            <crate::types::AckCode as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            command_descriptor: p_command_descriptor,
            ack_code: p_ack_code,
        })
    }
}

impl crate::wire::Layout for AckNack {
    const DESCRIPTOR: u8 = 0xF1;
    const NAME: &'static str = "ack_nack";
}

/// A decoded reserved field.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ReservedField {
    /// `ack_nack` (0xF1).
    AckNack(AckNack),
}

impl ReservedField {
    /// Field descriptor.
    pub fn descriptor(&self) -> u8 {
        match self {
            Self::AckNack(_) => 0xF1,
        }
    }

    /// Field name as printed in JSON.
    pub fn name(&self) -> &'static str {
        match self {
            Self::AckNack(_) => "ack_nack",
        }
    }

    /// Device of the layout used, for fields with per-device layouts.
    pub fn device(&self) -> Option<crate::Device> {
        match self {
            Self::AckNack(_) => None,
        }
    }

    /// Encodes the field data.
    pub fn encode_data(
        &self,
        w: &mut crate::wire::Writer<'_>,
    ) -> Result<(), crate::error::EncodeError> {
        match self {
            Self::AckNack(v) => crate::wire::Layout::encode_data(v, w),
        }
    }

    /// Writes the canonical JSON of the values (`{...}`).
    pub fn write_values_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::AckNack(v) => crate::wire::Wire::write_json(v, w),
        }
    }

    /// Decodes a reserved field of a set of kind `kind`; `None` if no reserved field applies.
    pub fn decode(
        kind: Option<crate::SetKind>,
        descriptor: u8,
        data: &[u8],
    ) -> Option<Result<Self, crate::error::DecodeError>> {
        match (kind, descriptor) {
            (Some(crate::SetKind::Command), 0xF1) => {
                Some(<AckNack as crate::wire::Layout>::decode_data(data).map(Self::AckNack))
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
            (Some(crate::SetKind::Command), 0xF1) => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AckNack as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::AckNack),
            ),
            _ => None,
        }
    }
}
