//! GNSS Data Set. Data from the GX5-45's internal GNSS receiver: position, velocity, DOP, time, clock, fix, satellite, hardware and DGNSS information.
//!
//! Descriptor set 0x81 (data set):
//! one struct per field layout, and `SetField`, the enum of all its fields.

/// Descriptor set of this module.
pub const SET: u8 = 0x81;

/// LLH position. Receiver position in the geodetic frame (latitude, longitude, heights) with accuracy estimates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LlhPosition {
    /// Latitude (WGS84). Units: deg.
    pub latitude: f64,
    /// Longitude (WGS84). Units: deg.
    pub longitude: f64,
    /// Height above the WGS84 ellipsoid. Units: m.
    pub ellipsoid_height: f64,
    /// Height above mean sea level. Units: m.
    pub msl_height: f64,
    /// Horizontal position accuracy estimate. Units: m.
    pub horizontal_accuracy: f32,
    /// Vertical position accuracy estimate. Units: m.
    pub vertical_accuracy: f32,
    /// Which values are valid.
    pub valid_flags: crate::types::GnssLlhPositionValidFlags,
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
        msl_height: <f64 as crate::wire::Wire>::ZERO,
        horizontal_accuracy: <f32 as crate::wire::Wire>::ZERO,
        vertical_accuracy: <f32 as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::GnssLlhPositionValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(42);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_latitude = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("latitude"))?;
        let p_longitude = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("longitude"))?;
        let p_ellipsoid_height =
            <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("ellipsoid_height"))?;
        let p_msl_height = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("msl_height"))?;
        let p_horizontal_accuracy =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("horizontal_accuracy"))?;
        let p_vertical_accuracy =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("vertical_accuracy"))?;
        let p_valid_flags =
            <crate::types::GnssLlhPositionValidFlags as crate::wire::Wire>::decode(r)
                .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            latitude: p_latitude,
            longitude: p_longitude,
            ellipsoid_height: p_ellipsoid_height,
            msl_height: p_msl_height,
            horizontal_accuracy: p_horizontal_accuracy,
            vertical_accuracy: p_vertical_accuracy,
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
        let v = &self.msl_height;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("msl_height"))?;
        let v = &self.horizontal_accuracy;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("horizontal_accuracy"))?;
        let v = &self.vertical_accuracy;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("vertical_accuracy"))?;
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
        let v = &self.msl_height;
        crate::json::key(w, &mut first, "msl_height")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.horizontal_accuracy;
        crate::json::key(w, &mut first, "horizontal_accuracy")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.vertical_accuracy;
        crate::json::key(w, &mut first, "vertical_accuracy")?;
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
                "latitude",
                "longitude",
                "ellipsoid_height",
                "msl_height",
                "horizontal_accuracy",
                "vertical_accuracy",
                "valid_flags",
            ],
        )?;
        let p_latitude = o.req("latitude", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_longitude = o.req("longitude", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_ellipsoid_height = o.req(
            "ellipsoid_height",
            <f64 as crate::json_read::FromJson>::from_json,
        )?;
        let p_msl_height = o.req("msl_height", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_horizontal_accuracy = o.req(
            "horizontal_accuracy",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_vertical_accuracy = o.req(
            "vertical_accuracy",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::GnssLlhPositionValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            latitude: p_latitude,
            longitude: p_longitude,
            ellipsoid_height: p_ellipsoid_height,
            msl_height: p_msl_height,
            horizontal_accuracy: p_horizontal_accuracy,
            vertical_accuracy: p_vertical_accuracy,
            valid_flags: p_valid_flags,
        })
    }
}

impl LlhPosition {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x81;
}

impl crate::wire::Layout for LlhPosition {
    const DESCRIPTOR: u8 = 0x03;
    const DESCRIPTOR_SET: Option<u8> = Some(0x81);
    const NAME: &'static str = "llh_position";
}

/// ECEF position. Receiver position in the Earth-centred, Earth-fixed frame with its accuracy estimate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EcefPosition {
    /// (x, y, z) ECEF position. Units: m.
    pub position: [f64; 3],
    /// Position accuracy estimate. Units: m.
    pub position_accuracy: f32,
    /// Which values are valid.
    pub valid_flags: crate::types::GnssEcefPositionValidFlags,
}

impl Default for EcefPosition {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for EcefPosition {
    const ZERO: Self = Self {
        position: <[f64; 3] as crate::wire::Wire>::ZERO,
        position_accuracy: <f32 as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::GnssEcefPositionValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(30);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_position =
            <[f64; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("position"))?;
        let p_position_accuracy =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("position_accuracy"))?;
        let p_valid_flags =
            <crate::types::GnssEcefPositionValidFlags as crate::wire::Wire>::decode(r)
                .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            position: p_position,
            position_accuracy: p_position_accuracy,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.position;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("position"))?;
        let v = &self.position_accuracy;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("position_accuracy"))?;
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
        let v = &self.position_accuracy;
        crate::json::key(w, &mut first, "position_accuracy")?;
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
        let o = crate::json_read::Obj::new(v, &["position", "position_accuracy", "valid_flags"])?;
        let p_position = o.req(
            "position",
            <[f64; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_position_accuracy = o.req(
            "position_accuracy",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::GnssEcefPositionValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            position: p_position,
            position_accuracy: p_position_accuracy,
            valid_flags: p_valid_flags,
        })
    }
}

impl EcefPosition {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x81;
}

impl crate::wire::Layout for EcefPosition {
    const DESCRIPTOR: u8 = 0x04;
    const DESCRIPTOR_SET: Option<u8> = Some(0x81);
    const NAME: &'static str = "ecef_position";
}

/// NED velocity. Receiver velocity in the north-east-down frame, with 3D and ground speed, heading and accuracy estimates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NedVelocity {
    /// (north, east, down) velocity. Units: m/s.
    pub velocity: [f32; 3],
    /// 3D speed. Units: m/s.
    pub speed: f32,
    /// Horizontal (ground) speed. Units: m/s.
    pub ground_speed: f32,
    /// Heading (direction of travel). Units: deg.
    pub heading: f32,
    /// Speed accuracy estimate. Units: m/s.
    pub speed_accuracy: f32,
    /// Heading accuracy estimate. Units: deg.
    pub heading_accuracy: f32,
    /// Which values are valid.
    pub valid_flags: crate::types::GnssNedVelocityValidFlags,
}

