//! Estimation Filter Data Set. Outputs of the navigation (Kalman) filter: its status and timestamp, the estimated position, velocity and attitude with their 1-sigma uncertainties, the estimated sensor biases, and bias-compensated inertial quantities.
//!
//! Descriptor set 0x82 (data set):
//! one struct per field layout, and `SetField`, the enum of all its fields.

/// Descriptor set of this module.
pub const SET: u8 = 0x82;

/// LLH position. Estimated position as WGS84 geodetic latitude, longitude and height above the ellipsoid.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LlhPosition {
    /// Latitude. Units: deg.
    pub latitude: f64,
    /// Longitude. Units: deg.
    pub longitude: f64,
    /// Height above the WGS84 ellipsoid. Units: m.
    pub ellipsoid_height: f64,
    /// Whether latitude, longitude and height are valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
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
        ellipsoid_height: <f64 as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(26);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_latitude = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("latitude"))?;
        let p_longitude = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("longitude"))?;
        let p_ellipsoid_height =
            <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("ellipsoid_height"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            latitude: p_latitude,
            longitude: p_longitude,
            ellipsoid_height: p_ellipsoid_height,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.latitude;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("latitude"))?;
        let v = &self.longitude;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("longitude"))?;
        let v = &self.ellipsoid_height;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("ellipsoid_height"))?;
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
        let v = &self.ellipsoid_height;
        crate::json::key(w, &mut first, "ellipsoid_height")?;
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
            &["latitude", "longitude", "ellipsoid_height", "valid_flags"],
        )?;
        let p_latitude = o.req("latitude", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_longitude = o.req("longitude", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_ellipsoid_height = o.req(
            "ellipsoid_height",
            <f64 as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            latitude: p_latitude,
            longitude: p_longitude,
            ellipsoid_height: p_ellipsoid_height,
            valid_flags: p_valid_flags,
        })
    }
}

impl LlhPosition {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for LlhPosition {
    const DESCRIPTOR: u8 = 0x01;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "llh_position";
}

/// NED velocity. Estimated velocity in the local-level north-east-down frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NedVelocity {
    /// North velocity. Units: m/s.
    pub north: f32,
    /// East velocity. Units: m/s.
    pub east: f32,
    /// Down velocity. Units: m/s.
    pub down: f32,
    /// Whether the velocity is valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for NedVelocity {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for NedVelocity {
    const ZERO: Self = Self {
        north: <f32 as crate::wire::Wire>::ZERO,
        east: <f32 as crate::wire::Wire>::ZERO,
        down: <f32 as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(14);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_north = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("north"))?;
        let p_east = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("east"))?;
        let p_down = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("down"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            north: p_north,
            east: p_east,
            down: p_down,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.north;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("north"))?;
        let v = &self.east;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("east"))?;
        let v = &self.down;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("down"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.north;
        crate::json::key(w, &mut first, "north")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.east;
        crate::json::key(w, &mut first, "east")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.down;
        crate::json::key(w, &mut first, "down")?;
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
        let o = crate::json_read::Obj::new(v, &["north", "east", "down", "valid_flags"])?;
        let p_north = o.req("north", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_east = o.req("east", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_down = o.req("down", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            north: p_north,
            east: p_east,
            down: p_down,
            valid_flags: p_valid_flags,
        })
    }
}

impl NedVelocity {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for NedVelocity {
    const DESCRIPTOR: u8 = 0x02;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "ned_velocity";
}

/// Attitude quaternion. Estimated orientation as a quaternion (q0, q1 i, q2 j, q3 k) rotating vectors from the earth-fixed local-level (NED) frame into the device (vehicle) frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AttitudeQuaternion {
    /// Quaternion (q0, q1, q2, q3); the GX5-45 lists the four floats separately.
    pub q: [f32; 4],
    /// Whether the quaternion is valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for AttitudeQuaternion {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AttitudeQuaternion {
    const ZERO: Self = Self {
        q: <[f32; 4] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(18);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_q = <[f32; 4] as crate::wire::Wire>::decode(r).map_err(|e| e.at("q"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            q: p_q,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.q;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("q"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.q;
        crate::json::key(w, &mut first, "q")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AttitudeQuaternion {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["q", "valid_flags"])?;
        let p_q = o.req("q", <[f32; 4] as crate::json_read::FromJson>::from_json)?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            q: p_q,
            valid_flags: p_valid_flags,
        })
    }
}

impl AttitudeQuaternion {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for AttitudeQuaternion {
    const DESCRIPTOR: u8 = 0x03;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "attitude_quaternion";
}

/// Attitude direction cosine matrix. Estimated orientation as a 3x3 direction cosine matrix, row-major (M11, M12, M13, M21, ...), that transforms a vector from the earth-fixed local-level (NED) frame into the device (vehicle) frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AttitudeDcm {
    /// Matrix elements in row-major order; the GX5-45 lists M1,1 ... M3,3 at offsets 0-32.
    pub dcm: [f32; 9],
    /// Whether the matrix is valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for AttitudeDcm {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AttitudeDcm {
    const ZERO: Self = Self {
        dcm: <[f32; 9] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(38);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_dcm = <[f32; 9] as crate::wire::Wire>::decode(r).map_err(|e| e.at("dcm"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            dcm: p_dcm,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.dcm;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("dcm"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.dcm;
        crate::json::key(w, &mut first, "dcm")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AttitudeDcm {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["dcm", "valid_flags"])?;
        let p_dcm = o.req("dcm", <[f32; 9] as crate::json_read::FromJson>::from_json)?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            dcm: p_dcm,
            valid_flags: p_valid_flags,
        })
    }
}

impl AttitudeDcm {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for AttitudeDcm {
    const DESCRIPTOR: u8 = 0x04;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "attitude_dcm";
}

/// Euler angles. Estimated roll, pitch and yaw relative to the local-level (NED) frame, in 3-2-1 (yaw-pitch-roll, aircraft) order.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EulerAngles {
    /// Roll angle. Units: rad.
    pub roll: f32,
    /// Pitch angle. Units: rad.
    pub pitch: f32,
    /// Yaw (heading) angle. Units: rad.
    pub yaw: f32,
    /// Whether the angles are valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for EulerAngles {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for EulerAngles {
    const ZERO: Self = Self {
        roll: <f32 as crate::wire::Wire>::ZERO,
        pitch: <f32 as crate::wire::Wire>::ZERO,
        yaw: <f32 as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(14);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_roll = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("roll"))?;
        let p_pitch = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("pitch"))?;
        let p_yaw = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("yaw"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            roll: p_roll,
            pitch: p_pitch,
            yaw: p_yaw,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.roll;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("roll"))?;
        let v = &self.pitch;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("pitch"))?;
        let v = &self.yaw;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("yaw"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
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
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for EulerAngles {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["roll", "pitch", "yaw", "valid_flags"])?;
        let p_roll = o.req("roll", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_pitch = o.req("pitch", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_yaw = o.req("yaw", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            roll: p_roll,
            pitch: p_pitch,
            yaw: p_yaw,
            valid_flags: p_valid_flags,
        })
    }
}

impl EulerAngles {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for EulerAngles {
    const DESCRIPTOR: u8 = 0x05;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "euler_angles";
}

/// Gyro bias. Estimated gyro bias, in the sensor frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GyroBias {
    /// (x, y, z) gyro bias. Units: rad/s.
    pub bias: [f32; 3],
    /// Whether the bias is valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for GyroBias {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GyroBias {
    const ZERO: Self = Self {
        bias: <[f32; 3] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(14);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_bias = <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("bias"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            bias: p_bias,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.bias;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("bias"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.bias;
        crate::json::key(w, &mut first, "bias")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GyroBias {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["bias", "valid_flags"])?;
        let p_bias = o.req("bias", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            bias: p_bias,
            valid_flags: p_valid_flags,
        })
    }
}

impl GyroBias {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for GyroBias {
    const DESCRIPTOR: u8 = 0x06;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "gyro_bias";
}

/// Accel bias. Estimated accelerometer bias, in the sensor frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AccelBias {
    /// (x, y, z) accelerometer bias. Units: m/s^2.
    pub bias: [f32; 3],
    /// Whether the bias is valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for AccelBias {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AccelBias {
    const ZERO: Self = Self {
        bias: <[f32; 3] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(14);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_bias = <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("bias"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            bias: p_bias,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.bias;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("bias"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.bias;
        crate::json::key(w, &mut first, "bias")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AccelBias {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["bias", "valid_flags"])?;
        let p_bias = o.req("bias", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            bias: p_bias,
            valid_flags: p_valid_flags,
        })
    }
}

impl AccelBias {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for AccelBias {
    const DESCRIPTOR: u8 = 0x07;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "accel_bias";
}

/// LLH position uncertainty. 1-sigma uncertainty of the estimated position, along the local-level north, east and down axes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LlhPositionUncertainty {
    /// North 1-sigma uncertainty. Units: m.
    pub north: f32,
    /// East 1-sigma uncertainty. Units: m.
    pub east: f32,
    /// Down 1-sigma uncertainty. Units: m.
    pub down: f32,
    /// Whether the uncertainties are valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for LlhPositionUncertainty {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for LlhPositionUncertainty {
    const ZERO: Self = Self {
        north: <f32 as crate::wire::Wire>::ZERO,
        east: <f32 as crate::wire::Wire>::ZERO,
        down: <f32 as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(14);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_north = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("north"))?;
        let p_east = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("east"))?;
        let p_down = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("down"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            north: p_north,
            east: p_east,
            down: p_down,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.north;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("north"))?;
        let v = &self.east;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("east"))?;
        let v = &self.down;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("down"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.north;
        crate::json::key(w, &mut first, "north")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.east;
        crate::json::key(w, &mut first, "east")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.down;
        crate::json::key(w, &mut first, "down")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for LlhPositionUncertainty {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["north", "east", "down", "valid_flags"])?;
        let p_north = o.req("north", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_east = o.req("east", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_down = o.req("down", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            north: p_north,
            east: p_east,
            down: p_down,
            valid_flags: p_valid_flags,
        })
    }
}

impl LlhPositionUncertainty {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for LlhPositionUncertainty {
    const DESCRIPTOR: u8 = 0x08;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "llh_position_uncertainty";
}

/// NED velocity uncertainty. 1-sigma uncertainty of the estimated velocity, along the local-level north, east and down axes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NedVelocityUncertainty {
    /// North 1-sigma uncertainty. Units: m/s.
    pub north: f32,
    /// East 1-sigma uncertainty. Units: m/s.
    pub east: f32,
    /// Down 1-sigma uncertainty. Units: m/s.
    pub down: f32,
    /// Whether the uncertainties are valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for NedVelocityUncertainty {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for NedVelocityUncertainty {
    const ZERO: Self = Self {
        north: <f32 as crate::wire::Wire>::ZERO,
        east: <f32 as crate::wire::Wire>::ZERO,
        down: <f32 as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(14);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_north = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("north"))?;
        let p_east = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("east"))?;
        let p_down = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("down"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            north: p_north,
            east: p_east,
            down: p_down,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.north;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("north"))?;
        let v = &self.east;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("east"))?;
        let v = &self.down;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("down"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.north;
        crate::json::key(w, &mut first, "north")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.east;
        crate::json::key(w, &mut first, "east")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.down;
        crate::json::key(w, &mut first, "down")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for NedVelocityUncertainty {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["north", "east", "down", "valid_flags"])?;
        let p_north = o.req("north", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_east = o.req("east", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_down = o.req("down", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            north: p_north,
            east: p_east,
            down: p_down,
            valid_flags: p_valid_flags,
        })
    }
}

impl NedVelocityUncertainty {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for NedVelocityUncertainty {
    const DESCRIPTOR: u8 = 0x09;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "ned_velocity_uncertainty";
}

/// Euler angles uncertainty. 1-sigma uncertainty of the estimated roll, pitch and yaw. The GX5-45 derives these from the quaternion uncertainty and flags them invalid when the pitch exceeds +/-70 degrees.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EulerAnglesUncertainty {
    /// Roll 1-sigma uncertainty. Units: rad.
    pub roll: f32,
    /// Pitch 1-sigma uncertainty. Units: rad.
    pub pitch: f32,
    /// Yaw 1-sigma uncertainty. Units: rad.
    pub yaw: f32,
    /// Whether the uncertainties are valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for EulerAnglesUncertainty {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for EulerAnglesUncertainty {
    const ZERO: Self = Self {
        roll: <f32 as crate::wire::Wire>::ZERO,
        pitch: <f32 as crate::wire::Wire>::ZERO,
        yaw: <f32 as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(14);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_roll = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("roll"))?;
        let p_pitch = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("pitch"))?;
        let p_yaw = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("yaw"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            roll: p_roll,
            pitch: p_pitch,
            yaw: p_yaw,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.roll;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("roll"))?;
        let v = &self.pitch;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("pitch"))?;
        let v = &self.yaw;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("yaw"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
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
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for EulerAnglesUncertainty {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["roll", "pitch", "yaw", "valid_flags"])?;
        let p_roll = o.req("roll", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_pitch = o.req("pitch", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_yaw = o.req("yaw", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            roll: p_roll,
            pitch: p_pitch,
            yaw: p_yaw,
            valid_flags: p_valid_flags,
        })
    }
}

