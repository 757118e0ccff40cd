//! System Command Set. Advanced commands for devices with several intelligent internal sensor blocks, such as switching the communication port to the native protocol of an embedded sensor.
//!
//! Descriptor set 0x7F (command set):
//! one struct per field layout, and `SetField`, the enum of all its fields.

/// Descriptor set of this module.
pub const SET: u8 = 0x7F;

/// Communication mode. Switch the communication protocol between standard MIP and the native protocols of an internal sensor block (IMU direct, or u-blox GNSS direct). Always active, even in the direct modes; the device acks just before switching. GNSS message settings are reloaded when returning to standard mode, and switching to or from GNSS direct takes longer than most commands.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CommunicationMode {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// New communication mode (ignored for functions other than write). Sent for: write.
    pub mode: Option<crate::types::SystemCommMode>,
}

impl Default for CommunicationMode {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for CommunicationMode {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        mode: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_mode = if r.left() > 0 {
            Some(
                <crate::types::SystemCommMode as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("mode"))?,
            )
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            mode: p_mode,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.mode {
            optionals.present("mode")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("mode"))?;
        } else {
            optionals.absent("mode");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.mode {
            crate::json::key(w, &mut first, "mode")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for CommunicationMode {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "mode"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_mode = o.opt(
            "mode",
            <crate::types::SystemCommMode as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            mode: p_mode,
        })
    }
}

impl CommunicationMode {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x7F;
}

impl crate::wire::Layout for CommunicationMode {
    const DESCRIPTOR: u8 = 0x10;
    const DESCRIPTOR_SET: Option<u8> = Some(0x7F);
    const NAME: &'static str = "communication_mode";
}

/// Communication mode (response). Current communication mode (reply to a read).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CommunicationModeResponse {
    /// Current communication mode.
    pub mode: crate::types::SystemCommMode,
}

impl Default for CommunicationModeResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for CommunicationModeResponse {
    const ZERO: Self = Self {
        mode: <crate::types::SystemCommMode as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(1);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_mode = <crate::types::SystemCommMode as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("mode"))?;
        Ok(Self { mode: p_mode })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.mode;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("mode"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.mode;
        crate::json::key(w, &mut first, "mode")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for CommunicationModeResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["mode"])?;
        let p_mode = o.req(
            "mode",
            <crate::types::SystemCommMode as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self { mode: p_mode })
    }
}

impl CommunicationModeResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x7F;
}

impl crate::wire::Layout for CommunicationModeResponse {
    const DESCRIPTOR: u8 = 0x90;
    const DESCRIPTOR_SET: Option<u8> = Some(0x7F);
    const NAME: &'static str = "communication_mode_response";
}

/// A decoded field of set 0x7F (`system`).
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SetField {
    /// `communication_mode` (0x10).
    CommunicationMode(CommunicationMode),
    /// `communication_mode_response` (0x90).
    CommunicationModeResponse(CommunicationModeResponse),
}

impl SetField {
    /// Field descriptor.
    pub fn descriptor(&self) -> u8 {
        match self {
            Self::CommunicationMode(_) => 0x10,
            Self::CommunicationModeResponse(_) => 0x90,
        }
    }

    /// Field name as printed in JSON.
    pub fn name(&self) -> &'static str {
        match self {
            Self::CommunicationMode(_) => "communication_mode",
            Self::CommunicationModeResponse(_) => "communication_mode_response",
        }
    }

    /// Device of the layout used, for fields with per-device layouts.
    pub fn device(&self) -> Option<crate::Device> {
        match self {
            Self::CommunicationMode(_) => None,
            Self::CommunicationModeResponse(_) => None,
        }
    }

    /// Encodes the field data.
    pub fn encode_data(
        &self,
        w: &mut crate::wire::Writer<'_>,
    ) -> Result<(), crate::error::EncodeError> {
        match self {
            Self::CommunicationMode(v) => crate::wire::Layout::encode_data(v, w),
            Self::CommunicationModeResponse(v) => crate::wire::Layout::encode_data(v, w),
        }
    }

    /// Writes the canonical JSON of the values (`{...}`).
    pub fn write_values_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::CommunicationMode(v) => crate::wire::Wire::write_json(v, w),
            Self::CommunicationModeResponse(v) => crate::wire::Wire::write_json(v, w),
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
            0x10 => Some(
                <CommunicationMode as crate::wire::Layout>::decode_data(data)
                    .map(Self::CommunicationMode),
            ),
            0x90 => Some(
                <CommunicationModeResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::CommunicationModeResponse),
            ),
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
            0x10 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <CommunicationMode as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::CommunicationMode),
            ),
            0x90 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <CommunicationModeResponse as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::CommunicationModeResponse),
            ),
            _ => None,
        }
    }
}
