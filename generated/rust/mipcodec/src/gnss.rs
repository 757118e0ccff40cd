//! GNSS Command Set. Configuration of the device's GNSS receivers and correction services.
//!
//! Descriptor set 0x0E (command set):
//! one struct per field layout, and `SetField`, the enum of all its fields.

/// Descriptor set of this module.
pub const SET: u8 = 0x0E;

/// Receiver info. Get information about the GNSS receivers in the device.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReceiverInfo {}

impl Default for ReceiverInfo {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ReceiverInfo {
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
impl crate::json_read::FromJson for ReceiverInfo {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        crate::json_read::Obj::new(v, &[])?;
        Ok(Self {})
    }
}

impl ReceiverInfo {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0E;
}

impl crate::wire::Layout for ReceiverInfo {
    const DESCRIPTOR: u8 = 0x01;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0E);
    const NAME: &'static str = "receiver_info";
}

/// Receiver info (response). One entry per physical GNSS receiver.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReceiverInfoResponse {
    /// Number of physical receivers in the device.
    pub num_receivers: u8,
    /// Information on each receiver.
    pub receiver_info: crate::bounded::BoundedVec<crate::types::GnssReceiverInfoEntry, 7>,
}

impl Default for ReceiverInfoResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ReceiverInfoResponse {
    const ZERO: Self = Self {
        num_receivers: <u8 as crate::wire::Wire>::ZERO,
        receiver_info: <crate::bounded::BoundedVec<crate::types::GnssReceiverInfoEntry, 7> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_num_receivers =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("num_receivers"))?;
        let p_receiver_info =
            crate::bounded::BoundedVec::<crate::types::GnssReceiverInfoEntry, 7>::decode_counted(
                r,
                u64::from(p_num_receivers),
            )
            .map_err(|e| e.at("receiver_info"))?;
        Ok(Self {
            num_receivers: p_num_receivers,
            receiver_info: p_receiver_info,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.num_receivers;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("num_receivers"))?;
        let v = &self.receiver_info;
        v.encode_counted(w, u64::from(self.num_receivers))
            .map_err(|e| e.at("receiver_info"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.num_receivers;
        crate::json::key(w, &mut first, "num_receivers")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.receiver_info;
        crate::json::key(w, &mut first, "receiver_info")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ReceiverInfoResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["num_receivers", "receiver_info"])?;
        let p_num_receivers = o.req(
            "num_receivers",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_receiver_info = o.req("receiver_info", <crate::bounded::BoundedVec<crate::types::GnssReceiverInfoEntry, 7> as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            num_receivers: p_num_receivers,
            receiver_info: p_receiver_info,
        })
    }
}

impl ReceiverInfoResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0E;
}

impl crate::wire::Layout for ReceiverInfoResponse {
    const DESCRIPTOR: u8 = 0x81;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0E);
    const NAME: &'static str = "receiver_info_response";
}

/// Signal configuration. Choose the GNSS constellations and frequency bands the receivers use. Only some combinations are valid: GPS or Galileo must be enabled, GPS L1 with BeiDou L1 alone is not allowed, and per constellation GPS none / L1 / L1+L5, GLONASS none / L1, Galileo none / L1+L5, BeiDou none / L1 / L1+L5.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SignalConfiguration {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// GPS signals to use. Sent for: write.
    pub gps_enable: Option<crate::types::GnssGpsSignals>,
    /// GLONASS signals to use. Sent for: write.
    pub glonass_enable: Option<crate::types::GnssGlonassSignals>,
    /// Galileo signals to use. Sent for: write.
    pub galileo_enable: Option<crate::types::GnssGalileoSignals>,
    /// BeiDou signals to use. Sent for: write.
    pub beidou_enable: Option<crate::types::GnssBeidouSignals>,
    /// Reserved. Sent for: write.
    pub reserved: Option<[u8; 4]>,
}

