//! Sensor (IMU) Data Set. Calibrated inertial sensor measurements.
//!
//! Descriptor set 0x80 (data set):
//! one struct per field layout, and `SetField`, the enum of all its fields.

/// Descriptor set of this module.
pub const SET: u8 = 0x80;

/// Scaled accelerometer vector. Sensed acceleration, temperature compensated, in g (1 g = 9.80665 m/s^2), X, Y, Z in the sensor (GX5-45) or vehicle (CV7) frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScaledAccel {
    /// (x, y, z) acceleration. Units: g.
    pub scaled_accel: [f32; 3],
}

impl Default for ScaledAccel {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ScaledAccel {
    const ZERO: Self = Self {
        scaled_accel: <[f32; 3] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(12);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_scaled_accel =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("scaled_accel"))?;
        Ok(Self {
            scaled_accel: p_scaled_accel,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.scaled_accel;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("scaled_accel"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.scaled_accel;
        crate::json::key(w, &mut first, "scaled_accel")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ScaledAccel {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["scaled_accel"])?;
        let p_scaled_accel = o.req(
            "scaled_accel",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            scaled_accel: p_scaled_accel,
        })
    }
}

impl ScaledAccel {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x80;
}

impl crate::wire::Layout for ScaledAccel {
    const DESCRIPTOR: u8 = 0x04;
    const DESCRIPTOR_SET: Option<u8> = Some(0x80);
    const NAME: &'static str = "scaled_accel";
}

/// Scaled gyro vector. Sensed angular rate, temperature compensated, in radians/second, X, Y, Z.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScaledGyro {
    /// (x, y, z) angular rate. Units: rad/s.
    pub scaled_gyro: [f32; 3],
}

impl Default for ScaledGyro {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ScaledGyro {
    const ZERO: Self = Self {
        scaled_gyro: <[f32; 3] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(12);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_scaled_gyro =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("scaled_gyro"))?;
        Ok(Self {
            scaled_gyro: p_scaled_gyro,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.scaled_gyro;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("scaled_gyro"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.scaled_gyro;
        crate::json::key(w, &mut first, "scaled_gyro")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ScaledGyro {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["scaled_gyro"])?;
        let p_scaled_gyro = o.req(
            "scaled_gyro",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            scaled_gyro: p_scaled_gyro,
        })
    }
}

impl ScaledGyro {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x80;
}

impl crate::wire::Layout for ScaledGyro {
    const DESCRIPTOR: u8 = 0x05;
    const DESCRIPTOR_SET: Option<u8> = Some(0x80);
    const NAME: &'static str = "scaled_gyro";
}

/// Scaled magnetometer vector. Sensed magnetic field, temperature compensated, in Gauss, X, Y, Z.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScaledMag {
    /// (x, y, z) magnetic field. Units: gauss.
    pub scaled_mag: [f32; 3],
}

impl Default for ScaledMag {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ScaledMag {
    const ZERO: Self = Self {
        scaled_mag: <[f32; 3] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(12);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_scaled_mag =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("scaled_mag"))?;
        Ok(Self {
            scaled_mag: p_scaled_mag,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.scaled_mag;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("scaled_mag"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.scaled_mag;
        crate::json::key(w, &mut first, "scaled_mag")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ScaledMag {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["scaled_mag"])?;
        let p_scaled_mag = o.req(
            "scaled_mag",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            scaled_mag: p_scaled_mag,
        })
    }
}

impl ScaledMag {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x80;
}

impl crate::wire::Layout for ScaledMag {
    const DESCRIPTOR: u8 = 0x06;
    const DESCRIPTOR_SET: Option<u8> = Some(0x80);
    const NAME: &'static str = "scaled_mag";
}

/// Delta theta vector. Time integral of the angular rate over the interval set by the IMU message format (the output period), in radians, X, Y, Z in the sensor (GX5-45) or vehicle (CV7) frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DeltaTheta {
    /// (x, y, z) integrated angular rate. Units: rad.
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
    pub const SET: u8 = 0x80;
}

impl crate::wire::Layout for DeltaTheta {
    const DESCRIPTOR: u8 = 0x07;
    const DESCRIPTOR_SET: Option<u8> = Some(0x80);
    const NAME: &'static str = "delta_theta";
}

/// Delta velocity vector. Time integral of the sensed (specific) acceleration over the interval set by the IMU message format, in g*seconds (multiply by 9.80665 for m/s), X, Y, Z in the sensor (GX5-45) or vehicle (CV7) frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DeltaVelocity {
    /// (x, y, z) integrated acceleration. Units: g*s.
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
    pub const SET: u8 = 0x80;
}

impl crate::wire::Layout for DeltaVelocity {
    const DESCRIPTOR: u8 = 0x08;
    const DESCRIPTOR_SET: Option<u8> = Some(0x80);
    const NAME: &'static str = "delta_velocity";
}

/// Complementary filter orientation matrix. 3x3 orientation (direction cosine) matrix from the complementary filter, rotating a vector from the earth-fixed (NED local-level) frame into the sensor (GX5-45) or vehicle (CV7) frame: v_local = M * v_earth. Elements sent row-major, M11 M12 M13 M21 ... M33.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CfOrientationMatrix {
    /// Orientation matrix, row-major (dimensionless).
    pub m: [f32; 9],
}

impl Default for CfOrientationMatrix {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for CfOrientationMatrix {
    const ZERO: Self = Self {
        m: <[f32; 9] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(36);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_m = <[f32; 9] as crate::wire::Wire>::decode(r).map_err(|e| e.at("m"))?;
        Ok(Self { m: p_m })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.m;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("m"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.m;
        crate::json::key(w, &mut first, "m")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for CfOrientationMatrix {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["m"])?;
        let p_m = o.req("m", <[f32; 9] as crate::json_read::FromJson>::from_json)?;
        Ok(Self { m: p_m })
    }
}

impl CfOrientationMatrix {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x80;
}

impl crate::wire::Layout for CfOrientationMatrix {
    const DESCRIPTOR: u8 = 0x09;
    const DESCRIPTOR_SET: Option<u8> = Some(0x80);
    const NAME: &'static str = "cf_orientation_matrix";
}

/// Complementary filter quaternion. Orientation quaternion (q0, q1, q2, q3) from the complementary filter, of the sensor (GX5-45) or vehicle (CV7) frame relative to the earth-fixed (NED) frame: v_local = Q^-1 * v_earth * Q.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CfQuaternion {
    /// Quaternion elements q0 (scalar), q1, q2, q3 (dimensionless).
    pub q: [f32; 4],
}

impl Default for CfQuaternion {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for CfQuaternion {
    const ZERO: Self = Self {
        q: <[f32; 4] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(16);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_q = <[f32; 4] as crate::wire::Wire>::decode(r).map_err(|e| e.at("q"))?;
        Ok(Self { q: p_q })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.q;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("q"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.q;
        crate::json::key(w, &mut first, "q")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for CfQuaternion {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["q"])?;
        let p_q = o.req("q", <[f32; 4] as crate::json_read::FromJson>::from_json)?;
        Ok(Self { q: p_q })
    }
}

impl CfQuaternion {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x80;
}

impl crate::wire::Layout for CfQuaternion {
    const DESCRIPTOR: u8 = 0x0A;
    const DESCRIPTOR_SET: Option<u8> = Some(0x80);
    const NAME: &'static str = "cf_quaternion";
}

/// Complementary filter Euler angles. Roll, pitch and yaw (aircraft 3-2-1 order) from the complementary filter, in radians, relative to the earth-fixed (NED local-level) frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CfEulerAngles {
    /// Roll angle. Units: rad.
    pub roll: f32,
    /// Pitch angle. Units: rad.
    pub pitch: f32,
    /// Yaw angle. Units: rad.
    pub yaw: f32,
}

impl Default for CfEulerAngles {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for CfEulerAngles {
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
impl crate::json_read::FromJson for CfEulerAngles {
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

impl CfEulerAngles {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x80;
}

impl crate::wire::Layout for CfEulerAngles {
    const DESCRIPTOR: u8 = 0x0C;
    const DESCRIPTOR_SET: Option<u8> = Some(0x80);
    const NAME: &'static str = "cf_euler_angles";
}

/// Complementary filter stabilized north vector. The complementary filter's gyro-stabilized estimate of the geomagnetic field vector (magnetic north), in Gauss, in the sensor frame. Equal to the magnetometer reading without magnetic interference, but free of transient interference.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CfStabilizedNorth {
    /// (x, y, z) stabilized magnetic field estimate. Units: gauss.
    pub stabilized_north: [f32; 3],
}

impl Default for CfStabilizedNorth {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for CfStabilizedNorth {
    const ZERO: Self = Self {
        stabilized_north: <[f32; 3] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(12);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_stabilized_north =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("stabilized_north"))?;
        Ok(Self {
            stabilized_north: p_stabilized_north,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.stabilized_north;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("stabilized_north"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.stabilized_north;
        crate::json::key(w, &mut first, "stabilized_north")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for CfStabilizedNorth {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["stabilized_north"])?;
        let p_stabilized_north = o.req(
            "stabilized_north",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            stabilized_north: p_stabilized_north,
        })
    }
}

impl CfStabilizedNorth {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x80;
}

impl crate::wire::Layout for CfStabilizedNorth {
    const DESCRIPTOR: u8 = 0x10;
    const DESCRIPTOR_SET: Option<u8> = Some(0x80);
    const NAME: &'static str = "cf_stabilized_north";
}

/// Complementary filter stabilized up vector. The complementary filter's gyro-stabilized estimate of the gravity vector (vertical), in g, in the sensor frame. Equal to the accelerometer reading when stationary, but free of linear acceleration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CfStabilizedUp {
    /// (x, y, z) stabilized gravity estimate. Units: g.
    pub stabilized_up: [f32; 3],
}

impl Default for CfStabilizedUp {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for CfStabilizedUp {
    const ZERO: Self = Self {
        stabilized_up: <[f32; 3] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(12);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_stabilized_up =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("stabilized_up"))?;
        Ok(Self {
            stabilized_up: p_stabilized_up,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.stabilized_up;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("stabilized_up"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.stabilized_up;
        crate::json::key(w, &mut first, "stabilized_up")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for CfStabilizedUp {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["stabilized_up"])?;
        let p_stabilized_up = o.req(
            "stabilized_up",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            stabilized_up: p_stabilized_up,
        })
    }
}

impl CfStabilizedUp {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x80;
}

impl crate::wire::Layout for CfStabilizedUp {
    const DESCRIPTOR: u8 = 0x11;
    const DESCRIPTOR_SET: Option<u8> = Some(0x80);
    const NAME: &'static str = "cf_stabilized_up";
}

/// GPS timestamp of sensor data (GX5-45 GPS correlation timestamp). GPS time of the sensor sample as time of week and week number, with status flags. Without a PPS the device runs on its internal clock and the time drifts; expect a jump when the PPS returns. The fractional part of the time of week is the time since the last PPS. The CV7 recommends the shared GPS timestamp (0xD3) instead.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GpsTimestamp {
    /// GPS time of week. Units: s.
    pub tow: f64,
    /// GPS week number since 1980. Units: weeks.
    pub week_number: u16,
    /// Timestamp status flags (GX5-45: Timestamp Flags).
    pub valid_flags: crate::types::SensorGpsTimestampFlags,
}

impl Default for GpsTimestamp {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GpsTimestamp {
    const ZERO: Self = Self {
        tow: <f64 as crate::wire::Wire>::ZERO,
        week_number: <u16 as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::SensorGpsTimestampFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(12);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_tow = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("tow"))?;
        let p_week_number =
            <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("week_number"))?;
        let p_valid_flags = <crate::types::SensorGpsTimestampFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            tow: p_tow,
            week_number: p_week_number,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.tow;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("tow"))?;
        let v = &self.week_number;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("week_number"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.tow;
        crate::json::key(w, &mut first, "tow")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.week_number;
        crate::json::key(w, &mut first, "week_number")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GpsTimestamp {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["tow", "week_number", "valid_flags"])?;
        let p_tow = o.req("tow", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_week_number = o.req(
            "week_number",
            <u16 as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::SensorGpsTimestampFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            tow: p_tow,
            week_number: p_week_number,
            valid_flags: p_valid_flags,
        })
    }
}

impl GpsTimestamp {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x80;
}

impl crate::wire::Layout for GpsTimestamp {
    const DESCRIPTOR: u8 = 0x12;
    const DESCRIPTOR_SET: Option<u8> = Some(0x80);
    const NAME: &'static str = "gps_timestamp";
}

/// Temperature statistics. Minimum, maximum and mean sensor temperature since the last power-on or reset, from the MEMS sensors or combined with board temperature sensors.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TemperatureStatistics {
    /// Minimum temperature. Units: degC.
    pub min_temp: f32,
    /// Maximum temperature. Units: degC.
    pub max_temp: f32,
    /// Mean temperature. Units: degC.
    pub mean_temp: f32,
}

impl Default for TemperatureStatistics {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for TemperatureStatistics {
    const ZERO: Self = Self {
        min_temp: <f32 as crate::wire::Wire>::ZERO,
        max_temp: <f32 as crate::wire::Wire>::ZERO,
        mean_temp: <f32 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(12);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_min_temp = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("min_temp"))?;
        let p_max_temp = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("max_temp"))?;
        let p_mean_temp = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("mean_temp"))?;
        Ok(Self {
            min_temp: p_min_temp,
            max_temp: p_max_temp,
            mean_temp: p_mean_temp,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.min_temp;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("min_temp"))?;
        let v = &self.max_temp;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("max_temp"))?;
        let v = &self.mean_temp;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("mean_temp"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.min_temp;
        crate::json::key(w, &mut first, "min_temp")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.max_temp;
        crate::json::key(w, &mut first, "max_temp")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.mean_temp;
        crate::json::key(w, &mut first, "mean_temp")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for TemperatureStatistics {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["min_temp", "max_temp", "mean_temp"])?;
        let p_min_temp = o.req("min_temp", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_max_temp = o.req("max_temp", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_mean_temp = o.req("mean_temp", <f32 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            min_temp: p_min_temp,
            max_temp: p_max_temp,
            mean_temp: p_mean_temp,
        })
    }
}

impl TemperatureStatistics {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x80;
}

impl crate::wire::Layout for TemperatureStatistics {
    const DESCRIPTOR: u8 = 0x14;
    const DESCRIPTOR_SET: Option<u8> = Some(0x80);
    const NAME: &'static str = "temperature_statistics";
}

/// Scaled ambient pressure. Sensed ambient pressure, temperature compensated, in millibar.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScaledPressure {
    /// Ambient pressure. Units: mbar.
    pub scaled_pressure: f32,
}

impl Default for ScaledPressure {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ScaledPressure {
    const ZERO: Self = Self {
        scaled_pressure: <f32 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(4);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_scaled_pressure =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("scaled_pressure"))?;
        Ok(Self {
            scaled_pressure: p_scaled_pressure,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.scaled_pressure;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("scaled_pressure"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.scaled_pressure;
        crate::json::key(w, &mut first, "scaled_pressure")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ScaledPressure {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["scaled_pressure"])?;
        let p_scaled_pressure = o.req(
            "scaled_pressure",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            scaled_pressure: p_scaled_pressure,
        })
    }
}

impl ScaledPressure {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x80;
}

impl crate::wire::Layout for ScaledPressure {
    const DESCRIPTOR: u8 = 0x17;
    const DESCRIPTOR_SET: Option<u8> = Some(0x80);
    const NAME: &'static str = "scaled_pressure";
}

/// Over-range status. Which sensor axes are near or beyond their range, per axis (a smaller, faster form of the over-range bits of the continuous BIT).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OverrangeStatus {
    /// Over-range flags, one per axis.
    pub status: crate::types::OverrangeStatusFlags,
}

impl Default for OverrangeStatus {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for OverrangeStatus {
    const ZERO: Self = Self {
        status: <crate::types::OverrangeStatusFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(2);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_status = <crate::types::OverrangeStatusFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("status"))?;
        Ok(Self { status: p_status })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.status;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("status"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.status;
        crate::json::key(w, &mut first, "status")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for OverrangeStatus {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["status"])?;
        let p_status = o.req(
            "status",
            <crate::types::OverrangeStatusFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self { status: p_status })
    }
}

impl OverrangeStatus {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x80;
}

impl crate::wire::Layout for OverrangeStatus {
    const DESCRIPTOR: u8 = 0x18;
    const DESCRIPTOR_SET: Option<u8> = Some(0x80);
    const NAME: &'static str = "overrange_status";
}

/// Odometer data. Speed measured by the odometer (wheel encoder) input and its uncertainty.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OdometerData {
    /// Average speed over the interval; can be negative with quadrature encoders. Units: m/s.
    pub speed: f32,
    /// Uncertainty of the speed. Units: m/s.
    pub uncertainty: f32,
    /// Bit 0 set when the odometer is configured.
    pub valid_flags: crate::types::OdometerDataValidFlags,
}

impl Default for OdometerData {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for OdometerData {
    const ZERO: Self = Self {
        speed: <f32 as crate::wire::Wire>::ZERO,
        uncertainty: <f32 as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::OdometerDataValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(10);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_speed = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("speed"))?;
        let p_uncertainty =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("uncertainty"))?;
        let p_valid_flags = <crate::types::OdometerDataValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            speed: p_speed,
            uncertainty: p_uncertainty,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.speed;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("speed"))?;
        let v = &self.uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("uncertainty"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.speed;
        crate::json::key(w, &mut first, "speed")?;
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
impl crate::json_read::FromJson for OdometerData {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["speed", "uncertainty", "valid_flags"])?;
        let p_speed = o.req("speed", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_uncertainty = o.req(
            "uncertainty",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::OdometerDataValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            speed: p_speed,
            uncertainty: p_uncertainty,
            valid_flags: p_valid_flags,
        })
    }
}

impl OdometerData {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x80;
}

impl crate::wire::Layout for OdometerData {
    const DESCRIPTOR: u8 = 0x40;
    const DESCRIPTOR_SET: Option<u8> = Some(0x80);
    const NAME: &'static str = "odometer_data";
}

/// A decoded field of set 0x80 (`sensor`).
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SetField {
    /// `scaled_accel` (0x04).
    ScaledAccel(ScaledAccel),
    /// `scaled_gyro` (0x05).
    ScaledGyro(ScaledGyro),
    /// `scaled_mag` (0x06).
    ScaledMag(ScaledMag),
    /// `delta_theta` (0x07).
    DeltaTheta(DeltaTheta),
    /// `delta_velocity` (0x08).
    DeltaVelocity(DeltaVelocity),
    /// `cf_orientation_matrix` (0x09).
    CfOrientationMatrix(CfOrientationMatrix),
    /// `cf_quaternion` (0x0A).
    CfQuaternion(CfQuaternion),
    /// `cf_euler_angles` (0x0C).
    CfEulerAngles(CfEulerAngles),
    /// `cf_stabilized_north` (0x10).
    CfStabilizedNorth(CfStabilizedNorth),
    /// `cf_stabilized_up` (0x11).
    CfStabilizedUp(CfStabilizedUp),
    /// `gps_timestamp` (0x12).
    GpsTimestamp(GpsTimestamp),
    /// `temperature_statistics` (0x14).
    TemperatureStatistics(TemperatureStatistics),
    /// `scaled_pressure` (0x17).
    ScaledPressure(ScaledPressure),
    /// `overrange_status` (0x18).
    OverrangeStatus(OverrangeStatus),
    /// `odometer_data` (0x40).
    OdometerData(OdometerData),
}

impl SetField {
    /// Field descriptor.
    pub fn descriptor(&self) -> u8 {
        match self {
            Self::ScaledAccel(_) => 0x04,
            Self::ScaledGyro(_) => 0x05,
            Self::ScaledMag(_) => 0x06,
            Self::DeltaTheta(_) => 0x07,
            Self::DeltaVelocity(_) => 0x08,
            Self::CfOrientationMatrix(_) => 0x09,
            Self::CfQuaternion(_) => 0x0A,
            Self::CfEulerAngles(_) => 0x0C,
            Self::CfStabilizedNorth(_) => 0x10,
            Self::CfStabilizedUp(_) => 0x11,
            Self::GpsTimestamp(_) => 0x12,
            Self::TemperatureStatistics(_) => 0x14,
            Self::ScaledPressure(_) => 0x17,
            Self::OverrangeStatus(_) => 0x18,
            Self::OdometerData(_) => 0x40,
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
            Self::CfOrientationMatrix(_) => "cf_orientation_matrix",
            Self::CfQuaternion(_) => "cf_quaternion",
            Self::CfEulerAngles(_) => "cf_euler_angles",
            Self::CfStabilizedNorth(_) => "cf_stabilized_north",
            Self::CfStabilizedUp(_) => "cf_stabilized_up",
            Self::GpsTimestamp(_) => "gps_timestamp",
            Self::TemperatureStatistics(_) => "temperature_statistics",
            Self::ScaledPressure(_) => "scaled_pressure",
            Self::OverrangeStatus(_) => "overrange_status",
            Self::OdometerData(_) => "odometer_data",
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
            Self::CfOrientationMatrix(_) => None,
            Self::CfQuaternion(_) => None,
            Self::CfEulerAngles(_) => None,
            Self::CfStabilizedNorth(_) => None,
            Self::CfStabilizedUp(_) => None,
            Self::GpsTimestamp(_) => None,
            Self::TemperatureStatistics(_) => None,
            Self::ScaledPressure(_) => None,
            Self::OverrangeStatus(_) => None,
            Self::OdometerData(_) => None,
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
            Self::CfOrientationMatrix(v) => crate::wire::Layout::encode_data(v, w),
            Self::CfQuaternion(v) => crate::wire::Layout::encode_data(v, w),
            Self::CfEulerAngles(v) => crate::wire::Layout::encode_data(v, w),
            Self::CfStabilizedNorth(v) => crate::wire::Layout::encode_data(v, w),
            Self::CfStabilizedUp(v) => crate::wire::Layout::encode_data(v, w),
            Self::GpsTimestamp(v) => crate::wire::Layout::encode_data(v, w),
            Self::TemperatureStatistics(v) => crate::wire::Layout::encode_data(v, w),
            Self::ScaledPressure(v) => crate::wire::Layout::encode_data(v, w),
            Self::OverrangeStatus(v) => crate::wire::Layout::encode_data(v, w),
            Self::OdometerData(v) => crate::wire::Layout::encode_data(v, w),
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
            Self::CfOrientationMatrix(v) => crate::wire::Wire::write_json(v, w),
            Self::CfQuaternion(v) => crate::wire::Wire::write_json(v, w),
            Self::CfEulerAngles(v) => crate::wire::Wire::write_json(v, w),
            Self::CfStabilizedNorth(v) => crate::wire::Wire::write_json(v, w),
            Self::CfStabilizedUp(v) => crate::wire::Wire::write_json(v, w),
            Self::GpsTimestamp(v) => crate::wire::Wire::write_json(v, w),
            Self::TemperatureStatistics(v) => crate::wire::Wire::write_json(v, w),
            Self::ScaledPressure(v) => crate::wire::Wire::write_json(v, w),
            Self::OverrangeStatus(v) => crate::wire::Wire::write_json(v, w),
            Self::OdometerData(v) => crate::wire::Wire::write_json(v, w),
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
            0x04 => {
                Some(<ScaledAccel as crate::wire::Layout>::decode_data(data).map(Self::ScaledAccel))
            }
            0x05 => {
                Some(<ScaledGyro as crate::wire::Layout>::decode_data(data).map(Self::ScaledGyro))
            }
            0x06 => {
                Some(<ScaledMag as crate::wire::Layout>::decode_data(data).map(Self::ScaledMag))
            }
            0x07 => {
                Some(<DeltaTheta as crate::wire::Layout>::decode_data(data).map(Self::DeltaTheta))
            }
            0x08 => Some(
                <DeltaVelocity as crate::wire::Layout>::decode_data(data).map(Self::DeltaVelocity),
            ),
            0x09 => Some(
                <CfOrientationMatrix as crate::wire::Layout>::decode_data(data)
                    .map(Self::CfOrientationMatrix),
            ),
            0x0A => Some(
                <CfQuaternion as crate::wire::Layout>::decode_data(data).map(Self::CfQuaternion),
            ),
            0x0C => Some(
                <CfEulerAngles as crate::wire::Layout>::decode_data(data).map(Self::CfEulerAngles),
            ),
            0x10 => Some(
                <CfStabilizedNorth as crate::wire::Layout>::decode_data(data)
                    .map(Self::CfStabilizedNorth),
            ),
            0x11 => Some(
                <CfStabilizedUp as crate::wire::Layout>::decode_data(data)
                    .map(Self::CfStabilizedUp),
            ),
            0x12 => Some(
                <GpsTimestamp as crate::wire::Layout>::decode_data(data).map(Self::GpsTimestamp),
            ),
            0x14 => Some(
                <TemperatureStatistics as crate::wire::Layout>::decode_data(data)
                    .map(Self::TemperatureStatistics),
            ),
            0x17 => Some(
                <ScaledPressure as crate::wire::Layout>::decode_data(data)
                    .map(Self::ScaledPressure),
            ),
            0x18 => Some(
                <OverrangeStatus as crate::wire::Layout>::decode_data(data)
                    .map(Self::OverrangeStatus),
            ),
            0x40 => Some(
                <OdometerData as crate::wire::Layout>::decode_data(data).map(Self::OdometerData),
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
            0x04 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ScaledAccel as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::ScaledAccel),
            ),
            0x05 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ScaledGyro as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::ScaledGyro),
            ),
            0x06 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ScaledMag as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::ScaledMag),
            ),
            0x07 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <DeltaTheta as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::DeltaTheta),
            ),
            0x08 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <DeltaVelocity as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::DeltaVelocity),
            ),
            0x09 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <CfOrientationMatrix as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::CfOrientationMatrix),
            ),
            0x0A => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <CfQuaternion as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::CfQuaternion),
            ),
            0x0C => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <CfEulerAngles as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::CfEulerAngles),
            ),
            0x10 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <CfStabilizedNorth as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::CfStabilizedNorth),
            ),
            0x11 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <CfStabilizedUp as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::CfStabilizedUp),
            ),
            0x12 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GpsTimestamp as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::GpsTimestamp),
            ),
            0x14 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <TemperatureStatistics as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::TemperatureStatistics),
            ),
            0x17 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ScaledPressure as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::ScaledPressure),
            ),
            0x18 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <OverrangeStatus as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::OverrangeStatus),
            ),
            0x40 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <OdometerData as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::OdometerData),
            ),
            _ => None,
        }
    }
}

