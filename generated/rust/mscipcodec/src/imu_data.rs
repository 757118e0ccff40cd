//! IMU Data Message. Scaled inertial measurements, pressure, temperature and GPS-correlated time.
//!
//! Descriptor set 0xA2 (data set):
//! one struct per field layout, and `SetField`, the enum of all its fields.

/// Descriptor set of this module.
pub const SET: u8 = 0xA2;

/// Scaled acceleration vector. X, Y and Z acceleration in g.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScaledAccel {
    /// Acceleration \[x, y, z\]. Units: g.
    pub accel: [f32; 3],
}

impl Default for ScaledAccel {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ScaledAccel {
    const ZERO: Self = Self {
        accel: <[f32; 3] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(12);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_accel = <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("accel"))?;
        Ok(Self { accel: p_accel })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.accel;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("accel"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.accel;
        crate::json::key(w, &mut first, "accel")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ScaledAccel {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["accel"])?;
        let p_accel = o.req("accel", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        Ok(Self { accel: p_accel })
    }
}

impl ScaledAccel {
    /// Descriptor set of the field.
    pub const SET: u8 = 0xA2;
}

impl crate::wire::Layout for ScaledAccel {
    const DESCRIPTOR: u8 = 0x81;
    const DESCRIPTOR_SET: Option<u8> = Some(0xA2);
    const NAME: &'static str = "scaled_accel";
}

/// Scaled angular rate vector. X, Y and Z angular rate in degrees per second.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScaledGyro {
    /// Angular rate \[x, y, z\]. Units: deg/s.
    pub gyro: [f32; 3],
}

impl Default for ScaledGyro {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ScaledGyro {
    const ZERO: Self = Self {
        gyro: <[f32; 3] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(12);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_gyro = <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("gyro"))?;
        Ok(Self { gyro: p_gyro })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.gyro;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("gyro"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.gyro;
        crate::json::key(w, &mut first, "gyro")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ScaledGyro {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["gyro"])?;
        let p_gyro = o.req("gyro", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        Ok(Self { gyro: p_gyro })
    }
}

impl ScaledGyro {
    /// Descriptor set of the field.
    pub const SET: u8 = 0xA2;
}

impl crate::wire::Layout for ScaledGyro {
    const DESCRIPTOR: u8 = 0x82;
    const DESCRIPTOR_SET: Option<u8> = Some(0xA2);
    const NAME: &'static str = "scaled_gyro";
}

/// Scaled magnetic field vector. X, Y and Z magnetic field in gauss.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScaledMag {
    /// Magnetic field \[x, y, z\]. Units: gauss.
    pub mag: [f32; 3],
}

impl Default for ScaledMag {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ScaledMag {
    const ZERO: Self = Self {
        mag: <[f32; 3] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(12);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_mag = <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("mag"))?;
        Ok(Self { mag: p_mag })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.mag;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("mag"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.mag;
        crate::json::key(w, &mut first, "mag")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ScaledMag {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["mag"])?;
        let p_mag = o.req("mag", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        Ok(Self { mag: p_mag })
    }
}

impl ScaledMag {
    /// Descriptor set of the field.
    pub const SET: u8 = 0xA2;
}

impl crate::wire::Layout for ScaledMag {
    const DESCRIPTOR: u8 = 0x83;
    const DESCRIPTOR_SET: Option<u8> = Some(0xA2);
    const NAME: &'static str = "scaled_mag";
}

/// Scaled delta theta vector. X, Y and Z change in angle in radians.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DeltaTheta {
    /// Change in angle \[x, y, z\]. Units: rad.
    pub delta_theta: [f32; 3],
}

impl Default for DeltaTheta {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for DeltaTheta {
    const ZERO: Self = Self {
        delta_theta: <[f32; 3] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(12);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_delta_theta =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("delta_theta"))?;
        Ok(Self {
            delta_theta: p_delta_theta,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.delta_theta;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("delta_theta"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.delta_theta;
        crate::json::key(w, &mut first, "delta_theta")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for DeltaTheta {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["delta_theta"])?;
        let p_delta_theta = o.req(
            "delta_theta",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            delta_theta: p_delta_theta,
        })
    }
}

impl DeltaTheta {
    /// Descriptor set of the field.
    pub const SET: u8 = 0xA2;
}

impl crate::wire::Layout for DeltaTheta {
    const DESCRIPTOR: u8 = 0x84;
    const DESCRIPTOR_SET: Option<u8> = Some(0xA2);
    const NAME: &'static str = "delta_theta";
}

/// Scaled delta velocity vector. X, Y and Z change in velocity in metres per second.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DeltaVelocity {
    /// Change in velocity \[x, y, z\]. Units: m/s.
    pub delta_velocity: [f32; 3],
}

impl Default for DeltaVelocity {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for DeltaVelocity {
    const ZERO: Self = Self {
        delta_velocity: <[f32; 3] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(12);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_delta_velocity =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("delta_velocity"))?;
        Ok(Self {
            delta_velocity: p_delta_velocity,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.delta_velocity;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("delta_velocity"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.delta_velocity;
        crate::json::key(w, &mut first, "delta_velocity")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for DeltaVelocity {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["delta_velocity"])?;
        let p_delta_velocity = o.req(
            "delta_velocity",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            delta_velocity: p_delta_velocity,
        })
    }
}

impl DeltaVelocity {
    /// Descriptor set of the field.
    pub const SET: u8 = 0xA2;
}

impl crate::wire::Layout for DeltaVelocity {
    const DESCRIPTOR: u8 = 0x85;
    const DESCRIPTOR_SET: Option<u8> = Some(0xA2);
    const NAME: &'static str = "delta_velocity";
}

/// Scaled pressure. Atmospheric pressure in millibar.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScaledPressure {
    /// Pressure. Units: mbar.
    pub pressure: f32,
}

impl Default for ScaledPressure {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ScaledPressure {
    const ZERO: Self = Self {
        pressure: <f32 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(4);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_pressure = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("pressure"))?;
        Ok(Self {
            pressure: p_pressure,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.pressure;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("pressure"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.pressure;
        crate::json::key(w, &mut first, "pressure")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ScaledPressure {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["pressure"])?;
        let p_pressure = o.req("pressure", <f32 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            pressure: p_pressure,
        })
    }
}

impl ScaledPressure {
    /// Descriptor set of the field.
    pub const SET: u8 = 0xA2;
}

impl crate::wire::Layout for ScaledPressure {
    const DESCRIPTOR: u8 = 0x86;
    const DESCRIPTOR_SET: Option<u8> = Some(0xA2);
    const NAME: &'static str = "scaled_pressure";
}

/// Scaled temperature. IMU temperature in degrees Celsius.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScaledTemperature {
    /// Temperature. Units: degC.
    pub temperature: f32,
}

impl Default for ScaledTemperature {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ScaledTemperature {
    const ZERO: Self = Self {
        temperature: <f32 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(4);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_temperature =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("temperature"))?;
        Ok(Self {
            temperature: p_temperature,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.temperature;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("temperature"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.temperature;
        crate::json::key(w, &mut first, "temperature")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ScaledTemperature {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["temperature"])?;
        let p_temperature = o.req(
            "temperature",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            temperature: p_temperature,
        })
    }
}

impl ScaledTemperature {
    /// Descriptor set of the field.
    pub const SET: u8 = 0xA2;
}

impl crate::wire::Layout for ScaledTemperature {
    const DESCRIPTOR: u8 = 0x87;
    const DESCRIPTOR_SET: Option<u8> = Some(0xA2);
    const NAME: &'static str = "scaled_temperature";
}

/// GPS correlated time. GPS time of the sample: seconds of the week (precision follows the output rate, 5 ms at 200 Hz), week number, and the correlation flags.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GpsCorrelatedTime {
    /// GPS seconds of the week. Units: s.
    pub seconds: f64,
    /// GPS week number. Units: weeks.
    pub week: u16,
    /// GPS correlated time flags.
    pub flags: crate::types::GpsTimeFlags,
}

impl Default for GpsCorrelatedTime {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GpsCorrelatedTime {
    const ZERO: Self = Self {
        seconds: <f64 as crate::wire::Wire>::ZERO,
        week: <u16 as crate::wire::Wire>::ZERO,
        flags: <crate::types::GpsTimeFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(12);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_seconds = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("seconds"))?;
        let p_week = <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("week"))?;
        let p_flags = <crate::types::GpsTimeFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("flags"))?;
        Ok(Self {
            seconds: p_seconds,
            week: p_week,
            flags: p_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.seconds;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("seconds"))?;
        let v = &self.week;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("week"))?;
        let v = &self.flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.seconds;
        crate::json::key(w, &mut first, "seconds")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.week;
        crate::json::key(w, &mut first, "week")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.flags;
        crate::json::key(w, &mut first, "flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GpsCorrelatedTime {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["seconds", "week", "flags"])?;
        let p_seconds = o.req("seconds", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_week = o.req("week", <u16 as crate::json_read::FromJson>::from_json)?;
        let p_flags = o.req(
            "flags",
            <crate::types::GpsTimeFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            seconds: p_seconds,
            week: p_week,
            flags: p_flags,
        })
    }
}

impl GpsCorrelatedTime {
    /// Descriptor set of the field.
    pub const SET: u8 = 0xA2;
}

impl crate::wire::Layout for GpsCorrelatedTime {
    const DESCRIPTOR: u8 = 0x88;
    const DESCRIPTOR_SET: Option<u8> = Some(0xA2);
    const NAME: &'static str = "gps_correlated_time";
}

/// Scaled aux accel vector. X, Y and Z acceleration of the auxiliary accelerometer in g.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScaledAuxAccel {
    /// Auxiliary acceleration \[x, y, z\]. Units: g.
    pub accel: [f32; 3],
}

impl Default for ScaledAuxAccel {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ScaledAuxAccel {
    const ZERO: Self = Self {
        accel: <[f32; 3] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(12);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_accel = <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("accel"))?;
        Ok(Self { accel: p_accel })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.accel;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("accel"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.accel;
        crate::json::key(w, &mut first, "accel")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ScaledAuxAccel {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["accel"])?;
        let p_accel = o.req("accel", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        Ok(Self { accel: p_accel })
    }
}

impl ScaledAuxAccel {
    /// Descriptor set of the field.
    pub const SET: u8 = 0xA2;
}

impl crate::wire::Layout for ScaledAuxAccel {
    const DESCRIPTOR: u8 = 0x89;
    const DESCRIPTOR_SET: Option<u8> = Some(0xA2);
    const NAME: &'static str = "scaled_aux_accel";
}

/// A decoded field of set 0xA2 (`imu_data`).
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SetField {
    /// `scaled_accel` (0x81).
    ScaledAccel(ScaledAccel),
    /// `scaled_gyro` (0x82).
    ScaledGyro(ScaledGyro),
    /// `scaled_mag` (0x83).
    ScaledMag(ScaledMag),
    /// `delta_theta` (0x84).
    DeltaTheta(DeltaTheta),
    /// `delta_velocity` (0x85).
    DeltaVelocity(DeltaVelocity),
    /// `scaled_pressure` (0x86).
    ScaledPressure(ScaledPressure),
    /// `scaled_temperature` (0x87).
    ScaledTemperature(ScaledTemperature),
    /// `gps_correlated_time` (0x88).
    GpsCorrelatedTime(GpsCorrelatedTime),
    /// `scaled_aux_accel` (0x89).
    ScaledAuxAccel(ScaledAuxAccel),
}

impl SetField {
    /// Field descriptor.
    pub fn descriptor(&self) -> u8 {
        match self {
            Self::ScaledAccel(_) => 0x81,
            Self::ScaledGyro(_) => 0x82,
            Self::ScaledMag(_) => 0x83,
            Self::DeltaTheta(_) => 0x84,
            Self::DeltaVelocity(_) => 0x85,
            Self::ScaledPressure(_) => 0x86,
            Self::ScaledTemperature(_) => 0x87,
            Self::GpsCorrelatedTime(_) => 0x88,
            Self::ScaledAuxAccel(_) => 0x89,
        }
    }

