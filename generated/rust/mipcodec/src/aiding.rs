//! Aiding Command Set. External aiding measurements for the navigation filter, each timestamped and tagged with the aiding frame it was measured in, plus the definition of those frames (lever arm and rotation relative to the vehicle frame) and control of how the device acknowledges aiding commands.
//!
//! Descriptor set 0x13 (command set):
//! one struct per field layout, and `SetField`, the enum of all its fields.

/// Descriptor set of this module.
pub const SET: u8 = 0x13;

/// Frame configuration. Define an aiding frame: the translation (lever arm) and rotation of an external aiding sensor relative to the vehicle frame. Aiding measurements name the frame they were taken in with their frame_id. Optionally the filter tracks errors in the frame definition.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrameConfig {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Reference frame number (at most 4). Sent for: write, read, save, load, default.
    pub frame_id: u8,
    /// Format of the rotation (also selects the format a read reports). Sent for: write, read.
    pub format: Option<crate::types::AidingFrameFormat>,
    /// If true, the Kalman filter tracks errors in this frame definition. Sent for: write.
    pub tracking_enabled: Option<bool>,
    /// Translation X, Y, Z of the frame in the vehicle frame. Units: m. Sent for: write.
    pub translation: Option<[f32; 3]>,
    /// Rotation of the frame, in the given format. Sent for: write.
    pub rotation: Option<crate::types::AidingFrameRotation>,
}

impl Default for FrameConfig {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for FrameConfig {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        frame_id: <u8 as crate::wire::Wire>::ZERO,
        format: None,
        tracking_enabled: None,
        translation: None,
        rotation: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_frame_id = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("frame_id"))?;
        let p_format = if r.left() > 0 {
            Some(
                <crate::types::AidingFrameFormat as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("format"))?,
            )
        } else {
            None
        };
        let p_tracking_enabled = if r.left() > 0 {
            Some(<bool as crate::wire::Wire>::decode(r).map_err(|e| e.at("tracking_enabled"))?)
        } else {
            None
        };
        let p_translation = if r.left() > 0 {
            Some(<[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("translation"))?)
        } else {
            None
        };
        let p_rotation = if r.left() > 0 {
            Some(
                crate::types::AidingFrameRotation::decode_selected(r, p_format.map_or(0, |s| s.0))
                    .map_err(|e| e.at("rotation"))?,
            )
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            frame_id: p_frame_id,
            format: p_format,
            tracking_enabled: p_tracking_enabled,
            translation: p_translation,
            rotation: p_rotation,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        let v = &self.frame_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("frame_id"))?;
        if let Some(v) = &self.format {
            optionals.present("format")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("format"))?;
        } else {
            optionals.absent("format");
        }
        if let Some(v) = &self.tracking_enabled {
            optionals.present("tracking_enabled")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("tracking_enabled"))?;
        } else {
            optionals.absent("tracking_enabled");
        }
        if let Some(v) = &self.translation {
            optionals.present("translation")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("translation"))?;
        } else {
            optionals.absent("translation");
        }
        if let Some(v) = &self.rotation {
            optionals.present("rotation")?;
            v.encode_selected(w, self.format.map_or(0, |s| s.0))
                .map_err(|e| e.at("rotation"))?;
        } else {
            optionals.absent("rotation");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.frame_id;
        crate::json::key(w, &mut first, "frame_id")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.format {
            crate::json::key(w, &mut first, "format")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.tracking_enabled {
            crate::json::key(w, &mut first, "tracking_enabled")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.translation {
            crate::json::key(w, &mut first, "translation")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.rotation {
            crate::json::key(w, &mut first, "rotation")?;
            v.write_json(w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for FrameConfig {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "function",
                "frame_id",
                "format",
                "tracking_enabled",
                "translation",
                "rotation",
            ],
        )?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_frame_id = o.req("frame_id", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_format = o.opt(
            "format",
            <crate::types::AidingFrameFormat as crate::json_read::FromJson>::from_json,
        )?;
        let p_tracking_enabled = o.opt(
            "tracking_enabled",
            <bool as crate::json_read::FromJson>::from_json,
        )?;
        let p_translation = o.opt(
            "translation",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_rotation = o.opt("rotation", |v| {
            crate::types::AidingFrameRotation::from_json_selected(v, p_format.map_or(0, |s| s.0))
        })?;
        Ok(Self {
            function: p_function,
            frame_id: p_frame_id,
            format: p_format,
            tracking_enabled: p_tracking_enabled,
            translation: p_translation,
            rotation: p_rotation,
        })
    }
}

impl FrameConfig {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x13;
}

impl crate::wire::Layout for FrameConfig {
    const DESCRIPTOR: u8 = 0x01;
    const DESCRIPTOR_SET: Option<u8> = Some(0x13);
    const NAME: &'static str = "frame_config";
}

/// Frame configuration (response). Current definition of an aiding frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrameConfigResponse {
    /// Reference frame number.
    pub frame_id: u8,
    /// Format of the rotation.
    pub format: crate::types::AidingFrameFormat,
    /// Whether the Kalman filter tracks errors in this frame.
    pub tracking_enabled: bool,
    /// Translation X, Y, Z. Units: m.
    pub translation: [f32; 3],
    /// Rotation, in the given format.
    pub rotation: crate::types::AidingFrameRotation,
}

impl Default for FrameConfigResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for FrameConfigResponse {
    const ZERO: Self = Self {
        frame_id: <u8 as crate::wire::Wire>::ZERO,
        format: <crate::types::AidingFrameFormat as crate::wire::Wire>::ZERO,
        tracking_enabled: <bool as crate::wire::Wire>::ZERO,
        translation: <[f32; 3] as crate::wire::Wire>::ZERO,
        rotation: crate::types::AidingFrameRotation::ZERO,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_frame_id = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("frame_id"))?;
        let p_format = <crate::types::AidingFrameFormat as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("format"))?;
        let p_tracking_enabled =
            <bool as crate::wire::Wire>::decode(r).map_err(|e| e.at("tracking_enabled"))?;
        let p_translation =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("translation"))?;
        let p_rotation = crate::types::AidingFrameRotation::decode_selected(r, p_format.0)
            .map_err(|e| e.at("rotation"))?;
        Ok(Self {
            frame_id: p_frame_id,
            format: p_format,
            tracking_enabled: p_tracking_enabled,
            translation: p_translation,
            rotation: p_rotation,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.frame_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("frame_id"))?;
        let v = &self.format;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("format"))?;
        let v = &self.tracking_enabled;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("tracking_enabled"))?;
        let v = &self.translation;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("translation"))?;
        let v = &self.rotation;
        v.encode_selected(w, self.format.0)
            .map_err(|e| e.at("rotation"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.frame_id;
        crate::json::key(w, &mut first, "frame_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.format;
        crate::json::key(w, &mut first, "format")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.tracking_enabled;
        crate::json::key(w, &mut first, "tracking_enabled")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.translation;
        crate::json::key(w, &mut first, "translation")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.rotation;
        crate::json::key(w, &mut first, "rotation")?;
        v.write_json(w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for FrameConfigResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "frame_id",
                "format",
                "tracking_enabled",
                "translation",
                "rotation",
            ],
        )?;
        let p_frame_id = o.req("frame_id", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_format = o.req(
            "format",
            <crate::types::AidingFrameFormat as crate::json_read::FromJson>::from_json,
        )?;
        let p_tracking_enabled = o.req(
            "tracking_enabled",
            <bool as crate::json_read::FromJson>::from_json,
        )?;
        let p_translation = o.req(
            "translation",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_rotation = o.req("rotation", |v| {
            crate::types::AidingFrameRotation::from_json_selected(v, p_format.0)
        })?;
        Ok(Self {
            frame_id: p_frame_id,
            format: p_format,
            tracking_enabled: p_tracking_enabled,
            translation: p_translation,
            rotation: p_rotation,
        })
    }
}

impl FrameConfigResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x13;
}

impl crate::wire::Layout for FrameConfigResponse {
    const DESCRIPTOR: u8 = 0x81;
    const DESCRIPTOR_SET: Option<u8> = Some(0x13);
    const NAME: &'static str = "frame_config_response";
}

/// Echo control. Control how the device answers aiding measurement commands: no ack, normal ack/nack, or echoing the aiding data back (useful for logging and post-processing).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EchoControl {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// How aiding commands are answered. Sent for: write.
    pub mode: Option<crate::types::AidingEchoMode>,
}

impl Default for EchoControl {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for EchoControl {
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
                <crate::types::AidingEchoMode as crate::wire::Wire>::decode(r)
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
impl crate::json_read::FromJson for EchoControl {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "mode"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_mode = o.opt(
            "mode",
            <crate::types::AidingEchoMode as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            mode: p_mode,
        })
    }
}

impl EchoControl {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x13;
}

impl crate::wire::Layout for EchoControl {
    const DESCRIPTOR: u8 = 0x1F;
    const DESCRIPTOR_SET: Option<u8> = Some(0x13);
    const NAME: &'static str = "echo_control";
}

/// Echo control (response). Current aiding echo mode.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EchoControlResponse {
    /// How aiding commands are answered.
    pub mode: crate::types::AidingEchoMode,
}