impl Default for SignalConfiguration {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SignalConfiguration {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        gps_enable: None,
        glonass_enable: None,
        galileo_enable: None,
        beidou_enable: None,
        reserved: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_gps_enable = if r.left() > 0 {
            Some(
                <crate::types::GnssGpsSignals as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("gps_enable"))?,
            )
        } else {
            None
        };
        let p_glonass_enable = if r.left() > 0 {
            Some(
                <crate::types::GnssGlonassSignals as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("glonass_enable"))?,
            )
        } else {
            None
        };
        let p_galileo_enable = if r.left() > 0 {
            Some(
                <crate::types::GnssGalileoSignals as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("galileo_enable"))?,
            )
        } else {
            None
        };
        let p_beidou_enable = if r.left() > 0 {
            Some(
                <crate::types::GnssBeidouSignals as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("beidou_enable"))?,
            )
        } else {
            None
        };
        let p_reserved = if r.left() > 0 {
            Some(<[u8; 4] as crate::wire::Wire>::decode(r).map_err(|e| e.at("reserved"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            gps_enable: p_gps_enable,
            glonass_enable: p_glonass_enable,
            galileo_enable: p_galileo_enable,
            beidou_enable: p_beidou_enable,
            reserved: p_reserved,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.gps_enable {
            optionals.present("gps_enable")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("gps_enable"))?;
        } else {
            optionals.absent("gps_enable");
        }
        if let Some(v) = &self.glonass_enable {
            optionals.present("glonass_enable")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("glonass_enable"))?;
        } else {
            optionals.absent("glonass_enable");
        }
        if let Some(v) = &self.galileo_enable {
            optionals.present("galileo_enable")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("galileo_enable"))?;
        } else {
            optionals.absent("galileo_enable");
        }
        if let Some(v) = &self.beidou_enable {
            optionals.present("beidou_enable")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("beidou_enable"))?;
        } else {
            optionals.absent("beidou_enable");
        }
        if let Some(v) = &self.reserved {
            optionals.present("reserved")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("reserved"))?;
        } else {
            optionals.absent("reserved");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.gps_enable {
            crate::json::key(w, &mut first, "gps_enable")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.glonass_enable {
            crate::json::key(w, &mut first, "glonass_enable")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.galileo_enable {
            crate::json::key(w, &mut first, "galileo_enable")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.beidou_enable {
            crate::json::key(w, &mut first, "beidou_enable")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.reserved {
            crate::json::key(w, &mut first, "reserved")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SignalConfiguration {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "function",
                "gps_enable",
                "glonass_enable",
                "galileo_enable",
                "beidou_enable",
                "reserved",
            ],
        )?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_gps_enable = o.opt(
            "gps_enable",
            <crate::types::GnssGpsSignals as crate::json_read::FromJson>::from_json,
        )?;
        let p_glonass_enable = o.opt(
            "glonass_enable",
            <crate::types::GnssGlonassSignals as crate::json_read::FromJson>::from_json,
        )?;
        let p_galileo_enable = o.opt(
            "galileo_enable",
            <crate::types::GnssGalileoSignals as crate::json_read::FromJson>::from_json,
        )?;
        let p_beidou_enable = o.opt(
            "beidou_enable",
            <crate::types::GnssBeidouSignals as crate::json_read::FromJson>::from_json,
        )?;
        let p_reserved = o.opt(
            "reserved",
            <[u8; 4] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            gps_enable: p_gps_enable,
            glonass_enable: p_glonass_enable,
            galileo_enable: p_galileo_enable,
            beidou_enable: p_beidou_enable,
            reserved: p_reserved,
        })
    }
}

impl SignalConfiguration {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0E;
}

impl crate::wire::Layout for SignalConfiguration {
    const DESCRIPTOR: u8 = 0x02;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0E);
    const NAME: &'static str = "signal_configuration";
}

/// Signal configuration (response). GNSS signals currently enabled.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SignalConfigurationResponse {
    /// GPS signals in use.
    pub gps_enable: crate::types::GnssGpsSignals,
    /// GLONASS signals in use.
    pub glonass_enable: crate::types::GnssGlonassSignals,
    /// Galileo signals in use.
    pub galileo_enable: crate::types::GnssGalileoSignals,
    /// BeiDou signals in use.
    pub beidou_enable: crate::types::GnssBeidouSignals,
    /// Reserved.
    pub reserved: [u8; 4],
}