impl Default for NedVelocity {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for NedVelocity {
    const ZERO: Self = Self {
        velocity: <[f32; 3] as crate::wire::Wire>::ZERO,
        speed: <f32 as crate::wire::Wire>::ZERO,
        ground_speed: <f32 as crate::wire::Wire>::ZERO,
        heading: <f32 as crate::wire::Wire>::ZERO,
        speed_accuracy: <f32 as crate::wire::Wire>::ZERO,
        heading_accuracy: <f32 as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::GnssNedVelocityValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(34);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_velocity =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("velocity"))?;
        let p_speed = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("speed"))?;
        let p_ground_speed =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("ground_speed"))?;
        let p_heading = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("heading"))?;
        let p_speed_accuracy =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("speed_accuracy"))?;
        let p_heading_accuracy =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("heading_accuracy"))?;
        let p_valid_flags =
            <crate::types::GnssNedVelocityValidFlags as crate::wire::Wire>::decode(r)
                .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            velocity: p_velocity,
            speed: p_speed,
            ground_speed: p_ground_speed,
            heading: p_heading,
            speed_accuracy: p_speed_accuracy,
            heading_accuracy: p_heading_accuracy,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.velocity;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("velocity"))?;
        let v = &self.speed;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("speed"))?;
        let v = &self.ground_speed;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("ground_speed"))?;
        let v = &self.heading;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("heading"))?;
        let v = &self.speed_accuracy;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("speed_accuracy"))?;
        let v = &self.heading_accuracy;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("heading_accuracy"))?;
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
        let v = &self.speed;
        crate::json::key(w, &mut first, "speed")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.ground_speed;
        crate::json::key(w, &mut first, "ground_speed")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.heading;
        crate::json::key(w, &mut first, "heading")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.speed_accuracy;
        crate::json::key(w, &mut first, "speed_accuracy")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.heading_accuracy;
        crate::json::key(w, &mut first, "heading_accuracy")?;
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
            &[
                "velocity",
                "speed",
                "ground_speed",
                "heading",
                "speed_accuracy",
                "heading_accuracy",
                "valid_flags",
            ],
        )?;
        let p_velocity = o.req(
            "velocity",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_speed = o.req("speed", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_ground_speed = o.req(
            "ground_speed",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_heading = o.req("heading", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_speed_accuracy = o.req(
            "speed_accuracy",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_heading_accuracy = o.req(
            "heading_accuracy",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::GnssNedVelocityValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            velocity: p_velocity,
            speed: p_speed,
            ground_speed: p_ground_speed,
            heading: p_heading,
            speed_accuracy: p_speed_accuracy,
            heading_accuracy: p_heading_accuracy,
            valid_flags: p_valid_flags,
        })
    }
}

impl NedVelocity {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x81;
}

impl crate::wire::Layout for NedVelocity {
    const DESCRIPTOR: u8 = 0x05;
    const DESCRIPTOR_SET: Option<u8> = Some(0x81);
    const NAME: &'static str = "ned_velocity";
}

/// ECEF velocity. Receiver velocity in the Earth-centred, Earth-fixed frame with its accuracy estimate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EcefVelocity {
    /// (x, y, z) ECEF velocity. Units: m/s.
    pub velocity: [f32; 3],
    /// Velocity accuracy estimate. Units: m/s.
    pub velocity_accuracy: f32,
    /// Which values are valid.
    pub valid_flags: crate::types::GnssEcefVelocityValidFlags,
}

impl Default for EcefVelocity {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for EcefVelocity {
    const ZERO: Self = Self {
        velocity: <[f32; 3] as crate::wire::Wire>::ZERO,
        velocity_accuracy: <f32 as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::GnssEcefVelocityValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(18);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_velocity =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("velocity"))?;
        let p_velocity_accuracy =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("velocity_accuracy"))?;
        let p_valid_flags =
            <crate::types::GnssEcefVelocityValidFlags as crate::wire::Wire>::decode(r)
                .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            velocity: p_velocity,
            velocity_accuracy: p_velocity_accuracy,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.velocity;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("velocity"))?;
        let v = &self.velocity_accuracy;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("velocity_accuracy"))?;
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
        let v = &self.velocity_accuracy;
        crate::json::key(w, &mut first, "velocity_accuracy")?;
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
        let o = crate::json_read::Obj::new(v, &["velocity", "velocity_accuracy", "valid_flags"])?;
        let p_velocity = o.req(
            "velocity",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_velocity_accuracy = o.req(
            "velocity_accuracy",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::GnssEcefVelocityValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            velocity: p_velocity,
            velocity_accuracy: p_velocity_accuracy,
            valid_flags: p_valid_flags,
        })
    }
}

impl EcefVelocity {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x81;
}

impl crate::wire::Layout for EcefVelocity {
    const DESCRIPTOR: u8 = 0x06;
    const DESCRIPTOR_SET: Option<u8> = Some(0x81);
    const NAME: &'static str = "ecef_velocity";
}

/// DOP data. Geometric, position, horizontal, vertical, time, northing and easting dilution of precision.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dop {
    /// Geometric DOP.
    pub gdop: f32,
    /// Position DOP.
    pub pdop: f32,
    /// Horizontal DOP.
    pub hdop: f32,
    /// Vertical DOP.
    pub vdop: f32,
    /// Time DOP.
    pub tdop: f32,
    /// Northing DOP.
    pub ndop: f32,
    /// Easting DOP.
    pub edop: f32,
    /// Which values are valid.
    pub valid_flags: crate::types::GnssDopValidFlags,
}

