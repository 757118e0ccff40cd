//! Shared Data Descriptors. Timestamps, time deltas and the event source, usable in any data descriptor set. Placed at the front of a message format, they are repeated in every continuation packet of a message that does not fit in one packet, so that a parser can group the packets of one sample by their timestamp (CV7 lines 4002-4024). The GX5-45 has no shared descriptors.
//!
//! Descriptor set 0xFF (data set; its fields are valid in every data set):
//! one struct per field layout, and `SetField`, the enum of all its fields.

/// Descriptor set of this module.
pub const SET: u8 = 0xFF;

/// Event source. Which event trigger caused this packet to be sent; 0 for packets sent by the scheduled streaming of the message format (0x0C,0x0F). Recommended as the first field of every event packet; as a shared descriptor it is repeated in continuation packets.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EventSource {
    /// Trigger (or, per line 1836, action) instance ID; 0 for scheduled streaming.
    pub trigger_id: u8,
}

impl Default for EventSource {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for EventSource {
    const ZERO: Self = Self {
        trigger_id: <u8 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(1);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_trigger_id = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("trigger_id"))?;
        Ok(Self {
            trigger_id: p_trigger_id,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.trigger_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("trigger_id"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.trigger_id;
        crate::json::key(w, &mut first, "trigger_id")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for EventSource {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["trigger_id"])?;
        let p_trigger_id = o.req("trigger_id", <u8 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            trigger_id: p_trigger_id,
        })
    }
}

impl EventSource {
    /// Descriptor set of the field.
    pub const SET: u8 = 0xFF;
}

impl crate::wire::Layout for EventSource {
    const DESCRIPTOR: u8 = 0xD0;
    const DESCRIPTOR_SET: Option<u8> = Some(0xFF);
    const NAME: &'static str = "event_source";
}

/// GPS timestamp. GPS time of the sample (for event packets, of the event trigger) as time of week and week number. Valid after PPS synchronisation and after both the time of week and the week number have been sent with the GPS Time Update command (0x01,0x72).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GpsTimestamp {
    /// GPS time of week. Units: s.
    pub tow: f64,
    /// GPS week number since 1980. Units: weeks.
    pub week_number: u16,
    /// Which parts of the time have been set.
    pub valid_flags: crate::types::SharedGpsTimestampValidFlags,
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
        valid_flags: <crate::types::SharedGpsTimestampValidFlags as crate::wire::Wire>::ZERO,
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
        let p_valid_flags =
            <crate::types::SharedGpsTimestampValidFlags as crate::wire::Wire>::decode(r)
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
            <crate::types::SharedGpsTimestampValidFlags as crate::json_read::FromJson>::from_json,
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
    pub const SET: u8 = 0xFF;
}

impl crate::wire::Layout for GpsTimestamp {
    const DESCRIPTOR: u8 = 0xD3;
    const DESCRIPTOR_SET: Option<u8> = Some(0xFF);
    const NAME: &'static str = "gps_timestamp";
}

/// Delta time. Seconds in the synchronised (external/GPS) clock domain since the last output of this field in the same descriptor set and event instance. The same value as external time delta 0xD8 in seconds; both restart one shared counter, so stream only one of them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DeltaTime {
    /// Seconds since the last output. Units: s.
    pub seconds: f64,
}

impl Default for DeltaTime {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for DeltaTime {
    const ZERO: Self = Self {
        seconds: <f64 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(8);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_seconds = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("seconds"))?;
        Ok(Self { seconds: p_seconds })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.seconds;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("seconds"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.seconds;
        crate::json::key(w, &mut first, "seconds")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for DeltaTime {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["seconds"])?;
        let p_seconds = o.req("seconds", <f64 as crate::json_read::FromJson>::from_json)?;
        Ok(Self { seconds: p_seconds })
    }
}

impl DeltaTime {
    /// Descriptor set of the field.
    pub const SET: u8 = 0xFF;
}

impl crate::wire::Layout for DeltaTime {
    const DESCRIPTOR: u8 = 0xD4;
    const DESCRIPTOR_SET: Option<u8> = Some(0xFF);
    const NAME: &'static str = "delta_time";
}

/// Reference timestamp. Time at which the data was sampled (for events, of the trigger) on the internal monotonic reference clock, in nanoseconds since power-on. Never jumps; always valid.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReferenceTimestamp {
    /// Nanoseconds since initialization. Units: ns.
    pub nanoseconds: u64,
}

