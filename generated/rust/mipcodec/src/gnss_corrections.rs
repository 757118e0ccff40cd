//! GNSS Corrections Data Set. Information about the RTK correction stream: the base station reported in the RTCM messages and the status and latency of the corrections received. Sent as the data is received (base rate 0).
//!
//! Descriptor set 0x93 (data set):
//! one struct per field layout, and `SetField`, the enum of all its fields.

/// Descriptor set of this module.
pub const SET: u8 = 0x93;

/// Base station information. Base station reported by the RTCM corrections (message 1005 or 1006): its ECEF position, antenna height, station id and indicators, with the GPS time the message was received.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BaseStationInfo {
    /// GPS time of week the message was received. Units: s.
    pub tow: f64,
    /// GPS week number (since 1980). Units: weeks.
    pub week_number: u16,
    /// (x, y, z) ECEF position of the base station. Units: m.
    pub ecef_position: [f64; 3],
    /// Antenna height above the survey marker. Units: m.
    pub height: f32,
    /// Reference station id (0-4095).
    pub station_id: u16,
    /// Base station indicator bits.
    pub indicators: crate::types::GnssBaseStationIndicators,
    /// Which values are valid.
    pub valid_flags: crate::types::GnssBaseStationInfoValidFlags,
}

impl Default for BaseStationInfo {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for BaseStationInfo {
    const ZERO: Self = Self {
        tow: <f64 as crate::wire::Wire>::ZERO,
        week_number: <u16 as crate::wire::Wire>::ZERO,
        ecef_position: <[f64; 3] as crate::wire::Wire>::ZERO,
        height: <f32 as crate::wire::Wire>::ZERO,
        station_id: <u16 as crate::wire::Wire>::ZERO,
        indicators: <crate::types::GnssBaseStationIndicators as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::GnssBaseStationInfoValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(44);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_tow = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("tow"))?;
        let p_week_number =
            <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("week_number"))?;
        let p_ecef_position =
            <[f64; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("ecef_position"))?;
        let p_height = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("height"))?;
        let p_station_id = <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("station_id"))?;
        let p_indicators =
            <crate::types::GnssBaseStationIndicators as crate::wire::Wire>::decode(r)
                .map_err(|e| e.at("indicators"))?;
        let p_valid_flags =
            <crate::types::GnssBaseStationInfoValidFlags as crate::wire::Wire>::decode(r)
                .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            tow: p_tow,
            week_number: p_week_number,
            ecef_position: p_ecef_position,
            height: p_height,
            station_id: p_station_id,
            indicators: p_indicators,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.tow;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("tow"))?;
        let v = &self.week_number;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("week_number"))?;
        let v = &self.ecef_position;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("ecef_position"))?;
        let v = &self.height;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("height"))?;
        let v = &self.station_id;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("station_id"))?;
        let v = &self.indicators;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("indicators"))?;
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
        let v = &self.ecef_position;
        crate::json::key(w, &mut first, "ecef_position")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.height;
        crate::json::key(w, &mut first, "height")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.station_id;
        crate::json::key(w, &mut first, "station_id")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.indicators;
        crate::json::key(w, &mut first, "indicators")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for BaseStationInfo {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "tow",
                "week_number",
                "ecef_position",
                "height",
                "station_id",
                "indicators",
                "valid_flags",
            ],
        )?;
        let p_tow = o.req("tow", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_week_number = o.req(
            "week_number",
            <u16 as crate::json_read::FromJson>::from_json,
        )?;
        let p_ecef_position = o.req(
            "ecef_position",
            <[f64; 3] as crate::json_read::FromJson>::from_json,
        )?;
        let p_height = o.req("height", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_station_id = o.req("station_id", <u16 as crate::json_read::FromJson>::from_json)?;
        let p_indicators = o.req(
            "indicators",
            <crate::types::GnssBaseStationIndicators as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::GnssBaseStationInfoValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            tow: p_tow,
            week_number: p_week_number,
            ecef_position: p_ecef_position,
            height: p_height,
            station_id: p_station_id,
            indicators: p_indicators,
            valid_flags: p_valid_flags,
        })
    }
}

impl BaseStationInfo {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x93;
}

impl crate::wire::Layout for BaseStationInfo {
    const DESCRIPTOR: u8 = 0x30;
    const DESCRIPTOR_SET: Option<u8> = Some(0x93);
    const NAME: &'static str = "base_station_info";
}