impl Default for SignalConfigurationResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SignalConfigurationResponse {
    const ZERO: Self = Self {
        gps_enable: <crate::types::GnssGpsSignals as crate::wire::Wire>::ZERO,
        glonass_enable: <crate::types::GnssGlonassSignals as crate::wire::Wire>::ZERO,
        galileo_enable: <crate::types::GnssGalileoSignals as crate::wire::Wire>::ZERO,
        beidou_enable: <crate::types::GnssBeidouSignals as crate::wire::Wire>::ZERO,
        reserved: <[u8; 4] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(8);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_gps_enable = <crate::types::GnssGpsSignals as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("gps_enable"))?;
        let p_glonass_enable = <crate::types::GnssGlonassSignals as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("glonass_enable"))?;
        let p_galileo_enable = <crate::types::GnssGalileoSignals as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("galileo_enable"))?;
        let p_beidou_enable = <crate::types::GnssBeidouSignals as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("beidou_enable"))?;
        let p_reserved = <[u8; 4] as crate::wire::Wire>::decode(r).map_err(|e| e.at("reserved"))?;
        Ok(Self {
            gps_enable: p_gps_enable,
            glonass_enable: p_glonass_enable,
            galileo_enable: p_galileo_enable,
            beidou_enable: p_beidou_enable,
            reserved: p_reserved,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.gps_enable;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("gps_enable"))?;
        let v = &self.glonass_enable;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("glonass_enable"))?;
        let v = &self.galileo_enable;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("galileo_enable"))?;
        let v = &self.beidou_enable;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("beidou_enable"))?;
        let v = &self.reserved;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("reserved"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.gps_enable;
        crate::json::key(w, &mut first, "gps_enable")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.glonass_enable;
        crate::json::key(w, &mut first, "glonass_enable")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.galileo_enable;
        crate::json::key(w, &mut first, "galileo_enable")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.beidou_enable;
        crate::json::key(w, &mut first, "beidou_enable")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.reserved;
        crate::json::key(w, &mut first, "reserved")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SignalConfigurationResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "gps_enable",
                "glonass_enable",
                "galileo_enable",
                "beidou_enable",
                "reserved",
            ],
        )?;
        let p_gps_enable = o.req(
            "gps_enable",
            <crate::types::GnssGpsSignals as crate::json_read::FromJson>::from_json,
        )?;
        let p_glonass_enable = o.req(
            "glonass_enable",
            <crate::types::GnssGlonassSignals as crate::json_read::FromJson>::from_json,
        )?;
        let p_galileo_enable = o.req(
            "galileo_enable",
            <crate::types::GnssGalileoSignals as crate::json_read::FromJson>::from_json,
        )?;
        let p_beidou_enable = o.req(
            "beidou_enable",
            <crate::types::GnssBeidouSignals as crate::json_read::FromJson>::from_json,
        )?;
        let p_reserved = o.req(
            "reserved",
            <[u8; 4] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            gps_enable: p_gps_enable,
            glonass_enable: p_glonass_enable,
            galileo_enable: p_galileo_enable,
            beidou_enable: p_beidou_enable,
            reserved: p_reserved,
        })
    }
}

impl SignalConfigurationResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0E;
}

impl crate::wire::Layout for SignalConfigurationResponse {
    const DESCRIPTOR: u8 = 0x82;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0E);
    const NAME: &'static str = "signal_configuration_response";
}