    /// Field name as printed in JSON.
    pub fn name(&self) -> &'static str {
        match self {
            Self::ScaledAccel(_) => "scaled_accel",
            Self::ScaledGyro(_) => "scaled_gyro",
            Self::ScaledMag(_) => "scaled_mag",
            Self::DeltaTheta(_) => "delta_theta",
            Self::DeltaVelocity(_) => "delta_velocity",
            Self::ScaledPressure(_) => "scaled_pressure",
            Self::ScaledTemperature(_) => "scaled_temperature",
            Self::GpsCorrelatedTime(_) => "gps_correlated_time",
            Self::ScaledAuxAccel(_) => "scaled_aux_accel",
        }
    }

    /// Device of the layout used, for fields with per-device layouts.
    pub fn device(&self) -> Option<crate::Device> {
        match self {
            Self::ScaledAccel(_) => None,
            Self::ScaledGyro(_) => None,
            Self::ScaledMag(_) => None,
            Self::DeltaTheta(_) => None,
            Self::DeltaVelocity(_) => None,
            Self::ScaledPressure(_) => None,
            Self::ScaledTemperature(_) => None,
            Self::GpsCorrelatedTime(_) => None,
            Self::ScaledAuxAccel(_) => None,
        }
    }

    /// Encodes the field data.
    pub fn encode_data(
        &self,
        w: &mut crate::wire::Writer<'_>,
    ) -> Result<(), crate::error::EncodeError> {
        match self {
            Self::ScaledAccel(v) => crate::wire::Layout::encode_data(v, w),
            Self::ScaledGyro(v) => crate::wire::Layout::encode_data(v, w),
            Self::ScaledMag(v) => crate::wire::Layout::encode_data(v, w),
            Self::DeltaTheta(v) => crate::wire::Layout::encode_data(v, w),
            Self::DeltaVelocity(v) => crate::wire::Layout::encode_data(v, w),
            Self::ScaledPressure(v) => crate::wire::Layout::encode_data(v, w),
            Self::ScaledTemperature(v) => crate::wire::Layout::encode_data(v, w),
            Self::GpsCorrelatedTime(v) => crate::wire::Layout::encode_data(v, w),
            Self::ScaledAuxAccel(v) => crate::wire::Layout::encode_data(v, w),
        }
    }