/// The fields of one packet of this set, decoded in place by [`decode_packet`]: one member per
/// field of the set with one layout (its own and the shared data fields); `index` says which members hold a field of the last packet, in packet order
/// (the others hold whatever they held).
#[cfg(any(feature = "set-sensor", not(feature = "select-sets")))]
#[derive(Clone, Debug)]
pub struct Packet {
    /// The fields decoded into their members, in packet order.
    pub index: crate::packets::PacketIndex,
    /// Field 0x04.
    pub scaled_accel: crate::sensor::ScaledAccel,
    /// Field 0x05.
    pub scaled_gyro: crate::sensor::ScaledGyro,
    /// Field 0x06.
    pub scaled_mag: crate::sensor::ScaledMag,
    /// Field 0x07.
    pub delta_theta: crate::sensor::DeltaTheta,
    /// Field 0x08.
    pub delta_velocity: crate::sensor::DeltaVelocity,
    /// Field 0x09.
    pub cf_orientation_matrix: crate::sensor::CfOrientationMatrix,
    /// Field 0x0A.
    pub cf_quaternion: crate::sensor::CfQuaternion,
    /// Field 0x0C.
    pub cf_euler_angles: crate::sensor::CfEulerAngles,
    /// Field 0x10.
    pub cf_stabilized_north: crate::sensor::CfStabilizedNorth,
    /// Field 0x11.
    pub cf_stabilized_up: crate::sensor::CfStabilizedUp,
    /// Field 0x12.
    pub sensor_gps_timestamp: crate::sensor::GpsTimestamp,
    /// Field 0x14.
    pub temperature_statistics: crate::sensor::TemperatureStatistics,
    /// Field 0x17.
    pub scaled_pressure: crate::sensor::ScaledPressure,
    /// Field 0x18.
    pub overrange_status: crate::sensor::OverrangeStatus,
    /// Field 0x40.
    pub odometer_data: crate::sensor::OdometerData,
    /// Field 0xD0 (shared).
    pub event_source: crate::shared::EventSource,
    /// Field 0xD3 (shared).
    pub shared_gps_timestamp: crate::shared::GpsTimestamp,
    /// Field 0xD4 (shared).
    pub delta_time: crate::shared::DeltaTime,
    /// Field 0xD5 (shared).
    pub reference_timestamp: crate::shared::ReferenceTimestamp,
    /// Field 0xD6 (shared).
    pub reference_time_delta: crate::shared::ReferenceTimeDelta,
    /// Field 0xD7 (shared).
    pub external_timestamp: crate::shared::ExternalTimestamp,
    /// Field 0xD8 (shared).
    pub external_time_delta: crate::shared::ExternalTimeDelta,
}