impl Default for Dop {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for Dop {
    const ZERO: Self = Self {
        gdop: <f32 as crate::wire::Wire>::ZERO,
        pdop: <f32 as crate::wire::Wire>::ZERO,
        hdop: <f32 as crate::wire::Wire>::ZERO,
        vdop: <f32 as crate::wire::Wire>::ZERO,
        tdop: <f32 as crate::wire::Wire>::ZERO,
        ndop: <f32 as crate::wire::Wire>::ZERO,
        edop: <f32 as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::GnssDopValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(30);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_gdop = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("gdop"))?;
        let p_pdop = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("pdop"))?;
        let p_hdop = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("hdop"))?;
        let p_vdop = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("vdop"))?;
        let p_tdop = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("tdop"))?;
        let p_ndop = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("ndop"))?;
        let p_edop = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("edop"))?;
        let p_valid_flags = <crate::types::GnssDopValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            gdop: p_gdop,
            pdop: p_pdop,
            hdop: p_hdop,
            vdop: p_vdop,
            tdop: p_tdop,
            ndop: p_ndop,
            edop: p_edop,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.gdop;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("gdop"))?;
        let v = &self.pdop;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("pdop"))?;
        let v = &self.hdop;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("hdop"))?;
        let v = &self.vdop;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("vdop"))?;
        let v = &self.tdop;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("tdop"))?;
        let v = &self.ndop;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("ndop"))?;
        let v = &self.edop;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("edop"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.gdop;
        crate::json::key(w, &mut first, "gdop")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.pdop;
        crate::json::key(w, &mut first, "pdop")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.hdop;
        crate::json::key(w, &mut first, "hdop")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.vdop;
        crate::json::key(w, &mut first, "vdop")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.tdop;
        crate::json::key(w, &mut first, "tdop")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.ndop;
        crate::json::key(w, &mut first, "ndop")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.edop;
        crate::json::key(w, &mut first, "edop")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for Dop {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "gdop",
                "pdop",
                "hdop",
                "vdop",
                "tdop",
                "ndop",
                "edop",
                "valid_flags",
            ],
        )?;
        let p_gdop = o.req("gdop", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_pdop = o.req("pdop", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_hdop = o.req("hdop", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_vdop = o.req("vdop", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_tdop = o.req("tdop", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_ndop = o.req("ndop", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_edop = o.req("edop", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::GnssDopValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            gdop: p_gdop,
            pdop: p_pdop,
            hdop: p_hdop,
            vdop: p_vdop,
            tdop: p_tdop,
            ndop: p_ndop,
            edop: p_edop,
            valid_flags: p_valid_flags,
        })
    }
}

impl Dop {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x81;
}

impl crate::wire::Layout for Dop {
    const DESCRIPTOR: u8 = 0x07;
    const DESCRIPTOR_SET: Option<u8> = Some(0x81);
    const NAME: &'static str = "dop";
}

/// UTC time. UTC date and time from the GNSS receiver, with separate date and time valid flags.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UtcTime {
    /// Year (1999-2099).
    pub year: u16,
    /// Month (1-12).
    pub month: u8,
    /// Day of the month (1-31).
    pub day: u8,
    /// Hour (0-23).
    pub hour: u8,
    /// Minute (0-59).
    pub minute: u8,
    /// Second (0-59).
    pub second: u8,
    /// Millisecond. Units: ms.
    pub millisecond: u32,
    /// Validity of the date and of the time.
    pub valid_flags: crate::types::GnssUtcTimeValidFlagsGx5,
}

impl Default for UtcTime {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for UtcTime {
    const ZERO: Self = Self {
        year: <u16 as crate::wire::Wire>::ZERO,
        month: <u8 as crate::wire::Wire>::ZERO,
        day: <u8 as crate::wire::Wire>::ZERO,
        hour: <u8 as crate::wire::Wire>::ZERO,
        minute: <u8 as crate::wire::Wire>::ZERO,
        second: <u8 as crate::wire::Wire>::ZERO,
        millisecond: <u32 as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::GnssUtcTimeValidFlagsGx5 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(13);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_year = <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("year"))?;
        let p_month = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("month"))?;
        let p_day = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("day"))?;
        let p_hour = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("hour"))?;
        let p_minute = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("minute"))?;
        let p_second = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("second"))?;
        let p_millisecond =
            <u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("millisecond"))?;
        let p_valid_flags =
            <crate::types::GnssUtcTimeValidFlagsGx5 as crate::wire::Wire>::decode(r)
                .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            year: p_year,
            month: p_month,
            day: p_day,
            hour: p_hour,
            minute: p_minute,
            second: p_second,
            millisecond: p_millisecond,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.year;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("year"))?;
        let v = &self.month;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("month"))?;
        let v = &self.day;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("day"))?;
        let v = &self.hour;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("hour"))?;
        let v = &self.minute;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("minute"))?;
        let v = &self.second;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("second"))?;
        let v = &self.millisecond;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("millisecond"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.year;
        crate::json::key(w, &mut first, "year")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.month;
        crate::json::key(w, &mut first, "month")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.day;
        crate::json::key(w, &mut first, "day")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.hour;
        crate::json::key(w, &mut first, "hour")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.minute;
        crate::json::key(w, &mut first, "minute")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.second;
        crate::json::key(w, &mut first, "second")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.millisecond;
        crate::json::key(w, &mut first, "millisecond")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for UtcTime {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "year",
                "month",
                "day",
                "hour",
                "minute",
                "second",
                "millisecond",
                "valid_flags",
            ],
        )?;
        let p_year = o.req("year", <u16 as crate::json_read::FromJson>::from_json)?;
        let p_month = o.req("month", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_day = o.req("day", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_hour = o.req("hour", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_minute = o.req("minute", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_second = o.req("second", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_millisecond = o.req(
            "millisecond",
            <u32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::GnssUtcTimeValidFlagsGx5 as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            year: p_year,
            month: p_month,
            day: p_day,
            hour: p_hour,
            minute: p_minute,
            second: p_second,
            millisecond: p_millisecond,
            valid_flags: p_valid_flags,
        })
    }
}

impl UtcTime {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x81;
}

impl crate::wire::Layout for UtcTime {
    const DESCRIPTOR: u8 = 0x08;
    const DESCRIPTOR_SET: Option<u8> = Some(0x81);
    const NAME: &'static str = "utc_time";
}

/// GPS time. GPS time of week and week number.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GpsTime {
    /// GPS time of week. Units: s.
    pub tow: f64,
    /// GPS week number (since 1980). Units: weeks.
    pub week_number: u16,
    /// Which values are valid.
    pub valid_flags: crate::types::GnssGpsTimeValidFlags,
}

impl Default for GpsTime {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GpsTime {
    const ZERO: Self = Self {
        tow: <f64 as crate::wire::Wire>::ZERO,
        week_number: <u16 as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::GnssGpsTimeValidFlags as crate::wire::Wire>::ZERO,
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
        let p_valid_flags = <crate::types::GnssGpsTimeValidFlags as crate::wire::Wire>::decode(r)
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
impl crate::json_read::FromJson for GpsTime {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["tow", "week_number", "valid_flags"])?;
        let p_tow = o.req("tow", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_week_number = o.req(
            "week_number",
            <u16 as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::GnssGpsTimeValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            tow: p_tow,
            week_number: p_week_number,
            valid_flags: p_valid_flags,
        })
    }
}

impl GpsTime {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x81;
}

impl crate::wire::Layout for GpsTime {
    const DESCRIPTOR: u8 = 0x09;
    const DESCRIPTOR_SET: Option<u8> = Some(0x81);
    const NAME: &'static str = "gps_time";
}

/// Clock information. GNSS receiver clock bias and drift, with an accuracy estimate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClockInfo {
    /// Receiver clock bias. Units: s.
    pub bias: f64,
    /// Receiver clock drift. Units: s/s.
    pub drift: f64,
    /// Clock accuracy estimate. Units: s.
    pub accuracy_estimate: f64,
    /// Which values are valid.
    pub valid_flags: crate::types::GnssClockInfoValidFlags,
}

impl Default for ClockInfo {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ClockInfo {
    const ZERO: Self = Self {
        bias: <f64 as crate::wire::Wire>::ZERO,
        drift: <f64 as crate::wire::Wire>::ZERO,
        accuracy_estimate: <f64 as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::GnssClockInfoValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(26);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_bias = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("bias"))?;
        let p_drift = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("drift"))?;
        let p_accuracy_estimate =
            <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("accuracy_estimate"))?;
        let p_valid_flags = <crate::types::GnssClockInfoValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            bias: p_bias,
            drift: p_drift,
            accuracy_estimate: p_accuracy_estimate,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.bias;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("bias"))?;
        let v = &self.drift;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("drift"))?;
        let v = &self.accuracy_estimate;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("accuracy_estimate"))?;
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
        let v = &self.drift;
        crate::json::key(w, &mut first, "drift")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.accuracy_estimate;
        crate::json::key(w, &mut first, "accuracy_estimate")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ClockInfo {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o =
            crate::json_read::Obj::new(v, &["bias", "drift", "accuracy_estimate", "valid_flags"])?;
        let p_bias = o.req("bias", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_drift = o.req("drift", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_accuracy_estimate = o.req(
            "accuracy_estimate",
            <f64 as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::GnssClockInfoValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            bias: p_bias,
            drift: p_drift,
            accuracy_estimate: p_accuracy_estimate,
            valid_flags: p_valid_flags,
        })
    }
}

impl ClockInfo {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x81;
}

impl crate::wire::Layout for ClockInfo {
    const DESCRIPTOR: u8 = 0x0A;
    const DESCRIPTOR_SET: Option<u8> = Some(0x81);
    const NAME: &'static str = "clock_info";
}

/// GNSS fix information. Fix type, number of satellites used and corrections applied.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FixInfo {
    /// Type of fix.
    pub fix_type: crate::types::GnssFixTypeGx5,
    /// Number of satellites used for the solution.
    pub num_sv: u8,
    /// Corrections used.
    pub fix_flags: crate::types::GnssFixFlags,
    /// Which values are valid.
    pub valid_flags: crate::types::GnssFixInfoValidFlags,
}

