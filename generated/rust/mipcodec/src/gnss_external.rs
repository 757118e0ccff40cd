//! GNSS External Data Set. Data of an external GNSS receiver whose NMEA sentences are fed to the device, re-emitted as MIP fields. A parameter the NMEA input does not supply has its valid flag cleared; the timestamps are those of the NMEA sentences. Sent as the data is received (base rate 0).
//!
//! Descriptor set 0x94 (data set):
//! one struct per field layout, and `SetField`, the enum of all its fields.

/// Descriptor set of this module.
pub const SET: u8 = 0x94;

/// GNSS LLH position. External receiver position in the WGS84 geodetic frame (latitude, longitude, heights) with accuracy estimates.
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
    pub const SET: u8 = 0x94;
}

impl crate::wire::Layout for LlhPosition {
    const DESCRIPTOR: u8 = 0x03;
    const DESCRIPTOR_SET: Option<u8> = Some(0x94);
    const NAME: &'static str = "llh_position";
}

/// GNSS NED velocity. External receiver velocity in the north-east-down frame, with 3D and ground speed, heading and accuracy estimates.
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
    pub const SET: u8 = 0x94;
}

impl crate::wire::Layout for NedVelocity {
    const DESCRIPTOR: u8 = 0x05;
    const DESCRIPTOR_SET: Option<u8> = Some(0x94);
    const NAME: &'static str = "ned_velocity";
}

/// GNSS UTC time. UTC date and time from the external receiver, with a flag telling whether the leap seconds are known.
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
    pub const SET: u8 = 0x94;
}

impl crate::wire::Layout for UtcTime {
    const DESCRIPTOR: u8 = 0x08;
    const DESCRIPTOR_SET: Option<u8> = Some(0x94);
    const NAME: &'static str = "utc_time";
}

/// GNSS fix information. Fix type, number of satellites used and corrections applied, from the external receiver.
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
    pub const SET: u8 = 0x94;
}

impl crate::wire::Layout for FixInfo {
    const DESCRIPTOR: u8 = 0x0B;
    const DESCRIPTOR_SET: Option<u8> = Some(0x94);
    const NAME: &'static str = "fix_info";
}

/// Satellite status. Sky position and health of one satellite reported by the external receiver; one field per satellite.
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
    pub const SET: u8 = 0x94;
}

impl crate::wire::Layout for SatelliteStatus {
    const DESCRIPTOR: u8 = 0x20;
    const DESCRIPTOR_SET: Option<u8> = Some(0x94);
    const NAME: &'static str = "satellite_status";
}

/// A decoded field of set 0x94 (`gnss_external`).
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SetField {
    /// `llh_position` (0x03).
    LlhPosition(LlhPosition),
    /// `ned_velocity` (0x05).
    NedVelocity(NedVelocity),
    /// `utc_time` (0x08).
    UtcTime(UtcTime),
    /// `fix_info` (0x0B).
    FixInfo(FixInfo),
    /// `satellite_status` (0x20).
    SatelliteStatus(SatelliteStatus),
}

impl SetField {
    /// Field descriptor.
    pub fn descriptor(&self) -> u8 {
        match self {
            Self::LlhPosition(_) => 0x03,
            Self::NedVelocity(_) => 0x05,
            Self::UtcTime(_) => 0x08,
            Self::FixInfo(_) => 0x0B,
            Self::SatelliteStatus(_) => 0x20,
        }
    }

    /// Field name as printed in JSON.
    pub fn name(&self) -> &'static str {
        match self {
            Self::LlhPosition(_) => "llh_position",
            Self::NedVelocity(_) => "ned_velocity",
            Self::UtcTime(_) => "utc_time",
            Self::FixInfo(_) => "fix_info",
            Self::SatelliteStatus(_) => "satellite_status",
        }
    }

    /// Device of the layout used, for fields with per-device layouts.
    pub fn device(&self) -> Option<crate::Device> {
        match self {
            Self::LlhPosition(_) => None,
            Self::NedVelocity(_) => None,
            Self::UtcTime(_) => None,
            Self::FixInfo(_) => None,
            Self::SatelliteStatus(_) => None,
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
            Self::UtcTime(v) => crate::wire::Layout::encode_data(v, w),
            Self::FixInfo(v) => crate::wire::Layout::encode_data(v, w),
            Self::SatelliteStatus(v) => crate::wire::Layout::encode_data(v, w),
        }
    }

    /// Writes the canonical JSON of the values (`{...}`).
    pub fn write_values_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::LlhPosition(v) => crate::wire::Wire::write_json(v, w),
            Self::NedVelocity(v) => crate::wire::Wire::write_json(v, w),
            Self::UtcTime(v) => crate::wire::Wire::write_json(v, w),
            Self::FixInfo(v) => crate::wire::Wire::write_json(v, w),
            Self::SatelliteStatus(v) => crate::wire::Wire::write_json(v, w),
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
            0x05 => {
                Some(<NedVelocity as crate::wire::Layout>::decode_data(data).map(Self::NedVelocity))
            }
            0x08 => Some(<UtcTime as crate::wire::Layout>::decode_data(data).map(Self::UtcTime)),
            0x0B => Some(<FixInfo as crate::wire::Layout>::decode_data(data).map(Self::FixInfo)),
            0x20 => Some(
                <SatelliteStatus as crate::wire::Layout>::decode_data(data)
                    .map(Self::SatelliteStatus),
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
            0x05 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <NedVelocity as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::NedVelocity),
            ),
            0x08 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <UtcTime as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::UtcTime),
            ),
            0x0B => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <FixInfo as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::FixInfo),
            ),
            0x20 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SatelliteStatus as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::SatelliteStatus),
            ),
            _ => None,
        }
    }
}