#[cfg(any(feature = "set-sensor", not(feature = "select-sets")))]
impl Packet {
    /// Nothing decoded, every member zero.
    pub const ZERO: Self = Self {
        index: crate::packets::PacketIndex::EMPTY,
        scaled_accel: <crate::sensor::ScaledAccel as crate::wire::Wire>::ZERO,
        scaled_gyro: <crate::sensor::ScaledGyro as crate::wire::Wire>::ZERO,
        scaled_mag: <crate::sensor::ScaledMag as crate::wire::Wire>::ZERO,
        delta_theta: <crate::sensor::DeltaTheta as crate::wire::Wire>::ZERO,
        delta_velocity: <crate::sensor::DeltaVelocity as crate::wire::Wire>::ZERO,
        cf_orientation_matrix: <crate::sensor::CfOrientationMatrix as crate::wire::Wire>::ZERO,
        cf_quaternion: <crate::sensor::CfQuaternion as crate::wire::Wire>::ZERO,
        cf_euler_angles: <crate::sensor::CfEulerAngles as crate::wire::Wire>::ZERO,
        cf_stabilized_north: <crate::sensor::CfStabilizedNorth as crate::wire::Wire>::ZERO,
        cf_stabilized_up: <crate::sensor::CfStabilizedUp as crate::wire::Wire>::ZERO,
        sensor_gps_timestamp: <crate::sensor::GpsTimestamp as crate::wire::Wire>::ZERO,
        temperature_statistics: <crate::sensor::TemperatureStatistics as crate::wire::Wire>::ZERO,
        scaled_pressure: <crate::sensor::ScaledPressure as crate::wire::Wire>::ZERO,
        overrange_status: <crate::sensor::OverrangeStatus as crate::wire::Wire>::ZERO,
        odometer_data: <crate::sensor::OdometerData as crate::wire::Wire>::ZERO,
        event_source: <crate::shared::EventSource as crate::wire::Wire>::ZERO,
        shared_gps_timestamp: <crate::shared::GpsTimestamp as crate::wire::Wire>::ZERO,
        delta_time: <crate::shared::DeltaTime as crate::wire::Wire>::ZERO,
        reference_timestamp: <crate::shared::ReferenceTimestamp as crate::wire::Wire>::ZERO,
        reference_time_delta: <crate::shared::ReferenceTimeDelta as crate::wire::Wire>::ZERO,
        external_timestamp: <crate::shared::ExternalTimestamp as crate::wire::Wire>::ZERO,
        external_time_delta: <crate::shared::ExternalTimeDelta as crate::wire::Wire>::ZERO,
    };
}