impl Default for EchoControlResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for EchoControlResponse {
    const ZERO: Self = Self {
        mode: <crate::types::AidingEchoMode as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(1);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_mode = <crate::types::AidingEchoMode as crate::wire::Wire>::decode(r)
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
impl crate::json_read::FromJson for EchoControlResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["mode"])?;
        let p_mode = o.req(
            "mode",
            <crate::types::AidingEchoMode as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self { mode: p_mode })
    }
}

impl EchoControlResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x13;
}

impl crate::wire::Layout for EchoControlResponse {
    const DESCRIPTOR: u8 = 0x9F;
    const DESCRIPTOR_SET: Option<u8> = Some(0x13);
    const NAME: &'static str = "echo_control_response";
}

/// ECEF position. Position aiding measurement in the WGS84 Earth-centred, Earth-fixed frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EcefPosition {
    /// Timestamp of the measurement.
    pub time: crate::types::AidingTime,
    /// Aiding frame the measurement was taken in (see frame_config).
    pub frame_id: u8,
    /// ECEF position X, Y, Z. Units: m.
    pub position: [f64; 3],
    /// ECEF position 1-sigma uncertainty; not 0 for a valid axis. Units: m.
    pub uncertainty: [f32; 3],
    /// Valid axes; invalid axes are ignored.
    pub valid_flags: crate::types::AidingVectorValidFlags,
}