impl Default for FixInfo {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for FixInfo {
    const ZERO: Self = Self {
        fix_type: <crate::types::GnssFixTypeGx5 as crate::wire::Wire>::ZERO,
        num_sv: <u8 as crate::wire::Wire>::ZERO,
        fix_flags: <crate::types::GnssFixFlags as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::GnssFixInfoValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(6);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_fix_type = <crate::types::GnssFixTypeGx5 as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("fix_type"))?;
        let p_num_sv = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("num_sv"))?;
        let p_fix_flags = <crate::types::GnssFixFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("fix_flags"))?;
        let p_valid_flags = <crate::types::GnssFixInfoValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            fix_type: p_fix_type,
            num_sv: p_num_sv,
            fix_flags: p_fix_flags,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.fix_type;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("fix_type"))?;
        let v = &self.num_sv;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("num_sv"))?;
        let v = &self.fix_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("fix_flags"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.fix_type;
        crate::json::key(w, &mut first, "fix_type")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.num_sv;
        crate::json::key(w, &mut first, "num_sv")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.fix_flags;
        crate::json::key(w, &mut first, "fix_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for FixInfo {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["fix_type", "num_sv", "fix_flags", "valid_flags"])?;
        let p_fix_type = o.req(
            "fix_type",
            <crate::types::GnssFixTypeGx5 as crate::json_read::FromJson>::from_json,
        )?;
        let p_num_sv = o.req("num_sv", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_fix_flags = o.req(
            "fix_flags",
            <crate::types::GnssFixFlags as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::GnssFixInfoValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            fix_type: p_fix_type,
            num_sv: p_num_sv,
            fix_flags: p_fix_flags,
            valid_flags: p_valid_flags,
        })
    }
}

impl FixInfo {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x81;
}

impl crate::wire::Layout for FixInfo {
    const DESCRIPTOR: u8 = 0x0B;
    const DESCRIPTOR_SET: Option<u8> = Some(0x81);
    const NAME: &'static str = "fix_info";
}

/// Space vehicle information. One entry per space vehicle: channel, SV id, carrier-to-noise ratio, azimuth, elevation and use/health flags. The entries arrive in a MIP packet of their own, separate from the other GNSS fields, one field per vehicle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SvInfo {
    /// Receiver channel number.
    pub channel: u8,
    /// Space vehicle id number.
    pub sv_id: u8,
    /// Carrier to noise ratio. Units: dBHz.
    pub carrier_to_noise_ratio: u16,
    /// Azimuth, whole degrees. Units: deg.
    pub azimuth: i16,
    /// Elevation, whole degrees. Units: deg.
    pub elevation: i16,
    /// Use and health of the vehicle.
    pub sv_flags: crate::types::GnssSvFlags,
    /// Which values are valid.
    pub valid_flags: crate::types::GnssSvInfoValidFlags,
}

impl Default for SvInfo {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SvInfo {
    const ZERO: Self = Self {
        channel: <u8 as crate::wire::Wire>::ZERO,
        sv_id: <u8 as crate::wire::Wire>::ZERO,
        carrier_to_noise_ratio: <u16 as crate::wire::Wire>::ZERO,
        azimuth: <i16 as crate::wire::Wire>::ZERO,
        elevation: <i16 as crate::wire::Wire>::ZERO,
        sv_flags: <crate::types::GnssSvFlags as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::GnssSvInfoValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(12);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_channel = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("channel"))?;
        let p_sv_id = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("sv_id"))?;
        let p_carrier_to_noise_ratio =
            <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("carrier_to_noise_ratio"))?;
        let p_azimuth = <i16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("azimuth"))?;
        let p_elevation = <i16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("elevation"))?;
        let p_sv_flags = <crate::types::GnssSvFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("sv_flags"))?;
        let p_valid_flags = <crate::types::GnssSvInfoValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            channel: p_channel,
            sv_id: p_sv_id,
            carrier_to_noise_ratio: p_carrier_to_noise_ratio,
            azimuth: p_azimuth,
            elevation: p_elevation,
            sv_flags: p_sv_flags,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.channel;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("channel"))?;
        let v = &self.sv_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("sv_id"))?;
        let v = &self.carrier_to_noise_ratio;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("carrier_to_noise_ratio"))?;
        let v = &self.azimuth;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("azimuth"))?;
        let v = &self.elevation;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("elevation"))?;
        let v = &self.sv_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("sv_flags"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.channel;
        crate::json::key(w, &mut first, "channel")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.sv_id;
        crate::json::key(w, &mut first, "sv_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.carrier_to_noise_ratio;
        crate::json::key(w, &mut first, "carrier_to_noise_ratio")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.azimuth;
        crate::json::key(w, &mut first, "azimuth")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.elevation;
        crate::json::key(w, &mut first, "elevation")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.sv_flags;
        crate::json::key(w, &mut first, "sv_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SvInfo {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "channel",
                "sv_id",
                "carrier_to_noise_ratio",
                "azimuth",
                "elevation",
                "sv_flags",
                "valid_flags",
            ],
        )?;
        let p_channel = o.req("channel", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_sv_id = o.req("sv_id", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_carrier_to_noise_ratio = o.req(
            "carrier_to_noise_ratio",
            <u16 as crate::json_read::FromJson>::from_json,
        )?;
        let p_azimuth = o.req("azimuth", <i16 as crate::json_read::FromJson>::from_json)?;
        let p_elevation = o.req("elevation", <i16 as crate::json_read::FromJson>::from_json)?;
        let p_sv_flags = o.req(
            "sv_flags",
            <crate::types::GnssSvFlags as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::GnssSvInfoValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            channel: p_channel,
            sv_id: p_sv_id,
            carrier_to_noise_ratio: p_carrier_to_noise_ratio,
            azimuth: p_azimuth,
            elevation: p_elevation,
            sv_flags: p_sv_flags,
            valid_flags: p_valid_flags,
        })
    }
}

impl SvInfo {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x81;
}

impl crate::wire::Layout for SvInfo {
    const DESCRIPTOR: u8 = 0x0C;
    const DESCRIPTOR_SET: Option<u8> = Some(0x81);
    const NAME: &'static str = "sv_info";
}

/// Hardware status. Receiver (sensor) power state, antenna connection state and antenna power. Only produced at 1 Hz; higher rates have no effect.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HardwareStatus {
    /// Receiver power state (GX5-45: sensor state).
    pub receiver_state: crate::types::GnssReceiverState,
    /// Antenna connection state.
    pub antenna_state: crate::types::GnssAntennaState,
    /// Antenna power state.
    pub antenna_power: crate::types::GnssAntennaPower,
    /// Which values are valid.
    pub valid_flags: crate::types::GnssHardwareStatusValidFlags,
}