/// SPARTN configuration. Configure the SPARTN corrections service: enable, connection type, and the current and next decryption keys with the GPS week and time of week until which each is valid. Enable and type take effect after a power cycle; keys can be updated while running. Enabling SPARTN blocks RTCM corrections.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpartnConfiguration {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// SPARTN subsystem: 0 disabled, 1 enabled. Sent for: write.
    pub enable: Option<u8>,
    /// Connection type. Sent for: write.
    pub r#type: Option<crate::types::SpartnConnectionType>,
    /// GPS time of week until which the current key is valid. Units: s. Sent for: write.
    pub current_key_tow: Option<u32>,
    /// GPS week until which the current key is valid. Units: weeks. Sent for: write.
    pub current_key_week: Option<u16>,
    /// Current key: 32 ASCII hex characters (e.g. "bc" for 0xBC). Sent for: write.
    pub current_key: Option<crate::wire::Str<32>>,
    /// GPS time of week until which the next key is valid. Units: s. Sent for: write.
    pub next_key_tow: Option<u32>,
    /// GPS week until which the next key is valid. Units: weeks. Sent for: write.
    pub next_key_week: Option<u16>,
    /// Next key: 32 ASCII hex characters. Sent for: write.
    pub next_key: Option<crate::wire::Str<32>>,
}

