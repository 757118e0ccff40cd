//! Filter Command Set. Configure, initialise and aid the navigation (Kalman) filter: reset and run it, give it an initial attitude or heading, set frame transformations and antenna offsets, choose its GNSS and heading sources, feed it external measurements and tune its noise models.
//!
//! Descriptor set 0x0D (command set):
//! one struct per field layout, and `SetField`, the enum of all its fields.

/// Descriptor set of this module.
pub const SET: u8 = 0x0D;

/// Reset filter. Put the filter back into its initialisation state. With auto-initialisation disabled, an initial attitude or heading must then be given before it runs again.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ResetFilter {}

impl Default for ResetFilter {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ResetFilter {
    const ZERO: Self = Self {};
    const FIXED_SIZE: Option<usize> = Some(0);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let _ = r;
        Ok(Self {})
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let _ = w;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        w.write_str("{}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ResetFilter {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        crate::json_read::Obj::new(v, &[])?;
        Ok(Self {})
    }
}

impl ResetFilter {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for ResetFilter {
    const DESCRIPTOR: u8 = 0x01;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "reset_filter";
}

/// Set initial attitude. Initialise the filter attitude from Euler angles of the sensor body frame relative to the local NED frame. Only accepted in the INIT state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SetInitialAttitude {
    /// Roll angle, in \[-pi, pi\]. Units: rad.
    pub roll: f32,
    /// Pitch angle, in \[-pi/2, pi/2\]. Units: rad.
    pub pitch: f32,
    /// Heading (yaw) angle, in \[-pi, pi\]. Units: rad.
    pub heading: f32,
}

impl Default for SetInitialAttitude {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SetInitialAttitude {
    const ZERO: Self = Self {
        roll: <f32 as crate::wire::Wire>::ZERO,
        pitch: <f32 as crate::wire::Wire>::ZERO,
        heading: <f32 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(12);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_roll = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("roll"))?;
        let p_pitch = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("pitch"))?;
        let p_heading = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("heading"))?;
        Ok(Self {
            roll: p_roll,
            pitch: p_pitch,
            heading: p_heading,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.roll;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("roll"))?;
        let v = &self.pitch;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("pitch"))?;
        let v = &self.heading;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("heading"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.roll;
        crate::json::key(w, &mut first, "roll")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.pitch;
        crate::json::key(w, &mut first, "pitch")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.heading;
        crate::json::key(w, &mut first, "heading")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SetInitialAttitude {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["roll", "pitch", "heading"])?;
        let p_roll = o.req("roll", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_pitch = o.req("pitch", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_heading = o.req("heading", <f32 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            roll: p_roll,
            pitch: p_pitch,
            heading: p_heading,
        })
    }
}

impl SetInitialAttitude {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for SetInitialAttitude {
    const DESCRIPTOR: u8 = 0x02;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "set_initial_attitude";
}

/// Set initial heading. Initialise the filter heading; roll and pitch come from the accelerometers. GX5-45: only accepted in the INIT state. CV7: the heading estimate is reset to this value, unless magnetometer aiding is enabled, in which case the magnetic heading is used instead.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SetInitialHeading {
    /// Initial heading, in \[-pi, pi\]. Units: rad.
    pub heading: f32,
}

impl Default for SetInitialHeading {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SetInitialHeading {
    const ZERO: Self = Self {
        heading: <f32 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(4);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_heading = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("heading"))?;
        Ok(Self { heading: p_heading })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.heading;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("heading"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.heading;
        crate::json::key(w, &mut first, "heading")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SetInitialHeading {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["heading"])?;
        let p_heading = o.req("heading", <f32 as crate::json_read::FromJson>::from_json)?;
        Ok(Self { heading: p_heading })
    }
}

impl SetInitialHeading {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for SetInitialHeading {
    const DESCRIPTOR: u8 = 0x03;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "set_initial_heading";
}

/// Run navigation filter. Start the filter by hand when the initialisation configuration asks it to wait for a run command; until then it stays in initialisation mode.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RunFilter {}

impl Default for RunFilter {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for RunFilter {
    const ZERO: Self = Self {};
    const FIXED_SIZE: Option<usize> = Some(0);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let _ = r;
        Ok(Self {})
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let _ = w;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        w.write_str("{}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for RunFilter {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        crate::json_read::Obj::new(v, &[])?;
        Ok(Self {})
    }
}

impl RunFilter {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for RunFilter {
    const DESCRIPTOR: u8 = 0x05;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "run_filter";
}

/// Vehicle dynamics mode. Set, read, save, load or reset the vehicle dynamics mode of the filter.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VehicleDynamicsMode {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// New dynamics mode. Sent for: write.
    pub mode: Option<crate::types::VehicleDynamicsMode>,
}

impl Default for VehicleDynamicsMode {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for VehicleDynamicsMode {
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
                <crate::types::VehicleDynamicsMode as crate::wire::Wire>::decode(r)
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
impl crate::json_read::FromJson for VehicleDynamicsMode {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "mode"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_mode = o.opt(
            "mode",
            <crate::types::VehicleDynamicsMode as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            mode: p_mode,
        })
    }
}

impl VehicleDynamicsMode {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for VehicleDynamicsMode {
    const DESCRIPTOR: u8 = 0x10;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "vehicle_dynamics_mode";
}

/// Vehicle dynamics mode (response). Current vehicle dynamics mode (reply to read).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VehicleDynamicsModeResponse {
    /// Current dynamics mode.
    pub mode: crate::types::VehicleDynamicsMode,
}

impl Default for VehicleDynamicsModeResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for VehicleDynamicsModeResponse {
    const ZERO: Self = Self {
        mode: <crate::types::VehicleDynamicsMode as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(1);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_mode = <crate::types::VehicleDynamicsMode as crate::wire::Wire>::decode(r)
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
impl crate::json_read::FromJson for VehicleDynamicsModeResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["mode"])?;
        let p_mode = o.req(
            "mode",
            <crate::types::VehicleDynamicsMode as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self { mode: p_mode })
    }
}

impl VehicleDynamicsModeResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for VehicleDynamicsModeResponse {
    const DESCRIPTOR: u8 = 0x80;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "vehicle_dynamics_mode_response";
}

/// Sensor to vehicle frame transformation. Euler angles (roll, pitch, yaw) of the rotation from the sensor body frame to the vehicle frame. Applies to the scaled IMU vectors, delta theta/velocity and the filter's orientation, linear acceleration, angular rate and gravity outputs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SensorToVehicleTransform {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Roll angle of the sensor-to-vehicle rotation. Units: rad. Sent for: write.
    pub roll: Option<f32>,
    /// Pitch angle of the sensor-to-vehicle rotation. Units: rad. Sent for: write.
    pub pitch: Option<f32>,
    /// Yaw angle of the sensor-to-vehicle rotation. Units: rad. Sent for: write.
    pub yaw: Option<f32>,
}

impl Default for SensorToVehicleTransform {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SensorToVehicleTransform {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        roll: None,
        pitch: None,
        yaw: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_roll = if r.left() > 0 {
            Some(<f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("roll"))?)
        } else {
            None
        };
        let p_pitch = if r.left() > 0 {
            Some(<f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("pitch"))?)
        } else {
            None
        };
        let p_yaw = if r.left() > 0 {
            Some(<f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("yaw"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            roll: p_roll,
            pitch: p_pitch,
            yaw: p_yaw,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.roll {
            optionals.present("roll")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("roll"))?;
        } else {
            optionals.absent("roll");
        }
        if let Some(v) = &self.pitch {
            optionals.present("pitch")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("pitch"))?;
        } else {
            optionals.absent("pitch");
        }
        if let Some(v) = &self.yaw {
            optionals.present("yaw")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("yaw"))?;
        } else {
            optionals.absent("yaw");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.roll {
            crate::json::key(w, &mut first, "roll")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.pitch {
            crate::json::key(w, &mut first, "pitch")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.yaw {
            crate::json::key(w, &mut first, "yaw")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SensorToVehicleTransform {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "roll", "pitch", "yaw"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_roll = o.opt("roll", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_pitch = o.opt("pitch", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_yaw = o.opt("yaw", <f32 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            roll: p_roll,
            pitch: p_pitch,
            yaw: p_yaw,
        })
    }
}

impl SensorToVehicleTransform {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for SensorToVehicleTransform {
    const DESCRIPTOR: u8 = 0x11;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "sensor_to_vehicle_transform";
}

/// Sensor to vehicle frame transformation (response). Current sensor-to-vehicle Euler angles (reply to read).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SensorToVehicleTransformResponse {
    /// Roll angle. Units: rad.
    pub roll: f32,
    /// Pitch angle. Units: rad.
    pub pitch: f32,
    /// Yaw angle. Units: rad.
    pub yaw: f32,
}

impl Default for SensorToVehicleTransformResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SensorToVehicleTransformResponse {
    const ZERO: Self = Self {
        roll: <f32 as crate::wire::Wire>::ZERO,
        pitch: <f32 as crate::wire::Wire>::ZERO,
        yaw: <f32 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(12);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_roll = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("roll"))?;
        let p_pitch = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("pitch"))?;
        let p_yaw = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("yaw"))?;
        Ok(Self {
            roll: p_roll,
            pitch: p_pitch,
            yaw: p_yaw,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.roll;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("roll"))?;
        let v = &self.pitch;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("pitch"))?;
        let v = &self.yaw;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("yaw"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.roll;
        crate::json::key(w, &mut first, "roll")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.pitch;
        crate::json::key(w, &mut first, "pitch")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.yaw;
        crate::json::key(w, &mut first, "yaw")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SensorToVehicleTransformResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["roll", "pitch", "yaw"])?;
        let p_roll = o.req("roll", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_pitch = o.req("pitch", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_yaw = o.req("yaw", <f32 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            roll: p_roll,
            pitch: p_pitch,
            yaw: p_yaw,
        })
    }
}

impl SensorToVehicleTransformResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for SensorToVehicleTransformResponse {
    const DESCRIPTOR: u8 = 0x81;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "sensor_to_vehicle_transform_response";
}

/// Sensor to vehicle frame offset. Offset from the sensor to the vehicle reference point, in the sensor frame, added to the estimated LLH position. Not a lever arm: no inertial compensation. Magnitude at most 10 m.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SensorToVehicleOffset {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// (x, y, z) offset in the sensor body frame. Units: m. Sent for: write.
    pub offset: Option<[f32; 3]>,
}

impl Default for SensorToVehicleOffset {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SensorToVehicleOffset {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        offset: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_offset = if r.left() > 0 {
            Some(<[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("offset"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            offset: p_offset,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.offset {
            optionals.present("offset")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("offset"))?;
        } else {
            optionals.absent("offset");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.offset {
            crate::json::key(w, &mut first, "offset")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SensorToVehicleOffset {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "offset"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_offset = o.opt(
            "offset",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            offset: p_offset,
        })
    }
}

impl SensorToVehicleOffset {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for SensorToVehicleOffset {
    const DESCRIPTOR: u8 = 0x12;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "sensor_to_vehicle_offset";
}

/// Sensor to vehicle frame offset (response). Current sensor-to-vehicle offset (reply to read).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SensorToVehicleOffsetResponse {
    /// (x, y, z) offset in the sensor body frame. Units: m.
    pub offset: [f32; 3],
}

impl Default for SensorToVehicleOffsetResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SensorToVehicleOffsetResponse {
    const ZERO: Self = Self {
        offset: <[f32; 3] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(12);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_offset = <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("offset"))?;
        Ok(Self { offset: p_offset })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.offset;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("offset"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.offset;
        crate::json::key(w, &mut first, "offset")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SensorToVehicleOffsetResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["offset"])?;
        let p_offset = o.req(
            "offset",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self { offset: p_offset })
    }
}

impl SensorToVehicleOffsetResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for SensorToVehicleOffsetResponse {
    const DESCRIPTOR: u8 = 0x82;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "sensor_to_vehicle_offset_response";
}

/// GNSS antenna offset. Offset from the sensor origin to the GNSS antenna RF (phase) centre; magnitude at most 10 m. GX5-45 (5-series): expressed in the sensor frame. CV7 (7-series): expressed in the vehicle frame; also used for NMEA input over GPIO.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AntennaOffset {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// (x, y, z) antenna offset (sensor frame on GX5-45, vehicle frame on CV7). Units: m. Sent for: write.
    pub offset: Option<[f32; 3]>,
}

impl Default for AntennaOffset {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AntennaOffset {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        offset: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_offset = if r.left() > 0 {
            Some(<[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("offset"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            offset: p_offset,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.offset {
            optionals.present("offset")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("offset"))?;
        } else {
            optionals.absent("offset");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.offset {
            crate::json::key(w, &mut first, "offset")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AntennaOffset {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "offset"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_offset = o.opt(
            "offset",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            offset: p_offset,
        })
    }
}

impl AntennaOffset {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for AntennaOffset {
    const DESCRIPTOR: u8 = 0x13;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "antenna_offset";
}

/// GNSS antenna offset (response). Current antenna offset (reply to read).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AntennaOffsetResponse {
    /// (x, y, z) antenna offset. Units: m.
    pub offset: [f32; 3],
}

impl Default for AntennaOffsetResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AntennaOffsetResponse {
    const ZERO: Self = Self {
        offset: <[f32; 3] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(12);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_offset = <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("offset"))?;
        Ok(Self { offset: p_offset })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.offset;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("offset"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.offset;
        crate::json::key(w, &mut first, "offset")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AntennaOffsetResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["offset"])?;
        let p_offset = o.req(
            "offset",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self { offset: p_offset })
    }
}

impl AntennaOffsetResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for AntennaOffsetResponse {
    const DESCRIPTOR: u8 = 0x83;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "antenna_offset_response";
}

/// Estimation control flags. Select which optional parameters the Kalman filter estimates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EstimationControl {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// States to estimate. Sent for: write.
    pub flags: Option<crate::types::EstimationControlFlags>,
}

impl Default for EstimationControl {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for EstimationControl {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        flags: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_flags = if r.left() > 0 {
            Some(
                <crate::types::EstimationControlFlags as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("flags"))?,
            )
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            flags: p_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.flags {
            optionals.present("flags")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("flags"))?;
        } else {
            optionals.absent("flags");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.flags {
            crate::json::key(w, &mut first, "flags")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for EstimationControl {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "flags"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_flags = o.opt(
            "flags",
            <crate::types::EstimationControlFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            flags: p_flags,
        })
    }
}

impl EstimationControl {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for EstimationControl {
    const DESCRIPTOR: u8 = 0x14;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "estimation_control";
}

/// Estimation control flags (response). Current estimation control flags (reply to read).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EstimationControlResponse {
    /// States being estimated.
    pub flags: crate::types::EstimationControlFlags,
}

impl Default for EstimationControlResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for EstimationControlResponse {
    const ZERO: Self = Self {
        flags: <crate::types::EstimationControlFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(2);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_flags = <crate::types::EstimationControlFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("flags"))?;
        Ok(Self { flags: p_flags })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.flags;
        crate::json::key(w, &mut first, "flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for EstimationControlResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["flags"])?;
        let p_flags = o.req(
            "flags",
            <crate::types::EstimationControlFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self { flags: p_flags })
    }
}

impl EstimationControlResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for EstimationControlResponse {
    const DESCRIPTOR: u8 = 0x84;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "estimation_control_response";
}

/// GNSS source control. Choose the source of GNSS updates to the filter. Changing it while running may put the filter back in its init state until data from the new source arrives.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GnssSourceControl {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// GNSS source. Sent for: write.
    pub source: Option<crate::types::FilterGnssSource>,
}

impl Default for GnssSourceControl {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GnssSourceControl {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        source: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_source = if r.left() > 0 {
            Some(
                <crate::types::FilterGnssSource as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("source"))?,
            )
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            source: p_source,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.source {
            optionals.present("source")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("source"))?;
        } else {
            optionals.absent("source");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.source {
            crate::json::key(w, &mut first, "source")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GnssSourceControl {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "source"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_source = o.opt(
            "source",
            <crate::types::FilterGnssSource as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            source: p_source,
        })
    }
}

impl GnssSourceControl {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for GnssSourceControl {
    const DESCRIPTOR: u8 = 0x15;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "gnss_source_control";
}

/// GNSS source control (response). Current GNSS source (reply to read).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GnssSourceControlResponse {
    /// GNSS source.
    pub source: crate::types::FilterGnssSource,
}

impl Default for GnssSourceControlResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GnssSourceControlResponse {
    const ZERO: Self = Self {
        source: <crate::types::FilterGnssSource as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(1);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_source = <crate::types::FilterGnssSource as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("source"))?;
        Ok(Self { source: p_source })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.source;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("source"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.source;
        crate::json::key(w, &mut first, "source")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GnssSourceControlResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["source"])?;
        let p_source = o.req(
            "source",
            <crate::types::FilterGnssSource as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self { source: p_source })
    }
}

impl GnssSourceControlResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for GnssSourceControlResponse {
    const DESCRIPTOR: u8 = 0x86;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "gnss_source_control_response";
}

/// External GNSS update. Give the filter one GNSS measurement from an external receiver. Only used (otherwise ignored or NACKed) when the GNSS source is external; at most 20 Hz.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ExternalGnssUpdate {
    /// GPS time of week. Units: s.
    pub gps_tow: f64,
    /// GPS week number. Units: weeks.
    pub gps_week: u16,
    /// Latitude. Units: deg.
    pub latitude: f64,
    /// Longitude. Units: deg.
    pub longitude: f64,
    /// Height above the WGS84 ellipsoid. Units: m.
    pub height: f64,
    /// (north, east, down) velocity. Units: m/s.
    pub velocity: [f32; 3],
    /// (north, east, down) position 1-sigma uncertainty. Units: m.
    pub position_uncertainty: [f32; 3],
    /// (north, east, down) velocity 1-sigma uncertainty. Units: m/s.
    pub velocity_uncertainty: [f32; 3],
}

impl Default for ExternalGnssUpdate {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ExternalGnssUpdate {
    const ZERO: Self = Self {
        gps_tow: <f64 as crate::wire::Wire>::ZERO,
        gps_week: <u16 as crate::wire::Wire>::ZERO,
        latitude: <f64 as crate::wire::Wire>::ZERO,
        longitude: <f64 as crate::wire::Wire>::ZERO,
        height: <f64 as crate::wire::Wire>::ZERO,
        velocity: <[f32; 3] as crate::wire::Wire>::ZERO,
        position_uncertainty: <[f32; 3] as crate::wire::Wire>::ZERO,
        velocity_uncertainty: <[f32; 3] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(70);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_gps_tow = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("gps_tow"))?;
        let p_gps_week = <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("gps_week"))?;
        let p_latitude = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("latitude"))?;
        let p_longitude = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("longitude"))?;
        let p_height = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("height"))?;
        let p_velocity =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("velocity"))?;
        let p_position_uncertainty =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("position_uncertainty"))?;
        let p_velocity_uncertainty =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("velocity_uncertainty"))?;
        Ok(Self {
            gps_tow: p_gps_tow,
            gps_week: p_gps_week,
            latitude: p_latitude,
            longitude: p_longitude,
            height: p_height,
            velocity: p_velocity,
            position_uncertainty: p_position_uncertainty,
            velocity_uncertainty: p_velocity_uncertainty,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.gps_tow;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("gps_tow"))?;
        let v = &self.gps_week;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("gps_week"))?;
        let v = &self.latitude;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("latitude"))?;
        let v = &self.longitude;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("longitude"))?;
        let v = &self.height;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("height"))?;
        let v = &self.velocity;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("velocity"))?;
        let v = &self.position_uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("position_uncertainty"))?;
        let v = &self.velocity_uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("velocity_uncertainty"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.gps_tow;
        crate::json::key(w, &mut first, "gps_tow")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.gps_week;
        crate::json::key(w, &mut first, "gps_week")?;
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
        let v = &self.velocity;
        crate::json::key(w, &mut first, "velocity")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.position_uncertainty;
        crate::json::key(w, &mut first, "position_uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.velocity_uncertainty;
        crate::json::key(w, &mut first, "velocity_uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ExternalGnssUpdate {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "gps_tow",
                "gps_week",
                "latitude",
                "longitude",
                "height",
                "velocity",
                "position_uncertainty",
                "velocity_uncertainty",
            ],
        )?;
        let p_gps_tow = o.req("gps_tow", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_gps_week = o.req("gps_week", <u16 as crate::json_read::FromJson>::from_json)?;
        let p_latitude = o.req("latitude", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_longitude = o.req("longitude", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_height = o.req("height", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_velocity = o.req(
            "velocity",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_position_uncertainty = o.req(
            "position_uncertainty",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_velocity_uncertainty = o.req(
            "velocity_uncertainty",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            gps_tow: p_gps_tow,
            gps_week: p_gps_week,
            latitude: p_latitude,
            longitude: p_longitude,
            height: p_height,
            velocity: p_velocity,
            position_uncertainty: p_position_uncertainty,
            velocity_uncertainty: p_velocity_uncertainty,
        })
    }
}

impl ExternalGnssUpdate {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for ExternalGnssUpdate {
    const DESCRIPTOR: u8 = 0x16;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "external_gnss_update";
}

/// External heading update. Give the filter one heading measurement (sensor frame relative to NED) from an external source. Only used when external heading aiding is enabled, otherwise NACKed; uncertainties of 0 or less are NACKed; a true (or magnetic) heading is NACKed when the declination source is invalid (see the manuals for which model refuses which).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ExternalHeadingUpdate {
    /// Heading angle, within +-pi. Units: rad.
    pub heading: f32,
    /// Heading 1-sigma uncertainty; must be greater than 0. Units: rad.
    pub heading_uncertainty: f32,
    /// True or magnetic heading.
    pub r#type: crate::types::ExternalHeadingType,
}

impl Default for ExternalHeadingUpdate {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ExternalHeadingUpdate {
    const ZERO: Self = Self {
        heading: <f32 as crate::wire::Wire>::ZERO,
        heading_uncertainty: <f32 as crate::wire::Wire>::ZERO,
        r#type: <crate::types::ExternalHeadingType as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(9);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_heading = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("heading"))?;
        let p_heading_uncertainty =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("heading_uncertainty"))?;
        let p_type = <crate::types::ExternalHeadingType as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("type"))?;
        Ok(Self {
            heading: p_heading,
            heading_uncertainty: p_heading_uncertainty,
            r#type: p_type,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.heading;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("heading"))?;
        let v = &self.heading_uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("heading_uncertainty"))?;
        let v = &self.r#type;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("type"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.heading;
        crate::json::key(w, &mut first, "heading")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.heading_uncertainty;
        crate::json::key(w, &mut first, "heading_uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.r#type;
        crate::json::key(w, &mut first, "type")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ExternalHeadingUpdate {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["heading", "heading_uncertainty", "type"])?;
        let p_heading = o.req("heading", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_heading_uncertainty = o.req(
            "heading_uncertainty",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_type = o.req(
            "type",
            <crate::types::ExternalHeadingType as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            heading: p_heading,
            heading_uncertainty: p_heading_uncertainty,
            r#type: p_type,
        })
    }
}

impl ExternalHeadingUpdate {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for ExternalHeadingUpdate {
    const DESCRIPTOR: u8 = 0x17;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "external_heading_update";
}

/// Heading update control. Select the aiding source(s) of filter heading updates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HeadingUpdateControl {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Heading aiding source (the manual's "Enable Flag"). Sent for: write.
    pub source: Option<crate::types::HeadingUpdateSource>,
}

impl Default for HeadingUpdateControl {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for HeadingUpdateControl {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        source: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_source = if r.left() > 0 {
            Some(
                <crate::types::HeadingUpdateSource as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("source"))?,
            )
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            source: p_source,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.source {
            optionals.present("source")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("source"))?;
        } else {
            optionals.absent("source");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.source {
            crate::json::key(w, &mut first, "source")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for HeadingUpdateControl {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "source"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_source = o.opt(
            "source",
            <crate::types::HeadingUpdateSource as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            source: p_source,
        })
    }
}

impl HeadingUpdateControl {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for HeadingUpdateControl {
    const DESCRIPTOR: u8 = 0x18;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "heading_update_control";
}

/// Heading update control (response). Current heading update source (reply to read).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HeadingUpdateControlResponse {
    /// Heading aiding source.
    pub source: crate::types::HeadingUpdateSource,
}

impl Default for HeadingUpdateControlResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for HeadingUpdateControlResponse {
    const ZERO: Self = Self {
        source: <crate::types::HeadingUpdateSource as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(1);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_source = <crate::types::HeadingUpdateSource as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("source"))?;
        Ok(Self { source: p_source })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.source;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("source"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.source;
        crate::json::key(w, &mut first, "source")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for HeadingUpdateControlResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["source"])?;
        let p_source = o.req(
            "source",
            <crate::types::HeadingUpdateSource as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self { source: p_source })
    }
}

impl HeadingUpdateControlResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for HeadingUpdateControlResponse {
    const DESCRIPTOR: u8 = 0x87;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "heading_update_control_response";
}

/// Auto-initialization control. Enable or disable automatic filter initialisation at startup (needs a valid heading source; otherwise use Set initial heading or Set initial attitude).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AutoInitControl {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// 0 disables, 1 enables auto-initialisation. Sent for: write.
    pub enable: Option<u8>,
}

impl Default for AutoInitControl {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AutoInitControl {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        enable: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_enable = if r.left() > 0 {
            Some(<u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("enable"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            enable: p_enable,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.enable {
            optionals.present("enable")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("enable"))?;
        } else {
            optionals.absent("enable");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.enable {
            crate::json::key(w, &mut first, "enable")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AutoInitControl {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "enable"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_enable = o.opt("enable", <u8 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            enable: p_enable,
        })
    }
}

impl AutoInitControl {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for AutoInitControl {
    const DESCRIPTOR: u8 = 0x19;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "auto_init_control";
}

/// Auto-initialization control (response). Current auto-initialisation setting (reply to read).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AutoInitControlResponse {
    /// 0 disabled, 1 enabled.
    pub enable: u8,
}

impl Default for AutoInitControlResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AutoInitControlResponse {
    const ZERO: Self = Self {
        enable: <u8 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(1);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_enable = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("enable"))?;
        Ok(Self { enable: p_enable })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.enable;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("enable"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.enable;
        crate::json::key(w, &mut first, "enable")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AutoInitControlResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["enable"])?;
        let p_enable = o.req("enable", <u8 as crate::json_read::FromJson>::from_json)?;
        Ok(Self { enable: p_enable })
    }
}

impl AutoInitControlResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for AutoInitControlResponse {
    const DESCRIPTOR: u8 = 0x88;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "auto_init_control_response";
}

/// Accelerometer noise standard deviation. Expected accelerometer (process) noise, 1-sigma per axis, used to tune the filter. Each value must be greater than 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AccelNoise {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// (x, y, z) accelerometer noise 1-sigma. Units: m/s^2. Sent for: write.
    pub noise: Option<[f32; 3]>,
}

impl Default for AccelNoise {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AccelNoise {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        noise: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_noise = if r.left() > 0 {
            Some(<[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("noise"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            noise: p_noise,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.noise {
            optionals.present("noise")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("noise"))?;
        } else {
            optionals.absent("noise");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.noise {
            crate::json::key(w, &mut first, "noise")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AccelNoise {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "noise"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_noise = o.opt("noise", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            noise: p_noise,
        })
    }
}

impl AccelNoise {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for AccelNoise {
    const DESCRIPTOR: u8 = 0x1A;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "accel_noise";
}

/// Accelerometer noise standard deviation (response). Current accelerometer noise 1-sigma (reply to read).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AccelNoiseResponse {
    /// (x, y, z) accelerometer noise 1-sigma. Units: m/s^2.
    pub noise: [f32; 3],
}

impl Default for AccelNoiseResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AccelNoiseResponse {
    const ZERO: Self = Self {
        noise: <[f32; 3] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(12);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_noise = <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("noise"))?;
        Ok(Self { noise: p_noise })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.noise;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("noise"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.noise;
        crate::json::key(w, &mut first, "noise")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AccelNoiseResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["noise"])?;
        let p_noise = o.req("noise", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        Ok(Self { noise: p_noise })
    }
}

impl AccelNoiseResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for AccelNoiseResponse {
    const DESCRIPTOR: u8 = 0x89;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "accel_noise_response";
}

/// Gyroscope noise standard deviation. Expected gyro (process) noise, 1-sigma per axis, used to tune the filter. Each value must be greater than 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GyroNoise {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// (x, y, z) gyro noise 1-sigma. Units: rad/s. Sent for: write.
    pub noise: Option<[f32; 3]>,
}

impl Default for GyroNoise {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GyroNoise {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        noise: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_noise = if r.left() > 0 {
            Some(<[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("noise"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            noise: p_noise,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.noise {
            optionals.present("noise")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("noise"))?;
        } else {
            optionals.absent("noise");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.noise {
            crate::json::key(w, &mut first, "noise")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GyroNoise {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "noise"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_noise = o.opt("noise", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            noise: p_noise,
        })
    }
}

impl GyroNoise {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for GyroNoise {
    const DESCRIPTOR: u8 = 0x1B;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "gyro_noise";
}

/// Gyroscope noise standard deviation (response). Current gyro noise 1-sigma (reply to read).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GyroNoiseResponse {
    /// (x, y, z) gyro noise 1-sigma. Units: rad/s.
    pub noise: [f32; 3],
}

impl Default for GyroNoiseResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GyroNoiseResponse {
    const ZERO: Self = Self {
        noise: <[f32; 3] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(12);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_noise = <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("noise"))?;
        Ok(Self { noise: p_noise })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.noise;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("noise"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.noise;
        crate::json::key(w, &mut first, "noise")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GyroNoiseResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["noise"])?;
        let p_noise = o.req("noise", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        Ok(Self { noise: p_noise })
    }
}

impl GyroNoiseResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for GyroNoiseResponse {
    const DESCRIPTOR: u8 = 0x8A;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "gyro_noise_response";
}

/// Accelerometer bias model parameters. First-order (Gauss-Markov) accelerometer bias model: time constant inverse (beta) and bias noise 1-sigma per axis. Noise values must be greater than 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AccelBiasModel {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// (x, y, z) accelerometer bias beta. Units: 1/s. Sent for: write.
    pub beta: Option<[f32; 3]>,
    /// (x, y, z) accelerometer bias noise 1-sigma. Units: m/s^2. Sent for: write.
    pub noise: Option<[f32; 3]>,
}

impl Default for AccelBiasModel {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AccelBiasModel {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        beta: None,
        noise: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_beta = if r.left() > 0 {
            Some(<[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("beta"))?)
        } else {
            None
        };
        let p_noise = if r.left() > 0 {
            Some(<[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("noise"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            beta: p_beta,
            noise: p_noise,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.beta {
            optionals.present("beta")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("beta"))?;
        } else {
            optionals.absent("beta");
        }
        if let Some(v) = &self.noise {
            optionals.present("noise")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("noise"))?;
        } else {
            optionals.absent("noise");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.beta {
            crate::json::key(w, &mut first, "beta")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.noise {
            crate::json::key(w, &mut first, "noise")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AccelBiasModel {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "beta", "noise"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_beta = o.opt("beta", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        let p_noise = o.opt("noise", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            beta: p_beta,
            noise: p_noise,
        })
    }
}

impl AccelBiasModel {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for AccelBiasModel {
    const DESCRIPTOR: u8 = 0x1C;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "accel_bias_model";
}

/// Accelerometer bias model parameters (response). Current accelerometer bias model (reply to read).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AccelBiasModelResponse {
    /// (x, y, z) accelerometer bias beta. Units: 1/s.
    pub beta: [f32; 3],
    /// (x, y, z) accelerometer bias noise 1-sigma. Units: m/s^2.
    pub noise: [f32; 3],
}

impl Default for AccelBiasModelResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AccelBiasModelResponse {
    const ZERO: Self = Self {
        beta: <[f32; 3] as crate::wire::Wire>::ZERO,
        noise: <[f32; 3] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(24);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_beta = <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("beta"))?;
        let p_noise = <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("noise"))?;
        Ok(Self {
            beta: p_beta,
            noise: p_noise,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.beta;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("beta"))?;
        let v = &self.noise;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("noise"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.beta;
        crate::json::key(w, &mut first, "beta")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.noise;
        crate::json::key(w, &mut first, "noise")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AccelBiasModelResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["beta", "noise"])?;
        let p_beta = o.req("beta", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        let p_noise = o.req("noise", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            beta: p_beta,
            noise: p_noise,
        })
    }
}

impl AccelBiasModelResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for AccelBiasModelResponse {
    const DESCRIPTOR: u8 = 0x8B;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "accel_bias_model_response";
}

/// Gyroscope bias model parameters. First-order (Gauss-Markov) gyro bias model: time constant inverse (beta) and bias noise 1-sigma per axis. Noise values must be greater than 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GyroBiasModel {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// (x, y, z) gyro bias beta. Units: 1/s. Sent for: write.
    pub beta: Option<[f32; 3]>,
    /// (x, y, z) gyro bias noise 1-sigma. Units: rad/s. Sent for: write.
    pub noise: Option<[f32; 3]>,
}

impl Default for GyroBiasModel {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GyroBiasModel {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        beta: None,
        noise: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_beta = if r.left() > 0 {
            Some(<[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("beta"))?)
        } else {
            None
        };
        let p_noise = if r.left() > 0 {
            Some(<[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("noise"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            beta: p_beta,
            noise: p_noise,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.beta {
            optionals.present("beta")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("beta"))?;
        } else {
            optionals.absent("beta");
        }
        if let Some(v) = &self.noise {
            optionals.present("noise")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("noise"))?;
        } else {
            optionals.absent("noise");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.beta {
            crate::json::key(w, &mut first, "beta")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.noise {
            crate::json::key(w, &mut first, "noise")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GyroBiasModel {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "beta", "noise"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_beta = o.opt("beta", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        let p_noise = o.opt("noise", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            beta: p_beta,
            noise: p_noise,
        })
    }
}

impl GyroBiasModel {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for GyroBiasModel {
    const DESCRIPTOR: u8 = 0x1D;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "gyro_bias_model";
}

/// Gyroscope bias model parameters (response). Current gyro bias model (reply to read).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GyroBiasModelResponse {
    /// (x, y, z) gyro bias beta. Units: 1/s.
    pub beta: [f32; 3],
    /// (x, y, z) gyro bias noise 1-sigma. Units: rad/s.
    pub noise: [f32; 3],
}

impl Default for GyroBiasModelResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GyroBiasModelResponse {
    const ZERO: Self = Self {
        beta: <[f32; 3] as crate::wire::Wire>::ZERO,
        noise: <[f32; 3] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(24);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_beta = <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("beta"))?;
        let p_noise = <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("noise"))?;
        Ok(Self {
            beta: p_beta,
            noise: p_noise,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.beta;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("beta"))?;
        let v = &self.noise;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("noise"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.beta;
        crate::json::key(w, &mut first, "beta")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.noise;
        crate::json::key(w, &mut first, "noise")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GyroBiasModelResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["beta", "noise"])?;
        let p_beta = o.req("beta", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        let p_noise = o.req("noise", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            beta: p_beta,
            noise: p_noise,
        })
    }
}

impl GyroBiasModelResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for GyroBiasModelResponse {
    const DESCRIPTOR: u8 = 0x8C;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "gyro_bias_model_response";
}

/// Zero velocity update (ZUPT) control. Enable zero-velocity updates, applied when the GNSS velocity magnitude is at or below the threshold. Negative thresholds are NACKed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ZuptControl {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// 0 disables, 1 enables ZUPTs. Sent for: write.
    pub enable: Option<u8>,
    /// Velocity magnitude at or below which a ZUPT is applied. Units: m/s. Sent for: write.
    pub threshold: Option<f32>,
}

impl Default for ZuptControl {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ZuptControl {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        enable: None,
        threshold: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_enable = if r.left() > 0 {
            Some(<u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("enable"))?)
        } else {
            None
        };
        let p_threshold = if r.left() > 0 {
            Some(<f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("threshold"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            enable: p_enable,
            threshold: p_threshold,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.enable {
            optionals.present("enable")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("enable"))?;
        } else {
            optionals.absent("enable");
        }
        if let Some(v) = &self.threshold {
            optionals.present("threshold")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("threshold"))?;
        } else {
            optionals.absent("threshold");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.enable {
            crate::json::key(w, &mut first, "enable")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.threshold {
            crate::json::key(w, &mut first, "threshold")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ZuptControl {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "enable", "threshold"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_enable = o.opt("enable", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_threshold = o.opt("threshold", <f32 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            enable: p_enable,
            threshold: p_threshold,
        })
    }
}

impl ZuptControl {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for ZuptControl {
    const DESCRIPTOR: u8 = 0x1E;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "zupt_control";
}

/// Zero velocity update control (response). Current ZUPT setting (reply to read).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ZuptControlResponse {
    /// 0 disabled, 1 enabled.
    pub enable: u8,
    /// ZUPT velocity threshold. Units: m/s.
    pub threshold: f32,
}

impl Default for ZuptControlResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ZuptControlResponse {
    const ZERO: Self = Self {
        enable: <u8 as crate::wire::Wire>::ZERO,
        threshold: <f32 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(5);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_enable = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("enable"))?;
        let p_threshold = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("threshold"))?;
        Ok(Self {
            enable: p_enable,
            threshold: p_threshold,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.enable;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("enable"))?;
        let v = &self.threshold;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("threshold"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.enable;
        crate::json::key(w, &mut first, "enable")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.threshold;
        crate::json::key(w, &mut first, "threshold")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ZuptControlResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["enable", "threshold"])?;
        let p_enable = o.req("enable", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_threshold = o.req("threshold", <f32 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            enable: p_enable,
            threshold: p_threshold,
        })
    }
}

impl ZuptControlResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for ZuptControlResponse {
    const DESCRIPTOR: u8 = 0x8D;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "zupt_control_response";
}

/// External heading update with timestamp. External heading measurement tagged with the GPS time it was taken; more accurate than 0x0D,0x17 under high angular rates. Same acceptance rules as 0x0D,0x17; at most 20 Hz on the GX5-45.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ExternalHeadingUpdateWithTime {
    /// GPS time of week of the measurement. Units: s.
    pub gps_tow: f64,
    /// GPS week number (not modulo 1024). Units: weeks.
    pub gps_week: u16,
    /// Heading angle from true north, within +-pi. Units: rad.
    pub heading: f32,
    /// Heading 1-sigma uncertainty; must be greater than 0. Units: rad.
    pub heading_uncertainty: f32,
    /// True or magnetic heading.
    pub r#type: crate::types::ExternalHeadingType,
}

impl Default for ExternalHeadingUpdateWithTime {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ExternalHeadingUpdateWithTime {
    const ZERO: Self = Self {
        gps_tow: <f64 as crate::wire::Wire>::ZERO,
        gps_week: <u16 as crate::wire::Wire>::ZERO,
        heading: <f32 as crate::wire::Wire>::ZERO,
        heading_uncertainty: <f32 as crate::wire::Wire>::ZERO,
        r#type: <crate::types::ExternalHeadingType as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(19);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_gps_tow = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("gps_tow"))?;
        let p_gps_week = <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("gps_week"))?;
        let p_heading = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("heading"))?;
        let p_heading_uncertainty =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("heading_uncertainty"))?;
        let p_type = <crate::types::ExternalHeadingType as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("type"))?;
        Ok(Self {
            gps_tow: p_gps_tow,
            gps_week: p_gps_week,
            heading: p_heading,
            heading_uncertainty: p_heading_uncertainty,
            r#type: p_type,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.gps_tow;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("gps_tow"))?;
        let v = &self.gps_week;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("gps_week"))?;
        let v = &self.heading;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("heading"))?;
        let v = &self.heading_uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("heading_uncertainty"))?;
        let v = &self.r#type;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("type"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.gps_tow;
        crate::json::key(w, &mut first, "gps_tow")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.gps_week;
        crate::json::key(w, &mut first, "gps_week")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.heading;
        crate::json::key(w, &mut first, "heading")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.heading_uncertainty;
        crate::json::key(w, &mut first, "heading_uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.r#type;
        crate::json::key(w, &mut first, "type")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ExternalHeadingUpdateWithTime {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "gps_tow",
                "gps_week",
                "heading",
                "heading_uncertainty",
                "type",
            ],
        )?;
        let p_gps_tow = o.req("gps_tow", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_gps_week = o.req("gps_week", <u16 as crate::json_read::FromJson>::from_json)?;
        let p_heading = o.req("heading", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_heading_uncertainty = o.req(
            "heading_uncertainty",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_type = o.req(
            "type",
            <crate::types::ExternalHeadingType as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            gps_tow: p_gps_tow,
            gps_week: p_gps_week,
            heading: p_heading,
            heading_uncertainty: p_heading_uncertainty,
            r#type: p_type,
        })
    }
}

impl ExternalHeadingUpdateWithTime {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for ExternalHeadingUpdateWithTime {
    const DESCRIPTOR: u8 = 0x1F;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "external_heading_update_with_time";
}

/// Zero angular rate update control. Control the zero angular rate update: when the magnitude of the angular rate vector is at or below the threshold, the filter applies a zero angular rate update. Negative thresholds are NACK'd.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ZeroAngularRateUpdateControl {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// 0 disables, 1 enables the update. Sent for: write.
    pub enable: Option<u8>,
    /// Angular rate magnitude at or below which the update is applied. Units: rad/s. Sent for: write.
    pub threshold: Option<f32>,
}

impl Default for ZeroAngularRateUpdateControl {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ZeroAngularRateUpdateControl {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        enable: None,
        threshold: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_enable = if r.left() > 0 {
            Some(<u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("enable"))?)
        } else {
            None
        };
        let p_threshold = if r.left() > 0 {
            Some(<f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("threshold"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            enable: p_enable,
            threshold: p_threshold,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.enable {
            optionals.present("enable")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("enable"))?;
        } else {
            optionals.absent("enable");
        }
        if let Some(v) = &self.threshold {
            optionals.present("threshold")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("threshold"))?;
        } else {
            optionals.absent("threshold");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.enable {
            crate::json::key(w, &mut first, "enable")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.threshold {
            crate::json::key(w, &mut first, "threshold")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ZeroAngularRateUpdateControl {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "enable", "threshold"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_enable = o.opt("enable", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_threshold = o.opt("threshold", <f32 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            enable: p_enable,
            threshold: p_threshold,
        })
    }
}

impl ZeroAngularRateUpdateControl {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for ZeroAngularRateUpdateControl {
    const DESCRIPTOR: u8 = 0x20;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "zero_angular_rate_update_control";
}

/// Zero angular rate update control (response). Current zero angular rate update settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ZeroAngularRateUpdateControlResponse {
    /// 0 disabled, 1 enabled.
    pub enable: u8,
    /// Angular rate threshold. Units: rad/s.
    pub threshold: f32,
}

impl Default for ZeroAngularRateUpdateControlResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ZeroAngularRateUpdateControlResponse {
    const ZERO: Self = Self {
        enable: <u8 as crate::wire::Wire>::ZERO,
        threshold: <f32 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(5);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_enable = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("enable"))?;
        let p_threshold = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("threshold"))?;
        Ok(Self {
            enable: p_enable,
            threshold: p_threshold,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.enable;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("enable"))?;
        let v = &self.threshold;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("threshold"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.enable;
        crate::json::key(w, &mut first, "enable")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.threshold;
        crate::json::key(w, &mut first, "threshold")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ZeroAngularRateUpdateControlResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["enable", "threshold"])?;
        let p_enable = o.req("enable", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_threshold = o.req("threshold", <f32 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            enable: p_enable,
            threshold: p_threshold,
        })
    }
}

impl ZeroAngularRateUpdateControlResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for ZeroAngularRateUpdateControlResponse {
    const DESCRIPTOR: u8 = 0x8E;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "zero_angular_rate_update_control_response";
}

/// Tare orientation. Use the current orientation relative to NED as the sensor-to-vehicle transformation for the selected axes. The filter must be initialized with a valid attitude, otherwise the command is NACK'd. Read is not supported.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TareOrientation {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Axes to tare; 0 resets all axes. Sent for: write.
    pub axes: Option<crate::types::TareAxes>,
}

impl Default for TareOrientation {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for TareOrientation {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        axes: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_axes = if r.left() > 0 {
            Some(
                <crate::types::TareAxes as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("axes"))?,
            )
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            axes: p_axes,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.axes {
            optionals.present("axes")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("axes"))?;
        } else {
            optionals.absent("axes");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.axes {
            crate::json::key(w, &mut first, "axes")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for TareOrientation {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "axes"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_axes = o.opt(
            "axes",
            <crate::types::TareAxes as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            axes: p_axes,
        })
    }
}

impl TareOrientation {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for TareOrientation {
    const DESCRIPTOR: u8 = 0x21;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "tare_orientation";
}

/// Commanded zero velocity update. Apply a zero velocity update now (at most 20 Hz).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CommandedZupt {}

impl Default for CommandedZupt {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for CommandedZupt {
    const ZERO: Self = Self {};
    const FIXED_SIZE: Option<usize> = Some(0);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let _ = r;
        Ok(Self {})
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let _ = w;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        w.write_str("{}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for CommandedZupt {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        crate::json_read::Obj::new(v, &[])?;
        Ok(Self {})
    }
}

impl CommandedZupt {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for CommandedZupt {
    const DESCRIPTOR: u8 = 0x22;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "commanded_zupt";
}

/// Commanded zero angular rate update. Apply a zero angular rate update now (at most 10 Hz).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CommandedZeroAngularRateUpdate {}

impl Default for CommandedZeroAngularRateUpdate {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for CommandedZeroAngularRateUpdate {
    const ZERO: Self = Self {};
    const FIXED_SIZE: Option<usize> = Some(0);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let _ = r;
        Ok(Self {})
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let _ = w;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        w.write_str("{}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for CommandedZeroAngularRateUpdate {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        crate::json_read::Obj::new(v, &[])?;
        Ok(Self {})
    }
}

impl CommandedZeroAngularRateUpdate {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for CommandedZeroAngularRateUpdate {
    const DESCRIPTOR: u8 = 0x23;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "commanded_zero_angular_rate_update";
}

/// Magnetometer capture auto calibration. Capture the current auto-calibration, fold it into the fixed hard and soft iron coefficients and reset the auto-calibration. Function save stores the coefficients as startup settings (like saving 0x0C,0x3A and 0x0C,0x3B).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MagCaptureAutoCalibration {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
}

impl Default for MagCaptureAutoCalibration {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for MagCaptureAutoCalibration {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(1);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        Ok(Self {
            function: p_function,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for MagCaptureAutoCalibration {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
        })
    }
}

impl MagCaptureAutoCalibration {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for MagCaptureAutoCalibration {
    const DESCRIPTOR: u8 = 0x27;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "mag_capture_auto_calibration";
}

/// Gravity noise standard deviation. Expected gravity noise (1-sigma) per axis, used to tune the filter. Each value must be greater than 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GravityNoiseStdDev {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Gravity noise 1-sigma (x, y, z). Units: g. Sent for: write.
    pub noise: Option<[f32; 3]>,
}

impl Default for GravityNoiseStdDev {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GravityNoiseStdDev {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        noise: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_noise = if r.left() > 0 {
            Some(<[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("noise"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            noise: p_noise,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.noise {
            optionals.present("noise")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("noise"))?;
        } else {
            optionals.absent("noise");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.noise {
            crate::json::key(w, &mut first, "noise")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GravityNoiseStdDev {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "noise"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_noise = o.opt("noise", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            noise: p_noise,
        })
    }
}

impl GravityNoiseStdDev {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for GravityNoiseStdDev {
    const DESCRIPTOR: u8 = 0x28;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "gravity_noise_std_dev";
}

/// Gravity noise standard deviation (response). Current gravity noise 1-sigma values.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GravityNoiseStdDevResponse {
    /// Gravity noise 1-sigma (x, y, z). Units: g.
    pub noise: [f32; 3],
}

impl Default for GravityNoiseStdDevResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GravityNoiseStdDevResponse {
    const ZERO: Self = Self {
        noise: <[f32; 3] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(12);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_noise = <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("noise"))?;
        Ok(Self { noise: p_noise })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.noise;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("noise"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.noise;
        crate::json::key(w, &mut first, "noise")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GravityNoiseStdDevResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["noise"])?;
        let p_noise = o.req("noise", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        Ok(Self { noise: p_noise })
    }
}

impl GravityNoiseStdDevResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for GravityNoiseStdDevResponse {
    const DESCRIPTOR: u8 = 0x93;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "gravity_noise_std_dev_response";
}

/// Pressure altitude noise standard deviation. Expected pressure altitude noise (1-sigma). Lower values make the height estimate follow pressure changes faster but more exposed to air pressure fluctuations. Must be greater than 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PressureAltitudeNoiseStdDev {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Pressure altitude noise 1-sigma. Units: m. Sent for: write.
    pub noise: Option<f32>,
}

impl Default for PressureAltitudeNoiseStdDev {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for PressureAltitudeNoiseStdDev {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        noise: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_noise = if r.left() > 0 {
            Some(<f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("noise"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            noise: p_noise,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.noise {
            optionals.present("noise")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("noise"))?;
        } else {
            optionals.absent("noise");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.noise {
            crate::json::key(w, &mut first, "noise")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for PressureAltitudeNoiseStdDev {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "noise"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_noise = o.opt("noise", <f32 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            noise: p_noise,
        })
    }
}

impl PressureAltitudeNoiseStdDev {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for PressureAltitudeNoiseStdDev {
    const DESCRIPTOR: u8 = 0x29;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "pressure_altitude_noise_std_dev";
}

/// Pressure altitude noise standard deviation (response). Current pressure altitude noise 1-sigma.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PressureAltitudeNoiseStdDevResponse {
    /// Pressure altitude noise 1-sigma. Units: m.
    pub noise: f32,
}

impl Default for PressureAltitudeNoiseStdDevResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for PressureAltitudeNoiseStdDevResponse {
    const ZERO: Self = Self {
        noise: <f32 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(4);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_noise = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("noise"))?;
        Ok(Self { noise: p_noise })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.noise;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("noise"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.noise;
        crate::json::key(w, &mut first, "noise")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for PressureAltitudeNoiseStdDevResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["noise"])?;
        let p_noise = o.req("noise", <f32 as crate::json_read::FromJson>::from_json)?;
        Ok(Self { noise: p_noise })
    }
}

impl PressureAltitudeNoiseStdDevResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for PressureAltitudeNoiseStdDevResponse {
    const DESCRIPTOR: u8 = 0x94;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "pressure_altitude_noise_std_dev_response";
}

/// Hard iron offset process noise. Expected hard iron offset process noise (1-sigma) per axis, used to tune the magnetometer auto-calibration states. Each value must be greater than 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HardIronOffsetNoise {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Hard iron offset noise 1-sigma (x, y, z). Units: gauss. Sent for: write.
    pub noise: Option<[f32; 3]>,
}

impl Default for HardIronOffsetNoise {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for HardIronOffsetNoise {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        noise: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_noise = if r.left() > 0 {
            Some(<[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("noise"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            noise: p_noise,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.noise {
            optionals.present("noise")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("noise"))?;
        } else {
            optionals.absent("noise");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.noise {
            crate::json::key(w, &mut first, "noise")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for HardIronOffsetNoise {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "noise"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_noise = o.opt("noise", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            noise: p_noise,
        })
    }
}

impl HardIronOffsetNoise {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for HardIronOffsetNoise {
    const DESCRIPTOR: u8 = 0x2B;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "hard_iron_offset_noise";
}

/// Hard iron offset process noise (response). Current hard iron offset process noise.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HardIronOffsetNoiseResponse {
    /// Hard iron offset noise 1-sigma (x, y, z). Units: gauss.
    pub noise: [f32; 3],
}

impl Default for HardIronOffsetNoiseResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for HardIronOffsetNoiseResponse {
    const ZERO: Self = Self {
        noise: <[f32; 3] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(12);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_noise = <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("noise"))?;
        Ok(Self { noise: p_noise })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.noise;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("noise"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.noise;
        crate::json::key(w, &mut first, "noise")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for HardIronOffsetNoiseResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["noise"])?;
        let p_noise = o.req("noise", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        Ok(Self { noise: p_noise })
    }
}

impl HardIronOffsetNoiseResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for HardIronOffsetNoiseResponse {
    const DESCRIPTOR: u8 = 0x96;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "hard_iron_offset_noise_response";
}

/// Soft iron matrix process noise. Expected soft iron matrix process noise (1-sigma), one value per matrix element, row by row (m11, m12, m13, m21, ... m33). Each value must be greater than 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SoftIronMatrixNoise {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Soft iron matrix noise 1-sigma, row-major m11..m33. Sent for: write.
    pub noise: Option<[f32; 9]>,
}

impl Default for SoftIronMatrixNoise {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SoftIronMatrixNoise {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        noise: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_noise = if r.left() > 0 {
            Some(<[f32; 9] as crate::wire::Wire>::decode(r).map_err(|e| e.at("noise"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            noise: p_noise,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.noise {
            optionals.present("noise")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("noise"))?;
        } else {
            optionals.absent("noise");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.noise {
            crate::json::key(w, &mut first, "noise")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SoftIronMatrixNoise {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "noise"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_noise = o.opt("noise", <[f32; 9] as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            noise: p_noise,
        })
    }
}

impl SoftIronMatrixNoise {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for SoftIronMatrixNoise {
    const DESCRIPTOR: u8 = 0x2C;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "soft_iron_matrix_noise";
}

/// Soft iron matrix process noise (response). Current soft iron matrix process noise.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SoftIronMatrixNoiseResponse {
    /// Soft iron matrix noise 1-sigma, row-major m11..m33.
    pub noise: [f32; 9],
}

impl Default for SoftIronMatrixNoiseResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SoftIronMatrixNoiseResponse {
    const ZERO: Self = Self {
        noise: <[f32; 9] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(36);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_noise = <[f32; 9] as crate::wire::Wire>::decode(r).map_err(|e| e.at("noise"))?;
        Ok(Self { noise: p_noise })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.noise;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("noise"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.noise;
        crate::json::key(w, &mut first, "noise")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SoftIronMatrixNoiseResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["noise"])?;
        let p_noise = o.req("noise", <[f32; 9] as crate::json_read::FromJson>::from_json)?;
        Ok(Self { noise: p_noise })
    }
}

impl SoftIronMatrixNoiseResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for SoftIronMatrixNoiseResponse {
    const DESCRIPTOR: u8 = 0x97;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "soft_iron_matrix_noise_response";
}

/// Magnetometer noise standard deviation. Expected magnetometer noise (1-sigma) per axis, used to tune the filter. Each value must be greater than 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MagNoiseStdDev {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Magnetometer noise 1-sigma (x, y, z). Units: gauss. Sent for: write.
    pub noise: Option<[f32; 3]>,
}

impl Default for MagNoiseStdDev {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for MagNoiseStdDev {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        noise: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_noise = if r.left() > 0 {
            Some(<[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("noise"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            noise: p_noise,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.noise {
            optionals.present("noise")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("noise"))?;
        } else {
            optionals.absent("noise");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.noise {
            crate::json::key(w, &mut first, "noise")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for MagNoiseStdDev {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "noise"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_noise = o.opt("noise", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            noise: p_noise,
        })
    }
}

impl MagNoiseStdDev {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for MagNoiseStdDev {
    const DESCRIPTOR: u8 = 0x42;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "mag_noise_std_dev";
}

/// Magnetometer noise standard deviation (response). Current magnetometer noise 1-sigma values.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MagNoiseStdDevResponse {
    /// Magnetometer noise 1-sigma (x, y, z). Units: gauss.
    pub noise: [f32; 3],
}

impl Default for MagNoiseStdDevResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for MagNoiseStdDevResponse {
    const ZERO: Self = Self {
        noise: <[f32; 3] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(12);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_noise = <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("noise"))?;
        Ok(Self { noise: p_noise })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.noise;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("noise"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.noise;
        crate::json::key(w, &mut first, "noise")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for MagNoiseStdDevResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["noise"])?;
        let p_noise = o.req("noise", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        Ok(Self { noise: p_noise })
    }
}

impl MagNoiseStdDevResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for MagNoiseStdDevResponse {
    const DESCRIPTOR: u8 = 0xB1;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "mag_noise_std_dev_response";
}

/// Declination source. Source of the local magnetic declination used to convert between magnetic and true north. With a valid declination the device reports heading relative to true north.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DeclinationSource {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Declination source. Sent for: write.
    pub source: Option<crate::types::MagneticParamSource>,
    /// Manual declination angle (used when source is manual). Units: rad. Sent for: write.
    pub declination: Option<f32>,
}

impl Default for DeclinationSource {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for DeclinationSource {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        source: None,
        declination: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_source = if r.left() > 0 {
            Some(
                <crate::types::MagneticParamSource as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("source"))?,
            )
        } else {
            None
        };
        let p_declination = if r.left() > 0 {
            Some(<f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("declination"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            source: p_source,
            declination: p_declination,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.source {
            optionals.present("source")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("source"))?;
        } else {
            optionals.absent("source");
        }
        if let Some(v) = &self.declination {
            optionals.present("declination")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("declination"))?;
        } else {
            optionals.absent("declination");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.source {
            crate::json::key(w, &mut first, "source")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.declination {
            crate::json::key(w, &mut first, "declination")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for DeclinationSource {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "source", "declination"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_source = o.opt(
            "source",
            <crate::types::MagneticParamSource as crate::json_read::FromJson>::from_json,
        )?;
        let p_declination = o.opt(
            "declination",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            source: p_source,
            declination: p_declination,
        })
    }
}

impl DeclinationSource {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for DeclinationSource {
    const DESCRIPTOR: u8 = 0x43;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "declination_source";
}

/// Declination source (response). Current declination source and angle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DeclinationSourceResponse {
    /// Declination source.
    pub source: crate::types::MagneticParamSource,
    /// Declination angle. Units: rad.
    pub declination: f32,
}

impl Default for DeclinationSourceResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for DeclinationSourceResponse {
    const ZERO: Self = Self {
        source: <crate::types::MagneticParamSource as crate::wire::Wire>::ZERO,
        declination: <f32 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(5);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_source = <crate::types::MagneticParamSource as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("source"))?;
        let p_declination =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("declination"))?;
        Ok(Self {
            source: p_source,
            declination: p_declination,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.source;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("source"))?;
        let v = &self.declination;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("declination"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.source;
        crate::json::key(w, &mut first, "source")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.declination;
        crate::json::key(w, &mut first, "declination")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for DeclinationSourceResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["source", "declination"])?;
        let p_source = o.req(
            "source",
            <crate::types::MagneticParamSource as crate::json_read::FromJson>::from_json,
        )?;
        let p_declination = o.req(
            "declination",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            source: p_source,
            declination: p_declination,
        })
    }
}

impl DeclinationSourceResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for DeclinationSourceResponse {
    const DESCRIPTOR: u8 = 0xB2;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "declination_source_response";
}

/// Gravity magnitude error adaptive measurement. Configure the gravity (accelerometer) magnitude error adaptive measurement, which rejects or de-weights gravity-vector aiding while the measured acceleration magnitude is off. The filter and limit parameters are used only in fixed mode and may be left out: with only the function and mode, the other values keep their previous settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GravityMagnitudeAdaptiveMeasurement {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Disabled, fixed or auto-adaptive. Sent for: write.
    pub mode: Option<crate::types::AdaptiveMeasurementMode>,
    /// Low-pass filter cutoff frequency. Units: Hz. Sent for: write.
    pub frequency: Option<f32>,
    /// Low limit. Units: m/s^2. Sent for: write.
    pub low_limit: Option<f32>,
    /// High limit. Units: m/s^2. Sent for: write.
    pub high_limit: Option<f32>,
    /// Low limit uncertainty, 1-sigma. Units: m/s^2. Sent for: write.
    pub low_limit_uncertainty: Option<f32>,
    /// High limit uncertainty, 1-sigma. Units: m/s^2. Sent for: write.
    pub high_limit_uncertainty: Option<f32>,
    /// Minimum uncertainty, 1-sigma. Units: m/s^2. Sent for: write.
    pub minimum_uncertainty: Option<f32>,
}

impl Default for GravityMagnitudeAdaptiveMeasurement {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GravityMagnitudeAdaptiveMeasurement {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        mode: None,
        frequency: None,
        low_limit: None,
        high_limit: None,
        low_limit_uncertainty: None,
        high_limit_uncertainty: None,
        minimum_uncertainty: None,
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
                <crate::types::AdaptiveMeasurementMode as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("mode"))?,
            )
        } else {
            None
        };
        let p_frequency = if r.left() > 0 {
            Some(<f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("frequency"))?)
        } else {
            None
        };
        let p_low_limit = if r.left() > 0 {
            Some(<f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("low_limit"))?)
        } else {
            None
        };
        let p_high_limit = if r.left() > 0 {
            Some(<f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("high_limit"))?)
        } else {
            None
        };
        let p_low_limit_uncertainty = if r.left() > 0 {
            Some(<f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("low_limit_uncertainty"))?)
        } else {
            None
        };
        let p_high_limit_uncertainty = if r.left() > 0 {
            Some(
                <f32 as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("high_limit_uncertainty"))?,
            )
        } else {
            None
        };
        let p_minimum_uncertainty = if r.left() > 0 {
            Some(<f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("minimum_uncertainty"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            mode: p_mode,
            frequency: p_frequency,
            low_limit: p_low_limit,
            high_limit: p_high_limit,
            low_limit_uncertainty: p_low_limit_uncertainty,
            high_limit_uncertainty: p_high_limit_uncertainty,
            minimum_uncertainty: p_minimum_uncertainty,
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
        if let Some(v) = &self.frequency {
            optionals.present("frequency")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("frequency"))?;
        } else {
            optionals.absent("frequency");
        }
        if let Some(v) = &self.low_limit {
            optionals.present("low_limit")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("low_limit"))?;
        } else {
            optionals.absent("low_limit");
        }
        if let Some(v) = &self.high_limit {
            optionals.present("high_limit")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("high_limit"))?;
        } else {
            optionals.absent("high_limit");
        }
        if let Some(v) = &self.low_limit_uncertainty {
            optionals.present("low_limit_uncertainty")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("low_limit_uncertainty"))?;
        } else {
            optionals.absent("low_limit_uncertainty");
        }
        if let Some(v) = &self.high_limit_uncertainty {
            optionals.present("high_limit_uncertainty")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("high_limit_uncertainty"))?;
        } else {
            optionals.absent("high_limit_uncertainty");
        }
        if let Some(v) = &self.minimum_uncertainty {
            optionals.present("minimum_uncertainty")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("minimum_uncertainty"))?;
        } else {
            optionals.absent("minimum_uncertainty");
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
        if let Some(v) = &self.frequency {
            crate::json::key(w, &mut first, "frequency")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.low_limit {
            crate::json::key(w, &mut first, "low_limit")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.high_limit {
            crate::json::key(w, &mut first, "high_limit")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.low_limit_uncertainty {
            crate::json::key(w, &mut first, "low_limit_uncertainty")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.high_limit_uncertainty {
            crate::json::key(w, &mut first, "high_limit_uncertainty")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.minimum_uncertainty {
            crate::json::key(w, &mut first, "minimum_uncertainty")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GravityMagnitudeAdaptiveMeasurement {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "function",
                "mode",
                "frequency",
                "low_limit",
                "high_limit",
                "low_limit_uncertainty",
                "high_limit_uncertainty",
                "minimum_uncertainty",
            ],
        )?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_mode = o.opt(
            "mode",
            <crate::types::AdaptiveMeasurementMode as crate::json_read::FromJson>::from_json,
        )?;
        let p_frequency = o.opt("frequency", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_low_limit = o.opt("low_limit", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_high_limit = o.opt("high_limit", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_low_limit_uncertainty = o.opt(
            "low_limit_uncertainty",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_high_limit_uncertainty = o.opt(
            "high_limit_uncertainty",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_minimum_uncertainty = o.opt(
            "minimum_uncertainty",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            mode: p_mode,
            frequency: p_frequency,
            low_limit: p_low_limit,
            high_limit: p_high_limit,
            low_limit_uncertainty: p_low_limit_uncertainty,
            high_limit_uncertainty: p_high_limit_uncertainty,
            minimum_uncertainty: p_minimum_uncertainty,
        })
    }
}

impl GravityMagnitudeAdaptiveMeasurement {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for GravityMagnitudeAdaptiveMeasurement {
    const DESCRIPTOR: u8 = 0x44;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "gravity_magnitude_adaptive_measurement";
}

/// Gravity magnitude error adaptive measurement (response). Current gravity magnitude adaptive measurement settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GravityMagnitudeAdaptiveMeasurementResponse {
    /// Disabled, fixed or auto-adaptive.
    pub mode: crate::types::AdaptiveMeasurementMode,
    /// Low-pass filter cutoff frequency. Units: Hz.
    pub frequency: f32,
    /// Low limit. Units: m/s^2.
    pub low_limit: f32,
    /// High limit. Units: m/s^2.
    pub high_limit: f32,
    /// Low limit uncertainty, 1-sigma. Units: m/s^2.
    pub low_limit_uncertainty: f32,
    /// High limit uncertainty, 1-sigma. Units: m/s^2.
    pub high_limit_uncertainty: f32,
    /// Minimum uncertainty, 1-sigma. Units: m/s^2.
    pub minimum_uncertainty: f32,
}

impl Default for GravityMagnitudeAdaptiveMeasurementResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GravityMagnitudeAdaptiveMeasurementResponse {
    const ZERO: Self = Self {
        mode: <crate::types::AdaptiveMeasurementMode as crate::wire::Wire>::ZERO,
        frequency: <f32 as crate::wire::Wire>::ZERO,
        low_limit: <f32 as crate::wire::Wire>::ZERO,
        high_limit: <f32 as crate::wire::Wire>::ZERO,
        low_limit_uncertainty: <f32 as crate::wire::Wire>::ZERO,
        high_limit_uncertainty: <f32 as crate::wire::Wire>::ZERO,
        minimum_uncertainty: <f32 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(25);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_mode = <crate::types::AdaptiveMeasurementMode as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("mode"))?;
        let p_frequency = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("frequency"))?;
        let p_low_limit = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("low_limit"))?;
        let p_high_limit = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("high_limit"))?;
        let p_low_limit_uncertainty =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("low_limit_uncertainty"))?;
        let p_high_limit_uncertainty =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("high_limit_uncertainty"))?;
        let p_minimum_uncertainty =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("minimum_uncertainty"))?;
        Ok(Self {
            mode: p_mode,
            frequency: p_frequency,
            low_limit: p_low_limit,
            high_limit: p_high_limit,
            low_limit_uncertainty: p_low_limit_uncertainty,
            high_limit_uncertainty: p_high_limit_uncertainty,
            minimum_uncertainty: p_minimum_uncertainty,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.mode;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("mode"))?;
        let v = &self.frequency;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("frequency"))?;
        let v = &self.low_limit;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("low_limit"))?;
        let v = &self.high_limit;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("high_limit"))?;
        let v = &self.low_limit_uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("low_limit_uncertainty"))?;
        let v = &self.high_limit_uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("high_limit_uncertainty"))?;
        let v = &self.minimum_uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("minimum_uncertainty"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.mode;
        crate::json::key(w, &mut first, "mode")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.frequency;
        crate::json::key(w, &mut first, "frequency")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.low_limit;
        crate::json::key(w, &mut first, "low_limit")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.high_limit;
        crate::json::key(w, &mut first, "high_limit")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.low_limit_uncertainty;
        crate::json::key(w, &mut first, "low_limit_uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.high_limit_uncertainty;
        crate::json::key(w, &mut first, "high_limit_uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.minimum_uncertainty;
        crate::json::key(w, &mut first, "minimum_uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GravityMagnitudeAdaptiveMeasurementResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "mode",
                "frequency",
                "low_limit",
                "high_limit",
                "low_limit_uncertainty",
                "high_limit_uncertainty",
                "minimum_uncertainty",
            ],
        )?;
        let p_mode = o.req(
            "mode",
            <crate::types::AdaptiveMeasurementMode as crate::json_read::FromJson>::from_json,
        )?;
        let p_frequency = o.req("frequency", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_low_limit = o.req("low_limit", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_high_limit = o.req("high_limit", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_low_limit_uncertainty = o.req(
            "low_limit_uncertainty",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_high_limit_uncertainty = o.req(
            "high_limit_uncertainty",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_minimum_uncertainty = o.req(
            "minimum_uncertainty",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            mode: p_mode,
            frequency: p_frequency,
            low_limit: p_low_limit,
            high_limit: p_high_limit,
            low_limit_uncertainty: p_low_limit_uncertainty,
            high_limit_uncertainty: p_high_limit_uncertainty,
            minimum_uncertainty: p_minimum_uncertainty,
        })
    }
}

impl GravityMagnitudeAdaptiveMeasurementResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for GravityMagnitudeAdaptiveMeasurementResponse {
    const DESCRIPTOR: u8 = 0xB3;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "gravity_magnitude_adaptive_measurement_response";
}

/// Magnetometer magnitude error adaptive measurement. Configure the magnetometer magnitude error adaptive measurement, which rejects magnetometer readings whose magnitude is outside the fixed or internally computed limits. The filter and limit parameters may be left out: with only the function and mode, the other values keep their previous settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MagMagnitudeAdaptiveMeasurement {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Disabled, fixed or auto-adaptive. Sent for: write.
    pub mode: Option<crate::types::AdaptiveMeasurementMode>,
    /// Low-pass filter cutoff frequency. Units: Hz. Sent for: write.
    pub frequency: Option<f32>,
    /// Low limit. Units: gauss. Sent for: write.
    pub low_limit: Option<f32>,
    /// High limit. Units: gauss. Sent for: write.
    pub high_limit: Option<f32>,
    /// Low limit uncertainty, 1-sigma. Units: gauss. Sent for: write.
    pub low_limit_uncertainty: Option<f32>,
    /// High limit uncertainty, 1-sigma. Units: gauss. Sent for: write.
    pub high_limit_uncertainty: Option<f32>,
    /// Minimum uncertainty, 1-sigma. Units: gauss. Sent for: write.
    pub minimum_uncertainty: Option<f32>,
}

impl Default for MagMagnitudeAdaptiveMeasurement {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for MagMagnitudeAdaptiveMeasurement {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        mode: None,
        frequency: None,
        low_limit: None,
        high_limit: None,
        low_limit_uncertainty: None,
        high_limit_uncertainty: None,
        minimum_uncertainty: None,
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
                <crate::types::AdaptiveMeasurementMode as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("mode"))?,
            )
        } else {
            None
        };
        let p_frequency = if r.left() > 0 {
            Some(<f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("frequency"))?)
        } else {
            None
        };
        let p_low_limit = if r.left() > 0 {
            Some(<f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("low_limit"))?)
        } else {
            None
        };
        let p_high_limit = if r.left() > 0 {
            Some(<f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("high_limit"))?)
        } else {
            None
        };
        let p_low_limit_uncertainty = if r.left() > 0 {
            Some(<f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("low_limit_uncertainty"))?)
        } else {
            None
        };
        let p_high_limit_uncertainty = if r.left() > 0 {
            Some(
                <f32 as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("high_limit_uncertainty"))?,
            )
        } else {
            None
        };
        let p_minimum_uncertainty = if r.left() > 0 {
            Some(<f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("minimum_uncertainty"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            mode: p_mode,
            frequency: p_frequency,
            low_limit: p_low_limit,
            high_limit: p_high_limit,
            low_limit_uncertainty: p_low_limit_uncertainty,
            high_limit_uncertainty: p_high_limit_uncertainty,
            minimum_uncertainty: p_minimum_uncertainty,
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
        if let Some(v) = &self.frequency {
            optionals.present("frequency")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("frequency"))?;
        } else {
            optionals.absent("frequency");
        }
        if let Some(v) = &self.low_limit {
            optionals.present("low_limit")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("low_limit"))?;
        } else {
            optionals.absent("low_limit");
        }
        if let Some(v) = &self.high_limit {
            optionals.present("high_limit")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("high_limit"))?;
        } else {
            optionals.absent("high_limit");
        }
        if let Some(v) = &self.low_limit_uncertainty {
            optionals.present("low_limit_uncertainty")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("low_limit_uncertainty"))?;
        } else {
            optionals.absent("low_limit_uncertainty");
        }
        if let Some(v) = &self.high_limit_uncertainty {
            optionals.present("high_limit_uncertainty")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("high_limit_uncertainty"))?;
        } else {
            optionals.absent("high_limit_uncertainty");
        }
        if let Some(v) = &self.minimum_uncertainty {
            optionals.present("minimum_uncertainty")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("minimum_uncertainty"))?;
        } else {
            optionals.absent("minimum_uncertainty");
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
        if let Some(v) = &self.frequency {
            crate::json::key(w, &mut first, "frequency")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.low_limit {
            crate::json::key(w, &mut first, "low_limit")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.high_limit {
            crate::json::key(w, &mut first, "high_limit")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.low_limit_uncertainty {
            crate::json::key(w, &mut first, "low_limit_uncertainty")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.high_limit_uncertainty {
            crate::json::key(w, &mut first, "high_limit_uncertainty")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.minimum_uncertainty {
            crate::json::key(w, &mut first, "minimum_uncertainty")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for MagMagnitudeAdaptiveMeasurement {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "function",
                "mode",
                "frequency",
                "low_limit",
                "high_limit",
                "low_limit_uncertainty",
                "high_limit_uncertainty",
                "minimum_uncertainty",
            ],
        )?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_mode = o.opt(
            "mode",
            <crate::types::AdaptiveMeasurementMode as crate::json_read::FromJson>::from_json,
        )?;
        let p_frequency = o.opt("frequency", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_low_limit = o.opt("low_limit", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_high_limit = o.opt("high_limit", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_low_limit_uncertainty = o.opt(
            "low_limit_uncertainty",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_high_limit_uncertainty = o.opt(
            "high_limit_uncertainty",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_minimum_uncertainty = o.opt(
            "minimum_uncertainty",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            mode: p_mode,
            frequency: p_frequency,
            low_limit: p_low_limit,
            high_limit: p_high_limit,
            low_limit_uncertainty: p_low_limit_uncertainty,
            high_limit_uncertainty: p_high_limit_uncertainty,
            minimum_uncertainty: p_minimum_uncertainty,
        })
    }
}

impl MagMagnitudeAdaptiveMeasurement {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for MagMagnitudeAdaptiveMeasurement {
    const DESCRIPTOR: u8 = 0x45;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "mag_magnitude_adaptive_measurement";
}

/// Magnetometer magnitude error adaptive measurement (response). Current magnetometer magnitude adaptive measurement settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MagMagnitudeAdaptiveMeasurementResponse {
    /// Disabled, fixed or auto-adaptive.
    pub mode: crate::types::AdaptiveMeasurementMode,
    /// Low-pass filter cutoff frequency. Units: Hz.
    pub frequency: f32,
    /// Low limit. Units: gauss.
    pub low_limit: f32,
    /// High limit. Units: gauss.
    pub high_limit: f32,
    /// Low limit uncertainty, 1-sigma. Units: gauss.
    pub low_limit_uncertainty: f32,
    /// High limit uncertainty, 1-sigma. Units: gauss.
    pub high_limit_uncertainty: f32,
    /// Minimum uncertainty, 1-sigma. Units: gauss.
    pub minimum_uncertainty: f32,
}

impl Default for MagMagnitudeAdaptiveMeasurementResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for MagMagnitudeAdaptiveMeasurementResponse {
    const ZERO: Self = Self {
        mode: <crate::types::AdaptiveMeasurementMode as crate::wire::Wire>::ZERO,
        frequency: <f32 as crate::wire::Wire>::ZERO,
        low_limit: <f32 as crate::wire::Wire>::ZERO,
        high_limit: <f32 as crate::wire::Wire>::ZERO,
        low_limit_uncertainty: <f32 as crate::wire::Wire>::ZERO,
        high_limit_uncertainty: <f32 as crate::wire::Wire>::ZERO,
        minimum_uncertainty: <f32 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(25);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_mode = <crate::types::AdaptiveMeasurementMode as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("mode"))?;
        let p_frequency = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("frequency"))?;
        let p_low_limit = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("low_limit"))?;
        let p_high_limit = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("high_limit"))?;
        let p_low_limit_uncertainty =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("low_limit_uncertainty"))?;
        let p_high_limit_uncertainty =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("high_limit_uncertainty"))?;
        let p_minimum_uncertainty =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("minimum_uncertainty"))?;
        Ok(Self {
            mode: p_mode,
            frequency: p_frequency,
            low_limit: p_low_limit,
            high_limit: p_high_limit,
            low_limit_uncertainty: p_low_limit_uncertainty,
            high_limit_uncertainty: p_high_limit_uncertainty,
            minimum_uncertainty: p_minimum_uncertainty,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.mode;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("mode"))?;
        let v = &self.frequency;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("frequency"))?;
        let v = &self.low_limit;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("low_limit"))?;
        let v = &self.high_limit;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("high_limit"))?;
        let v = &self.low_limit_uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("low_limit_uncertainty"))?;
        let v = &self.high_limit_uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("high_limit_uncertainty"))?;
        let v = &self.minimum_uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("minimum_uncertainty"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.mode;
        crate::json::key(w, &mut first, "mode")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.frequency;
        crate::json::key(w, &mut first, "frequency")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.low_limit;
        crate::json::key(w, &mut first, "low_limit")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.high_limit;
        crate::json::key(w, &mut first, "high_limit")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.low_limit_uncertainty;
        crate::json::key(w, &mut first, "low_limit_uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.high_limit_uncertainty;
        crate::json::key(w, &mut first, "high_limit_uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.minimum_uncertainty;
        crate::json::key(w, &mut first, "minimum_uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for MagMagnitudeAdaptiveMeasurementResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "mode",
                "frequency",
                "low_limit",
                "high_limit",
                "low_limit_uncertainty",
                "high_limit_uncertainty",
                "minimum_uncertainty",
            ],
        )?;
        let p_mode = o.req(
            "mode",
            <crate::types::AdaptiveMeasurementMode as crate::json_read::FromJson>::from_json,
        )?;
        let p_frequency = o.req("frequency", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_low_limit = o.req("low_limit", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_high_limit = o.req("high_limit", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_low_limit_uncertainty = o.req(
            "low_limit_uncertainty",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_high_limit_uncertainty = o.req(
            "high_limit_uncertainty",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_minimum_uncertainty = o.req(
            "minimum_uncertainty",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            mode: p_mode,
            frequency: p_frequency,
            low_limit: p_low_limit,
            high_limit: p_high_limit,
            low_limit_uncertainty: p_low_limit_uncertainty,
            high_limit_uncertainty: p_high_limit_uncertainty,
            minimum_uncertainty: p_minimum_uncertainty,
        })
    }
}

impl MagMagnitudeAdaptiveMeasurementResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for MagMagnitudeAdaptiveMeasurementResponse {
    const DESCRIPTOR: u8 = 0xB4;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "mag_magnitude_adaptive_measurement_response";
}

/// Magnetometer dip angle error adaptive measurement. Configure the magnetometer dip angle error adaptive measurement, which rejects magnetometer readings whose dip angle error exceeds the limit. Ignored while an auto-adaptive magnetometer or gravity magnitude mode is selected. Only disabled (0) and fixed (1) are documented.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MagDipAngleAdaptiveMeasurement {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Disabled (0) or fixed (1). Sent for: write.
    pub mode: Option<crate::types::AdaptiveMeasurementMode>,
    /// Low-pass filter cutoff frequency. Units: Hz. Sent for: write.
    pub frequency: Option<f32>,
    /// High limit of the dip angle error. Units: rad. Sent for: write.
    pub high_limit: Option<f32>,
    /// High limit uncertainty, 1-sigma. Units: rad. Sent for: write.
    pub high_limit_uncertainty: Option<f32>,
    /// Minimum uncertainty, 1-sigma. Units: rad. Sent for: write.
    pub minimum_uncertainty: Option<f32>,
}

impl Default for MagDipAngleAdaptiveMeasurement {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for MagDipAngleAdaptiveMeasurement {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        mode: None,
        frequency: None,
        high_limit: None,
        high_limit_uncertainty: None,
        minimum_uncertainty: None,
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
                <crate::types::AdaptiveMeasurementMode as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("mode"))?,
            )
        } else {
            None
        };
        let p_frequency = if r.left() > 0 {
            Some(<f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("frequency"))?)
        } else {
            None
        };
        let p_high_limit = if r.left() > 0 {
            Some(<f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("high_limit"))?)
        } else {
            None
        };
        let p_high_limit_uncertainty = if r.left() > 0 {
            Some(
                <f32 as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("high_limit_uncertainty"))?,
            )
        } else {
            None
        };
        let p_minimum_uncertainty = if r.left() > 0 {
            Some(<f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("minimum_uncertainty"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            mode: p_mode,
            frequency: p_frequency,
            high_limit: p_high_limit,
            high_limit_uncertainty: p_high_limit_uncertainty,
            minimum_uncertainty: p_minimum_uncertainty,
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
        if let Some(v) = &self.frequency {
            optionals.present("frequency")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("frequency"))?;
        } else {
            optionals.absent("frequency");
        }
        if let Some(v) = &self.high_limit {
            optionals.present("high_limit")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("high_limit"))?;
        } else {
            optionals.absent("high_limit");
        }
        if let Some(v) = &self.high_limit_uncertainty {
            optionals.present("high_limit_uncertainty")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("high_limit_uncertainty"))?;
        } else {
            optionals.absent("high_limit_uncertainty");
        }
        if let Some(v) = &self.minimum_uncertainty {
            optionals.present("minimum_uncertainty")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("minimum_uncertainty"))?;
        } else {
            optionals.absent("minimum_uncertainty");
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
        if let Some(v) = &self.frequency {
            crate::json::key(w, &mut first, "frequency")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.high_limit {
            crate::json::key(w, &mut first, "high_limit")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.high_limit_uncertainty {
            crate::json::key(w, &mut first, "high_limit_uncertainty")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.minimum_uncertainty {
            crate::json::key(w, &mut first, "minimum_uncertainty")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for MagDipAngleAdaptiveMeasurement {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "function",
                "mode",
                "frequency",
                "high_limit",
                "high_limit_uncertainty",
                "minimum_uncertainty",
            ],
        )?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_mode = o.opt(
            "mode",
            <crate::types::AdaptiveMeasurementMode as crate::json_read::FromJson>::from_json,
        )?;
        let p_frequency = o.opt("frequency", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_high_limit = o.opt("high_limit", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_high_limit_uncertainty = o.opt(
            "high_limit_uncertainty",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_minimum_uncertainty = o.opt(
            "minimum_uncertainty",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            mode: p_mode,
            frequency: p_frequency,
            high_limit: p_high_limit,
            high_limit_uncertainty: p_high_limit_uncertainty,
            minimum_uncertainty: p_minimum_uncertainty,
        })
    }
}

impl MagDipAngleAdaptiveMeasurement {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for MagDipAngleAdaptiveMeasurement {
    const DESCRIPTOR: u8 = 0x46;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "mag_dip_angle_adaptive_measurement";
}

/// Magnetometer dip angle error adaptive measurement (response). Current dip angle adaptive measurement settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MagDipAngleAdaptiveMeasurementResponse {
    /// Disabled (0) or fixed (1).
    pub mode: crate::types::AdaptiveMeasurementMode,
    /// Low-pass filter cutoff frequency. Units: Hz.
    pub frequency: f32,
    /// High limit of the dip angle error. Units: rad.
    pub high_limit: f32,
    /// High limit uncertainty, 1-sigma. Units: rad.
    pub high_limit_uncertainty: f32,
    /// Minimum uncertainty, 1-sigma. Units: rad.
    pub minimum_uncertainty: f32,
}

impl Default for MagDipAngleAdaptiveMeasurementResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for MagDipAngleAdaptiveMeasurementResponse {
    const ZERO: Self = Self {
        mode: <crate::types::AdaptiveMeasurementMode as crate::wire::Wire>::ZERO,
        frequency: <f32 as crate::wire::Wire>::ZERO,
        high_limit: <f32 as crate::wire::Wire>::ZERO,
        high_limit_uncertainty: <f32 as crate::wire::Wire>::ZERO,
        minimum_uncertainty: <f32 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(17);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_mode = <crate::types::AdaptiveMeasurementMode as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("mode"))?;
        let p_frequency = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("frequency"))?;
        let p_high_limit = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("high_limit"))?;
        let p_high_limit_uncertainty =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("high_limit_uncertainty"))?;
        let p_minimum_uncertainty =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("minimum_uncertainty"))?;
        Ok(Self {
            mode: p_mode,
            frequency: p_frequency,
            high_limit: p_high_limit,
            high_limit_uncertainty: p_high_limit_uncertainty,
            minimum_uncertainty: p_minimum_uncertainty,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.mode;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("mode"))?;
        let v = &self.frequency;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("frequency"))?;
        let v = &self.high_limit;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("high_limit"))?;
        let v = &self.high_limit_uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("high_limit_uncertainty"))?;
        let v = &self.minimum_uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("minimum_uncertainty"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.mode;
        crate::json::key(w, &mut first, "mode")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.frequency;
        crate::json::key(w, &mut first, "frequency")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.high_limit;
        crate::json::key(w, &mut first, "high_limit")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.high_limit_uncertainty;
        crate::json::key(w, &mut first, "high_limit_uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.minimum_uncertainty;
        crate::json::key(w, &mut first, "minimum_uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for MagDipAngleAdaptiveMeasurementResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "mode",
                "frequency",
                "high_limit",
                "high_limit_uncertainty",
                "minimum_uncertainty",
            ],
        )?;
        let p_mode = o.req(
            "mode",
            <crate::types::AdaptiveMeasurementMode as crate::json_read::FromJson>::from_json,
        )?;
        let p_frequency = o.req("frequency", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_high_limit = o.req("high_limit", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_high_limit_uncertainty = o.req(
            "high_limit_uncertainty",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_minimum_uncertainty = o.req(
            "minimum_uncertainty",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            mode: p_mode,
            frequency: p_frequency,
            high_limit: p_high_limit,
            high_limit_uncertainty: p_high_limit_uncertainty,
            minimum_uncertainty: p_minimum_uncertainty,
        })
    }
}

impl MagDipAngleAdaptiveMeasurementResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for MagDipAngleAdaptiveMeasurementResponse {
    const DESCRIPTOR: u8 = 0xB5;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "mag_dip_angle_adaptive_measurement_response";
}

/// Altitude aiding control. Select the altitude aiding input. GNSS is always the primary altitude; the aiding input improves it and bridges GNSS outages. Pressure altitude depends on weather and location and can vary by more than 40 m.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AltitudeAidingControl {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Altitude aiding input (0 disabled, 1 pressure). Sent for: write.
    pub source: Option<crate::types::AltitudeAidingSource>,
}

impl Default for AltitudeAidingControl {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AltitudeAidingControl {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        source: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_source = if r.left() > 0 {
            Some(
                <crate::types::AltitudeAidingSource as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("source"))?,
            )
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            source: p_source,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.source {
            optionals.present("source")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("source"))?;
        } else {
            optionals.absent("source");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.source {
            crate::json::key(w, &mut first, "source")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AltitudeAidingControl {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "source"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_source = o.opt(
            "source",
            <crate::types::AltitudeAidingSource as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            source: p_source,
        })
    }
}

impl AltitudeAidingControl {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for AltitudeAidingControl {
    const DESCRIPTOR: u8 = 0x47;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "altitude_aiding_control";
}

/// Altitude aiding control (response). Current altitude aiding input.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AltitudeAidingControlResponse {
    /// Altitude aiding input.
    pub source: crate::types::AltitudeAidingSource,
}

impl Default for AltitudeAidingControlResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AltitudeAidingControlResponse {
    const ZERO: Self = Self {
        source: <crate::types::AltitudeAidingSource as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(1);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_source = <crate::types::AltitudeAidingSource as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("source"))?;
        Ok(Self { source: p_source })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.source;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("source"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.source;
        crate::json::key(w, &mut first, "source")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AltitudeAidingControlResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["source"])?;
        let p_source = o.req(
            "source",
            <crate::types::AltitudeAidingSource as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self { source: p_source })
    }
}

impl AltitudeAidingControlResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for AltitudeAidingControlResponse {
    const DESCRIPTOR: u8 = 0xB7;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "altitude_aiding_control_response";
}

/// Pitch/roll aiding control. Select the pitch/roll aiding input. Pitch and roll always come from the GNSS-corrected inertial solution; the aiding input improves it at low dynamics and during GNSS outages.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PitchRollAidingControl {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Pitch/roll aiding input (0 disabled, 1 gravity vector). Sent for: write.
    pub source: Option<crate::types::PitchRollAidingSource>,
}

impl Default for PitchRollAidingControl {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for PitchRollAidingControl {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        source: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_source = if r.left() > 0 {
            Some(
                <crate::types::PitchRollAidingSource as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("source"))?,
            )
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            source: p_source,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.source {
            optionals.present("source")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("source"))?;
        } else {
            optionals.absent("source");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.source {
            crate::json::key(w, &mut first, "source")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for PitchRollAidingControl {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "source"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_source = o.opt(
            "source",
            <crate::types::PitchRollAidingSource as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            source: p_source,
        })
    }
}

impl PitchRollAidingControl {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for PitchRollAidingControl {
    const DESCRIPTOR: u8 = 0x4B;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "pitch_roll_aiding_control";
}

/// Pitch/roll aiding control (response). Current pitch/roll aiding input.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PitchRollAidingControlResponse {
    /// Pitch/roll aiding input.
    pub source: crate::types::PitchRollAidingSource,
}

impl Default for PitchRollAidingControlResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for PitchRollAidingControlResponse {
    const ZERO: Self = Self {
        source: <crate::types::PitchRollAidingSource as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(1);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_source = <crate::types::PitchRollAidingSource as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("source"))?;
        Ok(Self { source: p_source })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.source;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("source"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.source;
        crate::json::key(w, &mut first, "source")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for PitchRollAidingControlResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["source"])?;
        let p_source = o.req(
            "source",
            <crate::types::PitchRollAidingSource as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self { source: p_source })
    }
}

impl PitchRollAidingControlResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for PitchRollAidingControlResponse {
    const DESCRIPTOR: u8 = 0xBB;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "pitch_roll_aiding_control_response";
}

/// Inclination source. Source of the local magnetic inclination (dip angle), which matters for the magnetometer auto-calibration; without an accurate source, leave auto-calibration off.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InclinationSource {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Inclination source. Sent for: write.
    pub source: Option<crate::types::MagneticParamSource>,
    /// Manual inclination angle (used when source is manual). Units: rad. Sent for: write.
    pub inclination: Option<f32>,
}

impl Default for InclinationSource {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for InclinationSource {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        source: None,
        inclination: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_source = if r.left() > 0 {
            Some(
                <crate::types::MagneticParamSource as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("source"))?,
            )
        } else {
            None
        };
        let p_inclination = if r.left() > 0 {
            Some(<f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("inclination"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            source: p_source,
            inclination: p_inclination,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.source {
            optionals.present("source")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("source"))?;
        } else {
            optionals.absent("source");
        }
        if let Some(v) = &self.inclination {
            optionals.present("inclination")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("inclination"))?;
        } else {
            optionals.absent("inclination");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.source {
            crate::json::key(w, &mut first, "source")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.inclination {
            crate::json::key(w, &mut first, "inclination")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for InclinationSource {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "source", "inclination"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_source = o.opt(
            "source",
            <crate::types::MagneticParamSource as crate::json_read::FromJson>::from_json,
        )?;
        let p_inclination = o.opt(
            "inclination",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            source: p_source,
            inclination: p_inclination,
        })
    }
}

impl InclinationSource {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for InclinationSource {
    const DESCRIPTOR: u8 = 0x4C;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "inclination_source";
}

/// Inclination source (response). Current inclination source and angle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InclinationSourceResponse {
    /// Inclination source.
    pub source: crate::types::MagneticParamSource,
    /// Inclination angle. Units: rad.
    pub inclination: f32,
}

impl Default for InclinationSourceResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for InclinationSourceResponse {
    const ZERO: Self = Self {
        source: <crate::types::MagneticParamSource as crate::wire::Wire>::ZERO,
        inclination: <f32 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(5);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_source = <crate::types::MagneticParamSource as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("source"))?;
        let p_inclination =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("inclination"))?;
        Ok(Self {
            source: p_source,
            inclination: p_inclination,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.source;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("source"))?;
        let v = &self.inclination;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("inclination"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.source;
        crate::json::key(w, &mut first, "source")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.inclination;
        crate::json::key(w, &mut first, "inclination")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for InclinationSourceResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["source", "inclination"])?;
        let p_source = o.req(
            "source",
            <crate::types::MagneticParamSource as crate::json_read::FromJson>::from_json,
        )?;
        let p_inclination = o.req(
            "inclination",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            source: p_source,
            inclination: p_inclination,
        })
    }
}

impl InclinationSourceResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for InclinationSourceResponse {
    const DESCRIPTOR: u8 = 0xBC;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "inclination_source_response";
}

/// Magnetic field magnitude source. Source of the local magnetic field magnitude, used by the magnetometer auto-calibration and the magnetometer magnitude adaptive measurement. Source none uses a fixed 0.5 gauss.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MagneticFieldMagnitudeSource {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Magnitude source. Sent for: write.
    pub source: Option<crate::types::MagneticParamSource>,
    /// Manual field magnitude (used when source is manual). Units: gauss. Sent for: write.
    pub magnitude: Option<f32>,
}

impl Default for MagneticFieldMagnitudeSource {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for MagneticFieldMagnitudeSource {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        source: None,
        magnitude: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_source = if r.left() > 0 {
            Some(
                <crate::types::MagneticParamSource as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("source"))?,
            )
        } else {
            None
        };
        let p_magnitude = if r.left() > 0 {
            Some(<f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("magnitude"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            source: p_source,
            magnitude: p_magnitude,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.source {
            optionals.present("source")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("source"))?;
        } else {
            optionals.absent("source");
        }
        if let Some(v) = &self.magnitude {
            optionals.present("magnitude")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("magnitude"))?;
        } else {
            optionals.absent("magnitude");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.source {
            crate::json::key(w, &mut first, "source")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.magnitude {
            crate::json::key(w, &mut first, "magnitude")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for MagneticFieldMagnitudeSource {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "source", "magnitude"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_source = o.opt(
            "source",
            <crate::types::MagneticParamSource as crate::json_read::FromJson>::from_json,
        )?;
        let p_magnitude = o.opt("magnitude", <f32 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            source: p_source,
            magnitude: p_magnitude,
        })
    }
}

impl MagneticFieldMagnitudeSource {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for MagneticFieldMagnitudeSource {
    const DESCRIPTOR: u8 = 0x4D;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "magnetic_field_magnitude_source";
}

/// Magnetic field magnitude source (response). Current magnetic field magnitude source and value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MagneticFieldMagnitudeSourceResponse {
    /// Magnitude source.
    pub source: crate::types::MagneticParamSource,
    /// Field magnitude. Units: gauss.
    pub magnitude: f32,
}

impl Default for MagneticFieldMagnitudeSourceResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for MagneticFieldMagnitudeSourceResponse {
    const ZERO: Self = Self {
        source: <crate::types::MagneticParamSource as crate::wire::Wire>::ZERO,
        magnitude: <f32 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(5);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_source = <crate::types::MagneticParamSource as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("source"))?;
        let p_magnitude = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("magnitude"))?;
        Ok(Self {
            source: p_source,
            magnitude: p_magnitude,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.source;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("source"))?;
        let v = &self.magnitude;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("magnitude"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.source;
        crate::json::key(w, &mut first, "source")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.magnitude;
        crate::json::key(w, &mut first, "magnitude")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for MagneticFieldMagnitudeSourceResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["source", "magnitude"])?;
        let p_source = o.req(
            "source",
            <crate::types::MagneticParamSource as crate::json_read::FromJson>::from_json,
        )?;
        let p_magnitude = o.req("magnitude", <f32 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            source: p_source,
            magnitude: p_magnitude,
        })
    }
}

impl MagneticFieldMagnitudeSourceResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for MagneticFieldMagnitudeSourceResponse {
    const DESCRIPTOR: u8 = 0xBD;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "magnetic_field_magnitude_source_response";
}

/// Aiding measurement control. Enable or disable an internal aiding measurement source. The source is sent with every function; ALL (0xFFFF) applies save, load and default to every source.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AidingMeasurementControl {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Aiding measurement source. Sent for: write, read, save, load, default.
    pub source: crate::types::AidingMeasurementSource,
    /// Whether the source is used. Sent for: write.
    pub enable: Option<bool>,
}

impl Default for AidingMeasurementControl {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AidingMeasurementControl {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        source: <crate::types::AidingMeasurementSource as crate::wire::Wire>::ZERO,
        enable: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_source = <crate::types::AidingMeasurementSource as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("source"))?;
        let p_enable = if r.left() > 0 {
            Some(<bool as crate::wire::Wire>::decode(r).map_err(|e| e.at("enable"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            source: p_source,
            enable: p_enable,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        let v = &self.source;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("source"))?;
        if let Some(v) = &self.enable {
            optionals.present("enable")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("enable"))?;
        } else {
            optionals.absent("enable");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.source;
        crate::json::key(w, &mut first, "source")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.enable {
            crate::json::key(w, &mut first, "enable")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AidingMeasurementControl {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "source", "enable"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_source = o.req(
            "source",
            <crate::types::AidingMeasurementSource as crate::json_read::FromJson>::from_json,
        )?;
        let p_enable = o.opt("enable", <bool as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            source: p_source,
            enable: p_enable,
        })
    }
}

impl AidingMeasurementControl {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for AidingMeasurementControl {
    const DESCRIPTOR: u8 = 0x50;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "aiding_measurement_control";
}

/// Aiding measurement control (response). Whether an aiding measurement source is enabled.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AidingMeasurementControlResponse {
    /// Aiding measurement source.
    pub source: crate::types::AidingMeasurementSource,
    /// Whether the source is used.
    pub enable: bool,
}

impl Default for AidingMeasurementControlResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AidingMeasurementControlResponse {
    const ZERO: Self = Self {
        source: <crate::types::AidingMeasurementSource as crate::wire::Wire>::ZERO,
        enable: <bool as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(3);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_source = <crate::types::AidingMeasurementSource as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("source"))?;
        let p_enable = <bool as crate::wire::Wire>::decode(r).map_err(|e| e.at("enable"))?;
        Ok(Self {
            source: p_source,
            enable: p_enable,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.source;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("source"))?;
        let v = &self.enable;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("enable"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.source;
        crate::json::key(w, &mut first, "source")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.enable;
        crate::json::key(w, &mut first, "enable")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AidingMeasurementControlResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["source", "enable"])?;
        let p_source = o.req(
            "source",
            <crate::types::AidingMeasurementSource as crate::json_read::FromJson>::from_json,
        )?;
        let p_enable = o.req("enable", <bool as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            source: p_source,
            enable: p_enable,
        })
    }
}

impl AidingMeasurementControlResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for AidingMeasurementControlResponse {
    const DESCRIPTOR: u8 = 0xD0;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "aiding_measurement_control_response";
}

/// Navigation filter initialization. Source and values of the initial conditions (position, velocity, attitude) of the navigation filter. Every parameter is always sent; the initial condition source decides which of the user values are used, and the reference frame selector gives the units of the position (ECEF: m; LLH: deg, deg, m) and the frame of the velocity.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InitializationConfiguration {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Non-zero: initialize the filter only after a Run Navigation Filter (0x0D,0x05) command. Sent for: write.
    pub wait_for_run_command: Option<u8>,
    /// Which initial conditions are automatic and which user-specified. Sent for: write.
    pub initial_cond_src: Option<crate::types::FilterInitialConditionSource>,
    /// Allowed automatic heading alignment methods. Sent for: write.
    pub auto_heading_alignment_selector: Option<crate::types::HeadingAlignmentMethods>,
    /// User-specified initial heading. Units: deg. Sent for: write.
    pub initial_heading: Option<f32>,
    /// User-specified initial pitch. Units: deg. Sent for: write.
    pub initial_pitch: Option<f32>,
    /// User-specified initial roll. Units: deg. Sent for: write.
    pub initial_roll: Option<f32>,
    /// User-specified initial position (ECEF m, or LLH deg/deg/m, per reference_frame_selector). Sent for: write.
    pub initial_position: Option<[f32; 3]>,
    /// User-specified initial velocity, in the frame chosen by reference_frame_selector. Units: m/s. Sent for: write.
    pub initial_velocity: Option<[f32; 3]>,
    /// Frame of the initial position and velocity. Sent for: write.
    pub reference_frame_selector: Option<crate::types::FilterReferenceFrame>,
}

impl Default for InitializationConfiguration {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for InitializationConfiguration {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        wait_for_run_command: None,
        initial_cond_src: None,
        auto_heading_alignment_selector: None,
        initial_heading: None,
        initial_pitch: None,
        initial_roll: None,
        initial_position: None,
        initial_velocity: None,
        reference_frame_selector: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_wait_for_run_command = if r.left() > 0 {
            Some(<u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("wait_for_run_command"))?)
        } else {
            None
        };
        let p_initial_cond_src = if r.left() > 0 {
            Some(
                <crate::types::FilterInitialConditionSource as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("initial_cond_src"))?,
            )
        } else {
            None
        };
        let p_auto_heading_alignment_selector = if r.left() > 0 {
            Some(
                <crate::types::HeadingAlignmentMethods as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("auto_heading_alignment_selector"))?,
            )
        } else {
            None
        };
        let p_initial_heading = if r.left() > 0 {
            Some(<f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("initial_heading"))?)
        } else {
            None
        };
        let p_initial_pitch = if r.left() > 0 {
            Some(<f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("initial_pitch"))?)
        } else {
            None
        };
        let p_initial_roll = if r.left() > 0 {
            Some(<f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("initial_roll"))?)
        } else {
            None
        };
        let p_initial_position = if r.left() > 0 {
            Some(<[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("initial_position"))?)
        } else {
            None
        };
        let p_initial_velocity = if r.left() > 0 {
            Some(<[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("initial_velocity"))?)
        } else {
            None
        };
        let p_reference_frame_selector = if r.left() > 0 {
            Some(
                <crate::types::FilterReferenceFrame as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("reference_frame_selector"))?,
            )
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            wait_for_run_command: p_wait_for_run_command,
            initial_cond_src: p_initial_cond_src,
            auto_heading_alignment_selector: p_auto_heading_alignment_selector,
            initial_heading: p_initial_heading,
            initial_pitch: p_initial_pitch,
            initial_roll: p_initial_roll,
            initial_position: p_initial_position,
            initial_velocity: p_initial_velocity,
            reference_frame_selector: p_reference_frame_selector,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.wait_for_run_command {
            optionals.present("wait_for_run_command")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("wait_for_run_command"))?;
        } else {
            optionals.absent("wait_for_run_command");
        }
        if let Some(v) = &self.initial_cond_src {
            optionals.present("initial_cond_src")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("initial_cond_src"))?;
        } else {
            optionals.absent("initial_cond_src");
        }
        if let Some(v) = &self.auto_heading_alignment_selector {
            optionals.present("auto_heading_alignment_selector")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("auto_heading_alignment_selector"))?;
        } else {
            optionals.absent("auto_heading_alignment_selector");
        }
        if let Some(v) = &self.initial_heading {
            optionals.present("initial_heading")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("initial_heading"))?;
        } else {
            optionals.absent("initial_heading");
        }
        if let Some(v) = &self.initial_pitch {
            optionals.present("initial_pitch")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("initial_pitch"))?;
        } else {
            optionals.absent("initial_pitch");
        }
        if let Some(v) = &self.initial_roll {
            optionals.present("initial_roll")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("initial_roll"))?;
        } else {
            optionals.absent("initial_roll");
        }
        if let Some(v) = &self.initial_position {
            optionals.present("initial_position")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("initial_position"))?;
        } else {
            optionals.absent("initial_position");
        }
        if let Some(v) = &self.initial_velocity {
            optionals.present("initial_velocity")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("initial_velocity"))?;
        } else {
            optionals.absent("initial_velocity");
        }
        if let Some(v) = &self.reference_frame_selector {
            optionals.present("reference_frame_selector")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("reference_frame_selector"))?;
        } else {
            optionals.absent("reference_frame_selector");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.wait_for_run_command {
            crate::json::key(w, &mut first, "wait_for_run_command")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.initial_cond_src {
            crate::json::key(w, &mut first, "initial_cond_src")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.auto_heading_alignment_selector {
            crate::json::key(w, &mut first, "auto_heading_alignment_selector")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.initial_heading {
            crate::json::key(w, &mut first, "initial_heading")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.initial_pitch {
            crate::json::key(w, &mut first, "initial_pitch")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.initial_roll {
            crate::json::key(w, &mut first, "initial_roll")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.initial_position {
            crate::json::key(w, &mut first, "initial_position")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.initial_velocity {
            crate::json::key(w, &mut first, "initial_velocity")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.reference_frame_selector {
            crate::json::key(w, &mut first, "reference_frame_selector")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for InitializationConfiguration {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "function",
                "wait_for_run_command",
                "initial_cond_src",
                "auto_heading_alignment_selector",
                "initial_heading",
                "initial_pitch",
                "initial_roll",
                "initial_position",
                "initial_velocity",
                "reference_frame_selector",
            ],
        )?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_wait_for_run_command = o.opt(
            "wait_for_run_command",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_initial_cond_src = o.opt(
            "initial_cond_src",
            <crate::types::FilterInitialConditionSource as crate::json_read::FromJson>::from_json,
        )?;
        let p_auto_heading_alignment_selector = o.opt(
            "auto_heading_alignment_selector",
            <crate::types::HeadingAlignmentMethods as crate::json_read::FromJson>::from_json,
        )?;
        let p_initial_heading = o.opt(
            "initial_heading",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_initial_pitch = o.opt(
            "initial_pitch",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_initial_roll = o.opt(
            "initial_roll",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_initial_position = o.opt(
            "initial_position",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_initial_velocity = o.opt(
            "initial_velocity",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_reference_frame_selector = o.opt(
            "reference_frame_selector",
            <crate::types::FilterReferenceFrame as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            wait_for_run_command: p_wait_for_run_command,
            initial_cond_src: p_initial_cond_src,
            auto_heading_alignment_selector: p_auto_heading_alignment_selector,
            initial_heading: p_initial_heading,
            initial_pitch: p_initial_pitch,
            initial_roll: p_initial_roll,
            initial_position: p_initial_position,
            initial_velocity: p_initial_velocity,
            reference_frame_selector: p_reference_frame_selector,
        })
    }
}

impl InitializationConfiguration {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for InitializationConfiguration {
    const DESCRIPTOR: u8 = 0x52;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "initialization_configuration";
}

/// Navigation filter initialization (response). Current initial condition configuration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InitializationConfigurationResponse {
    /// Non-zero: wait for the run command.
    pub wait_for_run_command: u8,
    /// Initial condition source.
    pub initial_cond_src: crate::types::FilterInitialConditionSource,
    /// Allowed automatic heading alignment methods.
    pub auto_heading_alignment_selector: crate::types::HeadingAlignmentMethods,
    /// User-specified initial heading. Units: deg.
    pub initial_heading: f32,
    /// User-specified initial pitch. Units: deg.
    pub initial_pitch: f32,
    /// User-specified initial roll. Units: deg.
    pub initial_roll: f32,
    /// User-specified initial position (ECEF m, or LLH deg/deg/m).
    pub initial_position: [f32; 3],
    /// User-specified initial velocity. Units: m/s.
    pub initial_velocity: [f32; 3],
    /// Frame of the initial position and velocity.
    pub reference_frame_selector: crate::types::FilterReferenceFrame,
}

impl Default for InitializationConfigurationResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for InitializationConfigurationResponse {
    const ZERO: Self = Self {
        wait_for_run_command: <u8 as crate::wire::Wire>::ZERO,
        initial_cond_src: <crate::types::FilterInitialConditionSource as crate::wire::Wire>::ZERO,
        auto_heading_alignment_selector:
            <crate::types::HeadingAlignmentMethods as crate::wire::Wire>::ZERO,
        initial_heading: <f32 as crate::wire::Wire>::ZERO,
        initial_pitch: <f32 as crate::wire::Wire>::ZERO,
        initial_roll: <f32 as crate::wire::Wire>::ZERO,
        initial_position: <[f32; 3] as crate::wire::Wire>::ZERO,
        initial_velocity: <[f32; 3] as crate::wire::Wire>::ZERO,
        reference_frame_selector: <crate::types::FilterReferenceFrame as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(40);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_wait_for_run_command =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("wait_for_run_command"))?;
        let p_initial_cond_src =
            <crate::types::FilterInitialConditionSource as crate::wire::Wire>::decode(r)
                .map_err(|e| e.at("initial_cond_src"))?;
        let p_auto_heading_alignment_selector =
            <crate::types::HeadingAlignmentMethods as crate::wire::Wire>::decode(r)
                .map_err(|e| e.at("auto_heading_alignment_selector"))?;
        let p_initial_heading =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("initial_heading"))?;
        let p_initial_pitch =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("initial_pitch"))?;
        let p_initial_roll =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("initial_roll"))?;
        let p_initial_position =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("initial_position"))?;
        let p_initial_velocity =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("initial_velocity"))?;
        let p_reference_frame_selector =
            <crate::types::FilterReferenceFrame as crate::wire::Wire>::decode(r)
                .map_err(|e| e.at("reference_frame_selector"))?;
        Ok(Self {
            wait_for_run_command: p_wait_for_run_command,
            initial_cond_src: p_initial_cond_src,
            auto_heading_alignment_selector: p_auto_heading_alignment_selector,
            initial_heading: p_initial_heading,
            initial_pitch: p_initial_pitch,
            initial_roll: p_initial_roll,
            initial_position: p_initial_position,
            initial_velocity: p_initial_velocity,
            reference_frame_selector: p_reference_frame_selector,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.wait_for_run_command;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("wait_for_run_command"))?;
        let v = &self.initial_cond_src;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("initial_cond_src"))?;
        let v = &self.auto_heading_alignment_selector;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("auto_heading_alignment_selector"))?;
        let v = &self.initial_heading;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("initial_heading"))?;
        let v = &self.initial_pitch;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("initial_pitch"))?;
        let v = &self.initial_roll;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("initial_roll"))?;
        let v = &self.initial_position;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("initial_position"))?;
        let v = &self.initial_velocity;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("initial_velocity"))?;
        let v = &self.reference_frame_selector;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("reference_frame_selector"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.wait_for_run_command;
        crate::json::key(w, &mut first, "wait_for_run_command")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.initial_cond_src;
        crate::json::key(w, &mut first, "initial_cond_src")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.auto_heading_alignment_selector;
        crate::json::key(w, &mut first, "auto_heading_alignment_selector")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.initial_heading;
        crate::json::key(w, &mut first, "initial_heading")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.initial_pitch;
        crate::json::key(w, &mut first, "initial_pitch")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.initial_roll;
        crate::json::key(w, &mut first, "initial_roll")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.initial_position;
        crate::json::key(w, &mut first, "initial_position")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.initial_velocity;
        crate::json::key(w, &mut first, "initial_velocity")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.reference_frame_selector;
        crate::json::key(w, &mut first, "reference_frame_selector")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for InitializationConfigurationResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "wait_for_run_command",
                "initial_cond_src",
                "auto_heading_alignment_selector",
                "initial_heading",
                "initial_pitch",
                "initial_roll",
                "initial_position",
                "initial_velocity",
                "reference_frame_selector",
            ],
        )?;
        let p_wait_for_run_command = o.req(
            "wait_for_run_command",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_initial_cond_src = o.req(
            "initial_cond_src",
            <crate::types::FilterInitialConditionSource as crate::json_read::FromJson>::from_json,
        )?;
        let p_auto_heading_alignment_selector = o.req(
            "auto_heading_alignment_selector",
            <crate::types::HeadingAlignmentMethods as crate::json_read::FromJson>::from_json,
        )?;
        let p_initial_heading = o.req(
            "initial_heading",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_initial_pitch = o.req(
            "initial_pitch",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_initial_roll = o.req(
            "initial_roll",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_initial_position = o.req(
            "initial_position",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_initial_velocity = o.req(
            "initial_velocity",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_reference_frame_selector = o.req(
            "reference_frame_selector",
            <crate::types::FilterReferenceFrame as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            wait_for_run_command: p_wait_for_run_command,
            initial_cond_src: p_initial_cond_src,
            auto_heading_alignment_selector: p_auto_heading_alignment_selector,
            initial_heading: p_initial_heading,
            initial_pitch: p_initial_pitch,
            initial_roll: p_initial_roll,
            initial_position: p_initial_position,
            initial_velocity: p_initial_velocity,
            reference_frame_selector: p_reference_frame_selector,
        })
    }
}

impl InitializationConfigurationResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for InitializationConfigurationResponse {
    const DESCRIPTOR: u8 = 0xD2;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "initialization_configuration_response";
}

/// Adaptive filter control. Basic setup of the auto-adaptive filter: how aggressively it adjusts its statistical models, and how long measurements may be rejected before it enters recovery mode.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AdaptiveFilterControl {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Auto-adaptive operating level. Sent for: write.
    pub level: Option<crate::types::AdaptiveFilterLevel>,
    /// Longest measurement rejection before recovery mode. Units: ms. Sent for: write.
    pub time_limit: Option<u16>,
}

impl Default for AdaptiveFilterControl {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AdaptiveFilterControl {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        level: None,
        time_limit: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_level = if r.left() > 0 {
            Some(
                <crate::types::AdaptiveFilterLevel as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("level"))?,
            )
        } else {
            None
        };
        let p_time_limit = if r.left() > 0 {
            Some(<u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("time_limit"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            level: p_level,
            time_limit: p_time_limit,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.level {
            optionals.present("level")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("level"))?;
        } else {
            optionals.absent("level");
        }
        if let Some(v) = &self.time_limit {
            optionals.present("time_limit")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("time_limit"))?;
        } else {
            optionals.absent("time_limit");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.level {
            crate::json::key(w, &mut first, "level")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.time_limit {
            crate::json::key(w, &mut first, "time_limit")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AdaptiveFilterControl {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "level", "time_limit"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_level = o.opt(
            "level",
            <crate::types::AdaptiveFilterLevel as crate::json_read::FromJson>::from_json,
        )?;
        let p_time_limit = o.opt("time_limit", <u16 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            level: p_level,
            time_limit: p_time_limit,
        })
    }
}

impl AdaptiveFilterControl {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for AdaptiveFilterControl {
    const DESCRIPTOR: u8 = 0x53;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "adaptive_filter_control";
}

/// Adaptive filter control (response). Current adaptive filter settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AdaptiveFilterControlResponse {
    /// Auto-adaptive operating level.
    pub level: crate::types::AdaptiveFilterLevel,
    /// Longest measurement rejection before recovery mode. Units: ms.
    pub time_limit: u16,
}

impl Default for AdaptiveFilterControlResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AdaptiveFilterControlResponse {
    const ZERO: Self = Self {
        level: <crate::types::AdaptiveFilterLevel as crate::wire::Wire>::ZERO,
        time_limit: <u16 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(3);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_level = <crate::types::AdaptiveFilterLevel as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("level"))?;
        let p_time_limit = <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("time_limit"))?;
        Ok(Self {
            level: p_level,
            time_limit: p_time_limit,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.level;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("level"))?;
        let v = &self.time_limit;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("time_limit"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.level;
        crate::json::key(w, &mut first, "level")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.time_limit;
        crate::json::key(w, &mut first, "time_limit")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AdaptiveFilterControlResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["level", "time_limit"])?;
        let p_level = o.req(
            "level",
            <crate::types::AdaptiveFilterLevel as crate::json_read::FromJson>::from_json,
        )?;
        let p_time_limit = o.req("time_limit", <u16 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            level: p_level,
            time_limit: p_time_limit,
        })
    }
}

impl AdaptiveFilterControlResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for AdaptiveFilterControlResponse {
    const DESCRIPTOR: u8 = 0xD3;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "adaptive_filter_control_response";
}

/// GNSS multi-antenna offset. Antenna lever arm of one GNSS receiver, in the vehicle frame, for devices with several antennas. The offset magnitude is limited to 10 m.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MultiAntennaOffset {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Receiver: 1, 2, . Sent for: write, read, save, load, default.
    pub receiver_id: u8,
    /// Antenna lever arm in the vehicle frame. Units: m. Sent for: write.
    pub antenna_offset: Option<[f32; 3]>,
}

impl Default for MultiAntennaOffset {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for MultiAntennaOffset {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        receiver_id: <u8 as crate::wire::Wire>::ZERO,
        antenna_offset: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_receiver_id =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("receiver_id"))?;
        let p_antenna_offset = if r.left() > 0 {
            Some(<[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("antenna_offset"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            receiver_id: p_receiver_id,
            antenna_offset: p_antenna_offset,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        let v = &self.receiver_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("receiver_id"))?;
        if let Some(v) = &self.antenna_offset {
            optionals.present("antenna_offset")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("antenna_offset"))?;
        } else {
            optionals.absent("antenna_offset");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.receiver_id;
        crate::json::key(w, &mut first, "receiver_id")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.antenna_offset {
            crate::json::key(w, &mut first, "antenna_offset")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for MultiAntennaOffset {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "receiver_id", "antenna_offset"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_receiver_id = o.req("receiver_id", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_antenna_offset = o.opt(
            "antenna_offset",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            receiver_id: p_receiver_id,
            antenna_offset: p_antenna_offset,
        })
    }
}

impl MultiAntennaOffset {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for MultiAntennaOffset {
    const DESCRIPTOR: u8 = 0x54;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "multi_antenna_offset";
}

/// GNSS multi-antenna offset (response). Current antenna lever arm of a receiver.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MultiAntennaOffsetResponse {
    /// Receiver: 1, 2, .
    pub receiver_id: u8,
    /// Antenna lever arm in the vehicle frame. Units: m.
    pub antenna_offset: [f32; 3],
}

impl Default for MultiAntennaOffsetResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for MultiAntennaOffsetResponse {
    const ZERO: Self = Self {
        receiver_id: <u8 as crate::wire::Wire>::ZERO,
        antenna_offset: <[f32; 3] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(13);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_receiver_id =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("receiver_id"))?;
        let p_antenna_offset =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("antenna_offset"))?;
        Ok(Self {
            receiver_id: p_receiver_id,
            antenna_offset: p_antenna_offset,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.receiver_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("receiver_id"))?;
        let v = &self.antenna_offset;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("antenna_offset"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.receiver_id;
        crate::json::key(w, &mut first, "receiver_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.antenna_offset;
        crate::json::key(w, &mut first, "antenna_offset")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for MultiAntennaOffsetResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["receiver_id", "antenna_offset"])?;
        let p_receiver_id = o.req("receiver_id", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_antenna_offset = o.req(
            "antenna_offset",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            receiver_id: p_receiver_id,
            antenna_offset: p_antenna_offset,
        })
    }
}

impl MultiAntennaOffsetResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for MultiAntennaOffsetResponse {
    const DESCRIPTOR: u8 = 0xD4;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "multi_antenna_offset_response";
}

/// Relative position configuration. Reference location of the filter's relative position outputs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RelativePositionConfiguration {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// 0 automatic (RTK base station), 1 manual. Sent for: write.
    pub source: Option<crate::types::RelativePositionSource>,
    /// Frame of the reference coordinates. Sent for: write.
    pub reference_frame_selector: Option<crate::types::FilterReferenceFrame>,
    /// Reference location (ECEF m, or LLH deg/deg/m). Sent for: write.
    pub reference_coordinates: Option<[f64; 3]>,
}

impl Default for RelativePositionConfiguration {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for RelativePositionConfiguration {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        source: None,
        reference_frame_selector: None,
        reference_coordinates: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_source = if r.left() > 0 {
            Some(
                <crate::types::RelativePositionSource as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("source"))?,
            )
        } else {
            None
        };
        let p_reference_frame_selector = if r.left() > 0 {
            Some(
                <crate::types::FilterReferenceFrame as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("reference_frame_selector"))?,
            )
        } else {
            None
        };
        let p_reference_coordinates = if r.left() > 0 {
            Some(
                <[f64; 3] as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("reference_coordinates"))?,
            )
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            source: p_source,
            reference_frame_selector: p_reference_frame_selector,
            reference_coordinates: p_reference_coordinates,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.source {
            optionals.present("source")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("source"))?;
        } else {
            optionals.absent("source");
        }
        if let Some(v) = &self.reference_frame_selector {
            optionals.present("reference_frame_selector")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("reference_frame_selector"))?;
        } else {
            optionals.absent("reference_frame_selector");
        }
        if let Some(v) = &self.reference_coordinates {
            optionals.present("reference_coordinates")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("reference_coordinates"))?;
        } else {
            optionals.absent("reference_coordinates");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.source {
            crate::json::key(w, &mut first, "source")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.reference_frame_selector {
            crate::json::key(w, &mut first, "reference_frame_selector")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.reference_coordinates {
            crate::json::key(w, &mut first, "reference_coordinates")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for RelativePositionConfiguration {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "function",
                "source",
                "reference_frame_selector",
                "reference_coordinates",
            ],
        )?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_source = o.opt(
            "source",
            <crate::types::RelativePositionSource as crate::json_read::FromJson>::from_json,
        )?;
        let p_reference_frame_selector = o.opt(
            "reference_frame_selector",
            <crate::types::FilterReferenceFrame as crate::json_read::FromJson>::from_json,
        )?;
        let p_reference_coordinates = o.opt(
            "reference_coordinates",
            <[f64; 3] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            source: p_source,
            reference_frame_selector: p_reference_frame_selector,
            reference_coordinates: p_reference_coordinates,
        })
    }
}

impl RelativePositionConfiguration {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for RelativePositionConfiguration {
    const DESCRIPTOR: u8 = 0x55;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "relative_position_configuration";
}

/// Relative position configuration (response). Current relative position reference.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RelativePositionConfigurationResponse {
    /// 0 automatic (RTK base station), 1 manual.
    pub source: crate::types::RelativePositionSource,
    /// Frame of the reference coordinates.
    pub reference_frame_selector: crate::types::FilterReferenceFrame,
    /// Reference location (ECEF m, or LLH deg/deg/m).
    pub reference_coordinates: [f64; 3],
}

impl Default for RelativePositionConfigurationResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for RelativePositionConfigurationResponse {
    const ZERO: Self = Self {
        source: <crate::types::RelativePositionSource as crate::wire::Wire>::ZERO,
        reference_frame_selector: <crate::types::FilterReferenceFrame as crate::wire::Wire>::ZERO,
        reference_coordinates: <[f64; 3] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(26);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_source = <crate::types::RelativePositionSource as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("source"))?;
        let p_reference_frame_selector =
            <crate::types::FilterReferenceFrame as crate::wire::Wire>::decode(r)
                .map_err(|e| e.at("reference_frame_selector"))?;
        let p_reference_coordinates = <[f64; 3] as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("reference_coordinates"))?;
        Ok(Self {
            source: p_source,
            reference_frame_selector: p_reference_frame_selector,
            reference_coordinates: p_reference_coordinates,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.source;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("source"))?;
        let v = &self.reference_frame_selector;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("reference_frame_selector"))?;
        let v = &self.reference_coordinates;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("reference_coordinates"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.source;
        crate::json::key(w, &mut first, "source")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.reference_frame_selector;
        crate::json::key(w, &mut first, "reference_frame_selector")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.reference_coordinates;
        crate::json::key(w, &mut first, "reference_coordinates")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for RelativePositionConfigurationResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "source",
                "reference_frame_selector",
                "reference_coordinates",
            ],
        )?;
        let p_source = o.req(
            "source",
            <crate::types::RelativePositionSource as crate::json_read::FromJson>::from_json,
        )?;
        let p_reference_frame_selector = o.req(
            "reference_frame_selector",
            <crate::types::FilterReferenceFrame as crate::json_read::FromJson>::from_json,
        )?;
        let p_reference_coordinates = o.req(
            "reference_coordinates",
            <[f64; 3] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            source: p_source,
            reference_frame_selector: p_reference_frame_selector,
            reference_coordinates: p_reference_coordinates,
        })
    }
}

impl RelativePositionConfigurationResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for RelativePositionConfigurationResponse {
    const DESCRIPTOR: u8 = 0xD5;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "relative_position_configuration_response";
}

/// Reference point lever arm. Lever arm from the sensor to the filter's reference point, in the vehicle frame. Moving the reference point offsets the filter position and velocity outputs according to attitude and angular rate. Limited to 10 m for the vehicle reference point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReferencePointLeverArm {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Reference point; reserved, must be 1 (vehicle). Sent for: write.
    pub ref_point_sel: Option<crate::types::ReferencePointSelector>,
    /// Lever arm in the vehicle frame. Units: m. Sent for: write.
    pub lever_arm_offset: Option<[f32; 3]>,
}

impl Default for ReferencePointLeverArm {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ReferencePointLeverArm {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        ref_point_sel: None,
        lever_arm_offset: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_ref_point_sel = if r.left() > 0 {
            Some(
                <crate::types::ReferencePointSelector as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("ref_point_sel"))?,
            )
        } else {
            None
        };
        let p_lever_arm_offset = if r.left() > 0 {
            Some(<[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("lever_arm_offset"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            ref_point_sel: p_ref_point_sel,
            lever_arm_offset: p_lever_arm_offset,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.ref_point_sel {
            optionals.present("ref_point_sel")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("ref_point_sel"))?;
        } else {
            optionals.absent("ref_point_sel");
        }
        if let Some(v) = &self.lever_arm_offset {
            optionals.present("lever_arm_offset")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("lever_arm_offset"))?;
        } else {
            optionals.absent("lever_arm_offset");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.ref_point_sel {
            crate::json::key(w, &mut first, "ref_point_sel")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.lever_arm_offset {
            crate::json::key(w, &mut first, "lever_arm_offset")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ReferencePointLeverArm {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "ref_point_sel", "lever_arm_offset"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_ref_point_sel = o.opt(
            "ref_point_sel",
            <crate::types::ReferencePointSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_lever_arm_offset = o.opt(
            "lever_arm_offset",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            ref_point_sel: p_ref_point_sel,
            lever_arm_offset: p_lever_arm_offset,
        })
    }
}

impl ReferencePointLeverArm {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for ReferencePointLeverArm {
    const DESCRIPTOR: u8 = 0x56;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "reference_point_lever_arm";
}

/// Reference point lever arm (response). Current reference point lever arm.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReferencePointLeverArmResponse {
    /// Reference point.
    pub ref_point_sel: crate::types::ReferencePointSelector,
    /// Lever arm in the vehicle frame. Units: m.
    pub lever_arm_offset: [f32; 3],
}

impl Default for ReferencePointLeverArmResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ReferencePointLeverArmResponse {
    const ZERO: Self = Self {
        ref_point_sel: <crate::types::ReferencePointSelector as crate::wire::Wire>::ZERO,
        lever_arm_offset: <[f32; 3] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(13);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_ref_point_sel =
            <crate::types::ReferencePointSelector as crate::wire::Wire>::decode(r)
                .map_err(|e| e.at("ref_point_sel"))?;
        let p_lever_arm_offset =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("lever_arm_offset"))?;
        Ok(Self {
            ref_point_sel: p_ref_point_sel,
            lever_arm_offset: p_lever_arm_offset,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.ref_point_sel;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("ref_point_sel"))?;
        let v = &self.lever_arm_offset;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("lever_arm_offset"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.ref_point_sel;
        crate::json::key(w, &mut first, "ref_point_sel")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.lever_arm_offset;
        crate::json::key(w, &mut first, "lever_arm_offset")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ReferencePointLeverArmResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["ref_point_sel", "lever_arm_offset"])?;
        let p_ref_point_sel = o.req(
            "ref_point_sel",
            <crate::types::ReferencePointSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_lever_arm_offset = o.req(
            "lever_arm_offset",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            ref_point_sel: p_ref_point_sel,
            lever_arm_offset: p_lever_arm_offset,
        })
    }
}

impl ReferencePointLeverArmResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for ReferencePointLeverArmResponse {
    const DESCRIPTOR: u8 = 0xD6;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "reference_point_lever_arm_response";
}

/// Measurement speed lever arm. Lever arm of the speed measurement point (e.g. an odometer on one wheel), in the vehicle frame, used to compensate the speed difference caused by vehicle rotation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpeedLeverArm {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Speed source; reserved, must be 1. Sent for: write, read, save, load, default.
    pub source: u8,
    /// Lever arm in the vehicle frame. Units: m. Sent for: write.
    pub lever_arm_offset: Option<[f32; 3]>,
}

impl Default for SpeedLeverArm {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SpeedLeverArm {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        source: <u8 as crate::wire::Wire>::ZERO,
        lever_arm_offset: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_source = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("source"))?;
        let p_lever_arm_offset = if r.left() > 0 {
            Some(<[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("lever_arm_offset"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            source: p_source,
            lever_arm_offset: p_lever_arm_offset,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        let v = &self.source;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("source"))?;
        if let Some(v) = &self.lever_arm_offset {
            optionals.present("lever_arm_offset")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("lever_arm_offset"))?;
        } else {
            optionals.absent("lever_arm_offset");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.source;
        crate::json::key(w, &mut first, "source")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.lever_arm_offset {
            crate::json::key(w, &mut first, "lever_arm_offset")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SpeedLeverArm {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "source", "lever_arm_offset"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_source = o.req("source", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_lever_arm_offset = o.opt(
            "lever_arm_offset",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            source: p_source,
            lever_arm_offset: p_lever_arm_offset,
        })
    }
}

impl SpeedLeverArm {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for SpeedLeverArm {
    const DESCRIPTOR: u8 = 0x61;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "speed_lever_arm";
}

/// Measurement speed lever arm (response). Current speed measurement lever arm.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpeedLeverArmResponse {
    /// Speed source (1).
    pub source: u8,
    /// Lever arm in the vehicle frame. Units: m.
    pub lever_arm_offset: [f32; 3],
}

impl Default for SpeedLeverArmResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SpeedLeverArmResponse {
    const ZERO: Self = Self {
        source: <u8 as crate::wire::Wire>::ZERO,
        lever_arm_offset: <[f32; 3] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(13);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_source = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("source"))?;
        let p_lever_arm_offset =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("lever_arm_offset"))?;
        Ok(Self {
            source: p_source,
            lever_arm_offset: p_lever_arm_offset,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.source;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("source"))?;
        let v = &self.lever_arm_offset;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("lever_arm_offset"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.source;
        crate::json::key(w, &mut first, "source")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.lever_arm_offset;
        crate::json::key(w, &mut first, "lever_arm_offset")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SpeedLeverArmResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["source", "lever_arm_offset"])?;
        let p_source = o.req("source", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_lever_arm_offset = o.req(
            "lever_arm_offset",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            source: p_source,
            lever_arm_offset: p_lever_arm_offset,
        })
    }
}

impl SpeedLeverArmResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for SpeedLeverArmResponse {
    const DESCRIPTOR: u8 = 0xE1;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "speed_lever_arm_response";
}

/// Wheeled vehicle constraint control. Enable the wheeled vehicle kinematic constraint: velocity is assumed to lie along the vehicle X axis. Helps heading for ground vehicles, especially with intermittent GNSS.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WheeledVehicleConstraintControl {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// 0 disables, 1 enables the constraint. Sent for: write.
    pub enable: Option<u8>,
}

impl Default for WheeledVehicleConstraintControl {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for WheeledVehicleConstraintControl {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        enable: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_enable = if r.left() > 0 {
            Some(<u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("enable"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            enable: p_enable,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.enable {
            optionals.present("enable")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("enable"))?;
        } else {
            optionals.absent("enable");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.enable {
            crate::json::key(w, &mut first, "enable")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for WheeledVehicleConstraintControl {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "enable"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_enable = o.opt("enable", <u8 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            enable: p_enable,
        })
    }
}

impl WheeledVehicleConstraintControl {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for WheeledVehicleConstraintControl {
    const DESCRIPTOR: u8 = 0x63;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "wheeled_vehicle_constraint_control";
}

/// Wheeled vehicle constraint control (response). Whether the wheeled vehicle constraint is enabled.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WheeledVehicleConstraintControlResponse {
    /// 0 disabled, 1 enabled.
    pub enable: u8,
}

impl Default for WheeledVehicleConstraintControlResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for WheeledVehicleConstraintControlResponse {
    const ZERO: Self = Self {
        enable: <u8 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(1);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_enable = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("enable"))?;
        Ok(Self { enable: p_enable })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.enable;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("enable"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.enable;
        crate::json::key(w, &mut first, "enable")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for WheeledVehicleConstraintControlResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["enable"])?;
        let p_enable = o.req("enable", <u8 as crate::json_read::FromJson>::from_json)?;
        Ok(Self { enable: p_enable })
    }
}

impl WheeledVehicleConstraintControlResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for WheeledVehicleConstraintControlResponse {
    const DESCRIPTOR: u8 = 0xE3;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "wheeled_vehicle_constraint_control_response";
}

/// GNSS antenna offset calibration control. Enable tracking of the GNSS antenna lever arm error, up to the given maximum offset error (CV7: default 0.1 m, at most 0.5 m).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GnssAntennaCalibrationControl {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// 0 disables, 1 enables lever arm error tracking. Sent for: write.
    pub enable: Option<u8>,
    /// Largest absolute lever arm offset error in the vehicle frame. Units: m. Sent for: write.
    pub max_offset: Option<f32>,
}

impl Default for GnssAntennaCalibrationControl {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GnssAntennaCalibrationControl {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        enable: None,
        max_offset: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_enable = if r.left() > 0 {
            Some(<u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("enable"))?)
        } else {
            None
        };
        let p_max_offset = if r.left() > 0 {
            Some(<f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("max_offset"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            enable: p_enable,
            max_offset: p_max_offset,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.enable {
            optionals.present("enable")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("enable"))?;
        } else {
            optionals.absent("enable");
        }
        if let Some(v) = &self.max_offset {
            optionals.present("max_offset")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("max_offset"))?;
        } else {
            optionals.absent("max_offset");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.enable {
            crate::json::key(w, &mut first, "enable")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.max_offset {
            crate::json::key(w, &mut first, "max_offset")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GnssAntennaCalibrationControl {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "enable", "max_offset"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_enable = o.opt("enable", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_max_offset = o.opt("max_offset", <f32 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            enable: p_enable,
            max_offset: p_max_offset,
        })
    }
}

impl GnssAntennaCalibrationControl {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for GnssAntennaCalibrationControl {
    const DESCRIPTOR: u8 = 0x64;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "gnss_antenna_calibration_control";
}

/// GNSS antenna offset calibration control (response). Current antenna lever arm calibration settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GnssAntennaCalibrationControlResponse {
    /// 0 disabled, 1 enabled.
    pub enable: u8,
    /// Largest absolute lever arm offset error. Units: m.
    pub max_offset: f32,
}

impl Default for GnssAntennaCalibrationControlResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GnssAntennaCalibrationControlResponse {
    const ZERO: Self = Self {
        enable: <u8 as crate::wire::Wire>::ZERO,
        max_offset: <f32 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(5);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_enable = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("enable"))?;
        let p_max_offset = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("max_offset"))?;
        Ok(Self {
            enable: p_enable,
            max_offset: p_max_offset,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.enable;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("enable"))?;
        let v = &self.max_offset;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("max_offset"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.enable;
        crate::json::key(w, &mut first, "enable")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.max_offset;
        crate::json::key(w, &mut first, "max_offset")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GnssAntennaCalibrationControlResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["enable", "max_offset"])?;
        let p_enable = o.req("enable", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_max_offset = o.req("max_offset", <f32 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            enable: p_enable,
            max_offset: p_max_offset,
        })
    }
}

impl GnssAntennaCalibrationControlResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0D;
}

impl crate::wire::Layout for GnssAntennaCalibrationControlResponse {
    const DESCRIPTOR: u8 = 0xE4;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0D);
    const NAME: &'static str = "gnss_antenna_calibration_control_response";
}

/// A decoded field of set 0x0D (`filter`).
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SetField {
    /// `reset_filter` (0x01).
    ResetFilter(ResetFilter),
    /// `set_initial_attitude` (0x02).
    SetInitialAttitude(SetInitialAttitude),
    /// `set_initial_heading` (0x03).
    SetInitialHeading(SetInitialHeading),
    /// `run_filter` (0x05).
    RunFilter(RunFilter),
    /// `vehicle_dynamics_mode` (0x10).
    VehicleDynamicsMode(VehicleDynamicsMode),
    /// `vehicle_dynamics_mode_response` (0x80).
    VehicleDynamicsModeResponse(VehicleDynamicsModeResponse),
    /// `sensor_to_vehicle_transform` (0x11).
    SensorToVehicleTransform(SensorToVehicleTransform),
    /// `sensor_to_vehicle_transform_response` (0x81).
    SensorToVehicleTransformResponse(SensorToVehicleTransformResponse),
    /// `sensor_to_vehicle_offset` (0x12).
    SensorToVehicleOffset(SensorToVehicleOffset),
    /// `sensor_to_vehicle_offset_response` (0x82).
    SensorToVehicleOffsetResponse(SensorToVehicleOffsetResponse),
    /// `antenna_offset` (0x13).
    AntennaOffset(AntennaOffset),
    /// `antenna_offset_response` (0x83).
    AntennaOffsetResponse(AntennaOffsetResponse),
    /// `estimation_control` (0x14).
    EstimationControl(EstimationControl),
    /// `estimation_control_response` (0x84).
    EstimationControlResponse(EstimationControlResponse),
    /// `gnss_source_control` (0x15).
    GnssSourceControl(GnssSourceControl),
    /// `gnss_source_control_response` (0x86).
    GnssSourceControlResponse(GnssSourceControlResponse),
    /// `external_gnss_update` (0x16).
    ExternalGnssUpdate(ExternalGnssUpdate),
    /// `external_heading_update` (0x17).
    ExternalHeadingUpdate(ExternalHeadingUpdate),
    /// `heading_update_control` (0x18).
    HeadingUpdateControl(HeadingUpdateControl),
    /// `heading_update_control_response` (0x87).
    HeadingUpdateControlResponse(HeadingUpdateControlResponse),
    /// `auto_init_control` (0x19).
    AutoInitControl(AutoInitControl),
    /// `auto_init_control_response` (0x88).
    AutoInitControlResponse(AutoInitControlResponse),
    /// `accel_noise` (0x1A).
    AccelNoise(AccelNoise),
    /// `accel_noise_response` (0x89).
    AccelNoiseResponse(AccelNoiseResponse),
    /// `gyro_noise` (0x1B).
    GyroNoise(GyroNoise),
    /// `gyro_noise_response` (0x8A).
    GyroNoiseResponse(GyroNoiseResponse),
    /// `accel_bias_model` (0x1C).
    AccelBiasModel(AccelBiasModel),
    /// `accel_bias_model_response` (0x8B).
    AccelBiasModelResponse(AccelBiasModelResponse),
    /// `gyro_bias_model` (0x1D).
    GyroBiasModel(GyroBiasModel),
    /// `gyro_bias_model_response` (0x8C).
    GyroBiasModelResponse(GyroBiasModelResponse),
    /// `zupt_control` (0x1E).
    ZuptControl(ZuptControl),
    /// `zupt_control_response` (0x8D).
    ZuptControlResponse(ZuptControlResponse),
    /// `external_heading_update_with_time` (0x1F).
    ExternalHeadingUpdateWithTime(ExternalHeadingUpdateWithTime),
    /// `zero_angular_rate_update_control` (0x20).
    ZeroAngularRateUpdateControl(ZeroAngularRateUpdateControl),
    /// `zero_angular_rate_update_control_response` (0x8E).
    ZeroAngularRateUpdateControlResponse(ZeroAngularRateUpdateControlResponse),
    /// `tare_orientation` (0x21).
    TareOrientation(TareOrientation),
    /// `commanded_zupt` (0x22).
    CommandedZupt(CommandedZupt),
    /// `commanded_zero_angular_rate_update` (0x23).
    CommandedZeroAngularRateUpdate(CommandedZeroAngularRateUpdate),
    /// `mag_capture_auto_calibration` (0x27).
    MagCaptureAutoCalibration(MagCaptureAutoCalibration),
    /// `gravity_noise_std_dev` (0x28).
    GravityNoiseStdDev(GravityNoiseStdDev),
    /// `gravity_noise_std_dev_response` (0x93).
    GravityNoiseStdDevResponse(GravityNoiseStdDevResponse),
    /// `pressure_altitude_noise_std_dev` (0x29).
    PressureAltitudeNoiseStdDev(PressureAltitudeNoiseStdDev),
    /// `pressure_altitude_noise_std_dev_response` (0x94).
    PressureAltitudeNoiseStdDevResponse(PressureAltitudeNoiseStdDevResponse),
    /// `hard_iron_offset_noise` (0x2B).
    HardIronOffsetNoise(HardIronOffsetNoise),
    /// `hard_iron_offset_noise_response` (0x96).
    HardIronOffsetNoiseResponse(HardIronOffsetNoiseResponse),
    /// `soft_iron_matrix_noise` (0x2C).
    SoftIronMatrixNoise(SoftIronMatrixNoise),
    /// `soft_iron_matrix_noise_response` (0x97).
    SoftIronMatrixNoiseResponse(SoftIronMatrixNoiseResponse),
    /// `mag_noise_std_dev` (0x42).
    MagNoiseStdDev(MagNoiseStdDev),
    /// `mag_noise_std_dev_response` (0xB1).
    MagNoiseStdDevResponse(MagNoiseStdDevResponse),
    /// `declination_source` (0x43).
    DeclinationSource(DeclinationSource),
    /// `declination_source_response` (0xB2).
    DeclinationSourceResponse(DeclinationSourceResponse),
    /// `gravity_magnitude_adaptive_measurement` (0x44).
    GravityMagnitudeAdaptiveMeasurement(GravityMagnitudeAdaptiveMeasurement),
    /// `gravity_magnitude_adaptive_measurement_response` (0xB3).
    GravityMagnitudeAdaptiveMeasurementResponse(GravityMagnitudeAdaptiveMeasurementResponse),
    /// `mag_magnitude_adaptive_measurement` (0x45).
    MagMagnitudeAdaptiveMeasurement(MagMagnitudeAdaptiveMeasurement),
    /// `mag_magnitude_adaptive_measurement_response` (0xB4).
    MagMagnitudeAdaptiveMeasurementResponse(MagMagnitudeAdaptiveMeasurementResponse),
    /// `mag_dip_angle_adaptive_measurement` (0x46).
    MagDipAngleAdaptiveMeasurement(MagDipAngleAdaptiveMeasurement),
    /// `mag_dip_angle_adaptive_measurement_response` (0xB5).
    MagDipAngleAdaptiveMeasurementResponse(MagDipAngleAdaptiveMeasurementResponse),
    /// `altitude_aiding_control` (0x47).
    AltitudeAidingControl(AltitudeAidingControl),
    /// `altitude_aiding_control_response` (0xB7).
    AltitudeAidingControlResponse(AltitudeAidingControlResponse),
    /// `pitch_roll_aiding_control` (0x4B).
    PitchRollAidingControl(PitchRollAidingControl),
    /// `pitch_roll_aiding_control_response` (0xBB).
    PitchRollAidingControlResponse(PitchRollAidingControlResponse),
    /// `inclination_source` (0x4C).
    InclinationSource(InclinationSource),
    /// `inclination_source_response` (0xBC).
    InclinationSourceResponse(InclinationSourceResponse),
    /// `magnetic_field_magnitude_source` (0x4D).
    MagneticFieldMagnitudeSource(MagneticFieldMagnitudeSource),
    /// `magnetic_field_magnitude_source_response` (0xBD).
    MagneticFieldMagnitudeSourceResponse(MagneticFieldMagnitudeSourceResponse),
    /// `aiding_measurement_control` (0x50).
    AidingMeasurementControl(AidingMeasurementControl),
    /// `aiding_measurement_control_response` (0xD0).
    AidingMeasurementControlResponse(AidingMeasurementControlResponse),
    /// `initialization_configuration` (0x52).
    InitializationConfiguration(InitializationConfiguration),
    /// `initialization_configuration_response` (0xD2).
    InitializationConfigurationResponse(InitializationConfigurationResponse),
    /// `adaptive_filter_control` (0x53).
    AdaptiveFilterControl(AdaptiveFilterControl),
    /// `adaptive_filter_control_response` (0xD3).
    AdaptiveFilterControlResponse(AdaptiveFilterControlResponse),
    /// `multi_antenna_offset` (0x54).
    MultiAntennaOffset(MultiAntennaOffset),
    /// `multi_antenna_offset_response` (0xD4).
    MultiAntennaOffsetResponse(MultiAntennaOffsetResponse),
    /// `relative_position_configuration` (0x55).
    RelativePositionConfiguration(RelativePositionConfiguration),
    /// `relative_position_configuration_response` (0xD5).
    RelativePositionConfigurationResponse(RelativePositionConfigurationResponse),
    /// `reference_point_lever_arm` (0x56).
    ReferencePointLeverArm(ReferencePointLeverArm),
    /// `reference_point_lever_arm_response` (0xD6).
    ReferencePointLeverArmResponse(ReferencePointLeverArmResponse),
    /// `speed_lever_arm` (0x61).
    SpeedLeverArm(SpeedLeverArm),
    /// `speed_lever_arm_response` (0xE1).
    SpeedLeverArmResponse(SpeedLeverArmResponse),
    /// `wheeled_vehicle_constraint_control` (0x63).
    WheeledVehicleConstraintControl(WheeledVehicleConstraintControl),
    /// `wheeled_vehicle_constraint_control_response` (0xE3).
    WheeledVehicleConstraintControlResponse(WheeledVehicleConstraintControlResponse),
    /// `gnss_antenna_calibration_control` (0x64).
    GnssAntennaCalibrationControl(GnssAntennaCalibrationControl),
    /// `gnss_antenna_calibration_control_response` (0xE4).
    GnssAntennaCalibrationControlResponse(GnssAntennaCalibrationControlResponse),
}

impl SetField {
    /// Field descriptor.
    pub fn descriptor(&self) -> u8 {
        match self {
            Self::ResetFilter(_) => 0x01,
            Self::SetInitialAttitude(_) => 0x02,
            Self::SetInitialHeading(_) => 0x03,
            Self::RunFilter(_) => 0x05,
            Self::VehicleDynamicsMode(_) => 0x10,
            Self::VehicleDynamicsModeResponse(_) => 0x80,
            Self::SensorToVehicleTransform(_) => 0x11,
            Self::SensorToVehicleTransformResponse(_) => 0x81,
            Self::SensorToVehicleOffset(_) => 0x12,
            Self::SensorToVehicleOffsetResponse(_) => 0x82,
            Self::AntennaOffset(_) => 0x13,
            Self::AntennaOffsetResponse(_) => 0x83,
            Self::EstimationControl(_) => 0x14,
            Self::EstimationControlResponse(_) => 0x84,
            Self::GnssSourceControl(_) => 0x15,
            Self::GnssSourceControlResponse(_) => 0x86,
            Self::ExternalGnssUpdate(_) => 0x16,
            Self::ExternalHeadingUpdate(_) => 0x17,
            Self::HeadingUpdateControl(_) => 0x18,
            Self::HeadingUpdateControlResponse(_) => 0x87,
            Self::AutoInitControl(_) => 0x19,
            Self::AutoInitControlResponse(_) => 0x88,
            Self::AccelNoise(_) => 0x1A,
            Self::AccelNoiseResponse(_) => 0x89,
            Self::GyroNoise(_) => 0x1B,
            Self::GyroNoiseResponse(_) => 0x8A,
            Self::AccelBiasModel(_) => 0x1C,
            Self::AccelBiasModelResponse(_) => 0x8B,
            Self::GyroBiasModel(_) => 0x1D,
            Self::GyroBiasModelResponse(_) => 0x8C,
            Self::ZuptControl(_) => 0x1E,
            Self::ZuptControlResponse(_) => 0x8D,
            Self::ExternalHeadingUpdateWithTime(_) => 0x1F,
            Self::ZeroAngularRateUpdateControl(_) => 0x20,
            Self::ZeroAngularRateUpdateControlResponse(_) => 0x8E,
            Self::TareOrientation(_) => 0x21,
            Self::CommandedZupt(_) => 0x22,
            Self::CommandedZeroAngularRateUpdate(_) => 0x23,
            Self::MagCaptureAutoCalibration(_) => 0x27,
            Self::GravityNoiseStdDev(_) => 0x28,
            Self::GravityNoiseStdDevResponse(_) => 0x93,
            Self::PressureAltitudeNoiseStdDev(_) => 0x29,
            Self::PressureAltitudeNoiseStdDevResponse(_) => 0x94,
            Self::HardIronOffsetNoise(_) => 0x2B,
            Self::HardIronOffsetNoiseResponse(_) => 0x96,
            Self::SoftIronMatrixNoise(_) => 0x2C,
            Self::SoftIronMatrixNoiseResponse(_) => 0x97,
            Self::MagNoiseStdDev(_) => 0x42,
            Self::MagNoiseStdDevResponse(_) => 0xB1,
            Self::DeclinationSource(_) => 0x43,
            Self::DeclinationSourceResponse(_) => 0xB2,
            Self::GravityMagnitudeAdaptiveMeasurement(_) => 0x44,
            Self::GravityMagnitudeAdaptiveMeasurementResponse(_) => 0xB3,
            Self::MagMagnitudeAdaptiveMeasurement(_) => 0x45,
            Self::MagMagnitudeAdaptiveMeasurementResponse(_) => 0xB4,
            Self::MagDipAngleAdaptiveMeasurement(_) => 0x46,
            Self::MagDipAngleAdaptiveMeasurementResponse(_) => 0xB5,
            Self::AltitudeAidingControl(_) => 0x47,
            Self::AltitudeAidingControlResponse(_) => 0xB7,
            Self::PitchRollAidingControl(_) => 0x4B,
            Self::PitchRollAidingControlResponse(_) => 0xBB,
            Self::InclinationSource(_) => 0x4C,
            Self::InclinationSourceResponse(_) => 0xBC,
            Self::MagneticFieldMagnitudeSource(_) => 0x4D,
            Self::MagneticFieldMagnitudeSourceResponse(_) => 0xBD,
            Self::AidingMeasurementControl(_) => 0x50,
            Self::AidingMeasurementControlResponse(_) => 0xD0,
            Self::InitializationConfiguration(_) => 0x52,
            Self::InitializationConfigurationResponse(_) => 0xD2,
            Self::AdaptiveFilterControl(_) => 0x53,
            Self::AdaptiveFilterControlResponse(_) => 0xD3,
            Self::MultiAntennaOffset(_) => 0x54,
            Self::MultiAntennaOffsetResponse(_) => 0xD4,
            Self::RelativePositionConfiguration(_) => 0x55,
            Self::RelativePositionConfigurationResponse(_) => 0xD5,
            Self::ReferencePointLeverArm(_) => 0x56,
            Self::ReferencePointLeverArmResponse(_) => 0xD6,
            Self::SpeedLeverArm(_) => 0x61,
            Self::SpeedLeverArmResponse(_) => 0xE1,
            Self::WheeledVehicleConstraintControl(_) => 0x63,
            Self::WheeledVehicleConstraintControlResponse(_) => 0xE3,
            Self::GnssAntennaCalibrationControl(_) => 0x64,
            Self::GnssAntennaCalibrationControlResponse(_) => 0xE4,
        }
    }

    /// Field name as printed in JSON.
    pub fn name(&self) -> &'static str {
        match self {
            Self::ResetFilter(_) => "reset_filter",
            Self::SetInitialAttitude(_) => "set_initial_attitude",
            Self::SetInitialHeading(_) => "set_initial_heading",
            Self::RunFilter(_) => "run_filter",
            Self::VehicleDynamicsMode(_) => "vehicle_dynamics_mode",
            Self::VehicleDynamicsModeResponse(_) => "vehicle_dynamics_mode_response",
            Self::SensorToVehicleTransform(_) => "sensor_to_vehicle_transform",
            Self::SensorToVehicleTransformResponse(_) => "sensor_to_vehicle_transform_response",
            Self::SensorToVehicleOffset(_) => "sensor_to_vehicle_offset",
            Self::SensorToVehicleOffsetResponse(_) => "sensor_to_vehicle_offset_response",
            Self::AntennaOffset(_) => "antenna_offset",
            Self::AntennaOffsetResponse(_) => "antenna_offset_response",
            Self::EstimationControl(_) => "estimation_control",
            Self::EstimationControlResponse(_) => "estimation_control_response",
            Self::GnssSourceControl(_) => "gnss_source_control",
            Self::GnssSourceControlResponse(_) => "gnss_source_control_response",
            Self::ExternalGnssUpdate(_) => "external_gnss_update",
            Self::ExternalHeadingUpdate(_) => "external_heading_update",
            Self::HeadingUpdateControl(_) => "heading_update_control",
            Self::HeadingUpdateControlResponse(_) => "heading_update_control_response",
            Self::AutoInitControl(_) => "auto_init_control",
            Self::AutoInitControlResponse(_) => "auto_init_control_response",
            Self::AccelNoise(_) => "accel_noise",
            Self::AccelNoiseResponse(_) => "accel_noise_response",
            Self::GyroNoise(_) => "gyro_noise",
            Self::GyroNoiseResponse(_) => "gyro_noise_response",
            Self::AccelBiasModel(_) => "accel_bias_model",
            Self::AccelBiasModelResponse(_) => "accel_bias_model_response",
            Self::GyroBiasModel(_) => "gyro_bias_model",
            Self::GyroBiasModelResponse(_) => "gyro_bias_model_response",
            Self::ZuptControl(_) => "zupt_control",
            Self::ZuptControlResponse(_) => "zupt_control_response",
            Self::ExternalHeadingUpdateWithTime(_) => "external_heading_update_with_time",
            Self::ZeroAngularRateUpdateControl(_) => "zero_angular_rate_update_control",
            Self::ZeroAngularRateUpdateControlResponse(_) => {
                "zero_angular_rate_update_control_response"
            }
            Self::TareOrientation(_) => "tare_orientation",
            Self::CommandedZupt(_) => "commanded_zupt",
            Self::CommandedZeroAngularRateUpdate(_) => "commanded_zero_angular_rate_update",
            Self::MagCaptureAutoCalibration(_) => "mag_capture_auto_calibration",
            Self::GravityNoiseStdDev(_) => "gravity_noise_std_dev",
            Self::GravityNoiseStdDevResponse(_) => "gravity_noise_std_dev_response",
            Self::PressureAltitudeNoiseStdDev(_) => "pressure_altitude_noise_std_dev",
            Self::PressureAltitudeNoiseStdDevResponse(_) => {
                "pressure_altitude_noise_std_dev_response"
            }
            Self::HardIronOffsetNoise(_) => "hard_iron_offset_noise",
            Self::HardIronOffsetNoiseResponse(_) => "hard_iron_offset_noise_response",
            Self::SoftIronMatrixNoise(_) => "soft_iron_matrix_noise",
            Self::SoftIronMatrixNoiseResponse(_) => "soft_iron_matrix_noise_response",
            Self::MagNoiseStdDev(_) => "mag_noise_std_dev",
            Self::MagNoiseStdDevResponse(_) => "mag_noise_std_dev_response",
            Self::DeclinationSource(_) => "declination_source",
            Self::DeclinationSourceResponse(_) => "declination_source_response",
            Self::GravityMagnitudeAdaptiveMeasurement(_) => {
                "gravity_magnitude_adaptive_measurement"
            }
            Self::GravityMagnitudeAdaptiveMeasurementResponse(_) => {
                "gravity_magnitude_adaptive_measurement_response"
            }
            Self::MagMagnitudeAdaptiveMeasurement(_) => "mag_magnitude_adaptive_measurement",
            Self::MagMagnitudeAdaptiveMeasurementResponse(_) => {
                "mag_magnitude_adaptive_measurement_response"
            }
            Self::MagDipAngleAdaptiveMeasurement(_) => "mag_dip_angle_adaptive_measurement",
            Self::MagDipAngleAdaptiveMeasurementResponse(_) => {
                "mag_dip_angle_adaptive_measurement_response"
            }
            Self::AltitudeAidingControl(_) => "altitude_aiding_control",
            Self::AltitudeAidingControlResponse(_) => "altitude_aiding_control_response",
            Self::PitchRollAidingControl(_) => "pitch_roll_aiding_control",
            Self::PitchRollAidingControlResponse(_) => "pitch_roll_aiding_control_response",
            Self::InclinationSource(_) => "inclination_source",
            Self::InclinationSourceResponse(_) => "inclination_source_response",
            Self::MagneticFieldMagnitudeSource(_) => "magnetic_field_magnitude_source",
            Self::MagneticFieldMagnitudeSourceResponse(_) => {
                "magnetic_field_magnitude_source_response"
            }
            Self::AidingMeasurementControl(_) => "aiding_measurement_control",
            Self::AidingMeasurementControlResponse(_) => "aiding_measurement_control_response",
            Self::InitializationConfiguration(_) => "initialization_configuration",
            Self::InitializationConfigurationResponse(_) => "initialization_configuration_response",
            Self::AdaptiveFilterControl(_) => "adaptive_filter_control",
            Self::AdaptiveFilterControlResponse(_) => "adaptive_filter_control_response",
            Self::MultiAntennaOffset(_) => "multi_antenna_offset",
            Self::MultiAntennaOffsetResponse(_) => "multi_antenna_offset_response",
            Self::RelativePositionConfiguration(_) => "relative_position_configuration",
            Self::RelativePositionConfigurationResponse(_) => {
                "relative_position_configuration_response"
            }
            Self::ReferencePointLeverArm(_) => "reference_point_lever_arm",
            Self::ReferencePointLeverArmResponse(_) => "reference_point_lever_arm_response",
            Self::SpeedLeverArm(_) => "speed_lever_arm",
            Self::SpeedLeverArmResponse(_) => "speed_lever_arm_response",
            Self::WheeledVehicleConstraintControl(_) => "wheeled_vehicle_constraint_control",
            Self::WheeledVehicleConstraintControlResponse(_) => {
                "wheeled_vehicle_constraint_control_response"
            }
            Self::GnssAntennaCalibrationControl(_) => "gnss_antenna_calibration_control",
            Self::GnssAntennaCalibrationControlResponse(_) => {
                "gnss_antenna_calibration_control_response"
            }
        }
    }

    /// Device of the layout used, for fields with per-device layouts.
    pub fn device(&self) -> Option<crate::Device> {
        match self {
            Self::ResetFilter(_) => None,
            Self::SetInitialAttitude(_) => None,
            Self::SetInitialHeading(_) => None,
            Self::RunFilter(_) => None,
            Self::VehicleDynamicsMode(_) => None,
            Self::VehicleDynamicsModeResponse(_) => None,
            Self::SensorToVehicleTransform(_) => None,
            Self::SensorToVehicleTransformResponse(_) => None,
            Self::SensorToVehicleOffset(_) => None,
            Self::SensorToVehicleOffsetResponse(_) => None,
            Self::AntennaOffset(_) => None,
            Self::AntennaOffsetResponse(_) => None,
            Self::EstimationControl(_) => None,
            Self::EstimationControlResponse(_) => None,
            Self::GnssSourceControl(_) => None,
            Self::GnssSourceControlResponse(_) => None,
            Self::ExternalGnssUpdate(_) => None,
            Self::ExternalHeadingUpdate(_) => None,
            Self::HeadingUpdateControl(_) => None,
            Self::HeadingUpdateControlResponse(_) => None,
            Self::AutoInitControl(_) => None,
            Self::AutoInitControlResponse(_) => None,
            Self::AccelNoise(_) => None,
            Self::AccelNoiseResponse(_) => None,
            Self::GyroNoise(_) => None,
            Self::GyroNoiseResponse(_) => None,
            Self::AccelBiasModel(_) => None,
            Self::AccelBiasModelResponse(_) => None,
            Self::GyroBiasModel(_) => None,
            Self::GyroBiasModelResponse(_) => None,
            Self::ZuptControl(_) => None,
            Self::ZuptControlResponse(_) => None,
            Self::ExternalHeadingUpdateWithTime(_) => None,
            Self::ZeroAngularRateUpdateControl(_) => None,
            Self::ZeroAngularRateUpdateControlResponse(_) => None,
            Self::TareOrientation(_) => None,
            Self::CommandedZupt(_) => None,
            Self::CommandedZeroAngularRateUpdate(_) => None,
            Self::MagCaptureAutoCalibration(_) => None,
            Self::GravityNoiseStdDev(_) => None,
            Self::GravityNoiseStdDevResponse(_) => None,
            Self::PressureAltitudeNoiseStdDev(_) => None,
            Self::PressureAltitudeNoiseStdDevResponse(_) => None,
            Self::HardIronOffsetNoise(_) => None,
            Self::HardIronOffsetNoiseResponse(_) => None,
            Self::SoftIronMatrixNoise(_) => None,
            Self::SoftIronMatrixNoiseResponse(_) => None,
            Self::MagNoiseStdDev(_) => None,
            Self::MagNoiseStdDevResponse(_) => None,
            Self::DeclinationSource(_) => None,
            Self::DeclinationSourceResponse(_) => None,
            Self::GravityMagnitudeAdaptiveMeasurement(_) => None,
            Self::GravityMagnitudeAdaptiveMeasurementResponse(_) => None,
            Self::MagMagnitudeAdaptiveMeasurement(_) => None,
            Self::MagMagnitudeAdaptiveMeasurementResponse(_) => None,
            Self::MagDipAngleAdaptiveMeasurement(_) => None,
            Self::MagDipAngleAdaptiveMeasurementResponse(_) => None,
            Self::AltitudeAidingControl(_) => None,
            Self::AltitudeAidingControlResponse(_) => None,
            Self::PitchRollAidingControl(_) => None,
            Self::PitchRollAidingControlResponse(_) => None,
            Self::InclinationSource(_) => None,
            Self::InclinationSourceResponse(_) => None,
            Self::MagneticFieldMagnitudeSource(_) => None,
            Self::MagneticFieldMagnitudeSourceResponse(_) => None,
            Self::AidingMeasurementControl(_) => None,
            Self::AidingMeasurementControlResponse(_) => None,
            Self::InitializationConfiguration(_) => None,
            Self::InitializationConfigurationResponse(_) => None,
            Self::AdaptiveFilterControl(_) => None,
            Self::AdaptiveFilterControlResponse(_) => None,
            Self::MultiAntennaOffset(_) => None,
            Self::MultiAntennaOffsetResponse(_) => None,
            Self::RelativePositionConfiguration(_) => None,
            Self::RelativePositionConfigurationResponse(_) => None,
            Self::ReferencePointLeverArm(_) => None,
            Self::ReferencePointLeverArmResponse(_) => None,
            Self::SpeedLeverArm(_) => None,
            Self::SpeedLeverArmResponse(_) => None,
            Self::WheeledVehicleConstraintControl(_) => None,
            Self::WheeledVehicleConstraintControlResponse(_) => None,
            Self::GnssAntennaCalibrationControl(_) => None,
            Self::GnssAntennaCalibrationControlResponse(_) => None,
        }
    }

    /// Encodes the field data.
    pub fn encode_data(
        &self,
        w: &mut crate::wire::Writer<'_>,
    ) -> Result<(), crate::error::EncodeError> {
        match self {
            Self::ResetFilter(v) => crate::wire::Layout::encode_data(v, w),
            Self::SetInitialAttitude(v) => crate::wire::Layout::encode_data(v, w),
            Self::SetInitialHeading(v) => crate::wire::Layout::encode_data(v, w),
            Self::RunFilter(v) => crate::wire::Layout::encode_data(v, w),
            Self::VehicleDynamicsMode(v) => crate::wire::Layout::encode_data(v, w),
            Self::VehicleDynamicsModeResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::SensorToVehicleTransform(v) => crate::wire::Layout::encode_data(v, w),
            Self::SensorToVehicleTransformResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::SensorToVehicleOffset(v) => crate::wire::Layout::encode_data(v, w),
            Self::SensorToVehicleOffsetResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::AntennaOffset(v) => crate::wire::Layout::encode_data(v, w),
            Self::AntennaOffsetResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::EstimationControl(v) => crate::wire::Layout::encode_data(v, w),
            Self::EstimationControlResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::GnssSourceControl(v) => crate::wire::Layout::encode_data(v, w),
            Self::GnssSourceControlResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::ExternalGnssUpdate(v) => crate::wire::Layout::encode_data(v, w),
            Self::ExternalHeadingUpdate(v) => crate::wire::Layout::encode_data(v, w),
            Self::HeadingUpdateControl(v) => crate::wire::Layout::encode_data(v, w),
            Self::HeadingUpdateControlResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::AutoInitControl(v) => crate::wire::Layout::encode_data(v, w),
            Self::AutoInitControlResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::AccelNoise(v) => crate::wire::Layout::encode_data(v, w),
            Self::AccelNoiseResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::GyroNoise(v) => crate::wire::Layout::encode_data(v, w),
            Self::GyroNoiseResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::AccelBiasModel(v) => crate::wire::Layout::encode_data(v, w),
            Self::AccelBiasModelResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::GyroBiasModel(v) => crate::wire::Layout::encode_data(v, w),
            Self::GyroBiasModelResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::ZuptControl(v) => crate::wire::Layout::encode_data(v, w),
            Self::ZuptControlResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::ExternalHeadingUpdateWithTime(v) => crate::wire::Layout::encode_data(v, w),
            Self::ZeroAngularRateUpdateControl(v) => crate::wire::Layout::encode_data(v, w),
            Self::ZeroAngularRateUpdateControlResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::TareOrientation(v) => crate::wire::Layout::encode_data(v, w),
            Self::CommandedZupt(v) => crate::wire::Layout::encode_data(v, w),
            Self::CommandedZeroAngularRateUpdate(v) => crate::wire::Layout::encode_data(v, w),
            Self::MagCaptureAutoCalibration(v) => crate::wire::Layout::encode_data(v, w),
            Self::GravityNoiseStdDev(v) => crate::wire::Layout::encode_data(v, w),
            Self::GravityNoiseStdDevResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::PressureAltitudeNoiseStdDev(v) => crate::wire::Layout::encode_data(v, w),
            Self::PressureAltitudeNoiseStdDevResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::HardIronOffsetNoise(v) => crate::wire::Layout::encode_data(v, w),
            Self::HardIronOffsetNoiseResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::SoftIronMatrixNoise(v) => crate::wire::Layout::encode_data(v, w),
            Self::SoftIronMatrixNoiseResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::MagNoiseStdDev(v) => crate::wire::Layout::encode_data(v, w),
            Self::MagNoiseStdDevResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::DeclinationSource(v) => crate::wire::Layout::encode_data(v, w),
            Self::DeclinationSourceResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::GravityMagnitudeAdaptiveMeasurement(v) => crate::wire::Layout::encode_data(v, w),
            Self::GravityMagnitudeAdaptiveMeasurementResponse(v) => {
                crate::wire::Layout::encode_data(v, w)
            }
            Self::MagMagnitudeAdaptiveMeasurement(v) => crate::wire::Layout::encode_data(v, w),
            Self::MagMagnitudeAdaptiveMeasurementResponse(v) => {
                crate::wire::Layout::encode_data(v, w)
            }
            Self::MagDipAngleAdaptiveMeasurement(v) => crate::wire::Layout::encode_data(v, w),
            Self::MagDipAngleAdaptiveMeasurementResponse(v) => {
                crate::wire::Layout::encode_data(v, w)
            }
            Self::AltitudeAidingControl(v) => crate::wire::Layout::encode_data(v, w),
            Self::AltitudeAidingControlResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::PitchRollAidingControl(v) => crate::wire::Layout::encode_data(v, w),
            Self::PitchRollAidingControlResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::InclinationSource(v) => crate::wire::Layout::encode_data(v, w),
            Self::InclinationSourceResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::MagneticFieldMagnitudeSource(v) => crate::wire::Layout::encode_data(v, w),
            Self::MagneticFieldMagnitudeSourceResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::AidingMeasurementControl(v) => crate::wire::Layout::encode_data(v, w),
            Self::AidingMeasurementControlResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::InitializationConfiguration(v) => crate::wire::Layout::encode_data(v, w),
            Self::InitializationConfigurationResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::AdaptiveFilterControl(v) => crate::wire::Layout::encode_data(v, w),
            Self::AdaptiveFilterControlResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::MultiAntennaOffset(v) => crate::wire::Layout::encode_data(v, w),
            Self::MultiAntennaOffsetResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::RelativePositionConfiguration(v) => crate::wire::Layout::encode_data(v, w),
            Self::RelativePositionConfigurationResponse(v) => {
                crate::wire::Layout::encode_data(v, w)
            }
            Self::ReferencePointLeverArm(v) => crate::wire::Layout::encode_data(v, w),
            Self::ReferencePointLeverArmResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::SpeedLeverArm(v) => crate::wire::Layout::encode_data(v, w),
            Self::SpeedLeverArmResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::WheeledVehicleConstraintControl(v) => crate::wire::Layout::encode_data(v, w),
            Self::WheeledVehicleConstraintControlResponse(v) => {
                crate::wire::Layout::encode_data(v, w)
            }
            Self::GnssAntennaCalibrationControl(v) => crate::wire::Layout::encode_data(v, w),
            Self::GnssAntennaCalibrationControlResponse(v) => {
                crate::wire::Layout::encode_data(v, w)
            }
        }
    }

    /// Writes the canonical JSON of the values (`{...}`).
    pub fn write_values_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::ResetFilter(v) => crate::wire::Wire::write_json(v, w),
            Self::SetInitialAttitude(v) => crate::wire::Wire::write_json(v, w),
            Self::SetInitialHeading(v) => crate::wire::Wire::write_json(v, w),
            Self::RunFilter(v) => crate::wire::Wire::write_json(v, w),
            Self::VehicleDynamicsMode(v) => crate::wire::Wire::write_json(v, w),
            Self::VehicleDynamicsModeResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::SensorToVehicleTransform(v) => crate::wire::Wire::write_json(v, w),
            Self::SensorToVehicleTransformResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::SensorToVehicleOffset(v) => crate::wire::Wire::write_json(v, w),
            Self::SensorToVehicleOffsetResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::AntennaOffset(v) => crate::wire::Wire::write_json(v, w),
            Self::AntennaOffsetResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::EstimationControl(v) => crate::wire::Wire::write_json(v, w),
            Self::EstimationControlResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::GnssSourceControl(v) => crate::wire::Wire::write_json(v, w),
            Self::GnssSourceControlResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::ExternalGnssUpdate(v) => crate::wire::Wire::write_json(v, w),
            Self::ExternalHeadingUpdate(v) => crate::wire::Wire::write_json(v, w),
            Self::HeadingUpdateControl(v) => crate::wire::Wire::write_json(v, w),
            Self::HeadingUpdateControlResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::AutoInitControl(v) => crate::wire::Wire::write_json(v, w),
            Self::AutoInitControlResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::AccelNoise(v) => crate::wire::Wire::write_json(v, w),
            Self::AccelNoiseResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::GyroNoise(v) => crate::wire::Wire::write_json(v, w),
            Self::GyroNoiseResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::AccelBiasModel(v) => crate::wire::Wire::write_json(v, w),
            Self::AccelBiasModelResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::GyroBiasModel(v) => crate::wire::Wire::write_json(v, w),
            Self::GyroBiasModelResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::ZuptControl(v) => crate::wire::Wire::write_json(v, w),
            Self::ZuptControlResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::ExternalHeadingUpdateWithTime(v) => crate::wire::Wire::write_json(v, w),
            Self::ZeroAngularRateUpdateControl(v) => crate::wire::Wire::write_json(v, w),
            Self::ZeroAngularRateUpdateControlResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::TareOrientation(v) => crate::wire::Wire::write_json(v, w),
            Self::CommandedZupt(v) => crate::wire::Wire::write_json(v, w),
            Self::CommandedZeroAngularRateUpdate(v) => crate::wire::Wire::write_json(v, w),
            Self::MagCaptureAutoCalibration(v) => crate::wire::Wire::write_json(v, w),
            Self::GravityNoiseStdDev(v) => crate::wire::Wire::write_json(v, w),
            Self::GravityNoiseStdDevResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::PressureAltitudeNoiseStdDev(v) => crate::wire::Wire::write_json(v, w),
            Self::PressureAltitudeNoiseStdDevResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::HardIronOffsetNoise(v) => crate::wire::Wire::write_json(v, w),
            Self::HardIronOffsetNoiseResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::SoftIronMatrixNoise(v) => crate::wire::Wire::write_json(v, w),
            Self::SoftIronMatrixNoiseResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::MagNoiseStdDev(v) => crate::wire::Wire::write_json(v, w),
            Self::MagNoiseStdDevResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::DeclinationSource(v) => crate::wire::Wire::write_json(v, w),
            Self::DeclinationSourceResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::GravityMagnitudeAdaptiveMeasurement(v) => crate::wire::Wire::write_json(v, w),
            Self::GravityMagnitudeAdaptiveMeasurementResponse(v) => {
                crate::wire::Wire::write_json(v, w)
            }
            Self::MagMagnitudeAdaptiveMeasurement(v) => crate::wire::Wire::write_json(v, w),
            Self::MagMagnitudeAdaptiveMeasurementResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::MagDipAngleAdaptiveMeasurement(v) => crate::wire::Wire::write_json(v, w),
            Self::MagDipAngleAdaptiveMeasurementResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::AltitudeAidingControl(v) => crate::wire::Wire::write_json(v, w),
            Self::AltitudeAidingControlResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::PitchRollAidingControl(v) => crate::wire::Wire::write_json(v, w),
            Self::PitchRollAidingControlResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::InclinationSource(v) => crate::wire::Wire::write_json(v, w),
            Self::InclinationSourceResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::MagneticFieldMagnitudeSource(v) => crate::wire::Wire::write_json(v, w),
            Self::MagneticFieldMagnitudeSourceResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::AidingMeasurementControl(v) => crate::wire::Wire::write_json(v, w),
            Self::AidingMeasurementControlResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::InitializationConfiguration(v) => crate::wire::Wire::write_json(v, w),
            Self::InitializationConfigurationResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::AdaptiveFilterControl(v) => crate::wire::Wire::write_json(v, w),
            Self::AdaptiveFilterControlResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::MultiAntennaOffset(v) => crate::wire::Wire::write_json(v, w),
            Self::MultiAntennaOffsetResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::RelativePositionConfiguration(v) => crate::wire::Wire::write_json(v, w),
            Self::RelativePositionConfigurationResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::ReferencePointLeverArm(v) => crate::wire::Wire::write_json(v, w),
            Self::ReferencePointLeverArmResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::SpeedLeverArm(v) => crate::wire::Wire::write_json(v, w),
            Self::SpeedLeverArmResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::WheeledVehicleConstraintControl(v) => crate::wire::Wire::write_json(v, w),
            Self::WheeledVehicleConstraintControlResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::GnssAntennaCalibrationControl(v) => crate::wire::Wire::write_json(v, w),
            Self::GnssAntennaCalibrationControlResponse(v) => crate::wire::Wire::write_json(v, w),
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
                Some(<ResetFilter as crate::wire::Layout>::decode_data(data).map(Self::ResetFilter))
            }
            0x02 => Some(
                <SetInitialAttitude as crate::wire::Layout>::decode_data(data)
                    .map(Self::SetInitialAttitude),
            ),
            0x03 => Some(
                <SetInitialHeading as crate::wire::Layout>::decode_data(data)
                    .map(Self::SetInitialHeading),
            ),
            0x05 => {
                Some(<RunFilter as crate::wire::Layout>::decode_data(data).map(Self::RunFilter))
            }
            0x10 => Some(
                <VehicleDynamicsMode as crate::wire::Layout>::decode_data(data)
                    .map(Self::VehicleDynamicsMode),
            ),
            0x80 => Some(
                <VehicleDynamicsModeResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::VehicleDynamicsModeResponse),
            ),
            0x11 => Some(
                <SensorToVehicleTransform as crate::wire::Layout>::decode_data(data)
                    .map(Self::SensorToVehicleTransform),
            ),
            0x81 => Some(
                <SensorToVehicleTransformResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::SensorToVehicleTransformResponse),
            ),
            0x12 => Some(
                <SensorToVehicleOffset as crate::wire::Layout>::decode_data(data)
                    .map(Self::SensorToVehicleOffset),
            ),
            0x82 => Some(
                <SensorToVehicleOffsetResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::SensorToVehicleOffsetResponse),
            ),
            0x13 => Some(
                <AntennaOffset as crate::wire::Layout>::decode_data(data).map(Self::AntennaOffset),
            ),
            0x83 => Some(
                <AntennaOffsetResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::AntennaOffsetResponse),
            ),
            0x14 => Some(
                <EstimationControl as crate::wire::Layout>::decode_data(data)
                    .map(Self::EstimationControl),
            ),
            0x84 => Some(
                <EstimationControlResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::EstimationControlResponse),
            ),
            0x15 => Some(
                <GnssSourceControl as crate::wire::Layout>::decode_data(data)
                    .map(Self::GnssSourceControl),
            ),
            0x86 => Some(
                <GnssSourceControlResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::GnssSourceControlResponse),
            ),
            0x16 => Some(
                <ExternalGnssUpdate as crate::wire::Layout>::decode_data(data)
                    .map(Self::ExternalGnssUpdate),
            ),
            0x17 => Some(
                <ExternalHeadingUpdate as crate::wire::Layout>::decode_data(data)
                    .map(Self::ExternalHeadingUpdate),
            ),
            0x18 => Some(
                <HeadingUpdateControl as crate::wire::Layout>::decode_data(data)
                    .map(Self::HeadingUpdateControl),
            ),
            0x87 => Some(
                <HeadingUpdateControlResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::HeadingUpdateControlResponse),
            ),
            0x19 => Some(
                <AutoInitControl as crate::wire::Layout>::decode_data(data)
                    .map(Self::AutoInitControl),
            ),
            0x88 => Some(
                <AutoInitControlResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::AutoInitControlResponse),
            ),
            0x1A => {
                Some(<AccelNoise as crate::wire::Layout>::decode_data(data).map(Self::AccelNoise))
            }
            0x89 => Some(
                <AccelNoiseResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::AccelNoiseResponse),
            ),
            0x1B => {
                Some(<GyroNoise as crate::wire::Layout>::decode_data(data).map(Self::GyroNoise))
            }
            0x8A => Some(
                <GyroNoiseResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::GyroNoiseResponse),
            ),
            0x1C => Some(
                <AccelBiasModel as crate::wire::Layout>::decode_data(data)
                    .map(Self::AccelBiasModel),
            ),
            0x8B => Some(
                <AccelBiasModelResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::AccelBiasModelResponse),
            ),
            0x1D => Some(
                <GyroBiasModel as crate::wire::Layout>::decode_data(data).map(Self::GyroBiasModel),
            ),
            0x8C => Some(
                <GyroBiasModelResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::GyroBiasModelResponse),
            ),
            0x1E => {
                Some(<ZuptControl as crate::wire::Layout>::decode_data(data).map(Self::ZuptControl))
            }
            0x8D => Some(
                <ZuptControlResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::ZuptControlResponse),
            ),
            0x1F => Some(
                <ExternalHeadingUpdateWithTime as crate::wire::Layout>::decode_data(data)
                    .map(Self::ExternalHeadingUpdateWithTime),
            ),
            0x20 => Some(
                <ZeroAngularRateUpdateControl as crate::wire::Layout>::decode_data(data)
                    .map(Self::ZeroAngularRateUpdateControl),
            ),
            0x8E => Some(
                <ZeroAngularRateUpdateControlResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::ZeroAngularRateUpdateControlResponse),
            ),
            0x21 => Some(
                <TareOrientation as crate::wire::Layout>::decode_data(data)
                    .map(Self::TareOrientation),
            ),
            0x22 => Some(
                <CommandedZupt as crate::wire::Layout>::decode_data(data).map(Self::CommandedZupt),
            ),
            0x23 => Some(
                <CommandedZeroAngularRateUpdate as crate::wire::Layout>::decode_data(data)
                    .map(Self::CommandedZeroAngularRateUpdate),
            ),
            0x27 => Some(
                <MagCaptureAutoCalibration as crate::wire::Layout>::decode_data(data)
                    .map(Self::MagCaptureAutoCalibration),
            ),
            0x28 => Some(
                <GravityNoiseStdDev as crate::wire::Layout>::decode_data(data)
                    .map(Self::GravityNoiseStdDev),
            ),
            0x93 => Some(
                <GravityNoiseStdDevResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::GravityNoiseStdDevResponse),
            ),
            0x29 => Some(
                <PressureAltitudeNoiseStdDev as crate::wire::Layout>::decode_data(data)
                    .map(Self::PressureAltitudeNoiseStdDev),
            ),
            0x94 => Some(
                <PressureAltitudeNoiseStdDevResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::PressureAltitudeNoiseStdDevResponse),
            ),
            0x2B => Some(
                <HardIronOffsetNoise as crate::wire::Layout>::decode_data(data)
                    .map(Self::HardIronOffsetNoise),
            ),
            0x96 => Some(
                <HardIronOffsetNoiseResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::HardIronOffsetNoiseResponse),
            ),
            0x2C => Some(
                <SoftIronMatrixNoise as crate::wire::Layout>::decode_data(data)
                    .map(Self::SoftIronMatrixNoise),
            ),
            0x97 => Some(
                <SoftIronMatrixNoiseResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::SoftIronMatrixNoiseResponse),
            ),
            0x42 => Some(
                <MagNoiseStdDev as crate::wire::Layout>::decode_data(data)
                    .map(Self::MagNoiseStdDev),
            ),
            0xB1 => Some(
                <MagNoiseStdDevResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::MagNoiseStdDevResponse),
            ),
            0x43 => Some(
                <DeclinationSource as crate::wire::Layout>::decode_data(data)
                    .map(Self::DeclinationSource),
            ),
            0xB2 => Some(
                <DeclinationSourceResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::DeclinationSourceResponse),
            ),
            0x44 => Some(
                <GravityMagnitudeAdaptiveMeasurement as crate::wire::Layout>::decode_data(data)
                    .map(Self::GravityMagnitudeAdaptiveMeasurement),
            ),
            0xB3 => Some(
                <GravityMagnitudeAdaptiveMeasurementResponse as crate::wire::Layout>::decode_data(
                    data,
                )
                .map(Self::GravityMagnitudeAdaptiveMeasurementResponse),
            ),
            0x45 => Some(
                <MagMagnitudeAdaptiveMeasurement as crate::wire::Layout>::decode_data(data)
                    .map(Self::MagMagnitudeAdaptiveMeasurement),
            ),
            0xB4 => Some(
                <MagMagnitudeAdaptiveMeasurementResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::MagMagnitudeAdaptiveMeasurementResponse),
            ),
            0x46 => Some(
                <MagDipAngleAdaptiveMeasurement as crate::wire::Layout>::decode_data(data)
                    .map(Self::MagDipAngleAdaptiveMeasurement),
            ),
            0xB5 => Some(
                <MagDipAngleAdaptiveMeasurementResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::MagDipAngleAdaptiveMeasurementResponse),
            ),
            0x47 => Some(
                <AltitudeAidingControl as crate::wire::Layout>::decode_data(data)
                    .map(Self::AltitudeAidingControl),
            ),
            0xB7 => Some(
                <AltitudeAidingControlResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::AltitudeAidingControlResponse),
            ),
            0x4B => Some(
                <PitchRollAidingControl as crate::wire::Layout>::decode_data(data)
                    .map(Self::PitchRollAidingControl),
            ),
            0xBB => Some(
                <PitchRollAidingControlResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::PitchRollAidingControlResponse),
            ),
            0x4C => Some(
                <InclinationSource as crate::wire::Layout>::decode_data(data)
                    .map(Self::InclinationSource),
            ),
            0xBC => Some(
                <InclinationSourceResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::InclinationSourceResponse),
            ),
            0x4D => Some(
                <MagneticFieldMagnitudeSource as crate::wire::Layout>::decode_data(data)
                    .map(Self::MagneticFieldMagnitudeSource),
            ),
            0xBD => Some(
                <MagneticFieldMagnitudeSourceResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::MagneticFieldMagnitudeSourceResponse),
            ),
            0x50 => Some(
                <AidingMeasurementControl as crate::wire::Layout>::decode_data(data)
                    .map(Self::AidingMeasurementControl),
            ),
            0xD0 => Some(
                <AidingMeasurementControlResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::AidingMeasurementControlResponse),
            ),
            0x52 => Some(
                <InitializationConfiguration as crate::wire::Layout>::decode_data(data)
                    .map(Self::InitializationConfiguration),
            ),
            0xD2 => Some(
                <InitializationConfigurationResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::InitializationConfigurationResponse),
            ),
            0x53 => Some(
                <AdaptiveFilterControl as crate::wire::Layout>::decode_data(data)
                    .map(Self::AdaptiveFilterControl),
            ),
            0xD3 => Some(
                <AdaptiveFilterControlResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::AdaptiveFilterControlResponse),
            ),
            0x54 => Some(
                <MultiAntennaOffset as crate::wire::Layout>::decode_data(data)
                    .map(Self::MultiAntennaOffset),
            ),
            0xD4 => Some(
                <MultiAntennaOffsetResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::MultiAntennaOffsetResponse),
            ),
            0x55 => Some(
                <RelativePositionConfiguration as crate::wire::Layout>::decode_data(data)
                    .map(Self::RelativePositionConfiguration),
            ),
            0xD5 => Some(
                <RelativePositionConfigurationResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::RelativePositionConfigurationResponse),
            ),
            0x56 => Some(
                <ReferencePointLeverArm as crate::wire::Layout>::decode_data(data)
                    .map(Self::ReferencePointLeverArm),
            ),
            0xD6 => Some(
                <ReferencePointLeverArmResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::ReferencePointLeverArmResponse),
            ),
            0x61 => Some(
                <SpeedLeverArm as crate::wire::Layout>::decode_data(data).map(Self::SpeedLeverArm),
            ),
            0xE1 => Some(
                <SpeedLeverArmResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::SpeedLeverArmResponse),
            ),
            0x63 => Some(
                <WheeledVehicleConstraintControl as crate::wire::Layout>::decode_data(data)
                    .map(Self::WheeledVehicleConstraintControl),
            ),
            0xE3 => Some(
                <WheeledVehicleConstraintControlResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::WheeledVehicleConstraintControlResponse),
            ),
            0x64 => Some(
                <GnssAntennaCalibrationControl as crate::wire::Layout>::decode_data(data)
                    .map(Self::GnssAntennaCalibrationControl),
            ),
            0xE4 => Some(
                <GnssAntennaCalibrationControlResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::GnssAntennaCalibrationControlResponse),
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
            0x01 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ResetFilter as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::ResetFilter),
            ),
            0x02 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SetInitialAttitude as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::SetInitialAttitude),
            ),
            0x03 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SetInitialHeading as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::SetInitialHeading),
            ),
            0x05 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <RunFilter as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::RunFilter),
            ),
            0x10 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <VehicleDynamicsMode as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::VehicleDynamicsMode),
            ),
            0x80 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <VehicleDynamicsModeResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::VehicleDynamicsModeResponse),
            ),
            0x11 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SensorToVehicleTransform as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::SensorToVehicleTransform),
            ),
            0x81 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SensorToVehicleTransformResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::SensorToVehicleTransformResponse),
            ),
            0x12 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SensorToVehicleOffset as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::SensorToVehicleOffset),
            ),
            0x82 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SensorToVehicleOffsetResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::SensorToVehicleOffsetResponse),
            ),
            0x13 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AntennaOffset as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::AntennaOffset),
            ),
            0x83 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AntennaOffsetResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::AntennaOffsetResponse),
            ),
            0x14 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <EstimationControl as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::EstimationControl),
            ),
            0x84 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <EstimationControlResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::EstimationControlResponse),
            ),
            0x15 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GnssSourceControl as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GnssSourceControl),
            ),
            0x86 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GnssSourceControlResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GnssSourceControlResponse),
            ),
            0x16 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ExternalGnssUpdate as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::ExternalGnssUpdate),
            ),
            0x17 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ExternalHeadingUpdate as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::ExternalHeadingUpdate),
            ),
            0x18 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <HeadingUpdateControl as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::HeadingUpdateControl),
            ),
            0x87 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <HeadingUpdateControlResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::HeadingUpdateControlResponse),
            ),
            0x19 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AutoInitControl as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::AutoInitControl),
            ),
            0x88 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AutoInitControlResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::AutoInitControlResponse),
            ),
            0x1A => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AccelNoise as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::AccelNoise),
            ),
            0x89 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AccelNoiseResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::AccelNoiseResponse),
            ),
            0x1B => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GyroNoise as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GyroNoise),
            ),
            0x8A => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GyroNoiseResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GyroNoiseResponse),
            ),
            0x1C => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AccelBiasModel as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::AccelBiasModel),
            ),
            0x8B => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AccelBiasModelResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::AccelBiasModelResponse),
            ),
            0x1D => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GyroBiasModel as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GyroBiasModel),
            ),
            0x8C => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GyroBiasModelResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GyroBiasModelResponse),
            ),
            0x1E => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ZuptControl as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::ZuptControl),
            ),
            0x8D => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ZuptControlResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::ZuptControlResponse),
            ),
            0x1F => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ExternalHeadingUpdateWithTime as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::ExternalHeadingUpdateWithTime),
            ),
            0x20 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ZeroAngularRateUpdateControl as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::ZeroAngularRateUpdateControl),
            ),
            0x8E => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ZeroAngularRateUpdateControlResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::ZeroAngularRateUpdateControlResponse),
            ),
            0x21 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <TareOrientation as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::TareOrientation),
            ),
            0x22 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <CommandedZupt as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::CommandedZupt),
            ),
            0x23 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <CommandedZeroAngularRateUpdate as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::CommandedZeroAngularRateUpdate),
            ),
            0x27 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <MagCaptureAutoCalibration as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::MagCaptureAutoCalibration),
            ),
            0x28 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GravityNoiseStdDev as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GravityNoiseStdDev),
            ),
            0x93 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GravityNoiseStdDevResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GravityNoiseStdDevResponse),
            ),
            0x29 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <PressureAltitudeNoiseStdDev as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::PressureAltitudeNoiseStdDev),
            ),
            0x94 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <PressureAltitudeNoiseStdDevResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::PressureAltitudeNoiseStdDevResponse),
            ),
            0x2B => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <HardIronOffsetNoise as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::HardIronOffsetNoise),
            ),
            0x96 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <HardIronOffsetNoiseResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::HardIronOffsetNoiseResponse),
            ),
            0x2C => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SoftIronMatrixNoise as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::SoftIronMatrixNoise),
            ),
            0x97 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SoftIronMatrixNoiseResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::SoftIronMatrixNoiseResponse),
            ),
            0x42 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <MagNoiseStdDev as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::MagNoiseStdDev),
            ),
            0xB1 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <MagNoiseStdDevResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::MagNoiseStdDevResponse),
            ),
            0x43 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <DeclinationSource as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::DeclinationSource),
            ),
            0xB2 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <DeclinationSourceResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::DeclinationSourceResponse),
            ),
            0x44 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GravityMagnitudeAdaptiveMeasurement as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GravityMagnitudeAdaptiveMeasurement),
            ),
            0xB3 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GravityMagnitudeAdaptiveMeasurementResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GravityMagnitudeAdaptiveMeasurementResponse),
            ),
            0x45 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <MagMagnitudeAdaptiveMeasurement as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::MagMagnitudeAdaptiveMeasurement),
            ),
            0xB4 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <MagMagnitudeAdaptiveMeasurementResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::MagMagnitudeAdaptiveMeasurementResponse),
            ),
            0x46 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <MagDipAngleAdaptiveMeasurement as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::MagDipAngleAdaptiveMeasurement),
            ),
            0xB5 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <MagDipAngleAdaptiveMeasurementResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::MagDipAngleAdaptiveMeasurementResponse),
            ),
            0x47 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AltitudeAidingControl as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::AltitudeAidingControl),
            ),
            0xB7 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AltitudeAidingControlResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::AltitudeAidingControlResponse),
            ),
            0x4B => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <PitchRollAidingControl as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::PitchRollAidingControl),
            ),
            0xBB => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <PitchRollAidingControlResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::PitchRollAidingControlResponse),
            ),
            0x4C => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <InclinationSource as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::InclinationSource),
            ),
            0xBC => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <InclinationSourceResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::InclinationSourceResponse),
            ),
            0x4D => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <MagneticFieldMagnitudeSource as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::MagneticFieldMagnitudeSource),
            ),
            0xBD => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <MagneticFieldMagnitudeSourceResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::MagneticFieldMagnitudeSourceResponse),
            ),
            0x50 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AidingMeasurementControl as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::AidingMeasurementControl),
            ),
            0xD0 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AidingMeasurementControlResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::AidingMeasurementControlResponse),
            ),
            0x52 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <InitializationConfiguration as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::InitializationConfiguration),
            ),
            0xD2 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <InitializationConfigurationResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::InitializationConfigurationResponse),
            ),
            0x53 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AdaptiveFilterControl as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::AdaptiveFilterControl),
            ),
            0xD3 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AdaptiveFilterControlResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::AdaptiveFilterControlResponse),
            ),
            0x54 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <MultiAntennaOffset as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::MultiAntennaOffset),
            ),
            0xD4 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <MultiAntennaOffsetResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::MultiAntennaOffsetResponse),
            ),
            0x55 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <RelativePositionConfiguration as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::RelativePositionConfiguration),
            ),
            0xD5 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <RelativePositionConfigurationResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::RelativePositionConfigurationResponse),
            ),
            0x56 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ReferencePointLeverArm as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::ReferencePointLeverArm),
            ),
            0xD6 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ReferencePointLeverArmResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::ReferencePointLeverArmResponse),
            ),
            0x61 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SpeedLeverArm as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::SpeedLeverArm),
            ),
            0xE1 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SpeedLeverArmResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::SpeedLeverArmResponse),
            ),
            0x63 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <WheeledVehicleConstraintControl as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::WheeledVehicleConstraintControl),
            ),
            0xE3 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <WheeledVehicleConstraintControlResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::WheeledVehicleConstraintControlResponse),
            ),
            0x64 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GnssAntennaCalibrationControl as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GnssAntennaCalibrationControl),
            ),
            0xE4 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GnssAntennaCalibrationControlResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GnssAntennaCalibrationControlResponse),
            ),
            _ => None,
        }
    }
}