    /// Writes the canonical JSON of the values (`{...}`).
    pub fn write_values_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::ScaledAccel(v) => crate::wire::Wire::write_json(v, w),
            Self::ScaledGyro(v) => crate::wire::Wire::write_json(v, w),
            Self::ScaledMag(v) => crate::wire::Wire::write_json(v, w),
            Self::DeltaTheta(v) => crate::wire::Wire::write_json(v, w),
            Self::DeltaVelocity(v) => crate::wire::Wire::write_json(v, w),
            Self::ScaledPressure(v) => crate::wire::Wire::write_json(v, w),
            Self::ScaledTemperature(v) => crate::wire::Wire::write_json(v, w),
            Self::GpsCorrelatedTime(v) => crate::wire::Wire::write_json(v, w),
            Self::ScaledAuxAccel(v) => crate::wire::Wire::write_json(v, w),
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
            0x81 => {
                Some(<ScaledAccel as crate::wire::Layout>::decode_data(data).map(Self::ScaledAccel))
            }
            0x82 => {
                Some(<ScaledGyro as crate::wire::Layout>::decode_data(data).map(Self::ScaledGyro))
            }
            0x83 => {
                Some(<ScaledMag as crate::wire::Layout>::decode_data(data).map(Self::ScaledMag))
            }
            0x84 => {
                Some(<DeltaTheta as crate::wire::Layout>::decode_data(data).map(Self::DeltaTheta))
            }
            0x85 => Some(
                <DeltaVelocity as crate::wire::Layout>::decode_data(data).map(Self::DeltaVelocity),
            ),
            0x86 => Some(
                <ScaledPressure as crate::wire::Layout>::decode_data(data)
                    .map(Self::ScaledPressure),
            ),
            0x87 => Some(
                <ScaledTemperature as crate::wire::Layout>::decode_data(data)
                    .map(Self::ScaledTemperature),
            ),
            0x88 => Some(
                <GpsCorrelatedTime as crate::wire::Layout>::decode_data(data)
                    .map(Self::GpsCorrelatedTime),
            ),
            0x89 => Some(
                <ScaledAuxAccel as crate::wire::Layout>::decode_data(data)
                    .map(Self::ScaledAuxAccel),
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
            0x81 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ScaledAccel as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::ScaledAccel),
            ),
            0x82 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ScaledGyro as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::ScaledGyro),
            ),
            0x83 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ScaledMag as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::ScaledMag),
            ),
            0x84 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <DeltaTheta as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::DeltaTheta),
            ),
            0x85 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <DeltaVelocity as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::DeltaVelocity),
            ),
            0x86 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ScaledPressure as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::ScaledPressure),
            ),
            0x87 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ScaledTemperature as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::ScaledTemperature),
            ),
            0x88 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GpsCorrelatedTime as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::GpsCorrelatedTime),
            ),
            0x89 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ScaledAuxAccel as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::ScaledAuxAccel),
            ),
            _ => None,
        }
    }
}