impl Default for HardwareStatus {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for HardwareStatus {
    const ZERO: Self = Self {
        receiver_state: <crate::types::GnssReceiverState as crate::wire::Wire>::ZERO,
        antenna_state: <crate::types::GnssAntennaState as crate::wire::Wire>::ZERO,
        antenna_power: <crate::types::GnssAntennaPower as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::GnssHardwareStatusValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(5);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_receiver_state = <crate::types::GnssReceiverState as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("receiver_state"))?;
        let p_antenna_state = <crate::types::GnssAntennaState as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("antenna_state"))?;
        let p_antenna_power = <crate::types::GnssAntennaPower as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("antenna_power"))?;
        let p_valid_flags =
            <crate::types::GnssHardwareStatusValidFlags as crate::wire::Wire>::decode(r)
                .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            receiver_state: p_receiver_state,
            antenna_state: p_antenna_state,
            antenna_power: p_antenna_power,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.receiver_state;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("receiver_state"))?;
        let v = &self.antenna_state;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("antenna_state"))?;
        let v = &self.antenna_power;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("antenna_power"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.receiver_state;
        crate::json::key(w, &mut first, "receiver_state")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.antenna_state;
        crate::json::key(w, &mut first, "antenna_state")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.antenna_power;
        crate::json::key(w, &mut first, "antenna_power")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for HardwareStatus {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "receiver_state",
                "antenna_state",
                "antenna_power",
                "valid_flags",
            ],
        )?;
        let p_receiver_state = o.req(
            "receiver_state",
            <crate::types::GnssReceiverState as crate::json_read::FromJson>::from_json,
        )?;
        let p_antenna_state = o.req(
            "antenna_state",
            <crate::types::GnssAntennaState as crate::json_read::FromJson>::from_json,
        )?;
        let p_antenna_power = o.req(
            "antenna_power",
            <crate::types::GnssAntennaPower as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::GnssHardwareStatusValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            receiver_state: p_receiver_state,
            antenna_state: p_antenna_state,
            antenna_power: p_antenna_power,
            valid_flags: p_valid_flags,
        })
    }
}

impl HardwareStatus {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x81;
}

impl crate::wire::Layout for HardwareStatus {
    const DESCRIPTOR: u8 = 0x0D;
    const DESCRIPTOR_SET: Option<u8> = Some(0x81);
    const NAME: &'static str = "hardware_status";
}

/// DGNSS information. Age of the newest differential correction, base station id and status, and the number of DGNSS channels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DgnssInfo {
    /// Age of the newest correction (valid flag: latest age). Units: s.
    pub newest_age: f32,
    /// Base station id.
    pub base_station_id: i16,
    /// Base station status (UDRE scale factor).
    pub base_station_status: crate::types::GnssDgnssBaseStationStatus,
    /// Number of DGNSS channels.
    pub num_channels: u16,
    /// Which values are valid.
    pub valid_flags: crate::types::GnssDgnssInfoValidFlags,
}

impl Default for DgnssInfo {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for DgnssInfo {
    const ZERO: Self = Self {
        newest_age: <f32 as crate::wire::Wire>::ZERO,
        base_station_id: <i16 as crate::wire::Wire>::ZERO,
        base_station_status: <crate::types::GnssDgnssBaseStationStatus as crate::wire::Wire>::ZERO,
        num_channels: <u16 as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::GnssDgnssInfoValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(12);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_newest_age = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("newest_age"))?;
        let p_base_station_id =
            <i16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("base_station_id"))?;
        let p_base_station_status =
            <crate::types::GnssDgnssBaseStationStatus as crate::wire::Wire>::decode(r)
                .map_err(|e| e.at("base_station_status"))?;
        let p_num_channels =
            <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("num_channels"))?;
        let p_valid_flags = <crate::types::GnssDgnssInfoValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            newest_age: p_newest_age,
            base_station_id: p_base_station_id,
            base_station_status: p_base_station_status,
            num_channels: p_num_channels,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.newest_age;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("newest_age"))?;
        let v = &self.base_station_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("base_station_id"))?;
        let v = &self.base_station_status;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("base_station_status"))?;
        let v = &self.num_channels;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("num_channels"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.newest_age;
        crate::json::key(w, &mut first, "newest_age")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.base_station_id;
        crate::json::key(w, &mut first, "base_station_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.base_station_status;
        crate::json::key(w, &mut first, "base_station_status")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.num_channels;
        crate::json::key(w, &mut first, "num_channels")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for DgnssInfo {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "newest_age",
                "base_station_id",
                "base_station_status",
                "num_channels",
                "valid_flags",
            ],
        )?;
        let p_newest_age = o.req("newest_age", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_base_station_id = o.req(
            "base_station_id",
            <i16 as crate::json_read::FromJson>::from_json,
        )?;
        let p_base_station_status = o.req(
            "base_station_status",
            <crate::types::GnssDgnssBaseStationStatus as crate::json_read::FromJson>::from_json,
        )?;
        let p_num_channels = o.req(
            "num_channels",
            <u16 as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::GnssDgnssInfoValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            newest_age: p_newest_age,
            base_station_id: p_base_station_id,
            base_station_status: p_base_station_status,
            num_channels: p_num_channels,
            valid_flags: p_valid_flags,
        })
    }
}

impl DgnssInfo {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x81;
}

impl crate::wire::Layout for DgnssInfo {
    const DESCRIPTOR: u8 = 0x0E;
    const DESCRIPTOR_SET: Option<u8> = Some(0x81);
    const NAME: &'static str = "dgnss_info";
}

/// DGNSS channel status. One entry per space vehicle with differential corrections: SV id, correction age, pseudorange and pseudorange-rate corrections. One field per active vehicle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DgnssChannelStatus {
    /// Space vehicle id number.
    pub sv_id: u8,
    /// Age of the correction. Units: s.
    pub age: f32,
    /// Pseudorange correction. Units: m.
    pub pseudorange_correction: f32,
    /// Pseudorange rate correction. Units: m/s.
    pub pseudorange_rate_correction: f32,
    /// Which values are valid.
    pub valid_flags: crate::types::GnssDgnssChannelStatusValidFlags,
}