impl Default for EcefPosition {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for EcefPosition {
    const ZERO: Self = Self {
        time: <crate::types::AidingTime as crate::wire::Wire>::ZERO,
        frame_id: <u8 as crate::wire::Wire>::ZERO,
        position: <[f64; 3] as crate::wire::Wire>::ZERO,
        uncertainty: <[f32; 3] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::AidingVectorValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(49);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_time =
            <crate::types::AidingTime as crate::wire::Wire>::decode(r).map_err(|e| e.at("time"))?;
        let p_frame_id = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("frame_id"))?;
        let p_position =
            <[f64; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("position"))?;
        let p_uncertainty =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("uncertainty"))?;
        let p_valid_flags = <crate::types::AidingVectorValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            time: p_time,
            frame_id: p_frame_id,
            position: p_position,
            uncertainty: p_uncertainty,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.time;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("time"))?;
        let v = &self.frame_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("frame_id"))?;
        let v = &self.position;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("position"))?;
        let v = &self.uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("uncertainty"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.time;
        crate::json::key(w, &mut first, "time")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.frame_id;
        crate::json::key(w, &mut first, "frame_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.position;
        crate::json::key(w, &mut first, "position")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.uncertainty;
        crate::json::key(w, &mut first, "uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for EcefPosition {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &["time", "frame_id", "position", "uncertainty", "valid_flags"],
        )?;
        let p_time = o.req(
            "time",
            <crate::types::AidingTime as crate::json_read::FromJson>::from_json,
        )?;
        let p_frame_id = o.req("frame_id", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_position = o.req(
            "position",
            <[f64; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_uncertainty = o.req(
            "uncertainty",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::AidingVectorValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            time: p_time,
            frame_id: p_frame_id,
            position: p_position,
            uncertainty: p_uncertainty,
            valid_flags: p_valid_flags,
        })
    }
}

impl EcefPosition {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x13;
}

impl crate::wire::Layout for EcefPosition {
    const DESCRIPTOR: u8 = 0x21;
    const DESCRIPTOR_SET: Option<u8> = Some(0x13);
    const NAME: &'static str = "ecef_position";
}

/// LLH position. Geodetic position aiding measurement: WGS84 latitude, longitude and height above the ellipsoid, with uncertainty in north, east, down components. With latitude and longitude marked invalid it aids height only.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LlhPosition {
    /// Timestamp of the measurement.
    pub time: crate::types::AidingTime,
    /// Aiding frame the measurement was taken in.
    pub frame_id: u8,
    /// WGS84 latitude. Units: deg.
    pub latitude: f64,
    /// WGS84 longitude. Units: deg.
    pub longitude: f64,
    /// Height above the WGS84 ellipsoid. Units: m.
    pub height: f64,
    /// 1-sigma uncertainty in north, east, down (the table prints no unit); not 0 for a valid component. Units: m.
    pub uncertainty: [f32; 3],
    /// Valid components; invalid ones are ignored.
    pub valid_flags: crate::types::AidingLlhValidFlags,
}

impl Default for LlhPosition {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for LlhPosition {
    const ZERO: Self = Self {
        time: <crate::types::AidingTime as crate::wire::Wire>::ZERO,
        frame_id: <u8 as crate::wire::Wire>::ZERO,
        latitude: <f64 as crate::wire::Wire>::ZERO,
        longitude: <f64 as crate::wire::Wire>::ZERO,
        height: <f64 as crate::wire::Wire>::ZERO,
        uncertainty: <[f32; 3] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::AidingLlhValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(49);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_time =
            <crate::types::AidingTime as crate::wire::Wire>::decode(r).map_err(|e| e.at("time"))?;
        let p_frame_id = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("frame_id"))?;
        let p_latitude = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("latitude"))?;
        let p_longitude = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("longitude"))?;
        let p_height = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("height"))?;
        let p_uncertainty =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("uncertainty"))?;
        let p_valid_flags = <crate::types::AidingLlhValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            time: p_time,
            frame_id: p_frame_id,
            latitude: p_latitude,
            longitude: p_longitude,
            height: p_height,
            uncertainty: p_uncertainty,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.time;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("time"))?;
        let v = &self.frame_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("frame_id"))?;
        let v = &self.latitude;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("latitude"))?;
        let v = &self.longitude;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("longitude"))?;
        let v = &self.height;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("height"))?;
        let v = &self.uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("uncertainty"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.time;
        crate::json::key(w, &mut first, "time")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.frame_id;
        crate::json::key(w, &mut first, "frame_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.latitude;
        crate::json::key(w, &mut first, "latitude")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.longitude;
        crate::json::key(w, &mut first, "longitude")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.height;
        crate::json::key(w, &mut first, "height")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.uncertainty;
        crate::json::key(w, &mut first, "uncertainty")?;
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
        let o = crate::json_read::Obj::new(
            v,
            &[
                "time",
                "frame_id",
                "latitude",
                "longitude",
                "height",
                "uncertainty",
                "valid_flags",
            ],
        )?;
        let p_time = o.req(
            "time",
            <crate::types::AidingTime as crate::json_read::FromJson>::from_json,
        )?;
        let p_frame_id = o.req("frame_id", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_latitude = o.req("latitude", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_longitude = o.req("longitude", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_height = o.req("height", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_uncertainty = o.req(
            "uncertainty",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::AidingLlhValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            time: p_time,
            frame_id: p_frame_id,
            latitude: p_latitude,
            longitude: p_longitude,
            height: p_height,
            uncertainty: p_uncertainty,
            valid_flags: p_valid_flags,
        })
    }
}

impl LlhPosition {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x13;
}

impl crate::wire::Layout for LlhPosition {
    const DESCRIPTOR: u8 = 0x22;
    const DESCRIPTOR_SET: Option<u8> = Some(0x13);
    const NAME: &'static str = "llh_position";
}

/// Height above ellipsoid. Height aiding measurement above the WGS84 ellipsoid.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HeightAboveEllipsoid {
    /// Timestamp of the measurement.
    pub time: crate::types::AidingTime,
    /// Aiding frame the measurement was taken in.
    pub frame_id: u8,
    /// Height above the ellipsoid. Units: m.
    pub height: f32,
    /// 1-sigma uncertainty. Units: m.
    pub uncertainty: f32,
    /// Valid flags; 0 means the measurement is ignored (no bits are defined).
    pub valid_flags: u16,
}

impl Default for HeightAboveEllipsoid {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for HeightAboveEllipsoid {
    const ZERO: Self = Self {
        time: <crate::types::AidingTime as crate::wire::Wire>::ZERO,
        frame_id: <u8 as crate::wire::Wire>::ZERO,
        height: <f32 as crate::wire::Wire>::ZERO,
        uncertainty: <f32 as crate::wire::Wire>::ZERO,
        valid_flags: <u16 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(21);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_time =
            <crate::types::AidingTime as crate::wire::Wire>::decode(r).map_err(|e| e.at("time"))?;
        let p_frame_id = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("frame_id"))?;
        let p_height = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("height"))?;
        let p_uncertainty =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("uncertainty"))?;
        let p_valid_flags =
            <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            time: p_time,
            frame_id: p_frame_id,
            height: p_height,
            uncertainty: p_uncertainty,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.time;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("time"))?;
        let v = &self.frame_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("frame_id"))?;
        let v = &self.height;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("height"))?;
        let v = &self.uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("uncertainty"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.time;
        crate::json::key(w, &mut first, "time")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.frame_id;
        crate::json::key(w, &mut first, "frame_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.height;
        crate::json::key(w, &mut first, "height")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.uncertainty;
        crate::json::key(w, &mut first, "uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for HeightAboveEllipsoid {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &["time", "frame_id", "height", "uncertainty", "valid_flags"],
        )?;
        let p_time = o.req(
            "time",
            <crate::types::AidingTime as crate::json_read::FromJson>::from_json,
        )?;
        let p_frame_id = o.req("frame_id", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_height = o.req("height", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_uncertainty = o.req(
            "uncertainty",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <u16 as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            time: p_time,
            frame_id: p_frame_id,
            height: p_height,
            uncertainty: p_uncertainty,
            valid_flags: p_valid_flags,
        })
    }
}

impl HeightAboveEllipsoid {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x13;
}

impl crate::wire::Layout for HeightAboveEllipsoid {
    const DESCRIPTOR: u8 = 0x23;
    const DESCRIPTOR_SET: Option<u8> = Some(0x13);
    const NAME: &'static str = "height_above_ellipsoid";
}

/// ECEF velocity. Velocity aiding measurement in the WGS84 ECEF frame. Not for body-fixed sensors such as radar (use body frame velocity).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EcefVelocity {
    /// Timestamp of the measurement.
    pub time: crate::types::AidingTime,
    /// Aiding frame the measurement was taken in.
    pub frame_id: u8,
    /// ECEF velocity X, Y, Z. Units: m/s.
    pub velocity: [f32; 3],
    /// ECEF velocity 1-sigma uncertainty; not 0 for a valid axis. Units: m/s.
    pub uncertainty: [f32; 3],
    /// Valid axes; invalid axes are ignored.
    pub valid_flags: crate::types::AidingVectorValidFlags,
}

