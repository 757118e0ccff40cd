//! GNSS Receiver 2 Data Set. Data from the second internal GNSS receiver: position, velocity, time, fix and hardware state, clock, leap seconds and SBAS status. Base rate 5 Hz.
//!
//! Descriptor set 0x92 (data set):
//! one struct per field layout, and `SetField`, the enum of all its fields.

/// Descriptor set of this module.
pub const SET: u8 = 0x92;

/// GNSS LLH position. Receiver position in the WGS84 geodetic frame (latitude, longitude, heights) with accuracy estimates.
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
    pub const SET: u8 = 0x92;
}

impl crate::wire::Layout for LlhPosition {
    const DESCRIPTOR: u8 = 0x03;
    const DESCRIPTOR_SET: Option<u8> = Some(0x92);
    const NAME: &'static str = "llh_position";
}

/// GNSS ECEF position. Receiver position in the Earth-centred, Earth-fixed frame with its accuracy estimate.
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
    pub const SET: u8 = 0x92;
}

impl crate::wire::Layout for EcefPosition {
    const DESCRIPTOR: u8 = 0x04;
    const DESCRIPTOR_SET: Option<u8> = Some(0x92);
    const NAME: &'static str = "ecef_position";
}

/// GNSS NED velocity. Receiver velocity in the north-east-down frame, with 3D and ground speed, heading and accuracy estimates.
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
    pub const SET: u8 = 0x92;
}

impl crate::wire::Layout for NedVelocity {
    const DESCRIPTOR: u8 = 0x05;
    const DESCRIPTOR_SET: Option<u8> = Some(0x92);
    const NAME: &'static str = "ned_velocity";
}

/// GNSS ECEF velocity. Receiver velocity in the Earth-centred, Earth-fixed frame with its accuracy estimate.
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
    pub const SET: u8 = 0x92;
}

impl crate::wire::Layout for EcefVelocity {
    const DESCRIPTOR: u8 = 0x06;
    const DESCRIPTOR_SET: Option<u8> = Some(0x92);
    const NAME: &'static str = "ecef_velocity";
}

/// GNSS dilution of precision. Geometric, position, horizontal, vertical, time, northing and easting DOP of the current solution.
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
    pub const SET: u8 = 0x92;
}

impl crate::wire::Layout for Dop {
    const DESCRIPTOR: u8 = 0x07;
    const DESCRIPTOR_SET: Option<u8> = Some(0x92);
    const NAME: &'static str = "dop";
}

/// GNSS UTC time. UTC date and time of the GNSS solution, with a flag telling whether the leap seconds are known.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UtcTime {
    /// Year.
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
    /// Millisecond (0-999). Units: ms.
    pub millisecond: u32,
    /// Validity of the date/time and of the leap seconds.
    pub valid_flags: crate::types::GnssUtcTimeValidFlagsCv7,
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
        valid_flags: <crate::types::GnssUtcTimeValidFlagsCv7 as crate::wire::Wire>::ZERO,
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
            <crate::types::GnssUtcTimeValidFlagsCv7 as crate::wire::Wire>::decode(r)
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
            <crate::types::GnssUtcTimeValidFlagsCv7 as crate::json_read::FromJson>::from_json,
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
    pub const SET: u8 = 0x92;
}

impl crate::wire::Layout for UtcTime {
    const DESCRIPTOR: u8 = 0x08;
    const DESCRIPTOR_SET: Option<u8> = Some(0x92);
    const NAME: &'static str = "utc_time";
}

/// GNSS GPS time. GPS time of week and week number of the GNSS solution.
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
    pub const SET: u8 = 0x92;
}

impl crate::wire::Layout for GpsTime {
    const DESCRIPTOR: u8 = 0x09;
    const DESCRIPTOR_SET: Option<u8> = Some(0x92);
    const NAME: &'static str = "gps_time";
}

/// GNSS fix information. Fix type (including RTK float/fixed and differential), number of satellites used and corrections applied.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FixInfo {
    /// Type of fix.
    pub fix_type: crate::types::GnssFixTypeCv7,
    /// Number of satellites used in the solution.
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
        fix_type: <crate::types::GnssFixTypeCv7 as crate::wire::Wire>::ZERO,
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
        let p_fix_type = <crate::types::GnssFixTypeCv7 as crate::wire::Wire>::decode(r)
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
            <crate::types::GnssFixTypeCv7 as crate::json_read::FromJson>::from_json,
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
    pub const SET: u8 = 0x92;
}

impl crate::wire::Layout for FixInfo {
    const DESCRIPTOR: u8 = 0x0B;
    const DESCRIPTOR_SET: Option<u8> = Some(0x92);
    const NAME: &'static str = "fix_info";
}

/// GNSS hardware status. Power state of the receiver, state of the antenna connection and whether the antenna is powered.
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
    pub const SET: u8 = 0x92;
}

impl crate::wire::Layout for HardwareStatus {
    const DESCRIPTOR: u8 = 0x0D;
    const DESCRIPTOR_SET: Option<u8> = Some(0x92);
    const NAME: &'static str = "hardware_status";
}

/// GNSS clock information 2. Receiver clock bias and drift, with an accuracy estimate for each.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClockInfo2 {
    /// Receiver clock bias. Units: s.
    pub bias: f64,
    /// Receiver clock drift. Units: s/s.
    pub drift: f64,
    /// Clock bias accuracy estimate. Units: s.
    pub bias_accuracy_estimate: f64,
    /// Clock drift accuracy estimate. Units: s/s.
    pub drift_accuracy_estimate: f64,
    /// Which values are valid.
    pub valid_flags: crate::types::GnssClockInfo2ValidFlags,
}

impl Default for ClockInfo2 {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ClockInfo2 {
    const ZERO: Self = Self {
        bias: <f64 as crate::wire::Wire>::ZERO,
        drift: <f64 as crate::wire::Wire>::ZERO,
        bias_accuracy_estimate: <f64 as crate::wire::Wire>::ZERO,
        drift_accuracy_estimate: <f64 as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::GnssClockInfo2ValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(34);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_bias = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("bias"))?;
        let p_drift = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("drift"))?;
        let p_bias_accuracy_estimate =
            <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("bias_accuracy_estimate"))?;
        let p_drift_accuracy_estimate =
            <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("drift_accuracy_estimate"))?;
        let p_valid_flags =
            <crate::types::GnssClockInfo2ValidFlags as crate::wire::Wire>::decode(r)
                .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            bias: p_bias,
            drift: p_drift,
            bias_accuracy_estimate: p_bias_accuracy_estimate,
            drift_accuracy_estimate: p_drift_accuracy_estimate,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.bias;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("bias"))?;
        let v = &self.drift;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("drift"))?;
        let v = &self.bias_accuracy_estimate;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("bias_accuracy_estimate"))?;
        let v = &self.drift_accuracy_estimate;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("drift_accuracy_estimate"))?;
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
        let v = &self.bias_accuracy_estimate;
        crate::json::key(w, &mut first, "bias_accuracy_estimate")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.drift_accuracy_estimate;
        crate::json::key(w, &mut first, "drift_accuracy_estimate")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ClockInfo2 {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "bias",
                "drift",
                "bias_accuracy_estimate",
                "drift_accuracy_estimate",
                "valid_flags",
            ],
        )?;
        let p_bias = o.req("bias", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_drift = o.req("drift", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_bias_accuracy_estimate = o.req(
            "bias_accuracy_estimate",
            <f64 as crate::json_read::FromJson>::from_json,
        )?;
        let p_drift_accuracy_estimate = o.req(
            "drift_accuracy_estimate",
            <f64 as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::GnssClockInfo2ValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            bias: p_bias,
            drift: p_drift,
            bias_accuracy_estimate: p_bias_accuracy_estimate,
            drift_accuracy_estimate: p_drift_accuracy_estimate,
            valid_flags: p_valid_flags,
        })
    }
}

impl ClockInfo2 {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x92;
}

impl crate::wire::Layout for ClockInfo2 {
    const DESCRIPTOR: u8 = 0x10;
    const DESCRIPTOR_SET: Option<u8> = Some(0x92);
    const NAME: &'static str = "clock_info_2";
}

/// GPS leap seconds. Number of leap seconds between GPS time and UTC.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GpsLeapSeconds {
    /// GPS - UTC leap seconds. Units: s.
    pub leap_seconds: u8,
    /// Validity of the leap seconds.
    pub valid_flags: crate::types::GnssLeapSecondsValidFlags,
}

impl Default for GpsLeapSeconds {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GpsLeapSeconds {
    const ZERO: Self = Self {
        leap_seconds: <u8 as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::GnssLeapSecondsValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(3);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_leap_seconds =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("leap_seconds"))?;
        let p_valid_flags =
            <crate::types::GnssLeapSecondsValidFlags as crate::wire::Wire>::decode(r)
                .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            leap_seconds: p_leap_seconds,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.leap_seconds;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("leap_seconds"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.leap_seconds;
        crate::json::key(w, &mut first, "leap_seconds")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GpsLeapSeconds {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["leap_seconds", "valid_flags"])?;
        let p_leap_seconds = o.req(
            "leap_seconds",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::GnssLeapSecondsValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            leap_seconds: p_leap_seconds,
            valid_flags: p_valid_flags,
        })
    }
}

impl GpsLeapSeconds {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x92;
}

impl crate::wire::Layout for GpsLeapSeconds {
    const DESCRIPTOR: u8 = 0x11;
    const DESCRIPTOR_SET: Option<u8> = Some(0x92);
    const NAME: &'static str = "gps_leap_seconds";
}

/// SBAS information. SBAS system and satellite in use, number of corrections and the service status, with the GPS time.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SbasInfo {
    /// GPS time of week. Units: s.
    pub tow: f64,
    /// GPS week number (since 1980). Units: weeks.
    pub week_number: u16,
    /// SBAS system.
    pub sbas_system: crate::types::GnssSbasSystem,
    /// SBAS satellite id.
    pub sbas_id: u8,
    /// Number of SBAS corrections.
    pub count: u8,
    /// Status of the SBAS service.
    pub sbas_status: crate::types::GnssSbasStatus,
    /// Which values are valid.
    pub valid_flags: crate::types::GnssSbasInfoValidFlags,
}

impl Default for SbasInfo {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SbasInfo {
    const ZERO: Self = Self {
        tow: <f64 as crate::wire::Wire>::ZERO,
        week_number: <u16 as crate::wire::Wire>::ZERO,
        sbas_system: <crate::types::GnssSbasSystem as crate::wire::Wire>::ZERO,
        sbas_id: <u8 as crate::wire::Wire>::ZERO,
        count: <u8 as crate::wire::Wire>::ZERO,
        sbas_status: <crate::types::GnssSbasStatus as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::GnssSbasInfoValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(16);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_tow = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("tow"))?;
        let p_week_number =
            <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("week_number"))?;
        let p_sbas_system = <crate::types::GnssSbasSystem as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("sbas_system"))?;
        let p_sbas_id = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("sbas_id"))?;
        let p_count = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("count"))?;
        let p_sbas_status = <crate::types::GnssSbasStatus as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("sbas_status"))?;
        let p_valid_flags = <crate::types::GnssSbasInfoValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            tow: p_tow,
            week_number: p_week_number,
            sbas_system: p_sbas_system,
            sbas_id: p_sbas_id,
            count: p_count,
            sbas_status: p_sbas_status,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.tow;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("tow"))?;
        let v = &self.week_number;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("week_number"))?;
        let v = &self.sbas_system;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("sbas_system"))?;
        let v = &self.sbas_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("sbas_id"))?;
        let v = &self.count;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("count"))?;
        let v = &self.sbas_status;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("sbas_status"))?;
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
        let v = &self.sbas_system;
        crate::json::key(w, &mut first, "sbas_system")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.sbas_id;
        crate::json::key(w, &mut first, "sbas_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.count;
        crate::json::key(w, &mut first, "count")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.sbas_status;
        crate::json::key(w, &mut first, "sbas_status")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SbasInfo {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "tow",
                "week_number",
                "sbas_system",
                "sbas_id",
                "count",
                "sbas_status",
                "valid_flags",
            ],
        )?;
        let p_tow = o.req("tow", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_week_number = o.req(
            "week_number",
            <u16 as crate::json_read::FromJson>::from_json,
        )?;
        let p_sbas_system = o.req(
            "sbas_system",
            <crate::types::GnssSbasSystem as crate::json_read::FromJson>::from_json,
        )?;
        let p_sbas_id = o.req("sbas_id", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_count = o.req("count", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_sbas_status = o.req(
            "sbas_status",
            <crate::types::GnssSbasStatus as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::GnssSbasInfoValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            tow: p_tow,
            week_number: p_week_number,
            sbas_system: p_sbas_system,
            sbas_id: p_sbas_id,
            count: p_count,
            sbas_status: p_sbas_status,
            valid_flags: p_valid_flags,
        })
    }
}

impl SbasInfo {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x92;
}

impl crate::wire::Layout for SbasInfo {
    const DESCRIPTOR: u8 = 0x12;
    const DESCRIPTOR_SET: Option<u8> = Some(0x92);
    const NAME: &'static str = "sbas_info";
}

/// Satellite status. Sky position and health of one satellite; one field per satellite in view.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SatelliteStatus {
    /// Index of this field among the satellite status fields of this epoch.
    pub index: u8,
    /// Number of satellite status fields in this epoch.
    pub count: u8,
    /// GPS time of week. Units: s.
    pub tow: f64,
    /// GPS week number since 1980. Units: weeks.
    pub week_number: u16,
    /// Constellation of the satellite.
    pub gnss_id: crate::types::GnssConstellationId,
    /// Satellite number within its constellation.
    pub satellite_id: u8,
    /// Elevation of the satellite seen from the receiver. Units: deg.
    pub elevation: f32,
    /// Azimuth of the satellite seen from the receiver. Units: deg.
    pub azimuth: f32,
    /// True if the satellite is healthy.
    pub health: bool,
    /// Which parameters are valid.
    pub valid_flags: crate::types::GnssSatelliteStatusValidFlags,
}