/// The fields of one packet of this set, decoded in place by [`decode_packet`]: one member per
/// field of the set with one layout (its own and the shared data fields); `index` says which members hold a field of the last packet, in packet order
/// (the others hold whatever they held).
#[cfg(any(feature = "set-gnss-external", not(feature = "select-sets")))]
#[derive(Clone, Debug)]
pub struct Packet {
    /// The fields decoded into their members, in packet order.
    pub index: crate::packets::PacketIndex,
    /// Field 0x03.
    pub llh_position: crate::gnss_external::LlhPosition,
    /// Field 0x05.
    pub ned_velocity: crate::gnss_external::NedVelocity,
    /// Field 0x08.
    pub utc_time: crate::gnss_external::UtcTime,
    /// Field 0x0B.
    pub fix_info: crate::gnss_external::FixInfo,
    /// Field 0x20.
    pub satellite_status: crate::gnss_external::SatelliteStatus,
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

#[cfg(any(feature = "set-gnss-external", not(feature = "select-sets")))]
impl Packet {
    /// Nothing decoded, every member zero.
    pub const ZERO: Self = Self {
        index: crate::packets::PacketIndex::EMPTY,
        llh_position: <crate::gnss_external::LlhPosition as crate::wire::Wire>::ZERO,
        ned_velocity: <crate::gnss_external::NedVelocity as crate::wire::Wire>::ZERO,
        utc_time: <crate::gnss_external::UtcTime as crate::wire::Wire>::ZERO,
        fix_info: <crate::gnss_external::FixInfo as crate::wire::Wire>::ZERO,
        satellite_status: <crate::gnss_external::SatelliteStatus as crate::wire::Wire>::ZERO,
        event_source: <crate::shared::EventSource as crate::wire::Wire>::ZERO,
        gps_timestamp: <crate::shared::GpsTimestamp as crate::wire::Wire>::ZERO,
        delta_time: <crate::shared::DeltaTime as crate::wire::Wire>::ZERO,
        reference_timestamp: <crate::shared::ReferenceTimestamp as crate::wire::Wire>::ZERO,
        reference_time_delta: <crate::shared::ReferenceTimeDelta as crate::wire::Wire>::ZERO,
        external_timestamp: <crate::shared::ExternalTimestamp as crate::wire::Wire>::ZERO,
        external_time_delta: <crate::shared::ExternalTimeDelta as crate::wire::Wire>::ZERO,
    };
}

#[cfg(any(feature = "set-gnss-external", not(feature = "select-sets")))]
impl Default for Packet {
    fn default() -> Self {
        Self::ZERO
    }
}

#[cfg(any(feature = "set-gnss-external", not(feature = "select-sets")))]
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
            0x03 | 0x05 | 0x08 | 0x0B | 0x20 | 0xD0 | 0xD3 | 0xD4 | 0xD5 | 0xD6 | 0xD7 | 0xD8
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
            0x03 => Some(crate::FieldValue::GnssExternal(
                crate::gnss_external::SetField::LlhPosition(self.llh_position),
            )),
            0x05 => Some(crate::FieldValue::GnssExternal(
                crate::gnss_external::SetField::NedVelocity(self.ned_velocity),
            )),
            0x08 => Some(crate::FieldValue::GnssExternal(
                crate::gnss_external::SetField::UtcTime(self.utc_time),
            )),
            0x0B => Some(crate::FieldValue::GnssExternal(
                crate::gnss_external::SetField::FixInfo(self.fix_info),
            )),
            0x20 => Some(crate::FieldValue::GnssExternal(
                crate::gnss_external::SetField::SatelliteStatus(self.satellite_status),
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
#[cfg(any(feature = "set-gnss-external", not(feature = "select-sets")))]
pub fn decode_packet(
    payload: &[u8],
    out: &mut Packet,
    other: impl FnMut(crate::fields::FieldItem<'_>),
) -> usize {
    crate::packets::decode_set_packet(payload, out, other)
}