impl EulerAnglesUncertainty {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for EulerAnglesUncertainty {
    const DESCRIPTOR: u8 = 0x0A;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "euler_angles_uncertainty";
}

/// Gyro bias uncertainty. 1-sigma uncertainty of the estimated gyro bias, in the sensor frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GyroBiasUncertainty {
    /// (x, y, z) 1-sigma uncertainty. Units: rad/s.
    pub bias_uncertainty: [f32; 3],
    /// Whether the uncertainties are valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for GyroBiasUncertainty {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GyroBiasUncertainty {
    const ZERO: Self = Self {
        bias_uncertainty: <[f32; 3] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(14);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_bias_uncertainty =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("bias_uncertainty"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            bias_uncertainty: p_bias_uncertainty,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.bias_uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("bias_uncertainty"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.bias_uncertainty;
        crate::json::key(w, &mut first, "bias_uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GyroBiasUncertainty {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["bias_uncertainty", "valid_flags"])?;
        let p_bias_uncertainty = o.req(
            "bias_uncertainty",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            bias_uncertainty: p_bias_uncertainty,
            valid_flags: p_valid_flags,
        })
    }
}

impl GyroBiasUncertainty {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for GyroBiasUncertainty {
    const DESCRIPTOR: u8 = 0x0B;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "gyro_bias_uncertainty";
}

/// Accel bias uncertainty. 1-sigma uncertainty of the estimated accelerometer bias, in the sensor frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AccelBiasUncertainty {
    /// (x, y, z) 1-sigma uncertainty. Units: m/s^2.
    pub bias_uncertainty: [f32; 3],
    /// Whether the uncertainties are valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for AccelBiasUncertainty {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AccelBiasUncertainty {
    const ZERO: Self = Self {
        bias_uncertainty: <[f32; 3] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(14);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_bias_uncertainty =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("bias_uncertainty"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            bias_uncertainty: p_bias_uncertainty,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.bias_uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("bias_uncertainty"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.bias_uncertainty;
        crate::json::key(w, &mut first, "bias_uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AccelBiasUncertainty {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["bias_uncertainty", "valid_flags"])?;
        let p_bias_uncertainty = o.req(
            "bias_uncertainty",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            bias_uncertainty: p_bias_uncertainty,
            valid_flags: p_valid_flags,
        })
    }
}

impl AccelBiasUncertainty {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for AccelBiasUncertainty {
    const DESCRIPTOR: u8 = 0x0C;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "accel_bias_uncertainty";
}

/// Linear acceleration. Filter-compensated acceleration with the estimated gravity removed, in the vehicle frame (GX5-45: in the sensor frame when no sensor-to-vehicle rotation is set).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LinearAccel {
    /// (x, y, z) linear acceleration. Units: m/s^2.
    pub accel: [f32; 3],
    /// Whether the acceleration is valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for LinearAccel {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for LinearAccel {
    const ZERO: Self = Self {
        accel: <[f32; 3] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(14);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_accel = <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("accel"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            accel: p_accel,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.accel;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("accel"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.accel;
        crate::json::key(w, &mut first, "accel")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for LinearAccel {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["accel", "valid_flags"])?;
        let p_accel = o.req("accel", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            accel: p_accel,
            valid_flags: p_valid_flags,
        })
    }
}

impl LinearAccel {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for LinearAccel {
    const DESCRIPTOR: u8 = 0x0D;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "linear_accel";
}

/// Compensated angular rate. Angular rate with the estimated gyro bias removed, in the vehicle frame (GX5-45: in the sensor frame when no sensor-to-vehicle rotation is set).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CompAngularRate {
    /// (x, y, z) angular rate. Units: rad/s.
    pub gyro: [f32; 3],
    /// Whether the angular rate is valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for CompAngularRate {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for CompAngularRate {
    const ZERO: Self = Self {
        gyro: <[f32; 3] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(14);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_gyro = <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("gyro"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            gyro: p_gyro,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.gyro;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("gyro"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.gyro;
        crate::json::key(w, &mut first, "gyro")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for CompAngularRate {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["gyro", "valid_flags"])?;
        let p_gyro = o.req("gyro", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            gyro: p_gyro,
            valid_flags: p_valid_flags,
        })
    }
}

impl CompAngularRate {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for CompAngularRate {
    const DESCRIPTOR: u8 = 0x0E;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "comp_angular_rate";
}

/// WGS84 local gravity magnitude. Magnitude of the local gravity from the WGS84 gravity model (valid for altitudes up to 20 km). GX5-45 only.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Wgs84GravityMagnitude {
    /// Local gravity magnitude. Units: m/s^2.
    pub gravity_magnitude: f32,
    /// Whether the gravity value is valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for Wgs84GravityMagnitude {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for Wgs84GravityMagnitude {
    const ZERO: Self = Self {
        gravity_magnitude: <f32 as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(6);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_gravity_magnitude =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("gravity_magnitude"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            gravity_magnitude: p_gravity_magnitude,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.gravity_magnitude;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("gravity_magnitude"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.gravity_magnitude;
        crate::json::key(w, &mut first, "gravity_magnitude")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for Wgs84GravityMagnitude {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["gravity_magnitude", "valid_flags"])?;
        let p_gravity_magnitude = o.req(
            "gravity_magnitude",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            gravity_magnitude: p_gravity_magnitude,
            valid_flags: p_valid_flags,
        })
    }
}

impl Wgs84GravityMagnitude {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for Wgs84GravityMagnitude {
    const DESCRIPTOR: u8 = 0x0F;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "wgs84_gravity_magnitude";
}

/// Filter status. Layout for device gx5_45.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FilterStatusGx5_45 {
    /// Filter state.
    pub filter_state: crate::types::FilterStateGx5,
    /// Vehicle dynamics mode.
    pub dynamics_mode: crate::types::FilterDynamicsModeGx5,
    /// Status flags; their meaning depends on the filter state.
    pub status_flags: crate::types::FilterStatusFlagsGx5,
}

impl Default for FilterStatusGx5_45 {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for FilterStatusGx5_45 {
    const ZERO: Self = Self {
        filter_state: <crate::types::FilterStateGx5 as crate::wire::Wire>::ZERO,
        dynamics_mode: <crate::types::FilterDynamicsModeGx5 as crate::wire::Wire>::ZERO,
        status_flags: <crate::types::FilterStatusFlagsGx5 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(6);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_filter_state = <crate::types::FilterStateGx5 as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("filter_state"))?;
        let p_dynamics_mode = <crate::types::FilterDynamicsModeGx5 as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("dynamics_mode"))?;
        let p_status_flags = <crate::types::FilterStatusFlagsGx5 as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("status_flags"))?;
        Ok(Self {
            filter_state: p_filter_state,
            dynamics_mode: p_dynamics_mode,
            status_flags: p_status_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.filter_state;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("filter_state"))?;
        let v = &self.dynamics_mode;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("dynamics_mode"))?;
        let v = &self.status_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("status_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.filter_state;
        crate::json::key(w, &mut first, "filter_state")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.dynamics_mode;
        crate::json::key(w, &mut first, "dynamics_mode")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.status_flags;
        crate::json::key(w, &mut first, "status_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for FilterStatusGx5_45 {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["filter_state", "dynamics_mode", "status_flags"])?;
        let p_filter_state = o.req(
            "filter_state",
            <crate::types::FilterStateGx5 as crate::json_read::FromJson>::from_json,
        )?;
        let p_dynamics_mode = o.req(
            "dynamics_mode",
            <crate::types::FilterDynamicsModeGx5 as crate::json_read::FromJson>::from_json,
        )?;
        let p_status_flags = o.req(
            "status_flags",
            <crate::types::FilterStatusFlagsGx5 as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            filter_state: p_filter_state,
            dynamics_mode: p_dynamics_mode,
            status_flags: p_status_flags,
        })
    }
}

impl FilterStatusGx5_45 {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for FilterStatusGx5_45 {
    const DESCRIPTOR: u8 = 0x10;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "filter_status";
}

/// Filter status. Layout for device cv7_ins.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FilterStatusCv7Ins {
    /// Filter mode reached (Filter States page).
    pub filter_state: crate::types::FilterModeCv7,
    /// Dynamics mode.
    pub dynamics_mode: crate::types::FilterDynamicsModeCv7,
    /// Filter condition and warning flags.
    pub status_flags: crate::types::FilterStatusFlagsCv7,
}

impl Default for FilterStatusCv7Ins {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for FilterStatusCv7Ins {
    const ZERO: Self = Self {
        filter_state: <crate::types::FilterModeCv7 as crate::wire::Wire>::ZERO,
        dynamics_mode: <crate::types::FilterDynamicsModeCv7 as crate::wire::Wire>::ZERO,
        status_flags: <crate::types::FilterStatusFlagsCv7 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(6);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_filter_state = <crate::types::FilterModeCv7 as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("filter_state"))?;
        let p_dynamics_mode = <crate::types::FilterDynamicsModeCv7 as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("dynamics_mode"))?;
        let p_status_flags = <crate::types::FilterStatusFlagsCv7 as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("status_flags"))?;
        Ok(Self {
            filter_state: p_filter_state,
            dynamics_mode: p_dynamics_mode,
            status_flags: p_status_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.filter_state;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("filter_state"))?;
        let v = &self.dynamics_mode;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("dynamics_mode"))?;
        let v = &self.status_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("status_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.filter_state;
        crate::json::key(w, &mut first, "filter_state")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.dynamics_mode;
        crate::json::key(w, &mut first, "dynamics_mode")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.status_flags;
        crate::json::key(w, &mut first, "status_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for FilterStatusCv7Ins {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["filter_state", "dynamics_mode", "status_flags"])?;
        let p_filter_state = o.req(
            "filter_state",
            <crate::types::FilterModeCv7 as crate::json_read::FromJson>::from_json,
        )?;
        let p_dynamics_mode = o.req(
            "dynamics_mode",
            <crate::types::FilterDynamicsModeCv7 as crate::json_read::FromJson>::from_json,
        )?;
        let p_status_flags = o.req(
            "status_flags",
            <crate::types::FilterStatusFlagsCv7 as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            filter_state: p_filter_state,
            dynamics_mode: p_dynamics_mode,
            status_flags: p_status_flags,
        })
    }
}

impl FilterStatusCv7Ins {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for FilterStatusCv7Ins {
    const DESCRIPTOR: u8 = 0x10;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "filter_status";
}

/// Filter status. Filter state (or mode), dynamics mode and status flags. All three are device-specific: the same numbers mean different things on the GX5-45 and on the CV7.
///
/// The layout differs per device; one variant per device, in spec order.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FilterStatus {
    /// Layout for device `gx5_45`.
    Gx5_45(FilterStatusGx5_45),
    /// Layout for device `cv7_ins`.
    Cv7Ins(FilterStatusCv7Ins),
}

impl FilterStatus {
    /// Field descriptor.
    pub const DESCRIPTOR: u8 = 0x10;
    /// Field name as printed in JSON.
    pub const NAME: &'static str = "filter_status";

    /// Device whose layout this value uses.
    pub fn device(&self) -> crate::Device {
        match self {
            Self::Gx5_45(_) => crate::Device::Gx5_45,
            Self::Cv7Ins(_) => crate::Device::Cv7Ins,
        }
    }

    /// Decodes with `device`'s layout if it has one, else tries the layouts in spec order and
    /// keeps the first that decodes (reporting the first layout's error if none does).
    pub fn decode_data(
        data: &[u8],
        device: Option<crate::Device>,
    ) -> Result<Self, crate::error::DecodeError> {
        if device == Some(crate::Device::Gx5_45) {
            return <FilterStatusGx5_45 as crate::wire::Layout>::decode_data(data)
                .map(Self::Gx5_45);
        }
        if device == Some(crate::Device::Cv7Ins) {
            return <FilterStatusCv7Ins as crate::wire::Layout>::decode_data(data)
                .map(Self::Cv7Ins);
        }
        let first = match <FilterStatusGx5_45 as crate::wire::Layout>::decode_data(data) {
            Ok(v) => return Ok(Self::Gx5_45(v)),
            Err(e) => e,
        };
        if let Ok(v) = <FilterStatusCv7Ins as crate::wire::Layout>::decode_data(data) {
            return Ok(Self::Cv7Ins(v));
        }
        Err(first)
    }

    /// Encodes the field data.
    pub fn encode_data(
        &self,
        w: &mut crate::wire::Writer<'_>,
    ) -> Result<(), crate::error::EncodeError> {
        match self {
            Self::Gx5_45(v) => crate::wire::Layout::encode_data(v, w),
            Self::Cv7Ins(v) => crate::wire::Layout::encode_data(v, w),
        }
    }

    /// Writes the canonical JSON of the values.
    pub fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::Gx5_45(v) => crate::wire::Wire::write_json(v, w),
            Self::Cv7Ins(v) => crate::wire::Wire::write_json(v, w),
        }
    }

    /// Reads the values of `device`'s layout.
    #[cfg(feature = "std")]
    pub fn from_json(
        device: Option<crate::Device>,
        values: &crate::json_read::Json,
    ) -> Result<Self, crate::json_read::JsonError> {
        match device {
            Some(crate::Device::Gx5_45) => <FilterStatusGx5_45 as crate::json_read::FromJson>::from_json(values)
                .map(Self::Gx5_45)
                .map_err(|e| e.at("values")),
            Some(crate::Device::Cv7Ins) => <FilterStatusCv7Ins as crate::json_read::FromJson>::from_json(values)
                .map(Self::Cv7Ins)
                .map_err(|e| e.at("values")),
            None => Err(crate::json_read::JsonError::new(
                "field filter_status has per-device layouts; name one with \"device\" (gx5_45, cv7_ins)",
            )
            .at("device")),
        }
    }
}

/// GPS timestamp. GPS time of the filter solution in this packet. The CV7 notes that it may be deprecated in favour of the shared GPS timestamp field (0xD3).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GpsTimestamp {
    /// GPS time of week. Units: s.
    pub tow: f64,
    /// GPS week number since 1980. Units: weeks.
    pub week_number: u16,
    /// Whether the time is valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
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
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
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
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
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
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
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
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for GpsTimestamp {
    const DESCRIPTOR: u8 = 0x11;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "gps_timestamp";
}

/// Quaternion attitude uncertainty. 1-sigma uncertainty of the attitude quaternion, one value per quaternion element (dimensionless).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct QuaternionAttitudeUncertainty {
    /// 1-sigma uncertainty of (q0, q1, q2, q3).
    pub q: [f32; 4],
    /// Whether the uncertainties are valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for QuaternionAttitudeUncertainty {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for QuaternionAttitudeUncertainty {
    const ZERO: Self = Self {
        q: <[f32; 4] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(18);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_q = <[f32; 4] as crate::wire::Wire>::decode(r).map_err(|e| e.at("q"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            q: p_q,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.q;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("q"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.q;
        crate::json::key(w, &mut first, "q")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for QuaternionAttitudeUncertainty {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["q", "valid_flags"])?;
        let p_q = o.req("q", <[f32; 4] as crate::json_read::FromJson>::from_json)?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            q: p_q,
            valid_flags: p_valid_flags,
        })
    }
}

impl QuaternionAttitudeUncertainty {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for QuaternionAttitudeUncertainty {
    const DESCRIPTOR: u8 = 0x12;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "quaternion_attitude_uncertainty";
}

/// Gravity vector. Estimated gravity vector. GX5-45: in the sensor frame, or in the vehicle frame when a sensor-to-vehicle transformation is set; CV7: in the vehicle frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GravityVector {
    /// (x, y, z) gravity. Units: m/s^2.
    pub gravity: [f32; 3],
    /// Gravity vector valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for GravityVector {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GravityVector {
    const ZERO: Self = Self {
        gravity: <[f32; 3] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(14);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_gravity = <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("gravity"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            gravity: p_gravity,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.gravity;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("gravity"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.gravity;
        crate::json::key(w, &mut first, "gravity")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GravityVector {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["gravity", "valid_flags"])?;
        let p_gravity = o.req(
            "gravity",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            gravity: p_gravity,
            valid_flags: p_valid_flags,
        })
    }
}

impl GravityVector {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for GravityVector {
    const DESCRIPTOR: u8 = 0x13;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "gravity_vector";
}

/// Heading update source state. The last heading update the filter received: heading (relative to true north), its uncertainty and the sources in use.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HeadingUpdateState {
    /// Heading, from true north. Units: rad.
    pub heading: f32,
    /// 1-sigma heading uncertainty. Units: rad.
    pub heading_uncertainty: f32,
    /// Heading update sources in use (may be combined).
    pub source: crate::types::FilterHeadingSourceFlags,
    /// Whether a heading update arrived within 2 seconds.
    pub valid_flags: crate::types::FilterHeadingUpdateValidFlags,
}

impl Default for HeadingUpdateState {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for HeadingUpdateState {
    const ZERO: Self = Self {
        heading: <f32 as crate::wire::Wire>::ZERO,
        heading_uncertainty: <f32 as crate::wire::Wire>::ZERO,
        source: <crate::types::FilterHeadingSourceFlags as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterHeadingUpdateValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(12);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_heading = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("heading"))?;
        let p_heading_uncertainty =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("heading_uncertainty"))?;
        let p_source = <crate::types::FilterHeadingSourceFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("source"))?;
        let p_valid_flags =
            <crate::types::FilterHeadingUpdateValidFlags as crate::wire::Wire>::decode(r)
                .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            heading: p_heading,
            heading_uncertainty: p_heading_uncertainty,
            source: p_source,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.heading;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("heading"))?;
        let v = &self.heading_uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("heading_uncertainty"))?;
        let v = &self.source;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("source"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
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
        let v = &self.source;
        crate::json::key(w, &mut first, "source")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for HeadingUpdateState {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &["heading", "heading_uncertainty", "source", "valid_flags"],
        )?;
        let p_heading = o.req("heading", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_heading_uncertainty = o.req(
            "heading_uncertainty",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_source = o.req(
            "source",
            <crate::types::FilterHeadingSourceFlags as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterHeadingUpdateValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            heading: p_heading,
            heading_uncertainty: p_heading_uncertainty,
            source: p_source,
            valid_flags: p_valid_flags,
        })
    }
}

impl HeadingUpdateState {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for HeadingUpdateState {
    const DESCRIPTOR: u8 = 0x14;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "heading_update_state";
}

/// Magnetic model solution. Earth magnetic field at the current position from the World Magnetic Model (GX5-45: WMM 2010), in the NED frame; needs a valid GNSS position. Invalid while the model is being recalculated and when GNSS is unavailable.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MagneticModel {
    /// North component of the field. Units: gauss.
    pub intensity_north: f32,
    /// East component of the field. Units: gauss.
    pub intensity_east: f32,
    /// Down component of the field. Units: gauss.
    pub intensity_down: f32,
    /// Inclination (dip) angle. Units: rad.
    pub inclination: f32,
    /// Declination angle. Units: rad.
    pub declination: f32,
    /// Model solution valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for MagneticModel {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for MagneticModel {
    const ZERO: Self = Self {
        intensity_north: <f32 as crate::wire::Wire>::ZERO,
        intensity_east: <f32 as crate::wire::Wire>::ZERO,
        intensity_down: <f32 as crate::wire::Wire>::ZERO,
        inclination: <f32 as crate::wire::Wire>::ZERO,
        declination: <f32 as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(22);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_intensity_north =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("intensity_north"))?;
        let p_intensity_east =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("intensity_east"))?;
        let p_intensity_down =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("intensity_down"))?;
        let p_inclination =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("inclination"))?;
        let p_declination =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("declination"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            intensity_north: p_intensity_north,
            intensity_east: p_intensity_east,
            intensity_down: p_intensity_down,
            inclination: p_inclination,
            declination: p_declination,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.intensity_north;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("intensity_north"))?;
        let v = &self.intensity_east;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("intensity_east"))?;
        let v = &self.intensity_down;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("intensity_down"))?;
        let v = &self.inclination;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("inclination"))?;
        let v = &self.declination;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("declination"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.intensity_north;
        crate::json::key(w, &mut first, "intensity_north")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.intensity_east;
        crate::json::key(w, &mut first, "intensity_east")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.intensity_down;
        crate::json::key(w, &mut first, "intensity_down")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.inclination;
        crate::json::key(w, &mut first, "inclination")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.declination;
        crate::json::key(w, &mut first, "declination")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for MagneticModel {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "intensity_north",
                "intensity_east",
                "intensity_down",
                "inclination",
                "declination",
                "valid_flags",
            ],
        )?;
        let p_intensity_north = o.req(
            "intensity_north",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_intensity_east = o.req(
            "intensity_east",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_intensity_down = o.req(
            "intensity_down",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_inclination = o.req(
            "inclination",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_declination = o.req(
            "declination",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            intensity_north: p_intensity_north,
            intensity_east: p_intensity_east,
            intensity_down: p_intensity_down,
            inclination: p_inclination,
            declination: p_declination,
            valid_flags: p_valid_flags,
        })
    }
}

impl MagneticModel {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for MagneticModel {
    const DESCRIPTOR: u8 = 0x15;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "magnetic_model";
}

/// Gyro scale factor. Estimated gyro scale factor errors in the sensor body frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GyroScaleFactor {
    /// (x, y, z) scale factor, as a fraction (percent / 100). Units: %/100.
    pub scale_factor: [f32; 3],
    /// Scale factor values valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for GyroScaleFactor {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GyroScaleFactor {
    const ZERO: Self = Self {
        scale_factor: <[f32; 3] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(14);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_scale_factor =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("scale_factor"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            scale_factor: p_scale_factor,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.scale_factor;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("scale_factor"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.scale_factor;
        crate::json::key(w, &mut first, "scale_factor")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GyroScaleFactor {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["scale_factor", "valid_flags"])?;
        let p_scale_factor = o.req(
            "scale_factor",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            scale_factor: p_scale_factor,
            valid_flags: p_valid_flags,
        })
    }
}

impl GyroScaleFactor {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for GyroScaleFactor {
    const DESCRIPTOR: u8 = 0x16;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "gyro_scale_factor";
}

/// Accelerometer scale factor. Estimated accelerometer scale factor errors in the sensor body frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AccelScaleFactor {
    /// (x, y, z) scale factor, as a fraction (percent / 100). Units: %/100.
    pub scale_factor: [f32; 3],
    /// Scale factor values valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for AccelScaleFactor {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AccelScaleFactor {
    const ZERO: Self = Self {
        scale_factor: <[f32; 3] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(14);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_scale_factor =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("scale_factor"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            scale_factor: p_scale_factor,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.scale_factor;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("scale_factor"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.scale_factor;
        crate::json::key(w, &mut first, "scale_factor")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AccelScaleFactor {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["scale_factor", "valid_flags"])?;
        let p_scale_factor = o.req(
            "scale_factor",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            scale_factor: p_scale_factor,
            valid_flags: p_valid_flags,
        })
    }
}

impl AccelScaleFactor {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for AccelScaleFactor {
    const DESCRIPTOR: u8 = 0x17;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "accel_scale_factor";
}

/// Gyro scale factor uncertainty. 1-sigma uncertainty of the estimated gyro scale factors, sensor body frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GyroScaleFactorUncertainty {
    /// (x, y, z) 1-sigma uncertainty. Units: %/100.
    pub scale_factor_uncertainty: [f32; 3],
    /// Uncertainties valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for GyroScaleFactorUncertainty {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GyroScaleFactorUncertainty {
    const ZERO: Self = Self {
        scale_factor_uncertainty: <[f32; 3] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(14);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_scale_factor_uncertainty = <[f32; 3] as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("scale_factor_uncertainty"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            scale_factor_uncertainty: p_scale_factor_uncertainty,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.scale_factor_uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("scale_factor_uncertainty"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.scale_factor_uncertainty;
        crate::json::key(w, &mut first, "scale_factor_uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GyroScaleFactorUncertainty {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["scale_factor_uncertainty", "valid_flags"])?;
        let p_scale_factor_uncertainty = o.req(
            "scale_factor_uncertainty",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            scale_factor_uncertainty: p_scale_factor_uncertainty,
            valid_flags: p_valid_flags,
        })
    }
}

impl GyroScaleFactorUncertainty {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for GyroScaleFactorUncertainty {
    const DESCRIPTOR: u8 = 0x18;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "gyro_scale_factor_uncertainty";
}

/// Accelerometer scale factor uncertainty. 1-sigma uncertainty of the estimated accelerometer scale factors, sensor body frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AccelScaleFactorUncertainty {
    /// (x, y, z) 1-sigma uncertainty. Units: %/100.
    pub scale_factor_uncertainty: [f32; 3],
    /// Uncertainties valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for AccelScaleFactorUncertainty {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AccelScaleFactorUncertainty {
    const ZERO: Self = Self {
        scale_factor_uncertainty: <[f32; 3] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(14);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_scale_factor_uncertainty = <[f32; 3] as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("scale_factor_uncertainty"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            scale_factor_uncertainty: p_scale_factor_uncertainty,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.scale_factor_uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("scale_factor_uncertainty"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.scale_factor_uncertainty;
        crate::json::key(w, &mut first, "scale_factor_uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AccelScaleFactorUncertainty {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["scale_factor_uncertainty", "valid_flags"])?;
        let p_scale_factor_uncertainty = o.req(
            "scale_factor_uncertainty",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            scale_factor_uncertainty: p_scale_factor_uncertainty,
            valid_flags: p_valid_flags,
        })
    }
}

impl AccelScaleFactorUncertainty {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for AccelScaleFactorUncertainty {
    const DESCRIPTOR: u8 = 0x19;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "accel_scale_factor_uncertainty";
}

/// Compensated acceleration. Acceleration with the filter's bias estimate removed (gravity included; 0x0D is the linear acceleration without gravity). GX5-45: sensor frame, or vehicle frame when a sensor-to-vehicle transformation is set; CV7: vehicle frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CompensatedAccel {
    /// (x, y, z) compensated acceleration. Units: m/s^2.
    pub accel: [f32; 3],
    /// Compensated accelerations valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for CompensatedAccel {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for CompensatedAccel {
    const ZERO: Self = Self {
        accel: <[f32; 3] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(14);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_accel = <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("accel"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            accel: p_accel,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.accel;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("accel"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.accel;
        crate::json::key(w, &mut first, "accel")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for CompensatedAccel {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["accel", "valid_flags"])?;
        let p_accel = o.req("accel", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            accel: p_accel,
            valid_flags: p_valid_flags,
        })
    }
}

impl CompensatedAccel {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for CompensatedAccel {
    const DESCRIPTOR: u8 = 0x1C;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "compensated_accel";
}

/// Standard atmosphere model. US 1976 Standard Atmosphere values at the current altitude; needs a valid GNSS location (invalid while GNSS is unavailable).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StandardAtmosphere {
    /// Geometric altitude. Units: m.
    pub geometric_altitude: f32,
    /// Geopotential altitude. Units: m.
    pub geopotential_altitude: f32,
    /// Standard temperature. Units: degC.
    pub temperature: f32,
    /// Standard pressure. Units: mbar.
    pub pressure: f32,
    /// Standard air density. Units: kg/m^3.
    pub density: f32,
    /// Atmosphere model solution valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for StandardAtmosphere {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for StandardAtmosphere {
    const ZERO: Self = Self {
        geometric_altitude: <f32 as crate::wire::Wire>::ZERO,
        geopotential_altitude: <f32 as crate::wire::Wire>::ZERO,
        temperature: <f32 as crate::wire::Wire>::ZERO,
        pressure: <f32 as crate::wire::Wire>::ZERO,
        density: <f32 as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(22);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_geometric_altitude =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("geometric_altitude"))?;
        let p_geopotential_altitude =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("geopotential_altitude"))?;
        let p_temperature =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("temperature"))?;
        let p_pressure = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("pressure"))?;
        let p_density = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("density"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            geometric_altitude: p_geometric_altitude,
            geopotential_altitude: p_geopotential_altitude,
            temperature: p_temperature,
            pressure: p_pressure,
            density: p_density,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.geometric_altitude;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("geometric_altitude"))?;
        let v = &self.geopotential_altitude;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("geopotential_altitude"))?;
        let v = &self.temperature;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("temperature"))?;
        let v = &self.pressure;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("pressure"))?;
        let v = &self.density;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("density"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.geometric_altitude;
        crate::json::key(w, &mut first, "geometric_altitude")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.geopotential_altitude;
        crate::json::key(w, &mut first, "geopotential_altitude")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.temperature;
        crate::json::key(w, &mut first, "temperature")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.pressure;
        crate::json::key(w, &mut first, "pressure")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.density;
        crate::json::key(w, &mut first, "density")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for StandardAtmosphere {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "geometric_altitude",
                "geopotential_altitude",
                "temperature",
                "pressure",
                "density",
                "valid_flags",
            ],
        )?;
        let p_geometric_altitude = o.req(
            "geometric_altitude",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_geopotential_altitude = o.req(
            "geopotential_altitude",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_temperature = o.req(
            "temperature",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_pressure = o.req("pressure", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_density = o.req("density", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            geometric_altitude: p_geometric_altitude,
            geopotential_altitude: p_geopotential_altitude,
            temperature: p_temperature,
            pressure: p_pressure,
            density: p_density,
            valid_flags: p_valid_flags,
        })
    }
}

impl StandardAtmosphere {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for StandardAtmosphere {
    const DESCRIPTOR: u8 = 0x20;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "standard_atmosphere";
}

/// Pressure altitude. Altitude from the pressure sensor through the US 1976 Standard Atmosphere model; needs a valid pressure reading. The model supports pressures down to 0.0037 mbar (84,852 m).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PressureAltitude {
    /// Pressure altitude. Units: m.
    pub pressure_altitude: f32,
    /// Pressure altitude valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for PressureAltitude {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for PressureAltitude {
    const ZERO: Self = Self {
        pressure_altitude: <f32 as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(6);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_pressure_altitude =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("pressure_altitude"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            pressure_altitude: p_pressure_altitude,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.pressure_altitude;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("pressure_altitude"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.pressure_altitude;
        crate::json::key(w, &mut first, "pressure_altitude")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for PressureAltitude {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["pressure_altitude", "valid_flags"])?;
        let p_pressure_altitude = o.req(
            "pressure_altitude",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            pressure_altitude: p_pressure_altitude,
            valid_flags: p_valid_flags,
        })
    }
}

impl PressureAltitude {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for PressureAltitude {
    const DESCRIPTOR: u8 = 0x21;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "pressure_altitude";
}

/// Magnetometer auto hard iron offset. Offset vector the filter adds to the hard iron offset to compensate in-run magnetometer bias errors.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MagAutoHardIronOffset {
    /// (x, y, z) offset. Units: gauss.
    pub hard_iron_offset: [f32; 3],
    /// Vector valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for MagAutoHardIronOffset {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for MagAutoHardIronOffset {
    const ZERO: Self = Self {
        hard_iron_offset: <[f32; 3] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(14);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_hard_iron_offset =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("hard_iron_offset"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            hard_iron_offset: p_hard_iron_offset,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.hard_iron_offset;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("hard_iron_offset"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.hard_iron_offset;
        crate::json::key(w, &mut first, "hard_iron_offset")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for MagAutoHardIronOffset {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["hard_iron_offset", "valid_flags"])?;
        let p_hard_iron_offset = o.req(
            "hard_iron_offset",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            hard_iron_offset: p_hard_iron_offset,
            valid_flags: p_valid_flags,
        })
    }
}

impl MagAutoHardIronOffset {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for MagAutoHardIronOffset {
    const DESCRIPTOR: u8 = 0x25;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "mag_auto_hard_iron_offset";
}

/// Magnetometer auto soft iron matrix. Matrix the filter applies to the soft iron calibration matrix to compensate in-run magnetometer errors.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MagAutoSoftIronMatrix {
    /// M11..M33, row-major (dimensionless).
    pub soft_iron_matrix: [f32; 9],
    /// Matrix valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for MagAutoSoftIronMatrix {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for MagAutoSoftIronMatrix {
    const ZERO: Self = Self {
        soft_iron_matrix: <[f32; 9] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(38);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_soft_iron_matrix =
            <[f32; 9] as crate::wire::Wire>::decode(r).map_err(|e| e.at("soft_iron_matrix"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            soft_iron_matrix: p_soft_iron_matrix,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.soft_iron_matrix;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("soft_iron_matrix"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.soft_iron_matrix;
        crate::json::key(w, &mut first, "soft_iron_matrix")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for MagAutoSoftIronMatrix {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["soft_iron_matrix", "valid_flags"])?;
        let p_soft_iron_matrix = o.req(
            "soft_iron_matrix",
            <[f32; 9] as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            soft_iron_matrix: p_soft_iron_matrix,
            valid_flags: p_valid_flags,
        })
    }
}

impl MagAutoSoftIronMatrix {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for MagAutoSoftIronMatrix {
    const DESCRIPTOR: u8 = 0x26;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "mag_auto_soft_iron_matrix";
}

/// Magnetometer auto hard iron offset uncertainty. 1-sigma uncertainty of the auto hard iron offset (0x82,0x25).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MagAutoHardIronOffsetUncertainty {
    /// (x, y, z) 1-sigma uncertainty. Units: gauss.
    pub hard_iron_offset_uncertainty: [f32; 3],
    /// Vector valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for MagAutoHardIronOffsetUncertainty {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for MagAutoHardIronOffsetUncertainty {
    const ZERO: Self = Self {
        hard_iron_offset_uncertainty: <[f32; 3] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(14);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_hard_iron_offset_uncertainty = <[f32; 3] as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("hard_iron_offset_uncertainty"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            hard_iron_offset_uncertainty: p_hard_iron_offset_uncertainty,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.hard_iron_offset_uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("hard_iron_offset_uncertainty"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.hard_iron_offset_uncertainty;
        crate::json::key(w, &mut first, "hard_iron_offset_uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for MagAutoHardIronOffsetUncertainty {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["hard_iron_offset_uncertainty", "valid_flags"])?;
        let p_hard_iron_offset_uncertainty = o.req(
            "hard_iron_offset_uncertainty",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            hard_iron_offset_uncertainty: p_hard_iron_offset_uncertainty,
            valid_flags: p_valid_flags,
        })
    }
}

impl MagAutoHardIronOffsetUncertainty {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for MagAutoHardIronOffsetUncertainty {
    const DESCRIPTOR: u8 = 0x28;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "mag_auto_hard_iron_offset_uncertainty";
}

/// Magnetometer auto soft iron matrix uncertainty. 1-sigma uncertainty of each element of the auto soft iron matrix (0x82,0x26).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MagAutoSoftIronMatrixUncertainty {
    /// 1-sigma uncertainty of M11..M33, row-major (dimensionless).
    pub soft_iron_matrix_uncertainty: [f32; 9],
    /// Matrix valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for MagAutoSoftIronMatrixUncertainty {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for MagAutoSoftIronMatrixUncertainty {
    const ZERO: Self = Self {
        soft_iron_matrix_uncertainty: <[f32; 9] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(38);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_soft_iron_matrix_uncertainty = <[f32; 9] as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("soft_iron_matrix_uncertainty"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            soft_iron_matrix_uncertainty: p_soft_iron_matrix_uncertainty,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.soft_iron_matrix_uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("soft_iron_matrix_uncertainty"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.soft_iron_matrix_uncertainty;
        crate::json::key(w, &mut first, "soft_iron_matrix_uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for MagAutoSoftIronMatrixUncertainty {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["soft_iron_matrix_uncertainty", "valid_flags"])?;
        let p_soft_iron_matrix_uncertainty = o.req(
            "soft_iron_matrix_uncertainty",
            <[f32; 9] as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            soft_iron_matrix_uncertainty: p_soft_iron_matrix_uncertainty,
            valid_flags: p_valid_flags,
        })
    }
}

impl MagAutoSoftIronMatrixUncertainty {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for MagAutoSoftIronMatrixUncertainty {
    const DESCRIPTOR: u8 = 0x29;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "mag_auto_soft_iron_matrix_uncertainty";
}

/// GNSS antenna offset correction. Estimated correction of the GNSS antenna offset (the vector from the IMU to the antenna), in the sensor body frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GnssAntennaOffsetCorrection {
    /// (x, y, z) offset correction. Units: m.
    pub offset: [f32; 3],
    /// Offset correction values valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for GnssAntennaOffsetCorrection {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GnssAntennaOffsetCorrection {
    const ZERO: Self = Self {
        offset: <[f32; 3] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(14);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_offset = <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("offset"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            offset: p_offset,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.offset;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("offset"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.offset;
        crate::json::key(w, &mut first, "offset")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GnssAntennaOffsetCorrection {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["offset", "valid_flags"])?;
        let p_offset = o.req(
            "offset",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            offset: p_offset,
            valid_flags: p_valid_flags,
        })
    }
}

impl GnssAntennaOffsetCorrection {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for GnssAntennaOffsetCorrection {
    const DESCRIPTOR: u8 = 0x30;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "gnss_antenna_offset_correction";
}

/// GNSS antenna offset correction uncertainty. 1-sigma uncertainty of the GNSS antenna offset correction, sensor body frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GnssAntennaOffsetCorrectionUncertainty {
    /// (x, y, z) 1-sigma uncertainty. Units: m.
    pub offset_uncertainty: [f32; 3],
    /// Uncertainties valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for GnssAntennaOffsetCorrectionUncertainty {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GnssAntennaOffsetCorrectionUncertainty {
    const ZERO: Self = Self {
        offset_uncertainty: <[f32; 3] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(14);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_offset_uncertainty =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("offset_uncertainty"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            offset_uncertainty: p_offset_uncertainty,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.offset_uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("offset_uncertainty"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.offset_uncertainty;
        crate::json::key(w, &mut first, "offset_uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GnssAntennaOffsetCorrectionUncertainty {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["offset_uncertainty", "valid_flags"])?;
        let p_offset_uncertainty = o.req(
            "offset_uncertainty",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            offset_uncertainty: p_offset_uncertainty,
            valid_flags: p_valid_flags,
        })
    }
}

impl GnssAntennaOffsetCorrectionUncertainty {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for GnssAntennaOffsetCorrectionUncertainty {
    const DESCRIPTOR: u8 = 0x31;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "gnss_antenna_offset_correction_uncertainty";
}

/// Multi-antenna offset correction. Estimated correction of one GNSS antenna's offset, in the vehicle frame; added to the stored offset vector to compensate errors in its definition.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MultiAntennaOffsetCorrection {
    /// Receiver to which the antenna is attached.
    pub receiver_id: u8,
    /// (x, y, z) offset correction. Units: m.
    pub offset: [f32; 3],
    /// Offset correction valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for MultiAntennaOffsetCorrection {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for MultiAntennaOffsetCorrection {
    const ZERO: Self = Self {
        receiver_id: <u8 as crate::wire::Wire>::ZERO,
        offset: <[f32; 3] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(15);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_receiver_id =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("receiver_id"))?;
        let p_offset = <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("offset"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            receiver_id: p_receiver_id,
            offset: p_offset,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.receiver_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("receiver_id"))?;
        let v = &self.offset;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("offset"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.receiver_id;
        crate::json::key(w, &mut first, "receiver_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.offset;
        crate::json::key(w, &mut first, "offset")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for MultiAntennaOffsetCorrection {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["receiver_id", "offset", "valid_flags"])?;
        let p_receiver_id = o.req("receiver_id", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_offset = o.req(
            "offset",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            receiver_id: p_receiver_id,
            offset: p_offset,
            valid_flags: p_valid_flags,
        })
    }
}

impl MultiAntennaOffsetCorrection {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for MultiAntennaOffsetCorrection {
    const DESCRIPTOR: u8 = 0x34;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "multi_antenna_offset_correction";
}

/// Multi-antenna offset correction uncertainty. 1-sigma uncertainty of one GNSS antenna's offset correction, vehicle frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MultiAntennaOffsetCorrectionUncertainty {
    /// Receiver to which the antenna is attached.
    pub receiver_id: u8,
    /// (x, y, z) 1-sigma uncertainty. Units: m.
    pub offset_uncertainty: [f32; 3],
    /// Uncertainties valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for MultiAntennaOffsetCorrectionUncertainty {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for MultiAntennaOffsetCorrectionUncertainty {
    const ZERO: Self = Self {
        receiver_id: <u8 as crate::wire::Wire>::ZERO,
        offset_uncertainty: <[f32; 3] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(15);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_receiver_id =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("receiver_id"))?;
        let p_offset_uncertainty =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("offset_uncertainty"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            receiver_id: p_receiver_id,
            offset_uncertainty: p_offset_uncertainty,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.receiver_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("receiver_id"))?;
        let v = &self.offset_uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("offset_uncertainty"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.receiver_id;
        crate::json::key(w, &mut first, "receiver_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.offset_uncertainty;
        crate::json::key(w, &mut first, "offset_uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for MultiAntennaOffsetCorrectionUncertainty {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o =
            crate::json_read::Obj::new(v, &["receiver_id", "offset_uncertainty", "valid_flags"])?;
        let p_receiver_id = o.req("receiver_id", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_offset_uncertainty = o.req(
            "offset_uncertainty",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            receiver_id: p_receiver_id,
            offset_uncertainty: p_offset_uncertainty,
            valid_flags: p_valid_flags,
        })
    }
}

impl MultiAntennaOffsetCorrectionUncertainty {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for MultiAntennaOffsetCorrectionUncertainty {
    const DESCRIPTOR: u8 = 0x35;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "multi_antenna_offset_correction_uncertainty";
}

/// ECEF position uncertainty. 1-sigma position uncertainty in the ECEF frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EcefPositionUncertainty {
    /// (x, y, z) 1-sigma uncertainty. Units: m.
    pub position_uncertainty: [f32; 3],
    /// Uncertainties valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for EcefPositionUncertainty {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for EcefPositionUncertainty {
    const ZERO: Self = Self {
        position_uncertainty: <[f32; 3] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(14);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_position_uncertainty =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("position_uncertainty"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            position_uncertainty: p_position_uncertainty,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.position_uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("position_uncertainty"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.position_uncertainty;
        crate::json::key(w, &mut first, "position_uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for EcefPositionUncertainty {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["position_uncertainty", "valid_flags"])?;
        let p_position_uncertainty = o.req(
            "position_uncertainty",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            position_uncertainty: p_position_uncertainty,
            valid_flags: p_valid_flags,
        })
    }
}

impl EcefPositionUncertainty {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for EcefPositionUncertainty {
    const DESCRIPTOR: u8 = 0x36;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "ecef_position_uncertainty";
}

/// ECEF velocity uncertainty. 1-sigma velocity uncertainty in the ECEF frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EcefVelocityUncertainty {
    /// (x, y, z) 1-sigma uncertainty. Units: m/s.
    pub velocity_uncertainty: [f32; 3],
    /// Uncertainties valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for EcefVelocityUncertainty {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for EcefVelocityUncertainty {
    const ZERO: Self = Self {
        velocity_uncertainty: <[f32; 3] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(14);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_velocity_uncertainty =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("velocity_uncertainty"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            velocity_uncertainty: p_velocity_uncertainty,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.velocity_uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("velocity_uncertainty"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.velocity_uncertainty;
        crate::json::key(w, &mut first, "velocity_uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for EcefVelocityUncertainty {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["velocity_uncertainty", "valid_flags"])?;
        let p_velocity_uncertainty = o.req(
            "velocity_uncertainty",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            velocity_uncertainty: p_velocity_uncertainty,
            valid_flags: p_valid_flags,
        })
    }
}

impl EcefVelocityUncertainty {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for EcefVelocityUncertainty {
    const DESCRIPTOR: u8 = 0x37;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "ecef_velocity_uncertainty";
}

/// ECEF position. Estimated position in the ECEF frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EcefPosition {
    /// (x, y, z) ECEF position. Units: m.
    pub position: [f64; 3],
    /// Position valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for EcefPosition {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for EcefPosition {
    const ZERO: Self = Self {
        position: <[f64; 3] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(26);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_position =
            <[f64; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("position"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            position: p_position,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.position;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("position"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.position;
        crate::json::key(w, &mut first, "position")?;
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
        let o = crate::json_read::Obj::new(v, &["position", "valid_flags"])?;
        let p_position = o.req(
            "position",
            <[f64; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            position: p_position,
            valid_flags: p_valid_flags,
        })
    }
}

impl EcefPosition {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for EcefPosition {
    const DESCRIPTOR: u8 = 0x40;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "ecef_position";
}

/// ECEF velocity. Estimated velocity in the ECEF frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EcefVelocity {
    /// (x, y, z) ECEF velocity. Units: m/s.
    pub velocity: [f32; 3],
    /// Velocity valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for EcefVelocity {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for EcefVelocity {
    const ZERO: Self = Self {
        velocity: <[f32; 3] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(14);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_velocity =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("velocity"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            velocity: p_velocity,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.velocity;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("velocity"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.velocity;
        crate::json::key(w, &mut first, "velocity")?;
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
        let o = crate::json_read::Obj::new(v, &["velocity", "valid_flags"])?;
        let p_velocity = o.req(
            "velocity",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            velocity: p_velocity,
            valid_flags: p_valid_flags,
        })
    }
}

impl EcefVelocity {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for EcefVelocity {
    const DESCRIPTOR: u8 = 0x41;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "ecef_velocity";
}

/// NED relative position. Estimated position relative to the reference position set with Relative Position Configuration (0x0D,0x55), as north, east, down.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NedRelativePosition {
    /// (north, east, down) position relative to the reference. Units: m.
    pub relative_position: [f64; 3],
    /// Relative position valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for NedRelativePosition {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for NedRelativePosition {
    const ZERO: Self = Self {
        relative_position: <[f64; 3] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(26);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_relative_position =
            <[f64; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("relative_position"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            relative_position: p_relative_position,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.relative_position;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("relative_position"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.relative_position;
        crate::json::key(w, &mut first, "relative_position")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for NedRelativePosition {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["relative_position", "valid_flags"])?;
        let p_relative_position = o.req(
            "relative_position",
            <[f64; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            relative_position: p_relative_position,
            valid_flags: p_valid_flags,
        })
    }
}

impl NedRelativePosition {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for NedRelativePosition {
    const DESCRIPTOR: u8 = 0x42;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "ned_relative_position";
}

/// GNSS position aiding status. How the filter is using the position measurements of one GNSS receiver.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GnssPositionAidingStatus {
    /// GNSS receiver the status refers to.
    pub receiver_id: u8,
    /// GPS time of week of the last GNSS aiding measurement. Units: s.
    pub time_of_week: f32,
    /// Aiding measurement status.
    pub status: crate::types::FilterGnssAidingStatusFlags,
    /// Reserved.
    pub reserved: [u8; 8],
}

impl Default for GnssPositionAidingStatus {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GnssPositionAidingStatus {
    const ZERO: Self = Self {
        receiver_id: <u8 as crate::wire::Wire>::ZERO,
        time_of_week: <f32 as crate::wire::Wire>::ZERO,
        status: <crate::types::FilterGnssAidingStatusFlags as crate::wire::Wire>::ZERO,
        reserved: <[u8; 8] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(15);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_receiver_id =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("receiver_id"))?;
        let p_time_of_week =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("time_of_week"))?;
        let p_status = <crate::types::FilterGnssAidingStatusFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("status"))?;
        let p_reserved = <[u8; 8] as crate::wire::Wire>::decode(r).map_err(|e| e.at("reserved"))?;
        Ok(Self {
            receiver_id: p_receiver_id,
            time_of_week: p_time_of_week,
            status: p_status,
            reserved: p_reserved,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.receiver_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("receiver_id"))?;
        let v = &self.time_of_week;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("time_of_week"))?;
        let v = &self.status;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("status"))?;
        let v = &self.reserved;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("reserved"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.receiver_id;
        crate::json::key(w, &mut first, "receiver_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.time_of_week;
        crate::json::key(w, &mut first, "time_of_week")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.status;
        crate::json::key(w, &mut first, "status")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.reserved;
        crate::json::key(w, &mut first, "reserved")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GnssPositionAidingStatus {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o =
            crate::json_read::Obj::new(v, &["receiver_id", "time_of_week", "status", "reserved"])?;
        let p_receiver_id = o.req("receiver_id", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_time_of_week = o.req(
            "time_of_week",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_status = o.req(
            "status",
            <crate::types::FilterGnssAidingStatusFlags as crate::json_read::FromJson>::from_json,
        )?;
        let p_reserved = o.req(
            "reserved",
            <[u8; 8] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            receiver_id: p_receiver_id,
            time_of_week: p_time_of_week,
            status: p_status,
            reserved: p_reserved,
        })
    }
}

impl GnssPositionAidingStatus {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for GnssPositionAidingStatus {
    const DESCRIPTOR: u8 = 0x43;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "gnss_position_aiding_status";
}

/// Aiding measurement summary. Summary of one aiding measurement over the measurement interval ending at the given time: whether it is enabled and used, and any warnings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AidingMeasurementSummary {
    /// GPS time of week at the end of the measurement interval. Units: s.
    pub time_of_week: f32,
    /// Measurement source (not described by the manual).
    pub source: u8,
    /// Which aiding measurement is summarised.
    pub r#type: crate::types::FilterAidingMeasurementType,
    /// Measurement state and warnings.
    pub indicator: crate::types::FilterAidingMeasurementIndicator,
}

impl Default for AidingMeasurementSummary {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AidingMeasurementSummary {
    const ZERO: Self = Self {
        time_of_week: <f32 as crate::wire::Wire>::ZERO,
        source: <u8 as crate::wire::Wire>::ZERO,
        r#type: <crate::types::FilterAidingMeasurementType as crate::wire::Wire>::ZERO,
        indicator: <crate::types::FilterAidingMeasurementIndicator as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(7);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_time_of_week =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("time_of_week"))?;
        let p_source = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("source"))?;
        let p_type = <crate::types::FilterAidingMeasurementType as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("type"))?;
        let p_indicator =
            <crate::types::FilterAidingMeasurementIndicator as crate::wire::Wire>::decode(r)
                .map_err(|e| e.at("indicator"))?;
        Ok(Self {
            time_of_week: p_time_of_week,
            source: p_source,
            r#type: p_type,
            indicator: p_indicator,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.time_of_week;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("time_of_week"))?;
        let v = &self.source;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("source"))?;
        let v = &self.r#type;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("type"))?;
        let v = &self.indicator;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("indicator"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.time_of_week;
        crate::json::key(w, &mut first, "time_of_week")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.source;
        crate::json::key(w, &mut first, "source")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.r#type;
        crate::json::key(w, &mut first, "type")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.indicator;
        crate::json::key(w, &mut first, "indicator")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AidingMeasurementSummary {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["time_of_week", "source", "type", "indicator"])?;
        let p_time_of_week = o.req(
            "time_of_week",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_source = o.req("source", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_type = o.req(
            "type",
            <crate::types::FilterAidingMeasurementType as crate::json_read::FromJson>::from_json,
        )?;
        let p_indicator = o.req("indicator", <crate::types::FilterAidingMeasurementIndicator as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            time_of_week: p_time_of_week,
            source: p_source,
            r#type: p_type,
            indicator: p_indicator,
        })
    }
}

impl AidingMeasurementSummary {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for AidingMeasurementSummary {
    const DESCRIPTOR: u8 = 0x46;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "aiding_measurement_summary";
}

/// Odometer scale factor error. Estimated odometer scale factor error; the total scale factor is the user scale factor times (1 + this error).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OdometerScaleFactorError {
    /// Scale factor error (dimensionless).
    pub scale_factor_error: f32,
    /// Estimate valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for OdometerScaleFactorError {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for OdometerScaleFactorError {
    const ZERO: Self = Self {
        scale_factor_error: <f32 as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(6);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_scale_factor_error =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("scale_factor_error"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            scale_factor_error: p_scale_factor_error,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.scale_factor_error;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("scale_factor_error"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.scale_factor_error;
        crate::json::key(w, &mut first, "scale_factor_error")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for OdometerScaleFactorError {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["scale_factor_error", "valid_flags"])?;
        let p_scale_factor_error = o.req(
            "scale_factor_error",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            scale_factor_error: p_scale_factor_error,
            valid_flags: p_valid_flags,
        })
    }
}

impl OdometerScaleFactorError {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for OdometerScaleFactorError {
    const DESCRIPTOR: u8 = 0x47;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "odometer_scale_factor_error";
}

/// Odometer scale factor error uncertainty. 1-sigma uncertainty of the odometer scale factor error.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OdometerScaleFactorErrorUncertainty {
    /// 1-sigma uncertainty (dimensionless).
    pub scale_factor_error_uncertainty: f32,
    /// Uncertainty valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for OdometerScaleFactorErrorUncertainty {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for OdometerScaleFactorErrorUncertainty {
    const ZERO: Self = Self {
        scale_factor_error_uncertainty: <f32 as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(6);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_scale_factor_error_uncertainty = <f32 as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("scale_factor_error_uncertainty"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            scale_factor_error_uncertainty: p_scale_factor_error_uncertainty,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.scale_factor_error_uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("scale_factor_error_uncertainty"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.scale_factor_error_uncertainty;
        crate::json::key(w, &mut first, "scale_factor_error_uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for OdometerScaleFactorErrorUncertainty {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["scale_factor_error_uncertainty", "valid_flags"])?;
        let p_scale_factor_error_uncertainty = o.req(
            "scale_factor_error_uncertainty",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            scale_factor_error_uncertainty: p_scale_factor_error_uncertainty,
            valid_flags: p_valid_flags,
        })
    }
}

impl OdometerScaleFactorErrorUncertainty {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for OdometerScaleFactorErrorUncertainty {
    const DESCRIPTOR: u8 = 0x48;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "odometer_scale_factor_error_uncertainty";
}

/// GNSS dual antenna status. State of the GNSS dual-antenna heading measurement the filter last used.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GnssDualAntennaStatus {
    /// GPS time of week of the last dual-antenna aiding measurement. Units: s.
    pub time_of_week: f32,
    /// Dual-antenna heading. Units: rad.
    pub heading: f32,
    /// 1-sigma heading uncertainty. Units: rad.
    pub heading_uncertainty: f32,
    /// Fix type.
    pub fix_type: crate::types::FilterDualAntennaFixType,
    /// Receiver and antenna-offset validity.
    pub status_flags: crate::types::FilterDualAntennaStatusFlags,
    /// Field valid.
    pub valid_flags: crate::types::FilterOutputValidFlags,
}

impl Default for GnssDualAntennaStatus {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GnssDualAntennaStatus {
    const ZERO: Self = Self {
        time_of_week: <f32 as crate::wire::Wire>::ZERO,
        heading: <f32 as crate::wire::Wire>::ZERO,
        heading_uncertainty: <f32 as crate::wire::Wire>::ZERO,
        fix_type: <crate::types::FilterDualAntennaFixType as crate::wire::Wire>::ZERO,
        status_flags: <crate::types::FilterDualAntennaStatusFlags as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::FilterOutputValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(17);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_time_of_week =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("time_of_week"))?;
        let p_heading = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("heading"))?;
        let p_heading_uncertainty =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("heading_uncertainty"))?;
        let p_fix_type = <crate::types::FilterDualAntennaFixType as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("fix_type"))?;
        let p_status_flags =
            <crate::types::FilterDualAntennaStatusFlags as crate::wire::Wire>::decode(r)
                .map_err(|e| e.at("status_flags"))?;
        let p_valid_flags = <crate::types::FilterOutputValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            time_of_week: p_time_of_week,
            heading: p_heading,
            heading_uncertainty: p_heading_uncertainty,
            fix_type: p_fix_type,
            status_flags: p_status_flags,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.time_of_week;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("time_of_week"))?;
        let v = &self.heading;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("heading"))?;
        let v = &self.heading_uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("heading_uncertainty"))?;
        let v = &self.fix_type;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("fix_type"))?;
        let v = &self.status_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("status_flags"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.time_of_week;
        crate::json::key(w, &mut first, "time_of_week")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.heading;
        crate::json::key(w, &mut first, "heading")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.heading_uncertainty;
        crate::json::key(w, &mut first, "heading_uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.fix_type;
        crate::json::key(w, &mut first, "fix_type")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.status_flags;
        crate::json::key(w, &mut first, "status_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GnssDualAntennaStatus {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "time_of_week",
                "heading",
                "heading_uncertainty",
                "fix_type",
                "status_flags",
                "valid_flags",
            ],
        )?;
        let p_time_of_week = o.req(
            "time_of_week",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_heading = o.req("heading", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_heading_uncertainty = o.req(
            "heading_uncertainty",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_fix_type = o.req(
            "fix_type",
            <crate::types::FilterDualAntennaFixType as crate::json_read::FromJson>::from_json,
        )?;
        let p_status_flags = o.req(
            "status_flags",
            <crate::types::FilterDualAntennaStatusFlags as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::FilterOutputValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            time_of_week: p_time_of_week,
            heading: p_heading,
            heading_uncertainty: p_heading_uncertainty,
            fix_type: p_fix_type,
            status_flags: p_status_flags,
            valid_flags: p_valid_flags,
        })
    }
}

impl GnssDualAntennaStatus {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for GnssDualAntennaStatus {
    const DESCRIPTOR: u8 = 0x49;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "gnss_dual_antenna_status";
}

/// Aiding frame configuration error. Estimated error of one user aiding frame configuration (Aiding Frame Configuration, 0x13,0x01), used to compensate small errors in it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AidingFrameConfigError {
    /// Aiding reference frame id (as in 0x13,0x01).
    pub frame_id: u8,
    /// Translation error, X, Y, Z. Units: m.
    pub translation: [f32; 3],
    /// Attitude error quaternion.
    pub attitude: [f32; 4],
}

impl Default for AidingFrameConfigError {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AidingFrameConfigError {
    const ZERO: Self = Self {
        frame_id: <u8 as crate::wire::Wire>::ZERO,
        translation: <[f32; 3] as crate::wire::Wire>::ZERO,
        attitude: <[f32; 4] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(29);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_frame_id = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("frame_id"))?;
        let p_translation =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("translation"))?;
        let p_attitude =
            <[f32; 4] as crate::wire::Wire>::decode(r).map_err(|e| e.at("attitude"))?;
        Ok(Self {
            frame_id: p_frame_id,
            translation: p_translation,
            attitude: p_attitude,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.frame_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("frame_id"))?;
        let v = &self.translation;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("translation"))?;
        let v = &self.attitude;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("attitude"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.frame_id;
        crate::json::key(w, &mut first, "frame_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.translation;
        crate::json::key(w, &mut first, "translation")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.attitude;
        crate::json::key(w, &mut first, "attitude")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AidingFrameConfigError {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["frame_id", "translation", "attitude"])?;
        let p_frame_id = o.req("frame_id", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_translation = o.req(
            "translation",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_attitude = o.req(
            "attitude",
            <[f32; 4] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            frame_id: p_frame_id,
            translation: p_translation,
            attitude: p_attitude,
        })
    }
}

impl AidingFrameConfigError {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for AidingFrameConfigError {
    const DESCRIPTOR: u8 = 0x50;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "aiding_frame_config_error";
}

/// Aiding frame configuration error uncertainty. 1-sigma uncertainty of the estimated aiding frame configuration error (0x82,0x50).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AidingFrameConfigErrorUncertainty {
    /// Aiding reference frame id (as in 0x13,0x01).
    pub frame_id: u8,
    /// 1-sigma translation uncertainty, X, Y, Z. Units: m.
    pub translation_uncertainty: [f32; 3],
    /// 1-sigma attitude uncertainty, X, Y, Z. Units: rad.
    pub attitude_uncertainty: [f32; 3],
}

impl Default for AidingFrameConfigErrorUncertainty {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AidingFrameConfigErrorUncertainty {
    const ZERO: Self = Self {
        frame_id: <u8 as crate::wire::Wire>::ZERO,
        translation_uncertainty: <[f32; 3] as crate::wire::Wire>::ZERO,
        attitude_uncertainty: <[f32; 3] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(25);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_frame_id = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("frame_id"))?;
        let p_translation_uncertainty = <[f32; 3] as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("translation_uncertainty"))?;
        let p_attitude_uncertainty =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("attitude_uncertainty"))?;
        Ok(Self {
            frame_id: p_frame_id,
            translation_uncertainty: p_translation_uncertainty,
            attitude_uncertainty: p_attitude_uncertainty,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.frame_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("frame_id"))?;
        let v = &self.translation_uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("translation_uncertainty"))?;
        let v = &self.attitude_uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("attitude_uncertainty"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.frame_id;
        crate::json::key(w, &mut first, "frame_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.translation_uncertainty;
        crate::json::key(w, &mut first, "translation_uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.attitude_uncertainty;
        crate::json::key(w, &mut first, "attitude_uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AidingFrameConfigErrorUncertainty {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "frame_id",
                "translation_uncertainty",
                "attitude_uncertainty",
            ],
        )?;
        let p_frame_id = o.req("frame_id", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_translation_uncertainty = o.req(
            "translation_uncertainty",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_attitude_uncertainty = o.req(
            "attitude_uncertainty",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            frame_id: p_frame_id,
            translation_uncertainty: p_translation_uncertainty,
            attitude_uncertainty: p_attitude_uncertainty,
        })
    }
}

impl AidingFrameConfigErrorUncertainty {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x82;
}

impl crate::wire::Layout for AidingFrameConfigErrorUncertainty {
    const DESCRIPTOR: u8 = 0x51;
    const DESCRIPTOR_SET: Option<u8> = Some(0x82);
    const NAME: &'static str = "aiding_frame_config_error_uncertainty";
}

/// A decoded field of set 0x82 (`filter_data`).
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SetField {
    /// `llh_position` (0x01).
    LlhPosition(LlhPosition),
    /// `ned_velocity` (0x02).
    NedVelocity(NedVelocity),
    /// `attitude_quaternion` (0x03).
    AttitudeQuaternion(AttitudeQuaternion),
    /// `attitude_dcm` (0x04).
    AttitudeDcm(AttitudeDcm),
    /// `euler_angles` (0x05).
    EulerAngles(EulerAngles),
    /// `gyro_bias` (0x06).
    GyroBias(GyroBias),
    /// `accel_bias` (0x07).
    AccelBias(AccelBias),
    /// `llh_position_uncertainty` (0x08).
    LlhPositionUncertainty(LlhPositionUncertainty),
    /// `ned_velocity_uncertainty` (0x09).
    NedVelocityUncertainty(NedVelocityUncertainty),
    /// `euler_angles_uncertainty` (0x0A).
    EulerAnglesUncertainty(EulerAnglesUncertainty),
    /// `gyro_bias_uncertainty` (0x0B).
    GyroBiasUncertainty(GyroBiasUncertainty),
    /// `accel_bias_uncertainty` (0x0C).
    AccelBiasUncertainty(AccelBiasUncertainty),
    /// `linear_accel` (0x0D).
    LinearAccel(LinearAccel),
    /// `comp_angular_rate` (0x0E).
    CompAngularRate(CompAngularRate),
    /// `wgs84_gravity_magnitude` (0x0F).
    Wgs84GravityMagnitude(Wgs84GravityMagnitude),
    /// `filter_status` (0x10).
    FilterStatus(FilterStatus),
    /// `gps_timestamp` (0x11).
    GpsTimestamp(GpsTimestamp),
    /// `quaternion_attitude_uncertainty` (0x12).
    QuaternionAttitudeUncertainty(QuaternionAttitudeUncertainty),
    /// `gravity_vector` (0x13).
    GravityVector(GravityVector),
    /// `heading_update_state` (0x14).
    HeadingUpdateState(HeadingUpdateState),
    /// `magnetic_model` (0x15).
    MagneticModel(MagneticModel),
    /// `gyro_scale_factor` (0x16).
    GyroScaleFactor(GyroScaleFactor),
    /// `accel_scale_factor` (0x17).
    AccelScaleFactor(AccelScaleFactor),
    /// `gyro_scale_factor_uncertainty` (0x18).
    GyroScaleFactorUncertainty(GyroScaleFactorUncertainty),
    /// `accel_scale_factor_uncertainty` (0x19).
    AccelScaleFactorUncertainty(AccelScaleFactorUncertainty),
    /// `compensated_accel` (0x1C).
    CompensatedAccel(CompensatedAccel),
    /// `standard_atmosphere` (0x20).
    StandardAtmosphere(StandardAtmosphere),
    /// `pressure_altitude` (0x21).
    PressureAltitude(PressureAltitude),
    /// `mag_auto_hard_iron_offset` (0x25).
    MagAutoHardIronOffset(MagAutoHardIronOffset),
    /// `mag_auto_soft_iron_matrix` (0x26).
    MagAutoSoftIronMatrix(MagAutoSoftIronMatrix),
    /// `mag_auto_hard_iron_offset_uncertainty` (0x28).
    MagAutoHardIronOffsetUncertainty(MagAutoHardIronOffsetUncertainty),
    /// `mag_auto_soft_iron_matrix_uncertainty` (0x29).
    MagAutoSoftIronMatrixUncertainty(MagAutoSoftIronMatrixUncertainty),
    /// `gnss_antenna_offset_correction` (0x30).
    GnssAntennaOffsetCorrection(GnssAntennaOffsetCorrection),
    /// `gnss_antenna_offset_correction_uncertainty` (0x31).
    GnssAntennaOffsetCorrectionUncertainty(GnssAntennaOffsetCorrectionUncertainty),
    /// `multi_antenna_offset_correction` (0x34).
    MultiAntennaOffsetCorrection(MultiAntennaOffsetCorrection),
    /// `multi_antenna_offset_correction_uncertainty` (0x35).
    MultiAntennaOffsetCorrectionUncertainty(MultiAntennaOffsetCorrectionUncertainty),
    /// `ecef_position_uncertainty` (0x36).
    EcefPositionUncertainty(EcefPositionUncertainty),
    /// `ecef_velocity_uncertainty` (0x37).
    EcefVelocityUncertainty(EcefVelocityUncertainty),
    /// `ecef_position` (0x40).
    EcefPosition(EcefPosition),
    /// `ecef_velocity` (0x41).
    EcefVelocity(EcefVelocity),
    /// `ned_relative_position` (0x42).
    NedRelativePosition(NedRelativePosition),
    /// `gnss_position_aiding_status` (0x43).
    GnssPositionAidingStatus(GnssPositionAidingStatus),
    /// `aiding_measurement_summary` (0x46).
    AidingMeasurementSummary(AidingMeasurementSummary),
    /// `odometer_scale_factor_error` (0x47).
    OdometerScaleFactorError(OdometerScaleFactorError),
    /// `odometer_scale_factor_error_uncertainty` (0x48).
    OdometerScaleFactorErrorUncertainty(OdometerScaleFactorErrorUncertainty),
    /// `gnss_dual_antenna_status` (0x49).
    GnssDualAntennaStatus(GnssDualAntennaStatus),
    /// `aiding_frame_config_error` (0x50).
    AidingFrameConfigError(AidingFrameConfigError),
    /// `aiding_frame_config_error_uncertainty` (0x51).
    AidingFrameConfigErrorUncertainty(AidingFrameConfigErrorUncertainty),
}

impl SetField {
    /// Field descriptor.
    pub fn descriptor(&self) -> u8 {
        match self {
            Self::LlhPosition(_) => 0x01,
            Self::NedVelocity(_) => 0x02,
            Self::AttitudeQuaternion(_) => 0x03,
            Self::AttitudeDcm(_) => 0x04,
            Self::EulerAngles(_) => 0x05,
            Self::GyroBias(_) => 0x06,
            Self::AccelBias(_) => 0x07,
            Self::LlhPositionUncertainty(_) => 0x08,
            Self::NedVelocityUncertainty(_) => 0x09,
            Self::EulerAnglesUncertainty(_) => 0x0A,
            Self::GyroBiasUncertainty(_) => 0x0B,
            Self::AccelBiasUncertainty(_) => 0x0C,
            Self::LinearAccel(_) => 0x0D,
            Self::CompAngularRate(_) => 0x0E,
            Self::Wgs84GravityMagnitude(_) => 0x0F,
            Self::FilterStatus(_) => 0x10,
            Self::GpsTimestamp(_) => 0x11,
            Self::QuaternionAttitudeUncertainty(_) => 0x12,
            Self::GravityVector(_) => 0x13,
            Self::HeadingUpdateState(_) => 0x14,
            Self::MagneticModel(_) => 0x15,
            Self::GyroScaleFactor(_) => 0x16,
            Self::AccelScaleFactor(_) => 0x17,
            Self::GyroScaleFactorUncertainty(_) => 0x18,
            Self::AccelScaleFactorUncertainty(_) => 0x19,
            Self::CompensatedAccel(_) => 0x1C,
            Self::StandardAtmosphere(_) => 0x20,
            Self::PressureAltitude(_) => 0x21,
            Self::MagAutoHardIronOffset(_) => 0x25,
            Self::MagAutoSoftIronMatrix(_) => 0x26,
            Self::MagAutoHardIronOffsetUncertainty(_) => 0x28,
            Self::MagAutoSoftIronMatrixUncertainty(_) => 0x29,
            Self::GnssAntennaOffsetCorrection(_) => 0x30,
            Self::GnssAntennaOffsetCorrectionUncertainty(_) => 0x31,
            Self::MultiAntennaOffsetCorrection(_) => 0x34,
            Self::MultiAntennaOffsetCorrectionUncertainty(_) => 0x35,
            Self::EcefPositionUncertainty(_) => 0x36,
            Self::EcefVelocityUncertainty(_) => 0x37,
            Self::EcefPosition(_) => 0x40,
            Self::EcefVelocity(_) => 0x41,
            Self::NedRelativePosition(_) => 0x42,
            Self::GnssPositionAidingStatus(_) => 0x43,
            Self::AidingMeasurementSummary(_) => 0x46,
            Self::OdometerScaleFactorError(_) => 0x47,
            Self::OdometerScaleFactorErrorUncertainty(_) => 0x48,
            Self::GnssDualAntennaStatus(_) => 0x49,
            Self::AidingFrameConfigError(_) => 0x50,
            Self::AidingFrameConfigErrorUncertainty(_) => 0x51,
        }
    }

    /// Field name as printed in JSON.
    pub fn name(&self) -> &'static str {
        match self {
            Self::LlhPosition(_) => "llh_position",
            Self::NedVelocity(_) => "ned_velocity",
            Self::AttitudeQuaternion(_) => "attitude_quaternion",
            Self::AttitudeDcm(_) => "attitude_dcm",
            Self::EulerAngles(_) => "euler_angles",
            Self::GyroBias(_) => "gyro_bias",
            Self::AccelBias(_) => "accel_bias",
            Self::LlhPositionUncertainty(_) => "llh_position_uncertainty",
            Self::NedVelocityUncertainty(_) => "ned_velocity_uncertainty",
            Self::EulerAnglesUncertainty(_) => "euler_angles_uncertainty",
            Self::GyroBiasUncertainty(_) => "gyro_bias_uncertainty",
            Self::AccelBiasUncertainty(_) => "accel_bias_uncertainty",
            Self::LinearAccel(_) => "linear_accel",
            Self::CompAngularRate(_) => "comp_angular_rate",
            Self::Wgs84GravityMagnitude(_) => "wgs84_gravity_magnitude",
            Self::FilterStatus(_) => "filter_status",
            Self::GpsTimestamp(_) => "gps_timestamp",
            Self::QuaternionAttitudeUncertainty(_) => "quaternion_attitude_uncertainty",
            Self::GravityVector(_) => "gravity_vector",
            Self::HeadingUpdateState(_) => "heading_update_state",
            Self::MagneticModel(_) => "magnetic_model",
            Self::GyroScaleFactor(_) => "gyro_scale_factor",
            Self::AccelScaleFactor(_) => "accel_scale_factor",
            Self::GyroScaleFactorUncertainty(_) => "gyro_scale_factor_uncertainty",
            Self::AccelScaleFactorUncertainty(_) => "accel_scale_factor_uncertainty",
            Self::CompensatedAccel(_) => "compensated_accel",
            Self::StandardAtmosphere(_) => "standard_atmosphere",
            Self::PressureAltitude(_) => "pressure_altitude",
            Self::MagAutoHardIronOffset(_) => "mag_auto_hard_iron_offset",
            Self::MagAutoSoftIronMatrix(_) => "mag_auto_soft_iron_matrix",
            Self::MagAutoHardIronOffsetUncertainty(_) => "mag_auto_hard_iron_offset_uncertainty",
            Self::MagAutoSoftIronMatrixUncertainty(_) => "mag_auto_soft_iron_matrix_uncertainty",
            Self::GnssAntennaOffsetCorrection(_) => "gnss_antenna_offset_correction",
            Self::GnssAntennaOffsetCorrectionUncertainty(_) => {
                "gnss_antenna_offset_correction_uncertainty"
            }
            Self::MultiAntennaOffsetCorrection(_) => "multi_antenna_offset_correction",
            Self::MultiAntennaOffsetCorrectionUncertainty(_) => {
                "multi_antenna_offset_correction_uncertainty"
            }
            Self::EcefPositionUncertainty(_) => "ecef_position_uncertainty",
            Self::EcefVelocityUncertainty(_) => "ecef_velocity_uncertainty",
            Self::EcefPosition(_) => "ecef_position",
            Self::EcefVelocity(_) => "ecef_velocity",
            Self::NedRelativePosition(_) => "ned_relative_position",
            Self::GnssPositionAidingStatus(_) => "gnss_position_aiding_status",
            Self::AidingMeasurementSummary(_) => "aiding_measurement_summary",
            Self::OdometerScaleFactorError(_) => "odometer_scale_factor_error",
            Self::OdometerScaleFactorErrorUncertainty(_) => {
                "odometer_scale_factor_error_uncertainty"
            }
            Self::GnssDualAntennaStatus(_) => "gnss_dual_antenna_status",
            Self::AidingFrameConfigError(_) => "aiding_frame_config_error",
            Self::AidingFrameConfigErrorUncertainty(_) => "aiding_frame_config_error_uncertainty",
        }
    }

    /// Device of the layout used, for fields with per-device layouts.
    pub fn device(&self) -> Option<crate::Device> {
        match self {
            Self::LlhPosition(_) => None,
            Self::NedVelocity(_) => None,
            Self::AttitudeQuaternion(_) => None,
            Self::AttitudeDcm(_) => None,
            Self::EulerAngles(_) => None,
            Self::GyroBias(_) => None,
            Self::AccelBias(_) => None,
            Self::LlhPositionUncertainty(_) => None,
            Self::NedVelocityUncertainty(_) => None,
            Self::EulerAnglesUncertainty(_) => None,
            Self::GyroBiasUncertainty(_) => None,
            Self::AccelBiasUncertainty(_) => None,
            Self::LinearAccel(_) => None,
            Self::CompAngularRate(_) => None,
            Self::Wgs84GravityMagnitude(_) => None,
            Self::FilterStatus(v) => Some(v.device()),
            Self::GpsTimestamp(_) => None,
            Self::QuaternionAttitudeUncertainty(_) => None,
            Self::GravityVector(_) => None,
            Self::HeadingUpdateState(_) => None,
            Self::MagneticModel(_) => None,
            Self::GyroScaleFactor(_) => None,
            Self::AccelScaleFactor(_) => None,
            Self::GyroScaleFactorUncertainty(_) => None,
            Self::AccelScaleFactorUncertainty(_) => None,
            Self::CompensatedAccel(_) => None,
            Self::StandardAtmosphere(_) => None,
            Self::PressureAltitude(_) => None,
            Self::MagAutoHardIronOffset(_) => None,
            Self::MagAutoSoftIronMatrix(_) => None,
            Self::MagAutoHardIronOffsetUncertainty(_) => None,
            Self::MagAutoSoftIronMatrixUncertainty(_) => None,
            Self::GnssAntennaOffsetCorrection(_) => None,
            Self::GnssAntennaOffsetCorrectionUncertainty(_) => None,
            Self::MultiAntennaOffsetCorrection(_) => None,
            Self::MultiAntennaOffsetCorrectionUncertainty(_) => None,
            Self::EcefPositionUncertainty(_) => None,
            Self::EcefVelocityUncertainty(_) => None,
            Self::EcefPosition(_) => None,
            Self::EcefVelocity(_) => None,
            Self::NedRelativePosition(_) => None,
            Self::GnssPositionAidingStatus(_) => None,
            Self::AidingMeasurementSummary(_) => None,
            Self::OdometerScaleFactorError(_) => None,
            Self::OdometerScaleFactorErrorUncertainty(_) => None,
            Self::GnssDualAntennaStatus(_) => None,
            Self::AidingFrameConfigError(_) => None,
            Self::AidingFrameConfigErrorUncertainty(_) => None,
        }
    }

    /// Encodes the field data.
    pub fn encode_data(
        &self,
        w: &mut crate::wire::Writer<'_>,
    ) -> Result<(), crate::error::EncodeError> {
        match self {
            Self::LlhPosition(v) => crate::wire::Layout::encode_data(v, w),
            Self::NedVelocity(v) => crate::wire::Layout::encode_data(v, w),
            Self::AttitudeQuaternion(v) => crate::wire::Layout::encode_data(v, w),
            Self::AttitudeDcm(v) => crate::wire::Layout::encode_data(v, w),
            Self::EulerAngles(v) => crate::wire::Layout::encode_data(v, w),
            Self::GyroBias(v) => crate::wire::Layout::encode_data(v, w),
            Self::AccelBias(v) => crate::wire::Layout::encode_data(v, w),
            Self::LlhPositionUncertainty(v) => crate::wire::Layout::encode_data(v, w),
            Self::NedVelocityUncertainty(v) => crate::wire::Layout::encode_data(v, w),
            Self::EulerAnglesUncertainty(v) => crate::wire::Layout::encode_data(v, w),
            Self::GyroBiasUncertainty(v) => crate::wire::Layout::encode_data(v, w),
            Self::AccelBiasUncertainty(v) => crate::wire::Layout::encode_data(v, w),
            Self::LinearAccel(v) => crate::wire::Layout::encode_data(v, w),
            Self::CompAngularRate(v) => crate::wire::Layout::encode_data(v, w),
            Self::Wgs84GravityMagnitude(v) => crate::wire::Layout::encode_data(v, w),
            Self::FilterStatus(v) => v.encode_data(w),
            Self::GpsTimestamp(v) => crate::wire::Layout::encode_data(v, w),
            Self::QuaternionAttitudeUncertainty(v) => crate::wire::Layout::encode_data(v, w),
            Self::GravityVector(v) => crate::wire::Layout::encode_data(v, w),
            Self::HeadingUpdateState(v) => crate::wire::Layout::encode_data(v, w),
            Self::MagneticModel(v) => crate::wire::Layout::encode_data(v, w),
            Self::GyroScaleFactor(v) => crate::wire::Layout::encode_data(v, w),
            Self::AccelScaleFactor(v) => crate::wire::Layout::encode_data(v, w),
            Self::GyroScaleFactorUncertainty(v) => crate::wire::Layout::encode_data(v, w),
            Self::AccelScaleFactorUncertainty(v) => crate::wire::Layout::encode_data(v, w),
            Self::CompensatedAccel(v) => crate::wire::Layout::encode_data(v, w),
            Self::StandardAtmosphere(v) => crate::wire::Layout::encode_data(v, w),
            Self::PressureAltitude(v) => crate::wire::Layout::encode_data(v, w),
            Self::MagAutoHardIronOffset(v) => crate::wire::Layout::encode_data(v, w),
            Self::MagAutoSoftIronMatrix(v) => crate::wire::Layout::encode_data(v, w),
            Self::MagAutoHardIronOffsetUncertainty(v) => crate::wire::Layout::encode_data(v, w),
            Self::MagAutoSoftIronMatrixUncertainty(v) => crate::wire::Layout::encode_data(v, w),
            Self::GnssAntennaOffsetCorrection(v) => crate::wire::Layout::encode_data(v, w),
            Self::GnssAntennaOffsetCorrectionUncertainty(v) => {
                crate::wire::Layout::encode_data(v, w)
            }
            Self::MultiAntennaOffsetCorrection(v) => crate::wire::Layout::encode_data(v, w),
            Self::MultiAntennaOffsetCorrectionUncertainty(v) => {
                crate::wire::Layout::encode_data(v, w)
            }
            Self::EcefPositionUncertainty(v) => crate::wire::Layout::encode_data(v, w),
            Self::EcefVelocityUncertainty(v) => crate::wire::Layout::encode_data(v, w),
            Self::EcefPosition(v) => crate::wire::Layout::encode_data(v, w),
            Self::EcefVelocity(v) => crate::wire::Layout::encode_data(v, w),
            Self::NedRelativePosition(v) => crate::wire::Layout::encode_data(v, w),
            Self::GnssPositionAidingStatus(v) => crate::wire::Layout::encode_data(v, w),
            Self::AidingMeasurementSummary(v) => crate::wire::Layout::encode_data(v, w),
            Self::OdometerScaleFactorError(v) => crate::wire::Layout::encode_data(v, w),
            Self::OdometerScaleFactorErrorUncertainty(v) => crate::wire::Layout::encode_data(v, w),
            Self::GnssDualAntennaStatus(v) => crate::wire::Layout::encode_data(v, w),
            Self::AidingFrameConfigError(v) => crate::wire::Layout::encode_data(v, w),
            Self::AidingFrameConfigErrorUncertainty(v) => crate::wire::Layout::encode_data(v, w),
        }
    }

    /// Writes the canonical JSON of the values (`{...}`).
    pub fn write_values_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::LlhPosition(v) => crate::wire::Wire::write_json(v, w),
            Self::NedVelocity(v) => crate::wire::Wire::write_json(v, w),
            Self::AttitudeQuaternion(v) => crate::wire::Wire::write_json(v, w),
            Self::AttitudeDcm(v) => crate::wire::Wire::write_json(v, w),
            Self::EulerAngles(v) => crate::wire::Wire::write_json(v, w),
            Self::GyroBias(v) => crate::wire::Wire::write_json(v, w),
            Self::AccelBias(v) => crate::wire::Wire::write_json(v, w),
            Self::LlhPositionUncertainty(v) => crate::wire::Wire::write_json(v, w),
            Self::NedVelocityUncertainty(v) => crate::wire::Wire::write_json(v, w),
            Self::EulerAnglesUncertainty(v) => crate::wire::Wire::write_json(v, w),
            Self::GyroBiasUncertainty(v) => crate::wire::Wire::write_json(v, w),
            Self::AccelBiasUncertainty(v) => crate::wire::Wire::write_json(v, w),
            Self::LinearAccel(v) => crate::wire::Wire::write_json(v, w),
            Self::CompAngularRate(v) => crate::wire::Wire::write_json(v, w),
            Self::Wgs84GravityMagnitude(v) => crate::wire::Wire::write_json(v, w),
            Self::FilterStatus(v) => v.write_json(w),
            Self::GpsTimestamp(v) => crate::wire::Wire::write_json(v, w),
            Self::QuaternionAttitudeUncertainty(v) => crate::wire::Wire::write_json(v, w),
            Self::GravityVector(v) => crate::wire::Wire::write_json(v, w),
            Self::HeadingUpdateState(v) => crate::wire::Wire::write_json(v, w),
            Self::MagneticModel(v) => crate::wire::Wire::write_json(v, w),
            Self::GyroScaleFactor(v) => crate::wire::Wire::write_json(v, w),
            Self::AccelScaleFactor(v) => crate::wire::Wire::write_json(v, w),
            Self::GyroScaleFactorUncertainty(v) => crate::wire::Wire::write_json(v, w),
            Self::AccelScaleFactorUncertainty(v) => crate::wire::Wire::write_json(v, w),
            Self::CompensatedAccel(v) => crate::wire::Wire::write_json(v, w),
            Self::StandardAtmosphere(v) => crate::wire::Wire::write_json(v, w),
            Self::PressureAltitude(v) => crate::wire::Wire::write_json(v, w),
            Self::MagAutoHardIronOffset(v) => crate::wire::Wire::write_json(v, w),
            Self::MagAutoSoftIronMatrix(v) => crate::wire::Wire::write_json(v, w),
            Self::MagAutoHardIronOffsetUncertainty(v) => crate::wire::Wire::write_json(v, w),
            Self::MagAutoSoftIronMatrixUncertainty(v) => crate::wire::Wire::write_json(v, w),
            Self::GnssAntennaOffsetCorrection(v) => crate::wire::Wire::write_json(v, w),
            Self::GnssAntennaOffsetCorrectionUncertainty(v) => crate::wire::Wire::write_json(v, w),
            Self::MultiAntennaOffsetCorrection(v) => crate::wire::Wire::write_json(v, w),
            Self::MultiAntennaOffsetCorrectionUncertainty(v) => crate::wire::Wire::write_json(v, w),
            Self::EcefPositionUncertainty(v) => crate::wire::Wire::write_json(v, w),
            Self::EcefVelocityUncertainty(v) => crate::wire::Wire::write_json(v, w),
            Self::EcefPosition(v) => crate::wire::Wire::write_json(v, w),
            Self::EcefVelocity(v) => crate::wire::Wire::write_json(v, w),
            Self::NedRelativePosition(v) => crate::wire::Wire::write_json(v, w),
            Self::GnssPositionAidingStatus(v) => crate::wire::Wire::write_json(v, w),
            Self::AidingMeasurementSummary(v) => crate::wire::Wire::write_json(v, w),
            Self::OdometerScaleFactorError(v) => crate::wire::Wire::write_json(v, w),
            Self::OdometerScaleFactorErrorUncertainty(v) => crate::wire::Wire::write_json(v, w),
            Self::GnssDualAntennaStatus(v) => crate::wire::Wire::write_json(v, w),
            Self::AidingFrameConfigError(v) => crate::wire::Wire::write_json(v, w),
            Self::AidingFrameConfigErrorUncertainty(v) => crate::wire::Wire::write_json(v, w),
        }
    }

    /// Decodes field `descriptor` of this set; `None` if the set has no such field.
    pub fn decode(
        descriptor: u8,
        data: &[u8],
        device: Option<crate::Device>,
    ) -> Option<Result<Self, crate::error::DecodeError>> {
        match descriptor {
            0x01 => {
                Some(<LlhPosition as crate::wire::Layout>::decode_data(data).map(Self::LlhPosition))
            }
            0x02 => {
                Some(<NedVelocity as crate::wire::Layout>::decode_data(data).map(Self::NedVelocity))
            }
            0x03 => Some(
                <AttitudeQuaternion as crate::wire::Layout>::decode_data(data)
                    .map(Self::AttitudeQuaternion),
            ),
            0x04 => {
                Some(<AttitudeDcm as crate::wire::Layout>::decode_data(data).map(Self::AttitudeDcm))
            }
            0x05 => {
                Some(<EulerAngles as crate::wire::Layout>::decode_data(data).map(Self::EulerAngles))
            }
            0x06 => Some(<GyroBias as crate::wire::Layout>::decode_data(data).map(Self::GyroBias)),
            0x07 => {
                Some(<AccelBias as crate::wire::Layout>::decode_data(data).map(Self::AccelBias))
            }
            0x08 => Some(
                <LlhPositionUncertainty as crate::wire::Layout>::decode_data(data)
                    .map(Self::LlhPositionUncertainty),
            ),
            0x09 => Some(
                <NedVelocityUncertainty as crate::wire::Layout>::decode_data(data)
                    .map(Self::NedVelocityUncertainty),
            ),
            0x0A => Some(
                <EulerAnglesUncertainty as crate::wire::Layout>::decode_data(data)
                    .map(Self::EulerAnglesUncertainty),
            ),
            0x0B => Some(
                <GyroBiasUncertainty as crate::wire::Layout>::decode_data(data)
                    .map(Self::GyroBiasUncertainty),
            ),
            0x0C => Some(
                <AccelBiasUncertainty as crate::wire::Layout>::decode_data(data)
                    .map(Self::AccelBiasUncertainty),
            ),
            0x0D => {
                Some(<LinearAccel as crate::wire::Layout>::decode_data(data).map(Self::LinearAccel))
            }
            0x0E => Some(
                <CompAngularRate as crate::wire::Layout>::decode_data(data)
                    .map(Self::CompAngularRate),
            ),
            0x0F => Some(
                <Wgs84GravityMagnitude as crate::wire::Layout>::decode_data(data)
                    .map(Self::Wgs84GravityMagnitude),
            ),
            0x10 => Some(FilterStatus::decode_data(data, device).map(Self::FilterStatus)),
            0x11 => Some(
                <GpsTimestamp as crate::wire::Layout>::decode_data(data).map(Self::GpsTimestamp),
            ),
            0x12 => Some(
                <QuaternionAttitudeUncertainty as crate::wire::Layout>::decode_data(data)
                    .map(Self::QuaternionAttitudeUncertainty),
            ),
            0x13 => Some(
                <GravityVector as crate::wire::Layout>::decode_data(data).map(Self::GravityVector),
            ),
            0x14 => Some(
                <HeadingUpdateState as crate::wire::Layout>::decode_data(data)
                    .map(Self::HeadingUpdateState),
            ),
            0x15 => Some(
                <MagneticModel as crate::wire::Layout>::decode_data(data).map(Self::MagneticModel),
            ),
            0x16 => Some(
                <GyroScaleFactor as crate::wire::Layout>::decode_data(data)
                    .map(Self::GyroScaleFactor),
            ),
            0x17 => Some(
                <AccelScaleFactor as crate::wire::Layout>::decode_data(data)
                    .map(Self::AccelScaleFactor),
            ),
            0x18 => Some(
                <GyroScaleFactorUncertainty as crate::wire::Layout>::decode_data(data)
                    .map(Self::GyroScaleFactorUncertainty),
            ),
            0x19 => Some(
                <AccelScaleFactorUncertainty as crate::wire::Layout>::decode_data(data)
                    .map(Self::AccelScaleFactorUncertainty),
            ),
            0x1C => Some(
                <CompensatedAccel as crate::wire::Layout>::decode_data(data)
                    .map(Self::CompensatedAccel),
            ),
            0x20 => Some(
                <StandardAtmosphere as crate::wire::Layout>::decode_data(data)
                    .map(Self::StandardAtmosphere),
            ),
            0x21 => Some(
                <PressureAltitude as crate::wire::Layout>::decode_data(data)
                    .map(Self::PressureAltitude),
            ),
            0x25 => Some(
                <MagAutoHardIronOffset as crate::wire::Layout>::decode_data(data)
                    .map(Self::MagAutoHardIronOffset),
            ),
            0x26 => Some(
                <MagAutoSoftIronMatrix as crate::wire::Layout>::decode_data(data)
                    .map(Self::MagAutoSoftIronMatrix),
            ),
            0x28 => Some(
                <MagAutoHardIronOffsetUncertainty as crate::wire::Layout>::decode_data(data)
                    .map(Self::MagAutoHardIronOffsetUncertainty),
            ),
            0x29 => Some(
                <MagAutoSoftIronMatrixUncertainty as crate::wire::Layout>::decode_data(data)
                    .map(Self::MagAutoSoftIronMatrixUncertainty),
            ),
            0x30 => Some(
                <GnssAntennaOffsetCorrection as crate::wire::Layout>::decode_data(data)
                    .map(Self::GnssAntennaOffsetCorrection),
            ),
            0x31 => Some(
                <GnssAntennaOffsetCorrectionUncertainty as crate::wire::Layout>::decode_data(data)
                    .map(Self::GnssAntennaOffsetCorrectionUncertainty),
            ),
            0x34 => Some(
                <MultiAntennaOffsetCorrection as crate::wire::Layout>::decode_data(data)
                    .map(Self::MultiAntennaOffsetCorrection),
            ),
            0x35 => Some(
                <MultiAntennaOffsetCorrectionUncertainty as crate::wire::Layout>::decode_data(data)
                    .map(Self::MultiAntennaOffsetCorrectionUncertainty),
            ),
            0x36 => Some(
                <EcefPositionUncertainty as crate::wire::Layout>::decode_data(data)
                    .map(Self::EcefPositionUncertainty),
            ),
            0x37 => Some(
                <EcefVelocityUncertainty as crate::wire::Layout>::decode_data(data)
                    .map(Self::EcefVelocityUncertainty),
            ),
            0x40 => Some(
                <EcefPosition as crate::wire::Layout>::decode_data(data).map(Self::EcefPosition),
            ),
            0x41 => Some(
                <EcefVelocity as crate::wire::Layout>::decode_data(data).map(Self::EcefVelocity),
            ),
            0x42 => Some(
                <NedRelativePosition as crate::wire::Layout>::decode_data(data)
                    .map(Self::NedRelativePosition),
            ),
            0x43 => Some(
                <GnssPositionAidingStatus as crate::wire::Layout>::decode_data(data)
                    .map(Self::GnssPositionAidingStatus),
            ),
            0x46 => Some(
                <AidingMeasurementSummary as crate::wire::Layout>::decode_data(data)
                    .map(Self::AidingMeasurementSummary),
            ),
            0x47 => Some(
                <OdometerScaleFactorError as crate::wire::Layout>::decode_data(data)
                    .map(Self::OdometerScaleFactorError),
            ),
            0x48 => Some(
                <OdometerScaleFactorErrorUncertainty as crate::wire::Layout>::decode_data(data)
                    .map(Self::OdometerScaleFactorErrorUncertainty),
            ),
            0x49 => Some(
                <GnssDualAntennaStatus as crate::wire::Layout>::decode_data(data)
                    .map(Self::GnssDualAntennaStatus),
            ),
            0x50 => Some(
                <AidingFrameConfigError as crate::wire::Layout>::decode_data(data)
                    .map(Self::AidingFrameConfigError),
            ),
            0x51 => Some(
                <AidingFrameConfigErrorUncertainty as crate::wire::Layout>::decode_data(data)
                    .map(Self::AidingFrameConfigErrorUncertainty),
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
                        <LlhPosition as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::LlhPosition),
            ),
            0x02 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <NedVelocity as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::NedVelocity),
            ),
            0x03 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AttitudeQuaternion as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::AttitudeQuaternion),
            ),
            0x04 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AttitudeDcm as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::AttitudeDcm),
            ),
            0x05 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <EulerAngles as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::EulerAngles),
            ),
            0x06 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GyroBias as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GyroBias),
            ),
            0x07 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AccelBias as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::AccelBias),
            ),
            0x08 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <LlhPositionUncertainty as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::LlhPositionUncertainty),
            ),
            0x09 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <NedVelocityUncertainty as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::NedVelocityUncertainty),
            ),
            0x0A => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <EulerAnglesUncertainty as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::EulerAnglesUncertainty),
            ),
            0x0B => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GyroBiasUncertainty as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GyroBiasUncertainty),
            ),
            0x0C => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AccelBiasUncertainty as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::AccelBiasUncertainty),
            ),
            0x0D => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <LinearAccel as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::LinearAccel),
            ),
            0x0E => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <CompAngularRate as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::CompAngularRate),
            ),
            0x0F => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <Wgs84GravityMagnitude as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::Wgs84GravityMagnitude),
            ),
            0x10 => Some(FilterStatus::from_json(device, values).map(Self::FilterStatus)),
            0x11 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GpsTimestamp as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GpsTimestamp),
            ),
            0x12 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <QuaternionAttitudeUncertainty as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::QuaternionAttitudeUncertainty),
            ),
            0x13 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GravityVector as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GravityVector),
            ),
            0x14 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <HeadingUpdateState as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::HeadingUpdateState),
            ),
            0x15 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <MagneticModel as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::MagneticModel),
            ),
            0x16 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GyroScaleFactor as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GyroScaleFactor),
            ),
            0x17 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AccelScaleFactor as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::AccelScaleFactor),
            ),
            0x18 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GyroScaleFactorUncertainty as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GyroScaleFactorUncertainty),
            ),
            0x19 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AccelScaleFactorUncertainty as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::AccelScaleFactorUncertainty),
            ),
            0x1C => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <CompensatedAccel as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::CompensatedAccel),
            ),
            0x20 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <StandardAtmosphere as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::StandardAtmosphere),
            ),
            0x21 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <PressureAltitude as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::PressureAltitude),
            ),
            0x25 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <MagAutoHardIronOffset as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::MagAutoHardIronOffset),
            ),
            0x26 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <MagAutoSoftIronMatrix as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::MagAutoSoftIronMatrix),
            ),
            0x28 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <MagAutoHardIronOffsetUncertainty as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::MagAutoHardIronOffsetUncertainty),
            ),
            0x29 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <MagAutoSoftIronMatrixUncertainty as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::MagAutoSoftIronMatrixUncertainty),
            ),
            0x30 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GnssAntennaOffsetCorrection as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GnssAntennaOffsetCorrection),
            ),
            0x31 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GnssAntennaOffsetCorrectionUncertainty as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GnssAntennaOffsetCorrectionUncertainty),
            ),
            0x34 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <MultiAntennaOffsetCorrection as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::MultiAntennaOffsetCorrection),
            ),
            0x35 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <MultiAntennaOffsetCorrectionUncertainty as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::MultiAntennaOffsetCorrectionUncertainty),
            ),
            0x36 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <EcefPositionUncertainty as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::EcefPositionUncertainty),
            ),
            0x37 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <EcefVelocityUncertainty as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::EcefVelocityUncertainty),
            ),
            0x40 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <EcefPosition as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::EcefPosition),
            ),
            0x41 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <EcefVelocity as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::EcefVelocity),
            ),
            0x42 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <NedRelativePosition as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::NedRelativePosition),
            ),
            0x43 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GnssPositionAidingStatus as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GnssPositionAidingStatus),
            ),
            0x46 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AidingMeasurementSummary as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::AidingMeasurementSummary),
            ),
            0x47 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <OdometerScaleFactorError as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::OdometerScaleFactorError),
            ),
            0x48 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <OdometerScaleFactorErrorUncertainty as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::OdometerScaleFactorErrorUncertainty),
            ),
            0x49 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GnssDualAntennaStatus as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GnssDualAntennaStatus),
            ),
            0x50 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AidingFrameConfigError as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::AidingFrameConfigError),
            ),
            0x51 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AidingFrameConfigErrorUncertainty as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::AidingFrameConfigErrorUncertainty),
            ),
            _ => None,
        }
    }
}