/// The fields of one packet of this set, decoded in place by [`decode_packet`]: one member per
/// field of the set with one layout (its own); `index` says which members hold a field of the last packet, in packet order
/// (the others hold whatever they held).
#[cfg(any(feature = "set-imu-data", not(feature = "select-sets")))]
#[derive(Clone, Debug)]
pub struct Packet {
    /// The fields decoded into their members, in packet order.
    pub index: crate::packets::PacketIndex,
    /// Field 0x81.
    pub scaled_accel: crate::imu_data::ScaledAccel,
    /// Field 0x82.
    pub scaled_gyro: crate::imu_data::ScaledGyro,
    /// Field 0x83.
    pub scaled_mag: crate::imu_data::ScaledMag,
    /// Field 0x84.
    pub delta_theta: crate::imu_data::DeltaTheta,
    /// Field 0x85.
    pub delta_velocity: crate::imu_data::DeltaVelocity,
    /// Field 0x86.
    pub scaled_pressure: crate::imu_data::ScaledPressure,
    /// Field 0x87.
    pub scaled_temperature: crate::imu_data::ScaledTemperature,
    /// Field 0x88.
    pub gps_correlated_time: crate::imu_data::GpsCorrelatedTime,
    /// Field 0x89.
    pub scaled_aux_accel: crate::imu_data::ScaledAuxAccel,
}