impl Default for SpartnConfiguration {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SpartnConfiguration {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        enable: None,
        r#type: None,
        current_key_tow: None,
        current_key_week: None,
        current_key: None,
        next_key_tow: None,
        next_key_week: None,
        next_key: None,
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
        let p_type = if r.left() > 0 {
            Some(
                <crate::types::SpartnConnectionType as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("type"))?,
            )
        } else {
            None
        };
        let p_current_key_tow = if r.left() > 0 {
            Some(<u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("current_key_tow"))?)
        } else {
            None
        };
        let p_current_key_week = if r.left() > 0 {
            Some(<u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("current_key_week"))?)
        } else {
            None
        };
        let p_current_key = if r.left() > 0 {
            Some(
                <crate::wire::Str<32> as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("current_key"))?,
            )
        } else {
            None
        };
        let p_next_key_tow = if r.left() > 0 {
            Some(<u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("next_key_tow"))?)
        } else {
            None
        };
        let p_next_key_week = if r.left() > 0 {
            Some(<u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("next_key_week"))?)
        } else {
            None
        };
        let p_next_key = if r.left() > 0 {
            Some(
                <crate::wire::Str<32> as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("next_key"))?,
            )
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            enable: p_enable,
            r#type: p_type,
            current_key_tow: p_current_key_tow,
            current_key_week: p_current_key_week,
            current_key: p_current_key,
            next_key_tow: p_next_key_tow,
            next_key_week: p_next_key_week,
            next_key: p_next_key,
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
        if let Some(v) = &self.r#type {
            optionals.present("type")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("type"))?;
        } else {
            optionals.absent("type");
        }
        if let Some(v) = &self.current_key_tow {
            optionals.present("current_key_tow")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("current_key_tow"))?;
        } else {
            optionals.absent("current_key_tow");
        }
        if let Some(v) = &self.current_key_week {
            optionals.present("current_key_week")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("current_key_week"))?;
        } else {
            optionals.absent("current_key_week");
        }
        if let Some(v) = &self.current_key {
            optionals.present("current_key")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("current_key"))?;
        } else {
            optionals.absent("current_key");
        }
        if let Some(v) = &self.next_key_tow {
            optionals.present("next_key_tow")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("next_key_tow"))?;
        } else {
            optionals.absent("next_key_tow");
        }
        if let Some(v) = &self.next_key_week {
            optionals.present("next_key_week")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("next_key_week"))?;
        } else {
            optionals.absent("next_key_week");
        }
        if let Some(v) = &self.next_key {
            optionals.present("next_key")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("next_key"))?;
        } else {
            optionals.absent("next_key");
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
        if let Some(v) = &self.r#type {
            crate::json::key(w, &mut first, "type")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.current_key_tow {
            crate::json::key(w, &mut first, "current_key_tow")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.current_key_week {
            crate::json::key(w, &mut first, "current_key_week")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.current_key {
            crate::json::key(w, &mut first, "current_key")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.next_key_tow {
            crate::json::key(w, &mut first, "next_key_tow")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.next_key_week {
            crate::json::key(w, &mut first, "next_key_week")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.next_key {
            crate::json::key(w, &mut first, "next_key")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SpartnConfiguration {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "function",
                "enable",
                "type",
                "current_key_tow",
                "current_key_week",
                "current_key",
                "next_key_tow",
                "next_key_week",
                "next_key",
            ],
        )?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_enable = o.opt("enable", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_type = o.opt(
            "type",
            <crate::types::SpartnConnectionType as crate::json_read::FromJson>::from_json,
        )?;
        let p_current_key_tow = o.opt(
            "current_key_tow",
            <u32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_current_key_week = o.opt(
            "current_key_week",
            <u16 as crate::json_read::FromJson>::from_json,
        )?;
        let p_current_key = o.opt(
            "current_key",
            <crate::wire::Str<32> as crate::json_read::FromJson>::from_json,
        )?;
        let p_next_key_tow = o.opt(
            "next_key_tow",
            <u32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_next_key_week = o.opt(
            "next_key_week",
            <u16 as crate::json_read::FromJson>::from_json,
        )?;
        let p_next_key = o.opt(
            "next_key",
            <crate::wire::Str<32> as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            enable: p_enable,
            r#type: p_type,
            current_key_tow: p_current_key_tow,
            current_key_week: p_current_key_week,
            current_key: p_current_key,
            next_key_tow: p_next_key_tow,
            next_key_week: p_next_key_week,
            next_key: p_next_key,
        })
    }
}

impl SpartnConfiguration {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0E;
}

impl crate::wire::Layout for SpartnConfiguration {
    const DESCRIPTOR: u8 = 0x20;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0E);
    const NAME: &'static str = "spartn_configuration";
}

/// SPARTN configuration (response). Current SPARTN configuration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpartnConfigurationResponse {
    /// SPARTN subsystem: 0 disabled, 1 enabled.
    pub enable: u8,
    /// Connection type.
    pub r#type: crate::types::SpartnConnectionType,
    /// GPS time of week until which the current key is valid. Units: s.
    pub current_key_tow: u32,
    /// GPS week until which the current key is valid. Units: weeks.
    pub current_key_week: u16,
    /// Current key: 32 ASCII hex characters.
    pub current_key: crate::wire::Str<32>,
    /// GPS time of week until which the next key is valid. Units: s.
    pub next_key_tow: u32,
    /// GPS week until which the next key is valid. Units: weeks.
    pub next_key_week: u16,
    /// Next key: 32 ASCII hex characters.
    pub next_key: crate::wire::Str<32>,
}

impl Default for SpartnConfigurationResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SpartnConfigurationResponse {
    const ZERO: Self = Self {
        enable: <u8 as crate::wire::Wire>::ZERO,
        r#type: <crate::types::SpartnConnectionType as crate::wire::Wire>::ZERO,
        current_key_tow: <u32 as crate::wire::Wire>::ZERO,
        current_key_week: <u16 as crate::wire::Wire>::ZERO,
        current_key: <crate::wire::Str<32> as crate::wire::Wire>::ZERO,
        next_key_tow: <u32 as crate::wire::Wire>::ZERO,
        next_key_week: <u16 as crate::wire::Wire>::ZERO,
        next_key: <crate::wire::Str<32> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(78);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_enable = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("enable"))?;
        let p_type = <crate::types::SpartnConnectionType as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("type"))?;
        let p_current_key_tow =
            <u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("current_key_tow"))?;
        let p_current_key_week =
            <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("current_key_week"))?;
        let p_current_key = <crate::wire::Str<32> as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("current_key"))?;
        let p_next_key_tow =
            <u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("next_key_tow"))?;
        let p_next_key_week =
            <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("next_key_week"))?;
        let p_next_key =
            <crate::wire::Str<32> as crate::wire::Wire>::decode(r).map_err(|e| e.at("next_key"))?;
        Ok(Self {
            enable: p_enable,
            r#type: p_type,
            current_key_tow: p_current_key_tow,
            current_key_week: p_current_key_week,
            current_key: p_current_key,
            next_key_tow: p_next_key_tow,
            next_key_week: p_next_key_week,
            next_key: p_next_key,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.enable;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("enable"))?;
        let v = &self.r#type;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("type"))?;
        let v = &self.current_key_tow;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("current_key_tow"))?;
        let v = &self.current_key_week;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("current_key_week"))?;
        let v = &self.current_key;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("current_key"))?;
        let v = &self.next_key_tow;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("next_key_tow"))?;
        let v = &self.next_key_week;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("next_key_week"))?;
        let v = &self.next_key;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("next_key"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.enable;
        crate::json::key(w, &mut first, "enable")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.r#type;
        crate::json::key(w, &mut first, "type")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.current_key_tow;
        crate::json::key(w, &mut first, "current_key_tow")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.current_key_week;
        crate::json::key(w, &mut first, "current_key_week")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.current_key;
        crate::json::key(w, &mut first, "current_key")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.next_key_tow;
        crate::json::key(w, &mut first, "next_key_tow")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.next_key_week;
        crate::json::key(w, &mut first, "next_key_week")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.next_key;
        crate::json::key(w, &mut first, "next_key")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SpartnConfigurationResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "enable",
                "type",
                "current_key_tow",
                "current_key_week",
                "current_key",
                "next_key_tow",
                "next_key_week",
                "next_key",
            ],
        )?;
        let p_enable = o.req("enable", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_type = o.req(
            "type",
            <crate::types::SpartnConnectionType as crate::json_read::FromJson>::from_json,
        )?;
        let p_current_key_tow = o.req(
            "current_key_tow",
            <u32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_current_key_week = o.req(
            "current_key_week",
            <u16 as crate::json_read::FromJson>::from_json,
        )?;
        let p_current_key = o.req(
            "current_key",
            <crate::wire::Str<32> as crate::json_read::FromJson>::from_json,
        )?;
        let p_next_key_tow = o.req(
            "next_key_tow",
            <u32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_next_key_week = o.req(
            "next_key_week",
            <u16 as crate::json_read::FromJson>::from_json,
        )?;
        let p_next_key = o.req(
            "next_key",
            <crate::wire::Str<32> as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            enable: p_enable,
            r#type: p_type,
            current_key_tow: p_current_key_tow,
            current_key_week: p_current_key_week,
            current_key: p_current_key,
            next_key_tow: p_next_key_tow,
            next_key_week: p_next_key_week,
            next_key: p_next_key,
        })
    }
}