impl Default for DgnssChannelStatus {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for DgnssChannelStatus {
    const ZERO: Self = Self {
        sv_id: <u8 as crate::wire::Wire>::ZERO,
        age: <f32 as crate::wire::Wire>::ZERO,
        pseudorange_correction: <f32 as crate::wire::Wire>::ZERO,
        pseudorange_rate_correction: <f32 as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::GnssDgnssChannelStatusValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(15);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_sv_id = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("sv_id"))?;
        let p_age = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("age"))?;
        let p_pseudorange_correction =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("pseudorange_correction"))?;
        let p_pseudorange_rate_correction = <f32 as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("pseudorange_rate_correction"))?;
        let p_valid_flags =
            <crate::types::GnssDgnssChannelStatusValidFlags as crate::wire::Wire>::decode(r)
                .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            sv_id: p_sv_id,
            age: p_age,
            pseudorange_correction: p_pseudorange_correction,
            pseudorange_rate_correction: p_pseudorange_rate_correction,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.sv_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("sv_id"))?;
        let v = &self.age;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("age"))?;
        let v = &self.pseudorange_correction;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("pseudorange_correction"))?;
        let v = &self.pseudorange_rate_correction;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("pseudorange_rate_correction"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.sv_id;
        crate::json::key(w, &mut first, "sv_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.age;
        crate::json::key(w, &mut first, "age")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.pseudorange_correction;
        crate::json::key(w, &mut first, "pseudorange_correction")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.pseudorange_rate_correction;
        crate::json::key(w, &mut first, "pseudorange_rate_correction")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for DgnssChannelStatus {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "sv_id",
                "age",
                "pseudorange_correction",
                "pseudorange_rate_correction",
                "valid_flags",
            ],
        )?;
        let p_sv_id = o.req("sv_id", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_age = o.req("age", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_pseudorange_correction = o.req(
            "pseudorange_correction",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_pseudorange_rate_correction = o.req(
            "pseudorange_rate_correction",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req("valid_flags", <crate::types::GnssDgnssChannelStatusValidFlags as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            sv_id: p_sv_id,
            age: p_age,
            pseudorange_correction: p_pseudorange_correction,
            pseudorange_rate_correction: p_pseudorange_rate_correction,
            valid_flags: p_valid_flags,
        })
    }
}

impl DgnssChannelStatus {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x81;
}

impl crate::wire::Layout for DgnssChannelStatus {
    const DESCRIPTOR: u8 = 0x0F;
    const DESCRIPTOR_SET: Option<u8> = Some(0x81);
    const NAME: &'static str = "dgnss_channel_status";
}

/// A decoded field of set 0x81 (`gnss_data`).
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SetField {
    /// `llh_position` (0x03).
    LlhPosition(LlhPosition),
    /// `ecef_position` (0x04).
    EcefPosition(EcefPosition),
    /// `ned_velocity` (0x05).
    NedVelocity(NedVelocity),
    /// `ecef_velocity` (0x06).
    EcefVelocity(EcefVelocity),
    /// `dop` (0x07).
    Dop(Dop),
    /// `utc_time` (0x08).
    UtcTime(UtcTime),
    /// `gps_time` (0x09).
    GpsTime(GpsTime),
    /// `clock_info` (0x0A).
    ClockInfo(ClockInfo),
    /// `fix_info` (0x0B).
    FixInfo(FixInfo),
    /// `sv_info` (0x0C).
    SvInfo(SvInfo),
    /// `hardware_status` (0x0D).
    HardwareStatus(HardwareStatus),
    /// `dgnss_info` (0x0E).
    DgnssInfo(DgnssInfo),
    /// `dgnss_channel_status` (0x0F).
    DgnssChannelStatus(DgnssChannelStatus),
}

impl SetField {
    /// Field descriptor.
    pub fn descriptor(&self) -> u8 {
        match self {
            Self::LlhPosition(_) => 0x03,
            Self::EcefPosition(_) => 0x04,
            Self::NedVelocity(_) => 0x05,
            Self::EcefVelocity(_) => 0x06,
            Self::Dop(_) => 0x07,
            Self::UtcTime(_) => 0x08,
            Self::GpsTime(_) => 0x09,
            Self::ClockInfo(_) => 0x0A,
            Self::FixInfo(_) => 0x0B,
            Self::SvInfo(_) => 0x0C,
            Self::HardwareStatus(_) => 0x0D,
            Self::DgnssInfo(_) => 0x0E,
            Self::DgnssChannelStatus(_) => 0x0F,
        }
    }

    /// Field name as printed in JSON.
    pub fn name(&self) -> &'static str {
        match self {
            Self::LlhPosition(_) => "llh_position",
            Self::EcefPosition(_) => "ecef_position",
            Self::NedVelocity(_) => "ned_velocity",
            Self::EcefVelocity(_) => "ecef_velocity",
            Self::Dop(_) => "dop",
            Self::UtcTime(_) => "utc_time",
            Self::GpsTime(_) => "gps_time",
            Self::ClockInfo(_) => "clock_info",
            Self::FixInfo(_) => "fix_info",
            Self::SvInfo(_) => "sv_info",
            Self::HardwareStatus(_) => "hardware_status",
            Self::DgnssInfo(_) => "dgnss_info",
            Self::DgnssChannelStatus(_) => "dgnss_channel_status",
        }
    }

    /// Device of the layout used, for fields with per-device layouts.
    pub fn device(&self) -> Option<crate::Device> {
        match self {
            Self::LlhPosition(_) => None,
            Self::EcefPosition(_) => None,
            Self::NedVelocity(_) => None,
            Self::EcefVelocity(_) => None,
            Self::Dop(_) => None,
            Self::UtcTime(_) => None,
            Self::GpsTime(_) => None,
            Self::ClockInfo(_) => None,
            Self::FixInfo(_) => None,
            Self::SvInfo(_) => None,
            Self::HardwareStatus(_) => None,
            Self::DgnssInfo(_) => None,
            Self::DgnssChannelStatus(_) => None,
        }
    }

    /// Encodes the field data.
    pub fn encode_data(
        &self,
        w: &mut crate::wire::Writer<'_>,
    ) -> Result<(), crate::error::EncodeError> {
        match self {
            Self::LlhPosition(v) => crate::wire::Layout::encode_data(v, w),
            Self::EcefPosition(v) => crate::wire::Layout::encode_data(v, w),
            Self::NedVelocity(v) => crate::wire::Layout::encode_data(v, w),
            Self::EcefVelocity(v) => crate::wire::Layout::encode_data(v, w),
            Self::Dop(v) => crate::wire::Layout::encode_data(v, w),
            Self::UtcTime(v) => crate::wire::Layout::encode_data(v, w),
            Self::GpsTime(v) => crate::wire::Layout::encode_data(v, w),
            Self::ClockInfo(v) => crate::wire::Layout::encode_data(v, w),
            Self::FixInfo(v) => crate::wire::Layout::encode_data(v, w),
            Self::SvInfo(v) => crate::wire::Layout::encode_data(v, w),
            Self::HardwareStatus(v) => crate::wire::Layout::encode_data(v, w),
            Self::DgnssInfo(v) => crate::wire::Layout::encode_data(v, w),
            Self::DgnssChannelStatus(v) => crate::wire::Layout::encode_data(v, w),
        }
    }

    /// Writes the canonical JSON of the values (`{...}`).
    pub fn write_values_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::LlhPosition(v) => crate::wire::Wire::write_json(v, w),
            Self::EcefPosition(v) => crate::wire::Wire::write_json(v, w),
            Self::NedVelocity(v) => crate::wire::Wire::write_json(v, w),
            Self::EcefVelocity(v) => crate::wire::Wire::write_json(v, w),
            Self::Dop(v) => crate::wire::Wire::write_json(v, w),
            Self::UtcTime(v) => crate::wire::Wire::write_json(v, w),
            Self::GpsTime(v) => crate::wire::Wire::write_json(v, w),
            Self::ClockInfo(v) => crate::wire::Wire::write_json(v, w),
            Self::FixInfo(v) => crate::wire::Wire::write_json(v, w),
            Self::SvInfo(v) => crate::wire::Wire::write_json(v, w),
            Self::HardwareStatus(v) => crate::wire::Wire::write_json(v, w),
            Self::DgnssInfo(v) => crate::wire::Wire::write_json(v, w),
            Self::DgnssChannelStatus(v) => crate::wire::Wire::write_json(v, w),
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
            0x04 => Some(
                <EcefPosition as crate::wire::Layout>::decode_data(data).map(Self::EcefPosition),
            ),
            0x05 => {
                Some(<NedVelocity as crate::wire::Layout>::decode_data(data).map(Self::NedVelocity))
            }
            0x06 => Some(
                <EcefVelocity as crate::wire::Layout>::decode_data(data).map(Self::EcefVelocity),
            ),
            0x07 => Some(<Dop as crate::wire::Layout>::decode_data(data).map(Self::Dop)),
            0x08 => Some(<UtcTime as crate::wire::Layout>::decode_data(data).map(Self::UtcTime)),
            0x09 => Some(<GpsTime as crate::wire::Layout>::decode_data(data).map(Self::GpsTime)),
            0x0A => {
                Some(<ClockInfo as crate::wire::Layout>::decode_data(data).map(Self::ClockInfo))
            }
            0x0B => Some(<FixInfo as crate::wire::Layout>::decode_data(data).map(Self::FixInfo)),
            0x0C => Some(<SvInfo as crate::wire::Layout>::decode_data(data).map(Self::SvInfo)),
            0x0D => Some(
                <HardwareStatus as crate::wire::Layout>::decode_data(data)
                    .map(Self::HardwareStatus),
            ),
            0x0E => {
                Some(<DgnssInfo as crate::wire::Layout>::decode_data(data).map(Self::DgnssInfo))
            }
            0x0F => Some(
                <DgnssChannelStatus as crate::wire::Layout>::decode_data(data)
                    .map(Self::DgnssChannelStatus),
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
            0x03 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <LlhPosition as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::LlhPosition),
            ),
            0x04 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <EcefPosition as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::EcefPosition),
            ),
            0x05 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <NedVelocity as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::NedVelocity),
            ),
            0x06 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <EcefVelocity as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::EcefVelocity),
            ),
            0x07 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <Dop as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::Dop),
            ),
            0x08 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <UtcTime as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::UtcTime),
            ),
            0x09 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GpsTime as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::GpsTime),
            ),
            0x0A => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ClockInfo as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::ClockInfo),
            ),
            0x0B => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <FixInfo as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::FixInfo),
            ),
            0x0C => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SvInfo as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::SvInfo),
            ),
            0x0D => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <HardwareStatus as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::HardwareStatus),
            ),
            0x0E => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <DgnssInfo as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::DgnssInfo),
            ),
            0x0F => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <DgnssChannelStatus as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::DgnssChannelStatus),
            ),
            _ => None,
        }
    }
}