impl Default for SatelliteStatus {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SatelliteStatus {
    const ZERO: Self = Self {
        index: <u8 as crate::wire::Wire>::ZERO,
        count: <u8 as crate::wire::Wire>::ZERO,
        tow: <f64 as crate::wire::Wire>::ZERO,
        week_number: <u16 as crate::wire::Wire>::ZERO,
        gnss_id: <crate::types::GnssConstellationId as crate::wire::Wire>::ZERO,
        satellite_id: <u8 as crate::wire::Wire>::ZERO,
        elevation: <f32 as crate::wire::Wire>::ZERO,
        azimuth: <f32 as crate::wire::Wire>::ZERO,
        health: <bool as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::GnssSatelliteStatusValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(25);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_index = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("index"))?;
        let p_count = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("count"))?;
        let p_tow = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("tow"))?;
        let p_week_number =
            <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("week_number"))?;
        let p_gnss_id = <crate::types::GnssConstellationId as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("gnss_id"))?;
        let p_satellite_id =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("satellite_id"))?;
        let p_elevation = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("elevation"))?;
        let p_azimuth = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("azimuth"))?;
        let p_health = <bool as crate::wire::Wire>::decode(r).map_err(|e| e.at("health"))?;
        let p_valid_flags =
            <crate::types::GnssSatelliteStatusValidFlags as crate::wire::Wire>::decode(r)
                .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            index: p_index,
            count: p_count,
            tow: p_tow,
            week_number: p_week_number,
            gnss_id: p_gnss_id,
            satellite_id: p_satellite_id,
            elevation: p_elevation,
            azimuth: p_azimuth,
            health: p_health,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.index;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("index"))?;
        let v = &self.count;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("count"))?;
        let v = &self.tow;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("tow"))?;
        let v = &self.week_number;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("week_number"))?;
        let v = &self.gnss_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("gnss_id"))?;
        let v = &self.satellite_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("satellite_id"))?;
        let v = &self.elevation;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("elevation"))?;
        let v = &self.azimuth;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("azimuth"))?;
        let v = &self.health;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("health"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.index;
        crate::json::key(w, &mut first, "index")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.count;
        crate::json::key(w, &mut first, "count")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.tow;
        crate::json::key(w, &mut first, "tow")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.week_number;
        crate::json::key(w, &mut first, "week_number")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.gnss_id;
        crate::json::key(w, &mut first, "gnss_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.satellite_id;
        crate::json::key(w, &mut first, "satellite_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.elevation;
        crate::json::key(w, &mut first, "elevation")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.azimuth;
        crate::json::key(w, &mut first, "azimuth")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.health;
        crate::json::key(w, &mut first, "health")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SatelliteStatus {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "index",
                "count",
                "tow",
                "week_number",
                "gnss_id",
                "satellite_id",
                "elevation",
                "azimuth",
                "health",
                "valid_flags",
            ],
        )?;
        let p_index = o.req("index", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_count = o.req("count", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_tow = o.req("tow", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_week_number = o.req(
            "week_number",
            <u16 as crate::json_read::FromJson>::from_json,
        )?;
        let p_gnss_id = o.req(
            "gnss_id",
            <crate::types::GnssConstellationId as crate::json_read::FromJson>::from_json,
        )?;
        let p_satellite_id = o.req(
            "satellite_id",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_elevation = o.req("elevation", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_azimuth = o.req("azimuth", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_health = o.req("health", <bool as crate::json_read::FromJson>::from_json)?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::GnssSatelliteStatusValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            index: p_index,
            count: p_count,
            tow: p_tow,
            week_number: p_week_number,
            gnss_id: p_gnss_id,
            satellite_id: p_satellite_id,
            elevation: p_elevation,
            azimuth: p_azimuth,
            health: p_health,
            valid_flags: p_valid_flags,
        })
    }
}

impl SatelliteStatus {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x92;
}

impl crate::wire::Layout for SatelliteStatus {
    const DESCRIPTOR: u8 = 0x20;
    const DESCRIPTOR_SET: Option<u8> = Some(0x92);
    const NAME: &'static str = "satellite_status";
}

/// Raw observation. Raw pseudorange, carrier phase and Doppler of one signal; one field per tracked signal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Raw {
    /// Index of this field among the raw observation fields of this epoch.
    pub index: u8,
    /// Number of raw observation fields in this epoch.
    pub count: u8,
    /// GPS time of week. Units: s.
    pub tow: f64,
    /// GPS week number since 1980. Units: weeks.
    pub week_number: u16,
    /// Receiver number (1, 2, ...), or the reference station id when the measurement comes from RTCM.
    pub receiver_id: u16,
    /// Receiver channel tracking this satellite.
    pub tracking_channel: u8,
    /// Constellation of the satellite.
    pub gnss_id: crate::types::GnssConstellationId,
    /// Satellite number within its constellation.
    pub satellite_id: u8,
    /// Signal the observation is made on.
    pub signal_id: crate::types::GnssSignalId,
    /// Carrier-to-noise density ratio. Units: dB-Hz.
    pub signal_strength: f32,
    /// Tracking state of the signal.
    pub quality: crate::types::GnssSignalQuality,
    /// Pseudorange. Units: m.
    pub pseudorange: f64,
    /// Carrier phase, in carrier periods. Units: cycles.
    pub carrier_phase: f64,
    /// Doppler shift. Units: Hz.
    pub doppler: f32,
    /// Uncertainty of the pseudorange. Units: m.
    pub range_uncert: f32,
    /// Uncertainty of the carrier phase, in carrier periods. Units: cycles.
    pub phase_uncert: f32,
    /// Uncertainty of the Doppler shift. Units: Hz.
    pub doppler_uncert: f32,
    /// Minimum time the carrier phase has been continuously locked; the largest value reported depends on the receiver. Units: s.
    pub lock_time: f32,
    /// Which parameters are valid.
    pub valid_flags: crate::types::GnssRawValidFlags,
}

impl Default for Raw {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for Raw {
    const ZERO: Self = Self {
        index: <u8 as crate::wire::Wire>::ZERO,
        count: <u8 as crate::wire::Wire>::ZERO,
        tow: <f64 as crate::wire::Wire>::ZERO,
        week_number: <u16 as crate::wire::Wire>::ZERO,
        receiver_id: <u16 as crate::wire::Wire>::ZERO,
        tracking_channel: <u8 as crate::wire::Wire>::ZERO,
        gnss_id: <crate::types::GnssConstellationId as crate::wire::Wire>::ZERO,
        satellite_id: <u8 as crate::wire::Wire>::ZERO,
        signal_id: <crate::types::GnssSignalId as crate::wire::Wire>::ZERO,
        signal_strength: <f32 as crate::wire::Wire>::ZERO,
        quality: <crate::types::GnssSignalQuality as crate::wire::Wire>::ZERO,
        pseudorange: <f64 as crate::wire::Wire>::ZERO,
        carrier_phase: <f64 as crate::wire::Wire>::ZERO,
        doppler: <f32 as crate::wire::Wire>::ZERO,
        range_uncert: <f32 as crate::wire::Wire>::ZERO,
        phase_uncert: <f32 as crate::wire::Wire>::ZERO,
        doppler_uncert: <f32 as crate::wire::Wire>::ZERO,
        lock_time: <f32 as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::GnssRawValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(61);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_index = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("index"))?;
        let p_count = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("count"))?;
        let p_tow = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("tow"))?;
        let p_week_number =
            <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("week_number"))?;
        let p_receiver_id =
            <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("receiver_id"))?;
        let p_tracking_channel =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("tracking_channel"))?;
        let p_gnss_id = <crate::types::GnssConstellationId as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("gnss_id"))?;
        let p_satellite_id =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("satellite_id"))?;
        let p_signal_id = <crate::types::GnssSignalId as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("signal_id"))?;
        let p_signal_strength =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("signal_strength"))?;
        let p_quality = <crate::types::GnssSignalQuality as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("quality"))?;
        let p_pseudorange =
            <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("pseudorange"))?;
        let p_carrier_phase =
            <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("carrier_phase"))?;
        let p_doppler = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("doppler"))?;
        let p_range_uncert =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("range_uncert"))?;
        let p_phase_uncert =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("phase_uncert"))?;
        let p_doppler_uncert =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("doppler_uncert"))?;
        let p_lock_time = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("lock_time"))?;
        let p_valid_flags = <crate::types::GnssRawValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            index: p_index,
            count: p_count,
            tow: p_tow,
            week_number: p_week_number,
            receiver_id: p_receiver_id,
            tracking_channel: p_tracking_channel,
            gnss_id: p_gnss_id,
            satellite_id: p_satellite_id,
            signal_id: p_signal_id,
            signal_strength: p_signal_strength,
            quality: p_quality,
            pseudorange: p_pseudorange,
            carrier_phase: p_carrier_phase,
            doppler: p_doppler,
            range_uncert: p_range_uncert,
            phase_uncert: p_phase_uncert,
            doppler_uncert: p_doppler_uncert,
            lock_time: p_lock_time,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.index;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("index"))?;
        let v = &self.count;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("count"))?;
        let v = &self.tow;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("tow"))?;
        let v = &self.week_number;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("week_number"))?;
        let v = &self.receiver_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("receiver_id"))?;
        let v = &self.tracking_channel;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("tracking_channel"))?;
        let v = &self.gnss_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("gnss_id"))?;
        let v = &self.satellite_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("satellite_id"))?;
        let v = &self.signal_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("signal_id"))?;
        let v = &self.signal_strength;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("signal_strength"))?;
        let v = &self.quality;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("quality"))?;
        let v = &self.pseudorange;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("pseudorange"))?;
        let v = &self.carrier_phase;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("carrier_phase"))?;
        let v = &self.doppler;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("doppler"))?;
        let v = &self.range_uncert;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("range_uncert"))?;
        let v = &self.phase_uncert;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("phase_uncert"))?;
        let v = &self.doppler_uncert;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("doppler_uncert"))?;
        let v = &self.lock_time;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("lock_time"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.index;
        crate::json::key(w, &mut first, "index")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.count;
        crate::json::key(w, &mut first, "count")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.tow;
        crate::json::key(w, &mut first, "tow")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.week_number;
        crate::json::key(w, &mut first, "week_number")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.receiver_id;
        crate::json::key(w, &mut first, "receiver_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.tracking_channel;
        crate::json::key(w, &mut first, "tracking_channel")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.gnss_id;
        crate::json::key(w, &mut first, "gnss_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.satellite_id;
        crate::json::key(w, &mut first, "satellite_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.signal_id;
        crate::json::key(w, &mut first, "signal_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.signal_strength;
        crate::json::key(w, &mut first, "signal_strength")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.quality;
        crate::json::key(w, &mut first, "quality")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.pseudorange;
        crate::json::key(w, &mut first, "pseudorange")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.carrier_phase;
        crate::json::key(w, &mut first, "carrier_phase")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.doppler;
        crate::json::key(w, &mut first, "doppler")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.range_uncert;
        crate::json::key(w, &mut first, "range_uncert")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.phase_uncert;
        crate::json::key(w, &mut first, "phase_uncert")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.doppler_uncert;
        crate::json::key(w, &mut first, "doppler_uncert")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.lock_time;
        crate::json::key(w, &mut first, "lock_time")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for Raw {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "index",
                "count",
                "tow",
                "week_number",
                "receiver_id",
                "tracking_channel",
                "gnss_id",
                "satellite_id",
                "signal_id",
                "signal_strength",
                "quality",
                "pseudorange",
                "carrier_phase",
                "doppler",
                "range_uncert",
                "phase_uncert",
                "doppler_uncert",
                "lock_time",
                "valid_flags",
            ],
        )?;
        let p_index = o.req("index", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_count = o.req("count", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_tow = o.req("tow", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_week_number = o.req(
            "week_number",
            <u16 as crate::json_read::FromJson>::from_json,
        )?;
        let p_receiver_id = o.req(
            "receiver_id",
            <u16 as crate::json_read::FromJson>::from_json,
        )?;
        let p_tracking_channel = o.req(
            "tracking_channel",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_gnss_id = o.req(
            "gnss_id",
            <crate::types::GnssConstellationId as crate::json_read::FromJson>::from_json,
        )?;
        let p_satellite_id = o.req(
            "satellite_id",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_signal_id = o.req(
            "signal_id",
            <crate::types::GnssSignalId as crate::json_read::FromJson>::from_json,
        )?;
        let p_signal_strength = o.req(
            "signal_strength",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_quality = o.req(
            "quality",
            <crate::types::GnssSignalQuality as crate::json_read::FromJson>::from_json,
        )?;
        let p_pseudorange = o.req(
            "pseudorange",
            <f64 as crate::json_read::FromJson>::from_json,
        )?;
        let p_carrier_phase = o.req(
            "carrier_phase",
            <f64 as crate::json_read::FromJson>::from_json,
        )?;
        let p_doppler = o.req("doppler", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_range_uncert = o.req(
            "range_uncert",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_phase_uncert = o.req(
            "phase_uncert",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_doppler_uncert = o.req(
            "doppler_uncert",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_lock_time = o.req("lock_time", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::GnssRawValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            index: p_index,
            count: p_count,
            tow: p_tow,
            week_number: p_week_number,
            receiver_id: p_receiver_id,
            tracking_channel: p_tracking_channel,
            gnss_id: p_gnss_id,
            satellite_id: p_satellite_id,
            signal_id: p_signal_id,
            signal_strength: p_signal_strength,
            quality: p_quality,
            pseudorange: p_pseudorange,
            carrier_phase: p_carrier_phase,
            doppler: p_doppler,
            range_uncert: p_range_uncert,
            phase_uncert: p_phase_uncert,
            doppler_uncert: p_doppler_uncert,
            lock_time: p_lock_time,
            valid_flags: p_valid_flags,
        })
    }
}

impl Raw {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x92;
}

impl crate::wire::Layout for Raw {
    const DESCRIPTOR: u8 = 0x22;
    const DESCRIPTOR_SET: Option<u8> = Some(0x92);
    const NAME: &'static str = "raw";
}

/// GPS ephemeris. Broadcast ephemeris of one GPS satellite; one field per satellite.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GpsEphemeris {
    /// Index of this field among the ephemeris fields of this epoch.
    pub index: u8,
    /// Number of ephemeris fields in this epoch.
    pub count: u8,
    /// GPS time of week. Units: s.
    pub tow: f64,
    /// GPS week number since 1980. Units: weeks.
    pub week_number: u16,
    /// Satellite number within its constellation.
    pub satellite_id: u8,
    /// Satellite and signal health.
    pub health: u8,
    /// Issue of data, clock: changes whenever the clock data change; lines up data from different sources.
    pub iodc: u8,
    /// Issue of data, ephemeris.
    pub iode: u8,
    /// Reference time of the clock data. Units: s.
    pub t_oc: f64,
    /// Clock bias. Units: s.
    pub af0: f64,
    /// Clock drift. Units: s/s.
    pub af1: f64,
    /// Clock drift rate. Units: s/s^2.
    pub af2: f64,
    /// Group delay. Units: s.
    pub t_gd: f64,
    /// Inter-signal correction, L1. Units: s.
    pub isc_l1ca: f64,
    /// Inter-signal correction, L2 (or L5 when valid_flags.isc_l5 is set). Units: s.
    pub isc_l2c: f64,
    /// Reference time of the ephemeris. Units: s.
    pub t_oe: f64,
    /// Semi-major axis. Units: m.
    pub a: f64,
    /// Rate of the semi-major axis. Units: m/s.
    pub a_dot: f64,
    /// Mean anomaly at the reference time. Units: rad.
    pub mean_anomaly: f64,
    /// Mean motion difference from the computed value. Units: rad/s.
    pub delta_mean_motion: f64,
    /// Rate of the mean motion difference. Units: rad/s^2.
    pub delta_mean_motion_dot: f64,
    /// Orbit eccentricity (dimensionless).
    pub eccentricity: f64,
    /// Argument of perigee. Units: rad.
    pub argument_of_perigee: f64,
    /// Longitude of the ascending node. Units: rad.
    pub omega: f64,
    /// Rate of right ascension. Units: rad/s.
    pub omega_dot: f64,
    /// Inclination angle. Units: rad.
    pub inclination: f64,
    /// Rate of the inclination angle. Units: rad/s.
    pub inclination_dot: f64,
    /// Harmonic correction term, cosine, to the inclination. Units: rad.
    pub c_ic: f64,
    /// Harmonic correction term, sine, to the inclination. Units: rad.
    pub c_is: f64,
    /// Harmonic correction term, cosine, to the argument of latitude. Units: rad.
    pub c_uc: f64,
    /// Harmonic correction term, sine, to the argument of latitude. Units: rad.
    pub c_us: f64,
    /// Harmonic correction term, cosine, to the orbit radius. Units: m.
    pub c_rc: f64,
    /// Harmonic correction term, sine, to the orbit radius. Units: m.
    pub c_rs: f64,
    /// Which data are valid, and how isc_l2c is to be read.
    pub valid_flags: crate::types::GnssEphemerisValidFlags,
}

impl Default for GpsEphemeris {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GpsEphemeris {
    const ZERO: Self = Self {
        index: <u8 as crate::wire::Wire>::ZERO,
        count: <u8 as crate::wire::Wire>::ZERO,
        tow: <f64 as crate::wire::Wire>::ZERO,
        week_number: <u16 as crate::wire::Wire>::ZERO,
        satellite_id: <u8 as crate::wire::Wire>::ZERO,
        health: <u8 as crate::wire::Wire>::ZERO,
        iodc: <u8 as crate::wire::Wire>::ZERO,
        iode: <u8 as crate::wire::Wire>::ZERO,
        t_oc: <f64 as crate::wire::Wire>::ZERO,
        af0: <f64 as crate::wire::Wire>::ZERO,
        af1: <f64 as crate::wire::Wire>::ZERO,
        af2: <f64 as crate::wire::Wire>::ZERO,
        t_gd: <f64 as crate::wire::Wire>::ZERO,
        isc_l1ca: <f64 as crate::wire::Wire>::ZERO,
        isc_l2c: <f64 as crate::wire::Wire>::ZERO,
        t_oe: <f64 as crate::wire::Wire>::ZERO,
        a: <f64 as crate::wire::Wire>::ZERO,
        a_dot: <f64 as crate::wire::Wire>::ZERO,
        mean_anomaly: <f64 as crate::wire::Wire>::ZERO,
        delta_mean_motion: <f64 as crate::wire::Wire>::ZERO,
        delta_mean_motion_dot: <f64 as crate::wire::Wire>::ZERO,
        eccentricity: <f64 as crate::wire::Wire>::ZERO,
        argument_of_perigee: <f64 as crate::wire::Wire>::ZERO,
        omega: <f64 as crate::wire::Wire>::ZERO,
        omega_dot: <f64 as crate::wire::Wire>::ZERO,
        inclination: <f64 as crate::wire::Wire>::ZERO,
        inclination_dot: <f64 as crate::wire::Wire>::ZERO,
        c_ic: <f64 as crate::wire::Wire>::ZERO,
        c_is: <f64 as crate::wire::Wire>::ZERO,
        c_uc: <f64 as crate::wire::Wire>::ZERO,
        c_us: <f64 as crate::wire::Wire>::ZERO,
        c_rc: <f64 as crate::wire::Wire>::ZERO,
        c_rs: <f64 as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::GnssEphemerisValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(218);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_index = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("index"))?;
        let p_count = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("count"))?;
        let p_tow = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("tow"))?;
        let p_week_number =
            <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("week_number"))?;
        let p_satellite_id =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("satellite_id"))?;
        let p_health = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("health"))?;
        let p_iodc = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("iodc"))?;
        let p_iode = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("iode"))?;
        let p_t_oc = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("t_oc"))?;
        let p_af0 = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("af0"))?;
        let p_af1 = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("af1"))?;
        let p_af2 = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("af2"))?;
        let p_t_gd = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("t_gd"))?;
        let p_isc_l1ca = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("isc_l1ca"))?;
        let p_isc_l2c = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("isc_l2c"))?;
        let p_t_oe = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("t_oe"))?;
        let p_a = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("a"))?;
        let p_a_dot = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("a_dot"))?;
        let p_mean_anomaly =
            <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("mean_anomaly"))?;
        let p_delta_mean_motion =
            <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("delta_mean_motion"))?;
        let p_delta_mean_motion_dot =
            <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("delta_mean_motion_dot"))?;
        let p_eccentricity =
            <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("eccentricity"))?;
        let p_argument_of_perigee =
            <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("argument_of_perigee"))?;
        let p_omega = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("omega"))?;
        let p_omega_dot = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("omega_dot"))?;
        let p_inclination =
            <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("inclination"))?;
        let p_inclination_dot =
            <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("inclination_dot"))?;
        let p_c_ic = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("c_ic"))?;
        let p_c_is = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("c_is"))?;
        let p_c_uc = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("c_uc"))?;
        let p_c_us = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("c_us"))?;
        let p_c_rc = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("c_rc"))?;
        let p_c_rs = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("c_rs"))?;
        let p_valid_flags = <crate::types::GnssEphemerisValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            index: p_index,
            count: p_count,
            tow: p_tow,
            week_number: p_week_number,
            satellite_id: p_satellite_id,
            health: p_health,
            iodc: p_iodc,
            iode: p_iode,
            t_oc: p_t_oc,
            af0: p_af0,
            af1: p_af1,
            af2: p_af2,
            t_gd: p_t_gd,
            isc_l1ca: p_isc_l1ca,
            isc_l2c: p_isc_l2c,
            t_oe: p_t_oe,
            a: p_a,
            a_dot: p_a_dot,
            mean_anomaly: p_mean_anomaly,
            delta_mean_motion: p_delta_mean_motion,
            delta_mean_motion_dot: p_delta_mean_motion_dot,
            eccentricity: p_eccentricity,
            argument_of_perigee: p_argument_of_perigee,
            omega: p_omega,
            omega_dot: p_omega_dot,
            inclination: p_inclination,
            inclination_dot: p_inclination_dot,
            c_ic: p_c_ic,
            c_is: p_c_is,
            c_uc: p_c_uc,
            c_us: p_c_us,
            c_rc: p_c_rc,
            c_rs: p_c_rs,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.index;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("index"))?;
        let v = &self.count;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("count"))?;
        let v = &self.tow;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("tow"))?;
        let v = &self.week_number;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("week_number"))?;
        let v = &self.satellite_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("satellite_id"))?;
        let v = &self.health;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("health"))?;
        let v = &self.iodc;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("iodc"))?;
        let v = &self.iode;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("iode"))?;
        let v = &self.t_oc;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("t_oc"))?;
        let v = &self.af0;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("af0"))?;
        let v = &self.af1;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("af1"))?;
        let v = &self.af2;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("af2"))?;
        let v = &self.t_gd;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("t_gd"))?;
        let v = &self.isc_l1ca;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("isc_l1ca"))?;
        let v = &self.isc_l2c;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("isc_l2c"))?;
        let v = &self.t_oe;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("t_oe"))?;
        let v = &self.a;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("a"))?;
        let v = &self.a_dot;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("a_dot"))?;
        let v = &self.mean_anomaly;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("mean_anomaly"))?;
        let v = &self.delta_mean_motion;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("delta_mean_motion"))?;
        let v = &self.delta_mean_motion_dot;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("delta_mean_motion_dot"))?;
        let v = &self.eccentricity;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("eccentricity"))?;
        let v = &self.argument_of_perigee;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("argument_of_perigee"))?;
        let v = &self.omega;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("omega"))?;
        let v = &self.omega_dot;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("omega_dot"))?;
        let v = &self.inclination;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("inclination"))?;
        let v = &self.inclination_dot;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("inclination_dot"))?;
        let v = &self.c_ic;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("c_ic"))?;
        let v = &self.c_is;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("c_is"))?;
        let v = &self.c_uc;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("c_uc"))?;
        let v = &self.c_us;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("c_us"))?;
        let v = &self.c_rc;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("c_rc"))?;
        let v = &self.c_rs;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("c_rs"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.index;
        crate::json::key(w, &mut first, "index")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.count;
        crate::json::key(w, &mut first, "count")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.tow;
        crate::json::key(w, &mut first, "tow")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.week_number;
        crate::json::key(w, &mut first, "week_number")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.satellite_id;
        crate::json::key(w, &mut first, "satellite_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.health;
        crate::json::key(w, &mut first, "health")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.iodc;
        crate::json::key(w, &mut first, "iodc")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.iode;
        crate::json::key(w, &mut first, "iode")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.t_oc;
        crate::json::key(w, &mut first, "t_oc")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.af0;
        crate::json::key(w, &mut first, "af0")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.af1;
        crate::json::key(w, &mut first, "af1")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.af2;
        crate::json::key(w, &mut first, "af2")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.t_gd;
        crate::json::key(w, &mut first, "t_gd")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.isc_l1ca;
        crate::json::key(w, &mut first, "isc_l1ca")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.isc_l2c;
        crate::json::key(w, &mut first, "isc_l2c")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.t_oe;
        crate::json::key(w, &mut first, "t_oe")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.a;
        crate::json::key(w, &mut first, "a")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.a_dot;
        crate::json::key(w, &mut first, "a_dot")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.mean_anomaly;
        crate::json::key(w, &mut first, "mean_anomaly")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.delta_mean_motion;
        crate::json::key(w, &mut first, "delta_mean_motion")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.delta_mean_motion_dot;
        crate::json::key(w, &mut first, "delta_mean_motion_dot")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.eccentricity;
        crate::json::key(w, &mut first, "eccentricity")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.argument_of_perigee;
        crate::json::key(w, &mut first, "argument_of_perigee")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.omega;
        crate::json::key(w, &mut first, "omega")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.omega_dot;
        crate::json::key(w, &mut first, "omega_dot")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.inclination;
        crate::json::key(w, &mut first, "inclination")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.inclination_dot;
        crate::json::key(w, &mut first, "inclination_dot")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.c_ic;
        crate::json::key(w, &mut first, "c_ic")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.c_is;
        crate::json::key(w, &mut first, "c_is")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.c_uc;
        crate::json::key(w, &mut first, "c_uc")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.c_us;
        crate::json::key(w, &mut first, "c_us")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.c_rc;
        crate::json::key(w, &mut first, "c_rc")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.c_rs;
        crate::json::key(w, &mut first, "c_rs")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GpsEphemeris {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "index",
                "count",
                "tow",
                "week_number",
                "satellite_id",
                "health",
                "iodc",
                "iode",
                "t_oc",
                "af0",
                "af1",
                "af2",
                "t_gd",
                "isc_l1ca",
                "isc_l2c",
                "t_oe",
                "a",
                "a_dot",
                "mean_anomaly",
                "delta_mean_motion",
                "delta_mean_motion_dot",
                "eccentricity",
                "argument_of_perigee",
                "omega",
                "omega_dot",
                "inclination",
                "inclination_dot",
                "c_ic",
                "c_is",
                "c_uc",
                "c_us",
                "c_rc",
                "c_rs",
                "valid_flags",
            ],
        )?;
        let p_index = o.req("index", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_count = o.req("count", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_tow = o.req("tow", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_week_number = o.req(
            "week_number",
            <u16 as crate::json_read::FromJson>::from_json,
        )?;
        let p_satellite_id = o.req(
            "satellite_id",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_health = o.req("health", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_iodc = o.req("iodc", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_iode = o.req("iode", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_t_oc = o.req("t_oc", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_af0 = o.req("af0", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_af1 = o.req("af1", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_af2 = o.req("af2", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_t_gd = o.req("t_gd", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_isc_l1ca = o.req("isc_l1ca", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_isc_l2c = o.req("isc_l2c", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_t_oe = o.req("t_oe", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_a = o.req("a", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_a_dot = o.req("a_dot", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_mean_anomaly = o.req(
            "mean_anomaly",
            <f64 as crate::json_read::FromJson>::from_json,
        )?;
        let p_delta_mean_motion = o.req(
            "delta_mean_motion",
            <f64 as crate::json_read::FromJson>::from_json,
        )?;
        let p_delta_mean_motion_dot = o.req(
            "delta_mean_motion_dot",
            <f64 as crate::json_read::FromJson>::from_json,
        )?;
        let p_eccentricity = o.req(
            "eccentricity",
            <f64 as crate::json_read::FromJson>::from_json,
        )?;
        let p_argument_of_perigee = o.req(
            "argument_of_perigee",
            <f64 as crate::json_read::FromJson>::from_json,
        )?;
        let p_omega = o.req("omega", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_omega_dot = o.req("omega_dot", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_inclination = o.req(
            "inclination",
            <f64 as crate::json_read::FromJson>::from_json,
        )?;
        let p_inclination_dot = o.req(
            "inclination_dot",
            <f64 as crate::json_read::FromJson>::from_json,
        )?;
        let p_c_ic = o.req("c_ic", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_c_is = o.req("c_is", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_c_uc = o.req("c_uc", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_c_us = o.req("c_us", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_c_rc = o.req("c_rc", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_c_rs = o.req("c_rs", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::GnssEphemerisValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            index: p_index,
            count: p_count,
            tow: p_tow,
            week_number: p_week_number,
            satellite_id: p_satellite_id,
            health: p_health,
            iodc: p_iodc,
            iode: p_iode,
            t_oc: p_t_oc,
            af0: p_af0,
            af1: p_af1,
            af2: p_af2,
            t_gd: p_t_gd,
            isc_l1ca: p_isc_l1ca,
            isc_l2c: p_isc_l2c,
            t_oe: p_t_oe,
            a: p_a,
            a_dot: p_a_dot,
            mean_anomaly: p_mean_anomaly,
            delta_mean_motion: p_delta_mean_motion,
            delta_mean_motion_dot: p_delta_mean_motion_dot,
            eccentricity: p_eccentricity,
            argument_of_perigee: p_argument_of_perigee,
            omega: p_omega,
            omega_dot: p_omega_dot,
            inclination: p_inclination,
            inclination_dot: p_inclination_dot,
            c_ic: p_c_ic,
            c_is: p_c_is,
            c_uc: p_c_uc,
            c_us: p_c_us,
            c_rc: p_c_rc,
            c_rs: p_c_rs,
            valid_flags: p_valid_flags,
        })
    }
}

impl GpsEphemeris {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x92;
}

impl crate::wire::Layout for GpsEphemeris {
    const DESCRIPTOR: u8 = 0x61;
    const DESCRIPTOR_SET: Option<u8> = Some(0x92);
    const NAME: &'static str = "gps_ephemeris";
}

/// GLONASS ephemeris. Broadcast ephemeris of one GLONASS satellite; one field per satellite.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GlonassEphemeris {
    /// Index of this field among the ephemeris fields of this epoch.
    pub index: u8,
    /// Number of ephemeris fields in this epoch.
    pub count: u8,
    /// GPS time of week. Units: s.
    pub tow: f64,
    /// GPS week number since 1980. Units: weeks.
    pub week_number: u16,
    /// Satellite number within the constellation.
    pub satellite_id: u8,
    /// GLONASS frequency channel number (-7 to 24).
    pub freq_number: i8,
    /// Start time of the frame within the current day. Units: s.
    pub tk: u32,
    /// Reference time of the ephemeris. Units: s.
    pub tb: u32,
    /// Satellite type.
    pub sat_type: crate::types::GnssGlonassSatelliteType,
    /// Relative deviation of the carrier frequency from nominal (dimensionless).
    pub gamma: f64,
    /// Satellite time correction relative to GLONASS time. Units: s.
    pub tau_n: f64,
    /// Satellite position in the PZ-90 frame. Units: m.
    pub x: [f64; 3],
    /// Satellite velocity in the PZ-90 frame. Units: m/s.
    pub v: [f32; 3],
    /// Satellite acceleration due to perturbations, PZ-90 frame. Units: m/s^2.
    pub a: [f32; 3],
    /// Satellite health word Bn; non-zero means a malfunction.
    pub health: u8,
    /// Satellite operation mode (see the GLONASS ICD).
    pub p: u8,
    /// Day number within the four-year period. Units: days.
    pub nt: u8,
    /// Time difference between the L2 and L1 transmissions. Units: s.
    pub delta_tau_n: f32,
    /// User range accuracy index (see the GLONASS ICD).
    pub ft: u8,
    /// Age of the current information. Units: days.
    pub en: u8,
    /// Interval between adjacent values of tb. Units: min.
    pub p1: u8,
    /// 1 if tb is odd, 0 if even.
    pub p2: u8,
    /// Number of satellites in the almanac of this frame.
    pub p3: u8,
    /// Non-zero when ephemeris parameters are present.
    pub p4: u8,
    /// Which data are valid.
    pub valid_flags: crate::types::GnssGlonassEphemerisValidFlags,
}

impl Default for GlonassEphemeris {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GlonassEphemeris {
    const ZERO: Self = Self {
        index: <u8 as crate::wire::Wire>::ZERO,
        count: <u8 as crate::wire::Wire>::ZERO,
        tow: <f64 as crate::wire::Wire>::ZERO,
        week_number: <u16 as crate::wire::Wire>::ZERO,
        satellite_id: <u8 as crate::wire::Wire>::ZERO,
        freq_number: <i8 as crate::wire::Wire>::ZERO,
        tk: <u32 as crate::wire::Wire>::ZERO,
        tb: <u32 as crate::wire::Wire>::ZERO,
        sat_type: <crate::types::GnssGlonassSatelliteType as crate::wire::Wire>::ZERO,
        gamma: <f64 as crate::wire::Wire>::ZERO,
        tau_n: <f64 as crate::wire::Wire>::ZERO,
        x: <[f64; 3] as crate::wire::Wire>::ZERO,
        v: <[f32; 3] as crate::wire::Wire>::ZERO,
        a: <[f32; 3] as crate::wire::Wire>::ZERO,
        health: <u8 as crate::wire::Wire>::ZERO,
        p: <u8 as crate::wire::Wire>::ZERO,
        nt: <u8 as crate::wire::Wire>::ZERO,
        delta_tau_n: <f32 as crate::wire::Wire>::ZERO,
        ft: <u8 as crate::wire::Wire>::ZERO,
        en: <u8 as crate::wire::Wire>::ZERO,
        p1: <u8 as crate::wire::Wire>::ZERO,
        p2: <u8 as crate::wire::Wire>::ZERO,
        p3: <u8 as crate::wire::Wire>::ZERO,
        p4: <u8 as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::GnssGlonassEphemerisValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(102);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_index = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("index"))?;
        let p_count = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("count"))?;
        let p_tow = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("tow"))?;
        let p_week_number =
            <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("week_number"))?;
        let p_satellite_id =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("satellite_id"))?;
        let p_freq_number =
            <i8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("freq_number"))?;
        let p_tk = <u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("tk"))?;
        let p_tb = <u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("tb"))?;
        let p_sat_type = <crate::types::GnssGlonassSatelliteType as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("sat_type"))?;
        let p_gamma = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("gamma"))?;
        let p_tau_n = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("tau_n"))?;
        let p_x = <[f64; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("x"))?;
        let p_v = <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("v"))?;
        let p_a = <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("a"))?;
        let p_health = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("health"))?;
        let p_p = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("p"))?;
        let p_nt = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("nt"))?;
        let p_delta_tau_n =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("delta_tau_n"))?;
        let p_ft = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("ft"))?;
        let p_en = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("en"))?;
        let p_p1 = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("p1"))?;
        let p_p2 = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("p2"))?;
        let p_p3 = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("p3"))?;
        let p_p4 = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("p4"))?;
        let p_valid_flags =
            <crate::types::GnssGlonassEphemerisValidFlags as crate::wire::Wire>::decode(r)
                .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            index: p_index,
            count: p_count,
            tow: p_tow,
            week_number: p_week_number,
            satellite_id: p_satellite_id,
            freq_number: p_freq_number,
            tk: p_tk,
            tb: p_tb,
            sat_type: p_sat_type,
            gamma: p_gamma,
            tau_n: p_tau_n,
            x: p_x,
            v: p_v,
            a: p_a,
            health: p_health,
            p: p_p,
            nt: p_nt,
            delta_tau_n: p_delta_tau_n,
            ft: p_ft,
            en: p_en,
            p1: p_p1,
            p2: p_p2,
            p3: p_p3,
            p4: p_p4,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.index;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("index"))?;
        let v = &self.count;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("count"))?;
        let v = &self.tow;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("tow"))?;
        let v = &self.week_number;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("week_number"))?;
        let v = &self.satellite_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("satellite_id"))?;
        let v = &self.freq_number;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("freq_number"))?;
        let v = &self.tk;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("tk"))?;
        let v = &self.tb;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("tb"))?;
        let v = &self.sat_type;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("sat_type"))?;
        let v = &self.gamma;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("gamma"))?;
        let v = &self.tau_n;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("tau_n"))?;
        let v = &self.x;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("x"))?;
        let v = &self.v;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("v"))?;
        let v = &self.a;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("a"))?;
        let v = &self.health;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("health"))?;
        let v = &self.p;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("p"))?;
        let v = &self.nt;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("nt"))?;
        let v = &self.delta_tau_n;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("delta_tau_n"))?;
        let v = &self.ft;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("ft"))?;
        let v = &self.en;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("en"))?;
        let v = &self.p1;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("p1"))?;
        let v = &self.p2;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("p2"))?;
        let v = &self.p3;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("p3"))?;
        let v = &self.p4;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("p4"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.index;
        crate::json::key(w, &mut first, "index")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.count;
        crate::json::key(w, &mut first, "count")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.tow;
        crate::json::key(w, &mut first, "tow")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.week_number;
        crate::json::key(w, &mut first, "week_number")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.satellite_id;
        crate::json::key(w, &mut first, "satellite_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.freq_number;
        crate::json::key(w, &mut first, "freq_number")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.tk;
        crate::json::key(w, &mut first, "tk")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.tb;
        crate::json::key(w, &mut first, "tb")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.sat_type;
        crate::json::key(w, &mut first, "sat_type")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.gamma;
        crate::json::key(w, &mut first, "gamma")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.tau_n;
        crate::json::key(w, &mut first, "tau_n")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.x;
        crate::json::key(w, &mut first, "x")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.v;
        crate::json::key(w, &mut first, "v")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.a;
        crate::json::key(w, &mut first, "a")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.health;
        crate::json::key(w, &mut first, "health")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.p;
        crate::json::key(w, &mut first, "p")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.nt;
        crate::json::key(w, &mut first, "nt")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.delta_tau_n;
        crate::json::key(w, &mut first, "delta_tau_n")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.ft;
        crate::json::key(w, &mut first, "ft")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.en;
        crate::json::key(w, &mut first, "en")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.p1;
        crate::json::key(w, &mut first, "p1")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.p2;
        crate::json::key(w, &mut first, "p2")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.p3;
        crate::json::key(w, &mut first, "p3")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.p4;
        crate::json::key(w, &mut first, "p4")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GlonassEphemeris {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "index",
                "count",
                "tow",
                "week_number",
                "satellite_id",
                "freq_number",
                "tk",
                "tb",
                "sat_type",
                "gamma",
                "tau_n",
                "x",
                "v",
                "a",
                "health",
                "p",
                "nt",
                "delta_tau_n",
                "ft",
                "en",
                "p1",
                "p2",
                "p3",
                "p4",
                "valid_flags",
            ],
        )?;
        let p_index = o.req("index", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_count = o.req("count", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_tow = o.req("tow", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_week_number = o.req(
            "week_number",
            <u16 as crate::json_read::FromJson>::from_json,
        )?;
        let p_satellite_id = o.req(
            "satellite_id",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_freq_number = o.req("freq_number", <i8 as crate::json_read::FromJson>::from_json)?;
        let p_tk = o.req("tk", <u32 as crate::json_read::FromJson>::from_json)?;
        let p_tb = o.req("tb", <u32 as crate::json_read::FromJson>::from_json)?;
        let p_sat_type = o.req(
            "sat_type",
            <crate::types::GnssGlonassSatelliteType as crate::json_read::FromJson>::from_json,
        )?;
        let p_gamma = o.req("gamma", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_tau_n = o.req("tau_n", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_x = o.req("x", <[f64; 3] as crate::json_read::FromJson>::from_json)?;
        let p_v = o.req("v", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        let p_a = o.req("a", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        let p_health = o.req("health", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_p = o.req("p", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_nt = o.req("nt", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_delta_tau_n = o.req(
            "delta_tau_n",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_ft = o.req("ft", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_en = o.req("en", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_p1 = o.req("p1", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_p2 = o.req("p2", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_p3 = o.req("p3", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_p4 = o.req("p4", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::GnssGlonassEphemerisValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            index: p_index,
            count: p_count,
            tow: p_tow,
            week_number: p_week_number,
            satellite_id: p_satellite_id,
            freq_number: p_freq_number,
            tk: p_tk,
            tb: p_tb,
            sat_type: p_sat_type,
            gamma: p_gamma,
            tau_n: p_tau_n,
            x: p_x,
            v: p_v,
            a: p_a,
            health: p_health,
            p: p_p,
            nt: p_nt,
            delta_tau_n: p_delta_tau_n,
            ft: p_ft,
            en: p_en,
            p1: p_p1,
            p2: p_p2,
            p3: p_p3,
            p4: p_p4,
            valid_flags: p_valid_flags,
        })
    }
}

impl GlonassEphemeris {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x92;
}

impl crate::wire::Layout for GlonassEphemeris {
    const DESCRIPTOR: u8 = 0x62;
    const DESCRIPTOR_SET: Option<u8> = Some(0x92);
    const NAME: &'static str = "glonass_ephemeris";
}

/// Galileo ephemeris. Broadcast ephemeris of one Galileo satellite; one field per satellite.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GalileoEphemeris {
    /// Index of this field among the ephemeris fields of this epoch.
    pub index: u8,
    /// Number of ephemeris fields in this epoch.
    pub count: u8,
    /// GPS time of week. Units: s.
    pub tow: f64,
    /// GPS week number since 1980. Units: weeks.
    pub week_number: u16,
    /// Satellite number within its constellation.
    pub satellite_id: u8,
    /// Satellite and signal health.
    pub health: u8,
    /// Issue of data, clock: changes whenever the clock data change; lines up data from different sources.
    pub iodc: u8,
    /// Issue of data, ephemeris.
    pub iode: u8,
    /// Reference time of the clock data. Units: s.
    pub t_oc: f64,
    /// Clock bias. Units: s.
    pub af0: f64,
    /// Clock drift. Units: s/s.
    pub af1: f64,
    /// Clock drift rate. Units: s/s^2.
    pub af2: f64,
    /// Group delay. Units: s.
    pub t_gd: f64,
    /// Inter-signal correction, L1. Units: s.
    pub isc_l1ca: f64,
    /// Inter-signal correction, L2 (or L5 when valid_flags.isc_l5 is set). Units: s.
    pub isc_l2c: f64,
    /// Reference time of the ephemeris. Units: s.
    pub t_oe: f64,
    /// Semi-major axis. Units: m.
    pub a: f64,
    /// Rate of the semi-major axis. Units: m/s.
    pub a_dot: f64,
    /// Mean anomaly at the reference time. Units: rad.
    pub mean_anomaly: f64,
    /// Mean motion difference from the computed value. Units: rad/s.
    pub delta_mean_motion: f64,
    /// Rate of the mean motion difference. Units: rad/s^2.
    pub delta_mean_motion_dot: f64,
    /// Orbit eccentricity (dimensionless).
    pub eccentricity: f64,
    /// Argument of perigee. Units: rad.
    pub argument_of_perigee: f64,
    /// Longitude of the ascending node. Units: rad.
    pub omega: f64,
    /// Rate of right ascension. Units: rad/s.
    pub omega_dot: f64,
    /// Inclination angle. Units: rad.
    pub inclination: f64,
    /// Rate of the inclination angle. Units: rad/s.
    pub inclination_dot: f64,
    /// Harmonic correction term, cosine, to the inclination. Units: rad.
    pub c_ic: f64,
    /// Harmonic correction term, sine, to the inclination. Units: rad.
    pub c_is: f64,
    /// Harmonic correction term, cosine, to the argument of latitude. Units: rad.
    pub c_uc: f64,
    /// Harmonic correction term, sine, to the argument of latitude. Units: rad.
    pub c_us: f64,
    /// Harmonic correction term, cosine, to the orbit radius. Units: m.
    pub c_rc: f64,
    /// Harmonic correction term, sine, to the orbit radius. Units: m.
    pub c_rs: f64,
    /// Which data are valid, and how isc_l2c is to be read.
    pub valid_flags: crate::types::GnssEphemerisValidFlags,
}

impl Default for GalileoEphemeris {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GalileoEphemeris {
    const ZERO: Self = Self {
        index: <u8 as crate::wire::Wire>::ZERO,
        count: <u8 as crate::wire::Wire>::ZERO,
        tow: <f64 as crate::wire::Wire>::ZERO,
        week_number: <u16 as crate::wire::Wire>::ZERO,
        satellite_id: <u8 as crate::wire::Wire>::ZERO,
        health: <u8 as crate::wire::Wire>::ZERO,
        iodc: <u8 as crate::wire::Wire>::ZERO,
        iode: <u8 as crate::wire::Wire>::ZERO,
        t_oc: <f64 as crate::wire::Wire>::ZERO,
        af0: <f64 as crate::wire::Wire>::ZERO,
        af1: <f64 as crate::wire::Wire>::ZERO,
        af2: <f64 as crate::wire::Wire>::ZERO,
        t_gd: <f64 as crate::wire::Wire>::ZERO,
        isc_l1ca: <f64 as crate::wire::Wire>::ZERO,
        isc_l2c: <f64 as crate::wire::Wire>::ZERO,
        t_oe: <f64 as crate::wire::Wire>::ZERO,
        a: <f64 as crate::wire::Wire>::ZERO,
        a_dot: <f64 as crate::wire::Wire>::ZERO,
        mean_anomaly: <f64 as crate::wire::Wire>::ZERO,
        delta_mean_motion: <f64 as crate::wire::Wire>::ZERO,
        delta_mean_motion_dot: <f64 as crate::wire::Wire>::ZERO,
        eccentricity: <f64 as crate::wire::Wire>::ZERO,
        argument_of_perigee: <f64 as crate::wire::Wire>::ZERO,
        omega: <f64 as crate::wire::Wire>::ZERO,
        omega_dot: <f64 as crate::wire::Wire>::ZERO,
        inclination: <f64 as crate::wire::Wire>::ZERO,
        inclination_dot: <f64 as crate::wire::Wire>::ZERO,
        c_ic: <f64 as crate::wire::Wire>::ZERO,
        c_is: <f64 as crate::wire::Wire>::ZERO,
        c_uc: <f64 as crate::wire::Wire>::ZERO,
        c_us: <f64 as crate::wire::Wire>::ZERO,
        c_rc: <f64 as crate::wire::Wire>::ZERO,
        c_rs: <f64 as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::GnssEphemerisValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(218);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_index = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("index"))?;
        let p_count = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("count"))?;
        let p_tow = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("tow"))?;
        let p_week_number =
            <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("week_number"))?;
        let p_satellite_id =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("satellite_id"))?;
        let p_health = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("health"))?;
        let p_iodc = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("iodc"))?;
        let p_iode = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("iode"))?;
        let p_t_oc = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("t_oc"))?;
        let p_af0 = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("af0"))?;
        let p_af1 = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("af1"))?;
        let p_af2 = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("af2"))?;
        let p_t_gd = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("t_gd"))?;
        let p_isc_l1ca = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("isc_l1ca"))?;
        let p_isc_l2c = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("isc_l2c"))?;
        let p_t_oe = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("t_oe"))?;
        let p_a = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("a"))?;
        let p_a_dot = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("a_dot"))?;
        let p_mean_anomaly =
            <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("mean_anomaly"))?;
        let p_delta_mean_motion =
            <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("delta_mean_motion"))?;
        let p_delta_mean_motion_dot =
            <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("delta_mean_motion_dot"))?;
        let p_eccentricity =
            <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("eccentricity"))?;
        let p_argument_of_perigee =
            <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("argument_of_perigee"))?;
        let p_omega = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("omega"))?;
        let p_omega_dot = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("omega_dot"))?;
        let p_inclination =
            <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("inclination"))?;
        let p_inclination_dot =
            <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("inclination_dot"))?;
        let p_c_ic = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("c_ic"))?;
        let p_c_is = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("c_is"))?;
        let p_c_uc = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("c_uc"))?;
        let p_c_us = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("c_us"))?;
        let p_c_rc = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("c_rc"))?;
        let p_c_rs = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("c_rs"))?;
        let p_valid_flags = <crate::types::GnssEphemerisValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            index: p_index,
            count: p_count,
            tow: p_tow,
            week_number: p_week_number,
            satellite_id: p_satellite_id,
            health: p_health,
            iodc: p_iodc,
            iode: p_iode,
            t_oc: p_t_oc,
            af0: p_af0,
            af1: p_af1,
            af2: p_af2,
            t_gd: p_t_gd,
            isc_l1ca: p_isc_l1ca,
            isc_l2c: p_isc_l2c,
            t_oe: p_t_oe,
            a: p_a,
            a_dot: p_a_dot,
            mean_anomaly: p_mean_anomaly,
            delta_mean_motion: p_delta_mean_motion,
            delta_mean_motion_dot: p_delta_mean_motion_dot,
            eccentricity: p_eccentricity,
            argument_of_perigee: p_argument_of_perigee,
            omega: p_omega,
            omega_dot: p_omega_dot,
            inclination: p_inclination,
            inclination_dot: p_inclination_dot,
            c_ic: p_c_ic,
            c_is: p_c_is,
            c_uc: p_c_uc,
            c_us: p_c_us,
            c_rc: p_c_rc,
            c_rs: p_c_rs,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.index;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("index"))?;
        let v = &self.count;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("count"))?;
        let v = &self.tow;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("tow"))?;
        let v = &self.week_number;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("week_number"))?;
        let v = &self.satellite_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("satellite_id"))?;
        let v = &self.health;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("health"))?;
        let v = &self.iodc;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("iodc"))?;
        let v = &self.iode;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("iode"))?;
        let v = &self.t_oc;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("t_oc"))?;
        let v = &self.af0;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("af0"))?;
        let v = &self.af1;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("af1"))?;
        let v = &self.af2;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("af2"))?;
        let v = &self.t_gd;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("t_gd"))?;
        let v = &self.isc_l1ca;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("isc_l1ca"))?;
        let v = &self.isc_l2c;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("isc_l2c"))?;
        let v = &self.t_oe;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("t_oe"))?;
        let v = &self.a;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("a"))?;
        let v = &self.a_dot;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("a_dot"))?;
        let v = &self.mean_anomaly;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("mean_anomaly"))?;
        let v = &self.delta_mean_motion;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("delta_mean_motion"))?;
        let v = &self.delta_mean_motion_dot;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("delta_mean_motion_dot"))?;
        let v = &self.eccentricity;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("eccentricity"))?;
        let v = &self.argument_of_perigee;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("argument_of_perigee"))?;
        let v = &self.omega;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("omega"))?;
        let v = &self.omega_dot;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("omega_dot"))?;
        let v = &self.inclination;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("inclination"))?;
        let v = &self.inclination_dot;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("inclination_dot"))?;
        let v = &self.c_ic;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("c_ic"))?;
        let v = &self.c_is;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("c_is"))?;
        let v = &self.c_uc;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("c_uc"))?;
        let v = &self.c_us;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("c_us"))?;
        let v = &self.c_rc;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("c_rc"))?;
        let v = &self.c_rs;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("c_rs"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.index;
        crate::json::key(w, &mut first, "index")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.count;
        crate::json::key(w, &mut first, "count")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.tow;
        crate::json::key(w, &mut first, "tow")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.week_number;
        crate::json::key(w, &mut first, "week_number")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.satellite_id;
        crate::json::key(w, &mut first, "satellite_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.health;
        crate::json::key(w, &mut first, "health")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.iodc;
        crate::json::key(w, &mut first, "iodc")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.iode;
        crate::json::key(w, &mut first, "iode")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.t_oc;
        crate::json::key(w, &mut first, "t_oc")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.af0;
        crate::json::key(w, &mut first, "af0")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.af1;
        crate::json::key(w, &mut first, "af1")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.af2;
        crate::json::key(w, &mut first, "af2")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.t_gd;
        crate::json::key(w, &mut first, "t_gd")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.isc_l1ca;
        crate::json::key(w, &mut first, "isc_l1ca")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.isc_l2c;
        crate::json::key(w, &mut first, "isc_l2c")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.t_oe;
        crate::json::key(w, &mut first, "t_oe")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.a;
        crate::json::key(w, &mut first, "a")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.a_dot;
        crate::json::key(w, &mut first, "a_dot")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.mean_anomaly;
        crate::json::key(w, &mut first, "mean_anomaly")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.delta_mean_motion;
        crate::json::key(w, &mut first, "delta_mean_motion")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.delta_mean_motion_dot;
        crate::json::key(w, &mut first, "delta_mean_motion_dot")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.eccentricity;
        crate::json::key(w, &mut first, "eccentricity")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.argument_of_perigee;
        crate::json::key(w, &mut first, "argument_of_perigee")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.omega;
        crate::json::key(w, &mut first, "omega")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.omega_dot;
        crate::json::key(w, &mut first, "omega_dot")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.inclination;
        crate::json::key(w, &mut first, "inclination")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.inclination_dot;
        crate::json::key(w, &mut first, "inclination_dot")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.c_ic;
        crate::json::key(w, &mut first, "c_ic")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.c_is;
        crate::json::key(w, &mut first, "c_is")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.c_uc;
        crate::json::key(w, &mut first, "c_uc")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.c_us;
        crate::json::key(w, &mut first, "c_us")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.c_rc;
        crate::json::key(w, &mut first, "c_rc")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.c_rs;
        crate::json::key(w, &mut first, "c_rs")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GalileoEphemeris {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "index",
                "count",
                "tow",
                "week_number",
                "satellite_id",
                "health",
                "iodc",
                "iode",
                "t_oc",
                "af0",
                "af1",
                "af2",
                "t_gd",
                "isc_l1ca",
                "isc_l2c",
                "t_oe",
                "a",
                "a_dot",
                "mean_anomaly",
                "delta_mean_motion",
                "delta_mean_motion_dot",
                "eccentricity",
                "argument_of_perigee",
                "omega",
                "omega_dot",
                "inclination",
                "inclination_dot",
                "c_ic",
                "c_is",
                "c_uc",
                "c_us",
                "c_rc",
                "c_rs",
                "valid_flags",
            ],
        )?;
        let p_index = o.req("index", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_count = o.req("count", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_tow = o.req("tow", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_week_number = o.req(
            "week_number",
            <u16 as crate::json_read::FromJson>::from_json,
        )?;
        let p_satellite_id = o.req(
            "satellite_id",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_health = o.req("health", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_iodc = o.req("iodc", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_iode = o.req("iode", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_t_oc = o.req("t_oc", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_af0 = o.req("af0", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_af1 = o.req("af1", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_af2 = o.req("af2", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_t_gd = o.req("t_gd", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_isc_l1ca = o.req("isc_l1ca", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_isc_l2c = o.req("isc_l2c", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_t_oe = o.req("t_oe", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_a = o.req("a", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_a_dot = o.req("a_dot", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_mean_anomaly = o.req(
            "mean_anomaly",
            <f64 as crate::json_read::FromJson>::from_json,
        )?;
        let p_delta_mean_motion = o.req(
            "delta_mean_motion",
            <f64 as crate::json_read::FromJson>::from_json,
        )?;
        let p_delta_mean_motion_dot = o.req(
            "delta_mean_motion_dot",
            <f64 as crate::json_read::FromJson>::from_json,
        )?;
        let p_eccentricity = o.req(
            "eccentricity",
            <f64 as crate::json_read::FromJson>::from_json,
        )?;
        let p_argument_of_perigee = o.req(
            "argument_of_perigee",
            <f64 as crate::json_read::FromJson>::from_json,
        )?;
        let p_omega = o.req("omega", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_omega_dot = o.req("omega_dot", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_inclination = o.req(
            "inclination",
            <f64 as crate::json_read::FromJson>::from_json,
        )?;
        let p_inclination_dot = o.req(
            "inclination_dot",
            <f64 as crate::json_read::FromJson>::from_json,
        )?;
        let p_c_ic = o.req("c_ic", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_c_is = o.req("c_is", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_c_uc = o.req("c_uc", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_c_us = o.req("c_us", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_c_rc = o.req("c_rc", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_c_rs = o.req("c_rs", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::GnssEphemerisValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            index: p_index,
            count: p_count,
            tow: p_tow,
            week_number: p_week_number,
            satellite_id: p_satellite_id,
            health: p_health,
            iodc: p_iodc,
            iode: p_iode,
            t_oc: p_t_oc,
            af0: p_af0,
            af1: p_af1,
            af2: p_af2,
            t_gd: p_t_gd,
            isc_l1ca: p_isc_l1ca,
            isc_l2c: p_isc_l2c,
            t_oe: p_t_oe,
            a: p_a,
            a_dot: p_a_dot,
            mean_anomaly: p_mean_anomaly,
            delta_mean_motion: p_delta_mean_motion,
            delta_mean_motion_dot: p_delta_mean_motion_dot,
            eccentricity: p_eccentricity,
            argument_of_perigee: p_argument_of_perigee,
            omega: p_omega,
            omega_dot: p_omega_dot,
            inclination: p_inclination,
            inclination_dot: p_inclination_dot,
            c_ic: p_c_ic,
            c_is: p_c_is,
            c_uc: p_c_uc,
            c_us: p_c_us,
            c_rc: p_c_rc,
            c_rs: p_c_rs,
            valid_flags: p_valid_flags,
        })
    }
}

impl GalileoEphemeris {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x92;
}

impl crate::wire::Layout for GalileoEphemeris {
    const DESCRIPTOR: u8 = 0x63;
    const DESCRIPTOR_SET: Option<u8> = Some(0x92);
    const NAME: &'static str = "galileo_ephemeris";
}

/// BeiDou ephemeris. Broadcast ephemeris of one BeiDou satellite; one field per satellite.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BeidouEphemeris {
    /// Index of this field among the ephemeris fields of this epoch.
    pub index: u8,
    /// Number of ephemeris fields in this epoch.
    pub count: u8,
    /// GPS time of week. Units: s.
    pub tow: f64,
    /// GPS week number since 1980. Units: weeks.
    pub week_number: u16,
    /// Satellite number within its constellation.
    pub satellite_id: u8,
    /// Satellite and signal health.
    pub health: u8,
    /// Issue of data, clock: changes whenever the clock data change; lines up data from different sources.
    pub iodc: u8,
    /// Issue of data, ephemeris.
    pub iode: u8,
    /// Reference time of the clock data. Units: s.
    pub t_oc: f64,
    /// Clock bias. Units: s.
    pub af0: f64,
    /// Clock drift. Units: s/s.
    pub af1: f64,
    /// Clock drift rate. Units: s/s^2.
    pub af2: f64,
    /// Group delay. Units: s.
    pub t_gd: f64,
    /// Inter-signal correction, L1. Units: s.
    pub isc_l1ca: f64,
    /// Inter-signal correction, L2 (or L5 when valid_flags.isc_l5 is set). Units: s.
    pub isc_l2c: f64,
    /// Reference time of the ephemeris. Units: s.
    pub t_oe: f64,
    /// Semi-major axis. Units: m.
    pub a: f64,
    /// Rate of the semi-major axis. Units: m/s.
    pub a_dot: f64,
    /// Mean anomaly at the reference time. Units: rad.
    pub mean_anomaly: f64,
    /// Mean motion difference from the computed value. Units: rad/s.
    pub delta_mean_motion: f64,
    /// Rate of the mean motion difference. Units: rad/s^2.
    pub delta_mean_motion_dot: f64,
    /// Orbit eccentricity (dimensionless).
    pub eccentricity: f64,
    /// Argument of perigee. Units: rad.
    pub argument_of_perigee: f64,
    /// Longitude of the ascending node. Units: rad.
    pub omega: f64,
    /// Rate of right ascension. Units: rad/s.
    pub omega_dot: f64,
    /// Inclination angle. Units: rad.
    pub inclination: f64,
    /// Rate of the inclination angle. Units: rad/s.
    pub inclination_dot: f64,
    /// Harmonic correction term, cosine, to the inclination. Units: rad.
    pub c_ic: f64,
    /// Harmonic correction term, sine, to the inclination. Units: rad.
    pub c_is: f64,
    /// Harmonic correction term, cosine, to the argument of latitude. Units: rad.
    pub c_uc: f64,
    /// Harmonic correction term, sine, to the argument of latitude. Units: rad.
    pub c_us: f64,
    /// Harmonic correction term, cosine, to the orbit radius. Units: m.
    pub c_rc: f64,
    /// Harmonic correction term, sine, to the orbit radius. Units: m.
    pub c_rs: f64,
    /// Which data are valid, and how isc_l2c is to be read.
    pub valid_flags: crate::types::GnssEphemerisValidFlags,
}

impl Default for BeidouEphemeris {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for BeidouEphemeris {
    const ZERO: Self = Self {
        index: <u8 as crate::wire::Wire>::ZERO,
        count: <u8 as crate::wire::Wire>::ZERO,
        tow: <f64 as crate::wire::Wire>::ZERO,
        week_number: <u16 as crate::wire::Wire>::ZERO,
        satellite_id: <u8 as crate::wire::Wire>::ZERO,
        health: <u8 as crate::wire::Wire>::ZERO,
        iodc: <u8 as crate::wire::Wire>::ZERO,
        iode: <u8 as crate::wire::Wire>::ZERO,
        t_oc: <f64 as crate::wire::Wire>::ZERO,
        af0: <f64 as crate::wire::Wire>::ZERO,
        af1: <f64 as crate::wire::Wire>::ZERO,
        af2: <f64 as crate::wire::Wire>::ZERO,
        t_gd: <f64 as crate::wire::Wire>::ZERO,
        isc_l1ca: <f64 as crate::wire::Wire>::ZERO,
        isc_l2c: <f64 as crate::wire::Wire>::ZERO,
        t_oe: <f64 as crate::wire::Wire>::ZERO,
        a: <f64 as crate::wire::Wire>::ZERO,
        a_dot: <f64 as crate::wire::Wire>::ZERO,
        mean_anomaly: <f64 as crate::wire::Wire>::ZERO,
        delta_mean_motion: <f64 as crate::wire::Wire>::ZERO,
        delta_mean_motion_dot: <f64 as crate::wire::Wire>::ZERO,
        eccentricity: <f64 as crate::wire::Wire>::ZERO,
        argument_of_perigee: <f64 as crate::wire::Wire>::ZERO,
        omega: <f64 as crate::wire::Wire>::ZERO,
        omega_dot: <f64 as crate::wire::Wire>::ZERO,
        inclination: <f64 as crate::wire::Wire>::ZERO,
        inclination_dot: <f64 as crate::wire::Wire>::ZERO,
        c_ic: <f64 as crate::wire::Wire>::ZERO,
        c_is: <f64 as crate::wire::Wire>::ZERO,
        c_uc: <f64 as crate::wire::Wire>::ZERO,
        c_us: <f64 as crate::wire::Wire>::ZERO,
        c_rc: <f64 as crate::wire::Wire>::ZERO,
        c_rs: <f64 as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::GnssEphemerisValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(218);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_index = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("index"))?;
        let p_count = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("count"))?;
        let p_tow = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("tow"))?;
        let p_week_number =
            <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("week_number"))?;
        let p_satellite_id =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("satellite_id"))?;
        let p_health = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("health"))?;
        let p_iodc = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("iodc"))?;
        let p_iode = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("iode"))?;
        let p_t_oc = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("t_oc"))?;
        let p_af0 = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("af0"))?;
        let p_af1 = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("af1"))?;
        let p_af2 = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("af2"))?;
        let p_t_gd = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("t_gd"))?;
        let p_isc_l1ca = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("isc_l1ca"))?;
        let p_isc_l2c = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("isc_l2c"))?;
        let p_t_oe = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("t_oe"))?;
        let p_a = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("a"))?;
        let p_a_dot = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("a_dot"))?;
        let p_mean_anomaly =
            <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("mean_anomaly"))?;
        let p_delta_mean_motion =
            <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("delta_mean_motion"))?;
        let p_delta_mean_motion_dot =
            <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("delta_mean_motion_dot"))?;
        let p_eccentricity =
            <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("eccentricity"))?;
        let p_argument_of_perigee =
            <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("argument_of_perigee"))?;
        let p_omega = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("omega"))?;
        let p_omega_dot = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("omega_dot"))?;
        let p_inclination =
            <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("inclination"))?;
        let p_inclination_dot =
            <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("inclination_dot"))?;
        let p_c_ic = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("c_ic"))?;
        let p_c_is = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("c_is"))?;
        let p_c_uc = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("c_uc"))?;
        let p_c_us = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("c_us"))?;
        let p_c_rc = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("c_rc"))?;
        let p_c_rs = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("c_rs"))?;
        let p_valid_flags = <crate::types::GnssEphemerisValidFlags as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            index: p_index,
            count: p_count,
            tow: p_tow,
            week_number: p_week_number,
            satellite_id: p_satellite_id,
            health: p_health,
            iodc: p_iodc,
            iode: p_iode,
            t_oc: p_t_oc,
            af0: p_af0,
            af1: p_af1,
            af2: p_af2,
            t_gd: p_t_gd,
            isc_l1ca: p_isc_l1ca,
            isc_l2c: p_isc_l2c,
            t_oe: p_t_oe,
            a: p_a,
            a_dot: p_a_dot,
            mean_anomaly: p_mean_anomaly,
            delta_mean_motion: p_delta_mean_motion,
            delta_mean_motion_dot: p_delta_mean_motion_dot,
            eccentricity: p_eccentricity,
            argument_of_perigee: p_argument_of_perigee,
            omega: p_omega,
            omega_dot: p_omega_dot,
            inclination: p_inclination,
            inclination_dot: p_inclination_dot,
            c_ic: p_c_ic,
            c_is: p_c_is,
            c_uc: p_c_uc,
            c_us: p_c_us,
            c_rc: p_c_rc,
            c_rs: p_c_rs,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.index;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("index"))?;
        let v = &self.count;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("count"))?;
        let v = &self.tow;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("tow"))?;
        let v = &self.week_number;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("week_number"))?;
        let v = &self.satellite_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("satellite_id"))?;
        let v = &self.health;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("health"))?;
        let v = &self.iodc;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("iodc"))?;
        let v = &self.iode;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("iode"))?;
        let v = &self.t_oc;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("t_oc"))?;
        let v = &self.af0;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("af0"))?;
        let v = &self.af1;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("af1"))?;
        let v = &self.af2;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("af2"))?;
        let v = &self.t_gd;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("t_gd"))?;
        let v = &self.isc_l1ca;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("isc_l1ca"))?;
        let v = &self.isc_l2c;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("isc_l2c"))?;
        let v = &self.t_oe;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("t_oe"))?;
        let v = &self.a;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("a"))?;
        let v = &self.a_dot;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("a_dot"))?;
        let v = &self.mean_anomaly;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("mean_anomaly"))?;
        let v = &self.delta_mean_motion;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("delta_mean_motion"))?;
        let v = &self.delta_mean_motion_dot;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("delta_mean_motion_dot"))?;
        let v = &self.eccentricity;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("eccentricity"))?;
        let v = &self.argument_of_perigee;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("argument_of_perigee"))?;
        let v = &self.omega;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("omega"))?;
        let v = &self.omega_dot;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("omega_dot"))?;
        let v = &self.inclination;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("inclination"))?;
        let v = &self.inclination_dot;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("inclination_dot"))?;
        let v = &self.c_ic;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("c_ic"))?;
        let v = &self.c_is;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("c_is"))?;
        let v = &self.c_uc;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("c_uc"))?;
        let v = &self.c_us;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("c_us"))?;
        let v = &self.c_rc;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("c_rc"))?;
        let v = &self.c_rs;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("c_rs"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.index;
        crate::json::key(w, &mut first, "index")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.count;
        crate::json::key(w, &mut first, "count")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.tow;
        crate::json::key(w, &mut first, "tow")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.week_number;
        crate::json::key(w, &mut first, "week_number")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.satellite_id;
        crate::json::key(w, &mut first, "satellite_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.health;
        crate::json::key(w, &mut first, "health")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.iodc;
        crate::json::key(w, &mut first, "iodc")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.iode;
        crate::json::key(w, &mut first, "iode")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.t_oc;
        crate::json::key(w, &mut first, "t_oc")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.af0;
        crate::json::key(w, &mut first, "af0")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.af1;
        crate::json::key(w, &mut first, "af1")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.af2;
        crate::json::key(w, &mut first, "af2")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.t_gd;
        crate::json::key(w, &mut first, "t_gd")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.isc_l1ca;
        crate::json::key(w, &mut first, "isc_l1ca")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.isc_l2c;
        crate::json::key(w, &mut first, "isc_l2c")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.t_oe;
        crate::json::key(w, &mut first, "t_oe")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.a;
        crate::json::key(w, &mut first, "a")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.a_dot;
        crate::json::key(w, &mut first, "a_dot")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.mean_anomaly;
        crate::json::key(w, &mut first, "mean_anomaly")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.delta_mean_motion;
        crate::json::key(w, &mut first, "delta_mean_motion")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.delta_mean_motion_dot;
        crate::json::key(w, &mut first, "delta_mean_motion_dot")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.eccentricity;
        crate::json::key(w, &mut first, "eccentricity")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.argument_of_perigee;
        crate::json::key(w, &mut first, "argument_of_perigee")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.omega;
        crate::json::key(w, &mut first, "omega")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.omega_dot;
        crate::json::key(w, &mut first, "omega_dot")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.inclination;
        crate::json::key(w, &mut first, "inclination")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.inclination_dot;
        crate::json::key(w, &mut first, "inclination_dot")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.c_ic;
        crate::json::key(w, &mut first, "c_ic")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.c_is;
        crate::json::key(w, &mut first, "c_is")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.c_uc;
        crate::json::key(w, &mut first, "c_uc")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.c_us;
        crate::json::key(w, &mut first, "c_us")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.c_rc;
        crate::json::key(w, &mut first, "c_rc")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.c_rs;
        crate::json::key(w, &mut first, "c_rs")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for BeidouEphemeris {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "index",
                "count",
                "tow",
                "week_number",
                "satellite_id",
                "health",
                "iodc",
                "iode",
                "t_oc",
                "af0",
                "af1",
                "af2",
                "t_gd",
                "isc_l1ca",
                "isc_l2c",
                "t_oe",
                "a",
                "a_dot",
                "mean_anomaly",
                "delta_mean_motion",
                "delta_mean_motion_dot",
                "eccentricity",
                "argument_of_perigee",
                "omega",
                "omega_dot",
                "inclination",
                "inclination_dot",
                "c_ic",
                "c_is",
                "c_uc",
                "c_us",
                "c_rc",
                "c_rs",
                "valid_flags",
            ],
        )?;
        let p_index = o.req("index", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_count = o.req("count", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_tow = o.req("tow", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_week_number = o.req(
            "week_number",
            <u16 as crate::json_read::FromJson>::from_json,
        )?;
        let p_satellite_id = o.req(
            "satellite_id",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_health = o.req("health", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_iodc = o.req("iodc", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_iode = o.req("iode", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_t_oc = o.req("t_oc", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_af0 = o.req("af0", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_af1 = o.req("af1", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_af2 = o.req("af2", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_t_gd = o.req("t_gd", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_isc_l1ca = o.req("isc_l1ca", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_isc_l2c = o.req("isc_l2c", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_t_oe = o.req("t_oe", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_a = o.req("a", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_a_dot = o.req("a_dot", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_mean_anomaly = o.req(
            "mean_anomaly",
            <f64 as crate::json_read::FromJson>::from_json,
        )?;
        let p_delta_mean_motion = o.req(
            "delta_mean_motion",
            <f64 as crate::json_read::FromJson>::from_json,
        )?;
        let p_delta_mean_motion_dot = o.req(
            "delta_mean_motion_dot",
            <f64 as crate::json_read::FromJson>::from_json,
        )?;
        let p_eccentricity = o.req(
            "eccentricity",
            <f64 as crate::json_read::FromJson>::from_json,
        )?;
        let p_argument_of_perigee = o.req(
            "argument_of_perigee",
            <f64 as crate::json_read::FromJson>::from_json,
        )?;
        let p_omega = o.req("omega", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_omega_dot = o.req("omega_dot", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_inclination = o.req(
            "inclination",
            <f64 as crate::json_read::FromJson>::from_json,
        )?;
        let p_inclination_dot = o.req(
            "inclination_dot",
            <f64 as crate::json_read::FromJson>::from_json,
        )?;
        let p_c_ic = o.req("c_ic", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_c_is = o.req("c_is", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_c_uc = o.req("c_uc", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_c_us = o.req("c_us", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_c_rc = o.req("c_rc", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_c_rs = o.req("c_rs", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::GnssEphemerisValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            index: p_index,
            count: p_count,
            tow: p_tow,
            week_number: p_week_number,
            satellite_id: p_satellite_id,
            health: p_health,
            iodc: p_iodc,
            iode: p_iode,
            t_oc: p_t_oc,
            af0: p_af0,
            af1: p_af1,
            af2: p_af2,
            t_gd: p_t_gd,
            isc_l1ca: p_isc_l1ca,
            isc_l2c: p_isc_l2c,
            t_oe: p_t_oe,
            a: p_a,
            a_dot: p_a_dot,
            mean_anomaly: p_mean_anomaly,
            delta_mean_motion: p_delta_mean_motion,
            delta_mean_motion_dot: p_delta_mean_motion_dot,
            eccentricity: p_eccentricity,
            argument_of_perigee: p_argument_of_perigee,
            omega: p_omega,
            omega_dot: p_omega_dot,
            inclination: p_inclination,
            inclination_dot: p_inclination_dot,
            c_ic: p_c_ic,
            c_is: p_c_is,
            c_uc: p_c_uc,
            c_us: p_c_us,
            c_rc: p_c_rc,
            c_rs: p_c_rs,
            valid_flags: p_valid_flags,
        })
    }
}

impl BeidouEphemeris {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x92;
}

impl crate::wire::Layout for BeidouEphemeris {
    const DESCRIPTOR: u8 = 0x64;
    const DESCRIPTOR_SET: Option<u8> = Some(0x92);
    const NAME: &'static str = "beidou_ephemeris";
}

/// A decoded field of set 0x92 (`gnss_receiver_2`).
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
    /// `fix_info` (0x0B).
    FixInfo(FixInfo),
    /// `hardware_status` (0x0D).
    HardwareStatus(HardwareStatus),
    /// `clock_info_2` (0x10).
    ClockInfo2(ClockInfo2),
    /// `gps_leap_seconds` (0x11).
    GpsLeapSeconds(GpsLeapSeconds),
    /// `sbas_info` (0x12).
    SbasInfo(SbasInfo),
    /// `satellite_status` (0x20).
    SatelliteStatus(SatelliteStatus),
    /// `raw` (0x22).
    Raw(Raw),
    /// `gps_ephemeris` (0x61).
    GpsEphemeris(GpsEphemeris),
    /// `glonass_ephemeris` (0x62).
    GlonassEphemeris(GlonassEphemeris),
    /// `galileo_ephemeris` (0x63).
    GalileoEphemeris(GalileoEphemeris),
    /// `beidou_ephemeris` (0x64).
    BeidouEphemeris(BeidouEphemeris),
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
            Self::FixInfo(_) => 0x0B,
            Self::HardwareStatus(_) => 0x0D,
            Self::ClockInfo2(_) => 0x10,
            Self::GpsLeapSeconds(_) => 0x11,
            Self::SbasInfo(_) => 0x12,
            Self::SatelliteStatus(_) => 0x20,
            Self::Raw(_) => 0x22,
            Self::GpsEphemeris(_) => 0x61,
            Self::GlonassEphemeris(_) => 0x62,
            Self::GalileoEphemeris(_) => 0x63,
            Self::BeidouEphemeris(_) => 0x64,
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
            Self::FixInfo(_) => "fix_info",
            Self::HardwareStatus(_) => "hardware_status",
            Self::ClockInfo2(_) => "clock_info_2",
            Self::GpsLeapSeconds(_) => "gps_leap_seconds",
            Self::SbasInfo(_) => "sbas_info",
            Self::SatelliteStatus(_) => "satellite_status",
            Self::Raw(_) => "raw",
            Self::GpsEphemeris(_) => "gps_ephemeris",
            Self::GlonassEphemeris(_) => "glonass_ephemeris",
            Self::GalileoEphemeris(_) => "galileo_ephemeris",
            Self::BeidouEphemeris(_) => "beidou_ephemeris",
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
            Self::FixInfo(_) => None,
            Self::HardwareStatus(_) => None,
            Self::ClockInfo2(_) => None,
            Self::GpsLeapSeconds(_) => None,
            Self::SbasInfo(_) => None,
            Self::SatelliteStatus(_) => None,
            Self::Raw(_) => None,
            Self::GpsEphemeris(_) => None,
            Self::GlonassEphemeris(_) => None,
            Self::GalileoEphemeris(_) => None,
            Self::BeidouEphemeris(_) => None,
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
            Self::FixInfo(v) => crate::wire::Layout::encode_data(v, w),
            Self::HardwareStatus(v) => crate::wire::Layout::encode_data(v, w),
            Self::ClockInfo2(v) => crate::wire::Layout::encode_data(v, w),
            Self::GpsLeapSeconds(v) => crate::wire::Layout::encode_data(v, w),
            Self::SbasInfo(v) => crate::wire::Layout::encode_data(v, w),
            Self::SatelliteStatus(v) => crate::wire::Layout::encode_data(v, w),
            Self::Raw(v) => crate::wire::Layout::encode_data(v, w),
            Self::GpsEphemeris(v) => crate::wire::Layout::encode_data(v, w),
            Self::GlonassEphemeris(v) => crate::wire::Layout::encode_data(v, w),
            Self::GalileoEphemeris(v) => crate::wire::Layout::encode_data(v, w),
            Self::BeidouEphemeris(v) => crate::wire::Layout::encode_data(v, w),
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
            Self::FixInfo(v) => crate::wire::Wire::write_json(v, w),
            Self::HardwareStatus(v) => crate::wire::Wire::write_json(v, w),
            Self::ClockInfo2(v) => crate::wire::Wire::write_json(v, w),
            Self::GpsLeapSeconds(v) => crate::wire::Wire::write_json(v, w),
            Self::SbasInfo(v) => crate::wire::Wire::write_json(v, w),
            Self::SatelliteStatus(v) => crate::wire::Wire::write_json(v, w),
            Self::Raw(v) => crate::wire::Wire::write_json(v, w),
            Self::GpsEphemeris(v) => crate::wire::Wire::write_json(v, w),
            Self::GlonassEphemeris(v) => crate::wire::Wire::write_json(v, w),
            Self::GalileoEphemeris(v) => crate::wire::Wire::write_json(v, w),
            Self::BeidouEphemeris(v) => crate::wire::Wire::write_json(v, w),
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
            0x0B => Some(<FixInfo as crate::wire::Layout>::decode_data(data).map(Self::FixInfo)),
            0x0D => Some(
                <HardwareStatus as crate::wire::Layout>::decode_data(data)
                    .map(Self::HardwareStatus),
            ),
            0x10 => {
                Some(<ClockInfo2 as crate::wire::Layout>::decode_data(data).map(Self::ClockInfo2))
            }
            0x11 => Some(
                <GpsLeapSeconds as crate::wire::Layout>::decode_data(data)
                    .map(Self::GpsLeapSeconds),
            ),
            0x12 => Some(<SbasInfo as crate::wire::Layout>::decode_data(data).map(Self::SbasInfo)),
            0x20 => Some(
                <SatelliteStatus as crate::wire::Layout>::decode_data(data)
                    .map(Self::SatelliteStatus),
            ),
            0x22 => Some(<Raw as crate::wire::Layout>::decode_data(data).map(Self::Raw)),
            0x61 => Some(
                <GpsEphemeris as crate::wire::Layout>::decode_data(data).map(Self::GpsEphemeris),
            ),
            0x62 => Some(
                <GlonassEphemeris as crate::wire::Layout>::decode_data(data)
                    .map(Self::GlonassEphemeris),
            ),
            0x63 => Some(
                <GalileoEphemeris as crate::wire::Layout>::decode_data(data)
                    .map(Self::GalileoEphemeris),
            ),
            0x64 => Some(
                <BeidouEphemeris as crate::wire::Layout>::decode_data(data)
                    .map(Self::BeidouEphemeris),
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
            0x0B => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <FixInfo as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::FixInfo),
            ),
            0x0D => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <HardwareStatus as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::HardwareStatus),
            ),
            0x10 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ClockInfo2 as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::ClockInfo2),
            ),
            0x11 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GpsLeapSeconds as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::GpsLeapSeconds),
            ),
            0x12 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SbasInfo as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::SbasInfo),
            ),
            0x20 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SatelliteStatus as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::SatelliteStatus),
            ),
            0x22 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <Raw as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::Raw),
            ),
            0x61 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GpsEphemeris as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::GpsEphemeris),
            ),
            0x62 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GlonassEphemeris as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::GlonassEphemeris),
            ),
            0x63 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GalileoEphemeris as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::GalileoEphemeris),
            ),
            0x64 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <BeidouEphemeris as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::BeidouEphemeris),
            ),
            _ => None,
        }
    }
}