impl Default for ReferenceTimestamp {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ReferenceTimestamp {
    const ZERO: Self = Self {
        nanoseconds: <u64 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(8);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_nanoseconds =
            <u64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("nanoseconds"))?;
        Ok(Self {
            nanoseconds: p_nanoseconds,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.nanoseconds;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("nanoseconds"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.nanoseconds;
        crate::json::key(w, &mut first, "nanoseconds")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ReferenceTimestamp {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["nanoseconds"])?;
        let p_nanoseconds = o.req(
            "nanoseconds",
            <u64 as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            nanoseconds: p_nanoseconds,
        })
    }
}

impl ReferenceTimestamp {
    /// Descriptor set of the field.
    pub const SET: u8 = 0xFF;
}

impl crate::wire::Layout for ReferenceTimestamp {
    const DESCRIPTOR: u8 = 0xD5;
    const DESCRIPTOR_SET: Option<u8> = Some(0xFF);
    const NAME: &'static str = "reference_timestamp";
}

/// Reference time delta. Difference between the reference timestamp (0xD5) now and at the previous output of this field in the same descriptor set and event instance. Always valid.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReferenceTimeDelta {
    /// Nanoseconds since the last occurrence of this field. Units: ns.
    pub dt_nanos: u64,
}

impl Default for ReferenceTimeDelta {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ReferenceTimeDelta {
    const ZERO: Self = Self {
        dt_nanos: <u64 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(8);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_dt_nanos = <u64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("dt_nanos"))?;
        Ok(Self {
            dt_nanos: p_dt_nanos,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.dt_nanos;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("dt_nanos"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.dt_nanos;
        crate::json::key(w, &mut first, "dt_nanos")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ReferenceTimeDelta {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["dt_nanos"])?;
        let p_dt_nanos = o.req("dt_nanos", <u64 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            dt_nanos: p_dt_nanos,
        })
    }
}

impl ReferenceTimeDelta {
    /// Descriptor set of the field.
    pub const SET: u8 = 0xFF;
}

impl crate::wire::Layout for ReferenceTimeDelta {
    const DESCRIPTOR: u8 = 0xD6;
    const DESCRIPTOR_SET: Option<u8> = Some(0xFF);
    const NAME: &'static str = "reference_time_delta";
}

/// External timestamp. Time at which the data was sampled (for events, of the trigger) in the external clock domain, in nanoseconds: the GPS timestamp in nanoseconds. Valid once the external clock is synchronised with the PPS input.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ExternalTimestamp {
    /// External time in nanoseconds. Units: ns.
    pub nanoseconds: u64,
    /// Bit 0: nanoseconds valid.
    pub valid_flags: crate::types::ExternalTimestampValidFlags,
}

impl Default for ExternalTimestamp {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ExternalTimestamp {
    const ZERO: Self = Self {
        nanoseconds: <u64 as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::ExternalTimestampValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(10);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_nanoseconds =
            <u64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("nanoseconds"))?;
        let p_valid_flags =
            <crate::types::ExternalTimestampValidFlags as crate::wire::Wire>::decode(r)
                .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            nanoseconds: p_nanoseconds,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.nanoseconds;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("nanoseconds"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.nanoseconds;
        crate::json::key(w, &mut first, "nanoseconds")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ExternalTimestamp {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["nanoseconds", "valid_flags"])?;
        let p_nanoseconds = o.req(
            "nanoseconds",
            <u64 as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::ExternalTimestampValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            nanoseconds: p_nanoseconds,
            valid_flags: p_valid_flags,
        })
    }
}

impl ExternalTimestamp {
    /// Descriptor set of the field.
    pub const SET: u8 = 0xFF;
}

impl crate::wire::Layout for ExternalTimestamp {
    const DESCRIPTOR: u8 = 0xD7;
    const DESCRIPTOR_SET: Option<u8> = Some(0xFF);
    const NAME: &'static str = "external_timestamp";
}

/// External time delta. Difference between the external timestamp (0xD7) now and at the previous output of this field in the same descriptor set and event instance. The same value as delta time 0xD4 in nanoseconds; both restart one shared counter.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ExternalTimeDelta {
    /// Nanoseconds since the last occurrence of this field. Units: ns.
    pub dt_nanos: u64,
    /// Bit 0: delta valid.
    pub valid_flags: crate::types::ExternalTimeDeltaValidFlags,
}

impl Default for ExternalTimeDelta {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ExternalTimeDelta {
    const ZERO: Self = Self {
        dt_nanos: <u64 as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::ExternalTimeDeltaValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(10);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_dt_nanos = <u64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("dt_nanos"))?;
        let p_valid_flags =
            <crate::types::ExternalTimeDeltaValidFlags as crate::wire::Wire>::decode(r)
                .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            dt_nanos: p_dt_nanos,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.dt_nanos;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("dt_nanos"))?;
        let v = &self.valid_flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("valid_flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.dt_nanos;
        crate::json::key(w, &mut first, "dt_nanos")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ExternalTimeDelta {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["dt_nanos", "valid_flags"])?;
        let p_dt_nanos = o.req("dt_nanos", <u64 as crate::json_read::FromJson>::from_json)?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::ExternalTimeDeltaValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            dt_nanos: p_dt_nanos,
            valid_flags: p_valid_flags,
        })
    }
}