#[cfg(any(feature = "set-imu-data", not(feature = "select-sets")))]
impl Packet {
    /// Nothing decoded, every member zero.
    pub const ZERO: Self = Self {
        index: crate::packets::PacketIndex::EMPTY,
        scaled_accel: <crate::imu_data::ScaledAccel as crate::wire::Wire>::ZERO,
        scaled_gyro: <crate::imu_data::ScaledGyro as crate::wire::Wire>::ZERO,
        scaled_mag: <crate::imu_data::ScaledMag as crate::wire::Wire>::ZERO,
        delta_theta: <crate::imu_data::DeltaTheta as crate::wire::Wire>::ZERO,
        delta_velocity: <crate::imu_data::DeltaVelocity as crate::wire::Wire>::ZERO,
        scaled_pressure: <crate::imu_data::ScaledPressure as crate::wire::Wire>::ZERO,
        scaled_temperature: <crate::imu_data::ScaledTemperature as crate::wire::Wire>::ZERO,
        gps_correlated_time: <crate::imu_data::GpsCorrelatedTime as crate::wire::Wire>::ZERO,
        scaled_aux_accel: <crate::imu_data::ScaledAuxAccel as crate::wire::Wire>::ZERO,
    };
}

#[cfg(any(feature = "set-imu-data", not(feature = "select-sets")))]
impl Default for Packet {
    fn default() -> Self {
        Self::ZERO
    }
}