/// The fields of one packet of this set, decoded in place by [`decode_packet`]: one member per
/// field of the set with one layout (its own and the shared data fields); `index` says which members hold a field of the last packet, in packet order
/// (the others hold whatever they held).
#[cfg(any(feature = "set-gnss-data", not(feature = "select-sets")))]
#[derive(Clone, Debug)]
pub struct Packet {
    /// The fields decoded into their members, in packet order.
    pub index: crate::packets::PacketIndex,
    /// Field 0x03.
    pub llh_position: crate::gnss_data::LlhPosition,
    /// Field 0x04.
    pub ecef_position: crate::gnss_data::EcefPosition,
    /// Field 0x05.
    pub ned_velocity: crate::gnss_data::NedVelocity,
    /// Field 0x06.
    pub ecef_velocity: crate::gnss_data::EcefVelocity,
    /// Field 0x07.
    pub dop: crate::gnss_data::Dop,
    /// Field 0x08.
    pub utc_time: crate::gnss_data::UtcTime,
    /// Field 0x09.
    pub gps_time: crate::gnss_data::GpsTime,
    /// Field 0x0A.
    pub clock_info: crate::gnss_data::ClockInfo,
    /// Field 0x0B.
    pub fix_info: crate::gnss_data::FixInfo,
    /// Field 0x0C.
    pub sv_info: crate::gnss_data::SvInfo,
    /// Field 0x0D.
    pub hardware_status: crate::gnss_data::HardwareStatus,
    /// Field 0x0E.
    pub dgnss_info: crate::gnss_data::DgnssInfo,
    /// Field 0x0F.
    pub dgnss_channel_status: crate::gnss_data::DgnssChannelStatus,
    /// Field 0xD0 (shared).
    pub event_source: crate::shared::EventSource,
    /// Field 0xD3 (shared).
    pub gps_timestamp: crate::shared::GpsTimestamp,
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

#[cfg(any(feature = "set-gnss-data", not(feature = "select-sets")))]
impl Packet {
    /// Nothing decoded, every member zero.
    pub const ZERO: Self = Self {
        index: crate::packets::PacketIndex::EMPTY,
        llh_position: <crate::gnss_data::LlhPosition as crate::wire::Wire>::ZERO,
        ecef_position: <crate::gnss_data::EcefPosition as crate::wire::Wire>::ZERO,
        ned_velocity: <crate::gnss_data::NedVelocity as crate::wire::Wire>::ZERO,
        ecef_velocity: <crate::gnss_data::EcefVelocity as crate::wire::Wire>::ZERO,
        dop: <crate::gnss_data::Dop as crate::wire::Wire>::ZERO,
        utc_time: <crate::gnss_data::UtcTime as crate::wire::Wire>::ZERO,
        gps_time: <crate::gnss_data::GpsTime as crate::wire::Wire>::ZERO,
        clock_info: <crate::gnss_data::ClockInfo as crate::wire::Wire>::ZERO,
        fix_info: <crate::gnss_data::FixInfo as crate::wire::Wire>::ZERO,
        sv_info: <crate::gnss_data::SvInfo as crate::wire::Wire>::ZERO,
        hardware_status: <crate::gnss_data::HardwareStatus as crate::wire::Wire>::ZERO,
        dgnss_info: <crate::gnss_data::DgnssInfo as crate::wire::Wire>::ZERO,
        dgnss_channel_status: <crate::gnss_data::DgnssChannelStatus as crate::wire::Wire>::ZERO,
        event_source: <crate::shared::EventSource as crate::wire::Wire>::ZERO,
        gps_timestamp: <crate::shared::GpsTimestamp as crate::wire::Wire>::ZERO,
        delta_time: <crate::shared::DeltaTime as crate::wire::Wire>::ZERO,
        reference_timestamp: <crate::shared::ReferenceTimestamp as crate::wire::Wire>::ZERO,
        reference_time_delta: <crate::shared::ReferenceTimeDelta as crate::wire::Wire>::ZERO,
        external_timestamp: <crate::shared::ExternalTimestamp as crate::wire::Wire>::ZERO,
        external_time_delta: <crate::shared::ExternalTimeDelta as crate::wire::Wire>::ZERO,
    };
}

#[cfg(any(feature = "set-gnss-data", not(feature = "select-sets")))]
impl Default for Packet {
    fn default() -> Self {
        Self::ZERO
    }
}

#[cfg(any(feature = "set-gnss-data", not(feature = "select-sets")))]
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
            0x03 | 0x04
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
            0x03 => match <&[u8; 42]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.llh_position;
                    s.latitude = crate::packets::ld(d, 0);
                    s.longitude = crate::packets::ld(d, 8);
                    s.ellipsoid_height = crate::packets::ld(d, 16);
                    s.msl_height = crate::packets::ld(d, 24);
                    s.horizontal_accuracy = crate::packets::ld(d, 32);
                    s.vertical_accuracy = crate::packets::ld(d, 36);
                    s.valid_flags = crate::packets::ld(d, 40);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.llh_position),
            },
            0x04 => match <&[u8; 30]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.ecef_position;
                    s.position[0] = crate::packets::ld(d, 0);
                    s.position[1] = crate::packets::ld(d, 8);
                    s.position[2] = crate::packets::ld(d, 16);
                    s.position_accuracy = crate::packets::ld(d, 24);
                    s.valid_flags = crate::packets::ld(d, 28);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.ecef_position),
            },
            0x05 => match <&[u8; 34]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.ned_velocity;
                    s.velocity[0] = crate::packets::ld(d, 0);
                    s.velocity[1] = crate::packets::ld(d, 4);
                    s.velocity[2] = crate::packets::ld(d, 8);
                    s.speed = crate::packets::ld(d, 12);
                    s.ground_speed = crate::packets::ld(d, 16);
                    s.heading = crate::packets::ld(d, 20);
                    s.speed_accuracy = crate::packets::ld(d, 24);
                    s.heading_accuracy = crate::packets::ld(d, 28);
                    s.valid_flags = crate::packets::ld(d, 32);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.ned_velocity),
            },
            0x06 => match <&[u8; 18]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.ecef_velocity;
                    s.velocity[0] = crate::packets::ld(d, 0);
                    s.velocity[1] = crate::packets::ld(d, 4);
                    s.velocity[2] = crate::packets::ld(d, 8);
                    s.velocity_accuracy = crate::packets::ld(d, 12);
                    s.valid_flags = crate::packets::ld(d, 16);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.ecef_velocity),
            },
            0x07 => match <&[u8; 30]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.dop;
                    s.gdop = crate::packets::ld(d, 0);
                    s.pdop = crate::packets::ld(d, 4);
                    s.hdop = crate::packets::ld(d, 8);
                    s.vdop = crate::packets::ld(d, 12);
                    s.tdop = crate::packets::ld(d, 16);
                    s.ndop = crate::packets::ld(d, 20);
                    s.edop = crate::packets::ld(d, 24);
                    s.valid_flags = crate::packets::ld(d, 28);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.dop),
            },
            0x08 => match <&[u8; 13]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.utc_time;
                    s.year = crate::packets::ld(d, 0);
                    s.month = crate::packets::ld(d, 2);
                    s.day = crate::packets::ld(d, 3);
                    s.hour = crate::packets::ld(d, 4);
                    s.minute = crate::packets::ld(d, 5);
                    s.second = crate::packets::ld(d, 6);
                    s.millisecond = crate::packets::ld(d, 7);
                    s.valid_flags = crate::packets::ld(d, 11);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.utc_time),
            },
            0x09 => match <&[u8; 12]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.gps_time;
                    s.tow = crate::packets::ld(d, 0);
                    s.week_number = crate::packets::ld(d, 8);
                    s.valid_flags = crate::packets::ld(d, 10);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.gps_time),
            },
            0x0A => match <&[u8; 26]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.clock_info;
                    s.bias = crate::packets::ld(d, 0);
                    s.drift = crate::packets::ld(d, 8);
                    s.accuracy_estimate = crate::packets::ld(d, 16);
                    s.valid_flags = crate::packets::ld(d, 24);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.clock_info),
            },
            0x0B => match <&[u8; 6]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.fix_info;
                    s.fix_type = crate::packets::ld(d, 0);
                    s.num_sv = crate::packets::ld(d, 1);
                    s.fix_flags = crate::packets::ld(d, 2);
                    s.valid_flags = crate::packets::ld(d, 4);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.fix_info),
            },
            0x0C => match <&[u8; 12]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.sv_info;
                    s.channel = crate::packets::ld(d, 0);
                    s.sv_id = crate::packets::ld(d, 1);
                    s.carrier_to_noise_ratio = crate::packets::ld(d, 2);
                    s.azimuth = crate::packets::ld(d, 4);
                    s.elevation = crate::packets::ld(d, 6);
                    s.sv_flags = crate::packets::ld(d, 8);
                    s.valid_flags = crate::packets::ld(d, 10);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.sv_info),
            },
            0x0D => match <&[u8; 5]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.hardware_status;
                    s.receiver_state = crate::packets::ld(d, 0);
                    s.antenna_state = crate::packets::ld(d, 1);
                    s.antenna_power = crate::packets::ld(d, 2);
                    s.valid_flags = crate::packets::ld(d, 3);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.hardware_status),
            },
            0x0E => match <&[u8; 12]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.dgnss_info;
                    s.newest_age = crate::packets::ld(d, 0);
                    s.base_station_id = crate::packets::ld(d, 4);
                    s.base_station_status = crate::packets::ld(d, 6);
                    s.num_channels = crate::packets::ld(d, 8);
                    s.valid_flags = crate::packets::ld(d, 10);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.dgnss_info),
            },
            0x0F => match <&[u8; 15]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.dgnss_channel_status;
                    s.sv_id = crate::packets::ld(d, 0);
                    s.age = crate::packets::ld(d, 1);
                    s.pseudorange_correction = crate::packets::ld(d, 5);
                    s.pseudorange_rate_correction = crate::packets::ld(d, 9);
                    s.valid_flags = crate::packets::ld(d, 13);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.dgnss_channel_status),
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
                    let s = &mut self.gps_timestamp;
                    s.tow = crate::packets::ld(d, 0);
                    s.week_number = crate::packets::ld(d, 8);
                    s.valid_flags = crate::packets::ld(d, 10);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.gps_timestamp),
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
            0x03 => Some(crate::FieldValue::GnssData(
                crate::gnss_data::SetField::LlhPosition(self.llh_position),
            )),
            0x04 => Some(crate::FieldValue::GnssData(
                crate::gnss_data::SetField::EcefPosition(self.ecef_position),
            )),
            0x05 => Some(crate::FieldValue::GnssData(
                crate::gnss_data::SetField::NedVelocity(self.ned_velocity),
            )),
            0x06 => Some(crate::FieldValue::GnssData(
                crate::gnss_data::SetField::EcefVelocity(self.ecef_velocity),
            )),
            0x07 => Some(crate::FieldValue::GnssData(
                crate::gnss_data::SetField::Dop(self.dop),
            )),
            0x08 => Some(crate::FieldValue::GnssData(
                crate::gnss_data::SetField::UtcTime(self.utc_time),
            )),
            0x09 => Some(crate::FieldValue::GnssData(
                crate::gnss_data::SetField::GpsTime(self.gps_time),
            )),
            0x0A => Some(crate::FieldValue::GnssData(
                crate::gnss_data::SetField::ClockInfo(self.clock_info),
            )),
            0x0B => Some(crate::FieldValue::GnssData(
                crate::gnss_data::SetField::FixInfo(self.fix_info),
            )),
            0x0C => Some(crate::FieldValue::GnssData(
                crate::gnss_data::SetField::SvInfo(self.sv_info),
            )),
            0x0D => Some(crate::FieldValue::GnssData(
                crate::gnss_data::SetField::HardwareStatus(self.hardware_status),
            )),
            0x0E => Some(crate::FieldValue::GnssData(
                crate::gnss_data::SetField::DgnssInfo(self.dgnss_info),
            )),
            0x0F => Some(crate::FieldValue::GnssData(
                crate::gnss_data::SetField::DgnssChannelStatus(self.dgnss_channel_status),
            )),
            0xD0 => Some(crate::FieldValue::Shared(
                crate::shared::SetField::EventSource(self.event_source),
            )),
            0xD3 => Some(crate::FieldValue::Shared(
                crate::shared::SetField::GpsTimestamp(self.gps_timestamp),
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
#[cfg(any(feature = "set-gnss-data", not(feature = "select-sets")))]
pub fn decode_packet(
    payload: &[u8],
    out: &mut Packet,
    other: impl FnMut(crate::fields::FieldItem<'_>),
) -> usize {
    crate::packets::decode_set_packet(payload, out, other)
}