impl Default for EcefVelocity {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for EcefVelocity {
    const ZERO: Self = Self {
        time: <crate::types::AidingTime as crate::wire::Wire>::ZERO,
        frame_id: <u8 as crate::wire::Wire>::ZERO,
        velocity: <[f32; 3] as crate::wire::Wire>::ZERO,
        uncertainty: <[f32; 3] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::AidingVectorValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(37);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_time =
            <crate::types::AidingTime as crate::wire::Wire>::decode(r).map_err(|e| e.at("time"))?;
        let p_frame_id = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("frame_id"))?;
        let p_velocity =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("velocity"))?;
        let p_uncertainty =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("uncertainty"))?;
        let p_valid_flags = <crate::types::AidingVectorValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            time: p_time,
            frame_id: p_frame_id,
            velocity: p_velocity,
            uncertainty: p_uncertainty,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.time;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("time"))?;
        let v = &self.frame_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("frame_id"))?;
        let v = &self.velocity;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("velocity"))?;
        let v = &self.uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("uncertainty"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.time;
        crate::json::key(w, &mut first, "time")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.frame_id;
        crate::json::key(w, &mut first, "frame_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.velocity;
        crate::json::key(w, &mut first, "velocity")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.uncertainty;
        crate::json::key(w, &mut first, "uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for EcefVelocity {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &["time", "frame_id", "velocity", "uncertainty", "valid_flags"],
        )?;
        let p_time = o.req(
            "time",
            <crate::types::AidingTime as crate::json_read::FromJson>::from_json,
        )?;
        let p_frame_id = o.req("frame_id", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_velocity = o.req(
            "velocity",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_uncertainty = o.req(
            "uncertainty",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::AidingVectorValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            time: p_time,
            frame_id: p_frame_id,
            velocity: p_velocity,
            uncertainty: p_uncertainty,
            valid_flags: p_valid_flags,
        })
    }
}

impl EcefVelocity {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x13;
}

impl crate::wire::Layout for EcefVelocity {
    const DESCRIPTOR: u8 = 0x28;
    const DESCRIPTOR_SET: Option<u8> = Some(0x13);
    const NAME: &'static str = "ecef_velocity";
}

/// NED velocity. Velocity aiding measurement in the local north-east-down frame. Not for body-fixed sensors (use body frame velocity).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NedVelocity {
    /// Timestamp of the measurement.
    pub time: crate::types::AidingTime,
    /// Aiding frame the measurement was taken in.
    pub frame_id: u8,
    /// NED velocity (north, east, down). Units: m/s.
    pub velocity: [f32; 3],
    /// NED velocity 1-sigma uncertainty; not 0 for a valid axis. Units: m/s.
    pub uncertainty: [f32; 3],
    /// Valid components (x = north, y = east, z = down).
    pub valid_flags: crate::types::AidingVectorValidFlags,
}