#[cfg(any(feature = "set-imu-data", not(feature = "select-sets")))]
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
        matches!(
            descriptor,
            0x81 | 0x82 | 0x83 | 0x84 | 0x85 | 0x86 | 0x87 | 0x88 | 0x89
        )
    }

    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode_member(&mut self, descriptor: u8, data: &[u8]) -> bool {
        match descriptor {
            0x81 => match <&[u8; 12]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.scaled_accel;
                    s.accel[0] = crate::packets::ld(d, 0);
                    s.accel[1] = crate::packets::ld(d, 4);
                    s.accel[2] = crate::packets::ld(d, 8);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.scaled_accel),
            },
            0x82 => match <&[u8; 12]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.scaled_gyro;
                    s.gyro[0] = crate::packets::ld(d, 0);
                    s.gyro[1] = crate::packets::ld(d, 4);
                    s.gyro[2] = crate::packets::ld(d, 8);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.scaled_gyro),
            },
            0x83 => match <&[u8; 12]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.scaled_mag;
                    s.mag[0] = crate::packets::ld(d, 0);
                    s.mag[1] = crate::packets::ld(d, 4);
                    s.mag[2] = crate::packets::ld(d, 8);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.scaled_mag),
            },
            0x84 => match <&[u8; 12]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.delta_theta;
                    s.delta_theta[0] = crate::packets::ld(d, 0);
                    s.delta_theta[1] = crate::packets::ld(d, 4);
                    s.delta_theta[2] = crate::packets::ld(d, 8);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.delta_theta),
            },
            0x85 => match <&[u8; 12]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.delta_velocity;
                    s.delta_velocity[0] = crate::packets::ld(d, 0);
                    s.delta_velocity[1] = crate::packets::ld(d, 4);
                    s.delta_velocity[2] = crate::packets::ld(d, 8);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.delta_velocity),
            },
            0x86 => match <&[u8; 4]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.scaled_pressure;
                    s.pressure = crate::packets::ld(d, 0);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.scaled_pressure),
            },
            0x87 => match <&[u8; 4]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.scaled_temperature;
                    s.temperature = crate::packets::ld(d, 0);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.scaled_temperature),
            },
            0x88 => match <&[u8; 12]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.gps_correlated_time;
                    s.seconds = crate::packets::ld(d, 0);
                    s.week = crate::packets::ld(d, 8);
                    s.flags = crate::packets::ld(d, 10);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.gps_correlated_time),
            },
            0x89 => match <&[u8; 12]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.scaled_aux_accel;
                    s.accel[0] = crate::packets::ld(d, 0);
                    s.accel[1] = crate::packets::ld(d, 4);
                    s.accel[2] = crate::packets::ld(d, 8);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.scaled_aux_accel),
            },
            _ => false,
        }
    }

    fn field(&self, descriptor: u8) -> Option<crate::FieldValue> {
        if !self.index.contains(descriptor) {
            return None;
        }
        match descriptor {
            0x81 => Some(crate::FieldValue::ImuData(
                crate::imu_data::SetField::ScaledAccel(self.scaled_accel),
            )),
            0x82 => Some(crate::FieldValue::ImuData(
                crate::imu_data::SetField::ScaledGyro(self.scaled_gyro),
            )),
            0x83 => Some(crate::FieldValue::ImuData(
                crate::imu_data::SetField::ScaledMag(self.scaled_mag),
            )),
            0x84 => Some(crate::FieldValue::ImuData(
                crate::imu_data::SetField::DeltaTheta(self.delta_theta),
            )),
            0x85 => Some(crate::FieldValue::ImuData(
                crate::imu_data::SetField::DeltaVelocity(self.delta_velocity),
            )),
            0x86 => Some(crate::FieldValue::ImuData(
                crate::imu_data::SetField::ScaledPressure(self.scaled_pressure),
            )),
            0x87 => Some(crate::FieldValue::ImuData(
                crate::imu_data::SetField::ScaledTemperature(self.scaled_temperature),
            )),
            0x88 => Some(crate::FieldValue::ImuData(
                crate::imu_data::SetField::GpsCorrelatedTime(self.gps_correlated_time),
            )),
            0x89 => Some(crate::FieldValue::ImuData(
                crate::imu_data::SetField::ScaledAuxAccel(self.scaled_aux_accel),
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
#[cfg(any(feature = "set-imu-data", not(feature = "select-sets")))]
pub fn decode_packet(
    payload: &[u8],
    out: &mut Packet,
    other: impl FnMut(crate::fields::FieldItem<'_>),
) -> usize {
    crate::packets::decode_set_packet(payload, out, other)
}