impl SpartnConfigurationResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0E;
}

impl crate::wire::Layout for SpartnConfigurationResponse {
    const DESCRIPTOR: u8 = 0xA0;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0E);
    const NAME: &'static str = "spartn_configuration_response";
}

/// A decoded field of set 0x0E (`gnss`).
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SetField {
    /// `receiver_info` (0x01).
    ReceiverInfo(ReceiverInfo),
    /// `receiver_info_response` (0x81).
    ReceiverInfoResponse(ReceiverInfoResponse),
    /// `signal_configuration` (0x02).
    SignalConfiguration(SignalConfiguration),
    /// `signal_configuration_response` (0x82).
    SignalConfigurationResponse(SignalConfigurationResponse),
    /// `spartn_configuration` (0x20).
    SpartnConfiguration(SpartnConfiguration),
    /// `spartn_configuration_response` (0xA0).
    SpartnConfigurationResponse(SpartnConfigurationResponse),
}

impl SetField {
    /// Field descriptor.
    pub fn descriptor(&self) -> u8 {
        match self {
            Self::ReceiverInfo(_) => 0x01,
            Self::ReceiverInfoResponse(_) => 0x81,
            Self::SignalConfiguration(_) => 0x02,
            Self::SignalConfigurationResponse(_) => 0x82,
            Self::SpartnConfiguration(_) => 0x20,
            Self::SpartnConfigurationResponse(_) => 0xA0,
        }
    }