/// The fields of one packet of this set, decoded in place by [`decode_packet`]: one member per
/// field of the set with one layout (its own and the shared data fields); `index` says which members hold a field of the last packet, in packet order
/// (the others hold whatever they held).
#[cfg(any(feature = "set-filter-data", not(feature = "select-sets")))]
#[derive(Clone, Debug)]
pub struct Packet {
    /// The fields decoded into their members, in packet order.
    pub index: crate::packets::PacketIndex,
    /// Field 0x01.
    pub llh_position: crate::filter_data::LlhPosition,
    /// Field 0x02.
    pub ned_velocity: crate::filter_data::NedVelocity,
    /// Field 0x03.
    pub attitude_quaternion: crate::filter_data::AttitudeQuaternion,
    /// Field 0x04.
    pub attitude_dcm: crate::filter_data::AttitudeDcm,
    /// Field 0x05.
    pub euler_angles: crate::filter_data::EulerAngles,
    /// Field 0x06.
    pub gyro_bias: crate::filter_data::GyroBias,
    /// Field 0x07.
    pub accel_bias: crate::filter_data::AccelBias,
    /// Field 0x08.
    pub llh_position_uncertainty: crate::filter_data::LlhPositionUncertainty,
    /// Field 0x09.
    pub ned_velocity_uncertainty: crate::filter_data::NedVelocityUncertainty,
    /// Field 0x0A.
    pub euler_angles_uncertainty: crate::filter_data::EulerAnglesUncertainty,
    /// Field 0x0B.
    pub gyro_bias_uncertainty: crate::filter_data::GyroBiasUncertainty,
    /// Field 0x0C.
    pub accel_bias_uncertainty: crate::filter_data::AccelBiasUncertainty,
    /// Field 0x0D.
    pub linear_accel: crate::filter_data::LinearAccel,
    /// Field 0x0E.
    pub comp_angular_rate: crate::filter_data::CompAngularRate,
    /// Field 0x0F.
    pub wgs84_gravity_magnitude: crate::filter_data::Wgs84GravityMagnitude,
    /// Field 0x11.
    pub filter_data_gps_timestamp: crate::filter_data::GpsTimestamp,
    /// Field 0x12.
    pub quaternion_attitude_uncertainty: crate::filter_data::QuaternionAttitudeUncertainty,
    /// Field 0x13.
    pub gravity_vector: crate::filter_data::GravityVector,
    /// Field 0x14.
    pub heading_update_state: crate::filter_data::HeadingUpdateState,
    /// Field 0x15.
    pub magnetic_model: crate::filter_data::MagneticModel,
    /// Field 0x16.
    pub gyro_scale_factor: crate::filter_data::GyroScaleFactor,
    /// Field 0x17.
    pub accel_scale_factor: crate::filter_data::AccelScaleFactor,
    /// Field 0x18.
    pub gyro_scale_factor_uncertainty: crate::filter_data::GyroScaleFactorUncertainty,
    /// Field 0x19.
    pub accel_scale_factor_uncertainty: crate::filter_data::AccelScaleFactorUncertainty,
    /// Field 0x1C.
    pub compensated_accel: crate::filter_data::CompensatedAccel,
    /// Field 0x20.
    pub standard_atmosphere: crate::filter_data::StandardAtmosphere,
    /// Field 0x21.
    pub pressure_altitude: crate::filter_data::PressureAltitude,
    /// Field 0x25.
    pub mag_auto_hard_iron_offset: crate::filter_data::MagAutoHardIronOffset,
    /// Field 0x26.
    pub mag_auto_soft_iron_matrix: crate::filter_data::MagAutoSoftIronMatrix,
    /// Field 0x28.
    pub mag_auto_hard_iron_offset_uncertainty: crate::filter_data::MagAutoHardIronOffsetUncertainty,
    /// Field 0x29.
    pub mag_auto_soft_iron_matrix_uncertainty: crate::filter_data::MagAutoSoftIronMatrixUncertainty,
    /// Field 0x30.
    pub gnss_antenna_offset_correction: crate::filter_data::GnssAntennaOffsetCorrection,
    /// Field 0x31.
    pub gnss_antenna_offset_correction_uncertainty:
        crate::filter_data::GnssAntennaOffsetCorrectionUncertainty,
    /// Field 0x34.
    pub multi_antenna_offset_correction: crate::filter_data::MultiAntennaOffsetCorrection,
    /// Field 0x35.
    pub multi_antenna_offset_correction_uncertainty:
        crate::filter_data::MultiAntennaOffsetCorrectionUncertainty,
    /// Field 0x36.
    pub ecef_position_uncertainty: crate::filter_data::EcefPositionUncertainty,
    /// Field 0x37.
    pub ecef_velocity_uncertainty: crate::filter_data::EcefVelocityUncertainty,
    /// Field 0x40.
    pub ecef_position: crate::filter_data::EcefPosition,
    /// Field 0x41.
    pub ecef_velocity: crate::filter_data::EcefVelocity,
    /// Field 0x42.
    pub ned_relative_position: crate::filter_data::NedRelativePosition,
    /// Field 0x43.
    pub gnss_position_aiding_status: crate::filter_data::GnssPositionAidingStatus,
    /// Field 0x46.
    pub aiding_measurement_summary: crate::filter_data::AidingMeasurementSummary,
    /// Field 0x47.
    pub odometer_scale_factor_error: crate::filter_data::OdometerScaleFactorError,
    /// Field 0x48.
    pub odometer_scale_factor_error_uncertainty:
        crate::filter_data::OdometerScaleFactorErrorUncertainty,
    /// Field 0x49.
    pub gnss_dual_antenna_status: crate::filter_data::GnssDualAntennaStatus,
    /// Field 0x50.
    pub aiding_frame_config_error: crate::filter_data::AidingFrameConfigError,
    /// Field 0x51.
    pub aiding_frame_config_error_uncertainty:
        crate::filter_data::AidingFrameConfigErrorUncertainty,
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

#[cfg(any(feature = "set-filter-data", not(feature = "select-sets")))]
impl Packet {
    /// Nothing decoded, every member zero.
    pub const ZERO: Self = Self {
        index: crate::packets::PacketIndex::EMPTY,
        llh_position: <crate::filter_data::LlhPosition as crate::wire::Wire>::ZERO,
        ned_velocity: <crate::filter_data::NedVelocity as crate::wire::Wire>::ZERO,
        attitude_quaternion: <crate::filter_data::AttitudeQuaternion as crate::wire::Wire>::ZERO,
        attitude_dcm: <crate::filter_data::AttitudeDcm as crate::wire::Wire>::ZERO,
        euler_angles: <crate::filter_data::EulerAngles as crate::wire::Wire>::ZERO,
        gyro_bias: <crate::filter_data::GyroBias as crate::wire::Wire>::ZERO,
        accel_bias: <crate::filter_data::AccelBias as crate::wire::Wire>::ZERO,
        llh_position_uncertainty:
            <crate::filter_data::LlhPositionUncertainty as crate::wire::Wire>::ZERO,
        ned_velocity_uncertainty:
            <crate::filter_data::NedVelocityUncertainty as crate::wire::Wire>::ZERO,
        euler_angles_uncertainty:
            <crate::filter_data::EulerAnglesUncertainty as crate::wire::Wire>::ZERO,
        gyro_bias_uncertainty: <crate::filter_data::GyroBiasUncertainty as crate::wire::Wire>::ZERO,
        accel_bias_uncertainty:
            <crate::filter_data::AccelBiasUncertainty as crate::wire::Wire>::ZERO,
        linear_accel: <crate::filter_data::LinearAccel as crate::wire::Wire>::ZERO,
        comp_angular_rate: <crate::filter_data::CompAngularRate as crate::wire::Wire>::ZERO,
        wgs84_gravity_magnitude:
            <crate::filter_data::Wgs84GravityMagnitude as crate::wire::Wire>::ZERO,
        filter_data_gps_timestamp: <crate::filter_data::GpsTimestamp as crate::wire::Wire>::ZERO,
        quaternion_attitude_uncertainty:
            <crate::filter_data::QuaternionAttitudeUncertainty as crate::wire::Wire>::ZERO,
        gravity_vector: <crate::filter_data::GravityVector as crate::wire::Wire>::ZERO,
        heading_update_state: <crate::filter_data::HeadingUpdateState as crate::wire::Wire>::ZERO,
        magnetic_model: <crate::filter_data::MagneticModel as crate::wire::Wire>::ZERO,
        gyro_scale_factor: <crate::filter_data::GyroScaleFactor as crate::wire::Wire>::ZERO,
        accel_scale_factor: <crate::filter_data::AccelScaleFactor as crate::wire::Wire>::ZERO,
        gyro_scale_factor_uncertainty:
            <crate::filter_data::GyroScaleFactorUncertainty as crate::wire::Wire>::ZERO,
        accel_scale_factor_uncertainty:
            <crate::filter_data::AccelScaleFactorUncertainty as crate::wire::Wire>::ZERO,
        compensated_accel: <crate::filter_data::CompensatedAccel as crate::wire::Wire>::ZERO,
        standard_atmosphere: <crate::filter_data::StandardAtmosphere as crate::wire::Wire>::ZERO,
        pressure_altitude: <crate::filter_data::PressureAltitude as crate::wire::Wire>::ZERO,
        mag_auto_hard_iron_offset:
            <crate::filter_data::MagAutoHardIronOffset as crate::wire::Wire>::ZERO,
        mag_auto_soft_iron_matrix:
            <crate::filter_data::MagAutoSoftIronMatrix as crate::wire::Wire>::ZERO,
        mag_auto_hard_iron_offset_uncertainty:
            <crate::filter_data::MagAutoHardIronOffsetUncertainty as crate::wire::Wire>::ZERO,
        mag_auto_soft_iron_matrix_uncertainty:
            <crate::filter_data::MagAutoSoftIronMatrixUncertainty as crate::wire::Wire>::ZERO,
        gnss_antenna_offset_correction:
            <crate::filter_data::GnssAntennaOffsetCorrection as crate::wire::Wire>::ZERO,
        gnss_antenna_offset_correction_uncertainty:
            <crate::filter_data::GnssAntennaOffsetCorrectionUncertainty as crate::wire::Wire>::ZERO,
        multi_antenna_offset_correction:
            <crate::filter_data::MultiAntennaOffsetCorrection as crate::wire::Wire>::ZERO,
        multi_antenna_offset_correction_uncertainty:
            <crate::filter_data::MultiAntennaOffsetCorrectionUncertainty as crate::wire::Wire>::ZERO,
        ecef_position_uncertainty:
            <crate::filter_data::EcefPositionUncertainty as crate::wire::Wire>::ZERO,
        ecef_velocity_uncertainty:
            <crate::filter_data::EcefVelocityUncertainty as crate::wire::Wire>::ZERO,
        ecef_position: <crate::filter_data::EcefPosition as crate::wire::Wire>::ZERO,
        ecef_velocity: <crate::filter_data::EcefVelocity as crate::wire::Wire>::ZERO,
        ned_relative_position: <crate::filter_data::NedRelativePosition as crate::wire::Wire>::ZERO,
        gnss_position_aiding_status:
            <crate::filter_data::GnssPositionAidingStatus as crate::wire::Wire>::ZERO,
        aiding_measurement_summary:
            <crate::filter_data::AidingMeasurementSummary as crate::wire::Wire>::ZERO,
        odometer_scale_factor_error:
            <crate::filter_data::OdometerScaleFactorError as crate::wire::Wire>::ZERO,
        odometer_scale_factor_error_uncertainty:
            <crate::filter_data::OdometerScaleFactorErrorUncertainty as crate::wire::Wire>::ZERO,
        gnss_dual_antenna_status:
            <crate::filter_data::GnssDualAntennaStatus as crate::wire::Wire>::ZERO,
        aiding_frame_config_error:
            <crate::filter_data::AidingFrameConfigError as crate::wire::Wire>::ZERO,
        aiding_frame_config_error_uncertainty:
            <crate::filter_data::AidingFrameConfigErrorUncertainty as crate::wire::Wire>::ZERO,
        event_source: <crate::shared::EventSource as crate::wire::Wire>::ZERO,
        shared_gps_timestamp: <crate::shared::GpsTimestamp as crate::wire::Wire>::ZERO,
        delta_time: <crate::shared::DeltaTime as crate::wire::Wire>::ZERO,
        reference_timestamp: <crate::shared::ReferenceTimestamp as crate::wire::Wire>::ZERO,
        reference_time_delta: <crate::shared::ReferenceTimeDelta as crate::wire::Wire>::ZERO,
        external_timestamp: <crate::shared::ExternalTimestamp as crate::wire::Wire>::ZERO,
        external_time_delta: <crate::shared::ExternalTimeDelta as crate::wire::Wire>::ZERO,
    };
}

#[cfg(any(feature = "set-filter-data", not(feature = "select-sets")))]
impl Default for Packet {
    fn default() -> Self {
        Self::ZERO
    }
}

#[cfg(any(feature = "set-filter-data", not(feature = "select-sets")))]
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
            0x01 | 0x02
                | 0x03
                | 0x04
                | 0x05
                | 0x06
                | 0x07
                | 0x08
                | 0x09
                | 0x0A
                | 0x0B
                | 0x0C
                | 0x0D
                | 0x0E
                | 0x0F
                | 0x11
                | 0x12
                | 0x13
                | 0x14
                | 0x15
                | 0x16
                | 0x17
                | 0x18
                | 0x19
                | 0x1C
                | 0x20
                | 0x21
                | 0x25
                | 0x26
                | 0x28
                | 0x29
                | 0x30
                | 0x31
                | 0x34
                | 0x35
                | 0x36
                | 0x37
                | 0x40
                | 0x41
                | 0x42
                | 0x43
                | 0x46
                | 0x47
                | 0x48
                | 0x49
                | 0x50
                | 0x51
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
            0x01 => match <&[u8; 26]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.llh_position;
                    s.latitude = crate::packets::ld(d, 0);
                    s.longitude = crate::packets::ld(d, 8);
                    s.ellipsoid_height = crate::packets::ld(d, 16);
                    s.valid_flags = crate::packets::ld(d, 24);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.llh_position),
            },
            0x02 => match <&[u8; 14]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.ned_velocity;
                    s.north = crate::packets::ld(d, 0);
                    s.east = crate::packets::ld(d, 4);
                    s.down = crate::packets::ld(d, 8);
                    s.valid_flags = crate::packets::ld(d, 12);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.ned_velocity),
            },
            0x03 => match <&[u8; 18]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.attitude_quaternion;
                    s.q[0] = crate::packets::ld(d, 0);
                    s.q[1] = crate::packets::ld(d, 4);
                    s.q[2] = crate::packets::ld(d, 8);
                    s.q[3] = crate::packets::ld(d, 12);
                    s.valid_flags = crate::packets::ld(d, 16);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.attitude_quaternion),
            },
            0x04 => match <&[u8; 38]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.attitude_dcm;
                    s.dcm[0] = crate::packets::ld(d, 0);
                    s.dcm[1] = crate::packets::ld(d, 4);
                    s.dcm[2] = crate::packets::ld(d, 8);
                    s.dcm[3] = crate::packets::ld(d, 12);
                    s.dcm[4] = crate::packets::ld(d, 16);
                    s.dcm[5] = crate::packets::ld(d, 20);
                    s.dcm[6] = crate::packets::ld(d, 24);
                    s.dcm[7] = crate::packets::ld(d, 28);
                    s.dcm[8] = crate::packets::ld(d, 32);
                    s.valid_flags = crate::packets::ld(d, 36);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.attitude_dcm),
            },
            0x05 => match <&[u8; 14]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.euler_angles;
                    s.roll = crate::packets::ld(d, 0);
                    s.pitch = crate::packets::ld(d, 4);
                    s.yaw = crate::packets::ld(d, 8);
                    s.valid_flags = crate::packets::ld(d, 12);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.euler_angles),
            },
            0x06 => match <&[u8; 14]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.gyro_bias;
                    s.bias[0] = crate::packets::ld(d, 0);
                    s.bias[1] = crate::packets::ld(d, 4);
                    s.bias[2] = crate::packets::ld(d, 8);
                    s.valid_flags = crate::packets::ld(d, 12);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.gyro_bias),
            },
            0x07 => match <&[u8; 14]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.accel_bias;
                    s.bias[0] = crate::packets::ld(d, 0);
                    s.bias[1] = crate::packets::ld(d, 4);
                    s.bias[2] = crate::packets::ld(d, 8);
                    s.valid_flags = crate::packets::ld(d, 12);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.accel_bias),
            },
            0x08 => match <&[u8; 14]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.llh_position_uncertainty;
                    s.north = crate::packets::ld(d, 0);
                    s.east = crate::packets::ld(d, 4);
                    s.down = crate::packets::ld(d, 8);
                    s.valid_flags = crate::packets::ld(d, 12);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.llh_position_uncertainty),
            },
            0x09 => match <&[u8; 14]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.ned_velocity_uncertainty;
                    s.north = crate::packets::ld(d, 0);
                    s.east = crate::packets::ld(d, 4);
                    s.down = crate::packets::ld(d, 8);
                    s.valid_flags = crate::packets::ld(d, 12);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.ned_velocity_uncertainty),
            },
            0x0A => match <&[u8; 14]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.euler_angles_uncertainty;
                    s.roll = crate::packets::ld(d, 0);
                    s.pitch = crate::packets::ld(d, 4);
                    s.yaw = crate::packets::ld(d, 8);
                    s.valid_flags = crate::packets::ld(d, 12);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.euler_angles_uncertainty),
            },
            0x0B => match <&[u8; 14]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.gyro_bias_uncertainty;
                    s.bias_uncertainty[0] = crate::packets::ld(d, 0);
                    s.bias_uncertainty[1] = crate::packets::ld(d, 4);
                    s.bias_uncertainty[2] = crate::packets::ld(d, 8);
                    s.valid_flags = crate::packets::ld(d, 12);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.gyro_bias_uncertainty),
            },
            0x0C => match <&[u8; 14]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.accel_bias_uncertainty;
                    s.bias_uncertainty[0] = crate::packets::ld(d, 0);
                    s.bias_uncertainty[1] = crate::packets::ld(d, 4);
                    s.bias_uncertainty[2] = crate::packets::ld(d, 8);
                    s.valid_flags = crate::packets::ld(d, 12);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.accel_bias_uncertainty),
            },
            0x0D => match <&[u8; 14]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.linear_accel;
                    s.accel[0] = crate::packets::ld(d, 0);
                    s.accel[1] = crate::packets::ld(d, 4);
                    s.accel[2] = crate::packets::ld(d, 8);
                    s.valid_flags = crate::packets::ld(d, 12);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.linear_accel),
            },
            0x0E => match <&[u8; 14]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.comp_angular_rate;
                    s.gyro[0] = crate::packets::ld(d, 0);
                    s.gyro[1] = crate::packets::ld(d, 4);
                    s.gyro[2] = crate::packets::ld(d, 8);
                    s.valid_flags = crate::packets::ld(d, 12);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.comp_angular_rate),
            },
            0x0F => match <&[u8; 6]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.wgs84_gravity_magnitude;
                    s.gravity_magnitude = crate::packets::ld(d, 0);
                    s.valid_flags = crate::packets::ld(d, 4);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.wgs84_gravity_magnitude),
            },
            0x11 => match <&[u8; 12]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.filter_data_gps_timestamp;
                    s.tow = crate::packets::ld(d, 0);
                    s.week_number = crate::packets::ld(d, 8);
                    s.valid_flags = crate::packets::ld(d, 10);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.filter_data_gps_timestamp),
            },
            0x12 => match <&[u8; 18]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.quaternion_attitude_uncertainty;
                    s.q[0] = crate::packets::ld(d, 0);
                    s.q[1] = crate::packets::ld(d, 4);
                    s.q[2] = crate::packets::ld(d, 8);
                    s.q[3] = crate::packets::ld(d, 12);
                    s.valid_flags = crate::packets::ld(d, 16);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.quaternion_attitude_uncertainty),
            },
            0x13 => match <&[u8; 14]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.gravity_vector;
                    s.gravity[0] = crate::packets::ld(d, 0);
                    s.gravity[1] = crate::packets::ld(d, 4);
                    s.gravity[2] = crate::packets::ld(d, 8);
                    s.valid_flags = crate::packets::ld(d, 12);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.gravity_vector),
            },
            0x14 => match <&[u8; 12]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.heading_update_state;
                    s.heading = crate::packets::ld(d, 0);
                    s.heading_uncertainty = crate::packets::ld(d, 4);
                    s.source = crate::packets::ld(d, 8);
                    s.valid_flags = crate::packets::ld(d, 10);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.heading_update_state),
            },
            0x15 => match <&[u8; 22]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.magnetic_model;
                    s.intensity_north = crate::packets::ld(d, 0);
                    s.intensity_east = crate::packets::ld(d, 4);
                    s.intensity_down = crate::packets::ld(d, 8);
                    s.inclination = crate::packets::ld(d, 12);
                    s.declination = crate::packets::ld(d, 16);
                    s.valid_flags = crate::packets::ld(d, 20);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.magnetic_model),
            },
            0x16 => match <&[u8; 14]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.gyro_scale_factor;
                    s.scale_factor[0] = crate::packets::ld(d, 0);
                    s.scale_factor[1] = crate::packets::ld(d, 4);
                    s.scale_factor[2] = crate::packets::ld(d, 8);
                    s.valid_flags = crate::packets::ld(d, 12);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.gyro_scale_factor),
            },
            0x17 => match <&[u8; 14]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.accel_scale_factor;
                    s.scale_factor[0] = crate::packets::ld(d, 0);
                    s.scale_factor[1] = crate::packets::ld(d, 4);
                    s.scale_factor[2] = crate::packets::ld(d, 8);
                    s.valid_flags = crate::packets::ld(d, 12);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.accel_scale_factor),
            },
            0x18 => match <&[u8; 14]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.gyro_scale_factor_uncertainty;
                    s.scale_factor_uncertainty[0] = crate::packets::ld(d, 0);
                    s.scale_factor_uncertainty[1] = crate::packets::ld(d, 4);
                    s.scale_factor_uncertainty[2] = crate::packets::ld(d, 8);
                    s.valid_flags = crate::packets::ld(d, 12);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.gyro_scale_factor_uncertainty),
            },
            0x19 => match <&[u8; 14]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.accel_scale_factor_uncertainty;
                    s.scale_factor_uncertainty[0] = crate::packets::ld(d, 0);
                    s.scale_factor_uncertainty[1] = crate::packets::ld(d, 4);
                    s.scale_factor_uncertainty[2] = crate::packets::ld(d, 8);
                    s.valid_flags = crate::packets::ld(d, 12);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.accel_scale_factor_uncertainty),
            },
            0x1C => match <&[u8; 14]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.compensated_accel;
                    s.accel[0] = crate::packets::ld(d, 0);
                    s.accel[1] = crate::packets::ld(d, 4);
                    s.accel[2] = crate::packets::ld(d, 8);
                    s.valid_flags = crate::packets::ld(d, 12);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.compensated_accel),
            },
            0x20 => match <&[u8; 22]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.standard_atmosphere;
                    s.geometric_altitude = crate::packets::ld(d, 0);
                    s.geopotential_altitude = crate::packets::ld(d, 4);
                    s.temperature = crate::packets::ld(d, 8);
                    s.pressure = crate::packets::ld(d, 12);
                    s.density = crate::packets::ld(d, 16);
                    s.valid_flags = crate::packets::ld(d, 20);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.standard_atmosphere),
            },
            0x21 => match <&[u8; 6]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.pressure_altitude;
                    s.pressure_altitude = crate::packets::ld(d, 0);
                    s.valid_flags = crate::packets::ld(d, 4);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.pressure_altitude),
            },
            0x25 => match <&[u8; 14]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.mag_auto_hard_iron_offset;
                    s.hard_iron_offset[0] = crate::packets::ld(d, 0);
                    s.hard_iron_offset[1] = crate::packets::ld(d, 4);
                    s.hard_iron_offset[2] = crate::packets::ld(d, 8);
                    s.valid_flags = crate::packets::ld(d, 12);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.mag_auto_hard_iron_offset),
            },
            0x26 => match <&[u8; 38]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.mag_auto_soft_iron_matrix;
                    s.soft_iron_matrix[0] = crate::packets::ld(d, 0);
                    s.soft_iron_matrix[1] = crate::packets::ld(d, 4);
                    s.soft_iron_matrix[2] = crate::packets::ld(d, 8);
                    s.soft_iron_matrix[3] = crate::packets::ld(d, 12);
                    s.soft_iron_matrix[4] = crate::packets::ld(d, 16);
                    s.soft_iron_matrix[5] = crate::packets::ld(d, 20);
                    s.soft_iron_matrix[6] = crate::packets::ld(d, 24);
                    s.soft_iron_matrix[7] = crate::packets::ld(d, 28);
                    s.soft_iron_matrix[8] = crate::packets::ld(d, 32);
                    s.valid_flags = crate::packets::ld(d, 36);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.mag_auto_soft_iron_matrix),
            },
            0x28 => match <&[u8; 14]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.mag_auto_hard_iron_offset_uncertainty;
                    s.hard_iron_offset_uncertainty[0] = crate::packets::ld(d, 0);
                    s.hard_iron_offset_uncertainty[1] = crate::packets::ld(d, 4);
                    s.hard_iron_offset_uncertainty[2] = crate::packets::ld(d, 8);
                    s.valid_flags = crate::packets::ld(d, 12);
                    true
                }
                _ => crate::packets::decode_into(
                    data,
                    &mut self.mag_auto_hard_iron_offset_uncertainty,
                ),
            },
            0x29 => match <&[u8; 38]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.mag_auto_soft_iron_matrix_uncertainty;
                    s.soft_iron_matrix_uncertainty[0] = crate::packets::ld(d, 0);
                    s.soft_iron_matrix_uncertainty[1] = crate::packets::ld(d, 4);
                    s.soft_iron_matrix_uncertainty[2] = crate::packets::ld(d, 8);
                    s.soft_iron_matrix_uncertainty[3] = crate::packets::ld(d, 12);
                    s.soft_iron_matrix_uncertainty[4] = crate::packets::ld(d, 16);
                    s.soft_iron_matrix_uncertainty[5] = crate::packets::ld(d, 20);
                    s.soft_iron_matrix_uncertainty[6] = crate::packets::ld(d, 24);
                    s.soft_iron_matrix_uncertainty[7] = crate::packets::ld(d, 28);
                    s.soft_iron_matrix_uncertainty[8] = crate::packets::ld(d, 32);
                    s.valid_flags = crate::packets::ld(d, 36);
                    true
                }
                _ => crate::packets::decode_into(
                    data,
                    &mut self.mag_auto_soft_iron_matrix_uncertainty,
                ),
            },
            0x30 => match <&[u8; 14]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.gnss_antenna_offset_correction;
                    s.offset[0] = crate::packets::ld(d, 0);
                    s.offset[1] = crate::packets::ld(d, 4);
                    s.offset[2] = crate::packets::ld(d, 8);
                    s.valid_flags = crate::packets::ld(d, 12);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.gnss_antenna_offset_correction),
            },
            0x31 => match <&[u8; 14]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.gnss_antenna_offset_correction_uncertainty;
                    s.offset_uncertainty[0] = crate::packets::ld(d, 0);
                    s.offset_uncertainty[1] = crate::packets::ld(d, 4);
                    s.offset_uncertainty[2] = crate::packets::ld(d, 8);
                    s.valid_flags = crate::packets::ld(d, 12);
                    true
                }
                _ => crate::packets::decode_into(
                    data,
                    &mut self.gnss_antenna_offset_correction_uncertainty,
                ),
            },
            0x34 => match <&[u8; 15]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.multi_antenna_offset_correction;
                    s.receiver_id = crate::packets::ld(d, 0);
                    s.offset[0] = crate::packets::ld(d, 1);
                    s.offset[1] = crate::packets::ld(d, 5);
                    s.offset[2] = crate::packets::ld(d, 9);
                    s.valid_flags = crate::packets::ld(d, 13);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.multi_antenna_offset_correction),
            },
            0x35 => match <&[u8; 15]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.multi_antenna_offset_correction_uncertainty;
                    s.receiver_id = crate::packets::ld(d, 0);
                    s.offset_uncertainty[0] = crate::packets::ld(d, 1);
                    s.offset_uncertainty[1] = crate::packets::ld(d, 5);
                    s.offset_uncertainty[2] = crate::packets::ld(d, 9);
                    s.valid_flags = crate::packets::ld(d, 13);
                    true
                }
                _ => crate::packets::decode_into(
                    data,
                    &mut self.multi_antenna_offset_correction_uncertainty,
                ),
            },
            0x36 => match <&[u8; 14]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.ecef_position_uncertainty;
                    s.position_uncertainty[0] = crate::packets::ld(d, 0);
                    s.position_uncertainty[1] = crate::packets::ld(d, 4);
                    s.position_uncertainty[2] = crate::packets::ld(d, 8);
                    s.valid_flags = crate::packets::ld(d, 12);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.ecef_position_uncertainty),
            },
            0x37 => match <&[u8; 14]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.ecef_velocity_uncertainty;
                    s.velocity_uncertainty[0] = crate::packets::ld(d, 0);
                    s.velocity_uncertainty[1] = crate::packets::ld(d, 4);
                    s.velocity_uncertainty[2] = crate::packets::ld(d, 8);
                    s.valid_flags = crate::packets::ld(d, 12);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.ecef_velocity_uncertainty),
            },
            0x40 => match <&[u8; 26]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.ecef_position;
                    s.position[0] = crate::packets::ld(d, 0);
                    s.position[1] = crate::packets::ld(d, 8);
                    s.position[2] = crate::packets::ld(d, 16);
                    s.valid_flags = crate::packets::ld(d, 24);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.ecef_position),
            },
            0x41 => match <&[u8; 14]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.ecef_velocity;
                    s.velocity[0] = crate::packets::ld(d, 0);
                    s.velocity[1] = crate::packets::ld(d, 4);
                    s.velocity[2] = crate::packets::ld(d, 8);
                    s.valid_flags = crate::packets::ld(d, 12);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.ecef_velocity),
            },
            0x42 => match <&[u8; 26]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.ned_relative_position;
                    s.relative_position[0] = crate::packets::ld(d, 0);
                    s.relative_position[1] = crate::packets::ld(d, 8);
                    s.relative_position[2] = crate::packets::ld(d, 16);
                    s.valid_flags = crate::packets::ld(d, 24);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.ned_relative_position),
            },
            0x43 => match <&[u8; 15]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.gnss_position_aiding_status;
                    s.receiver_id = crate::packets::ld(d, 0);
                    s.time_of_week = crate::packets::ld(d, 1);
                    s.status = crate::packets::ld(d, 5);
                    s.reserved[0] = crate::packets::ld(d, 7);
                    s.reserved[1] = crate::packets::ld(d, 8);
                    s.reserved[2] = crate::packets::ld(d, 9);
                    s.reserved[3] = crate::packets::ld(d, 10);
                    s.reserved[4] = crate::packets::ld(d, 11);
                    s.reserved[5] = crate::packets::ld(d, 12);
                    s.reserved[6] = crate::packets::ld(d, 13);
                    s.reserved[7] = crate::packets::ld(d, 14);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.gnss_position_aiding_status),
            },
            0x46 => match <&[u8; 7]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.aiding_measurement_summary;
                    s.time_of_week = crate::packets::ld(d, 0);
                    s.source = crate::packets::ld(d, 4);
                    s.r#type = crate::packets::ld(d, 5);
                    s.indicator = crate::packets::ld(d, 6);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.aiding_measurement_summary),
            },
            0x47 => match <&[u8; 6]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.odometer_scale_factor_error;
                    s.scale_factor_error = crate::packets::ld(d, 0);
                    s.valid_flags = crate::packets::ld(d, 4);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.odometer_scale_factor_error),
            },
            0x48 => match <&[u8; 6]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.odometer_scale_factor_error_uncertainty;
                    s.scale_factor_error_uncertainty = crate::packets::ld(d, 0);
                    s.valid_flags = crate::packets::ld(d, 4);
                    true
                }
                _ => crate::packets::decode_into(
                    data,
                    &mut self.odometer_scale_factor_error_uncertainty,
                ),
            },
            0x49 => match <&[u8; 17]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.gnss_dual_antenna_status;
                    s.time_of_week = crate::packets::ld(d, 0);
                    s.heading = crate::packets::ld(d, 4);
                    s.heading_uncertainty = crate::packets::ld(d, 8);
                    s.fix_type = crate::packets::ld(d, 12);
                    s.status_flags = crate::packets::ld(d, 13);
                    s.valid_flags = crate::packets::ld(d, 15);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.gnss_dual_antenna_status),
            },
            0x50 => match <&[u8; 29]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.aiding_frame_config_error;
                    s.frame_id = crate::packets::ld(d, 0);
                    s.translation[0] = crate::packets::ld(d, 1);
                    s.translation[1] = crate::packets::ld(d, 5);
                    s.translation[2] = crate::packets::ld(d, 9);
                    s.attitude[0] = crate::packets::ld(d, 13);
                    s.attitude[1] = crate::packets::ld(d, 17);
                    s.attitude[2] = crate::packets::ld(d, 21);
                    s.attitude[3] = crate::packets::ld(d, 25);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.aiding_frame_config_error),
            },
            0x51 => match <&[u8; 25]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.aiding_frame_config_error_uncertainty;
                    s.frame_id = crate::packets::ld(d, 0);
                    s.translation_uncertainty[0] = crate::packets::ld(d, 1);
                    s.translation_uncertainty[1] = crate::packets::ld(d, 5);
                    s.translation_uncertainty[2] = crate::packets::ld(d, 9);
                    s.attitude_uncertainty[0] = crate::packets::ld(d, 13);
                    s.attitude_uncertainty[1] = crate::packets::ld(d, 17);
                    s.attitude_uncertainty[2] = crate::packets::ld(d, 21);
                    true
                }
                _ => crate::packets::decode_into(
                    data,
                    &mut self.aiding_frame_config_error_uncertainty,
                ),
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
            0x01 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::LlhPosition(self.llh_position),
            )),
            0x02 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::NedVelocity(self.ned_velocity),
            )),
            0x03 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::AttitudeQuaternion(self.attitude_quaternion),
            )),
            0x04 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::AttitudeDcm(self.attitude_dcm),
            )),
            0x05 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::EulerAngles(self.euler_angles),
            )),
            0x06 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::GyroBias(self.gyro_bias),
            )),
            0x07 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::AccelBias(self.accel_bias),
            )),
            0x08 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::LlhPositionUncertainty(self.llh_position_uncertainty),
            )),
            0x09 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::NedVelocityUncertainty(self.ned_velocity_uncertainty),
            )),
            0x0A => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::EulerAnglesUncertainty(self.euler_angles_uncertainty),
            )),
            0x0B => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::GyroBiasUncertainty(self.gyro_bias_uncertainty),
            )),
            0x0C => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::AccelBiasUncertainty(self.accel_bias_uncertainty),
            )),
            0x0D => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::LinearAccel(self.linear_accel),
            )),
            0x0E => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::CompAngularRate(self.comp_angular_rate),
            )),
            0x0F => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::Wgs84GravityMagnitude(self.wgs84_gravity_magnitude),
            )),
            0x11 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::GpsTimestamp(self.filter_data_gps_timestamp),
            )),
            0x12 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::QuaternionAttitudeUncertainty(
                    self.quaternion_attitude_uncertainty,
                ),
            )),
            0x13 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::GravityVector(self.gravity_vector),
            )),
            0x14 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::HeadingUpdateState(self.heading_update_state),
            )),
            0x15 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::MagneticModel(self.magnetic_model),
            )),
            0x16 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::GyroScaleFactor(self.gyro_scale_factor),
            )),
            0x17 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::AccelScaleFactor(self.accel_scale_factor),
            )),
            0x18 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::GyroScaleFactorUncertainty(
                    self.gyro_scale_factor_uncertainty,
                ),
            )),
            0x19 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::AccelScaleFactorUncertainty(
                    self.accel_scale_factor_uncertainty,
                ),
            )),
            0x1C => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::CompensatedAccel(self.compensated_accel),
            )),
            0x20 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::StandardAtmosphere(self.standard_atmosphere),
            )),
            0x21 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::PressureAltitude(self.pressure_altitude),
            )),
            0x25 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::MagAutoHardIronOffset(self.mag_auto_hard_iron_offset),
            )),
            0x26 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::MagAutoSoftIronMatrix(self.mag_auto_soft_iron_matrix),
            )),
            0x28 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::MagAutoHardIronOffsetUncertainty(
                    self.mag_auto_hard_iron_offset_uncertainty,
                ),
            )),
            0x29 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::MagAutoSoftIronMatrixUncertainty(
                    self.mag_auto_soft_iron_matrix_uncertainty,
                ),
            )),
            0x30 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::GnssAntennaOffsetCorrection(
                    self.gnss_antenna_offset_correction,
                ),
            )),
            0x31 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::GnssAntennaOffsetCorrectionUncertainty(
                    self.gnss_antenna_offset_correction_uncertainty,
                ),
            )),
            0x34 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::MultiAntennaOffsetCorrection(
                    self.multi_antenna_offset_correction,
                ),
            )),
            0x35 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::MultiAntennaOffsetCorrectionUncertainty(
                    self.multi_antenna_offset_correction_uncertainty,
                ),
            )),
            0x36 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::EcefPositionUncertainty(
                    self.ecef_position_uncertainty,
                ),
            )),
            0x37 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::EcefVelocityUncertainty(
                    self.ecef_velocity_uncertainty,
                ),
            )),
            0x40 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::EcefPosition(self.ecef_position),
            )),
            0x41 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::EcefVelocity(self.ecef_velocity),
            )),
            0x42 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::NedRelativePosition(self.ned_relative_position),
            )),
            0x43 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::GnssPositionAidingStatus(
                    self.gnss_position_aiding_status,
                ),
            )),
            0x46 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::AidingMeasurementSummary(
                    self.aiding_measurement_summary,
                ),
            )),
            0x47 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::OdometerScaleFactorError(
                    self.odometer_scale_factor_error,
                ),
            )),
            0x48 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::OdometerScaleFactorErrorUncertainty(
                    self.odometer_scale_factor_error_uncertainty,
                ),
            )),
            0x49 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::GnssDualAntennaStatus(self.gnss_dual_antenna_status),
            )),
            0x50 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::AidingFrameConfigError(
                    self.aiding_frame_config_error,
                ),
            )),
            0x51 => Some(crate::FieldValue::FilterData(
                crate::filter_data::SetField::AidingFrameConfigErrorUncertainty(
                    self.aiding_frame_config_error_uncertainty,
                ),
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
#[cfg(any(feature = "set-filter-data", not(feature = "select-sets")))]
pub fn decode_packet(
    payload: &[u8],
    out: &mut Packet,
    other: impl FnMut(crate::fields::FieldItem<'_>),
) -> usize {
    crate::packets::decode_set_packet(payload, out, other)
}