/// RTK corrections status. Status of the RTK corrections received in the current epoch, the RTK dongle status and the latency of the last correction per constellation, with the GPS time.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RtkCorrectionsStatus {
    /// GPS time of week. Units: s.
    pub tow: f64,
    /// GPS week number (since 1980). Units: weeks.
    pub week_number: u16,
    /// Status of the corrections received during this epoch.
    pub epoch_status: crate::types::RtkCorrectionsEpochStatus,
    /// RTK dongle status flags (only valid when an RTK dongle is used).
    pub dongle_status: u32,
    /// Latency of the last GPS correction. Units: s.
    pub gps_correction_latency: f32,
    /// Latency of the last GLONASS correction. Units: s.
    pub glonass_correction_latency: f32,
    /// Latency of the last Galileo correction. Units: s.
    pub galileo_correction_latency: f32,
    /// Latency of the last BeiDou correction. Units: s.
    pub beidou_correction_latency: f32,
    /// Reserved for future use.
    pub reserved: [u32; 4],
    /// Which values are valid.
    pub valid_flags: crate::types::RtkCorrectionsStatusValidFlags,
}

impl Default for RtkCorrectionsStatus {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for RtkCorrectionsStatus {
    const ZERO: Self = Self {
        tow: <f64 as crate::wire::Wire>::ZERO,
        week_number: <u16 as crate::wire::Wire>::ZERO,
        epoch_status: <crate::types::RtkCorrectionsEpochStatus as crate::wire::Wire>::ZERO,
        dongle_status: <u32 as crate::wire::Wire>::ZERO,
        gps_correction_latency: <f32 as crate::wire::Wire>::ZERO,
        glonass_correction_latency: <f32 as crate::wire::Wire>::ZERO,
        galileo_correction_latency: <f32 as crate::wire::Wire>::ZERO,
        beidou_correction_latency: <f32 as crate::wire::Wire>::ZERO,
        reserved: <[u32; 4] as crate::wire::Wire>::ZERO,
        valid_flags: <crate::types::RtkCorrectionsStatusValidFlags as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(50);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_tow = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("tow"))?;
        let p_week_number =
            <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("week_number"))?;
        let p_epoch_status =
            <crate::types::RtkCorrectionsEpochStatus as crate::wire::Wire>::decode(r)
                .map_err(|e| e.at("epoch_status"))?;
        let p_dongle_status =
            <u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("dongle_status"))?;
        let p_gps_correction_latency =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("gps_correction_latency"))?;
        let p_glonass_correction_latency = <f32 as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("glonass_correction_latency"))?;
        let p_galileo_correction_latency = <f32 as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("galileo_correction_latency"))?;
        let p_beidou_correction_latency =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("beidou_correction_latency"))?;
        let p_reserved =
            <[u32; 4] as crate::wire::Wire>::decode(r).map_err(|e| e.at("reserved"))?;
        let p_valid_flags =
            <crate::types::RtkCorrectionsStatusValidFlags as crate::wire::Wire>::decode(r)
                .map_err(|e| e.at("valid_flags"))?;
        Ok(Self {
            tow: p_tow,
            week_number: p_week_number,
            epoch_status: p_epoch_status,
            dongle_status: p_dongle_status,
            gps_correction_latency: p_gps_correction_latency,
            glonass_correction_latency: p_glonass_correction_latency,
            galileo_correction_latency: p_galileo_correction_latency,
            beidou_correction_latency: p_beidou_correction_latency,
            reserved: p_reserved,
            valid_flags: p_valid_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.tow;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("tow"))?;
        let v = &self.week_number;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("week_number"))?;
        let v = &self.epoch_status;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("epoch_status"))?;
        let v = &self.dongle_status;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("dongle_status"))?;
        let v = &self.gps_correction_latency;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("gps_correction_latency"))?;
        let v = &self.glonass_correction_latency;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("glonass_correction_latency"))?;
        let v = &self.galileo_correction_latency;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("galileo_correction_latency"))?;
        let v = &self.beidou_correction_latency;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("beidou_correction_latency"))?;
        let v = &self.reserved;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("reserved"))?;
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
        let v = &self.epoch_status;
        crate::json::key(w, &mut first, "epoch_status")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.dongle_status;
        crate::json::key(w, &mut first, "dongle_status")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.gps_correction_latency;
        crate::json::key(w, &mut first, "gps_correction_latency")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.glonass_correction_latency;
        crate::json::key(w, &mut first, "glonass_correction_latency")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.galileo_correction_latency;
        crate::json::key(w, &mut first, "galileo_correction_latency")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.beidou_correction_latency;
        crate::json::key(w, &mut first, "beidou_correction_latency")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.reserved;
        crate::json::key(w, &mut first, "reserved")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.valid_flags;
        crate::json::key(w, &mut first, "valid_flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for RtkCorrectionsStatus {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "tow",
                "week_number",
                "epoch_status",
                "dongle_status",
                "gps_correction_latency",
                "glonass_correction_latency",
                "galileo_correction_latency",
                "beidou_correction_latency",
                "reserved",
                "valid_flags",
            ],
        )?;
        let p_tow = o.req("tow", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_week_number = o.req(
            "week_number",
            <u16 as crate::json_read::FromJson>::from_json,
        )?;
        let p_epoch_status = o.req(
            "epoch_status",
            <crate::types::RtkCorrectionsEpochStatus as crate::json_read::FromJson>::from_json,
        )?;
        let p_dongle_status = o.req(
            "dongle_status",
            <u32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_gps_correction_latency = o.req(
            "gps_correction_latency",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_glonass_correction_latency = o.req(
            "glonass_correction_latency",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_galileo_correction_latency = o.req(
            "galileo_correction_latency",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_beidou_correction_latency = o.req(
            "beidou_correction_latency",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_reserved = o.req(
            "reserved",
            <[u32; 4] as crate::json_read::FromJson>::from_json,
        )?;
        let p_valid_flags = o.req(
            "valid_flags",
            <crate::types::RtkCorrectionsStatusValidFlags as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            tow: p_tow,
            week_number: p_week_number,
            epoch_status: p_epoch_status,
            dongle_status: p_dongle_status,
            gps_correction_latency: p_gps_correction_latency,
            glonass_correction_latency: p_glonass_correction_latency,
            galileo_correction_latency: p_galileo_correction_latency,
            beidou_correction_latency: p_beidou_correction_latency,
            reserved: p_reserved,
            valid_flags: p_valid_flags,
        })
    }
}

impl RtkCorrectionsStatus {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x93;
}

impl crate::wire::Layout for RtkCorrectionsStatus {
    const DESCRIPTOR: u8 = 0x31;
    const DESCRIPTOR_SET: Option<u8> = Some(0x93);
    const NAME: &'static str = "rtk_corrections_status";
}

/// A decoded field of set 0x93 (`gnss_corrections`).
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SetField {
    /// `base_station_info` (0x30).
    BaseStationInfo(BaseStationInfo),
    /// `rtk_corrections_status` (0x31).
    RtkCorrectionsStatus(RtkCorrectionsStatus),
}

impl SetField {
    /// Field descriptor.
    pub fn descriptor(&self) -> u8 {
        match self {
            Self::BaseStationInfo(_) => 0x30,
            Self::RtkCorrectionsStatus(_) => 0x31,
        }
    }

    /// Field name as printed in JSON.
    pub fn name(&self) -> &'static str {
        match self {
            Self::BaseStationInfo(_) => "base_station_info",
            Self::RtkCorrectionsStatus(_) => "rtk_corrections_status",
        }
    }

    /// Device of the layout used, for fields with per-device layouts.
    pub fn device(&self) -> Option<crate::Device> {
        match self {
            Self::BaseStationInfo(_) => None,
            Self::RtkCorrectionsStatus(_) => None,
        }
    }

    /// Encodes the field data.
    pub fn encode_data(
        &self,
        w: &mut crate::wire::Writer<'_>,
    ) -> Result<(), crate::error::EncodeError> {
        match self {
            Self::BaseStationInfo(v) => crate::wire::Layout::encode_data(v, w),
            Self::RtkCorrectionsStatus(v) => crate::wire::Layout::encode_data(v, w),
        }
    }

    /// Writes the canonical JSON of the values (`{...}`).
    pub fn write_values_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::BaseStationInfo(v) => crate::wire::Wire::write_json(v, w),
            Self::RtkCorrectionsStatus(v) => crate::wire::Wire::write_json(v, w),
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
            0x30 => Some(
                <BaseStationInfo as crate::wire::Layout>::decode_data(data)
                    .map(Self::BaseStationInfo),
            ),
            0x31 => Some(
                <RtkCorrectionsStatus as crate::wire::Layout>::decode_data(data)
                    .map(Self::RtkCorrectionsStatus),
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
            0x30 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <BaseStationInfo as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::BaseStationInfo),
            ),
            0x31 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <RtkCorrectionsStatus as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::RtkCorrectionsStatus),
            ),
            _ => None,
        }
    }
}