    /// Field name as printed in JSON.
    pub fn name(&self) -> &'static str {
        match self {
            Self::ReceiverInfo(_) => "receiver_info",
            Self::ReceiverInfoResponse(_) => "receiver_info_response",
            Self::SignalConfiguration(_) => "signal_configuration",
            Self::SignalConfigurationResponse(_) => "signal_configuration_response",
            Self::SpartnConfiguration(_) => "spartn_configuration",
            Self::SpartnConfigurationResponse(_) => "spartn_configuration_response",
        }
    }

    /// Device of the layout used, for fields with per-device layouts.
    pub fn device(&self) -> Option<crate::Device> {
        match self {
            Self::ReceiverInfo(_) => None,
            Self::ReceiverInfoResponse(_) => None,
            Self::SignalConfiguration(_) => None,
            Self::SignalConfigurationResponse(_) => None,
            Self::SpartnConfiguration(_) => None,
            Self::SpartnConfigurationResponse(_) => None,
        }
    }

    /// Encodes the field data.
    pub fn encode_data(
        &self,
        w: &mut crate::wire::Writer<'_>,
    ) -> Result<(), crate::error::EncodeError> {
        match self {
            Self::ReceiverInfo(v) => crate::wire::Layout::encode_data(v, w),
            Self::ReceiverInfoResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::SignalConfiguration(v) => crate::wire::Layout::encode_data(v, w),
            Self::SignalConfigurationResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::SpartnConfiguration(v) => crate::wire::Layout::encode_data(v, w),
            Self::SpartnConfigurationResponse(v) => crate::wire::Layout::encode_data(v, w),
        }
    }

    /// Writes the canonical JSON of the values (`{...}`).
    pub fn write_values_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::ReceiverInfo(v) => crate::wire::Wire::write_json(v, w),
            Self::ReceiverInfoResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::SignalConfiguration(v) => crate::wire::Wire::write_json(v, w),
            Self::SignalConfigurationResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::SpartnConfiguration(v) => crate::wire::Wire::write_json(v, w),
            Self::SpartnConfigurationResponse(v) => crate::wire::Wire::write_json(v, w),
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
            0x01 => Some(
                <ReceiverInfo as crate::wire::Layout>::decode_data(data).map(Self::ReceiverInfo),
            ),
            0x81 => Some(
                <ReceiverInfoResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::ReceiverInfoResponse),
            ),
            0x02 => Some(
                <SignalConfiguration as crate::wire::Layout>::decode_data(data)
                    .map(Self::SignalConfiguration),
            ),
            0x82 => Some(
                <SignalConfigurationResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::SignalConfigurationResponse),
            ),
            0x20 => Some(
                <SpartnConfiguration as crate::wire::Layout>::decode_data(data)
                    .map(Self::SpartnConfiguration),
            ),
            0xA0 => Some(
                <SpartnConfigurationResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::SpartnConfigurationResponse),
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
                        <ReceiverInfo as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::ReceiverInfo),
            ),
            0x81 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ReceiverInfoResponse as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::ReceiverInfoResponse),
            ),
            0x02 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SignalConfiguration as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::SignalConfiguration),
            ),
            0x82 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SignalConfigurationResponse as crate::json_read::FromJson>::from_json(
                            values,
                        )
                        .map_err(|e| e.at("values"))
                    })
                    .map(Self::SignalConfigurationResponse),
            ),
            0x20 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SpartnConfiguration as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::SpartnConfiguration),
            ),
            0xA0 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SpartnConfigurationResponse as crate::json_read::FromJson>::from_json(
                            values,
                        )
                        .map_err(|e| e.at("values"))
                    })
                    .map(Self::SpartnConfigurationResponse),
            ),
            _ => None,
        }
    }
}
