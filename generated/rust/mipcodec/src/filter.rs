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
    const NAME: &'static str = "external_heading_update_with_time";
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
                        <ResetFilter as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::ResetFilter),
            ),
            0x02 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SetInitialAttitude as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::SetInitialAttitude),
            ),
            0x03 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SetInitialHeading as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::SetInitialHeading),
            ),
            0x05 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <RunFilter as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::RunFilter),
            ),
            0x10 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <VehicleDynamicsMode as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::VehicleDynamicsMode),
            ),
            0x80 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <VehicleDynamicsModeResponse as crate::json_read::FromJson>::from_json(
                            values,
                        )
                        .map_err(|e| e.at("values"))
                    })
                    .map(Self::VehicleDynamicsModeResponse),
            ),
            0x11 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SensorToVehicleTransform as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::SensorToVehicleTransform),
            ),
            0x81 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SensorToVehicleTransformResponse as crate::json_read::FromJson>::from_json(
                            values,
                        )
                        .map_err(|e| e.at("values"))
                    })
                    .map(Self::SensorToVehicleTransformResponse),
            ),
            0x12 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SensorToVehicleOffset as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::SensorToVehicleOffset),
            ),
            0x82 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SensorToVehicleOffsetResponse as crate::json_read::FromJson>::from_json(
                            values,
                        )
                        .map_err(|e| e.at("values"))
                    })
                    .map(Self::SensorToVehicleOffsetResponse),
            ),
            0x13 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AntennaOffset as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::AntennaOffset),
            ),
            0x83 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AntennaOffsetResponse as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::AntennaOffsetResponse),
            ),
            0x14 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <EstimationControl as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::EstimationControl),
            ),
            0x84 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <EstimationControlResponse as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::EstimationControlResponse),
            ),
            0x15 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GnssSourceControl as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::GnssSourceControl),
            ),
            0x86 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GnssSourceControlResponse as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::GnssSourceControlResponse),
            ),
            0x16 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ExternalGnssUpdate as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::ExternalGnssUpdate),
            ),
            0x17 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ExternalHeadingUpdate as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::ExternalHeadingUpdate),
            ),
            0x18 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <HeadingUpdateControl as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::HeadingUpdateControl),
            ),
            0x87 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <HeadingUpdateControlResponse as crate::json_read::FromJson>::from_json(
                            values,
                        )
                        .map_err(|e| e.at("values"))
                    })
                    .map(Self::HeadingUpdateControlResponse),
            ),
            0x19 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AutoInitControl as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::AutoInitControl),
            ),
            0x88 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AutoInitControlResponse as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::AutoInitControlResponse),
            ),
            0x1A => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AccelNoise as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::AccelNoise),
            ),
            0x89 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AccelNoiseResponse as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::AccelNoiseResponse),
            ),
            0x1B => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GyroNoise as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::GyroNoise),
            ),
            0x8A => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GyroNoiseResponse as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::GyroNoiseResponse),
            ),
            0x1C => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AccelBiasModel as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::AccelBiasModel),
            ),
            0x8B => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AccelBiasModelResponse as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::AccelBiasModelResponse),
            ),
            0x1D => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GyroBiasModel as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::GyroBiasModel),
            ),
            0x8C => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GyroBiasModelResponse as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::GyroBiasModelResponse),
            ),
            0x1E => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ZuptControl as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::ZuptControl),
            ),
            0x8D => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ZuptControlResponse as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::ZuptControlResponse),
            ),
            0x1F => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ExternalHeadingUpdateWithTime as crate::json_read::FromJson>::from_json(
                            values,
                        )
                        .map_err(|e| e.at("values"))
                    })
                    .map(Self::ExternalHeadingUpdateWithTime),
            ),
            _ => None,
        }
    }
}