impl Default for NedVelocity {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for NedVelocity {
    const ZERO: Self = Self {
        time: <crate::types::AidingTime as crate::wire::Wire>::ZERO,
        frame_id: <u8 as crate::wire::Wire>::ZERO,
        velocity: <[f32; 3] as crate::wire::Wire>::ZERO,
        uncertainty: <[f32; 3] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::AidingVectorValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(37);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_time =
            <crate::types::AidingTime as crate::wire::Wire>::decode(r).map_err(|e| e.at("time"))?;
        let p_frame_id = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("frame_id"))?;
        let p_velocity =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("velocity"))?;
        let p_uncertainty =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("uncertainty"))?;
        let p_valid_flags = <crate::types::AidingVectorValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            time: p_time,
            frame_id: p_frame_id,
            velocity: p_velocity,
            uncertainty: p_uncertainty,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.time;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("time"))?;
        let v = &self.frame_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("frame_id"))?;
        let v = &self.velocity;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("velocity"))?;
        let v = &self.uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("uncertainty"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.time;
        crate::json::key(w, &mut first, "time")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.frame_id;
        crate::json::key(w, &mut first, "frame_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.velocity;
        crate::json::key(w, &mut first, "velocity")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.uncertainty;
        crate::json::key(w, &mut first, "uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for NedVelocity {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &["time", "frame_id", "velocity", "uncertainty", "valid_flags"],
        )?;
        let p_time = o.req(
            "time",
            <crate::types::AidingTime as crate::json_read::FromJson>::from_json,
        )?;
        let p_frame_id = o.req("frame_id", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_velocity = o.req(
            "velocity",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_uncertainty = o.req(
            "uncertainty",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::AidingVectorValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            time: p_time,
            frame_id: p_frame_id,
            velocity: p_velocity,
            uncertainty: p_uncertainty,
            valid_flags: p_valid_flags,
        })
    }
}

impl NedVelocity {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x13;
}

impl crate::wire::Layout for NedVelocity {
    const DESCRIPTOR: u8 = 0x29;
    const DESCRIPTOR_SET: Option<u8> = Some(0x13);
    const NAME: &'static str = "ned_velocity";
}

/// Body frame velocity. Velocity aiding measurement in a frame fixed to the vehicle (the aiding frame given by frame_id), e.g. pre-processed radar, lidar, wheel-speed or air-speed velocity. Up to four such sensors.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BodyFrameVelocity {
    /// Timestamp of the measurement.
    pub time: crate::types::AidingTime,
    /// Aiding frame the measurement was taken in (must be > 0).
    pub frame_id: u8,
    /// Velocity X, Y, Z in the aiding frame. Units: m/s.
    pub velocity: [f32; 3],
    /// 1-sigma uncertainty; not 0 (or negative) for a valid axis. Units: m/s.
    pub uncertainty: [f32; 3],
    /// Valid axes; invalid axes are ignored.
    pub valid_flags: crate::types::AidingVectorValidFlags,
}

impl Default for BodyFrameVelocity {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for BodyFrameVelocity {
    const ZERO: Self = Self {
        time: <crate::types::AidingTime as crate::wire::Wire>::ZERO,
        frame_id: <u8 as crate::wire::Wire>::ZERO,
        velocity: <[f32; 3] as crate::wire::Wire>::ZERO,
        uncertainty: <[f32; 3] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::AidingVectorValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(37);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_time =
            <crate::types::AidingTime as crate::wire::Wire>::decode(r).map_err(|e| e.at("time"))?;
        let p_frame_id = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("frame_id"))?;
        let p_velocity =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("velocity"))?;
        let p_uncertainty =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("uncertainty"))?;
        let p_valid_flags = <crate::types::AidingVectorValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            time: p_time,
            frame_id: p_frame_id,
            velocity: p_velocity,
            uncertainty: p_uncertainty,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.time;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("time"))?;
        let v = &self.frame_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("frame_id"))?;
        let v = &self.velocity;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("velocity"))?;
        let v = &self.uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("uncertainty"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.time;
        crate::json::key(w, &mut first, "time")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.frame_id;
        crate::json::key(w, &mut first, "frame_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.velocity;
        crate::json::key(w, &mut first, "velocity")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.uncertainty;
        crate::json::key(w, &mut first, "uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for BodyFrameVelocity {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &["time", "frame_id", "velocity", "uncertainty", "valid_flags"],
        )?;
        let p_time = o.req(
            "time",
            <crate::types::AidingTime as crate::json_read::FromJson>::from_json,
        )?;
        let p_frame_id = o.req("frame_id", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_velocity = o.req(
            "velocity",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_uncertainty = o.req(
            "uncertainty",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::AidingVectorValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            time: p_time,
            frame_id: p_frame_id,
            velocity: p_velocity,
            uncertainty: p_uncertainty,
            valid_flags: p_valid_flags,
        })
    }
}

impl BodyFrameVelocity {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x13;
}

impl crate::wire::Layout for BodyFrameVelocity {
    const DESCRIPTOR: u8 = 0x2A;
    const DESCRIPTOR_SET: Option<u8> = Some(0x13);
    const NAME: &'static str = "body_frame_velocity";
}

/// True heading. Heading aiding measurement relative to true north (e.g. dual-antenna GNSS compass).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TrueHeading {
    /// Timestamp of the measurement.
    pub time: crate::types::AidingTime,
    /// Aiding frame the measurement was taken in.
    pub frame_id: u8,
    /// True heading, within +/- pi. Units: rad.
    pub heading: f32,
    /// 1-sigma uncertainty; not 0 unless the valid flags are 0. Units: rad.
    pub uncertainty: f32,
    /// Valid flags; 0 means the measurement is ignored (no bits are defined).
    pub valid_flags: u16,
}