/// The fields of one packet of this set, decoded in place by [`decode_packet`]: one member per
/// field of the set with one layout (its own and the shared data fields); `index` says which members hold a field of the last packet, in packet order
/// (the others hold whatever they held).
#[cfg(any(feature = "set-gnss-receiver-2", not(feature = "select-sets")))]
#[derive(Clone, Debug)]
pub struct Packet {
    /// The fields decoded into their members, in packet order.
    pub index: crate::packets::PacketIndex,
    /// Field 0x03.
    pub llh_position: crate::gnss_receiver_2::LlhPosition,
    /// Field 0x04.
    pub ecef_position: crate::gnss_receiver_2::EcefPosition,
    /// Field 0x05.
    pub ned_velocity: crate::gnss_receiver_2::NedVelocity,
    /// Field 0x06.
    pub ecef_velocity: crate::gnss_receiver_2::EcefVelocity,
    /// Field 0x07.
    pub dop: crate::gnss_receiver_2::Dop,
    /// Field 0x08.
    pub utc_time: crate::gnss_receiver_2::UtcTime,
    /// Field 0x09.
    pub gps_time: crate::gnss_receiver_2::GpsTime,
    /// Field 0x0B.
    pub fix_info: crate::gnss_receiver_2::FixInfo,
    /// Field 0x0D.
    pub hardware_status: crate::gnss_receiver_2::HardwareStatus,
    /// Field 0x10.
    pub clock_info_2: crate::gnss_receiver_2::ClockInfo2,
    /// Field 0x11.
    pub gps_leap_seconds: crate::gnss_receiver_2::GpsLeapSeconds,
    /// Field 0x12.
    pub sbas_info: crate::gnss_receiver_2::SbasInfo,
    /// Field 0x20.
    pub satellite_status: crate::gnss_receiver_2::SatelliteStatus,
    /// Field 0x22.
    pub raw: crate::gnss_receiver_2::Raw,
    /// Field 0x61.
    pub gps_ephemeris: crate::gnss_receiver_2::GpsEphemeris,
    /// Field 0x62.
    pub glonass_ephemeris: crate::gnss_receiver_2::GlonassEphemeris,
    /// Field 0x63.
    pub galileo_ephemeris: crate::gnss_receiver_2::GalileoEphemeris,
    /// Field 0x64.
    pub beidou_ephemeris: crate::gnss_receiver_2::BeidouEphemeris,
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

#[cfg(any(feature = "set-gnss-receiver-2", not(feature = "select-sets")))]
impl Packet {
    /// Nothing decoded, every member zero.
    pub const ZERO: Self = Self {
        index: crate::packets::PacketIndex::EMPTY,
        llh_position: <crate::gnss_receiver_2::LlhPosition as crate::wire::Wire>::ZERO,
        ecef_position: <crate::gnss_receiver_2::EcefPosition as crate::wire::Wire>::ZERO,
        ned_velocity: <crate::gnss_receiver_2::NedVelocity as crate::wire::Wire>::ZERO,
        ecef_velocity: <crate::gnss_receiver_2::EcefVelocity as crate::wire::Wire>::ZERO,
        dop: <crate::gnss_receiver_2::Dop as crate::wire::Wire>::ZERO,
        utc_time: <crate::gnss_receiver_2::UtcTime as crate::wire::Wire>::ZERO,
        gps_time: <crate::gnss_receiver_2::GpsTime as crate::wire::Wire>::ZERO,
        fix_info: <crate::gnss_receiver_2::FixInfo as crate::wire::Wire>::ZERO,
        hardware_status: <crate::gnss_receiver_2::HardwareStatus as crate::wire::Wire>::ZERO,
        clock_info_2: <crate::gnss_receiver_2::ClockInfo2 as crate::wire::Wire>::ZERO,
        gps_leap_seconds: <crate::gnss_receiver_2::GpsLeapSeconds as crate::wire::Wire>::ZERO,
        sbas_info: <crate::gnss_receiver_2::SbasInfo as crate::wire::Wire>::ZERO,
        satellite_status: <crate::gnss_receiver_2::SatelliteStatus as crate::wire::Wire>::ZERO,
        raw: <crate::gnss_receiver_2::Raw as crate::wire::Wire>::ZERO,
        gps_ephemeris: <crate::gnss_receiver_2::GpsEphemeris as crate::wire::Wire>::ZERO,
        glonass_ephemeris: <crate::gnss_receiver_2::GlonassEphemeris as crate::wire::Wire>::ZERO,
        galileo_ephemeris: <crate::gnss_receiver_2::GalileoEphemeris as crate::wire::Wire>::ZERO,
        beidou_ephemeris: <crate::gnss_receiver_2::BeidouEphemeris as crate::wire::Wire>::ZERO,
        event_source: <crate::shared::EventSource as crate::wire::Wire>::ZERO,
        gps_timestamp: <crate::shared::GpsTimestamp as crate::wire::Wire>::ZERO,
        delta_time: <crate::shared::DeltaTime as crate::wire::Wire>::ZERO,
        reference_timestamp: <crate::shared::ReferenceTimestamp as crate::wire::Wire>::ZERO,
        reference_time_delta: <crate::shared::ReferenceTimeDelta as crate::wire::Wire>::ZERO,
        external_timestamp: <crate::shared::ExternalTimestamp as crate::wire::Wire>::ZERO,
        external_time_delta: <crate::shared::ExternalTimeDelta as crate::wire::Wire>::ZERO,
    };
}

#[cfg(any(feature = "set-gnss-receiver-2", not(feature = "select-sets")))]
impl Default for Packet {
    fn default() -> Self {
        Self::ZERO
    }
}

#[cfg(any(feature = "set-gnss-receiver-2", not(feature = "select-sets")))]
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
                | 0x0B
                | 0x0D
                | 0x10
                | 0x11
                | 0x12
                | 0x20
                | 0x22
                | 0x61
                | 0x62
                | 0x63
                | 0x64
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
            0x10 => match <&[u8; 34]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.clock_info_2;
                    s.bias = crate::packets::ld(d, 0);
                    s.drift = crate::packets::ld(d, 8);
                    s.bias_accuracy_estimate = crate::packets::ld(d, 16);
                    s.drift_accuracy_estimate = crate::packets::ld(d, 24);
                    s.valid_flags = crate::packets::ld(d, 32);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.clock_info_2),
            },
            0x11 => match <&[u8; 3]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.gps_leap_seconds;
                    s.leap_seconds = crate::packets::ld(d, 0);
                    s.valid_flags = crate::packets::ld(d, 1);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.gps_leap_seconds),
            },
            0x12 => match <&[u8; 16]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.sbas_info;
                    s.tow = crate::packets::ld(d, 0);
                    s.week_number = crate::packets::ld(d, 8);
                    s.sbas_system = crate::packets::ld(d, 10);
                    s.sbas_id = crate::packets::ld(d, 11);
                    s.count = crate::packets::ld(d, 12);
                    s.sbas_status = crate::packets::ld(d, 13);
                    s.valid_flags = crate::packets::ld(d, 14);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.sbas_info),
            },
            0x20 => match <&[u8; 25]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) if d[22] <= 1 => {
                    let s = &mut self.satellite_status;
                    s.index = crate::packets::ld(d, 0);
                    s.count = crate::packets::ld(d, 1);
                    s.tow = crate::packets::ld(d, 2);
                    s.week_number = crate::packets::ld(d, 10);
                    s.gnss_id = crate::packets::ld(d, 12);
                    s.satellite_id = crate::packets::ld(d, 13);
                    s.elevation = crate::packets::ld(d, 14);
                    s.azimuth = crate::packets::ld(d, 18);
                    s.health = crate::packets::ld(d, 22);
                    s.valid_flags = crate::packets::ld(d, 23);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.satellite_status),
            },
            0x22 => match <&[u8; 61]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.raw;
                    s.index = crate::packets::ld(d, 0);
                    s.count = crate::packets::ld(d, 1);
                    s.tow = crate::packets::ld(d, 2);
                    s.week_number = crate::packets::ld(d, 10);
                    s.receiver_id = crate::packets::ld(d, 12);
                    s.tracking_channel = crate::packets::ld(d, 14);
                    s.gnss_id = crate::packets::ld(d, 15);
                    s.satellite_id = crate::packets::ld(d, 16);
                    s.signal_id = crate::packets::ld(d, 17);
                    s.signal_strength = crate::packets::ld(d, 18);
                    s.quality = crate::packets::ld(d, 22);
                    s.pseudorange = crate::packets::ld(d, 23);
                    s.carrier_phase = crate::packets::ld(d, 31);
                    s.doppler = crate::packets::ld(d, 39);
                    s.range_uncert = crate::packets::ld(d, 43);
                    s.phase_uncert = crate::packets::ld(d, 47);
                    s.doppler_uncert = crate::packets::ld(d, 51);
                    s.lock_time = crate::packets::ld(d, 55);
                    s.valid_flags = crate::packets::ld(d, 59);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.raw),
            },
            0x61 => match <&[u8; 218]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.gps_ephemeris;
                    s.index = crate::packets::ld(d, 0);
                    s.count = crate::packets::ld(d, 1);
                    s.tow = crate::packets::ld(d, 2);
                    s.week_number = crate::packets::ld(d, 10);
                    s.satellite_id = crate::packets::ld(d, 12);
                    s.health = crate::packets::ld(d, 13);
                    s.iodc = crate::packets::ld(d, 14);
                    s.iode = crate::packets::ld(d, 15);
                    s.t_oc = crate::packets::ld(d, 16);
                    s.af0 = crate::packets::ld(d, 24);
                    s.af1 = crate::packets::ld(d, 32);
                    s.af2 = crate::packets::ld(d, 40);
                    s.t_gd = crate::packets::ld(d, 48);
                    s.isc_l1ca = crate::packets::ld(d, 56);
                    s.isc_l2c = crate::packets::ld(d, 64);
                    s.t_oe = crate::packets::ld(d, 72);
                    s.a = crate::packets::ld(d, 80);
                    s.a_dot = crate::packets::ld(d, 88);
                    s.mean_anomaly = crate::packets::ld(d, 96);
                    s.delta_mean_motion = crate::packets::ld(d, 104);
                    s.delta_mean_motion_dot = crate::packets::ld(d, 112);
                    s.eccentricity = crate::packets::ld(d, 120);
                    s.argument_of_perigee = crate::packets::ld(d, 128);
                    s.omega = crate::packets::ld(d, 136);
                    s.omega_dot = crate::packets::ld(d, 144);
                    s.inclination = crate::packets::ld(d, 152);
                    s.inclination_dot = crate::packets::ld(d, 160);
                    s.c_ic = crate::packets::ld(d, 168);
                    s.c_is = crate::packets::ld(d, 176);
                    s.c_uc = crate::packets::ld(d, 184);
                    s.c_us = crate::packets::ld(d, 192);
                    s.c_rc = crate::packets::ld(d, 200);
                    s.c_rs = crate::packets::ld(d, 208);
                    s.valid_flags = crate::packets::ld(d, 216);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.gps_ephemeris),
            },
            0x62 => match <&[u8; 102]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.glonass_ephemeris;
                    s.index = crate::packets::ld(d, 0);
                    s.count = crate::packets::ld(d, 1);
                    s.tow = crate::packets::ld(d, 2);
                    s.week_number = crate::packets::ld(d, 10);
                    s.satellite_id = crate::packets::ld(d, 12);
                    s.freq_number = crate::packets::ld(d, 13);
                    s.tk = crate::packets::ld(d, 14);
                    s.tb = crate::packets::ld(d, 18);
                    s.sat_type = crate::packets::ld(d, 22);
                    s.gamma = crate::packets::ld(d, 23);
                    s.tau_n = crate::packets::ld(d, 31);
                    s.x[0] = crate::packets::ld(d, 39);
                    s.x[1] = crate::packets::ld(d, 47);
                    s.x[2] = crate::packets::ld(d, 55);
                    s.v[0] = crate::packets::ld(d, 63);
                    s.v[1] = crate::packets::ld(d, 67);
                    s.v[2] = crate::packets::ld(d, 71);
                    s.a[0] = crate::packets::ld(d, 75);
                    s.a[1] = crate::packets::ld(d, 79);
                    s.a[2] = crate::packets::ld(d, 83);
                    s.health = crate::packets::ld(d, 87);
                    s.p = crate::packets::ld(d, 88);
                    s.nt = crate::packets::ld(d, 89);
                    s.delta_tau_n = crate::packets::ld(d, 90);
                    s.ft = crate::packets::ld(d, 94);
                    s.en = crate::packets::ld(d, 95);
                    s.p1 = crate::packets::ld(d, 96);
                    s.p2 = crate::packets::ld(d, 97);
                    s.p3 = crate::packets::ld(d, 98);
                    s.p4 = crate::packets::ld(d, 99);
                    s.valid_flags = crate::packets::ld(d, 100);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.glonass_ephemeris),
            },
            0x63 => match <&[u8; 218]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.galileo_ephemeris;
                    s.index = crate::packets::ld(d, 0);
                    s.count = crate::packets::ld(d, 1);
                    s.tow = crate::packets::ld(d, 2);
                    s.week_number = crate::packets::ld(d, 10);
                    s.satellite_id = crate::packets::ld(d, 12);
                    s.health = crate::packets::ld(d, 13);
                    s.iodc = crate::packets::ld(d, 14);
                    s.iode = crate::packets::ld(d, 15);
                    s.t_oc = crate::packets::ld(d, 16);
                    s.af0 = crate::packets::ld(d, 24);
                    s.af1 = crate::packets::ld(d, 32);
                    s.af2 = crate::packets::ld(d, 40);
                    s.t_gd = crate::packets::ld(d, 48);
                    s.isc_l1ca = crate::packets::ld(d, 56);
                    s.isc_l2c = crate::packets::ld(d, 64);
                    s.t_oe = crate::packets::ld(d, 72);
                    s.a = crate::packets::ld(d, 80);
                    s.a_dot = crate::packets::ld(d, 88);
                    s.mean_anomaly = crate::packets::ld(d, 96);
                    s.delta_mean_motion = crate::packets::ld(d, 104);
                    s.delta_mean_motion_dot = crate::packets::ld(d, 112);
                    s.eccentricity = crate::packets::ld(d, 120);
                    s.argument_of_perigee = crate::packets::ld(d, 128);
                    s.omega = crate::packets::ld(d, 136);
                    s.omega_dot = crate::packets::ld(d, 144);
                    s.inclination = crate::packets::ld(d, 152);
                    s.inclination_dot = crate::packets::ld(d, 160);
                    s.c_ic = crate::packets::ld(d, 168);
                    s.c_is = crate::packets::ld(d, 176);
                    s.c_uc = crate::packets::ld(d, 184);
                    s.c_us = crate::packets::ld(d, 192);
                    s.c_rc = crate::packets::ld(d, 200);
                    s.c_rs = crate::packets::ld(d, 208);
                    s.valid_flags = crate::packets::ld(d, 216);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.galileo_ephemeris),
            },
            0x64 => match <&[u8; 218]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.beidou_ephemeris;
                    s.index = crate::packets::ld(d, 0);
                    s.count = crate::packets::ld(d, 1);
                    s.tow = crate::packets::ld(d, 2);
                    s.week_number = crate::packets::ld(d, 10);
                    s.satellite_id = crate::packets::ld(d, 12);
                    s.health = crate::packets::ld(d, 13);
                    s.iodc = crate::packets::ld(d, 14);
                    s.iode = crate::packets::ld(d, 15);
                    s.t_oc = crate::packets::ld(d, 16);
                    s.af0 = crate::packets::ld(d, 24);
                    s.af1 = crate::packets::ld(d, 32);
                    s.af2 = crate::packets::ld(d, 40);
                    s.t_gd = crate::packets::ld(d, 48);
                    s.isc_l1ca = crate::packets::ld(d, 56);
                    s.isc_l2c = crate::packets::ld(d, 64);
                    s.t_oe = crate::packets::ld(d, 72);
                    s.a = crate::packets::ld(d, 80);
                    s.a_dot = crate::packets::ld(d, 88);
                    s.mean_anomaly = crate::packets::ld(d, 96);
                    s.delta_mean_motion = crate::packets::ld(d, 104);
                    s.delta_mean_motion_dot = crate::packets::ld(d, 112);
                    s.eccentricity = crate::packets::ld(d, 120);
                    s.argument_of_perigee = crate::packets::ld(d, 128);
                    s.omega = crate::packets::ld(d, 136);
                    s.omega_dot = crate::packets::ld(d, 144);
                    s.inclination = crate::packets::ld(d, 152);
                    s.inclination_dot = crate::packets::ld(d, 160);
                    s.c_ic = crate::packets::ld(d, 168);
                    s.c_is = crate::packets::ld(d, 176);
                    s.c_uc = crate::packets::ld(d, 184);
                    s.c_us = crate::packets::ld(d, 192);
                    s.c_rc = crate::packets::ld(d, 200);
                    s.c_rs = crate::packets::ld(d, 208);
                    s.valid_flags = crate::packets::ld(d, 216);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.beidou_ephemeris),
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
            0x03 => Some(crate::FieldValue::GnssReceiver2(
                crate::gnss_receiver_2::SetField::LlhPosition(self.llh_position),
            )),
            0x04 => Some(crate::FieldValue::GnssReceiver2(
                crate::gnss_receiver_2::SetField::EcefPosition(self.ecef_position),
            )),
            0x05 => Some(crate::FieldValue::GnssReceiver2(
                crate::gnss_receiver_2::SetField::NedVelocity(self.ned_velocity),
            )),
            0x06 => Some(crate::FieldValue::GnssReceiver2(
                crate::gnss_receiver_2::SetField::EcefVelocity(self.ecef_velocity),
            )),
            0x07 => Some(crate::FieldValue::GnssReceiver2(
                crate::gnss_receiver_2::SetField::Dop(self.dop),
            )),
            0x08 => Some(crate::FieldValue::GnssReceiver2(
                crate::gnss_receiver_2::SetField::UtcTime(self.utc_time),
            )),
            0x09 => Some(crate::FieldValue::GnssReceiver2(
                crate::gnss_receiver_2::SetField::GpsTime(self.gps_time),
            )),
            0x0B => Some(crate::FieldValue::GnssReceiver2(
                crate::gnss_receiver_2::SetField::FixInfo(self.fix_info),
            )),
            0x0D => Some(crate::FieldValue::GnssReceiver2(
                crate::gnss_receiver_2::SetField::HardwareStatus(self.hardware_status),
            )),
            0x10 => Some(crate::FieldValue::GnssReceiver2(
                crate::gnss_receiver_2::SetField::ClockInfo2(self.clock_info_2),
            )),
            0x11 => Some(crate::FieldValue::GnssReceiver2(
                crate::gnss_receiver_2::SetField::GpsLeapSeconds(self.gps_leap_seconds),
            )),
            0x12 => Some(crate::FieldValue::GnssReceiver2(
                crate::gnss_receiver_2::SetField::SbasInfo(self.sbas_info),
            )),
            0x20 => Some(crate::FieldValue::GnssReceiver2(
                crate::gnss_receiver_2::SetField::SatelliteStatus(self.satellite_status),
            )),
            0x22 => Some(crate::FieldValue::GnssReceiver2(
                crate::gnss_receiver_2::SetField::Raw(self.raw),
            )),
            0x61 => Some(crate::FieldValue::GnssReceiver2(
                crate::gnss_receiver_2::SetField::GpsEphemeris(self.gps_ephemeris),
            )),
            0x62 => Some(crate::FieldValue::GnssReceiver2(
                crate::gnss_receiver_2::SetField::GlonassEphemeris(self.glonass_ephemeris),
            )),
            0x63 => Some(crate::FieldValue::GnssReceiver2(
                crate::gnss_receiver_2::SetField::GalileoEphemeris(self.galileo_ephemeris),
            )),
            0x64 => Some(crate::FieldValue::GnssReceiver2(
                crate::gnss_receiver_2::SetField::BeidouEphemeris(self.beidou_ephemeris),
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
#[cfg(any(feature = "set-gnss-receiver-2", not(feature = "select-sets")))]
pub fn decode_packet(
    payload: &[u8],
    out: &mut Packet,
    other: impl FnMut(crate::fields::FieldItem<'_>),
) -> usize {
    crate::packets::decode_set_packet(payload, out, other)
}