impl ExternalTimeDelta {
    /// Descriptor set of the field.
    pub const SET: u8 = 0xFF;
}

impl crate::wire::Layout for ExternalTimeDelta {
    const DESCRIPTOR: u8 = 0xD8;
    const DESCRIPTOR_SET: Option<u8> = Some(0xFF);
    const NAME: &'static str = "external_time_delta";
}

/// A decoded field of set 0xFF (`shared`).
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SetField {
    /// `event_source` (0xD0).
    EventSource(EventSource),
    /// `gps_timestamp` (0xD3).
    GpsTimestamp(GpsTimestamp),
    /// `delta_time` (0xD4).
    DeltaTime(DeltaTime),
    /// `reference_timestamp` (0xD5).
    ReferenceTimestamp(ReferenceTimestamp),
    /// `reference_time_delta` (0xD6).
    ReferenceTimeDelta(ReferenceTimeDelta),
    /// `external_timestamp` (0xD7).
    ExternalTimestamp(ExternalTimestamp),
    /// `external_time_delta` (0xD8).
    ExternalTimeDelta(ExternalTimeDelta),
}

impl SetField {
    /// Field descriptor.
    pub fn descriptor(&self) -> u8 {
        match self {
            Self::EventSource(_) => 0xD0,
            Self::GpsTimestamp(_) => 0xD3,
            Self::DeltaTime(_) => 0xD4,
            Self::ReferenceTimestamp(_) => 0xD5,
            Self::ReferenceTimeDelta(_) => 0xD6,
            Self::ExternalTimestamp(_) => 0xD7,
            Self::ExternalTimeDelta(_) => 0xD8,
        }
    }

    /// Field name as printed in JSON.
    pub fn name(&self) -> &'static str {
        match self {
            Self::EventSource(_) => "event_source",
            Self::GpsTimestamp(_) => "gps_timestamp",
            Self::DeltaTime(_) => "delta_time",
            Self::ReferenceTimestamp(_) => "reference_timestamp",
            Self::ReferenceTimeDelta(_) => "reference_time_delta",
            Self::ExternalTimestamp(_) => "external_timestamp",
            Self::ExternalTimeDelta(_) => "external_time_delta",
        }
    }

    /// Device of the layout used, for fields with per-device layouts.
    pub fn device(&self) -> Option<crate::Device> {
        match self {
            Self::EventSource(_) => None,
            Self::GpsTimestamp(_) => None,
            Self::DeltaTime(_) => None,
            Self::ReferenceTimestamp(_) => None,
            Self::ReferenceTimeDelta(_) => None,
            Self::ExternalTimestamp(_) => None,
            Self::ExternalTimeDelta(_) => None,
        }
    }

    /// Encodes the field data.
    pub fn encode_data(
        &self,
        w: &mut crate::wire::Writer<'_>,
    ) -> Result<(), crate::error::EncodeError> {
        match self {
            Self::EventSource(v) => crate::wire::Layout::encode_data(v, w),
            Self::GpsTimestamp(v) => crate::wire::Layout::encode_data(v, w),
            Self::DeltaTime(v) => crate::wire::Layout::encode_data(v, w),
            Self::ReferenceTimestamp(v) => crate::wire::Layout::encode_data(v, w),
            Self::ReferenceTimeDelta(v) => crate::wire::Layout::encode_data(v, w),
            Self::ExternalTimestamp(v) => crate::wire::Layout::encode_data(v, w),
            Self::ExternalTimeDelta(v) => crate::wire::Layout::encode_data(v, w),
        }
    }

    /// Writes the canonical JSON of the values (`{...}`).
    pub fn write_values_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::EventSource(v) => crate::wire::Wire::write_json(v, w),
            Self::GpsTimestamp(v) => crate::wire::Wire::write_json(v, w),
            Self::DeltaTime(v) => crate::wire::Wire::write_json(v, w),
            Self::ReferenceTimestamp(v) => crate::wire::Wire::write_json(v, w),
            Self::ReferenceTimeDelta(v) => crate::wire::Wire::write_json(v, w),
            Self::ExternalTimestamp(v) => crate::wire::Wire::write_json(v, w),
            Self::ExternalTimeDelta(v) => crate::wire::Wire::write_json(v, w),
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
            0xD0 => {
                Some(<EventSource as crate::wire::Layout>::decode_data(data).map(Self::EventSource))
            }
            0xD3 => Some(
                <GpsTimestamp as crate::wire::Layout>::decode_data(data).map(Self::GpsTimestamp),
            ),
            0xD4 => {
                Some(<DeltaTime as crate::wire::Layout>::decode_data(data).map(Self::DeltaTime))
            }
            0xD5 => Some(
                <ReferenceTimestamp as crate::wire::Layout>::decode_data(data)
                    .map(Self::ReferenceTimestamp),
            ),
            0xD6 => Some(
                <ReferenceTimeDelta as crate::wire::Layout>::decode_data(data)
                    .map(Self::ReferenceTimeDelta),
            ),
            0xD7 => Some(
                <ExternalTimestamp as crate::wire::Layout>::decode_data(data)
                    .map(Self::ExternalTimestamp),
            ),
            0xD8 => Some(
                <ExternalTimeDelta as crate::wire::Layout>::decode_data(data)
                    .map(Self::ExternalTimeDelta),
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
            0xD0 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <EventSource as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::EventSource),
            ),
            0xD3 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GpsTimestamp as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::GpsTimestamp),
            ),
            0xD4 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <DeltaTime as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::DeltaTime),
            ),
            0xD5 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ReferenceTimestamp as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::ReferenceTimestamp),
            ),
            0xD6 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ReferenceTimeDelta as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::ReferenceTimeDelta),
            ),
            0xD7 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ExternalTimestamp as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::ExternalTimestamp),
            ),
            0xD8 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ExternalTimeDelta as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::ExternalTimeDelta),
            ),
            _ => None,
        }
    }
}