impl Default for TrueHeading {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for TrueHeading {
    const ZERO: Self = Self {
        time: <crate::types::AidingTime as crate::wire::Wire>::ZERO,
        frame_id: <u8 as crate::wire::Wire>::ZERO,
        heading: <f32 as crate::wire::Wire>::ZERO,
        uncertainty: <f32 as crate::wire::Wire>::ZERO,
        valid_flags: <u16 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(21);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_time =
            <crate::types::AidingTime as crate::wire::Wire>::decode(r).map_err(|e| e.at("time"))?;
        let p_frame_id = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("frame_id"))?;
        let p_heading = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("heading"))?;
        let p_uncertainty =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("uncertainty"))?;
        let p_valid_flags =
            <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            time: p_time,
            frame_id: p_frame_id,
            heading: p_heading,
            uncertainty: p_uncertainty,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.time;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("time"))?;
        let v = &self.frame_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("frame_id"))?;
        let v = &self.heading;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("heading"))?;
        let v = &self.uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("uncertainty"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.time;
        crate::json::key(w, &mut first, "time")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.frame_id;
        crate::json::key(w, &mut first, "frame_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.heading;
        crate::json::key(w, &mut first, "heading")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.uncertainty;
        crate::json::key(w, &mut first, "uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for TrueHeading {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &["time", "frame_id", "heading", "uncertainty", "valid_flags"],
        )?;
        let p_time = o.req(
            "time",
            <crate::types::AidingTime as crate::json_read::FromJson>::from_json,
        )?;
        let p_frame_id = o.req("frame_id", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_heading = o.req("heading", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_uncertainty = o.req(
            "uncertainty",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <u16 as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            time: p_time,
            frame_id: p_frame_id,
            heading: p_heading,
            uncertainty: p_uncertainty,
            valid_flags: p_valid_flags,
        })
    }
}

impl TrueHeading {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x13;
}

impl crate::wire::Layout for TrueHeading {
    const DESCRIPTOR: u8 = 0x31;
    const DESCRIPTOR_SET: Option<u8> = Some(0x13);
    const NAME: &'static str = "true_heading";
}

/// Magnetic field. Magnetic field aiding measurement from a calibrated external magnetometer, in the aiding frame given by frame_id.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MagneticField {
    /// Timestamp of the measurement.
    pub time: crate::types::AidingTime,
    /// Aiding frame the measurement was taken in (must be > 0).
    pub frame_id: u8,
    /// Magnetic field X, Y, Z. Units: gauss.
    pub magnetic_field: [f32; 3],
    /// 1-sigma uncertainty; not 0 for a valid axis. Units: gauss.
    pub uncertainty: [f32; 3],
    /// Valid axes; invalid axes are ignored.
    pub valid_flags: crate::types::AidingVectorValidFlags,
}

impl Default for MagneticField {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for MagneticField {
    const ZERO: Self = Self {
        time: <crate::types::AidingTime as crate::wire::Wire>::ZERO,
        frame_id: <u8 as crate::wire::Wire>::ZERO,
        magnetic_field: <[f32; 3] as crate::wire::Wire>::ZERO,
        uncertainty: <[f32; 3] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::AidingVectorValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(37);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_time =
            <crate::types::AidingTime as crate::wire::Wire>::decode(r).map_err(|e| e.at("time"))?;
        let p_frame_id = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("frame_id"))?;
        let p_magnetic_field =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("magnetic_field"))?;
        let p_uncertainty =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("uncertainty"))?;
        let p_valid_flags = <crate::types::AidingVectorValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            time: p_time,
            frame_id: p_frame_id,
            magnetic_field: p_magnetic_field,
            uncertainty: p_uncertainty,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.time;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("time"))?;
        let v = &self.frame_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("frame_id"))?;
        let v = &self.magnetic_field;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("magnetic_field"))?;
        let v = &self.uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("uncertainty"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.time;
        crate::json::key(w, &mut first, "time")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.frame_id;
        crate::json::key(w, &mut first, "frame_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.magnetic_field;
        crate::json::key(w, &mut first, "magnetic_field")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.uncertainty;
        crate::json::key(w, &mut first, "uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for MagneticField {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "time",
                "frame_id",
                "magnetic_field",
                "uncertainty",
                "valid_flags",
            ],
        )?;
        let p_time = o.req(
            "time",
            <crate::types::AidingTime as crate::json_read::FromJson>::from_json,
        )?;
        let p_frame_id = o.req("frame_id", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_magnetic_field = o.req(
            "magnetic_field",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_uncertainty = o.req(
            "uncertainty",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::AidingVectorValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            time: p_time,
            frame_id: p_frame_id,
            magnetic_field: p_magnetic_field,
            uncertainty: p_uncertainty,
            valid_flags: p_valid_flags,
        })
    }
}

impl MagneticField {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x13;
}

impl crate::wire::Layout for MagneticField {
    const DESCRIPTOR: u8 = 0x32;
    const DESCRIPTOR_SET: Option<u8> = Some(0x13);
    const NAME: &'static str = "magnetic_field";
}