/// The fields of one packet of this set, decoded in place by [`decode_packet`]: one member per
/// field of the set with one layout (its own and the shared data fields); `index` says which members hold a field of the last packet, in packet order
/// (the others hold whatever they held).
#[cfg(any(feature = "set-gnss-corrections", not(feature = "select-sets")))]
#[derive(Clone, Debug)]
pub struct Packet {
    /// The fields decoded into their members, in packet order.
    pub index: crate::packets::PacketIndex,
    /// Field 0x30.
    pub base_station_info: crate::gnss_corrections::BaseStationInfo,
    /// Field 0x31.
    pub rtk_corrections_status: crate::gnss_corrections::RtkCorrectionsStatus,
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

#[cfg(any(feature = "set-gnss-corrections", not(feature = "select-sets")))]
impl Packet {
    /// Nothing decoded, every member zero.
    pub const ZERO: Self = Self {
        index: crate::packets::PacketIndex::EMPTY,
        base_station_info: <crate::gnss_corrections::BaseStationInfo as crate::wire::Wire>::ZERO,
        rtk_corrections_status:
            <crate::gnss_corrections::RtkCorrectionsStatus as crate::wire::Wire>::ZERO,
        event_source: <crate::shared::EventSource as crate::wire::Wire>::ZERO,
        gps_timestamp: <crate::shared::GpsTimestamp as crate::wire::Wire>::ZERO,
        delta_time: <crate::shared::DeltaTime as crate::wire::Wire>::ZERO,
        reference_timestamp: <crate::shared::ReferenceTimestamp as crate::wire::Wire>::ZERO,
        reference_time_delta: <crate::shared::ReferenceTimeDelta as crate::wire::Wire>::ZERO,
        external_timestamp: <crate::shared::ExternalTimestamp as crate::wire::Wire>::ZERO,
        external_time_delta: <crate::shared::ExternalTimeDelta as crate::wire::Wire>::ZERO,
    };
}

#[cfg(any(feature = "set-gnss-corrections", not(feature = "select-sets")))]
impl Default for Packet {
    fn default() -> Self {
        Self::ZERO
    }
}

#[cfg(any(feature = "set-gnss-corrections", not(feature = "select-sets")))]
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
            0x30 | 0x31 | 0xD0 | 0xD3 | 0xD4 | 0xD5 | 0xD6 | 0xD7 | 0xD8
        )
    }

    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode_member(&mut self, descriptor: u8, data: &[u8]) -> bool {
        match descriptor {
            0x30 => match <&[u8; 44]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.base_station_info;
                    s.tow = crate::packets::ld(d, 0);
                    s.week_number = crate::packets::ld(d, 8);
                    s.ecef_position[0] = crate::packets::ld(d, 10);
                    s.ecef_position[1] = crate::packets::ld(d, 18);
                    s.ecef_position[2] = crate::packets::ld(d, 26);
                    s.height = crate::packets::ld(d, 34);
                    s.station_id = crate::packets::ld(d, 38);
                    s.indicators = crate::packets::ld(d, 40);
                    s.valid_flags = crate::packets::ld(d, 42);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.base_station_info),
            },
            0x31 => match <&[u8; 50]>::try_from(data) {
                // a fixed layout: one load per value at a constant offset, straight into the member
                Ok(d) => {
                    let s = &mut self.rtk_corrections_status;
                    s.tow = crate::packets::ld(d, 0);
                    s.week_number = crate::packets::ld(d, 8);
                    s.epoch_status = crate::packets::ld(d, 10);
                    s.dongle_status = crate::packets::ld(d, 12);
                    s.gps_correction_latency = crate::packets::ld(d, 16);
                    s.glonass_correction_latency = crate::packets::ld(d, 20);
                    s.galileo_correction_latency = crate::packets::ld(d, 24);
                    s.beidou_correction_latency = crate::packets::ld(d, 28);
                    s.reserved[0] = crate::packets::ld(d, 32);
                    s.reserved[1] = crate::packets::ld(d, 36);
                    s.reserved[2] = crate::packets::ld(d, 40);
                    s.reserved[3] = crate::packets::ld(d, 44);
                    s.valid_flags = crate::packets::ld(d, 48);
                    true
                }
                _ => crate::packets::decode_into(data, &mut self.rtk_corrections_status),
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
            0x30 => Some(crate::FieldValue::GnssCorrections(
                crate::gnss_corrections::SetField::BaseStationInfo(self.base_station_info),
            )),
            0x31 => Some(crate::FieldValue::GnssCorrections(
                crate::gnss_corrections::SetField::RtkCorrectionsStatus(
                    self.rtk_corrections_status,
                ),
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
#[cfg(any(feature = "set-gnss-corrections", not(feature = "select-sets")))]
pub fn decode_packet(
    payload: &[u8],
    out: &mut Packet,
    other: impl FnMut(crate::fields::FieldItem<'_>),
) -> usize {
    crate::packets::decode_set_packet(payload, out, other)
}