/// The fields of one packet of this set, decoded in place by [`decode_packet`]: one member per
/// field of the set with one layout (its own); `index` says which members hold a field of the last packet, in packet order
/// (the others hold whatever they held).
#[cfg(any(feature = "set-shared", not(feature = "select-sets")))]
#[derive(Clone, Debug)]
pub struct Packet {
    /// The fields decoded into their members, in packet order.
    pub index: crate::packets::PacketIndex,
    /// Field 0xD0.
    pub event_source: crate::shared::EventSource,
    /// Field 0xD3.
    pub gps_timestamp: crate::shared::GpsTimestamp,
    /// Field 0xD4.
    pub delta_time: crate::shared::DeltaTime,
    /// Field 0xD5.
    pub reference_timestamp: crate::shared::ReferenceTimestamp,
    /// Field 0xD6.
    pub reference_time_delta: crate::shared::ReferenceTimeDelta,
    /// Field 0xD7.
    pub external_timestamp: crate::shared::ExternalTimestamp,
    /// Field 0xD8.
    pub external_time_delta: crate::shared::ExternalTimeDelta,
}

#[cfg(any(feature = "set-shared", not(feature = "select-sets")))]
impl Packet {
    /// Nothing decoded, every member zero.
    pub const ZERO: Self = Self {
        index: crate::packets::PacketIndex::EMPTY,
        event_source: <crate::shared::EventSource as crate::wire::Wire>::ZERO,
        gps_timestamp: <crate::shared::GpsTimestamp as crate::wire::Wire>::ZERO,
        delta_time: <crate::shared::DeltaTime as crate::wire::Wire>::ZERO,
        reference_timestamp: <crate::shared::ReferenceTimestamp as crate::wire::Wire>::ZERO,
        reference_time_delta: <crate::shared::ReferenceTimeDelta as crate::wire::Wire>::ZERO,
        external_timestamp: <crate::shared::ExternalTimestamp as crate::wire::Wire>::ZERO,
        external_time_delta: <crate::shared::ExternalTimeDelta as crate::wire::Wire>::ZERO,
    };
}

#[cfg(any(feature = "set-shared", not(feature = "select-sets")))]
impl Default for Packet {
    fn default() -> Self {
        Self::ZERO
    }
}

#[cfg(any(feature = "set-shared", not(feature = "select-sets")))]
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
        matches!(descriptor, 0xD0 | 0xD3 | 0xD4 | 0xD5 | 0xD6 | 0xD7 | 0xD8)
    }

    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode_member(&mut self, descriptor: u8, data: &[u8]) -> bool {
        match descriptor {
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
#[cfg(any(feature = "set-shared", not(feature = "select-sets")))]
pub fn decode_packet(
    payload: &[u8],
    out: &mut Packet,
    other: impl FnMut(crate::fields::FieldItem<'_>),
) -> usize {
    crate::packets::decode_set_packet(payload, out, other)
}