/// Pressure. Static air pressure aiding measurement, to constrain altitude drift during GNSS outages.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pressure {
    /// Timestamp of the measurement.
    pub time: crate::types::AidingTime,
    /// Aiding frame the measurement was taken in.
    pub frame_id: u8,
    /// Static pressure. Units: mbar.
    pub pressure: f32,
    /// 1-sigma uncertainty; not 0 unless the valid flags are 0. Units: mbar.
    pub uncertainty: f32,
    /// Valid flags; 0 means the measurement is ignored (no bits are defined).
    pub valid_flags: u16,
}

impl Default for Pressure {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for Pressure {
    const ZERO: Self = Self {
        time: <crate::types::AidingTime as crate::wire::Wire>::ZERO,
        frame_id: <u8 as crate::wire::Wire>::ZERO,
        pressure: <f32 as crate::wire::Wire>::ZERO,
        uncertainty: <f32 as crate::wire::Wire>::ZERO,
        valid_flags: <u16 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(21);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_time =
            <crate::types::AidingTime as crate::wire::Wire>::decode(r).map_err(|e| e.at("time"))?;
        let p_frame_id = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("frame_id"))?;
        let p_pressure = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("pressure"))?;
        let p_uncertainty =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("uncertainty"))?;
        let p_valid_flags =
            <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            time: p_time,
            frame_id: p_frame_id,
            pressure: p_pressure,
            uncertainty: p_uncertainty,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.time;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("time"))?;
        let v = &self.frame_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("frame_id"))?;
        let v = &self.pressure;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("pressure"))?;
        let v = &self.uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("uncertainty"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.time;
        crate::json::key(w, &mut first, "time")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.frame_id;
        crate::json::key(w, &mut first, "frame_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.pressure;
        crate::json::key(w, &mut first, "pressure")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.uncertainty;
        crate::json::key(w, &mut first, "uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for Pressure {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &["time", "frame_id", "pressure", "uncertainty", "valid_flags"],
        )?;
        let p_time = o.req(
            "time",
            <crate::types::AidingTime as crate::json_read::FromJson>::from_json,
        )?;
        let p_frame_id = o.req("frame_id", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_pressure = o.req("pressure", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_uncertainty = o.req(
            "uncertainty",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <u16 as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            time: p_time,
            frame_id: p_frame_id,
            pressure: p_pressure,
            uncertainty: p_uncertainty,
            valid_flags: p_valid_flags,
        })
    }
}

impl Pressure {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x13;
}

impl crate::wire::Layout for Pressure {
    const DESCRIPTOR: u8 = 0x33;
    const DESCRIPTOR_SET: Option<u8> = Some(0x13);
    const NAME: &'static str = "pressure";
}

/// A decoded field of set 0x13 (`aiding`).
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SetField {
    /// `frame_config` (0x01).
    FrameConfig(FrameConfig),
    /// `frame_config_response` (0x81).
    FrameConfigResponse(FrameConfigResponse),
    /// `echo_control` (0x1F).
    EchoControl(EchoControl),
    /// `echo_control_response` (0x9F).
    EchoControlResponse(EchoControlResponse),
    /// `ecef_position` (0x21).
    EcefPosition(EcefPosition),
    /// `llh_position` (0x22).
    LlhPosition(LlhPosition),
    /// `height_above_ellipsoid` (0x23).
    HeightAboveEllipsoid(HeightAboveEllipsoid),
    /// `ecef_velocity` (0x28).
    EcefVelocity(EcefVelocity),
    /// `ned_velocity` (0x29).
    NedVelocity(NedVelocity),
    /// `body_frame_velocity` (0x2A).
    BodyFrameVelocity(BodyFrameVelocity),
    /// `true_heading` (0x31).
    TrueHeading(TrueHeading),
    /// `magnetic_field` (0x32).
    MagneticField(MagneticField),
    /// `pressure` (0x33).
    Pressure(Pressure),
}

impl SetField {
    /// Field descriptor.
    pub fn descriptor(&self) -> u8 {
        match self {
            Self::FrameConfig(_) => 0x01,
            Self::FrameConfigResponse(_) => 0x81,
            Self::EchoControl(_) => 0x1F,
            Self::EchoControlResponse(_) => 0x9F,
            Self::EcefPosition(_) => 0x21,
            Self::LlhPosition(_) => 0x22,
            Self::HeightAboveEllipsoid(_) => 0x23,
            Self::EcefVelocity(_) => 0x28,
            Self::NedVelocity(_) => 0x29,
            Self::BodyFrameVelocity(_) => 0x2A,
            Self::TrueHeading(_) => 0x31,
            Self::MagneticField(_) => 0x32,
            Self::Pressure(_) => 0x33,
        }
    }

    /// Field name as printed in JSON.
    pub fn name(&self) -> &'static str {
        match self {
            Self::FrameConfig(_) => "frame_config",
            Self::FrameConfigResponse(_) => "frame_config_response",
            Self::EchoControl(_) => "echo_control",
            Self::EchoControlResponse(_) => "echo_control_response",
            Self::EcefPosition(_) => "ecef_position",
            Self::LlhPosition(_) => "llh_position",
            Self::HeightAboveEllipsoid(_) => "height_above_ellipsoid",
            Self::EcefVelocity(_) => "ecef_velocity",
            Self::NedVelocity(_) => "ned_velocity",
            Self::BodyFrameVelocity(_) => "body_frame_velocity",
            Self::TrueHeading(_) => "true_heading",
            Self::MagneticField(_) => "magnetic_field",
            Self::Pressure(_) => "pressure",
        }
    }

    /// Device of the layout used, for fields with per-device layouts.
    pub fn device(&self) -> Option<crate::Device> {
        match self {
            Self::FrameConfig(_) => None,
            Self::FrameConfigResponse(_) => None,
            Self::EchoControl(_) => None,
            Self::EchoControlResponse(_) => None,
            Self::EcefPosition(_) => None,
            Self::LlhPosition(_) => None,
            Self::HeightAboveEllipsoid(_) => None,
            Self::EcefVelocity(_) => None,
            Self::NedVelocity(_) => None,
            Self::BodyFrameVelocity(_) => None,
            Self::TrueHeading(_) => None,
            Self::MagneticField(_) => None,
            Self::Pressure(_) => None,
        }
    }

    /// Encodes the field data.
    pub fn encode_data(
        &self,
        w: &mut crate::wire::Writer<'_>,
    ) -> Result<(), crate::error::EncodeError> {
        match self {
            Self::FrameConfig(v) => crate::wire::Layout::encode_data(v, w),
            Self::FrameConfigResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::EchoControl(v) => crate::wire::Layout::encode_data(v, w),
            Self::EchoControlResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::EcefPosition(v) => crate::wire::Layout::encode_data(v, w),
            Self::LlhPosition(v) => crate::wire::Layout::encode_data(v, w),
            Self::HeightAboveEllipsoid(v) => crate::wire::Layout::encode_data(v, w),
            Self::EcefVelocity(v) => crate::wire::Layout::encode_data(v, w),
            Self::NedVelocity(v) => crate::wire::Layout::encode_data(v, w),
            Self::BodyFrameVelocity(v) => crate::wire::Layout::encode_data(v, w),
            Self::TrueHeading(v) => crate::wire::Layout::encode_data(v, w),
            Self::MagneticField(v) => crate::wire::Layout::encode_data(v, w),
            Self::Pressure(v) => crate::wire::Layout::encode_data(v, w),
        }
    }

    /// Writes the canonical JSON of the values (`{...}`).
    pub fn write_values_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::FrameConfig(v) => crate::wire::Wire::write_json(v, w),
            Self::FrameConfigResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::EchoControl(v) => crate::wire::Wire::write_json(v, w),
            Self::EchoControlResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::EcefPosition(v) => crate::wire::Wire::write_json(v, w),
            Self::LlhPosition(v) => crate::wire::Wire::write_json(v, w),
            Self::HeightAboveEllipsoid(v) => crate::wire::Wire::write_json(v, w),
            Self::EcefVelocity(v) => crate::wire::Wire::write_json(v, w),
            Self::NedVelocity(v) => crate::wire::Wire::write_json(v, w),
            Self::BodyFrameVelocity(v) => crate::wire::Wire::write_json(v, w),
            Self::TrueHeading(v) => crate::wire::Wire::write_json(v, w),
            Self::MagneticField(v) => crate::wire::Wire::write_json(v, w),
            Self::Pressure(v) => crate::wire::Wire::write_json(v, w),
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
            0x01 => {
                Some(<FrameConfig as crate::wire::Layout>::decode_data(data).map(Self::FrameConfig))
            }
            0x81 => Some(
                <FrameConfigResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::FrameConfigResponse),
            ),
            0x1F => {
                Some(<EchoControl as crate::wire::Layout>::decode_data(data).map(Self::EchoControl))
            }
            0x9F => Some(
                <EchoControlResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::EchoControlResponse),
            ),
            0x21 => Some(
                <EcefPosition as crate::wire::Layout>::decode_data(data).map(Self::EcefPosition),
            ),
            0x22 => {
                Some(<LlhPosition as crate::wire::Layout>::decode_data(data).map(Self::LlhPosition))
            }
            0x23 => Some(
                <HeightAboveEllipsoid as crate::wire::Layout>::decode_data(data)
                    .map(Self::HeightAboveEllipsoid),
            ),
            0x28 => Some(
                <EcefVelocity as crate::wire::Layout>::decode_data(data).map(Self::EcefVelocity),
            ),
            0x29 => {
                Some(<NedVelocity as crate::wire::Layout>::decode_data(data).map(Self::NedVelocity))
            }
            0x2A => Some(
                <BodyFrameVelocity as crate::wire::Layout>::decode_data(data)
                    .map(Self::BodyFrameVelocity),
            ),
            0x31 => {
                Some(<TrueHeading as crate::wire::Layout>::decode_data(data).map(Self::TrueHeading))
            }
            0x32 => Some(
                <MagneticField as crate::wire::Layout>::decode_data(data).map(Self::MagneticField),
            ),
            0x33 => Some(<Pressure as crate::wire::Layout>::decode_data(data).map(Self::Pressure)),
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
            0x01 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <FrameConfig as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::FrameConfig),
            ),
            0x81 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <FrameConfigResponse as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::FrameConfigResponse),
            ),
            0x1F => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <EchoControl as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::EchoControl),
            ),
            0x9F => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <EchoControlResponse as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::EchoControlResponse),
            ),
            0x21 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <EcefPosition as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::EcefPosition),
            ),
            0x22 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <LlhPosition as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::LlhPosition),
            ),
            0x23 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <HeightAboveEllipsoid as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::HeightAboveEllipsoid),
            ),
            0x28 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <EcefVelocity as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::EcefVelocity),
            ),
            0x29 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <NedVelocity as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::NedVelocity),
            ),
            0x2A => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <BodyFrameVelocity as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::BodyFrameVelocity),
            ),
            0x31 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <TrueHeading as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::TrueHeading),
            ),
            0x32 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <MagneticField as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::MagneticField),
            ),
            0x33 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <Pressure as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::Pressure),
            ),
            _ => None,
        }
    }
}