#[cfg(any(feature = "set-sensor", not(feature = "select-sets")))]
impl Default for Packet {
    fn default() -> Self {
        Self::ZERO
    }
}

#[cfg(any(feature = "set-sensor", not(feature = "select-sets")))]
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
            0x04 | 0x05
                | 0x06
                | 0x07
                | 0x08
                | 0x09
                | 0x0A
                | 0x0C
                | 0x10
                | 0x11
                | 0x12
                | 0x14
                | 0x17
                | 0x18
                | 0x40
                | 0xD0
                | 0xD3
                | 0xD4
                | 0xD5
                | 0xD6
                | 0xD7
                | 0xD8
        )
    }

    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode_member(&mut self, descriptor: u8, data: &[u8]) -> bool {
        match descriptor {
            0x04 => match <&[u8; 12]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.scaled_accel;
                    s.scaled_accel[0] = crate::packets::ld(d, 0);
                    s.scaled_accel[1] = crate::packets::ld(d, 4);
                    s.scaled_accel[2] = crate::packets::ld(d, 8);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.scaled_accel),
            },
            0x05 => match <&[u8; 12]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.scaled_gyro;
                    s.scaled_gyro[0] = crate::packets::ld(d, 0);
                    s.scaled_gyro[1] = crate::packets::ld(d, 4);
                    s.scaled_gyro[2] = crate::packets::ld(d, 8);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.scaled_gyro),
            },
            0x06 => match <&[u8; 12]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.scaled_mag;
                    s.scaled_mag[0] = crate::packets::ld(d, 0);
                    s.scaled_mag[1] = crate::packets::ld(d, 4);
                    s.scaled_mag[2] = crate::packets::ld(d, 8);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.scaled_mag),
            },
            0x07 => match <&[u8; 12]>::try_from(data) {
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
            0x08 => match <&[u8; 12]>::try_from(data) {
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
            0x09 => match <&[u8; 36]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.cf_orientation_matrix;
                    s.m[0] = crate::packets::ld(d, 0);
                    s.m[1] = crate::packets::ld(d, 4);
                    s.m[2] = crate::packets::ld(d, 8);
                    s.m[3] = crate::packets::ld(d, 12);
                    s.m[4] = crate::packets::ld(d, 16);
                    s.m[5] = crate::packets::ld(d, 20);
                    s.m[6] = crate::packets::ld(d, 24);
                    s.m[7] = crate::packets::ld(d, 28);
                    s.m[8] = crate::packets::ld(d, 32);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.cf_orientation_matrix),
            },
            0x0A => match <&[u8; 16]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.cf_quaternion;
                    s.q[0] = crate::packets::ld(d, 0);
                    s.q[1] = crate::packets::ld(d, 4);
                    s.q[2] = crate::packets::ld(d, 8);
                    s.q[3] = crate::packets::ld(d, 12);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.cf_quaternion),
            },
            0x0C => match <&[u8; 12]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.cf_euler_angles;
                    s.roll = crate::packets::ld(d, 0);
                    s.pitch = crate::packets::ld(d, 4);
                    s.yaw = crate::packets::ld(d, 8);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.cf_euler_angles),
            },
            0x10 => match <&[u8; 12]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.cf_stabilized_north;
                    s.stabilized_north[0] = crate::packets::ld(d, 0);
                    s.stabilized_north[1] = crate::packets::ld(d, 4);
                    s.stabilized_north[2] = crate::packets::ld(d, 8);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.cf_stabilized_north),
            },
            0x11 => match <&[u8; 12]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.cf_stabilized_up;
                    s.stabilized_up[0] = crate::packets::ld(d, 0);
                    s.stabilized_up[1] = crate::packets::ld(d, 4);
                    s.stabilized_up[2] = crate::packets::ld(d, 8);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.cf_stabilized_up),
            },
            0x12 => match <&[u8; 12]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.sensor_gps_timestamp;
                    s.tow = crate::packets::ld(d, 0);
                    s.week_number = crate::packets::ld(d, 8);
                    s.valid_flags = crate::packets::ld(d, 10);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.sensor_gps_timestamp),
            },
            0x14 => match <&[u8; 12]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.temperature_statistics;
                    s.min_temp = crate::packets::ld(d, 0);
                    s.max_temp = crate::packets::ld(d, 4);
                    s.mean_temp = crate::packets::ld(d, 8);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.temperature_statistics),
            },
            0x17 => match <&[u8; 4]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.scaled_pressure;
                    s.scaled_pressure = crate::packets::ld(d, 0);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.scaled_pressure),
            },
            0x18 => match <&[u8; 2]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.overrange_status;
                    s.status = crate::packets::ld(d, 0);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.overrange_status),
            },
            0x40 => match <&[u8; 10]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.odometer_data;
                    s.speed = crate::packets::ld(d, 0);
                    s.uncertainty = crate::packets::ld(d, 4);
                    s.valid_flags = crate::packets::ld(d, 8);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.odometer_data),
            },
            0xD0 => match <&[u8; 1]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.event_source;
                    s.trigger_id = crate::packets::ld(d, 0);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.event_source),
            },
            0xD3 => match <&[u8; 12]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.shared_gps_timestamp;
                    s.tow = crate::packets::ld(d, 0);
                    s.week_number = crate::packets::ld(d, 8);
                    s.valid_flags = crate::packets::ld(d, 10);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.shared_gps_timestamp),
            },
            0xD4 => match <&[u8; 8]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.delta_time;
                    s.seconds = crate::packets::ld(d, 0);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.delta_time),
            },
            0xD5 => match <&[u8; 8]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.reference_timestamp;
                    s.nanoseconds = crate::packets::ld(d, 0);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.reference_timestamp),
            },
            0xD6 => match <&[u8; 8]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.reference_time_delta;
                    s.dt_nanos = crate::packets::ld(d, 0);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.reference_time_delta),
            },
            0xD7 => match <&[u8; 10]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.external_timestamp;
                    s.nanoseconds = crate::packets::ld(d, 0);
                    s.valid_flags = crate::packets::ld(d, 8);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.external_timestamp),
            },
            0xD8 => match <&[u8; 10]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.external_time_delta;
                    s.dt_nanos = crate::packets::ld(d, 0);
                    s.valid_flags = crate::packets::ld(d, 8);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.external_time_delta),
            },
            _ => false,
        }
    }

    fn field(&self, descriptor: u8) -> Option<crate::FieldValue> {
        if !self.index.contains(descriptor) {
            return None;
        }
        match descriptor {
            0x04 => Some(crate::FieldValue::Sensor(
                crate::sensor::SetField::ScaledAccel(self.scaled_accel),
            )),
            0x05 => Some(crate::FieldValue::Sensor(
                crate::sensor::SetField::ScaledGyro(self.scaled_gyro),
            )),
            0x06 => Some(crate::FieldValue::Sensor(
                crate::sensor::SetField::ScaledMag(self.scaled_mag),
            )),
            0x07 => Some(crate::FieldValue::Sensor(
                crate::sensor::SetField::DeltaTheta(self.delta_theta),
            )),
            0x08 => Some(crate::FieldValue::Sensor(
                crate::sensor::SetField::DeltaVelocity(self.delta_velocity),
            )),
            0x09 => Some(crate::FieldValue::Sensor(
                crate::sensor::SetField::CfOrientationMatrix(self.cf_orientation_matrix),
            )),
            0x0A => Some(crate::FieldValue::Sensor(
                crate::sensor::SetField::CfQuaternion(self.cf_quaternion),
            )),
            0x0C => Some(crate::FieldValue::Sensor(
                crate::sensor::SetField::CfEulerAngles(self.cf_euler_angles),
            )),
            0x10 => Some(crate::FieldValue::Sensor(
                crate::sensor::SetField::CfStabilizedNorth(self.cf_stabilized_north),
            )),
            0x11 => Some(crate::FieldValue::Sensor(
                crate::sensor::SetField::CfStabilizedUp(self.cf_stabilized_up),
            )),
            0x12 => Some(crate::FieldValue::Sensor(
                crate::sensor::SetField::GpsTimestamp(self.sensor_gps_timestamp),
            )),
            0x14 => Some(crate::FieldValue::Sensor(
                crate::sensor::SetField::TemperatureStatistics(self.temperature_statistics),
            )),
            0x17 => Some(crate::FieldValue::Sensor(
                crate::sensor::SetField::ScaledPressure(self.scaled_pressure),
            )),
            0x18 => Some(crate::FieldValue::Sensor(
                crate::sensor::SetField::OverrangeStatus(self.overrange_status),
            )),
            0x40 => Some(crate::FieldValue::Sensor(
                crate::sensor::SetField::OdometerData(self.odometer_data),
            )),
            0xD0 => Some(crate::FieldValue::Shared(
                crate::shared::SetField::EventSource(self.event_source),
            )),
            0xD3 => Some(crate::FieldValue::Shared(
                crate::shared::SetField::GpsTimestamp(self.shared_gps_timestamp),
            )),
            0xD4 => Some(crate::FieldValue::Shared(
                crate::shared::SetField::DeltaTime(self.delta_time),
            )),
            0xD5 => Some(crate::FieldValue::Shared(
                crate::shared::SetField::ReferenceTimestamp(self.reference_timestamp),
            )),
            0xD6 => Some(crate::FieldValue::Shared(
                crate::shared::SetField::ReferenceTimeDelta(self.reference_time_delta),
            )),
            0xD7 => Some(crate::FieldValue::Shared(
                crate::shared::SetField::ExternalTimestamp(self.external_timestamp),
            )),
            0xD8 => Some(crate::FieldValue::Shared(
                crate::shared::SetField::ExternalTimeDelta(self.external_time_delta),
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
#[cfg(any(feature = "set-sensor", not(feature = "select-sets")))]
pub fn decode_packet(
    payload: &[u8],
    out: &mut Packet,
    other: impl FnMut(crate::fields::FieldItem<'_>),
) -> usize {
    crate::packets::decode_set_packet(payload, out, other)
}
